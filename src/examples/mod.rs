//! The worked-example catalog: every entry of `shared/CATALOG.md`, the
//! registry behind `catalog()`, `solve()` and `parse_inputs()`.
//!
//! Each example is one [`Example`] value: id, title, source, fields, solver,
//! answer keys, result labels, its place in the lab and its practice mode.
//! Each topic file (`coordinates.rs`, …) lists its examples in its
//! `TOPIC`; [`TOPICS`] lists the topics. Everything else (the catalog,
//! the module map, `catalog.json`, practice's list) is derived from these.

pub mod answers;
pub mod chains;
pub mod coordinates;
pub mod correlation;
pub mod drill;
pub mod fields;
pub mod filters;
pub mod interest;
pub mod matching;
pub mod projection;
pub mod resampling;
pub mod series;
pub mod transformations;

use crate::error::{Error, Result};
use crate::solution::{Record, Solution, Value};
use drill::Drill;
use fields::{Field, FieldInfo};
use serde::Serialize;

/// The topics in the order the page shows them: the one hand-kept list of
/// topics (each topic file keeps the one list of its examples).
pub const TOPICS: [Topic; 9] = [
    coordinates::TOPIC,
    transformations::TOPIC,
    correlation::TOPIC,
    matching::TOPIC,
    resampling::TOPIC,
    filters::TOPIC,
    interest::TOPIC,
    chains::TOPIC,
    projection::TOPIC,
];

/// A solver: validated inputs (defaults filled in) to a solution.
pub type Solver = fn(&Record) -> Result<Solution>;

/// A topic: its page module (`web/<module>/`, `pkg/<module>.js`), its
/// title, and its examples in page order.
#[derive(Clone, Copy)]
pub struct Topic {
    pub module: &'static str,
    pub title: &'static str,
    pub examples: &'static [Example],
}

/// Where an example meets the image lab: the lab family it opens in, and
/// the lab's readings it explains (the lab links a clicked pixel's reading
/// to this example).
#[derive(Clone, Copy)]
pub struct Lab {
    pub family: &'static str,
    pub explains: &'static [&'static str],
}

impl Lab {
    /// `lab: Some(Lab::new(family, explains))` in a descriptor.
    pub const fn new(family: &'static str, explains: &'static [&'static str]) -> Lab {
        Lab { family, explains }
    }
}

/// Everything about one worked example, declared in one value: what the
/// catalog, the solver, the answer line, the result tables, the lab and
/// practice mode need. Every list the page or the tests keep of examples
/// is derived from these.
#[derive(Clone, Copy)]
pub struct Example {
    pub id: &'static str,
    pub title: &'static str,
    pub source: &'static str,
    pub summary: &'static str,
    /// The input fields with the seed's defaults.
    pub fields: fn() -> Vec<Field>,
    pub solve: Solver,
    /// The one to three result keys of the answer line at the top of the
    /// page ("GSD = 35.65 cm; the course notes print 35.37 cm").
    pub answer: &'static [&'static str],
    /// What result keys mean: `(key, label, unit)` ("" for no unit); the
    /// ones present in a solution are put into its `labels`.
    pub labels: &'static [(&'static str, &'static str, &'static str)],
    pub lab: Option<Lab>,
    /// Practice mode: how variants are drawn and answers checked.
    pub practice: Option<Drill>,
}

impl Example {
    /// Solves with `inputs` (a missing field takes the seed's default),
    /// checking them first: what [`solve`] does once it has found the
    /// example, and what practice calls for a variant.
    pub fn run(&self, inputs: &Record) -> Result<Solution> {
        let used = fields::validate(&(self.fields)(), inputs)?;
        let mut solution = (self.solve)(&used)?;
        solution.label_present(self.labels);
        if solution.answer.is_empty() {
            solution.answer = self
                .answer
                .iter()
                .filter(|k| solution.result.get(k).is_some())
                .map(|k| k.to_string())
                .collect();
        }
        solution.checked()
    }
}

/// Every example of `topics` with its topic, in page order. (`topics` is
/// [`TOPICS`] or a topic module's own list: never look anything up in
/// [`TOPICS`] here, or every topic is linked into every module.)
pub fn of(topics: &'static [Topic]) -> impl Iterator<Item = (&'static Topic, &'static Example)> {
    topics
        .iter()
        .flat_map(|t| t.examples.iter().map(move |e| (t, e)))
}

/// Every example, in page order.
pub fn all() -> impl Iterator<Item = &'static Example> {
    TOPICS.iter().flat_map(|t| t.examples.iter())
}

/// The example `id` among `topics`.
pub fn find(topics: &'static [Topic], id: &str) -> Result<&'static Example> {
    of(topics)
        .map(|(_, e)| e)
        .find(|e| e.id == id)
        .ok_or_else(|| Error::UnknownExample { id: id.to_string() })
}

/// The module (a [`Topic::module`]) that solves example `id`.
pub fn module_of(id: &str) -> Option<&'static str> {
    of(&TOPICS).find(|(_, e)| e.id == id).map(|(t, _)| t.module)
}

/// The JSON shape of a catalog entry.
#[derive(Serialize)]
pub struct EntryInfo {
    pub id: &'static str,
    pub title: &'static str,
    pub topic: &'static str,
    pub source: &'static str,
    /// The course document(s) `source` refers to, named in full.
    pub document: String,
    pub summary: &'static str,
    pub status: &'static str,
    /// Whether practice mode has a generator for this example.
    pub practice: bool,
    /// The wasm module that solves it (a [`Topic::module`]).
    pub module: &'static str,
    /// The image lab's family it opens in, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lab: Option<&'static str>,
    /// The lab's readings it explains.
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    pub explains: &'static [&'static str],
    pub inputs: Vec<FieldInfo>,
}

impl EntryInfo {
    fn new(t: &Topic, e: &Example) -> Self {
        EntryInfo {
            id: e.id,
            title: e.title,
            topic: t.title,
            source: e.source,
            document: answers::document(e.source),
            summary: e.summary,
            status: "ready",
            practice: e.practice.is_some(),
            module: t.module,
            lab: e.lab.map(|l| l.family),
            explains: e.lab.map_or(&[], |l| l.explains),
            inputs: (e.fields)().iter().map(FieldInfo::from).collect(),
        }
    }
}

/// The catalog: every example with its topic, practice, module, lab and
/// input fields (what the build writes to `catalog.json`).
pub fn catalog() -> Vec<EntryInfo> {
    catalog_of(&TOPICS)
}

/// The catalog of `topics` only (a topic module's own).
pub fn catalog_of(topics: &'static [Topic]) -> Vec<EntryInfo> {
    of(topics).map(|(t, e)| EntryInfo::new(t, e)).collect()
}

/// Solves example `id` with `inputs` (a missing field takes the seed's
/// default). Inputs are checked before any arithmetic.
pub fn solve(id: &str, inputs: &Record) -> Result<Solution> {
    solve_in(&TOPICS, id, inputs)
}

/// [`solve`] among `topics` only (a topic module's).
pub fn solve_in(topics: &'static [Topic], id: &str, inputs: &Record) -> Result<Solution> {
    find(topics, id)?.run(inputs)
}

/// Texts parsed into typed inputs, and a message for each field that failed.
#[derive(Debug, Serialize, PartialEq)]
pub struct Parsed {
    pub inputs: Record,
    pub errors: Record,
}

/// Parses the texts of a form or URL (`{key: text}`) into typed inputs with
/// the same checks as [`solve`]; every failing field gets its own message.
pub fn parse_inputs(id: &str, texts: &Record) -> Result<Parsed> {
    parse_inputs_in(&TOPICS, id, texts)
}

/// [`parse_inputs`] among `entries` only (a topic module's).
pub fn parse_inputs_in(topics: &'static [Topic], id: &str, texts: &Record) -> Result<Parsed> {
    let entry = find(topics, id)?;
    let fields = (entry.fields)();
    let mut out = Parsed {
        inputs: Record::new(),
        errors: Record::new(),
    };
    for (key, v) in texts.iter() {
        let Some(field) = fields.iter().find(|f| f.key == key) else {
            let known: Vec<_> = fields.iter().map(|f| f.key.to_string()).collect();
            let e = Error::UnknownField {
                field: key.to_string(),
                known,
            };
            out.errors.set(key, Value::Text(e.to_string()));
            continue;
        };
        let parsed = match v {
            Value::Text(t) => field.parse_text(t),
            other => field.check(other),
        };
        match parsed {
            Ok(value) => out.inputs.set(key, value),
            // A field that does not apply in the chosen mode never blocks.
            Err(_) if !fields::applies(&fields, field, texts) => {}
            Err(e) => out.errors.set(key, Value::Text(e.to_string())),
        }
    }
    Ok(out)
}
