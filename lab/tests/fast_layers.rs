//! Fast layers against their references at every pixel (issue 31): every
//! operator of the lab's menu on 8-bit images (random and structured,
//! 1×1 to 97×61, every border policy, each operator's parameters) takes
//! the core's fast path, and each layer is tied here to the reference
//! function over the whole image within the tolerance docs/lab.md states:
//!
//! * filters with integer kernels, the median, Sobel/Prewitt `gx`, `gy`
//!   and magnitude, Förstner's `w` and `q`, Moravec's means: the
//!   reference's value rounded to `f32`, bit for bit (`NaN` where it has
//!   none);
//! * custom kernels of fractions: within `10⁻⁶ · Σ|k| · 255 / |divisor|`;
//! * the edge direction: within 10⁻⁴ degrees;
//! * resampling: nearest neighbour exactly, bilinear and bicubic within
//!   10⁻⁴ (relative above 1, absolute below);
//! * the NCC surface: within 10⁻⁶, flat windows where the reference's are;
//! * points (Förstner, Moravec) and the best NCC position: the reference's
//!   exactly (same pixels, same scores, same ellipses).
//!
//! And bands (item 4): each layer-producing operator run on a band of
//! rows with `ops::halo` rows of real neighbours gives the whole image's
//! rows (and points) at every pixel.
//!
//! Natively (`cargo test`) and as wasm with `+simd128` in Node (the lab's
//! SIMD loops: `RUSTFLAGS="-C target-feature=+simd128" cargo test --target
//! wasm32-unknown-unknown --target-dir target/simd128 -p photogrammetry-lab
//! --test fast_layers`).

mod common;

use common::random;
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use photogrammetry_lab::ops::{self, Image, Layer, Op, Rect};
use photogrammetry_playground::correlation;
use photogrammetry_playground::filter::{self, Kernel};
use photogrammetry_playground::matching::Model;
use photogrammetry_playground::raster::{Border, Grid};
use photogrammetry_playground::resample::{self, Method};

/// Random images and structured ones: a checkerboard of 4-pixel squares
/// (exact corners, ties), ramps with a flat block, a disc.
fn images() -> Vec<(String, Grid)> {
    let mut out = Vec::new();
    for (k, &(w, h)) in [(1, 1), (7, 5), (64, 48), (97, 61)].iter().enumerate() {
        out.push((format!("random {w}×{h}"), random(w, h, 7 + k as u64)));
    }
    out.push((
        "checkerboard 64×48".into(),
        Grid::from_fn(64, 48, |c, r| {
            if (c / 4 + r / 4) % 2 == 0 {
                30.0
            } else {
                220.0
            }
        }),
    ));
    out.push((
        "ramps 97×61".into(),
        Grid::from_fn(97, 61, |c, r| {
            if (20..40).contains(&c) && (10..30).contains(&r) {
                128.0
            } else {
                ((2 * c + 3 * r) % 256) as f64
            }
        }),
    ));
    out.push((
        "disc 33×29".into(),
        Grid::from_fn(33, 29, |c, r| {
            let (dx, dy) = (c as f64 - 16.0, r as f64 - 14.0);
            if dx * dx + dy * dy < 81.0 {
                200.0
            } else {
                40.0
            }
        }),
    ));
    out
}

const BORDERS: [&str; 4] = ["replicate", "reflect", "zero", "crop"];

/// `layer` against a reference `f64` grid over `region`-less whole
/// coordinates: `want(c, r)` (None: no value there), `ok(got, want)`.
fn check(
    what: &str,
    layer: &Layer,
    w: usize,
    h: usize,
    want: impl Fn(usize, usize) -> Option<f64>,
    ok: impl Fn(f32, f64) -> bool,
) {
    for r in 0..h {
        for c in 0..w {
            match (layer.at(c, r), want(c, r)) {
                (Some(_), Some(v)) => {
                    let got = layer.data[(r - layer.r0) * layer.width + (c - layer.c0)];
                    assert!(
                        ok(got, v),
                        "{what} at ({c}, {r}): layer {got}, reference {v}"
                    );
                }
                (None, None) => {}
                (g, v) => panic!("{what} at ({c}, {r}): layer {g:?}, reference {v:?}"),
            }
        }
    }
}

/// The reference's value rounded to `f32`, bit for bit.
fn rounded(got: f32, want: f64) -> bool {
    got.to_bits() == (want as f32).to_bits()
}

fn within(tol: f64) -> impl Fn(f32, f64) -> bool {
    move |got, want| (f64::from(got) - want).abs() <= tol * want.abs().max(1.0)
}

#[test]
fn filters_equal_the_reference_rounded_to_f32() {
    let named = photogrammetry_playground::filter::NAMES;
    let customs: [(&str, Option<f64>); 4] = [
        ("1 1 1 1 1\n1 1 1 1 1\n1 1 1 1 1", None),
        ("1 0 2\n-1 3 1\n0 1 1\n2 0 -1\n1 0 0", None),
        ("0.1 0.25 -0.3;0.7 1.5 0.2;-0.05 0.4 0.33", Some(0.3)),
        (&"1 ".repeat(15), None),
    ];
    for (name, img) in images() {
        let (w, h) = (img.width(), img.height());
        let image = Image::from(&img);
        assert!(image.gray().is_some(), "{name} is 8-bit");
        for b in BORDERS {
            let border = ops::border(b).unwrap();
            for k in named {
                let layer = ops::fast_filter(&image, k, border, None).unwrap();
                let reference = match ops::kernel(k, None).unwrap() {
                    Some(kk) => filter::correlate(&img, &kk, border),
                    None => filter::median(&img, 3, 3, border),
                };
                let Ok(reference) = reference else {
                    assert!(
                        layer.is_none(),
                        "{k} {b} {name}: the reference has no pixel"
                    );
                    continue;
                };
                let layer = layer.expect("the fast path takes an 8-bit image");
                let at = |c, r| reference.at_input(c, r);
                check(&format!("{k} {b} {name}"), &layer, w, h, at, rounded);
            }
            for (text, d) in customs {
                let (rows, d) = ops::custom_kernel(text, d).unwrap();
                let kernel = Kernel::new("k", &rows, d).unwrap();
                let integer = rows.iter().flatten().all(|v| v.fract() == 0.0);
                let scale = rows.iter().flatten().map(|v| v.abs()).sum::<f64>() * 255.0 / d.abs();
                let layer = ops::fast_filter(&image, "custom", border, Some((&rows, d))).unwrap();
                let Ok(reference) = filter::correlate(&img, &kernel, border) else {
                    assert!(layer.is_none());
                    continue;
                };
                let at = |c, r| reference.at_input(c, r);
                let what = format!("custom {text:?} {b} {name}");
                let layer = layer.unwrap();
                if integer {
                    check(&what, &layer, w, h, at, rounded);
                } else {
                    check(&what, &layer, w, h, at, |g, v| {
                        (f64::from(g) - v).abs() <= 1e-6 * scale
                    });
                }
            }
        }
    }
}

#[test]
fn edges_equal_the_reference() {
    for (name, img) in images() {
        let (w, h) = (img.width(), img.height());
        for b in BORDERS {
            let border = ops::border(b).unwrap();
            for op in ["sobel", "prewitt"] {
                let layers = ops::fast_edges(&Image::from(&img), op, border).unwrap();
                let (kx, ky) = ops::edge_kernels(op).unwrap();
                let Ok(g) = filter::gradient(&img, &kx, &ky, border) else {
                    assert!(layers.is_none());
                    continue;
                };
                let layers = layers.unwrap();
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
                check(&what("gx"), &layers[0], w, h, pick(&g.gx), rounded);
                check(&what("gy"), &layers[1], w, h, pick(&g.gy), rounded);
                check(
                    &what("magnitude"),
                    &layers[2],
                    w,
                    h,
                    pick(&g.magnitude),
                    rounded,
                );
                let (gx, gy) = (pick(&g.gx), pick(&g.gy));
                let dir = |c, r| {
                    gx(c, r)
                        .zip(gy(c, r))
                        .map(|(x, y): (f64, f64)| y.atan2(x).to_degrees())
                };
                check(&what("direction"), &layers[3], w, h, dir, |g, v| {
                    (f64::from(g) - v).abs() <= 1e-4
                });
            }
        }
    }
}

/// Every magnitude the 8-bit edge kernels can give (|gx|, |gy| ≤ 4·255):
/// `√(gx² + gy²)` in `f32` is the reference's `hypot` rounded to `f32`.
#[test]
fn every_edge_magnitude_rounds_as_the_reference() {
    for x in 0..=1020i32 {
        for y in 0..=x {
            let (fx, fy) = (x as f32, y as f32);
            let fast = (fx * fx + fy * fy).sqrt();
            let want = f64::from(x).hypot(f64::from(y)) as f32;
            assert_eq!(fast.to_bits(), want.to_bits(), "({x}, {y})");
        }
    }
}

#[test]
fn interest_maps_and_points_equal_the_reference() {
    // points compared (the lists must not all be empty)
    let (mut nf, mut nm) = (0, 0);
    for (name, img) in images() {
        let (w, h) = (img.width(), img.height());
        for size in [3, 4, 5, 7] {
            for (sigma, t, q) in [(8.0, 0.5, 0.5), (2.0, 1.5, 0.0), (8.0, 3.0, 0.75)] {
                let fast = ops::forstner(&img, size, sigma, t, q);
                let Ok((rl, rp)) = ops::forstner_reference(&img, size, sigma, t, q) else {
                    assert!(
                        fast.is_err(),
                        "Förstner {size} {name}: the reference refuses it"
                    );
                    continue;
                };
                let (ls, ps) = fast.unwrap();
                for (l, r) in ls.iter().zip(&rl) {
                    let what = format!("Förstner {size} {} {name}", l.name);
                    check(
                        &what,
                        l,
                        w,
                        h,
                        |c, rr| r.at(c, rr),
                        |g, v| g.to_bits() == (v as f32).to_bits(),
                    );
                }
                // the reference's layers are its f64 values rounded; the
                // exact values are the window functions' (exact_at)
                let op = Op::Forstner { size };
                for (c, r) in [(w / 2, h / 2), (3, 3)] {
                    let m = photogrammetry_playground::interest::window_at(&img, c, r, size).map(
                        |win| {
                            photogrammetry_playground::interest::forstner(&win)
                                .unwrap()
                                .measures
                        },
                    );
                    assert_eq!(
                        ops::exact_at(&img, &img, &op, "w", c, r).unwrap(),
                        m.map(|m| m.w)
                    );
                    if let (Some(m), Some(v)) = (m, ls[0].at(c, r)) {
                        assert_eq!(v, f64::from(m.w as f32));
                    }
                }
                assert_eq!(ps, rp, "Förstner {size} σn {sigma} T {t} q {q} {name}");
                nf += ps.len();
            }
        }
        // the photo's automatic threshold: the reference's 99.9th percentile of w
        for size in [3, 5, 7] {
            let Ok(map) = photogrammetry_playground::interest::forstner_map(&img, size) else {
                continue;
            };
            let mut ws: Vec<f64> = map.cells.iter().flatten().map(|m| m.w).collect();
            ws.sort_by(f64::total_cmp);
            let k = ((1.0 - ops::W_TOP_SHARE) * (ws.len() - 1) as f64).floor() as usize;
            let kept = ops::ForstnerKept::new(&img, size).unwrap();
            let got = kept.auto_threshold(8.0).map(|a| a.w_min);
            assert_eq!(got, (ws[k] > 0.0).then_some(ws[k]), "w_min {size} {name}");
        }
        for size in [3, 4, 5, 8] {
            for threshold in [0.0, 500.0, 4000.0] {
                let fast = ops::moravec(&img, size, threshold);
                let Ok((rl, rp)) = ops::moravec_reference(&img, size, threshold) else {
                    assert!(fast.is_err(), "Moravec {size} {name}");
                    continue;
                };
                let (l, ps) = fast.unwrap();
                check(
                    &format!("Moravec {size} {name}"),
                    &l,
                    w,
                    h,
                    |c, r| rl.at(c, r),
                    |g, v| g.to_bits() == (v as f32).to_bits(),
                );
                assert_eq!(ps, rp, "Moravec {size} threshold {threshold} {name}");
                nm += ps.len();
            }
        }
    }
    assert!(
        nf > 1000 && nm > 1000,
        "{nf} Förstner points, {nm} Moravec points"
    );
}

#[test]
fn resampling_equals_the_reference() {
    for (name, img) in images() {
        let (w, h) = (img.width(), img.height());
        let (fw, fh) = (w as f64 - 1.0, h as f64 - 1.0);
        let mut warps: Vec<(String, &str, Vec<f64>, usize, usize)> = [
            (0.0, 1.0),
            (0.0, 2.0),
            (7.0, 1.15),
            (90.0, 1.0),
            (-33.0, 0.6),
            (180.0, 3.0),
        ]
        .iter()
        .map(|&(a, s)| (format!("rotate {a}° ×{s}"), "rotate", vec![a, s], w, h))
        .collect();
        if w > 4 && h > 4 {
            // a quadrilateral inside the image, rectified to 23 × 17
            let q = vec![0.5, 1.0, fw - 1.5, 0.25, fw - 0.5, fh - 1.0, 1.25, fh - 0.5];
            warps.push(("projective".into(), "projective", q, 23, 17));
        }
        for (what, kind, params, ow, oh) in warps {
            let warp = ops::Warp::new((w, h), kind, &params, ow, oh).unwrap();
            let layers = ops::resample(&img, &warp, 0..oh).unwrap();
            for (layer, (method, mname)) in layers.iter().zip(ops::METHODS) {
                let reference =
                    resample::warp(&img, ow, oh, |x, y| warp.position(x, y), method, 0.0);
                let at = |c, r| reference.get(c, r);
                let label = format!("{what} {mname} {name}");
                match method {
                    Method::Nearest => check(&label, layer, ow, oh, at, |g, v| f64::from(g) == v),
                    _ => check(&label, layer, ow, oh, at, within(1e-4)),
                }
            }
        }
    }
}

#[test]
fn ncc_surfaces_and_best_positions_equal_the_reference() {
    for (name, img) in images() {
        let (w, h) = (img.width(), img.height());
        for n in [1, 3, 5, 9, 15] {
            if n + 2 > w || n + 2 > h || n % 2 == 0 || n < 3 {
                continue;
            }
            let (c, r) = (w / 3, h / 3);
            let t = Rect {
                c0: c.min(w - n),
                r0: r.min(h - n),
                width: n,
                height: n,
            };
            let reach = 6;
            let s0 = (t.c0.saturating_sub(reach), t.r0.saturating_sub(reach));
            let s = Rect {
                c0: s0.0,
                r0: s0.1,
                width: (n + 2 * reach).min(w - s0.0),
                height: (n + 2 * reach).min(h - s0.1),
            };
            // the same image and a shifted, brighter copy
            let other = Grid::from_fn(w, h, |cc, rr| {
                img.get((cc + 1).min(w - 1), (rr + 2).min(h - 1))
                    .unwrap()
                    .min(200.0)
                    + 3.0
            });
            for (bname, b) in [("same", &img), ("shifted", &other)] {
                let m = ops::correlate(&img, t, b, s, Model::ShiftRadiometric).unwrap();
                let tg = img.window(t.c0, t.r0, n, n).unwrap();
                let sg = b.window(s.c0, s.r0, s.width, s.height).unwrap();
                let want = correlation::correlate_2d(&tg, &sg).unwrap();
                let what = format!("NCC {n}×{n} {bname} {name}");
                assert_eq!(
                    (m.surface.width, m.surface.height),
                    (want.width, want.height)
                );
                for j in 0..want.height {
                    for i in 0..want.width {
                        match (m.surface.rho(i, j), want.rho(i, j)) {
                            (Some(g), Some(v)) => {
                                assert!((g - v).abs() <= 1e-6, "{what} ({i}, {j}): {g} vs {v}")
                            }
                            (None, None) => {}
                            (g, v) => panic!("{what} ({i}, {j}): {g:?} vs {v:?}"),
                        }
                    }
                }
                assert_eq!(m.surface.best, want.best, "{what}");
                assert_eq!(
                    m.surface.best_rho,
                    want.best.and_then(|(i, j)| want.rho(i, j)),
                    "{what}"
                );
                // the inspector's exact ρ of a surface pixel
                if let Some((i, j)) = want.best {
                    let op = Op::Correlation {
                        template: t,
                        search: s,
                    };
                    let (cc, rr) = (s.c0 + i + n / 2, s.r0 + j + n / 2);
                    assert_eq!(
                        ops::exact_at(&img, b, &op, "ncc", cc, rr).unwrap(),
                        want.rho(i, j)
                    );
                }
            }
        }
    }
}

#[test]
fn boundaries_equal_the_reference() {
    let mut traced = 0;
    for (name, img) in images() {
        let (w, h) = (img.width(), img.height());
        for threshold in [-1.0, 100.0, 128.0, 128.5, 300.0] {
            for (c, r) in [(0, 0), (w / 2, h / 2), (w - 1, h / 3), (w / 5, h - 1)] {
                let t = ops::boundary(&img, threshold, c, r).unwrap();
                let what = format!("{name} threshold {threshold} at ({c}, {r})");
                let (mask, n) = common::boundary_is_the_reference(&t, &img, threshold, c, r, &what);
                check(&what, &t.region, w, h, |cc, rr| mask.get(cc, rr), rounded);
                traced += n;
            }
        }
    }
    assert!(traced > 1000, "{traced} boundary pixels");
}

/// The rows `start … end` of a band run on `img`'s rows `start − halo …
/// end + halo` (clipped), against the whole image's.
#[test]
fn bands_with_their_halo_equal_the_whole_image() {
    let img = random(97, 61, 99);
    let board = Grid::from_fn(64, 48, |c, r| {
        if (c / 4 + r / 4) % 2 == 0 {
            30.0
        } else {
            220.0
        }
    });
    let op_runs: Vec<(Op, &str)> = {
        let mut v = Vec::new();
        for b in BORDERS {
            let border = ops::border(b).unwrap();
            for k in ["gaussian-5", "median", "log"] {
                v.push((
                    Op::Filter {
                        kernel: k.into(),
                        border,
                        custom: None,
                    },
                    b,
                ));
            }
            let (rows, d) = ops::custom_kernel(&["1 2 3 2 1"; 7].join("\n"), None).unwrap();
            v.push((
                Op::Filter {
                    kernel: "custom".into(),
                    border,
                    custom: Some((rows, d)),
                },
                b,
            ));
            v.push((
                Op::Edges {
                    operator: "sobel".into(),
                    border,
                },
                b,
            ));
        }
        for size in [3, 4, 5, 7] {
            v.push((Op::Forstner { size }, ""));
            v.push((Op::Moravec { size }, ""));
        }
        v
    };
    for grid in [&img, &board] {
        let (w, h) = (grid.width(), grid.height());
        for (op, b) in &op_runs {
            let halo = ops::halo(op).unwrap().expect("a banded operator");
            let run = |g: &Grid| -> (Vec<Layer>, Vec<ops::Point>) {
                match op {
                    Op::Filter {
                        kernel,
                        border,
                        custom,
                    } => {
                        let c = custom.as_ref().map(|(r, d)| (r.as_slice(), *d));
                        (
                            vec![ops::filter_image(g, kernel, *border, c).unwrap()],
                            vec![],
                        )
                    }
                    Op::Edges { operator, border } => {
                        (ops::edges(g, operator, *border).unwrap(), vec![])
                    }
                    Op::Forstner { size } => ops::forstner(g, *size, 8.0, 0.8, 0.5).unwrap(),
                    Op::Moravec { size } => {
                        let (l, p) = ops::moravec(g, *size, 300.0).unwrap();
                        (vec![l], p)
                    }
                    _ => unreachable!(),
                }
            };
            let (whole, points) = run(grid);
            for (start, end) in [(0, 9), (9, 20), (20, 21), (21, h - 7), (h - 7, h)] {
                let (r0, r1) = (start.saturating_sub(halo), (end + halo).min(h));
                let band = grid.window(0, r0, w, r1 - r0).unwrap();
                let (bl, bp) = run(&band);
                for (l, wl) in bl.iter().zip(&whole) {
                    for r in start..end {
                        for c in 0..w {
                            let got = (r >= r0).then(|| l.at(c, r - r0)).flatten();
                            assert_eq!(
                                got.map(f64::to_bits),
                                wl.at(c, r).map(f64::to_bits),
                                "{op:?} {b} {} band {start}…{end} (halo {halo}) at ({c}, {r})",
                                l.name
                            );
                        }
                    }
                }
                let mine: Vec<_> = bp
                    .iter()
                    .map(|p| ops::Point { r: p.r + r0, ..*p })
                    .filter(|p| (start..end).contains(&p.r))
                    .collect();
                let want: Vec<_> = points
                    .iter()
                    .filter(|p| (start..end).contains(&p.r))
                    .copied()
                    .collect();
                assert_eq!(mine, want, "{op:?} points, band {start}…{end}");
            }
        }
    }
    // resampling runs by bands of output rows over the whole input
    for (kind, params, ow, oh) in [
        ("rotate", vec![7.0, 1.15], 97, 61),
        (
            "projective",
            vec![3.0, 2.0, 90.0, 4.0, 95.0, 58.0, 1.0, 55.0],
            40,
            30,
        ),
    ] {
        let warp = ops::Warp::new((97, 61), kind, &params, ow, oh).unwrap();
        let whole = ops::resample(&img, &warp, 0..oh).unwrap();
        for (start, end) in [(0, 5), (5, 17), (17, oh)] {
            let band = ops::resample(&img, &warp, start..end).unwrap();
            for (l, wl) in band.iter().zip(&whole) {
                assert_eq!(l.r0, start);
                for r in start..end {
                    for c in 0..ow {
                        assert_eq!(
                            l.at(c, r).map(f64::to_bits),
                            wl.at(c, r).map(f64::to_bits),
                            "{kind} {} ({c}, {r})",
                            l.name
                        );
                    }
                }
            }
        }
    }
    // operators that do not band say so
    let op = Op::Correlation {
        template: Rect {
            c0: 0,
            r0: 0,
            width: 3,
            height: 3,
        },
        search: Rect {
            c0: 0,
            r0: 0,
            width: 9,
            height: 9,
        },
    };
    assert_eq!(ops::halo(&op).unwrap(), None);
}

#[test]
fn images_that_are_not_8_bit_take_the_reference() {
    let img = Grid::from_fn(20, 15, |c, r| (c * r) as f64 / 7.0);
    assert!(Image::from(&img).gray().is_none());
    let border = Border::Replicate;
    let l = ops::filter_image(&img, "mean", border, None).unwrap();
    let want = filter::correlate(&img, &filter::mean3(), border).unwrap();
    check(
        "mean of fractions",
        &l,
        20,
        15,
        |c, r| want.at_input(c, r),
        rounded,
    );
    let (ls, ps) = ops::forstner(&img, 5, 2.0, 2.0, 0.0).unwrap();
    let (rl, rp) = ops::forstner_reference(&img, 5, 2.0, 2.0, 0.0).unwrap();
    assert_eq!(ps, rp);
    check(
        "w of fractions",
        &ls[0],
        20,
        15,
        |c, r| rl[0].at(c, r),
        |g, v| g.to_bits() == (v as f32).to_bits(),
    );
}

/// An image made from its bytes alone (`Image::from_bytes`: a band of an
/// 8-bit photo in a pool worker, no `f64` grid built) gives every operator
/// the same layers and points as the image from its grid, and the
/// reference paths that need a grid (the region of a boundary, the crop
/// border of a 1-pixel image) get the one built from the bytes.
#[test]
fn images_from_bytes_alone_equal_images_from_their_grid() {
    for (name, img) in images() {
        let bytes = img.to_u8().unwrap();
        let (w, h) = (img.width(), img.height());
        let b = || Image::from_bytes(w, h, &bytes).unwrap();
        assert_eq!(b().grid(), &img, "{name}: the grid built from the bytes");
        for border in [Border::Replicate, Border::Crop] {
            for kernel in ["mean", "gaussian-5", "median", "log"] {
                let got = ops::filter_image(b(), kernel, border, None);
                let want = ops::filter_image(&img, kernel, border, None);
                same(got, want, format!("{name}: {kernel} {border:?}"));
            }
            let got = ops::edges(b(), "sobel", border);
            same(
                got,
                ops::edges(&img, "sobel", border),
                format!("{name}: sobel"),
            );
        }
        let got = ops::forstner(b(), 5, 2.0, 0.5, 0.5);
        same(
            got,
            ops::forstner(&img, 5, 2.0, 0.5, 0.5),
            format!("{name}: Förstner"),
        );
        let got = ops::moravec(b(), 4, 100.0);
        same(
            got,
            ops::moravec(&img, 4, 100.0),
            format!("{name}: Moravec"),
        );
        let got = ops::boundary(b(), 128.0, w / 2, h / 2).map(|t| (t.region, t.boundary.code));
        let want = ops::boundary(&img, 128.0, w / 2, h / 2).map(|t| (t.region, t.boundary.code));
        same(got, want, format!("{name}: boundary"));
    }
    assert!(Image::from_bytes(3, 2, &[1, 2, 3, 4, 5]).is_err());
    assert!(Image::from_bytes(0, 0, &[]).is_err());
}

/// Equal results (or the same error), NaN equal to NaN (layers mark "no value" with it): the
/// same `Debug` text, which prints every `f32` and `f64` exactly.
fn same<T: std::fmt::Debug>(got: T, want: T, what: String) {
    let (g, w) = (format!("{got:?}"), format!("{want:?}"));
    assert!(g == w, "{what}: {g} != {w}");
}
