//! Seed 000 Examples 13–14 and seed 003: the Förstner operator (gradient
//! table, N, det N, N⁻¹, trace N⁻¹, w, q, eigenvalues, seed 003's precision
//! test and error ellipse) and the Moravec operator on a window, step by
//! step; and the Förstner operator on a generated test pattern, where the
//! window can be moved and the whole image is thresholded and suppressed.

use super::fields::{is_seed, Field, Inputs, Kind};
use super::{Example, Lab, Topic};
use crate::error::{Error, Result};
use crate::interest::{self, Case, Forstner, Measures, Precision};
use crate::raster::Grid;
use crate::solution::{num, tex, NoteKind, Record, Solution, Step, Value};

mod forstner_image;
mod moravec_window;
use forstner_image::*;
use moravec_window::*;

const TITLE: &str = "Interest operators";
/// Side of the generated test pattern (pixels).
pub const PATTERN_SIZE: usize = 64;
/// Seed of the test pattern's noise generator (fixed: the pattern is the
/// same on every run and every machine).
pub const PATTERN_SEED: u64 = 7;

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[
        Example {
            id: "forstner-window",
            title: "Förstner operator",
            source: "Worked examples, Example 13; Lecture 21: Image matching",
            summary: "Gradients by central differences, the matrix N, its inverse, weight w, roundness q, and Lecture 21's precision test with the error ellipse.",
            fields: forstner_fields,
            solve: forstner_window,
            answer: &["w", "q", "accepted"],
            labels: &[],
            lab: Some(Lab { family: "interest", explains: &[] }),
            practice: None,
        },
        Example {
            id: "moravec-window",
            title: "Moravec operator",
            source: "Worked examples, Example 14",
            summary: "Four directional differences at each interior pixel, squared and summed, averaged over the window.",
            fields: moravec_fields,
            solve: moravec_window,
            answer: &["sums", "mean"],
            labels: &[],
            lab: Some(Lab { family: "interest", explains: &[] }),
            practice: None,
        },
        Example {
            id: "forstner-image",
            title: "Förstner operator on a test pattern",
            source: "Lecture 21: Image matching; Worked examples, Example 13",
            summary: "Move a window over a generated 64×64 pattern (corners, edges, a flat area, noise): N, w, q and the error ellipse there, and the interest points of the whole image after thresholding and suppression.",
            fields: image_fields,
            solve: forstner_image,
            answer: &["w", "q", "points"],
            labels: &[],
            lab: Some(Lab { family: "interest", explains: &[] }),
            practice: None,
        },
];

/// The topic: its module (`web/interest/`) and title.
pub const TOPIC: Topic = Topic {
    module: "interest",
    title: TITLE,
    examples: EXAMPLES,
};

fn rows(m: &[[f64; 4]]) -> Value {
    Value::matrix(&m.iter().map(|r| r.to_vec()).collect::<Vec<_>>())
}

fn window_field(default: Value, help: &'static str) -> Field {
    Field {
        key: "window",
        label: "Window of grey values",
        help,
        kind: Kind::Matrix {
            rows: None,
            cols: None,
        },
        default,
        when: None,
    }
}

fn example_13() -> Value {
    Value::matrix(
        &[
            [10.0, 13.0, 3.0, 11.0, 13.0],
            [11.0, 15.0, 10.0, 9.0, 9.0],
            [9.0, 24.0, 7.0, 8.0, 10.0],
            [10.0, 13.0, 14.0, 15.0, 13.0],
            [13.0, 18.0, 17.0, 19.0, 21.0],
        ]
        .map(|r| r.to_vec()),
    )
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

fn forstner_fields() -> Vec<Field> {
    vec![
        window_field(
            example_13(),
            "At least 3×3 (5×5 or 7×7 in the course notes); gradients are computed at the interior pixels.",
        ),
        sigma_n(1.0),
        threshold(),
    ]
}

fn moravec_fields() -> Vec<Field> {
    vec![window_field(
        rows(&[
            [12.0, 15.0, 5.0, 13.0],
            [10.0, 27.0, 9.0, 11.0],
            [11.0, 14.0, 15.0, 13.0],
            [12.0, 19.0, 18.0, 22.0],
        ]),
        "At least 3×3 (4×4 or 8×8 in the course notes); differences are computed at the interior pixels.",
    )]
}

/// Fixed places of the test pattern, one for each of seed 003's cases
/// (1-based column, row): the flat background, the long vertical edge and
/// the centre of the checkerboard.
const REFERENCE_WINDOWS: &[(&str, usize, usize)] = &[
    ("flat background", 34, 16),
    ("vertical edge", 47, 14),
    ("checkerboard corner", 47, 47),
];

fn image_fields() -> Vec<Field> {
    let side = PATTERN_SIZE as f64;
    vec![
        Field::integer("c", "Window centre: column c", 9.0)
            .range(1.0, side)
            .help("Column of the window's centre pixel, counted from 1 at the left."),
        Field::integer("r", "Window centre: row r", 9.0)
            .range(1.0, side)
            .help("Row of the window's centre pixel, counted from 1 at the top."),
        Field::integer("window_size", "Window size", 5.0)
            .range(3.0, 9.0)
            .help("Odd: 5×5 or 7×7 in the course notes."),
        Field::number("noise", "Noise added to the pattern", 2.0)
            .unit("grey values")
            .range(0.0, 50.0)
            .help("Uniform noise of ± this many grey values (a fixed sequence, the same every time)."),
        sigma_n(2.0),
        threshold(),
        Field::number("q_min", "Least roundness q", 0.5)
            .range(0.0, 1.0)
            .help("Förstner's roundness test (q at least this) on top of Lecture 21's threshold; 0 switches it off (Lecture 21 alone)."),
    ]
}

/// A validated matrix input as a grid.
fn grid(inputs: &Record, key: &str) -> Result<Grid> {
    let rows: Vec<Vec<f64>> = match inputs.get(key) {
        Some(Value::List(rows)) => rows
            .iter()
            .map(|r| match r {
                Value::List(xs) => xs
                    .iter()
                    .map(|x| {
                        x.as_f64()
                            .ok_or_else(|| Error::Internal(format!("{key}: not a number")))
                    })
                    .collect(),
                _ => Err(Error::Internal(format!("{key}: not a matrix"))),
            })
            .collect::<Result<_>>()?,
        _ => {
            return Err(Error::Internal(format!(
                "validated input \"{key}\" is missing"
            )))
        }
    };
    Grid::from_rows(key, &rows)
}

fn bmatrix(m: &[[f64; 2]; 2]) -> String {
    format!(
        r"\begin{{bmatrix}} {} & {} \\ {} & {} \end{{bmatrix}}",
        num(m[0][0]),
        num(m[0][1]),
        num(m[1][0]),
        num(m[1][1])
    )
}

fn mat(m: &[[f64; 2]; 2]) -> Value {
    Value::matrix(&[m[0].to_vec(), m[1].to_vec()])
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
    let mut diffs = vec![
        r"\footnotesize\begin{array}{l|l|l}".to_string(),
        r"\text{Pixel} & g'_x & g'_y \\ \hline".to_string(),
    ];
    let mut products = vec![
        r"\small\begin{array}{l|r|r|r|r|r}".to_string(),
        r"\text{Pixel} & g'_x & g'_y & g'_x g'_y & (g'_x)^2 & (g'_y)^2 \\ \hline".to_string(),
    ];
    for t in &f.rows {
        diffs.push(format!(
            r"{} = {} & ({} - {})/2 = {} & ({} - {})/2 = {} \\",
            pos(t.c, t.r),
            num(t.g),
            num(t.right),
            tex(t.left),
            num(t.gx),
            num(t.down),
            tex(t.up),
            num(t.gy),
        ));
        products.push(format!(
            r"{} & {} & {} & {} & {} & {} \\",
            pos(t.c, t.r),
            num(t.gx),
            num(t.gy),
            num(t.gxgy),
            num(t.gx2),
            num(t.gy2)
        ));
    }
    diffs.push(r"\end{array}".to_string());
    let sm = &f.sums;
    products.push(format!(
        r"\hline \text{{sum}} & {} & {} & {} & {} & {}",
        num(sm.gx),
        num(sm.gy),
        num(sm.gxgy),
        num(sm.gx2),
        num(sm.gy2)
    ));
    products.push(r"\end{array}".to_string());
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
        .formula(
            r"g'_x = \frac{g(c+1,r) - g(c-1,r)}{2},\quad g'_y = \frac{g(c,r+1) - g(c,r-1)}{2}",
            diffs.join("\n"),
        )
        .value("table", Value::matrix(&table))
        .value("gx", Value::matrix(&f.gx.rows()))
        .value("gy", Value::matrix(&f.gy.rows())),
    );
    s.step(
        Step::new(
            "Gradient table: products, squares and sums",
            "The rest of the course notes' table: the product and the squares at each pixel, then the column sums.",
        )
        .formula(
            r"\sum g'_x,\ \sum g'_y,\ \sum g'_x g'_y,\ \sum (g'_x)^2,\ \sum (g'_y)^2",
            products.join("\n"),
        )
        .value("sum_gx", sm.gx)
        .value("sum_gy", sm.gy)
        .value("sum_gxgy", sm.gxgy)
        .value("sum_gx2", sm.gx2)
        .value("sum_gy2", sm.gy2),
    );
    s.step(
        Step::new(
            "The matrix N",
            "The sums of squares on the diagonal, the sum of products off it: the normal-equation matrix of a shift of the window.",
        )
        .formula(
            r"N = \begin{bmatrix} \sum (g'_x)^2 & \sum g'_x g'_y \\ \sum g'_x g'_y & \sum (g'_y)^2 \end{bmatrix}",
            format!("N = {}", bmatrix(&m.n)),
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
            .formula(
                r"\det N = \sum (g'_x)^2 \sum (g'_y)^2 - \left(\sum g'_x g'_y\right)^2",
                format!(
                    r"\det N = {} \times {} - {}^2 = {}",
                    num(a),
                    num(d),
                    tex(b),
                    num(m.det)
                ),
            )
            .value("det_n", m.det)
            .value("trace_n", m.trace),
    );
    match m.inverse {
        Some(inv) => s.step(
            Step::new(
                "Inverse of N",
                "Swap the diagonal, change the sign of the off-diagonal, divide by the determinant. N⁻¹ is the cofactor matrix of the shift: Σuv = σn²·N⁻¹.",
            )
            .formula(
                r"N^{-1} = \frac{1}{\det N} \begin{bmatrix} \sum (g'_y)^2 & -\sum g'_x g'_y \\ -\sum g'_x g'_y & \sum (g'_x)^2 \end{bmatrix}",
                format!(
                    r"N^{{-1}} = \frac{{1}}{{{}}} {} = {}",
                    num(m.det),
                    bmatrix(&[[d, -b], [-b, a]]),
                    bmatrix(&inv)
                ),
            )
            .value("n_inverse", mat(&inv)),
        ),
        None => s.step(Step::new(
            "Inverse of N",
            "det N = 0: N has no inverse, so N⁻¹ and trace N⁻¹ have no value (the position is undetermined in at least one direction).",
        )),
    }
    s.step(
        Step::new(
            "Trace of N⁻¹ and the weight w",
            "trace N⁻¹ = trace N / det N is σu² + σv² up to σn²: the size of the error ellipse. A distinct point has a SMALL trace N⁻¹, so Förstner's weight is its reciprocal, w = det N / trace N, large for a distinct point. Where det N = 0, trace N⁻¹ is infinite and w = 0 (its limit).",
        )
        .formula(
            r"\operatorname{tr} N^{-1} = \frac{\operatorname{tr} N}{\det N},\quad w = \frac{1}{\operatorname{tr} N^{-1}} = \frac{\det N}{\operatorname{tr} N}",
            match m.trace_inverse {
                Some(ti) => format!(
                    r"\operatorname{{tr}} N^{{-1}} = \frac{{{}}}{{{}}} = {},\quad w = \frac{{{}}}{{{}}} = {}",
                    num(m.trace),
                    num(m.det),
                    num(ti),
                    num(m.det),
                    num(m.trace),
                    num(m.w)
                ),
                None => r"\operatorname{tr} N^{-1} = \infty,\quad w = 0".to_string(),
            },
        )
        .value("trace_n_inverse", m.trace_inverse)
        .value("w", m.w),
    );
    s.step(
        Step::new(
            "Roundness q",
            "q = 1 for a circular error ellipse (a symmetric corner), q = 0 for a straight edge; no value for a flat window (N = 0).",
        )
        .formula(
            r"q = \frac{4 \det N}{(\operatorname{tr} N)^2} = 1 - \left(\frac{\lambda_1 - \lambda_2}{\lambda_1 + \lambda_2}\right)^2",
            match m.q {
                Some(q) => format!(
                    r"q = \frac{{4 \times {}}}{{{}^2}} = {}",
                    num(m.det),
                    num(m.trace),
                    num(q)
                ),
                None => r"q = \frac{0}{0}\ \text{(no value)}".to_string(),
            },
        )
        .value("q", m.q),
    );
    s.step(
        Step::new(
            "Eigenvalues of N",
            "The gradient energy along the strongest and the weakest direction. λmin = det N / λmax (the same number as tr/2 − root, without cancellation).",
        )
        .formula(
            r"\lambda_{1,2} = \frac{\operatorname{tr} N}{2} \pm \sqrt{\left(\frac{N_{11} - N_{22}}{2}\right)^2 + N_{12}^2}",
            format!(
                r"\lambda_{{max}} = {},\quad \lambda_{{min}} = {}",
                num(m.lambda_max),
                num(m.lambda_min)
            ),
        )
        .value("lambda_max", m.lambda_max)
        .value("lambda_min", m.lambda_min),
    );
    let mm = m.m as f64;
    s.step(
        Step::new(
            "Lecture 21: precision of the position",
            "The gradient covariance is Σ∇g∇g = N/m (m pixels), its smallest eigenvalue λmin(N)/m; the largest eigenvalue of the shift's covariance Σuv = σn²·N⁻¹ is then σn²/λmin(N) — m cancels. The point is accepted when λmax(Σuv) ≤ T².",
        )
        .formula(
            r"\lambda_{max}(\Sigma_{uv}) = \frac{\sigma_n^2\, \lambda_{min}^{-1}(\Sigma_{\nabla g \nabla g})}{m} = \frac{\sigma_n^2}{\lambda_{min}(N)} \le T^2",
            format!(
                r"\lambda_{{min}}(\Sigma_{{\nabla g \nabla g}}) = \frac{{{}}}{{{}}} = {},\quad \lambda_{{max}}(\Sigma_{{uv}}) = \frac{{{}^2}}{{{}}} = {}\ \text{{px}}^2 {} {}^2 = {}\ \text{{px}}^2",
                num(m.lambda_min),
                num(mm),
                num(m.lambda_min / mm),
                num(sigma_n),
                num(m.lambda_min),
                opt_num(p.lambda_max_shift),
                if p.accepted { r"\le" } else { ">" },
                num(t),
                num(t * t)
            ),
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
    s.step(
        Step::new(
            "Error ellipse and the three cases",
            &format!(
                "The standard error ellipse of the position has semi-axes √λ(Σuv); its long axis lies along the weakest gradient direction. {case_text}"
            ),
        )
        .formula(
            r"\sigma_{max} = \sqrt{\lambda_{max}(\Sigma_{uv})},\quad \sigma_{min} = \sqrt{\frac{\sigma_n^2}{\lambda_{max}(N)}}",
            format!(
                r"\sigma_{{max}} = {}\ \text{{px}},\quad \sigma_{{min}} = {}\ \text{{px}},\quad \theta = {}^\circ",
                opt_num(p.sigma_max),
                opt_num(p.sigma_min),
                num(m.weak_angle.to_degrees())
            ),
        )
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

/// What each result key is, for the page's result table.
fn label_results(s: &mut Solution) {
    s.label_present(&[
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
    ]);
}

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

fn forstner_window(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let (sigma_n, t) = (i.number("sigma_n")?, i.number("threshold_px")?);
    let window = grid(inputs, "window")?;
    let f = interest::forstner(&window)?;
    let p = interest::precision(&f.measures, sigma_n, t);
    let mut s = Solution::new("forstner-window", "Förstner operator", inputs.clone());
    forstner_steps(&mut s, &f, &p, sigma_n, t);
    s.result = forstner_result(&f, &p);
    label_results(&mut s);
    singular_notes(&mut s, &f.measures);
    s.note(
        NoteKind::Convention,
        "Gradients are the worked examples' central differences, at the interior pixels only (the border pixels are neighbours). Lecture 21 computes them with a Sobel operator instead; the rest of the operator is the same.",
    ).about(&["gx", "gy"]);
    if is_seed(&forstner_fields(), inputs) {
        example_13_notes(&mut s, &f);
    } else {
        s.note(
            NoteKind::Convention,
            "The course documents give no noise level σn; the Example 13 default is 1 grey value.",
        )
        .about(&["lambda_max_shift", "accepted"]);
    }
    Ok(s)
}

fn example_13_notes(s: &mut Solution, f: &Forstner) {
    let m = &f.measures;
    for (key, label) in [
        ("sum_gx", "Sum of the column gradients Σg′x"),
        ("sum_gy", "Sum of the row gradients Σg′y"),
        ("sum_gxgy", "Sum of the products Σg′x·g′y"),
        ("sum_gx2", "Sum of the squares Σg′x²"),
        ("sum_gy2", "Sum of the squares Σg′y²"),
    ] {
        s.label(key, label, "");
    }
    let (printed_b, printed_det, printed_tr) = (-22.75, 8891.9375, 0.02);
    s.textbook = Some(
        Record::new()
            .with("sum_gx", -9.0)
            .with("sum_gy", 17.5)
            .with("sum_gxgy", -22.25)
            .with("sum_gx2", 82.0)
            .with("sum_gy2", 114.75)
            .with("n", mat(&[[82.0, printed_b], [printed_b, 114.75]]))
            .with("det_n", printed_det)
            .with(
                "n_inverse",
                mat(&[
                    [114.75 / printed_det, 22.75 / printed_det],
                    [22.75 / printed_det, 82.0 / printed_det],
                ]),
            )
            .with("trace_n_inverse", printed_tr),
    );
    s.note(
        NoteKind::Erratum,
        format!(
            "The course notes' table is right row by row, and its sum of g′x·g′y is {}; but the N it prints has {} off the diagonal. The determinant and inverse it prints follow from the slip: 82 × 114.75 − 22.75² = {} instead of 82 × 114.75 − 22.25² = {}, and 1/{} in front of N⁻¹ instead of 1/{}.",
            num(f.sums.gxgy),
            num(printed_b),
            num(82.0 * 114.75 - printed_b * printed_b),
            num(m.det),
            num(printed_det),
            num(m.det)
        ),
    ).about(&["n", "det_n", "n_inverse"]);
    s.note(
        NoteKind::Rounding,
        format!(
            "The course notes give trace N⁻¹ = {printed_tr}: the exact value is 196.75/{} = {}, and even its own determinant gives 196.75/{} = {}. Rounded to one significant digit, both slips disappear in a rounding of {} %.",
            num(m.det),
            opt_num(m.trace_inverse),
            num(printed_det),
            num(196.75 / printed_det),
            crate::solution::fmt_sig(
                m.trace_inverse
                    .map_or(0.0, |t| ((t - printed_tr) / t * 100.0).abs()),
                2
            )
        ),
    ).about(&["trace_n_inverse"]);
    s.note(
        NoteKind::Erratum,
        format!(
            "The course notes' rule \"the window is classified as an interest point if the trace exceeds a certain threshold\" is backwards. trace N⁻¹ = σu² + σv² (up to σn²) is the size of the error ellipse: a distinct point has a SMALL trace N⁻¹, and a flat window has an infinite one — the rule as printed would pick exactly the homogeneous areas. Förstner accepts a window when the weight w = 1/trace N⁻¹ = det N/trace N exceeds a threshold (here w = {}); Lecture 21 accepts when λmax(Σuv) ≤ T².",
            num(m.w)
        ),
    ).about(&["accepted"]);
    s.note(
        NoteKind::Convention,
        "The course documents give no noise level σn; the default is 1 grey value, with Lecture 21's T = 0.5 px.",
    ).about(&["lambda_max_shift", "accepted"]);
}
