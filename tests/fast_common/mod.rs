//! Shared by the fast-path tests: a seeded PRNG for random images, the
//! sizes every fast path is tried on, and the float tolerance.
#![allow(dead_code)]

/// 1×1 up to 257×131, odd and even, thin and square.
pub const SIZES: [(usize, usize); 12] = [
    (1, 1),
    (1, 7),
    (7, 1),
    (2, 2),
    (3, 5),
    (5, 3),
    (16, 3),
    (17, 17),
    (33, 2),
    (31, 40),
    (64, 9),
    (257, 131),
];

/// splitmix64: the same stream on every platform.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in `0 .. n`.
    pub fn below(&mut self, n: u64) -> u64 {
        self.next() % n.max(1)
    }
}

/// A random 8-bit image: noise plus a few flat blocks (flat windows and
/// ties happen).
pub fn random_image(w: usize, h: usize, seed: u64) -> Vec<u8> {
    let mut rng = Rng(seed.wrapping_mul(7919).wrapping_add(17));
    let mut v: Vec<u8> = (0..w * h).map(|_| rng.below(256) as u8).collect();
    for _ in 0..3 {
        let (bw, bh) = (rng.below(8) as usize + 1, rng.below(8) as usize + 1);
        let (c0, r0) = (rng.below(w as u64) as usize, rng.below(h as u64) as usize);
        let val = rng.below(256) as u8;
        for r in r0..(r0 + bh).min(h) {
            for c in c0..(c0 + bw).min(w) {
                v[r * w + c] = val;
            }
        }
    }
    v
}

/// Within 1e-4 of the reference, relative to its size (or to 1 below 1).
pub fn close(got: f32, want: f64) -> bool {
    (f64::from(got) - want).abs() <= 1e-4 * want.abs().max(1.0)
}
