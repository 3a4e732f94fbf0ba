//! The image lab: real photos in, the core's operators over the whole
//! image, results out as layers. A second wasm module beside the worked
//! examples' one, loaded only when the lab opens (in a Web Worker).
//!
//! - [`decode`]: JPEG, PNG, TIFF, WebP, BMP, GIF → grey
//!   [`Grid`](photogrammetry_playground::raster::Grid) under `image::Limits`,
//!   upright by the EXIF orientation and reduced to the working size (HEIC,
//!   AVIF and RAW refused by their signatures).
//! - [`sample`]: the generated scanned frame photo with Example 4's fiducials.
//! - [`ops`]: the lab's operator menu: names and parameters → the core's
//!   whole-image functions → layers.
//! - [`paint`]: layers and photos to RGBA (the page's colour scales).
//! - `wasm`: the thin wasm-bindgen exports; the only file that knows JS.

pub mod decode;
pub mod ops;
pub mod paint;
pub mod sample;
#[cfg(target_arch = "wasm32")]
pub mod wasm;
