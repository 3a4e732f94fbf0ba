//! A sweep's series (issue 34, `docs/sweeps.md`): one example solved at many
//! values of one input in one call, keeping only the chosen results.
//!
//! Every point is [`Example::run`](crate::examples::Example::run) with the
//! inputs and that value — the same solver, the same checks, the same
//! numbers and messages as `solve(id, inputs with that value)` — run under
//! [`without_steps`]: the steps, which only the page's step list and
//! figures read, are not built (see [`crate::solution::steps_wanted`]).

use crate::error::{Error, Result};
use crate::examples::fields::Field;
use crate::examples::{self, Topic};
use crate::solution::{without_steps, Record, Value};
use serde::Serialize;

/// Points of one series at most (the page sweeps 2–500; its table 121 cells).
pub const MAX_POINTS: usize = 10_000;
/// Results read off each point at most.
pub const MAX_PLOTTED: usize = 64;

/// The series: the chosen results at each point and the solver's message
/// where a point has no solution.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Series {
    /// `{ key: [its value at each point] }` in the order asked: the
    /// solution's own value (a number, or whatever the result is there),
    /// null where the point has no solution or the solution no such result.
    pub results: Record,
    /// The solver's message at each point, null where it solved.
    pub errors: Vec<Option<String>>,
}

/// Example `id` among `topics` solved with `inputs` and input `key` set to
/// each of `values`, reading results `plot` off each solution. An unknown
/// `id` is an error of the whole call (every point would have it); a point
/// the solver refuses is that point's message.
pub fn solve_series_in(
    topics: &'static [Topic],
    id: &str,
    inputs: &Record,
    key: &str,
    values: &[Value],
    plot: &[String],
) -> Result<Series> {
    if values.len() > MAX_POINTS {
        return Err(Error::input(
            "values",
            format!("at most {MAX_POINTS} points, got {}", values.len()),
        ));
    }
    if plot.len() > MAX_PLOTTED {
        return Err(Error::input(
            "plot",
            format!("at most {MAX_PLOTTED} results, got {}", plot.len()),
        ));
    }
    let example = examples::find(topics, id)?;
    let mut columns: Vec<Vec<Value>> = vec![Vec::with_capacity(values.len()); plot.len()];
    let mut errors = Vec::with_capacity(values.len());
    let mut point = inputs.clone();
    for v in values {
        point.set(key, v.clone());
        match without_steps(|| example.run(&point)) {
            Ok(s) => {
                for (column, k) in columns.iter_mut().zip(plot) {
                    column.push(s.result.get(k).cloned().unwrap_or(Value::Null));
                }
                errors.push(None);
            }
            Err(e) => {
                for column in &mut columns {
                    column.push(Value::Null);
                }
                errors.push(Some(e.to_string()));
            }
        }
    }
    let mut results = Record::new();
    for (k, column) in plot.iter().zip(columns) {
        results.set(k, Value::List(column));
    }
    Ok(Series { results, errors })
}

/// A count a person typed (a sweep's steps, its table's rows): `text` read
/// as an integer input's box is (the one number reader, [`crate::read`]),
/// a whole number within `min..=max`, refused in that box's words
/// (`"text: must be at most 500 (got 800)"`).
pub fn read_count(text: &str, min: f64, max: f64) -> Result<f64> {
    if !(min.is_finite() && max.is_finite() && min <= max) {
        return Err(Error::input(
            "min",
            format!("min and max must be finite numbers with min ≤ max (got {min} and {max})"),
        ));
    }
    let field = Field::integer("text", "Count", min).range(min, max);
    field
        .parse_text(text)?
        .as_f64()
        .ok_or_else(|| Error::input("text", "must be a whole number"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::examples::fields::{Field, Kind};
    use crate::examples::TOPICS;

    /// The number fields of an example (what a sweep can run over).
    fn number_fields(e: &examples::Example) -> Vec<Field> {
        (e.fields)()
            .into_iter()
            .filter(|f| {
                matches!(
                    f.kind,
                    Kind::Number { .. } | Kind::Integer { .. } | Kind::Angle { .. }
                )
            })
            .collect()
    }

    #[test]
    fn every_point_is_the_solution_of_solve_with_that_value() {
        let mut swept = 0;
        for e in examples::all() {
            for f in number_fields(e).into_iter().take(2) {
                let d = f.default.as_f64().unwrap_or(1.0);
                let values: Vec<Value> = [d, d * 0.9, d * 1.1 + 1.0, -1e9, f64::NAN, 1e300]
                    .into_iter()
                    .map(Value::Number)
                    .collect();
                let probe = crate::examples::solve(e.id, &Record::new()).unwrap();
                let plot: Vec<String> = probe
                    .result
                    .keys()
                    .map(str::to_string)
                    .chain(["no_such_result".to_string()])
                    .collect();
                let series =
                    solve_series_in(&TOPICS, e.id, &Record::new(), f.key, &values, &plot).unwrap();
                assert_eq!(series.errors.len(), values.len());
                for (i, v) in values.iter().enumerate() {
                    let inputs = Record::new().with(f.key, v.clone());
                    match crate::examples::solve(e.id, &inputs) {
                        Ok(s) => {
                            assert_eq!(series.errors[i], None, "{} {}={v:?}", e.id, f.key);
                            for k in &plot {
                                let Some(Value::List(col)) = series.results.get(k) else {
                                    panic!("{k}: no column")
                                };
                                let want = s.result.get(k).cloned().unwrap_or(Value::Null);
                                // bit for bit: NaN never occurs in a checked solution
                                assert_eq!(col[i], want, "{} {k} at {}={v:?}", e.id, f.key);
                            }
                        }
                        Err(err) => {
                            assert_eq!(series.errors[i].as_deref(), Some(err.to_string().as_str()));
                            for k in &plot {
                                let Some(Value::List(col)) = series.results.get(k) else {
                                    panic!("{k}: no column")
                                };
                                assert_eq!(col[i], Value::Null);
                            }
                        }
                    }
                }
                swept += 1;
            }
        }
        assert!(swept >= 12, "only {swept} fields swept");
    }

    #[test]
    fn a_count_is_read_as_an_integer_box_is() {
        assert_eq!(read_count(" 200 ", 2.0, 500.0).unwrap(), 200.0);
        assert_eq!(read_count("2e2", 2.0, 500.0).unwrap(), 200.0);
        let msg = |t: &str| read_count(t, 2.0, 500.0).unwrap_err().to_string();
        assert_eq!(msg("800"), "text: must be at most 500 (got 800)");
        assert_eq!(msg("1"), "text: must be at least 2 (got 1)");
        assert!(msg("12.5").contains("whole number"), "{}", msg("12.5"));
        assert!(msg("abc").starts_with("text: "), "{}", msg("abc"));
        assert!(msg("").starts_with("text: "), "{}", msg(""));
        assert!(read_count("3", 5.0, 2.0)
            .unwrap_err()
            .to_string()
            .starts_with("min: "));
        assert!(read_count("3", f64::NAN, 2.0).is_err());
    }

    #[test]
    fn steps_come_back_after_a_series() {
        let values = [Value::Number(1200.0)];
        solve_series_in(&TOPICS, "gsd", &Record::new(), "dpi", &values, &[]).unwrap();
        assert!(!crate::examples::solve("gsd", &Record::new())
            .unwrap()
            .steps
            .is_empty());
    }

    #[test]
    fn an_unknown_example_or_too_many_points_is_an_error_of_the_call() {
        let e = solve_series_in(&TOPICS, "nope", &Record::new(), "dpi", &[], &[]).unwrap_err();
        assert!(e.to_string().contains("nope"), "{e}");
        let many = vec![Value::Number(1.0); MAX_POINTS + 1];
        let e = solve_series_in(&TOPICS, "gsd", &Record::new(), "dpi", &many, &[]).unwrap_err();
        assert!(e.to_string().starts_with("values: "), "{e}");
    }
}
