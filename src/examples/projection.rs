//! Seed 004, map projection: geographic → UTM and back step by step through
//! Karney's Krüger series, with Snyder's classical series beside it, and
//! Lecture 7's printed UTM facts checked. Each example is one file beside
//! this one; this file keeps what they share: the ellipsoid and latitude
//! fields, numbers for LaTeX, the ellipsoid and coefficient steps, the
//! result labels and the practice draws and tolerances.

mod figure;
mod utm;
mod utm_facts;
mod utm_inverse;

use super::drill::{Mistake, Rng, Tolerance};
use super::fields::{Field, Inputs};
use super::{Example, Topic};
use crate::error::{Error, Result};
use crate::projection::krueger::Series;
use crate::projection::utm::{self as grid, ZoneRule};
use crate::projection::Ellipsoid;
use crate::solution::{fmt_sig, with_unit, Form, Relation, Step, Value};

const TITLE: &str = "Map projection";

/// The examples of this topic, in page order.
pub const EXAMPLES: &[Example] = &[utm::EXAMPLE, utm_inverse::EXAMPLE, utm_facts::EXAMPLE];

/// The topic: its module (`web/projection/`) and title.
pub const TOPIC: Topic = Topic {
    module: "projection",
    title: TITLE,
    examples: EXAMPLES,
};

/// The ellipsoid choices (`ELLIPSOIDS` in `projection/mod.rs`, same order).
const ELLIPSOID_OPTIONS: &[(&str, &str)] = &[
    ("wgs84", "WGS 84"),
    ("grs80", "GRS 80"),
    ("international-1924", "International 1924 (Hayford)"),
    ("bessel-1841", "Bessel 1841"),
    ("clarke-1866", "Clarke 1866"),
    ("everest-1830", "Everest 1830 (1937 adjustment)"),
];

fn ellipsoid_field() -> Field {
    Field::choice("ellipsoid", "Ellipsoid", ELLIPSOID_OPTIONS, "wgs84")
        .help("The reference ellipsoid of the datum. WGS 84 and GRS 80 differ by 0.1 mm in the polar radius.")
}

fn latitude_field(default: f64) -> Field {
    Field::angle("latitude", "Latitude φ", 90.0, ('N', 'S'), default).help(
        "Degrees (13.75), or degrees, minutes, seconds (13°45'00\"N or 13 45 0); south negative or S.",
    )
}

/// The ellipsoid a validated (or drawn) `ellipsoid` field names.
fn ellipsoid(i: &Inputs) -> Result<Ellipsoid> {
    let id = i.text("ellipsoid")?;
    Ellipsoid::by_id(id).ok_or_else(|| Error::Internal(format!("no ellipsoid \"{id}\"")))
}

/// What the result keys of the forward and inverse examples mean.
const LABELS: &[(&str, &str, &str)] = &[
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
];

// ---------------------------------------------------------------------------
// Numbers for LaTeX

/// A number with `decimals` decimals, thousands separated by `sep`.
fn grouped(x: f64, decimals: usize, sep: &str) -> String {
    let s = format!("{:.*}", decimals, x.abs());
    let (int, frac) = match s.split_once('.') {
        Some((i, f)) => (i, Some(f)),
        None => (s.as_str(), None),
    };
    let mut out = String::new();
    for (k, ch) in int.chars().enumerate() {
        if k > 0 && (int.len() - k) % 3 == 0 {
            out.push_str(sep);
        }
        out.push(ch);
    }
    let sign = if x < 0.0 && s.chars().any(|c| c != '0' && c != '.') {
        "-"
    } else {
        ""
    };
    match frac {
        Some(f) => format!("{sign}{out}.{f}"),
        None => format!("{sign}{out}"),
    }
}

/// A number for LaTeX with `decimals` decimals, thousands separated by
/// thin spaces.
fn fixed(x: f64, decimals: usize) -> String {
    grouped(x, decimals, r"\,")
}

/// A plain-text number with thin spaces between thousands and `d` decimals.
fn plain(x: f64, d: usize) -> String {
    grouped(x, d, "\u{2009}")
}

/// Metres to the micrometre, with the unit.
fn metres(x: f64) -> String {
    with_unit(&fixed(x, 6), "m")
}

/// A number in LaTeX with `sig` significant digits, powers of ten written out.
fn sci(x: f64, sig: usize) -> String {
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

/// Degrees for LaTeX: `12.5^\circ`.
fn deg(x: String) -> String {
    format!(r"{x}^\circ")
}

// ---------------------------------------------------------------------------
// Shared steps

/// The ellipsoid's constants as a step.
fn ellipsoid_step(ell: &Ellipsoid) -> Step {
    Step::new(
        "The ellipsoid",
        &format!(
            "{}: {}. Everything else follows from a and the flattening f: the eccentricity e, the third flattening n (the small number the series are written in) and the polar radius b.",
            ell.name, ell.source
        ),
    )
    .relation(
        Relation::new("f").result(format!(r"\frac{{1}}{{{}}}", fmt_sig(ell.inv_f, 13))),
    )
    .relation(
        Relation::new("e^2")
            .key("e2")
            .sym("f(2-f)")
            .result(fmt_sig(ell.e2(), 12)),
    )
    .relation(
        Relation::new("n")
            .key("n")
            .sym(r"\frac{f}{2-f}")
            .result(fmt_sig(ell.n(), 12)),
    )
    .relation(
        Relation::new("e'^2")
            .key("ep2")
            .sym(r"\frac{e^2}{1-e^2}")
            .result(fmt_sig(ell.ep2(), 12)),
    )
    .relation(
        Relation::new("b")
            .key("b")
            .sym("a(1-f)")
            .result(with_unit(&fixed(ell.b(), 4), "m")),
    )
    .value("a", ell.a)
    .value("inverse_flattening", ell.inv_f)
    .value("e2", ell.e2())
    .value("n", ell.n())
    .value("ep2", ell.ep2())
    .value("b", ell.b())
}

/// The rectifying radius and the six coefficients of the forward (α) or
/// inverse (β) series as a step.
fn coefficient_step(s: &Series, forward: bool) -> Step {
    let (name, key, c, text, first, second) = if forward {
        (
            r"\alpha",
            "alpha",
            s.alpha,
            "The rectifying radius A (the meridian's length is 2πA) and Krüger's coefficients α₁…α₆ (Karney 2011, eq. 35), each a polynomial in n; α_j shrinks like n^j, so six terms reach nanometres.",
            [
                r"\tfrac12 n",
                r"- \tfrac23 n^2",
                r"+ \tfrac{5}{16} n^3",
                r"+ \tfrac{41}{180} n^4",
                r"- \tfrac{127}{288} n^5",
                r"+ \tfrac{7891}{37800} n^6",
            ],
            r"\tfrac{13}{48} n^2 - \tfrac35 n^3 + \dots",
        )
    } else {
        (
            r"\beta",
            "beta",
            s.beta,
            "The rectifying radius A and the coefficients β₁…β₆ of the inverse series (Karney 2011, eq. 36).",
            [
                r"\tfrac12 n",
                r"- \tfrac23 n^2",
                r"+ \tfrac{37}{96} n^3",
                r"- \tfrac{1}{360} n^4",
                r"- \tfrac{81}{512} n^5",
                r"+ \tfrac{96199}{604800} n^6",
            ],
            r"\tfrac{1}{48} n^2 + \tfrac{1}{15} n^3 - \dots",
        )
    };
    let mut step = Step::new(
        if forward {
            "Rectifying radius and the α coefficients"
        } else {
            "Rectifying radius and the β coefficients"
        },
        text,
    )
    .relation(
        Relation::new("A")
            .key("rectifying_radius")
            .sym(r"\frac{a}{1+n}\left(1 + \frac{n^2}{4} + \frac{n^4}{64} + \frac{n^6}{256}\right)")
            .result(with_unit(&fixed(s.rectifying_radius, 6), "m")),
    );
    for (j, x) in c.iter().enumerate() {
        let r = Relation::new(format!("{name}_{}", j + 1));
        let r = match j {
            0 => r.sym(Form::terms(first)),
            1 => r.sym(second),
            _ => r,
        };
        step = step.relation(r.key(&format!("{key}[{}]", j + 1)).result(sci(*x, 10)));
    }
    step.value("rectifying_radius", s.rectifying_radius)
        .value(key, Value::numbers(&c))
}

/// `lhs = sym`, with the numbers `start ± sum = value`: a series' sum added
/// to (`plus`) or taken from where it starts (ξ = ξ′ + Σ…, ξ′ = ξ − Σ…).
fn series_relation(
    lhs: &str,
    key: &str,
    sym: &str,
    start: f64,
    value: f64,
    plus: bool,
) -> Relation {
    let (op, sum) = if plus {
        ("+", value - start)
    } else {
        ("-", start - value)
    };
    Relation::new(lhs)
        .key(key)
        .sym(sym)
        .subst(format!("{} {op} {}", fmt_sig(start, 14), par(sci(sum, 10))))
        .result(fmt_sig(value, 14))
}

/// λ₀ = 6·zone − 183 with the numbers.
fn central_meridian_relation(zone: u8, central_meridian: f64) -> Relation {
    Relation::new(r"\lambda_0")
        .key("central_meridian")
        .sym(r"6\cdot\text{zone} - 183")
        .subst(format!(r"6\cdot {zone} - 183"))
        .result(deg(central_meridian.to_string()))
}

// ---------------------------------------------------------------------------
// Practice: what the drills of the forward and inverse examples share.
//
// Tolerances (a 10-digit calculator, intermediates kept to 10 significant
// digits): zone and central meridian exact; angles in degrees ± 0.000001°
// (about 0.1 m on the ground); the dimensionless τ′, ξ′, η′, ξ, η ± 1e-9
// (6 mm on the ground: k₀A ≈ 6.4·10⁶ m); E and N ± 0.01 m (a centimetre:
// the last digits of ξ, η typed to 10 digits move them by a few mm); x, y
// ± 0.001 m (a subtraction); k ± 0.000001 (1 ppm); the convergence
// ± 0.0001° (0.36″).

const WHOLE: Tolerance = Tolerance::abs(0.0);
const DEGREES: Tolerance = Tolerance::abs(1e-6);
const RATIO: Tolerance = Tolerance::abs(1e-9);
const SCALE: Tolerance = Tolerance::abs(1e-6);
const CONVERGENCE: Tolerance = Tolerance::abs(1e-4);

/// The sign flip of a value east or west of the central meridian.
const EAST_WEST: &str = "The size is right but the sign is not: east of the central meridian it is positive, west negative.";
/// The central meridian taken for the zone's eastern edge.
const EDGE: &str = "6·zone − 180 is the zone's eastern edge; its central meridian is 6·zone − 183.";
/// The sign flip of the meridian convergence.
const CONVERGENCE_FLIP: &str = "The size is right but the sign is not: γ has the sign of Δλ·sin φ (east of the central meridian in the north, positive).";

/// The wrong central meridians of `zone` (exactly `cm`) both projections'
/// practice knows: its eastern edge 6·zone − 180 and the neighbouring
/// zones' meridians (`off` says why in that example's words).
fn meridian_mistakes(zone: f64, cm: f64, off: &'static str) -> [Mistake; 3] {
    [
        Mistake::new(
            "central_meridian",
            "6·zone − 180 without the −3",
            EDGE,
            6.0 * zone - 180.0,
        ),
        Mistake::new("central_meridian", "zone off by one", off, cm - 6.0),
        Mistake::new("central_meridian", "zone off by one", off, cm + 6.0),
    ]
}

/// The false northing of a point at latitude `lat` (0 counts as north).
fn false_northing_at(lat: f64) -> f64 {
    if lat >= 0.0 {
        grid::Hemisphere::North.false_northing()
    } else {
        grid::Hemisphere::South.false_northing()
    }
}

/// A number of a drawn variant (NaN when it has none).
fn n(i: &crate::solution::Record, key: &str) -> f64 {
    i.number(key).unwrap_or(f64::NAN)
}

/// A number with `d` decimals drawn from `lo..=hi` (in those units).
fn decimals(rng: &mut Rng, lo: f64, hi: f64, d: i32) -> f64 {
    let p = 10f64.powi(d);
    rng.int((lo * p).round() as i64, (hi * p).round() as i64) as f64 / p
}

/// A point (latitude, longitude, degrees with 4 decimals) inside its zone:
/// 0.1° to 2.9° from the central meridian (near but never on a border), in
/// both hemispheres, and now and then in south-west Norway (zone 32V) or on
/// Svalbard (zones 31X–37X), where the regular zone rule is wrong.
fn draw_point(rng: &mut Rng) -> (f64, f64) {
    match rng.int(0, 7) {
        // South-west Norway, west of 6°E: zone 32, not the regular 31.
        0 => (decimals(rng, 56.2, 63.8, 4), decimals(rng, 3.2, 5.8, 4)),
        // Svalbard: zones 31, 33, 35, 37 only, each 9° or 12° wide.
        1 => {
            let (west, east) = rng.pick(&[(0.0, 9.0), (9.0, 21.0), (21.0, 33.0), (33.0, 42.0)]);
            (
                decimals(rng, 72.2, 83.8, 4),
                decimals(rng, west + 0.2, east - 0.2, 4),
            )
        }
        _ => {
            let zone = rng.int(1, 60) as u8;
            let dlon = decimals(rng, 0.1, 2.9, 4) * if rng.coin() { 1.0 } else { -1.0 };
            let lon = grid::central_meridian(zone) + dlon;
            let lat = decimals(rng, 0.5, 79.5, 4) * if rng.coin() { 1.0 } else { -1.0 };
            // The exceptions are all in the north: mirror such a point south.
            let lat = if grid::standard_zone(lat, lon).1 == ZoneRule::Regular {
                lat
            } else {
                -lat
            };
            (lat, (lon * 1e4).round() / 1e4)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_grouped_by_thousands() {
        assert_eq!(fixed(1_520_582.494_4, 3), r"1\,520\,582.494");
        assert_eq!(fixed(-662.5, 1), "-662.5");
        assert_eq!(fixed(-0.0001, 2), "0.00");
        assert_eq!(plain(10_000_000.0, 0), "10\u{2009}000\u{2009}000");
        assert_eq!(sci(1.25e-7, 3), r"{1.25\times 10^{-7}}");
        assert_eq!(par("-1".into()), "(-1)");
    }
}
