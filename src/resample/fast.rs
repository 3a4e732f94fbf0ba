//! Affine warps of an 8-bit image, bilinear or bicubic, `f32` output:
//! [`super::warp`] with the map `(x, y) ↦ (m₀₀x + m₀₁y + m₀₂, m₁₀x + m₁₁y + m₁₂)`
//! and the same rules for where a value exists ([`super::bilinear`],
//! [`super::bicubic`]), `fill` elsewhere.
//!
//! Per output row the columns whose whole neighbourhood lies inside are
//! found once (the map is linear in the column, and the rounded
//! coordinates are monotone in it, so checking the two ends of the run
//! proves every column between); those run without any position test, the
//! few columns outside the run take the checked path. Positions are
//! computed per pixel in `f64` with the reference's expression, so both
//! take the same pixel and fraction; the interpolation is in `f64` (scalar `f64` costs what `f32` does), stored as `f32`.

use crate::error::{Error, Result};
use crate::raster::{check_len, Gray};

use super::Method;

/// An affine output → input map `[[m00, m01, m02], [m10, m11, m12]]`.
pub type Affine = [[f64; 3]; 2];

fn pos(m: &Affine, x: f64, y: f64) -> (f64, f64) {
    (
        m[0][0] * x + m[0][1] * y + m[0][2],
        m[1][0] * x + m[1][1] * y + m[1][2],
    )
}

/// The cubic convolution weights `[f(1+s), f(s), f(1−s), f(2−s)]` in `f32`
/// (the polynomials of [`super::cubic`] on each piece).
fn cubic4(s: f64, a: f64) -> [f64; 4] {
    let near = |x: f64| ((a + 2.0) * x - (a + 3.0)) * x * x + 1.0;
    let far = |x: f64| ((a * x - 5.0 * a) * x + 8.0 * a) * x - 4.0 * a;
    [far(1.0 + s), near(s), near(1.0 - s), far(2.0 - s)]
}

/// What each method needs around a position.
#[derive(Clone, Copy)]
struct Rule {
    w: usize,
    h: usize,
    method: Method,
}

impl Rule {
    /// The top-left pixel of the neighbourhood and the fractions, when the
    /// reference has a value at `(u, v)` (exactly its tests).
    fn locate(self, u: f64, v: f64) -> Option<(usize, usize, f64, f64)> {
        let (w, h) = (self.w, self.h);
        let within = |x: f64, n: usize| x.is_finite() && x >= 0.0 && x <= n as f64 - 1.0;
        if self.method != Method::Nearest && (!within(u, w) || !within(v, h)) {
            return None;
        }
        match self.method {
            Method::Bilinear => {
                if w < 2 || h < 2 {
                    return None;
                }
                let c = (u.floor() as usize).min(w - 2);
                let r = (v.floor() as usize).min(h - 2);
                Some((c, r, u - c as f64, v - r as f64))
            }
            Method::Bicubic => {
                let (fx, fy) = (u.floor(), v.floor());
                if fx < 1.0 || fy < 1.0 || fx + 2.0 > w as f64 - 1.0 || fy + 2.0 > h as f64 - 1.0 {
                    return None;
                }
                Some((fx as usize - 1, fy as usize - 1, u - fx, v - fy))
            }
            Method::Nearest => {
                let (cx, ry) = ((u + 0.5).floor(), (v + 0.5).floor());
                (cx >= 0.0 && ry >= 0.0 && cx < w as f64 && ry < h as f64).then_some((
                    cx as usize,
                    ry as usize,
                    0.0,
                    0.0,
                ))
            }
        }
    }

    /// Whether `(u, v)` is strictly inside the part where [`Rule::locate`]
    /// takes the plain `floor` neighbourhood (no edge adjustment).
    fn interior(self, u: f64, v: f64) -> bool {
        let (w, h) = (self.w as f64, self.h as f64);
        match self.method {
            Method::Bilinear => u >= 0.0 && v >= 0.0 && u < w - 1.0 && v < h - 1.0,
            Method::Bicubic => u >= 1.0 && v >= 1.0 && u < w - 2.0 && v < h - 2.0,
            Method::Nearest => false,
        }
    }
}

/// One sample from a located neighbourhood.
fn sample(src: &[u8], w: usize, method: Method, a: f64, loc: (usize, usize, f64, f64)) -> f32 {
    let (c, r, fu, fv) = loc;
    let p = |i: usize, j: usize| f64::from(src.get((r + j) * w + c + i).copied().unwrap_or(0));
    let v = match method {
        Method::Nearest => p(0, 0),
        Method::Bilinear => {
            let (dc, dr) = (fu, fv);
            let i1 = p(0, 0) + dc * (p(1, 0) - p(0, 0));
            let i2 = p(0, 1) + dc * (p(1, 1) - p(0, 1));
            i1 + dr * (i2 - i1)
        }
        Method::Bicubic => {
            let (wc, wr) = (cubic4(fu, a), cubic4(fv, a));
            let mut v = 0.0;
            for (j, wj) in wr.iter().enumerate() {
                let row = (0..4).map(|i| p(i, j) * wc[i]).sum::<f64>();
                v += wj * row;
            }
            v
        }
    };
    v as f32
}

/// The first and last column of row `y` whose positions are all interior
/// (`None` when there is none): solved from the linear map, then proven at
/// both ends.
fn interior_run(rule: Rule, m: &Affine, y: f64, width: usize) -> Option<(usize, usize)> {
    let (w, h) = (rule.w as f64, rule.h as f64);
    let (lo_u, hi_u, lo_v, hi_v) = match rule.method {
        Method::Bilinear => (0.0, w - 1.0, 0.0, h - 1.0),
        Method::Bicubic => (1.0, w - 2.0, 1.0, h - 2.0),
        // rounding `u + 0.5` near the last pixel: always the checked path
        Method::Nearest => return None,
    };
    let mut lo = 0.0f64;
    let mut hi = width as f64 - 1.0;
    for (k, (a, b)) in [(lo_u, hi_u), (lo_v, hi_v)].into_iter().enumerate() {
        let slope = m[k][0];
        let base = m[k][1] * y + m[k][2];
        if slope == 0.0 {
            if !(base >= a && base < b) {
                return None;
            }
            continue;
        }
        let (t1, t2) = ((a - base) / slope, (b - base) / slope);
        let (t_lo, t_hi) = if slope > 0.0 { (t1, t2) } else { (t2, t1) };
        lo = lo.max(t_lo.ceil() + 1.0);
        hi = hi.min(t_hi.floor() - 1.0);
    }
    if !(lo.is_finite() && hi.is_finite()) || lo > hi || lo < 0.0 {
        return None;
    }
    let (c0, c1) = (lo as usize, hi as usize);
    let (u0, v0) = pos(m, c0 as f64, y);
    let (u1, v1) = pos(m, c1 as f64, y);
    (rule.interior(u0, v0) && rule.interior(u1, v1)).then_some((c0, c1))
}

/// Warps `img` into an `out_w × out_h` image (`out`, row-major): output
/// pixel `(x, y)` is the input at `m·(x, y, 1)` by `method` (bicubic with
/// kernel parameter `a`), `fill` where the reference has no value.
pub fn warp_affine(
    img: Gray,
    m: &Affine,
    method: Method,
    a: f64,
    fill: f32,
    (out_w, out_h): (usize, usize),
    out: &mut [f32],
) -> Result<()> {
    if m.iter().flatten().any(|v| !v.is_finite()) || !a.is_finite() {
        return Err(Error::input("map", "must be finite numbers"));
    }
    check_len("output", out, out_w * out_h)?;
    let rule = Rule {
        w: img.width(),
        h: img.height(),
        method,
    };
    let (src, w) = (img.data(), img.width());
    for (y, row) in out.chunks_exact_mut(out_w.max(1)).enumerate() {
        let yf = y as f64;
        let checked = |x: usize| {
            let (u, v) = pos(m, x as f64, yf);
            rule.locate(u, v)
                .map_or(fill, |loc| sample(src, w, method, a, loc))
        };
        let Some((c0, c1)) = interior_run(rule, m, yf, out_w) else {
            for (x, o) in row.iter_mut().enumerate() {
                *o = checked(x);
            }
            continue;
        };
        for (x, o) in row.iter_mut().enumerate().take(c0) {
            *o = checked(x);
        }
        for (x, o) in row.iter_mut().enumerate().skip(c1 + 1) {
            *o = checked(x);
        }
        let run = row.get_mut(c0..=c1).unwrap_or(&mut []);
        match method {
            Method::Bilinear => bilinear_run(src, w, m, yf, c0, run),
            Method::Bicubic => bicubic_run(src, w, m, yf, c0, a, run),
            Method::Nearest => {
                for (k, o) in run.iter_mut().enumerate() {
                    *o = checked(c0 + k);
                }
            }
        }
    }
    Ok(())
}

/// Bilinear over a run of interior columns starting at `c0`.
fn bilinear_run(src: &[u8], w: usize, m: &Affine, y: f64, c0: usize, run: &mut [f32]) {
    for (k, o) in run.iter_mut().enumerate() {
        let (u, v) = pos(m, (c0 + k) as f64, y);
        let (fu, fv) = (u.floor(), v.floor());
        let i = fv as usize * w + fu as usize;
        let (dc, dr) = (u - fu, v - fv);
        let q = src.get(i..i + 2).unwrap_or(&[0, 0]);
        let s = src.get(i + w..i + w + 2).unwrap_or(&[0, 0]);
        let (p0, p1) = (f64::from(q[0]), f64::from(q[1]));
        let (p2, p3) = (f64::from(s[0]), f64::from(s[1]));
        let i1 = p0 + dc * (p1 - p0);
        let i2 = p2 + dc * (p3 - p2);
        *o = (i1 + dr * (i2 - i1)) as f32;
    }
}

/// Bicubic over a run of interior columns starting at `c0`.
fn bicubic_run(src: &[u8], w: usize, m: &Affine, y: f64, c0: usize, a: f64, run: &mut [f32]) {
    for (k, o) in run.iter_mut().enumerate() {
        let (u, v) = pos(m, (c0 + k) as f64, y);
        let (fu, fv) = (u.floor(), v.floor());
        let (wc, wr) = (cubic4(u - fu, a), cubic4(v - fv, a));
        let top = (fv as usize - 1) * w + fu as usize - 1;
        let mut acc = 0.0f64;
        for (j, wj) in wr.iter().enumerate() {
            let s = top + j * w;
            let p = src.get(s..s + 4).unwrap_or(&[0, 0, 0, 0]);
            let row = f64::from(p[0]) * wc[0]
                + f64::from(p[1]) * wc[1]
                + f64::from(p[2]) * wc[2]
                + f64::from(p[3]) * wc[3];
            acc += wj * row;
        }
        *o = acc as f32;
    }
}
