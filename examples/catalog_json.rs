//! Writes the page's `catalog.json` from the Rust entries, natively (issue 19):
//!   cargo run --example catalog_json -- dist/catalog.json
//! `scripts/build.sh` runs it; `scripts/catalog-json.mjs` then checks the file
//! against the built wasm's own `catalog()` (serde-wasm-bindgen, not this
//! serde_json), and `tests/e2e/modules.test.mjs` against every topic module's.
//! Each entry of `examples::catalog()` without its `inputs` (the form's
//! fields: most of the bytes), which come with the entry's module.

use photogrammetry_playground::examples;
use std::process::ExitCode;

fn main() -> ExitCode {
    let Some(out) = std::env::args().nth(1) else {
        eprintln!("usage: catalog_json <out.json>");
        return ExitCode::FAILURE;
    };
    let mut entries = match serde_json::to_value(examples::catalog()) {
        Ok(serde_json::Value::Array(entries)) => entries,
        other => {
            eprintln!("catalog_json: the catalog is not a list ({other:?})");
            return ExitCode::FAILURE;
        }
    };
    for entry in &mut entries {
        if let Some(fields) = entry.as_object_mut() {
            fields.remove("inputs");
        }
    }
    let json = serde_json::Value::Array(entries).to_string();
    if let Err(e) = std::fs::write(&out, format!("{json}\n")) {
        eprintln!("catalog_json: cannot write {out}: {e}");
        return ExitCode::FAILURE;
    }
    ExitCode::SUCCESS
}
