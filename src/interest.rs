//! Interest operators: the Förstner operator (seed 000 Example 13, seed 003)
//! and the Moravec operator (seed 000 Example 14), on one window and as
//! whole-image maps with thresholding and non-maximum suppression.
//!
//! One computation path: [`forstner_map`] and [`moravec_map`] cut the window
//! of every pixel out of the image with [`window_at`] and call [`forstner`]
//! and [`moravec`] on it, the same functions the worked examples call.
//!
//! Conventions (as the seeds): `c` column to the right, `r` row downward,
//! zero-based here; gradients by central differences
//! `g′x = (g(c+1, r) − g(c−1, r))/2`, `g′y = (g(c, r+1) − g(c, r−1))/2`,
//! computed at the interior pixels of the window (the border pixels only
//! serve as neighbours).

use crate::error::{Error, Result};
use crate::raster::Grid;

pub mod fast;

/// Smallest window side: a central difference needs a neighbour on each side.
pub const MIN_WINDOW: usize = 3;
/// Largest window side accepted by the window functions.
pub const MAX_WINDOW: usize = 32;
/// Largest image side accepted by the whole-image maps.
pub const MAX_IMAGE: usize = 4096;
/// `det N` counts as zero when `det N ≤ SINGULAR_TOL · (trace N)²`: a
/// straight edge in any direction, whose `det N` is zero up to rounding.
pub const SINGULAR_TOL: f64 = 1e-12;

/// The central-difference gradient at `(c, r)`:
/// `((g(c+1, r) − g(c−1, r))/2, (g(c, r+1) − g(c, r−1))/2)`, or `None`
/// on the border of the grid (or outside), where a neighbour is missing.
///
/// This is seed 000's gradient for the Förstner operator (Example 13).
pub fn central_difference(g: &Grid, c: usize, r: usize) -> Option<(f64, f64)> {
    if c == 0 || r == 0 {
        return None;
    }
    let left = g.get(c - 1, r)?;
    let right = g.get(c + 1, r)?;
    let up = g.get(c, r - 1)?;
    let down = g.get(c, r + 1)?;
    Some(((right - left) / 2.0, (down - up) / 2.0))
}

/// Checks that a window is at least 3×3 and at most
/// [`MAX_WINDOW`]×[`MAX_WINDOW`]; `field` names the input in errors.
pub fn check_window(field: &str, w: &Grid) -> Result<()> {
    let (cols, rows) = (w.width(), w.height());
    if cols < MIN_WINDOW || rows < MIN_WINDOW {
        return Err(Error::input(
            field,
            format!(
                "is {rows}×{cols}; the window needs at least {MIN_WINDOW}×{MIN_WINDOW} so that an interior pixel has a neighbour on every side"
            ),
        ));
    }
    if cols > MAX_WINDOW || rows > MAX_WINDOW {
        return Err(Error::input(
            field,
            format!("is {rows}×{cols}; at most {MAX_WINDOW}×{MAX_WINDOW} is allowed"),
        ));
    }
    Ok(())
}

/// One row of the Förstner gradient table: an interior pixel of the window.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GradientRow {
    /// Column and row in the window, zero-based.
    pub c: usize,
    pub r: usize,
    /// The grey value and its four neighbours.
    pub g: f64,
    pub left: f64,
    pub right: f64,
    pub up: f64,
    pub down: f64,
    /// `g′x = (right − left)/2`, `g′y = (down − up)/2`.
    pub gx: f64,
    pub gy: f64,
    /// `g′x·g′y`, `(g′x)²`, `(g′y)²`.
    pub gxgy: f64,
    pub gx2: f64,
    pub gy2: f64,
}

/// The column sums of the gradient table.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Sums {
    pub gx: f64,
    pub gy: f64,
    pub gxgy: f64,
    pub gx2: f64,
    pub gy2: f64,
}

/// Everything that follows from `N`: the quantities seed 000 and seed 003
/// use, with "no value" as `None` where `N` is singular.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measures {
    /// `N = [[Σg′x², Σg′xg′y], [Σg′xg′y, Σg′y²]]`.
    pub n: [[f64; 2]; 2],
    /// `det N`, set to exactly 0 when [`Measures::singular`].
    pub det: f64,
    /// `trace N = Σg′x² + Σg′y²`.
    pub trace: f64,
    /// `det N` is zero (up to [`SINGULAR_TOL`]): a flat window or a straight edge.
    pub singular: bool,
    /// `N⁻¹ = adj N / det N`; `None` when singular.
    pub inverse: Option<[[f64; 2]; 2]>,
    /// `trace N⁻¹ = trace N / det N`; `None` (infinite) when singular.
    pub trace_inverse: Option<f64>,
    /// Förstner's weight `w = det N / trace N = 1 / trace N⁻¹`; 0 when
    /// singular (its limit: `0 ≤ w ≤ trace N / 4`).
    pub w: f64,
    /// Roundness `q = 4 det N / (trace N)²` in [0, 1]; `None` when `N = 0`.
    pub q: Option<f64>,
    /// Eigenvalues of `N`, `lambda_max ≥ lambda_min ≥ 0`.
    pub lambda_max: f64,
    pub lambda_min: f64,
    /// Direction of the eigenvector of `lambda_min` (radians, from +c toward
    /// +r): the direction in which the position is least certain.
    pub weak_angle: f64,
    /// Number of gradient pixels summed (`m` of seed 003).
    pub m: usize,
}

impl Measures {
    /// The measures of `N` built from the table sums of `m` pixels.
    pub fn from_sums(s: &Sums, m: usize) -> Self {
        let (a, b, d) = (s.gx2, s.gxgy, s.gy2);
        let trace = a + d;
        let det_raw = a * d - b * b;
        let singular = trace <= 0.0 || det_raw <= SINGULAR_TOL * trace * trace;
        let det = if singular { 0.0 } else { det_raw };
        let root = ((a - d) / 2.0).hypot(b);
        let lambda_max = trace / 2.0 + root;
        // det/λmax rather than trace/2 − root: no cancellation for thin ellipses.
        let lambda_min = if singular || lambda_max <= 0.0 {
            0.0
        } else {
            det / lambda_max
        };
        let (inverse, trace_inverse, w) = if singular {
            (None, None, 0.0)
        } else {
            (
                Some([[d / det, -b / det], [-b / det, a / det]]),
                Some(trace / det),
                det / trace,
            )
        };
        let q = (trace > 0.0).then(|| 4.0 * det / (trace * trace));
        let strong = 0.5 * (2.0 * b).atan2(a - d);
        let weak_angle = if trace > 0.0 {
            strong + std::f64::consts::FRAC_PI_2
        } else {
            0.0
        };
        Measures {
            n: [[a, b], [b, d]],
            det,
            trace,
            singular,
            inverse,
            trace_inverse,
            w,
            q,
            lambda_max,
            lambda_min,
            weak_angle,
            m,
        }
    }
}

/// The Förstner operator on one window: the gradient table row by row, its
/// sums and the measures of `N`.
#[derive(Debug, Clone, PartialEq)]
pub struct Forstner {
    /// The interior pixels in row-major order (the seed's table order).
    pub rows: Vec<GradientRow>,
    /// `g′x`, `g′y` of the interior, `(width − 2) × (height − 2)`.
    pub gx: Grid,
    pub gy: Grid,
    pub sums: Sums,
    pub measures: Measures,
}

/// The Förstner operator on a window of at least 3×3 (`field` names it in
/// errors): central-difference gradients at every interior pixel, `N`, and
/// everything that follows from `N`.
pub fn forstner(window: &Grid) -> Result<Forstner> {
    check_window("window", window)?;
    let (wi, hi) = (window.width() - 2, window.height() - 2);
    let mut rows = Vec::with_capacity(wi * hi);
    let mut sums = Sums::default();
    for r in 1..=hi {
        for c in 1..=wi {
            let get = |c: usize, r: usize| {
                window
                    .get(c, r)
                    .ok_or_else(|| Error::Internal(format!("window pixel ({c}, {r}) missing")))
            };
            let (g, left, right, up, down) = (
                get(c, r)?,
                get(c - 1, r)?,
                get(c + 1, r)?,
                get(c, r - 1)?,
                get(c, r + 1)?,
            );
            let (gx, gy) = central_difference(window, c, r)
                .ok_or_else(|| Error::Internal("interior pixel without neighbours".into()))?;
            let row = GradientRow {
                c,
                r,
                g,
                left,
                right,
                up,
                down,
                gx,
                gy,
                gxgy: gx * gy,
                gx2: gx * gx,
                gy2: gy * gy,
            };
            sums.gx += row.gx;
            sums.gy += row.gy;
            sums.gxgy += row.gxgy;
            sums.gx2 += row.gx2;
            sums.gy2 += row.gy2;
            rows.push(row);
        }
    }
    let gx = Grid::new("gx", wi, hi, rows.iter().map(|t| t.gx).collect())?;
    let gy = Grid::new("gy", wi, hi, rows.iter().map(|t| t.gy).collect())?;
    let measures = Measures::from_sums(&sums, rows.len());
    Ok(Forstner {
        rows,
        gx,
        gy,
        sums,
        measures,
    })
}

/// Seed 003's three cases of the error ellipse.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Case {
    /// Uncertain in every direction: no gradient worth the name.
    Flat,
    /// Certain across, uncertain along one direction.
    Edge,
    /// Certain in every direction: a distinct point.
    Corner,
}

impl Case {
    pub fn name(self) -> &'static str {
        match self {
            Case::Flat => "flat",
            Case::Edge => "edge",
            Case::Corner => "corner",
        }
    }
}

/// Seed 003's precision of the position: `Σuv = σn² N⁻¹`, its eigenvalues
/// and the threshold test `λmax(Σuv) ≤ T²`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Precision {
    /// `λmax(Σuv) = σn² / λmin(N)` in px²; `None` (infinite) when `λmin(N) = 0`.
    pub lambda_max_shift: Option<f64>,
    /// `λmin(Σuv) = σn² / λmax(N)` in px²; `None` when `N = 0`.
    pub lambda_min_shift: Option<f64>,
    /// Semi-axes of the standard error ellipse, `√λ` in px (major, minor).
    pub sigma_max: Option<f64>,
    pub sigma_min: Option<f64>,
    /// `λmax(Σuv) ≤ T²`.
    pub accepted: bool,
    /// Flat (both axes > T), edge (only the major axis > T) or corner.
    pub case: Case,
}

/// The precision of a window's position for noise `sigma_n` (grey values)
/// and threshold `threshold_px` (pixels), as seed 003 step 3.
pub fn precision(m: &Measures, sigma_n: f64, threshold_px: f64) -> Precision {
    let var = sigma_n * sigma_n;
    let lambda_max_shift = (m.lambda_min > 0.0).then(|| var / m.lambda_min);
    let lambda_min_shift = (m.lambda_max > 0.0).then(|| var / m.lambda_max);
    let t2 = threshold_px * threshold_px;
    let accepted = lambda_max_shift.is_some_and(|l| l <= t2);
    let case = if accepted {
        Case::Corner
    } else if lambda_min_shift.is_some_and(|l| l <= t2) {
        Case::Edge
    } else {
        Case::Flat
    };
    Precision {
        lambda_max_shift,
        lambda_min_shift,
        sigma_max: lambda_max_shift.map(f64::sqrt),
        sigma_min: lambda_min_shift.map(f64::sqrt),
        accepted,
        case,
    }
}

/// One interior pixel of the Moravec operator: the four directional
/// differences of seed 000 and the sum of their squares.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MoravecPixel {
    /// Column and row in the window, zero-based.
    pub c: usize,
    pub r: usize,
    pub g: f64,
    /// `[row, column, main diagonal, other diagonal]`:
    /// `g(c+1,r) − g(c−1,r)`, `g(c,r+1) − g(c,r−1)`,
    /// `g(c+1,r+1) − g(c−1,r−1)`, `g(c−1,r+1) − g(c+1,r−1)`.
    pub diffs: [f64; 4],
    /// The minuend and subtrahend of each difference.
    pub pairs: [(f64, f64); 4],
    /// `Σ diffs²`.
    pub sum: f64,
}

/// The Moravec operator of seed 000 on one window.
#[derive(Debug, Clone, PartialEq)]
pub struct Moravec {
    pub pixels: Vec<MoravecPixel>,
    /// The sums at the interior pixels, `(width − 2) × (height − 2)`.
    pub sums: Grid,
    /// The measure of distinctness: the mean of the sums.
    pub mean: f64,
}

/// The Moravec operator of seed 000 on a window of at least 3×3: at each
/// interior pixel the four directional differences across the pixel,
/// squared and summed; the mean of those sums over the interior.
pub fn moravec(window: &Grid) -> Result<Moravec> {
    check_window("window", window)?;
    let (wi, hi) = (window.width() - 2, window.height() - 2);
    let get = |c: usize, r: usize| {
        window
            .get(c, r)
            .ok_or_else(|| Error::Internal(format!("window pixel ({c}, {r}) missing")))
    };
    let mut pixels = Vec::with_capacity(wi * hi);
    for r in 1..=hi {
        for c in 1..=wi {
            let pairs = [
                (get(c + 1, r)?, get(c - 1, r)?),
                (get(c, r + 1)?, get(c, r - 1)?),
                (get(c + 1, r + 1)?, get(c - 1, r - 1)?),
                (get(c - 1, r + 1)?, get(c + 1, r - 1)?),
            ];
            let diffs = pairs.map(|(a, b)| a - b);
            let sum = diffs.iter().map(|d| d * d).sum();
            pixels.push(MoravecPixel {
                c,
                r,
                g: get(c, r)?,
                diffs,
                pairs,
                sum,
            });
        }
    }
    let sums = Grid::new("sums", wi, hi, pixels.iter().map(|p| p.sum).collect())?;
    let mean = sums.data().iter().sum::<f64>() / pixels.len() as f64;
    Ok(Moravec { pixels, sums, mean })
}

/// Offset of a window's reference pixel from its top-left corner:
/// `(size − 1) / 2` — the centre of an odd window (2 of 5, 3 of 7), the
/// top-left of the central 2×2 of an even one (1 of 4, 3 of 8).
pub fn anchor(size: usize) -> usize {
    size.saturating_sub(1) / 2
}

/// The `size × size` window whose reference pixel ([`anchor`]) is `(c, r)`,
/// if it lies wholly inside the image.
pub fn window_at(image: &Grid, c: usize, r: usize, size: usize) -> Option<Grid> {
    let a = anchor(size);
    if c < a || r < a {
        return None;
    }
    image.window(c - a, r - a, size, size)
}

fn check_map(image: &Grid, size: usize) -> Result<()> {
    if !(MIN_WINDOW..=MAX_WINDOW).contains(&size) {
        return Err(Error::input(
            "window_size",
            format!("must be between {MIN_WINDOW} and {MAX_WINDOW} (got {size})"),
        ));
    }
    if image.width() > MAX_IMAGE || image.height() > MAX_IMAGE {
        return Err(Error::input(
            "image",
            format!(
                "is {}×{}; at most {MAX_IMAGE}×{MAX_IMAGE} is allowed",
                image.height(),
                image.width()
            ),
        ));
    }
    if image.width() < size || image.height() < size {
        return Err(Error::input(
            "image",
            format!(
                "is {}×{}, smaller than the {size}×{size} window",
                image.height(),
                image.width()
            ),
        ));
    }
    Ok(())
}

/// A whole-image map: one value per pixel, `None` where the window does
/// not fit inside the image.
#[derive(Debug, Clone, PartialEq)]
pub struct Map<T> {
    pub width: usize,
    pub height: usize,
    pub size: usize,
    pub cells: Vec<Option<T>>,
}

impl<T: Copy> Map<T> {
    /// The value at `(c, r)`, `None` outside or where the window does not fit.
    pub fn get(&self, c: usize, r: usize) -> Option<T> {
        if c >= self.width || r >= self.height {
            return None;
        }
        self.cells.get(r * self.width + c).copied().flatten()
    }

    fn build(image: &Grid, size: usize, f: impl Fn(&Grid) -> Result<T>) -> Result<Self> {
        check_map(image, size)?;
        let (width, height) = (image.width(), image.height());
        let mut cells = Vec::with_capacity(width * height);
        for r in 0..height {
            for c in 0..width {
                cells.push(match window_at(image, c, r, size) {
                    Some(w) => Some(f(&w)?),
                    None => None,
                });
            }
        }
        Ok(Map {
            width,
            height,
            size,
            cells,
        })
    }
}

/// The Förstner measures of every pixel's `size × size` window (5 or 7 in
/// the seed): [`forstner`] on [`window_at`], nothing else.
pub fn forstner_map(image: &Grid, size: usize) -> Result<Map<Measures>> {
    Map::build(image, size, |w| forstner(w).map(|f| f.measures))
}

/// The Moravec mean of every pixel's `size × size` window (4 or 8 in the
/// seed): [`moravec`] on [`window_at`], nothing else.
pub fn moravec_map(image: &Grid, size: usize) -> Result<Map<f64>> {
    Map::build(image, size, |w| moravec(w).map(|m| m.mean))
}

/// Non-maximum suppression: the indices (row-major) of the cells whose
/// score is the largest within the `(2·radius + 1)²` neighbourhood, among
/// the cells that have a score. Of equal scores the first in row-major
/// order wins.
pub fn suppress(scores: &[Option<f64>], width: usize, height: usize, radius: usize) -> Vec<usize> {
    let mut kept = Vec::new();
    for r in 0..height {
        for c in 0..width {
            let i = r * width + c;
            let Some(s) = scores.get(i).copied().flatten() else {
                continue;
            };
            let mut best = true;
            'scan: for rr in r.saturating_sub(radius)..(r + radius + 1).min(height) {
                for cc in c.saturating_sub(radius)..(c + radius + 1).min(width) {
                    let j = rr * width + cc;
                    if j == i {
                        continue;
                    }
                    if let Some(t) = scores.get(j).copied().flatten() {
                        if t > s || (t == s && j < i) {
                            best = false;
                            break 'scan;
                        }
                    }
                }
            }
            if best {
                kept.push(i);
            }
        }
    }
    kept
}

/// A detected interest point (zero-based pixel) and its score.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InterestPoint {
    pub c: usize,
    pub r: usize,
    pub score: f64,
}

/// Thresholding and suppression of a map.
#[derive(Debug, Clone, PartialEq)]
pub struct Detection {
    /// The pixels that pass the threshold.
    pub candidates: Vec<InterestPoint>,
    /// The candidates left after non-maximum suppression.
    pub points: Vec<InterestPoint>,
    /// The suppression radius used (`size / 2`).
    pub radius: usize,
}

fn detect(scores: Vec<Option<f64>>, width: usize, height: usize, size: usize) -> Detection {
    let radius = size / 2;
    let point = |i: usize, s: f64| InterestPoint {
        c: i % width.max(1),
        r: i / width.max(1),
        score: s,
    };
    let candidates = scores
        .iter()
        .enumerate()
        .filter_map(|(i, s)| s.map(|s| point(i, s)))
        .collect();
    let points = suppress(&scores, width, height, radius)
        .into_iter()
        .filter_map(|i| scores.get(i).copied().flatten().map(|s| point(i, s)))
        .collect();
    Detection {
        candidates,
        points,
        radius,
    }
}

/// Seed 003 steps 3 and 4 on a Förstner map: keep the pixels with
/// `λmax(Σuv) ≤ T²` (and, optionally, roundness `q ≥ q_min`; 0 switches
/// that off), then within each `size × size` neighbourhood the one with
/// the smallest `λmax(Σuv)`. A point's score is `λmax(Σuv)` (px²).
pub fn forstner_points(
    map: &Map<Measures>,
    sigma_n: f64,
    threshold_px: f64,
    q_min: f64,
) -> Detection {
    // Suppression keeps maxima; the seed keeps the minimum of λmax(Σuv).
    let scores = map
        .cells
        .iter()
        .map(|m| {
            let m = (*m)?;
            let p = precision(&m, sigma_n, threshold_px);
            let round = q_min <= 0.0 || m.q.is_some_and(|q| q >= q_min);
            match (p.accepted && round, p.lambda_max_shift) {
                (true, Some(l)) => Some(-l),
                _ => None,
            }
        })
        .collect();
    let mut d = detect(scores, map.width, map.height, map.size);
    for p in d.candidates.iter_mut().chain(d.points.iter_mut()) {
        p.score = -p.score;
    }
    d
}

/// Seed 000's rule on a Moravec map: keep the pixels whose mean exceeds
/// `threshold`, then the largest within each `size × size` neighbourhood.
pub fn moravec_points(map: &Map<f64>, threshold: f64) -> Detection {
    let scores = map
        .cells
        .iter()
        .map(|m| m.filter(|&v| v > threshold))
        .collect();
    detect(scores, map.width, map.height, map.size)
}

/// A deterministic test pattern of `size × size` grey values (at least
/// 32): a flat background (40), a bright square (160) with four corners, a
/// long vertical edge (to 120), a diagonal edge (to 110), a checkerboard
/// X-corner (30/190), plus uniform noise of ± `noise` grey values from a
/// fixed generator (`seed`).
pub fn test_pattern(size: usize, noise: f64, seed: u64) -> Result<Grid> {
    let s = size as f64 / 64.0;
    let at = |x: f64| x * s;
    let mut state = seed ^ 0x9E37_79B9_7F4A_7C15;
    let mut next = move || {
        // xorshift64*: a fixed, portable sequence.
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        let x = state.wrapping_mul(0x2545_F491_4F6C_DD1D);
        (x >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut data = Vec::with_capacity(size * size);
    for r in 0..size {
        for c in 0..size {
            let (x, y) = (c as f64, r as f64);
            let mut g = 40.0;
            if x >= at(8.0) && x < at(24.0) && y >= at(8.0) && y < at(24.0) {
                g = 160.0;
            }
            if x >= at(46.0) && y < at(28.0) {
                g = 120.0;
            }
            if y - x > at(34.0) {
                g = 110.0;
            }
            if x >= at(36.0) && x < at(56.0) && y >= at(36.0) && y < at(56.0) {
                let right = x >= at(46.0);
                let low = y >= at(46.0);
                g = if right == low { 190.0 } else { 30.0 };
            }
            let n = (2.0 * next() - 1.0) * noise;
            data.push((g + n).round());
        }
    }
    Grid::new("image", size, size, data)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn central_difference_at_border_is_none() {
        let g = Grid::from_rows(
            "g",
            &[
                vec![1.0, 2.0, 4.0],
                vec![0.0, 5.0, 0.0],
                vec![3.0, 9.0, 3.0],
            ],
        )
        .unwrap();
        assert_eq!(central_difference(&g, 1, 1), Some((0.0, 3.5)));
        assert_eq!(central_difference(&g, 0, 1), None);
        assert_eq!(central_difference(&g, 2, 1), None);
        assert_eq!(central_difference(&g, 1, 2), None);
    }

    #[test]
    fn suppression_keeps_the_first_of_equal_maxima() {
        let s = [Some(1.0), Some(1.0), None, Some(0.5)];
        assert_eq!(suppress(&s, 4, 1, 1), vec![0, 3]);
    }

    #[test]
    fn anchors() {
        assert_eq!([anchor(4), anchor(5), anchor(7), anchor(8)], [1, 2, 3, 3]);
    }
}
