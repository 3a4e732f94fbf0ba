//! Example 6: the 2-D correlation coefficient of two equal-size arrays.

use super::*;

pub(super) fn grid(inputs: &Record, key: &str) -> Result<Grid> {
    Grid::from_rows(key, &rows(inputs, key)?)
}

pub(super) fn ncc_2d(inputs: &Record) -> Result<Solution> {
    let a = grid(inputs, "a")?;
    let b = grid(inputs, "b")?;
    let n = correlation::ncc_grid(&a, &b)?;
    let (av, bv) = (a.data(), b.data());
    let mut s = Solution::new("ncc-2d", "2-D correlation coefficient", inputs.clone());
    s.step(
        Step::new(
            "Means",
            &format!(
                "The mean grey value of each {}×{} array.",
                a.height(),
                a.width()
            ),
        )
        .formula(
            r"\bar A = \frac{1}{mn}\sum_{i,j} A_{ij},\quad \bar B = \frac{1}{mn}\sum_{i,j} B_{ij}",
            format!(
                r"{},\quad {}",
                tex_mean(r"\sum A", r"\bar A", av, n.mean_a),
                tex_mean(r"\sum B", r"\bar B", bv, n.mean_b)
            ),
        )
        .value("mean_a", n.mean_a)
        .value("mean_b", n.mean_b),
    );
    let da: Vec<Vec<f64>> = a
        .rows()
        .iter()
        .map(|r| r.iter().map(|x| x - n.mean_a).collect())
        .collect();
    let db: Vec<Vec<f64>> = b
        .rows()
        .iter()
        .map(|r| r.iter().map(|x| x - n.mean_b).collect())
        .collect();
    s.step(
        Step::new(
            "Sum of products of deviations",
            "Each value's deviation from its array's mean, multiplied pairwise and summed.",
        )
        .formula(
            r"\sum_{i,j} (A_{ij} - \bar A)(B_{ij} - \bar B)",
            format!(
                r"{} = {}",
                tex_dev_terms(av, n.mean_a, Some((bv, n.mean_b))),
                num(n.sum_dadb)
            ),
        )
        .value("da", Value::matrix(&da))
        .value("db", Value::matrix(&db))
        .value("sum_dadb", n.sum_dadb),
    );
    s.step(
        Step::new("Sum of squared deviations of A", "")
            .formula(
                r"\sum_{i,j} (A_{ij} - \bar A)^2",
                format!(
                    r"{} = {}",
                    tex_dev_terms(av, n.mean_a, None),
                    num(n.sum_da2)
                ),
            )
            .value("sum_da2", n.sum_da2),
    );
    s.step(
        Step::new("Sum of squared deviations of B", "")
            .formula(
                r"\sum_{i,j} (B_{ij} - \bar B)^2",
                format!(
                    r"{} = {}",
                    tex_dev_terms(bv, n.mean_b, None),
                    num(n.sum_db2)
                ),
            )
            .value("sum_db2", n.sum_db2),
    );
    let flat = flat_text(&n, "A", "B");
    s.step(
        ncc_values(
            Step::new(
                "Correlation coefficient",
                if flat.is_empty() {
                    "The sum of products over the square root of the product of the two sums of squares."
                } else {
                    &flat
                },
            )
            .formula(RHO_SYMBOLIC, rho_formula(&n)),
            &n,
        ),
    );
    s.result = Record::new()
        .with("mean_a", n.mean_a)
        .with("mean_b", n.mean_b)
        .with("sum_dadb", n.sum_dadb)
        .with("sum_da2", n.sum_da2)
        .with("sum_db2", n.sum_db2)
        .with("rho", opt(n.rho));
    if !flat.is_empty() {
        s.note(
            NoteKind::Warning,
            format!("{flat} The correlation coefficient is 0/0 and has no value."),
        )
        .about(&["rho"]);
    }
    if is_seed(&ncc_2d_fields(), inputs) {
        seed_notes_6(&mut s, &n, av, bv);
    }
    label_results(&mut s);
    Ok(s)
}

pub(super) fn seed_notes_6(s: &mut Solution, n: &Ncc, av: &[f64], bv: &[f64]) {
    s.textbook = Some(
        Record::new()
            .with("mean_a", 58.5)
            .with("mean_b", 59.1)
            .with("sum_dadb", 1149.22)
            .with("sum_da2", 843.56)
            .with("sum_db2", 2604.89)
            .with("rho", 0.7753),
    );
    let (ma, mb) = (58.8, 59.1);
    let seed_dadb: f64 = av.iter().zip(bv).map(|(a, b)| (a - ma) * (b - mb)).sum();
    let seed_da2: f64 = av.iter().map(|a| (a - ma) * (a - ma)).sum();
    let seed_db2: f64 = bv.iter().map(|b| (b - mb) * (b - mb)).sum();
    let plain: f64 = bv.iter().map(|b| b - mb).sum();
    s.note(
        NoteKind::Erratum,
        format!(
            "The course notes print Ā = 58.5, but the nine values sum to 529 and 529/9 = {}. Their sums then use 58.8 (the mean rounded to one decimal), so 58.5 is a typo in the printed mean only.",
            num(n.mean_a)
        ),
    ).about(&["mean_a"]);
    s.note(
        NoteKind::Rounding,
        format!(
            "With the rounded means 58.8 and 59.1 the three sums come out as {}, {} and {} — the course notes' 1149.22, 843.56 and 2604.89. The exact sums {}, {} and {} agree to the printed two decimals: deviations from a mean add up to zero, so moving a mean by δ changes a sum of squares only by n·δ² (here 9 × {}² = {}).",
            fmt_sig(seed_dadb, 8),
            fmt_sig(seed_da2, 8),
            fmt_sig(seed_db2, 8),
            num(n.sum_dadb),
            num(n.sum_da2),
            num(n.sum_db2),
            fmt_sig(ma - n.mean_a, 3),
            fmt_sig(9.0 * (ma - n.mean_a).powi(2), 2)
        ),
    ).about(&["mean_b", "sum_dadb", "sum_da2", "sum_db2"]);
    s.note(
        NoteKind::Erratum,
        format!(
            "The course notes write the third sum without the squares, (52 − 59.1) + (37 − 59.1) + …, which adds up to {} (deviations sum to zero); its value 2604.89 is the sum of the squares, (52 − 59.1)² + (37 − 59.1)² + ….",
            fmt_sig(plain, 2)
        ),
    ).about(&["sum_db2"]);
    s.note(
        NoteKind::Rounding,
        format!(
            "ρ = {} is the course notes' 0.7753 to four decimals.",
            rho_text(n.rho)
        ),
    )
    .about(&["rho"]);
}
