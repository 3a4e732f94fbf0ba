//! Example 10: least-squares matching in 1-D (shift, optionally gain and offset).

use super::*;

/// What each result key is, for the page's result table.
pub(super) fn label_results(s: &mut Solution) {
    s.label_present(&[
        ("first_dc", "First iteration: shift increment dc", "px"),
        ("first_dr", "First iteration: shift increment dr", "px"),
        ("first_da", "First iteration: gain increment da", ""),
        (
            "first_db",
            "First iteration: offset increment db",
            "grey values",
        ),
        ("c", "Matched position c (after the last iteration)", "px"),
        ("r", "Matched position r (after the last iteration)", "px"),
        ("a", "Gain a", ""),
        ("b", "Offset b", "grey values"),
        ("iterations", "Iterations", ""),
        ("converged", "Converged", ""),
        ("status", "How the run ended", ""),
        ("sigma0", "σ0 of the last iteration", "grey values"),
        ("parameters", "Estimates a1 … a8", ""),
        ("true_parameters", "True values a1 … a8 (generated)", ""),
        ("std_dev", "Standard deviations of a1 … a8", ""),
        (
            "expected_sigma0",
            "Expected σ0 from the noise",
            "grey values",
        ),
    ]);
}

pub(super) fn lsm_1d(inputs: &Record) -> Result<Solution> {
    let t = numbers(inputs, "template")?;
    let sw = numbers(inputs, "search")?;
    let c0 = Inputs(inputs).number("c0")?;
    let radiometric = flag_value(inputs, "radiometric")?;
    let model = if radiometric {
        Model::ShiftRadiometric
    } else {
        Model::Shift
    };
    let set = settings(model, Gradients::SearchWindow, inputs)?;
    let m = matching::match_1d(&t, &sw, Params::shift(c0 - 1.0, 0.0, 1.0, 0.0), set)
        .map_err(|e| said_of(e, "c0"))?;
    let syms = symbols(&m.estimated, true);
    let n = t.len();
    let half = (n as f64 - 1.0) / 2.0;
    let mut s = Solution::new("lsm-1d", "1-D least-squares matching", inputs.clone());

    let first_pos: Vec<f64> = (0..n).map(|i| c0 - half + i as f64).collect();
    s.step(
        Step::new(
            "Template and start",
            "The template's centre is placed at the start position c⁰ of the search window; the template's pixels then fall on these search-window positions.",
        )
        .formula(
            r"c_i = c^0 + \left(i - \tfrac{n+1}{2}\right),\quad i = 1 \dots n",
            format!(
                r"T = {},\quad c_i = {}",
                column(&t),
                column(&first_pos)
            ),
        )
        .value("template", Value::numbers(&t))
        .value("search", Value::numbers(&sw))
        .value("positions", Value::numbers(&first_pos)),
    );
    let (eq, lin) = if radiometric {
        (
            r"G_t(c) + V = a\,G_s(c + dc) + b",
            r"[G_t(c) - (a^0 G_s(c) + b^0)] + V = a^0\frac{\partial G_s(c)}{\partial c}\,dc + G_s(c)\,da + db",
        )
    } else {
        (
            r"G_t(c) + V = G_s(c + dc)",
            r"[G_t(c) - G_s(c)] + V = \frac{\partial G_s(c)}{\partial c}\,dc",
        )
    };
    s.step(
        Step::new(
            "Observation equation",
            "Each template pixel is one observation. Taylor's first-order term turns the unknown shift into a linear unknown; the gradient is the central difference (G_s(c+1) − G_s(c−1))/2 of the search window, resampled at the current position.",
        )
        .formula(eq, lin.to_string()),
    );
    if let Some(it) = m.iterations.first() {
        first_iteration_1d(&mut s, it, &t, &syms);
    }
    s.step(table_step(&m, &syms, -1.0));
    status_step(&mut s, &m, &syms, set.max_iterations);

    let first = m.iterations.first();
    let inc = |k: usize| first.and_then(|it| it.increments.get(k).copied());
    s.result = Record::new()
        .with("first_dc", inc(0))
        .with("first_da", if radiometric { inc(1) } else { None })
        .with("first_db", if radiometric { inc(2) } else { None })
        .with("c", m.params.a[2] + 1.0)
        .with("a", m.params.gain())
        .with("b", m.params.offset())
        .with("iterations", m.iterations.len())
        .with("converged", m.converged())
        .with("status", m.status.word())
        .with("sigma0", m.sigma0());
    s.note(
        NoteKind::Convention,
        "Positions count from 1 as in the course notes; c is the search-window position of the template's centre pixel. dL + V = A·dX with V = A·dX − dL.",
    ).about(&["c"]);
    if seed_inputs(&lsm_1d_fields(), inputs, &["template", "search", "c0"]) {
        ex10_notes(&mut s, &m, radiometric);
    }
    label_results(&mut s);
    Ok(s)
}

pub(super) fn first_iteration_1d(s: &mut Solution, it: &Iteration, t: &[f64], syms: &[&str]) {
    let b = it.bordered.data();
    let g = it.patch.data();
    let (a0, b0) = (it.params.gain(), it.params.offset());
    let modelled: Vec<f64> = g.iter().map(|x| a0 * x + b0).collect();
    s.step(
        Step::new(
            "Difference vector dL (iteration 1)",
            "The template minus the search patch resampled at the current position (and scaled by the current gain and offset).",
        )
        .formula(
            r"d\mathbf{L} = G_t - (a^0 G_s + b^0)",
            format!(
                r"d\mathbf{{L}} = {} - {} = {}",
                column(t),
                column(&modelled),
                column(&it.dl)
            ),
        )
        .value("patch", Value::numbers(g))
        .value("dL", Value::numbers(&it.dl)),
    );
    let rows: Vec<Vec<String>> = (0..g.len())
        .map(|i| {
            let right = b.get(i + 2).copied().unwrap_or(0.0);
            let left = b.get(i).copied().unwrap_or(0.0);
            let mut row = vec![format!(r"({} - {})/2", num(right), tex(left))];
            for (k, sym) in syms.iter().enumerate().skip(1) {
                let v = it.a.get(i).and_then(|r| r.get(k)).copied().unwrap_or(0.0);
                let _ = sym;
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
        .formula(
            &format!(r"A_{{i,1}} = {gain_note}\frac{{G_s(c_i+1) - G_s(c_i-1)}}{{2}}"),
            format!(r"A = {} = {}", bmatrix(&rows), numeric(&it.a)),
        )
        .value("A", Value::matrix(&it.a))
        .value("bordered", Value::numbers(b)),
    );
    s.step(normal_step(it, syms).value(
        "c_after_first",
        it.params.a[2] + 1.0 + it.increments.first().copied().unwrap_or(0.0),
    ));
}

pub(super) fn ex10_notes(s: &mut Solution, m: &Matching, radiometric: bool) {
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
