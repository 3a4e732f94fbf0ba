//! Correlation matching (seed 000, Examples 5–9) across the wasm boundary in
//! headless Chromium: the seed solutions as plain JS data, null (never NaN)
//! for flat windows and non-concave neighbourhoods, bad inputs as JS Errors
//! naming the field, and a module that keeps answering.
#![cfg(target_arch = "wasm32")]

use js_sys::{Array, Error as JsErr, Reflect, JSON};
// The exports as the page's topic module pkg/correlation.js (web/correlation/) has them.
photogrammetry_playground::export_examples!(
    photogrammetry_playground::examples::correlation::TOPIC
);
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

fn arr(v: &JsValue, path: &[&str]) -> Array {
    at(v, path).dyn_into().expect("an Array")
}

fn obj(json: &str) -> JsValue {
    JSON::parse(json).expect("json")
}

fn solve_err(id: &str, inputs: JsValue) -> String {
    let e: JsValue = solve(id.into(), inputs).expect_err("should throw").into();
    let e: JsErr = e.dyn_into().expect("a real JS Error");
    String::from(e.message())
}

fn has_note(s: &JsValue, kind: &str, needle: &str) -> bool {
    arr(s, &["notes"]).iter().any(|n| {
        get(&n, "kind").as_string().as_deref() == Some(kind)
            && get(&n, "text")
                .as_string()
                .unwrap_or_default()
                .contains(needle)
    })
}

#[wasm_bindgen_test]
fn the_five_entries_are_ready_with_editable_arrays() {
    let cat: Array = catalog().unwrap().dyn_into().unwrap();
    for id in [
        "ncc-1d",
        "ncc-2d",
        "ncc-surface",
        "subpixel-1d",
        "subpixel-2d",
    ] {
        let e = cat
            .iter()
            .find(|e| get(e, "id").as_string().as_deref() == Some(id))
            .unwrap_or_else(|| panic!("{id} missing"));
        assert_eq!(get(&e, "status").as_string().as_deref(), Some("ready"));
        assert_eq!(get(&e, "topic").as_string().as_deref(), Some("Correlation"));
    }
    let surface = cat
        .iter()
        .find(|e| get(e, "id").as_string().as_deref() == Some("ncc-surface"))
        .unwrap();
    let search = arr(&surface, &["inputs"]).get(1);
    assert_eq!(get(&search, "kind").as_string().as_deref(), Some("matrix"));
    assert!(get(&search, "default_text")
        .as_string()
        .unwrap()
        .starts_with("44, 45, 64, 50, 45, 43; 43"));
    let sub = cat
        .iter()
        .find(|e| get(e, "id").as_string().as_deref() == Some("subpixel-2d"))
        .unwrap();
    let rho_from = arr(&sub, &["inputs"]).get(3);
    assert_eq!(
        get(&rho_from, "kind").as_string().as_deref(),
        Some("choice")
    );
    assert_eq!(arr(&rho_from, &["options"]).length(), 2);
}

#[wasm_bindgen_test]
fn the_seed_solutions_cross_the_boundary() {
    let s = solve("ncc-1d".into(), JsValue::UNDEFINED).unwrap();
    assert_eq!(num(&s, &["result", "best"]), 5.0);
    assert!((arr(&s, &["result", "rho"]).get(3).as_f64().unwrap() - 0.673_053_19).abs() < 1e-8);
    assert_eq!(arr(&s, &["textbook", "rho"]).get(3).as_f64(), Some(0.69));
    assert!(has_note(&s, "erratum", "ρ4 is printed as 0.69"));

    let s = solve("ncc-2d".into(), JsValue::NULL).unwrap();
    assert!((num(&s, &["result", "rho"]) - 0.775_269_268).abs() < 1e-9);
    assert_eq!(num(&s, &["textbook", "mean_a"]), 58.5);
    assert!(has_note(&s, "erratum", "without the squares"));

    let s = solve("ncc-surface".into(), obj("{}")).unwrap();
    assert_eq!(num(&s, &["result", "best_position"]), 10.0);
    assert_eq!(num(&s, &["result", "best_c"]), 3.0);
    assert_eq!(num(&s, &["result", "best_r"]), 4.0);
    let row3: Array = arr(&s, &["result", "rho"]).get(2).dyn_into().unwrap();
    assert!((row3.get(1).as_f64().unwrap() - 0.966_489_366).abs() < 1e-8);

    let s = solve("subpixel-1d".into(), JsValue::UNDEFINED).unwrap();
    assert!((num(&s, &["result", "c_max"]) - 86.0 / 11.0).abs() < 1e-12);
    assert_eq!(num(&s, &["textbook", "c_max"]), 7.82);
    let s = solve("subpixel-1d".into(), obj(r#"{"rho_from": "exact"}"#)).unwrap();
    assert!((num(&s, &["result", "c_max"]) - 47.0 / 6.0).abs() < 1e-12);
    assert!((num(&s, &["result", "peak_shift"]) - (47.0 / 6.0 - 86.0 / 11.0)).abs() < 1e-12);

    let s = solve("subpixel-2d".into(), JsValue::UNDEFINED).unwrap();
    assert!((num(&s, &["result", "c_max"]) - 3.011_096_372).abs() < 1e-8);
    assert!((num(&s, &["result", "r_max"]) - 4.075_987_003).abs() < 1e-8);
    assert_eq!(num(&s, &["textbook", "c_max"]), 3.012);
    let s = solve("subpixel-2d".into(), obj(r#"{"rho_from": "exact"}"#)).unwrap();
    assert!((num(&s, &["result", "c_max"]) - 3.011_087_663).abs() < 1e-8);
}

#[wasm_bindgen_test]
fn documented_answers_are_null_with_a_note_not_nan() {
    // flat B
    let s = solve("ncc-2d".into(), obj(r#"{"b": [[5,5,5],[5,5,5],[5,5,5]]}"#)).unwrap();
    assert!(at(&s, &["result", "rho"]).is_null());
    assert!(has_note(&s, "warning", "B has no variance"));
    // flat template in 1-D
    let s = solve("ncc-1d".into(), obj(r#"{"template": [2, 2, 2]}"#)).unwrap();
    assert!(arr(&s, &["result", "rho"]).iter().all(|v| v.is_null()));
    assert!(at(&s, &["result", "best"]).is_null());
    // a saddle is reported, not returned as a peak
    let s = solve(
        "subpixel-2d".into(),
        obj(r#"{"rho": [[0.5,0.9,0.5],[0.1,0.5,0.1],[0.5,0.9,0.5]]}"#),
    )
    .unwrap();
    assert!(at(&s, &["result", "c_max"]).is_null());
    assert!(at(&s, &["result", "r_max"]).is_null());
    assert_eq!(
        at(&s, &["result", "extremum"]).as_string().as_deref(),
        Some("saddle")
    );
    assert!(has_note(&s, "warning", "not concave"));
    // a valley in 1-D
    let s = solve("subpixel-1d".into(), obj(r#"{"rho": [0.9, 0.2, 0.8]}"#)).unwrap();
    assert!(at(&s, &["result", "c_max"]).is_null());
}

#[wasm_bindgen_test]
fn bad_inputs_throw_js_errors_and_the_module_keeps_answering() {
    assert_eq!(
        solve_err("ncc-1d", obj(r#"{"search": [1, 2, 3]}"#)),
        "template: has 7 values but the search array only 3: the template must fit in the search array"
    );
    assert_eq!(
        solve_err("ncc-surface", obj(r#"{"search": [[1,2,3,4],[5,6,7,8]]}"#)),
        "template: is 3×3 but the search array only 2×4: the template must fit in the search array"
    );
    assert_eq!(
        solve_err("ncc-2d", obj(r#"{"a": [[1, 2], [3]]}"#)),
        "a: rows must all have the same length: row 1 has 2 numbers, row 2 has 1"
    );
    assert_eq!(
        solve_err("ncc-2d", obj(r#"{"a": []}"#)),
        "a: is empty: give at least one row"
    );
    assert_eq!(
        solve_err("ncc-1d", obj(r#"{"template": []}"#)),
        "template: is empty: give at least 2 numbers"
    );
    let nan = Array::of3(&1.0.into(), &JsValue::from_f64(f64::NAN), &3.0.into());
    let inputs = js_sys::Object::new();
    Reflect::set(&inputs, &"search".into(), &nan).unwrap();
    assert_eq!(
        solve_err("ncc-1d", inputs.into()),
        "search[2]: is NaN; give a number"
    );
    assert_eq!(
        solve_err("subpixel-1d", obj(r#"{"positions": [7, 7, 9]}"#)),
        "positions: values 1 and 2 are the same position; three different positions are needed"
    );
    assert_eq!(
        solve_err("subpixel-2d", obj(r#"{"rho_from": "rounded"}"#)),
        "rho_from: \"rounded\" is not one of the choices (printed, exact)"
    );
    // parse_inputs: per-field messages for the form
    let p = parse_inputs("ncc-2d".into(), obj(r#"{"a": "1 2; 3", "b": "1 2; 3 4"}"#)).unwrap();
    assert!(get(&get(&p, "errors"), "a")
        .as_string()
        .unwrap()
        .contains("same length"));
    assert_eq!(arr(&p, &["inputs", "b"]).length(), 2);
    // after all that, the module still answers
    let s = solve("ncc-surface".into(), JsValue::UNDEFINED).unwrap();
    assert_eq!(num(&s, &["result", "best_position"]), 10.0);
}

#[wasm_bindgen_test]
fn a_64_by_64_search_array_solves_in_the_browser() {
    // Speed belongs to `npm run bench`; here the answer of a large what-if is
    // checked against a plain NCC written out in the test.
    let template = [[1.0, 5.0, 2.0], [7.0, 3.0, 9.0], [4.0, 8.0, 6.0]];
    let mut grid = vec![vec![0.0f64; 64]; 64];
    let mut rows = Vec::new();
    let mut x: u32 = 12345;
    for row_values in grid.iter_mut() {
        let mut row = Vec::new();
        for v in row_values.iter_mut() {
            x = x.wrapping_mul(1_103_515_245).wrapping_add(12345);
            *v = f64::from((x >> 16) % 256);
            row.push(v.to_string());
        }
        rows.push(format!("[{}]", row.join(",")));
    }
    let search = format!("[{}]", rows.join(","));
    let inputs = obj(&format!(
        r#"{{"search": {search}, "template": [[1,5,2],[7,3,9],[4,8,6]]}}"#
    ));
    let s = solve("ncc-surface".into(), inputs).unwrap();
    let rho = arr(&s, &["result", "rho"]);
    assert_eq!(rho.length(), 62);
    let t_mean = template.iter().flatten().sum::<f64>() / 9.0;
    for (r, c) in [(0usize, 0usize), (0, 61), (61, 0), (30, 17), (61, 61)] {
        let w: Vec<f64> = (0..3)
            .flat_map(|i| (0..3).map(move |j| (i, j)))
            .map(|(i, j)| grid[r + i][c + j])
            .collect();
        let w_mean = w.iter().sum::<f64>() / 9.0;
        let (mut stw, mut sww, mut stt) = (0.0, 0.0, 0.0);
        for (k, wv) in w.iter().enumerate() {
            let tv = template[k / 3][k % 3] - t_mean;
            let wv = wv - w_mean;
            stw += tv * wv;
            sww += wv * wv;
            stt += tv * tv;
        }
        let want = stw / (sww * stt).sqrt();
        let row: Array = rho.get(r as u32).dyn_into().expect("a row");
        assert_eq!(row.length(), 62);
        let got = row.get(c as u32).as_f64().expect("a number");
        assert!(
            (got - want).abs() < 1e-12,
            "rho at ({r}, {c}): {got} vs {want}"
        );
    }
}
