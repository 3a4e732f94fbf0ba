//! Seed 000, Example 18: the length of a boundary from its chain code.

use super::*;
use crate::examples::drill::{drill, or_given, tol, value_in, BoxDef, Drill, Mistake, Tolerance};
use crate::examples::Lab;

pub const EXAMPLE: Example = Example {
    id: "boundary-length",
    title: "Boundary length",
    source: "Worked examples, Example 18",
    summary: "The length of a digital edge: pixels minus one when 4-connected; axial steps 1 and diagonal steps √2 when 8-connected.",
    fields,
    solve,
    answer: &["length"],
    labels: LABELS,
    lab: Some(Lab::new("boundaries", &[])),
    practice: drill(Drill::new(gen_edge, boxes, Some(chain), mistakes)),
};

/// Example 18 (a), rebuilt: a 4-connected edge of 24 pixels.
const EX18A_START: Pixel = [1, 1];
const EX18A_CODE: [u8; 23] = [
    1, 1, 4, 4, 1, 1, 1, 2, 2, 1, 1, 1, 4, 4, 4, 1, 1, 2, 2, 2, 1, 1, 4,
];
/// Example 18 (b), rebuilt: 4 horizontal, 4 vertical and 9 diagonal steps.
const EX18B_START: Pixel = [1, 1];
const EX18B_CODE: [u8; 17] = [1, 8, 8, 8, 7, 7, 8, 1, 2, 2, 3, 3, 2, 2, 1, 8, 1];

fn fields() -> Vec<Field> {
    edge_fields(EX18B_START, &EX18B_CODE)
}

fn solve(inputs: &Record) -> Result<Solution> {
    let conn = connectivity(inputs)?;
    let e = edge(inputs, conn, false)?;
    let p = &e.path;
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
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
            .relations(count_relations(&l, conn))
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
        closed_shape(&mut s, p)?;
    } else {
        s.step(broken_step(p));
        s.result.set("code", Value::Null);
        s.result.set("differential", Value::Null);
    }
    s.result.set("pixels", pixel_value(&p.pixels));
    s.result.set("closed", p.closed);
    path_results(&mut s.result, &e);
    problems(&mut s, p, conn);
    regions_note(&mut s, &e);
    conn_note(&mut s, conn);
    label_code(&mut s, conn);
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

/// `n_h`, `n_v`, `n_d`: how many digits of each kind, counted.
fn count_relations(l: &chain::Length, conn: Connectivity) -> Vec<Relation> {
    let (h, v, d) = match conn {
        Connectivity::Eight => (r"\{1, 5\}", r"\{3, 7\}", r"\{2, 4, 6, 8\}"),
        Connectivity::Four => (r"\{1, 3\}", r"\{2, 4\}", r"\{\}"),
    };
    [
        ("n_h", "horizontal", h, l.horizontal),
        ("n_v", "vertical", v, l.vertical),
        ("n_d", "diagonal", d, l.diagonal),
    ]
    .into_iter()
    .map(|(lhs, key, digits, n)| {
        Relation::new(lhs)
            .key(key)
            .sym(format!(r"\#\{{k : a_k \in {digits}\}}"))
            .value(n as f64, "")
    })
    .collect()
}

// ---------------------------------------------------------------- practice

fn boxes(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("horizontal", "Horizontal steps", None, tol::WHOLE)
            .nudge("Steps straight left or right: codes 1 and 5."),
        BoxDef::new("vertical", "Vertical steps", None, tol::WHOLE)
            .nudge("Steps straight up or down: codes 3 and 7."),
        BoxDef::new("diagonal", "Diagonal steps", None, tol::WHOLE)
            .nudge("The even codes: 2, 4, 6, 8."),
        BoxDef::new("length", "Length", Some("px"), Tolerance::abs(0.005))
            .nudge("Straight steps count 1, diagonal ones √2."),
    ]
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = EXAMPLE.run(i)?;
    let h = or_given(g, "horizontal", value_in(&s, "horizontal")?);
    let v = or_given(g, "vertical", value_in(&s, "vertical")?);
    let d = or_given(g, "diagonal", value_in(&s, "diagonal")?);
    Ok(Record::new()
        .with("horizontal", h)
        .with("vertical", v)
        .with("diagonal", d)
        .with("length", h + v + std::f64::consts::SQRT_2 * d))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let v = chain(i, &Record::new())?;
    let n = |k: &str| v.number(k).unwrap_or(f64::NAN);
    let (h, vv, d) = (n("horizontal"), n("vertical"), n("diagonal"));
    Ok(vec![
        Mistake::new(
            "length",
            "diagonal steps counted as 1",
            "A diagonal step is √2 pixel spacings long.",
            h + vv + d,
        ),
        Mistake::new(
            "length",
            "4- vs 8-connectivity",
            "With 8-connectivity a diagonal is one step of √2; 4-connectivity would walk it as two steps.",
            h + vv + 2.0 * d,
        ),
    ])
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
