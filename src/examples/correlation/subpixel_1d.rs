//! Example 8: the subpixel peak of a parabola through three correlation coefficients.

use super::*;

/// Example 5 computed exactly: positions (sub-window centres) and ρ of the
/// best sub-window and its two neighbours, and the best index.
pub(super) fn example_5_exact() -> Result<([f64; 3], [f64; 3], usize)> {
    let profile = correlate_1d(&EX5_TEMPLATE, &EX5_SEARCH)?;
    let half = half(EX5_TEMPLATE.len());
    let best = profile.best.unwrap_or(0);
    let pick = |k: usize| profile.windows.get(k).and_then(|w| w.rho);
    match (best.checked_sub(1), pick(best), pick(best + 1)) {
        (Some(k0), Some(r1), Some(r2)) => match pick(k0) {
            Some(r0) => {
                let c = |k: usize| k as f64 + 1.0 + half;
                Ok(([c(k0), c(best), c(best + 1)], [r0, r1, r2], best))
            }
            None => Err(Error::input(
                "rho_from",
                "Example 5 has no exact ρ beside its best match",
            )),
        },
        _ => Err(Error::input(
            "rho_from",
            "Example 5's best match has no neighbour on both sides",
        )),
    }
}

pub(super) fn extremum_name(e: &Extremum) -> &'static str {
    match e {
        Extremum::Maximum { .. } => "maximum",
        Extremum::Minimum { .. } => "minimum",
        Extremum::Saddle { .. } => "saddle",
        Extremum::Degenerate => "none",
    }
}

pub(super) fn subpixel_1d(inputs: &Record) -> Result<Solution> {
    let exact_mode = text(inputs, "rho_from")? == "exact";
    let mut s = Solution::new("subpixel-1d", "Subpixel peak in 1-D", inputs.clone());
    let (x, y) = if exact_mode {
        let (x, y, best) = example_5_exact()?;
        s.step(
            Step::new(
                "ρ from Example 5, computed exactly",
                &format!(
                    "Example 5's template and search array give the best match at sub-window {} (centre c = {}); its neighbours are sub-windows {} and {}.",
                    best + 1,
                    num(x[1]),
                    best,
                    best + 2
                ),
            )
            .formula(
                r"(c_i, \rho_i)",
                format!(
                    r"({}, {}),\ ({}, {}),\ ({}, {})",
                    num(x[0]),
                    num(y[0]),
                    num(x[1]),
                    num(y[1]),
                    num(x[2]),
                    num(y[2])
                ),
            )
            .value("positions", Value::numbers(&x))
            .value("rho", Value::numbers(&y)),
        );
        let defaults = subpixel_1d_fields();
        let changed = ["positions", "rho"].iter().any(|k| {
            defaults
                .iter()
                .any(|f| f.key == *k && inputs.get(k) != Some(&f.default))
        });
        if changed {
            s.note(
                NoteKind::Warning,
                "With ρ taken from Example 5 computed exactly, the positions and ρ fields are not used.",
            ).about(&["positions", "rho"]);
        }
        (x, y)
    } else {
        (
            three("positions", &list(inputs, "positions")?)?,
            three("rho", &list(inputs, "rho")?)?,
        )
    };
    let p = parabola_peak(x, y)?;
    parabola_steps(&mut s, x, y, &p);
    let c_max = p.extremum.maximum().map(|a| a[0]);
    s.result = Record::new()
        .with("coefficients", Value::numbers(&p.coefficients))
        .with("c_max", opt(c_max))
        .with("extremum", extremum_name(&p.extremum))
        .with("rho_max", opt(peak_value(&p.extremum)))
        .with("positions", Value::numbers(&x))
        .with("rho", Value::numbers(&y));
    extremum_notes_1d(&mut s, &p, x);

    let printed = parabola_peak([7.0, 8.0, 9.0], [0.69, 0.97, 0.37])?;
    let printed_c = printed.extremum.maximum().map(|a| a[0]);
    if exact_mode {
        if let (Some(ce), Some(cp)) = (c_max, printed_c) {
            s.step(
                Step::new(
                    "How far the peak moves",
                    "The same parabola through the printed ρ (0.69, 0.97, 0.37) peaks elsewhere; the difference is what the printed ρ4 = 0.69 (exact 0.6731) and the rounding cost.",
                )
                .formula(
                    r"\Delta c = c_{\max}^{\text{exact}} - c_{\max}^{\text{printed}}",
                    format!(
                        r"\Delta c = {} - {} = {}\ \text{{px}}",
                        num(ce),
                        num(cp),
                        num(ce - cp)
                    ),
                )
                .value("c_max_printed_rho", cp)
                .value("peak_shift", ce - cp),
            );
            s.result.set("c_max_printed_rho", cp);
            s.result.set("peak_shift", ce - cp);
        }
        s.note(
            NoteKind::Convention,
            "ρ comes from Example 5's arrays computed exactly, not from the values the course notes print; the printed values shown beside are the course notes' answer from their printed ρ.",
        ).about(&["coefficients", "c_max"]);
    }
    let seed = is_seed(&subpixel_1d_fields(), inputs);
    if seed || exact_mode {
        s.textbook = Some(
            Record::new()
                .with("coefficients", Value::numbers(&[-25.91, 6.88, -0.44]))
                .with("c_max", 7.82),
        );
        let (pa, pc) = (printed.coefficients, printed_c.unwrap_or(0.0));
        s.note(
            NoteKind::Rounding,
            format!(
                "From the printed ρ the coefficients are exactly a0 = {}, a1 = {}, a2 = {} and c = {}, which the course notes print as −25.91, 6.88, −0.44 and 7.82.",
                num(pa[0]),
                num(pa[1]),
                num(pa[2]),
                num(pc)
            ),
        ).about(&["coefficients", "c_max"]);
        s.note(
            NoteKind::Erratum,
            "The course notes write the peak condition as 66.8 + (2)(−0.44)c = 0; a1 is 6.88 (66.8 would put the peak at c = 75.9). Their result c = 7.82 is right for 6.88.",
        ).about(&[]);
    }
    if seed {
        let (xe, ye, _) = example_5_exact()?;
        let e = parabola_peak(xe, ye)?;
        if let (Some(ce), Some(cp)) = (e.extremum.maximum(), printed_c) {
            s.note(
                NoteKind::Erratum,
                format!(
                    "These are the printed ρ of Example 5, including ρ4 = 0.69, whose exact value is {} (Example 5). With the exact ρ ({}, {}, {}) the peak is at c = {}, {} px from {}: choose “exact” to chain from Example 5.",
                    num(ye[0]),
                    num(ye[0]),
                    num(ye[1]),
                    num(ye[2]),
                    num(ce[0]),
                    fmt_sig(ce[0] - cp, 2),
                    num(cp)
                ),
            ).about(&["rho"]);
        }
    }
    label_results(&mut s);
    Ok(s)
}

pub(super) fn peak_value(e: &Extremum) -> Option<f64> {
    match e {
        Extremum::Maximum { value, .. } => Some(*value),
        _ => None,
    }
}

pub(super) fn parabola_steps(s: &mut Solution, x: [f64; 3], y: [f64; 3], p: &Parabola) {
    let a: Vec<Vec<f64>> = x.iter().map(|c| vec![1.0, *c, c * c]).collect();
    let eqs: Vec<String> = x
        .iter()
        .zip(&y)
        .map(|(c, r)| {
            format!(
                r"{} = a_0 + a_1 ({}) + a_2 ({})^2",
                num(*r),
                num(*c),
                num(*c)
            )
        })
        .collect();
    s.step(
        Step::new(
            "Three equations",
            "A 2nd-order polynomial ρ(c) = a0 + a1·c + a2·c² through the best ρ and its two neighbours: one equation per position, in matrix form A·X = L.",
        )
        .formula(
            r"\rho_i = a_0 + a_1 c_i + a_2 c_i^2,\quad A X = L",
            format!(
                r"\begin{{aligned}} {} \end{{aligned}}\quad {} \begin{{bmatrix}} a_0 \\ a_1 \\ a_2 \end{{bmatrix}} = {}",
                eqs.join(r" \\ "),
                tex_matrix(&a),
                tex_column(&y)
            ),
        )
        .value("A", Value::matrix(&a))
        .value("L", Value::numbers(&y)),
    );
    s.step(
        Step::new(
            "Coefficients",
            "Three equations, three unknowns: the parabola passes exactly through the three points. (Solved about the middle position with divided differences, which is the same as A⁻¹L but exact for any size of c.)",
        )
        .formula(
            r"X = A^{-1} L",
            format!(
                r"\begin{{bmatrix}} a_0 \\ a_1 \\ a_2 \end{{bmatrix}} = {}",
                tex_column(&p.coefficients)
            ),
        )
        .value("coefficients", Value::numbers(&p.coefficients)),
    );
    let [_, a1, a2] = p.coefficients;
    let (text, sub) = match p.extremum {
        Extremum::Maximum { at, value } => (
            "The slope of the parabola is zero at its maximum (a2 < 0, so it opens downward).".to_string(),
            format!(
                r"{} + 2 ({}) c = 0 \;\Rightarrow\; c = -\frac{{{}}}{{2 \times {}}} = {},\quad \rho_{{\max}} = {}",
                num(a1),
                num(a2),
                num(a1),
                tex(a2),
                num(at[0]),
                num(value)
            ),
        ),
        Extremum::Minimum { at, .. } => (
            "a2 > 0: the parabola opens upward, so its stationary point is a minimum, not a peak. There is no subpixel maximum.".to_string(),
            format!(
                r"a_2 = {} > 0,\quad c_{{\min}} = -\frac{{{}}}{{2 \times {}}} = {}",
                num(a2),
                num(a1),
                tex(a2),
                num(at[0])
            ),
        ),
        _ => (
            "a2 = 0: the three values lie on a straight line, which has no maximum.".to_string(),
            format!(r"a_2 = {} \approx 0", num(a2)),
        ),
    };
    let mut step = Step::new("Location of the maximum", &text)
        .formula(r"\frac{\partial \rho}{\partial c} = a_1 + 2 a_2 c = 0", sub)
        .value("extremum", extremum_name(&p.extremum));
    step = step.value("c_max", opt(p.extremum.maximum().map(|a| a[0])));
    s.step(step);
}

pub(super) fn extremum_notes_1d(s: &mut Solution, p: &Parabola, x: [f64; 3]) {
    match p.extremum {
        Extremum::Maximum { at, .. } => {
            let lo = x.iter().fold(f64::INFINITY, |m, v| m.min(*v));
            let hi = x.iter().fold(f64::NEG_INFINITY, |m, v| m.max(*v));
            if at[0] < lo || at[0] > hi {
                s.note(
                    NoteKind::Warning,
                    format!(
                        "The maximum c = {} lies outside the three positions ({} … {}): it is extrapolated, and the middle value is not the largest; a correlation peak should be bracketed by its neighbours.",
                        num(at[0]),
                        num(lo),
                        num(hi)
                    ),
                ).about(&["c_max"]);
            }
        }
        Extremum::Minimum { .. } => s.note(
            NoteKind::Warning,
            "The fitted parabola opens upward (a2 > 0): its stationary point is a minimum, so there is no subpixel peak and no peak column.",
        ).about(&["c_max", "coefficients"]),
        _ => s.note(
            NoteKind::Warning,
            "The three values lie on a straight line (a2 = 0): the parabola has no maximum, so there is no peak column.",
        ).about(&["c_max", "coefficients"]),
    }
}
