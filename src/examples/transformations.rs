//! Seed 000, Example 4 (fiducials: similarity and affine transformation) and
//! seed 004, Table 9.5.1 (every 2-D transformation model), estimated by least
//! squares step by step: observation equations, A and L, N = AᵀA, AᵀL, X, V,
//! σ0 and the parameters' precision, with the seed's printed values and why
//! they differ.

use super::drill::{mat, or_given, value_in, BoxDef, Mistake, Tolerance};
use super::fields::{to_rows, Field, Inputs};
use super::{Example, Topic};
use crate::error::{Error, Result};
use crate::lsq::ILL_CONDITIONED;
use crate::solution::{fmt_sig, num, tex, Form, NoteKind, Record, Relation, Solution, Step, Value};
use crate::transform::{self, Fit, Model, PointPair, Transform};

mod fiducial_affine;
mod fiducial_similarity;
mod fiducials;
mod transform_fit;

const TITLE: &str = "Transformations";
/// The most control points a point list may hold.
pub const MAX_POINTS: usize = 1000;
/// Matrices with more rows than this are shown shortened in the LaTeX.
const SHOW_ROWS: usize = 24;

/// Example 4's fiducials: `[c, r, x, y]`, pixels and millimetres.
pub const FIDUCIALS: [[f64; 4]; 4] = [
    [48.15, 2699.98, -113.002, 0.008],
    [5353.12, 2699.13, 112.991, 0.036],
    [2700.21, 47.62, 0.008, 112.998],
    [2700.56, 5352.74, -0.016, -113.0],
];

/// Eight check points for the prepared set `control-12`, `[c, r, x, y]`.
/// Made up for this playground (the seed has only the four fiducials): the
/// positions spread over the photo; `(x, y)` computed from Example 4's affine
/// fit, plus a radial distortion of 4·10⁻⁹·ρ² (about 5 µm at 110 mm) and a
/// few micrometres of measurement noise, rounded to 0.001 mm like the seed.
pub const CHECK_POINTS: [[f64; 4]; 8] = [
    [612.4, 598.85, -88.946, 89.521],
    [4791.27, 605.12, 89.079, 89.25],
    [4788.93, 4795.66, 88.955, -89.275],
    [606.71, 4801.38, -89.223, -89.519],
    [2702.35, 2698.02, 0.074, 0.091],
    [1521.84, 1893.47, -50.208, 34.366],
    [3955.62, 1402.19, 53.472, 55.287],
    [1788.05, 3987.73, -38.885, -54.849],
];

/// What Example 4 prints: (a) `X`, `V`; (b) `X`, `V`.
const SIM_PRINTED_X: [f64; 4] = [0.043, 0.000, -115.030, 115.040];
const SIM_PRINTED_V: [f64; 8] = [0.006, 0.009, 0.006, -0.006, -0.014, -0.001, 0.002, -0.002];
const AFF_PRINTED_X: [f64; 6] = [0.043, 0.000, -115.030, -0.000, 0.043, 115.030];
const AFF_PRINTED_V: [f64; 8] = [0.006, 0.002, 0.006, 0.002, -0.006, -0.002, -0.006, -0.002];

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[
    fiducial_similarity::EXAMPLE,
    fiducial_affine::EXAMPLE,
    transform_fit::EXAMPLE,
];

/// The topic: its module (`web/transformations/`) and title.
pub const TOPIC: Topic = Topic {
    module: "transformations",
    title: TITLE,
    examples: EXAMPLES,
};

/// `[c, r, x, y]` to `[u, v, x, y]` with `u = c`, `v = −r`.
fn row_axis_up(points: &[[f64; 4]]) -> Vec<Vec<f64>> {
    points
        .iter()
        .map(|p| vec![p[0], -p[1], p[2], p[3]])
        .collect()
}

/// `[u, v, x, y]` rows to point pairs (rows have been checked to hold 4).
fn pairs(rows: &[Vec<f64>]) -> Result<Vec<PointPair>> {
    rows.iter()
        .enumerate()
        .map(|(i, r)| match r.as_slice() {
            [u, v, x, y] => Ok(PointPair {
                u: *u,
                v: *v,
                x: *x,
                y: *y,
            }),
            _ => Err(Error::input(
                "points",
                format!(
                    "point {} has {} number{}; each point needs 4",
                    i + 1,
                    r.len(),
                    if r.len() == 1 { "" } else { "s" }
                ),
            )),
        })
        .collect()
}

// ---------------------------------------------------------------- LaTeX

/// `a` → `a`, `a7` → `a_{7}`, `a21` → `a_{21}` (a parameter's name, not
/// LaTeX, to LaTeX).
fn tex_name(n: &str) -> String {
    let split = n.find(|c: char| c.is_ascii_digit()).unwrap_or(n.len());
    let (base, idx) = n.split_at(split);
    if idx.is_empty() {
        base.to_string()
    } else {
        format!("{base}_{{{idx}}}")
    }
}

/// Rows to show: all, or the first ones and a marker when there are many.
fn shown(n: usize) -> (usize, bool) {
    if n > SHOW_ROWS {
        (SHOW_ROWS - 4, true)
    } else {
        (n, false)
    }
}

/// Rows of LaTeX cells as a matrix named `name`, shortened to the rows
/// [`shown`] and a row of dots when there are many.
fn grid_cut(env: &'static str, rows: Vec<Vec<String>>, name: &str) -> Form {
    let (k, cut) = shown(rows.len());
    let cols = rows.first().map_or(1, Vec::len);
    let mut rows: Vec<Vec<String>> = rows.into_iter().take(k).collect();
    if cut {
        rows.push(vec![r"\vdots".to_string(); cols]);
    }
    Form::grid_tex(env, rows, name)
}

/// A matrix of numbers, shortened when long.
fn matrix(rows: &[Vec<f64>], name: &str) -> Form {
    grid_cut(
        "bmatrix",
        rows.iter()
            .map(|r| r.iter().map(|&x| num(x)).collect())
            .collect(),
        name,
    )
}

/// A column of numbers, shortened when long.
fn vector(xs: &[f64], name: &str) -> Form {
    grid_cut("bmatrix", xs.iter().map(|&x| vec![num(x)]).collect(), name)
}

/// The column of the parameters' symbols, shortened when long.
fn symbols(names: &[String]) -> Form {
    grid_cut(
        "bmatrix",
        names.iter().map(|n| vec![tex_name(n)]).collect(),
        "X",
    )
}

/// The model's equations, symbolic: one relation for x, one for y.
fn model_relations(model: Model) -> [Relation; 2] {
    let eq = |lhs: &str, rhs: &str| Relation::new(lhs).sym(rhs);
    match model {
        Model::Helmert => [eq("x", r"a\,u + b\,v + c"), eq("y", r"-b\,u + a\,v + d")],
        Model::Affine => [eq("x", r"a\,u + b\,v + c"), eq("y", r"d\,u + e\,v + f")],
        Model::PseudoAffine => [
            eq("x", r"a_1 uv + a_2 u + a_3 v + a_4"),
            eq("y", r"a_5 uv + a_6 u + a_7 v + a_8"),
        ],
        Model::Projective => [
            eq("x", r"\frac{a_1 u + a_2 v + a_3}{a_7 u + a_8 v + 1}"),
            eq("y", r"\frac{a_4 u + a_5 v + a_6}{a_7 u + a_8 v + 1}"),
        ],
        Model::Conformal2 => [
            Relation::new("x").sym(Form::terms([
                "a_1 u + a_2 v",
                "+ a_3 (u^2 - v^2)",
                "+ 2 a_4 uv + a_5",
            ])),
            Relation::new("y").sym(Form::terms([
                "-a_2 u + a_1 v",
                "+ 2 a_3 uv",
                "- a_4 (u^2 - v^2) + a_6",
            ])),
        ],
        Model::Polynomial2 => [
            Relation::new("x")
                .sym(r"\sum_{i+j \le 4} a_{ij}\, u^{i-1} v^{j-1}")
                .sym(Form::terms([
                    "a_{11} + a_{21} u + a_{12} v",
                    "+ a_{31} u^2 + a_{22} uv + a_{13} v^2",
                ])),
            eq("y", r"\sum_{i+j \le 4} b_{ij}\, u^{i-1} v^{j-1}"),
        ],
        Model::Polynomial3 => [
            Relation::new("x")
                .sym(r"\sum_{i+j \le 5} a_{ij}\, u^{i-1} v^{j-1}")
                .sym(Form::terms([
                    "a_{11} + a_{21} u + a_{12} v",
                    "+ a_{31} u^2 + a_{22} uv + a_{13} v^2",
                    "+ a_{41} u^3 + a_{32} u^2 v",
                    "+ a_{23} u v^2 + a_{14} v^3",
                ])),
            eq("y", r"\sum_{i+j \le 5} b_{ij}\, u^{i-1} v^{j-1}"),
        ],
        Model::Similarity => [eq("x", r"a\,x' - b\,y' + c"), eq("y", r"b\,x' + a\,y' + d")],
        Model::FiducialAffine => [eq("x", r"a\,x' + b\,y' + e"), eq("y", r"c\,x' + d\,y' + f")],
    }
}

/// One observation equation with its numbers: `l_k + v_k = Σ A_kj·X_j`,
/// a term per parameter.
fn obs_relation(k: usize, row: &[f64], l: f64, names: &[String]) -> Relation {
    let mut terms: Vec<String> = Vec::new();
    for (c, n) in row.iter().zip(names) {
        if *c == 0.0 {
            continue;
        }
        let name = tex_name(n);
        let (sign, mag) = if *c < 0.0 { ("-", -c) } else { ("+", *c) };
        let term = if mag == 1.0 {
            name
        } else {
            format!(r"{}\,{name}", num(mag))
        };
        terms.push(match (terms.is_empty(), sign) {
            (true, "-") => format!("-{term}"),
            (true, _) => term,
            (false, _) => format!("{sign} {term}"),
        });
    }
    if terms.is_empty() {
        terms.push("0".to_string());
    }
    Relation::new(format!("{} + v_{{{k}}}", num(l))).subst(Form::terms(terms))
}

// ---------------------------------------------------------------- steps

/// The least-squares steps every entry shares, from the observation
/// equations to the parameters' precision.
fn adjustment_steps(s: &mut Solution, model: Model, fit: &Fit, src: &str) {
    let names = model.param_names();
    let adj = &fit.adjustment;
    let (n_obs, u) = (fit.l.len(), model.n_params());
    let n_pts = n_obs / 2;

    let lin = if model.is_linearised() {
        " The projective model is not linear in its parameters; multiplying out its denominator gives the linearised form that is solved here: a₁u + a₂v + a₃ − a₇·u·x − a₈·v·x = x (and the same for y with a₄, a₅, a₆), so x and y appear in A as well as in L."
    } else {
        ""
    };
    let mut step = Step::new(
        "Observation equations",
        &format!(
            "Each of the {n_pts} points gives two equations, one for x and one for y, with {src} as the source coordinates: {n_obs} equations in {u} unknowns. An observation plus its residual equals the model's value: l + v = A·X.{lin}"
        ),
    );
    if model.is_linearised() {
        step = step
            .relation(Relation::new(r"x\,(a_7 u + a_8 v + 1)").sym(r"a_1 u + a_2 v + a_3"))
            .relation(Relation::new(r"a_1 u + a_2 v + a_3 - a_7\,u x - a_8\,v x").sym("x"));
    } else {
        for r in model_relations(model) {
            step = step.relation(r);
        }
    }
    let (k, cut) = shown(n_obs);
    for (i, (row, l)) in fit.a.iter().zip(&fit.l).take(k).enumerate() {
        step = step.relation(obs_relation(i + 1, row, *l, &names));
    }
    if cut {
        step = step.relation(Relation::new(Form::default()).subst(r"\vdots"));
    }
    s.step(step);

    s.step(
        Step::new(
            "Design matrix A and observations L",
            &format!(
                "Rows 2i−1 and 2i of A belong to point i (its x and its y equation); L holds the target coordinates in the same order. A is {n_obs}×{u}."
            ),
        )
        .relation(Relation::new(r"A\,X").sym("L + V"))
        .relation(
            Relation::new(matrix(&fit.a, "A").then(symbols(&names)))
                .key("L")
                .subst(vector(&fit.l, "L").then("+ V")),
        )
        .value("A", Value::matrix(&fit.a))
        .value("L", Value::numbers(&fit.l)),
    );

    s.step(
        Step::new(
            "Normal equations",
            "Multiplying by Aᵀ gives u equations in u unknowns (all observations have weight 1, P = I).",
        )
        .relation(
            Relation::new("N")
                .key("N")
                .sym(r"A^\mathsf{T} A")
                .result(matrix(&adj.n, "N")),
        )
        .relation(
            Relation::new(r"A^\mathsf{T} L")
                .key("AtL")
                .result(vector(&adj.atl, r"A^\mathsf{T} L")),
        )
        .value("N", Value::matrix(&adj.n))
        .value("AtL", Value::numbers(&adj.atl))
        .value("condition", adj.condition),
    );

    s.step(
        Step::new(
            "Solution",
            "The parameters that make the sum of squared residuals smallest.",
        )
        .relation(
            Relation::new("X")
                .key("parameters")
                .sym(r"(A^\mathsf{T} A)^{-1} A^\mathsf{T} L")
                .sym(r"Q_{xx}\, A^\mathsf{T} L")
                .subst(symbols(&names))
                .result(vector(&adj.x, "X")),
        )
        .value("X", Value::numbers(&adj.x))
        .value("Qxx", Value::matrix(&adj.qxx))
        .value("parameter_names", names_value(&names)),
    );

    let vtext = if model.is_linearised() {
        format!(
            "V holds the residuals of the linearised equations, D·(x̂ − x) with D = a₇u + a₈v + 1; the residuals of the coordinates themselves, x̂ − x, are listed beside them (at these points D lies between {} and {}).",
            num(denominators(fit).0),
            num(denominators(fit).1)
        )
    } else {
        "Each residual is the fitted coordinate minus the given one (x̂ − x, ŷ − y), in the order of the rows of A.".to_string()
    };
    let pr: Vec<f64> = fit.point_residuals.iter().flatten().copied().collect();
    s.step(
        Step::new("Residuals", &vtext)
            .relation(
                Relation::new("V")
                    .key("residuals")
                    .sym(r"A\,X - L")
                    .result(vector(&adj.v, "V")),
            )
            .value("V", Value::numbers(&adj.v))
            .value(
                "point_residuals",
                Value::matrix(&to_rows(&fit.point_residuals)),
            )
            .value("coordinate_residuals", Value::numbers(&pr))
            .value("fitted", Value::matrix(&to_rows(&fit.fitted))),
    );

    let r = adj.redundancy;
    let sigma0 = Relation::new(r"\sigma_0")
        .key("sigma0")
        .sym(r"\sqrt{\frac{V^\mathsf{T} V}{n - u}}");
    let s0_step = match adj.sigma0 {
        Some(s0) => Step::new(
            "Standard deviation of unit weight",
            &format!("The redundancy is r = n − u = {n_obs} − {u} = {r}."),
        )
        .relation(
            sigma0
                .subst(format!(
                    r"\sqrt{{\frac{{{}}}{{{n_obs} - {u}}}}}",
                    num(adj.vtpv)
                ))
                .value(s0, ""),
        ),
        None => Step::new(
            "Standard deviation of unit weight",
            &format!(
                "There are exactly as many equations as unknowns (r = n − u = {n_obs} − {u} = 0): the transformation passes through the points, the residuals vanish and σ0 cannot be estimated."
            ),
        )
        .relation(
            sigma0
                .subst(format!(r"\sqrt{{\frac{{{}}}{{0}}}}", num(adj.vtpv)))
                .result(r"\text{(undefined)}"),
        ),
    };
    s.step(
        s0_step
            .value("sigma0", adj.sigma0)
            .value("redundancy", r)
            .value("vtv", adj.vtpv),
    );

    let q: Vec<f64> = (0..u)
        .map(|j| {
            adj.qxx
                .get(j)
                .and_then(|row| row.get(j))
                .copied()
                .unwrap_or(0.0)
        })
        .collect();
    let rule = Relation::new(r"\sigma_{x_j}")
        .key("std_devs")
        .sym(r"\sigma_0 \sqrt{q_{jj}}");
    let prec = match (&adj.std_dev, adj.sigma0) {
        (Some(sd), Some(s0)) => {
            let mut step = Step::new(
                "Precision of the parameters",
                "Each parameter's standard deviation is σ0 times the square root of its diagonal element of Qxx = N⁻¹.",
            )
            .relation(rule);
            for ((n, sdj), qj) in names.iter().zip(sd).zip(&q) {
                step = step.relation(
                    Relation::new(format!(r"\sigma_{{{}}}", tex_name(n)))
                        .subst(format!(r"{} \sqrt{{{}}}", num(s0), num(*qj)))
                        .value(*sdj, ""),
                );
            }
            step.value("std_devs", Value::numbers(sd))
        }
        _ => Step::new(
            "Precision of the parameters",
            "Without redundancy there is no σ0, so the parameters' standard deviations cannot be given; only the cofactors q_jj of Qxx = N⁻¹ are known.",
        )
        .relation(rule)
        .value("std_devs", Value::Null),
    };
    s.step(prec.value("q_diagonal", Value::numbers(&q)));

    if let Some((scale, rot)) = scale_rotation(&fit.transform) {
        let (a, b) = (
            fit.transform.params.first().copied().unwrap_or(0.0),
            fit.transform.params.get(1).copied().unwrap_or(0.0),
        );
        // the sine's sign: b (similarity) or −b (Helmert)
        let (sine, sb) = if model == Model::Similarity {
            ("b", b)
        } else {
            ("-b", -b)
        };
        s.step(
            Step::new(
                "Scale and rotation",
                "A similarity is a scale times a rotation (counter-clockwise positive) plus a shift.",
            )
            .relation(
                Relation::new("m")
                    .key("scale")
                    .sym(r"\sqrt{a^2 + b^2}")
                    .subst(format!(r"\sqrt{{{}^2 + {}^2}}", tex(a), tex(b)))
                    .value(scale, ""),
            )
            .relation(
                Relation::new(r"\theta")
                    .key("rotation_deg")
                    .sym(format!(r"\operatorname{{atan2}}({sine}, a)"))
                    .subst(format!(r"\operatorname{{atan2}}({}, {})", num(sb), num(a)))
                    .result(format!(r"{}^\circ", num(rot))),
            )
            .value("scale", scale)
            .value("rotation_deg", rot),
        );
    }
}

/// Scale and rotation (degrees) of a Helmert or similarity transformation.
fn scale_rotation(t: &Transform) -> Option<(f64, f64)> {
    let a = t.params.first().copied()?;
    let b = t.params.get(1).copied()?;
    let sb = match t.model {
        Model::Similarity => b,
        Model::Helmert => -b,
        _ => return None,
    };
    Some((a.hypot(b), sb.atan2(a).to_degrees()))
}

fn denominators(fit: &Fit) -> (f64, f64) {
    let p = &fit.transform.params;
    let (a7, a8) = (
        p.get(6).copied().unwrap_or(0.0),
        p.get(7).copied().unwrap_or(0.0),
    );
    let ds: Vec<f64> = fit
        .a
        .iter()
        .step_by(2)
        .map(|row| {
            let u = row.first().copied().unwrap_or(0.0);
            let v = row.get(1).copied().unwrap_or(0.0);
            a7 * u + a8 * v + 1.0
        })
        .collect();
    let lo = ds.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = ds.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if lo.is_finite() && hi.is_finite() {
        (lo, hi)
    } else {
        (1.0, 1.0)
    }
}

fn names_value(names: &[String]) -> Value {
    Value::List(names.iter().map(|n| Value::Text(n.clone())).collect())
}

/// The inverse step, where a closed form exists; returns the inverse's
/// parameters (or `None`).
fn inverse_step(
    s: &mut Solution,
    fit: &Fit,
    first: Option<&PointPair>,
    src: &str,
) -> Result<Option<Vec<f64>>> {
    let model = fit.transform.model;
    let inv = match fit.transform.inverse() {
        Ok(Some(inv)) => inv,
        Ok(None) => {
            s.step(Step::new(
                "Inverse transformation",
                &format!(
                    "The {} model has no inverse of the same form in closed form (inverting it means solving a quadratic or cubic in u and v, which need not have one real solution); to go from (x, y) back to {src}, fit the model in the other direction.",
                    model.name()
                ),
            ));
            return Ok(None);
        }
        Err(e) => {
            s.note(
                NoteKind::Warning,
                format!("The fitted transformation cannot be inverted: {e}."),
            )
            .about(&["inverse_parameters"]);
            return Ok(None);
        }
    };
    let names = model.param_names();
    // Check on the first point: its fitted (x̂, ŷ) goes back to (u, v).
    let mut check = String::new();
    let mut step_values = Record::new();
    if let (Some(f), Some(p)) = (fit.fitted.first(), first) {
        let (u, v) = (p.u, p.v);
        if let Ok((bu, bv)) = inv.apply(f[0], f[1]) {
            check = format!(
                " Check with point 1: (x̂, ŷ) = ({}, {}) maps back to ({}, {}); the point was ({}, {}).",
                num(f[0]),
                num(f[1]),
                num(bu),
                num(bv),
                num(u),
                num(v)
            );
            step_values.set("check_back", Value::numbers(&[bu, bv]));
        }
    }
    let mut st = Step::new(
        "Inverse transformation",
        &format!(
            "The inverse is a transformation of the same form, from (x, y) back to {src}: the 3×3 matrix of the transformation inverted and scaled so that its last element is 1.{check}"
        ),
    )
    .relation(
        Relation::new("H^{-1}")
            .key("inverse_parameters")
            .sym(r"\frac{\operatorname{adj} H}{\det H}"),
    );
    for (n, p) in names.iter().zip(&inv.params) {
        st = st.relation(Relation::new(format!("{}'", tex_name(n))).value(*p, ""));
    }
    st = st.value("inverse_parameters", Value::numbers(&inv.params));
    for (k, v) in step_values.iter() {
        st = st.value(k, v.clone());
    }
    s.step(st);
    Ok(Some(inv.params))
}

fn common_result(s: &mut Solution, fit: &Fit, inverse: Option<Vec<f64>>) {
    let adj = &fit.adjustment;
    let names = fit.transform.model.param_names();
    s.result.set("parameters", Value::numbers(&adj.x));
    s.result.set("residuals", Value::numbers(&adj.v));
    s.result.set("sigma0", adj.sigma0);
    s.result.set("redundancy", adj.redundancy);
    s.result.set("parameter_names", names_value(&names));
    s.result.set(
        "std_devs",
        adj.std_dev
            .as_ref()
            .map_or(Value::Null, |sd| Value::numbers(sd)),
    );
    s.result.set(
        "point_residuals",
        Value::matrix(&to_rows(&fit.point_residuals)),
    );
    s.result.set(
        "inverse_parameters",
        inverse.map_or(Value::Null, |p| Value::numbers(&p)),
    );
    s.result.set("condition", adj.condition);
}

/// Labels of the result keys; `unit` is the target system's (mm for the
/// fiducials, none for arbitrary points).
fn label_results(s: &mut Solution, names: &[String], unit: &str) {
    let params = format!("Parameters [{}]", names.join(", "));
    s.label_present(&[
        ("parameters", params.as_str(), ""),
        ("residuals", "Residuals V = A·X − L, [vx1, vy1, …]", unit),
        ("sigma0", "Standard deviation of unit weight σ0", unit),
        ("redundancy", "Redundancy r = n − u", ""),
        ("parameter_names", "Parameter names", ""),
        ("std_devs", "Standard deviations of the parameters", ""),
        (
            "point_residuals",
            "Coordinate residuals (x̂ − x, ŷ − y) per point",
            unit,
        ),
        (
            "inverse_parameters",
            "Parameters of the inverse transformation",
            "",
        ),
        ("condition", "Condition number of N (columns scaled)", ""),
        ("scale", "Scale m", ""),
        ("rotation_deg", "Rotation θ", "°"),
        ("model", "Model", ""),
        ("point_set", "Control points", ""),
        ("fitted", "Transformed points (x̂, ŷ)", unit),
    ]);
}

fn condition_note(s: &mut Solution, fit: &Fit) {
    let c = fit.adjustment.condition;
    if c > ILL_CONDITIONED {
        let hint = if fit.transform.model == Model::PseudoAffine {
            " With four points laid out like Example 4's fiducials — a diamond whose diagonals run along the axes — the uv column of A is almost a combination of the columns of 1, u and v, so the uv terms are decided by the measurement noise; add points off the diagonals (the prepared set control-12)."
        } else {
            " Spread the points more evenly, or add points."
        };
        s.note(
            NoteKind::Warning,
            format!(
                "The normal matrix is nearly singular (condition number {} after scaling its columns, above {}): the parameters are poorly determined and may mean little.{hint}",
                fmt_sig(c, 3),
                fmt_sig(ILL_CONDITIONED, 1)
            ),
        ).about(&["parameters", "condition"]);
    }
    if fit.adjustment.redundancy == 0 {
        s.note(
            NoteKind::Warning,
            "No redundancy (r = 0): the model passes exactly through the points, so σ0, the parameters' precision and every check on the measurements are undefined (σ0 has no value). Add points to get them.",
        ).about(&["sigma0", "std_devs"]);
    }
}

// ---------------------------------------------------------------- practice

/// Rounds to `decimals` decimals.
fn round_to(x: f64, decimals: i32) -> f64 {
    let f = 10f64.powi(decimals);
    (x * f).round() / f
}

/// `A·X − L` for given parameters.
fn residuals(a: &[Vec<f64>], l: &[f64], x: &[f64]) -> Vec<f64> {
    a.iter()
        .zip(l)
        .map(|(row, l)| row.iter().zip(x).map(|(a, b)| a * b).sum::<f64>() - l)
        .collect()
}

/// A step's value `key`, alone in a record (to read it as an input).
fn step_value(s: &Solution, key: &str) -> Record {
    s.steps
        .iter()
        .find_map(|st| st.values.get(key))
        .map(|v| Record::new().with(key, v.clone()))
        .unwrap_or_default()
}

/// σ₀ from the student's parameters: V = A·X − L with their X (A and L do
/// not depend on X: the fits are linear), over the redundancy.
fn chain_sigma0(ex: &Example, i: &Record, g: &Record) -> Result<Record> {
    let s = ex.run(i)?;
    let a = Inputs(&step_value(&s, "A")).rows("A")?;
    let l = Inputs(&step_value(&s, "L")).list("L")?;
    let n = a.first().map_or(0, Vec::len);
    let mut out = Record::new();
    let mut x = Vec::new();
    for k in 1..=n {
        let key = format!("parameters[{k}]");
        let v = or_given(g, &key, value_in(&s, &key)?);
        x.push(v);
        out.set(&key, v);
    }
    let vv: f64 = residuals(&a, &l, &x).iter().map(|v| v * v).sum();
    let redundancy = value_in(&s, "redundancy")?;
    out.set("sigma0", or_given(g, "sigma0", (vv / redundancy).sqrt()));
    Ok(out)
}
