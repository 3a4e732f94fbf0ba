//! Interest operators: seed 000 Examples 13 (Förstner) and 14 (Moravec)
//! reproduced number by number with the printed values and notes; seed 003's
//! precision test; the properties of N (flat, edge, symmetric corner, 90°
//! rotation); whole-image maps equal to the window computation; thresholding,
//! suppression and the test pattern; every class of bad input.
#![cfg(not(target_arch = "wasm32"))]

use photogrammetry_playground::examples::{parse_inputs, solve};
use photogrammetry_playground::interest::{
    self, central_difference, forstner, forstner_map, forstner_points, moravec, moravec_map,
    moravec_points, precision, suppress, test_pattern, window_at, Case,
};
use photogrammetry_playground::raster::Grid;
use photogrammetry_playground::solution::{NoteKind, Piece, Record, Relation, Solution, Value};

/// A tiny deterministic generator (xorshift64*), fixed seeds only.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
    /// A whole grey value in [0, 255].
    fn grey(&mut self) -> f64 {
        (self.next() * 256.0).floor().min(255.0)
    }
}

fn grid(rows: &[&[f64]]) -> Grid {
    Grid::from_rows(
        "window",
        &rows.iter().map(|r| r.to_vec()).collect::<Vec<_>>(),
    )
    .unwrap()
}

fn random_grid(rng: &mut Rng, w: usize, h: usize) -> Grid {
    let data = (0..w * h).map(|_| rng.grey()).collect();
    Grid::new("window", w, h, data).unwrap()
}

/// The window turned by 90° (clockwise: new (c, r) = (h−1−r, c)).
fn rotate(g: &Grid) -> Grid {
    let (w, h) = (g.width(), g.height());
    Grid::from_fn(h, w, |c, r| g.get(r, h - 1 - c).unwrap())
}

fn example_13() -> Grid {
    grid(&[
        &[10.0, 13.0, 3.0, 11.0, 13.0],
        &[11.0, 15.0, 10.0, 9.0, 9.0],
        &[9.0, 24.0, 7.0, 8.0, 10.0],
        &[10.0, 13.0, 14.0, 15.0, 13.0],
        &[13.0, 18.0, 17.0, 19.0, 21.0],
    ])
}

fn num(s: &Solution, key: &str) -> f64 {
    s.result
        .number(key)
        .unwrap_or_else(|| panic!("result {key} of {} is not a number", s.id))
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

fn has_note(s: &Solution, kind: NoteKind, needle: &str) -> bool {
    s.notes
        .iter()
        .any(|n| n.kind == kind && n.text.contains(needle))
}

fn err(id: &str, inputs: Record) -> String {
    solve(id, &inputs).unwrap_err().to_string()
}

// ---------------------------------------------------------------- Example 13

#[test]
fn example_13_gradient_table_row_by_row() {
    let f = forstner(&example_13()).unwrap();
    // the seed's table: (c, r) from 1, g'x, g'y, product, squares
    let seed: [(usize, usize, f64, f64, f64, f64, f64); 9] = [
        (2, 2, -0.5, 5.5, -2.75, 0.25, 30.25),
        (3, 2, -3.0, 2.0, -6.0, 9.0, 4.0),
        (4, 2, -0.5, -1.5, 0.75, 0.25, 2.25),
        (2, 3, -1.0, -1.0, 1.0, 1.0, 1.0),
        (3, 3, -8.0, 2.0, -16.0, 64.0, 4.0),
        (4, 3, 1.5, 3.0, 4.5, 2.25, 9.0),
        (2, 4, 2.0, -3.0, -6.0, 4.0, 9.0),
        (3, 4, 1.0, 5.0, 5.0, 1.0, 25.0),
        (4, 4, -0.5, 5.5, -2.75, 0.25, 30.25),
    ];
    assert_eq!(f.rows.len(), 9);
    for (row, s) in f.rows.iter().zip(seed) {
        assert_eq!(
            (
                row.c + 1,
                row.r + 1,
                row.gx,
                row.gy,
                row.gxgy,
                row.gx2,
                row.gy2
            ),
            s
        );
    }
    assert_eq!(f.sums.gx, -9.0);
    assert_eq!(f.sums.gy, 17.5);
    assert_eq!(f.sums.gxgy, -22.25);
    assert_eq!(f.sums.gx2, 82.0);
    assert_eq!(f.sums.gy2, 114.75);
    // the table's neighbours are the seed's: P(c3, r3) = 7, (8 − 24)/2, (14 − 10)/2
    let p = f.rows[4];
    assert_eq!(
        (p.g, p.right, p.left, p.down, p.up),
        (7.0, 8.0, 24.0, 14.0, 10.0)
    );
    assert_eq!(central_difference(&example_13(), 2, 2), Some((-8.0, 2.0)));
    assert_eq!(central_difference(&example_13(), 0, 2), None);
}

#[test]
fn example_13_solution_exact_values_printed_values_and_notes() {
    let s = solve("forstner-window", &Record::new()).unwrap();
    let det = 82.0 * 114.75 - 22.25 * 22.25;
    assert_eq!(det, 8914.4375);
    assert_eq!(
        matrix(s.result.get("n").unwrap()),
        [[82.0, -22.25], [-22.25, 114.75]]
    );
    assert_eq!(num(&s, "det_n"), det);
    let inv = matrix(s.result.get("n_inverse").unwrap());
    let expect = [[114.75 / det, 22.25 / det], [22.25 / det, 82.0 / det]];
    for (a, b) in inv.iter().flatten().zip(expect.iter().flatten()) {
        assert!((a - b).abs() < 1e-15, "{a} vs {b}");
    }
    assert!((num(&s, "trace_n_inverse") - 196.75 / det).abs() < 1e-15);
    assert!((num(&s, "trace_n_inverse") - 0.022_070_938).abs() < 1e-9);
    assert!((num(&s, "w") - det / 196.75).abs() < 1e-12);
    assert!((num(&s, "q") - 4.0 * det / (196.75 * 196.75)).abs() < 1e-15);
    let root = (16.375f64 * 16.375 + 22.25 * 22.25).sqrt();
    assert!((num(&s, "lambda_max") - (98.375 + root)).abs() < 1e-12);
    assert!((num(&s, "lambda_min") - (98.375 - root)).abs() < 1e-12);
    assert!((num(&s, "lambda_min") - 70.748_868_8).abs() < 1e-6);
    // seed 003 with σn = 1: λmax(Σuv) = 1/λmin(N) ≤ 0.25 → accepted, a corner
    assert!((num(&s, "lambda_max_shift") - 1.0 / (98.375 - root)).abs() < 1e-15);
    assert_eq!(s.result.get("accepted"), Some(&Value::Bool(true)));
    assert_eq!(s.result.get("case"), Some(&Value::from("corner")));
    assert_eq!(
        matrix(s.result.get("gx").unwrap()),
        [[-0.5, -3.0, -0.5], [-1.0, -8.0, 1.5], [2.0, 1.0, -0.5]]
    );
    assert_eq!(
        matrix(s.result.get("gy").unwrap()),
        [[5.5, 2.0, -1.5], [-1.0, 2.0, 3.0], [-3.0, 5.0, 5.5]]
    );
    // CATALOG.md keys first, in order
    let keys: Vec<_> = s.result.keys().take(11).collect();
    assert_eq!(
        keys,
        [
            "gx",
            "gy",
            "n",
            "det_n",
            "n_inverse",
            "trace_n_inverse",
            "w",
            "q",
            "lambda_min",
            "lambda_max_shift",
            "accepted"
        ]
    );
    // printed values beside the exact ones
    let t = s.textbook.as_ref().expect("textbook for the seed's inputs");
    assert_eq!(
        matrix(t.get("n").unwrap()),
        [[82.0, -22.75], [-22.75, 114.75]]
    );
    assert_eq!(t.number("det_n"), Some(8891.9375));
    assert_eq!(t.number("trace_n_inverse"), Some(0.02));
    assert_eq!(t.number("sum_gxgy"), Some(-22.25));
    assert_eq!(t.number("sum_gx2"), Some(82.0));
    assert!(has_note(&s, NoteKind::Erratum, "-22.75 off the diagonal"));
    assert!(has_note(&s, NoteKind::Erratum, "8891.938 instead of"));
    assert!(has_note(&s, NoteKind::Rounding, "0.02207094"));
    assert!(has_note(&s, NoteKind::Rounding, "0.02212679"));
    assert!(has_note(&s, NoteKind::Erratum, "is backwards"));
    assert!(has_note(&s, NoteKind::Convention, "no noise level"));
    // the table step lays out the seed's rows
    let table = &s.steps[0].substituted;
    assert!(table.contains(r"P(c_{2}, r_{2}) = 15 & (10 - 11)/2 = -0.5 & (24 - 13)/2 = 5.5 \\"));
    assert!(table.contains(r"P(c_{3}, r_{3}) = 7 & (8 - 24)/2 = -8 & (14 - 10)/2 = 2 \\"));
    let products = &s.steps[1].substituted;
    assert!(products.contains(r"P(c_{2}, r_{2}) & -0.5 & 5.5 & -2.75 & 0.25 & 30.25 \\"));
    assert!(products.contains(r"\text{sum} & -9 & 17.5 & -22.25 & 82 & 114.75"));
    assert!(s.steps[3].substituted.contains("8914.438"));
    for step in &s.steps {
        assert!(!step.formula.is_empty(), "{}", step.title);
        assert!(!step.substituted.is_empty(), "{}", step.title);
    }
}

#[test]
fn threshold_and_noise_decide_acceptance_and_the_case() {
    // σmax = 0.1189 px, σmin = 0.0891 px at σn = 1
    let s = solve("forstner-window", &Record::new().with("threshold_px", 0.1)).unwrap();
    assert_eq!(s.result.get("accepted"), Some(&Value::Bool(false)));
    assert_eq!(s.result.get("case"), Some(&Value::from("edge")));
    assert!(s.textbook.is_none());
    let s = solve("forstner-window", &Record::new().with("sigma_n", 10.0)).unwrap();
    assert_eq!(s.result.get("case"), Some(&Value::from("flat")));
    let s = solve("forstner-window", &Record::new().with("sigma_n", 4.0)).unwrap();
    assert!((num(&s, "lambda_max_shift") - 16.0 / num(&s, "lambda_min")).abs() < 1e-15);
    assert!((num(&s, "sigma_max_px") - 4.0 * 0.118_888_610).abs() < 1e-8);
}

// ---------------------------------------------------------------- Example 14

#[test]
fn example_14_moravec_reproduced() {
    let s = solve("moravec-window", &Record::new()).unwrap();
    assert_eq!(
        matrix(s.result.get("sums").unwrap()),
        [[47.0, 361.0], [153.0, 171.0]]
    );
    assert_eq!(num(&s, "mean"), 183.0);
    let keys: Vec<_> = s.result.keys().take(2).collect();
    assert_eq!(keys, ["sums", "mean"]);
    // the four differences of each pixel: row, column, main, other diagonal
    assert_eq!(
        matrix(s.result.get("differences").unwrap()),
        [
            [2.0, 2.0, 27.0, -1.0, -1.0, 3.0, 6.0, 47.0],
            [3.0, 2.0, 9.0, -16.0, 10.0, -2.0, 1.0, 361.0],
            [2.0, 3.0, 14.0, 4.0, -8.0, 8.0, 3.0, 153.0],
            [3.0, 3.0, 15.0, -1.0, 9.0, -5.0, 8.0, 171.0],
        ]
    );
    let t = s.textbook.as_ref().unwrap();
    assert_eq!(t.number("mean"), Some(183.0));
    assert_eq!(
        matrix(t.get("sums").unwrap()),
        [[47.0, 361.0], [153.0, 171.0]]
    );
    assert!(has_note(
        &s,
        NoteKind::Convention,
        "agree with the course notes"
    ));
    assert!(has_note(&s, NoteKind::Convention, "MINIMUM"));
    assert!(s.steps[0]
        .substituted
        .contains(r"S(c_{2}, r_{2}) = (9 - 10)^2 + (14 - 15)^2 + (15 - 12)^2 + (11 - 5)^2 = 47"));
    assert!(s.steps[1]
        .substituted
        .contains(r"\sum S = 47 + 361 + 153 + 171 = 732,\quad \bar S = \frac{732}{4} = 183"));
}

#[test]
fn moravec_8x8_and_a_flat_window() {
    let mut rng = Rng(14);
    let w = random_grid(&mut rng, 8, 8);
    let m = moravec(&w).unwrap();
    assert_eq!(m.pixels.len(), 36);
    let by_hand: f64 = m
        .pixels
        .iter()
        .map(|p| {
            let g = |dc: isize, dr: isize| {
                w.get((p.c as isize + dc) as usize, (p.r as isize + dr) as usize)
                    .unwrap()
            };
            [
                g(1, 0) - g(-1, 0),
                g(0, 1) - g(0, -1),
                g(1, 1) - g(-1, -1),
                g(-1, 1) - g(1, -1),
            ]
            .iter()
            .map(|d| d * d)
            .sum::<f64>()
        })
        .sum::<f64>()
        / 36.0;
    assert_eq!(m.mean, by_hand);
    let s = solve(
        "moravec-window",
        &Record::new().with("window", Value::matrix(&vec![vec![9.0; 4]; 4])),
    )
    .unwrap();
    assert_eq!(num(&s, "mean"), 0.0);
    assert!(s.textbook.is_none());
}

// ---------------------------------------------------------------- properties

#[test]
fn flat_window_has_n_zero_and_no_division() {
    for (v, size) in [(0.0, 5), (17.0, 5), (255.0, 7), (-3.5, 3)] {
        let w = Value::matrix(&vec![vec![v; size]; size]);
        let s = solve("forstner-window", &Record::new().with("window", w)).unwrap();
        assert_eq!(matrix(s.result.get("n").unwrap()), [[0.0, 0.0], [0.0, 0.0]]);
        assert_eq!(num(&s, "det_n"), 0.0);
        assert_eq!(num(&s, "w"), 0.0);
        assert_eq!(num(&s, "lambda_min"), 0.0);
        for key in ["n_inverse", "trace_n_inverse", "q", "lambda_max_shift"] {
            assert_eq!(s.result.get(key), Some(&Value::Null), "{key}");
        }
        assert_eq!(s.result.get("accepted"), Some(&Value::Bool(false)));
        assert_eq!(s.result.get("case"), Some(&Value::from("flat")));
        assert!(has_note(&s, NoteKind::Warning, "flat"));
    }
}

#[test]
fn straight_edges_give_lambda_min_zero_and_q_zero() {
    let mut rng = Rng(3);
    for trial in 0..60 {
        let size = [3, 5, 7][trial % 3];
        let profile: Vec<f64> = (0..2 * size + 1).map(|_| rng.grey()).collect();
        let (a, b) = (rng.next() * 20.0 - 10.0, rng.next() * 20.0 - 10.0);
        let w = match trial % 5 {
            // step edges with any profile, across columns, rows, the diagonal
            0 => Grid::from_fn(size, size, |c, _| profile[c]),
            1 => Grid::from_fn(size, size, |_, r| profile[r]),
            2 => Grid::from_fn(size, size, |c, r| profile[c + r]),
            3 => Grid::from_fn(size, size, |c, r| profile[c + size - 1 - r]),
            // a linear ramp in any direction
            _ => Grid::from_fn(size, size, |c, r| a * c as f64 + b * r as f64),
        };
        let f = forstner(&w).unwrap();
        let m = f.measures;
        if m.trace == 0.0 {
            continue; // a constant profile: flat, tested above
        }
        assert!(m.singular, "trial {trial}: {:?}", m.n);
        assert_eq!(m.lambda_min, 0.0, "trial {trial}");
        assert_eq!(m.q, Some(0.0), "trial {trial}");
        assert_eq!(m.w, 0.0);
        assert_eq!((m.inverse, m.trace_inverse), (None, None));
        let p = precision(&m, 1.0, 0.5);
        assert_eq!(p.lambda_max_shift, None);
        assert!(!p.accepted);
        assert_ne!(p.case, Case::Corner);
    }
    let s = solve(
        "forstner-window",
        &Record::new().with(
            "window",
            Value::matrix(&vec![vec![10.0, 10.0, 10.0, 200.0, 200.0]; 5]),
        ),
    )
    .unwrap();
    assert_eq!(num(&s, "q"), 0.0);
    assert_eq!(num(&s, "lambda_min"), 0.0);
    assert_eq!(s.result.get("lambda_max_shift"), Some(&Value::Null));
    assert_eq!(s.result.get("case"), Some(&Value::from("edge")));
    assert!(has_note(&s, NoteKind::Warning, "straight edge"));
}

#[test]
fn symmetric_corners_give_q_one() {
    // a window that a quarter turn maps onto itself has N = λ·I
    let mut rng = Rng(11);
    for size in [3, 5, 7, 9] {
        for _ in 0..20 {
            let mut w = random_grid(&mut rng, size, size);
            for _ in 0..3 {
                let turned = rotate(&w);
                w = Grid::from_fn(size, size, |c, r| {
                    w.get(c, r).unwrap().max(turned.get(c, r).unwrap())
                });
            }
            assert_eq!(rotate(&w), w);
            let m = forstner(&w).unwrap().measures;
            if m.trace == 0.0 {
                continue;
            }
            assert!((m.q.unwrap() - 1.0).abs() < 1e-12, "{:?}", m.n);
            assert_eq!(m.n[0][1], 0.0);
            assert_eq!(m.n[0][0], m.n[1][1]);
            assert_eq!(m.lambda_min, m.lambda_max);
        }
    }
    // a bright square centred in the window: four symmetric corners
    let mut rows = vec![vec![20.0; 7]; 7];
    for row in rows.iter_mut().take(5).skip(2) {
        for v in row.iter_mut().take(5).skip(2) {
            *v = 220.0;
        }
    }
    let s = solve(
        "forstner-window",
        &Record::new().with("window", Value::matrix(&rows)),
    )
    .unwrap();
    assert!((num(&s, "q") - 1.0).abs() < 1e-15);
    assert_eq!(s.result.get("case"), Some(&Value::from("corner")));
    assert!((num(&s, "sigma_max_px") - num(&s, "sigma_min_px")).abs() < 1e-15);
}

#[test]
fn a_quarter_turn_leaves_w_and_q_unchanged() {
    let mut rng = Rng(90);
    for (w, h) in [(5, 5), (7, 7), (4, 6), (3, 8), (8, 8)] {
        for _ in 0..25 {
            let g = random_grid(&mut rng, w, h);
            let a = forstner(&g).unwrap().measures;
            let b = forstner(&rotate(&g)).unwrap().measures;
            // N turns: the diagonal swaps, the off-diagonal changes sign
            assert_eq!(b.n[0][0], a.n[1][1]);
            assert_eq!(b.n[1][1], a.n[0][0]);
            assert_eq!(b.n[0][1], -a.n[0][1]);
            let rel = |x: f64, y: f64| (x - y).abs() <= 1e-12 * x.abs().max(1.0);
            assert!(rel(a.w, b.w), "{} vs {}", a.w, b.w);
            assert!(rel(a.q.unwrap(), b.q.unwrap()));
            assert!(rel(a.lambda_min, b.lambda_min));
            assert!(rel(a.det, b.det));
            // the ellipse turns with the window
            let turn = (b.weak_angle - a.weak_angle).to_degrees().rem_euclid(180.0);
            if a.q.unwrap() < 0.999 {
                assert!((turn - 90.0).abs() < 1e-6, "{turn}");
            }
        }
    }
}

#[test]
fn whole_image_maps_equal_the_window_computation() {
    let mut rng = Rng(2024);
    let image = random_grid(&mut rng, 23, 19);
    for size in [5, 7] {
        let map = forstner_map(&image, size).unwrap();
        let a = interest::anchor(size);
        for r in 0..19 {
            for c in 0..23 {
                let inside = c >= a && r >= a && c + size - a <= 23 && r + size - a <= 19;
                match window_at(&image, c, r, size) {
                    Some(w) => {
                        assert!(inside);
                        assert_eq!(map.get(c, r), Some(forstner(&w).unwrap().measures));
                        // the window is the one around (c, r)
                        assert_eq!(w.get(a, a), image.get(c, r));
                    }
                    None => {
                        assert!(!inside);
                        assert_eq!(map.get(c, r), None);
                    }
                }
            }
        }
    }
    for size in [4, 8] {
        let map = moravec_map(&image, size).unwrap();
        let mut n = 0;
        for r in 0..19 {
            for c in 0..23 {
                let expect = window_at(&image, c, r, size).map(|w| moravec(&w).unwrap().mean);
                assert_eq!(map.get(c, r), expect);
                n += usize::from(expect.is_some());
            }
        }
        assert_eq!(n, (23 - size + 1) * (19 - size + 1));
    }
}

#[test]
fn thresholding_and_suppression() {
    let image = test_pattern(64, 2.0, 7).unwrap();
    assert_eq!(image, test_pattern(64, 2.0, 7).unwrap(), "deterministic");
    assert_ne!(image, test_pattern(64, 2.0, 8).unwrap());
    for size in [5, 7] {
        let map = forstner_map(&image, size).unwrap();
        for q_min in [0.0, 0.5] {
            let d = forstner_points(&map, 2.0, 0.5, q_min);
            assert_eq!(d.radius, size / 2);
            assert!(!d.points.is_empty());
            for p in &d.candidates {
                let m = map.get(p.c, p.r).unwrap();
                assert!(p.score <= 0.25 && (p.score - 4.0 / m.lambda_min).abs() < 1e-12);
                assert!(q_min == 0.0 || m.q.unwrap() >= q_min);
            }
            for p in &d.points {
                assert!(d.candidates.contains(p));
                // nothing better within the neighbourhood
                for o in &d.candidates {
                    let near = p.c.abs_diff(o.c) <= d.radius && p.r.abs_diff(o.r) <= d.radius;
                    if near && o != p {
                        assert!(o.score >= p.score);
                    }
                }
            }
            // every suppressed candidate has a better-or-equal one near it
            for o in d.candidates.iter().filter(|o| !d.points.contains(o)) {
                assert!(d.candidates.iter().any(|p| p != o
                    && p.c.abs_diff(o.c) <= d.radius
                    && p.r.abs_diff(o.r) <= d.radius
                    && p.score <= o.score));
            }
        }
    }
    let m = moravec_map(&image, 4).unwrap();
    let d = moravec_points(&m, 5000.0);
    assert!(d.candidates.iter().all(|p| p.score > 5000.0));
    assert!(d.points.len() < d.candidates.len());
    assert!(moravec_points(&m, 1e12).points.is_empty());
    // suppression ties: the first in row-major order wins
    assert_eq!(
        suppress(&[Some(2.0), Some(2.0), Some(1.0), None], 2, 2, 1),
        vec![0]
    );
}

#[test]
fn test_pattern_image_mode_finds_the_corners_and_the_three_cases() {
    let s = solve("forstner-image", &Record::new()).unwrap();
    let points: Vec<(f64, f64)> = matrix(s.result.get("points").unwrap())
        .iter()
        .map(|p| (p[0], p[1]))
        .collect();
    assert_eq!(
        points,
        [
            (9.0, 9.0),
            (24.0, 9.0),
            (9.0, 24.0),
            (24.0, 24.0),
            (47.0, 28.0),
            (37.0, 37.0),
            (46.0, 37.0),
            (56.0, 37.0),
            (37.0, 46.0),
            (47.0, 46.0),
            (56.0, 47.0),
            (37.0, 56.0),
            (47.0, 56.0),
            (56.0, 56.0),
        ]
    );
    assert_eq!(s.result.get("case"), Some(&Value::from("corner")));
    assert_eq!(s.result.get("accepted"), Some(&Value::Bool(true)));
    let values = &s.steps[0].values;
    let image = matrix(values.get("image").unwrap());
    assert_eq!((image.len(), image[0].len()), (64, 64));
    // the window shown is the map's window: w equals the map at (c, r)
    let w_map = match values.get("w_map").unwrap() {
        Value::List(rows) => rows.clone(),
        _ => panic!(),
    };
    let at = |c: usize, r: usize| match &w_map[r] {
        Value::List(xs) => xs[c].clone(),
        _ => panic!(),
    };
    assert_eq!(at(8, 8), Value::Number(num(&s, "w")));
    assert_eq!(at(0, 0), Value::Null);
    assert_eq!(at(63, 10), Value::Null);
    let grid = Grid::from_rows("image", &image).unwrap();
    let w = window_at(&grid, 8, 8, 5).unwrap();
    assert_eq!(matrix(s.result.get("window").unwrap()), w.rows());
    assert_eq!(num(&s, "w"), forstner(&w).unwrap().measures.w);

    // on the square's top edge, in the flat background
    let at_pos =
        |c: f64, r: f64| solve("forstner-image", &Record::new().with("c", c).with("r", r)).unwrap();
    let edge = at_pos(16.0, 9.0);
    assert_eq!(edge.result.get("case"), Some(&Value::from("edge")));
    assert!(num(&edge, "q") < 0.1);
    assert!(num(&edge, "sigma_min_px") < 0.5);
    let flat = at_pos(35.0, 12.0);
    assert_eq!(flat.result.get("case"), Some(&Value::from("flat")));
    assert!(num(&flat, "sigma_min_px") > 0.5);
    // the three reference windows of seed 003's cases: one of each, and each
    // the same as moving the window there
    let refs = s
        .steps
        .iter()
        .find(|st| st.title == "The three cases on the image")
        .and_then(|st| st.values.get("references"))
        .expect("reference windows");
    let Value::List(refs) = refs else {
        panic!("references is not a list: {refs:?}")
    };
    let cases: Vec<&Value> = refs
        .iter()
        .map(|r| match r {
            Value::Object(o) => o.get("case").unwrap(),
            other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(
        cases,
        [
            &Value::from("flat"),
            &Value::from("edge"),
            &Value::from("corner")
        ]
    );
    for r in refs {
        let Value::Object(o) = r else { unreachable!() };
        let (c, rr) = (o.number("c").unwrap(), o.number("r").unwrap());
        let moved = at_pos(c, rr);
        assert_eq!(o.get("case"), moved.result.get("case"));
        assert_eq!(o.get("sigma_min_px"), moved.result.get("sigma_min_px"));
        assert_eq!(o.get("sigma_max_px"), moved.result.get("sigma_max_px"));
    }
    // the noise-free pattern: the flat window is exactly flat
    let clean = solve(
        "forstner-image",
        &Record::new()
            .with("c", 35.0)
            .with("r", 12.0)
            .with("noise", 0.0),
    )
    .unwrap();
    assert_eq!(num(&clean, "det_n"), 0.0);
    assert_eq!(clean.result.get("q"), Some(&Value::Null));
    // seed 003 alone (q_min = 0) also accepts some noisy edge windows
    let alone = solve("forstner-image", &Record::new().with("q_min", 0.0)).unwrap();
    assert!(matrix(alone.result.get("points").unwrap()).len() > points.len());
    assert!(num(&alone, "candidates") > num(&s, "candidates"));
    let listed = matrix(s.steps[s.steps.len() - 2].values.get("candidates").unwrap());
    assert_eq!(listed.len() as f64, num(&s, "candidates"));
    // a 7×7 window works too, and the window follows the input
    let seven = solve(
        "forstner-image",
        &Record::new()
            .with("window_size", 7.0)
            .with("c", 4.0)
            .with("r", 61.0),
    )
    .unwrap();
    assert_eq!(matrix(seven.result.get("window").unwrap()).len(), 7);
}

// ---------------------------------------------------------------- bad input

#[test]
fn bad_windows_are_named_errors() {
    for id in ["forstner-window", "moravec-window"] {
        let with = |w: Value| Record::new().with("window", w);
        let e = err(id, with(Value::matrix(&[vec![1.0, 2.0], vec![3.0, 4.0]])));
        assert_eq!(
            e,
            "window: is 2×2; the window needs at least 3×3 so that an interior pixel has a neighbour on every side"
        );
        let e = err(id, with(Value::matrix(&vec![vec![1.0; 9]; 2])));
        assert!(e.starts_with("window: is 2×9"), "{e}");
        let e = err(
            id,
            with(Value::matrix(&[
                vec![1.0, 2.0, 3.0],
                vec![1.0, 2.0],
                vec![1.0, 2.0, 3.0],
            ])),
        );
        assert_eq!(
            e,
            "window: rows must all have the same length: row 1 has 3 numbers, row 2 has 2"
        );
        let mut rows = vec![vec![1.0; 5]; 5];
        rows[2][3] = f64::NAN;
        let e = err(id, with(Value::matrix(&rows)));
        assert_eq!(e, "window[3][4]: is NaN; give a number");
        rows[2][3] = f64::INFINITY;
        assert!(err(id, with(Value::matrix(&rows))).contains("infinite"));
        let e = err(id, with(Value::matrix(&vec![vec![1.0; 33]; 33])));
        assert_eq!(e, "window: is 33×33; at most 32×32 is allowed");
        let e = err(id, with(Value::from("10 13 3")));
        assert!(e.starts_with("window: must be a list of rows"), "{e}");
        let e = err(id, with(Value::List(vec![])));
        assert!(e.starts_with("window: is empty"), "{e}");
        let e = err(id, Record::new().with("sigma", 1.0));
        assert!(e.starts_with("sigma: unknown field"), "{e}");
        // and texts, as the page sends them
        let p = parse_inputs(id, &Record::new().with("window", "1 2 3; 4 5")).unwrap();
        assert!(p.errors.get("window").is_some());
    }
    let e = err("forstner-window", Record::new().with("sigma_n", 0.0));
    assert_eq!(e, "sigma_n: must be greater than 0 grey values (got 0)");
    let e = err("forstner-window", Record::new().with("threshold_px", -1.0));
    assert!(e.starts_with("threshold_px: must be greater than 0"), "{e}");
    let e = err("forstner-window", Record::new().with("sigma_n", f64::NAN));
    assert_eq!(e, "sigma_n: is NaN; give a number");
}

#[test]
fn bad_image_mode_inputs_are_named_errors() {
    let e = err("forstner-image", Record::new().with("window_size", 6.0));
    assert_eq!(
        e,
        "window_size: must be odd so that the window has a centre pixel (got 6)"
    );
    let e = err("forstner-image", Record::new().with("window_size", 11.0));
    assert!(e.starts_with("window_size: must be at most 9"), "{e}");
    let e = err("forstner-image", Record::new().with("c", 2.0));
    assert_eq!(
        e,
        "c: must be between 3 and 62 so that the 5×5 window lies inside the 64×64 image (got 2)"
    );
    let e = err(
        "forstner-image",
        Record::new().with("r", 62.0).with("window_size", 7.0),
    );
    assert!(e.starts_with("r: must be between 4 and 61"), "{e}");
    let e = err("forstner-image", Record::new().with("c", 9.5));
    assert_eq!(e, "c: must be a whole number (got 9.5)");
    let e = err("forstner-image", Record::new().with("q_min", 1.5));
    assert!(e.starts_with("q_min: must be at most 1"), "{e}");
    let e = err("forstner-image", Record::new().with("noise", -1.0));
    assert!(e.starts_with("noise: must be at least 0"), "{e}");
    // the core's own checks
    let tiny = Grid::from_rows("image", &vec![vec![1.0; 4]; 4]).unwrap();
    let e = forstner_map(&tiny, 5).unwrap_err().to_string();
    assert_eq!(e, "image: is 4×4, smaller than the 5×5 window");
    let e = moravec_map(&tiny, 2).unwrap_err().to_string();
    assert_eq!(e, "window_size: must be between 3 and 32 (got 2)");
}

// ---------------------------------------------------------------- issue 30

mod parts_common;

fn keyed<'a>(s: &'a Solution, key: &str) -> &'a Relation {
    s.steps
        .iter()
        .flat_map(|st| st.parts.iter())
        .find(|r| r.key.as_deref() == Some(key))
        .unwrap_or_else(|| panic!("{}: no relation keyed {key}", s.id))
}

/// Issue 30, item 2: every step is data (its LaTeX made from its parts) and
/// every practice box's hints come from the relation keyed with its value.
#[test]
fn steps_are_data_and_hints_are_keyed() {
    let with_numbers = parts_common::steps_are_data_and_hints_are_keyed(
        &photogrammetry_playground::examples::interest::TOPIC,
        4,
    );
    // det N, w, q and the weak axis of forstner-window, w, q and the weak
    // axis of forstner-image, the mean of moravec-window: in every variant
    assert!(with_numbers >= 4 * (4 + 3 + 1), "{with_numbers}");
    let s = solve("forstner-window", &Record::new()).unwrap();
    // N and N⁻¹ are grids the page can lay out, with their numbers
    let n = keyed(&s, "n");
    let Piece::Grid { grid } = &n.result[0].0[0] else {
        panic!("N is not a grid: {n:?}")
    };
    assert_eq!(grid.rows, [["82", "-22.25"], ["-22.25", "114.75"]]);
    let inv = keyed(&s, "n_inverse");
    assert!(inv.result[0]
        .0
        .iter()
        .any(|p| matches!(p, Piece::Grid { .. })));
    assert_eq!(
        keyed(&s, "det_n").question_latex(),
        r"\det N = 82 \times 114.75 - (-22.25)^2 = \;?"
    );
    assert_eq!(
        keyed(&s, "w").question_latex(),
        r"w = \frac{8914.438}{196.75} = \;?"
    );
    // Moravec: each interior pixel's sum is its own relation, a sum of terms
    let s = solve("moravec-window", &Record::new()).unwrap();
    let r = keyed(&s, "sums[1,2]");
    assert_eq!(r.substituted[0].0.len(), 4);
    assert_eq!(
        r.substituted_latex(),
        r"S(c_{3}, r_{2}) = (11 - 27)^2 + (15 - 5)^2 + (13 - 15)^2 + (14 - 13)^2 = 361"
    );
    assert_eq!(
        keyed(&s, "mean").question_latex(),
        r"\bar S = \frac{732}{4} = \;?"
    );
}
