//! Example 18: the length of a boundary from its chain code.

use super::*;

pub(super) fn boundary_length(inputs: &Record) -> Result<Solution> {
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
