//! Least-squares matching across the wasm boundary in headless Chromium:
//! the seed's Examples 10–11, every way a run can end, and errors as JS
//! `Error`s with the module answering afterwards.
#![cfg(target_arch = "wasm32")]

use js_sys::{Array, Error as JsErr, Reflect, JSON};
// The exports as the page's topic module pkg/matching.js (web/matching/) has them.
photogrammetry_playground::export_examples!(photogrammetry_playground::examples::matching::TOPIC);
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

fn get(v: &JsValue, key: &str) -> JsValue {
    Reflect::get(v, &JsValue::from_str(key)).expect("property")
}

fn num(v: &JsValue, path: &[&str]) -> f64 {
    let mut cur = v.clone();
    for k in path {
        cur = get(&cur, k);
    }
    cur.as_f64()
        .unwrap_or_else(|| panic!("{path:?} is not a number"))
}

fn text(v: &JsValue, path: &[&str]) -> String {
    let mut cur = v.clone();
    for k in path {
        cur = get(&cur, k);
    }
    cur.as_string()
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
fn example_10_across_the_boundary() {
    let s = solve("lsm-1d".into(), JsValue::UNDEFINED).unwrap();
    assert!((num(&s, &["result", "first_dc"]) + 11.5 / 39.0).abs() < 1e-12);
    assert!(get(&get(&s, "result"), "first_da").is_null());
    assert_eq!(get(&get(&s, "result"), "converged").as_bool(), Some(true));
    assert_eq!(num(&s, &["result", "iterations"]), 13.0);
    assert!((num(&s, &["result", "c"]) - 7.769_971).abs() < 2e-4);
    assert_eq!(num(&s, &["textbook", "first_dc"]), -0.2945);
    let s = solve("lsm-1d".into(), obj(r#"{"radiometric": true}"#)).unwrap();
    assert!((num(&s, &["result", "first_da"]) - 5.0 / 32.0).abs() < 1e-12);
    assert_eq!(num(&s, &["result", "iterations"]), 7.0);
}

#[wasm_bindgen_test]
fn example_11_both_readings() {
    let s = solve("lsm-2d".into(), JsValue::UNDEFINED).unwrap();
    assert!((num(&s, &["result", "first_dc"]) - 0.186_049_4).abs() < 1e-6);
    assert!((num(&s, &["result", "c"]) - 3.163_718).abs() < 2e-4);
    assert_eq!(num(&s, &["result", "iterations"]), 11.0);
    let s = solve("lsm-2d".into(), obj(r#"{"gradients": "patch-edge"}"#)).unwrap();
    assert!((num(&s, &["result", "first_dc"]) - 0.193_654_5).abs() < 1e-6);
    assert!((num(&s, &["result", "first_db"]) + 5.372_021).abs() < 1e-5);
    assert_eq!(num(&s, &["result", "iterations"]), 81.0);
    assert!((num(&s, &["result", "c"]) - 3.163_852).abs() < 3e-4);
    assert!((num(&s, &["result", "r"]) - 4.106_619).abs() < 3e-4);
    // the iteration table carries one patch per iteration for the figures
    let steps: Array = get(&s, "steps").dyn_into().unwrap();
    let table = steps
        .iter()
        .find(|st| text(st, &["title"]) == "Every iteration")
        .expect("iteration table");
    let patches: Array = get(&get(&table, "values"), "patches").dyn_into().unwrap();
    assert_eq!(patches.length(), 81);
}

#[wasm_bindgen_test]
fn every_end_status_arrives() {
    let s = solve(
        "lsm-1d".into(),
        obj(r#"{"search": [5,5,5,5,5,5,5,5,5,5,5,5]}"#),
    )
    .unwrap();
    assert_eq!(text(&s, &["result", "status"]), "degenerate");
    assert!(get(&get(&s, "result"), "first_dc").is_null());
    let s = solve(
        "lsm-2d".into(),
        obj(r#"{"gradients": "patch-edge", "max_iterations": 30}"#),
    )
    .unwrap();
    assert_eq!(text(&s, &["result", "status"]), "not-converged");
    assert_eq!(get(&get(&s, "result"), "converged").as_bool(), Some(false));
    let s = solve("lsm-affine".into(), obj(r#"{"shift_c": 6, "shift_r": 0}"#)).unwrap();
    assert_eq!(text(&s, &["result", "status"]), "left-window");
    let s = solve(
        "lsm-affine".into(),
        obj(r#"{"shift_c": 3, "shift_r": 1.5, "rotation_deg": 35}"#),
    )
    .unwrap();
    assert_eq!(text(&s, &["result", "status"]), "not-converged");
    let s = solve("lsm-1d".into(), obj(r#"{"c0": 4}"#)).unwrap();
    assert_eq!(text(&s, &["result", "status"]), "left-window");
    let s = solve("lsm-affine".into(), JsValue::UNDEFINED).unwrap();
    assert_eq!(text(&s, &["result", "status"]), "converged");
    let est: Array = get(&get(&s, "result"), "parameters").dyn_into().unwrap();
    assert_eq!(est.length(), 8);
    assert!((est.get(6).as_f64().unwrap() - 1.2).abs() < 1e-3);
}

#[wasm_bindgen_test]
fn bad_inputs_are_js_errors_and_the_module_keeps_answering() {
    assert!(solve_err("lsm-1d", obj(r#"{"c0": 2}"#))
        .starts_with("c0: the patch does not fit at the start"));
    assert!(solve_err("lsm-2d", obj(r#"{"gradients": "sobel"}"#))
        .starts_with("gradients: \"sobel\" is not one of the choices"));
    assert!(solve_err("lsm-affine", obj(r#"{"patch_size": 20}"#))
        .starts_with("patch_size: must be odd"));
    assert!(solve_err("lsm-2d", obj(r#"{"template": [[1, 2], [3]]}"#))
        .starts_with("template: rows must all have the same length"));
    let s = solve("lsm-1d".into(), JsValue::UNDEFINED).unwrap();
    assert_eq!(num(&s, &["result", "iterations"]), 13.0);
}
