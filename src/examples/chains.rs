//! Seed 000, Examples 17–18 and the exercise: Freeman chain codes, the
//! differential chain code, boundary length, and the simple boundary
//! descriptors (diameter, major and minor axis, basic rectangle,
//! eccentricity), on pixels the student gives in order, as a code, or as
//! regions whose outer boundary is traced.

use super::drill::{mat, Rng};
use super::fields::{Field, Inputs, MAX_DIM, MAX_LEN};
use super::{Example, Topic};
use crate::chain::{self, Boundary, Connectivity, Path, Pixel};
use crate::error::{Error, Result};
use crate::solution::{
    exact_minus_printed, num, tex, Form, NoteKind, Record, Relation, Solution, Step, Value,
};

mod boundary_length;
mod boundary_shape;
mod chain_code;
mod edge;
use edge::*;

const TITLE: &str = "Chain codes and boundaries";
/// How far from the origin a pixel may lie.
const MAX_COORD: f64 = 100_000.0;
/// How many pixels or digits a formula shows before "…".
const SHOW: usize = 48;
/// How many breaks or branches the notes list one by one.
const LIST: usize = 4;

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[
    chain_code::EXAMPLE,
    boundary_length::EXAMPLE,
    boundary_shape::EXAMPLE,
];

/// The topic: its module (`web/chains/`) and title.
pub const TOPIC: Topic = Topic {
    module: "chains",
    title: TITLE,
    examples: EXAMPLES,
};

// ---------------------------------------------------------------- fields

fn pixel_value(ps: &[Pixel]) -> Value {
    Value::matrix(&pixel_rows(ps))
}

fn pixel_rows(ps: &[Pixel]) -> Vec<Vec<f64>> {
    ps.iter().map(|p| vec![p[0] as f64, p[1] as f64]).collect()
}

fn point_value(p: [f64; 2]) -> Value {
    Value::numbers(&p)
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
fn given_field(default: &'static str) -> Field {
    Field::choice("given", "The edge is given as", GIVEN, default).help(
        "Which input describes the edge: the pixels in order, a code from a start pixel, or pixels of regions whose outer boundary is traced clockwise from the top-most, left-most pixel.",
    )
}

fn pixels_field(default: &[Pixel], help: &'static str) -> Field {
    Field::points("pixels", "Pixels [c, r]", 2, MAX_LEN, &pixel_rows(default)).help(help)
}

fn code_field(default: &[u8]) -> Field {
    let digits: Vec<f64> = default.iter().map(|&d| f64::from(d)).collect();
    Field::vector("code", "Chain code", (1, MAX_LEN), &digits).help(
        "Direction digits 1–8 (1–4 with 4-connectivity), separated by spaces or commas; a run such as 441121 is read digit by digit.",
    )
}

fn start_field(default: Pixel) -> Field {
    Field::vector(
        "start",
        "Start pixel [c, r] of the code",
        (2, 2),
        &[default[0] as f64, default[1] as f64],
    )
    .help("Where the code starts: column to the right, row downward.")
}

fn connectivity_field() -> Field {
    Field::choice("connectivity", "Connectivity", CONNECTIVITY, "8").help(
        "8: steps to all eight neighbours, digits 1 (east) to 8 (south-east) counter-clockwise; 4: only left, up, right, down, digits 1 (east), 2 (north), 3 (west), 4 (south).",
    )
}

/// The fields of the pixel modes (`pixels`) and of the code mode (`code`,
/// `start`): each applies only when `given` chooses it.
const PIXEL_MODES: &[&str] = &["pixels", "region"];
const CODE_MODE: &[&str] = &["code"];

/// The fields of an edge given by pixels or by a code (the chain code's
/// and the boundary length's): the seed's edge is the one `code` walks
/// from `start`.
fn edge_fields(start: Pixel, code: &[u8]) -> Vec<Field> {
    vec![
        given_field("pixels"),
        pixels_field(
            &decoded(start, code, Connectivity::Eight),
            "The edge's pixels in order, one [c, r] per row (column to the right, row downward). Repeat the first pixel at the end for a closed boundary. With “regions”: any pixels, in any order.",
        )
        .when("given", PIXEL_MODES),
        code_field(code).when("given", CODE_MODE),
        start_field(start).when("given", CODE_MODE),
        connectivity_field(),
    ]
}

// ---------------------------------------------------------------- inputs

fn connectivity(inputs: &Record) -> Result<Connectivity> {
    Ok(conn_of(Inputs(inputs).text("connectivity")?))
}

fn coordinate(field: &str, what: &str, x: f64) -> Result<i64> {
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

fn pixel(field: &str, what: &str, xy: &[f64]) -> Result<Pixel> {
    match xy {
        [c, r] => Ok([coordinate(field, what, *c)?, coordinate(field, what, *r)?]),
        _ => Err(Error::input(
            field,
            format!("{what} needs two numbers, c and r"),
        )),
    }
}

fn pixels(inputs: &Record) -> Result<Vec<Pixel>> {
    Inputs(inputs)
        .rows("pixels")?
        .iter()
        .enumerate()
        .map(|(i, xy)| pixel("pixels", &format!("point {}", i + 1), xy))
        .collect()
}

fn start(inputs: &Record) -> Result<Pixel> {
    pixel("start", "the start pixel", &Inputs(inputs).list("start")?)
}

/// The code's digits; a number of several digits is read digit by digit.
fn digits(inputs: &Record) -> Result<Vec<u8>> {
    let mut out = Vec::new();
    for (i, x) in Inputs(inputs).list("code")?.into_iter().enumerate() {
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

// ---------------------------------------------------------------- labels

/// What each result key means, for the result table (the code's label
/// depends on the connectivity: [`label_code`]).
const LABELS: &[(&str, &str, &str)] = &[
    ("differential", "Differential chain code", ""),
    ("differences", "Differences before mod", ""),
    ("pixels", "Pixels [c, r] in coding order", ""),
    ("closed", "Closed boundary", ""),
    ("breaks", "Breaks [k, c, r, c′, r′]: pixel k to k+1", ""),
    ("branches", "Repeated pixels [k, first k, c, r]", ""),
    ("regions", "Regions", ""),
    ("length", "Length L", "px"),
    ("horizontal", "Horizontal steps", ""),
    ("vertical", "Vertical steps", ""),
    ("diagonal", "Diagonal steps", ""),
    ("pixel_count", "Pixels N", ""),
    ("diameter", "Diameter D", "px"),
    ("major_axis", "Major axis (end pixels [c, r])", ""),
    ("minor_axis_length", "Minor axis length m", "px"),
    ("basic_rectangle", "Basic rectangle (corners [c, r])", ""),
    ("eccentricity", "Eccentricity E = D / m", ""),
    ("minor_axis", "Minor axis (ends [c, r])", ""),
    ("boundary", "Traced boundary [c, r]", ""),
];

/// Labels the chain code, whose digits depend on the connectivity.
fn label_code(s: &mut Solution, conn: Connectivity) {
    let digits = match conn {
        Connectivity::Eight => "Chain code (digits 1–8)",
        Connectivity::Four => "Chain code (digits 1–4)",
    };
    s.label_present(&[("code", digits, "")]);
}

// ---------------------------------------------- practice (code and length)

/// Steps of the generated edges.
const STEPS: usize = 6;

/// 8-connectivity digits and their steps (c right, r down; 2 = north-east).
const DIRS: [(u8, i64, i64); 5] = [(1, 1, 0), (2, 1, -1), (3, 0, -1), (7, 0, 1), (8, 1, 1)];

/// An open edge that never crosses itself: it never steps left, and never
/// goes straight back up after going down (or down after up). One step is
/// diagonal and one vertical, so every kind of step is practised.
fn gen_edge(rng: &mut Rng) -> Record {
    let mut digits: Vec<u8> = Vec::new();
    let diag = rng.int(0, STEPS as i64 - 1) as usize;
    let vert = (diag + rng.int(1, STEPS as i64 - 1) as usize) % STEPS;
    for k in 0..STEPS {
        let prev = digits.last().copied();
        let choices: Vec<u8> = DIRS
            .iter()
            .map(|d| d.0)
            .filter(|&d| {
                let ok_kind = if k == diag {
                    d == 2 || d == 8
                } else if k == vert {
                    d == 3 || d == 7
                } else {
                    true
                };
                ok_kind && !matches!((prev, d), (Some(3), 7) | (Some(7), 3))
            })
            .collect();
        digits.push(rng.pick(&choices));
    }
    let (mut c, mut r) = (rng.num(2, 9), rng.num(6, 12));
    let mut pixels = vec![vec![c, r]];
    for d in &digits {
        let (_, dc, dr) = DIRS
            .iter()
            .copied()
            .find(|x| x.0 == *d)
            .unwrap_or((1, 1, 0));
        c += dc as f64;
        r += dr as f64;
        pixels.push(vec![c, r]);
    }
    Record::new()
        .with("given", "pixels")
        .with("pixels", mat(&pixels))
}
