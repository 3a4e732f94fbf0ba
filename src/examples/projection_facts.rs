//! Lecture 7's UTM facts, checked: where the scale factor is 1, the scale at
//! 90 km, the width of a zone and the distortion at its edge, the latitude
//! limits, the false easting and northing, and the zones it names for
//! Thailand and Pakistan, with the seed's printed values beside the exact
//! ones and a note for every difference.

use super::fields::{is_seed, Field, Inputs};
use super::projection::{ellipsoid, ellipsoid_field, fixed, label_results, latitude_field, plain};
use super::Example;
use crate::error::{Error, Result};
use crate::projection::krueger;
use crate::projection::utm::{self, K0};
use crate::projection::{dms, Ellipsoid};
use crate::solution::{fmt_sig, NoteKind, Record, Solution, Step, Value};

/// Longitude extents of the countries the seed names (degrees east), from
/// their westernmost and easternmost points.
const THAILAND: (f64, f64) = (97.34, 105.64);
const PAKISTAN: (f64, f64) = (60.87, 77.84);
/// The seed's "1.0000 at a distance of 90 kilometers".
const SEED_K1_KM: f64 = 90.0;

/// Lecture 7's UTM facts.
pub const EXAMPLE: Example = Example {
    id: "utm-facts",
    title: "Lecture 7's UTM facts, checked",
    source: "Lecture 7: Image processing, UTM",
    summary: "Where the scale factor is 1, how wide a zone is at a latitude, the distortion at its edge, the latitude limits and the zones of Thailand and Pakistan: the lecture's numbers beside the exact ones.",
    fields,
    solve,
    answer: &["k1_distance_km", "latitude_max", "edge_distortion_ppm"],
    labels: &[],
    lab: None,
    practice: None,
};

fn fields() -> Vec<Field> {
    vec![
        latitude_field(0.0).help(
            "The parallel along which the zone is measured (0 = the equator); degrees or degrees, minutes, seconds.",
        ),
        ellipsoid_field(),
    ]
}

/// The zones a band of longitudes [west, east] touches (regular rule).
fn zones_between(west: f64, east: f64) -> Vec<f64> {
    let first = utm::standard_zone(0.0, west).0;
    let last = utm::standard_zone(0.0, east).0;
    (first..=last).map(f64::from).collect()
}

/// The longitude difference on parallel `lat` where k = 1 (bisection; k
/// grows with |Δλ| along a parallel).
fn k_one_dlon(ell: &Ellipsoid, lat: f64) -> Result<f64> {
    let (mut lo, mut hi) = (0.0, 30.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if krueger::forward(ell, K0, lat, mid)?.k < 1.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

fn solve(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let lat = i.number("latitude")?;
    let ell = ellipsoid(&i)?;
    if !(utm::LAT_MIN..=utm::LAT_MAX).contains(&lat) {
        return Err(Error::input(
            "latitude",
            format!("UTM covers 80°S to 84°N only (got {}°)", fmt_sig(lat, 12)),
        ));
    }
    let mut s = Solution::new(
        "utm-facts",
        "Lecture 7's UTM facts, checked",
        inputs.clone(),
    );
    let on_cm = krueger::forward(&ell, K0, lat, 0.0)?;
    let edge = krueger::forward(&ell, K0, lat, 3.0)?;

    // where k = 1
    let d1 = k_one_dlon(&ell, lat)?;
    let at1 = krueger::forward(&ell, K0, lat, d1)?;
    let k1_km = at1.x / 1000.0;
    let sphere_km = K0 * ell.a / 1000.0 * (1.0 / K0).acosh();
    s.step(
        Step::new(
            "Where the scale factor is 1",
            "On the central meridian k = k₀ = 0.9996; k grows with the square of the distance x from it. Along this parallel, k = 1 where the bisection below puts it; on a sphere of radius a it would be where cosh(x/(k₀a)) = 1/k₀.",
        )
        .formula(
            r"k(x) \approx k_0 \cosh\frac{x}{k_0 a}\ \Rightarrow\ k = 1\ \text{at}\ x \approx k_0 a\,\operatorname{acosh}\frac{1}{k_0}",
            format!(
                r"k = 1\ \text{{at}}\ \Delta\lambda = {}^\circ,\quad x = {}\ \text{{km}}\quad(\text{{sphere: }} {}\ \text{{km}})",
                fmt_sig(d1, 10),
                fixed(k1_km, 3),
                fixed(sphere_km, 3)
            ),
        )
        .value("k1_distance_km", k1_km)
        .value("k1_longitude_offset", d1),
    );

    // k at 90 km
    let at90 = krueger::inverse(&ell, K0, SEED_K1_KM * 1000.0, on_cm.y)?;
    s.step(
        Step::new(
            "The scale factor 90 km from the central meridian",
            "What the lecture's distance gives: the inverse series at x = 90 km on this parallel's northing.",
        )
        .formula(
            r"k(x = 90\ \text{km}) \approx k_0\left(1 + \frac{x^2}{2R^2}\right)",
            format!(
                r"k = {}\ \ (\approx 0.9996\,(1 + 90^2/(2\cdot 6371^2)) = {})",
                fmt_sig(at90.k, 10),
                fmt_sig(K0 * (1.0 + 90f64.powi(2) / (2.0 * 6371f64.powi(2))), 7)
            ),
        )
        .value("k_at_90km", at90.k)
        .value("k_at_90km_ppm", (at90.k - 1.0) * 1e6),
    );

    // the zone's width and its edge
    let width_map = 2.0 * edge.x / 1000.0;
    let nu = ell.a / (1.0 - ell.e2() * lat.to_radians().sin().powi(2)).sqrt();
    let width_ground = nu * lat.to_radians().cos() * 6f64.to_radians() / 1000.0;
    s.step(
        Step::new(
            "A zone's width at this latitude",
            &format!(
                "A zone spans 6° of longitude; on the ground that is an arc of the parallel at latitude {}, of radius N cos φ; on the map it is twice the edge's x.",
                dms::format(lat, 'N', 'S', 0)
            ),
        )
        .formula(
            r"w_{\text{ground}} = N\cos\varphi\cdot 6^\circ\tfrac{\pi}{180},\quad N = \frac{a}{\sqrt{1-e^2\sin^2\varphi}},\quad w_{\text{map}} = 2\,x(\Delta\lambda = 3^\circ)",
            format!(
                r"w_{{\text{{ground}}}} = {}\ \text{{km}},\quad w_{{\text{{map}}}} = 2 \times {}\ \text{{km}} = {}\ \text{{km}}",
                fixed(width_ground, 3),
                fixed(edge.x / 1000.0, 3),
                fixed(width_map, 3)
            ),
        )
        .value("zone_width_ground_km", width_ground)
        .value("zone_width_km", width_map),
    );
    s.step(
        Step::new(
            "The distortion at the zone's edge",
            "The scale factor 3° from the central meridian, and how many millimetres per kilometre (parts per million) the map lengthens or shortens there.",
        )
        .formula(
            r"k_{\text{edge}} = k(\Delta\lambda = 3^\circ),\quad \text{distortion} = (k_{\text{edge}} - 1)\cdot 10^6\ \text{ppm}",
            format!(
                r"k_{{\text{{edge}}}} = {},\quad ({} - 1)\cdot 10^6 = {}\ \text{{ppm}}\quad(\text{{centre: }}{}\ \text{{ppm}})",
                fmt_sig(edge.k, 10),
                fmt_sig(edge.k, 10),
                fmt_sig((edge.k - 1.0) * 1e6, 6),
                fmt_sig((on_cm.k - 1.0) * 1e6, 6)
            ),
        )
        .value("edge_scale_factor", edge.k)
        .value("edge_distortion_ppm", (edge.k - 1.0) * 1e6),
    );

    // WGS 84 against GRS 80 on this parallel
    let (w, g) = (
        Ellipsoid::by_id("wgs84").ok_or_else(|| Error::Internal("no wgs84".into()))?,
        Ellipsoid::by_id("grs80").ok_or_else(|| Error::Internal("no grs80".into()))?,
    );
    let apart = |la: f64, dl: f64| -> Result<f64> {
        let a = krueger::forward(&w, K0, la, dl)?;
        let b = krueger::forward(&g, K0, la, dl)?;
        Ok((a.x - b.x).hypot(a.y - b.y))
    };
    let mut wg = 0f64;
    for dl in [0.0, 1.5, 3.0] {
        wg = wg.max(apart(lat, dl)?);
    }
    // and anywhere in a zone, 80°S to 84°N
    let mut wg_all = 0f64;
    for j in 0..=41 {
        for dl in [0.0, 3.0] {
            wg_all = wg_all.max(apart(-80.0 + 4.0 * f64::from(j), dl)?);
        }
    }
    s.step(
        Step::new(
            "WGS 84 against GRS 80",
            "The two ellipsoids differ only in the flattening's 10th digit (polar radii 0.105 mm apart). The largest distance between the UTM coordinates of the same latitude and longitude on the two, across the zone on this parallel:",
        )
        .formula(
            r"\max_{\Delta\lambda\in\{0, 1.5^\circ, 3^\circ\}} \left|(x, y)_{\text{WGS 84}} - (x, y)_{\text{GRS 80}}\right|",
            format!(
                r"{}\ \text{{mm}}\quad\text{{anywhere from }}80^\circ\text{{S to }}84^\circ\text{{N:}}\;{}\ \text{{mm}}",
                fmt_sig(wg * 1000.0, 4),
                fmt_sig(wg_all * 1000.0, 4)
            ),
        )
        .value("wgs84_grs80_difference_mm", wg * 1000.0)
        .value("wgs84_grs80_difference_max_mm", wg_all * 1000.0),
    );

    let thai = zones_between(THAILAND.0, THAILAND.1);
    let pak = zones_between(PAKISTAN.0, PAKISTAN.1);
    s.step(
        Step::new(
            "The zones of Thailand and Pakistan",
            &format!(
                "Thailand spans {}°E to {}°E, Pakistan {}°E to {}°E; zone z covers 6z − 186 to 6z − 180 degrees.",
                THAILAND.0, THAILAND.1, PAKISTAN.0, PAKISTAN.1
            ),
        )
        .formula(
            r"\text{zone} = \left\lfloor\frac{\lambda^\circ + 180}{6}\right\rfloor + 1",
            format!(
                r"\text{{Thailand: }} {} \ldots {},\quad \text{{Pakistan: }} {} \ldots {}",
                thai.first().copied().unwrap_or(0.0),
                thai.last().copied().unwrap_or(0.0),
                pak.first().copied().unwrap_or(0.0),
                pak.last().copied().unwrap_or(0.0)
            ),
        )
        .value("zones_thailand", Value::numbers(&thai))
        .value("zones_pakistan", Value::numbers(&pak)),
    );

    // a figure: the zone at this latitude, the point on its eastern edge
    let u = utm::forward(&ell, lat, 6.0, Some(31))?;
    let mut k_profile = Vec::new();
    for j in 0..=140 {
        let dl = -3.5 + 7.0 * f64::from(j) / 140.0;
        let f = krueger::forward(&ell, K0, lat, dl)?;
        k_profile.push(vec![dl, f.x / 1000.0, f.k]);
    }
    s.step(
        Step::new(
            "The scale factor across the zone",
            "k along this parallel from 3.5° west to 3.5° east of the central meridian, drawn in the figure with the two lines where k = 1.",
        )
        .value("k_profile", Value::matrix(&k_profile))
        .value("k1_distance_km", k1_km)
        .value("point_dlon", u.dlon),
    );

    s.result = Record::new()
        .with("k1_distance_km", k1_km)
        .with("k1_longitude_offset", d1)
        .with("k_at_90km", at90.k)
        .with("k_at_90km_ppm", (at90.k - 1.0) * 1e6)
        .with("central_scale_factor", K0)
        .with("zone_width_deg", 6.0)
        .with("zone_width_km", width_map)
        .with("zone_width_ground_km", width_ground)
        .with("edge_scale_factor", edge.k)
        .with("edge_distortion_ppm", (edge.k - 1.0) * 1e6)
        .with("latitude_min", utm::LAT_MIN)
        .with("latitude_max", utm::LAT_MAX)
        .with("false_easting_m", utm::FALSE_EASTING)
        .with("false_northing_south_m", utm::FALSE_NORTHING_SOUTH)
        .with("zones_thailand", Value::numbers(&thai))
        .with("zones_pakistan", Value::numbers(&pak))
        .with("wgs84_grs80_difference_mm", wg * 1000.0)
        .with("wgs84_grs80_difference_max_mm", wg_all * 1000.0);
    label_results(&mut s);
    s.label_present(&[
        (
            "k1_distance_km",
            "Distance from the central meridian where k = 1",
            "km",
        ),
        (
            "k1_longitude_offset",
            "Longitude difference where k = 1",
            "°",
        ),
        (
            "k_at_90km",
            "Scale factor 90 km from the central meridian",
            "",
        ),
        (
            "k_at_90km_ppm",
            "Scale error 90 km from the central meridian, (k − 1)·10⁶",
            "ppm",
        ),
        (
            "central_scale_factor",
            "Scale factor on the central meridian k₀",
            "",
        ),
        ("zone_width_deg", "Zone width", "°"),
        ("zone_width_km", "Zone width on the map", "km"),
        (
            "zone_width_ground_km",
            "Zone width on the ground (along the parallel)",
            "km",
        ),
        ("edge_scale_factor", "Scale factor at the zone edge", ""),
        ("edge_distortion_ppm", "Distortion at the zone edge", "ppm"),
        ("latitude_min", "Southern limit of UTM", "°"),
        ("latitude_max", "Northern limit of UTM", "°"),
        ("false_easting_m", "False easting", "m"),
        ("false_northing_south_m", "False northing in the south", "m"),
        ("zones_thailand", "Zones of Thailand", ""),
        ("zones_pakistan", "Zones of Pakistan", ""),
        (
            "wgs84_grs80_difference_mm",
            "WGS 84 − GRS 80, largest difference on this parallel",
            "mm",
        ),
        (
            "wgs84_grs80_difference_max_mm",
            "WGS 84 − GRS 80, largest difference in any zone",
            "mm",
        ),
    ]);

    s.note(
        NoteKind::Convention,
        "The lecture calls UTM a Gauss–Krüger projection \"with the meridian tangent to the cylinder\". Gauss–Krüger with k₀ = 1 is tangent; UTM's k₀ = 0.9996 shrinks the whole zone so that the map is true to scale on two lines about 180 km either side of the central meridian, as if the cylinder cut the ellipsoid (secant): lengths near the central meridian are 0.04 % short, near the edges up to about 0.1 % long.",
    );
    if is_seed(&fields(), inputs) {
        s.textbook = Some(
            Record::new()
                .with("k1_distance_km", SEED_K1_KM)
                .with("k_at_90km_ppm", 0.0)
                .with("central_scale_factor", 0.9996)
                .with("zone_width_deg", 6.0)
                .with("latitude_min", -80.0)
                .with("latitude_max", 80.0)
                .with("false_easting_m", 500_000.0)
                .with("false_northing_south_m", 10_000_000.0)
                .with("zones_thailand", Value::numbers(&[47.0]))
                .with("zones_pakistan", Value::numbers(&[41.0, 42.0, 43.0])),
        );
        s.note(
            NoteKind::Erratum,
            format!(
                "The lecture says the scale factor is 1.0000 \"at a distance of 90 kilometers from the central meridian\". It is 1 at {} km (on the equator; about k₀·a·acosh(1/k₀) = {} km at any latitude, since k depends almost only on x). At 90 km, k = {}: k − k₀ grows with the square of the distance, so half the distance makes up only a quarter of the 0.0004. The two lines of true scale are about 360 km apart, not 180 km.",
                plain(k1_km, 1),
                plain(sphere_km, 1),
                fmt_sig(at90.k, 6)
            ),
        )
        .about(&["k1_distance_km", "k_at_90km_ppm"]);
        s.note(
            NoteKind::Erratum,
            "The lecture says UTM projects \"from −80 to +80 deg latitude\". The southern limit is right; the northern limit is 84°N (band X is 12° tall, 72°N–84°N, so that UTM reaches the north of Greenland and Svalbard). Beyond both limits the Universal Polar Stereographic (UPS) projection is used.",
        )
        .about(&["latitude_max"]);
        s.note(
            NoteKind::Erratum,
            format!(
                "The lecture gives \"Thailand: Zone 47\". Zone 47 covers 96°E–102°E, western and central Thailand with Bangkok; Thailand reaches {}°E in the east (Ubon Ratchathani province), which is zone 48 (102°E–108°E). Thai maps use both zones. Pakistan ({}°E–{}°E) is zones 41, 42 and 43, as the lecture says.",
                THAILAND.1, PAKISTAN.0, PAKISTAN.1
            ),
        )
        .about(&["zones_thailand"]);
        s.note(
            NoteKind::Convention,
            format!(
                "\"WGS84 and GRS80 is nearly same (several 10cm and meter difference)\": the two ellipsoids give UTM coordinates at most {} mm apart on this parallel and {} mm anywhere from 80°S to 84°N. Decimetre-to-metre differences come from the datums and reference frames (where the ellipsoid sits, e.g. a national datum against WGS 84 or ITRF), not from the ellipsoids' shapes.",
                fmt_sig(wg * 1000.0, 2),
                fmt_sig(wg_all * 1000.0, 2)
            ),
        );
        s.note(
            NoteKind::Convention,
            "The lecture lists \"Everest 19XX\" among the ellipsoids; this playground offers Everest 1830 in its 1937 adjustment (a = 6 377 276.345 m, 1/f = 300.8017, EPSG 7015), the one of Thailand's Indian 1975 datum. Pakistan's Kalianpur datums use other Everest definitions (e.g. 1962: a = 6 377 301.243 m).",
        );
        s.note(
            NoteKind::Rounding,
            "\"500km is added\" and \"10,000km is added\": exactly 500 000 m and 10 000 000 m, the false easting and the southern false northing.",
        );
    }
    Ok(s)
}
