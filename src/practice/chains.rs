//! Practice for seed 000, Examples 17–18: chain codes, boundary length and
//! boundary shape.

use super::grade::tol;
use super::{mat, or_given, value_in, BoxDef, Mistake, Rng, Spec, Tolerance};
use crate::error::Result;
use crate::examples;
use crate::solution::{Record, Value};

pub fn specs() -> Vec<Spec> {
    vec![
        Spec {
            id: "chain-code",
            generate: gen_edge,
            boxes: boxes_code,
            chain: Some(chain_code),
            mistakes: mistakes_code,
        },
        Spec {
            id: "boundary-length",
            generate: gen_edge,
            boxes: boxes_length,
            chain: Some(chain_length),
            mistakes: mistakes_length,
        },
        Spec {
            id: "boundary-shape",
            generate: gen_region,
            boxes: boxes_shape,
            chain: Some(chain_shape),
            mistakes: mistakes_shape,
        },
    ]
}

/// Steps of the generated edges.
const STEPS: usize = 6;

/// 8-connectivity digits and their steps (c right, r down; 2 = north-east).
const DIRS: [(u8, i64, i64); 5] = [(1, 1, 0), (2, 1, -1), (3, 0, -1), (7, 0, 1), (8, 1, 1)];

/// An open edge that never crosses itself: it never steps left, and never
/// goes straight back up after going down (or down after up). One step is
/// diagonal and one vertical, so every kind of step is practised.
fn gen_edge(rng: &mut Rng) -> Record {
    let mut digits: Vec<u8> = Vec::new();
    let diag = rng.int(0, STEPS as i64 - 1) as usize;
    let vert = (diag + rng.int(1, STEPS as i64 - 1) as usize) % STEPS;
    for k in 0..STEPS {
        let prev = digits.last().copied();
        let choices: Vec<u8> = DIRS
            .iter()
            .map(|d| d.0)
            .filter(|&d| {
                let ok_kind = if k == diag {
                    d == 2 || d == 8
                } else if k == vert {
                    d == 3 || d == 7
                } else {
                    true
                };
                ok_kind && !matches!((prev, d), (Some(3), 7) | (Some(7), 3))
            })
            .collect();
        digits.push(rng.pick(&choices));
    }
    let (mut c, mut r) = (rng.num(2, 9), rng.num(6, 12));
    let mut pixels = vec![vec![c, r]];
    for d in &digits {
        let (_, dc, dr) = DIRS
            .iter()
            .copied()
            .find(|x| x.0 == *d)
            .unwrap_or((1, 1, 0));
        c += dc as f64;
        r += dr as f64;
        pixels.push(vec![c, r]);
    }
    Record::new()
        .with("given", "pixels")
        .with("pixels", mat(&pixels))
}

fn boxes_code(_: &Record) -> Vec<BoxDef> {
    let mut b: Vec<BoxDef> = (1..=STEPS)
        .map(|k| {
            BoxDef::new(&format!("code[{k}]"), &format!("Code digit {k}"), None, tol::WHOLE)
                .nudge("1 = east, counted counter-clockwise: 2 north-east, 3 north … 8 south-east. Rows count down, so north is r − 1.")
        })
        .collect();
    for k in 1..STEPS {
        b.push(
            BoxDef::new(
                &format!("differential[{k}]"),
                &format!("Differential digit {k}"),
                None,
                tol::WHOLE,
            )
            .nudge("Each digit minus the one before; add 8 when it is negative."),
        );
    }
    b
}

fn chain_code(i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve("chain-code", i)?;
    let mut out = Record::new();
    let mut code = Vec::new();
    for k in 1..=STEPS {
        let key = format!("code[{k}]");
        let d = or_given(g, &key, value_in(&s, &key)?);
        code.push(d);
        out.set(&key, d);
    }
    for k in 1..STEPS {
        out.set(
            &format!("differential[{k}]"),
            (code[k] - code[k - 1]).rem_euclid(8.0),
        );
    }
    Ok(out)
}

fn mistakes_code(i: &Record) -> Result<Vec<Mistake>> {
    let v = chain_code(i, &Record::new())?;
    let digit = |k: usize| v.number(&format!("code[{k}]")).unwrap_or(f64::NAN);
    let mut out = Vec::new();
    for k in 1..=STEPS {
        let d = digit(k);
        out.push(Mistake::new(
            &format!("code[{k}]"),
            "y not flipped",
            "Rows count down: a step to r − 1 goes north (2 or 3), to r + 1 south (7 or 8).",
            (9.0 - d).rem_euclid(8.0) + 1.0,
        ));
        // 4-connectivity numbering: 1 east, 2 north, 3 west, 4 south.
        let four = match d as u8 {
            3 => Some(2.0),
            7 => Some(4.0),
            _ => None,
        };
        if let Some(f) = four {
            out.push(Mistake::new(
                &format!("code[{k}]"),
                "4- vs 8-connectivity",
                "With 8 directions north is 3 and south 7; 2 and 4 are the 4-connectivity numbers.",
                f,
            ));
        }
    }
    for k in 1..STEPS {
        out.push(Mistake::new(
            &format!("differential[{k}]"),
            "subtracted the wrong way round",
            "The differential digit is this digit minus the one before, not the other way.",
            (digit(k) - digit(k + 1)).rem_euclid(8.0),
        ));
    }
    Ok(out)
}

fn boxes_length(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("horizontal", "Horizontal steps", None, tol::WHOLE)
            .nudge("Steps straight left or right: codes 1 and 5."),
        BoxDef::new("vertical", "Vertical steps", None, tol::WHOLE)
            .nudge("Steps straight up or down: codes 3 and 7."),
        BoxDef::new("diagonal", "Diagonal steps", None, tol::WHOLE)
            .nudge("The even codes: 2, 4, 6, 8."),
        BoxDef::new("length", "Length", Some("px"), Tolerance::abs(0.005))
            .nudge("Straight steps count 1, diagonal ones √2."),
    ]
}

fn chain_length(i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve("boundary-length", i)?;
    let h = or_given(g, "horizontal", value_in(&s, "horizontal")?);
    let v = or_given(g, "vertical", value_in(&s, "vertical")?);
    let d = or_given(g, "diagonal", value_in(&s, "diagonal")?);
    Ok(Record::new()
        .with("horizontal", h)
        .with("vertical", v)
        .with("diagonal", d)
        .with("length", h + v + std::f64::consts::SQRT_2 * d))
}

fn mistakes_length(i: &Record) -> Result<Vec<Mistake>> {
    let v = chain_length(i, &Record::new())?;
    let n = |k: &str| v.number(k).unwrap_or(f64::NAN);
    let (h, vv, d) = (n("horizontal"), n("vertical"), n("diagonal"));
    Ok(vec![
        Mistake::new(
            "length",
            "diagonal steps counted as 1",
            "A diagonal step is √2 pixel spacings long.",
            h + vv + d,
        ),
        Mistake::new(
            "length",
            "4- vs 8-connectivity",
            "With 8-connectivity a diagonal is one step of √2; 4-connectivity would walk it as two steps.",
            h + vv + 2.0 * d,
        ),
    ])
}

/// A region: a w × h block of pixels with its four corner pixels cut off,
/// somewhere on a small grid.
fn gen_region(rng: &mut Rng) -> Record {
    let w = rng.int(4, 8);
    let mut h = rng.int(3, 6);
    if h == w {
        h -= 1;
    }
    let (c0, r0) = (rng.int(1, 6), rng.int(1, 6));
    let mut pixels = Vec::new();
    for r in 0..h {
        for c in 0..w {
            let corner = (c == 0 || c == w - 1) && (r == 0 || r == h - 1);
            if !corner || rng.int(0, 3) == 0 {
                pixels.push(vec![(c0 + c) as f64, (r0 + r) as f64]);
            }
        }
    }
    Record::new().with("pixels", mat(&pixels))
}

fn boxes_shape(_: &Record) -> Vec<BoxDef> {
    let t = Tolerance::abs(0.005);
    vec![
        BoxDef::new("diameter", "Diameter", Some("px"), t)
            .nudge("The largest distance between two boundary pixels: √(Δc² + Δr²)."),
        BoxDef::new("minor_axis_length", "Minor axis length", Some("px"), t)
            .nudge("The extent of the boundary perpendicular to the major axis."),
        BoxDef::new("eccentricity", "Eccentricity", None, Tolerance::abs(0.005))
            .nudge("Major axis (the diameter) over minor axis."),
    ]
}

fn chain_shape(i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve("boundary-shape", i)?;
    let d = or_given(g, "diameter", value_in(&s, "diameter")?);
    let m = or_given(g, "minor_axis_length", value_in(&s, "minor_axis_length")?);
    Ok(Record::new()
        .with("diameter", d)
        .with("minor_axis_length", m)
        .with("eccentricity", d / m))
}

fn mistakes_shape(i: &Record) -> Result<Vec<Mistake>> {
    let s = examples::solve("boundary-shape", i)?;
    let (d, m) = (
        value_in(&s, "diameter")?,
        value_in(&s, "minor_axis_length")?,
    );
    // the major axis' ends: Δc and Δr between them
    let ends = match s.result.get("major_axis") {
        Some(Value::List(ends)) => ends
            .iter()
            .map(|e| match e {
                Value::List(xy) => xy.iter().map(|x| x.as_f64().unwrap_or(f64::NAN)).collect(),
                _ => vec![f64::NAN, f64::NAN],
            })
            .collect::<Vec<Vec<f64>>>(),
        _ => Vec::new(),
    };
    let (dc, dr) = match ends.as_slice() {
        [a, b] if a.len() == 2 && b.len() == 2 => ((b[0] - a[0]).abs(), (b[1] - a[1]).abs()),
        _ => (f64::NAN, f64::NAN),
    };
    Ok(vec![
        Mistake::new(
            "eccentricity",
            "minor over major",
            "The seed's eccentricity is the major axis over the minor one (≥ 1).",
            m / d,
        ),
        Mistake::new(
            "diameter",
            "city-block distance",
            "The diameter is the straight-line distance √(Δc² + Δr²), not the steps |Δc| + |Δr| along the grid.",
            dc + dr,
        ),
        Mistake::new(
            "diameter",
            "square root forgotten",
            "Δc² + Δr² is the squared distance; the diameter is its square root.",
            dc * dc + dr * dr,
        ),
    ])
}
