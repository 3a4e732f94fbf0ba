//! Helpers the lab's integration tests share (each test file: `mod common;`).

use photogrammetry_playground::raster::Grid;

/// A random image, SplitMix64 grey values 0 … 255.
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
