//! Seed 000, Example 15's edges: the Prewitt and Sobel responses and the
//! gradient magnitude of one window, the selected pixel's sums written out;
//! and its practice.

use super::super::drill::{
    drill, mat, or_given, rows_of, tol, transpose, BoxDef, Drill, Mistake, Rng,
};
use super::super::{Example, Lab};
use super::*;
use crate::filter::Gradient;

pub const EXAMPLE: Example = Example {
    id: "edge-window",
    title: "Prewitt and Sobel edges",
    source: "Worked examples, Example 15",
    summary: "The responses to the Prewitt or Sobel kernels in both directions and the edge magnitude √(Gx² + Gy²).",
    fields,
    solve,
    answer: &["selected_gx", "selected_gy", "selected_magnitude"],
    labels: LABELS,
    lab: Some(Lab::new("edges", &["window"])),
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

const OPERATORS: &[(&str, &str)] = &[("prewitt", "Prewitt"), ("sobel", "Sobel")];

fn fields() -> Vec<Field> {
    let [sc, sr] = select_fields();
    vec![
        window_field(),
        Field::choice("operator", "Edge operator", OPERATORS, "prewitt"),
        sc,
        sr,
        border_field(),
    ]
}

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

fn solve(inputs: &Record) -> Result<Solution> {
    let (window, sc, sr) = window_and_selection(inputs)?;
    let i = Inputs(inputs);
    let op = i.text("operator")?;
    let border = border_of(i.text("border")?)?;
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
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    s.step(
        Step::new(
            &format!("The {title} kernels"),
            "The first kernel takes the top row minus the bottom row, the second the right column minus the left one; the course notes call their responses Gx and Gy.",
        )
        .relation(
            Relation::new(format!(r"\mathrm{{{nx}}}"))
                .key("kernel_x")
                .result(kernel_form(&kx, nx)),
        )
        .relation(
            Relation::new(format!(r"\mathrm{{{ny}}}"))
                .key("kernel_y")
                .result(kernel_form(&ky, ny)),
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
                .relations(written_sum(
                    "G_x",
                    &format!(r"\sum_j\sum_i \mathrm{{{nx}}}(i, j)\, f(r + j, c + i)"),
                    "selected_gx",
                    px,
                ))
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
                .relations(written_sum(
                    "G_y",
                    &format!(r"\sum_j\sum_i \mathrm{{{ny}}}(i, j)\, f(r + j, c + i)"),
                    "selected_gy",
                    py,
                ))
                .value("selected_gy", py.value),
            );
            s.step(
                Step::new(
                    "Edge magnitude at the selected pixel",
                    "The length of the gradient vector (Gx, Gy).",
                )
                .relation(Relation::new("|G|").sym(r"\sqrt{G_x^2 + G_y^2}"))
                .relation(
                    Relation::new(format!("|G|{}", pixel_name(sc, sr)))
                        .key("selected_magnitude")
                        .subst(format!(
                            r"\sqrt{{{}^2 + {}^2}}",
                            tex(px.value),
                            tex(py.value)
                        ))
                        .value(m, ""),
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
        ("G_x", "Gx"),
        "gx",
        &g.gx,
    ));
    s.step(matrix_step(
        "Gy over the window",
        &format!("The response to {ny} at every pixel with an output."),
        ("G_y", "Gy"),
        "gy",
        &g.gy,
    ));
    s.step(
        matrix_step(
            "Edge magnitude over the window",
            "√(Gx² + Gy²) at every pixel with an output: large where the grey values change fast in any direction.",
            ("|G|", "|G|"),
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

// ---------------------------------------------------------------------------
// Practice

/// The window's centre: the pixel the boxes ask for, written out in the
/// steps (so each box's hint is its own pixel's sum).
const CENTRE: f64 = 3.0;

fn generate(rng: &mut Rng) -> Record {
    Record::new()
        .with("window", mat(&practice_window(rng)))
        .with("operator", if rng.coin() { "prewitt" } else { "sobel" })
        .with("select_c", CENTRE)
        .with("select_r", CENTRE)
}

/// The sign flip of a gradient: the kernel mirrored.
const KERNEL_FLIP: &str = "The size is right but the sign is not: apply the kernel as written, its positive side where it is printed.";

fn boxes(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("selected_gx", "Gx at the centre", None, tol::GREY)
            .nudge("The seed's x kernel: top row minus bottom row, applied as written.")
            .sign_flip(KERNEL_FLIP),
        BoxDef::new("selected_gy", "Gy at the centre", None, tol::GREY)
            .nudge("The y kernel: right column minus left column.")
            .sign_flip(KERNEL_FLIP),
        BoxDef::new(
            "selected_magnitude",
            "Edge magnitude at the centre",
            None,
            tol::GREY,
        )
        .nudge("√(Gx² + Gy²)."),
    ]
}

fn number(s: &Solution, key: &str) -> f64 {
    s.result.number(key).unwrap_or(f64::NAN)
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = EXAMPLE.run(i)?;
    let gx = or_given(g, "selected_gx", number(&s, "selected_gx"));
    let gy = or_given(g, "selected_gy", number(&s, "selected_gy"));
    Ok(Record::new()
        .with("selected_gx", gx)
        .with("selected_gy", gy)
        .with("selected_magnitude", gx.hypot(gy)))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let s = EXAMPLE.run(i)?;
    let (gx, gy) = (number(&s, "selected_gx"), number(&s, "selected_gy"));
    const SWAP: &str =
        "The seed's Gx kernel differences top and bottom rows; Gy the right and left columns.";
    let t = EXAMPLE.run(
        &i.clone()
            .with("window", mat(&transpose(&rows_of(i, "window")))),
    )?;
    Ok(vec![
        Mistake::new("selected_gx", "x and y swapped", SWAP, gy),
        Mistake::new("selected_gy", "x and y swapped", SWAP, gx),
        Mistake::new(
            "selected_gx",
            "rows and columns swapped",
            "The window's rows run down, its columns to the right.",
            number(&t, "selected_gx"),
        ),
        Mistake::new(
            "selected_magnitude",
            "|Gx| + |Gy| instead of the root",
            "The magnitude is the length of the gradient vector: √(Gx² + Gy²).",
            gx.abs() + gy.abs(),
        ),
    ])
}
