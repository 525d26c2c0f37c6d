//! Exact reducibility: detecting that a curve is a degree-elevated lower-degree curve
//! (seed 000 §14.1, Theorem 14.1.1: degree `< j` iff `Delta^j P_0 = 0`).

use cagd_core::{BezierCurve, Result, check_tolerance};

use super::method::Method;
use super::operator::operator;
use super::reduce::{Reduction, reduce};

/// Default relative tolerance of [`exact_degree`].
///
/// Justification: the power coefficient of `t^j` is `C(n,j) Delta^j P_0`, and
/// `||Delta^j P_0||_inf <= 2^j max_i ||P_i||_inf`, so we compare
/// `||Delta^j P_0||_inf / (2^j max ||P_i||_inf)` with the tolerance. A curve elevated in
/// `f64` carries control-point rounding of a few ulp, which the differences amplify by at
/// most `2^j`, and the differencing itself adds at most `j` ulp: the ratio stays below
/// `(n + 4) eps <= 1.6e-14` for `n <= 64`. `1e-12` leaves a margin of 60 and still calls a
/// genuine top coefficient of relative size `1e-12` significant.
pub const DEFAULT_REL_TOL: f64 = 1e-12;

/// The smallest degree `k` such that the curve is, up to `rel_tol`, a degree-`k` curve
/// elevated to its degree `n`: every `Delta^j P_0`, `j > k`, has
/// `||Delta^j P_0||_inf <= rel_tol * 2^j * max_i ||P_i||_inf`. Rational curves are tested
/// in homogeneous coordinates.
///
/// # Errors
/// [`cagd_core::Error::BadTolerance`] when `rel_tol` is not finite and positive.
pub fn exact_degree(curve: &BezierCurve, rel_tol: f64) -> Result<usize> {
    check_tolerance(rel_tol)?;
    let (pts, d) = match curve.weights() {
        None => (curve.points().to_vec(), curve.dim()),
        Some(_) => (curve.homogeneous_points(), curve.dim() + 1),
    };
    let n = curve.degree();
    let scale = pts.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if scale == 0.0 {
        return Ok(0);
    }
    // Difference table in place: after level j, entry 0 holds Delta^j P_0.
    let mut diff = pts;
    let mut degree = 0;
    let mut pow = 1.0;
    for j in 1..=n {
        for i in 0..=n - j {
            for k in 0..d {
                diff[i * d + k] = diff[(i + 1) * d + k] - diff[i * d + k];
            }
        }
        pow *= 2.0;
        let top = diff[..d].iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if top > rel_tol * pow * scale {
            degree = j;
        }
    }
    Ok(degree)
}

/// If `curve` is (up to [`DEFAULT_REL_TOL`]) an elevated lower-degree curve, returns that
/// lower-degree curve; otherwise a copy of `curve` (report with bound `0`).
///
/// The reduction uses whichever reproducing operator amplifies rounding least
/// ([`Method::GeneralizedInverse`] or stepwise [`Method::Forrest`], compared by
/// [`crate::Operator::norm_inf`]); both reproduce exactly elevated curves exactly in exact
/// arithmetic. The report carries the certified bound as usual.
///
/// # Errors
/// As [`reduce`] (in practice none for a valid curve).
pub fn reduce_exact(curve: &BezierCurve) -> Result<Reduction> {
    let n = curve.degree();
    let k = exact_degree(curve, DEFAULT_REL_TOL)?;
    if k >= n {
        return Ok(Reduction {
            curve: curve.clone(),
            report: super::reduce::Report {
                method: Method::GeneralizedInverse,
                degree_from: n,
                degree_to: n,
                error_bound: Some(0.0),
                bound_level: crate::BoundLevel::Tight,
                max_error: None,
                space: crate::ErrorSpace::Euclidean,
                homogeneous_bound: curve.weights().map(|_| 0.0),
            },
        });
    }
    let a = operator(Method::GeneralizedInverse, n, k)?;
    let b = operator(Method::Forrest, n, k)?;
    let method = if a.norm_inf() <= b.norm_inf() {
        a.method()
    } else {
        b.method()
    };
    reduce(curve, k, method)
}
