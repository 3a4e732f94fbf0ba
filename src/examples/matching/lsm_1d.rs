//! Example 10: least-squares matching in 1-D (shift, optionally gain and
//! offset), and its practice: the first normal equation, the first shift
//! and the converged position.

use super::*;
use crate::examples::drill::{drill, nums, or_given, tol, value_in, BoxDef, Drill, Mistake, Rng};
use crate::solution::exact_minus_printed;

pub const EXAMPLE: Example = Example {
    id: "lsm-1d",
    title: "1-D least-squares matching",
    source: "Worked examples, Example 10",
    summary: "Refines the best correlation position of Example 5 to a subpixel shift (and optionally a gain and offset) by iterated least squares.",
    fields,
    solve,
    answer: &["c"],
    labels: LABELS,
    lab: None,
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

const EX5_TEMPLATE: [f64; 7] = [1.0, 2.0, 9.0, 9.0, 8.0, 2.0, 1.0];
const EX5_SEARCH: [f64; 12] = [1.0, 2.0, 2.0, 1.0, 1.0, 3.0, 8.0, 8.0, 6.0, 1.0, 1.0, 1.0];

fn fields() -> Vec<Field> {
    vec![
        Field::vector("template", "Template T", (3, MAX_1D), &EX5_TEMPLATE)
            .help("The template's grey values, left to right."),
        Field::vector("search", "Search window S", (3, MAX_1D), &EX5_SEARCH)
            .help("The search window's grey values; positions count from 1."),
        Field::number("c0", "Start position c⁰", 8.0)
            .unit("px")
            .range(1.0, MAX_1D as f64)
            .help("Search-window position of the template's centre pixel to start from (Example 5's best match)."),
        Field::flag("radiometric", "Estimate gain a and offset b", false)
            .help("Also estimate the linear radiometric change G_t = a·G_s + b (start a⁰ = 1, b⁰ = 0)."),
        max_iterations(),
    ]
}

fn solve(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let t = i.list("template")?;
    let sw = i.list("search")?;
    let c0 = i.number("c0")?;
    let radiometric = i.flag("radiometric")?;
    let set = settings(shift_model(radiometric), Gradients::SearchWindow, inputs)?;
    let m = matching::match_1d(&t, &sw, Params::shift(c0 - 1.0, 0.0, 1.0, 0.0), set)
        .map_err(|e| said_of(e, "c0"))?;
    let syms = symbols(&m.estimated, true);
    let n = t.len();
    let half = (n as f64 - 1.0) / 2.0;
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());

    let first_pos: Vec<f64> = (0..n).map(|i| c0 - half + i as f64).collect();
    s.step(
        Step::new(
            "Template and start",
            "The template's centre is placed at the start position c⁰ of the search window; the template's pixels then fall on these search-window positions.",
        )
        .relation(Relation::new("T").key("template").subst(Form::column(&t, "T")))
        .relation(
            Relation::new("c_i")
                .key("positions")
                .sym(r"c^0 + \left(i - \tfrac{n+1}{2}\right)")
                .subst(Form::column(&first_pos, "c_i")),
        )
        .relation(Relation::new("i").sym(r"1 \dots n").subst(format!(r"1 \dots {n}")))
        .value("template", Value::numbers(&t))
        .value("search", Value::numbers(&sw))
        .value("positions", Value::numbers(&first_pos)),
    );
    let (eq, lin) = if radiometric {
        (
            Relation::new(r"G_t(c) + V").sym(r"a\,G_s(c + dc) + b"),
            Relation::new(r"[G_t(c) - (a^0 G_s(c) + b^0)] + V").sym(Form::terms([
                r"a^0\frac{\partial G_s(c)}{\partial c}\,dc",
                r"+ G_s(c)\,da",
                "+ db",
            ])),
        )
    } else {
        (
            Relation::new(r"G_t(c) + V").sym(r"G_s(c + dc)"),
            Relation::new(r"[G_t(c) - G_s(c)] + V").sym(r"\frac{\partial G_s(c)}{\partial c}\,dc"),
        )
    };
    s.step(
        Step::new(
            "Observation equation",
            "Each template pixel is one observation. Taylor's first-order term turns the unknown shift into a linear unknown; the gradient is the central difference (G_s(c+1) − G_s(c−1))/2 of the search window, resampled at the current position.",
        )
        .relation(eq)
        .relation(lin),
    );
    if let Some(it) = m.iterations.first() {
        first_iteration_1d(&mut s, it, &t, &syms);
    }
    s.step(table_step(&m, &syms, -1.0, None));
    status_step(&mut s, &m, &syms, set.max_iterations);

    let inc = |k: usize| first_increment(&m, k);
    s.result = with_run(
        Record::new()
            .with("first_dc", inc(0))
            .with("first_da", if radiometric { inc(1) } else { None })
            .with("first_db", if radiometric { inc(2) } else { None })
            .with("c", m.params.a[2] + 1.0),
        &m,
    );
    s.note(
        NoteKind::Convention,
        "Positions count from 1 as in the course notes; c is the search-window position of the template's centre pixel. dL + V = A·dX with V = A·dX − dL.",
    ).about(&["c"]);
    if seed_inputs(&fields(), inputs, &["template", "search", "c0"]) {
        ex10_notes(&mut s, &m, radiometric);
    }
    Ok(s)
}

fn first_iteration_1d(s: &mut Solution, it: &Iteration, t: &[f64], syms: &[Sym]) {
    let b = it.bordered.data();
    let g = it.patch.data();
    s.step(
        difference_step(
            "The template minus the search patch resampled at the current position (and scaled by the current gain and offset).",
            it,
            t,
        )
        .value("patch", Value::numbers(g))
        .value("dL", Value::numbers(&it.dl)),
    );
    let rows: Vec<Vec<String>> = (0..g.len())
        .map(|i| {
            let right = b.get(i + 2).copied().unwrap_or(0.0);
            let left = b.get(i).copied().unwrap_or(0.0);
            let mut row = vec![format!(r"({} - {})/2", num(right), tex(left))];
            for k in 1..syms.len() {
                let v = it.a.get(i).and_then(|r| r.get(k)).copied().unwrap_or(0.0);
                row.push(num(v));
            }
            row
        })
        .collect();
    let gain_note = if it.params.gain() == 1.0 {
        ""
    } else {
        r"a^0\,"
    };
    s.step(
        Step::new(
            "Design matrix A (iteration 1)",
            "The gradient column is the central difference of the resampled search window: the neighbours one pixel left and right of each patch pixel, the outermost ones from the one-pixel border around the patch.",
        )
        .relation(
            Relation::new("A_{i,1}")
                .sym(format!(r"{gain_note}\frac{{G_s(c_i+1) - G_s(c_i-1)}}{{2}}")),
        )
        .relation(design_matrix(rows, &it.a))
        .value("A", Value::matrix(&it.a))
        .value("bordered", Value::numbers(b)),
    );
    let c0 = it.params.a[2] + 1.0;
    let dc = it.increments.first().copied().unwrap_or(0.0);
    s.step(
        normal_step(it, syms)
            .relation(moved("c", "c_after_first", c0, dc))
            .value("c_after_first", c0 + dc),
    );
}

fn ex10_notes(s: &mut Solution, m: &Matching, radiometric: bool) {
    let Some(first) = m.iterations.first() else {
        return;
    };
    let dc = first.increments.first().copied().unwrap_or(0.0);
    let mut printed = Record::new();
    if radiometric {
        printed = printed
            .with("first_dc", -0.295)
            .with("first_da", 0.156)
            .with("first_db", -0.053);
        let da = first.increments.get(1).copied().unwrap_or(0.0);
        let db = first.increments.get(2).copied().unwrap_or(0.0);
        s.note(
            NoteKind::Rounding,
            format!(
                "The course notes print dX = [−0.295, 0.156, −0.053]; exactly dc = {}, da = {} (= 5/32), db = {} (= −3/56). The last rounds to −0.054: the course notes cut it off instead of rounding.",
                num(dc),
                num(da),
                num(db)
            ),
        ).about(&["first_dc", "first_da", "first_db"]);
        s.note(
            NoteKind::Convention,
            "With a⁰ = 1 and b⁰ = 0 the gradient column is orthogonal to the columns G_s and 1 (Σ∂G·G_s = 0 and Σ∂G = 0 here), so the first dc is the same as without radiometry.",
        ).about(&["first_da", "first_db"]);
    } else {
        printed = printed
            .with("first_dc", -0.2945)
            .with("c_after_first", 7.705);
        s.label(
            "c_after_first",
            "Position c after the first iteration",
            "px",
        );
        s.note(
            NoteKind::Rounding,
            format!(
                "The course notes print dc = −0.2945; exactly dc = AᵀdL / AᵀA = −11.5 / 39 = {}, which rounds to −0.2949 ({}). They then use −0.295, so c = 8 − 0.295 = 7.705 (exactly {}; {}).",
                num(dc),
                exact_minus_printed(dc, -0.2945, "px"),
                num(8.0 + dc),
                exact_minus_printed(8.0 + dc, 7.705, "px")
            ),
        ).about(&["first_dc", "c_after_first"]);
    }
    s.note(
        NoteKind::Convention,
        format!(
            "The course notes stop after the first iteration (\"iterated until the increment approaches zero\"). Iterated to the end, c = {} after {} iterations{}, {} px from the first iteration's {}: the first step alone stops well short of the optimum.",
            num(m.params.a[2] + 1.0),
            m.iterations.len(),
            if radiometric {
                format!(
                    " with a = {} and b = {}",
                    num(m.params.gain()),
                    num(m.params.offset())
                )
            } else {
                ", the increments alternating in sign and roughly halving".to_string()
            },
            num(m.params.a[2] + 1.0 - (8.0 + dc)),
            num(8.0 + dc)
        ),
    ).about(&["c", "iterations"]);
    s.textbook = Some(printed);
}

// ---------------------------------------------------------------- practice

/// The boxes: the first normal equation by hand, the first shift and the
/// converged position (the iterations are long by hand).
fn boxes(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("N[1,1]", "N = Σ g² (iteration 1)", None, tol::SUM)
            .nudge("g is the search window's gradient at each template pixel, (g(c+1) − g(c−1)) / 2; square and add."),
        BoxDef::new("AtL[1]", "AᵀdL = Σ g·dL (iteration 1)", None, tol::SUM)
            .nudge("dL is the template minus the search patch at the start position; multiply by g and add."),
        BoxDef::new("first_dc", "First shift Δc", Some("px"), SHIFT)
            .nudge("Δc = AᵀdL / N.")
            .axis(),
        BoxDef::new("c_after_first", "Position after the first iteration", Some("px"), SHIFT)
            .nudge("The start position plus the first shift."),
        BoxDef::new("c", "Converged position c", Some("px"), SHIFT)
            .nudge("Resample, repeat until the shift is tiny."),
    ]
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = EXAMPLE.run(i)?;
    let n = or_given(g, "N[1,1]", value_in(&s, "N[1,1]")?);
    let atl = or_given(g, "AtL[1]", value_in(&s, "AtL[1]")?);
    let dc = or_given(g, "first_dc", atl / n);
    let c0 = Inputs(i).number("c0")?;
    Ok(Record::new()
        .with("N[1,1]", n)
        .with("AtL[1]", atl)
        .with("first_dc", dc)
        .with("c_after_first", or_given(g, "c_after_first", c0 + dc))
        .with("c", value_in(&s, "c")?))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let s = EXAMPLE.run(i)?;
    const HALF: &str = "The gradient is (g(c+1) − g(c−1)) / 2: without the ½ it is twice too big.";
    const SIGN: &str = "The gradient is (g(c+1) − g(c−1)) / 2: right minus left.";
    let (n, atl, dc) = (
        value_in(&s, "N[1,1]")?,
        value_in(&s, "AtL[1]")?,
        value_in(&s, "first_dc")?,
    );
    let c0 = Inputs(i).number("c0")?;
    Ok(vec![
        Mistake::new("AtL[1]", "gradient taken the wrong way", SIGN, -atl),
        Mistake::new("first_dc", "gradient taken the wrong way", SIGN, -dc),
        Mistake::new("N[1,1]", "½ forgotten in the gradient", HALF, 4.0 * n),
        Mistake::new("AtL[1]", "½ forgotten in the gradient", HALF, 2.0 * atl),
        Mistake::new(
            "first_dc",
            "N over AᵀdL",
            "The shift is AᵀdL / N, not its inverse.",
            n / atl,
        ),
        Mistake::new(
            "c_after_first",
            "shift subtracted",
            "The new position is the old one plus the increment.",
            c0 - dc,
        ),
    ])
}

/// A smooth bump of grey values sampled at `x` (the template's shape).
fn bump(x: f64, centre: f64, height: f64, width: f64) -> f64 {
    20.0 + height * (-((x - centre) / width).powi(2)).exp()
}

/// A search window with a smooth bump; the template is the same bump
/// sampled a fraction of a pixel away, so the match is off the start by
/// that fraction.
fn generate(rng: &mut Rng) -> Record {
    let (height, width) = (rng.num(40, 80), rng.num(15, 25) / 10.0);
    let n = 12;
    let centre = rng.num(5, 7) as usize; // 0-based search position of the peak
    let frac = rng.num(-4, 4) / 10.0;
    let frac = if frac == 0.0 { 0.3 } else { frac };
    let search: Vec<f64> = (0..n)
        .map(|k| bump(k as f64, centre as f64 + frac, height, width).round())
        .collect();
    let template: Vec<f64> = (0..7)
        .map(|k| bump(k as f64, 3.0, height, width).round())
        .collect();
    Record::new()
        .with("template", nums(&template))
        .with("search", nums(&search))
        .with("c0", (centre + 1) as f64)
}
