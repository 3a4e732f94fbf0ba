//! Grading a variant's answer boxes: how each text was read, its value
//! against the solver's (within the box's tolerance, or to the digits the
//! student gave), against the values the student's own earlier answers
//! imply (error carried forward) or earlier values rounded as shown, and
//! against the example's known mistakes.

use super::read::{check_unit, read, UnitCheck};
use super::{
    boxes_of, decimals_of, decode, digits_needed, encode, inputs_of, round_sig, spec_in, value_in,
    BoxDef, Mistake, Spec,
};
use crate::error::{Error, Result};
use crate::examples::{Topic, TOPICS};
use crate::solution::{fmt_sig, Record, Value};
use serde::ser::{Serialize, SerializeMap, Serializer};

/// The verdict on one box.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    Correct,
    /// The right value to the digits typed, but fewer digits than the box
    /// asks for: ½ point, "Right, but give at least N significant digits".
    Imprecise,
    Consistent,
    Wrong,
    Unreadable,
    Empty,
}

/// The grade of one box.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct BoxGrade {
    pub verdict: Verdict,
    /// The name of the known mistake the answer matches.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mistake: Option<&'static str>,
    pub message: String,
    /// How the text was read ("0.0282 mm"); `None` when it could not be.
    pub read: Option<String>,
    /// "ok" or "off": the number against the expected one.
    pub value: Option<&'static str>,
    /// "ok", or "coarse" when the answer is right only to fewer digits than
    /// the tolerance asks for.
    pub precision: Option<&'static str>,
    /// "ok" (the box's unit or one converted to it), "omitted" (none typed:
    /// the box's unit is taken), "wrong"; `None` for boxes without a unit.
    pub unit: Option<&'static str>,
    /// 1 for correct or consistent, ½ for imprecise (right but too coarse)
    /// and for a right number in a wrong unit, else 0.
    pub points: f64,
}

/// All boxes of a variant graded: `{ boxes: { key: BoxGrade }, score, out_of }`.
#[derive(Debug, Clone, PartialEq)]
pub struct Graded {
    pub code: String,
    pub boxes: Vec<(String, BoxGrade)>,
    pub score: f64,
    pub out_of: usize,
}

impl Graded {
    pub fn get(&self, key: &str) -> Option<&BoxGrade> {
        self.boxes.iter().find(|(k, _)| k == key).map(|(_, g)| g)
    }
}

struct Boxes<'a>(&'a [(String, BoxGrade)]);

impl Serialize for Boxes<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in self.0 {
            m.serialize_entry(k, v)?;
        }
        m.end()
    }
}

impl Serialize for Graded {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(4))?;
        m.serialize_entry("code", &self.code)?;
        m.serialize_entry("boxes", &Boxes(&self.boxes))?;
        m.serialize_entry("score", &self.score)?;
        m.serialize_entry("out_of", &self.out_of)?;
        m.end()
    }
}

/// A box's answer as read, in the box's unit.
struct Answer {
    x: f64,
    half_ulp: f64,
    unit: Option<&'static str>,
}

/// Rounded to no fewer decimals than the course prints for the box, and
/// right to the digits given (58.2 for 58.22 where the notes print 58.5).
fn as_printed(b: &BoxDef, exact: f64, a: &Answer) -> bool {
    b.printed_half.is_some_and(|h| {
        a.half_ulp <= h * (1.0 + 1e-9) && (a.x - exact).abs() <= a.half_ulp * (1.0 + 1e-9)
    })
}

/// The answer is right: within the tolerance, or as precise as the course prints it.
fn right(b: &BoxDef, exact: f64, a: &Answer) -> bool {
    b.tolerance.accepts(exact, a.x) || as_printed(b, exact, a)
}

/// Grades `answers` (`{ key: text }`) for variant `code` of example `id`.
pub fn grade(id: &str, code: &str, answers: &Record) -> Result<Graded> {
    grade_in(&TOPICS, id, code, answers)
}

/// [`grade`] among `topics` only (a topic module's).
pub fn grade_in(
    topics: &'static [Topic],
    id: &str,
    code: &str,
    answers: &Record,
) -> Result<Graded> {
    let spec = spec_in(topics, id)?;
    let variant = decode(code)?;
    let inputs = inputs_of(&spec, variant);
    let solution = spec.example.run(&inputs)?;
    let boxes = boxes_of(&spec, &inputs, &solution);
    for (k, _) in answers.iter() {
        if !boxes.iter().any(|b| b.key == k) {
            let known: Vec<_> = boxes.iter().map(|b| b.key.as_str()).collect();
            return Err(Error::input(
                format!("answers.{k}"),
                format!("no such box (this example has: {})", known.join(", ")),
            ));
        }
    }
    let exact: Vec<f64> = boxes
        .iter()
        .map(|b| value_in(&solution, &b.key))
        .collect::<Result<_>>()?;
    let mistakes = (spec.mistakes)(&inputs)?;
    let mut read_so_far: Vec<Option<Answer>> = Vec::new();
    let mut out = Vec::new();
    for (k, b) in boxes.iter().enumerate() {
        let text = match answers.get(&b.key) {
            None | Some(Value::Null) => String::new(),
            Some(Value::Text(t)) => t.clone(),
            Some(Value::Number(x)) => format!("{x}"),
            Some(other) => {
                return Err(Error::input(
                    format!("answers.{}", b.key),
                    format!("must be a string (got {})", other.type_name()),
                ))
            }
        };
        let ctx = Ctx {
            spec: &spec,
            inputs: &inputs,
            boxes: &boxes,
            exact: &exact,
            earlier: &read_so_far,
            mistakes: &mistakes,
        };
        let (g, answer) = grade_box(&ctx, k, &text);
        out.push((b.key.clone(), g));
        read_so_far.push(answer);
    }
    let score = out.iter().map(|(_, g)| g.points).sum();
    Ok(Graded {
        code: encode(variant),
        out_of: out.len(),
        boxes: out,
        score,
    })
}

struct Ctx<'a> {
    spec: &'a Spec,
    inputs: &'a Record,
    boxes: &'a [BoxDef],
    exact: &'a [f64],
    earlier: &'a [Option<Answer>],
    mistakes: &'a [Mistake],
}

fn shown(x: f64) -> String {
    fmt_sig(x, 10)
}

fn grade_box(ctx: &Ctx, k: usize, text: &str) -> (BoxGrade, Option<Answer>) {
    let b = &ctx.boxes[k];
    let blank = |verdict, message: String, read: Option<String>| BoxGrade {
        verdict,
        mistake: None,
        message,
        read,
        value: None,
        precision: None,
        unit: None,
        points: 0.0,
    };
    let reading = match read(text) {
        Ok(None) => return (blank(Verdict::Empty, "No answer yet.".into(), None), None),
        Ok(Some(r)) => r,
        Err(why) => {
            let msg =
                format!("Could not read this as a number: {why}. It is not counted as wrong.");
            return (blank(Verdict::Unreadable, msg, None), None);
        }
    };
    let typed_unit = reading.unit.map(|u| format!(" {u}")).unwrap_or_default();
    let read_text = Some(format!("{}{typed_unit}", shown(reading.number)));
    let (factor, unit) = match (b.unit, check_unit(reading.unit, b.unit)) {
        (None, UnitCheck::Omitted) => (1.0, None),
        (Some(_), UnitCheck::Omitted) => (1.0, Some("omitted")),
        (_, UnitCheck::Fits { factor }) => (factor, Some("ok")),
        (_, UnitCheck::Wrong) => (1.0, Some("wrong")),
    };
    let a = Answer {
        x: reading.number * factor,
        half_ulp: reading.half_ulp * factor,
        unit: reading.unit,
    };
    let mut g = BoxGrade {
        verdict: Verdict::Wrong,
        mistake: None,
        message: String::new(),
        read: read_text,
        value: Some("off"),
        precision: None,
        unit,
        points: 0.0,
    };
    let exact = ctx.exact[k];
    let tol = b.tolerance;
    let ok = |g: &mut BoxGrade, verdict, message: String| {
        g.verdict = verdict;
        g.value = Some("ok");
        g.precision = Some("ok");
        g.points = 1.0;
        g.message = message;
    };
    if unit == Some("wrong") {
        let want = b.unit.unwrap_or("no unit");
        g.message = match a.unit {
            Some(u) if tol.accepts(exact, a.x) => {
                format!("The number is right but the unit is not: this box is in {want}, not {u}.")
            }
            Some(u) => format!("This box is in {want}; {u} does not fit it."),
            None => format!("This box is in {want}."),
        };
        if tol.accepts(exact, a.x) {
            g.value = Some("ok");
            g.points = 0.5;
        }
        return (g, Some(a));
    }
    if tol.accepts(exact, a.x) {
        ok(&mut g, Verdict::Correct, "Correct.".into());
        return (g, Some(a));
    }
    if as_printed(b, exact, &a) {
        let msg = format!(
            "Correct to {}, as the course notes print it.",
            b.printed_half.map(decimals_of).unwrap_or_default()
        );
        ok(&mut g, Verdict::Correct, msg);
        return (g, Some(a));
    }
    // the digits demanded: the tolerance's, or the course's where it prints fewer
    let demanded = tol.allowed(exact).max(b.printed_half.unwrap_or(0.0));
    let coarse_limit = (10.0 * demanded).max(0.005 * exact.abs());
    if a.half_ulp > demanded
        && a.half_ulp <= coarse_limit
        && (a.x - exact).abs() <= a.half_ulp * (1.0 + 1e-9)
    {
        g.verdict = Verdict::Imprecise;
        g.value = Some("ok");
        g.precision = Some("coarse");
        g.points = 0.5;
        g.message = format!(
            "Right, but give at least {}: this box asks for {}.",
            digits_needed(exact, demanded),
            match b.printed_half {
                Some(half) => format!(
                    "{}, or {} as the course notes print it",
                    super::tolerance_text(tol, b.unit),
                    decimals_of(half)
                ),
                None => super::tolerance_text(tol, b.unit),
            }
        );
        return (g, Some(a));
    }
    if let Some(chain) = ctx.spec.chain {
        if let Some(msg) = carried(ctx, chain, k, a.x) {
            ok(&mut g, Verdict::Consistent, msg);
            return (g, Some(a));
        }
        if let Some(msg) = rounded_as_shown(ctx, chain, k, a.x) {
            ok(&mut g, Verdict::Correct, msg);
            return (g, Some(a));
        }
        if let Some(msg) = from_own_rounding(ctx, chain, k, a.x) {
            ok(&mut g, Verdict::Correct, msg);
            return (g, Some(a));
        }
    }
    // The generic slips, only where they fit the box: a sign flip where the
    // box says what one means there, a factor of ten where the value is
    // not a whole count.
    const DECIMAL: &str = "Off by a factor of 10: a unit or a decimal point slipped.";
    let mut generic = Vec::new();
    if let Some(explain) = b.sign_flip {
        generic.push((-exact, "sign flipped", explain));
    }
    if tol != tol::WHOLE {
        generic.push((exact * 10.0, "decimal slip", DECIMAL));
        generic.push((exact / 10.0, "decimal slip", DECIMAL));
    }
    let named = ctx
        .mistakes
        .iter()
        .filter(|m| m.key == b.key)
        .map(|m| (m.value, m.name, m.explain))
        .chain(generic);
    for (value, name, explain) in named {
        if value.is_finite() && tol.accepts(value, a.x) && !tol.accepts(exact, value) {
            g.mistake = Some(name);
            g.message = format!("Not quite — {name}? {explain}");
            return (g, Some(a));
        }
    }
    g.message = match super::tolerance_text(tol, b.unit).as_str() {
        "exact" => "Not the expected value. Try the hints.".to_string(),
        within => format!("Not within {within} of the expected value. Try the hints."),
    };
    (g, Some(a))
}

/// "Consistent with your …": the answer follows from the student's own
/// earlier answers, one of which is off.
fn carried(ctx: &Ctx, chain: super::Chain, k: usize, x: f64) -> Option<String> {
    let mut given = Record::new();
    let mut off = Vec::new();
    for (j, a) in ctx.earlier.iter().enumerate() {
        if let Some(a) = a {
            given.set(&ctx.boxes[j].key, a.x);
            if !right(&ctx.boxes[j], ctx.exact[j], a) {
                off.push(j);
            }
        }
    }
    if off.is_empty() {
        return None;
    }
    let b = &ctx.boxes[k];
    let value = chain(ctx.inputs, &given).ok()?.number(&b.key)?;
    if b.tolerance.accepts(value, x) && !b.tolerance.accepts(ctx.exact[k], value) {
        let names: Vec<String> = off
            .iter()
            .map(|&j| format!("{} (step {})", ctx.boxes[j].label, j + 1))
            .collect();
        Some(format!(
            "Consistent with your {}: this follows correctly from what you wrote there.",
            names.join(" and ")
        ))
    } else {
        None
    }
}

/// Every earlier box within its tolerance, but this answer follows from
/// them as typed (rounded) rather than from the exact values: correct. A
/// long chain (UTM's series, a fit's σ₀) magnifies an intermediate's
/// allowed rounding beyond a later box's tolerance.
fn from_own_rounding(ctx: &Ctx, chain: super::Chain, k: usize, x: f64) -> Option<String> {
    let mut given = Record::new();
    for (j, a) in ctx.earlier.iter().enumerate() {
        if let Some(a) = a {
            if !right(&ctx.boxes[j], ctx.exact[j], a) {
                return None;
            }
            given.set(&ctx.boxes[j].key, a.x);
        }
    }
    if given.is_empty() {
        return None;
    }
    let b = &ctx.boxes[k];
    let value = chain(ctx.inputs, &given).ok()?.number(&b.key)?;
    b.tolerance
        .accepts(value, x)
        .then(|| "Correct: it follows from your own (rounded) earlier answers.".to_string())
}

/// An answer that follows from an earlier value rounded as shown (to 3, 4
/// or 5 significant digits) is accepted, unless that rounding is far
/// coarser than the earlier box itself asks for (more than ten times its
/// tolerance): k = 1.000128 is never shown as 1.00, and (k − 1)·10⁶ from
/// it would be 0 ppm.
fn rounded_as_shown(ctx: &Ctx, chain: super::Chain, k: usize, x: f64) -> Option<String> {
    let b = &ctx.boxes[k];
    for j in 0..k {
        let (e, t) = (ctx.exact[j], ctx.boxes[j].tolerance);
        for sig in 3..=5 {
            let r = round_sig(e, sig);
            if (r - e).abs() > 10.0 * t.allowed(e) {
                continue;
            }
            let given = Record::new().with(&ctx.boxes[j].key, r);
            let Some(value) = chain(ctx.inputs, &given)
                .ok()
                .and_then(|v| v.number(&b.key))
            else {
                continue;
            };
            if b.tolerance.accepts(value, x) {
                return Some(format!(
                    "Correct: it follows from {} rounded to {}.",
                    ctx.boxes[j].label,
                    shown(r)
                ));
            }
        }
    }
    None
}

/// Tolerances the topic files share.
pub use crate::examples::drill::tol;
