//! Seed 004: UTM back to latitude and longitude step by step through the
//! inverse Krüger series, with Snyder's inverse beside it, and its practice.

use super::super::drill::{drill, or_given, BoxDef, Drill, Mistake, Rng, Tolerance};
use super::super::fields::{is_seed, Field, Inputs};
use super::super::Example;
use super::figure::figure_step;
use super::*;
use crate::projection::krueger::{self, Series};
use crate::projection::utm::{self, Hemisphere, FALSE_EASTING, FALSE_NORTHING_SOUTH, K0};
use crate::projection::{dms, snyder};
use crate::solution::{NoteKind, Record, Solution};

pub const EXAMPLE: Example = Example {
    id: "utm-inverse",
    title: "UTM to latitude and longitude",
    source: "Lecture 7: Image processing, UTM",
    summary:
        "From zone, hemisphere, easting and northing back to latitude and longitude, step by step.",
    fields,
    solve,
    answer: &["latitude", "longitude"],
    labels: LABELS,
    lab: None,
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

/// `hemisphere`: a hemisphere, or a latitude band letter (which names the
/// hemisphere and is checked against the result).
const HEMISPHERE_OPTIONS: &[(&str, &str)] = &[
    ("north", "north"),
    ("south", "south"),
    ("C", "band C (80°S–72°S)"),
    ("D", "band D (72°S–64°S)"),
    ("E", "band E (64°S–56°S)"),
    ("F", "band F (56°S–48°S)"),
    ("G", "band G (48°S–40°S)"),
    ("H", "band H (40°S–32°S)"),
    ("J", "band J (32°S–24°S)"),
    ("K", "band K (24°S–16°S)"),
    ("L", "band L (16°S–8°S)"),
    ("M", "band M (8°S–0°)"),
    ("N", "band N (0°–8°N)"),
    ("P", "band P (8°N–16°N)"),
    ("Q", "band Q (16°N–24°N)"),
    ("R", "band R (24°N–32°N)"),
    ("S", "band S (32°N–40°N)"),
    ("T", "band T (40°N–48°N)"),
    ("U", "band U (48°N–56°N)"),
    ("V", "band V (56°N–64°N)"),
    ("W", "band W (64°N–72°N)"),
    ("X", "band X (72°N–84°N)"),
];

/// The default: Bangkok (13°45′N, 100°30′E, WGS 84, the forward example's
/// default point) in UTM to the millimetre.
const DEFAULT_E: f64 = 662_176.290;
const DEFAULT_N: f64 = 1_520_582.494;

fn fields() -> Vec<Field> {
    vec![
        Field::integer("zone", "Zone", 47.0)
            .range(1.0, 60.0)
            .help("UTM zone 1–60; zone z has its central meridian at 6z − 183 degrees."),
        Field::choice("hemisphere", "Hemisphere or band", HEMISPHERE_OPTIONS, "north")
            .help("north or south, or a latitude band letter C–X (I and O are not used); a band letter is checked against the result."),
        Field::number("easting", "Easting E", DEFAULT_E)
            .unit("m")
            .range(utm::EASTING_MIN, utm::EASTING_MAX)
            .help("500 000 m on the central meridian; legal from 100 000 m to 900 000 m."),
        Field::number("northing", "Northing N", DEFAULT_N)
            .unit("m")
            .range(0.0, utm::FALSE_NORTHING_SOUTH)
            .help("From the equator; in the south 10 000 000 m is added. Legal: 0–9 500 000 m north, 1 000 000–10 000 000 m south."),
        ellipsoid_field(),
    ]
}

fn solve(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let zone = i.number("zone")? as u8;
    let hem_text = i.text("hemisphere")?;
    let band = hem_text.chars().next().filter(|_| hem_text.len() == 1);
    let hemisphere = match (hem_text, band) {
        ("north", _) => Hemisphere::North,
        ("south", _) => Hemisphere::South,
        (_, Some(b)) => utm::band_hemisphere(b).ok_or_else(|| {
            Error::input(
                "hemisphere",
                format!("\"{b}\" is not a latitude band (C–X without I and O)"),
            )
        })?,
        _ => {
            return Err(Error::input(
                "hemisphere",
                "must be north, south or a band letter",
            ))
        }
    };
    let (e, north) = (i.number("easting")?, i.number("northing")?);
    let ell = ellipsoid(&i)?;
    let inv = utm::inverse(&ell, zone, hemisphere, e, north)?;
    let series = Series::new(&ell);
    let tm = inv.tm;
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    s.step(ellipsoid_step(&ell));
    s.step(
        Step::new(
            "Remove the false easting and northing",
            "x is measured east of the central meridian, y north of the equator.",
        )
        .relation(central_meridian_relation(zone, inv.central_meridian))
        .relation(
            Relation::new("x")
                .key("x")
                .sym(r"E - 500\,000")
                .subst(format!(r"{} - 500\,000", fixed(e, 6)))
                .result(metres(inv.x)),
        )
        .relation(
            Relation::new("y")
                .key("y")
                .sym("N - N_0")
                .subst(format!(
                    "{} - {}",
                    fixed(north, 6),
                    fixed(hemisphere.false_northing(), 0)
                ))
                .result(metres(inv.y)),
        )
        .value("x", inv.x)
        .value("y", inv.y)
        .value("central_meridian", inv.central_meridian),
    );
    s.step(coefficient_step(&series, false));
    let ka = format!(r"0.9996 \times {}", fixed(series.rectifying_radius, 6));
    s.step(
        Step::new(
            "Back to the sphere",
            "ξ and η are the map coordinates in units of k₀A; the β series undoes Krüger's series.",
        )
        .relation(
            Relation::new(r"\xi")
                .key("xi")
                .sym(r"\frac{y}{k_0 A}")
                .subst(format!(r"\frac{{{}}}{{{ka}}}", fixed(inv.y, 6)))
                .result(fmt_sig(tm.xi, 14)),
        )
        .relation(
            Relation::new(r"\eta")
                .key("eta")
                .sym(r"\frac{x}{k_0 A}")
                .subst(format!(r"\frac{{{}}}{{{ka}}}", fixed(inv.x, 6)))
                .result(fmt_sig(tm.eta, 14)),
        )
        .relation(series_relation(
            r"\xi'",
            "xi_prime",
            r"\xi - \sum_{j=1}^{6}\beta_j \sin 2j\xi\cosh 2j\eta",
            tm.xi,
            tm.xi_prime,
            false,
        ))
        .relation(series_relation(
            r"\eta'",
            "eta_prime",
            r"\eta - \sum_{j=1}^{6}\beta_j\cos 2j\xi \sinh 2j\eta",
            tm.eta,
            tm.eta_prime,
            false,
        ))
        .value("xi", tm.xi)
        .value("eta", tm.eta)
        .value("xi_prime", tm.xi_prime)
        .value("eta_prime", tm.eta_prime),
    );
    let (xp, ep) = (
        par(fmt_sig(tm.xi_prime, 14)),
        par(fmt_sig(tm.eta_prime, 14)),
    );
    s.step(
        Step::new(
            "Conformal latitude and longitude",
            "On the sphere the inverse is closed: τ′ = tan χ and the longitude difference.",
        )
        .relation(
            Relation::new(r"\tau'")
                .key("tau_prime")
                .sym(r"\frac{\sin\xi'}{\sqrt{\sinh^2\eta' + \cos^2\xi'}}")
                .subst(format!(
                    r"\frac{{\sin {xp}}}{{\sqrt{{\sinh^2 {ep} + \cos^2 {xp}}}}}"
                ))
                .result(fmt_sig(tm.tau_prime, 14)),
        )
        .relation(
            Relation::new(r"\Delta\lambda")
                .key("dlon")
                .sym(r"\operatorname{atan2}(\sinh\eta', \cos\xi')")
                .subst(format!(r"\operatorname{{atan2}}(\sinh {ep}, \cos {xp})"))
                .result(deg(fmt_sig(tm.dlon_deg, 12))),
        )
        .value("tau_prime", tm.tau_prime)
        .value("dlon", tm.dlon_deg),
    );
    s.step(
        Step::new(
            "Latitude by Newton's method",
            &format!(
                "τ′(τ) has no closed inverse; Newton's method from τ = τ′/(1 − e²) converged in {} iteration{}.",
                tm.iterations,
                if tm.iterations == 1 { "" } else { "s" }
            ),
        )
        .relation(Relation::new(r"\tau_{i+1}").sym(
            r"\tau_i + \frac{(\tau' - \tau'(\tau_i))\,(1 + (1-e^2)\tau_i^2)}{(1-e^2)\sqrt{1+\tau_i^2}\,\sqrt{1+\tau'(\tau_i)^2}}",
        ))
        .relation(Relation::new(r"\tau").key("tau").result(fmt_sig(tm.tau, 14)))
        .relation(
            Relation::new(r"\varphi")
                .key("latitude")
                .sym(r"\arctan\tau")
                .subst(format!(r"\arctan {}", par(fmt_sig(tm.tau, 14))))
                .result(deg(fmt_sig(inv.latitude, 13))),
        )
        .relation(
            Relation::new(r"\lambda")
                .key("longitude")
                .sym(r"\lambda_0 + \Delta\lambda")
                .subst(format!(
                    "{} + {}",
                    inv.central_meridian,
                    par(fmt_sig(tm.dlon_deg, 12))
                ))
                .result(deg(fmt_sig(inv.longitude, 13))),
        )
        .value("tau", tm.tau)
        .value("latitude", inv.latitude)
        .value("longitude", inv.longitude)
        .value("iterations", tm.iterations),
    );
    s.step(
        Step::new(
            "Meridian convergence and scale factor",
            "From the derivative of the β series and the sphere's own γ and k.",
        )
        .relation(Relation::new("p").result(fmt_sig(tm.p, 14)))
        .relation(Relation::new("q").result(sci(tm.q, 10)))
        .relation(
            Relation::new(r"\gamma")
                .key("convergence")
                .sym(r"\operatorname{atan2}(q, p) + \operatorname{atan2}(\sin\xi'\tanh\eta', \cos\xi')")
                .result(deg(fmt_sig(tm.gamma.to_degrees(), 12))),
        )
        .relation(
            Relation::new("k")
                .key("scale_factor")
                .sym(r"k_0\,\frac{A}{a}\,\frac{w}{\sqrt{p^2+q^2}}")
                .result(fmt_sig(tm.k, 14)),
        )
        .relation(Relation::new("w").sym(
            r"\sqrt{1 - e^2 + \frac{e^2}{1+\tau^2}}\,\sqrt{1+\tau^2}\,\sqrt{\sinh^2\eta'+\cos^2\xi'}",
        ))
        .value("scale_factor", tm.k)
        .value("convergence", tm.gamma.to_degrees()),
    );
    let c = snyder::inverse(&ell, K0, inv.x, inv.y)?;
    let cd = (c.lat_deg - inv.latitude)
        .abs()
        .max((c.dlon_deg - tm.dlon_deg).abs());
    s.step(
        Step::new(
            "The classical series, for comparison",
            "Snyder's inverse: the footpoint latitude φ₁ from the meridian arc, then power series in D = x/(N₁k₀).",
        )
        .relation(Relation::new(r"\mu").sym(r"\frac{M}{a(1-e^2/4-3e^4/64-5e^6/256)}"))
        .relation(
            Relation::new(r"\varphi_1")
                .sym(r"\mu + \left(\tfrac{3e_1}{2}-\tfrac{27e_1^3}{32}\right)\sin 2\mu + \dots")
                .result(deg(fmt_sig(c.phi1.to_degrees(), 12))),
        )
        .relation(Relation::new("D").result(fmt_sig(c.d, 12)))
        .relation(
            Relation::new(r"\varphi")
                .key("classical_latitude")
                .sym(r"\varphi_1 - \frac{N_1\tan\varphi_1}{R_1}\left[\tfrac{D^2}{2} - \dots\right]")
                .result(deg(fmt_sig(c.lat_deg, 12))),
        )
        .relation(
            Relation::new(r"\Delta\lambda")
                .sym(r"\frac{D - (1+2T_1+C_1)D^3/6 + \dots}{\cos\varphi_1}"),
        )
        .relation(
            Relation::new(r"\lambda")
                .key("classical_longitude")
                .result(deg(fmt_sig(inv.central_meridian + c.dlon_deg, 12))),
        )
        .relation(
            Relation::new(r"\text{largest difference}")
                .key("classical_difference_deg")
                .result(format!(r"{}\,{{}}^\circ", sci(cd, 3))),
        )
        .value("classical_latitude", c.lat_deg)
        .value("classical_longitude", inv.central_meridian + c.dlon_deg),
    );
    if let Ok(u) = utm::forward(&ell, inv.latitude, inv.longitude, Some(zone)) {
        s.step(figure_step(&ell, inv.latitude, &u)?);
    }
    s.result = Record::new()
        .with("latitude", inv.latitude)
        .with("longitude", inv.longitude)
        .with("scale_factor", tm.k)
        .with("convergence", tm.gamma.to_degrees())
        .with(
            "latitude_dms",
            dms::format(inv.latitude, 'N', 'S', 5).as_str(),
        )
        .with(
            "longitude_dms",
            dms::format(inv.longitude, 'E', 'W', 5).as_str(),
        )
        .with("band", utm::band_letter(inv.latitude).to_string().as_str())
        .with("hemisphere", hemisphere.name())
        .with("iterations", tm.iterations)
        .with("classical_latitude", c.lat_deg)
        .with("classical_longitude", inv.central_meridian + c.dlon_deg)
        .with("classical_difference_deg", cd);
    if let Some(b) = band {
        if let Some((south, north)) = utm::band_limits(b) {
            let tol = 1e-9;
            if inv.latitude < south - tol || inv.latitude > north + tol {
                s.note(
                    NoteKind::Warning,
                    format!(
                        "The point is at latitude {}, in band {}, not in band {b} ({}° to {}°): check the northing or the band letter.",
                        dms::format(inv.latitude, 'N', 'S', 2),
                        utm::band_letter(inv.latitude),
                        south,
                        north
                    ),
                );
            }
        }
    }
    if !(utm::LAT_MIN..=utm::LAT_MAX).contains(&inv.latitude) {
        s.note(
            NoteKind::Warning,
            format!(
                "Latitude {} is outside 80°S–84°N, where UTM is used; polar maps use UPS.",
                fmt_sig(inv.latitude, 9)
            ),
        );
    }
    if inv.tm.dlon_deg.abs() > 3.0 + 1e-9 {
        s.note(
            NoteKind::Warning,
            format!(
                "The point is {}° from the central meridian, outside the zone's 6°: it belongs to a neighbouring zone.",
                fmt_sig(inv.tm.dlon_deg.abs(), 6)
            ),
        );
    }
    if is_seed(&fields(), inputs) {
        s.note(
            NoteKind::Convention,
            "The default easting and northing are those of the \"Latitude and longitude to UTM\" example's default point (Bangkok, 13°45′N 100°30′E, WGS 84), rounded to the millimetre: the inverse returns that point to within about 10⁻⁸°.",
        );
    }
    Ok(s)
}

// ---------------------------------------------------------------------------
// Practice: the inverse projection as the steps show it, box by box.

const SUBTRACTION: Tolerance = Tolerance::abs(0.001);

fn generate(rng: &mut Rng) -> Record {
    let (lat, lon) = draw_point(rng);
    let ell = Ellipsoid::by_id("wgs84");
    let f = ell.and_then(|e| utm::forward(&e, lat, lon, None).ok());
    let (zone, hemisphere, e, nn) = match f {
        Some(f) => (
            f64::from(f.zone),
            f.hemisphere.name(),
            (f.easting * 100.0).round() / 100.0,
            (f.northing * 100.0).round() / 100.0,
        ),
        // Unreachable: every drawn point is a UTM point.
        None => (47.0, "north", 662_176.29, 1_520_582.49),
    };
    Record::new()
        .with("zone", zone)
        .with("hemisphere", hemisphere)
        .with("easting", e)
        .with("northing", nn)
        .with("ellipsoid", "wgs84")
}

fn boxes(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("central_meridian", "Central meridian λ₀", Some("°"), WHOLE)
            .nudge("6·zone − 183°."),
        BoxDef::new("x", "x = E − 500 000 m", Some("m"), SUBTRACTION)
            .nudge("Take off the false easting.")
            .sign_flip(EAST_WEST),
        BoxDef::new("y", "y (from the equator)", Some("m"), SUBTRACTION)
            .nudge("In the south take off the 10 000 000 m false northing; in the north y = N."),
        BoxDef::new("xi", "ξ = y / (k₀A)", None, RATIO)
            .nudge("A is the rectifying radius; k₀ = 0.9996."),
        BoxDef::new("eta", "η = x / (k₀A)", None, RATIO).nudge("The same for x."),
        BoxDef::new("xi_prime", "ξ′ (back to the sphere)", None, RATIO)
            .nudge("ξ′ = ξ − Σ βⱼ sin 2jξ cosh 2jη."),
        BoxDef::new("eta_prime", "η′ (back to the sphere)", None, RATIO)
            .nudge("η′ = η − Σ βⱼ cos 2jξ sinh 2jη."),
        BoxDef::new("tau_prime", "τ′ = tan χ", None, RATIO)
            .nudge("τ′ = sin ξ′ / √(sinh² η′ + cos² ξ′)."),
        BoxDef::new("latitude", "Latitude φ", Some("°"), DEGREES)
            .nudge("τ = tan φ from τ′ by Newton's method (two or three steps), then φ = atan τ.")
            .sign_flip("The size is right but the sign is not: north of the equator φ is positive, south negative."),
        BoxDef::new("dlon", "Δλ", Some("°"), DEGREES)
            .nudge("Δλ = atan2(sinh η′, cos ξ′), in degrees.")
            .sign_flip(EAST_WEST),
        BoxDef::new("longitude", "Longitude λ", Some("°"), DEGREES).nudge("λ = λ₀ + Δλ."),
        BoxDef::new("scale_factor", "Point scale factor k", None, SCALE).nudge(
            "k = k₀·(A/a)/√(p² + q²)·√(1 − e² + e²/(1 + τ²))·√(1 + τ²)·√(sinh² η′ + cos² ξ′).",
        ),
        BoxDef::new(
            "convergence",
            "Meridian convergence γ",
            Some("°"),
            CONVERGENCE,
        )
        .nudge("γ = atan2(q, p) + atan2(sin ξ′·tanh η′, cos ξ′), in degrees.")
        .sign_flip(CONVERGENCE_FLIP),
    ]
}

/// The boxes from the student's earlier answers: the stages of
/// [`krueger::inverse`], each replaced by what was given.
fn chain(i: &Record, g: &Record) -> Result<Record> {
    let inputs = Inputs(i);
    let ell = ellipsoid(&inputs)?;
    let s = Series::new(&ell);
    let ka = K0 * s.rectifying_radius;
    let south = inputs.text("hemisphere")? == "south";
    let cm = or_given(g, "central_meridian", 6.0 * n(i, "zone") - 183.0);
    let x = or_given(g, "x", n(i, "easting") - FALSE_EASTING);
    let false_northing = if south { FALSE_NORTHING_SOUTH } else { 0.0 };
    let y = or_given(g, "y", n(i, "northing") - false_northing);
    let xi = or_given(g, "xi", y / ka);
    let eta = or_given(g, "eta", x / ka);
    let (a, b, p1, q) = krueger::sums(&s.beta, xi, eta);
    let xip = or_given(g, "xi_prime", xi - a);
    let etap = or_given(g, "eta_prime", eta - b);
    let p = 1.0 - p1;
    let (taup, dlon) = krueger::sphere_inverse(xip, etap);
    let taup = or_given(g, "tau_prime", taup);
    let (tau, _) = krueger::tau_from_tau_prime(taup, s.e)?;
    let dlon = or_given(g, "dlon", dlon.to_degrees());
    let gamma = krueger::inverse_convergence(p, q, xip, etap);
    let k = K0 * krueger::inverse_scale(&s, ell.a, p, q, tau, xip, etap);
    Ok(Record::new()
        .with("central_meridian", cm)
        .with("x", x)
        .with("y", y)
        .with("xi", xi)
        .with("eta", eta)
        .with("xi_prime", xip)
        .with("eta_prime", etap)
        .with("tau_prime", taup)
        .with("latitude", or_given(g, "latitude", tau.atan().to_degrees()))
        .with("dlon", dlon)
        .with(
            "longitude",
            or_given(g, "longitude", utm::lon_diff(cm + dlon, 0.0)),
        )
        .with("scale_factor", or_given(g, "scale_factor", k))
        .with("convergence", gamma.to_degrees()))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let exact = chain(i, &Record::new())?;
    let v = |k: &str| exact.number(k).unwrap_or(f64::NAN);
    let inputs = Inputs(i);
    let ell = ellipsoid(&inputs)?;
    let a = Series::new(&ell).rectifying_radius;
    let zone = n(i, "zone");
    let (e, north) = (n(i, "easting"), n(i, "northing"));
    let south = inputs.text("hemisphere")? == "south";
    const OFF: &str = "Zone z spans 6z − 186° to 6z − 180°: its central meridian is 6z − 183°.";
    const RAD: &str = "That is the angle in radians; the box asks for degrees (× 180/π).";
    const K0_: &str = "k₀ = 0.9996 scales the whole projection: divide by k₀·A, not by A.";
    const SWAP: &str = "Latitude is north–south, longitude east–west.";
    let mut out = meridian_mistakes(zone, v("central_meridian"), OFF).to_vec();
    out.extend([
        Mistake::new(
            "x",
            "false easting forgotten",
            "E includes the 500 000 m false easting: x = E − 500 000 m.",
            e,
        ),
        Mistake::new("xi", "k₀ = 0.9996 forgotten", K0_, v("y") / a),
        Mistake::new("eta", "k₀ = 0.9996 forgotten", K0_, v("x") / a),
        Mistake::new(
            "latitude",
            "conformal latitude taken for the latitude",
            "atan τ′ is the conformal latitude χ; the geodetic φ comes from τ, found from τ′ by Newton's method.",
            v("tau_prime").atan().to_degrees(),
        ),
        Mistake::new("latitude", "degrees vs radians", RAD, v("latitude").to_radians()),
        Mistake::new("latitude", "latitude and longitude swapped", SWAP, v("longitude")),
        Mistake::new("dlon", "degrees vs radians", RAD, v("dlon").to_radians()),
        Mistake::new(
            "longitude",
            "6·zone − 180 without the −3",
            EDGE,
            utm::lon_diff(6.0 * zone - 180.0 + v("dlon"), 0.0),
        ),
        Mistake::new("longitude", "latitude and longitude swapped", SWAP, v("latitude")),
        Mistake::new("scale_factor", "k₀ = 0.9996 forgotten", K0_, v("scale_factor") / K0),
        Mistake::new("convergence", "degrees vs radians", RAD, v("convergence").to_radians()),
    ]);
    out.push(if south {
        Mistake::new(
            "y",
            "false northing forgotten",
            "South of the equator N includes 10 000 000 m: y = N − 10 000 000 m (negative).",
            north,
        )
    } else {
        Mistake::new(
            "y",
            "false northing applied in the north",
            "The 10 000 000 m false northing is for the southern hemisphere only: in the north y = N.",
            north - FALSE_NORTHING_SOUTH,
        )
    });
    Ok(out)
}
