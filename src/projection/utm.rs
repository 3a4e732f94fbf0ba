//! The Universal Transverse Mercator layer on the Krüger series: 60 zones of
//! 6° (with the Norway and Svalbard exceptions), latitude bands C–X,
//! k₀ = 0.9996, false easting 500 000 m, false northing 0 (north) or
//! 10 000 000 m (south), and the legal ranges (those of GeographicLib's
//! `UTMUPS` with MGRS limits).
//!
//! Longitudes are refused beyond ±180° (not wrapped); 180° and −180° are the
//! same meridian and both fall in zone 1, as in GeographicLib.

use super::krueger;
use super::Ellipsoid;
use crate::error::{Error, Result};

/// Scale on the central meridian.
pub const K0: f64 = 0.9996;
/// Added to x so that eastings are positive (m).
pub const FALSE_EASTING: f64 = 500_000.0;
/// Added to y in the southern hemisphere (m).
pub const FALSE_NORTHING_SOUTH: f64 = 10_000_000.0;
/// UTM covers these latitudes (degrees); beyond, UPS.
pub const LAT_MIN: f64 = -80.0;
pub const LAT_MAX: f64 = 84.0;
/// Legal eastings (m): 100 km to 900 km.
pub const EASTING_MIN: f64 = 100_000.0;
pub const EASTING_MAX: f64 = 900_000.0;
/// Legal northings (m): north 0 to 9 500 km, south 1 000 km to 10 000 km.
pub const NORTHING_NORTH_MAX: f64 = 9_500_000.0;
pub const NORTHING_SOUTH_MIN: f64 = 1_000_000.0;
/// How far from its central meridian a forced zone may take a point: the
/// Krüger series stays within a millimetre of the exact projection to here
/// (tests/fixtures compare it with GeographicLib's exact one).
pub const MAX_FORCED_OFFSET_DEG: f64 = 40.0;
/// The latitude band letters from 80°S, 8° each (X: 72°N–84°N, 12°).
pub const BANDS: [char; 20] = [
    'C', 'D', 'E', 'F', 'G', 'H', 'J', 'K', 'L', 'M', 'N', 'P', 'Q', 'R', 'S', 'T', 'U', 'V', 'W',
    'X',
];

/// North or south of the equator (latitude 0 counts as north).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Hemisphere {
    North,
    South,
}

impl Hemisphere {
    pub fn name(self) -> &'static str {
        match self {
            Hemisphere::North => "north",
            Hemisphere::South => "south",
        }
    }
    pub fn false_northing(self) -> f64 {
        match self {
            Hemisphere::North => 0.0,
            Hemisphere::South => FALSE_NORTHING_SOUTH,
        }
    }
}

/// Why a point got its zone.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ZoneRule {
    /// ⌊(λ + 180)/6⌋ + 1.
    Regular,
    /// Band V, 3°E–12°E: zone 32 (south-west Norway).
    Norway,
    /// Band X, 0°–42°E: zones 31, 33, 35, 37 only (Svalbard).
    Svalbard,
    /// Chosen by the user.
    Forced,
}

/// The band index 0–19 of a latitude in [−80, 84] (X is 72°–84°).
pub fn band_index(lat: f64) -> usize {
    let i = ((lat + 80.0) / 8.0).floor();
    i.clamp(0.0, 19.0) as usize
}

/// The latitude band letter of `lat` (degrees, −80 … 84).
pub fn band_letter(lat: f64) -> char {
    BANDS[band_index(lat)]
}

/// The southern edge of a band and its northern edge (degrees).
pub fn band_limits(letter: char) -> Option<(f64, f64)> {
    let i = BANDS.iter().position(|&b| b == letter)?;
    let south = -80.0 + 8.0 * i as f64;
    let north = if letter == 'X' { 84.0 } else { south + 8.0 };
    Some((south, north))
}

/// The hemisphere a band letter lies in (C–M south, N–X north).
pub fn band_hemisphere(letter: char) -> Option<Hemisphere> {
    let i = BANDS.iter().position(|&b| b == letter)?;
    Some(if i >= 10 {
        Hemisphere::North
    } else {
        Hemisphere::South
    })
}

/// The longitude of zone `zone`'s central meridian: 6·zone − 183 (degrees).
pub fn central_meridian(zone: u8) -> f64 {
    6.0 * f64::from(zone) - 183.0
}

/// The standard zone of a point and the rule that gave it. `lat` must be in
/// [−80, 84] and `lon` in [−180, 180] (checked by [`forward`]).
pub fn standard_zone(lat: f64, lon: f64) -> (u8, ZoneRule) {
    let lon = if lon >= 180.0 { lon - 360.0 } else { lon };
    let regular = (((lon + 180.0) / 6.0).floor() as i32 + 1).clamp(1, 60) as u8;
    let band = band_letter(lat);
    if band == 'V' && regular == 31 && lon >= 3.0 {
        return (32, ZoneRule::Norway);
    }
    if band == 'X' && (0.0..42.0).contains(&lon) {
        let zone = if lon < 9.0 {
            31
        } else if lon < 21.0 {
            33
        } else if lon < 33.0 {
            35
        } else {
            37
        };
        return (zone, ZoneRule::Svalbard);
    }
    (regular, ZoneRule::Regular)
}

/// Longitude difference lon − lon0 reduced to [−180, 180).
pub fn lon_diff(lon: f64, lon0: f64) -> f64 {
    let d = (lon - lon0).rem_euclid(360.0);
    if d >= 180.0 {
        d - 360.0
    } else {
        d
    }
}

/// A geographic point in UTM, with everything that led there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Forward {
    pub zone: u8,
    pub rule: ZoneRule,
    /// The zone the rules would give (differs from `zone` when forced).
    pub standard_zone: u8,
    pub band: char,
    pub hemisphere: Hemisphere,
    pub central_meridian: f64,
    /// λ − λ₀ (degrees).
    pub dlon: f64,
    pub tm: krueger::Forward,
    pub easting: f64,
    pub northing: f64,
    /// Inside the legal easting and northing ranges.
    pub legal: bool,
}

fn check_lat_lon(lat: f64, lon: f64) -> Result<()> {
    if !lat.is_finite() {
        return Err(Error::input("latitude", "is not a finite number"));
    }
    if !lon.is_finite() {
        return Err(Error::input("longitude", "is not a finite number"));
    }
    if lat.abs() > 90.0 {
        return Err(Error::input(
            "latitude",
            format!("must be between −90° and 90° (got {lat}°)"),
        ));
    }
    if lon.abs() > 180.0 {
        return Err(Error::input(
            "longitude",
            format!("must be between −180° and 180° (got {lon}°); longitudes are not wrapped"),
        ));
    }
    if !(LAT_MIN..=LAT_MAX).contains(&lat) {
        return Err(Error::input(
            "latitude",
            format!(
                "UTM covers 80°S to 84°N only (got {lat}°); the polar caps use the Universal Polar Stereographic (UPS) projection, not built here"
            ),
        ));
    }
    Ok(())
}

/// Whether an easting and northing lie in the legal UTM ranges.
pub fn legal(easting: f64, northing: f64, hemisphere: Hemisphere) -> bool {
    let e_ok = (EASTING_MIN..=EASTING_MAX).contains(&easting);
    let n_ok = match hemisphere {
        Hemisphere::North => (0.0..=NORTHING_NORTH_MAX).contains(&northing),
        Hemisphere::South => (NORTHING_SOUTH_MIN..=FALSE_NORTHING_SOUTH).contains(&northing),
    };
    e_ok && n_ok
}

/// Geographic → UTM. `zone`: `None` for the standard zone, or a zone 1–60
/// to force (up to [`MAX_FORCED_OFFSET_DEG`] from its central meridian).
pub fn forward(ell: &Ellipsoid, lat: f64, lon: f64, zone: Option<u8>) -> Result<Forward> {
    check_lat_lon(lat, lon)?;
    let (std_zone, std_rule) = standard_zone(lat, lon);
    let (zone, rule) = match zone {
        None => (std_zone, std_rule),
        Some(z) if (1..=60).contains(&z) => (z, ZoneRule::Forced),
        Some(z) => return Err(Error::input("zone", format!("must be 1 to 60 (got {z})"))),
    };
    let lon0 = central_meridian(zone);
    let dlon = lon_diff(lon, lon0);
    if dlon.abs() > MAX_FORCED_OFFSET_DEG {
        return Err(Error::input(
            "zone",
            format!(
                "zone {zone} has its central meridian at {lon0}°, {:.6}° from the point; the series is trusted only within {MAX_FORCED_OFFSET_DEG}° of it (the standard zone is {std_zone})",
                dlon.abs()
            ),
        ));
    }
    let hemisphere = if lat >= 0.0 {
        Hemisphere::North
    } else {
        Hemisphere::South
    };
    let tm = krueger::forward(ell, K0, lat, dlon)?;
    let easting = FALSE_EASTING + tm.x;
    let northing = hemisphere.false_northing() + tm.y;
    Ok(Forward {
        zone,
        rule,
        standard_zone: std_zone,
        band: band_letter(lat),
        hemisphere,
        central_meridian: lon0,
        dlon,
        tm,
        easting,
        northing,
        legal: legal(easting, northing, hemisphere),
    })
}

/// UTM → geographic, with the intermediates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inverse {
    pub central_meridian: f64,
    /// x = E − 500 000, y = N − false northing (m).
    pub x: f64,
    pub y: f64,
    pub tm: krueger::Inverse,
    pub latitude: f64,
    /// Longitude in [−180, 180).
    pub longitude: f64,
}

/// UTM → geographic. Refuses eastings and northings outside the legal
/// ranges (naming the field).
pub fn inverse(
    ell: &Ellipsoid,
    zone: u8,
    hemisphere: Hemisphere,
    easting: f64,
    northing: f64,
) -> Result<Inverse> {
    if !(1..=60).contains(&zone) {
        return Err(Error::input(
            "zone",
            format!("must be 1 to 60 (got {zone})"),
        ));
    }
    if !(EASTING_MIN..=EASTING_MAX).contains(&easting) {
        return Err(Error::input(
            "easting",
            format!(
                "must be between 100 000 m and 900 000 m, the legal UTM range (got {easting} m)"
            ),
        ));
    }
    let (lo, hi) = match hemisphere {
        Hemisphere::North => (0.0, NORTHING_NORTH_MAX),
        Hemisphere::South => (NORTHING_SOUTH_MIN, FALSE_NORTHING_SOUTH),
    };
    if !(lo..=hi).contains(&northing) {
        return Err(Error::input(
            "northing",
            format!(
                "must be between {} m and {} m in the {} hemisphere, the legal UTM range (got {northing} m)",
                group(lo),
                group(hi),
                hemisphere.name()
            ),
        ));
    }
    let lon0 = central_meridian(zone);
    let x = easting - FALSE_EASTING;
    let y = northing - hemisphere.false_northing();
    let tm = krueger::inverse(ell, K0, x, y)?;
    Ok(Inverse {
        central_meridian: lon0,
        x,
        y,
        tm,
        latitude: tm.lat_deg,
        longitude: lon_diff(lon0 + tm.dlon_deg, 0.0),
    })
}

/// The zones a band of longitudes [`west`, `east`] (degrees) touches, by
/// the regular rule.
pub fn zones_between(west: f64, east: f64) -> Vec<u8> {
    let first = standard_zone(0.0, west).0;
    let last = standard_zone(0.0, east).0;
    (first..=last).collect()
}

/// The longitude difference (degrees) on the parallel at `lat` where the
/// UTM point scale is 1 (k grows with |Δλ| along a parallel).
pub fn k_one_dlon(ell: &Ellipsoid, lat: f64) -> Result<f64> {
    krueger::along_parallel(ell, K0, lat, 1.0, |f| f.k)
}

/// The longitude difference (degrees) on the parallel at `lat` whose
/// UTM x (east of the central meridian) is `x` metres.
pub fn dlon_at_x(ell: &Ellipsoid, lat: f64, x: f64) -> Result<f64> {
    krueger::along_parallel(ell, K0, lat, x, |f| f.x)
}

/// The UTM scale factor at `x` metres from the central meridian on a
/// sphere of radius `r`: k ≈ k₀ cosh(x/(k₀r)) (the calculator's formula;
/// with r the Gaussian radius √(MN) it is close to the ellipsoid's).
pub fn sphere_scale_at(x: f64, r: f64) -> f64 {
    K0 * (x / (K0 * r)).cosh()
}

/// Where k = 1 on a sphere of radius `r`: x = k₀r·acosh(1/k₀) (m).
pub fn sphere_k_one_distance(r: f64) -> f64 {
    K0 * r * (1.0 / K0).acosh()
}

/// A whole number of metres with thin spaces between thousands.
pub fn group(x: f64) -> String {
    let s = format!("{}", x.abs().round() as u64);
    let mut out = String::new();
    for (i, ch) in s.chars().enumerate() {
        if i > 0 && (s.len() - i) % 3 == 0 {
            out.push(' ');
        }
        out.push(ch);
    }
    if x < 0.0 {
        format!("−{out}")
    } else {
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zones_and_bands_at_their_edges() {
        assert_eq!(standard_zone(0.0, -180.0).0, 1);
        assert_eq!(standard_zone(0.0, 180.0).0, 1);
        assert_eq!(standard_zone(0.0, 179.999).0, 60);
        assert_eq!(standard_zone(0.0, 0.0).0, 31);
        assert_eq!(standard_zone(0.0, -1e-9).0, 30);
        assert_eq!(standard_zone(56.0, 3.0), (32, ZoneRule::Norway));
        assert_eq!(standard_zone(55.999, 3.0).0, 31);
        assert_eq!(standard_zone(64.0, 3.0).0, 31);
        assert_eq!(band_letter(-80.0), 'C');
        assert_eq!(band_letter(84.0), 'X');
        assert_eq!(band_letter(72.0), 'X');
        assert_eq!(band_letter(71.999), 'W');
        assert_eq!(band_letter(0.0), 'N');
        assert_eq!(band_letter(-1e-9), 'M');
        assert_eq!(group(10_000_000.0), "10 000 000");
        assert_eq!(lon_diff(-177.0, 177.0), 6.0);
        assert_eq!(zones_between(60.87, 77.84), vec![41, 42, 43]);
        assert_eq!(zones_between(97.34, 101.0), vec![47]);
    }

    #[test]
    fn k_is_one_about_180_km_from_the_central_meridian() {
        let w = Ellipsoid::by_id("wgs84").unwrap();
        let d = k_one_dlon(&w, 0.0).unwrap();
        let f = krueger::forward(&w, K0, 0.0, d).unwrap();
        assert!((f.k - 1.0).abs() < 1e-14, "{}", f.k);
        assert!((f.x - 180_000.0).abs() < 1_000.0, "{}", f.x);
        assert!((dlon_at_x(&w, 0.0, f.x).unwrap() - d).abs() < 1e-12);
        let sphere = sphere_k_one_distance(w.a);
        assert!((sphere_scale_at(sphere, w.a) - 1.0).abs() < 1e-15);
        assert!((sphere - f.x).abs() < 1_000.0, "{sphere}");
    }
}
