//! Seed 000, Example 1: from a pixel's column and row to its image
//! coordinates in mm, and its practice.

use super::super::drill::{drill, or_given, tol, BoxDef, Drill, Mistake, Rng};
use super::super::fields::{is_seed, Field, Inputs};
use super::super::Example;
use super::*;
use crate::coords;
use crate::error::Result;
use crate::solution::{exact_minus_printed, fmt_sig, num, tex, Record, Relation, Solution, Step};

pub const EXAMPLE: Example = Example {
    id: "pixel-to-photo",
    title: "Pixel to image coordinates",
    source: "Worked examples, Example 1",
    summary: "From a pixel's column and row to its image coordinates in mm, relative to the image centre.",
    fields,
    solve,
    answer: &["x_mm", "y_mm"],
    labels: LABELS,
    lab: None,
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

fn fields() -> Vec<Field> {
    conversion_fields(
        (1600.0, 1400.0),
        coordinate("c", "Column c of the point", 995.0, "px")
            .help("Pixel column, counted to the right from the left edge."),
        coordinate("r", "Row r of the point", 480.0, "px")
            .help("Pixel row, counted downward from the top edge."),
    )
}

fn solve(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let (dpi, c, r) = (i.number("dpi")?, i.number("c")?, i.number("r")?);
    let frame = frame(&i)?;
    let o = coords::pixel_to_image(dpi, frame, c, r)?;
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    s.step(centre_step(frame));
    s.step(
        Step::new(
            "Offsets from the centre in pixels",
            "x counts to the right like c; y counts upward, against r, hence the minus sign.",
        )
        .relation(
            Relation::new("x_p")
                .key("x_px")
                .sym("c - c_0")
                .subst(format!("{} - {}", num(c), num(o.c0)))
                .value(o.x_px, "px"),
        )
        .relation(
            Relation::new("y_p")
                .key("y_px")
                .sym("-(r - r_0)")
                .subst(format!("-({} - {})", num(r), num(o.r0)))
                .value(o.y_px, "px"),
        )
        .value("x_px", o.x_px)
        .value("y_px", o.y_px),
    );
    s.step(pixel_size_step(dpi, o.pixel_size_mm));
    s.step(
        Step::new(
            "Image coordinates in mm",
            "Each pixel offset times the pixel size.",
        )
        .relation(
            Relation::new("x")
                .key("x_mm")
                .sym(r"x_p \cdot p")
                .subst(format!(r"{} \times {}", tex(o.x_px), num(o.pixel_size_mm)))
                .value(o.x_mm, "mm"),
        )
        .relation(
            Relation::new("y")
                .key("y_mm")
                .sym(r"y_p \cdot p")
                .subst(format!(r"{} \times {}", tex(o.y_px), num(o.pixel_size_mm)))
                .value(o.y_mm, "mm"),
        )
        .value("x_mm", o.x_mm)
        .value("y_mm", o.y_mm),
    );
    s.result = Record::new()
        .with("c0", o.c0)
        .with("r0", o.r0)
        .with("x_px", o.x_px)
        .with("y_px", o.y_px)
        .with("pixel_size_mm", o.pixel_size_mm)
        .with("x_mm", o.x_mm)
        .with("y_mm", o.y_mm);
    convention_note(&mut s);
    if !o.inside {
        s.note(NoteKind::Warning, outside_note(c, r, frame))
            .about(&["x_mm", "y_mm"]);
    }
    if is_seed(&fields(), inputs) {
        let (p, x, y) = (0.042, 8.19, 9.24);
        s.textbook = Some(
            Record::new()
                .with("c0", 800.0)
                .with("r0", 700.0)
                .with("x_px", 195.0)
                .with("y_px", 220.0)
                .with("pixel_size_mm", p)
                .with("x_mm", x)
                .with("y_mm", y),
        );
        pixel_rounding_note(&mut s, dpi, o.pixel_size_mm, p);
        s.note(
            NoteKind::Rounding,
            format!(
                "So the printed x = 195 × 0.042 = {x} mm and y = 220 × 0.042 = {y} mm fall short of the exact {} mm and {} mm (x: {}; y: {}) — about {} and {} pixels at this resolution, far beyond the printed precision.",
                num(o.x_mm),
                num(o.y_mm),
                exact_minus_printed(o.x_mm, x, "mm"),
                exact_minus_printed(o.y_mm, y, "mm"),
                fmt_sig((o.x_mm - x) / o.pixel_size_mm, 2),
                fmt_sig((o.y_mm - y) / o.pixel_size_mm, 2),
            ),
        )
        .about(&["x_mm", "y_mm"]);
    }
    Ok(s)
}

// ---------------------------------------------------------------------------
// Practice

/// An offset from the centre: never 0, so a sign error shows.
fn offset(rng: &mut Rng, half: f64) -> f64 {
    let k = rng.int(1, (half as i64 * 9 / 10).max(2));
    if rng.coin() {
        k as f64
    } else {
        -(k as f64)
    }
}

fn generate(rng: &mut Rng) -> Record {
    let (scan, _, columns, rows) = draw_scan(rng);
    let c = columns / 2.0 + offset(rng, columns / 2.0);
    let mut r = rows / 2.0 + offset(rng, rows / 2.0);
    // Keep the two offsets apart so each box has one answer.
    if (r - rows / 2.0).abs() == (c - columns / 2.0).abs() {
        r += 1.0;
    }
    scan.with("c", c).with("r", r)
}

fn boxes(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("c0", "Centre column c₀", Some("px"), tol::PIXEL)
            .nudge("The origin of the image coordinates is the image centre: half the width."),
        BoxDef::new("r0", "Centre row r₀", Some("px"), tol::PIXEL)
            .nudge("Half the height, in rows."),
        BoxDef::new("x_px", "x in pixels", Some("px"), tol::PIXEL)
            .nudge("How many columns to the right of the centre is the point?")
            .axis(),
        BoxDef::new("y_px", "y in pixels", Some("px"), tol::PIXEL)
            .nudge("Rows count downward, y counts upward: mind the sign.")
            .axis(),
        pixel_size_box(),
        BoxDef::new("x_mm", "Image coordinate x", Some("mm"), tol::LENGTH)
            .nudge("Pixels times the pixel size.")
            .axis(),
        BoxDef::new("y_mm", "Image coordinate y", Some("mm"), tol::LENGTH)
            .nudge("Pixels times the pixel size, with y's sign.")
            .axis(),
    ]
}

/// The boxes from the student's earlier answers: each stage of the
/// solver's arithmetic on the values given so far.
fn chain(i: &Record, g: &Record) -> Result<Record> {
    let (c0, r0) = centre_or_given(i, g)?;
    let x_px = or_given(g, "x_px", n(i, "c") - c0);
    let y_px = or_given(g, "y_px", -(n(i, "r") - r0));
    let p = or_given(g, "pixel_size_mm", coords::pixel_size_mm(n(i, "dpi"))?);
    Ok(Record::new()
        .with("c0", c0)
        .with("r0", r0)
        .with("x_px", x_px)
        .with("y_px", y_px)
        .with("pixel_size_mm", p)
        .with("x_mm", x_px * p)
        .with("y_mm", y_px * p))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let o = coords::pixel_to_image(n(i, "dpi"), frame(&Inputs(i))?, n(i, "c"), n(i, "r"))?;
    let (rows, c) = (n(i, "rows"), n(i, "c"));
    let p = o.pixel_size_mm;
    const FLIP: &str = "r counts down, y counts up: y = −(r − r₀).";
    const PX: &str = "That is the offset in pixels; multiply by the pixel size to get millimetres.";
    const ROUND: &str = "The seed rounds the pixel size to 3 decimals; that costs several pixels here. Keep at least 4 significant digits.";
    Ok(vec![
        Mistake::new("c0", "rows and columns swapped", SWAP, o.r0),
        Mistake::new("r0", "rows and columns swapped", SWAP, o.c0),
        Mistake::new("x_px", "rows and columns swapped", SWAP, c - rows / 2.0),
        Mistake::new("y_px", "y not flipped", FLIP, -o.y_px),
        inches_mistake(i),
        Mistake::new("x_mm", "pixels vs millimetres", PX, o.x_px),
        Mistake::new("y_mm", "pixels vs millimetres", PX, o.y_px),
        Mistake::new("y_mm", "y not flipped", FLIP, -o.y_px * p),
        Mistake::new(
            "x_mm",
            "the seed's rounded pixel size",
            ROUND,
            o.x_px * seed_rounded(p),
        ),
        Mistake::new(
            "y_mm",
            "the seed's rounded pixel size",
            ROUND,
            o.y_px * seed_rounded(p),
        ),
        Mistake::new(
            "x_mm",
            "rows and columns swapped",
            SWAP,
            (c - rows / 2.0) * p,
        ),
    ])
}
