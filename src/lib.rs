//! Photogrammetry Playground: the worked examples of digital photogrammetry
//! and image processing, solved step by step, for the browser (through
//! WebAssembly) and natively.
//!
//! What lives where:
//! - [`error`]: the one [`Error`](error::Error) type; nothing panics on input.
//! - [`solution`]: the step-by-step trace ([`Solution`](solution::Solution)).
//! - [`raster`]: the [`Grid`](raster::Grid) every image operator works on,
//!   with checked access and a [`Border`](raster::Border) policy.
//! - [`lsq`]: least-squares adjustment with its intermediates, rank and
//!   condition checks.
//! - [`coords`]: pixel ↔ image coordinates, pixel size, scale, GSD.
//! - [`chain`]: Freeman chain codes, boundary tracing, boundary descriptors.
//! - [`interest`]: the Förstner and Moravec interest operators, on a window
//!   and as whole-image maps with thresholding and suppression.
//! - [`examples`]: the catalog of worked examples, their input fields and the
//!   solvers that turn core results into steps.
//! - `wasm`: the thin wasm-bindgen exports (`catalog`, `solve`,
//!   `parse_inputs`); the only file that knows about JavaScript.

pub mod chain;
pub mod coords;
pub mod error;
pub mod examples;
pub mod interest;
pub mod lsq;
pub mod raster;
pub mod solution;
#[cfg(target_arch = "wasm32")]
pub mod wasm;
