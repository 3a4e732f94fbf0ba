//! Seed 000, Examples 5–9: correlation matching step by step — the 1-D
//! and 2-D normalized cross-correlation coefficient, the correlation
//! surface, and the subpixel peak from a parabola (1-D) and a six-term
//! quadratic surface fitted by least squares (2-D), with the seed's printed
//! values and why they differ.

use super::fields::{is_seed, Field, Kind, MAX_LEN};
use super::Entry;
use crate::correlation::{
    self, correlate_1d, correlate_2d, parabola_peak, quadric_peak, Extremum, Flat, Ncc, Parabola,
    Quadric,
};
use crate::error::{Error, Result};
use crate::raster::Grid;
use crate::solution::{
    exact_minus_printed, fmt_sig, num, tex, NoteKind, Record, Solution, Step, Value,
};

const TOPIC: &str = "Correlation";
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

pub fn entries() -> Vec<Entry> {
    vec![
        Entry {
            id: "ncc-1d",
            title: "1-D correlation matching",
            topic: TOPIC,
            source: "Worked examples, Example 5",
            summary: "The normalized correlation coefficient of a template with every sub-window of a 1-D search array, and the best match.",
            fields: ncc_1d_fields,
            solve: Some(ncc_1d),
        },
        Entry {
            id: "ncc-2d",
            title: "2-D correlation coefficient",
            topic: TOPIC,
            source: "Worked examples, Example 6",
            summary: "The normalized correlation coefficient of two equal-size arrays, with their means and the three sums.",
            fields: ncc_2d_fields,
            solve: Some(ncc_2d),
        },
        Entry {
            id: "ncc-surface",
            title: "Correlation surface",
            topic: TOPIC,
            source: "Worked examples, Example 7",
            summary: "The correlation coefficient of a 2-D template at every position of a search array, and the best position with its centre pixel.",
            fields: ncc_surface_fields,
            solve: Some(ncc_surface),
        },
        Entry {
            id: "subpixel-1d",
            title: "Subpixel peak in 1-D",
            topic: TOPIC,
            source: "Worked examples, Example 8",
            summary: "A parabola through the best correlation coefficient and its two neighbours, and the location of its maximum.",
            fields: subpixel_1d_fields,
            solve: Some(subpixel_1d),
        },
        Entry {
            id: "subpixel-2d",
            title: "Subpixel peak in 2-D",
            topic: TOPIC,
            source: "Worked examples, Example 9",
            summary: "A six-term quadratic surface fitted by least squares to the 3×3 correlation coefficients around the best one, and the location of its maximum.",
            fields: subpixel_2d_fields,
            solve: Some(subpixel_2d),
        },
    ]
}

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

// ---------------------------------------------------------------- Example 5

fn ncc_1d(inputs: &Record) -> Result<Solution> {
    let template = list(inputs, "template")?;
    let search = list(inputs, "search")?;
    let profile = correlate_1d(&template, &search)?;
    let n = template.len();
    let mut s = Solution::new("ncc-1d", "1-D correlation matching", inputs.clone());
    let first = profile.windows.first().copied();
    let (mean_a, sum_da2) = first.map_or((0.0, 0.0), |w| (w.mean_a, w.sum_da2));

    s.step(
        Step::new(
            "Template mean",
            "The mean of the template's grey values, and the sum of its squared deviations from it (the same for every sub-window).",
        )
        .formula(
            r"\bar A = \frac{1}{n}\sum A_j,\quad \sum (A_j - \bar A)^2",
            format!(
                r"{},\quad \sum (A_j - \bar A)^2 = {} = {}",
                tex_mean(r"\sum A_j", r"\bar A", &template, mean_a),
                tex_dev_terms(&template, mean_a, None),
                num(sum_da2)
            ),
        )
        .value("mean_template", mean_a)
        .value("sum_da2", sum_da2),
    );

    let count = profile.windows.len();
    let starts: Vec<f64> = (1..=count).map(|k| k as f64).collect();
    let half = (n as f64 - 1.0) / 2.0;
    let centres: Vec<f64> = starts.iter().map(|k| k + half).collect();
    s.step(
        Step::new(
            "Sub-windows",
            &format!(
                "The template slides along the search array one value at a time. With {} search values and a template of {n}, there are {} − {n} + 1 = {count} sub-windows B_k = (S_k, …, S_(k+{})), counted from 1; the centre of B_k is at column c = k + {}.",
                search.len(),
                search.len(),
                n - 1,
                num(half)
            ),
        )
        .formula(
            r"K = N - n + 1",
            format!("K = {} - {n} + 1 = {count}", search.len()),
        )
        .value("starts", Value::numbers(&starts))
        .value("centres", Value::numbers(&centres)),
    );

    let mut detailed: Vec<usize> = (0..count.min(MAX_DETAILED)).collect();
    if let Some(b) = profile.best {
        if b >= MAX_DETAILED {
            detailed.push(b);
        }
    }
    for &k in &detailed {
        let Some(w) = profile.windows.get(k) else {
            continue;
        };
        let sub = search.get(k..k + n).unwrap_or(&[]);
        let mut text = format!(
            "B_{} = {}: its mean, then the correlation coefficient with the template.",
            k + 1,
            tex_list(sub).replace(r",\ ", ", ")
        );
        let flat = flat_text(w, "The template", &format!("B_{}", k + 1));
        if !flat.is_empty() {
            text = format!("{text} {flat}");
        }
        let step = Step::new(&format!("Sub-window {}", k + 1), &text)
            .formula(
                &format!(
                    r"\bar B_{{{0}}} = \frac{{1}}{{n}}\sum B_j,\quad {RHO_SYMBOLIC}",
                    k + 1
                ),
                format!(
                    r"{},\quad {}",
                    tex_mean(
                        &format!(r"\sum B_{{{}}}", k + 1),
                        &format!(r"\bar B_{{{}}}", k + 1),
                        sub,
                        w.mean_b
                    ),
                    tex_rho_chain(&format!(r"\rho_{{{}}}", k + 1), &template, sub, w)
                ),
            )
            .value("k", (k + 1) as f64)
            .value("start", (k + 1) as f64)
            .value("centre", k as f64 + 1.0 + half)
            .value("window", Value::numbers(sub));
        s.step(ncc_values(step, w));
    }

    let means: Vec<f64> = profile.windows.iter().map(|w| w.mean_b).collect();
    let rhos: Vec<Option<f64>> = profile.windows.iter().map(|w| w.rho).collect();
    let rho_tex: Vec<String> = rhos.iter().map(|r| rho_text(*r)).collect();
    let shown = if rho_tex.len() > 2 * MAX_TERMS {
        format!(
            r"{},\ \dots,\ {}",
            rho_tex[..MAX_TERMS].join(r",\ "),
            rho_tex[rho_tex.len() - 1]
        )
    } else {
        rho_tex.join(r",\ ")
    };
    let mut all = Step::new(
        "All positions",
        &format!(
            "The correlation coefficient at every position{}.",
            if count > detailed.len() {
                format!(
                    " (the computation of the first {MAX_DETAILED} and the best is written out above; select a position in the figure for any other)"
                )
            } else {
                String::new()
            }
        ),
    )
    .formula(r"\rho_k,\ k = 1 \dots K", format!(r"\rho = [{shown}]"))
    .value("mean_subwindows", Value::numbers(&means))
    .value("rho", opt_list(rhos.iter().copied()))
    .value(
        "sum_dadb",
        Value::numbers(&profile.windows.iter().map(|w| w.sum_dadb).collect::<Vec<_>>()),
    )
    .value(
        "sum_db2",
        Value::numbers(&profile.windows.iter().map(|w| w.sum_db2).collect::<Vec<_>>()),
    )
    .value("centres", Value::numbers(&centres));
    all = all.value("best", opt(profile.best.map(|b| (b + 1) as f64)));
    s.step(all);

    let best_c = profile.best.map(|b| b as f64 + 1.0 + half);
    match (profile.best, profile.best.and_then(|b| rhos.get(b).copied().flatten())) {
        (Some(b), Some(r)) => s.step(
            Step::new(
                "Best match",
                &format!(
                    "The largest correlation coefficient is at sub-window {} (centre at column c = {}): the best match for the template.",
                    b + 1,
                    num(b as f64 + 1.0 + half)
                ),
            )
            .formula(
                r"k^* = \arg\max_k \rho_k",
                format!(r"k^* = {},\quad \rho_{{{}}} = {}", b + 1, b + 1, num(r)),
            )
            .value("best", (b + 1) as f64)
            .value("best_c", b as f64 + 1.0 + half),
        ),
        _ => s.step(Step::new(
            "Best match",
            "No position has a correlation coefficient, so there is no best match.",
        )),
    }

    s.result = Record::new()
        .with("mean_template", mean_a)
        .with("mean_subwindows", Value::numbers(&means))
        .with("rho", opt_list(rhos.iter().copied()))
        .with("best", opt(profile.best.map(|b| (b + 1) as f64)))
        .with("centres", Value::numbers(&centres))
        .with("best_c", opt(best_c));

    s.note(
        NoteKind::Convention,
        format!(
            "Positions count from 1, as the course notes do: sub-window k covers search values k … k+{}, and its centre is at column c = k + {} (the positions Example 8 uses).",
            n - 1,
            num(half)
        ),
    ).about(&["centres", "best_c", "best"]);
    flat_notes_1d(&mut s, &profile);
    if is_seed(&ncc_1d_fields(), inputs) {
        seed_notes_5(&mut s, &profile);
    }
    label_results(&mut s);
    Ok(s)
}

fn flat_notes_1d(s: &mut Solution, profile: &correlation::Profile) {
    let Some(first) = profile.windows.first() else {
        return;
    };
    if matches!(first.flat(), Flat::A | Flat::Both) {
        s.note(
            NoteKind::Warning,
            "The template has no variance (all its values are equal): the correlation coefficient is 0/0 at every position, so no ρ has a value and there is no best match.",
        ).about(&["rho", "best"]);
        return;
    }
    let flat: Vec<String> = profile
        .windows
        .iter()
        .enumerate()
        .filter(|(_, w)| w.rho.is_none())
        .map(|(k, _)| (k + 1).to_string())
        .collect();
    if !flat.is_empty() {
        s.note(
            NoteKind::Warning,
            format!(
                "Sub-window{} {} {} no variance (all values equal): ρ is 0/0 there and has no value.",
                if flat.len() > 1 { "s" } else { "" },
                flat.join(", "),
                if flat.len() > 1 { "have" } else { "has" }
            ),
        ).about(&["rho"]);
        if profile.best.is_none() {
            s.note(
                NoteKind::Warning,
                "No sub-window has a correlation coefficient, so there is no best match.",
            )
            .about(&["best"]);
        }
    }
    if profile.ties > 1 {
        s.note(
            NoteKind::Warning,
            format!(
                "{} positions share the largest correlation coefficient; the first of them is taken as the best.",
                profile.ties
            ),
        ).about(&["best"]);
    }
}

fn seed_notes_5(s: &mut Solution, profile: &correlation::Profile) {
    s.textbook = Some(
        Record::new()
            .with("mean_template", 4.57)
            .with(
                "mean_subwindows",
                Value::numbers(&[2.57, 3.57, 4.14, 4.0, 4.0, 4.0]),
            )
            .with("rho", Value::numbers(&EX5_PRINTED))
            .with("best", 5.0),
    );
    let w = |k: usize| profile.windows.get(k).copied();
    let r = |k: usize| w(k).and_then(|w| w.rho).unwrap_or(0.0);
    let (r1, r4, r5) = (r(0), r(3), r(4));
    let mean_a = w(0).map_or(0.0, |w| w.mean_a);
    let means: Vec<f64> = profile.windows.iter().map(|w| w.mean_b).collect();
    let (dadb4, da2, db24) = w(3).map_or((0.0, 0.0, 0.0), |w| (w.sum_dadb, w.sum_da2, w.sum_db2));
    s.note(
        NoteKind::Rounding,
        format!(
            "The course notes' means Ā = 4.57 and B̄ = 2.57, 3.57, 4.14, 4, 4, 4 are the exact {} and {} rounded to two decimals; ρ2 = −0.59, ρ3 = −0.09 and ρ6 = 0.37 match the exact values to the printed two decimals.",
            num(mean_a),
            means.iter().map(|m| num(*m)).collect::<Vec<_>>().join(", ")
        ),
    ).about(&["mean_template", "mean_subwindows"]);
    s.note(
        NoteKind::Rounding,
        format!(
            "ρ1 is printed as −0.5: the exact {} rounded to one decimal only (two decimals give {}).",
            num(r1),
            fmt_sig(round_to(r1, 2), 3)
        ),
    ).about(&["rho"]);
    s.note(
        NoteKind::Erratum,
        format!(
            "ρ4 is printed as 0.69, but B4 = [1, 1, 3, 8, 8, 6, 1] gives Σ(A−Ā)(B−B̄) = {}, Σ(A−Ā)² = {}, Σ(B−B̄)² = {} and ρ4 = {} ≈ {}: the printed value is too high by more than rounding (ρ4: {}). Example 8 uses the printed 0.69.",
            num(dadb4),
            num(da2),
            num(db24),
            num(r4),
            fmt_sig(round_to(r4, 2), 2),
            exact_minus_printed(r4, 0.69, "")
        ),
    ).about(&["rho"]);
    s.note(
        NoteKind::Rounding,
        format!(
            "ρ5 is printed as 0.97; the exact {} rounds to {} (the course notes cut the third decimal off). The best match, sub-window 5, is the same.",
            num(r5),
            fmt_sig(round_to(r5, 2), 2)
        ),
    ).about(&["rho", "best"]);
}

// ---------------------------------------------------------------- Example 6

fn grid(inputs: &Record, key: &str) -> Result<Grid> {
    Grid::from_rows(key, &rows(inputs, key)?)
}

fn ncc_2d(inputs: &Record) -> Result<Solution> {
    let a = grid(inputs, "a")?;
    let b = grid(inputs, "b")?;
    let n = correlation::ncc_grid(&a, &b)?;
    let (av, bv) = (a.data(), b.data());
    let mut s = Solution::new("ncc-2d", "2-D correlation coefficient", inputs.clone());
    s.step(
        Step::new(
            "Means",
            &format!(
                "The mean grey value of each {}×{} array.",
                a.height(),
                a.width()
            ),
        )
        .formula(
            r"\bar A = \frac{1}{mn}\sum_{i,j} A_{ij},\quad \bar B = \frac{1}{mn}\sum_{i,j} B_{ij}",
            format!(
                r"{},\quad {}",
                tex_mean(r"\sum A", r"\bar A", av, n.mean_a),
                tex_mean(r"\sum B", r"\bar B", bv, n.mean_b)
            ),
        )
        .value("mean_a", n.mean_a)
        .value("mean_b", n.mean_b),
    );
    let da: Vec<Vec<f64>> = a
        .rows()
        .iter()
        .map(|r| r.iter().map(|x| x - n.mean_a).collect())
        .collect();
    let db: Vec<Vec<f64>> = b
        .rows()
        .iter()
        .map(|r| r.iter().map(|x| x - n.mean_b).collect())
        .collect();
    s.step(
        Step::new(
            "Sum of products of deviations",
            "Each value's deviation from its array's mean, multiplied pairwise and summed.",
        )
        .formula(
            r"\sum_{i,j} (A_{ij} - \bar A)(B_{ij} - \bar B)",
            format!(
                r"{} = {}",
                tex_dev_terms(av, n.mean_a, Some((bv, n.mean_b))),
                num(n.sum_dadb)
            ),
        )
        .value("da", Value::matrix(&da))
        .value("db", Value::matrix(&db))
        .value("sum_dadb", n.sum_dadb),
    );
    s.step(
        Step::new("Sum of squared deviations of A", "")
            .formula(
                r"\sum_{i,j} (A_{ij} - \bar A)^2",
                format!(
                    r"{} = {}",
                    tex_dev_terms(av, n.mean_a, None),
                    num(n.sum_da2)
                ),
            )
            .value("sum_da2", n.sum_da2),
    );
    s.step(
        Step::new("Sum of squared deviations of B", "")
            .formula(
                r"\sum_{i,j} (B_{ij} - \bar B)^2",
                format!(
                    r"{} = {}",
                    tex_dev_terms(bv, n.mean_b, None),
                    num(n.sum_db2)
                ),
            )
            .value("sum_db2", n.sum_db2),
    );
    let flat = flat_text(&n, "A", "B");
    s.step(
        ncc_values(
            Step::new(
                "Correlation coefficient",
                if flat.is_empty() {
                    "The sum of products over the square root of the product of the two sums of squares."
                } else {
                    &flat
                },
            )
            .formula(RHO_SYMBOLIC, rho_formula(&n)),
            &n,
        ),
    );
    s.result = Record::new()
        .with("mean_a", n.mean_a)
        .with("mean_b", n.mean_b)
        .with("sum_dadb", n.sum_dadb)
        .with("sum_da2", n.sum_da2)
        .with("sum_db2", n.sum_db2)
        .with("rho", opt(n.rho));
    if !flat.is_empty() {
        s.note(
            NoteKind::Warning,
            format!("{flat} The correlation coefficient is 0/0 and has no value."),
        )
        .about(&["rho"]);
    }
    if is_seed(&ncc_2d_fields(), inputs) {
        seed_notes_6(&mut s, &n, av, bv);
    }
    label_results(&mut s);
    Ok(s)
}

fn seed_notes_6(s: &mut Solution, n: &Ncc, av: &[f64], bv: &[f64]) {
    s.textbook = Some(
        Record::new()
            .with("mean_a", 58.5)
            .with("mean_b", 59.1)
            .with("sum_dadb", 1149.22)
            .with("sum_da2", 843.56)
            .with("sum_db2", 2604.89)
            .with("rho", 0.7753),
    );
    let (ma, mb) = (58.8, 59.1);
    let seed_dadb: f64 = av.iter().zip(bv).map(|(a, b)| (a - ma) * (b - mb)).sum();
    let seed_da2: f64 = av.iter().map(|a| (a - ma) * (a - ma)).sum();
    let seed_db2: f64 = bv.iter().map(|b| (b - mb) * (b - mb)).sum();
    let plain: f64 = bv.iter().map(|b| b - mb).sum();
    s.note(
        NoteKind::Erratum,
        format!(
            "The course notes print Ā = 58.5, but the nine values sum to 529 and 529/9 = {}. Their sums then use 58.8 (the mean rounded to one decimal), so 58.5 is a typo in the printed mean only.",
            num(n.mean_a)
        ),
    ).about(&["mean_a"]);
    s.note(
        NoteKind::Rounding,
        format!(
            "With the rounded means 58.8 and 59.1 the three sums come out as {}, {} and {} — the course notes' 1149.22, 843.56 and 2604.89. The exact sums {}, {} and {} agree to the printed two decimals: deviations from a mean add up to zero, so moving a mean by δ changes a sum of squares only by n·δ² (here 9 × {}² = {}).",
            fmt_sig(seed_dadb, 8),
            fmt_sig(seed_da2, 8),
            fmt_sig(seed_db2, 8),
            num(n.sum_dadb),
            num(n.sum_da2),
            num(n.sum_db2),
            fmt_sig(ma - n.mean_a, 3),
            fmt_sig(9.0 * (ma - n.mean_a).powi(2), 2)
        ),
    ).about(&["mean_b", "sum_dadb", "sum_da2", "sum_db2"]);
    s.note(
        NoteKind::Erratum,
        format!(
            "The course notes write the third sum without the squares, (52 − 59.1) + (37 − 59.1) + …, which adds up to {} (deviations sum to zero); its value 2604.89 is the sum of the squares, (52 − 59.1)² + (37 − 59.1)² + ….",
            fmt_sig(plain, 2)
        ),
    ).about(&["sum_db2"]);
    s.note(
        NoteKind::Rounding,
        format!(
            "ρ = {} is the course notes' 0.7753 to four decimals.",
            rho_text(n.rho)
        ),
    )
    .about(&["rho"]);
}

// ---------------------------------------------------------------- Example 7

/// A grid's centre offset: `(size − 1)/2`.
fn half(size: usize) -> f64 {
    (size as f64 - 1.0) / 2.0
}

fn ncc_surface(inputs: &Record) -> Result<Solution> {
    let template = grid(inputs, "template")?;
    let search = grid(inputs, "search")?;
    let surface = correlate_2d(&template, &search)?;
    let (tw, th) = (template.width(), template.height());
    let mut s = Solution::new("ncc-surface", "Correlation surface", inputs.clone());
    let t_mean = surface.windows.first().map_or(0.0, |w| w.mean_a);
    let t_da2 = surface.windows.first().map_or(0.0, |w| w.sum_da2);
    s.step(
        Step::new(
            "Template mean",
            "The template's mean and the sum of its squared deviations, the same for every position.",
        )
        .formula(
            r"\bar T = \frac{1}{mn}\sum T_{ij},\quad \sum (T_{ij} - \bar T)^2",
            format!(
                r"{},\quad \sum (T_{{ij}} - \bar T)^2 = {} = {}",
                tex_mean(r"\sum T_{ij}", r"\bar T", template.data(), t_mean),
                tex_dev_terms(template.data(), t_mean, None),
                num(t_da2)
            ),
        )
        .value("mean_template", t_mean)
        .value("sum_da2", t_da2),
    );
    let (w, h) = (surface.width, surface.height);
    s.step(
        Step::new(
            "Positions",
            &format!(
                "The {th}×{tw} template is placed at every position where it fits inside the {}×{} search array: {} − {th} + 1 = {h} rows by {} − {tw} + 1 = {w} columns of positions, numbered 1 … {} row by row.",
                search.height(),
                search.width(),
                search.height(),
                search.width(),
                w * h
            ),
        )
        .formula(
            r"K_r = R - m + 1,\quad K_c = C - n + 1",
            format!(
                "K_r = {} - {th} + 1 = {h},\\quad K_c = {} - {tw} + 1 = {w}",
                search.height(),
                search.width()
            ),
        )
        .value("rows", h as f64)
        .value("cols", w as f64),
    );

    if let Some((bc, br)) = surface.best {
        if let (Some(bw), Some(win)) = (
            surface.windows.get(br * w + bc),
            search.window(bc, br, tw, th),
        ) {
            let wv = win.data();
            let step = Step::new(
                "The best window in full",
                &format!(
                    "The window at position {} (rows {}–{}, columns {}–{} of the search array), computed term by term; every other position is computed the same way (select one in the figure).",
                    br * w + bc + 1,
                    br + 1,
                    br + th,
                    bc + 1,
                    bc + tw
                ),
            )
            .formula(
                &format!(r"\bar B = \frac{{1}}{{mn}}\sum B_{{ij}},\quad {RHO_SYMBOLIC}"),
                format!(
                    r"{},\quad {}",
                    tex_mean(r"\sum B_{ij}", r"\bar B", wv, bw.mean_b),
                    tex_rho_chain(r"\rho", template.data(), wv, bw)
                ),
            )
            .value("position", (br * w + bc + 1) as f64)
            .value("window", Value::matrix(&win.rows()));
            s.step(ncc_values(step, bw));
        }
    }

    let rho_rows = surface.rho_rows();
    let grid_of = |f: &dyn Fn(&Ncc) -> f64| -> Value {
        Value::List(
            surface
                .windows
                .chunks(w.max(1))
                .map(|row| Value::numbers(&row.iter().map(f).collect::<Vec<_>>()))
                .collect(),
        )
    };
    let tex_rows: Vec<String> = rho_rows
        .iter()
        .take(MAX_TERMS)
        .map(|r| {
            let mut cells: Vec<String> = r.iter().take(MAX_TERMS).map(|x| rho_text(*x)).collect();
            if r.len() > MAX_TERMS {
                cells.push(r"\cdots".to_string());
            }
            cells.join(" & ")
        })
        .collect();
    let more_rows = if rho_rows.len() > MAX_TERMS {
        r" \\ \vdots"
    } else {
        ""
    };
    s.step(
        Step::new(
            "Correlation surface",
            "The correlation coefficient at every position, as a grid: row i, column j is the window whose top-left pixel is row i, column j of the search array.",
        )
        .formula(
            r"\rho_{ij}",
            format!(
                r"\rho = \begin{{bmatrix}} {}{more_rows} \end{{bmatrix}}",
                tex_rows.join(r" \\ ")
            ),
        )
        .value("rho", opt_rows(&rho_rows))
        .value("mean_b", grid_of(&|n: &Ncc| n.mean_b))
        .value("sum_dadb", grid_of(&|n: &Ncc| n.sum_dadb))
        .value("sum_db2", grid_of(&|n: &Ncc| n.sum_db2)),
    );

    let (hx, hy) = (half(tw), half(th));
    let best = surface.best.map(|(c, r)| {
        (
            (r * w + c + 1) as f64,
            c as f64 + 1.0 + hx,
            r as f64 + 1.0 + hy,
            (c + 1) as f64,
            (r + 1) as f64,
        )
    });
    match (best, surface.best.and_then(|(c, r)| surface.rho(c, r))) {
        (Some((pos, c, r, col, row)), Some(rho)) => s.step(
            Step::new(
                "Best position",
                &format!(
                    "The largest ρ is at position {} (row {}, column {} of the surface). That window's top-left pixel is column {}, row {} of the search array, so its centre pixel is c = {} + {}, r = {} + {}.",
                    num(pos),
                    num(row),
                    num(col),
                    num(col),
                    num(row),
                    num(col),
                    num(hx),
                    num(row),
                    num(hy)
                ),
            )
            .formula(
                r"\rho_{\max},\quad c = j + \tfrac{n-1}{2},\quad r = i + \tfrac{m-1}{2}",
                format!(
                    r"\rho_{{\max}} = {},\quad c = {} + {} = {},\quad r = {} + {} = {}",
                    num(rho),
                    num(col),
                    num(hx),
                    num(c),
                    num(row),
                    num(hy),
                    num(r)
                ),
            )
            .value("best_position", pos)
            .value("best_c", c)
            .value("best_r", r)
            .value("best_col", col)
            .value("best_row", row),
        ),
        _ => s.step(Step::new(
            "Best position",
            "No position has a correlation coefficient, so there is no best position.",
        )),
    }

    s.result = Record::new()
        .with("rho", opt_rows(&rho_rows))
        .with("best_position", opt(best.map(|b| b.0)))
        .with("best_c", opt(best.map(|b| b.1)))
        .with("best_r", opt(best.map(|b| b.2)))
        .with("best_col", opt(best.map(|b| b.3)))
        .with("best_row", opt(best.map(|b| b.4)));

    s.note(
        NoteKind::Convention,
        "Positions count from 1 row by row, as the course notes do (position 10 of a 4×4 surface is row 3, column 2); c is the column (to the right) and r the row (down) of the search array, also from 1.",
    ).about(&["best_position", "best_c", "best_r"]);
    if tw % 2 == 0 || th % 2 == 0 {
        s.note(
            NoteKind::Warning,
            "The template has an even number of columns or rows, so its centre lies between pixels: the centre c, r of the best window ends in .5.",
        ).about(&["best_c", "best_r"]);
    }
    {
        let template_flat = surface
            .windows
            .first()
            .is_some_and(|w| matches!(w.flat(), Flat::A | Flat::Both));
        if template_flat {
            s.note(
                NoteKind::Warning,
                "The template has no variance (all its values are equal): ρ is 0/0 at every position, so the surface has no values and there is no best position.",
            ).about(&["rho", "best_position"]);
        } else {
            let flat = surface.windows.iter().filter(|w| w.rho.is_none()).count();
            if flat > 0 {
                s.note(
                    NoteKind::Warning,
                    format!(
                        "{flat} window{} of the search array {} no variance (all values equal): ρ is 0/0 there and has no value.",
                        if flat > 1 { "s" } else { "" },
                        if flat > 1 { "have" } else { "has" }
                    ),
                ).about(&["rho"]);
            }
        }
    }
    if surface.ties > 1 {
        s.note(
            NoteKind::Warning,
            format!(
                "{} positions share the largest ρ; the first in row-by-row order is taken.",
                surface.ties
            ),
        )
        .about(&["best_position"]);
    }
    if is_seed(&ncc_surface_fields(), inputs) {
        seed_notes_7(&mut s, &rho_rows);
    }
    label_results(&mut s);
    Ok(s)
}

fn seed_notes_7(s: &mut Solution, rho_rows: &[Vec<Option<f64>>]) {
    s.textbook = Some(
        Record::new()
            .with("rho", Value::matrix(&rows_of(&EX7_PRINTED)))
            .with("best_position", 10.0)
            .with("best_c", 3.0)
            .with("best_r", 4.0),
    );
    let mut off = Vec::new();
    for (i, row) in EX7_PRINTED.iter().enumerate() {
        for (j, printed) in row.iter().enumerate() {
            let exact = rho_rows
                .get(i)
                .and_then(|r| r.get(j))
                .copied()
                .flatten()
                .unwrap_or(0.0);
            if (round_to(exact, 4) - printed).abs() > 1e-9 {
                off.push(format!(
                    "row {}, column {}: printed {}, exact {} (rounds to {})",
                    i + 1,
                    j + 1,
                    fmt_sig(*printed, 4),
                    fmt_sig(exact, 6),
                    fmt_sig(round_to(exact, 4), 4)
                ));
            }
        }
    }
    if off.is_empty() {
        s.note(
            NoteKind::Rounding,
            "All 16 printed coefficients are the exact ones rounded to four decimals.",
        )
        .about(&["rho"]);
    } else {
        s.note(
            NoteKind::Rounding,
            format!(
                "{} of the 16 printed coefficients agree with the exact ones rounded to four decimals; {} differ in the last digit, cut off rather than rounded: {}. The best position (10, centre c = 3, r = 4) is the same.",
                16 - off.len(),
                off.len(),
                off.join("; ")
            ),
        ).about(&["rho"]);
    }
}

// ---------------------------------------------------------------- Example 8

/// Example 5 computed exactly: positions (sub-window centres) and ρ of the
/// best sub-window and its two neighbours, and the best index.
fn example_5_exact() -> Result<([f64; 3], [f64; 3], usize)> {
    let profile = correlate_1d(&EX5_TEMPLATE, &EX5_SEARCH)?;
    let half = half(EX5_TEMPLATE.len());
    let best = profile.best.unwrap_or(0);
    let pick = |k: usize| profile.windows.get(k).and_then(|w| w.rho);
    match (best.checked_sub(1), pick(best), pick(best + 1)) {
        (Some(k0), Some(r1), Some(r2)) => match pick(k0) {
            Some(r0) => {
                let c = |k: usize| k as f64 + 1.0 + half;
                Ok(([c(k0), c(best), c(best + 1)], [r0, r1, r2], best))
            }
            None => Err(Error::input(
                "rho_from",
                "Example 5 has no exact ρ beside its best match",
            )),
        },
        _ => Err(Error::input(
            "rho_from",
            "Example 5's best match has no neighbour on both sides",
        )),
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

fn subpixel_1d(inputs: &Record) -> Result<Solution> {
    let exact_mode = text(inputs, "rho_from")? == "exact";
    let mut s = Solution::new("subpixel-1d", "Subpixel peak in 1-D", inputs.clone());
    let (x, y) = if exact_mode {
        let (x, y, best) = example_5_exact()?;
        s.step(
            Step::new(
                "ρ from Example 5, computed exactly",
                &format!(
                    "Example 5's template and search array give the best match at sub-window {} (centre c = {}); its neighbours are sub-windows {} and {}.",
                    best + 1,
                    num(x[1]),
                    best,
                    best + 2
                ),
            )
            .formula(
                r"(c_i, \rho_i)",
                format!(
                    r"({}, {}),\ ({}, {}),\ ({}, {})",
                    num(x[0]),
                    num(y[0]),
                    num(x[1]),
                    num(y[1]),
                    num(x[2]),
                    num(y[2])
                ),
            )
            .value("positions", Value::numbers(&x))
            .value("rho", Value::numbers(&y)),
        );
        let defaults = subpixel_1d_fields();
        let changed = ["positions", "rho"].iter().any(|k| {
            defaults
                .iter()
                .any(|f| f.key == *k && inputs.get(k) != Some(&f.default))
        });
        if changed {
            s.note(
                NoteKind::Warning,
                "With ρ taken from Example 5 computed exactly, the positions and ρ fields are not used.",
            ).about(&["positions", "rho"]);
        }
        (x, y)
    } else {
        (
            three("positions", &list(inputs, "positions")?)?,
            three("rho", &list(inputs, "rho")?)?,
        )
    };
    let p = parabola_peak(x, y)?;
    parabola_steps(&mut s, x, y, &p);
    let c_max = p.extremum.maximum().map(|a| a[0]);
    s.result = Record::new()
        .with("coefficients", Value::numbers(&p.coefficients))
        .with("c_max", opt(c_max))
        .with("extremum", extremum_name(&p.extremum))
        .with("rho_max", opt(peak_value(&p.extremum)))
        .with("positions", Value::numbers(&x))
        .with("rho", Value::numbers(&y));
    extremum_notes_1d(&mut s, &p, x);

    let printed = parabola_peak([7.0, 8.0, 9.0], [0.69, 0.97, 0.37])?;
    let printed_c = printed.extremum.maximum().map(|a| a[0]);
    if exact_mode {
        if let (Some(ce), Some(cp)) = (c_max, printed_c) {
            s.step(
                Step::new(
                    "How far the peak moves",
                    "The same parabola through the printed ρ (0.69, 0.97, 0.37) peaks elsewhere; the difference is what the printed ρ4 = 0.69 (exact 0.6731) and the rounding cost.",
                )
                .formula(
                    r"\Delta c = c_{\max}^{\text{exact}} - c_{\max}^{\text{printed}}",
                    format!(
                        r"\Delta c = {} - {} = {}\ \text{{px}}",
                        num(ce),
                        num(cp),
                        num(ce - cp)
                    ),
                )
                .value("c_max_printed_rho", cp)
                .value("peak_shift", ce - cp),
            );
            s.result.set("c_max_printed_rho", cp);
            s.result.set("peak_shift", ce - cp);
        }
        s.note(
            NoteKind::Convention,
            "ρ comes from Example 5's arrays computed exactly, not from the values the course notes print; the printed values shown beside are the course notes' answer from their printed ρ.",
        ).about(&["coefficients", "c_max"]);
    }
    let seed = is_seed(&subpixel_1d_fields(), inputs);
    if seed || exact_mode {
        s.textbook = Some(
            Record::new()
                .with("coefficients", Value::numbers(&[-25.91, 6.88, -0.44]))
                .with("c_max", 7.82),
        );
        let (pa, pc) = (printed.coefficients, printed_c.unwrap_or(0.0));
        s.note(
            NoteKind::Rounding,
            format!(
                "From the printed ρ the coefficients are exactly a0 = {}, a1 = {}, a2 = {} and c = {}, which the course notes print as −25.91, 6.88, −0.44 and 7.82.",
                num(pa[0]),
                num(pa[1]),
                num(pa[2]),
                num(pc)
            ),
        ).about(&["coefficients", "c_max"]);
        s.note(
            NoteKind::Erratum,
            "The course notes write the peak condition as 66.8 + (2)(−0.44)c = 0; a1 is 6.88 (66.8 would put the peak at c = 75.9). Their result c = 7.82 is right for 6.88.",
        ).about(&[]);
    }
    if seed {
        let (xe, ye, _) = example_5_exact()?;
        let e = parabola_peak(xe, ye)?;
        if let (Some(ce), Some(cp)) = (e.extremum.maximum(), printed_c) {
            s.note(
                NoteKind::Erratum,
                format!(
                    "These are the printed ρ of Example 5, including ρ4 = 0.69, whose exact value is {} (Example 5). With the exact ρ ({}, {}, {}) the peak is at c = {}, {} px from {}: choose “exact” to chain from Example 5.",
                    num(ye[0]),
                    num(ye[0]),
                    num(ye[1]),
                    num(ye[2]),
                    num(ce[0]),
                    fmt_sig(ce[0] - cp, 2),
                    num(cp)
                ),
            ).about(&["rho"]);
        }
    }
    label_results(&mut s);
    Ok(s)
}

fn peak_value(e: &Extremum) -> Option<f64> {
    match e {
        Extremum::Maximum { value, .. } => Some(*value),
        _ => None,
    }
}

fn parabola_steps(s: &mut Solution, x: [f64; 3], y: [f64; 3], p: &Parabola) {
    let a: Vec<Vec<f64>> = x.iter().map(|c| vec![1.0, *c, c * c]).collect();
    let eqs: Vec<String> = x
        .iter()
        .zip(&y)
        .map(|(c, r)| {
            format!(
                r"{} = a_0 + a_1 ({}) + a_2 ({})^2",
                num(*r),
                num(*c),
                num(*c)
            )
        })
        .collect();
    s.step(
        Step::new(
            "Three equations",
            "A 2nd-order polynomial ρ(c) = a0 + a1·c + a2·c² through the best ρ and its two neighbours: one equation per position, in matrix form A·X = L.",
        )
        .formula(
            r"\rho_i = a_0 + a_1 c_i + a_2 c_i^2,\quad A X = L",
            format!(
                r"\begin{{aligned}} {} \end{{aligned}}\quad {} \begin{{bmatrix}} a_0 \\ a_1 \\ a_2 \end{{bmatrix}} = {}",
                eqs.join(r" \\ "),
                tex_matrix(&a),
                tex_column(&y)
            ),
        )
        .value("A", Value::matrix(&a))
        .value("L", Value::numbers(&y)),
    );
    s.step(
        Step::new(
            "Coefficients",
            "Three equations, three unknowns: the parabola passes exactly through the three points. (Solved about the middle position with divided differences, which is the same as A⁻¹L but exact for any size of c.)",
        )
        .formula(
            r"X = A^{-1} L",
            format!(
                r"\begin{{bmatrix}} a_0 \\ a_1 \\ a_2 \end{{bmatrix}} = {}",
                tex_column(&p.coefficients)
            ),
        )
        .value("coefficients", Value::numbers(&p.coefficients)),
    );
    let [_, a1, a2] = p.coefficients;
    let (text, sub) = match p.extremum {
        Extremum::Maximum { at, value } => (
            "The slope of the parabola is zero at its maximum (a2 < 0, so it opens downward).".to_string(),
            format!(
                r"{} + 2 ({}) c = 0 \;\Rightarrow\; c = -\frac{{{}}}{{2 \times {}}} = {},\quad \rho_{{\max}} = {}",
                num(a1),
                num(a2),
                num(a1),
                tex(a2),
                num(at[0]),
                num(value)
            ),
        ),
        Extremum::Minimum { at, .. } => (
            "a2 > 0: the parabola opens upward, so its stationary point is a minimum, not a peak. There is no subpixel maximum.".to_string(),
            format!(
                r"a_2 = {} > 0,\quad c_{{\min}} = -\frac{{{}}}{{2 \times {}}} = {}",
                num(a2),
                num(a1),
                tex(a2),
                num(at[0])
            ),
        ),
        _ => (
            "a2 = 0: the three values lie on a straight line, which has no maximum.".to_string(),
            format!(r"a_2 = {} \approx 0", num(a2)),
        ),
    };
    let mut step = Step::new("Location of the maximum", &text)
        .formula(r"\frac{\partial \rho}{\partial c} = a_1 + 2 a_2 c = 0", sub)
        .value("extremum", extremum_name(&p.extremum));
    step = step.value("c_max", opt(p.extremum.maximum().map(|a| a[0])));
    s.step(step);
}

fn extremum_notes_1d(s: &mut Solution, p: &Parabola, x: [f64; 3]) {
    match p.extremum {
        Extremum::Maximum { at, .. } => {
            let lo = x.iter().fold(f64::INFINITY, |m, v| m.min(*v));
            let hi = x.iter().fold(f64::NEG_INFINITY, |m, v| m.max(*v));
            if at[0] < lo || at[0] > hi {
                s.note(
                    NoteKind::Warning,
                    format!(
                        "The maximum c = {} lies outside the three positions ({} … {}): it is extrapolated, and the middle value is not the largest; a correlation peak should be bracketed by its neighbours.",
                        num(at[0]),
                        num(lo),
                        num(hi)
                    ),
                ).about(&["c_max"]);
            }
        }
        Extremum::Minimum { .. } => s.note(
            NoteKind::Warning,
            "The fitted parabola opens upward (a2 > 0): its stationary point is a minimum, so there is no subpixel peak and no peak column.",
        ).about(&["c_max", "coefficients"]),
        _ => s.note(
            NoteKind::Warning,
            "The three values lie on a straight line (a2 = 0): the parabola has no maximum, so there is no peak column.",
        ).about(&["c_max", "coefficients"]),
    }
}

// ---------------------------------------------------------------- Example 9

/// Example 7 computed exactly: the columns, rows and 3×3 ρ around the best.
/// A 3×3 neighbourhood of ρ: its columns, rows and values.
type Neighbourhood = ([f64; 3], [f64; 3], [[f64; 3]; 3]);

fn example_7_exact() -> Result<(Neighbourhood, (usize, usize))> {
    let t = Grid::from_rows("template", &rows_of(&EX7_TEMPLATE))?;
    let sg = Grid::from_rows("search", &rows_of(&EX7_SEARCH))?;
    let surface = correlate_2d(&t, &sg)?;
    let Some((bc, br)) = surface.best else {
        return Err(Error::input("rho_from", "Example 7 has no best position"));
    };
    if bc == 0 || br == 0 || bc + 1 >= surface.width || br + 1 >= surface.height {
        return Err(Error::input(
            "rho_from",
            "Example 7's best position lies on the edge of the surface",
        ));
    }
    let mut rho = [[0.0; 3]; 3];
    for (i, row) in rho.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = surface.rho(bc + j - 1, br + i - 1).ok_or_else(|| {
                Error::input("rho_from", "Example 7 has a flat window beside its best")
            })?;
        }
    }
    let (hx, hy) = (half(t.width()), half(t.height()));
    let c = |k: usize| k as f64 + 1.0 + hx;
    let r = |k: usize| k as f64 + 1.0 + hy;
    Ok((
        (
            [c(bc - 1), c(bc), c(bc + 1)],
            [r(br - 1), r(br), r(br + 1)],
            rho,
        ),
        (bc, br),
    ))
}

const EX9_PRINTED_RHO: [[f64; 3]; 3] = [
    [-0.3334, 0.2394, -0.3921],
    [0.0585, 0.9665, 0.0806],
    [-0.2321, 0.2904, -0.1268],
];

fn subpixel_2d(inputs: &Record) -> Result<Solution> {
    let exact_mode = text(inputs, "rho_from")? == "exact";
    let mut s = Solution::new("subpixel-2d", "Subpixel peak in 2-D", inputs.clone());
    let (c, r, rho) = if exact_mode {
        let ((c, r, rho), (bc, br)) = example_7_exact()?;
        s.step(
            Step::new(
                "ρ from Example 7, computed exactly",
                &format!(
                    "Example 7's template and search array give the best position at surface row {}, column {} (centre pixel c = {}, r = {}); its 3×3 neighbourhood of exact coefficients:",
                    br + 1,
                    bc + 1,
                    num(c[1]),
                    num(r[1])
                ),
            )
            .formula(
                r"\rho(c, r)",
                tex_matrix(&rows_of(&rho)),
            )
            .value("c", Value::numbers(&c))
            .value("r", Value::numbers(&r))
            .value("rho", Value::matrix(&rows_of(&rho))),
        );
        let defaults = subpixel_2d_fields();
        let changed = ["c", "r", "rho"].iter().any(|k| {
            defaults
                .iter()
                .any(|f| f.key == *k && inputs.get(k) != Some(&f.default))
        });
        if changed {
            s.note(
                NoteKind::Warning,
                "With ρ taken from Example 7 computed exactly, the c, r and ρ fields are not used.",
            )
            .about(&["c", "r", "rho"]);
        }
        (c, r, rho)
    } else {
        let m = rows(inputs, "rho")?;
        let row = |i: usize| -> Result<[f64; 3]> {
            three("rho", m.get(i).map(Vec::as_slice).unwrap_or(&[]))
        };
        (
            three("c", &list(inputs, "c")?)?,
            three("r", &list(inputs, "r")?)?,
            [row(0)?, row(1)?, row(2)?],
        )
    };
    let q = quadric_peak(c, r, rho)?;
    quadric_steps(&mut s, c, r, &q);
    let at = q.extremum.maximum();
    s.result = Record::new()
        .with("coefficients", Value::numbers(&q.coefficients))
        .with("c_max", opt(at.map(|a| a[0])))
        .with("r_max", opt(at.map(|a| a[1])))
        .with("extremum", extremum_name(&q.extremum))
        .with("rho_max", opt(peak_value(&q.extremum)))
        .with("residuals", Value::numbers(&q.adjustment.v))
        .with("sigma0", opt(q.adjustment.sigma0))
        .with("c", Value::numbers(&c))
        .with("r", Value::numbers(&r))
        .with("rho", Value::matrix(&rows_of(&rho)));
    extremum_notes_2d(&mut s, &q, c, r);
    s.note(
        NoteKind::Convention,
        "The least-squares fit is computed in coordinates centred on the middle of the neighbourhood (u = c − c̄, v = r − r̄): the same surface as the course notes' nine equations in c and r, but a well-conditioned system for any c and r. The coefficients are then written in the course notes' form.",
    ).about(&[]);

    let printed = quadric_peak([2.0, 3.0, 4.0], [3.0, 4.0, 5.0], EX9_PRINTED_RHO)?;
    let printed_at = printed.extremum.maximum();
    if exact_mode {
        if let (Some(e), Some(p)) = (at, printed_at) {
            let d = ((e[0] - p[0]).powi(2) + (e[1] - p[1]).powi(2)).sqrt();
            s.step(
                Step::new(
                    "How far the peak moves",
                    "The same fit to the printed ρ (four decimals) peaks at a slightly different place; the difference is what rounding the coefficients of Example 7 costs.",
                )
                .formula(
                    r"\Delta = \sqrt{(c^{\text{exact}} - c^{\text{printed}})^2 + (r^{\text{exact}} - r^{\text{printed}})^2}",
                    format!(
                        r"\Delta c = {} - {} = {},\quad \Delta r = {} - {} = {},\quad \Delta = {}\ \text{{px}}",
                        num(e[0]),
                        num(p[0]),
                        fmt_sig(e[0] - p[0], 3),
                        num(e[1]),
                        num(p[1]),
                        fmt_sig(e[1] - p[1], 3),
                        fmt_sig(d, 3)
                    ),
                )
                .value("c_max_printed_rho", p[0])
                .value("r_max_printed_rho", p[1])
                .value("peak_shift", d),
            );
            s.result.set("c_max_printed_rho", p[0]);
            s.result.set("r_max_printed_rho", p[1]);
            s.result.set("peak_shift", d);
        }
        s.note(
            NoteKind::Convention,
            "ρ comes from Example 7's arrays computed exactly, not from the four-decimal values the course notes print; the printed values shown beside are the course notes' answer from their printed ρ.",
        ).about(&["coefficients", "c_max", "r_max"]);
    }
    let seed = is_seed(&subpixel_2d_fields(), inputs);
    if seed || exact_mode {
        let pc = [-12.297, 3.785, 3.634, 0.041, -0.656, -0.461];
        s.textbook = Some(
            Record::new()
                .with("coefficients", Value::numbers(&pc))
                .with("c_max", 3.012)
                .with("r_max", 4.075),
        );
        let from_rounded = stationary(&pc);
        let pa = printed.coefficients;
        s.note(
            NoteKind::Rounding,
            format!(
                "From the printed ρ the least-squares coefficients are a0 = {}, a1 = {}, a2 = {}, a3 = {}, a4 = {}, a5 = {}: the course notes' values to three decimals.",
                num(pa[0]),
                num(pa[1]),
                num(pa[2]),
                num(pa[3]),
                num(pa[4]),
                num(pa[5])
            ),
        ).about(&["coefficients"]);
        if let (Some((rc, rr)), Some(p)) = (from_rounded, printed_at) {
            s.note(
                NoteKind::Rounding,
                format!(
                    "The course notes' c = 3.012 and r = 4.075 come from their coefficients rounded to three decimals (they give c = {}, r = {}). From the unrounded coefficients the maximum is at c = {}, r = {}, which to three decimals is {}, {} (c: {}; r: {}): about {} px from the printed point, beyond its three decimals.",
                    fmt_sig(rc, 5),
                    fmt_sig(rr, 5),
                    num(p[0]),
                    num(p[1]),
                    format_args!("{:.3}", p[0]),
                    format_args!("{:.3}", p[1]),
                    exact_minus_printed(p[0], 3.012, "px"),
                    exact_minus_printed(p[1], 4.075, "px"),
                    fmt_sig(((p[0] - 3.012).powi(2) + (p[1] - 4.075).powi(2)).sqrt(), 1)
                ),
            ).about(&["c_max", "r_max"]);
        }
    }
    if seed {
        s.note(
            NoteKind::Erratum,
            "The course notes' third equation is labelled ρ(3+1, 4+1) and written with c = 4, r = 5, but its value −0.3921 is ρ at c = 4, r = 3, the upper right neighbour: it should read ρ(3+1, 4−1) = a0 + a1(4) + a2(3) + a3(4)(3) + a4(4)² + a5(3)². The ninth equation is the real ρ(3+1, 4+1) = −0.1268. The course notes' coefficients fit the corrected equation (see the coefficients above), so only the label and the written terms are wrong; this solution uses the corrected one.",
        ).about(&[]);
        let ((ce, re, rhoe), _) = example_7_exact()?;
        let e = quadric_peak(ce, re, rhoe)?;
        if let (Some(ea), Some(pa)) = (e.extremum.maximum(), printed_at) {
            let d = ((ea[0] - pa[0]).powi(2) + (ea[1] - pa[1]).powi(2)).sqrt();
            s.note(
                NoteKind::Convention,
                format!(
                    "These ρ are Example 7's values as printed to four decimals. With the exact coefficients of Example 7 the maximum is at c = {}, r = {}, {} px away: choose “exact” to chain from Example 7.",
                    num(ea[0]),
                    num(ea[1]),
                    fmt_sig(d, 2)
                ),
            ).about(&["rho"]);
        }
    }
    label_results(&mut s);
    Ok(s)
}

/// The stationary point of the seed-form coefficients (for checking the
/// printed answer), if the 2×2 system is regular.
fn stationary(a: &[f64; 6]) -> Option<(f64, f64)> {
    let det = 4.0 * a[4] * a[5] - a[3] * a[3];
    if det == 0.0 {
        return None;
    }
    let c = (-a[1] * 2.0 * a[5] + a[2] * a[3]) / det;
    let r = (-a[2] * 2.0 * a[4] + a[1] * a[3]) / det;
    Some((c, r))
}

fn quadric_steps(s: &mut Solution, c: [f64; 3], r: [f64; 3], q: &Quadric) {
    s.step(
        Step::new(
            "Nine equations",
            &format!(
                "The surface ρ = a0 + a1·c + a2·r + a3·c·r + a4·c² + a5·r² at the best position and its 8 neighbours (c = {}, {}, {}; r = {}, {}, {}): nine equations for six unknowns, one row of A per (c, r) in reading order (r = {} first), solved by least squares.",
                num(c[0]),
                num(c[1]),
                num(c[2]),
                num(r[0]),
                num(r[1]),
                num(r[2]),
                num(r[0])
            ),
        )
        .formula(
            r"\rho(c, r) = a_0 + a_1 c + a_2 r + a_3 c r + a_4 c^2 + a_5 r^2,\quad A X = L,\quad A_i = [1,\ c_i,\ r_i,\ c_i r_i,\ c_i^2,\ r_i^2]",
            format!(
                r"{} \begin{{bmatrix}} a_0 \\ a_1 \\ a_2 \\ a_3 \\ a_4 \\ a_5 \end{{bmatrix}} = {}",
                tex_matrix(&q.design),
                tex_column(&q.observations)
            ),
        )
        .value("A", Value::matrix(&q.design))
        .value("L", Value::numbers(&q.observations)),
    );
    let adj = &q.adjustment;
    let [cm, rm] = q.centre;
    s.step(
        Step::new(
            "Least squares",
            &format!(
                "In centred coordinates u = c − {}, v = r − {} the normal equations are simple; their solution b gives the same surface. Residuals V = A·X − L show how far the nine ρ are from the fitted surface.",
                num(cm),
                num(rm)
            ),
        )
        .formula(
            r"N = A^T A,\quad X = N^{-1} A^T L,\quad V = A X - L,\quad \sigma_0 = \sqrt{\frac{V^T V}{9 - 6}}",
            format!(
                r"N = {},\quad A^T L = {},\quad b = {},\quad V = {},\quad \sigma_0 = {}",
                tex_matrix(&adj.n),
                tex_column(&adj.atl),
                tex_column(&adj.x),
                tex_list(&adj.v),
                adj.sigma0.map_or_else(|| "-".to_string(), num)
            ),
        )
        .value("N", Value::matrix(&adj.n))
        .value("AtL", Value::numbers(&adj.atl))
        .value("local_coefficients", Value::numbers(&adj.x))
        .value("residuals", Value::numbers(&adj.v))
        .value("sigma0", opt(adj.sigma0))
        .value("centre", Value::numbers(&q.centre)),
    );
    let b = q.local;
    let a = q.coefficients;
    s.step(
        Step::new(
            "Coefficients in c and r",
            "Expanding u = c − c̄ and v = r − r̄ gives the coefficients of the course notes' form.",
        )
        .formula(
            r"a_1 = b_1 - b_3 \bar r - 2 b_4 \bar c,\ a_2 = b_2 - b_3 \bar c - 2 b_5 \bar r,\ a_3 = b_3,\ a_4 = b_4,\ a_5 = b_5,\ a_0 = \rho(0, 0)",
            format!(
                r"a_0 = {},\ a_1 = {},\ a_2 = {},\ a_3 = {},\ a_4 = {},\ a_5 = {}\quad (b_1 = {},\ b_2 = {})",
                num(a[0]),
                num(a[1]),
                num(a[2]),
                num(a[3]),
                num(a[4]),
                num(a[5]),
                num(b[1]),
                num(b[2])
            ),
        )
        .value("coefficients", Value::numbers(&a)),
    );
    let system = format!(
        r"\begin{{bmatrix}} 2 a_4 & a_3 \\ a_3 & 2 a_5 \end{{bmatrix}} = {},\quad \det = 4 a_4 a_5 - a_3^2 = {}",
        tex_matrix(&[vec![2.0 * a[4], a[3]], vec![a[3], 2.0 * a[5]]]),
        num(q.det)
    );
    let (text, sub) = match q.extremum {
        Extremum::Maximum { at, value } => (
            "Both slopes are zero at the maximum. The surface is concave (a4 < 0 and 4·a4·a5 − a3² > 0), so the stationary point is a true maximum.",
            format!(
                r"{system}:\ {} + {} r + 2({}) c = 0,\ {} + {} c + 2({}) r = 0 \;\Rightarrow\; c = {},\ r = {},\ \rho_{{\max}} = {}",
                num(a[1]),
                tex(a[3]),
                num(a[4]),
                num(a[2]),
                tex(a[3]),
                num(a[5]),
                num(at[0]),
                num(at[1]),
                num(value)
            ),
        ),
        Extremum::Minimum { at, .. } => (
            "The surface curves upward in every direction (a4 > 0 and 4·a4·a5 − a3² > 0): the stationary point is a minimum, so there is no subpixel maximum.",
            format!(r"{system},\ \text{{minimum at }} c = {},\ r = {}", num(at[0]), num(at[1])),
        ),
        Extremum::Saddle { at, .. } => (
            "4·a4·a5 − a3² < 0: the surface curves down one way and up the other; the stationary point is a saddle, not a maximum, so there is no subpixel peak.",
            format!(r"{system} < 0,\ \text{{saddle at }} c = {},\ r = {}", num(at[0]), num(at[1])),
        ),
        Extremum::Degenerate => (
            "4·a4·a5 − a3² = 0: the surface is flat in some direction (a ridge or a plane), so it has no single maximum.",
            system,
        ),
    };
    let at = q.extremum.maximum();
    s.step(
        Step::new("Location of the maximum", text)
            .formula(
                r"\frac{\partial \rho}{\partial c} = a_1 + a_3 r + 2 a_4 c = 0,\quad \frac{\partial \rho}{\partial r} = a_2 + a_3 c + 2 a_5 r = 0",
                sub,
            )
            .value("det", q.det)
            .value("extremum", extremum_name(&q.extremum))
            .value("c_max", opt(at.map(|a| a[0])))
            .value("r_max", opt(at.map(|a| a[1]))),
    );
}

fn extremum_notes_2d(s: &mut Solution, q: &Quadric, c: [f64; 3], r: [f64; 3]) {
    let span = |x: [f64; 3]| {
        (
            x.iter().fold(f64::INFINITY, |m, v| m.min(*v)),
            x.iter().fold(f64::NEG_INFINITY, |m, v| m.max(*v)),
        )
    };
    match q.extremum {
        Extremum::Maximum { at, .. } => {
            let ((c0, c1), (r0, r1)) = (span(c), span(r));
            if at[0] < c0 || at[0] > c1 || at[1] < r0 || at[1] > r1 {
                s.note(
                    NoteKind::Warning,
                    format!(
                        "The maximum (c, r) = ({}, {}) lies outside the 3×3 neighbourhood: it is extrapolated, and the centre value is probably not the largest.",
                        num(at[0]),
                        num(at[1])
                    ),
                ).about(&["c_max", "r_max"]);
            }
        }
        Extremum::Minimum { .. } => s.note(
            NoteKind::Warning,
            "The fitted surface is not concave: it curves upward, its stationary point is a minimum, so there is no subpixel peak (no peak column or row).",
        ).about(&["c_max", "r_max", "coefficients"]),
        Extremum::Saddle { .. } => s.note(
            NoteKind::Warning,
            "The fitted surface is not concave: 4·a4·a5 − a3² < 0 makes its stationary point a saddle, so there is no subpixel peak (no peak column or row).",
        ).about(&["c_max", "r_max", "coefficients"]),
        Extremum::Degenerate => s.note(
            NoteKind::Warning,
            "The fitted surface is not concave: 4·a4·a5 − a3² = 0 (flat in some direction), so it has no single maximum (no peak column or row).",
        ).about(&["c_max", "r_max", "coefficients"]),
    }
}
