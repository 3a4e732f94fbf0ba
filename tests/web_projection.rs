//! UTM across the wasm boundary in headless Chromium: the worked examples as
//! the page gets them (plain JS data, DMS texts parsed, the figure's data),
//! the checkpoint 55°N 12°E, bad input as JS `Error`s naming the field, and
//! a module that keeps answering.
#![cfg(target_arch = "wasm32")]

use js_sys::{Array, Error as JsErr, Object, Reflect, JSON};
// The exports as the page's topic module pkg/projection.js (web/projection/) has them.
photogrammetry_playground::export_examples!(photogrammetry_playground::examples::projection::TOPIC);
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

fn get(v: &JsValue, key: &str) -> JsValue {
    Reflect::get(v, &JsValue::from_str(key)).expect("property")
}

fn at(v: &JsValue, path: &[&str]) -> JsValue {
    path.iter().fold(v.clone(), |cur, k| get(&cur, k))
}

fn num(v: &JsValue, path: &[&str]) -> f64 {
    at(v, path)
        .as_f64()
        .unwrap_or_else(|| panic!("{path:?} is not a number"))
}

fn string(v: &JsValue, path: &[&str]) -> String {
    at(v, path)
        .as_string()
        .unwrap_or_else(|| panic!("{path:?} is not a string"))
}

fn obj(json: &str) -> JsValue {
    JSON::parse(json).expect("json")
}

fn solve_err(id: &str, inputs: JsValue) -> String {
    let e: JsValue = solve(id.into(), inputs).expect_err("should throw").into();
    let e: JsErr = e.dyn_into().expect("a real JS Error");
    String::from(e.message())
}

#[wasm_bindgen_test]
fn utm_default_and_the_checkpoint_in_the_browser() {
    let s = solve("utm".into(), JsValue::UNDEFINED).unwrap();
    assert!(s.is_instance_of::<Object>());
    // GeoConvert: 47n 662176.290477 1520582.494360
    assert_eq!(num(&s, &["result", "zone"]), 47.0);
    assert_eq!(string(&s, &["result", "band"]), "P");
    assert_eq!(string(&s, &["result", "hemisphere"]), "north");
    assert!((num(&s, &["result", "easting"]) - 662_176.290_477).abs() < 1e-6);
    assert!((num(&s, &["result", "northing"]) - 1_520_582.494_360).abs() < 1e-6);
    assert_eq!(num(&s, &["textbook", "zone"]), 47.0);
    assert_eq!(string(&s, &["labels", "easting", "unit"]), "m");
    let c = solve(
        "utm".into(),
        obj(r#"{"latitude": 55, "longitude": 12, "ellipsoid": "grs80", "zone": 32}"#),
    )
    .unwrap();
    assert!((num(&c, &["result", "easting"]) - 691_875.632).abs() < 5e-4);
    assert!((num(&c, &["result", "northing"]) - 6_098_907.825).abs() < 5e-4);
    assert!(at(&c, &["textbook"]).is_null());
    // the figure's data arrive as arrays of arrays of numbers
    let steps: Array = get(&s, "steps").dyn_into().unwrap();
    let fig = steps.get(steps.length() - 1);
    let merids: Array = at(&fig, &["values", "meridians"]).dyn_into().unwrap();
    assert_eq!(merids.length(), 7);
    let first: Array = merids.get(0).dyn_into().unwrap();
    let pt: Array = first.get(0).dyn_into().unwrap();
    assert_eq!(pt.length(), 2);
    assert!(pt.get(0).as_f64().unwrap() > 100.0);
    let k: Array = at(&fig, &["values", "k_profile"]).dyn_into().unwrap();
    assert_eq!(k.length(), 141);
}

#[wasm_bindgen_test]
fn dms_texts_parse_and_the_inverse_returns_the_point() {
    let p = parse_inputs(
        "utm".into(),
        obj(r#"{"latitude": "55°00'00\"N", "longitude": "12 0 0 E", "ellipsoid": "grs80", "zone": "32"}"#),
    )
    .unwrap();
    let errors: Array = Object::keys(&get(&p, "errors").dyn_into::<Object>().unwrap());
    assert_eq!(errors.length(), 0);
    assert_eq!(num(&p, &["inputs", "latitude"]), 55.0);
    let s = solve("utm".into(), get(&p, "inputs")).unwrap();
    let back = solve(
        "utm-inverse".into(),
        obj(&format!(
            r#"{{"zone": 32, "hemisphere": "U", "easting": {}, "northing": {}, "ellipsoid": "grs80"}}"#,
            num(&s, &["result", "easting"]),
            num(&s, &["result", "northing"])
        )),
    )
    .unwrap();
    assert!((num(&back, &["result", "latitude"]) - 55.0).abs() < 1e-9);
    assert!((num(&back, &["result", "longitude"]) - 12.0).abs() < 1e-9);
    let bad = parse_inputs(
        "utm".into(),
        obj(r#"{"latitude": "55 61", "longitude": "12 W E"}"#),
    )
    .unwrap();
    let lat = string(&bad, &["errors", "latitude"]);
    assert!(
        lat.starts_with("latitude: \"55 61\": minutes must be less than 60"),
        "{lat}"
    );
    assert!(string(&bad, &["errors", "longitude"]).starts_with("longitude: "));
}

#[wasm_bindgen_test]
fn bad_input_throws_errors_naming_the_field_and_the_module_keeps_answering() {
    assert_eq!(
        solve_err("utm", obj(r#"{"latitude": 91}"#)),
        "latitude: must be between −90° and 90° (got 91°)"
    );
    assert_eq!(
        solve_err("utm", obj(r#"{"longitude": -180.5}"#)),
        "longitude: must be between −180° and 180° (got -180.5°)"
    );
    assert!(solve_err("utm", obj(r#"{"latitude": 84.5}"#)).contains("UPS"));
    assert!(solve_err("utm", obj(r#"{"latitude": "abc"}"#))
        .starts_with("latitude: \"abc\" is not an angle"));
    assert!(solve_err("utm-inverse", obj(r#"{"hemisphere": "O"}"#))
        .starts_with("hemisphere: \"O\" is not one of the choices"));
    assert_eq!(
        solve_err("utm-inverse", obj(r#"{"easting": 99999}"#)),
        "easting: must be at least 100000 m (got 99999)"
    );
    assert!(solve_err(
        "utm-inverse",
        obj(r#"{"hemisphere": "south", "northing": 10}"#)
    )
    .starts_with("northing: must be between 1 000 000 m"));
    // still answering
    let facts = solve("utm-facts".into(), JsValue::UNDEFINED).unwrap();
    assert!((num(&facts, &["result", "k1_distance_km"]) - 179.754).abs() < 1e-3);
    assert_eq!(num(&facts, &["textbook", "k1_distance_km"]), 90.0);
    let thai: Array = at(&facts, &["result", "zones_thailand"])
        .dyn_into()
        .unwrap();
    assert_eq!(thai.length(), 2);
    let cat: Array = catalog().unwrap().dyn_into().unwrap();
    let utm = cat
        .iter()
        .find(|e| get(e, "id").as_string().as_deref() == Some("utm"))
        .unwrap();
    let lat = Array::from(&get(&utm, "inputs")).get(0);
    assert_eq!(string(&lat, &["kind"]), "angle");
    assert_eq!(string(&lat, &["unit"]), "°");
}
