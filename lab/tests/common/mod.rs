//! Helpers the lab's integration tests share (each test file: `mod common;`).

use photogrammetry_lab::ops::Traced;
use photogrammetry_playground::chain::{self, Connectivity};
use photogrammetry_playground::raster::Grid;

/// A random image, SplitMix64 grey values 0 … 255.
#[allow(dead_code)]
pub fn random(w: usize, h: usize, seed: u64) -> Grid {
    let mut s = seed;
    let data = (0..w * h)
        .map(|_| {
            s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = s;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) % 256) as f64
        })
        .collect();
    Grid::new("image", w, h, data).unwrap()
}

/// Checks a traced boundary `t` (the lab's `ops::boundary` at `(c, r)` for
/// `threshold` on `img`) against the reference (`chain::region_at`,
/// `chain::trace`, `chain::length`, 8-connected): its boundary and length
/// equal. Returns the reference's region (for the caller's layer check)
/// and the boundary's pixel count.
#[allow(dead_code)] // (each test file compiles this module; not every one traces)
pub fn boundary_is_the_reference(
    t: &Traced,
    img: &Grid,
    threshold: f64,
    c: usize,
    r: usize,
    what: &str,
) -> (Grid, usize) {
    let mask = chain::region_at(img, threshold, c, r, Connectivity::Eight).unwrap();
    let want = chain::trace(&mask, Connectivity::Eight).remove(0);
    assert_eq!(t.boundary, want, "{what}");
    assert_eq!(
        t.length,
        chain::length(&want.code, Connectivity::Eight),
        "{what}"
    );
    (mask, want.pixels.len())
}
