//! The classical transverse Mercator series, as J. P. Snyder prints it in
//! *Map Projections — A Working Manual* (USGS Professional Paper 1395, 1987,
//! eqs. 3-21, 8-9 to 8-12, 8-17 to 8-25): power series in the longitude
//! difference A = Δλ·cos φ, good to about a millimetre within 3–4° of the
//! central meridian and drifting off beyond. Here so that a student can see
//! where it departs from the exact (Krüger) series.

use super::Ellipsoid;
use crate::error::{Error, Result};

/// The meridian arc M from the equator to latitude φ (Snyder eq. 3-21).
pub fn meridian_arc(ell: &Ellipsoid, phi: f64) -> f64 {
    let e2 = ell.e2();
    let (e4, e6) = (e2 * e2, e2 * e2 * e2);
    ell.a
        * ((1.0 - e2 / 4.0 - 3.0 * e4 / 64.0 - 5.0 * e6 / 256.0) * phi
            - (3.0 * e2 / 8.0 + 3.0 * e4 / 32.0 + 45.0 * e6 / 1024.0) * (2.0 * phi).sin()
            + (15.0 * e4 / 256.0 + 45.0 * e6 / 1024.0) * (4.0 * phi).sin()
            - (35.0 * e6 / 3072.0) * (6.0 * phi).sin())
}

/// The forward series with its terms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Forward {
    /// N = a/√(1 − e² sin² φ), T = tan² φ, C = e′² cos² φ, A = Δλ cos φ, M.
    pub big_n: f64,
    pub t: f64,
    pub c: f64,
    pub a: f64,
    pub m: f64,
    /// x east of the central meridian, y north of the equator (m).
    pub x: f64,
    pub y: f64,
    /// Point scale k and meridian convergence γ (radians).
    pub k: f64,
    pub gamma: f64,
}

/// Snyder's forward series (eqs. 8-9, 8-10, 8-11) and the usual series for
/// the convergence, γ = A tan φ [1 + A²(1 + 3C + 2C²)/3 + A⁴(2 − T)/15].
pub fn forward(ell: &Ellipsoid, k0: f64, lat_deg: f64, dlon_deg: f64) -> Forward {
    let phi = lat_deg.to_radians();
    let ep2 = ell.ep2();
    let co = phi.cos();
    let big_n = ell.prime_vertical_radius(lat_deg);
    let t = phi.tan().powi(2);
    let c = ep2 * co * co;
    let a = dlon_deg.to_radians() * co;
    let m = meridian_arc(ell, phi);
    let (a2, a3, a4) = (a * a, a * a * a, a * a * a * a);
    let (a5, a6) = (a4 * a, a4 * a2);
    let x = k0
        * big_n
        * (a + (1.0 - t + c) * a3 / 6.0
            + (5.0 - 18.0 * t + t * t + 72.0 * c - 58.0 * ep2) * a5 / 120.0);
    let y = k0
        * (m + big_n
            * phi.tan()
            * (a2 / 2.0
                + (5.0 - t + 9.0 * c + 4.0 * c * c) * a4 / 24.0
                + (61.0 - 58.0 * t + t * t + 600.0 * c - 330.0 * ep2) * a6 / 720.0));
    let k = k0
        * (1.0
            + (1.0 + c) * a2 / 2.0
            + (5.0 - 4.0 * t + 42.0 * c + 13.0 * c * c - 28.0 * ep2) * a4 / 24.0
            + (61.0 - 148.0 * t + 16.0 * t * t) * a6 / 720.0);
    let gamma =
        a * phi.tan() * (1.0 + a2 * (1.0 + 3.0 * c + 2.0 * c * c) / 3.0 + a4 * (2.0 - t) / 15.0);
    Forward {
        big_n,
        t,
        c,
        a,
        m,
        x,
        y,
        k,
        gamma,
    }
}

/// The inverse series with its footpoint latitude φ₁.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inverse {
    /// μ = M/(a(1 − e²/4 − 3e⁴/64 − 5e⁶/256)), e₁ = (1 − √(1 − e²))/(1 + √(1 − e²)).
    pub mu: f64,
    pub e1: f64,
    /// Footpoint latitude φ₁ (radians), D = x/(N₁k₀).
    pub phi1: f64,
    pub d: f64,
    pub lat_deg: f64,
    pub dlon_deg: f64,
}

/// Snyder's inverse series (eqs. 8-12, 8-17 to 8-25, 7-19, 3-24, 3-26).
pub fn inverse(ell: &Ellipsoid, k0: f64, x: f64, y: f64) -> Result<Inverse> {
    let e2 = ell.e2();
    let ep2 = ell.ep2();
    let (e4, e6) = (e2 * e2, e2 * e2 * e2);
    let mu = y / k0 / (ell.a * (1.0 - e2 / 4.0 - 3.0 * e4 / 64.0 - 5.0 * e6 / 256.0));
    let r = (1.0 - e2).sqrt();
    let e1 = (1.0 - r) / (1.0 + r);
    let phi1 = mu
        + (3.0 * e1 / 2.0 - 27.0 * e1.powi(3) / 32.0) * (2.0 * mu).sin()
        + (21.0 * e1 * e1 / 16.0 - 55.0 * e1.powi(4) / 32.0) * (4.0 * mu).sin()
        + (151.0 * e1.powi(3) / 96.0) * (6.0 * mu).sin()
        + (1097.0 * e1.powi(4) / 512.0) * (8.0 * mu).sin();
    if phi1.is_nan() || phi1.abs() >= std::f64::consts::FRAC_PI_2 {
        return Err(Error::input(
            "northing",
            "puts the footpoint at or beyond the pole",
        ));
    }
    let (s, co) = phi1.sin_cos();
    let c1 = ep2 * co * co;
    let t1 = phi1.tan().powi(2);
    let w = 1.0 - e2 * s * s;
    let n1 = ell.a / w.sqrt();
    let r1 = ell.a * (1.0 - e2) / w.powf(1.5);
    let d = x / (n1 * k0);
    let (d2, d3, d4) = (d * d, d * d * d, d * d * d * d);
    let (d5, d6) = (d4 * d, d4 * d2);
    let phi = phi1
        - n1 * phi1.tan() / r1
            * (d2 / 2.0 - (5.0 + 3.0 * t1 + 10.0 * c1 - 4.0 * c1 * c1 - 9.0 * ep2) * d4 / 24.0
                + (61.0 + 90.0 * t1 + 298.0 * c1 + 45.0 * t1 * t1 - 252.0 * ep2 - 3.0 * c1 * c1)
                    * d6
                    / 720.0);
    let dlon = (d - (1.0 + 2.0 * t1 + c1) * d3 / 6.0
        + (5.0 - 2.0 * c1 + 28.0 * t1 - 3.0 * c1 * c1 + 8.0 * ep2 + 24.0 * t1 * t1) * d5 / 120.0)
        / co;
    Ok(Inverse {
        mu,
        e1,
        phi1,
        d,
        lat_deg: phi.to_degrees(),
        dlon_deg: dlon.to_degrees(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::projection::krueger;

    #[test]
    fn close_to_the_exact_series_near_the_central_meridian() {
        let w = Ellipsoid::by_id("wgs84").unwrap();
        let s = forward(&w, 0.9996, 40.0, 2.0);
        let k = krueger::forward(&w, 0.9996, 40.0, 2.0).unwrap();
        assert!((s.x - k.x).abs() < 1e-3 && (s.y - k.y).abs() < 1e-3);
        let far = forward(&w, 0.9996, 40.0, 15.0);
        let kf = krueger::forward(&w, 0.9996, 40.0, 15.0).unwrap();
        assert!((far.x - kf.x).hypot(far.y - kf.y) > 0.01);
        let i = inverse(&w, 0.9996, k.x, k.y).unwrap();
        assert!((i.lat_deg - 40.0).abs() < 1e-7 && (i.dlon_deg - 2.0).abs() < 1e-7);
    }
}
