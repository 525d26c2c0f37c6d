//! Input validation shared by every constructor: flat point buffers, weights, tolerances.
//!
//! Constructors validate once, so algorithms receive valid objects and need no re-checks.

use crate::{Error, Result};

/// Whether every value is finite, in one pass that vectorises: `x * 0` is `0` for finite
/// `x` and NaN otherwise, summed in eight independent lanes (a `position(!is_finite)` or
/// one chain of additions does not vectorise). The batch kernels scan whole inputs and
/// outputs with it. Goes beyond the seeds (input validation).
pub fn all_finite(x: &[f64]) -> bool {
    let mut acc = [0.0f64; 8];
    let mut chunks = x.chunks_exact(8);
    for c in &mut chunks {
        for (a, v) in acc.iter_mut().zip(c) {
            *a += v * 0.0;
        }
    }
    for (a, v) in acc.iter_mut().zip(chunks.remainder()) {
        *a += v * 0.0;
    }
    acc.iter().all(|a| *a == 0.0)
}

/// Checks a flat row-major point buffer (`point i, coordinate k at i * dim + k`) and returns
/// the number of points.
///
/// # Errors
/// [`Error::ZeroDimension`], [`Error::NotEnoughPoints`] (empty buffer),
/// [`Error::LengthMismatch`] (length not a multiple of `dim`), [`Error::NonFinite`].
pub fn check_points(points: &[f64], dim: usize) -> Result<usize> {
    if dim == 0 {
        return Err(Error::ZeroDimension);
    }
    if points.is_empty() {
        return Err(Error::NotEnoughPoints { got: 0, need: 1 });
    }
    if points.len() % dim != 0 {
        return Err(Error::LengthMismatch {
            what: "points (length must be a multiple of dim)",
            got: points.len(),
            expected: (points.len() / dim + 1) * dim,
        });
    }
    if let Some(pos) = points.iter().position(|x| !x.is_finite()) {
        return Err(Error::NonFinite {
            index: pos / dim,
            coord: pos % dim,
            value: points[pos],
        });
    }
    Ok(points.len() / dim)
}

/// Checks that `weights` has `n_points` entries, each finite and at least `f64::MIN_POSITIVE`
/// (`2^-1022`): positive and not subnormal. A subnormal weight carries only a few
/// significant bits, and so does every homogeneous point `w P` made from it (a weight of
/// `1e-320` rounds `w P` to about 1 part in 2 000), so neither the evaluation nor any bound
/// computed in homogeneous coordinates would stand; a curve is unchanged by a common
/// factor of its weights, so such input can be rescaled by the caller. (ADDED: not in the
/// seeds; found by the C ABI fuzz run, a G1 reduction of a curve with weights `1e-320`.)
///
/// # Errors
/// [`Error::LengthMismatch`], [`Error::NonPositiveWeight`].
pub fn check_weights(weights: &[f64], n_points: usize) -> Result<()> {
    if weights.len() != n_points {
        return Err(Error::LengthMismatch {
            what: "weights",
            got: weights.len(),
            expected: n_points,
        });
    }
    if let Some(index) = weights
        .iter()
        .position(|w| !(w.is_finite() && *w >= f64::MIN_POSITIVE))
    {
        return Err(Error::NonPositiveWeight {
            index,
            weight: weights[index],
        });
    }
    Ok(())
}

/// Checks that a tolerance is finite and `> 0`.
///
/// # Errors
/// [`Error::BadTolerance`].
pub fn check_tolerance(tol: f64) -> Result<()> {
    if tol.is_finite() && tol > 0.0 {
        Ok(())
    } else {
        Err(Error::BadTolerance { value: tol })
    }
}

/// Checks that a parameter value is finite.
///
/// # Errors
/// [`Error::BadParameter`].
pub fn check_finite_param(name: &'static str, value: f64) -> Result<()> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(Error::BadParameter {
            name,
            value,
            why: "must be finite",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points() {
        assert_eq!(check_points(&[0.0, 1.0, 2.0, 3.0], 2), Ok(2));
        assert_eq!(check_points(&[0.0], 0), Err(Error::ZeroDimension));
        assert_eq!(
            check_points(&[], 2),
            Err(Error::NotEnoughPoints { got: 0, need: 1 })
        );
        assert!(matches!(
            check_points(&[0.0, 1.0, 2.0], 2),
            Err(Error::LengthMismatch { .. })
        ));
        assert!(matches!(
            check_points(&[0.0, 1.0, f64::NAN, 3.0], 2),
            Err(Error::NonFinite {
                index: 1,
                coord: 0,
                ..
            })
        ));
        assert!(matches!(
            check_points(&[0.0, f64::INFINITY], 2),
            Err(Error::NonFinite {
                index: 0,
                coord: 1,
                ..
            })
        ));
    }

    #[test]
    fn weights() {
        assert!(check_weights(&[1.0, 2.0], 2).is_ok());
        assert!(matches!(
            check_weights(&[1.0], 2),
            Err(Error::LengthMismatch { .. })
        ));
        assert!(matches!(
            check_weights(&[1.0, 0.0], 2),
            Err(Error::NonPositiveWeight { index: 1, .. })
        ));
        assert!(matches!(
            check_weights(&[-0.5, 1.0], 2),
            Err(Error::NonPositiveWeight { index: 0, .. })
        ));
        assert!(matches!(
            check_weights(&[1.0, 1e-320], 2),
            Err(Error::NonPositiveWeight { index: 1, .. })
        ));
        assert!(check_weights(&[1.0, f64::MIN_POSITIVE], 2).is_ok());
        assert!(matches!(
            check_weights(&[f64::NAN, 1.0], 2),
            Err(Error::NonPositiveWeight { index: 0, .. })
        ));
    }

    #[test]
    fn tolerance() {
        assert!(check_tolerance(1e-9).is_ok());
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(check_tolerance(bad).is_err());
        }
    }
}
