//! Seed 000, Examples 5–9 (correlation matching), reproduced natively with
//! their numbers; the properties of the correlation coefficient and of the
//! subpixel fits; flat windows, templates that do not fit, non-concave
//! neighbourhoods and every bad-input class.
#![cfg(not(target_arch = "wasm32"))]

mod parts_common;

use photogrammetry_playground::correlation::{
    correlate_1d, correlate_2d, ncc, ncc_grid, parabola_peak, quadric_peak, Extremum,
};
use photogrammetry_playground::examples::{parse_inputs, solve};
use photogrammetry_playground::raster::Grid;
use photogrammetry_playground::solution::{NoteKind, Record, Solution, Value};

// ------------------------------------------------------------ helpers

/// A tiny deterministic PRNG (xorshift64*), so the property tests need no
/// dependency and always see the same numbers.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    /// Uniform in [lo, hi).
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn values(&mut self, n: usize) -> Vec<f64> {
        (0..n).map(|_| self.uniform(0.0, 255.0).round()).collect()
    }
}

fn num(v: &Value) -> f64 {
    v.as_f64()
        .unwrap_or_else(|| panic!("{v:?} is not a number"))
}

fn list(v: &Value) -> Vec<Value> {
    match v {
        Value::List(xs) => xs.clone(),
        other => panic!("{other:?} is not a list"),
    }
}

fn nums(v: &Value) -> Vec<f64> {
    list(v).iter().map(num).collect()
}

fn rows(v: &Value) -> Vec<Vec<f64>> {
    list(v).iter().map(nums).collect()
}

fn result<'a>(s: &'a Solution, key: &str) -> &'a Value {
    s.result
        .get(key)
        .unwrap_or_else(|| panic!("result {key} missing in {}", s.id))
}

fn printed<'a>(s: &'a Solution, key: &str) -> &'a Value {
    s.textbook
        .as_ref()
        .and_then(|t| t.get(key))
        .unwrap_or_else(|| panic!("printed {key} missing in {}", s.id))
}

fn assert_close(got: f64, expected: f64, tol: f64, what: &str) {
    assert!(
        (got - expected).abs() <= tol,
        "{what} = {got}, expected {expected}"
    );
}

fn has_note(s: &Solution, kind: NoteKind, needle: &str) -> bool {
    s.notes
        .iter()
        .any(|n| n.kind == kind && n.text.contains(needle))
}

fn notes(s: &Solution) -> String {
    s.notes
        .iter()
        .map(|n| format!("{:?}: {}", n.kind, n.text))
        .collect::<Vec<_>>()
        .join("\n")
}

fn err(id: &str, inputs: Record) -> String {
    solve(id, &inputs).unwrap_err().to_string()
}

fn vals(xs: &[f64]) -> Value {
    Value::numbers(xs)
}

fn mat(rows: &[&[f64]]) -> Value {
    Value::matrix(&rows.iter().map(|r| r.to_vec()).collect::<Vec<_>>())
}

fn keys(s: &Solution) -> Vec<&str> {
    s.result.keys().collect()
}

fn every_step_has_a_formula(s: &Solution) {
    for step in &s.steps {
        assert!(
            !step.formula.is_empty() && !step.substituted.is_empty(),
            "{}: step \"{}\" has no formula",
            s.id,
            step.title
        );
    }
}

// ------------------------------------------------------------ Example 5

#[test]
fn example_5_ncc_1d_exact_values_and_printed_ones() {
    let s = solve("ncc-1d", &Record::new()).unwrap();
    assert_eq!(
        &keys(&s)[..4],
        ["mean_template", "mean_subwindows", "rho", "best"]
    );
    assert_close(num(result(&s, "mean_template")), 32.0 / 7.0, 1e-15, "Ā");
    let means = nums(result(&s, "mean_subwindows"));
    let expected_means = [18.0, 25.0, 29.0, 28.0, 28.0, 28.0].map(|x| x / 7.0);
    for (m, e) in means.iter().zip(expected_means) {
        assert_close(*m, e, 1e-14, "B̄");
    }
    assert_eq!(means.len(), 6);
    // ρ_k = Σ(A−Ā)(B−B̄) / √(Σ(A−Ā)²·Σ(B−B̄)²), by hand with Σ(A−Ā)² = 628/7
    let saa = 628.0 / 7.0;
    let by_hand = [
        (-198.0 / 7.0) / (saa * 264.0 / 7.0f64).sqrt(),
        (-296.0 / 7.0) / (saa * 404.0 / 7.0f64).sqrt(),
        (-46.0 / 7.0) / (saa * 412.0 / 7.0f64).sqrt(),
        51.0 / (saa * 64.0f64).sqrt(),
        74.0 / (saa * 64.0f64).sqrt(),
        28.0 / (saa * 64.0f64).sqrt(),
    ];
    let rho = nums(result(&s, "rho"));
    for (k, (r, e)) in rho.iter().zip(by_hand).enumerate() {
        assert_close(*r, e, 1e-14, &format!("ρ{}", k + 1));
    }
    assert_close(rho[0], -0.486_276_637, 1e-9, "ρ1");
    assert_close(rho[3], 0.673_053_190, 1e-9, "ρ4");
    assert_close(rho[4], 0.976_586_982, 1e-9, "ρ5");
    assert_eq!(num(result(&s, "best")), 5.0);
    assert_eq!(num(result(&s, "best_c")), 8.0);
    assert_eq!(nums(result(&s, "centres")), [4.0, 5.0, 6.0, 7.0, 8.0, 9.0]);
    // printed beside exact
    assert_eq!(num(printed(&s, "mean_template")), 4.57);
    assert_eq!(
        nums(printed(&s, "rho")),
        [-0.5, -0.59, -0.09, 0.69, 0.97, 0.37]
    );
    assert_eq!(
        nums(printed(&s, "mean_subwindows")),
        [2.57, 3.57, 4.14, 4.0, 4.0, 4.0]
    );
    assert_eq!(num(printed(&s, "best")), 5.0);
    // every printed number is either the exact one at its precision or explained
    assert!(
        has_note(&s, NoteKind::Erratum, "ρ4 is printed as 0.69"),
        "{}",
        notes(&s)
    );
    assert!(has_note(&s, NoteKind::Erratum, "ρ4 = 0.6730532 ≈ 0.67"));
    assert!(has_note(&s, NoteKind::Rounding, "ρ1 is printed as −0.5"));
    assert!(has_note(&s, NoteKind::Rounding, "0.976587 rounds to 0.98"));
    assert!(has_note(&s, NoteKind::Convention, "c = k + 3"));
    for (k, (p, e)) in [-0.5, -0.59, -0.09, 0.69, 0.97, 0.37]
        .iter()
        .zip(&rho)
        .enumerate()
    {
        let rounds = ((e * 100.0).round() / 100.0 - p).abs() < 1e-9;
        // ρ2, ρ3, ρ6 round to the printed value; ρ1, ρ4, ρ5 are in notes
        assert_eq!(rounds, [1, 2, 5].contains(&k), "ρ{}", k + 1);
    }
    // the steps: template mean, sub-windows, six sub-windows, all, best
    assert_eq!(s.steps.len(), 10);
    every_step_has_a_formula(&s);
    assert!(s.steps[2]
        .substituted
        .contains(r"\frac{-28.28571}{\sqrt{89.71429 \times 37.71429}} = -0.4862766"));
    assert!(s.steps[6].substituted.contains("= 0.976587"));
}

// ------------------------------------------------------------ Example 6

#[test]
fn example_6_ncc_2d_exact_values_and_the_two_slips() {
    let s = solve("ncc-2d", &Record::new()).unwrap();
    assert_eq!(
        keys(&s),
        ["mean_a", "mean_b", "sum_dadb", "sum_da2", "sum_db2", "rho"]
    );
    assert_close(num(result(&s, "mean_a")), 529.0 / 9.0, 1e-12, "Ā");
    assert_close(num(result(&s, "mean_b")), 532.0 / 9.0, 1e-12, "B̄");
    assert_close(num(result(&s, "sum_dadb")), 10_343.0 / 9.0, 1e-9, "ΣdAdB");
    assert_close(num(result(&s, "sum_da2")), 7592.0 / 9.0, 1e-9, "ΣdA²");
    assert_close(num(result(&s, "sum_db2")), 23_444.0 / 9.0, 1e-9, "ΣdB²");
    let rho = 10_343.0 / (7592.0f64 * 23_444.0).sqrt();
    assert_close(num(result(&s, "rho")), rho, 1e-14, "ρ");
    assert_close(rho, 0.775_269_268, 1e-9, "ρ");
    assert_eq!(num(printed(&s, "mean_a")), 58.5);
    assert_eq!(num(printed(&s, "sum_db2")), 2604.89);
    assert_eq!(num(printed(&s, "rho")), 0.7753);
    assert!(
        has_note(&s, NoteKind::Erratum, "print Ā = 58.5"),
        "{}",
        notes(&s)
    );
    assert!(has_note(&s, NoteKind::Erratum, "529/9 = 58.77778"));
    assert!(has_note(&s, NoteKind::Erratum, "without the squares"));
    // the seed's sums, recomputed with its rounded means 58.8 and 59.1
    assert!(has_note(
        &s,
        NoteKind::Rounding,
        "come out as 1149.22, 843.56 and 2604.89"
    ));
    assert!(has_note(&s, NoteKind::Rounding, "0.7753 to four decimals"));
    assert_eq!(s.steps.len(), 5);
    every_step_has_a_formula(&s);
    assert!(s.steps[4]
        .substituted
        .contains(r"\frac{1149.222}{\sqrt{843.5556 \times 2604.889}} = 0.7752693"));
}

// ------------------------------------------------------------ Example 7

const EX7_EXACT: [[f64; 4]; 4] = [
    [
        -0.330_091_606,
        0.540_579_703,
        -0.174_554_804,
        -0.121_716_124,
    ],
    [
        -0.333_376_264,
        0.239_406_686,
        -0.392_101_322,
        -0.271_832_908,
    ],
    [0.058_530_514, 0.966_489_366, 0.080_562_923, 0.622_816_994],
    [
        -0.232_080_381,
        0.290_394_611,
        -0.126_764_580,
        -0.199_688_554,
    ],
];

#[test]
fn example_7_surface_exact_values_and_printed_ones() {
    let s = solve("ncc-surface", &Record::new()).unwrap();
    assert_eq!(&keys(&s)[..4], ["rho", "best_position", "best_c", "best_r"]);
    let rho = rows(result(&s, "rho"));
    assert_eq!(rho.len(), 4);
    for (i, row) in rho.iter().enumerate() {
        assert_eq!(row.len(), 4);
        for (j, r) in row.iter().enumerate() {
            assert_close(*r, EX7_EXACT[i][j], 1e-9, &format!("ρ[{i}][{j}]"));
        }
    }
    // the best window by hand: T̄ = 370/9, B̄ = 524/9, sums 6640/9, 888.9, 5900/9
    assert_close(
        rho[2][1],
        6640.0 / (8000.0f64 * 5900.0).sqrt(),
        1e-14,
        "ρ10",
    );
    assert_eq!(num(result(&s, "best_position")), 10.0);
    assert_eq!(num(result(&s, "best_c")), 3.0);
    assert_eq!(num(result(&s, "best_r")), 4.0);
    assert_eq!(num(result(&s, "best_col")), 2.0);
    assert_eq!(num(result(&s, "best_row")), 3.0);
    let p = rows(printed(&s, "rho"));
    assert_eq!(p[0], [-0.3301, 0.5405, -0.1745, -0.1217]);
    assert_eq!(num(printed(&s, "best_position")), 10.0);
    // 14 printed values are the exact ones rounded; two are cut off
    let mut off = 0;
    for i in 0..4 {
        for j in 0..4 {
            if ((rho[i][j] * 1e4).round() / 1e4 - p[i][j]).abs() > 1e-9 {
                off += 1;
                assert!(
                    (rho[i][j] * 1e4).trunc() / 1e4 - p[i][j] == 0.0,
                    "({i},{j}) is neither rounded nor truncated"
                );
            }
        }
    }
    assert_eq!(off, 2);
    assert!(
        has_note(&s, NoteKind::Rounding, "printed 0.5405, exact 0.54058"),
        "{}",
        notes(&s)
    );
    assert!(has_note(
        &s,
        NoteKind::Rounding,
        "printed -0.1745, exact -0.174555"
    ));
    assert!(has_note(&s, NoteKind::Convention, "position 10 of a 4×4"));
    every_step_has_a_formula(&s);
    let full = s
        .steps
        .iter()
        .find(|st| st.title == "The best window in full")
        .unwrap();
    assert!(full.substituted.contains("= 0.9664894"));
    assert_eq!(full.values.number("position"), Some(10.0));
}

// ------------------------------------------------------------ Example 8

fn choice(v: &str) -> Value {
    Value::Text(v.to_string())
}

#[test]
fn example_8_parabola_from_the_printed_rho() {
    let s = solve("subpixel-1d", &Record::new()).unwrap();
    assert_eq!(&keys(&s)[..2], ["coefficients", "c_max"]);
    let a = nums(result(&s, "coefficients"));
    // exact for the printed ρ (0.69, 0.97, 0.37)
    assert_close(a[0], -25.91, 1e-10, "a0");
    assert_close(a[1], 6.88, 1e-11, "a1");
    assert_close(a[2], -0.44, 1e-12, "a2");
    assert_close(num(result(&s, "c_max")), 86.0 / 11.0, 1e-12, "c");
    assert_eq!(nums(printed(&s, "coefficients")), [-25.91, 6.88, -0.44]);
    assert_eq!(num(printed(&s, "c_max")), 7.82);
    assert!(
        has_note(&s, NoteKind::Erratum, "66.8 + (2)(−0.44)c = 0"),
        "{}",
        notes(&s)
    );
    assert!(has_note(&s, NoteKind::Erratum, "peak is at c = 7.833333"));
    assert!(s.result.get("peak_shift").is_none());
    every_step_has_a_formula(&s);
    assert!(s.steps[2]
        .substituted
        .contains(r"c = -\frac{6.88}{2 \times (-0.44)} = 7.818182"));
}

#[test]
fn example_8_chained_from_the_exact_rho_of_example_5() {
    let s = solve(
        "subpixel-1d",
        &Record::new().with("rho_from", choice("exact")),
    )
    .unwrap();
    let e5 = solve("ncc-1d", &Record::new()).unwrap();
    let r5 = nums(result(&e5, "rho"));
    assert_eq!(nums(result(&s, "rho")), r5[3..6]);
    assert_eq!(nums(result(&s, "positions")), [7.0, 8.0, 9.0]);
    // the three windows share Σ(B−B̄)² = 64, so ρ ∝ 51, 74, 28 and the peak
    // is 8 + (51 − 28) / (2·(51 − 148 + 28)) = 8 − 1/6
    assert_close(num(result(&s, "c_max")), 8.0 - 1.0 / 6.0, 1e-12, "c");
    assert_close(
        num(result(&s, "c_max_printed_rho")),
        86.0 / 11.0,
        1e-12,
        "c printed",
    );
    assert_close(
        num(result(&s, "peak_shift")),
        47.0 / 6.0 - 86.0 / 11.0,
        1e-12,
        "shift",
    );
    let a = nums(result(&s, "coefficients"));
    assert_close(a[2], -0.455_300_688, 1e-9, "a2");
    assert_close(a[1], 7.133_044_106, 1e-9, "a1");
    assert!(s.textbook.is_some());
    assert!(s
        .steps
        .iter()
        .any(|st| st.title == "How far the peak moves"));
    assert!(has_note(&s, NoteKind::Convention, "computed exactly"));
    // editing positions in exact mode is reported as unused
    let s = solve(
        "subpixel-1d",
        &Record::new()
            .with("rho_from", choice("exact"))
            .with("rho", vals(&[0.1, 0.2, 0.1])),
    )
    .unwrap();
    assert!(has_note(&s, NoteKind::Warning, "are not used"));
}

// ------------------------------------------------------------ Example 9

#[test]
fn example_9_quadric_from_the_printed_rho() {
    let s = solve("subpixel-2d", &Record::new()).unwrap();
    assert_eq!(&keys(&s)[..3], ["coefficients", "c_max", "r_max"]);
    let a = nums(result(&s, "coefficients"));
    let expected = [
        -12.296_988_889,
        3.785_35,
        3.634_333_333,
        0.041,
        -0.656_316_667,
        -0.460_966_667,
    ];
    for (i, (got, e)) in a.iter().zip(expected).enumerate() {
        assert_close(*got, e, 1e-8, &format!("a{i}"));
    }
    let p = nums(printed(&s, "coefficients"));
    for (i, (got, e)) in a.iter().zip(&p).enumerate() {
        assert_close((got * 1000.0).round() / 1000.0, *e, 1e-12, &format!("a{i}"));
    }
    assert_close(num(result(&s, "c_max")), 3.011_096_372, 1e-8, "c");
    assert_close(num(result(&s, "r_max")), 4.075_987_003, 1e-8, "r");
    assert_eq!(num(printed(&s, "c_max")), 3.012);
    assert_eq!(num(printed(&s, "r_max")), 4.075);
    assert!(
        has_note(&s, NoteKind::Rounding, "c = 3.0123, r = 4.0754"),
        "{}",
        notes(&s)
    );
    assert!(has_note(&s, NoteKind::Rounding, "3.011, 4.076"));
    assert!(has_note(&s, NoteKind::Convention, "centred"));
    // the seed's third equation: labelled (c, r) = (4, 5) but its −0.3921 is
    // ρ at (4, 3); it is used there (and (4, 5) holds the ninth, −0.1268)
    assert!(
        has_note(
            &s,
            NoteKind::Erratum,
            "third equation is labelled ρ(3+1, 4+1)"
        ),
        "{}",
        notes(&s)
    );
    let used = rows(result(&s, "rho"));
    assert_eq!(used[0][2], -0.3921);
    assert_eq!(used[2][2], -0.1268);
    // residuals and σ0 of the 9-equation, 6-unknown fit
    assert_eq!(nums(result(&s, "residuals")).len(), 9);
    assert_close(num(result(&s, "sigma0")), 0.145_761_576, 1e-8, "σ0");
    every_step_has_a_formula(&s);
    // the fit in centred coordinates: N for a 3×3 grid is the textbook one
    let ls = s
        .steps
        .iter()
        .find(|st| st.title == "Least squares")
        .unwrap();
    let n = rows(ls.values.get("N").unwrap());
    assert_eq!(n[0], [9.0, 0.0, 0.0, 0.0, 6.0, 6.0]);
    assert_eq!(n[3], [0.0, 0.0, 0.0, 4.0, 0.0, 0.0]);
}

#[test]
fn example_9_chained_from_the_exact_rho_of_example_7() {
    let s = solve(
        "subpixel-2d",
        &Record::new().with("rho_from", choice("exact")),
    )
    .unwrap();
    let e7 = solve("ncc-surface", &Record::new()).unwrap();
    let surface = rows(result(&e7, "rho"));
    let used = rows(result(&s, "rho"));
    for i in 0..3 {
        assert_eq!(used[i], surface[i + 1][0..3]);
    }
    assert_close(num(result(&s, "c_max")), 3.011_087_663, 1e-8, "c");
    assert_close(num(result(&s, "r_max")), 4.075_993_563, 1e-8, "r");
    let shift = num(result(&s, "peak_shift"));
    assert!(shift > 1e-6 && shift < 2e-5, "shift {shift}");
}

// ------------------------------------------------------------ properties

#[test]
fn rho_is_one_for_a_positive_gain_and_minus_one_for_a_negative_one() {
    let mut rng = Rng(0x5eed_0001);
    for trial in 0..200 {
        let n = 2 + (rng.next() % 60) as usize;
        let a = rng.values(n);
        if a.iter().all(|x| *x == a[0]) {
            continue;
        }
        let gain = rng.uniform(0.05, 4.0);
        let offset = rng.uniform(-300.0, 300.0);
        let up: Vec<f64> = a.iter().map(|x| gain * x + offset).collect();
        let down: Vec<f64> = a.iter().map(|x| -gain * x + offset).collect();
        let r = ncc(&a, &up).unwrap().rho.unwrap();
        assert_close(r, 1.0, 1e-12, &format!("trial {trial}: ρ(a, g·a + o)"));
        let r = ncc(&a, &down).unwrap().rho.unwrap();
        assert_close(r, -1.0, 1e-12, &format!("trial {trial}: ρ(a, −g·a + o)"));
        // and offset alone changes nothing, against any other array
        let b = rng.values(n);
        let shifted: Vec<f64> = b.iter().map(|x| x + offset).collect();
        let (r1, r2) = (ncc(&a, &b).unwrap().rho, ncc(&a, &shifted).unwrap().rho);
        match (r1, r2) {
            (Some(r1), Some(r2)) => assert_close(r1, r2, 1e-12, "offset invariance"),
            (None, None) => {}
            other => panic!("offset changed flatness: {other:?}"),
        }
    }
}

#[test]
fn in_2d_too_rho_is_plus_or_minus_one_under_any_gain_and_offset() {
    let mut rng = Rng(0x5eed_0005);
    for trial in 0..100 {
        let (w, h) = (2 + (rng.next() % 9) as usize, 2 + (rng.next() % 9) as usize);
        let a = Grid::new("a", w, h, rng.values(w * h)).unwrap();
        if a.data().iter().all(|x| *x == a.data()[0]) {
            continue;
        }
        let gain = rng.uniform(0.05, 4.0);
        let offset = rng.uniform(-300.0, 300.0);
        let up = Grid::from_fn(w, h, |c, r| gain * a.get(c, r).unwrap() + offset);
        let down = Grid::from_fn(w, h, |c, r| -gain * a.get(c, r).unwrap() + offset);
        let r = ncc_grid(&a, &up).unwrap().rho.unwrap();
        assert_close(r, 1.0, 1e-12, &format!("trial {trial}: ρ(A, g·A + o)"));
        let r = ncc_grid(&a, &down).unwrap().rho.unwrap();
        assert_close(r, -1.0, 1e-12, &format!("trial {trial}: ρ(A, −g·A + o)"));
        let b = Grid::new("b", w, h, rng.values(w * h)).unwrap();
        let shifted = Grid::from_fn(w, h, |c, r| b.get(c, r).unwrap() + offset);
        match (
            ncc_grid(&a, &b).unwrap().rho,
            ncc_grid(&a, &shifted).unwrap().rho,
        ) {
            (Some(r1), Some(r2)) => assert_close(r1, r2, 1e-12, "offset invariance (2-D)"),
            (None, None) => {}
            other => panic!("offset changed flatness: {other:?}"),
        }
    }
}

#[test]
fn a_template_cut_from_a_search_array_is_found_at_rho_one() {
    let mut rng = Rng(0x5eed_0002);
    for _ in 0..20 {
        let search = rng.values(80);
        let k = (rng.next() % 70) as usize;
        let template: Vec<f64> = search[k..k + 9].iter().map(|x| 0.5 * x + 10.0).collect();
        let p = correlate_1d(&template, &search).unwrap();
        assert_eq!(p.best, Some(k));
        assert_close(p.windows[k].rho.unwrap(), 1.0, 1e-12, "ρ at the cut");
        // one computation path: every position equals ncc of that window
        for (i, w) in p.windows.iter().enumerate() {
            assert_eq!(*w, ncc(&template, &search[i..i + 9]).unwrap());
        }
    }
    // 2-D: the surface equals ncc_grid window by window, and finds the cut
    let noise = rng.values(20 * 15);
    let search = Grid::new("search", 20, 15, noise).unwrap();
    let template = search.window(7, 5, 5, 4).unwrap();
    let bright = Grid::from_fn(5, 4, |c, r| 2.0 * template.get(c, r).unwrap() - 7.0);
    let s = correlate_2d(&bright, &search).unwrap();
    assert_eq!((s.width, s.height), (16, 12));
    assert_eq!(s.best, Some((7, 5)));
    assert_close(s.rho(7, 5).unwrap(), 1.0, 1e-12, "ρ at the cut");
    for r in 0..s.height {
        for c in 0..s.width {
            let w = search.window(c, r, 5, 4).unwrap();
            assert_eq!(s.windows[r * s.width + c], ncc_grid(&bright, &w).unwrap());
        }
    }
}

#[test]
fn the_parabola_peak_of_a_sampled_parabola_is_exact() {
    let mut rng = Rng(0x5eed_0003);
    for _ in 0..200 {
        let (peak, height) = (rng.uniform(-500.0, 500.0), rng.uniform(-1.0, 1.0));
        let curv = -rng.uniform(0.01, 3.0);
        let x0 = (peak + rng.uniform(-0.5, 0.5)).round();
        let step = rng.uniform(0.2, 3.0);
        let x = [x0 - step, x0, x0 + step];
        let y = x.map(|c| height + curv * (c - peak) * (c - peak));
        let p = parabola_peak(x, y).unwrap();
        let Extremum::Maximum { at, value } = p.extremum else {
            panic!("no maximum for a concave parabola");
        };
        assert_close(at[0], peak, 1e-9 * (1.0 + peak.abs()), "peak");
        assert_close(value, height, 1e-8, "peak value");
        assert_close(p.coefficients[2], curv, 1e-9, "a2");
        assert_close(p.coefficients[1], -2.0 * curv * peak, 1e-7, "a1");
    }
}

#[test]
fn the_quadric_peak_of_a_sampled_concave_quadric_is_exact() {
    let mut rng = Rng(0x5eed_0004);
    for _ in 0..200 {
        // ρ = h − [dc dr]·M·[dc dr]ᵀ with M positive definite
        let (pc, pr) = (rng.uniform(0.0, 60.0), rng.uniform(0.0, 60.0));
        let (m11, m22) = (rng.uniform(0.05, 2.0), rng.uniform(0.05, 2.0));
        let m12 = rng.uniform(-0.9, 0.9) * (m11 * m22).sqrt();
        let h = rng.uniform(0.5, 1.0);
        let f = |c: f64, r: f64| {
            let (u, v) = (c - pc, r - pr);
            h - (m11 * u * u + 2.0 * m12 * u * v + m22 * v * v)
        };
        let (c0, r0) = (pc.round(), pr.round());
        let c = [c0 - 1.0, c0, c0 + 1.0];
        let r = [r0 - 1.0, r0, r0 + 1.0];
        let rho = r.map(|ri| c.map(|ci| f(ci, ri)));
        let q = quadric_peak(c, r, rho).unwrap();
        let Extremum::Maximum { at, value } = q.extremum else {
            panic!("no maximum for a concave quadric: {:?}", q.extremum);
        };
        assert_close(at[0], pc, 1e-9, "c peak");
        assert_close(at[1], pr, 1e-9, "r peak");
        assert_close(value, h, 1e-9, "peak value");
        assert!(q.adjustment.v.iter().all(|v| v.abs() < 1e-9));
        assert_close(q.coefficients[4], -m11, 1e-9, "a4");
        assert_close(q.coefficients[3], -2.0 * m12, 1e-9, "a3");
    }
}

// ------------------------------------------------------------ documented answers

#[test]
fn flat_windows_give_null_with_a_note_never_nan() {
    // a flat B in 2-D
    let s = solve(
        "ncc-2d",
        &Record::new().with(
            "b",
            mat(&[&[5.0, 5.0, 5.0], &[5.0, 5.0, 5.0], &[5.0, 5.0, 5.0]]),
        ),
    )
    .unwrap();
    assert_eq!(result(&s, "rho"), &Value::Null);
    assert_eq!(num(result(&s, "sum_db2")), 0.0);
    assert!(has_note(&s, NoteKind::Warning, "B has no variance"));
    assert!(s.textbook.is_none());
    // 0.1 three times: a mean that is not exactly representable
    let n = ncc(&[1.0, 2.0, 3.0], &[0.1, 0.1, 0.1]).unwrap();
    assert_eq!(n.rho, None);

    // a flat template in 1-D: no ρ anywhere, no best
    let s = solve(
        "ncc-1d",
        &Record::new().with("template", vals(&[3.0, 3.0, 3.0])),
    )
    .unwrap();
    assert!(list(result(&s, "rho")).iter().all(|v| *v == Value::Null));
    assert_eq!(result(&s, "best"), &Value::Null);
    assert!(has_note(&s, NoteKind::Warning, "template has no variance"));

    // one flat sub-window among others
    let s = solve(
        "ncc-1d",
        &Record::new()
            .with("template", vals(&[1.0, 5.0, 2.0]))
            .with("search", vals(&[4.0, 4.0, 4.0, 9.0, 1.0, 6.0])),
    )
    .unwrap();
    let rho = list(result(&s, "rho"));
    assert_eq!(rho[0], Value::Null);
    assert!(rho[1..].iter().all(|v| v.as_f64().is_some()));
    assert!(has_note(
        &s,
        NoteKind::Warning,
        "Sub-window 1 has no variance"
    ));

    // a surface over a search array with a flat patch
    let mut search = vec![vec![7.0; 6]; 6];
    search[5] = vec![1.0, 9.0, 3.0, 8.0, 2.0, 5.0];
    let search: Vec<&[f64]> = search.iter().map(Vec::as_slice).collect();
    let s = solve("ncc-surface", &Record::new().with("search", mat(&search))).unwrap();
    let rho = list(result(&s, "rho"));
    assert!(list(&rho[0]).iter().all(|v| *v == Value::Null));
    assert!(list(&rho[3]).iter().all(|v| v.as_f64().is_some()));
    assert!(has_note(&s, NoteKind::Warning, "12 windows"));
    // a flat template on a surface
    let s = solve(
        "ncc-surface",
        &Record::new().with("template", mat(&[&[2.0, 2.0], &[2.0, 2.0]])),
    )
    .unwrap();
    assert_eq!(result(&s, "best_position"), &Value::Null);
    assert!(has_note(&s, NoteKind::Warning, "template has no variance"));
    assert!(has_note(
        &s,
        NoteKind::Warning,
        "centre lies between pixels"
    ));
}

#[test]
fn a_template_larger_than_the_search_array_is_refused() {
    assert_eq!(
        err(
            "ncc-1d",
            Record::new().with("search", vals(&[1.0, 2.0, 3.0]))
        ),
        "template: has 7 values but the search array only 3: the template must fit in the search array"
    );
    assert_eq!(
        err(
            "ncc-surface",
            Record::new().with(
                "search",
                mat(&[&[1.0, 2.0, 3.0, 4.0], &[5.0, 6.0, 7.0, 8.0]])
            )
        ),
        "template: is 3×3 but the search array only 2×4: the template must fit in the search array"
    );
    // the same size fits: one position
    let s = solve(
        "ncc-surface",
        &Record::new().with(
            "search",
            mat(&[
                &[30.0, 50.0, 30.0],
                &[50.0, 51.0, 50.0],
                &[30.0, 50.0, 31.0],
            ]),
        ),
    )
    .unwrap();
    assert_eq!(rows(result(&s, "rho")).len(), 1);
    assert_eq!(num(result(&s, "best_position")), 1.0);
}

#[test]
fn a_non_concave_neighbourhood_is_reported_not_returned_as_a_peak() {
    // a saddle: a peak along c, a valley along r
    let s = solve(
        "subpixel-2d",
        &Record::new().with(
            "rho",
            mat(&[&[0.5, 0.9, 0.5], &[0.1, 0.5, 0.1], &[0.5, 0.9, 0.5]]),
        ),
    )
    .unwrap();
    assert_eq!(result(&s, "c_max"), &Value::Null);
    assert_eq!(result(&s, "r_max"), &Value::Null);
    assert_eq!(result(&s, "extremum"), &Value::from("saddle"));
    assert!(has_note(&s, NoteKind::Warning, "saddle"), "{}", notes(&s));
    assert!(s.textbook.is_none());
    // a bowl: a minimum
    let s = solve(
        "subpixel-2d",
        &Record::new().with(
            "rho",
            mat(&[&[0.9, 0.5, 0.9], &[0.5, 0.1, 0.5], &[0.9, 0.5, 0.9]]),
        ),
    )
    .unwrap();
    assert_eq!(result(&s, "extremum"), &Value::from("minimum"));
    assert_eq!(result(&s, "c_max"), &Value::Null);
    // a plane: no stationary point
    let s = solve(
        "subpixel-2d",
        &Record::new().with(
            "rho",
            mat(&[&[0.1, 0.2, 0.3], &[0.2, 0.3, 0.4], &[0.3, 0.4, 0.5]]),
        ),
    )
    .unwrap();
    assert_eq!(result(&s, "extremum"), &Value::from("none"));
    assert!(has_note(&s, NoteKind::Warning, "not concave"));
    // 1-D: a valley and a line
    let s = solve(
        "subpixel-1d",
        &Record::new().with("rho", vals(&[0.9, 0.2, 0.8])),
    )
    .unwrap();
    assert_eq!(result(&s, "c_max"), &Value::Null);
    assert_eq!(result(&s, "extremum"), &Value::from("minimum"));
    assert!(has_note(&s, NoteKind::Warning, "opens upward"));
    let s = solve(
        "subpixel-1d",
        &Record::new().with("rho", vals(&[0.2, 0.4, 0.6])),
    )
    .unwrap();
    assert_eq!(result(&s, "extremum"), &Value::from("none"));
    // a peak outside the three positions is returned with a warning
    let s = solve(
        "subpixel-1d",
        &Record::new().with("rho", vals(&[0.5, 0.8, 0.95])),
    )
    .unwrap();
    assert!(num(result(&s, "c_max")) > 9.0);
    assert!(has_note(&s, NoteKind::Warning, "extrapolated"));
}

#[test]
fn bad_inputs_name_the_field_and_say_what_is_wrong() {
    let r = Record::new;
    assert_eq!(
        err("ncc-1d", r().with("template", vals(&[]))),
        "template: is empty: give at least 2 numbers"
    );
    assert_eq!(
        err("ncc-1d", r().with("template", vals(&[4.0]))),
        "template: needs at least 2 numbers (got 1)"
    );
    assert_eq!(
        err("ncc-1d", r().with("search", vals(&[1.0, f64::NAN, 3.0]))),
        "search[2]: is NaN; give a number"
    );
    assert_eq!(
        err("ncc-2d", r().with("a", mat(&[&[1.0, 2.0], &[3.0]]))),
        "a: rows must all have the same length: row 1 has 2 numbers, row 2 has 1"
    );
    assert_eq!(
        err("ncc-2d", r().with("a", Value::List(vec![]))),
        "a: is empty: give at least one row"
    );
    assert_eq!(
        err("ncc-2d", r().with("b", mat(&[&[1.0, 2.0], &[3.0, 4.0]]))),
        "b: is 2×2 but a is 3×3: the arrays must be the same size"
    );
    assert_eq!(
        err(
            "ncc-surface",
            r().with("template", mat(&[&[1.0, f64::INFINITY]]))
        ),
        "template[1][2]: is infinite; give a finite number"
    );
    assert_eq!(
        err("subpixel-1d", r().with("positions", vals(&[7.0, 7.0, 9.0]))),
        "positions: values 1 and 2 are the same position; three different positions are needed"
    );
    assert_eq!(
        err("subpixel-1d", r().with("rho", vals(&[0.1, 0.2]))),
        "rho: needs at least 3 numbers (got 2)"
    );
    assert_eq!(
        err("subpixel-2d", r().with("r", vals(&[3.0, 4.0, 4.0]))),
        "r: values 2 and 3 are the same position; three different positions are needed"
    );
    assert_eq!(
        err(
            "subpixel-2d",
            r().with("rho", mat(&[&[1.0, 2.0, 3.0], &[1.0, 2.0, 3.0]]))
        ),
        "rho: must have 3 rows (got 2)"
    );
    assert_eq!(
        err("subpixel-2d", r().with("rho_from", choice("rounded"))),
        "rho_from: \"rounded\" is not one of the choices (printed, exact)"
    );
    assert!(err("ncc-2d", r().with("a", 3.0)).starts_with("a: must be a list of rows"));
    // too much work for one click
    let big: Vec<Vec<f64>> = (0..512)
        .map(|r| (0..512).map(|c| ((r * c) % 7) as f64).collect())
        .collect();
    let tpl: Vec<Vec<f64>> = big[..100].iter().map(|r| r[..100].to_vec()).collect();
    let e = err(
        "ncc-surface",
        r().with("search", Value::matrix(&big))
            .with("template", Value::matrix(&tpl)),
    );
    assert!(
        e.starts_with("search: a 100×100 template at 413×413 positions"),
        "{e}"
    );
}

#[test]
fn text_inputs_parse_as_the_page_sends_them() {
    let p = parse_inputs(
        "ncc-2d",
        &Record::new()
            .with("a", "48 50 48; 51 67 71; 55 67 72")
            .with("b", "52, 37, 41\n67, 54, 78\n42, 74, 87"),
    )
    .unwrap();
    assert!(p.errors.is_empty(), "{:?}", p.errors);
    let s = solve("ncc-2d", &p.inputs).unwrap();
    assert!(s.textbook.is_some());
    let p = parse_inputs(
        "ncc-1d",
        &Record::new()
            .with("template", "1, 2, x")
            .with("search", "[1 2 3 4]"),
    )
    .unwrap();
    assert_eq!(
        p.errors.get("template"),
        Some(&Value::from("template: \"x\" is not a number"))
    );
    assert!(p.errors.get("search").is_none());
    let p = parse_inputs("subpixel-1d", &Record::new().with("rho_from", "exact")).unwrap();
    assert_eq!(p.inputs.get("rho_from"), Some(&choice("exact")));
}

#[test]
fn a_64_by_64_search_array_and_a_long_1d_search_solve() {
    // (how fast they solve is measured by `npm run bench`, not asserted here)
    let mut rng = Rng(0x5eed_0005);
    let search: Vec<Vec<f64>> = (0..64).map(|_| rng.values(64)).collect();
    for k in [3usize, 9, 21, 32] {
        let template: Vec<Vec<f64>> = search[10..10 + k]
            .iter()
            .map(|r| r[20..20 + k].to_vec())
            .collect();
        let s = solve(
            "ncc-surface",
            &Record::new()
                .with("search", Value::matrix(&search))
                .with("template", Value::matrix(&template)),
        )
        .unwrap();
        assert_eq!(num(result(&s, "best_col")), 21.0);
        assert_eq!(num(result(&s, "best_row")), 11.0);
        assert_eq!(rows(result(&s, "rho")).len(), 65 - k);
    }
    // a long 1-D search
    let search = rng.values(4096);
    let template = search[1000..1100].to_vec();
    let s = solve(
        "ncc-1d",
        &Record::new()
            .with("search", vals(&search))
            .with("template", vals(&template)),
    )
    .unwrap();
    assert_eq!(num(result(&s, "best")), 1001.0);
    assert_eq!(s.steps.len(), 2 + 12 + 1 + 2);
}

// ------------------------------------------------------------ steps as data

/// Every step with a formula has parts (its LaTeX made from them), and
/// every practice box's hint comes from the relation keyed with the box's
/// value (`tests/parts_common`); in "exact" mode too, and no relation has
/// nothing on its right (it would print its left-hand side alone).
#[test]
fn steps_are_data_and_practice_hints_come_from_keyed_relations() {
    use photogrammetry_playground::examples::correlation::{EXAMPLES, TOPIC};
    let with_numbers = parts_common::steps_are_data_and_hints_are_keyed(&TOPIC, 5);
    // every box but "best" (its relation has no numbers to put in)
    assert!(with_numbers >= 5 * (22 + 6 - 1), "{with_numbers}");
    let exact = Record::new().with("rho_from", "exact");
    for e in EXAMPLES {
        for s in [e.run(&Record::new()), e.run(&exact)].into_iter().flatten() {
            for step in &s.steps {
                assert!(
                    step.formula.is_empty() || !step.parts.is_empty(),
                    "{}: \"{}\"",
                    e.id,
                    step.title
                );
                for r in &step.parts {
                    assert!(
                        !(r.symbolic.is_empty() && r.substituted.is_empty() && r.result.is_empty()),
                        "{}: \"{}\" has an empty relation",
                        e.id,
                        step.title
                    );
                }
            }
        }
    }
    // the ρ of Example 6 as data: symbols, the numbers put in, the result
    let s = solve("ncc-2d", &Record::new()).unwrap();
    let rho = s
        .steps
        .iter()
        .flat_map(|st| &st.parts)
        .find(|r| r.key.as_deref() == Some("rho"))
        .unwrap();
    assert_eq!(
        rho.substituted_latex(),
        r"\rho = \frac{1149.222}{\sqrt{843.5556 \times 2604.889}} = 0.7752693"
    );
    assert_eq!(
        rho.question_latex(),
        r"\rho = \frac{1149.222}{\sqrt{843.5556 \times 2604.889}} = \;?"
    );
}
