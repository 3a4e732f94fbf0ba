//! The live threshold on a colour photo's levels (issue 31, item 3): the
//! kept map suppresses once for every `T` (its maxima with approximate
//! `λmax(Σuv)`, the shown points' exact ones found from the reference's
//! window), so a threshold moved up past twice the first one does not redo
//! it. Its points for thresholds moved up and down are the reference's.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use photogrammetry_lab::decode::luma;
use photogrammetry_lab::ops::{self, Image};
use photogrammetry_playground::raster::Grid;
use std::cell::OnceCell;

/// A colour photo's greys (`decode::luma`) of smooth blobs plus noise:
/// SplitMix64 numbers, channels `0..=255`.
fn photo(w: usize, h: usize, seed: u64) -> Grid {
    let mut s = seed;
    let mut next = move |n: u64| {
        s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = s;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) % n) as f64
    };
    let data = (0..w * h)
        .map(|i| {
            let (x, y) = ((i % w) as f64, (i / w) as f64);
            let base = 100.0 + 60.0 * (x / 23.0).sin() * (y / 17.0).cos();
            let ch = |n: f64| (base + n).clamp(0.0, 255.0).round();
            luma(ch(next(9)), ch(next(9)), ch(next(9)))
        })
        .collect();
    Grid::new("image", w, h, data).unwrap()
}

#[test]
fn kept_points_for_thresholds_up_and_down_are_the_references() {
    for (seed, size) in [(3, 5), (11, 4), (5, 7)] {
        let g = photo(97, 71, seed);
        let keep = OnceCell::from(ops::levels_of(g.data()));
        assert!(keep.get().unwrap().is_some(), "the photo has levels");
        let img = || Image::with_bytes(&g, None).with_levels(&keep);
        let mut kept = ops::ForstnerKept::new(img(), size).unwrap();
        let own = kept.auto_threshold(8.0).map_or(0.5, |a| a.threshold_px);
        let mut found = 0;
        for q_min in [0.5, 0.0] {
            for t in [0.5 * own, own, 5.0 * own, 0.2 * own, 20.0 * own, own] {
                let got = kept.points(8.0, t, q_min).unwrap();
                let (_, want) = ops::forstner_reference(&g, size, 8.0, t, q_min).unwrap();
                assert_eq!(
                    got, want,
                    "seed {seed}, {size}×{size}, T {t}, q_min {q_min}"
                );
                found += got.len();
            }
        }
        assert!(found > 0, "seed {seed}: no points at all");
    }
}

/// Times of the kept map's steps on a 12 MP colour photo (`cargo test
/// --release -p photogrammetry-lab --test threshold -- --ignored --nocapture`).
#[test]
#[ignore]
fn profile_12_mp() {
    let g = photo(4000, 3000, 7);
    let keep = OnceCell::from(ops::levels_of(g.data()));
    let t = std::time::Instant::now();
    let mut kept =
        ops::ForstnerKept::new(Image::with_bytes(&g, None).with_levels(&keep), 5).unwrap();
    println!("map {:?}", t.elapsed());
    let t = std::time::Instant::now();
    let auto = kept.auto_threshold(8.0);
    println!(
        "auto {:?} {:?}",
        t.elapsed(),
        auto.as_ref().map(|a| a.threshold_px)
    );
    let at = auto.map_or(0.5, |a| a.threshold_px);
    for tp in [at, 0.3, 0.8, 0.5, 0.3, 1.2, 3.0] {
        let t = std::time::Instant::now();
        let n = kept.points(8.0, tp, 0.5).unwrap().len();
        println!("points T={tp:.3}: {:?} ({n} numbers)", t.elapsed());
    }
}
