//! Seed 000, Examples 10–11, and seed 003's affine + radiometric
//! generalisation: least-squares matching step by step — the first iteration
//! laid out as the seed does, then every iteration as a table, and how the
//! run ended.

use super::fields::{Field, Inputs, Kind};
use super::{Example, Lab, Topic};
use crate::error::{Error, Result};
use crate::matching::{
    self, Gradients, Iteration, Matching, Model, Param, Params, Settings, Status,
};
use crate::raster::Grid;
use crate::solution::{
    exact_minus_printed, fmt_sig, num, tex, NoteKind, Record, Solution, Step, Value,
};

mod lsm_1d;
mod lsm_2d;
mod lsm_affine;
use lsm_1d::*;
use lsm_2d::*;
use lsm_affine::*;

const TITLE: &str = "Least-squares matching";
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

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[
        Example {
            id: "lsm-1d",
            title: "1-D least-squares matching",
            source: "Worked examples, Example 10",
            summary: "Refines the best correlation position of Example 5 to a subpixel shift (and optionally a gain and offset) by iterated least squares.",
            fields: lsm_1d_fields,
            solve: lsm_1d,
            answer: &["c"],
            labels: &[],
            lab: None,
            practice: None,
        },
        Example {
            id: "lsm-2d",
            title: "2-D least-squares matching",
            source: "Worked examples, Example 11",
            summary: "Refines the best correlation position of Example 7 to a subpixel shift with a gain and offset by iterated least squares.",
            fields: lsm_2d_fields,
            solve: lsm_2d,
            answer: &["c", "r"],
            labels: &[],
            lab: Some(Lab { family: "correlation", explains: &[] }),
            practice: None,
        },
        Example {
            id: "lsm-affine",
            title: "Affine + radiometric least-squares matching",
            source: "Lecture 21: Image matching",
            summary: "A generated patch pair with a known shift, rotation, scale, shear, gain and offset, recovered by eight-parameter least-squares matching.",
            fields: lsm_affine_fields,
            solve: lsm_affine,
            answer: &["parameters", "sigma0"],
            labels: &[],
            lab: Some(Lab { family: "correlation", explains: &[] }),
            practice: None,
        },
];

/// The topic: its module (`web/matching/`) and title.
pub const TOPIC: Topic = Topic {
    module: "matching",
    title: TITLE,
    examples: EXAMPLES,
};

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
        flag("radiometric", "Estimate gain a and offset b", true)
            .help("Example 11 estimates the radiometric change G_t = a·G_s + b with the shift; off, a and b stay at their start values and only the shift is estimated."),
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

/// The two kinds of pair `lsm-affine` matches: one generated with a known
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

fn lsm_affine_fields() -> Vec<Field> {
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
        matrix("template", "Template T", &affine_template_default())
            .help("The template's grey values, rows top to bottom (at most 64 × 64).")
            .when("pair", PATCHES),
        matrix("search", "Search window S", &affine_search_default())
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

/// The `template` and `search` patches of the 2-D matching examples, as rows
/// and as grids, each at most `MAX_2D` a side.
struct Patches {
    tr: Vec<Vec<f64>>,
    sr: Vec<Vec<f64>>,
    template: Grid,
    search: Grid,
}

fn patches(inputs: &Record) -> Result<Patches> {
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
    Ok(Patches {
        template: Grid::from_rows("template", &tr)?,
        search: Grid::from_rows("search", &sr)?,
        tr,
        sr,
    })
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
