//! Knot vectors of B-spline / NURBS curves and surfaces (DESIGN.md: a full, clamped or
//! unclamped, non-decreasing vector of `n_points + degree + 1` knots).
//!
//! With degree `p`, `n` control points and knots `u_0 <= ... <= u_{n+p}`, the curve is
//! defined on the domain `[u_p, u_n]`, which is the union of the spans `[u_s, u_{s+1})`,
//! `s = p..n-1`; a span with `u_s == u_{s+1}` is empty.

use crate::binomial::check_degree;
use crate::{Error, Result};

/// The largest knot magnitude accepted (`1e300`). Beyond it a domain such as
/// `[267, 1.8e308]` is finite but its parameter arithmetic is not (a sampling parameter
/// `a + s (b - a)`, a sum of two knots, overflows), and a measured error or a bound
/// computed on it would be meaningless; the C ABI fuzz harness found one such case.
pub const MAX_KNOT: f64 = 1e300;

/// Checks a knot vector for `n_points` control points of degree `degree` and returns the
/// domain `(u_p, u_n)`.
///
/// Checked in this order: the degree (`<= MAX_DEGREE`), `n_points >= degree + 1`, the
/// knot count `n_points + degree + 1`, finiteness and magnitude (`|u_i| <= MAX_KNOT`),
/// monotonicity, multiplicities `<= degree + 1`, and a domain of positive length.
///
/// # Errors
/// [`Error::DegreeOutOfRange`], [`Error::NotEnoughPoints`], [`Error::KnotCount`],
/// [`Error::NonFiniteKnot`], [`Error::KnotsNotNondecreasing`] (first decreasing index),
/// [`Error::MultiplicityAboveDegree`], and [`Error::BadParameter`] (name `"knots"`) when
/// `u_p == u_n` (an empty domain) or a knot exceeds [`MAX_KNOT`] in magnitude.
///
/// ```
/// # use cagd_core::check_knots;
/// assert_eq!(check_knots(&[0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], 4, 2)?, (0.0, 1.0));
/// assert!(check_knots(&[0.0, 0.0, 1.0, 0.5, 1.0, 1.0, 1.0], 4, 2).is_err());
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn check_knots(knots: &[f64], n_points: usize, degree: usize) -> Result<(f64, f64)> {
    check_degree(degree)?;
    if n_points < degree + 1 {
        return Err(Error::NotEnoughPoints {
            got: n_points,
            need: degree + 1,
        });
    }
    let expected = n_points + degree + 1;
    if knots.len() != expected {
        return Err(Error::KnotCount {
            got: knots.len(),
            expected,
        });
    }
    if let Some(index) = knots.iter().position(|k| !k.is_finite()) {
        return Err(Error::NonFiniteKnot {
            index,
            value: knots[index],
        });
    }
    if let Some(index) = knots.iter().position(|k| k.abs() > MAX_KNOT) {
        return Err(Error::BadParameter {
            name: "knots",
            value: knots[index],
            why: "knot values must lie within +-1e300 (sums, differences and quotients of \
                  parameters must stay finite and resolvable)",
        });
    }
    if let Some(i) = knots.windows(2).position(|w| w[1] < w[0]) {
        return Err(Error::KnotsNotNondecreasing { index: i + 1 });
    }
    let mut start = 0;
    while start < knots.len() {
        let mult = multiplicity_from(knots, start);
        if mult > degree + 1 {
            return Err(Error::MultiplicityAboveDegree {
                knot: knots[start],
                mult,
                degree,
            });
        }
        start += mult;
    }
    let (a, b) = (knots[degree], knots[n_points]);
    if a >= b {
        return Err(Error::BadParameter {
            name: "knots",
            value: a,
            why: "the domain [knots[degree], knots[n_points]] must have positive length",
        });
    }
    Ok((a, b))
}

/// Number of knots equal to `knots[start]` from `start` on (the vector is sorted).
fn multiplicity_from(knots: &[f64], start: usize) -> usize {
    knots[start..]
        .iter()
        .take_while(|k| **k == knots[start])
        .count()
}

/// The multiplicity of `value` in the sorted knot vector (`0` when it is not a knot, or
/// `value` is NaN). Binary search, `O(log n)`.
pub fn knot_multiplicity(knots: &[f64], value: f64) -> usize {
    let lo = knots.partition_point(|k| *k < value);
    let hi = knots.partition_point(|k| *k <= value);
    hi.saturating_sub(lo)
}

/// The span index `s` in `degree..n_points` with `u_s <= t < u_{s+1}` and `u_s < u_{s+1}`
/// for a valid knot vector (see [`check_knots`]).
///
/// Robust at the ends: for `t >= u_n` the last non-empty span is returned (so that the
/// right end of the domain evaluates as a limit from the left, and larger `t` extrapolate
/// the last piece), for `t < u_p` the first non-empty span (extrapolation to the left).
/// Binary search, `O(log n)`. A NaN `t` gives the first span; callers reject it first.
pub fn find_span(knots: &[f64], degree: usize, n_points: usize, t: f64) -> usize {
    let inner = &knots[degree..n_points];
    let (lo, hi) = (knots[degree], knots[n_points]);
    let count = if t >= hi {
        inner.partition_point(|k| *k < hi)
    } else if t < lo {
        inner.partition_point(|k| *k <= lo)
    } else {
        inner.partition_point(|k| *k <= t)
    };
    // count >= 1 because inner[0] = lo <= t (or the clamped key) and lo < hi.
    degree + count.max(1) - 1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn knots_beyond_the_resolvable_range_are_refused() {
        // The C ABI fuzz harness's case: domain [267, 1.8e308], finite but not computable
        // (a reduction reported a bound of 9e-13 beside a measured error of 3e-7).
        let mut k = vec![266.98315011236474; 6];
        k.push(8.988_465_674_311_578e307);
        k.extend([f64::MAX; 6]);
        let e = check_knots(&k, 7, 5).unwrap_err();
        assert!(
            matches!(e, Error::BadParameter { name: "knots", .. }),
            "{e}"
        );
        // The same vector on a domain of 1e300 is accepted.
        let k: Vec<f64> = [0.0; 6]
            .into_iter()
            .chain([0.5e300])
            .chain([1e300; 6])
            .collect();
        assert_eq!(check_knots(&k, 7, 5).unwrap(), (0.0, 1e300));
        let neg: Vec<f64> = k.iter().map(|x| -x).rev().collect();
        assert!(check_knots(&neg, 7, 5).is_ok());
        let mut far = neg;
        far[0] = -1.0001e300;
        assert!(check_knots(&far, 7, 5).is_err());
    }

    #[test]
    fn each_error_variant() {
        let good = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
        assert_eq!(check_knots(&good, 4, 2), Ok((0.0, 1.0)));
        assert!(matches!(
            check_knots(&good, 4, 65),
            Err(Error::DegreeOutOfRange { degree: 65, .. })
        ));
        assert!(matches!(
            check_knots(&good, 2, 2),
            Err(Error::NotEnoughPoints { got: 2, need: 3 })
        ));
        assert!(matches!(
            check_knots(&good[1..], 4, 2),
            Err(Error::KnotCount {
                got: 6,
                expected: 7
            })
        ));
        let mut nan = good;
        nan[3] = f64::NAN;
        assert!(matches!(
            check_knots(&nan, 4, 2),
            Err(Error::NonFiniteKnot { index: 3, .. })
        ));
        let dec = [0.0, 0.0, 0.0, 0.5, 0.4, 1.0, 1.0];
        assert_eq!(
            check_knots(&dec, 4, 2),
            Err(Error::KnotsNotNondecreasing { index: 4 })
        );
        let high = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        assert!(matches!(
            check_knots(&high, 4, 2),
            Err(Error::MultiplicityAboveDegree {
                mult: 4,
                degree: 2,
                ..
            })
        ));
        let bezier = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        // Unclamped with an empty domain: u_1 = u_2 = 0.5.
        let flat = [0.0, 0.5, 0.5, 0.5, 1.0, 2.0];
        assert!(check_knots(&bezier, 3, 2).is_ok());
        assert!(matches!(
            check_knots(&flat, 3, 2),
            Err(Error::BadParameter { name: "knots", .. })
        ));
    }

    #[test]
    fn spans() {
        let k = [0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0];
        // n = 5, p = 2: spans 2 = [0, 0.5), 3 empty, 4 = [0.5, 1).
        assert_eq!(find_span(&k, 2, 5, 0.0), 2);
        assert_eq!(find_span(&k, 2, 5, 0.49), 2);
        assert_eq!(find_span(&k, 2, 5, 0.5), 4);
        assert_eq!(find_span(&k, 2, 5, 1.0), 4);
        assert_eq!(find_span(&k, 2, 5, 7.0), 4);
        assert_eq!(find_span(&k, 2, 5, -1.0), 2);
        assert_eq!(knot_multiplicity(&k, 0.5), 2);
        // Unclamped with an empty first span: u_2 = u_3 = 1.
        let u = [0.0, 0.5, 1.0, 1.0, 2.0, 3.0, 4.0];
        assert_eq!(find_span(&u, 2, 4, -5.0), 3);
        assert_eq!(find_span(&u, 2, 4, 1.0), 3);
        assert_eq!(find_span(&u, 2, 4, 2.0), 3);
        assert_eq!(find_span(&u, 2, 4, 9.0), 3);
    }
}
