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
use photogrammetry_playground::raster::{Border, Gray, GrayF32, Grid};
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
    /// The grey values as [`Levels`] when they are not bytes, found once
    /// when first asked for: kept in the caller's cell ([`Image::with_levels`])
    /// or in `found`.
    keep: Option<&'a std::cell::OnceCell<Option<Levels>>>,
    found: std::cell::OnceCell<Option<Levels>>,
}

/// Grey values that are whole numbers over one scale: `grey = n / scale`
/// in one `f64` division, bit for bit, every `n` an integer 0 … 2²⁴ − 1
/// (exact in `f32`). A colour photo's BT.601 greys are such numbers
/// (`n = 299·R + 587·G + 114·B`, `scale` 1000; reduced `k×` by area
/// averages, the block's sum over `1000·k²`), and so are 16-bit greys
/// (`scale` 1): the fast filter passes read `n` ([`GrayF32`]), their sums
/// of `n` are exact integers below 2²⁴, and dividing by `scale` once gives
/// the grey values the reference reads — the same greys the explained
/// pixel's window holds.
#[derive(Debug, Clone, PartialEq)]
pub struct Levels {
    pub data: Vec<f32>,
    pub scale: f64,
    /// The largest `n`.
    pub max: f32,
}

/// The scales [`levels_of`] tries: 1 (16-bit greys), `1000·k²` (colour
/// photos' greys, reduced `k×` for `k` 1 … 4).
const LEVEL_SCALES: [f64; 5] = [1.0, 1000.0, 4000.0, 9000.0, 16000.0];

impl Levels {
    /// Levels given as they are (a band of a colour photo the page found
    /// once, `n` each a whole number 0 … 2²⁴ − 1 over `scale`); an error
    /// names what is wrong.
    pub fn new(data: Vec<f32>, scale: f64) -> Result<Levels> {
        if !(scale.is_finite() && scale > 0.0) {
            return Err(Error::input("scale", "must be a finite number above 0"));
        }
        if let Some(i) = data
            .iter()
            .position(|&n| !((0.0..16_777_216.0).contains(&n) && n.fract() == 0.0))
        {
            return Err(Error::input(
                "levels",
                format!("value {} is not a whole number 0 … 16777215", i + 1),
            ));
        }
        let max = data.iter().fold(0.0f32, |m, &n| if n > m { n } else { m });
        Ok(Levels { data, scale, max })
    }

    /// The grey values `n / scale` as a `width × height` grid (the
    /// reference paths' input), bit for bit the photo's greys.
    pub fn grid(&self, width: usize, height: usize) -> Result<Grid> {
        let data = self
            .data
            .iter()
            .map(|&n| f64::from(n) / self.scale)
            .collect();
        Grid::new("levels", width, height, data)
    }

    /// The levels as an image of `width × height` for the fast passes.
    pub fn view(&self, width: usize, height: usize) -> Option<GrayF32<'_>> {
        GrayF32::new("image", &self.data, width, height).ok()
    }

    /// The `size × size` window whose reference pixel is `(c, r)` in a
    /// `width`-wide image, as the reference functions read it: each grey
    /// `n / scale` (bit for bit the photo's grey). `None` where it does not
    /// fit.
    pub fn window(&self, width: usize, c: usize, r: usize, size: usize) -> Option<Grid> {
        let a = photogrammetry_playground::interest::anchor(size);
        let (c0, r0) = (c.checked_sub(a)?, r.checked_sub(a)?);
        if width == 0 || c0 + size > width || (r0 + size) * width > self.data.len() {
            return None;
        }
        let data = (r0..r0 + size)
            .flat_map(|y| &self.data[y * width + c0..y * width + c0 + size])
            .map(|&n| f64::from(n) / self.scale)
            .collect();
        Grid::new("window", size, size, data).ok()
    }

    /// A bound on the relative distance between a sum of squared
    /// differences of the levels over `scale²` (exact integers, then three
    /// `f64` roundings) and the reference's sum of `terms` squared
    /// differences of the divided greys: each grey `n / scale` is within
    /// `2⁻⁵³·max/scale` of its value, a difference of at least `1/scale`
    /// within `2⁻⁵²·max + 2⁻⁵³` of its own (relative), its square twice that,
    /// and a sum of positive terms adds `2⁻⁵³` a term — doubled for safety.
    pub fn sum_slack(&self, terms: usize) -> f64 {
        let max = f64::from(self.max).max(1.0);
        2.0 * (4.0 * max + 1.0 + terms as f64 + 8.0) * 2f64.powi(-53)
    }

    /// The least level `n` whose grey is at least `threshold`: `n ≥ cut`
    /// exactly when `n / scale ≥ threshold` in `f64` (the reference's
    /// comparison of the divided grey). The division is correctly rounded,
    /// so monotone in `n`: the levels on the upper side are those from one
    /// cut on, `⌈scale·threshold⌉` moved by a step where the product or the
    /// quotient rounds across it. Above every level: `2²⁵`.
    pub fn cut(&self, threshold: f64) -> f32 {
        const TOP: f64 = 33_554_432.0;
        let s = self.scale;
        let mut k = (threshold * s).ceil().clamp(0.0, TOP);
        while k > 0.0 && (k - 1.0) / s >= threshold {
            k -= 1.0;
        }
        while k < TOP && k / s < threshold {
            k += 1.0;
        }
        k as f32
    }
}

/// `values` as [`Levels`] when they are such numbers over one of the
/// scales 1, 1000, 4000, 9000, 16000 (checked at every value: `n / scale`
/// must give the value back bit for bit), else `None`.
pub fn levels_of(values: &[f64]) -> Option<Levels> {
    const LIMIT: f64 = 16_777_216.0;
    // (floor, not round: a wasm instruction, not a libm call; v ≥ 0)
    let level = |v: f64, scale: f64| {
        let n = (v * scale + 0.5).floor();
        (v >= 0.0 && n < LIMIT && n / scale == v, n)
    };
    // a scale is tried on every value only when a spread of 64 of them fit
    // (a photo's greys fail a wrong scale at once; a dark top rows' whole
    // numbers would fit scale 1 for a long way)
    let step = (values.len() / 64).max(1);
    for scale in LEVEL_SCALES {
        if !values.iter().step_by(step).all(|&v| level(v, scale).0) {
            continue;
        }
        // one pass without a branch per value (the check folded into `ok`)
        let mut data = vec![0.0f32; values.len()];
        let (mut ok, mut max) = (true, 0.0f32);
        for (d, &v) in data.iter_mut().zip(values) {
            let (fits, n) = level(v, scale);
            ok &= fits;
            let n = n as f32;
            max = if n > max { n } else { max };
            *d = n;
        }
        if ok {
            return Some(Levels { data, scale, max });
        }
    }
    None
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
            keep: None,
            found: std::cell::OnceCell::new(),
        }
    }

    /// The same image with the caller's cell for its [`Levels`] (the wasm
    /// `LabImage` keeps them with the photo): found once, when an operator
    /// first asks, and kept there for the next.
    pub fn with_levels(self, keep: &'a std::cell::OnceCell<Option<Levels>>) -> Self {
        Image {
            keep: Some(keep),
            ..self
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
            keep: None,
            found: std::cell::OnceCell::new(),
        })
    }

    /// An image of `width × height` given by its [`Levels`] alone, kept in
    /// the caller's cell (a band of a colour photo sent as levels), without
    /// its `f64` grid (built by [`Image::grid`] only if a reference path
    /// needs it).
    pub fn from_levels(
        width: usize,
        height: usize,
        keep: &'a std::cell::OnceCell<Option<Levels>>,
    ) -> Result<Self> {
        match keep.get() {
            Some(Some(l)) => GrayF32::new("levels", &l.data, width, height)?,
            _ => return Err(Error::input("levels", "are missing")),
        };
        Ok(Image {
            width,
            height,
            given: None,
            built: std::cell::OnceCell::new(),
            bytes: None,
            keep: Some(keep),
            found: std::cell::OnceCell::new(),
        })
    }

    /// The grey values as a grid (the reference paths' input): the caller's,
    /// or built from the bytes or the levels the first time it is asked for.
    pub fn grid(&self) -> &Grid {
        if let Some(g) = self.given {
            return g;
        }
        self.built.get_or_init(|| {
            let kept = self.keep.and_then(|k| k.get()).and_then(|l| l.as_ref());
            match (self.gray(), kept) {
                (Some(g), _) => g.to_grid(),
                (None, Some(l)) => l
                    .grid(self.width, self.height)
                    .unwrap_or_else(|_| Grid::filled(self.width, self.height, 0.0)),
                (None, None) => Grid::filled(self.width, self.height, 0.0),
            }
        })
    }

    /// The grey values as [`Levels`] when the image is not 8-bit and its
    /// greys are such numbers (found once; `None` for an 8-bit image: its
    /// bytes are the fast paths' input).
    pub fn levels(&self) -> Option<&Levels> {
        if self.bytes.is_some() {
            return None;
        }
        self.keep
            .unwrap_or(&self.found)
            .get_or_init(|| levels_of(self.grid().data()))
            .as_ref()
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
            keep: None,
            found: std::cell::OnceCell::new(),
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
            keep: Some(img.keep.unwrap_or(&img.found)),
            found: std::cell::OnceCell::new(),
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
