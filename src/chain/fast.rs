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
    for r in 1..=h {
        let row0 = r * pw;
        for c in 1..=w {
            let i = row0 + c;
            let v = f[i];
            if v == 0 {
                continue;
            }
            // outer border start: 1 with background on the left;
            // hole border start: ≥ 1 with background on the right
            let from = if v == 1 && f[i - 1] == 0 {
                Some((4usize, false))
            } else if v >= 1 && f[i + 1] == 0 {
                Some((0usize, true))
            } else {
                None
            };
            if let Some((d2, hole)) = from {
                let points = follow(&mut f, &offs, pw, i, d2);
                out.push(Contour { points, hole });
            }
        }
    }
    Ok(out)
}

/// Follows the border through label index `start`, whose background
/// neighbour is in direction `d2`; marks it; returns its pixels.
fn follow(f: &mut [i8], offs: &[isize; 8], pw: usize, start: usize, d2: usize) -> Vec<(u32, u32)> {
    const NBD: i8 = 2;
    let at = |i: usize, k: usize| i.wrapping_add_signed(offs[k & 7]);
    let xy = |i: usize| (((i % pw) - 1) as u32, ((i / pw) - 1) as u32);
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
    loop {
        points.push(xy(i3));
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
        if points.len() > 8 * f.len() {
            break; // cannot happen: each (pixel, direction) state once
        }
    }
    points
}
