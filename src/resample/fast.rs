//! Affine warps of an 8-bit image, bilinear or bicubic, `f32` output:
//! [`super::warp`] with the map `(x, y) ↦ (m₀₀x + m₀₁y + m₀₂, m₁₀x + m₁₁y + m₁₂)`
//! and the same rules for where a value exists ([`super::bilinear`],
//! [`super::bicubic`]), `fill` elsewhere.
//!
//! Per output row the columns whose whole neighbourhood lies inside are
//! found once (the map is linear in the column, and the rounded
//! coordinates are monotone in it, so checking the two ends of the run
//! proves every column between); those run without any position test, the
//! few columns outside the run take the checked path, whose positions are
//! the reference's expression in `f64`.
//!
//! Inside a run, the scalar build computes each position along the row in
//! `f64` and interpolates in `f64`. The `+simd128` build steps exact
//! fixed-point positions (40 fraction bits, `fixed_run`, proven interior
//! at both ends again; integer adds and shifts instead of `f64x2` floor,
//! truncation and demotion per pixel took T5 bilinear at 2048² in Node
//! from 33 to 14 ms of CPU time, bicubic from 72 to 49) and then
//! interpolates bilinear in `f32x4` over four output pixels (error bound
//! 6.8·10⁻⁵, below the 1e-4 rule; see `bilinear_run`) and bicubic in
//! `f64x2` per pixel. The output is stored as `f32`.

use crate::error::{Error, Result};
use crate::raster::{check_len, Gray, GrayF32};

use super::Method;

/// What the warps read: an 8-bit image ([`Gray`]) or whole-number levels
/// over one scale ([`Levels`]: a colour photo's `n = 299·R + 587·G +
/// 114·B` over 1000). Each value is read as `f64` (exact), interpolated as
/// the reference interpolates, and the result divided by the scale once
/// ([`Source::out`]).
pub trait Source: Copy {
    fn width(&self) -> usize;
    fn height(&self) -> usize;
    /// Pixel `i` (row-major) as `f64`, 0 outside.
    fn get(&self, i: usize) -> f64;
    /// Pixel `i`, unchecked.
    ///
    /// # Safety
    /// `i < width · height`.
    unsafe fn get_unchecked(&self, i: usize) -> f64;
    /// An interpolated value of the levels as the output's grey.
    fn out(&self, v: f64) -> f32;
    /// Bilinear over a run of interior columns (see [`bilinear_scalar`]).
    fn bilinear_run(self, m: &Affine, base: (f64, f64), c0: usize, run: &mut [f32]) {
        bilinear_scalar(self, m, base, c0, run);
    }
    /// Bicubic over a run of interior columns (see [`bicubic_scalar`]).
    fn bicubic_run(self, m: &Affine, base: (f64, f64), c0: usize, a: f64, run: &mut [f32]) {
        bicubic_scalar(self, m, base, c0, a, run);
    }
}

impl Source for Gray<'_> {
    fn width(&self) -> usize {
        Gray::width(self)
    }
    fn height(&self) -> usize {
        Gray::height(self)
    }
    fn get(&self, i: usize) -> f64 {
        f64::from(self.data().get(i).copied().unwrap_or(0))
    }
    #[inline(always)]
    unsafe fn get_unchecked(&self, i: usize) -> f64 {
        debug_assert!(i < self.data().len());
        f64::from(*self.data().get_unchecked(i))
    }
    #[inline(always)]
    fn out(&self, v: f64) -> f32 {
        v as f32
    }
    fn bilinear_run(self, m: &Affine, base: (f64, f64), c0: usize, run: &mut [f32]) {
        bilinear_run(self, m, base, c0, run);
    }
    fn bicubic_run(self, m: &Affine, base: (f64, f64), c0: usize, a: f64, run: &mut [f32]) {
        bicubic_run(self, m, base, c0, a, run);
    }
}

/// Whole-number levels `n` (exact in `f32`) whose greys are `n / scale`:
/// interpolated in `f64` on `n` (the scalar runs), each result divided by
/// `scale` once. Against the reference on the divided greys: the same
/// expression scaled, so within a few `f64` roundings (≈ 10⁻¹⁵ relative
/// of the neighbourhood's largest grey) before the `f32` rounding; nearest
/// neighbours are the greys themselves.
#[derive(Debug, Clone, Copy)]
pub struct Levels<'a> {
    img: GrayF32<'a>,
    scale: f64,
}

impl<'a> Levels<'a> {
    /// `img`'s values over `scale` (finite, greater than 0).
    pub fn new(img: GrayF32<'a>, scale: f64) -> Result<Self> {
        if !(scale.is_finite() && scale > 0.0) {
            return Err(Error::input(
                "scale",
                "must be a finite number greater than 0",
            ));
        }
        Ok(Levels { img, scale })
    }
}

impl Source for Levels<'_> {
    fn width(&self) -> usize {
        self.img.width()
    }
    fn height(&self) -> usize {
        self.img.height()
    }
    fn get(&self, i: usize) -> f64 {
        f64::from(self.img.data().get(i).copied().unwrap_or(0.0))
    }
    #[inline(always)]
    unsafe fn get_unchecked(&self, i: usize) -> f64 {
        debug_assert!(i < self.img.data().len());
        f64::from(*self.img.data().get_unchecked(i))
    }
    #[inline(always)]
    fn out(&self, v: f64) -> f32 {
        (v / self.scale) as f32
    }
}

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
fn sample<S: Source>(src: S, method: Method, a: f64, loc: (usize, usize, f64, f64)) -> f32 {
    let (c, r, fu, fv) = loc;
    let w = src.width();
    let p = |i: usize, j: usize| src.get((r + j) * w + c + i);
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
    src.out(v)
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
pub fn warp_affine<S: Source>(
    img: S,
    m: &Affine,
    method: Method,
    a: f64,
    fill: f32,
    size: (usize, usize),
    out: &mut [f32],
) -> Result<()> {
    warp_affine_with(img, m, &|x, y| pos(m, x, y), method, a, fill, size, out)
}

/// [`warp_affine`], the positions of the checked columns (those outside
/// the interior runs, and every column of `Nearest`) from `exact(x, y)`:
/// the caller's own expression of the same map (the reference's closure),
/// so that where a value exists and which pixel is nearest are decided on
/// the reference's positions to the bit; `m` serves inside the runs,
/// whose neighbourhoods lie inside with a column to spare.
#[allow(clippy::too_many_arguments)]
pub fn warp_affine_with<S: Source>(
    img: S,
    m: &Affine,
    exact: &dyn Fn(f64, f64) -> (f64, f64),
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
    for (y, row) in out.chunks_exact_mut(out_w.max(1)).enumerate() {
        let yf = y as f64;
        let checked = |x: usize| {
            let (u, v) = exact(x as f64, yf);
            rule.locate(u, v)
                .map_or(fill, |loc| sample(img, method, a, loc))
        };
        if method == Method::Nearest {
            nearest_row(img, m, yf, row, checked);
            continue;
        }
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
            Method::Bilinear => img.bilinear_run(m, base, c0, run),
            Method::Bicubic => img.bicubic_run(m, base, c0, a, run),
            Method::Nearest => {
                for (k, o) in run.iter_mut().enumerate() {
                    *o = checked(c0 + k);
                }
            }
        }
    }
    Ok(())
}

/// Nearest neighbours of one output row: the affine position along the
/// row rounded where it lies more than 10⁻⁹ px from a rounding edge and
/// inside (the caller's own position is within 10⁻¹² px of it there, so
/// both round alike); `checked(x)` (the caller's position, the reference's
/// rules) elsewhere.
fn nearest_row<S: Source>(
    img: S,
    m: &Affine,
    y: f64,
    row: &mut [f32],
    checked: impl Fn(usize) -> f32,
) {
    const EDGE: f64 = 1e-9;
    let (w, h) = (img.width() as f64, img.height() as f64);
    let base = row_base(m, y);
    for (x, o) in row.iter_mut().enumerate() {
        let (u, v) = along(m, base, x as f64);
        let (fu, fv) = (u + 0.5, v + 0.5);
        let (cu, cv) = (fu.floor(), fv.floor());
        let (du, dv) = (fu - cu, fv - cv);
        let clear = du > EDGE && du < 1.0 - EDGE && dv > EDGE && dv < 1.0 - EDGE;
        *o = if clear && cu >= 0.0 && cv >= 0.0 && cu < w && cv < h {
            img.out(img.get(cv as usize * img.width() + cu as usize))
        } else {
            checked(x)
        };
    }
}

/// Any output → input map (a projective one): output pixel `(x, y)` is
/// the input at `map(x, y)` by `method`, with the reference's rules for
/// where a value exists ([`super::warp`]), one checked sample per pixel
/// from the 8-bit image (no allocation, no `f64` image).
#[allow(clippy::too_many_arguments)]
pub fn warp_map<S: Source>(
    img: S,
    map: &dyn Fn(f64, f64) -> (f64, f64),
    method: Method,
    a: f64,
    fill: f32,
    (out_w, out_h): (usize, usize),
    out: &mut [f32],
) -> Result<()> {
    if !a.is_finite() {
        return Err(Error::input("a", "must be a finite number"));
    }
    check_len("output", out, out_w * out_h)?;
    let rule = Rule {
        w: img.width(),
        h: img.height(),
        method,
    };
    for (y, row) in out.chunks_exact_mut(out_w.max(1)).enumerate() {
        for (x, o) in row.iter_mut().enumerate() {
            let (u, v) = map(x as f64, y as f64);
            *o = rule
                .locate(u, v)
                .map_or(fill, |loc| sample(img, method, a, loc));
        }
    }
    Ok(())
}

/// Pixel `i` of an interior neighbourhood, unchecked.
///
/// Safety: `i < w·h`. The runs call it only for columns between the two
/// ends [`interior_run`] proved interior (positions monotone along the
/// row, [`along`]), whose neighbourhoods lie inside the `w × h` image, and
/// [`Gray`] and [`GrayF32`] hold exactly `w·h` values.
#[inline(always)]
unsafe fn px<S: Source>(src: S, i: usize) -> f64 {
    src.get_unchecked(i)
}

/// Bilinear over a run of interior columns starting at `c0`: positions
/// along the row ([`along`]), no position test and no bounds check.
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
fn bilinear_run(img: Gray, m: &Affine, base: (f64, f64), c0: usize, run: &mut [f32]) {
    bilinear_scalar(img, m, base, c0, run);
}

/// The `f64` bilinear of one run (the scalar build, and the SIMD build's
/// last columns of a run).
fn bilinear_scalar<S: Source>(img: S, m: &Affine, base: (f64, f64), c0: usize, run: &mut [f32]) {
    let (src, w) = (img, img.width());
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
        *o = img.out(i1 + dr * (i2 - i1));
    }
}

/// Fraction bits of the fixed-point positions of the SIMD bilinear run.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
const FIX: i32 = 40;

/// The fixed-point positions `U(k) = U₀ + k·dU` (`2⁴⁰` per pixel) of a run
/// of `len` columns from `c0`, for one coordinate (`k = 0` map row): `Some`
/// only when both ends lie in `[lo, limit)` pixels, so (exactly linear in
/// `k`) every column between does, without overflow.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn fixed_run(slope: f64, start: f64, len: usize, lo: f64, limit: f64) -> Option<(i64, i64)> {
    let scale = (1i64 << FIX) as f64;
    if !(slope.abs() < 1e6 && (0.0..4e6).contains(&start) && limit < 4e6) {
        return None;
    }
    let (u0, du) = (
        (start * scale).round() as i64,
        (slope * scale).round() as i64,
    );
    let last = i64::try_from(len.checked_sub(1)?)
        .ok()?
        .checked_mul(du)?
        .checked_add(u0)?;
    let (lo, lim) = ((lo * scale) as i64, (limit * scale) as i64);
    (u0 >= lo && u0 < lim && last >= lo && last < lim).then_some((u0, du))
}

/// Bilinear over a run of interior columns, four output pixels per
/// `f32x4`. Positions are exact fixed-point integers `U₀ + k·dU` with 40
/// fraction bits (within `len·2⁻⁴¹` px of [`along`]'s, ≈ 2·10⁻⁹ px at
/// 4096 columns, checked interior at both ends, so at every column);
/// the integer parts index the image, the fractions' top 24 bits become
/// `f32`; the two byte pairs of each pixel are read as `u16` lanes and the
/// reference's three interpolations run in `f32`.
///
/// Error against the `f64` reference: a fraction is within `2⁻²⁴` px,
/// ≤ 255·2⁻²⁴ ≈ 1.5·10⁻⁵ in the value; every `f32` product and sum has a
/// magnitude ≤ 255 and rounds by ≤ 2⁻¹⁷ ≈ 7.6·10⁻⁶; `i1`, `i2` carry
/// ≤ 3·10⁻⁵ each and the last interpolation, a convex combination of them,
/// adds ≤ 3.8·10⁻⁵: ≤ 6.8·10⁻⁵ in all, below the 1e-4 (absolute below 1)
/// of the rule.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn bilinear_run(img: Gray, m: &Affine, base: (f64, f64), c0: usize, run: &mut [f32]) {
    use core::arch::wasm32::*;
    let (src, w, h) = (img.data(), img.width(), img.height());
    let quads = run.len() / 4;
    let (u_start, v_start) = along(m, base, c0 as f64);
    let fixed = (quads > 0)
        .then(|| {
            Some((
                fixed_run(m[0][0], u_start, run.len(), 0.0, w as f64 - 1.0)?,
                fixed_run(m[1][0], v_start, run.len(), 0.0, h as f64 - 1.0)?,
            ))
        })
        .flatten();
    let Some(((u0, du), (v0, dv))) = fixed else {
        return bilinear_scalar(img, m, base, c0, run);
    };
    let mut ua = i64x2(u0, u0.wrapping_add(du));
    let mut ub = i64x2(u0.wrapping_add(2 * du), u0.wrapping_add(3 * du));
    let mut va = i64x2(v0, v0.wrapping_add(dv));
    let mut vb = i64x2(v0.wrapping_add(2 * dv), v0.wrapping_add(3 * dv));
    let (su, sv) = (
        i64x2_splat(du.wrapping_mul(4)),
        i64x2_splat(dv.wrapping_mul(4)),
    );
    let wv = i32x4_splat(w as i32);
    let low24 = i32x4_splat(0xFF_FFFF);
    let unit = f32x4_splat(1.0 / (1u32 << 24) as f32);
    let zero = i32x4_splat(0);
    let sp = src.as_ptr();
    // integer part and fraction of four lanes (`U ≥ 0` in the run)
    let split = |a: v128, b: v128| {
        let int = i32x4_shuffle::<0, 2, 4, 6>(u64x2_shr(a, FIX as u32), u64x2_shr(b, FIX as u32));
        let f = i32x4_shuffle::<0, 2, 4, 6>(
            u64x2_shr(a, FIX as u32 - 24),
            u64x2_shr(b, FIX as u32 - 24),
        );
        (
            int,
            f32x4_mul(f32x4_convert_i32x4(v128_and(f, low24)), unit),
        )
    };
    for o in run.chunks_exact_mut(4) {
        let (col, dc) = split(ua, ub);
        let (row, dr) = split(va, vb);
        (ua, ub) = (i64x2_add(ua, su), i64x2_add(ub, su));
        (va, vb) = (i64x2_add(va, sv), i64x2_add(vb, sv));
        let idx = i32x4_add(i32x4_mul(row, wv), col);
        let (i0, i1, i2, i3) = (
            i32x4_extract_lane::<0>(idx) as usize,
            i32x4_extract_lane::<1>(idx) as usize,
            i32x4_extract_lane::<2>(idx) as usize,
            i32x4_extract_lane::<3>(idx) as usize,
        );
        // SAFETY: interior positions (`fixed_run`: col < w − 1, row < h − 1),
        // so i + w + 1 < w·h for each of the four and both two-byte reads
        // are in bounds.
        let g = unsafe {
            debug_assert!(i0.max(i1).max(i2).max(i3) + w + 2 <= src.len());
            let rd = |i: usize| (sp.add(i) as *const u16).read_unaligned();
            u16x8(
                rd(i0),
                rd(i1),
                rd(i2),
                rd(i3),
                rd(i0 + w),
                rd(i1 + w),
                rd(i2 + w),
                rd(i3 + w),
            )
        };
        // bytes [a0 b0 a1 b1 a2 b2 a3 b3 | c0 d0 …]: top-left, top-right,
        // bottom-left, bottom-right of each pixel, one u32 lane each
        let p0 = f32x4_convert_i32x4(i8x16_shuffle::<
            0,
            16,
            16,
            16,
            2,
            16,
            16,
            16,
            4,
            16,
            16,
            16,
            6,
            16,
            16,
            16,
        >(g, zero));
        let p1 = f32x4_convert_i32x4(i8x16_shuffle::<
            1,
            16,
            16,
            16,
            3,
            16,
            16,
            16,
            5,
            16,
            16,
            16,
            7,
            16,
            16,
            16,
        >(g, zero));
        let p2 = f32x4_convert_i32x4(i8x16_shuffle::<
            8,
            16,
            16,
            16,
            10,
            16,
            16,
            16,
            12,
            16,
            16,
            16,
            14,
            16,
            16,
            16,
        >(g, zero));
        let p3 = f32x4_convert_i32x4(i8x16_shuffle::<
            9,
            16,
            16,
            16,
            11,
            16,
            16,
            16,
            13,
            16,
            16,
            16,
            15,
            16,
            16,
            16,
        >(g, zero));
        let top = f32x4_add(p0, f32x4_mul(dc, f32x4_sub(p1, p0)));
        let bottom = f32x4_add(p2, f32x4_mul(dc, f32x4_sub(p3, p2)));
        let v = f32x4_add(top, f32x4_mul(dr, f32x4_sub(bottom, top)));
        // SAFETY: `o` holds 4 f32.
        unsafe { v128_store(o.as_mut_ptr() as *mut v128, v) };
    }
    let done = 4 * quads;
    bilinear_scalar(
        img,
        m,
        base,
        c0 + done,
        run.get_mut(done..).unwrap_or(&mut []),
    );
}

/// Bicubic over a run of interior columns starting at `c0`.
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
fn bicubic_run(img: Gray, m: &Affine, base: (f64, f64), c0: usize, a: f64, run: &mut [f32]) {
    bicubic_scalar(img, m, base, c0, a, run);
}

/// The `f64` bicubic of one run (the scalar build; the SIMD build's
/// fallback).
fn bicubic_scalar<S: Source>(
    img: S,
    m: &Affine,
    base: (f64, f64),
    c0: usize,
    a: f64,
    run: &mut [f32],
) {
    let (src, w) = (img, img.width());
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
        *o = img.out(acc);
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
    let (u_start, v_start) = along(m, base, c0 as f64);
    let fixed = fixed_run(m[0][0], u_start, run.len(), 1.0, w as f64 - 2.0).and_then(|fu| {
        Some((
            fu,
            fixed_run(m[1][0], v_start, run.len(), 1.0, img.height() as f64 - 2.0)?,
        ))
    });
    let Some(((mut pu, du), (mut pv, dv))) = fixed else {
        return bicubic_scalar(img, m, base, c0, a, run);
    };
    let unit = 1.0 / (1u64 << 32) as f64;
    for o in run.iter_mut() {
        // fixed-point position (see `fixed_run`): integer part, and the
        // fraction's top 32 bits (exact in f64, within 2⁻³² px)
        let (fu, fv) = ((pu >> FIX) as usize, (pv >> FIX) as usize);
        let st = f64x2(
            f64::from((pu >> (FIX - 32)) as u32) * unit,
            f64::from((pv >> (FIX - 32)) as u32) * unit,
        );
        (pu, pv) = (pu.wrapping_add(du), pv.wrapping_add(dv));
        let n0 = near(st); // [wc1, wr1]
        let n1 = near(f64x2_sub(one, st)); // [wc2, wr2]
        let f0 = far(f64x2_add(one, st)); // [wc0, wr0]
        let f1 = far(f64x2_sub(two, st)); // [wc3, wr3]
        let wc01 = i64x2_shuffle::<0, 2>(f0, n0);
        let wc23 = i64x2_shuffle::<0, 2>(n1, f1);
        let top = (fv - 1) * w + fu - 1;
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
