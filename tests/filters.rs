//! Seed 000, Examples 12a/12b, 15, 16 and seed 004's mean example reproduced
//! natively, every printed value beside the exact one; the properties of the
//! resampling and filter cores; every class of bad input.
#![cfg(not(target_arch = "wasm32"))]

use photogrammetry_playground::examples::{parse_inputs, solve};
use photogrammetry_playground::filter::{self, Kernel};
use photogrammetry_playground::raster::{Border, Grid};
use photogrammetry_playground::resample::{self, SEED_A};
use photogrammetry_playground::solution::{NoteKind, Record, Solution, Value};

// ---------------------------------------------------------------------------
// helpers

/// A tiny deterministic PRNG (xorshift64*), so that no dependency is needed.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// A whole number in [0, n).
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn grid(&mut self, w: usize, h: usize) -> Grid {
        let data = (0..w * h).map(|_| (self.unit() * 255.0).round()).collect();
        Grid::new("g", w, h, data).unwrap()
    }
}

fn matrix(v: &Value) -> Vec<Vec<f64>> {
    match v {
        Value::List(rows) => rows
            .iter()
            .map(|r| match r {
                Value::List(xs) => xs.iter().map(|x| x.as_f64().unwrap()).collect(),
                other => panic!("not a row: {other:?}"),
            })
            .collect(),
        other => panic!("not a matrix: {other:?}"),
    }
}

fn result_matrix(s: &Solution, key: &str) -> Vec<Vec<f64>> {
    matrix(s.result.get(key).unwrap_or_else(|| panic!("{key} missing")))
}

fn printed_matrix(s: &Solution, key: &str) -> Vec<Vec<f64>> {
    matrix(s.textbook.as_ref().expect("textbook").get(key).unwrap())
}

fn result(s: &Solution, key: &str) -> f64 {
    s.result
        .number(key)
        .unwrap_or_else(|| panic!("result {key} missing or null in {}", s.id))
}

fn printed(s: &Solution, key: &str) -> f64 {
    s.textbook
        .as_ref()
        .and_then(|t| t.number(key))
        .unwrap_or_else(|| panic!("printed {key} missing in {}", s.id))
}

fn has_note(s: &Solution, kind: NoteKind, needle: &str) -> bool {
    s.notes
        .iter()
        .any(|n| n.kind == kind && n.text.contains(needle))
}

fn assert_matrix(got: &[Vec<f64>], expected: &[Vec<f64>], tol: f64) {
    assert_eq!(got.len(), expected.len(), "{got:?} vs {expected:?}");
    for (a, b) in got.iter().zip(expected) {
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(b) {
            assert!((x - y).abs() <= tol, "{got:?} vs {expected:?}");
        }
    }
}

/// Cells where a printed value differs from the exact one by more than half
/// a unit of its `decimals` (1-based row, column).
fn mismatches(exact: &[Vec<f64>], printed: &[Vec<f64>], decimals: i32) -> Vec<(usize, usize)> {
    let tol = 0.5 * 10f64.powi(-decimals) + 1e-9;
    let mut out = Vec::new();
    for (j, (a, b)) in exact.iter().zip(printed).enumerate() {
        for (i, (x, y)) in a.iter().zip(b).enumerate() {
            if (x - y).abs() > tol {
                out.push((j + 1, i + 1));
            }
        }
    }
    out
}

fn rows<const N: usize>(m: [[f64; N]; N]) -> Vec<Vec<f64>> {
    m.iter().map(|r| r.to_vec()).collect()
}

fn window_value(m: &[[f64; 5]; 5]) -> Value {
    Value::matrix(&rows(*m))
}

const EX16: [[f64; 5]; 5] = [
    [1.0, 2.0, 1.0, 1.0, 1.0],
    [1.0, 1.0, 9.0, 2.0, 1.0],
    [1.0, 9.0, 9.0, 8.0, 1.0],
    [1.0, 1.0, 8.0, 1.0, 2.0],
    [2.0, 1.0, 1.0, 1.0, 1.0],
];
const SEED004: [[f64; 5]; 5] = [
    [5.0, 6.0, 7.0, 8.0, 9.0],
    [11.0, 10.0, 20.0, 30.0, 9.0],
    [31.0, 50.0, 60.0, 70.0, 9.0],
    [40.0, 30.0, 20.0, 10.0, 9.0],
    [58.0, 95.0, 105.0, 106.0, 98.0],
];

/// A written-out sum with its line breaks taken out (one line per kernel
/// row in the step), for matching against the seed's one-line sums.
fn flat(tex: &str) -> String {
    let s = tex
        .replace(r"\begin{aligned}", "")
        .replace(r"\end{aligned}", "")
        .replace(r"\\", " ")
        .replace(r"&\qquad", " ")
        .replace('&', " ")
        .replace(r"\tfrac", r"\frac")
        .replace(r"\big(", r"\left(")
        .replace(r"\big)", r"\right)");
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

// ---------------------------------------------------------------------------
// Example 12a / 12b

#[test]
fn example_12a_nearest_and_bilinear_with_the_printed_values() {
    let s = solve("resample", &Record::new()).unwrap();
    assert_eq!(result(&s, "nearest_c"), 547.0);
    assert_eq!(result(&s, "nearest_r"), 817.0);
    assert_eq!(result(&s, "nearest"), 72.0);
    assert!((result(&s, "i1") - 75.08).abs() < 1e-9);
    assert!((result(&s, "i2") - 76.24).abs() < 1e-9);
    assert!((result(&s, "bilinear") - 75.3584).abs() < 1e-9);
    assert_eq!(result(&s, "bilinear_rounded"), 75.0);
    assert_eq!(s.result.get("bicubic"), Some(&Value::Null));
    assert_eq!(printed(&s, "bilinear"), 75.35);
    assert_eq!(printed(&s, "i2"), 76.24);
    assert_eq!(printed(&s, "nearest"), 72.0);
    assert!(has_note(&s, NoteKind::Rounding, "printed 75.35: cut off"));
    assert!(has_note(&s, NoteKind::Convention, "0.56·(78 − 74)"));
    assert!(has_note(&s, NoteKind::Warning, "No bicubic value"));
    let keys: Vec<_> = s.result.keys().collect();
    assert_eq!(
        &keys[..7],
        [
            "nearest_c",
            "nearest_r",
            "nearest",
            "i1",
            "i2",
            "bilinear",
            "bicubic"
        ]
    );
    let i1 = s
        .steps
        .iter()
        .find(|st| st.title.contains("upper row"))
        .unwrap();
    assert!(
        i1.substituted.contains(r"72 + 0.44\,(79 - 72) = 75.08"),
        "{}",
        i1.substituted
    );
    for st in &s.steps {
        assert!(
            !st.formula.is_empty() && !st.substituted.is_empty(),
            "{}",
            st.title
        );
    }
}

fn example_12b() -> Record {
    Record::new()
        .with(
            "patch",
            Value::matrix(&rows([
                [58.0, 54.0, 66.0, 64.0],
                [54.0, 62.0, 67.0, 59.0],
                [52.0, 57.0, 60.0, 54.0],
                [53.0, 46.0, 52.0, 48.0],
            ])),
        )
        .with("first_c", 523.0)
        .with("first_r", 835.0)
        .with("c", 523.72)
        .with("r", 835.24)
}

#[test]
fn example_12b_every_printed_value_reproduced() {
    let s = solve("resample", &example_12b()).unwrap();
    assert_eq!(result(&s, "nearest_c"), 524.0);
    assert_eq!(result(&s, "nearest_r"), 835.0);
    assert_eq!(result(&s, "nearest"), 54.0);
    assert!((result(&s, "i1") - 55.12).abs() < 1e-9);
    assert!((result(&s, "i2") - 59.76).abs() < 1e-9);
    assert!((result(&s, "bilinear") - 56.2336).abs() < 1e-9);
    assert_eq!(result(&s, "bilinear_rounded"), 56.0);
    assert_eq!(printed(&s, "bilinear"), 56.234);
    assert_eq!(printed(&s, "i1"), 55.12);
    assert!(has_note(&s, NoteKind::Erratum, "523.72m"));
    assert!(has_note(&s, NoteKind::Rounding, "56.234"));
    // a what-if (another position) drops the textbook
    let s = solve("resample", &example_12b().with("c", 524.5)).unwrap();
    assert!(s.textbook.is_none());
}

#[test]
fn bicubic_inside_the_patch_is_seed_004s_matrix_product() {
    let s = solve("resample", &Record::new().with("c", 546.3).with("r", 818.6)).unwrap();
    let p = [
        [68.0, 64.0, 72.0, 79.0],
        [64.0, 71.0, 78.0, 74.0],
        [61.0, 65.0, 71.0, 78.0],
        [63.0, 56.0, 62.0, 68.0],
    ];
    // printed weight formulas of seed 004
    let f = |y: f64| {
        [
            -y * (1.0 - y) * (1.0 - y),
            (1.0 - y) + y * (1.0 - y) * (1.0 - y),
            y + y * y * (1.0 - y),
            -y * y * (1.0 - y),
        ]
    };
    let (ws, wt) = (f(0.3), f(0.6));
    let mut q = 0.0;
    for j in 0..4 {
        for i in 0..4 {
            q += wt[j] * p[j][i] * ws[i];
        }
    }
    assert!((result(&s, "bicubic") - q).abs() < 1e-9);
    assert!(s.textbook.is_none());
    assert!(!has_note(&s, NoteKind::Warning, "No bicubic"));
    let st = s.steps.iter().find(|st| st.title.contains("4×4")).unwrap();
    assert!(st.values.get("neighbourhood").is_some());
}

// ---------------------------------------------------------------------------
// resampling properties

#[test]
fn interpolation_reproduces_the_samples_at_pixel_centres() {
    let mut rng = Rng(0x5eed_0001);
    let mut checked = 0;
    for _ in 0..20 {
        let (w, h) = (2 + rng.below(7), 2 + rng.below(7));
        let g = rng.grid(w, h);
        for r in 0..h {
            for c in 0..w {
                let v = g.get(c, r).unwrap();
                let (x, y) = (c as f64, r as f64);
                assert_eq!(resample::nearest(&g, x, y).unwrap().value, v);
                assert!((resample::bilinear(&g, x, y).unwrap().value - v).abs() < 1e-12);
                // bicubic needs the 4×4 neighbourhood c−1 … c+2, r−1 … r+2
                let inside = c >= 1 && c + 2 < w && r >= 1 && r + 2 < h;
                for a in [SEED_A, -0.5] {
                    match resample::bicubic(&g, x, y, a) {
                        Some(b) => {
                            assert!(inside, "bicubic at ({c}, {r}) of {w}×{h} should be refused");
                            assert!((b.value - v).abs() < 1e-12);
                            checked += 1;
                        }
                        None => assert!(!inside, "bicubic at ({c}, {r}) of {w}×{h} refused"),
                    }
                }
            }
        }
    }
    assert!(checked > 100, "only {checked} bicubic values checked");
}

#[test]
fn linear_ramps_bilinear_and_keys_exact_seed_kernel_off_by_a_known_cubic() {
    let mut rng = Rng(0x5eed_0002);
    for _ in 0..200 {
        let (alpha, beta, gamma) = (
            rng.unit() * 10.0 - 5.0,
            rng.unit() * 10.0 - 5.0,
            rng.unit() * 100.0,
        );
        let g = Grid::from_fn(6, 6, |c, r| gamma + alpha * c as f64 + beta * r as f64);
        let (x, y) = (1.0 + rng.unit() * 3.0, 1.0 + rng.unit() * 3.0);
        let exact = gamma + alpha * x + beta * y;
        assert!((resample::bilinear(&g, x, y).unwrap().value - exact).abs() < 1e-9);
        {
            let (x, y) = (x.min(3.999), y.min(3.999));
            let b = resample::bicubic(&g, x, y, -0.5).expect("inside the 6×6 grid");
            assert!((b.value - (gamma + alpha * x + beta * y)).abs() < 1e-9);
        }
        // seed 004's a = −1 adds s(1−s)(1−2s) per unit of slope
        let (x, y) = (x.min(3.999), y.min(3.999));
        let b = resample::bicubic(&g, x, y, SEED_A).unwrap();
        let e = |s: f64| s * (1.0 - s) * (1.0 - 2.0 * s);
        let expected = gamma + alpha * (x + e(b.s)) + beta * (y + e(b.t));
        assert!(
            (b.value - expected).abs() < 1e-9,
            "{} vs {expected}",
            b.value
        );
    }
    // the deviation is real: at s = 0.25 it is 0.09375 of the slope
    let g = Grid::from_fn(6, 6, |c, _| c as f64);
    let b = resample::bicubic(&g, 2.25, 2.0, SEED_A).unwrap();
    assert!((b.value - 2.25 - 0.09375).abs() < 1e-12);
}

#[test]
fn cubic_convolution_weights_sum_to_one() {
    let mut rng = Rng(0x5eed_0003);
    for _ in 0..1000 {
        let s = rng.unit();
        let a = -rng.unit() * 2.0;
        let w = resample::cubic_weights(s, a);
        assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-12, "{s} {a}");
    }
    assert_eq!(resample::cubic_weights(0.0, SEED_A), [0.0, 1.0, 0.0, 0.0]);
    assert_eq!(resample::cubic(2.5, SEED_A), 0.0);
}

#[test]
fn neighbourhoods_that_leave_the_patch_are_reported_not_read() {
    let g = Grid::from_fn(4, 4, |c, r| (c * r) as f64);
    assert!(resample::bilinear(&g, -0.01, 1.0).is_none());
    assert!(resample::bilinear(&g, 1.0, 3.01).is_none());
    assert!(resample::bicubic(&g, 0.99, 1.5, SEED_A).is_none());
    assert!(resample::bicubic(&g, 1.5, 2.0, SEED_A).is_none());
    assert!(resample::bicubic(&g, 1.0, 1.999, SEED_A).is_some());
    assert!(resample::nearest(&g, 3.6, 0.0).is_none());
    assert!(resample::bilinear(&g, f64::NAN, 0.0).is_none());
}

// ---------------------------------------------------------------------------
// Example 15: mean and Gaussian

#[test]
fn example_15_mean_exact_and_every_slip_flagged() {
    let s = solve("filter-window", &Record::new()).unwrap();
    let exact = rows([
        [102.0 / 9.0, 100.0 / 9.0, 80.0 / 9.0],
        [113.0 / 9.0, 115.0 / 9.0, 95.0 / 9.0],
        [125.0 / 9.0, 15.0, 124.0 / 9.0],
    ]);
    let out = result_matrix(&s, "output");
    assert_matrix(&out, &exact, 1e-12);
    assert_eq!(result(&s, "selected"), 102.0 / 9.0);
    assert_eq!(result(&s, "kernel_sum"), 1.0);
    assert_eq!(
        (result(&s, "output_first_c"), result(&s, "output_first_r")),
        (2.0, 2.0)
    );
    // printed values and where they differ
    let detail = printed_matrix(&s, "pixel_results");
    assert_eq!(mismatches(&out, &detail, 2), [(2, 1), (2, 3), (3, 1)]);
    let grid = printed_matrix(&s, "output");
    assert_eq!(mismatches(&out, &grid, 1), [(2, 1), (2, 3), (3, 1)]);
    assert_eq!(printed(&s, "selected"), 11.33);
    assert!(has_note(
        &s,
        NoteKind::Erratum,
        "the 10 at (r4, c1) is copied as 1"
    ));
    assert!(has_note(&s, NoteKind::Erratum, "125/9 = 13.89"));
    assert!(has_note(&s, NoteKind::Rounding, "113/9 = 12.556"));
    assert!(has_note(&s, NoteKind::Rounding, "95/9 = 10.556"));
    assert!(has_note(&s, NoteKind::Rounding, "12.5 and 10.5"));
    assert!(has_note(&s, NoteKind::Convention, "correlation"));
    // the selected pixel's sum written out as the seed writes it
    let st = s
        .steps
        .iter()
        .find(|st| st.title.contains("written out"))
        .unwrap();
    assert!(
        flat(&st.substituted).contains(r"\frac{1}{9}\left(10 + 13 + 3 + 11 + 15 + 10 + 9 + 24 + 7\right) = \frac{102}{9} = 11.33333"),
        "{}",
        st.substituted
    );
    // the slipped pixel selected: its own printed value beside the exact one
    let s = solve(
        "filter-window",
        &Record::new().with("select_c", 2.0).with("select_r", 4.0),
    )
    .unwrap();
    assert_eq!(result(&s, "selected"), 125.0 / 9.0);
    assert_eq!(printed(&s, "selected"), 12.88);
    let st = s
        .steps
        .iter()
        .find(|st| st.title.contains("written out"))
        .unwrap();
    assert!(flat(&st.substituted)
        .contains(r"9 + 24 + 7 + 10 + 13 + 14 + 13 + 18 + 17\right) = \frac{125}{9}"));
    // one piece per kernel row (the page breaks lines between them), as
    // the kernel is laid out
    let sum = st
        .parts
        .iter()
        .find(|r| r.key.as_deref() == Some("numerator_sum"))
        .unwrap();
    let rows: Vec<String> = sum.substituted[0].0.iter().map(|p| p.latex()).collect();
    assert_eq!(
        rows,
        [
            r"\tfrac{1}{9}\big(9 + 24 + 7",
            "+ 10 + 13 + 14",
            r"+ 13 + 18 + 17\big)"
        ]
    );
    assert_eq!(sum.result.len(), 2, "125/9 and its value");
}

#[test]
fn example_15_gaussian_exact_and_the_grid_rounding() {
    let s = solve("filter-window", &Record::new().with("kernel", "gaussian-3")).unwrap();
    let exact = rows([
        [205.0 / 16.0, 164.0 / 16.0, 145.0 / 16.0],
        [229.0 / 16.0, 12.0, 10.0],
        [230.0 / 16.0, 229.0 / 16.0, 223.0 / 16.0],
    ]);
    let out = result_matrix(&s, "output");
    assert_matrix(&out, &exact, 1e-12);
    assert_eq!(
        mismatches(&out, &printed_matrix(&s, "pixel_results"), 1),
        []
    );
    assert_eq!(
        mismatches(&out, &printed_matrix(&s, "pixel_results"), 2),
        [(1, 3), (2, 1), (3, 1), (3, 2)]
    );
    // only the one-decimal precision of those is printed; the grid has 10.25 → 10.2
    assert_eq!(printed_matrix(&s, "output")[0][1], 10.2);
    assert!(has_note(
        &s,
        NoteKind::Rounding,
        "10.25 at (r2, c3) as 10.2"
    ));
    let st = s
        .steps
        .iter()
        .find(|st| st.title.contains("written out"))
        .unwrap();
    assert!(flat(&st.substituted).contains(
        r"\frac{1}{16}\left(10 + 2 \times 13 + 3 + 2 \times 11 + 4 \times 15 + 2 \times 10 + 9 + 2 \times 24 + 7\right) = \frac{205}{16} = 12.8125"
    ), "{}", st.substituted);
}

// ---------------------------------------------------------------------------
// Example 15: Prewitt and Sobel

#[test]
fn example_15_prewitt_and_sobel_reproduced() {
    for (op, gx, gy) in [
        (
            "prewitt",
            [
                [-14.0, -12.0, 2.0],
                [-1.0, -8.0, -14.0],
                [-8.0, -15.0, -32.0],
            ],
            [[-10.0, -24.0, 12.0], [1.0, -20.0, 1.0], [6.0, -13.0, 6.0]],
        ),
        (
            "sobel",
            [
                [-25.0, -16.0, 5.0],
                [1.0, -12.0, -20.0],
                [-2.0, -25.0, -43.0],
            ],
            [[-11.0, -30.0, 11.0], [-1.0, -36.0, 4.0], [10.0, -11.0, 5.0]],
        ),
    ] {
        let s = solve("edge-window", &Record::new().with("operator", op)).unwrap();
        assert_eq!(result_matrix(&s, "gx"), rows(gx), "{op}");
        assert_eq!(result_matrix(&s, "gy"), rows(gy), "{op}");
        assert_eq!(printed_matrix(&s, "gx"), rows(gx));
        let mag = result_matrix(&s, "magnitude");
        for j in 0..3 {
            for i in 0..3 {
                assert_eq!(mag[j][i], f64::hypot(gx[j][i], gy[j][i]));
            }
        }
        // printed magnitudes: one decimal, two for 21.54 and 19.85
        let pm = printed_matrix(&s, "magnitude");
        assert_eq!(mismatches(&mag, &pm, 1), [], "{op}");
        assert_eq!(result(&s, "selected_gx"), gx[0][0]);
        assert_eq!(
            result(&s, "selected_magnitude"),
            f64::hypot(gx[0][0], gy[0][0])
        );
        assert!(has_note(
            &s,
            NoteKind::Convention,
            "top row minus bottom row"
        ));
        let keys: Vec<_> = s.result.keys().collect();
        assert_eq!(&keys[..3], ["gx", "gy", "magnitude"]);
    }
    let s = solve("edge-window", &Record::new()).unwrap();
    assert_eq!(printed_matrix(&s, "magnitude")[1][1], 21.54);
    let st = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Gx at"))
        .unwrap();
    assert!(
        flat(&st.substituted).contains("= 10 + 13 + 3 - 9 - 24 - 7 = -14"),
        "{}",
        st.substituted
    );
    let st = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Gy at"))
        .unwrap();
    assert!(
        flat(&st.substituted).contains("= -10 + 3 - 11 + 10 - 9 + 7 = -10"),
        "{}",
        st.substituted
    );
    let s = solve(
        "edge-window",
        &Record::new()
            .with("operator", "sobel")
            .with("select_c", 4.0)
            .with("select_r", 4.0),
    )
    .unwrap();
    let st = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Gx at"))
        .unwrap();
    assert!(
        flat(&st.substituted).contains(r"7 + 2 \times 8 + 10 - 17 - 2 \times 19 - 21 = -43"),
        "{}",
        st.substituted
    );
    assert_eq!(printed(&s, "selected_magnitude"), 43.3);
}

// ---------------------------------------------------------------------------
// Example 16 and seed 004

#[test]
fn example_16_laplacian_every_value() {
    let s = solve(
        "filter-window",
        &Record::new()
            .with("window", window_value(&EX16))
            .with("kernel", "laplacian-8"),
    )
    .unwrap();
    let expected = rows([
        [25.0, -39.0, 15.0],
        [-41.0, -33.0, -31.0],
        [24.0, -33.0, 23.0],
    ]);
    assert_eq!(result_matrix(&s, "output"), expected);
    assert_eq!(printed_matrix(&s, "output"), expected);
    assert_eq!(printed(&s, "selected"), 25.0);
    assert_eq!(result(&s, "kernel_sum"), 0.0);
    assert!(has_note(
        &s,
        NoteKind::Convention,
        "Every value of Example 16 is reproduced"
    ));
    assert!(has_note(&s, NoteKind::Convention, "sum to 0"));
    let st = s
        .steps
        .iter()
        .find(|st| st.title.contains("written out"))
        .unwrap();
    assert!(
        flat(&st.substituted).contains(r"= 1 + 2 + 1 + 1 - 8 \times 1 + 9 + 1 + 9 + 9 = 25"),
        "{}",
        st.substituted
    );
}

#[test]
fn seed_004_mean_is_33_and_its_laplacian_is_flagged() {
    let base = Record::new().with("window", window_value(&SEED004));
    let s = solve(
        "filter-window",
        &base.clone().with("select_c", 3.0).with("select_r", 3.0),
    )
    .unwrap();
    assert!((result(&s, "selected") - 300.0 / 9.0).abs() < 1e-12);
    assert_eq!(printed(&s, "selected"), 33.0);
    assert!(has_note(
        &s,
        NoteKind::Rounding,
        "300/9 = 33.33, printed as 33"
    ));
    assert!(has_note(&s, NoteKind::Convention, "true convolution"));
    let st = s
        .steps
        .iter()
        .find(|st| st.title.contains("written out"))
        .unwrap();
    assert!(flat(&st.substituted)
        .contains(r"\left(10 + 20 + 30 + 50 + 60 + 70 + 30 + 20 + 10\right) = \frac{300}{9}"));
    // another pixel: the seed prints nothing for it
    let s = solve("filter-window", &base).unwrap();
    assert!(s.textbook.is_none());

    let s = solve(
        "filter-window",
        &Record::new().with("kernel", "laplacian-004"),
    )
    .unwrap();
    assert_eq!(result(&s, "kernel_sum"), -7.0);
    assert!(has_note(&s, NoteKind::Erratum, "sum to -7, not 0"));
    assert!(has_note(&s, NoteKind::Erratum, "The centre must be 8"));
    // the built-in kernels that sum right get no erratum
    for k in filter::NAMES
        .into_iter()
        .filter(|&k| !matches!(k, "median" | "laplacian-004"))
    {
        let s = solve(
            "filter-window",
            &Record::new()
                .with("kernel", k)
                .with("select_c", 3.0)
                .with("select_r", 3.0),
        )
        .unwrap();
        assert!(s.notes.iter().all(|n| !n.text.contains("must be 8")), "{k}");
        let sum = result(&s, "kernel_sum");
        assert!(sum.abs() < 1e-12 || (sum - 1.0).abs() < 1e-12, "{k}: {sum}");
    }
}

#[test]
fn every_kernel_median_and_custom_kernels() {
    // 5×5 kernels on the 5×5 window: one output pixel, the centre
    let s = solve(
        "filter-window",
        &Record::new()
            .with("kernel", "gaussian-5")
            .with("select_c", 3.0)
            .with("select_r", 3.0),
    )
    .unwrap();
    assert_eq!(result_matrix(&s, "output").len(), 1);
    let g = Grid::from_rows(
        "w",
        &rows(photogrammetry_playground::examples::filters::EXAMPLE_15),
    )
    .unwrap();
    let direct = filter::pixel_sum(&g, &filter::gaussian5(), 2, 2, Border::Crop)
        .unwrap()
        .value;
    assert_eq!(result(&s, "selected"), direct);
    // the default selection (2, 2) has no output under a 5×5 kernel: a warning, null
    let s = solve("filter-window", &Record::new().with("kernel", "log")).unwrap();
    assert_eq!(s.result.get("selected"), Some(&Value::Null));
    assert!(has_note(
        &s,
        NoteKind::Warning,
        "reaches outside the window"
    ));
    assert!(has_note(&s, NoteKind::Convention, "Laplacian of Gaussian"));
    // median of (r2, c2)'s nine values 10 13 3 11 15 10 9 24 7 → 10
    let s = solve("filter-window", &Record::new().with("kernel", "median")).unwrap();
    assert_eq!(result(&s, "selected"), 10.0);
    assert_eq!(s.result.get("kernel"), Some(&Value::Null));
    let st = s
        .steps
        .iter()
        .find(|st| st.title.contains("written out"))
        .unwrap();
    assert!(
        st.substituted.contains("3, 7, 9, 10, 10, 11, 13, 15, 24"),
        "{}",
        st.substituted
    );
    // custom: a 1/16 kernel typed as integers equals the built-in Gaussian
    let s = solve(
        "filter-window",
        &Record::new()
            .with("kernel", "custom")
            .with(
                "custom_kernel",
                Value::matrix(&rows([[1.0, 2.0, 1.0], [2.0, 4.0, 2.0], [1.0, 2.0, 1.0]])),
            )
            .with("custom_divisor", 16.0),
    )
    .unwrap();
    let gauss = solve("filter-window", &Record::new().with("kernel", "gaussian-3")).unwrap();
    assert_eq!(result_matrix(&s, "output"), result_matrix(&gauss, "output"));
    // a custom 1×3 kernel (odd, not square) is fine; its sum is noted
    let s = solve(
        "filter-window",
        &Record::new()
            .with("kernel", "custom")
            .with("custom_kernel", Value::matrix(&[vec![1.0, 1.0, 1.0]])),
    )
    .unwrap();
    assert_eq!(result_matrix(&s, "output")[0].len(), 3);
    assert_eq!(result_matrix(&s, "output").len(), 5);
    assert!(has_note(&s, NoteKind::Warning, "sum to 3"));
}

#[test]
fn border_policies_give_whole_window_output() {
    for (b, corner) in [
        // (r1, c1) under the 3×3 mean
        (
            "replicate",
            (10.0 * 4.0 + 13.0 * 2.0 + 11.0 * 2.0 + 15.0) / 9.0,
        ),
        (
            "reflect",
            (15.0 + 11.0 + 15.0 + 13.0 + 10.0 + 13.0 + 15.0 + 11.0 + 15.0) / 9.0,
        ),
        ("zero", (10.0 + 13.0 + 11.0 + 15.0) / 9.0),
    ] {
        let s = solve(
            "filter-window",
            &Record::new()
                .with("border", b)
                .with("select_c", 1.0)
                .with("select_r", 1.0),
        )
        .unwrap();
        let out = result_matrix(&s, "output");
        assert_eq!((out.len(), out[0].len()), (5, 5));
        assert!((out[0][0] - corner).abs() < 1e-12, "{b}");
        assert!((result(&s, "selected") - corner).abs() < 1e-12, "{b}");
        assert!((out[1][1] - 102.0 / 9.0).abs() < 1e-12);
        assert!(s.textbook.is_none());
        assert_eq!(result(&s, "output_first_c"), 1.0);
        let e = solve("edge-window", &Record::new().with("border", b)).unwrap();
        assert_eq!(result_matrix(&e, "gx").len(), 5);
        assert_eq!(result_matrix(&e, "gx")[1][1], -14.0);
    }
}

// ---------------------------------------------------------------------------
// filter properties

fn smoothing() -> Vec<Kernel> {
    vec![
        filter::mean3(),
        filter::weighted_mean(),
        filter::gaussian3(),
        filter::gaussian5(),
        filter::sharpen(),
    ]
}
fn derivatives() -> Vec<Kernel> {
    vec![
        filter::laplacian4(),
        filter::laplacian8(),
        filter::log5(),
        filter::high_pass(),
        filter::prewitt_x(),
        filter::prewitt_y(),
        filter::sobel_x(),
        filter::sobel_y(),
        filter::central_c(),
        filter::central_r(),
    ]
}

#[test]
fn a_constant_image_is_kept_by_smoothing_and_zero_under_derivatives() {
    let g = Grid::filled(7, 6, 42.0);
    for border in [Border::Crop, Border::Replicate, Border::Reflect] {
        for k in smoothing() {
            let f = filter::correlate(&g, &k, border).unwrap();
            assert!(
                f.output.data().iter().all(|v| (v - 42.0).abs() < 1e-12),
                "{k:?} {border:?}"
            );
        }
        for k in derivatives() {
            let f = filter::correlate(&g, &k, border).unwrap();
            assert!(
                f.output.data().iter().all(|v| v.abs() < 1e-12),
                "{k:?} {border:?}"
            );
        }
        let m = filter::median(&g, 3, 3, border).unwrap();
        assert!(m.output.data().iter().all(|v| *v == 42.0));
        let gr = filter::gradient(&g, &filter::sobel_x(), &filter::sobel_y(), border).unwrap();
        assert!(gr.magnitude.data().iter().all(|v| *v == 0.0));
    }
}

#[test]
fn mean_and_median_agree_with_a_direct_computation_on_random_windows() {
    let mut rng = Rng(0x5eed_0004);
    for _ in 0..50 {
        let (w, h) = (3 + rng.below(6), 3 + rng.below(6));
        let g = rng.grid(w, h);
        let mean = filter::correlate(&g, &filter::mean3(), Border::Crop).unwrap();
        let median = filter::median(&g, 3, 3, Border::Crop).unwrap();
        for r in 1..h - 1 {
            for c in 1..w - 1 {
                let mut v = Vec::new();
                for j in r - 1..=r + 1 {
                    for i in c - 1..=c + 1 {
                        v.push(g.get(i, j).unwrap());
                    }
                }
                let m = v.iter().sum::<f64>() / 9.0;
                assert!((mean.at_input(c, r).unwrap() - m).abs() < 1e-9);
                v.sort_by(|a, b| a.partial_cmp(b).unwrap());
                assert_eq!(median.at_input(c, r), Some(v[4]));
            }
        }
    }
}

#[test]
fn the_written_out_sum_is_the_whole_image_operator_bit_for_bit() {
    let mut rng = Rng(0x5eed_0005);
    let mut kernels = smoothing();
    kernels.extend(derivatives());
    kernels.push(filter::laplacian_seed004_printed());
    for _ in 0..10 {
        let (w, h) = (4 + rng.below(5), 4 + rng.below(5));
        let g = rng.grid(w, h);
        for k in &kernels {
            for border in [
                Border::Crop,
                Border::Replicate,
                Border::Reflect,
                Border::Zero,
            ] {
                let Ok(f) = filter::correlate(&g, k, border) else {
                    continue;
                };
                for r in 0..g.height() {
                    for c in 0..g.width() {
                        let p = filter::pixel_sum(&g, k, c, r, border).map(|p| p.value);
                        assert_eq!(p, f.at_input(c, r), "{k:?} {border:?} ({c}, {r})");
                    }
                }
            }
        }
    }
}

#[test]
fn gradients_for_the_forstner_operator_share_one_region() {
    // central differences (g(c+1) − g(c−1))/2 along columns and rows
    let g = Grid::from_fn(5, 4, |c, r| (c * c + 3 * r) as f64);
    let d = filter::gradient(&g, &filter::central_c(), &filter::central_r(), Border::Crop).unwrap();
    assert_eq!(
        (d.region.c0, d.region.r0, d.region.width, d.region.height),
        (1, 1, 3, 2)
    );
    assert_eq!(d.gx.rows(), vec![vec![2.0, 4.0, 6.0], vec![2.0, 4.0, 6.0]]);
    assert_eq!(d.gy.rows(), vec![vec![3.0; 3], vec![3.0; 3]]);
}

// ---------------------------------------------------------------------------
// bad inputs

fn err(id: &str, inputs: Record) -> String {
    solve(id, &inputs).expect_err("should fail").to_string()
}

#[test]
fn bad_inputs_name_the_field_and_say_what_is_wrong() {
    let r = Record::new;
    // positions outside the patch
    assert_eq!(
        err("resample", r().with("c", 548.5)),
        "c: 548.5 is outside the patch: its pixel centres run from column 545 to 548"
    );
    assert_eq!(
        err("resample", r().with("r", 816.0)),
        "r: 816 is outside the patch: its pixel centres run from row 817 to 820"
    );
    assert_eq!(
        err(
            "resample",
            r().with("patch", Value::matrix(&[vec![1.0, 2.0]]))
        ),
        "patch: is 1×2 (rows × columns); bilinear interpolation needs at least 2×2 pixels"
    );
    assert_eq!(
        err("resample", r().with("c", f64::NAN)),
        "c: is NaN; give a number"
    );
    // empty and ragged windows
    assert!(
        err("filter-window", r().with("window", Value::List(vec![])))
            .starts_with("window: is empty")
    );
    assert!(err(
        "edge-window",
        r().with("window", Value::matrix(&[vec![1.0, 2.0, 3.0], vec![4.0]]))
    )
    .starts_with("window: rows must all have the same length"));
    assert!(err(
        "resample",
        r().with("patch", Value::matrix(&[vec![1.0, 2.0], vec![3.0]]))
    )
    .starts_with("patch: rows must all have the same length"));
    assert_eq!(
        err("filter-window", r().with("window", Value::matrix(&[vec![1.0, 2.0], vec![3.0, 4.0]]))),
        "window: is 2×2 (rows × columns); the 3×3 kernel fits nowhere inside it — give a larger window or a border policy other than crop"
    );
    // even-sized, empty and oversized custom kernels
    let custom = |k: Value| r().with("kernel", "custom").with("custom_kernel", k);
    assert_eq!(
        err("filter-window", custom(Value::matrix(&[vec![1.0, 1.0], vec![1.0, 1.0]]))),
        "custom_kernel: is 2×2; a kernel needs an odd number of rows and of columns, so that it has a centre pixel"
    );
    assert!(
        err("filter-window", custom(Value::List(vec![]))).starts_with("custom_kernel: is empty")
    );
    assert_eq!(
        err(
            "filter-window",
            custom(Value::matrix(&vec![vec![1.0; 17]; 17]))
        ),
        "custom_kernel: is 17×17; at most 15×15 is allowed"
    );
    assert_eq!(
        err(
            "filter-window",
            r().with("kernel", "custom").with("custom_divisor", 0.0)
        ),
        "custom_divisor: must be greater than 0 (got 0)"
    );
    // with another kernel the custom fields do not apply: ignored
    assert!(solve("filter-window", &r().with("custom_divisor", 0.0)).is_ok());
    // selections and choices
    assert_eq!(
        err("filter-window", r().with("select_c", 6.0)),
        "select_c: column 6 is outside the window (it has 5 columns)"
    );
    assert_eq!(
        err("edge-window", r().with("select_r", 0.0)),
        "select_r: must be at least 1 (got 0)"
    );
    assert!(err("filter-window", r().with("kernel", "box"))
        .starts_with("kernel: \"box\" is not one of the choices"));
    assert!(err("edge-window", r().with("operator", "canny"))
        .starts_with("operator: \"canny\" is not one of the choices"));
    assert!(err("edge-window", r().with("border", "wrap"))
        .starts_with("border: \"wrap\" is not one of the choices"));
    assert!(err("filter-window", r().with("window", "1 2 3"))
        .starts_with("window: must be a list of rows"));
    // the core rejects bad kernels itself
    assert!(Kernel::new("k", &[vec![1.0, 2.0, 3.0, 4.0]], 1.0).is_err());
    assert!(Kernel::new("k", &[vec![1.0]], 0.0).is_err());
    assert!(filter::median(&Grid::filled(3, 3, 1.0), 2, 3, Border::Crop).is_err());
    assert!(filter::correlate(&Grid::filled(2, 9, 1.0), &filter::mean3(), Border::Crop).is_err());
}

#[test]
fn texts_parse_into_the_same_solutions() {
    let p = parse_inputs(
        "filter-window",
        &Record::new()
            .with(
                "window",
                "1 2 1 1 1; 1 1 9 2 1; 1 9 9 8 1; 1 1 8 1 2; 2 1 1 1 1",
            )
            .with("kernel", "laplacian-8"),
    )
    .unwrap();
    assert!(p.errors.is_empty());
    let s = solve("filter-window", &p.inputs).unwrap();
    assert_eq!(result_matrix(&s, "output")[0][0], 25.0);
    let p = parse_inputs(
        "filter-window",
        &Record::new().with("custom_kernel", "1 1; 1 1"),
    )
    .unwrap();
    assert!(
        p.errors.is_empty(),
        "shape is checked when the kernel is used"
    );
    let p = parse_inputs("resample", &Record::new().with("patch", "1 2; 3")).unwrap();
    assert!(p.errors.get("patch").is_some());
}

#[test]
fn central_difference_kernels_equal_the_forstner_operators_gradients() {
    // one computation path: filter::gradient with central_c/central_r is the
    // interest module's central_difference at every interior pixel
    let mut rng = Rng(0x5eed_0006);
    for _ in 0..10 {
        let (w, h) = (3 + rng.below(6), 3 + rng.below(6));
        let g = rng.grid(w, h);
        let d =
            filter::gradient(&g, &filter::central_c(), &filter::central_r(), Border::Crop).unwrap();
        for r in 1..h - 1 {
            for c in 1..w - 1 {
                let (gx, gy) =
                    photogrammetry_playground::interest::central_difference(&g, c, r).unwrap();
                assert_eq!(d.gx.get(c - 1, r - 1), Some(gx));
                assert_eq!(d.gy.get(c - 1, r - 1), Some(gy));
            }
        }
    }
}

// ---------------------------------------------------------------- issue 30

mod parts_common;

/// Issue 30, item 2: every step is data (its LaTeX made from its parts) and
/// every practice box's hints come from the relation keyed with its value.
#[test]
fn resampling_and_filters_steps_are_data_and_hints_are_keyed() {
    let with_numbers = parts_common::steps_are_data_and_hints_are_keyed(
        &photogrammetry_playground::examples::resampling::TOPIC,
        10,
    );
    // nearest, I1, I2, I and the bicubic value: in every variant
    assert_eq!(with_numbers, 10 * 5);
    let s = solve("resample", &Record::new()).unwrap();
    let st = s
        .steps
        .iter()
        .find(|st| st.title.contains("between the rows"))
        .unwrap();
    assert_eq!(st.formula, r"I = I_1 + dr\,(I_2 - I_1)");
    assert_eq!(
        st.substituted,
        r"I = 75.08 + 0.24\,(76.24 - 75.08) = 75.3584,\quad I \approx 75"
    );
    // the bicubic value: the row weights times the weighted rows of P
    let s = solve(
        "resample",
        &Record::new().with("c", 546.44).with("r", 818.24),
    )
    .unwrap();
    let st = s
        .steps
        .iter()
        .find(|st| st.title.contains("4×4 product"))
        .unwrap();
    let q = st
        .parts
        .iter()
        .find(|r| r.key.as_deref() == Some("bicubic"))
        .unwrap();
    assert!(
        q.question_latex().starts_with(r"Q = [-0.1"),
        "{}",
        q.question_latex()
    );
    assert!(
        st.substituted
            .starts_with(r"P = \begin{bmatrix}68 & 64 & 72 & 79 \\"),
        "{}",
        st.substituted
    );
}

#[test]
fn filters_steps_are_data_and_hints_are_keyed() {
    let with_numbers = parts_common::steps_are_data_and_hints_are_keyed(
        &photogrammetry_playground::examples::filters::TOPIC,
        10,
    );
    // the sum of filter-window (its output boxes are elements of the whole
    // filtered grid: formula and nudge only) and the three boxes of
    // edge-window, whose variants select the centre: in every variant
    assert_eq!(with_numbers, 10 * (1 + 3));
    let s = solve(
        "edge-window",
        &Record::new().with("select_c", 3.0).with("select_r", 3.0),
    )
    .unwrap();
    let st = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Gx at"))
        .unwrap();
    assert_eq!(
        st.formula,
        r"G_x(r, c) = \sum_j\sum_i \mathrm{pk_x}(i, j)\, f(r + j, c + i)"
    );
    assert_eq!(
        st.parts[1].question_latex(),
        r"G_x(r_{3}, c_{3}) = 15 + 10 + 9 - 13 - 14 - 15 = \;?"
    );
    // a kernel with its divisor: the factor, then the numerators as a grid
    let s = solve("filter-window", &Record::new().with("kernel", "gaussian-3")).unwrap();
    let w = &s.steps[0].parts[0];
    assert_eq!(w.substituted[0].0.len(), 2);
    assert_eq!(
        s.steps[0].substituted,
        r"w = \frac{1}{16} \begin{bmatrix}1 & 2 & 1 \\ 2 & 4 & 2 \\ 1 & 2 & 1\end{bmatrix}"
    );
}
