//! Tests of the field kinds: parsing, checking and defaults.

use super::*;

fn dpi() -> Field {
    Field::number("dpi", "Scan resolution", 600.0)
        .unit("dpi")
        .positive(1e5)
}

#[test]
fn number_limits_name_the_field() {
    let f = dpi();
    assert_eq!(f.check(&Value::Number(900.0)), Ok(Value::Number(900.0)));
    let e = f.check(&Value::Number(0.0)).unwrap_err().to_string();
    assert_eq!(e, "dpi: must be greater than 0 dpi (got 0)");
    let e = f.check(&Value::Number(f64::NAN)).unwrap_err().to_string();
    assert_eq!(e, "dpi: is NaN; give a number");
    let e = f
        .check(&Value::Number(f64::INFINITY))
        .unwrap_err()
        .to_string();
    assert!(e.contains("infinite"), "{e}");
    let e = f.check(&Value::Text("900".into())).unwrap_err().to_string();
    assert_eq!(e, "dpi: must be a number, got the string \"900\"");
}

#[test]
fn a_choice_of_numbers_also_takes_the_number() {
    let f = Field::choice(
        "connectivity",
        "Connectivity",
        &[("8", "8"), ("4", "4")],
        "8",
    );
    assert_eq!(f.check(&Value::Number(4.0)), Ok(Value::Text("4".into())));
    assert_eq!(f.check(&Value::Number(8.0)), Ok(Value::Text("8".into())));
    assert_eq!(
        f.check(&Value::Text("4".into())),
        Ok(Value::Text("4".into()))
    );
    let e = f.check(&Value::Number(6.0)).unwrap_err().to_string();
    assert_eq!(e, "connectivity: 6 is not one of the choices (8, 4)");
    let e = f.check(&Value::Number(f64::NAN)).unwrap_err().to_string();
    assert!(e.starts_with("connectivity: NaN is not one of"), "{e}");
    let e = f.check(&Value::Bool(true)).unwrap_err().to_string();
    assert!(
        e.starts_with("connectivity: must be one of the choices"),
        "{e}"
    );
    // options that are words take no number
    let g = Field::choice("model", "Model", &[("helmert", "Helmert")], "helmert");
    let e = g.check(&Value::Number(1.0)).unwrap_err().to_string();
    assert_eq!(e, "model: 1 is not one of the choices (helmert)");
}

#[test]
fn number_text_parsing() {
    let f = dpi();
    assert_eq!(f.parse_text(" 1e3 "), Ok(Value::Number(1000.0)));
    // the one number reader's rules (practice's): a decimal comma, fractions, ×10^, a unit
    assert_eq!(f.parse_text("1200,5"), Ok(Value::Number(1200.5)));
    assert_eq!(f.parse_text("1,2e3"), Ok(Value::Number(1200.0)));
    assert_eq!(f.parse_text("2400/2"), Ok(Value::Number(1200.0)));
    assert_eq!(f.parse_text("1.2×10^3 dpi"), Ok(Value::Number(1200.0)));
    for bad in [
        "", "abc", "NaN", "inf", "1e999", "9 5", "<img>", "5 mm", "-5",
    ] {
        let e = f.parse_text(bad).unwrap_err();
        assert_eq!(e.field(), Some("dpi"), "{bad}: {e}");
    }
    assert_eq!(
        f.parse_text("5 mm").unwrap_err().to_string(),
        "dpi: this field is in dpi; mm does not fit it"
    );
    let mm = Field::number("x_mm", "x", 0.0).unit("mm");
    assert_eq!(mm.parse_text("-1,242 cm"), Ok(Value::Number(-12.42)));
    let n = Field::integer("n", "n", 3.0);
    assert_eq!(n.parse_text("1,5e1"), Ok(Value::Number(15.0)));
    assert_eq!(
        n.parse_text("1,5").unwrap_err().to_string(),
        "n: must be a whole number (got 1.5)"
    );
}

#[test]
fn list_texts_say_how_they_read_a_comma() {
    let v = Field {
        key: "v",
        label: "V",
        help: "",
        kind: Kind::Vector {
            min_len: 2,
            max_len: 9,
        },
        default: Value::numbers(&[1.0, 2.0]),
        when: None,
    };
    assert_eq!(v.parse_text("0,5 1,5"), Ok(Value::numbers(&[0.5, 1.5])));
    assert_eq!(v.parse_text("1,2,3"), Ok(Value::numbers(&[1.0, 2.0, 3.0])));
    let e = v.parse_text("1,5, 2").unwrap_err().to_string();
    assert!(e.starts_with("v: \"1,5, 2\" is ambiguous"), "{e}");
    // too few numbers after commas that separated: the message says how they were read
    let p = Field::points("p", "P", 3, 9, &[vec![1.0, 2.0, 3.0]]);
    assert_eq!(
        p.parse_text("1,5 2,5 3,5; 1,5,2"),
        Ok(Value::matrix(&[vec![1.5, 2.5, 3.5], vec![1.0, 5.0, 2.0]]))
    );
    let e = p.parse_text("0,5").unwrap_err().to_string();
    assert!(
        e.contains("every comma separates two numbers") && e.contains("0,5 1,5"),
        "{e}"
    );
}

#[test]
fn matrix_text_round_trip_and_ragged_rows() {
    let f = Field {
        key: "a",
        label: "A",
        help: "",
        kind: Kind::Matrix {
            rows: None,
            cols: None,
        },
        default: Value::matrix(&[vec![1.0, 2.0], vec![3.0, 4.5]]),
        when: None,
    };
    let text = f.format(&f.default);
    assert_eq!(text, "1, 2; 3, 4.5");
    assert_eq!(f.parse_text(&text), Ok(f.default.clone()));
    assert_eq!(f.parse_text("[1 2]\n[3 4.5]"), Ok(f.default.clone()));
    let e = f.parse_text("1 2; 3").unwrap_err().to_string();
    assert!(e.contains("same length"), "{e}");
    assert!(f.parse_text("").is_err());
}

#[test]
fn validate_fills_defaults_and_rejects_unknown() -> crate::error::Result<()> {
    let fields = [dpi()];
    let used = validate(&fields, &Record::new())?;
    assert_eq!(used.number("dpi"), Some(600.0));
    assert!(is_seed(&fields, &used));
    let e = validate(&fields, &Record::new().with("dpu", 3.0)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "dpu: unknown field (this example takes: dpi)"
    );
    Ok(())
}
