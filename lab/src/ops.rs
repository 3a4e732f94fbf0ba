//! The lab's operator menu: names and parameters in, the core's
//! whole-image functions called, layers out. Nothing is computed here that
//! the core does not compute for the worked examples (DESIGN.md's first
//! rule): this module only picks kernels, cuts windows and collects
//! results.
//!
//! Every operator runs the core's fast path over the whole image when the
//! image is 8-bit (every grey value an integer 0 … 255: `Image::bytes`),
//! the reference functions otherwise. Layers are `f32`; the worked
//! example's exact number of one pixel is [`exact_at`]'s (the reference
//! function on that pixel's window). docs/lab.md states how close each
//! fast layer is to its reference; `lab/tests/fast_layers.rs` checks it at
//! every pixel.

use std::borrow::Cow;

use photogrammetry_playground::error::{Error, Result};
use photogrammetry_playground::filter::{self, Kernel, Region};
use photogrammetry_playground::raster::{Border, Gray, Grid};
use photogrammetry_playground::read::short;

mod boundary;
mod correlation;
mod custom;
mod exact;
mod filters;
mod forstner;
mod moravec;
mod resample;
pub use boundary::*;
pub use correlation::*;
pub use custom::*;
pub use exact::*;
pub use filters::*;
pub use forstner::*;
pub use moravec::*;
pub use resample::*;

/// One result image: `width × height` values whose pixel `(0, 0)` sits on
/// input pixel `(c0, r0)`; `NaN` where there is no value.
#[derive(Debug, Clone, PartialEq)]
pub struct Layer {
    pub name: String,
    pub width: usize,
    pub height: usize,
    pub c0: usize,
    pub r0: usize,
    pub data: Vec<f32>,
    /// Signed values (drawn with the diverging colour scale).
    pub signed: bool,
}

impl Layer {
    /// A layer of `f32` values over `region`.
    pub fn new(name: &str, region: Region, data: Vec<f32>, signed: bool) -> Self {
        Layer {
            name: name.to_string(),
            width: region.width,
            height: region.height,
            c0: region.c0,
            r0: region.r0,
            data,
            signed,
        }
    }

    /// A reference result (`f64`) as a layer (each value rounded to `f32`).
    pub fn from_grid(name: &str, g: &Grid, region: Region, signed: bool) -> Self {
        let data = g.data().iter().map(|&v| v as f32).collect();
        Layer::new(
            name,
            Region {
                width: g.width(),
                height: g.height(),
                ..region
            },
            data,
            signed,
        )
    }

    /// The value at input pixel `(c, r)`, if the layer covers it.
    pub fn at(&self, c: usize, r: usize) -> Option<f64> {
        if c < self.c0 || r < self.r0 || c >= self.c0 + self.width || r >= self.r0 + self.height {
            return None;
        }
        let v = self.data[(r - self.r0) * self.width + (c - self.c0)];
        (!v.is_nan()).then_some(f64::from(v))
    }
}

/// The whole image as a region.
pub fn whole(width: usize, height: usize) -> Region {
    Region {
        c0: 0,
        r0: 0,
        width,
        height,
    }
}

/// An image as the operators take it: its grey values, and their bytes
/// when every value is an integer 0 … 255 (the fast paths' input), kept by
/// the caller (the wasm `LabImage` converts once) or found here. An image
/// made from bytes alone ([`Image::from_bytes`]: a band of an 8-bit photo)
/// has no `f64` grid until a reference path asks for one ([`Image::grid`]
/// builds it then, once): the fast paths read the bytes only.
#[derive(Debug, Clone)]
pub struct Image<'a> {
    width: usize,
    height: usize,
    given: Option<&'a Grid>,
    built: std::cell::OnceCell<Grid>,
    bytes: Option<Cow<'a, [u8]>>,
}

impl<'a> Image<'a> {
    /// `grid` with the bytes the caller already has (`None`: not 8-bit).
    pub fn with_bytes(grid: &'a Grid, bytes: Option<&'a [u8]>) -> Self {
        let bytes = bytes
            .filter(|b| b.len() == grid.width() * grid.height())
            .map(Cow::Borrowed);
        Image {
            width: grid.width(),
            height: grid.height(),
            given: Some(grid),
            built: std::cell::OnceCell::new(),
            bytes,
        }
    }

    /// An 8-bit image of `width × height` `bytes` (row-major), without its
    /// `f64` grid (built by [`Image::grid`] only if a reference path needs it).
    pub fn from_bytes(width: usize, height: usize, bytes: &'a [u8]) -> Result<Self> {
        Gray::new("image", bytes, width, height)?;
        Ok(Image {
            width,
            height,
            given: None,
            built: std::cell::OnceCell::new(),
            bytes: Some(Cow::Borrowed(bytes)),
        })
    }

    /// The grey values as a grid (the reference paths' input): the caller's,
    /// or built from the bytes the first time it is asked for.
    pub fn grid(&self) -> &Grid {
        if let Some(g) = self.given {
            return g;
        }
        self.built.get_or_init(|| match self.gray() {
            Some(g) => g.to_grid(),
            None => Grid::filled(self.width, self.height, 0.0),
        })
    }

    /// The 8-bit view, when the image is 8-bit.
    pub fn gray(&self) -> Option<Gray<'_>> {
        let b = self.bytes.as_deref()?;
        Gray::new("image", b, self.width, self.height).ok()
    }

    pub fn width(&self) -> usize {
        self.width
    }
    pub fn height(&self) -> usize {
        self.height
    }
}

impl<'a> From<&'a Grid> for Image<'a> {
    fn from(grid: &'a Grid) -> Self {
        Image {
            width: grid.width(),
            height: grid.height(),
            given: Some(grid),
            built: std::cell::OnceCell::new(),
            bytes: grid.to_u8().map(Cow::Owned),
        }
    }
}

impl<'a> From<&'a Image<'a>> for Image<'a> {
    fn from(img: &'a Image<'a>) -> Self {
        Image {
            width: img.width,
            height: img.height,
            given: img.given.or(img.built.get()),
            built: std::cell::OnceCell::new(),
            bytes: img.bytes.as_deref().map(Cow::Borrowed),
        }
    }
}

/// A border policy by name: `replicate`, `reflect`, `zero`, `crop`.
pub fn border(name: &str) -> Result<Border> {
    match name {
        "replicate" => Ok(Border::Replicate),
        "reflect" => Ok(Border::Reflect),
        "zero" => Ok(Border::Zero),
        "crop" => Ok(Border::Crop),
        _ => Err(Error::input(
            "border",
            format!(
                "must be replicate, reflect, zero or crop (got \"{}\")",
                short(name)
            ),
        )),
    }
}

/// A kernel by the `filter-window` example's names (`None` for `median`).
pub fn kernel(name: &str, custom: Option<(&[Vec<f64>], f64)>) -> Result<Option<Kernel>> {
    if let Some(k) = filter::by_name(name) {
        return Ok(k);
    }
    Ok(Some(match name {
        "custom" => match custom {
            Some((rows, d)) => Kernel::new("custom_kernel", rows, d)?,
            None => return Err(Error::input("custom_kernel", "is missing")),
        },
        _ => return Err(Error::input("kernel", format!("unknown kernel \"{name}\""))),
    }))
}

/// An interest point with its standard error ellipse (Förstner) in pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    pub c: usize,
    pub r: usize,
    pub score: f64,
    /// Semi-axes of the error ellipse (px) and the major axis's direction
    /// (radians from +c toward +r); zero for Moravec points.
    pub major: f64,
    pub minor: f64,
    pub angle: f64,
}

/// A rectangle of an image: top-left `(c0, r0)`, `width × height`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rect {
    pub c0: usize,
    pub r0: usize,
    pub width: usize,
    pub height: usize,
}

fn cut(img: &Grid, field: &str, r: Rect) -> Result<Grid> {
    img.window(r.c0, r.r0, r.width, r.height).ok_or_else(|| {
        Error::input(
            field,
            format!(
                "the {}×{} box at column {}, row {} does not lie inside the {}×{} image",
                r.width,
                r.height,
                r.c0,
                r.r0,
                img.width(),
                img.height()
            ),
        )
    })
}
