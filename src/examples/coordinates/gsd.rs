//! Seed 000, Example 2: the ground sample distance of a scanned photo, and
//! its practice.

use super::super::drill::{drill, or_given, BoxDef, Drill, Mistake, Rng, Tolerance};
use super::super::fields::{is_seed, Field, Inputs};
use super::super::Example;
use super::*;
use crate::coords;
use crate::error::Result;
use crate::solution::{
    exact_minus_printed, exact_minus_printed_share, num, with_unit, Record, Relation, Solution,
    Step,
};

pub const EXAMPLE: Example = Example {
    id: "gsd",
    title: "Ground sample distance",
    source: "Worked examples, Example 2",
    summary: "The ground size of one scanned pixel, from the scan resolution, focal length and flying height.",
    fields,
    solve,
    answer: &["gsd_cm"],
    labels: LABELS,
    lab: None,
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

fn fields() -> Vec<Field> {
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

fn solve(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let (dpi, f, h) = (
        i.number("dpi")?,
        i.number("focal_length_mm")?,
        i.number("flying_height_m")?,
    );
    let g = coords::gsd(dpi, f, h)?;
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    s.step(
        Step::new(
            "Photo scale",
            "The scale of a vertical photo over flat ground is the focal length over the flying height, both in the same unit (f in metres here).",
        )
        .relation(
            Relation::new(r"\frac{1}{m}")
                .key("scale_denominator")
                .sym(r"\frac{f}{H}")
                .subst(format!(
                    r"\frac{{{}\ \text{{mm}} / 1000}}{{{}\ \text{{m}}}}",
                    num(f),
                    num(h)
                ))
                .result(format!(r"\frac{{1}}{{{}}}", num(g.scale_denominator))),
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
        .relation(
            Relation::new(r"\text{GSD}")
                .key("gsd_mm")
                .sym(r"p \cdot m")
                .subst(format!(
                    r"{} \times {}",
                    num(g.pixel_size_mm),
                    num(g.scale_denominator)
                ))
                .value(g.gsd_mm, "mm"),
        )
        .relation(
            Relation::new(r"\text{GSD}")
                .key("gsd_cm")
                .subst(format!(
                    r"\frac{{{}}}{{10}}",
                    with_unit(&num(g.gsd_mm), "mm")
                ))
                .value(gsd_cm, "cm"),
        )
        .value("gsd_mm", g.gsd_mm)
        .value("gsd_cm", gsd_cm),
    );
    s.result = Record::new()
        .with("scale_denominator", g.scale_denominator)
        .with("pixel_size_mm", g.pixel_size_mm)
        .with("gsd_mm", g.gsd_mm)
        .with("gsd_cm", gsd_cm);
    if is_seed(&fields(), inputs) {
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

// ---------------------------------------------------------------------------
// Practice

fn generate(rng: &mut Rng) -> Record {
    Record::new()
        .with("dpi", rng.pick(&DPIS) as f64)
        .with(
            "focal_length_mm",
            rng.pick(&[88, 152, 153, 210, 305]) as f64,
        )
        .with("flying_height_m", rng.num(5, 60) * 100.0)
}

fn boxes(_: &Record) -> Vec<BoxDef> {
    let rel = Tolerance::rel(0.002);
    vec![
        BoxDef::new(
            "scale_denominator",
            "Scale number m",
            None,
            Tolerance::rel(0.001),
        )
        .nudge("Scale = f / H, with both lengths in the same unit."),
        pixel_size_box(),
        BoxDef::new("gsd_mm", "Ground sample distance in mm", Some("mm"), rel).nudge(
            "One pixel on the photo covers the pixel size times the scale number on the ground.",
        ),
        BoxDef::new("gsd_cm", "Ground sample distance in cm", Some("cm"), rel)
            .nudge("The same length in centimetres."),
    ]
}

/// The boxes from the student's earlier answers: the exact stages of
/// [`coords::gsd`], each replaced by what was given.
fn chain(i: &Record, g: &Record) -> Result<Record> {
    let exact = coords::gsd(
        n(i, "dpi"),
        n(i, "focal_length_mm"),
        n(i, "flying_height_m"),
    )?;
    let m = or_given(g, "scale_denominator", exact.scale_denominator);
    let p = or_given(g, "pixel_size_mm", exact.pixel_size_mm);
    let mm = or_given(g, "gsd_mm", p * m);
    Ok(Record::new()
        .with("scale_denominator", m)
        .with("pixel_size_mm", p)
        .with("gsd_mm", mm)
        .with("gsd_cm", mm / 10.0))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let g = coords::gsd(
        n(i, "dpi"),
        n(i, "focal_length_mm"),
        n(i, "flying_height_m"),
    )?;
    let (m, p) = (g.scale_denominator, g.pixel_size_mm);
    const ROUND: &str =
        "The seed rounds the pixel size to 3 decimals; keep at least 4 significant digits.";
    Ok(vec![
        Mistake::new(
            "scale_denominator",
            "millimetres vs metres",
            "H is in metres and f in millimetres: turn f into metres first.",
            n(i, "flying_height_m") / n(i, "focal_length_mm"),
        ),
        inches_mistake(i),
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
            g.gsd_mm,
        ),
    ])
}
