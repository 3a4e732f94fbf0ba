//! The lab's operator menu: names and parameters in, the core's whole-image
//! functions called, layers out. Nothing is computed here that the core does
//! not compute for the worked examples (DESIGN.md's first rule): this file
//! only picks kernels, cuts windows and collects results.

use photogrammetry_playground::chain::{self, Connectivity};
use photogrammetry_playground::correlation::{self, Surface};
use photogrammetry_playground::error::{Error, Result};
use photogrammetry_playground::filter::{self, Kernel, Region};
use photogrammetry_playground::interest::{self, Measures};
use photogrammetry_playground::matching::{self, Gradients, Matching, Model, Params, Settings};
use photogrammetry_playground::raster::{Border, Gray, Grid};
use photogrammetry_playground::read::short;
use photogrammetry_playground::resample::{self, Method};
use photogrammetry_playground::solution::fmt_sig;
use photogrammetry_playground::transform::{self, Fit, PointPair};

mod custom;
mod forstner;
pub use custom::*;
pub use forstner::*;

/// One result image: `width × height` values whose pixel `(0, 0)` sits on
/// input pixel `(c0, r0)`; `NaN` where there is no value.
#[derive(Debug, Clone, PartialEq)]
pub struct Layer {
    pub name: String,
    pub width: usize,
    pub height: usize,
    pub c0: usize,
    pub r0: usize,
    pub data: Vec<f64>,
    /// Signed values (drawn with the diverging colour scale).
    pub signed: bool,
}

impl Layer {
    fn from_grid(name: &str, g: &Grid, region: Region, signed: bool) -> Self {
        Layer {
            name: name.to_string(),
            width: g.width(),
            height: g.height(),
            c0: region.c0,
            r0: region.r0,
            data: g.data().to_vec(),
            signed,
        }
    }
    /// The value at input pixel `(c, r)`, if the layer covers it.
    pub fn at(&self, c: usize, r: usize) -> Option<f64> {
        if c < self.c0 || r < self.r0 || c >= self.c0 + self.width || r >= self.r0 + self.height {
            return None;
        }
        let v = self.data[(r - self.r0) * self.width + (c - self.c0)];
        (!v.is_nan()).then_some(v)
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

/// A filter over the whole image: `filter::correlate` with the named
/// kernel, or `filter::median` 3×3.
pub fn filter_image(
    img: &Grid,
    kernel_name: &str,
    border: Border,
    custom: Option<(&[Vec<f64>], f64)>,
) -> Result<Layer> {
    if let Some(layer) = fast_filter(img, kernel_name, border)? {
        return Ok(layer);
    }
    let f = match kernel(kernel_name, custom)? {
        Some(k) => filter::correlate(img, &k, border)?,
        None => filter::median(img, 3, 3, border)?,
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

/// The 8-bit bytes of `img` and the output region `border` leaves for a
/// `(2·hx+1) × (2·hy+1)` window, when the fast paths apply.
fn fast_input(img: &Grid, hx: usize, hy: usize, border: Border) -> Option<(Vec<u8>, Region)> {
    let bytes = img.to_u8()?;
    let region = filter::output_region(img.width(), img.height(), hx, hy, border)?;
    Some((bytes, region))
}

/// The part of a full-size fast output that `region` covers, as `f64`
/// through `f`.
fn cut_region<T: Copy>(full: &[T], w: usize, region: Region, f: impl Fn(T) -> f64) -> Vec<f64> {
    (region.r0..region.r0 + region.height)
        .flat_map(|r| {
            let start = r * w + region.c0;
            full.get(start..start + region.width)
                .unwrap_or(&[])
                .iter()
                .map(|&v| f(v))
                .collect::<Vec<f64>>()
        })
        .collect()
}

fn region_layer(name: &str, region: Region, data: Vec<f64>, signed: bool) -> Layer {
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

/// An integer-kernel response by `filter::fast::separable` with divisor 1:
/// every partial sum is an integer below 2²⁴, so the `f32` sums are exact,
/// and dividing them in `f64` gives the bits of the reference's
/// `Σ n·f / divisor` (`+ 0.0` turns a `−0` sum into the reference's `0`).
fn integer_response(
    g: Gray,
    kx: &[f32],
    ky: &[f32],
    divisor: f64,
    border: Border,
    region: Region,
) -> Result<Vec<f64>> {
    let w = g.width();
    let mut out = vec![0.0f32; w * g.height()];
    filter::fast::separable(g, kx, ky, 1.0, border, &mut out)?;
    Ok(cut_region(&out, w, region, |v| {
        (f64::from(v) + 0.0) / divisor
    }))
}

/// The menu's filters on an 8-bit image by the core's fast paths, with the
/// worked example's exact numbers (so "explain this pixel" shows the same
/// value the example computes): the 3×3 median by `filter::fast::median3`
/// (integers), the separable integer kernels ([`separable_taps`]) by
/// [`integer_response`]. `None` for other kernels and other images, which
/// take the reference path. Tied to `filter::correlate` / `filter::median`
/// bit for bit at every pixel by lab/tests/operators.rs.
pub fn fast_filter(img: &Grid, kernel_name: &str, border: Border) -> Result<Option<Layer>> {
    let taps = separable_taps(kernel_name);
    let half = match (kernel_name, taps) {
        ("median", _) => 1,
        (_, Some((kx, _, _))) => kx.len() / 2,
        _ => return Ok(None),
    };
    let (w, h) = (img.width(), img.height());
    let Some((bytes, region)) = fast_input(img, half, half, border) else {
        return Ok(None);
    };
    let g = Gray::new("image", &bytes, w, h)?;
    let data = match taps {
        Some((kx, ky, divisor)) => integer_response(g, kx, ky, divisor, border, region)?,
        None => {
            let mut out = vec![0u8; w * h];
            filter::fast::median3(g, border, &mut out)?;
            cut_region(&out, w, region, f64::from)
        }
    };
    Ok(Some(region_layer(kernel_name, region, data, false)))
}

/// Prewitt or Sobel on an 8-bit image by the fast separable path:
/// `gx`, `gy` exact integer sums (see [`integer_response`]), magnitude and
/// direction from them in `f64` as [`edges`] computes them. `None` when
/// the image is not 8-bit or `border` leaves no pixel.
pub fn fast_edges(img: &Grid, operator: &str, border: Border) -> Result<Option<Vec<Layer>>> {
    // gx: top minus bottom (ky = [1 0 −1]); gy: right minus left (kx = [−1 0 1])
    let (sx, sy): (&[f32], &[f32]) = match operator {
        "prewitt" => (&[1.0, 1.0, 1.0], &[1.0, 1.0, 1.0]),
        "sobel" => (&[1.0, 2.0, 1.0], &[1.0, 2.0, 1.0]),
        _ => return Ok(None),
    };
    let (w, h) = (img.width(), img.height());
    let Some((bytes, region)) = fast_input(img, 1, 1, border) else {
        return Ok(None);
    };
    let g = Gray::new("image", &bytes, w, h)?;
    let gx = integer_response(g, sx, &[1.0, 0.0, -1.0], 1.0, border, region)?;
    let gy = integer_response(g, &[-1.0, 0.0, 1.0], sy, 1.0, border, region)?;
    let mag = gx.iter().zip(&gy).map(|(x, y)| x.hypot(*y)).collect();
    let dir = gx
        .iter()
        .zip(&gy)
        .map(|(x, y)| y.atan2(*x).to_degrees())
        .collect();
    Ok(Some(vec![
        region_layer("gx", region, gx, true),
        region_layer("gy", region, gy, true),
        region_layer("magnitude", region, mag, false),
        region_layer("direction", region, dir, true),
    ]))
}

/// Prewitt or Sobel `gx`, `gy`, magnitude and direction (`atan2(gy, gx)`
/// in degrees) over the whole image: `filter::gradient`.
pub fn edges(img: &Grid, operator: &str, border: Border) -> Result<Vec<Layer>> {
    if let Some(layers) = fast_edges(img, operator, border)? {
        return Ok(layers);
    }
    let (kx, ky) = match operator {
        "prewitt" => (filter::prewitt_x(), filter::prewitt_y()),
        "sobel" => (filter::sobel_x(), filter::sobel_y()),
        _ => {
            return Err(Error::input(
                "operator",
                format!("must be prewitt or sobel (got \"{}\")", short(operator)),
            ))
        }
    };
    let g = filter::gradient(img, &kx, &ky, border)?;
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

fn map_layer<T: Copy>(name: &str, map: &interest::Map<T>, f: impl Fn(T) -> Option<f64>) -> Layer {
    Layer {
        name: name.to_string(),
        width: map.width,
        height: map.height,
        c0: 0,
        r0: 0,
        data: map
            .cells
            .iter()
            .map(|m| m.and_then(&f).unwrap_or(f64::NAN))
            .collect(),
        signed: false,
    }
}

/// The Moravec map (`interest::moravec_map`) and its points above
/// `threshold` after suppression (`interest::moravec_points`).
pub fn moravec(img: &Grid, size: usize, threshold: f64) -> Result<(Layer, Vec<Point>)> {
    if !threshold.is_finite() {
        return Err(Error::input("threshold", "must be a finite number"));
    }
    let map = interest::moravec_map(img, size)?;
    let det = interest::moravec_points(&map, threshold);
    let points = det
        .points
        .iter()
        .map(|p| Point {
            c: p.c,
            r: p.r,
            score: p.score,
            major: 0.0,
            minor: 0.0,
            angle: 0.0,
        })
        .collect();
    Ok((map_layer("moravec", &map, Some), points))
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

/// What template matching found.
#[derive(Debug, Clone, PartialEq)]
pub struct Correlation {
    /// The NCC surface: entry `(i, j)` is the template's top-left at search
    /// pixel `(search.c0 + i, search.r0 + j)`.
    pub surface: Surface,
    pub template: Grid,
    pub search: Rect,
    /// Template centre at the best whole-pixel position (image pixels).
    pub best: Option<(usize, usize)>,
    /// The 3×3 ρ around the best position (rows r−1 … r+1) when it is not
    /// on the surface's edge, and the quadric's subpixel centre (image px).
    pub around: Option<[[f64; 3]; 3]>,
    pub subpixel: Option<(f64, f64)>,
    /// Least-squares matching from the subpixel (or best) position, in the
    /// window `lsm_window` of the search image.
    pub lsm: Option<Matching>,
    pub lsm_window: Rect,
}

/// NCC of the `template` box of `a` over the `search` box of `b`
/// (`correlation::correlate_2d`), the best match, the 3×3 quadric subpixel
/// peak (`correlation::quadric_peak`), then least-squares matching
/// (`matching::match_2d`) with `model` from there.
pub fn correlate(
    a: &Grid,
    template: Rect,
    b: &Grid,
    search: Rect,
    model: Model,
) -> Result<Correlation> {
    if template.width.is_multiple_of(2) || template.height.is_multiple_of(2) || template.width < 3 {
        return Err(Error::input(
            "template",
            "must be an odd number of pixels across and down (at least 3), so that it has a centre",
        ));
    }
    let t = cut(a, "template", template)?;
    let s = cut(b, "search", search)?;
    let surface = correlation::correlate_2d(&t, &s)?;
    let (hw, hh) = (template.width / 2, template.height / 2);
    let best = surface
        .best
        .map(|(i, j)| (search.c0 + i + hw, search.r0 + j + hh));
    let mut around = None;
    let mut subpixel = None;
    if let Some((i, j)) = surface.best {
        if i >= 1 && j >= 1 && i + 1 < surface.width && j + 1 < surface.height {
            let mut rho = [[0.0; 3]; 3];
            let mut ok = true;
            for (dj, row) in rho.iter_mut().enumerate() {
                for (di, v) in row.iter_mut().enumerate() {
                    match surface.rho(i + di - 1, j + dj - 1) {
                        Some(x) => *v = x,
                        None => ok = false,
                    }
                }
            }
            if ok {
                let (bc, br) = best.map_or((0.0, 0.0), |(c, r)| (c as f64, r as f64));
                let cs = [bc - 1.0, bc, bc + 1.0];
                let rs = [br - 1.0, br, br + 1.0];
                around = Some(rho);
                let peak = correlation::quadric_peak(cs, rs, rho)
                    .ok()
                    .and_then(|q| q.extremum.maximum());
                if let Some([qc, qr]) = peak {
                    // a peak more than a pixel away is no refinement
                    if (qc - bc).abs() <= 1.0 && (qr - br).abs() <= 1.0 {
                        subpixel = Some((qc, qr));
                    }
                }
            }
        }
    }
    // LSM in a window of the search image round the match, a margin of
    // half a template on each side
    let start = subpixel.or(best.map(|(c, r)| (c as f64, r as f64)));
    let mut lsm_window = Rect {
        c0: 0,
        r0: 0,
        width: 0,
        height: 0,
    };
    let lsm = match start {
        Some((c, r)) => {
            let (mc, mr) = (template.width, template.height);
            let c0 = (c.round() as usize).saturating_sub(mc);
            let r0 = (r.round() as usize).saturating_sub(mr);
            lsm_window = Rect {
                c0,
                r0,
                width: (2 * mc + 1).min(b.width() - c0),
                height: (2 * mr + 1).min(b.height() - r0),
            };
            let win = cut(b, "search", lsm_window)?;
            let settings = Settings {
                model,
                gradients: Gradients::SearchWindow,
                max_iterations: matching::DEFAULT_ITERATIONS,
            };
            let p = Params::shift(c - c0 as f64, r - r0 as f64, 1.0, 0.0);
            matching::match_2d(&t, &win, p, settings).ok()
        }
        None => None,
    };
    Ok(Correlation {
        surface,
        template: t,
        search,
        best,
        around,
        subpixel,
        lsm,
        lsm_window,
    })
}

/// Below this ρ a best match is called doubtful: the window found looks
/// little like the template (a ρ of 0.7 leaves half of the template's
/// variance, 1 − ρ², unexplained).
pub const DOUBT_RHO: f64 = 0.7;

/// A least-squares gain outside `1/DOUBT_GAIN … DOUBT_GAIN` is called
/// doubtful: the contrast had to change by more than half to fit, which two
/// photos of one scene seldom need; LSM has likely fitted another feature.
pub const DOUBT_GAIN: f64 = 1.5;

/// Why a match is doubtful, one sentence per reason (none: nothing to say):
/// the best whole-pixel position on the edge of the search box (ρ may rise
/// further outside it), a best ρ below [`DOUBT_RHO`], an LSM gain outside
/// `1/DOUBT_GAIN … DOUBT_GAIN`. LSM's own "converged" says only that the
/// updates became small, not that the match is right.
pub fn doubts(m: &Correlation) -> Vec<String> {
    let mut out = Vec::new();
    let s = &m.surface;
    if let Some((i, j)) = s.best {
        let mut sides = Vec::new();
        if i == 0 {
            sides.push("left");
        }
        if i + 1 == s.width {
            sides.push("right");
        }
        if j == 0 {
            sides.push("top");
        }
        if j + 1 == s.height {
            sides.push("bottom");
        }
        if !sides.is_empty() {
            out.push(format!(
                "the best position is on the {} edge of the search area, so ρ may rise further outside it: search further (a larger ±)",
                sides.join(" and ")
            ));
        }
        if let Some(rho) = s.rho(i, j).filter(|r| *r < DOUBT_RHO) {
            out.push(format!(
                "the best ρ = {} is below {DOUBT_RHO}: the window found looks little like the template",
                fmt_sig(rho, 3)
            ));
        }
    }
    if let Some(l) = &m.lsm {
        let gain = l.params.a[6];
        if !(1.0 / DOUBT_GAIN..=DOUBT_GAIN).contains(&gain) {
            out.push(format!(
                "LSM's gain {} is outside {} … {DOUBT_GAIN} (far from 1): it changed the contrast a lot to fit, likely to another feature",
                fmt_sig(gain, 3),
                fmt_sig(1.0 / DOUBT_GAIN, 3)
            ));
        }
    }
    out
}

/// Resampling by a transformation of output pixel → input position
/// (`resample::warp`), one layer per method.
pub fn warp(
    img: &Grid,
    width: usize,
    height: usize,
    map: &dyn Fn(f64, f64) -> (f64, f64),
    methods: &[Method],
) -> Vec<Grid> {
    methods
        .iter()
        .map(|&m| resample::warp(img, width, height, map, m, 0.0))
        .collect()
}

/// Rotation by `angle_deg` (clockwise on the screen) and scaling by
/// `scale` about the image centre: the output → input map.
pub fn rotate_scale(
    img: &Grid,
    angle_deg: f64,
    scale: f64,
) -> Result<impl Fn(f64, f64) -> (f64, f64)> {
    if !(scale.is_finite() && scale > 0.0 && angle_deg.is_finite()) {
        return Err(Error::input("scale", "must be a number greater than 0"));
    }
    let (mc, mr) = (
        (img.width() as f64 - 1.0) / 2.0,
        (img.height() as f64 - 1.0) / 2.0,
    );
    let (s, c) = angle_deg.to_radians().sin_cos();
    Ok(move |x: f64, y: f64| {
        let (dx, dy) = (x - mc, y - mr);
        // inverse of "rotate by θ then scale": rotate by −θ, divide by s
        (
            (c * dx + s * dy) / scale + mc,
            (-s * dx + c * dy) / scale + mr,
        )
    })
}

/// The projective rectification of four clicked points onto a rectangle
/// `width × height`: the 004 table's projective model fitted through
/// `transform::fit` from output corners to the clicked input positions.
pub fn projective(
    clicked: &[(f64, f64)],
    width: usize,
    height: usize,
) -> Result<transform::Transform> {
    if clicked.len() != 4 {
        return Err(Error::input(
            "points",
            format!("needs 4 clicked points, got {}", clicked.len()),
        ));
    }
    let (w, h) = (width as f64 - 1.0, height as f64 - 1.0);
    let corners = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)];
    let pairs: Vec<PointPair> = corners
        .iter()
        .zip(clicked)
        .map(|(&(u, v), &(x, y))| PointPair { u, v, x, y })
        .collect();
    Ok(transform::fit(transform::Model::Projective, &pairs)
        .map_err(|e| e.in_field("points"))?
        .transform)
}

/// A traced region: threshold, the region at the picked pixel
/// (`chain::region_at`), its outer boundary (`chain::trace`) with chain code,
/// length and shape (`chain::length`, `chain::shape`).
#[derive(Debug, Clone, PartialEq)]
pub struct Traced {
    pub mask: Grid,
    pub boundary: chain::Boundary,
    pub length: chain::Length,
    pub shape: Option<chain::Shape>,
}

/// Longest boundary (pixels) whose shape descriptors are computed:
/// `chain::shape`'s diameter compares every pair of boundary pixels.
pub const MAX_SHAPE_PIXELS: usize = 4000;

/// Traces the region of `img` containing `(c, r)` after thresholding.
pub fn boundary(img: &Grid, threshold: f64, c: usize, r: usize) -> Result<Traced> {
    if !threshold.is_finite() {
        return Err(Error::input("threshold", "must be a finite number"));
    }
    let conn = Connectivity::Eight;
    let mask = chain::region_at(img, threshold, c, r, conn).ok_or_else(|| {
        Error::input(
            "pixel",
            format!(
                "({c}, {r}) is outside the {}×{} image",
                img.width(),
                img.height()
            ),
        )
    })?;
    let boundary = chain::trace(&mask, conn)
        .into_iter()
        .next()
        .ok_or_else(|| Error::Internal("a picked region has no boundary".into()))?;
    let length = chain::length(&boundary.code, conn);
    // the diameter compares every pair of boundary pixels: skipped for
    // long boundaries
    let shape = (boundary.pixels.len() <= MAX_SHAPE_PIXELS)
        .then(|| chain::shape("boundary", &boundary.pixels).ok())
        .flatten();
    Ok(Traced {
        mask,
        boundary,
        length,
        shape,
    })
}

/// One fiducial measured: template matching + LSM round `approx`.
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    pub approx: (f64, f64),
    pub measured: (f64, f64),
    pub ncc: f64,
    pub iterations: usize,
}

/// Measures each fiducial near its approximate position: NCC of `template`
/// over a box of `±reach` pixels, subpixel peak, LSM (shift + radiometric).
pub fn measure_marks(
    img: &Grid,
    template: &Grid,
    approx: &[(f64, f64)],
    reach: usize,
) -> Result<Vec<Mark>> {
    let (tw, th) = (template.width(), template.height());
    let a = Grid::new("template", tw, th, template.data().to_vec())?;
    let whole_t = Rect {
        c0: 0,
        r0: 0,
        width: tw,
        height: th,
    };
    approx
        .iter()
        .enumerate()
        .map(|(k, &(c, r))| {
            let field = format!("mark {}", k + 1);
            let side = 2 * reach + tw;
            let c0 = (c.round() as i64 - (reach + tw / 2) as i64).max(0) as usize;
            let r0 = (r.round() as i64 - (reach + th / 2) as i64).max(0) as usize;
            let search = Rect {
                c0,
                r0,
                width: side.min(img.width().saturating_sub(c0)),
                height: side.min(img.height().saturating_sub(r0)),
            };
            let m = correlate(&a, whole_t, img, search, Model::ShiftRadiometric)
                .map_err(|e| Error::input(&field, e.to_string()))?;
            let best = m
                .best
                .ok_or_else(|| Error::input(&field, "no match found (the search box is flat)"))?;
            let ncc = m
                .surface
                .rho(best.0 - c0 - tw / 2, best.1 - r0 - th / 2)
                .unwrap_or(0.0);
            let (measured, iterations) = match &m.lsm {
                Some(l) if l.status == matching::Status::Converged => (
                    (
                        l.params.a[2] + m.lsm_window.c0 as f64,
                        l.params.a[5] + m.lsm_window.r0 as f64,
                    ),
                    l.iterations.len(),
                ),
                _ => (m.subpixel.unwrap_or((best.0 as f64, best.1 as f64)), 0),
            };
            Ok(Mark {
                approx: (c, r),
                measured,
                ncc,
                iterations,
            })
        })
        .collect()
}

/// Example 4's similarity and affine fits of measured marks `(c, r)` to the
/// calibrated `(x, y)` (mm), with `x′ = c`, `y′ = −r`.
pub fn fit_fiducials(measured: &[(f64, f64)], calibrated: &[[f64; 2]]) -> Result<(Fit, Fit)> {
    let pairs: Vec<PointPair> = measured
        .iter()
        .zip(calibrated)
        .map(|(&(c, r), &[x, y])| PointPair { u: c, v: -r, x, y })
        .collect();
    Ok((
        transform::fit(transform::Model::Similarity, &pairs)?,
        transform::fit(transform::Model::FiducialAffine, &pairs)?,
    ))
}
