//! Förstner's operator over a whole image: the `w` and `q` maps, seed 003's
//! threshold and suppression with error ellipses, and the map kept for a live
//! threshold (the slider re-thresholds the kept maxima, it does not recompute
//! the map).

use super::*;

/// Förstner's `w` and `q` maps (`interest::forstner_map`), seed 003's
/// threshold and suppression (`interest::forstner_points`), each point with
/// its error ellipse `Σuv = σn²·N⁻¹`.
pub fn forstner(
    img: &Grid,
    size: usize,
    sigma_n: f64,
    threshold_px: f64,
    q_min: f64,
) -> Result<(Vec<Layer>, Vec<Point>)> {
    check_detect(sigma_n, threshold_px, q_min)?;
    let map = forstner_maps(img, size)?;
    let points = forstner_detect(&map, sigma_n, threshold_px, q_min)?;
    Ok((forstner_layers(&map), points))
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

/// The point at `(c, r)` of a map with its error ellipse (`interest::precision`).
fn point_at(
    map: &interest::Map<Measures>,
    c: usize,
    r: usize,
    score: f64,
    sigma_n: f64,
    threshold_px: f64,
) -> Option<Point> {
    let m: Measures = map.get(c, r)?;
    let pr = interest::precision(&m, sigma_n, threshold_px);
    Some(Point {
        c,
        r,
        score,
        major: pr.sigma_max?,
        minor: pr.sigma_min?,
        angle: m.weak_angle,
    })
}

/// Förstner's map over `size × size` windows (`interest::forstner_map`),
/// kept by the lab so that a new threshold re-uses it.
pub fn forstner_maps(img: &Grid, size: usize) -> Result<interest::Map<Measures>> {
    interest::forstner_map(img, size)
}

/// The `w` and `q` layers of a Förstner map.
pub fn forstner_layers(map: &interest::Map<Measures>) -> Vec<Layer> {
    vec![
        map_layer("w", map, |m: Measures| Some(m.w)),
        map_layer("q", map, |m: Measures| m.q),
    ]
}

/// Seed 003's threshold and suppression on a computed map
/// (`interest::forstner_points`), each point with its error ellipse: the
/// points of [`forstner`] without recomputing the map.
pub fn forstner_detect(
    map: &interest::Map<Measures>,
    sigma_n: f64,
    threshold_px: f64,
    q_min: f64,
) -> Result<Vec<Point>> {
    check_detect(sigma_n, threshold_px, q_min)?;
    let det = interest::forstner_points(map, sigma_n, threshold_px, q_min);
    Ok(det
        .points
        .iter()
        .filter_map(|p| point_at(map, p.c, p.r, p.score, sigma_n, threshold_px))
        .collect())
}

/// A Förstner map with its suppression done for one `σn` and roundness
/// `q_min`, so that a new threshold `T` costs only a pass over the kept
/// local maxima (the live threshold slider).
///
/// Why this equals [`forstner_detect`] (seed 003's rule) for every `T`: a
/// pixel is kept there when it passes the threshold (`λmax(Σuv) ≤ T²`,
/// `q ≥ q_min`) and no candidate in its window scores higher (or the same
/// and comes first). The score is `−λmax(Σuv)`, and a pixel with a higher
/// score (a smaller `λmax(Σuv)`) that passes the roundness test passes the
/// threshold whenever a lower-scored one does. So the higher-scored
/// candidates in a window are the same for every `T`: the pixels kept
/// for `T` are the local maxima among the round pixels (found once) whose
/// `λmax(Σuv) ≤ T²`. Tested against [`forstner_detect`] at every pixel.
#[derive(Debug, Clone)]
pub struct ForstnerKept {
    pub map: interest::Map<Measures>,
    suppressed: Option<Suppressed>,
}

/// The local maxima of one suppression: `(σn, q_min)` and the maxima
/// (cell index, `λmax(Σuv)`).
#[derive(Debug, Clone)]
struct Suppressed {
    sigma_n: f64,
    q_min: f64,
    maxima: Vec<(usize, f64)>,
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

/// The photo-relative threshold for `σn` (None when the map has no
/// textured pixel: `w_min` is 0).
pub fn auto_threshold(map: &interest::Map<Measures>, sigma_n: f64) -> Option<AutoThreshold> {
    let mut w: Vec<f64> = map.cells.iter().flatten().map(|m| m.w).collect();
    if w.is_empty() {
        return None;
    }
    let k = ((1.0 - W_TOP_SHARE) * (w.len() - 1) as f64).floor() as usize;
    let (_, at, _) = w.select_nth_unstable_by(k, f64::total_cmp);
    let w_min = *at;
    (w_min > 0.0 && sigma_n > 0.0).then(|| AutoThreshold {
        w_min,
        threshold_px: sigma_n / w_min.sqrt(),
    })
}

impl ForstnerKept {
    pub fn new(map: interest::Map<Measures>) -> Self {
        ForstnerKept {
            map,
            suppressed: None,
        }
    }

    /// The points for `T` (as [`forstner_detect`]); the suppression is
    /// redone only when `σn` or `q_min` changed.
    pub fn points(&mut self, sigma_n: f64, threshold_px: f64, q_min: f64) -> Result<Vec<Point>> {
        check_detect(sigma_n, threshold_px, q_min)?;
        let fresh = matches!(&self.suppressed, Some(s) if s.sigma_n == sigma_n && s.q_min == q_min);
        if !fresh {
            let var = sigma_n * sigma_n;
            let scores: Vec<Option<f64>> = self
                .map
                .cells
                .iter()
                .map(|m| {
                    let m = (*m)?;
                    let round = q_min <= 0.0 || m.q.is_some_and(|q| q >= q_min);
                    // interest::precision's λmax(Σuv) = σn² / λmin(N)
                    (round && m.lambda_min > 0.0).then(|| -(var / m.lambda_min))
                })
                .collect();
            let maxima =
                interest::suppress(&scores, self.map.width, self.map.height, self.map.size / 2)
                    .into_iter()
                    .filter_map(|i| scores[i].map(|s| (i, -s)))
                    .collect();
            self.suppressed = Some(Suppressed {
                sigma_n,
                q_min,
                maxima,
            });
        }
        let Some(Suppressed { maxima, .. }) = &self.suppressed else {
            return Ok(Vec::new());
        };
        let t2 = threshold_px * threshold_px;
        let w = self.map.width.max(1);
        Ok(maxima
            .iter()
            .filter(|(_, l)| *l <= t2)
            .filter_map(|&(i, l)| point_at(&self.map, i % w, i / w, l, sigma_n, threshold_px))
            .collect())
    }
}
