//! Input fields of the worked examples: their kinds, limits and seed
//! defaults, the checks every input passes before any arithmetic, and the
//! text form the page and the URL use. One place decides what is valid, for
//! `solve` (typed values) and `parse_inputs` (texts) alike.

use crate::error::{Error, Result};
use crate::read::{self, short};
use crate::solution::{fmt_sig, Record, Value};
use serde::Serialize;

/// Largest number of elements a vector or point list may have.
pub const MAX_LEN: usize = 4096;
/// Largest number of rows or columns of a matrix.
pub const MAX_DIM: usize = 512;

/// The kind of an input field and its limits.
#[derive(Debug, Clone, PartialEq)]
pub enum Kind {
    /// A real number, with a unit and optional bounds.
    Number {
        unit: Option<&'static str>,
        min: Option<f64>,
        max: Option<f64>,
        /// `min` itself is not allowed (a dpi of 0 is not a resolution).
        min_exclusive: bool,
    },
    /// A whole number with optional bounds.
    Integer { min: Option<f64>, max: Option<f64> },
    /// A list of numbers.
    Vector { min_len: usize, max_len: usize },
    /// A matrix; `None` means any size up to [`MAX_DIM`].
    Matrix {
        rows: Option<usize>,
        cols: Option<usize>,
    },
    /// A list of points, each `point_len` numbers.
    Points {
        point_len: usize,
        min_len: usize,
        max_len: usize,
        /// Column names, when the page should offer a table to edit the
        /// points (else only the text).
        columns: Option<&'static [&'static str]>,
    },
    /// One of a fixed set of option values.
    Choice {
        options: &'static [(&'static str, &'static str)],
    },
    /// True or false.
    Flag,
    /// An angle in degrees, typed as decimal degrees or degrees, minutes and
    /// seconds with an optional hemisphere letter (`55°30'N`); |angle| ≤ max.
    Angle { max: f64, pos: char, neg: char },
}

/// One input of a worked example.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    pub key: &'static str,
    pub label: &'static str,
    pub help: &'static str,
    pub kind: Kind,
    /// The seed's value.
    pub default: Value,
    /// `Some`: the field applies only in some modes (see [`When`]).
    pub when: Option<When>,
}

/// A field that applies only when field `key`'s value (a choice's text) is
/// one of `values`. A field that does not apply is never an error: `solve`
/// ignores its value and `parse_inputs` does not check it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct When {
    pub key: &'static str,
    pub values: &'static [&'static str],
}

impl When {
    /// True when `value` (the controlling field's value) is one of `values`.
    pub fn holds(&self, value: Option<&Value>) -> bool {
        match value {
            Some(Value::Text(t)) => self.values.contains(&t.trim()),
            _ => false,
        }
    }
}

impl Field {
    /// A number field with the seed's default.
    pub fn number(key: &'static str, label: &'static str, default: f64) -> Self {
        Field {
            key,
            label,
            help: "",
            kind: Kind::Number {
                unit: None,
                min: None,
                max: None,
                min_exclusive: false,
            },
            default: Value::Number(default),
            when: None,
        }
    }

    /// Makes the field apply only when field `key` is one of `values`.
    pub fn when(mut self, key: &'static str, values: &'static [&'static str]) -> Self {
        self.when = Some(When { key, values });
        self
    }

    /// Sets the help text.
    pub fn help(mut self, help: &'static str) -> Self {
        self.help = help;
        self
    }

    /// Sets the unit of a number field.
    pub fn unit(mut self, u: &'static str) -> Self {
        if let Kind::Number { unit, .. } = &mut self.kind {
            *unit = Some(u);
        }
        self
    }

    /// Bounds a number field to `(0, max]`.
    pub fn positive(mut self, upper: f64) -> Self {
        if let Kind::Number {
            min,
            max,
            min_exclusive,
            ..
        } = &mut self.kind
        {
            *min = Some(0.0);
            *min_exclusive = true;
            *max = Some(upper);
        }
        self
    }

    /// An integer field with the seed's default.
    pub fn integer(key: &'static str, label: &'static str, default: f64) -> Self {
        Field {
            kind: Kind::Integer {
                min: None,
                max: None,
            },
            ..Field::number(key, label, default)
        }
    }

    /// Bounds a number or integer field to `[lo, hi]`.
    pub fn range(mut self, lo: f64, hi: f64) -> Self {
        match &mut self.kind {
            Kind::Number {
                min,
                max,
                min_exclusive,
                ..
            } => {
                *min = Some(lo);
                *max = Some(hi);
                *min_exclusive = false;
            }
            Kind::Integer { min, max } => {
                *min = Some(lo);
                *max = Some(hi);
            }
            _ => {}
        }
        self
    }

    /// A point-list field: each point `point_len` numbers, at most `max_len`
    /// points (at least one; the solver says how many its model needs).
    pub fn points(
        key: &'static str,
        label: &'static str,
        point_len: usize,
        max_len: usize,
        default: &[Vec<f64>],
    ) -> Self {
        Field {
            key,
            label,
            help: "",
            kind: Kind::Points {
                point_len,
                min_len: 1,
                max_len,
                columns: None,
            },
            default: Value::matrix(default),
            when: None,
        }
    }

    /// Names the columns of a point-list field: the page then edits the
    /// points in a table (with add and remove buttons) beside the text.
    pub fn columns(mut self, names: &'static [&'static str]) -> Self {
        if let Kind::Points { columns, .. } = &mut self.kind {
            *columns = Some(names);
        }
        self
    }

    /// A choice field; `options` are `(value, label)` pairs.
    pub fn choice(
        key: &'static str,
        label: &'static str,
        options: &'static [(&'static str, &'static str)],
        default: &'static str,
    ) -> Self {
        Field {
            key,
            label,
            help: "",
            kind: Kind::Choice { options },
            default: Value::from(default),
            when: None,
        }
    }

    /// An angle field (degrees or degrees-minutes-seconds) within ±`max`,
    /// with hemisphere letters `pos` (positive) and `neg` (negative).
    pub fn angle(
        key: &'static str,
        label: &'static str,
        max: f64,
        (pos, neg): (char, char),
        default: f64,
    ) -> Self {
        Field {
            kind: Kind::Angle { max, pos, neg },
            ..Field::number(key, label, default)
        }
    }

    /// Checks a typed value against the field's kind and limits; returns it
    /// normalised (integers as whole numbers).
    pub fn check(&self, v: &Value) -> Result<Value> {
        let key = self.key;
        match &self.kind {
            Kind::Number {
                min,
                max,
                min_exclusive,
                unit,
            } => {
                let x = finite_number(key, v)?;
                let u = unit.map(|u| format!(" {u}")).unwrap_or_default();
                if let Some(lo) = min {
                    if *min_exclusive && x <= *lo {
                        return Err(Error::input(
                            key,
                            format!(
                                "must be greater than {}{u} (got {})",
                                fmt_sig(*lo, 12),
                                fmt_sig(x, 12)
                            ),
                        ));
                    }
                    if !*min_exclusive && x < *lo {
                        return Err(Error::input(
                            key,
                            format!(
                                "must be at least {}{u} (got {})",
                                fmt_sig(*lo, 12),
                                fmt_sig(x, 12)
                            ),
                        ));
                    }
                }
                if let Some(hi) = max {
                    if x > *hi {
                        return Err(Error::input(
                            key,
                            format!(
                                "must be at most {}{u} (got {})",
                                fmt_sig(*hi, 12),
                                fmt_sig(x, 12)
                            ),
                        ));
                    }
                }
                Ok(Value::Number(x))
            }
            Kind::Integer { min, max } => {
                let x = finite_number(key, v)?;
                if x.fract() != 0.0 {
                    return Err(Error::input(
                        key,
                        format!("must be a whole number (got {})", fmt_sig(x, 12)),
                    ));
                }
                if let Some(lo) = min {
                    if x < *lo {
                        return Err(Error::input(
                            key,
                            format!("must be at least {lo} (got {x})"),
                        ));
                    }
                }
                if let Some(hi) = max {
                    if x > *hi {
                        return Err(Error::input(key, format!("must be at most {hi} (got {x})")));
                    }
                }
                Ok(Value::Number(x))
            }
            Kind::Vector { min_len, max_len } => {
                let xs = number_list(key, v)?;
                check_len(key, xs.len(), *min_len, *max_len, "numbers")?;
                Ok(Value::numbers(&xs))
            }
            Kind::Matrix { rows, cols } => {
                let m = number_rows(key, v)?;
                if m.is_empty() {
                    return Err(Error::input(key, "is empty: give at least one row"));
                }
                let width = m[0].len();
                if width == 0 {
                    return Err(Error::input(key, "row 1 is empty"));
                }
                for (i, row) in m.iter().enumerate() {
                    if row.len() != width {
                        return Err(Error::input(
                            key,
                            format!(
                                "rows must all have the same length: row 1 has {width} numbers, row {} has {}",
                                i + 1,
                                row.len()
                            ),
                        ));
                    }
                }
                if let Some(r) = rows {
                    if m.len() != *r {
                        return Err(Error::input(
                            key,
                            format!("must have {r} rows (got {})", m.len()),
                        ));
                    }
                }
                if let Some(c) = cols {
                    if width != *c {
                        return Err(Error::input(
                            key,
                            format!("must have {c} columns (got {width})"),
                        ));
                    }
                }
                if m.len() > MAX_DIM || width > MAX_DIM {
                    return Err(Error::input(
                        key,
                        format!(
                            "is {}×{width}; at most {MAX_DIM}×{MAX_DIM} is allowed",
                            m.len()
                        ),
                    ));
                }
                Ok(Value::matrix(&m))
            }
            Kind::Points {
                point_len,
                min_len,
                max_len,
                ..
            } => {
                let m = number_rows(key, v)?;
                check_len(key, m.len(), *min_len, *max_len, "points")?;
                for (i, row) in m.iter().enumerate() {
                    if row.len() != *point_len {
                        return Err(Error::input(
                            key,
                            format!(
                                "point {} has {} number{}; each point needs {point_len}",
                                i + 1,
                                row.len(),
                                if row.len() == 1 { "" } else { "s" }
                            ),
                        ));
                    }
                }
                Ok(Value::matrix(&m))
            }
            Kind::Choice { options } => match v {
                Value::Text(s) if options.iter().any(|(o, _)| o == s) => Ok(v.clone()),
                Value::Text(s) => Err(Error::input(
                    key,
                    format!(
                        "\"{s}\" is not one of the choices ({})",
                        options
                            .iter()
                            .map(|(o, _)| *o)
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                )),
                // a choice whose options are numbers ("8", "4") also takes the number
                Value::Number(x) => match options
                    .iter()
                    .find(|(o, _)| o.parse::<f64>().is_ok_and(|n| n == *x))
                {
                    Some((o, _)) => Ok(Value::Text((*o).to_string())),
                    None => Err(Error::input(
                        key,
                        format!(
                            "{} is not one of the choices ({})",
                            fmt_sig(*x, 15),
                            options
                                .iter()
                                .map(|(o, _)| *o)
                                .collect::<Vec<_>>()
                                .join(", ")
                        ),
                    )),
                },
                other => Err(Error::input(
                    key,
                    format!("must be one of the choices, got {}", other.type_name()),
                )),
            },
            Kind::Angle { max, pos, neg } => {
                let x = match v {
                    Value::Text(t) => crate::projection::dms::parse(t, *pos, *neg)
                        .map_err(|e| Error::input(key, e))?,
                    other => finite_number(key, other)?,
                };
                if x.abs() > *max {
                    return Err(Error::input(
                        key,
                        format!(
                            "must be between −{max}° and {max}° (got {}°)",
                            fmt_sig(x, 12)
                        ),
                    ));
                }
                Ok(Value::Number(x))
            }
            Kind::Flag => match v {
                Value::Bool(_) => Ok(v.clone()),
                other => Err(Error::input(
                    key,
                    format!("must be true or false, got {}", other.type_name()),
                )),
            },
        }
    }

    /// Parses the text a user typed (or a URL carried) and checks it.
    /// Numbers are read by the one number reader of the playground
    /// ([`crate::read`], the practice boxes' rules: a decimal
    /// point or comma, `1.5e3`, `1.5×10^3`, fractions, and the field's unit
    /// or one of its dimension after a number); lists by its
    /// [`read::read_rows`], whose rule for a decimal comma in a list is
    /// stated there (and in docs/API.md).
    pub fn parse_text(&self, text: &str) -> Result<Value> {
        let key = self.key;
        let t = text.trim();
        let bad = |why: String| Error::input(key, why);
        let v = match &self.kind {
            Kind::Number { unit, .. } => Value::Number(read::read_value(t, *unit).map_err(bad)?),
            Kind::Integer { .. } => Value::Number(read::read_value(t, None).map_err(bad)?),
            Kind::Vector { .. } => Value::numbers(&read::read_list(t).map_err(bad)?),
            Kind::Matrix { .. } | Kind::Points { .. } => {
                Value::matrix(&read::read_rows(t).map_err(bad)?)
            }
            Kind::Choice { .. } | Kind::Angle { .. } => Value::Text(t.to_string()),
            Kind::Flag => match t {
                "true" | "1" | "yes" | "on" => Value::Bool(true),
                "false" | "0" | "no" | "off" | "" => Value::Bool(false),
                _ => return Err(bad(format!("\"{}\" is not true or false", short(t)))),
            },
        };
        // A list of the wrong size whose commas may have been decimal commas
        // says how the reader took them.
        self.check(&v)
            .map_err(|e| match (&v, read::comma_hint(t), e) {
                (Value::List(_), Some(hint), Error::InvalidInput { field, reason }) => {
                    Error::InvalidInput {
                        field,
                        reason: format!("{reason} ({hint})"),
                    }
                }
                (_, _, e) => e,
            })
    }

    /// The text form of a value, as [`Field::parse_text`] reads it back.
    pub fn format(&self, v: &Value) -> String {
        match v {
            Value::Number(x) => fmt_sig(*x, 15),
            Value::Bool(b) => b.to_string(),
            Value::Text(s) => s.clone(),
            Value::List(items) => {
                let nested = items.iter().any(|i| matches!(i, Value::List(_)));
                if nested {
                    items
                        .iter()
                        .map(|r| self.format(r))
                        .collect::<Vec<_>>()
                        .join("; ")
                } else {
                    items
                        .iter()
                        .map(|x| self.format(x))
                        .collect::<Vec<_>>()
                        .join(", ")
                }
            }
            Value::Null | Value::Object(_) => String::new(),
        }
    }

    /// A matrix field of any size up to [`MAX_DIM`] × [`MAX_DIM`] with the
    /// seed's rows (fix its size with [`shape`](Self::shape)).
    pub fn matrix(key: &'static str, label: &'static str, default: &[Vec<f64>]) -> Self {
        Field {
            kind: Kind::Matrix {
                rows: None,
                cols: None,
            },
            default: Value::matrix(default),
            ..Field::number(key, label, 0.0)
        }
    }

    /// Fixes the size of a matrix field to `rows` × `cols`.
    pub fn shape(mut self, rows: usize, cols: usize) -> Self {
        if let Kind::Matrix { rows: r, cols: c } = &mut self.kind {
            *r = Some(rows);
            *c = Some(cols);
        }
        self
    }

    /// A list-of-numbers field of `min_len` to `max_len` elements.
    pub fn vector(
        key: &'static str,
        label: &'static str,
        (min_len, max_len): (usize, usize),
        default: &[f64],
    ) -> Self {
        Field {
            kind: Kind::Vector { min_len, max_len },
            default: Value::numbers(default),
            ..Field::number(key, label, 0.0)
        }
    }

    /// A true/false field.
    pub fn flag(key: &'static str, label: &'static str, default: bool) -> Self {
        Field {
            kind: Kind::Flag,
            default: Value::Bool(default),
            ..Field::number(key, label, 0.0)
        }
    }
}

fn check_len(key: &str, n: usize, min: usize, max: usize, what: &str) -> Result<()> {
    if n == 0 {
        return Err(Error::input(
            key,
            format!("is empty: give at least {} {what}", min.max(1)),
        ));
    }
    if n < min {
        return Err(Error::input(
            key,
            format!("needs at least {min} {what} (got {n})"),
        ));
    }
    if n > max {
        return Err(Error::input(
            key,
            format!("has {n} {what}; at most {max} are allowed"),
        ));
    }
    Ok(())
}

fn finite_number(key: &str, v: &Value) -> Result<f64> {
    match v {
        Value::Number(x) if x.is_nan() => Err(Error::input(key, "is NaN; give a number")),
        Value::Number(x) if x.is_infinite() => {
            Err(Error::input(key, "is infinite; give a finite number"))
        }
        Value::Number(x) => Ok(*x),
        Value::Text(s) => Err(Error::input(
            key,
            format!("must be a number, got the string \"{}\"", short(s)),
        )),
        other => Err(Error::input(
            key,
            format!("must be a number, got {}", other.type_name()),
        )),
    }
}

fn number_list(key: &str, v: &Value) -> Result<Vec<f64>> {
    match v {
        Value::List(items) => items
            .iter()
            .enumerate()
            .map(|(i, x)| finite_number(&format!("{key}[{}]", i + 1), x))
            .collect(),
        other => Err(Error::input(
            key,
            format!("must be a list of numbers, got {}", other.type_name()),
        )),
    }
}

fn number_rows(key: &str, v: &Value) -> Result<Vec<Vec<f64>>> {
    match v {
        Value::List(rows) => rows
            .iter()
            .enumerate()
            .map(|(i, row)| match row {
                Value::List(items) => items
                    .iter()
                    .enumerate()
                    .map(|(j, x)| finite_number(&format!("{key}[{}][{}]", i + 1, j + 1), x))
                    .collect(),
                other => Err(Error::input(
                    key,
                    format!(
                        "row {} must be a list of numbers, got {}",
                        i + 1,
                        other.type_name()
                    ),
                )),
            })
            .collect(),
        other => Err(Error::input(
            key,
            format!("must be a list of rows, got {}", other.type_name()),
        )),
    }
}

/// A fixed-size array as the rows a matrix field or value takes.
pub fn to_rows<const N: usize>(m: &[[f64; N]]) -> Vec<Vec<f64>> {
    m.iter().map(|r| r.to_vec()).collect()
}

/// Checks a whole input object against an example's fields: unknown keys are
/// errors, missing keys take the seed's default. Returns the inputs as used.
pub fn validate(fields: &[Field], raw: &Record) -> Result<Record> {
    for key in raw.keys() {
        if !fields.iter().any(|f| f.key == key) {
            return Err(Error::UnknownField {
                field: key.to_string(),
                known: fields.iter().map(|f| f.key.to_string()).collect(),
            });
        }
    }
    let mut out = Record::new();
    for f in fields {
        let v = match raw.get(f.key) {
            // A field that does not apply keeps a valid value and otherwise
            // takes its default: it is never an error.
            Some(v) if !applies(fields, f, raw) => f.check(v).unwrap_or_else(|_| f.default.clone()),
            Some(v) => f.check(v)?,
            None => f.default.clone(),
        };
        out.set(f.key, v);
    }
    Ok(out)
}

/// True when field `f` applies to `inputs` (typed, or texts: a choice's text
/// is the same either way); a missing controlling field takes its default.
pub fn applies(fields: &[Field], f: &Field, inputs: &Record) -> bool {
    let Some(when) = f.when else {
        return true;
    };
    let control = inputs.get(when.key).or_else(|| {
        fields
            .iter()
            .find(|g| g.key == when.key)
            .map(|g| &g.default)
    });
    when.holds(control)
}

/// Typed access to validated inputs (see [`validate`]).
pub struct Inputs<'a>(pub &'a Record);

impl Inputs<'_> {
    pub fn number(&self, key: &str) -> Result<f64> {
        self.0
            .number(key)
            .ok_or_else(|| Error::Internal(format!("validated input \"{key}\" is not a number")))
    }

    /// The text of a validated choice field.
    pub fn text(&self, key: &str) -> Result<&str> {
        match self.0.get(key) {
            Some(Value::Text(t)) => Ok(t),
            _ => Err(Error::Internal(format!(
                "validated input \"{key}\" is not a string"
            ))),
        }
    }

    /// The rows of a validated matrix or point-list field.
    pub fn rows(&self, key: &str) -> Result<Vec<Vec<f64>>> {
        let bad = || Error::Internal(format!("validated input \"{key}\" is not a list of rows"));
        match self.0.get(key) {
            Some(Value::List(rows)) => rows
                .iter()
                .map(|r| match r {
                    Value::List(xs) => xs.iter().map(|x| x.as_f64().ok_or_else(bad)).collect(),
                    _ => Err(bad()),
                })
                .collect(),
            _ => Err(bad()),
        }
    }

    /// The numbers of a validated vector field.
    pub fn list(&self, key: &str) -> Result<Vec<f64>> {
        let bad = || {
            Error::Internal(format!(
                "validated input \"{key}\" is not a list of numbers"
            ))
        };
        match self.0.get(key) {
            Some(Value::List(xs)) => xs.iter().map(|x| x.as_f64().ok_or_else(bad)).collect(),
            _ => Err(bad()),
        }
    }

    /// The value of a validated flag field.
    pub fn flag(&self, key: &str) -> Result<bool> {
        match self.0.get(key) {
            Some(Value::Bool(b)) => Ok(*b),
            _ => Err(Error::Internal(format!(
                "validated input \"{key}\" is not a flag"
            ))),
        }
    }
}

/// True when every input equals the field's seed default.
/// A field that does not apply (see [`When`]) is not compared.
pub fn is_seed(fields: &[Field], inputs: &Record) -> bool {
    fields
        .iter()
        .all(|f| !applies(fields, f, inputs) || inputs.get(f.key) == Some(&f.default))
}

/// The JSON shape of a field in `catalog()`.
#[derive(Serialize)]
pub struct FieldInfo {
    pub key: &'static str,
    pub label: &'static str,
    pub help: &'static str,
    pub kind: &'static str,
    pub unit: Option<&'static str>,
    pub min: Option<f64>,
    pub max: Option<f64>,
    pub min_exclusive: bool,
    pub rows: Option<usize>,
    pub cols: Option<usize>,
    pub point_len: Option<usize>,
    pub columns: Option<&'static [&'static str]>,
    pub max_len: Option<usize>,
    pub options: Option<Vec<ChoiceInfo>>,
    pub default: Value,
    pub default_text: String,
    pub when: Option<When>,
}

#[derive(Serialize)]
pub struct ChoiceInfo {
    pub value: &'static str,
    pub label: &'static str,
}

impl From<&Field> for FieldInfo {
    fn from(f: &Field) -> Self {
        let mut info = FieldInfo {
            key: f.key,
            label: f.label,
            help: f.help,
            kind: "",
            unit: None,
            min: None,
            max: None,
            min_exclusive: false,
            rows: None,
            cols: None,
            point_len: None,
            columns: None,
            max_len: None,
            options: None,
            default: f.default.clone(),
            default_text: f.format(&f.default),
            when: f.when,
        };
        match &f.kind {
            Kind::Number {
                unit,
                min,
                max,
                min_exclusive,
            } => {
                info.kind = "number";
                info.unit = *unit;
                info.min = *min;
                info.max = *max;
                info.min_exclusive = *min_exclusive;
            }
            Kind::Integer { min, max } => {
                info.kind = "integer";
                info.min = *min;
                info.max = *max;
            }
            Kind::Vector { max_len, .. } => {
                info.kind = "vector";
                info.max_len = Some(*max_len);
            }
            Kind::Matrix { rows, cols } => {
                info.kind = "matrix";
                info.rows = *rows;
                info.cols = *cols;
            }
            Kind::Points {
                point_len,
                max_len,
                columns,
                ..
            } => {
                info.kind = "points";
                info.point_len = Some(*point_len);
                info.columns = *columns;
                info.max_len = Some(*max_len);
            }
            Kind::Choice { options } => {
                info.kind = "choice";
                info.options = Some(
                    options
                        .iter()
                        .map(|&(value, label)| ChoiceInfo { value, label })
                        .collect(),
                );
            }
            Kind::Flag => info.kind = "flag",
            Kind::Angle { max, .. } => {
                info.kind = "angle";
                info.unit = Some("°");
                info.min = Some(-max);
                info.max = Some(*max);
            }
        }
        info
    }
}

#[cfg(test)]
mod tests;
