//! Seed 000, Examples 10–11, and seed 003's affine + radiometric model:
//! least-squares matching reproduced natively with its numbers, its
//! convergence and every way a run can end.
#![cfg(not(target_arch = "wasm32"))]

use photogrammetry_playground::examples::solve;
use photogrammetry_playground::matching::{
    self, affine_from, match_1d, match_2d, synthetic_pair, Gradients, Model, Params, Settings,
    Status,
};
use photogrammetry_playground::raster::Grid;
use photogrammetry_playground::resample;
use photogrammetry_playground::solution::{NoteKind, Record, Solution, Value};

fn result(s: &Solution, key: &str) -> f64 {
    s.result
        .number(key)
        .unwrap_or_else(|| panic!("result {key} missing in {}", s.id))
}

fn printed(s: &Solution, key: &str) -> f64 {
    s.textbook
        .as_ref()
        .and_then(|t| t.number(key))
        .unwrap_or_else(|| panic!("printed {key} missing in {}", s.id))
}

fn assert_close(s: &Solution, key: &str, expected: f64, tol: f64) {
    let got = result(s, key);
    assert!(
        (got - expected).abs() <= tol,
        "{}.{key} = {got}, expected {expected}",
        s.id
    );
}

fn has_note(s: &Solution, kind: NoteKind, needle: &str) -> bool {
    s.notes
        .iter()
        .any(|n| n.kind == kind && n.text.contains(needle))
}

fn status(s: &Solution) -> String {
    match s.result.get("status") {
        Some(Value::Text(t)) => t.clone(),
        other => panic!("status is {other:?}"),
    }
}

fn converged(s: &Solution) -> bool {
    s.result.get("converged") == Some(&Value::Bool(true))
}

fn list(v: Option<&Value>) -> Vec<f64> {
    match v {
        Some(Value::List(xs)) => xs.iter().map(|x| x.as_f64().unwrap()).collect(),
        other => panic!("not a list: {other:?}"),
    }
}

fn text(s: &str) -> Value {
    Value::Text(s.to_string())
}

/// A tiny deterministic generator for the property tests.
/// Matching settings with the gradients the seeds state.
fn stated(model: Model, max_iterations: usize) -> Settings {
    Settings {
        model,
        gradients: Gradients::SearchWindow,
        max_iterations,
    }
}

struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

// ------------------------------------------------------------ Example 10

#[test]
fn example_10_shift_only_first_iteration_and_convergence() {
    let s = solve("lsm-1d", &Record::new()).unwrap();
    assert_close(&s, "first_dc", -11.5 / 39.0, 1e-15);
    assert_eq!(s.result.get("first_da"), Some(&Value::Null));
    assert_eq!(s.result.get("first_db"), Some(&Value::Null));
    assert!(converged(&s));
    assert_eq!(status(&s), "converged");
    assert_close(&s, "iterations", 13.0, 0.0);
    assert_close(&s, "c", 7.769_971, 2e-4);
    assert_close(&s, "a", 1.0, 0.0);
    assert_close(&s, "b", 0.0, 0.0);
    // the seed's printed values beside the exact ones
    assert_eq!(printed(&s, "first_dc"), -0.2945);
    assert_eq!(printed(&s, "c_after_first"), 7.705);
    assert!(has_note(&s, NoteKind::Rounding, "rounds to −0.2949"));
    assert!(has_note(&s, NoteKind::Convention, "after 13 iterations"));
    // the first iteration laid out as the seed does
    let a = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Design"))
        .unwrap();
    assert!(a.substituted.contains("(3 - 1)/2"), "{}", a.substituted);
    assert!(a.substituted.contains("(1 - 1)/2"));
    assert_eq!(
        first_a(&s).iter().map(|r| r[0]).collect::<Vec<_>>(),
        vec![1.0, 3.5, 2.5, -1.0, -3.5, -2.5, 0.0]
    );
    let dl = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Difference"))
        .unwrap();
    assert_eq!(
        list(dl.values.get("dL")),
        vec![0.0, -1.0, 1.0, 1.0, 2.0, 1.0, 0.0]
    );
    let ne = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Normal"))
        .unwrap();
    assert!(ne.substituted.contains("39") && ne.substituted.contains("-11.5"));
    assert!((ne.values.number("c_after_first").unwrap() - (8.0 - 11.5 / 39.0)).abs() < 1e-12);
    // every iteration in the table, with the increments alternating in sign
    let table = s
        .steps
        .iter()
        .find(|st| st.title == "Every iteration")
        .unwrap();
    let dc = list(table.values.get("dc"));
    assert_eq!(dc.len(), 13);
    assert!(dc.windows(2).all(|w| w[0] * w[1] < 0.0));
    assert!(dc.last().unwrap().abs() <= matching::POSITION_TOL);
    let keys: Vec<_> = s.result.keys().take(8).collect();
    assert_eq!(
        keys,
        [
            "first_dc",
            "first_da",
            "first_db",
            "c",
            "a",
            "b",
            "iterations",
            "converged"
        ]
    );
}

#[test]
fn example_10_with_radiometry() {
    let s = solve("lsm-1d", &Record::new().with("radiometric", true)).unwrap();
    assert_close(&s, "first_dc", -11.5 / 39.0, 1e-14);
    assert_close(&s, "first_da", 5.0 / 32.0, 1e-14);
    assert_close(&s, "first_db", -3.0 / 56.0, 1e-14);
    assert_eq!(printed(&s, "first_dc"), -0.295);
    assert_eq!(printed(&s, "first_da"), 0.156);
    assert_eq!(printed(&s, "first_db"), -0.053);
    assert!(has_note(&s, NoteKind::Rounding, "rounds to −0.054"));
    assert!(converged(&s));
    assert_close(&s, "iterations", 7.0, 0.0);
    assert_close(&s, "c", 7.769_383, 2e-4);
    assert_close(&s, "a", 1.279_031, 5e-4);
    assert_close(&s, "b", -0.544_695, 2e-3);
    let ne = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Normal"))
        .unwrap();
    assert!(ne
        .substituted
        .contains(r"39 & 0 & 0 \\ 0 & 176 & 28 \\ 0 & 28 & 7"));
}

#[test]
fn a_what_if_has_no_textbook() {
    let s = solve("lsm-1d", &Record::new().with("c0", 7.5)).unwrap();
    assert!(s.textbook.is_none());
    assert!(converged(&s));
}

// ------------------------------------------------------------ Example 11

const PRINTED_A: [[f64; 2]; 9] = [
    [9.0, 7.5],
    [1.5, 2.0],
    [-7.5, 7.0],
    [3.5, 0.5],
    [1.0, 1.5],
    [-2.5, 0.5],
    [10.0, -7.0],
    [1.5, -0.5],
    [-8.5, -6.5],
];

fn first_a(s: &Solution) -> Vec<Vec<f64>> {
    let step = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Design"))
        .unwrap();
    match step.values.get("A") {
        Some(Value::List(rows)) => rows.iter().map(|r| list(Some(r))).collect(),
        other => panic!("{other:?}"),
    }
}

#[test]
fn example_11_search_window_reading() {
    let s = solve("lsm-2d", &Record::new()).unwrap();
    assert_eq!(s.inputs.get("gradients"), Some(&text("search-window")));
    assert_close(&s, "first_dc", 0.186_049_4, 1e-6);
    assert_close(&s, "first_dr", 0.107_289_3, 1e-6);
    assert_close(&s, "first_da", 0.140_693_6, 1e-6);
    assert_close(&s, "first_db", -5.508_121, 1e-5);
    let a = first_a(&s);
    assert_eq!(a[0], vec![10.0, 9.0, 47.0, 1.0]);
    assert_eq!(a[8], vec![-6.5, -8.0, 51.0, 1.0]);
    // where the stated formula and the printed matrix differ
    let differing: usize = a
        .iter()
        .zip(PRINTED_A)
        .map(|(r, p)| (0..2).filter(|&j| r[j] != p[j]).count())
        .sum();
    assert_eq!(differing, 9);
    assert!(has_note(
        &s,
        NoteKind::Erratum,
        "at 9 of its 18 gradient entries"
    ));
    assert!(has_note(&s, NoteKind::Erratum, "(65 − 45)/2 = 10"));
    assert!(converged(&s));
    assert_close(&s, "iterations", 11.0, 0.0);
    assert_close(&s, "c", 3.163_718, 2e-4);
    assert_close(&s, "r", 4.112_809, 2e-4);
    assert_close(&s, "a", 1.452_846, 1e-3);
    assert_close(&s, "b", -43.534_21, 0.05);
    assert_eq!(printed(&s, "first_dc"), 0.194);
    assert_eq!(printed(&s, "first_db"), -5.372);
    // the bottom border row leaves the 6-row window from iteration 2 on
    assert!(has_note(&s, NoteKind::Warning, "Border samples outside"));
    let keys: Vec<_> = s.result.keys().take(10).collect();
    assert_eq!(
        keys,
        [
            "first_dc",
            "first_dr",
            "first_da",
            "first_db",
            "c",
            "r",
            "a",
            "b",
            "iterations",
            "converged"
        ]
    );
}

#[test]
fn example_11_patch_edge_reading_reproduces_the_printed_matrix() {
    let s = solve(
        "lsm-2d",
        &Record::new().with("gradients", text("patch-edge")),
    )
    .unwrap();
    let a = first_a(&s);
    for (row, p) in a.iter().zip(PRINTED_A) {
        assert_eq!(&row[..2], &p[..]);
    }
    let step = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Design"))
        .unwrap();
    assert!(step
        .substituted
        .contains("(65 - 47)/2 & (62 - 47)/2 & 47 & 1"));
    // the printed increments, to their three decimals
    for (key, p) in [
        ("first_dc", 0.194),
        ("first_dr", 0.086),
        ("first_da", 0.138),
        ("first_db", -5.372),
    ] {
        assert!((result(&s, key) - p).abs() < 5e-4, "{key}");
        assert_eq!(printed(&s, key), p);
    }
    assert_close(&s, "first_dc", 0.193_654_5, 1e-6);
    assert_close(&s, "first_db", -5.372_021, 1e-5);
    assert!(converged(&s));
    assert_close(&s, "iterations", 81.0, 0.0);
    assert_close(&s, "c", 3.163_852, 3e-4);
    assert_close(&s, "r", 4.106_619, 3e-4);
    assert_close(&s, "a", 1.448_151, 1e-5);
    assert_close(&s, "b", -43.267_80, 1e-4);
    // the two readings end close together: the gradients steer the path, the
    // observations fix the optimum
    let sw = solve("lsm-2d", &Record::new()).unwrap();
    for (key, tol) in [("c", 1e-3), ("r", 1e-2), ("a", 1e-2), ("b", 0.5)] {
        assert!(
            (result(&s, key) - result(&sw, key)).abs() < tol,
            "{key}: patch-edge {} vs search-window {}",
            result(&s, key),
            result(&sw, key)
        );
    }
    assert!(has_note(
        &s,
        NoteKind::Rounding,
        "patch-edge gradients give, rounded"
    ));
    assert!(has_note(&s, NoteKind::Convention, "zig-zags"));
}

#[test]
fn an_iteration_limit_ends_as_not_converged_with_the_last_increments() {
    let s = solve(
        "lsm-2d",
        &Record::new()
            .with("gradients", text("patch-edge"))
            .with("max_iterations", 30.0),
    )
    .unwrap();
    assert!(!converged(&s));
    assert_eq!(status(&s), "not-converged");
    assert_close(&s, "iterations", 30.0, 0.0);
    assert!(has_note(
        &s,
        NoteKind::Warning,
        "Not converged within the limit of 30"
    ));
    assert!(has_note(
        &s,
        NoteKind::Warning,
        "The last increments were dc = "
    ));
}

// ------------------------------------------------------------ how runs end

#[test]
fn a_flat_patch_is_degenerate() {
    let flat = Value::numbers(&[5.0; 12]);
    let s = solve("lsm-1d", &Record::new().with("search", flat)).unwrap();
    assert_eq!(status(&s), "degenerate");
    assert!(!converged(&s));
    assert_eq!(s.result.get("first_dc"), Some(&Value::Null));
    assert_close(&s, "iterations", 0.0, 0.0);
    assert_close(&s, "c", 8.0, 0.0);
    assert!(has_note(&s, NoteKind::Warning, "flat"));
    let flat2 = Value::matrix(&vec![vec![7.0; 6]; 6]);
    let s = solve("lsm-2d", &Record::new().with("search", flat2)).unwrap();
    assert_eq!(status(&s), "degenerate");
    // natively through the core as well
    let m = match_1d(
        &[1.0, 2.0, 3.0],
        &[4.0; 5],
        Params::shift(2.0, 0.0, 1.0, 0.0),
        stated(Model::Shift, 10),
    )
    .unwrap();
    assert!(matches!(m.status, Status::Degenerate { .. }));
}

#[test]
fn a_start_outside_the_pull_in_range_and_a_patch_leaving_the_window() {
    // a shift of 6 px is beyond the pull-in range of the generated texture:
    // the first steps throw the patch out of the search window
    let s = solve(
        "lsm-affine",
        &Record::new().with("shift_c", 6.0).with("shift_r", 0.0),
    )
    .unwrap();
    assert_eq!(status(&s), "left-window");
    assert!(!converged(&s));
    assert!(has_note(&s, NoteKind::Warning, "outside the search window"));
    // a start far from a rotated patch (35°, 3 px): the run neither
    // converges nor leaves the window, it ends at the iteration limit with
    // its last increments reported
    let s = solve(
        "lsm-affine",
        &Record::new()
            .with("shift_c", 3.0)
            .with("shift_r", 1.5)
            .with("rotation_deg", 35.0),
    )
    .unwrap();
    assert_eq!(status(&s), "not-converged");
    assert!(has_note(&s, NoteKind::Warning, "The last increments were"));
    // the same shift with a smaller rotation (20°) is within the pull-in
    // range and converges
    let s = solve(
        "lsm-affine",
        &Record::new()
            .with("shift_c", 3.0)
            .with("shift_r", 1.5)
            .with("rotation_deg", 20.0),
    )
    .unwrap();
    assert_eq!(status(&s), "converged");
    // 1-D: a start at the window's left end walks out
    let s = solve("lsm-1d", &Record::new().with("c0", 4.0)).unwrap();
    assert_eq!(status(&s), "left-window", "{:?}", s.result);
    assert!(
        has_note(&s, NoteKind::Warning, "left the search window")
            || has_note(&s, NoteKind::Warning, "outside the search window")
    );
}

// ------------------------------------------------------------ synthetic

#[test]
fn synthetic_shifts_up_to_one_pixel_are_recovered_to_a_hundredth() {
    let mut rng = Lcg(42);
    for k in 0..25 {
        let (dc, dr) = (rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
        let truth = affine_from(dc, dr, 0.0, 1.0, 0.0, 1.0, 0.0);
        let pair = synthetic_pair(15, &truth, 0.0, k).unwrap();
        let start = Params::shift(pair.centre, pair.centre, 1.0, 0.0);
        for model in [Model::Shift, Model::ShiftRadiometric] {
            let m = match_2d(&pair.template, &pair.search, start, stated(model, 100)).unwrap();
            assert!(m.converged(), "{dc} {dr}: {:?}", m.status);
            let (c, r) = (m.params.a[2] - pair.centre, m.params.a[5] - pair.centre);
            assert!(
                (c - dc).abs() < 0.01 && (r - dr).abs() < 0.01,
                "{dc} {dr} → {c} {r}"
            );
        }
    }
}

/// A smooth continuous texture: a sum of sinusoids of 18 to 40 px wavelength
/// (fixed by `seed`), so that images sampled from it at shifted positions are
/// not themselves bilinear interpolations of each other.
fn texture(seed: u64) -> impl Fn(f64, f64) -> f64 {
    let mut rng = Lcg(seed);
    let waves: Vec<(f64, f64, f64, f64)> = (0..5)
        .map(|_| {
            let k = std::f64::consts::TAU / rng.range(18.0, 40.0);
            let dir = rng.range(0.0, std::f64::consts::PI);
            (
                k * dir.cos(),
                k * dir.sin(),
                rng.range(0.0, 6.3),
                rng.range(10.0, 30.0),
            )
        })
        .collect();
    move |x, y| {
        100.0
            + waves
                .iter()
                .map(|(kx, ky, ph, amp)| amp * (kx * x + ky * y + ph).sin())
                .sum::<f64>()
    }
}

/// The sum of squared differences between `template` and the search window
/// resampled bilinearly at the shift `(sc, sr)` from `centre`.
fn ssd(template: &Grid, search: &Grid, centre: f64, sc: f64, sr: f64) -> f64 {
    let (n, h) = (template.width(), (template.width() / 2) as f64);
    let mut total = 0.0;
    for r in 0..template.height() {
        for c in 0..n {
            let (x, y) = (centre + sc + c as f64 - h, centre + sr + r as f64 - h);
            let b = resample::bilinear(search, x, y).expect("inside the window");
            total += (template.get(c, r).unwrap() - b.value).powi(2);
        }
    }
    total
}

#[test]
fn shifts_of_a_continuous_texture_reach_the_least_squares_optimum_in_2d() {
    // The template is sampled from the texture itself at the shifted
    // positions, not resampled from the search window, so the bilinear
    // interpolation the matching works with only approximates the texture.
    // The matching still ends within 0.01 px of the least-squares optimum of
    // its own model (a grid search of the sum of squared differences in
    // steps of 0.001 px; the gap comes from the central-difference
    // gradients). That optimum lies within 0.15 px of the true shift: the
    // bilinear interpolation's own bias, measured up to 0.10 px for this
    // texture. Within the model, synthetic_pair's shifts are recovered
    // exactly (the test above).
    let mut rng = Lcg(2026);
    let (n, m) = (15usize, 31usize);
    let centre = (m / 2) as f64;
    let h = (n / 2) as f64;
    let mut worst_bias: f64 = 0.0;
    for k in 0..8 {
        let f = texture(100 + k);
        let (dc, dr) = (rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
        let search = Grid::from_fn(m, m, |c, r| f(c as f64, r as f64));
        let template = Grid::from_fn(n, n, |c, r| {
            f(centre + dc + c as f64 - h, centre + dr + r as f64 - h)
        });
        let out = match_2d(
            &template,
            &search,
            Params::shift(centre, centre, 1.0, 0.0),
            stated(Model::Shift, 100),
        )
        .unwrap();
        assert!(out.converged(), "{dc} {dr}: {:?}", out.status);
        let (c, r) = (out.params.a[2] - centre, out.params.a[5] - centre);
        // the grid minimum of the SSD within ±0.02 px of the matching's answer
        let mut best = (c, r, ssd(&template, &search, centre, c, r));
        for i in -20..=20 {
            for j in -20..=20 {
                let (sc, sr) = (c + i as f64 * 0.001, r + j as f64 * 0.001);
                let v = ssd(&template, &search, centre, sc, sr);
                if v < best.2 {
                    best = (sc, sr, v);
                }
            }
        }
        assert!(
            (best.0 - c).abs() < 0.01 && (best.1 - r).abs() < 0.01,
            "{dc} {dr}: matching {c} {r}, SSD minimum {} {}",
            best.0,
            best.1
        );
        let bias = (c - dc).abs().max((r - dr).abs());
        assert!(bias < 0.15, "{dc} {dr} → {c} {r}");
        worst_bias = worst_bias.max(bias);
    }
    // the texture is not a bilinear copy: the interpolation's bias shows
    assert!(worst_bias > 0.01, "largest bias {worst_bias}");
}

#[test]
fn shifts_of_a_continuous_profile_are_recovered_to_two_hundredths_in_1d() {
    // in 1-D the bilinear (linear) interpolation's bias stays below 0.02 px
    // for this profile; measured largest error 0.0115 px
    let mut rng = Lcg(1717);
    for k in 0..20 {
        let f = texture(300 + k);
        let profile = |x: f64| f(x, 0.37 * x);
        let dc = rng.range(-1.0, 1.0);
        let search: Vec<f64> = (0..31).map(|c| profile(c as f64)).collect();
        let template: Vec<f64> = (0..11)
            .map(|c| profile(15.0 + dc + c as f64 - 5.0))
            .collect();
        for model in [Model::Shift, Model::ShiftRadiometric] {
            let out = match_1d(
                &template,
                &search,
                Params::shift(15.0, 0.0, 1.0, 0.0),
                stated(model, 100),
            )
            .unwrap();
            assert!(out.converged(), "{dc}: {:?}", out.status);
            let c = out.params.a[2] - 15.0;
            assert!((c - dc).abs() < 0.02, "{model:?} {dc} → {c}");
        }
    }
}

#[test]
fn the_1d_affine_radiometric_model_recovers_scale_shift_gain_and_offset() {
    // T(u) = a7·S(a1·u + a3) + a8 with S linear between its samples, so the
    // model fits exactly: every parameter comes back
    let search: Vec<f64> = (0..41)
        .map(|c| {
            let x = c as f64;
            90.0 + 30.0 * (x / 4.0).sin() + 12.0 * (x / 2.3 + 1.0).cos()
        })
        .collect();
    let linear = |x: f64| {
        let i = (x.floor() as usize).min(search.len() - 2);
        let t = x - i as f64;
        search[i] * (1.0 - t) + search[i + 1] * t
    };
    let (a1, a3, gain, offset) = (1.06, 20.35, 1.3, -12.0);
    let template: Vec<f64> = (0..15)
        .map(|i| gain * linear(a1 * (i as f64 - 7.0) + a3) + offset)
        .collect();
    let out = match_1d(
        &template,
        &search,
        Params::shift(20.0, 0.0, 1.0, 0.0),
        stated(Model::AffineRadiometric, 100),
    )
    .unwrap();
    assert!(out.converged(), "{:?}", out.status);
    let p = out.params.a;
    for (name, got, want, tol) in [
        // to the convergence tolerance (a last step moving no pixel by more
        // than 1e-4 px is not taken further)
        ("a1", p[0], a1, 2e-5),
        ("a3", p[2], a3, 1e-4),
        ("gain", p[6], gain, 1e-4),
        ("offset", p[7], offset, 1e-2),
    ] {
        assert!((got - want).abs() < tol, "{name}: {got} vs {want}");
    }
    // the rows stay put in 1-D
    assert_eq!((p[3], p[4], p[5]), (0.0, 1.0, 0.0));
}

#[test]
fn the_affine_radiometric_model_recovers_known_parameters() {
    let s = solve("lsm-affine", &Record::new()).unwrap();
    assert!(converged(&s));
    let est = list(s.result.get("parameters"));
    let truth = list(s.result.get("true_parameters"));
    assert_eq!(est.len(), 8);
    for (e, t) in est.iter().zip(&truth) {
        assert!((e - t).abs() < 1e-3, "{est:?} vs {truth:?}");
    }
    assert!(result(&s, "sigma0") < 0.01);
    assert!(has_note(&s, NoteKind::Convention, "two stacked systems"));
    let mut rng = Lcg(7);
    for k in 0..8 {
        let inputs = Record::new()
            .with("shift_c", rng.range(-1.5, 1.5))
            .with("shift_r", rng.range(-1.5, 1.5))
            .with("rotation_deg", rng.range(-8.0, 8.0))
            .with("scale", rng.range(0.93, 1.07))
            .with("shear", rng.range(-0.05, 0.05))
            .with("gain", rng.range(0.7, 1.5))
            .with("offset", rng.range(-30.0, 30.0))
            .with("seed", k as f64);
        let s = solve("lsm-affine", &inputs).unwrap();
        assert!(converged(&s), "{inputs:?}: {}", status(&s));
        let est = list(s.result.get("parameters"));
        let truth = list(s.result.get("true_parameters"));
        for (j, (e, t)) in est.iter().zip(&truth).enumerate() {
            let tol = if j == 7 { 0.05 } else { 2e-3 };
            assert!((e - t).abs() < tol, "a{}: {e} vs {t} ({inputs:?})", j + 1);
        }
    }
}

#[test]
fn noise_raises_sigma0_as_expected() {
    let mut last = 0.0;
    for noise in [0.0, 1.0, 3.0, 6.0] {
        let s = solve("lsm-affine", &Record::new().with("noise", noise)).unwrap();
        assert!(converged(&s), "noise {noise}");
        let s0 = result(&s, "sigma0");
        assert!(s0 > last, "σ0 {s0} at noise {noise} not above {last}");
        last = s0;
        if noise > 0.0 {
            let expected = result(&s, "expected_sigma0");
            assert!(
                (s0 / expected - 1.0).abs() < 0.2,
                "noise {noise}: σ0 {s0}, expected {expected}"
            );
            // the parameters' standard deviations grow with the noise, and
            // the estimates stay within a few of them
            let sd = list(s.result.get("std_dev"));
            let est = list(s.result.get("parameters"));
            let truth = list(s.result.get("true_parameters"));
            for j in 0..8 {
                assert!((est[j] - truth[j]).abs() < 5.0 * sd[j] + 1e-6, "a{}", j + 1);
            }
        } else {
            assert_eq!(s.result.get("expected_sigma0"), Some(&Value::Null));
        }
    }
}

#[test]
fn the_example_and_the_core_are_one_computation() {
    let t = [1.0, 2.0, 9.0, 9.0, 8.0, 2.0, 1.0];
    let sw = [1.0, 2.0, 2.0, 1.0, 1.0, 3.0, 8.0, 8.0, 6.0, 1.0, 1.0, 1.0];
    let m = match_1d(
        &t,
        &sw,
        Params::shift(7.0, 0.0, 1.0, 0.0),
        stated(Model::ShiftRadiometric, 100),
    )
    .unwrap();
    let s = solve("lsm-1d", &Record::new().with("radiometric", true)).unwrap();
    assert_eq!(result(&s, "c"), m.params.a[2] + 1.0);
    assert_eq!(result(&s, "a"), m.params.gain());
    assert_eq!(Some(result(&s, "sigma0")), m.sigma0());
    // a 2-D run on a one-row-high window is refused cleanly, not a panic
    let g = Grid::from_rows("t", &[t.to_vec()]).unwrap();
    let s2 = Grid::from_rows("s", &[sw.to_vec()]).unwrap();
    let e = match_2d(
        &g,
        &s2,
        Params::shift(7.0, 0.0, 1.0, 0.0),
        stated(Model::Shift, 10),
    )
    .unwrap_err();
    assert_eq!(e.field(), Some("search"));
    assert!(e.to_string().contains("at least 2×2"), "{e}");
}

// ------------------------------------------------------------ bad inputs

fn err(id: &str, inputs: Record) -> String {
    solve(id, &inputs).unwrap_err().to_string()
}

#[test]
fn bad_inputs_name_the_field() {
    let e = err("lsm-1d", Record::new().with("c0", 2.0));
    assert!(
        e.starts_with("c0: the patch does not fit at the start"),
        "{e}"
    );
    let e = err(
        "lsm-1d",
        Record::new().with("search", Value::numbers(&[1.0, 2.0, 3.0])),
    );
    assert!(
        e.starts_with("template: has 7 values, more than the 3 of the search window"),
        "{e}"
    );
    let e = err(
        "lsm-1d",
        Record::new().with("template", Value::numbers(&[1.0])),
    );
    assert!(e.starts_with("template: needs at least 3"), "{e}");
    let e = err("lsm-1d", Record::new().with("max_iterations", 0.0));
    assert!(e.starts_with("max_iterations: must be at least 1"), "{e}");
    let e = err("lsm-1d", Record::new().with("radiometric", text("yes")));
    assert!(e.starts_with("radiometric: must be true or false"), "{e}");
    let e = err("lsm-1d", Record::new().with("c0", f64::NAN));
    assert_eq!(e, "c0: is NaN; give a number");
    let e = err("lsm-2d", Record::new().with("gradients", text("sobel")));
    assert!(
        e.starts_with("gradients: \"sobel\" is not one of the choices"),
        "{e}"
    );
    let e = err("lsm-2d", Record::new().with("r0", 6.0));
    assert!(
        e.starts_with("c0: the patch does not fit at the start"),
        "{e}"
    );
    let e = err(
        "lsm-2d",
        Record::new().with("template", Value::matrix(&[vec![1.0, 2.0], vec![3.0]])),
    );
    assert!(
        e.starts_with("template: rows must all have the same length"),
        "{e}"
    );
    let big = Value::matrix(&vec![vec![1.0; 65]; 65]);
    let e = err("lsm-2d", Record::new().with("search", big));
    assert!(e.starts_with("search: is larger than 64×64"), "{e}");
    let e = err("lsm-affine", Record::new().with("patch_size", 20.0));
    assert!(e.starts_with("patch_size: must be odd"), "{e}");
    let e = err("lsm-affine", Record::new().with("scale", 0.0));
    assert!(e.starts_with("scale: must be at least 0.5"), "{e}");
    let e = err("lsm-affine", Record::new().with("noise", -1.0));
    assert!(e.starts_with("noise: must be at least 0"), "{e}");
    let e = err("lsm-affine", Record::new().with("spin", 1.0));
    assert!(e.starts_with("spin: unknown field"), "{e}");
}

mod parts_common;

/// Issue 30, item 2: the steps are data, and every practice box's hints
/// come from the relation that computes its value.
#[test]
fn steps_are_data_and_practice_hints_are_keyed() {
    let topic = photogrammetry_playground::examples::matching::TOPIC;
    let n = parts_common::steps_are_data_and_hints_are_keyed(&topic, 3);
    // the first normal equation, the first shifts, the positions after
    // them, the scale and the rotation have their numbers put in
    assert!(n >= 3 * (4 + 4 + 2), "{n} boxes with numbers");
    let s = solve("lsm-1d", &Record::new()).unwrap();
    let ne = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Normal"))
        .unwrap();
    let dc = ne
        .parts
        .iter()
        .find(|r| r.key.as_deref() == Some("first_dc"))
        .unwrap();
    assert_eq!(
        dc.question_latex(),
        r"dc = \frac{-11.5}{39} = \;?",
        "the first shift by hand"
    );
}
