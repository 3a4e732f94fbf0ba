//! Resampling a grid at a fractional position: nearest neighbour, bilinear
//! (with the seeds' row interpolations `I1`, `I2` and the final `I`) and
//! bicubic as seed 004's cubic convolution.
//!
//! Positions are continuous grid coordinates: `x` counts columns and `y`
//! rows from the centre of pixel `(0, 0)`, so integer positions are pixel
//! centres. A position whose neighbourhood is not inside the grid gives
//! `None`: nothing is read out of bounds and nothing is extrapolated.

use crate::raster::Grid;

pub mod fast;

/// Seed 004's cubic convolution kernel is `a = −1` of the family
/// `f(x) = (a+2)|x|³ − (a+3)|x|² + 1` for `|x| < 1`,
/// `a|x|³ − 5a|x|² + 8a|x| − 4a` for `1 ≤ |x| < 2`, 0 beyond:
/// `1 − 2|x|² + |x|³` and `4 − 8|x| + 5|x|² − |x|³`.
pub const SEED_A: f64 = -1.0;

/// The cubic convolution kernel with parameter `a` (seed 004: `a = −1`;
/// Keys' `a = −1/2` also reproduces linear and quadratic ramps).
pub fn cubic(x: f64, a: f64) -> f64 {
    let x = x.abs();
    if x < 1.0 {
        (a + 2.0) * x * x * x - (a + 3.0) * x * x + 1.0
    } else if x < 2.0 {
        a * x * x * x - 5.0 * a * x * x + 8.0 * a * x - 4.0 * a
    } else {
        0.0
    }
}

/// The four weights `[f(1+s), f(s), f(1−s), f(2−s)]` of the pixels at
/// offsets −1, 0, 1, 2 from `[u]`, for the fraction `s = u − [u]`.
/// They sum to 1 for every `s` and `a`.
pub fn cubic_weights(s: f64, a: f64) -> [f64; 4] {
    [
        cubic(1.0 + s, a),
        cubic(s, a),
        cubic(1.0 - s, a),
        cubic(2.0 - s, a),
    ]
}

/// True when `x` lies in `[0, n − 1]` (between the first and last pixel centre).
fn within(x: f64, n: usize) -> bool {
    x.is_finite() && x >= 0.0 && x <= (n as f64 - 1.0)
}

/// The nearest pixel and its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Nearest {
    /// Column and row of the nearest pixel (zero-based).
    pub c: usize,
    pub r: usize,
    pub value: f64,
}

/// The pixel nearest to `(x, y)`: both rounded, halves up (`2.5 → 3`).
/// `None` when the rounded position is not a pixel of the grid.
pub fn nearest(img: &Grid, x: f64, y: f64) -> Option<Nearest> {
    let (cx, ry) = ((x + 0.5).floor(), (y + 0.5).floor());
    if !(cx >= 0.0 && ry >= 0.0) {
        return None;
    }
    let (c, r) = (cx as usize, ry as usize);
    img.get(c, r).map(|value| Nearest { c, r, value })
}

/// Bilinear interpolation with its intermediates, as the seed writes it:
/// `I1 = P00 + dc·(P10 − P00)` along the upper row, `I2 = P01 + dc·(P11 − P01)`
/// along the lower row, then `I = I1 + dr·(I2 − I1)` between them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bilinear {
    /// The upper-left pixel of the 2×2 neighbourhood (zero-based).
    pub c: usize,
    pub r: usize,
    /// Fractions from it, in `[0, 1]`.
    pub dc: f64,
    pub dr: f64,
    /// `[P(c, r), P(c+1, r), P(c, r+1), P(c+1, r+1)]`.
    pub p: [f64; 4],
    pub i1: f64,
    pub i2: f64,
    pub value: f64,
}

impl Bilinear {
    /// The weights of the four pixels, in the order of `p`:
    /// `(1−dc)(1−dr), dc(1−dr), (1−dc)dr, dc·dr`.
    pub fn weights(&self) -> [f64; 4] {
        let (dc, dr) = (self.dc, self.dr);
        [
            (1.0 - dc) * (1.0 - dr),
            dc * (1.0 - dr),
            (1.0 - dc) * dr,
            dc * dr,
        ]
    }
}

/// One linear interpolation, `a + t·(b − a)`, as the seed writes each
/// stage of bilinear interpolation (practice carries a student's stages
/// forward with it).
pub fn lerp(a: f64, b: f64, t: f64) -> f64 {
    a + t * (b - a)
}

/// Bilinear interpolation at `(x, y)`. The 2×2 neighbourhood starts at
/// `([x], [y])`, moved one pixel back on the last column or row so that a
/// position on the last pixel centre still has one (with `dc` or `dr` = 1).
/// `None` outside `[0, width−1] × [0, height−1]` or for a grid narrower or
/// lower than 2 pixels.
pub fn bilinear(img: &Grid, x: f64, y: f64) -> Option<Bilinear> {
    let (w, h) = (img.width(), img.height());
    if w < 2 || h < 2 || !within(x, w) || !within(y, h) {
        return None;
    }
    let c = (x.floor() as usize).min(w - 2);
    let r = (y.floor() as usize).min(h - 2);
    let (dc, dr) = (x - c as f64, y - r as f64);
    let p = [
        img.get(c, r)?,
        img.get(c + 1, r)?,
        img.get(c, r + 1)?,
        img.get(c + 1, r + 1)?,
    ];
    let i1 = lerp(p[0], p[1], dc);
    let i2 = lerp(p[2], p[3], dc);
    let value = lerp(i1, i2, dr);
    Some(Bilinear {
        c,
        r,
        dc,
        dr,
        p,
        i1,
        i2,
        value,
    })
}

/// Cubic convolution with its intermediates, in seed 004's layout
/// `Q = [f(1+t) f(t) f(1−t) f(2−t)] · P · [f(1+s) f(s) f(1−s) f(2−s)]ᵀ`
/// with `s = u − [u]` along the columns, `t = v − [v]` along the rows and
/// `P` the 4×4 pixels from `([u]−1, [v]−1)` to `([u]+2, [v]+2)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Bicubic {
    /// The upper-left pixel of the 4×4 neighbourhood (zero-based).
    pub c: usize,
    pub r: usize,
    /// Fractions `s` (columns) and `t` (rows).
    pub s: f64,
    pub t: f64,
    /// Kernel parameter used.
    pub a: f64,
    /// Column weights `f(1+s) … f(2−s)` and row weights `f(1+t) … f(2−t)`.
    pub wc: [f64; 4],
    pub wr: [f64; 4],
    /// `P`, row by row.
    pub p: [[f64; 4]; 4],
    /// Each row of `P` interpolated along the columns: `P · wc`.
    pub rows: [f64; 4],
    /// `wr · (P · wc)`.
    pub value: f64,
}

/// Cubic convolution at `(x, y)` with kernel parameter `a`; `None` unless the
/// whole 4×4 neighbourhood `[x]−1 … [x]+2`, `[y]−1 … [y]+2` is inside.
pub fn bicubic(img: &Grid, x: f64, y: f64, a: f64) -> Option<Bicubic> {
    if !within(x, img.width()) || !within(y, img.height()) || !a.is_finite() {
        return None;
    }
    let (fx, fy) = (x.floor(), y.floor());
    if fx < 1.0 || fy < 1.0 {
        return None;
    }
    let (c, r) = (fx as usize - 1, fy as usize - 1);
    let patch = img.window(c, r, 4, 4)?;
    let (s, t) = (x - fx, y - fy);
    let (wc, wr) = (cubic_weights(s, a), cubic_weights(t, a));
    let mut p = [[0.0; 4]; 4];
    let mut rows = [0.0; 4];
    for (j, row) in p.iter_mut().enumerate() {
        for (i, v) in row.iter_mut().enumerate() {
            *v = patch.get(i, j)?;
        }
        rows[j] = row.iter().zip(&wc).map(|(v, w)| v * w).sum();
    }
    let value = rows.iter().zip(&wr).map(|(v, w)| v * w).sum();
    Some(Bicubic {
        c,
        r,
        s,
        t,
        a,
        wc,
        wr,
        p,
        rows,
        value,
    })
}

/// The three interpolation methods, for whole-image resampling.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    Nearest,
    Bilinear,
    /// Seed 004's cubic convolution ([`SEED_A`]).
    Bicubic,
}

/// The value at `(x, y)` by `method`: [`nearest`], [`bilinear`] or
/// [`bicubic`] with [`SEED_A`], nothing else (`None` where that function
/// gives `None`).
pub fn value_at(img: &Grid, x: f64, y: f64, method: Method) -> Option<f64> {
    match method {
        Method::Nearest => nearest(img, x, y).map(|n| n.value),
        Method::Bilinear => bilinear(img, x, y).map(|b| b.value),
        Method::Bicubic => bicubic(img, x, y, SEED_A).map(|b| b.value),
    }
}

/// A `width × height` image whose pixel `(c, r)` is the input resampled at
/// `map(c, r)` (output → input position, "indirect" resampling) by
/// `method`; `fill` where [`value_at`] has no value (outside the input, or
/// too near its edge for the method's neighbourhood).
pub fn warp(
    img: &Grid,
    width: usize,
    height: usize,
    map: impl Fn(f64, f64) -> (f64, f64),
    method: Method,
    fill: f64,
) -> Grid {
    Grid::from_fn(width, height, |c, r| {
        let (x, y) = map(c as f64, r as f64);
        value_at(img, x, y, method).unwrap_or(fill)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seed_kernel_matches_the_printed_weight_formulas() {
        for k in 0..=10 {
            let y = f64::from(k) / 10.0;
            let w = cubic_weights(y, SEED_A);
            let printed = [
                -y * (1.0 - y) * (1.0 - y),
                (1.0 - y) + y * (1.0 - y) * (1.0 - y),
                y + y * y * (1.0 - y),
                -y * y * (1.0 - y),
            ];
            for (a, b) in w.iter().zip(printed) {
                assert!((a - b).abs() < 1e-14);
            }
        }
    }

    #[test]
    fn neighbourhoods_outside_are_none() {
        let g = Grid::from_fn(4, 4, |c, r| (c + 10 * r) as f64);
        assert!(bilinear(&g, 3.0, 3.0).is_some());
        assert!(bilinear(&g, 3.01, 0.0).is_none());
        assert!(bicubic(&g, 0.5, 1.5, SEED_A).is_none());
        assert!(bicubic(&g, 1.5, 1.5, SEED_A).is_some());
        assert!(bicubic(&g, 2.5, 1.5, SEED_A).is_none());
        assert!(nearest(&g, -0.6, 0.0).is_none());
        assert_eq!(nearest(&g, 2.5, 0.4).map(|n| n.c), Some(3));
    }
}
