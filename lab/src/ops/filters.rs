//! Filters and edges over the whole image: on an 8-bit image, or one whose
//! greys are [`Levels`] (a colour photo's BT.601 greys, 16-bit greys), the
//! core's `filter::fast` paths (exact integer sums, divided in `f64` as the
//! reference divides — by the levels' scale too —, then rounded to the
//! layer's `f32`), otherwise `filter::correlate` / `filter::median` /
//! `filter::gradient`.

use super::*;
use photogrammetry_playground::filter::fast::{self, Rows};

/// What the fast passes read: an 8-bit image's bytes, or [`Levels`]
/// (`n`, with `grey = n / scale`; `max` the largest `n`).
#[derive(Clone, Copy)]
enum Source<'a> {
    Bytes(Gray<'a>),
    Levels(GrayF32<'a>, f64, f32),
}

impl<'a> Source<'a> {
    /// The image's fast input, `None` when it has neither.
    fn of(img: &'a Image<'a>) -> Option<Self> {
        if let Some(g) = img.gray() {
            return Some(Source::Bytes(g));
        }
        let l = img.levels()?;
        Some(Source::Levels(
            l.view(img.width(), img.height())?,
            l.scale,
            l.max,
        ))
    }
    fn size(&self) -> (usize, usize) {
        match self {
            Source::Bytes(g) => (g.width(), g.height()),
            Source::Levels(g, ..) => (g.width(), g.height()),
        }
    }
    /// The scale the sums are divided by (1 for bytes).
    fn scale(&self) -> f64 {
        match self {
            Source::Bytes(_) => 1.0,
            Source::Levels(_, s, _) => *s,
        }
    }
    /// The largest value (255 for bytes).
    fn max(&self) -> f64 {
        match self {
            Source::Bytes(_) => 255.0,
            Source::Levels(_, _, m) => f64::from(*m),
        }
    }
    fn separable(&self, kx: &[f32], ky: &[f32], d: f32, b: Border, out: &mut [f32]) -> Result<()> {
        match *self {
            Source::Bytes(g) => fast::separable(g, kx, ky, d, b, out),
            Source::Levels(g, ..) => fast::separable(g, kx, ky, d, b, out),
        }
    }
}

/// A filter over the whole image: `filter::correlate` with the named
/// kernel (or the custom one), or `filter::median` 3×3.
pub fn filter_image<'a>(
    img: impl Into<Image<'a>>,
    kernel_name: &str,
    border: Border,
    custom: Option<(&[Vec<f64>], f64)>,
) -> Result<Layer> {
    let img = img.into();
    if let Some(layer) = fast_filter(&img, kernel_name, border, custom)? {
        return Ok(layer);
    }
    let f = match kernel(kernel_name, custom)? {
        Some(k) => filter::correlate(img.grid(), &k, border)?,
        None => filter::median(img.grid(), 3, 3, border)?,
    };
    let signed = f.output.data().iter().any(|&v| v < 0.0);
    Ok(Layer::from_grid(kernel_name, &f.output, f.region, signed))
}

/// The separable integer kernels of the menu as `(kx, ky, divisor)`:
/// `kernel = ky ⊗ kx / divisor` entry by entry (lab/tests/operators.rs
/// checks each against `filter::by_name`).
pub fn separable_taps(name: &str) -> Option<(&'static [f32], &'static [f32], f64)> {
    Some(match name {
        "mean" => (&[1.0; 3], &[1.0; 3], 9.0),
        "gaussian-3" => (&[1.0, 2.0, 1.0], &[1.0, 2.0, 1.0], 16.0),
        "gaussian-5" => (
            &[1.0, 4.0, 6.0, 4.0, 1.0],
            &[1.0, 4.0, 6.0, 4.0, 1.0],
            256.0,
        ),
        _ => return None,
    })
}

/// `(kx, ky)` with `rows[j][i] = ky[j]·kx[i]` exactly, for a kernel of
/// integers (a k×k mean, a custom Gaussian), else `None`.
fn integer_factors(rows: &[Vec<f64>]) -> Option<(Vec<f32>, Vec<f32>)> {
    if rows.iter().flatten().any(|v| v.fract() != 0.0) {
        return None;
    }
    let base = rows.iter().find(|r| r.iter().any(|&v| v != 0.0))?;
    let i0 = base.iter().position(|&v| v != 0.0)?;
    let ky: Vec<f64> = rows.iter().map(|r| r[i0] / base[i0]).collect();
    let exact = rows
        .iter()
        .zip(&ky)
        .all(|(r, &y)| r.iter().zip(base).all(|(&v, &x)| y * x == v));
    (exact && ky.iter().all(|v| v.fract() == 0.0)).then(|| {
        (
            base.iter().map(|&v| v as f32).collect(),
            ky.iter().map(|&v| v as f32).collect(),
        )
    })
}

/// The part of a full-size fast output that `region` covers, through `f`
/// (in place when the region is the whole image).
fn finish(mut full: Vec<f32>, w: usize, region: Region, f: impl Fn(f32) -> f32) -> Vec<f32> {
    if region.c0 == 0 && region.r0 == 0 && region.width == w {
        full.truncate(region.width * region.height);
        for v in &mut full {
            *v = f(*v);
        }
        return full;
    }
    let mut out = Vec::with_capacity(region.width * region.height);
    for r in region.r0..region.r0 + region.height {
        let start = r * w + region.c0;
        if let Some(row) = full.get(start..start + region.width) {
            out.extend(row.iter().map(|&v| f(v)));
        }
    }
    out
}

/// The response `Σ n·f / divisor` of every pixel (`f32`), by the
/// separable pass when the kernel factors into integer vectors.
fn response(
    g: impl Rows + Copy,
    rows: &[Vec<f64>],
    divisor: f32,
    border: Border,
) -> Result<Vec<f32>> {
    let (w, h) = (g.width(), g.height());
    let mut out = vec![0.0f32; w * h];
    if let Some((kx, ky)) = integer_factors(rows) {
        fast::separable(g, &kx, &ky, divisor, border, &mut out)?;
    } else {
        let k: Vec<f32> = rows.iter().flatten().map(|&v| v as f32).collect();
        let kw = rows.first().map_or(0, Vec::len);
        fast::correlate(g, &k, (kw, rows.len()), divisor, border, &mut out)?;
    }
    Ok(out)
}

/// Whether `Σ n·f / d` can be divided in `f32` with the reference's bits
/// rounded to `f32`: integer taps with `Σ|n|·255 < 2²⁴` (every sum an
/// exact integer in `f32`) and an integer divisor below 2²⁴ — the `f32`
/// quotient of two exact integers is then the `f32` nearest the `f64`
/// one (no double rounding: a quotient `s/d` never lies within 2⁻⁵³ of
/// an `f32` midpoint it is not on).
fn f32_division_exact(rows: &[Vec<f64>], d: f64) -> bool {
    sums_exact(rows, 255.0) && d.fract() == 0.0 && d != 0.0 && d.abs() < 16_777_216.0
}

/// Whether every sum `Σ n·f` of integer taps over values `0 … max` is an
/// exact integer in `f32` (`Σ|n|·max < 2²⁴`).
fn sums_exact(rows: &[Vec<f64>], max: f64) -> bool {
    let taps = rows.iter().flatten();
    let integer = taps.clone().all(|v| v.fract() == 0.0);
    integer && taps.map(|v| v.abs()).sum::<f64>() * max < 16_777_216.0
}

/// `Σ n·f / divisor` as the reference divides it (`f64`; `+ 0.0` turns a
/// `−0` sum into `0`), rounded to `f32`.
fn divided(s: f32, divisor: f64) -> f32 {
    ((f64::from(s) + 0.0) / divisor) as f32
}

/// The menu's filters on an 8-bit image, or one of [`Levels`], by the
/// core's fast paths: the 3×3 median by `filter::fast::median3` (bytes) or
/// `median3_f32` (levels; the middle `n` over the scale), every kernel by
/// [`response`] then [`divided`] (by `divisor × scale`); `None` for other
/// images (the reference path) or when `border` leaves no pixel. For
/// kernels of integers with `Σ|n|·max < 2²⁴` every sum is exact: on bytes
/// every value is the reference's rounded to `f32` (lab/tests/fast_layers.rs),
/// on levels the exact quotient rounded to `f32` (the reference's `f64`
/// sum of the divided greys is within a few `f64` roundings of it).
pub fn fast_filter(
    img: &Image,
    kernel_name: &str,
    border: Border,
    custom: Option<(&[Vec<f64>], f64)>,
) -> Result<Option<Layer>> {
    let Some(src) = Source::of(img) else {
        return Ok(None);
    };
    let (w, h) = src.size();
    let scale = src.scale();
    let k = kernel(kernel_name, custom)?;
    let (hw, hh) = k
        .as_ref()
        .map_or((1, 1), |k| (k.half_width(), k.half_height()));
    let Some(region) = filter::output_region(w, h, hw, hh, border) else {
        return Ok(None);
    };
    let cut = |r: usize| r * w + region.c0..r * w + region.c0 + region.width;
    let (data, signed) = match (&k, src) {
        (None, Source::Bytes(g)) => {
            let mut out = vec![0u8; w * h];
            fast::median3(g, border, &mut out)?;
            let mut data = Vec::with_capacity(region.width * region.height);
            for r in region.r0..region.r0 + region.height {
                let row = out.get(cut(r)).unwrap_or(&[]);
                data.extend(row.iter().map(|&v| f32::from(v)));
            }
            (data, false)
        }
        (None, Source::Levels(g, ..)) => {
            let mut out = vec![0.0f32; w * h];
            fast::median3_f32(g, border, &mut out)?;
            let mut data = Vec::with_capacity(region.width * region.height);
            for r in region.r0..region.r0 + region.height {
                let row = out.get(cut(r)).unwrap_or(&[]);
                data.extend(row.iter().map(|&v| (f64::from(v) / scale) as f32));
            }
            (data, false)
        }
        (Some(k), _) => {
            let rows = k.numerators().rows();
            let d = k.divisor();
            // divided in the pass (f32) where that gives the reference's
            // value rounded (bytes), else summed there and divided here in f64
            let in_pass = matches!(src, Source::Bytes(_)) && f32_division_exact(&rows, d);
            let dp = if in_pass { d as f32 } else { 1.0 };
            let full = match separable_taps(kernel_name) {
                Some((kx, ky, _)) => {
                    let mut out = vec![0.0f32; w * h];
                    match src {
                        // (sums of 9 bytes as integers, divided by 9 in f32: the same values)
                        Source::Bytes(g) if kernel_name == "mean" && in_pass => {
                            fast::mean3(g, border, &mut out)?
                        }
                        _ => src.separable(kx, ky, dp, border, &mut out)?,
                    }
                    out
                }
                None => match src {
                    Source::Bytes(g) => response(g, &rows, dp, border)?,
                    Source::Levels(g, ..) => response(g, &rows, dp, border)?,
                },
            };
            let whole_region = region.c0 == 0 && region.r0 == 0 && region.width == w;
            let data = if in_pass && whole_region {
                // (the passes start their sums at +0: no −0 to turn)
                full
            } else if in_pass {
                finish(full, w, region, |v| v + 0.0)
            } else {
                finish(full, w, region, |s| divided(s, d * scale))
            };
            let signed = data.iter().any(|&v| v < 0.0);
            (data, signed)
        }
    };
    Ok(Some(Layer::new(kernel_name, region, data, signed)))
}

/// The edge kernels by name: `(kx, ky)` of `filter::gradient`, and their
/// separable taps `((sx, [1 0 −1]), ([−1 0 1], sy))`: gx is top minus
/// bottom, gy right minus left.
pub fn edge_kernels(operator: &str) -> Result<(Kernel, Kernel)> {
    match operator {
        "prewitt" => Ok((filter::prewitt_x(), filter::prewitt_y())),
        "sobel" => Ok((filter::sobel_x(), filter::sobel_y())),
        _ => Err(Error::input(
            "operator",
            format!("must be prewitt or sobel (got \"{}\")", short(operator)),
        )),
    }
}

/// Prewitt or Sobel on an 8-bit image by the fast separable path: `gx`,
/// `gy` exact integer sums, the magnitude `√(gx² + gy²)` in `f32` (the
/// reference's `hypot` rounded to `f32`, checked for every pair of sums),
/// the direction by `filter::fast::direction_deg` (within 1e-4°). On
/// [`Levels`] the same exact sums of `n` (below 2²⁴ for `max` under 2²¹),
/// `gx`, `gy` and `√(gx² + gy²)` divided by the scale in `f64`. `None`
/// when the image has neither or `border` leaves no pixel.
pub fn fast_edges(img: &Image, operator: &str, border: Border) -> Result<Option<Vec<Layer>>> {
    edge_kernels(operator)?;
    let sx: &[f32] = if operator == "sobel" {
        &[1.0, 2.0, 1.0]
    } else {
        &[1.0, 1.0, 1.0]
    };
    let Some(src) = Source::of(img) else {
        return Ok(None);
    };
    let scale = src.scale();
    if src.max() * 8.0 >= 16_777_216.0 {
        return Ok(None);
    }
    let (w, h) = src.size();
    let Some(region) = filter::output_region(w, h, 1, 1, border) else {
        return Ok(None);
    };
    let mut gx = vec![0.0f32; w * h];
    let mut gy = vec![0.0f32; w * h];
    src.separable(sx, &[1.0, 0.0, -1.0], 1.0, border, &mut gx)?;
    src.separable(&[-1.0, 0.0, 1.0], sx, 1.0, border, &mut gy)?;
    // (the passes start their sums at +0: no −0 to turn)
    let mut gx = finish(gx, w, region, |v| v);
    let mut gy = finish(gy, w, region, |v| v);
    let mut dir = vec![0.0f32; gx.len()];
    // (the direction of the sums is the greys' direction: the scale cancels)
    fast::direction_deg(&gx, &gy, &mut dir);
    let mag = if matches!(src, Source::Bytes(_)) {
        gx.iter()
            .zip(&gy)
            .map(|(x, y)| (x * x + y * y).sqrt())
            .collect()
    } else {
        let mag = gx
            .iter()
            .zip(&gy)
            .map(|(&x, &y)| {
                let (x, y) = (f64::from(x), f64::from(y));
                ((x * x + y * y).sqrt() / scale) as f32
            })
            .collect();
        for v in gx.iter_mut().chain(gy.iter_mut()) {
            *v = (f64::from(*v) / scale) as f32;
        }
        mag
    };
    Ok(Some(vec![
        Layer::new("gx", region, gx, true),
        Layer::new("gy", region, gy, true),
        Layer::new("magnitude", region, mag, false),
        Layer::new("direction", region, dir, true),
    ]))
}

/// Prewitt or Sobel `gx`, `gy`, magnitude and direction (`atan2(gy, gx)`
/// in degrees) over the whole image: `filter::gradient`.
pub fn edges<'a>(img: impl Into<Image<'a>>, operator: &str, border: Border) -> Result<Vec<Layer>> {
    let img = img.into();
    if let Some(layers) = fast_edges(&img, operator, border)? {
        return Ok(layers);
    }
    let (kx, ky) = edge_kernels(operator)?;
    let g = filter::gradient(img.grid(), &kx, &ky, border)?;
    let dir = Grid::new(
        "direction",
        g.region.width,
        g.region.height,
        g.gx.data()
            .iter()
            .zip(g.gy.data())
            .map(|(x, y)| y.atan2(*x).to_degrees())
            .collect(),
    )?;
    Ok(vec![
        Layer::from_grid("gx", &g.gx, g.region, true),
        Layer::from_grid("gy", &g.gy, g.region, true),
        Layer::from_grid("magnitude", &g.magnitude, g.region, false),
        Layer::from_grid("direction", &dir, g.region, true),
    ])
}
