//! Seed 000, Examples 15–16 and seed 004's kernels: a window filtered with
//! any kernel of the course (or a custom one, or the median), and the
//! Prewitt and Sobel edge operators with the gradient magnitude. The output
//! pixel the student selects is worked out as the seeds write it; the
//! seeds' printed values stand beside the exact ones, every slip explained.

use super::fields::{Field, Inputs, Kind};
use super::Entry;
use crate::error::{Error, Result};
use crate::filter::{self, Filtered, Gradient, Kernel, PixelSum};
use crate::raster::{Border, Grid};
use crate::solution::{num, tex, NoteKind, Record, Solution, Step, Value};

const TOPIC: &str = "Filters and edges";

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

pub fn entries() -> Vec<Entry> {
    vec![
        Entry {
            id: "filter-window",
            title: "Filtering a window",
            topic: TOPIC,
            source: "Worked examples, Examples 15–16; Lecture 7: Image processing",
            summary: "A window of grey values under a smoothing, sharpening or Laplacian kernel (or the median), each output pixel's sum written out.",
            fields: filter_fields,
            solve: Some(filter_window),
        },
        Entry {
            id: "edge-window",
            title: "Prewitt and Sobel edges",
            topic: TOPIC,
            source: "Worked examples, Example 15",
            summary: "The responses to the Prewitt or Sobel kernels in both directions and the edge magnitude √(Gx² + Gy²).",
            fields: edge_fields,
            solve: Some(edge_window),
        },
    ]
}

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

// ---------------------------------------------------------------------------
// filter-window

fn filter_window(inputs: &Record) -> Result<Solution> {
    let (window, sc, sr) = window_and_selection(inputs)?;
    let name = text(inputs, "kernel")?;
    let border = border_of(text(inputs, "border")?)?;
    let kernel = named_kernel(name, inputs)?;
    let (kw, kh) = kernel.as_ref().map_or((3, 3), |k| (k.width(), k.height()));
    if filter::output_region(window.width(), window.height(), kw / 2, kh / 2, border).is_none() {
        return Err(too_small(&window, kw, kh));
    }
    let mut s = Solution::new("filter-window", "Filtering a window", inputs.clone());
    let label = KERNELS
        .iter()
        .find(|(k, _)| *k == name)
        .map_or(name, |(_, l)| *l);

    let (filtered, selected): (Filtered, Option<f64>) = match &kernel {
        Some(k) => {
            s.step(
                Step::new(
                    "The kernel",
                    &format!(
                        "{label}: its weights are the numerators divided by {}; they sum to {}.",
                        num(k.divisor()),
                        num(k.sum())
                    ),
                )
                .formula(
                    r"w(i, j) = \frac{n(i, j)}{d}",
                    format!("w = {}", kernel_tex(k)),
                )
                .value("numerators", Value::matrix(&k.numerators().rows()))
                .value("divisor", k.divisor())
                .value("weights", Value::matrix(&k.weights().rows()))
                .value("kernel_sum", k.sum()),
            );
            let filtered = filter::correlate(&window, k, border)?;
            let ps = filter::pixel_sum(&window, k, sc, sr, border);
            match &ps {
                Some(ps) => s.step(
                    Step::new(
                        "The selected pixel, written out",
                        &format!(
                            "Put the kernel's centre on the pixel in row {}, column {} (grey value {}), multiply each weight with the grey value under it and add.",
                            sr + 1,
                            sc + 1,
                            num(window.get(sc, sr).unwrap_or(0.0))
                        ),
                    )
                    .formula(
                        r"g(r, c) = \frac{1}{d}\sum_{j}\sum_{i} n(i, j)\, f(r + j, c + i)",
                        written_sum("g", ps),
                    )
                    .value("select_c", sc + 1)
                    .value("select_r", sr + 1)
                    .value("neighbourhood", Value::numbers(&ps.values))
                    .value("numerator_sum", ps.numerator_sum)
                    .value("selected", ps.value),
                ),
                None => selection_note(&mut s, sc, sr, kw, kh),
            }
            (filtered, ps.map(|p| p.value))
        }
        None => {
            let filtered = filter::median(&window, 3, 3, border)?;
            let nb = filter::neighbourhood(&window, sc, sr, 3, 3, border);
            s.step(
                Step::new(
                    "The median",
                    "No weights: the output is the middle value of the nine grey values under the 3×3 window, sorted (Lecture 7: \"selecting median instead of mean\"). Unlike the mean it is always a grey value of the data.",
                )
                .formula(r"g(r, c) = \operatorname{median}\{ f(r + j, c + i) : |i|, |j| \le 1 \}", String::new()),
            );
            let value = match &nb {
                Some(values) => {
                    let mut sorted = values.clone();
                    sorted.sort_by(f64::total_cmp);
                    let m = filter::median_of(values);
                    let list = |v: &[f64]| v.iter().map(|x| num(*x)).collect::<Vec<_>>().join(", ");
                    s.step(
                        Step::new(
                            "The selected pixel, written out",
                            &format!(
                                "The nine grey values around row {}, column {}, sorted; the fifth is the median.",
                                sr + 1,
                                sc + 1
                            ),
                        )
                        .formula(
                            r"g(r, c) = \operatorname{median}(f_1, \dots, f_9) = f_{(5)}",
                            format!(
                                r"g{} = \operatorname{{median}}({}) = \operatorname{{median}}({}) = {}",
                                pixel_name(sc, sr),
                                list(values),
                                list(&sorted),
                                m.map_or_else(String::new, num)
                            ),
                        )
                        .value("select_c", sc + 1)
                        .value("select_r", sr + 1)
                        .value("neighbourhood", Value::numbers(values))
                        .value("sorted", Value::numbers(&sorted))
                        .value("selected", m),
                    );
                    m
                }
                None => {
                    selection_note(&mut s, sc, sr, 3, 3);
                    None
                }
            };
            (filtered, value)
        }
    };

    let out = &filtered.output;
    s.step(
        matrix_step(
            "The filtered window",
            "The same sum at every pixel where there is an output.",
            "g",
            "output",
            out,
        )
        .value("pixel_results", Value::matrix(&out.rows()))
        .value("output_first_c", filtered.region.c0 + 1)
        .value("output_first_r", filtered.region.r0 + 1),
    );
    s.result = Record::new()
        .with("output", Value::matrix(&out.rows()))
        .with("selected", selected)
        .with(
            "kernel",
            kernel
                .as_ref()
                .map_or(Value::Null, |k| Value::matrix(&k.weights().rows())),
        )
        .with("kernel_sum", kernel.as_ref().map(Kernel::sum))
        .with("output_first_c", filtered.region.c0 + 1)
        .with("output_first_r", filtered.region.r0 + 1);
    s.label("output", "Filtered window", "");
    s.label("selected", "Output at the selected pixel", "");
    s.label("kernel", "Kernel weights", "");
    s.label("kernel_sum", "Sum of the kernel weights", "");
    s.label("output_first_c", "Column of the output's first pixel", "");
    s.label("output_first_r", "Row of the output's first pixel", "");

    correlation_note(&mut s);
    if let Some(k) = &kernel {
        kernel_sum_notes(&mut s, name, k);
    }
    crop_note(&mut s, border, filtered.region, &window);
    if name == "log" {
        s.note(
            NoteKind::Convention,
            "The course notes describe the Laplacian of Gaussian in words (smooth with the Gaussian, then apply the Laplacian) without a kernel. It is built here from the course notes' own kernels: the 3×3 Gaussian 1/16·[1 2 1; 2 4 2; 1 2 1] convolved with the 4-neighbour Laplacian [0 1 0; 1 −4 1; 0 1 0], one 5×5 kernel that sums to 0.",
        ).about(&["kernel"]);
    }
    if border == Border::Crop {
        seed_filter_cases(&mut s, &window, name, filtered.region, sc, sr);
        if s.textbook
            .as_ref()
            .is_some_and(|t| t.get("pixel_results").is_some())
        {
            s.label(
                "pixel_results",
                "Each output pixel worked out (printed with more decimals)",
                "",
            );
        }
    }
    Ok(s)
}

/// Example 15's printed means, pixel by pixel and in the output grid.
const EX15_MEAN_PIXELS: [[f64; 3]; 3] = [
    [11.33, 11.11, 8.89],
    [12.55, 12.78, 10.55],
    [12.88, 15.0, 13.78],
];
const EX15_MEAN_GRID: [[f64; 3]; 3] = [[11.3, 11.1, 8.9], [12.5, 12.8, 10.5], [12.9, 15.0, 13.8]];
const EX15_GAUSS_PIXELS: [[f64; 3]; 3] =
    [[12.81, 10.25, 9.1], [14.3, 12.0, 10.0], [14.4, 14.3, 13.94]];
const EX15_GAUSS_GRID: [[f64; 3]; 3] = [[12.8, 10.2, 9.1], [14.3, 12.0, 10.0], [14.4, 14.3, 13.9]];
const EX16_GRID: [[f64; 3]; 3] = [
    [25.0, -39.0, 15.0],
    [-41.0, -33.0, -31.0],
    [24.0, -33.0, 23.0],
];

fn seed_filter_cases(
    s: &mut Solution,
    window: &Grid,
    kernel: &str,
    region: filter::Region,
    sc: usize,
    sr: usize,
) {
    let textbook = |grid: &[[f64; 3]; 3], pixels: Option<&[[f64; 3]; 3]>| {
        let g = to_rows(grid);
        let detail = pixels.map(|p| to_rows(p));
        let sel = printed_at(detail.as_ref().unwrap_or(&g), region, sc, sr);
        let mut t = Record::new().with("output", Value::matrix(&g));
        if let Some(d) = &detail {
            t.set("pixel_results", Value::matrix(d));
        }
        t.with("selected", sel)
    };
    if same_window(window, &EXAMPLE_15) && kernel == "mean" {
        s.textbook = Some(textbook(&EX15_MEAN_GRID, Some(&EX15_MEAN_PIXELS)));
        s.note(
            NoteKind::Erratum,
            "Pixel (r4, c2): the course notes' sum reads 1/9(9+24+7+1+13+14+13+18+17) — the 10 at (r4, c1) is copied as 1. With it the sum is 125 and the mean 125/9 = 13.89, not 116/9 = 12.89 (printed 12.88, and 12.9 in the output grid instead of 13.9).",
        ).about(&["output", "pixel_results", "selected"]);
        s.note(
            NoteKind::Rounding,
            "The course notes cut the means off after two decimals instead of rounding: 113/9 = 12.556 at (r3, c2) is printed 12.55 and 95/9 = 10.556 at (r3, c4) 10.55 (rounded: 12.56 and 10.56); its slipped 116/9 = 12.889 is printed 12.88. The output grid then cuts these again to 12.5 and 10.5, where 12.6 and 10.6 are right.",
        ).about(&["output", "pixel_results"]);
        s.note(
            NoteKind::Erratum,
            "Harmless: for pixel (r2, c4) the course notes list the middle row as 9 + 9 + 10 instead of 10 + 9 + 9; the total 80 and the mean 8.89 are right.",
        ).about(&["pixel_results"]);
    } else if same_window(window, &EXAMPLE_15) && kernel == "gaussian-3" {
        s.textbook = Some(textbook(&EX15_GAUSS_GRID, Some(&EX15_GAUSS_PIXELS)));
        s.note(
            NoteKind::Rounding,
            "Every Gaussian sum of the course notes is right. Four of its per-pixel values are printed with one decimal where the others have two: 145/16 = 9.0625 as 9.1, 229/16 = 14.3125 as 14.3 (twice) and 230/16 = 14.375 as 14.4. The output grid prints 164/16 = 10.25 at (r2, c3) as 10.2, where rounding half up gives 10.3.",
        ).about(&["output", "pixel_results"]);
        s.note(
            NoteKind::Erratum,
            "Harmless: several of the course notes' Gaussian sums list their terms out of kernel order (at (r2, c4): 9×4 for the centre before 2×9 + 2×10 for its right and left neighbours); every total is right.",
        );
    } else if same_window(window, &EXAMPLE_16) && kernel == "laplacian-8" {
        s.textbook = Some(textbook(&EX16_GRID, None));
        s.note(
            NoteKind::Convention,
            "Every value of Example 16 is reproduced. The course notes write the centre term as −9×8 where the centre grey value 9 is multiplied by the kernel's −8: the same product.",
        ).about(&["output"]);
    } else if same_window(window, &SEED_004) && kernel == "mean" {
        if (sc, sr) == (2, 2) {
            s.textbook = Some(Record::new().with("selected", 33.0));
        }
        s.note(
            NoteKind::Rounding,
            "Lecture 7 works out only the centre pixel (row 3, column 3): (10 + 20 + 30 + 50 + 60 + 70 + 30 + 20 + 10)/9 = 300/9 = 33.33, printed as 33.",
        ).about(&["selected"]);
        s.note(
            NoteKind::Convention,
            "Lecture 7's formula g(i, j) = Σ Σ f(m, n)·PSF(i − m, j − n) is a true convolution (the kernel turned by 180°); for the symmetric mean kernel that is the same as applying it as written.",
        ).about(&["kernel"]);
    }
}

// ---------------------------------------------------------------------------
// edge-window

/// Printed Gx, Gy and magnitude.
type Printed3 = ([[f64; 3]; 3], [[f64; 3]; 3], [[f64; 3]; 3]);

const EX15_PREWITT: Printed3 = (
    [
        [-14.0, -12.0, 2.0],
        [-1.0, -8.0, -14.0],
        [-8.0, -15.0, -32.0],
    ],
    [[-10.0, -24.0, 12.0], [1.0, -20.0, 1.0], [6.0, -13.0, 6.0]],
    [[17.2, 26.8, 12.2], [1.4, 21.54, 14.0], [10.0, 19.85, 32.6]],
);
const EX15_SOBEL: Printed3 = (
    [
        [-25.0, -16.0, 5.0],
        [1.0, -12.0, -20.0],
        [-2.0, -25.0, -43.0],
    ],
    [[-11.0, -30.0, 11.0], [-1.0, -36.0, 4.0], [10.0, -11.0, 5.0]],
    [[27.3, 34.0, 12.1], [1.4, 37.9, 20.4], [10.2, 27.3, 43.3]],
);

fn edge_window(inputs: &Record) -> Result<Solution> {
    let (window, sc, sr) = window_and_selection(inputs)?;
    let op = text(inputs, "operator")?;
    let border = border_of(text(inputs, "border")?)?;
    let (kx, ky, nx, ny, title) = match op {
        "sobel" => (
            filter::sobel_x(),
            filter::sobel_y(),
            "sk_x",
            "sk_y",
            "Sobel",
        ),
        _ => (
            filter::prewitt_x(),
            filter::prewitt_y(),
            "pk_x",
            "pk_y",
            "Prewitt",
        ),
    };
    if filter::output_region(window.width(), window.height(), 1, 1, border).is_none() {
        return Err(too_small(&window, 3, 3));
    }
    let g: Gradient = filter::gradient(&window, &kx, &ky, border)?;
    let mut s = Solution::new("edge-window", "Prewitt and Sobel edges", inputs.clone());
    s.step(
        Step::new(
            &format!("The {title} kernels"),
            "The first kernel takes the top row minus the bottom row, the second the right column minus the left one; the course notes call their responses Gx and Gy.",
        )
        .formula(
            &format!(r"\mathrm{{{nx}}},\quad \mathrm{{{ny}}}"),
            format!(
                r"\mathrm{{{nx}}} = {},\quad \mathrm{{{ny}}} = {}",
                kernel_tex(&kx),
                kernel_tex(&ky)
            ),
        )
        .value("kernel_x", Value::matrix(&kx.numerators().rows()))
        .value("kernel_y", Value::matrix(&ky.numerators().rows())),
    );
    let px = filter::pixel_sum(&window, &kx, sc, sr, border);
    let py = filter::pixel_sum(&window, &ky, sc, sr, border);
    let selected = match (&px, &py) {
        (Some(px), Some(py)) => {
            let m = px.value.hypot(py.value);
            let at = format!("row {}, column {}", sr + 1, sc + 1);
            s.step(
                Step::new(
                    "Gx at the selected pixel, written out",
                    &format!("The kernel {nx} centred on the pixel in {at}: weights times grey values, added."),
                )
                .formula(
                    &format!(r"G_x(r, c) = \sum_j\sum_i \mathrm{{{nx}}}(i, j)\, f(r + j, c + i)"),
                    written_sum("G_x", px),
                )
                .value("select_c", sc + 1)
                .value("select_r", sr + 1)
                .value("neighbourhood", Value::numbers(&px.values))
                .value("selected_gx", px.value),
            );
            s.step(
                Step::new(
                    "Gy at the selected pixel, written out",
                    &format!("The kernel {ny} on the same pixel."),
                )
                .formula(
                    &format!(r"G_y(r, c) = \sum_j\sum_i \mathrm{{{ny}}}(i, j)\, f(r + j, c + i)"),
                    written_sum("G_y", py),
                )
                .value("selected_gy", py.value),
            );
            s.step(
                Step::new(
                    "Edge magnitude at the selected pixel",
                    "The length of the gradient vector (Gx, Gy).",
                )
                .formula(
                    r"|G| = \sqrt{G_x^2 + G_y^2}",
                    format!(
                        r"|G|{} = \sqrt{{{}^2 + {}^2}} = {}",
                        pixel_name(sc, sr),
                        tex(px.value),
                        tex(py.value),
                        num(m)
                    ),
                )
                .value("selected_magnitude", m),
            );
            Some((px.value, py.value, m))
        }
        _ => {
            selection_note(&mut s, sc, sr, 3, 3);
            None
        }
    };
    s.step(matrix_step(
        "Gx over the window",
        &format!("The response to {nx} at every pixel with an output."),
        "G_x",
        "gx",
        &g.gx,
    ));
    s.step(matrix_step(
        "Gy over the window",
        &format!("The response to {ny} at every pixel with an output."),
        "G_y",
        "gy",
        &g.gy,
    ));
    s.step(
        matrix_step(
            "Edge magnitude over the window",
            "√(Gx² + Gy²) at every pixel with an output: large where the grey values change fast in any direction.",
            "|G|",
            "magnitude",
            &g.magnitude,
        )
        .value("output_first_c", g.region.c0 + 1)
        .value("output_first_r", g.region.r0 + 1),
    );
    s.result = Record::new()
        .with("gx", Value::matrix(&g.gx.rows()))
        .with("gy", Value::matrix(&g.gy.rows()))
        .with("magnitude", Value::matrix(&g.magnitude.rows()))
        .with("selected_gx", selected.map(|v| v.0))
        .with("selected_gy", selected.map(|v| v.1))
        .with("selected_magnitude", selected.map(|v| v.2))
        .with("output_first_c", g.region.c0 + 1)
        .with("output_first_r", g.region.r0 + 1);
    for (k, l) in [
        ("gx", "Gx: top row minus bottom row"),
        ("gy", "Gy: right column minus left column"),
        ("magnitude", "Edge magnitude √(Gx² + Gy²)"),
        ("selected_gx", "Gx at the selected pixel"),
        ("selected_gy", "Gy at the selected pixel"),
        ("selected_magnitude", "Edge magnitude at the selected pixel"),
        ("output_first_c", "Column of the output's first pixel"),
        ("output_first_r", "Row of the output's first pixel"),
    ] {
        s.label(k, l, "");
    }
    correlation_note(&mut s);
    s.note(
        NoteKind::Convention,
        format!("The course notes' names are kept: Gx is the response to {nx} (top row minus bottom row, a change along the rows, upward) and Gy to {ny} (right column minus left, a change along the columns). The Förstner operator's g′x is the other way round: a difference along the columns."),
    ).about(&["gx", "gy"]);
    crop_note(&mut s, border, g.region, &window);
    if border == Border::Crop && same_window(&window, &EXAMPLE_15) {
        let (tx, ty, tm) = if op == "sobel" {
            EX15_SOBEL
        } else {
            EX15_PREWITT
        };
        let (rx, ry, rm) = (to_rows(&tx), to_rows(&ty), to_rows(&tm));
        let mut t = Record::new()
            .with("gx", Value::matrix(&rx))
            .with("gy", Value::matrix(&ry))
            .with("magnitude", Value::matrix(&rm));
        if selected.is_some() {
            t.set("selected_gx", printed_at(&rx, g.region, sc, sr));
            t.set("selected_gy", printed_at(&ry, g.region, sc, sr));
            t.set("selected_magnitude", printed_at(&rm, g.region, sc, sr));
        }
        s.textbook = Some(t);
        s.note(
            NoteKind::Rounding,
            format!(
                "Every {title} value of Example 15 is reproduced: the responses exactly, the magnitudes within the one or two decimals the course notes print."
            ),
        ).about(&["magnitude", "selected_magnitude"]);
    }
    Ok(s)
}
