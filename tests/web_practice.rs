//! Practice mode across the wasm boundary in headless Chromium: a variant
//! by code, grading of a right answer, a malformed number, an empty box, a
//! known mistake; bad ids, codes and answers as JS `Error`s, never a trap.
#![cfg(target_arch = "wasm32")]

use js_sys::{Error as JsErr, Reflect, JSON};
// The exports as the page's pkg/all.js has them (web/all/): every example
// and practice mode.
photogrammetry_playground::export_all!();
use wasm_bindgen::{JsCast, JsError, JsValue};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

fn at(v: &JsValue, path: &[&str]) -> JsValue {
    path.iter().fold(v.clone(), |cur, k| {
        Reflect::get(&cur, &JsValue::from_str(k)).expect("property")
    })
}

fn text(v: &JsValue, path: &[&str]) -> String {
    at(v, path)
        .as_string()
        .unwrap_or_else(|| panic!("{path:?} is not a string"))
}

fn obj(json: &str) -> JsValue {
    JSON::parse(json).expect("json")
}

fn message(e: JsError) -> String {
    let e: JsValue = e.into();
    let e: JsErr = e.dyn_into().expect("a real JS Error");
    String::from(e.message())
}

#[wasm_bindgen_test]
fn a_code_gives_the_same_variant_and_solve_accepts_its_inputs() {
    let a = practice("gsd".into(), JsValue::from_str("1K7Q2")).unwrap();
    let b = practice("gsd".into(), JsValue::from_str("1k7q2")).unwrap();
    assert_eq!(text(&a, &["code"]), "1K7Q2");
    assert_eq!(
        JSON::stringify(&at(&a, &["inputs"])).unwrap(),
        JSON::stringify(&at(&b, &["inputs"])).unwrap()
    );
    let s = solve("gsd".into(), at(&a, &["inputs"])).unwrap();
    assert!(at(&s, &["result", "gsd_cm"]).as_f64().unwrap() > 0.0);
    assert_eq!(text(&a, &["boxes", "0", "key"]), "scale_denominator");
    assert_eq!(text(&a, &["boxes", "1", "unit"]), "mm");
    // A fresh variant has a code that gives it back.
    let f = practice("ncc-1d".into(), JsValue::UNDEFINED).unwrap();
    let again = practice("ncc-1d".into(), at(&f, &["code"])).unwrap();
    assert_eq!(
        JSON::stringify(&at(&f, &["inputs"])).unwrap(),
        JSON::stringify(&at(&again, &["inputs"])).unwrap()
    );
}

#[wasm_bindgen_test]
fn grading_reads_names_and_never_traps() {
    let p = practice("gsd".into(), JsValue::from_str("1K7Q2")).unwrap();
    let s = solve("gsd".into(), at(&p, &["inputs"])).unwrap();
    let m = at(&s, &["result", "scale_denominator"]).as_f64().unwrap();
    let f = at(&s, &["inputs", "focal_length_mm"]).as_f64().unwrap();
    let h = at(&s, &["inputs", "flying_height_m"]).as_f64().unwrap();
    let answers = obj(&format!(
        r#"{{"scale_denominator": "{}", "pixel_size_mm": "0,0.3", "gsd_mm": "", "gsd_cm": "{}"}}"#,
        format!("{m:.2}").replace('.', ","),
        h / f
    ));
    let g = grade("gsd".into(), "1K7Q2".into(), answers).unwrap();
    assert_eq!(
        text(&g, &["boxes", "scale_denominator", "verdict"]),
        "correct"
    );
    assert_eq!(
        text(&g, &["boxes", "pixel_size_mm", "verdict"]),
        "unreadable"
    );
    assert!(text(&g, &["boxes", "pixel_size_mm", "message"]).contains("not counted as wrong"));
    assert_eq!(text(&g, &["boxes", "gsd_mm", "verdict"]), "empty");
    // H/f with f left in millimetres is a named mistake in the scale box,
    // not in gsd_cm: there it is just wrong.
    assert_eq!(text(&g, &["boxes", "gsd_cm", "verdict"]), "wrong");
    assert_eq!(at(&g, &["score"]).as_f64(), Some(1.0));
    assert_eq!(at(&g, &["out_of"]).as_f64(), Some(4.0));
    let mistake = obj(&format!(r#"{{"scale_denominator": "{}"}}"#, h / f));
    let g = grade("gsd".into(), "1K7Q2".into(), mistake).unwrap();
    assert_eq!(
        text(&g, &["boxes", "scale_denominator", "mistake"]),
        "millimetres vs metres"
    );
}

#[wasm_bindgen_test]
fn bad_input_is_a_clear_error() {
    let e = message(practice("gsd".into(), JsValue::from_str("ZZ")).unwrap_err());
    assert!(e.starts_with("code:"), "{e}");
    let e = message(practice("gsd".into(), JsValue::from_f64(5.0)).unwrap_err());
    assert!(e.starts_with("code: must be a string"), "{e}");
    let e = message(practice("no-such".into(), JsValue::NULL).unwrap_err());
    assert!(e.contains("unknown example"), "{e}");
    let e = message(grade("gsd".into(), "1K7Q2".into(), obj(r#"{"nope": "1"}"#)).unwrap_err());
    assert!(e.starts_with("answers.nope:"), "{e}");
    let e = message(grade("gsd".into(), "1K7Q2".into(), obj(r#"{"gsd_mm": [1]}"#)).unwrap_err());
    assert!(e.contains("must be a string"), "{e}");
    let e = message(grade("gsd".into(), "1K7Q2".into(), JsValue::from_f64(3.0)).unwrap_err());
    assert!(e.starts_with("answers:"), "{e}");
    // Still answering after the errors.
    let g = grade("gsd".into(), "1K7Q2".into(), JsValue::UNDEFINED).unwrap();
    assert_eq!(text(&g, &["boxes", "gsd_cm", "verdict"]), "empty");
}

#[wasm_bindgen_test]
fn utm_practice_carries_the_students_zone_forward() {
    let p = practice("utm".into(), JsValue::from_str("1K7Q2")).unwrap();
    assert_eq!(text(&p, &["boxes", "0", "key"]), "zone");
    assert_eq!(text(&p, &["boxes", "8", "key"]), "easting");
    assert_eq!(text(&p, &["boxes", "8", "tolerance_text"]), "± 0.01 m");
    assert_eq!(text(&p, &["boxes", "6", "tolerance_text"]), "± 10⁻⁹");
    let s = solve("utm".into(), at(&p, &["inputs"])).unwrap();
    let zone = at(&s, &["result", "zone"]).as_f64().unwrap();
    // zone off by one, and the central meridian that follows from it
    let answers = obj(&format!(
        r#"{{"zone": "{}", "central_meridian": "{}"}}"#,
        zone + 1.0,
        6.0 * (zone + 1.0) - 183.0
    ));
    let g = grade("utm".into(), "1K7Q2".into(), answers).unwrap();
    assert_eq!(text(&g, &["boxes", "zone", "verdict"]), "wrong");
    assert_eq!(
        text(&g, &["boxes", "central_meridian", "verdict"]),
        "consistent"
    );
    assert!(text(&g, &["boxes", "central_meridian", "message"]).contains("Zone (step 1)"));
    // the −3 left out is named
    let g = grade(
        "utm".into(),
        "1K7Q2".into(),
        obj(&format!(
            r#"{{"central_meridian": "{}"}}"#,
            6.0 * zone - 180.0
        )),
    )
    .unwrap();
    assert_eq!(
        text(&g, &["boxes", "central_meridian", "mistake"]),
        "6·zone − 180 without the −3"
    );
}

#[wasm_bindgen_test]
fn utm_facts_has_variants_and_separate_verdicts_cross_the_boundary() {
    let p = practice("utm-facts".into(), JsValue::from_str("1K7Q2")).unwrap();
    let lat = at(&p, &["inputs", "latitude"]).as_f64().unwrap();
    assert!((0.5..=79.5).contains(&lat.abs()), "{lat}");
    assert!(at(&p, &["inputs", "ellipsoid"]).as_string().is_some());
    let s = solve("utm-facts".into(), at(&p, &["inputs"])).unwrap();
    let x1 = at(&s, &["result", "k1_distance_km"]).as_f64().unwrap();
    // the lecture's 90 km, named; the value off, the unit taken as the box's
    let g = grade(
        "utm-facts".into(),
        "1K7Q2".into(),
        obj(&format!(
            r#"{{"k1_distance_km": "90", "zone_width_km": "{x1} ppm"}}"#
        )),
    )
    .unwrap();
    let b = ["boxes", "k1_distance_km"];
    assert_eq!(text(&g, &[b[0], b[1], "verdict"]), "wrong");
    assert_eq!(text(&g, &[b[0], b[1], "mistake"]), "the lecture's 90 km");
    assert_eq!(text(&g, &[b[0], b[1], "value"]), "off");
    assert_eq!(text(&g, &[b[0], b[1], "unit"]), "omitted");
    // a unit that does not fit the box: unit "wrong"
    assert_eq!(text(&g, &["boxes", "zone_width_km", "unit"]), "wrong");
}
