//! Example 9: the subpixel peak of a six-term quadratic surface fitted to 3×3 coefficients.

use super::*;

/// Example 7 computed exactly: the columns, rows and 3×3 ρ around the best.
/// A 3×3 neighbourhood of ρ: its columns, rows and values.
pub(super) type Neighbourhood = ([f64; 3], [f64; 3], [[f64; 3]; 3]);

pub(super) fn example_7_exact() -> Result<(Neighbourhood, (usize, usize))> {
    let t = Grid::from_rows("template", &rows_of(&EX7_TEMPLATE))?;
    let sg = Grid::from_rows("search", &rows_of(&EX7_SEARCH))?;
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

pub(super) const EX9_PRINTED_RHO: [[f64; 3]; 3] = [
    [-0.3334, 0.2394, -0.3921],
    [0.0585, 0.9665, 0.0806],
    [-0.2321, 0.2904, -0.1268],
];

pub(super) fn subpixel_2d(inputs: &Record) -> Result<Solution> {
    let exact_mode = text(inputs, "rho_from")? == "exact";
    let mut s = Solution::new("subpixel-2d", "Subpixel peak in 2-D", inputs.clone());
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
            .formula(
                r"\rho(c, r)",
                tex_matrix(&rows_of(&rho)),
            )
            .value("c", Value::numbers(&c))
            .value("r", Value::numbers(&r))
            .value("rho", Value::matrix(&rows_of(&rho))),
        );
        let defaults = subpixel_2d_fields();
        let changed = ["c", "r", "rho"].iter().any(|k| {
            defaults
                .iter()
                .any(|f| f.key == *k && inputs.get(k) != Some(&f.default))
        });
        if changed {
            s.note(
                NoteKind::Warning,
                "With ρ taken from Example 7 computed exactly, the c, r and ρ fields are not used.",
            )
            .about(&["c", "r", "rho"]);
        }
        (c, r, rho)
    } else {
        let m = rows(inputs, "rho")?;
        let row = |i: usize| -> Result<[f64; 3]> {
            three("rho", m.get(i).map(Vec::as_slice).unwrap_or(&[]))
        };
        (
            three("c", &list(inputs, "c")?)?,
            three("r", &list(inputs, "r")?)?,
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
        .with("rho", Value::matrix(&rows_of(&rho)));
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
                .formula(
                    r"\Delta = \sqrt{(c^{\text{exact}} - c^{\text{printed}})^2 + (r^{\text{exact}} - r^{\text{printed}})^2}",
                    format!(
                        r"\Delta c = {} - {} = {},\quad \Delta r = {} - {} = {},\quad \Delta = {}\ \text{{px}}",
                        num(e[0]),
                        num(p[0]),
                        fmt_sig(e[0] - p[0], 3),
                        num(e[1]),
                        num(p[1]),
                        fmt_sig(e[1] - p[1], 3),
                        fmt_sig(d, 3)
                    ),
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
    let seed = is_seed(&subpixel_2d_fields(), inputs);
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
        if let (Some((rc, rr)), Some(p)) = (from_rounded, printed_at) {
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
    label_results(&mut s);
    Ok(s)
}

/// The stationary point of the seed-form coefficients (for checking the
/// printed answer), if the 2×2 system is regular.
pub(super) fn stationary(a: &[f64; 6]) -> Option<(f64, f64)> {
    let det = 4.0 * a[4] * a[5] - a[3] * a[3];
    if det == 0.0 {
        return None;
    }
    let c = (-a[1] * 2.0 * a[5] + a[2] * a[3]) / det;
    let r = (-a[2] * 2.0 * a[4] + a[1] * a[3]) / det;
    Some((c, r))
}

pub(super) fn quadric_steps(s: &mut Solution, c: [f64; 3], r: [f64; 3], q: &Quadric) {
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
        .formula(
            r"\rho(c, r) = a_0 + a_1 c + a_2 r + a_3 c r + a_4 c^2 + a_5 r^2,\quad A X = L,\quad A_i = [1,\ c_i,\ r_i,\ c_i r_i,\ c_i^2,\ r_i^2]",
            format!(
                r"{} \begin{{bmatrix}} a_0 \\ a_1 \\ a_2 \\ a_3 \\ a_4 \\ a_5 \end{{bmatrix}} = {}",
                tex_matrix(&q.design),
                tex_column(&q.observations)
            ),
        )
        .value("A", Value::matrix(&q.design))
        .value("L", Value::numbers(&q.observations)),
    );
    let adj = &q.adjustment;
    let [cm, rm] = q.centre;
    s.step(
        Step::new(
            "Least squares",
            &format!(
                "In centred coordinates u = c − {}, v = r − {} the normal equations are simple; their solution b gives the same surface. Residuals V = A·X − L show how far the nine ρ are from the fitted surface.",
                num(cm),
                num(rm)
            ),
        )
        .formula(
            r"N = A^T A,\quad X = N^{-1} A^T L,\quad V = A X - L,\quad \sigma_0 = \sqrt{\frac{V^T V}{9 - 6}}",
            format!(
                r"N = {},\quad A^T L = {},\quad b = {},\quad V = {},\quad \sigma_0 = {}",
                tex_matrix(&adj.n),
                tex_column(&adj.atl),
                tex_column(&adj.x),
                tex_list(&adj.v),
                adj.sigma0.map_or_else(|| "-".to_string(), num)
            ),
        )
        .value("N", Value::matrix(&adj.n))
        .value("AtL", Value::numbers(&adj.atl))
        .value("local_coefficients", Value::numbers(&adj.x))
        .value("residuals", Value::numbers(&adj.v))
        .value("sigma0", opt(adj.sigma0))
        .value("centre", Value::numbers(&q.centre)),
    );
    let b = q.local;
    let a = q.coefficients;
    s.step(
        Step::new(
            "Coefficients in c and r",
            "Expanding u = c − c̄ and v = r − r̄ gives the coefficients of the course notes' form.",
        )
        .formula(
            r"a_1 = b_1 - b_3 \bar r - 2 b_4 \bar c,\ a_2 = b_2 - b_3 \bar c - 2 b_5 \bar r,\ a_3 = b_3,\ a_4 = b_4,\ a_5 = b_5,\ a_0 = \rho(0, 0)",
            format!(
                r"a_0 = {},\ a_1 = {},\ a_2 = {},\ a_3 = {},\ a_4 = {},\ a_5 = {}\quad (b_1 = {},\ b_2 = {})",
                num(a[0]),
                num(a[1]),
                num(a[2]),
                num(a[3]),
                num(a[4]),
                num(a[5]),
                num(b[1]),
                num(b[2])
            ),
        )
        .value("coefficients", Value::numbers(&a)),
    );
    let system = format!(
        r"\begin{{bmatrix}} 2 a_4 & a_3 \\ a_3 & 2 a_5 \end{{bmatrix}} = {},\quad \det = 4 a_4 a_5 - a_3^2 = {}",
        tex_matrix(&[vec![2.0 * a[4], a[3]], vec![a[3], 2.0 * a[5]]]),
        num(q.det)
    );
    let (text, sub) = match q.extremum {
        Extremum::Maximum { at, value } => (
            "Both slopes are zero at the maximum. The surface is concave (a4 < 0 and 4·a4·a5 − a3² > 0), so the stationary point is a true maximum.",
            format!(
                r"{system}:\ {} + {} r + 2({}) c = 0,\ {} + {} c + 2({}) r = 0 \;\Rightarrow\; c = {},\ r = {},\ \rho_{{\max}} = {}",
                num(a[1]),
                tex(a[3]),
                num(a[4]),
                num(a[2]),
                tex(a[3]),
                num(a[5]),
                num(at[0]),
                num(at[1]),
                num(value)
            ),
        ),
        Extremum::Minimum { at, .. } => (
            "The surface curves upward in every direction (a4 > 0 and 4·a4·a5 − a3² > 0): the stationary point is a minimum, so there is no subpixel maximum.",
            format!(r"{system},\ \text{{minimum at }} c = {},\ r = {}", num(at[0]), num(at[1])),
        ),
        Extremum::Saddle { at, .. } => (
            "4·a4·a5 − a3² < 0: the surface curves down one way and up the other; the stationary point is a saddle, not a maximum, so there is no subpixel peak.",
            format!(r"{system} < 0,\ \text{{saddle at }} c = {},\ r = {}", num(at[0]), num(at[1])),
        ),
        Extremum::Degenerate => (
            "4·a4·a5 − a3² = 0: the surface is flat in some direction (a ridge or a plane), so it has no single maximum.",
            system,
        ),
    };
    let at = q.extremum.maximum();
    s.step(
        Step::new("Location of the maximum", text)
            .formula(
                r"\frac{\partial \rho}{\partial c} = a_1 + a_3 r + 2 a_4 c = 0,\quad \frac{\partial \rho}{\partial r} = a_2 + a_3 c + 2 a_5 r = 0",
                sub,
            )
            .value("det", q.det)
            .value("extremum", extremum_name(&q.extremum))
            .value("c_max", opt(at.map(|a| a[0])))
            .value("r_max", opt(at.map(|a| a[1]))),
    );
}

pub(super) fn extremum_notes_2d(s: &mut Solution, q: &Quadric, c: [f64; 3], r: [f64; 3]) {
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
