//! Lecture 21: least-squares matching with an affine geometric model and
//! gain and offset, on a generated patch pair or on two given patches; and
//! its practice: the converged affine part, its shifts, scale and rotation.

use super::*;
use crate::examples::drill::{drill, or_given, value_in, BoxDef, Drill, Mistake, Rng};
use crate::examples::Lab;

pub const EXAMPLE: Example = Example {
    id: "lsm-affine",
    title: "Affine + radiometric least-squares matching",
    source: "Lecture 21: Image matching",
    summary: "A generated patch pair with a known shift, rotation, scale, shear, gain and offset, recovered by eight-parameter least-squares matching.",
    fields,
    solve,
    answer: &["parameters", "sigma0"],
    labels: LABELS,
    lab: Some(Lab::new("correlation", &["affine-lsm"])),
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

/// The two kinds of pair this example matches: one generated with a known
/// change, or two patches given as grey values (e.g. from the image lab).
const PAIR_OPTIONS: &[(&str, &str)] = &[
    ("generated", "Generated, with a known change"),
    ("patches", "Given patches (as from the lab)"),
];
const GENERATED: &[&str] = &["generated"];
const PATCHES: &[&str] = &["patches"];

/// The default given pair: an 11 × 11 texture and a 7 × 7 template made
/// from it (rotated 4°, scaled 1.05, centred at column 6.3, row 5.8,
/// gain 1.1, offset −5, rounded to whole grey values).
fn affine_search_default() -> Vec<Vec<f64>> {
    [
        [150, 173, 180, 165, 133, 93, 63, 52, 65, 94, 127],
        [153, 181, 190, 175, 143, 106, 80, 72, 83, 104, 124],
        [142, 169, 177, 165, 140, 115, 101, 103, 116, 131, 137],
        [129, 147, 149, 137, 120, 110, 113, 129, 150, 163, 159],
        [127, 130, 118, 101, 89, 91, 110, 140, 170, 185, 179],
        [140, 125, 100, 74, 61, 69, 97, 136, 170, 188, 182],
        [162, 135, 98, 66, 50, 58, 87, 124, 155, 170, 164],
        [178, 147, 109, 76, 61, 68, 91, 118, 137, 142, 132],
        [177, 150, 119, 95, 87, 96, 113, 127, 130, 118, 99],
        [155, 136, 117, 109, 115, 131, 146, 149, 136, 110, 79],
        [121, 106, 100, 109, 131, 157, 175, 174, 152, 116, 79],
    ]
    .iter()
    .map(|r| r.iter().map(|&x| f64::from(x)).collect())
    .collect()
}

fn affine_template_default() -> Vec<Vec<f64>> {
    [
        [192, 169, 135, 108, 99, 110, 130],
        [171, 151, 128, 117, 123, 144, 166],
        [137, 117, 103, 106, 129, 163, 190],
        [109, 84, 72, 84, 118, 160, 190],
        [101, 68, 54, 68, 103, 142, 170],
        [111, 75, 61, 73, 101, 130, 146],
        [125, 96, 87, 100, 122, 137, 136],
    ]
    .iter()
    .map(|r| r.iter().map(|&x| f64::from(x)).collect())
    .collect()
}

fn fields() -> Vec<Field> {
    let n = |key, label, default, lo, hi, unit: Option<&'static str>, help| {
        let f = Field::number(key, label, default)
            .range(lo, hi)
            .help(help)
            .when("pair", GENERATED);
        match unit {
            Some(u) => f.unit(u),
            None => f,
        }
    };
    vec![
        Field::choice("pair", "Patch pair", PAIR_OPTIONS, "generated")
            .help("Generated: a texture seen through a known affine and radiometric change; the truth is shown beside the estimates. Given: any template and search window as grey values, and a start position (the image lab links its affine matches here)."),
        Field::matrix("template", "Template T", &affine_template_default())
            .help("The template's grey values, rows top to bottom (at most 64 × 64).")
            .when("pair", PATCHES),
        Field::matrix("search", "Search window S", &affine_search_default())
            .help("The search window's grey values; columns c and rows r count from 1 (at most 64 × 64).")
            .when("pair", PATCHES),
        Field::number("c0", "Start column c⁰", 6.0)
            .unit("px")
            .range(1.0, MAX_2D as f64)
            .help("Column of the template's centre in the search window to start from; the affine part starts as the identity, gain 1, offset 0.")
            .when("pair", PATCHES),
        Field::number("r0", "Start row r⁰", 6.0)
            .unit("px")
            .range(1.0, MAX_2D as f64)
            .help("Row of the template's centre in the search window to start from.")
            .when("pair", PATCHES),
        Field::integer("patch_size", "Template size", 21.0)
            .range(5.0, 41.0)
            .help("Side of the square template in pixels (odd).")
            .when("pair", GENERATED),
        n(
            "shift_c",
            "Shift in c (a3)",
            1.3,
            -10.0,
            10.0,
            Some("px"),
            "Column shift of the template centre from the search window's centre.",
        ),
        n(
            "shift_r",
            "Shift in r (a6)",
            -0.7,
            -10.0,
            10.0,
            Some("px"),
            "Row shift (downward positive).",
        ),
        n(
            "rotation_deg",
            "Rotation θ",
            5.0,
            -45.0,
            45.0,
            Some("°"),
            "Clockwise on the screen, since rows count downward.",
        ),
        n(
            "scale",
            "Scale s",
            1.05,
            0.5,
            2.0,
            None,
            "Size of a search-window pixel step per template pixel.",
        ),
        n(
            "shear",
            "Shear k",
            0.02,
            -0.5,
            0.5,
            None,
            "[a1 a2; a4 a5] = s·R(θ)·[1 k; 0 1].",
        ),
        n(
            "gain",
            "Gain a7",
            1.2,
            0.1,
            10.0,
            None,
            "Radiometric scale: T = a7·S + a8.",
        ),
        n(
            "offset",
            "Offset a8",
            -15.0,
            -255.0,
            255.0,
            None,
            "Radiometric offset in grey values.",
        ),
        n(
            "noise",
            "Noise σ",
            0.0,
            0.0,
            50.0,
            None,
            "Standard deviation of the Gaussian noise added to each image (grey values).",
        ),
        Field::integer("seed", "Random seed", 1.0)
            .range(0.0, 1e9)
            .help("Chooses the texture and the noise; the same seed gives the same pair.")
            .when("pair", GENERATED),
        max_iterations(),
    ]
}

fn solve(inputs: &Record) -> Result<Solution> {
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    let set = settings(Model::AffineRadiometric, Gradients::SearchWindow, inputs)?;
    let given = Inputs(inputs).text("pair")? == "patches";
    let pair = if given {
        given_pair(&mut s, inputs)?
    } else {
        generated_pair(&mut s, inputs)?
    };
    let Pair {
        template,
        search,
        start,
        origin,
        truth,
        noise,
    } = pair;
    let m = matching::match_2d(&template, &search, start, set).map_err(|e| {
        if given {
            said_of(e, "c0")
        } else {
            e
        }
    })?;
    let syms = symbols(&m.estimated, false);
    s.step(
        Step::new(
            "Observation equation and initial values (Lecture 21)",
            if given {
                "One equation per template pixel, linearised at the current parameters; G_p, G_q are the central-difference gradients of the resampled search patch along the window's columns and rows. Initial values as Lecture 21 says, with the translations at the start position: the diagonal of the affine part 1, gain 1, offset 0."
            } else {
                "One equation per template pixel, linearised at the current parameters; G_p, G_q are the central-difference gradients of the resampled search patch along the window's columns and rows. Initial values as Lecture 21 says: translations zero, the diagonal of the affine part 1, gain 1, offset 0."
            },
        )
        .relation(Relation::new("T - (a_7 G + a_8) + V").sym(Form::terms([
            r"a_7G_p(u\,da_1 + v\,da_2 + da_3)",
            r"+ a_7G_q(u\,da_4 + v\,da_5 + da_6)",
            r"+ G\,da_7",
            "+ da_8",
        ])))
        .relation(Relation::new(r"\mathbf{a}^0").subst(format!(
            "[1, 0, {}, 0, 1, {}, 1, 0]",
            num(start.a[2] - origin),
            num(start.a[5] - origin)
        ))),
    );
    if let Some(it) = m.iterations.first() {
        s.step(
            Step::new(
                "Design matrix and normal equations (iteration 1)",
                "A has one row per template pixel and eight columns; N = AᵀA is 8×8.",
            )
            .relation(Relation::new("A_i").sym(Form::terms([
                r"[a_7G_p u,",
                r"a_7G_p v,",
                r"a_7G_p,",
                r"a_7G_q u,",
                r"a_7G_q v,",
                r"a_7G_q,",
                r"G,",
                r"1]",
            ])))
            .relation(Relation::new("A_1").subst(Form::grid(
                "bmatrix",
                &it.a[..it.a.len().min(1)],
                "A_1",
            )))
            .relation(
                Relation::new("N")
                    .key("N")
                    .sym(r"A^\mathsf{T}A")
                    .result(Form::grid("bmatrix", &it.adjustment.n, "N")),
            )
            .relation(
                Relation::new(r"d\mathbf{X}")
                    .key("increments")
                    .sym(r"(A^\mathsf{T}A)^{-1}A^\mathsf{T}d\mathbf{L}")
                    .result(Form::column(&it.increments, r"d\mathbf{X}")),
            )
            .value("A", Value::matrix(&it.a))
            .value("N", Value::matrix(&it.adjustment.n))
            .value("increments", Value::numbers(&it.increments)),
        );
    }
    s.step(table_step(&m, &syms, origin, Some("parameters")));
    status_step(&mut s, &m, &syms, set.max_iterations);

    let est: Vec<f64> = (0..8)
        .map(|k| {
            let x = m.params.a.get(k).copied().unwrap_or(0.0);
            if k == 2 || k == 5 {
                x - origin
            } else {
                x
            }
        })
        .collect();
    let sd = m.std_dev();
    let sd_text = |k: usize| {
        sd.as_ref()
            .and_then(|v| v.get(k))
            .map_or("–".to_string(), |x| fmt_sig(*x, 3))
    };
    let est_text = |k: usize| num(est.get(k).copied().unwrap_or(0.0));
    let mut header = vec![String::new()];
    if truth.is_some() {
        header.push(r"\text{true}".to_string());
    }
    header.extend([r"\text{estimate}".to_string(), r"\sigma".to_string()]);
    let mut rows = vec![header];
    rows.extend((0..8).map(|k| {
        let mut row = vec![format!("a_{}", k + 1)];
        if let Some(t) = &truth {
            row.push(num(t.a.get(k).copied().unwrap_or(0.0)));
        }
        row.extend([est_text(k), sd_text(k)]);
        row
    }));
    let title = if truth.is_some() {
        "Estimates beside the truth"
    } else {
        "Estimates"
    };
    let how = if given {
        "a3 and a6 are the column and row of the template's centre in the search window, counted from 1. The standard deviations are σ0·√qᵢᵢ from the last iteration's Qxx = N⁻¹."
    } else {
        "The standard deviations are σ0·√qᵢᵢ from the last iteration's Qxx = N⁻¹."
    };
    let true_parameters = truth.as_ref().map_or(Value::Null, |t| Value::numbers(&t.a));
    // the scale and rotation the estimate implies (no shear: the first
    // column of [a1 a2; a4 a5] is s·(cos θ, sin θ))
    let (scale, rotation) = (est[0].hypot(est[3]), est[3].atan2(est[0]).to_degrees());
    let mut step = Step::new(title, how)
        .relation(
            Relation::new(r"\sigma_{a_j}")
                .key("std_dev")
                .sym(r"\sigma_0\sqrt{q_{jj}}"),
        )
        .relation(
            Relation::new(Form::default())
                .key("estimates")
                .subst(Form::grid_tex("array", rows, "estimates")),
        )
        .relation(
            Relation::new("s")
                .key("estimated_scale")
                .sym(r"\sqrt{a_1^2 + a_4^2}")
                .subst(format!(r"\sqrt{{{}^2 + {}^2}}", tex(est[0]), tex(est[3])))
                .value(scale, ""),
        )
        .relation(
            Relation::new(r"\theta")
                .key("estimated_rotation_deg")
                .sym(r"\operatorname{atan2}(a_4, a_1)")
                .subst(format!(
                    r"\operatorname{{atan2}}({}, {})",
                    num(est[3]),
                    num(est[0])
                ))
                .result(format!(r"{}^\circ", num(rotation))),
        )
        .value("parameters", Value::numbers(&est))
        .value("true_parameters", true_parameters.clone())
        .value("estimated_scale", scale)
        .value("estimated_rotation_deg", rotation);
    if let Some(sd) = &sd {
        step = step.value("std_dev", Value::numbers(sd));
    }
    s.step(step);
    // the noise the residuals should show: template noise plus the search
    // noise carried through the bilinear weights and the gain
    let expected = if noise > 0.0 {
        let m2 = mean_square_weights(&template, &m.params);
        let e = noise * (1.0 + m.params.gain().powi(2) * m2).sqrt();
        s.step(
            Step::new(
                "σ0 against the noise",
                "Each residual carries the template's noise and the search window's noise, the latter through the four bilinear weights w_k and the gain; averaged over the patch this is what σ0 should come out as.",
            )
            .relation(
                Relation::new(r"\sigma_0")
                    .key("sigma0")
                    .result(m.sigma0().map_or("–".to_string(), num)),
            )
            .relation(
                Relation::new(r"\sigma_0")
                    .key("expected_sigma0")
                    .op(r"\approx")
                    .sym(r"\sigma_n\sqrt{1 + a_7^2\,\overline{\textstyle\sum_k w_k^2}}")
                    .subst(format!(
                        r"{}\sqrt{{1 + {}^2 \times {}}}",
                        num(noise),
                        num(m.params.gain()),
                        num(m2)
                    ))
                    .value(e, ""),
            )
            .value("expected_sigma0", e),
        );
        Some(e)
    } else {
        None
    };
    s.result = Record::new()
        .with("parameters", Value::numbers(&est))
        .with("iterations", m.iterations.len())
        .with("converged", m.converged())
        .with("sigma0", m.sigma0())
        .with("true_parameters", true_parameters)
        .with(
            "std_dev",
            sd.as_ref().map_or(Value::Null, |v| Value::numbers(v)),
        )
        .with("status", m.status.word())
        .with("expected_sigma0", expected);
    s.note(
        NoteKind::Convention,
        "Lecture 21 writes the affine and the radiometric parts as two stacked systems of 2m rows with zero blocks (its second block's unknowns are misprinted as Δa5 … Δa8). Both parts describe the same grey values, so here they form one observation per pixel, T = a7·S(p, q) + a8, with all eight unknowns in one m × 8 design matrix — the formulation of worked examples 10–11.",
    ).about(&["parameters"]);
    if given {
        s.note(
            NoteKind::Convention,
            "Columns c (to the right) and rows r (downward) count from 1 as in the course notes: the estimates a3, a6 are the search-window position of the template's centre pixel.",
        )
        .about(&["parameters"]);
    } else {
        s.note(
            NoteKind::Convention,
            "The template is made from the search window with the same bilinear interpolation the matching uses, so without noise the model fits exactly and the estimates return the true values. Real images also carry the interpolation's own error: for a template sampled from a smooth continuous texture instead, the least-squares optimum itself lies up to about 0.1 px from the true shift (measured in this project's tests).",
        ).about(&["parameters", "sigma0"]);
    }
    if m.converged() {
        if let (Some(sd), Some(truth)) = (&sd, &truth) {
            let off: Vec<String> = (0..8)
                .filter(|&k| {
                    let d = (est.get(k).copied().unwrap_or(0.0)
                        - truth.a.get(k).copied().unwrap_or(0.0))
                    .abs();
                    d > 5.0 * sd.get(k).copied().unwrap_or(0.0) + 1e-3
                })
                .map(|k| format!("a{}", k + 1))
                .collect();
            if !off.is_empty() {
                s.note(
                    NoteKind::Warning,
                    format!(
                        "The run converged, but {} lie more than five standard deviations from the truth: it found another optimum. The start (identity, zero shift) is outside the pull-in range for this transformation.",
                        off.join(", ")
                    ),
                ).about(&["parameters"]);
            }
        }
    }
    Ok(s)
}

/// The pair this example matches, its start, the origin its shifts count
/// from (the search window's centre, or −1 for 1-based positions), and the
/// truth when it is known.
struct Pair {
    template: Grid,
    search: Grid,
    start: Params,
    origin: f64,
    truth: Option<Params>,
    noise: f64,
}

/// Seed 003's generated pair: a texture seen through a known affine and
/// radiometric change, started at the identity with zero shift.
fn generated_pair(s: &mut Solution, inputs: &Record) -> Result<Pair> {
    let i = Inputs(inputs);
    let size = i.number("patch_size")?;
    if size.rem_euclid(2.0) != 1.0 {
        return Err(Error::input(
            "patch_size",
            format!("must be odd, so that the template has a centre pixel (got {size})"),
        ));
    }
    let truth = matching::affine_from(
        i.number("shift_c")?,
        i.number("shift_r")?,
        i.number("rotation_deg")?,
        i.number("scale")?,
        i.number("shear")?,
        i.number("gain")?,
        i.number("offset")?,
    );
    let noise = i.number("noise")?;
    let seed = i.number("seed")?;
    let pair = matching::synthetic_pair(size as usize, &truth, noise, seed as u64)?;
    let a = &truth.a;
    s.step(
        Step::new(
            "The generated pair",
            "A smooth texture (six sinusoids, wavelengths 7–16 px, drawn with the random seed) fills the search window. The template is that window seen through the chosen transformation — resampled bilinearly at p = a1·u + a2·v + a3, q = a4·u + a5·v + a6 — then scaled by the gain and shifted by the offset; noise is added to both. u, v count from the template's centre, p, q from the search window's centre.",
        )
        .relation(
            Relation::new(cells(&[&["a_1", "a_2"], &["a_4", "a_5"]]))
                .sym(
                    Form::from("s")
                        .then(cells(&[&[r"\cos\theta", r"-\sin\theta"], &[r"\sin\theta", r"\cos\theta"]]))
                        .then(cells(&[&["1", "k"], &["0", "1"]])),
                )
                .subst(Form::grid("bmatrix", &[vec![a[0], a[1]], vec![a[3], a[4]]], "")),
        )
        .relation(Relation::new("T(u,v)").sym(r"a_7\,S(p,q) + a_8 + n"))
        .relation(
            Relation::new(cells(&[&["a_3"], &["a_6"]]))
                .subst(Form::column(&[a[2], a[5]], "")),
        )
        .relation(Relation::new("a_7").value(a[6], ""))
        .relation(Relation::new("a_8").value(a[7], ""))
        .relation(Relation::new(r"\sigma_n").value(noise, ""))
        .value("template", Value::matrix(&pair.template.rows()))
        .value("search", Value::matrix(&pair.search.rows()))
        .value("true_parameters", Value::numbers(&truth.a)),
    );
    Ok(Pair {
        start: Params::shift(pair.centre, pair.centre, 1.0, 0.0),
        origin: pair.centre,
        template: pair.template,
        search: pair.search,
        truth: Some(truth),
        noise,
    })
}

/// A given template and search window (as the image lab cuts them from a
/// photo), started at (c⁰, r⁰) with the identity, gain 1 and offset 0;
/// positions count from 1.
fn given_pair(s: &mut Solution, inputs: &Record) -> Result<Pair> {
    let Patches {
        tr,
        sr,
        template,
        search,
    } = patches(inputs)?;
    let i = Inputs(inputs);
    let (c0, r0) = (i.number("c0")?, i.number("r0")?);
    s.step(
        Step::new(
            "Template, search window and start",
            "The template's centre is placed at (c⁰, r⁰) in the search window, columns c to the right and rows r downward, both counted from 1; u, v count from the template's centre.",
        )
        .relation(Relation::new("T").key("template").subst(Form::grid("bmatrix", &tr, "T")))
        .relation(Relation::new("(c^0, r^0)").subst(format!("({}, {})", num(c0), num(r0))))
        .value("template", Value::matrix(&tr))
        .value("search", Value::matrix(&sr)),
    );
    Ok(Pair {
        template,
        search,
        start: Params::shift(c0 - 1.0, r0 - 1.0, 1.0, 0.0),
        origin: -1.0,
        truth: None,
        noise: 0.0,
    })
}

/// A matrix of symbols (no name).
fn cells(rows: &[&[&str]]) -> Form {
    Form::grid_tex(
        "bmatrix",
        rows.iter()
            .map(|r| r.iter().map(|c| c.to_string()).collect())
            .collect(),
        "",
    )
}

/// Mean over the template pixels of Σ w_k² of the four bilinear weights at
/// the parameters' positions.
fn mean_square_weights(t: &Grid, p: &Params) -> f64 {
    let (w, h) = (t.width(), t.height());
    let (cu, cv) = ((w as f64 - 1.0) / 2.0, (h as f64 - 1.0) / 2.0);
    let mut sum = 0.0;
    for j in 0..h {
        for i in 0..w {
            let (c, r) = p.map(i as f64 - cu, j as f64 - cv);
            let (fc, fr) = (c - c.floor(), r - r.floor());
            sum += ((1.0 - fc).powi(2) + fc * fc) * ((1.0 - fr).powi(2) + fr * fr);
        }
    }
    sum / (w * h).max(1) as f64
}

// ---------------------------------------------------------------- practice

/// The affine part's parameters and the scale: to 0.001 (0.1 %).
const AFFINE: Tolerance = Tolerance::abs(0.001);

fn boxes(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("parameters[1]", "a₁ (converged)", None, AFFINE).nudge(
            "The affine model's first parameter after convergence: s·cos θ when there is no shear.",
        ),
        BoxDef::new("parameters[4]", "a₄ (converged)", None, AFFINE)
            .nudge("The fourth parameter: s·sin θ when there is no shear."),
        BoxDef::new("parameters[3]", "Shift a₃ (columns)", Some("px"), SHIFT)
            .nudge("The affine model's column shift after convergence.")
            .axis(),
        BoxDef::new("parameters[6]", "Shift a₆ (rows)", Some("px"), SHIFT)
            .nudge("The row shift after convergence.")
            .axis(),
        BoxDef::new("estimated_scale", "Scale s = √(a₁² + a₄²)", None, AFFINE)
            .nudge("[a₁ a₂; a₄ a₅] = s·R(θ) without shear: the first column is s·(cos θ, sin θ)."),
        BoxDef::new(
            "estimated_rotation_deg",
            "Rotation θ = atan2(a₄, a₁)",
            Some("°"),
            Tolerance::abs(0.05),
        )
        .nudge("The angle of the first column (a₁, a₄), in degrees."),
    ]
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = EXAMPLE.run(i)?;
    let mut out = Record::new();
    let mut p = [0.0; 7];
    for k in [1, 4, 3, 6] {
        let key = format!("parameters[{k}]");
        p[k] = or_given(g, &key, value_in(&s, &key)?);
        out.set(&key, p[k]);
    }
    let scale = or_given(g, "estimated_scale", p[1].hypot(p[4]));
    Ok(out
        .with("estimated_scale", scale)
        .with("estimated_rotation_deg", p[4].atan2(p[1]).to_degrees()))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let s = EXAMPLE.run(i)?;
    let (a1, a4, a3, a6) = (
        value_in(&s, "parameters[1]")?,
        value_in(&s, "parameters[4]")?,
        value_in(&s, "parameters[3]")?,
        value_in(&s, "parameters[6]")?,
    );
    const SWAP: &str = "a₃ shifts the columns c, a₆ the rows r.";
    let theta = a4.atan2(a1);
    Ok(vec![
        Mistake::new("parameters[3]", "rows and columns swapped", SWAP, a6),
        Mistake::new("parameters[6]", "rows and columns swapped", SWAP, a3),
        Mistake::new(
            "estimated_rotation_deg",
            "degrees vs radians",
            "atan2 gives radians; the box asks for degrees (× 180/π).",
            theta,
        ),
        Mistake::new(
            "estimated_scale",
            "a₁ taken as the scale",
            "a₁ = s·cos θ: the scale is the length of the column (a₁, a₄).",
            a1,
        ),
    ])
}

/// A generated 11 × 11 pair with a small shift, rotation, scale, gain and
/// offset, within the pull-in range of its start.
fn generate(rng: &mut Rng) -> Record {
    let shift_c = rng.num(-15, 15) / 10.0;
    let shift_r = rng.num(-15, 15) / 10.0;
    // The pull-in range of an 11×11 patch: shifts of 1.5 px along both axes
    // at once (≈2 px) with a rotation can leave the window. The shift is kept
    // within 1.5 px of the start (only the row shift of such a draw is
    // shortened, so every other variant keeps its numbers).
    let reach = (1.5f64 * 1.5 - shift_c * shift_c).max(0.0).sqrt();
    let shift_r = if shift_r.abs() > reach {
        shift_r.signum() * (reach * 10.0).floor() / 10.0 + 0.0
    } else {
        shift_r
    };
    Record::new()
        .with("patch_size", 11.0)
        .with("shift_c", shift_c)
        .with("shift_r", shift_r)
        .with("rotation_deg", rng.num(-5, 5))
        .with("scale", rng.num(95, 105) / 100.0)
        .with("shear", 0.0)
        .with("gain", rng.num(90, 120) / 100.0)
        .with("offset", rng.num(-10, 10))
        .with("noise", rng.num(0, 2))
        .with("seed", texture(rng.num(1, 100)))
}

/// The texture seed of a generated pair. Five of `synthetic_pair`'s
/// textures (found by the release audit over every variant) leave the 11×11
/// patch with a weak gradient in one direction: with them LSM takes 30–75
/// iterations or walks out of the window. Their variants take the next
/// texture instead (only those variants change).
fn texture(seed: f64) -> f64 {
    const WEAK: [f64; 5] = [4.0, 25.0, 62.0, 81.0, 97.0];
    if WEAK.contains(&seed) {
        seed + 1.0
    } else {
        seed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn numbers_of(s: &Solution, key: &str) -> Vec<f64> {
        match s.result.get(key) {
            Some(Value::List(xs)) => xs.iter().filter_map(Value::as_f64).collect(),
            other => panic!("{key}: {other:?}"),
        }
    }

    fn step_matrix(s: &Solution, key: &str) -> Value {
        s.steps
            .iter()
            .find_map(|st| st.values.get(key).cloned())
            .unwrap_or_else(|| panic!("{key}: in no step"))
    }

    #[test]
    fn given_patches_match_as_the_generated_pair_does() {
        // the generated pair, handed over as given patches with the same start
        let g = EXAMPLE.run(&Record::new()).unwrap();
        let search = step_matrix(&g, "search");
        let n = match &search {
            Value::List(rows) => rows.len() as f64,
            _ => panic!("search"),
        };
        let origin = (n - 1.0) / 2.0;
        let inputs = Record::new()
            .with("pair", "patches")
            .with("template", step_matrix(&g, "template"))
            .with("search", search)
            .with("c0", origin + 1.0)
            .with("r0", origin + 1.0);
        let p = EXAMPLE.run(&inputs).unwrap();
        let (eg, ep) = (numbers_of(&g, "parameters"), numbers_of(&p, "parameters"));
        for k in 0..8 {
            // a3, a6: from the window's centre there, 1-based positions here
            let shift = if k == 2 || k == 5 { origin + 1.0 } else { 0.0 };
            assert!(
                (ep[k] - (eg[k] + shift)).abs() < 1e-9,
                "a{}: {ep:?} vs {eg:?}",
                k + 1
            );
        }
        assert_eq!(p.result.get("true_parameters"), Some(&Value::Null));
        assert_eq!(p.result.get("converged"), Some(&Value::Bool(true)));
        // the default given pair: 4°, 1.05, centre (6.3, 5.8) within the
        // rounding of its grey values to integers
        let d = EXAMPLE.run(&Record::new().with("pair", "patches")).unwrap();
        let e = numbers_of(&d, "parameters");
        let (sn, cs) = 4f64.to_radians().sin_cos();
        assert!(
            (e[0] - 1.05 * cs).abs() < 0.02 && (e[3] - 1.05 * sn).abs() < 0.02,
            "{e:?}"
        );
        assert!(
            (e[2] - 6.3).abs() < 0.05 && (e[5] - 5.8).abs() < 0.05,
            "{e:?}"
        );
        assert!(
            (e[6] - 1.1).abs() < 0.05 && (e[7] + 5.0).abs() < 5.0,
            "{e:?}"
        );
    }
}
