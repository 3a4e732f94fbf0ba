//! The lab's interest maps over a whole 8-bit image, row by row, with the
//! numbers of the window functions: the `size × size` windows of
//! [`crate::interest::window_at`] (reference pixel at
//! [`crate::interest::anchor`]), whose `(size − 2)²` interior pixels carry
//! the gradients, summed as exact integers by running column sums over a
//! ring of `size − 2` rows (no per-window work, no map of results kept).
//!
//! * [`forstner_rows`]: per window `Σdx²`, `Σdy²`, `Σdx·dy` of the central
//!   differences `dx = I(c+1, r) − I(c−1, r)`, `dy = I(c, r+1) − I(c, r−1)`
//!   ([`Sums4`]: four times the sums of `g′ = d/2` products, so
//!   [`Sums4::sums`] are the reference's `f64` sums bit for bit — every
//!   term `d²/4` and every partial sum is exact in `f64` — and
//!   [`Sums4::w_q`], [`Sums4::lambda_min`], [`Sums4::measures`] are
//!   [`crate::interest::Measures::from_sums`]'s numbers bit for bit).
//! * [`moravec_rows`]: per window the sum of the four squared directional
//!   differences of every interior pixel; `sum / (size − 2)²` in `f64` is
//!   [`crate::interest::moravec`]'s mean bit for bit.
//! * [`Suppressor`]: [`crate::interest::suppress`] fed one row of scores at
//!   a time, deciding a row once the `radius` rows below it are in (a ring
//!   of `2·radius + 1` rows).
//!
//! Windows that do not fit (the first `anchor` rows and columns, the last
//! `size − 1 − anchor`) have no value, as in the reference's maps.
//! `tests/web_fast.rs` ties all of it to the reference at every pixel.

use crate::error::{Error, Result};
use crate::interest::{anchor, Measures, Sums, MAX_WINDOW, MIN_WINDOW, SINGULAR_TOL};
use crate::raster::{Gray, GrayF32};

/// Where the `size × size` windows fit in a `width × height` image:
/// reference pixels `(c, r)` with `c0 ≤ c < c0 + columns`,
/// `r0 ≤ r < r0 + rows` (`c0 = r0 = anchor(size)`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fit {
    pub c0: usize,
    pub r0: usize,
    pub columns: usize,
    pub rows: usize,
}

/// The windows of `size` in `width × height` (error: a size outside
/// [`MIN_WINDOW`] … [`MAX_WINDOW`], or an image smaller than the window).
pub fn fit(width: usize, height: usize, size: usize) -> Result<Fit> {
    if !(MIN_WINDOW..=MAX_WINDOW).contains(&size) {
        return Err(Error::input(
            "window_size",
            format!("must be between {MIN_WINDOW} and {MAX_WINDOW} (got {size})"),
        ));
    }
    if width < size || height < size {
        return Err(Error::input(
            "image",
            format!("is {height}×{width}, smaller than the {size}×{size} window"),
        ));
    }
    Ok(Fit {
        c0: anchor(size),
        r0: anchor(size),
        columns: width - size + 1,
        rows: height - size + 1,
    })
}

/// Rows of real neighbours a window needs on each side of its reference
/// pixel, at most: `size − 1 − anchor(size)` (below and right; the
/// anchor above and left is never more).
pub fn reach(size: usize) -> usize {
    size.saturating_sub(1) - anchor(size)
}

/// The integers [`window_rows`] sums: `i32` for bytes' products, `i64`
/// for a colour photo's levels (`n < 2²⁴`: products up to 2⁴⁸).
trait Whole:
    Copy
    + Default
    + std::ops::Add<Output = Self>
    + std::ops::Sub<Output = Self>
    + std::ops::AddAssign
    + std::ops::SubAssign
    + std::iter::Sum
{
}
impl Whole for i32 {}
impl Whole for i64 {}

/// Window sums of `channels` per-pixel integer values over a `w × h`
/// image: `value(y, rows)` fills `rows[k][x]` for image row `y`
/// (`1 ≤ y ≤ h − 2`, columns `1 … w − 2`; the others are not read), and
/// `emit(r, sums)` gets, for every row `r` of the fit, `sums[k][j]` = the
/// sum over the interior of the window whose reference pixel is
/// `(fit.c0 + j, r)`.
fn window_rows<T: Whole>(
    (w, h): (usize, usize),
    size: usize,
    channels: usize,
    mut value: impl FnMut(usize, &mut [Vec<T>]),
    mut emit: impl FnMut(usize, &[Vec<T>]),
) -> Result<Fit> {
    let f = fit(w, h, size)?;
    let k = size - 2;
    // ring of k value rows (slot y % k), column sums over the k rows of
    // the current windows, the window sums of one output row
    let mut ring = vec![vec![vec![T::default(); w]; channels]; k];
    let mut col = vec![vec![T::default(); w]; channels];
    let mut out = vec![vec![T::default(); f.columns]; channels];
    // out[j] = Σ cs[j + 1 … j + k]: a running sum, the entering and
    // leaving columns as two slices of equal length (no index checks)
    let horizontal = |col: &[Vec<T>], out: &mut [Vec<T>]| {
        for (cs, o) in col.iter().zip(out.iter_mut()) {
            let Some((first, rest)) = o.split_first_mut() else {
                continue;
            };
            let mut s: T = cs.iter().skip(1).take(k).copied().sum();
            *first = s;
            let n = rest.len();
            let (enter, leave) = (&cs[k + 1..k + 1 + n], &cs[1..1 + n]);
            for ((ov, &e), &l) in rest.iter_mut().zip(enter).zip(leave) {
                s += e - l;
                *ov = s;
            }
        }
    };
    for y in 1..=k {
        let slot = &mut ring[y % k];
        value(y, slot);
        for (c, s) in col.iter_mut().zip(slot.iter()) {
            for (a, &b) in c.iter_mut().zip(s) {
                *a += b;
            }
        }
    }
    horizontal(&col, &mut out);
    emit(f.r0, &out);
    for i in 1..f.rows {
        // the window of output row i covers value rows i + 1 … i + k: row i
        // leaves (its slot is the new row's), row i + k enters
        let y = i + k;
        let slot = &mut ring[y % k];
        for (c, s) in col.iter_mut().zip(slot.iter()) {
            for (a, &b) in c.iter_mut().zip(s) {
                *a -= b;
            }
        }
        value(y, slot);
        for (c, s) in col.iter_mut().zip(slot.iter()) {
            for (a, &b) in c.iter_mut().zip(s) {
                *a += b;
            }
        }
        horizontal(&col, &mut out);
        emit(f.r0 + i, &out);
    }
    Ok(f)
}

/// The three rows `y − 1`, `y`, `y + 1` of an image (`1 ≤ y ≤ h − 2`).
fn three_rows<'a>(img: &Gray<'a>, y: usize) -> (&'a [u8], &'a [u8], &'a [u8]) {
    let row = |i: usize| img.row(i).unwrap_or(&[]);
    (row(y - 1), row(y), row(y + 1))
}

/// Four times the Förstner sums of one window: `Σdx²`, `Σdy²`, `Σdx·dy`
/// of the central differences (integers; `g′ = d/2`).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Sums4 {
    pub xx: i32,
    pub yy: i32,
    pub xy: i32,
}

impl Sums4 {
    /// `Σg′x²`, `Σg′y²`, `Σg′xg′y` exactly (`Σg′x`, `Σg′y` are not kept: 0).
    pub fn sums(self) -> Sums {
        Sums {
            gx2: f64::from(self.xx) / 4.0,
            gy2: f64::from(self.yy) / 4.0,
            gxgy: f64::from(self.xy) / 4.0,
            ..Sums::default()
        }
    }

    /// `Measures::from_sums` of these sums over `m` gradient pixels.
    pub fn measures(self, m: usize) -> Measures {
        Measures::from_sums(&self.sums(), m)
    }

    /// `(trace, det, singular)` as `Measures::from_sums` computes them.
    fn trace_det(self) -> (f64, f64, bool) {
        let s = self.sums();
        let (a, b, d) = (s.gx2, s.gxgy, s.gy2);
        let trace = a + d;
        let det_raw = a * d - b * b;
        let singular = trace <= 0.0 || det_raw <= SINGULAR_TOL * trace * trace;
        (trace, if singular { 0.0 } else { det_raw }, singular)
    }

    /// Förstner's `w` and `q` (`NaN` where `q` has none: `N = 0`), the
    /// bits of `Measures::from_sums`'s `w` and `q`.
    pub fn w_q(self) -> (f64, f64) {
        let (trace, det, singular) = self.trace_det();
        let w = if singular { 0.0 } else { det / trace };
        let q = if trace > 0.0 {
            4.0 * det / (trace * trace)
        } else {
            f64::NAN
        };
        (w, q)
    }

    /// `16·det N` and `4·trace N` as exact integers (no singular rule).
    pub fn det_trace(self) -> (i64, i64) {
        let (a, d, b) = (i64::from(self.xx), i64::from(self.yy), i64::from(self.xy));
        (a * d - b * b, a + d)
    }

    /// `λmin(N)` with `√(x² + y²)` for `hypot`: within 10⁻¹⁴ (relative) of
    /// [`Sums4::lambda_min`], for a first sort.
    pub fn lambda_min_approx(self) -> f64 {
        let (trace, det, singular) = self.trace_det();
        let s = self.sums();
        let x = (s.gx2 - s.gy2) / 2.0;
        let lambda_max = trace / 2.0 + (x * x + s.gxgy * s.gxgy).sqrt();
        if singular || lambda_max <= 0.0 {
            0.0
        } else {
            det / lambda_max
        }
    }

    /// The sums of the `size × size` window whose reference pixel is
    /// `(c, r)`, from its own pixels (one window; `None` where it does not
    /// fit).
    pub fn at(img: &Gray, size: usize, c: usize, r: usize) -> Option<Sums4> {
        let a = anchor(size);
        let (c0, r0) = (c.checked_sub(a)?, r.checked_sub(a)?);
        if size < MIN_WINDOW || c0 + size > img.width() || r0 + size > img.height() {
            return None;
        }
        let px = |x: usize, y: usize| {
            i32::from(img.row(y).and_then(|row| row.get(x).copied()).unwrap_or(0))
        };
        let mut s = Sums4::default();
        for y in r0 + 1..r0 + size - 1 {
            for x in c0 + 1..c0 + size - 1 {
                let dx = px(x + 1, y) - px(x - 1, y);
                let dy = px(x, y + 1) - px(x, y - 1);
                s.xx += dx * dx;
                s.yy += dy * dy;
                s.xy += dx * dy;
            }
        }
        Some(s)
    }

    /// `λmin(N)`, the bits of `Measures::from_sums`'s `lambda_min`.
    pub fn lambda_min(self) -> f64 {
        let (trace, det, singular) = self.trace_det();
        let s = self.sums();
        let root = ((s.gx2 - s.gy2) / 2.0).hypot(s.gxgy);
        let lambda_max = trace / 2.0 + root;
        if singular || lambda_max <= 0.0 {
            0.0
        } else {
            det / lambda_max
        }
    }
}

/// [`Sums4::w_q`] of a row of windows, rounded to `f32`: the same
/// operations on the same values (so the same bits), written with selects
/// instead of branches so that the compiler vectorises the loop.
pub fn w_q_row(xx: &[i32], yy: &[i32], xy: &[i32], w_out: &mut [f32], q_out: &mut [f32]) {
    let n = xx
        .len()
        .min(yy.len())
        .min(xy.len())
        .min(w_out.len())
        .min(q_out.len());
    let (xx, yy, xy) = (&xx[..n], &yy[..n], &xy[..n]);
    let (w_out, q_out) = (&mut w_out[..n], &mut q_out[..n]);
    for i in 0..n {
        let (a, d, b) = (
            f64::from(xx[i]) / 4.0,
            f64::from(yy[i]) / 4.0,
            f64::from(xy[i]) / 4.0,
        );
        let trace = a + d;
        let det_raw = a * d - b * b;
        let singular = trace <= 0.0 || det_raw <= SINGULAR_TOL * trace * trace;
        let det = if singular { 0.0 } else { det_raw };
        let w = det / trace;
        let q = 4.0 * det / (trace * trace);
        w_out[i] = (if singular { 0.0 } else { w }) as f32;
        q_out[i] = (if trace > 0.0 { q } else { f64::NAN }) as f32;
    }
}

/// Förstner's window sums for every `size × size` window of `img` that
/// fits ([`fit`]): `emit(r, xx, yy, xy)` per row `r` of the fit, entry `j`
/// for the window at column `fit.c0 + j` (see [`Sums4`]).
pub fn forstner_rows(
    img: Gray,
    size: usize,
    mut emit: impl FnMut(usize, &[i32], &[i32], &[i32]),
) -> Result<Fit> {
    window_rows(
        (img.width(), img.height()),
        size,
        3,
        |y, rows| {
            let (up, mid, down) = three_rows(&img, y);
            let n = mid.len().saturating_sub(2);
            if let [xx, yy, xy] = rows {
                let (xx, yy, xy) = (&mut xx[1..=n], &mut yy[1..=n], &mut xy[1..=n]);
                let (r, l, d, u) = (&mid[2..2 + n], &mid[..n], &down[1..=n], &up[1..=n]);
                for i in 0..n {
                    let dx = i32::from(r[i]) - i32::from(l[i]);
                    let dy = i32::from(d[i]) - i32::from(u[i]);
                    xx[i] = dx * dx;
                    yy[i] = dy * dy;
                    xy[i] = dx * dy;
                }
            }
        },
        |r, s| {
            if let [xx, yy, xy] = s {
                emit(r, xx, yy, xy);
            }
        },
    )
}

/// One row of Moravec's per-pixel sums: for image column `i + 1` of the
/// rows `[up, mid, down]`, the four squared differences across it (row,
/// column, both diagonals) in `s[i + 1]`, each level widened by `whole`
/// first (bytes in `i32`, which the compiler vectorises; levels in `i64`).
fn moravec_row<L: Copy, T: Whole + std::ops::Mul<Output = T>>(
    [up, mid, down]: [&[L]; 3],
    s: &mut [T],
    whole: impl Fn(L) -> T,
) {
    let n = mid.len().saturating_sub(2);
    let s = &mut s[1..=n];
    let sq = |a: L, b: L| {
        let d = whole(a) - whole(b);
        d * d
    };
    // image column i + 1: its neighbours i, i + 1, i + 2
    let (ml, mr) = (&mid[..n], &mid[2..2 + n]);
    let (ul, uc, ur) = (&up[..n], &up[1..=n], &up[2..2 + n]);
    let (dl, dc, dr) = (&down[..n], &down[1..=n], &down[2..2 + n]);
    for i in 0..n {
        s[i] = sq(mr[i], ml[i]) + sq(dc[i], uc[i]) + sq(dr[i], ul[i]) + sq(dl[i], ur[i]);
    }
}

/// Moravec's window sums for every `size × size` window that fits: per
/// interior pixel `Σ` of the four squared differences across it (row,
/// column, both diagonals, as [`crate::interest::moravec`]), summed over
/// the window's interior; `emit(r, sums)` as in [`forstner_rows`]. The
/// reference's mean is `sum as f64 / ((size − 2)² as f64)`.
pub fn moravec_rows(img: Gray, size: usize, mut emit: impl FnMut(usize, &[i32])) -> Result<Fit> {
    window_rows(
        (img.width(), img.height()),
        size,
        1,
        |y, rows| {
            let (up, mid, down) = three_rows(&img, y);
            if let [s] = rows {
                moravec_row([up, mid, down], s, i32::from);
            }
        },
        |r, s| {
            if let [s] = s {
                emit(r, s);
            }
        },
    )
}

/// The three rows `y − 1`, `y`, `y + 1` of levels as whole numbers
/// (`1 ≤ y ≤ h − 2`; every level an integer below 2²⁴, exact in `i64`).
fn three_levels(img: &GrayF32, y: usize, rows: &mut [Vec<i64>; 3]) {
    for (k, row) in rows.iter_mut().enumerate() {
        let src = img.row(y + k - 1).unwrap_or(&[]);
        row.clear();
        row.extend(src.iter().map(|&v| v as i64));
    }
}

/// [`forstner_rows`] of a [`GrayF32`] of whole-number levels (a colour
/// photo's `n = scale · grey`, each below 2²⁴): the same integer sums of
/// the levels' central differences, in `i64` (they pass 2³¹).
pub fn forstner_rows_levels(
    img: GrayF32,
    size: usize,
    mut emit: impl FnMut(usize, &[i64], &[i64], &[i64]),
) -> Result<Fit> {
    let mut three: [Vec<i64>; 3] = Default::default();
    window_rows(
        (img.width(), img.height()),
        size,
        3,
        |y, rows| {
            three_levels(&img, y, &mut three);
            let [up, mid, down] = &three;
            let n = mid.len().saturating_sub(2);
            if let [xx, yy, xy] = rows {
                let (xx, yy, xy) = (&mut xx[1..=n], &mut yy[1..=n], &mut xy[1..=n]);
                let (r, l, d, u) = (&mid[2..2 + n], &mid[..n], &down[1..=n], &up[1..=n]);
                for i in 0..n {
                    let dx = r[i] - l[i];
                    let dy = d[i] - u[i];
                    xx[i] = dx * dx;
                    yy[i] = dy * dy;
                    xy[i] = dx * dy;
                }
            }
        },
        |r, s| {
            if let [xx, yy, xy] = s {
                emit(r, xx, yy, xy);
            }
        },
    )
}

/// [`moravec_rows`] of a [`GrayF32`] of whole-number levels, in `i64`.
pub fn moravec_rows_levels(
    img: GrayF32,
    size: usize,
    mut emit: impl FnMut(usize, &[i64]),
) -> Result<Fit> {
    let mut three: [Vec<i64>; 3] = Default::default();
    window_rows(
        (img.width(), img.height()),
        size,
        1,
        |y, rows| {
            three_levels(&img, y, &mut three);
            let [up, mid, down] = &three;
            if let [s] = rows {
                moravec_row([up, mid, down], s, |v| v);
            }
        },
        |r, s| {
            if let [s] = s {
                emit(r, s);
            }
        },
    )
}

/// [`crate::interest::suppress`] one row at a time: push the score rows
/// `0, 1, 2, …` of a `width × height` map in order (`NaN`: no score), each
/// with a payload per cell; a cell is kept when no cell of its
/// `(2·radius + 1)²` neighbourhood scores higher, or the same and comes
/// first in row-major order — the reference's rule. Kept cells are
/// reported as `(c, r, score, payload)` in row-major order, each row once
/// the `radius` rows below it are in ([`Suppressor::finish`] decides the
/// last ones).
///
/// With [`Suppressor::refined`] the pushed scores may be approximations
/// (within a quarter of `tol`, relative): two scores closer than `tol` are
/// compared by `exact(payload)` instead, so the decisions are the exact
/// scores' (the reported score is the pushed one).
pub struct Suppressor<'e, P> {
    width: usize,
    height: usize,
    radius: usize,
    /// `(row, scores, payloads)` in slot `row % (2·radius + 1)`.
    ring: Vec<(Option<usize>, Vec<f64>, Vec<P>)>,
    /// Per slot, the largest score within `radius` columns of each cell
    /// (`−∞` where none): a cell below a neighbour's beyond the tolerance
    /// is out without a closer look.
    near: Vec<Vec<f64>>,
    /// A row of scratch for `near`.
    scratch: Vec<f64>,
    /// Scratch for `decide`: the largest `near` over the rows of a
    /// cell's neighbourhood, and the columns that need a closer look.
    column_max: Vec<f64>,
    open: Vec<usize>,
    pushed: usize,
    decided: usize,
    refine: Option<Refine<'e, P>>,
}

/// [`Suppressor::refined`]'s tolerance and exact score.
type Refine<'e, P> = (f64, Box<dyn Fn(&P) -> f64 + 'e>);

impl<'e, P: Copy + Default> Suppressor<'e, P> {
    pub fn new(width: usize, height: usize, radius: usize) -> Self {
        let n = 2 * radius + 1;
        Suppressor {
            width,
            height,
            radius,
            ring: (0..n)
                .map(|_| (None, vec![f64::NAN; width], vec![P::default(); width]))
                .collect(),
            near: vec![vec![f64::NEG_INFINITY; width]; n],
            scratch: vec![0.0; width],
            column_max: vec![f64::NEG_INFINITY; width],
            open: vec![0; width],
            pushed: 0,
            decided: 0,
            refine: None,
        }
    }

    /// Scores closer than `tol` (relative) compared by `exact(payload)`.
    pub fn refined(mut self, tol: f64, exact: impl Fn(&P) -> f64 + 'e) -> Self {
        self.refine = Some((tol, Box::new(exact)));
        self
    }

    /// The next row's scores and payloads (`width` each; fewer are padded
    /// with no score); rows past `height` are ignored.
    pub fn push(
        &mut self,
        scores: impl IntoIterator<Item = (f64, P)>,
        kept: &mut impl FnMut(usize, usize, f64, P),
    ) {
        self.push_with(
            |s, p| {
                for ((sv, pv), (so, po)) in scores.into_iter().zip(s.iter_mut().zip(p.iter_mut())) {
                    *so = sv;
                    *po = pv;
                }
            },
            kept,
        );
    }

    /// The next row written in place: `fill(scores, payloads)` gets the
    /// row's slots (`width` each, scores `NaN` to start with).
    pub fn push_with(
        &mut self,
        fill: impl FnOnce(&mut [f64], &mut [P]),
        kept: &mut impl FnMut(usize, usize, f64, P),
    ) {
        if self.pushed >= self.height {
            return;
        }
        let n = self.ring.len();
        let (tag, s, p) = &mut self.ring[self.pushed % n];
        *tag = Some(self.pushed);
        s.fill(f64::NAN);
        fill(s, p);
        // the row's largest score within `radius` columns
        widen(
            &mut self.near[self.pushed % n],
            s,
            &mut self.scratch,
            self.radius,
        );
        self.pushed += 1;
        while self.decided + self.radius < self.pushed {
            self.decide(kept);
        }
    }

    /// Rows of no scores up to row `r` (the rows before a map's first
    /// window; none when `r` is already pushed).
    pub fn skip_to(&mut self, r: usize, kept: &mut impl FnMut(usize, usize, f64, P)) {
        while self.pushed < r.min(self.height) {
            self.push_empty(kept);
        }
    }

    /// A row of no scores.
    pub fn push_empty(&mut self, kept: &mut impl FnMut(usize, usize, f64, P)) {
        self.push(std::iter::empty(), kept);
    }

    /// Decides the rows still open (after the last row is pushed; rows
    /// never pushed have no scores).
    pub fn finish(&mut self, kept: &mut impl FnMut(usize, usize, f64, P)) {
        while self.decided < self.pushed {
            self.decide(kept);
        }
    }

    fn row(&self, r: usize) -> Option<(&[f64], &[P])> {
        let (tag, s, p) = self.ring.get(r % self.ring.len())?;
        (*tag == Some(r)).then_some((&s[..], &p[..]))
    }

    /// Whether `t` (payload `pt`) beats `s` (payload `ps`): higher, or the
    /// same and `earlier` in row-major order.
    fn beats(&self, t: f64, pt: &P, s: f64, ps: &P, earlier: bool) -> bool {
        let (t, s) = match &self.refine {
            Some((tol, exact)) if (t - s).abs() <= tol * t.abs().max(s.abs()) => {
                (exact(pt), exact(ps))
            }
            _ => (t, s),
        };
        t > s || (earlier && t == s)
    }

    fn decide(&mut self, kept: &mut impl FnMut(usize, usize, f64, P)) {
        let r = self.decided;
        self.decided += 1;
        let (w, rad) = (self.width, self.radius);
        let n = self.ring.len();
        // scores below `s − margin` never beat `s` (nor NaN): no closer look
        let tol = self.refine.as_ref().map_or(0.0, |(t, _)| 2.0 * t);
        let (lo, hi) = (r.saturating_sub(rad), (r + rad + 1).min(self.pushed));
        if self.row(r).is_none() {
            return;
        }
        // a neighbour higher beyond the tolerance: out at once. Found for
        // the whole row without a branch per cell (the largest `near` over
        // the neighbourhood's rows, then the columns left written down):
        // on a noisy photo which cells are out is a coin toss per cell
        let mut column_max = std::mem::take(&mut self.column_max);
        let mut open = std::mem::take(&mut self.open);
        column_max.fill(f64::NEG_INFINITY);
        for rr in lo..hi {
            if self.row(rr).is_some() {
                for (m, &t) in column_max.iter_mut().zip(&self.near[rr % n]) {
                    *m = if t > *m { t } else { *m };
                }
            }
        }
        let (scores, payload) = self.row(r).unwrap_or_default();
        let mut k = 0;
        for (c, (&s, &m)) in scores.iter().zip(&column_max).enumerate() {
            // (NaN: no score; `near` is never NaN)
            let out = s.is_nan() || m > s + tol * s.abs();
            if let Some(o) = open.get_mut(k) {
                *o = c;
            }
            k += usize::from(!out);
        }
        let rows: Vec<(usize, &[f64], &[P])> = (lo..hi)
            .filter_map(|rr| self.row(rr).map(|(row, pay)| (rr, row, pay)))
            .collect();
        for &c in &open[..k] {
            let s = scores[c];
            let floor = s - tol * s.abs();
            let ps = &payload[c];
            let (c0, c1) = (c.saturating_sub(rad), (c + rad + 1).min(w));
            let mut best = true;
            'scan: for &(rr, row, pay) in &rows {
                for cc in c0..c1 {
                    let t = row[cc];
                    // (NaN, no score: never ≥)
                    let lower = t.partial_cmp(&floor).is_none_or(|o| o.is_lt());
                    if lower || (rr == r && cc == c) {
                        continue;
                    }
                    let earlier = rr < r || (rr == r && cc < c);
                    if self.beats(t, &pay[cc], s, ps, earlier) {
                        best = false;
                        break 'scan;
                    }
                }
            }
            if best {
                kept(c, r, s, *ps);
            }
        }
        drop(rows);
        self.column_max = column_max;
        self.open = open;
    }
}

/// `near[c]` = the largest of `s[c − radius … c + radius]` (NaN, no score:
/// −∞), by element-wise selects over shifted slices (vectorised).
fn widen(near: &mut [f64], s: &[f64], prev: &mut [f64], radius: usize) {
    for (m, &t) in near.iter_mut().zip(s.iter()) {
        *m = if t.is_nan() { f64::NEG_INFINITY } else { t };
    }
    let w = near.len();
    for _ in 0..radius.min(w) {
        prev.copy_from_slice(near);
        let (left, right) = (&prev[..w - 1], &prev[1..]);
        for (m, &t) in near[1..].iter_mut().zip(left) {
            *m = if t > *m { t } else { *m };
        }
        for (m, &t) in near[..w - 1].iter_mut().zip(right) {
            *m = if t > *m { t } else { *m };
        }
    }
}
