//! Every worked example and practice mode: `catalog`, `solve`,
//! `parse_inputs`, `practice`, `grade`.
#![cfg(target_arch = "wasm32")]
photogrammetry_playground::export_all!();
