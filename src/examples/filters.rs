//! Seed 000, Examples 15–16 and seed 004's kernels: a window filtered with
//! any kernel of the course (or a custom one, or the median), and the
//! Prewitt and Sobel edge operators with the gradient magnitude. The output
//! pixel the student selects is worked out as the seeds write it; the
//! seeds' printed values stand beside the exact ones, every slip explained.
//! Each example is one file beside this one; this file keeps what they
//! share: the window, selection and border fields, the written-out sum,
//! the notes and the practice windows.

mod edge_window;
mod filter_window;

use super::drill::Rng;
use super::fields::{to_rows, Field, Inputs};
use super::{Example, Topic};
use crate::error::{Error, Result};
use crate::filter::{self, Kernel, PixelSum};
use crate::raster::{Border, Grid};
use crate::solution::{num, tex, Form, NoteKind, Record, Relation, Solution, Step, Value};

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

const BORDERS: &[(&str, &str)] = &[
    (
        "crop",
        "Crop: only where the kernel fits (as the course documents do)",
    ),
    ("replicate", "Replicate the edge pixel"),
    ("reflect", "Reflect about the edge pixel"),
    ("zero", "Zero outside"),
];

/// What the result keys of the two examples mean.
const LABELS: &[(&str, &str, &str)] = &[
    ("output", "Filtered window", ""),
    ("selected", "Output at the selected pixel", ""),
    ("kernel", "Kernel weights", ""),
    ("kernel_sum", "Sum of the kernel weights", ""),
    ("gx", "Gx: top row minus bottom row", ""),
    ("gy", "Gy: right column minus left column", ""),
    ("magnitude", "Edge magnitude √(Gx² + Gy²)", ""),
    ("selected_gx", "Gx at the selected pixel", ""),
    ("selected_gy", "Gy at the selected pixel", ""),
    (
        "selected_magnitude",
        "Edge magnitude at the selected pixel",
        "",
    ),
    ("output_first_c", "Column of the output's first pixel", ""),
    ("output_first_r", "Row of the output's first pixel", ""),
];

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[filter_window::EXAMPLE, edge_window::EXAMPLE];

/// The topic: its module (`web/filters/`) and title.
pub const TOPIC: Topic = Topic {
    module: "filters",
    title: TITLE,
    examples: EXAMPLES,
};

// ---------------------------------------------------------------------------
// Fields

fn window_field() -> Field {
    Field::matrix("window", "Window of grey values", &to_rows(&EXAMPLE_15)).help(
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
    Field::choice("border", "At the window's edge", BORDERS, "crop").help(
        "Crop keeps only the pixels where the whole kernel lies inside the window, as the course documents do; the other policies give an output for every pixel by inventing values outside.",
    )
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

/// The window as a grid, and the selected pixel (zero-based), checked.
fn window_and_selection(inputs: &Record) -> Result<(Grid, usize, usize)> {
    let i = Inputs(inputs);
    let window = Grid::from_rows("window", &i.rows("window")?)?;
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

/// The sum `Σ n·f` written out as the seed writes it, one piece per
/// kernel row (rows of zero weights left out), so that the page breaks
/// lines where the kernel's rows end.
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
            lines.push(line.trim_start().to_string());
        }
    }
    if lines.is_empty() {
        lines.push("0".to_string());
    }
    lines
}

/// The selected pixel's sum as the seeds write it, `name(r_2, c_2) =
/// 1/9 (10 + 13 + 3 ⏎ + 11 + 15 + 10 ⏎ + 9 + 24 + 7) = 102/9 = 11.33333`,
/// after the general formula `symbolic` (whose left-hand side is
/// `name(r, c)`); `key` is the value it computes.
fn written_sum(name: &str, symbolic: &str, key: &str, ps: &PixelSum) -> [Relation; 2] {
    let lines = written_lines(ps);
    let last = lines.len() - 1;
    let scaled = ps.divisor != 1.0;
    let d = num(ps.divisor);
    let pieces = lines.iter().enumerate().map(|(i, l)| {
        let open = if i == 0 && scaled {
            format!(r"\tfrac{{1}}{{{d}}}\big(")
        } else {
            String::new()
        };
        let close = if i == last && scaled { r"\big)" } else { "" };
        format!("{open}{l}{close}")
    });
    let mut numbers = Relation::new(format!("{name}{}", pixel_name(ps.c, ps.r)))
        .key(key)
        .subst(Form::terms(pieces));
    if scaled {
        numbers = numbers.result(format!(r"\frac{{{}}}{{{d}}}", num(ps.numerator_sum)));
    }
    [
        Relation::new(format!("{name}(r, c)")).sym(symbolic),
        numbers.value(ps.value, ""),
    ]
}

/// The kernel as a formula: `\frac{1}{16}` and its numerators as a grid
/// named `name`.
fn kernel_form(k: &Kernel, name: &str) -> Form {
    let m = Form::grid("bmatrix", &k.numerators().rows(), name);
    if k.divisor() == 1.0 {
        m
    } else {
        Form::from(format!(r"\frac{{1}}{{{}}}", num(k.divisor()))).then(m)
    }
}

/// A whole output grid: `symbol = [ symbol(r, c) ]` and its values, the
/// grid named `name` for the page's captions.
fn matrix_step(title: &str, text: &str, (symbol, name): (&str, &str), key: &str, g: &Grid) -> Step {
    Step::new(title, text)
        .relation(
            Relation::new(symbol)
                .key(key)
                .sym(format!("[\\,{symbol}(r, c)\\,]"))
                .result(Form::grid("bmatrix", &g.rows(), name)),
        )
        .value(key, Value::matrix(&g.rows()))
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

// ---------------------------------------------------------------------------
// Practice: the windows both drills draw.

/// A 5×5 window of grey values (about 10–60, 0–75 with a steep slope) with
/// an edge and some texture: no 3×3 neighbourhood is flat.
fn practice_window(rng: &mut Rng) -> Vec<Vec<f64>> {
    let (gc, gr) = (rng.num(-6, 6), rng.num(-6, 6));
    let (gc, gr) = (
        if gc == 0.0 { 4.0 } else { gc },
        if gr == 0.0 { -3.0 } else { gr },
    );
    let noise: Vec<Vec<f64>> = (0..5)
        .map(|_| (0..5).map(|_| rng.num(-4, 4)).collect())
        .collect();
    let ramp = |gc: f64| -> Vec<Vec<f64>> {
        (0..5)
            .map(|r| {
                (0..5)
                    .map(|c| {
                        (35.0 + gc * (c as f64 - 2.0) + gr * (r as f64 - 2.0) + noise[r][c])
                            .clamp(0.0, 99.0)
                    })
                    .collect()
            })
            .collect()
    };
    let w = ramp(gc);
    // Now and then the noise cancels a gentle slope and leaves a 3×3
    // neighbourhood flat (about one window in 10 000). Such a window gets a
    // steeper slope: |gc| ≥ 6 spans 12 grey levels over three columns, which
    // noise of ± 4 cannot bring below 4.
    if flat_neighbourhood(&w) {
        ramp(gc + 5.0 * gc.signum())
    } else {
        w
    }
}

/// Whether some interior pixel's 3×3 neighbourhood spans less than 3 grey levels.
fn flat_neighbourhood(w: &[Vec<f64>]) -> bool {
    (1..w.len().saturating_sub(1)).any(|r| {
        (1..w[r].len().saturating_sub(1)).any(|c| {
            let n = || (r - 1..=r + 1).flat_map(|y| w[y][c - 1..=c + 1].iter().copied());
            n().fold(f64::MIN, f64::max) - n().fold(f64::MAX, f64::min) < 3.0
        })
    })
}
