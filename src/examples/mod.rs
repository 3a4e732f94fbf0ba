//! The worked-example catalog: every entry of `shared/CATALOG.md`, the
//! registry behind `catalog()`, `solve()` and `parse_inputs()`.
//!
//! Each topic file (`coordinates.rs`, …) lists its entries with their input
//! fields and a solver that calls the core modules and turns their results
//! into a [`Solution`]. Entries not built yet are listed in [`coming`].
//!
//! To add an example: write `fn fields() -> Vec<Field>` and
//! `fn solve(inputs: &Record) -> Result<Solution>` in its topic file, list it
//! in that file's `entries()`, and remove it from [`coming`].

pub mod answers;
pub mod chains;
pub mod coordinates;
pub mod correlation;
pub mod fields;
pub mod filters;
pub mod interest;
pub mod matching;
pub mod projection;
pub mod projection_facts;
pub mod projection_figure;
pub mod resampling;
pub mod transformations;

use crate::error::{Error, Result};
use crate::solution::{Record, Solution, Value};
use fields::{Field, FieldInfo};
use serde::Serialize;

/// The topics in the order the page shows them.
pub const TOPICS: [&str; 9] = [
    "Coordinates",
    "Transformations",
    "Correlation",
    "Least-squares matching",
    "Resampling",
    "Filters and edges",
    "Interest operators",
    "Chain codes and boundaries",
    "Map projection",
];

/// A solver: validated inputs (defaults filled in) to a solution.
pub type Solver = fn(&Record) -> Result<Solution>;

/// A topic file's list of entries (`coordinates::entries`, …).
pub type Entries = fn() -> Vec<Entry>;

/// One catalog entry.
pub struct Entry {
    pub id: &'static str,
    pub title: &'static str,
    pub topic: &'static str,
    pub source: &'static str,
    pub summary: &'static str,
    /// The input fields with the seed's defaults.
    pub fields: fn() -> Vec<Field>,
    /// `None` while the example is not built yet.
    pub solve: Option<Solver>,
}

impl Entry {
    /// An entry that is listed but not built yet.
    #[allow(dead_code)] // none is coming at the moment
    const fn coming(
        id: &'static str,
        title: &'static str,
        topic: &'static str,
        source: &'static str,
    ) -> Self {
        Entry {
            id,
            title,
            topic,
            source,
            summary: "",
            fields: Vec::new,
            solve: None,
        }
    }
}

/// Entries of the catalog that are not built yet.
fn coming() -> Vec<Entry> {
    Vec::new()
}

/// The page's wasm modules of worked examples: one per topic, each its own
/// small crate under `web/<name>/` that exports only these entries (see
/// `export_examples!` in `src/wasm.rs`), so that an example's page loads
/// only its topic's code. `catalog.json` names each entry's module.
///
/// A topic module must never call [`entries`], [`catalog`], [`solve`] or
/// [`parse_inputs`]: those reach every topic and would link them all in.
pub const MODULES: [(&str, Entries); 9] = [
    ("coordinates", coordinates::entries),
    ("transformations", transformations::entries),
    ("correlation", correlation::entries),
    ("matching", matching::entries),
    ("resampling", resampling::entries),
    ("filters", filters::entries),
    ("interest", interest::entries),
    ("chains", chains::entries),
    ("projection", projection::entries),
];

/// The module (a name of [`MODULES`]) that solves example `id`.
pub fn module_of(id: &str) -> Option<&'static str> {
    MODULES
        .iter()
        .find(|(_, entries)| entries().iter().any(|e| e.id == id))
        .map(|(name, _)| *name)
}

/// Every entry, grouped by topic in [`TOPICS`] order.
pub fn entries() -> Vec<Entry> {
    let mut all: Vec<Entry> = MODULES.iter().flat_map(|(_, entries)| entries()).collect();
    all.extend(coming());
    all.sort_by_key(|e| {
        TOPICS
            .iter()
            .position(|t| *t == e.topic)
            .unwrap_or(TOPICS.len())
    });
    all
}

fn find(entries: Vec<Entry>, id: &str) -> Result<Entry> {
    entries
        .into_iter()
        .find(|e| e.id == id)
        .ok_or_else(|| Error::UnknownExample { id: id.to_string() })
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
    /// Whether practice mode has a generator for this example (in the whole
    /// catalog; a topic module's own catalog leaves it out, as it leaves
    /// practice out).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub practice: Option<bool>,
    /// The wasm module that solves it (a name of [`MODULES`]; in the whole
    /// catalog only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub module: Option<&'static str>,
    pub inputs: Vec<FieldInfo>,
}

impl EntryInfo {
    fn new(e: &Entry) -> Self {
        EntryInfo {
            id: e.id,
            title: e.title,
            topic: e.topic,
            source: e.source,
            document: answers::document(e.source),
            summary: e.summary,
            status: if e.solve.is_some() { "ready" } else { "coming" },
            practice: None,
            module: None,
            inputs: (e.fields)().iter().map(FieldInfo::from).collect(),
        }
    }
}

/// The catalog: every entry with its status, practice, module and input
/// fields (what the build writes to `catalog.json`).
pub fn catalog() -> Vec<EntryInfo> {
    entries()
        .iter()
        .map(|e| EntryInfo {
            practice: Some(crate::practice::has(e.id)),
            module: module_of(e.id),
            ..EntryInfo::new(e)
        })
        .collect()
}

/// The catalog of `entries` only (a topic module's own): without
/// `practice` and `module`, which would reach every topic.
pub fn catalog_of(entries: Vec<Entry>) -> Vec<EntryInfo> {
    entries.iter().map(EntryInfo::new).collect()
}

/// Solves example `id` with `inputs` (a missing field takes the seed's
/// default). Inputs are checked before any arithmetic.
pub fn solve(id: &str, inputs: &Record) -> Result<Solution> {
    solve_in(entries(), id, inputs)
}

/// [`solve`] among `entries` only (a topic module's).
pub fn solve_in(entries: Vec<Entry>, id: &str, inputs: &Record) -> Result<Solution> {
    let entry = find(entries, id)?;
    let solver = entry
        .solve
        .ok_or_else(|| Error::NotBuilt { id: id.to_string() })?;
    let used = fields::validate(&(entry.fields)(), inputs)?;
    let mut solution = solver(&used)?;
    if solution.answer.is_empty() {
        solution.answer = answers::keys(id)
            .iter()
            .filter(|k| solution.result.get(k).is_some())
            .map(|k| k.to_string())
            .collect();
    }
    solution.checked()
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
    parse_inputs_in(entries(), id, texts)
}

/// [`parse_inputs`] among `entries` only (a topic module's).
pub fn parse_inputs_in(entries: Vec<Entry>, id: &str, texts: &Record) -> Result<Parsed> {
    let entry = find(entries, id)?;
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
