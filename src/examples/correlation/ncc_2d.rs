//! Example 6: the 2-D correlation coefficient of two equal-size arrays.

use super::*;
use crate::correlation::{mean, sums_about};
use crate::examples::drill::{
    drill, mat, or_given, rows_of, tol, transpose, BoxDef, Drill, Mistake,
};
use crate::examples::fields::is_seed;
use crate::solution::{fmt_sig, NoteKind, Solution};

pub const EXAMPLE: Example = Example {
    id: "ncc-2d",
    title: "2-D correlation coefficient",
    source: "Worked examples, Example 6",
    summary: "The normalized correlation coefficient of two equal-size arrays, with their means and the three sums.",
    fields,
    solve,
    answer: &["rho"],
    labels: LABELS,
    lab: Some(Lab::new("correlation", &["rho"])),
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

fn fields() -> Vec<Field> {
    vec![
        Field::matrix(
            "a",
            "Array A",
            &[
                vec![48.0, 50.0, 48.0],
                vec![51.0, 67.0, 71.0],
                vec![55.0, 67.0, 72.0],
            ],
        )
        .help("Grey values of the first image patch (rows separated by ;)."),
        Field::matrix(
            "b",
            "Array B",
            &[
                vec![52.0, 37.0, 41.0],
                vec![67.0, 54.0, 78.0],
                vec![42.0, 74.0, 87.0],
            ],
        )
        .help("Grey values of the second image patch, the same size as A."),
    ]
}

fn solve(inputs: &Record) -> Result<Solution> {
    let a = grid(inputs, "a")?;
    let b = grid(inputs, "b")?;
    let n = correlation::ncc_grid(&a, &b)?;
    let (av, bv) = (a.data(), b.data());
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    let [sum_a, mean_a] = mean_relations(
        r"\sum A",
        r"\bar A",
        r"\frac{1}{mn}\sum_{i,j} A_{ij}",
        "mean_a",
        av,
        n.mean_a,
    );
    let [sum_b, mean_b] = mean_relations(
        r"\sum B",
        r"\bar B",
        r"\frac{1}{mn}\sum_{i,j} B_{ij}",
        "mean_b",
        bv,
        n.mean_b,
    );
    s.step(
        Step::new(
            "Means",
            &format!(
                "The mean grey value of each {}×{} array.",
                a.height(),
                a.width()
            ),
        )
        .relation(sum_a)
        .relation(mean_a)
        .relation(sum_b)
        .relation(mean_b)
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
        .relation(products_relation(AB_2D, av, bv, &n))
        .value("da", Value::matrix(&da))
        .value("db", Value::matrix(&db))
        .value("sum_dadb", n.sum_dadb),
    );
    s.step(
        Step::new("Sum of squared deviations of A", "")
            .relation(squares_relation(
                "A", "A_{ij}", "sum_da2", av, n.mean_a, n.sum_da2,
            ))
            .value("sum_da2", n.sum_da2),
    );
    s.step(
        Step::new("Sum of squared deviations of B", "")
            .relation(squares_relation(
                "B", "B_{ij}", "sum_db2", bv, n.mean_b, n.sum_db2,
            ))
            .value("sum_db2", n.sum_db2),
    );
    let flat = flat_text(&n, "A", "B");
    s.step(ncc_values(
        Step::new(
            "Correlation coefficient",
            if flat.is_empty() {
                "The sum of products over the square root of the product of the two sums of squares."
            } else {
                &flat
            },
        )
        .relation(rho_relation(r"\rho", &n)),
        &n,
    ));
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
    if is_seed(&fields(), inputs) {
        seed_notes_6(&mut s, &n, av, bv);
    }
    Ok(s)
}

fn seed_notes_6(s: &mut Solution, n: &Ncc, av: &[f64], bv: &[f64]) {
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

// ---------------------------------------------------------------- practice

fn generate(rng: &mut Rng) -> Record {
    let a: Vec<Vec<f64>> = (0..3)
        .map(|_| textured(rng, 3).iter().map(|v| 20.0 + 7.0 * v).collect())
        .collect();
    let offset = rng.num(-10, 10);
    let b: Vec<Vec<f64>> = a
        .iter()
        .map(|row| row.iter().map(|v| v + offset + rng.num(-12, 12)).collect())
        .collect();
    Record::new().with("a", mat(&a)).with("b", mat(&b))
}

fn boxes(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("mean_a", "Mean of A", None, tol::GREY)
            .nudge("Nine values: add them, divide by 9."),
        BoxDef::new("mean_b", "Mean of B", None, tol::GREY).nudge("The same for B."),
        BoxDef::new("sum_dadb", "Σ ΔA·ΔB", None, tol::SUM)
            .nudge("Subtract the means, multiply the two deviations pixel by pixel, add.")
            .sign_flip(RHO_FLIP),
        BoxDef::new("sum_da2", "Σ ΔA²", None, tol::SUM)
            .nudge("The squared deviations of A, added."),
        BoxDef::new("sum_db2", "Σ ΔB²", None, tol::SUM)
            .nudge("The squared deviations of B, added."),
        BoxDef::new("rho", "Correlation coefficient ρ", None, tol::RHO)
            .nudge("Σ ΔA·ΔB over the root of Σ ΔA² · Σ ΔB².")
            .sign_flip(RHO_FLIP),
    ]
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let a: Vec<f64> = rows_of(i, "a").concat();
    let b: Vec<f64> = rows_of(i, "b").concat();
    let ma = or_given(g, "mean_a", mean(&a));
    let mb = or_given(g, "mean_b", mean(&b));
    let [ab, aa, bb] = sums_about(&a, ma, &b, mb);
    let ab = or_given(g, "sum_dadb", ab);
    let aa = or_given(g, "sum_da2", aa);
    let bb = or_given(g, "sum_db2", bb);
    Ok(Record::new()
        .with("mean_a", ma)
        .with("mean_b", mb)
        .with("sum_dadb", ab)
        .with("sum_da2", aa)
        .with("sum_db2", bb)
        .with("rho", correlation::rho_of_sums(ab, aa, bb)))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let a: Vec<f64> = rows_of(i, "a").concat();
    let b = rows_of(i, "b");
    let bt: Vec<f64> = transpose(&b).concat();
    let swapped = chain(&i.clone().with("b", mat(&transpose(&b))), &Record::new())?;
    const SWAP: &str = "Pair each pixel of A with the pixel of B at the same row and column.";
    Ok(vec![
        Mistake::new(
            "rho",
            "mean not subtracted",
            "ρ compares the deviations from the means: subtract the means first.",
            rho_about(&a, 0.0, &b.concat(), 0.0),
        ),
        Mistake::new(
            "rho",
            "rows and columns swapped",
            SWAP,
            rho_about(&a, mean(&a), &bt, mean(&bt)),
        ),
        Mistake::new(
            "sum_dadb",
            "rows and columns swapped",
            SWAP,
            swapped.number("sum_dadb").unwrap_or(f64::NAN),
        ),
        Mistake::new(
            "sum_dadb",
            "mean not subtracted",
            "Multiply the deviations ΔA = A − Ā and ΔB = B − B̄, not the grey values.",
            sums_about(&a, 0.0, &b.concat(), 0.0)[0],
        ),
    ])
}
