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

#[wasm_bindgen]
extern "C" {
    /// The page's random numbers, for a fresh practice variant.
    #[wasm_bindgen(js_namespace = Math, js_name = random)]
    fn math_random() -> f64;
}

/// A practice variant of example `id`: `{ id, code, inputs, boxes }`; the
/// variant of `code` when given (a string like `"1K7Q2"`), a new one when
/// `code` is `undefined` or `null`.
#[wasm_bindgen]
pub fn practice(id: &str, code: JsValue) -> Result<JsValue, JsError> {
    let code = if code.is_undefined() || code.is_null() {
        None
    } else {
        Some(
            code.as_string()
                .ok_or_else(|| JsError::new("code: must be a string like \"1K7Q2\""))?,
        )
    };
    let fresh = (math_random() * f64::from(crate::practice::VARIANTS)) as u32;
    let p = crate::practice::practice(id, code.as_deref(), fresh).map_err(js_error)?;
    to_js(&p)
}

/// Grades `answers` (`{ box key: text }`) for variant `code` of example `id`:
/// `{ code, boxes: { key: { verdict, mistake?, message, read, value,
/// precision, unit, points } }, score, out_of }`.
#[wasm_bindgen]
pub fn grade(id: &str, code: &str, answers: JsValue) -> Result<JsValue, JsError> {
    let answers = record_from_js("answers", answers)?;
    let g = crate::practice::grade(id, code, &answers).map_err(js_error)?;
    to_js(&g)
}
