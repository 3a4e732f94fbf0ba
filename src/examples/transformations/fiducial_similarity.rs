//! Example 4(a): the similarity transformation from the four fiducials
//! (pixels to photo millimetres), with the seed's printed values.

use super::fiducials::{max_abs, rounding_notes, Printed};
use super::*;
use crate::examples::drill::{drill, Drill};
use crate::examples::Lab;

pub const EXAMPLE: Example = Example {
    id: "fiducial-similarity",
    title: "Fiducials: similarity transformation",
    source: "Worked examples, Example 4(a)",
    summary: "Pixel to photo coordinates through the four fiducials: a similarity transformation (scale, rotation, shift) by least squares.",
    fields: fiducials::fields,
    solve,
    answer: &["parameters", "sigma0"],
    labels: &[],
    lab: Some(Lab::new("fiducials", &["similarity"])),
    practice: drill(Drill::new(
        fiducials::generate,
        |_| fiducials::boxes(PARAMETERS),
        Some(|i, g| chain_sigma0(&EXAMPLE, i, g)),
        |i| fiducials::mistakes(&EXAMPLE, i, PARAMETERS.len()),
    )),
};

/// The parameters in the order of X: `(name, is a shift)`.
const PARAMETERS: &[(&str, bool)] = &[("a", false), ("b", false), ("c", true), ("d", true)];

fn solve(inputs: &Record) -> Result<Solution> {
    fiducials::example4(&EXAMPLE, inputs, Model::Similarity, &PRINTED)
}

const PRINTED: Printed = Printed {
    x: &SIM_PRINTED_X,
    v: &SIM_PRINTED_V,
    notes: seed_notes,
};

fn seed_notes(s: &mut Solution, fit: &Fit, cr: &[PointPair]) -> Result<()> {
    // The stated equations with y' = r literally, as the table header says.
    let literal: Vec<PointPair> = cr.to_vec();
    let lit = transform::fit(Model::Similarity, &literal)?;
    let x = &fit.adjustment.x;
    let g = |i: usize| x.get(i).copied().unwrap_or(0.0);
    s.note(
        NoteKind::Erratum,
        format!(
            "The course notes' table heads the pixel columns x′ (c) and y′ (r). Read with y′ = r, their printed matrix has the rows [x′, y′, 1, 0] and [−y′, x′, 0, 1], i.e. x = a·x′ + b·y′ + c, y = b·x′ − a·y′ + d — not its own equations x = a·x′ − b·y′ + c, y = b·x′ + a·y′ + d. The printed rows [c, r, 1, 0] and [−r, c, 0, 1] are exactly the stated equations with y′ = −r: [x′, −y′, 1, 0] and [y′, x′, 0, 1]. So the printed A is the similarity in (x′, y′) = (c, −r) — in (c, r) a scale, a rotation and a reflection of the row axis, which is what pixel → photo needs — and the printed X is its least-squares solution: a = {}, b = {}, c = {}, d = {}. Put y′ = r literally into the stated equations and no similarity fits: σ0 = {} mm, residuals up to {} mm.",
            num(g(0)),
            num(g(1)),
            num(g(2)),
            num(g(3)),
            fmt_sig(lit.adjustment.sigma0.unwrap_or(0.0), 3),
            fmt_sig(max_abs(&lit.adjustment.v), 3)
        ),
    );
    let names = Model::Similarity.param_names();
    rounding_notes(s, "parameters", &names, x, &SIM_PRINTED_X);
    if let Some((_, rot)) = scale_rotation(&fit.transform) {
        s.note(
            NoteKind::Rounding,
            format!(
                "b = {} is printed as 0.000 (its sign lost in the rounding): a rotation of {}° between the scanned photo and the fiducial system.",
                num(g(1)),
                fmt_sig(rot, 2)
            ),
        ).about(&["parameters", "rotation_deg"]);
    }
    Ok(())
}
