//! The generated scanned frame photo: a terrain-like scene inside a dark
//! frame carrying Example 4's four fiducial marks, scanned at a known
//! resolution with a known affine distortion, so that a student who measures
//! the marks and fits Example 4's transformations can check the fit against
//! the truth.
//!
//! The truth is Example 4's affine form, pixel → photo (mm), with
//! `x′ = c`, `y′ = −r`: `x = a·x′ + b·y′ + e`, `y = c·x′ + d·y′ + f`
//! ([`TRUE_AFFINE`], in the order `[a, b, e, c, d, f]` of
//! `transform::Model::FiducialAffine`). The fiducials' calibrated positions
//! are Example 4's; their pixel positions follow from the inverse.

use photogrammetry_playground::error::{Error, Result};
use photogrammetry_playground::examples::transformations::FIDUCIALS;
use photogrammetry_playground::raster::Grid;

/// Side of the generated scan (pixels).
pub const SIDE: usize = 1000;
/// Nominal pixel size of the scan (mm): 101.6 dpi.
pub const PIXEL_MM: f64 = 0.25;
/// Radius of the bright disc of a fiducial mark (pixels).
const MARK_RADIUS: f64 = 5.0;
/// Grey value of the frame around the picture.
const FRAME_GREY: f64 = 30.0;
/// Grey value of a mark.
const MARK_GREY: f64 = 225.0;
/// Standard deviation of the scan noise (grey values).
pub const NOISE: f64 = 1.5;
/// Half the side of the terrain picture (mm).
const PICTURE_HALF_MM: f64 = 100.0;

/// The true pixel → photo affine `[a, b, e, c, d, f]` (mm, with `x′ = c`,
/// `y′ = −r`): about 0.25 mm a pixel, the two axes scaled 0.2 % apart, a
/// slight shear and rotation, the principal point 0.12 mm right and 0.08 mm
/// up of the scan's centre.
pub const TRUE_AFFINE: [f64; 6] = [
    0.2502,
    0.0004,
    0.12 - 0.2502 * 499.5 - 0.0004 * -499.5,
    -0.0003,
    0.2497,
    0.08 + 0.0003 * 499.5 - 0.2497 * -499.5,
];

/// The calibrated fiducial positions `[x, y]` (mm), Example 4's.
pub fn calibrated() -> [[f64; 2]; 4] {
    FIDUCIALS.map(|f| [f[2], f[3]])
}

/// Pixel `(c, r)` of photo position `(x, y)` under [`TRUE_AFFINE`].
pub fn pixel_of(x: f64, y: f64) -> (f64, f64) {
    let [a, b, e, c, d, f] = TRUE_AFFINE;
    // [a b; c d]·[x′; y′] = [x − e; y − f]
    let det = a * d - b * c;
    let (px, py) = (x - e, y - f);
    let xp = (d * px - b * py) / det;
    let yp = (a * py - c * px) / det;
    (xp, -yp)
}

/// The true pixel positions `(c, r)` of the four fiducials.
pub fn true_marks() -> [(f64, f64); 4] {
    calibrated().map(|[x, y]| pixel_of(x, y))
}

/// Where a student would look for each mark: the calibrated position at
/// the nominal pixel size about the scan's centre (a few pixels off the
/// truth).
pub fn nominal_marks() -> [(f64, f64); 4] {
    let m = (SIDE as f64 - 1.0) / 2.0;
    calibrated().map(|[x, y]| (m + x / PIXEL_MM, m - y / PIXEL_MM))
}

/// How much of a pixel at distance `d` from a mark's centre is mark: a disc
/// of [`MARK_RADIUS`] with a one-pixel soft edge, so that the centre can be
/// measured to a fraction of a pixel.
fn coverage(d: f64) -> f64 {
    (MARK_RADIUS + 0.5 - d).clamp(0.0, 1.0)
}

/// A fiducial mark drawn at `(mc, mr)` on a flat frame: the grey value at
/// pixel `(c, r)`.
pub fn mark_value(c: f64, r: f64, mc: f64, mr: f64) -> f64 {
    let d = (c - mc).hypot(r - mr);
    let disc = coverage(d);
    // a thin cross through the disc's centre (half-width 0.75 px, 12 px arms)
    let arm = |along: f64, across: f64| {
        if along.abs() <= 12.0 {
            (1.25 - across.abs()).clamp(0.0, 1.0)
        } else {
            0.0
        }
    };
    let cross = arm(c - mc, r - mr).max(arm(r - mr, c - mc));
    FRAME_GREY + (MARK_GREY - FRAME_GREY) * disc.max(cross * 0.8)
}

/// A `size × size` template of a mark at its centre (odd `size`).
pub fn mark_template(size: usize) -> Result<Grid> {
    if size < 5 || size.is_multiple_of(2) || size > 63 {
        return Err(Error::input(
            "template_size",
            format!("must be odd and between 5 and 63 (got {size})"),
        ));
    }
    let m = (size as f64 - 1.0) / 2.0;
    Ok(Grid::from_fn(size, size, |c, r| {
        mark_value(c as f64, r as f64, m, m)
    }))
}

fn hash(c: usize, r: usize, seed: u64) -> f64 {
    let mut z = (c as u64)
        .wrapping_mul(0x9E37_79B9_7F4A_7C15)
        .wrapping_add((r as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F))
        .wrapping_add(seed);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    (z >> 11) as f64 / (1u64 << 53) as f64
}

/// The terrain: rolling hills, fields (a few sharp-edged blocks) and a road.
fn terrain(x: f64, y: f64) -> f64 {
    let hills = 40.0 * (x / 23.0).sin() * (y / 31.0).cos() + 25.0 * ((x + 2.0 * y) / 17.0).sin();
    let field = if ((x / 30.0).floor() + (y / 24.0).floor()).rem_euclid(3.0) == 0.0 {
        30.0
    } else {
        0.0
    };
    let road = if (y - 0.4 * x - 10.0).abs() < 2.0 {
        60.0
    } else {
        0.0
    };
    (120.0 + hills + field + road).clamp(0.0, 255.0)
}

/// The generated scan: [`SIDE`] × [`SIDE`] grey values 0 … 255.
pub fn scanned_frame() -> Grid {
    let [a, b, e, c6, d, f] = TRUE_AFFINE;
    let marks = true_marks();
    Grid::from_fn(SIDE, SIDE, |c, r| {
        let (cf, rf) = (c as f64, r as f64);
        let x = a * cf - b * rf + e;
        let y = c6 * cf - d * rf + f;
        let base = if x.abs() < PICTURE_HALF_MM && y.abs() < PICTURE_HALF_MM {
            terrain(x, y)
        } else {
            marks
                .iter()
                .map(|&(mc, mr)| mark_value(cf, rf, mc, mr))
                .fold(FRAME_GREY, f64::max)
        };
        // uniform noise of standard deviation NOISE
        let n = (hash(c, r, 7) - 0.5) * NOISE * 12f64.sqrt();
        (base + n).clamp(0.0, 255.0)
    })
}
