//! Example 4(b): the affine transformation from the four fiducials (pixels
//! to photo millimetres), with the seed's printed values.

use super::fiducials::{rounding_notes, Printed};
use super::*;
use crate::examples::drill::{drill, Drill};
use crate::examples::Lab;

pub const EXAMPLE: Example = Example {
    id: "fiducial-affine",
    title: "Fiducials: affine transformation",
    source: "Worked examples, Example 4(b)",
    summary: "Pixel to photo coordinates through the four fiducials: an affine transformation (two scales, shear, rotation, shift) by least squares.",
    fields: fiducials::fields,
    solve,
    answer: &["parameters", "sigma0"],
    labels: &[],
    lab: Some(Lab::new("fiducials", &["affine"])),
    practice: drill(Drill::new(
        fiducials::generate,
        |_| fiducials::boxes(PARAMETERS),
        Some(|i, g| chain_sigma0(&EXAMPLE, i, g)),
        |i| fiducials::mistakes(&EXAMPLE, i, PARAMETERS.len()),
    )),
};

/// The parameters in the order of X: `(name, is a shift)`.
const PARAMETERS: &[(&str, bool)] = &[
    ("a", false),
    ("b", false),
    ("e", true),
    ("c", false),
    ("d", false),
    ("f", true),
];

fn solve(inputs: &Record) -> Result<Solution> {
    fiducials::example4(&EXAMPLE, inputs, Model::FiducialAffine, &PRINTED)
}

const PRINTED: Printed = Printed {
    x: &AFF_PRINTED_X,
    v: &AFF_PRINTED_V,
    notes: seed_notes,
};

fn seed_notes(s: &mut Solution, fit: &Fit, cr: &[PointPair]) -> Result<()> {
    let lit = transform::fit(Model::FiducialAffine, cr)?;
    let lx = &lit.adjustment.x;
    let g = |i: usize| lx.get(i).copied().unwrap_or(0.0);
    s.note(
        NoteKind::Convention,
        format!(
            "Here the printed A carries −r in its y′ columns ([c, −r, 1, 0, 0, 0] and [0, 0, 0, c, −r, 1]): y′ = −r is written into the matrix, consistent with the equations x = a·x′ + b·y′ + e, y = c·x′ + d·y′ + f. An affine transformation could absorb the flip itself: with y′ = r it fits just as well (σ0 = {} mm, the same residuals) but b and d change sign (b = {}, d = {}).",
            fmt_sig(lit.adjustment.sigma0.unwrap_or(0.0), 4),
            num(g(1)),
            num(g(4))
        ),
    );
    let names = Model::FiducialAffine.param_names();
    rounding_notes(s, "parameters", &names, &fit.adjustment.x, &AFF_PRINTED_X);
    Ok(())
}
