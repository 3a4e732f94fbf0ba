//! Seed 000, Examples 5–9: correlation matching step by step — the 1-D
//! and 2-D normalized cross-correlation coefficient, the correlation
//! surface, and the subpixel peak from a parabola (1-D) and a six-term
//! quadratic surface fitted by least squares (2-D), with the seed's printed
//! values and why they differ.

use super::fields::{is_seed, Field, Kind, MAX_LEN};
use super::{Example, Lab, Topic};
use crate::correlation::{
    self, correlate_1d, correlate_2d, parabola_peak, quadric_peak, Extremum, Flat, Ncc, Parabola,
    Quadric,
};
use crate::error::{Error, Result};
use crate::raster::Grid;
use crate::solution::{
    exact_minus_printed, fmt_sig, num, tex, NoteKind, Record, Solution, Step, Value,
};

mod ncc_1d;
mod ncc_2d;
mod ncc_surface;
mod subpixel_1d;
mod subpixel_2d;
use ncc_1d::*;
use ncc_2d::*;
use ncc_surface::*;
use subpixel_1d::*;
use subpixel_2d::*;

const TITLE: &str = "Correlation";
/// Sub-windows shown with their full computation (the rest are in the
/// "all positions" table and the result).
const MAX_DETAILED: usize = 12;
/// Arrays up to this many values have their sums written out term by term.
const MAX_TERMS: usize = 12;

/// Example 5's template and search array.
const EX5_TEMPLATE: [f64; 7] = [1.0, 2.0, 9.0, 9.0, 8.0, 2.0, 1.0];
const EX5_SEARCH: [f64; 12] = [1.0, 2.0, 2.0, 1.0, 1.0, 3.0, 8.0, 8.0, 6.0, 1.0, 1.0, 1.0];
/// Example 7's template and search array.
const EX7_TEMPLATE: [[f64; 3]; 3] = [[30.0, 50.0, 30.0], [50.0, 50.0, 50.0], [30.0, 50.0, 30.0]];
const EX7_SEARCH: [[f64; 6]; 6] = [
    [44.0, 45.0, 64.0, 50.0, 45.0, 43.0],
    [43.0, 44.0, 63.0, 48.0, 49.0, 45.0],
    [45.0, 47.0, 65.0, 50.0, 45.0, 45.0],
    [62.0, 62.0, 69.0, 64.0, 64.0, 63.0],
    [48.0, 48.0, 68.0, 51.0, 55.0, 50.0],
    [41.0, 44.0, 63.0, 48.0, 42.0, 47.0],
];
/// Example 7's surface as the seed prints it (4 decimals).
const EX7_PRINTED: [[f64; 4]; 4] = [
    [-0.3301, 0.5405, -0.1745, -0.1217],
    [-0.3334, 0.2394, -0.3921, -0.2718],
    [0.0585, 0.9665, 0.0806, 0.6228],
    [-0.2321, 0.2904, -0.1268, -0.1997],
];
/// Example 5's ρ as the seed prints them.
const EX5_PRINTED: [f64; 6] = [-0.5, -0.59, -0.09, 0.69, 0.97, 0.37];

const RHO_FROM: &[(&str, &str)] = &[
    (
        "printed",
        "The course notes' printed ρ (as the example does)",
    ),
    ("exact", "Exact ρ, computed from the example's arrays"),
];

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[
        Example {
            id: "ncc-1d",
            title: "1-D correlation matching",
            source: "Worked examples, Example 5",
            summary: "The normalized correlation coefficient of a template with every sub-window of a 1-D search array, and the best match.",
            fields: ncc_1d_fields,
            solve: ncc_1d,
            answer: &["best", "best_c"],
            labels: &[],
            lab: None,
            practice: None,
        },
        Example {
            id: "ncc-2d",
            title: "2-D correlation coefficient",
            source: "Worked examples, Example 6",
            summary: "The normalized correlation coefficient of two equal-size arrays, with their means and the three sums.",
            fields: ncc_2d_fields,
            solve: ncc_2d,
            answer: &["rho"],
            labels: &[],
            lab: Some(Lab { family: "correlation", explains: &[] }),
            practice: None,
        },
        Example {
            id: "ncc-surface",
            title: "Correlation surface",
            source: "Worked examples, Example 7",
            summary: "The correlation coefficient of a 2-D template at every position of a search array, and the best position with its centre pixel.",
            fields: ncc_surface_fields,
            solve: ncc_surface,
            answer: &["best_position", "best_c", "best_r"],
            labels: &[],
            lab: Some(Lab { family: "correlation", explains: &[] }),
            practice: None,
        },
        Example {
            id: "subpixel-1d",
            title: "Subpixel peak in 1-D",
            source: "Worked examples, Example 8",
            summary: "A parabola through the best correlation coefficient and its two neighbours, and the location of its maximum.",
            fields: subpixel_1d_fields,
            solve: subpixel_1d,
            answer: &["c_max"],
            labels: &[],
            lab: None,
            practice: None,
        },
        Example {
            id: "subpixel-2d",
            title: "Subpixel peak in 2-D",
            source: "Worked examples, Example 9",
            summary: "A six-term quadratic surface fitted by least squares to the 3×3 correlation coefficients around the best one, and the location of its maximum.",
            fields: subpixel_2d_fields,
            solve: subpixel_2d,
            answer: &["c_max", "r_max"],
            labels: &[],
            lab: Some(Lab { family: "correlation", explains: &[] }),
            practice: None,
        },
];

/// The topic: its module (`web/correlation/`) and title.
pub const TOPIC: Topic = Topic {
    module: "correlation",
    title: TITLE,
    examples: EXAMPLES,
};

// ---------------------------------------------------------------- fields

fn vector(
    key: &'static str,
    label: &'static str,
    help: &'static str,
    default: &[f64],
    min_len: usize,
    max_len: usize,
) -> Field {
    Field {
        key,
        label,
        help,
        kind: Kind::Vector { min_len, max_len },
        default: Value::numbers(default),
        when: None,
    }
}

fn matrix(
    key: &'static str,
    label: &'static str,
    help: &'static str,
    default: Vec<Vec<f64>>,
    shape: Option<(usize, usize)>,
) -> Field {
    Field {
        key,
        label,
        help,
        kind: Kind::Matrix {
            rows: shape.map(|s| s.0),
            cols: shape.map(|s| s.1),
        },
        default: Value::matrix(&default),
        when: None,
    }
}

fn rho_from_field(help: &'static str) -> Field {
    Field {
        key: "rho_from",
        label: "Take ρ from",
        help,
        kind: Kind::Choice { options: RHO_FROM },
        default: Value::Text("printed".to_string()),
        when: None,
    }
}

fn rows_of<const N: usize>(m: &[[f64; N]]) -> Vec<Vec<f64>> {
    m.iter().map(|r| r.to_vec()).collect()
}

fn ncc_1d_fields() -> Vec<Field> {
    vec![
        vector(
            "template",
            "Template A",
            "The pattern to find: at least 2 grey values.",
            &EX5_TEMPLATE,
            2,
            MAX_LEN,
        ),
        vector(
            "search",
            "Search array",
            "Grey values to search in; at least as long as the template.",
            &EX5_SEARCH,
            2,
            MAX_LEN,
        ),
    ]
}

fn ncc_2d_fields() -> Vec<Field> {
    vec![
        matrix(
            "a",
            "Array A",
            "Grey values of the first image patch (rows separated by ;).",
            vec![
                vec![48.0, 50.0, 48.0],
                vec![51.0, 67.0, 71.0],
                vec![55.0, 67.0, 72.0],
            ],
            None,
        ),
        matrix(
            "b",
            "Array B",
            "Grey values of the second image patch, the same size as A.",
            vec![
                vec![52.0, 37.0, 41.0],
                vec![67.0, 54.0, 78.0],
                vec![42.0, 74.0, 87.0],
            ],
            None,
        ),
    ]
}

fn ncc_surface_fields() -> Vec<Field> {
    vec![
        matrix(
            "template",
            "Template T",
            "The pattern to find (rows separated by ;).",
            rows_of(&EX7_TEMPLATE),
            None,
        ),
        matrix(
            "search",
            "Search array S",
            "Grey values to search in; the template must fit inside (64×64 and more is fine).",
            rows_of(&EX7_SEARCH),
            None,
        ),
    ]
}

/// The subpixel fields that only the "printed" mode uses.
const PRINTED: &[&str] = &["printed"];

fn subpixel_1d_fields() -> Vec<Field> {
    vec![
        vector(
            "positions",
            "Positions c",
            "Centre columns of the best sub-window and its two neighbours.",
            &[7.0, 8.0, 9.0],
            3,
            3,
        )
        .when("rho_from", PRINTED),
        vector(
            "rho",
            "Correlation coefficients ρ",
            "ρ at the three positions (the printed values of Example 5).",
            &[0.69, 0.97, 0.37],
            3,
            3,
        )
        .when("rho_from", PRINTED),
        rho_from_field(
            "“Printed” uses the positions and ρ above; “Exact” takes them from Example 5's arrays computed exactly (the fields above are then not used).",
        ),
    ]
}

fn subpixel_2d_fields() -> Vec<Field> {
    vec![
        vector(
            "c",
            "Columns c",
            "The three columns of the neighbourhood (centre pixels in the search array).",
            &[2.0, 3.0, 4.0],
            3,
            3,
        )
        .when("rho_from", PRINTED),
        vector(
            "r",
            "Rows r",
            "The three rows of the neighbourhood.",
            &[3.0, 4.0, 5.0],
            3,
            3,
        )
        .when("rho_from", PRINTED),
        matrix(
            "rho",
            "Correlation coefficients ρ",
            "3×3: one row per r, one column per c (the printed values of Example 7).",
            rows_of(&[
                [-0.3334, 0.2394, -0.3921],
                [0.0585, 0.9665, 0.0806],
                [-0.2321, 0.2904, -0.1268],
            ]),
            Some((3, 3)),
        )
        .when("rho_from", PRINTED),
        rho_from_field(
            "“Printed” uses c, r and ρ above; “Exact” takes them from Example 7's arrays computed exactly (the fields above are then not used).",
        ),
    ]
}

// ---------------------------------------------------------------- input access

fn list(inputs: &Record, key: &str) -> Result<Vec<f64>> {
    match inputs.get(key) {
        Some(Value::List(items)) => items
            .iter()
            .map(|v| {
                v.as_f64().ok_or_else(|| {
                    Error::Internal(format!(
                        "validated input \"{key}\" is not a list of numbers"
                    ))
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
        Some(Value::List(items)) => items
            .iter()
            .map(|row| match row {
                Value::List(xs) => xs
                    .iter()
                    .map(|v| {
                        v.as_f64().ok_or_else(|| {
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

fn three(key: &str, xs: &[f64]) -> Result<[f64; 3]> {
    match xs {
        [a, b, c] => Ok([*a, *b, *c]),
        _ => Err(Error::input(
            key,
            format!("needs exactly 3 numbers (got {})", xs.len()),
        )),
    }
}

fn text<'a>(inputs: &'a Record, key: &str) -> Result<&'a str> {
    match inputs.get(key) {
        Some(Value::Text(t)) => Ok(t),
        _ => Err(Error::Internal(format!(
            "validated input \"{key}\" is not a choice"
        ))),
    }
}

// ---------------------------------------------------------------- formatting

fn opt(x: Option<f64>) -> Value {
    x.map_or(Value::Null, Value::Number)
}

fn opt_list(xs: impl Iterator<Item = Option<f64>>) -> Value {
    Value::List(xs.map(opt).collect())
}

fn opt_rows(rows: &[Vec<Option<f64>>]) -> Value {
    Value::List(rows.iter().map(|r| opt_list(r.iter().copied())).collect())
}

/// `ρ` as text, or "no value" for a flat window.
fn rho_text(r: Option<f64>) -> String {
    r.map_or_else(|| r"\text{no value}".to_string(), num)
}

/// A number rounded to `d` decimals, for comparing with printed values.
fn round_to(x: f64, d: i32) -> f64 {
    let f = 10f64.powi(d);
    (x * f).round() / f
}

/// LaTeX of a row vector `[x1, x2, …]` (long ones abbreviated).
fn tex_list(xs: &[f64]) -> String {
    let shown: Vec<String> = if xs.len() > 2 * MAX_TERMS {
        let mut v: Vec<String> = xs[..MAX_TERMS / 2].iter().map(|x| num(*x)).collect();
        v.push(r"\dots".to_string());
        v.extend(xs[xs.len() - 2..].iter().map(|x| num(*x)));
        v
    } else {
        xs.iter().map(|x| num(*x)).collect()
    };
    format!("[{}]", shown.join(",\\ "))
}

/// LaTeX of a matrix (`bmatrix`).
fn tex_matrix(rows: &[Vec<f64>]) -> String {
    let body: Vec<String> = rows
        .iter()
        .map(|r| r.iter().map(|x| num(*x)).collect::<Vec<_>>().join(" & "))
        .collect();
    format!(r"\begin{{bmatrix}} {} \end{{bmatrix}}", body.join(r" \\ "))
}

/// LaTeX of a column vector.
fn tex_column(xs: &[f64]) -> String {
    let rows: Vec<Vec<f64>> = xs.iter().map(|x| vec![*x]).collect();
    tex_matrix(&rows)
}

/// `(x1 + x2 + … + xn)`, written out when short.
fn tex_sum_terms(xs: &[f64]) -> String {
    if xs.len() <= MAX_TERMS {
        xs.iter().map(|x| tex(*x)).collect::<Vec<_>>().join(" + ")
    } else {
        let n = xs.len();
        format!(
            r"{} + {} + \dots + {}",
            tex(xs[0]),
            tex(xs[1]),
            tex(xs[n - 1])
        )
    }
}

/// `(a1 − Ā)(b1 − B̄) + …` (or `(a1 − Ā)² + …` with `b = None`), written
/// out when short.
fn tex_dev_terms(a: &[f64], ma: f64, b: Option<(&[f64], f64)>) -> String {
    let term = |i: usize| -> String {
        let ai = a.get(i).copied().unwrap_or(0.0);
        match b {
            Some((bs, mb)) => {
                let bi = bs.get(i).copied().unwrap_or(0.0);
                format!("({} - {})({} - {})", num(ai), num(ma), num(bi), num(mb))
            }
            None => format!("({} - {})^2", num(ai), num(ma)),
        }
    };
    let n = a.len();
    if n <= MAX_TERMS {
        (0..n).map(term).collect::<Vec<_>>().join(" + ")
    } else {
        format!(r"{} + {} + \dots + {}", term(0), term(1), term(n - 1))
    }
}

fn flat_text(n: &Ncc, a_name: &str, b_name: &str) -> String {
    match n.flat() {
        Flat::Neither => String::new(),
        Flat::A => {
            format!("{a_name} has no variance (all its values are equal), so ρ has no value.")
        }
        Flat::B => {
            format!("{b_name} has no variance (all its values are equal), so ρ has no value.")
        }
        Flat::Both => format!("Neither {a_name} nor {b_name} has any variance, so ρ has no value."),
    }
}

/// The ρ step of one pair: the quotient written out.
fn rho_formula(n: &Ncc) -> String {
    let value = match n.rho {
        Some(r) => num(r),
        None => r"\text{no value (division by zero)}".to_string(),
    };
    format!(
        r"\rho = \frac{{{}}}{{\sqrt{{{} \times {}}}}} = {}",
        num(n.sum_dadb),
        num(n.sum_da2),
        num(n.sum_db2),
        value
    )
}

/// A mean with its sum written out on a chain of its own:
/// `\sum A = 48 + 50 + … = 529,\quad \bar A = \frac{529}{9} = 58.77778`.
/// The page breaks a long chain at its top-level `+` and `\quad`, never
/// inside a fraction, so the written-out sum stays outside the fraction.
fn tex_mean(sum_sym: &str, mean_sym: &str, xs: &[f64], mean: f64) -> String {
    let total: f64 = xs.iter().sum();
    format!(
        r"{sum_sym} = {} = {},\quad {mean_sym} = \frac{{{}}}{{{}}} = {}",
        tex_sum_terms(xs),
        num(total),
        num(total),
        xs.len(),
        num(mean)
    )
}

/// The three sums of a correlation coefficient written out, each on a chain
/// of its own, then `rho = \frac{v1}{\sqrt{v2 × v3}} = ρ` with the values only.
fn tex_rho_chain(rho_sym: &str, a: &[f64], b: &[f64], n: &Ncc) -> String {
    let quotient = match n.rho {
        Some(_) => rho_formula(n).trim_start_matches(r"\rho = ").to_string(),
        None => rho_text(None),
    };
    format!(
        r"\sum (A - \bar A)(B - \bar B) = {} = {},\quad \sum (A - \bar A)^2 = {} = {},\quad \sum (B - \bar B)^2 = {} = {},\quad {rho_sym} = {}",
        tex_dev_terms(a, n.mean_a, Some((b, n.mean_b))),
        num(n.sum_dadb),
        tex_dev_terms(a, n.mean_a, None),
        num(n.sum_da2),
        tex_dev_terms(b, n.mean_b, None),
        num(n.sum_db2),
        quotient
    )
}

const RHO_SYMBOLIC: &str = r"\rho = \frac{\sum (A - \bar A)(B - \bar B)}{\sqrt{\sum (A - \bar A)^2 \, \sum (B - \bar B)^2}}";

fn ncc_values(step: Step, n: &Ncc) -> Step {
    step.value("mean_a", n.mean_a)
        .value("mean_b", n.mean_b)
        .value("sum_dadb", n.sum_dadb)
        .value("sum_da2", n.sum_da2)
        .value("sum_db2", n.sum_db2)
        .value("rho", opt(n.rho))
}

/// What each result key of this topic means, for the page's table.
fn label_results(s: &mut Solution) {
    s.label_present(&[
        ("mean_template", "Template mean Ā", ""),
        ("mean_subwindows", "Sub-window means B̄ₖ", ""),
        ("rho", "Correlation coefficients ρ", ""),
        ("best", "Best sub-window (from 1)", ""),
        ("centres", "Sub-window centres c", "px"),
        ("best_c", "Centre column c of the best window", "px"),
        ("best_r", "Centre row r of the best window", "px"),
        ("best_position", "Best position (from 1, row by row)", ""),
        ("best_col", "Surface column of the best position", ""),
        ("best_row", "Surface row of the best position", ""),
        ("mean_a", "Mean Ā", ""),
        ("mean_b", "Mean B̄", ""),
        ("sum_dadb", "Σ(A−Ā)(B−B̄)", ""),
        ("sum_da2", "Σ(A−Ā)²", ""),
        ("sum_db2", "Σ(B−B̄)²", ""),
        ("coefficients", "Coefficients a₀, a₁, …", ""),
        ("c_max", "Subpixel peak column c", "px"),
        ("r_max", "Subpixel peak row r", "px"),
        ("extremum", "Stationary point", ""),
        ("rho_max", "ρ at the peak", ""),
        ("positions", "Positions c used", "px"),
        ("c", "Columns c used", "px"),
        ("r", "Rows r used", "px"),
        ("residuals", "Residuals V of the nine ρ", ""),
        ("sigma0", "σ₀ of the fit", ""),
        ("c_max_printed_rho", "Peak column from the printed ρ", "px"),
        ("r_max_printed_rho", "Peak row from the printed ρ", "px"),
        ("peak_shift", "How far the peak moves", "px"),
    ]);
}
