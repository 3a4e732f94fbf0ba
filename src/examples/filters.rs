//! Seed 000, Examples 15–16 and seed 004's kernels: a window filtered with
//! any kernel of the course (or a custom one, or the median), and the
//! Prewitt and Sobel edge operators with the gradient magnitude. The output
//! pixel the student selects is worked out as the seeds write it; the
//! seeds' printed values stand beside the exact ones, every slip explained.

use super::fields::{Field, Inputs, Kind};
use super::{Example, Lab, Topic};
use crate::error::{Error, Result};
use crate::filter::{self, Filtered, Gradient, Kernel, PixelSum};
use crate::raster::{Border, Grid};
use crate::solution::{num, tex, NoteKind, Record, Solution, Step, Value};

mod edge_window;
mod filter_window;
use edge_window::*;
use filter_window::*;

const TITLE: &str = "Filters and edges";

/// The largest custom kernel side (a kernel is applied at every pixel).
const MAX_KERNEL: usize = 15;
/// The largest window side, for selections.
const MAX_SIDE: f64 = super::fields::MAX_DIM as f64;

/// Example 15's window (seed 000).
pub const EXAMPLE_15: [[f64; 5]; 5] = [
    [10.0, 13.0, 3.0, 11.0, 13.0],
    [11.0, 15.0, 10.0, 9.0, 9.0],
    [9.0, 24.0, 7.0, 8.0, 10.0],
    [10.0, 13.0, 14.0, 15.0, 13.0],
    [13.0, 18.0, 17.0, 19.0, 21.0],
];

/// Example 16's window (seed 000).
pub const EXAMPLE_16: [[f64; 5]; 5] = [
    [1.0, 2.0, 1.0, 1.0, 1.0],
    [1.0, 1.0, 9.0, 2.0, 1.0],
    [1.0, 9.0, 9.0, 8.0, 1.0],
    [1.0, 1.0, 8.0, 1.0, 2.0],
    [2.0, 1.0, 1.0, 1.0, 1.0],
];

/// Seed 004's 5×5 image f(x, y) under the 3×3 mean.
pub const SEED_004: [[f64; 5]; 5] = [
    [5.0, 6.0, 7.0, 8.0, 9.0],
    [11.0, 10.0, 20.0, 30.0, 9.0],
    [31.0, 50.0, 60.0, 70.0, 9.0],
    [40.0, 30.0, 20.0, 10.0, 9.0],
    [58.0, 95.0, 105.0, 106.0, 98.0],
];

const KERNELS: &[(&str, &str)] = &[
    ("mean", "3×3 mean (1/9)"),
    ("weighted-mean", "3×3 weighted mean (1/10, centre 2)"),
    ("gaussian-3", "3×3 Gaussian (1/16)"),
    ("gaussian-5", "5×5 Gaussian (1/256)"),
    ("laplacian-4", "Laplacian, 4 neighbours (centre −4)"),
    ("laplacian-8", "Laplacian, 8 neighbours (centre −8)"),
    (
        "laplacian-004",
        "Lecture 7's Laplacian as printed (centre 1)",
    ),
    ("log", "Laplacian of Gaussian (5×5)"),
    ("sharpen", "Sharpening (Lecture 7, 1/9)"),
    ("high-pass", "High-pass (Lecture 7, 1/9)"),
    ("median", "3×3 median"),
    ("custom", "Custom kernel"),
];

const OPERATORS: &[(&str, &str)] = &[("prewitt", "Prewitt"), ("sobel", "Sobel")];

const BORDERS: &[(&str, &str)] = &[
    (
        "crop",
        "Crop: only where the kernel fits (as the course documents do)",
    ),
    ("replicate", "Replicate the edge pixel"),
    ("reflect", "Reflect about the edge pixel"),
    ("zero", "Zero outside"),
];

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[
        Example {
            id: "filter-window",
            title: "Filtering a window",
            source: "Worked examples, Examples 15–16; Lecture 7: Image processing",
            summary: "A window of grey values under a smoothing, sharpening or Laplacian kernel (or the median), each output pixel's sum written out.",
            fields: filter_fields,
            solve: filter_window,
            answer: &["selected", "output"],
            labels: &[],
            lab: Some(Lab { family: "filters", explains: &[] }),
            practice: None,
        },
        Example {
            id: "edge-window",
            title: "Prewitt and Sobel edges",
            source: "Worked examples, Example 15",
            summary: "The responses to the Prewitt or Sobel kernels in both directions and the edge magnitude √(Gx² + Gy²).",
            fields: edge_fields,
            solve: edge_window,
            answer: &["selected_gx", "selected_gy", "selected_magnitude"],
            labels: &[],
            lab: Some(Lab { family: "edges", explains: &[] }),
            practice: None,
        },
];

/// The topic: its module (`web/filters/`) and title.
pub const TOPIC: Topic = Topic {
    module: "filters",
    title: TITLE,
    examples: EXAMPLES,
};

// ---------------------------------------------------------------------------
// Field builders and input readers shared with the resampling examples (kept
// here, not in fields.rs, so that the shared file stays untouched).

/// A matrix field of any size up to `MAX_DIM` × `MAX_DIM`.
pub(super) fn matrix_field(key: &'static str, label: &'static str, default: &[Vec<f64>]) -> Field {
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

/// A choice field; `options` are `(value, label)` pairs.
pub(super) fn choice_field(
    key: &'static str,
    label: &'static str,
    options: &'static [(&'static str, &'static str)],
    default: &'static str,
) -> Field {
    Field {
        key,
        label,
        help: "",
        kind: Kind::Choice { options },
        default: Value::from(default),
        when: None,
    }
}

/// The text of a validated choice field.
pub(super) fn text<'a>(inputs: &'a Record, key: &str) -> Result<&'a str> {
    match inputs.get(key) {
        Some(Value::Text(t)) => Ok(t),
        _ => Err(Error::Internal(format!(
            "validated input \"{key}\" is not a string"
        ))),
    }
}

/// The rows of a validated matrix field.
pub(super) fn rows(inputs: &Record, key: &str) -> Result<Vec<Vec<f64>>> {
    let bad = || Error::Internal(format!("validated input \"{key}\" is not a matrix"));
    match inputs.get(key) {
        Some(Value::List(rows)) => rows
            .iter()
            .map(|r| match r {
                Value::List(xs) => xs.iter().map(|x| x.as_f64().ok_or_else(bad)).collect(),
                _ => Err(bad()),
            })
            .collect(),
        _ => Err(bad()),
    }
}

/// A matrix in LaTeX.
pub(super) fn bmatrix(rows: &[Vec<f64>]) -> String {
    let body = rows
        .iter()
        .map(|r| r.iter().map(|x| num(*x)).collect::<Vec<_>>().join(" & "))
        .collect::<Vec<_>>()
        .join(r" \\ ");
    format!(r"\begin{{bmatrix}} {body} \end{{bmatrix}}")
}

fn to_rows<const N: usize>(m: &[[f64; N]]) -> Vec<Vec<f64>> {
    m.iter().map(|r| r.to_vec()).collect()
}

// ---------------------------------------------------------------------------
// Fields

fn window_field() -> Field {
    matrix_field("window", "Window of grey values", &to_rows(&EXAMPLE_15)).help(
        "Rows of grey values. Example 15: the default. Example 16: 1 2 1 1 1; 1 1 9 2 1; 1 9 9 8 1; 1 1 8 1 2; 2 1 1 1 1. Lecture 7: 5 6 7 8 9; 11 10 20 30 9; 31 50 60 70 9; 40 30 20 10 9; 58 95 105 106 98.",
    )
}

fn select_fields() -> [Field; 2] {
    [
        Field::integer("select_c", "Selected pixel: column", 2.0)
            .range(1.0, MAX_SIDE)
            .help("Column of the output pixel whose sum is written out, counted from 1 at the left of the window."),
        Field::integer("select_r", "Selected pixel: row", 2.0)
            .range(1.0, MAX_SIDE)
            .help("Row of the output pixel whose sum is written out, counted from 1 at the top of the window."),
    ]
}

fn border_field() -> Field {
    choice_field("border", "At the window's edge", BORDERS, "crop").help(
        "Crop keeps only the pixels where the whole kernel lies inside the window, as the course documents do; the other policies give an output for every pixel by inventing values outside.",
    )
}

fn filter_fields() -> Vec<Field> {
    let [sc, sr] = select_fields();
    vec![
        window_field(),
        choice_field("kernel", "Kernel", KERNELS, "mean")
            .help("Example 15 uses the mean and the Gaussian, Example 16 the 8-neighbour Laplacian, Lecture 7 the mean."),
        matrix_field(
            "custom_kernel",
            "Custom kernel (numerators)",
            &[vec![0.0, -1.0, 0.0], vec![-1.0, 5.0, -1.0], vec![0.0, -1.0, 0.0]],
        )
        .help("Used when the kernel is Custom: an odd number of rows and of columns, at most 15×15; applied as written (no flip).")
        .when("kernel", &["custom"]),
        Field::number("custom_divisor", "Custom kernel divisor", 1.0)
            .positive(1e12)
            .help("The custom kernel's numerators are divided by this (16 for a 1/16 kernel).")
            .when("kernel", &["custom"]),
        sc,
        sr,
        border_field(),
    ]
}

fn edge_fields() -> Vec<Field> {
    let [sc, sr] = select_fields();
    vec![
        window_field(),
        choice_field("operator", "Edge operator", OPERATORS, "prewitt"),
        sc,
        sr,
        border_field(),
    ]
}

// ---------------------------------------------------------------------------
// Shared pieces

fn border_of(name: &str) -> Result<Border> {
    match name {
        "crop" => Ok(Border::Crop),
        "replicate" => Ok(Border::Replicate),
        "reflect" => Ok(Border::Reflect),
        "zero" => Ok(Border::Zero),
        other => Err(Error::Internal(format!("unknown border \"{other}\""))),
    }
}

/// The named kernel (`None` for the median).
fn named_kernel(name: &str, inputs: &Record) -> Result<Option<Kernel>> {
    if let Some(k) = filter::by_name(name) {
        return Ok(k);
    }
    Ok(Some(match name {
        "custom" => {
            let k = rows(inputs, "custom_kernel")?;
            let (h, w) = (k.len(), k.first().map_or(0, Vec::len));
            if h > MAX_KERNEL || w > MAX_KERNEL {
                return Err(Error::input(
                    "custom_kernel",
                    format!("is {h}×{w}; at most {MAX_KERNEL}×{MAX_KERNEL} is allowed"),
                ));
            }
            Kernel::new(
                "custom_kernel",
                &k,
                Inputs(inputs).number("custom_divisor")?,
            )?
        }
        other => return Err(Error::Internal(format!("unknown kernel \"{other}\""))),
    }))
}

/// The window as a grid, and the selected pixel (zero-based), checked.
fn window_and_selection(inputs: &Record) -> Result<(Grid, usize, usize)> {
    let window = Grid::from_rows("window", &rows(inputs, "window")?)?;
    let i = Inputs(inputs);
    let (sc, sr) = (i.number("select_c")?, i.number("select_r")?);
    if sc > window.width() as f64 {
        return Err(Error::input(
            "select_c",
            format!(
                "column {sc} is outside the window (it has {} columns)",
                window.width()
            ),
        ));
    }
    if sr > window.height() as f64 {
        return Err(Error::input(
            "select_r",
            format!(
                "row {sr} is outside the window (it has {} rows)",
                window.height()
            ),
        ));
    }
    // select_c, select_r are whole numbers ≥ 1 (checked by their fields)
    Ok((window, sc as usize - 1, sr as usize - 1))
}

/// The error for a window too small for a neighbourhood under `Crop`.
fn too_small(window: &Grid, kw: usize, kh: usize) -> Error {
    Error::input(
        "window",
        format!(
            "is {}×{} (rows × columns); the {kh}×{kw} kernel fits nowhere inside it — give a larger window or a border policy other than crop",
            window.height(),
            window.width()
        ),
    )
}

/// `(r_2, c_3)`: a pixel as the seed names it (1-based).
fn pixel_name(c: usize, r: usize) -> String {
    format!("(r_{{{}}}, c_{{{}}})", r + 1, c + 1)
}

/// `2 \times 13`, `- 9`, `+ (-3)`: one term of a written-out sum.
fn term(n: f64, f: f64, first: bool) -> Option<String> {
    if n == 0.0 {
        return None;
    }
    let sign = match (n < 0.0, first) {
        (true, true) => "-",
        (true, false) => " - ",
        (false, true) => "",
        (false, false) => " + ",
    };
    let a = n.abs();
    let body = if a == 1.0 {
        tex(f)
    } else {
        format!(r"{} \times {}", num(a), tex(f))
    };
    Some(format!("{sign}{body}"))
}

/// The sum `Σ n·f` written out as the seed writes it.
/// The sum `Σ n·f` written out as the seed writes it, one line per kernel
/// row (rows of zero weights left out).
fn written_lines(ps: &PixelSum) -> Vec<String> {
    let mut lines = Vec::new();
    let w = ps.width.max(1);
    for (nums, vals) in ps.numerators.chunks(w).zip(ps.values.chunks(w)) {
        let mut line = String::new();
        for (n, f) in nums.iter().zip(vals) {
            if let Some(t) = term(*n, *f, lines.is_empty() && line.is_empty()) {
                line.push_str(&t);
            }
        }
        if !line.is_empty() {
            lines.push(line);
        }
    }
    if lines.is_empty() {
        lines.push("0".to_string());
    }
    lines
}

/// The selected pixel's sum, aligned one kernel row per line:
/// `g(r_2, c_2) = 1/9 (10 + 13 + 3 ⏎ + 11 + 15 + 10 ⏎ + 9 + 24 + 7) = 102/9 = 11.33333`.
fn written_sum(name: &str, ps: &PixelSum) -> String {
    let lines = written_lines(ps);
    let last = lines.len().saturating_sub(1);
    let scaled = ps.divisor != 1.0;
    let d = num(ps.divisor);
    let mut body = String::new();
    for (i, l) in lines.iter().enumerate() {
        let open = if i == 0 && scaled {
            format!(r"\tfrac{{1}}{{{d}}}\big(")
        } else {
            String::new()
        };
        let close = if i == last && scaled { r"\big)" } else { "" };
        let lead = if i == 0 { "&= " } else { r"&\qquad " };
        body.push_str(&format!(r"{lead}{open}{l}{close} \\ "));
    }
    let total = if scaled {
        format!(
            r"&= \frac{{{}}}{{{d}}} = {}",
            num(ps.numerator_sum),
            num(ps.value)
        )
    } else {
        format!("&= {}", num(ps.value))
    };
    format!(
        r"\begin{{aligned}} {name}{} {body}{total} \end{{aligned}}",
        pixel_name(ps.c, ps.r)
    )
}

/// The kernel in LaTeX: `\frac{1}{16}\begin{bmatrix}…\end{bmatrix}`.
fn kernel_tex(k: &Kernel) -> String {
    let m = bmatrix(&k.numerators().rows());
    if k.divisor() == 1.0 {
        m
    } else {
        format!(r"\frac{{1}}{{{}}}{m}", num(k.divisor()))
    }
}

fn matrix_step(title: &str, text: &str, symbol: &str, key: &str, g: &Grid) -> Step {
    Step::new(title, text)
        .formula(
            &format!("{symbol} = [\\,{symbol}(r, c)\\,]"),
            format!("{symbol} = {}", bmatrix(&g.rows())),
        )
        .value(key, Value::matrix(&g.rows()))
}

/// Notes for a kernel whose sum is not what its kind needs.
fn kernel_sum_notes(s: &mut Solution, name: &str, k: &Kernel) {
    let sum = k.sum();
    let expected = match name {
        "mean" | "weighted-mean" | "gaussian-3" | "gaussian-5" | "sharpen" => Some(1.0),
        "laplacian-4" | "laplacian-8" | "laplacian-004" | "log" | "high-pass" => Some(0.0),
        _ => None,
    };
    match expected {
        Some(e) if (sum - e).abs() > 1e-12 => s.note(
            NoteKind::Erratum,
            format!(
                "Lecture 7 prints its Laplacian as [−1 −1 −1; −1 1 −1; −1 −1 −1]. Its weights sum to {}, not 0, so a flat area of grey value g comes out as {}·g instead of 0 and the filter is no edge detector. The centre must be 8: [−1 −1 −1; −1 8 −1; −1 −1 −1] sums to 0 and is the worked examples' 8-neighbour Laplacian with the sign turned (the same page's high-pass kernel is it divided by 9).",
                num(sum),
                num(sum)
            ),
        ).about(&["kernel", "kernel_sum"]),
        Some(1.0) => s.note(
            NoteKind::Convention,
            "The kernel's weights sum to 1, as a smoothing (or sharpening) kernel's must: a flat area keeps its grey value.",
        ).about(&["kernel_sum"]),
        Some(_) => s.note(
            NoteKind::Convention,
            "The kernel's weights sum to 0, as a derivative kernel's must: a flat area gives 0.",
        ).about(&["kernel_sum"]),
        None => {
            if (sum - 1.0).abs() > 1e-12 && sum.abs() > 1e-12 {
                s.note(
                    NoteKind::Warning,
                    format!(
                        "The custom kernel's weights sum to {}: a flat area of grey value g comes out as {}·g. A smoothing kernel sums to 1 (grey values kept), a derivative kernel to 0.",
                        num(sum),
                        num(sum)
                    ),
                ).about(&["kernel_sum"]);
            } else {
                s.note(
                    NoteKind::Convention,
                    format!(
                        "The custom kernel's weights sum to {}: {}",
                        num(sum),
                        if sum.abs() <= 1e-12 {
                            "a flat area gives 0, as for a derivative kernel."
                        } else {
                            "a flat area keeps its grey value, as under a smoothing kernel."
                        }
                    ),
                ).about(&["kernel_sum"]);
            }
        }
    }
}

fn correlation_note(s: &mut Solution) {
    s.note(
        NoteKind::Convention,
        "Kernels are applied as written: the kernel's top-left weight multiplies the window's top-left pixel (correlation). The course documents say \"convolve\" but their sums do exactly this; a true convolution would first turn the kernel by 180°, which changes nothing for symmetric kernels and only the sign of the Prewitt and Sobel responses.",
    );
}

fn crop_note(s: &mut Solution, border: Border, region: filter::Region, window: &Grid) {
    if border == Border::Crop {
        s.note(
            NoteKind::Convention,
            format!(
                "Output only where the whole kernel lies inside the window, as the course documents do: the {}×{} interior of the {}×{} window, from row {} column {} on.",
                region.height,
                region.width,
                window.height(),
                window.width(),
                region.r0 + 1,
                region.c0 + 1
            ),
        ).about(&["output_first_c", "output_first_r"]);
    } else {
        let how = match border {
            Border::Replicate => "repeating the nearest edge pixel",
            Border::Reflect => "mirroring the window about its edge pixels",
            _ => "taking 0 outside the window",
        };
        s.note(
            NoteKind::Convention,
            format!("Output for every pixel of the window; values outside it are made up by {how}. The course documents keep only the interior."),
        ).about(&["output_first_c", "output_first_r"]);
    }
}

fn selection_note(s: &mut Solution, c: usize, r: usize, kw: usize, kh: usize) {
    s.note(
        NoteKind::Warning,
        format!(
            "The selected pixel (row {}, column {}) has no output: the {kh}×{kw} kernel centred on it reaches outside the window. Select a pixel of the interior, or choose a border policy other than crop.",
            r + 1,
            c + 1
        ),
    );
}

fn same_window<const N: usize>(window: &Grid, m: &[[f64; N]]) -> bool {
    window.rows() == to_rows(m)
}

/// Printed value at input pixel `(c, r)` of a printed interior grid.
fn printed_at(printed: &[Vec<f64>], region: filter::Region, c: usize, r: usize) -> Option<f64> {
    if !region.contains(c, r) {
        return None;
    }
    printed
        .get(r - region.r0)
        .and_then(|row| row.get(c - region.c0))
        .copied()
}
