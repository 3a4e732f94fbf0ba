//! Seed 000, Examples 15–16 and Lecture 7: one kernel (mean, weighted,
//! median, Laplacian, LoG, sharpening, high-pass) applied to one window,
//! sum by sum; and its practice.

use super::super::drill::{
    drill, mat, or_given, rows_of, tol, value_in, BoxDef, Drill, Mistake, Rng,
};
use super::super::{Example, Lab};
use super::*;
use crate::filter::Filtered;

pub const EXAMPLE: Example = Example {
    id: "filter-window",
    title: "Filtering a window",
    source: "Worked examples, Examples 15–16; Lecture 7: Image processing",
    summary: "A window of grey values under a smoothing, sharpening or Laplacian kernel (or the median), each output pixel's sum written out.",
    fields,
    solve,
    answer: &["selected", "output"],
    labels: LABELS,
    lab: Some(Lab::new("filters", &["window"])),
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

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

fn fields() -> Vec<Field> {
    let [sc, sr] = select_fields();
    vec![
        window_field(),
        Field::choice("kernel", "Kernel", KERNELS, "mean")
            .help("Example 15 uses the mean and the Gaussian, Example 16 the 8-neighbour Laplacian, Lecture 7 the mean."),
        Field::matrix(
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

/// The named kernel (`None` for the median).
fn named_kernel(name: &str, inputs: &Record) -> Result<Option<Kernel>> {
    if let Some(k) = filter::by_name(name) {
        return Ok(k);
    }
    Ok(Some(match name {
        "custom" => {
            let k = Inputs(inputs).rows("custom_kernel")?;
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

fn solve(inputs: &Record) -> Result<Solution> {
    let (window, sc, sr) = window_and_selection(inputs)?;
    let i = Inputs(inputs);
    let name = i.text("kernel")?;
    let border = border_of(i.text("border")?)?;
    let kernel = named_kernel(name, inputs)?;
    let (kw, kh) = kernel.as_ref().map_or((3, 3), |k| (k.width(), k.height()));
    if filter::output_region(window.width(), window.height(), kw / 2, kh / 2, border).is_none() {
        return Err(too_small(&window, kw, kh));
    }
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
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
                .relation(
                    Relation::new("w")
                        .key("weights")
                        .sym(r"\frac{1}{d}\, n")
                        .subst(kernel_form(k, "n")),
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
                    .relations(written_sum(
                        "g",
                        r"\frac{1}{d}\sum_{j}\sum_{i} n(i, j)\, f(r + j, c + i)",
                        "numerator_sum",
                        ps,
                    ))
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
                .relation(
                    Relation::new("g(r, c)")
                        .sym(r"\operatorname{median}\{ f(r + j, c + i) : |i|, |j| \le 1 \}"),
                ),
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
                        .relation(
                            Relation::new("g(r, c)")
                                .sym(r"\operatorname{median}(f_1, \dots, f_9)")
                                .sym("f_{(5)}"),
                        )
                        .relation(
                            Relation::new(format!("g{}", pixel_name(sc, sr)))
                                .key("selected")
                                .subst(format!(r"\operatorname{{median}}({})", list(values)))
                                .subst(format!(r"\operatorname{{median}}({})", list(&sorted)))
                                .result(m.map_or_else(String::new, num)),
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
            ("g", "g"),
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
pub(super) const EX15_MEAN_PIXELS: [[f64; 3]; 3] = [
    [11.33, 11.11, 8.89],
    [12.55, 12.78, 10.55],
    [12.88, 15.0, 13.78],
];
pub(super) const EX15_MEAN_GRID: [[f64; 3]; 3] =
    [[11.3, 11.1, 8.9], [12.5, 12.8, 10.5], [12.9, 15.0, 13.8]];
pub(super) const EX15_GAUSS_PIXELS: [[f64; 3]; 3] =
    [[12.81, 10.25, 9.1], [14.3, 12.0, 10.0], [14.4, 14.3, 13.94]];
pub(super) const EX15_GAUSS_GRID: [[f64; 3]; 3] =
    [[12.8, 10.2, 9.1], [14.3, 12.0, 10.0], [14.4, 14.3, 13.9]];
pub(super) const EX16_GRID: [[f64; 3]; 3] = [
    [25.0, -39.0, 15.0],
    [-41.0, -33.0, -31.0],
    [24.0, -33.0, 23.0],
];

pub(super) fn seed_filter_cases(
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

// ---------------------------------------------------------------------------
// Practice

/// Kernels with their divisor (custom kernels divide by 1).
const DRILL_KERNELS: [(&str, f64); 6] = [
    ("mean", 9.0),
    ("weighted-mean", 10.0),
    ("gaussian-3", 16.0),
    ("laplacian-8", 1.0),
    ("sharpen", 9.0),
    ("custom", 1.0),
];

/// Directional kernels: flipping them changes the result, so the
/// convolution-vs-correlation mistake shows.
const CUSTOM: [[[f64; 3]; 3]; 4] = [
    [[-2.0, -1.0, 0.0], [-1.0, 1.0, 1.0], [0.0, 1.0, 2.0]],
    [[1.0, 2.0, 1.0], [0.0, 0.0, 0.0], [-1.0, -2.0, -1.0]],
    [[0.0, 1.0, 2.0], [-1.0, 0.0, 1.0], [-2.0, -1.0, 0.0]],
    [[1.0, 0.0, -1.0], [2.0, 0.0, -2.0], [1.0, 0.0, -1.0]],
];

fn generate(rng: &mut Rng) -> Record {
    let (kernel, _) = rng.pick(&DRILL_KERNELS);
    let mut r = Record::new()
        .with("window", mat(&practice_window(rng)))
        .with("kernel", kernel);
    if kernel == "custom" {
        let k = rng.pick(&CUSTOM);
        r.set(
            "custom_kernel",
            mat(&k.iter().map(|row| row.to_vec()).collect::<Vec<_>>()),
        );
    }
    r
}

/// The output pixels asked for (row, column within the 3×3 output).
const FILTER_BOXES: [(usize, usize); 3] = [(1, 1), (2, 2), (3, 2)];

fn boxes(_: &Record) -> Vec<BoxDef> {
    let first = BoxDef::new(
        "numerator_sum",
        "Sum of numerator × grey value at row 1, column 1 (before dividing)",
        None,
        tol::GREY,
    )
    .nudge("The kernel's numerators (its weights times the divisor) on the 3×3 neighbourhood of window pixel (2, 2): multiply each pair and add. Applied as written: no flip.");
    std::iter::once(first)
        .chain(FILTER_BOXES
        .iter()
        .map(|&(r, c)| {
            BoxDef::new(
                &format!("output[{r},{c}]"),
                &format!("Output at row {r}, column {c} of the 3×3 result"),
                None,
                tol::GREY,
            )
            .nudge("Lay the kernel on the window with its centre on the pixel, multiply each pair, add, divide by the kernel's divisor. Applied as written: no flip.")
        }))
        .collect()
}

/// The first output pixel from the student's sum of numerators.
fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = EXAMPLE.run(i)?;
    let sum = or_given(g, "numerator_sum", value_in(&s, "numerator_sum")?);
    let divisor = value_in(&s, "divisor")?;
    let mut out = Record::new()
        .with("numerator_sum", sum)
        .with("output[1,1]", or_given(g, "output[1,1]", sum / divisor));
    for &(r, c) in &FILTER_BOXES[1..] {
        let key = format!("output[{r},{c}]");
        out.set(&key, value_in(&s, &key)?);
    }
    Ok(out)
}

fn output(i: &Record, r: usize, c: usize) -> Result<f64> {
    value_in(&EXAMPLE.run(i)?, &format!("output[{r},{c}]"))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let s = EXAMPLE.run(i)?;
    let kernel = Inputs(i).text("kernel").ok().map(str::to_string);
    let divisor = DRILL_KERNELS
        .iter()
        .find(|(k, _)| Some(k.to_string()) == kernel)
        .map_or(1.0, |k| k.1);
    let flipped = if kernel.as_deref() == Some("custom") {
        let k = rows_of(i, "custom_kernel");
        let f: Vec<Vec<f64>> = k
            .iter()
            .rev()
            .map(|row| row.iter().rev().copied().collect())
            .collect();
        Some(i.clone().with("custom_kernel", mat(&f)))
    } else {
        None
    };
    let mut out = Vec::new();
    if let Some(f) = &flipped {
        out.push(Mistake::new(
            "numerator_sum",
            "kernel flipped",
            "The seeds apply the kernel as written (correlation); flipping it first is convolution.",
            value_in(&EXAMPLE.run(f)?, "numerator_sum")?,
        ));
    }
    if divisor != 1.0 {
        out.push(Mistake::new(
            "numerator_sum",
            "divided already",
            "This box asks for the sum before dividing by the divisor.",
            value_in(&s, "numerator_sum")? / divisor,
        ));
    }
    for &(r, c) in &FILTER_BOXES {
        let key = format!("output[{r},{c}]");
        let x = value_in(&s, &key)?;
        if let Some(f) = &flipped {
            out.push(Mistake::new(
                &key,
                "kernel flipped",
                "The seeds apply the kernel as written (correlation); flipping it first is convolution.",
                output(f, r, c)?,
            ));
        }
        if divisor != 1.0 {
            out.push(Mistake::new(
                &key,
                "divisor forgotten",
                "The kernel's weights are the numerators over the divisor: divide the sum.",
                x * divisor,
            ));
        }
        out.push(Mistake::new(
            &key,
            "rows and columns swapped",
            "Row r counts down, column c to the right: this is the pixel at row c, column r.",
            value_in(&s, &format!("output[{c},{r}]"))?,
        ));
    }
    Ok(out)
}
