//! The photo's own Förstner threshold (`w_min`, the `w` of rank
//! `ops::top_rank` among the windows that fit) on the routes the test
//! photos of `fast_layers.rs` and `colour_layers.rs` never take, each
//! against the reference's own map (`interest::forstner_map`, its `w`
//! sorted):
//!
//! * 8-bit, more than 4096 windows whose `f32` `w` is the rank's value:
//!   `exact_w_min` recomputes them by a pass over the image;
//! * a colour photo's levels with more than 2¹⁶ windows near the rank's
//!   value (a periodic photo: every window holds the same gradients, its
//!   `f64` `w` differing only by the reference's order of summation):
//!   `levels_w_min`'s first route gives up, the second (each window's own
//!   bound from its sums) answers;
//! * a `w` layer that is not the photo's (each value 0.1 % off): neither
//!   route finds the rank's value near the layer's, so the last one takes
//!   every window's reference `w`.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use photogrammetry_lab::ops::{self, Image};
use photogrammetry_playground::interest::{self, fast::stream};
use photogrammetry_playground::raster::Grid;
use std::cell::OnceCell;

/// The reference's `w_min`: its map's `w` sorted, the value of rank
/// `⌊(1 − share)·(n − 1)⌋`, written out here (not `ops::top_rank`).
fn reference_w_min(grid: &Grid, size: usize) -> f64 {
    let map = interest::forstner_map(grid, size).unwrap();
    let mut ws: Vec<f64> = map.cells.iter().flatten().map(|m| m.w).collect();
    ws.sort_by(f64::total_cmp);
    let k = ((1.0 - 0.001) * (ws.len() - 1) as f64).floor() as usize;
    ws[k]
}

/// A periodic photo of `levels` (period 3 both ways: a 5 × 5 window's 3 × 3
/// interior holds each phase once, so every window has the same gradients).
fn periodic(width: usize, height: usize, scale: f64, base: [[f64; 3]; 3]) -> Grid {
    Grid::from_fn(width, height, |c, r| base[r % 3][c % 3] / scale)
}

#[test]
fn eight_bit_photo_with_thousands_of_tied_windows() {
    let g = periodic(
        100,
        90,
        1.0,
        [
            [12.0, 200.0, 77.0],
            [140.0, 31.0, 250.0],
            [66.0, 180.0, 9.0],
        ],
    );
    let bytes: Vec<u8> = g.data().iter().map(|&v| v as u8).collect();
    let kept = ops::ForstnerKept::new(Image::from_bytes(100, 90, &bytes).unwrap(), 5).unwrap();
    let w = &kept.layers()[0].data;
    let fit = stream::fit(100, 90, 5).unwrap();
    // every window ties on the layer (more than exact_w_min's 4096 at a time)
    let cells: Vec<f32> = (fit.r0..fit.r0 + fit.rows)
        .flat_map(|r| w[r * 100 + fit.c0..r * 100 + fit.c0 + fit.columns].to_vec())
        .collect();
    assert!(cells.len() > 4096 && cells.iter().all(|&x| x == cells[0]));
    let want = reference_w_min(&g, 5);
    assert!(want > 0.0);
    assert_eq!(kept.auto_threshold(8.0).map(|a| a.w_min), Some(want));
    assert_eq!(
        ops::exact_w_min(&bytes, 100, 90, 5, w, fit),
        Some(want),
        "exact_w_min"
    );
}

#[test]
fn colour_levels_with_more_windows_near_the_rank_than_the_first_route_takes() {
    // greys n / 1000 (no binary fraction: the reference's sums round, and
    // differently for each window's order), 296² = 87616 windows
    let base = [
        [37_123.0, 201_457.0, 88_001.0],
        [140_999.0, 12_345.0, 249_876.0],
        [66_600.0, 180_333.0, 9_871.0],
    ];
    let g = periodic(300, 300, 1000.0, base);
    let keep = OnceCell::from(ops::levels_of(g.data()));
    let lv = keep.get().unwrap().as_ref().unwrap();
    assert_eq!(lv.scale, 1000.0);
    let kept = ops::ForstnerKept::new(Image::with_bytes(&g, None).with_levels(&keep), 5).unwrap();
    let want = reference_w_min(&g, 5);
    // the windows' reference w are not all one number (the rank matters)
    let map = interest::forstner_map(&g, 5).unwrap();
    let ws: Vec<f64> = map.cells.iter().flatten().map(|m| m.w).collect();
    assert!(ws.iter().any(|&x| x != ws[0]), "every window's w the same");
    assert!(ws.iter().all(|&x| (x - want).abs() <= 1e-9 * want));
    assert_eq!(kept.auto_threshold(8.0).map(|a| a.w_min), Some(want));
    let w = &kept.layers()[0].data;
    assert_eq!(ops::levels_w_min(lv, 300, 300, 5, w), Some(want));
}

#[test]
fn a_layer_that_is_not_the_photos_falls_back_to_every_window() {
    // a colour photo's levels of no pattern (SplitMix64)
    let mut s = 0x5eed_u64;
    let mut next = move || {
        s = s.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = s;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) % 255_000) as f64
    };
    let (width, height) = (61, 47);
    let data: Vec<f64> = (0..width * height).map(|_| next() / 1000.0).collect();
    let g = Grid::new("image", width, height, data).unwrap();
    let keep = OnceCell::from(ops::levels_of(g.data()));
    let lv = keep.get().unwrap().as_ref().unwrap();
    for size in [4, 5, 7] {
        let want = reference_w_min(&g, size);
        assert!(want > 0.0, "size {size}: w_min 0 (no rank to miss)");
        let kept =
            ops::ForstnerKept::new(Image::with_bytes(&g, None).with_levels(&keep), size).unwrap();
        let w = &kept.layers()[0].data;
        assert_eq!(ops::levels_w_min(lv, width, height, size, w), Some(want));
        // each value 0.1 % high: same order, no value near the rank's
        let off: Vec<f32> = w.iter().map(|&x| x * 1.001).collect();
        assert_eq!(
            ops::levels_w_min(lv, width, height, size, &off),
            Some(want),
            "size {size}: a layer 0.1 % off"
        );
    }
}
