//! The wasm-bindgen boundary: thin exports that convert JS values to and from
//! the core's plain data and turn every [`Error`] into a thrown JS `Error`.
//!
//! The page loads one small wasm module per topic (the crates under `web/`)
//! and practice mode one more; each is a three-line crate that invokes a
//! macro of this file, so the exports are written once, here:
//! - [`export_examples!`]`(examples::coordinates::TOPIC, …)`: `catalog`, `solve`,
//!   `solve_series`, `read_count` and `parse_inputs` over those entries only (link-time optimisation
//!   drops every other topic);
//! - [`export_all!`]`()`: the same over the whole catalog, plus `practice`
//!   and `grade` (practice mode and the compatibility package).
//!
//! Every argument of every export is taken as a `JsValue` and its JS type
//! checked here ([`string_arg`], `record_from_js`): a wrong type is a thrown
//! `Error` that names the argument ("id: must be a string naming an example,
//! got a number"), never a trap (tests/e2e/api-types.test.mjs calls every
//! export of every module with every kind of JS value).
//!
//! The functions below are what the macros call; they are not exports.

use crate::error::Error;
use crate::examples::{self, Topic};
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

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(js_namespace = Array, js_name = isArray)]
    fn js_is_array(v: &JsValue) -> bool;
    #[wasm_bindgen(js_namespace = ArrayBuffer, js_name = isView)]
    fn js_is_view(v: &JsValue) -> bool;
}

/// What kind of JS value `v` is, as a message says it: "a number",
/// "null", "an array", "a typed array", "a function" …
pub fn js_kind(v: &JsValue) -> &'static str {
    if v.is_undefined() {
        "undefined"
    } else if v.is_null() {
        "null"
    } else if v.is_string() {
        "a string"
    } else if v.as_f64().is_some() {
        "a number"
    } else if v.as_bool().is_some() {
        "a boolean"
    } else if v.is_function() {
        "a function"
    } else if v.is_bigint() {
        "a BigInt"
    } else if v.is_symbol() {
        "a symbol"
    } else if js_is_array(v) {
        "an array"
    } else if js_is_view(v) {
        "a typed array"
    } else {
        "an object"
    }
}

/// Argument `what` of an export, which must be a string; `meaning` says
/// what it is for ("naming an example"). Every string argument of the
/// exports (and of the lab's) comes through here: wasm-bindgen's own `&str`
/// would copy a non-string into wasm memory and trap. Not an export itself:
/// `what` and `meaning` are the export's own words (literals), and the JS
/// value is the `JsValue`.
pub fn string_arg(
    what: &'static str,
    meaning: &'static str,
    v: &JsValue,
) -> Result<String, JsError> {
    v.as_string().ok_or_else(|| {
        JsError::new(&format!(
            "{what}: must be a string {meaning}, got {}",
            js_kind(v)
        ))
    })
}

/// Longer strings cannot be an id or a code: they reach the core cut short,
/// so that its message quotes a few characters, not the whole text.
const LONGEST_NAME: usize = 64;

/// A string argument that names something (an id, a code), cut short when
/// it is too long to name anything.
fn name_arg(what: &'static str, meaning: &'static str, v: &JsValue) -> Result<String, JsError> {
    let s = string_arg(what, meaning, v)?;
    Ok(if s.chars().count() > LONGEST_NAME {
        crate::read::short(&s)
    } else {
        s
    })
}

/// The id argument of every export.
fn id_arg(id: &JsValue) -> Result<String, JsError> {
    name_arg("id", "naming an example", id)
}

/// Reads a JS object of inputs; `undefined`/`null` mean "all defaults".
fn record_from_js(what: &str, v: JsValue) -> Result<Record, JsError> {
    if v.is_undefined() || v.is_null() {
        return Ok(Record::new());
    }
    if !v.is_object() || v.is_function() || js_is_array(&v) || js_is_view(&v) {
        return Err(JsError::new(&format!(
            "{what}: must be an object of fields like {{ dpi: 1200 }}, got {}",
            js_kind(&v)
        )));
    }
    match serde_wasm_bindgen::from_value::<Value>(v) {
        Ok(Value::Object(r)) => Ok(r),
        Ok(other) => Err(JsError::new(&format!(
            "{what}: must be an object of fields like {{ dpi: 1200 }}, got {}",
            other.type_name()
        ))),
        Err(e) => Err(JsError::new(&format!("{what}: cannot be read: {e}"))),
    }
}

/// `catalog()` of a topic module: its examples only.
pub fn catalog_of(topics: &'static [Topic]) -> Result<JsValue, JsError> {
    to_js(&examples::catalog_of(topics))
}

/// `solve(id, inputs)` among `topics`.
pub fn solve_in(
    topics: &'static [Topic],
    id: &JsValue,
    inputs: JsValue,
) -> Result<JsValue, JsError> {
    let id = id_arg(id)?;
    let inputs = record_from_js("inputs", inputs)?;
    let solution = examples::solve_in(topics, &id, &inputs).map_err(js_error)?;
    to_js(&solution)
}

/// `parse_inputs(id, texts)` among `topics`.
pub fn parse_inputs_in(
    topics: &'static [Topic],
    id: &JsValue,
    texts: JsValue,
) -> Result<JsValue, JsError> {
    let id = id_arg(id)?;
    let texts = record_from_js("texts", texts)?;
    let parsed = examples::parse_inputs_in(topics, &id, &texts).map_err(js_error)?;
    to_js(&parsed)
}

/// A JS array argument `what` read as values: `items` says what its
/// elements must be ("numbers"), `one` what one must be ("a number"), and
/// `item` takes one (`Err`: refused, given back).
fn list_arg<T>(
    what: &str,
    items: &str,
    one: &str,
    v: JsValue,
    item: impl Fn(Value) -> Result<T, Value>,
) -> Result<Vec<T>, JsError> {
    if !js_is_array(&v) {
        return Err(JsError::new(&format!(
            "{what}: must be an array of {items}, got {}",
            js_kind(&v)
        )));
    }
    let list = match serde_wasm_bindgen::from_value::<Value>(v) {
        Ok(Value::List(list)) => list,
        Ok(other) => {
            return Err(JsError::new(&format!(
                "{what}: must be an array of {items}, got {}",
                other.type_name()
            )))
        }
        Err(e) => return Err(JsError::new(&format!("{what}: cannot be read: {e}"))),
    };
    list.into_iter()
        .enumerate()
        .map(|(i, x)| {
            item(x).map_err(|x| {
                JsError::new(&format!(
                    "{what}[{i}]: must be {one}, got {}",
                    x.type_name()
                ))
            })
        })
        .collect()
}

/// `solve_series(id, inputs, key, values, plot)` among `topics`: see
/// [`crate::series`].
pub fn solve_series_in(
    topics: &'static [Topic],
    id: &JsValue,
    inputs: JsValue,
    key: &JsValue,
    values: JsValue,
    plot: JsValue,
) -> Result<JsValue, JsError> {
    let id = id_arg(id)?;
    let inputs = record_from_js("inputs", inputs)?;
    let key = name_arg("key", "naming an input of the example", key)?;
    let values = list_arg("values", "numbers", "a number", values, |x| match x {
        Value::Number(_) => Ok(x),
        other => Err(other),
    })?;
    let plot = list_arg(
        "plot",
        "strings (result keys)",
        "a string",
        plot,
        |x| match x {
            Value::Text(t) => Ok(t),
            other => Err(other),
        },
    )?;
    let series =
        crate::examples::series::solve_series_in(topics, &id, &inputs, &key, &values, &plot)
            .map_err(js_error)?;
    to_js(&series)
}

/// `read_count(text, min, max)`: see [`crate::examples::series::read_count`].
pub fn read_count(text: &JsValue, min: &JsValue, max: &JsValue) -> Result<JsValue, JsError> {
    let text = string_arg("text", "(a count typed in a box)", text)?;
    let number = |what: &str, v: &JsValue| {
        v.as_f64()
            .ok_or_else(|| JsError::new(&format!("{what}: must be a number, got {}", js_kind(v))))
    };
    let (min, max) = (number("min", min)?, number("max", max)?);
    let n = crate::examples::series::read_count(&text, min, max).map_err(js_error)?;
    Ok(JsValue::from_f64(n))
}

#[wasm_bindgen]
extern "C" {
    /// The page's random numbers, for a fresh practice variant.
    #[wasm_bindgen(js_namespace = Math, js_name = random)]
    fn math_random() -> f64;
}

/// `practice(id, code)` among `topics`: see [`export_all!`].
pub fn practice(
    topics: &'static [Topic],
    id: &JsValue,
    code: &JsValue,
) -> Result<JsValue, JsError> {
    let id = id_arg(id)?;
    let code = if code.is_undefined() || code.is_null() {
        None
    } else {
        Some(name_arg("code", CODE_MEANING, code)?)
    };
    let fresh = (math_random() * f64::from(crate::practice::VARIANTS)) as u32;
    let p = crate::practice::practice_in(topics, &id, code.as_deref(), fresh).map_err(js_error)?;
    to_js(&p)
}

const CODE_MEANING: &str = "like \"1K7Q2\" (a practice variant's code)";

/// `grade(id, code, answers)` among `topics`: see [`export_all!`].
pub fn grade(
    topics: &'static [Topic],
    id: &JsValue,
    code: &JsValue,
    answers: JsValue,
) -> Result<JsValue, JsError> {
    let id = id_arg(id)?;
    let code = name_arg("code", CODE_MEANING, code)?;
    let answers = record_from_js("answers", answers)?;
    let g = crate::practice::grade_in(topics, &id, &code, &answers).map_err(js_error)?;
    to_js(&g)
}

/// The exports of a topic module: `catalog`, `solve` and `parse_inputs` over
/// the given topics (`examples::<topic>::TOPIC`), and, when the invoking
/// crate has its `practice` feature on, `practice` and `grade` over them.
/// The invoking crate depends on `wasm-bindgen` (the attribute names it).
/// The allocator of the worked-example modules (see [`export_examples!`]).
pub use talc;

#[macro_export]
macro_rules! export_examples {
    (@in $topics:expr) => {
        const TOPICS: &[$crate::examples::Topic] = $topics;

        /// Talc, not the default dlmalloc: the same service in fewer bytes
        /// of the module an example's page loads first.
        #[global_allocator]
        static ALLOCATOR: $crate::wasm::talc::wasm::WasmDynamicTalc =
            $crate::wasm::talc::wasm::new_wasm_dynamic_allocator();

        /// This module's worked examples: `[{ id, title, topic, source,
        /// document, summary, status, inputs }]`.
        #[::wasm_bindgen::prelude::wasm_bindgen]
        pub fn catalog() -> ::std::result::Result<::wasm_bindgen::JsValue, ::wasm_bindgen::JsError> {
            $crate::wasm::catalog_of(TOPICS)
        }

        /// Solves example `id` with typed `inputs`; throws an `Error` naming
        /// the field on bad input.
        #[::wasm_bindgen::prelude::wasm_bindgen]
        pub fn solve(
            id: ::wasm_bindgen::JsValue,
            inputs: ::wasm_bindgen::JsValue,
        ) -> ::std::result::Result<::wasm_bindgen::JsValue, ::wasm_bindgen::JsError> {
            $crate::wasm::solve_in(TOPICS, &id, inputs)
        }

        /// A sweep's series: example `id` solved with `inputs` and input
        /// `key` set to each of `values` (numbers), results `plot` (keys)
        /// read off each: `{ results: { key: [value…] }, errors: [message
        /// or null…] }`, each point exactly `solve(id, inputs with that
        /// value)`'s, without building steps.
        #[::wasm_bindgen::prelude::wasm_bindgen]
        pub fn solve_series(
            id: ::wasm_bindgen::JsValue,
            inputs: ::wasm_bindgen::JsValue,
            key: ::wasm_bindgen::JsValue,
            values: ::wasm_bindgen::JsValue,
            plot: ::wasm_bindgen::JsValue,
        ) -> ::std::result::Result<::wasm_bindgen::JsValue, ::wasm_bindgen::JsError> {
            $crate::wasm::solve_series_in(TOPICS, &id, inputs, &key, values, plot)
        }

        /// A count typed in a box (a sweep's steps): a whole number within
        /// `min..=max`, read as an integer input's text; throws in its words.
        #[::wasm_bindgen::prelude::wasm_bindgen]
        pub fn read_count(
            text: ::wasm_bindgen::JsValue,
            min: ::wasm_bindgen::JsValue,
            max: ::wasm_bindgen::JsValue,
        ) -> ::std::result::Result<::wasm_bindgen::JsValue, ::wasm_bindgen::JsError> {
            $crate::wasm::read_count(&text, &min, &max)
        }

        /// Parses form or URL texts `{ key: text }` into `{ inputs, errors }`.
        #[::wasm_bindgen::prelude::wasm_bindgen]
        pub fn parse_inputs(
            id: ::wasm_bindgen::JsValue,
            texts: ::wasm_bindgen::JsValue,
        ) -> ::std::result::Result<::wasm_bindgen::JsValue, ::wasm_bindgen::JsError> {
            $crate::wasm::parse_inputs_in(TOPICS, &id, texts)
        }

        /// A practice variant of example `id` (this module's builds with
        /// the `practice` feature only: `pkg/<topic>_practice.js`).
        #[cfg(feature = "practice")]
        #[::wasm_bindgen::prelude::wasm_bindgen]
        pub fn practice(
            id: ::wasm_bindgen::JsValue,
            code: ::wasm_bindgen::JsValue,
        ) -> ::std::result::Result<::wasm_bindgen::JsValue, ::wasm_bindgen::JsError> {
            $crate::wasm::practice(TOPICS, &id, &code)
        }

        /// Grades `answers` for variant `code` of example `id` (with the
        /// `practice` feature only).
        #[cfg(feature = "practice")]
        #[::wasm_bindgen::prelude::wasm_bindgen]
        pub fn grade(
            id: ::wasm_bindgen::JsValue,
            code: ::wasm_bindgen::JsValue,
            answers: ::wasm_bindgen::JsValue,
        ) -> ::std::result::Result<::wasm_bindgen::JsValue, ::wasm_bindgen::JsError> {
            $crate::wasm::grade(TOPICS, &id, &code, answers)
        }
    };
    ($($topic:path),+ $(,)?) => {
        $crate::export_examples!(@in &[$($topic),+]);
    };
}

/// The exports of the whole catalog ([`export_examples!`] over every topic
/// of `examples::TOPICS`): `catalog`, `solve`, `parse_inputs`, and practice
/// mode's `practice` and `grade` (with the invoking crate's `practice`
/// feature): the one-package API (`pkg/photogrammetry_playground.js`).
#[macro_export]
macro_rules! export_all {
    () => {
        $crate::export_examples!(@in &$crate::examples::TOPICS);
    };
}
