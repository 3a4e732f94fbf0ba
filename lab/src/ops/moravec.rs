//! Moravec's operator over a whole image: the map of window means and seed
//! 000's points (above the threshold, the largest in each window). On an
//! 8-bit image by the core's row-by-row window sums
//! (`interest::fast::stream::moravec_rows`: each mean the reference's bit
//! for bit, the layer its `f32` rounding, the points the reference's);
//! on a colour photo's levels (`ops::Levels`) by the same sums in `i64`
//! (`stream::moravec_rows_levels`: each mean within `Levels::sum_slack` of
//! the reference's, the points the reference's — a mean near the threshold
//! and near-ties compared by the reference's own window, the points' scores
//! the reference's); otherwise `interest::moravec_map` and
//! `interest::moravec_points`.

use super::*;
use photogrammetry_playground::interest;
use photogrammetry_playground::interest::fast::stream::{self, Suppressor};

fn point(c: usize, r: usize, score: f64) -> Point {
    Point {
        c,
        r,
        score,
        major: 0.0,
        minor: 0.0,
        angle: 0.0,
    }
}

/// The Moravec map and its points above `threshold` after suppression.
pub fn moravec<'a>(
    img: impl Into<Image<'a>>,
    size: usize,
    threshold: f64,
) -> Result<(Layer, Vec<Point>)> {
    if !threshold.is_finite() {
        return Err(Error::input("threshold", "must be a finite number"));
    }
    let img = img.into();
    let Some(g) = img.gray() else {
        if let Some(lv) = img.levels() {
            return moravec_levels(lv, img.width(), img.height(), size, threshold);
        }
        return moravec_reference(img.grid(), size, threshold);
    };
    let (w, h) = (g.width(), g.height());
    let n = ((size.max(2) - 2) * (size.max(2) - 2)) as f64;
    let a = interest::anchor(size);
    let mut data = vec![f32::NAN; w * h];
    let mut points = Vec::new();
    let mut sup = Suppressor::<()>::new(w, h, size / 2);
    let mut keep = |c: usize, r: usize, s: f64, _: ()| points.push(point(c, r, s));
    let mut row = vec![(f64::NAN, ()); w];
    stream::moravec_rows(g, size, |r, sums| {
        sup.skip_to(r, &mut keep);
        let out = &mut data[r * w + a..r * w + a + sums.len()];
        for (&s, o) in sums.iter().zip(out.iter_mut()) {
            *o = (f64::from(s) / n) as f32;
        }
        // a mean above the threshold needs a sum above threshold·n (up to
        // rounding): only those are divided again, exactly
        let floor = threshold * n * (1.0 - 1e-12);
        for (&s, cell) in sums.iter().zip(&mut row[a..]) {
            let v = f64::from(s);
            cell.0 = if v > floor && v / n > threshold {
                v / n
            } else {
                f64::NAN
            };
        }
        sup.push(row.iter().copied(), &mut keep);
    })?;
    // (the rows below the last window have no scores)
    sup.finish(&mut keep);
    Ok((Layer::new("moravec", whole(w, h), data, false), points))
}

/// [`moravec`] of a colour photo's levels (`w × h`): the sums of squared
/// differences of `n` exact in `i64`, each mean `sum / scale² / (size − 2)²`
/// within `slack` (relative) of the reference's; a mean within `slack` of
/// the threshold is the reference's own window's, near-ties are compared by
/// the reference's windows (`Suppressor::refined`), and a point's score is
/// its window's reference mean.
fn moravec_levels(
    lv: &Levels,
    w: usize,
    h: usize,
    size: usize,
    threshold: f64,
) -> Result<(Layer, Vec<Point>)> {
    let view = lv
        .view(w, h)
        .ok_or_else(|| Error::input("image", "has levels of another size"))?;
    let m = (size.max(2) - 2) * (size.max(2) - 2);
    let n = m as f64;
    let unit = lv.scale * lv.scale;
    let slack = lv.sum_slack(4 * m);
    let a = interest::anchor(size);
    let exact = |&(c, r): &(usize, usize)| {
        lv.window(w, c, r, size)
            .and_then(|win| interest::moravec(&win).ok())
            .map_or(f64::NAN, |m| m.mean)
    };
    let mut data = vec![f32::NAN; w * h];
    let mut kept = Vec::new();
    let mut sup = Suppressor::<(usize, usize)>::new(w, h, size / 2).refined(4.0 * slack, exact);
    let mut keep = |c: usize, r: usize, _: f64, p: (usize, usize)| kept.push((c, r, p));
    let mut row = vec![(f64::NAN, (0, 0)); w];
    stream::moravec_rows_levels(view, size, |r, sums| {
        sup.skip_to(r, &mut keep);
        let out = &mut data[r * w + a..r * w + a + sums.len()];
        for ((&s, o), (j, cell)) in sums
            .iter()
            .zip(out.iter_mut())
            .zip(row[a..].iter_mut().enumerate())
        {
            let v = s as f64 / unit / n;
            *o = v as f32;
            // above the threshold beyond the slack, or the reference's own mean
            let v = if (v - threshold).abs() <= slack * v.abs().max(threshold.abs()) {
                exact(&(a + j, r))
            } else {
                v
            };
            *cell = (if v > threshold { v } else { f64::NAN }, (a + j, r));
        }
        sup.push(row.iter().copied(), &mut keep);
    })?;
    sup.finish(&mut keep);
    drop(sup);
    let points = kept
        .into_iter()
        .map(|(c, r, p)| point(c, r, exact(&p)))
        .collect();
    Ok((Layer::new("moravec", whole(w, h), data, false), points))
}

/// The reference route: `interest::moravec_map`, `interest::moravec_points`.
pub fn moravec_reference(img: &Grid, size: usize, threshold: f64) -> Result<(Layer, Vec<Point>)> {
    if !threshold.is_finite() {
        return Err(Error::input("threshold", "must be a finite number"));
    }
    let map = interest::moravec_map(img, size)?;
    let det = interest::moravec_points(&map, threshold);
    let points = det
        .points
        .iter()
        .map(|p| point(p.c, p.r, p.score))
        .collect();
    let data = map
        .cells
        .iter()
        .map(|m| m.map_or(f32::NAN, |v| v as f32))
        .collect();
    Ok((
        Layer::new("moravec", whole(map.width, map.height), data, false),
        points,
    ))
}
