//! Result layers and photos to RGBA pixels: the page's one colour
//! convention (`www/colour-scales.js`), computed here instead of in a
//! per-pixel JavaScript loop.
//!
//! - A grey (unsigned) layer is stretched from its smallest to its largest
//!   finite value: `g = round((v − lo) / (hi − lo) · 255)`, dark = low (the
//!   photo itself is painted the same way).
//! - A signed layer is symmetric about 0 (`m = max(|min|, |max|)`): white at
//!   0, towards the negative end colour (blue) below and the positive one
//!   (orange) above, `round(255 − |v/m| · (255 − end))` per channel.
//! - NaN and ±∞ are transparent (`[0, 0, 0, 0]`).
//!
//! `round` is JavaScript's `Math.round` (halves up) on these non-negative
//! numbers, so the pixels are those the page painted before. The end colours
//! are the caller's (the worker passes colour-scales.js's), never a second
//! copy here.

/// A layer's value (`f32` or `f64`), read as `f64` as JavaScript reads it.
pub trait Value: Copy {
    fn get(self) -> f64;
}

impl Value for f64 {
    #[inline(always)]
    fn get(self) -> f64 {
        self
    }
}

impl Value for f32 {
    #[inline(always)]
    fn get(self) -> f64 {
        self as f64
    }
}

/// How a layer's values map to colours (the legend shows it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scale {
    /// Diverging about 0 (`lo = −hi`), else a grey stretch.
    pub signed: bool,
    /// The values painted at the ends of the scale.
    pub lo: f64,
    pub hi: f64,
    /// The smallest and largest finite values (0, 0 when there is none).
    pub min: f64,
    pub max: f64,
}

/// The smallest and largest finite values of `data`, folded into `acc`
/// (start with [`Range::EMPTY`]; a layer read in parts folds each part).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    pub min: f64,
    pub max: f64,
}

impl Range {
    pub const EMPTY: Range = Range {
        min: f64::INFINITY,
        max: f64::NEG_INFINITY,
    };

    /// `self` widened by the finite values of `data`.
    pub fn fold<T: Value>(self, data: &[T]) -> Range {
        let (mut lo, mut hi) = (self.min, self.max);
        for v in data {
            let v = v.get();
            if v.is_finite() {
                lo = lo.min(v);
                hi = hi.max(v);
            }
        }
        Range { min: lo, max: hi }
    }
}

impl Scale {
    /// The scale of a layer whose finite values span `range`.
    pub fn new(range: Range, signed: bool) -> Scale {
        let (min, max) = if range.min <= range.max {
            (range.min, range.max)
        } else {
            (0.0, 0.0)
        };
        if signed {
            let m = min.abs().max(max.abs());
            let m = if m == 0.0 { 1.0 } else { m };
            Scale {
                signed,
                lo: -m,
                hi: m,
                min,
                max,
            }
        } else {
            Scale {
                signed,
                lo: min,
                hi: if max > min { max } else { min + 1.0 },
                min,
                max,
            }
        }
    }

    /// The scale of `data`.
    pub fn of<T: Value>(data: &[T], signed: bool) -> Scale {
        Scale::new(Range::EMPTY.fold(data), signed)
    }
}

/// The end colours of the signed scale (RGB), below and above 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Ends {
    pub negative: [u8; 3],
    pub positive: [u8; 3],
}

/// `Math.round(x)` for `0 ≤ x < 2⁵²`: the nearest integer, halves up
/// (`x − trunc(x)` is exact there; `floor(x + 0.5)` is not always).
#[inline(always)]
fn round_up(x: f64) -> f64 {
    let t = x.trunc();
    if x - t >= 0.5 {
        t + 1.0
    } else {
        t
    }
}

/// The RGBA of one value on `scale`.
#[inline(always)]
pub fn colour(v: f64, scale: &Scale, ends: &Ends) -> [u8; 4] {
    if !v.is_finite() {
        return [0, 0, 0, 0];
    }
    if scale.signed {
        let u = (v / scale.hi).clamp(-1.0, 1.0);
        let end = if u < 0.0 {
            ends.negative
        } else {
            ends.positive
        };
        let a = u.abs();
        let ch = |e: u8| round_up(255.0 - a * (255.0 - e as f64)) as u8;
        [ch(end[0]), ch(end[1]), ch(end[2]), 255]
    } else {
        let g = round_up(((v - scale.lo) / (scale.hi - scale.lo)) * 255.0) as u8;
        [g, g, g, 255]
    }
}

/// `data` painted on `scale` into `out` (4 bytes a value).
pub fn paint<T: Value>(data: &[T], scale: &Scale, ends: &Ends, out: &mut [u8]) {
    assert_eq!(
        out.len(),
        data.len() * 4,
        "paint: out must hold 4 bytes a value"
    );
    if !scale.signed {
        grey(data, scale, out);
        return;
    }
    for (v, px) in data.iter().zip(out.chunks_exact_mut(4)) {
        px.copy_from_slice(&colour(v.get(), scale, ends));
    }
}

/// The grey stretch (every photo, most layers).
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
fn grey<T: Value>(data: &[T], scale: &Scale, out: &mut [u8]) {
    let ends = Ends {
        negative: [0; 3],
        positive: [0; 3],
    };
    for (v, px) in data.iter().zip(out.chunks_exact_mut(4)) {
        px.copy_from_slice(&colour(v.get(), scale, &ends));
    }
}

/// The grey stretch, two values a step (`f64x2`): the same arithmetic as
/// [`colour`] (subtract, divide, multiply, round halves up), so the same
/// bytes; NaN and ±∞ give 0 in all four bytes.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn grey<T: Value>(data: &[T], scale: &Scale, out: &mut [u8]) {
    use core::arch::wasm32::*;
    let lo = f64x2_splat(scale.lo);
    let span = f64x2_splat(scale.hi - scale.lo);
    let k255 = f64x2_splat(255.0);
    let half = f64x2_splat(0.5);
    let one = f64x2_splat(1.0);
    let zero = f64x2_splat(0.0);
    let alpha = u32x4_splat(0xff00_0000);
    let grey3 = u32x4_splat(0x0001_0101);
    let mut pairs = data.chunks_exact(2);
    let mut outs = out.chunks_exact_mut(8);
    for (p, o) in (&mut pairs).zip(&mut outs) {
        let v = f64x2(p[0].get(), p[1].get());
        let t = f64x2_mul(f64x2_div(f64x2_sub(v, lo), span), k255);
        let tr = f64x2_trunc(t);
        let up = f64x2_ge(f64x2_sub(t, tr), half);
        let r = f64x2_add(tr, v128_and(up, one));
        // finite: v − v == 0 (NaN, ±∞ give NaN); a mask of 64-bit lanes
        let finite = f64x2_eq(f64x2_sub(v, v), zero);
        let g = i32x4_trunc_sat_f64x2_zero(r);
        // 0 … 255 in the two low lanes: g·0x010101 | alpha, where finite
        let px = v128_or(i32x4_mul(g, grey3), alpha);
        let keep = i32x4_shuffle::<0, 2, 4, 4>(finite, zero);
        let px = v128_and(px, keep);
        o.copy_from_slice(&u64x2_extract_lane::<0>(px).to_le_bytes());
    }
    let ends = Ends {
        negative: [0; 3],
        positive: [0; 3],
    };
    for (v, px) in pairs
        .remainder()
        .iter()
        .zip(outs.into_remainder().chunks_exact_mut(4))
    {
        px.copy_from_slice(&colour(v.get(), scale, &ends));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ENDS: Ends = Ends {
        negative: [29, 95, 191],
        positive: [217, 119, 6],
    };

    /// The page's JavaScript painting (view.js before this module), as a spec.
    fn js(v: f64, s: &Scale) -> [u8; 4] {
        let js_round = |x: f64| (x + 0.5).floor();
        if !v.is_finite() {
            return [0, 0, 0, 0];
        }
        if s.signed {
            let u = (v / s.hi).clamp(-1.0, 1.0);
            let e = if u < 0.0 {
                ENDS.negative
            } else {
                ENDS.positive
            };
            let a = u.abs();
            let c = |e: u8| js_round(255.0 - a * (255.0 - e as f64)) as u8;
            [c(e[0]), c(e[1]), c(e[2]), 255]
        } else {
            let g = js_round(((v - s.lo) / (s.hi - s.lo)) * 255.0) as u8;
            [g, g, g, 255]
        }
    }

    fn painted<T: Value>(data: &[T], signed: bool) -> (Scale, Vec<u8>) {
        let s = Scale::of(data, signed);
        let mut out = vec![7u8; data.len() * 4];
        paint(data, &s, &ENDS, &mut out);
        (s, out)
    }

    #[test]
    fn grey_stretch_ends_and_halves() {
        // 0 … 2: 1 is exactly 127.5 → 128 (JavaScript rounds halves up)
        let (s, out) = painted(&[0.0f64, 1.0, 2.0, f64::NAN, f64::INFINITY], false);
        assert_eq!(
            (s.lo, s.hi, s.min, s.max, s.signed),
            (0.0, 2.0, 0.0, 2.0, false)
        );
        assert_eq!(
            out,
            [0, 0, 0, 255, 128, 128, 128, 255, 255, 255, 255, 255, 0, 0, 0, 0, 0, 0, 0, 0]
        );
    }

    #[test]
    fn a_flat_layer_is_black_and_an_empty_one_has_a_scale() {
        let (s, out) = painted(&[5.0f32, 5.0, 5.0], false);
        assert_eq!((s.lo, s.hi), (5.0, 6.0));
        assert_eq!(out, [0, 0, 0, 255].repeat(3));
        let (s, out) = painted(&[f64::NAN], false);
        assert_eq!((s.lo, s.hi, s.min, s.max), (0.0, 1.0, 0.0, 0.0));
        assert_eq!(out, [0, 0, 0, 0]);
        let s = Scale::of::<f64>(&[], true);
        assert_eq!((s.lo, s.hi), (-1.0, 1.0));
    }

    #[test]
    fn signed_scale_is_blue_white_orange() {
        let (s, out) = painted(&[-4.0f64, 0.0, 2.0, 4.0, -2.0], true);
        assert_eq!((s.lo, s.hi, s.min, s.max), (-4.0, 4.0, -4.0, 4.0));
        assert_eq!(&out[0..4], &[29, 95, 191, 255]);
        assert_eq!(&out[4..8], &[255, 255, 255, 255]);
        // halfway to orange: 255 − 0.5·(255 − e)
        assert_eq!(&out[8..12], &[236, 187, 131, 255]);
        assert_eq!(&out[12..16], &[217, 119, 6, 255]);
        assert_eq!(&out[16..20], &[142, 175, 223, 255]);
        // −0 is white (the positive side, |u| = 0)
        assert_eq!(painted(&[-0.0f64, 1.0], true).1[0..4], [255, 255, 255, 255]);
    }

    #[test]
    fn math_round_not_floor_of_x_plus_half() {
        // 0.49999999999999994 + 0.5 rounds to 1 in f64; Math.round gives 0
        assert_eq!(round_up(0.499_999_999_999_999_94), 0.0);
        assert_eq!(round_up(254.5), 255.0);
        assert_eq!(round_up(3.0), 3.0);
    }

    #[test]
    fn equals_the_javascript_painting_on_random_layers() {
        let mut s = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        };
        for n in [1usize, 2, 3, 7, 64, 1001] {
            for signed in [false, true] {
                let data: Vec<f64> = (0..n)
                    .map(|i| match next() % 23 {
                        0 => f64::NAN,
                        1 => f64::NEG_INFINITY,
                        2 => (i % 5) as f64 * 0.5,
                        _ => (next() % 100_000) as f64 / 997.0 - if signed { 50.0 } else { 0.0 },
                    })
                    .collect();
                let (sc, out) = painted(&data, signed);
                for (i, v) in data.iter().enumerate() {
                    // Math.round and floor(x + 0.5) agree away from the 0.49999999999999994 case
                    assert_eq!(
                        out[4 * i..4 * i + 4],
                        js(*v, &sc),
                        "n {n} signed {signed} value {v}"
                    );
                }
                let f: Vec<f32> = data.iter().map(|&v| v as f32).collect();
                let (sf, outf) = painted(&f, signed);
                for (i, v) in f.iter().enumerate() {
                    assert_eq!(outf[4 * i..4 * i + 4], js(*v as f64, &sf));
                }
            }
        }
    }
}
