//! The wasm boundary in headless Chromium: `catalog()`, `solve()` and
//! `parse_inputs()` as the page calls them, errors as real JS `Error`s, and
//! a module that keeps answering after an error.
#![cfg(target_arch = "wasm32")]

use js_sys::{Array, Error as JsErr, Object, Reflect, JSON};
// The exports as the page's pkg/all.js has them (web/all/): every example
// and practice mode.
photogrammetry_playground::export_all!();
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

/// `{dpi: 1200}` etc. from a JSON literal, as page code would write it.
fn obj(json: &str) -> JsValue {
    JSON::parse(json).expect("json")
}

/// Calls `solve` and returns the thrown JS Error's message.
fn solve_err(id: &str, inputs: JsValue) -> String {
    let e: JsValue = solve(id.into(), inputs).expect_err("should throw").into();
    let e: JsErr = e.dyn_into().expect("a real JS Error");
    String::from(e.message())
}

#[wasm_bindgen_test]
fn catalog_is_plain_data_with_typed_fields() {
    let cat: Array = catalog().unwrap().dyn_into().expect("an Array");
    assert_eq!(cat.length(), 26);
    let gsd = cat
        .iter()
        .find(|e| get(e, "id").as_string().as_deref() == Some("gsd"))
        .expect("gsd in the catalog");
    assert!(gsd.is_instance_of::<Object>());
    assert_eq!(get(&gsd, "status").as_string().as_deref(), Some("ready"));
    assert_eq!(
        get(&gsd, "topic").as_string().as_deref(),
        Some("Coordinates")
    );
    // the whole catalog (catalog.json) names each entry's module and practice
    assert_eq!(
        get(&gsd, "module").as_string().as_deref(),
        Some("coordinates")
    );
    assert_eq!(get(&gsd, "practice").as_bool(), Some(true));
    let inputs: Array = get(&gsd, "inputs").dyn_into().unwrap();
    let dpi = inputs.get(0);
    assert_eq!(get(&dpi, "key").as_string().as_deref(), Some("dpi"));
    assert_eq!(get(&dpi, "kind").as_string().as_deref(), Some("number"));
    assert_eq!(get(&dpi, "unit").as_string().as_deref(), Some("dpi"));
    assert_eq!(num(&dpi, &["default"]), 900.0);
    assert_eq!(
        get(&dpi, "default_text").as_string().as_deref(),
        Some("900")
    );
    assert_eq!(get(&dpi, "min_exclusive").as_bool(), Some(true));
    // an entry not built yet (if any is left) is listed with no inputs
    if let Some(coming) = cat
        .iter()
        .find(|e| get(e, "status").as_string().as_deref() == Some("coming"))
    {
        assert_eq!(Array::from(&get(&coming, "inputs")).length(), 0);
    }
}

#[wasm_bindgen_test]
fn solve_returns_the_seed_solution_as_plain_objects() {
    let s = solve("gsd".into(), JsValue::UNDEFINED).unwrap();
    assert!((num(&s, &["result", "gsd_cm"]) - 35.649_122_8).abs() < 1e-6);
    assert_eq!(num(&s, &["textbook", "gsd_cm"]), 35.37);
    let steps: Array = get(&s, "steps").dyn_into().unwrap();
    assert_eq!(steps.length(), 3);
    assert!(get(&steps.get(2), "substituted")
        .as_string()
        .unwrap()
        .contains("356.4912"));
    let notes: Array = get(&s, "notes").dyn_into().unwrap();
    assert!(notes.length() >= 2);
    assert_eq!(
        get(&notes.get(0), "kind").as_string().as_deref(),
        Some("rounding")
    );

    let s = solve("pixel-to-photo".into(), obj("{}")).unwrap();
    assert!((num(&s, &["result", "x_mm"]) - 8.255).abs() < 1e-12);
    let s = solve("photo-to-pixel".into(), JsValue::NULL).unwrap();
    assert!((num(&s, &["result", "r"]) - 1_349.055_118).abs() < 1e-6);
}

#[wasm_bindgen_test]
fn a_what_if_fills_the_other_fields_with_defaults() {
    let s = solve("gsd".into(), obj(r#"{"dpi": 1200}"#)).unwrap();
    let expected = 25.4 / 1200.0 * (1920.0 / 0.152) / 10.0;
    assert!((num(&s, &["result", "gsd_cm"]) - expected).abs() < 1e-9);
    assert_eq!(num(&s, &["inputs", "focal_length_mm"]), 152.0);
    assert!(get(&s, "textbook").is_null());
}

#[wasm_bindgen_test]
fn errors_are_js_errors_and_the_module_keeps_answering() {
    assert_eq!(
        solve_err("gsd", obj(r#"{"dpi": -5}"#)),
        "dpi: must be greater than 0 dpi (got -5)"
    );
    assert_eq!(
        solve_err("gsd", obj(r#"{"dpi": "900"}"#)),
        "dpi: must be a number, got the string \"900\""
    );
    let nan = Object::new();
    Reflect::set(&nan, &"dpi".into(), &JsValue::from_f64(f64::NAN)).unwrap();
    assert_eq!(solve_err("gsd", nan.into()), "dpi: is NaN; give a number");
    let inf = Object::new();
    Reflect::set(&inf, &"c".into(), &JsValue::from_f64(f64::INFINITY)).unwrap();
    assert_eq!(
        solve_err("pixel-to-photo", inf.into()),
        "c: is infinite; give a finite number"
    );
    assert!(solve_err("gsd", obj(r#"{"height": 3}"#)).starts_with("height: unknown field"));
    assert!(solve_err("nope", JsValue::UNDEFINED).contains("unknown example id \"nope\""));
    assert!(solve_err("gsd", JsValue::from_f64(3.0)).starts_with("inputs: must be an object"));
    // after all that, the module still answers
    let s = solve("gsd".into(), JsValue::UNDEFINED).unwrap();
    assert!((num(&s, &["result", "gsd_cm"]) - 35.649_122_8).abs() < 1e-6);
}

#[wasm_bindgen_test]
fn parse_inputs_returns_typed_inputs_and_per_field_errors() {
    let p = parse_inputs(
        "gsd".into(),
        obj(r#"{"dpi": "1200", "flying_height_m": "abc"}"#),
    )
    .unwrap();
    assert_eq!(num(&p, &["inputs", "dpi"]), 1200.0);
    assert_eq!(
        get(&get(&p, "errors"), "flying_height_m")
            .as_string()
            .as_deref(),
        Some("flying_height_m: \"abc\" is not a number")
    );
    let s = solve("gsd".into(), get(&p, "inputs")).unwrap();
    assert!((num(&s, &["result", "gsd_cm"]) - 26.736_842).abs() < 1e-6);
}

#[wasm_bindgen_test]
fn notes_answer_and_mode_fields_cross_as_plain_data() {
    // every note carries `keys` (an array, possibly empty); `answer` lists result keys
    let s = solve("photo-to-pixel".into(), JsValue::UNDEFINED).unwrap();
    let notes: Array = get(&s, "notes").dyn_into().unwrap();
    let mut erratum_keys = None;
    for n in notes.iter() {
        let keys: Array = get(&n, "keys").dyn_into().expect("keys is an array");
        if get(&n, "kind").as_string().as_deref() == Some("erratum") {
            erratum_keys = Some(
                keys.iter()
                    .map(|k| k.as_string().unwrap())
                    .collect::<Vec<_>>(),
            );
        }
    }
    assert_eq!(erratum_keys, Some(vec!["dr_px".to_string()]));
    let answer: Array = get(&s, "answer").dyn_into().expect("answer is an array");
    assert_eq!(
        answer
            .iter()
            .map(|k| k.as_string().unwrap())
            .collect::<Vec<_>>(),
        ["c", "r"]
    );
    let s = solve("gsd".into(), JsValue::UNDEFINED).unwrap();
    assert_eq!(
        Array::from(&get(&s, "answer"))
            .get(0)
            .as_string()
            .as_deref(),
        Some("gsd_cm")
    );

    // `when` is { key, values } or null; `document` names the course document
    let cat: Array = catalog().unwrap().dyn_into().unwrap();
    let gsd = cat
        .iter()
        .find(|e| get(e, "id").as_string().as_deref() == Some("gsd"))
        .unwrap();
    assert_eq!(
        get(&gsd, "source").as_string().as_deref(),
        Some("Worked examples, Example 2")
    );
    assert!(get(&gsd, "document")
        .as_string()
        .unwrap()
        .starts_with("Course notes — Worked examples 1–18"));
    let chain = cat
        .iter()
        .find(|e| get(e, "id").as_string().as_deref() == Some("chain-code"))
        .unwrap();
    let inputs: Array = get(&chain, "inputs").dyn_into().unwrap();
    let field = |key: &str| {
        inputs
            .iter()
            .find(|f| get(f, "key").as_string().as_deref() == Some(key))
            .unwrap()
    };
    let when = get(&field("code"), "when");
    assert_eq!(get(&when, "key").as_string().as_deref(), Some("given"));
    let values: Array = get(&when, "values").dyn_into().unwrap();
    assert_eq!(values.length(), 1);
    assert_eq!(values.get(0).as_string().as_deref(), Some("code"));
    assert!(get(&field("given"), "when").is_null());

    // a field that does not apply never blocks: chain-code from pixels with an empty code
    let p = parse_inputs(
        "chain-code".into(),
        obj(r#"{"given": "pixels", "code": ""}"#),
    )
    .unwrap();
    assert_eq!(
        Object::keys(get(&p, "errors").unchecked_ref::<Object>()).length(),
        0
    );
    let s = solve("chain-code".into(), get(&p, "inputs")).unwrap();
    assert_eq!(Array::from(&get(&get(&s, "result"), "code")).length(), 16);
    // where it applies, the same text is an error at its field
    let p = parse_inputs("chain-code".into(), obj(r#"{"given": "code", "code": ""}"#)).unwrap();
    assert!(get(&get(&p, "errors"), "code")
        .as_string()
        .unwrap()
        .starts_with("code:"));
}
