//! Förstner's operator over a whole image: the `w` and `q` maps, seed 003's
//! threshold and suppression with error ellipses, and what is kept for a
//! live threshold (the slider re-thresholds the kept local maxima, it does
//! not recompute the map).
//!
//! On an 8-bit image everything comes from the core's row-by-row window
//! sums (`interest::fast::stream`): `w`, `q`, `λmin` and the measures of a
//! point are `Measures::from_sums`'s numbers bit for bit, the layers their
//! `f32` roundings, the points exactly the reference's (same candidates,
//! same scores, the same suppression rule row by row). A colour photo's
//! levels take the same sums in `i64` (`levels`: decisions near a bound by
//! the reference's own window, so the points are still the reference's).
//! Other images take the reference: `interest::forstner_map` and
//! `interest::forstner_points`.

use super::*;
use photogrammetry_playground::interest::fast::stream::{self, Sums4, Suppressor};
use photogrammetry_playground::interest::{self, Measures};

mod levels;
pub use levels::{exact_measures, levels_w_min};

/// Förstner's `w` and `q` layers and seed 003's points for one threshold
/// (`interest::forstner_map`, `interest::forstner_points`), each point with
/// its error ellipse `Σuv = σn²·N⁻¹`.
pub fn forstner<'a>(
    img: impl Into<Image<'a>>,
    size: usize,
    sigma_n: f64,
    threshold_px: f64,
    q_min: f64,
) -> Result<(Vec<Layer>, Vec<Point>)> {
    check_detect(sigma_n, threshold_px, q_min)?;
    let t2 = threshold_px * threshold_px;
    // the map and the suppression for this T in one pass over the image
    let mut kept = ForstnerKept::build(img, size, Some((sigma_n, q_min, t2)))?;
    let points = kept.points(sigma_n, threshold_px, q_min)?;
    Ok((std::mem::take(&mut kept.layers), points))
}

/// The detection parameters, checked before any work.
fn check_detect(sigma_n: f64, threshold_px: f64, q_min: f64) -> Result<()> {
    for (field, v) in [("sigma_n", sigma_n), ("threshold_px", threshold_px)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(Error::input(field, "must be a number greater than 0"));
        }
    }
    if !q_min.is_finite() {
        return Err(Error::input("q_min", "must be a number"));
    }
    Ok(())
}

/// The point at `(c, r)` with the measures of its window and its error
/// ellipse (`interest::precision`).
fn point_of(m: &Measures, c: usize, r: usize, score: f64, sigma_n: f64, t: f64) -> Option<Point> {
    let pr = interest::precision(m, sigma_n, t);
    Some(Point {
        c,
        r,
        score,
        major: pr.sigma_max?,
        minor: pr.sigma_min?,
        angle: m.weak_angle,
    })
}

/// The reference route (images that are not 8-bit, and the tests): the map
/// of every window's measures, its `w` and `q` layers, seed 003's points.
pub fn forstner_reference(
    img: &Grid,
    size: usize,
    sigma_n: f64,
    threshold_px: f64,
    q_min: f64,
) -> Result<(Vec<Layer>, Vec<Point>)> {
    check_detect(sigma_n, threshold_px, q_min)?;
    let map = interest::forstner_map(img, size)?;
    let det = interest::forstner_points(&map, sigma_n, threshold_px, q_min);
    let points = det
        .points
        .iter()
        .filter_map(|p| {
            point_of(
                &map.get(p.c, p.r)?,
                p.c,
                p.r,
                p.score,
                sigma_n,
                threshold_px,
            )
        })
        .collect();
    Ok((map_layers(&map), points))
}

fn map_layers(map: &interest::Map<Measures>) -> Vec<Layer> {
    let layer = |name: &str, f: &dyn Fn(&Measures) -> Option<f64>| {
        let data = map
            .cells
            .iter()
            .map(|m| m.as_ref().and_then(f).map_or(f32::NAN, |v| v as f32))
            .collect();
        Layer::new(name, whole(map.width, map.height), data, false)
    };
    vec![layer("w", &|m| Some(m.w)), layer("q", &|m| m.q)]
}

/// The share of a photo's pixels the photo-relative threshold keeps: a
/// corner is rare, so `w_min` is the `w` that only the strongest 0.1 % of
/// the pixels reach (its 99.9th percentile). Förstner and Gülch's
/// `w_min = 5 · median(w)` was tried and rejected: on a photo with flat
/// areas the median `w` is tiny (8.8 on the chessboard), and it kept 2678
/// points there, more than the fixed T = 0.5 px (923); the 99.9th
/// percentile keeps 181 (the board has 88 square corners, each found once
/// or twice by 5 × 5 windows), 109 on the cameraman.
pub const W_TOP_SHARE: f64 = 0.001;

/// The threshold chosen for one photo: `w_min` at the top [`W_TOP_SHARE`]
/// of its `w`, turned into seed 003's `T`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AutoThreshold {
    /// `w_min`: the `w` reached by the top [`W_TOP_SHARE`] of the map's pixels.
    pub w_min: f64,
    /// `T = σn / √w_min` (px): seed 003's test `λmax(Σuv) = σn²/λmin(N) ≤ T²`
    /// then keeps the pixels whose `λmin(N) ≥ w_min` (and `w ≤ λmin(N) ≤ 2w`,
    /// so about those with `w ≥ w_min`), whatever `σn`.
    pub threshold_px: f64,
}

/// The rank of `w_min` among `n` values of `w` (ascending).
pub fn top_rank(n: usize) -> usize {
    ((1.0 - W_TOP_SHARE) * (n - 1) as f64).floor() as usize
}

/// The exact `w` of rank [`top_rank`] among the `size × size` windows of
/// the 8-bit `bytes` (`width × height`) that `fit` places, from their `w`
/// layer `wl` (full size, `f32`): found on the layer (rounding keeps the
/// order), then the windows whose `f32` is that value recomputed exactly
/// (their own sums: one by one for a few, by a pass over the image for
/// many). The lab's pool computes `wl` by bands and this on the whole
/// photo (the same `w_min` as one [`ForstnerKept`]).
pub fn exact_w_min(
    bytes: &[u8],
    width: usize,
    height: usize,
    size: usize,
    wl: &[f32],
    fit: stream::Fit,
) -> Option<f64> {
    let cells = |r: usize| {
        let start = r * width + fit.c0;
        wl.get(start..start + fit.columns).unwrap_or(&[])
    };
    // the value of rank k by its bits (w ≥ 0: the order of the bits is the
    // order of the values): a histogram of the top 12 bits (16 KB, in the
    // first-level cache), then the one bucket it falls in — two passes, no
    // copy of the layer
    let mut hist = vec![0u32; 1 << 12];
    let mut n = 0;
    for r in fit.r0..fit.r0 + fit.rows {
        let row = cells(r);
        for &x in row {
            hist[(x.to_bits() >> 20) as usize] += 1;
        }
        n += row.len();
    }
    if n == 0 {
        return None;
    }
    let k = top_rank(n);
    let (mut bucket, mut before) = (0, 0);
    for (b, &count) in hist.iter().enumerate() {
        let count = count as usize;
        if before + count > k {
            bucket = b;
            break;
        }
        before += count;
    }
    let mut inside: Vec<f32> = (fit.r0..fit.r0 + fit.rows)
        .flat_map(cells)
        .copied()
        .filter(|x| (x.to_bits() >> 20) as usize == bucket)
        .collect();
    let v = *inside
        .select_nth_unstable_by(k.checked_sub(before)?, f32::total_cmp)
        .1;
    if v == 0.0 {
        // a w rounds to 0 only when it is 0 (no w is that small)
        return Some(0.0);
    }
    let below = before + inside.iter().filter(|&&x| x < v).count();
    let same = inside.iter().filter(|&&x| x == v).count();
    drop(inside);
    let g = Gray::new("image", bytes, width, height).ok()?;
    let mut group = Vec::with_capacity(same);
    if same <= 4096 {
        for r in fit.r0..fit.r0 + fit.rows {
            for (j, &x) in cells(r).iter().enumerate() {
                if x == v {
                    group.push(Sums4::at(&g, size, fit.c0 + j, r)?.w_q().0);
                }
            }
        }
    } else {
        stream::forstner_rows(g, size, |r, xx, yy, xy| {
            for (j, &x) in cells(r).iter().enumerate() {
                if x == v {
                    let s = Sums4 {
                        xx: xx[j],
                        yy: yy[j],
                        xy: xy[j],
                    };
                    group.push(s.w_q().0);
                }
            }
        })
        .ok()?;
    }
    let rank = k.checked_sub(below)?;
    group.sort_by(f64::total_cmp);
    group.get(rank).copied()
}

/// Where the image lives for a new suppression.
#[derive(Debug, Clone)]
enum Source {
    /// The 8-bit image (the window sums are recomputed row by row).
    Fast {
        bytes: Vec<u8>,
        width: usize,
        height: usize,
        /// Where the windows that fit lie (`w_min`'s cells).
        fit: stream::Fit,
    },
    /// A colour photo's levels (the window sums recomputed row by row, in
    /// `i64`; a window's exact measures from its greys `n / scale`).
    Levels {
        levels: Levels,
        width: usize,
        height: usize,
    },
    /// The reference's map of every window's measures.
    Reference(interest::Map<Measures>),
}

/// A kept local maximum: pixel, `λmax(Σuv)`, and its window's sums (fast
/// route) to build the measures of a shown point.
#[derive(Debug, Clone, Copy)]
struct Maximum {
    c: usize,
    r: usize,
    lambda: f64,
    sums: Option<Sums4>,
}

/// The local maxima of one suppression: `(σn, q_min)`, the largest `T²`
/// they serve, and the maxima.
#[derive(Debug, Clone)]
struct Suppressed {
    sigma_n: f64,
    q_min: f64,
    limit: f64,
    maxima: Vec<Maximum>,
}

/// A Förstner map with its suppression done for one `σn` and roundness
/// `q_min`, so that a new threshold `T` costs only a pass over the kept
/// local maxima (the live threshold slider).
///
/// Why this equals seed 003's rule (threshold, then suppression) for every
/// `T`: a pixel is kept there when it passes the threshold
/// (`λmax(Σuv) ≤ T²`, `q ≥ q_min`) and no candidate in its window scores
/// higher (or the same and comes first). The score is `−λmax(Σuv)`, and a
/// pixel with a higher score (a smaller `λmax(Σuv)`) that passes the
/// roundness test passes the threshold whenever a lower-scored one does.
/// So the higher-scored candidates in a window are the same for every `T`:
/// the pixels kept for `T` are the local maxima among the round pixels
/// whose `λmax(Σuv) ≤ L` (any `L ≥ T²`: a pixel above `L` never outscores
/// one below it) that have `λmax(Σuv) ≤ T²`. The suppression is done for
/// `L = 4·T²` (a `T` up to twice the first one re-uses it) and redone for
/// a larger `T`. Tested against the reference at every pixel.
#[derive(Debug, Clone)]
pub struct ForstnerKept {
    size: usize,
    layers: Vec<Layer>,
    /// `w_min` (the automatic threshold's), found when first asked for: the
    /// pool's bands and `run_forstner` never ask.
    w_min: std::cell::OnceCell<Option<f64>>,
    source: Source,
    suppressed: Option<Suppressed>,
}

impl ForstnerKept {
    /// Förstner's map over `size × size` windows: its `w` and `q` layers
    /// and `w_min` now, points later.
    pub fn new<'a>(img: impl Into<Image<'a>>, size: usize) -> Result<Self> {
        ForstnerKept::build(img, size, None)
    }

    /// [`ForstnerKept::new`], and the suppression for `(σn, q_min, limit)`
    /// in the same pass over the image when asked.
    fn build<'a>(
        img: impl Into<Image<'a>>,
        size: usize,
        detect: Option<(f64, f64, f64)>,
    ) -> Result<Self> {
        let img = img.into();
        let Some(g) = img.gray() else {
            if let Some(lv) = img.levels() {
                let (width, height) = (img.width(), img.height());
                let (layers, _, maxima) = levels::build(lv, width, height, size, detect)?;
                return Ok(ForstnerKept {
                    size,
                    layers,
                    w_min: std::cell::OnceCell::new(),
                    source: Source::Levels {
                        levels: lv.clone(),
                        width,
                        height,
                    },
                    suppressed: detect.zip(maxima).map(|((sigma_n, q_min, limit), maxima)| {
                        Suppressed {
                            sigma_n,
                            q_min,
                            limit,
                            maxima,
                        }
                    }),
                });
            }
            let map = interest::forstner_map(img.grid(), size)?;
            let mut w: Vec<f64> = map.cells.iter().flatten().map(|m| m.w).collect();
            let w_min = (!w.is_empty()).then(|| {
                let k = top_rank(w.len());
                // sorted as the groups are (one sort in the wasm, not a second
                // selection: a lab visit's download); this route is the rare one
                w.sort_by(f64::total_cmp);
                w[k]
            });
            let mut kept = ForstnerKept {
                size,
                layers: map_layers(&map),
                w_min: std::cell::OnceCell::from(w_min),
                source: Source::Reference(map),
                suppressed: None,
            };
            if let Some((sigma_n, q_min, limit)) = detect {
                kept.suppress(sigma_n, q_min, limit);
            }
            return Ok(kept);
        };
        let (width, height) = (g.width(), g.height());
        let mut wl = vec![f32::NAN; width * height];
        let mut ql = vec![f32::NAN; width * height];
        let mut detector = detect.map(|(sigma_n, q_min, limit)| {
            Detector::new(width, height, size, sigma_n, q_min, limit)
        });
        let fit = stream::forstner_rows(g, size, |r, xx, yy, xy| {
            let c0 = r * width + interest::anchor(size);
            let (wo, qo) = (&mut wl[c0..c0 + xx.len()], &mut ql[c0..c0 + xx.len()]);
            stream::w_q_row(xx, yy, xy, wo, qo);
            if let Some(d) = detector.as_mut() {
                d.row(r, xx, yy, xy);
            }
        })?;
        let suppressed = detector
            .zip(detect)
            .map(|(d, (sigma_n, q_min, limit))| Suppressed {
                sigma_n,
                q_min,
                limit,
                maxima: d.finish(),
            });
        Ok(ForstnerKept {
            size,
            layers: vec![
                Layer::new("w", whole(width, height), wl, false),
                Layer::new("q", whole(width, height), ql, false),
            ],
            w_min: std::cell::OnceCell::new(),
            source: Source::Fast {
                bytes: g.data().to_vec(),
                width,
                height,
                fit,
            },
            suppressed,
        })
    }

    /// The window size the map was computed with.
    pub fn size(&self) -> usize {
        self.size
    }

    /// The `w` and `q` layers.
    pub fn layers(&self) -> &[Layer] {
        &self.layers
    }

    /// The threshold chosen for this photo for `σn` (None when the map has
    /// no textured pixel: `w_min` is 0, or no window fits).
    pub fn auto_threshold(&self, sigma_n: f64) -> Option<AutoThreshold> {
        let w_min = (*self.w_min.get_or_init(|| match &self.source {
            Source::Fast {
                bytes,
                width,
                height,
                fit,
            } => {
                let wl = self.layers.first().map_or(&[][..], |l| &l.data[..]);
                exact_w_min(bytes, *width, *height, self.size, wl, *fit)
            }
            Source::Levels {
                levels,
                width,
                height,
            } => {
                let wl = self.layers.first().map_or(&[][..], |l| &l.data[..]);
                levels_w_min(levels, *width, *height, self.size, wl)
            }
            // (the reference route finds it with its map)
            Source::Reference(_) => None,
        }))?;
        (w_min > 0.0 && sigma_n > 0.0).then(|| AutoThreshold {
            w_min,
            threshold_px: sigma_n / w_min.sqrt(),
        })
    }

    /// Suppression for `σn`, `q_min` among the round pixels with
    /// `λmax(Σuv) ≤ limit`.
    fn suppress(&mut self, sigma_n: f64, q_min: f64, limit: f64) {
        let var = sigma_n * sigma_n;
        let round = |q: f64| q_min <= 0.0 || q >= q_min;
        let mut maxima = Vec::new();
        match &self.source {
            Source::Fast {
                bytes,
                width,
                height,
                ..
            } => {
                let Ok(g) = Gray::new("image", bytes, *width, *height) else {
                    return;
                };
                let mut d = Detector::new(*width, *height, self.size, sigma_n, q_min, limit);
                if stream::forstner_rows(g, self.size, |r, xx, yy, xy| d.row(r, xx, yy, xy)).is_ok()
                {
                    maxima = d.finish();
                }
            }
            Source::Levels {
                levels,
                width,
                height,
            } => {
                let detect = Some((sigma_n, q_min, limit));
                if let Ok((_, _, Some(m))) =
                    levels::build(levels, *width, *height, self.size, detect)
                {
                    maxima = m;
                }
            }
            Source::Reference(map) => {
                let scores: Vec<Option<f64>> = map
                    .cells
                    .iter()
                    .map(|m| {
                        let m = (*m)?;
                        let ok = q_min <= 0.0 || m.q.is_some_and(round);
                        // interest::precision's λmax(Σuv) = σn² / λmin(N)
                        (ok && m.lambda_min > 0.0)
                            .then(|| var / m.lambda_min)
                            .filter(|&l| l <= limit)
                            .map(|l| -l)
                    })
                    .collect();
                let wd = map.width.max(1);
                maxima = interest::suppress(&scores, map.width, map.height, self.size / 2)
                    .into_iter()
                    .filter_map(|i| {
                        scores[i].map(|s| Maximum {
                            c: i % wd,
                            r: i / wd,
                            lambda: -s,
                            sums: None,
                        })
                    })
                    .collect();
            }
        }
        self.suppressed = Some(Suppressed {
            sigma_n,
            q_min,
            limit,
            maxima,
        });
    }

    /// The points for `T` (seed 003's rule); the suppression is redone only
    /// when `σn` or `q_min` changed or `T` is more than twice the `T` it
    /// was done for.
    pub fn points(&mut self, sigma_n: f64, threshold_px: f64, q_min: f64) -> Result<Vec<Point>> {
        check_detect(sigma_n, threshold_px, q_min)?;
        let t2 = threshold_px * threshold_px;
        let fresh = matches!(&self.suppressed,
            Some(s) if s.sigma_n == sigma_n && s.q_min == q_min && s.limit >= t2);
        if !fresh {
            // a colour photo's suppression for every `T` at once (its
            // maxima carry their approximate λ; the shown ones' exact λ and
            // measures are found below): a new `T` never redoes it
            let limit = match self.source {
                Source::Levels { .. } => f64::MAX,
                _ => 4.0 * t2,
            };
            self.suppress(sigma_n, q_min, limit);
        }
        let Some(s) = &self.suppressed else {
            return Ok(Vec::new());
        };
        let m = (self.size - 2) * (self.size - 2);
        let var = sigma_n * sigma_n;
        Ok(s.maxima
            .iter()
            // (a fast maximum's λ is within 10⁻¹⁴ of the exact one, a
            // colour photo's within 10⁻⁶ / 8: the exact one decides below)
            .filter(|x| x.lambda <= t2 * (1.0 + 1e-6))
            .filter_map(|x| {
                let (ms, lambda) = match (&self.source, x.sums) {
                    (_, Some(sums)) => (sums.measures(m), var / sums.lambda_min()),
                    (Source::Reference(map), None) => (map.get(x.c, x.r)?, x.lambda),
                    (Source::Levels { levels, width, .. }, None) => {
                        let ms = exact_measures(levels, *width, self.size, x.c, x.r)?;
                        // (the reference route's λmax(Σuv), as `levels::score_of`)
                        (ms, var / ms.lambda_min)
                    }
                    _ => return None,
                };
                (lambda <= t2).then_some(())?;
                point_of(&ms, x.c, x.r, lambda, sigma_n, threshold_px)
            })
            .collect())
    }
}

/// Relative distance under which approximate scores are compared exactly.
const REFINE: f64 = 1e-12;

/// Seed 003's candidates of the fast route, fed row by row into the
/// suppression: a window is a candidate when round (`q ≥ q_min`) and
/// `λmax(Σuv) = σn²/λmin ≤ limit`. A row's scores are first found by a
/// loop the compiler vectorises, on the exact integers `16·det`, `4·trace`
/// in `f64`: `λmin ≤ 2·det/trace` rules out most windows, the roundness is
/// decided by products, `λmax(Σuv)` is `σn²·λmax/det` with `√` for
/// `hypot` (within 10⁻¹⁴ of the exact one); a window within 10⁻⁹ of the
/// roundness bound or the singular rule, or within 10⁻¹² of the limit, is
/// decided exactly (`Sums4::w_q`, `Sums4::lambda_min`, the reference's
/// numbers). The suppression compares the approximate scores and near-ties
/// by the exact ones (`Suppressor::refined`), and a shown point's score is
/// the exact one ([`ForstnerKept::points`]) — the reference's decisions and
/// numbers.
struct Detector {
    sup: Suppressor<'static, Sums4>,
    maxima: Vec<Maximum>,
    next: usize,
    height: usize,
    anchor: usize,
    var: f64,
    q_min: f64,
    limit: f64,
}

impl Detector {
    fn new(width: usize, height: usize, size: usize, sigma_n: f64, q_min: f64, limit: f64) -> Self {
        let var = sigma_n * sigma_n;
        let exact = move |s: &Sums4| -(var / s.lambda_min());
        Detector {
            sup: Suppressor::new(width, height, size / 2).refined(REFINE, exact),
            maxima: Vec::new(),
            next: 0,
            height,
            anchor: interest::anchor(size),
            var,
            q_min,
            limit,
        }
    }

    /// Row `r` of the fit: its windows' sums (from column `anchor`).
    fn row(&mut self, r: usize, xx: &[i32], yy: &[i32], xy: &[i32]) {
        while self.next < r {
            self.empty_row();
        }
        let n = xx.len().min(yy.len()).min(xy.len());
        let (xx, yy, xy) = (&xx[..n], &yy[..n], &xy[..n]);
        let (var, q_min, limit) = (self.var, self.q_min, self.limit);
        let floor = var / limit;
        let a0 = self.anchor;
        let fill = |scores: &mut [f64], payload: &mut [Sums4]| {
            let scores = &mut scores[a0..a0 + n];
            let k = Consts {
                var,
                q_min,
                limit,
                floor,
            };
            let done = scores_simd(xx, yy, xy, &k, scores);
            for i in done..n {
                scores[i] = k.score(f64::from(xx[i]), f64::from(yy[i]), f64::from(xy[i]));
            }
            let payload = &mut payload[a0..a0 + n];
            for i in 0..n {
                let s = Sums4 {
                    xx: xx[i],
                    yy: yy[i],
                    xy: xy[i],
                };
                payload[i] = s;
                if scores[i] == f64::INFINITY {
                    scores[i] = exact_score(s, var, q_min, limit);
                }
            }
        };
        let (sup, maxima) = (&mut self.sup, &mut self.maxima);
        sup.push_with(fill, &mut keep(maxima));
        self.next = r + 1;
    }

    fn empty_row(&mut self) {
        self.sup.push_empty(&mut keep(&mut self.maxima));
        self.next += 1;
    }

    /// The kept maxima, after the last rows.
    fn finish(mut self) -> Vec<Maximum> {
        while self.next < self.height {
            self.empty_row();
        }
        self.sup.finish(&mut keep(&mut self.maxima));
        self.maxima
    }
}

/// The suppression's kept cells as maxima (their `λmax(Σuv)` within
/// 10⁻¹⁴ of the exact one, found exactly when shown).
fn keep(maxima: &mut Vec<Maximum>) -> impl FnMut(usize, usize, f64, Sums4) + '_ {
    move |c, r, score, sums| {
        maxima.push(Maximum {
            c,
            r,
            lambda: -score,
            sums: Some(sums),
        })
    }
}

/// The exact score `−λmax(Σuv)` of a candidate window, NaN otherwise (the
/// reference's test, its numbers).
fn exact_score(s: Sums4, var: f64, q_min: f64, limit: f64) -> f64 {
    let round = q_min <= 0.0 || s.w_q().1 >= q_min;
    let lmin = s.lambda_min();
    let l = var / lmin;
    if round && lmin > 0.0 && l <= limit {
        -l
    } else {
        f64::NAN
    }
}

/// The constants of one detection.
struct Consts {
    var: f64,
    q_min: f64,
    limit: f64,
    /// `σn²/limit`: the least `λmin` a candidate has.
    floor: f64,
}

impl Consts {
    /// The approximate score `−λmax(Σuv)` of the window with `Σdx² = a`,
    /// `Σdy² = d`, `Σdx·dy = b`; NaN when it is no candidate; `+∞` when
    /// only the exact numbers can tell ([`Detector`]).
    #[inline(always)]
    fn score(&self, a: f64, d: f64, b: f64) -> f64 {
        let (var, q_min, limit) = (self.var, self.q_min, self.limit);
        // 4·trace and 16·det, exact integers
        let (tr4, det4) = (a + d, a * d - b * b);
        let t2 = tr4 * tr4;
        let maybe = tr4 > 0.0 && det4 >= 2.0 * self.floor * tr4 * (1.0 - 1e-9);
        // q = 4·det4/tr4²; singular: det4 ≤ 10⁻¹²·tr4²
        let qd = 4.0 * det4 - q_min * t2;
        let q_near = q_min > 0.0 && qd.abs() <= 1e-9 * q_min * t2;
        let round = q_min <= 0.0 || qd > 0.0;
        let sing_near = det4 <= 2e-12 * t2;
        let x = (a - d) / 8.0;
        let bb = b / 4.0;
        let l = var * (tr4 / 8.0 + (x * x + bb * bb).sqrt()) / (det4 / 16.0);
        let l_near = (l - limit).abs() <= limit * REFINE;
        if !maybe {
            f64::NAN
        } else if q_near || sing_near || l_near {
            f64::INFINITY
        } else if round && l <= limit {
            -l
        } else {
            f64::NAN
        }
    }
}

/// [`Consts::score`] two windows at a time (`f64x2`); returns how many
/// were scored.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn scores_simd(xx: &[i32], yy: &[i32], xy: &[i32], k: &Consts, out: &mut [f64]) -> usize {
    use core::arch::wasm32::*;
    let n = out.len().min(xx.len()).min(yy.len()).min(xy.len());
    let sp = f64x2_splat;
    let (var, qm, lim) = (sp(k.var), sp(k.q_min), sp(k.limit));
    let fl2 = sp(2.0 * k.floor * (1.0 - 1e-9));
    let q_on = if k.q_min > 0.0 {
        u64x2_splat(u64::MAX)
    } else {
        u64x2_splat(0)
    };
    let q_off = v128_not(q_on);
    let (nan, inf) = (sp(f64::NAN), sp(f64::INFINITY));
    let mut i = 0;
    while i + 2 <= n {
        let pair = |v: &[i32]| f64x2(f64::from(v[i]), f64::from(v[i + 1]));
        let (a, d, b) = (pair(xx), pair(yy), pair(xy));
        let tr4 = f64x2_add(a, d);
        let det4 = f64x2_sub(f64x2_mul(a, d), f64x2_mul(b, b));
        let t2 = f64x2_mul(tr4, tr4);
        let maybe = v128_and(f64x2_gt(tr4, sp(0.0)), f64x2_ge(det4, f64x2_mul(fl2, tr4)));
        let qt = f64x2_mul(qm, t2);
        let qd = f64x2_sub(f64x2_mul(sp(4.0), det4), qt);
        let q_near = v128_and(q_on, f64x2_le(f64x2_abs(qd), f64x2_mul(sp(1e-9), qt)));
        let round = v128_or(q_off, f64x2_gt(qd, sp(0.0)));
        let sing_near = f64x2_le(det4, f64x2_mul(sp(2e-12), t2));
        let x = f64x2_mul(f64x2_sub(a, d), sp(0.125));
        let bb = f64x2_mul(b, sp(0.25));
        let root = f64x2_sqrt(f64x2_add(f64x2_mul(x, x), f64x2_mul(bb, bb)));
        let lmax = f64x2_add(f64x2_mul(tr4, sp(0.125)), root);
        let l = f64x2_div(f64x2_mul(var, lmax), f64x2_mul(det4, sp(0.0625)));
        let l_near = f64x2_le(f64x2_abs(f64x2_sub(l, lim)), f64x2_mul(lim, sp(REFINE)));
        let near = v128_or(v128_or(q_near, sing_near), l_near);
        let ok = v128_and(round, f64x2_le(l, lim));
        let clear = v128_bitselect(f64x2_neg(l), nan, ok);
        let v = v128_bitselect(v128_bitselect(inf, clear, near), nan, maybe);
        out[i] = f64x2_extract_lane::<0>(v);
        out[i + 1] = f64x2_extract_lane::<1>(v);
        i += 2;
    }
    i
}

#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
fn scores_simd(_: &[i32], _: &[i32], _: &[i32], _: &Consts, _: &mut [f64]) -> usize {
    0
}
