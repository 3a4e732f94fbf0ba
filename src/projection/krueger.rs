//! The transverse Mercator by the Krüger series to order 6 in n, as in
//! C. F. F. Karney, "Transverse Mercator with an accuracy of a few
//! nanometers", J. Geodesy 85 (2011) 475–485, eqs. (7)–(36): the conformal
//! latitude exactly through τ′, then a series in the complex variable
//! ζ′ = ξ′ + iη′ for ζ = ξ + iη, and γ and k from the derivative of the same
//! series. Good to about 5 nm within 3900 km of the central meridian.
//!
//! Angles in the structs are radians unless the name ends in `_deg`;
//! lengths are metres; the central meridian is at longitude difference 0.

use super::Ellipsoid;
use crate::error::{Error, Result};

/// Terms of the series.
pub const ORDER: usize = 6;

/// The ellipsoid's constants for the series: n, the rectifying radius A and
/// the coefficients α (forward) and β (inverse).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Series {
    pub n: f64,
    /// A = a/(1 + n)·(1 + n²/4 + n⁴/64 + n⁶/256): 2πA is the meridian's length.
    pub rectifying_radius: f64,
    pub alpha: [f64; ORDER],
    pub beta: [f64; ORDER],
    /// e, for the conformal latitude.
    pub e: f64,
    pub e2: f64,
}

/// Karney (2011), eq. (35): α₁ … α₆ as polynomials in n (coefficients of
/// n¹ … n⁶; row j starts at n^j).
const ALPHA: [[f64; ORDER]; ORDER] = [
    [
        1.0 / 2.0,
        -2.0 / 3.0,
        5.0 / 16.0,
        41.0 / 180.0,
        -127.0 / 288.0,
        7891.0 / 37800.0,
    ],
    [
        0.0,
        13.0 / 48.0,
        -3.0 / 5.0,
        557.0 / 1440.0,
        281.0 / 630.0,
        -1983433.0 / 1935360.0,
    ],
    [
        0.0,
        0.0,
        61.0 / 240.0,
        -103.0 / 140.0,
        15061.0 / 26880.0,
        167603.0 / 181440.0,
    ],
    [
        0.0,
        0.0,
        0.0,
        49561.0 / 161280.0,
        -179.0 / 168.0,
        6601661.0 / 7257600.0,
    ],
    [
        0.0,
        0.0,
        0.0,
        0.0,
        34729.0 / 80640.0,
        -3418889.0 / 1995840.0,
    ],
    [0.0, 0.0, 0.0, 0.0, 0.0, 212378941.0 / 319334400.0],
];

/// Karney (2011), eq. (36): β₁ … β₆.
const BETA: [[f64; ORDER]; ORDER] = [
    [
        1.0 / 2.0,
        -2.0 / 3.0,
        37.0 / 96.0,
        -1.0 / 360.0,
        -81.0 / 512.0,
        96199.0 / 604800.0,
    ],
    [
        0.0,
        1.0 / 48.0,
        1.0 / 15.0,
        -437.0 / 1440.0,
        46.0 / 105.0,
        -1118711.0 / 3870720.0,
    ],
    [
        0.0,
        0.0,
        17.0 / 480.0,
        -37.0 / 840.0,
        -209.0 / 4480.0,
        5569.0 / 90720.0,
    ],
    [
        0.0,
        0.0,
        0.0,
        4397.0 / 161280.0,
        -11.0 / 504.0,
        -830251.0 / 7257600.0,
    ],
    [0.0, 0.0, 0.0, 0.0, 4583.0 / 161280.0, -108847.0 / 3991680.0],
    [0.0, 0.0, 0.0, 0.0, 0.0, 20648693.0 / 638668800.0],
];

fn poly(row: &[f64; ORDER], n: f64) -> f64 {
    // Horner from the highest power: Σ c_i n^(i+1)
    row.iter().rev().fold(0.0, |acc, &c| (acc + c) * n)
}

impl Series {
    /// The series constants of an ellipsoid.
    pub fn new(ell: &Ellipsoid) -> Series {
        let n = ell.n();
        let n2 = n * n;
        let rectifying_radius =
            ell.a / (1.0 + n) * (1.0 + n2 * (1.0 / 4.0 + n2 * (1.0 / 64.0 + n2 / 256.0)));
        let mut alpha = [0.0; ORDER];
        let mut beta = [0.0; ORDER];
        for j in 0..ORDER {
            alpha[j] = poly(&ALPHA[j], n);
            beta[j] = poly(&BETA[j], n);
        }
        let e2 = ell.e2();
        Series {
            n,
            rectifying_radius,
            alpha,
            beta,
            e: e2.sqrt(),
            e2,
        }
    }

    /// The length of the meridian from the equator to a pole, πA/2 (m).
    pub fn quarter_meridian(&self) -> f64 {
        std::f64::consts::FRAC_PI_2 * self.rectifying_radius
    }
}

/// τ′ = tan χ (χ the conformal latitude) from τ = tan φ, exactly:
/// τ′ = τ√(1 + σ²) − σ√(1 + τ²), σ = sinh(e·atanh(e·τ/√(1 + τ²))).
pub fn tau_prime(tau: f64, e: f64) -> f64 {
    let tau1 = tau.hypot(1.0);
    let sigma = (e * (e * tau / tau1).atanh()).sinh();
    sigma.hypot(1.0) * tau - sigma * tau1
}

/// τ from τ′ by Newton's method (Karney 2011, eqs. 19–21); the number of
/// iterations it took. Converges in 2–3 iterations everywhere.
pub fn tau_from_tau_prime(taup: f64, e: f64) -> Result<(f64, usize)> {
    const MAX_ITERATIONS: usize = 10;
    let e2 = e * e;
    let e2m = 1.0 - e2;
    let tol = f64::EPSILON.sqrt() * 0.1 * taup.abs().max(1.0);
    let mut tau = taup / e2m;
    for i in 1..=MAX_ITERATIONS {
        let taupa = tau_prime(tau, e);
        let dtau =
            (taup - taupa) * (1.0 + e2m * tau * tau) / (e2m * tau.hypot(1.0) * taupa.hypot(1.0));
        tau += dtau;
        if dtau.abs() < tol {
            return Ok((tau, i));
        }
    }
    Err(Error::NotConverged {
        what: "the latitude from the conformal latitude".into(),
        iterations: MAX_ITERATIONS,
        detail: format!("τ′ = {taup}"),
    })
}

/// Sums the series at ζ = ξ + iη with coefficients `c` (α forward, β
/// inverse): `(Σ c_j sin 2jξ cosh 2jη, Σ c_j cos 2jξ sinh 2jη,
///   Σ 2j c_j cos 2jξ cosh 2jη, Σ 2j c_j sin 2jξ sinh 2jη)`.
pub fn sums(c: &[f64; ORDER], xi: f64, eta: f64) -> (f64, f64, f64, f64) {
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

/// The Gauss–Schreiber transverse Mercator on the sphere (Karney 2011,
/// eq. 10): `(ξ′, η′)` from τ′ = tan χ and the longitude difference
/// `dlon` (radians): ξ′ = atan2(τ′, cos Δλ), η′ = asinh(sin Δλ/√(τ′² + cos² Δλ)).
pub fn sphere_forward(taup: f64, dlon: f64) -> (f64, f64) {
    let (sl, cl) = dlon.sin_cos();
    (taup.atan2(cl), (sl / taup.hypot(cl)).asinh())
}

/// The sphere's part of the meridian convergence (radians):
/// γ′ = atan2(τ′ sin Δλ, √(1 + τ′²) cos Δλ), `dlon` in radians.
pub fn sphere_convergence(taup: f64, dlon: f64) -> f64 {
    let (sl, cl) = dlon.sin_cos();
    (sl * taup).atan2(cl * taup.hypot(1.0))
}

/// The sphere's part of the point scale: k′ = √(1 − e² sin² φ)·√(1 + τ²)
/// / √(τ′² + cos² Δλ), φ and `dlon` in radians, τ = tan φ.
pub fn sphere_scale(e2: f64, phi: f64, taup: f64, dlon: f64) -> f64 {
    (1.0 - e2 * phi.sin().powi(2)).sqrt() * phi.tan().hypot(1.0) / taup.hypot(dlon.cos())
}

/// The series' part of the forward point scale: k″ = (A/a)·√(p′² + q′²).
pub fn series_scale(s: &Series, a: f64, p: f64, q: f64) -> f64 {
    s.rectifying_radius / a * p.hypot(q)
}

/// The inverse on the sphere: `(τ′, Δλ)` (Δλ in radians) from ξ′, η′:
/// τ′ = sin ξ′/√(sinh² η′ + cos² ξ′), Δλ = atan2(sinh η′, cos ξ′)
/// (τ′ infinite at a pole).
pub fn sphere_inverse(xip: f64, etap: f64) -> (f64, f64) {
    let sh = etap.sinh();
    let c = xip.cos().max(0.0);
    let r = sh.hypot(c);
    let taup = if r == 0.0 {
        f64::INFINITY.copysign(xip)
    } else {
        xip.sin() / r
    };
    (taup, sh.atan2(c))
}

/// The meridian convergence of the inverse (radians): atan2(q, p) +
/// atan2(sin ξ′ tanh η′, cos ξ′).
pub fn inverse_convergence(p: f64, q: f64, xip: f64, etap: f64) -> f64 {
    q.atan2(p) + (xip.sin() * etap.tanh()).atan2(xip.cos().max(0.0))
}

/// The point scale of the inverse without k₀: (A/a)/√(p² + q²)·
/// √(1 − e² + e²/(1 + τ²))·√(1 + τ²)·√(sinh² η′ + cos² ξ′).
pub fn inverse_scale(s: &Series, a: f64, p: f64, q: f64, tau: f64, xip: f64, etap: f64) -> f64 {
    let r = etap.sinh().hypot(xip.cos().max(0.0));
    s.rectifying_radius / a / p.hypot(q)
        * (1.0 - s.e2 + s.e2 / (1.0 + tau * tau)).sqrt()
        * tau.hypot(1.0)
        * r
}

/// The longitude difference (degrees, 0° to 30°) on the parallel at
/// `lat_deg` where `what` of the forward projection, growing with Δλ,
/// reaches `target` (bisection to the last bit): where k = 1, or where x
/// is a given distance.
pub fn along_parallel(
    ell: &Ellipsoid,
    k0: f64,
    lat_deg: f64,
    target: f64,
    what: impl Fn(&Forward) -> f64,
) -> Result<f64> {
    let (mut lo, mut hi) = (0.0, 30.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if what(&forward(ell, k0, lat_deg, mid)?) < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// Every intermediate of the forward projection.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Forward {
    /// τ = tan φ.
    pub tau: f64,
    /// σ = sinh(e·atanh(e·sin φ)).
    pub sigma: f64,
    /// τ′ = tan χ.
    pub tau_prime: f64,
    /// Gauss–Schreiber coordinates on the sphere: ξ′ = atan2(τ′, cos λ),
    /// η′ = asinh(sin λ/√(τ′² + cos² λ)).
    pub xi_prime: f64,
    pub eta_prime: f64,
    /// ξ = ξ′ + Σ α_j sin 2jξ′ cosh 2jη′, η = η′ + Σ α_j cos 2jξ′ sinh 2jη′.
    pub xi: f64,
    pub eta: f64,
    /// x = k₀Aη (east of the central meridian), y = k₀Aξ (north of the
    /// equator), metres.
    pub x: f64,
    pub y: f64,
    /// p′ = 1 + Σ 2jα_j cos 2jξ′ cosh 2jη′, q′ = Σ 2jα_j sin 2jξ′ sinh 2jη′.
    pub p: f64,
    pub q: f64,
    /// γ′ (sphere) and γ″ = atan2(q′, p′); γ = γ′ + γ″ (radians, positive
    /// when grid north is east of true north... as GeographicLib: the
    /// bearing of grid north clockwise from true north).
    pub gamma_sphere: f64,
    pub gamma_series: f64,
    pub gamma: f64,
    /// k′ (sphere), k″ = (A/a)√(p′² + q′²); k = k₀k′k″.
    pub k_sphere: f64,
    pub k_series: f64,
    pub k: f64,
}

/// Forward projection of latitude `lat_deg` at longitude difference
/// `dlon_deg` from the central meridian, with central scale `k0`.
/// Needs |lat| < 90 and |dlon| < 90 (the callers check their own ranges).
pub fn forward(ell: &Ellipsoid, k0: f64, lat_deg: f64, dlon_deg: f64) -> Result<Forward> {
    if lat_deg.is_nan() || lat_deg.abs() >= 90.0 {
        return Err(Error::input(
            "latitude",
            format!("must be strictly between −90° and 90° for the transverse Mercator series (got {lat_deg})"),
        ));
    }
    if dlon_deg.is_nan() || dlon_deg.abs() >= 90.0 {
        return Err(Error::input(
            "longitude",
            format!("must be less than 90° from the central meridian (got {dlon_deg}°)"),
        ));
    }
    let s = Series::new(ell);
    let phi = lat_deg.to_radians();
    let lam = dlon_deg.to_radians();
    let tau = phi.tan();
    let sigma = (s.e * (s.e * phi.sin()).atanh()).sinh();
    let taup = tau_prime(tau, s.e);
    let (xip, etap) = sphere_forward(taup, lam);
    let (a, b, p1, q1) = sums(&s.alpha, xip, etap);
    let xi = xip + a;
    let eta = etap + b;
    let p = 1.0 + p1;
    let q = q1;
    let gamma_sphere = sphere_convergence(taup, lam);
    let gamma_series = q.atan2(p);
    let k_sphere = sphere_scale(s.e2, phi, taup, lam);
    let k_series = series_scale(&s, ell.a, p, q);
    Ok(Forward {
        tau,
        sigma,
        tau_prime: taup,
        xi_prime: xip,
        eta_prime: etap,
        xi,
        eta,
        x: k0 * s.rectifying_radius * eta,
        y: k0 * s.rectifying_radius * xi,
        p,
        q,
        gamma_sphere,
        gamma_series,
        gamma: gamma_sphere + gamma_series,
        k_sphere,
        k_series,
        k: k0 * k_sphere * k_series,
    })
}

/// Every intermediate of the inverse projection.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inverse {
    /// ξ = y/(k₀A), η = x/(k₀A).
    pub xi: f64,
    pub eta: f64,
    /// ξ′ = ξ − Σ β_j sin 2jξ cosh 2jη, η′ = η − Σ β_j cos 2jξ sinh 2jη.
    pub xi_prime: f64,
    pub eta_prime: f64,
    /// τ′ = sin ξ′/√(sinh² η′ + cos² ξ′).
    pub tau_prime: f64,
    /// τ = tan φ from τ′ by Newton's method, and the iterations taken.
    pub tau: f64,
    pub iterations: usize,
    /// Latitude and longitude difference from the central meridian (degrees).
    pub lat_deg: f64,
    pub dlon_deg: f64,
    /// p = 1 − Σ 2jβ_j cos 2jξ cosh 2jη, q = Σ 2jβ_j sin 2jξ sinh 2jη.
    pub p: f64,
    pub q: f64,
    /// Meridian convergence γ (radians) and point scale k.
    pub gamma: f64,
    pub k: f64,
}

/// Inverse projection of `x` (east of the central meridian) and `y` (north
/// of the equator), metres, with central scale `k0`.
pub fn inverse(ell: &Ellipsoid, k0: f64, x: f64, y: f64) -> Result<Inverse> {
    let s = Series::new(ell);
    let xi = y / (k0 * s.rectifying_radius);
    let eta = x / (k0 * s.rectifying_radius);
    if xi.is_nan() || xi.abs() > std::f64::consts::FRAC_PI_2 {
        return Err(Error::input(
            "northing",
            "lies beyond the pole (farther from the equator than the quarter meridian)",
        ));
    }
    if eta.is_nan() || eta.abs() >= 1.0 {
        return Err(Error::input(
            "easting",
            "is too far from the central meridian for the transverse Mercator series",
        ));
    }
    let (a, b, p1, q1) = sums(&s.beta, xi, eta);
    let xip = xi - a;
    let etap = eta - b;
    let p = 1.0 - p1;
    let q = q1;
    let (taup, dlon) = sphere_inverse(xip, etap);
    let (tau, iterations, lat_deg, dlon_deg, gamma, k);
    if taup.is_infinite() {
        // a pole
        tau = f64::INFINITY;
        iterations = 0;
        lat_deg = 90.0_f64.copysign(xip);
        dlon_deg = 0.0;
        gamma = q.atan2(p);
        k = s.rectifying_radius / ell.a / p.hypot(q)
            * (1.0 - s.e2).sqrt()
            * (s.e * s.e.atanh()).exp();
    } else {
        let (t, it) = tau_from_tau_prime(taup, s.e)?;
        tau = t;
        iterations = it;
        lat_deg = tau.atan().to_degrees();
        dlon_deg = dlon.to_degrees();
        gamma = inverse_convergence(p, q, xip, etap);
        k = inverse_scale(&s, ell.a, p, q, tau, xip, etap);
    }
    Ok(Inverse {
        xi,
        eta,
        xi_prime: xip,
        eta_prime: etap,
        tau_prime: taup,
        tau,
        iterations,
        lat_deg,
        dlon_deg,
        p,
        q,
        gamma,
        k: k0 * k,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn published_checkpoint_55n_12e_grs80_zone_32() {
        let grs = Ellipsoid::by_id("grs80").unwrap();
        let f = forward(&grs, 0.9996, 55.0, 3.0).unwrap();
        assert!(
            (f.x + 500_000.0 - 691_875.632_139_661).abs() < 1e-6,
            "{}",
            f.x
        );
        assert!((f.y - 6_098_907.825_005_013).abs() < 1e-6, "{}", f.y);
        assert!((f.gamma.to_degrees() - 2.458_199_874_231_578).abs() < 1e-12);
        assert!((f.k - 1.000_051_680_955_138).abs() < 1e-12);
        let i = inverse(&grs, 0.9996, f.x, f.y).unwrap();
        assert!((i.lat_deg - 55.0).abs() < 1e-12 && (i.dlon_deg - 3.0).abs() < 1e-12);
        assert!((i.gamma - f.gamma).abs() < 1e-14 && (i.k - f.k).abs() < 1e-14);
    }

    #[test]
    fn the_quarter_meridian_of_wgs84() {
        let s = Series::new(&Ellipsoid::by_id("wgs84").unwrap());
        assert!((s.quarter_meridian() - 10_001_965.729_312_724).abs() < 1e-6);
    }
}
