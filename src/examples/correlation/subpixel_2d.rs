//! Example 9: the subpixel peak of a six-term quadratic surface fitted to 3×3 coefficients.

use super::*;
use crate::correlation::{correlate_2d, quadric_peak, stationary, Quadric};
use crate::examples::drill::{
    drill, mat, nums, or_given, rows_of, transpose, value_in, BoxDef, Drill, Mistake, Tolerance,
};
use crate::examples::fields::is_seed;
use crate::solution::{exact_minus_printed, fmt_sig, with_unit, NoteKind, Solution};

pub const EXAMPLE: Example = Example {
    id: "subpixel-2d",
    title: "Subpixel peak in 2-D",
    source: "Worked examples, Example 9",
    summary: "A six-term quadratic surface fitted by least squares to the 3×3 correlation coefficients around the best one, and the location of its maximum.",
    fields,
    solve,
    answer: &["c_max", "r_max"],
    labels: LABELS,
    lab: Some(Lab::new("correlation", &["subpixel"])),
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

fn fields() -> Vec<Field> {
    vec![
        Field::vector("c", "Columns c", (3, 3), &[2.0, 3.0, 4.0])
            .help("The three columns of the neighbourhood (centre pixels in the search array).")
            .when("rho_from", PRINTED),
        Field::vector("r", "Rows r", (3, 3), &[3.0, 4.0, 5.0])
            .help("The three rows of the neighbourhood.")
            .when("rho_from", PRINTED),
        Field::matrix("rho", "Correlation coefficients ρ", &to_rows(&EX9_PRINTED_RHO))
            .shape(3, 3)
            .help("3×3: one row per r, one column per c (the printed values of Example 7).")
            .when("rho_from", PRINTED),
        rho_from_field(
            "“Printed” uses c, r and ρ above; “Exact” takes them from Example 7's arrays computed exactly (the fields above are then not used).",
        ),
    ]
}

/// Example 7 computed exactly: the columns, rows and 3×3 ρ around the best.
/// A 3×3 neighbourhood of ρ: its columns, rows and values.
type Neighbourhood = ([f64; 3], [f64; 3], [[f64; 3]; 3]);

fn example_7_exact() -> Result<(Neighbourhood, (usize, usize))> {
    let t = Grid::from_rows("template", &to_rows(&EX7_TEMPLATE))?;
    let sg = Grid::from_rows("search", &to_rows(&EX7_SEARCH))?;
    let surface = correlate_2d(&t, &sg)?;
    let Some((bc, br)) = surface.best else {
        return Err(Error::input("rho_from", "Example 7 has no best position"));
    };
    if bc == 0 || br == 0 || bc + 1 >= surface.width || br + 1 >= surface.height {
        return Err(Error::input(
            "rho_from",
            "Example 7's best position lies on the edge of the surface",
        ));
    }
    let mut rho = [[0.0; 3]; 3];
    for (i, row) in rho.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = surface.rho(bc + j - 1, br + i - 1).ok_or_else(|| {
                Error::input("rho_from", "Example 7 has a flat window beside its best")
            })?;
        }
    }
    let (hx, hy) = (half(t.width()), half(t.height()));
    let c = |k: usize| k as f64 + 1.0 + hx;
    let r = |k: usize| k as f64 + 1.0 + hy;
    Ok((
        (
            [c(bc - 1), c(bc), c(bc + 1)],
            [r(br - 1), r(br), r(br + 1)],
            rho,
        ),
        (bc, br),
    ))
}

const EX9_PRINTED_RHO: [[f64; 3]; 3] = [
    [-0.3334, 0.2394, -0.3921],
    [0.0585, 0.9665, 0.0806],
    [-0.2321, 0.2904, -0.1268],
];

fn solve(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let exact_mode = i.text("rho_from")? == "exact";
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    let (c, r, rho) = if exact_mode {
        let ((c, r, rho), (bc, br)) = example_7_exact()?;
        s.step(
            Step::new(
                "ρ from Example 7, computed exactly",
                &format!(
                    "Example 7's template and search array give the best position at surface row {}, column {} (centre pixel c = {}, r = {}); its 3×3 neighbourhood of exact coefficients:",
                    br + 1,
                    bc + 1,
                    num(c[1]),
                    num(r[1])
                ),
            )
            .relation(
                Relation::new("c")
                    .key("c")
                    .sym(r"j + \tfrac{n-1}{2}")
                    .result(list_form(&c.map(num))),
            )
            .relation(
                Relation::new("r")
                    .key("r")
                    .sym(r"i + \tfrac{m-1}{2}")
                    .result(list_form(&r.map(num))),
            )
            .relation(
                Relation::new(r"\rho(c, r)")
                    .key("rho")
                    .sym(r"\rho_{ij}")
                    .result(Form::grid("bmatrix", &to_rows(&rho), "ρ")),
            )
            .value("c", Value::numbers(&c))
            .value("r", Value::numbers(&r))
            .value("rho", Value::matrix(&to_rows(&rho))),
        );
        unused_note(
            &mut s,
            &fields(),
            inputs,
            &["c", "r", "rho"],
            "With ρ taken from Example 7 computed exactly, the c, r and ρ fields are not used.",
        );
        (c, r, rho)
    } else {
        let m = i.rows("rho")?;
        let row = |i: usize| -> Result<[f64; 3]> {
            three("rho", m.get(i).map(Vec::as_slice).unwrap_or(&[]))
        };
        (
            three("c", &i.list("c")?)?,
            three("r", &i.list("r")?)?,
            [row(0)?, row(1)?, row(2)?],
        )
    };
    let q = quadric_peak(c, r, rho)?;
    quadric_steps(&mut s, c, r, &q);
    let at = q.extremum.maximum();
    s.result = Record::new()
        .with("coefficients", Value::numbers(&q.coefficients))
        .with("c_max", opt(at.map(|a| a[0])))
        .with("r_max", opt(at.map(|a| a[1])))
        .with("extremum", extremum_name(&q.extremum))
        .with("rho_max", opt(peak_value(&q.extremum)))
        .with("residuals", Value::numbers(&q.adjustment.v))
        .with("sigma0", opt(q.adjustment.sigma0))
        .with("c", Value::numbers(&c))
        .with("r", Value::numbers(&r))
        .with("rho", Value::matrix(&to_rows(&rho)));
    extremum_notes_2d(&mut s, &q, c, r);
    s.note(
        NoteKind::Convention,
        "The least-squares fit is computed in coordinates centred on the middle of the neighbourhood (u = c − c̄, v = r − r̄): the same surface as the course notes' nine equations in c and r, but a well-conditioned system for any c and r. The coefficients are then written in the course notes' form.",
    ).about(&[]);

    let printed = quadric_peak([2.0, 3.0, 4.0], [3.0, 4.0, 5.0], EX9_PRINTED_RHO)?;
    let printed_at = printed.extremum.maximum();
    if exact_mode {
        if let (Some(e), Some(p)) = (at, printed_at) {
            let d = ((e[0] - p[0]).powi(2) + (e[1] - p[1]).powi(2)).sqrt();
            s.step(
                Step::new(
                    "How far the peak moves",
                    "The same fit to the printed ρ (four decimals) peaks at a slightly different place; the difference is what rounding the coefficients of Example 7 costs.",
                )
                .relation(
                    Relation::new(r"\Delta c")
                        .sym(r"c^{\text{exact}} - c^{\text{printed}}")
                        .subst(format!("{} - {}", num(e[0]), tex(p[0])))
                        .result(with_unit(&fmt_sig(e[0] - p[0], 3), "px")),
                )
                .relation(
                    Relation::new(r"\Delta r")
                        .sym(r"r^{\text{exact}} - r^{\text{printed}}")
                        .subst(format!("{} - {}", num(e[1]), tex(p[1])))
                        .result(with_unit(&fmt_sig(e[1] - p[1], 3), "px")),
                )
                .relation(
                    Relation::new(r"\Delta")
                        .key("peak_shift")
                        .sym(r"\sqrt{\Delta c^2 + \Delta r^2}")
                        .result(with_unit(&fmt_sig(d, 3), "px")),
                )
                .value("c_max_printed_rho", p[0])
                .value("r_max_printed_rho", p[1])
                .value("peak_shift", d),
            );
            s.result.set("c_max_printed_rho", p[0]);
            s.result.set("r_max_printed_rho", p[1]);
            s.result.set("peak_shift", d);
        }
        s.note(
            NoteKind::Convention,
            "ρ comes from Example 7's arrays computed exactly, not from the four-decimal values the course notes print; the printed values shown beside are the course notes' answer from their printed ρ.",
        ).about(&["coefficients", "c_max", "r_max"]);
    }
    let seed = is_seed(&fields(), inputs);
    if seed || exact_mode {
        let pc = [-12.297, 3.785, 3.634, 0.041, -0.656, -0.461];
        s.textbook = Some(
            Record::new()
                .with("coefficients", Value::numbers(&pc))
                .with("c_max", 3.012)
                .with("r_max", 4.075),
        );
        let from_rounded = stationary(&pc);
        let pa = printed.coefficients;
        s.note(
            NoteKind::Rounding,
            format!(
                "From the printed ρ the least-squares coefficients are a0 = {}, a1 = {}, a2 = {}, a3 = {}, a4 = {}, a5 = {}: the course notes' values to three decimals.",
                num(pa[0]),
                num(pa[1]),
                num(pa[2]),
                num(pa[3]),
                num(pa[4]),
                num(pa[5])
            ),
        ).about(&["coefficients"]);
        if let (Some([rc, rr]), Some(p)) = (from_rounded, printed_at) {
            s.note(
                NoteKind::Rounding,
                format!(
                    "The course notes' c = 3.012 and r = 4.075 come from their coefficients rounded to three decimals (they give c = {}, r = {}). From the unrounded coefficients the maximum is at c = {}, r = {}, which to three decimals is {}, {} (c: {}; r: {}): about {} px from the printed point, beyond its three decimals.",
                    fmt_sig(rc, 5),
                    fmt_sig(rr, 5),
                    num(p[0]),
                    num(p[1]),
                    format_args!("{:.3}", p[0]),
                    format_args!("{:.3}", p[1]),
                    exact_minus_printed(p[0], 3.012, "px"),
                    exact_minus_printed(p[1], 4.075, "px"),
                    fmt_sig(((p[0] - 3.012).powi(2) + (p[1] - 4.075).powi(2)).sqrt(), 1)
                ),
            ).about(&["c_max", "r_max"]);
        }
    }
    if seed {
        s.note(
            NoteKind::Erratum,
            "The course notes' third equation is labelled ρ(3+1, 4+1) and written with c = 4, r = 5, but its value −0.3921 is ρ at c = 4, r = 3, the upper right neighbour: it should read ρ(3+1, 4−1) = a0 + a1(4) + a2(3) + a3(4)(3) + a4(4)² + a5(3)². The ninth equation is the real ρ(3+1, 4+1) = −0.1268. The course notes' coefficients fit the corrected equation (see the coefficients above), so only the label and the written terms are wrong; this solution uses the corrected one.",
        ).about(&[]);
        let ((ce, re, rhoe), _) = example_7_exact()?;
        let e = quadric_peak(ce, re, rhoe)?;
        if let (Some(ea), Some(pa)) = (e.extremum.maximum(), printed_at) {
            let d = ((ea[0] - pa[0]).powi(2) + (ea[1] - pa[1]).powi(2)).sqrt();
            s.note(
                NoteKind::Convention,
                format!(
                    "These ρ are Example 7's values as printed to four decimals. With the exact coefficients of Example 7 the maximum is at c = {}, r = {}, {} px away: choose “exact” to chain from Example 7.",
                    num(ea[0]),
                    num(ea[1]),
                    fmt_sig(d, 2)
                ),
            ).about(&["rho"]);
        }
    }
    Ok(s)
}

fn quadric_steps(s: &mut Solution, c: [f64; 3], r: [f64; 3], q: &Quadric) {
    let first = q.design.first().cloned().unwrap_or_default();
    let at = |k: usize| first.get(k).copied().unwrap_or(0.0);
    s.step(
        Step::new(
            "Nine equations",
            &format!(
                "The surface ρ = a0 + a1·c + a2·r + a3·c·r + a4·c² + a5·r² at the best position and its 8 neighbours (c = {}, {}, {}; r = {}, {}, {}): nine equations for six unknowns, one row of A per (c, r) in reading order (r = {} first), solved by least squares.",
                num(c[0]),
                num(c[1]),
                num(c[2]),
                num(r[0]),
                num(r[1]),
                num(r[2]),
                num(r[0])
            ),
        )
        .relation(
            Relation::new(r"\rho(c, r)").sym(Form::terms([
                "a_0",
                "+ a_1 c",
                "+ a_2 r",
                "+ a_3 c r",
                "+ a_4 c^2",
                "+ a_5 r^2",
            ])),
        )
        .relation(
            Relation::new(r"\rho_1")
                .subst(Form::terms([
                    "a_0".to_string(),
                    format!("+ a_1 ({})", num(at(1))),
                    format!("+ a_2 ({})", num(at(2))),
                    format!("+ a_3 ({})({})", num(at(1)), num(at(2))),
                    format!("+ a_4 ({})^2", num(at(1))),
                    format!("+ a_5 ({})^2", num(at(2))),
                ]))
                .value(q.observations.first().copied().unwrap_or(0.0), ""),
        )
        .relation(
            Relation::new("A X")
                .sym("L")
                .subst(Form::grid("bmatrix", &q.design, "A").then(unknowns(6, "X")))
                .result(Form::column(&q.observations, "L")),
        )
        .value("A", Value::matrix(&q.design))
        .value("L", Value::numbers(&q.observations)),
    );
    let adj = &q.adjustment;
    let [cm, rm] = q.centre;
    let sigma0 = Relation::new(r"\sigma_0")
        .key("sigma0")
        .sym(r"\sqrt{\frac{V^T V}{9 - 6}}")
        .subst(format!(r"\sqrt{{\frac{{{}}}{{3}}}}", num(adj.vtpv)));
    let sigma0 = match adj.sigma0 {
        Some(x) => sigma0.value(x, ""),
        None => sigma0.result("-"),
    };
    s.step(
        Step::new(
            "Least squares",
            &format!(
                "In centred coordinates u = c − {}, v = r − {} the normal equations are simple; their solution b gives the same surface. Residuals V = A·X − L show how far the nine ρ are from the fitted surface.",
                num(cm),
                num(rm)
            ),
        )
        .relation(
            Relation::new("N")
                .key("N")
                .sym("A^T A")
                .result(Form::grid("bmatrix", &adj.n, "N")),
        )
        .relation(
            Relation::new("A^T L")
                .key("AtL")
                .result(Form::column(&adj.atl, "AᵀL")),
        )
        .relation(
            Relation::new("b")
                .key("local_coefficients")
                .sym(r"N^{-1} A^T L")
                .subst(
                    Form::grid("bmatrix", &adj.n, "N")
                        .then("^{-1}")
                        .then(Form::column(&adj.atl, "AᵀL")),
                )
                .result(Form::column(&adj.x, "b")),
        )
        .relation(
            Relation::new("V")
                .key("residuals")
                .sym("A X - L")
                .result(list_form(&adj.v.iter().map(|v| num(*v)).collect::<Vec<_>>())),
        )
        .relation(sigma0)
        .value("N", Value::matrix(&adj.n))
        .value("AtL", Value::numbers(&adj.atl))
        .value("local_coefficients", Value::numbers(&adj.x))
        .value("residuals", Value::numbers(&adj.v))
        .value("sigma0", opt(adj.sigma0))
        .value("centre", Value::numbers(&q.centre)),
    );
    let b = q.local;
    let a = q.coefficients;
    let plain = |k: usize| {
        Relation::new(format!("a_{k}"))
            .sym(format!("b_{k}"))
            .value(a[k], "")
    };
    s.step(
        Step::new(
            "Coefficients in c and r",
            "Expanding u = c − c̄ and v = r − r̄ gives the coefficients of the course notes' form.",
        )
        .relation(
            Relation::new("a_1")
                .sym(r"b_1 - b_3 \bar r - 2 b_4 \bar c")
                .subst(format!(
                    r"{} - {} \cdot {} - 2 \cdot {} \cdot {}",
                    num(b[1]),
                    tex(b[3]),
                    num(rm),
                    tex(b[4]),
                    num(cm)
                ))
                .value(a[1], ""),
        )
        .relation(
            Relation::new("a_2")
                .sym(r"b_2 - b_3 \bar c - 2 b_5 \bar r")
                .subst(format!(
                    r"{} - {} \cdot {} - 2 \cdot {} \cdot {}",
                    num(b[2]),
                    tex(b[3]),
                    num(cm),
                    tex(b[5]),
                    num(rm)
                ))
                .value(a[2], ""),
        )
        .relation(plain(3))
        .relation(plain(4))
        .relation(plain(5))
        .relation(
            Relation::new("a_0")
                .key("coefficients")
                .sym(r"\rho(0, 0)")
                .value(a[0], ""),
        )
        .value("coefficients", Value::numbers(&a)),
    );
    let hessian = Relation::new(Form::grid_tex(
        "bmatrix",
        vec![
            vec!["2 a_4".to_string(), "a_3".to_string()],
            vec!["a_3".to_string(), "2 a_5".to_string()],
        ],
        "",
    ))
    .result(Form::grid(
        "bmatrix",
        &[vec![2.0 * a[4], a[3]], vec![a[3], 2.0 * a[5]]],
        "",
    ));
    let det = Relation::new(r"\det")
        .key("det")
        .sym(r"4 a_4 a_5 - a_3^2")
        .subst(Form::terms([
            format!(r"4 \cdot {} \cdot {}", tex(a[4]), tex(a[5])),
            format!("- {}^2", tex(a[3])),
        ]))
        .value(q.det, "");
    let slope = |lhs: &str, sym: &str, terms: [String; 3]| {
        Relation::new(lhs)
            .sym(sym)
            .sym("0")
            .subst(Form::terms(terms))
            .result("0")
    };
    let slope_c = slope(
        r"\frac{\partial \rho}{\partial c}",
        "a_1 + a_3 r + 2 a_4 c",
        [
            num(a[1]),
            format!("+ {} r", tex(a[3])),
            format!("+ 2 {} c", tex(a[4])),
        ],
    );
    let slope_r = slope(
        r"\frac{\partial \rho}{\partial r}",
        "a_2 + a_3 c + 2 a_5 r",
        [
            num(a[2]),
            format!("+ {} c", tex(a[3])),
            format!("+ 2 {} r", tex(a[5])),
        ],
    );
    // c = N_c / det and r = N_r / det (Cramer's rule), the numerators first
    // so that no long fraction has to fit a line
    let n_c = a[2] * a[3] - 2.0 * a[1] * a[5];
    let n_r = a[1] * a[3] - 2.0 * a[2] * a[4];
    let numerators = [
        Relation::new("N_c")
            .sym("a_2 a_3 - 2 a_1 a_5")
            .subst(Form::terms([
                format!(r"{} \cdot {}", num(a[2]), tex(a[3])),
                format!(r"- 2 \cdot {} \cdot {}", tex(a[1]), tex(a[5])),
            ]))
            .value(n_c, ""),
        Relation::new("N_r")
            .sym("a_1 a_3 - 2 a_2 a_4")
            .subst(Form::terms([
                format!(r"{} \cdot {}", num(a[1]), tex(a[3])),
                format!(r"- 2 \cdot {} \cdot {}", tex(a[2]), tex(a[4])),
            ]))
            .value(n_r, ""),
    ];
    let point = |c_name: &str, r_name: &str, at: [f64; 2], keyed: bool| {
        let (rc, rr) = (Relation::new(c_name), Relation::new(r_name));
        let (rc, rr) = if keyed {
            (rc.key("c_max"), rr.key("r_max"))
        } else {
            (rc, rr)
        };
        let quotient = |n: f64| format!(r"\frac{{{}}}{{{}}}", num(n), num(q.det));
        numerators.clone().into_iter().chain([
            rc.sym(r"\frac{N_c}{\det}")
                .subst(quotient(n_c))
                .value(at[0], "px"),
            rr.sym(r"\frac{N_r}{\det}")
                .subst(quotient(n_r))
                .value(at[1], "px"),
        ])
    };
    let (text, rels): (&str, Vec<Relation>) = match q.extremum {
        Extremum::Maximum { at, value } => (
            "Both slopes are zero at the maximum. The surface is concave (a4 < 0 and 4·a4·a5 − a3² > 0), so the stationary point is a true maximum.",
            point("c", "r", at, true).chain([Relation::new(r"\rho_{\max}")
                    .key("rho_max")
                    .value(value, "")])
                .collect(),
        ),
        Extremum::Minimum { at, .. } => (
            "The surface curves upward in every direction (a4 > 0 and 4·a4·a5 − a3² > 0): the stationary point is a minimum, so there is no subpixel maximum.",
            point(r"c_{\min}", r"r_{\min}", at, false).collect(),
        ),
        Extremum::Saddle { at, .. } => (
            "4·a4·a5 − a3² < 0: the surface curves down one way and up the other; the stationary point is a saddle, not a maximum, so there is no subpixel peak.",
            std::iter::once(Relation::new(r"\det").op("<").result("0"))
                .chain(point(r"c_{\text{saddle}}", r"r_{\text{saddle}}", at, false))
                .collect(),
        ),
        Extremum::Degenerate => (
            "4·a4·a5 − a3² = 0: the surface is flat in some direction (a ridge or a plane), so it has no single maximum.",
            Vec::new(),
        ),
    };
    let at = q.extremum.maximum();
    let step = Step::new("Location of the maximum", text)
        .relations([slope_c, slope_r, hessian, det])
        .relations(rels);
    s.step(
        step.value("det", q.det)
            .value("extremum", extremum_name(&q.extremum))
            .value("c_max", opt(at.map(|a| a[0])))
            .value("r_max", opt(at.map(|a| a[1]))),
    );
}

fn extremum_notes_2d(s: &mut Solution, q: &Quadric, c: [f64; 3], r: [f64; 3]) {
    let span = |x: [f64; 3]| {
        (
            x.iter().fold(f64::INFINITY, |m, v| m.min(*v)),
            x.iter().fold(f64::NEG_INFINITY, |m, v| m.max(*v)),
        )
    };
    match q.extremum {
        Extremum::Maximum { at, .. } => {
            let ((c0, c1), (r0, r1)) = (span(c), span(r));
            if at[0] < c0 || at[0] > c1 || at[1] < r0 || at[1] > r1 {
                s.note(
                    NoteKind::Warning,
                    format!(
                        "The maximum (c, r) = ({}, {}) lies outside the 3×3 neighbourhood: it is extrapolated, and the centre value is probably not the largest.",
                        num(at[0]),
                        num(at[1])
                    ),
                ).about(&["c_max", "r_max"]);
            }
        }
        Extremum::Minimum { .. } => s.note(
            NoteKind::Warning,
            "The fitted surface is not concave: it curves upward, its stationary point is a minimum, so there is no subpixel peak (no peak column or row).",
        ).about(&["c_max", "r_max", "coefficients"]),
        Extremum::Saddle { .. } => s.note(
            NoteKind::Warning,
            "The fitted surface is not concave: 4·a4·a5 − a3² < 0 makes its stationary point a saddle, so there is no subpixel peak (no peak column or row).",
        ).about(&["c_max", "r_max", "coefficients"]),
        Extremum::Degenerate => s.note(
            NoteKind::Warning,
            "The fitted surface is not concave: 4·a4·a5 − a3² = 0 (flat in some direction), so it has no single maximum (no peak column or row).",
        ).about(&["c_max", "r_max", "coefficients"]),
    }
}

// ---------------------------------------------------------------- practice

fn generate(rng: &mut Rng) -> Record {
    let (k, m) = (rng.num(3, 30), rng.num(3, 30));
    let alpha = rng.num(8, 25) / 100.0;
    let beta = rng.num(8, 25) / 100.0;
    let dc = rng.num(-35, 35) / 100.0;
    let mut dr = rng.num(-35, 35) / 100.0;
    if (dr - dc).abs() < 0.1 {
        dr = if dc > 0.0 { dc - 0.3 } else { dc + 0.3 };
    }
    let peak = rng.num(85, 97) / 100.0;
    let rho: Vec<Vec<f64>> = (-1..=1)
        .map(|r| {
            (-1..=1)
                .map(|c| {
                    let v = peak - alpha * (c as f64 - dc).powi(2) - beta * (r as f64 - dr).powi(2);
                    (v * 100.0).round() / 100.0
                })
                .collect()
        })
        .collect();
    Record::new()
        .with("c", nums(&[k - 1.0, k, k + 1.0]))
        .with("r", nums(&[m - 1.0, m, m + 1.0]))
        .with("rho", mat(&rho))
}

/// The centred coefficients b₁ … b₅ (u = c − c̄, v = r − r̄) that the peak
/// follows from: four decimals are plenty.
const LOCAL: Tolerance = Tolerance::abs(0.0005);

fn boxes(_: &Record) -> Vec<BoxDef> {
    let t = Tolerance::abs(0.01);
    let fit = "Fit ρ = b₀ + b₁u + b₂v + b₃uv + b₄u² + b₅v² by least squares in the centred coordinates u = c − c̄, v = r − r̄ (each −1, 0 or 1): the normal equations nearly separate.";
    vec![
        BoxDef::new("local_coefficients[2]", "b₁ (u)", None, LOCAL)
            .nudge("Σ u·ρ over Σ u²: the right column minus the left, over 6.")
            .axis(),
        BoxDef::new("local_coefficients[3]", "b₂ (v)", None, LOCAL)
            .nudge("Σ v·ρ over Σ v²: the bottom row minus the top, over 6.")
            .axis(),
        BoxDef::new("local_coefficients[4]", "b₃ (uv)", None, LOCAL)
            .nudge("Σ uv·ρ over Σ u²v²: the four corners, over 4."),
        BoxDef::new("local_coefficients[5]", "b₄ (u²)", None, LOCAL).nudge(fit),
        BoxDef::new("local_coefficients[6]", "b₅ (v²)", None, LOCAL).nudge(fit),
        BoxDef::new("c_max", "Peak column c_max", Some("px"), t).nudge(
            "Both slopes zero: b₁ + b₃v + 2b₄u = 0 and b₂ + b₃u + 2b₅v = 0; then c = c̄ + u.",
        ),
        BoxDef::new("r_max", "Peak row r_max", Some("px"), t)
            .nudge("Solve the two derivative equations together; r = r̄ + v."),
    ]
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = EXAMPLE.run(i)?;
    let mut out = Record::new();
    let mut b = [0.0; 6];
    for (k, bk) in b.iter_mut().enumerate().skip(1) {
        let key = format!("local_coefficients[{}]", k + 1);
        *bk = or_given(g, &key, value_in(&s, &key)?);
        out.set(&key, *bk);
    }
    let (cc, rc) = (value_in(&s, "centre[1]")?, value_in(&s, "centre[2]")?);
    // the stationary point of the centred surface (b₀ does not matter)
    let [u, v] = stationary(&b).unwrap_or([f64::NAN, f64::NAN]);
    Ok(out
        .with("c_max", or_given(g, "c_max", cc + u))
        .with("r_max", or_given(g, "r_max", rc + v)))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let swapped = i.clone().with("rho", mat(&transpose(&rows_of(i, "rho"))));
    let s = EXAMPLE.run(&swapped)?;
    const SWAP: &str = "The rows of the ρ table are the rows r; its columns are the columns c.";
    let mut out = Vec::new();
    for k in [2, 3] {
        let key = format!("local_coefficients[{k}]");
        out.push(Mistake::new(
            &key,
            "rows and columns swapped",
            SWAP,
            value_in(&s, &key)?,
        ));
    }
    for key in ["c_max", "r_max"] {
        out.push(Mistake::new(
            key,
            "rows and columns swapped",
            SWAP,
            s.result.number(key).unwrap_or(f64::NAN),
        ));
    }
    Ok(out)
}
