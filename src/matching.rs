//! Least-squares matching (LSM) in 1-D and 2-D: the template `T` is matched
//! into the search window `S` by adjusting geometric and radiometric
//! parameters until the resampled search patch fits the template best in the
//! least-squares sense.
//!
//! The observation equation for template pixel `(u, v)` (its offset from the
//! template centre, so `u` to the right and `v` down) is
//!
//! ```text
//! T(u, v) + V = a7 · S(p, q) + a8,   p = a1·u + a2·v + a3,   q = a4·u + a5·v + a6
//! ```
//!
//! with `(p, q)` the zero-based column and row in the search window. The
//! [`Model`] decides which of the eight parameters are estimated: the shift
//! `(a3, a6)` only, the shift with linear radiometry (gain `a7`, offset `a8`,
//! seed 000's `a` and `b`), or all eight (seed 003's affine + radiometric
//! generalisation). In 1-D, `v = 0` and `q` stays on the one row.
//!
//! Every iteration
//! 1. resamples the search patch *and its one-pixel border* at the current
//!    parameters by bilinear interpolation ([`crate::resample::bilinear`]),
//! 2. takes central-difference gradients `(g(+1) − g(−1)) / 2` on that
//!    resampled grid ([`Gradients::SearchWindow`]) — or, as seed 000's printed
//!    Example 11 matrix does, inside the patch only with each edge pixel
//!    standing in for its missing neighbour ([`Gradients::PatchEdge`]) — and
//!    turns them into gradients along the search window's axes (the inverse
//!    transpose of the affine part; the identity for the shift models),
//! 3. builds `dL = T − (a7·S + a8)` and the design matrix `A` of the
//!    linearised equation and solves `dL + V = A·dX` with [`crate::lsq`],
//! 4. adds the increments to the parameters.
//!
//! How a run ends — there is no silent result, [`Status`] is always set:
//! - **converged** when an iteration's increments move no patch pixel by more
//!   than [`POSITION_TOL`] px and change no modelled grey value
//!   `a7·S + a8` by more than [`GREY_TOL`];
//! - **not converged** when the iteration limit is reached first (the last
//!   iteration's increments are in its record);
//! - **left the window** when the parameters put a patch pixel outside the
//!   search window (bilinear interpolation needs the pixel's four
//!   neighbours). The one-pixel *border* may reach up to one pixel past the
//!   window's edge: such border samples take the value at the nearest point of
//!   the window (the replicate policy of [`crate::raster::Border`]) and are
//!   counted in [`Iteration::clamped`];
//! - **degenerate** when the system cannot determine the parameters: a flat
//!   patch has no gradients, a gain driven to zero removes the geometric
//!   columns, an affine part that folds the patch flat has no inverse.
//!
//! A start outside the pull-in range has no status of its own: the matching
//! cannot know the truth. It shows as one of the above — most often *left
//! the window* or *not converged* — or as *converged* at another optimum,
//! which only a caller that knows the truth can tell (the affine LSM
//! example warns when estimates lie more than five standard deviations from
//! its generated truth).

use crate::error::{Error, Result};
use crate::lsq::{self, Adjustment};
use crate::raster::Grid;
use crate::resample;
use crate::rng::Rng;

/// Convergence: largest movement of a patch pixel by one iteration's
/// increments (px).
pub const POSITION_TOL: f64 = 1e-4;
/// Convergence: largest change of a modelled grey value `a7·S + a8` by one
/// iteration's radiometric increments (grey values).
pub const GREY_TOL: f64 = 1e-3;
/// The default iteration limit.
pub const DEFAULT_ITERATIONS: usize = 100;
/// The largest iteration limit accepted.
pub const MAX_ITERATIONS: usize = 200;
/// Smallest |det| of the affine part `[a1 a2; a4 a5]` before the patch counts
/// as folded flat.
const MIN_DET: f64 = 1e-6;
/// Slack for "inside the window" against rounding of the positions.
const EDGE_SLACK: f64 = 1e-9;

/// Which parameters are estimated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Model {
    /// The shift only: `a3` (1-D) or `a3, a6` (2-D).
    Shift,
    /// The shift with gain `a7` and offset `a8`.
    ShiftRadiometric,
    /// All eight: the affine `a1 … a6` and the radiometric `a7, a8` (in 1-D
    /// the scale `a1`, the shift `a3`, `a7` and `a8`).
    AffineRadiometric,
}

/// How the gradients of the resampled patch are taken.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Gradients {
    /// Central differences with the resampled one-pixel border: the
    /// neighbours outside the patch come from the search window (the formula
    /// the seeds state).
    SearchWindow,
    /// Central differences inside the patch only; an edge pixel stands in for
    /// its missing outside neighbour (what seed 000's printed Example 11
    /// matrix did).
    PatchEdge,
}

/// One of the eight parameters, in seed 003's numbering.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Param {
    A1,
    A2,
    A3,
    A4,
    A5,
    A6,
    /// Gain `a7` (seed 000's `a`).
    Gain,
    /// Offset `a8` (seed 000's `b`).
    Offset,
}

impl Param {
    /// Index into [`Params::a`].
    pub fn index(self) -> usize {
        match self {
            Param::A1 => 0,
            Param::A2 => 1,
            Param::A3 => 2,
            Param::A4 => 3,
            Param::A5 => 4,
            Param::A6 => 5,
            Param::Gain => 6,
            Param::Offset => 7,
        }
    }
}

/// The eight parameters `a1 … a8` (zero-based search-window positions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params {
    pub a: [f64; 8],
}

impl Params {
    /// A pure shift: the template centre at column `c`, row `r` of the search
    /// window (zero-based), with gain and offset.
    pub fn shift(c: f64, r: f64, gain: f64, offset: f64) -> Self {
        Params {
            a: [1.0, 0.0, c, 0.0, 1.0, r, gain, offset],
        }
    }
    /// The search-window position of template offset `(u, v)`.
    pub fn map(&self, u: f64, v: f64) -> (f64, f64) {
        let a = &self.a;
        (a[0] * u + a[1] * v + a[2], a[3] * u + a[4] * v + a[5])
    }
    pub fn gain(&self) -> f64 {
        self.a[6]
    }
    pub fn offset(&self) -> f64 {
        self.a[7]
    }
    /// Determinant of the affine part.
    pub fn det(&self) -> f64 {
        self.a[0] * self.a[4] - self.a[1] * self.a[3]
    }
}

/// What the run is asked to do.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    pub model: Model,
    pub gradients: Gradients,
    /// Iteration limit, 1 ..= [`MAX_ITERATIONS`].
    pub max_iterations: usize,
}

/// How a run ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Status {
    /// The increments fell below [`POSITION_TOL`] and [`GREY_TOL`].
    Converged,
    /// The iteration limit was reached; the last record holds the last
    /// increments.
    NotConverged,
    /// The updated parameters put a patch pixel outside the search window.
    LeftWindow { detail: String },
    /// The parameters cannot be determined (flat patch, singular system).
    Degenerate { reason: String },
}

impl Status {
    /// A short machine word: `converged`, `not-converged`, `left-window`,
    /// `degenerate`.
    pub fn word(&self) -> &'static str {
        match self {
            Status::Converged => "converged",
            Status::NotConverged => "not-converged",
            Status::LeftWindow { .. } => "left-window",
            Status::Degenerate { .. } => "degenerate",
        }
    }
}

/// The record of one iteration.
#[derive(Debug, Clone, PartialEq)]
pub struct Iteration {
    /// The parameters this iteration resampled at.
    pub params: Params,
    /// The resampled search patch with its one-pixel border,
    /// `(w + 2) × (h + 2)` in 2-D, `(w + 2) × 1` in 1-D.
    pub bordered: Grid,
    /// The resampled patch itself, `w × h` (the border cut off).
    pub patch: Grid,
    /// Gradients along the search window's columns and rows, `w × h`
    /// (`gr` is zero in 1-D).
    pub gc: Grid,
    pub gr: Grid,
    /// `dL = T − (a7·S + a8)`, row-major.
    pub dl: Vec<f64>,
    /// The design matrix, one row per template pixel, one column per
    /// estimated parameter.
    pub a: Vec<Vec<f64>>,
    /// The least-squares solution of `dL + V = A·dX`.
    pub adjustment: Adjustment,
    /// `dX`, one per estimated parameter.
    pub increments: Vec<f64>,
    /// Largest movement of a patch pixel by the increments (px).
    pub max_move: f64,
    /// Largest change of a modelled grey value by the increments.
    pub max_grey_change: f64,
    /// Border samples that fell outside the search window (replicated).
    pub clamped: usize,
}

/// The whole run.
#[derive(Debug, Clone, PartialEq)]
pub struct Matching {
    /// The estimated parameters, in the order of the columns of `A`.
    pub estimated: Vec<Param>,
    pub start: Params,
    /// The parameters after the last update.
    pub params: Params,
    pub iterations: Vec<Iteration>,
    pub status: Status,
}

impl Matching {
    pub fn converged(&self) -> bool {
        self.status == Status::Converged
    }
    /// σ0 of the last iteration's adjustment.
    pub fn sigma0(&self) -> Option<f64> {
        self.iterations.last().and_then(|i| i.adjustment.sigma0)
    }
    /// Standard deviations of the estimated parameters (last iteration).
    pub fn std_dev(&self) -> Option<Vec<f64>> {
        self.iterations
            .last()
            .and_then(|i| i.adjustment.std_dev.clone())
    }
}

/// Bilinear sample ([`crate::resample::bilinear`]) at a zero-based
/// position, the position first clamped into the grid (the replicate border
/// policy). `None` only for a grid under 2×2, which [`check`] refuses.
fn sample(grid: &Grid, c: f64, r: f64) -> Option<f64> {
    let cmax = grid.width().saturating_sub(1) as f64;
    let rmax = grid.height().saturating_sub(1) as f64;
    resample::bilinear(grid, c.clamp(0.0, cmax), r.clamp(0.0, rmax)).map(|b| b.value)
}

/// The parameters a model estimates.
pub fn estimated(model: Model, one_d: bool) -> Vec<Param> {
    use Param::*;
    match (model, one_d) {
        (Model::Shift, true) => vec![A3],
        (Model::Shift, false) => vec![A3, A6],
        (Model::ShiftRadiometric, true) => vec![A3, Gain, Offset],
        (Model::ShiftRadiometric, false) => vec![A3, A6, Gain, Offset],
        (Model::AffineRadiometric, true) => vec![A1, A3, Gain, Offset],
        (Model::AffineRadiometric, false) => vec![A1, A2, A3, A4, A5, A6, Gain, Offset],
    }
}

/// 1-D least-squares matching of `template` into `search`; `start.a[2]` is
/// the zero-based search position of the template centre.
pub fn match_1d(
    template: &[f64],
    search: &[f64],
    start: Params,
    settings: Settings,
) -> Result<Matching> {
    let t = Grid::new("template", template.len(), 1, template.to_vec())?;
    // Bilinear interpolation needs a 2×2 neighbourhood: the signal becomes
    // a grid of two identical rows, always read on the first (dr = 0).
    let s = Grid::new("search", search.len(), 2, [search, search].concat())?;
    let mut start = start;
    // 1-D: the rows stay put
    start.a[1] = 0.0;
    start.a[3] = 0.0;
    start.a[4] = 1.0;
    start.a[5] = 0.0;
    run(&t, &s, start, settings, true)
}

/// 2-D least-squares matching of `template` into `search`; `start.a[2]`,
/// `start.a[5]` are the zero-based column and row of the template centre.
pub fn match_2d(
    template: &Grid,
    search: &Grid,
    start: Params,
    settings: Settings,
) -> Result<Matching> {
    run(template, search, start, settings, false)
}

/// The template offsets `(u, v)` of pixel `(i, j)` from the template centre.
fn offsets(t: &Grid, one_d: bool) -> impl Fn(usize, usize) -> (f64, f64) {
    let cu = (t.width() as f64 - 1.0) / 2.0;
    let cv = if one_d {
        0.0
    } else {
        (t.height() as f64 - 1.0) / 2.0
    };
    move |i, j| (i as f64 - cu, j as f64 - cv)
}

/// Where patch pixel positions leave the window, if they do.
fn outside(t: &Grid, s: &Grid, p: &Params, one_d: bool) -> Option<String> {
    let off = offsets(t, one_d);
    let cmax = s.width() as f64 - 1.0 + EDGE_SLACK;
    let rmax = s.height() as f64 - 1.0 + EDGE_SLACK;
    for j in 0..t.height() {
        for i in 0..t.width() {
            let (u, v) = off(i, j);
            let (c, r) = p.map(u, v);
            if !(c.is_finite() && r.is_finite()) {
                return Some("the parameters are no longer finite numbers".to_string());
            }
            if c < -EDGE_SLACK || c > cmax || (!one_d && (r < -EDGE_SLACK || r > rmax)) {
                let at = if one_d {
                    format!("template pixel {} falls at position {:.3}", i + 1, c + 1.0)
                } else {
                    format!(
                        "template pixel (column {}, row {}) falls at column {:.3}, row {:.3}",
                        i + 1,
                        j + 1,
                        c + 1.0,
                        r + 1.0
                    )
                };
                let size = if one_d {
                    format!("positions 1 … {}", s.width())
                } else {
                    format!("columns 1 … {}, rows 1 … {}", s.width(), s.height())
                };
                return Some(format!("{at}, outside the search window ({size})"));
            }
        }
    }
    None
}

/// Checks the sizes and the start; `Err` names the field.
fn check(t: &Grid, s: &Grid, start: &Params, settings: &Settings, one_d: bool) -> Result<()> {
    if s.width() < 2 || s.height() < 2 {
        return Err(Error::input(
            "search",
            format!(
                "is {}×{}; bilinear interpolation needs a window of at least 2×2 (use the 1-D matching for a single row)",
                s.width(),
                s.height()
            ),
        ));
    }
    if one_d && t.width() > s.width() {
        return Err(Error::input(
            "template",
            format!(
                "has {} values, more than the {} of the search window",
                t.width(),
                s.width()
            ),
        ));
    }
    if t.width() > s.width() || t.height() > s.height() {
        return Err(Error::input(
            "template",
            format!(
                "is {}×{}, larger than the {}×{} search window",
                t.width(),
                t.height(),
                s.width(),
                s.height()
            ),
        ));
    }
    let u = estimated(settings.model, one_d).len();
    let n = t.width() * t.height();
    if n < u {
        return Err(Error::input(
            "template",
            format!("has {n} pixels; this model estimates {u} parameters and needs at least {u}"),
        ));
    }
    if !(1..=MAX_ITERATIONS).contains(&settings.max_iterations) {
        return Err(Error::input(
            "max_iterations",
            format!(
                "must be between 1 and {MAX_ITERATIONS} (got {})",
                settings.max_iterations
            ),
        ));
    }
    if start.a.iter().any(|x| !x.is_finite()) {
        return Err(Error::input("start", "the start values must be finite"));
    }
    if let Some(detail) = outside(t, s, start, one_d) {
        return Err(Error::input(
            "start",
            format!("the patch does not fit at the start: {detail}"),
        ));
    }
    Ok(())
}

fn run(t: &Grid, s: &Grid, start: Params, settings: Settings, one_d: bool) -> Result<Matching> {
    check(t, s, &start, &settings, one_d)?;
    let est = estimated(settings.model, one_d);
    let mut params = start;
    let mut iterations = Vec::new();
    let mut status = Status::NotConverged;
    for _ in 0..settings.max_iterations {
        match iterate(t, s, &params, &est, settings.gradients, one_d)? {
            Err(reason) => {
                status = Status::Degenerate { reason };
                break;
            }
            Ok(it) => {
                for (k, p) in est.iter().enumerate() {
                    params.a[p.index()] += it.increments.get(k).copied().unwrap_or(0.0);
                }
                let done = it.max_move <= POSITION_TOL && it.max_grey_change <= GREY_TOL;
                iterations.push(it);
                if let Some(detail) = outside(t, s, &params, one_d) {
                    status = Status::LeftWindow { detail };
                    break;
                }
                if done {
                    status = Status::Converged;
                    break;
                }
            }
        }
    }
    Ok(Matching {
        estimated: est,
        start,
        params,
        iterations,
        status,
    })
}

/// One iteration at `p`. The outer `Err` is a bug-class error, the inner
/// `Err` the reason the system is degenerate.
fn iterate(
    t: &Grid,
    s: &Grid,
    p: &Params,
    est: &[Param],
    gradients: Gradients,
    one_d: bool,
) -> Result<std::result::Result<Iteration, String>> {
    let (w, h) = (t.width(), t.height());
    let off = offsets(t, one_d);
    let det = p.det();
    if det.abs() < MIN_DET {
        return Ok(Err(format!(
            "the affine part [a1 a2; a4 a5] has determinant {det:.3e}: it folds the patch flat, so no position is defined"
        )));
    }
    let gain = p.gain();
    if gain.abs() < MIN_DET {
        return Ok(Err(format!(
            "the gain a7 = {gain:.3e} is zero: the search patch no longer enters the model"
        )));
    }
    // 1. resample the patch and its one-pixel border
    let (bw, bh) = (w + 2, if one_d { 1 } else { h + 2 });
    let mut bordered = Grid::filled(bw, bh, 0.0);
    let (cmax, rmax) = (s.width() as f64 - 1.0, s.height() as f64 - 1.0);
    let mut clamped = 0;
    for bj in 0..bh {
        for bi in 0..bw {
            let i = bi as f64 - 1.0;
            let j = if one_d { 0.0 } else { bj as f64 - 1.0 };
            let (u, v) = off(0, 0);
            let (c, r) = p.map(u + i, v + j);
            let out = c < -EDGE_SLACK
                || c > cmax + EDGE_SLACK
                || (!one_d && (r < -EDGE_SLACK || r > rmax + EDGE_SLACK));
            if out {
                clamped += 1;
            }
            let g = sample(s, c, if one_d { 0.0 } else { r })
                .ok_or_else(|| Error::Internal("empty search window".to_string()))?;
            bordered.set(bi, bj, g);
        }
    }
    let (dj, pw) = (usize::from(!one_d), w);
    let patch = Grid::from_fn(w, h, |i, j| bordered.get(i + 1, j + dj).unwrap_or(0.0));
    // 2. gradients along the template axes, then along the window's axes
    let at = |i: isize, j: isize| -> f64 {
        match gradients {
            Gradients::SearchWindow => bordered
                .get((i + 1) as usize, (j + dj as isize) as usize)
                .unwrap_or(0.0),
            Gradients::PatchEdge => {
                let ci = i.clamp(0, pw as isize - 1) as usize;
                let cj = j.clamp(0, h as isize - 1) as usize;
                patch.get(ci, cj).unwrap_or(0.0)
            }
        }
    };
    let mut gc = Grid::filled(w, h, 0.0);
    let mut gr = Grid::filled(w, h, 0.0);
    for j in 0..h {
        for i in 0..w {
            let (ii, jj) = (i as isize, j as isize);
            let gu = (at(ii + 1, jj) - at(ii - 1, jj)) / 2.0;
            let gv = if one_d {
                0.0
            } else {
                (at(ii, jj + 1) - at(ii, jj - 1)) / 2.0
            };
            // [gu, gv] = Jᵀ [gc, gr] with J = [a1 a2; a4 a5]
            let a = &p.a;
            let (c_, r_) = if one_d {
                (gu / a[0], 0.0)
            } else {
                ((a[4] * gu - a[3] * gv) / det, (a[0] * gv - a[1] * gu) / det)
            };
            gc.set(i, j, c_);
            gr.set(i, j, r_);
        }
    }
    if gc.data().iter().chain(gr.data()).all(|g| *g == 0.0) {
        return Ok(Err(
            "the resampled search patch is flat: it has no grey-value gradient, so its position cannot be determined".to_string(),
        ));
    }
    // 3. dL and A
    let n = w * h;
    let mut dl = Vec::with_capacity(n);
    let mut a = Vec::with_capacity(n);
    for j in 0..h {
        for i in 0..w {
            let (u, v) = off(i, j);
            let g = patch.get(i, j).unwrap_or(0.0);
            let tv = t.get(i, j).unwrap_or(0.0);
            dl.push(tv - (gain * g + p.offset()));
            let (x, y) = (
                gain * gc.get(i, j).unwrap_or(0.0),
                gain * gr.get(i, j).unwrap_or(0.0),
            );
            a.push(
                est.iter()
                    .map(|q| match q {
                        Param::A1 => x * u,
                        Param::A2 => x * v,
                        Param::A3 => x,
                        Param::A4 => y * u,
                        Param::A5 => y * v,
                        Param::A6 => y,
                        Param::Gain => g,
                        Param::Offset => 1.0,
                    })
                    .collect::<Vec<_>>(),
            );
        }
    }
    let adjustment = match lsq::adjust(&a, &dl, None) {
        Ok(adj) => adj,
        Err(e @ (Error::Singular { .. } | Error::TooFewObservations { .. })) => {
            return Ok(Err(e.to_string()))
        }
        Err(e) => return Err(e),
    };
    let increments = adjustment.x.clone();
    // 4. what the increments do to positions and grey values
    let mut dp = Params { a: [0.0; 8] };
    for (k, q) in est.iter().enumerate() {
        dp.a[q.index()] = increments.get(k).copied().unwrap_or(0.0);
    }
    let mut max_move: f64 = 0.0;
    let mut max_grey_change: f64 = 0.0;
    for j in 0..h {
        for i in 0..w {
            let (u, v) = off(i, j);
            let (dc, dr) = dp.map(u, v);
            max_move = max_move.max(dc.hypot(dr));
            let g = patch.get(i, j).unwrap_or(0.0);
            max_grey_change = max_grey_change.max((dp.gain() * g + dp.offset()).abs());
        }
    }
    Ok(Ok(Iteration {
        params: *p,
        bordered,
        patch,
        gc,
        gr,
        dl,
        a,
        adjustment,
        increments,
        max_move,
        max_grey_change,
        clamped,
    }))
}

/// A generated pair for trying the affine + radiometric model: a smooth
/// texture `f` (a sum of sinusoids of wavelengths 7–16 px, directions and
/// phases drawn from `seed`) sampled at the pixels gives the search window
/// `S`, and the template is that window seen through the parameters `truth`,
/// resampled with the same bilinear interpolation the matching uses:
/// `T(u, v) = a7·S(a1·u + a2·v + a3, a4·u + a5·v + a6) + a8` — exactly the
/// observation equation of the matching, so without noise its estimates
/// return `truth` (real images add the interpolation's own error). Coordinates are centred: `(u, v)` from the template centre,
/// `(p, q)` from the search window centre. Noise of standard deviation
/// `noise` (grey values) is added to both images.
#[derive(Debug, Clone, PartialEq)]
pub struct SyntheticPair {
    pub template: Grid,
    pub search: Grid,
    /// Zero-based column/row of the search window's centre.
    pub centre: f64,
}

/// Parameters from shift, rotation (degrees, clockwise on the screen as rows
/// count downward), scale and shear: `[a1 a2; a4 a5] = s·R(θ)·[1 k; 0 1]`.
pub fn affine_from(
    shift_c: f64,
    shift_r: f64,
    rotation_deg: f64,
    scale: f64,
    shear: f64,
    gain: f64,
    offset: f64,
) -> Params {
    let (sn, cs) = rotation_deg.to_radians().sin_cos();
    Params {
        a: [
            scale * cs,
            scale * (cs * shear - sn),
            shift_c,
            scale * sn,
            scale * (sn * shear + cs),
            shift_r,
            gain,
            offset,
        ],
    }
}

/// Builds the pair: a `size × size` template (`size` odd) and a search
/// window just large enough for the patch and its border at the start
/// (identity) and at `truth`, plus two pixels.
pub fn synthetic_pair(size: usize, truth: &Params, noise: f64, seed: u64) -> Result<SyntheticPair> {
    if size < 3 || size.is_multiple_of(2) || size > 101 {
        return Err(Error::input(
            "patch_size",
            format!("must be odd and between 3 and 101 (got {size})"),
        ));
    }
    if !(noise.is_finite() && noise >= 0.0) {
        return Err(Error::input("noise", "must be zero or positive"));
    }
    if truth.a.iter().any(|x| !x.is_finite()) {
        return Err(Error::input("parameters", "must be finite"));
    }
    let mut rng = Rng::new(seed ^ 0x5EED_0003);
    let waves: Vec<(f64, f64, f64, f64)> = (0..6)
        .map(|_| {
            let wavelength = 7.0 + 9.0 * rng.unit();
            let dir = std::f64::consts::PI * rng.unit();
            let phase = std::f64::consts::TAU * rng.unit();
            let k = std::f64::consts::TAU / wavelength;
            (k * dir.cos(), k * dir.sin(), phase, 12.0 + 8.0 * rng.unit())
        })
        .collect();
    let f = |p: f64, q: f64| -> f64 {
        120.0
            + waves
                .iter()
                .map(|(kx, ky, ph, amp)| amp * (kx * p + ky * q + ph).sin())
                .sum::<f64>()
    };
    let half = (size as f64 - 1.0) / 2.0 + 1.0;
    let mut reach = half;
    for (u, v) in [(-half, -half), (half, -half), (-half, half), (half, half)] {
        let (p, q) = truth.map(u, v);
        reach = reach.max(p.abs()).max(q.abs());
    }
    if reach > 400.0 {
        return Err(Error::input(
            "parameters",
            "the transformed patch reaches more than 400 px from the centre",
        ));
    }
    let h = reach.ceil() as usize + 2;
    let w = 2 * h + 1;
    let centre = h as f64;
    let clean = Grid::from_fn(w, w, |i, j| f(i as f64 - centre, j as f64 - centre));
    let search = Grid::from_fn(w, w, |i, j| {
        clean.get(i, j).unwrap_or(0.0) + noise * rng_normal_at(seed, 1, i, j)
    });
    let c0 = (size as f64 - 1.0) / 2.0;
    let mut template = Grid::filled(size, size, 0.0);
    for j in 0..size {
        for i in 0..size {
            let (p, q) = truth.map(i as f64 - c0, j as f64 - c0);
            let g = sample(&clean, p + centre, q + centre)
                .ok_or_else(|| Error::Internal("empty synthetic window".to_string()))?;
            let t = truth.gain() * g + truth.offset() + noise * rng_normal_at(seed, 2, i, j);
            template.set(i, j, t);
        }
    }
    Ok(SyntheticPair {
        template,
        search,
        centre,
    })
}

/// A standard normal number for pixel `(i, j)` of image `image`, the same
/// whatever order pixels are visited in.
fn rng_normal_at(seed: u64, image: u64, i: usize, j: usize) -> f64 {
    let key = seed
        .wrapping_mul(0x1000_0000_01B3)
        .wrapping_add(image << 48)
        .wrapping_add((j as u64) << 24)
        .wrapping_add(i as u64);
    Rng::new(key).normal()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn settings(model: Model) -> Settings {
        Settings {
            model,
            gradients: Gradients::SearchWindow,
            max_iterations: DEFAULT_ITERATIONS,
        }
    }

    #[test]
    fn example_10_first_increment() {
        let t = [1.0, 2.0, 9.0, 9.0, 8.0, 2.0, 1.0];
        let s = [1.0, 2.0, 2.0, 1.0, 1.0, 3.0, 8.0, 8.0, 6.0, 1.0, 1.0, 1.0];
        let m = match_1d(
            &t,
            &s,
            Params::shift(7.0, 0.0, 1.0, 0.0),
            settings(Model::Shift),
        )
        .unwrap();
        assert!((m.iterations[0].increments[0] + 11.5 / 39.0).abs() < 1e-12);
        assert_eq!(
            m.iterations[0].a.iter().map(|r| r[0]).collect::<Vec<_>>(),
            [1.0, 3.5, 2.5, -1.0, -3.5, -2.5, 0.0]
        );
    }
}
