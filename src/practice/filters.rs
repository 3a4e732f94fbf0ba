//! Practice for seed 000, Examples 15–16 and seed 004: a kernel applied to
//! a window, and edge operators.

use crate::examples::drill::{rows_of, transpose};
use super::grade::tol;
use super::{mat, or_given, pick, value_in, BoxDef, Mistake, Rng, Spec};
use crate::error::Result;
use crate::examples;
use crate::solution::Record;

pub fn specs() -> Vec<Spec> {
    vec![
        Spec {
            id: "filter-window",
            generate: gen_filter,
            boxes: boxes_filter,
            chain: Some(chain_filter),
            mistakes: mistakes_filter,
        },
        Spec {
            id: "edge-window",
            generate: gen_edge,
            boxes: boxes_edge,
            chain: Some(chain_edge),
            mistakes: mistakes_edge,
        },
    ]
}

/// Kernels with their divisor (custom kernels divide by 1).
const KERNELS: [(&str, f64); 6] = [
    ("mean", 9.0),
    ("weighted-mean", 10.0),
    ("gaussian-3", 16.0),
    ("laplacian-8", 1.0),
    ("sharpen", 9.0),
    ("custom", 1.0),
];

/// Directional kernels: flipping them changes the result, so the
/// convolution-vs-correlation mistake shows.
const CUSTOM: [[[f64; 3]; 3]; 4] = [
    [[-2.0, -1.0, 0.0], [-1.0, 1.0, 1.0], [0.0, 1.0, 2.0]],
    [[1.0, 2.0, 1.0], [0.0, 0.0, 0.0], [-1.0, -2.0, -1.0]],
    [[0.0, 1.0, 2.0], [-1.0, 0.0, 1.0], [-2.0, -1.0, 0.0]],
    [[1.0, 0.0, -1.0], [2.0, 0.0, -2.0], [1.0, 0.0, -1.0]],
];

/// A 5×5 window of grey values (about 10–60, 0–75 with a steep slope) with
/// an edge and some texture: no 3×3 neighbourhood is flat.
fn window(rng: &mut Rng) -> Vec<Vec<f64>> {
    let (gc, gr) = (rng.num(-6, 6), rng.num(-6, 6));
    let (gc, gr) = (
        if gc == 0.0 { 4.0 } else { gc },
        if gr == 0.0 { -3.0 } else { gr },
    );
    let noise: Vec<Vec<f64>> = (0..5)
        .map(|_| (0..5).map(|_| rng.num(-4, 4)).collect())
        .collect();
    let ramp = |gc: f64| -> Vec<Vec<f64>> {
        (0..5)
            .map(|r| {
                (0..5)
                    .map(|c| {
                        (35.0 + gc * (c as f64 - 2.0) + gr * (r as f64 - 2.0) + noise[r][c])
                            .clamp(0.0, 99.0)
                    })
                    .collect()
            })
            .collect()
    };
    let w = ramp(gc);
    // Now and then the noise cancels a gentle slope and leaves a 3×3
    // neighbourhood flat (about one window in 10 000). Such a window gets a
    // steeper slope: |gc| ≥ 6 spans 12 grey levels over three columns, which
    // noise of ± 4 cannot bring below 4.
    if flat_neighbourhood(&w) {
        ramp(gc + 5.0 * gc.signum())
    } else {
        w
    }
}

/// Whether some interior pixel's 3×3 neighbourhood spans less than 3 grey levels.
fn flat_neighbourhood(w: &[Vec<f64>]) -> bool {
    (1..w.len().saturating_sub(1)).any(|r| {
        (1..w[r].len().saturating_sub(1)).any(|c| {
            let n = || (r - 1..=r + 1).flat_map(|y| w[y][c - 1..=c + 1].iter().copied());
            n().fold(f64::MIN, f64::max) - n().fold(f64::MAX, f64::min) < 3.0
        })
    })
}

fn gen_filter(rng: &mut Rng) -> Record {
    let (kernel, _) = rng.pick(&KERNELS);
    let mut r = Record::new()
        .with("window", mat(&window(rng)))
        .with("kernel", kernel);
    if kernel == "custom" {
        let k = rng.pick(&CUSTOM);
        r.set(
            "custom_kernel",
            mat(&k.iter().map(|row| row.to_vec()).collect::<Vec<_>>()),
        );
    }
    r
}

/// The output pixels asked for (row, column within the 3×3 output).
const FILTER_BOXES: [(usize, usize); 3] = [(1, 1), (2, 2), (3, 2)];

fn boxes_filter(_: &Record) -> Vec<BoxDef> {
    let first = BoxDef::new(
        "numerator_sum",
        "Sum of numerator × grey value at row 1, column 1 (before dividing)",
        None,
        tol::GREY,
    )
    .nudge("The kernel's numerators (its weights times the divisor) on the 3×3 neighbourhood of window pixel (2, 2): multiply each pair and add. Applied as written: no flip.");
    std::iter::once(first)
        .chain(FILTER_BOXES
        .iter()
        .map(|&(r, c)| {
            BoxDef::new(
                &format!("output[{r},{c}]"),
                &format!("Output at row {r}, column {c} of the 3×3 result"),
                None,
                tol::GREY,
            )
            .nudge("Lay the kernel on the window with its centre on the pixel, multiply each pair, add, divide by the kernel's divisor. Applied as written: no flip.")
        }))
        .collect()
}

/// The first output pixel from the student's sum of numerators.
fn chain_filter(i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve("filter-window", i)?;
    let sum = or_given(g, "numerator_sum", value_in(&s, "numerator_sum")?);
    let divisor = value_in(&s, "divisor")?;
    let mut out = Record::new()
        .with("numerator_sum", sum)
        .with("output[1,1]", or_given(g, "output[1,1]", sum / divisor));
    for &(r, c) in &FILTER_BOXES[1..] {
        let key = format!("output[{r},{c}]");
        out.set(&key, value_in(&s, &key)?);
    }
    Ok(out)
}

fn output(i: &Record, r: usize, c: usize) -> Result<f64> {
    value_in(
        &examples::solve("filter-window", i)?,
        &format!("output[{r},{c}]"),
    )
}

fn mistakes_filter(i: &Record) -> Result<Vec<Mistake>> {
    let s = examples::solve("filter-window", i)?;
    let kernel = i.get("kernel").and_then(|v| match v {
        crate::solution::Value::Text(t) => Some(t.clone()),
        _ => None,
    });
    let divisor = KERNELS
        .iter()
        .find(|(k, _)| Some(k.to_string()) == kernel)
        .map_or(1.0, |k| k.1);
    let flipped = if kernel.as_deref() == Some("custom") {
        let k = rows_of(i, "custom_kernel");
        let f: Vec<Vec<f64>> = k
            .iter()
            .rev()
            .map(|row| row.iter().rev().copied().collect())
            .collect();
        Some(i.clone().with("custom_kernel", mat(&f)))
    } else {
        None
    };
    let mut out = Vec::new();
    if let Some(f) = &flipped {
        out.push(Mistake::new(
            "numerator_sum",
            "kernel flipped",
            "The seeds apply the kernel as written (correlation); flipping it first is convolution.",
            value_in(&examples::solve("filter-window", f)?, "numerator_sum")?,
        ));
    }
    if divisor != 1.0 {
        out.push(Mistake::new(
            "numerator_sum",
            "divided already",
            "This box asks for the sum before dividing by the divisor.",
            value_in(&s, "numerator_sum")? / divisor,
        ));
    }
    for &(r, c) in &FILTER_BOXES {
        let key = format!("output[{r},{c}]");
        let x = value_in(&s, &key)?;
        if let Some(f) = &flipped {
            out.push(Mistake::new(
                &key,
                "kernel flipped",
                "The seeds apply the kernel as written (correlation); flipping it first is convolution.",
                output(f, r, c)?,
            ));
        }
        if divisor != 1.0 {
            out.push(Mistake::new(
                &key,
                "divisor forgotten",
                "The kernel's weights are the numerators over the divisor: divide the sum.",
                x * divisor,
            ));
        }
        out.push(Mistake::new(
            &key,
            "rows and columns swapped",
            "Row r counts down, column c to the right: this is the pixel at row c, column r.",
            value_in(&s, &format!("output[{c},{r}]"))?,
        ));
    }
    Ok(out)
}

fn gen_edge(rng: &mut Rng) -> Record {
    Record::new()
        .with("window", mat(&window(rng)))
        .with("operator", if rng.coin() { "prewitt" } else { "sobel" })
}

/// The sign flip of a gradient: the kernel mirrored.
const KERNEL_FLIP: &str = "The size is right but the sign is not: apply the kernel as written, its positive side where it is printed.";

fn boxes_edge(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("gx[2,2]", "Gx at the centre", None, tol::GREY)
            .nudge("The seed's x kernel: top row minus bottom row, applied as written.")
            .sign_flip(KERNEL_FLIP),
        BoxDef::new("gy[2,2]", "Gy at the centre", None, tol::GREY)
            .nudge("The y kernel: right column minus left column.")
            .sign_flip(KERNEL_FLIP),
        BoxDef::new(
            "magnitude[2,2]",
            "Edge magnitude at the centre",
            None,
            tol::GREY,
        )
        .nudge("√(Gx² + Gy²)."),
    ]
}

fn chain_edge(i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve("edge-window", i)?;
    let gx = or_given(g, "gx[2,2]", value_in(&s, "gx[2,2]")?);
    let gy = or_given(g, "gy[2,2]", value_in(&s, "gy[2,2]")?);
    Ok(Record::new()
        .with("gx[2,2]", gx)
        .with("gy[2,2]", gy)
        .with("magnitude[2,2]", gx.hypot(gy)))
}

fn mistakes_edge(i: &Record) -> Result<Vec<Mistake>> {
    let s = examples::solve("edge-window", i)?;
    let (gx, gy) = (value_in(&s, "gx[2,2]")?, value_in(&s, "gy[2,2]")?);
    const SWAP: &str =
        "The seed's Gx kernel differences top and bottom rows; Gy the right and left columns.";
    let t = examples::solve(
        "edge-window",
        &i.clone()
            .with("window", mat(&transpose(&rows_of(i, "window")))),
    )?;
    let tx = t
        .result
        .get("gx")
        .and_then(|v| pick(v, &[2, 2]))
        .unwrap_or(f64::NAN);
    Ok(vec![
        Mistake::new("gx[2,2]", "x and y swapped", SWAP, gy),
        Mistake::new("gy[2,2]", "x and y swapped", SWAP, gx),
        Mistake::new(
            "gx[2,2]",
            "rows and columns swapped",
            "The window's rows run down, its columns to the right.",
            tx,
        ),
        Mistake::new(
            "magnitude[2,2]",
            "|Gx| + |Gy| instead of the root",
            "The magnitude is the length of the gradient vector: √(Gx² + Gy²).",
            gx.abs() + gy.abs(),
        ),
    ])
}
