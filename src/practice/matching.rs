//! Practice for seed 000, Examples 10–11 and seed 003: least-squares
//! matching. The iterations are long by hand, so the boxes ask for the
//! first shift (one linear least-squares step) and the converged position.

use super::{mat, nums, value_in, BoxDef, Mistake, Rng, Spec, Tolerance};
use crate::error::Result;
use crate::examples;
use crate::solution::Record;

pub fn specs() -> Vec<Spec> {
    vec![
        Spec {
            id: "lsm-1d",
            generate: gen_1d,
            boxes: |_| {
                vec![
                    BoxDef::new("first_dc", "First shift Δc", Some("px"), SHIFT)
                        .nudge("Gradient of the search window at each template pixel, then Δc = Σ g·Δg / Σ g²."),
                    BoxDef::new("c", "Converged position c", Some("px"), SHIFT)
                        .nudge("Resample, repeat until the shift is tiny."),
                ]
            },
            chain: None,
            mistakes: |i| swap_sign(&examples::solve("lsm-1d", i)?, &["first_dc"]),
        },
        Spec {
            id: "lsm-2d",
            generate: gen_2d,
            boxes: |_| {
                vec![
                    BoxDef::new("first_dc", "First shift Δc", Some("px"), SHIFT)
                        .nudge("Gradients gc, gr of the search window; the normal equations of Δc, Δr, Δa, Δb."),
                    BoxDef::new("first_dr", "First shift Δr", Some("px"), SHIFT)
                        .nudge("The second unknown of the same system."),
                    BoxDef::new("c", "Converged column c", Some("px"), SHIFT)
                        .nudge("Resample by bilinear interpolation and iterate."),
                    BoxDef::new("r", "Converged row r", Some("px"), SHIFT)
                        .nudge("The row of the converged position."),
                ]
            },
            chain: None,
            mistakes: mistakes_2d,
        },
        Spec {
            id: "lsm-affine",
            generate: gen_affine,
            boxes: |_| {
                vec![
                    BoxDef::new("parameters[3]", "Shift a₃ (columns)", Some("px"), SHIFT)
                        .nudge("The affine model's column shift after convergence."),
                    BoxDef::new("parameters[6]", "Shift a₆ (rows)", Some("px"), SHIFT)
                        .nudge("The row shift after convergence."),
                ]
            },
            chain: None,
            mistakes: |i| {
                let s = examples::solve("lsm-affine", i)?;
                let (a3, a6) = (
                    value_in(&s, "parameters[3]")?,
                    value_in(&s, "parameters[6]")?,
                );
                const SWAP: &str = "a₃ shifts the columns c, a₆ the rows r.";
                Ok(vec![
                    Mistake::new("parameters[3]", "rows and columns swapped", SWAP, a6),
                    Mistake::new("parameters[6]", "rows and columns swapped", SWAP, a3),
                ])
            },
        },
    ]
}

const SHIFT: Tolerance = Tolerance::abs(0.01);

fn swap_sign(s: &crate::solution::Solution, keys: &[&str]) -> Result<Vec<Mistake>> {
    keys.iter()
        .map(|k| {
            Ok(Mistake::new(
                k,
                "gradient taken the wrong way",
                "The gradient is (g(c+1) − g(c−1)) / 2: right minus left.",
                -value_in(s, k)?,
            ))
        })
        .collect()
}

/// A smooth bump of grey values sampled at `x` (the template's shape).
fn bump(x: f64, centre: f64, height: f64, width: f64) -> f64 {
    20.0 + height * (-((x - centre) / width).powi(2)).exp()
}

/// A search window with a smooth bump; the template is the same bump
/// sampled a fraction of a pixel away, so the match is off the start by
/// that fraction.
fn gen_1d(rng: &mut Rng) -> Record {
    let (height, width) = (rng.num(40, 80), rng.num(15, 25) / 10.0);
    let n = 12;
    let centre = rng.num(5, 7) as usize; // 0-based search position of the peak
    let frac = rng.num(-4, 4) / 10.0;
    let frac = if frac == 0.0 { 0.3 } else { frac };
    let search: Vec<f64> = (0..n)
        .map(|k| bump(k as f64, centre as f64 + frac, height, width).round())
        .collect();
    let template: Vec<f64> = (0..7)
        .map(|k| bump(k as f64, 3.0, height, width).round())
        .collect();
    Record::new()
        .with("template", nums(&template))
        .with("search", nums(&search))
        .with("c0", (centre + 1) as f64)
}

fn bump2(c: f64, r: f64, cc: f64, rc: f64, h: f64) -> f64 {
    20.0 + h * (-((c - cc).powi(2) / 2.5 + (r - rc).powi(2) / 1.8)).exp()
}

fn gen_2d(rng: &mut Rng) -> Record {
    let h = rng.num(60, 120);
    let (pc, pr) = (rng.num(2, 3), rng.num(2, 3)); // 0-based peak pixel
    let (fc, fr) = (rng.num(-3, 3) / 10.0, rng.num(-3, 3) / 10.0);
    let search: Vec<Vec<f64>> = (0..6)
        .map(|r| {
            (0..6)
                .map(|c| bump2(c as f64, r as f64, pc + fc, pr + fr, h).round())
                .collect()
        })
        .collect();
    let template: Vec<Vec<f64>> = (0..3)
        .map(|r| {
            (0..3)
                .map(|c| bump2(c as f64, r as f64, 1.0, 1.0, h).round())
                .collect()
        })
        .collect();
    Record::new()
        .with("template", mat(&template))
        .with("search", mat(&search))
        .with("c0", pc + 1.0)
        .with("r0", pr + 1.0)
        .with("a0", 1.0)
        .with("b0", 0.0)
}

fn mistakes_2d(i: &Record) -> Result<Vec<Mistake>> {
    let s = examples::solve("lsm-2d", i)?;
    let (dc, dr) = (value_in(&s, "first_dc")?, value_in(&s, "first_dr")?);
    const SWAP: &str = "Δc moves along the columns (right), Δr along the rows (down).";
    Ok(vec![
        Mistake::new("first_dc", "rows and columns swapped", SWAP, dr),
        Mistake::new("first_dr", "rows and columns swapped", SWAP, dc),
    ])
}

fn gen_affine(rng: &mut Rng) -> Record {
    Record::new()
        .with("patch_size", 11.0)
        .with("shift_c", rng.num(-15, 15) / 10.0)
        .with("shift_r", rng.num(-15, 15) / 10.0)
        .with("rotation_deg", rng.num(-5, 5))
        .with("scale", rng.num(95, 105) / 100.0)
        .with("shear", 0.0)
        .with("gain", rng.num(90, 120) / 100.0)
        .with("offset", rng.num(-10, 10))
        .with("noise", rng.num(0, 2))
        .with("seed", rng.num(1, 100))
}
