//! Seed 000, Examples 10–11, and seed 003's affine + radiometric
//! generalisation: least-squares matching step by step — the first iteration
//! laid out as the seed does, then every iteration as a table, and how the
//! run ended.

use super::fields::{Field, Inputs, Kind};
use super::Entry;
use crate::error::{Error, Result};
use crate::matching::{
    self, Gradients, Iteration, Matching, Model, Param, Params, Settings, Status,
};
use crate::raster::Grid;
use crate::solution::{
    exact_minus_printed, fmt_sig, num, tex, NoteKind, Record, Solution, Step, Value,
};

const TOPIC: &str = "Least-squares matching";
/// Largest 1-D template or search window.
const MAX_1D: usize = 512;
/// Largest side of a 2-D template or search window.
const MAX_2D: usize = 64;

const EX5_TEMPLATE: [f64; 7] = [1.0, 2.0, 9.0, 9.0, 8.0, 2.0, 1.0];
const EX5_SEARCH: [f64; 12] = [1.0, 2.0, 2.0, 1.0, 1.0, 3.0, 8.0, 8.0, 6.0, 1.0, 1.0, 1.0];

fn ex7_template() -> Vec<Vec<f64>> {
    vec![
        vec![30.0, 50.0, 30.0],
        vec![50.0, 50.0, 50.0],
        vec![30.0, 50.0, 30.0],
    ]
}

fn ex7_search() -> Vec<Vec<f64>> {
    vec![
        vec![44.0, 45.0, 64.0, 50.0, 45.0, 43.0],
        vec![43.0, 44.0, 63.0, 48.0, 49.0, 45.0],
        vec![45.0, 47.0, 65.0, 50.0, 45.0, 45.0],
        vec![62.0, 62.0, 69.0, 64.0, 64.0, 63.0],
        vec![48.0, 48.0, 68.0, 51.0, 55.0, 50.0],
        vec![41.0, 44.0, 63.0, 48.0, 42.0, 47.0],
    ]
}

/// Example 11's printed design matrix (columns ∂G/∂c, ∂G/∂r).
const EX11_PRINTED_GRADIENTS: [[f64; 2]; 9] = [
    [9.0, 7.5],
    [1.5, 2.0],
    [-7.5, 7.0],
    [3.5, 0.5],
    [1.0, 1.5],
    [-2.5, 0.5],
    [10.0, -7.0],
    [1.5, -0.5],
    [-8.5, -6.5],
];

pub fn entries() -> Vec<Entry> {
    vec![
        Entry {
            id: "lsm-1d",
            title: "1-D least-squares matching",
            topic: TOPIC,
            source: "Worked examples, Example 10",
            summary: "Refines the best correlation position of Example 5 to a subpixel shift (and optionally a gain and offset) by iterated least squares.",
            fields: lsm_1d_fields,
            solve: Some(lsm_1d),
        },
        Entry {
            id: "lsm-2d",
            title: "2-D least-squares matching",
            topic: TOPIC,
            source: "Worked examples, Example 11",
            summary: "Refines the best correlation position of Example 7 to a subpixel shift with a gain and offset by iterated least squares.",
            fields: lsm_2d_fields,
            solve: Some(lsm_2d),
        },
        Entry {
            id: "lsm-affine",
            title: "Affine + radiometric least-squares matching",
            topic: TOPIC,
            source: "Lecture 21: Image matching",
            summary: "A generated patch pair with a known shift, rotation, scale, shear, gain and offset, recovered by eight-parameter least-squares matching.",
            fields: lsm_affine_fields,
            solve: Some(lsm_affine),
        },
    ]
}

// ---------------------------------------------------------------- fields

fn vector(key: &'static str, label: &'static str, default: &[f64]) -> Field {
    Field {
        key,
        label,
        help: "",
        kind: Kind::Vector {
            min_len: 3,
            max_len: MAX_1D,
        },
        default: Value::numbers(default),
        when: None,
    }
}

fn matrix(key: &'static str, label: &'static str, default: &[Vec<f64>]) -> Field {
    Field {
        key,
        label,
        help: "",
        kind: Kind::Matrix {
            rows: None,
            cols: None,
        },
        default: Value::matrix(default),
        when: None,
    }
}

fn flag(key: &'static str, label: &'static str, default: bool) -> Field {
    Field {
        key,
        label,
        help: "",
        kind: Kind::Flag,
        default: Value::Bool(default),
        when: None,
    }
}

const GRADIENT_OPTIONS: &[(&str, &str)] = &[
    (
        "search-window",
        "Search window: neighbours outside the patch from the search window (the stated formula)",
    ),
    (
        "patch-edge",
        "Patch edge: inside the patch only, an edge pixel stands in for its outside neighbour (the printed matrix)",
    ),
];

fn max_iterations() -> Field {
    Field::integer(
        "max_iterations",
        "Iteration limit",
        matching::DEFAULT_ITERATIONS as f64,
    )
    .range(1.0, matching::MAX_ITERATIONS as f64)
    .help("The run stops as “not converged” when this many iterations have not reached the tolerances.")
}

fn lsm_1d_fields() -> Vec<Field> {
    vec![
        vector("template", "Template T", &EX5_TEMPLATE)
            .help("The template's grey values, left to right."),
        vector("search", "Search window S", &EX5_SEARCH)
            .help("The search window's grey values; positions count from 1."),
        Field::number("c0", "Start position c⁰", 8.0)
            .unit("px")
            .range(1.0, MAX_1D as f64)
            .help("Search-window position of the template's centre pixel to start from (Example 5's best match)."),
        flag("radiometric", "Estimate gain a and offset b", false)
            .help("Also estimate the linear radiometric change G_t = a·G_s + b (start a⁰ = 1, b⁰ = 0)."),
        max_iterations(),
    ]
}

fn lsm_2d_fields() -> Vec<Field> {
    vec![
        matrix("template", "Template T", &ex7_template())
            .help("The template's grey values, rows top to bottom."),
        matrix("search", "Search window S", &ex7_search())
            .help("The search window's grey values; columns c and rows r count from 1."),
        Field::number("c0", "Start column c⁰", 3.0)
            .unit("px")
            .range(1.0, MAX_2D as f64)
            .help("Column of the template's centre in the search window (Example 7's best match)."),
        Field::number("r0", "Start row r⁰", 4.0)
            .unit("px")
            .range(1.0, MAX_2D as f64)
            .help("Row of the template's centre in the search window."),
        Field::number("a0", "Start gain a⁰", 1.0)
            .range(-1000.0, 1000.0)
            .help("Start value of the gain a in G_t = a·G_s + b."),
        Field::number("b0", "Start offset b⁰", -20.0)
            .range(-10000.0, 10000.0)
            .help("Start value of the offset b."),
        Field {
            key: "gradients",
            label: "Gradients at the patch edge",
            help: "How ∂G_s/∂c and ∂G_s/∂r are taken at the patch's edge pixels.",
            kind: Kind::Choice {
                options: GRADIENT_OPTIONS,
            },
            default: Value::Text("search-window".to_string()),
            when: None,
        },
        max_iterations(),
    ]
}

fn lsm_affine_fields() -> Vec<Field> {
    let n = |key, label, default, lo, hi, unit: Option<&'static str>, help| {
        let f = Field::number(key, label, default).range(lo, hi).help(help);
        match unit {
            Some(u) => f.unit(u),
            None => f,
        }
    };
    vec![
        Field::integer("patch_size", "Template size", 21.0)
            .range(5.0, 41.0)
            .help("Side of the square template in pixels (odd)."),
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
            .help("Chooses the texture and the noise; the same seed gives the same pair."),
        max_iterations(),
    ]
}

// ---------------------------------------------------------------- inputs

fn numbers(inputs: &Record, key: &str) -> Result<Vec<f64>> {
    match inputs.get(key) {
        Some(Value::List(xs)) => xs
            .iter()
            .map(|x| {
                x.as_f64().ok_or_else(|| {
                    Error::Internal(format!("validated input \"{key}\" is not numeric"))
                })
            })
            .collect(),
        _ => Err(Error::Internal(format!(
            "validated input \"{key}\" is not a list"
        ))),
    }
}

fn rows(inputs: &Record, key: &str) -> Result<Vec<Vec<f64>>> {
    match inputs.get(key) {
        Some(Value::List(rs)) => rs
            .iter()
            .map(|r| match r {
                Value::List(xs) => xs
                    .iter()
                    .map(|x| {
                        x.as_f64().ok_or_else(|| {
                            Error::Internal(format!("validated input \"{key}\" is not numeric"))
                        })
                    })
                    .collect(),
                _ => Err(Error::Internal(format!(
                    "validated input \"{key}\" is not a matrix"
                ))),
            })
            .collect(),
        _ => Err(Error::Internal(format!(
            "validated input \"{key}\" is not a matrix"
        ))),
    }
}

fn flag_value(inputs: &Record, key: &str) -> Result<bool> {
    match inputs.get(key) {
        Some(Value::Bool(b)) => Ok(*b),
        _ => Err(Error::Internal(format!(
            "validated input \"{key}\" is not a flag"
        ))),
    }
}

fn text(inputs: &Record, key: &str) -> Result<String> {
    match inputs.get(key) {
        Some(Value::Text(t)) => Ok(t.clone()),
        _ => Err(Error::Internal(format!(
            "validated input \"{key}\" is not a choice"
        ))),
    }
}

/// True when the listed inputs equal their seed defaults.
fn seed_inputs(fields: &[Field], inputs: &Record, keys: &[&str]) -> bool {
    keys.iter().all(|k| {
        fields
            .iter()
            .find(|f| f.key == *k)
            .is_some_and(|f| inputs.get(k) == Some(&f.default))
    })
}

// ---------------------------------------------------------------- LaTeX

fn column(xs: &[f64]) -> String {
    let body: Vec<String> = xs.iter().map(|x| num(*x)).collect();
    format!(r"\begin{{bmatrix}} {} \end{{bmatrix}}", body.join(r" \\ "))
}

fn bmatrix(rows: &[Vec<String>]) -> String {
    let body: Vec<String> = rows.iter().map(|r| r.join(" & ")).collect();
    format!(r"\begin{{bmatrix}} {} \end{{bmatrix}}", body.join(r" \\ "))
}

fn numeric(rows: &[Vec<f64>]) -> String {
    bmatrix(
        &rows
            .iter()
            .map(|r| r.iter().map(|x| num(*x)).collect())
            .collect::<Vec<_>>(),
    )
}

fn short(x: f64) -> String {
    fmt_sig(x, 5)
}

/// The symbol of an estimated parameter's increment, per example.
fn symbols(est: &[Param], seed000: bool) -> Vec<&'static str> {
    est.iter()
        .map(|p| match (p, seed000) {
            (Param::A3, true) => "c",
            (Param::A6, true) => "r",
            (Param::Gain, true) => "a",
            (Param::Offset, true) => "b",
            (Param::A1, _) => "a_1",
            (Param::A2, _) => "a_2",
            (Param::A3, _) => "a_3",
            (Param::A4, _) => "a_4",
            (Param::A5, _) => "a_5",
            (Param::A6, _) => "a_6",
            (Param::Gain, _) => "a_7",
            (Param::Offset, _) => "a_8",
        })
        .collect()
}

// ---------------------------------------------------------------- shared steps

/// The value a parameter shows as: positions 1-based (seed 000) or relative
/// to the search window's centre (seed 003).
fn shown(p: &Params, q: Param, origin: f64) -> f64 {
    let x = p.a[q.index()];
    match q {
        Param::A3 | Param::A6 => x - origin,
        _ => x,
    }
}

fn normal_step(it: &Iteration, syms: &[&str]) -> Step {
    let adj = &it.adjustment;
    let dx: Vec<String> = syms.iter().map(|s| format!(r"d{s}")).collect();
    Step::new(
        "Normal equations and increments (iteration 1)",
        "N = AᵀA and AᵀdL; their solution is the first set of increments.",
    )
    .formula(
        r"d\mathbf{X} = (A^\mathsf{T}A)^{-1}A^\mathsf{T}d\mathbf{L}",
        format!(
            r"A^\mathsf{{T}}A = {},\quad A^\mathsf{{T}}d\mathbf{{L}} = {},\quad {} = {}",
            numeric(&adj.n),
            column(&adj.atl),
            column_sym(&dx),
            column(&it.increments)
        ),
    )
    .value("N", Value::matrix(&adj.n))
    .value("AtL", Value::numbers(&adj.atl))
    .value("increments", Value::numbers(&it.increments))
}

fn column_sym(xs: &[String]) -> String {
    format!(r"\begin{{bmatrix}} {} \end{{bmatrix}}", xs.join(r" \\ "))
}

/// The iteration table: parameters where each iteration resampled, its
/// increments and σ0; plus the per-iteration arrays for the figures.
fn table_step(m: &Matching, syms: &[&str], origin: f64) -> Step {
    let mut header: Vec<String> = vec!["k".into()];
    header.extend(syms.iter().map(|s| s.to_string()));
    header.extend(syms.iter().map(|s| format!("d{s}")));
    header.push(r"\sigma_0".into());
    let mut lines = vec![header.join(" & ")];
    let mut per_param: Vec<Vec<f64>> = vec![Vec::new(); m.estimated.len()];
    let mut per_inc: Vec<Vec<f64>> = vec![Vec::new(); m.estimated.len()];
    let mut sigma: Vec<Value> = Vec::new();
    for (k, it) in m.iterations.iter().enumerate() {
        let mut row = vec![(k + 1).to_string()];
        for (j, q) in m.estimated.iter().enumerate() {
            let v = shown(&it.params, *q, origin);
            row.push(short(v));
            if let Some(col) = per_param.get_mut(j) {
                col.push(v);
            }
        }
        for (j, d) in it.increments.iter().enumerate() {
            row.push(fmt_sig(*d, 3));
            if let Some(col) = per_inc.get_mut(j) {
                col.push(*d);
            }
        }
        row.push(it.adjustment.sigma0.map_or("–".to_string(), short));
        sigma.push(it.adjustment.sigma0.into());
        lines.push(row.join(" & "));
    }
    let mut last = vec![r"\text{end}".to_string()];
    last.extend(
        m.estimated
            .iter()
            .map(|q| short(shown(&m.params, *q, origin))),
    );
    last.extend(m.estimated.iter().map(|_| String::new()));
    last.push(String::new());
    lines.push(last.join(" & "));
    let cols = "r|".to_string() + &"r".repeat(syms.len()) + "|" + &"r".repeat(syms.len()) + "|r";
    let symbolic = format!(
        r"{} \leftarrow {} + d{}",
        syms.first().copied().unwrap_or("x"),
        syms.first().copied().unwrap_or("x"),
        syms.first().copied().unwrap_or("x")
    );
    let mut step = Step::new(
        "Every iteration",
        "Each row: the parameters the iteration resampled at, the increments it solved for, and σ0 of its adjustment. The last row holds the parameters after the last update.",
    )
    .formula(
        &symbolic,
        format!(
            r"\begin{{array}}{{{cols}}} {} \end{{array}}",
            lines.join(r" \\ ")
        ),
    );
    for (j, s) in syms.iter().enumerate() {
        let clean = s.replace('_', "");
        step = step
            .value(
                &clean,
                Value::numbers(per_param.get(j).map_or(&[][..], |v| v)),
            )
            .value(
                &format!("d{clean}"),
                Value::numbers(per_inc.get(j).map_or(&[][..], |v| v)),
            );
    }
    step.value("sigma0", Value::List(sigma))
        .value(
            "patches",
            Value::List(
                m.iterations
                    .iter()
                    .map(|it| Value::matrix(&it.patch.rows()))
                    .collect(),
            ),
        )
        .value(
            "differences",
            Value::List(
                m.iterations
                    .iter()
                    .map(|it| {
                        let w = it.patch.width().max(1);
                        Value::matrix(&it.dl.chunks(w).map(<[f64]>::to_vec).collect::<Vec<_>>())
                    })
                    .collect(),
            ),
        )
}

/// The closing step and, unless converged, a warning note.
/// The convergence test in the parameters actually estimated (`syms`, see
/// [`symbols`]), and whether it has a radiometric part.
fn convergence_test(syms: &[&str]) -> (&'static str, bool) {
    let has = |s: &str| syms.contains(&s);
    if has("a_1") {
        (
            r"\max_i \lVert d\mathbf{x}_i \rVert \le 10^{-4}\ \text{px},\quad \max_i |da_7\, G_i + da_8| \le 10^{-3}",
            true,
        )
    } else {
        match (has("r"), has("a")) {
            (true, true) => (
                r"\sqrt{dc^2 + dr^2} \le 10^{-4}\ \text{px},\quad \max_i |da\, G_i + db| \le 10^{-3}",
                true,
            ),
            (true, false) => (r"\sqrt{dc^2 + dr^2} \le 10^{-4}\ \text{px}", false),
            (false, true) => (
                r"|dc| \le 10^{-4}\ \text{px},\quad \max_i |da\, G_i + db| \le 10^{-3}",
                true,
            ),
            (false, false) => (r"|dc| \le 10^{-4}\ \text{px}", false),
        }
    }
}

/// A symbol such as `a_7` as prose writes it: `a₇`.
fn prose_symbol(s: &str) -> String {
    const SUB: [char; 10] = ['₀', '₁', '₂', '₃', '₄', '₅', '₆', '₇', '₈', '₉'];
    s.replace('_', "")
        .chars()
        .map(|c| c.to_digit(10).map_or(c, |d| SUB[d as usize]))
        .collect()
}

fn status_step(s: &mut Solution, m: &Matching, syms: &[&str], limit: usize) {
    let k = m.iterations.len();
    let last = m.iterations.last();
    let incs = last.map_or(String::new(), |it| {
        syms.iter()
            .zip(&it.increments)
            .map(|(s, d)| format!("d{} = {}", prose_symbol(s), fmt_sig(*d, 3)))
            .collect::<Vec<_>>()
            .join(", ")
    });
    let (test, radiometric) = convergence_test(syms);
    let (title, text) = match &m.status {
        Status::Converged => (
            "Converged".to_string(),
            format!(
                "Converged in {k} iteration{}: the last increments ({incs}) move no template pixel by more than {} px{}.",
                if k == 1 { "" } else { "s" },
                matching::POSITION_TOL,
                if radiometric {
                    format!(
                        " and change no modelled grey value by more than {}",
                        matching::GREY_TOL
                    )
                } else {
                    String::new()
                }
            ),
        ),
        Status::NotConverged => (
            "Not converged".to_string(),
            format!(
                "Not converged within the limit of {limit} iterations. The last increments were {incs} (largest pixel movement {} px); raise the iteration limit or start closer.",
                last.map_or("–".to_string(), |it| fmt_sig(it.max_move, 3))
            ),
        ),
        Status::LeftWindow { detail } => (
            "Stopped: the patch left the search window".to_string(),
            format!(
                "After {k} iteration{} the updated parameters put the patch outside the search window: {detail}. Bilinear resampling needs each patch pixel's four neighbours, so the run stops here; the start is probably outside the pull-in range.",
                if k == 1 { "" } else { "s" }
            ),
        ),
        Status::Degenerate { reason } => (
            "Stopped: degenerate".to_string(),
            format!("Iteration {} could not be solved: {reason}.", k + 1),
        ),
    };
    s.step(
        Step::new(&title, &text)
            .formula(test, format!(r"\text{{{}}}", m.status.word()))
            .value("status", m.status.word())
            .value("iterations", k),
    );
    if m.status != Status::Converged {
        s.note(NoteKind::Warning, text)
            .about(&["converged", "status"]);
    }
    let clamped: Vec<(usize, usize)> = m
        .iterations
        .iter()
        .enumerate()
        .filter(|(_, it)| it.clamped > 0)
        .map(|(k, it)| (k + 1, it.clamped))
        .collect();
    if let (Some(first), Some(last)) = (clamped.first(), clamped.last()) {
        let most = clamped.iter().map(|c| c.1).max().unwrap_or(0);
        s.note(
            NoteKind::Warning,
            format!(
                "Border samples outside the search window in {} of the iterations ({} … {}), up to {most} per iteration. The patch itself stayed inside; the one-pixel border around it reached past the window's edge, and those samples took the value at the nearest point of the window, which flattens the gradient at that edge.",
                clamped.len(),
                first.0,
                last.0
            ),
        ).about(&["iterations"]);
    }
}

fn settings(model: Model, gradients: Gradients, inputs: &Record) -> Result<Settings> {
    let limit = Inputs(inputs).number("max_iterations")?;
    Ok(Settings {
        model,
        gradients,
        max_iterations: limit as usize,
    })
}

/// The run's error, said of the input it is about.
fn said_of(e: Error, start_fields: &str) -> Error {
    match e {
        Error::InvalidInput { field, reason } if field == "start" => Error::InvalidInput {
            field: start_fields.to_string(),
            reason,
        },
        other => other,
    }
}

// ---------------------------------------------------------------- lsm-1d

/// What each result key is, for the page's result table.
fn label_results(s: &mut Solution) {
    s.label_present(&[
        ("first_dc", "First iteration: shift increment dc", "px"),
        ("first_dr", "First iteration: shift increment dr", "px"),
        ("first_da", "First iteration: gain increment da", ""),
        (
            "first_db",
            "First iteration: offset increment db",
            "grey values",
        ),
        ("c", "Matched position c (after the last iteration)", "px"),
        ("r", "Matched position r (after the last iteration)", "px"),
        ("a", "Gain a", ""),
        ("b", "Offset b", "grey values"),
        ("iterations", "Iterations", ""),
        ("converged", "Converged", ""),
        ("status", "How the run ended", ""),
        ("sigma0", "σ0 of the last iteration", "grey values"),
        ("parameters", "Estimates a1 … a8", ""),
        ("true_parameters", "True values a1 … a8 (generated)", ""),
        ("std_dev", "Standard deviations of a1 … a8", ""),
        (
            "expected_sigma0",
            "Expected σ0 from the noise",
            "grey values",
        ),
    ]);
}

fn lsm_1d(inputs: &Record) -> Result<Solution> {
    let t = numbers(inputs, "template")?;
    let sw = numbers(inputs, "search")?;
    let c0 = Inputs(inputs).number("c0")?;
    let radiometric = flag_value(inputs, "radiometric")?;
    let model = if radiometric {
        Model::ShiftRadiometric
    } else {
        Model::Shift
    };
    let set = settings(model, Gradients::SearchWindow, inputs)?;
    let m = matching::match_1d(&t, &sw, Params::shift(c0 - 1.0, 0.0, 1.0, 0.0), set)
        .map_err(|e| said_of(e, "c0"))?;
    let syms = symbols(&m.estimated, true);
    let n = t.len();
    let half = (n as f64 - 1.0) / 2.0;
    let mut s = Solution::new("lsm-1d", "1-D least-squares matching", inputs.clone());

    let first_pos: Vec<f64> = (0..n).map(|i| c0 - half + i as f64).collect();
    s.step(
        Step::new(
            "Template and start",
            "The template's centre is placed at the start position c⁰ of the search window; the template's pixels then fall on these search-window positions.",
        )
        .formula(
            r"c_i = c^0 + \left(i - \tfrac{n+1}{2}\right),\quad i = 1 \dots n",
            format!(
                r"T = {},\quad c_i = {}",
                column(&t),
                column(&first_pos)
            ),
        )
        .value("template", Value::numbers(&t))
        .value("search", Value::numbers(&sw))
        .value("positions", Value::numbers(&first_pos)),
    );
    let (eq, lin) = if radiometric {
        (
            r"G_t(c) + V = a\,G_s(c + dc) + b",
            r"[G_t(c) - (a^0 G_s(c) + b^0)] + V = a^0\frac{\partial G_s(c)}{\partial c}\,dc + G_s(c)\,da + db",
        )
    } else {
        (
            r"G_t(c) + V = G_s(c + dc)",
            r"[G_t(c) - G_s(c)] + V = \frac{\partial G_s(c)}{\partial c}\,dc",
        )
    };
    s.step(
        Step::new(
            "Observation equation",
            "Each template pixel is one observation. Taylor's first-order term turns the unknown shift into a linear unknown; the gradient is the central difference (G_s(c+1) − G_s(c−1))/2 of the search window, resampled at the current position.",
        )
        .formula(eq, lin.to_string()),
    );
    if let Some(it) = m.iterations.first() {
        first_iteration_1d(&mut s, it, &t, &syms);
    }
    s.step(table_step(&m, &syms, -1.0));
    status_step(&mut s, &m, &syms, set.max_iterations);

    let first = m.iterations.first();
    let inc = |k: usize| first.and_then(|it| it.increments.get(k).copied());
    s.result = Record::new()
        .with("first_dc", inc(0))
        .with("first_da", if radiometric { inc(1) } else { None })
        .with("first_db", if radiometric { inc(2) } else { None })
        .with("c", m.params.a[2] + 1.0)
        .with("a", m.params.gain())
        .with("b", m.params.offset())
        .with("iterations", m.iterations.len())
        .with("converged", m.converged())
        .with("status", m.status.word())
        .with("sigma0", m.sigma0());
    s.note(
        NoteKind::Convention,
        "Positions count from 1 as in the course notes; c is the search-window position of the template's centre pixel. dL + V = A·dX with V = A·dX − dL.",
    ).about(&["c"]);
    if seed_inputs(&lsm_1d_fields(), inputs, &["template", "search", "c0"]) {
        ex10_notes(&mut s, &m, radiometric);
    }
    label_results(&mut s);
    Ok(s)
}

fn first_iteration_1d(s: &mut Solution, it: &Iteration, t: &[f64], syms: &[&str]) {
    let b = it.bordered.data();
    let g = it.patch.data();
    let (a0, b0) = (it.params.gain(), it.params.offset());
    let modelled: Vec<f64> = g.iter().map(|x| a0 * x + b0).collect();
    s.step(
        Step::new(
            "Difference vector dL (iteration 1)",
            "The template minus the search patch resampled at the current position (and scaled by the current gain and offset).",
        )
        .formula(
            r"d\mathbf{L} = G_t - (a^0 G_s + b^0)",
            format!(
                r"d\mathbf{{L}} = {} - {} = {}",
                column(t),
                column(&modelled),
                column(&it.dl)
            ),
        )
        .value("patch", Value::numbers(g))
        .value("dL", Value::numbers(&it.dl)),
    );
    let rows: Vec<Vec<String>> = (0..g.len())
        .map(|i| {
            let right = b.get(i + 2).copied().unwrap_or(0.0);
            let left = b.get(i).copied().unwrap_or(0.0);
            let mut row = vec![format!(r"({} - {})/2", num(right), tex(left))];
            for (k, sym) in syms.iter().enumerate().skip(1) {
                let v = it.a.get(i).and_then(|r| r.get(k)).copied().unwrap_or(0.0);
                let _ = sym;
                row.push(num(v));
            }
            row
        })
        .collect();
    let gain_note = if it.params.gain() == 1.0 {
        ""
    } else {
        r"a^0\,"
    };
    s.step(
        Step::new(
            "Design matrix A (iteration 1)",
            "The gradient column is the central difference of the resampled search window: the neighbours one pixel left and right of each patch pixel, the outermost ones from the one-pixel border around the patch.",
        )
        .formula(
            &format!(r"A_{{i,1}} = {gain_note}\frac{{G_s(c_i+1) - G_s(c_i-1)}}{{2}}"),
            format!(r"A = {} = {}", bmatrix(&rows), numeric(&it.a)),
        )
        .value("A", Value::matrix(&it.a))
        .value("bordered", Value::numbers(b)),
    );
    s.step(normal_step(it, syms).value(
        "c_after_first",
        it.params.a[2] + 1.0 + it.increments.first().copied().unwrap_or(0.0),
    ));
}

fn ex10_notes(s: &mut Solution, m: &Matching, radiometric: bool) {
    let Some(first) = m.iterations.first() else {
        return;
    };
    let dc = first.increments.first().copied().unwrap_or(0.0);
    let mut printed = Record::new();
    if radiometric {
        printed = printed
            .with("first_dc", -0.295)
            .with("first_da", 0.156)
            .with("first_db", -0.053);
        let da = first.increments.get(1).copied().unwrap_or(0.0);
        let db = first.increments.get(2).copied().unwrap_or(0.0);
        s.note(
            NoteKind::Rounding,
            format!(
                "The course notes print dX = [−0.295, 0.156, −0.053]; exactly dc = {}, da = {} (= 5/32), db = {} (= −3/56). The last rounds to −0.054: the course notes cut it off instead of rounding.",
                num(dc),
                num(da),
                num(db)
            ),
        ).about(&["first_dc", "first_da", "first_db"]);
        s.note(
            NoteKind::Convention,
            "With a⁰ = 1 and b⁰ = 0 the gradient column is orthogonal to the columns G_s and 1 (Σ∂G·G_s = 0 and Σ∂G = 0 here), so the first dc is the same as without radiometry.",
        ).about(&["first_da", "first_db"]);
    } else {
        printed = printed
            .with("first_dc", -0.2945)
            .with("c_after_first", 7.705);
        s.label(
            "c_after_first",
            "Position c after the first iteration",
            "px",
        );
        s.note(
            NoteKind::Rounding,
            format!(
                "The course notes print dc = −0.2945; exactly dc = AᵀdL / AᵀA = −11.5 / 39 = {}, which rounds to −0.2949 ({}). They then use −0.295, so c = 8 − 0.295 = 7.705 (exactly {}; {}).",
                num(dc),
                exact_minus_printed(dc, -0.2945, "px"),
                num(8.0 + dc),
                exact_minus_printed(8.0 + dc, 7.705, "px")
            ),
        ).about(&["first_dc", "c_after_first"]);
    }
    s.note(
        NoteKind::Convention,
        format!(
            "The course notes stop after the first iteration (\"iterated until the increment approaches zero\"). Iterated to the end, c = {} after {} iterations{}, {} px from the first iteration's {}: the first step alone stops well short of the optimum.",
            num(m.params.a[2] + 1.0),
            m.iterations.len(),
            if radiometric {
                format!(
                    " with a = {} and b = {}",
                    num(m.params.gain()),
                    num(m.params.offset())
                )
            } else {
                ", the increments alternating in sign and roughly halving".to_string()
            },
            num(m.params.a[2] + 1.0 - (8.0 + dc)),
            num(8.0 + dc)
        ),
    ).about(&["c", "iterations"]);
    s.textbook = Some(printed);
}

// ---------------------------------------------------------------- lsm-2d

fn lsm_2d(inputs: &Record) -> Result<Solution> {
    let tr = rows(inputs, "template")?;
    let sr = rows(inputs, "search")?;
    for (key, m) in [("template", &tr), ("search", &sr)] {
        if m.len() > MAX_2D || m.first().map_or(0, Vec::len) > MAX_2D {
            return Err(Error::input(
                key,
                format!("is larger than {MAX_2D}×{MAX_2D}, the largest window this example takes"),
            ));
        }
    }
    let t = Grid::from_rows("template", &tr)?;
    let sw = Grid::from_rows("search", &sr)?;
    let i = Inputs(inputs);
    let (c0, r0, a0, b0) = (
        i.number("c0")?,
        i.number("r0")?,
        i.number("a0")?,
        i.number("b0")?,
    );
    let gradients = match text(inputs, "gradients")?.as_str() {
        "patch-edge" => Gradients::PatchEdge,
        _ => Gradients::SearchWindow,
    };
    let set = settings(Model::ShiftRadiometric, gradients, inputs)?;
    let start = Params::shift(c0 - 1.0, r0 - 1.0, a0, b0);
    let m = matching::match_2d(&t, &sw, start, set).map_err(|e| said_of(e, "c0"))?;
    let syms = symbols(&m.estimated, true);
    let mut s = Solution::new("lsm-2d", "2-D least-squares matching", inputs.clone());
    s.step(
        Step::new(
            "Template and start",
            "The template's centre is placed at (c⁰, r⁰) in the search window.",
        )
        .formula(
            r"T,\quad (c^0, r^0),\quad a^0,\ b^0",
            format!(
                r"T = {},\quad (c^0, r^0) = ({}, {}),\quad a^0 = {},\ b^0 = {}",
                numeric(&tr),
                num(c0),
                num(r0),
                num(a0),
                num(b0)
            ),
        )
        .value("template", Value::matrix(&tr))
        .value("search", Value::matrix(&sr)),
    );
    s.step(
        Step::new(
            "Observation equation",
            "Each template pixel is one observation; the shift enters through the gradients, the radiometry linearly.",
        )
        .formula(
            r"G_t(c,r) + V = a\,G_s(c+dc, r+dr) + b",
            r"[G_t - (a^0 G_s + b^0)] + V = a^0\frac{\partial G_s}{\partial c}dc + a^0\frac{\partial G_s}{\partial r}dr + G_s\,da + db".to_string(),
        ),
    );
    if let Some(it) = m.iterations.first() {
        first_iteration_2d(&mut s, it, &t, gradients, &syms);
    }
    s.step(table_step(&m, &syms, -1.0));
    status_step(&mut s, &m, &syms, set.max_iterations);
    let first = m.iterations.first();
    let inc = |k: usize| first.and_then(|it| it.increments.get(k).copied());
    s.result = Record::new()
        .with("first_dc", inc(0))
        .with("first_dr", inc(1))
        .with("first_da", inc(2))
        .with("first_db", inc(3))
        .with("c", m.params.a[2] + 1.0)
        .with("r", m.params.a[5] + 1.0)
        .with("a", m.params.gain())
        .with("b", m.params.offset())
        .with("iterations", m.iterations.len())
        .with("converged", m.converged())
        .with("status", m.status.word())
        .with("sigma0", m.sigma0());
    s.note(
        NoteKind::Convention,
        "Columns c (to the right) and rows r (downward) count from 1 as in the course notes; (c, r) is the search-window position of the template's centre pixel.",
    ).about(&["c", "r"]);
    if seed_inputs(
        &lsm_2d_fields(),
        inputs,
        &["template", "search", "c0", "r0", "a0", "b0"],
    ) {
        ex11_notes(&mut s, &m, gradients, inputs)?;
    }
    label_results(&mut s);
    Ok(s)
}

fn first_iteration_2d(
    s: &mut Solution,
    it: &Iteration,
    t: &Grid,
    gradients: Gradients,
    syms: &[&str],
) {
    let (a0, b0) = (it.params.gain(), it.params.offset());
    let modelled: Vec<f64> = it.patch.data().iter().map(|g| a0 * g + b0).collect();
    s.step(
        Step::new(
            "Difference vector dL (iteration 1)",
            "Template minus the modelled search patch a⁰·G_s + b⁰, pixel by pixel, row by row.",
        )
        .formula(
            r"d\mathbf{L} = G_t - (a^0 G_s + b^0)",
            format!(
                r"d\mathbf{{L}} = {} - {} = {}",
                column(t.data()),
                column(&modelled),
                column(&it.dl)
            ),
        )
        .value("patch", Value::matrix(&it.patch.rows()))
        .value("dL", Value::numbers(&it.dl)),
    );
    let (w, h) = (it.patch.width(), it.patch.height());
    let bordered = &it.bordered;
    let pick = |i: isize, j: isize| -> f64 {
        match gradients {
            Gradients::SearchWindow => bordered
                .get((i + 1).max(0) as usize, (j + 1).max(0) as usize)
                .unwrap_or(0.0),
            Gradients::PatchEdge => it
                .patch
                .get(
                    i.clamp(0, w as isize - 1) as usize,
                    j.clamp(0, h as isize - 1) as usize,
                )
                .unwrap_or(0.0),
        }
    };
    let mut rows = Vec::new();
    for j in 0..h as isize {
        for i in 0..w as isize {
            let k = (j as usize) * w + i as usize;
            let arow = it.a.get(k);
            rows.push(vec![
                format!(r"({} - {})/2", num(pick(i + 1, j)), tex(pick(i - 1, j))),
                format!(r"({} - {})/2", num(pick(i, j + 1)), tex(pick(i, j - 1))),
                num(arow.and_then(|r| r.get(2)).copied().unwrap_or(0.0)),
                "1".to_string(),
            ]);
        }
    }
    let how = match gradients {
        Gradients::SearchWindow => "Central differences of the resampled search window: the outer neighbours of the edge pixels come from the one-pixel border around the patch (the formula the course notes state).",
        Gradients::PatchEdge => "Central differences inside the patch only: an edge pixel stands in for its neighbour outside the patch (what the printed matrix does).",
    };
    let gain = if a0 == 1.0 { "" } else { r"a^0\," };
    s.step(
        Step::new("Design matrix A (iteration 1)", how)
            .formula(
                &format!(
                    r"A_i = [{gain}\tfrac{{G_s(c+1,r) - G_s(c-1,r)}}{{2}},\ {gain}\tfrac{{G_s(c,r+1) - G_s(c,r-1)}}{{2}},\ G_s(c,r),\ 1]"
                ),
                format!(r"A = {} = {}", bmatrix(&rows), numeric(&it.a)),
            )
            .value("A", Value::matrix(&it.a))
            .value("gc", Value::matrix(&it.gc.rows()))
            .value("gr", Value::matrix(&it.gr.rows()))
            .value("bordered", Value::matrix(&it.bordered.rows())),
    );
    let inc = |k: usize| it.increments.get(k).copied().unwrap_or(0.0);
    s.step(
        normal_step(it, syms)
            .value("c_after_first", it.params.a[2] + 1.0 + inc(0))
            .value("r_after_first", it.params.a[5] + 1.0 + inc(1)),
    );
}

fn ex11_notes(s: &mut Solution, m: &Matching, gradients: Gradients, inputs: &Record) -> Result<()> {
    s.textbook = Some(
        Record::new()
            .with("first_dc", 0.194)
            .with("first_dr", 0.086)
            .with("first_da", 0.138)
            .with("first_db", -5.372),
    );
    // the other reading, for the comparison
    let other = match gradients {
        Gradients::SearchWindow => Gradients::PatchEdge,
        Gradients::PatchEdge => Gradients::SearchWindow,
    };
    let t = Grid::from_rows("template", &ex7_template())?;
    let sw = Grid::from_rows("search", &ex7_search())?;
    let limit = Inputs(inputs).number("max_iterations")? as usize;
    let alt = matching::match_2d(
        &t,
        &sw,
        m.start,
        Settings {
            model: Model::ShiftRadiometric,
            gradients: other,
            max_iterations: limit,
        },
    )?;
    let (sw_run, pe_run) = match gradients {
        Gradients::SearchWindow => (m, &alt),
        Gradients::PatchEdge => (&alt, m),
    };
    let labels = ["∂G/∂c", "∂G/∂r"];
    let mut diffs = Vec::new();
    if let Some(first) = sw_run.iterations.first() {
        for (k, printed) in EX11_PRINTED_GRADIENTS.iter().enumerate() {
            for (j, p) in printed.iter().enumerate() {
                let exact = first
                    .a
                    .get(k)
                    .and_then(|r| r.get(j))
                    .copied()
                    .unwrap_or(0.0);
                if (exact - p).abs() > 1e-9 {
                    diffs.push(format!(
                        "row {} (c = {}, r = {}) {}: formula {} , printed {}",
                        k + 1,
                        k % 3 + 2,
                        k / 3 + 3,
                        labels.get(j).copied().unwrap_or(""),
                        num(exact),
                        num(*p)
                    ));
                }
            }
        }
    }
    s.note(
        NoteKind::Erratum,
        format!(
            "The printed design matrix does not follow its own formula ∂G_s/∂c = (G_s(c+1, r) − G_s(c−1, r))/2 at {} of its 18 gradient entries: {}. At every patch-edge pixel the course notes used the edge pixel itself for the neighbour outside the 3×3 patch (e.g. row 1 writes (65 − 47)/2 where the search window has 45 left of 47, giving (65 − 45)/2 = 10). Choose “Patch edge” under “Gradients at the patch edge” to reproduce the printed matrix.",
            diffs.len(),
            diffs.join("; ")
        ),
    ).about(&["first_dc", "first_dr", "first_da", "first_db"]);
    let fmt_inc = |run: &Matching| -> String {
        run.iterations.first().map_or("–".to_string(), |it| {
            it.increments
                .iter()
                .map(|x| num(*x))
                .collect::<Vec<_>>()
                .join(", ")
        })
    };
    s.note(
        NoteKind::Rounding,
        format!(
            "The printed dX = [0.194, 0.086, 0.138, −5.372] is what the patch-edge gradients give, rounded to three decimals (exactly [{}]). The stated formula gives dX = [{}].",
            fmt_inc(pe_run),
            fmt_inc(sw_run)
        ),
    ).about(&["first_dc", "first_dr", "first_da", "first_db"]);
    let end = |run: &Matching| -> String {
        format!(
            "{} after {} iterations: c = {}, r = {}, a = {}, b = {}",
            run.status.word(),
            run.iterations.len(),
            num(run.params.a[2] + 1.0),
            num(run.params.a[5] + 1.0),
            num(run.params.gain()),
            num(run.params.offset())
        )
    };
    s.note(
        NoteKind::Convention,
        format!(
            "The course notes stop after the first iteration (c = 3.194, r = 4.086, a = 1.138, b = −25.372). Iterated: with the search-window gradients (the stated formula) {}; with the patch-edge gradients (the printed matrix) {}. The gain and offset move far beyond their first step, and with the patch-edge gradients (too small at the edge pixels) every step overshoots, so that run zig-zags towards the optimum and needs many more iterations.",
            end(sw_run),
            end(pe_run)
        ),
    ).about(&["c", "r", "a", "b"]);
    Ok(())
}

// ---------------------------------------------------------------- lsm-affine

fn lsm_affine(inputs: &Record) -> Result<Solution> {
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
    let set = settings(Model::AffineRadiometric, Gradients::SearchWindow, inputs)?;
    let start = Params::shift(pair.centre, pair.centre, 1.0, 0.0);
    let m = matching::match_2d(&pair.template, &pair.search, start, set)?;
    let syms = symbols(&m.estimated, false);
    let origin = pair.centre;
    let mut s = Solution::new(
        "lsm-affine",
        "Affine + radiometric least-squares matching",
        inputs.clone(),
    );
    let a = &truth.a;
    s.step(
        Step::new(
            "The generated pair",
            "A smooth texture (six sinusoids, wavelengths 7–16 px, drawn with the random seed) fills the search window. The template is that window seen through the chosen transformation — resampled bilinearly at p = a1·u + a2·v + a3, q = a4·u + a5·v + a6 — then scaled by the gain and shifted by the offset; noise is added to both. u, v count from the template's centre, p, q from the search window's centre.",
        )
        .formula(
            r"\begin{bmatrix} a_1 & a_2 \\ a_4 & a_5 \end{bmatrix} = s\begin{bmatrix} \cos\theta & -\sin\theta \\ \sin\theta & \cos\theta \end{bmatrix}\begin{bmatrix} 1 & k \\ 0 & 1 \end{bmatrix},\quad T(u,v) = a_7\,S(p,q) + a_8 + n",
            format!(
                r"\begin{{bmatrix}} a_1 & a_2 \\ a_4 & a_5 \end{{bmatrix}} = {},\quad \begin{{bmatrix}} a_3 \\ a_6 \end{{bmatrix}} = {},\quad a_7 = {},\ a_8 = {},\ \sigma_n = {}",
                numeric(&[vec![a[0], a[1]], vec![a[3], a[4]]]),
                column(&[a[2], a[5]]),
                num(a[6]),
                num(a[7]),
                num(noise)
            ),
        )
        .value("template", Value::matrix(&pair.template.rows()))
        .value("search", Value::matrix(&pair.search.rows()))
        .value("true_parameters", Value::numbers(&truth.a)),
    );
    s.step(
        Step::new(
            "Observation equation and initial values (Lecture 21)",
            "One equation per template pixel, linearised at the current parameters; G_p, G_q are the central-difference gradients of the resampled search patch along the window's columns and rows. Initial values as Lecture 21 says: translations zero, the diagonal of the affine part 1, gain 1, offset 0.",
        )
        .formula(
            r"T - (a_7 G + a_8) + V = a_7G_p(u\,da_1 + v\,da_2 + da_3) + a_7G_q(u\,da_4 + v\,da_5 + da_6) + G\,da_7 + da_8",
            r"\mathbf{a}^0 = [1, 0, 0, 0, 1, 0, 1, 0]".to_string(),
        ),
    );
    if let Some(it) = m.iterations.first() {
        s.step(
            Step::new(
                "Design matrix and normal equations (iteration 1)",
                "A has one row per template pixel and eight columns; N = AᵀA is 8×8.",
            )
            .formula(
                r"A_i = [a_7G_p u,\ a_7G_p v,\ a_7G_p,\ a_7G_q u,\ a_7G_q v,\ a_7G_q,\ G,\ 1]",
                format!(
                    r"A_1 = {},\quad N = {},\quad d\mathbf{{X}} = {}",
                    numeric(&it.a.iter().take(1).cloned().collect::<Vec<_>>()),
                    numeric(&it.adjustment.n),
                    column(&it.increments)
                ),
            )
            .value("A", Value::matrix(&it.a))
            .value("N", Value::matrix(&it.adjustment.n))
            .value("increments", Value::numbers(&it.increments)),
        );
    }
    s.step(table_step(&m, &syms, origin));
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
    let rows: Vec<String> = (0..8)
        .map(|k| {
            format!(
                r"a_{} & {} & {} & {}",
                k + 1,
                num(truth.a.get(k).copied().unwrap_or(0.0)),
                num(est.get(k).copied().unwrap_or(0.0)),
                sd.as_ref()
                    .and_then(|v| v.get(k))
                    .map_or("–".to_string(), |x| fmt_sig(*x, 3))
            )
        })
        .collect();
    let mut step = Step::new(
        "Estimates beside the truth",
        "The standard deviations are σ0·√qᵢᵢ from the last iteration's Qxx = N⁻¹.",
    )
    .formula(
        r"\sigma_{a_j} = \sigma_0\sqrt{q_{jj}}",
        format!(
            r"\begin{{array}}{{l|rrr}} & \text{{true}} & \text{{estimate}} & \sigma \\ \hline {} \end{{array}}",
            rows.join(r" \\ ")
        ),
    )
    .value("parameters", Value::numbers(&est))
    .value("true_parameters", Value::numbers(&truth.a))
    // the scale and rotation the estimate implies (no shear: the first
    // column of [a1 a2; a4 a5] is s·(cos θ, sin θ))
    .value("estimated_scale", est[0].hypot(est[3]))
    .value("estimated_rotation_deg", est[3].atan2(est[0]).to_degrees());
    if let Some(sd) = &sd {
        step = step.value("std_dev", Value::numbers(sd));
    }
    // the noise the residuals should show: template noise plus the search
    // noise carried through bilinear weights and the gain
    s.step(step);
    // the noise the residuals should show: template noise plus the search
    // noise carried through the bilinear weights and the gain
    let expected = if noise > 0.0 {
        let m2 = mean_square_weights(&pair.template, &m.params);
        let e = noise * (1.0 + m.params.gain().powi(2) * m2).sqrt();
        s.step(
            Step::new(
                "σ0 against the noise",
                "Each residual carries the template's noise and the search window's noise, the latter through the four bilinear weights w_k and the gain; averaged over the patch this is what σ0 should come out as.",
            )
            .formula(
                r"\sigma_0 \approx \sigma_n\sqrt{1 + a_7^2\,\overline{\textstyle\sum_k w_k^2}}",
                format!(
                    r"\sigma_0 = {},\quad \sigma_n\sqrt{{1 + a_7^2\,\overline{{\textstyle\sum_k w_k^2}}}} = {}\sqrt{{1 + {}^2 \times {}}} = {}",
                    m.sigma0().map_or("–".to_string(), num),
                    num(noise),
                    num(m.params.gain()),
                    num(m2),
                    num(e)
                ),
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
        .with("true_parameters", Value::numbers(&truth.a))
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
    s.note(
        NoteKind::Convention,
        "The template is made from the search window with the same bilinear interpolation the matching uses, so without noise the model fits exactly and the estimates return the true values. Real images also carry the interpolation's own error: for a template sampled from a smooth continuous texture instead, the least-squares optimum itself lies up to about 0.1 px from the true shift (measured in this project's tests).",
    ).about(&["parameters", "sigma0"]);
    if m.converged() {
        if let Some(sd) = &sd {
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
    label_results(&mut s);
    Ok(s)
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
