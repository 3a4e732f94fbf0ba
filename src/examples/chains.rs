//! Seed 000, Examples 17–18 and the exercise: Freeman chain codes, the
//! differential chain code, boundary length, and the simple boundary
//! descriptors (diameter, major and minor axis, basic rectangle,
//! eccentricity), on pixels the student gives in order, as a code, or as
//! regions whose outer boundary is traced.

use super::fields::{Field, Kind, MAX_DIM, MAX_LEN};
use super::Entry;
use crate::chain::{self, Boundary, Connectivity, Path, Pixel};
use crate::error::{Error, Result};
use crate::solution::{exact_minus_printed, num, tex, NoteKind, Record, Solution, Step, Value};

const TOPIC: &str = "Chain codes and boundaries";
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

pub fn entries() -> Vec<Entry> {
    vec![
        Entry {
            id: "chain-code",
            title: "Freeman chain code",
            topic: TOPIC,
            source: "Worked examples, Example 17 and the exercise",
            summary: "The chain code and differential chain code of a digital edge or closed boundary, from its pixels, from a code, or traced around drawn regions.",
            fields: chain_code_fields,
            solve: Some(chain_code),
        },
        Entry {
            id: "boundary-length",
            title: "Boundary length",
            topic: TOPIC,
            source: "Worked examples, Example 18",
            summary: "The length of a digital edge: pixels minus one when 4-connected; axial steps 1 and diagonal steps √2 when 8-connected.",
            fields: boundary_length_fields,
            solve: Some(boundary_length),
        },
        Entry {
            id: "boundary-shape",
            title: "Boundary descriptors",
            topic: TOPIC,
            source: "Worked examples, boundary descriptors",
            summary: "Diameter, major and minor axis, basic rectangle and eccentricity of the outer boundary of a drawn region.",
            fields: boundary_shape_fields,
            solve: Some(boundary_shape),
        },
    ]
}

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

// ---------------------------------------------------------------- the edge

#[derive(Clone, Copy, PartialEq, Eq)]
enum Given {
    Pixels,
    Code,
    Region,
}

/// The edge an example works on, however it was given.
struct Edge {
    given: Given,
    path: Path,
    /// The code before it was reversed ("from the end"), when it was.
    forward: Option<Vec<u8>>,
    /// Region mode: every region's outer boundary.
    regions: Vec<Boundary>,
}

fn edge(inputs: &Record, conn: Connectivity, from_end: bool) -> Result<Edge> {
    let given = match inputs.get("given") {
        Some(Value::Text(t)) if t == "code" => Given::Code,
        Some(Value::Text(t)) if t == "region" => Given::Region,
        _ => Given::Pixels,
    };
    let mut regions = Vec::new();
    let raw: Vec<Pixel> = match given {
        Given::Pixels => pixels(inputs)?,
        Given::Code => chain::decode(start(inputs)?, &digits(inputs)?, conn)?,
        Given::Region => {
            regions = chain::trace_pixels("pixels", &pixels(inputs)?, conn, MAX_DIM)?;
            let first = regions
                .first()
                .ok_or_else(|| Error::Internal("no region traced".into()))?;
            let mut ps = first.pixels.clone();
            if !first.code.is_empty() {
                ps.extend(first.pixels.first().copied());
            }
            ps
        }
    };
    let forward = from_end.then(|| chain::analyse(&raw, conn).code).flatten();
    let ordered: Vec<Pixel> = if from_end {
        raw.iter().rev().copied().collect()
    } else {
        raw
    };
    let mut path = chain::analyse(&ordered, conn);
    if given == Given::Region {
        // a traced boundary walks one-pixel-wide parts out and back: that
        // is how it is traced, not a branch of the input
        path.revisits.clear();
    }
    Ok(Edge {
        given,
        path,
        forward,
        regions,
    })
}

fn pixel_tex(p: Pixel) -> String {
    format!("({},{})", p[0], p[1])
}

/// Items for LaTeX, `per_line` to a line (a `gathered` block when more than
/// one), at most [`SHOW`] of them.
fn list_tex<T>(items: &[T], f: impl Fn(&T) -> String, sep: &str, per_line: usize) -> String {
    let shown: Vec<String> = items.iter().take(SHOW).map(f).collect();
    let mut lines: Vec<String> = shown.chunks(per_line.max(1)).map(|c| c.join(sep)).collect();
    if items.len() > SHOW {
        lines.push(format!(r"\ldots\ (\text{{{} in all}})", items.len()));
    }
    if lines.len() > 1 {
        format!(r"\begin{{gathered}}{}\end{{gathered}}", lines.join(r" \\ "))
    } else {
        lines.concat()
    }
}

fn digits_tex(code: &[u8]) -> String {
    if code.is_empty() {
        return r"\text{(empty)}".to_string();
    }
    list_tex(code, |d| d.to_string(), r"\;", 24)
}

fn pixel_text(p: Pixel) -> String {
    format!("({}, {})", p[0], p[1])
}

fn edge_step(e: &Edge, conn: Connectivity, inputs: &Record) -> Result<Step> {
    let p = &e.path;
    let n = p.pixels.len();
    let kind = if p.closed {
        "closed boundary"
    } else {
        "open edge"
    };
    let shown = list_tex(&p.pixels, |q| pixel_tex(*q), r"\;", 8);
    let step = match e.given {
        Given::Pixels => Step::new(
            "The edge",
            &format!(
                "{n} pixels [c, r] in the order given ({kind}{}). Columns count to the right, rows downward.",
                if p.closed {
                    "; the last pixel repeats the first, so the code also has the closing step"
                } else {
                    ""
                }
            ),
        )
        .formula(r"p_1, p_2, \ldots, p_n", shown),
        Given::Code => {
            let s = start(inputs)?;
            Step::new(
                "Decoding the code",
                &format!(
                    "From the start pixel {} each digit moves one step in its direction; the walk visits {n} pixels ({kind}).",
                    pixel_text(s)
                ),
            )
            .formula(
                r"p_{k+1} = p_k + \Delta(a_k)",
                shown,
            )
        }
        Given::Region => {
            let r = e.regions.len();
            Step::new(
                "Tracing the outer boundary",
                &format!(
                    "The pixels form {r} region{} ({}-connected). The outer boundary of the region of the top-most, left-most pixel is followed clockwise on the screen, keeping the region on the right and looking for the next region pixel counter-clockwise first (Moore's tracing for 8-connectivity), until the first step repeats. It has {n} boundary positions; a one-pixel-wide part is walked out and back.",
                    if r == 1 { "" } else { "s" },
                    conn.directions()
                ),
            )
            .formula(r"b_1, b_2, \ldots, b_n", shown)
            .value(
                "boundaries",
                Value::List(e.regions.iter().map(|b| pixel_value(&b.pixels)).collect()),
            )
        }
    };
    Ok(step
        .value("pixels", pixel_value(&p.pixels))
        .value("closed", p.closed))
}

fn numbering_step(conn: Connectivity) -> Step {
    let (formula, text) = match conn {
        Connectivity::Eight => (
            r"\begin{array}{ccc} 4 & 3 & 2 \\ 5 & \cdot & 1 \\ 6 & 7 & 8 \end{array}",
            "Each step to one of the eight neighbours gets a digit: 1 to the east, counting counter-clockwise to 8 to the south-east (rows count downward, so 3 = north is one row up).",
        ),
        Connectivity::Four => (
            r"\begin{array}{ccc} & 2 & \\ 3 & \cdot & 1 \\ & 4 & \end{array}",
            "With 4-connectivity only the four axial steps are allowed: 1 east, 2 north, 3 west, 4 south, counter-clockwise as in the 8-connectivity figure.",
        ),
    };
    let steps: Vec<String> = (1..=conn.directions())
        .filter_map(|d| {
            conn.step(d)
                .map(|(dc, dr)| format!(r"\Delta({d}) = ({dc},{dr})"))
        })
        .collect();
    Step::new("Direction numbers", text)
        .formula(formula, list_tex(&steps, String::clone, r",\ ", 4))
}

fn code_step(path: &Path, code: &[u8]) -> Step {
    Step::new(
        "Chain code",
        &format!(
            "The direction of each step from one pixel to the next, {} digit{}.",
            code.len(),
            if code.len() == 1 { "" } else { "s" }
        ),
    )
    .formula(
        r"a_k = \operatorname{dir}(c_{k+1} - c_k,\ r_{k+1} - r_k)",
        format!("a = {}", digits_tex(code)),
    )
    .value("code", digits_value(code))
    .value("pixels", pixel_value(&path.pixels))
}

fn reverse_step(forward: &[u8], code: &[u8], conn: Connectivity) -> Step {
    let half = conn.directions() / 2;
    Step::new(
        "Coding from the other end",
        &format!(
            "Walking the edge the other way takes the steps in reverse order, each in the opposite direction: the forward code read backwards with {half} added (mod {}).",
            conn.directions()
        ),
    )
    .formula(
        &format!(r"a'_k = (a_{{n+1-k}} + {half} - 1) \bmod {} + 1", conn.directions()),
        format!(
            r"a = {} \;\Rightarrow\; a' = {}",
            digits_tex(forward),
            digits_tex(code)
        ),
    )
    .value("forward", digits_value(forward))
}

fn differential_steps(d: &chain::Differential, closed: bool, conn: Connectivity) -> [Step; 2] {
    let n = conn.directions();
    let diffs = list_tex(&d.differences, |x| tex(*x as f64), r"\;", 20);
    let first = if closed {
        "For a closed boundary the first element is the first digit minus the last; then each"
    } else {
        "Each"
    };
    [
        Step::new(
            "Differences",
            &format!(
                "{first} digit minus the one before it: {} differences for {} digits.",
                d.differences.len(),
                d.differences.len() + usize::from(!closed)
            ),
        )
        .formula(
            if closed {
                r"d_1 = a_1 - a_n,\quad d_k = a_k - a_{k-1}"
            } else {
                r"d_k = a_{k+1} - a_k"
            },
            format!(
                "d = {}",
                if d.differences.is_empty() {
                    r"\text{(empty)}".to_string()
                } else {
                    diffs
                }
            ),
        )
        .value(
            "differences",
            Value::List(d.differences.iter().map(|&x| Value::Number(x as f64)).collect()),
        ),
        Step::new(
            "Differential chain code",
            &format!(
                "Negative differences plus {n} (the number of directions): each element counts the turn from one step to the next in {}° steps counter-clockwise, so it does not change when the shape is rotated by a multiple of {}°.",
                360 / u32::from(n),
                360 / u32::from(n)
            ),
        )
        .formula(
            &format!(r"d_k \bmod {n}"),
            digits_tex(&d.code),
        )
        .value("differential", digits_value(&d.code)),
    ]
}

/// Warnings for breaks and branches, and the step that shows where.
fn problems(s: &mut Solution, path: &Path, conn: Connectivity) {
    for g in path.gaps.iter().take(LIST) {
        let why = if g.from == g.to {
            "are the same pixel".to_string()
        } else if conn == Connectivity::Four && Connectivity::Eight.between(g.from, g.to).is_some()
        {
            "are diagonal neighbours, not a step with 4-connectivity".to_string()
        } else {
            "are not neighbours".to_string()
        };
        s.note(
            NoteKind::Warning,
            format!(
                "The path is not connected: pixel {} {} and pixel {} {} {why}, so there is no chain code. Fill the gap or choose the other connectivity.",
                g.index + 1,
                pixel_text(g.from),
                g.index + 2,
                pixel_text(g.to)
            ),
        ).about(&["code", "differential", "length", "breaks"]);
    }
    if path.gaps.len() > LIST {
        s.note(
            NoteKind::Warning,
            format!("… and {} more breaks.", path.gaps.len() - LIST),
        )
        .about(&["breaks"]);
    }
    for r in path.revisits.iter().take(LIST) {
        s.note(
            NoteKind::Warning,
            format!(
                "The path branches or crosses itself: pixel {} {} is pixel {} again. A chain code of an edge visits each pixel once; the code below walks the path as given.",
                r.index + 1,
                pixel_text(r.pixel),
                r.first + 1
            ),
        ).about(&["branches"]);
    }
    if path.revisits.len() > LIST {
        s.note(
            NoteKind::Warning,
            format!("… and {} more repeated pixels.", path.revisits.len() - LIST),
        )
        .about(&["branches"]);
    }
    if !path.closed && path.gaps.is_empty() {
        if let (Some(&a), Some(&b)) = (path.pixels.first(), path.pixels.last()) {
            if path.pixels.len() > 2 && conn.between(b, a).is_some() {
                s.note(
                    NoteKind::Warning,
                    format!(
                        "The last pixel {} is a neighbour of the first {}: to code a closed boundary, repeat the first pixel at the end.",
                        pixel_text(b),
                        pixel_text(a)
                    ),
                ).about(&["closed"]);
            }
        }
    }
    if path.pixels.len() == 1 {
        s.note(
            NoteKind::Warning,
            "A single pixel has no steps: its chain code and differential code are empty and its length is 0.",
        ).about(&["code", "differential", "length"]);
    }
}

fn breaks_value(path: &Path) -> Value {
    Value::List(
        path.gaps
            .iter()
            .map(|g| {
                Value::numbers(&[
                    (g.index + 1) as f64,
                    g.from[0] as f64,
                    g.from[1] as f64,
                    g.to[0] as f64,
                    g.to[1] as f64,
                ])
            })
            .collect(),
    )
}

fn branches_value(path: &Path) -> Value {
    Value::List(
        path.revisits
            .iter()
            .map(|r| {
                Value::numbers(&[
                    (r.index + 1) as f64,
                    (r.first + 1) as f64,
                    r.pixel[0] as f64,
                    r.pixel[1] as f64,
                ])
            })
            .collect(),
    )
}

fn broken_step(path: &Path) -> Step {
    let at = list_tex(
        &path.gaps,
        |g| {
            format!(
                r"p_{{{}}}{} \to p_{{{}}}{}",
                g.index + 1,
                pixel_tex(g.from),
                g.index + 2,
                pixel_tex(g.to)
            )
        },
        r",\quad ",
        2,
    );
    Step::new(
        "The path breaks",
        &format!(
            "{} step{} between consecutive pixels {} not a step to a neighbour, so the edge has no chain code until the gaps are filled.",
            path.gaps.len(),
            if path.gaps.len() == 1 { "" } else { "s" },
            if path.gaps.len() == 1 { "is" } else { "are" }
        ),
    )
    .formula(r"p_k \to p_{k+1}\ \text{not neighbours}", at)
    .value("breaks", breaks_value(path))
}

fn regions_note(s: &mut Solution, e: &Edge) {
    if e.regions.len() > 1 {
        let starts: Vec<String> = e
            .regions
            .iter()
            .skip(1)
            .take(LIST)
            .map(|b| b.pixels.first().map(|p| pixel_text(*p)).unwrap_or_default())
            .collect();
        s.note(
            NoteKind::Warning,
            format!(
                "The pixels form {} separate regions; the one starting at {} is used. The others start at {}{}.",
                e.regions.len(),
                e.regions
                    .first()
                    .and_then(|b| b.pixels.first())
                    .map(|p| pixel_text(*p))
                    .unwrap_or_default(),
                starts.join(", "),
                if e.regions.len() > LIST + 1 { ", …" } else { "" }
            ),
        ).about(&["regions"]);
    }
}

fn conn_note(s: &mut Solution, conn: Connectivity) {
    if conn == Connectivity::Four {
        s.note(
            NoteKind::Convention,
            "The course notes' figure of the 4-connectivity numbering is lost; it is taken here as 1 = east, 2 = north, 3 = west, 4 = south, counter-clockwise from east like the 8-connectivity figure. Its differential code counts turns of 90° (mod 4).",
        ).about(&["code", "differential"]);
    }
}

/// The descriptors of a closed boundary as result keys.
fn set_shape(result: &mut Record, sh: &chain::Shape) {
    result.set("diameter", sh.diameter);
    result.set("major_axis", pixel_value(&sh.major_axis));
    result.set("minor_axis_length", sh.minor_axis_length);
    result.set(
        "basic_rectangle",
        Value::List(sh.basic_rectangle.iter().map(|p| point_value(*p)).collect()),
    );
    result.set("eccentricity", sh.eccentricity);
    result.set(
        "minor_axis",
        Value::List(sh.minor_axis.iter().map(|p| point_value(*p)).collect()),
    );
}

/// One step with the descriptors of a closed boundary, for the examples
/// whose subject is the code or the length (`boundary-shape` has a step each).
fn shape_summary_step(sh: &chain::Shape) -> Step {
    let [a, b] = sh.major_axis;
    let e = sh
        .eccentricity
        .map_or(r"\text{no value (}m = 0\text{)}".to_string(), num);
    Step::new(
        "Shape of the closed boundary",
        "The descriptors of the worked examples for this boundary (the example “Boundary descriptors” shows each step): the diameter D between the two farthest pixels (the major axis), the width m across it (the minor axis), the basic rectangle D × m, and the eccentricity D / m.",
    )
    .formula(
        r"D = \max_{i,j} \lVert p_i - p_j \rVert,\quad m = t_{\max} - t_{\min},\quad E = \frac{D}{m}",
        format!(
            r"D = \lVert {} - {} \rVert = {},\quad m = {},\quad E = {}",
            pixel_tex(b),
            pixel_tex(a),
            num(sh.diameter),
            num(sh.minor_axis_length),
            e
        ),
    )
    .value("diameter", sh.diameter)
    .value("minor_axis_length", sh.minor_axis_length)
    .value("eccentricity", sh.eccentricity)
}

/// What each result key means, for the result table.
fn label_results(s: &mut Solution, conn: Connectivity) {
    let digits = match conn {
        Connectivity::Eight => "Chain code (digits 1–8)",
        Connectivity::Four => "Chain code (digits 1–4)",
    };
    s.label_present(&[
        ("code", digits, ""),
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
    ]);
}

// ---------------------------------------------------------------- solvers

/// The step that adds up a length.
fn length_step(l: &chain::Length, conn: Connectivity, p: &Path) -> Step {
    let positions = p.pixels.len() + usize::from(p.closed);
    let step = match conn {
        Connectivity::Four if !p.closed => Step::new(
            "Length",
            "A 4-connected edge: every step is one pixel side, so the length is the number of pixels minus 1.",
        )
        .formula(
            "L = N - 1",
            format!("L = {} - 1 = {}", positions, num(l.length)),
        ),
        Connectivity::Four => Step::new(
            "Length",
            "A closed 4-connected boundary: one step per pixel, the last one back to the start, so the length is the number of pixels.",
        )
        .formula("L = N", format!("L = {}", num(l.length))),
        Connectivity::Eight => Step::new(
            "Length",
            "Horizontal and vertical steps count 1, diagonal steps √2 (the diagonal of a pixel).",
        )
        .formula(
            r"L = n_h + n_v + \sqrt{2}\, n_d",
            format!(
                r"L = {} + {} + \sqrt{{2}} \times {} = {}",
                l.horizontal,
                l.vertical,
                l.diagonal,
                num(l.length)
            ),
        ),
    };
    step.value("length", l.length)
}

fn is_code_input(inputs: &Record, code: &[u8], conn: &str) -> bool {
    text(inputs, "given").is_ok_and(|g| g == "code")
        && text(inputs, "connectivity").is_ok_and(|c| c == conn)
        && digits(inputs).is_ok_and(|d| d == code)
}

fn conn_of(text: &str) -> Connectivity {
    if text == "4" {
        Connectivity::Four
    } else {
        Connectivity::Eight
    }
}

fn is_pixel_input(inputs: &Record, start: Pixel, code: &[u8], conn: &str) -> bool {
    text(inputs, "given").is_ok_and(|g| g == "pixels")
        && text(inputs, "connectivity").is_ok_and(|c| c == conn)
        && inputs.get("pixels") == Some(&pixel_value(&decoded(start, code, conn_of(conn))))
}

fn chain_code(inputs: &Record) -> Result<Solution> {
    let conn = connectivity(inputs)?;
    let from_end = text(inputs, "from")? == "end";
    let e = edge(inputs, conn, from_end)?;
    let mut s = Solution::new("chain-code", "Freeman chain code", inputs.clone());
    s.step(edge_step(&e, conn, inputs)?);
    s.step(numbering_step(conn));
    let p = &e.path;
    s.result.set("code", Value::Null);
    s.result.set("differential", Value::Null);
    s.result.set("pixels", pixel_value(&p.pixels));
    s.result.set("closed", p.closed);
    s.result.set("differences", Value::Null);
    if let Some(code) = &p.code {
        s.step(code_step(p, code));
        if let Some(fwd) = &e.forward {
            s.step(reverse_step(fwd, code, conn));
        }
        let d = chain::differential(code, conn, p.closed);
        let [diff, dcode] = differential_steps(&d, p.closed, conn);
        s.step(diff);
        s.step(dcode);
        s.result.set("code", digits_value(code));
        s.result.set("differential", digits_value(&d.code));
        s.result.set(
            "differences",
            Value::List(
                d.differences
                    .iter()
                    .map(|&x| Value::Number(x as f64))
                    .collect(),
            ),
        );
        let l = chain::length(code, conn);
        s.step(length_step(&l, conn, p));
        s.result.set("length", l.length);
        if p.closed {
            let sh = chain::shape("pixels", &p.pixels)?;
            s.step(shape_summary_step(&sh));
            set_shape(&mut s.result, &sh);
        }
    } else {
        s.step(broken_step(p));
        s.result.set("length", Value::Null);
    }
    s.result.set("breaks", breaks_value(p));
    s.result.set("branches", branches_value(p));
    if e.given == Given::Region {
        s.result.set("regions", e.regions.len());
    }
    label_results(&mut s, conn);
    problems(&mut s, p, conn);
    regions_note(&mut s, &e);
    conn_note(&mut s, conn);
    s.note(
        NoteKind::Convention,
        "Differential code as the course notes compute it: each digit minus the one before, plus the number of directions when negative. An open edge of n digits gives n − 1 elements; a closed boundary gives n, the first from its first and last digits.",
    ).about(&["differential", "differences"]);
    let ex17_pixels = is_pixel_input(inputs, EX17_START, &EX17_CODE, "8");
    let ex17 = ex17_pixels || is_code_input(inputs, &EX17_CODE, "8");
    if ex17 && !from_end {
        s.textbook = Some(
            Record::new()
                .with("code", digits_value(&EX17_CODE))
                .with("differential", Value::numbers(&EX17_DIFFERENTIAL))
                .with("differences", Value::numbers(&EX17_DIFFERENCES)),
        );
        s.note(
            NoteKind::Convention,
            format!(
                "Worked examples, Example 17: its figure is lost; the edge shown is rebuilt from the printed code, starting at {} (any start pixel gives the same code). The printed code, the differences and the differential code are reproduced digit for digit.",
                pixel_text(EX17_START)
            ),
        ).about(&["code", "differential", "differences"]);
    }
    if ex17 && from_end {
        if let Some(code) = &p.code {
            let d = chain::differential(code, conn, false);
            s.note(
                NoteKind::Convention,
                format!(
                    "Worked examples, the exercise after Example 17: the same edge coded from its right end. The course notes print no answer; it is {} with differential code {}. Each digit is the opposite of a forward digit, in reverse order, and the differential code is the forward one reversed with every element negated (mod 8).",
                    join(code),
                    join(&d.code)
                ),
            ).about(&["code", "differential"]);
        }
    }
    if is_code_input(inputs, &FIG_C_CODE, "4") && !from_end {
        s.textbook = Some(Record::new().with("code", digits_value(&FIG_C_CODE)));
        s.note(
            NoteKind::Convention,
            format!(
                "Worked examples, figure c: the 4-connectivity chain code printed for a sample edge. The figure is lost; the edge shown is the one this code walks from the start pixel {}.",
                start(inputs).map(pixel_text).unwrap_or_default()
            ),
        ).about(&["code"]);
    }
    Ok(s)
}

fn join(code: &[u8]) -> String {
    code.iter().map(u8::to_string).collect::<Vec<_>>().join(" ")
}

fn boundary_length(inputs: &Record) -> Result<Solution> {
    let conn = connectivity(inputs)?;
    let e = edge(inputs, conn, false)?;
    let p = &e.path;
    let mut s = Solution::new("boundary-length", "Boundary length", inputs.clone());
    s.step(edge_step(&e, conn, inputs)?);
    s.result.set("length", Value::Null);
    s.result.set("horizontal", Value::Null);
    s.result.set("vertical", Value::Null);
    s.result.set("diagonal", Value::Null);
    s.result.set("pixel_count", p.pixels.len());
    if let Some(code) = &p.code {
        s.step(code_step(p, code));
        let l = chain::length(code, conn);
        s.step(
            Step::new(
                "Counting the steps",
                match conn {
                    Connectivity::Eight => "Horizontal steps are digits 1 and 5, vertical ones 3 and 7, diagonal ones the even digits 2, 4, 6, 8.",
                    Connectivity::Four => "Horizontal steps are digits 1 and 3, vertical ones 2 and 4; there are no diagonal steps.",
                },
            )
            .formula(
                r"n_h,\ n_v,\ n_d",
                format!(
                    r"n_h = {},\ n_v = {},\ n_d = {}",
                    l.horizontal, l.vertical, l.diagonal
                ),
            )
            .value("horizontal", l.horizontal)
            .value("vertical", l.vertical)
            .value("diagonal", l.diagonal),
        );
        s.step(length_step(&l, conn, p));
        s.result.set("length", l.length);
        s.result.set("horizontal", l.horizontal);
        s.result.set("vertical", l.vertical);
        s.result.set("diagonal", l.diagonal);
        s.result.set("code", digits_value(code));
        let d = chain::differential(code, conn, p.closed);
        let [_, dcode] = differential_steps(&d, p.closed, conn);
        s.step(dcode);
        s.result.set("differential", digits_value(&d.code));
        if p.closed {
            let sh = chain::shape("pixels", &p.pixels)?;
            s.step(shape_summary_step(&sh));
            set_shape(&mut s.result, &sh);
        }
    } else {
        s.step(broken_step(p));
        s.result.set("code", Value::Null);
        s.result.set("differential", Value::Null);
    }
    s.result.set("pixels", pixel_value(&p.pixels));
    s.result.set("closed", p.closed);
    s.result.set("breaks", breaks_value(p));
    s.result.set("branches", branches_value(p));
    if e.given == Given::Region {
        s.result.set("regions", e.regions.len());
    }
    problems(&mut s, p, conn);
    regions_note(&mut s, &e);
    conn_note(&mut s, conn);
    label_results(&mut s, conn);
    if p.closed && p.code.is_some() {
        s.note(
            NoteKind::Convention,
            "A closed boundary's length includes the step from the last pixel back to the first.",
        )
        .about(&["length"]);
    }
    let b = is_pixel_input(inputs, EX18B_START, &EX18B_CODE, "8")
        || is_code_input(inputs, &EX18B_CODE, "8");
    let a = is_pixel_input(inputs, EX18A_START, &EX18A_CODE, "4")
        || is_code_input(inputs, &EX18A_CODE, "4");
    if b {
        s.textbook = Some(
            Record::new()
                .with("length", 20.7)
                .with("horizontal", 4.0)
                .with("vertical", 4.0)
                .with("diagonal", 9.0),
        );
        s.note(
            NoteKind::Convention,
            "Worked examples, Example 18 (b): its figure is lost; the curve shown is a rebuilt one with the course notes' counts, 4 horizontal, 4 vertical and 9 diagonal steps (only the counts matter for the length).",
        ).about(&["horizontal", "vertical", "diagonal"]);
        s.note(
            NoteKind::Rounding,
            format!(
                "The course notes print 4 + 4 + 9√2 = 20.7; exactly it is {} (rounded to one decimal; {}).",
                num(8.0 + 9.0 * std::f64::consts::SQRT_2),
                exact_minus_printed(8.0 + 9.0 * std::f64::consts::SQRT_2, 20.7, "")
            ),
        )
        .about(&["length"]);
    }
    if a {
        s.textbook = Some(Record::new().with("length", 23.0).with("pixel_count", 24.0));
        s.note(
            NoteKind::Convention,
            "Worked examples, Example 18 (a): its figure is lost; the curve shown is a rebuilt 4-connected edge with the course notes' 24 pixels (only the count matters for the length): 24 − 1 = 23, as printed.",
        ).about(&["length", "pixel_count"]);
    }
    Ok(s)
}

fn point_value(p: [f64; 2]) -> Value {
    Value::numbers(&p)
}

fn boundary_shape(inputs: &Record) -> Result<Solution> {
    let conn = connectivity(inputs)?;
    let mut probe = inputs.clone();
    probe.set("given", "region");
    let e = edge(&probe, conn, false)?;
    let b = &e.path.pixels;
    let sh = chain::shape("pixels", b)?;
    let mut s = Solution::new("boundary-shape", "Boundary descriptors", inputs.clone());
    s.step(edge_step(&e, conn, &probe)?);
    let [a, z] = sh.major_axis;
    s.step(
        Step::new(
            "Diameter",
            "The largest distance between two boundary pixels (between pixel centres); the first such pair along the boundary is taken.",
        )
        .formula(
            r"D = \max_{i,j} \sqrt{(c_i - c_j)^2 + (r_i - r_j)^2}",
            format!(
                r"D = \sqrt{{({} - {})^2 + ({} - {})^2}} = {}",
                z[0],
                tex(a[0] as f64),
                z[1],
                tex(a[1] as f64),
                num(sh.diameter)
            ),
        )
        .value("diameter", sh.diameter),
    );
    let u = sh.axis_direction;
    s.step(
        Step::new(
            "Major axis",
            "The segment between the two farthest pixels; its direction u is the unit vector from one end to the other.",
        )
        .formula(
            r"u = \frac{p_b - p_a}{D}",
            format!(
                r"p_a = {},\ p_b = {},\ u = ({},\ {})",
                pixel_tex(a),
                pixel_tex(z),
                num(u[0]),
                num(u[1])
            ),
        )
        .value("major_axis", pixel_value(&sh.major_axis))
        .value("direction", point_value(u)),
    );
    s.step(
        Step::new(
            "Minor axis",
            "Perpendicular to the major axis (direction v), as long as the boundary is wide across it: the offsets t of all boundary pixels along v, from the major axis, span the minor axis. It is drawn through the middle of the basic rectangle.",
        )
        .formula(
            r"v = (-u_r,\ u_c),\quad t_i = (p_i - p_a)\cdot v,\quad m = t_{\max} - t_{\min}",
            format!(
                r"t_{{\min}} = {},\ t_{{\max}} = {},\ m = {}",
                num(sh.across[0]),
                num(sh.across[1]),
                num(sh.minor_axis_length)
            ),
        )
        .value("minor_axis_length", sh.minor_axis_length)
        .value(
            "minor_axis",
            Value::List(sh.minor_axis.iter().map(|p| point_value(*p)).collect()),
        ),
    );
    let rect = Value::List(sh.basic_rectangle.iter().map(|p| point_value(*p)).collect());
    s.step(
        Step::new(
            "Basic rectangle",
            "The box with sides along the two axes that just encloses the boundary: from one end of the major axis to the other, and from the smallest to the largest distance across it.",
        )
        .formula(
            r"p_a + s\,u + t\,v,\quad s \in \{0, D\},\ t \in \{t_{\min}, t_{\max}\}",
            list_tex(
                &sh.basic_rectangle,
                |p| format!("({},\\ {})", num(p[0]), num(p[1])),
                r"\;",
                2,
            ),
        )
        .value("basic_rectangle", rect.clone()),
    );
    let ecc_step = Step::new(
        "Eccentricity",
        "The ratio of the major axis to the minor axis.",
    );
    s.step(match sh.eccentricity {
        Some(x) => ecc_step
            .formula(
                r"E = \frac{D}{m}",
                format!(
                    r"E = \frac{{{}}}{{{}}} = {}",
                    num(sh.diameter),
                    num(sh.minor_axis_length),
                    num(x)
                ),
            )
            .value("eccentricity", x),
        None => ecc_step
            .formula(
                r"E = \frac{D}{m}",
                format!(
                    r"E = \frac{{{}}}{{0}}\ \text{{: no value}}",
                    num(sh.diameter)
                ),
            )
            .value("eccentricity", Value::Null),
    });
    s.result = Record::new();
    set_shape(&mut s.result, &sh);
    let code = e.path.code.clone().unwrap_or_default();
    let d = chain::differential(&code, conn, e.path.closed);
    let l = chain::length(&code, conn);
    s.step(
        Step::new(
            "Code and length of the traced boundary",
            "The traced boundary's chain code (closed: the last digit leads back to the start), its differential code (the first element from the last and the first digit) and its length (axial steps 1, diagonal steps √2).",
        )
        .formula(
            r"a,\quad d_k = (a_k - a_{k-1}) \bmod n,\quad L = n_h + n_v + \sqrt{2}\, n_d",
            format!(
                r"a = {},\quad d = {},\quad L = {} + {} + \sqrt{{2}} \times {} = {}",
                digits_tex(&code),
                digits_tex(&d.code),
                l.horizontal,
                l.vertical,
                l.diagonal,
                num(l.length)
            ),
        )
        .value("code", digits_value(&code))
        .value("differential", digits_value(&d.code))
        .value("length", l.length),
    );
    s.result.set("boundary", pixel_value(b));
    s.result.set("code", digits_value(&code));
    s.result.set("differential", digits_value(&d.code));
    s.result.set("length", l.length);
    s.result.set("closed", e.path.closed);
    s.result.set("regions", e.regions.len());
    label_results(&mut s, conn);
    if sh.eccentricity.is_none() {
        s.note(
            NoteKind::Warning,
            "All boundary pixels lie on one straight line, so the minor axis has length 0 and the eccentricity has no value.",
        ).about(&["minor_axis_length", "eccentricity"]);
    }
    regions_note(&mut s, &e);
    conn_note(&mut s, conn);
    s.note(
        NoteKind::Convention,
        "Distances are measured between pixel centres (a pixel's own size is not added), as the boundary length is. The course notes do not fix where the minor axis crosses the major one; it is drawn through the centre of the basic rectangle. The diameter and the rectangle only depend on the outermost pixels, so a filled region and its boundary give the same values.",
    ).about(&["diameter", "major_axis", "minor_axis_length", "basic_rectangle"]);
    Ok(s)
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
