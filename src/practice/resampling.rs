//! Practice for seed 000, Examples 12a/12b: nearest neighbour, bilinear and
//! bicubic resampling at a fractional position.

use super::correlation::rows_of;
use super::grade::tol;
use super::{mat, or_given, BoxDef, Mistake, Rng, Spec, Tolerance};
use crate::error::Result;
use crate::examples;
use crate::solution::Record;

pub fn specs() -> Vec<Spec> {
    vec![Spec {
        id: "resample",
        generate,
        boxes,
        chain: Some(chain),
        mistakes,
    }]
}

/// A fraction in 0.05–0.95 with two decimals, never one half (so the
/// nearest pixel is never a tie).
fn fraction(rng: &mut Rng) -> f64 {
    let k = rng.int(5, 94);
    let k = if k == 50 { 51 } else { k };
    k as f64 / 100.0
}

fn generate(rng: &mut Rng) -> Record {
    let patch: Vec<Vec<f64>> = (0..4)
        .map(|_| (0..4).map(|_| rng.num(40, 90)).collect())
        .collect();
    let (first_c, first_r) = (rng.num(100, 900), rng.num(100, 900));
    // Inside the central cell so that bicubic has its 4×4 neighbourhood.
    let c = first_c + 1.0 + fraction(rng);
    let r = first_r + 1.0 + fraction(rng);
    Record::new()
        .with("patch", mat(&patch))
        .with("first_c", first_c)
        .with("first_r", first_r)
        .with("c", (c * 100.0).round() / 100.0)
        .with("r", (r * 100.0).round() / 100.0)
}

fn boxes(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("nearest", "Nearest neighbour", None, tol::WHOLE)
            .nudge("Round c and r to the nearest whole pixel and read its grey value."),
        BoxDef::new("i1", "Upper row interpolated I₁", None, tol::GREY)
            .nudge("Along the upper row of the 2×2 neighbourhood: move the fraction Δc from the left pixel to the right one."),
        BoxDef::new("i2", "Lower row interpolated I₂", None, tol::GREY)
            .nudge("The same along the lower row."),
        BoxDef::new("bilinear", "Bilinear value", None, tol::GREY)
            .nudge("Now between I₁ and I₂ by the fraction Δr."),
        BoxDef::new("bicubic", "Bicubic value", None, Tolerance::abs(0.05))
            .nudge("Cubic-convolution weights for the four columns and four rows of the 4×4 patch."),
    ]
}

/// The 2×2 neighbourhood and the fractions: `(p00, p10, p01, p11, dc, dr)`.
fn cell(i: &Record) -> (f64, f64, f64, f64, f64, f64) {
    let p = rows_of(i, "patch");
    let n = |k: &str| i.number(k).unwrap_or(f64::NAN);
    let (x, y) = (n("c") - n("first_c"), n("r") - n("first_r"));
    let (c, r) = (x.floor() as usize, y.floor() as usize);
    let g = |c: usize, r: usize| {
        p.get(r)
            .and_then(|row| row.get(c))
            .copied()
            .unwrap_or(f64::NAN)
    };
    (
        g(c, r),
        g(c + 1, r),
        g(c, r + 1),
        g(c + 1, r + 1),
        x - c as f64,
        y - r as f64,
    )
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve("resample", i)?;
    let (p00, p10, p01, p11, dc, dr) = cell(i);
    let i1 = or_given(g, "i1", p00 + dc * (p10 - p00));
    let i2 = or_given(g, "i2", p01 + dc * (p11 - p01));
    Ok(Record::new()
        .with("nearest", s.result.number("nearest").unwrap_or(f64::NAN))
        .with("i1", i1)
        .with("i2", i2)
        .with("bilinear", or_given(g, "bilinear", i1 + dr * (i2 - i1)))
        .with("bicubic", s.result.number("bicubic").unwrap_or(f64::NAN)))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let (p00, p10, p01, p11, dc, dr) = cell(i);
    const SWAP: &str = "The pixel the position is nearer to gets the larger weight: the left pixel's weight is 1 − Δc, the right one's Δc.";
    let i1 = p00 + (1.0 - dc) * (p10 - p00);
    let i2 = p01 + (1.0 - dc) * (p11 - p01);
    let keys = examples::solve("resample", &i.clone().with("cubic_a", -0.5))?;
    Ok(vec![
        Mistake::new(
            "nearest",
            "rounded down",
            "Nearest means rounding to the nearest pixel, not cutting the fraction off.",
            p00,
        ),
        Mistake::new("i1", "bilinear weights swapped", SWAP, i1),
        Mistake::new("i2", "bilinear weights swapped", SWAP, i2),
        Mistake::new(
            "bilinear",
            "bilinear weights swapped",
            SWAP,
            i1 + (1.0 - dr) * (i2 - i1),
        ),
        Mistake::new(
            "bilinear",
            "rows and columns swapped",
            "Δc moves along a row (between columns), Δr down a column.",
            {
                let j1 = p00 + dr * (p10 - p00);
                let j2 = p01 + dr * (p11 - p01);
                j1 + dc * (j2 - j1)
            },
        ),
        Mistake::new(
            "bicubic",
            "Keys' a = −0.5 instead of the seed's kernel",
            "Seed 004's kernel 1 − 2|x|² + |x|³ is cubic convolution with a = −1.",
            keys.result.number("bicubic").unwrap_or(f64::NAN),
        ),
    ])
}
