//! The transverse Mercator and UTM against an independent implementation
//! (GeographicLib 2.1.2's TransverseMercatorProj and GeoConvert, stored in
//! tests/fixtures/ by tests/fixtures/make_utm.sh), the published
//! checkpoints, the zone and band rules, and the worked examples.

use photogrammetry_playground::examples::{catalog, parse_inputs, solve};
use photogrammetry_playground::projection::utm::{self, Hemisphere, ZoneRule};
use photogrammetry_playground::projection::{krueger, snyder, Ellipsoid, ELLIPSOIDS};
use photogrammetry_playground::solution::{NoteKind, Record, Solution, Value};

const K0: f64 = 0.9996;

struct TmRow {
    ell: Ellipsoid,
    lat: f64,
    dlon: f64,
    series: [f64; 4],
    exact: [f64; 4],
}

fn tm_rows() -> Vec<TmRow> {
    let text = include_str!("fixtures/tm_points.txt");
    text.lines()
        .map(|line| {
            let f: Vec<&str> = line.split_whitespace().collect();
            assert_eq!(f.len(), 11, "{line}");
            let n = |i: usize| f[i].parse::<f64>().unwrap();
            TmRow {
                ell: Ellipsoid::by_id(f[0]).unwrap(),
                lat: n(1),
                dlon: n(2),
                series: [n(3), n(4), n(5), n(6)],
                exact: [n(7), n(8), n(9), n(10)],
            }
        })
        .collect()
}

#[test]
fn forward_agrees_with_geographiclib_on_every_ellipsoid_within_a_micrometre() {
    let rows = tm_rows();
    assert_eq!(rows.len(), 828);
    for e in ELLIPSOIDS {
        assert_eq!(
            rows.iter().filter(|r| r.ell.id == e.id).count(),
            138,
            "{}",
            e.id
        );
    }
    let (mut worst_xy, mut worst_g, mut worst_k) = (0f64, 0f64, 0f64);
    for r in &rows {
        let f = krueger::forward(&r.ell, K0, r.lat, r.dlon).unwrap();
        let what = format!("{} {} {}", r.ell.id, r.lat, r.dlon);
        // GeographicLib's own series, printed to 1 nm
        let dxy = (f.x - r.series[0]).abs().max((f.y - r.series[1]).abs());
        let dg = (f.gamma.to_degrees() - r.series[2]).abs();
        let dk = (f.k - r.series[3]).abs();
        assert!(
            dxy < 1e-6,
            "{what}: x {} vs {}, y {} vs {}",
            f.x,
            r.series[0],
            f.y,
            r.series[1]
        );
        assert!(
            dg < 1e-9,
            "{what}: γ {} vs {}",
            f.gamma.to_degrees(),
            r.series[2]
        );
        assert!(dk < 1e-9, "{what}: k {} vs {}", f.k, r.series[3]);
        worst_xy = worst_xy.max(dxy);
        worst_g = worst_g.max(dg);
        worst_k = worst_k.max(dk);
        // and the exact projection (elliptic functions): the series is good to
        // nanometres even 40° from the central meridian
        assert!(
            (f.x - r.exact[0]).abs() < 1e-6,
            "{what}: exact x {}",
            r.exact[0]
        );
        assert!(
            (f.y - r.exact[1]).abs() < 1e-6,
            "{what}: exact y {}",
            r.exact[1]
        );
        assert!((f.gamma.to_degrees() - r.exact[2]).abs() < 1e-9, "{what}");
        assert!((f.k - r.exact[3]).abs() < 1e-9, "{what}");
    }
    // far tighter than required: the same series, summed in another order
    assert!(worst_xy < 5e-9, "worst |Δx|, |Δy| = {worst_xy} m");
    assert!(worst_g < 1e-12 && worst_k < 1e-13, "{worst_g} {worst_k}");
}

#[test]
fn inverse_returns_the_input_within_a_nanodegree() {
    for r in tm_rows() {
        let i = krueger::inverse(&r.ell, K0, r.series[0], r.series[1]).unwrap();
        let what = format!("{} {} {}", r.ell.id, r.lat, r.dlon);
        assert!((i.lat_deg - r.lat).abs() < 1e-9, "{what}: φ {}", i.lat_deg);
        assert!(
            (i.dlon_deg - r.dlon).abs() < 1e-9,
            "{what}: Δλ {}",
            i.dlon_deg
        );
        assert!(
            (i.gamma.to_degrees() - r.series[2]).abs() < 1e-9,
            "{what}: γ"
        );
        assert!((i.k - r.series[3]).abs() < 1e-9, "{what}: k");
        assert!(i.iterations <= 4, "{what}: {} iterations", i.iterations);
    }
}

struct UtmRow {
    lat: f64,
    lon: f64,
    forced: u8,
    zone: u8,
    hemisphere: Hemisphere,
    easting: f64,
    northing: f64,
    band: char,
}

fn utm_rows() -> Vec<UtmRow> {
    include_str!("fixtures/utm_wgs84.txt")
        .lines()
        .map(|line| {
            let f: Vec<&str> = line.split_whitespace().collect();
            assert_eq!(f.len(), 7, "{line}");
            let zh = f[3];
            UtmRow {
                lat: f[0].parse().unwrap(),
                lon: f[1].parse().unwrap(),
                forced: f[2].parse().unwrap(),
                zone: zh[..zh.len() - 1].parse().unwrap(),
                hemisphere: if zh.ends_with('n') {
                    Hemisphere::North
                } else {
                    Hemisphere::South
                },
                easting: f[4].parse().unwrap(),
                northing: f[5].parse().unwrap(),
                band: f[6].chars().next().unwrap(),
            }
        })
        .collect()
}

#[test]
fn utm_zones_bands_and_coordinates_agree_with_geoconvert_at_every_boundary() {
    let wgs = Ellipsoid::by_id("wgs84").unwrap();
    let rows = utm_rows();
    assert_eq!(rows.len(), 276);
    for r in rows {
        let forced = (r.forced != 0).then_some(r.forced);
        let u = utm::forward(&wgs, r.lat, r.lon, forced).unwrap();
        let what = format!("{} {} zone {}", r.lat, r.lon, r.forced);
        assert_eq!(u.zone, r.zone, "{what}");
        assert_eq!(u.hemisphere, r.hemisphere, "{what}");
        assert_eq!(u.band, r.band, "{what}");
        // GeoConvert prints micrometres
        assert!(
            (u.easting - r.easting).abs() < 1e-6,
            "{what}: E {} vs {}",
            u.easting,
            r.easting
        );
        assert!(
            (u.northing - r.northing).abs() < 1e-6,
            "{what}: N {} vs {}",
            u.northing,
            r.northing
        );
        // and back
        let i = utm::inverse(&wgs, u.zone, u.hemisphere, u.easting, u.northing);
        if let Ok(i) = i {
            assert!((i.latitude - r.lat).abs() < 1e-9, "{what}");
            assert!(
                utm::lon_diff(i.longitude, r.lon).abs() < 1e-9,
                "{what}: λ {}",
                i.longitude
            );
        } else {
            // only outside the legal ranges
            assert!(!u.legal, "{what}: {i:?}");
        }
    }
}

#[test]
fn the_published_checkpoints() {
    let grs = Ellipsoid::by_id("grs80").unwrap();
    // 55°N 12°E on GRS80 in zone 32 (12°E is the zone's eastern edge; the
    // standard zone there is 33)
    let u = utm::forward(&grs, 55.0, 12.0, Some(32)).unwrap();
    assert_eq!(u.standard_zone, 33);
    assert!((u.easting - 691_875.632).abs() < 5e-4, "{}", u.easting);
    assert!((u.northing - 6_098_907.825).abs() < 5e-4, "{}", u.northing);
    // 55°S: N = 10 000 000 − 6 098 907.825
    let s = utm::forward(&grs, -55.0, 12.0, Some(32)).unwrap();
    assert_eq!(s.hemisphere, Hemisphere::South);
    assert!((s.northing - (10_000_000.0 - u.northing)).abs() < 1e-8);
    assert!((s.easting - u.easting).abs() < 1e-9);
    // forced into zone 32 at 6°W, 15° off the central meridian: still within
    // 1 mm of the exact projection (GeographicLib's TransverseMercatorProj
    // without -s: x = −955 673.814 189 040, y = 6 198 246.671 090 279 on WGS84)
    let wgs = Ellipsoid::by_id("wgs84").unwrap();
    let f = utm::forward(&wgs, 55.0, -6.0, Some(32)).unwrap();
    assert_eq!(f.rule, ZoneRule::Forced);
    assert!(!f.legal);
    let (xe, ye) = (-955_673.814_189_040, 6_198_246.671_090_279);
    let d = (f.tm.x - xe).hypot(f.tm.y - ye);
    assert!(d < 1e-3, "{d} m from the exact projection");
    // here the classical series is 0.406 m off
    let c = snyder::forward(&wgs, K0, 55.0, -15.0);
    let dc = (c.x - xe).hypot(c.y - ye);
    assert!((0.40..0.41).contains(&dc), "classical {dc} m");
    // the quarter meridian of WGS84 (GeodSolve -i 0 0 90 0: 10 001 965.729 313 m)
    let q = krueger::Series::new(&wgs).quarter_meridian();
    assert!((q - 10_001_965.729).abs() < 5e-4, "{q}");
}

#[test]
fn zone_and_band_rules_at_every_boundary() {
    use utm::standard_zone as z;
    assert_eq!(z(0.0, -180.0).0, 1);
    assert_eq!(z(0.0, 180.0).0, 1); // the same meridian as −180
    assert_eq!(z(0.0, 179.999_999).0, 60);
    assert_eq!(z(0.0, -0.000_001).0, 30);
    assert_eq!(z(0.0, 0.0).0, 31);
    // Norway: band V (56°–64°N), 3°E–12°E → 32
    assert_eq!(z(56.0, 3.0), (32, ZoneRule::Norway));
    assert_eq!(z(56.0, 2.999_999), (31, ZoneRule::Regular));
    assert_eq!(z(63.999_999, 11.999), (32, ZoneRule::Regular));
    assert_eq!(z(63.999_999, 5.0), (32, ZoneRule::Norway));
    assert_eq!(z(64.0, 5.0), (31, ZoneRule::Regular));
    assert_eq!(z(55.999_999, 5.0), (31, ZoneRule::Regular));
    // Svalbard: band X (72°–84°N), 0°–42°E → 31, 33, 35, 37 only
    for (lon, zone) in [
        (0.0, 31),
        (8.999, 31),
        (9.0, 33),
        (20.999, 33),
        (21.0, 35),
        (32.999, 35),
        (33.0, 37),
        (41.999, 37),
    ] {
        assert_eq!(z(72.0, lon), (zone, ZoneRule::Svalbard), "{lon}");
        assert_eq!(z(84.0, lon), (zone, ZoneRule::Svalbard), "{lon}");
    }
    assert_eq!(z(72.0, 42.0), (38, ZoneRule::Regular));
    assert_eq!(z(71.999_999, 9.0), (32, ZoneRule::Regular));
    // bands: C at 80°S … X from 72°N to 84°N inclusive, no I or O
    let letters: String = (0..20)
        .map(|i| utm::band_letter(-80.0 + 8.0 * i as f64))
        .collect();
    assert_eq!(letters, "CDEFGHJKLMNPQRSTUVWX");
    assert_eq!(utm::band_letter(84.0), 'X');
    assert_eq!(utm::band_limits('X'), Some((72.0, 84.0)));
    assert_eq!(utm::band_limits('I'), None);
    assert_eq!(utm::band_hemisphere('M'), Some(Hemisphere::South));
    assert_eq!(utm::band_hemisphere('N'), Some(Hemisphere::North));
    // 84°N and 80°S are still UTM; beyond is UPS
    let wgs = Ellipsoid::by_id("wgs84").unwrap();
    assert!(utm::forward(&wgs, 84.0, 10.0, None).is_ok());
    assert!(utm::forward(&wgs, -80.0, 10.0, None).is_ok());
    let e = utm::forward(&wgs, 84.000_001, 10.0, None)
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("latitude: UTM covers 80°S to 84°N only") && e.contains("UPS"),
        "{e}"
    );
    let e = utm::forward(&wgs, -80.5, 10.0, None)
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("latitude: UTM covers"), "{e}");
}

fn num(s: &Solution, key: &str) -> f64 {
    s.result
        .number(key)
        .unwrap_or_else(|| panic!("{}: no number {key}", s.id))
}

fn text<'a>(s: &'a Solution, key: &str) -> &'a str {
    match s.result.get(key) {
        Some(Value::Text(t)) => t,
        other => panic!("{}: {key} is {other:?}", s.id),
    }
}

fn has_note(s: &Solution, kind: NoteKind, part: &str) -> bool {
    s.notes
        .iter()
        .any(|n| n.kind == kind && n.text.contains(part))
}

fn err(id: &str, inputs: Record) -> String {
    solve(id, &inputs).expect_err("should fail").to_string()
}

#[test]
fn utm_default_is_bangkok_in_zone_47_as_geoconvert_says() {
    let s = solve("utm", &Record::new()).unwrap();
    // GeoConvert -u -p 6: 47n 662176.290477 1520582.494360; MGRS 47P
    assert_eq!(num(&s, "zone"), 47.0);
    assert_eq!(text(&s, "band"), "P");
    assert_eq!(text(&s, "hemisphere"), "north");
    assert_eq!(num(&s, "central_meridian"), 99.0);
    assert!((num(&s, "easting") - 662_176.290_477).abs() < 1e-6);
    assert!((num(&s, "northing") - 1_520_582.494_360).abs() < 1e-6);
    assert_eq!(
        text(&s, "utm_text"),
        "47P 662\u{2009}176.290 m E, 1\u{2009}520\u{2009}582.494 m N"
    );
    // the seed's "Thailand: Zone 47" beside it
    assert_eq!(s.textbook.as_ref().unwrap().number("zone"), Some(47.0));
    // every step of the computation has its formula with the numbers in
    for st in &s.steps[..s.steps.len() - 1] {
        assert!(
            !st.formula.is_empty() && !st.substituted.is_empty(),
            "{}",
            st.title
        );
    }
    let zone_step = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Zone"))
        .unwrap();
    assert!(zone_step
        .substituted
        .contains(r"\lambda_0 = 6\cdot 47 - 183 = 99^\circ"));
    let en = s
        .steps
        .iter()
        .find(|st| st.title == "Easting and northing")
        .unwrap();
    assert!(
        en.substituted
            .contains(r"E = 500\,000 + 162\,176.290477 = 662\,176.290477\,\text{m}"),
        "{}",
        en.substituted
    );
    // near the central meridian the classical series agrees to a micrometre
    assert!(num(&s, "classical_difference_m") < 1e-6);
    // the figure's data: meridians, parallels, k across the zone
    let fig = s.steps.last().unwrap();
    let Some(Value::List(m)) = fig.values.get("meridians") else {
        panic!()
    };
    assert_eq!(m.len(), 7);
    let Some(Value::List(k)) = fig.values.get("k_profile") else {
        panic!()
    };
    assert_eq!(k.len(), 141);
}

#[test]
fn utm_checkpoints_through_the_worked_example() {
    let grs = |lat: f64, lon: f64| {
        Record::new()
            .with("latitude", lat)
            .with("longitude", lon)
            .with("ellipsoid", "grs80")
            .with("zone", 32.0)
    };
    let s = solve("utm", &grs(55.0, 12.0)).unwrap();
    assert!((num(&s, "easting") - 691_875.632).abs() < 5e-4);
    assert!((num(&s, "northing") - 6_098_907.825).abs() < 5e-4);
    assert_eq!(text(&s, "zone_rule"), "forced");
    assert_eq!(num(&s, "standard_zone"), 33.0);
    assert!(s.textbook.is_none());
    let south = solve("utm", &grs(-55.0, 12.0)).unwrap();
    assert_eq!(text(&south, "hemisphere"), "south");
    assert_eq!(text(&south, "band"), "F");
    assert!((num(&south, "northing") - (10_000_000.0 - num(&s, "northing"))).abs() < 1e-8);
    // 6°W forced into zone 32: outside the legal range, said so, and the
    // classical series 0.406 m off
    let far = solve("utm", &grs(55.0, -6.0)).unwrap();
    assert_eq!(far.result.get("in_legal_range"), Some(&Value::Bool(false)));
    assert!(has_note(
        &far,
        NoteKind::Warning,
        "outside the legal UTM range"
    ));
    assert!(has_note(
        &far,
        NoteKind::Warning,
        "15° from the central meridian"
    ));
    assert!((0.40..0.41).contains(&num(&far, "classical_difference_m")));
    // its exact-vs-classical profile reaches past the point, growing from
    // 0.58 mm at 0.25° (Snyder's meridian arc stops at e⁶) to 0.64 m at 16°
    let prof = far
        .steps
        .last()
        .unwrap()
        .values
        .get("difference_profile")
        .unwrap()
        .clone();
    let Value::List(rows) = prof else { panic!() };
    let d = |r: &Value| match r {
        Value::List(x) => x[2].as_f64().unwrap(),
        _ => panic!(),
    };
    assert!((5e-4..7e-4).contains(&d(&rows[0])), "{}", d(&rows[0]));
    assert!((0.6..0.7).contains(&d(rows.last().unwrap())));
}

#[test]
fn degrees_minutes_seconds_are_read_from_the_form_and_the_url() {
    let texts = Record::new()
        .with("latitude", "55°00'00\"N")
        .with("longitude", "12 0 0 E")
        .with("ellipsoid", "grs80")
        .with("zone", "32");
    let p = parse_inputs("utm", &texts).unwrap();
    assert!(p.errors.is_empty(), "{:?}", p.errors);
    assert_eq!(p.inputs.number("latitude"), Some(55.0));
    assert_eq!(p.inputs.number("longitude"), Some(12.0));
    let s = solve("utm", &p.inputs).unwrap();
    assert!((num(&s, "easting") - 691_875.632).abs() < 5e-4);
    // typed strings work in solve() too; S and W are negative
    let s = solve(
        "utm",
        &Record::new()
            .with("latitude", "33 52 S")
            .with("longitude", "151°12'E"),
    )
    .unwrap();
    assert_eq!(s.inputs.number("latitude"), Some(-(33.0 + 52.0 / 60.0)));
    assert_eq!(text(&s, "hemisphere"), "south");
    assert_eq!(num(&s, "zone"), 56.0);
    let p = parse_inputs(
        "utm",
        &Record::new()
            .with("latitude", "55 61")
            .with("longitude", "12E N"),
    )
    .unwrap();
    assert!(p.errors.get("latitude").is_some() && p.errors.get("longitude").is_some());
}

#[test]
fn bad_inputs_name_the_field() {
    let r = Record::new;
    assert_eq!(
        err("utm", r().with("latitude", 91.0)),
        "latitude: must be between −90° and 90° (got 91°)"
    );
    // longitudes beyond ±180 are refused, not wrapped
    assert_eq!(
        err("utm", r().with("longitude", 181.0)),
        "longitude: must be between −180° and 180° (got 181°)"
    );
    assert_eq!(
        err("utm", r().with("latitude", f64::NAN)),
        "latitude: is NaN; give a number"
    );
    assert!(err("utm", r().with("longitude", f64::INFINITY)).starts_with("longitude: is infinite"));
    assert!(err("utm", r().with("latitude", 85.0))
        .starts_with("latitude: UTM covers 80°S to 84°N only"));
    assert!(err("utm", r().with("latitude", -80.5)).contains("UPS"));
    assert_eq!(
        err("utm", r().with("zone", 61.0)),
        "zone: must be at most 60 (got 61)"
    );
    assert!(err("utm", r().with("zone", 1.0))
        .starts_with("zone: zone 1 has its central meridian at -177°"));
    assert!(err("utm", r().with("ellipsoid", "airy"))
        .starts_with("ellipsoid: \"airy\" is not one of the choices"));
    assert!(err("utm", r().with("latitude", "55 30.5 10"))
        .starts_with("latitude: \"55 30.5 10\": the minutes must be a whole number"));
    // the inverse: a band letter that does not exist, eastings and northings
    // outside the legal ranges
    assert!(err("utm-inverse", r().with("hemisphere", "I"))
        .starts_with("hemisphere: \"I\" is not one of the choices (north, south, C, D"));
    assert!(err("utm-inverse", r().with("hemisphere", "Y")).starts_with("hemisphere: \"Y\""));
    assert_eq!(
        err("utm-inverse", r().with("easting", 50_000.0)),
        "easting: must be at least 100000 m (got 50000)"
    );
    assert_eq!(
        err("utm-inverse", r().with("easting", 950_000.0)),
        "easting: must be at most 900000 m (got 950000)"
    );
    assert!(err("utm-inverse", r().with("northing", 9_600_000.0))
        .starts_with("northing: must be between 0 m and 9 500 000 m in the north"));
    assert!(err(
        "utm-inverse",
        r().with("hemisphere", "south").with("northing", 500_000.0)
    )
    .starts_with("northing: must be between 1 000 000 m and 10 000 000 m in the south"));
    assert_eq!(
        err("utm-inverse", r().with("zone", 0.0)),
        "zone: must be at least 1 (got 0)"
    );
    assert!(err("utm-inverse", r().with("northing", f64::NAN)).starts_with("northing: is NaN"));
    assert!(err("utm-facts", r().with("latitude", 86.0)).starts_with("latitude: UTM covers"));
}

#[test]
fn utm_inverse_returns_the_point_and_checks_a_band_letter() {
    let s = solve("utm-inverse", &Record::new()).unwrap();
    // the default is Bangkok's E, N rounded to the millimetre
    assert!((num(&s, "latitude") - 13.75).abs() < 1e-7);
    assert!((num(&s, "longitude") - 100.5).abs() < 1e-7);
    assert_eq!(text(&s, "band"), "P");
    assert!((num(&s, "scale_factor") - 0.999_925_344).abs() < 1e-9);
    // round trip to 1e-9° from every ellipsoid, both hemispheres
    for e in ELLIPSOIDS {
        for (lat, lon) in [(48.2, 16.37), (-33.9, 18.4), (0.0, -78.5), (83.5, -30.0)] {
            let f = solve(
                "utm",
                &Record::new()
                    .with("latitude", lat)
                    .with("longitude", lon)
                    .with("ellipsoid", e.id),
            )
            .unwrap();
            let b = solve(
                "utm-inverse",
                &Record::new()
                    .with("zone", num(&f, "zone"))
                    .with("hemisphere", text(&f, "band"))
                    .with("easting", num(&f, "easting"))
                    .with("northing", num(&f, "northing"))
                    .with("ellipsoid", e.id),
            )
            .unwrap();
            assert!((num(&b, "latitude") - lat).abs() < 1e-9, "{} {lat}", e.id);
            assert!((num(&b, "longitude") - lon).abs() < 1e-9, "{} {lon}", e.id);
            assert!((num(&b, "convergence") - num(&f, "convergence")).abs() < 1e-9);
            assert!((num(&b, "scale_factor") - num(&f, "scale_factor")).abs() < 1e-12);
            assert_eq!(text(&b, "hemisphere"), text(&f, "hemisphere"));
            assert!(
                b.notes.iter().all(|n| n.kind != NoteKind::Warning),
                "{:?}",
                b.notes
            );
        }
    }
    // a band letter that does not fit the northing: a warning, not an error
    let s = solve("utm-inverse", &Record::new().with("hemisphere", "Q")).unwrap();
    assert!(has_note(&s, NoteKind::Warning, "in band P, not in band Q"));
    let s = solve(
        "utm-inverse",
        &Record::new()
            .with("hemisphere", "M")
            .with("northing", 9_000_000.0),
    )
    .unwrap();
    assert_eq!(text(&s, "hemisphere"), "south");
    assert!(num(&s, "latitude") < 0.0);
}

#[test]
fn seed_004_facts_with_the_printed_numbers_and_a_note_for_each_difference() {
    let s = solve("utm-facts", &Record::new()).unwrap();
    // k = 1 about 180 km from the central meridian, not 90
    assert!((num(&s, "k1_distance_km") - 179.754).abs() < 1e-3);
    let k90 = num(&s, "k_at_90km");
    assert!((k90 - 0.999_700_3).abs() < 1e-7);
    assert!((num(&s, "k_at_90km_ppm") + 299.73).abs() < 0.01);
    assert!((num(&s, "zone_width_km") - 667.957).abs() < 1e-3);
    assert!((num(&s, "zone_width_ground_km") - 667.917).abs() < 1e-3);
    assert!((num(&s, "edge_scale_factor") - 1.000_981_06).abs() < 1e-8);
    assert_eq!(num(&s, "latitude_max"), 84.0);
    assert!(num(&s, "wgs84_grs80_difference_max_mm") < 0.2);
    let tb = s.textbook.as_ref().unwrap();
    assert_eq!(tb.number("k1_distance_km"), Some(90.0));
    assert_eq!(tb.number("latitude_max"), Some(80.0));
    assert_eq!(tb.number("latitude_min"), Some(-80.0));
    assert_eq!(tb.get("zones_thailand"), Some(&Value::numbers(&[47.0])));
    assert_eq!(
        s.result.get("zones_thailand"),
        Some(&Value::numbers(&[47.0, 48.0]))
    );
    assert_eq!(s.result.get("zones_pakistan"), tb.get("zones_pakistan"));
    assert!(has_note(&s, NoteKind::Erratum, "It is 1 at 179.8 km"));
    assert!(has_note(
        &s,
        NoteKind::Erratum,
        "the northern limit is 84°N"
    ));
    assert!(has_note(&s, NoteKind::Erratum, "which is zone 48"));
    assert!(has_note(&s, NoteKind::Convention, "secant"));
    assert!(has_note(
        &s,
        NoteKind::Convention,
        "not from the ellipsoids"
    ));
    // every textbook key is a result key
    for k in tb.keys() {
        assert!(s.result.get(k).is_some(), "{k}");
    }
    // at 60°N the zone is half as wide, k = 1 still about 180 km out
    let n60 = solve("utm-facts", &Record::new().with("latitude", "60N")).unwrap();
    assert!(s.textbook.is_some() && n60.textbook.is_none());
    assert!((num(&n60, "zone_width_ground_km") - 0.5 * 667.9).abs() < 2.0);
    assert!((num(&n60, "k1_distance_km") - 180.0).abs() < 1.0);
    assert!(num(&n60, "k1_longitude_offset") > 3.0);
}

#[test]
fn every_result_key_has_a_label_and_the_catalog_lists_the_three() {
    for id in ["utm", "utm-inverse", "utm-facts"] {
        let e = catalog().into_iter().find(|e| e.id == id).unwrap();
        assert_eq!(e.status, "ready");
        assert_eq!(e.topic, "Map projection");
        let s = solve(id, &Record::new()).unwrap();
        for key in s.result.keys() {
            assert!(s.labels.get(key).is_some(), "{id}: {key} has no label");
        }
    }
    let utm = catalog().into_iter().find(|e| e.id == "utm").unwrap();
    let lat = &utm.inputs[0];
    assert_eq!(
        (lat.key, lat.kind, lat.unit),
        ("latitude", "angle", Some("°"))
    );
    assert_eq!((lat.min, lat.max), (Some(-90.0), Some(90.0)));
    let ell = &utm.inputs[2];
    let opts: Vec<_> = ell
        .options
        .as_ref()
        .unwrap()
        .iter()
        .map(|o| o.value)
        .collect();
    assert_eq!(
        opts,
        [
            "wgs84",
            "grs80",
            "international-1924",
            "bessel-1841",
            "clarke-1866",
            "everest-1830"
        ]
    );
    assert!(catalog().iter().all(|e| e.status == "ready"));
}

#[test]
fn formulas_are_well_formed_latex_for_many_inputs() {
    // braces balance, and no power of ten is raised again (10^{-10}^\circ
    // is a KaTeX error)
    let cases = [
        ("utm", Record::new()),
        (
            "utm",
            Record::new()
                .with("latitude", -79.9)
                .with("longitude", -179.9),
        ),
        (
            "utm",
            Record::new()
                .with("latitude", 55.0)
                .with("longitude", -6.0)
                .with("zone", 32.0),
        ),
        (
            "utm",
            Record::new().with("latitude", 0.0).with("longitude", 3.0),
        ),
        ("utm-inverse", Record::new()),
        (
            "utm-inverse",
            Record::new()
                .with("easting", 500_000.0)
                .with("northing", 0.0),
        ),
        (
            "utm-inverse",
            Record::new()
                .with("hemisphere", "C")
                .with("easting", 899_000.0)
                .with("northing", 1_000_000.0),
        ),
        ("utm-facts", Record::new()),
        ("utm-facts", Record::new().with("latitude", 84.0)),
    ];
    for (id, inputs) in cases {
        let s = solve(id, &inputs).unwrap();
        for st in &s.steps {
            for tex in [&st.formula, &st.substituted] {
                let mut depth = 0i32;
                for ch in tex.chars() {
                    match ch {
                        '{' => depth += 1,
                        '}' => depth -= 1,
                        _ => {}
                    }
                    assert!(depth >= 0, "{id} {}: {tex}", st.title);
                }
                assert_eq!(depth, 0, "{id} {}: {tex}", st.title);
                let flat = tex.replace(' ', "");
                for (i, _) in flat.match_indices("\\times10^{") {
                    let rest = &flat[i + 10..];
                    let close = rest.find('}').unwrap();
                    assert!(
                        !rest[close + 1..].starts_with('^'),
                        "{id} {}: {tex}",
                        st.title
                    );
                }
            }
        }
    }
}

/// Steps are data: every step with a formula has its relations, and every
/// practice box of the three examples has the relation that computes it
/// (its key), whose numbers hint ends with the result as "?" and does not
/// show the answer.
#[test]
fn steps_have_parts_and_practice_hints_come_from_keyed_relations() {
    use photogrammetry_playground::practice::{encode, practice as variant};
    use photogrammetry_playground::solution::num as shown;
    for id in ["utm", "utm-inverse", "utm-facts"] {
        let s = solve(id, &Record::new()).unwrap();
        for st in &s.steps {
            if !st.formula.is_empty() || !st.substituted.is_empty() {
                assert!(!st.parts.is_empty(), "{id} {}: no parts", st.title);
            }
        }
        for v in [3, 7, 11] {
            let p = variant(id, Some(&encode(v)), 0).unwrap();
            let s = solve(id, &p.inputs).unwrap();
            let mut with_numbers = 0;
            for b in &p.boxes {
                let r = s
                    .steps
                    .iter()
                    .flat_map(|st| st.parts.iter())
                    .find(|r| r.key.as_deref() == Some(b.key.as_str()))
                    .unwrap_or_else(|| panic!("{id}: no relation computes box {}", b.key));
                assert_eq!(b.hints.numbers, r.question_latex(), "{id} {}", b.key);
                if b.hints.numbers.is_empty() {
                    continue;
                }
                with_numbers += 1;
                assert!(b.hints.numbers.ends_with(r"\;?"), "{}", b.hints.numbers);
                let x = s
                    .result
                    .number(&b.key)
                    .or_else(|| s.steps.iter().find_map(|st| st.values.number(&b.key)));
                let x = shown(x.unwrap());
                if x.len() >= 4 {
                    assert!(
                        !b.hints.numbers.contains(&x),
                        "{id} {}: {x} in {}",
                        b.key,
                        b.hints.numbers
                    );
                }
            }
            // most boxes show their numbers
            assert!(
                2 * with_numbers >= p.boxes.len(),
                "{id}: {with_numbers} of {}",
                p.boxes.len()
            );
        }
    }
    // the zone step as relations: the floor, λ₀, Δλ, i, the band, the hemisphere
    let s = solve("utm", &Record::new()).unwrap();
    let zone = s
        .steps
        .iter()
        .find(|st| st.title.starts_with("Zone"))
        .unwrap();
    let keys: Vec<_> = zone
        .parts
        .iter()
        .map(|r| r.key.as_deref().unwrap_or(""))
        .collect();
    assert_eq!(
        keys,
        ["zone", "central_meridian", "dlon", "", "band", "hemisphere"]
    );
    assert_eq!(
        zone.parts[2].substituted_latex(),
        r"\Delta\lambda = 100.5^\circ - 99^\circ = 1.5^\circ"
    );
}
