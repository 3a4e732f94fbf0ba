//! Seed 000, Examples 1–3: pixel ↔ image coordinates and the ground sample
//! distance, step by step, with the seed's printed values and why they differ.
//! Each example is one file beside this one; this file keeps what they
//! share: field builders, the centre and pixel-size steps, notes, labels and
//! the practice draws.

mod gsd;
mod photo_to_pixel;
mod pixel_to_photo;

use super::drill::{or_given, BoxDef, Mistake, Rng, Tolerance};
use super::fields::{Field, Inputs};
use super::{Example, Topic};
use crate::coords::Frame;
use crate::error::Result;
use crate::solution::{exact_minus_printed_share, num, NoteKind, Record, Relation, Solution, Step};

const TITLE: &str = "Coordinates";
/// The largest scan resolution accepted (dpi).
const MAX_DPI: f64 = 100_000.0;
/// The largest image side accepted (pixels).
const MAX_SIDE: f64 = 1_000_000.0;
/// How far outside the image a point may lie (pixels or mm).
const MAX_COORD: f64 = 10_000_000.0;

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[
    pixel_to_photo::EXAMPLE,
    gsd::EXAMPLE,
    photo_to_pixel::EXAMPLE,
];

/// The topic: its module (`web/coordinates/`) and title.
pub const TOPIC: Topic = Topic {
    module: "coordinates",
    title: TITLE,
    examples: EXAMPLES,
};

/// What the result keys of the three examples mean.
const LABELS: &[(&str, &str, &str)] = &[
    ("c0", "Centre column c₀", "px"),
    ("r0", "Centre row r₀", "px"),
    ("x_px", "x offset from the centre", "px"),
    ("y_px", "y offset from the centre", "px"),
    ("pixel_size_mm", "Pixel size p", "mm"),
    ("x_mm", "Image coordinate x", "mm"),
    ("y_mm", "Image coordinate y", "mm"),
    ("dc_px", "Column offset Δc", "px"),
    ("dr_px", "Row offset Δr", "px"),
    ("c", "Column c", "px"),
    ("r", "Row r", "px"),
    ("scale_denominator", "Scale number m (1 : m)", ""),
    ("gsd_mm", "Ground sample distance", "mm"),
    ("gsd_cm", "Ground sample distance", "cm"),
];

fn dpi(default: f64) -> Field {
    Field::number("dpi", "Scan resolution", default)
        .unit("dpi")
        .positive(MAX_DPI)
        .help("Dots (pixels) per inch; one inch is 25.4 mm.")
}

fn size(key: &'static str, label: &'static str, default: f64) -> Field {
    Field::integer(key, label, default)
        .range(1.0, MAX_SIDE)
        .help("Image size in pixels.")
}

/// The image's width and height in pixels, with the seed's defaults.
fn frame_fields(columns: f64, rows: f64) -> [Field; 2] {
    [
        size("columns", "Image width (columns)", columns),
        size("rows", "Image height (rows)", rows),
    ]
}

/// The fields of the two conversions: the scan resolution (the seed scans
/// both at 600 dpi), the image size and the point's two coordinates.
fn conversion_fields((columns, rows): (f64, f64), first: Field, second: Field) -> Vec<Field> {
    let [columns, rows] = frame_fields(columns, rows);
    vec![dpi(600.0), columns, rows, first, second]
}

/// A coordinate of the point (it may lie outside the image).
fn coordinate(key: &'static str, label: &'static str, default: f64, unit: &'static str) -> Field {
    Field::number(key, label, default)
        .unit(unit)
        .range(-MAX_COORD, MAX_COORD)
}

/// The image size of the inputs (validated, or drawn by practice).
fn frame(i: &Inputs) -> Result<Frame> {
    Ok(Frame {
        columns: i.number("columns")?,
        rows: i.number("rows")?,
    })
}

fn centre_step(frame: Frame) -> Step {
    let (c0, r0) = frame.centre();
    Step::new(
        "Image centre",
        "The image coordinate system has its origin at the image centre, half the width and half the height from the top-left corner.",
    )
    .relation(
        Relation::new("c_0")
            .key("c0")
            .sym(r"\frac{C}{2}")
            .subst(format!(r"\frac{{{}}}{{2}}", num(frame.columns)))
            .value(c0, ""),
    )
    .relation(
        Relation::new("r_0")
            .key("r0")
            .sym(r"\frac{R}{2}")
            .subst(format!(r"\frac{{{}}}{{2}}", num(frame.rows)))
            .value(r0, ""),
    )
    .value("c0", c0)
    .value("r0", r0)
}

fn pixel_size_step(dpi: f64, p: f64) -> Step {
    Step::new(
        "Pixel size",
        "One inch is 25.4 mm; a scan at this resolution puts this many pixels into one inch.",
    )
    .relation(
        Relation::new("p")
            .key("pixel_size_mm")
            .sym(r"\frac{25.4\ \text{mm}}{\text{dpi}}")
            .subst(format!(r"\frac{{25.4\ \text{{mm}}}}{{{}}}", num(dpi)))
            .value(p, "mm"),
    )
    .value("pixel_size_mm", p)
}

/// The note every pixel-size rounding in the seed needs.
fn pixel_rounding_note(s: &mut Solution, dpi: f64, exact: f64, printed: f64) {
    s.note(
        NoteKind::Rounding,
        format!(
            "The course notes round the pixel size 25.4/{} = {} mm to {} mm ({}) and compute on with the rounded value; every length derived from the pixel size is off by about the same proportion.",
            num(dpi),
            num(exact),
            num(printed),
            exact_minus_printed_share(exact, printed, "mm"),
        ),
    )
    .about(&["pixel_size_mm"]);
}

fn convention_note(s: &mut Solution) {
    s.note(
        NoteKind::Convention,
        "Pixel coordinates are taken as continuous with the origin at the top-left corner of the image, so the centre is (C/2, R/2), as the course notes do. If whole numbers counted pixel centres from 0, the centre would be ((C−1)/2, (R−1)/2), half a pixel away.",
    )
    .about(&["c0", "r0"]);
}

fn outside_note(c: f64, r: f64, frame: Frame) -> String {
    format!(
        "The point (c, r) = ({}, {}) lies outside the {} × {} pixel image; the coordinates are computed all the same.",
        num(c),
        num(r),
        num(frame.columns),
        num(frame.rows)
    )
}

// ---------------------------------------------------------------------------
// Practice: what the three examples' drills share.

/// Scan resolutions whose pixel size 25.4/dpi, rounded to 3 decimals as the
/// seed does, is off by more than the tolerance (so that mistake can be told).
const DPIS: [i64; 10] = [300, 400, 600, 800, 900, 1000, 1200, 1500, 1800, 2400];
/// Pixel sizes are graded to 0.1 %.
const PIXEL_SIZE: Tolerance = Tolerance::rel(0.001);

/// A drawn input (NaN when missing: the audit then finds it).
fn n(inputs: &Record, key: &str) -> f64 {
    inputs.number(key).unwrap_or(f64::NAN)
}

/// The seed's habit: the pixel size rounded to 3 decimals.
fn seed_rounded(p: f64) -> f64 {
    (p * 1000.0).round() / 1000.0
}

/// An image size (even, so the centre is a whole pixel) and a different
/// second size, so swapping rows and columns shows.
fn sizes(rng: &mut Rng) -> (f64, f64) {
    let columns = 2 * rng.int(400, 1500);
    let delta = 2 * rng.int(50, 300) * if rng.coin() { 1 } else { -1 };
    let rows = (columns + delta).max(400);
    let rows = if rows == columns { columns + 200 } else { rows };
    (columns as f64, rows as f64)
}

/// A drawn scan of the two conversions: the inputs `dpi`, `columns` and
/// `rows`, and the three numbers.
fn draw_scan(rng: &mut Rng) -> (Record, f64, f64, f64) {
    let dpi = rng.pick(&DPIS) as f64;
    let (columns, rows) = sizes(rng);
    let inputs = Record::new()
        .with("dpi", dpi)
        .with("columns", columns)
        .with("rows", rows);
    (inputs, dpi, columns, rows)
}

/// The image centre `(c₀, r₀)`, each as the student gave it where given
/// (the first boxes of both conversions' chains).
fn centre_or_given(i: &Record, g: &Record) -> Result<(f64, f64)> {
    let (c0, r0) = frame(&Inputs(i))?.centre();
    Ok((or_given(g, "c0", c0), or_given(g, "r0", r0)))
}

/// The swap of rows and columns, in the words of the boxes that show it.
const SWAP: &str =
    "The image is columns wide and rows high: c₀ is half the columns, r₀ half the rows.";
/// The pixel size's box, the same in every example.
fn pixel_size_box() -> BoxDef {
    BoxDef::new("pixel_size_mm", "Pixel size", Some("mm"), PIXEL_SIZE)
        .nudge("One inch is 25.4 mm, and it holds dpi pixels.")
}
/// Forgetting the 25.4 mm of an inch.
fn inches_mistake(inputs: &Record) -> Mistake {
    Mistake::new(
        "pixel_size_mm",
        "inches not converted",
        "25.4/dpi gives millimetres; 1/dpi gives inches.",
        1.0 / n(inputs, "dpi"),
    )
}
