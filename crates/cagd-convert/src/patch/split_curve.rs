//! Generalized subdivision of a rectangular patch along a degree-`k` polynomial curve
//! `u = f(v) = sum_l B^k_l(v) a_l` (SPEC-convert §15.7, Theorem 15.7.1 with the erratum
//! `r + α = j`, by the recommended corner-cutting algorithm: no multinomial enumeration).

use cagd_core::{Error, Result};

use super::ruled::ruled_subpatch;
use super::{PatchPiece, TensorSurface};

/// Region D5 `{0 <= u <= f(v)}` as an `m x (k m + n)` patch with the map (15.7.2)
/// `u = s f(t)`, `v = t`. `a` are the Bernstein coefficients of `f` (degree `k = a.len()-1`).
///
/// # Errors
/// [`Error::BadParameter`] when `f` leaves `[0, 1]` (precondition of §15.7) or a
/// coefficient is not finite; [`Error::NotEnoughPoints`] when `a` is empty.
pub fn curve_split_d5(p: &TensorSurface, a: &[f64]) -> Result<PatchPiece> {
    ruled_subpatch(p, &[0.0], a, 0.0, 1.0, false)
}

/// Region D7, the curved triangle `u = s f(t)`, `v = b t` (SPEC-convert §15.7, eqs.
/// 15.7.6–15.7.10; `a_k = 0` when the curve meets `u = 0` at `v = b`): the rows of `P` are
/// first restricted to `v in [0, b]`, then cut as for D5. Output `m x (k m + n)`.
///
/// # Errors
/// As [`curve_split_d5`], and [`Error::BadParameter`] unless `0 < b <= 1`.
pub fn curve_split_d7(p: &TensorSurface, a: &[f64], b: f64) -> Result<PatchPiece> {
    if !(b.is_finite() && b > 0.0 && b <= 1.0) {
        return Err(Error::BadParameter {
            name: "b",
            value: b,
            why: "the curved triangle D7 needs 0 < b <= 1",
        });
    }
    ruled_subpatch(p, &[0.0], a, 0.0, b, false)
}

/// Both sides of the curve `u = f(v)` (Bernstein coefficients `a`): D5 `{u <= f(v)}` as
/// `u = s f(t)`, and its complement `{u >= f(v)}` as `u = f(t) + s (1 - f(t))`, each an
/// `m x (k m + n)` patch with a ruled domain. Together they tile the unit square (the
/// curve is their common boundary).
/// (SPEC-convert §15.7, Theorem 15.7.1 by the recommended corner-cutting algorithm.)
///
/// # Errors
/// As [`curve_split_d5`].
pub fn split_along_curve(p: &TensorSurface, a: &[f64]) -> Result<Vec<PatchPiece>> {
    Ok(vec![
        ruled_subpatch(p, &[0.0], a, 0.0, 1.0, false)?,
        ruled_subpatch(p, a, &[1.0], 0.0, 1.0, false)?,
    ])
}
