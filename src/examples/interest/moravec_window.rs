//! Seed 000, Example 14: the Moravec operator on one window, the four
//! directional differences at each interior pixel and their mean.

use super::*;
use crate::examples::drill::{drill, mat as rows_value, Drill, Rng};
use crate::examples::fields::is_seed;
use crate::examples::Lab;
use crate::interest;

pub const EXAMPLE: Example = Example {
    id: "moravec-window",
    title: "Moravec operator",
    source: "Worked examples, Example 14",
    summary: "Four directional differences at each interior pixel, squared and summed, averaged over the window.",
    fields,
    solve,
    answer: &["sums", "mean"],
    labels: LABELS,
    lab: Some(Lab::new("interest", &["moravec"])),
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

fn fields() -> Vec<Field> {
    let example_14 = [
        [12.0, 15.0, 5.0, 13.0],
        [10.0, 27.0, 9.0, 11.0],
        [11.0, 14.0, 15.0, 13.0],
        [12.0, 19.0, 18.0, 22.0],
    ]
    .map(|r| r.to_vec());
    vec![window_field(
        &example_14,
        "At least 3×3 (4×4 or 8×8 in the course notes); differences are computed at the interior pixels.",
    )]
}

fn solve(inputs: &Record) -> Result<Solution> {
    let window = grid(inputs, "window")?;
    let mv = interest::moravec(&window)?;
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    let mut step = Step::new(
        "Directional differences at each interior pixel",
        "Across each interior pixel, in the row direction g(c+1, r) − g(c−1, r), the column direction g(c, r+1) − g(c, r−1), the main diagonal g(c+1, r+1) − g(c−1, r−1) and the other diagonal g(c−1, r+1) − g(c+1, r−1); squared and summed. Table rows are [c, r, g, row, column, main diagonal, other diagonal, sum], positions from 1.",
    )
    // the rule is what every box of `sums` computes; each pixel's own
    // numbers are the relations below, keyed with the element's path
    .relation(
        Relation::new("S(c,r)")
            .key("sums")
            .sym(Form::terms(["d_1^2", "+ d_2^2", "+ d_3^2", "+ d_4^2"])),
    )
    .relation(Relation::new("d_1").sym("g_{c+1,r} - g_{c-1,r}"))
    .relation(Relation::new("d_2").sym("g_{c,r+1} - g_{c,r-1}"))
    .relation(Relation::new("d_3").sym("g_{c+1,r+1} - g_{c-1,r-1}"))
    .relation(Relation::new("d_4").sym("g_{c-1,r+1} - g_{c+1,r-1}"));
    let mut table = Vec::new();
    for p in &mv.pixels {
        let terms = p.pairs.iter().enumerate().map(|(k, (a, b))| {
            let plus = if k == 0 { "" } else { "+ " };
            format!("{plus}({} - {})^2", num(*a), tex(*b))
        });
        // the element of `sums`: interior row and column from 1 (the
        // border pixels are row and column 0)
        let key = format!("sums[{},{}]", p.r, p.c);
        step = step.relation(
            Relation::new(format!("S(c_{{{}}}, r_{{{}}})", p.c + 1, p.r + 1))
                .key(&key)
                .subst(Form::terms(terms))
                .value(p.sum, ""),
        );
        let mut row = vec![(p.c + 1) as f64, (p.r + 1) as f64, p.g];
        row.extend(p.diffs);
        row.push(p.sum);
        table.push(row);
    }
    s.step(
        step.value("table", Value::matrix(&table))
            .value("sums", Value::matrix(&mv.sums.rows())),
    );
    let n = mv.pixels.len();
    let total: f64 = mv.pixels.iter().map(|p| p.sum).sum();
    let sums = mv.pixels.iter().enumerate().map(|(k, p)| {
        let plus = if k == 0 { "" } else { "+ " };
        format!("{plus}{}", num(p.sum))
    });
    s.step(
        Step::new(
            "Measure of distinctness",
            "The mean of the sums over the interior pixels. The window counts as an interest point if it exceeds a threshold.",
        )
        .relation(
            Relation::new(r"\sum S")
                .subst(Form::terms(sums))
                .value(total, ""),
        )
        .relation(
            Relation::new(r"\bar S")
                .key("mean")
                .sym(r"\frac{1}{n} \sum S(c, r)")
                .subst(format!(r"\frac{{{}}}{{{}}}", num(total), n))
                .value(mv.mean, ""),
        )
        .value("mean", mv.mean),
    );
    s.result = Record::new()
        .with("sums", Value::matrix(&mv.sums.rows()))
        .with("mean", mv.mean)
        .with("differences", Value::matrix(&table));
    s.note(
        NoteKind::Convention,
        "This is the Moravec operator as the worked examples define it: differences across the pixel (c+1 against c−1), all four directions summed, averaged over the window. Moravec's original operator sums squared differences of neighbouring pixels along each direction and keeps the MINIMUM over the four directions, so that an edge (strong in one direction only) scores low; the course notes' average responds to edges as strongly as to corners.",
    ).about(&["sums", "mean"]);
    if is_seed(&fields(), inputs) {
        s.textbook = Some(
            Record::new()
                .with(
                    "sums",
                    Value::matrix(&[vec![47.0, 361.0], vec![153.0, 171.0]]),
                )
                .with("mean", 183.0),
        );
        s.note(
            NoteKind::Convention,
            "All four sums (47, 361, 153, 171) and the mean 183 agree with the course notes. The course notes write the row difference at P(c2, r3) as (11 − 15) and list the other diagonal before the main one at every pixel; the squares are the same.",
        ).about(&["sums", "mean"]);
    }
    Ok(s)
}

// ---------------------------------------------------------------- practice

fn generate(rng: &mut Rng) -> Record {
    let w: Vec<Vec<f64>> = (0..4)
        .map(|_| (0..4).map(|_| rng.num(5, 30)).collect())
        .collect();
    Record::new().with("window", rows_value(&w))
}

/// The interior pixels of the 4×4 practice window (row, column from 1).
const INTERIOR: [(usize, usize); 4] = [(1, 1), (1, 2), (2, 1), (2, 2)];

fn boxes(_: &Record) -> Vec<BoxDef> {
    let mut b: Vec<BoxDef> = INTERIOR
        .iter()
        .map(|&(r, c)| {
            BoxDef::new(
                &format!("sums[{r},{c}]"),
                &format!("Sum at interior row {r}, column {c}"),
                None,
                tol::WHOLE,
            )
            .nudge("Four differences across the pixel (left–right, up–down, both diagonals), each squared, added.")
        })
        .collect();
    b.push(
        BoxDef::new("mean", "Mean of the sums", None, tol::GREY)
            .nudge("Add the interior sums and divide by how many there are."),
    );
    b
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = EXAMPLE.run(i)?;
    let mut out = Record::new();
    let mut total = 0.0;
    for &(r, c) in &INTERIOR {
        let key = format!("sums[{r},{c}]");
        let x = or_given(g, &key, value_in(&s, &key)?);
        total += x;
        out.set(&key, x);
    }
    out.set("mean", total / INTERIOR.len() as f64);
    Ok(out)
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let s = EXAMPLE.run(i)?;
    let w = Inputs(&s.inputs).rows("window")?;
    let g = |c: usize, r: usize| {
        w.get(r)
            .and_then(|row| row.get(c))
            .copied()
            .unwrap_or(f64::NAN)
    };
    let mut out = Vec::new();
    for &(r, c) in &INTERIOR {
        let key = format!("sums[{r},{c}]");
        let abs: f64 = [
            g(c + 1, r) - g(c - 1, r),
            g(c, r + 1) - g(c, r - 1),
            g(c + 1, r + 1) - g(c - 1, r - 1),
            g(c - 1, r + 1) - g(c + 1, r - 1),
        ]
        .iter()
        .map(|d| d.abs())
        .sum();
        out.push(Mistake::new(
            &key,
            "differences not squared",
            "Moravec adds the squares of the four differences.",
            abs,
        ));
        out.push(Mistake::new(
            &key,
            "rows and columns swapped",
            "Row r counts down, column c to the right.",
            value_in(&s, &format!("sums[{c},{r}]"))?,
        ));
    }
    Ok(out)
}
