//! Example 5: the 1-D correlation coefficient of a template with every sub-window of a search array.

use super::*;

pub(super) fn ncc_1d(inputs: &Record) -> Result<Solution> {
    let template = list(inputs, "template")?;
    let search = list(inputs, "search")?;
    let profile = correlate_1d(&template, &search)?;
    let n = template.len();
    let mut s = Solution::new("ncc-1d", "1-D correlation matching", inputs.clone());
    let first = profile.windows.first().copied();
    let (mean_a, sum_da2) = first.map_or((0.0, 0.0), |w| (w.mean_a, w.sum_da2));

    s.step(
        Step::new(
            "Template mean",
            "The mean of the template's grey values, and the sum of its squared deviations from it (the same for every sub-window).",
        )
        .formula(
            r"\bar A = \frac{1}{n}\sum A_j,\quad \sum (A_j - \bar A)^2",
            format!(
                r"{},\quad \sum (A_j - \bar A)^2 = {} = {}",
                tex_mean(r"\sum A_j", r"\bar A", &template, mean_a),
                tex_dev_terms(&template, mean_a, None),
                num(sum_da2)
            ),
        )
        .value("mean_template", mean_a)
        .value("sum_da2", sum_da2),
    );

    let count = profile.windows.len();
    let starts: Vec<f64> = (1..=count).map(|k| k as f64).collect();
    let half = (n as f64 - 1.0) / 2.0;
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
        .formula(
            r"K = N - n + 1",
            format!("K = {} - {n} + 1 = {count}", search.len()),
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
            tex_list(sub).replace(r",\ ", ", ")
        );
        let flat = flat_text(w, "The template", &format!("B_{}", k + 1));
        if !flat.is_empty() {
            text = format!("{text} {flat}");
        }
        let step = Step::new(&format!("Sub-window {}", k + 1), &text)
            .formula(
                &format!(
                    r"\bar B_{{{0}}} = \frac{{1}}{{n}}\sum B_j,\quad {RHO_SYMBOLIC}",
                    k + 1
                ),
                format!(
                    r"{},\quad {}",
                    tex_mean(
                        &format!(r"\sum B_{{{}}}", k + 1),
                        &format!(r"\bar B_{{{}}}", k + 1),
                        sub,
                        w.mean_b
                    ),
                    tex_rho_chain(&format!(r"\rho_{{{}}}", k + 1), &template, sub, w)
                ),
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
    let shown = if rho_tex.len() > 2 * MAX_TERMS {
        format!(
            r"{},\ \dots,\ {}",
            rho_tex[..MAX_TERMS].join(r",\ "),
            rho_tex[rho_tex.len() - 1]
        )
    } else {
        rho_tex.join(r",\ ")
    };
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
    .formula(r"\rho_k,\ k = 1 \dots K", format!(r"\rho = [{shown}]"))
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
            .formula(
                r"k^* = \arg\max_k \rho_k",
                format!(r"k^* = {},\quad \rho_{{{}}} = {}", b + 1, b + 1, num(r)),
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
    if is_seed(&ncc_1d_fields(), inputs) {
        seed_notes_5(&mut s, &profile);
    }
    label_results(&mut s);
    Ok(s)
}

pub(super) fn flat_notes_1d(s: &mut Solution, profile: &correlation::Profile) {
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

pub(super) fn seed_notes_5(s: &mut Solution, profile: &correlation::Profile) {
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
