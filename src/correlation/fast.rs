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
    // sum tables of I and I² with a zero first row and column
    let stride = sw + 1;
    let mut s1 = vec![0i64; stride * (sh + 1)];
    let mut s2 = vec![0i64; stride * (sh + 1)];
    for r in 0..sh {
        let (mut a, mut b) = (0i64, 0i64);
        let row = search.row(r).unwrap_or(&[]);
        for c in 0..sw {
            let v = i64::from(row.get(c).copied().unwrap_or(0));
            a += v;
            b += v * v;
            let i = (r + 1) * stride + c + 1;
            s1[i] = s1[i - stride] + a;
            s2[i] = s2[i - stride] + b;
        }
    }
    let t = template.data();
    let st: i64 = t.iter().map(|&v| i64::from(v)).sum();
    let st2: i64 = t.iter().map(|&v| i64::from(v) * i64::from(v)).sum();
    let nn = n as i64;
    let dt = (nn * st2 - st * st) as f64;
    let cross = CrossSums::new(search, template);
    let mut acc = vec![0i32; ow];
    let mut best: Option<Peak> = None;
    for (r, o) in out.chunks_exact_mut(ow).enumerate() {
        cross.row(r, &mut acc);
        for (c, (ov, &sit)) in o.iter_mut().zip(&acc).enumerate() {
            let rect = |s: &[i64]| {
                s[(r + th) * stride + c + tw] - s[r * stride + c + tw] - s[(r + th) * stride + c]
                    + s[r * stride + c]
            };
            let (si, si2) = (rect(&s1), rect(&s2));
            let di = (nn * si2 - si * si) as f64;
            let num = (nn * i64::from(sit) - si * st) as f64;
            *ov = if di > 0.0 && dt > 0.0 {
                let rho = (num / (di * dt).sqrt()).clamp(-1.0, 1.0) as f32;
                if best.is_none_or(|b| rho > b.rho) {
                    best = Some(Peak { c, r, rho });
                }
                rho
            } else {
                f32::NAN
            };
        }
    }
    Ok(best)
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
