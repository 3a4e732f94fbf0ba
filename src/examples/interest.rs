//! Seed 000 Examples 13–14 and seed 003: the Förstner operator (gradient
//! table, N, det N, N⁻¹, trace N⁻¹, w, q, eigenvalues, seed 003's precision
//! test and error ellipse) and the Moravec operator on a window, step by
//! step; and the Förstner operator on a generated test pattern, where the
//! window can be moved and the whole image is thresholded and suppressed.

use super::drill::{or_given, tol, value_in, BoxDef, Mistake, Tolerance};
use super::fields::{to_rows, Field, Inputs};
use super::{Example, Topic};
use crate::error::Result;
use crate::interest::{Case, Forstner, Measures, Precision, Sums};
use crate::raster::Grid;
use crate::solution::{
    num, tex, with_unit, Form, NoteKind, Record, Relation, Solution, Step, Value,
};

mod forstner_image;
mod forstner_window;
mod moravec_window;

const TITLE: &str = "Interest operators";
/// Side of the generated test pattern (pixels).
pub const PATTERN_SIZE: usize = 64;
/// Seed of the test pattern's noise generator (fixed: the pattern is the
/// same on every run and every machine).
pub const PATTERN_SEED: u64 = 7;

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[
    forstner_window::EXAMPLE,
    moravec_window::EXAMPLE,
    forstner_image::EXAMPLE,
];

/// The topic: its module (`web/interest/`) and title.
pub const TOPIC: Topic = Topic {
    module: "interest",
    title: TITLE,
    examples: EXAMPLES,
};

/// The window of grey values, with the seed's rows.
fn window_field(default: &[Vec<f64>], help: &'static str) -> Field {
    Field::matrix("window", "Window of grey values", default).help(help)
}

fn sigma_n(default: f64) -> Field {
    Field::number("sigma_n", "Noise σn of the grey values", default)
        .unit("grey values")
        .positive(1000.0)
        .help("Standard deviation of the image noise; Lecture 21's Σuv = σn²·N⁻¹. The course documents give no value.")
}

fn threshold() -> Field {
    Field::number("threshold_px", "Threshold T on the position", 0.5)
        .unit("px")
        .positive(100.0)
        .help(
            "Lecture 21: a point is accepted when λmax(Σuv) ≤ T² (T = 0.5 px in the course notes).",
        )
}

/// A validated matrix input as a grid.
fn grid(inputs: &Record, key: &str) -> Result<Grid> {
    Grid::from_rows(key, &Inputs(inputs).rows(key)?)
}

fn mat(m: &[[f64; 2]; 2]) -> Value {
    Value::matrix(&to_rows(m))
}

fn opt_mat(m: Option<[[f64; 2]; 2]>) -> Value {
    m.as_ref().map_or(Value::Null, mat)
}

/// `P(c_2, r_2)`: a window position, 1-based as the seed counts.
fn pos(c: usize, r: usize) -> String {
    format!("P(c_{{{}}}, r_{{{}}})", c + 1, r + 1)
}

fn opt_num(x: Option<f64>) -> String {
    x.map_or(r"\infty".to_string(), num)
}

/// The steps of the Förstner operator on one window (shared by the window
/// example and the image mode).
fn forstner_steps(s: &mut Solution, f: &Forstner, p: &Precision, sigma_n: f64, t: f64) {
    let m = &f.measures;
    let mut diffs = vec![vec![
        r"\text{Pixel}".to_string(),
        "g'_x".to_string(),
        "g'_y".to_string(),
    ]];
    let mut products = vec![[
        r"\text{Pixel}",
        "g'_x",
        "g'_y",
        "g'_x g'_y",
        "(g'_x)^2",
        "(g'_y)^2",
    ]
    .map(String::from)
    .to_vec()];
    for t in &f.rows {
        diffs.push(vec![
            format!("{} = {}", pos(t.c, t.r), num(t.g)),
            format!("({} - {})/2 = {}", num(t.right), tex(t.left), num(t.gx)),
            format!("({} - {})/2 = {}", num(t.down), tex(t.up), num(t.gy)),
        ]);
        let mut row = vec![pos(t.c, t.r)];
        row.extend([t.gx, t.gy, t.gxgy, t.gx2, t.gy2].map(num));
        products.push(row);
    }
    let sm = &f.sums;
    let mut sum_row = vec![r"\text{sum}".to_string()];
    sum_row.extend([sm.gx, sm.gy, sm.gxgy, sm.gx2, sm.gy2].map(num));
    products.push(sum_row);
    let table: Vec<Vec<f64>> = f
        .rows
        .iter()
        .map(|t| {
            vec![
                (t.c + 1) as f64,
                (t.r + 1) as f64,
                t.g,
                t.gx,
                t.gy,
                t.gxgy,
                t.gx2,
                t.gy2,
            ]
        })
        .collect();
    s.step(
        Step::new(
            "Gradient table: central differences",
            "At every interior pixel of the window, row by row as the course notes lay it out: g′x = (g(c+1, r) − g(c−1, r))/2 across the columns and g′y = (g(c, r+1) − g(c, r−1))/2 down the rows. Table rows are [c, r, g, g′x, g′y, g′x·g′y, (g′x)², (g′y)²], positions from 1.",
        )
        .relation(Relation::new("g'_x").key("gx").sym(r"\frac{g(c+1,r) - g(c-1,r)}{2}"))
        .relation(Relation::new("g'_y").key("gy").sym(r"\frac{g(c,r+1) - g(c,r-1)}{2}"))
        .relation(Relation::new(Form::default()).key("table").subst(Form::grid_tex(
            "array",
            diffs,
            "gradient table",
        )))
        .value("table", Value::matrix(&table))
        .value("gx", Value::matrix(&f.gx.rows()))
        .value("gy", Value::matrix(&f.gy.rows())),
    );
    let mut sums = Step::new(
        "Gradient table: products, squares and sums",
        "The rest of the course notes' table: the product and the squares at each pixel, then the column sums.",
    );
    for (key, sym) in [
        ("sum_gx", r"\sum g'_x"),
        ("sum_gy", r"\sum g'_y"),
        ("sum_gxgy", r"\sum g'_x g'_y"),
        ("sum_gx2", r"\sum (g'_x)^2"),
        ("sum_gy2", r"\sum (g'_y)^2"),
    ] {
        sums = sums.relation(Relation::new(Form::default()).key(key).sym(sym));
    }
    s.step(
        sums.relation(Relation::new(Form::default()).subst(Form::grid_tex(
            "array",
            products,
            "products and sums",
        )))
        .value("sum_gx", sm.gx)
        .value("sum_gy", sm.gy)
        .value("sum_gxgy", sm.gxgy)
        .value("sum_gx2", sm.gx2)
        .value("sum_gy2", sm.gy2),
    );
    let symbolic_n = vec![
        vec![r"\sum (g'_x)^2".to_string(), r"\sum g'_x g'_y".to_string()],
        vec![r"\sum g'_x g'_y".to_string(), r"\sum (g'_y)^2".to_string()],
    ];
    s.step(
        Step::new(
            "The matrix N",
            "The sums of squares on the diagonal, the sum of products off it: the normal-equation matrix of a shift of the window.",
        )
        .relation(
            Relation::new("N")
                .key("n")
                .sym(Form::grid_tex("bmatrix", symbolic_n, ""))
                .result(Form::grid("bmatrix", &to_rows(&m.n), "N")),
        )
        .value("n", mat(&m.n)),
    );
    let [[a, b], [_, d]] = m.n;
    let det_text = if m.trace == 0.0 {
        "N = 0: the window has no gradient at all (a flat window), so det N = 0."
    } else if m.singular {
        "det N = 0 (up to rounding): all gradients point one way, a straight edge. N cannot be inverted."
    } else {
        "The determinant of the 2×2 matrix."
    };
    s.step(
        Step::new("Determinant of N", det_text)
            .relation(
                Relation::new(r"\det N")
                    .key("det_n")
                    .sym(r"\sum (g'_x)^2 \sum (g'_y)^2 - \left(\sum g'_x g'_y\right)^2")
                    .subst(format!(r"{} \times {} - {}^2", num(a), num(d), tex(b)))
                    .value(m.det, ""),
            )
            .value("det_n", m.det)
            .value("trace_n", m.trace),
    );
    match m.inverse {
        Some(inv) => {
            let cofactors = vec![
                vec![r"\sum (g'_y)^2".to_string(), r"-\sum g'_x g'_y".to_string()],
                vec![r"-\sum g'_x g'_y".to_string(), r"\sum (g'_x)^2".to_string()],
            ];
            s.step(
                Step::new(
                    "Inverse of N",
                    "Swap the diagonal, change the sign of the off-diagonal, divide by the determinant. N⁻¹ is the cofactor matrix of the shift: Σuv = σn²·N⁻¹.",
                )
                .relation(
                    Relation::new("N^{-1}")
                        .key("n_inverse")
                        .sym(Form::from(r"\frac{1}{\det N}").then(Form::grid_tex(
                            "bmatrix",
                            cofactors,
                            "",
                        )))
                        .subst(
                            Form::from(format!(r"\frac{{1}}{{{}}}", num(m.det)))
                                .then(Form::grid("bmatrix", &[vec![d, -b], vec![-b, a]], "")),
                        )
                        .result(Form::grid("bmatrix", &to_rows(&inv), "N^{-1}")),
                )
                .value("n_inverse", mat(&inv)),
            )
        }
        None => s.step(Step::new(
            "Inverse of N",
            "det N = 0: N has no inverse, so N⁻¹ and trace N⁻¹ have no value (the position is undetermined in at least one direction).",
        )),
    }
    let trace_inverse = Relation::new(r"\operatorname{tr} N^{-1}")
        .key("trace_n_inverse")
        .sym(r"\frac{\operatorname{tr} N}{\det N}");
    let w = Relation::new("w")
        .key("w")
        .sym(r"\frac{1}{\operatorname{tr} N^{-1}}")
        .sym(r"\frac{\det N}{\operatorname{tr} N}");
    let (trace_inverse, w) = match m.trace_inverse {
        Some(ti) => (
            trace_inverse
                .subst(format!(r"\frac{{{}}}{{{}}}", num(m.trace), num(m.det)))
                .value(ti, ""),
            w.subst(format!(r"\frac{{{}}}{{{}}}", num(m.det), num(m.trace)))
                .value(m.w, ""),
        ),
        None => (trace_inverse.result(r"\infty"), w.value(m.w, "")),
    };
    s.step(
        Step::new(
            "Trace of N⁻¹ and the weight w",
            "trace N⁻¹ = trace N / det N is σu² + σv² up to σn²: the size of the error ellipse. A distinct point has a SMALL trace N⁻¹, so Förstner's weight is its reciprocal, w = det N / trace N, large for a distinct point. Where det N = 0, trace N⁻¹ is infinite and w = 0 (its limit).",
        )
        .relation(trace_inverse)
        .relation(w)
        .value("trace_n_inverse", m.trace_inverse)
        .value("w", m.w),
    );
    let q = Relation::new("q")
        .key("q")
        .sym(r"\frac{4 \det N}{(\operatorname{tr} N)^2}")
        .sym(r"1 - \left(\frac{\lambda_1 - \lambda_2}{\lambda_1 + \lambda_2}\right)^2");
    let q = match m.q {
        Some(x) => q
            .subst(format!(
                r"\frac{{4 \times {}}}{{{}^2}}",
                num(m.det),
                num(m.trace)
            ))
            .value(x, ""),
        None => q.subst(r"\frac{0}{0}").result(r"\text{no value}"),
    };
    s.step(
        Step::new(
            "Roundness q",
            "q = 1 for a circular error ellipse (a symmetric corner), q = 0 for a straight edge; no value for a flat window (N = 0).",
        )
        .relation(q)
        .value("q", m.q),
    );
    s.step(
        Step::new(
            "Eigenvalues of N",
            "The gradient energy along the strongest and the weakest direction. λmin = det N / λmax (the same number as tr/2 − root, without cancellation).",
        )
        .relation(Relation::new(r"\lambda_{1,2}").sym(
            r"\frac{\operatorname{tr} N}{2} \pm \sqrt{\left(\frac{N_{11} - N_{22}}{2}\right)^2 + N_{12}^2}",
        ))
        .relation(Relation::new(r"\lambda_{max}").key("lambda_max").value(m.lambda_max, ""))
        .relation(Relation::new(r"\lambda_{min}").key("lambda_min").value(m.lambda_min, ""))
        .value("lambda_max", m.lambda_max)
        .value("lambda_min", m.lambda_min),
    );
    let mm = m.m as f64;
    let px2 = |x: &str| format!(r"{x}\,\text{{px}}^2");
    let shift = r"\lambda_{max}(\Sigma_{uv})";
    s.step(
        Step::new(
            "Lecture 21: precision of the position",
            "The gradient covariance is Σ∇g∇g = N/m (m pixels), its smallest eigenvalue λmin(N)/m; the largest eigenvalue of the shift's covariance Σuv = σn²·N⁻¹ is then σn²/λmin(N) — m cancels. The point is accepted when λmax(Σuv) ≤ T².",
        )
        .relation(
            Relation::new(r"\lambda_{min}(\Sigma_{\nabla g \nabla g})")
                .subst(format!(r"\frac{{{}}}{{{}}}", num(m.lambda_min), num(mm)))
                .value(m.lambda_min / mm, ""),
        )
        .relation(
            Relation::new(shift)
                .key("lambda_max_shift")
                .sym(r"\frac{\sigma_n^2\, \lambda_{min}^{-1}(\Sigma_{\nabla g \nabla g})}{m}")
                .sym(r"\frac{\sigma_n^2}{\lambda_{min}(N)}")
                .subst(format!(
                    r"\frac{{{}^2}}{{{}}}",
                    num(sigma_n),
                    num(m.lambda_min)
                ))
                .result(px2(&opt_num(p.lambda_max_shift))),
        )
        .relation(Relation::new(shift).op(r"\le").sym("T^2"))
        .relation(
            Relation::new("T^2")
                .subst(format!("{}^2", num(t)))
                .result(px2(&num(t * t))),
        )
        .relation(
            Relation::new(px2(&opt_num(p.lambda_max_shift)))
                .key("accepted")
                .op(if p.accepted { r"\le" } else { ">" })
                .result(px2(&num(t * t))),
        )
        .value("m", mm)
        .value("lambda_max_shift", p.lambda_max_shift)
        .value("accepted", p.accepted),
    );
    let case_text = match p.case {
        Case::Corner => "Both semi-axes are within T: a corner, a distinct point (Lecture 21's small circle).",
        Case::Edge => "Only across the edge is the position within T; along it the ellipse is long (Lecture 21's edge case).",
        Case::Flat => "Neither direction is within T: a flat, homogeneous area (Lecture 21's large ellipse).",
    };
    let degrees = |x: f64| format!(r"{}^\circ", num(x));
    let theta = Relation::new(r"\theta").key("weak_angle_deg");
    let theta = if m.trace > 0.0 {
        theta
            .sym(r"\tfrac{1}{2} \operatorname{atan2}(2 N_{12},\ N_{11} - N_{22}) + 90^\circ")
            .subst(format!(
                r"\tfrac{{1}}{{2}} \operatorname{{atan2}}(2 \times {},\ {} - {}) + 90^\circ",
                tex(b),
                num(a),
                tex(d)
            ))
    } else {
        theta
    };
    s.step(
        Step::new(
            "Error ellipse and the three cases",
            &format!(
                "The standard error ellipse of the position has semi-axes √λ(Σuv); its long axis lies along the weakest gradient direction. {case_text}"
            ),
        )
        .relation(
            Relation::new(r"\sigma_{max}")
                .key("sigma_max_px")
                .sym(r"\sqrt{\lambda_{max}(\Sigma_{uv})}")
                .result(with_unit(&opt_num(p.sigma_max), "px")),
        )
        .relation(
            Relation::new(r"\sigma_{min}")
                .key("sigma_min_px")
                .sym(r"\sqrt{\frac{\sigma_n^2}{\lambda_{max}(N)}}")
                .result(with_unit(&opt_num(p.sigma_min), "px")),
        )
        .relation(theta.result(degrees(m.weak_angle.to_degrees())))
        .value("sigma_max_px", p.sigma_max)
        .value("sigma_min_px", p.sigma_min)
        .value("weak_angle_deg", m.weak_angle.to_degrees())
        .value("case", p.case.name()),
    );
}

/// The Förstner result keys of `shared/CATALOG.md` and the extra ones.
fn forstner_result(f: &Forstner, p: &Precision) -> Record {
    let m = &f.measures;
    Record::new()
        .with("gx", Value::matrix(&f.gx.rows()))
        .with("gy", Value::matrix(&f.gy.rows()))
        .with("n", mat(&m.n))
        .with("det_n", m.det)
        .with("n_inverse", opt_mat(m.inverse))
        .with("trace_n_inverse", m.trace_inverse)
        .with("w", m.w)
        .with("q", m.q)
        .with("lambda_min", m.lambda_min)
        .with("lambda_max_shift", p.lambda_max_shift)
        .with("accepted", p.accepted)
        .with("lambda_max", m.lambda_max)
        .with("trace_n", m.trace)
        .with("sigma_max_px", p.sigma_max)
        .with("sigma_min_px", p.sigma_min)
        .with("weak_angle_deg", m.weak_angle.to_degrees())
        .with("case", p.case.name())
}

/// What each result key is, for the page's result table (the three
/// examples share it).
const LABELS: &[(&str, &str, &str)] = &[
    ("gx", "Gradients g′x (interior)", "grey values/px"),
    ("gy", "Gradients g′y (interior)", "grey values/px"),
    ("n", "Matrix N", ""),
    ("det_n", "det N", ""),
    ("n_inverse", "N⁻¹", ""),
    ("trace_n_inverse", "trace N⁻¹", ""),
    ("w", "Weight w = det N / trace N", ""),
    ("q", "Roundness q = 4 det N / trace² N", ""),
    ("lambda_min", "Smaller eigenvalue λmin(N)", ""),
    ("lambda_max_shift", "λmax(Σuv) = σn² / λmin(N)", "px²"),
    ("accepted", "Accepted: λmax(Σuv) ≤ T²", ""),
    ("lambda_max", "Larger eigenvalue λmax(N)", ""),
    ("trace_n", "trace N", ""),
    ("sigma_max_px", "Error ellipse, major semi-axis", "px"),
    ("sigma_min_px", "Error ellipse, minor semi-axis", "px"),
    (
        "weak_angle_deg",
        "Direction of the major axis (from +c toward +r)",
        "°",
    ),
    ("case", "Lecture 21's case", ""),
    ("window", "The window", "grey values"),
    ("candidates", "Pixels that pass the threshold", ""),
    ("points", "Interest points [c, r, λmax(Σuv)]", ""),
    ("sums", "Sums of squared differences", "grey values²"),
    ("mean", "Measure of distinctness (mean)", "grey values²"),
    (
        "differences",
        "[c, r, g, row, column, main diag., other diag., sum]",
        "",
    ),
];

fn singular_notes(s: &mut Solution, m: &Measures) {
    if m.trace == 0.0 {
        s.note(
            NoteKind::Warning,
            "The window is flat: every gradient is zero, so N = 0. N⁻¹, trace N⁻¹, q and λmax(Σuv) have no value; w = 0. The position cannot be determined in any direction.",
        ).about(&["n_inverse", "trace_n_inverse", "q", "w", "lambda_max_shift"]);
    } else if m.singular {
        s.note(
            NoteKind::Warning,
            "det N = 0: the gradients all point along one direction (a straight edge), so λmin(N) = 0 and q = 0. N⁻¹, trace N⁻¹ and λmax(Σuv) have no value (they are infinite); w = 0. The position is fixed across the edge only.",
        ).about(&["det_n", "n_inverse", "trace_n_inverse", "q", "w", "lambda_max_shift"]);
    }
}

// ------------------------------------------------- practice (both Förstner)

/// The Förstner boxes (the window's and the test pattern's, which drops
/// det N).
fn forstner_boxes() -> Vec<BoxDef> {
    let sum = tol::SUM;
    vec![
        BoxDef::new("n[1,1]", "N₁₁ = Σ gx²", None, sum)
            .nudge("gx = (g(c+1) − g(c−1)) / 2 at each interior pixel; square and add."),
        BoxDef::new("n[1,2]", "N₁₂ = Σ gx·gy", None, sum)
            .nudge("gy = (g(r+1) − g(r−1)) / 2; multiply gx and gy pixel by pixel and add.")
            .sign_flip("The size is right but the sign is not: gx is the next column minus the previous one, gy the next row minus the previous one."),
        BoxDef::new("n[2,2]", "N₂₂ = Σ gy²", None, sum).nudge("Square gy and add."),
        BoxDef::new(
            "det_n",
            "det N",
            None,
            Tolerance {
                atol: 0.5,
                rtol: 0.001,
            },
        )
        .nudge("N₁₁·N₂₂ − N₁₂²."),
        BoxDef::new(
            "w",
            "Weight w = 1 / tr(N⁻¹)",
            None,
            Tolerance {
                atol: 0.01,
                rtol: 0.001,
            },
        )
        .nudge("tr(N⁻¹) = tr N / det N, so w = det N / tr N."),
        BoxDef::new("q", "Roundness q", None, Tolerance::abs(0.001))
            .nudge("q = 4 det N / (tr N)²: 1 for a round error ellipse."),
        BoxDef::new(
            "weak_angle_deg",
            "Direction of the weak axis",
            Some("°"),
            Tolerance::abs(0.1),
        )
        .nudge("The strong direction is ½·atan2(2N₁₂, N₁₁ − N₂₂); the weak one is 90° on."),
    ]
}

/// The later Förstner boxes from the student's N (and det N, where it has
/// a box): the example's solution `s` gives the exact ones.
fn forstner_chain(s: &Solution, g: &Record) -> Result<Record> {
    let a = or_given(g, "n[1,1]", value_in(s, "n[1,1]")?);
    let b = or_given(g, "n[1,2]", value_in(s, "n[1,2]")?);
    let d = or_given(g, "n[2,2]", value_in(s, "n[2,2]")?);
    let det = or_given(g, "det_n", a * d - b * b);
    let trace = a + d;
    // the direction of the weak axis from the student's N, as the core computes it
    let sums = Sums {
        gx: 0.0,
        gy: 0.0,
        gxgy: b,
        gx2: a,
        gy2: d,
    };
    let weak = Measures::from_sums(&sums, 1).weak_angle;
    Ok(Record::new()
        .with("n[1,1]", a)
        .with("n[1,2]", b)
        .with("n[2,2]", d)
        .with("det_n", det)
        .with("w", or_given(g, "w", det / trace))
        .with("q", 4.0 * det / (trace * trace))
        .with("weak_angle_deg", weak.to_degrees()))
}

fn forstner_mistakes(s: &Solution) -> Result<Vec<Mistake>> {
    let v = |k: &str| value_in(s, k);
    let (a, b, d) = (v("n[1,1]")?, v("n[1,2]")?, v("n[2,2]")?);
    const HALF: &str = "The central difference is (g(c+1) − g(c−1)) / 2: without the ½ every product is 4 times too big.";
    const SWAP: &str = "gx runs along a row (columns c), gy down a column (rows r).";
    Ok(vec![
        Mistake::new("n[1,1]", "½ forgotten in the gradient", HALF, 4.0 * a),
        Mistake::new("n[1,2]", "½ forgotten in the gradient", HALF, 4.0 * b),
        Mistake::new("n[2,2]", "½ forgotten in the gradient", HALF, 4.0 * d),
        Mistake::new("n[1,1]", "rows and columns swapped", SWAP, d),
        Mistake::new("n[2,2]", "rows and columns swapped", SWAP, a),
        Mistake::new(
            "det_n",
            "plus instead of minus",
            "det N = N₁₁·N₂₂ − N₁₂².",
            a * d + b * b,
        ),
        Mistake::new(
            "w",
            "tr(N⁻¹) instead of its inverse",
            "w is one over the trace of N⁻¹: det N / tr N.",
            v("trace_n_inverse").unwrap_or(f64::NAN),
        ),
        Mistake::new("w", "½ forgotten in the gradient", HALF, 4.0 * v("w")?),
        Mistake::new(
            "q",
            "the 4 left out",
            "q = 4 det N / (tr N)², so that a round ellipse gives 1.",
            v("q")? / 4.0,
        ),
        Mistake::new(
            "weak_angle_deg",
            "degrees vs radians",
            "That is the angle in radians; the box asks for degrees (× 180/π).",
            v("weak_angle_deg")?.to_radians(),
        ),
    ])
}
