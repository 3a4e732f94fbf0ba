//! Interest operators across the wasm boundary in headless Chromium: the
//! seed examples solve with their numbers as plain JS data, "no value" is a
//! JS null, bad windows arrive as JS Errors naming the field, and the module
//! keeps answering.
#![cfg(target_arch = "wasm32")]

use js_sys::{Array, Error as JsErr, Object, Reflect, JSON};
// The exports as the page's topic module pkg/interest.js (web/interest/) has them.
photogrammetry_playground::export_examples!(photogrammetry_playground::examples::interest::TOPIC);
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
    let rows: Array = v.clone().dyn_into().expect("an Array of rows");
    rows.iter()
        .map(|r| {
            let r: Array = r.dyn_into().expect("a row Array");
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
fn the_interest_entries_are_ready() {
    let cat: Array = catalog().unwrap().dyn_into().unwrap();
    for id in ["forstner-window", "moravec-window", "forstner-image"] {
        let e = cat
            .iter()
            .find(|e| get(e, "id").as_string().as_deref() == Some(id))
            .unwrap_or_else(|| panic!("{id} in the catalog"));
        assert_eq!(get(&e, "status").as_string().as_deref(), Some("ready"));
        assert_eq!(
            get(&e, "topic").as_string().as_deref(),
            Some("Interest operators")
        );
    }
}

#[wasm_bindgen_test]
fn example_13_across_the_boundary() {
    let s = solve("forstner-window".into(), JsValue::UNDEFINED).unwrap();
    let r = get(&s, "result");
    assert_eq!(matrix(&get(&r, "n")), [[82.0, -22.25], [-22.25, 114.75]]);
    assert_eq!(num(&r, &["det_n"]), 8914.4375);
    assert!((num(&r, &["trace_n_inverse"]) - 196.75 / 8914.4375).abs() < 1e-15);
    assert!((num(&r, &["w"]) - 8914.4375 / 196.75).abs() < 1e-12);
    assert_eq!(get(&r, "accepted").as_bool(), Some(true));
    assert_eq!(get(&r, "case").as_string().as_deref(), Some("corner"));
    let t = get(&s, "textbook");
    assert_eq!(num(&t, &["det_n"]), 8891.9375);
    assert_eq!(matrix(&get(&t, "n"))[0][1], -22.75);
    let steps: Array = get(&s, "steps").dyn_into().unwrap();
    let table = matrix(&get(&get(&steps.get(0), "values"), "table"));
    assert_eq!(table[4], [3.0, 3.0, 7.0, -8.0, 2.0, -16.0, 64.0, 4.0]);
    let notes: Array = get(&s, "notes").dyn_into().unwrap();
    assert!(notes.iter().any(|n| {
        get(&n, "kind").as_string().as_deref() == Some("erratum")
            && get(&n, "text").as_string().unwrap().contains("backwards")
    }));
}

#[wasm_bindgen_test]
fn example_14_and_a_flat_window_with_nulls() {
    let s = solve("moravec-window".into(), JsValue::NULL).unwrap();
    assert_eq!(
        matrix(&get(&get(&s, "result"), "sums")),
        [[47.0, 361.0], [153.0, 171.0]]
    );
    assert_eq!(num(&s, &["result", "mean"]), 183.0);
    assert_eq!(num(&s, &["textbook", "mean"]), 183.0);

    let s = solve(
        "forstner-window".into(),
        obj(r#"{"window": [[5,5,5,5,5],[5,5,5,5,5],[5,5,5,5,5],[5,5,5,5,5],[5,5,5,5,5]]}"#),
    )
    .unwrap();
    let r = get(&s, "result");
    for key in ["n_inverse", "trace_n_inverse", "q", "lambda_max_shift"] {
        assert!(get(&r, key).is_null(), "{key} should be null");
    }
    assert_eq!(num(&r, &["w"]), 0.0);
    assert_eq!(get(&r, "case").as_string().as_deref(), Some("flat"));
    assert!(get(&s, "textbook").is_null());
}

#[wasm_bindgen_test]
fn the_image_mode_across_the_boundary() {
    let s = solve("forstner-image".into(), obj(r#"{"c": 16, "r": 9}"#)).unwrap();
    let r = get(&s, "result");
    assert_eq!(get(&r, "case").as_string().as_deref(), Some("edge"));
    assert_eq!(matrix(&get(&r, "window")).len(), 5);
    assert_eq!(matrix(&get(&r, "points")).len(), 14);
    let steps: Array = get(&s, "steps").dyn_into().unwrap();
    let w_map: Array = get(&get(&steps.get(0), "values"), "w_map")
        .dyn_into()
        .unwrap();
    let row: Array = w_map.get(0).dyn_into().unwrap();
    assert!(row.get(0).is_null());
    let row: Array = w_map.get(8).dyn_into().unwrap();
    assert_eq!(row.get(15).as_f64(), Some(num(&r, &["w"])));
}

#[wasm_bindgen_test]
fn bad_windows_are_js_errors_and_the_module_keeps_answering() {
    assert_eq!(
        solve_err("forstner-window", obj(r#"{"window": [[1,2],[3,4]]}"#)),
        "window: is 2×2; the window needs at least 3×3 so that an interior pixel has a neighbour on every side"
    );
    assert_eq!(
        solve_err(
            "moravec-window",
            obj(r#"{"window": [[1,2,3],[4,5],[6,7,8]]}"#)
        ),
        "window: rows must all have the same length: row 1 has 3 numbers, row 2 has 2"
    );
    let nan_window = Array::new();
    for i in 0..3 {
        let row = Array::new();
        for j in 0..3 {
            let v = if (i, j) == (1, 2) { f64::NAN } else { 1.0 };
            row.push(&JsValue::from_f64(v));
        }
        nan_window.push(&row);
    }
    let inputs = Object::new();
    Reflect::set(&inputs, &"window".into(), &nan_window).unwrap();
    assert_eq!(
        solve_err("forstner-window", inputs.into()),
        "window[2][3]: is NaN; give a number"
    );
    assert_eq!(
        solve_err("forstner-image", obj(r#"{"window_size": 6}"#)),
        "window_size: must be odd so that the window has a centre pixel (got 6)"
    );
    assert!(solve_err("forstner-image", obj(r#"{"c": 1}"#)).starts_with("c: must be between 3"));
    let p = parse_inputs(
        "forstner-window".into(),
        obj(r#"{"window": "1 2 3; 4 5 6; 7 8"}"#),
    )
    .unwrap();
    assert!(get(&get(&p, "errors"), "window")
        .as_string()
        .unwrap()
        .contains("same length"));
    // each class for the other operator too
    assert!(
        solve_err("moravec-window", obj(r#"{"window": [[1,2],[3,4]]}"#))
            .starts_with("window: is 2×2; the window needs at least 3×3")
    );
    assert!(solve_err(
        "forstner-window",
        obj(r#"{"window": [[1,2,3],[4,5],[6,7,8]]}"#)
    )
    .starts_with("window: rows must all have the same length"));
    let nan_inputs = Object::new();
    Reflect::set(&nan_inputs, &"window".into(), &nan_window).unwrap();
    assert_eq!(
        solve_err("moravec-window", nan_inputs.into()),
        "window[2][3]: is NaN; give a number"
    );
    // still answering
    let s = solve("moravec-window".into(), JsValue::UNDEFINED).unwrap();
    assert_eq!(num(&s, &["result", "mean"]), 183.0);
}
