//! The edge a solver works on (pixels, a region or a chain code, read from the inputs) and the steps the three examples share.

use super::*;

#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Given {
    Pixels,
    Code,
    Region,
}

/// The edge an example works on, however it was given.
pub(super) struct Edge {
    pub(super) given: Given,
    pub(super) path: Path,
    /// The code before it was reversed ("from the end"), when it was.
    pub(super) forward: Option<Vec<u8>>,
    /// Region mode: every region's outer boundary.
    pub(super) regions: Vec<Boundary>,
}

pub(super) fn edge(inputs: &Record, conn: Connectivity, from_end: bool) -> Result<Edge> {
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

pub(super) fn pixel_tex(p: Pixel) -> String {
    format!("({},{})", p[0], p[1])
}

/// Items as pieces of a formula the page may break between, the later
/// ones after `sep` (`\;`), at most [`SHOW`] of them and then how many in all.
pub(super) fn list_form<T>(items: &[T], f: impl Fn(&T) -> String, sep: &str) -> Form {
    let mut pieces: Vec<String> = items
        .iter()
        .take(SHOW)
        .enumerate()
        .map(|(k, x)| {
            if k == 0 {
                f(x)
            } else {
                format!("{sep}{}", f(x))
            }
        })
        .collect();
    if items.len() > SHOW {
        pieces.push(format!(r"\ldots\ (\text{{{} in all}})", items.len()));
    }
    Form::terms(pieces)
}

/// A chain code's digits (`\text{(empty)}` for none).
pub(super) fn digits_form(code: &[u8]) -> Form {
    if code.is_empty() {
        return Form::from(r"\text{(empty)}");
    }
    list_form(code, |d| d.to_string(), r"\;")
}

pub(super) fn pixel_text(p: Pixel) -> String {
    format!("({}, {})", p[0], p[1])
}

pub(super) fn edge_step(e: &Edge, conn: Connectivity, inputs: &Record) -> Result<Step> {
    let p = &e.path;
    let n = p.pixels.len();
    let kind = if p.closed {
        "closed boundary"
    } else {
        "open edge"
    };
    let shown = || {
        Relation::new(Form::default())
            .key("pixels")
            .result(list_form(&p.pixels, |q| pixel_tex(*q), r"\;"))
    };
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
        .relation(Relation::new(Form::default()).sym(r"p_1, p_2, \ldots, p_n"))
        .relation(shown()),
        Given::Code => {
            let s = start(inputs)?;
            Step::new(
                "Decoding the code",
                &format!(
                    "From the start pixel {} each digit moves one step in its direction; the walk visits {n} pixels ({kind}).",
                    pixel_text(s)
                ),
            )
            .relation(Relation::new("p_{k+1}").sym(r"p_k + \Delta(a_k)"))
            .relation(shown())
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
            .relation(Relation::new(Form::default()).sym(r"b_1, b_2, \ldots, b_n"))
            .relation(shown())
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

pub(super) fn numbering_step(conn: Connectivity) -> Step {
    let cells = |rows: [[&str; 3]; 3]| {
        rows.iter()
            .map(|r| r.iter().map(|c| c.to_string()).collect())
            .collect()
    };
    let (figure, text) = match conn {
        Connectivity::Eight => (
            cells([["4", "3", "2"], ["5", r"\cdot", "1"], ["6", "7", "8"]]),
            "Each step to one of the eight neighbours gets a digit: 1 to the east, counting counter-clockwise to 8 to the south-east (rows count downward, so 3 = north is one row up).",
        ),
        Connectivity::Four => (
            cells([["", "2", ""], ["3", r"\cdot", "1"], ["", "4", ""]]),
            "With 4-connectivity only the four axial steps are allowed: 1 east, 2 north, 3 west, 4 south, counter-clockwise as in the 8-connectivity figure.",
        ),
    };
    let mut step = Step::new("Direction numbers", text).relation(
        Relation::new(Form::default()).sym(Form::grid_tex("array", figure, "direction numbers")),
    );
    for d in 1..=conn.directions() {
        if let Some((dc, dr)) = conn.step(d) {
            step = step
                .relation(Relation::new(format!(r"\Delta({d})")).result(format!("({dc},{dr})")));
        }
    }
    step
}

pub(super) fn code_step(path: &Path, code: &[u8]) -> Step {
    Step::new(
        "Chain code",
        &format!(
            "The direction of each step from one pixel to the next, {} digit{}.",
            code.len(),
            if code.len() == 1 { "" } else { "s" }
        ),
    )
    .relation(Relation::new("a_k").sym(r"\operatorname{dir}(c_{k+1} - c_k,\ r_{k+1} - r_k)"))
    .relation(Relation::new("a").key("code").result(digits_form(code)))
    .value("code", digits_value(code))
    .value("pixels", pixel_value(&path.pixels))
}

pub(super) fn reverse_step(forward: &[u8], code: &[u8], conn: Connectivity) -> Step {
    let half = conn.directions() / 2;
    Step::new(
        "Coding from the other end",
        &format!(
            "Walking the edge the other way takes the steps in reverse order, each in the opposite direction: the forward code read backwards with {half} added (mod {}).",
            conn.directions()
        ),
    )
    .relation(Relation::new("a'_k").sym(format!(
        r"(a_{{n+1-k}} + {half} - 1) \bmod {} + 1",
        conn.directions()
    )))
    .relation(Relation::new("a").key("forward").result(digits_form(forward)))
    .relation(Relation::new("a'").key("code").result(digits_form(code)))
    .value("forward", digits_value(forward))
}

pub(super) fn differential_steps(
    d: &chain::Differential,
    closed: bool,
    conn: Connectivity,
) -> [Step; 2] {
    let n = conn.directions();
    let diffs = if d.differences.is_empty() {
        Form::from(r"\text{(empty)}")
    } else {
        list_form(&d.differences, |x| tex(*x as f64), r"\;")
    };
    let rule = if closed {
        vec![
            Relation::new("d_1").sym("a_1 - a_n"),
            Relation::new("d_k").sym("a_k - a_{k-1}"),
        ]
    } else {
        vec![Relation::new("d_k").sym("a_{k+1} - a_k")]
    };
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
        .relations(rule)
        .relation(Relation::new("d").key("differences").result(diffs))
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
        .relation(
            Relation::new(Form::default())
                .key("differential")
                .sym(format!(r"d_k \bmod {n}"))
                .result(digits_form(&d.code)),
        )
        .value("differential", digits_value(&d.code)),
    ]
}

/// Warnings for breaks and branches, and the step that shows where.
pub(super) fn problems(s: &mut Solution, path: &Path, conn: Connectivity) {
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

pub(super) fn breaks_value(path: &Path) -> Value {
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

pub(super) fn branches_value(path: &Path) -> Value {
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

pub(super) fn broken_step(path: &Path) -> Step {
    let mut step = Step::new(
        "The path breaks",
        &format!(
            "{} step{} between consecutive pixels {} not a step to a neighbour, so the edge has no chain code until the gaps are filled.",
            path.gaps.len(),
            if path.gaps.len() == 1 { "" } else { "s" },
            if path.gaps.len() == 1 { "is" } else { "are" }
        ),
    )
    .relation(
        Relation::new("p_k")
            .op(r"\to")
            .sym(r"p_{k+1}\ \text{not neighbours}"),
    );
    for g in path.gaps.iter().take(SHOW) {
        step = step.relation(
            Relation::new(format!(r"p_{{{}}}{}", g.index + 1, pixel_tex(g.from)))
                .key("breaks")
                .op(r"\to")
                .result(format!(r"p_{{{}}}{}", g.index + 2, pixel_tex(g.to))),
        );
    }
    if path.gaps.len() > SHOW {
        step = step.relation(
            Relation::new(Form::default())
                .result(format!(r"\ldots\ (\text{{{} in all}})", path.gaps.len())),
        );
    }
    step.value("breaks", breaks_value(path))
}

pub(super) fn regions_note(s: &mut Solution, e: &Edge) {
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

pub(super) fn conn_note(s: &mut Solution, conn: Connectivity) {
    if conn == Connectivity::Four {
        s.note(
            NoteKind::Convention,
            "The course notes' figure of the 4-connectivity numbering is lost; it is taken here as 1 = east, 2 = north, 3 = west, 4 = south, counter-clockwise from east like the 8-connectivity figure. Its differential code counts turns of 90° (mod 4).",
        ).about(&["code", "differential"]);
    }
}

/// The descriptors of a closed boundary as result keys.
pub(super) fn set_shape(result: &mut Record, sh: &chain::Shape) {
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

/// The descriptors of a closed boundary (one summary step and their
/// result keys); nothing for an open edge.
pub(super) fn closed_shape(s: &mut Solution, p: &Path) -> Result<()> {
    if p.closed {
        let sh = chain::shape("pixels", &p.pixels)?;
        s.step(shape_summary_step(&sh));
        set_shape(&mut s.result, &sh);
    }
    Ok(())
}

/// Where the path breaks or branches, and how many regions were traced.
pub(super) fn path_results(result: &mut Record, e: &Edge) {
    result.set("breaks", breaks_value(&e.path));
    result.set("branches", branches_value(&e.path));
    if e.given == Given::Region {
        result.set("regions", e.regions.len());
    }
}

/// One step with the descriptors of a closed boundary, for the examples
/// whose subject is the code or the length (the boundary descriptors
/// example has a step each).
pub(super) fn shape_summary_step(sh: &chain::Shape) -> Step {
    let [a, b] = sh.major_axis;
    let e = sh
        .eccentricity
        .map_or(r"\text{no value (}m = 0\text{)}".to_string(), num);
    Step::new(
        "Shape of the closed boundary",
        "The descriptors of the worked examples for this boundary (the example “Boundary descriptors” shows each step): the diameter D between the two farthest pixels (the major axis), the width m across it (the minor axis), the basic rectangle D × m, and the eccentricity D / m.",
    )
    .relation(
        Relation::new("D")
            .key("diameter")
            .sym(r"\max_{i,j} \lVert p_i - p_j \rVert")
            .subst(format!(r"\lVert {} - {} \rVert", pixel_tex(b), pixel_tex(a)))
            .value(sh.diameter, ""),
    )
    .relation(
        Relation::new("m")
            .key("minor_axis_length")
            .sym(r"t_{\max} - t_{\min}")
            .value(sh.minor_axis_length, ""),
    )
    .relation(
        Relation::new("E")
            .key("eccentricity")
            .sym(r"\frac{D}{m}")
            .result(e),
    )
    .value("diameter", sh.diameter)
    .value("minor_axis_length", sh.minor_axis_length)
    .value("eccentricity", sh.eccentricity)
}

// ---------------------------------------------------------------- solvers

/// The step that adds up a length.
pub(super) fn length_step(l: &chain::Length, conn: Connectivity, p: &Path) -> Step {
    let positions = p.pixels.len() + usize::from(p.closed);
    let step = match conn {
        Connectivity::Four if !p.closed => Step::new(
            "Length",
            "A 4-connected edge: every step is one pixel side, so the length is the number of pixels minus 1.",
        )
        .relation(
            Relation::new("L")
                .key("length")
                .sym("N - 1")
                .subst(format!("{positions} - 1"))
                .value(l.length, ""),
        ),
        Connectivity::Four => Step::new(
            "Length",
            "A closed 4-connected boundary: one step per pixel, the last one back to the start, so the length is the number of pixels.",
        )
        .relation(Relation::new("L").key("length").sym("N").value(l.length, "")),
        Connectivity::Eight => Step::new(
            "Length",
            "Horizontal and vertical steps count 1, diagonal steps √2 (the diagonal of a pixel).",
        )
        .relation(length_relation(l)),
    };
    step.value("length", l.length)
}

pub(super) fn is_code_input(inputs: &Record, code: &[u8], conn: &str) -> bool {
    Inputs(inputs).text("given").is_ok_and(|g| g == "code")
        && Inputs(inputs).text("connectivity").is_ok_and(|c| c == conn)
        && digits(inputs).is_ok_and(|d| d == code)
}

pub(super) fn conn_of(text: &str) -> Connectivity {
    if text == "4" {
        Connectivity::Four
    } else {
        Connectivity::Eight
    }
}

pub(super) fn is_pixel_input(inputs: &Record, start: Pixel, code: &[u8], conn: &str) -> bool {
    Inputs(inputs).text("given").is_ok_and(|g| g == "pixels")
        && Inputs(inputs).text("connectivity").is_ok_and(|c| c == conn)
        && inputs.get("pixels") == Some(&pixel_value(&decoded(start, code, conn_of(conn))))
}

/// `L = n_h + n_v + √2 n_d` with the counts put in.
pub(super) fn length_relation(l: &chain::Length) -> Relation {
    Relation::new("L")
        .key("length")
        .sym(r"n_h + n_v + \sqrt{2}\, n_d")
        .subst(format!(
            r"{} + {} + \sqrt{{2}} \times {}",
            l.horizontal, l.vertical, l.diagonal
        ))
        .value(l.length, "")
}
