//! Practice mode: fresh numbers for every worked example, answers checked
//! box by box against the exact solver, errors carried forward, known
//! mistakes named, and a hint ladder.
//!
//! - A variant is a short code: a version digit and four Crockford base-32
//!   digits (`1K7Q2`). The code seeds a small deterministic PRNG ([`Rng`])
//!   that the example's generator draws its inputs from, constructively.
//! - Each example's [`Spec`] (in the topic files beside this one) says how to
//!   draw the inputs, which values get an answer box, how the later boxes
//!   follow from the earlier ones (for errors carried forward) and which
//!   mistakes students make.
//! - The expected values are the solver's own results
//!   ([`crate::examples::solve`]); a test ties every chain to them.

pub mod grade;

use crate::error::{Error, Result};
use crate::examples::{self, Topic, TOPICS};
use crate::solution::{Record, Relation, Solution};
use serde::Serialize;

pub use grade::{grade, grade_in, Graded};

/// The version of the generators; part of every code.
pub const VERSION: u32 = 1;
/// Crockford's base 32 (no I, L, O, U).
const ALPHABET: &[u8; 32] = b"0123456789ABCDEFGHJKMNPQRSTVWXYZ";
/// Digits of a code after the version digit.
const CODE_DIGITS: usize = 4;
/// How many different variants one example has.
pub const VARIANTS: u32 = 1 << (5 * CODE_DIGITS);

pub use crate::examples::drill::{
    mat, nums, or_given, pick, round_sig, split_key, tol, value_in, BoxDef, Chain, Mistake, Spec,
    Tolerance, AXIS_FLIP,
};
pub use crate::read;
pub use crate::rng::Rng;

/// Encodes a variant number as a code (`1K7Q2`).
pub fn encode(variant: u32) -> String {
    let mut s = VERSION.to_string();
    for i in (0..CODE_DIGITS).rev() {
        s.push(ALPHABET[((variant >> (5 * i)) & 31) as usize] as char);
    }
    s
}

/// Reads a code (case-insensitive; I and L read as 1, O as 0).
pub fn decode(code: &str) -> Result<u32> {
    let bad = |why: String| Error::input("code", why);
    let code = code.trim().to_ascii_uppercase();
    let mut chars = code.chars();
    let version = chars
        .next()
        .ok_or_else(|| bad("is empty; a practice code looks like 1K7Q2".into()))?;
    let rest: Vec<char> = chars.collect();
    if !version.is_ascii_digit() || rest.len() != CODE_DIGITS {
        return Err(bad(format!(
            "\"{code}\" is not a practice code (a version digit and {CODE_DIGITS} letters or digits, like 1K7Q2)"
        )));
    }
    if version.to_digit(10) != Some(VERSION) {
        return Err(bad(format!(
            "\"{code}\" is a version-{version} code; this playground makes version-{VERSION} codes"
        )));
    }
    let mut v = 0u32;
    for ch in rest {
        let ch = match ch {
            'I' | 'L' => '1',
            'O' => '0',
            c => c,
        };
        let d = ALPHABET
            .iter()
            .position(|&a| a as char == ch)
            .ok_or_else(|| bad(format!("\"{code}\": '{ch}' is not a code letter")))?;
        v = (v << 5) | d as u32;
    }
    Ok(v)
}

/// Every example that has practice, in catalog order (the descriptors'
/// drills).
pub fn specs() -> Vec<Spec> {
    specs_in(&TOPICS)
}

/// The practice of every example of `topics` that has one.
pub fn specs_in(topics: &'static [Topic]) -> Vec<Spec> {
    examples::of(topics)
        .filter_map(|(_, e)| e.practice.map(|d| spec_of(e, d)))
        .collect()
}

fn spec_of(e: &'static examples::Example, d: examples::drill::Drill) -> Spec {
    Spec {
        id: e.id,
        example: e,
        generate: d.generate,
        boxes: d.boxes,
        chain: d.chain,
        mistakes: d.mistakes,
    }
}

/// The practice of example `id` among `topics` (a topic module's own, or
/// [`TOPICS`]).
pub fn spec_in(topics: &'static [Topic], id: &str) -> Result<Spec> {
    let e = examples::find(topics, id)?;
    e.practice
        .map(|d| spec_of(e, d))
        .ok_or_else(|| Error::input("id", format!("\"{id}\" has no practice mode yet")))
}

/// [`spec_in`] over every topic.
pub fn spec(id: &str) -> Result<Spec> {
    spec_in(&TOPICS, id)
}

/// The seed of variant `variant` of example `id` (codes differ per example).
fn seed(id: &str, variant: u32) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in id.bytes() {
        h = (h ^ b as u64).wrapping_mul(0x100_0000_01b3);
    }
    h ^ ((VERSION as u64) << 40) ^ variant as u64
}

/// The inputs of variant `variant` of `spec`.
pub fn inputs_of(spec: &Spec, variant: u32) -> Record {
    (spec.generate)(&mut Rng::new(seed(spec.id, variant)))
}

/// What a box looks like to the page.
#[derive(Debug, Clone, Serialize)]
pub struct BoxInfo {
    pub key: String,
    pub label: String,
    pub unit: Option<&'static str>,
    pub tolerance: Tolerance,
    /// The tolerance in words: "± 0.05 px", "± 0.1 %"; with "(or 1
    /// decimal, as the course notes print it)" where the course prints
    /// fewer digits than the tolerance asks for.
    pub tolerance_text: String,
    /// Half a unit in the course's last printed decimal, when an answer
    /// rounded that far is accepted (see `tolerance_text`); else `None`.
    pub printed_half: Option<f64>,
    /// The hint ladder: a nudge, the formula (LaTeX), the formula with this
    /// variant's numbers (LaTeX, the result left out), and the index of the
    /// worked step in `solve(id, inputs).steps`.
    pub hints: Hints,
    /// The exact value of the box for this variant (what a worksheet's
    /// answer key prints).
    pub expected: Option<f64>,
}

#[derive(Debug, Clone, Serialize)]
pub struct Hints {
    pub nudge: String,
    pub formula: String,
    pub numbers: String,
    pub step: usize,
    /// The relation the formula and numbers come from, for the page's
    /// layout (its result is never shown with the numbers).
    pub relation: Option<Relation>,
}

/// A practice variant: `{ code, inputs, boxes }`.
#[derive(Debug, Clone, Serialize)]
pub struct Practice {
    pub id: String,
    pub code: String,
    pub inputs: Record,
    pub boxes: Vec<BoxInfo>,
}

/// A practice variant of example `id`: the one of `code`, or variant
/// `fresh` (any number, reduced to the code range) when `code` is `None`.
pub fn practice(id: &str, code: Option<&str>, fresh: u32) -> Result<Practice> {
    practice_in(&TOPICS, id, code, fresh)
}

/// [`practice`] among `topics` only (a topic module's).
pub fn practice_in(
    topics: &'static [Topic],
    id: &str,
    code: Option<&str>,
    fresh: u32,
) -> Result<Practice> {
    let spec = spec_in(topics, id)?;
    let variant = match code {
        Some(c) => decode(c)?,
        None => fresh % VARIANTS,
    };
    let inputs = inputs_of(&spec, variant);
    let solution = spec.example.run(&inputs)?;
    let boxes = boxes_of(&spec, &inputs, &solution)
        .into_iter()
        .map(|b| box_info(&b, &solution))
        .collect();
    Ok(Practice {
        id: id.to_string(),
        code: encode(variant),
        inputs,
        boxes,
    })
}

/// The boxes of a variant as shown and graded: the spec's, each marked
/// where its tolerance would demand more digits than the course's own
/// worked example prints for that value (its `textbook` value for the
/// seed). The digits are counted as significant digits, so that a variant of
/// another size asks for as many as the seed's printed value shows: the
/// notes print the mean Ā as 58.5 (three), so 58.2 for a mean of 58.22 is
/// correct; they print the pixel size as 0.028 mm (two), so 0.028 for
/// 0.02822 is correct too (their own note says what that rounding costs the
/// GSD, whose box asks for its own digits). The tolerance still judges a
/// value given with more digits: 58.27 (two decimals claimed, 0.05 off) is
/// wrong.
pub fn boxes_of(spec: &Spec, inputs: &Record, solution: &Solution) -> Vec<BoxDef> {
    let mut boxes = (spec.boxes)(inputs);
    let Some(printed) = printed_values(spec.example) else {
        return boxes;
    };
    for b in &mut boxes {
        let (base, idx) = split_key(&b.key);
        let Some(p) = printed.get(base).and_then(|v| pick(v, &idx)) else {
            continue;
        };
        let Ok(x) = value_in(solution, &b.key) else {
            continue;
        };
        let Some(half) = printed_half_at(p, x) else {
            continue;
        };
        if b.tolerance.allowed(x) < half {
            b.printed_half = Some(half);
        }
    }
    boxes
}

/// The significant digits a printed value shows (58.5 → 3, 0.028 → 2);
/// `None` for a whole number, whose trailing zeros cannot be told.
pub fn printed_significant_digits(p: f64) -> Option<i32> {
    if !p.is_finite() || p == 0.0 || p.fract() == 0.0 {
        return None;
    }
    let text = format!("{}", p.abs());
    let digits: String = text.chars().filter(|c| c.is_ascii_digit()).collect();
    Some(digits.trim_start_matches('0').len() as i32)
}

/// Half a unit in the last of those significant digits at the size of `x`
/// (printed 58.5, x = 58.22 → 0.05; printed 0.028, x = 0.02822 → 0.0005).
pub fn printed_half_at(p: f64, x: f64) -> Option<f64> {
    let sig = printed_significant_digits(p)?;
    if x == 0.0 || !x.is_finite() {
        return None;
    }
    Some(0.5 * 10f64.powi(x.abs().log10().floor() as i32 - sig + 1))
}

/// The values the course's worked example prints for example `id` (the
/// seed's `textbook`), solved once per example and kept: `grade` runs on
/// every keystroke.
fn printed_values(example: &'static examples::Example) -> Option<Record> {
    use std::cell::RefCell;
    use std::collections::HashMap;
    thread_local! {
        static PRINTED: RefCell<HashMap<&'static str, Option<Record>>> = RefCell::new(HashMap::new());
    }
    PRINTED.with(|cache| {
        cache
            .borrow_mut()
            .entry(example.id)
            .or_insert_with(|| example.run(&Record::new()).ok().and_then(|s| s.textbook))
            .clone()
    })
}

/// The decimals that half-unit `half` stands for, in words (0.05 → "1
/// decimal", 0.5 → "the nearest whole number", 5 → "the nearest 10").
pub fn decimals_of(half: f64) -> String {
    let d = (-(2.0 * half).log10()).round() as i32;
    match d {
        1.. => format!("{d} decimal{}", if d == 1 { "" } else { "s" }),
        0 => "the nearest whole number".to_string(),
        _ => format!("the nearest {}", 10f64.powi(-d)),
    }
}

/// The significant digits an answer near `exact` needs so that rounding
/// it stays within `allowed`: "3 significant digits" (or "2 decimals" for
/// an exact zero, where significant digits say nothing).
pub fn digits_needed(exact: f64, allowed: f64) -> String {
    if allowed <= 0.0 || !allowed.is_finite() {
        return "all the digits".to_string();
    }
    let decimals = (-(2.0 * allowed).log10() - 1e-9).ceil().max(0.0) as i32;
    if exact == 0.0 || !exact.is_finite() {
        return format!("{decimals} decimals");
    }
    let lead = exact.abs().log10().floor() as i32;
    let n = (lead + 1 + decimals).max(1);
    format!("{n} significant digit{}", if n == 1 { "" } else { "s" })
}

/// The second and third hints of box `key`: the formula, and the formula
/// with this variant's numbers but not what they come to. Read from the
/// steps' parts: the relation that computes the box's value (its `key`),
/// else the first relation of the box's step with numbers put in.
fn hints_of(key: &str, s: &Solution, step: usize) -> (String, String, Option<Relation>) {
    // the relation of the box's own element (`sums[1,2]`), else of its value (`sums`)
    let (base, _) = split_key(key);
    let relations = || s.steps.iter().flat_map(|st| st.parts.iter());
    let keyed = relations()
        .find(|r| r.key.as_deref() == Some(key))
        .or_else(|| relations().find(|r| r.key.as_deref() == Some(base)));
    let in_step = || {
        s.steps
            .get(step)
            .and_then(|st| st.parts.iter().find(|r| !r.substituted.is_empty()))
    };
    match keyed.or_else(in_step) {
        // a relation with symbols: both hints laid out from it
        Some(r) if !r.symbolic.is_empty() => {
            (r.symbolic_latex(), r.question_latex(), Some(r.clone()))
        }
        // numbers only: the formula is the step's
        Some(r) => (
            s.steps
                .get(step)
                .map(|st| st.formula.clone())
                .unwrap_or_default(),
            r.question_latex(),
            None,
        ),
        None => (
            s.steps
                .get(step)
                .map(|st| st.formula.clone())
                .unwrap_or_default(),
            String::new(),
            None,
        ),
    }
}

fn box_info(b: &BoxDef, s: &Solution) -> BoxInfo {
    let step = step_of(&b.key, s);
    let (formula, numbers, relation) = hints_of(&b.key, s, step);
    BoxInfo {
        key: b.key.clone(),
        label: b.label.clone(),
        unit: b.unit,
        tolerance: b.tolerance,
        tolerance_text: match b.printed_half {
            Some(half) => format!(
                "{} (or {}, as the course notes print it)",
                tolerance_text(b.tolerance, b.unit),
                decimals_of(half)
            ),
            None => tolerance_text(b.tolerance, b.unit),
        },
        printed_half: b.printed_half,
        hints: Hints {
            nudge: b.nudge.clone(),
            formula,
            numbers,
            step,
            relation,
        },
        expected: value_in(s, &b.key).ok(),
    }
}

/// The tolerance in words.
pub fn tolerance_text(t: Tolerance, unit: Option<&str>) -> String {
    let u = unit.map(|u| format!(" {u}")).unwrap_or_default();
    let abs = if t.atol > 0.0 && t.atol < 1e-4 {
        // 10⁻⁷ (or 2.5×10⁻⁷) rather than 0.0000001
        let e = format!("{:e}", t.atol);
        let (mantissa, exp) = e.split_once('e').unwrap_or((e.as_str(), "0"));
        let sup: String = exp
            .chars()
            .map(|c| match c {
                '-' => '⁻',
                d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹']
                    [d.to_digit(10).unwrap_or(0) as usize],
            })
            .collect();
        if mantissa == "1" {
            format!("10{sup}")
        } else {
            format!("{mantissa}×10{sup}")
        }
    } else {
        crate::solution::fmt_sig(t.atol, 3)
    };
    let rel = crate::solution::fmt_sig(t.rtol * 100.0, 3);
    match (t.atol > 0.0, t.rtol > 0.0) {
        (true, true) => format!("± ({abs}{u} + {rel} %)"),
        (true, false) => format!("± {abs}{u}"),
        (false, true) => format!("± {rel} %"),
        (false, false) => "exact".to_string(),
    }
}

/// The step that shows box `key`: the first whose values carry its base
/// name, else the last step.
fn step_of(key: &str, s: &Solution) -> usize {
    let (base, _) = split_key(key);
    s.steps
        .iter()
        .position(|st| st.values.get(base).is_some())
        .unwrap_or(s.steps.len().saturating_sub(1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solution::Value;

    #[test]
    fn codes_round_trip_and_read_forgivingly() {
        for v in [0, 1, 31, 32, 12345, VARIANTS - 1] {
            assert_eq!(decode(&encode(v)).unwrap(), v);
        }
        assert_eq!(encode(0), "10000");
        assert_eq!(decode("1oill").unwrap(), decode("10111").unwrap());
        assert!(decode("").is_err());
        assert!(decode("1K7Q").is_err());
        assert!(decode("2K7Q2")
            .unwrap_err()
            .to_string()
            .contains("version-2"));
        assert!(decode("1K7U2").unwrap_err().to_string().contains("'U'"));
    }

    #[test]
    fn rng_is_deterministic_and_in_range() {
        let (mut a, mut b) = (Rng::new(7), Rng::new(7));
        for _ in 0..1000 {
            let x = a.int(-3, 5);
            assert_eq!(x, b.int(-3, 5));
            assert!((-3..=5).contains(&x));
        }
    }

    #[test]
    fn tolerance_edges() {
        let t = Tolerance {
            atol: 0.01,
            rtol: 0.001,
        };
        // allowed around 10: 0.01 + 0.01 = 0.02
        assert!(t.accepts(10.0, 10.02));
        assert!(t.accepts(10.0, 9.98));
        assert!(!t.accepts(10.0, 10.0201));
        assert!(!t.accepts(10.0, 9.9799));
        assert_eq!(tolerance_text(t, Some("mm")), "± (0.01 mm + 0.1 %)");
        assert_eq!(tolerance_text(Tolerance::abs(1e-9), None), "± 10⁻⁹");
        assert_eq!(
            tolerance_text(Tolerance::abs(2.5e-7), Some("°")),
            "± 2.5×10⁻⁷ °"
        );
        assert_eq!(tolerance_text(Tolerance::abs(0.0), None), "exact");
    }

    #[test]
    fn keys_split_and_pick() {
        assert_eq!(split_key("n[1,2]"), ("n", vec![1, 2]));
        let m = Value::matrix(&[vec![1.0, 2.0], vec![3.0, 4.0]]);
        assert_eq!(pick(&m, &[2, 1]), Some(3.0));
        assert_eq!(pick(&m, &[3, 1]), None);
        assert_eq!(pick(&m, &[0, 1]), None);
    }
}
