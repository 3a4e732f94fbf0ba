//! Freeman chain codes on a pixel grid, the differential chain code, boundary
//! tracing of a binary image, and the simple boundary descriptors of seed 000
//! (length, diameter, major and minor axis, basic rectangle, eccentricity).
//!
//! Pixels are `[c, r]`: column to the right, row downward. Directions are
//! numbered as in the seed's figure, from 1 = east counted counter-clockwise
//! as seen on the screen (so 3 = north is `r − 1`):
//!
//! ```text
//! 8-connectivity      4-connectivity
//!   4 3 2                  2
//!   5 · 1                3 · 1
//!   6 7 8                  4
//! ```
//!
//! The 4-connectivity numbering (1 = east, 2 = north, 3 = west, 4 = south)
//! is an assumption: the seed's figure a is lost; this is the numbering that
//! follows the same rule as its 8-connectivity figure.

use crate::error::{Error, Result};
use crate::raster::Grid;
use std::collections::HashMap;

pub mod fast;

/// A pixel `[c, r]`.
pub type Pixel = [i64; 2];

/// Which neighbours count as connected, and so which directions a chain code
/// has.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Connectivity {
    /// Left, up, right, down: 4 directions, digits 1–4.
    Four,
    /// Also the diagonals: 8 directions, digits 1–8.
    Eight,
}

/// Steps `(Δc, Δr)` of directions 1…8 (index 0 is direction 1).
const STEPS8: [(i64, i64); 8] = [
    (1, 0),
    (1, -1),
    (0, -1),
    (-1, -1),
    (-1, 0),
    (-1, 1),
    (0, 1),
    (1, 1),
];
/// Steps `(Δc, Δr)` of directions 1…4.
const STEPS4: [(i64, i64); 4] = [(1, 0), (0, -1), (-1, 0), (0, 1)];

impl Connectivity {
    /// The number of directions, 4 or 8.
    pub fn directions(self) -> u8 {
        match self {
            Connectivity::Four => 4,
            Connectivity::Eight => 8,
        }
    }

    fn steps(self) -> &'static [(i64, i64)] {
        match self {
            Connectivity::Four => &STEPS4,
            Connectivity::Eight => &STEPS8,
        }
    }

    /// The step `(Δc, Δr)` of direction `digit` (1-based), if it is one.
    pub fn step(self, digit: u8) -> Option<(i64, i64)> {
        let i = usize::from(digit).checked_sub(1)?;
        self.steps().get(i).copied()
    }

    /// The direction digit of the step `(Δc, Δr)`, if it is a step between
    /// neighbours under this connectivity.
    pub fn digit(self, dc: i64, dr: i64) -> Option<u8> {
        let i = self.steps().iter().position(|&s| s == (dc, dr))?;
        u8::try_from(i + 1).ok()
    }

    /// The direction digit of the step from `a` to `b`, if they are
    /// distinct neighbours.
    pub fn between(self, a: Pixel, b: Pixel) -> Option<u8> {
        self.digit(b[0].checked_sub(a[0])?, b[1].checked_sub(a[1])?)
    }

    /// `digit + k` on the circle of directions (`k` may be negative).
    pub fn turn(self, digit: u8, k: i64) -> u8 {
        let n = i64::from(self.directions());
        let d = (i64::from(digit) - 1 + k).rem_euclid(n) + 1;
        d as u8
    }
}

/// Where an ordered pixel path breaks: pixels `index` and `index + 1`
/// (0-based) are not neighbours.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Gap {
    pub index: usize,
    pub from: Pixel,
    pub to: Pixel,
}

/// A pixel the path visits a second time: at `index`, first at `first`
/// (0-based). The pixels then do not form a simple edge: the path branches
/// (or crosses itself) there.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Revisit {
    pub index: usize,
    pub first: usize,
    pub pixel: Pixel,
}

/// An ordered pixel path, checked and coded.
#[derive(Debug, Clone, PartialEq)]
pub struct Path {
    /// The pixels in order; for a closed boundary without the repeated start.
    pub pixels: Vec<Pixel>,
    /// True when the given path ended on its first pixel again.
    pub closed: bool,
    /// The chain code, one digit per step (a closed boundary has as many
    /// steps as pixels); `None` when the path breaks somewhere.
    pub code: Option<Vec<u8>>,
    /// Every place where consecutive pixels are not neighbours.
    pub gaps: Vec<Gap>,
    /// Every pixel visited twice (other than the closing return to the start).
    pub revisits: Vec<Revisit>,
}

/// Checks and codes an ordered pixel path. A path whose last pixel repeats
/// its first
/// is a closed boundary (at least 3 entries); the repeat is dropped from
/// [`Path::pixels`] and the closing step is the last code digit.
pub fn analyse(pixels: &[Pixel], conn: Connectivity) -> Path {
    let closed = pixels.len() >= 3 && pixels.first() == pixels.last();
    let body: &[Pixel] = if closed {
        &pixels[..pixels.len() - 1]
    } else {
        pixels
    };
    let mut gaps = Vec::new();
    let mut code = Vec::with_capacity(pixels.len());
    for (i, w) in pixels.windows(2).enumerate() {
        let (a, b) = (w[0], w[1]);
        match conn.between(a, b) {
            Some(d) => code.push(d),
            None => gaps.push(Gap {
                index: i,
                from: a,
                to: b,
            }),
        }
    }
    let mut revisits = Vec::new();
    let mut seen: HashMap<Pixel, usize> = HashMap::with_capacity(body.len());
    for (i, &p) in body.iter().enumerate() {
        match seen.get(&p) {
            Some(&first) => revisits.push(Revisit {
                index: i,
                first,
                pixel: p,
            }),
            None => {
                seen.insert(p, i);
            }
        }
    }
    Path {
        pixels: body.to_vec(),
        closed,
        code: gaps.is_empty().then_some(code),
        gaps,
        revisits,
    }
}

/// The chain code of an ordered path of neighbouring pixels, or the first
/// place where it breaks.
pub fn encode(pixels: &[Pixel], conn: Connectivity) -> std::result::Result<Vec<u8>, Gap> {
    let mut code = Vec::with_capacity(pixels.len());
    for (i, w) in pixels.windows(2).enumerate() {
        match conn.between(w[0], w[1]) {
            Some(d) => code.push(d),
            None => {
                return Err(Gap {
                    index: i,
                    from: w[0],
                    to: w[1],
                })
            }
        }
    }
    Ok(code)
}

/// The pixels a chain code walks from `start` (the start included, so one
/// more pixel than digits). A digit that is no direction is an error of
/// field `code`.
pub fn decode(start: Pixel, code: &[u8], conn: Connectivity) -> Result<Vec<Pixel>> {
    let mut out = Vec::with_capacity(code.len() + 1);
    let mut p = start;
    out.push(p);
    for (i, &d) in code.iter().enumerate() {
        let (dc, dr) = conn.step(d).ok_or_else(|| {
            Error::input(
                "code",
                format!(
                    "digit {} is {d}; with {}-connectivity the directions are 1 to {}",
                    i + 1,
                    conn.directions(),
                    conn.directions()
                ),
            )
        })?;
        p = match (p[0].checked_add(dc), p[1].checked_add(dr)) {
            (Some(c), Some(r)) => [c, r],
            _ => return Err(Error::input("code", "walks out of the coordinate range")),
        };
        out.push(p);
    }
    Ok(out)
}

/// The code of the same edge walked the other way: the digits in reverse
/// order, each turned by half a circle.
pub fn reverse(code: &[u8], conn: Connectivity) -> Vec<u8> {
    let half = i64::from(conn.directions() / 2);
    code.iter().rev().map(|&d| conn.turn(d, half)).collect()
}

/// The differential chain code and the plain differences it comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Differential {
    /// `a[k+1] − a[k]` as computed (may be negative); for a closed boundary
    /// the first is `a[1] − a[n]`.
    pub differences: Vec<i64>,
    /// The differences taken modulo the number of directions (0 ≤ d < n):
    /// counter-clockwise turns in steps of 45° (or 90°).
    pub code: Vec<u8>,
}

/// The differential chain code as the seed computes it: each digit minus the
/// one before, negative values plus the number of directions. An open edge
/// of `n` digits gives `n − 1`; a closed boundary gives `n`, its first
/// element the first digit minus the last.
pub fn differential(code: &[u8], conn: Connectivity, closed: bool) -> Differential {
    let n = i64::from(conn.directions());
    let mut differences = Vec::with_capacity(code.len());
    if closed {
        if let (Some(&first), Some(&last)) = (code.first(), code.last()) {
            differences.push(i64::from(first) - i64::from(last));
        }
    }
    differences.extend(code.windows(2).map(|w| i64::from(w[1]) - i64::from(w[0])));
    let code = differences.iter().map(|d| d.rem_euclid(n) as u8).collect();
    Differential { differences, code }
}

/// The length of a coded path: axial steps count 1, diagonal ones √2.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Length {
    /// Steps to the left or right.
    pub horizontal: usize,
    /// Steps up or down.
    pub vertical: usize,
    /// Diagonal steps (8-connectivity only).
    pub diagonal: usize,
    /// `horizontal + vertical + √2 · diagonal`.
    pub length: f64,
}

/// The length of the path a chain code walks. For a 4-connected open edge
/// this is the number of pixels minus 1, as the seed says.
pub fn length(code: &[u8], conn: Connectivity) -> Length {
    let (mut horizontal, mut vertical, mut diagonal) = (0, 0, 0);
    for &d in code {
        match conn.step(d) {
            Some((_, 0)) => horizontal += 1,
            Some((0, _)) => vertical += 1,
            Some(_) => diagonal += 1,
            None => {}
        }
    }
    Length {
        horizontal,
        vertical,
        diagonal,
        length: (horizontal + vertical) as f64 + std::f64::consts::SQRT_2 * diagonal as f64,
    }
}

/// The outer boundary of one region of a binary image.
#[derive(Debug, Clone, PartialEq)]
pub struct Boundary {
    /// The boundary pixels in tracing order (clockwise on the screen),
    /// starting at the region's top-most, left-most pixel; a pixel of a
    /// one-pixel-wide part appears once for each pass.
    pub pixels: Vec<Pixel>,
    /// The closed chain code: `code[k]` leads from `pixels[k]` to
    /// `pixels[k+1]`, the last digit back to the start. Empty for a region
    /// of a single pixel.
    pub code: Vec<u8>,
    /// The number of pixels of the region.
    pub area: usize,
}

fn is_set(image: &Grid, p: Pixel) -> bool {
    match (usize::try_from(p[0]), usize::try_from(p[1])) {
        (Ok(c), Ok(r)) => image.get(c, r).is_some_and(|v| v != 0.0),
        _ => false,
    }
}

/// The outer boundary of every region (connected set of non-zero pixels
/// under `conn`) of a binary image, regions in the order of their top-most,
/// left-most pixel (row by row). Each boundary is traced clockwise as seen on
/// the screen (the region on the right of each step) by following its outer
/// side, Moore's neighbour tracing for 8-connectivity; it stops when the
/// start pixel is left again in the first direction (Jacob's criterion), so
/// one-pixel-wide parts are walked out and back.
pub fn trace(image: &Grid, conn: Connectivity) -> Vec<Boundary> {
    let (w, h) = (image.width(), image.height());
    let mut label = vec![false; w * h];
    let mut out = Vec::new();
    for r in 0..h {
        for c in 0..w {
            let start = [c as i64, r as i64];
            if label[r * w + c] || !is_set(image, start) {
                continue;
            }
            let area = flood(image, conn, start, &mut label);
            out.push(trace_one(image, conn, start, area));
        }
    }
    out
}

/// Marks the region of `start` in `label`; returns its size.
fn flood(image: &Grid, conn: Connectivity, start: Pixel, label: &mut [bool]) -> usize {
    let w = image.width();
    let index = |p: Pixel| (p[1] as usize) * w + p[0] as usize;
    let mut stack = vec![start];
    let mut area = 0;
    if let Some(l) = label.get_mut(index(start)) {
        *l = true;
    }
    while let Some(p) = stack.pop() {
        area += 1;
        for &(dc, dr) in conn.steps() {
            let q = [p[0] + dc, p[1] + dr];
            if is_set(image, q) {
                if let Some(l) = label.get_mut(index(q)) {
                    if !*l {
                        *l = true;
                        stack.push(q);
                    }
                }
            }
        }
    }
    area
}

/// Follows the outer side of the region whose top-most, left-most pixel is
/// `start`.
fn trace_one(image: &Grid, conn: Connectivity, start: Pixel, area: usize) -> Boundary {
    let n = i64::from(conn.directions());
    // The direction tried first after arriving in direction `d` (0-based):
    // the first neighbour clockwise after the known background one.
    let first_try = |d: i64| -> i64 {
        match conn {
            Connectivity::Four => d + 1,
            Connectivity::Eight => d + 2 + (d % 2),
        }
    };
    // Next step from `p` having arrived in direction `d`: the first region
    // pixel scanning clockwise (decreasing direction numbers).
    let next = |p: Pixel, d: i64| -> Option<i64> {
        let s = first_try(d);
        (0..n).map(|k| (s - k).rem_euclid(n)).find(|&k| {
            conn.step(k as u8 + 1)
                .is_some_and(|(dc, dr)| is_set(image, [p[0] + dc, p[1] + dr]))
        })
    };
    // Arrive "from below going north": the first neighbour tried is west,
    // which is background for the top-most, left-most pixel.
    let arrive = match conn {
        Connectivity::Four => 1,
        Connectivity::Eight => 2,
    };
    let mut pixels = vec![start];
    let mut code = Vec::new();
    let Some(d0) = next(start, arrive) else {
        return Boundary { pixels, code, area };
    };
    let (mut p, mut d) = (start, d0);
    // Every (pixel, direction) state is visited at most once, so the walk
    // ends within 4·n·area steps; the bound only guards against a bug.
    let limit = 4 * conn.directions() as usize * area.max(1) + 8;
    for _ in 0..limit {
        let Some((dc, dr)) = conn.step(d as u8 + 1) else {
            break;
        };
        code.push(d as u8 + 1);
        p = [p[0] + dc, p[1] + dr];
        let Some(nd) = next(p, d) else {
            break;
        };
        if p == start && nd == d0 {
            break;
        }
        pixels.push(p);
        d = nd;
    }
    Boundary { pixels, code, area }
}

/// A binary image of a pixel set, with one background pixel around it, and
/// the position of its top-left corner: image pixel `(i, j)` is pixel
/// `[c0 + i, r0 + j]`. `field` names the input in errors; at most
/// `max_side` columns and rows.
pub fn image_of(field: &str, pixels: &[Pixel], max_side: usize) -> Result<(Grid, Pixel)> {
    let Some(first) = pixels.first() else {
        return Err(Error::input(field, "is empty: give at least one pixel"));
    };
    let (mut lo, mut hi) = (*first, *first);
    for p in pixels {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let span = |k: usize| {
        let s = i128::from(hi[k]) - i128::from(lo[k]) + 1;
        usize::try_from(s).unwrap_or(usize::MAX)
    };
    if span(0) > max_side || span(1) > max_side {
        return Err(Error::input(
            field,
            format!(
                "the pixels span {} columns × {} rows; at most {max_side} × {max_side} can be traced",
                span(0),
                span(1)
            ),
        ));
    }
    let (Some(c0), Some(r0)) = (lo[0].checked_sub(1), lo[1].checked_sub(1)) else {
        return Err(Error::input(
            field,
            "a pixel lies at the edge of the coordinate range",
        ));
    };
    let origin = [c0, r0];
    let (w, h) = (span(0) + 2, span(1) + 2);
    let mut g = Grid::filled(w, h, 0.0);
    for p in pixels {
        g.set(
            (p[0] - origin[0]) as usize,
            (p[1] - origin[1]) as usize,
            1.0,
        );
    }
    Ok((g, origin))
}

/// The outer boundary of every region of a set of pixels, in image
/// coordinates (see [`trace`] and [`image_of`]).
pub fn trace_pixels(
    field: &str,
    pixels: &[Pixel],
    conn: Connectivity,
    max_side: usize,
) -> Result<Vec<Boundary>> {
    let (g, origin) = image_of(field, pixels, max_side)?;
    let mut out = trace(&g, conn);
    for b in &mut out {
        for p in &mut b.pixels {
            *p = [p[0] + origin[0], p[1] + origin[1]];
        }
    }
    Ok(out)
}

/// The simple descriptors of a boundary, measured between pixel centres.
#[derive(Debug, Clone, PartialEq)]
pub struct Shape {
    /// The largest distance between two boundary pixels.
    pub diameter: f64,
    /// The two farthest pixels (the first such pair in boundary order).
    pub major_axis: [Pixel; 2],
    /// Unit vector along the major axis, from its first end to its second
    /// (`[1, 0]` when the boundary is a single pixel).
    pub axis_direction: [f64; 2],
    /// The extent of the boundary across the major axis.
    pub minor_axis_length: f64,
    /// The minor axis: perpendicular to the major one, through the centre of
    /// the basic rectangle, as long as the rectangle is wide.
    pub minor_axis: [[f64; 2]; 2],
    /// The corners of the basic rectangle (sides along and across the major
    /// axis, just enclosing the boundary), in order around it.
    pub basic_rectangle: [[f64; 2]; 4],
    /// Major over minor axis; `None` when the minor axis has length 0 (all
    /// pixels on one straight line).
    pub eccentricity: Option<f64>,
    /// Lowest and highest offset across the major axis (along the
    /// perpendicular `[−u_r, u_c]`), from the first end of the major axis.
    pub across: [f64; 2],
}

/// Diameter, major and minor axis, basic rectangle and eccentricity of a
/// boundary as seed 000 defines them. Distances are exact integer
/// comparisons (squared), so ties are decided by boundary order.
pub fn shape(field: &str, boundary: &[Pixel]) -> Result<Shape> {
    let Some(&first) = boundary.first() else {
        return Err(Error::input(field, "is empty: give at least one pixel"));
    };
    let mut best = (0i128, first, first);
    for (i, &a) in boundary.iter().enumerate() {
        for &b in boundary.iter().skip(i + 1) {
            let dc = i128::from(b[0]) - i128::from(a[0]);
            let dr = i128::from(b[1]) - i128::from(a[1]);
            let d2 = dc * dc + dr * dr;
            if d2 > best.0 {
                best = (d2, a, b);
            }
        }
    }
    let (d2, a, b) = best;
    let diameter = (d2 as f64).sqrt();
    let u = if d2 > 0 {
        [
            (b[0] - a[0]) as f64 / diameter,
            (b[1] - a[1]) as f64 / diameter,
        ]
    } else {
        [1.0, 0.0]
    };
    let v = [-u[1], u[0]];
    let (mut s_lo, mut s_hi, mut t_lo, mut t_hi) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for p in boundary {
        let (x, y) = ((p[0] - a[0]) as f64, (p[1] - a[1]) as f64);
        let s = x * u[0] + y * u[1];
        let t = x * v[0] + y * v[1];
        s_lo = s_lo.min(s);
        s_hi = s_hi.max(s);
        t_lo = t_lo.min(t);
        t_hi = t_hi.max(t);
    }
    let at = |s: f64, t: f64| {
        [
            a[0] as f64 + s * u[0] + t * v[0],
            a[1] as f64 + s * u[1] + t * v[1],
        ]
    };
    let minor = t_hi - t_lo;
    let mid = (s_lo + s_hi) / 2.0;
    Ok(Shape {
        diameter,
        major_axis: [a, b],
        axis_direction: u,
        minor_axis_length: minor,
        minor_axis: [at(mid, t_lo), at(mid, t_hi)],
        basic_rectangle: [
            at(s_lo, t_lo),
            at(s_hi, t_lo),
            at(s_hi, t_hi),
            at(s_lo, t_hi),
        ],
        eccentricity: (minor > 1e-9).then(|| diameter / minor),
        across: [t_lo, t_hi],
    })
}

/// The region of `image` that contains pixel `(c, r)`: the connected set
/// (under `conn`) of pixels on the same side of `threshold` as `(c, r)`
/// (`≥ threshold` or `< threshold`), as a binary grid (1 inside, 0 outside)
/// that [`trace`] turns into its boundary. `None` when `(c, r)` is outside.
pub fn region_at(
    image: &Grid,
    threshold: f64,
    c: usize,
    r: usize,
    conn: Connectivity,
) -> Option<Grid> {
    let (w, h) = (image.width(), image.height());
    let side = |v: f64| v >= threshold;
    let want = side(image.get(c, r)?);
    let mut mask = Grid::filled(w, h, 0.0);
    let mut stack = vec![(c, r)];
    mask.set(c, r, 1.0);
    let steps: &[(i64, i64)] = match conn {
        Connectivity::Four => &[(1, 0), (0, -1), (-1, 0), (0, 1)],
        Connectivity::Eight => &STEPS8,
    };
    while let Some((pc, pr)) = stack.pop() {
        for &(dc, dr) in steps {
            let (Ok(nc), Ok(nr)) = (
                usize::try_from(pc as i64 + dc),
                usize::try_from(pr as i64 + dr),
            ) else {
                continue;
            };
            match (image.get(nc, nr), mask.get(nc, nr)) {
                (Some(v), Some(m)) if m == 0.0 && side(v) == want => {
                    mask.set(nc, nr, 1.0);
                    stack.push((nc, nr));
                }
                _ => {}
            }
        }
    }
    Some(mask)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbering_is_counter_clockwise_from_east_with_r_down() {
        let c = Connectivity::Eight;
        assert_eq!(c.digit(1, 0), Some(1));
        assert_eq!(c.digit(0, -1), Some(3));
        assert_eq!(c.digit(1, 1), Some(8));
        assert_eq!(c.digit(2, 0), None);
        assert_eq!(Connectivity::Four.digit(0, 1), Some(4));
        assert_eq!(Connectivity::Four.digit(1, 1), None);
        assert_eq!(c.turn(7, 4), 3);
        assert_eq!(c.turn(1, -1), 8);
    }

    #[test]
    fn square_is_traced_clockwise_from_top_left() {
        let g = Grid::from_rows(
            "g",
            &[
                vec![0.0, 0.0, 0.0, 0.0],
                vec![0.0, 1.0, 1.0, 0.0],
                vec![0.0, 1.0, 1.0, 0.0],
                vec![0.0, 0.0, 0.0, 0.0],
            ],
        )
        .unwrap();
        let b = trace(&g, Connectivity::Eight);
        assert_eq!(b.len(), 1);
        assert_eq!(b[0].code, vec![1, 7, 5, 3]);
        assert_eq!(b[0].pixels, vec![[1, 1], [2, 1], [2, 2], [1, 2]]);
        let b = trace(&g, Connectivity::Four);
        assert_eq!(b[0].code, vec![1, 4, 3, 2]);
    }

    #[test]
    fn thin_line_is_walked_out_and_back() {
        let g = Grid::from_rows("g", &[vec![1.0, 1.0, 1.0]]).unwrap();
        let b = trace(&g, Connectivity::Eight);
        assert_eq!(b[0].code, vec![1, 1, 5, 5]);
        assert_eq!(b[0].pixels, vec![[0, 0], [1, 0], [2, 0], [1, 0]]);
    }
}
