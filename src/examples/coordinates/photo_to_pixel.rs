//! Seed 000, Example 3: from image coordinates in mm to the pixel's column
//! and row, and its practice.

use super::super::drill::{drill, or_given, tol, BoxDef, Drill, Mistake, Rng, Tolerance};
use super::super::fields::{is_seed, Field, Inputs};
use super::super::Example;
use super::*;
use crate::coords;
use crate::error::Result;
use crate::solution::{exact_minus_printed, num, tex, Record, Relation, Solution, Step};

pub const EXAMPLE: Example = Example {
    id: "photo-to-pixel",
    title: "Image to pixel coordinates",
    source: "Worked examples, Example 3",
    summary: "From image coordinates in mm to the pixel's column and row.",
    fields,
    solve,
    answer: &["c", "r"],
    labels: LABELS,
    lab: None,
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

fn fields() -> Vec<Field> {
    conversion_fields(
        (1800.0, 1500.0),
        coordinate("x_mm", "Image coordinate x", -12.42, "mm")
            .help("To the right of the image centre."),
        coordinate("y_mm", "Image coordinate y", -25.36, "mm").help("Up from the image centre."),
    )
}

fn solve(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let (dpi, x, y) = (i.number("dpi")?, i.number("x_mm")?, i.number("y_mm")?);
    let frame = frame(&i)?;
    let o = coords::image_to_pixel(dpi, frame, x, y)?;
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    s.step(centre_step(frame));
    s.step(pixel_size_step(dpi, o.pixel_size_mm));
    let p = num(o.pixel_size_mm);
    s.step(
        Step::new(
            "Offsets from the centre in pixels",
            "Divide by the pixel size. Columns count to the right like x; rows count downward, against y, so the row offset is −y/p.",
        )
        .relation(
            Relation::new(r"\Delta c")
                .key("dc_px")
                .sym(r"\frac{x}{p}")
                .subst(format!(r"\frac{{{}}}{{{p}}}", num(x)))
                .value(o.dc_px, "px"),
        )
        .relation(
            Relation::new(r"\Delta r")
                .key("dr_px")
                .sym(r"-\frac{y}{p}")
                .subst(format!(r"-\frac{{{}}}{{{p}}}", num(y)))
                .value(o.dr_px, "px"),
        )
        .value("dc_px", o.dc_px)
        .value("dr_px", o.dr_px),
    );
    s.step(
        Step::new("Pixel coordinates", "Add the offsets to the centre.")
            .relation(
                Relation::new("c")
                    .key("c")
                    .sym(r"c_0 + \Delta c")
                    .subst(format!("{} + {}", num(o.c0), tex(o.dc_px)))
                    .value(o.c, ""),
            )
            .relation(
                Relation::new("r")
                    .key("r")
                    .sym(r"r_0 + \Delta r")
                    .subst(format!("{} + {}", num(o.r0), tex(o.dr_px)))
                    .value(o.r, ""),
            )
            .value("c", o.c)
            .value("r", o.r),
    );
    s.result = Record::new()
        .with("c0", o.c0)
        .with("r0", o.r0)
        .with("pixel_size_mm", o.pixel_size_mm)
        .with("dc_px", o.dc_px)
        .with("dr_px", o.dr_px)
        .with("c", o.c)
        .with("r", o.r);
    convention_note(&mut s);
    if !o.inside {
        s.note(NoteKind::Warning, outside_note(o.c, o.r, frame))
            .about(&["c", "r"]);
    }
    if is_seed(&fields(), inputs) {
        let (p, dc, dr, c, r) = (0.042, -295.7, -603.8, 604.3, 1353.8);
        s.textbook = Some(
            Record::new()
                .with("c0", 900.0)
                .with("r0", 750.0)
                .with("pixel_size_mm", p)
                .with("dc_px", dc)
                .with("dr_px", dr)
                .with("c", c)
                .with("r", r),
        );
        pixel_rounding_note(&mut s, dpi, o.pixel_size_mm, p);
        s.note(
            NoteKind::Erratum,
            format!(
                "A sign slip: the course notes write the row offset as r_p = −25.36/0.042 = {dr} and then add +603.8 (750 + 603.8). Their −603.8 is y/p; the row offset is −y/p = +{} (exact +{} with the exact pixel size), since rows count downward. The notes also name both offsets c_p and r_p, the same symbols as the final pixel coordinates.",
                num(-dr),
                num(o.dr_px)
            ),
        )
        .about(&["dr_px"]);
        s.note(
            NoteKind::Rounding,
            format!(
                "From the rounded pixel size the printed offsets {dc} and {} px are {} and {} px too large in size, so the printed c = {c} and r = {r} differ from the exact {} and {} (c: {}; r: {}).",
                -dr,
                num(dc.abs() - o.dc_px.abs()),
                num(dr.abs() - o.dr_px.abs()),
                num(o.c),
                num(o.r),
                exact_minus_printed(o.c, c, "px"),
                exact_minus_printed(o.r, r, "px")
            ),
        )
        .about(&["dc_px", "c", "r"]);
    }
    Ok(s)
}

// ---------------------------------------------------------------------------
// Practice

/// Pixel offsets from millimetres: 0.05 px plus 0.02 %.
const OFFSET: Tolerance = Tolerance {
    atol: 0.05,
    rtol: 0.0002,
};

fn generate(rng: &mut Rng) -> Record {
    let (scan, dpi, columns, rows) = draw_scan(rng);
    let p = coords::MM_PER_INCH / dpi;
    // x, y in mm with 2 decimals, inside 90 % of the image half-size.
    let coord = |rng: &mut Rng, half_px: f64| {
        let lim = (half_px * p * 0.9 * 100.0) as i64;
        let k = rng.int(100, lim.max(101));
        (if rng.coin() { k } else { -k }) as f64 / 100.0
    };
    let x = coord(rng, columns / 2.0);
    let y = coord(rng, rows / 2.0);
    scan.with("x_mm", x).with("y_mm", y)
}

fn boxes(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("c0", "Centre column c₀", Some("px"), tol::PIXEL)
            .nudge("The image centre: half the width in columns."),
        BoxDef::new("r0", "Centre row r₀", Some("px"), tol::PIXEL)
            .nudge("Half the height in rows."),
        pixel_size_box(),
        BoxDef::new("dc_px", "Column offset Δc", Some("px"), OFFSET)
            .nudge("Millimetres divided by the pixel size give pixels.")
            .axis(),
        BoxDef::new("dr_px", "Row offset Δr", Some("px"), OFFSET)
            .nudge("y counts up, rows count down: mind the sign.")
            .axis(),
        BoxDef::new("c", "Column c", Some("px"), OFFSET).nudge("Start at the centre column."),
        BoxDef::new("r", "Row r", Some("px"), OFFSET).nudge("Start at the centre row."),
    ]
}

/// The boxes from the student's earlier answers: each stage of the
/// solver's arithmetic on the values given so far.
fn chain(i: &Record, g: &Record) -> Result<Record> {
    let (c0, r0) = centre_or_given(i, g)?;
    let p = or_given(g, "pixel_size_mm", coords::pixel_size_mm(n(i, "dpi"))?);
    let dc = or_given(g, "dc_px", n(i, "x_mm") / p);
    let dr = or_given(g, "dr_px", -n(i, "y_mm") / p);
    Ok(Record::new()
        .with("c0", c0)
        .with("r0", r0)
        .with("pixel_size_mm", p)
        .with("dc_px", dc)
        .with("dr_px", dr)
        .with("c", c0 + dc)
        .with("r", r0 + dr))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let (x, y) = (n(i, "x_mm"), n(i, "y_mm"));
    let o = coords::image_to_pixel(n(i, "dpi"), frame(&Inputs(i))?, x, y)?;
    let p = o.pixel_size_mm;
    // the centre with rows and columns swapped
    let (swapped_c0, swapped_r0) = (o.r0, o.c0);
    const FLIP: &str = "y counts up, r counts down: Δr = −y / pixel size.";
    const TIMES: &str = "Millimetres divided by the pixel size give pixels, not multiplied.";
    const ROUND: &str = "The seed rounds the pixel size to 3 decimals; that costs pixels here.";
    Ok(vec![
        Mistake::new("c0", "rows and columns swapped", SWAP, swapped_c0),
        Mistake::new("r0", "rows and columns swapped", SWAP, swapped_r0),
        Mistake::new("dc_px", "pixels vs millimetres", TIMES, x * p),
        Mistake::new("dr_px", "y not flipped", FLIP, y / p),
        Mistake::new("r", "y not flipped", FLIP, o.r0 + y / p),
        Mistake::new("c", "rows and columns swapped", SWAP, swapped_c0 + o.dc_px),
        Mistake::new(
            "c",
            "the seed's rounded pixel size",
            ROUND,
            o.c0 + x / seed_rounded(p),
        ),
        Mistake::new(
            "r",
            "the seed's rounded pixel size",
            ROUND,
            o.r0 - y / seed_rounded(p),
        ),
    ])
}
