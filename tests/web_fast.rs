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
            let (mut gx, mut gy, mut mag) = (
                vec![0.0f32; w * h],
                vec![0.0f32; w * h],
                vec![0.0f32; w * h],
            );
            fast::sobel(img, border, &mut gx, &mut gy, &mut mag).unwrap();
            let reg = g.region;
            for r in 0..reg.height {
                for c in 0..reg.width {
                    let i = (r + reg.r0) * w + c + reg.c0;
                    let at = |grid: &photogrammetry_playground::raster::Grid| {
                        grid.get(c, r).unwrap_or(f64::NAN)
                    };
                    assert_eq!(
                        f64::from(gx[i]),
                        at(&g.gx),
                        "gx {w}×{h} {border:?} ({c}, {r})"
                    );
                    assert_eq!(
                        f64::from(gy[i]),
                        -at(&g.gy),
                        "gy {w}×{h} {border:?} ({c}, {r})"
                    );
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

#[test]
fn forstner_wq_equals_the_window_operator() {
    use photogrammetry_playground::interest::{self, fast as ifast, Measures, Sums};
    for (k, &(w, h)) in SIZES.iter().enumerate() {
        let bytes = random_image(w, h, 300 + k as u64);
        let img = Gray::new("img", &bytes, w, h).unwrap();
        let grid = img.to_grid();
        let (mut wo, mut qo) = (vec![0.0f32; w * h], vec![0.0f32; w * h]);
        ifast::forstner_wq(img, 5, &mut wo, &mut qo).unwrap();
        // plain reference everywhere: replicated central differences, the
        // 5×5 sums of the replicated products, the core's Measures
        let px = |c: isize, r: isize| grid.at(c, r, Border::Replicate).unwrap_or(0.0);
        let grad = |c: isize, r: isize| {
            let (c, r) = (c.clamp(0, w as isize - 1), r.clamp(0, h as isize - 1));
            (
                (px(c + 1, r) - px(c - 1, r)) / 2.0,
                (px(c, r + 1) - px(c, r - 1)) / 2.0,
            )
        };
        // the core's whole-image map (7×7 windows: 5×5 gradients) where it fits
        let map = interest::forstner_map(&grid, 7).ok();
        for r in 0..h as isize {
            for c in 0..w as isize {
                let mut s = Sums::default();
                for j in -2..=2 {
                    for i in -2..=2 {
                        let (gx, gy) = grad(c + i, r + j);
                        s.gx2 += gx * gx;
                        s.gy2 += gy * gy;
                        s.gxgy += gx * gy;
                    }
                }
                let m = Measures::from_sums(&s, 25);
                let i = r as usize * w + c as usize;
                let what = format!("{w}×{h} at ({c}, {r})");
                assert!(close(wo[i], m.w), "w {what}: {} vs {}", wo[i], m.w);
                assert!(close(qo[i], m.q.unwrap_or(0.0)), "q {what}");
                if let Some(mm) = map.as_ref().and_then(|m| m.get(c as usize, r as usize)) {
                    assert!(close(wo[i], mm.w), "w (map) {what}");
                    assert!(close(qo[i], mm.q.unwrap_or(0.0)), "q (map) {what}");
                }
            }
        }
    }
    let bytes = random_image(9, 9, 1);
    let img = Gray::new("img", &bytes, 9, 9).unwrap();
    let mut o = vec![0.0f32; 81];
    assert!(ifast::forstner_wq(img, 4, &mut o.clone(), &mut o).is_err());
}

#[test]
fn moravec_equals_moravec_map_exactly() {
    use photogrammetry_playground::interest::{self, fast as ifast};
    for (k, &(w, h)) in SIZES.iter().enumerate() {
        let bytes = random_image(w, h, 700 + k as u64);
        let img = Gray::new("img", &bytes, w, h).unwrap();
        let grid = img.to_grid();
        for size in [3, 4, 5, 8] {
            let mut out = vec![0.0f64; w * h];
            let fast = ifast::moravec(img, size, &mut out);
            let Ok(map) = interest::moravec_map(&grid, size) else {
                assert!(
                    fast.is_err(),
                    "{w}×{h} size {size}: the reference refuses it"
                );
                continue;
            };
            fast.unwrap();
            for r in 0..h {
                for c in 0..w {
                    let got = out[r * w + c];
                    match map.get(c, r) {
                        Some(want) => assert_eq!(got, want, "{w}×{h} size {size} at ({c}, {r})"),
                        None => assert!(got.is_nan(), "{w}×{h} size {size} at ({c}, {r}): {got}"),
                    }
                }
            }
        }
    }
}

#[test]
fn affine_warps_equal_resample_warp() {
    use photogrammetry_playground::resample::{self, fast as rfast, Method};
    for (k, &(w, h)) in SIZES.iter().enumerate() {
        let bytes = random_image(w, h, 400 + k as u64);
        let img = Gray::new("img", &bytes, w, h).unwrap();
        let grid = img.to_grid();
        let mut rng = Rng(k as u64);
        let (cx, cy) = ((w as f64 - 1.0) / 2.0, (h as f64 - 1.0) / 2.0);
        let maps = [
            // the benchmark's: 7° and 1.15 about the centre
            {
                let a = 7f64.to_radians();
                let (ca, sa) = (a.cos() / 1.15, a.sin() / 1.15);
                [
                    [ca, sa, cx - ca * cx - sa * cy],
                    [-sa, ca, cy + sa * cx - ca * cy],
                ]
            },
            // identity and a pure shift (positions on pixel centres)
            [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            [[1.0, 0.0, 0.5], [0.0, 1.0, -1.25]],
            // a random one, flipped
            {
                let f = |r: &mut Rng| r.below(2001) as f64 / 1000.0 - 1.0;
                [
                    [f(&mut rng), f(&mut rng), cx],
                    [f(&mut rng), -f(&mut rng), cy],
                ]
            },
        ];
        let (ow, oh) = (w + 3, h.max(2) - 1);
        for m in maps {
            let map = |x: f64, y: f64| {
                (
                    m[0][0] * x + m[0][1] * y + m[0][2],
                    m[1][0] * x + m[1][1] * y + m[1][2],
                )
            };
            for (method, a) in [
                (Method::Bilinear, 0.0),
                (Method::Bicubic, resample::SEED_A),
                (Method::Bicubic, -0.75),
                (Method::Nearest, 0.0),
            ] {
                let mut out = vec![0.0f32; ow * oh];
                rfast::warp_affine(img, &m, method, a, -1.0, (ow, oh), &mut out).unwrap();
                for r in 0..oh {
                    for c in 0..ow {
                        let (x, y) = map(c as f64, r as f64);
                        let want = match method {
                            Method::Bicubic => resample::bicubic(&grid, x, y, a).map(|b| b.value),
                            _ => resample::value_at(&grid, x, y, method),
                        }
                        .unwrap_or(-1.0);
                        let got = out[r * ow + c];
                        assert!(
                            close(got, want),
                            "{method:?} a={a} {w}×{h} map {m:?} at ({c}, {r}): fast {got}, reference {want}"
                        );
                    }
                }
                if method == Method::Bilinear {
                    let whole = resample::warp(&grid, ow, oh, map, method, -1.0);
                    for (g, want) in out.iter().zip(whole.data()) {
                        assert!(close(*g, *want));
                    }
                }
            }
        }
    }
}

#[test]
fn zncc_equals_correlate_2d() {
    use photogrammetry_playground::correlation::{self, fast as cfast};
    // fixed cases, then every shared size as the search image with a
    // template of about a third of it (odd and even, 1×1 up) and one of
    // up to 21×21 (the reference's product budget caps the template)
    let mut cases = vec![
        (1, 1, 1, 1),
        (7, 5, 3, 3),
        (40, 31, 21, 21),
        (33, 20, 9, 5),
        (64, 9, 17, 3),
        (25, 25, 25, 25),
    ];
    for (k, &(w, h)) in SIZES.iter().enumerate() {
        cases.push((w, h, (w / 3).clamp(1, 15) + k % 2, (h / 3).clamp(1, 11)));
        cases.push((w, h, w.min(21), h.min(21)));
    }
    let cases: Vec<_> = cases
        .into_iter()
        .map(|(sw, sh, tw, th)| (sw, sh, tw.min(sw), th.min(sh)))
        .collect();
    for (k, &(sw, sh, tw, th)) in cases.iter().enumerate() {
        let s = random_image(sw, sh, 500 + k as u64);
        // the template cut from the search image (peak ρ = 1) and a random one
        let (tc, tr) = ((sw - tw) / 2, (sh - th) / 2);
        let cut: Vec<u8> = (0..th)
            .flat_map(|r| s[(tr + r) * sw + tc..(tr + r) * sw + tc + tw].to_vec())
            .collect();
        for t in [cut, random_image(tw, th, 600 + k as u64)] {
            let sg = Gray::new("s", &s, sw, sh).unwrap();
            let tg = Gray::new("t", &t, tw, th).unwrap();
            let (ow, oh) = (sw - tw + 1, sh - th + 1);
            let mut out = vec![0.0f32; ow * oh];
            let peak = cfast::zncc(sg, tg, &mut out).unwrap();
            let reference = correlation::correlate_2d(&tg.to_grid(), &sg.to_grid()).unwrap();
            for r in 0..oh {
                for c in 0..ow {
                    let got = out[r * ow + c];
                    match reference.rho(c, r) {
                        Some(want) => assert!(close(got, want), "({c}, {r}): {got} vs {want}"),
                        None => assert!(got.is_nan(), "({c}, {r}) flat: {got}"),
                    }
                }
            }
            // the same best position, unless two ρ tie within rounding
            if let (Some(p), Some((bc, br))) = (peak, reference.best) {
                let want = reference.rho(bc, br).unwrap_or(0.0);
                assert!(close(p.rho, want));
                assert!((p.c, p.r) == (bc, br) || (f64::from(p.rho) - want).abs() < 1e-6);
            } else {
                assert_eq!(peak.is_some(), reference.best.is_some());
            }
        }
    }
}

/// Plain reference for the borders: labels of 8-connected foreground and
/// 4-connected background components (background connected to outside the
/// image is one component, label 0).
fn components(img: &[u8], w: usize, h: usize) -> (Vec<usize>, Vec<usize>) {
    let fg = |c: isize, r: isize| {
        c >= 0
            && r >= 0
            && (c as usize) < w
            && (r as usize) < h
            && img[r as usize * w + c as usize] != 0
    };
    let mut fl = vec![usize::MAX; w * h];
    let mut bl = vec![usize::MAX; w * h];
    let mut next = (1, 1);
    for start in 0..w * h {
        let is_fg = img[start] != 0;
        let labels = if is_fg { &mut fl } else { &mut bl };
        if labels[start] != usize::MAX {
            continue;
        }
        let steps: &[(isize, isize)] = if is_fg {
            &[
                (1, 0),
                (-1, 0),
                (0, 1),
                (0, -1),
                (1, 1),
                (1, -1),
                (-1, 1),
                (-1, -1),
            ]
        } else {
            &[(1, 0), (-1, 0), (0, 1), (0, -1)]
        };
        let mut stack = vec![start];
        let mut members = vec![];
        let mut touches_outside = false;
        labels[start] = 0;
        while let Some(p) = stack.pop() {
            members.push(p);
            let (c, r) = ((p % w) as isize, (p / w) as isize);
            for &(dc, dr) in steps {
                let (nc, nr) = (c + dc, r + dr);
                if nc < 0 || nr < 0 || nc as usize >= w || nr as usize >= h {
                    touches_outside = true;
                    continue;
                }
                let q = nr as usize * w + nc as usize;
                if fg(nc, nr) == is_fg && labels[q] == usize::MAX {
                    labels[q] = 0;
                    stack.push(q);
                }
            }
        }
        let id = if is_fg {
            next.0 += 1;
            next.0
        } else if touches_outside {
            0
        } else {
            next.1 += 1;
            next.1
        };
        for m in members {
            labels[m] = id;
        }
    }
    (fl, bl)
}

#[test]
fn contours_are_every_border_exactly() {
    use photogrammetry_playground::chain::{self, fast as chfast, Connectivity};
    use std::collections::{BTreeMap, BTreeSet};
    for (k, &(w, h)) in SIZES.iter().enumerate() {
        for density in [2u64, 5, 9] {
            let mut rng = Rng(900 + k as u64 * 31 + density);
            let bytes: Vec<u8> = (0..w * h)
                .map(|_| if rng.below(10) < density { 255 } else { 0 })
                .collect();
            let img = Gray::new("img", &bytes, w, h).unwrap();
            let found = chfast::contours(img).unwrap();
            let (fl, bl) = components(&bytes, w, h);
            // every (region, background component) pair that touches
            // through a 4-neighbour is one border: the region's pixels with
            // a 4-neighbour in that background (0: the outside)
            let mut borders: BTreeMap<(usize, usize), BTreeSet<(u32, u32)>> = BTreeMap::new();
            for r in 0..h {
                for c in 0..w {
                    if bytes[r * w + c] == 0 {
                        continue;
                    }
                    for (dc, dr) in [(1isize, 0isize), (-1, 0), (0, 1), (0, -1)] {
                        let (nc, nr) = (c as isize + dc, r as isize + dr);
                        let inside = nc >= 0 && nr >= 0 && (nc as usize) < w && (nr as usize) < h;
                        let q = if inside {
                            nr as usize * w + nc as usize
                        } else {
                            0
                        };
                        if !inside || bytes[q] == 0 {
                            let b = if inside { bl[q] } else { 0 };
                            borders
                                .entry((fl[r * w + c], b))
                                .or_default()
                                .insert((c as u32, r as u32));
                        }
                    }
                }
            }
            assert_eq!(
                found.len(),
                borders.len(),
                "{w}×{h} density {density}: number of borders"
            );
            let outer = chain::trace(&img.to_grid(), Connectivity::Eight);
            let mut outer_iter = outer.iter();
            let mut seen = BTreeSet::new();
            for ct in &found {
                let (c0, r0) = ct.points[0];
                let region = fl[r0 as usize * w + c0 as usize];
                let pts: BTreeSet<(u32, u32)> = ct.points.iter().copied().collect();
                let pair = borders
                    .iter()
                    .find(|((f, b), set)| {
                        *f == region
                            && (*b != 0 || !ct.hole)
                            && **set == pts
                            && !seen.contains(&(*f, *b))
                    })
                    .map(|(p, _)| *p);
                let pair = pair.unwrap_or_else(|| {
                    panic!("{w}×{h} density {density}: border at ({c0}, {r0}) (hole {}) is no region's border", ct.hole)
                });
                assert!(seen.insert(pair), "{w}×{h}: border {pair:?} twice");
                if !ct.hole {
                    // the core's Moore tracing: same region, same start,
                    // same pixels walked the other way round
                    let b = outer_iter.next().expect("as many outer borders as regions");
                    let mut ours: Vec<[i64; 2]> = ct
                        .points
                        .iter()
                        .map(|&(c, r)| [i64::from(c), i64::from(r)])
                        .collect();
                    ours[1..].reverse();
                    assert_eq!(ours, b.pixels, "{w}×{h}: outer border at ({c0}, {r0})");
                }
            }
            assert!(
                outer_iter.next().is_none(),
                "{w}×{h}: regions without an outer border"
            );
        }
    }
}

/// The warps where the cubic weights cancel hardest: 0/255 checkerboards
/// and stripes (neighbours of opposite sign weights at full contrast),
/// fractions next to 0, ½ and 1 and exactly on pixel centres, values near
/// zero (the tolerance is absolute there). Bicubic sums in `f64` from
/// fixed-point fractions within 2⁻³² px, so the only loss is the `f32`
/// store: 1e-6 relative holds with a wide margin below the 1e-4 rule.
/// Bilinear runs in `f32` in the SIMD build: its error bound, 6.8·10⁻⁵
/// (absolute below 1, relative above; `resample::fast`'s `bilinear_run`),
/// is what is asserted, below the rule's 1e-4.
#[test]
fn warps_hold_the_tolerance_where_weights_cancel() {
    use photogrammetry_playground::resample::{self, fast as rfast, Method};
    let (w, h) = (37, 29);
    let images: [Vec<u8>; 3] = [
        (0..w * h)
            .map(|i| if (i % w + i / w) % 2 == 0 { 0 } else { 255 })
            .collect(),
        (0..w * h)
            .map(|i| if (i % w) % 4 < 2 { 255 } else { 0 })
            .collect(),
        (0..w * h)
            .map(|i| if (i / w) % 3 == 0 { 255 } else { 0 })
            .collect(),
    ];
    let shifts = [
        0.0,
        1e-12,
        1e-7,
        0.25,
        0.5 - 1e-9,
        0.5,
        0.5 + 1e-9,
        1.0 - 1e-7,
        1.0 - 1e-12,
    ];
    for bytes in &images {
        let img = Gray::new("img", bytes, w, h).unwrap();
        let grid = img.to_grid();
        for &sx in &shifts {
            for &sy in &shifts {
                for m in [
                    [[1.0, 0.0, sx], [0.0, 1.0, sy]],
                    [[0.999_999, 1e-7, sx + 0.5], [-1e-7, 1.000_001, sy]],
                    [[0.5, 0.0, sx + 3.0], [0.0, 0.25, sy + 2.0]],
                ] {
                    for a in [resample::SEED_A, -0.75, -0.5] {
                        let mut out = vec![0.0f32; w * h];
                        rfast::warp_affine(img, &m, Method::Bicubic, a, -1.0, (w, h), &mut out)
                            .unwrap();
                        for r in 0..h {
                            for c in 0..w {
                                let (x, y) = (
                                    m[0][0] * c as f64 + m[0][1] * r as f64 + m[0][2],
                                    m[1][0] * c as f64 + m[1][1] * r as f64 + m[1][2],
                                );
                                let want =
                                    resample::bicubic(&grid, x, y, a).map_or(-1.0, |b| b.value);
                                let got = out[r * w + c];
                                let err = (f64::from(got) - want).abs();
                                assert!(
                                    err <= 1e-6 * want.abs().max(1.0),
                                    "a={a} map {m:?} at ({c}, {r}): fast {got}, reference {want}"
                                );
                            }
                        }
                        let mut lin = vec![0.0f32; w * h];
                        rfast::warp_affine(img, &m, Method::Bilinear, 0.0, -1.0, (w, h), &mut lin)
                            .unwrap();
                        for r in 0..h {
                            for c in 0..w {
                                let (x, y) = (
                                    m[0][0] * c as f64 + m[0][1] * r as f64 + m[0][2],
                                    m[1][0] * c as f64 + m[1][1] * r as f64 + m[1][2],
                                );
                                let want = resample::value_at(&grid, x, y, Method::Bilinear)
                                    .unwrap_or(-1.0);
                                let err = (f64::from(lin[r * w + c]) - want).abs();
                                assert!(
                                    err <= 6.8e-5 * want.abs().max(1.0),
                                    "bilinear map {m:?} at ({c}, {r}): error {err:e}"
                                );
                            }
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn forstner_rows_give_the_window_operators_numbers_bit_for_bit() {
    use photogrammetry_playground::interest::{self, fast::stream};
    for (k, &(w, h)) in SIZES.iter().enumerate() {
        let bytes = random_image(w, h, 900 + k as u64);
        let img = Gray::new("img", &bytes, w, h).unwrap();
        let grid = img.to_grid();
        for size in [3, 4, 5, 6, 7, 9] {
            let Ok(map) = interest::forstner_map(&grid, size) else {
                assert!(stream::forstner_rows(img, size, |_, _, _, _| {}).is_err());
                continue;
            };
            let mut seen = vec![false; w * h];
            let f = stream::forstner_rows(img, size, |r, xx, yy, xy| {
                for (j, ((&a, &d), &b)) in xx.iter().zip(yy).zip(xy).enumerate() {
                    let c = stream::fit(w, h, size).unwrap().c0 + j;
                    let s = stream::Sums4 {
                        xx: a,
                        yy: d,
                        xy: b,
                    };
                    let m = map.get(c, r).expect("the reference has this window");
                    let (gw, gq) = s.w_q();
                    let what = format!("{w}×{h} size {size} at ({c}, {r})");
                    assert_eq!(gw.to_bits(), m.w.to_bits(), "w {what}");
                    assert_eq!(gq.to_bits(), m.q.unwrap_or(f64::NAN).to_bits(), "q {what}");
                    assert_eq!(
                        s.lambda_min().to_bits(),
                        m.lambda_min.to_bits(),
                        "λmin {what}"
                    );
                    assert_eq!(s.measures(m.m), m, "measures {what}");
                    seen[r * w + c] = true;
                }
            })
            .unwrap();
            assert_eq!(f.columns * f.rows, map.cells.iter().flatten().count());
            for (i, s) in seen.iter().enumerate() {
                assert_eq!(*s, map.cells[i].is_some(), "{w}×{h} size {size} cell {i}");
            }
        }
    }
}

#[test]
fn moravec_rows_give_the_window_means_bit_for_bit() {
    use photogrammetry_playground::interest::{self, fast::stream};
    for (k, &(w, h)) in SIZES.iter().enumerate() {
        let bytes = random_image(w, h, 950 + k as u64);
        let img = Gray::new("img", &bytes, w, h).unwrap();
        let grid = img.to_grid();
        for size in [3, 4, 5, 8] {
            let Ok(map) = interest::moravec_map(&grid, size) else {
                assert!(stream::moravec_rows(img, size, |_, _| {}).is_err());
                continue;
            };
            let n = ((size - 2) * (size - 2)) as f64;
            let mut count = 0;
            stream::moravec_rows(img, size, |r, sums| {
                for (j, &s) in sums.iter().enumerate() {
                    let c = interest::anchor(size) + j;
                    let want = map.get(c, r).expect("the reference has this window");
                    assert_eq!(f64::from(s) / n, want, "{w}×{h} size {size} at ({c}, {r})");
                    count += 1;
                }
            })
            .unwrap();
            assert_eq!(count, map.cells.iter().flatten().count());
        }
    }
}

#[test]
fn the_row_suppressor_keeps_what_suppress_keeps() {
    use photogrammetry_playground::interest::{self, fast::stream::Suppressor};
    let mut rng = Rng(5);
    for &(w, h) in SIZES.iter().chain(&[(40, 3), (3, 40)]) {
        for radius in 0..4 {
            // few distinct values: ties everywhere; a third without a score
            let scores: Vec<Option<f64>> = (0..w * h)
                .map(|_| (rng.below(3) > 0).then(|| rng.below(6) as f64 - 2.0))
                .collect();
            let want = interest::suppress(&scores, w, h, radius);
            let mut got = Vec::new();
            let mut s = Suppressor::new(w, h, radius);
            let mut keep = |c: usize, r: usize, v: f64, p: usize| {
                assert_eq!(p, r * w + c);
                assert_eq!(Some(v), scores[p]);
                got.push(p);
            };
            for r in 0..h {
                let row = (0..w).map(|c| (scores[r * w + c].unwrap_or(f64::NAN), r * w + c));
                s.push(row, &mut keep);
            }
            s.finish(&mut keep);
            assert_eq!(got, want, "{w}×{h} radius {radius}");
        }
    }
}

#[test]
fn correlate_equals_the_reference_for_any_kernel() {
    let mut rng = Rng(77);
    for (k, &(w, h)) in SIZES.iter().enumerate() {
        let bytes = random_image(w, h, 1000 + k as u64);
        let img = Gray::new("img", &bytes, w, h).unwrap();
        let grid = img.to_grid();
        for (kw, kh) in [(1, 1), (3, 3), (5, 5), (3, 5), (7, 3), (15, 15)] {
            for integer in [true, false] {
                let taps: Vec<f64> = (0..kw * kh)
                    .map(|_| {
                        let v = rng.below(11) as f64 - 5.0;
                        if integer {
                            v
                        } else {
                            v / 7.0
                        }
                    })
                    .collect();
                let rows: Vec<Vec<f64>> = taps.chunks(kw).map(<[f64]>::to_vec).collect();
                let divisor = if integer { 9.0 } else { 0.3 };
                let kernel = Kernel::new("k", &rows, divisor).unwrap();
                let k32: Vec<f32> = taps.iter().map(|&v| v as f32).collect();
                let scale: f64 = taps.iter().map(|v| v.abs()).sum::<f64>() * 255.0 / divisor;
                for border in BORDERS {
                    let Ok(reference) = filter::correlate(&grid, &kernel, border) else {
                        continue;
                    };
                    let mut out = vec![0.0f32; w * h];
                    fast::correlate(img, &k32, (kw, kh), divisor as f32, border, &mut out).unwrap();
                    let reg = reference.region;
                    for r in reg.r0..reg.r0 + reg.height {
                        for c in reg.c0..reg.c0 + reg.width {
                            let want = reference.at_input(c, r).unwrap();
                            let got = f64::from(out[r * w + c]);
                            // integer taps: the f32 nearest the exact value
                            // (one unit in the last place); others within
                            // 1e-6 of the kernel's range
                            let tol = if integer {
                                f64::from(f32::EPSILON) * want.abs()
                            } else {
                                1e-6 * scale
                            };
                            assert!(
                                (got - want).abs() <= tol,
                                "{kw}×{kh} {w}×{h} {border:?} at ({c}, {r}): {got} vs {want}"
                            );
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn direction_is_atan2_in_degrees() {
    let mut xs = vec![0.0f32, -0.0, 1.0, -1.0, 1020.0, -1020.0, 3.0, -3.0];
    let mut rng = Rng(3);
    xs.extend((0..300).map(|_| rng.below(2041) as f32 - 1020.0));
    for &x in &xs {
        let ys: Vec<f32> = xs.iter().step_by(3).copied().collect();
        let gx = vec![x; ys.len()];
        let mut out = vec![0.0f32; ys.len()];
        fast::direction_deg(&gx, &ys, &mut out);
        for (&y, &d) in ys.iter().zip(&out) {
            let want = (f64::from(y) + 0.0).atan2(f64::from(x) + 0.0).to_degrees();
            assert!(
                (f64::from(d) - want).abs() <= 1e-4,
                "atan2({y}, {x}): {d} vs {want}"
            );
        }
    }
}

#[test]
fn warps_by_the_references_own_positions_equal_resample_warp() {
    use photogrammetry_playground::resample::{self, fast as rfast, Method};
    for (k, &(w, h)) in SIZES.iter().enumerate() {
        let bytes = random_image(w, h, 1100 + k as u64);
        let img = Gray::new("img", &bytes, w, h).unwrap();
        let grid = img.to_grid();
        let (mc, mr) = ((w as f64 - 1.0) / 2.0, (h as f64 - 1.0) / 2.0);
        // the lab's rotation (an odd width and scale 2 put nearest
        // neighbours on exact halves), and a homography
        for (angle, scale) in [(0.0, 2.0), (7.0, 1.15), (90.0, 1.0), (-33.0, 0.6)] {
            let (s, c) = f64::to_radians(angle).sin_cos();
            let rot = |x: f64, y: f64| {
                let (dx, dy) = (x - mc, y - mr);
                (
                    (c * dx + s * dy) / scale + mc,
                    (-s * dx + c * dy) / scale + mr,
                )
            };
            let (a, b) = (c / scale, s / scale);
            let m = [[a, b, mc - a * mc - b * mr], [-b, a, mr + b * mc - a * mr]];
            let hom = |x: f64, y: f64| {
                let d = 1.0 + 0.01 * x - 0.02 * y;
                (
                    (0.9 * x + 0.1 * y + 0.5) / d,
                    (-0.05 * x + 1.1 * y + 0.25) / d,
                )
            };
            for method in [Method::Nearest, Method::Bilinear, Method::Bicubic] {
                let (ow, oh) = (w + 2, h + 1);
                let mut out = vec![0.0f32; ow * oh];
                rfast::warp_affine_with(
                    img,
                    &m,
                    &rot,
                    method,
                    resample::SEED_A,
                    -1.0,
                    (ow, oh),
                    &mut out,
                )
                .unwrap();
                let want = resample::warp(&grid, ow, oh, rot, method, -1.0);
                let mut proj = vec![0.0f32; ow * oh];
                rfast::warp_map(
                    img,
                    &hom,
                    method,
                    resample::SEED_A,
                    -1.0,
                    (ow, oh),
                    &mut proj,
                )
                .unwrap();
                let want_p = resample::warp(&grid, ow, oh, hom, method, -1.0);
                for i in 0..ow * oh {
                    let what = format!("{method:?} {w}×{h} {angle}° ×{scale} pixel {i}");
                    if method == Method::Nearest {
                        assert_eq!(f64::from(out[i]), want.data()[i], "{what}");
                        assert_eq!(f64::from(proj[i]), want_p.data()[i], "{what} projective");
                    } else {
                        assert!(
                            close(out[i], want.data()[i]),
                            "{what}: {} vs {}",
                            out[i],
                            want.data()[i]
                        );
                        assert!(close(proj[i], want_p.data()[i]), "{what} projective");
                    }
                }
            }
        }
    }
}

#[test]
fn a_refined_suppressor_decides_on_the_exact_scores() {
    use photogrammetry_playground::interest::{self, fast::stream::Suppressor};
    let mut rng = Rng(11);
    for &(w, h) in &[(40usize, 30usize), (7, 5), (1, 9)] {
        for radius in 1..4 {
            // exact scores with many ties and near-ties, pushed perturbed by
            // up to 2.5·10⁻¹³ (relative): the refinement sorts them out
            let exact: Vec<Option<f64>> = (0..w * h)
                .map(|_| (rng.below(4) > 0).then(|| 1.0 + rng.below(5) as f64 * 1e-13))
                .collect();
            let want = interest::suppress(&exact, w, h, radius);
            let ex = exact.clone();
            let mut s = Suppressor::new(w, h, radius)
                .refined(1e-12, move |&i: &usize| ex[i].unwrap_or(f64::NAN));
            let mut got = Vec::new();
            let mut keep = |c: usize, r: usize, _: f64, p: usize| {
                assert_eq!(p, r * w + c);
                got.push(p);
            };
            for r in 0..h {
                let row: Vec<(f64, usize)> = (0..w)
                    .map(|c| {
                        let i = r * w + c;
                        let noise = (rng.below(11) as f64 - 5.0) * 5e-14;
                        (exact[i].map_or(f64::NAN, |v| v * (1.0 + noise)), i)
                    })
                    .collect();
                s.push(row, &mut keep);
            }
            s.finish(&mut keep);
            assert_eq!(got, want, "{w}×{h} radius {radius}");
        }
    }
}

#[test]
fn one_windows_sums_and_the_approximate_lambda_min() {
    use photogrammetry_playground::interest::fast::stream::{self, Sums4};
    for (k, &(w, h)) in SIZES.iter().enumerate() {
        let bytes = random_image(w, h, 1300 + k as u64);
        let img = Gray::new("img", &bytes, w, h).unwrap();
        for size in [3, 4, 5, 8] {
            let _ = stream::forstner_rows(img, size, |r, xx, yy, xy| {
                for j in 0..xx.len() {
                    let c = stream::fit(w, h, size).unwrap().c0 + j;
                    let s = Sums4 {
                        xx: xx[j],
                        yy: yy[j],
                        xy: xy[j],
                    };
                    assert_eq!(
                        Sums4::at(&img, size, c, r),
                        Some(s),
                        "{w}×{h} size {size} ({c}, {r})"
                    );
                    let (e, a) = (s.lambda_min(), s.lambda_min_approx());
                    assert!((e - a).abs() <= 1e-14 * e.abs(), "{e} vs {a}");
                }
            });
            assert_eq!(Sums4::at(&img, size, w, 0), None);
        }
    }
}

#[test]
fn the_w_q_rows_are_w_q_rounded() {
    use photogrammetry_playground::interest::fast::stream::{w_q_row, Sums4};
    let mut rng = Rng(21);
    let n = 4000;
    // random sums, and the edge cases: N = 0, straight edges (det 0), tiny
    let mut xx: Vec<i32> = (0..n).map(|_| rng.below(60_000_000) as i32).collect();
    let mut yy: Vec<i32> = (0..n).map(|_| rng.below(60_000_000) as i32).collect();
    let mut xy: Vec<i32> = (0..n)
        .map(|_| rng.below(60_000_000) as i32 - 30_000_000)
        .collect();
    for (i, (a, d, b)) in [
        (0, 0, 0),
        (4, 9, 6),
        (4, 9, -6),
        (1, 0, 0),
        (25, 16, 20),
        (3, 3, 3),
    ]
    .into_iter()
    .enumerate()
    {
        (xx[i], yy[i], xy[i]) = (a, d, b);
    }
    let (mut w, mut q) = (vec![0.0f32; n], vec![0.0f32; n]);
    w_q_row(&xx, &yy, &xy, &mut w, &mut q);
    for i in 0..n {
        let (ew, eq) = Sums4 {
            xx: xx[i],
            yy: yy[i],
            xy: xy[i],
        }
        .w_q();
        assert_eq!(w[i].to_bits(), (ew as f32).to_bits(), "w {i}");
        assert_eq!(q[i].to_bits(), (eq as f32).to_bits(), "q {i}");
    }
}
