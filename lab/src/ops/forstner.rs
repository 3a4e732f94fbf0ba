//! Förstner's operator over a whole image: the `w` and `q` maps, seed 003's
//! threshold and suppression with error ellipses, and what is kept for a
//! live threshold (the slider re-thresholds the kept local maxima, it does
//! not recompute the map).
//!
//! On an 8-bit image everything comes from the core's row-by-row window
//! sums (`interest::fast::stream`): `w`, `q`, `λmin` and the measures of a
//! point are `Measures::from_sums`'s numbers bit for bit, the layers their
//! `f32` roundings, the points exactly the reference's (same candidates,
//! same scores, the same suppression rule row by row). Other images take
//! the reference: `interest::forstner_map` and `interest::forstner_points`.

use super::*;
use photogrammetry_playground::interest::fast::stream::{self, Sums4, Suppressor};
use photogrammetry_playground::interest::{self, Measures};

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
    let mut kept = ForstnerKept::new(img, size)?;
    let t2 = threshold_px * threshold_px;
    kept.suppress(sigma_n, q_min, t2);
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
fn top_rank(n: usize) -> usize {
    ((1.0 - W_TOP_SHARE) * (n - 1) as f64).floor() as usize
}

/// The exact `w` of rank [`top_rank`] among the `size × size` windows of
/// the 8-bit `bytes` (`width × height`) that `fit` places, from their `w`
/// layer `wl` (full size, `f32`): found on the layer (rounding keeps the
/// order), then the windows whose `f32` is that value recomputed exactly
/// (their own sums). The lab's pool computes `wl` by bands and this on the
/// whole photo (the same `w_min` as one [`ForstnerKept`]).
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
    let mut all: Vec<f32> = (fit.r0..fit.r0 + fit.rows)
        .flat_map(cells)
        .copied()
        .collect();
    if all.is_empty() {
        return None;
    }
    let k = top_rank(all.len());
    let v = *all.select_nth_unstable_by(k, f32::total_cmp).1;
    if v == 0.0 {
        // a w rounds to 0 only when it is 0 (no w is that small)
        return Some(0.0);
    }
    let below = all.iter().filter(|&&x| x < v).count();
    drop(all);
    let g = Gray::new("image", bytes, width, height).ok()?;
    let mut group = Vec::new();
    stream::forstner_rows(g, size, |r, xx, yy, xy| {
        let row = cells(r);
        for (j, &x) in row.iter().enumerate() {
            if x == v {
                group.push(
                    Sums4 {
                        xx: xx[j],
                        yy: yy[j],
                        xy: xy[j],
                    }
                    .w_q()
                    .0,
                );
            }
        }
    })
    .ok()?;
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
    w_min: Option<f64>,
    source: Source,
    suppressed: Option<Suppressed>,
}

impl ForstnerKept {
    /// Förstner's map over `size × size` windows: its `w` and `q` layers
    /// and `w_min` now, points later.
    pub fn new<'a>(img: impl Into<Image<'a>>, size: usize) -> Result<Self> {
        let img = img.into();
        let Some(g) = img.gray() else {
            let map = interest::forstner_map(img.grid, size)?;
            let mut w: Vec<f64> = map.cells.iter().flatten().map(|m| m.w).collect();
            let w_min = (!w.is_empty()).then(|| {
                let k = top_rank(w.len());
                *w.select_nth_unstable_by(k, f64::total_cmp).1
            });
            return Ok(ForstnerKept {
                size,
                layers: map_layers(&map),
                w_min,
                source: Source::Reference(map),
                suppressed: None,
            });
        };
        let (width, height) = (g.width(), g.height());
        let mut wl = vec![f32::NAN; width * height];
        let mut ql = vec![f32::NAN; width * height];
        let fit = stream::forstner_rows(g, size, |r, xx, yy, xy| {
            let c0 = r * width + interest::anchor(size);
            let (wo, qo) = (&mut wl[c0..c0 + xx.len()], &mut ql[c0..c0 + xx.len()]);
            for ((((&a, &d), &b), wv), qv) in xx.iter().zip(yy).zip(xy).zip(wo).zip(qo) {
                let (w, q) = Sums4 {
                    xx: a,
                    yy: d,
                    xy: b,
                }
                .w_q();
                *wv = w as f32;
                *qv = q as f32;
            }
        })?;
        let mut kept = ForstnerKept {
            size,
            layers: vec![
                Layer::new("w", whole(width, height), wl, false),
                Layer::new("q", whole(width, height), ql, false),
            ],
            w_min: None,
            source: Source::Fast {
                bytes: g.data().to_vec(),
                width,
                height,
            },
            suppressed: None,
        };
        kept.w_min = kept.exact_w_min(fit);
        Ok(kept)
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
        let w_min = self.w_min?;
        (w_min > 0.0 && sigma_n > 0.0).then(|| AutoThreshold {
            w_min,
            threshold_px: sigma_n / w_min.sqrt(),
        })
    }

    /// The exact `w` of rank [`top_rank`] among the windows of `fit`
    /// ([`exact_w_min`] on this map's own image and `w` layer).
    fn exact_w_min(&self, fit: stream::Fit) -> Option<f64> {
        let Source::Fast {
            bytes,
            width,
            height,
        } = &self.source
        else {
            return None;
        };
        exact_w_min(
            bytes,
            *width,
            *height,
            self.size,
            &self.layers.first()?.data,
            fit,
        )
    }

    /// Suppression for `σn`, `q_min` among the round pixels with
    /// `λmax(Σuv) ≤ limit`.
    fn suppress(&mut self, sigma_n: f64, q_min: f64, limit: f64) {
        let var = sigma_n * sigma_n;
        let round = |q: f64| q_min <= 0.0 || q >= q_min;
        let radius = self.size / 2;
        let mut maxima = Vec::new();
        match &self.source {
            Source::Fast {
                bytes,
                width,
                height,
            } => {
                let (w, h) = (*width, *height);
                let Ok(g) = Gray::new("image", bytes, w, h) else {
                    return;
                };
                let a = interest::anchor(self.size);
                let mut sup = Suppressor::<Sums4>::new(w, h, radius);
                let mut keep = |c: usize, r: usize, s: f64, sums: Sums4| {
                    maxima.push(Maximum {
                        c,
                        r,
                        lambda: -s,
                        sums: Some(sums),
                    });
                };
                // λmin ≤ 2w: a window with 2w below σn²/limit cannot pass
                let floor = var / limit;
                let mut row = vec![(f64::NAN, Sums4::default()); w];
                let mut next = 0;
                let fit = stream::forstner_rows(g, self.size, |r, xx, yy, xy| {
                    while next < r {
                        sup.push(
                            std::iter::repeat_n((f64::NAN, Sums4::default()), w),
                            &mut keep,
                        );
                        next += 1;
                    }
                    for (j, ((&a2, &d2), &b2)) in xx.iter().zip(yy).zip(xy).enumerate() {
                        let s = Sums4 {
                            xx: a2,
                            yy: d2,
                            xy: b2,
                        };
                        let (wv, q) = s.w_q();
                        let mut score = f64::NAN;
                        if round(q) && 2.0 * wv * (1.0 + 1e-9) >= floor {
                            let lmin = s.lambda_min();
                            if lmin > 0.0 {
                                let l = var / lmin;
                                if l <= limit {
                                    score = -l;
                                }
                            }
                        }
                        row[a + j] = (score, s);
                    }
                    sup.push(row.iter().copied(), &mut keep);
                    next = r + 1;
                });
                if fit.is_ok() {
                    while next < h {
                        sup.push(
                            std::iter::repeat_n((f64::NAN, Sums4::default()), w),
                            &mut keep,
                        );
                        next += 1;
                    }
                    sup.finish(&mut keep);
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
                maxima = interest::suppress(&scores, map.width, map.height, radius)
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
            self.suppress(sigma_n, q_min, 4.0 * t2);
        }
        let Some(s) = &self.suppressed else {
            return Ok(Vec::new());
        };
        let m = (self.size - 2) * (self.size - 2);
        Ok(s.maxima
            .iter()
            .filter(|x| x.lambda <= t2)
            .filter_map(|x| {
                let ms = match (&self.source, x.sums) {
                    (_, Some(sums)) => sums.measures(m),
                    (Source::Reference(map), None) => map.get(x.c, x.r)?,
                    _ => return None,
                };
                point_of(&ms, x.c, x.r, x.lambda, sigma_n, threshold_px)
            })
            .collect())
    }
}
