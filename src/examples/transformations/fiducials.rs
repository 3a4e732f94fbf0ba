//! Example 4: the similarity and affine transformations from four fiducial marks (pixels to photo millimetres), with the seed's printed values.

use super::*;

pub(super) fn fiducial_similarity(inputs: &Record) -> Result<Solution> {
    example4(inputs, Model::Similarity)
}

pub(super) fn fiducial_affine(inputs: &Record) -> Result<Solution> {
    example4(inputs, Model::FiducialAffine)
}

pub(super) fn example4(inputs: &Record, model: Model) -> Result<Solution> {
    let rows = Inputs(inputs).rows("points")?;
    let cr = pairs(&rows)?;
    // x' = c, y' = −r: the row axis turned up.
    let pts: Vec<PointPair> = cr
        .iter()
        .map(|p| PointPair {
            u: p.u,
            v: -p.v,
            x: p.x,
            y: p.y,
        })
        .collect();
    let fit = transform::fit(model, &pts)?;
    let (id, title) = if model == Model::Similarity {
        (
            "fiducial-similarity",
            "Fiducials: similarity transformation",
        )
    } else {
        ("fiducial-affine", "Fiducials: affine transformation")
    };
    let mut s = Solution::new(id, title, inputs.clone());

    let table: Vec<String> = pts
        .iter()
        .enumerate()
        .map(|(i, b)| {
            format!(
                r"{} & {} & {} & {} & {}",
                i + 1,
                num(b.u),
                tex(b.v),
                num(b.x),
                num(b.y)
            )
        })
        .collect();
    let (k, cut) = shown(table.len());
    let mut table: Vec<String> = table.into_iter().take(k).collect();
    if cut {
        table.push(r"\vdots & & & &".to_string());
    }
    s.step(
        Step::new(
            "Axes: x′ = c, y′ = −r",
            "The pixel system counts rows r downward, the photo system counts y upward. The design matrices of Example 4 only fit the fiducials with the row axis turned up: x′ = c, y′ = −r. (The photo x axis runs along c, its y axis against r.)",
        )
        .formula(
            r"x' = c,\qquad y' = -r",
            format!(
                r"\begin{{array}}{{c|rr|rr}} \text{{No.}} & x' = c & y' = -r & x & y \\ \hline {} \end{{array}}",
                table.join(r" \\ ")
            ),
        )
        .value("source", Value::matrix(&pts.iter().map(|p| vec![p.u, p.v]).collect::<Vec<_>>()))
        .value("target", Value::matrix(&pts.iter().map(|p| vec![p.x, p.y]).collect::<Vec<_>>()))
        .value("pixel", Value::matrix(&cr.iter().map(|p| vec![p.u, p.v]).collect::<Vec<_>>())),
    );
    adjustment_steps(&mut s, model, &fit, "(x′, y′) = (c, −r)");
    let inverse = inverse_step(&mut s, &fit, pts.first(), "(x′, y′)")?;
    common_result(&mut s, &fit, inverse);
    if let Some((scale, rot)) = scale_rotation(&fit.transform) {
        s.result.set("scale", scale);
        s.result.set("rotation_deg", rot);
    }
    label_results(&mut s, &model.param_names(), "mm");
    s.note(
        NoteKind::Convention,
        "Points are entered as the course notes' table gives them, [c, r, x, y]; the solver turns the row axis up (x′ = c, y′ = −r) before forming A, which is what the printed matrices do. Residuals V = A·X − L (fitted minus given), in mm, in the order of the rows of A: v1 = x of fiducial 1, v2 = y of fiducial 1, …",
    );
    condition_note(&mut s, &fit);
    if is_seed(&fiducial_fields(), inputs) {
        if model == Model::Similarity {
            seed_notes_similarity(&mut s, &fit, &cr)?;
        } else {
            seed_notes_affine(&mut s, &fit, &cr)?;
        }
    }
    Ok(s)
}

/// `A·X − L` for given parameters.
pub(super) fn residuals_with(fit: &Fit, x: &[f64]) -> Vec<f64> {
    fit.a
        .iter()
        .zip(&fit.l)
        .map(|(row, l)| row.iter().zip(x).map(|(a, b)| a * b).sum::<f64>() - l)
        .collect()
}

pub(super) fn max_abs(xs: &[f64]) -> f64 {
    xs.iter().fold(0.0, |m, x| m.max(x.abs()))
}

pub(super) fn round_to(x: f64, decimals: i32) -> f64 {
    let f = 10f64.powi(decimals);
    (x * f).round() / f
}

/// Notes on printed values that are not the exact ones rounded to three
/// decimals: which, and whether two decimals explain them.
pub(super) fn rounding_notes(
    s: &mut Solution,
    what: &str,
    names: &[String],
    exact: &[f64],
    printed: &[f64],
) {
    let mut to_two = Vec::new();
    let mut other = Vec::new();
    let mut fine = Vec::new();
    for ((n, e), p) in names.iter().zip(exact).zip(printed) {
        let d = (e - p).abs();
        if d <= 0.0005 + 1e-12 {
            fine.push(format!("{n} = {} → {:.3}", num(*e), p));
        } else if (round_to(*e, 2) - p).abs() < 1e-9 {
            to_two.push(format!(
                "{n}: printed {:.3}, exact {} ({:.3} to three decimals, {:.2} to two)",
                p,
                num(*e),
                e,
                e
            ));
        } else {
            other.push(format!("{n}: printed {:.3}, exact {}", p, num(*e)));
        }
    }
    if !fine.is_empty() {
        s.note(
            NoteKind::Rounding,
            format!(
                "{} {what} are the exact values rounded to three decimals: {}.",
                if to_two.is_empty() && other.is_empty() {
                    "The printed"
                } else {
                    "The other printed"
                },
                fine.join(", ")
            ),
        )
        .about(&[what]);
    }
    if !to_two.is_empty() {
        s.note(
            NoteKind::Rounding,
            format!(
                "Beyond its printed precision: {}. The course notes rounded these to two decimals and printed a third, zero, decimal that they do not have.",
                to_two.join("; ")
            ),
        ).about(&[what]);
    }
    if !other.is_empty() {
        s.note(
            NoteKind::Erratum,
            format!(
                "These printed values are not the exact ones rounded: {}.",
                other.join("; ")
            ),
        )
        .about(&[what]);
    }
}

pub(super) fn printed_residual_note(s: &mut Solution, fit: &Fit, printed_x: &[f64]) {
    let v = residuals_with(fit, printed_x);
    let a = fit.adjustment.x.first().copied().unwrap_or(0.0);
    s.note(
        NoteKind::Rounding,
        format!(
            "The printed residuals come from the unrounded parameters: with the printed X they would reach {} mm (instead of at most {} mm), because the scale a = {} printed as 0.043 is {} % too {} (of the printed value), which over 5300 pixels is about {} mm. Three decimals are far too few for a scale in mm per pixel; the exact values are given here with seven significant digits.",
            fmt_sig(max_abs(&v), 3),
            fmt_sig(max_abs(&fit.adjustment.v), 2),
            num(a),
            fmt_sig(((a - 0.043) / 0.043 * 100.0).abs(), 2),
            if a > 0.043 { "small" } else { "large" },
            fmt_sig(((0.043 - a) * 5305.0).abs(), 2)
        ),
    ).about(&["residuals"]);
}

pub(super) fn seed_notes_similarity(s: &mut Solution, fit: &Fit, cr: &[PointPair]) -> Result<()> {
    s.textbook = Some(
        Record::new()
            .with("parameters", Value::numbers(&SIM_PRINTED_X))
            .with("residuals", Value::numbers(&SIM_PRINTED_V)),
    );
    // The stated equations with y' = r literally, as the table header says.
    let literal: Vec<PointPair> = cr.to_vec();
    let lit = transform::fit(Model::Similarity, &literal)?;
    let x = &fit.adjustment.x;
    let g = |i: usize| x.get(i).copied().unwrap_or(0.0);
    s.note(
        NoteKind::Erratum,
        format!(
            "The course notes' table heads the pixel columns x′ (c) and y′ (r). Read with y′ = r, their printed matrix has the rows [x′, y′, 1, 0] and [−y′, x′, 0, 1], i.e. x = a·x′ + b·y′ + c, y = b·x′ − a·y′ + d — not its own equations x = a·x′ − b·y′ + c, y = b·x′ + a·y′ + d. The printed rows [c, r, 1, 0] and [−r, c, 0, 1] are exactly the stated equations with y′ = −r: [x′, −y′, 1, 0] and [y′, x′, 0, 1]. So the printed A is the similarity in (x′, y′) = (c, −r) — in (c, r) a scale, a rotation and a reflection of the row axis, which is what pixel → photo needs — and the printed X is its least-squares solution: a = {}, b = {}, c = {}, d = {}. Put y′ = r literally into the stated equations and no similarity fits: σ0 = {} mm, residuals up to {} mm.",
            num(g(0)),
            num(g(1)),
            num(g(2)),
            num(g(3)),
            fmt_sig(lit.adjustment.sigma0.unwrap_or(0.0), 3),
            fmt_sig(max_abs(&lit.adjustment.v), 3)
        ),
    );
    let names = Model::Similarity.param_names();
    rounding_notes(s, "parameters", &names, x, &SIM_PRINTED_X);
    if let Some((_, rot)) = scale_rotation(&fit.transform) {
        s.note(
            NoteKind::Rounding,
            format!(
                "b = {} is printed as 0.000 (its sign lost in the rounding): a rotation of {}° between the scanned photo and the fiducial system.",
                num(g(1)),
                fmt_sig(rot, 2)
            ),
        ).about(&["parameters", "rotation_deg"]);
    }
    printed_residual_note(s, fit, &SIM_PRINTED_X);
    let vnames: Vec<String> = (1..=8).map(|i| format!("v{i}")).collect();
    rounding_notes(s, "residuals", &vnames, &fit.adjustment.v, &SIM_PRINTED_V);
    s.note(
        NoteKind::Convention,
        "The course notes print neither σ0 nor the parameters' precision; they are computed here from the same adjustment (r = 8 − 4 = 4).",
    ).about(&["sigma0", "std_devs"]);
    Ok(())
}

pub(super) fn seed_notes_affine(s: &mut Solution, fit: &Fit, cr: &[PointPair]) -> Result<()> {
    s.textbook = Some(
        Record::new()
            .with("parameters", Value::numbers(&AFF_PRINTED_X))
            .with("residuals", Value::numbers(&AFF_PRINTED_V)),
    );
    let lit = transform::fit(Model::FiducialAffine, cr)?;
    let lx = &lit.adjustment.x;
    let g = |i: usize| lx.get(i).copied().unwrap_or(0.0);
    s.note(
        NoteKind::Convention,
        format!(
            "Here the printed A carries −r in its y′ columns ([c, −r, 1, 0, 0, 0] and [0, 0, 0, c, −r, 1]): y′ = −r is written into the matrix, consistent with the equations x = a·x′ + b·y′ + e, y = c·x′ + d·y′ + f. An affine transformation could absorb the flip itself: with y′ = r it fits just as well (σ0 = {} mm, the same residuals) but b and d change sign (b = {}, d = {}).",
            fmt_sig(lit.adjustment.sigma0.unwrap_or(0.0), 4),
            num(g(1)),
            num(g(4))
        ),
    );
    let names = Model::FiducialAffine.param_names();
    rounding_notes(s, "parameters", &names, &fit.adjustment.x, &AFF_PRINTED_X);
    printed_residual_note(s, fit, &AFF_PRINTED_X);
    let vnames: Vec<String> = (1..=8).map(|i| format!("v{i}")).collect();
    rounding_notes(s, "residuals", &vnames, &fit.adjustment.v, &AFF_PRINTED_V);
    s.note(
        NoteKind::Convention,
        "The course notes print neither σ0 nor the parameters' precision; they are computed here from the same adjustment (r = 8 − 6 = 2).",
    ).about(&["sigma0", "std_devs"]);
    Ok(())
}
