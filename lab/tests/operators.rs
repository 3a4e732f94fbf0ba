//! The lab's whole-image filters, edges and interest operators against the
//! core's window functions (DESIGN.md's first rule) and against known
//! truths. (Matching, fiducials, rectification, warps, boundaries:
//! geometry.rs.)

mod common;

use common::random;
use photogrammetry_lab::ops;
use photogrammetry_playground::filter::{self, neighbourhood};
use photogrammetry_playground::interest;
use photogrammetry_playground::raster::Grid;

const BORDERS: [&str; 4] = ["replicate", "reflect", "zero", "crop"];

#[test]
fn every_filter_equals_its_window_sum_at_every_pixel_under_every_border() {
    let img = random(11, 9, 1);
    for b in BORDERS {
        let border = ops::border(b).unwrap();
        // every named kernel (the median has none)
        for k in filter::NAMES.into_iter().filter(|&k| k != "median") {
            let kernel = ops::kernel(k, None).unwrap().unwrap();
            let layer = ops::filter_image(&img, k, border, None).unwrap();
            let mut covered = 0;
            for r in 0..9 {
                for c in 0..11 {
                    // the worked example's function for one window
                    match filter::pixel_sum(&img, &kernel, c, r, border) {
                        Some(p) => {
                            // the layer: the value rounded to f32; the
                            // inspector's exact value: the example's
                            let f = Some(f64::from(p.value as f32));
                            assert_eq!(layer.at(c, r), f, "{k} {b} ({c}, {r})");
                            let op = ops::Op::Filter {
                                kernel: k.into(),
                                border,
                                custom: None,
                            };
                            let exact = ops::exact_at(&img, &img, &op, k, c, r).unwrap();
                            assert_eq!(exact, Some(p.value), "{k} {b} ({c}, {r})");
                            covered += 1;
                        }
                        None => assert_eq!(layer.at(c, r), None, "{k} {b} ({c}, {r})"),
                    }
                }
            }
            let half = kernel.half_width();
            let want = if b == "crop" {
                (11 - 2 * half) * (9 - 2 * half)
            } else {
                99
            };
            assert_eq!(covered, want, "{k} {b}");
        }
        // the median: the median of the 3×3 neighbourhood
        let layer = ops::filter_image(&img, "median", border, None).unwrap();
        for r in 0..9 {
            for c in 0..11 {
                let want =
                    neighbourhood(&img, c, r, 3, 3, border).and_then(|v| filter::median_of(&v));
                assert_eq!(layer.at(c, r), want, "median {b} ({c}, {r})");
                let op = ops::Op::Filter {
                    kernel: "median".into(),
                    border,
                    custom: None,
                };
                let exact = ops::exact_at(&img, &img, &op, "median", c, r).unwrap();
                assert_eq!(exact, want, "median {b} ({c}, {r})");
            }
        }
    }
}

#[test]
fn edges_equal_the_kernel_sums_the_magnitude_and_the_direction() {
    let img = random(10, 8, 2);
    for b in BORDERS {
        let border = ops::border(b).unwrap();
        for (op, kx, ky) in [
            ("prewitt", filter::prewitt_x(), filter::prewitt_y()),
            ("sobel", filter::sobel_x(), filter::sobel_y()),
        ] {
            let ls = ops::edges(&img, op, border).unwrap();
            for r in 0..8 {
                for c in 0..10 {
                    let gx = filter::pixel_sum(&img, &kx, c, r, border).map(|p| p.value);
                    let gy = filter::pixel_sum(&img, &ky, c, r, border).map(|p| p.value);
                    let f32_of = |v: Option<f64>| v.map(|v| f64::from(v as f32));
                    assert_eq!(ls[0].at(c, r), f32_of(gx));
                    assert_eq!(ls[1].at(c, r), f32_of(gy));
                    let m = gx.zip(gy).map(|(x, y)| x.hypot(y));
                    assert_eq!(ls[2].at(c, r), f32_of(m), "{op} {b} ({c}, {r})");
                    // direction: atan2(gy, gx) in degrees, −180° … 180°
                    let d = gx.zip(gy).map(|(x, y)| y.atan2(x).to_degrees());
                    assert_eq!(ls[3].name, "direction");
                    match (ls[3].at(c, r), d) {
                        (Some(x), Some(y)) => {
                            assert!((x - y).abs() <= 1e-4, "{op} {b} ({c}, {r}): {x} vs {y}")
                        }
                        (x, y) => assert_eq!(x, y, "{op} {b} direction ({c}, {r})"),
                    }
                    // the inspector's exact values: the example's
                    let eop = ops::Op::Edges {
                        operator: op.into(),
                        border,
                    };
                    for (l, want) in [("gx", gx), ("gy", gy), ("magnitude", m), ("direction", d)] {
                        let exact = ops::exact_at(&img, &img, &eop, l, c, r).unwrap();
                        assert_eq!(exact, want, "{op} {b} {l} ({c}, {r})");
                    }
                    if let Some(d) = ls[3].at(c, r) {
                        assert!((-180.0..=180.0).contains(&d));
                    }
                }
            }
        }
    }
}

#[test]
fn forstner_and_moravec_maps_equal_their_window_functions_at_every_pixel() {
    let img = random(12, 10, 3);
    let (ls, _) = ops::forstner(&img, 5, 2.0, 0.5, 0.0).unwrap();
    let (mor, _) = ops::moravec(&img, 4, 0.0).unwrap();
    for r in 0..10 {
        for c in 0..12 {
            let win = interest::window_at(&img, c, r, 5);
            let want = win.map(|w| interest::forstner(&w).unwrap().measures);
            let f32_of = |v: Option<f64>| v.map(|v| f64::from(v as f32));
            assert_eq!(ls[0].at(c, r), f32_of(want.map(|m| m.w)), "w ({c}, {r})");
            assert_eq!(ls[1].at(c, r), f32_of(want.and_then(|m| m.q)));
            let op = ops::Op::Forstner { size: 5 };
            let exact = |l| ops::exact_at(&img, &img, &op, l, c, r).unwrap();
            assert_eq!(exact("w"), want.map(|m| m.w));
            assert_eq!(exact("q"), want.and_then(|m| m.q));
            let win = interest::window_at(&img, c, r, 4);
            let want = win.map(|w| interest::moravec(&w).unwrap().mean);
            assert_eq!(mor.at(c, r), f32_of(want), "moravec ({c}, {r})");
            let op = ops::Op::Moravec { size: 4 };
            assert_eq!(
                ops::exact_at(&img, &img, &op, "moravec", c, r).unwrap(),
                want
            );
        }
    }
}

#[test]
fn forstner_finds_the_checkerboard_corners_within_half_a_pixel() {
    // 8-px squares: the corners are between pixels, at c = 8k − 0.5.
    let img = Grid::from_fn(48, 48, |c, r| {
        if (c / 8 + r / 8) % 2 == 0 {
            40.0
        } else {
            200.0
        }
    });
    let (_, pts) = ops::forstner(&img, 5, 1.0, 0.5, 0.5).unwrap();
    // every inner corner (k = 1 … 5 both ways) is found, and only those
    let mut found = [false; 25];
    for p in &pts {
        let (kc, kr) = ((p.c as f64 + 0.5) / 8.0, (p.r as f64 + 0.5) / 8.0);
        let (nc, nr) = (kc.round(), kr.round());
        // the window's anchor pixel lies half a pixel from the true corner
        let (dc, dr) = (p.c as f64 - (8.0 * nc - 0.5), p.r as f64 - (8.0 * nr - 0.5));
        assert!(
            dc.abs() <= 0.5 && dr.abs() <= 0.5,
            "{p:?} is {dc}, {dr} px off"
        );
        assert!(
            (1.0..=5.0).contains(&nc) && (1.0..=5.0).contains(&nr),
            "{p:?}"
        );
        found[(nr as usize - 1) * 5 + nc as usize - 1] = true;
        assert!(p.major > 0.0 && p.minor > 0.0 && p.major >= p.minor);
    }
    assert_eq!(pts.len(), 25, "{pts:?}");
    assert!(found.iter().all(|&f| f));
}

#[test]
fn a_handful_of_pixels_of_a_sample_photo_agree_with_an_independent_computation() {
    // The numbers come from tests/corpus/independent.py: its own PNG decoder
    // (zlib and the scanline filters) and the sums written out by hand.
    let bytes = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../www/lab/samples/camera.png"
    ))
    .unwrap();
    let img = photogrammetry_lab::decode::decode("camera.png", &bytes)
        .unwrap()
        .grid;
    let mean = ops::filter_image(&img, "mean", ops::border("crop").unwrap(), None).unwrap();
    let edges = ops::edges(&img, "sobel", ops::border("crop").unwrap()).unwrap();
    for (c, r, grey, m, gx) in [
        (0, 0, 200.0, None, None),
        (100, 50, 210.0, Some(1884.0 / 9.0), Some(-5.0)),
        (256, 256, 14.0, Some(10.0), Some(-32.0)),
        (300, 400, 155.0, Some(1397.0 / 9.0), Some(-31.0)),
        (511, 511, 149.0, None, None),
    ] {
        assert_eq!(img.get(c, r), Some(grey), "({c}, {r})");
        match (mean.at(c, r), m) {
            (Some(a), Some(b)) => assert_eq!(a, f64::from(b as f32), "({c}, {r}): {a} vs {b}"),
            (a, b) => assert_eq!(a, b, "({c}, {r})"),
        }
        assert_eq!(edges[0].at(c, r), gx, "({c}, {r})");
    }
}

/// The lab's fast routes (`ops::fast_filter`, `ops::fast_edges`: the core's
/// `filter::fast` paths) give the reference's value rounded to `f32` at
/// every pixel (the bits of `value as f32`, not only within a tolerance):
/// random 8-bit images of odd sizes from 1×1 up, every border.
#[test]
fn fast_routes_give_the_reference_bits_at_every_pixel() {
    for (name, kx, ky, d) in ["mean", "gaussian-3", "gaussian-5"]
        .map(|n| (n, ops::separable_taps(n).unwrap()))
        .map(|(n, (kx, ky, d))| (n, kx, ky, d))
    {
        let k = ops::kernel(name, None).unwrap().unwrap();
        assert_eq!((k.width(), k.height()), (kx.len(), ky.len()), "{name}");
        for (j, y) in ky.iter().enumerate() {
            for (i, x) in kx.iter().enumerate() {
                assert_eq!(
                    k.numerators().get(i, j),
                    Some(f64::from(x * y)),
                    "{name} ({i}, {j})"
                );
            }
        }
        assert_eq!(k.divisor(), d, "{name}");
    }
    let same = |what: &str, got: &ops::Layer, want: &Grid, c0: usize, r0: usize| {
        assert_eq!(
            (got.width, got.height, got.c0, got.r0),
            (want.width(), want.height(), c0, r0),
            "{what}"
        );
        for (i, (g, w)) in got.data.iter().zip(want.data()).enumerate() {
            assert_eq!(
                g.to_bits(),
                (*w as f32).to_bits(),
                "{what} at {i}: fast {g}, reference {w}"
            );
        }
    };
    let sizes = [
        (1, 1),
        (2, 3),
        (3, 1),
        (5, 5),
        (6, 7),
        (17, 4),
        (31, 23),
        (64, 9),
    ];
    for (s, &(w, h)) in sizes.iter().enumerate() {
        let mut img = random(w, h, 40 + s as u64);
        if s % 2 == 1 {
            // flat runs: zero sums (no −0 may reach the layer)
            let d: Vec<f64> = img
                .data()
                .iter()
                .enumerate()
                .map(|(i, v)| if i % 5 < 3 { 7.0 } else { *v })
                .collect();
            img = Grid::new("image", w, h, d).unwrap();
        }
        for b in BORDERS {
            let border = ops::border(b).unwrap();
            for name in ["mean", "gaussian-3", "gaussian-5", "median"] {
                let fast = ops::fast_filter(&(&img).into(), name, border, None).unwrap();
                let want = match ops::kernel(name, None).unwrap() {
                    Some(k) => filter::correlate(&img, &k, border),
                    None => filter::median(&img, 3, 3, border),
                };
                match (fast, want) {
                    (Some(f), Ok(r)) => same(
                        &format!("{name} {b} {w}×{h}"),
                        &f,
                        &r.output,
                        r.region.c0,
                        r.region.r0,
                    ),
                    (None, Err(_)) => {}
                    (f, r) => panic!(
                        "{name} {b} {w}×{h}: fast {:?} vs reference {:?}",
                        f.is_some(),
                        r.is_ok()
                    ),
                }
            }
            for (op, kx, ky) in [
                ("prewitt", filter::prewitt_x(), filter::prewitt_y()),
                ("sobel", filter::sobel_x(), filter::sobel_y()),
            ] {
                let fast = ops::fast_edges(&(&img).into(), op, border).unwrap();
                let Ok(g) = filter::gradient(&img, &kx, &ky, border) else {
                    assert!(fast.is_none(), "{op} {b} {w}×{h}");
                    continue;
                };
                let fast = fast.unwrap();
                let (c0, r0) = (g.region.c0, g.region.r0);
                let what = format!("{op} {b} {w}×{h}");
                same(&format!("{what} gx"), &fast[0], &g.gx, c0, r0);
                same(&format!("{what} gy"), &fast[1], &g.gy, c0, r0);
                same(&format!("{what} magnitude"), &fast[2], &g.magnitude, c0, r0);
                // and the whole-image operator the lab calls routes there
                assert_eq!(ops::edges(&img, op, border).unwrap(), fast, "{what}");
            }
        }
    }
    // neither 8-bit nor levels (whole numbers over 1, 1000, 4000, … as a
    // colour photo's greys are: lab/tests/colour_layers.rs): the reference path
    let frac = Grid::new("image", 3, 3, vec![std::f64::consts::SQRT_2; 9]).unwrap();
    assert!(
        ops::fast_filter(&(&frac).into(), "mean", ops::border("zero").unwrap(), None)
            .unwrap()
            .is_none()
    );
}

#[test]
fn a_custom_kernel_is_checked_field_by_field() {
    let err = |text: &str, d: Option<f64>| ops::custom_kernel(text, d).unwrap_err().to_string();
    assert!(err("1 2 x", None).starts_with("custom_kernel: row 1: \"x\" is not a number"));
    assert!(err("1 2 1\n2 4", None).contains("row 2 has 2 numbers but row 1 has 3"));
    assert!(err("1 1\n1 1", None).contains("is 2×2 (rows × columns); a kernel needs an odd number"));
    let big = vec!["1 ".repeat(17); 17].join("\n");
    assert!(err(&big, None).contains("is 17×17 (rows × columns); at most 15×15"));
    assert!(err("  \n ", None).starts_with("custom_kernel: is empty"));
    assert!(err("0 0 0", None).contains("all weights are 0"));
    assert!(err("-1 0 1", None).starts_with("custom_divisor: the weights sum to 0"));
    assert!(
        err("1 2 1", Some(0.0)).starts_with("custom_divisor: must be a finite number other than 0")
    );
    // rows on lines or after `;`, numbers by spaces or commas; normalised by the sum
    let (rows, d) = ops::custom_kernel("1, 2, 1; 2 4 2\n 1 2 1 ", None).unwrap();
    assert_eq!(
        rows,
        vec![
            vec![1.0, 2.0, 1.0],
            vec![2.0, 4.0, 2.0],
            vec![1.0, 2.0, 1.0]
        ]
    );
    assert_eq!(d, 16.0);
    assert_eq!(ops::custom_kernel("-1 0 1", Some(2.0)).unwrap().1, 2.0);
}

/// The worked example `filter-window` on `window` (rows) with a custom
/// kernel: its output's centre (the crop interior's middle pixel).
fn filter_window_custom(window: &[Vec<f64>], kernel: &[Vec<f64>], divisor: f64) -> f64 {
    use photogrammetry_playground::examples::solve;
    use photogrammetry_playground::solution::{Record, Value};
    let s = solve(
        "filter-window",
        &Record::new()
            .with("window", Value::matrix(window))
            .with("kernel", "custom")
            .with("custom_kernel", Value::matrix(kernel))
            .with("custom_divisor", divisor)
            .with("border", "crop"),
    )
    .unwrap();
    match s.result.get("output").unwrap() {
        Value::List(rows) => match &rows[1] {
            Value::List(row) => match &row[1] {
                Value::Number(v) => *v,
                other => panic!("{other:?}"),
            },
            other => panic!("{other:?}"),
        },
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_custom_kernel_over_the_image_equals_filter_window_at_every_pixel() {
    let img = random(13, 11, 7);
    // a 5×3 (rows × columns) asymmetric kernel, normalised by its sum (10)
    let (rows, d) = ops::custom_kernel("1 0 2\n-1 3 1\n0 1 1\n2 0 -1\n1 0 0", None).unwrap();
    assert_eq!(d, 10.0);
    let kernel = filter::Kernel::new("custom_kernel", &rows, d).unwrap();
    for b in BORDERS {
        let border = ops::border(b).unwrap();
        let layer = ops::filter_image(&img, "custom", border, Some((&rows, d))).unwrap();
        assert_eq!(layer.name, "custom");
        for r in 0..11 {
            for c in 0..13 {
                let want = filter::pixel_sum(&img, &kernel, c, r, border).map(|p| p.value);
                let f32_of = want.map(|v| f64::from(v as f32));
                assert_eq!(layer.at(c, r), f32_of, "{b} ({c}, {r})");
                let Some(v) = want else { continue };
                // the lab's "explain": the (k+2)-sized neighbourhood under the
                // same border, solved by the worked example with the kernel
                // (under crop it exists only a pixel further inside)
                let Some(win) = neighbourhood(&img, c, r, 5, 7, border) else {
                    assert!(
                        b == "crop" && (c < 2 || r < 3 || c > 10 || r > 7),
                        "({c}, {r})"
                    );
                    continue;
                };
                let win: Vec<Vec<f64>> = win.chunks(5).map(<[f64]>::to_vec).collect();
                if (c + r) % 3 == 0 {
                    assert_eq!(filter_window_custom(&win, &rows, d), v, "{b} ({c}, {r})");
                }
            }
        }
    }
}

#[test]
fn forstner_points_from_a_kept_map_equal_a_full_run_for_every_threshold() {
    let img = interest::test_pattern(64, 3.0, 5).unwrap();
    let mut kept = ops::ForstnerKept::new(&img, 5).unwrap();
    for (t, q) in [(0.3, 0.5), (0.5, 0.5), (1.0, 0.0), (2.0, 0.7)] {
        let (ls, ps) = ops::forstner(&img, 5, 8.0, t, q).unwrap();
        let (rl, rp) = ops::forstner_reference(&img, 5, 8.0, t, q).unwrap();
        // NaN where no window fits: compared by their bits
        let bits = |ls: &[ops::Layer]| -> Vec<(String, Vec<u32>)> {
            ls.iter()
                .map(|l| (l.name.clone(), l.data.iter().map(|v| v.to_bits()).collect()))
                .collect()
        };
        assert_eq!(bits(&ls), bits(kept.layers()));
        assert_eq!(bits(&ls), bits(&rl), "T = {t}");
        assert_eq!(ps, rp, "T = {t}");
        assert_eq!(kept.points(8.0, t, q).unwrap(), ps, "T = {t}");
    }
    // a lower threshold keeps no more points than a higher one
    let mut n = |t| kept.points(8.0, t, 0.0).unwrap().len();
    let (low, high) = (n(0.3), n(1.0));
    assert!(low <= high && high > 0, "{low} {high}");
    assert!(kept
        .points(8.0, 0.0, 0.5)
        .unwrap_err()
        .to_string()
        .starts_with("threshold_px: "));
}

#[test]
fn the_kept_suppression_gives_seed_003s_points_for_every_threshold() {
    // a noisy pattern (many candidates, ties of equal windows), a random
    // image, and one that is not 8-bit (the reference route)
    let half = Grid::from_fn(30, 27, |c, r| ((c * 7 + r * 13) % 23) as f64 + 0.5);
    for img in [
        interest::test_pattern(64, 3.0, 9).unwrap(),
        random(40, 33, 11),
        half,
    ] {
        for size in [3, 4, 5, 7] {
            let mut kept = ops::ForstnerKept::new(&img, size).unwrap();
            for (sigma, q) in [(8.0, 0.5), (8.0, 0.0), (2.5, 0.75)] {
                // rising and falling T: the suppression re-used and redone
                for t in [0.05, 0.2, 0.35, 0.5, 0.8, 1.0, 1.7, 3.0, 100.0, 0.4] {
                    let (_, want) = ops::forstner_reference(&img, size, sigma, t, q).unwrap();
                    assert_eq!(
                        kept.points(sigma, t, q).unwrap(),
                        want,
                        "size {size} σn {sigma} q {q} T {t}"
                    );
                }
            }
        }
    }
    let mut kept = ops::ForstnerKept::new(&random(9, 9, 1), 3).unwrap();
    assert!(kept
        .points(8.0, f64::NAN, 0.5)
        .unwrap_err()
        .to_string()
        .starts_with("threshold_px: "));
}
