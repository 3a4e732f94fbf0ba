//! Seed 000, Examples 17–18 and the exercise: Freeman chain codes, the
//! differential chain code, boundary length, and the simple boundary
//! descriptors (diameter, major and minor axis, basic rectangle,
//! eccentricity), on pixels the student gives in order, as a code, or as
//! regions whose outer boundary is traced.

use super::fields::{Field, Kind, MAX_DIM, MAX_LEN};
use super::{Example, Lab, Topic};
use crate::chain::{self, Boundary, Connectivity, Path, Pixel};
use crate::error::{Error, Result};
use crate::solution::{exact_minus_printed, num, tex, NoteKind, Record, Solution, Step, Value};

mod boundary_length;
mod boundary_shape;
mod chain_code;
mod edge;
use boundary_length::*;
use boundary_shape::*;
use chain_code::*;
use edge::*;

const TITLE: &str = "Chain codes and boundaries";
/// How far from the origin a pixel may lie.
const MAX_COORD: f64 = 100_000.0;
/// How many pixels or digits a formula shows before "…".
const SHOW: usize = 48;
/// How many breaks or branches the notes list one by one.
const LIST: usize = 4;

/// Example 17's edge, rebuilt from its printed code (the figure is lost).
const EX17_START: Pixel = [1, 4];
const EX17_CODE: [u8; 16] = [1, 8, 8, 8, 7, 1, 1, 2, 3, 4, 4, 2, 1, 1, 2, 2];
const EX17_DIFFERENCES: [f64; 15] = [
    7.0, 0.0, 0.0, -1.0, -6.0, 0.0, 1.0, 1.0, 1.0, 0.0, -2.0, -1.0, 0.0, 1.0, 0.0,
];
const EX17_DIFFERENTIAL: [f64; 15] = [
    7.0, 0.0, 0.0, 7.0, 2.0, 0.0, 1.0, 1.0, 1.0, 0.0, 6.0, 7.0, 0.0, 1.0, 0.0,
];
/// The 4-connectivity code of the seed's figure c.
const FIG_C_CODE: [u8; 15] = [4, 4, 1, 1, 2, 1, 1, 4, 1, 1, 2, 2, 2, 3, 3];
/// Example 18 (a), rebuilt: a 4-connected edge of 24 pixels.
const EX18A_START: Pixel = [1, 1];
const EX18A_CODE: [u8; 23] = [
    1, 1, 4, 4, 1, 1, 1, 2, 2, 1, 1, 1, 4, 4, 4, 1, 1, 2, 2, 2, 1, 1, 4,
];
/// Example 18 (b), rebuilt: 4 horizontal, 4 vertical and 9 diagonal steps.
const EX18B_START: Pixel = [1, 1];
const EX18B_CODE: [u8; 17] = [1, 8, 8, 8, 7, 7, 8, 1, 2, 2, 3, 3, 2, 2, 1, 8, 1];
/// The default region of `boundary-shape`: a tilted, filled ellipse.
const BLOB: [Pixel; 55] = [
    [7, 1],
    [8, 1],
    [9, 1],
    [10, 1],
    [11, 1],
    [12, 1],
    [5, 2],
    [6, 2],
    [7, 2],
    [8, 2],
    [9, 2],
    [10, 2],
    [11, 2],
    [12, 2],
    [4, 3],
    [5, 3],
    [6, 3],
    [7, 3],
    [8, 3],
    [9, 3],
    [10, 3],
    [11, 3],
    [12, 3],
    [3, 4],
    [4, 4],
    [5, 4],
    [6, 4],
    [7, 4],
    [8, 4],
    [9, 4],
    [10, 4],
    [11, 4],
    [2, 5],
    [3, 5],
    [4, 5],
    [5, 5],
    [6, 5],
    [7, 5],
    [8, 5],
    [9, 5],
    [10, 5],
    [2, 6],
    [3, 6],
    [4, 6],
    [5, 6],
    [6, 6],
    [7, 6],
    [8, 6],
    [9, 6],
    [2, 7],
    [3, 7],
    [4, 7],
    [5, 7],
    [6, 7],
    [7, 7],
];

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[
        Example {
            id: "chain-code",
            title: "Freeman chain code",
            source: "Worked examples, Example 17 and the exercise",
            summary: "The chain code and differential chain code of a digital edge or closed boundary, from its pixels, from a code, or traced around drawn regions.",
            fields: chain_code_fields,
            solve: chain_code,
            answer: &["code", "differential"],
            labels: &[],
            lab: Some(Lab { family: "boundaries", explains: &[] }),
            practice: None,
        },
        Example {
            id: "boundary-length",
            title: "Boundary length",
            source: "Worked examples, Example 18",
            summary: "The length of a digital edge: pixels minus one when 4-connected; axial steps 1 and diagonal steps √2 when 8-connected.",
            fields: boundary_length_fields,
            solve: boundary_length,
            answer: &["length"],
            labels: &[],
            lab: Some(Lab { family: "boundaries", explains: &[] }),
            practice: None,
        },
        Example {
            id: "boundary-shape",
            title: "Boundary descriptors",
            source: "Worked examples, boundary descriptors",
            summary: "Diameter, major and minor axis, basic rectangle and eccentricity of the outer boundary of a drawn region.",
            fields: boundary_shape_fields,
            solve: boundary_shape,
            answer: &["diameter", "minor_axis_length", "eccentricity"],
            labels: &[],
            lab: Some(Lab { family: "boundaries", explains: &[] }),
            practice: None,
        },
];

/// The topic: its module (`web/chains/`) and title.
pub const TOPIC: Topic = Topic {
    module: "chains",
    title: TITLE,
    examples: EXAMPLES,
};

// ---------------------------------------------------------------- fields

fn field(
    key: &'static str,
    label: &'static str,
    help: &'static str,
    kind: Kind,
    d: Value,
) -> Field {
    Field {
        key,
        label,
        help,
        kind,
        default: d,
        when: None,
    }
}

fn pixel_value(ps: &[Pixel]) -> Value {
    Value::List(
        ps.iter()
            .map(|p| Value::numbers(&[p[0] as f64, p[1] as f64]))
            .collect(),
    )
}

fn digits_value(code: &[u8]) -> Value {
    Value::List(code.iter().map(|&d| Value::Number(f64::from(d))).collect())
}

fn decoded(start: Pixel, code: &[u8], conn: Connectivity) -> Vec<Pixel> {
    chain::decode(start, code, conn).unwrap_or_default()
}

const GIVEN: &[(&str, &str)] = &[
    (
        "pixels",
        "Pixels in order (an edge; repeat the first to close it)",
    ),
    ("code", "A start pixel and a chain code"),
    (
        "region",
        "Pixels of regions (their outer boundaries are traced)",
    ),
];
const CONNECTIVITY: &[(&str, &str)] = &[("8", "8-connectivity"), ("4", "4-connectivity")];
const FROM: &[(&str, &str)] = &[
    ("start", "From the first pixel (the left end)"),
    ("end", "From the last pixel (the right end)"),
];

fn given_field(default: &str) -> Field {
    field(
        "given",
        "The edge is given as",
        "Which input describes the edge: the pixels in order, a code from a start pixel, or pixels of regions whose outer boundary is traced clockwise from the top-most, left-most pixel.",
        Kind::Choice { options: GIVEN },
        Value::from(default),
    )
}

fn pixels_field(default: &[Pixel], help: &'static str) -> Field {
    field(
        "pixels",
        "Pixels [c, r]",
        help,
        Kind::Points {
            point_len: 2,
            min_len: 1,
            max_len: MAX_LEN,
            columns: None,
        },
        pixel_value(default),
    )
}

fn code_field(default: &[u8]) -> Field {
    field(
        "code",
        "Chain code",
        "Direction digits 1–8 (1–4 with 4-connectivity), separated by spaces or commas; a run such as 441121 is read digit by digit.",
        Kind::Vector {
            min_len: 1,
            max_len: MAX_LEN,
        },
        digits_value(default),
    )
}

fn start_field(default: Pixel) -> Field {
    field(
        "start",
        "Start pixel [c, r] of the code",
        "Where the code starts: column to the right, row downward.",
        Kind::Vector {
            min_len: 2,
            max_len: 2,
        },
        Value::numbers(&[default[0] as f64, default[1] as f64]),
    )
}

fn connectivity_field() -> Field {
    field(
        "connectivity",
        "Connectivity",
        "8: steps to all eight neighbours, digits 1 (east) to 8 (south-east) counter-clockwise; 4: only left, up, right, down, digits 1 (east), 2 (north), 3 (west), 4 (south).",
        Kind::Choice {
            options: CONNECTIVITY,
        },
        Value::from("8"),
    )
}

/// The fields of the pixel modes (`pixels`) and of the code mode (`code`,
/// `start`): each applies only when `given` chooses it.
const PIXEL_MODES: &[&str] = &["pixels", "region"];
const CODE_MODE: &[&str] = &["code"];

fn chain_code_fields() -> Vec<Field> {
    vec![
        given_field("pixels"),
        pixels_field(
            &decoded(EX17_START, &EX17_CODE, Connectivity::Eight),
            "The edge's pixels in order, one [c, r] per row (column to the right, row downward). Repeat the first pixel at the end for a closed boundary. With “regions”: any pixels, in any order.",
        )
        .when("given", PIXEL_MODES),
        code_field(&EX17_CODE).when("given", CODE_MODE),
        start_field(EX17_START).when("given", CODE_MODE),
        connectivity_field(),
        field(
            "from",
            "Start coding from",
            "The course notes' Example 17 starts at the left end; its exercise at the right end. A closed boundary is walked the other way round.",
            Kind::Choice { options: FROM },
            Value::from("start"),
        ),
    ]
}

fn boundary_length_fields() -> Vec<Field> {
    vec![
        given_field("pixels"),
        pixels_field(
            &decoded(EX18B_START, &EX18B_CODE, Connectivity::Eight),
            "The edge's pixels in order, one [c, r] per row (column to the right, row downward). Repeat the first pixel at the end for a closed boundary. With “regions”: any pixels, in any order.",
        )
        .when("given", PIXEL_MODES),
        code_field(&EX18B_CODE).when("given", CODE_MODE),
        start_field(EX18B_START).when("given", CODE_MODE),
        connectivity_field(),
    ]
}

fn boundary_shape_fields() -> Vec<Field> {
    vec![
        pixels_field(
            &BLOB,
            "Pixels of a region or of a closed boundary, any order, one [c, r] per row. The outer boundary of the region of the top-most, left-most pixel is traced and described.",
        ),
        connectivity_field(),
    ]
}

// ---------------------------------------------------------------- inputs

fn text<'a>(inputs: &'a Record, key: &str) -> Result<&'a str> {
    match inputs.get(key) {
        Some(Value::Text(t)) => Ok(t),
        _ => Err(Error::Internal(format!(
            "validated input \"{key}\" is not a choice"
        ))),
    }
}

fn connectivity(inputs: &Record) -> Result<Connectivity> {
    Ok(conn_of(text(inputs, "connectivity")?))
}

fn rows(inputs: &Record, key: &str) -> Result<Vec<Value>> {
    match inputs.get(key) {
        Some(Value::List(items)) => Ok(items.clone()),
        _ => Err(Error::Internal(format!(
            "validated input \"{key}\" is not a list"
        ))),
    }
}

fn coordinate(field: &str, what: &str, v: &Value) -> Result<i64> {
    let x = v.as_f64().ok_or_else(|| {
        Error::Internal(format!("validated input \"{field}\" holds a non-number"))
    })?;
    if x.fract() != 0.0 {
        return Err(Error::input(
            field,
            format!("{what} must be whole pixel positions (got {})", num(x)),
        ));
    }
    if x.abs() > MAX_COORD {
        return Err(Error::input(
            field,
            format!(
                "{what} lies too far out ({}); coordinates up to ±{} are accepted",
                num(x),
                num(MAX_COORD)
            ),
        ));
    }
    Ok(x as i64)
}

fn pixel(field: &str, what: &str, v: &Value) -> Result<Pixel> {
    match v {
        Value::List(xy) if xy.len() == 2 => Ok([
            coordinate(field, what, &xy[0])?,
            coordinate(field, what, &xy[1])?,
        ]),
        _ => Err(Error::input(
            field,
            format!("{what} needs two numbers, c and r"),
        )),
    }
}

fn pixels(inputs: &Record) -> Result<Vec<Pixel>> {
    rows(inputs, "pixels")?
        .iter()
        .enumerate()
        .map(|(i, v)| pixel("pixels", &format!("point {}", i + 1), v))
        .collect()
}

fn start(inputs: &Record) -> Result<Pixel> {
    pixel(
        "start",
        "the start pixel",
        &Value::List(rows(inputs, "start")?),
    )
}

/// The code's digits; a number of several digits is read digit by digit.
fn digits(inputs: &Record) -> Result<Vec<u8>> {
    let mut out = Vec::new();
    for (i, v) in rows(inputs, "code")?.iter().enumerate() {
        let x = v.as_f64().unwrap_or(f64::NAN);
        if !(x.fract() == 0.0 && x >= 1.0) {
            return Err(Error::input(
                "code",
                format!(
                    "entry {} is {}; a chain code is made of direction digits 1 to 8",
                    i + 1,
                    num(x)
                ),
            ));
        }
        if x > 9_007_199_254_740_992.0 {
            return Err(Error::input(
                "code",
                format!(
                    "entry {} has too many digits to read as one number; separate the digits with spaces",
                    i + 1
                ),
            ));
        }
        let run = format!("{}", x as u64);
        out.extend(run.bytes().map(|b| b.saturating_sub(b'0')));
    }
    if out.len() > MAX_LEN {
        return Err(Error::input(
            "code",
            format!("has {} digits; at most {MAX_LEN} are allowed", out.len()),
        ));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rebuilt_examples_have_the_seeds_counts() {
        let a = chain::length(&EX18A_CODE, Connectivity::Four);
        assert_eq!(a.length, 23.0);
        let b = chain::length(&EX18B_CODE, Connectivity::Eight);
        assert_eq!((b.horizontal, b.vertical, b.diagonal), (4, 4, 9));
    }
}
