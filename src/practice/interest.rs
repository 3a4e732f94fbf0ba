//! Practice for seed 000, Examples 13–14 and seed 003: the Förstner and
//! Moravec interest operators.

use super::correlation::rows_of;
use super::grade::tol;
use super::{mat, or_given, value_in, BoxDef, Mistake, Rng, Spec, Tolerance};
use crate::error::Result;
use crate::examples;
use crate::solution::{Record, Solution};

pub fn specs() -> Vec<Spec> {
    vec![
        Spec {
            id: "forstner-window",
            generate: gen_forstner,
            boxes: boxes_forstner,
            chain: Some(|i, g| chain_forstner("forstner-window", i, g)),
            mistakes: |i| forstner_mistakes(&examples::solve("forstner-window", i)?),
        },
        Spec {
            id: "moravec-window",
            generate: gen_moravec,
            boxes: boxes_moravec,
            chain: Some(chain_moravec),
            mistakes: mistakes_moravec,
        },
        Spec {
            id: "forstner-image",
            generate: gen_image,
            // The pattern's steps are large: det N runs to 10⁸, so no box for it.
            boxes: |i| {
                boxes_forstner(i)
                    .into_iter()
                    .filter(|b| b.key != "det_n")
                    .collect()
            },
            chain: Some(|i, g| chain_forstner("forstner-image", i, g)),
            mistakes: |i| {
                let all = forstner_mistakes(&examples::solve("forstner-image", i)?)?;
                Ok(all.into_iter().filter(|m| m.key != "det_n").collect())
            },
        },
    ]
}

/// A 5×5 window with a corner: a brighter quadrant (its corner at an
/// interior pixel, a random one of the four orientations) plus noise.
fn gen_forstner(rng: &mut Rng) -> Record {
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
    Record::new().with("window", mat(&w))
}

fn boxes_forstner(_: &Record) -> Vec<BoxDef> {
    let sum = tol::SUM;
    vec![
        BoxDef::new("n[1,1]", "N₁₁ = Σ gx²", None, sum)
            .nudge("gx = (g(c+1) − g(c−1)) / 2 at each interior pixel; square and add."),
        BoxDef::new("n[1,2]", "N₁₂ = Σ gx·gy", None, sum)
            .nudge("gy = (g(r+1) − g(r−1)) / 2; multiply gx and gy pixel by pixel and add.")
            .sign_flip("The size is right but the sign is not: gx is the next column minus the previous one, gy the next row minus the previous one."),
        BoxDef::new("n[2,2]", "N₂₂ = Σ gy²", None, sum).nudge("Square gy and add."),
        BoxDef::new(
            "det_n",
            "det N",
            None,
            Tolerance {
                atol: 0.5,
                rtol: 0.001,
            },
        )
        .nudge("N₁₁·N₂₂ − N₁₂²."),
        BoxDef::new(
            "w",
            "Weight w = 1 / tr(N⁻¹)",
            None,
            Tolerance {
                atol: 0.01,
                rtol: 0.001,
            },
        )
        .nudge("tr(N⁻¹) = tr N / det N, so w = det N / tr N."),
        BoxDef::new("q", "Roundness q", None, Tolerance::abs(0.001))
            .nudge("q = 4 det N / (tr N)²: 1 for a round error ellipse."),
        BoxDef::new(
            "weak_angle_deg",
            "Direction of the weak axis",
            Some("°"),
            Tolerance::abs(0.1),
        )
        .nudge("The strong direction is ½·atan2(2N₁₂, N₁₁ − N₂₂); the weak one is 90° on."),
    ]
}

/// The later boxes from the student's N (and det N, where it has a box).
fn chain_forstner(id: &str, i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve(id, i)?;
    let a = or_given(g, "n[1,1]", value_in(&s, "n[1,1]")?);
    let b = or_given(g, "n[1,2]", value_in(&s, "n[1,2]")?);
    let d = or_given(g, "n[2,2]", value_in(&s, "n[2,2]")?);
    let det = or_given(g, "det_n", a * d - b * b);
    let trace = a + d;
    let strong = 0.5 * (2.0 * b).atan2(a - d);
    Ok(Record::new()
        .with("n[1,1]", a)
        .with("n[1,2]", b)
        .with("n[2,2]", d)
        .with("det_n", det)
        .with("w", or_given(g, "w", det / trace))
        .with("q", 4.0 * det / (trace * trace))
        .with(
            "weak_angle_deg",
            (strong + std::f64::consts::FRAC_PI_2).to_degrees(),
        ))
}

fn forstner_mistakes(s: &Solution) -> Result<Vec<Mistake>> {
    let v = |k: &str| value_in(s, k);
    let (a, b, d) = (v("n[1,1]")?, v("n[1,2]")?, v("n[2,2]")?);
    const HALF: &str = "The central difference is (g(c+1) − g(c−1)) / 2: without the ½ every product is 4 times too big.";
    const SWAP: &str = "gx runs along a row (columns c), gy down a column (rows r).";
    Ok(vec![
        Mistake::new("n[1,1]", "½ forgotten in the gradient", HALF, 4.0 * a),
        Mistake::new("n[1,2]", "½ forgotten in the gradient", HALF, 4.0 * b),
        Mistake::new("n[2,2]", "½ forgotten in the gradient", HALF, 4.0 * d),
        Mistake::new("n[1,1]", "rows and columns swapped", SWAP, d),
        Mistake::new("n[2,2]", "rows and columns swapped", SWAP, a),
        Mistake::new(
            "det_n",
            "plus instead of minus",
            "det N = N₁₁·N₂₂ − N₁₂².",
            a * d + b * b,
        ),
        Mistake::new(
            "w",
            "tr(N⁻¹) instead of its inverse",
            "w is one over the trace of N⁻¹: det N / tr N.",
            v("trace_n_inverse").unwrap_or(f64::NAN),
        ),
        Mistake::new("w", "½ forgotten in the gradient", HALF, 4.0 * v("w")?),
        Mistake::new(
            "q",
            "the 4 left out",
            "q = 4 det N / (tr N)², so that a round ellipse gives 1.",
            v("q")? / 4.0,
        ),
        Mistake::new(
            "weak_angle_deg",
            "degrees vs radians",
            "That is the angle in radians; the box asks for degrees (× 180/π).",
            v("weak_angle_deg")?.to_radians(),
        ),
    ])
}

fn gen_moravec(rng: &mut Rng) -> Record {
    let w: Vec<Vec<f64>> = (0..4)
        .map(|_| (0..4).map(|_| rng.num(5, 30)).collect())
        .collect();
    Record::new().with("window", mat(&w))
}

const MORAVEC: [(usize, usize); 4] = [(1, 1), (1, 2), (2, 1), (2, 2)];

fn boxes_moravec(_: &Record) -> Vec<BoxDef> {
    let mut b: Vec<BoxDef> = MORAVEC
        .iter()
        .map(|&(r, c)| {
            BoxDef::new(
                &format!("sums[{r},{c}]"),
                &format!("Sum at interior row {r}, column {c}"),
                None,
                tol::WHOLE,
            )
            .nudge("Four differences across the pixel (left–right, up–down, both diagonals), each squared, added.")
        })
        .collect();
    b.push(
        BoxDef::new("mean", "Mean of the sums", None, tol::GREY)
            .nudge("Add the interior sums and divide by how many there are."),
    );
    b
}

fn chain_moravec(i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve("moravec-window", i)?;
    let mut out = Record::new();
    let mut total = 0.0;
    for &(r, c) in &MORAVEC {
        let key = format!("sums[{r},{c}]");
        let x = or_given(g, &key, value_in(&s, &key)?);
        total += x;
        out.set(&key, x);
    }
    out.set("mean", total / MORAVEC.len() as f64);
    Ok(out)
}

fn mistakes_moravec(i: &Record) -> Result<Vec<Mistake>> {
    let w = rows_of(i, "window");
    let g = |c: usize, r: usize| {
        w.get(r)
            .and_then(|row| row.get(c))
            .copied()
            .unwrap_or(f64::NAN)
    };
    let s = examples::solve("moravec-window", i)?;
    let mut out = Vec::new();
    for &(r, c) in &MORAVEC {
        let key = format!("sums[{r},{c}]");
        let abs: f64 = [
            g(c + 1, r) - g(c - 1, r),
            g(c, r + 1) - g(c, r - 1),
            g(c + 1, r + 1) - g(c - 1, r - 1),
            g(c - 1, r + 1) - g(c + 1, r - 1),
        ]
        .iter()
        .map(|d| d.abs())
        .sum();
        out.push(Mistake::new(
            &key,
            "differences not squared",
            "Moravec adds the squares of the four differences.",
            abs,
        ));
        out.push(Mistake::new(
            &key,
            "rows and columns swapped",
            "Row r counts down, column c to the right.",
            value_in(&s, &format!("sums[{c},{r}]"))?,
        ));
    }
    Ok(out)
}

/// Places on the test pattern with a corner or an X-corner (1-based
/// centres), as seed 003 suggests looking at.
const PLACES: [(i64, i64); 8] = [
    (9, 9),
    (24, 9),
    (9, 24),
    (24, 24),
    (47, 47),
    (37, 47),
    (47, 37),
    (47, 29),
];

fn gen_image(rng: &mut Rng) -> Record {
    let (c, r) = rng.pick(&PLACES);
    Record::new()
        // Up to one pixel up or left: every such window holds the corner
        // (one pixel down or right of some places it holds only an edge).
        .with("c", (c + rng.int(-1, 0)) as f64)
        .with("r", (r + rng.int(-1, 0)) as f64)
        .with("window_size", rng.pick(&[5.0, 7.0]))
        .with("noise", rng.num(0, 4))
}
