//! Practice for seed 000, Examples 1–3: pixel ↔ image coordinates and the
//! ground sample distance.

use super::grade::tol;
use super::{or_given, BoxDef, Mistake, Rng, Spec, Tolerance};
use crate::error::Result;
use crate::solution::Record;

/// Scan resolutions whose pixel size 25.4/dpi, rounded to 3 decimals as the
/// seed does, is off by more than the tolerance (so that mistake can be told).
const DPIS: [i64; 10] = [300, 400, 600, 800, 900, 1000, 1200, 1500, 1800, 2400];
/// Pixel sizes are graded to 0.1 %.
const PIXEL_SIZE: Tolerance = Tolerance::rel(0.001);
/// Pixel offsets from millimetres: 0.05 px plus 0.02 %.
const OFFSET: Tolerance = Tolerance {
    atol: 0.05,
    rtol: 0.0002,
};

pub fn specs() -> Vec<Spec> {
    vec![
        Spec {
            id: "pixel-to-photo",
            generate: gen_pixel_to_photo,
            boxes: boxes_pixel_to_photo,
            chain: Some(chain_pixel_to_photo),
            mistakes: mistakes_pixel_to_photo,
        },
        Spec {
            id: "gsd",
            generate: gen_gsd,
            boxes: boxes_gsd,
            chain: Some(chain_gsd),
            mistakes: mistakes_gsd,
        },
        Spec {
            id: "photo-to-pixel",
            generate: gen_photo_to_pixel,
            boxes: boxes_photo_to_pixel,
            chain: Some(chain_photo_to_pixel),
            mistakes: mistakes_photo_to_pixel,
        },
    ]
}

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

/// An offset from the centre: never 0, so a sign error shows.
fn offset(rng: &mut Rng, half: f64) -> f64 {
    let k = rng.int(1, (half as i64 * 9 / 10).max(2));
    if rng.coin() {
        k as f64
    } else {
        -(k as f64)
    }
}

fn gen_pixel_to_photo(rng: &mut Rng) -> Record {
    let dpi = rng.pick(&DPIS) as f64;
    let (columns, rows) = sizes(rng);
    let c = columns / 2.0 + offset(rng, columns / 2.0);
    let mut r = rows / 2.0 + offset(rng, rows / 2.0);
    // Keep the two offsets apart so each box has one answer.
    if (r - rows / 2.0).abs() == (c - columns / 2.0).abs() {
        r += 1.0;
    }
    Record::new()
        .with("dpi", dpi)
        .with("columns", columns)
        .with("rows", rows)
        .with("c", c)
        .with("r", r)
}

fn boxes_pixel_to_photo(_: &Record) -> Vec<BoxDef> {
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
        BoxDef::new("pixel_size_mm", "Pixel size", Some("mm"), PIXEL_SIZE)
            .nudge("One inch is 25.4 mm, and it holds dpi pixels."),
        BoxDef::new("x_mm", "Image coordinate x", Some("mm"), tol::LENGTH)
            .nudge("Pixels times the pixel size.")
            .axis(),
        BoxDef::new("y_mm", "Image coordinate y", Some("mm"), tol::LENGTH)
            .nudge("Pixels times the pixel size, with y's sign.")
            .axis(),
    ]
}

fn chain_pixel_to_photo(i: &Record, g: &Record) -> Result<Record> {
    let c0 = or_given(g, "c0", n(i, "columns") / 2.0);
    let r0 = or_given(g, "r0", n(i, "rows") / 2.0);
    let x_px = or_given(g, "x_px", n(i, "c") - c0);
    let y_px = or_given(g, "y_px", -(n(i, "r") - r0));
    let p = or_given(g, "pixel_size_mm", 25.4 / n(i, "dpi"));
    Ok(Record::new()
        .with("c0", c0)
        .with("r0", r0)
        .with("x_px", x_px)
        .with("y_px", y_px)
        .with("pixel_size_mm", p)
        .with("x_mm", x_px * p)
        .with("y_mm", y_px * p))
}

fn mistakes_pixel_to_photo(i: &Record) -> Result<Vec<Mistake>> {
    let (columns, rows, c, r) = (n(i, "columns"), n(i, "rows"), n(i, "c"), n(i, "r"));
    let p = 25.4 / n(i, "dpi");
    let (x_px, y_px) = (c - columns / 2.0, rows / 2.0 - r);
    const SWAP: &str =
        "The image is columns wide and rows high: c₀ is half the columns, r₀ half the rows.";
    const FLIP: &str = "r counts down, y counts up: y = −(r − r₀).";
    const PX: &str = "That is the offset in pixels; multiply by the pixel size to get millimetres.";
    const ROUND: &str = "The seed rounds the pixel size to 3 decimals; that costs several pixels here. Keep at least 4 significant digits.";
    Ok(vec![
        Mistake::new("c0", "rows and columns swapped", SWAP, rows / 2.0),
        Mistake::new("r0", "rows and columns swapped", SWAP, columns / 2.0),
        Mistake::new("x_px", "rows and columns swapped", SWAP, c - rows / 2.0),
        Mistake::new("y_px", "y not flipped", FLIP, -y_px),
        Mistake::new(
            "pixel_size_mm",
            "inches not converted",
            "25.4/dpi gives millimetres; 1/dpi gives inches.",
            1.0 / n(i, "dpi"),
        ),
        Mistake::new("x_mm", "pixels vs millimetres", PX, x_px),
        Mistake::new("y_mm", "pixels vs millimetres", PX, y_px),
        Mistake::new("y_mm", "y not flipped", FLIP, -y_px * p),
        Mistake::new(
            "x_mm",
            "the seed's rounded pixel size",
            ROUND,
            x_px * seed_rounded(p),
        ),
        Mistake::new(
            "y_mm",
            "the seed's rounded pixel size",
            ROUND,
            y_px * seed_rounded(p),
        ),
        Mistake::new(
            "x_mm",
            "rows and columns swapped",
            SWAP,
            (c - rows / 2.0) * p,
        ),
    ])
}

fn gen_gsd(rng: &mut Rng) -> Record {
    Record::new()
        .with("dpi", rng.pick(&DPIS) as f64)
        .with(
            "focal_length_mm",
            rng.pick(&[88, 152, 153, 210, 305]) as f64,
        )
        .with("flying_height_m", rng.num(5, 60) * 100.0)
}

fn boxes_gsd(_: &Record) -> Vec<BoxDef> {
    let rel = Tolerance::rel(0.002);
    vec![
        BoxDef::new(
            "scale_denominator",
            "Scale number m",
            None,
            Tolerance::rel(0.001),
        )
        .nudge("Scale = f / H, with both lengths in the same unit."),
        BoxDef::new("pixel_size_mm", "Pixel size", Some("mm"), PIXEL_SIZE)
            .nudge("One inch is 25.4 mm, and it holds dpi pixels."),
        BoxDef::new("gsd_mm", "Ground sample distance in mm", Some("mm"), rel).nudge(
            "One pixel on the photo covers the pixel size times the scale number on the ground.",
        ),
        BoxDef::new("gsd_cm", "Ground sample distance in cm", Some("cm"), rel)
            .nudge("The same length in centimetres."),
    ]
}

fn chain_gsd(i: &Record, g: &Record) -> Result<Record> {
    let m = or_given(
        g,
        "scale_denominator",
        n(i, "flying_height_m") / (n(i, "focal_length_mm") / 1000.0),
    );
    let p = or_given(g, "pixel_size_mm", 25.4 / n(i, "dpi"));
    let mm = or_given(g, "gsd_mm", p * m);
    Ok(Record::new()
        .with("scale_denominator", m)
        .with("pixel_size_mm", p)
        .with("gsd_mm", mm)
        .with("gsd_cm", mm / 10.0))
}

fn mistakes_gsd(i: &Record) -> Result<Vec<Mistake>> {
    let m = n(i, "flying_height_m") / (n(i, "focal_length_mm") / 1000.0);
    let p = 25.4 / n(i, "dpi");
    const ROUND: &str =
        "The seed rounds the pixel size to 3 decimals; keep at least 4 significant digits.";
    Ok(vec![
        Mistake::new(
            "scale_denominator",
            "millimetres vs metres",
            "H is in metres and f in millimetres: turn f into metres first.",
            n(i, "flying_height_m") / n(i, "focal_length_mm"),
        ),
        Mistake::new(
            "pixel_size_mm",
            "inches not converted",
            "25.4/dpi gives millimetres; 1/dpi gives inches.",
            1.0 / n(i, "dpi"),
        ),
        Mistake::new(
            "gsd_mm",
            "the seed's rounded pixel size",
            ROUND,
            seed_rounded(p) * m,
        ),
        Mistake::new(
            "gsd_cm",
            "the seed's rounded pixel size",
            ROUND,
            seed_rounded(p) * m / 10.0,
        ),
        Mistake::new(
            "gsd_cm",
            "millimetres vs centimetres",
            "That is the value in millimetres; 10 mm make 1 cm.",
            p * m,
        ),
    ])
}

fn gen_photo_to_pixel(rng: &mut Rng) -> Record {
    let dpi = rng.pick(&DPIS) as f64;
    let (columns, rows) = sizes(rng);
    let p = 25.4 / dpi;
    // x, y in mm with 2 decimals, inside 90 % of the image half-size.
    let coord = |rng: &mut Rng, half_px: f64| {
        let lim = (half_px * p * 0.9 * 100.0) as i64;
        let k = rng.int(100, lim.max(101));
        (if rng.coin() { k } else { -k }) as f64 / 100.0
    };
    let x = coord(rng, columns / 2.0);
    let y = coord(rng, rows / 2.0);
    Record::new()
        .with("dpi", dpi)
        .with("columns", columns)
        .with("rows", rows)
        .with("x_mm", x)
        .with("y_mm", y)
}

fn boxes_photo_to_pixel(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("c0", "Centre column c₀", Some("px"), tol::PIXEL)
            .nudge("The image centre: half the width in columns."),
        BoxDef::new("r0", "Centre row r₀", Some("px"), tol::PIXEL)
            .nudge("Half the height in rows."),
        BoxDef::new("pixel_size_mm", "Pixel size", Some("mm"), PIXEL_SIZE)
            .nudge("One inch is 25.4 mm, and it holds dpi pixels."),
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

fn chain_photo_to_pixel(i: &Record, g: &Record) -> Result<Record> {
    let c0 = or_given(g, "c0", n(i, "columns") / 2.0);
    let r0 = or_given(g, "r0", n(i, "rows") / 2.0);
    let p = or_given(g, "pixel_size_mm", 25.4 / n(i, "dpi"));
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

fn mistakes_photo_to_pixel(i: &Record) -> Result<Vec<Mistake>> {
    let (columns, rows, x, y) = (n(i, "columns"), n(i, "rows"), n(i, "x_mm"), n(i, "y_mm"));
    let p = 25.4 / n(i, "dpi");
    const SWAP: &str =
        "The image is columns wide and rows high: c₀ is half the columns, r₀ half the rows.";
    const FLIP: &str = "y counts up, r counts down: Δr = −y / pixel size.";
    const TIMES: &str = "Millimetres divided by the pixel size give pixels, not multiplied.";
    const ROUND: &str = "The seed rounds the pixel size to 3 decimals; that costs pixels here.";
    Ok(vec![
        Mistake::new("c0", "rows and columns swapped", SWAP, rows / 2.0),
        Mistake::new("r0", "rows and columns swapped", SWAP, columns / 2.0),
        Mistake::new("dc_px", "pixels vs millimetres", TIMES, x * p),
        Mistake::new("dr_px", "y not flipped", FLIP, y / p),
        Mistake::new("r", "y not flipped", FLIP, rows / 2.0 + y / p),
        Mistake::new("c", "rows and columns swapped", SWAP, rows / 2.0 + x / p),
        Mistake::new(
            "c",
            "the seed's rounded pixel size",
            ROUND,
            columns / 2.0 + x / seed_rounded(p),
        ),
        Mistake::new(
            "r",
            "the seed's rounded pixel size",
            ROUND,
            rows / 2.0 - y / seed_rounded(p),
        ),
    ])
}
