//! Reading a student's answer box: a number (decimal point or comma,
//! scientific notation, a fraction) and an optional unit, with the
//! precision the text carries. A text that cannot be read is never a wrong
//! answer: it is reported as unreadable, with what could not be read.

/// What an answer text was read as.
#[derive(Debug, Clone, PartialEq)]
pub struct Reading {
    /// The number as typed, before any unit conversion.
    pub number: f64,
    /// Half a unit of the last digit typed (0 for a fraction: exact).
    pub half_ulp: f64,
    /// The unit typed after the number, if any (normalised: "mm", "°" …).
    pub unit: Option<&'static str>,
}

/// A unit a student may type, its dimension and its size in the
/// dimension's base unit (mm, px, degree, grey value).
struct UnitDef {
    names: &'static [&'static str],
    canonical: &'static str,
    dimension: &'static str,
    scale: f64,
}

const UNITS: &[UnitDef] = &[
    UnitDef {
        names: &[
            "mm",
            "millimetre",
            "millimetres",
            "millimeter",
            "millimeters",
        ],
        canonical: "mm",
        dimension: "length",
        scale: 1.0,
    },
    UnitDef {
        names: &[
            "cm",
            "centimetre",
            "centimetres",
            "centimeter",
            "centimeters",
        ],
        canonical: "cm",
        dimension: "length",
        scale: 10.0,
    },
    UnitDef {
        names: &["m", "metre", "metres", "meter", "meters"],
        canonical: "m",
        dimension: "length",
        scale: 1000.0,
    },
    UnitDef {
        names: &["km", "kilometre", "kilometres", "kilometer", "kilometers"],
        canonical: "km",
        dimension: "length",
        scale: 1.0e6,
    },
    UnitDef {
        names: &["µm", "μm", "um", "micron", "microns"],
        canonical: "µm",
        dimension: "length",
        scale: 0.001,
    },
    UnitDef {
        names: &["px", "pixel", "pixels", "pel"],
        canonical: "px",
        dimension: "pixel",
        scale: 1.0,
    },
    UnitDef {
        names: &["°", "deg", "degree", "degrees"],
        canonical: "°",
        dimension: "angle",
        scale: 1.0,
    },
    UnitDef {
        names: &["rad", "radian", "radians"],
        canonical: "rad",
        dimension: "angle",
        scale: 180.0 / std::f64::consts::PI,
    },
    UnitDef {
        names: &["ppm", "mm/km"],
        canonical: "ppm",
        dimension: "ratio",
        scale: 1.0,
    },
    UnitDef {
        names: &[
            "gv",
            "grey values",
            "grey value",
            "gray values",
            "gray value",
        ],
        canonical: "grey values",
        dimension: "grey",
        scale: 1.0,
    },
];

fn unit_def(name: &str) -> Option<&'static UnitDef> {
    let lower = name.trim().to_lowercase();
    UNITS.iter().find(|u| u.names.contains(&lower.as_str()))
}

/// How a typed unit relates to the unit of the box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum UnitCheck {
    /// No unit typed: the box's own unit is meant.
    Omitted,
    /// The box's unit, or one of the same dimension (converted by `factor`).
    Fits { factor: f64 },
    /// A unit of another dimension (pixels typed in a millimetre box).
    Wrong,
}

/// Compares the unit typed with the box's unit.
pub fn check_unit(typed: Option<&str>, expected: Option<&str>) -> UnitCheck {
    let Some(typed) = typed else {
        return UnitCheck::Omitted;
    };
    let (Some(t), Some(e)) = (unit_def(typed), expected.and_then(unit_def)) else {
        return UnitCheck::Wrong;
    };
    if t.dimension == e.dimension {
        UnitCheck::Fits {
            factor: t.scale / e.scale,
        }
    } else {
        UnitCheck::Wrong
    }
}

/// The one reader's spelling rules, before anything is read: a real minus
/// (−) and a dash are a minus, a thin or no-break space is a space, and
/// `×`, `⋅`, `·` are a multiplication (`2.5×10^-3`).
fn normalise(text: &str) -> String {
    text.trim()
        .chars()
        .map(|ch| match ch {
            '\u{2212}' | '\u{2013}' => '-',
            '\u{00a0}' | '\u{202f}' | '\u{2009}' => ' ',
            '\u{00d7}' | '\u{22c5}' | '\u{00b7}' => '*',
            c => c,
        })
        .collect()
}

/// A text quoted in a message: at most 24 characters (a pasted page is not
/// echoed back whole).
pub fn short(s: &str) -> String {
    let mut out: String = s.chars().take(24).collect();
    if s.chars().count() > 24 {
        out.push('…');
    }
    out
}

/// Splits a normalised text into its number part and a trailing unit.
fn split_unit(t: &str) -> (&str, &str) {
    let num_end = t
        .char_indices()
        .find(|&(i, ch)| {
            !(ch.is_ascii_digit()
                || matches!(ch, '.' | ',' | '+' | '-' | '/' | '*' | '^' | ' ')
                || ((ch == 'e' || ch == 'E') && next_is_exponent(&t[i + ch.len_utf8()..])))
        })
        .map_or(t.len(), |(i, _)| i);
    let (num_text, unit_text) = t.split_at(num_end);
    (num_text.trim(), unit_text.trim())
}

/// The number part of a text (no unit), with half a unit of its last digit.
fn number_part(num_text: &str) -> Result<(f64, f64), String> {
    if num_text.is_empty() {
        return Err("there is no number in it".to_string());
    }
    if num_text.contains(' ') {
        return Err(format!(
            "\"{}\" has a space inside the number; write it without spaces",
            short(num_text)
        ));
    }
    let (x, half) = read_number(num_text)?;
    if !x.is_finite() {
        return Err(format!("\"{}\" is too large", short(num_text)));
    }
    Ok((x, half))
}

/// Reads an answer text. `Ok(None)` for an empty box; `Err` says what
/// could not be read.
///
/// This is the one number reader of the playground: a practice answer box
/// here; an example's input fields through [`read_value`] (a number, with
/// the field's unit) and [`read_rows`] (lists), on the same rules.
/// Practice grading (`grade.rs`) relies on this signature: keep it stable.
pub fn read(text: &str) -> Result<Option<Reading>, String> {
    let t = normalise(text);
    if t.is_empty() {
        return Ok(None);
    }
    let (num_text, unit_text) = split_unit(&t);
    let unit = if unit_text.is_empty() {
        None
    } else {
        match unit_def(unit_text) {
            Some(u) => Some(u.canonical),
            None => {
                return Err(format!(
                    "\"{}\" is not a unit this box knows (try mm, cm, m, km, px, °, rad, ppm)",
                    short(unit_text)
                ))
            }
        }
    };
    let (number, half_ulp) = number_part(num_text)?;
    Ok(Some(Reading {
        number,
        half_ulp,
        unit,
    }))
}

/// Reads the text of a number input field whose unit is `unit` (`None`: a
/// plain number), on [`read`]'s rules (a decimal point or comma, `1.5e3`,
/// `1.5×10^3`, a fraction `3/4`), and a unit after the number when the
/// field has one: the field's own unit, or one of the same dimension,
/// converted (`26.7 cm` in a millimetre field is 267). The message of an
/// `Err` says what could not be read; the caller names the field.
pub fn read_value(text: &str, unit: Option<&str>) -> Result<f64, String> {
    let t = normalise(text);
    if t.is_empty() {
        return Err("is empty; enter a number".to_string());
    }
    let (num_text, unit_text) = split_unit(&t);
    let not_a_number = || format!("\"{}\" is not a number", short(&t));
    if num_text.is_empty() {
        return Err(not_a_number());
    }
    let (x, _) = number_part(num_text)?;
    if unit_text.is_empty() {
        return Ok(x);
    }
    let Some(own) = unit else {
        if unit_def(unit_text).is_none() {
            return Err(not_a_number());
        }
        return Err(format!(
            "\"{}\": this field takes a plain number, without a unit",
            short(&t)
        ));
    };
    if unit_text.eq_ignore_ascii_case(own) {
        return Ok(x);
    }
    match check_unit(Some(unit_text), Some(own)) {
        UnitCheck::Fits { factor } => Ok(x * factor),
        _ if unit_def(unit_text).is_none() => Err(format!(
            "\"{}\" is not a unit (this field is in {own})",
            short(unit_text)
        )),
        _ => Err(format!(
            "this field is in {own}; {} does not fit it",
            short(unit_text)
        )),
    }
}

/// Reads the text of a list input (a vector, or a matrix or point list of
/// rows): rows are separated by `;` or new lines, square brackets are
/// ignored, empty rows skipped, and each row is read by [`read_list`].
pub fn read_rows(text: &str) -> Result<Vec<Vec<f64>>, String> {
    text.split([';', '\n'])
        .map(|r| r.trim().trim_matches(['[', ']']).trim())
        .filter(|r| !r.is_empty())
        .map(read_list)
        .collect()
}

/// Reads one row of numbers. How a decimal comma and a list's commas live
/// together (the rule docs/API.md states for every list input):
/// - the numbers of a row are separated by spaces or by commas;
/// - in a row with no space (`1,2,3`), every comma separates numbers;
/// - in a row whose numbers are separated by spaces only (`0,5 1,5 2`), a
///   comma between two digits is a decimal comma;
/// - a row with both (`1,5, 2`: a comma with a space separates, and another
///   comma stands between two digits) is ambiguous: refused, saying so.
///
/// Each number follows [`read`]'s rules, without a unit.
pub fn read_list(row: &str) -> Result<Vec<f64>, String> {
    let t = normalise(&row.replace(['[', ']'], " "));
    let spaced = t.contains(char::is_whitespace);
    let decimal_comma = has_digit_comma(&t);
    let separating_comma = t.split(',').count() - 1 > digit_commas(&t);
    if spaced && decimal_comma && separating_comma {
        return Err(format!(
            "\"{}\" is ambiguous: a comma with a space separates numbers in it, and another comma stands between two digits (a decimal comma, or one more separator?); write decimal points (1.5), or separate the numbers with spaces only (0,5 1,5)",
            short(&t)
        ));
    }
    // A decimal comma only where spaces alone separate the numbers.
    let tokens: Vec<&str> = if spaced && decimal_comma {
        t.split_whitespace().collect()
    } else {
        t.split(|c: char| c == ',' || c.is_whitespace())
            .filter(|s| !s.is_empty())
            .collect()
    };
    tokens
        .into_iter()
        .map(|tok| {
            number_part(tok).map(|(x, _)| x).map_err(|e| {
                if tok.contains(',') {
                    format!("{e} (in a row of numbers separated by spaces, a comma between two digits is a decimal comma: 0,5 1,5)")
                } else {
                    e
                }
            })
        })
        .collect()
}

/// A hint for a list that was read but came out the wrong size, when a
/// row without spaces has a comma between two digits that may have been
/// meant as a decimal comma (it separated two numbers).
pub fn comma_hint(text: &str) -> Option<&'static str> {
    text.split([';', '\n'])
        .map(|r| r.trim().trim_matches(['[', ']']).trim())
        .any(|r| !r.contains(char::is_whitespace) && has_digit_comma(r))
        .then_some(
            "in a row written without spaces every comma separates two numbers; for a decimal comma, separate the numbers with spaces (0,5 1,5)",
        )
}

/// The number of commas with a digit on both sides.
fn digit_commas(s: &str) -> usize {
    let b = s.as_bytes();
    (1..b.len().saturating_sub(1))
        .filter(|&i| b[i] == b',' && b[i - 1].is_ascii_digit() && b[i + 1].is_ascii_digit())
        .count()
}

fn has_digit_comma(s: &str) -> bool {
    digit_commas(s) > 0
}

fn next_is_exponent(rest: &str) -> bool {
    let rest = rest.strip_prefix(['+', '-']).unwrap_or(rest);
    rest.starts_with(|c: char| c.is_ascii_digit())
}

/// A number without unit: decimal (point or comma), `1.2e-3`,
/// `1.2*10^-3`, or a fraction `a/b`.
fn read_number(s: &str) -> Result<(f64, f64), String> {
    if let Some((a, b)) = s.split_once('/') {
        let (x, _) = read_decimal(a)?;
        let (y, _) = read_decimal(b)?;
        if y == 0.0 {
            return Err(format!("\"{}\" divides by zero", short(s)));
        }
        return Ok((x / y, 0.0));
    }
    let (mantissa, exponent) = if let Some((m, e)) = s.split_once("*10^") {
        (m, Some(e))
    } else if let Some(i) = s.find(['e', 'E']) {
        (&s[..i], Some(&s[i + 1..]))
    } else {
        (s, None)
    };
    let (m, half) = read_decimal(mantissa)?;
    match exponent {
        None => Ok((m, half)),
        Some(e) => {
            let e = e.strip_prefix('+').unwrap_or(e);
            let k: i32 = e
                .parse()
                .ok()
                .filter(|k: &i32| k.abs() <= 300)
                .ok_or_else(|| {
                    format!(
                        "\"{}\": the exponent must be a whole number from −300 to 300",
                        short(s)
                    )
                })?;
            let p = 10f64.powi(k);
            Ok((m * p, half * p))
        }
    }
}

/// A plain decimal with a point or a comma; returns the value and half a
/// unit of its last digit.
fn read_decimal(s: &str) -> Result<(f64, f64), String> {
    let s = s.trim();
    let unsigned = s.strip_prefix(['+', '-']).unwrap_or(s);
    let seps = unsigned.matches(['.', ',']).count();
    let ok = !unsigned.is_empty()
        && seps <= 1
        && unsigned
            .chars()
            .all(|c| c.is_ascii_digit() || c == '.' || c == ',')
        && unsigned.chars().any(|c| c.is_ascii_digit());
    if !ok {
        return Err(format!("\"{}\" is not a number", short(s)));
    }
    let normal = s.replace(',', ".");
    let x: f64 = normal
        .parse()
        .map_err(|_| format!("\"{}\" is not a number", short(s)))?;
    let decimals = normal.split_once('.').map_or(0, |(_, f)| f.len());
    let half = 0.5 * 10f64.powi(-(decimals.min(300) as i32));
    Ok((x, half))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn n(s: &str) -> f64 {
        read(s).unwrap().unwrap().number
    }

    #[test]
    fn reads_the_usual_forms() {
        assert_eq!(n("0.0282"), 0.0282);
        assert_eq!(n("0,0282"), 0.0282);
        assert_eq!(n(" −12.5 "), -12.5);
        assert_eq!(n("2.5e-3"), 0.0025);
        assert_eq!(n("2,5E3"), 2500.0);
        assert!((n("2.5×10^-3") - 0.0025).abs() < 1e-15);
        assert_eq!(n("3/4"), 0.75);
        assert_eq!(n("-1/2"), -0.5);
        assert_eq!(read("").unwrap(), None);
        assert_eq!(read("   ").unwrap(), None);
    }

    #[test]
    fn reads_precision_and_units() {
        let r = read("26.7 cm").unwrap().unwrap();
        assert_eq!((r.number, r.unit), (26.7, Some("cm")));
        assert!((r.half_ulp - 0.05).abs() < 1e-12);
        assert_eq!(read("3/4").unwrap().unwrap().half_ulp, 0.0);
        let e = read("1.5e2").unwrap().unwrap();
        assert!((e.half_ulp - 5.0).abs() < 1e-9);
        assert_eq!(read("12°").unwrap().unwrap().unit, Some("°"));
        assert_eq!(read("8 px").unwrap().unwrap().unit, Some("px"));
    }

    #[test]
    fn malformed_texts_say_why() {
        for bad in [
            "abc",
            "1.2.3",
            "1,2,3",
            "--4",
            "1/0",
            "12 34",
            "5 parsecs",
            "e5",
        ] {
            assert!(read(bad).is_err(), "{bad} should not read");
        }
    }

    #[test]
    fn an_input_field_reads_as_an_answer_box_does() {
        // issue 29, item 2: the same value from the same text, wherever typed
        for text in ["0,5", "0.5", "1/2", "5e-1", "5×10^-1", "+0,5", "50e-2"] {
            let answer = read(text).unwrap().unwrap().number;
            assert_eq!(read_value(text, None), Ok(answer), "{text}");
            assert!((answer - 0.5).abs() < 1e-15, "{text}");
        }
        assert_eq!(read_value("1,5e3", None), Ok(1500.0));
        assert_eq!(read_value("3/4", Some("mm")), Ok(0.75));
        assert_eq!(read_value("−12,42", Some("mm")), Ok(-12.42));
        // a unit where the field has one: its own, or converted within its dimension
        assert_eq!(read_value("1200 dpi", Some("dpi")), Ok(1200.0));
        assert_eq!(read_value("26,7 cm", Some("mm")), Ok(267.0));
        assert_eq!(read_value("0.5 m", Some("mm")), Ok(500.0));
        assert_eq!(
            read_value("8 px", Some("mm")),
            Err("this field is in mm; px does not fit it".to_string())
        );
        assert_eq!(
            read_value("8 px", None),
            Err("\"8 px\": this field takes a plain number, without a unit".to_string())
        );
        assert_eq!(
            read_value("8 parsecs", Some("mm")),
            Err("\"parsecs\" is not a unit (this field is in mm)".to_string())
        );
        for bad in [
            "",
            "abc",
            "NaN",
            "inf",
            "1e999",
            "9".repeat(400).as_str(),
            "12 34",
        ] {
            assert!(read_value(bad, None).is_err(), "{bad}");
        }
        // a long text is quoted short
        let e = read_value(&"1".repeat(500).replace('1', "x"), None).unwrap_err();
        assert!(e.len() < 120, "{e}");
    }

    #[test]
    fn lists_take_a_decimal_comma_only_between_spaces() {
        assert_eq!(read_list("1,2,3"), Ok(vec![1.0, 2.0, 3.0]));
        assert_eq!(read_list("1, 2, 3"), Ok(vec![1.0, 2.0, 3.0]));
        assert_eq!(read_list("1 2 3"), Ok(vec![1.0, 2.0, 3.0]));
        assert_eq!(read_list("0,5 1,5 2"), Ok(vec![0.5, 1.5, 2.0]));
        assert_eq!(read_list("[0.5, 1.5]"), Ok(vec![0.5, 1.5]));
        assert_eq!(read_list("1/2 3/4 −1e1"), Ok(vec![0.5, 0.75, -10.0]));
        assert_eq!(read_list("1 , 2"), Ok(vec![1.0, 2.0]));
        let e = read_list("1,5, 2").unwrap_err();
        assert!(e.contains("is ambiguous") && e.contains("0,5 1,5"), "{e}");
        let e = read_list("1,2,3 4").unwrap_err();
        assert!(e.contains("decimal comma"), "{e}");
        assert_eq!(
            read_rows("1,5 2; 3 4,5\n[5 6]"),
            Ok(vec![vec![1.5, 2.0], vec![3.0, 4.5], vec![5.0, 6.0]])
        );
        assert_eq!(
            read_rows("1,2; 3,4"),
            Ok(vec![vec![1.0, 2.0], vec![3.0, 4.0]])
        );
        assert!(comma_hint("0,5").is_some());
        assert!(comma_hint("0,5 1").is_none());
        assert!(comma_hint("1, 2").is_none());
    }

    #[test]
    fn units_convert_within_a_dimension() {
        assert_eq!(
            check_unit(Some("mm"), Some("cm")),
            UnitCheck::Fits { factor: 0.1 }
        );
        assert_eq!(check_unit(Some("px"), Some("mm")), UnitCheck::Wrong);
        assert_eq!(
            check_unit(Some("m"), Some("km")),
            UnitCheck::Fits { factor: 0.001 }
        );
        assert_eq!(
            check_unit(Some("mm/km"), Some("ppm")),
            UnitCheck::Fits { factor: 1.0 }
        );
        assert_eq!(check_unit(Some("ppm"), Some("km")), UnitCheck::Wrong);
        let r = read("180,6 km").unwrap().unwrap();
        assert_eq!((r.number, r.unit), (180.6, Some("km")));
        assert_eq!(read("128 ppm").unwrap().unwrap().unit, Some("ppm"));
        assert_eq!(check_unit(None, Some("mm")), UnitCheck::Omitted);
        assert_eq!(check_unit(Some("mm"), None), UnitCheck::Wrong);
    }
}
