//! Every border of a binary 8-bit image, outer and hole, by Suzuki and
//! Abe's border following (1985; OpenCV's `findContours(RETR_LIST,
//! CHAIN_APPROX_NONE)`): one raster scan over a label image, each border
//! followed once from its first pixel, every border pixel listed in order.
//!
//! Foreground is any non-zero byte, 8-connected; holes are the 4-connected
//! background components enclosed by it. Outside the image counts as
//! background. Each pixel is read by the raster scan once and by the
//! following at most 8 times per visit, and a pixel is visited at most
//! twice per border it lies on (once per pass of a one-pixel-wide part).
//! Built with `+simd128`, the scan tests 16 labels per step for the only
//! pixels that can start a border (non-zero with a zero left or right
//! neighbour) and skips the rest; the follower steps the point
//! coordinates with each move instead of dividing the label index.
//!
//! An outer border is [`super::trace`]'s boundary of the same region
//! (the same pixels from the same start, walked the other way round);
//! `tests/web_fast.rs` checks that, and that every border is exactly the
//! set of region pixels with a 4-neighbour in the background it separates.

use crate::error::Result;
use crate::raster::Gray;

/// One border: its pixels `(c, r)` in following order, and whether it is
/// the border of a hole.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Contour {
    pub points: Vec<(u32, u32)>,
    pub hole: bool,
}

/// Neighbour offsets `(dr, dc)`, counter-clockwise on the screen from east.
const DIRS: [(isize, isize); 8] = [
    (0, 1),
    (-1, 1),
    (-1, 0),
    (-1, -1),
    (0, -1),
    (1, -1),
    (1, 0),
    (1, 1),
];

/// All borders in the order the raster scan meets them.
pub fn contours(img: Gray) -> Result<Vec<Contour>> {
    let (w, h) = (img.width(), img.height());
    // label image with a background frame of one pixel: 0 background,
    // 1 foreground not yet on a border, 2 on a border, −2 on a border with
    // background to its east. Suzuki–Abe write the border's number NBD
    // there; without the hierarchy only its sign is ever read, so one byte
    // per pixel does (a quarter of the memory traffic of an i32 label).
    let pw = w + 2;
    let mut f = vec![0i8; pw * (h + 2)];
    for r in 0..h {
        let src = img.row(r).unwrap_or(&[]);
        let dst = f
            .get_mut((r + 1) * pw + 1..(r + 1) * pw + 1 + w)
            .unwrap_or(&mut []);
        for (d, &s) in dst.iter_mut().zip(src) {
            *d = i8::from(s != 0);
        }
    }
    let offs: [isize; 8] = DIRS.map(|(dr, dc)| dr * pw as isize + dc);
    let mut out = Vec::new();
    // a pixel can start a border only where it is non-zero and its left or
    // right neighbour is zero; following a border turns 1 into ±2 and never
    // changes which labels are zero, so candidates found ahead stay valid
    let mut visit = |f: &mut [i8], i: usize| {
        let v = f.get(i).copied().unwrap_or(0);
        let (left, right) = (
            f.get(i - 1).copied().unwrap_or(0),
            f.get(i + 1).copied().unwrap_or(0),
        );
        // outer border start: 1 with background on the left;
        // hole border start: ≥ 1 with background on the right
        let from = if v == 1 && left == 0 {
            Some((4usize, false))
        } else if v >= 1 && right == 0 {
            Some((0usize, true))
        } else {
            None
        };
        if let Some((d2, hole)) = from {
            let points = follow(f, &offs, pw, i, d2);
            out.push(Contour { points, hole });
        }
    };
    for r in 1..=h {
        let row0 = r * pw;
        let mut c = 1;
        while c <= w {
            // 16 columns at once where they fit before the right frame
            #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
            if c + 16 <= w + 1 {
                let mut mask = candidates16(&f, row0 + c);
                while mask != 0 {
                    visit(&mut f, row0 + c + mask.trailing_zeros() as usize);
                    mask &= mask - 1;
                }
                c += 16;
                continue;
            }
            if f.get(row0 + c).is_some_and(|&v| v != 0) {
                visit(&mut f, row0 + c);
            }
            c += 1;
        }
    }
    Ok(out)
}

/// Bit `k` set where label `i + k` (`k < 16`) is non-zero with a zero
/// left or right neighbour.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn candidates16(f: &[i8], i: usize) -> u32 {
    use core::arch::wasm32::*;
    if i == 0 || i + 17 > f.len() {
        // not reached (the scan calls it inside the frame): all candidates
        return 0xFFFF;
    }
    // SAFETY: 1 ≤ i and i + 17 ≤ f.len(), so the three 16-byte reads from
    // i − 1, i and i + 1 are in bounds.
    let (l, v, r) = unsafe {
        let p = f.as_ptr().add(i);
        (
            v128_load(p.sub(1) as *const v128),
            v128_load(p as *const v128),
            v128_load(p.add(1) as *const v128),
        )
    };
    let z = i8x16_splat(0);
    let edge = v128_or(i8x16_eq(l, z), i8x16_eq(r, z));
    u32::from(i8x16_bitmask(v128_andnot(edge, i8x16_eq(v, z))))
}

/// Follows the border through label index `start`, whose background
/// neighbour is in direction `d2`; marks it; returns its pixels.
fn follow(f: &mut [i8], offs: &[isize; 8], pw: usize, start: usize, d2: usize) -> Vec<(u32, u32)> {
    const NBD: i8 = 2;
    let at = |i: usize, k: usize| i.wrapping_add_signed(offs[k & 7]);
    let xy = |i: usize| (((i % pw) - 1) as u32, ((i / pw) - 1) as u32);
    // the point's image coordinates, stepped with each move (no division)
    let step = |(c, r): (u32, u32), k: usize| {
        let (dr, dc) = DIRS[k & 7];
        (
            c.wrapping_add_signed(dc as i32),
            r.wrapping_add_signed(dr as i32),
        )
    };
    let get = |f: &[i8], i: usize| f.get(i).copied().unwrap_or(0);
    // 3.1: clockwise from d2, the first non-zero neighbour
    let Some(k1) = (0..8)
        .map(|s| (d2 + 8 - s) & 7)
        .find(|&k| get(f, at(start, k)) != 0)
    else {
        if let Some(v) = f.get_mut(start) {
            *v = -NBD;
        }
        return vec![xy(start)];
    };
    let i1 = at(start, k1);
    let mut points = Vec::new();
    let (mut i3, mut back) = (start, k1); // back: direction from i3 to i2
    let mut p3 = xy(start);
    loop {
        points.push(p3);
        // 3.3: counter-clockwise from the one after i2, the first non-zero
        let mut east_zero = false;
        let mut k4 = back;
        for s in 1..=8 {
            let k = (back + s) & 7;
            if get(f, at(i3, k)) != 0 {
                k4 = k;
                break;
            }
            if k == 0 {
                east_zero = true;
            }
        }
        // 3.4
        if let Some(v) = f.get_mut(i3) {
            if east_zero {
                *v = -NBD;
            } else if *v == 1 {
                *v = NBD;
            }
        }
        let i4 = at(i3, k4);
        // 3.5
        if i4 == start && i3 == i1 {
            break;
        }
        back = (k4 + 4) & 7;
        i3 = i4;
        p3 = step(p3, k4);
        if points.len() > 8 * f.len() {
            break; // cannot happen: each (pixel, direction) state once
        }
    }
    points
}
