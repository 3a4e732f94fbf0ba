//! Map projection: reference ellipsoids, the transverse Mercator (Karney's
//! 2011 Krüger series of order 6, and Snyder's classical series beside it),
//! the UTM layer (zones, bands, false easting and northing) and angles in
//! degrees, minutes and seconds.
//!
//! - [`Ellipsoid`]: a, 1/f and what follows from them (e², n, e′², b).
//! - [`krueger`]: the transverse Mercator to nanometres, forward and inverse,
//!   with the meridian convergence γ and the point scale k.
//! - [`snyder`]: the classical series of Snyder's *Map Projections — A
//!   Working Manual* (1987), as many textbooks print it.
//! - [`utm`]: zones (with the Norway and Svalbard exceptions), latitude
//!   bands C–X, hemispheres and the legal ranges.
//! - [`dms`]: reading and writing degrees, minutes and seconds.

pub mod dms;
pub mod krueger;
pub mod snyder;
pub mod utm;

/// A reference ellipsoid, defined by its semi-major axis and flattening.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipsoid {
    /// The id used by the catalog (`"wgs84"`).
    pub id: &'static str,
    /// Its name in words.
    pub name: &'static str,
    /// Semi-major axis a (m).
    pub a: f64,
    /// Inverse flattening 1/f.
    pub inv_f: f64,
    /// Where the figures come from (how the ellipsoid is defined).
    pub source: &'static str,
}

/// Clarke 1866 is defined by a and b; its 1/f = a/(a − b).
const CLARKE_1866_A: f64 = 6_378_206.4;
const CLARKE_1866_B: f64 = 6_356_583.8;

/// The ellipsoids offered, in the order the page lists them.
pub const ELLIPSOIDS: [Ellipsoid; 6] = [
    Ellipsoid {
        id: "wgs84",
        name: "WGS 84",
        a: 6_378_137.0,
        inv_f: 298.257_223_563,
        source: "EPSG 7030: a = 6 378 137 m, 1/f = 298.257223563",
    },
    Ellipsoid {
        id: "grs80",
        name: "GRS 80",
        a: 6_378_137.0,
        inv_f: 298.257_222_101,
        source: "EPSG 7019: a = 6 378 137 m, 1/f = 298.257222101",
    },
    Ellipsoid {
        id: "international-1924",
        name: "International 1924 (Hayford)",
        a: 6_378_388.0,
        inv_f: 297.0,
        source: "EPSG 7022: a = 6 378 388 m, 1/f = 297",
    },
    Ellipsoid {
        id: "bessel-1841",
        name: "Bessel 1841",
        a: 6_377_397.155,
        inv_f: 299.152_812_8,
        source: "EPSG 7004: a = 6 377 397.155 m, 1/f = 299.1528128",
    },
    Ellipsoid {
        id: "clarke-1866",
        name: "Clarke 1866",
        a: CLARKE_1866_A,
        inv_f: CLARKE_1866_A / (CLARKE_1866_A - CLARKE_1866_B),
        source: "EPSG 7008: a = 6 378 206.4 m, b = 6 356 583.8 m (1/f = a/(a − b) = 294.9786982…)",
    },
    Ellipsoid {
        id: "everest-1830",
        name: "Everest 1830 (1937 adjustment)",
        a: 6_377_276.345,
        inv_f: 300.801_7,
        source: "EPSG 7015: a = 6 377 276.345 m, 1/f = 300.8017 (PROJ's evrst30; India, Thailand)",
    },
];

impl Ellipsoid {
    /// The ellipsoid with catalog id `id`.
    pub fn by_id(id: &str) -> Option<Ellipsoid> {
        ELLIPSOIDS.iter().copied().find(|e| e.id == id)
    }
    /// Flattening f = (a − b)/a.
    pub fn f(&self) -> f64 {
        1.0 / self.inv_f
    }
    /// Semi-minor axis b = a(1 − f).
    pub fn b(&self) -> f64 {
        self.a * (1.0 - self.f())
    }
    /// First eccentricity squared e² = f(2 − f).
    pub fn e2(&self) -> f64 {
        let f = self.f();
        f * (2.0 - f)
    }
    /// Third flattening n = f/(2 − f) = (a − b)/(a + b).
    pub fn n(&self) -> f64 {
        let f = self.f();
        f / (2.0 - f)
    }
    /// Second eccentricity squared e′² = e²/(1 − e²).
    pub fn ep2(&self) -> f64 {
        let e2 = self.e2();
        e2 / (1.0 - e2)
    }
    /// The prime-vertical radius of curvature at latitude `lat_deg`,
    /// N = a/√(1 − e² sin² φ) (m).
    pub fn prime_vertical_radius(&self, lat_deg: f64) -> f64 {
        self.a / (1.0 - self.e2() * lat_deg.to_radians().sin().powi(2)).sqrt()
    }
    /// The meridian's radius of curvature at latitude `lat_deg`,
    /// M = a(1 − e²)/(1 − e² sin² φ)^{3/2} (m).
    pub fn meridian_radius(&self, lat_deg: f64) -> f64 {
        let w2 = 1.0 - self.e2() * lat_deg.to_radians().sin().powi(2);
        self.a * (1.0 - self.e2()) / w2.powf(1.5)
    }
    /// The radius of the parallel at latitude `lat_deg`, N cos φ (m): an
    /// arc of Δλ radians along it is N cos φ·Δλ long.
    pub fn parallel_radius(&self, lat_deg: f64) -> f64 {
        self.prime_vertical_radius(lat_deg) * lat_deg.to_radians().cos()
    }
    /// The Gaussian mean radius at latitude `lat_deg`, R = √(MN) (m): the
    /// sphere that fits the ellipsoid best there.
    pub fn gaussian_radius(&self, lat_deg: f64) -> f64 {
        (self.meridian_radius(lat_deg) * self.prime_vertical_radius(lat_deg)).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derived_constants_of_wgs84() {
        let w = Ellipsoid::by_id("wgs84").unwrap();
        assert!((w.b() - 6_356_752.314_245_179).abs() < 1e-8);
        assert!((w.e2() - 0.006_694_379_990_141_317).abs() < 1e-17);
        assert!((w.n() - 0.001_679_220_386_383_705).abs() < 1e-17);
        assert!((w.ep2() - 0.006_739_496_742_276_435).abs() < 1e-17);
        assert!((w.prime_vertical_radius(0.0) - w.a).abs() < 1e-9);
        assert!((w.meridian_radius(0.0) - w.a * (1.0 - w.e2())).abs() < 1e-9);
        // at the pole both radii are a²/b
        let polar = w.a * w.a / w.b();
        assert!((w.meridian_radius(90.0) - polar).abs() < 1e-6);
        assert!((w.gaussian_radius(90.0) - polar).abs() < 1e-6);
        assert!((w.parallel_radius(60.0) - w.prime_vertical_radius(60.0) / 2.0).abs() < 1e-6);
        let c = Ellipsoid::by_id("clarke-1866").unwrap();
        assert!((c.b() - CLARKE_1866_B).abs() < 1e-8);
        assert!(Ellipsoid::by_id("airy").is_none());
    }
}
