//! Seed 000, Example 17 and the exercise: the chain code of a boundary,
//! its reverse and its differential code.

use super::*;
use crate::examples::drill::{drill, or_given, tol, value_in, BoxDef, Drill, Mistake};
use crate::examples::fields::Inputs;
use crate::examples::Lab;

pub const EXAMPLE: Example = Example {
    id: "chain-code",
    title: "Freeman chain code",
    source: "Worked examples, Example 17 and the exercise",
    summary: "The chain code and differential chain code of a digital edge or closed boundary, from its pixels, from a code, or traced around drawn regions.",
    fields,
    solve,
    answer: &["code", "differential"],
    labels: LABELS,
    lab: Some(Lab::new("boundaries", &["code"])),
    practice: drill(Drill::new(gen_edge, boxes, Some(chain), mistakes)),
};

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
const FROM: &[(&str, &str)] = &[
    ("start", "From the first pixel (the left end)"),
    ("end", "From the last pixel (the right end)"),
];

fn fields() -> Vec<Field> {
    let mut fields = edge_fields(EX17_START, &EX17_CODE);
    fields.push(
        Field::choice("from", "Start coding from", FROM, "start").help(
            "The course notes' Example 17 starts at the left end; its exercise at the right end. A closed boundary is walked the other way round.",
        ),
    );
    fields
}

fn solve(inputs: &Record) -> Result<Solution> {
    let conn = connectivity(inputs)?;
    let from_end = Inputs(inputs).text("from")? == "end";
    let e = edge(inputs, conn, from_end)?;
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
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
        closed_shape(&mut s, p)?;
    } else {
        s.step(broken_step(p));
        s.result.set("length", Value::Null);
    }
    path_results(&mut s.result, &e);
    label_code(&mut s, conn);
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

// ---------------------------------------------------------------- practice

fn boxes(_: &Record) -> Vec<BoxDef> {
    let mut b: Vec<BoxDef> = (1..=STEPS)
        .map(|k| {
            BoxDef::new(&format!("code[{k}]"), &format!("Code digit {k}"), None, tol::WHOLE)
                .nudge("1 = east, counted counter-clockwise: 2 north-east, 3 north … 8 south-east. Rows count down, so north is r − 1.")
        })
        .collect();
    for k in 1..STEPS {
        b.push(
            BoxDef::new(
                &format!("differential[{k}]"),
                &format!("Differential digit {k}"),
                None,
                tol::WHOLE,
            )
            .nudge("Each digit minus the one before; add 8 when it is negative."),
        );
    }
    b
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = EXAMPLE.run(i)?;
    let mut out = Record::new();
    let mut code = Vec::new();
    for k in 1..=STEPS {
        let key = format!("code[{k}]");
        let d = or_given(g, &key, value_in(&s, &key)?);
        code.push(d);
        out.set(&key, d);
    }
    for k in 1..STEPS {
        out.set(
            &format!("differential[{k}]"),
            (code[k] - code[k - 1]).rem_euclid(8.0),
        );
    }
    Ok(out)
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let v = chain(i, &Record::new())?;
    let digit = |k: usize| v.number(&format!("code[{k}]")).unwrap_or(f64::NAN);
    let mut out = Vec::new();
    for k in 1..=STEPS {
        let d = digit(k);
        out.push(Mistake::new(
            &format!("code[{k}]"),
            "y not flipped",
            "Rows count down: a step to r − 1 goes north (2 or 3), to r + 1 south (7 or 8).",
            (9.0 - d).rem_euclid(8.0) + 1.0,
        ));
        // 4-connectivity numbering: 1 east, 2 north, 3 west, 4 south.
        let four = match d as u8 {
            3 => Some(2.0),
            7 => Some(4.0),
            _ => None,
        };
        if let Some(f) = four {
            out.push(Mistake::new(
                &format!("code[{k}]"),
                "4- vs 8-connectivity",
                "With 8 directions north is 3 and south 7; 2 and 4 are the 4-connectivity numbers.",
                f,
            ));
        }
    }
    for k in 1..STEPS {
        out.push(Mistake::new(
            &format!("differential[{k}]"),
            "subtracted the wrong way round",
            "The differential digit is this digit minus the one before, not the other way.",
            (digit(k) - digit(k + 1)).rem_euclid(8.0),
        ));
    }
    Ok(out)
}
