//! The boundary descriptors: diameter, major and minor axis, basic rectangle.

use super::*;

pub(super) fn point_value(p: [f64; 2]) -> Value {
    Value::numbers(&p)
}

pub(super) fn boundary_shape(inputs: &Record) -> Result<Solution> {
    let conn = connectivity(inputs)?;
    let mut probe = inputs.clone();
    probe.set("given", "region");
    let e = edge(&probe, conn, false)?;
    let b = &e.path.pixels;
    let sh = chain::shape("pixels", b)?;
    let mut s = Solution::new("boundary-shape", "Boundary descriptors", inputs.clone());
    s.step(edge_step(&e, conn, &probe)?);
    let [a, z] = sh.major_axis;
    s.step(
        Step::new(
            "Diameter",
            "The largest distance between two boundary pixels (between pixel centres); the first such pair along the boundary is taken.",
        )
        .formula(
            r"D = \max_{i,j} \sqrt{(c_i - c_j)^2 + (r_i - r_j)^2}",
            format!(
                r"D = \sqrt{{({} - {})^2 + ({} - {})^2}} = {}",
                z[0],
                tex(a[0] as f64),
                z[1],
                tex(a[1] as f64),
                num(sh.diameter)
            ),
        )
        .value("diameter", sh.diameter),
    );
    let u = sh.axis_direction;
    s.step(
        Step::new(
            "Major axis",
            "The segment between the two farthest pixels; its direction u is the unit vector from one end to the other.",
        )
        .formula(
            r"u = \frac{p_b - p_a}{D}",
            format!(
                r"p_a = {},\ p_b = {},\ u = ({},\ {})",
                pixel_tex(a),
                pixel_tex(z),
                num(u[0]),
                num(u[1])
            ),
        )
        .value("major_axis", pixel_value(&sh.major_axis))
        .value("direction", point_value(u)),
    );
    s.step(
        Step::new(
            "Minor axis",
            "Perpendicular to the major axis (direction v), as long as the boundary is wide across it: the offsets t of all boundary pixels along v, from the major axis, span the minor axis. It is drawn through the middle of the basic rectangle.",
        )
        .formula(
            r"v = (-u_r,\ u_c),\quad t_i = (p_i - p_a)\cdot v,\quad m = t_{\max} - t_{\min}",
            format!(
                r"t_{{\min}} = {},\ t_{{\max}} = {},\ m = {}",
                num(sh.across[0]),
                num(sh.across[1]),
                num(sh.minor_axis_length)
            ),
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
        .formula(
            r"p_a + s\,u + t\,v,\quad s \in \{0, D\},\ t \in \{t_{\min}, t_{\max}\}",
            list_tex(
                &sh.basic_rectangle,
                |p| format!("({},\\ {})", num(p[0]), num(p[1])),
                r"\;",
                2,
            ),
        )
        .value("basic_rectangle", rect.clone()),
    );
    let ecc_step = Step::new(
        "Eccentricity",
        "The ratio of the major axis to the minor axis.",
    );
    s.step(match sh.eccentricity {
        Some(x) => ecc_step
            .formula(
                r"E = \frac{D}{m}",
                format!(
                    r"E = \frac{{{}}}{{{}}} = {}",
                    num(sh.diameter),
                    num(sh.minor_axis_length),
                    num(x)
                ),
            )
            .value("eccentricity", x),
        None => ecc_step
            .formula(
                r"E = \frac{D}{m}",
                format!(
                    r"E = \frac{{{}}}{{0}}\ \text{{: no value}}",
                    num(sh.diameter)
                ),
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
        .formula(
            r"a,\quad d_k = (a_k - a_{k-1}) \bmod n,\quad L = n_h + n_v + \sqrt{2}\, n_d",
            format!(
                r"a = {},\quad d = {},\quad L = {} + {} + \sqrt{{2}} \times {} = {}",
                digits_tex(&code),
                digits_tex(&d.code),
                l.horizontal,
                l.vertical,
                l.diagonal,
                num(l.length)
            ),
        )
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
    label_results(&mut s, conn);
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
