//! Every fast whole-image path against the core's plain reference function,
//! at every pixel: random 8-bit images from 1×1 to 257×131, every border
//! policy that applies. Integer outputs (median, boundaries) must be equal;
//! float outputs within 1e-4 relative (of the value, or of 1 for values
//! below 1).
//!
//! The same file runs natively (`cargo test`) and as wasm in Node
//! (`cargo test --target wasm32-unknown-unknown --test web_fast`), once
//! without and once with `-C target-feature=+simd128` (scripts/test.sh), so
//! the scalar and the SIMD loops are both tied to the reference.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

#[path = "fast_common/mod.rs"]
mod fast_common;
use fast_common::*;

use photogrammetry_playground::filter::{self, fast, Kernel};
use photogrammetry_playground::raster::{Border, Gray};

const BORDERS: [Border; 4] = [
    Border::Replicate,
    Border::Reflect,
    Border::Zero,
    Border::Crop,
];

/// Compares a full-image fast output with a reference `Filtered` (which
/// covers only the interior under `Crop`).
fn same_filtered(what: &str, fast: &[f32], w: usize, reference: &filter::Filtered) {
    let reg = reference.region;
    for r in reg.r0..reg.r0 + reg.height {
        for c in reg.c0..reg.c0 + reg.width {
            let want = reference.at_input(c, r).unwrap_or(f64::NAN);
            let got = fast[r * w + c];
            assert!(
                close(got, want),
                "{what}: pixel ({c}, {r}) of {w} wide: fast {got}, reference {want}"
            );
        }
    }
}

#[test]
fn mean3_and_gaussian5_equal_correlate() {
    let taps = fast::gaussian_taps(1.0, 2).unwrap_or_default();
    let k32: Vec<f32> = taps.iter().map(|&v| v as f32).collect();
    let outer: Vec<Vec<f64>> = taps
        .iter()
        .map(|a| taps.iter().map(|b| a * b).collect())
        .collect();
    let gauss = Kernel::new("k", &outer, 1.0).unwrap();
    for (k, &(w, h)) in SIZES.iter().enumerate() {
        let bytes = random_image(w, h, k as u64);
        let img = Gray::new("img", &bytes, w, h).unwrap();
        let grid = img.to_grid();
        for border in BORDERS {
            let mut out = vec![0.0f32; w * h];
            if let Ok(reference) = filter::correlate(&grid, &filter::mean3(), border) {
                fast::mean3(img, border, &mut out).unwrap();
                same_filtered(&format!("mean3 {w}×{h} {border:?}"), &out, w, &reference);
            }
            if let Ok(reference) = filter::correlate(&grid, &gauss, border) {
                fast::separable(img, &k32, &k32, 1.0, border, &mut out).unwrap();
                same_filtered(&format!("gauss5 {w}×{h} {border:?}"), &out, w, &reference);
            }
        }
    }
}

#[test]
fn sobel_equals_gradient() {
    for (k, &(w, h)) in SIZES.iter().enumerate() {
        let bytes = random_image(w, h, 100 + k as u64);
        let img = Gray::new("img", &bytes, w, h).unwrap();
        let grid = img.to_grid();
        for border in BORDERS {
            // sobel_y is right minus left (the fast gx), sobel_x top minus
            // bottom (minus the fast gy)
            let Ok(g) = filter::gradient(&grid, &filter::sobel_y(), &filter::sobel_x(), border)
            else {
                continue;
            };
            let (mut gx, mut gy, mut mag) =
                (vec![0.0f32; w * h], vec![0.0f32; w * h], vec![0.0f32; w * h]);
            fast::sobel(img, border, &mut gx, &mut gy, &mut mag).unwrap();
            let reg = g.region;
            for r in 0..reg.height {
                for c in 0..reg.width {
                    let i = (r + reg.r0) * w + c + reg.c0;
                    let at = |grid: &photogrammetry_playground::raster::Grid| {
                        grid.get(c, r).unwrap_or(f64::NAN)
                    };
                    assert_eq!(f64::from(gx[i]), at(&g.gx), "gx {w}×{h} {border:?} ({c}, {r})");
                    assert_eq!(f64::from(gy[i]), -at(&g.gy), "gy {w}×{h} {border:?} ({c}, {r})");
                    assert!(close(mag[i], at(&g.magnitude)), "magnitude ({c}, {r})");
                }
            }
        }
    }
}

#[test]
fn median3_equals_median_exactly() {
    for (k, &(w, h)) in SIZES.iter().enumerate() {
        // few grey levels too, so that ties are common
        for levels in [256u32, 3] {
            let bytes: Vec<u8> = random_image(w, h, 200 + k as u64)
                .iter()
                .map(|&v| (u32::from(v) % levels) as u8)
                .collect();
            let img = Gray::new("img", &bytes, w, h).unwrap();
            let grid = img.to_grid();
            for border in BORDERS {
                let Ok(reference) = filter::median(&grid, 3, 3, border) else {
                    continue;
                };
                let mut out = vec![0u8; w * h];
                fast::median3(img, border, &mut out).unwrap();
                let reg = reference.region;
                for r in reg.r0..reg.r0 + reg.height {
                    for c in reg.c0..reg.c0 + reg.width {
                        assert_eq!(
                            Some(f64::from(out[r * w + c])),
                            reference.at_input(c, r),
                            "median {w}×{h} {border:?} at ({c}, {r})"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn wrong_buffers_are_errors_not_panics() {
    let bytes = random_image(5, 4, 1);
    assert!(Gray::new("img", &bytes, 4, 4).is_err());
    let img = Gray::new("img", &bytes, 5, 4).unwrap();
    let mut short = vec![0.0f32; 19];
    assert!(fast::mean3(img, Border::Replicate, &mut short).is_err());
    let mut out = vec![0.0f32; 20];
    assert!(fast::separable(img, &[1.0, 1.0], &[1.0], 1.0, Border::Zero, &mut out).is_err());
}
