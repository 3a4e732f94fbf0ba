//! Practice for Lecture 7's UTM: latitude and longitude to UTM (through the
//! Krüger series, as the example's steps show it) and back, and the facts
//! (a zone's width, its edge's distortion, where k = 1) on a drawn parallel.
//!
//! Points are drawn inside their zone (0.1° to 2.9° from the central
//! meridian, so near but never on a border), in both hemispheres, and now
//! and then in south-west Norway (zone 32V) or on Svalbard (zones 31X–37X),
//! where the regular zone rule is wrong.
//!
//! Tolerances (a 10-digit calculator, intermediates kept to 10 significant
//! digits): zone and central meridian exact; angles in degrees ± 0.000001°
//! (about 0.1 m on the ground); the dimensionless τ′, ξ′, η′, ξ, η ± 1e-9
//! (6 mm on the ground: k₀A ≈ 6.4·10⁶ m); E and N ± 0.01 m (a centimetre:
//! the last digits of ξ, η typed to 10 digits move them by a few mm); x, y
//! ± 0.001 m (a subtraction); k ± 0.000001 (1 ppm); the convergence
//! ± 0.0001° (0.36″).

use super::{or_given, BoxDef, Mistake, Rng, Spec, Tolerance};
use crate::error::{Error, Result};
use crate::projection::krueger::{self, Series};
use crate::projection::utm::{self, ZoneRule, FALSE_EASTING, FALSE_NORTHING_SOUTH, K0};
use crate::projection::Ellipsoid;
use crate::solution::{Record, Value};

pub fn specs() -> Vec<Spec> {
    vec![
        Spec {
            id: "utm",
            generate: gen_forward,
            boxes: boxes_forward,
            chain: Some(chain_forward),
            mistakes: mistakes_forward,
        },
        Spec {
            id: "utm-inverse",
            generate: gen_inverse,
            boxes: boxes_inverse,
            chain: Some(chain_inverse),
            mistakes: mistakes_inverse,
        },
        Spec {
            id: "utm-facts",
            generate: gen_facts,
            boxes: boxes_facts,
            chain: Some(chain_facts),
            mistakes: mistakes_facts,
        },
    ]
}

const WHOLE: Tolerance = Tolerance::abs(0.0);
const DEGREES: Tolerance = Tolerance::abs(1e-6);
const RATIO: Tolerance = Tolerance::abs(1e-9);
const METRES: Tolerance = Tolerance::abs(0.01);
const SUBTRACTION: Tolerance = Tolerance::abs(0.001);
const SCALE: Tolerance = Tolerance::abs(1e-6);
const CONVERGENCE: Tolerance = Tolerance::abs(1e-4);

fn n(i: &Record, key: &str) -> f64 {
    i.number(key).unwrap_or(f64::NAN)
}

fn text(i: &Record, key: &str) -> String {
    match i.get(key) {
        Some(Value::Text(t)) => t.clone(),
        _ => String::new(),
    }
}

fn ellipsoid(i: &Record) -> Result<Ellipsoid> {
    let id = text(i, "ellipsoid");
    let id = if id.is_empty() { "wgs84".into() } else { id };
    Ellipsoid::by_id(&id).ok_or_else(|| Error::Internal(format!("no ellipsoid \"{id}\"")))
}

/// A number with `d` decimals drawn from `lo..=hi` (in those units).
fn decimals(rng: &mut Rng, lo: f64, hi: f64, d: i32) -> f64 {
    let p = 10f64.powi(d);
    rng.int((lo * p).round() as i64, (hi * p).round() as i64) as f64 / p
}

/// A point (latitude, longitude, degrees with 4 decimals) inside its zone.
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
            let lon = utm::central_meridian(zone) + dlon;
            let lat = decimals(rng, 0.5, 79.5, 4) * if rng.coin() { 1.0 } else { -1.0 };
            // The exceptions are all in the north: mirror such a point south.
            let lat = if utm::standard_zone(lat, lon).1 == ZoneRule::Regular {
                lat
            } else {
                -lat
            };
            (lat, (lon * 1e4).round() / 1e4)
        }
    }
}

fn gen_forward(rng: &mut Rng) -> Record {
    let (lat, lon) = draw_point(rng);
    Record::new()
        .with("latitude", lat)
        .with("longitude", lon)
        .with("ellipsoid", "wgs84")
}

/// The sign flip of a value east or west of the central meridian.
const EAST_WEST: &str = "The size is right but the sign is not: east of the central meridian it is positive, west negative.";
/// The sign flip of the meridian convergence.
const CONVERGENCE_FLIP: &str = "The size is right but the sign is not: γ has the sign of Δλ·sin φ (east of the central meridian in the north, positive).";

fn boxes_forward(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("zone", "Zone", None, WHOLE)
            .nudge("⌊(λ + 180°) / 6°⌋ + 1 — but check the exceptions: zone 32 in south-west Norway (56°–64°N, 3°–12°E), zones 31, 33, 35, 37 on Svalbard (72°–84°N)."),
        BoxDef::new("central_meridian", "Central meridian λ₀", Some("°"), WHOLE)
            .nudge("The middle of the zone: 6·zone − 183°."),
        BoxDef::new("dlon", "Δλ = λ − λ₀", Some("°"), DEGREES)
            .nudge("How far east (+) or west (−) of the central meridian the point is, in degrees.")
            .sign_flip(EAST_WEST),
        BoxDef::new("tau_prime", "τ′ = tan χ (conformal latitude)", None, RATIO)
            .nudge("τ = tan φ, σ = sinh(e·atanh(e·τ/√(1 + τ²))), τ′ = τ√(1 + σ²) − σ√(1 + τ²)."),
        BoxDef::new("xi_prime", "ξ′ (on the sphere)", None, RATIO)
            .nudge("ξ′ = atan2(τ′, cos Δλ), with Δλ in radians."),
        BoxDef::new("eta_prime", "η′ (on the sphere)", None, RATIO)
            .nudge("η′ = asinh(sin Δλ / √(τ′² + cos² Δλ)), with Δλ in radians."),
        BoxDef::new("xi", "ξ (Krüger series)", None, RATIO)
            .nudge("ξ = ξ′ + Σ αⱼ sin 2jξ′ cosh 2jη′ (j = 1 … 6)."),
        BoxDef::new("eta", "η (Krüger series)", None, RATIO)
            .nudge("η = η′ + Σ αⱼ cos 2jξ′ sinh 2jη′."),
        BoxDef::new("easting", "Easting E", Some("m"), METRES)
            .nudge("E = 500 000 m + k₀·A·η, with k₀ = 0.9996 and A the rectifying radius."),
        BoxDef::new("northing", "Northing N", Some("m"), METRES)
            .nudge("N = k₀·A·ξ, plus 10 000 000 m south of the equator (and only there)."),
        BoxDef::new("scale_factor", "Point scale factor k", None, SCALE)
            .nudge("k = k₀·k′·k″: the sphere's factor times the series' factor."),
        BoxDef::new("convergence", "Meridian convergence γ", Some("°"), CONVERGENCE)
            .nudge("γ = γ′ + γ″: atan2(sin Δλ·τ′, cos Δλ·√(1 + τ′²)) plus the series' part atan2(q′, p′); in degrees.")
            .sign_flip(CONVERGENCE_FLIP),
    ]
}

/// The series sums at ζ = ξ + iη with coefficients `c` (as the Krüger
/// module sums them): `(Σ c sin 2jξ cosh 2jη, Σ c cos 2jξ sinh 2jη,
/// Σ 2jc cos 2jξ cosh 2jη, Σ 2jc sin 2jξ sinh 2jη)`.
fn sums(c: &[f64], xi: f64, eta: f64) -> (f64, f64, f64, f64) {
    let mut out = (0.0, 0.0, 0.0, 0.0);
    for (j, &cj) in c.iter().enumerate() {
        let m = 2.0 * (j + 1) as f64;
        let (s, co) = (m * xi).sin_cos();
        let (sh, ch) = ((m * eta).sinh(), (m * eta).cosh());
        out.0 += cj * s * ch;
        out.1 += cj * co * sh;
        out.2 += m * cj * co * ch;
        out.3 += m * cj * s * sh;
    }
    out
}

fn chain_forward(i: &Record, g: &Record) -> Result<Record> {
    let ell = ellipsoid(i)?;
    let s = Series::new(&ell);
    let (lat, lon) = (n(i, "latitude"), n(i, "longitude"));
    let zone = or_given(g, "zone", f64::from(utm::standard_zone(lat, lon).0));
    let cm = or_given(g, "central_meridian", 6.0 * zone - 183.0);
    let dlon = or_given(g, "dlon", utm::lon_diff(lon, cm));
    let phi = lat.to_radians();
    let tau = phi.tan();
    let taup = or_given(g, "tau_prime", krueger::tau_prime(tau, s.e));
    let (sl, cl) = dlon.to_radians().sin_cos();
    let xip = or_given(g, "xi_prime", taup.atan2(cl));
    let etap = or_given(g, "eta_prime", (sl / taup.hypot(cl)).asinh());
    let (a, b, p1, q1) = sums(&s.alpha, xip, etap);
    let xi = or_given(g, "xi", xip + a);
    let eta = or_given(g, "eta", etap + b);
    let false_northing = if lat >= 0.0 {
        0.0
    } else {
        FALSE_NORTHING_SOUTH
    };
    let (p, q) = (1.0 + p1, q1);
    let gamma = (sl * taup).atan2(cl * taup.hypot(1.0)) + q.atan2(p);
    let k_sphere = (1.0 - s.e2 * phi.sin().powi(2)).sqrt() * tau.hypot(1.0) / taup.hypot(cl);
    let k = K0 * k_sphere * s.rectifying_radius / ell.a * p.hypot(q);
    Ok(Record::new()
        .with("zone", zone)
        .with("central_meridian", cm)
        .with("dlon", dlon)
        .with("tau_prime", taup)
        .with("xi_prime", xip)
        .with("eta_prime", etap)
        .with("xi", xi)
        .with("eta", eta)
        .with(
            "easting",
            or_given(g, "easting", FALSE_EASTING + K0 * s.rectifying_radius * eta),
        )
        .with(
            "northing",
            or_given(
                g,
                "northing",
                false_northing + K0 * s.rectifying_radius * xi,
            ),
        )
        .with("scale_factor", or_given(g, "scale_factor", k))
        .with("convergence", gamma.to_degrees()))
}

fn mistakes_forward(i: &Record) -> Result<Vec<Mistake>> {
    let ell = ellipsoid(i)?;
    let (lat, lon) = (n(i, "latitude"), n(i, "longitude"));
    let exact = chain_forward(i, &Record::new())?;
    let v = |k: &str| exact.number(k).unwrap_or(f64::NAN);
    let with = |g: Record, k: &str| -> Result<f64> {
        Ok(chain_forward(i, &g)?.number(k).unwrap_or(f64::NAN))
    };
    let (zone, rule) = utm::standard_zone(lat, lon);
    let zone = f64::from(zone);
    let cm = v("central_meridian");
    let regular = |l: f64| (((l + 180.0) / 6.0).floor() + 1.0).clamp(1.0, 60.0);
    const SWAP: &str =
        "φ is the latitude (north–south), λ the longitude (east–west): the zone comes from λ.";
    const RULE: &str = "South-west Norway (56°–64°N, 3°–12°E) is all zone 32; on Svalbard (72°–84°N, 0°–42°E) only zones 31, 33, 35 and 37 are used.";
    const EDGE: &str =
        "6·zone − 180 is the zone's eastern edge; its central meridian is 6·zone − 183.";
    const OFF: &str =
        "Zone z spans 6z − 186° to 6z − 180°: that meridian belongs to the next zone.";
    const RAD: &str = "Degrees and radians mixed: trigonometric functions need Δλ in radians, the box asks for degrees.";
    const FE: &str = "The false easting: E = 500 000 m + x, so that eastings are never negative.";
    const K0_: &str = "k₀ = 0.9996 scales the whole projection: x = k₀·A·η, y = k₀·A·ξ.";
    let mut out = vec![
        Mistake::new("zone", "latitude and longitude swapped", SWAP, regular(lat)),
        Mistake::new(
            "central_meridian",
            "6·zone − 180 without the −3",
            EDGE,
            6.0 * zone - 180.0,
        ),
        Mistake::new("central_meridian", "zone off by one", OFF, cm - 6.0),
        Mistake::new("central_meridian", "zone off by one", OFF, cm + 6.0),
        Mistake::new("dlon", "degrees vs radians", RAD, v("dlon").to_radians()),
        Mistake::new(
            "dlon",
            "6·zone − 180 without the −3",
            EDGE,
            lon - (6.0 * zone - 180.0),
        ),
        Mistake::new(
            "tau_prime",
            "conformal latitude skipped",
            "τ′ is tan of the conformal latitude χ, not tan φ: apply the σ correction.",
            lat.to_radians().tan(),
        ),
    ];
    if rule != ZoneRule::Regular {
        out.insert(
            0,
            Mistake::new(
                "zone",
                "Norway/Svalbard exception missed",
                RULE,
                regular(lon),
            ),
        );
    }
    // Δλ in degrees fed to sin and cos as if radians.
    let in_degrees = Record::new().with("dlon", v("dlon").to_degrees());
    for key in ["xi_prime", "eta_prime", "easting", "northing"] {
        out.push(Mistake::new(
            key,
            "degrees vs radians",
            RAD,
            with(in_degrees.clone(), key)?,
        ));
    }
    let edge = Record::new().with("central_meridian", 6.0 * zone - 180.0);
    out.push(Mistake::new(
        "easting",
        "6·zone − 180 without the −3",
        EDGE,
        with(edge, "easting")?,
    ));
    for d in [-6.0, 6.0] {
        let g = Record::new().with("central_meridian", cm + d);
        out.push(Mistake::new(
            "easting",
            "zone off by one",
            OFF,
            with(g, "easting")?,
        ));
    }
    let a = Series::new(&ell).rectifying_radius;
    let (xi, eta) = (v("xi"), v("eta"));
    let false_northing = if lat >= 0.0 {
        0.0
    } else {
        FALSE_NORTHING_SOUTH
    };
    out.extend([
        Mistake::new("easting", "false easting forgotten", FE, K0 * a * eta),
        Mistake::new(
            "easting",
            "k₀ = 0.9996 forgotten",
            K0_,
            FALSE_EASTING + a * eta,
        ),
        Mistake::new(
            "northing",
            "k₀ = 0.9996 forgotten",
            K0_,
            false_northing + a * xi,
        ),
        Mistake::new(
            "scale_factor",
            "k₀ = 0.9996 forgotten",
            K0_,
            v("scale_factor") / K0,
        ),
        Mistake::new(
            "convergence",
            "degrees vs radians",
            "That is γ in radians; the box asks for degrees (× 180/π).",
            v("convergence").to_radians(),
        ),
    ]);
    out.push(if lat >= 0.0 {
        Mistake::new(
            "northing",
            "false northing applied in the north",
            "The 10 000 000 m false northing is for the southern hemisphere only.",
            v("northing") + FALSE_NORTHING_SOUTH,
        )
    } else {
        Mistake::new(
            "northing",
            "false northing forgotten",
            "South of the equator N = 10 000 000 m + k₀·A·ξ (ξ is negative there).",
            v("northing") - FALSE_NORTHING_SOUTH,
        )
    });
    // The whole projection with φ and λ swapped, where that is a UTM point.
    if let Ok(f) = utm::forward(&ell, lon, lat, None) {
        out.push(Mistake::new(
            "easting",
            "latitude and longitude swapped",
            SWAP,
            f.easting,
        ));
        out.push(Mistake::new(
            "northing",
            "latitude and longitude swapped",
            SWAP,
            f.northing,
        ));
    }
    Ok(out)
}

fn gen_inverse(rng: &mut Rng) -> Record {
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

fn boxes_inverse(_: &Record) -> Vec<BoxDef> {
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

fn chain_inverse(i: &Record, g: &Record) -> Result<Record> {
    let ell = ellipsoid(i)?;
    let s = Series::new(&ell);
    let ka = K0 * s.rectifying_radius;
    let south = text(i, "hemisphere") == "south";
    let cm = or_given(g, "central_meridian", 6.0 * n(i, "zone") - 183.0);
    let x = or_given(g, "x", n(i, "easting") - FALSE_EASTING);
    let false_northing = if south { FALSE_NORTHING_SOUTH } else { 0.0 };
    let y = or_given(g, "y", n(i, "northing") - false_northing);
    let xi = or_given(g, "xi", y / ka);
    let eta = or_given(g, "eta", x / ka);
    let (a, b, p1, q1) = sums(&s.beta, xi, eta);
    let xip = or_given(g, "xi_prime", xi - a);
    let etap = or_given(g, "eta_prime", eta - b);
    let (p, q) = (1.0 - p1, q1);
    let sh = etap.sinh();
    let c = xip.cos().max(0.0);
    let r = sh.hypot(c);
    let taup = or_given(g, "tau_prime", xip.sin() / r);
    let (tau, _) = krueger::tau_from_tau_prime(taup, s.e)?;
    let dlon = or_given(g, "dlon", sh.atan2(c).to_degrees());
    let gamma = q.atan2(p) + (xip.sin() * etap.tanh()).atan2(c);
    let k = K0 * s.rectifying_radius / ell.a / p.hypot(q)
        * (1.0 - s.e2 + s.e2 / (1.0 + tau * tau)).sqrt()
        * tau.hypot(1.0)
        * r;
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

fn mistakes_inverse(i: &Record) -> Result<Vec<Mistake>> {
    let exact = chain_inverse(i, &Record::new())?;
    let v = |k: &str| exact.number(k).unwrap_or(f64::NAN);
    let ell = ellipsoid(i)?;
    let a = Series::new(&ell).rectifying_radius;
    let zone = n(i, "zone");
    let (e, north) = (n(i, "easting"), n(i, "northing"));
    let south = text(i, "hemisphere") == "south";
    const EDGE: &str =
        "6·zone − 180 is the zone's eastern edge; its central meridian is 6·zone − 183.";
    const OFF: &str = "Zone z spans 6z − 186° to 6z − 180°: its central meridian is 6z − 183°.";
    const RAD: &str = "That is the angle in radians; the box asks for degrees (× 180/π).";
    const K0_: &str = "k₀ = 0.9996 scales the whole projection: divide by k₀·A, not by A.";
    const SWAP: &str = "Latitude is north–south, longitude east–west.";
    let mut out = vec![
        Mistake::new("central_meridian", "6·zone − 180 without the −3", EDGE, 6.0 * zone - 180.0),
        Mistake::new("central_meridian", "zone off by one", OFF, v("central_meridian") - 6.0),
        Mistake::new("central_meridian", "zone off by one", OFF, v("central_meridian") + 6.0),
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
    ];
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

// ---------------------------------------------------------------------------
// utm-facts: the zone's width, the distortion at its edge and the lines of
// true scale, on a drawn parallel and ellipsoid.
//
// What a student computes with a calculator: the ground width N cos φ · 6°
// (N the prime-vertical radius), the map width 2x at Δλ = 3° (x from the
// transverse Mercator series, or k₀·R·atanh(cos φ sin 3°) on the Gaussian
// sphere R = √(MN)), the edge's k ≈ k₀ cosh(x/(k₀R)), its distortion
// (k − 1)·10⁶, where k = 1 (x = k₀R·acosh(1/k₀)) and the longitude
// difference there (x/(k₀N cos φ), the series' first term). The tolerances
// cover those formulas (a test checks them on a thousand variants): ± 0.01 km
// on the widths (10 m), ± 10⁻⁶ on k and ± 1 ppm, ± 0.05 km on the distance
// of true scale, ± (0.0005° + 0.5 %) on its longitude difference (the first
// term alone is 0.4 % short near 80° latitude).

const WIDTH: Tolerance = Tolerance::abs(0.01);
const EDGE_K: Tolerance = Tolerance::abs(1e-6);
const PPM: Tolerance = Tolerance::abs(1.0);
const K1_KM: Tolerance = Tolerance::abs(0.05);
const K1_DEG: Tolerance = Tolerance {
    atol: 0.0005,
    rtol: 0.005,
};

/// The ellipsoids a facts variant is drawn on (WGS 84 most often).
const FACTS_ELLIPSOIDS: &[&str] = &[
    "wgs84",
    "wgs84",
    "wgs84",
    "grs80",
    "international-1924",
    "bessel-1841",
    "clarke-1866",
    "everest-1830",
];

fn gen_facts(rng: &mut Rng) -> Record {
    // a parallel with two decimals, 0.5° to 79.5° from the equator either way
    // (the poles' zones are slivers: N cos φ small)
    let lat = decimals(rng, 0.5, 79.5, 2) * if rng.coin() { 1.0 } else { -1.0 };
    Record::new()
        .with("latitude", lat)
        .with("ellipsoid", rng.pick(FACTS_ELLIPSOIDS))
}

fn boxes_facts(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("zone_width_ground_km", "Zone width on the ground (along the parallel)", Some("km"), WIDTH)
            .nudge("6° of longitude along the parallel: an arc of radius N·cos φ, with N = a/√(1 − e² sin² φ) and the angle in radians."),
        BoxDef::new("zone_width_km", "Zone width on the map", Some("km"), WIDTH)
            .nudge("Twice the easting offset x of the zone's edge (Δλ = 3°): a little more than k₀ times the ground width, because the map stretches away from the central meridian."),
        BoxDef::new("edge_scale_factor", "Scale factor at the zone edge", None, EDGE_K)
            .nudge("k ≈ k₀·cosh(x/(k₀R)) with x half the map width and R = √(MN) the Gaussian radius at this latitude."),
        BoxDef::new("edge_distortion_ppm", "Distortion at the zone edge", Some("ppm"), PPM)
            .nudge("(k − 1)·10⁶: millimetres per kilometre, positive where the map is too long, negative where it is too short (far north or south the edge is nearer than the line of k = 1)."),
        BoxDef::new("k1_distance_km", "Distance from the central meridian where k = 1", Some("km"), K1_KM)
            .nudge("Solve k₀·cosh(x/(k₀R)) = 1 for x."),
        BoxDef::new("k1_longitude_offset", "Longitude difference where k = 1", Some("°"), K1_DEG)
            .nudge("Along the parallel x ≈ k₀·N cos φ·Δλ (Δλ in radians): solve for Δλ, then convert to degrees."),
    ]
}

/// N cos φ, the radius of the parallel, and R = √(MN), the Gaussian radius.
fn radii(ell: &Ellipsoid, lat: f64) -> (f64, f64) {
    let (s, c) = lat.to_radians().sin_cos();
    let w2 = 1.0 - ell.e2() * s * s;
    let nu = ell.a / w2.sqrt();
    let rho = ell.a * (1.0 - ell.e2()) / w2.powf(1.5);
    (nu * c, (rho * nu).sqrt())
}

/// Bisection on `0..30°` for the Δλ where `f(Δλ)` (growing with Δλ)
/// reaches `target` (as the solver finds where k = 1).
fn along_parallel(target: f64, f: impl Fn(f64) -> Result<f64>) -> Result<f64> {
    let (mut lo, mut hi) = (0.0, 30.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if f(mid)? < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// The solver's values, and the later boxes from the student's earlier ones.
fn chain_facts(i: &Record, g: &Record) -> Result<Record> {
    let s = crate::examples::solve("utm-facts", i)?;
    let v = |k: &str| super::value_in(&s, k);
    let ell = ellipsoid(i)?;
    let lat = n(i, "latitude");
    let (_, r) = radii(&ell, lat);
    let (ground, map) = (v("zone_width_ground_km")?, v("zone_width_km")?);
    // The map width from the student's ground width: the same stretch.
    let ground_given = or_given(g, "zone_width_ground_km", ground);
    let map_given = or_given(g, "zone_width_km", map * ground_given / ground);
    // k at the edge from the student's map width, on the Gaussian sphere
    // (tied to the exact k at the exact width).
    let k_sphere = |w_km: f64| K0 * (w_km * 500.0 / (K0 * r)).cosh();
    let k_edge = or_given(
        g,
        "edge_scale_factor",
        v("edge_scale_factor")? * k_sphere(map_given) / k_sphere(map),
    );
    // where k = 1, and the Δλ at the student's distance along the parallel
    let x1 = or_given(g, "k1_distance_km", v("k1_distance_km")?);
    let d1 = if g.number("k1_distance_km").is_some() {
        along_parallel(x1 * 1000.0, |d| Ok(krueger::forward(&ell, K0, lat, d)?.x))?
    } else {
        v("k1_longitude_offset")?
    };
    Ok(Record::new()
        .with("zone_width_ground_km", ground_given)
        .with("zone_width_km", map_given)
        .with("edge_scale_factor", k_edge)
        .with(
            "edge_distortion_ppm",
            or_given(g, "edge_distortion_ppm", (k_edge - 1.0) * 1e6),
        )
        .with("k1_distance_km", x1)
        .with(
            "k1_longitude_offset",
            or_given(g, "k1_longitude_offset", d1),
        ))
}

fn mistakes_facts(i: &Record) -> Result<Vec<Mistake>> {
    let ell = ellipsoid(i)?;
    let lat = n(i, "latitude");
    let exact = chain_facts(i, &Record::new())?;
    let v = |k: &str| exact.number(k).unwrap_or(f64::NAN);
    let (parallel, _) = radii(&ell, lat);
    let nu = parallel / lat.to_radians().cos();
    const COS: &str =
        "Along a parallel the radius is N·cos φ: the meridians close in towards the pole.";
    const RAD: &str = "Degrees and radians mixed: an arc is radius × angle in radians.";
    const HALF: &str = "A zone is 6° wide, 3° either side of its central meridian: the edge is 3° from it, the width 6°.";
    const A_N: &str = "The parallel's radius is N·cos φ with N = a/√(1 − e² sin² φ), the prime-vertical radius, not the equatorial radius a.";
    const GROUND: &str = "That is the width on the ground; on the map the zone is scaled by k₀ and stretched towards its edges (x(3°) on both sides).";
    const K0_: &str =
        "k₀ = 0.9996 scales the whole projection: k = k₀·cosh(x/(k₀R)), not cosh(x/R).";
    const PCT: &str = "ppm is parts per million, (k − 1)·10⁶; (k − 1)·100 is per cent.";
    const SIGN: &str = "(k − 1)·10⁶ is positive where the map is longer than the ground (k > 1), negative where it is shorter.";
    const LECTURE: &str = "The lecture's 90 km is wrong: k − k₀ grows with the square of x, so k reaches 1 only about 180 km from the central meridian.";
    const BOTH: &str = "That is the distance between the two lines of true scale; each is half of it from the central meridian.";
    let edge6 = krueger::forward(&ell, K0, lat, 6.0)?;
    let (k, x1) = (v("edge_scale_factor"), v("k1_distance_km"));
    Ok(vec![
        Mistake::new(
            "zone_width_ground_km",
            "cos φ forgotten",
            COS,
            nu * 6f64.to_radians() / 1000.0,
        ),
        Mistake::new(
            "zone_width_ground_km",
            "degrees vs radians",
            RAD,
            parallel * 6.0 / 1000.0,
        ),
        Mistake::new(
            "zone_width_ground_km",
            "half-zone: 3° for 6°",
            HALF,
            v("zone_width_ground_km") / 2.0,
        ),
        Mistake::new(
            "zone_width_ground_km",
            "a instead of N",
            A_N,
            ell.a * lat.to_radians().cos() * 6f64.to_radians() / 1000.0,
        ),
        Mistake::new(
            "zone_width_km",
            "the ground width, not the map's",
            GROUND,
            v("zone_width_ground_km"),
        ),
        Mistake::new(
            "zone_width_km",
            "half-zone: 3° for 6°",
            HALF,
            v("zone_width_km") / 2.0,
        ),
        Mistake::new(
            "zone_width_km",
            "k₀ = 0.9996 forgotten",
            K0_,
            v("zone_width_km") / K0,
        ),
        Mistake::new("edge_scale_factor", "k₀ = 0.9996 forgotten", K0_, k / K0),
        Mistake::new("edge_scale_factor", "half-zone: 3° for 6°", HALF, edge6.k),
        Mistake::new(
            "edge_distortion_ppm",
            "k₀ = 0.9996 forgotten",
            K0_,
            (k / K0 - 1.0) * 1e6,
        ),
        Mistake::new(
            "edge_distortion_ppm",
            "per cent, not ppm",
            PCT,
            (k - 1.0) * 100.0,
        ),
        Mistake::new("edge_distortion_ppm", "sign flipped", SIGN, (1.0 - k) * 1e6),
        Mistake::new("k1_distance_km", "the lecture's 90 km", LECTURE, 90.0),
        Mistake::new("k1_distance_km", "both lines' separation", BOTH, 2.0 * x1),
        Mistake::new(
            "k1_longitude_offset",
            "degrees vs radians",
            "That is Δλ in radians; the box asks for degrees (× 180/π).",
            v("k1_longitude_offset").to_radians(),
        ),
        Mistake::new(
            "k1_longitude_offset",
            "cos φ forgotten",
            COS,
            (x1 * 1000.0 / (K0 * nu)).to_degrees(),
        ),
    ])
}
