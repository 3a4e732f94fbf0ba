//! Seed 000, Examples 1–3: pixel ↔ image coordinates and the ground sample
//! distance, step by step, with the seed's printed values and why they differ.

use super::fields::{is_seed, Field, Inputs};
use super::{Example, Topic};
use crate::coords::{self, Frame};
use crate::error::Result;
use crate::solution::{
    exact_minus_printed, exact_minus_printed_share, num, tex, NoteKind, Record, Solution, Step,
};

const TITLE: &str = "Coordinates";
/// The largest scan resolution accepted (dpi).
const MAX_DPI: f64 = 100_000.0;
/// The largest image side accepted (pixels).
const MAX_SIDE: f64 = 1_000_000.0;
/// How far outside the image a point may lie (pixels or mm).
const MAX_COORD: f64 = 10_000_000.0;

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[
        Example {
            id: "pixel-to-photo",
            title: "Pixel to image coordinates",
            source: "Worked examples, Example 1",
            summary: "From a pixel's column and row to its image coordinates in mm, relative to the image centre.",
            fields: pixel_to_photo_fields,
            solve: pixel_to_photo,
            answer: &["x_mm", "y_mm"],
            labels: &[],
            lab: None,
            practice: None,
        },
        Example {
            id: "gsd",
            title: "Ground sample distance",
            source: "Worked examples, Example 2",
            summary: "The ground size of one scanned pixel, from the scan resolution, focal length and flying height.",
            fields: gsd_fields,
            solve: gsd,
            answer: &["gsd_cm"],
            labels: &[],
            lab: None,
            practice: None,
        },
        Example {
            id: "photo-to-pixel",
            title: "Image to pixel coordinates",
            source: "Worked examples, Example 3",
            summary: "From image coordinates in mm to the pixel's column and row.",
            fields: photo_to_pixel_fields,
            solve: photo_to_pixel,
            answer: &["c", "r"],
            labels: &[],
            lab: None,
            practice: None,
        },
];

/// The topic: its module (`web/coordinates/`) and title.
pub const TOPIC: Topic = Topic {
    module: "coordinates",
    title: TITLE,
    examples: EXAMPLES,
};

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

fn pixel_to_photo_fields() -> Vec<Field> {
    vec![
        dpi(600.0),
        size("columns", "Image width (columns)", 1600.0),
        size("rows", "Image height (rows)", 1400.0),
        Field::number("c", "Column c of the point", 995.0)
            .unit("px")
            .range(-MAX_COORD, MAX_COORD)
            .help("Pixel column, counted to the right from the left edge."),
        Field::number("r", "Row r of the point", 480.0)
            .unit("px")
            .range(-MAX_COORD, MAX_COORD)
            .help("Pixel row, counted downward from the top edge."),
    ]
}

fn gsd_fields() -> Vec<Field> {
    vec![
        dpi(900.0),
        Field::number("focal_length_mm", "Focal length f", 152.0)
            .unit("mm")
            .positive(10_000.0)
            .help("Camera focal length."),
        Field::number("flying_height_m", "Flying height H", 1920.0)
            .unit("m")
            .positive(1_000_000.0)
            .help("Height of the camera above the ground."),
    ]
}

fn photo_to_pixel_fields() -> Vec<Field> {
    vec![
        dpi(600.0),
        size("columns", "Image width (columns)", 1800.0),
        size("rows", "Image height (rows)", 1500.0),
        Field::number("x_mm", "Image coordinate x", -12.42)
            .unit("mm")
            .range(-MAX_COORD, MAX_COORD)
            .help("To the right of the image centre."),
        Field::number("y_mm", "Image coordinate y", -25.36)
            .unit("mm")
            .range(-MAX_COORD, MAX_COORD)
            .help("Up from the image centre."),
    ]
}

/// Labels of the result keys shared by the three examples.
fn label_results(s: &mut Solution) {
    s.label_present(&[
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
    ]);
}

fn centre_step(frame: Frame) -> Step {
    let (c0, r0) = frame.centre();
    Step::new(
        "Image centre",
        "The image coordinate system has its origin at the image centre, half the width and half the height from the top-left corner.",
    )
    .formula(
        r"c_0 = \frac{C}{2},\quad r_0 = \frac{R}{2}",
        format!(
            r"c_0 = \frac{{{}}}{{2}} = {},\quad r_0 = \frac{{{}}}{{2}} = {}",
            num(frame.columns),
            num(c0),
            num(frame.rows),
            num(r0)
        ),
    )
    .value("c0", c0)
    .value("r0", r0)
}

fn pixel_size_step(dpi: f64, p: f64) -> Step {
    Step::new(
        "Pixel size",
        "One inch is 25.4 mm; a scan at this resolution puts this many pixels into one inch.",
    )
    .formula(
        r"p = \frac{25.4\ \text{mm}}{\text{dpi}}",
        format!(
            r"p = \frac{{25.4\ \text{{mm}}}}{{{}}} = {}\ \text{{mm}}",
            num(dpi),
            num(p)
        ),
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

fn pixel_to_photo(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let (dpi, c, r) = (i.number("dpi")?, i.number("c")?, i.number("r")?);
    let frame = Frame {
        columns: i.number("columns")?,
        rows: i.number("rows")?,
    };
    let o = coords::pixel_to_image(dpi, frame, c, r)?;
    let mut s = Solution::new(
        "pixel-to-photo",
        "Pixel to image coordinates",
        inputs.clone(),
    );
    s.step(centre_step(frame));
    s.step(
        Step::new(
            "Offsets from the centre in pixels",
            "x counts to the right like c; y counts upward, against r, hence the minus sign.",
        )
        .formula(
            r"x_p = c - c_0,\quad y_p = -(r - r_0)",
            format!(
                r"x_p = {} - {} = {}\ \text{{px}},\quad y_p = -({} - {}) = {}\ \text{{px}}",
                num(c),
                num(o.c0),
                num(o.x_px),
                num(r),
                num(o.r0),
                num(o.y_px)
            ),
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
        .formula(
            r"x = x_p \cdot p,\quad y = y_p \cdot p",
            format!(
                r"x = {} \times {} = {}\ \text{{mm}},\quad y = {} \times {} = {}\ \text{{mm}}",
                tex(o.x_px),
                num(o.pixel_size_mm),
                num(o.x_mm),
                tex(o.y_px),
                num(o.pixel_size_mm),
                num(o.y_mm)
            ),
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
    label_results(&mut s);
    convention_note(&mut s);
    if !o.inside {
        s.note(NoteKind::Warning, outside_note(c, r, frame))
            .about(&["x_mm", "y_mm"]);
    }
    if is_seed(&pixel_to_photo_fields(), inputs) {
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
                crate::solution::fmt_sig((o.x_mm - x) / o.pixel_size_mm, 2),
                crate::solution::fmt_sig((o.y_mm - y) / o.pixel_size_mm, 2),
            ),
        )
        .about(&["x_mm", "y_mm"]);
    }
    Ok(s)
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

fn gsd(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let (dpi, f, h) = (
        i.number("dpi")?,
        i.number("focal_length_mm")?,
        i.number("flying_height_m")?,
    );
    let g = coords::gsd(dpi, f, h)?;
    let mut s = Solution::new("gsd", "Ground sample distance", inputs.clone());
    s.step(
        Step::new(
            "Photo scale",
            "The scale of a vertical photo over flat ground is the focal length over the flying height, both in the same unit (f in metres here).",
        )
        .formula(
            r"\frac{1}{m} = \frac{f}{H}",
            format!(
                r"\frac{{1}}{{m}} = \frac{{{}\ \text{{mm}} / 1000}}{{{}\ \text{{m}}}} = \frac{{1}}{{{}}}",
                num(f),
                num(h),
                num(g.scale_denominator)
            ),
        )
        .value("scale_denominator", g.scale_denominator),
    );
    s.step(pixel_size_step(dpi, g.pixel_size_mm));
    let gsd_cm = g.gsd_mm / 10.0;
    s.step(
        Step::new(
            "Ground sample distance",
            "One pixel on the photo covers the pixel size times the scale number on the ground.",
        )
        .formula(
            r"\text{GSD} = p \cdot m",
            format!(
                r"\text{{GSD}} = {} \times {} = {}\ \text{{mm}} = {}\ \text{{cm}}",
                num(g.pixel_size_mm),
                num(g.scale_denominator),
                num(g.gsd_mm),
                num(gsd_cm)
            ),
        )
        .value("gsd_mm", g.gsd_mm)
        .value("gsd_cm", gsd_cm),
    );
    s.result = Record::new()
        .with("scale_denominator", g.scale_denominator)
        .with("pixel_size_mm", g.pixel_size_mm)
        .with("gsd_mm", g.gsd_mm)
        .with("gsd_cm", gsd_cm);
    label_results(&mut s);
    if is_seed(&gsd_fields(), inputs) {
        let (m, p, mm, cm) = (12632.0, 0.028, 353.7, 35.37);
        s.textbook = Some(
            Record::new()
                .with("scale_denominator", m)
                .with("pixel_size_mm", p)
                .with("gsd_mm", mm)
                .with("gsd_cm", cm),
        );
        s.note(
            NoteKind::Rounding,
            format!(
                "The course notes round the scale number 1920/0.152 = {} to {m} ({}): harmless on its own.",
                num(g.scale_denominator),
                exact_minus_printed_share(g.scale_denominator, m, ""),
            ),
        )
        .about(&["scale_denominator"]);
        pixel_rounding_note(&mut s, dpi, g.pixel_size_mm, p);
        s.note(
            NoteKind::Rounding,
            format!(
                "With both rounded values the course notes get 0.028 × 12632 = {} mm ≈ {mm} mm = {cm} cm instead of the exact {} mm = {} cm ({}; {}), almost all of it from the pixel size.",
                num(p * m),
                num(g.gsd_mm),
                num(gsd_cm),
                exact_minus_printed_share(g.gsd_mm, mm, "mm"),
                exact_minus_printed(gsd_cm, cm, "cm"),
            ),
        )
        .about(&["gsd_mm", "gsd_cm"]);
    }
    Ok(s)
}

fn photo_to_pixel(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let (dpi, x, y) = (i.number("dpi")?, i.number("x_mm")?, i.number("y_mm")?);
    let frame = Frame {
        columns: i.number("columns")?,
        rows: i.number("rows")?,
    };
    let o = coords::image_to_pixel(dpi, frame, x, y)?;
    let mut s = Solution::new(
        "photo-to-pixel",
        "Image to pixel coordinates",
        inputs.clone(),
    );
    s.step(centre_step(frame));
    s.step(pixel_size_step(dpi, o.pixel_size_mm));
    s.step(
        Step::new(
            "Offsets from the centre in pixels",
            "Divide by the pixel size. Columns count to the right like x; rows count downward, against y, so the row offset is −y/p.",
        )
        .formula(
            r"\Delta c = \frac{x}{p},\quad \Delta r = -\frac{y}{p}",
            format!(
                r"\Delta c = \frac{{{}}}{{{}}} = {}\ \text{{px}},\quad \Delta r = -\frac{{{}}}{{{}}} = {}\ \text{{px}}",
                num(x),
                num(o.pixel_size_mm),
                num(o.dc_px),
                num(y),
                num(o.pixel_size_mm),
                num(o.dr_px)
            ),
        )
        .value("dc_px", o.dc_px)
        .value("dr_px", o.dr_px),
    );
    s.step(
        Step::new("Pixel coordinates", "Add the offsets to the centre.")
            .formula(
                r"c = c_0 + \Delta c,\quad r = r_0 + \Delta r",
                format!(
                    r"c = {} + {} = {},\quad r = {} + {} = {}",
                    num(o.c0),
                    tex(o.dc_px),
                    num(o.c),
                    num(o.r0),
                    tex(o.dr_px),
                    num(o.r)
                ),
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
    label_results(&mut s);
    convention_note(&mut s);
    if !o.inside {
        s.note(NoteKind::Warning, outside_note(o.c, o.r, frame))
            .about(&["c", "r"]);
    }
    if is_seed(&photo_to_pixel_fields(), inputs) {
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
