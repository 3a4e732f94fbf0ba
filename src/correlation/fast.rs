//! Zero-mean normalised cross-correlation of an 8-bit template over every
//! position of an 8-bit search image, with sum tables for the window sums.
//!
//! With `n` template pixels, `ΣI`, `ΣI²` of each window from integral
//! images, `ΣT`, `ΣT²` once, and the cross sums `ΣI·T` as exact integers,
//! `ρ = (n·ΣIT − ΣI·ΣT) / √((n·ΣI² − (ΣI)²)(n·ΣT² − (ΣT)²))` — the same
//! quantity as [`super::correlate_2d`]'s `ρ`, which forms the deviations
//! first (`tests/web_fast.rs` ties them). Flat windows (no variance) have
//! no `ρ`: `NaN` in the map. The cross sums run 8 products per SIMD
//! instruction (`i32x4.dot_i16x8_s`) when built with `+simd128`.

use crate::error::{Error, Result};
use crate::raster::{check_len, Gray};

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
use core::arch::wasm32::*;

/// Largest template the exact integer cross sums allow (`n·255² < 2³¹`).
pub const MAX_TEMPLATE_PIXELS: usize = 33_025;

/// The best position `(c, r)` of the template's top-left and its `ρ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Peak {
    pub c: usize,
    pub r: usize,
    pub rho: f32,
}

/// Fills `out` (`(sw − tw + 1) × (sh − th + 1)`, row-major) with `ρ` of
/// `template` at every position of `search`; returns the first largest `ρ`
/// in row-major order (`None` when every window is flat).
pub fn zncc(search: Gray, template: Gray, out: &mut [f32]) -> Result<Option<Peak>> {
    let (sw, sh) = (search.width(), search.height());
    let (tw, th) = (template.width(), template.height());
    if tw > sw || th > sh {
        return Err(Error::input(
            "template",
            format!("is {th}×{tw} but the search image only {sh}×{sw}"),
        ));
    }
    let n = tw * th;
    if n > MAX_TEMPLATE_PIXELS {
        return Err(Error::input(
            "template",
            format!("has {n} pixels; at most {MAX_TEMPLATE_PIXELS} are allowed"),
        ));
    }
    let (ow, oh) = (sw - tw + 1, sh - th + 1);
    check_len("output", out, ow * oh)?;
    // sum tables of I and I² with a zero first row and column, in `i32`
    // with wrapping adds: a window's sum taken from four entries with
    // wrapping differences is exact (it is below 2³¹: `n·255² < 2³¹`)
    let stride = sw + 1;
    let mut s1 = vec![0i32; stride * (sh + 1)];
    let mut s2 = vec![0i32; stride * (sh + 1)];
    for r in 0..sh {
        let (mut a, mut b) = (0i32, 0i32);
        let row = search.row(r).unwrap_or(&[]);
        for c in 0..sw {
            let v = i32::from(row.get(c).copied().unwrap_or(0));
            a = a.wrapping_add(v);
            b = b.wrapping_add(v * v);
            let i = (r + 1) * stride + c + 1;
            s1[i] = s1[i - stride].wrapping_add(a);
            s2[i] = s2[i - stride].wrapping_add(b);
        }
    }
    let t = template.data();
    let st: i64 = t.iter().map(|&v| i64::from(v)).sum();
    let st2: i64 = t.iter().map(|&v| i64::from(v) * i64::from(v)).sum();
    let nn = n as i64;
    let consts = RhoConsts {
        n: nn as f64,
        st: st as f64,
        dt: (nn * st2 - st * st) as f64,
    };
    let cross = CrossSums::new(search, template);
    let mut acc = vec![0i32; ow];
    let mut best: Option<Peak> = None;
    for (r, o) in out.chunks_exact_mut(ow).enumerate() {
        cross.row(r, &mut acc);
        let rows = [
            table_rows(&s1, stride, r, th),
            table_rows(&s2, stride, r, th),
        ];
        rho_row(rows[0], rows[1], tw, &acc, &consts, o);
        for (c, &rho) in o.iter().enumerate() {
            if !rho.is_nan() && best.is_none_or(|b| rho > b.rho) {
                best = Some(Peak { c, r, rho });
            }
        }
    }
    Ok(best)
}

/// Rows `r` and `r + th` of a sum table (`stride` entries each).
fn table_rows(s: &[i32], stride: usize, r: usize, th: usize) -> [&[i32]; 2] {
    [r, r + th].map(|i| s.get(i * stride..(i + 1) * stride).unwrap_or(&[]))
}

/// The template's terms of `ρ`: `n`, `ΣT` and `n·ΣT² − (ΣT)²`.
struct RhoConsts {
    n: f64,
    st: f64,
    dt: f64,
}

/// `ρ` of one output row from the sum tables' rows `[top, bottom]` (`top`
/// = the window's first row, `bottom` = one past its last) and the cross
/// sums `sit`: `(n·ΣIT − ΣI·ΣT) / √((n·ΣI² − (ΣI)²)·dt)`, clamped to
/// `[−1, 1]`, `NaN` for a flat window or template. Every term before the
/// square root is an integer below 2⁵³, so exact in `f64`: the value is
/// the one the `i64` formula gives, 4 positions per step with `+simd128`.
fn rho_row(s1: [&[i32]; 2], s2: [&[i32]; 2], tw: usize, sit: &[i32], k: &RhoConsts, o: &mut [f32]) {
    let rect = |s: [&[i32]; 2], c: usize| {
        let g = |row: &[i32], i: usize| row.get(i).copied().unwrap_or(0);
        g(s[1], c + tw)
            .wrapping_sub(g(s[0], c + tw))
            .wrapping_sub(g(s[1], c))
            .wrapping_add(g(s[0], c))
    };
    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
    let done = 0;
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    let done = if s1.iter().chain(&s2).all(|row| row.len() >= o.len() + tw) && sit.len() >= o.len()
    {
        let ow = o.len();
        let n4 = ow / 4 * 4;
        let (nv, stv, dtv) = (f64x2_splat(k.n), f64x2_splat(k.st), f64x2_splat(k.dt));
        let (m1, p1, zero) = (f64x2_splat(-1.0), f64x2_splat(1.0), f64x2_splat(0.0));
        let dt_ok = if k.dt > 0.0 {
            u64x2_splat(u64::MAX)
        } else {
            u64x2_splat(0)
        };
        let nan = f32x4_splat(f32::NAN);
        // SAFETY (every load): i + 4 ≤ n4 + tw ≤ ow + tw ≤ the row's length
        // (checked above), and sit.len() ≥ ow.
        let ld = |row: &[i32], i: usize| unsafe { v128_load(row.as_ptr().add(i) as *const v128) };
        let rect4 = |s: [&[i32]; 2], c: usize| {
            i32x4_add(
                i32x4_sub(i32x4_sub(ld(s[1], c + tw), ld(s[0], c + tw)), ld(s[1], c)),
                ld(s[0], c),
            )
        };
        // ρ of the two positions in the low lanes of the `i32x4`s, and
        // whether each has one (all ones in its 64-bit lane)
        let half = |si: v128, si2: v128, x: v128| {
            let (si, si2, x) = (
                f64x2_convert_low_i32x4(si),
                f64x2_convert_low_i32x4(si2),
                f64x2_convert_low_i32x4(x),
            );
            let di = f64x2_sub(f64x2_mul(nv, si2), f64x2_mul(si, si));
            let num = f64x2_sub(f64x2_mul(nv, x), f64x2_mul(si, stv));
            let rho = f64x2_div(num, f64x2_sqrt(f64x2_mul(di, dtv)));
            let rho = f64x2_pmin(f64x2_pmax(rho, m1), p1);
            (
                f32x4_demote_f64x2_zero(rho),
                v128_and(f64x2_gt(di, zero), dt_ok),
            )
        };
        let mut c = 0;
        while c < n4 {
            let (si, si2, x) = (rect4(s1, c), rect4(s2, c), ld(sit, c));
            let up = |v: v128| i32x4_shuffle::<2, 3, 2, 3>(v, v);
            let (lo, ok_lo) = half(si, si2, x);
            let (hi, ok_hi) = half(up(si), up(si2), up(x));
            let rho = i32x4_shuffle::<0, 1, 4, 5>(lo, hi);
            let ok = i32x4_shuffle::<0, 2, 4, 6>(ok_lo, ok_hi);
            // SAFETY: c + 4 ≤ n4 ≤ ow = o.len().
            unsafe {
                v128_store(
                    o.as_mut_ptr().add(c) as *mut v128,
                    v128_bitselect(rho, nan, ok),
                )
            };
            c += 4;
        }
        n4
    } else {
        0
    };
    for (c, ov) in o.iter_mut().enumerate().skip(done) {
        let (si, si2) = (f64::from(rect(s1, c)), f64::from(rect(s2, c)));
        let di = k.n * si2 - si * si;
        let num = k.n * f64::from(sit.get(c).copied().unwrap_or(0)) - si * k.st;
        *ov = if di > 0.0 && k.dt > 0.0 {
            (num / (di * k.dt).sqrt()).clamp(-1.0, 1.0) as f32
        } else {
            f32::NAN
        };
    }
}

/// The cross sums `Σ I·T` of one output row.
struct CrossSums {
    /// Search rows as `i16`, each padded with zeros to `padded_w`.
    search: Vec<i16>,
    padded_w: usize,
    /// Template rows as `i16`, each padded with zeros to `tpw` (multiple of 8).
    template: Vec<i16>,
    tpw: usize,
    tw: usize,
    th: usize,
}

impl CrossSums {
    fn new(search: Gray, template: Gray) -> Self {
        let (tw, th) = (template.width(), template.height());
        let tpw = tw.div_ceil(8) * 8;
        let padded_w = search.width() + tpw;
        let mut s = vec![0i16; padded_w * search.height()];
        for (r, row) in s.chunks_exact_mut(padded_w).enumerate() {
            for (d, &v) in row.iter_mut().zip(search.row(r).unwrap_or(&[])) {
                *d = i16::from(v);
            }
        }
        let mut t = vec![0i16; tpw * th];
        for (r, row) in t.chunks_exact_mut(tpw).enumerate() {
            for (d, &v) in row.iter_mut().zip(template.row(r).unwrap_or(&[])) {
                *d = i16::from(v);
            }
        }
        CrossSums {
            search: s,
            padded_w,
            template: t,
            tpw,
            tw,
            th,
        }
    }

    /// `acc[c] = Σ_j Σ_i T(i, j) · I(c + i, r + j)`.
    fn row(&self, r: usize, acc: &mut [i32]) {
        #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
        {
            let ow = acc.len();
            if ow + self.tpw <= self.padded_w
                && (r + self.th) * self.padded_w <= self.search.len()
                && self.template.len() == self.tpw * self.th
            {
                let tv: Vec<v128> = self
                    .template
                    .chunks_exact(8)
                    .map(|c| i16x8(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]))
                    .collect();
                let per_row = self.tpw / 8;
                let pw = self.padded_w;
                let sp = self.search.as_ptr();
                // four positions at a time: each template vector loaded once
                // for four dot products
                let mut c0 = 0;
                while c0 + 4 <= ow {
                    let z = i32x4_splat(0);
                    let (mut s0, mut s1, mut s2, mut s3) = (z, z, z, z);
                    for (j, trow) in tv.chunks_exact(per_row).enumerate() {
                        let base = (r + j) * pw + c0;
                        for (k, t) in trow.iter().enumerate() {
                            // SAFETY: base + 8k + 3 + 8 ≤ (r + j)·pw + ow − 1 + tpw
                            // < (r + j + 1)·pw ≤ search.len() (checked above).
                            unsafe {
                                let p = sp.add(base + 8 * k);
                                s0 =
                                    i32x4_add(s0, i32x4_dot_i16x8(v128_load(p as *const v128), *t));
                                s1 = i32x4_add(
                                    s1,
                                    i32x4_dot_i16x8(v128_load(p.add(1) as *const v128), *t),
                                );
                                s2 = i32x4_add(
                                    s2,
                                    i32x4_dot_i16x8(v128_load(p.add(2) as *const v128), *t),
                                );
                                s3 = i32x4_add(
                                    s3,
                                    i32x4_dot_i16x8(v128_load(p.add(3) as *const v128), *t),
                                );
                            }
                        }
                    }
                    // horizontal sums of the four accumulators, as one vector
                    let t0 = i32x4_add(
                        i32x4_shuffle::<0, 4, 1, 5>(s0, s1),
                        i32x4_shuffle::<2, 6, 3, 7>(s0, s1),
                    );
                    let t1 = i32x4_add(
                        i32x4_shuffle::<0, 4, 1, 5>(s2, s3),
                        i32x4_shuffle::<2, 6, 3, 7>(s2, s3),
                    );
                    let sums = i32x4_add(
                        i32x4_shuffle::<0, 1, 4, 5>(t0, t1),
                        i32x4_shuffle::<2, 3, 6, 7>(t0, t1),
                    );
                    if let Some(dst) = acc.get_mut(c0..c0 + 4) {
                        // SAFETY: dst holds 4 i32.
                        unsafe { v128_store(dst.as_mut_ptr() as *mut v128, sums) };
                    }
                    c0 += 4;
                }
                for (c, a) in acc.iter_mut().enumerate().skip(c0) {
                    let mut sum = i32x4_splat(0);
                    for j in 0..self.th {
                        let base = (r + j) * self.padded_w + c;
                        for k in 0..per_row {
                            // SAFETY: base + 8k + 8 ≤ (r + j)·padded_w + ow − 1 + tpw
                            // < (r + j + 1)·padded_w ≤ search.len() (checked above).
                            let s = unsafe {
                                v128_load(self.search.as_ptr().add(base + 8 * k) as *const v128)
                            };
                            sum = i32x4_add(sum, i32x4_dot_i16x8(s, tv[j * per_row + k]));
                        }
                    }
                    *a = i32x4_extract_lane::<0>(sum)
                        + i32x4_extract_lane::<1>(sum)
                        + i32x4_extract_lane::<2>(sum)
                        + i32x4_extract_lane::<3>(sum);
                }
                return;
            }
        }
        acc.fill(0);
        for j in 0..self.th {
            let srow = self
                .search
                .get((r + j) * self.padded_w..(r + j + 1) * self.padded_w)
                .unwrap_or(&[]);
            let trow = self
                .template
                .get(j * self.tpw..j * self.tpw + self.tw)
                .unwrap_or(&[]);
            for (i, &t) in trow.iter().enumerate() {
                let t = i32::from(t);
                for (a, &s) in acc.iter_mut().zip(srow.iter().skip(i)) {
                    *a += t * i32::from(s);
                }
            }
        }
    }
}
