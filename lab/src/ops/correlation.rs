//! Template matching: NCC of a template over a search box, its best
//! whole-pixel position, the quadric's subpixel peak and least-squares
//! matching from there; and the fiducial marks measured that way.
//!
//! On 8-bit images the surface is the core's `correlation::fast::zncc`
//! (`f32`); the best position, the 3×3 ρ round it, the subpixel peak and
//! LSM use the reference's numbers (`correlation::ncc` of the windows at
//! the positions within 10⁻⁶ of the fast maximum, the first largest in
//! row-major order as `correlation::correlate_2d` picks it), so they are
//! the reference's exactly. A colour photo's levels (`ops::Levels`) take
//! the same route with exact integer sums ([`zncc_levels`]: `ρ` is
//! scale-free, so the levels serve as they are). Other images take
//! `correlation::correlate_2d`.

use super::*;
use photogrammetry_playground::correlation::{self, fast as cfast};
use photogrammetry_playground::matching::{self, Gradients, Matching, Model, Params, Settings};
use photogrammetry_playground::solution::fmt_sig;
use photogrammetry_playground::transform::{self, Fit, PointPair};

/// The NCC surface: `ρ` (`f32`, `NaN` where the template or the window is
/// flat) of each position, entry `(i, j)` the template's top-left at search
/// pixel `(search.c0 + i, search.r0 + j)`; the best position and its exact
/// `ρ`.
#[derive(Debug, Clone, PartialEq)]
pub struct NccSurface {
    pub width: usize,
    pub height: usize,
    pub rho: Vec<f32>,
    /// The first largest `ρ` in row-major order, as `correlate_2d` picks it.
    pub best: Option<(usize, usize)>,
    /// The reference's `ρ` there.
    pub best_rho: Option<f64>,
}

impl NccSurface {
    /// The surface's `ρ` at position `(i, j)` (`None` outside or flat).
    pub fn rho(&self, i: usize, j: usize) -> Option<f64> {
        if i >= self.width || j >= self.height {
            return None;
        }
        let v = *self.rho.get(j * self.width + i)?;
        (!v.is_nan()).then_some(f64::from(v))
    }
}

/// The reference's `ρ` of `t` with the window of `s` at position `(i, j)`.
fn exact_rho(t: &Grid, s: &Grid, i: usize, j: usize) -> Option<f64> {
    let win = s.window(i, j, t.width(), t.height())?;
    correlation::ncc(t.data(), win.data()).ok()?.rho
}

/// The fast path's input: both boxes as bytes (8-bit images), or as a
/// colour photo's levels (whole numbers; `ρ` is scale-free, so the levels
/// serve as they are).
enum Boxes {
    Bytes(Vec<u8>, Vec<u8>),
    Levels(Vec<i64>, Vec<i64>),
}

/// The surface of `t` over `s`: the fast path on bytes or levels, the
/// exact best.
fn surface(t: &Grid, s: &Grid, boxes: Option<Boxes>) -> Result<NccSurface> {
    let (tw, th, sw, sh) = (t.width(), t.height(), s.width(), s.height());
    let fits = tw <= sw
        && th <= sh
        && tw * th <= cfast::MAX_TEMPLATE_PIXELS
        && (sw - tw + 1) * (sh - th + 1) * tw * th <= correlation::MAX_PRODUCTS_2D;
    let (ow, oh) = (sw.saturating_sub(tw) + 1, sh.saturating_sub(th) + 1);
    let mut rho = vec![0.0f32; if fits { ow * oh } else { 0 }];
    let peak = match boxes.filter(|_| fits) {
        Some(Boxes::Bytes(tb, sb)) => Some(cfast::zncc(
            Gray::new("search", &sb, sw, sh)?,
            Gray::new("template", &tb, tw, th)?,
            &mut rho,
        )?),
        Some(Boxes::Levels(tl, sl)) => zncc_levels(&tl, (tw, th), &sl, (sw, sh), &mut rho),
        None => None,
    };
    let Some(peak) = peak else {
        let r = correlation::correlate_2d(t, s)?;
        let rho = r
            .windows
            .iter()
            .map(|w| w.rho.map_or(f32::NAN, |v| v as f32))
            .collect();
        let best_rho = r.best.and_then(|(i, j)| r.rho(i, j));
        return Ok(NccSurface {
            width: r.width,
            height: r.height,
            rho,
            best: r.best,
            best_rho,
        });
    };
    // the fast ρ is within 10⁻⁷ of the reference's: the reference's best
    // is among the positions within 10⁻⁶ of the fast maximum
    let mut best: Option<((usize, usize), f64)> = None;
    if let Some(p) = peak {
        let floor = p.rho - 1e-6;
        for (k, &v) in rho.iter().enumerate() {
            if v >= floor {
                let (i, j) = (k % ow, k / ow);
                if let Some(x) = exact_rho(t, s, i, j) {
                    if best.is_none_or(|(_, b)| x > b) {
                        best = Some(((i, j), x));
                    }
                }
            }
        }
    }
    Ok(NccSurface {
        width: ow,
        height: oh,
        rho,
        best: best.map(|b| b.0),
        best_rho: best.map(|b| b.1),
    })
}

/// `ρ` of a template of levels `t` (`tw × th`) at every position of the
/// search levels `s` (`sw × sh`), into `out` (`(sw − tw + 1) × (sh − th + 1)`,
/// `NaN` where the template or the window is flat), as
/// `correlation::fast::zncc` does on bytes: `ΣI`, `ΣI²` of each window
/// from sum tables, the cross sums `ΣI·T` direct, all exact `i64`
/// integers, `n·ΣIT − ΣI·ΣT` and the variances exact in `i128`, then one
/// `f64` quotient (within a few units of 10⁻¹⁶ of the exact `ρ`; the
/// reference's, from deviations of the divided greys, is within its own
/// roundings of it). The first largest `ρ` in row-major order, or
/// `Some(None)` when every window is flat; `None` (take the reference)
/// when the sums could leave `i64` (`max² · pixels ≥ 2⁶²`).
fn zncc_levels(
    t: &[i64],
    (tw, th): (usize, usize),
    s: &[i64],
    (sw, sh): (usize, usize),
    out: &mut [f32],
) -> Option<Option<cfast::Peak>> {
    let (ow, oh) = ((sw + 1).checked_sub(tw)?, (sh + 1).checked_sub(th)?);
    if t.len() != tw * th || s.len() != sw * sh || out.len() != ow * oh || tw == 0 || th == 0 {
        return None;
    }
    let max = t.iter().chain(s).fold(0i64, |m, &v| m.max(v.abs())) as f64;
    if max * max * (sw * sh) as f64 >= 2f64.powi(62) {
        return None;
    }
    let stride = sw + 1;
    let mut s1 = vec![0i64; stride * (sh + 1)];
    let mut s2 = vec![0i64; stride * (sh + 1)];
    for (r, row) in s.chunks_exact(sw).enumerate() {
        let (mut a, mut b) = (0i64, 0i64);
        for (c, &v) in row.iter().enumerate() {
            a += v;
            b += v * v;
            let i = (r + 1) * stride + c + 1;
            s1[i] = s1[i - stride] + a;
            s2[i] = s2[i - stride] + b;
        }
    }
    let nn = (tw * th) as i128;
    let st: i64 = t.iter().sum();
    let st2: i64 = t.iter().map(|v| v * v).sum();
    let (st, st2) = (i128::from(st), i128::from(st2));
    let dt = (nn * st2 - st * st) as f64;
    let mut best: Option<cfast::Peak> = None;
    for (r, o) in out.chunks_exact_mut(ow).enumerate() {
        for (c, ov) in o.iter_mut().enumerate() {
            let mut sit = 0i64;
            for (j, trow) in t.chunks_exact(tw).enumerate() {
                let k = (r + j) * sw + c;
                sit += trow
                    .iter()
                    .zip(&s[k..k + tw])
                    .map(|(a, b)| a * b)
                    .sum::<i64>();
            }
            let rect = |q: &[i64]| {
                i128::from(
                    q[(r + th) * stride + c + tw]
                        - q[r * stride + c + tw]
                        - q[(r + th) * stride + c]
                        + q[r * stride + c],
                )
            };
            let (si, si2) = (rect(&s1), rect(&s2));
            let di = (nn * si2 - si * si) as f64;
            let num = (nn * i128::from(sit) - si * st) as f64;
            *ov = if di > 0.0 && dt > 0.0 {
                let rho = (num / (di * dt).sqrt()).clamp(-1.0, 1.0) as f32;
                if best.is_none_or(|b| rho > b.rho) {
                    best = Some(cfast::Peak { c, r, rho });
                }
                rho
            } else {
                f32::NAN
            };
        }
    }
    Some(best)
}

/// The levels of a box of a colour photo (`None` for an 8-bit image).
fn box_levels(img: &Image, r: Rect) -> Option<Vec<i64>> {
    let l = img.levels()?;
    let w = img.width();
    let mut out = Vec::with_capacity(r.width * r.height);
    for row in r.r0..r.r0 + r.height {
        let k = row * w + r.c0;
        out.extend(l.data.get(k..k + r.width)?.iter().map(|&n| n as i64));
    }
    Some(out)
}

/// The bytes of a box of an 8-bit image.
fn box_bytes(img: &Image, r: Rect) -> Option<Vec<u8>> {
    let g = img.gray()?;
    let mut out = Vec::with_capacity(r.width * r.height);
    for row in r.r0..r.r0 + r.height {
        out.extend_from_slice(g.row(row)?.get(r.c0..r.c0 + r.width)?);
    }
    Some(out)
}

/// What template matching found.
#[derive(Debug, Clone, PartialEq)]
pub struct Correlation {
    /// The NCC surface.
    pub surface: NccSurface,
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
pub fn correlate<'a, 'b>(
    a: impl Into<Image<'a>>,
    template: Rect,
    b: impl Into<Image<'b>>,
    search: Rect,
    model: Model,
) -> Result<Correlation> {
    let (a, b) = (a.into(), b.into());
    if template.width.is_multiple_of(2) || template.height.is_multiple_of(2) || template.width < 3 {
        return Err(Error::input(
            "template",
            "must be an odd number of pixels across and down (at least 3), so that it has a centre",
        ));
    }
    let t = cut(a.grid(), "template", template)?;
    let s = cut(b.grid(), "search", search)?;
    let boxes = match (box_bytes(&a, template), box_bytes(&b, search)) {
        (Some(tb), Some(sb)) => Some(Boxes::Bytes(tb, sb)),
        _ => box_levels(&a, template)
            .zip(box_levels(&b, search))
            .map(|(tl, sl)| Boxes::Levels(tl, sl)),
    };
    let surface = surface(&t, &s, boxes)?;
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
                    match exact_rho(&t, &s, i + di - 1, j + dj - 1) {
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
            let win = cut(b.grid(), "search", lsm_window)?;
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
        if let Some(rho) = s.best_rho.filter(|r| *r < DOUBT_RHO) {
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
pub fn measure_marks<'a>(
    img: impl Into<Image<'a>>,
    template: &Grid,
    approx: &[(f64, f64)],
    reach: usize,
) -> Result<Vec<Mark>> {
    let img = img.into();
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
            let m = correlate(&a, whole_t, &img, search, Model::ShiftRadiometric)
                .map_err(|e| Error::input(&field, e.to_string()))?;
            let best = m
                .best
                .ok_or_else(|| Error::input(&field, "no match found (the search box is flat)"))?;
            let ncc = m.surface.best_rho.unwrap_or(0.0);
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
