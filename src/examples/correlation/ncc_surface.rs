//! Example 7: the correlation surface of a 2-D template over a search array.

use super::*;

/// A grid's centre offset: `(size − 1)/2`.
pub(super) fn half(size: usize) -> f64 {
    (size as f64 - 1.0) / 2.0
}

pub(super) fn ncc_surface(inputs: &Record) -> Result<Solution> {
    let template = grid(inputs, "template")?;
    let search = grid(inputs, "search")?;
    let surface = correlate_2d(&template, &search)?;
    let (tw, th) = (template.width(), template.height());
    let mut s = Solution::new("ncc-surface", "Correlation surface", inputs.clone());
    let t_mean = surface.windows.first().map_or(0.0, |w| w.mean_a);
    let t_da2 = surface.windows.first().map_or(0.0, |w| w.sum_da2);
    s.step(
        Step::new(
            "Template mean",
            "The template's mean and the sum of its squared deviations, the same for every position.",
        )
        .formula(
            r"\bar T = \frac{1}{mn}\sum T_{ij},\quad \sum (T_{ij} - \bar T)^2",
            format!(
                r"{},\quad \sum (T_{{ij}} - \bar T)^2 = {} = {}",
                tex_mean(r"\sum T_{ij}", r"\bar T", template.data(), t_mean),
                tex_dev_terms(template.data(), t_mean, None),
                num(t_da2)
            ),
        )
        .value("mean_template", t_mean)
        .value("sum_da2", t_da2),
    );
    let (w, h) = (surface.width, surface.height);
    s.step(
        Step::new(
            "Positions",
            &format!(
                "The {th}×{tw} template is placed at every position where it fits inside the {}×{} search array: {} − {th} + 1 = {h} rows by {} − {tw} + 1 = {w} columns of positions, numbered 1 … {} row by row.",
                search.height(),
                search.width(),
                search.height(),
                search.width(),
                w * h
            ),
        )
        .formula(
            r"K_r = R - m + 1,\quad K_c = C - n + 1",
            format!(
                "K_r = {} - {th} + 1 = {h},\\quad K_c = {} - {tw} + 1 = {w}",
                search.height(),
                search.width()
            ),
        )
        .value("rows", h as f64)
        .value("cols", w as f64),
    );

    if let Some((bc, br)) = surface.best {
        if let (Some(bw), Some(win)) = (
            surface.windows.get(br * w + bc),
            search.window(bc, br, tw, th),
        ) {
            let wv = win.data();
            let step = Step::new(
                "The best window in full",
                &format!(
                    "The window at position {} (rows {}–{}, columns {}–{} of the search array), computed term by term; every other position is computed the same way (select one in the figure).",
                    br * w + bc + 1,
                    br + 1,
                    br + th,
                    bc + 1,
                    bc + tw
                ),
            )
            .formula(
                &format!(r"\bar B = \frac{{1}}{{mn}}\sum B_{{ij}},\quad {RHO_SYMBOLIC}"),
                format!(
                    r"{},\quad {}",
                    tex_mean(r"\sum B_{ij}", r"\bar B", wv, bw.mean_b),
                    tex_rho_chain(r"\rho", template.data(), wv, bw)
                ),
            )
            .value("position", (br * w + bc + 1) as f64)
            .value("window", Value::matrix(&win.rows()));
            s.step(ncc_values(step, bw));
        }
    }

    let rho_rows = surface.rho_rows();
    let grid_of = |f: &dyn Fn(&Ncc) -> f64| -> Value {
        Value::List(
            surface
                .windows
                .chunks(w.max(1))
                .map(|row| Value::numbers(&row.iter().map(f).collect::<Vec<_>>()))
                .collect(),
        )
    };
    let tex_rows: Vec<String> = rho_rows
        .iter()
        .take(MAX_TERMS)
        .map(|r| {
            let mut cells: Vec<String> = r.iter().take(MAX_TERMS).map(|x| rho_text(*x)).collect();
            if r.len() > MAX_TERMS {
                cells.push(r"\cdots".to_string());
            }
            cells.join(" & ")
        })
        .collect();
    let more_rows = if rho_rows.len() > MAX_TERMS {
        r" \\ \vdots"
    } else {
        ""
    };
    s.step(
        Step::new(
            "Correlation surface",
            "The correlation coefficient at every position, as a grid: row i, column j is the window whose top-left pixel is row i, column j of the search array.",
        )
        .formula(
            r"\rho_{ij}",
            format!(
                r"\rho = \begin{{bmatrix}} {}{more_rows} \end{{bmatrix}}",
                tex_rows.join(r" \\ ")
            ),
        )
        .value("rho", opt_rows(&rho_rows))
        .value("mean_b", grid_of(&|n: &Ncc| n.mean_b))
        .value("sum_dadb", grid_of(&|n: &Ncc| n.sum_dadb))
        .value("sum_db2", grid_of(&|n: &Ncc| n.sum_db2)),
    );

    let (hx, hy) = (half(tw), half(th));
    let best = surface.best.map(|(c, r)| {
        (
            (r * w + c + 1) as f64,
            c as f64 + 1.0 + hx,
            r as f64 + 1.0 + hy,
            (c + 1) as f64,
            (r + 1) as f64,
        )
    });
    match (best, surface.best.and_then(|(c, r)| surface.rho(c, r))) {
        (Some((pos, c, r, col, row)), Some(rho)) => s.step(
            Step::new(
                "Best position",
                &format!(
                    "The largest ρ is at position {} (row {}, column {} of the surface). That window's top-left pixel is column {}, row {} of the search array, so its centre pixel is c = {} + {}, r = {} + {}.",
                    num(pos),
                    num(row),
                    num(col),
                    num(col),
                    num(row),
                    num(col),
                    num(hx),
                    num(row),
                    num(hy)
                ),
            )
            .formula(
                r"\rho_{\max},\quad c = j + \tfrac{n-1}{2},\quad r = i + \tfrac{m-1}{2}",
                format!(
                    r"\rho_{{\max}} = {},\quad c = {} + {} = {},\quad r = {} + {} = {}",
                    num(rho),
                    num(col),
                    num(hx),
                    num(c),
                    num(row),
                    num(hy),
                    num(r)
                ),
            )
            .value("best_position", pos)
            .value("best_c", c)
            .value("best_r", r)
            .value("best_col", col)
            .value("best_row", row),
        ),
        _ => s.step(Step::new(
            "Best position",
            "No position has a correlation coefficient, so there is no best position.",
        )),
    }

    s.result = Record::new()
        .with("rho", opt_rows(&rho_rows))
        .with("best_position", opt(best.map(|b| b.0)))
        .with("best_c", opt(best.map(|b| b.1)))
        .with("best_r", opt(best.map(|b| b.2)))
        .with("best_col", opt(best.map(|b| b.3)))
        .with("best_row", opt(best.map(|b| b.4)));

    s.note(
        NoteKind::Convention,
        "Positions count from 1 row by row, as the course notes do (position 10 of a 4×4 surface is row 3, column 2); c is the column (to the right) and r the row (down) of the search array, also from 1.",
    ).about(&["best_position", "best_c", "best_r"]);
    if tw % 2 == 0 || th % 2 == 0 {
        s.note(
            NoteKind::Warning,
            "The template has an even number of columns or rows, so its centre lies between pixels: the centre c, r of the best window ends in .5.",
        ).about(&["best_c", "best_r"]);
    }
    {
        let template_flat = surface
            .windows
            .first()
            .is_some_and(|w| matches!(w.flat(), Flat::A | Flat::Both));
        if template_flat {
            s.note(
                NoteKind::Warning,
                "The template has no variance (all its values are equal): ρ is 0/0 at every position, so the surface has no values and there is no best position.",
            ).about(&["rho", "best_position"]);
        } else {
            let flat = surface.windows.iter().filter(|w| w.rho.is_none()).count();
            if flat > 0 {
                s.note(
                    NoteKind::Warning,
                    format!(
                        "{flat} window{} of the search array {} no variance (all values equal): ρ is 0/0 there and has no value.",
                        if flat > 1 { "s" } else { "" },
                        if flat > 1 { "have" } else { "has" }
                    ),
                ).about(&["rho"]);
            }
        }
    }
    if surface.ties > 1 {
        s.note(
            NoteKind::Warning,
            format!(
                "{} positions share the largest ρ; the first in row-by-row order is taken.",
                surface.ties
            ),
        )
        .about(&["best_position"]);
    }
    if is_seed(&ncc_surface_fields(), inputs) {
        seed_notes_7(&mut s, &rho_rows);
    }
    label_results(&mut s);
    Ok(s)
}

pub(super) fn seed_notes_7(s: &mut Solution, rho_rows: &[Vec<Option<f64>>]) {
    s.textbook = Some(
        Record::new()
            .with("rho", Value::matrix(&rows_of(&EX7_PRINTED)))
            .with("best_position", 10.0)
            .with("best_c", 3.0)
            .with("best_r", 4.0),
    );
    let mut off = Vec::new();
    for (i, row) in EX7_PRINTED.iter().enumerate() {
        for (j, printed) in row.iter().enumerate() {
            let exact = rho_rows
                .get(i)
                .and_then(|r| r.get(j))
                .copied()
                .flatten()
                .unwrap_or(0.0);
            if (round_to(exact, 4) - printed).abs() > 1e-9 {
                off.push(format!(
                    "row {}, column {}: printed {}, exact {} (rounds to {})",
                    i + 1,
                    j + 1,
                    fmt_sig(*printed, 4),
                    fmt_sig(exact, 6),
                    fmt_sig(round_to(exact, 4), 4)
                ));
            }
        }
    }
    if off.is_empty() {
        s.note(
            NoteKind::Rounding,
            "All 16 printed coefficients are the exact ones rounded to four decimals.",
        )
        .about(&["rho"]);
    } else {
        s.note(
            NoteKind::Rounding,
            format!(
                "{} of the 16 printed coefficients agree with the exact ones rounded to four decimals; {} differ in the last digit, cut off rather than rounded: {}. The best position (10, centre c = 3, r = 4) is the same.",
                16 - off.len(),
                off.len(),
                off.join("; ")
            ),
        ).about(&["rho"]);
    }
}
