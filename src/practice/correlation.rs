//! Practice for seed 000, Examples 5–9: normalized cross-correlation in 1-D
//! and 2-D, the correlation surface and subpixel peaks.

use super::grade::tol;
use super::{mat, nums, or_given, BoxDef, Mistake, Rng, Spec, Tolerance};
use crate::error::{Error, Result};
use crate::examples;
use crate::solution::Record;

pub fn specs() -> Vec<Spec> {
    vec![
        Spec {
            id: "ncc-1d",
            generate: gen_ncc_1d,
            boxes: boxes_ncc_1d,
            chain: Some(chain_ncc_1d),
            mistakes: mistakes_ncc_1d,
        },
        Spec {
            id: "ncc-2d",
            generate: gen_ncc_2d,
            boxes: boxes_ncc_2d,
            chain: Some(chain_ncc_2d),
            mistakes: mistakes_ncc_2d,
        },
        Spec {
            id: "ncc-surface",
            generate: gen_surface,
            boxes: boxes_surface,
            chain: Some(chain_surface),
            mistakes: mistakes_surface,
        },
        Spec {
            id: "subpixel-1d",
            generate: gen_sub_1d,
            boxes: boxes_sub_1d,
            chain: Some(chain_sub_1d),
            mistakes: mistakes_sub_1d,
        },
        Spec {
            id: "subpixel-2d",
            generate: gen_sub_2d,
            boxes: boxes_sub_2d,
            chain: Some(chain_sub_2d),
            mistakes: mistakes_sub_2d,
        },
    ]
}

/// Template length and number of sub-windows of the 1-D variants.
const N_T: usize = 7;
const WINDOWS: usize = 5;

/// Grey values 0–9 in which no two neighbours are equal: every window of
/// two or more values has texture.
pub(crate) fn textured(rng: &mut Rng, n: usize) -> Vec<f64> {
    let mut v = vec![rng.num(0, 9)];
    for i in 1..n {
        v.push(((v[i - 1] as i64 + rng.int(1, 9)) % 10) as f64);
    }
    v
}

pub(crate) fn list(inputs: &Record, key: &str) -> Vec<f64> {
    match inputs.get(key) {
        Some(crate::solution::Value::List(xs)) => xs.iter().filter_map(|x| x.as_f64()).collect(),
        _ => Vec::new(),
    }
}

pub(crate) fn rows_of(inputs: &Record, key: &str) -> Vec<Vec<f64>> {
    match inputs.get(key) {
        Some(crate::solution::Value::List(rs)) => rs
            .iter()
            .map(|r| match r {
                crate::solution::Value::List(xs) => xs.iter().filter_map(|x| x.as_f64()).collect(),
                _ => Vec::new(),
            })
            .collect(),
        _ => Vec::new(),
    }
}

fn mean(xs: &[f64]) -> f64 {
    xs.iter().sum::<f64>() / xs.len().max(1) as f64
}

/// ρ of two equally long lists, with the first list's mean given.
fn rho_with(a: &[f64], ma: f64, b: &[f64]) -> f64 {
    let mb = mean(b);
    let (mut ab, mut aa, mut bb) = (0.0, 0.0, 0.0);
    for (x, y) in a.iter().zip(b) {
        ab += (x - ma) * (y - mb);
        aa += (x - ma) * (x - ma);
        bb += (y - mb) * (y - mb);
    }
    ab / (aa * bb).sqrt()
}

/// ρ without the means subtracted: the mistake.
pub(crate) fn rho_raw(a: &[f64], b: &[f64]) -> f64 {
    let (mut ab, mut aa, mut bb) = (0.0, 0.0, 0.0);
    for (x, y) in a.iter().zip(b) {
        ab += x * y;
        aa += x * x;
        bb += y * y;
    }
    ab / (aa * bb).sqrt()
}

/// A bump like the seed's template (1 2 9 9 8 2 1): distinct values rising
/// to a peak and falling, so no shifted copy of it looks like it.
fn bump(rng: &mut Rng) -> Vec<f64> {
    let mut pool: Vec<f64> = (0..10).map(f64::from).collect();
    let mut v = Vec::new();
    for _ in 0..N_T {
        let k = rng.int(0, pool.len() as i64 - 1) as usize;
        v.push(pool.remove(k));
    }
    let peak = rng.int(2, N_T as i64 - 3) as usize;
    v.sort_by(|a, b| a.total_cmp(b));
    // Every other value goes up the left flank, the rest down the right.
    let top = v.pop().unwrap_or(9.0);
    let (mut left, mut right) = (Vec::new(), Vec::new());
    for (i, x) in v.into_iter().enumerate() {
        if (i % 2 == 0 && left.len() < peak) || right.len() >= N_T - 1 - peak {
            left.push(x);
        } else {
            right.push(x);
        }
    }
    right.reverse();
    left.push(top);
    left.extend(right);
    left
}

fn gen_ncc_1d(rng: &mut Rng) -> Record {
    let t = bump(rng);
    let mut s = textured(rng, N_T + WINDOWS - 1);
    // The template, brightened, at a random place: the best match (ρ = 1,
    // as brightness does not change ρ).
    let at = rng.int(0, WINDOWS as i64 - 1) as usize;
    let gain = rng.num(0, 3);
    for (k, v) in t.iter().enumerate() {
        s[at + k] = v + gain;
    }
    Record::new()
        .with("template", nums(&t))
        .with("search", nums(&s))
}

/// The sign flip of ρ (and of Σ ΔA·ΔB, which gives ρ its sign).
const RHO_FLIP: &str = "The size is right but the sign is not: take both deviations the same way round, each value minus its own mean.";

fn boxes_ncc_1d(_: &Record) -> Vec<BoxDef> {
    let mut b = vec![
        BoxDef::new("mean_template", "Template mean Ā", None, tol::GREY)
            .nudge("Add the template's grey values and divide by how many there are."),
    ];
    for k in 1..=WINDOWS {
        b.push(
            BoxDef::new(&format!("rho[{k}]"), &format!("ρ at sub-window {k}"), None, tol::RHO)
                .nudge("Subtract each mean, then: sum of products over the root of the product of the sums of squares.")
                .sign_flip(RHO_FLIP),
        );
    }
    b.push(
        BoxDef::new("best", "Best sub-window (from 1)", None, tol::WHOLE)
            .nudge("The sub-window with the largest ρ."),
    );
    b
}

fn chain_ncc_1d(i: &Record, g: &Record) -> Result<Record> {
    let (t, s) = (list(i, "template"), list(i, "search"));
    let ma = or_given(g, "mean_template", mean(&t));
    let mut out = Record::new().with("mean_template", ma);
    let mut best = (0usize, f64::NEG_INFINITY);
    for k in 1..=WINDOWS {
        let key = format!("rho[{k}]");
        let w = s.get(k - 1..k - 1 + t.len()).unwrap_or(&[]);
        let rho = or_given(g, &key, rho_with(&t, ma, w));
        if rho > best.1 {
            best = (k, rho);
        }
        out.set(&key, rho);
    }
    out.set("best", or_given(g, "best", best.0 as f64));
    Ok(out)
}

fn mistakes_ncc_1d(i: &Record) -> Result<Vec<Mistake>> {
    let (t, s) = (list(i, "template"), list(i, "search"));
    let mut out = Vec::new();
    for k in 1..=WINDOWS {
        let w = s.get(k - 1..k - 1 + t.len()).unwrap_or(&[]);
        out.push(Mistake::new(
            &format!("rho[{k}]"),
            "mean not subtracted",
            "ρ compares the deviations from the means: subtract Ā from the template and B̄ from the sub-window first.",
            rho_raw(&t, w),
        ));
    }
    let best = chain_ncc_1d(i, &Record::new())?
        .number("best")
        .unwrap_or(0.0);
    out.push(Mistake::new(
        "best",
        "counted from 0",
        "The seed counts the sub-windows from 1.",
        best - 1.0,
    ));
    Ok(out)
}

fn gen_ncc_2d(rng: &mut Rng) -> Record {
    let a: Vec<Vec<f64>> = (0..3)
        .map(|_| textured(rng, 3).iter().map(|v| 20.0 + 7.0 * v).collect())
        .collect();
    let offset = rng.num(-10, 10);
    let b: Vec<Vec<f64>> = a
        .iter()
        .map(|row| row.iter().map(|v| v + offset + rng.num(-12, 12)).collect())
        .collect();
    Record::new().with("a", mat(&a)).with("b", mat(&b))
}

fn boxes_ncc_2d(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("mean_a", "Mean of A", None, tol::GREY)
            .nudge("Nine values: add them, divide by 9."),
        BoxDef::new("mean_b", "Mean of B", None, tol::GREY).nudge("The same for B."),
        BoxDef::new("sum_dadb", "Σ ΔA·ΔB", None, tol::SUM)
            .nudge("Subtract the means, multiply the two deviations pixel by pixel, add.")
            .sign_flip(RHO_FLIP),
        BoxDef::new("sum_da2", "Σ ΔA²", None, tol::SUM)
            .nudge("The squared deviations of A, added."),
        BoxDef::new("sum_db2", "Σ ΔB²", None, tol::SUM)
            .nudge("The squared deviations of B, added."),
        BoxDef::new("rho", "Correlation coefficient ρ", None, tol::RHO)
            .nudge("Σ ΔA·ΔB over the root of Σ ΔA² · Σ ΔB².")
            .sign_flip(RHO_FLIP),
    ]
}

fn chain_ncc_2d(i: &Record, g: &Record) -> Result<Record> {
    let a: Vec<f64> = rows_of(i, "a").concat();
    let b: Vec<f64> = rows_of(i, "b").concat();
    let ma = or_given(g, "mean_a", mean(&a));
    let mb = or_given(g, "mean_b", mean(&b));
    let dot = |f: &dyn Fn(f64, f64) -> f64| a.iter().zip(&b).map(|(x, y)| f(*x, *y)).sum::<f64>();
    let ab = or_given(g, "sum_dadb", dot(&|x, y| (x - ma) * (y - mb)));
    let aa = or_given(g, "sum_da2", dot(&|x, _| (x - ma) * (x - ma)));
    let bb = or_given(g, "sum_db2", dot(&|_, y| (y - mb) * (y - mb)));
    Ok(Record::new()
        .with("mean_a", ma)
        .with("mean_b", mb)
        .with("sum_dadb", ab)
        .with("sum_da2", aa)
        .with("sum_db2", bb)
        .with("rho", ab / (aa * bb).sqrt()))
}

pub(crate) fn transpose(m: &[Vec<f64>]) -> Vec<Vec<f64>> {
    (0..m.first().map_or(0, Vec::len))
        .map(|j| m.iter().map(|r| r.get(j).copied().unwrap_or(0.0)).collect())
        .collect()
}

fn mistakes_ncc_2d(i: &Record) -> Result<Vec<Mistake>> {
    let a: Vec<f64> = rows_of(i, "a").concat();
    let b = rows_of(i, "b");
    let bt: Vec<f64> = transpose(&b).concat();
    let swapped = chain_ncc_2d(&i.clone().with("b", mat(&transpose(&b))), &Record::new())?;
    const SWAP: &str = "Pair each pixel of A with the pixel of B at the same row and column.";
    Ok(vec![
        Mistake::new(
            "rho",
            "mean not subtracted",
            "ρ compares the deviations from the means: subtract the means first.",
            rho_raw(&a, &b.concat()),
        ),
        Mistake::new(
            "rho",
            "rows and columns swapped",
            SWAP,
            rho_with(&a, mean(&a), &bt),
        ),
        Mistake::new(
            "sum_dadb",
            "rows and columns swapped",
            SWAP,
            swapped.number("sum_dadb").unwrap_or(f64::NAN),
        ),
        Mistake::new(
            "sum_dadb",
            "mean not subtracted",
            "Multiply the deviations ΔA = A − Ā and ΔB = B − B̄, not the grey values.",
            a.iter().zip(b.concat()).map(|(x, y)| x * y).sum(),
        ),
    ])
}

fn gen_surface(rng: &mut Rng) -> Record {
    let search: Vec<Vec<f64>> = (0..6)
        .map(|_| {
            textured(rng, 6)
                .iter()
                .map(|v| 10.0 * v + rng.num(0, 9))
                .collect()
        })
        .collect();
    // The template is the search window at (pc, pr) plus a little noise;
    // pc ≠ pr so that swapping rows and columns shows.
    let pc = rng.int(0, 3) as usize;
    let pr = (pc + rng.int(1, 3) as usize) % 4;
    let offset = rng.num(-5, 5);
    let template: Vec<Vec<f64>> = (0..3)
        .map(|r| {
            (0..3)
                .map(|c| search[pr + r][pc + c] + offset + rng.num(-2, 2))
                .collect()
        })
        .collect();
    Record::new()
        .with("template", mat(&template))
        .with("search", mat(&search))
}

fn surface_best(i: &Record) -> Result<(f64, f64)> {
    let s = examples::solve("ncc-surface", i)?;
    match (s.result.number("best_c"), s.result.number("best_r")) {
        (Some(c), Some(r)) => Ok((c, r)),
        _ => Err(Error::Internal(
            "ncc-surface variant without a best match".into(),
        )),
    }
}

fn boxes_surface(i: &Record) -> Vec<BoxDef> {
    let (c, r) = surface_best(i).unwrap_or((2.0, 2.0));
    vec![
        BoxDef::new("mean_template", "Template mean Ā", None, tol::GREY)
            .nudge("Nine grey values: add them, divide by 9."),
        BoxDef::new("sum_da2", "Σ ΔA² of the template", None, tol::SUM).nudge(
            "Subtract Ā from each template value, square, add. It is the same for every position.",
        ),
        BoxDef::new("rho[1,1]", "ρ at the top-left position", None, tol::RHO)
            .nudge("The sub-window whose top-left pixel is the search array's top-left pixel.")
            .sign_flip(RHO_FLIP),
        BoxDef::new(
            &format!("rho[{},{}]", r as usize - 1, c as usize - 1),
            "ρ at the best position",
            None,
            tol::RHO,
        )
        .nudge("Compute ρ for every position; this is the largest.")
        .sign_flip(RHO_FLIP),
        BoxDef::new(
            "best_c",
            "Best match: centre column c",
            Some("px"),
            tol::WHOLE,
        )
        .nudge("The centre pixel of the best sub-window, counted from 1."),
        BoxDef::new("best_r", "Best match: centre row r", Some("px"), tol::WHOLE)
            .nudge("The centre pixel's row, counted from 1."),
    ]
}

/// ρ at surface position (row `pr`, column `pc`), 1-based, from the
/// template's mean and Σ ΔA² (the student's, when given).
fn surface_rho(t: &[f64], ma: f64, aa: f64, s: &[Vec<f64>], pr: usize, pc: usize) -> f64 {
    let w: Vec<f64> = s
        .iter()
        .skip(pr - 1)
        .take(3)
        .flat_map(|row| row.iter().skip(pc - 1).take(3).copied())
        .collect();
    let mb = mean(&w);
    let (mut ab, mut bb) = (0.0, 0.0);
    for (x, y) in t.iter().zip(&w) {
        ab += (x - ma) * (y - mb);
        bb += (y - mb) * (y - mb);
    }
    ab / (aa * bb).sqrt()
}

fn chain_surface(i: &Record, g: &Record) -> Result<Record> {
    let (c, r) = surface_best(i)?;
    let t = rows_of(i, "template").concat();
    let s = rows_of(i, "search");
    let ma = or_given(g, "mean_template", mean(&t));
    let aa = or_given(
        g,
        "sum_da2",
        t.iter().map(|x| (x - ma) * (x - ma)).sum::<f64>(),
    );
    let (br, bc) = (r as usize - 1, c as usize - 1);
    let best = format!("rho[{br},{bc}]");
    let mut out = Record::new()
        .with("mean_template", ma)
        .with("sum_da2", aa)
        .with(
            "rho[1,1]",
            or_given(g, "rho[1,1]", surface_rho(&t, ma, aa, &s, 1, 1)),
        );
    out.set(
        &best,
        or_given(g, &best, surface_rho(&t, ma, aa, &s, br, bc)),
    );
    Ok(out.with("best_c", c).with("best_r", r))
}

fn mistakes_surface(i: &Record) -> Result<Vec<Mistake>> {
    let (c, r) = surface_best(i)?;
    let t = rows_of(i, "template").concat();
    let s = rows_of(i, "search");
    let w: Vec<f64> = s[..3].iter().flat_map(|row| row[..3].to_vec()).collect();
    const SWAP: &str = "c is the column (to the right), r the row (down).";
    const CORNER: &str =
        "The position asked for is the centre pixel of the sub-window, not its top-left corner.";
    Ok(vec![
        Mistake::new(
            "sum_da2",
            "mean not subtracted",
            "Σ ΔA² adds the squared deviations from the mean, not the squared grey values.",
            t.iter().map(|x| x * x).sum(),
        ),
        Mistake::new(
            "rho[1,1]",
            "mean not subtracted",
            "Subtract both means first.",
            rho_raw(&t, &w),
        ),
        Mistake::new("best_c", "rows and columns swapped", SWAP, r),
        Mistake::new("best_r", "rows and columns swapped", SWAP, c),
        Mistake::new("best_c", "top-left instead of centre", CORNER, c - 1.0),
        Mistake::new("best_r", "top-left instead of centre", CORNER, r - 1.0),
    ])
}

fn gen_sub_1d(rng: &mut Rng) -> Record {
    let k = rng.num(4, 30);
    let mid = rng.num(80, 99);
    let left = mid - rng.num(3, 40);
    let mut right = mid - rng.num(3, 40);
    if right == left {
        right -= 2.0;
    }
    Record::new()
        .with("positions", nums(&[k - 1.0, k, k + 1.0]))
        .with("rho", nums(&[left / 100.0, mid / 100.0, right / 100.0]))
}

fn boxes_sub_1d(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("coefficients[1]", "a₀", None, tol::PARAM).nudge(
            "Put the three (c, ρ) pairs into ρ = a₀ + a₁c + a₂c² and solve the three equations.",
        ),
        BoxDef::new("coefficients[2]", "a₁", None, tol::PARAM).nudge("The linear coefficient."),
        BoxDef::new("coefficients[3]", "a₂", None, tol::PARAM)
            .nudge("The quadratic coefficient: negative for a peak."),
        BoxDef::new(
            "c_max",
            "Peak position c_max",
            Some("px"),
            Tolerance::abs(0.005),
        )
        .nudge("Where the derivative a₁ + 2a₂c is zero."),
    ]
}

fn chain_sub_1d(i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve("subpixel-1d", i)?;
    let co = |k: usize| {
        let key = format!("coefficients[{k}]");
        or_given(g, &key, super::value_in(&s, &key).unwrap_or(f64::NAN))
    };
    let (a0, a1, a2) = (co(1), co(2), co(3));
    Ok(Record::new()
        .with("coefficients[1]", a0)
        .with("coefficients[2]", a1)
        .with("coefficients[3]", a2)
        .with("c_max", or_given(g, "c_max", -a1 / (2.0 * a2))))
}

fn mistakes_sub_1d(i: &Record) -> Result<Vec<Mistake>> {
    let v = chain_sub_1d(i, &Record::new())?;
    let (a1, a2) = (
        v.number("coefficients[2]").unwrap_or(f64::NAN),
        v.number("coefficients[3]").unwrap_or(f64::NAN),
    );
    let c_max = -a1 / (2.0 * a2);
    // the middle position: where the offset is measured from
    let k = list(i, "positions").get(1).copied().unwrap_or(f64::NAN);
    Ok(vec![
        Mistake::new(
            "c_max",
            "sign lost in −a₁/(2a₂)",
            "Setting a₁ + 2a₂c = 0 gives c = −a₁ / (2a₂).",
            a1 / (2.0 * a2),
        ),
        Mistake::new(
            "coefficients[3]",
            "½ forgotten in a₂",
            "The second difference ρ₋ − 2ρ₀ + ρ₊ is 2a₂ (with positions one pixel apart): halve it.",
            2.0 * a2,
        ),
        Mistake::new(
            "c_max",
            "the offset, not the position",
            "The parabola's peak is an offset from the middle position: add it to that position.",
            c_max - k,
        ),
        Mistake::new(
            "c_max",
            "offset the wrong way",
            "The peak lies on the side of the larger neighbour: c_max − c₀ has the sign of ρ₊ − ρ₋.",
            2.0 * k - c_max,
        ),
    ])
}

fn gen_sub_2d(rng: &mut Rng) -> Record {
    let (k, m) = (rng.num(3, 30), rng.num(3, 30));
    let alpha = rng.num(8, 25) / 100.0;
    let beta = rng.num(8, 25) / 100.0;
    let dc = rng.num(-35, 35) / 100.0;
    let mut dr = rng.num(-35, 35) / 100.0;
    if (dr - dc).abs() < 0.1 {
        dr = if dc > 0.0 { dc - 0.3 } else { dc + 0.3 };
    }
    let peak = rng.num(85, 97) / 100.0;
    let rho: Vec<Vec<f64>> = (-1..=1)
        .map(|r| {
            (-1..=1)
                .map(|c| {
                    let v = peak - alpha * (c as f64 - dc).powi(2) - beta * (r as f64 - dr).powi(2);
                    (v * 100.0).round() / 100.0
                })
                .collect()
        })
        .collect();
    Record::new()
        .with("c", nums(&[k - 1.0, k, k + 1.0]))
        .with("r", nums(&[m - 1.0, m, m + 1.0]))
        .with("rho", mat(&rho))
}

/// The centred coefficients b₁ … b₅ (u = c − c̄, v = r − r̄) that the peak
/// follows from: four decimals are plenty.
const LOCAL: Tolerance = Tolerance::abs(0.0005);

fn boxes_sub_2d(_: &Record) -> Vec<BoxDef> {
    let t = Tolerance::abs(0.01);
    let fit = "Fit ρ = b₀ + b₁u + b₂v + b₃uv + b₄u² + b₅v² by least squares in the centred coordinates u = c − c̄, v = r − r̄ (each −1, 0 or 1): the normal equations nearly separate.";
    vec![
        BoxDef::new("local_coefficients[2]", "b₁ (u)", None, LOCAL)
            .nudge("Σ u·ρ over Σ u²: the right column minus the left, over 6.")
            .axis(),
        BoxDef::new("local_coefficients[3]", "b₂ (v)", None, LOCAL)
            .nudge("Σ v·ρ over Σ v²: the bottom row minus the top, over 6.")
            .axis(),
        BoxDef::new("local_coefficients[4]", "b₃ (uv)", None, LOCAL)
            .nudge("Σ uv·ρ over Σ u²v²: the four corners, over 4."),
        BoxDef::new("local_coefficients[5]", "b₄ (u²)", None, LOCAL).nudge(fit),
        BoxDef::new("local_coefficients[6]", "b₅ (v²)", None, LOCAL).nudge(fit),
        BoxDef::new("c_max", "Peak column c_max", Some("px"), t).nudge(
            "Both slopes zero: b₁ + b₃v + 2b₄u = 0 and b₂ + b₃u + 2b₅v = 0; then c = c̄ + u.",
        ),
        BoxDef::new("r_max", "Peak row r_max", Some("px"), t)
            .nudge("Solve the two derivative equations together; r = r̄ + v."),
    ]
}

fn chain_sub_2d(i: &Record, g: &Record) -> Result<Record> {
    let s = examples::solve("subpixel-2d", i)?;
    let mut out = Record::new();
    let mut b = [0.0; 6];
    for (k, bk) in b.iter_mut().enumerate().skip(1) {
        let key = format!("local_coefficients[{}]", k + 1);
        *bk = or_given(g, &key, super::value_in(&s, &key)?);
        out.set(&key, *bk);
    }
    let (cc, rc) = (
        super::value_in(&s, "centre[1]")?,
        super::value_in(&s, "centre[2]")?,
    );
    let det = 4.0 * b[4] * b[5] - b[3] * b[3];
    let u = (-2.0 * b[1] * b[5] + b[2] * b[3]) / det;
    let v = (-2.0 * b[2] * b[4] + b[1] * b[3]) / det;
    Ok(out
        .with("c_max", or_given(g, "c_max", cc + u))
        .with("r_max", or_given(g, "r_max", rc + v)))
}

fn mistakes_sub_2d(i: &Record) -> Result<Vec<Mistake>> {
    let swapped = i.clone().with("rho", mat(&transpose(&rows_of(i, "rho"))));
    let s = examples::solve("subpixel-2d", &swapped)?;
    const SWAP: &str = "The rows of the ρ table are the rows r; its columns are the columns c.";
    let mut out = Vec::new();
    for k in [2, 3] {
        let key = format!("local_coefficients[{k}]");
        out.push(Mistake::new(
            &key,
            "rows and columns swapped",
            SWAP,
            super::value_in(&s, &key)?,
        ));
    }
    Ok(out
        .into_iter()
        .chain(vec![
            Mistake::new(
                "c_max",
                "rows and columns swapped",
                SWAP,
                s.result.number("c_max").unwrap_or(f64::NAN),
            ),
            Mistake::new(
                "r_max",
                "rows and columns swapped",
                SWAP,
                s.result.number("r_max").unwrap_or(f64::NAN),
            ),
        ])
        .collect())
}
