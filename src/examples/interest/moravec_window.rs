//! The Moravec operator on one window: the four directional variances and the interest value.

use super::*;

pub(super) fn moravec_window(inputs: &Record) -> Result<Solution> {
    let window = grid(inputs, "window")?;
    let mv = interest::moravec(&window)?;
    let mut s = Solution::new("moravec-window", "Moravec operator", inputs.clone());
    let mut lines = vec![r"\footnotesize\begin{aligned}".to_string()];
    let mut table = Vec::new();
    for p in &mv.pixels {
        let terms: Vec<String> = p
            .pairs
            .iter()
            .map(|(a, b)| format!("({} - {})^2", num(*a), tex(*b)))
            .collect();
        let (first, second) = terms.split_at(2);
        lines.push(format!(
            r"{} = {}:&\quad {} \\ &\quad + {} = {} \\",
            pos(p.c, p.r),
            num(p.g),
            first.join(" + "),
            second.join(" + "),
            num(p.sum)
        ));
        let mut row = vec![(p.c + 1) as f64, (p.r + 1) as f64, p.g];
        row.extend(p.diffs);
        row.push(p.sum);
        table.push(row);
    }
    lines.push(r"\end{aligned}".to_string());
    s.step(
        Step::new(
            "Directional differences at each interior pixel",
            "Across each interior pixel, in the row direction g(c+1, r) − g(c−1, r), the column direction g(c, r+1) − g(c, r−1), the main diagonal g(c+1, r+1) − g(c−1, r−1) and the other diagonal g(c−1, r+1) − g(c+1, r−1); squared and summed. Table rows are [c, r, g, row, column, main diagonal, other diagonal, sum], positions from 1.",
        )
        .formula(
            r"S(c,r) = d_1^2 + d_2^2 + d_3^2 + d_4^2,\quad d_1 = g_{c+1,r} - g_{c-1,r},\quad d_2 = g_{c,r+1} - g_{c,r-1},\quad d_3 = g_{c+1,r+1} - g_{c-1,r-1},\quad d_4 = g_{c-1,r+1} - g_{c+1,r-1}",
            lines.join("\n"),
        )
        .value("table", Value::matrix(&table))
        .value("sums", Value::matrix(&mv.sums.rows())),
    );
    let n = mv.pixels.len();
    let sums: Vec<String> = mv.pixels.iter().map(|p| num(p.sum)).collect();
    s.step(
        Step::new(
            "Measure of distinctness",
            "The mean of the sums over the interior pixels. The window counts as an interest point if it exceeds a threshold.",
        )
        .formula(
            r"\bar S = \frac{1}{n} \sum S(c, r)",
            format!(
                r"\sum S = {} = {},\quad \bar S = \frac{{{}}}{{{}}} = {}",
                sums.join(" + "),
                num(mv.pixels.iter().map(|p| p.sum).sum::<f64>()),
                num(mv.pixels.iter().map(|p| p.sum).sum::<f64>()),
                n,
                num(mv.mean)
            ),
        )
        .value("mean", mv.mean),
    );
    s.result = Record::new()
        .with("sums", Value::matrix(&mv.sums.rows()))
        .with("mean", mv.mean)
        .with("differences", Value::matrix(&table));
    label_results(&mut s);
    s.note(
        NoteKind::Convention,
        "This is the Moravec operator as the worked examples define it: differences across the pixel (c+1 against c−1), all four directions summed, averaged over the window. Moravec's original operator sums squared differences of neighbouring pixels along each direction and keeps the MINIMUM over the four directions, so that an edge (strong in one direction only) scores low; the course notes' average responds to edges as strongly as to corners.",
    ).about(&["sums", "mean"]);
    if is_seed(&moravec_fields(), inputs) {
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
