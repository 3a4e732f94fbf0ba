//! Seed 000, Examples 1–3, reproduced natively with their numbers.
#![cfg(not(target_arch = "wasm32"))]

use photogrammetry_playground::examples::{catalog, parse_inputs, solve};
use photogrammetry_playground::solution::{NoteKind, Record, Solution, Value};

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

fn result(s: &Solution, key: &str) -> f64 {
    s.result
        .number(key)
        .unwrap_or_else(|| panic!("result {key} missing in {}", s.id))
}

fn printed(s: &Solution, key: &str) -> f64 {
    s.textbook
        .as_ref()
        .and_then(|t| t.number(key))
        .unwrap_or_else(|| panic!("printed {key} missing in {}", s.id))
}

fn assert_close(s: &Solution, key: &str, expected: f64, tol: f64) {
    let got = result(s, key);
    assert!(
        close(got, expected, tol),
        "{}.{key} = {got}, expected {expected}",
        s.id
    );
}

fn has_note(s: &Solution, kind: NoteKind, needle: &str) -> bool {
    s.notes
        .iter()
        .any(|n| n.kind == kind && n.text.contains(needle))
}

#[test]
fn example_1_pixel_to_photo_exact_values_and_printed_ones() {
    let s = solve("pixel-to-photo", &Record::new()).unwrap();
    assert_close(&s, "c0", 800.0, 0.0);
    assert_close(&s, "r0", 700.0, 0.0);
    assert_close(&s, "x_px", 195.0, 0.0);
    assert_close(&s, "y_px", 220.0, 0.0);
    assert_close(&s, "pixel_size_mm", 25.4 / 600.0, 1e-15);
    assert_close(&s, "x_mm", 8.255, 1e-12);
    assert_close(&s, "y_mm", 9.313_333_333_333, 1e-9);
    // the seed's printed values, beside the exact ones
    assert_eq!(printed(&s, "pixel_size_mm"), 0.042);
    assert_eq!(printed(&s, "x_mm"), 8.19);
    assert_eq!(printed(&s, "y_mm"), 9.24);
    assert!(has_note(
        &s,
        NoteKind::Rounding,
        "0.04233333 mm to 0.042 mm"
    ));
    assert!(has_note(&s, NoteKind::Rounding, "8.255"));
    assert!(has_note(&s, NoteKind::Convention, "(C/2, R/2)"));
    // same keys, same order as CATALOG.md
    let keys: Vec<_> = s.result.keys().collect();
    assert_eq!(
        keys,
        ["c0", "r0", "x_px", "y_px", "pixel_size_mm", "x_mm", "y_mm"]
    );
    // every step shows its formula and the numbers put in
    for step in &s.steps {
        assert!(
            !step.formula.is_empty() && !step.substituted.is_empty(),
            "{}",
            step.title
        );
    }
    assert!(s.steps[3]
        .substituted
        .contains(r"195 \times 0.04233333 = 8.255"));
}

#[test]
fn example_2_gsd_exact_values_and_printed_ones() {
    let s = solve("gsd", &Record::new()).unwrap();
    assert_close(&s, "scale_denominator", 1920.0 / 0.152, 1e-9);
    assert_close(&s, "pixel_size_mm", 25.4 / 900.0, 1e-15);
    assert_close(&s, "gsd_mm", 356.491_228, 1e-5);
    assert_close(&s, "gsd_cm", 35.649_122_8, 1e-6);
    assert_eq!(printed(&s, "scale_denominator"), 12632.0);
    assert_eq!(printed(&s, "gsd_cm"), 35.37);
    assert!(has_note(
        &s,
        NoteKind::Rounding,
        "0.028 × 12632 = 353.696 mm"
    ));
    let keys: Vec<_> = s.result.keys().collect();
    assert_eq!(
        keys,
        ["scale_denominator", "pixel_size_mm", "gsd_mm", "gsd_cm"]
    );
}

#[test]
fn example_3_photo_to_pixel_exact_values_and_the_sign_slip() {
    let s = solve("photo-to-pixel", &Record::new()).unwrap();
    let p = 25.4 / 600.0;
    assert_close(&s, "c0", 900.0, 0.0);
    assert_close(&s, "r0", 750.0, 0.0);
    assert_close(&s, "dc_px", -12.42 / p, 1e-9);
    assert_close(&s, "dr_px", 25.36 / p, 1e-9);
    assert_close(&s, "c", 606.614_173, 1e-6);
    assert_close(&s, "r", 1_349.055_118, 1e-6);
    assert_eq!(printed(&s, "c"), 604.3);
    assert_eq!(printed(&s, "r"), 1353.8);
    assert_eq!(printed(&s, "dr_px"), -603.8);
    assert!(has_note(
        &s,
        NoteKind::Erratum,
        "row offset is −y/p = +603.8"
    ));
    assert!(has_note(&s, NoteKind::Rounding, "c = 604.3 and r = 1353.8"));
}

#[test]
fn every_result_key_is_labelled_for_the_page() {
    for id in ["pixel-to-photo", "gsd", "photo-to-pixel"] {
        let s = solve(id, &Record::new()).unwrap();
        for key in s.result.keys() {
            assert!(s.labels.get(key).is_some(), "{id}: {key} has no label");
        }
    }
    let s = solve("gsd", &Record::new()).unwrap();
    let Some(Value::Object(l)) = s.labels.get("gsd_cm") else {
        panic!("gsd_cm label missing")
    };
    assert_eq!(l.get("unit"), Some(&Value::from("cm")));
}

#[test]
fn what_if_inputs_take_defaults_for_the_rest_and_drop_the_textbook() {
    let s = solve("gsd", &Record::new().with("dpi", 1200.0)).unwrap();
    assert_close(&s, "gsd_cm", 25.4 / 1200.0 * (1920.0 / 0.152) / 10.0, 1e-9);
    assert_eq!(s.inputs.number("focal_length_mm"), Some(152.0));
    assert!(s.textbook.is_none());
    assert!(s.notes.iter().all(|n| n.kind != NoteKind::Rounding));

    let s = solve("gsd", &Record::new().with("flying_height_m", 2400.0)).unwrap();
    assert_close(&s, "gsd_cm", 25.4 / 900.0 * (2400.0 / 0.152) / 10.0, 1e-9);

    // round trip: Example 1's answer fed to Example 3's solver
    let a = solve(
        "pixel-to-photo",
        &Record::new().with("c", 12.5).with("r", 1399.0),
    )
    .unwrap();
    let b = solve(
        "photo-to-pixel",
        &Record::new()
            .with("columns", 1600.0)
            .with("rows", 1400.0)
            .with("x_mm", result(&a, "x_mm"))
            .with("y_mm", result(&a, "y_mm")),
    )
    .unwrap();
    assert_close(&b, "c", 12.5, 1e-9);
    assert_close(&b, "r", 1399.0, 1e-9);
}

#[test]
fn a_point_outside_the_image_is_allowed_but_noted() {
    let s = solve("pixel-to-photo", &Record::new().with("c", 1700.0)).unwrap();
    assert_close(&s, "x_mm", 900.0 * 25.4 / 600.0, 1e-9);
    assert!(has_note(&s, NoteKind::Warning, "outside"));
    let s = solve("photo-to-pixel", &Record::new().with("y_mm", -40.0)).unwrap();
    assert!(has_note(&s, NoteKind::Warning, "outside"));
    let inside = solve("pixel-to-photo", &Record::new()).unwrap();
    assert!(!has_note(&inside, NoteKind::Warning, "outside"));
}

fn err(id: &str, inputs: Record) -> String {
    solve(id, &inputs).expect_err("should fail").to_string()
}

#[test]
fn bad_inputs_name_the_field_and_say_what_is_wrong() {
    let r = Record::new;
    assert_eq!(
        err("gsd", r().with("dpi", 0.0)),
        "dpi: must be greater than 0 dpi (got 0)"
    );
    assert_eq!(
        err("gsd", r().with("dpi", -5.0)),
        "dpi: must be greater than 0 dpi (got -5)"
    );
    assert_eq!(
        err("gsd", r().with("focal_length_mm", -152.0)),
        "focal_length_mm: must be greater than 0 mm (got -152)"
    );
    assert_eq!(
        err("gsd", r().with("flying_height_m", 0.0)),
        "flying_height_m: must be greater than 0 m (got 0)"
    );
    assert_eq!(
        err("pixel-to-photo", r().with("columns", 0.0)),
        "columns: must be at least 1 (got 0)"
    );
    assert_eq!(
        err("photo-to-pixel", r().with("rows", -3.0)),
        "rows: must be at least 1 (got -3)"
    );
    assert_eq!(
        err("pixel-to-photo", r().with("columns", 16.5)),
        "columns: must be a whole number (got 16.5)"
    );
    assert_eq!(
        err("gsd", r().with("dpi", f64::NAN)),
        "dpi: is NaN; give a number"
    );
    assert_eq!(
        err("pixel-to-photo", r().with("c", f64::INFINITY)),
        "c: is infinite; give a finite number"
    );
    assert_eq!(
        err("gsd", r().with("dpi", "900")),
        "dpi: must be a number, got the string \"900\""
    );
    assert_eq!(
        err("gsd", r().with("dpi", Value::Null)),
        "dpi: must be a number, got null"
    );
    assert_eq!(
        err("gsd", r().with("altitude", 3.0)),
        "altitude: unknown field (this example takes: dpi, focal_length_mm, flying_height_m)"
    );
    assert_eq!(
        err("no-such-example", r()),
        "unknown example id \"no-such-example\" (see catalog() for the ids)"
    );
    if let Some(e) = catalog().into_iter().find(|e| e.status == "coming") {
        let expected = format!("example \"{}\" is not built yet", e.id);
        assert_eq!(err(e.id, r()), expected);
    }
}

#[test]
fn parse_inputs_reports_every_bad_field_at_once() {
    let texts = Record::new()
        .with("dpi", "abc")
        .with("focal_length_mm", "-1")
        .with("flying_height_m", " 2400 ")
        .with("<img src=x>", "1");
    let p = parse_inputs("gsd", &texts).unwrap();
    assert_eq!(p.inputs.number("flying_height_m"), Some(2400.0));
    assert_eq!(p.inputs.len(), 1);
    assert_eq!(p.errors.len(), 3);
    assert_eq!(
        p.errors.get("dpi"),
        Some(&Value::from("dpi: \"abc\" is not a number"))
    );
    assert!(p.errors.get("<img src=x>").is_some());
    // what parses, solves; text and typed inputs agree
    let ok = parse_inputs("gsd", &Record::new().with("dpi", "1200")).unwrap();
    assert!(ok.errors.is_empty());
    assert_eq!(
        solve("gsd", &ok.inputs).unwrap().result,
        solve("gsd", &Record::new().with("dpi", 1200.0))
            .unwrap()
            .result
    );
}

#[test]
fn catalog_lists_every_catalog_md_entry_with_fields_for_the_built_ones() {
    let ids = [
        "pixel-to-photo",
        "gsd",
        "photo-to-pixel",
        "fiducial-similarity",
        "fiducial-affine",
        "transform-fit",
        "ncc-1d",
        "ncc-2d",
        "ncc-surface",
        "subpixel-1d",
        "subpixel-2d",
        "lsm-1d",
        "lsm-2d",
        "lsm-affine",
        "resample",
        "filter-window",
        "edge-window",
        "forstner-window",
        "moravec-window",
        "forstner-image",
        "chain-code",
        "boundary-length",
        "boundary-shape",
        "utm",
        "utm-inverse",
        "utm-facts",
    ];
    // the ids of ../shared/CATALOG.md: each is in the catalog (which may have more)
    let cat = catalog();
    assert!(cat.len() >= ids.len());
    for id in ids {
        assert!(
            cat.iter().any(|e| e.id == id),
            "{id} missing from the catalog"
        );
    }
    for e in &cat {
        let built = e.status == "ready";
        assert_eq!(built, !e.inputs.is_empty(), "{}", e.id);
        if built {
            // every built entry solves with its defaults, and each
            // default's text parses back to the default
            let solved = solve(e.id, &Record::new()).unwrap();
            // every result and every printed value (intermediates too)
            // the page lists has a human label
            let printed = solved.textbook.iter().flat_map(|t| t.keys());
            for key in solved.result.keys().chain(printed) {
                assert!(
                    solved.labels.get(key).is_some(),
                    "{}: result {key} has no label",
                    e.id
                );
            }
            let defaults = solved.inputs;
            let mut texts = Record::new();
            for f in &e.inputs {
                texts.set(f.key, f.default_text.as_str());
            }
            let parsed = parse_inputs(e.id, &texts).unwrap();
            assert!(parsed.errors.is_empty(), "{}: {:?}", e.id, parsed.errors);
            assert_eq!(parsed.inputs, defaults, "{}", e.id);
        }
    }
}

mod parts_common;

/// Issue 30, item 2: every step is data (its LaTeX made from its parts) and
/// every practice box's hints come from the relation keyed with its value.
#[test]
fn steps_are_data_and_hints_are_keyed() {
    let with_numbers = parts_common::steps_are_data_and_hints_are_keyed(
        &photogrammetry_playground::examples::coordinates::TOPIC,
        20,
    );
    // every box of the three examples (7 + 4 + 7) shows its numbers
    assert_eq!(with_numbers, 20 * 18);
    let s = solve("gsd", &Record::new()).unwrap();
    assert_eq!(
        s.steps[2].substituted,
        r"\text{GSD} = 0.02822222 \times 12631.58 = 356.4912\,\text{mm},\quad \text{GSD} = \frac{356.4912\,\text{mm}}{10} = 35.64912\,\text{cm}"
    );
    let s = solve("photo-to-pixel", &Record::new()).unwrap();
    assert_eq!(
        s.steps[2].formula,
        r"\Delta c = \frac{x}{p},\quad \Delta r = -\frac{y}{p}"
    );
    assert_eq!(
        s.steps[2].parts[1].question_latex(),
        r"\Delta r = -\frac{-25.36}{0.04233333} = \;?"
    );
}
