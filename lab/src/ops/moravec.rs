//! Moravec's operator over a whole image: the map of window means and seed
//! 000's points (above the threshold, the largest in each window). On an
//! 8-bit image by the core's row-by-row window sums
//! (`interest::fast::stream::moravec_rows`: each mean the reference's bit
//! for bit, the layer its `f32` rounding, the points the reference's);
//! otherwise `interest::moravec_map` and `interest::moravec_points`.

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
    let mut next = 0;
    let empty = |w: usize| std::iter::repeat_n((f64::NAN, ()), w);
    stream::moravec_rows(g, size, |r, sums| {
        while next < r {
            sup.push(empty(w), &mut keep);
            next += 1;
        }
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
        next = r + 1;
    })?;
    while next < h {
        sup.push(empty(w), &mut keep);
        next += 1;
    }
    sup.finish(&mut keep);
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
