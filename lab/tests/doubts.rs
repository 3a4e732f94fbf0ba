//! The lab's judgement of its own results (issue 29, item 12): a match it
//! calls doubtful, and why; Förstner's default threshold chosen per photo.

use photogrammetry_lab::ops::{self, Rect};
use photogrammetry_playground::interest;
use photogrammetry_playground::matching::Model;
use photogrammetry_playground::raster::Grid;

/// camera.png as the lab decodes it.
fn camera() -> Grid {
    let bytes = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../www/lab/samples/camera.png"
    ))
    .unwrap();
    photogrammetry_lab::decode::decode("camera.png", &bytes)
        .unwrap()
        .grid
}

#[test]
fn a_match_on_the_search_boxs_edge_or_with_a_gain_far_from_1_is_doubtful_and_says_why() {
    let a = camera();
    let t = Rect {
        c0: 240,
        r0: 120,
        width: 21,
        height: 21,
    };
    // the true position (the template's own) in the middle of the box: nothing to say
    let around = Rect {
        c0: 225,
        r0: 105,
        width: 51,
        height: 51,
    };
    let m = ops::correlate(&a, t, &a, around, Model::ShiftRadiometric).unwrap();
    assert_eq!(m.best, Some((250, 130)));
    assert_eq!(ops::doubts(&m), Vec::<String>::new());
    // a smooth blob, and a box that stops 4 px short of the template's own
    // position, to its right: ρ falls with the distance, so the best is on
    // the box's left edge
    let blob = Grid::new(
        "image",
        120,
        100,
        (0..100)
            .flat_map(|r| (0..120).map(move |c| (c as f64, r as f64)))
            .map(|(c, r)| 20.0 + 200.0 * (-((c - 60.0).powi(2) + (r - 50.0).powi(2)) / 450.0).exp())
            .collect(),
    )
    .unwrap();
    let tb = Rect {
        c0: 50,
        r0: 40,
        width: 11,
        height: 11,
    };
    let short = Rect {
        c0: 54,
        r0: 30,
        width: 40,
        height: 31,
    };
    let m = ops::correlate(&blob, tb, &blob, short, Model::ShiftRadiometric).unwrap();
    assert_eq!(m.best.map(|b| b.0), Some(54 + 5));
    let d = ops::doubts(&m);
    assert!(
        d.iter().any(|s| s.contains("left edge of the search area")),
        "{d:?}"
    );
    // the search photo at a third of the contrast: ρ = 1 (NCC does not see a
    // gain); LSM's gain (template = gain · search + offset) is 3
    let dim = Grid::new(
        "image",
        a.width(),
        a.height(),
        (0..a.height())
            .flat_map(|r| (0..a.width()).map(move |c| (r, c)))
            .map(|(r, c)| a.get(c, r).unwrap() / 3.0 + 20.0)
            .collect(),
    )
    .unwrap();
    let m = ops::correlate(&a, t, &dim, around, Model::ShiftRadiometric).unwrap();
    assert_eq!(m.best, Some((250, 130)));
    let gain = m.lsm.as_ref().unwrap().params.a[6];
    assert!((gain - 3.0).abs() < 1e-3, "{gain}");
    let d = ops::doubts(&m);
    assert_eq!(d.len(), 1, "{d:?}");
    assert!(
        d[0].starts_with("LSM's gain 3 is outside 0.667 … 1.5"),
        "{d:?}"
    );
}

#[test]
fn forstners_threshold_for_a_photo_keeps_its_strongest_pixels_and_about_the_chessboards_corners() {
    let bytes = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../www/lab/samples/left01.jpg"
    ))
    .unwrap();
    let img = photogrammetry_lab::decode::decode("left01.jpg", &bytes)
        .unwrap()
        .grid;
    let mut kept = ops::ForstnerKept::new(&img, 5).unwrap();
    let auto = kept.auto_threshold(8.0).unwrap();
    // w_min: the w that 0.1 % of the pixels reach (the reference's map)
    let map = interest::forstner_map(&img, 5).unwrap();
    let ws: Vec<f64> = map.cells.iter().flatten().map(|m| m.w).collect();
    let above = ws.iter().filter(|w| **w >= auto.w_min).count() as f64 / ws.len() as f64;
    assert!((above - ops::W_TOP_SHARE).abs() < 2e-4, "{above}");
    // exactly the reference's 99.9th percentile
    let mut sorted = ws.clone();
    sorted.sort_by(f64::total_cmp);
    let k = ((1.0 - ops::W_TOP_SHARE) * (ws.len() - 1) as f64).floor() as usize;
    assert_eq!(auto.w_min, sorted[k]);
    assert!((auto.threshold_px - 8.0 / auto.w_min.sqrt()).abs() < 1e-12);
    // T scales with σn: the same pixels pass whatever σn
    let twice = kept.auto_threshold(16.0).unwrap();
    assert!((twice.threshold_px - 2.0 * auto.threshold_px).abs() < 1e-12);
    let n = kept.points(8.0, auto.threshold_px, 0.5).unwrap().len();
    let n16 = kept.points(16.0, twice.threshold_px, 0.5).unwrap().len();
    assert_eq!(n, n16);
    // the fixed T = 0.5 px kept 923 points, mostly texture; the board has 88 square corners
    let fixed = kept.points(8.0, 0.5, 0.5).unwrap().len();
    assert_eq!(fixed, 923);
    assert!((88..=200).contains(&n), "{n} points");
    // no textured pixel: no threshold
    let flat = Grid::new("image", 20, 20, vec![7.0; 400]).unwrap();
    assert_eq!(
        ops::ForstnerKept::new(&flat, 5)
            .unwrap()
            .auto_threshold(8.0),
        None
    );
}
