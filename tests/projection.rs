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
        assert_eq!(rows.iter().filter(|r| r.ell.id == e.id).count(), 138, "{}", e.id);
    }
    let (mut worst_xy, mut worst_g, mut worst_k) = (0f64, 0f64, 0f64);
    for r in &rows {
        let f = krueger::forward(&r.ell, K0, r.lat, r.dlon).unwrap();
        let what = format!("{} {} {}", r.ell.id, r.lat, r.dlon);
        // GeographicLib's own series, printed to 1 nm
        let dxy = (f.x - r.series[0]).abs().max((f.y - r.series[1]).abs());
        let dg = (f.gamma.to_degrees() - r.series[2]).abs();
        let dk = (f.k - r.series[3]).abs();
        assert!(dxy < 1e-6, "{what}: x {} vs {}, y {} vs {}", f.x, r.series[0], f.y, r.series[1]);
        assert!(dg < 1e-9, "{what}: γ {} vs {}", f.gamma.to_degrees(), r.series[2]);
        assert!(dk < 1e-9, "{what}: k {} vs {}", f.k, r.series[3]);
        worst_xy = worst_xy.max(dxy);
        worst_g = worst_g.max(dg);
        worst_k = worst_k.max(dk);
        // and the exact projection (elliptic functions): the series is good to
        // nanometres even 40° from the central meridian
        assert!((f.x - r.exact[0]).abs() < 1e-6, "{what}: exact x {}", r.exact[0]);
        assert!((f.y - r.exact[1]).abs() < 1e-6, "{what}: exact y {}", r.exact[1]);
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
        assert!((i.dlon_deg - r.dlon).abs() < 1e-9, "{what}: Δλ {}", i.dlon_deg);
        assert!((i.gamma.to_degrees() - r.series[2]).abs() < 1e-9, "{what}: γ");
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
        assert!((u.easting - r.easting).abs() < 1e-6, "{what}: E {} vs {}", u.easting, r.easting);
        assert!((u.northing - r.northing).abs() < 1e-6, "{what}: N {} vs {}", u.northing, r.northing);
        // and back
        let i = utm::inverse(&wgs, u.zone, u.hemisphere, u.easting, u.northing);
        if let Ok(i) = i {
            assert!((i.latitude - r.lat).abs() < 1e-9, "{what}");
            assert!(utm::lon_diff(i.longitude, r.lon).abs() < 1e-9, "{what}: λ {}", i.longitude);
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
    for (lon, zone) in [(0.0, 31), (8.999, 31), (9.0, 33), (20.999, 33), (21.0, 35), (32.999, 35), (33.0, 37), (41.999, 37)] {
        assert_eq!(z(72.0, lon), (zone, ZoneRule::Svalbard), "{lon}");
        assert_eq!(z(84.0, lon), (zone, ZoneRule::Svalbard), "{lon}");
    }
    assert_eq!(z(72.0, 42.0), (38, ZoneRule::Regular));
    assert_eq!(z(71.999_999, 9.0), (32, ZoneRule::Regular));
    // bands: C at 80°S … X from 72°N to 84°N inclusive, no I or O
    let letters: String = (0..20).map(|i| utm::band_letter(-80.0 + 8.0 * i as f64)).collect();
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
    let e = utm::forward(&wgs, 84.000_001, 10.0, None).unwrap_err().to_string();
    assert!(e.starts_with("latitude: UTM covers 80°S to 84°N only") && e.contains("UPS"), "{e}");
    let e = utm::forward(&wgs, -80.5, 10.0, None).unwrap_err().to_string();
    assert!(e.starts_with("latitude: UTM covers"), "{e}");
}

#[test]
#[ignore]
fn dump() {
    for id in ["utm", "utm-inverse", "utm-facts"] {
        let s = solve(id, &Record::new()).unwrap();
        for st in &s.steps {
            println!("## {}\n{}\n{}\n", st.title, st.text, st.substituted);
        }
        for (k, v) in s.result.iter() {
            println!("{k} = {v:?}");
        }
        for n in &s.notes {
            println!("NOTE {:?}: {}", n.kind, n.text);
        }
    }
}
