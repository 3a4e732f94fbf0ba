//! The step-by-step trace a worked example returns: [`Solution`], [`Step`],
//! [`Note`], and the plain [`Value`] they carry. All of it serialises to the
//! plain JS data described in `docs/API.md`.

use crate::error::{Error, Result};
use serde::de::{self, Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::ser::{Serialize, SerializeMap, Serializer};
use std::fmt;

/// A plain data value: what inputs, results and step values are made of.
///
/// Unlike a JSON value it keeps NaN and infinities, so that validation can say
/// "is NaN" instead of seeing a null.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    Null,
    Bool(bool),
    Number(f64),
    Text(String),
    List(Vec<Value>),
    Object(Record),
}

impl Value {
    /// A short description of the value's type, for error messages.
    pub fn type_name(&self) -> &'static str {
        match self {
            Value::Null => "null",
            Value::Bool(_) => "a boolean",
            Value::Number(_) => "a number",
            Value::Text(_) => "a string",
            Value::List(_) => "a list",
            Value::Object(_) => "an object",
        }
    }

    /// A list of numbers.
    pub fn numbers(xs: &[f64]) -> Value {
        Value::List(xs.iter().map(|&x| Value::Number(x)).collect())
    }

    /// A matrix (list of rows) of numbers.
    pub fn matrix(rows: &[Vec<f64>]) -> Value {
        Value::List(rows.iter().map(|r| Value::numbers(r)).collect())
    }

    /// The number inside, if this is a number.
    pub fn as_f64(&self) -> Option<f64> {
        match self {
            Value::Number(x) => Some(*x),
            _ => None,
        }
    }

    /// True when any number inside is NaN or infinite.
    pub fn has_non_finite(&self) -> bool {
        match self {
            Value::Number(x) => !x.is_finite(),
            Value::List(xs) => xs.iter().any(Value::has_non_finite),
            Value::Object(r) => r.iter().any(|(_, v)| v.has_non_finite()),
            _ => false,
        }
    }
}

impl From<f64> for Value {
    fn from(x: f64) -> Self {
        Value::Number(x)
    }
}
impl From<usize> for Value {
    fn from(x: usize) -> Self {
        Value::Number(x as f64)
    }
}
impl From<bool> for Value {
    fn from(x: bool) -> Self {
        Value::Bool(x)
    }
}
impl From<&str> for Value {
    fn from(x: &str) -> Self {
        Value::Text(x.to_string())
    }
}
impl From<Option<f64>> for Value {
    fn from(x: Option<f64>) -> Self {
        x.map_or(Value::Null, Value::Number)
    }
}

impl Serialize for Value {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        match self {
            Value::Null => s.serialize_unit(),
            Value::Bool(b) => s.serialize_bool(*b),
            Value::Number(x) => s.serialize_f64(*x),
            Value::Text(t) => s.serialize_str(t),
            Value::List(xs) => xs.serialize(s),
            Value::Object(r) => r.serialize(s),
        }
    }
}

impl<'de> Deserialize<'de> for Value {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        d.deserialize_any(ValueVisitor)
    }
}

struct ValueVisitor;

impl<'de> Visitor<'de> for ValueVisitor {
    type Value = Value;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a plain data value")
    }
    fn visit_unit<E>(self) -> std::result::Result<Value, E> {
        Ok(Value::Null)
    }
    fn visit_none<E>(self) -> std::result::Result<Value, E> {
        Ok(Value::Null)
    }
    fn visit_some<D: Deserializer<'de>>(self, d: D) -> std::result::Result<Value, D::Error> {
        Value::deserialize(d)
    }
    fn visit_bool<E>(self, b: bool) -> std::result::Result<Value, E> {
        Ok(Value::Bool(b))
    }
    fn visit_i64<E>(self, x: i64) -> std::result::Result<Value, E> {
        Ok(Value::Number(x as f64))
    }
    fn visit_u64<E>(self, x: u64) -> std::result::Result<Value, E> {
        Ok(Value::Number(x as f64))
    }
    fn visit_f64<E>(self, x: f64) -> std::result::Result<Value, E> {
        Ok(Value::Number(x))
    }
    fn visit_str<E: de::Error>(self, s: &str) -> std::result::Result<Value, E> {
        Ok(Value::Text(s.to_string()))
    }
    fn visit_string<E>(self, s: String) -> std::result::Result<Value, E> {
        Ok(Value::Text(s))
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> std::result::Result<Value, A::Error> {
        let mut out = Vec::new();
        while let Some(v) = seq.next_element()? {
            out.push(v);
        }
        Ok(Value::List(out))
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> std::result::Result<Value, A::Error> {
        let mut out = Record::new();
        while let Some((k, v)) = map.next_entry::<String, Value>()? {
            out.set(&k, v);
        }
        Ok(Value::Object(out))
    }
}

/// A map from names to values that keeps insertion order (results are shown
/// in the order the catalog lists their keys).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Record(Vec<(String, Value)>);

impl Record {
    pub fn new() -> Self {
        Record(Vec::new())
    }
    /// Sets `key` (replacing an earlier value of the same key in place).
    pub fn set(&mut self, key: &str, value: impl Into<Value>) {
        let value = value.into();
        match self.0.iter_mut().find(|(k, _)| k == key) {
            Some(slot) => slot.1 = value,
            None => self.0.push((key.to_string(), value)),
        }
    }
    /// Builder form of [`Record::set`].
    pub fn with(mut self, key: &str, value: impl Into<Value>) -> Self {
        self.set(key, value);
        self
    }
    pub fn get(&self, key: &str) -> Option<&Value> {
        self.0.iter().find(|(k, _)| k == key).map(|(_, v)| v)
    }
    pub fn keys(&self) -> impl Iterator<Item = &str> {
        self.0.iter().map(|(k, _)| k.as_str())
    }
    pub fn iter(&self) -> impl Iterator<Item = (&str, &Value)> {
        self.0.iter().map(|(k, v)| (k.as_str(), v))
    }
    pub fn len(&self) -> usize {
        self.0.len()
    }
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
    /// The number stored under `key`, if there is one.
    pub fn number(&self, key: &str) -> Option<f64> {
        self.get(key).and_then(Value::as_f64)
    }
}

impl Serialize for Record {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in &self.0 {
            m.serialize_entry(k, v)?;
        }
        m.end()
    }
}

/// What a note is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum NoteKind {
    /// The seed prints something wrong: a slip, a typo, a wrong sign.
    Erratum,
    /// The seed's value differs because it rounded an intermediate.
    Rounding,
    /// A convention the computation follows (axes, origins, counting).
    Convention,
    /// The inputs are valid but unusual (a point outside the image).
    Warning,
}

/// A remark attached to a solution.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Note {
    pub kind: NoteKind,
    pub text: String,
    /// The result or textbook keys the note concerns (possibly none): the
    /// page places the note beside them, and shows a printed value that
    /// differs under an "erratum" or "convention" note as such.
    pub keys: Vec<String>,
}

impl Note {
    /// True when the note names `key`.
    pub fn concerns(&self, key: &str) -> bool {
        self.keys.iter().any(|k| k == key)
    }
}

/// The note just added by [`Solution::note`], to name its keys.
pub struct NoteKeys<'a>(&'a mut Vec<Note>);

impl NoteKeys<'_> {
    /// Names the result or textbook keys the note concerns.
    pub fn about(self, keys: &[&str]) {
        if let Some(n) = self.0.last_mut() {
            n.keys.extend(keys.iter().map(|k| k.to_string()));
        }
    }
}

/// One step of a worked solution.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Step {
    pub title: String,
    /// Plain text explaining the step.
    pub text: String,
    /// The formula in LaTeX, with symbols.
    pub formula: String,
    /// The same formula with the numbers put in (LaTeX).
    pub substituted: String,
    /// The step's numbers, for figures and tables.
    pub values: Record,
}

impl Step {
    pub fn new(title: &str, text: &str) -> Self {
        Step {
            title: title.to_string(),
            text: text.to_string(),
            formula: String::new(),
            substituted: String::new(),
            values: Record::new(),
        }
    }
    pub fn formula(mut self, symbolic: &str, substituted: String) -> Self {
        self.formula = symbolic.to_string();
        self.substituted = substituted;
        self
    }
    pub fn value(mut self, key: &str, v: impl Into<Value>) -> Self {
        self.values.set(key, v);
        self
    }
}

/// A whole worked solution: the inputs as used, the steps, the result, the
/// seed's printed values when the inputs are the seed's, and notes.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Solution {
    pub id: String,
    pub title: String,
    pub inputs: Record,
    pub steps: Vec<Step>,
    pub result: Record,
    pub textbook: Option<Record>,
    pub notes: Vec<Note>,
    /// The one to three result keys that are the answer of the example,
    /// for the answer line at the top of the page.
    pub answer: Vec<String>,
    /// What each result key means: `{ key: { label, unit } }` (unit may be
    /// null), for tables a student can read. Keys without one show as is.
    pub labels: Record,
}

impl Solution {
    pub fn new(id: &str, title: &str, inputs: Record) -> Self {
        Solution {
            id: id.to_string(),
            title: title.to_string(),
            inputs,
            steps: Vec::new(),
            result: Record::new(),
            textbook: None,
            notes: Vec::new(),
            answer: Vec::new(),
            labels: Record::new(),
        }
    }
    /// Says what result `key` is, for the page: `label` in words and its
    /// `unit` ("" when it has none).
    pub fn label(&mut self, key: &str, label: &str, unit: &str) {
        let unit = if unit.is_empty() {
            Value::Null
        } else {
            Value::from(unit)
        };
        self.labels.set(
            key,
            Value::Object(Record::new().with("label", label).with("unit", unit)),
        );
    }
    /// Labels the results that are present, from a table of
    /// `(key, label, unit)` rows shared by a topic's examples.
    pub fn label_present(&mut self, table: &[(&str, &str, &str)]) {
        for &(key, label, unit) in table {
            if self.result.get(key).is_some() {
                self.label(key, label, unit);
            }
        }
    }
    pub fn step(&mut self, step: Step) {
        self.steps.push(step);
    }
    /// Adds a note; chain [`Note::about`] to name the keys it concerns:
    /// `s.note(NoteKind::Rounding, "…").about(&["gsd_cm"]);`
    pub fn note(&mut self, kind: NoteKind, text: impl Into<String>) -> NoteKeys<'_> {
        self.notes.push(Note {
            kind,
            text: text.into(),
            keys: Vec::new(),
        });
        NoteKeys(&mut self.notes)
    }
    /// Final check before a solution leaves the core: no NaN or infinity in
    /// the result or the step values (a bug if it happens, reported as such).
    pub fn checked(self) -> Result<Self> {
        for (k, v) in self.result.iter() {
            if v.has_non_finite() {
                return Err(Error::Internal(format!(
                    "result \"{k}\" of {} is not a finite number",
                    self.id
                )));
            }
        }
        for s in &self.steps {
            for (k, v) in s.values.iter() {
                if v.has_non_finite() {
                    return Err(Error::Internal(format!(
                        "value \"{k}\" of step \"{}\" is not a finite number",
                        s.title
                    )));
                }
            }
        }
        Ok(self)
    }
}

/// Formats a number for text and LaTeX: up to `sig` significant digits,
/// trailing zeros dropped, a real minus sign avoided (plain `-`).
pub fn fmt_sig(x: f64, sig: usize) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    if x == 0.0 {
        return "0".to_string();
    }
    let magnitude = x.abs().log10().floor() as i32;
    let decimals = (sig as i32 - 1 - magnitude).max(0) as usize;
    let mut s = format!("{x:.decimals$}");
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.pop();
        }
    }
    if s == "-0" {
        s = "0".to_string();
    }
    s
}

/// The one way a note states how an exact value and a printed one differ:
/// `"exact − printed = +0.065 mm"` (the sign always shown, a real minus).
/// The page's table shows the same difference, exact − printed; a test
/// recomputes every such statement from `result` and `textbook`.
pub fn exact_minus_printed(exact: f64, printed: f64, unit: &str) -> String {
    let d = exact - printed;
    let sign = if d < 0.0 { "−" } else { "+" };
    let unit = if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    };
    format!("exact − printed = {sign}{}{unit}", num(d.abs()))
}

/// [`exact_minus_printed`] and the same difference as a share of the
/// printed value, in one equation so that both carry the one sign:
/// `"exact − printed = +0.065 mm = +0.79 % of the printed value"`
/// ((exact − printed) / |printed|; the share is left out when nothing was
/// printed, 0).
pub fn exact_minus_printed_share(exact: f64, printed: f64, unit: &str) -> String {
    let d = exact_minus_printed(exact, printed, unit);
    if printed == 0.0 {
        return d;
    }
    let p = (exact - printed) / printed.abs() * 100.0;
    let sign = if p < 0.0 { "−" } else { "+" };
    format!("{d} = {sign}{} % of the printed value", fmt_sig(p.abs(), 2))
}

/// [`fmt_sig`] with 7 significant digits: what the steps show.
pub fn num(x: f64) -> String {
    fmt_sig(x, 7)
}

/// A number for LaTeX: negative numbers in parentheses, so that
/// `a - (-3)` reads right when substituted.
pub fn tex(x: f64) -> String {
    let s = num(x);
    if s.starts_with('-') {
        format!("({s})")
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_significant_digits() {
        assert_eq!(num(25.4 / 600.0), "0.04233333");
        assert_eq!(num(8.255), "8.255");
        assert_eq!(num(1920.0 / 0.152), "12631.58");
        assert_eq!(num(-0.0), "0");
        assert_eq!(num(195.0), "195");
        assert_eq!(tex(-12.42), "(-12.42)");
    }

    #[test]
    fn differences_are_exact_minus_printed() {
        assert_eq!(
            exact_minus_printed(8.255, 8.19, "mm"),
            "exact − printed = +0.065 mm"
        );
        assert_eq!(
            exact_minus_printed(1349.055118, 1353.8, "px"),
            "exact − printed = −4.744882 px"
        );
        assert_eq!(exact_minus_printed(0.5, 0.5, ""), "exact − printed = +0");
    }

    #[test]
    fn the_share_carries_the_sign_of_the_difference() {
        assert_eq!(
            exact_minus_printed_share(25.4 / 600.0, 0.0423, "mm"),
            "exact − printed = +0.00003333333 mm = +0.079 % of the printed value"
        );
        assert_eq!(
            exact_minus_printed_share(-1.98, -2.0, ""),
            "exact − printed = +0.02 = +1 % of the printed value"
        );
        assert_eq!(
            exact_minus_printed_share(8.19, 8.255, "mm"),
            "exact − printed = −0.065 mm = −0.79 % of the printed value"
        );
    }

    #[test]
    fn record_keeps_order_and_replaces() {
        let mut r = Record::new().with("b", 1.0).with("a", 2.0);
        r.set("b", 3.0);
        assert_eq!(r.keys().collect::<Vec<_>>(), ["b", "a"]);
        assert_eq!(r.number("b"), Some(3.0));
    }

    #[test]
    fn checked_rejects_nan_results() {
        let mut s = Solution::new("x", "X", Record::new());
        s.result.set("bad", f64::NAN);
        assert!(matches!(s.checked(), Err(Error::Internal(_))));
    }
}
