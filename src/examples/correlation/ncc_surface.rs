//! Example 7: the correlation surface of a 2-D template over a search array.

use super::*;
use crate::correlation::{correlate_2d, mean, sums_about};
use crate::examples::drill::{drill, mat, or_given, rows_of, tol, BoxDef, Drill, Mistake};
use crate::examples::fields::is_seed;
use crate::solution::{fmt_sig, NoteKind, Solution};

/// Example 7's surface as the seed prints it (4 decimals).
const EX7_PRINTED: [[f64; 4]; 4] = [
    [-0.3301, 0.5405, -0.1745, -0.1217],
    [-0.3334, 0.2394, -0.3921, -0.2718],
    [0.0585, 0.9665, 0.0806, 0.6228],
    [-0.2321, 0.2904, -0.1268, -0.1997],
];

pub const EXAMPLE: Example = Example {
    id: "ncc-surface",
    title: "Correlation surface",
    source: "Worked examples, Example 7",
    summary: "The correlation coefficient of a 2-D template at every position of a search array, and the best position with its centre pixel.",
    fields,
    solve,
    answer: &["best_position", "best_c", "best_r"],
    labels: LABELS,
    lab: Some(Lab::new("correlation", &[])),
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

fn fields() -> Vec<Field> {
    vec![
        Field::matrix("template", "Template T", &to_rows(&EX7_TEMPLATE))
            .help("The pattern to find (rows separated by ;)."),
        Field::matrix("search", "Search array S", &to_rows(&EX7_SEARCH)).help(
            "Grey values to search in; the template must fit inside (64×64 and more is fine).",
        ),
    ]
}

fn solve(inputs: &Record) -> Result<Solution> {
    let template = grid(inputs, "template")?;
    let search = grid(inputs, "search")?;
    let surface = correlate_2d(&template, &search)?;
    let (tw, th) = (template.width(), template.height());
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    let t_mean = surface.windows.first().map_or(0.0, |w| w.mean_a);
    let t_da2 = surface.windows.first().map_or(0.0, |w| w.sum_da2);
    let [sum, mean_rel] = mean_relations(
        r"\sum T_{ij}",
        r"\bar T",
        r"\frac{1}{mn}\sum T_{ij}",
        "mean_template",
        template.data(),
        t_mean,
    );
    s.step(
        Step::new(
            "Template mean",
            "The template's mean and the sum of its squared deviations, the same for every position.",
        )
        .relation(sum)
        .relation(mean_rel)
        .relation(squares_relation(
            "T",
            "T_{ij}",
            "sum_da2",
            template.data(),
            t_mean,
            t_da2,
        ))
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
        .relation(
            Relation::new("K_r")
                .sym("R - m + 1")
                .subst(format!("{} - {th} + 1", search.height()))
                .value(h as f64, ""),
        )
        .relation(
            Relation::new("K_c")
                .sym("C - n + 1")
                .subst(format!("{} - {tw} + 1", search.width()))
                .value(w as f64, ""),
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
            let [sum, mean_rel] = mean_relations(
                r"\sum B_{ij}",
                r"\bar B",
                r"\frac{1}{mn}\sum B_{ij}",
                "mean_b",
                wv,
                bw.mean_b,
            );
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
            .relation(sum)
            .relation(mean_rel);
            let step = rho_chain(step, TB_2D, r"\rho", template.data(), wv, bw)
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
    let mut cells: Vec<Vec<String>> = rho_rows
        .iter()
        .take(MAX_TERMS)
        .map(|r| {
            let mut cells: Vec<String> = r.iter().take(MAX_TERMS).map(|x| rho_text(*x)).collect();
            if r.len() > MAX_TERMS {
                cells.push(r"\cdots".to_string());
            }
            cells
        })
        .collect();
    if rho_rows.len() > MAX_TERMS {
        let width = cells.first().map_or(1, Vec::len);
        cells.push(vec![r"\vdots".to_string(); width]);
    }
    s.step(
        Step::new(
            "Correlation surface",
            "The correlation coefficient at every position, as a grid: row i, column j is the window whose top-left pixel is row i, column j of the search array.",
        )
        .relation(
            Relation::new(r"\rho")
                .sym(r"[\rho_{ij}]")
                .result(Form::grid_tex("bmatrix", cells, "ρ")),
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
            .relation(Relation::new(r"\rho_{\max}").value(rho, ""))
            .relation(
                Relation::new("k")
                    .key("best_position")
                    .sym("(i - 1) K_c + j")
                    .subst(format!(r"({} - 1) \cdot {w} + {}", num(row), num(col)))
                    .value(pos, ""),
            )
            .relation(
                Relation::new("c")
                    .key("best_c")
                    .sym(r"j + \tfrac{n-1}{2}")
                    .subst(format!("{} + {}", num(col), num(hx)))
                    .value(c, "px"),
            )
            .relation(
                Relation::new("r")
                    .key("best_r")
                    .sym(r"i + \tfrac{m-1}{2}")
                    .subst(format!("{} + {}", num(row), num(hy)))
                    .value(r, "px"),
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
    if is_seed(&fields(), inputs) {
        seed_notes_7(&mut s, &rho_rows);
    }
    Ok(s)
}

fn seed_notes_7(s: &mut Solution, rho_rows: &[Vec<Option<f64>>]) {
    s.textbook = Some(
        Record::new()
            .with("rho", Value::matrix(&to_rows(&EX7_PRINTED)))
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

// ---------------------------------------------------------------- practice

fn generate(rng: &mut Rng) -> Record {
    let search: Vec<Vec<f64>> = (0..6)
        .map(|_| {
            textured(rng, 6)
                .iter()
                .map(|v| 10.0 * v + rng.num(0, 9))
                .collect()
        })
        .collect();
    // The template is the search window at (pc, pr) plus a little noise;
    // pc ≠ pr so that swapping rows and columns shows.
    let pc = rng.int(0, 3) as usize;
    let pr = (pc + rng.int(1, 3) as usize) % 4;
    let offset = rng.num(-5, 5);
    let template: Vec<Vec<f64>> = (0..3)
        .map(|r| {
            (0..3)
                .map(|c| search[pr + r][pc + c] + offset + rng.num(-2, 2))
                .collect()
        })
        .collect();
    Record::new()
        .with("template", mat(&template))
        .with("search", mat(&search))
}

/// The centre column and row of the best window.
fn best_of(i: &Record) -> Result<(f64, f64)> {
    let s = EXAMPLE.run(i)?;
    match (s.result.number("best_c"), s.result.number("best_r")) {
        (Some(c), Some(r)) => Ok((c, r)),
        _ => Err(Error::Internal(format!(
            "{} variant without a best match",
            EXAMPLE.id
        ))),
    }
}

fn boxes(i: &Record) -> Vec<BoxDef> {
    let (c, r) = best_of(i).unwrap_or((2.0, 2.0));
    vec![
        BoxDef::new("mean_template", "Template mean Ā", None, tol::GREY)
            .nudge("Nine grey values: add them, divide by 9."),
        BoxDef::new("sum_da2", "Σ ΔA² of the template", None, tol::SUM).nudge(
            "Subtract Ā from each template value, square, add. It is the same for every position.",
        ),
        BoxDef::new("rho[1,1]", "ρ at the top-left position", None, tol::RHO)
            .nudge("The sub-window whose top-left pixel is the search array's top-left pixel.")
            .sign_flip(RHO_FLIP),
        BoxDef::new(
            &format!("rho[{},{}]", r as usize - 1, c as usize - 1),
            "ρ at the best position",
            None,
            tol::RHO,
        )
        .nudge("Compute ρ for every position; this is the largest.")
        .sign_flip(RHO_FLIP),
        BoxDef::new(
            "best_c",
            "Best match: centre column c",
            Some("px"),
            tol::WHOLE,
        )
        .nudge("The centre pixel of the best sub-window, counted from 1."),
        BoxDef::new("best_r", "Best match: centre row r", Some("px"), tol::WHOLE)
            .nudge("The centre pixel's row, counted from 1."),
    ]
}

/// The 3×3 window of the search array at surface position (row `pr`,
/// column `pc`), 1-based, in row-major order.
fn window(s: &[Vec<f64>], pr: usize, pc: usize) -> Result<Vec<f64>> {
    Grid::from_rows("search", s)?
        .window(pc - 1, pr - 1, 3, 3)
        .map(|w| w.data().to_vec())
        .ok_or_else(|| Error::Internal(format!("no window at row {pr}, column {pc}")))
}

/// ρ at surface position (row `pr`, column `pc`), 1-based, from the
/// template's mean and Σ ΔA² (the student's, when given).
fn rho_at(t: &[f64], ma: f64, aa: f64, s: &[Vec<f64>], pr: usize, pc: usize) -> Result<f64> {
    let w = window(s, pr, pc)?;
    let [ab, _, bb] = sums_about(t, ma, &w, mean(&w));
    Ok(correlation::rho_of_sums(ab, aa, bb))
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let (c, r) = best_of(i)?;
    let t = rows_of(i, "template").concat();
    let s = rows_of(i, "search");
    let ma = or_given(g, "mean_template", mean(&t));
    let aa = or_given(g, "sum_da2", sums_about(&t, ma, &t, ma)[1]);
    let (br, bc) = (r as usize - 1, c as usize - 1);
    let best = format!("rho[{br},{bc}]");
    let mut out = Record::new()
        .with("mean_template", ma)
        .with("sum_da2", aa)
        .with(
            "rho[1,1]",
            or_given(g, "rho[1,1]", rho_at(&t, ma, aa, &s, 1, 1)?),
        );
    out.set(&best, or_given(g, &best, rho_at(&t, ma, aa, &s, br, bc)?));
    Ok(out.with("best_c", c).with("best_r", r))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let (c, r) = best_of(i)?;
    let t = rows_of(i, "template").concat();
    let w = window(&rows_of(i, "search"), 1, 1)?;
    const SWAP: &str = "c is the column (to the right), r the row (down).";
    const CORNER: &str =
        "The position asked for is the centre pixel of the sub-window, not its top-left corner.";
    Ok(vec![
        Mistake::new(
            "sum_da2",
            "mean not subtracted",
            "Σ ΔA² adds the squared deviations from the mean, not the squared grey values.",
            sums_about(&t, 0.0, &t, 0.0)[1],
        ),
        Mistake::new(
            "rho[1,1]",
            "mean not subtracted",
            "Subtract both means first.",
            rho_about(&t, 0.0, &w, 0.0),
        ),
        Mistake::new("best_c", "rows and columns swapped", SWAP, r),
        Mistake::new("best_r", "rows and columns swapped", SWAP, c),
        Mistake::new("best_c", "top-left instead of centre", CORNER, c - 1.0),
        Mistake::new("best_r", "top-left instead of centre", CORNER, r - 1.0),
    ])
}
