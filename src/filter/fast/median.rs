//! The 3×3 median of [`super`]: on 8-bit images ([`median3`]) and on
//! `f32` images ([`median3_f32`]); each output is exactly the middle of
//! the nine values its reference ([`crate::filter::median`]) takes.

use super::{effective, pad_row, row_at};
use crate::error::Result;
use crate::raster::{check_len, fold, Border, Gray, GrayF32};

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
use core::arch::wasm32::*;

/// The 3×3 median of an 8-bit image: each column of three sorted once
/// (`lo ≤ mid ≤ hi`), then per pixel the median of
/// `max(lo)`, `med(mid)`, `min(hi)` over the three columns — exactly the
/// middle of the nine values. With `+simd128` 16 pixels per step
/// ([`median3_rows`]).
pub fn median3(img: Gray, border: Border, out: &mut [u8]) -> Result<()> {
    let (w, h) = (img.width(), img.height());
    check_len("output", out, w * h)?;
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    return median3_rows(img, border, out);
    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
    median3_columns(img, border, out)
}

/// [`median3`] without `+simd128`: every row's columns sorted into three
/// padded rows, then combined.
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
fn median3_columns(img: Gray, border: Border, out: &mut [u8]) -> Result<()> {
    let w = img.width();
    let zeros = vec![0u8; w];
    let mut lo = vec![0u8; w + 2];
    let mut mid = vec![0u8; w + 2];
    let mut hi = vec![0u8; w + 2];
    for (r, o) in out.chunks_exact_mut(w).enumerate() {
        let r = r as isize;
        let a = row_at(&img, r - 1, border).unwrap_or(&zeros);
        let b = row_at(&img, r, border).unwrap_or(&zeros);
        let c = row_at(&img, r + 1, border).unwrap_or(&zeros);
        sort_columns(a, b, c, &mut lo[1..=w], &mut mid[1..=w], &mut hi[1..=w]);
        pad_row(&mut lo, w, 1, border, 0);
        pad_row(&mut mid, w, 1, border, 0);
        pad_row(&mut hi, w, 1, border, 0);
        combine_median(&lo, &mid, &hi, o);
    }
    Ok(())
}

/// [`median3`] of an `f32` image (its values, none NaN): the same sorted
/// columns and the same selection, scalar — every output is one of the
/// nine inputs, as the reference's median is.
pub fn median3_f32(img: GrayF32, border: Border, out: &mut [f32]) -> Result<()> {
    let (w, h) = (img.width(), img.height());
    check_len("output", out, w * h)?;
    let zeros = vec![0.0f32; w];
    let mut lo = vec![0.0f32; w + 2];
    let mut mid = vec![0.0f32; w + 2];
    let mut hi = vec![0.0f32; w + 2];
    let (mn, mx) = (
        |a: f32, b: f32| if b < a { b } else { a },
        |a: f32, b: f32| if b > a { b } else { a },
    );
    let m3 = |a: f32, b: f32, c: f32| mx(mn(a, b), mn(mx(a, b), c));
    for (r, o) in out.chunks_exact_mut(w).enumerate() {
        let r = r as isize;
        let at = |d: isize| {
            fold(r + d, h, effective(border))
                .and_then(|i| img.row(i))
                .unwrap_or(&zeros)
        };
        let (a, b, c) = (at(-1), at(0), at(1));
        for x in 0..w {
            let (va, vb, vc) = (a[x], b[x], c[x]);
            let (l1, h1) = (mn(va, vb), mx(va, vb));
            let m1 = mx(l1, vc);
            lo[x + 1] = mn(l1, vc);
            mid[x + 1] = mn(m1, h1);
            hi[x + 1] = mx(m1, h1);
        }
        pad_row(&mut lo, w, 1, border, 0.0);
        pad_row(&mut mid, w, 1, border, 0.0);
        pad_row(&mut hi, w, 1, border, 0.0);
        for (x, o) in o.iter_mut().enumerate() {
            let l = mx(mx(lo[x], lo[x + 1]), lo[x + 2]);
            let m = m3(mid[x], mid[x + 1], mid[x + 2]);
            let hh = mn(mn(hi[x], hi[x + 1]), hi[x + 2]);
            *o = m3(l, m, hh);
        }
    }
    Ok(())
}

fn med3(a: u8, b: u8, c: u8) -> u8 {
    a.min(b).max(a.max(b).min(c))
}

/// `(a, b, c)` sorted.
fn sort3(a: u8, b: u8, c: u8) -> [u8; 3] {
    let (l1, h1) = (a.min(b), a.max(b));
    let m1 = l1.max(c);
    [l1.min(c), m1.min(h1), m1.max(h1)]
}

/// Sorts each column `(a[x], b[x], c[x])` into `lo[x] ≤ mid[x] ≤ hi[x]`.
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
fn sort_columns(a: &[u8], b: &[u8], c: &[u8], lo: &mut [u8], mid: &mut [u8], hi: &mut [u8]) {
    for (x, ((l, m), hh)) in lo
        .iter_mut()
        .zip(mid.iter_mut())
        .zip(hi.iter_mut())
        .enumerate()
    {
        let g = |r: &[u8]| r.get(x).copied().unwrap_or(0);
        [*l, *m, *hh] = sort3(g(a), g(b), g(c));
    }
}

/// `out[x] = med(max(lo[x..x+3]), med(mid[x..x+3]), min(hi[x..x+3]))`
/// (the sorted columns padded by one on each side).
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
fn combine_median(lo: &[u8], mid: &[u8], hi: &[u8], out: &mut [u8]) {
    for (x, o) in out.iter_mut().enumerate() {
        let g = |s: &[u8], i: usize| s.get(i).copied().unwrap_or(0);
        let l = g(lo, x).max(g(lo, x + 1)).max(g(lo, x + 2));
        let m = med3(g(mid, x), g(mid, x + 1), g(mid, x + 2));
        let hh = g(hi, x).min(g(hi, x + 1)).min(g(hi, x + 2));
        *o = med3(l, m, hh);
    }
}

/// The median at column `x` of the three rows `rows` (columns outside
/// read by `border`, zeros where it reads nothing).
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn median_at(rows: [&[u8]; 3], x: usize, border: Border) -> u8 {
    let w = rows[1].len();
    let col = |c: isize| {
        let i = fold(c, w, effective(border));
        let g = |r: &[u8]| i.and_then(|i| r.get(i)).copied().unwrap_or(0);
        sort3(g(rows[0]), g(rows[1]), g(rows[2]))
    };
    let x = x as isize;
    let (a, b, c) = (col(x - 1), col(x), col(x + 1));
    let l = a[0].max(b[0]).max(c[0]);
    let m = med3(a[1], b[1], c[1]);
    let hh = a[2].min(b[2]).min(c[2]);
    med3(l, m, hh)
}

/// [`median3`] with `+simd128`, one output row at a time: the sorted
/// columns (`lo ≤ mid ≤ hi`) of 16 pixels at a time kept in registers,
/// their left and right neighbours' taken from the blocks beside by a
/// byte shuffle (no store and reload of sorted rows); the last `w mod 16`
/// pixels by [`median_at`].
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn median3_rows(img: Gray, border: Border, out: &mut [u8]) -> Result<()> {
    let w = img.width();
    if w == 0 {
        return Ok(());
    }
    let zeros = vec![0u8; w];
    let row = |r: usize, d: isize| row_at(&img, r as isize + d, border).unwrap_or(&zeros);
    for (r, o) in out.chunks_exact_mut(w).enumerate() {
        let rows = [row(r, -1), row(r, 0), row(r, 1)];
        let done = median_row_simd(rows, border, o);
        for (x, v) in o.iter_mut().enumerate().skip(done) {
            *v = median_at(rows, x, border);
        }
    }
    Ok(())
}

/// The SIMD part of [`median3_rows`] for one output row: its first
/// `w / 16 · 16` pixels; returns how many.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn median_row_simd(rows: [&[u8]; 3], border: Border, o: &mut [u8]) -> usize {
    let w = o.len();
    if rows.iter().any(|r| r.len() < w) {
        return 0;
    }
    let n = w / 16 * 16;
    if n == 0 {
        return 0;
    }
    let [ra, rb, rc] = rows;
    // the sorted columns x … x + 15: (lo, mid, hi)
    let block = |x: usize| {
        // SAFETY: x + 16 ≤ n ≤ w ≤ every row's length (checked above).
        let ld = |r: &[u8]| unsafe { v128_load(r.as_ptr().add(x) as *const v128) };
        let (a, b, c) = (ld(ra), ld(rb), ld(rc));
        let (l1, h1) = (u8x16_min(a, b), u8x16_max(a, b));
        let m1 = u8x16_max(l1, c);
        (u8x16_min(l1, c), u8x16_min(m1, h1), u8x16_max(m1, h1))
    };
    // the sorted single column c (outside read by the border), every lane
    let splat = |c: isize| {
        let i = fold(c, w, effective(border));
        let [a, b, cc] = rows.map(|r| i.and_then(|i| r.get(i)).copied().unwrap_or(0));
        let [l, m, h] = sort3(a, b, cc);
        (u8x16_splat(l), u8x16_splat(m), u8x16_splat(h))
    };
    let m3 = |a: v128, b: v128, c: v128| u8x16_max(u8x16_min(a, b), u8x16_min(u8x16_max(a, b), c));
    // columns x − 1 … x + 14 and x + 1 … x + 16
    let left = |p: v128, c: v128| {
        i8x16_shuffle::<15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30>(p, c)
    };
    let right = |c: v128, n: v128| {
        i8x16_shuffle::<1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16>(c, n)
    };
    let med = |p: (v128, v128, v128), c: (v128, v128, v128), n: (v128, v128, v128)| {
        let l = u8x16_max(u8x16_max(left(p.0, c.0), c.0), right(c.0, n.0));
        let m = m3(left(p.1, c.1), c.1, right(c.1, n.1));
        let h = u8x16_min(u8x16_min(left(p.2, c.2), c.2), right(c.2, n.2));
        m3(l, m, h)
    };
    let op = o.as_mut_ptr();
    let mut prev = splat(-1);
    let mut cur = block(0);
    let mut x = 0;
    while x + 16 < n {
        let next = block(x + 16);
        // SAFETY: x + 16 ≤ n ≤ w = o.len().
        unsafe { v128_store(op.add(x) as *mut v128, med(prev, cur, next)) };
        prev = cur;
        cur = next;
        x += 16;
    }
    let next = splat(n as isize);
    // SAFETY: x + 16 = n ≤ w = o.len().
    unsafe { v128_store(op.add(x) as *mut v128, med(prev, cur, next)) };
    n
}
