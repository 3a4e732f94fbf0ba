//! Table 9.5.1's models fitted by least squares to any point pairs.

use super::*;

pub(super) fn transform_fit(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let model_id = i.text("model")?;
    let model = Model::from_id(model_id)
        .ok_or_else(|| Error::input("model", format!("\"{model_id}\" is not a model")))?;
    let set = i.text("point_set")?.to_string();
    let rows = match set.as_str() {
        "fiducials" => row_axis_up(&FIDUCIALS),
        "control-12" => {
            let all: Vec<[f64; 4]> = FIDUCIALS.iter().chain(&CHECK_POINTS).copied().collect();
            row_axis_up(&all)
        }
        _ => i.rows("points")?,
    };
    let pts = pairs(&rows)?;
    let fit = transform::fit(model, &pts).map_err(|e| match e {
        Error::InvalidInput { field, reason } if reason.contains("more needed") => {
            Error::InvalidInput {
                field,
                reason: format!(
                    "{reason}; add points in the table or choose the prepared set \"control-12\" (12 points)"
                ),
            }
        }
        other => other,
    })?;
    let mut used = inputs.clone();
    used.set("points", Value::matrix(&rows));
    let mut s = Solution::new(
        "transform-fit",
        "2-D transformations by least squares",
        used,
    );

    let set_text = match set.as_str() {
        "fiducials" => "Example 4's four fiducials (prepared set; the table's points are not used), u = c, v = −r.".to_string(),
        "control-12" => "Example 4's four fiducials and eight check points (prepared set `control-12`; the table's points are not used), u = c, v = −r. The check points are made up for this playground.".to_string(),
        _ => format!("The {} points of the table.", pts.len()),
    };
    s.step(
        Step::new(
            "Model and control points",
            &format!(
                "Table 9.5.1, {}: {} parameters, so at least {} points; {} given. {set_text}",
                model.name(),
                model.n_params(),
                model.min_points(),
                pts.len()
            ),
        )
        .formula(equations_tex(model), String::new())
        .value(
            "source",
            Value::matrix(&pts.iter().map(|p| vec![p.u, p.v]).collect::<Vec<_>>()),
        )
        .value(
            "target",
            Value::matrix(&pts.iter().map(|p| vec![p.x, p.y]).collect::<Vec<_>>()),
        ),
    );
    adjustment_steps(&mut s, model, &fit, "(u, v)");
    let inverse = inverse_step(&mut s, &fit, pts.first(), "(u, v)")?;
    common_result(&mut s, &fit, inverse);
    s.result.set("model", model.id());
    s.result.set("point_set", set.as_str());
    if let Some((scale, rot)) = scale_rotation(&fit.transform) {
        s.result.set("scale", scale);
        s.result.set("rotation_deg", rot);
    }
    s.result
        .set("fitted", Value::matrix(&pairs_to_rows(&fit.fitted)));
    label_results(&mut s, &model.param_names(), "");

    s.note(
        NoteKind::Convention,
        "Table 9.5.1 maps image (u, v) to map (x, y); here (u, v) is any source system and (x, y) any target. Parameters are listed in the table's order; residuals V = A·X − L as [vx1, vy1, vx2, vy2, …]. The default points are Example 4's fiducials with the row axis turned up (u = c, v = −r); with v = r the conformal models (Helmert, second-order conformal) cannot fit, since they allow no reflection.",
    ).about(&["parameter_names"]);
    if model == Model::Projective {
        s.note(
            NoteKind::Convention,
            "Unlike the other models, a shift of every target point by (Δx, Δy) changes more than a3 and a6: x + Δx = (a1·u + a2·v + a3 + Δx·D)/D with D = a7·u + a8·v + 1, so a1 … a6 all take up part of the shift (a1 + Δx·a7, a2 + Δx·a8, a3 + Δx, and likewise for y) while a7 and a8 stay.",
        );
    }
    match model {
        Model::Projective => s.note(
            NoteKind::Erratum,
            "Table 9.5.1 prints the projective denominator as a7·u + a8 + 1. It must be a7·u + a8·v + 1: as printed, a8 + 1 is one constant, the model would have only 7 independent parameters and could not represent a tilt about the u axis. The corrected form is solved here, in its linearised form a1·u + a2·v + a3 − a7·u·x − a8·v·x = x (and likewise for y), which is linear in a1 … a8 and needs no initial values; its residuals V are those of the linearised equations (D·(x̂ − x)), the coordinate residuals x̂ − x are given separately (residuals of the points).",
        ).about(&["parameters", "residuals", "point_residuals"]),
        Model::Polynomial2 | Model::Polynomial3 => s.note(
            NoteKind::Convention,
            "The course notes' polynomial Σᵢ Σⱼ a_ij·u^(i−1)·v^(j−1), i, j = 1 … n (n at most 3), runs over a square of exponents and would include u²v² (and for order 3 up to u³v³). Here a polynomial of order k has every term u^p·v^q with p + q ≤ k (the usual definition): 6 terms per coordinate for k = 2, 10 for k = 3; a_ij multiplies u^(i−1)·v^(j−1) as in the course notes. Coordinates are used as given (not centred or scaled), so that the parameters are the table's; the condition number is reported.",
        ).about(&["parameters"]),
        Model::Helmert => s.note(
            NoteKind::Convention,
            "The table's Helmert transformation x = a·u + b·v + c, y = −b·u + a·v + d is Example 4's similarity with b of the other sign (Example 4: x = a·x′ − b·y′ + c).",
        ).about(&["parameter_names"]),
        _ => {}
    }
    condition_note(&mut s, &fit);

    // Example 4's printed values, in the table's parameter names.
    let fid = row_axis_up(&FIDUCIALS);
    if rows == fid {
        let tb = match model {
            Model::Helmert => Some((
                vec![
                    SIM_PRINTED_X[0],
                    -SIM_PRINTED_X[1],
                    SIM_PRINTED_X[2],
                    SIM_PRINTED_X[3],
                ],
                SIM_PRINTED_V.to_vec(),
                "Example 4(a)",
            )),
            // Same positions: the table's (a, b, c, d, e, f) are Example 4's
            // (a, b, e, c, d, f).
            Model::Affine => Some((
                AFF_PRINTED_X.to_vec(),
                AFF_PRINTED_V.to_vec(),
                "Example 4(b)",
            )),
            _ => None,
        };
        if let Some((x, v, which)) = tb {
            s.textbook = Some(
                Record::new()
                    .with("parameters", Value::numbers(&x))
                    .with("residuals", Value::numbers(&v)),
            );
            s.note(
                NoteKind::Rounding,
                format!(
                    "With Example 4's fiducials this is {which}; its printed values are shown in this table's parameter names and order. See that example for why its shifts (printed −115.030, 115.040 / 115.030) differ from the exact ones beyond their third decimal: they were rounded to two."
                ),
            ).about(&["parameters", "residuals"]);
        }
    }
    Ok(s)
}
