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

/// The position of column `x` on a row whose constant part is `base`
/// (`m·(0, y, 1)`): one product and one sum per coordinate, monotone in `x`
/// (rounding is monotone), so the interior test at the two ends of a run
/// holds for every column between. It differs from [`pos`] by at most a
/// rounding of the last bit; both interpolations are continuous, so a
/// `floor` that flips at an exact integer changes the value by nothing
/// visible at `1e-4`.
#[inline(always)]
fn along(m: &Affine, base: (f64, f64), x: f64) -> (f64, f64) {
    (m[0][0] * x + base.0, m[1][0] * x + base.1)
}

fn row_base(m: &Affine, y: f64) -> (f64, f64) {
    (m[0][1] * y + m[0][2], m[1][1] * y + m[1][2])
}

/// The first and last column of row `y` whose positions are all interior
/// (`None` when there is none): solved from the linear map, then proven at
/// both ends with the expression the run uses ([`along`]).
fn interior_run(rule: Rule, m: &Affine, y: f64, width: usize) -> Option<(usize, usize)> {
    let (w, h) = (rule.w as f64, rule.h as f64);
    let (lo_u, hi_u, lo_v, hi_v) = match rule.method {
        Method::Bilinear => (0.0, w - 1.0, 0.0, h - 1.0),
        Method::Bicubic => (1.0, w - 2.0, 1.0, h - 2.0),
        // rounding `u + 0.5` near the last pixel: always the checked path
        Method::Nearest => return None,
    };
    let base = row_base(m, y);
    let mut lo = 0.0f64;
    let mut hi = width as f64 - 1.0;
    for (k, (a, b)) in [(lo_u, hi_u), (lo_v, hi_v)].into_iter().enumerate() {
        let slope = m[k][0];
        let b0 = if k == 0 { base.0 } else { base.1 };
        if slope == 0.0 {
            if !(b0 >= a && b0 < b) {
                return None;
            }
            continue;
        }
        let (t1, t2) = ((a - b0) / slope, (b - b0) / slope);
        let (t_lo, t_hi) = if slope > 0.0 { (t1, t2) } else { (t2, t1) };
        lo = lo.max(t_lo.ceil() + 1.0);
        hi = hi.min(t_hi.floor() - 1.0);
    }
    if !(lo.is_finite() && hi.is_finite()) || lo > hi || lo < 0.0 {
        return None;
    }
    let (c0, c1) = (lo as usize, hi as usize);
    let (u0, v0) = along(m, base, c0 as f64);
    let (u1, v1) = along(m, base, c1 as f64);
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
        let base = row_base(m, yf);
        match method {
            Method::Bilinear => bilinear_run(img, m, base, c0, run),
            Method::Bicubic => bicubic_run(img, m, base, c0, a, run),
            Method::Nearest => {
                for (k, o) in run.iter_mut().enumerate() {
                    *o = checked(c0 + k);
                }
            }
        }
    }
    Ok(())
}

/// Pixel `i` of an interior neighbourhood, unchecked.
///
/// Safety: `i < src.len()`. The runs call it only for columns between the
/// two ends [`interior_run`] proved interior (positions monotone along the
/// row, [`along`]), whose neighbourhoods lie inside the `w × h` image, and
/// [`Gray`] holds exactly `w·h` bytes.
#[inline(always)]
unsafe fn px(src: &[u8], i: usize) -> f64 {
    debug_assert!(i < src.len());
    f64::from(*src.get_unchecked(i))
}

/// Bilinear over a run of interior columns starting at `c0`: positions
/// along the row ([`along`]), no position test and no bounds check.
fn bilinear_run(img: Gray, m: &Affine, base: (f64, f64), c0: usize, run: &mut [f32]) {
    let (src, w) = (img.data(), img.width());
    for (k, o) in run.iter_mut().enumerate() {
        let (u, v) = along(m, base, (c0 + k) as f64);
        let (fu, fv) = (u.floor(), v.floor());
        let i = fv as usize * w + fu as usize;
        let (dc, dr) = (u - fu, v - fv);
        // SAFETY: an interior position (see `px`): i + w + 1 < w·h.
        let (p0, p1, p2, p3) = unsafe {
            (
                px(src, i),
                px(src, i + 1),
                px(src, i + w),
                px(src, i + w + 1),
            )
        };
        let i1 = p0 + dc * (p1 - p0);
        let i2 = p2 + dc * (p3 - p2);
        *o = (i1 + dr * (i2 - i1)) as f32;
    }
}

/// Bicubic over a run of interior columns starting at `c0`.
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
fn bicubic_run(img: Gray, m: &Affine, base: (f64, f64), c0: usize, a: f64, run: &mut [f32]) {
    let (src, w) = (img.data(), img.width());
    for (k, o) in run.iter_mut().enumerate() {
        let (u, v) = along(m, base, (c0 + k) as f64);
        let (fu, fv) = (u.floor(), v.floor());
        let (wc, wr) = (cubic4(u - fu, a), cubic4(v - fv, a));
        let top = (fv as usize - 1) * w + fu as usize - 1;
        let mut acc = 0.0f64;
        for (j, wj) in wr.iter().enumerate() {
            let s = top + j * w;
            // SAFETY: an interior position (see `px`): the 4×4 block from
            // `top` lies inside the image.
            let row = unsafe {
                px(src, s) * wc[0]
                    + px(src, s + 1) * wc[1]
                    + px(src, s + 2) * wc[2]
                    + px(src, s + 3) * wc[3]
            };
            acc += wj * row;
        }
        *o = acc as f32;
    }
}

/// Bicubic over a run of interior columns, `f64x2` lanes: the fractions of
/// `u` and `v` share the weight polynomials (one lane each), the 16 bytes
/// are widened together and each row's four become two `f64x2`, and the
/// 16 products are summed in `f64` as in the scalar path.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn bicubic_run(img: Gray, m: &Affine, base: (f64, f64), c0: usize, a: f64, run: &mut [f32]) {
    use core::arch::wasm32::*;
    let (src, w) = (img.data(), img.width());
    let (one, two) = (f64x2_splat(1.0), f64x2_splat(2.0));
    let (a2, a3) = (f64x2_splat(a + 2.0), f64x2_splat(a + 3.0));
    let (av, a5, a8, a4) = (
        f64x2_splat(a),
        f64x2_splat(5.0 * a),
        f64x2_splat(8.0 * a),
        f64x2_splat(4.0 * a),
    );
    let near = |x: v128| {
        f64x2_add(
            f64x2_mul(f64x2_sub(f64x2_mul(a2, x), a3), f64x2_mul(x, x)),
            one,
        )
    };
    let far = |x: v128| {
        f64x2_sub(
            f64x2_mul(
                f64x2_add(f64x2_mul(f64x2_sub(f64x2_mul(av, x), a5), x), a8),
                x,
            ),
            a4,
        )
    };
    let slope = f64x2(m[0][0], m[1][0]);
    let b = f64x2(base.0, base.1);
    for (k, o) in run.iter_mut().enumerate() {
        let uv = f64x2_add(f64x2_mul(slope, f64x2_splat((c0 + k) as f64)), b);
        let fl = f64x2_floor(uv);
        let st = f64x2_sub(uv, fl);
        let n0 = near(st); // [wc1, wr1]
        let n1 = near(f64x2_sub(one, st)); // [wc2, wr2]
        let f0 = far(f64x2_add(one, st)); // [wc0, wr0]
        let f1 = far(f64x2_sub(two, st)); // [wc3, wr3]
        let wc01 = i64x2_shuffle::<0, 2>(f0, n0);
        let wc23 = i64x2_shuffle::<0, 2>(n1, f1);
        let (fu, fv) = (f64x2_extract_lane::<0>(fl), f64x2_extract_lane::<1>(fl));
        let top = (fv as usize - 1) * w + fu as usize - 1;
        // SAFETY: an interior position (see `px`): the 4×4 block from `top`
        // lies inside the image, so each 4-byte read is in bounds.
        let q = |j: usize| unsafe {
            debug_assert!(top + j * w + 4 <= src.len());
            (src.as_ptr().add(top + j * w) as *const u32).read_unaligned()
        };
        let bytes = u32x4(q(0), q(1), q(2), q(3));
        // bytes → u16 → u32 (rows 0, 1 | rows 2, 3), then per row
        // [p0, p1] and [p2, p3] as f64 (the integers are exact)
        let (h01, h23) = (
            u16x8_extend_low_u8x16(bytes),
            u16x8_extend_high_u8x16(bytes),
        );
        let rows = [
            u32x4_extend_low_u16x8(h01),
            u32x4_extend_high_u16x8(h01),
            u32x4_extend_low_u16x8(h23),
            u32x4_extend_high_u16x8(h23),
        ];
        let row = |p: v128| {
            let lo = f64x2_convert_low_i32x4(p);
            let hi = f64x2_convert_low_i32x4(i64x2_shuffle::<1, 1>(p, p));
            f64x2_add(f64x2_mul(lo, wc01), f64x2_mul(hi, wc23))
        };
        let (r0, r1, r2, r3) = (row(rows[0]), row(rows[1]), row(rows[2]), row(rows[3]));
        let acc = f64x2_add(
            f64x2_add(
                f64x2_mul(r0, i64x2_shuffle::<1, 1>(f0, f0)),
                f64x2_mul(r1, i64x2_shuffle::<1, 1>(n0, n0)),
            ),
            f64x2_add(
                f64x2_mul(r2, i64x2_shuffle::<1, 1>(n1, n1)),
                f64x2_mul(r3, i64x2_shuffle::<1, 1>(f1, f1)),
            ),
        );
        *o = (f64x2_extract_lane::<0>(acc) + f64x2_extract_lane::<1>(acc)) as f32;
    }
}
