//! Example 4, shared by its two examples: the similarity and affine
//! transformations from four fiducial marks (pixels to photo millimetres),
//! with the seed's printed values; and their practice (drawn fiducials,
//! the parameters and σ₀).

use super::*;
use crate::examples::drill::Rng;
use crate::examples::fields::is_seed;

/// Example 4's fiducials as the course notes' table gives them.
pub(super) fn fields() -> Vec<Field> {
    vec![Field::points(
        "points",
        "Fiducials [c, r, x, y]",
        4,
        MAX_POINTS,
        &to_rows(&FIDUCIALS),
    )
    .columns(&["c (px)", "r (px)", "x (mm)", "y (mm)"])
    .help("One row per fiducial: measured column c and row r (pixels, r downward), calibrated x and y (mm). The solver uses x′ = c, y′ = −r.")]
}

/// What the course notes print for Example 4(a) or (b), and the example's
/// own notes on it.
pub(super) struct Printed {
    /// The printed parameters X.
    pub x: &'static [f64],
    /// The printed residuals V.
    pub v: &'static [f64],
    /// The example's own notes (from the fit and the points as given,
    /// `[c, r, x, y]`), the rounding of its parameters among them: they
    /// come before the notes both examples share.
    pub notes: fn(&mut Solution, &Fit, &[PointPair]) -> Result<()>,
}

/// Example 4(a) or (b): `model` fitted to the fiducials with the row axis
/// turned up; with the seed's fiducials, the notes on what is printed.
pub(super) fn example4(
    ex: &Example,
    inputs: &Record,
    model: Model,
    printed: &Printed,
) -> Result<Solution> {
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
    let mut s = Solution::new(ex.id, ex.title, inputs.clone());

    let mut table = vec![vec![
        r"\text{No.}".to_string(),
        "x' = c".to_string(),
        "y' = -r".to_string(),
        "x".to_string(),
        "y".to_string(),
    ]];
    table.extend(
        pts.iter()
            .enumerate()
            .map(|(i, b)| vec![(i + 1).to_string(), num(b.u), tex(b.v), num(b.x), num(b.y)]),
    );
    s.step(
        Step::new(
            "Axes: x′ = c, y′ = −r",
            "The pixel system counts rows r downward, the photo system counts y upward. The design matrices of Example 4 only fit the fiducials with the row axis turned up: x′ = c, y′ = −r. (The photo x axis runs along c, its y axis against r.)",
        )
        .relation(Relation::new("x'").sym("c"))
        .relation(Relation::new("y'").sym("-r"))
        .relation(
            Relation::new(Form::default())
                .key("source")
                .subst(grid_cut("array", table, "fiducials")),
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
    if is_seed(&fields(), inputs) {
        printed_notes(&mut s, &fit, &cr, model, printed)?;
    }
    Ok(s)
}

/// The seed's printed values beside the computed ones: the example's own
/// notes, then the residuals' (from the rounded parameters and rounded
/// themselves) and where σ0 comes from.
fn printed_notes(
    s: &mut Solution,
    fit: &Fit,
    cr: &[PointPair],
    model: Model,
    printed: &Printed,
) -> Result<()> {
    s.textbook = Some(
        Record::new()
            .with("parameters", Value::numbers(printed.x))
            .with("residuals", Value::numbers(printed.v)),
    );
    (printed.notes)(s, fit, cr)?;
    printed_residual_note(s, fit, printed.x);
    let vnames: Vec<String> = (1..=8).map(|i| format!("v{i}")).collect();
    rounding_notes(s, "residuals", &vnames, &fit.adjustment.v, printed.v);
    let n = model.param_names().len();
    s.note(
        NoteKind::Convention,
        format!("The course notes print neither σ0 nor the parameters' precision; they are computed here from the same adjustment (r = 8 − {n} = {}).", 8 - n),
    ).about(&["sigma0", "std_devs"]);
    Ok(())
}

pub(super) fn max_abs(xs: &[f64]) -> f64 {
    xs.iter().fold(0.0, |m, x| m.max(x.abs()))
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

fn printed_residual_note(s: &mut Solution, fit: &Fit, printed_x: &[f64]) {
    let v = residuals(&fit.a, &fit.l, printed_x);
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

// ---------------------------------------------------------------- practice

/// Four fiducials at the middle of the sides (as in Example 4): calibrated
/// x, y in mm, measured c, r in pixels from a scan at about 600 dpi, turned
/// by a fraction of a degree, with a few tenths of a pixel of noise.
pub(super) fn generate(rng: &mut Rng) -> Record {
    let a = rng.pick(&[106.0, 110.0, 113.0, 115.0]);
    let k = rng.num(2340, 2380) / 100.0; // pixels per mm
    let theta = (rng.num(-50, 50) / 100.0).to_radians();
    // The centre far enough in that every fiducial has a positive pixel
    // position (Example 4's lie about 48 px from the edges).
    let margin = (k * (a + 0.1)).ceil();
    let (cc, rc) = (margin + rng.num(30, 80), margin + rng.num(30, 80));
    let mut points = Vec::new();
    for (ux, uy) in [(-1.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
        let x = round_to(a * ux + rng.num(-30, 30) / 1000.0, 3);
        let y = round_to(a * uy + rng.num(-30, 30) / 1000.0, 3);
        let xp = k * (x * theta.cos() + y * theta.sin());
        let yp = k * (-x * theta.sin() + y * theta.cos());
        let c = round_to(cc + xp + rng.num(-30, 30) / 100.0, 2);
        let r = round_to(rc - yp + rng.num(-30, 30) / 100.0, 2);
        points.push(vec![c, r, x, y]);
    }
    Record::new().with("points", mat(&points))
}

/// Scale-like parameters to 0.01 %, translations to 0.01 mm.
const SCALE: Tolerance = Tolerance {
    atol: 1e-7,
    rtol: 1e-4,
};
const SHIFT: Tolerance = Tolerance::abs(0.01);

/// The boxes: each parameter (`(name, is a shift)`, in the order of X)
/// and σ₀.
pub(super) fn boxes(names: &[(&str, bool)]) -> Vec<BoxDef> {
    let mut b: Vec<BoxDef> = names
        .iter()
        .enumerate()
        .map(|(k, &(name, shift))| {
            let b = BoxDef::new(
                &format!("parameters[{}]", k + 1),
                &format!("Parameter {name}"),
                if shift { Some("mm") } else { None },
                if shift { SHIFT } else { SCALE },
            )
            .nudge("Write two equations per fiducial with x′ = c and y′ = −r, then solve the normal equations N·X = Aᵀ·L.");
            if shift {
                b.axis()
            } else {
                b
            }
        })
        .collect();
    b.push(
        BoxDef::new(
            "sigma0",
            "σ₀",
            Some("mm"),
            Tolerance {
                atol: 0.0005,
                rtol: 0.01,
            },
        )
        .nudge("√(VᵀV / redundancy), with V = A·X − L."),
    );
    b
}

/// The axis mistakes: y not flipped, rows and columns swapped, in each of
/// the `n` parameters.
pub(super) fn mistakes(ex: &Example, i: &Record, n: usize) -> Result<Vec<Mistake>> {
    let p = Inputs(i).rows("points")?;
    let flipped: Vec<Vec<f64>> = p.iter().map(|q| vec![q[0], -q[1], q[2], q[3]]).collect();
    let swapped: Vec<Vec<f64>> = p.iter().map(|q| vec![q[1], q[0], q[2], q[3]]).collect();
    let f = ex.run(&i.clone().with("points", mat(&flipped)))?;
    let s = ex.run(&i.clone().with("points", mat(&swapped)))?;
    let mut out = Vec::new();
    for k in 1..=n {
        let key = format!("parameters[{k}]");
        out.push(Mistake::new(
            &key,
            "y not flipped",
            "Rows count down and y counts up: use y′ = −r, not r.",
            value_in(&f, &key)?,
        ));
        out.push(Mistake::new(
            &key,
            "rows and columns swapped",
            "x′ is the column c, y′ comes from the row r.",
            value_in(&s, &key)?,
        ));
    }
    Ok(out)
}
