//! A decoded photo to grey values in one pass: upright by its EXIF
//! orientation and reduced to the working size by an integer factor `k`
//! (each grey value the area average of a `k × k` block of the upright
//! photo), without an intermediate copy of the photo (no rotated copy, no
//! full-size grey grid: the only grid held is the working one).
//!
//! Each pixel's luma is summed as the whole number `299·R + 587·G + 114·B`
//! (`1000·v` for a grey pixel; exact in `f64` for 8- and 16-bit samples,
//! also summed over a block), and each sum is divided by `1000·k²` once:
//! at `k = 1` the value is [`super::luma`] of the pixel, bit for bit.

use image::DynamicImage;

/// The upright size of a photo stored `w × h` with EXIF orientation `exif`
/// (5 … 8 swap the sides).
pub fn upright_size(exif: u8, w: usize, h: usize) -> (usize, usize) {
    if exif >= 5 {
        (h, w)
    } else {
        (w, h)
    }
}

/// Stored rows turned into one tile when the upright rows are the stored
/// columns (orientations 5 … 8): each stored column of the tile is then
/// written as one run of `TILE` values into its upright row.
const TILE: usize = 64;

/// The `ow × oh` grid of block sums of `f(pixel)` over the upright photo
/// (blocks of `k × k`; the upright photo's last `< k` columns and rows,
/// when its sides are not multiples of `k`, are left out), divided by
/// `1000·k²`. `samples`: the stored photo, `w × h` pixels of `ch` samples.
///
/// Where stored pixel `(x, y)` of a photo stored `w × h` lands upright, by
/// EXIF orientation: 1 `(x, y)`; 2 `(w−1−x, y)` (mirrored left to right);
/// 3 `(w−1−x, h−1−y)` (turned 180°); 4 `(x, h−1−y)` (mirrored top to
/// bottom); 5 `(y, x)`; 6 `(h−1−y, x)` (turned 90° clockwise: the stored
/// top row becomes the right column); 7 `(h−1−y, w−1−x)`; 8 `(y, w−1−x)`
/// (turned 90° counter-clockwise).
fn blocks<T: Copy>(
    samples: &[T],
    ch: usize,
    (w, h): (usize, usize),
    exif: u8,
    k: usize,
    (ow, oh): (usize, usize),
    f: impl Fn(&[T]) -> f64,
) -> Vec<f64> {
    let div = (1000 * k * k) as f64;
    if k == 1 && !(2..=8).contains(&exif) {
        return samples.chunks_exact(ch).map(|p| f(p) / div).collect();
    }
    let mut out = vec![0.0; ow * oh];
    let (uw, vh) = (ow * k, oh * k);
    // stored row y's values f(pixel), in stored order
    let row_of = |y: usize, buf: &mut [f64]| {
        let src = &samples[y * w * ch..(y + 1) * w * ch];
        for (b, p) in buf.iter_mut().zip(src.chunks_exact(ch)) {
            *b = f(p);
        }
    };
    if exif < 5 {
        // a stored row is an upright row (v), read backwards when mirrored
        let mut row = vec![0.0; w];
        for y in 0..h {
            let v = if matches!(exif, 3 | 4) { h - 1 - y } else { y };
            if v >= vh {
                continue;
            }
            row_of(y, &mut row);
            if matches!(exif, 2 | 3) {
                row.reverse();
            }
            let dst = &mut out[(v / k) * ow..(v / k + 1) * ow];
            for (d, block) in dst.iter_mut().zip(row.chunks_exact(k)) {
                *d += block.iter().sum::<f64>();
            }
        }
    } else {
        // a stored row is an upright column (u), a stored column an upright row (v)
        let mut tile = vec![0.0; TILE * w];
        let mut col = [usize::MAX; TILE];
        for y0 in (0..h).step_by(TILE) {
            let n = TILE.min(h - y0);
            for t in 0..n {
                let y = y0 + t;
                row_of(y, &mut tile[t * w..(t + 1) * w]);
                let u = if matches!(exif, 6 | 7) { h - 1 - y } else { y };
                col[t] = if u < uw { u / k } else { usize::MAX };
            }
            for x in 0..w {
                let v = if matches!(exif, 7 | 8) { w - 1 - x } else { x };
                if v >= vh {
                    continue;
                }
                let dst = &mut out[(v / k) * ow..(v / k + 1) * ow];
                for t in 0..n {
                    if col[t] != usize::MAX {
                        dst[col[t]] += tile[t * w + x];
                    }
                }
            }
        }
    }
    for v in &mut out {
        *v /= div;
    }
    out
}

/// The stored photo's kind: `"grey"` or `"colour"`, bits per sample, and
/// the largest value of that depth.
pub type Kind = (&'static str, u32, f64);

/// Grey values of `img` (stored orientation), upright by `exif` and
/// reduced by `k` to `ow × oh`; `None` for a pixel layout the lab does not
/// read.
pub fn grey(
    img: &DynamicImage,
    exif: u8,
    k: usize,
    out: (usize, usize),
) -> Option<(Vec<f64>, Kind)> {
    let size = (img.width() as usize, img.height() as usize);
    // one instance of `blocks` per sample type (a smaller wasm module);
    // grey or colour is a branch per pixel
    fn luma1000(colour: bool, r: f64, g: impl FnOnce() -> (f64, f64)) -> f64 {
        if colour {
            let (g, b) = g();
            299.0 * r + 587.0 * g + 114.0 * b
        } else {
            1000.0 * r
        }
    }
    let run8 = |s: &[u8], ch: usize, colour: bool| {
        blocks(s, ch, size, exif, k, out, |p| {
            luma1000(colour, f64::from(p[0]), || {
                (f64::from(p[1]), f64::from(p[2]))
            })
        })
    };
    let run16 = |s: &[u16], ch: usize, colour: bool| {
        blocks(s, ch, size, exif, k, out, |p| {
            luma1000(colour, f64::from(p[0]), || {
                (f64::from(p[1]), f64::from(p[2]))
            })
        })
    };
    let run32 = |s: &[f32], ch: usize| {
        blocks(s, ch, size, exif, k, out, |p| {
            luma1000(true, f64::from(p[0]), || (f64::from(p[1]), f64::from(p[2])))
        })
    };
    const G8: Kind = ("grey", 8, 255.0);
    const C8: Kind = ("colour", 8, 255.0);
    const G16: Kind = ("grey", 16, 65535.0);
    const C16: Kind = ("colour", 16, 65535.0);
    const C32: Kind = ("colour", 32, 1.0);
    Some(match img {
        DynamicImage::ImageLuma8(b) => (run8(b.as_raw(), 1, false), G8),
        DynamicImage::ImageLumaA8(b) => (run8(b.as_raw(), 2, false), G8),
        DynamicImage::ImageRgb8(b) => (run8(b.as_raw(), 3, true), C8),
        DynamicImage::ImageRgba8(b) => (run8(b.as_raw(), 4, true), C8),
        DynamicImage::ImageLuma16(b) => (run16(b.as_raw(), 1, false), G16),
        DynamicImage::ImageLumaA16(b) => (run16(b.as_raw(), 2, false), G16),
        DynamicImage::ImageRgb16(b) => (run16(b.as_raw(), 3, true), C16),
        DynamicImage::ImageRgba16(b) => (run16(b.as_raw(), 4, true), C16),
        DynamicImage::ImageRgb32F(b) => (run32(b.as_raw(), 3), C32),
        DynamicImage::ImageRgba32F(b) => (run32(b.as_raw(), 4), C32),
        _ => return None,
    })
}
