//! Example 11: least-squares matching in 2-D (shifts, gain and offset),
//! and its practice: the first shifts and the converged position.

use super::*;
use crate::examples::drill::{drill, mat, or_given, value_in, BoxDef, Drill, Mistake, Rng};
use crate::examples::Lab;

pub const EXAMPLE: Example = Example {
    id: "lsm-2d",
    title: "2-D least-squares matching",
    source: "Worked examples, Example 11",
    summary: "Refines the best correlation position of Example 7 to a subpixel shift with a gain and offset by iterated least squares.",
    fields,
    solve,
    answer: &["c", "r"],
    labels: LABELS,
    lab: Some(Lab::new("correlation", &["lsm"])),
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

pub(super) fn ex7_template() -> Vec<Vec<f64>> {
    vec![
        vec![30.0, 50.0, 30.0],
        vec![50.0, 50.0, 50.0],
        vec![30.0, 50.0, 30.0],
    ]
}

pub(super) fn ex7_search() -> Vec<Vec<f64>> {
    vec![
        vec![44.0, 45.0, 64.0, 50.0, 45.0, 43.0],
        vec![43.0, 44.0, 63.0, 48.0, 49.0, 45.0],
        vec![45.0, 47.0, 65.0, 50.0, 45.0, 45.0],
        vec![62.0, 62.0, 69.0, 64.0, 64.0, 63.0],
        vec![48.0, 48.0, 68.0, 51.0, 55.0, 50.0],
        vec![41.0, 44.0, 63.0, 48.0, 42.0, 47.0],
    ]
}

/// Example 11's printed design matrix (columns ∂G/∂c, ∂G/∂r).
const EX11_PRINTED_GRADIENTS: [[f64; 2]; 9] = [
    [9.0, 7.5],
    [1.5, 2.0],
    [-7.5, 7.0],
    [3.5, 0.5],
    [1.0, 1.5],
    [-2.5, 0.5],
    [10.0, -7.0],
    [1.5, -0.5],
    [-8.5, -6.5],
];

const GRADIENT_OPTIONS: &[(&str, &str)] = &[
    (
        "search-window",
        "Search window: neighbours outside the patch from the search window (the stated formula)",
    ),
    (
        "patch-edge",
        "Patch edge: inside the patch only, an edge pixel stands in for its outside neighbour (the printed matrix)",
    ),
];

fn fields() -> Vec<Field> {
    vec![
        Field::matrix("template", "Template T", &ex7_template())
            .help("The template's grey values, rows top to bottom."),
        Field::matrix("search", "Search window S", &ex7_search())
            .help("The search window's grey values; columns c and rows r count from 1."),
        Field::number("c0", "Start column c⁰", 3.0)
            .unit("px")
            .range(1.0, MAX_2D as f64)
            .help("Column of the template's centre in the search window (Example 7's best match)."),
        Field::number("r0", "Start row r⁰", 4.0)
            .unit("px")
            .range(1.0, MAX_2D as f64)
            .help("Row of the template's centre in the search window."),
        Field::flag("radiometric", "Estimate gain a and offset b", true)
            .help("Example 11 estimates the radiometric change G_t = a·G_s + b with the shift; off, a and b stay at their start values and only the shift is estimated."),
        Field::number("a0", "Start gain a⁰", 1.0)
            .range(-1000.0, 1000.0)
            .help("Start value of the gain a in G_t = a·G_s + b."),
        Field::number("b0", "Start offset b⁰", -20.0)
            .range(-10000.0, 10000.0)
            .help("Start value of the offset b."),
        Field::choice(
            "gradients",
            "Gradients at the patch edge",
            GRADIENT_OPTIONS,
            "search-window",
        )
        .help("How ∂G_s/∂c and ∂G_s/∂r are taken at the patch's edge pixels."),
        max_iterations(),
    ]
}

fn solve(inputs: &Record) -> Result<Solution> {
    let Patches {
        tr,
        sr,
        template: t,
        search: sw,
    } = patches(inputs)?;
    let i = Inputs(inputs);
    let (c0, r0, a0, b0) = (
        i.number("c0")?,
        i.number("r0")?,
        i.number("a0")?,
        i.number("b0")?,
    );
    let gradients = match i.text("gradients")? {
        "patch-edge" => Gradients::PatchEdge,
        _ => Gradients::SearchWindow,
    };
    let radiometric = i.flag("radiometric")?;
    let set = settings(shift_model(radiometric), gradients, inputs)?;
    let start = Params::shift(c0 - 1.0, r0 - 1.0, a0, b0);
    let m = matching::match_2d(&t, &sw, start, set).map_err(|e| said_of(e, "c0"))?;
    let syms = symbols(&m.estimated, true);
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    s.step(
        Step::new(
            "Template and start",
            "The template's centre is placed at (c⁰, r⁰) in the search window.",
        )
        .relation(
            Relation::new("T")
                .key("template")
                .subst(Form::grid("bmatrix", &tr, "T")),
        )
        .relation(Relation::new("(c^0, r^0)").subst(format!("({}, {})", num(c0), num(r0))))
        .relation(Relation::new("a^0").value(a0, ""))
        .relation(Relation::new("b^0").value(b0, ""))
        .value("template", Value::matrix(&tr))
        .value("search", Value::matrix(&sr)),
    );
    s.step(
        Step::new(
            "Observation equation",
            "Each template pixel is one observation; the shift enters through the gradients, the radiometry linearly.",
        )
        .relation(Relation::new("G_t(c,r) + V").sym(r"a\,G_s(c+dc, r+dr) + b"))
        .relation(
            Relation::new(r"[G_t - (a^0 G_s + b^0)] + V").sym(Form::terms([
                r"a^0\frac{\partial G_s}{\partial c}dc",
                r"+ a^0\frac{\partial G_s}{\partial r}dr",
                r"+ G_s\,da",
                "+ db",
            ])),
        ),
    );
    if let Some(it) = m.iterations.first() {
        first_iteration_2d(&mut s, it, &t, gradients, &syms);
    }
    s.step(table_step(&m, &syms, -1.0, None));
    status_step(&mut s, &m, &syms, set.max_iterations);
    let inc = |k: usize| first_increment(&m, k);
    s.result = with_run(
        Record::new()
            .with("first_dc", inc(0))
            .with("first_dr", inc(1))
            .with("first_da", inc(2))
            .with("first_db", inc(3))
            .with("c", m.params.a[2] + 1.0)
            .with("r", m.params.a[5] + 1.0),
        &m,
    );
    s.note(
        NoteKind::Convention,
        "Columns c (to the right) and rows r (downward) count from 1 as in the course notes; (c, r) is the search-window position of the template's centre pixel.",
    ).about(&["c", "r"]);
    if !radiometric {
        s.note(
            NoteKind::Convention,
            format!(
                "Shift only: the gain and offset are not estimated but kept at their start values a = {}, b = {}, so each equation has the two columns ∂G_s/∂c, ∂G_s/∂r.",
                num(a0),
                num(b0)
            ),
        )
        .about(&["a", "b"]);
    }
    if radiometric
        && seed_inputs(
            &fields(),
            inputs,
            &["template", "search", "c0", "r0", "a0", "b0"],
        )
    {
        ex11_notes(&mut s, &m, gradients, inputs)?;
    }
    Ok(s)
}

fn first_iteration_2d(
    s: &mut Solution,
    it: &Iteration,
    t: &Grid,
    gradients: Gradients,
    syms: &[Sym],
) {
    let a0 = it.params.gain();
    let radiometric = syms.iter().any(|s| s.key == "a");
    s.step(
        difference_step(
            "Template minus the modelled search patch a⁰·G_s + b⁰, pixel by pixel, row by row.",
            it,
            t.data(),
        )
        .value("patch", Value::matrix(&it.patch.rows()))
        .value("dL", Value::numbers(&it.dl)),
    );
    let (w, h) = (it.patch.width(), it.patch.height());
    let bordered = &it.bordered;
    let pick = |i: isize, j: isize| -> f64 {
        match gradients {
            Gradients::SearchWindow => bordered
                .get((i + 1).max(0) as usize, (j + 1).max(0) as usize)
                .unwrap_or(0.0),
            Gradients::PatchEdge => it
                .patch
                .get(
                    i.clamp(0, w as isize - 1) as usize,
                    j.clamp(0, h as isize - 1) as usize,
                )
                .unwrap_or(0.0),
        }
    };
    let mut rows = Vec::new();
    for j in 0..h as isize {
        for i in 0..w as isize {
            let k = (j as usize) * w + i as usize;
            let arow = it.a.get(k);
            let mut row = vec![
                format!(r"({} - {})/2", num(pick(i + 1, j)), tex(pick(i - 1, j))),
                format!(r"({} - {})/2", num(pick(i, j + 1)), tex(pick(i, j - 1))),
            ];
            if radiometric {
                row.push(num(arow.and_then(|r| r.get(2)).copied().unwrap_or(0.0)));
                row.push("1".to_string());
            }
            rows.push(row);
        }
    }
    let how = match gradients {
        Gradients::SearchWindow => "Central differences of the resampled search window: the outer neighbours of the edge pixels come from the one-pixel border around the patch (the formula the course notes state).",
        Gradients::PatchEdge => "Central differences inside the patch only: an edge pixel stands in for its neighbour outside the patch (what the printed matrix does).",
    };
    let gain = if a0 == 1.0 { "" } else { r"a^0\," };
    let tail = if radiometric { r",\ G_s(c,r),\ 1" } else { "" };
    s.step(
        Step::new("Design matrix A (iteration 1)", how)
            .relation(Relation::new("A_i").sym(format!(
                r"[{gain}\tfrac{{G_s(c+1,r) - G_s(c-1,r)}}{{2}},\ {gain}\tfrac{{G_s(c,r+1) - G_s(c,r-1)}}{{2}}{tail}]"
            )))
            .relation(design_matrix(rows, &it.a))
            .value("A", Value::matrix(&it.a))
            .value("gc", Value::matrix(&it.gc.rows()))
            .value("gr", Value::matrix(&it.gr.rows()))
            .value("bordered", Value::matrix(&it.bordered.rows())),
    );
    let inc = |k: usize| it.increments.get(k).copied().unwrap_or(0.0);
    let (c0, r0) = (it.params.a[2] + 1.0, it.params.a[5] + 1.0);
    s.step(
        normal_step(it, syms)
            .relation(moved("c", "c_after_first", c0, inc(0)))
            .relation(moved("r", "r_after_first", r0, inc(1)))
            .value("c_after_first", c0 + inc(0))
            .value("r_after_first", r0 + inc(1)),
    );
}

fn ex11_notes(s: &mut Solution, m: &Matching, gradients: Gradients, inputs: &Record) -> Result<()> {
    s.textbook = Some(
        Record::new()
            .with("first_dc", 0.194)
            .with("first_dr", 0.086)
            .with("first_da", 0.138)
            .with("first_db", -5.372),
    );
    // the other reading, for the comparison
    let other = match gradients {
        Gradients::SearchWindow => Gradients::PatchEdge,
        Gradients::PatchEdge => Gradients::SearchWindow,
    };
    let t = Grid::from_rows("template", &ex7_template())?;
    let sw = Grid::from_rows("search", &ex7_search())?;
    let limit = Inputs(inputs).number("max_iterations")? as usize;
    let alt = matching::match_2d(
        &t,
        &sw,
        m.start,
        Settings {
            model: Model::ShiftRadiometric,
            gradients: other,
            max_iterations: limit,
        },
    )?;
    let (sw_run, pe_run) = match gradients {
        Gradients::SearchWindow => (m, &alt),
        Gradients::PatchEdge => (&alt, m),
    };
    let labels = ["∂G/∂c", "∂G/∂r"];
    let mut diffs = Vec::new();
    if let Some(first) = sw_run.iterations.first() {
        for (k, printed) in EX11_PRINTED_GRADIENTS.iter().enumerate() {
            for (j, p) in printed.iter().enumerate() {
                let exact = first
                    .a
                    .get(k)
                    .and_then(|r| r.get(j))
                    .copied()
                    .unwrap_or(0.0);
                if (exact - p).abs() > 1e-9 {
                    diffs.push(format!(
                        "row {} (c = {}, r = {}) {}: formula {} , printed {}",
                        k + 1,
                        k % 3 + 2,
                        k / 3 + 3,
                        labels.get(j).copied().unwrap_or(""),
                        num(exact),
                        num(*p)
                    ));
                }
            }
        }
    }
    s.note(
        NoteKind::Erratum,
        format!(
            "The printed design matrix does not follow its own formula ∂G_s/∂c = (G_s(c+1, r) − G_s(c−1, r))/2 at {} of its 18 gradient entries: {}. At every patch-edge pixel the course notes used the edge pixel itself for the neighbour outside the 3×3 patch (e.g. row 1 writes (65 − 47)/2 where the search window has 45 left of 47, giving (65 − 45)/2 = 10). Choose “Patch edge” under “Gradients at the patch edge” to reproduce the printed matrix.",
            diffs.len(),
            diffs.join("; ")
        ),
    ).about(&["first_dc", "first_dr", "first_da", "first_db"]);
    let fmt_inc = |run: &Matching| -> String {
        run.iterations.first().map_or("–".to_string(), |it| {
            it.increments
                .iter()
                .map(|x| num(*x))
                .collect::<Vec<_>>()
                .join(", ")
        })
    };
    s.note(
        NoteKind::Rounding,
        format!(
            "The printed dX = [0.194, 0.086, 0.138, −5.372] is what the patch-edge gradients give, rounded to three decimals (exactly [{}]). The stated formula gives dX = [{}].",
            fmt_inc(pe_run),
            fmt_inc(sw_run)
        ),
    ).about(&["first_dc", "first_dr", "first_da", "first_db"]);
    let end = |run: &Matching| -> String {
        format!(
            "{} after {} iterations: c = {}, r = {}, a = {}, b = {}",
            run.status.word(),
            run.iterations.len(),
            num(run.params.a[2] + 1.0),
            num(run.params.a[5] + 1.0),
            num(run.params.gain()),
            num(run.params.offset())
        )
    };
    s.note(
        NoteKind::Convention,
        format!(
            "The course notes stop after the first iteration (c = 3.194, r = 4.086, a = 1.138, b = −25.372). Iterated: with the search-window gradients (the stated formula) {}; with the patch-edge gradients (the printed matrix) {}. The gain and offset move far beyond their first step, and with the patch-edge gradients (too small at the edge pixels) every step overshoots, so that run zig-zags towards the optimum and needs many more iterations.",
            end(sw_run),
            end(pe_run)
        ),
    ).about(&["c", "r", "a", "b"]);
    Ok(())
}

// ---------------------------------------------------------------- practice

fn boxes(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("first_dc", "First shift Δc", Some("px"), SHIFT)
            .nudge("Gradients gc, gr of the search window; the normal equations of Δc, Δr, Δa, Δb.")
            .axis(),
        BoxDef::new("first_dr", "First shift Δr", Some("px"), SHIFT)
            .nudge("The second unknown of the same system.")
            .axis(),
        BoxDef::new(
            "c_after_first",
            "Column after the first iteration",
            Some("px"),
            SHIFT,
        )
        .nudge("The start column plus Δc."),
        BoxDef::new(
            "r_after_first",
            "Row after the first iteration",
            Some("px"),
            SHIFT,
        )
        .nudge("The start row plus Δr."),
        BoxDef::new("c", "Converged column c", Some("px"), SHIFT)
            .nudge("Resample by bilinear interpolation and iterate."),
        BoxDef::new("r", "Converged row r", Some("px"), SHIFT)
            .nudge("The row of the converged position."),
    ]
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = EXAMPLE.run(i)?;
    let dc = or_given(g, "first_dc", value_in(&s, "first_dc")?);
    let dr = or_given(g, "first_dr", value_in(&s, "first_dr")?);
    let (c0, r0) = (Inputs(i).number("c0")?, Inputs(i).number("r0")?);
    Ok(Record::new()
        .with("first_dc", dc)
        .with("first_dr", dr)
        .with("c_after_first", or_given(g, "c_after_first", c0 + dc))
        .with("r_after_first", or_given(g, "r_after_first", r0 + dr))
        .with("c", value_in(&s, "c")?)
        .with("r", value_in(&s, "r")?))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let s = EXAMPLE.run(i)?;
    let (dc, dr) = (value_in(&s, "first_dc")?, value_in(&s, "first_dr")?);
    const SWAP: &str = "Δc moves along the columns (right), Δr along the rows (down).";
    const SUB: &str = "The new position is the old one plus the increment.";
    const ONCE: &str = "One iteration is only the first step: resample the search window at the new position and solve again until the increments are negligible.";
    let (c0, r0) = (Inputs(i).number("c0")?, Inputs(i).number("r0")?);
    Ok(vec![
        Mistake::new("first_dc", "rows and columns swapped", SWAP, dr),
        Mistake::new("first_dr", "rows and columns swapped", SWAP, dc),
        Mistake::new("c_after_first", "shift subtracted", SUB, c0 - dc),
        Mistake::new("r_after_first", "shift subtracted", SUB, r0 - dr),
        Mistake::new("c", "stopped after one iteration", ONCE, c0 + dc),
        Mistake::new("r", "stopped after one iteration", ONCE, r0 + dr),
    ])
}

/// A smooth 2-D bump of grey values sampled at (c, r).
fn bump2(c: f64, r: f64, cc: f64, rc: f64, h: f64) -> f64 {
    20.0 + h * (-((c - cc).powi(2) / 2.5 + (r - rc).powi(2) / 1.8)).exp()
}

/// A 6 × 6 search window with a bump a fraction of a pixel off a pixel
/// centre, and the 3 × 3 template of the bump centred.
fn generate(rng: &mut Rng) -> Record {
    let h = rng.num(60, 120);
    let (pc, pr) = (rng.num(2, 3), rng.num(2, 3)); // 0-based peak pixel
    let (fc, fr) = (rng.num(-3, 3) / 10.0, rng.num(-3, 3) / 10.0);
    let search: Vec<Vec<f64>> = (0..6)
        .map(|r| {
            (0..6)
                .map(|c| bump2(c as f64, r as f64, pc + fc, pr + fr, h).round())
                .collect()
        })
        .collect();
    let template: Vec<Vec<f64>> = (0..3)
        .map(|r| {
            (0..3)
                .map(|c| bump2(c as f64, r as f64, 1.0, 1.0, h).round())
                .collect()
        })
        .collect();
    Record::new()
        .with("template", mat(&template))
        .with("search", mat(&search))
        .with("c0", pc + 1.0)
        .with("r0", pr + 1.0)
        .with("a0", 1.0)
        .with("b0", 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lsm_2d_without_radiometry_estimates_the_shift_only() {
        let s = EXAMPLE
            .run(&Record::new().with("radiometric", false).with("b0", 0.0))
            .unwrap();
        let t = Grid::from_rows("template", &ex7_template()).unwrap();
        let sw = Grid::from_rows("search", &ex7_search()).unwrap();
        let m = matching::match_2d(
            &t,
            &sw,
            Params::shift(2.0, 3.0, 1.0, 0.0),
            Settings {
                model: Model::Shift,
                gradients: Gradients::SearchWindow,
                max_iterations: matching::DEFAULT_ITERATIONS,
            },
        )
        .unwrap();
        assert_eq!(s.result.get("c"), Some(&Value::Number(m.params.a[2] + 1.0)));
        assert_eq!(s.result.get("r"), Some(&Value::Number(m.params.a[5] + 1.0)));
        assert_eq!(s.result.get("a"), Some(&Value::Number(1.0)));
        assert_eq!(s.result.get("b"), Some(&Value::Number(0.0)));
        assert_eq!(s.result.get("first_da"), Some(&Value::Null));
    }
}
