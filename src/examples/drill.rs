//! What an example's practice mode is made of, declared in the example's
//! own file ([`super::Example::practice`]): how to draw a variant's inputs,
//! its answer boxes with their tolerances, how later boxes follow from
//! earlier answers (errors carried forward) and the mistakes students make.
//! The practice engine (`crate::practice`: codes, grading, hints) reads
//! these; this layer knows nothing of it.

use crate::error::{Error, Result};
pub use crate::rng::Rng;
use crate::solution::{Record, Solution, Value};
use serde::Serialize;

/// An example's practice, as its descriptor declares it: `practice:
/// drill(Drill::new(generate, boxes, Some(chain), mistakes))`. Without the `practice` feature (the page's topic
/// modules, which have no practice exports) it is [`Drill::ELSEWHERE`]: the
/// catalog still says the example has practice, and none of the drill's code
/// is linked into the module.
pub const fn drill(d: Drill) -> Option<Drill> {
    if cfg!(feature = "practice") {
        Some(d)
    } else {
        Some(Drill::ELSEWHERE)
    }
}

fn elsewhere_inputs(_: &mut Rng) -> Record {
    Record::new()
}
fn elsewhere_boxes(_: &Record) -> Vec<BoxDef> {
    Vec::new()
}
fn elsewhere_mistakes(_: &Record) -> Result<Vec<Mistake>> {
    Err(Error::input(
        "id",
        "practice mode is in this topic's practice module (pkg/<topic>_practice.js)",
    ))
}

impl Drill {
    /// A drill from its parts, in the order of the fields: the one-line
    /// form every descriptor uses.
    pub const fn new(
        generate: fn(&mut Rng) -> Record,
        boxes: fn(&Record) -> Vec<BoxDef>,
        chain: Option<Chain>,
        mistakes: fn(&Record) -> Result<Vec<Mistake>>,
    ) -> Drill {
        Drill {
            generate,
            boxes,
            chain,
            mistakes,
        }
    }

    /// The drill of a build without the `practice` feature: draws nothing.
    pub const ELSEWHERE: Drill =
        Drill::new(elsewhere_inputs, elsewhere_boxes, None, elsewhere_mistakes);
}

/// How one example is practised.
#[derive(Clone, Copy)]
pub struct Drill {
    /// Draws the inputs (constructively: every draw is a good variant).
    pub generate: fn(&mut Rng) -> Record,
    /// The answer boxes for these inputs, in the order a student fills them.
    pub boxes: fn(&Record) -> Vec<BoxDef>,
    /// Later boxes from earlier ones; `None` when the boxes do not build
    /// on each other in a way worth carrying forward.
    pub chain: Option<Chain>,
    /// The known mistakes and the values they give.
    pub mistakes: fn(&Record) -> Result<Vec<Mistake>>,
}

/// The tolerance of a box: `|x − x*| ≤ atol + rtol·|x*|`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Tolerance {
    pub atol: f64,
    pub rtol: f64,
}

impl Tolerance {
    pub const fn abs(atol: f64) -> Self {
        Tolerance { atol, rtol: 0.0 }
    }
    pub const fn rel(rtol: f64) -> Self {
        Tolerance { atol: 0.0, rtol }
    }
    /// The allowed deviation around `expected`.
    pub fn allowed(self, expected: f64) -> f64 {
        self.atol + self.rtol * expected.abs()
    }
    pub fn accepts(self, expected: f64, x: f64) -> bool {
        (x - expected).abs() <= self.allowed(expected) * (1.0 + 1e-9) + 1e-12
    }
}

/// One answer box of an example.
#[derive(Debug, Clone)]
pub struct BoxDef {
    /// A result key, or a path into one: `rho[3]` (1-based element),
    /// `n[1,2]` (row 1, column 2). Also a key of a step's values.
    pub key: String,
    pub label: String,
    pub unit: Option<&'static str>,
    pub tolerance: Tolerance,
    /// The first rung of the hint ladder: what to think about.
    pub nudge: String,
    /// What a sign flip means in this box, when it is a mistake worth
    /// naming there (a coordinate: "check which way the axis points");
    /// `None` for values whose sign is never in doubt (a mean, a length).
    pub sign_flip: Option<&'static str>,
    /// Half a unit in the last decimal the course's own worked example
    /// prints for this value, when that is coarser than the tolerance: an
    /// answer rounded to those digits is as precise as the box demands
    /// (set by [`boxes_of`]).
    pub printed_half: Option<f64>,
}

/// The sign flip of a coordinate, an offset or a shift.
pub const AXIS_FLIP: &str =
    "The size is right but the sign is not: check which way the axis points.";

impl BoxDef {
    pub fn new(key: &str, label: &str, unit: Option<&'static str>, tol: Tolerance) -> Self {
        BoxDef {
            key: key.to_string(),
            label: label.to_string(),
            unit,
            tolerance: tol,
            nudge: String::new(),
            sign_flip: None,
            printed_half: None,
        }
    }
    pub fn nudge(mut self, text: &str) -> Self {
        self.nudge = text.to_string();
        self
    }
    /// A coordinate, offset or shift: a sign flip is named, with the axis hint.
    pub fn axis(self) -> Self {
        self.sign_flip(AXIS_FLIP)
    }
    /// A sign flip is named in this box, with `explain`.
    pub fn sign_flip(mut self, explain: &'static str) -> Self {
        self.sign_flip = Some(explain);
        self
    }
}

/// A mistake students make, with the value it gives in box `key`.
#[derive(Debug, Clone, PartialEq)]
pub struct Mistake {
    pub key: String,
    /// Short name shown in the feedback ("y not flipped").
    pub name: &'static str,
    /// One sentence on what went wrong.
    pub explain: &'static str,
    pub value: f64,
}

impl Mistake {
    pub fn new(key: &str, name: &'static str, explain: &'static str, value: f64) -> Self {
        Mistake {
            key: key.to_string(),
            name,
            explain,
            value,
        }
    }
}

/// The box values a student's earlier answers imply: `given` holds the
/// answers (by box key) to use instead of the exact values.
pub type Chain = fn(&Record, &Record) -> Result<Record>;

/// How one example is practised (with its example: what the engine keeps).
pub struct Spec {
    pub id: &'static str,
    /// The example it practises (its solver gives the expected values).
    pub example: &'static super::Example,
    /// Draws the inputs (constructively: every draw is a good variant).
    pub generate: fn(&mut Rng) -> Record,
    /// The answer boxes for these inputs, in the order a student fills them.
    pub boxes: fn(&Record) -> Vec<BoxDef>,
    /// Later boxes from earlier ones; `None` when the boxes do not build
    /// on each other in a way worth carrying forward.
    pub chain: Option<Chain>,
    /// The known mistakes and the values they give.
    pub mistakes: fn(&Record) -> Result<Vec<Mistake>>,
}

pub mod tol {
    use super::Tolerance;
    /// Lengths and coordinates derived from a pixel size: 0.1 %.
    pub const LENGTH: Tolerance = Tolerance {
        atol: 0.001,
        rtol: 0.001,
    };
    /// Pixel positions and counts to a hundredth of a pixel.
    pub const PIXEL: Tolerance = Tolerance::abs(0.01);
    /// Whole numbers.
    pub const WHOLE: Tolerance = Tolerance::abs(0.0);
    /// Grey values (means, filtered values).
    pub const GREY: Tolerance = Tolerance::abs(0.01);
    /// Sums of products and squares.
    pub const SUM: Tolerance = Tolerance {
        atol: 0.05,
        rtol: 0.0005,
    };
    /// Correlation coefficients.
    pub const RHO: Tolerance = Tolerance::abs(0.001);
    /// Fitted parameters.
    pub const PARAM: Tolerance = Tolerance {
        atol: 0.001,
        rtol: 0.001,
    };
}

/// The base name and 1-based indices of a box key (`n[1,2]` → `n`, [1, 2]).
pub fn split_key(key: &str) -> (&str, Vec<usize>) {
    match key.split_once('[') {
        Some((base, rest)) => {
            let idx = rest
                .trim_end_matches(']')
                .split(',')
                .filter_map(|p| p.trim().parse().ok())
                .collect();
            (base, idx)
        }
        None => (key, Vec::new()),
    }
}

/// The value of box `key` in a solution (its result, else a step's values).
pub fn value_in(s: &Solution, key: &str) -> Result<f64> {
    let (base, idx) = split_key(key);
    let v = s
        .result
        .get(base)
        .or_else(|| s.steps.iter().find_map(|st| st.values.get(base)))
        .ok_or_else(|| Error::Internal(format!("practice box {key} is not in {}", s.id)))?;
    pick(v, &idx).ok_or_else(|| Error::Internal(format!("practice box {key} is not a number")))
}

/// The number at 1-based `idx` inside a value (booleans count 1/0).
pub fn pick(v: &Value, idx: &[usize]) -> Option<f64> {
    match (v, idx.split_first()) {
        (Value::Number(x), None) => Some(*x),
        (Value::Bool(b), None) => Some(if *b { 1.0 } else { 0.0 }),
        (Value::List(xs), Some((&i, rest))) => pick(xs.get(i.checked_sub(1)?)?, rest),
        _ => None,
    }
}

/// Rounds to `sig` significant digits.
pub fn round_sig(x: f64, sig: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let p = 10f64.powi(sig - 1 - x.abs().log10().floor() as i32);
    (x * p).round() / p
}

/// Shorthands for the topic files.
pub fn nums(xs: &[f64]) -> Value {
    Value::numbers(xs)
}
pub fn mat(rows: &[Vec<f64>]) -> Value {
    Value::matrix(rows)
}

/// The value of `key` in `given`, else `exact`: what a chain computes on.
pub fn or_given(given: &Record, key: &str, exact: f64) -> f64 {
    given.number(key).unwrap_or(exact)
}

/// The numbers of list input `key` of a drawn variant (empty when it has
/// none): the lenient form of [`Inputs::list`](super::fields::Inputs::list)
/// for boxes and mistakes, whose inputs the generator made.
pub fn list(inputs: &Record, key: &str) -> Vec<f64> {
    super::fields::Inputs(inputs).list(key).unwrap_or_default()
}

/// The rows of matrix input `key` of a drawn variant (empty when it has
/// none); see [`list`].
pub fn rows_of(inputs: &Record, key: &str) -> Vec<Vec<f64>> {
    super::fields::Inputs(inputs).rows(key).unwrap_or_default()
}

/// A matrix with rows and columns swapped (a short row counts as zeros).
pub fn transpose(m: &[Vec<f64>]) -> Vec<Vec<f64>> {
    (0..m.first().map_or(0, Vec::len))
        .map(|j| m.iter().map(|r| r.get(j).copied().unwrap_or(0.0)).collect())
        .collect()
}
