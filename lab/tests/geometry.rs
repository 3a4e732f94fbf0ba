//! The lab's geometric operators against the core's functions and known
//! truths: NCC and least-squares matching of a photo with a known shift or
//! affine (and every match against its worked example), the fiducial fit,
//! projective rectification, warps and boundary tracing. (The filters,
//! edges and interest operators: operators.rs.)

mod common;

use common::random;
use photogrammetry_lab::ops::{self, Rect};
use photogrammetry_lab::sample;
use photogrammetry_playground::examples::solve;
use photogrammetry_playground::matching::{Model, Status};
use photogrammetry_playground::raster::Grid;
use photogrammetry_playground::resample::{self, Method};
use photogrammetry_playground::solution::Solution;
use photogrammetry_playground::solution::{Record, Value};
use photogrammetry_playground::transform::{self, PointPair};

#[test]
fn ncc_and_lsm_recover_a_known_subpixel_shift_of_a_photo() {
    // camera.png, and the same photo shifted by (+3.3, −1.6) px by bicubic
    // resampling: the truth is the shift (interpolation adds its own error,
    // a few hundredths of a pixel on a photo; tolerance 0.1 px: two interpolations of a sharp photo, the cubic convolution that made the shifted copy and LSM's bilinear resampling, each err by a few hundredths of a pixel).
    let bytes = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../www/lab/samples/camera.png"
    ))
    .unwrap();
    let a = photogrammetry_lab::decode::decode("camera.png", &bytes)
        .unwrap()
        .grid;
    let (sx, sy) = (3.3, -1.6);
    let b = resample::warp(&a, 512, 512, |x, y| (x - sx, y - sy), Method::Bicubic, 0.0);
    let t = Rect {
        c0: 240,
        r0: 120,
        width: 21,
        height: 21,
    };
    let s = Rect {
        c0: 225,
        r0: 105,
        width: 51,
        height: 51,
    };
    let m = ops::correlate(&a, t, &b, s, Model::ShiftRadiometric).unwrap();
    // whole-pixel best: the template centre (250, 130) moved by the shift
    assert_eq!(m.best, Some((253, 128)));
    let (qc, qr) = m.subpixel.unwrap();
    assert!(
        (qc - 253.3).abs() < 0.3 && (qr - 128.4).abs() < 0.3,
        "{qc}, {qr}"
    );
    let l = m.lsm.unwrap();
    assert_eq!(l.status, Status::Converged);
    let c = l.params.a[2] + m.lsm_window.c0 as f64;
    let r = l.params.a[5] + m.lsm_window.r0 as f64;
    assert!(
        (c - 253.3).abs() < 0.1 && (r - 128.4).abs() < 0.1,
        "{c}, {r}"
    );
}

#[test]
fn lsm_recovers_a_known_affine_of_a_photo() {
    // the photo warped by a 4° rotation, 1.05 scale about (250, 130), plus a
    // shift; affine LSM from the NCC match recovers the affine part within
    // 0.01 and the position within 0.05 px (interpolation error again).
    let bytes = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../www/lab/samples/camera.png"
    ))
    .unwrap();
    let a = photogrammetry_lab::decode::decode("camera.png", &bytes)
        .unwrap()
        .grid;
    let (th, s) = (4f64.to_radians(), 1.05);
    let (cx, cy, dx, dy) = (250.0, 130.0, 2.4, 1.7);
    // b(x) = a(A⁻¹(x − centre − d) + centre): a patch of a at centre maps
    // to b at centre + d with matrix A = s·R(θ)
    let b = resample::warp(
        &a,
        512,
        512,
        |x, y| {
            let (u, v) = (x - cx - dx, y - cy - dy);
            let (sn, cs) = th.sin_cos();
            ((cs * u + sn * v) / s + cx, (-sn * u + cs * v) / s + cy)
        },
        Method::Bicubic,
        0.0,
    );
    let t = Rect {
        c0: 235,
        r0: 115,
        width: 31,
        height: 31,
    };
    let sr = Rect {
        c0: 225,
        r0: 105,
        width: 55,
        height: 55,
    };
    let m = ops::correlate(&a, t, &b, sr, Model::AffineRadiometric).unwrap();
    let l = m.lsm.unwrap();
    assert_eq!(
        l.status,
        Status::Converged,
        "{:?} {:?}",
        l.status,
        l.params.a
    );
    let p = l.params.a;
    let (sn, cs) = th.sin_cos();
    for (got, want) in [
        (p[0], s * cs),
        (p[1], -s * sn),
        (p[3], s * sn),
        (p[4], s * cs),
    ] {
        assert!((got - want).abs() < 0.01, "{p:?}");
    }
    let (c, r) = (p[2] + m.lsm_window.c0 as f64, p[5] + m.lsm_window.r0 as f64);
    assert!(
        (c - (cx + dx)).abs() < 0.05 && (r - (cy + dy)).abs() < 0.05,
        "{c}, {r}"
    );
}

/// A key of a worked example's result as a number or a list of numbers.
fn result_numbers(sol: &Solution, key: &str) -> Vec<f64> {
    match sol.result.get(key) {
        Some(Value::List(xs)) => xs.iter().map(|x| x.as_f64().unwrap()).collect(),
        Some(v) => vec![v.as_f64().unwrap()],
        None => panic!("{key}: missing"),
    }
}

#[test]
fn every_lab_match_is_its_worked_example() {
    // the warped photo of the test above; each LSM model of the lab, its
    // window handed to the example the lab links (the link's inputs):
    // shift and shift + radiometric to lsm-2d, affine to lsm-affine with
    // the given patches; the 3×3 ρ round the best to subpixel-2d
    let bytes = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../www/lab/samples/camera.png"
    ))
    .unwrap();
    let a = photogrammetry_lab::decode::decode("camera.png", &bytes)
        .unwrap()
        .grid;
    let (th, sc) = (4f64.to_radians(), 1.05);
    let b = resample::warp(
        &a,
        512,
        512,
        |x, y| {
            let (u, v) = (x - 252.4, y - 131.7);
            let (sn, cs) = th.sin_cos();
            (
                (cs * u + sn * v) / sc + 250.0,
                (-sn * u + cs * v) / sc + 130.0,
            )
        },
        Method::Bicubic,
        0.0,
    );
    let t = Rect {
        c0: 240,
        r0: 120,
        width: 21,
        height: 21,
    };
    let sr = Rect {
        c0: 225,
        r0: 105,
        width: 51,
        height: 51,
    };
    for (model, id, radiometric) in [
        (Model::Shift, "lsm-2d", false),
        (Model::ShiftRadiometric, "lsm-2d", true),
        (Model::AffineRadiometric, "lsm-affine", true),
    ] {
        let m = ops::correlate(&a, t, &b, sr, model).unwrap();
        let l = m.lsm.as_ref().unwrap();
        assert_eq!(l.status, Status::Converged, "{model:?}");
        let w = m.lsm_window;
        let window = b.window(w.c0, w.r0, w.width, w.height).unwrap();
        let mut inputs = Record::new()
            .with("template", Value::matrix(&m.template.rows()))
            .with("search", Value::matrix(&window.rows()))
            .with("c0", l.start.a[2] + 1.0)
            .with("r0", l.start.a[5] + 1.0);
        if id == "lsm-2d" {
            inputs = inputs
                .with("radiometric", radiometric)
                .with("a0", 1.0)
                .with("b0", 0.0);
        } else {
            inputs = inputs.with("pair", "patches");
        }
        let sol = solve(id, &inputs).unwrap();
        let p = l.params.a;
        // the example counts from 1 in the window, the lab from 0 in the image
        let (c, r) = (p[2] + w.c0 as f64, p[5] + w.r0 as f64);
        let close = |x: f64, y: f64| (x - y).abs() < 1e-9;
        if id == "lsm-2d" {
            let ec = result_numbers(&sol, "c")[0] - 1.0 + w.c0 as f64;
            let er = result_numbers(&sol, "r")[0] - 1.0 + w.r0 as f64;
            assert!(
                close(ec, c) && close(er, r),
                "{model:?}: {ec}, {er} vs {c}, {r}"
            );
            assert!(close(result_numbers(&sol, "a")[0], p[6]), "{model:?}");
            assert!(close(result_numbers(&sol, "b")[0], p[7]), "{model:?}");
            if !radiometric {
                assert_eq!((p[6], p[7]), (1.0, 0.0));
            }
        } else {
            let e = result_numbers(&sol, "parameters");
            for k in [0, 1, 3, 4, 6, 7] {
                assert!(close(e[k], p[k]), "a{}: {} vs {}", k + 1, e[k], p[k]);
            }
            assert!(close(e[2] - 1.0 + w.c0 as f64, c) && close(e[5] - 1.0 + w.r0 as f64, r));
            // and the truth is found: 4°, 1.05 about the template centre;
            // the position within 0.1 px (the bicubic copy and LSM's
            // bilinear resampling each err by a few hundredths on a photo)
            assert!(
                (e[0] - sc * th.cos()).abs() < 0.01 && (e[3] - sc * th.sin()).abs() < 0.01,
                "{e:?}"
            );
            assert!(
                (c - 252.4).abs() < 0.1 && (r - 131.7).abs() < 0.1,
                "{c}, {r}"
            );
        }
        assert_eq!(
            result_numbers(&sol, "iterations")[0],
            l.iterations.len() as f64,
            "{model:?}"
        );
        // subpixel-2d with the 3×3 ρ round the best (0-based image positions)
        let (bc, br) = m.best.unwrap();
        let rho = m.around.unwrap();
        let cols = [bc as f64 - 1.0, bc as f64, bc as f64 + 1.0];
        let rows = [br as f64 - 1.0, br as f64, br as f64 + 1.0];
        let sol = solve(
            "subpixel-2d",
            &Record::new()
                .with("c", Value::numbers(&cols))
                .with("r", Value::numbers(&rows))
                .with(
                    "rho",
                    Value::matrix(&rho.iter().map(|r| r.to_vec()).collect::<Vec<_>>()),
                ),
        )
        .unwrap();
        let (qc, qr) = m.subpixel.unwrap();
        assert_eq!(result_numbers(&sol, "c_max")[0], qc);
        assert_eq!(result_numbers(&sol, "r_max")[0], qr);
    }
}

#[test]
fn the_fiducial_fit_on_the_generated_frame_recovers_the_known_affine() {
    let img = sample::scanned_frame();
    let template = sample::mark_template(21).unwrap();
    let marks = ops::measure_marks(&img, &template, &sample::nominal_marks(), 12).unwrap();
    // each mark within 0.1 px of its true position: noise 1.5 grey values
    // against 195 of contrast, and LSM's bilinear resampling of the mark's
    // one-pixel soft edge (its own error of a few hundredths of a pixel)
    for (m, t) in marks.iter().zip(sample::true_marks()) {
        assert!(m.ncc > 0.95, "{m:?}");
        assert!(m.iterations > 0, "{m:?}");
        let d = (m.measured.0 - t.0).hypot(m.measured.1 - t.1);
        assert!(d < 0.1, "{m:?} vs {t:?}: {d} px");
    }
    let measured: Vec<(f64, f64)> = marks.iter().map(|m| m.measured).collect();
    let (sim, aff) = ops::fit_fiducials(&measured, &sample::calibrated()).unwrap();
    // the affine: 0.1 px of measuring error is 0.025 mm at the marks, so
    // the scales are within about 0.1·0.25/450 ≈ 6·10⁻⁵ and the shifts 0.03 mm
    let p = &aff.transform.params;
    let t = sample::TRUE_AFFINE;
    for i in [0, 1, 3, 4] {
        assert!((p[i] - t[i]).abs() < 1e-4, "{p:?} vs {t:?}");
    }
    for i in [2, 5] {
        assert!((p[i] - t[i]).abs() < 0.03, "{p:?} vs {t:?}");
    }
    // the similarity cannot take the two scales and the shear: its residuals
    // are larger than the affine's
    let rms = |f: &photogrammetry_playground::transform::Fit| {
        (f.adjustment.vtpv / f.adjustment.v.len() as f64).sqrt()
    };
    assert!(
        rms(&sim) > 5.0 * rms(&aff),
        "{} vs {}",
        rms(&sim),
        rms(&aff)
    );
}

/// The projective map through four point pairs, solved here on its own:
/// x·(h7·u + h8·v + 1) = h1·u + h2·v + h3, y·(…) = h4·u + h5·v + h6, eight
/// equations in eight unknowns by Gaussian elimination with pivoting.
type XY = (f64, f64);

fn homography(pairs: &[(XY, XY)]) -> [f64; 8] {
    let mut m = Vec::new();
    for &((u, v), (x, y)) in pairs {
        m.push(vec![u, v, 1.0, 0.0, 0.0, 0.0, -x * u, -x * v, x]);
        m.push(vec![0.0, 0.0, 0.0, u, v, 1.0, -y * u, -y * v, y]);
    }
    for k in 0..8 {
        let p = (k..8)
            .max_by(|&a, &b| m[a][k].abs().total_cmp(&m[b][k].abs()))
            .unwrap();
        m.swap(k, p);
        let pivot = m[k].clone();
        for (i, row) in m.iter_mut().enumerate() {
            if i != k {
                let f = row[k] / pivot[k];
                for (x, p) in row.iter_mut().zip(&pivot).skip(k) {
                    *x -= f * p;
                }
            }
        }
    }
    std::array::from_fn(|k| m[k][8] / m[k][k])
}

#[test]
fn projective_rectification_equals_fit_and_the_point_functions() {
    let img = random(40, 30, 9);
    let (w, h) = (16, 12);
    // a quadrilateral clicked clockwise from the top left (fractional, as
    // clicks are)
    let clicked = [(5.3, 4.1), (33.7, 6.4), (30.2, 25.6), (7.9, 22.2)];
    let t = ops::projective(&clicked, w, h).unwrap();
    // the 004 table's projective model through transform::fit, output
    // corners to the clicked points
    let corners = [(0.0, 0.0), (15.0, 0.0), (15.0, 11.0), (0.0, 11.0)];
    let pairs: Vec<PointPair> = corners
        .iter()
        .zip(&clicked)
        .map(|(&(u, v), &(x, y))| PointPair { u, v, x, y })
        .collect();
    let fit = transform::fit(transform::Model::Projective, &pairs).unwrap();
    assert_eq!(t.params, fit.transform.params);
    // the corners land on the clicks, and every output pixel where the
    // independent solution puts it
    let hm = homography(&corners.iter().copied().zip(clicked).collect::<Vec<_>>());
    for (&(u, v), &(x, y)) in corners.iter().zip(&clicked) {
        let (px, py) = t.apply(u, v).unwrap();
        assert!((px - x).abs() < 1e-9 && (py - y).abs() < 1e-9, "({u}, {v})");
    }
    let methods = [Method::Nearest, Method::Bilinear, Method::Bicubic];
    let map = |x: f64, y: f64| t.apply(x, y).unwrap_or((f64::NAN, f64::NAN));
    let grids = ops::warp(&img, w, h, &map, &methods);
    let mut inside = [0; 3];
    for r in 0..h {
        for c in 0..w {
            let (u, v) = (c as f64, r as f64);
            let den = hm[6] * u + hm[7] * v + 1.0;
            let x = (hm[0] * u + hm[1] * v + hm[2]) / den;
            let y = (hm[3] * u + hm[4] * v + hm[5]) / den;
            let (px, py) = t.apply(u, v).unwrap();
            assert!((px - x).abs() < 1e-9 && (py - y).abs() < 1e-9, "({c}, {r})");
            for (k, m) in methods.iter().enumerate() {
                let want = match m {
                    Method::Nearest => resample::nearest(&img, px, py).map(|n| n.value),
                    Method::Bilinear => resample::bilinear(&img, px, py).map(|n| n.value),
                    Method::Bicubic => {
                        resample::bicubic(&img, px, py, resample::SEED_A).map(|n| n.value)
                    }
                };
                if want.is_some() {
                    inside[k] += 1;
                }
                assert_eq!(
                    grids[k].get(c, r),
                    Some(want.unwrap_or(0.0)),
                    "{m:?} ({c}, {r})"
                );
            }
        }
    }
    // the quadrilateral lies inside the image: every output pixel has a value
    assert_eq!(inside, [w * h; 3]);
    // three points on a line have no projective map
    let flat = [(1.0, 1.0), (5.0, 5.0), (9.0, 9.0), (13.0, 13.0)];
    let e = ops::projective(&flat, w, h).unwrap_err().to_string();
    assert!(e.starts_with("points"), "{e}");
}

#[test]
fn warp_equals_the_point_functions_and_boundary_traces_the_picked_region() {
    let img = random(9, 7, 4);
    let map = |x: f64, y: f64| (0.9 * x + 0.3, 0.8 * y + 0.45);
    for m in [Method::Nearest, Method::Bilinear, Method::Bicubic] {
        let g = resample::warp(&img, 9, 7, map, m, 0.0);
        for r in 0..7 {
            for c in 0..9 {
                let (x, y) = map(c as f64, r as f64);
                let want = match m {
                    Method::Nearest => resample::nearest(&img, x, y).map(|n| n.value),
                    Method::Bilinear => resample::bilinear(&img, x, y).map(|n| n.value),
                    Method::Bicubic => {
                        resample::bicubic(&img, x, y, resample::SEED_A).map(|n| n.value)
                    }
                };
                assert_eq!(g.get(c, r), Some(want.unwrap_or(0.0)));
            }
        }
    }
    // a 3×2 bright block in a dark image: boundary of 6 pixels, area 6
    let img = Grid::from_fn(8, 6, |c, r| {
        if (2..5).contains(&c) && (1..3).contains(&r) {
            200.0
        } else {
            10.0
        }
    });
    let t = ops::boundary(&img, 100.0, 3, 2).unwrap();
    assert_eq!(t.boundary.area, 6);
    assert_eq!(t.boundary.pixels.len(), 6);
    assert_eq!(
        t.length.horizontal + t.length.vertical + t.length.diagonal,
        6
    );
    assert_eq!(t.boundary.code, vec![1, 1, 7, 5, 5, 3]);
}
