//! 2-D coordinate transformations `(u, v) → (x, y)` estimated from point
//! pairs by least squares through [`crate::lsq`]: every model of Table 9.5.1
//! of the image processing lecture (Helmert, affine, pseudo-affine,
//! projective, second-order conformal, polynomials of order 2 and 3) and the
//! similarity and affine transformation of the worked examples' Example 4
//! with that example's own parameter names.
//!
//! Every model is linear in its parameters except the projective one, which
//! is solved in its linearised form: multiplying
//! `x = (a1·u + a2·v + a3) / (a7·u + a8·v + 1)` out gives
//! `a1·u + a2·v + a3 − a7·u·x − a8·v·x = x` (and the same for `y`), linear
//! in `a1 … a8`. Its residuals `V = A·X − L` are those of the linearised
//! equations, `D·(x̂ − x)` with `D = a7·u + a8·v + 1`; [`Fit::point_residuals`]
//! holds `x̂ − x` itself for every model.
//!
//! A polynomial of order `k` has the terms `u^p·v^q` with `p + q ≤ k`
//! (6 per coordinate for `k = 2`, 10 for `k = 3`); its parameters are named
//! `a_ij` with `i = p + 1`, `j = q + 1` as in the lecture's double sum.

use crate::error::{Error, Result};
use crate::lsq::{self, Adjustment};

/// Largest absolute coordinate accepted (a guard against sums that overflow
/// in the normal equations of the cubic polynomial).
pub const MAX_COORD: f64 = 1e7;

/// A transformation model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Model {
    /// Table 9.5.1 (1): `x = a·u + b·v + c`, `y = −b·u + a·v + d`.
    Helmert,
    /// Table 9.5.1 (2): `x = a·u + b·v + c`, `y = d·u + e·v + f`.
    Affine,
    /// Table 9.5.1 (3): `x = a1·uv + a2·u + a3·v + a4`, `y = a5·uv + a6·u + a7·v + a8`.
    PseudoAffine,
    /// Table 9.5.1 (4), with the denominator `a7·u + a8·v + 1`.
    Projective,
    /// Table 9.5.1 (5): the conformal map `z = (a1 − i·a2)·w + (a3 − i·a4)·w² + a5 + i·a6`.
    Conformal2,
    /// Table 9.5.1 (6), all terms `u^p·v^q` with `p + q ≤ 2`.
    Polynomial2,
    /// Table 9.5.1 (6), all terms `u^p·v^q` with `p + q ≤ 3`.
    Polynomial3,
    /// Example 4 (a): `x = a·x′ − b·y′ + c`, `y = b·x′ + a·y′ + d`.
    Similarity,
    /// Example 4 (b): `x = a·x′ + b·y′ + e`, `y = c·x′ + d·y′ + f`,
    /// parameters in the order `[a, b, e, c, d, f]`.
    FiducialAffine,
}

/// Exponents `(p, q)` of the polynomial terms, in parameter order.
const POLY_TERMS: [(i32, i32); 10] = [
    (0, 0),
    (1, 0),
    (0, 1),
    (2, 0),
    (1, 1),
    (0, 2),
    (3, 0),
    (2, 1),
    (1, 2),
    (0, 3),
];

impl Model {
    /// The models of Table 9.5.1, in the table's order.
    pub const TABLE: [Model; 7] = [
        Model::Helmert,
        Model::Affine,
        Model::PseudoAffine,
        Model::Projective,
        Model::Conformal2,
        Model::Polynomial2,
        Model::Polynomial3,
    ];

    /// The id used by the catalog (`helmert`, `pseudo-affine`, …).
    pub fn id(self) -> &'static str {
        match self {
            Model::Helmert => "helmert",
            Model::Affine => "affine",
            Model::PseudoAffine => "pseudo-affine",
            Model::Projective => "projective",
            Model::Conformal2 => "conformal-2",
            Model::Polynomial2 => "polynomial-2",
            Model::Polynomial3 => "polynomial-3",
            Model::Similarity => "similarity",
            Model::FiducialAffine => "affine-fiducials",
        }
    }

    /// The model for a catalog id.
    pub fn from_id(id: &str) -> Option<Model> {
        Model::TABLE
            .into_iter()
            .chain([Model::Similarity, Model::FiducialAffine])
            .find(|m| m.id() == id)
    }

    /// A readable name.
    pub fn name(self) -> &'static str {
        match self {
            Model::Helmert => "Helmert",
            Model::Affine | Model::FiducialAffine => "affine",
            Model::PseudoAffine => "pseudo-affine",
            Model::Projective => "projective",
            Model::Conformal2 => "second-order conformal",
            Model::Polynomial2 => "second-order polynomial",
            Model::Polynomial3 => "third-order polynomial",
            Model::Similarity => "similarity",
        }
    }

    /// The number of polynomial terms per coordinate, for polynomial models.
    fn poly_terms(self) -> Option<usize> {
        match self {
            Model::Polynomial2 => Some(6),
            Model::Polynomial3 => Some(10),
            _ => None,
        }
    }

    /// The parameter names, in parameter order.
    pub fn param_names(self) -> Vec<String> {
        let list = |xs: &[&str]| xs.iter().map(|s| s.to_string()).collect();
        match self {
            Model::Helmert | Model::Similarity => list(&["a", "b", "c", "d"]),
            Model::Affine => list(&["a", "b", "c", "d", "e", "f"]),
            Model::FiducialAffine => list(&["a", "b", "e", "c", "d", "f"]),
            Model::PseudoAffine | Model::Projective => (1..=8).map(|i| format!("a{i}")).collect(),
            Model::Conformal2 => (1..=6).map(|i| format!("a{i}")).collect(),
            Model::Polynomial2 | Model::Polynomial3 => {
                let k = self.poly_terms().unwrap_or(0);
                ["a", "b"]
                    .iter()
                    .flat_map(|c| {
                        POLY_TERMS
                            .iter()
                            .take(k)
                            .map(move |(p, q)| format!("{c}{}{}", p + 1, q + 1))
                    })
                    .collect()
            }
        }
    }

    /// The number of parameters `u`.
    pub fn n_params(self) -> usize {
        match self {
            Model::Helmert | Model::Similarity => 4,
            Model::Affine | Model::FiducialAffine | Model::Conformal2 => 6,
            Model::PseudoAffine | Model::Projective => 8,
            Model::Polynomial2 => 12,
            Model::Polynomial3 => 20,
        }
    }

    /// The fewest point pairs that determine the model (two equations each).
    pub fn min_points(self) -> usize {
        self.n_params().div_ceil(2)
    }

    /// True for the projective model, solved in linearised form.
    pub fn is_linearised(self) -> bool {
        self == Model::Projective
    }

    /// True when the inverse is again a transformation of the same model,
    /// in closed form.
    pub fn has_closed_inverse(self) -> bool {
        matches!(
            self,
            Model::Helmert
                | Model::Affine
                | Model::Projective
                | Model::Similarity
                | Model::FiducialAffine
        )
    }

    /// The two rows of the design matrix and the two observations for one
    /// point pair: `(row for x, row for y, x, y)`.
    pub fn rows(self, p: &PointPair) -> (Vec<f64>, Vec<f64>, f64, f64) {
        let PointPair { u, v, x, y } = *p;
        let (rx, ry) = match self {
            Model::Helmert => (vec![u, v, 1.0, 0.0], vec![v, -u, 0.0, 1.0]),
            Model::Similarity => (vec![u, -v, 1.0, 0.0], vec![v, u, 0.0, 1.0]),
            Model::Affine | Model::FiducialAffine => (
                vec![u, v, 1.0, 0.0, 0.0, 0.0],
                vec![0.0, 0.0, 0.0, u, v, 1.0],
            ),
            Model::PseudoAffine => (
                vec![u * v, u, v, 1.0, 0.0, 0.0, 0.0, 0.0],
                vec![0.0, 0.0, 0.0, 0.0, u * v, u, v, 1.0],
            ),
            Model::Projective => (
                vec![u, v, 1.0, 0.0, 0.0, 0.0, -u * x, -v * x],
                vec![0.0, 0.0, 0.0, u, v, 1.0, -u * y, -v * y],
            ),
            Model::Conformal2 => {
                let (d, w) = (u * u - v * v, 2.0 * u * v);
                (vec![u, v, d, w, 1.0, 0.0], vec![v, -u, w, -d, 0.0, 1.0])
            }
            Model::Polynomial2 | Model::Polynomial3 => {
                let k = self.poly_terms().unwrap_or(0);
                let terms: Vec<f64> = POLY_TERMS
                    .iter()
                    .take(k)
                    .map(|&(p, q)| u.powi(p) * v.powi(q))
                    .collect();
                let zeros = vec![0.0; k];
                (
                    [terms.clone(), zeros.clone()].concat(),
                    [zeros, terms].concat(),
                )
            }
        };
        (rx, ry, x, y)
    }
}

/// One control point: its position `(u, v)` in the source system and
/// `(x, y)` in the target system.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointPair {
    pub u: f64,
    pub v: f64,
    pub x: f64,
    pub y: f64,
}

/// A transformation: a model with its parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct Transform {
    pub model: Model,
    pub params: Vec<f64>,
}

impl Transform {
    /// A transformation from its parameters (as many as the model has).
    pub fn new(model: Model, params: Vec<f64>) -> Result<Self> {
        if params.len() != model.n_params() {
            return Err(Error::input(
                "parameters",
                format!(
                    "the {} model has {} parameters, {} given",
                    model.name(),
                    model.n_params(),
                    params.len()
                ),
            ));
        }
        if params.iter().any(|p| !p.is_finite()) {
            return Err(Error::input(
                "parameters",
                "must be finite numbers (NaN or infinity given)",
            ));
        }
        Ok(Transform { model, params })
    }

    /// Maps `(u, v)` to `(x, y)`. Fails only for the projective model on its
    /// vanishing line (denominator zero) or for a result that overflows.
    pub fn apply(&self, u: f64, v: f64) -> Result<(f64, f64)> {
        let p = &self.params;
        let at = |i: usize| p.get(i).copied().unwrap_or(0.0);
        let (x, y) = if self.model == Model::Projective {
            let den = at(6) * u + at(7) * v + 1.0;
            let scale = 1.0 + (at(6) * u).abs() + (at(7) * v).abs();
            if den.abs() <= 1e-12 * scale {
                return Err(Error::input(
                    "point",
                    format!(
                        "({u}, {v}) lies on the vanishing line of the projective transformation (a7·u + a8·v + 1 = 0)"
                    ),
                ));
            }
            (
                (at(0) * u + at(1) * v + at(2)) / den,
                (at(3) * u + at(4) * v + at(5)) / den,
            )
        } else {
            // Every other model is linear in its parameters: x = A_x·p, y = A_y·p.
            let (rx, ry, _, _) = self.model.rows(&PointPair {
                u,
                v,
                x: 0.0,
                y: 0.0,
            });
            let dot = |r: &[f64]| r.iter().zip(p).map(|(a, b)| a * b).sum::<f64>();
            (dot(&rx), dot(&ry))
        };
        if x.is_finite() && y.is_finite() {
            Ok((x, y))
        } else {
            Err(Error::input(
                "point",
                format!("({u}, {v}) maps outside the range of finite numbers"),
            ))
        }
    }

    /// The homogeneous 3×3 matrix of a Helmert, similarity, affine or
    /// projective transformation (`None` for the other models).
    pub fn matrix(&self) -> Option<[[f64; 3]; 3]> {
        let p = &self.params;
        let g = |i: usize| p.get(i).copied().unwrap_or(0.0);
        match self.model {
            Model::Helmert => Some([[g(0), g(1), g(2)], [-g(1), g(0), g(3)], [0.0, 0.0, 1.0]]),
            Model::Similarity => Some([[g(0), -g(1), g(2)], [g(1), g(0), g(3)], [0.0, 0.0, 1.0]]),
            Model::Affine => Some([[g(0), g(1), g(2)], [g(3), g(4), g(5)], [0.0, 0.0, 1.0]]),
            Model::FiducialAffine => {
                Some([[g(0), g(1), g(2)], [g(3), g(4), g(5)], [0.0, 0.0, 1.0]])
            }
            Model::Projective => Some([[g(0), g(1), g(2)], [g(3), g(4), g(5)], [g(6), g(7), 1.0]]),
            _ => None,
        }
    }

    /// The inverse transformation `(x, y) → (u, v)`, of the same model, for
    /// the models that have one in closed form. `Ok(None)` for the others
    /// (pseudo-affine, second-order conformal and polynomials: inverting them
    /// means solving a quadratic or cubic, with no single-valued formula);
    /// an error when the transformation is singular.
    pub fn inverse(&self) -> Result<Option<Transform>> {
        let Some(m) = self.matrix() else {
            return Ok(None);
        };
        let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        let norm: f64 = m.iter().flatten().map(|x| x.abs()).fold(0.0, f64::max);
        let regular = det.abs() > 1e-14 * norm.powi(3); // false for NaN too
        if !regular {
            return Err(Error::Singular {
                reason: format!(
                    "the {} transformation is singular (determinant {det:e}) and has no inverse",
                    self.model.name()
                ),
            });
        }
        // Adjugate / determinant.
        let c = |r1: usize, c1: usize, r2: usize, c2: usize| {
            m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]
        };
        let inv = [
            [c(1, 1, 2, 2), -c(0, 1, 2, 2), c(0, 1, 1, 2)],
            [-c(1, 0, 2, 2), c(0, 0, 2, 2), -c(0, 0, 1, 2)],
            [c(1, 0, 2, 1), -c(0, 0, 2, 1), c(0, 0, 1, 1)],
        ];
        let w = inv[2][2];
        let finite_origin = w.abs() > 1e-14 * norm.powi(2);
        if !finite_origin {
            return Err(Error::Singular {
                reason: "the inverse projective transformation maps the origin of (x, y) to infinity and cannot be written with the denominator a7·x + a8·y + 1".to_string(),
            });
        }
        let h = |r: usize, c: usize| inv[r][c] / w;
        let params = match self.model {
            Model::Helmert => vec![h(0, 0), h(0, 1), h(0, 2), h(1, 2)],
            Model::Similarity => vec![h(0, 0), h(1, 0), h(0, 2), h(1, 2)],
            Model::Affine | Model::FiducialAffine => {
                vec![h(0, 0), h(0, 1), h(0, 2), h(1, 0), h(1, 1), h(1, 2)]
            }
            _ => vec![
                h(0, 0),
                h(0, 1),
                h(0, 2),
                h(1, 0),
                h(1, 1),
                h(1, 2),
                h(2, 0),
                h(2, 1),
            ],
        };
        Transform::new(self.model, params).map(Some)
    }
}

/// An estimated transformation with every intermediate of the adjustment.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    pub transform: Transform,
    /// The design matrix, two rows per point (`x` row, then `y` row).
    pub a: Vec<Vec<f64>>,
    /// The observations `L`, `[x1, y1, x2, y2, …]`.
    pub l: Vec<f64>,
    /// The adjustment (`N`, `AᵀL`, `X`, `V = A·X − L`, `σ0`, `Qxx`, …).
    pub adjustment: Adjustment,
    /// Each source point transformed, `(x̂, ŷ)`.
    pub fitted: Vec<[f64; 2]>,
    /// `(x̂ − x, ŷ − y)` per point; equal to `V` for the models linear in
    /// their parameters, `V / D` for the linearised projective model.
    pub point_residuals: Vec<[f64; 2]>,
}

/// Checks point pairs before any arithmetic: finite, within
/// [`MAX_COORD`], enough of them, no two at the same position, spread in two
/// directions where the model needs it, and for the projective model from
/// four points no three on a line. Errors name the field `points`.
pub fn check_points(model: Model, points: &[PointPair]) -> Result<()> {
    let err = |reason: String| Error::input("points", reason);
    for (i, p) in points.iter().enumerate() {
        for (name, c) in [("u", p.u), ("v", p.v), ("x", p.x), ("y", p.y)] {
            if !c.is_finite() {
                return Err(err(format!(
                    "point {}: {name} is {}; give a finite number",
                    i + 1,
                    if c.is_nan() { "NaN" } else { "infinite" }
                )));
            }
            if c.abs() > MAX_COORD {
                return Err(err(format!(
                    "point {}: {name} = {c} is beyond ±{MAX_COORD:e}",
                    i + 1
                )));
            }
        }
    }
    let need = model.min_points();
    if points.len() < need {
        return Err(err(format!(
            "the {} model has {} parameters and needs at least {need} points; {} given ({} more needed)",
            model.name(),
            model.n_params(),
            points.len(),
            need - points.len()
        )));
    }
    for (i, p) in points.iter().enumerate() {
        for (j, q) in points.iter().enumerate().skip(i + 1) {
            if p.u == q.u && p.v == q.v {
                return Err(err(format!(
                    "points {} and {} have the same source position (u, v) = ({}, {}); each control point must be measured once",
                    i + 1,
                    j + 1,
                    p.u,
                    p.v
                )));
            }
            if p.x == q.x && p.y == q.y {
                return Err(err(format!(
                    "points {} and {} have the same target position (x, y) = ({}, {}); two different points cannot map to one",
                    i + 1,
                    j + 1,
                    p.x,
                    p.y
                )));
            }
        }
    }
    // Helmert and similarity are fixed by any two distinct points and the
    // second-order conformal map z = c1·w + c2·w² + c3 by any three (a
    // complex Vandermonde system, regular for distinct w, on a line or not);
    // every other model needs points spread in two directions.
    if !matches!(
        model,
        Model::Helmert | Model::Similarity | Model::Conformal2
    ) {
        let src: Vec<[f64; 2]> = points.iter().map(|p| [p.u, p.v]).collect();
        if collinear(&src) {
            return Err(err(format!(
                "all {} points lie on one line in the source system (u, v); the {} model needs points spread in two directions",
                points.len(),
                model.name()
            )));
        }
    }
    if model == Model::Projective && points.len() == 4 {
        for (side, pts) in [
            (
                "source (u, v)",
                points.iter().map(|p| [p.u, p.v]).collect::<Vec<_>>(),
            ),
            ("target (x, y)", points.iter().map(|p| [p.x, p.y]).collect()),
        ] {
            for skip in 0..4 {
                let three: Vec<[f64; 2]> = pts
                    .iter()
                    .enumerate()
                    .filter(|(k, _)| *k != skip)
                    .map(|(_, p)| *p)
                    .collect();
                if collinear(&three) {
                    let which: Vec<String> = (1..=4)
                        .filter(|k| *k != skip + 1)
                        .map(|k| k.to_string())
                        .collect();
                    return Err(err(format!(
                        "points {} lie on one line in the {side} system; a projective transformation from four points needs no three of them on a line",
                        which.join(", ")
                    )));
                }
            }
        }
    }
    Ok(())
}

/// True when the points lie on one line: the smaller eigenvalue of their
/// scatter matrix is negligible beside the larger.
fn collinear(pts: &[[f64; 2]]) -> bool {
    let n = pts.len() as f64;
    if pts.len() < 3 {
        return true;
    }
    let mu = pts
        .iter()
        .fold([0.0, 0.0], |s, p| [s[0] + p[0], s[1] + p[1]]);
    let mu = [mu[0] / n, mu[1] / n];
    let (mut sxx, mut syy, mut sxy) = (0.0, 0.0, 0.0);
    for p in pts {
        let (dx, dy) = (p[0] - mu[0], p[1] - mu[1]);
        sxx += dx * dx;
        syy += dy * dy;
        sxy += dx * dy;
    }
    let tr = sxx + syy;
    let det = sxx * syy - sxy * sxy;
    // λmin·λmax = det, λmin + λmax = tr: λmin/λmax ≈ det / tr² when small.
    let spread = det > 1e-20 * tr * tr; // false for NaN too
    !spread
}

/// Estimates `model` from point pairs by least squares (each point gives an
/// `x` and a `y` observation; unit weights).
pub fn fit(model: Model, points: &[PointPair]) -> Result<Fit> {
    check_points(model, points)?;
    let mut a = Vec::with_capacity(2 * points.len());
    let mut l = Vec::with_capacity(2 * points.len());
    for p in points {
        let (rx, ry, x, y) = model.rows(p);
        a.push(rx);
        a.push(ry);
        l.push(x);
        l.push(y);
    }
    let adjustment = lsq::adjust(&a, &l, None).map_err(|e| match e {
        Error::Singular { reason } => Error::input(
            "points",
            format!(
                "these points do not determine the {} model: {reason}",
                model.name()
            ),
        ),
        other => other.in_field("points"),
    })?;
    let transform = Transform::new(model, adjustment.x.clone())
        .map_err(|e| Error::Internal(format!("fit produced bad parameters: {e}")))?;
    let mut fitted = Vec::with_capacity(points.len());
    let mut point_residuals = Vec::with_capacity(points.len());
    for (i, p) in points.iter().enumerate() {
        let (fx, fy) = transform.apply(p.u, p.v).map_err(|_| {
            Error::input(
                "points",
                format!(
                    "point {} lies on the vanishing line of the fitted projective transformation",
                    i + 1
                ),
            )
        })?;
        fitted.push([fx, fy]);
        point_residuals.push([fx - p.x, fy - p.y]);
    }
    Ok(Fit {
        transform,
        a,
        l,
        adjustment,
        fitted,
        point_residuals,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pp(u: f64, v: f64, x: f64, y: f64) -> PointPair {
        PointPair { u, v, x, y }
    }

    #[test]
    fn every_model_has_consistent_sizes() {
        for m in Model::TABLE
            .into_iter()
            .chain([Model::Similarity, Model::FiducialAffine])
        {
            assert_eq!(m.param_names().len(), m.n_params(), "{m:?}");
            let (rx, ry, _, _) = m.rows(&pp(1.0, 2.0, 3.0, 4.0));
            assert_eq!(rx.len(), m.n_params());
            assert_eq!(ry.len(), m.n_params());
            assert_eq!(Model::from_id(m.id()), Some(m));
        }
        assert_eq!(
            Model::Polynomial2.param_names()[..6],
            ["a11", "a21", "a12", "a31", "a22", "a13"]
        );
    }

    #[test]
    fn helmert_inverse_round_trips() {
        let t = Transform::new(Model::Helmert, vec![0.8, 0.3, 5.0, -2.0]).unwrap();
        let i = t.inverse().unwrap().unwrap();
        let (x, y) = t.apply(3.0, 7.0).unwrap();
        let (u, v) = i.apply(x, y).unwrap();
        assert!((u - 3.0).abs() < 1e-12 && (v - 7.0).abs() < 1e-12);
    }

    #[test]
    fn four_points_three_on_a_line_are_refused_for_the_projective_model() {
        let pts = [
            pp(0.0, 0.0, 0.0, 0.0),
            pp(1.0, 1.0, 1.0, 0.0),
            pp(2.0, 2.0, 1.0, 1.0),
            pp(0.0, 1.0, 0.0, 1.0),
        ];
        let e = fit(Model::Projective, &pts).unwrap_err().to_string();
        assert!(e.contains("points 1, 2, 3 lie on one line"), "{e}");
    }
}
