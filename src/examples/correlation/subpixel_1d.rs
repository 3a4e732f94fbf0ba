//! Example 8: the subpixel peak of a parabola through three correlation coefficients.

use super::*;
use crate::correlation::{correlate_1d, parabola_peak, Extremum, Parabola};
use crate::examples::drill::Tolerance;
use crate::examples::drill::{drill, list, nums, or_given, tol, value_in, BoxDef, Drill, Mistake};
use crate::examples::fields::is_seed;
use crate::solution::{fmt_sig, NoteKind, Solution};

pub const EXAMPLE: Example = Example {
    id: "subpixel-1d",
    title: "Subpixel peak in 1-D",
    source: "Worked examples, Example 8",
    summary: "A parabola through the best correlation coefficient and its two neighbours, and the location of its maximum.",
    fields,
    solve,
    answer: &["c_max"],
    labels: LABELS,
    lab: None,
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

fn fields() -> Vec<Field> {
    vec![
        Field::vector("positions", "Positions c", (3, 3), &[7.0, 8.0, 9.0])
            .help("Centre columns of the best sub-window and its two neighbours.")
            .when("rho_from", PRINTED),
        Field::vector("rho", "Correlation coefficients ρ", (3, 3), &[0.69, 0.97, 0.37])
            .help("ρ at the three positions (the printed values of Example 5).")
            .when("rho_from", PRINTED),
        rho_from_field(
            "“Printed” uses the positions and ρ above; “Exact” takes them from Example 5's arrays computed exactly (the fields above are then not used).",
        ),
    ]
}

/// Example 5 computed exactly: positions (sub-window centres) and ρ of the
/// best sub-window and its two neighbours, and the best index.
fn example_5_exact() -> Result<([f64; 3], [f64; 3], usize)> {
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

fn solve(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let exact_mode = i.text("rho_from")? == "exact";
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
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
            .relation(
                Relation::new("c")
                    .key("positions")
                    .sym(r"k + \tfrac{n - 1}{2}")
                    .result(list_form(&x.map(num))),
            )
            .relation(
                Relation::new(r"\rho")
                    .key("rho")
                    .sym(r"\rho_k")
                    .result(list_form(&y.map(num))),
            )
            .value("positions", Value::numbers(&x))
            .value("rho", Value::numbers(&y)),
        );
        unused_note(
            &mut s,
            &fields(),
            inputs,
            &["positions", "rho"],
            "With ρ taken from Example 5 computed exactly, the positions and ρ fields are not used.",
        );
        (x, y)
    } else {
        (
            three("positions", &i.list("positions")?)?,
            three("rho", &i.list("rho")?)?,
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
                .relation(
                    Relation::new(r"\Delta c")
                        .key("peak_shift")
                        .sym(r"c_{\max}^{\text{exact}} - c_{\max}^{\text{printed}}")
                        .subst(format!("{} - {}", num(ce), tex(cp)))
                        .value(ce - cp, "px"),
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
    let seed = is_seed(&fields(), inputs);
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
    Ok(s)
}

fn parabola_steps(s: &mut Solution, x: [f64; 3], y: [f64; 3], p: &Parabola) {
    let a: Vec<Vec<f64>> = x.iter().map(|c| vec![1.0, *c, c * c]).collect();
    let mut step = Step::new(
        "Three equations",
        "A 2nd-order polynomial ρ(c) = a0 + a1·c + a2·c² through the best ρ and its two neighbours: one equation per position, in matrix form A·X = L.",
    );
    step = step.relation(Relation::new(r"\rho_i").sym(r"a_0 + a_1 c_i + a_2 c_i^2"));
    for (k, (c, r)) in x.iter().zip(&y).enumerate() {
        step = step.relation(
            Relation::new(format!(r"\rho_{}", k + 1))
                .subst(format!(r"a_0 + a_1 ({}) + a_2 ({})^2", num(*c), num(*c)))
                .value(*r, ""),
        );
    }
    s.step(
        step.relation(
            Relation::new("A X")
                .sym("L")
                .subst(Form::grid("bmatrix", &a, "A").then(unknowns(3, "X")))
                .result(Form::column(&y, "L")),
        )
        .value("A", Value::matrix(&a))
        .value("L", Value::numbers(&y)),
    );
    s.step(
        Step::new(
            "Coefficients",
            "Three equations, three unknowns: the parabola passes exactly through the three points. (Solved about the middle position with divided differences, which is the same as A⁻¹L but exact for any size of c.)",
        )
        .relation(
            Relation::new("X")
                .key("coefficients")
                .sym(r"A^{-1} L")
                .subst(
                    Form::grid("bmatrix", &a, "A")
                        .then("^{-1}")
                        .then(Form::column(&y, "L")),
                )
                .result(Form::column(&p.coefficients, "X")),
        )
        .value("coefficients", Value::numbers(&p.coefficients)),
    );
    let [a0, a1, a2] = p.coefficients;
    let slope = Relation::new(r"\frac{\partial \rho}{\partial c}")
        .sym("a_1 + 2 a_2 c")
        .sym("0")
        .subst(format!("{} + 2 {} c", num(a1), tex(a2)))
        .result("0");
    let quotient = format!(r"-\frac{{{}}}{{2 \times {}}}", num(a1), tex(a2));
    let (text, rels) = match p.extremum {
        Extremum::Maximum { at: c, value } => (
            "The slope of the parabola is zero at its maximum (a2 < 0, so it opens downward).",
            vec![
                Relation::new("c")
                    .key("c_max")
                    .sym(r"-\frac{a_1}{2 a_2}")
                    .subst(quotient.as_str())
                    .value(c[0], "px"),
                Relation::new(r"\rho_{\max}")
                    .key("rho_max")
                    .sym(r"a_0 + a_1 c + a_2 c^2")
                    .subst(Form::terms([
                        num(a0),
                        format!(r"+ {} \cdot {}", tex(a1), num(c[0])),
                        format!(r"+ {} \cdot {}^2", tex(a2), num(c[0])),
                    ]))
                    .value(value, ""),
            ],
        ),
        Extremum::Minimum { at: c, .. } => (
            "a2 > 0: the parabola opens upward, so its stationary point is a minimum, not a peak. There is no subpixel maximum.",
            vec![
                Relation::new("a_2").value(a2, ""),
                Relation::new(r"c_{\min}")
                    .sym(r"-\frac{a_1}{2 a_2}")
                    .subst(quotient.as_str())
                    .value(c[0], "px"),
            ],
        ),
        _ => (
            "a2 = 0: the three values lie on a straight line, which has no maximum.",
            vec![Relation::new("a_2")
                .op(r"\approx")
                .subst(num(a2))
                .result("0")],
        ),
    };
    let step = Step::new("Location of the maximum", text)
        .relation(slope)
        .relations(rels);
    s.step(
        step.value("extremum", extremum_name(&p.extremum))
            .value("c_max", opt(p.extremum.maximum().map(|a| a[0]))),
    );
}

fn extremum_notes_1d(s: &mut Solution, p: &Parabola, x: [f64; 3]) {
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

// ---------------------------------------------------------------- practice

fn generate(rng: &mut Rng) -> Record {
    let k = rng.num(4, 30);
    let mid = rng.num(80, 99);
    let left = mid - rng.num(3, 40);
    let mut right = mid - rng.num(3, 40);
    if right == left {
        right -= 2.0;
    }
    Record::new()
        .with("positions", nums(&[k - 1.0, k, k + 1.0]))
        .with("rho", nums(&[left / 100.0, mid / 100.0, right / 100.0]))
}

fn boxes(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("coefficients[1]", "a₀", None, tol::PARAM).nudge(
            "Put the three (c, ρ) pairs into ρ = a₀ + a₁c + a₂c² and solve the three equations.",
        ),
        BoxDef::new("coefficients[2]", "a₁", None, tol::PARAM).nudge("The linear coefficient."),
        BoxDef::new("coefficients[3]", "a₂", None, tol::PARAM)
            .nudge("The quadratic coefficient: negative for a peak."),
        BoxDef::new(
            "c_max",
            "Peak position c_max",
            Some("px"),
            Tolerance::abs(0.005),
        )
        .nudge("Where the derivative a₁ + 2a₂c is zero."),
    ]
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = EXAMPLE.run(i)?;
    let co = |k: usize| -> Result<f64> {
        let key = format!("coefficients[{k}]");
        Ok(or_given(g, &key, value_in(&s, &key)?))
    };
    let (a0, a1, a2) = (co(1)?, co(2)?, co(3)?);
    Ok(Record::new()
        .with("coefficients[1]", a0)
        .with("coefficients[2]", a1)
        .with("coefficients[3]", a2)
        .with("c_max", or_given(g, "c_max", -a1 / (2.0 * a2))))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let v = chain(i, &Record::new())?;
    let (a1, a2) = (
        v.number("coefficients[2]").unwrap_or(f64::NAN),
        v.number("coefficients[3]").unwrap_or(f64::NAN),
    );
    let c_max = -a1 / (2.0 * a2);
    // the middle position: where the offset is measured from
    let k = list(i, "positions").get(1).copied().unwrap_or(f64::NAN);
    Ok(vec![
        Mistake::new(
            "c_max",
            "sign lost in −a₁/(2a₂)",
            "Setting a₁ + 2a₂c = 0 gives c = −a₁ / (2a₂).",
            a1 / (2.0 * a2),
        ),
        Mistake::new(
            "coefficients[3]",
            "½ forgotten in a₂",
            "The second difference ρ₋ − 2ρ₀ + ρ₊ is 2a₂ (with positions one pixel apart): halve it.",
            2.0 * a2,
        ),
        Mistake::new(
            "c_max",
            "the offset, not the position",
            "The parabola's peak is an offset from the middle position: add it to that position.",
            c_max - k,
        ),
        Mistake::new(
            "c_max",
            "offset the wrong way",
            "The peak lies on the side of the larger neighbour: c_max − c₀ has the sign of ρ₊ − ρ₋.",
            2.0 * k - c_max,
        ),
    ])
}
