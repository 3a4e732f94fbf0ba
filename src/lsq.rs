//! Least-squares adjustment by indirect observations (Gauss–Markov):
//! `L + V = A·X` with optional weights, solved through the normal equations
//! with every intermediate kept for the steps: `N = AᵀPA`, `AᵀPL`,
//! `X = N⁻¹AᵀPL`, `V = A·X − L`, `σ0 = √(VᵀPV / r)`, `Qxx = N⁻¹` and the
//! parameters' standard deviations `σ0·√q_ii`.
//!
//! Rank and condition are checked on the column-scaled normal matrix (so that
//! a column of pixel coordinates in the thousands beside a column of ones is
//! not mistaken for ill-conditioning): a system whose smallest scaled
//! eigenvalue is below [`SINGULAR_RATIO`] of the largest is refused with the
//! reason, never solved into nonsense.

use crate::error::{Error, Result};
use nalgebra::{DMatrix, DVector, SymmetricEigen};

/// Scaled eigenvalue ratio below which the normal matrix counts as singular.
pub const SINGULAR_RATIO: f64 = 1e-12;
/// Scaled condition number above which a solution is flagged as weak.
pub const ILL_CONDITIONED: f64 = 1e8;

/// The result of an adjustment, with its intermediates.
#[derive(Debug, Clone, PartialEq)]
pub struct Adjustment {
    /// The estimated parameters `X`.
    pub x: Vec<f64>,
    /// Residuals `V = A·X − L`, one per observation.
    pub v: Vec<f64>,
    /// The normal matrix `N = AᵀPA`.
    pub n: Vec<Vec<f64>>,
    /// The right-hand side `AᵀPL`.
    pub atl: Vec<f64>,
    /// The cofactor matrix of the parameters, `Qxx = N⁻¹`.
    pub qxx: Vec<Vec<f64>>,
    /// `r = n − u`, observations minus unknowns.
    pub redundancy: usize,
    /// `VᵀPV`.
    pub vtpv: f64,
    /// `σ0 = √(VᵀPV / r)`; `None` when `r = 0` (no redundancy, no estimate).
    pub sigma0: Option<f64>,
    /// `σ0·√q_ii` per parameter; `None` when `σ0` is.
    pub std_dev: Option<Vec<f64>>,
    /// Condition number of the column-scaled normal matrix.
    pub condition: f64,
}

/// Solves `L + V = A·X` for `X` by least squares. `a` has one row per
/// observation; `weights`, if given, is the diagonal of `P` (all > 0).
pub fn adjust(a: &[Vec<f64>], l: &[f64], weights: Option<&[f64]>) -> Result<Adjustment> {
    let n_obs = a.len();
    let u = a.first().map_or(0, Vec::len);
    if u == 0 {
        return Err(Error::input("A", "the design matrix has no columns"));
    }
    if let Some((i, row)) = a.iter().enumerate().find(|(_, r)| r.len() != u) {
        return Err(Error::input(
            "A",
            format!("row {} has {} entries, row 1 has {u}", i + 1, row.len()),
        ));
    }
    if l.len() != n_obs {
        return Err(Error::input(
            "L",
            format!("has {} observations but A has {n_obs} rows", l.len()),
        ));
    }
    if n_obs < u {
        return Err(Error::TooFewObservations {
            needed: u,
            given: n_obs,
        });
    }
    if a.iter().flatten().chain(l).any(|x| !x.is_finite()) {
        return Err(Error::input("A", "A and L must hold finite numbers only"));
    }
    let p = match weights {
        Some(w) if w.len() != n_obs => {
            return Err(Error::input(
                "P",
                format!("has {} weights for {n_obs} observations", w.len()),
            ))
        }
        Some(w) if w.iter().any(|x| !(x.is_finite() && *x > 0.0)) => {
            return Err(Error::input("P", "weights must be positive finite numbers"))
        }
        Some(w) => DVector::from_column_slice(w),
        None => DVector::from_element(n_obs, 1.0),
    };

    let am = DMatrix::from_fn(n_obs, u, |i, j| a[i][j]);
    let lv = DVector::from_column_slice(l);
    let atp = DMatrix::from_fn(u, n_obs, |j, i| a[i][j] * p[i]);
    let n = &atp * &am;
    let atl = &atp * &lv;

    // Rank and condition on the scaled normal matrix D·N·D, D = diag(1/√n_jj).
    if let Some(j) = (0..u).find(|&j| n[(j, j)] == 0.0) {
        return Err(Error::Singular {
            reason: format!(
                "parameter {} does not appear in any observation (its column of A is zero)",
                j + 1
            ),
        });
    }
    let d = DVector::from_fn(u, |j, _| 1.0 / n[(j, j)].sqrt());
    let ns = DMatrix::from_fn(u, u, |i, j| n[(i, j)] * d[i] * d[j]);
    let eig = SymmetricEigen::new(ns.clone());
    let max = eig.eigenvalues.max();
    let min = eig.eigenvalues.min();
    let determined = min > SINGULAR_RATIO * max; // false for NaN too
    if !determined {
        let rank = eig
            .eigenvalues
            .iter()
            .filter(|&&e| e > SINGULAR_RATIO * max)
            .count();
        return Err(Error::Singular {
            reason: format!(
                "the normal matrix is singular (rank {rank} of {u}): the observations do not determine all {u} parameters"
            ),
        });
    }
    let condition = max / min;
    let chol = ns.cholesky().ok_or_else(|| Error::Singular {
        reason: "the normal matrix is not positive definite".to_string(),
    })?;
    let qs = chol.inverse();
    let qxx = DMatrix::from_fn(u, u, |i, j| qs[(i, j)] * d[i] * d[j]);
    let x = &qxx * &atl;
    let v = &am * &x - &lv;
    let vtpv: f64 = v.iter().zip(p.iter()).map(|(vi, pi)| vi * vi * pi).sum();
    let redundancy = n_obs - u;
    let sigma0 = (redundancy > 0).then(|| (vtpv / redundancy as f64).sqrt());
    let std_dev = sigma0.map(|s| (0..u).map(|j| s * qxx[(j, j)].max(0.0).sqrt()).collect());
    let rows = |m: &DMatrix<f64>| -> Vec<Vec<f64>> {
        (0..m.nrows())
            .map(|i| (0..m.ncols()).map(|j| m[(i, j)]).collect())
            .collect()
    };
    Ok(Adjustment {
        x: x.iter().copied().collect(),
        v: v.iter().copied().collect(),
        n: rows(&n),
        atl: atl.iter().copied().collect(),
        qxx: rows(&qxx),
        redundancy,
        vtpv,
        sigma0,
        std_dev,
        condition,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fits_a_line_exactly_and_with_residuals() {
        // y = 2 + 3x, observed without noise
        let a: Vec<Vec<f64>> = (0..5).map(|i| vec![1.0, i as f64]).collect();
        let l: Vec<f64> = (0..5).map(|i| 2.0 + 3.0 * i as f64).collect();
        let s = adjust(&a, &l, None).unwrap();
        assert!((s.x[0] - 2.0).abs() < 1e-12 && (s.x[1] - 3.0).abs() < 1e-12);
        assert_eq!(s.redundancy, 3);
        assert!(s.sigma0.unwrap() < 1e-12);
        // mean of 1, 2, 4: residuals sum to zero, sigma0 by hand
        let s = adjust(&[vec![1.0], vec![1.0], vec![1.0]], &[1.0, 2.0, 4.0], None).unwrap();
        assert!((s.x[0] - 7.0 / 3.0).abs() < 1e-12);
        let vtv: f64 = [1.0f64, 2.0, 4.0]
            .iter()
            .map(|y| (7.0 / 3.0 - y).powi(2))
            .sum();
        assert!((s.sigma0.unwrap() - (vtv / 2.0).sqrt()).abs() < 1e-12);
        assert!((s.std_dev.unwrap()[0] - s.sigma0.unwrap() / 3f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn weights_pull_the_estimate() {
        let a = [vec![1.0], vec![1.0]];
        let s = adjust(&a, &[0.0, 3.0], Some(&[2.0, 1.0])).unwrap();
        assert!((s.x[0] - 1.0).abs() < 1e-12);
    }

    #[test]
    fn exactly_determined_has_no_sigma0() {
        let s = adjust(&[vec![1.0, 0.0], vec![0.0, 2.0]], &[3.0, 4.0], None).unwrap();
        assert_eq!(s.redundancy, 0);
        assert_eq!(s.sigma0, None);
        assert_eq!(s.x, vec![3.0, 2.0]);
    }

    #[test]
    fn degenerate_systems_are_refused_with_a_reason() {
        let e = adjust(&[vec![1.0, 2.0]], &[1.0], None).unwrap_err();
        assert_eq!(
            e.to_string(),
            "too few observations: 2 are needed, 1 given (1 more needed)"
        );
        let e = adjust(
            &[vec![1.0, 2.0], vec![2.0, 4.0], vec![3.0, 6.0]],
            &[1.0, 2.0, 3.0],
            None,
        )
        .unwrap_err();
        assert!(e.to_string().contains("rank 1 of 2"), "{e}");
        let e = adjust(&[vec![1.0, 0.0], vec![1.0, 0.0]], &[1.0, 2.0], None).unwrap_err();
        assert!(e.to_string().contains("parameter 2"), "{e}");
        assert!(adjust(&[vec![f64::NAN]], &[1.0], None).is_err());
        assert!(adjust(&[vec![1.0]], &[1.0], Some(&[0.0])).is_err());
    }

    #[test]
    fn large_coordinates_beside_ones_are_not_ill_conditioned() {
        let a: Vec<Vec<f64>> = (0..4)
            .map(|i| vec![5000.0 + 100.0 * i as f64, 1.0])
            .collect();
        let l: Vec<f64> = a.iter().map(|r| 0.04 * r[0] - 115.0).collect();
        let s = adjust(&a, &l, None).unwrap();
        assert!((s.x[0] - 0.04).abs() < 1e-12 && (s.x[1] + 115.0).abs() < 1e-9);
    }
}
