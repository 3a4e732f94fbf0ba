//! Seed 000, Example 4 and seed 004, Table 9.5.1: exact values, printed
//! values and notes, property tests of every model (fixed seeds), and every
//! class of bad input.
#![cfg(not(target_arch = "wasm32"))]

use photogrammetry_playground::examples::transformations::{CHECK_POINTS, FIDUCIALS};
use photogrammetry_playground::examples::{parse_inputs, solve};
use photogrammetry_playground::solution::{NoteKind, Record, Solution, Value};
use photogrammetry_playground::transform::{fit, Model, PointPair, Transform};

// ------------------------------------------------------------- helpers

fn list(s: &Solution, key: &str) -> Vec<f64> {
    match s.result.get(key) {
        Some(Value::List(xs)) => xs.iter().map(|x| x.as_f64().expect("number")).collect(),
        other => panic!("result {key} of {} is {other:?}", s.id),
    }
}

fn printed(s: &Solution, key: &str) -> Vec<f64> {
    match s.textbook.as_ref().and_then(|t| t.get(key)) {
        Some(Value::List(xs)) => xs.iter().map(|x| x.as_f64().expect("number")).collect(),
        other => panic!("printed {key} of {} is {other:?}", s.id),
    }
}

fn assert_all_close(got: &[f64], want: &[f64], tol: f64, what: &str) {
    assert_eq!(got.len(), want.len(), "{what}: lengths");
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            (g - w).abs() <= tol * (1.0 + w.abs()),
            "{what}[{i}] = {g}, expected {w}"
        );
    }
}

fn has_note(s: &Solution, kind: NoteKind, needle: &str) -> bool {
    s.notes
        .iter()
        .any(|n| n.kind == kind && n.text.contains(needle))
}

fn err(id: &str, inputs: Record) -> String {
    solve(id, &inputs).expect_err("should fail").to_string()
}

fn points(rows: &[[f64; 4]]) -> Value {
    Value::matrix(&rows.iter().map(|r| r.to_vec()).collect::<Vec<_>>())
}

/// A tiny deterministic PRNG (xorshift64*), uniform and normal draws.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
    fn normal(&mut self) -> f64 {
        let (u1, u2) = (self.next().max(1e-300), self.next());
        (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
    }
}

// ------------------------------------------------------------- Example 4

/// Computed independently in exact rational arithmetic (Python fractions)
/// from the seed's table with x′ = c, y′ = −r.
const SIM_X: [f64; 4] = [
    0.042_600_109_339_176_74,
    -4.440_877_385_447_242e-6,
    -115.034_781_491_015_72,
    115.037_143_335_077_93,
];
const SIM_V: [f64; 8] = [
    0.006_423_493_5,
    0.009_486_293_2,
    0.005_729_309_3,
    -0.005_862_335_1,
    -0.013_751_726_9,
    -0.001_465_173_2,
    0.001_598_924_0,
    -0.002_158_784_9,
];
const AFF_X: [f64; 6] = [
    0.042_600_239_515_097_3,
    7.333_900_103_913_863e-6,
    -115.027_322_254_376_61,
    -1.547_666_341_339_314_6e-6,
    0.042_599_978_625_240_925,
    115.028_977_279_414_1,
];
const AFF_V: [f64; 8] = [
    0.006_077_894_7,
    0.001_812_470_7,
    0.006_076_748_9,
    0.001_812_129_0,
    -0.006_078_753_6,
    -0.001_812_726_9,
    -0.006_075_889_9,
    -0.001_811_872_9,
];

#[test]
fn example_4a_similarity_exact_and_printed() {
    let s = solve("fiducial-similarity", &Record::new()).unwrap();
    assert_all_close(&list(&s, "parameters"), &SIM_X, 1e-10, "X");
    assert_all_close(&list(&s, "residuals"), &SIM_V, 1e-9, "V");
    let s0 = s.result.number("sigma0").unwrap();
    assert!((s0 - 0.009_961_383_208_414_8).abs() < 1e-12, "{s0}");
    assert_eq!(s.result.number("redundancy"), Some(4.0));
    let sd = list(&s, "std_devs");
    assert!((sd[0] - 1.877_72e-6).abs() < 1e-10 && (sd[2] - 0.008_730_467).abs() < 1e-8);
    assert!((s.result.number("scale").unwrap() - 0.042_600_11).abs() < 1e-8);
    assert!((s.result.number("rotation_deg").unwrap() + 0.005_972_8).abs() < 1e-6);
    // the printed values, and each difference explained
    assert_eq!(printed(&s, "parameters"), [0.043, 0.0, -115.03, 115.04]);
    assert_eq!(
        printed(&s, "residuals"),
        [0.006, 0.009, 0.006, -0.006, -0.014, -0.001, 0.002, -0.002]
    );
    for (p, e) in printed(&s, "residuals").iter().zip(SIM_V) {
        assert!(
            (p - e).abs() <= 0.0005,
            "printed residuals are the exact ones rounded"
        );
    }
    assert!(has_note(&s, NoteKind::Erratum, "[−y′, x′, 0, 1]"));
    assert!(has_note(
        &s,
        NoteKind::Erratum,
        "stated equations with y′ = −r"
    ));
    assert!(has_note(&s, NoteKind::Erratum, "σ0 = 113 mm"));
    assert!(has_note(
        &s,
        NoteKind::Rounding,
        "-115.035 to three decimals"
    ));
    assert!(has_note(
        &s,
        NoteKind::Rounding,
        "115.037 to three decimals"
    ));
    assert!(has_note(&s, NoteKind::Rounding, "would reach 2.16 mm"));
    assert!(has_note(
        &s,
        NoteKind::Rounding,
        "The printed residuals are the exact values"
    ));
    assert!(has_note(&s, NoteKind::Convention, "x′ = c, y′ = −r"));
    // the steps show A as printed and the axis table
    let a = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Design"))
        .unwrap();
    assert!(a
        .substituted
        .contains(r"48.15 & 2699.98 & 1 & 0 \\ -2699.98 & 48.15 & 0 & 1"));
    assert!(s.steps[0].title.contains("y′ = −r"));
    let titles: Vec<&str> = s.steps.iter().map(|st| st.title.as_str()).collect();
    for t in [
        "Observation equations",
        "Normal equations",
        "Solution",
        "Residuals",
        "Standard deviation of unit weight",
        "Precision of the parameters",
        "Inverse transformation",
    ] {
        assert!(titles.contains(&t), "step {t} missing: {titles:?}");
    }
    // the inverse maps the photo back to (c, −r)
    let inv = Transform::new(Model::Similarity, list(&s, "inverse_parameters")).unwrap();
    let fwd = Transform::new(Model::Similarity, SIM_X.to_vec()).unwrap();
    let (x, y) = fwd.apply(48.15, -2699.98).unwrap();
    let (u, v) = inv.apply(x, y).unwrap();
    assert!((u - 48.15).abs() < 1e-9 && (v + 2699.98).abs() < 1e-9);
}

#[test]
fn example_4b_affine_exact_and_printed() {
    let s = solve("fiducial-affine", &Record::new()).unwrap();
    assert_all_close(&list(&s, "parameters"), &AFF_X, 1e-10, "X");
    assert_all_close(&list(&s, "residuals"), &AFF_V, 1e-9, "V");
    let s0 = s.result.number("sigma0").unwrap();
    assert!((s0 - 0.008_968_642_276_43).abs() < 1e-12, "{s0}");
    assert_eq!(s.result.number("redundancy"), Some(2.0));
    assert_eq!(
        s.result.get("parameter_names"),
        Some(&Value::List(
            ["a", "b", "e", "c", "d", "f"].map(Value::from).to_vec()
        ))
    );
    assert_eq!(
        printed(&s, "parameters"),
        [0.043, 0.0, -115.03, -0.0, 0.043, 115.03]
    );
    for (p, e) in printed(&s, "residuals").iter().zip(AFF_V) {
        assert!((p - e).abs() <= 0.0005);
    }
    assert!(has_note(
        &s,
        NoteKind::Convention,
        "carries −r in its y′ columns"
    ));
    assert!(has_note(&s, NoteKind::Convention, "d = -0.04259998"));
    assert!(has_note(
        &s,
        NoteKind::Rounding,
        "-115.027 to three decimals"
    ));
    assert!(has_note(
        &s,
        NoteKind::Rounding,
        "115.029 to three decimals"
    ));
    assert!(has_note(&s, NoteKind::Rounding, "a = 0.04260024 → 0.043"));
    let a = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Design"))
        .unwrap();
    assert!(a
        .substituted
        .contains(r"48.15 & -2699.98 & 1 & 0 & 0 & 0 \\ 0 & 0 & 0 & 48.15 & -2699.98 & 1"));
}

#[test]
fn example_4_with_other_points_has_no_textbook_but_solves() {
    let mut pts = FIDUCIALS;
    pts[0][2] = -113.102;
    let s = solve(
        "fiducial-similarity",
        &Record::new().with("points", points(&pts)),
    )
    .unwrap();
    assert!(s.textbook.is_none());
    assert!(!has_note(&s, NoteKind::Erratum, "[−y′, x′, 0, 1]"));
    assert!((list(&s, "residuals")[0] - SIM_V[0]).abs() > 0.01);
    // two points determine a similarity exactly
    let s = solve(
        "fiducial-similarity",
        &Record::new().with("points", points(&FIDUCIALS[..2])),
    )
    .unwrap();
    assert_eq!(s.result.get("sigma0"), Some(&Value::Null));
    assert_eq!(s.result.get("std_devs"), Some(&Value::Null));
    assert!(has_note(&s, NoteKind::Warning, "No redundancy"));
}

#[test]
fn transform_fit_defaults_reproduce_example_4_in_the_table_names() {
    let s = solve("transform-fit", &Record::new()).unwrap();
    assert_eq!(s.result.get("model"), Some(&Value::from("helmert")));
    let x = list(&s, "parameters");
    assert_all_close(
        &x,
        &[SIM_X[0], -SIM_X[1], SIM_X[2], SIM_X[3]],
        1e-10,
        "helmert",
    );
    assert_all_close(&list(&s, "residuals"), &SIM_V, 1e-9, "V");
    assert_eq!(printed(&s, "parameters"), [0.043, -0.0, -115.03, 115.04]);
    assert!(has_note(&s, NoteKind::Convention, "b of the other sign"));

    let s = solve("transform-fit", &Record::new().with("model", "affine")).unwrap();
    // the table's (a, b, c, d, e, f) are Example 4's (a, b, e, c, d, f)
    assert_all_close(&list(&s, "parameters"), &AFF_X, 1e-10, "affine");
    assert_eq!(
        printed(&s, "parameters"),
        [0.043, 0.0, -115.03, -0.0, 0.043, 115.03]
    );
}

#[test]
fn the_projective_model_is_solved_linearised_with_the_corrected_denominator() {
    let s = solve(
        "transform-fit",
        &Record::new()
            .with("model", "projective")
            .with("point_set", "control-12"),
    )
    .unwrap();
    assert!(has_note(&s, NoteKind::Erratum, "a7·u + a8 + 1"));
    assert!(has_note(&s, NoteKind::Erratum, "a7·u + a8·v + 1"));
    // and that, unlike the other models, a shift of the targets moves a1 … a6
    // (see shifting_the_targets_changes_only_the_shift_parameters)
    assert!(has_note(
        &s,
        NoteKind::Convention,
        "a1 … a6 all take up part of the shift"
    ));
    let obs = &s.steps[1];
    assert!(obs.text.contains("linearised form"));
    assert!(obs.formula.contains(r"a_7\,u x"));
    // V = D·(x̂ − x) for the linearised equations
    let v = list(&s, "residuals");
    let x = list(&s, "parameters");
    let pr = match s.result.get("point_residuals") {
        Some(Value::List(rows)) => rows
            .iter()
            .flat_map(|r| match r {
                Value::List(xy) => xy.iter().map(|z| z.as_f64().unwrap()).collect(),
                _ => vec![],
            })
            .collect::<Vec<f64>>(),
        _ => panic!(),
    };
    let all: Vec<[f64; 4]> = FIDUCIALS.iter().chain(&CHECK_POINTS).copied().collect();
    for (i, p) in all.iter().enumerate() {
        let d = x[6] * p[0] + x[7] * (-p[1]) + 1.0;
        assert!((v[2 * i] - d * pr[2 * i]).abs() < 1e-12);
        assert!((v[2 * i + 1] - d * pr[2 * i + 1]).abs() < 1e-12);
    }
    assert_eq!(s.result.number("redundancy"), Some(16.0));
}

#[test]
fn the_prepared_sets_fit_every_model() {
    for m in Model::TABLE {
        let s = solve(
            "transform-fit",
            &Record::new()
                .with("model", m.id())
                .with("point_set", "control-12"),
        )
        .unwrap_or_else(|e| panic!("{m:?}: {e}"));
        let r = s.result.number("redundancy").unwrap();
        assert_eq!(r as usize, 24 - m.n_params(), "{m:?}");
        let s0 = s.result.number("sigma0").unwrap();
        assert!(s0 > 0.0 && s0 < 0.01, "{m:?}: σ0 = {s0}");
        assert!(s.result.number("condition").unwrap() < 1e8, "{m:?}");
        // the points used are reported, so the table can show them
        match s.inputs.get("points") {
            Some(Value::List(rows)) => assert_eq!(rows.len(), 12),
            other => panic!("{other:?}"),
        }
        assert_eq!(
            list(&s, "parameters").len(),
            m.n_params(),
            "{m:?} parameters in the table's order"
        );
    }
    let s = solve(
        "transform-fit",
        &Record::new()
            .with("model", "projective")
            .with("point_set", "fiducials"),
    )
    .unwrap();
    assert_eq!(s.result.number("redundancy"), Some(0.0));
    assert_eq!(s.result.get("sigma0"), Some(&Value::Null));
}

#[test]
fn pseudo_affine_from_the_fiducial_diamond_warns_of_a_nearly_singular_system() {
    let s = solve(
        "transform-fit",
        &Record::new().with("model", "pseudo-affine"),
    )
    .unwrap();
    assert!(s.result.number("condition").unwrap() > 1e8);
    assert!(has_note(&s, NoteKind::Warning, "nearly singular"));
    assert!(has_note(&s, NoteKind::Warning, "diamond"));
}

#[test]
fn polynomials_have_the_total_degree_terms_and_say_so() {
    assert_eq!(Model::Polynomial2.n_params(), 12);
    assert_eq!(Model::Polynomial3.n_params(), 20);
    assert_eq!(
        Model::Polynomial3.param_names()[6..10],
        ["a41", "a32", "a23", "a14"]
    );
    let s = solve(
        "transform-fit",
        &Record::new()
            .with("model", "polynomial-2")
            .with("point_set", "control-12"),
    )
    .unwrap();
    assert!(has_note(&s, NoteKind::Convention, "p + q ≤ k"));
}

#[test]
fn closed_form_inverses_round_trip_and_the_others_say_none() {
    let cases = [
        (Model::Helmert, vec![0.8, 0.3, 5.0, -2.0]),
        (Model::Similarity, vec![0.8, 0.3, 5.0, -2.0]),
        (Model::Affine, vec![0.8, 0.1, 5.0, -0.2, 1.1, -2.0]),
        (Model::FiducialAffine, vec![0.8, 0.1, 5.0, -0.2, 1.1, -2.0]),
        (
            Model::Projective,
            vec![0.8, 0.1, 5.0, -0.2, 1.1, -2.0, 0.01, -0.02],
        ),
    ];
    for (m, p) in cases {
        let t = Transform::new(m, p).unwrap();
        let inv = t.inverse().unwrap().expect("closed form");
        for (u, v) in [(3.0, 7.0), (-4.5, 2.25), (0.0, 0.0)] {
            let (x, y) = t.apply(u, v).unwrap();
            let (bu, bv) = inv.apply(x, y).unwrap();
            assert!((bu - u).abs() < 1e-10 && (bv - v).abs() < 1e-10, "{m:?}");
        }
    }
    for m in [
        Model::PseudoAffine,
        Model::Conformal2,
        Model::Polynomial2,
        Model::Polynomial3,
    ] {
        let t = Transform::new(m, vec![0.5; m.n_params()]).unwrap();
        assert_eq!(t.inverse(), Ok(None), "{m:?}");
    }
    let singular = Transform::new(Model::Affine, vec![1.0, 2.0, 0.0, 2.0, 4.0, 0.0]).unwrap();
    assert!(singular
        .inverse()
        .unwrap_err()
        .to_string()
        .contains("singular"));
}

// ------------------------------------------------------------- properties

/// True parameters per model: Example 4's affine plus small nonlinear terms.
fn truth(m: Model) -> Vec<f64> {
    match m {
        Model::Helmert | Model::Similarity => vec![0.0426, 0.0012, -115.0, 115.0],
        Model::Affine | Model::FiducialAffine => {
            vec![0.0426, 0.0009, -115.0, -0.0007, 0.0425, 115.0]
        }
        Model::PseudoAffine => vec![2e-9, 0.0426, 0.0009, -115.0, -1e-9, -0.0007, 0.0425, 115.0],
        Model::Projective => vec![0.0426, 0.0009, -115.0, -0.0007, 0.0425, 115.0, 2e-6, -1e-6],
        Model::Conformal2 => vec![0.0426, 0.0009, 1e-8, -2e-8, -115.0, 115.0],
        Model::Polynomial2 => vec![
            -115.0, 0.0426, 0.0009, 1e-8, -2e-9, 3e-9, 115.0, -0.0007, 0.0425, -1e-9, 2e-9, 1e-8,
        ],
        Model::Polynomial3 => vec![
            -115.0, 0.0426, 0.0009, 1e-8, -2e-9, 3e-9, 1e-12, -2e-12, 1e-12, 3e-13, 115.0, -0.0007,
            0.0425, -1e-9, 2e-9, 1e-8, -1e-12, 2e-13, 1e-12, -2e-12,
        ],
    }
}

/// `n` points over a 5400 × 5400 pixel photo (v = −r), mapped by `t`, with
/// normal noise of `sigma` on x and y.
fn generate(t: &Transform, n: usize, sigma: f64, rng: &mut Rng) -> Vec<PointPair> {
    (0..n)
        .map(|_| {
            let (u, v) = (rng.uniform(0.0, 5400.0), rng.uniform(-5400.0, 0.0));
            let (x, y) = t.apply(u, v).unwrap();
            PointPair {
                u,
                v,
                x: x + sigma * rng.normal(),
                y: y + sigma * rng.normal(),
            }
        })
        .collect()
}

fn all_models() -> Vec<Model> {
    Model::TABLE
        .into_iter()
        .chain([Model::Similarity, Model::FiducialAffine])
        .collect()
}

#[test]
fn noise_free_points_recover_the_parameters_exactly() {
    let mut rng = Rng(0x5EED_0004);
    for m in all_models() {
        let t = Transform::new(m, truth(m)).unwrap();
        let pts = generate(&t, m.min_points() + 6, 0.0, &mut rng);
        let f = fit(m, &pts).unwrap_or_else(|e| panic!("{m:?}: {e}"));
        // each parameter's error, times the largest value its column takes,
        // moves no coordinate by more than 1e-8 mm
        for (j, (est, tru)) in f.transform.params.iter().zip(&t.params).enumerate() {
            let col = f.a.iter().map(|r| r[j].abs()).fold(0.0, f64::max);
            assert!(
                (est - tru).abs() * col < 1e-8,
                "{m:?} parameter {j}: {est} vs {tru}"
            );
        }
        assert!(f.adjustment.sigma0.unwrap() < 1e-9, "{m:?}");
        // exactly determined: also recovered (random points that are not
        // nearly on a curve of the model: redrawn until well conditioned)
        let (pts, f) = (0..50)
            .map(|_| {
                let pts = generate(&t, m.min_points(), 0.0, &mut rng);
                let f = fit(m, &pts).unwrap();
                (pts, f)
            })
            .find(|(_, f)| f.adjustment.condition < 1e6)
            .expect("a well-conditioned draw");
        assert_eq!(f.adjustment.redundancy, 2 * m.min_points() - m.n_params());
        for (p, q) in pts.iter().zip(&f.fitted) {
            assert!(
                (p.x - q[0]).abs() < 1e-7 && (p.y - q[1]).abs() < 1e-7,
                "{m:?} {} {} cond {}",
                p.x - q[0],
                p.y - q[1],
                f.adjustment.condition
            );
        }
    }
}

#[test]
fn with_noise_sigma0_estimates_the_noise() {
    let mut rng = Rng(42);
    let sigma = 0.005;
    for m in all_models() {
        let t = Transform::new(m, truth(m)).unwrap();
        let pts = generate(&t, 400, sigma, &mut rng);
        let f = fit(m, &pts).unwrap();
        let s0 = f.adjustment.sigma0.unwrap();
        assert!(
            (s0 / sigma - 1.0).abs() < 0.08,
            "{m:?}: σ0 = {s0}, noise {sigma}"
        );
    }
}

#[test]
fn shuffling_the_points_changes_nothing() {
    let mut rng = Rng(7);
    for m in all_models() {
        let t = Transform::new(m, truth(m)).unwrap();
        let pts = generate(&t, 3 * m.min_points(), 0.003, &mut rng);
        let a = fit(m, &pts).unwrap();
        // a fixed permutation: reverse, then rotate by 3
        let mut order: Vec<usize> = (0..pts.len()).rev().collect();
        order.rotate_left(3);
        let shuffled: Vec<PointPair> = order.iter().map(|&i| pts[i]).collect();
        let b = fit(m, &shuffled).unwrap();
        for (x, y) in a.transform.params.iter().zip(&b.transform.params) {
            assert!((x - y).abs() <= 1e-9 * (1.0 + x.abs()), "{m:?}: {x} vs {y}");
        }
        let (sa, sb) = (a.adjustment.sigma0.unwrap(), b.adjustment.sigma0.unwrap());
        assert!((sa - sb).abs() < 1e-12, "{m:?}");
        for (k, &i) in order.iter().enumerate() {
            let (ra, rb) = (a.point_residuals[i], b.point_residuals[k]);
            assert!(
                (ra[0] - rb[0]).abs() < 1e-8 && (ra[1] - rb[1]).abs() < 1e-8,
                "{m:?} {ra:?} {rb:?}"
            );
        }
    }
}

#[test]
fn shifting_the_targets_only_changes_the_shift_parameters() {
    let mut rng = Rng(99);
    let (tx, ty) = (12.5, -7.25);
    for m in all_models() {
        let t = Transform::new(m, truth(m)).unwrap();
        let pts = generate(&t, 3 * m.min_points(), 0.003, &mut rng);
        let moved: Vec<PointPair> = pts
            .iter()
            .map(|p| PointPair {
                x: p.x + tx,
                y: p.y + ty,
                ..*p
            })
            .collect();
        let a = fit(m, &pts).unwrap().transform.params;
        let b = fit(m, &moved).unwrap().transform.params;
        let mut expected = a.clone();
        match m {
            Model::Helmert | Model::Similarity => {
                expected[2] += tx;
                expected[3] += ty;
            }
            Model::Affine => {
                expected[2] += tx;
                expected[5] += ty;
            }
            Model::FiducialAffine => {
                expected[2] += tx;
                expected[5] += ty;
            }
            Model::PseudoAffine => {
                expected[3] += tx;
                expected[7] += ty;
            }
            Model::Conformal2 => {
                expected[4] += tx;
                expected[5] += ty;
            }
            Model::Polynomial2 => {
                expected[0] += tx;
                expected[6] += ty;
            }
            Model::Polynomial3 => {
                expected[0] += tx;
                expected[10] += ty;
            }
            Model::Projective => {
                // A shift of the target is again projective, but it moves
                // a1…a6 too: x + t = (a1 + t·a7)u + (a2 + t·a8)v + (a3 + t) over D.
                let (a7, a8) = (a[6], a[7]);
                for (k, d) in [
                    (0, tx * a7),
                    (1, tx * a8),
                    (2, tx),
                    (3, ty * a7),
                    (4, ty * a8),
                    (5, ty),
                ] {
                    expected[k] += d;
                }
            }
        }
        for (j, (x, y)) in expected.iter().zip(&b).enumerate() {
            assert!(
                (x - y).abs() <= 1e-9 * (1.0 + x.abs()),
                "{m:?} parameter {j}: {y}, expected {x}"
            );
        }
    }
}

// ------------------------------------------------------------- bad input

#[test]
fn too_few_points_say_how_many_more() {
    assert_eq!(
        err("transform-fit", Record::new().with("model", "polynomial-3")),
        "points: the third-order polynomial model has 20 parameters and needs at least 10 points; 4 given (6 more needed); add points in the table or choose the prepared set \"control-12\" (12 points)"
    );
    assert_eq!(
        err(
            "fiducial-affine",
            Record::new().with("points", points(&FIDUCIALS[..2]))
        ),
        "points: the affine model has 6 parameters and needs at least 3 points; 2 given (1 more needed)"
    );
    assert_eq!(
        err(
            "fiducial-similarity",
            Record::new().with("points", points(&FIDUCIALS[..1]))
        ),
        "points: the similarity model has 4 parameters and needs at least 2 points; 1 given (1 more needed)"
    );
    assert!(err(
        "fiducial-similarity",
        Record::new().with("points", Value::List(vec![]))
    )
    .starts_with("points: is empty"));
}

#[test]
fn duplicate_points_are_refused() {
    let mut pts = FIDUCIALS;
    pts[3] = pts[1];
    assert_eq!(
        err("fiducial-affine", Record::new().with("points", points(&pts))),
        "points: points 2 and 4 have the same source position (u, v) = (5353.12, -2699.13); each control point must be measured once"
    );
    let mut pts = FIDUCIALS;
    pts[2][2] = pts[0][2];
    pts[2][3] = pts[0][3];
    assert!(err(
        "fiducial-affine",
        Record::new().with("points", points(&pts))
    )
    .contains("points 1 and 3 have the same target position"));
}

#[test]
fn collinear_points_are_refused() {
    let line = [
        [0.0, 0.0, 0.0, 0.0],
        [1.0, 1.0, 1.0, 2.0],
        [2.0, 2.0, 2.0, 4.1],
        [3.0, 3.0, 3.0, 6.0],
        [4.0, 4.0, 4.0, 8.0],
        [5.0, 5.0, 5.0, 10.2],
    ];
    for model in ["affine", "pseudo-affine", "projective", "polynomial-2"] {
        let e = err(
            "transform-fit",
            Record::new()
                .with("model", model)
                .with("points", points(&line)),
        );
        assert!(
            e.starts_with("points: all 6 points lie on one line in the source system"),
            "{model}: {e}"
        );
    }
    // a similarity is fixed by any two points, on a line or not
    assert!(solve(
        "transform-fit",
        &Record::new().with("points", points(&line))
    )
    .is_ok());
    // and the second-order conformal map z = c1·w + c2·w² + c3 by any three
    // distinct points: points on a line fit, and points generated from known
    // parameters on a line are recovered
    let truth = [0.9, 0.2, 0.01, -0.02, 5.0, -3.0];
    let map = Transform::new(Model::Conformal2, truth.to_vec()).expect("parameters");
    let on_line: Vec<[f64; 4]> = (0..4)
        .map(|k| {
            let (u, v) = (k as f64 * 10.0, k as f64 * 5.0);
            let (x, y) = map.apply(u, v).expect("apply");
            [u, v, x, y]
        })
        .collect();
    let s = solve(
        "transform-fit",
        &Record::new()
            .with("model", "conformal-2")
            .with("points", points(&on_line)),
    )
    .expect("conformal-2 from points on a line");
    assert_all_close(
        &list(&s, "parameters"),
        &truth,
        1e-9,
        "conformal-2 on a line",
    );
    // three of four on a line: the projective model cannot be determined
    let three = [
        [0.0, 0.0, 0.0, 0.0],
        [1.0, 0.0, 1.0, 0.0],
        [2.0, 0.0, 2.0, 0.5],
        [0.0, 1.0, 0.0, 1.0],
    ];
    assert_eq!(
        err(
            "transform-fit",
            Record::new()
                .with("model", "projective")
                .with("points", points(&three))
        ),
        "points: points 1, 2, 3 lie on one line in the source (u, v) system; a projective transformation from four points needs no three of them on a line"
    );
    let mut target_three = three;
    target_three[2] = [2.0, 0.5, 2.0, 0.0];
    assert!(err(
        "transform-fit",
        Record::new()
            .with("model", "projective")
            .with("points", points(&target_three))
    )
    .contains("in the target (x, y) system"));
    // an exactly singular system: the uv column of A is zero
    let diamond = [
        [-1.0, 0.0, -1.0, 0.0],
        [1.0, 0.0, 1.0, 0.0],
        [0.0, 1.0, 0.0, 1.0],
        [0.0, -1.0, 0.0, -1.0],
    ];
    let e = err(
        "transform-fit",
        Record::new()
            .with("model", "pseudo-affine")
            .with("points", points(&diamond)),
    );
    assert!(
        e.starts_with("points: these points do not determine the pseudo-affine model"),
        "{e}"
    );
}

#[test]
fn non_finite_and_misshapen_points_are_refused() {
    let mut rows: Vec<Value> = FIDUCIALS.iter().map(|r| Value::numbers(r)).collect();
    rows[1] = Value::numbers(&[1.0, f64::NAN, 2.0, 3.0]);
    assert_eq!(
        err(
            "fiducial-similarity",
            Record::new().with("points", Value::List(rows.clone()))
        ),
        "points[2][2]: is NaN; give a number"
    );
    rows[1] = Value::numbers(&[1.0, 2.0, f64::INFINITY, 3.0]);
    assert_eq!(
        err(
            "transform-fit",
            Record::new().with("points", Value::List(rows.clone()))
        ),
        "points[2][3]: is infinite; give a finite number"
    );
    rows[1] = Value::numbers(&[1.0, 2.0, 3.0]);
    assert_eq!(
        err(
            "transform-fit",
            Record::new().with("points", Value::List(rows.clone()))
        ),
        "points: point 2 has 3 numbers; each point needs 4"
    );
    rows[1] = Value::from("1 2 3 4");
    assert!(err(
        "transform-fit",
        Record::new().with("points", Value::List(rows))
    )
    .contains("row 2 must be a list of numbers"));
    assert_eq!(
        err("transform-fit", Record::new().with("model", "spline")),
        "model: \"spline\" is not one of the choices (helmert, affine, pseudo-affine, projective, conformal-2, polynomial-2, polynomial-3)"
    );
    assert!(err("transform-fit", Record::new().with("point_set", "all"))
        .starts_with("point_set: \"all\" is not one of the choices"));
    let mut big = FIDUCIALS;
    big[0][0] = 2e7;
    assert!(err(
        "fiducial-affine",
        Record::new().with("points", points(&big))
    )
    .contains("point 1: u = 20000000 is beyond"));
    // the core checks its own inputs too
    let bad = [PointPair {
        u: f64::NAN,
        v: 0.0,
        x: 0.0,
        y: 0.0,
    }; 3];
    assert!(fit(Model::Affine, &bad)
        .unwrap_err()
        .to_string()
        .contains("NaN"));
}

#[test]
fn points_parse_from_text_as_the_table_sends_them() {
    let p = parse_inputs(
        "transform-fit",
        &Record::new()
            .with("points", "0 0 1 1; 1 0 2 1\n0 1 1 2; 1 1 2.5 2")
            .with("model", "affine"),
    )
    .unwrap();
    assert!(p.errors.is_empty(), "{:?}", p.errors);
    let s = solve("transform-fit", &p.inputs).unwrap();
    assert_eq!(s.result.number("redundancy"), Some(2.0));
    let p = parse_inputs(
        "transform-fit",
        &Record::new().with("points", "0 0 1; 1 0 2 1"),
    )
    .unwrap();
    assert_eq!(
        p.errors.get("points"),
        Some(&Value::from(
            "points: point 1 has 3 numbers; each point needs 4"
        ))
    );
}

mod parts_common;

/// Issue 30, item 2: the steps are data, and every practice box's hints
/// come from the relation that computes its value.
#[test]
fn steps_are_data_and_practice_hints_are_keyed() {
    let topic = photogrammetry_playground::examples::transformations::TOPIC;
    let n = parts_common::steps_are_data_and_hints_are_keyed(&topic, 3);
    // σ₀ has its numbers put in (the parameters: their symbols)
    assert!(n >= 3 * 3, "{n} boxes with numbers");
    let s = solve("fiducial-similarity", &Record::new()).unwrap();
    let sol = s.steps.iter().find(|st| st.title == "Solution").unwrap();
    let x = &sol.parts[0];
    assert_eq!(x.key.as_deref(), Some("parameters"));
    assert!(x.question_latex().ends_with(r"\;?"));
    assert!(sol
        .formula
        .starts_with(r"X = (A^\mathsf{T} A)^{-1} A^\mathsf{T} L"));
    // the model's two equations are two relations
    let obs = s
        .steps
        .iter()
        .find(|st| st.title == "Observation equations")
        .unwrap();
    assert_eq!(
        obs.formula,
        r"x = a\,x' - b\,y' + c,\quad y = b\,x' + a\,y' + d"
    );
    assert_eq!(obs.parts.len(), 2 + 8);
}
