//! Förstner's operator on a colour photo's levels (`ops::Levels`: each grey
//! `n / scale`, `n` a whole number below 2²⁴): the window sums of the
//! levels' central differences exact in `i64`
//! (`stream::forstner_rows_levels`), divided by `4·scale²` — within
//! `Levels::sum_slack` (relative) of the reference's `f64` sums of the
//! divided greys. The `w` and `q` layers are those sums' numbers rounded to
//! `f32`; every decision of seed 003 (singular, round, `λmax(Σuv) ≤ T²`,
//! the suppression's comparisons) is taken on them only where they are
//! farther from the bound than their error can reach, and otherwise on the
//! reference's own window ([`exact_measures`]: the reference's sums in its
//! order, `Measures::from_sums`), so the points, their scores, their
//! ellipses and the automatic threshold's `w_min` are the reference's.

use super::*;
use photogrammetry_playground::interest::{Sums, SINGULAR_TOL};

/// The reference's measures of the `size × size` window whose reference
/// pixel is `(c, r)`: `interest::forstner`'s sums of `g′x = (right − left)/2`,
/// `g′y = (down − up)/2` of the greys `n / scale`, in its row-major order,
/// then `Measures::from_sums` (the same numbers, no window copied).
pub fn exact_measures(
    lv: &Levels,
    width: usize,
    size: usize,
    c: usize,
    r: usize,
) -> Option<Measures> {
    let a = interest::anchor(size);
    let (c0, r0) = (c.checked_sub(a)?, r.checked_sub(a)?);
    if size < 3 || c0 + size > width || (r0 + size) * width > lv.data.len() {
        return None;
    }
    let g = |x: usize, y: usize| f64::from(lv.data[y * width + x]) / lv.scale;
    let mut s = Sums::default();
    for y in r0 + 1..r0 + size - 1 {
        for x in c0 + 1..c0 + size - 1 {
            let gx = (g(x + 1, y) - g(x - 1, y)) / 2.0;
            let gy = (g(x, y + 1) - g(x, y - 1)) / 2.0;
            s.gx += gx;
            s.gy += gy;
            s.gxgy += gx * gy;
            s.gx2 += gx * gx;
            s.gy2 += gy * gy;
        }
    }
    Some(Measures::from_sums(&s, (size - 2) * (size - 2)))
}

/// Seed 003's score of a window from its measures: `−λmax(Σuv)` when it
/// is round and `λmax(Σuv) = σn²/λmin ≤ limit`, NaN otherwise (the
/// reference route's test).
fn score_of(m: &Measures, var: f64, q_min: f64, limit: f64) -> f64 {
    let round = q_min <= 0.0 || m.q.is_some_and(|q| q >= q_min);
    let l = var / m.lambda_min;
    if round && m.lambda_min > 0.0 && l <= limit {
        -l
    } else {
        f64::NAN
    }
}

/// One window's sums in the reference's units (`Σg′x²`, `Σg′y²`,
/// `Σg′xg′y`) and the bound on their distance from the reference's.
#[derive(Clone, Copy)]
struct Approx {
    a: f64,
    d: f64,
    b: f64,
    /// `|det − det′|` at most (`det′` the reference's `a′d′ − b′²`).
    e_det: f64,
    /// relative distance of `a`, `d`, `trace` from the reference's.
    slack: f64,
}

impl Approx {
    fn new(xx: i64, yy: i64, xy: i64, unit: f64, slack: f64) -> Self {
        let (a, d, b) = (xx as f64 / unit, yy as f64 / unit, xy as f64 / unit);
        let t = a + d;
        // |a − a′| ≤ s·a, |d − d′| ≤ s·d, |b − b′| ≤ s·(a + d)/2 (|g′x g′y| ≤
        // (g′x² + g′y²)/2): |ad − a′d′| + |b² − b′²| ≤ 3s·t² (s ≪ 1), and the
        // products' own roundings
        let e_det = (4.0 * slack + 1e-15) * t * t;
        Approx {
            a,
            d,
            b,
            e_det,
            slack,
        }
    }

    fn trace(&self) -> f64 {
        self.a + self.d
    }

    /// `(w, q)` as `Measures::from_sums` computes them from these sums.
    fn w_q(&self) -> (f64, f64) {
        let t = self.trace();
        let det_raw = self.a * self.d - self.b * self.b;
        let singular = t <= 0.0 || det_raw <= SINGULAR_TOL * t * t;
        let det = if singular { 0.0 } else { det_raw };
        let w = if singular { 0.0 } else { det / t };
        let q = if t > 0.0 {
            4.0 * det / (t * t)
        } else {
            f64::NAN
        };
        (w, q)
    }

    /// The score when these sums decide it beyond their error: `Some(score)`
    /// (NaN: no candidate), `None` when only the reference's window can
    /// tell (near a bound, or too uncertain: the suppression compares the
    /// scores within [`TOL`] / 4 of the exact ones).
    fn score(&self, var: f64, q_min: f64, limit: f64) -> Option<f64> {
        let (a, d, b, e, s) = (self.a, self.d, self.b, self.e_det, self.slack);
        let t = a + d;
        if t <= 0.0 {
            // every difference 0: the reference's sums are 0 too (singular)
            return Some(f64::NAN);
        }
        let t2 = t * t;
        let det = a * d - b * b;
        // singular: det′ ≤ SINGULAR_TOL·t′²
        let sing = SINGULAR_TOL * t2;
        if (det - sing).abs() <= e + 3.0 * s * sing {
            return None;
        }
        if det < sing {
            return Some(f64::NAN);
        }
        if det <= 4.0 * e {
            return None;
        }
        // λmax(Σuv) = σn²·λmax/det; its relative error
        let x = (a - d) / 2.0;
        let l = var * (t / 2.0 + (x * x + b * b).sqrt()) / det;
        let rel = e / det + 4.0 * s + 1e-14;
        if rel > TOL / 8.0 || (l - limit).abs() <= 2.0 * rel * limit {
            return None;
        }
        if q_min > 0.0 {
            let qd = 4.0 * det - q_min * t2;
            if qd.abs() <= 4.0 * e + 3.0 * s * q_min * t2 + 1e-14 * q_min * t2 {
                return None;
            }
            if qd < 0.0 {
                return Some(f64::NAN);
            }
        }
        Some(if l <= limit { -l } else { f64::NAN })
    }
}

/// The suppression's tolerance on a colour photo: approximate scores are
/// within `TOL / 8` of the reference's (else the reference's are pushed),
/// and two within `TOL` of each other are compared by the reference's.
const TOL: f64 = 1e-6;

/// `w` and `q` layers of the levels `lv` (`width × height`) and, with
/// `detect = (σn, q_min, limit)`, the local maxima of seed 003's candidates
/// (the reference's; their `λmax(Σuv)` within `TOL` / 8 of the exact one).
pub(super) fn build(
    lv: &Levels,
    width: usize,
    height: usize,
    size: usize,
    detect: Option<(f64, f64, f64)>,
) -> Result<(Vec<Layer>, stream::Fit, Option<Vec<Maximum>>)> {
    let view = lv
        .view(width, height)
        .ok_or_else(|| Error::input("image", "has levels of another size"))?;
    let m = (size.max(2) - 2) * (size.max(2) - 2);
    let unit = 4.0 * lv.scale * lv.scale;
    let slack = lv.sum_slack(m);
    let a0 = interest::anchor(size);
    let mut wl = vec![f32::NAN; width * height];
    let mut ql = vec![f32::NAN; width * height];
    let var = detect.map_or(0.0, |(s, _, _)| s * s);
    let (q_min, limit) = detect.map_or((0.0, 0.0), |(_, q, l)| (q, l));
    let exact = |&(c, r): &(usize, usize)| {
        exact_measures(lv, width, size, c, r).map_or(f64::NAN, |m| score_of(&m, var, q_min, limit))
    };
    let mut sup = detect.map(|_| Suppressor::new(width, height, size / 2).refined(TOL, exact));
    let mut maxima = Vec::new();
    let mut keep = |c: usize, r: usize, s: f64, _: (usize, usize)| maxima.push((c, r, s));
    let mut row = vec![(f64::NAN, (0usize, 0usize)); width];
    let mut next = 0;
    let fit = stream::forstner_rows_levels(view, size, |r, xx, yy, xy| {
        let c0 = r * width + a0;
        let n = xx.len().min(yy.len()).min(xy.len());
        let (wo, qo) = (&mut wl[c0..c0 + n], &mut ql[c0..c0 + n]);
        for i in 0..n {
            let s = Approx::new(xx[i], yy[i], xy[i], unit, slack);
            let (w, q) = s.w_q();
            wo[i] = w as f32;
            qo[i] = q as f32;
            if sup.is_some() {
                let p = (a0 + i, r);
                row[a0 + i] = (s.score(var, q_min, limit).unwrap_or_else(|| exact(&p)), p);
            }
        }
        if let Some(sup) = sup.as_mut() {
            while next < r {
                sup.push_empty(&mut keep);
                next += 1;
            }
            sup.push(row.iter().copied(), &mut keep);
            next = r + 1;
        }
    })?;
    if let Some(mut sup) = sup {
        while next < height {
            sup.push_empty(&mut keep);
            next += 1;
        }
        sup.finish(&mut keep);
    }
    let maxima = detect.map(|_| {
        maxima
            .into_iter()
            .map(|(c, r, s)| Maximum {
                c,
                r,
                lambda: -s,
                sums: None,
            })
            .collect()
    });
    let layers = vec![
        Layer::new("w", whole(width, height), wl, false),
        Layer::new("q", whole(width, height), ql, false),
    ];
    Ok((layers, fit, maxima))
}

/// `w_min` (the `w` of rank [`top_rank`] among the windows that fit) of the
/// levels `lv` from their `w` layer `wl` (this module's, or the pool's
/// bands' put together): the layer's value `v` of that rank; the windows
/// whose layer value lies within one bound for all windows (from the
/// largest trace the photo's levels allow) of `[v(1 − 10⁻⁶), v(1 + 10⁻⁶)]`
/// recomputed by the reference's window; the value of the rank among them
/// when it lies in that range (then it is the reference's). Else the same
/// with each window's own bound from its sums (a pass over the levels),
/// and else every window's reference `w` (`lab/tests/auto_threshold.rs`
/// reaches both: a periodic photo, a layer that is not the photo's).
pub fn levels_w_min(
    lv: &Levels,
    width: usize,
    height: usize,
    size: usize,
    wl: &[f32],
) -> Option<f64> {
    let fit = stream::fit(width, height, size).ok()?;
    let view = lv.view(width, height)?;
    let cells = |r: usize| {
        wl.get(r * width + fit.c0..r * width + fit.c0 + fit.columns)
            .unwrap_or(&[])
    };
    let mut all: Vec<f32> = (fit.r0..fit.r0 + fit.rows)
        .flat_map(cells)
        .copied()
        .collect();
    if all.is_empty() || all.iter().any(|v| v.is_nan()) {
        return None;
    }
    let k = top_rank(all.len());
    let v = f64::from(*all.select_nth_unstable_by(k, f32::total_cmp).1);
    drop(all);
    let (lo, hi) = (v * (1.0 - 1e-6), v * (1.0 + 1e-6));
    let m = (size - 2) * (size - 2);
    let (unit, slack) = (4.0 * lv.scale * lv.scale, lv.sum_slack(m));
    // first from the layer alone, with one bound for every window: a
    // trace is at most m·(max/scale)²/2 (|g′| ≤ max/2), so a layer value
    // is within `e` of the reference's w (its f32 rounding included)
    let top = f64::from(lv.max) / lv.scale;
    let t_max = 1.01 * m as f64 * top * top / 2.0;
    let e = 2.0 * (4.0 * slack + 1e-15) * t_max
        + 4.0 * SINGULAR_TOL * t_max
        + 2.0 * (4.0 * slack + 1e-14 + 2f64.powi(-23)) * v;
    let (mut below, mut group) = (0, Vec::new());
    for r in fit.r0..fit.r0 + fit.rows {
        for (j, &x) in cells(r).iter().enumerate() {
            let x = f64::from(x);
            if x + e < lo {
                below += 1;
            } else if x - e <= hi {
                group.push((fit.c0 + j, r));
            }
        }
        if group.len() > 1 << 16 {
            break;
        }
    }
    if group.len() <= 1 << 16 {
        let mut exact: Vec<f64> = group
            .iter()
            .filter_map(|&(c, r)| exact_measures(lv, width, size, c, r).map(|m| m.w))
            .collect();
        exact.sort_by(f64::total_cmp);
        if let Some(&x) = k.checked_sub(below).and_then(|i| exact.get(i)) {
            if (lo..=hi).contains(&x) {
                return Some(x);
            }
        }
    }
    // (the bound of one window at a time: the sums again)
    let mut below = 0;
    let mut group = Vec::new();
    stream::forstner_rows_levels(view, size, |r, xx, yy, xy| {
        for (i, ((&x, &y), &z)) in xx.iter().zip(yy).zip(xy).enumerate() {
            let s = Approx::new(x, y, z, unit, slack);
            let w = s.w_q().0;
            // |w − w′| ≤ e_det/t′ + …: a bound from the sums
            let t = s.trace();
            // (and a singular rule decided the other way: w′ = 0 with w ≤ SINGULAR_TOL·t′ + e_det/t)
            let e = if t > 0.0 {
                2.0 * s.e_det / t + 4.0 * SINGULAR_TOL * t + 4.0 * slack * w + 1e-14 * w
            } else {
                0.0
            };
            if w + e < lo {
                below += 1;
            } else if w - e <= hi {
                group.push((fit.c0 + i, r));
            }
        }
    })
    .ok()?;
    let mut exact: Vec<f64> = group
        .iter()
        .filter_map(|&(c, r)| exact_measures(lv, width, size, c, r).map(|m| m.w))
        .collect();
    exact.sort_by(f64::total_cmp);
    match k.checked_sub(below).and_then(|i| exact.get(i)) {
        Some(&x) if (lo..=hi).contains(&x) => Some(x),
        _ => {
            let mut every: Vec<f64> = (fit.r0..fit.r0 + fit.rows)
                .flat_map(|r| (0..fit.columns).map(move |j| (fit.c0 + j, r)))
                .filter_map(|(c, r)| exact_measures(lv, width, size, c, r).map(|m| m.w))
                .collect();
            every.get(k)?;
            // sorted as `exact` is (one sort in the wasm, not a second selection)
            every.sort_by(f64::total_cmp);
            Some(every[k])
        }
    }
}
