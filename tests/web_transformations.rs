//! The transformation examples across the wasm boundary in headless
//! Chromium: Example 4 and transform-fit solve, bad point lists arrive as JS
//! `Error`s with their message, and the module keeps answering.
#![cfg(target_arch = "wasm32")]

use js_sys::{Array, Error as JsErr, Reflect, JSON};
// The exports as the page's topic module pkg/transformations.js (web/transformations/) has them.
photogrammetry_playground::export_examples!(
    photogrammetry_playground::examples::transformations::TOPIC
);
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

fn get(v: &JsValue, key: &str) -> JsValue {
    Reflect::get(v, &JsValue::from_str(key)).expect("property")
}

fn numbers(v: &JsValue) -> Vec<f64> {
    let a: Array = v.clone().dyn_into().expect("an Array");
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

#[wasm_bindgen_test]
fn the_catalog_offers_a_point_table_a_model_and_prepared_sets() {
    let cat: Array = catalog().unwrap().dyn_into().unwrap();
    let fit = cat
        .iter()
        .find(|e| get(e, "id").as_string().as_deref() == Some("transform-fit"))
        .expect("transform-fit");
    assert_eq!(get(&fit, "status").as_string().as_deref(), Some("ready"));
    let inputs: Array = get(&fit, "inputs").dyn_into().unwrap();
    let kinds: Vec<(String, String)> = inputs
        .iter()
        .map(|f| {
            (
                get(&f, "key").as_string().unwrap(),
                get(&f, "kind").as_string().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        kinds,
        [
            ("model".to_string(), "choice".to_string()),
            ("point_set".to_string(), "choice".to_string()),
            ("points".to_string(), "points".to_string()),
        ]
    );
    let points = inputs.get(2);
    assert_eq!(get(&points, "point_len").as_f64(), Some(4.0));
    let options: Array = get(&inputs.get(1), "options").dyn_into().unwrap();
    let values: Vec<String> = options
        .iter()
        .map(|o| get(&o, "value").as_string().unwrap())
        .collect();
    assert_eq!(values, ["table", "fiducials", "control-12"]);
}

#[wasm_bindgen_test]
fn example_4_solves_across_the_boundary() {
    let s = solve("fiducial-similarity".into(), JsValue::UNDEFINED).unwrap();
    let x = numbers(&get(&get(&s, "result"), "parameters"));
    assert!((x[0] - 0.042_600_109_339).abs() < 1e-11);
    assert!((x[2] + 115.034_781_491).abs() < 1e-8);
    let v = numbers(&get(&get(&s, "result"), "residuals"));
    assert_eq!(v.len(), 8);
    assert!((v[4] + 0.013_751_727).abs() < 1e-8);
    let s0 = get(&get(&s, "result"), "sigma0").as_f64().unwrap();
    assert!((s0 - 0.009_961_383).abs() < 1e-8);
    assert_eq!(
        numbers(&get(&get(&s, "textbook"), "parameters")),
        [0.043, 0.0, -115.03, 115.04]
    );
    let notes: Array = get(&s, "notes").dyn_into().unwrap();
    assert!(notes.iter().any(
        |n| get(&n, "kind").as_string().as_deref() == Some("erratum")
            && get(&n, "text").as_string().unwrap().contains("y′ = −r")
    ));

    let s = solve("fiducial-affine".into(), obj("{}")).unwrap();
    let x = numbers(&get(&get(&s, "result"), "parameters"));
    assert!((x[4] - 0.042_599_978_6).abs() < 1e-9);
}

#[wasm_bindgen_test]
fn transform_fit_with_an_edited_point_and_every_model() {
    let edited = obj(
        r#"{"model": "affine", "points": [[48.15, -2699.98, -113.002, 0.008], [5353.12, -2699.13, 112.991, 0.036], [2700.21, -47.62, 0.008, 112.998], [2700.56, -5352.74, -0.016, -112.9]]}"#,
    );
    let s = solve("transform-fit".into(), edited).unwrap();
    let v = numbers(&get(&get(&s, "result"), "residuals"));
    assert!(v.iter().any(|r| r.abs() > 0.02), "{v:?}");
    assert!(get(&s, "textbook").is_null());
    for m in [
        "helmert",
        "affine",
        "pseudo-affine",
        "projective",
        "conformal-2",
        "polynomial-2",
        "polynomial-3",
    ] {
        let s = solve(
            "transform-fit".into(),
            obj(&format!(r#"{{"model": "{m}", "point_set": "control-12"}}"#)),
        )
        .unwrap();
        let r = get(&get(&s, "result"), "redundancy").as_f64().unwrap();
        assert!(r > 0.0, "{m}");
        assert!(get(&get(&s, "result"), "sigma0").as_f64().is_some(), "{m}");
    }
    // r = 0: sigma0 arrives as null, not NaN
    let s = solve("transform-fit".into(), obj(r#"{"model": "projective"}"#)).unwrap();
    assert!(get(&get(&s, "result"), "sigma0").is_null());
}

#[wasm_bindgen_test]
fn bad_points_are_js_errors_and_the_module_keeps_answering() {
    assert_eq!(
        solve_err("transform-fit", obj(r#"{"model": "polynomial-3"}"#)),
        "points: the third-order polynomial model has 20 parameters and needs at least 10 points; 4 given (6 more needed); add points in the table or choose the prepared set \"control-12\" (12 points)"
    );
    assert_eq!(
        solve_err(
            "fiducial-affine",
            obj(r#"{"points": [[1, 2, 3, 4], [5, 6, 7, 8], [1, 2, 9, 9]]}"#)
        ),
        "points: points 1 and 3 have the same source position (u, v) = (1, -2); each control point must be measured once"
    );
    assert!(solve_err(
        "transform-fit",
        obj(r#"{"points": [[1, 2, 3, 4], [5, 6, 3, 4]]}"#)
    )
    .starts_with("points: points 1 and 2 have the same target position (x, y) = (3, 4)"));
    assert!(solve_err(
        "transform-fit",
        obj(r#"{"model": "projective", "points": [[0, 0, 0, 0], [1, 0, 1, 0], [0, 1, 2, 0], [1, 1, 0, 1]]}"#)
    )
    .contains("lie on one line in the target (x, y) system"));
    assert!(solve_err(
        "transform-fit",
        obj(r#"{"model": "affine", "points": [[0, 0, 0, 0], [1, 1, 1, 1], [2, 2, 2, 2.5]]}"#)
    )
    .starts_with("points: all 3 points lie on one line"));
    assert!(solve_err(
        "transform-fit",
        obj(r#"{"model": "projective", "points": [[0, 0, 0, 0], [1, 0, 1, 0], [2, 0, 2, 1], [0, 1, 0, 1]]}"#)
    )
    .contains("points 1, 2, 3 lie on one line"));
    assert_eq!(
        solve_err(
            "transform-fit",
            obj(r#"{"points": [[1, 2, 3], [4, 5, 6, 7]]}"#)
        ),
        "points: point 1 has 3 numbers; each point needs 4"
    );
    let row = Array::of4(
        &JsValue::from_f64(1.0),
        &JsValue::from_f64(f64::NAN),
        &JsValue::from_f64(0.0),
        &JsValue::from_f64(0.0),
    );
    let inputs = js_sys::Object::new();
    Reflect::set(&inputs, &"points".into(), &Array::of1(&row)).unwrap();
    assert_eq!(
        solve_err("fiducial-similarity", inputs.into()),
        "points[1][2]: is NaN; give a number"
    );
    let row = Array::of4(
        &JsValue::from_f64(f64::INFINITY),
        &JsValue::from_f64(0.0),
        &JsValue::from_f64(0.0),
        &JsValue::from_f64(0.0),
    );
    let inputs = js_sys::Object::new();
    Reflect::set(&inputs, &"points".into(), &Array::of1(&row)).unwrap();
    assert_eq!(
        solve_err("transform-fit", inputs.into()),
        "points[1][1]: is infinite; give a finite number"
    );
    // parse_inputs reports the bad point text per field
    let p = parse_inputs(
        "transform-fit".into(),
        obj(r#"{"points": "1 2 3 4; 5 6 x 8"}"#),
    )
    .unwrap();
    assert_eq!(
        get(&get(&p, "errors"), "points").as_string().as_deref(),
        Some("points: \"x\" is not a number")
    );
    // still answering
    let s = solve("fiducial-similarity".into(), JsValue::UNDEFINED).unwrap();
    assert_eq!(get(&get(&s, "result"), "redundancy").as_f64(), Some(4.0));
}
