//! Colour photos on the fast paths (issue 31): a colour photo's greys are
//! the BT.601 sums `n = 299·R + 587·G + 114·B` over 1000 (over `1000·k²`
//! reduced `k×`), 16-bit greys whole numbers — `ops::Levels`. The filters
//! (every named kernel, the median, custom kernels) and the edges run the
//! core's fast passes on `n` and divide by the scale once; each layer is
//! tied here to the reference function on the `f64` greys (the grid the
//! explained pixel reads) at every pixel:
//!
//! * the median: the reference's value rounded to `f32`, bit for bit;
//! * integer kernels whose sums of `n` are exact in `f32`
//!   (`Σ|k|·max n < 2²⁴`), `gx`, `gy` and the magnitude: within half an
//!   `f32` step of the reference plus `10⁻¹²·Σ|k|·top/|d|` (its own `f64`
//!   roundings of the divided greys; `top` the photo's largest grey);
//! * other kernels: within `10⁻⁶ · Σ|k| · top / |d|` (the `f32` sums);
//! * the direction: within 10⁻⁴ degrees.
//!
//! And a band of rows with its halo equals the whole photo's rows bit for
//! bit (the band finds the same levels over the same scale).

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

mod common;

use photogrammetry_lab::decode::luma;
use photogrammetry_lab::ops::{self, Image, Layer, Op};
use photogrammetry_playground::filter::{self, Kernel};
use photogrammetry_playground::raster::Grid;

/// SplitMix64 numbers below `n`.
fn numbers(seed: u64, n: u64) -> impl FnMut() -> f64 {
    let mut s = seed;
    move || {
        s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = s;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) % n) as f64
    }
}

/// A colour photo's greys as the decoder makes them (`decode::luma`).
fn colour(w: usize, h: usize, seed: u64) -> Grid {
    let mut next = numbers(seed, 256);
    let data = (0..w * h)
        .map(|_| {
            let (r, g, b) = (next(), next(), next());
            luma(r, g, b)
        })
        .collect();
    Grid::new("image", w, h, data).unwrap()
}

/// A colour photo reduced 2× as the decoder reduces it: each grey the
/// block's four BT.601 sums over 4000 (`decode/grey.rs`).
fn colour_reduced(w: usize, h: usize, seed: u64) -> Grid {
    let mut next = numbers(seed, 256);
    let data = (0..w * h)
        .map(|_| {
            let s: f64 = (0..4)
                .map(|_| 299.0 * next() + 587.0 * next() + 114.0 * next())
                .sum();
            s / 4000.0
        })
        .collect();
    Grid::new("image", w, h, data).unwrap()
}

fn images() -> Vec<(String, Grid, f64)> {
    let mut out = Vec::new();
    for (k, &(w, h)) in [(1, 1), (7, 5), (33, 29), (64, 48)].iter().enumerate() {
        out.push((
            format!("colour {w}×{h}"),
            colour(w, h, 3 + k as u64),
            1000.0,
        ));
    }
    out.push((
        "colour reduced 2× 40×31".into(),
        colour_reduced(40, 31, 5),
        4000.0,
    ));
    // a colour checkerboard: two colours, flat squares (ties, zero gradients)
    let (a, b) = (luma(200.0, 30.0, 90.0), luma(10.0, 240.0, 33.0));
    out.push((
        "colour checkerboard 48×40".into(),
        Grid::from_fn(48, 40, |c, r| if (c / 4 + r / 4) % 2 == 0 { a } else { b }),
        1000.0,
    ));
    let mut next = numbers(11, 65536);
    let data = (0..45 * 37).map(|_| next()).collect();
    out.push((
        "16-bit 45×37".into(),
        Grid::new("image", 45, 37, data).unwrap(),
        1.0,
    ));
    out
}

/// A custom kernel's rows and divisor.
type Custom = (Vec<Vec<f64>>, f64);

const BORDERS: [&str; 4] = ["replicate", "reflect", "zero", "crop"];

fn check(
    what: &str,
    layer: &Layer,
    want: impl Fn(usize, usize) -> Option<f64>,
    ok: impl Fn(f32, f64) -> bool,
) {
    let mut n = 0;
    for r in layer.r0..layer.r0 + layer.height {
        for c in layer.c0..layer.c0 + layer.width {
            let got = layer.data[(r - layer.r0) * layer.width + (c - layer.c0)];
            let v =
                want(c, r).unwrap_or_else(|| panic!("{what} at ({c}, {r}): no reference value"));
            assert!(
                ok(got, v),
                "{what} at ({c}, {r}): layer {got}, reference {v}"
            );
            n += 1;
        }
    }
    assert!(n > 0 || layer.data.is_empty(), "{what}");
}

/// Half an `f32` step of `want` plus `abs`.
fn near(abs: f64) -> impl Fn(f32, f64) -> bool {
    move |got, want| (f64::from(got) - want).abs() <= want.abs() * 2f64.powi(-24) * 1.000_001 + abs
}

#[test]
fn colour_photos_take_the_fast_filters() {
    let named = photogrammetry_playground::filter::NAMES;
    let customs: [(&str, Option<f64>); 3] = [
        ("1 0 2\n-1 3 1\n0 1 1\n2 0 -1\n1 0 0", None),
        ("0.1 0.25 -0.3;0.7 1.5 0.2;-0.05 0.4 0.33", Some(0.3)),
        (&"1 ".repeat(15), None),
    ];
    for (name, img, scale) in images() {
        let image = Image::from(&img);
        assert!(image.gray().is_none(), "{name} is not 8-bit");
        let levels = image.levels().expect("its greys are levels");
        assert_eq!(levels.scale, scale, "{name}");
        // the largest grey (tolerances are relative to it)
        let top = f64::from(levels.max) / levels.scale;
        for b in BORDERS {
            let border = ops::border(b).unwrap();
            let mut runs: Vec<(String, Option<Custom>)> =
                named.iter().map(|k| (k.to_string(), None)).collect();
            for (text, d) in customs {
                runs.push(("custom".into(), Some(ops::custom_kernel(text, d).unwrap())));
            }
            for (k, custom) in &runs {
                let c = custom.as_ref().map(|(r, d)| (r.as_slice(), *d));
                let layer = ops::fast_filter(&image, k, border, c).unwrap();
                let kern = ops::kernel(k, c).unwrap();
                let reference = match &kern {
                    Some(kk) => filter::correlate(&img, kk, border),
                    None => filter::median(&img, 3, 3, border),
                };
                let what = format!("{k} {custom:?} {b} {name}");
                let Ok(reference) = reference else {
                    assert!(layer.is_none(), "{what}: the reference has no pixel");
                    continue;
                };
                let layer = layer.expect("the fast path takes a colour photo");
                let at = |c, r| reference.at_input(c, r);
                let Some(kk) = kern else {
                    check(&what, &layer, at, |g, v| {
                        g.to_bits() == (v as f32).to_bits()
                    });
                    continue;
                };
                let rows = kk.numerators().rows();
                let taps: f64 = rows.iter().flatten().map(|v| v.abs()).sum();
                let range = taps * top / kk.divisor().abs();
                let exact = rows.iter().flatten().all(|v| v.fract() == 0.0)
                    && taps * f64::from(levels.max) < 16_777_216.0;
                if exact {
                    check(&what, &layer, at, near(1e-12 * range));
                } else {
                    check(&what, &layer, at, |g, v| {
                        (f64::from(g) - v).abs() <= 1e-6 * range
                    });
                }
            }
        }
    }
}

#[test]
fn colour_photos_take_the_fast_edges() {
    for (name, img, _) in images() {
        let top = img.data().iter().fold(0.0f64, |a, &b| a.max(b));
        for b in BORDERS {
            let border = ops::border(b).unwrap();
            for op in ["sobel", "prewitt"] {
                let layers = ops::fast_edges(&Image::from(&img), op, border).unwrap();
                let (kx, ky) = ops::edge_kernels(op).unwrap();
                let Ok(g) = filter::gradient(&img, &kx, &ky, border) else {
                    assert!(layers.is_none());
                    continue;
                };
                let layers = layers.expect("the fast path takes a colour photo");
                let reg = g.region;
                let pick = |grid: &Grid| {
                    let grid = grid.clone();
                    move |c: usize, r: usize| {
                        reg.contains(c, r)
                            .then(|| grid.get(c - reg.c0, r - reg.r0))
                            .flatten()
                    }
                };
                let what = |l: &str| format!("{op} {l} {b} {name}");
                let tol = near(1e-12 * 8.0 * top);
                check(&what("gx"), &layers[0], pick(&g.gx), &tol);
                check(&what("gy"), &layers[1], pick(&g.gy), &tol);
                check(&what("magnitude"), &layers[2], pick(&g.magnitude), &tol);
                let (gx, gy) = (pick(&g.gx), pick(&g.gy));
                // (where the reference's gradient is zero but for its own f64
                // roundings of the divided greys — a reflected border, a flat
                // square — its direction is those roundings' and the fast
                // path's exact sums give 0: no direction to compare)
                let dir = |c, r| {
                    gx(c, r).zip(gy(c, r)).map(|(x, y): (f64, f64)| {
                        if x.hypot(y) <= 1e-9 * top {
                            f64::NAN
                        } else {
                            y.atan2(x).to_degrees()
                        }
                    })
                };
                check(&what("direction"), &layers[3], dir, |g, v| {
                    let d = (f64::from(g) - v).abs();
                    v.is_nan() || d <= 1e-4 || (d - 360.0).abs() <= 1e-4
                });
            }
        }
    }
}

/// The explained pixel: `exact_at` reads the `f64` greys the layer was
/// computed from (the levels over their scale, bit for bit), and the
/// layer's value is that number within the stated tolerance.
#[test]
fn the_explained_pixel_reads_the_greys_the_layer_was_made_from() {
    let img = colour(33, 29, 21);
    let image = Image::from(&img);
    let levels = image.levels().unwrap();
    for (n, g) in levels.data.iter().zip(img.data()) {
        assert_eq!((f64::from(*n) / levels.scale).to_bits(), g.to_bits());
    }
    let border = ops::border("reflect").unwrap();
    let mean = ops::fast_filter(&image, "gaussian-3", border, None)
        .unwrap()
        .unwrap();
    let op = Op::Filter {
        kernel: "gaussian-3".into(),
        border,
        custom: None,
    };
    for (c, r) in [(0, 0), (16, 14), (32, 28)] {
        let exact = ops::exact_at(&img, &img, &op, "gaussian-3", c, r)
            .unwrap()
            .unwrap();
        assert!(
            near(1e-12 * 255.0)(mean.data[r * 33 + c], exact),
            "({c}, {r})"
        );
    }
}

/// A band of rows with its halo, run on its own (as a pool worker runs it),
/// equals the whole colour photo's rows bit for bit.
#[test]
fn colour_bands_with_their_halo_equal_the_whole_photo() {
    let img = colour(57, 41, 8);
    let (w, h) = (img.width(), img.height());
    for b in BORDERS {
        let border = ops::border(b).unwrap();
        let (rows, d) = ops::custom_kernel(&["1 2 3 2 1"; 7].join("\n"), None).unwrap();
        let mut opsv: Vec<Op> = ["gaussian-5", "median", "log", "mean"]
            .iter()
            .map(|k| Op::Filter {
                kernel: k.to_string(),
                border,
                custom: None,
            })
            .collect();
        opsv.push(Op::Filter {
            kernel: "custom".into(),
            border,
            custom: Some((rows, d)),
        });
        opsv.push(Op::Edges {
            operator: "sobel".into(),
            border,
        });
        for op in &opsv {
            let halo = ops::halo(op).unwrap().unwrap();
            let run = |g: &Grid| -> Vec<Layer> {
                match op {
                    Op::Filter {
                        kernel,
                        border,
                        custom,
                    } => {
                        let c = custom.as_ref().map(|(r, d)| (r.as_slice(), *d));
                        vec![ops::filter_image(g, kernel, *border, c).unwrap()]
                    }
                    Op::Edges { operator, border } => ops::edges(g, operator, *border).unwrap(),
                    _ => unreachable!(),
                }
            };
            let whole = run(&img);
            for (start, end) in [(0, 9), (9, 20), (20, 21), (21, h - 7), (h - 7, h)] {
                let (r0, r1) = (start.saturating_sub(halo), (end + halo).min(h));
                let band = img.window(0, r0, w, r1 - r0).unwrap();
                for (l, wl) in run(&band).iter().zip(&whole) {
                    for r in start..end {
                        for c in 0..w {
                            let got = (r >= r0).then(|| l.at(c, r - r0)).flatten();
                            assert_eq!(
                                got.map(f64::to_bits),
                                wl.at(c, r).map(f64::to_bits),
                                "{op:?} {} band {start}…{end} at ({c}, {r})",
                                l.name
                            );
                        }
                    }
                }
            }
        }
    }
}

/// Greys that are no such numbers (e.g. `f32` samples) keep the reference
/// paths: no levels, the reference's layers.
#[test]
fn other_greys_keep_the_reference_paths() {
    let img = Grid::from_fn(9, 7, |c, r| 0.1 + (c * 7 + r) as f64 / 3.0);
    assert!(ops::levels_of(img.data()).is_none());
    let border = ops::border("replicate").unwrap();
    assert!(ops::fast_filter(&Image::from(&img), "mean", border, None)
        .unwrap()
        .is_none());
    let layer = ops::filter_image(&img, "mean", border, None).unwrap();
    let reference = filter::correlate(
        &img,
        &Kernel::new("k", &vec![vec![1.0; 3]; 3], 9.0).unwrap(),
        border,
    )
    .unwrap();
    check(
        "mean",
        &layer,
        |c, r| reference.at_input(c, r),
        |g, v| g.to_bits() == (v as f32).to_bits(),
    );
}

/// A scale that fits the values `levels_of` looks at first but not one
/// further on is not taken: every value gives its grey back.
#[test]
fn levels_fit_every_value_not_a_sample() {
    let mut v: Vec<f64> = (0..10_000).map(|i| (i % 251) as f64).collect();
    v[5_001] = 0.1;
    let l = ops::levels_of(&v).expect("whole numbers over 1000 … 16000");
    assert_eq!(l.scale, 1000.0);
    for (n, g) in l.data.iter().zip(&v) {
        assert_eq!((f64::from(*n) / l.scale).to_bits(), g.to_bits());
    }
    v[5_001] = std::f64::consts::PI;
    assert!(ops::levels_of(&v).is_none());
}

/// `a` and `b` the same points: pixel and score bit for bit.
fn same_points(what: &str, a: &[ops::Point], b: &[ops::Point]) {
    let key = |p: &ops::Point| (p.c, p.r, p.score.to_bits());
    assert_eq!(
        a.iter().map(key).collect::<Vec<_>>(),
        b.iter().map(key).collect::<Vec<_>>(),
        "{what}: points"
    );
}

/// A layer's `f32` within `rel` (relative) plus half an `f32` step of the
/// reference layer's `f64` value, NaN where it is NaN (the reference
/// layer's `f32`s are its `f64`s rounded: their own half step is allowed).
fn close_layers(what: &str, got: &Layer, want: &Layer, rel: f64) {
    assert_eq!((got.width, got.height), (want.width, want.height), "{what}");
    for (i, (&g, &v)) in got.data.iter().zip(&want.data).enumerate() {
        let (g, v) = (f64::from(g), f64::from(v));
        let ok = (g.is_nan() && v.is_nan())
            || (g - v).abs() <= v.abs() * (2f64.powi(-23) * 1.000_001 + rel);
        assert!(
            ok,
            "{what} at ({}, {}): layer {g}, reference {v}",
            i % got.width,
            i / got.width
        );
    }
}

/// Moravec on a colour photo's levels: the means within `Levels::sum_slack`
/// of the reference's (1e-8 covers it for these photos), the points exactly
/// the reference's (threshold and near-ties decided by the reference's own
/// windows, their scores the reference's means).
#[test]
fn colour_photos_take_the_fast_moravec() {
    for (name, img, scale) in images() {
        let lv = ops::levels_of(img.data()).expect("levels");
        assert_eq!(lv.scale, scale, "{name}");
        for size in [3, 4, 5, 8] {
            let Ok((rl, rp)) = ops::moravec_reference(&img, size, 0.0) else {
                assert!(
                    ops::moravec(Image::from(&img), size, 0.0).is_err(),
                    "{name}"
                );
                continue;
            };
            // thresholds: none, the median mean, one above every mean but a few, one at a mean
            let mut means: Vec<f64> = rl
                .data
                .iter()
                .filter(|v| v.is_finite())
                .map(|&v| f64::from(v))
                .collect();
            means.sort_by(f64::total_cmp);
            let at = ops::moravec_reference(&img, size, 0.0).unwrap();
            let exact_mean = at.1.first().map_or(0.0, |p| p.score);
            for t in [
                0.0,
                means[means.len() / 2],
                means[means.len() * 19 / 20],
                exact_mean,
            ] {
                let what = format!("{name}, Moravec {size}×{size}, threshold {t}");
                let (fl, fp) = ops::moravec(Image::from(&img), size, t).unwrap();
                let (rl, rp) = if t == 0.0 {
                    (rl.clone(), rp.clone())
                } else {
                    ops::moravec_reference(&img, size, t).unwrap()
                };
                close_layers(&what, &fl, &rl, 1e-8);
                same_points(&what, &fp, &rp);
                assert!(
                    t > 0.0 || !fp.is_empty() || name.contains("checkerboard"),
                    "{what}: no points"
                );
            }
        }
    }
}

/// Förstner on a colour photo's levels: `w` and `q` within `10⁻⁸·trace N`
/// and `10⁻⁷` of the reference's (plus the `f32` roundings), and the points
/// with their scores and ellipses, the automatic threshold's `w_min`, and a
/// kept map's points for another threshold exactly the reference's.
#[test]
fn colour_photos_take_the_fast_forstner() {
    use photogrammetry_playground::interest;
    for (name, img, _) in images() {
        let mut found = 0;
        for size in [3, 4, 5, 7] {
            let Ok(map) = interest::forstner_map(&img, size) else {
                assert!(
                    ops::forstner(Image::from(&img), size, 8.0, 0.5, 0.5).is_err(),
                    "{name}"
                );
                continue;
            };
            // the reference's w_min, and the thresholds tried: the photo's own, twice it, 0.5 px
            let mut w: Vec<f64> = map.cells.iter().flatten().map(|m| m.w).collect();
            let k = ops::top_rank(w.len());
            let w_min = *w.select_nth_unstable_by(k, f64::total_cmp).1;
            let sigma_n = 8.0;
            let kept = ops::ForstnerKept::new(Image::from(&img), size).unwrap();
            let auto = kept.auto_threshold(sigma_n);
            assert_eq!(
                auto.map(|a| a.w_min.to_bits()),
                (w_min > 0.0).then(|| w_min.to_bits()),
                "{name} {size}: w_min"
            );
            let own = auto.map_or(0.5, |a| a.threshold_px);
            for (t, q_min) in [(own, 0.5), (2.0 * own, 0.0), (0.5, 0.5)] {
                let what = format!("{name}, Förstner {size}×{size}, T {t}, q_min {q_min}");
                let (fl, fp) = ops::forstner(Image::from(&img), size, sigma_n, t, q_min).unwrap();
                let (rl, rp) = ops::forstner_reference(&img, size, sigma_n, t, q_min).unwrap();
                for (i, m) in map.cells.iter().enumerate() {
                    let (gw, gq) = (f64::from(fl[0].data[i]), f64::from(fl[1].data[i]));
                    let (vw, vq) = (f64::from(rl[0].data[i]), f64::from(rl[1].data[i]));
                    let Some(m) = m else {
                        assert!(
                            gw.is_nan() && gq.is_nan(),
                            "{what}: a value where no window fits"
                        );
                        continue;
                    };
                    let at = (i % img.width(), i / img.width());
                    assert!(
                        (gw - vw).abs() <= vw.abs() * 2f64.powi(-23) + 1e-8 * m.trace,
                        "{what} w at {at:?}: {gw} vs {vw}"
                    );
                    assert!(
                        (gq.is_nan() && vq.is_nan()) || (gq - vq).abs() <= 2f64.powi(-23) + 1e-7,
                        "{what} q at {at:?}: {gq} vs {vq}"
                    );
                }
                assert_eq!(fp, rp, "{what}: points");
                found += fp.len();
            }
            // the kept map's points for another threshold
            let mut kept = kept;
            for t in [own, 0.5 * own] {
                let got = kept.points(sigma_n, t, 0.5).unwrap();
                let (_, want) = ops::forstner_reference(&img, size, sigma_n, t, 0.5).unwrap();
                assert_eq!(got, want, "{name} {size}: kept map's points for T {t}");
            }
        }
        assert!(found > 0 || img.width() < 30, "{name}: no points at all");
    }
}

/// `Levels::cut`: `n ≥ cut` exactly when `n / scale ≥ t` in `f64` (the
/// reference's comparison), at the edges — `t` every grey `n / scale` of a
/// colour photo (0 … 255 000 over 1000), and the `f64` next to it on each
/// side — for the levels around it; and the cut is `⌈scale·t⌉` but where
/// the product rounds across a whole number.
#[test]
fn a_threshold_on_levels_is_the_reference_comparison() {
    let mut moved = 0;
    for scale in [1000.0, 4000.0, 1.0] {
        let l = ops::Levels {
            data: Vec::new(),
            scale,
            max: 0.0,
        };
        let top: u32 = if scale == 1.0 { 65_535 } else { 255_000 };
        for n in (0..=top).step_by(if scale == 4000.0 { 7 } else { 1 }) {
            let g = f64::from(n) / scale;
            for t in [g, g.next_down(), g.next_up(), g - 0.4 / scale] {
                let cut = l.cut(t);
                assert_eq!(cut.fract(), 0.0);
                for m in n.saturating_sub(2)..=n + 2 {
                    let m = m as f32;
                    assert_eq!(
                        m >= cut,
                        f64::from(m) / scale >= t,
                        "scale {scale}, threshold {t}, level {m}: cut {cut}"
                    );
                }
                if f64::from(cut) != (t * scale).ceil().max(0.0) {
                    moved += 1;
                }
            }
        }
    }
    // the plain ceiling is wrong for some greys: the search moves it
    assert!(moved > 0, "{moved}");
    let l = ops::levels_of(&[0.0, 255.0]).unwrap();
    assert_eq!(
        (l.cut(-3.0), l.cut(0.0), l.cut(1e30)),
        (0.0, 0.0, 33_554_432.0)
    );
}

/// Boundary tracing on a colour photo's levels: the region, its boundary
/// (pixels, chain code, area) and length exactly the reference's
/// (`chain::region_at` on the greys, `chain::trace`), thresholds at the
/// greys themselves and beside them.
#[test]
fn colour_photos_take_the_fast_boundary() {
    let mut traced = 0;
    for (name, img, _) in images() {
        let (w, h) = (img.width(), img.height());
        let mid = img.get(w / 2, h / 2).unwrap();
        let levels = ops::levels_of(img.data()).expect("levels");
        for threshold in [-1.0, 60.0, 128.0, mid, mid.next_up(), mid.next_down(), 1e6] {
            for (c, r) in [(0, 0), (w / 2, h / 2), (w - 1, h / 3), (w / 5, h - 1)] {
                let keep = std::cell::OnceCell::new();
                keep.set(Some(levels.clone())).unwrap();
                let image = Image::with_bytes(&img, None).with_levels(&keep);
                let t = ops::boundary(&image, threshold, c, r).unwrap();
                let what = format!("{name} threshold {threshold} at ({c}, {r})");
                let (mask, n) = common::boundary_is_the_reference(&t, &img, threshold, c, r, &what);
                check(
                    &what,
                    &t.region,
                    |cc, rr| mask.get(cc, rr),
                    |g, v| f64::from(g) == v,
                );
                traced += n;
            }
        }
    }
    assert!(traced > 1000, "{traced} boundary pixels");
    // out of the image: the reference's message
    let img = colour(7, 5, 1);
    let e = ops::boundary(&img, 100.0, 7, 0).unwrap_err().to_string();
    assert!(e.contains("(7, 0) is outside the 7×5 image"), "{e}");
}

/// NCC on a colour photo's levels (exact integer sums, `ρ` scale-free):
/// the surface within half an `f32` step plus 10⁻¹² of the reference's
/// `correlate_2d` on the greys, flat windows where the reference's are;
/// the best position and its `ρ` exactly the reference's.
#[test]
fn colour_photos_take_the_fast_ncc() {
    use photogrammetry_playground::correlation;
    use photogrammetry_playground::matching::Model;
    let mut compared = 0;
    for (name, img, _) in images() {
        let (w, h) = (img.width(), img.height());
        for n in [3, 5, 9] {
            if w < n + 2 || h < n + 2 {
                continue;
            }
            let t = ops::Rect {
                c0: (w / 3).min(w - n),
                r0: (h / 3).min(h - n),
                width: n,
                height: n,
            };
            let reach = 6;
            let s0 = (t.c0.saturating_sub(reach), t.r0.saturating_sub(reach));
            let s = ops::Rect {
                c0: s0.0,
                r0: s0.1,
                width: (n + 2 * reach).min(w - s0.0),
                height: (n + 2 * reach).min(h - s0.1),
            };
            // the same photo, and the photo shifted by (1, 2)
            let other = Grid::from_fn(w, h, |cc, rr| {
                img.get((cc + 1).min(w - 1), (rr + 2).min(h - 1)).unwrap()
            });
            for (bname, b) in [("same", &img), ("shifted", &other)] {
                assert!(ops::levels_of(b.data()).is_some(), "{name}: levels");
                let m = ops::correlate(&img, t, b, s, Model::ShiftRadiometric).unwrap();
                let tg = img.window(t.c0, t.r0, n, n).unwrap();
                let sg = b.window(s.c0, s.r0, s.width, s.height).unwrap();
                let want = correlation::correlate_2d(&tg, &sg).unwrap();
                let what = format!("NCC {n}×{n} {bname} {name}");
                assert_eq!(
                    (m.surface.width, m.surface.height),
                    (want.width, want.height),
                    "{what}"
                );
                for j in 0..want.height {
                    for i in 0..want.width {
                        let g = m.surface.rho[j * want.width + i];
                        match want.rho(i, j) {
                            Some(v) => assert!(
                                near(1e-12)(g, v),
                                "{what} ({i}, {j}): layer {g}, reference {v}"
                            ),
                            None => assert!(g.is_nan(), "{what} ({i}, {j}): {g}, flat"),
                        }
                        compared += 1;
                    }
                }
                assert_eq!(m.surface.best, want.best, "{what}");
                assert_eq!(
                    m.surface.best_rho,
                    want.best.and_then(|(i, j)| want.rho(i, j)),
                    "{what}"
                );
            }
        }
    }
    assert!(compared > 2000, "{compared}");
}

/// Resampling a colour photo's levels (rotations through the affine runs,
/// a projective warp pixel by pixel; nearest, bilinear, bicubic), whole
/// and in bands: nearest neighbours the reference's greys rounded to
/// `f32` bit for bit, bilinear and bicubic within half an `f32` step plus
/// 10⁻⁹ of `resample::warp` on the greys (the same expression on `n`,
/// divided by the scale once; the runs' positions along a row differ from
/// the reference's in the last bit).
#[test]
fn colour_photos_take_the_fast_resampling() {
    use photogrammetry_playground::resample::{self as rs, Method};
    let mut compared = 0;
    let worst = std::cell::Cell::new(0.0f64);
    for (name, img, _) in images() {
        let (w, h) = (img.width(), img.height());
        let (ow, oh) = (w + 3, h + 2);
        let (cw, ch) = (w as f64 - 1.0, h as f64 - 1.0);
        let warps: [(&str, Vec<f64>); 4] = [
            ("rotate", vec![7.0, 1.15]),
            ("rotate", vec![-33.0, 0.8]),
            ("rotate", vec![90.0, 1.0]),
            (
                "projective",
                vec![0.3, 0.2, cw * 0.9, 0.1, cw, ch * 0.8, 0.1, ch * 0.95],
            ),
        ];
        for (kind, params) in warps {
            let warp = ops::Warp::new((w, h), kind, &params, ow, oh).unwrap();
            let what = format!("{name} {kind} {params:?}");
            let whole = ops::resample(&img, &warp, 0..oh).unwrap();
            // two bands: each the whole warp's rows
            let cut = oh / 2;
            let top = ops::resample(&img, &warp, 0..cut).unwrap();
            let bottom = ops::resample(&img, &warp, cut..oh).unwrap();
            for (k, (method, mname)) in ops::METHODS.iter().enumerate() {
                let want = rs::warp(&img, ow, oh, |x, y| warp.position(x, y), *method, 0.0);
                let layer = &whole[k];
                assert_eq!(layer.name, *mname);
                check(
                    &format!("{what} {mname}"),
                    layer,
                    |c, r| want.get(c, r),
                    |g, v| {
                        if *method == Method::Nearest {
                            return g.to_bits() == (v as f32).to_bits();
                        }
                        let beyond = (f64::from(g) - v).abs() - v.abs() * 2f64.powi(-24);
                        worst.set(worst.get().max(beyond));
                        near(1e-9)(g, v)
                    },
                );
                let joined: Vec<f32> = [&top[k].data[..], &bottom[k].data[..]].concat();
                assert_eq!(joined, layer.data, "{what} {mname}: bands");
                compared += layer.data.len();
            }
        }
    }
    assert!(compared > 20_000, "{compared}");
    eprintln!(
        "resampling: worst beyond half an f32 step {:e}",
        worst.get()
    );
}

/// A band sent as levels (`Levels::new`, `Image::from_levels`: what the
/// pool's workers get of a colour photo) runs as the photo made from its
/// greys: the same layers bit for bit, its grid the greys bit for bit; and
/// levels that are not whole numbers are refused, naming the value.
#[test]
fn an_image_from_levels_is_the_photo() {
    let img = colour(33, 29, 8);
    let found = ops::levels_of(img.data()).unwrap();
    let keep = std::cell::OnceCell::new();
    keep.set(Some(
        ops::Levels::new(found.data.clone(), found.scale).unwrap(),
    ))
    .unwrap();
    let from = Image::from_levels(33, 29, &keep).unwrap();
    assert_eq!(from.levels(), Some(&found));
    let border = ops::border("reflect").unwrap();
    for kernel in ["mean", "gaussian-5", "median"] {
        let a = ops::filter_image(&from, kernel, border, None).unwrap();
        let b = ops::filter_image(&img, kernel, border, None).unwrap();
        assert_eq!(a, b, "{kernel}");
    }
    let warp = ops::Warp::new((33, 29), "rotate", &[11.0, 1.1], 30, 30).unwrap();
    assert_eq!(
        ops::resample(&from, &warp, 0..30).unwrap(),
        ops::resample(&img, &warp, 0..30).unwrap()
    );
    let bits = |g: &Grid| g.data().iter().map(|v| v.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(from.grid()), bits(&img));
    for (bad, at) in [(0.5, 2), (-1.0, 2), (f32::NAN, 2), (16_777_216.0, 2)] {
        let e = ops::Levels::new(vec![1.0, bad, 3.0], 1000.0)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains(&format!("value {at} is not a whole number")),
            "{e}"
        );
    }
    assert!(ops::Levels::new(vec![1.0], 0.0).is_err());
    assert!(Image::from_levels(33, 28, &keep).is_err());
}
