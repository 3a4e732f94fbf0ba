//! The lab's wasm-bindgen boundary: thin exports over [`crate::decode`],
//! [`crate::sample`] and [`crate::ops`]. Images stay in wasm memory as
//! [`LabImage`]; result layers leave as `Float32Array`s (one copy each),
//! which the worker posts to the page as transferables. Every error is a
//! thrown JS `Error` whose message names the field or the file; a string
//! argument is taken as a `JsValue` and checked (`wasm::string_arg`), so that
//! a wrong type is such an error, never a trap.

use crate::decode;
use crate::ops::{self, Layer, Point, Rect};
use crate::sample;
use js_sys::{Array, Float64Array, Object, Reflect};
use photogrammetry_playground::error::Error;
use photogrammetry_playground::filter;
use photogrammetry_playground::matching::{Model, Status};
use photogrammetry_playground::raster::Grid;
use photogrammetry_playground::wasm::string_arg;
use wasm_bindgen::prelude::*;

fn js_error(e: Error) -> JsError {
    JsError::new(&e.to_string())
}

fn obj(fields: &[(&str, JsValue)]) -> Result<JsValue, JsError> {
    let o = Object::new();
    for (k, v) in fields {
        Reflect::set(&o, &JsValue::from_str(k), v)
            .map_err(|_| JsError::new("internal error (please report): cannot build a result"))?;
    }
    Ok(o.into())
}

fn num(x: f64) -> JsValue {
    JsValue::from_f64(x)
}

/// A grey image held in wasm memory: its grey values as an `f64` grid,
/// or, for an image made from 8-bit bytes (`image_from_u8`: the pool's
/// bands), the bytes alone, the grid built only when a reference path or
/// the explained pixel asks for it ([`LabImage::grid`]).
#[wasm_bindgen]
pub struct LabImage {
    width: usize,
    height: usize,
    grid: std::cell::OnceCell<Grid>,
    format: String,
    colour: String,
    bits: u32,
    max_value: f64,
    photo: decode::Photo,
    /// The grey values as bytes when the image is 8-bit, found once (the
    /// operators' fast paths read them: `run::image`).
    bytes: std::cell::OnceCell<Option<Vec<u8>>>,
    /// The grey values as levels when they are not bytes (a colour photo's
    /// BT.601 greys: `ops::Levels`), found when an operator first asks
    /// (`ops::Image::levels`) and kept for every later one.
    levels: std::cell::OnceCell<Option<ops::Levels>>,
}

impl LabImage {
    /// The grey values as a grid: built from the bytes (or the levels) the
    /// first time it is needed when the image was made from them.
    fn grid(&self) -> &Grid {
        self.grid.get_or_init(|| {
            // a band sent as levels (`image_from_levels`): n / scale
            if let Some(Some(l)) = self.levels.get() {
                if let Ok(g) = l.grid(self.width, self.height) {
                    return g;
                }
            }
            let b = self.bytes.get().and_then(|b| b.as_deref()).unwrap_or(&[]);
            match photogrammetry_playground::raster::Gray::new("image", b, self.width, self.height)
            {
                Ok(g) => g.to_grid(),
                Err(_) => Grid::filled(self.width, self.height, 0.0),
            }
        })
    }

    /// Its bytes when it is 8-bit (found once from the grid).
    fn bytes(&self) -> Option<&[u8]> {
        self.bytes.get_or_init(|| self.grid().to_u8()).as_deref()
    }
}

/// A photo's orientation and reduction as the page reads them (`photo()`,
/// `probe_image`): `orientation` (1 … 8), `turned` (its words, or
/// `undefined`), `photoWidth`, `photoHeight` (upright, before reduction),
/// `factor` (1: not reduced), `width`, `height` (the lab's grid),
/// `reduced` (the reduction in words, or `undefined`).
fn photo_js(p: &decode::Photo) -> Result<JsValue, JsError> {
    let words = |w: Option<String>| w.map_or(JsValue::UNDEFINED, |w| JsValue::from_str(&w));
    obj(&[
        ("orientation", num(f64::from(p.orientation))),
        ("turned", words(p.turned())),
        ("photoWidth", num(p.width as f64)),
        ("photoHeight", num(p.height as f64)),
        ("factor", num(p.factor as f64)),
        ("width", num(p.work_width as f64)),
        ("height", num(p.work_height as f64)),
        ("reduced", words(p.reduced())),
    ])
}

#[wasm_bindgen]
impl LabImage {
    /// The EXIF orientation applied at decoding, 1 … 8 (1: none).
    pub fn orientation(&self) -> u8 {
        self.photo.orientation
    }
    /// The reduction factor `k`: one pixel of this image is the area
    /// average of `k × k` pixels of the photo (1: not reduced).
    pub fn factor(&self) -> usize {
        self.photo.factor
    }
    /// What decoding did (orientation, reduction), as `photo_js` says.
    pub fn photo(&self) -> Result<JsValue, JsError> {
        photo_js(&self.photo)
    }
    pub fn width(&self) -> usize {
        self.width
    }
    pub fn height(&self) -> usize {
        self.height
    }
    /// `PNG`, `JPEG`, `TIFF`, `generated` or `raw`.
    pub fn format(&self) -> String {
        self.format.clone()
    }
    /// `grey` or `colour` (what the file stored).
    pub fn colour(&self) -> String {
        self.colour.clone()
    }
    pub fn bits(&self) -> u32 {
        self.bits
    }
    /// The largest grey value the sample depth allows.
    pub fn max_value(&self) -> f64 {
        self.max_value
    }
    /// The grey values, row-major (one copy out of wasm memory).
    pub fn grey(&self) -> Float64Array {
        Float64Array::from(self.grid().data())
    }
    /// The `w × h` neighbourhood centred on `(c, r)` read under `border`
    /// (`filter::neighbourhood`), row-major: the window a worked example
    /// gets for that pixel.
    pub fn neighbourhood(
        &self,
        c: usize,
        r: usize,
        w: usize,
        h: usize,
        border: JsValue,
    ) -> Result<Float64Array, JsError> {
        let b = ops::border(&string_arg("border", "naming a border rule", &border)?)
            .map_err(js_error)?;
        filter::neighbourhood(self.grid(), c, r, w, h, b)
            .map(|v| Float64Array::from(v.as_slice()))
            .ok_or_else(|| JsError::new("window: part of it lies outside the image (border crop)"))
    }
    /// The grey value at `(c, r)`, `undefined` outside.
    pub fn value(&self, c: usize, r: usize) -> Option<f64> {
        self.grid().get(c, r)
    }
    /// The `w × h` window with top-left `(c, r)`, row-major (`Float64Array`).
    pub fn window(&self, c: usize, r: usize, w: usize, h: usize) -> Result<Float64Array, JsError> {
        self.grid()
            .window(c, r, w, h)
            .map(|g| Float64Array::from(g.data()))
            .ok_or_else(|| JsError::new("window: does not lie inside the image"))
    }
}

fn wrap(grid: Grid, format: &str, colour: &str, bits: u32, max_value: f64) -> LabImage {
    let (w, h) = (grid.width(), grid.height());
    let img = bare(w, h, format, colour, bits, max_value);
    let _ = img.grid.set(grid);
    img
}

/// A `w × h` image with neither its grid nor its bytes yet (`wrap`, `image_from_u8`).
fn bare(w: usize, h: usize, format: &str, colour: &str, bits: u32, max_value: f64) -> LabImage {
    LabImage {
        photo: decode::Photo {
            orientation: 1,
            width: w,
            height: h,
            factor: 1,
            work_width: w,
            work_height: h,
        },
        width: w,
        height: h,
        grid: std::cell::OnceCell::new(),
        format: format.into(),
        colour: colour.into(),
        bits,
        max_value,
        bytes: std::cell::OnceCell::new(),
        levels: std::cell::OnceCell::new(),
    }
}

/// Decodes a PNG, JPEG, TIFF, WebP, BMP or GIF file to grey values (BT.601
/// luma), upright by its EXIF orientation and reduced to the working size
/// when larger (`photo()` says what was done).
#[wasm_bindgen]
pub fn decode_image(name: JsValue, bytes: &[u8]) -> Result<LabImage, JsError> {
    let name = string_arg("name", "naming the file", &name)?;
    let d = decode::decode(&name, bytes).map_err(js_error)?;
    let mut img = wrap(d.grid, d.format, d.colour, d.bits, d.max_value);
    img.photo = d.photo;
    Ok(img)
}

/// What `decode_image` would make of a file, from its header only:
/// `{ format, orientation, turned, photoWidth, photoHeight, factor, width,
/// height, reduced }` (`photo_js`), or the error `decode_image` would throw
/// for a file the lab refuses. The page offers a reduction with it.
#[wasm_bindgen]
pub fn probe_image(name: JsValue, bytes: &[u8]) -> Result<JsValue, JsError> {
    let name = string_arg("name", "naming the file", &name)?;
    let (format, photo) = decode::probe(&name, bytes).map_err(js_error)?;
    let o = photo_js(&photo)?;
    Reflect::set(&o, &JsValue::from_str("format"), &JsValue::from_str(format))
        .map_err(|_| JsError::new("internal error (please report): cannot build a result"))?;
    Ok(o)
}

/// An image from raw 8-bit grey bytes (row-major): a band of an 8-bit
/// photo (the pool's), the benchmark's image. Only its bytes are kept: the
/// operators' fast paths read them, and the `f64` grid is built only if a
/// reference path or an explained pixel needs it.
#[wasm_bindgen]
pub fn image_from_u8(width: usize, height: usize, data: &[u8]) -> Result<LabImage, JsError> {
    photogrammetry_playground::raster::Gray::new("image", data, width, height).map_err(js_error)?;
    let img = bare(width, height, "raw", "grey", 8, 255.0);
    let _ = img.bytes.set(Some(data.to_vec()));
    Ok(img)
}

/// The generated scanned frame photo with Example 4's fiducials.
#[wasm_bindgen]
pub fn scanned_frame() -> LabImage {
    wrap(sample::scanned_frame(), "generated", "grey", 8, 255.0)
}

/// The scanned frame's truth: `{ affine: [a, b, e, c, d, f], marks: [c, r]×4
/// (true), nominal: [c, r]×4, calibrated: [x, y]×4, pixel_mm }`.
#[wasm_bindgen]
pub fn scanned_frame_truth() -> Result<JsValue, JsError> {
    let flat = |v: Vec<f64>| -> JsValue { Float64Array::from(v.as_slice()).into() };
    obj(&[
        ("affine", flat(sample::TRUE_AFFINE.to_vec())),
        (
            "marks",
            flat(
                sample::true_marks()
                    .iter()
                    .flat_map(|&(c, r)| [c, r])
                    .collect(),
            ),
        ),
        (
            "nominal",
            flat(
                sample::nominal_marks()
                    .iter()
                    .flat_map(|&(c, r)| [c, r])
                    .collect(),
            ),
        ),
        (
            "calibrated",
            flat(sample::calibrated().iter().flatten().copied().collect()),
        ),
        ("pixel_mm", num(sample::PIXEL_MM)),
    ])
}

/// Traps the wasm instance on purpose (a wasm `unreachable` instruction),
/// so that the recovery from a trapped instance can be tested
/// (`lab/tests/web_lab.rs`). Only in builds with the `test-hooks` feature
/// (the tests' builds turn it on): the page's module has no such export.
#[cfg(feature = "test-hooks")]
#[wasm_bindgen]
pub fn trap_for_tests() {
    core::arch::wasm32::unreachable()
}

// Layers and photos painted to RGBA in the worker (crate::paint).
mod paint;

// The pool's bands (www/lab/tiles.js): Förstner's threshold over the whole photo.
mod bands;
pub use bands::{image_from_grey, image_from_levels, image_levels};

// The page's SIMD build decodes JPEG only; the others come decoded from the scalar build.
mod formats;

// The operators' exports: run_*, ForstnerMaps, op_halo, exact_at (crate::ops).
mod run;
pub use run::*;

// The fast 8-bit exports that `npm run bench -- ops` times: only in builds
// with the `bench` feature (scripts/bench-ops/run.sh and the tests' builds).
#[cfg(feature = "bench")]
mod fast;
#[cfg(feature = "bench")]
pub use fast::FastImage;
