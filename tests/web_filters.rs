//! Resampling, filters and edges across the wasm boundary in headless
//! Chromium: the seed examples solve with their numbers, bad inputs arrive
//! as JS `Error`s naming the field, and the module keeps answering.
#![cfg(target_arch = "wasm32")]

use js_sys::{Array, Error as JsErr, Reflect, JSON};
// The exports of a topic module (web/filters/, web/resampling/), here over
// two topics' entries at once.
photogrammetry_playground::export_examples!(
    photogrammetry_playground::examples::filters::TOPIC,
    photogrammetry_playground::examples::resampling::TOPIC
);
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

fn matrix(v: &JsValue) -> Vec<Vec<f64>> {
    let rows: Array = v.clone().dyn_into().expect("an array of rows");
    rows.iter()
        .map(|r| {
            let r: Array = r.dyn_into().expect("a row");
            r.iter().map(|x| x.as_f64().expect("a number")).collect()
        })
        .collect()
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
fn the_three_entries_are_ready_with_typed_fields() {
    let cat: Array = catalog().unwrap().dyn_into().unwrap();
    for id in ["resample", "filter-window", "edge-window"] {
        let e = cat
            .iter()
            .find(|e| get(e, "id").as_string().as_deref() == Some(id))
            .expect("in the catalog");
        assert_eq!(get(&e, "status").as_string().as_deref(), Some("ready"));
    }
    let f = cat
        .iter()
        .find(|e| get(e, "id").as_string().as_deref() == Some("filter-window"))
        .unwrap();
    let inputs: Array = get(&f, "inputs").dyn_into().unwrap();
    let window = inputs.get(0);
    assert_eq!(get(&window, "kind").as_string().as_deref(), Some("matrix"));
    assert_eq!(
        get(&window, "default_text").as_string().as_deref(),
        Some("10, 13, 3, 11, 13; 11, 15, 10, 9, 9; 9, 24, 7, 8, 10; 10, 13, 14, 15, 13; 13, 18, 17, 19, 21")
    );
    let kernel = inputs.get(1);
    assert_eq!(get(&kernel, "kind").as_string().as_deref(), Some("choice"));
}

#[wasm_bindgen_test]
fn example_12a_across_the_boundary() {
    let s = solve("resample".into(), JsValue::UNDEFINED).unwrap();
    assert_eq!(num(&s, &["result", "nearest"]), 72.0);
    assert!((num(&s, &["result", "bilinear"]) - 75.3584).abs() < 1e-9);
    assert!(get(&get(&s, "result"), "bicubic").is_null());
    assert_eq!(num(&s, &["textbook", "bilinear"]), 75.35);
    let s = solve("resample".into(), obj(r#"{"c": 546.5, "r": 818.5}"#)).unwrap();
    // weights −0.125, 0.625, 0.625, −0.125 at s = t = 0.5 (a = −1):
    // rows 66.625, 75.875, 67.625, 57.375, then 74.1875
    assert!((num(&s, &["result", "bicubic"]) - 74.1875).abs() < 1e-9);
    assert!(get(&s, "textbook").is_null());
}

#[wasm_bindgen_test]
fn examples_15_and_16_across_the_boundary() {
    let s = solve("filter-window".into(), JsValue::UNDEFINED).unwrap();
    let out = matrix(&get(&get(&s, "result"), "output"));
    assert!((out[2][0] - 125.0 / 9.0).abs() < 1e-12);
    assert_eq!(matrix(&get(&get(&s, "textbook"), "output"))[2][0], 12.9);
    let s = solve(
        "filter-window".into(),
        obj(r#"{"window": [[1,2,1,1,1],[1,1,9,2,1],[1,9,9,8,1],[1,1,8,1,2],[2,1,1,1,1]], "kernel": "laplacian-8"}"#),
    )
    .unwrap();
    assert_eq!(
        matrix(&get(&get(&s, "result"), "output")),
        vec![
            vec![25.0, -39.0, 15.0],
            vec![-41.0, -33.0, -31.0],
            vec![24.0, -33.0, 23.0]
        ]
    );
    let s = solve("edge-window".into(), obj(r#"{"operator": "sobel"}"#)).unwrap();
    assert_eq!(matrix(&get(&get(&s, "result"), "gx"))[2][2], -43.0);
    assert_eq!(num(&s, &["result", "selected_gy"]), -11.0);
}

#[wasm_bindgen_test]
fn bad_inputs_are_js_errors_and_the_module_keeps_answering() {
    assert_eq!(
        solve_err("resample", obj(r#"{"c": 600}"#)),
        "c: 600 is outside the patch: its pixel centres run from column 545 to 548"
    );
    assert!(solve_err("resample", obj(r#"{"r": 700}"#)).starts_with("r: 700 is outside the patch"));
    assert!(solve_err("resample", obj(r#"{"patch": [[1,2,3],[4,5]]}"#))
        .starts_with("patch: rows must all have the same length"));
    assert!(solve_err("filter-window", obj(r#"{"window": []}"#)).starts_with("window: is empty"));
    assert!(
        solve_err("edge-window", obj(r#"{"window": [[1,2,3],[4]]}"#))
            .starts_with("window: rows must all have the same length")
    );
    assert_eq!(
        solve_err(
            "filter-window",
            obj(r#"{"kernel": "custom", "custom_kernel": [[1,1],[1,1]]}"#)
        ),
        "custom_kernel: is 2×2; a kernel needs an odd number of rows and of columns, so that it has a centre pixel"
    );
    assert!(solve_err(
        "filter-window",
        obj(r#"{"kernel": "custom", "custom_kernel": []}"#)
    )
    .starts_with("custom_kernel: is empty"));
    assert_eq!(
        solve_err("filter-window", obj(r#"{"select_c": 9}"#)),
        "select_c: column 9 is outside the window (it has 5 columns)"
    );
    let s = solve("filter-window".into(), JsValue::UNDEFINED).unwrap();
    assert!((num(&s, &["result", "selected"]) - 102.0 / 9.0).abs() < 1e-12);
}
