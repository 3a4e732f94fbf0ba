//! The step-by-step trace a worked example returns: [`Solution`], [`Step`],
//! [`Note`], and the plain [`Value`] they carry. All of it serialises to the
//! plain JS data described in `docs/API.md`.

use crate::error::{Error, Result};
use serde::de::{self, Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::ser::{Serialize, SerializeMap, Serializer};
use std::cell::Cell;
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

/// One piece of a formula: LaTeX, or a matrix given by its cells so that
/// the page can show a long one in blocks without reading LaTeX back.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(untagged)]
pub enum Piece {
    Tex { tex: String },
    Grid { grid: Grid },
}

/// A matrix of a formula: its environment (`bmatrix`, `pmatrix`, `vmatrix`,
/// `array`), its rows of cell LaTeX and, when it has one, its name (the
/// page captions blocks of a long matrix "rows 1–8 of A").
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Grid {
    pub env: &'static str,
    pub rows: Vec<Vec<String>>,
    pub name: Option<String>,
}

impl Piece {
    /// The piece as LaTeX.
    pub fn latex(&self) -> String {
        match self {
            Piece::Tex { tex } => tex.clone(),
            Piece::Grid { grid } => {
                let body = grid
                    .rows
                    .iter()
                    .map(|r| r.join(" & "))
                    .collect::<Vec<_>>()
                    .join(r" \\ ");
                let cols = grid.rows.iter().map(Vec::len).max().unwrap_or(0);
                let spec = if grid.env == "array" {
                    format!("{{{}}}", "r".repeat(cols.max(1)))
                } else {
                    String::new()
                };
                format!(r"\begin{{{0}}}{spec}{body}\end{{{0}}}", grid.env)
            }
        }
    }
}

/// One side of a relation: pieces the page may break a line between (the
/// terms of a long sum are separate pieces; a short form is one piece).
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
#[serde(transparent)]
pub struct Form(pub Vec<Piece>);

impl Form {
    /// A form of several pieces (`["a_0", "+ a_1 x", "+ a_2 y"]`) the page
    /// may break between.
    pub fn terms<S: Into<String>>(terms: impl IntoIterator<Item = S>) -> Self {
        Form(
            terms
                .into_iter()
                .map(|t| Piece::Tex { tex: t.into() })
                .collect(),
        )
    }
    /// A matrix of numbers (cells formatted with [`num`]) in `env`, named
    /// `name` for captions ("" for none).
    pub fn grid(env: &'static str, rows: &[Vec<f64>], name: &str) -> Self {
        Form::grid_tex(
            env,
            rows.iter()
                .map(|r| r.iter().map(|&x| num(x)).collect())
                .collect(),
            name,
        )
    }
    /// A matrix of LaTeX cells.
    pub fn grid_tex(env: &'static str, rows: Vec<Vec<String>>, name: &str) -> Self {
        Form(vec![Piece::Grid {
            grid: Grid {
                env,
                rows,
                name: (!name.is_empty()).then(|| name.to_string()),
            },
        }])
    }
    /// Appends the pieces of `other` (a product of matrices, a matrix
    /// with a factor before it).
    pub fn then(mut self, other: impl Into<Form>) -> Self {
        self.0.extend(other.into().0);
        self
    }
    /// The form as LaTeX (pieces joined by a space).
    pub fn latex(&self) -> String {
        self.0
            .iter()
            .map(Piece::latex)
            .collect::<Vec<_>>()
            .join(" ")
    }
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
    /// A column vector of numbers (a one-column `bmatrix`), named `name`
    /// for captions ("" for none).
    pub fn column(xs: &[f64], name: &str) -> Self {
        let rows: Vec<Vec<f64>> = xs.iter().map(|&x| vec![x]).collect();
        Form::grid("bmatrix", &rows, name)
    }
}

impl From<&str> for Form {
    fn from(t: &str) -> Self {
        Form(vec![Piece::Tex { tex: t.to_string() }])
    }
}
impl From<String> for Form {
    fn from(tex: String) -> Self {
        Form(vec![Piece::Tex { tex }])
    }
}
impl From<&String> for Form {
    fn from(t: &String) -> Self {
        Form::from(t.as_str())
    }
}

/// One equation (or other relation) of a step: `lhs op symbolic… `, and
/// with the numbers put in `lhs op substituted… op result…`.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Relation {
    /// The result or step value this relation computes, if it is one (what
    /// practice's hints point at).
    pub key: Option<String>,
    pub lhs: Form,
    /// The relation sign as LaTeX: `=`, `\approx`, `<`, `\Rightarrow` ….
    pub op: String,
    /// Right-hand sides with symbols, left to right.
    pub symbolic: Vec<Form>,
    /// Right-hand sides with the numbers put in.
    pub substituted: Vec<Form>,
    /// What it comes to, with its unit (later forms: the same value in
    /// another unit or rounding).
    pub result: Vec<Form>,
}

impl Relation {
    /// A relation `lhs = …` (add sides with [`sym`](Self::sym),
    /// [`subst`](Self::subst), [`result`](Self::result)).
    pub fn new(lhs: impl Into<Form>) -> Self {
        Relation {
            key: None,
            lhs: lhs.into(),
            op: "=".to_string(),
            symbolic: Vec::new(),
            substituted: Vec::new(),
            result: Vec::new(),
        }
    }
    /// The key of the value it computes.
    pub fn key(mut self, key: &str) -> Self {
        self.key = Some(key.to_string());
        self
    }
    /// Another relation sign than `=`.
    pub fn op(mut self, op: &str) -> Self {
        self.op = op.to_string();
        self
    }
    /// A right-hand side with symbols.
    pub fn sym(mut self, f: impl Into<Form>) -> Self {
        self.symbolic.push(f.into());
        self
    }
    /// A right-hand side with the numbers put in.
    pub fn subst(mut self, f: impl Into<Form>) -> Self {
        self.substituted.push(f.into());
        self
    }
    /// What it comes to, as LaTeX (a unit included: [`with_unit`]).
    pub fn result(mut self, f: impl Into<Form>) -> Self {
        self.result.push(f.into());
        self
    }
    /// What it comes to: a number ([`num`]) and its unit ("" for none).
    pub fn value(self, x: f64, unit: &str) -> Self {
        self.result(with_unit(&num(x), unit))
    }
    fn chain(&self, sides: &[&[Form]]) -> String {
        let mut out = self.lhs.latex();
        for f in sides.iter().flat_map(|s| s.iter()) {
            if out.is_empty() {
                out = f.latex();
            } else {
                out = format!("{out} {} {}", self.op, f.latex());
            }
        }
        out
    }
    /// `lhs op symbolic…` as LaTeX ("" when it has no symbolic side).
    pub fn symbolic_latex(&self) -> String {
        if self.symbolic.is_empty() {
            return String::new();
        }
        self.chain(&[&self.symbolic])
    }
    /// `lhs op substituted… op result…` as LaTeX ("" when it has neither:
    /// a rule with symbols only has no numbers to show).
    pub fn substituted_latex(&self) -> String {
        if self.substituted.is_empty() && self.result.is_empty() {
            return String::new();
        }
        self.chain(&[&self.substituted, &self.result])
    }
    /// `lhs op substituted… op ?`: the numbers without what they come to
    /// (practice's third hint); "" when nothing is substituted.
    pub fn question_latex(&self) -> String {
        if self.substituted.is_empty() {
            return String::new();
        }
        format!(r"{} {} \;?", self.chain(&[&self.substituted]), self.op)
    }
}

/// A number or LaTeX value with its unit: `255\,\text{mm}`.
pub fn with_unit(value: &str, unit: &str) -> String {
    if unit.is_empty() {
        value.to_string()
    } else {
        format!(r"{value}\,\text{{{unit}}}")
    }
}

/// The separator of the relations of one step in its LaTeX strings.
const RELATIONS_APART: &str = r",\quad ";

thread_local! {
    /// False inside [`without_steps`].
    static STEPS_WANTED: Cell<bool> = const { Cell::new(true) };
}

/// Whether the solution being built keeps its steps: false inside
/// [`without_steps`] (a sweep's series, `crate::examples::series`, reads only the
/// results). A solver may skip work whose only output is a step (a
/// figure's data) when it is false — never work a result depends on.
pub fn steps_wanted() -> bool {
    STEPS_WANTED.with(Cell::get)
}

/// Runs `f` (a solver) without building steps: [`Solution::step`] drops
/// them and [`Step::relation`] joins no LaTeX. Results, notes and errors
/// are the solver's own, as with steps.
pub fn without_steps<T>(f: impl FnOnce() -> T) -> T {
    /// Puts the flag back however `f` ends.
    struct Restore(bool);
    impl Drop for Restore {
        fn drop(&mut self) {
            STEPS_WANTED.with(|c| c.set(self.0));
        }
    }
    let _restore = Restore(STEPS_WANTED.with(|c| c.replace(false)));
    f()
}

/// One step of a worked solution.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Step {
    pub title: String,
    /// Plain text explaining the step.
    pub text: String,
    /// The formula in LaTeX, with symbols (made from `parts`).
    pub formula: String,
    /// The same formula with the numbers put in (LaTeX, made from `parts`).
    pub substituted: String,
    /// The formula as data: its relations, from which `formula` and
    /// `substituted` are made (the page lays them out from these).
    pub parts: Vec<Relation>,
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
            parts: Vec::new(),
            values: Record::new(),
        }
    }
    /// Adds a relation; `formula` and `substituted` are made again from
    /// all the relations (the one place LaTeX of a step is put together).
    pub fn relation(mut self, r: Relation) -> Self {
        if !steps_wanted() {
            return self; // the step is dropped: no LaTeX to join
        }
        self.parts.push(r);
        let join = |f: fn(&Relation) -> String| {
            self.parts
                .iter()
                .map(f)
                .filter(|t| !t.is_empty())
                .collect::<Vec<_>>()
                .join(RELATIONS_APART)
        };
        self.formula = join(Relation::symbolic_latex);
        self.substituted = join(Relation::substituted_latex);
        self
    }
    /// Adds several relations in order (a rule whose number of equations
    /// depends on the inputs).
    pub fn relations(self, rs: impl IntoIterator<Item = Relation>) -> Self {
        rs.into_iter().fold(self, Step::relation)
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
    /// Adds a step (dropped inside [`without_steps`]).
    pub fn step(&mut self, step: Step) {
        if steps_wanted() {
            self.steps.push(step);
        }
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
    fn a_step_s_latex_is_made_from_its_relations() {
        let step = Step::new("GSD", "")
            .relation(
                Relation::new("GSD")
                    .key("gsd_cm")
                    .sym(r"\frac{p H}{c}")
                    .subst(r"\frac{0.028 \cdot 1000}{152}")
                    .value(0.18421, "mm")
                    .result(with_unit("0.018421", "cm")),
            )
            .relation(
                Relation::new("k")
                    .op(r"\approx")
                    .subst("2 + 2")
                    .value(4.0, ""),
            );
        assert_eq!(step.formula, r"GSD = \frac{p H}{c}");
        assert_eq!(
            step.substituted,
            r"GSD = \frac{0.028 \cdot 1000}{152} = 0.18421\,\text{mm} = 0.018421\,\text{cm},\quad k \approx 2 + 2 \approx 4"
        );
        assert_eq!(
            step.parts[0].question_latex(),
            r"GSD = \frac{0.028 \cdot 1000}{152} = \;?"
        );
        let m = Form::grid("bmatrix", &[vec![1.0, -2.5], vec![0.0, 3.0]], "A");
        assert_eq!(m.latex(), r"\begin{bmatrix}1 & -2.5 \\ 0 & 3\end{bmatrix}");
        let json = serde_json::to_string(&step.parts[0]).unwrap();
        assert!(json.contains(r#""lhs":[{"tex":"GSD"}]"#), "{json}");
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
