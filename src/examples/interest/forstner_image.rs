//! Seed 003: the Förstner operator on a generated test pattern, where the
//! window can be moved and the whole image is thresholded and suppressed.

use super::*;
use crate::error::Error;
use crate::examples::drill::{drill, Drill, Rng};
use crate::examples::Lab;
use crate::interest;

pub const EXAMPLE: Example = Example {
    id: "forstner-image",
    title: "Förstner operator on a test pattern",
    source: "Lecture 21: Image matching; Worked examples, Example 13",
    summary: "Move a window over a generated 64×64 pattern (corners, edges, a flat area, noise): N, w, q and the error ellipse there, and the interest points of the whole image after thresholding and suppression.",
    fields,
    solve,
    answer: &["w", "q", "points"],
    labels: LABELS,
    lab: Some(Lab::new("interest", &[])),
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

/// Fixed places of the test pattern, one for each of seed 003's cases
/// (1-based column, row): the flat background, the long vertical edge and
/// the centre of the checkerboard.
const REFERENCE_WINDOWS: &[(&str, usize, usize)] = &[
    ("flat background", 34, 16),
    ("vertical edge", 47, 14),
    ("checkerboard corner", 47, 47),
];

fn fields() -> Vec<Field> {
    let side = PATTERN_SIZE as f64;
    vec![
        Field::integer("c", "Window centre: column c", 9.0)
            .range(1.0, side)
            .help("Column of the window's centre pixel, counted from 1 at the left."),
        Field::integer("r", "Window centre: row r", 9.0)
            .range(1.0, side)
            .help("Row of the window's centre pixel, counted from 1 at the top."),
        Field::integer("window_size", "Window size", 5.0)
            .range(3.0, 9.0)
            .help("Odd: 5×5 or 7×7 in the course notes."),
        Field::number("noise", "Noise added to the pattern", 2.0)
            .unit("grey values")
            .range(0.0, 50.0)
            .help("Uniform noise of ± this many grey values (a fixed sequence, the same every time)."),
        sigma_n(2.0),
        threshold(),
        Field::number("q_min", "Least roundness q", 0.5)
            .range(0.0, 1.0)
            .help("Förstner's roundness test (q at least this) on top of Lecture 21's threshold; 0 switches it off (Lecture 21 alone)."),
    ]
}

fn solve(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let size = i.number("window_size")? as usize;
    let (c1, r1) = (i.number("c")? as usize, i.number("r")? as usize);
    let (noise, sigma_n) = (i.number("noise")?, i.number("sigma_n")?);
    let (t, q_min) = (i.number("threshold_px")?, i.number("q_min")?);
    if size.is_multiple_of(2) {
        return Err(Error::input(
            "window_size",
            format!("must be odd so that the window has a centre pixel (got {size})"),
        ));
    }
    let half = size / 2;
    let side = PATTERN_SIZE;
    for (key, v) in [("c", c1), ("r", r1)] {
        if v < half + 1 || v + half > side {
            return Err(Error::input(
                key,
                format!(
                    "must be between {} and {} so that the {size}×{size} window lies inside the {side}×{side} image (got {v})",
                    half + 1,
                    side - half
                ),
            ));
        }
    }
    let (c, r) = (c1 - 1, r1 - 1);
    let image = interest::test_pattern(side, noise, PATTERN_SEED)?;
    let window = interest::window_at(&image, c, r, size)
        .ok_or_else(|| Error::Internal("checked window does not fit".into()))?;
    let f = interest::forstner(&window)?;
    let p = interest::precision(&f.measures, sigma_n, t);
    let map = interest::forstner_map(&image, size)?;
    let det = interest::forstner_points(&map, sigma_n, t, q_min);

    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    s.step(
        Step::new(
            "The test pattern",
            &format!(
                "A generated {side}×{side} image: flat background (40), a bright square (160) with four corners, a long vertical edge (120), a diagonal edge (110), a checkerboard with nine X-corners (30/190), and uniform noise of ±{} grey values from a fixed generator.",
                num(noise)
            ),
        )
        .value("image", Value::matrix(&image.rows())),
    );
    s.step(
        Step::new(
            "The window",
            &format!(
                "The {size}×{size} window centred on pixel (c, r) = ({c1}, {r1}), counted from 1; columns {} to {}, rows {} to {}.",
                c1 - half,
                c1 + half,
                r1 - half,
                r1 + half
            ),
        )
        .value("window", Value::matrix(&window.rows()))
        .value("c", c1 as f64)
        .value("r", r1 as f64),
    );
    forstner_steps(&mut s, &f, &p, sigma_n, t);
    // Seed 003's three cases side by side: one window of each kind of place
    // in the pattern, drawn on the image with its ellipse.
    let mut references = Vec::new();
    let mut lines = Vec::new();
    for (place, rc, rr) in REFERENCE_WINDOWS {
        let Some(win) = interest::window_at(&image, rc - 1, rr - 1, size) else {
            continue;
        };
        let rf = interest::forstner(&win)?;
        let rp = interest::precision(&rf.measures, sigma_n, t);
        references.push(
            Record::new()
                .with("place", *place)
                .with("c", *rc as f64)
                .with("r", *rr as f64)
                .with("case", rp.case.name())
                .with("sigma_max_px", rp.sigma_max)
                .with("sigma_min_px", rp.sigma_min)
                .with("weak_angle_deg", rf.measures.weak_angle.to_degrees()),
        );
        lines.push(format!(
            "{place} at ({rc}, {rr}): {} (semi-axes {} and {} px)",
            rp.case.name(),
            rp.sigma_max.map_or("∞".to_string(), num),
            rp.sigma_min.map_or("∞".to_string(), num),
        ));
    }
    s.step(
        Step::new(
            "The three cases on the image",
            &format!(
                "Lecture 21's three cases, each at a fixed place of the pattern with the same window size, σn and T: {}. The figure draws their ellipses on the image beside the moving window's.",
                lines.join("; ")
            ),
        )
        .value(
            "references",
            Value::List(references.into_iter().map(Value::Object).collect()),
        ),
    );
    let one_based = |pts: &[interest::InterestPoint]| {
        Value::matrix(
            &pts.iter()
                .map(|p| vec![(p.c + 1) as f64, (p.r + 1) as f64, p.score])
                .collect::<Vec<_>>(),
        )
    };
    s.step(
        Step::new(
            "Whole image: thresholding",
            &format!(
                "The same computation for the window of every pixel where it fits ({} pixels). Kept: λmax(Σuv) ≤ T² = {} px²{}. {} pixels pass. Rows are [c, r, λmax(Σuv)].",
                map.cells.iter().filter(|m| m.is_some()).count(),
                num(t * t),
                if q_min > 0.0 {
                    format!(" and q ≥ {}", num(q_min))
                } else {
                    String::new()
                },
                det.candidates.len()
            ),
        )
        .relation(
            Relation::new(r"\lambda_{max}(\Sigma_{uv})")
                .sym(r"\frac{\sigma_n^2}{\lambda_{min}(N)}"),
        )
        .relation(Relation::new(r"\lambda_{max}(\Sigma_{uv})").op(r"\le").sym("T^2"))
        .relation(
            Relation::new(format!(
                r"\frac{{{}^2}}{{\lambda_{{min}}(N)}}",
                num(sigma_n)
            ))
            .op(r"\le")
            .subst(format!("{}^2", num(t))),
        )
        .value("candidates", one_based(&det.candidates)),
    );
    s.step(
        Step::new(
            "Non-maximum suppression",
            &format!(
                "Lecture 21 step 4: within each {0}×{0} neighbourhood only the candidate with the smallest λmax(Σuv) is kept (the most precise position). {1} interest points remain. Rows are [c, r, λmax(Σuv)].",
                2 * det.radius + 1,
                det.points.len()
            ),
        )
        .relation(Relation::new(Form::default()).key("points").sym(
            r"\min(\lambda_{max,1}, \lambda_{max,2}, \dots, \lambda_{max,k})",
        ))
        .value("points", one_based(&det.points)),
    );
    let w_map = Value::List(
        (0..side)
            .map(|r| {
                Value::List(
                    (0..side)
                        .map(|c| map.get(c, r).map_or(Value::Null, |m| Value::Number(m.w)))
                        .collect(),
                )
            })
            .collect(),
    );
    if let Some(step) = s.steps.first_mut() {
        step.values.set("w_map", w_map);
    }
    let mut result = forstner_result(&f, &p);
    result.set("window", Value::matrix(&window.rows()));
    result.set("candidates", det.candidates.len());
    result.set("points", one_based(&det.points));
    s.result = result;
    singular_notes(&mut s, &f.measures);
    s.note(
        NoteKind::Convention,
        "Gradients by the worked examples' central differences; σn is not given in the course documents (default 2 grey values, a little above this pattern's noise). The roundness test (q at least the least roundness) is Förstner's, not Lecture 21's: with a least roundness of 0 (Lecture 21 alone) some windows on the noisy edges pass too, because noise along an edge makes λmin(N) small but not zero.",
    ).about(&["points", "q"]);
    s.note(
        NoteKind::Convention,
        "The map has no value where the window does not fit inside the image (a border of half the window).",
    );
    Ok(s)
}

// ---------------------------------------------------------------- practice

/// Places on the test pattern with a corner or an X-corner (1-based
/// centres), as seed 003 suggests looking at.
const PLACES: [(i64, i64); 8] = [
    (9, 9),
    (24, 9),
    (9, 24),
    (24, 24),
    (47, 47),
    (37, 47),
    (47, 37),
    (47, 29),
];

fn generate(rng: &mut Rng) -> Record {
    let (c, r) = rng.pick(&PLACES);
    Record::new()
        // Up to one pixel up or left: every such window holds the corner
        // (one pixel down or right of some places it holds only an edge).
        .with("c", (c + rng.int(-1, 0)) as f64)
        .with("r", (r + rng.int(-1, 0)) as f64)
        .with("window_size", rng.pick(&[5.0, 7.0]))
        .with("noise", rng.num(0, 4))
}

/// The Förstner boxes without det N: the pattern's steps are large, det N
/// runs to 10⁸.
fn boxes(_: &Record) -> Vec<BoxDef> {
    forstner_boxes()
        .into_iter()
        .filter(|b| b.key != "det_n")
        .collect()
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    forstner_chain(&EXAMPLE.run(i)?, g)
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let all = forstner_mistakes(&EXAMPLE.run(i)?)?;
    Ok(all.into_iter().filter(|m| m.key != "det_n").collect())
}
