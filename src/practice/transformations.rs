//! Practice for seed 000, Example 4 and seed 004's Table 9.5.1: fiducial
//! transformations and 2-D transformations fitted to control points.

use super::correlation::rows_of;
use super::{mat, or_given, value_in, BoxDef, Mistake, Rng, Spec, Tolerance};
use crate::error::Result;
use crate::examples;
use crate::solution::Record;

pub fn specs() -> Vec<Spec> {
    vec![
        Spec {
            id: "fiducial-similarity",
            generate: gen_fiducials,
            boxes: |_| fiducial_boxes(false),
            chain: Some(|i, g| chain_sigma0("fiducial-similarity", i, g)),
            mistakes: |i| fiducial_mistakes("fiducial-similarity", i, 4),
        },
        Spec {
            id: "fiducial-affine",
            generate: gen_fiducials,
            boxes: |_| fiducial_boxes(true),
            chain: Some(|i, g| chain_sigma0("fiducial-affine", i, g)),
            mistakes: |i| fiducial_mistakes("fiducial-affine", i, 6),
        },
        Spec {
            id: "transform-fit",
            generate: gen_fit,
            boxes: boxes_fit,
            chain: Some(|i, g| chain_sigma0("transform-fit", i, g)),
            mistakes: mistakes_fit,
        },
    ]
}

/// Rounds to `d` decimals.
fn dec(x: f64, d: i32) -> f64 {
    let p = 10f64.powi(d);
    (x * p).round() / p
}

/// Four fiducials at the middle of the sides (as in Example 4): calibrated
/// x, y in mm, measured c, r in pixels from a scan at about 600 dpi, turned
/// by a fraction of a degree, with a few tenths of a pixel of noise.
fn gen_fiducials(rng: &mut Rng) -> Record {
    let a = rng.pick(&[106.0, 110.0, 113.0, 115.0]);
    let k = rng.num(2340, 2380) / 100.0; // pixels per mm
    let theta = (rng.num(-50, 50) / 100.0).to_radians();
    // The centre far enough in that every fiducial has a positive pixel
    // position (Example 4's lie about 48 px from the edges).
    let margin = (k * (a + 0.1)).ceil();
    let (cc, rc) = (margin + rng.num(30, 80), margin + rng.num(30, 80));
    let mut points = Vec::new();
    for (ux, uy) in [(-1.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
        let x = dec(a * ux + rng.num(-30, 30) / 1000.0, 3);
        let y = dec(a * uy + rng.num(-30, 30) / 1000.0, 3);
        let xp = k * (x * theta.cos() + y * theta.sin());
        let yp = k * (-x * theta.sin() + y * theta.cos());
        let c = dec(cc + xp + rng.num(-30, 30) / 100.0, 2);
        let r = dec(rc - yp + rng.num(-30, 30) / 100.0, 2);
        points.push(vec![c, r, x, y]);
    }
    Record::new().with("points", mat(&points))
}

/// Scale-like parameters to 0.01 %, translations to 0.01 mm.
const SCALE: Tolerance = Tolerance {
    atol: 1e-7,
    rtol: 1e-4,
};
const SHIFT: Tolerance = Tolerance::abs(0.01);

fn fiducial_boxes(affine: bool) -> Vec<BoxDef> {
    let names: &[(&str, bool)] = if affine {
        &[
            ("a", false),
            ("b", false),
            ("e", true),
            ("c", false),
            ("d", false),
            ("f", true),
        ]
    } else {
        &[("a", false), ("b", false), ("c", true), ("d", true)]
    };
    let mut b: Vec<BoxDef> = names
        .iter()
        .enumerate()
        .map(|(k, &(name, shift))| {
            let b = BoxDef::new(
                &format!("parameters[{}]", k + 1),
                &format!("Parameter {name}"),
                if shift { Some("mm") } else { None },
                if shift { SHIFT } else { SCALE },
            )
            .nudge("Write two equations per fiducial with x′ = c and y′ = −r, then solve the normal equations N·X = Aᵀ·L.");
            if shift {
                b.axis()
            } else {
                b
            }
        })
        .collect();
    b.push(
        BoxDef::new(
            "sigma0",
            "σ₀",
            Some("mm"),
            Tolerance {
                atol: 0.0005,
                rtol: 0.01,
            },
        )
        .nudge("√(VᵀV / redundancy), with V = A·X − L."),
    );
    b
}

fn fiducial_mistakes(id: &str, i: &Record, n: usize) -> Result<Vec<Mistake>> {
    let p = rows_of(i, "points");
    let flipped: Vec<Vec<f64>> = p.iter().map(|q| vec![q[0], -q[1], q[2], q[3]]).collect();
    let swapped: Vec<Vec<f64>> = p.iter().map(|q| vec![q[1], q[0], q[2], q[3]]).collect();
    let f = examples::solve(id, &i.clone().with("points", mat(&flipped)))?;
    let s = examples::solve(id, &i.clone().with("points", mat(&swapped)))?;
    let mut out = Vec::new();
    for k in 1..=n {
        let key = format!("parameters[{k}]");
        out.push(Mistake::new(
            &key,
            "y not flipped",
            "Rows count down and y counts up: use y′ = −r, not r.",
            value_in(&f, &key)?,
        ));
        out.push(Mistake::new(
            &key,
            "rows and columns swapped",
            "x′ is the column c, y′ comes from the row r.",
            value_in(&s, &key)?,
        ));
    }
    Ok(out)
}

/// Four to six control points with small whole-number source coordinates
/// and targets from a Helmert or affine transformation with round
/// parameters, plus a little noise.
fn gen_fit(rng: &mut Rng) -> Record {
    let model = if rng.coin() { "helmert" } else { "affine" };
    let n = rng.int(4, 6) as usize;
    // Corners of a box plus extra points: never all on a line.
    let (w, h) = (rng.num(4, 9), rng.num(4, 9));
    let mut uv = vec![(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)];
    while uv.len() < n {
        let p = (rng.num(1, w as i64 - 1), rng.num(1, h as i64 - 1));
        if !uv.contains(&p) {
            uv.push(p);
        } else {
            uv.push((p.0, h + uv.len() as f64));
        }
    }
    let (a, b) = (rng.num(50, 200) / 100.0, rng.num(-50, 50) / 100.0);
    let (c, d) = (rng.num(-20, 20), rng.num(-20, 20));
    let (e, f) = if model == "affine" {
        (rng.num(50, 200) / 100.0, rng.num(-50, 50) / 100.0)
    } else {
        (a, -b)
    };
    let points: Vec<Vec<f64>> = uv
        .iter()
        .map(|&(u, v)| {
            let x = a * u + b * v + c + rng.num(-2, 2) / 100.0;
            let y = f * u + e * v + d + rng.num(-2, 2) / 100.0;
            vec![u, v, dec(x, 2), dec(y, 2)]
        })
        .collect();
    Record::new()
        .with("model", model)
        .with("point_set", "table")
        .with("points", mat(&points))
}

fn is_affine(i: &Record) -> bool {
    matches!(i.get("model"), Some(crate::solution::Value::Text(t)) if t == "affine")
}

fn boxes_fit(i: &Record) -> Vec<BoxDef> {
    let names: &[&str] = if is_affine(i) {
        &["a", "b", "c", "d", "e", "f"]
    } else {
        &["a", "b", "c", "d"]
    };
    let t = Tolerance {
        atol: 0.002,
        rtol: 0.001,
    };
    let mut b: Vec<BoxDef> = names
        .iter()
        .enumerate()
        .map(|(k, name)| {
            BoxDef::new(
                &format!("parameters[{}]", k + 1),
                &format!("Parameter {name}"),
                None,
                t,
            )
            .nudge("Two equations per point; solve the normal equations (AᵀA)·X = AᵀL.")
        })
        .collect();
    b.push(
        BoxDef::new(
            "sigma0",
            "σ₀",
            None,
            Tolerance {
                atol: 0.001,
                rtol: 0.01,
            },
        )
        .nudge("√(VᵀV / redundancy), with V = A·X − L."),
    );
    b
}

/// A step's value `key`, alone in a record.
fn step_value(s: &crate::solution::Solution, key: &str) -> Record {
    s.steps
        .iter()
        .find_map(|st| st.values.get(key))
        .map(|v| Record::new().with(key, v.clone()))
        .unwrap_or_default()
}

/// σ₀ from the student's parameters: V = A·X − L with their X (A and L do
/// not depend on X: the fits are linear), over the redundancy.
fn chain_sigma0(id: &str, i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve(id, i)?;
    let a = rows_of(&step_value(&s, "A"), "A");
    let l = super::correlation::list(&step_value(&s, "L"), "L");
    let n = a.first().map_or(0, Vec::len);
    let mut out = Record::new();
    let mut x = Vec::new();
    for k in 1..=n {
        let key = format!("parameters[{k}]");
        let v = or_given(g, &key, value_in(&s, &key)?);
        x.push(v);
        out.set(&key, v);
    }
    let vv: f64 = a
        .iter()
        .zip(&l)
        .map(|(row, li)| (row.iter().zip(&x).map(|(p, q)| p * q).sum::<f64>() - li).powi(2))
        .sum();
    let redundancy = value_in(&s, "redundancy")?;
    out.set("sigma0", or_given(g, "sigma0", (vv / redundancy).sqrt()));
    Ok(out)
}

fn mistakes_fit(i: &Record) -> Result<Vec<Mistake>> {
    let p = rows_of(i, "points");
    let swapped: Vec<Vec<f64>> = p.iter().map(|q| vec![q[1], q[0], q[2], q[3]]).collect();
    let s = examples::solve("transform-fit", &i.clone().with("points", mat(&swapped)))?;
    let n = if is_affine(i) { 6 } else { 4 };
    let mut out = (1..=n)
        .map(|k| {
            let key = format!("parameters[{k}]");
            Ok(Mistake::new(
                &key,
                "u and v swapped",
                "The first source coordinate is u, the second v.",
                value_in(&s, &key)?,
            ))
        })
        .collect::<Result<Vec<_>>>()?;
    // σ₀ from VᵀV over the wrong count, or without the root
    let exact = examples::solve("transform-fit", i)?;
    let (sigma0, redundancy) = (value_in(&exact, "sigma0")?, value_in(&exact, "redundancy")?);
    let vtv = sigma0 * sigma0 * redundancy;
    let observations = 2.0 * p.len() as f64;
    out.extend([
        Mistake::new(
            "sigma0",
            "divided by the observations, not the redundancy",
            "σ₀² = VᵀV / r with r = observations − unknowns: the fitted parameters use up some of the observations.",
            (vtv / observations).sqrt(),
        ),
        Mistake::new(
            "sigma0",
            "square root forgotten",
            "VᵀV / r is σ₀²; σ₀ is its square root.",
            vtv / redundancy,
        ),
    ]);
    Ok(out)
}
