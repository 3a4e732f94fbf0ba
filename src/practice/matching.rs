//! Practice for seed 000, Examples 10–11 and seed 003: least-squares
//! matching. The iterations are long by hand, so the boxes ask for the
//! first shift (one linear least-squares step) and the converged position.

use super::grade::tol;
use super::{mat, nums, or_given, value_in, BoxDef, Mistake, Rng, Spec, Tolerance};
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
                    BoxDef::new("N[1,1]", "N = Σ g² (iteration 1)", None, tol::SUM)
                        .nudge("g is the search window's gradient at each template pixel, (g(c+1) − g(c−1)) / 2; square and add."),
                    BoxDef::new("AtL[1]", "AᵀdL = Σ g·dL (iteration 1)", None, tol::SUM)
                        .nudge("dL is the template minus the search patch at the start position; multiply by g and add."),
                    BoxDef::new("first_dc", "First shift Δc", Some("px"), SHIFT)
                        .nudge("Δc = AᵀdL / N.")
                        .axis(),
                    BoxDef::new("c_after_first", "Position after the first iteration", Some("px"), SHIFT)
                        .nudge("The start position plus the first shift."),
                    BoxDef::new("c", "Converged position c", Some("px"), SHIFT)
                        .nudge("Resample, repeat until the shift is tiny."),
                ]
            },
            chain: Some(chain_1d),
            mistakes: mistakes_1d,
        },
        Spec {
            id: "lsm-2d",
            generate: gen_2d,
            boxes: |_| {
                vec![
                    BoxDef::new("first_dc", "First shift Δc", Some("px"), SHIFT)
                        .nudge("Gradients gc, gr of the search window; the normal equations of Δc, Δr, Δa, Δb.")
                        .axis(),
                    BoxDef::new("first_dr", "First shift Δr", Some("px"), SHIFT)
                        .nudge("The second unknown of the same system.")
                        .axis(),
                    BoxDef::new("c_after_first", "Column after the first iteration", Some("px"), SHIFT)
                        .nudge("The start column plus Δc."),
                    BoxDef::new("r_after_first", "Row after the first iteration", Some("px"), SHIFT)
                        .nudge("The start row plus Δr."),
                    BoxDef::new("c", "Converged column c", Some("px"), SHIFT)
                        .nudge("Resample by bilinear interpolation and iterate."),
                    BoxDef::new("r", "Converged row r", Some("px"), SHIFT)
                        .nudge("The row of the converged position."),
                ]
            },
            chain: Some(chain_2d),
            mistakes: mistakes_2d,
        },
        Spec {
            id: "lsm-affine",
            generate: gen_affine,
            boxes: |_| {
                vec![
                    BoxDef::new("parameters[1]", "a₁ (converged)", None, AFFINE)
                        .nudge("The affine model's first parameter after convergence: s·cos θ when there is no shear."),
                    BoxDef::new("parameters[4]", "a₄ (converged)", None, AFFINE)
                        .nudge("The fourth parameter: s·sin θ when there is no shear."),
                    BoxDef::new("parameters[3]", "Shift a₃ (columns)", Some("px"), SHIFT)
                        .nudge("The affine model's column shift after convergence.")
                        .axis(),
                    BoxDef::new("parameters[6]", "Shift a₆ (rows)", Some("px"), SHIFT)
                        .nudge("The row shift after convergence.")
                        .axis(),
                    BoxDef::new("estimated_scale", "Scale s = √(a₁² + a₄²)", None, AFFINE)
                        .nudge("[a₁ a₂; a₄ a₅] = s·R(θ) without shear: the first column is s·(cos θ, sin θ)."),
                    BoxDef::new("estimated_rotation_deg", "Rotation θ = atan2(a₄, a₁)", Some("°"), Tolerance::abs(0.05))
                        .nudge("The angle of the first column (a₁, a₄), in degrees."),
                ]
            },
            chain: Some(chain_affine),
            mistakes: mistakes_affine,
        },
    ]
}

/// The affine part's parameters and the scale: to 0.001 (0.1 %).
const AFFINE: Tolerance = Tolerance::abs(0.001);

fn chain_1d(i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve("lsm-1d", i)?;
    let n = or_given(g, "N[1,1]", value_in(&s, "N[1,1]")?);
    let atl = or_given(g, "AtL[1]", value_in(&s, "AtL[1]")?);
    let dc = or_given(g, "first_dc", atl / n);
    let c0 = i.number("c0").unwrap_or(f64::NAN);
    Ok(Record::new()
        .with("N[1,1]", n)
        .with("AtL[1]", atl)
        .with("first_dc", dc)
        .with("c_after_first", or_given(g, "c_after_first", c0 + dc))
        .with("c", value_in(&s, "c")?))
}

fn mistakes_1d(i: &Record) -> Result<Vec<Mistake>> {
    let s = examples::solve("lsm-1d", i)?;
    const HALF: &str = "The gradient is (g(c+1) − g(c−1)) / 2: without the ½ it is twice too big.";
    let (n, atl, dc) = (
        value_in(&s, "N[1,1]")?,
        value_in(&s, "AtL[1]")?,
        value_in(&s, "first_dc")?,
    );
    let c0 = i.number("c0").unwrap_or(f64::NAN);
    let mut out = swap_sign(&s, &["AtL[1]", "first_dc"])?;
    out.extend([
        Mistake::new("N[1,1]", "½ forgotten in the gradient", HALF, 4.0 * n),
        Mistake::new("AtL[1]", "½ forgotten in the gradient", HALF, 2.0 * atl),
        Mistake::new(
            "first_dc",
            "N over AᵀdL",
            "The shift is AᵀdL / N, not its inverse.",
            n / atl,
        ),
        Mistake::new(
            "c_after_first",
            "shift subtracted",
            "The new position is the old one plus the increment.",
            c0 - dc,
        ),
    ]);
    Ok(out)
}

fn chain_2d(i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve("lsm-2d", i)?;
    let dc = or_given(g, "first_dc", value_in(&s, "first_dc")?);
    let dr = or_given(g, "first_dr", value_in(&s, "first_dr")?);
    let (c0, r0) = (
        i.number("c0").unwrap_or(f64::NAN),
        i.number("r0").unwrap_or(f64::NAN),
    );
    Ok(Record::new()
        .with("first_dc", dc)
        .with("first_dr", dr)
        .with("c_after_first", or_given(g, "c_after_first", c0 + dc))
        .with("r_after_first", or_given(g, "r_after_first", r0 + dr))
        .with("c", value_in(&s, "c")?)
        .with("r", value_in(&s, "r")?))
}

fn chain_affine(i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve("lsm-affine", i)?;
    let mut out = Record::new();
    let mut p = [0.0; 7];
    for k in [1, 4, 3, 6] {
        let key = format!("parameters[{k}]");
        p[k] = or_given(g, &key, value_in(&s, &key)?);
        out.set(&key, p[k]);
    }
    let scale = or_given(g, "estimated_scale", p[1].hypot(p[4]));
    Ok(out
        .with("estimated_scale", scale)
        .with("estimated_rotation_deg", p[4].atan2(p[1]).to_degrees()))
}

fn mistakes_affine(i: &Record) -> Result<Vec<Mistake>> {
    let s = examples::solve("lsm-affine", i)?;
    let (a1, a4, a3, a6) = (
        value_in(&s, "parameters[1]")?,
        value_in(&s, "parameters[4]")?,
        value_in(&s, "parameters[3]")?,
        value_in(&s, "parameters[6]")?,
    );
    const SWAP: &str = "a₃ shifts the columns c, a₆ the rows r.";
    let theta = a4.atan2(a1);
    Ok(vec![
        Mistake::new("parameters[3]", "rows and columns swapped", SWAP, a6),
        Mistake::new("parameters[6]", "rows and columns swapped", SWAP, a3),
        Mistake::new(
            "estimated_rotation_deg",
            "degrees vs radians",
            "atan2 gives radians; the box asks for degrees (× 180/π).",
            theta,
        ),
        Mistake::new(
            "estimated_scale",
            "a₁ taken as the scale",
            "a₁ = s·cos θ: the scale is the length of the column (a₁, a₄).",
            a1,
        ),
    ])
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
    const SUB: &str = "The new position is the old one plus the increment.";
    const ONCE: &str = "One iteration is only the first step: resample the search window at the new position and solve again until the increments are negligible.";
    let (c0, r0) = (
        i.number("c0").unwrap_or(f64::NAN),
        i.number("r0").unwrap_or(f64::NAN),
    );
    Ok(vec![
        Mistake::new("first_dc", "rows and columns swapped", SWAP, dr),
        Mistake::new("first_dr", "rows and columns swapped", SWAP, dc),
        Mistake::new("c_after_first", "shift subtracted", SUB, c0 - dc),
        Mistake::new("r_after_first", "shift subtracted", SUB, r0 - dr),
        Mistake::new("c", "stopped after one iteration", ONCE, c0 + dc),
        Mistake::new("r", "stopped after one iteration", ONCE, r0 + dr),
    ])
}

fn gen_affine(rng: &mut Rng) -> Record {
    let shift_c = rng.num(-15, 15) / 10.0;
    let shift_r = rng.num(-15, 15) / 10.0;
    // The pull-in range of an 11×11 patch: shifts of 1.5 px along both axes
    // at once (≈2 px) with a rotation can leave the window. The shift is kept
    // within 1.5 px of the start (only the row shift of such a draw is
    // shortened, so every other variant keeps its numbers).
    let reach = (1.5f64 * 1.5 - shift_c * shift_c).max(0.0).sqrt();
    let shift_r = if shift_r.abs() > reach {
        shift_r.signum() * (reach * 10.0).floor() / 10.0 + 0.0
    } else {
        shift_r
    };
    Record::new()
        .with("patch_size", 11.0)
        .with("shift_c", shift_c)
        .with("shift_r", shift_r)
        .with("rotation_deg", rng.num(-5, 5))
        .with("scale", rng.num(95, 105) / 100.0)
        .with("shear", 0.0)
        .with("gain", rng.num(90, 120) / 100.0)
        .with("offset", rng.num(-10, 10))
        .with("noise", rng.num(0, 2))
        .with("seed", texture(rng.num(1, 100)))
}

/// The texture seed of a generated pair. Five of `synthetic_pair`'s
/// textures (found by the release audit over every variant) leave the 11×11
/// patch with a weak gradient in one direction: with them LSM takes 30–75
/// iterations or walks out of the window. Their variants take the next
/// texture instead (only those variants change).
fn texture(seed: f64) -> f64 {
    const WEAK: [f64; 5] = [4.0, 25.0, 62.0, 81.0, 97.0];
    if WEAK.contains(&seed) {
        seed + 1.0
    } else {
        seed
    }
}
