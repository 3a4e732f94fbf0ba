//! Lecture 7's UTM facts, checked: where the scale factor is 1, the scale at
//! 90 km, the width of a zone and the distortion at its edge, the latitude
//! limits, the false easting and northing, and the zones it names for
//! Thailand and Pakistan, with the seed's printed values beside the exact
//! ones and a note for every difference; and its practice on a drawn
//! parallel.

use super::super::drill::{drill, or_given, value_in, BoxDef, Drill, Mistake, Rng, Tolerance};
use super::super::fields::{is_seed, Field, Inputs};
use super::super::Example;
use super::*;
use crate::projection::dms;
use crate::projection::krueger;
use crate::projection::utm::{self, K0};
use crate::solution::{steps_wanted, NoteKind, Record, Solution};

pub const EXAMPLE: Example = Example {
    id: "utm-facts",
    title: "Lecture 7's UTM facts, checked",
    source: "Lecture 7: Image processing, UTM",
    summary: "Where the scale factor is 1, how wide a zone is at a latitude, the distortion at its edge, the latitude limits and the zones of Thailand and Pakistan: the lecture's numbers beside the exact ones.",
    fields,
    solve,
    answer: &["k1_distance_km", "latitude_max", "edge_distortion_ppm"],
    labels: FACT_LABELS,
    lab: None,
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

/// Longitude extents of the countries the seed names (degrees east), from
/// their westernmost and easternmost points.
const THAILAND: (f64, f64) = (97.34, 105.64);
const PAKISTAN: (f64, f64) = (60.87, 77.84);
/// The seed's "1.0000 at a distance of 90 kilometers".
const SEED_K1_KM: f64 = 90.0;

/// What the result keys mean.
const FACT_LABELS: &[(&str, &str, &str)] = &[
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
];

fn fields() -> Vec<Field> {
    vec![
        latitude_field(0.0).help(
            "The parallel along which the zone is measured (0 = the equator); degrees or degrees, minutes, seconds.",
        ),
        ellipsoid_field(),
    ]
}

/// The zones of a band of longitudes, as numbers.
fn zones_between(band: (f64, f64)) -> Vec<f64> {
    utm::zones_between(band.0, band.1)
        .into_iter()
        .map(f64::from)
        .collect()
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
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());
    let on_cm = krueger::forward(&ell, K0, lat, 0.0)?;
    let edge = krueger::forward(&ell, K0, lat, 3.0)?;

    // where k = 1
    let d1 = utm::k_one_dlon(&ell, lat)?;
    let at1 = krueger::forward(&ell, K0, lat, d1)?;
    let k1_km = at1.x / 1000.0;
    let sphere_km = utm::sphere_k_one_distance(ell.a) / 1000.0;
    s.step(
        Step::new(
            "Where the scale factor is 1",
            "On the central meridian k = k₀ = 0.9996; k grows with the square of the distance x from it. Along this parallel, k = 1 where the bisection below puts it; on a sphere of radius a it would be where cosh(x/(k₀a)) = 1/k₀.",
        )
        .relation(
            Relation::new("k(x)")
                .op(r"\approx")
                .sym(r"k_0 \cosh\frac{x}{k_0 a}"),
        )
        .relation(
            Relation::new(r"\Delta\lambda_{k=1}")
                .key("k1_longitude_offset")
                .result(deg(fmt_sig(d1, 10))),
        )
        .relation(
            Relation::new("x_{k=1}")
                .key("k1_distance_km")
                .result(with_unit(&fixed(k1_km, 3), "km")),
        )
        .relation(
            Relation::new(r"x_{k=1}^{\text{sphere}}")
                .sym(r"k_0 a\,\operatorname{acosh}\frac{1}{k_0}")
                .subst(format!(
                    r"0.9996 \times {}\ \text{{km}} \times \operatorname{{acosh}}\frac{{1}}{{0.9996}}",
                    fixed(ell.a / 1000.0, 3)
                ))
                .result(with_unit(&fixed(sphere_km, 3), "km")),
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
        .relation(
            Relation::new(r"k(x = 90\ \text{km})")
                .key("k_at_90km")
                .result(fmt_sig(at90.k, 10)),
        )
        .relation(
            Relation::new(r"k(x = 90\ \text{km})")
                .op(r"\approx")
                .sym(r"k_0\left(1 + \frac{x^2}{2R^2}\right)")
                .subst(r"0.9996\,(1 + 90^2/(2\cdot 6371^2))")
                .result(fmt_sig(
                    K0 * (1.0 + 90f64.powi(2) / (2.0 * 6371f64.powi(2))),
                    7,
                )),
        )
        .value("k_at_90km", at90.k)
        .value("k_at_90km_ppm", (at90.k - 1.0) * 1e6),
    );

    // the zone's width and its edge
    let width_map = 2.0 * edge.x / 1000.0;
    let nu = ell.prime_vertical_radius(lat);
    let width_ground = ell.parallel_radius(lat) * 6f64.to_radians() / 1000.0;
    s.step(
        Step::new(
            "A zone's width at this latitude",
            &format!(
                "A zone spans 6° of longitude; on the ground that is an arc of the parallel at latitude {}, of radius N cos φ; on the map it is twice the edge's x.",
                dms::format(lat, 'N', 'S', 0)
            ),
        )
        .relation(
            Relation::new(r"w_{\text{ground}}")
                .key("zone_width_ground_km")
                .sym(r"N\cos\varphi\cdot 6^\circ\tfrac{\pi}{180}")
                .subst(format!(
                    r"{}\ \text{{km}} \cdot \cos {} \cdot 6\tfrac{{\pi}}{{180}}",
                    fixed(nu / 1000.0, 4),
                    deg(par(fmt_sig(lat, 12)))
                ))
                .result(with_unit(&fixed(width_ground, 3), "km")),
        )
        .relation(
            Relation::new("N")
                .sym(r"\frac{a}{\sqrt{1-e^2\sin^2\varphi}}")
                .result(with_unit(&fixed(nu, 3), "m")),
        )
        .relation(
            Relation::new(r"w_{\text{map}}")
                .key("zone_width_km")
                .sym(r"2\,x(\Delta\lambda = 3^\circ)")
                .subst(format!(
                    r"2 \times {}",
                    with_unit(&fixed(edge.x / 1000.0, 3), "km")
                ))
                .result(with_unit(&fixed(width_map, 3), "km")),
        )
        .value("zone_width_ground_km", width_ground)
        .value("zone_width_km", width_map),
    );
    s.step(
        Step::new(
            "The distortion at the zone's edge",
            "The scale factor 3° from the central meridian, and how many millimetres per kilometre (parts per million) the map lengthens or shortens there.",
        )
        .relation(
            Relation::new(r"k_{\text{edge}}")
                .key("edge_scale_factor")
                .sym(r"k(\Delta\lambda = 3^\circ)")
                .result(fmt_sig(edge.k, 10)),
        )
        .relation(
            Relation::new(r"\text{distortion}")
                .key("edge_distortion_ppm")
                .sym(r"(k_{\text{edge}} - 1)\cdot 10^6\ \text{ppm}")
                .subst(format!(r"({} - 1)\cdot 10^6", fmt_sig(edge.k, 10)))
                .result(with_unit(&fmt_sig((edge.k - 1.0) * 1e6, 6), "ppm")),
        )
        .relation(
            Relation::new(r"\text{distortion}_{\text{centre}}")
                .result(with_unit(&fmt_sig((on_cm.k - 1.0) * 1e6, 6), "ppm")),
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
        .relation(
            Relation::new("d")
                .key("wgs84_grs80_difference_mm")
                .sym(r"\max_{\Delta\lambda\in\{0, 1.5^\circ, 3^\circ\}} \left|(x, y)_{\text{WGS 84}} - (x, y)_{\text{GRS 80}}\right|")
                .result(with_unit(&fmt_sig(wg * 1000.0, 4), "mm")),
        )
        .relation(
            Relation::new(r"d_{80^\circ\text{S}\ldots 84^\circ\text{N}}")
                .key("wgs84_grs80_difference_max_mm")
                .result(with_unit(&fmt_sig(wg_all * 1000.0, 4), "mm")),
        )
        .value("wgs84_grs80_difference_mm", wg * 1000.0)
        .value("wgs84_grs80_difference_max_mm", wg_all * 1000.0),
    );

    let thai = zones_between(THAILAND);
    let pak = zones_between(PAKISTAN);
    let span = |z: &[f64]| {
        format!(
            r"{} \ldots {}",
            z.first().copied().unwrap_or(0.0),
            z.last().copied().unwrap_or(0.0)
        )
    };
    s.step(
        Step::new(
            "The zones of Thailand and Pakistan",
            &format!(
                "Thailand spans {}°E to {}°E, Pakistan {}°E to {}°E; zone z covers 6z − 186 to 6z − 180 degrees.",
                THAILAND.0, THAILAND.1, PAKISTAN.0, PAKISTAN.1
            ),
        )
        .relation(
            Relation::new(r"\text{zone}")
                .sym(r"\left\lfloor\frac{\lambda^\circ + 180}{6}\right\rfloor + 1"),
        )
        .relation(
            Relation::new(r"\text{Thailand}")
                .key("zones_thailand")
                .op(":")
                .result(span(&thai)),
        )
        .relation(
            Relation::new(r"\text{Pakistan}")
                .key("zones_pakistan")
                .op(":")
                .result(span(&pak)),
        )
        .value("zones_thailand", Value::numbers(&thai))
        .value("zones_pakistan", Value::numbers(&pak)),
    );

    // a figure: the zone at this latitude, the point on its eastern edge
    let u = utm::forward(&ell, lat, 6.0, Some(31))?;
    let mut k_profile = Vec::new();
    // the figure's data only (a sweep's series builds no steps); within
    // 3.5° of the meridian at this latitude it cannot fail
    let last = if steps_wanted() { 140 } else { -1 };
    for j in 0..=last {
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

// ---------------------------------------------------------------------------
// Practice: the zone's width, the distortion at its edge and the lines of
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

fn generate(rng: &mut Rng) -> Record {
    // a parallel with two decimals, 0.5° to 79.5° from the equator either way
    // (the poles' zones are slivers: N cos φ small)
    let lat = decimals(rng, 0.5, 79.5, 2) * if rng.coin() { 1.0 } else { -1.0 };
    Record::new()
        .with("latitude", lat)
        .with("ellipsoid", rng.pick(FACTS_ELLIPSOIDS))
}

fn boxes(_: &Record) -> Vec<BoxDef> {
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

/// The solver's values, and the later boxes from the student's earlier ones.
fn chain(i: &Record, g: &Record) -> Result<Record> {
    let s = EXAMPLE.run(i)?;
    let v = |k: &str| value_in(&s, k);
    let ell = ellipsoid(&Inputs(i))?;
    let lat = n(i, "latitude");
    let r = ell.gaussian_radius(lat);
    let (ground, map) = (v("zone_width_ground_km")?, v("zone_width_km")?);
    // The map width from the student's ground width: the same stretch.
    let ground_given = or_given(g, "zone_width_ground_km", ground);
    let map_given = or_given(g, "zone_width_km", map * ground_given / ground);
    // k at the edge from the student's map width, on the Gaussian sphere
    // (tied to the exact k at the exact width).
    let k_sphere = |w_km: f64| utm::sphere_scale_at(w_km * 500.0, r);
    let k_edge = or_given(
        g,
        "edge_scale_factor",
        v("edge_scale_factor")? * k_sphere(map_given) / k_sphere(map),
    );
    // where k = 1, and the Δλ at the student's distance along the parallel
    let x1 = or_given(g, "k1_distance_km", v("k1_distance_km")?);
    let d1 = if g.number("k1_distance_km").is_some() {
        utm::dlon_at_x(&ell, lat, x1 * 1000.0)?
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

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let ell = ellipsoid(&Inputs(i))?;
    let lat = n(i, "latitude");
    let exact = chain(i, &Record::new())?;
    let v = |k: &str| exact.number(k).unwrap_or(f64::NAN);
    let parallel = ell.parallel_radius(lat);
    let nu = ell.prime_vertical_radius(lat);
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
