//! Issue 13, "every solution readable on every screen": the parts of the
//! interface the page reads for it, over the whole catalog: each example's
//! answer keys, labels for every key the page shows, notes keyed to their
//! quantities with differences stated one way (exact − printed) and their
//! percentages with the same sign (issue 29), and fields that apply only in
//! some modes.

use photogrammetry_playground::examples::{catalog, parse_inputs, solve};
use photogrammetry_playground::solution::{NoteKind, Record, Solution, Value};

/// Every built example solved with its seed inputs.
fn seed_solutions() -> Vec<Solution> {
    catalog()
        .iter()
        .filter(|e| e.status == "ready")
        .map(|e| solve(e.id, &Record::new()).unwrap_or_else(|err| panic!("{}: {err}", e.id)))
        .collect()
}

#[test]
fn every_example_has_an_answer_of_one_to_three_result_keys() {
    for s in seed_solutions() {
        assert!(
            (1..=3).contains(&s.answer.len()),
            "{}: answer {:?}",
            s.id,
            s.answer
        );
        for k in &s.answer {
            assert!(
                s.result.get(k).is_some(),
                "{}: answer {k} is no result key",
                s.id
            );
        }
    }
    let s = solve("gsd", &Record::new()).unwrap();
    assert_eq!(s.answer, ["gsd_cm"]);
    let s = solve("pixel-to-photo", &Record::new()).unwrap();
    assert_eq!(s.answer, ["x_mm", "y_mm"]);
    let s = solve("fiducial-affine", &Record::new()).unwrap();
    assert_eq!(s.answer, ["parameters", "sigma0"]);
    let s = solve("ncc-2d", &Record::new()).unwrap();
    assert_eq!(s.answer, ["rho"]);
}

/// Some what-ifs in other modes, whose notes are not the seed's.
fn variants() -> Vec<Solution> {
    let cases: Vec<(&str, Record)> = vec![
        (
            "chain-code",
            Record::new()
                .with("given", "code")
                .with("connectivity", "4")
                .with("code", Value::numbers(&[1.0, 1.0, 2.0, 3.0, 3.0, 4.0])),
        ),
        (
            "chain-code",
            Record::new().with("pixels", Value::matrix(&[vec![1.0, 1.0], vec![3.0, 1.0]])),
        ),
        ("boundary-length", Record::new().with("given", "region")),
        (
            "boundary-shape",
            Record::new().with(
                "pixels",
                Value::matrix(&[vec![1.0, 1.0], vec![2.0, 1.0], vec![3.0, 1.0]]),
            ),
        ),
        (
            "filter-window",
            Record::new()
                .with("kernel", "custom")
                .with("custom_divisor", 2.0),
        ),
        (
            "filter-window",
            Record::new()
                .with("kernel", "laplacian-8")
                .with("border", "replicate"),
        ),
        (
            "edge-window",
            Record::new()
                .with("operator", "sobel")
                .with("select_c", 1.0),
        ),
        ("subpixel-1d", Record::new().with("rho_from", "exact")),
        (
            "subpixel-1d",
            Record::new().with("rho", Value::numbers(&[0.9, 0.5, 0.9])),
        ),
        ("subpixel-2d", Record::new().with("rho_from", "exact")),
        ("lsm-1d", Record::new().with("radiometric", true)),
        ("lsm-2d", Record::new().with("gradients", "patch-edge")),
        ("resample", Record::new().with("c", 545.5).with("r", 817.5)),
        ("resample", Record::new().with("cubic_a", -0.5)),
        (
            "transform-fit",
            Record::new()
                .with("model", "projective")
                .with("point_set", "control-12"),
        ),
        (
            "transform-fit",
            Record::new()
                .with("model", "polynomial-2")
                .with("point_set", "control-12"),
        ),
        (
            "forstner-window",
            Record::new().with(
                "window",
                Value::matrix(&[vec![5.0; 3], vec![5.0; 3], vec![5.0; 3]]),
            ),
        ),
        (
            "ncc-1d",
            Record::new().with("template", Value::numbers(&[2.0, 2.0, 2.0])),
        ),
        ("pixel-to-photo", Record::new().with("c", 5000.0)),
        ("photo-to-pixel", Record::new().with("x_mm", 500.0)),
    ];
    cases
        .into_iter()
        .map(|(id, inputs)| solve(id, &inputs).unwrap_or_else(|e| panic!("{id}: {e}")))
        .collect()
}

#[test]
fn notes_name_only_keys_of_the_solution() {
    for s in seed_solutions().into_iter().chain(variants()) {
        for n in &s.notes {
            for k in &n.keys {
                let known = s.result.get(k).is_some()
                    || s.textbook.as_ref().is_some_and(|t| t.get(k).is_some());
                assert!(
                    known,
                    "{}: note names {k}, not a result or printed key: {}",
                    s.id, n.text
                );
            }
        }
    }
}

#[test]
fn photo_to_pixel_sign_slip_is_an_erratum_keyed_to_the_row_offset() {
    let s = solve("photo-to-pixel", &Record::new()).unwrap();
    let erratum = s
        .notes
        .iter()
        .find(|n| n.kind == NoteKind::Erratum)
        .expect("an erratum note");
    assert_eq!(erratum.keys, ["dr_px"]);
    let rounding: Vec<_> = s
        .notes
        .iter()
        .filter(|n| n.kind == NoteKind::Rounding)
        .collect();
    assert!(rounding.iter().any(|n| n.concerns("c") && n.concerns("r")));
    assert!(rounding.iter().any(|n| n.concerns("pixel_size_mm")));
    // the note gives the differences in the table's direction
    let n = rounding.iter().find(|n| n.concerns("r")).unwrap();
    assert!(
        n.text.contains("r: exact − printed = −4.744882 px"),
        "{}",
        n.text
    );
    assert!(
        n.text.contains("c: exact − printed = +2.314173 px"),
        "{}",
        n.text
    );
}

const TAG: &str = "exact − printed = ";

/// Every "exact − printed = ±d" a note states, as numbers.
fn stated_differences(text: &str) -> Vec<f64> {
    text.match_indices(TAG)
        .map(|(i, _)| {
            let (sign, d) = signed_number(&text[i + TAG.len()..])
                .unwrap_or_else(|| panic!("no number after the sign: {text}"));
            assert!(
                sign.is_some(),
                "a stated difference without its sign: {text}"
            );
            d
        })
        .collect()
}

/// A number as a note writes it: the sign it was written with (`None`
/// when it has none) and its value.
type Signed = (Option<f64>, f64);

/// A signed number at the start of `s` ("−0.79", "+2.3e-5"), with the
/// sign it was written with (`None` when it has none).
fn signed_number(s: &str) -> Option<Signed> {
    let (sign, rest) = if let Some(r) = s.strip_prefix('−') {
        (Some(-1.0), r)
    } else if let Some(r) = s.strip_prefix('+') {
        (Some(1.0), r)
    } else {
        (None, s)
    };
    let digits: String = rest
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == 'e' || *c == '-')
        .collect();
    let x: f64 = digits.parse().ok()?;
    Some((sign, sign.unwrap_or(1.0) * x))
}

/// The numbers of a value, flattened (a number, a list, a matrix).
fn flat(v: &Value) -> Vec<f64> {
    match v {
        Value::Number(x) => vec![*x],
        Value::List(xs) => xs.iter().flat_map(flat).collect(),
        _ => Vec::new(),
    }
}

/// The (exact, printed) pairs of the page's table for `key`, element by
/// element, where the result (or a step value) and the printed value are
/// numbers of the same shape.
fn table_pairs(s: &Solution, key: &str) -> Vec<(f64, f64)> {
    let Some(printed) = s.textbook.as_ref().and_then(|t| t.get(key)) else {
        return Vec::new();
    };
    let exact = s
        .result
        .get(key)
        .or_else(|| s.steps.iter().find_map(|st| st.values.get(key)));
    let (Some(exact), printed) = (exact.map(flat), flat(printed)) else {
        return Vec::new();
    };
    if exact.len() != printed.len() {
        return Vec::new();
    }
    exact.into_iter().zip(printed).collect()
}

/// Differences the page's table shows for `key`: exact − printed.
fn table_differences(s: &Solution, key: &str) -> Vec<f64> {
    table_pairs(s, key).iter().map(|(e, p)| e - p).collect()
}

#[test]
fn every_stated_difference_is_exact_minus_printed_of_a_key_of_its_note() {
    let mut checked = 0;
    for s in seed_solutions() {
        for n in &s.notes {
            for d in stated_differences(&n.text) {
                let candidates: Vec<f64> = n
                    .keys
                    .iter()
                    .flat_map(|k| table_differences(&s, k))
                    .collect();
                // the text shows 7 significant digits
                let ok = candidates
                    .iter()
                    .any(|c| (c - d).abs() <= 1e-6 * c.abs().max(1e-9) + 1e-12);
                assert!(
                    ok,
                    "{}: the note states exact − printed = {d}, but its keys {:?} give {candidates:?}: {}",
                    s.id, n.keys, n.text
                );
                checked += 1;
            }
        }
    }
    assert!(checked >= 8, "only {checked} stated differences found");
}

#[test]
fn a_wrong_sign_would_fail_the_difference_check() {
    // the check above, against a note written the other way round
    let s = solve("photo-to-pixel", &Record::new()).unwrap();
    let c = table_differences(&s, "c");
    assert_eq!(c.len(), 1);
    let wrong = stated_differences("c: exact − printed = −2.314173 px");
    assert!((wrong[0] - c[0]).abs() > 1.0);
    let right = stated_differences("c: exact − printed = +2.314173 px");
    assert!((right[0] - c[0]).abs() < 1e-6);
}

// ------------------------------------------------- percentages (issue 29, item 3)
// Every "exact − printed = ±d" a note states, and the percentage stated with
// it, carry the same sign: the share is (exact − printed) / |printed|, written
// "exact − printed = +0.0002222222 mm = +0.79 % of the printed value".

/// Every stated difference of a note with the percentages that follow it
/// (before the next stated difference): `[(d, [(sign, share)])]`.
fn differences_and_shares(text: &str) -> Vec<(f64, Vec<Signed>)> {
    let starts: Vec<usize> = text.match_indices(TAG).map(|(i, _)| i).collect();
    starts
        .iter()
        .enumerate()
        .map(|(k, &i)| {
            let end = starts.get(k + 1).copied().unwrap_or(text.len());
            let span = &text[i + TAG.len()..end];
            let (_, d) =
                signed_number(span).unwrap_or_else(|| panic!("no number after \"{TAG}\": {text}"));
            // every "<number> %" of the span, read back from its first digit or sign
            let shares = span
                .match_indices(" %")
                .filter_map(|(j, _)| {
                    let before = &span[..j];
                    let start = before
                        .char_indices()
                        .rev()
                        .take_while(|(_, c)| c.is_ascii_digit() || matches!(c, '.' | '−' | '+'))
                        .last()
                        .map(|(s, _)| s)?;
                    signed_number(&before[start..])
                })
                .collect();
            (d, shares)
        })
        .collect()
}

#[test]
fn every_percentage_has_the_sign_and_size_of_its_difference() {
    let mut checked = 0;
    for s in seed_solutions() {
        for n in &s.notes {
            for (d, shares) in differences_and_shares(&n.text) {
                for (sign, share) in shares {
                    let sign = sign.unwrap_or_else(|| {
                        panic!(
                            "{}: a percentage without its sign after exact − printed: {}",
                            s.id, n.text
                        )
                    });
                    assert_eq!(
                        sign,
                        if d < 0.0 { -1.0 } else { 1.0 },
                        "{}: exact − printed = {d} but the percentage is {share} %: {}",
                        s.id,
                        n.text
                    );
                    // the share of the printed value, from the table's own numbers
                    let pair = n
                        .keys
                        .iter()
                        .flat_map(|k| table_pairs(&s, k))
                        .find(|(x, p)| ((x - p) - d).abs() <= 1e-6 * d.abs().max(1e-9));
                    let (x, p) = pair
                        .unwrap_or_else(|| panic!("{}: no table row gives {d}: {}", s.id, n.text));
                    let want = (x - p) / p.abs() * 100.0;
                    assert!(
                        (share - want).abs() <= 0.05 * want.abs(),
                        "{}: the note says {share} %, the table gives {want} %: {}",
                        s.id,
                        n.text
                    );
                    checked += 1;
                }
            }
        }
    }
    // gsd (scale number, pixel size, GSD) and the pixel size of the two
    // pixel/photo examples
    assert!(checked >= 5, "only {checked} percentages found");
}

#[test]
fn the_note_of_the_issue_would_fail() {
    // "exact − printed = +0.000222 mm; −0.79 %", as the issue saw it
    let found = differences_and_shares("(exact − printed = +0.000222 mm; −0.79 %)");
    assert_eq!(found, vec![(0.000222, vec![(Some(-1.0), -0.79)])]);
    let found = differences_and_shares(
        "(exact − printed = −0.065 mm = −0.79 % of the printed value; exact − printed = +1 px)",
    );
    assert_eq!(
        found,
        vec![(-0.065, vec![(Some(-1.0), -0.79)]), (1.0, vec![])]
    );
}

#[test]
fn the_gsd_pixel_size_note_reads_as_one_equation() {
    let s = solve("gsd", &Record::new()).unwrap();
    let n = s
        .notes
        .iter()
        .find(|n| n.text.contains("round the pixel size"))
        .expect("the pixel size note");
    assert!(
        n.text
            .contains("(exact − printed = +0.0002222222 mm = +0.79 % of the printed value)"),
        "{}",
        n.text
    );
}

// ------------------------------------------------------- mode-dependent fields

/// `(id, field, controlling key, a value where it applies, one where not)`.
const MODE_FIELDS: &[(&str, &str, &str, &str, &str)] = &[
    ("chain-code", "code", "given", "code", "pixels"),
    ("chain-code", "start", "given", "code", "region"),
    ("chain-code", "pixels", "given", "pixels", "code"),
    ("boundary-length", "code", "given", "code", "pixels"),
    ("boundary-length", "start", "given", "code", "pixels"),
    ("boundary-length", "pixels", "given", "region", "code"),
    ("filter-window", "custom_kernel", "kernel", "custom", "mean"),
    (
        "filter-window",
        "custom_divisor",
        "kernel",
        "custom",
        "median",
    ),
    ("subpixel-1d", "positions", "rho_from", "printed", "exact"),
    ("subpixel-1d", "rho", "rho_from", "printed", "exact"),
    ("subpixel-2d", "c", "rho_from", "printed", "exact"),
    ("subpixel-2d", "r", "rho_from", "printed", "exact"),
    ("subpixel-2d", "rho", "rho_from", "printed", "exact"),
    ("transform-fit", "points", "point_set", "table", "fiducials"),
];

#[test]
fn the_catalog_says_when_a_field_applies() {
    let cat = catalog();
    for &(id, key, control, yes, no) in MODE_FIELDS {
        let e = cat.iter().find(|e| e.id == id).unwrap();
        let f = e.inputs.iter().find(|f| f.key == key).unwrap();
        let w = f.when.unwrap_or_else(|| panic!("{id}.{key} has no when"));
        assert_eq!(w.key, control, "{id}.{key}");
        assert!(
            w.values.contains(&yes) && !w.values.contains(&no),
            "{id}.{key}"
        );
    }
    // every `when` names a choice field of the same entry and its options
    for e in &cat {
        for f in &e.inputs {
            let Some(w) = f.when else { continue };
            let ctl = e
                .inputs
                .iter()
                .find(|g| g.key == w.key)
                .unwrap_or_else(|| panic!("{}.{}: when names {}", e.id, f.key, w.key));
            let opts = ctl.options.as_ref().expect("a choice");
            for v in w.values {
                assert!(
                    opts.iter().any(|o| o.value == *v),
                    "{}.{}: {v}",
                    e.id,
                    f.key
                );
            }
            assert!(!w.values.is_empty());
        }
    }
    // fields without a mode say so
    let gsd = cat.iter().find(|e| e.id == "gsd").unwrap();
    assert!(gsd.inputs.iter().all(|f| f.when.is_none()));
}

#[test]
fn a_field_that_does_not_apply_never_blocks_parse_or_solve() {
    for &(id, key, control, yes, no) in MODE_FIELDS {
        // an empty text is an error for every one of these fields
        let texts = Record::new().with(control, no).with(key, "");
        let p = parse_inputs(id, &texts).unwrap();
        assert!(
            p.errors.is_empty(),
            "{id}.{key} with {control} = {no}: {:?}",
            p.errors
        );
        assert!(
            solve(id, &p.inputs).is_ok(),
            "{id}.{key} with {control} = {no}"
        );
        // typed: an invalid value is ignored, the default used
        let typed = Record::new()
            .with(control, no)
            .with(key, Value::List(Vec::new()));
        let s = solve(id, &typed).unwrap_or_else(|e| panic!("{id}.{key}: {e}"));
        assert!(s.inputs.get(key).is_some());
        // where it applies, the same text is an error naming the field
        let texts = Record::new().with(control, yes).with(key, "");
        let p = parse_inputs(id, &texts).unwrap();
        assert!(
            p.errors.get(key).is_some(),
            "{id}.{key} with {control} = {yes}"
        );
        let typed = Record::new()
            .with(control, yes)
            .with(key, Value::List(Vec::new()));
        let e = solve(id, &typed).unwrap_err();
        assert_eq!(e.field(), Some(key), "{id}: {e}");
    }
}

#[test]
fn chain_code_from_pixels_solves_with_an_empty_code() {
    let texts = Record::new()
        .with("given", "pixels")
        .with("code", "")
        .with("start", "x");
    let p = parse_inputs("chain-code", &texts).unwrap();
    assert!(p.errors.is_empty(), "{:?}", p.errors);
    let s = solve("chain-code", &p.inputs).unwrap();
    let seed = solve("chain-code", &Record::new()).unwrap();
    assert_eq!(s.result, seed.result);
    // a valid value of a field that does not apply is kept, and ignored
    let s = solve(
        "chain-code",
        &Record::new()
            .with("given", "pixels")
            .with("code", Value::numbers(&[1.0, 1.0])),
    )
    .unwrap();
    assert_eq!(s.result, seed.result);
    assert_eq!(s.inputs.get("code"), Some(&Value::numbers(&[1.0, 1.0])));
    // and the printed comparison stays: the code does not count
    assert_eq!(s.textbook, seed.textbook);
}

#[test]
fn every_entry_names_its_course_document() {
    for e in catalog() {
        assert!(!e.document.is_empty(), "{}: no document", e.id);
        assert!(
            !e.source.contains("Seed") && !e.source.contains("seed"),
            "{}: {}",
            e.id,
            e.source
        );
    }
    let cat = catalog();
    let gsd = cat.iter().find(|e| e.id == "gsd").unwrap();
    assert_eq!(gsd.source, "Worked examples, Example 2");
    assert_eq!(
        gsd.document,
        "Course notes — Worked examples 1–18 (digital image coordinates to boundary descriptors)"
    );
    let f = cat.iter().find(|e| e.id == "forstner-window").unwrap();
    assert!(
        f.document.contains("Lecture 21 — Image matching"),
        "{}",
        f.document
    );
}

#[test]
fn every_key_the_page_shows_has_a_label() {
    let mut missing = Vec::new();
    for s in seed_solutions().into_iter().chain(variants()) {
        let printed = s.textbook.iter().flat_map(|t| t.keys());
        for key in s.result.keys().chain(printed) {
            let Some(Value::Object(l)) = s.labels.get(key) else {
                missing.push(format!("{}: {key}", s.id));
                continue;
            };
            let Some(Value::Text(label)) = l.get("label") else {
                panic!("{}: {key}'s label is not text", s.id)
            };
            if label.is_empty() || label.contains('_') {
                missing.push(format!("{}: {key} → {label}", s.id));
            }
        }
    }
    missing.dedup();
    assert!(missing.is_empty(), "no label: {missing:?}");
}

/// The arguments of every `\frac{…}{…}`, `\tfrac`, `\sqrt{…}` in `tex`.
fn unbreakable_parts(tex: &str) -> Vec<String> {
    let mut out = Vec::new();
    for cmd in [r"\frac{", r"\tfrac{", r"\sqrt{"] {
        let mut from = 0;
        while let Some(i) = tex[from..].find(cmd) {
            let start = from + i + cmd.len();
            let mut depth = 1;
            let mut end = start;
            for (k, ch) in tex[start..].char_indices() {
                match ch {
                    '{' => depth += 1,
                    '}' => depth -= 1,
                    _ => {}
                }
                if depth == 0 {
                    end = start + k;
                    break;
                }
            }
            out.push(tex[start..end].to_string());
            from = start;
        }
    }
    out
}

#[test]
fn no_written_out_sum_sits_inside_a_fraction_or_a_root() {
    for s in seed_solutions().into_iter().chain(variants()) {
        for st in &s.steps {
            for part in unbreakable_parts(&st.substituted) {
                let terms = part.matches(" + ").count() + part.matches(" - ").count();
                assert!(
                    terms <= 3 || part.len() <= 40,
                    "{}, step \"{}\": a sum of {} terms inside a fraction or root: {part}",
                    s.id,
                    st.title,
                    terms + 1
                );
            }
        }
    }
}

#[test]
fn resample_says_where_its_bicubic_value_would_be() {
    let s = solve("resample", &Record::new()).unwrap();
    assert_eq!(s.result.get("bicubic"), Some(&Value::Null));
    let n = s
        .notes
        .iter()
        .find(|n| n.concerns("bicubic"))
        .expect("a note on bicubic");
    assert!(
        n.text.contains("columns 546 to 549 and rows 816 to 819"),
        "{}",
        n.text
    );
    assert!(
        n.text
            .contains("patch covers columns 545–548 and rows 817–820"),
        "{}",
        n.text
    );
    assert!(n.text.contains("c = 546.44 and r = 818.24"), "{}", n.text);
    // the inputs the note suggests do give one
    let s = solve(
        "resample",
        &Record::new().with("c", 546.44).with("r", 818.24),
    )
    .unwrap();
    assert!(s.result.number("bicubic").is_some());
    assert!(s.notes.iter().all(|n| !n.text.contains("No bicubic")));
}

#[test]
fn convergence_tests_name_the_parameters_estimated() {
    let step = |s: &Solution| {
        s.steps
            .iter()
            .find(|st| st.title == "Converged")
            .cloned()
            .expect("a converged step")
    };
    let s = solve("lsm-1d", &Record::new()).unwrap();
    let st = step(&s);
    assert_eq!(st.formula, r"|dc| \le 10^{-4}\ \text{px}");
    assert!(!st.text.contains("grey value"), "{}", st.text);
    let s = solve("lsm-1d", &Record::new().with("radiometric", true)).unwrap();
    let st = step(&s);
    assert!(st.formula.contains(r"|da\, G_i + db|"), "{}", st.formula);
    assert!(!st.formula.contains("da_7"));
    let s = solve("lsm-2d", &Record::new()).unwrap();
    assert!(step(&s).formula.starts_with(r"\sqrt{dc^2 + dr^2}"));
    let s = solve("lsm-affine", &Record::new()).unwrap();
    let st = step(&s);
    assert!(st.formula.contains("da_7"));
    assert!(
        st.text.contains("da₇ = ") && !st.text.contains("da_7"),
        "{}",
        st.text
    );
}

/// Words a student would not know: the internal names of the course
/// documents, and "null" for a value that does not exist.
fn jargon(text: &str) -> Option<&'static str> {
    let lower = text.to_lowercase();
    let lower = lower.replace("random seed", "");
    ["seed 00", "the seed", "seed's", "null"]
        .into_iter()
        .find(|w| lower.contains(w))
}

#[test]
fn catalog_and_solutions_speak_a_students_words() {
    for e in catalog() {
        for t in [e.title, e.source, e.summary] {
            assert_eq!(jargon(t), None, "{}: {t}", e.id);
        }
        for f in &e.inputs {
            assert_eq!(jargon(f.label), None, "{}.{}: {}", e.id, f.key, f.label);
            assert_eq!(jargon(f.help), None, "{}.{}: {}", e.id, f.key, f.help);
            for o in f.options.iter().flatten() {
                assert_eq!(jargon(o.label), None, "{}.{}: {}", e.id, f.key, o.label);
                assert!(!o.label.contains('_'), "{}.{}: {}", e.id, f.key, o.label);
            }
        }
    }
    for s in seed_solutions().into_iter().chain(variants()) {
        for st in &s.steps {
            assert_eq!(jargon(&st.title), None, "{}: {}", s.id, st.title);
            assert_eq!(jargon(&st.text), None, "{}: {}", s.id, st.text);
        }
        for n in &s.notes {
            assert_eq!(jargon(&n.text), None, "{}: {}", s.id, n.text);
        }
    }
}
