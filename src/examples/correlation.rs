//! Seed 000, Examples 5–9: correlation matching step by step — the 1-D
//! and 2-D normalized cross-correlation coefficient, the correlation
//! surface, and the subpixel peak from a parabola (1-D) and a six-term
//! quadratic surface fitted by least squares (2-D), with the seed's printed
//! values and why they differ.
//!
//! Each example is one file beside this one; here is only what they share:
//! the seed's arrays, the `rho_from` field, the result labels and the
//! relation builders of means, sums and ρ.

use super::drill::Rng;
use super::fields::{to_rows, Field, Inputs};
use super::{Example, Lab, Topic};
use crate::correlation::{self, Extremum, Flat, Ncc};
use crate::error::{Error, Result};
use crate::raster::Grid;
use crate::solution::{num, tex, Form, NoteKind, Record, Relation, Solution, Step, Value};

pub mod ncc_1d;
pub mod ncc_2d;
pub mod ncc_surface;
pub mod subpixel_1d;
pub mod subpixel_2d;

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

const RHO_FROM: &[(&str, &str)] = &[
    (
        "printed",
        "The course notes' printed ρ (as the example does)",
    ),
    ("exact", "Exact ρ, computed from the example's arrays"),
];

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[
    ncc_1d::EXAMPLE,
    ncc_2d::EXAMPLE,
    ncc_surface::EXAMPLE,
    subpixel_1d::EXAMPLE,
    subpixel_2d::EXAMPLE,
];

/// The topic: its module (`web/correlation/`) and title.
pub const TOPIC: Topic = Topic {
    module: "correlation",
    title: TITLE,
    examples: EXAMPLES,
};

/// What each result key of this topic means, for the page's table (every
/// example's `labels`; only the keys a solution has are used).
const LABELS: &[(&str, &str, &str)] = &[
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
];

// ---------------------------------------------------------------- fields

fn rho_from_field(help: &'static str) -> Field {
    Field::choice("rho_from", "Take ρ from", RHO_FROM, "printed").help(help)
}

/// The subpixel fields that only the "printed" mode uses.
const PRINTED: &[&str] = &["printed"];

// ---------------------------------------------------------------- input access

/// Matrix input `key` as a grid.
fn grid(inputs: &Record, key: &str) -> Result<Grid> {
    Grid::from_rows(key, &Inputs(inputs).rows(key)?)
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

/// A grid's centre offset: `(size − 1)/2`.
fn half(size: usize) -> f64 {
    (size as f64 - 1.0) / 2.0
}

/// True when any of `keys` differs from its default: fields a mode does
/// not use were changed (worth a note).
/// The warning of the subpixel examples' "exact" mode, which does not read
/// the printed fields `keys`: given when any of them was changed.
fn unused_note(s: &mut Solution, fields: &[Field], inputs: &Record, keys: &[&str], text: &str) {
    let changed = keys.iter().any(|k| {
        fields
            .iter()
            .any(|f| f.key == *k && inputs.get(k) != Some(&f.default))
    });
    if changed {
        s.note(NoteKind::Warning, text).about(keys);
    }
}

fn extremum_name(e: &Extremum) -> &'static str {
    match e {
        Extremum::Maximum { .. } => "maximum",
        Extremum::Minimum { .. } => "minimum",
        Extremum::Saddle { .. } => "saddle",
        Extremum::Degenerate => "none",
    }
}

fn peak_value(e: &Extremum) -> Option<f64> {
    match e {
        Extremum::Maximum { value, .. } => Some(*value),
        _ => None,
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

/// `ρ` as LaTeX, or "no value" for a flat window.
fn rho_text(r: Option<f64>) -> String {
    r.map_or_else(|| r"\text{no value}".to_string(), num)
}

/// A number rounded to `d` decimals, for comparing with printed values.
fn round_to(x: f64, d: i32) -> f64 {
    let f = 10f64.powi(d);
    (x * f).round() / f
}

/// The indices of a long list that are shown: all of a short one, else
/// the first [`MAX_TERMS`] and the last (`None` marks the gap).
fn shown(n: usize) -> Vec<Option<usize>> {
    if n <= 2 * MAX_TERMS {
        (0..n).map(Some).collect()
    } else {
        (0..MAX_TERMS)
            .map(Some)
            .chain([None, Some(n - 1)])
            .collect()
    }
}

/// A list as plain text, `1, 2, 9, …, 1` (for a step's text).
fn plain_list(xs: &[f64]) -> String {
    let cells: Vec<String> = shown(xs.len())
        .into_iter()
        .map(|i| i.map_or_else(|| "…".to_string(), |i| num(xs[i])))
        .collect();
    format!("[{}]", cells.join(", "))
}

/// A list of LaTeX cells as a form `[x_1, x_2, …]` the page may break
/// between elements (long ones abbreviated).
fn list_form(cells: &[String]) -> Form {
    let picked: Vec<&str> = shown(cells.len())
        .into_iter()
        .map(|i| i.map_or(r"\dots", |i| cells[i].as_str()))
        .collect();
    let last = picked.len().saturating_sub(1);
    Form::terms(picked.iter().enumerate().map(|(k, c)| {
        let open = if k == 0 { "[" } else { "" };
        let close = if k == last { "]" } else { "," };
        format!("{open}{c}{close}")
    }))
}

/// A column of LaTeX symbols (`a_0 … a_n`).
fn unknowns(n: usize, name: &str) -> Form {
    Form::grid_tex(
        "bmatrix",
        (0..n).map(|k| vec![format!("a_{k}")]).collect(),
        name,
    )
}

/// A sum written out term by term as a form (`t_1 + t_2 + …`), the terms
/// pieces the page may break between; long sums abbreviated as
/// `t_1 + t_2 + \dots + t_n`.
fn sum_form(n: usize, term: impl Fn(usize) -> String) -> Form {
    let picked: Vec<Option<usize>> = if n <= MAX_TERMS {
        (0..n).map(Some).collect()
    } else {
        vec![Some(0), Some(1), None, Some(n - 1)]
    };
    Form::terms(picked.into_iter().enumerate().map(|(k, i)| {
        let t = i.map_or_else(|| r"\dots".to_string(), &term);
        if k == 0 {
            t
        } else {
            format!("+ {t}")
        }
    }))
}

/// A mean with its sum written out, as two relations:
/// `\sum A = 48 + 50 + … = 529` and `\bar A = \frac{529}{9} = 58.77778`
/// (`def` is the mean's definition, `key` the value it computes).
fn mean_relations(
    sum_sym: &str,
    mean_sym: &str,
    def: &str,
    key: &str,
    xs: &[f64],
    mean: f64,
) -> [Relation; 2] {
    let total: f64 = xs.iter().sum();
    [
        Relation::new(sum_sym)
            .subst(sum_form(xs.len(), |i| tex(xs[i])))
            .value(total, ""),
        Relation::new(mean_sym)
            .key(key)
            .sym(def)
            .subst(format!(r"\frac{{{}}}{{{}}}", num(total), xs.len()))
            .value(mean, ""),
    ]
}

/// The names of the two arrays in a step's sums: their letter, and how
/// one value is written (`A`, `A_j`, `T_{ij}`).
#[derive(Clone, Copy)]
struct Names {
    a: &'static str,
    a_i: &'static str,
    b: &'static str,
    b_i: &'static str,
}

/// Template A against sub-window B (1-D).
const AB_1D: Names = Names {
    a: "A",
    a_i: "A_j",
    b: "B",
    b_i: "B_j",
};
/// Array A against array B (2-D).
const AB_2D: Names = Names {
    a: "A",
    a_i: "A_{ij}",
    b: "B",
    b_i: "B_{ij}",
};
/// Template T against window B (2-D).
const TB_2D: Names = Names {
    a: "T",
    a_i: "T_{ij}",
    b: "B",
    b_i: "B_{ij}",
};

/// `Σ ΔA·ΔB = Σ(A − Ā)(B − B̄) = (a₁ − Ā)(b₁ − B̄) + … = v`.
fn products_relation(x: Names, a: &[f64], b: &[f64], n: &Ncc) -> Relation {
    Relation::new(format!(r"\sum \Delta {} \, \Delta {}", x.a, x.b))
        .key("sum_dadb")
        .sym(format!(
            r"\sum ({} - \bar {})({} - \bar {})",
            x.a_i, x.a, x.b_i, x.b
        ))
        .subst(sum_form(a.len(), |i| {
            format!(
                "({} - {})({} - {})",
                num(a[i]),
                num(n.mean_a),
                num(b.get(i).copied().unwrap_or(0.0)),
                num(n.mean_b)
            )
        }))
        .value(n.sum_dadb, "")
}

/// `Σ ΔA² = Σ(A − Ā)² = (a₁ − Ā)² + … = v` (`key`: `sum_da2` or `sum_db2`).
fn squares_relation(
    name: &str,
    name_i: &str,
    key: &str,
    xs: &[f64],
    mean: f64,
    v: f64,
) -> Relation {
    Relation::new(format!(r"\sum \Delta {name}^2"))
        .key(key)
        .sym(format!(r"\sum ({name_i} - \bar {name})^2"))
        .subst(sum_form(xs.len(), |i| {
            format!("({} - {})^2", num(xs[i]), num(mean))
        }))
        .value(v, "")
}

/// The symbolic ρ: sum of products over the root of the sums of squares.
const RHO_SYMBOLIC: &str =
    r"\frac{\sum (A - \bar A)(B - \bar B)}{\sqrt{\sum (A - \bar A)^2 \, \sum (B - \bar B)^2}}";

/// `ρ = \frac{Σ}{\sqrt{Σ × Σ}} = value` (or "no value" for a flat array).
fn rho_relation(rho_sym: &str, n: &Ncc) -> Relation {
    let r = Relation::new(rho_sym)
        .key("rho")
        .sym(RHO_SYMBOLIC)
        .subst(format!(
            r"\frac{{{}}}{{\sqrt{{{} \times {}}}}}",
            num(n.sum_dadb),
            num(n.sum_da2),
            num(n.sum_db2)
        ));
    match n.rho {
        Some(v) => r.value(v, ""),
        None => r.result(r"\text{no value (division by zero)}"),
    }
}

/// The three sums and ρ of one pair, each a relation of `step` (the sums
/// with their numbers only: ρ's symbolic side says what they are).
fn rho_chain(step: Step, x: Names, rho_sym: &str, a: &[f64], b: &[f64], n: &Ncc) -> Step {
    let numbers_only = |r: Relation| Relation {
        symbolic: Vec::new(),
        ..r
    };
    step.relation(numbers_only(products_relation(x, a, b, n)))
        .relation(numbers_only(squares_relation(
            x.a, x.a_i, "sum_da2", a, n.mean_a, n.sum_da2,
        )))
        .relation(numbers_only(squares_relation(
            x.b, x.b_i, "sum_db2", b, n.mean_b, n.sum_db2,
        )))
        .relation(rho_relation(rho_sym, n))
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

fn ncc_values(step: Step, n: &Ncc) -> Step {
    step.value("mean_a", n.mean_a)
        .value("mean_b", n.mean_b)
        .value("sum_dadb", n.sum_dadb)
        .value("sum_da2", n.sum_da2)
        .value("sum_db2", n.sum_db2)
        .value("rho", opt(n.rho))
}

// ---------------------------------------------------------------- practice

/// Grey values 0–9 in which no two neighbours are equal: every window of
/// two or more values has texture.
fn textured(rng: &mut Rng, n: usize) -> Vec<f64> {
    let mut v = vec![rng.num(0, 9)];
    for i in 1..n {
        v.push(((v[i - 1] as i64 + rng.int(1, 9)) % 10) as f64);
    }
    v
}

/// ρ of `a` and `b` about the means given (a student's, for errors carried
/// forward; 0 and 0 for the "mean not subtracted" mistake).
fn rho_about(a: &[f64], mean_a: f64, b: &[f64], mean_b: f64) -> f64 {
    let [ab, aa, bb] = correlation::sums_about(a, mean_a, b, mean_b);
    correlation::rho_of_sums(ab, aa, bb)
}

/// The sign flip of ρ (and of Σ ΔA·ΔB, which gives ρ its sign).
const RHO_FLIP: &str = "The size is right but the sign is not: take both deviations the same way round, each value minus its own mean.";
