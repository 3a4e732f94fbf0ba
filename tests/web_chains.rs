//! Chain codes across the wasm boundary in headless Chromium: Example 17, the
//! exercise, Example 18 and the descriptors as the page gets them; broken,
//! branching and single-pixel paths as documented answers; bad input as JS
//! `Error`s; a module that keeps answering.
#![cfg(target_arch = "wasm32")]

use js_sys::{Array, Error as JsErr, Reflect, JSON};
// The exports as the page's topic module pkg/chains.js (web/chains/) has them.
photogrammetry_playground::export_examples!(photogrammetry_playground::examples::chains::TOPIC);
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

fn list(v: &JsValue, path: &[&str]) -> Vec<f64> {
    let a: Array = at(v, path).dyn_into().expect("an Array");
    a.iter().map(|x| x.as_f64().expect("a number")).collect()
}

fn obj(json: &str) -> JsValue {
    JSON::parse(json).expect("json")
}

fn solve_err(id: &str, inputs: JsValue) -> String {
    let e: JsValue = solve(id.into(), inputs).expect_err("should throw").into();
    let e: JsErr = e.dyn_into().expect("a real JS Error");
    String::from(e.message())
}

fn notes_text(s: &JsValue) -> String {
    let notes: Array = get(s, "notes").dyn_into().unwrap();
    notes
        .iter()
        .map(|n| get(&n, "text").as_string().unwrap_or_default())
        .collect::<Vec<_>>()
        .join("\n")
}

#[wasm_bindgen_test]
fn example_17_and_the_exercise_cross_the_boundary() {
    let s = solve("chain-code".into(), JsValue::UNDEFINED).unwrap();
    let code = [
        1., 8., 8., 8., 7., 1., 1., 2., 3., 4., 4., 2., 1., 1., 2., 2.,
    ];
    assert_eq!(list(&s, &["result", "code"]), code);
    assert_eq!(
        list(&s, &["result", "differential"]),
        [7., 0., 0., 7., 2., 0., 1., 1., 1., 0., 6., 7., 0., 1., 0.]
    );
    assert_eq!(list(&s, &["textbook", "code"]), code);
    let pixels: Array = at(&s, &["result", "pixels"]).dyn_into().unwrap();
    assert_eq!(pixels.length(), 17);
    let s = solve("chain-code".into(), obj(r#"{"from": "end"}"#)).unwrap();
    assert_eq!(
        list(&s, &["result", "code"]),
        [6., 6., 5., 5., 6., 8., 8., 7., 6., 5., 5., 3., 4., 4., 4., 5.]
    );
    assert!(get(&s, "textbook").is_null());
}

#[wasm_bindgen_test]
fn example_18_and_the_descriptors_cross_the_boundary() {
    let s = solve("boundary-length".into(), JsValue::NULL).unwrap();
    assert!((num(&s, &["result", "length"]) - (8.0 + 9.0 * 2f64.sqrt())).abs() < 1e-12);
    assert_eq!(num(&s, &["textbook", "length"]), 20.7);
    let s = solve("boundary-shape".into(), JsValue::UNDEFINED).unwrap();
    assert!((num(&s, &["result", "eccentricity"]) - 2.125).abs() < 1e-12);
    let rect: Array = at(&s, &["result", "basic_rectangle"]).dyn_into().unwrap();
    assert_eq!(rect.length(), 4);
}

#[wasm_bindgen_test]
fn broken_branching_and_single_pixel_paths_are_documented_answers() {
    let s = solve(
        "chain-code".into(),
        obj(r#"{"pixels": [[0,0],[1,0],[3,0]]}"#),
    )
    .unwrap();
    assert!(at(&s, &["result", "code"]).is_null());
    let breaks: Array = at(&s, &["result", "breaks"]).dyn_into().unwrap();
    assert_eq!(breaks.length(), 1);
    assert!(notes_text(&s).contains("pixel 2 (1, 0) and pixel 3 (3, 0) are not neighbours"));
    let s = solve(
        "chain-code".into(),
        obj(r#"{"pixels": [[0,0],[1,0],[2,0],[1,0],[1,1]]}"#),
    )
    .unwrap();
    assert_eq!(list(&s, &["result", "code"]), [1., 1., 5., 7.]);
    assert!(notes_text(&s).contains("pixel 4 (1, 0) is pixel 2 again"));
    // a single pixel: an empty code and zero length, for each example
    let s = solve("chain-code".into(), obj(r#"{"pixels": [[3,3]]}"#)).unwrap();
    assert_eq!(list(&s, &["result", "code"]), Vec::<f64>::new());
    let s = solve("boundary-length".into(), obj(r#"{"pixels": [[3,3]]}"#)).unwrap();
    assert_eq!(num(&s, &["result", "length"]), 0.0);
    let s = solve("boundary-shape".into(), obj(r#"{"pixels": [[3,3]]}"#)).unwrap();
    assert_eq!(num(&s, &["result", "diameter"]), 0.0);
    assert!(at(&s, &["result", "eccentricity"]).is_null());
    let s = solve(
        "chain-code".into(),
        obj(r#"{"given": "region", "pixels": [[0,0],[1,0],[0,1],[1,1]]}"#),
    )
    .unwrap();
    assert_eq!(list(&s, &["result", "code"]), [1., 7., 5., 3.]);
    assert_eq!(at(&s, &["result", "closed"]).as_bool(), Some(true));
}

#[wasm_bindgen_test]
fn bad_inputs_are_js_errors_and_the_module_keeps_answering() {
    assert_eq!(
        solve_err("chain-code", obj(r#"{"given": "code", "code": [1, 9]}"#)),
        "code: digit 2 is 9; with 8-connectivity the directions are 1 to 8"
    );
    assert!(solve_err("chain-code", obj(r#"{"pixels": []}"#)).starts_with("pixels: is empty"));
    assert_eq!(
        solve_err("chain-code", obj(r#"{"pixels": [[0.5, 1]]}"#)),
        "pixels: point 1 must be whole pixel positions (got 0.5)"
    );
    assert_eq!(
        solve_err("boundary-length", obj(r#"{"connectivity": 6}"#)),
        "connectivity: 6 is not one of the choices (8, 4)"
    );
    assert!(
        solve_err("boundary-length", obj(r#"{"connectivity": true}"#))
            .starts_with("connectivity: must be one of the choices")
    );
    assert!(
        solve_err("boundary-shape", obj(r#"{"pixels": [[0,0],[9000,0]]}"#))
            .contains("can be traced")
    );
    // still answering
    let s = solve("chain-code".into(), JsValue::UNDEFINED).unwrap();
    assert_eq!(list(&s, &["result", "code"]).len(), 16);
}

#[wasm_bindgen_test]
fn texts_from_the_form_parse_and_solve() {
    let p = parse_inputs(
        "chain-code".into(),
        obj(r#"{"given": "code", "connectivity": "4", "code": "441121141122233"}"#),
    )
    .unwrap();
    let s = solve("chain-code".into(), get(&p, "inputs")).unwrap();
    assert_eq!(
        list(&s, &["result", "code"]),
        [4., 4., 1., 1., 2., 1., 1., 4., 1., 1., 2., 2., 2., 3., 3.]
    );
    assert!(notes_text(&s).contains("figure c"));
}

#[wasm_bindgen_test]
fn a_numeric_choice_takes_the_number_across_the_boundary() {
    // {connectivity: 4} as a JS number is the choice "4"
    let by_number = solve(
        "boundary-length".into(),
        obj(r#"{"given": "code", "connectivity": 4, "code": [4, 4, 1, 1, 2, 1, 1, 4]}"#),
    )
    .unwrap();
    let by_text = solve(
        "boundary-length".into(),
        obj(r#"{"given": "code", "connectivity": "4", "code": [4, 4, 1, 1, 2, 1, 1, 4]}"#),
    )
    .unwrap();
    assert_eq!(num(&by_number, &["result", "length"]), 8.0);
    assert_eq!(
        num(&by_number, &["result", "length"]),
        num(&by_text, &["result", "length"])
    );
    assert_eq!(
        at(&by_number, &["inputs", "connectivity"])
            .as_string()
            .as_deref(),
        Some("4")
    );
}
