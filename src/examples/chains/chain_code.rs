//! Example 17 and the exercise: the chain code of a boundary, its reverse and its differential code.

use super::*;

pub(super) fn chain_code(inputs: &Record) -> Result<Solution> {
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

pub(super) fn join(code: &[u8]) -> String {
    code.iter().map(u8::to_string).collect::<Vec<_>>().join(" ")
}
