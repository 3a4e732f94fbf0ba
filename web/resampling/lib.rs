//! The Resampling examples' wasm module: `catalog`, `solve`, `parse_inputs`.
#![cfg(target_arch = "wasm32")]
photogrammetry_playground::export_examples!(photogrammetry_playground::examples::resampling::TOPIC);
