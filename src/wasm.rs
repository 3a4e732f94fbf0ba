//! The wasm-bindgen boundary: thin exports that convert JS values to and from
//! the core's plain data and turn every [`Error`] into a thrown JS `Error`.

use crate::error::Error;
use crate::examples;
use crate::solution::{Record, Value};
use serde::Serialize;
use wasm_bindgen::prelude::*;

fn to_js<T: Serialize>(v: &T) -> Result<JsValue, JsError> {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| JsError::new(&format!("internal error (please report): {e}")))
}

fn js_error(e: Error) -> JsError {
    JsError::new(&e.to_string())
}

/// Reads a JS object of inputs; `undefined`/`null` mean "all defaults".
fn record_from_js(what: &str, v: JsValue) -> Result<Record, JsError> {
    if v.is_undefined() || v.is_null() {
        return Ok(Record::new());
    }
    match serde_wasm_bindgen::from_value::<Value>(v) {
        Ok(Value::Object(r)) => Ok(r),
        Ok(other) => Err(JsError::new(&format!(
            "{what}: must be an object of fields, got {}",
            other.type_name()
        ))),
        Err(e) => Err(JsError::new(&format!("{what}: cannot be read: {e}"))),
    }
}

/// Every worked example: `[{ id, title, topic, source, summary, status, inputs }]`.
#[wasm_bindgen]
pub fn catalog() -> Result<JsValue, JsError> {
    to_js(&examples::catalog())
}

/// Solves example `id` with typed `inputs`; throws an `Error` naming the
/// field on bad input.
#[wasm_bindgen]
pub fn solve(id: &str, inputs: JsValue) -> Result<JsValue, JsError> {
    let inputs = record_from_js("inputs", inputs)?;
    let solution = examples::solve(id, &inputs).map_err(js_error)?;
    to_js(&solution)
}

/// Parses form or URL texts `{ key: text }` into `{ inputs, errors }`.
#[wasm_bindgen]
pub fn parse_inputs(id: &str, texts: JsValue) -> Result<JsValue, JsError> {
    let texts = record_from_js("texts", texts)?;
    let parsed = examples::parse_inputs(id, &texts).map_err(js_error)?;
    to_js(&parsed)
}
