//! Measured error between two curves with the same parametrisation.

use cagd_core::{BezierCurve, Result};

/// `max_t ||p(t) - q(t)||` (Euclidean; rational curves are compared in Euclidean space): the
/// parametric distance of cagd-core ([`cagd_core::curve_distance`]: dense sampling plus
/// Brent refinement of every local maximum; for polynomial curves the difference curve is
/// formed first, so the result is accurate relative to the error itself).
///
/// Being a maximum over evaluated points it never exceeds the true maximum by more than
/// the evaluation rounding, so a certified bound must be at least this value.
///
/// # Errors
/// [`cagd_core::Error::LengthMismatch`] when the dimensions differ.
pub fn max_deviation(p: &BezierCurve, q: &BezierCurve) -> Result<f64> {
    cagd_core::curve_distance(p, q)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_of_a_line_to_a_parabola() {
        // p(t) = 2t(1-t) (degree 2, points 0, 1, 0), q = 0: max 1/2 at t = 1/2.
        let p = BezierCurve::new(vec![0.0, 1.0, 0.0], 1).unwrap();
        let q = BezierCurve::new(vec![0.0, 0.0], 1).unwrap();
        assert!((max_deviation(&p, &q).unwrap() - 0.5).abs() < 1e-15);
        let q2 = BezierCurve::new(vec![0.0, 0.0, 0.0, 0.0], 2).unwrap();
        assert!(max_deviation(&p, &q2).is_err());
    }
}
