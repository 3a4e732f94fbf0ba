//! Seed 004, map projection: geographic → UTM (`utm`) and back
//! (`utm-inverse`) step by step through Karney's Krüger series, with
//! Snyder's classical series beside it. Seed 004's printed UTM facts are the
//! `utm-facts` example (`projection_facts.rs`).

use super::fields::{is_seed, Field, Inputs};
use super::projection_figure::figure_step;
use super::{Example, Topic};
use crate::error::{Error, Result};
use crate::projection::krueger::Series;
use crate::projection::utm::{self, Hemisphere, ZoneRule, K0};
use crate::projection::{dms, snyder, Ellipsoid};
use crate::solution::{fmt_sig, NoteKind, Record, Solution, Step, Value};

const TITLE: &str = "Map projection";

/// The ellipsoid choices (`ELLIPSOIDS` in `projection/mod.rs`, same order).
pub(super) const ELLIPSOID_OPTIONS: &[(&str, &str)] = &[
    ("wgs84", "WGS 84"),
    ("grs80", "GRS 80"),
    ("international-1924", "International 1924 (Hayford)"),
    ("bessel-1841", "Bessel 1841"),
    ("clarke-1866", "Clarke 1866"),
    ("everest-1830", "Everest 1830 (1937 adjustment)"),
];

/// `hemisphere` of `utm-inverse`: a hemisphere, or a latitude band letter
/// (which names the hemisphere and is checked against the result).
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

/// The seed's default point: Bangkok (13°45′N, 100°30′E), in the zone the
/// seed names for Thailand.
const DEFAULT_LAT: f64 = 13.75;
const DEFAULT_LON: f64 = 100.5;
/// The default point's UTM coordinates to the millimetre (utm-inverse).
const DEFAULT_E: f64 = 662_176.290;
const DEFAULT_N: f64 = 1_520_582.494;

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[
        Example {
            id: "utm",
            title: "Latitude and longitude to UTM",
            source: "Lecture 7: Image processing, UTM",
            summary: "A point's zone, band, easting and northing, scale factor and meridian convergence, step by step through the Krüger series, with the classical series beside it.",
            fields: utm_fields,
            solve: solve_utm,
            answer: &["zone", "easting", "northing"],
            labels: &[],
            lab: None,
            practice: None,
        },
        Example {
            id: "utm-inverse",
            title: "UTM to latitude and longitude",
            source: "Lecture 7: Image processing, UTM",
            summary: "From zone, hemisphere, easting and northing back to latitude and longitude, step by step.",
            fields: inverse_fields,
            solve: solve_inverse,
            answer: &["latitude", "longitude"],
            labels: &[],
            lab: None,
            practice: None,
        },
        super::projection_facts::EXAMPLE,
];

/// The topic: its module (`web/projection/`) and title.
pub const TOPIC: Topic = Topic {
    module: "projection",
    title: TITLE,
    examples: EXAMPLES,
};

pub(super) fn ellipsoid_field() -> Field {
    Field::choice("ellipsoid", "Ellipsoid", ELLIPSOID_OPTIONS, "wgs84")
        .help("The reference ellipsoid of the datum. WGS 84 and GRS 80 differ by 0.1 mm in the polar radius.")
}

pub(super) fn latitude_field(default: f64) -> Field {
    Field::angle("latitude", "Latitude φ", 90.0, ('N', 'S'), default).help(
        "Degrees (13.75), or degrees, minutes, seconds (13°45'00\"N or 13 45 0); south negative or S.",
    )
}

fn utm_fields() -> Vec<Field> {
    vec![
        latitude_field(DEFAULT_LAT),
        Field::angle("longitude", "Longitude λ", 180.0, ('E', 'W'), DEFAULT_LON).help(
            "Degrees (100.5) or 100°30'E; west negative or W. Beyond ±180° is refused, not wrapped.",
        ),
        ellipsoid_field(),
        Field::integer("zone", "Force a zone", 0.0)
            .range(0.0, 60.0)
            .help("0 = the standard zone; 1–60 puts the point in that zone instead (to see what happens far from its central meridian)."),
    ]
}

fn inverse_fields() -> Vec<Field> {
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

/// The ellipsoid a validated `ellipsoid` field names.
pub(super) fn ellipsoid(i: &Inputs) -> Result<Ellipsoid> {
    let id = i.text("ellipsoid")?;
    Ellipsoid::by_id(id).ok_or_else(|| Error::Internal(format!("no ellipsoid \"{id}\"")))
}

// ---------------------------------------------------------------------------
// Numbers for LaTeX

/// A number with `decimals` decimals, thousands separated by thin spaces.
pub(super) fn fixed(x: f64, decimals: usize) -> String {
    let s = format!("{:.*}", decimals, x.abs());
    let (int, frac) = match s.split_once('.') {
        Some((i, f)) => (i.to_string(), Some(f.to_string())),
        None => (s.clone(), None),
    };
    let mut grouped = String::new();
    for (k, ch) in int.chars().enumerate() {
        if k > 0 && (int.len() - k) % 3 == 0 {
            grouped.push_str(r"\,");
        }
        grouped.push(ch);
    }
    let sign = if x < 0.0 && s.chars().any(|c| c != '0' && c != '.') {
        "-"
    } else {
        ""
    };
    match frac {
        Some(f) => format!("{sign}{grouped}.{f}"),
        None => format!("{sign}{grouped}"),
    }
}

/// Metres to the micrometre.
pub(super) fn metres(x: f64) -> String {
    fixed(x, 6)
}

/// A number in LaTeX with `sig` significant digits, powers of ten written out.
pub(super) fn sci(x: f64, sig: usize) -> String {
    if x == 0.0 || (1e-3..1e6).contains(&x.abs()) {
        return fmt_sig(x, sig);
    }
    let s = format!("{:.*e}", sig.saturating_sub(1), x);
    match s.split_once('e') {
        Some((m, e)) => {
            let m = m.trim_end_matches('0').trim_end_matches('.');
            // braced, so that a following ^\circ is not a double superscript
            format!(r"{{{m}\times 10^{{{e}}}}}")
        }
        None => s,
    }
}

/// In parentheses when negative (for substituted formulas).
fn par(s: String) -> String {
    if s.starts_with('-') {
        format!("({s})")
    } else {
        s
    }
}

/// A plain-text number with thin spaces between thousands and `d` decimals.
pub(super) fn plain(x: f64, d: usize) -> String {
    fixed(x, d).replace(r"\,", "\u{2009}")
}

// ---------------------------------------------------------------------------
// Shared steps

/// The ellipsoid's constants as a step.
pub(super) fn ellipsoid_step(ell: &Ellipsoid) -> Step {
    Step::new(
        "The ellipsoid",
        &format!(
            "{}: {}. Everything else follows from a and the flattening f: the eccentricity e, the third flattening n (the small number the series are written in) and the polar radius b.",
            ell.name, ell.source
        ),
    )
    .formula(
        r"e^2 = f(2-f),\quad n = \frac{f}{2-f},\quad e'^2 = \frac{e^2}{1-e^2},\quad b = a(1-f)",
        format!(
            r"f = \frac{{1}}{{{}}},\quad e^2 = {},\quad n = {},\quad e'^2 = {},\quad b = {}\ \text{{m}}",
            fmt_sig(ell.inv_f, 13),
            fmt_sig(ell.e2(), 12),
            fmt_sig(ell.n(), 12),
            fmt_sig(ell.ep2(), 12),
            fixed(ell.b(), 4)
        ),
    )
    .value("a", ell.a)
    .value("inverse_flattening", ell.inv_f)
    .value("e2", ell.e2())
    .value("n", ell.n())
    .value("ep2", ell.ep2())
    .value("b", ell.b())
}

fn coefficient_step(s: &Series, forward: bool) -> Step {
    let (name, c, text, formula) = if forward {
        (
            r"\alpha",
            s.alpha,
            "The rectifying radius A (the meridian's length is 2πA) and Krüger's coefficients α₁…α₆ (Karney 2011, eq. 35), each a polynomial in n; α_j shrinks like n^j, so six terms reach nanometres.",
            r"A = \frac{a}{1+n}\left(1 + \frac{n^2}{4} + \frac{n^4}{64} + \frac{n^6}{256}\right),\quad \alpha_1 = \tfrac12 n - \tfrac23 n^2 + \tfrac{5}{16} n^3\quad {} + \tfrac{41}{180} n^4 - \tfrac{127}{288} n^5 + \tfrac{7891}{37800} n^6,\quad \alpha_2 = \tfrac{13}{48} n^2 - \tfrac35 n^3 + \dots",
        )
    } else {
        (
            r"\beta",
            s.beta,
            "The rectifying radius A and the coefficients β₁…β₆ of the inverse series (Karney 2011, eq. 36).",
            r"A = \frac{a}{1+n}\left(1 + \frac{n^2}{4} + \frac{n^4}{64} + \frac{n^6}{256}\right),\quad \beta_1 = \tfrac12 n - \tfrac23 n^2 + \tfrac{37}{96} n^3\quad {} - \tfrac{1}{360} n^4 - \tfrac{81}{512} n^5 + \tfrac{96199}{604800} n^6,\quad \beta_2 = \tfrac{1}{48} n^2 + \tfrac{1}{15} n^3 - \dots",
        )
    };
    let list = c
        .iter()
        .enumerate()
        .map(|(j, x)| format!(r"{name}_{} = {}", j + 1, sci(*x, 10)))
        .collect::<Vec<_>>()
        .join(r",\quad ");
    Step::new(
        if forward {
            "Rectifying radius and the α coefficients"
        } else {
            "Rectifying radius and the β coefficients"
        },
        text,
    )
    .formula(
        formula,
        format!(
            r"A = {}\ \text{{m}};\quad {list}",
            fixed(s.rectifying_radius, 6)
        ),
    )
    .value("rectifying_radius", s.rectifying_radius)
    .value(if forward { "alpha" } else { "beta" }, Value::numbers(&c))
}

/// Labels of every result key of the three examples.
pub(super) fn label_results(s: &mut Solution) {
    s.label_present(&[
        ("zone", "UTM zone", ""),
        ("band", "Latitude band", ""),
        ("hemisphere", "Hemisphere", ""),
        ("central_meridian", "Central meridian λ₀", "°"),
        ("easting", "Easting E", "m"),
        ("northing", "Northing N", "m"),
        ("scale_factor", "Point scale factor k", ""),
        ("convergence", "Meridian convergence γ", "°"),
        ("utm_text", "UTM coordinates (to the mm)", ""),
        ("latitude", "Latitude φ", "°"),
        ("longitude", "Longitude λ", "°"),
        ("latitude_dms", "Latitude", "° ′ ″"),
        ("longitude_dms", "Longitude", "° ′ ″"),
        ("standard_zone", "Standard zone of the point", ""),
        ("zone_rule", "How the zone was chosen", ""),
        ("in_legal_range", "Inside the legal UTM range", ""),
        ("classical_easting", "Easting by the classical series", "m"),
        (
            "classical_northing",
            "Northing by the classical series",
            "m",
        ),
        ("classical_difference_m", "Classical − exact, distance", "m"),
        (
            "classical_latitude",
            "Latitude by the classical series",
            "°",
        ),
        (
            "classical_longitude",
            "Longitude by the classical series",
            "°",
        ),
        (
            "classical_difference_deg",
            "Classical − exact, largest angle",
            "°",
        ),
        ("iterations", "Newton iterations for φ", ""),
    ]);
}

// ---------------------------------------------------------------------------
// utm: geographic → UTM

fn rule_text(rule: ZoneRule) -> &'static str {
    match rule {
        ZoneRule::Regular => "regular",
        ZoneRule::Norway => "Norway exception (band V, 3°E–12°E → 32)",
        ZoneRule::Svalbard => "Svalbard exception (band X, 0°–42°E → 31, 33, 35, 37)",
        ZoneRule::Forced => "forced",
    }
}

fn solve_utm(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let (lat, lon) = (i.number("latitude")?, i.number("longitude")?);
    let ell = ellipsoid(&i)?;
    let forced = i.number("zone")?;
    let forced = (forced >= 1.0).then_some(forced as u8);
    let u = utm::forward(&ell, lat, lon, forced)?;
    let series = Series::new(&ell);
    let tm = u.tm;
    let mut s = Solution::new("utm", "Latitude and longitude to UTM", inputs.clone());

    s.step(
        Step::new(
            "The point",
            &format!(
                "Latitude {} and longitude {}; in the formulas the angles are in radians.",
                dms::format(lat, 'N', 'S', 4),
                dms::format(lon, 'E', 'W', 4)
            ),
        )
        .formula(
            r"\varphi = \frac{\pi}{180}\,\varphi^\circ,\quad \lambda = \frac{\pi}{180}\,\lambda^\circ",
            format!(
                r"\varphi = {}^\circ = {}\ \text{{rad}},\quad \lambda = {}^\circ = {}\ \text{{rad}}",
                fmt_sig(lat, 12),
                fmt_sig(lat.to_radians(), 12),
                fmt_sig(lon, 12),
                fmt_sig(lon.to_radians(), 12)
            ),
        )
        .value("latitude", lat)
        .value("longitude", lon),
    );
    s.step(ellipsoid_step(&ell));

    let regular = (((if lon >= 180.0 { lon - 360.0 } else { lon }) + 180.0) / 6.0).floor() + 1.0;
    let zone_text = match u.rule {
        ZoneRule::Regular => format!(
            "Zones are 6° wide, numbered eastward from 180°. {}",
            if lon >= 180.0 {
                "180° is the same meridian as −180°, so it starts zone 1."
            } else {
                ""
            }
        ),
        ZoneRule::Norway => "The regular rule gives zone 31, but in band V (56°N–64°N) zone 32 is widened to 3°E to cover south-west Norway.".to_string(),
        ZoneRule::Svalbard => format!(
            "The regular rule gives zone {regular}, but in band X (72°N–84°N) between 0° and 42°E only the zones 31, 33, 35 and 37 are used (Svalbard); they are 9° or 12° wide."
        ),
        ZoneRule::Forced => format!(
            "Zone {} is forced; the rules would give zone {}. The transverse Mercator works in any zone, but the farther from the central meridian, the larger the scale error.",
            u.zone, u.standard_zone
        ),
    };
    s.step(
        Step::new("Zone, central meridian, band and hemisphere", zone_text.trim())
            .formula(
                r"\text{zone} = \left\lfloor \frac{\lambda^\circ + 180}{6} \right\rfloor + 1,\quad \lambda_0 = 6\cdot\text{zone} - 183,\quad \Delta\lambda = \lambda - \lambda_0,\quad i = \left\lfloor\frac{\varphi^\circ + 80}{8}\right\rfloor,\quad \text{band} = \text{CDE}\ldots\text{WX}[i]",
                format!(
                    r"\left\lfloor \frac{{{} + 180}}{{6}} \right\rfloor + 1 = {}\ \Rightarrow\ \text{{zone}} = {},\quad \lambda_0 = 6\cdot {} - 183 = {}^\circ,\quad \Delta\lambda = {}^\circ,\quad \text{{band}}\ \text{{{}}},\quad \text{{{}}}",
                    par(fmt_sig(lon, 12)),
                    regular,
                    u.zone,
                    u.zone,
                    u.central_meridian,
                    fmt_sig(u.dlon, 12),
                    u.band,
                    u.hemisphere.name()
                ),
            )
            .value("zone", f64::from(u.zone))
            .value("central_meridian", u.central_meridian)
            .value("dlon", u.dlon),
    );
    s.step(coefficient_step(&series, true));
    s.step(
        Step::new(
            "Conformal latitude",
            "The ellipsoid is first mapped conformally onto a sphere: τ = tan φ becomes τ′ = tan χ, computed exactly (not by a series).",
        )
        .formula(
            r"\tau = \tan\varphi,\quad \sigma = \sinh\!\left(e \,\operatorname{atanh}\frac{e\,\tau}{\sqrt{1+\tau^2}}\right),\quad \tau' = \tau\sqrt{1+\sigma^2} - \sigma\sqrt{1+\tau^2}",
            format!(
                r"\tau = {},\quad \sigma = {},\quad \tau' = {}\quad(\chi = {}^\circ)",
                fmt_sig(tm.tau, 14),
                fmt_sig(tm.sigma, 14),
                fmt_sig(tm.tau_prime, 14),
                fmt_sig(tm.tau_prime.atan().to_degrees(), 12)
            ),
        )
        .value("tau", tm.tau)
        .value("sigma", tm.sigma)
        .value("tau_prime", tm.tau_prime),
    );
    s.step(
        Step::new(
            "Transverse Mercator on the sphere",
            "The Gauss–Schreiber coordinates ξ′ (along the central meridian) and η′ (across it), both in units of the sphere's radius.",
        )
        .formula(
            r"\xi' = \operatorname{atan2}(\tau', \cos\Delta\lambda),\quad \eta' = \operatorname{asinh}\frac{\sin\Delta\lambda}{\sqrt{\tau'^2 + \cos^2\Delta\lambda}}",
            format!(
                r"\xi' = {},\quad \eta' = {}",
                fmt_sig(tm.xi_prime, 14),
                fmt_sig(tm.eta_prime, 14)
            ),
        )
        .value("xi_prime", tm.xi_prime)
        .value("eta_prime", tm.eta_prime),
    );
    s.step(
        Step::new(
            "Krüger's series",
            "From the sphere back to the ellipsoid: six terms of a series in the complex number ζ′ = ξ′ + iη′, written out in real and imaginary parts.",
        )
        .formula(
            r"\xi = \xi' + \sum_{j=1}^{6} \alpha_j \sin 2j\xi' \cosh 2j\eta',\quad \eta = \eta' + \sum_{j=1}^{6} \alpha_j \cos 2j\xi' \sinh 2j\eta'",
            format!(
                r"\xi = \xi' + {} = {},\quad \eta = \eta' + {} = {}",
                par(sci(tm.xi - tm.xi_prime, 10)),
                fmt_sig(tm.xi, 14),
                par(sci(tm.eta - tm.eta_prime, 10)),
                fmt_sig(tm.eta, 14)
            ),
        )
        .value("xi", tm.xi)
        .value("eta", tm.eta),
    );
    s.step(
        Step::new(
            "Easting and northing",
            &format!(
                "Scaled by k₀ = 0.9996 and the rectifying radius; 500 000 m is added so that eastings are positive{}.",
                if u.hemisphere == Hemisphere::South {
                    ", and 10 000 000 m in the southern hemisphere so that northings are too"
                } else {
                    "; north of the equator the northing is y itself"
                }
            ),
        )
        .formula(
            r"x = k_0 A \eta,\quad y = k_0 A \xi,\quad E = 500\,000 + x,\quad N = N_0 + y",
            format!(
                r"x = 0.9996 \times {} \times {} = {}\ \text{{m}},\quad y = {}\ \text{{m}},\quad E = {}\ \text{{m}},\quad N = {} + {} = {}\ \text{{m}}",
                fixed(series.rectifying_radius, 6),
                par(fmt_sig(tm.eta, 14)),
                metres(tm.x),
                metres(tm.y),
                metres(u.easting),
                fixed(u.hemisphere.false_northing(), 0),
                par(metres(tm.y)),
                metres(u.northing)
            ),
        )
        .value("x", tm.x)
        .value("y", tm.y)
        .value("easting", u.easting)
        .value("northing", u.northing),
    );
    s.step(
        Step::new(
            "Meridian convergence and scale factor",
            "From the derivative of the same series: γ is the angle from true north to grid north (clockwise), k how much the map enlarges lengths at the point.",
        )
        .formula(
            r"p' = 1 + \sum 2j\alpha_j \cos 2j\xi' \cosh 2j\eta',\quad q' = \sum 2j\alpha_j \sin 2j\xi' \sinh 2j\eta',\quad \gamma = \operatorname{atan2}(\tau' \sin\Delta\lambda,\quad \sqrt{1+\tau'^2}\cos\Delta\lambda) + \operatorname{atan2}(q', p'),\quad k = k_0 \frac{\sqrt{1-e^2\sin^2\varphi}\,\sqrt{1+\tau^2}}{\sqrt{\tau'^2 + \cos^2\Delta\lambda}}\cdot\frac{A}{a}\sqrt{p'^2+q'^2}",
            format!(
                r"p' = {},\quad q' = {},\quad \gamma = {}^\circ + {}\,{{}}^\circ = {}^\circ,\quad k = 0.9996 \times {} \times {} = {}",
                fmt_sig(tm.p, 14),
                par(sci(tm.q, 10)),
                fmt_sig(tm.gamma_sphere.to_degrees(), 12),
                par(sci(tm.gamma_series.to_degrees(), 10)),
                fmt_sig(tm.gamma.to_degrees(), 12),
                fmt_sig(tm.k_sphere, 14),
                fmt_sig(tm.k_series, 14),
                fmt_sig(tm.k, 14)
            ),
        )
        .value("scale_factor", tm.k)
        .value("convergence", tm.gamma.to_degrees()),
    );

    // the classical series beside it
    let c = snyder::forward(&ell, K0, lat, u.dlon);
    let ce = utm::FALSE_EASTING + c.x;
    let cn = u.hemisphere.false_northing() + c.y;
    let cd = (c.x - tm.x).hypot(c.y - tm.y);
    s.step(
        Step::new(
            "The classical series, for comparison",
            "Snyder's power series in A = Δλ·cos φ (Map Projections — A Working Manual, 1987, eqs. 8-9, 8-10), as many textbooks print it. Near the central meridian it agrees to a millimetre; its error grows quickly with the distance from it.",
        )
        .formula(
            r"x = k_0 N\,(A + c_3 A^3 + c_5 A^5),\quad y = k_0\,\bigl(M + N\tan\varphi\,(\tfrac{A^2}{2} + c_4 A^4 + c_6 A^6)\bigr),\quad c_3 = \frac{1-T+C}{6},\quad c_5 = \frac{5-18T+T^2+72C-58e'^2}{120},\quad c_4 = \frac{5-T+9C+4C^2}{24},\quad c_6 = \frac{61-58T+T^2+600C-330e'^2}{720},\quad N = \frac{a}{\sqrt{1-e^2\sin^2\varphi}},\quad T = \tan^2\varphi,\quad C = e'^2\cos^2\varphi,\quad A = \Delta\lambda\cos\varphi",
            format!(
                r"N = {}\ \text{{m}},\quad T = {},\quad C = {},\quad A = {},\quad M = {}\ \text{{m}};\quad x = {}\ \text{{m}},\quad y = {}\ \text{{m}};\quad \text{{distance from the exact point}} = {}\ \text{{m}}",
                fixed(c.big_n, 4),
                fmt_sig(c.t, 12),
                fmt_sig(c.c, 12),
                fmt_sig(c.a, 12),
                fixed(c.m, 6),
                metres(c.x),
                metres(c.y),
                sci(cd, 4)
            ),
        )
        .value("classical_easting", ce)
        .value("classical_northing", cn)
        .value("classical_difference_m", cd),
    );
    s.step(figure_step(&ell, lat, &u)?);

    s.result = Record::new()
        .with("zone", f64::from(u.zone))
        .with("band", u.band.to_string().as_str())
        .with("hemisphere", u.hemisphere.name())
        .with("central_meridian", u.central_meridian)
        .with("easting", u.easting)
        .with("northing", u.northing)
        .with("scale_factor", tm.k)
        .with("convergence", tm.gamma.to_degrees())
        .with(
            "utm_text",
            format!(
                "{}{} {} m E, {} m N",
                u.zone,
                u.band,
                plain(u.easting, 3),
                plain(u.northing, 3)
            )
            .as_str(),
        )
        .with("latitude_dms", dms::format(lat, 'N', 'S', 4).as_str())
        .with("longitude_dms", dms::format(lon, 'E', 'W', 4).as_str())
        .with("standard_zone", f64::from(u.standard_zone))
        .with("zone_rule", rule_text(u.rule))
        .with("in_legal_range", u.legal)
        .with("classical_easting", ce)
        .with("classical_northing", cn)
        .with("classical_difference_m", cd);
    label_results(&mut s);

    if !u.legal {
        s.note(
            NoteKind::Warning,
            format!(
                "E = {} m, N = {} m is outside the legal UTM range (E 100 000–900 000 m; N 0–9 500 000 m north, 1 000 000–10 000 000 m south). The numbers are still the exact transverse Mercator, but no UTM map sheet holds them{}.",
                plain(u.easting, 3),
                plain(u.northing, 3),
                if u.rule == ZoneRule::Forced {
                    format!("; the point's own zone is {}", u.standard_zone)
                } else {
                    String::new()
                }
            ),
        );
    }
    if u.dlon.abs() > 3.0 + 1e-12 && u.rule != ZoneRule::Svalbard {
        s.note(
            NoteKind::Warning,
            format!(
                "The point is {}° from the central meridian, outside the 6° zone: the scale factor is {} ({:+.0} ppm), and the classical series is {} m off here.",
                fmt_sig(u.dlon.abs(), 8),
                fmt_sig(tm.k, 10),
                (tm.k - 1.0) * 1e6,
                fmt_sig(cd, 3)
            ),
        );
    }
    s.note(
        NoteKind::Convention,
        "Latitude 0 counts as north (band N, false northing 0). Longitudes beyond ±180° are refused, not wrapped; 180° and −180° are the same meridian and both lie in zone 1, as in GeographicLib.",
    );
    if is_seed(&utm_fields(), inputs) {
        s.textbook = Some(Record::new().with("zone", 47.0));
        s.note(
            NoteKind::Convention,
            "The lecture gives no coordinates, only \"Thailand: Zone 47\"; this default point is Bangkok (13°45′N, 100°30′E), which is indeed in zone 47. Eastern Thailand (east of 102°E) is in zone 48: see the example \"Lecture 7's UTM facts, checked\".",
        );
    }
    Ok(s)
}

// ---------------------------------------------------------------------------
// utm-inverse: UTM → geographic

fn solve_inverse(inputs: &Record) -> Result<Solution> {
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
    let (e, n) = (i.number("easting")?, i.number("northing")?);
    let ell = ellipsoid(&i)?;
    let inv = utm::inverse(&ell, zone, hemisphere, e, n)?;
    let series = Series::new(&ell);
    let tm = inv.tm;
    let mut s = Solution::new(
        "utm-inverse",
        "UTM to latitude and longitude",
        inputs.clone(),
    );
    s.step(ellipsoid_step(&ell));
    s.step(
        Step::new(
            "Remove the false easting and northing",
            "x is measured east of the central meridian, y north of the equator.",
        )
        .formula(
            r"\lambda_0 = 6\cdot\text{zone} - 183,\quad x = E - 500\,000,\quad y = N - N_0",
            format!(
                r"\lambda_0 = 6\cdot{zone} - 183 = {}^\circ,\quad x = {} - 500\,000 = {}\ \text{{m}},\quad y = {} - {} = {}\ \text{{m}}",
                inv.central_meridian,
                metres(e),
                metres(inv.x),
                metres(n),
                fixed(hemisphere.false_northing(), 0),
                metres(inv.y)
            ),
        )
        .value("x", inv.x)
        .value("y", inv.y)
        .value("central_meridian", inv.central_meridian),
    );
    s.step(coefficient_step(&series, false));
    s.step(
        Step::new(
            "Back to the sphere",
            "ξ and η are the map coordinates in units of k₀A; the β series undoes Krüger's series.",
        )
        .formula(
            r"\xi = \frac{y}{k_0 A},\quad \eta = \frac{x}{k_0 A},\quad \xi' = \xi - \sum_{j=1}^{6}\beta_j \sin 2j\xi\cosh 2j\eta,\quad \eta' = \eta - \sum_{j=1}^{6}\beta_j\cos 2j\xi \sinh 2j\eta",
            format!(
                r"\xi = {},\quad \eta = {},\quad \xi' = {},\quad \eta' = {}",
                fmt_sig(tm.xi, 14),
                fmt_sig(tm.eta, 14),
                fmt_sig(tm.xi_prime, 14),
                fmt_sig(tm.eta_prime, 14)
            ),
        )
        .value("xi", tm.xi)
        .value("eta", tm.eta)
        .value("xi_prime", tm.xi_prime)
        .value("eta_prime", tm.eta_prime),
    );
    s.step(
        Step::new(
            "Conformal latitude and longitude",
            "On the sphere the inverse is closed: τ′ = tan χ and the longitude difference.",
        )
        .formula(
            r"\tau' = \frac{\sin\xi'}{\sqrt{\sinh^2\eta' + \cos^2\xi'}},\quad \Delta\lambda = \operatorname{atan2}(\sinh\eta', \cos\xi')",
            format!(
                r"\tau' = {},\quad \Delta\lambda = {}^\circ",
                fmt_sig(tm.tau_prime, 14),
                fmt_sig(tm.dlon_deg, 12)
            ),
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
        .formula(
            r"\tau_{i+1} = \tau_i + \frac{(\tau' - \tau'(\tau_i))\,(1 + (1-e^2)\tau_i^2)}{(1-e^2)\sqrt{1+\tau_i^2}\,\sqrt{1+\tau'(\tau_i)^2}},\quad \varphi = \arctan\tau,\quad \lambda = \lambda_0 + \Delta\lambda",
            format!(
                r"\tau = {},\quad \varphi = {}^\circ,\quad \lambda = {} + {} = {}^\circ",
                fmt_sig(tm.tau, 14),
                fmt_sig(inv.latitude, 13),
                inv.central_meridian,
                par(fmt_sig(tm.dlon_deg, 12)),
                fmt_sig(inv.longitude, 13)
            ),
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
        .formula(
            r"\gamma = \operatorname{atan2}(q, p) + \operatorname{atan2}(\sin\xi'\tanh\eta', \cos\xi'),\quad k = k_0\,\frac{A}{a}\,\frac{w}{\sqrt{p^2+q^2}},\quad w = \sqrt{1 - e^2 + \frac{e^2}{1+\tau^2}}\,\sqrt{1+\tau^2}\,\sqrt{\sinh^2\eta'+\cos^2\xi'}",
            format!(
                r"p = {},\quad q = {},\quad \gamma = {}^\circ,\quad k = {}",
                fmt_sig(tm.p, 14),
                par(sci(tm.q, 10)),
                fmt_sig(tm.gamma.to_degrees(), 12),
                fmt_sig(tm.k, 14)
            ),
        )
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
        .formula(
            r"\mu = \frac{M}{a(1-e^2/4-3e^4/64-5e^6/256)},\quad \varphi_1 = \mu + \left(\tfrac{3e_1}{2}-\tfrac{27e_1^3}{32}\right)\sin 2\mu + \dots,\quad \varphi = \varphi_1 - \frac{N_1\tan\varphi_1}{R_1}\left[\tfrac{D^2}{2} - \dots\right],\quad \Delta\lambda = \frac{D - (1+2T_1+C_1)D^3/6 + \dots}{\cos\varphi_1}",
            format!(
                r"\varphi_1 = {}^\circ,\quad D = {},\quad \varphi = {}^\circ,\quad \lambda = {}^\circ\quad(\text{{largest difference}}\ {}\,{{}}^\circ)",
                fmt_sig(c.phi1.to_degrees(), 12),
                fmt_sig(c.d, 12),
                fmt_sig(c.lat_deg, 12),
                fmt_sig(inv.central_meridian + c.dlon_deg, 12),
                sci(cd, 3)
            ),
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
    label_results(&mut s);
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
    if is_seed(&inverse_fields(), inputs) {
        s.note(
            NoteKind::Convention,
            "The default easting and northing are those of the \"Latitude and longitude to UTM\" example's default point (Bangkok, 13°45′N 100°30′E, WGS 84), rounded to the millimetre: the inverse returns that point to within about 10⁻⁸°.",
        );
    }
    Ok(s)
}
