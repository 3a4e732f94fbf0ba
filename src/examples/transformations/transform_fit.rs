//! Table 9.5.1's models fitted by least squares to any point pairs; and its
//! practice: a Helmert or affine fit to a few drawn points.

use super::*;
use crate::examples::drill::{drill, Drill, Rng};

pub const EXAMPLE: Example = Example {
    id: "transform-fit",
    title: "2-D transformations by least squares",
    source: "Lecture 7: Image processing, Table 9.5.1",
    summary: "Any model of the transform table — Helmert, affine, pseudo-affine, projective, second-order conformal, polynomials — fitted to your control points.",
    fields,
    solve,
    answer: &["parameters", "sigma0"],
    labels: &[],
    lab: None,
    practice: drill(Drill::new(generate, boxes, Some(|i, g| chain_sigma0(&EXAMPLE, i, g)), mistakes)),
};

const MODELS: &[(&str, &str)] = &[
    ("helmert", "1) Helmert (4 parameters)"),
    ("affine", "2) Affine (6)"),
    ("pseudo-affine", "3) Pseudo-affine (8)"),
    ("projective", "4) Projective (8)"),
    ("conformal-2", "5) Second-order conformal (6)"),
    ("polynomial-2", "6) Polynomial, order 2 (12)"),
    ("polynomial-3", "6) Polynomial, order 3 (20)"),
];

const POINT_SETS: &[(&str, &str)] = &[
    ("table", "The points in the table"),
    ("fiducials", "Example 4's four fiducials"),
    (
        "control-12",
        "Fiducials + 8 check points (12, enough for every model)",
    ),
];

fn fields() -> Vec<Field> {
    vec![
        Field::choice("model", "Model (Table 9.5.1)", MODELS, "helmert")
            .help("The transformation x = f(u, v), y = g(u, v); the number is how many parameters it has. Each point gives two equations."),
        Field::choice("point_set", "Control points", POINT_SETS, "table")
            .help("\"The points in the table\" uses the point list below. A prepared set replaces it: Example 4's fiducials, or the fiducials with 8 check points, enough for every model (the third-order polynomial needs 10)."),
        Field::points(
            "points",
            "Points [u, v, x, y]",
            4,
            MAX_POINTS,
            &row_axis_up(&FIDUCIALS),
        )
        .columns(&["u", "v", "x", "y"])
        .help("One row per control point: source (u, v), target (x, y). The default is Example 4's fiducials with u = c, v = −r (row axis turned up) and x, y in mm.")
        .when("point_set", &["table"]),
    ]
}

fn solve(inputs: &Record) -> Result<Solution> {
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
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, used);

    let set_text = match set.as_str() {
        "fiducials" => "Example 4's four fiducials (prepared set; the table's points are not used), u = c, v = −r.".to_string(),
        "control-12" => "Example 4's four fiducials and eight check points (prepared set `control-12`; the table's points are not used), u = c, v = −r. The check points are made up for this playground.".to_string(),
        _ => format!("The {} points of the table.", pts.len()),
    };
    let [model_eq_x, model_eq_y] = model_relations(model);
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
        .relation(model_eq_x)
        .relation(model_eq_y)
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
    s.result.set("fitted", Value::matrix(&to_rows(&fit.fitted)));
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

// ---------------------------------------------------------------- practice

/// Four to six control points with small whole-number source coordinates
/// and targets from a Helmert or affine transformation with round
/// parameters, plus a little noise.
fn generate(rng: &mut Rng) -> Record {
    let model = if rng.coin() { "helmert" } else { "affine" };
    let n = rng.int(4, 6) as usize;
    // Corners of a box plus extra points: never all on a line.
    let (w, h) = (rng.num(4, 9), rng.num(4, 9));
    let mut uv = vec![(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)];
    while uv.len() < n {
        let p = (rng.num(1, w as i64 - 1), rng.num(1, h as i64 - 1));
        if !uv.contains(&p) {
            uv.push(p);
        } else {
            uv.push((p.0, h + uv.len() as f64));
        }
    }
    let (a, b) = (rng.num(50, 200) / 100.0, rng.num(-50, 50) / 100.0);
    let (c, d) = (rng.num(-20, 20), rng.num(-20, 20));
    let (e, f) = if model == "affine" {
        (rng.num(50, 200) / 100.0, rng.num(-50, 50) / 100.0)
    } else {
        (a, -b)
    };
    let points: Vec<Vec<f64>> = uv
        .iter()
        .map(|&(u, v)| {
            let x = a * u + b * v + c + rng.num(-2, 2) / 100.0;
            let y = f * u + e * v + d + rng.num(-2, 2) / 100.0;
            vec![u, v, round_to(x, 2), round_to(y, 2)]
        })
        .collect();
    Record::new()
        .with("model", model)
        .with("point_set", "table")
        .with("points", mat(&points))
}

/// The parameters of the drawn model, in the order of X.
fn names(i: &Record) -> &'static [&'static str] {
    if Inputs(i).text("model").is_ok_and(|m| m == "affine") {
        &["a", "b", "c", "d", "e", "f"]
    } else {
        &["a", "b", "c", "d"]
    }
}

fn boxes(i: &Record) -> Vec<BoxDef> {
    let t = Tolerance {
        atol: 0.002,
        rtol: 0.001,
    };
    let mut b: Vec<BoxDef> = names(i)
        .iter()
        .enumerate()
        .map(|(k, name)| {
            BoxDef::new(
                &format!("parameters[{}]", k + 1),
                &format!("Parameter {name}"),
                None,
                t,
            )
            .nudge("Two equations per point; solve the normal equations (AᵀA)·X = AᵀL.")
        })
        .collect();
    b.push(
        BoxDef::new(
            "sigma0",
            "σ₀",
            None,
            Tolerance {
                atol: 0.001,
                rtol: 0.01,
            },
        )
        .nudge("√(VᵀV / redundancy), with V = A·X − L."),
    );
    b
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let p = Inputs(i).rows("points")?;
    let swapped: Vec<Vec<f64>> = p.iter().map(|q| vec![q[1], q[0], q[2], q[3]]).collect();
    let s = EXAMPLE.run(&i.clone().with("points", mat(&swapped)))?;
    let mut out = (1..=names(i).len())
        .map(|k| {
            let key = format!("parameters[{k}]");
            Ok(Mistake::new(
                &key,
                "u and v swapped",
                "The first source coordinate is u, the second v.",
                value_in(&s, &key)?,
            ))
        })
        .collect::<Result<Vec<_>>>()?;
    // σ₀ from VᵀV over the wrong count, or without the root
    let exact = EXAMPLE.run(i)?;
    let (sigma0, redundancy) = (value_in(&exact, "sigma0")?, value_in(&exact, "redundancy")?);
    let vtv = sigma0 * sigma0 * redundancy;
    let observations = 2.0 * p.len() as f64;
    out.extend([
        Mistake::new(
            "sigma0",
            "divided by the observations, not the redundancy",
            "σ₀² = VᵀV / r with r = observations − unknowns: the fitted parameters use up some of the observations.",
            (vtv / observations).sqrt(),
        ),
        Mistake::new(
            "sigma0",
            "square root forgotten",
            "VᵀV / r is σ₀²; σ₀ is its square root.",
            vtv / redundancy,
        ),
    ]);
    Ok(out)
}
