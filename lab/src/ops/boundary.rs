//! Boundary tracing: threshold, the region at the picked pixel, its outer
//! boundary with chain code, length and shape.
//!
//! On an 8-bit image, and on a colour photo's levels (the threshold as a
//! level, [`Levels::cut`]): the region filled on bytes or levels, its
//! borders by the core's `chain::fast::contours` (Suzuki–Abe), the outer
//! one walked the other way round from the same start — `chain::trace`'s
//! boundary (`tests/web_fast.rs` ties the two). Otherwise
//! `chain::region_at` and `chain::trace`.

use super::*;
use photogrammetry_playground::chain::{self, fast as cfast, Connectivity};

/// A traced region: the region at the picked pixel (`chain::region_at`, as
/// a layer of 1 inside, 0 outside), its outer boundary (`chain::trace`)
/// with chain code, length and shape (`chain::length`, `chain::shape`).
#[derive(Debug, Clone, PartialEq)]
pub struct Traced {
    pub region: Layer,
    pub boundary: chain::Boundary,
    pub length: chain::Length,
    pub shape: Option<chain::Shape>,
}

/// Longest boundary (pixels) whose shape descriptors are computed:
/// `chain::shape`'s diameter compares every pair of boundary pixels.
pub const MAX_SHAPE_PIXELS: usize = 4000;

fn outside(c: usize, r: usize, w: usize, h: usize) -> Error {
    Error::input("pixel", format!("({c}, {r}) is outside the {w}×{h} image"))
}

/// Traces the region of `img` containing `(c, r)` after thresholding.
pub fn boundary<'a>(
    img: impl Into<Image<'a>>,
    threshold: f64,
    c: usize,
    r: usize,
) -> Result<Traced> {
    if !threshold.is_finite() {
        return Err(Error::input("threshold", "must be a finite number"));
    }
    let img = img.into();
    let (w, h) = (img.width(), img.height());
    if c >= w || r >= h {
        return Err(outside(c, r, w, h));
    }
    let conn = Connectivity::Eight;
    let (mask, area) = match (img.gray(), img.levels()) {
        (Some(g), _) => fill_bytes(g, threshold, c, r),
        (None, Some(l)) => fill_levels(l, w, h, threshold, c, r),
        (None, None) => None,
    }
    .map_or((None, 0), |(m, a)| (Some(m), a));
    let (region, boundary) = match mask {
        Some(mask) => {
            let b = outer(&mask, w, h, area)?;
            let data = mask.iter().map(|&m| f32::from(m)).collect();
            (Layer::new("region", whole(w, h), data, false), b)
        }
        None => {
            let mask = chain::region_at(img.grid(), threshold, c, r, conn)
                .ok_or_else(|| outside(c, r, w, h))?;
            let b = chain::trace(&mask, conn)
                .into_iter()
                .next()
                .ok_or_else(|| Error::Internal("a picked region has no boundary".into()))?;
            (Layer::from_grid("region", &mask, whole(w, h), false), b)
        }
    };
    let length = chain::length(&boundary.code, conn);
    // the diameter compares every pair of boundary pixels: skipped for
    // long boundaries
    let shape = (boundary.pixels.len() <= MAX_SHAPE_PIXELS)
        .then(|| chain::shape("boundary", &boundary.pixels).ok())
        .flatten();
    Ok(Traced {
        region,
        boundary,
        length,
        shape,
    })
}

/// [`fill`] on an 8-bit image: a table of each byte's side.
fn fill_bytes(g: Gray, threshold: f64, c: usize, r: usize) -> Option<(Vec<u8>, usize)> {
    let (w, h, data) = (g.width(), g.height(), g.data());
    let side: Vec<bool> = (0..=255u8).map(|v| f64::from(v) >= threshold).collect();
    let want = side[usize::from(*data.get(r * w + c).filter(|_| c < w)?)];
    let same: Vec<bool> = side.iter().map(|&s| s == want).collect();
    fill(w, h, c, r, |i| same[usize::from(data[i])])
}

/// [`fill`] on a colour photo's levels: the threshold compared as a level
/// ([`Levels::cut`]: `n ≥ cut` exactly when the grey `n / scale` is at
/// least the threshold).
fn fill_levels(
    l: &Levels,
    w: usize,
    h: usize,
    threshold: f64,
    c: usize,
    r: usize,
) -> Option<(Vec<u8>, usize)> {
    let (cut, data) = (l.cut(threshold), &l.data[..]);
    if data.len() != w * h {
        return None;
    }
    let want = *data.get(r * w + c).filter(|_| c < w)? >= cut;
    fill(w, h, c, r, |i| (data[i] >= cut) == want)
}

/// The 8-connected region of the pixels on `(c, r)`'s side of the
/// threshold (`same(i)` for pixel `i = row·w + column`; `v ≥ threshold` or
/// not, as `chain::region_at`): a mask of 1 and 0, and its pixel count. A
/// scan-line fill: each seed is widened to its whole run of the row, then
/// the rows above and below are searched over that run and one more pixel
/// on each side (the diagonal neighbours).
fn fill(
    w: usize,
    h: usize,
    c: usize,
    r: usize,
    same: impl Fn(usize) -> bool,
) -> Option<(Vec<u8>, usize)> {
    if c >= w || r >= h {
        return None;
    }
    let mut mask = vec![0u8; w * h];
    let mut stack = vec![(c, r)];
    let mut area = 0;
    while let Some((x, y)) = stack.pop() {
        let row = y * w;
        if mask[row + x] != 0 {
            continue;
        }
        let (mut x0, mut x1) = (x, x);
        while x0 > 0 && mask[row + x0 - 1] == 0 && same(row + x0 - 1) {
            x0 -= 1;
        }
        while x1 + 1 < w && mask[row + x1 + 1] == 0 && same(row + x1 + 1) {
            x1 += 1;
        }
        mask[row + x0..=row + x1].fill(1);
        area += x1 - x0 + 1;
        let (s0, s1) = (x0.saturating_sub(1), (x1 + 1).min(w - 1));
        for ny in [y.wrapping_sub(1), y + 1] {
            if ny >= h {
                continue;
            }
            let nrow = ny * w;
            let mut in_run = false;
            for nx in s0..=s1 {
                let open = mask[nrow + nx] == 0 && same(nrow + nx);
                if open && !in_run {
                    stack.push((nx, ny));
                }
                in_run = open;
            }
        }
    }
    Some((mask, area))
}

/// The outer border of the one region of `mask` as `chain::trace` gives
/// it: `chain::fast::contours`'s first border (the raster scan meets the
/// outer one first), walked the other way round from the same start.
fn outer(mask: &[u8], w: usize, h: usize, area: usize) -> Result<chain::Boundary> {
    let borders = cfast::contours(Gray::new("region", mask, w, h)?)?;
    let first = borders
        .into_iter()
        .find(|b| !b.hole)
        .ok_or_else(|| Error::Internal("a picked region has no boundary".into()))?;
    let mut pixels: Vec<chain::Pixel> = first
        .points
        .iter()
        .map(|&(c, r)| [i64::from(c), i64::from(r)])
        .collect();
    if pixels.len() > 1 {
        pixels[1..].reverse();
    }
    let n = pixels.len();
    let code = if n > 1 {
        (0..n)
            .map(|k| {
                let (a, b) = (pixels[k], pixels[(k + 1) % n]);
                Connectivity::Eight
                    .digit(b[0] - a[0], b[1] - a[1])
                    .ok_or_else(|| Error::Internal("a border step between non-neighbours".into()))
            })
            .collect::<Result<Vec<u8>>>()?
    } else {
        Vec::new()
    };
    Ok(chain::Boundary { pixels, code, area })
}
