//! Fast whole-image paths of the filters on 8-bit images: separable
//! kernels over a ring of converted rows, Sobel from one vertical and one
//! horizontal pass, and the 3×3 median from sorted columns (no sorting of
//! nine values per pixel). Output `f32` (filters) or `u8` (median).
//!
//! Each function gives the output of its reference in [`super`] at every
//! pixel (`tests/web_fast.rs` ties them): [`separable`] is
//! [`super::correlate`] with the outer-product kernel, [`sobel`] is
//! [`super::gradient`] with [`super::sobel_y`] (`gx`) and the negated
//! [`super::sobel_x`] (`gy`), [`median3`] is [`super::median`] 3×3.
//! Border policies `Replicate`, `Reflect` and `Zero` read outside as the
//! reference does; `Crop` computes the whole image as `Replicate` (its
//! interior, the part `Crop` keeps, is the same under every policy).
//!
//! Built with `+simd128` (wasm), the inner loops run on `core::arch::wasm32`
//! vectors, 4 floats or 16 bytes at a time; everywhere else the same loops
//! run scalar.

use crate::error::{Error, Result};
use crate::raster::{check_len, fold, Border, Gray, GrayF32};

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
use core::arch::wasm32::*;

mod median;
pub use median::{median3, median3_f32};

/// The border a fast path applies (`Crop` computed as `Replicate`).
fn effective(border: Border) -> Border {
    match border {
        Border::Crop => Border::Replicate,
        b => b,
    }
}

/// Fills the `pad` cells on each side of `row[pad .. pad + w]` by `border`
/// (`zero` where the policy reads nothing).
pub(crate) fn pad_row<T: Copy>(row: &mut [T], w: usize, pad: usize, border: Border, zero: T) {
    for i in 0..pad {
        let x = i as isize - pad as isize;
        let v = fold(x, w, effective(border)).and_then(|c| row.get(pad + c).copied());
        if let Some(cell) = row.get_mut(i) {
            *cell = v.unwrap_or(zero);
        }
        let x = (w + i) as isize;
        let v = fold(x, w, effective(border)).and_then(|c| row.get(pad + c).copied());
        if let Some(cell) = row.get_mut(pad + w + i) {
            *cell = v.unwrap_or(zero);
        }
    }
}

/// The source row read for row position `r` (`None`: a row of zeros).
pub(crate) fn row_at<'a>(img: &Gray<'a>, r: isize, border: Border) -> Option<&'a [u8]> {
    fold(r, img.height(), effective(border)).and_then(|i| img.row(i))
}

/// An image the filter passes read row by row as `f32`: an 8-bit
/// [`Gray`]'s bytes converted, or a [`GrayF32`]'s values copied.
pub trait Rows {
    fn width(&self) -> usize;
    fn height(&self) -> usize;
    /// Row `i` into `dst` as `f32` (nothing past the last row).
    fn load(&self, i: usize, dst: &mut [f32]);
}

impl Rows for Gray<'_> {
    fn width(&self) -> usize {
        Gray::width(self)
    }
    fn height(&self) -> usize {
        Gray::height(self)
    }
    fn load(&self, i: usize, dst: &mut [f32]) {
        if let Some(src) = self.row(i) {
            convert_row(src, dst);
        }
    }
}

impl Rows for GrayF32<'_> {
    fn width(&self) -> usize {
        GrayF32::width(self)
    }
    fn height(&self) -> usize {
        GrayF32::height(self)
    }
    fn load(&self, i: usize, dst: &mut [f32]) {
        if let Some(src) = self.row(i) {
            let n = src.len().min(dst.len());
            dst[..n].copy_from_slice(&src[..n]);
        }
    }
}

/// Rows of an image converted to `f32` once each, kept in a ring of
/// `2·radius + 1` slots: the rows a vertical pass needs at one output row
/// lie within `radius` of it, so they never share a slot.
pub(crate) struct RowRing {
    slots: Vec<Vec<f32>>,
    tags: Vec<Option<usize>>,
    zeros: Vec<f32>,
}

impl RowRing {
    pub(crate) fn new(width: usize, radius: usize) -> Self {
        let n = 2 * radius + 1;
        RowRing {
            slots: vec![vec![0.0; width]; n],
            tags: vec![None; n],
            zeros: vec![0.0; width],
        }
    }

    /// Makes sure source row `i` is converted; returns its slot.
    fn load(&mut self, img: &impl Rows, i: usize) -> usize {
        let slot = i % self.slots.len();
        if self.tags[slot] != Some(i) {
            if let Some(dst) = self.slots.get_mut(slot) {
                img.load(i, dst);
            }
            self.tags[slot] = Some(i);
        }
        slot
    }

    /// The converted rows for positions `r − radius … r + radius`.
    pub(crate) fn rows(
        &mut self,
        img: &impl Rows,
        r: usize,
        radius: usize,
        border: Border,
    ) -> Vec<&[f32]> {
        let idx: Vec<Option<usize>> = (0..=2 * radius)
            .map(|j| {
                fold(
                    r as isize + j as isize - radius as isize,
                    img.height(),
                    effective(border),
                )
            })
            .collect();
        let slots: Vec<Option<usize>> = idx.iter().map(|i| i.map(|i| self.load(img, i))).collect();
        slots
            .iter()
            .map(|s| match s {
                Some(s) => self.slots.get(*s).map_or(&self.zeros[..], |v| &v[..]),
                None => &self.zeros[..],
            })
            .collect()
    }
}

/// `dst[x] = src[x]` as `f32`.
pub(crate) fn convert_row(src: &[u8], dst: &mut [f32]) {
    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
    let done = 0;
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    let done = {
        let n = src.len().min(dst.len()) / 16 * 16;
        for (s, d) in src[..n].chunks_exact(16).zip(dst[..n].chunks_exact_mut(16)) {
            // SAFETY: `s` holds 16 bytes and `d` 16 floats (chunks_exact);
            // wasm loads and stores need no alignment.
            unsafe {
                let v = v128_load(s.as_ptr() as *const v128);
                // the signed conversion (one x86 instruction; the unsigned
                // one is emulated) is exact for these values
                let lo = u16x8_extend_low_u8x16(v);
                let hi = u16x8_extend_high_u8x16(v);
                let p = d.as_mut_ptr() as *mut v128;
                v128_store(p, f32x4_convert_i32x4(u32x4_extend_low_u16x8(lo)));
                v128_store(p.add(1), f32x4_convert_i32x4(u32x4_extend_high_u16x8(lo)));
                v128_store(p.add(2), f32x4_convert_i32x4(u32x4_extend_low_u16x8(hi)));
                v128_store(p.add(3), f32x4_convert_i32x4(u32x4_extend_high_u16x8(hi)));
            }
        }
        n
    };
    for (s, d) in src[done..].iter().zip(&mut dst[done..]) {
        *d = f32::from(*s);
    }
}

/// Whether `k` reads the same backwards (`k[j] = k[n − 1 − j]`): its
/// symmetric taps are then applied once to the sum of their two inputs.
fn symmetric(k: &[f32]) -> bool {
    k.iter().eq(k.iter().rev())
}

/// `Σ_j k[j] · v(j)` for a symmetric `k` of odd length, in the order the
/// SIMD loops use: `k[m]·v(m) + Σ_{j<m} k[j]·(v(j) + v(n − 1 − j))`.
/// (With integer taps and inputs every sum is exact, so the value is the
/// plain sum's; with fractional taps it differs by rounding only.)
fn sym_dot(k: &[f32], v: impl Fn(usize) -> f32) -> f32 {
    let (n, m) = (k.len(), k.len() / 2);
    let mut acc = k.get(m).copied().unwrap_or(0.0) * v(m);
    for (j, kj) in k.iter().enumerate().take(m) {
        acc += kj * (v(j) + v(n - 1 - j));
    }
    acc
}

/// `dst[x] = Σ_j k[j] · rows[j][x]` (symmetric taps paired, [`sym_dot`]).
pub(crate) fn vertical(rows: &[&[f32]], k: &[f32], dst: &mut [f32]) {
    let sym = symmetric(k) && k.len() % 2 == 1 && rows.len() == k.len();
    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
    let done = 0;
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    let done = if let (Ok(r5), Ok(k5)) = (<&[&[f32]; 5]>::try_from(rows), <&[f32; 5]>::try_from(k))
    {
        if sym {
            vertical_sym(r5, k5, dst)
        } else {
            vertical_n(r5, k5, dst)
        }
    } else if let (Ok(r3), Ok(k3)) = (<&[&[f32]; 3]>::try_from(rows), <&[f32; 3]>::try_from(k)) {
        if sym {
            vertical_sym(r3, k3, dst)
        } else {
            vertical_n(r3, k3, dst)
        }
    } else if sym {
        0
    } else {
        let w = dst.len();
        if rows.iter().all(|r| r.len() >= w) {
            let n = w / 4 * 4;
            let ks: Vec<v128> = k.iter().map(|&v| f32x4_splat(v)).collect();
            let mut x = 0;
            while x < n {
                let mut acc = f32x4_splat(0.0);
                for (r, kv) in rows.iter().zip(&ks) {
                    // SAFETY: x + 4 ≤ w ≤ r.len() (checked above).
                    let v = unsafe { v128_load(r.as_ptr().add(x) as *const v128) };
                    acc = f32x4_add(acc, f32x4_mul(*kv, v));
                }
                // SAFETY: x + 4 ≤ w = dst.len().
                unsafe { v128_store(dst.as_mut_ptr().add(x) as *mut v128, acc) };
                x += 4;
            }
            n
        } else {
            0
        }
    };
    for (x, d) in dst.iter_mut().enumerate().skip(done) {
        let at = |j: usize| rows.get(j).and_then(|r| r.get(x)).copied().unwrap_or(0.0);
        *d = if sym {
            sym_dot(k, at)
        } else {
            rows.iter()
                .zip(k)
                .map(|(r, kv)| kv * r.get(x).copied().unwrap_or(0.0))
                .sum()
        };
    }
}

/// `dst[x] = Σ_i k[i] · src[x + i] / divisor` (`src` padded by the
/// kernel's radius; symmetric taps paired, [`sym_dot`]).
pub(crate) fn horizontal(src: &[f32], k: &[f32], divisor: f32, dst: &mut [f32]) {
    let sym = symmetric(k) && k.len() % 2 == 1;
    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
    let done = 0;
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    let done = if let Ok(k5) = <&[f32; 5]>::try_from(k) {
        if sym {
            horizontal_sym(src, k5, divisor, dst)
        } else {
            horizontal_n(src, k5, divisor, dst)
        }
    } else if let Ok(k3) = <&[f32; 3]>::try_from(k) {
        if sym {
            horizontal_sym(src, k3, divisor, dst)
        } else {
            horizontal_n(src, k3, divisor, dst)
        }
    } else if sym {
        0
    } else {
        let w = dst.len();
        if src.len() + 1 >= w + k.len() {
            let n = w / 4 * 4;
            let ks: Vec<v128> = k.iter().map(|&v| f32x4_splat(v)).collect();
            let dv = f32x4_splat(divisor);
            let mut x = 0;
            while x < n {
                let mut acc = f32x4_splat(0.0);
                for (i, kv) in ks.iter().enumerate() {
                    // SAFETY: x + i + 4 ≤ w − 4 + k.len() + 3 < src.len() + 1.
                    let v = unsafe { v128_load(src.as_ptr().add(x + i) as *const v128) };
                    acc = f32x4_add(acc, f32x4_mul(*kv, v));
                }
                // SAFETY: x + 4 ≤ w = dst.len().
                unsafe { v128_store(dst.as_mut_ptr().add(x) as *mut v128, f32x4_div(acc, dv)) };
                x += 4;
            }
            n
        } else {
            0
        }
    };
    for (x, d) in dst.iter_mut().enumerate().skip(done) {
        let s: f32 = if sym {
            sym_dot(k, |i| src.get(x + i).copied().unwrap_or(0.0))
        } else {
            k.iter()
                .enumerate()
                .map(|(i, kv)| kv * src.get(x + i).copied().unwrap_or(0.0))
                .sum()
        };
        *d = s / divisor;
    }
}

/// [`vertical`] for a symmetric `N`-tap kernel ([`sym_dot`]'s order,
/// unrolled); returns the number of outputs written (a multiple of 4; 0 if
/// a row is short).
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn vertical_sym<const N: usize>(rows: &[&[f32]; N], k: &[f32; N], dst: &mut [f32]) -> usize {
    let w = dst.len();
    if rows.iter().any(|r| r.len() < w) {
        return 0;
    }
    let (n, m) = (w / 4 * 4, N / 2);
    let ks = k.map(|v| f32x4_splat(v));
    let ps = rows.map(|r| r.as_ptr());
    let mut x = 0;
    while x < n {
        // SAFETY: j < N and x + 4 ≤ w ≤ every row's length (checked above).
        let ld = |j: usize| unsafe { v128_load(ps[j].add(x) as *const v128) };
        let mut acc = f32x4_mul(ks[m], ld(m));
        for (j, kj) in ks.iter().enumerate().take(m) {
            acc = f32x4_add(acc, f32x4_mul(*kj, f32x4_add(ld(j), ld(N - 1 - j))));
        }
        // SAFETY: x + 4 ≤ w = dst.len().
        unsafe { v128_store(dst.as_mut_ptr().add(x) as *mut v128, acc) };
        x += 4;
    }
    n
}

/// [`horizontal`] for a symmetric `N`-tap kernel ([`sym_dot`]'s order,
/// unrolled; no division when `divisor` is 1); returns the number of
/// outputs written.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn horizontal_sym<const N: usize>(
    src: &[f32],
    k: &[f32; N],
    divisor: f32,
    dst: &mut [f32],
) -> usize {
    let w = dst.len();
    if src.len() + 1 < w + N {
        return 0;
    }
    let (n, m) = (w / 4 * 4, N / 2);
    let ks = k.map(|v| f32x4_splat(v));
    let dv = f32x4_splat(divisor);
    let p = src.as_ptr();
    let mut x = 0;
    while x < n {
        // SAFETY: x + i + 4 ≤ w − 4 + N + 3 < src.len() + 1 for i < N.
        let ld = |i: usize| unsafe { v128_load(p.add(x + i) as *const v128) };
        let mut acc = f32x4_mul(ks[m], ld(m));
        for (j, kj) in ks.iter().enumerate().take(m) {
            acc = f32x4_add(acc, f32x4_mul(*kj, f32x4_add(ld(j), ld(N - 1 - j))));
        }
        if divisor != 1.0 {
            acc = f32x4_div(acc, dv);
        }
        // SAFETY: x + 4 ≤ w = dst.len().
        unsafe { v128_store(dst.as_mut_ptr().add(x) as *mut v128, acc) };
        x += 4;
    }
    n
}

/// [`vertical`] for `N` taps known at compile time (unrolled); returns the
/// number of outputs written (a multiple of 4; 0 if a row is short).
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn vertical_n<const N: usize>(rows: &[&[f32]; N], k: &[f32; N], dst: &mut [f32]) -> usize {
    let w = dst.len();
    if rows.iter().any(|r| r.len() < w) {
        return 0;
    }
    let n = w / 4 * 4;
    let ks = k.map(|v| f32x4_splat(v));
    let ps = rows.map(|r| r.as_ptr());
    let mut x = 0;
    while x < n {
        let mut acc = f32x4_splat(0.0);
        for j in 0..N {
            // SAFETY: x + 4 ≤ w ≤ every row's length (checked above).
            let v = unsafe { v128_load(ps[j].add(x) as *const v128) };
            acc = f32x4_add(acc, f32x4_mul(ks[j], v));
        }
        // SAFETY: x + 4 ≤ w = dst.len().
        unsafe { v128_store(dst.as_mut_ptr().add(x) as *mut v128, acc) };
        x += 4;
    }
    n
}

/// [`horizontal`] for `N` taps known at compile time (unrolled; no
/// division when `divisor` is 1); returns the number of outputs written.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn horizontal_n<const N: usize>(src: &[f32], k: &[f32; N], divisor: f32, dst: &mut [f32]) -> usize {
    let w = dst.len();
    if src.len() + 1 < w + N {
        return 0;
    }
    let n = w / 4 * 4;
    let ks = k.map(|v| f32x4_splat(v));
    let dv = f32x4_splat(divisor);
    let p = src.as_ptr();
    let mut x = 0;
    while x < n {
        let mut acc = f32x4_splat(0.0);
        for (i, kv) in ks.iter().enumerate() {
            // SAFETY: x + i + 4 ≤ w − 4 + N + 3 < src.len() + 1.
            let v = unsafe { v128_load(p.add(x + i) as *const v128) };
            acc = f32x4_add(acc, f32x4_mul(*kv, v));
        }
        if divisor != 1.0 {
            acc = f32x4_div(acc, dv);
        }
        // SAFETY: x + 4 ≤ w = dst.len().
        unsafe { v128_store(dst.as_mut_ptr().add(x) as *mut v128, acc) };
        x += 4;
    }
    n
}

fn check_taps(field: &str, k: &[f32]) -> Result<()> {
    if k.len().is_multiple_of(2) || k.iter().any(|v| !v.is_finite()) {
        return Err(Error::input(
            field,
            "needs an odd number of finite taps (a centre tap)",
        ));
    }
    Ok(())
}

/// `out = Σ_j Σ_i ky[j] · kx[i] · I(c + i − a, r + j − b) / divisor`: the
/// separable kernel `ky ⊗ kx / divisor` applied as written (correlation),
/// a vertical pass over a ring of converted rows, then a horizontal pass.
/// (Integer taps and a divisor keep integer sums exact: the 3×3 mean is
/// the `f32` nearest to the reference's value.)
pub fn separable(
    img: impl Rows,
    kx: &[f32],
    ky: &[f32],
    divisor: f32,
    border: Border,
    out: &mut [f32],
) -> Result<()> {
    check_taps("kx", kx)?;
    check_taps("ky", ky)?;
    if !(divisor.is_finite() && divisor != 0.0) {
        return Err(Error::input("divisor", "must be a finite non-zero number"));
    }
    let (w, h) = (img.width(), img.height());
    check_len("output", out, w * h)?;
    let (rx, ry) = (kx.len() / 2, ky.len() / 2);
    let mut ring = RowRing::new(w, ry);
    let mut tmp = vec![0.0f32; w + 2 * rx];
    for (r, o) in out.chunks_exact_mut(w).enumerate() {
        let rows = ring.rows(&img, r, ry, border);
        vertical(&rows, ky, &mut tmp[rx..rx + w]);
        pad_row(&mut tmp, w, rx, border, 0.0);
        horizontal(&tmp, kx, divisor, o);
    }
    Ok(())
}

/// `out = Σ_j Σ_i k[j·kw + i] · I(c + i − kw/2, r + j − kh/2) / divisor`:
/// any odd `kw × kh` kernel (row-major `k`) applied as written
/// (correlation, [`super::correlate`]), one multiply-add pass along the row
/// per non-zero tap over the rows of a ring, each row padded by the border
/// once. Integer taps with `Σ|k|·255 < 2²⁴` keep every partial sum an
/// exact integer (any order of adding gives the same `f32`), and a divisor
/// exact in `f32` makes the output the `f32` nearest to the reference's
/// value.
pub fn correlate(
    img: impl Rows,
    k: &[f32],
    (kw, kh): (usize, usize),
    divisor: f32,
    border: Border,
    out: &mut [f32],
) -> Result<()> {
    if kw.is_multiple_of(2) || kh.is_multiple_of(2) || k.len() != kw * kh {
        return Err(Error::input(
            "kernel",
            format!(
                "needs an odd number of rows and of columns and {kw}×{kh} taps (got {})",
                k.len()
            ),
        ));
    }
    if k.iter().any(|v| !v.is_finite()) {
        return Err(Error::input("kernel", "needs finite taps"));
    }
    if !(divisor.is_finite() && divisor != 0.0) {
        return Err(Error::input("divisor", "must be a finite non-zero number"));
    }
    let (w, h) = (img.width(), img.height());
    check_len("output", out, w * h)?;
    let (rx, ry) = (kw / 2, kh / 2);
    let mut ring = RowRing::new(w, ry);
    let mut padded = vec![0.0f32; w + 2 * rx];
    let mut acc = vec![0.0f32; w];
    for (r, o) in out.chunks_exact_mut(w).enumerate() {
        let rows = ring.rows(&img, r, ry, border);
        acc.fill(0.0);
        for (row, taps) in rows.iter().zip(k.chunks_exact(kw)) {
            if taps.iter().all(|&t| t == 0.0) {
                continue;
            }
            if let Some(mid) = padded.get_mut(rx..rx + w) {
                mid.copy_from_slice(row.get(..w).unwrap_or(&[]));
            }
            pad_row(&mut padded, w, rx, border, 0.0);
            for (i, &t) in taps.iter().enumerate() {
                if t != 0.0 {
                    axpy(&mut acc, t, padded.get(i..i + w).unwrap_or(&[]));
                }
            }
        }
        for (d, a) in o.iter_mut().zip(&acc) {
            *d = a / divisor;
        }
    }
    Ok(())
}

/// `acc[x] += t · src[x]` (the loop the compiler turns into SIMD).
fn axpy(acc: &mut [f32], t: f32, src: &[f32]) {
    for (a, s) in acc.iter_mut().zip(src) {
        *a += t * s;
    }
}

/// `out = atan2(y, x)` in degrees, `(−180, 180]` as `f64::atan2` (of
/// `+0` for `−0`): Cephes' `atanf` (the argument reduced to
/// `[0, tan π/8]`, a degree-9 odd polynomial; relative error about
/// 2·10⁻⁷) on `min(|x|, |y|) / max(|x|, |y|)`, then the octant; branch
/// free, so the compiler vectorises it.
pub fn direction_deg(x: &[f32], y: &[f32], out: &mut [f32]) {
    use std::f32::consts::{FRAC_PI_2, FRAC_PI_4, PI};
    const TAN_PI_8: f32 = 0.414_213_57;
    let n = out.len().min(x.len()).min(y.len());
    let (x, y, out) = (&x[..n], &y[..n], &mut out[..n]);
    // selects, not f32::min/max (libm calls in wasm): the loop vectorises
    for i in 0..n {
        let (gx, gy) = (x[i] + 0.0, y[i] + 0.0);
        let (ax, ay) = (gx.abs(), gy.abs());
        let swap = ay > ax;
        let lo = if swap { ax } else { ay };
        let hi = if swap { ay } else { ax };
        let t = lo / if hi > 0.0 { hi } else { 1.0 };
        let reduce = t > TAN_PI_8;
        let u = if reduce { (t - 1.0) / (t + 1.0) } else { t };
        let z = u * u;
        let p = (((8.053_744_5e-2 * z - 1.387_768_6e-1) * z + 1.997_771_1e-1) * z - 3.333_295e-1)
            * z
            * u
            + u;
        let v = if reduce { FRAC_PI_4 + p } else { p };
        let v = if swap { FRAC_PI_2 - v } else { v };
        let v = if gx < 0.0 { PI - v } else { v };
        let v = if gy < 0.0 { -v } else { v };
        out[i] = v * (180.0 / PI);
    }
}

/// The 3×3 mean: `(1/9) · Σ` of the neighbourhood (sums exact in `f32`).
/// With `+simd128` the sums run in integers (`u16`, at most 2295) 8
/// pixels at a time: the same exact sums, divided by 9 in `f32`.
pub fn mean3(img: Gray, border: Border, out: &mut [f32]) -> Result<()> {
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    {
        let (w, h) = (img.width(), img.height());
        check_len("output", out, w * h)?;
        let zeros = vec![0u8; w];
        let mut vs = vec![0u16; w + 2];
        for (r, o) in out.chunks_exact_mut(w).enumerate() {
            let rows = [-1, 0, 1].map(|d| row_at(&img, r as isize + d, border).unwrap_or(&zeros));
            vsum3_u8(rows, &mut vs[1..=w]);
            pad_row(&mut vs, w, 1, border, 0);
            hsum3_div9(&vs, o);
        }
        Ok(())
    }
    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
    separable(img, &[1.0; 3], &[1.0; 3], 9.0, border, out)
}

/// `dst[x] = a[x] + b[x] + c[x]` in `u16`, 16 pixels at a time.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn vsum3_u8(rows: [&[u8]; 3], dst: &mut [u16]) {
    let w = dst.len();
    let [a, b, c] = rows;
    let done = if a.len() >= w && b.len() >= w && c.len() >= w {
        let n = w / 16 * 16;
        let mut x = 0;
        while x < n {
            // SAFETY: x + 16 ≤ w ≤ every row's length and dst.len() = w
            // (16 u16 = two vectors); wasm loads need no alignment.
            unsafe {
                let va = v128_load(a.as_ptr().add(x) as *const v128);
                let vb = v128_load(b.as_ptr().add(x) as *const v128);
                let vc = v128_load(c.as_ptr().add(x) as *const v128);
                let lo = u16x8_add(
                    u16x8_add(u16x8_extend_low_u8x16(va), u16x8_extend_low_u8x16(vb)),
                    u16x8_extend_low_u8x16(vc),
                );
                let hi = u16x8_add(
                    u16x8_add(u16x8_extend_high_u8x16(va), u16x8_extend_high_u8x16(vb)),
                    u16x8_extend_high_u8x16(vc),
                );
                let p = dst.as_mut_ptr().add(x) as *mut v128;
                v128_store(p, lo);
                v128_store(p.add(1), hi);
            }
            x += 16;
        }
        n
    } else {
        0
    };
    for (x, d) in dst.iter_mut().enumerate().skip(done) {
        let at = |r: &[u8]| u16::from(r.get(x).copied().unwrap_or(0));
        *d = at(a) + at(b) + at(c);
    }
}

/// `dst[x] = (src[x] + src[x + 1] + src[x + 2]) / 9` (`src` padded by 1),
/// the sum exact in `u16`, 8 pixels at a time.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn hsum3_div9(src: &[u16], dst: &mut [f32]) {
    let w = dst.len();
    let done = if src.len() >= w + 2 {
        let n = w / 8 * 8;
        let nine = f32x4_splat(9.0);
        let mut x = 0;
        while x < n {
            // SAFETY: x + 2 + 8 ≤ w + 2 ≤ src.len(); x + 8 ≤ w = dst.len().
            unsafe {
                let p = src.as_ptr().add(x);
                let s = u16x8_add(
                    u16x8_add(
                        v128_load(p as *const v128),
                        v128_load(p.add(1) as *const v128),
                    ),
                    v128_load(p.add(2) as *const v128),
                );
                let lo = f32x4_convert_i32x4(u32x4_extend_low_u16x8(s));
                let hi = f32x4_convert_i32x4(u32x4_extend_high_u16x8(s));
                let d = dst.as_mut_ptr().add(x) as *mut v128;
                v128_store(d, f32x4_div(lo, nine));
                v128_store(d.add(1), f32x4_div(hi, nine));
            }
            x += 8;
        }
        n
    } else {
        0
    };
    for (x, d) in dst.iter_mut().enumerate().skip(done) {
        let s: u16 = (0..3).map(|i| src.get(x + i).copied().unwrap_or(0)).sum();
        *d = f32::from(s) / 9.0;
    }
}

/// The Gaussian taps `k(i) = exp(−i²/(2σ²)) / Σ_j exp(−j²/(2σ²))`,
/// `i = −radius … radius` (`None` for σ not finite and positive).
pub fn gaussian_taps(sigma: f64, radius: usize) -> Option<Vec<f64>> {
    if !(sigma.is_finite() && sigma > 0.0) {
        return None;
    }
    let r = radius as f64;
    let raw: Vec<f64> = (0..=2 * radius)
        .map(|i| {
            let x = i as f64 - r;
            (-x * x / (2.0 * sigma * sigma)).exp()
        })
        .collect();
    let sum: f64 = raw.iter().sum();
    Some(raw.iter().map(|v| v / sum).collect())
}

/// Sobel over the whole image: `gx` = the `[−1 0 1; −2 0 2; −1 0 1]`
/// response (right minus left, [`super::sobel_y`]), `gy` its transpose
/// (down minus up, −[`super::sobel_x`]), `mag = √(gx² + gy²)`.
pub fn sobel(
    img: impl Rows,
    border: Border,
    gx: &mut [f32],
    gy: &mut [f32],
    mag: &mut [f32],
) -> Result<()> {
    let (w, h) = (img.width(), img.height());
    for (f, o) in [("gx", &*gx), ("gy", &*gy), ("magnitude", &*mag)] {
        check_len(f, o, w * h)?;
    }
    let mut ring = RowRing::new(w, 1);
    let mut vs = vec![0.0f32; w + 2];
    let mut vd = vec![0.0f32; w + 2];
    let rows_out = gx
        .chunks_exact_mut(w)
        .zip(gy.chunks_exact_mut(w))
        .zip(mag.chunks_exact_mut(w));
    for (r, ((ox, oy), om)) in rows_out.enumerate() {
        let rows = ring.rows(&img, r, 1, border);
        vertical(&rows, &[1.0, 2.0, 1.0], &mut vs[1..=w]);
        vertical(&rows, &[-1.0, 0.0, 1.0], &mut vd[1..=w]);
        pad_row(&mut vs, w, 1, border, 0.0);
        pad_row(&mut vd, w, 1, border, 0.0);
        horizontal(&vs, &[-1.0, 0.0, 1.0], 1.0, ox);
        horizontal(&vd, &[1.0, 2.0, 1.0], 1.0, oy);
        magnitude(ox, oy, om);
    }
    Ok(())
}

/// `m = √(x² + y²)`.
fn magnitude(x: &[f32], y: &[f32], m: &mut [f32]) {
    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
    let done = 0;
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    let done = {
        let n = m.len().min(x.len()).min(y.len()) / 4 * 4;
        let mut i = 0;
        while i < n {
            // SAFETY: i + 4 ≤ n ≤ every length.
            unsafe {
                let a = v128_load(x.as_ptr().add(i) as *const v128);
                let b = v128_load(y.as_ptr().add(i) as *const v128);
                let s = f32x4_sqrt(f32x4_add(f32x4_mul(a, a), f32x4_mul(b, b)));
                v128_store(m.as_mut_ptr().add(i) as *mut v128, s);
            }
            i += 4;
        }
        n
    };
    for ((a, b), o) in x.iter().zip(y).zip(m.iter_mut()).skip(done) {
        *o = (a * a + b * b).sqrt();
    }
}
