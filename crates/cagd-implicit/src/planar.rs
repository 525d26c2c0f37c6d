//! Validation of the input of every algorithm of this crate (a planar rational or
//! polynomial Bézier curve of degree `1..=MAX_IMPLICIT_DEGREE`) and its homogeneous control
//! points `q_i = (w_i x_i, w_i y_i, w_i)` (SPEC-convert §0 and §15.8), exact and `f64`.

use cagd_core::{BezierCurve, Error, Result};

#[cfg(test)]
use crate::rational::{Q, q};

/// The largest curve degree the implicitization accepts. The exact coefficients cost
/// `O(n^5)` word operations per prime, `O(n)` primes (about 7 ms at degree 10 for random
/// doubles, see the crate docs); the curve–curve intersection solves a polynomial of degree
/// `n * m` in the Bernstein basis.
pub const MAX_IMPLICIT_DEGREE: usize = 16;

/// Checks that `curve` is planar and of degree `1..=MAX_IMPLICIT_DEGREE` (points are finite
/// and weights positive by construction of [`BezierCurve`]).
///
/// # Errors
/// [`Error::NotPlanar`], [`Error::NotEnoughPoints`] (degree 0),
/// [`Error::DegreeOutOfRange`] (above the range).
pub fn check_planar(curve: &BezierCurve) -> Result<()> {
    if curve.dim() != 2 {
        return Err(Error::NotPlanar { dim: curve.dim() });
    }
    let n = curve.degree();
    if n == 0 {
        return Err(Error::NotEnoughPoints { got: 1, need: 2 });
    }
    if n > MAX_IMPLICIT_DEGREE {
        return Err(Error::DegreeOutOfRange {
            degree: n,
            max: MAX_IMPLICIT_DEGREE,
        });
    }
    Ok(())
}

/// The weight of control point `i` (1 for a polynomial curve).
pub(crate) fn weight(curve: &BezierCurve, i: usize) -> f64 {
    curve.weights().map_or(1.0, |w| w[i])
}

/// Exact homogeneous control points `(w_i x_i, w_i y_i, w_i)` of a planar curve (the
/// test oracle of the integer route `IntHom::from_curve`).
#[cfg(test)]
pub(crate) fn exact_homogeneous(curve: &BezierCurve) -> Vec<[Q; 3]> {
    (0..=curve.degree())
        .map(|i| {
            let p = curve.point(i);
            let w = q(weight(curve, i));
            [&w * q(p[0]), &w * q(p[1]), w]
        })
        .collect()
}

/// `f64` homogeneous control points (rounded products).
pub(crate) fn homogeneous_f64(curve: &BezierCurve) -> Vec<[f64; 3]> {
    (0..=curve.degree())
        .map(|i| {
            let p = curve.point(i);
            let w = weight(curve, i);
            [w * p[0], w * p[1], w]
        })
        .collect()
}

/// Point and first derivative of the homogeneous curve `sum_i B^n_i(t) q_i` at `t`
/// (de Casteljau; the derivative is `n (b_1 - b_0)` of the last level).
pub(crate) fn hom_eval(hom: &[[f64; 3]], t: f64) -> ([f64; 3], [f64; 3]) {
    let n = hom.len() - 1;
    let mut b: Vec<[f64; 3]> = hom.to_vec();
    let s = 1.0 - t;
    if n == 0 {
        return (b[0], [0.0; 3]);
    }
    for level in 1..n {
        for i in 0..=n - level {
            let next = b[i + 1];
            for (x, y) in b[i].iter_mut().zip(next) {
                *x = s * *x + t * y;
            }
        }
    }
    let nf = n as f64;
    let d = [
        nf * (b[1][0] - b[0][0]),
        nf * (b[1][1] - b[0][1]),
        nf * (b[1][2] - b[0][2]),
    ];
    let p = [
        s * b[0][0] + t * b[1][0],
        s * b[0][1] + t * b[1][1],
        s * b[0][2] + t * b[1][2],
    ];
    (p, d)
}

/// Euclidean point and derivative `(P(t), P'(t))` of the homogeneous curve at `t`
/// (`P = (X, Y)/W`, `P' = ((X', Y') - W' P)/W`).
pub(crate) fn point_and_tangent(hom: &[[f64; 3]], t: f64) -> ([f64; 2], [f64; 2]) {
    let (h, d) = hom_eval(hom, t);
    let p = [h[0] / h[2], h[1] / h[2]];
    let dp = [(d[0] - d[2] * p[0]) / h[2], (d[1] - d[2] * p[1]) / h[2]];
    (p, dp)
}

/// A curve as `f64` homogeneous control points `(X_i, Y_i, W_i)`: evaluation and the
/// Gauss–Newton foot point (used by inversion and intersection).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct HomCurve {
    pub(crate) hom: Vec<[f64; 3]>,
}

impl HomCurve {
    /// The homogeneous points of a planar curve.
    pub(crate) fn new(curve: &BezierCurve) -> Self {
        HomCurve {
            hom: homogeneous_f64(curve),
        }
    }

    /// The degree.
    pub(crate) fn degree(&self) -> usize {
        self.hom.len() - 1
    }

    /// The point at `t`.
    pub(crate) fn point(&self, t: f64) -> [f64; 2] {
        point_and_tangent(&self.hom, t).0
    }

    /// Point and first derivative at `t`.
    pub(crate) fn point_and_tangent(&self, t: f64) -> ([f64; 2], [f64; 2]) {
        point_and_tangent(&self.hom, t)
    }

    /// Gauss–Newton on `|P(t) - p|^2` from `t`; returns the best `t` and its distance.
    pub(crate) fn polish(&self, x: f64, y: f64, mut t: f64) -> (f64, f64) {
        let dist = |t: f64| {
            let p = self.point(t);
            (p[0] - x).hypot(p[1] - y)
        };
        let mut best = (t, dist(t));
        for _ in 0..8 {
            let (p, d) = self.point_and_tangent(t);
            let dd = d[0] * d[0] + d[1] * d[1];
            if dd.is_nan() || dd <= 0.0 {
                break;
            }
            let step = (d[0] * (p[0] - x) + d[1] * (p[1] - y)) / dd;
            t -= step;
            let e = dist(t);
            if e < best.1 {
                best = (t, e);
            }
            if step.abs() <= 1e-16 * t.abs().max(1.0) {
                break;
            }
        }
        best
    }
}

/// The largest absolute control-point coordinate, at least 1 (the scale of relative
/// geometric tolerances).
pub(crate) fn coordinate_scale(hom: &[[f64; 3]]) -> f64 {
    hom.iter()
        .filter(|h| h[2] != 0.0)
        .flat_map(|h| [(h[0] / h[2]).abs(), (h[1] / h[2]).abs()])
        .fold(1.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_non_planar_and_degree_zero() {
        let c3 = BezierCurve::new(vec![0.0; 9], 3).unwrap();
        assert_eq!(check_planar(&c3), Err(Error::NotPlanar { dim: 3 }));
        let c0 = BezierCurve::new(vec![1.0, 2.0], 2).unwrap();
        assert_eq!(
            check_planar(&c0),
            Err(Error::NotEnoughPoints { got: 1, need: 2 })
        );
        let big = BezierCurve::new(vec![0.0; 2 * (MAX_IMPLICIT_DEGREE + 2)], 2).unwrap();
        assert!(matches!(
            check_planar(&big),
            Err(Error::DegreeOutOfRange { .. })
        ));
    }

    #[test]
    fn homogeneous_evaluation_matches_the_curve() {
        let c = BezierCurve::new_rational(
            vec![0.0, 0.0, 1.0, 2.0, 3.0, 1.0, 4.0, 0.0],
            vec![1.0, 2.0, 0.5, 1.5],
            2,
        )
        .unwrap();
        let hom = homogeneous_f64(&c);
        for &t in &[0.0, 0.3, 0.77, 1.0] {
            let (p, dp) = point_and_tangent(&hom, t);
            let e = c.eval(t);
            assert!((p[0] - e[0]).abs() < 1e-14 && (p[1] - e[1]).abs() < 1e-14);
            let h = 1e-6;
            let (a, b) = (c.eval(t - h), c.eval(t + h));
            assert!((dp[0] - (b[0] - a[0]) / (2.0 * h)).abs() < 1e-6);
            assert!((dp[1] - (b[1] - a[1]) / (2.0 * h)).abs() < 1e-6);
        }
    }
}
