//! Examples 15–16 and Lecture 7: one kernel (mean, weighted, median, Laplacian, LoG, sharpening, high-pass) applied to one window, sum by sum.

use super::*;

// filter-window

pub(super) fn filter_window(inputs: &Record) -> Result<Solution> {
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
