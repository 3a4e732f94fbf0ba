//! The Förstner measures `w` and `q` of every pixel of an 8-bit image at
//! once, with running sums instead of one window per pixel.
//!
//! Per pixel: central differences `dx = I(c+1, r) − I(c−1, r)`,
//! `dy = I(c, r+1) − I(c, r−1)` (border replicate; `g′x = dx/2`), the
//! products `dx²`, `dy²`, `dx·dy` as integers, their 5×5 (or any odd
//! `size`) window sums with the product images replicated at the border,
//! then `det N = Sxx·Syy − Sxy²`, `trace N = Sxx + Syy` (exact integers in
//! `f64`, in units of `1/4` per sum), `w = det/trace`, `q = 4·det/trace²`,
//! both 0 where the trace is 0. This is the benchmark's T3 definition.
//!
//! Where the window fits, it is the core's [`super::forstner_map`] with a
//! `(size + 2)`-pixel window (whose gradients are the `size × size`
//! interior), up to its `det ≤ 10⁻¹²·trace²` rule that sets a near-zero
//! `det` to 0; on the border it is [`super::Measures::from_sums`] of the
//! replicated sums (`tests/web_fast.rs`).
//!
//! [`moravec`]: the Moravec mean of every window, from a sum table of the
//! per-pixel sums of four squared differences, equal to
//! [`super::moravec_map`] exactly.

use crate::error::{Error, Result};
use crate::raster::{check_len, fold, Border, Gray};

pub mod stream;

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
use core::arch::wasm32::*;

/// The products `dx², dy², dx·dy` of image row `r`.
fn products(img: &Gray, r: usize, pxx: &mut [i32], pyy: &mut [i32], pxy: &mut [i32]) {
    let (w, h) = (img.width(), img.height());
    let row = |i: isize| {
        fold(i, h, Border::Replicate)
            .and_then(|i| img.row(i))
            .unwrap_or(&[])
    };
    let (up, mid, down) = (row(r as isize - 1), row(r as isize), row(r as isize + 1));
    let at = |s: &[u8], c: usize| i32::from(s.get(c).copied().unwrap_or(0));
    for c in 0..w {
        let dx = at(mid, (c + 1).min(w - 1)) - at(mid, c.saturating_sub(1));
        let dy = at(down, c) - at(up, c);
        if let (Some(a), Some(b), Some(d)) = (pxx.get_mut(c), pyy.get_mut(c), pxy.get_mut(c)) {
            *a = dx * dx;
            *b = dy * dy;
            *d = dx * dy;
        }
    }
}

/// Product rows kept in a ring of `size` slots keyed by image row.
struct ProductRing {
    rows: Vec<[Vec<i32>; 3]>,
    tags: Vec<Option<usize>>,
}

impl ProductRing {
    fn slot(&mut self, img: &Gray, r: usize) -> usize {
        let s = r % self.rows.len();
        if self.tags[s] != Some(r) {
            if let Some([a, b, d]) = self.rows.get_mut(s) {
                products(img, r, a, b, d);
            }
            self.tags[s] = Some(r);
        }
        s
    }
}

/// `dst[x] = Σ_k rows[k][x]`.
fn add_rows(rows: &[&[i32]], dst: &mut [i32]) {
    dst.fill(0);
    for r in rows {
        #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
        let done = 0;
        #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
        let done = {
            let n = dst.len().min(r.len()) / 4 * 4;
            let mut x = 0;
            while x < n {
                // SAFETY: x + 4 ≤ n ≤ both lengths.
                unsafe {
                    let p = dst.as_mut_ptr().add(x) as *mut v128;
                    let v = v128_load(r.as_ptr().add(x) as *const v128);
                    v128_store(p, i32x4_add(v128_load(p), v));
                }
                x += 4;
            }
            n
        };
        for (d, v) in dst.iter_mut().zip(r.iter()).skip(done) {
            *d += v;
        }
    }
}

/// `dst[x] = Σ_{i < size} src[x + i]` (a running sum along the row).
fn box_row(src: &[i32], size: usize, dst: &mut [i32]) {
    let mut s: i32 = src.iter().take(size).sum();
    let mut iter = dst.iter_mut().enumerate().peekable();
    while let Some((x, d)) = iter.next() {
        *d = s;
        if iter.peek().is_some() {
            s += src.get(x + size).copied().unwrap_or(0) - src.get(x).copied().unwrap_or(0);
        }
    }
}

/// `w` and `q` of every pixel for a `size × size` window of gradients
/// (odd, 3 … 31), border replicate.
pub fn forstner_wq(img: Gray, size: usize, w_out: &mut [f32], q_out: &mut [f32]) -> Result<()> {
    if size.is_multiple_of(2) || !(3..=31).contains(&size) {
        return Err(Error::input(
            "window_size",
            format!("must be odd, 3 … 31 (got {size})"),
        ));
    }
    let (w, h) = (img.width(), img.height());
    check_len("w", w_out, w * h)?;
    check_len("q", q_out, w * h)?;
    let rad = size / 2;
    let mut ring = ProductRing {
        rows: (0..size)
            .map(|_| [vec![0; w], vec![0; w], vec![0; w]])
            .collect(),
        tags: vec![None; size],
    };
    let mut vert = [
        vec![0i32; w + 2 * rad],
        vec![0i32; w + 2 * rad],
        vec![0i32; w + 2 * rad],
    ];
    let mut sums = [vec![0i32; w], vec![0i32; w], vec![0i32; w]];
    for (r, (wo, qo)) in w_out
        .chunks_exact_mut(w)
        .zip(q_out.chunks_exact_mut(w))
        .enumerate()
    {
        let slots: Vec<usize> = (0..size)
            .map(|j| {
                let i = fold(r as isize + j as isize - rad as isize, h, Border::Replicate);
                ring.slot(&img, i.unwrap_or(0))
            })
            .collect();
        for (k, (v, s)) in vert.iter_mut().zip(sums.iter_mut()).enumerate() {
            let rows: Vec<&[i32]> = slots
                .iter()
                .filter_map(|&sl| ring.rows.get(sl).map(|p| &p[k][..]))
                .collect();
            add_rows(&rows, &mut v[rad..rad + w]);
            crate::filter::fast::pad_row(v, w, rad, Border::Replicate, 0);
            box_row(v, size, s);
        }
        measures(&sums[0], &sums[1], &sums[2], wo, qo);
    }
    Ok(())
}

/// `w = det/(4·trace)`, `q = 4·det/trace²` from the sums of `dx²`, `dy²`,
/// `dx·dy` (each 4× the sum of `g′` products).
fn measures(sxx: &[i32], syy: &[i32], sxy: &[i32], wo: &mut [f32], qo: &mut [f32]) {
    let it = sxx
        .iter()
        .zip(syy)
        .zip(sxy)
        .zip(wo.iter_mut().zip(qo.iter_mut()));
    for (((&a, &d), &b), (wv, qv)) in it {
        let (a, d, b) = (f64::from(a), f64::from(d), f64::from(b));
        let tr = a + d;
        if tr > 0.0 {
            let det = a * d - b * b;
            *wv = (det / (4.0 * tr)) as f32;
            *qv = (4.0 * det / (tr * tr)) as f32;
        } else {
            *wv = 0.0;
            *qv = 0.0;
        }
    }
}

/// The Moravec mean of every pixel's `size × size` window, with a sum table
/// instead of one window per pixel: [`super::moravec_map`] at every pixel
/// (`NaN` where it has no value: the window does not fit), exactly — the
/// per-pixel sums of the four squared differences
/// `(I(c+1, r) − I(c−1, r))² + (I(c, r+1) − I(c, r−1))² + …` are integers,
/// each window adds the `(size − 2)²` of its interior as an exact integer
/// (the reference adds the same integers in `f64`, exactly below 2⁵³) and
/// divides by their count as the reference does (`tests/web_fast.rs`).
pub fn moravec(img: Gray, size: usize, out: &mut [f64]) -> Result<()> {
    let (w, h) = (img.width(), img.height());
    if !(super::MIN_WINDOW..=super::MAX_WINDOW).contains(&size) {
        return Err(Error::input(
            "window_size",
            format!(
                "must be between {} and {} (got {size})",
                super::MIN_WINDOW,
                super::MAX_WINDOW
            ),
        ));
    }
    if w < size || h < size {
        return Err(Error::input(
            "image",
            format!("is {h}×{w}, smaller than the {size}×{size} window"),
        ));
    }
    check_len("output", out, w * h)?;
    let data = img.data();
    let px = |c: usize, r: usize| i64::from(data.get(r * w + c).copied().unwrap_or(0));
    // sum table of the per-pixel sums (0 on the image's outer ring, which
    // no window interior reaches), zero first row and column
    let stride = w + 1;
    let mut st = vec![0i64; stride * (h + 1)];
    for r in 0..h {
        let mut run = 0i64;
        for c in 0..w {
            if c >= 1 && c + 1 < w && r >= 1 && r + 1 < h {
                let d = |a: i64, b: i64| (a - b) * (a - b);
                run += d(px(c + 1, r), px(c - 1, r))
                    + d(px(c, r + 1), px(c, r - 1))
                    + d(px(c + 1, r + 1), px(c - 1, r - 1))
                    + d(px(c - 1, r + 1), px(c + 1, r - 1));
            }
            let i = (r + 1) * stride + c + 1;
            st[i] = st[i - stride] + run;
        }
    }
    let (a, k) = (super::anchor(size), size - 2);
    let count = (k * k) as f64;
    for (r, row) in out.chunks_exact_mut(w).enumerate() {
        for (c, o) in row.iter_mut().enumerate() {
            // the window's top-left (c − a, r − a) and its interior from +1
            *o = if c >= a && r >= a && c - a + size <= w && r - a + size <= h {
                let (x0, y0) = (c - a + 1, r - a + 1);
                let sum = st[(y0 + k) * stride + x0 + k]
                    - st[y0 * stride + x0 + k]
                    - st[(y0 + k) * stride + x0]
                    + st[y0 * stride + x0];
                sum as f64 / count
            } else {
                f64::NAN
            };
        }
    }
    Ok(())
}
