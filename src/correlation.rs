//! Normalized cross-correlation (NCC) and subpixel correlation peaks.
//!
//! - [`ncc`]: the correlation coefficient of two equal-size arrays,
//!   `ρ = Σ(A−Ā)(B−B̄) / √(Σ(A−Ā)² · Σ(B−B̄)²)`, with its means and three sums.
//! - [`correlate_1d`], [`correlate_2d`]: the coefficient of a template at
//!   every position where it fits inside a search array (1-D profile, 2-D
//!   correlation surface), and the best position.
//! - [`parabola_peak`]: the 2nd-order polynomial `ρ = a0 + a1·c + a2·c²`
//!   through three values and the location of its maximum.
//! - [`quadric_peak`]: the six-term surface
//!   `ρ = a0 + a1·c + a2·r + a3·c·r + a4·c² + a5·r²` fitted by least squares
//!   ([`crate::lsq`]) to a 3×3 neighbourhood, and the location of its
//!   maximum.
//!
//! An array without variance has no correlation coefficient (`rho: None`),
//! and a fitted curve or surface without a true maximum says what it is
//! instead ([`Extremum`]): nothing here returns NaN.
//!
//! One computation path: [`ncc`], [`correlate_1d`] and [`correlate_2d`] all
//! go through the same [`Template::against`].

use crate::error::{Error, Result};
use crate::lsq::{self, Adjustment};
use crate::raster::Grid;

pub mod fast;

/// Relative size under which a sum of squared deviations counts as zero
/// (the array is flat up to rounding), measured against `n·max|x|²`.
const FLAT: f64 = 1e-24;
/// Relative size under which a curvature (or the determinant of the
/// surface's Hessian) counts as zero.
const DEGENERATE: f64 = 1e-12;

/// The correlation coefficient of two arrays with its intermediates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ncc {
    /// Number of values in each array.
    pub n: usize,
    /// `Ā`, the mean of the first array (the template).
    pub mean_a: f64,
    /// `B̄`, the mean of the second array (the window).
    pub mean_b: f64,
    /// `Σ(A−Ā)(B−B̄)`.
    pub sum_dadb: f64,
    /// `Σ(A−Ā)²`.
    pub sum_da2: f64,
    /// `Σ(B−B̄)²`.
    pub sum_db2: f64,
    /// `ρ`, or `None` when either array has no variance.
    pub rho: Option<f64>,
}

/// Which array of a pair has no variance.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Flat {
    Neither,
    A,
    B,
    Both,
}

impl Ncc {
    /// Which of the two arrays is flat (has no variance).
    pub fn flat(&self) -> Flat {
        match (
            is_flat(self.sum_da2, self.n, self.mean_a),
            is_flat(self.sum_db2, self.n, self.mean_b),
        ) {
            (false, false) => Flat::Neither,
            (true, false) => Flat::A,
            (false, true) => Flat::B,
            (true, true) => Flat::Both,
        }
    }
}

/// True when a sum of squared deviations is zero up to rounding.
fn is_flat(sum_sq: f64, n: usize, mean: f64) -> bool {
    sum_sq <= FLAT * n as f64 * mean * mean || sum_sq <= 0.0
}

/// A template prepared for correlation: its mean, deviations and `Σ(A−Ā)²`,
/// computed once and used at every position.
#[derive(Debug, Clone, PartialEq)]
pub struct Template {
    values: Vec<f64>,
    mean: f64,
    dev: Vec<f64>,
    sum_da2: f64,
}

impl Template {
    /// Prepares `values` (non-empty, finite; `field` names them in errors).
    pub fn new(field: &str, values: &[f64]) -> Result<Self> {
        check_values(field, values)?;
        let mean = mean(values);
        let dev: Vec<f64> = values.iter().map(|a| a - mean).collect();
        let sum_da2 = dev.iter().map(|d| d * d).sum();
        Ok(Template {
            values: values.to_vec(),
            mean,
            dev,
            sum_da2,
        })
    }

    /// The template's values.
    pub fn values(&self) -> &[f64] {
        &self.values
    }
    /// `Ā`.
    pub fn mean(&self) -> f64 {
        self.mean
    }
    /// `Σ(A−Ā)²`.
    pub fn sum_da2(&self) -> f64 {
        self.sum_da2
    }
    /// True when the template has no variance (no position has a `ρ`).
    pub fn is_flat(&self) -> bool {
        is_flat(self.sum_da2, self.values.len(), self.mean)
    }

    /// The correlation with a window given as an iterator over its values
    /// in the template's order (exactly `len` of them; the callers
    /// guarantee the length).
    fn against<I>(&self, window: I) -> Ncc
    where
        I: Iterator<Item = f64> + Clone,
    {
        let n = self.values.len();
        let mean_b = window.clone().sum::<f64>() / n as f64;
        let (sum_dadb, sum_db2) = cross_sums(self.dev.iter().copied(), window, mean_b);
        let mut out = Ncc {
            n,
            mean_a: self.mean,
            mean_b,
            sum_dadb,
            sum_da2: self.sum_da2,
            sum_db2,
            rho: None,
        };
        if out.flat() == Flat::Neither {
            let rho = rho_of_sums(sum_dadb, self.sum_da2, sum_db2);
            if rho.is_finite() {
                out.rho = Some(rho.clamp(-1.0, 1.0));
            }
        }
        out
    }
}

/// `Σ ΔA·(B−B̄)` and `Σ (B−B̄)²` over deviations `da` of A and values `b`.
fn cross_sums(
    da: impl Iterator<Item = f64>,
    b: impl Iterator<Item = f64>,
    mean_b: f64,
) -> (f64, f64) {
    let (mut sum_dadb, mut sum_db2) = (0.0, 0.0);
    for (da, b) in da.zip(b) {
        let db = b - mean_b;
        sum_dadb += da * db;
        sum_db2 += db * db;
    }
    (sum_dadb, sum_db2)
}

/// The mean of `xs` (0 for none).
pub fn mean(xs: &[f64]) -> f64 {
    xs.iter().sum::<f64>() / xs.len().max(1) as f64
}

/// The three sums of a correlation coefficient about means that are
/// given, not computed: `[Σ(A−Ā)(B−B̄), Σ(A−Ā)², Σ(B−B̄)²]` (a stage of
/// [`ncc`]: what practice carries a student's rounded or wrong means
/// through; means 0 give the sums of the plain grey values).
pub fn sums_about(a: &[f64], mean_a: f64, b: &[f64], mean_b: f64) -> [f64; 3] {
    let da = a.iter().map(|x| x - mean_a);
    let (sum_dadb, sum_db2) = cross_sums(da.clone(), b.iter().copied(), mean_b);
    [sum_dadb, da.map(|d| d * d).sum(), sum_db2]
}

/// `ρ = Σ(A−Ā)(B−B̄) / √(Σ(A−Ā)² · Σ(B−B̄)²)` from its three sums (the last
/// stage of [`ncc`]; not finite when a sum of squares is 0).
pub fn rho_of_sums(sum_dadb: f64, sum_da2: f64, sum_db2: f64) -> f64 {
    sum_dadb / (sum_da2 * sum_db2).sqrt()
}

fn check_values(field: &str, values: &[f64]) -> Result<()> {
    if values.is_empty() {
        return Err(Error::input(field, "is empty: give at least one value"));
    }
    if let Some(i) = values.iter().position(|x| !x.is_finite()) {
        return Err(Error::input(
            field,
            format!("value {} is not a finite number", i + 1),
        ));
    }
    Ok(())
}

/// Where both slopes of `ρ = a0 + a1·x + a2·y + a3·x·y + a4·x² + a5·y²`
/// are zero: `[2a4 a3; a3 2a5]·[x y]ᵀ = −[a1 a2]ᵀ` by Cramer's rule
/// (`None` when the determinant `4·a4·a5 − a3²` is 0). A stage of
/// [`quadric_peak`], for coefficients given (printed, or a student's).
pub fn stationary(a: &[f64; 6]) -> Option<[f64; 2]> {
    let det = 4.0 * a[4] * a[5] - a[3] * a[3];
    if det == 0.0 {
        return None;
    }
    Some([
        (-a[1] * 2.0 * a[5] + a[2] * a[3]) / det,
        (-a[2] * 2.0 * a[4] + a[1] * a[3]) / det,
    ])
}

/// The correlation coefficient of two equal-length arrays `a` and `b`
/// (1-D, or 2-D arrays in row-major order).
///
/// `ρ = Σ(A−Ā)(B−B̄) / √(Σ(A−Ā)² · Σ(B−B̄)²)`; `rho` is `None` when either
/// array has no variance.
pub fn ncc(a: &[f64], b: &[f64]) -> Result<Ncc> {
    let t = Template::new("a", a)?;
    check_values("b", b)?;
    if a.len() != b.len() {
        return Err(Error::input(
            "b",
            format!(
                "has {} values but a has {}: the arrays must be the same size",
                b.len(),
                a.len()
            ),
        ));
    }
    Ok(t.against(b.iter().copied()))
}

/// [`ncc`] of two grids of the same shape.
pub fn ncc_grid(a: &Grid, b: &Grid) -> Result<Ncc> {
    if (a.width(), a.height()) != (b.width(), b.height()) {
        return Err(Error::input(
            "b",
            format!(
                "is {}×{} but a is {}×{}: the arrays must be the same size",
                b.height(),
                b.width(),
                a.height(),
                a.width()
            ),
        ));
    }
    ncc(a.data(), b.data())
}

/// The correlation of a template at every position of a 1-D search array.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    /// Template length `n`.
    pub template_len: usize,
    /// One entry per position `k = 0 … len(search) − n` (the sub-window
    /// `search[k .. k+n]`).
    pub windows: Vec<Ncc>,
    /// Index of the largest `ρ` (the first one on ties), `None` when no
    /// position has a `ρ`.
    pub best: Option<usize>,
    /// Number of positions that share the largest `ρ`.
    pub ties: usize,
}

/// The largest `Some` value's index (first on ties) and the number of ties.
fn best_of(rhos: impl Iterator<Item = Option<f64>>) -> (Option<usize>, usize) {
    let mut best: Option<(usize, f64)> = None;
    let mut ties = 0;
    for (i, r) in rhos.enumerate() {
        let Some(r) = r else { continue };
        match best {
            Some((_, b)) if r < b => {}
            Some((_, b)) if r == b => ties += 1,
            _ => {
                best = Some((i, r));
                ties = 1;
            }
        }
    }
    (best.map(|(i, _)| i), ties)
}

fn check_fits_1d(template: &[f64], search: &[f64]) -> Result<()> {
    check_values("template", template)?;
    check_values("search", search)?;
    if template.len() > search.len() {
        return Err(Error::input(
            "template",
            format!(
                "has {} values but the search array only {}: the template must fit in the search array",
                template.len(),
                search.len()
            ),
        ));
    }
    Ok(())
}

/// The correlation coefficient of `template` with every sub-window of
/// `search` of the same length.
pub fn correlate_1d(template: &[f64], search: &[f64]) -> Result<Profile> {
    check_fits_1d(template, search)?;
    let t = Template::new("template", template)?;
    let windows: Vec<Ncc> = search
        .windows(template.len())
        .map(|w| t.against(w.iter().copied()))
        .collect();
    let (best, ties) = best_of(windows.iter().map(|w| w.rho));
    Ok(Profile {
        template_len: template.len(),
        windows,
        best,
        ties,
    })
}

/// The correlation surface of a 2-D template over a search array.
#[derive(Debug, Clone, PartialEq)]
pub struct Surface {
    /// Number of positions across (`search width − template width + 1`).
    pub width: usize,
    /// Number of positions down.
    pub height: usize,
    /// One entry per position, row-major: entry `r·width + c` is the
    /// sub-window whose top-left pixel is search `(c, r)` (0-based).
    pub windows: Vec<Ncc>,
    /// `(c, r)` of the largest `ρ` (the first in row-major order on ties),
    /// `None` when no position has a `ρ`.
    pub best: Option<(usize, usize)>,
    /// Number of positions that share the largest `ρ`.
    pub ties: usize,
}

impl Surface {
    /// The `ρ` at position `(c, r)` (0-based), `None` outside or when flat.
    pub fn rho(&self, c: usize, r: usize) -> Option<f64> {
        if c >= self.width || r >= self.height {
            return None;
        }
        self.windows.get(r * self.width + c).and_then(|w| w.rho)
    }

    /// The surface as rows of `ρ` (`None` where a window is flat).
    pub fn rho_rows(&self) -> Vec<Vec<Option<f64>>> {
        self.windows
            .chunks(self.width.max(1))
            .map(|row| row.iter().map(|w| w.rho).collect())
            .collect()
    }
}

/// Largest number of template-by-position products [`correlate_2d`]
/// accepts: a 64×64 search array with any template is well below it.
pub const MAX_PRODUCTS_2D: usize = 20_000_000;

/// The correlation coefficient of `template` with every sub-window of
/// `search` of the template's size.
pub fn correlate_2d(template: &Grid, search: &Grid) -> Result<Surface> {
    let (tw, th) = (template.width(), template.height());
    let (sw, sh) = (search.width(), search.height());
    if tw > sw || th > sh {
        return Err(Error::input(
            "template",
            format!(
                "is {th}×{tw} but the search array only {sh}×{sw}: the template must fit in the search array"
            ),
        ));
    }
    let (width, height) = (sw - tw + 1, sh - th + 1);
    let products = width
        .saturating_mul(height)
        .saturating_mul(tw.saturating_mul(th));
    if products > MAX_PRODUCTS_2D {
        return Err(Error::input(
            "search",
            format!(
                "a {th}×{tw} template at {height}×{width} positions takes {products} products; at most {MAX_PRODUCTS_2D} are allowed (use a smaller search array or template)"
            ),
        ));
    }
    let t = Template::new("template", template.data())?;
    let data = search.data();
    let mut windows = Vec::with_capacity(width * height);
    for r in 0..height {
        for c in 0..width {
            // rows r..r+th of the search array, columns c..c+tw
            let rows = data
                .chunks(sw)
                .skip(r)
                .take(th)
                .flat_map(move |row| row.iter().skip(c).take(tw).copied());
            windows.push(t.against(rows));
        }
    }
    let (best, ties) = best_of(windows.iter().map(|w| w.rho));
    Ok(Surface {
        width,
        height,
        windows,
        best: best.map(|i| (i % width, i / width)),
        ties,
    })
}

/// What a fitted curve or surface has at its stationary point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Extremum {
    /// A true maximum at this location (`[c]` or `[c, r]`) with this value.
    Maximum { at: [f64; 2], value: f64 },
    /// The curvature is upward: the stationary point is a minimum.
    Minimum { at: [f64; 2], value: f64 },
    /// The surface curves up one way and down the other.
    Saddle { at: [f64; 2], value: f64 },
    /// No curvature (a straight line or a ridge/valley): no single
    /// stationary point.
    Degenerate,
}

impl Extremum {
    /// The location of the maximum, if there is one.
    pub fn maximum(&self) -> Option<[f64; 2]> {
        match self {
            Extremum::Maximum { at, .. } => Some(*at),
            _ => None,
        }
    }
}

/// The parabola through three points and its extremum.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parabola {
    /// `[a0, a1, a2]` of `ρ = a0 + a1·c + a2·c²`.
    pub coefficients: [f64; 3],
    /// The same parabola about the middle position `m`:
    /// `ρ = b0 + b1·(c−m) + b2·(c−m)²`.
    pub local: [f64; 3],
    /// The centre `m` of the local form (the mean of the positions).
    pub centre: f64,
    /// The extremum; `at[1]` is unused (0).
    pub extremum: Extremum,
}

fn check_distinct(field: &str, x: [f64; 3]) -> Result<()> {
    if let Some(i) = x.iter().position(|v| !v.is_finite()) {
        return Err(Error::input(
            field,
            format!("value {} is not a finite number", i + 1),
        ));
    }
    let scale = x.iter().fold(1.0f64, |m, v| m.max(v.abs()));
    for i in 0..3 {
        for j in (i + 1)..3 {
            if (x[i] - x[j]).abs() <= 1e-9 * scale {
                return Err(Error::input(
                    field,
                    format!(
                        "values {} and {} are the same position; three different positions are needed",
                        i + 1,
                        j + 1
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// The parabola `ρ = a0 + a1·c + a2·c²` through `(x[i], y[i])` and the
/// location of its maximum `c = −a1 / (2·a2)` (a maximum only when
/// `a2 < 0`).
///
/// Computed about the mean position (divided differences), then expanded to
/// the seed's form, so that large positions stay exact.
pub fn parabola_peak(x: [f64; 3], y: [f64; 3]) -> Result<Parabola> {
    check_distinct("positions", x)?;
    if let Some(i) = y.iter().position(|v| !v.is_finite()) {
        return Err(Error::input(
            "rho",
            format!("value {} is not a finite number", i + 1),
        ));
    }
    let m = (x[0] + x[1] + x[2]) / 3.0;
    let u = [x[0] - m, x[1] - m, x[2] - m];
    let d1 = (y[1] - y[0]) / (u[1] - u[0]);
    let d2 = (y[2] - y[1]) / (u[2] - u[1]);
    let b2 = (d2 - d1) / (u[2] - u[0]);
    let b1 = d1 - b2 * (u[0] + u[1]);
    let b0 = y[0] - d1 * u[0] + b2 * u[0] * u[1];
    let coefficients = [b0 - b1 * m + b2 * m * m, b1 - 2.0 * b2 * m, b2];
    // curvature scale: what a2 would be for a change of max|y| over the span
    let span = u.iter().fold(0.0f64, |s, v| s.max(v.abs()));
    let ymax = y.iter().fold(0.0f64, |s, v| s.max(v.abs()));
    let tol = DEGENERATE * ymax / (span * span);
    let extremum = if b2.abs() <= tol {
        Extremum::Degenerate
    } else {
        let du = -b1 / (2.0 * b2);
        let at = [m + du, 0.0];
        let value = b0 + b1 * du + b2 * du * du;
        if b2 < 0.0 {
            Extremum::Maximum { at, value }
        } else {
            Extremum::Minimum { at, value }
        }
    };
    Ok(Parabola {
        coefficients,
        local: [b0, b1, b2],
        centre: m,
        extremum,
    })
}

/// The six-term quadratic surface fitted to a 3×3 neighbourhood.
#[derive(Debug, Clone, PartialEq)]
pub struct Quadric {
    /// `[a0 … a5]` of `ρ = a0 + a1·c + a2·r + a3·c·r + a4·c² + a5·r²`.
    pub coefficients: [f64; 6],
    /// The same surface about the centre `(c̄, r̄)`, in `u = c − c̄`,
    /// `v = r − r̄`: `[b0 … b5]`.
    pub local: [f64; 6],
    /// `(c̄, r̄)`, the means of the given columns and rows.
    pub centre: [f64; 2],
    /// The nine observation equations in the seed's form: rows
    /// `[1, c, r, c·r, c², r²]`, row-major over the neighbourhood
    /// (`r` outer, `c` inner).
    pub design: Vec<Vec<f64>>,
    /// The nine observed `ρ` in the same order.
    pub observations: Vec<f64>,
    /// The least-squares adjustment in the centred coordinates (its `x` is
    /// [`Quadric::local`]; `v` are the residuals of the nine `ρ`).
    pub adjustment: Adjustment,
    /// The determinant of the Hessian over 1: `4·a4·a5 − a3²`.
    pub det: f64,
    /// The extremum of the surface.
    pub extremum: Extremum,
}

/// Fits `ρ = a0 + a1·c + a2·r + a3·c·r + a4·c² + a5·r²` by least squares to
/// the 3×3 values `rho[i][j]` at column `c[j]`, row `r[i]`, and locates its
/// maximum from `∂ρ/∂c = a1 + a3·r + 2·a4·c = 0`,
/// `∂ρ/∂r = a2 + a3·c + 2·a5·r = 0`. It is a maximum only when the
/// surface is concave (`a4 < 0` and `4·a4·a5 − a3² > 0`).
///
/// The adjustment runs in coordinates centred on `(c̄, r̄)` (a well
/// conditioned system however large `c`, `r` are); the result is the same
/// least-squares surface, expanded to the seed's form.
pub fn quadric_peak(c: [f64; 3], r: [f64; 3], rho: [[f64; 3]; 3]) -> Result<Quadric> {
    check_distinct("c", c)?;
    check_distinct("r", r)?;
    for (i, row) in rho.iter().enumerate() {
        if let Some(j) = row.iter().position(|v| !v.is_finite()) {
            return Err(Error::input(
                "rho",
                format!(
                    "value at row {}, column {} is not a finite number",
                    i + 1,
                    j + 1
                ),
            ));
        }
    }
    let cm = (c[0] + c[1] + c[2]) / 3.0;
    let rm = (r[0] + r[1] + r[2]) / 3.0;
    let mut design = Vec::with_capacity(9);
    let mut local_design = Vec::with_capacity(9);
    let mut observations = Vec::with_capacity(9);
    for (ri, row) in r.iter().zip(rho.iter()) {
        for (ci, value) in c.iter().zip(row.iter()) {
            design.push(vec![1.0, *ci, *ri, ci * ri, ci * ci, ri * ri]);
            let (u, v) = (ci - cm, ri - rm);
            local_design.push(vec![1.0, u, v, u * v, u * u, v * v]);
            observations.push(*value);
        }
    }
    let adjustment =
        lsq::adjust(&local_design, &observations, None).map_err(|e| e.in_field("c"))?;
    let b: [f64; 6] = match adjustment.x.as_slice() {
        [b0, b1, b2, b3, b4, b5] => [*b0, *b1, *b2, *b3, *b4, *b5],
        _ => {
            return Err(Error::Internal(
                "the surface fit did not return six coefficients".to_string(),
            ))
        }
    };
    let coefficients = [
        b[0] - b[1] * cm - b[2] * rm + b[3] * cm * rm + b[4] * cm * cm + b[5] * rm * rm,
        b[1] - b[3] * rm - 2.0 * b[4] * cm,
        b[2] - b[3] * cm - 2.0 * b[5] * rm,
        b[3],
        b[4],
        b[5],
    ];
    let det = 4.0 * b[4] * b[5] - b[3] * b[3];
    let scale = (4.0 * b[4] * b[5]).abs().max(b[3] * b[3]);
    // curvature that is rounding noise against the data (a plane) is none
    let span = |x: [f64; 3], m: f64| x.iter().fold(0.0f64, |s, v| s.max((v - m).abs()));
    let (su, sv) = (span(c, cm), span(r, rm));
    let rho_max = rho.iter().flatten().fold(0.0f64, |s, v| s.max(v.abs()));
    let curvature = (b[4].abs() * su * su)
        .max(b[5].abs() * sv * sv)
        .max(b[3].abs() * su * sv);
    let flat = curvature <= DEGENERATE * rho_max;
    let extremum = if flat || det.abs() <= DEGENERATE * scale || scale == 0.0 {
        Extremum::Degenerate
    } else {
        let [u, v] = stationary(&b).unwrap_or([0.0, 0.0]);
        let value = b[0] + b[1] * u + b[2] * v + b[3] * u * v + b[4] * u * u + b[5] * v * v;
        let at = [cm + u, rm + v];
        if det < 0.0 {
            Extremum::Saddle { at, value }
        } else if b[4] < 0.0 {
            Extremum::Maximum { at, value }
        } else {
            Extremum::Minimum { at, value }
        }
    };
    Ok(Quadric {
        coefficients,
        local: b,
        centre: [cm, rm],
        design,
        observations,
        adjustment,
        det,
        extremum,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seed_example_6() {
        let a = [48.0, 50.0, 48.0, 51.0, 67.0, 71.0, 55.0, 67.0, 72.0];
        let b = [52.0, 37.0, 41.0, 67.0, 54.0, 78.0, 42.0, 74.0, 87.0];
        let n = ncc(&a, &b).unwrap();
        assert!((n.rho.unwrap() - 0.775_269_267_865_958).abs() < 1e-12);
        assert!((n.sum_dadb - 1_149.222_222_222_222).abs() < 1e-9);
    }

    #[test]
    fn flat_arrays_have_no_rho() {
        let n = ncc(&[0.1, 0.1, 0.1], &[1.0, 2.0, 3.0]).unwrap();
        assert_eq!(n.rho, None);
        assert_eq!(n.flat(), Flat::A);
        let n = ncc(&[1.0, 2.0, 3.0], &[7.0; 3]).unwrap();
        assert_eq!((n.rho, n.flat()), (None, Flat::B));
    }

    #[test]
    fn parabola_and_quadric_shapes() {
        let p = parabola_peak([7.0, 8.0, 9.0], [0.69, 0.97, 0.37]).unwrap();
        assert!((p.extremum.maximum().unwrap()[0] - 7.818_181_818_181_818).abs() < 1e-12);
        let p = parabola_peak([1.0, 2.0, 3.0], [1.0, 0.0, 1.0]).unwrap();
        assert!(matches!(p.extremum, Extremum::Minimum { .. }));
        let p = parabola_peak([1.0, 2.0, 3.0], [1.0, 2.0, 3.0]).unwrap();
        assert_eq!(p.extremum, Extremum::Degenerate);
        let q = quadric_peak([0.0, 1.0, 2.0], [0.0, 1.0, 2.0], [[0.0; 3]; 3]).unwrap();
        assert_eq!(q.extremum, Extremum::Degenerate);
    }
}
