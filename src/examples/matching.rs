//! Seed 000, Examples 10–11, and seed 003's affine + radiometric
//! generalisation: least-squares matching step by step — the first iteration
//! laid out as the seed does, then every iteration as a table, and how the
//! run ended.

use super::drill::Tolerance;
use super::fields::{Field, Inputs};
use super::{Example, Topic};
use crate::error::{Error, Result};
use crate::matching::{
    self, Gradients, Iteration, Matching, Model, Param, Params, Settings, Status,
};
use crate::raster::Grid;
use crate::solution::{fmt_sig, num, tex, Form, NoteKind, Record, Relation, Solution, Step, Value};

mod lsm_1d;
mod lsm_2d;
mod lsm_affine;

const TITLE: &str = "Least-squares matching";
/// Largest 1-D template or search window.
const MAX_1D: usize = 512;
/// Largest side of a 2-D template or search window.
const MAX_2D: usize = 64;

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[lsm_1d::EXAMPLE, lsm_2d::EXAMPLE, lsm_affine::EXAMPLE];

/// The topic: its module (`web/matching/`) and title.
pub const TOPIC: Topic = Topic {
    module: "matching",
    title: TITLE,
    examples: EXAMPLES,
};

/// What each result key of the topic's examples is, for the page's result
/// table (the keys a solution has are labelled).
const LABELS: &[(&str, &str, &str)] = &[
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
];

/// Shifts and positions in practice: to a hundredth of a pixel.
const SHIFT: Tolerance = Tolerance::abs(0.01);

// ---------------------------------------------------------------- fields

fn max_iterations() -> Field {
    Field::integer(
        "max_iterations",
        "Iteration limit",
        matching::DEFAULT_ITERATIONS as f64,
    )
    .range(1.0, matching::MAX_ITERATIONS as f64)
    .help("The run stops as “not converged” when this many iterations have not reached the tolerances.")
}

// ---------------------------------------------------------------- inputs

/// The `template` and `search` patches of the 2-D matching examples, as rows
/// and as grids, each at most `MAX_2D` a side.
struct Patches {
    tr: Vec<Vec<f64>>,
    sr: Vec<Vec<f64>>,
    template: Grid,
    search: Grid,
}

fn patches(inputs: &Record) -> Result<Patches> {
    let tr = Inputs(inputs).rows("template")?;
    let sr = Inputs(inputs).rows("search")?;
    for (key, m) in [("template", &tr), ("search", &sr)] {
        if m.len() > MAX_2D || m.first().map_or(0, Vec::len) > MAX_2D {
            return Err(Error::input(
                key,
                format!("is larger than {MAX_2D}×{MAX_2D}, the largest window this example takes"),
            ));
        }
    }
    Ok(Patches {
        template: Grid::from_rows("template", &tr)?,
        search: Grid::from_rows("search", &sr)?,
        tr,
        sr,
    })
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

// ---------------------------------------------------------------- symbols

fn short(x: f64) -> String {
    fmt_sig(x, 5)
}

/// An estimated parameter as the steps write it: in LaTeX, as the key of
/// its step values and results, and in prose.
#[derive(Clone, Copy)]
struct Sym {
    tex: &'static str,
    key: &'static str,
    prose: &'static str,
    /// The unit of its increments in the steps ("" for none).
    unit: &'static str,
}

/// The symbols of the estimated parameters: seed 000's c, r, a, b, or
/// Lecture 21's a₁ … a₈.
fn symbols(est: &[Param], seed000: bool) -> Vec<Sym> {
    let sym = |tex, key, prose, unit| Sym {
        tex,
        key,
        prose,
        unit,
    };
    est.iter()
        .map(|p| match (p, seed000) {
            (Param::A3, true) => sym("c", "c", "c", "px"),
            (Param::A6, true) => sym("r", "r", "r", "px"),
            (Param::Gain, true) => sym("a", "a", "a", ""),
            (Param::Offset, true) => sym("b", "b", "b", ""),
            (Param::A1, _) => sym("a_1", "a1", "a₁", ""),
            (Param::A2, _) => sym("a_2", "a2", "a₂", ""),
            (Param::A3, _) => sym("a_3", "a3", "a₃", "px"),
            (Param::A4, _) => sym("a_4", "a4", "a₄", ""),
            (Param::A5, _) => sym("a_5", "a5", "a₅", ""),
            (Param::A6, _) => sym("a_6", "a6", "a₆", "px"),
            (Param::Gain, _) => sym("a_7", "a7", "a₇", ""),
            (Param::Offset, _) => sym("a_8", "a8", "a₈", ""),
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

/// The difference vector of the first iteration: the template minus the
/// modelled search patch.
fn difference_step(text: &str, it: &Iteration, template: &[f64]) -> Step {
    let (a0, b0) = (it.params.gain(), it.params.offset());
    let modelled: Vec<f64> = it.patch.data().iter().map(|g| a0 * g + b0).collect();
    Step::new("Difference vector dL (iteration 1)", text).relation(
        Relation::new(r"d\mathbf{L}")
            .key("dL")
            .sym(r"G_t - (a^0 G_s + b^0)")
            .subst(
                Form::column(template, "G_t")
                    .then("-")
                    .then(Form::column(&modelled, "a^0 G_s + b^0")),
            )
            .result(Form::column(&it.dl, r"d\mathbf{L}")),
    )
}

/// The normal equations of the first iteration and the increments they
/// give (seed 000's examples: `c^1 = c^0 + dc` for each position).
fn normal_step(it: &Iteration, syms: &[Sym]) -> Step {
    let adj = &it.adjustment;
    let at: Vec<Vec<f64>> = (0..adj.n.len())
        .map(|j| {
            it.a.iter()
                .map(|r| r.get(j).copied().unwrap_or(0.0))
                .collect()
        })
        .collect();
    let mut n = Relation::new(r"A^\mathsf{T}A").key("N");
    let mut atl = Relation::new(r"A^\mathsf{T}d\mathbf{L}").key("AtL");
    if syms.len() == 1 {
        // one unknown: the sums by hand, Σ g² and Σ g·dL, as products
        let at = Form::grid("bmatrix", &at, r"A^\mathsf{T}");
        n = n.subst(at.clone().then(Form::grid("bmatrix", &it.a, "A")));
        atl = atl.subst(at.then(Form::column(&it.dl, r"d\mathbf{L}")));
    }
    let mut step = Step::new(
        "Normal equations and increments (iteration 1)",
        "N = AᵀA and AᵀdL; their solution is the first set of increments.",
    )
    .relation(n.result(Form::grid("bmatrix", &adj.n, "N")))
    .relation(atl.result(Form::column(&adj.atl, r"A^\mathsf{T}d\mathbf{L}")));
    let first = |k: usize| it.increments.get(k).copied().unwrap_or(0.0);
    let n11 = adj
        .n
        .first()
        .and_then(|r| r.first())
        .copied()
        .unwrap_or(0.0);
    if let ([sym], [atl]) = (syms, adj.atl.as_slice()) {
        // one unknown: the increment is a quotient
        step = step.relation(
            Relation::new(format!("d{}", sym.tex))
                .key(&format!("first_d{}", sym.key))
                .sym(r"\frac{A^\mathsf{T}d\mathbf{L}}{A^\mathsf{T}A}")
                .subst(format!(r"\frac{{{}}}{{{}}}", num(*atl), num(n11)))
                .value(first(0), sym.unit),
        );
    } else {
        step = step.relation(
            Relation::new(r"Q_{xx}")
                .key("Qxx")
                .sym(r"(A^\mathsf{T}A)^{-1}")
                .result(Form::grid("bmatrix", &adj.qxx, r"Q_{xx}")),
        );
        for (k, sym) in syms.iter().enumerate() {
            let row = adj.qxx.get(k).map_or(&[][..], Vec::as_slice);
            let terms = row.iter().zip(&adj.atl).enumerate().map(|(j, (q, b))| {
                let term = format!(r"{} \cdot {}", tex(*q), tex(*b));
                if j == 0 {
                    term
                } else {
                    format!("+ {term}")
                }
            });
            step = step.relation(
                Relation::new(format!("d{}", sym.tex))
                    .key(&format!("first_d{}", sym.key))
                    .sym(format!(r"(Q_{{xx}} A^\mathsf{{T}}d\mathbf{{L}})_{}", k + 1))
                    .subst(Form::terms(terms))
                    .value(first(k), sym.unit),
            );
        }
    }
    step.value("N", Value::matrix(&adj.n))
        .value("AtL", Value::numbers(&adj.atl))
        .value("increments", Value::numbers(&it.increments))
}

/// The position after the first iteration: `c¹ = c⁰ + dc` (1-based).
fn moved(sym: &str, key: &str, start: f64, d: f64) -> Relation {
    Relation::new(format!("{sym}^1"))
        .key(key)
        .sym(format!("{sym}^0 + d{sym}"))
        .subst(format!("{} + {}", num(start), tex(d)))
        .value(start + d, "px")
}

/// The iteration table: parameters where each iteration resampled, its
/// increments and σ0; plus the per-iteration arrays for the figures.
/// `vector`: the result key of all the parameters together (Lecture 21's
/// `parameters`), else each parameter's own key is its result's.
fn table_step(m: &Matching, syms: &[Sym], origin: f64, vector: Option<&str>) -> Step {
    let mut header: Vec<String> = vec!["k".into()];
    header.extend(syms.iter().map(|s| s.tex.to_string()));
    header.extend(syms.iter().map(|s| format!("d{}", s.tex)));
    header.push(r"\sigma_0".into());
    let mut lines = vec![header];
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
        lines.push(row);
    }
    let mut last = vec![r"\text{end}".to_string()];
    last.extend(
        m.estimated
            .iter()
            .map(|q| short(shown(&m.params, *q, origin))),
    );
    last.extend(m.estimated.iter().map(|_| String::new()));
    last.push(String::new());
    lines.push(last);
    let mut step = Step::new(
        "Every iteration",
        "Each row: the parameters the iteration resampled at, the increments it solved for, and σ0 of its adjustment. The last row holds the parameters after the last update.",
    );
    // the update rule, keyed to what it ends with: each result of seed 000,
    // or the vector of Lecture 21's parameters
    match vector {
        Some(key) => {
            step = step.relation(
                Relation::new("a_j")
                    .key(key)
                    .op(r"\leftarrow")
                    .sym("a_j + da_j"),
            );
        }
        None => {
            for sym in syms {
                step = step.relation(
                    Relation::new(sym.tex)
                        .key(sym.key)
                        .op(r"\leftarrow")
                        .sym(format!("{0} + d{0}", sym.tex)),
                );
            }
        }
    }
    step = step.relation(
        Relation::new(Form::default())
            .key("iterations")
            .subst(Form::grid_tex("array", lines, "iterations")),
    );
    for (j, s) in syms.iter().enumerate() {
        step = step
            .value(
                s.key,
                Value::numbers(per_param.get(j).map_or(&[][..], |v| v)),
            )
            .value(
                &format!("d{}", s.key),
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

/// The convergence test in the parameters actually estimated, one relation
/// per tolerance, and whether it has a radiometric part.
fn convergence_test(est: &[Param]) -> (Vec<Relation>, bool) {
    let has = |p: Param| est.contains(&p);
    let position = if has(Param::A1) {
        r"\max_i \lVert d\mathbf{x}_i \rVert"
    } else if has(Param::A6) {
        r"\sqrt{dc^2 + dr^2}"
    } else {
        "|dc|"
    };
    let grey = if has(Param::A1) {
        r"\max_i |da_7\, G_i + da_8|"
    } else {
        r"\max_i |da\, G_i + db|"
    };
    let radiometric = has(Param::Gain);
    let mut out = vec![Relation::new(position)
        .op(r"\le")
        .sym(r"10^{-4}\ \text{px}")];
    if radiometric {
        out.push(Relation::new(grey).op(r"\le").sym(r"10^{-3}"));
    }
    (out, radiometric)
}

/// The 1-D and 2-D examples' model: the shift, with gain and offset when
/// `radiometric`.
fn shift_model(radiometric: bool) -> Model {
    if radiometric {
        Model::ShiftRadiometric
    } else {
        Model::Shift
    }
}

/// The design matrix of iteration 1: its entries worked (`rows`, LaTeX) and
/// their values `a`.
fn design_matrix(rows: Vec<Vec<String>>, a: &[Vec<f64>]) -> Relation {
    Relation::new("A")
        .key("A")
        .subst(Form::grid_tex("bmatrix", rows, "A"))
        .result(Form::grid("bmatrix", a, "A"))
}

/// Increment `k` of the first iteration (none when there was none).
fn first_increment(m: &Matching, k: usize) -> Option<f64> {
    m.iterations
        .first()
        .and_then(|it| it.increments.get(k).copied())
}

/// The results of the 1-D and 2-D examples after the position: gain,
/// offset, and how the run ended.
fn with_run(r: Record, m: &Matching) -> Record {
    r.with("a", m.params.gain())
        .with("b", m.params.offset())
        .with("iterations", m.iterations.len())
        .with("converged", m.converged())
        .with("status", m.status.word())
        .with("sigma0", m.sigma0())
}

fn status_step(s: &mut Solution, m: &Matching, syms: &[Sym], limit: usize) {
    let k = m.iterations.len();
    let last = m.iterations.last();
    let incs = last.map_or(String::new(), |it| {
        syms.iter()
            .zip(&it.increments)
            .map(|(s, d)| format!("d{} = {}", s.prose, fmt_sig(*d, 3)))
            .collect::<Vec<_>>()
            .join(", ")
    });
    let (tests, radiometric) = convergence_test(&m.estimated);
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
    let mut step = Step::new(&title, &text);
    for t in tests {
        step = step.relation(t);
    }
    s.step(
        step.relation(
            Relation::new(Form::default())
                .key("status")
                .result(format!(r"\text{{{}}}", m.status.word())),
        )
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
