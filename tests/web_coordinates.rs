//! A topic module's boundary in headless Chromium, as the page's
//! pkg/coordinates.js (web/coordinates/) has it: its own catalog (without
//! `practice` and `module`, which only catalog.json carries), its examples
//! solved, and another topic's example refused by name.
#![cfg(target_arch = "wasm32")]

use js_sys::{Array, Error as JsErr, Reflect, JSON};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::*;

photogrammetry_playground::export_examples!(
    photogrammetry_playground::examples::coordinates::TOPIC
);

wasm_bindgen_test_configure!(run_in_browser);

fn get(v: &JsValue, key: &str) -> JsValue {
    Reflect::get(v, &JsValue::from_str(key)).expect("property")
}

fn message(e: wasm_bindgen::JsError) -> String {
    let e: JsValue = e.into();
    let e: JsErr = e.dyn_into().expect("a real JS Error");
    String::from(e.message())
}

#[wasm_bindgen_test]
fn the_catalog_is_the_topics_own() {
    let cat: Array = catalog().unwrap().dyn_into().expect("an Array");
    let ids: Vec<String> = cat
        .iter()
        .map(|e| get(&e, "id").as_string().unwrap())
        .collect();
    assert_eq!(ids, ["pixel-to-photo", "gsd", "photo-to-pixel"]);
    for e in cat.iter() {
        assert_eq!(get(&e, "topic").as_string().as_deref(), Some("Coordinates"));
        assert_eq!(get(&e, "status").as_string().as_deref(), Some("ready"));
        // the catalog's flags come from the descriptors, in every module
        assert_eq!(get(&e, "practice").as_bool(), Some(true));
        assert_eq!(
            get(&e, "module").as_string().as_deref(),
            Some("coordinates")
        );
    }
}

#[wasm_bindgen_test]
fn its_examples_parse_and_solve() {
    let p = parse_inputs("gsd".into(), JSON::parse(r#"{"dpi":"1200"}"#).unwrap()).unwrap();
    let s = solve("gsd".into(), get(&p, "inputs")).unwrap();
    let gsd = get(&get(&s, "result"), "gsd_cm").as_f64().unwrap();
    // 1200 dpi: a 25.4/1200 mm pixel at scale 1 : 1920 m / 0.152 m → 26.737 cm
    let expected = 25.4 / 1200.0 * (1920.0 / 0.152) / 10.0;
    assert!((gsd - expected).abs() < 1e-9, "{gsd} vs {expected}");
    assert!((gsd - 26.737).abs() < 1e-3, "{gsd}");
    let s = solve("pixel-to-photo".into(), JsValue::UNDEFINED).unwrap();
    assert!(get(&get(&s, "result"), "x_mm").as_f64().is_some());
}

#[wasm_bindgen_test]
fn another_topics_example_is_unknown_here() {
    let m = message(solve("ncc-2d".into(), JsValue::UNDEFINED).unwrap_err());
    assert!(m.contains("ncc-2d"), "{m}");
    let m = message(parse_inputs("utm".into(), JsValue::UNDEFINED).unwrap_err());
    assert!(m.contains("utm"), "{m}");
}
