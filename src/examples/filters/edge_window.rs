//! Example 15's edges: Prewitt and Sobel gradients, magnitude and direction of one window.

use super::*;

// edge-window

/// Printed Gx, Gy and magnitude.
pub(super) type Printed3 = ([[f64; 3]; 3], [[f64; 3]; 3], [[f64; 3]; 3]);

pub(super) const EX15_PREWITT: Printed3 = (
    [
        [-14.0, -12.0, 2.0],
        [-1.0, -8.0, -14.0],
        [-8.0, -15.0, -32.0],
    ],
    [[-10.0, -24.0, 12.0], [1.0, -20.0, 1.0], [6.0, -13.0, 6.0]],
    [[17.2, 26.8, 12.2], [1.4, 21.54, 14.0], [10.0, 19.85, 32.6]],
);
pub(super) const EX15_SOBEL: Printed3 = (
    [
        [-25.0, -16.0, 5.0],
        [1.0, -12.0, -20.0],
        [-2.0, -25.0, -43.0],
    ],
    [[-11.0, -30.0, 11.0], [-1.0, -36.0, 4.0], [10.0, -11.0, 5.0]],
    [[27.3, 34.0, 12.1], [1.4, 37.9, 20.4], [10.2, 27.3, 43.3]],
);

pub(super) fn edge_window(inputs: &Record) -> Result<Solution> {
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
