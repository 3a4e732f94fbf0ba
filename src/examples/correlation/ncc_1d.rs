//! Example 5: the 1-D correlation coefficient of a template with every sub-window of a search array.

use super::*;
use crate::correlation::{correlate_1d, mean};
use crate::examples::drill::{drill, list, nums, or_given, tol, BoxDef, Drill, Mistake};
use crate::examples::fields::{is_seed, MAX_LEN};
use crate::solution::{exact_minus_printed, fmt_sig, NoteKind, Solution};

/// Example 5's ρ as the seed prints them.
const EX5_PRINTED: [f64; 6] = [-0.5, -0.59, -0.09, 0.69, 0.97, 0.37];

pub const EXAMPLE: Example = Example {
    id: "ncc-1d",
    title: "1-D correlation matching",
    source: "Worked examples, Example 5",
    summary: "The normalized correlation coefficient of a template with every sub-window of a 1-D search array, and the best match.",
    fields,
    solve,
    answer: &["best", "best_c"],
    labels: LABELS,
    lab: None,
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

fn fields() -> Vec<Field> {
    vec![
        Field::vector("template", "Template A", (2, MAX_LEN), &EX5_TEMPLATE)
            .help("The pattern to find: at least 2 grey values."),
        Field::vector("search", "Search array", (2, MAX_LEN), &EX5_SEARCH)
            .help("Grey values to search in; at least as long as the template."),
    ]
}

fn solve(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let template = i.list("template")?;
    let search = i.list("search")?;
    let profile = correlate_1d(&template, &search)?;
    let n = template.len();
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    let first = profile.windows.first().copied();
    let (mean_a, sum_da2) = first.map_or((0.0, 0.0), |w| (w.mean_a, w.sum_da2));

    let [sum, mean_rel] = mean_relations(
        r"\sum A_j",
        r"\bar A",
        r"\frac{1}{n}\sum A_j",
        "mean_template",
        &template,
        mean_a,
    );
    s.step(
        Step::new(
            "Template mean",
            "The mean of the template's grey values, and the sum of its squared deviations from it (the same for every sub-window).",
        )
        .relation(sum)
        .relation(mean_rel)
        .relation(squares_relation("A", "A_j", "sum_da2", &template, mean_a, sum_da2))
        .value("mean_template", mean_a)
        .value("sum_da2", sum_da2),
    );

    let count = profile.windows.len();
    let starts: Vec<f64> = (1..=count).map(|k| k as f64).collect();
    let half = half(n);
    let centres: Vec<f64> = starts.iter().map(|k| k + half).collect();
    s.step(
        Step::new(
            "Sub-windows",
            &format!(
                "The template slides along the search array one value at a time. With {} search values and a template of {n}, there are {} − {n} + 1 = {count} sub-windows B_k = (S_k, …, S_(k+{})), counted from 1; the centre of B_k is at column c = k + {}.",
                search.len(),
                search.len(),
                n - 1,
                num(half)
            ),
        )
        .relation(
            Relation::new("K")
                .sym("N - n + 1")
                .subst(format!("{} - {n} + 1", search.len()))
                .value(count as f64, ""),
        )
        .value("starts", Value::numbers(&starts))
        .value("centres", Value::numbers(&centres)),
    );

    let mut detailed: Vec<usize> = (0..count.min(MAX_DETAILED)).collect();
    if let Some(b) = profile.best {
        if b >= MAX_DETAILED {
            detailed.push(b);
        }
    }
    for &k in &detailed {
        let Some(w) = profile.windows.get(k) else {
            continue;
        };
        let sub = search.get(k..k + n).unwrap_or(&[]);
        let mut text = format!(
            "B_{} = {}: its mean, then the correlation coefficient with the template.",
            k + 1,
            plain_list(sub)
        );
        let flat = flat_text(w, "The template", &format!("B_{}", k + 1));
        if !flat.is_empty() {
            text = format!("{text} {flat}");
        }
        let [sum, mean_rel] = mean_relations(
            &format!(r"\sum B_{{{}}}", k + 1),
            &format!(r"\bar B_{{{}}}", k + 1),
            r"\frac{1}{n}\sum B_j",
            "mean_b",
            sub,
            w.mean_b,
        );
        let step = Step::new(&format!("Sub-window {}", k + 1), &text)
            .relation(sum)
            .relation(mean_rel);
        let step = rho_chain(
            step,
            AB_1D,
            &format!(r"\rho_{{{}}}", k + 1),
            &template,
            sub,
            w,
        )
        .value("k", (k + 1) as f64)
        .value("start", (k + 1) as f64)
        .value("centre", k as f64 + 1.0 + half)
        .value("window", Value::numbers(sub));
        s.step(ncc_values(step, w));
    }

    let means: Vec<f64> = profile.windows.iter().map(|w| w.mean_b).collect();
    let rhos: Vec<Option<f64>> = profile.windows.iter().map(|w| w.rho).collect();
    let rho_tex: Vec<String> = rhos.iter().map(|r| rho_text(*r)).collect();
    let mut all = Step::new(
        "All positions",
        &format!(
            "The correlation coefficient at every position{}.",
            if count > detailed.len() {
                format!(
                    " (the computation of the first {MAX_DETAILED} and the best is written out above; select a position in the figure for any other)"
                )
            } else {
                String::new()
            }
        ),
    )
    .relation(
        Relation::new(r"\rho")
            .sym(r"[\rho_1, \dots, \rho_K]")
            .result(list_form(&rho_tex)),
    )
    .value("mean_subwindows", Value::numbers(&means))
    .value("rho", opt_list(rhos.iter().copied()))
    .value(
        "sum_dadb",
        Value::numbers(&profile.windows.iter().map(|w| w.sum_dadb).collect::<Vec<_>>()),
    )
    .value(
        "sum_db2",
        Value::numbers(&profile.windows.iter().map(|w| w.sum_db2).collect::<Vec<_>>()),
    )
    .value("centres", Value::numbers(&centres));
    all = all.value("best", opt(profile.best.map(|b| (b + 1) as f64)));
    s.step(all);

    let best_c = profile.best.map(|b| b as f64 + 1.0 + half);
    match (profile.best, profile.best.and_then(|b| rhos.get(b).copied().flatten())) {
        (Some(b), Some(r)) => s.step(
            Step::new(
                "Best match",
                &format!(
                    "The largest correlation coefficient is at sub-window {} (centre at column c = {}): the best match for the template.",
                    b + 1,
                    num(b as f64 + 1.0 + half)
                ),
            )
            .relation(
                Relation::new("k^*")
                    .key("best")
                    .sym(r"\arg\max_k \rho_k")
                    .value((b + 1) as f64, ""),
            )
            .relation(Relation::new(format!(r"\rho_{{{}}}", b + 1)).value(r, ""))
            .relation(
                Relation::new("c")
                    .key("best_c")
                    .sym(r"k^* + \tfrac{n - 1}{2}")
                    .subst(format!("{} + {}", b + 1, num(half)))
                    .value(b as f64 + 1.0 + half, "px"),
            )
            .value("best", (b + 1) as f64)
            .value("best_c", b as f64 + 1.0 + half),
        ),
        _ => s.step(Step::new(
            "Best match",
            "No position has a correlation coefficient, so there is no best match.",
        )),
    }

    s.result = Record::new()
        .with("mean_template", mean_a)
        .with("mean_subwindows", Value::numbers(&means))
        .with("rho", opt_list(rhos.iter().copied()))
        .with("best", opt(profile.best.map(|b| (b + 1) as f64)))
        .with("centres", Value::numbers(&centres))
        .with("best_c", opt(best_c));

    s.note(
        NoteKind::Convention,
        format!(
            "Positions count from 1, as the course notes do: sub-window k covers search values k … k+{}, and its centre is at column c = k + {} (the positions Example 8 uses).",
            n - 1,
            num(half)
        ),
    ).about(&["centres", "best_c", "best"]);
    flat_notes_1d(&mut s, &profile);
    if is_seed(&fields(), inputs) {
        seed_notes_5(&mut s, &profile);
    }
    Ok(s)
}

fn flat_notes_1d(s: &mut Solution, profile: &correlation::Profile) {
    let Some(first) = profile.windows.first() else {
        return;
    };
    if matches!(first.flat(), Flat::A | Flat::Both) {
        s.note(
            NoteKind::Warning,
            "The template has no variance (all its values are equal): the correlation coefficient is 0/0 at every position, so no ρ has a value and there is no best match.",
        ).about(&["rho", "best"]);
        return;
    }
    let flat: Vec<String> = profile
        .windows
        .iter()
        .enumerate()
        .filter(|(_, w)| w.rho.is_none())
        .map(|(k, _)| (k + 1).to_string())
        .collect();
    if !flat.is_empty() {
        s.note(
            NoteKind::Warning,
            format!(
                "Sub-window{} {} {} no variance (all values equal): ρ is 0/0 there and has no value.",
                if flat.len() > 1 { "s" } else { "" },
                flat.join(", "),
                if flat.len() > 1 { "have" } else { "has" }
            ),
        ).about(&["rho"]);
        if profile.best.is_none() {
            s.note(
                NoteKind::Warning,
                "No sub-window has a correlation coefficient, so there is no best match.",
            )
            .about(&["best"]);
        }
    }
    if profile.ties > 1 {
        s.note(
            NoteKind::Warning,
            format!(
                "{} positions share the largest correlation coefficient; the first of them is taken as the best.",
                profile.ties
            ),
        ).about(&["best"]);
    }
}

fn seed_notes_5(s: &mut Solution, profile: &correlation::Profile) {
    s.textbook = Some(
        Record::new()
            .with("mean_template", 4.57)
            .with(
                "mean_subwindows",
                Value::numbers(&[2.57, 3.57, 4.14, 4.0, 4.0, 4.0]),
            )
            .with("rho", Value::numbers(&EX5_PRINTED))
            .with("best", 5.0),
    );
    let w = |k: usize| profile.windows.get(k).copied();
    let r = |k: usize| w(k).and_then(|w| w.rho).unwrap_or(0.0);
    let (r1, r4, r5) = (r(0), r(3), r(4));
    let mean_a = w(0).map_or(0.0, |w| w.mean_a);
    let means: Vec<f64> = profile.windows.iter().map(|w| w.mean_b).collect();
    let (dadb4, da2, db24) = w(3).map_or((0.0, 0.0, 0.0), |w| (w.sum_dadb, w.sum_da2, w.sum_db2));
    s.note(
        NoteKind::Rounding,
        format!(
            "The course notes' means Ā = 4.57 and B̄ = 2.57, 3.57, 4.14, 4, 4, 4 are the exact {} and {} rounded to two decimals; ρ2 = −0.59, ρ3 = −0.09 and ρ6 = 0.37 match the exact values to the printed two decimals.",
            num(mean_a),
            means.iter().map(|m| num(*m)).collect::<Vec<_>>().join(", ")
        ),
    ).about(&["mean_template", "mean_subwindows"]);
    s.note(
        NoteKind::Rounding,
        format!(
            "ρ1 is printed as −0.5: the exact {} rounded to one decimal only (two decimals give {}).",
            num(r1),
            fmt_sig(round_to(r1, 2), 3)
        ),
    ).about(&["rho"]);
    s.note(
        NoteKind::Erratum,
        format!(
            "ρ4 is printed as 0.69, but B4 = [1, 1, 3, 8, 8, 6, 1] gives Σ(A−Ā)(B−B̄) = {}, Σ(A−Ā)² = {}, Σ(B−B̄)² = {} and ρ4 = {} ≈ {}: the printed value is too high by more than rounding (ρ4: {}). Example 8 uses the printed 0.69.",
            num(dadb4),
            num(da2),
            num(db24),
            num(r4),
            fmt_sig(round_to(r4, 2), 2),
            exact_minus_printed(r4, 0.69, "")
        ),
    ).about(&["rho"]);
    s.note(
        NoteKind::Rounding,
        format!(
            "ρ5 is printed as 0.97; the exact {} rounds to {} (the course notes cut the third decimal off). The best match, sub-window 5, is the same.",
            num(r5),
            fmt_sig(round_to(r5, 2), 2)
        ),
    ).about(&["rho", "best"]);
}

// ---------------------------------------------------------------- practice

/// Template length and number of sub-windows of the variants.
const N_T: usize = 7;
const WINDOWS: usize = 5;

/// A bump like the seed's template (1 2 9 9 8 2 1): distinct values rising
/// to a peak and falling, so no shifted copy of it looks like it.
fn bump(rng: &mut Rng) -> Vec<f64> {
    let mut pool: Vec<f64> = (0..10).map(f64::from).collect();
    let mut v = Vec::new();
    for _ in 0..N_T {
        let k = rng.int(0, pool.len() as i64 - 1) as usize;
        v.push(pool.remove(k));
    }
    let peak = rng.int(2, N_T as i64 - 3) as usize;
    v.sort_by(|a, b| a.total_cmp(b));
    // Every other value goes up the left flank, the rest down the right.
    let top = v.pop().unwrap_or(9.0);
    let (mut left, mut right) = (Vec::new(), Vec::new());
    for (i, x) in v.into_iter().enumerate() {
        if (i % 2 == 0 && left.len() < peak) || right.len() >= N_T - 1 - peak {
            left.push(x);
        } else {
            right.push(x);
        }
    }
    right.reverse();
    left.push(top);
    left.extend(right);
    left
}

fn generate(rng: &mut Rng) -> Record {
    let t = bump(rng);
    let mut s = textured(rng, N_T + WINDOWS - 1);
    // The template, brightened, at a random place: the best match (ρ = 1,
    // as brightness does not change ρ).
    let at = rng.int(0, WINDOWS as i64 - 1) as usize;
    let gain = rng.num(0, 3);
    for (k, v) in t.iter().enumerate() {
        s[at + k] = v + gain;
    }
    Record::new()
        .with("template", nums(&t))
        .with("search", nums(&s))
}

fn boxes(_: &Record) -> Vec<BoxDef> {
    let mut b = vec![
        BoxDef::new("mean_template", "Template mean Ā", None, tol::GREY)
            .nudge("Add the template's grey values and divide by how many there are."),
    ];
    for k in 1..=WINDOWS {
        b.push(
            BoxDef::new(&format!("rho[{k}]"), &format!("ρ at sub-window {k}"), None, tol::RHO)
                .nudge("Subtract each mean, then: sum of products over the root of the product of the sums of squares.")
                .sign_flip(RHO_FLIP),
        );
    }
    b.push(
        BoxDef::new("best", "Best sub-window (from 1)", None, tol::WHOLE)
            .nudge("The sub-window with the largest ρ."),
    );
    b
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let (t, s) = (list(i, "template"), list(i, "search"));
    let ma = or_given(g, "mean_template", mean(&t));
    let mut out = Record::new().with("mean_template", ma);
    let mut best = (0usize, f64::NEG_INFINITY);
    for k in 1..=WINDOWS {
        let key = format!("rho[{k}]");
        let w = s.get(k - 1..k - 1 + t.len()).unwrap_or(&[]);
        let rho = or_given(g, &key, rho_about(&t, ma, w, mean(w)));
        if rho > best.1 {
            best = (k, rho);
        }
        out.set(&key, rho);
    }
    out.set("best", or_given(g, "best", best.0 as f64));
    Ok(out)
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let (t, s) = (list(i, "template"), list(i, "search"));
    let mut out = Vec::new();
    for k in 1..=WINDOWS {
        let w = s.get(k - 1..k - 1 + t.len()).unwrap_or(&[]);
        out.push(Mistake::new(
            &format!("rho[{k}]"),
            "mean not subtracted",
            "ρ compares the deviations from the means: subtract Ā from the template and B̄ from the sub-window first.",
            rho_about(&t, 0.0, w, 0.0),
        ));
    }
    let best = chain(i, &Record::new())?.number("best").unwrap_or(0.0);
    out.push(Mistake::new(
        "best",
        "counted from 0",
        "The seed counts the sub-windows from 1.",
        best - 1.0,
    ));
    Ok(out)
}
