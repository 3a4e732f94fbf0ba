//! Seed 000, boundary descriptors: diameter, major and minor axis, basic
//! rectangle and eccentricity of the outer boundary of a drawn region.

use super::*;
use crate::examples::drill::{drill, or_given, value_in, BoxDef, Drill, Mistake, Rng, Tolerance};
use crate::examples::Lab;

pub const EXAMPLE: Example = Example {
    id: "boundary-shape",
    title: "Boundary descriptors",
    source: "Worked examples, boundary descriptors",
    summary: "Diameter, major and minor axis, basic rectangle and eccentricity of the outer boundary of a drawn region.",
    fields,
    solve,
    answer: &["diameter", "minor_axis_length", "eccentricity"],
    labels: LABELS,
    lab: Some(Lab::new("boundaries", &[])),
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

/// The default region of `boundary-shape`: a tilted, filled ellipse.
const BLOB: [Pixel; 55] = [
    [7, 1],
    [8, 1],
    [9, 1],
    [10, 1],
    [11, 1],
    [12, 1],
    [5, 2],
    [6, 2],
    [7, 2],
    [8, 2],
    [9, 2],
    [10, 2],
    [11, 2],
    [12, 2],
    [4, 3],
    [5, 3],
    [6, 3],
    [7, 3],
    [8, 3],
    [9, 3],
    [10, 3],
    [11, 3],
    [12, 3],
    [3, 4],
    [4, 4],
    [5, 4],
    [6, 4],
    [7, 4],
    [8, 4],
    [9, 4],
    [10, 4],
    [11, 4],
    [2, 5],
    [3, 5],
    [4, 5],
    [5, 5],
    [6, 5],
    [7, 5],
    [8, 5],
    [9, 5],
    [10, 5],
    [2, 6],
    [3, 6],
    [4, 6],
    [5, 6],
    [6, 6],
    [7, 6],
    [8, 6],
    [9, 6],
    [2, 7],
    [3, 7],
    [4, 7],
    [5, 7],
    [6, 7],
    [7, 7],
];

fn fields() -> Vec<Field> {
    vec![
        pixels_field(
            &BLOB,
            "Pixels of a region or of a closed boundary, any order, one [c, r] per row. The outer boundary of the region of the top-most, left-most pixel is traced and described.",
        ),
        connectivity_field(),
    ]
}

fn solve(inputs: &Record) -> Result<Solution> {
    let conn = connectivity(inputs)?;
    let mut probe = inputs.clone();
    probe.set("given", "region");
    let e = edge(&probe, conn, false)?;
    let b = &e.path.pixels;
    let sh = chain::shape("pixels", b)?;
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    s.step(edge_step(&e, conn, &probe)?);
    let [a, z] = sh.major_axis;
    s.step(
        Step::new(
            "Diameter",
            "The largest distance between two boundary pixels (between pixel centres); the first such pair along the boundary is taken.",
        )
        .relation(
            Relation::new("D")
                .key("diameter")
                .sym(r"\max_{i,j} \sqrt{(c_i - c_j)^2 + (r_i - r_j)^2}")
                .subst(format!(
                    r"\sqrt{{({} - {})^2 + ({} - {})^2}}",
                    z[0],
                    tex(a[0] as f64),
                    z[1],
                    tex(a[1] as f64)
                ))
                .value(sh.diameter, ""),
        )
        .value("diameter", sh.diameter),
    );
    let u = sh.axis_direction;
    s.step(
        Step::new(
            "Major axis",
            "The segment between the two farthest pixels; its direction u is the unit vector from one end to the other.",
        )
        .relation(Relation::new("p_a").key("major_axis").result(pixel_tex(a)))
        .relation(Relation::new("p_b").result(pixel_tex(z)))
        .relation(
            Relation::new("u")
                .key("direction")
                .sym(r"\frac{p_b - p_a}{D}")
                .result(format!(r"({},\ {})", num(u[0]), num(u[1]))),
        )
        .value("major_axis", pixel_value(&sh.major_axis))
        .value("direction", point_value(u)),
    );
    s.step(
        Step::new(
            "Minor axis",
            "Perpendicular to the major axis (direction v), as long as the boundary is wide across it: the offsets t of all boundary pixels along v, from the major axis, span the minor axis. It is drawn through the middle of the basic rectangle.",
        )
        .relation(Relation::new("v").sym(r"(-u_r,\ u_c)"))
        .relation(Relation::new("t_i").sym(r"(p_i - p_a)\cdot v"))
        .relation(Relation::new(r"t_{\min}").value(sh.across[0], ""))
        .relation(Relation::new(r"t_{\max}").value(sh.across[1], ""))
        .relation(
            Relation::new("m")
                .key("minor_axis_length")
                .sym(r"t_{\max} - t_{\min}")
                .subst(format!("{} - {}", num(sh.across[1]), tex(sh.across[0])))
                .value(sh.minor_axis_length, ""),
        )
        .value("minor_axis_length", sh.minor_axis_length)
        .value(
            "minor_axis",
            Value::List(sh.minor_axis.iter().map(|p| point_value(*p)).collect()),
        ),
    );
    let rect = Value::List(sh.basic_rectangle.iter().map(|p| point_value(*p)).collect());
    s.step(
        Step::new(
            "Basic rectangle",
            "The box with sides along the two axes that just encloses the boundary: from one end of the major axis to the other, and from the smallest to the largest distance across it.",
        )
        .relation(Relation::new(Form::default()).sym(r"p_a + s\,u + t\,v"))
        .relation(Relation::new("s").op(r"\in").sym(r"\{0, D\}"))
        .relation(Relation::new("t").op(r"\in").sym(r"\{t_{\min}, t_{\max}\}"))
        .relation(
            Relation::new(Form::default())
                .key("basic_rectangle")
                .result(list_form(
                    &sh.basic_rectangle,
                    |p| format!(r"({},\ {})", num(p[0]), num(p[1])),
                    r"\;",
                )),
        )
        .value("basic_rectangle", rect.clone()),
    );
    let ecc_step = Step::new(
        "Eccentricity",
        "The ratio of the major axis to the minor axis.",
    );
    let eccentricity = Relation::new("E").key("eccentricity").sym(r"\frac{D}{m}");
    s.step(match sh.eccentricity {
        Some(x) => ecc_step
            .relation(
                eccentricity
                    .subst(format!(
                        r"\frac{{{}}}{{{}}}",
                        num(sh.diameter),
                        num(sh.minor_axis_length)
                    ))
                    .value(x, ""),
            )
            .value("eccentricity", x),
        None => ecc_step
            .relation(
                eccentricity
                    .subst(format!(r"\frac{{{}}}{{0}}", num(sh.diameter)))
                    .result(r"\text{no value}"),
            )
            .value("eccentricity", Value::Null),
    });
    s.result = Record::new();
    set_shape(&mut s.result, &sh);
    let code = e.path.code.clone().unwrap_or_default();
    let d = chain::differential(&code, conn, e.path.closed);
    let l = chain::length(&code, conn);
    s.step(
        Step::new(
            "Code and length of the traced boundary",
            "The traced boundary's chain code (closed: the last digit leads back to the start), its differential code (the first element from the last and the first digit) and its length (axial steps 1, diagonal steps √2).",
        )
        .relation(Relation::new("a").key("code").result(digits_form(&code)))
        .relation(
            Relation::new("d_k")
                .key("differential")
                .sym(r"(a_k - a_{k-1}) \bmod n"),
        )
        .relation(Relation::new("d").result(digits_form(&d.code)))
        .relation(length_relation(&l))
        .value("code", digits_value(&code))
        .value("differential", digits_value(&d.code))
        .value("length", l.length),
    );
    s.result.set("boundary", pixel_value(b));
    s.result.set("code", digits_value(&code));
    s.result.set("differential", digits_value(&d.code));
    s.result.set("length", l.length);
    s.result.set("closed", e.path.closed);
    s.result.set("regions", e.regions.len());
    label_code(&mut s, conn);
    if sh.eccentricity.is_none() {
        s.note(
            NoteKind::Warning,
            "All boundary pixels lie on one straight line, so the minor axis has length 0 and the eccentricity has no value.",
        ).about(&["minor_axis_length", "eccentricity"]);
    }
    regions_note(&mut s, &e);
    conn_note(&mut s, conn);
    s.note(
        NoteKind::Convention,
        "Distances are measured between pixel centres (a pixel's own size is not added), as the boundary length is. The course notes do not fix where the minor axis crosses the major one; it is drawn through the centre of the basic rectangle. The diameter and the rectangle only depend on the outermost pixels, so a filled region and its boundary give the same values.",
    ).about(&["diameter", "major_axis", "minor_axis_length", "basic_rectangle"]);
    Ok(s)
}

// ---------------------------------------------------------------- practice

/// A region: a w × h block of pixels with its four corner pixels cut off,
/// somewhere on a small grid.
fn generate(rng: &mut Rng) -> Record {
    let w = rng.int(4, 8);
    let mut h = rng.int(3, 6);
    if h == w {
        h -= 1;
    }
    let (c0, r0) = (rng.int(1, 6), rng.int(1, 6));
    let mut pixels = Vec::new();
    for r in 0..h {
        for c in 0..w {
            let corner = (c == 0 || c == w - 1) && (r == 0 || r == h - 1);
            if !corner || rng.int(0, 3) == 0 {
                pixels.push(vec![(c0 + c) as f64, (r0 + r) as f64]);
            }
        }
    }
    Record::new().with("pixels", mat(&pixels))
}

fn boxes(_: &Record) -> Vec<BoxDef> {
    let t = Tolerance::abs(0.005);
    vec![
        BoxDef::new("diameter", "Diameter", Some("px"), t)
            .nudge("The largest distance between two boundary pixels: √(Δc² + Δr²)."),
        BoxDef::new("minor_axis_length", "Minor axis length", Some("px"), t)
            .nudge("The extent of the boundary perpendicular to the major axis."),
        BoxDef::new("eccentricity", "Eccentricity", None, Tolerance::abs(0.005))
            .nudge("Major axis (the diameter) over minor axis."),
    ]
}

fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = EXAMPLE.run(i)?;
    let d = or_given(g, "diameter", value_in(&s, "diameter")?);
    let m = or_given(g, "minor_axis_length", value_in(&s, "minor_axis_length")?);
    Ok(Record::new()
        .with("diameter", d)
        .with("minor_axis_length", m)
        .with("eccentricity", d / m))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let s = EXAMPLE.run(i)?;
    let (d, m) = (
        value_in(&s, "diameter")?,
        value_in(&s, "minor_axis_length")?,
    );
    // the major axis' ends: Δc and Δr between them
    let ends = Inputs(&s.result).rows("major_axis")?;
    let (dc, dr) = match ends.as_slice() {
        [a, b] if a.len() == 2 && b.len() == 2 => ((b[0] - a[0]).abs(), (b[1] - a[1]).abs()),
        _ => (f64::NAN, f64::NAN),
    };
    Ok(vec![
        Mistake::new(
            "eccentricity",
            "minor over major",
            "The seed's eccentricity is the major axis over the minor one (≥ 1).",
            m / d,
        ),
        Mistake::new(
            "diameter",
            "city-block distance",
            "The diameter is the straight-line distance √(Δc² + Δr²), not the steps |Δc| + |Δr| along the grid.",
            dc + dr,
        ),
        Mistake::new(
            "diameter",
            "square root forgotten",
            "Δc² + Δr² is the squared distance; the diameter is its square root.",
            dc * dc + dr * dr,
        ),
    ])
}
