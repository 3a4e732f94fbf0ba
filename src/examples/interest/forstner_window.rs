//! Seed 000, Example 13 and seed 003: the Förstner operator on a window
//! the student gives (gradient table, N, det N, N⁻¹, trace N⁻¹, w, q,
//! eigenvalues, the precision test and the error ellipse).

use super::*;
use crate::examples::drill::{drill, mat as rows_value, Drill, Rng};
use crate::examples::fields::is_seed;
use crate::examples::Lab;
use crate::interest;

pub const EXAMPLE: Example = Example {
    id: "forstner-window",
    title: "Förstner operator",
    source: "Worked examples, Example 13; Lecture 21: Image matching",
    summary: "Gradients by central differences, the matrix N, its inverse, weight w, roundness q, and Lecture 21's precision test with the error ellipse.",
    fields,
    solve,
    answer: &["w", "q", "accepted"],
    labels: LABELS,
    lab: Some(Lab::new("interest", &["forstner"])),
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

/// Example 13's window.
fn example_13() -> Vec<Vec<f64>> {
    [
        [10.0, 13.0, 3.0, 11.0, 13.0],
        [11.0, 15.0, 10.0, 9.0, 9.0],
        [9.0, 24.0, 7.0, 8.0, 10.0],
        [10.0, 13.0, 14.0, 15.0, 13.0],
        [13.0, 18.0, 17.0, 19.0, 21.0],
    ]
    .map(|r| r.to_vec())
    .to_vec()
}

fn fields() -> Vec<Field> {
    vec![
        window_field(
            &example_13(),
            "At least 3×3 (5×5 or 7×7 in the course notes); gradients are computed at the interior pixels.",
        ),
        sigma_n(1.0),
        threshold(),
    ]
}

fn solve(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let (sigma_n, t) = (i.number("sigma_n")?, i.number("threshold_px")?);
    let window = grid(inputs, "window")?;
    let f = interest::forstner(&window)?;
    let p = interest::precision(&f.measures, sigma_n, t);
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    forstner_steps(&mut s, &f, &p, sigma_n, t);
    s.result = forstner_result(&f, &p);
    singular_notes(&mut s, &f.measures);
    s.note(
        NoteKind::Convention,
        "Gradients are the worked examples' central differences, at the interior pixels only (the border pixels are neighbours). Lecture 21 computes them with a Sobel operator instead; the rest of the operator is the same.",
    ).about(&["gx", "gy"]);
    if is_seed(&fields(), inputs) {
        example_13_notes(&mut s, &f);
    } else {
        s.note(
            NoteKind::Convention,
            "The course documents give no noise level σn; the Example 13 default is 1 grey value.",
        )
        .about(&["lambda_max_shift", "accepted"]);
    }
    Ok(s)
}

fn example_13_notes(s: &mut Solution, f: &Forstner) {
    let m = &f.measures;
    for (key, label) in [
        ("sum_gx", "Sum of the column gradients Σg′x"),
        ("sum_gy", "Sum of the row gradients Σg′y"),
        ("sum_gxgy", "Sum of the products Σg′x·g′y"),
        ("sum_gx2", "Sum of the squares Σg′x²"),
        ("sum_gy2", "Sum of the squares Σg′y²"),
    ] {
        s.label(key, label, "");
    }
    let (printed_b, printed_det, printed_tr) = (-22.75, 8891.9375, 0.02);
    s.textbook = Some(
        Record::new()
            .with("sum_gx", -9.0)
            .with("sum_gy", 17.5)
            .with("sum_gxgy", -22.25)
            .with("sum_gx2", 82.0)
            .with("sum_gy2", 114.75)
            .with("n", mat(&[[82.0, printed_b], [printed_b, 114.75]]))
            .with("det_n", printed_det)
            .with(
                "n_inverse",
                mat(&[
                    [114.75 / printed_det, 22.75 / printed_det],
                    [22.75 / printed_det, 82.0 / printed_det],
                ]),
            )
            .with("trace_n_inverse", printed_tr),
    );
    s.note(
        NoteKind::Erratum,
        format!(
            "The course notes' table is right row by row, and its sum of g′x·g′y is {}; but the N it prints has {} off the diagonal. The determinant and inverse it prints follow from the slip: 82 × 114.75 − 22.75² = {} instead of 82 × 114.75 − 22.25² = {}, and 1/{} in front of N⁻¹ instead of 1/{}.",
            num(f.sums.gxgy),
            num(printed_b),
            num(82.0 * 114.75 - printed_b * printed_b),
            num(m.det),
            num(printed_det),
            num(m.det)
        ),
    ).about(&["n", "det_n", "n_inverse"]);
    s.note(
        NoteKind::Rounding,
        format!(
            "The course notes give trace N⁻¹ = {printed_tr}: the exact value is 196.75/{} = {}, and even its own determinant gives 196.75/{} = {}. Rounded to one significant digit, both slips disappear in a rounding of {} %.",
            num(m.det),
            opt_num(m.trace_inverse),
            num(printed_det),
            num(196.75 / printed_det),
            crate::solution::fmt_sig(
                m.trace_inverse
                    .map_or(0.0, |t| ((t - printed_tr) / t * 100.0).abs()),
                2
            )
        ),
    ).about(&["trace_n_inverse"]);
    s.note(
        NoteKind::Erratum,
        format!(
            "The course notes' rule \"the window is classified as an interest point if the trace exceeds a certain threshold\" is backwards. trace N⁻¹ = σu² + σv² (up to σn²) is the size of the error ellipse: a distinct point has a SMALL trace N⁻¹, and a flat window has an infinite one — the rule as printed would pick exactly the homogeneous areas. Förstner accepts a window when the weight w = 1/trace N⁻¹ = det N/trace N exceeds a threshold (here w = {}); Lecture 21 accepts when λmax(Σuv) ≤ T².",
            num(m.w)
        ),
    ).about(&["accepted"]);
    s.note(
        NoteKind::Convention,
        "The course documents give no noise level σn; the default is 1 grey value, with Lecture 21's T = 0.5 px.",
    ).about(&["lambda_max_shift", "accepted"]);
}

// ---------------------------------------------------------------- practice

/// A 5×5 window with a corner: a brighter quadrant (its corner at an
/// interior pixel, a random one of the four orientations) plus noise.
fn generate(rng: &mut Rng) -> Record {
    // The corner between interior pixels, so both edges cross the 3×3
    // interior where the gradients are taken.
    let (cc, cr) = (rng.int(2, 3), rng.int(2, 3));
    let (right, down) = (rng.coin(), rng.coin());
    let (base, step) = (rng.num(10, 40), rng.num(8, 20));
    let w: Vec<Vec<f64>> = (0..5)
        .map(|r| {
            (0..5)
                .map(|c| {
                    let inside = ((c >= cc) == right) && ((r >= cr) == down);
                    base + if inside { step } else { 0.0 } + rng.num(-3, 3)
                })
                .collect()
        })
        .collect();
    Record::new().with("window", rows_value(&w))
}

fn boxes(_: &Record) -> Vec<BoxDef> {
    forstner_boxes()
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    forstner_chain(&EXAMPLE.run(i)?, g)
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    forstner_mistakes(&EXAMPLE.run(i)?)
}
