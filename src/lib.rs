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
//! - [`matching`]: least-squares matching (1-D, 2-D; shift, radiometric,
//!   affine + radiometric) with the record of every iteration.
//! - [`resample`]: nearest, bilinear and bicubic (cubic convolution) values
//!   at fractional positions, with their intermediates.
//! - [`filter`]: kernels (smoothing, Laplacian, sharpening, edges), median,
//!   gradients and magnitude, with a border policy.
//! - [`correlation`]: normalized cross-correlation (1-D, 2-D, surfaces) and subpixel peaks.
//! - [`chain`]: Freeman chain codes, boundary tracing, boundary descriptors.
//! - [`interest`]: the Förstner and Moravec interest operators, on a window
//!   and as whole-image maps with thresholding and suppression.
//! - [`transform`]: 2-D transformations estimated from point pairs by least squares.
//! - [`projection`]: ellipsoids, the transverse Mercator (Krüger series and
//!   Snyder's classical one), UTM zones and bands, degrees-minutes-seconds.
//! - [`read`]: the one reader of numbers a person types (inputs and
//!   practice answers): units, fractions, ×10^.
//! - [`rng`]: the one pseudo-random generator (SplitMix64).
//! - [`examples`]: the catalog of worked examples, their input fields and the
//!   solvers that turn core results into steps.
//! - [`practice`]: practice mode: variant codes and generators, answer
//!   reading and grading with carried-forward errors and known mistakes.
//! - `wasm`: the thin wasm-bindgen boundary (`catalog`, `solve`,
//!   `parse_inputs`, `practice`, `grade`) as macros that the page's modules
//!   (`web/<topic>/`, `web/all/`) invoke; the only file that knows about
//!   JavaScript.

pub mod chain;
pub mod coords;
pub mod correlation;
pub mod error;
pub mod examples;
pub mod filter;
pub mod interest;
pub mod lsq;
pub mod matching;
pub mod practice;
pub mod projection;
pub mod raster;
pub mod read;
pub mod resample;
pub mod rng;
pub mod solution;
pub mod transform;
#[cfg(target_arch = "wasm32")]
pub mod wasm;
