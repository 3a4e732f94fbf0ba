//! Seed 000, Examples 17–18, the exercise and figure c, reproduced natively:
//! chain codes, differential codes, lengths, boundary tracing and
//! descriptors, with their properties and every class of bad input.
#![cfg(not(target_arch = "wasm32"))]

use photogrammetry_playground::chain::{self, Connectivity, Pixel};
use photogrammetry_playground::examples::{parse_inputs, solve};
use photogrammetry_playground::raster::Grid;
use photogrammetry_playground::solution::{NoteKind, Record, Relation, Solution, Value};
use std::collections::HashSet;

const EX17: [f64; 16] = [
    1., 8., 8., 8., 7., 1., 1., 2., 3., 4., 4., 2., 1., 1., 2., 2.,
];
const EX17_DIFFERENTIAL: [f64; 15] = [7., 0., 0., 7., 2., 0., 1., 1., 1., 0., 6., 7., 0., 1., 0.];
const EX17_DIFFERENCES: [f64; 15] = [
    7., 0., 0., -1., -6., 0., 1., 1., 1., 0., -2., -1., 0., 1., 0.,
];
const EXERCISE: [f64; 16] = [
    6., 6., 5., 5., 6., 8., 8., 7., 6., 5., 5., 3., 4., 4., 4., 5.,
];
const EXERCISE_DIFFERENTIAL: [f64; 15] =
    [0., 7., 0., 1., 2., 0., 7., 7., 7., 0., 6., 1., 0., 0., 1.];

// ------------------------------------------------------------ helpers

/// A tiny deterministic PRNG (xorshift64*), so property tests are repeatable.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
}

fn numbers(v: Option<&Value>) -> Vec<f64> {
    match v {
        Some(Value::List(xs)) => xs.iter().map(|x| x.as_f64().expect("a number")).collect(),
        other => panic!("not a list of numbers: {other:?}"),
    }
}

fn rows(v: Option<&Value>) -> Vec<Vec<f64>> {
    match v {
        Some(Value::List(xs)) => xs.iter().map(|r| numbers(Some(r))).collect(),
        other => panic!("not a list of rows: {other:?}"),
    }
}

fn result_numbers(s: &Solution, key: &str) -> Vec<f64> {
    numbers(s.result.get(key))
}

fn printed_numbers(s: &Solution, key: &str) -> Vec<f64> {
    numbers(s.textbook.as_ref().expect("textbook values").get(key))
}

fn num(s: &Solution, key: &str) -> f64 {
    s.result
        .number(key)
        .unwrap_or_else(|| panic!("result {key} missing in {}", s.id))
}

fn has_note(s: &Solution, kind: NoteKind, needle: &str) -> bool {
    s.notes
        .iter()
        .any(|n| n.kind == kind && n.text.contains(needle))
}

fn px(list: &[Pixel]) -> Value {
    Value::List(
        list.iter()
            .map(|p| Value::numbers(&[p[0] as f64, p[1] as f64]))
            .collect(),
    )
}

fn err(id: &str, inputs: Record) -> String {
    solve(id, &inputs)
        .expect_err("should be an error")
        .to_string()
}

fn digits(code: &[f64]) -> Vec<u8> {
    code.iter().map(|&d| d as u8).collect()
}

/// A random simple-ish walk of `n` steps (the code is valid, pixels may
/// repeat: that does not matter for encode/decode).
fn random_code(rng: &mut Rng, n: usize, conn: Connectivity) -> Vec<u8> {
    (0..n)
        .map(|_| rng.below(u64::from(conn.directions())) as u8 + 1)
        .collect()
}

/// A random binary image of blobs.
fn random_image(rng: &mut Rng, w: usize, h: usize) -> Grid {
    let mut g = Grid::filled(w, h, 0.0);
    for _ in 0..(w * h / 6) {
        let (c, r) = (rng.below(w as u64) as usize, rng.below(h as u64) as usize);
        let (bw, bh) = (1 + rng.below(3) as usize, 1 + rng.below(3) as usize);
        for j in r..(r + bh).min(h) {
            for i in c..(c + bw).min(w) {
                g.set(i, j, 1.0);
            }
        }
    }
    g
}

fn set(g: &Grid, p: Pixel) -> bool {
    p[0] >= 0
        && p[1] >= 0
        && g.get(p[0] as usize, p[1] as usize)
            .is_some_and(|v| v != 0.0)
}

// ------------------------------------------------------------ the seed

#[test]
fn example_17_code_and_differential_code_as_printed() {
    let s = solve("chain-code", &Record::new()).unwrap();
    assert_eq!(result_numbers(&s, "code"), EX17);
    assert_eq!(result_numbers(&s, "differences"), EX17_DIFFERENCES);
    assert_eq!(result_numbers(&s, "differential"), EX17_DIFFERENTIAL);
    assert_eq!(s.result.get("closed"), Some(&Value::Bool(false)));
    // the rebuilt edge: 17 pixels from (1, 4) that the code walks
    let pixels = rows(s.result.get("pixels"));
    assert_eq!(pixels.len(), 17);
    assert_eq!(pixels[0], [1.0, 4.0]);
    assert_eq!(pixels[16], [11.0, 1.0]);
    // printed values beside ours: identical
    assert_eq!(printed_numbers(&s, "code"), EX17);
    assert_eq!(printed_numbers(&s, "differences"), EX17_DIFFERENCES);
    assert_eq!(printed_numbers(&s, "differential"), EX17_DIFFERENTIAL);
    assert!(has_note(
        &s,
        NoteKind::Convention,
        "rebuilt from the printed code"
    ));
    assert!(has_note(&s, NoteKind::Convention, "n − 1 elements"));
    let keys: Vec<_> = s.result.keys().collect();
    assert_eq!(&keys[..3], ["code", "differential", "pixels"]);
    for step in &s.steps {
        assert!(
            !step.formula.is_empty() && !step.substituted.is_empty(),
            "{}",
            step.title
        );
    }
    let code_step = s.steps.iter().find(|t| t.title == "Chain code").unwrap();
    assert!(code_step.substituted.contains(r"1 \;8 \;8 \;8 \;7 \;1"));
    let d = s.steps.iter().find(|t| t.title == "Differences").unwrap();
    assert!(
        d.substituted.contains(r"7 \;0 \;0 \;(-1) \;(-6)"),
        "{}",
        d.substituted
    );
    // the same from the printed code itself, typed as one run of digits
    let s2 = solve(
        "chain-code",
        &Record::new()
            .with("given", "code")
            .with("code", Value::numbers(&[1888711234421122.0])),
    )
    .unwrap();
    assert_eq!(result_numbers(&s2, "code"), EX17);
    assert_eq!(s2.result.get("pixels"), s.result.get("pixels"));
    assert!(s2.textbook.is_some());
}

#[test]
fn exercise_codes_the_same_edge_from_its_right_end() {
    let s = solve("chain-code", &Record::new().with("from", "end")).unwrap();
    assert_eq!(result_numbers(&s, "code"), EXERCISE);
    assert_eq!(result_numbers(&s, "differential"), EXERCISE_DIFFERENTIAL);
    assert_eq!(rows(s.result.get("pixels"))[0], [11.0, 1.0]);
    // the seed prints no answer to the exercise
    assert!(s.textbook.is_none());
    assert!(has_note(
        &s,
        NoteKind::Convention,
        "exercise after Example 17"
    ));
    let rev = s
        .steps
        .iter()
        .find(|t| t.title == "Coding from the other end")
        .expect("a step relating the two codes");
    assert_eq!(numbers(rev.values.get("forward")), EX17);
    // relation: reversed forward code turned by 4; differential reversed and negated
    let fwd = digits(&EX17);
    assert_eq!(chain::reverse(&fwd, Connectivity::Eight), digits(&EXERCISE));
    let back: Vec<f64> = EX17_DIFFERENTIAL
        .iter()
        .rev()
        .map(|d| (8.0 - d) % 8.0)
        .collect();
    assert_eq!(back, EXERCISE_DIFFERENTIAL);
}

#[test]
fn example_18_b_length_with_diagonals() {
    let s = solve("boundary-length", &Record::new()).unwrap();
    let exact = 8.0 + 9.0 * 2f64.sqrt();
    assert!((num(&s, "length") - exact).abs() < 1e-12);
    assert_eq!(num(&s, "horizontal"), 4.0);
    assert_eq!(num(&s, "vertical"), 4.0);
    assert_eq!(num(&s, "diagonal"), 9.0);
    let t = s.textbook.as_ref().unwrap();
    assert_eq!(t.number("length"), Some(20.7));
    assert_eq!(t.number("diagonal"), Some(9.0));
    assert!(has_note(&s, NoteKind::Rounding, "20.72792"));
    assert!(has_note(&s, NoteKind::Convention, "Example 18 (b)"));
    let keys: Vec<_> = s.result.keys().collect();
    assert_eq!(&keys[..4], ["length", "horizontal", "vertical", "diagonal"]);
    let last = s.steps.iter().find(|t| t.title == "Length").unwrap();
    assert!(last
        .substituted
        .contains(r"L = 4 + 4 + \sqrt{2} \times 9 = 20.72792"));
}

#[test]
fn example_18_a_length_of_a_4_connected_edge() {
    let code = [
        1., 1., 4., 4., 1., 1., 1., 2., 2., 1., 1., 1., 4., 4., 4., 1., 1., 2., 2., 2., 1., 1., 4.,
    ];
    let by_code = Record::new()
        .with("given", "code")
        .with("connectivity", "4")
        .with("code", Value::numbers(&code))
        .with("start", Value::numbers(&[1.0, 1.0]));
    let s = solve("boundary-length", &by_code).unwrap();
    assert_eq!(num(&s, "length"), 23.0);
    assert_eq!(num(&s, "pixel_count"), 24.0);
    assert_eq!(num(&s, "diagonal"), 0.0);
    let t = s.textbook.as_ref().unwrap();
    assert_eq!(t.number("length"), Some(23.0));
    assert_eq!(t.number("pixel_count"), Some(24.0));
    let step = s.steps.iter().find(|t| t.title == "Length").unwrap();
    assert!(step.substituted.contains("L = 24 - 1 = 23"));
    // the same edge given by its pixels is recognised too
    let pixels = s.result.get("pixels").unwrap().clone();
    let s2 = solve(
        "boundary-length",
        &Record::new()
            .with("connectivity", "4")
            .with("pixels", pixels),
    )
    .unwrap();
    assert_eq!(num(&s2, "length"), 23.0);
    assert!(has_note(&s2, NoteKind::Convention, "Example 18 (a)"));
}

#[test]
fn figure_c_4_connectivity_code_decoded_and_re_encoded() {
    let printed = [4., 4., 1., 1., 2., 1., 1., 4., 1., 1., 2., 2., 2., 3., 3.];
    let s = solve(
        "chain-code",
        &Record::new()
            .with("given", "code")
            .with("connectivity", "4")
            .with("code", Value::numbers(&[441121141122233.0])),
    )
    .unwrap();
    assert_eq!(result_numbers(&s, "code"), printed);
    assert_eq!(printed_numbers(&s, "code"), printed);
    assert!(has_note(&s, NoteKind::Convention, "figure c"));
    assert!(has_note(&s, NoteKind::Convention, "2 = north"));
    let pixels = s.result.get("pixels").unwrap().clone();
    assert_eq!(rows(Some(&pixels)).len(), 16);
    // re-encode the decoded pixels
    let again = solve(
        "chain-code",
        &Record::new()
            .with("connectivity", "4")
            .with("pixels", pixels),
    )
    .unwrap();
    assert_eq!(result_numbers(&again, "code"), printed);
    // 4-connectivity differential: mod 4
    assert_eq!(
        result_numbers(&s, "differential"),
        [0., 1., 0., 1., 3., 0., 3., 1., 0., 1., 0., 0., 1., 0.]
    );
}

#[test]
fn boundary_shape_of_the_default_region() {
    let s = solve("boundary-shape", &Record::new()).unwrap();
    assert!((num(&s, "diameter") - 136f64.sqrt()).abs() < 1e-12);
    assert_eq!(rows(s.result.get("major_axis")), [[12.0, 1.0], [2.0, 7.0]]);
    assert!((num(&s, "minor_axis_length") - 64.0 / 136f64.sqrt()).abs() < 1e-12);
    assert!((num(&s, "eccentricity") - 2.125).abs() < 1e-12);
    let rect = rows(s.result.get("basic_rectangle"));
    assert_eq!(rect.len(), 4);
    // the rectangle is D long and m wide
    let side = |a: &Vec<f64>, b: &Vec<f64>| ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt();
    assert!((side(&rect[0], &rect[1]) - 136f64.sqrt()).abs() < 1e-9);
    assert!((side(&rect[1], &rect[2]) - 64.0 / 136f64.sqrt()).abs() < 1e-9);
    assert_eq!(num(&s, "regions"), 1.0);
    assert!(has_note(&s, NoteKind::Convention, "pixel centres"));
    let keys: Vec<_> = s.result.keys().collect();
    assert_eq!(
        &keys[..5],
        [
            "diameter",
            "major_axis",
            "minor_axis_length",
            "basic_rectangle",
            "eccentricity"
        ]
    );
}

#[test]
fn shape_of_a_square_and_a_bar() {
    let square = [
        [0, 0],
        [1, 0],
        [2, 0],
        [2, 1],
        [2, 2],
        [1, 2],
        [0, 2],
        [0, 1],
    ];
    let sh = chain::shape("pixels", &square).unwrap();
    assert!((sh.diameter - 8f64.sqrt()).abs() < 1e-12);
    assert_eq!(sh.major_axis, [[0, 0], [2, 2]]);
    assert!((sh.minor_axis_length - 8f64.sqrt()).abs() < 1e-12);
    assert!((sh.eccentricity.unwrap() - 1.0).abs() < 1e-12);
    // a straight bar: no minor axis, no eccentricity (null with a note)
    let s = solve(
        "boundary-shape",
        &Record::new().with("pixels", px(&[[0, 0], [1, 0], [2, 0], [3, 0], [4, 0]])),
    )
    .unwrap();
    assert_eq!(num(&s, "diameter"), 4.0);
    assert_eq!(num(&s, "minor_axis_length"), 0.0);
    assert_eq!(s.result.get("eccentricity"), Some(&Value::Null));
    assert!(has_note(&s, NoteKind::Warning, "one straight line"));
    // filled and hollow square: same descriptors
    let filled: Vec<Pixel> = (0..5).flat_map(|r| (0..5).map(move |c| [c, r])).collect();
    let hollow: Vec<Pixel> = filled
        .iter()
        .copied()
        .filter(|p| p[0] % 4 == 0 || p[1] % 4 == 0)
        .collect();
    let a = solve("boundary-shape", &Record::new().with("pixels", px(&filled))).unwrap();
    let b = solve("boundary-shape", &Record::new().with("pixels", px(&hollow))).unwrap();
    for k in ["diameter", "minor_axis_length", "eccentricity"] {
        assert_eq!(a.result.get(k), b.result.get(k), "{k}");
    }
}

// ------------------------------------------------------------ properties

#[test]
fn encode_then_decode_returns_the_pixels_and_back() {
    let mut rng = Rng(0x5eed_c0de);
    for conn in [Connectivity::Eight, Connectivity::Four] {
        for n in [0usize, 1, 2, 7, 40, 300] {
            let code = random_code(&mut rng, n, conn);
            let start = [rng.below(50) as i64 - 25, rng.below(50) as i64 - 25];
            let pixels = chain::decode(start, &code, conn).unwrap();
            assert_eq!(pixels.len(), n + 1);
            assert_eq!(chain::encode(&pixels, conn).unwrap(), code);
            let again = chain::decode(start, &chain::encode(&pixels, conn).unwrap(), conn).unwrap();
            assert_eq!(again, pixels);
            // reversing twice is the identity; the reversed code walks back
            let rev = chain::reverse(&code, conn);
            assert_eq!(chain::reverse(&rev, conn), code);
            let end = *pixels.last().unwrap();
            let back = chain::decode(end, &rev, conn).unwrap();
            let mut fwd = back.clone();
            fwd.reverse();
            assert_eq!(fwd, pixels);
        }
    }
}

#[test]
fn rotating_by_90_degrees_adds_2_and_keeps_the_differential_code() {
    let mut rng = Rng(42);
    for conn in [Connectivity::Eight, Connectivity::Four] {
        let quarter = i64::from(conn.directions() / 4);
        for _ in 0..50 {
            let n = 1 + rng.below(60) as usize;
            let code = random_code(&mut rng, n, conn);
            let pixels = chain::decode([3, 5], &code, conn).unwrap();
            // counter-clockwise on the screen with r downward: (c, r) -> (r, -c)
            let turned: Vec<Pixel> = pixels.iter().map(|p| [p[1], -p[0]]).collect();
            let code2 = chain::encode(&turned, conn).unwrap();
            let expected: Vec<u8> = code.iter().map(|&d| conn.turn(d, quarter)).collect();
            assert_eq!(code2, expected);
            for closed in [false, true] {
                assert_eq!(
                    chain::differential(&code, conn, closed).code,
                    chain::differential(&code2, conn, closed).code
                );
            }
        }
    }
    // a traced region turned by 90°: the closed code is turned by 2 and its
    // sequence rotated (tracing starts at another pixel)
    let img = random_image(&mut rng, 12, 9);
    let region: Vec<Pixel> = (0..9)
        .flat_map(|r| (0..12).map(move |c| [c, r]))
        .filter(|&p| set(&img, p))
        .collect();
    let b1 = chain::trace_pixels("p", &region, Connectivity::Eight, 64).unwrap();
    let turned: Vec<Pixel> = region.iter().map(|p| [p[1], -p[0]]).collect();
    let b2 = chain::trace_pixels("p", &turned, Connectivity::Eight, 64).unwrap();
    let mut codes1: Vec<Vec<u8>> = b1
        .iter()
        .map(|b| {
            b.code
                .iter()
                .map(|&d| Connectivity::Eight.turn(d, 2))
                .collect()
        })
        .collect();
    let mut codes2: Vec<Vec<u8>> = b2.iter().map(|b| canonical(&b.code)).collect();
    codes1 = codes1.iter().map(|c| canonical(c)).collect();
    codes1.sort();
    codes2.sort();
    assert_eq!(codes1, codes2);
}

/// The smallest rotation of a cyclic sequence.
fn canonical(code: &[u8]) -> Vec<u8> {
    (0..code.len().max(1))
        .map(|k| {
            let mut c = code.to_vec();
            c.rotate_left(k.min(code.len()));
            c
        })
        .min()
        .unwrap_or_default()
}

#[test]
fn tracing_a_rectangle_gives_its_code_and_perimeter() {
    for w in 1..=7usize {
        for h in 1..=6usize {
            let g = Grid::from_fn(w + 4, h + 3, |c, r| {
                if (2..2 + w).contains(&c) && (1..1 + h).contains(&r) {
                    1.0
                } else {
                    0.0
                }
            });
            for (conn, [e, s, wst, n]) in [
                (Connectivity::Eight, [1u8, 7, 5, 3]),
                (Connectivity::Four, [1u8, 4, 3, 2]),
            ] {
                let b = chain::trace(&g, conn);
                assert_eq!(b.len(), 1);
                let mut expected = vec![e; w - 1];
                expected.extend(vec![s; h - 1]);
                expected.extend(vec![wst; w - 1]);
                expected.extend(vec![n; h - 1]);
                assert_eq!(b[0].code, expected, "{w}×{h} {conn:?}");
                assert_eq!(b[0].pixels[0], [2, 1]);
                assert_eq!(b[0].area, w * h);
                let l = chain::length(&b[0].code, conn);
                assert_eq!(l.length, (2 * (w - 1) + 2 * (h - 1)) as f64);
            }
            // the same through the solver
            let pixels: Vec<Pixel> = (0..h as i64)
                .flat_map(|r| (0..w as i64).map(move |c| [c, r]))
                .collect();
            let s = solve(
                "boundary-length",
                &Record::new()
                    .with("given", "region")
                    .with("pixels", px(&pixels)),
            )
            .unwrap();
            assert_eq!(num(&s, "length"), (2 * (w - 1) + 2 * (h - 1)) as f64);
            assert_eq!(s.result.get("closed"), Some(&Value::Bool(w * h > 1)));
        }
    }
}

#[test]
fn differential_code_of_a_closed_boundary_does_not_depend_on_the_start() {
    let mut rng = Rng(7);
    for conn in [Connectivity::Eight, Connectivity::Four] {
        for _ in 0..20 {
            let img = random_image(&mut rng, 14, 10);
            for b in chain::trace(&img, conn) {
                let n = b.pixels.len();
                if b.code.is_empty() {
                    continue;
                }
                let base = chain::differential(&b.code, conn, true).code;
                assert_eq!(base.len(), n);
                for k in [1, n / 2, n - 1] {
                    let mut ps = b.pixels.clone();
                    ps.rotate_left(k);
                    ps.push(ps[0]);
                    let path = chain::analyse(&ps, conn);
                    assert!(path.closed);
                    let code = path.code.expect("a connected boundary");
                    let mut expected_code = b.code.clone();
                    expected_code.rotate_left(k);
                    assert_eq!(code, expected_code);
                    let mut expected = base.clone();
                    expected.rotate_left(k);
                    assert_eq!(chain::differential(&code, conn, true).code, expected);
                }
            }
        }
    }
}

/// The background reachable from outside the image (the exterior).
fn exterior(g: &Grid, conn: Connectivity) -> HashSet<Pixel> {
    let (w, h) = (g.width() as i64, g.height() as i64);
    let mut seen = HashSet::new();
    let mut stack = vec![[-1i64, -1i64]];
    seen.insert([-1, -1]);
    while let Some(p) = stack.pop() {
        for d in 1..=conn.directions() {
            let (dc, dr) = conn.step(d).unwrap();
            let q = [p[0] + dc, p[1] + dr];
            if q[0] < -1 || q[1] < -1 || q[0] > w || q[1] > h || set(g, q) || seen.contains(&q) {
                continue;
            }
            seen.insert(q);
            stack.push(q);
        }
    }
    seen
}

#[test]
fn traced_boundaries_are_closed_paths_around_each_region() {
    let mut rng = Rng(2024);
    for round in 0..40 {
        let (w, h) = (5 + rng.below(12) as usize, 4 + rng.below(9) as usize);
        let img = random_image(&mut rng, w, h);
        for conn in [Connectivity::Eight, Connectivity::Four] {
            // background is connected the other way round
            let bg = match conn {
                Connectivity::Eight => Connectivity::Four,
                Connectivity::Four => Connectivity::Eight,
            };
            let outside = exterior(&img, bg);
            let boundaries = chain::trace(&img, conn);
            let mut on_some: HashSet<Pixel> = HashSet::new();
            let mut total_area = 0;
            let mut last_start: Option<Pixel> = None;
            for b in &boundaries {
                total_area += b.area;
                // regions in raster order of their first pixel
                let s = b.pixels[0];
                if let Some(l) = last_start {
                    assert!((s[1], s[0]) > (l[1], l[0]), "round {round}");
                }
                last_start = Some(s);
                // a closed path of neighbours over region pixels
                let mut ps = b.pixels.clone();
                if !b.code.is_empty() {
                    ps.push(ps[0]);
                }
                assert_eq!(chain::encode(&ps, conn).unwrap(), b.code, "round {round}");
                for p in &b.pixels {
                    assert!(set(&img, *p));
                    on_some.insert(*p);
                    // every traced pixel touches the exterior
                    let touches = (1..=8).any(|d| {
                        let (dc, dr) = Connectivity::Eight.step(d).unwrap();
                        outside.contains(&[p[0] + dc, p[1] + dr])
                    });
                    assert!(touches, "round {round}: {p:?} is not on an outer boundary");
                }
            }
            let count = img.data().iter().filter(|&&v| v != 0.0).count();
            assert_eq!(total_area, count);
            // every region pixel next to the exterior (across a side for
            // 8-connected regions, any neighbour for 4-connected) is traced
            for r in 0..h as i64 {
                for c in 0..w as i64 {
                    let p = [c, r];
                    if !set(&img, p) {
                        continue;
                    }
                    let next = (1..=bg.directions()).any(|d| {
                        let (dc, dr) = bg.step(d).unwrap();
                        outside.contains(&[c + dc, r + dr])
                    });
                    if next {
                        assert!(on_some.contains(&p), "round {round} {conn:?}: {p:?} missed");
                    }
                }
            }
        }
    }
}

// ------------------------------------------------------------ odd input

#[test]
fn a_disconnected_path_is_pointed_out_where_it_breaks() {
    let s = solve(
        "chain-code",
        &Record::new().with("pixels", px(&[[0, 0], [1, 0], [3, 0], [4, 1]])),
    )
    .unwrap();
    assert_eq!(s.result.get("code"), Some(&Value::Null));
    assert_eq!(s.result.get("differential"), Some(&Value::Null));
    assert_eq!(rows(s.result.get("breaks")), [[2.0, 1.0, 0.0, 3.0, 0.0]]);
    assert!(has_note(
        &s,
        NoteKind::Warning,
        "pixel 2 (1, 0) and pixel 3 (3, 0) are not neighbours"
    ));
    assert!(s.steps.iter().any(|t| t.title == "The path breaks"));
    // a diagonal step is a break with 4-connectivity
    let s = solve(
        "boundary-length",
        &Record::new()
            .with("connectivity", "4")
            .with("pixels", px(&[[0, 0], [1, 1]])),
    )
    .unwrap();
    assert_eq!(s.result.get("length"), Some(&Value::Null));
    assert!(has_note(&s, NoteKind::Warning, "diagonal neighbours"));
    // the same pixel twice in a row
    let s = solve(
        "chain-code",
        &Record::new().with("pixels", px(&[[0, 0], [0, 0]])),
    )
    .unwrap();
    assert!(has_note(&s, NoteKind::Warning, "are the same pixel"));
}

#[test]
fn a_branching_path_is_pointed_out_where_it_branches() {
    // out along a row, back one pixel, then down: pixel (1, 0) twice
    let s = solve(
        "chain-code",
        &Record::new().with("pixels", px(&[[0, 0], [1, 0], [2, 0], [1, 0], [1, 1]])),
    )
    .unwrap();
    assert_eq!(result_numbers(&s, "code"), [1.0, 1.0, 5.0, 7.0]);
    assert_eq!(rows(s.result.get("branches")), [[4.0, 2.0, 1.0, 0.0]]);
    assert!(has_note(
        &s,
        NoteKind::Warning,
        "pixel 4 (1, 0) is pixel 2 again"
    ));
}

#[test]
fn closed_boundaries_single_pixels_and_near_misses() {
    // a closed boundary: the first pixel repeated
    let sq = [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]];
    let s = solve("chain-code", &Record::new().with("pixels", px(&sq))).unwrap();
    assert_eq!(s.result.get("closed"), Some(&Value::Bool(true)));
    assert_eq!(result_numbers(&s, "code"), [1.0, 7.0, 5.0, 3.0]);
    // first element from the last and the first digit: 1 - 3 = -2 -> 6
    assert_eq!(result_numbers(&s, "differences"), [-2.0, 6.0, -2.0, -2.0]);
    assert_eq!(result_numbers(&s, "differential"), [6.0, 6.0, 6.0, 6.0]);
    let l = solve("boundary-length", &Record::new().with("pixels", px(&sq))).unwrap();
    assert_eq!(num(&l, "length"), 4.0);
    // a closed shape also gets its descriptors, from the same core function
    assert!((num(&s, "diameter") - 2f64.sqrt()).abs() < 1e-15);
    assert!((num(&s, "eccentricity") - 1.0).abs() < 1e-12);
    assert_eq!(num(&s, "length"), 4.0);
    assert!((num(&l, "minor_axis_length") - 2f64.sqrt()).abs() < 1e-12);
    assert_eq!(result_numbers(&l, "differential"), [6.0, 6.0, 6.0, 6.0]);
    assert!(s.labels.get("eccentricity").is_some());
    // an open edge has none
    let open = solve("chain-code", &Record::new()).unwrap();
    assert!(open.result.get("diameter").is_none());
    // not closed, but could be: a hint
    let s = solve("chain-code", &Record::new().with("pixels", px(&sq[..4]))).unwrap();
    assert_eq!(s.result.get("closed"), Some(&Value::Bool(false)));
    assert!(has_note(&s, NoteKind::Warning, "repeat the first pixel"));
    // a single pixel: empty code, length 0, documented with a note
    let one = Record::new().with("pixels", px(&[[5, 5]]));
    let s = solve("chain-code", &one).unwrap();
    assert!(result_numbers(&s, "code").is_empty());
    assert!(result_numbers(&s, "differential").is_empty());
    assert!(has_note(&s, NoteKind::Warning, "A single pixel"));
    let l = solve("boundary-length", &one).unwrap();
    assert_eq!(num(&l, "length"), 0.0);
    let sh = solve("boundary-shape", &one).unwrap();
    assert_eq!(num(&sh, "diameter"), 0.0);
    assert_eq!(sh.result.get("eccentricity"), Some(&Value::Null));
    // a single-pixel region traced
    let s = solve("chain-code", &one.clone().with("given", "region")).unwrap();
    assert!(result_numbers(&s, "code").is_empty());
}

#[test]
fn several_regions_are_traced_in_order_and_the_first_is_used() {
    let pixels = [[5, 0], [6, 0], [0, 3], [1, 3], [0, 4], [9, 9]];
    let s = solve(
        "chain-code",
        &Record::new()
            .with("given", "region")
            .with("pixels", px(&pixels)),
    )
    .unwrap();
    assert_eq!(num(&s, "regions"), 3.0);
    assert_eq!(result_numbers(&s, "code"), [1.0, 5.0]);
    assert!(has_note(&s, NoteKind::Warning, "3 separate regions"));
    let traced = s.steps[0].values.get("boundaries").unwrap();
    match traced {
        Value::List(bs) => assert_eq!(bs.len(), 3),
        _ => panic!("boundaries"),
    }
    let sh = solve("boundary-shape", &Record::new().with("pixels", px(&pixels))).unwrap();
    assert_eq!(num(&sh, "regions"), 3.0);
    assert_eq!(num(&sh, "diameter"), 1.0);
}

#[test]
fn bad_inputs_name_the_field() {
    let e = err(
        "chain-code",
        Record::new().with("pixels", Value::List(vec![])),
    );
    assert!(e.starts_with("pixels: is empty"), "{e}");
    let e = err(
        "chain-code",
        Record::new().with("pixels", Value::matrix(&[vec![0.0, 0.0], vec![1.5, 0.0]])),
    );
    assert_eq!(e, "pixels: point 2 must be whole pixel positions (got 1.5)");
    let e = err(
        "chain-code",
        Record::new().with("pixels", Value::matrix(&[vec![0.0, 0.0, 1.0]])),
    );
    assert!(e.contains("each point needs 2"), "{e}");
    let e = err(
        "chain-code",
        Record::new().with("pixels", Value::matrix(&[vec![1e9, 0.0]])),
    );
    assert!(e.starts_with("pixels: point 1 lies too far out"), "{e}");
    let code = |c: &[f64], conn: &str| {
        err(
            "chain-code",
            Record::new()
                .with("given", "code")
                .with("connectivity", conn)
                .with("code", Value::numbers(c)),
        )
    };
    assert_eq!(
        code(&[1.0, 9.0], "8"),
        "code: digit 2 is 9; with 8-connectivity the directions are 1 to 8"
    );
    assert_eq!(
        code(&[1.0, 5.0], "4"),
        "code: digit 2 is 5; with 4-connectivity the directions are 1 to 4"
    );
    assert_eq!(
        code(&[0.0], "8"),
        "code: entry 1 is 0; a chain code is made of direction digits 1 to 8"
    );
    assert!(code(&[10.0], "8").starts_with("code: digit 2 is 0"));
    assert!(code(&[2.5], "8").contains("entry 1 is 2.5"));
    assert!(code(&[1e17], "8").contains("too many digits"));
    let e = err(
        "chain-code",
        Record::new()
            .with("given", "code")
            .with("start", Value::numbers(&[0.5, 1.0])),
    );
    assert!(e.starts_with("start: the start pixel must be whole"), "{e}");
    let e = err(
        "chain-code",
        Record::new()
            .with("given", "code")
            .with("start", Value::numbers(&[1.0])),
    );
    assert!(e.starts_with("start: needs at least 2"), "{e}");
    let e = err("chain-code", Record::new().with("connectivity", "6"));
    assert!(e.contains("\"6\" is not one of the choices (8, 4)"), "{e}");
    let e = err("chain-code", Record::new().with("from", "middle"));
    assert!(e.starts_with("from:"), "{e}");
    let e = err("boundary-shape", Record::new().with("from", "end"));
    assert!(e.starts_with("from: unknown field"), "{e}");
    let e = err(
        "boundary-shape",
        Record::new().with("pixels", px(&[[0, 0], [5000, 0]])),
    );
    assert!(e.contains("at most 512 × 512 can be traced"), "{e}");
    let e = err(
        "chain-code",
        Record::new()
            .with("given", "code")
            .with("code", Value::Number(f64::NAN)),
    );
    assert!(e.starts_with("code:"), "{e}");
    // with the pixels given, the code and start fields do not apply: ignored
    let s = solve(
        "chain-code",
        &Record::new()
            .with("code", Value::Number(f64::NAN))
            .with("start", Value::numbers(&[1.0])),
    )
    .unwrap();
    assert_eq!(
        s.result.get("code"),
        solve("chain-code", &Record::new())
            .unwrap()
            .result
            .get("code")
    );
}

#[test]
fn text_inputs_parse_as_the_page_sends_them() {
    let texts = Record::new()
        .with("given", "code")
        .with("code", "441121141122233")
        .with("connectivity", "4")
        .with("pixels", "1 4; 2 4\n3 5");
    let p = parse_inputs("chain-code", &texts).unwrap();
    assert!(p.errors.is_empty(), "{:?}", p.errors);
    let s = solve("chain-code", &p.inputs).unwrap();
    assert_eq!(result_numbers(&s, "code").len(), 15);
    let p = parse_inputs("chain-code", &Record::new().with("pixels", "1 4; 2")).unwrap();
    assert!(p.errors.get("pixels").is_some());
}

#[test]
fn connectivity_given_as_a_number_is_the_same_choice() {
    // docs/API.md: a choice whose options are numbers also takes the number
    let code = [4., 4., 1., 1., 2., 1., 1., 4.];
    let base = || {
        Record::new()
            .with("given", "code")
            .with("code", Value::numbers(&code))
    };
    let as_text = solve("boundary-length", &base().with("connectivity", "4")).unwrap();
    let as_number = solve("boundary-length", &base().with("connectivity", 4.0)).unwrap();
    assert_eq!(num(&as_number, "length"), 8.0);
    assert_eq!(num(&as_number, "length"), num(&as_text, "length"));
    assert_eq!(
        as_number.inputs.get("connectivity"),
        Some(&Value::from("4"))
    );
    let eight = solve("boundary-length", &base().with("connectivity", 8.0)).unwrap();
    assert_eq!(eight.inputs.get("connectivity"), Some(&Value::from("8")));
    let e = err("boundary-length", base().with("connectivity", 6.0));
    assert_eq!(e, "connectivity: 6 is not one of the choices (8, 4)");
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
        &photogrammetry_playground::examples::chains::TOPIC,
        4,
    );
    // the length of boundary-length, the diameter, minor axis and
    // eccentricity of boundary-shape: in every variant
    assert!(with_numbers >= 4 * (1 + 3), "{with_numbers}");
    let s = solve("boundary-length", &Record::new()).unwrap();
    assert_eq!(
        keyed(&s, "length").question_latex(),
        r"L = 4 + 4 + \sqrt{2} \times 9 = \;?"
    );
    // a code is a list of pieces the page may break between, one a digit
    let s = solve("chain-code", &Record::new()).unwrap();
    let code = keyed(&s, "code");
    assert_eq!(code.result[0].0.len(), EX17.len());
    let s = solve("boundary-shape", &Record::new()).unwrap();
    let d = keyed(&s, "diameter");
    assert!(
        d.question_latex().starts_with(r"D = \sqrt{("),
        "{}",
        d.question_latex()
    );
    assert_eq!(keyed(&s, "basic_rectangle").result[0].0.len(), 4);
    // the direction numbers are a figure (a grid) and one relation each
    let s = solve("chain-code", &Record::new()).unwrap();
    let numbers = s
        .steps
        .iter()
        .find(|t| t.title == "Direction numbers")
        .unwrap();
    assert_eq!(numbers.parts.len(), 1 + 8);
    assert!(numbers.substituted.contains(r"\Delta(3) = (0,-1)"));
}
