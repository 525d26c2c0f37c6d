//! The uniform reduction of a curve whose coordinates lie outside `[2^-450, 2^450]` (e.g.
//! near `1e300`, where the certified bounds' squares overflow) in a frame scaled by a
//! power of two (ADDED, beyond seed 001): the control points are multiplied by `2^-e`, `e`
//! the binary exponent of their largest magnitude (the factors of the Bézier bound's
//! scaled route, `bezier::bound`), the curve is reduced there, and the result and its
//! bounds are multiplied back by `2^e`.
//!
//! **Why the bounds stay true.** Multiplying by a power of two is exact unless the product
//! is subnormal, where it is off by less than `2^-1074` per coordinate. A B-spline or NURBS
//! curve is a convex combination of its control points (positive weights), so moving each
//! point by at most `d` (Euclidean) moves the curve by at most `d`. With `C` the input,
//! `C_s` the curve of the scaled points, `C'_s` the reduction in the scaled frame (bound
//! `b_s`) and `C'` the result moved back, `||C - C'||` is at most `||C - 2^e C_s|| +
//! 2^e ||C_s - C'_s|| + ||2^e C'_s - C'|| <= 2^e (b_s + a) + a` with `a = dim 2^-1074`
//! (each rounding at most half an ulp of the subnormals, `sqrt(dim) <= dim`); only one of
//! the two roundings can happen (scaling down, the input's small coordinates; scaling up,
//! the result's). The sums are rounded upwards ([`next_up`]), and a bound that overflows in
//! model units is the only refusal.

use cagd_core::{BSplineCurve, BezierCurve, Error, Result};

use super::UniformReduction;
use crate::bezier::pow2_factors;

/// `reduce` applied to `curve` scaled by the power of two of its largest coordinate
/// magnitude `amax`, the result moved back (module docs).
///
/// # Errors
/// Those of `reduce`, and [`Error::BadParameter`] (`"points"`) when a bound or a point of
/// the result overflows in model units.
pub(super) fn reduce_scaled(
    curve: &BSplineCurve,
    amax: f64,
    reduce: impl Fn(&BSplineCurve) -> Result<UniformReduction>,
) -> Result<UniformReduction> {
    let (s1, s2) = pow2_factors(amax);
    let down = |x: &[f64]| -> Vec<f64> { x.iter().map(|v| v * s1 * s2).collect() };
    let up = |x: &[f64]| -> Vec<f64> { x.iter().map(|v| v / s1 / s2).collect() };
    let dim = curve.dim();
    let scaled = match curve.weights() {
        Some(w) => BSplineCurve::new_rational(
            curve.degree(),
            curve.knots().to_vec(),
            down(curve.points()),
            w.to_vec(),
            dim,
        )?,
        None => BSplineCurve::new(
            curve.degree(),
            curve.knots().to_vec(),
            down(curve.points()),
            dim,
        )?,
    };
    let red = reduce(&scaled)?;
    #[allow(clippy::cast_precision_loss, reason = "dim is small")]
    let a = dim as f64 * f64::from_bits(1);
    let model_bound = |b: f64| next_up(next_up(b + a) / s1 / s2 + a);
    let (segment_bound, error_bound) =
        (model_bound(red.segment_bound), model_bound(red.error_bound));
    let c = &red.curve;
    let pts = up(c.points());
    if !segment_bound.is_finite() || !error_bound.is_finite() {
        return Err(too_large(curve, "the certified error bound overflows"));
    }
    if pts.iter().any(|x| !x.is_finite()) {
        return Err(too_large(curve, "the reduced control points overflow"));
    }
    let merged = match c.weights() {
        Some(w) => {
            BSplineCurve::new_rational(c.degree(), c.knots().to_vec(), pts, w.to_vec(), dim)?
        }
        None => BSplineCurve::new(c.degree(), c.knots().to_vec(), pts, dim)?,
    };
    let segments = red
        .segments
        .iter()
        .map(|s| {
            let p = up(s.points());
            if p.iter().any(|x| !x.is_finite()) {
                return Err(too_large(curve, "the reduced segments overflow"));
            }
            match s.weights() {
                Some(w) => BezierCurve::new_rational(p, w.to_vec(), s.dim()),
                None => BezierCurve::new(p, s.dim()),
            }
        })
        .collect::<Result<_>>()?;
    Ok(UniformReduction {
        curve: merged,
        segments,
        segment_bound,
        error_bound,
    })
}

/// The next double above `x >= 0` (`f64::next_up`, stable only from Rust 1.86, above the
/// workspace's MSRV); `x` itself when it is infinite or NaN.
fn next_up(x: f64) -> f64 {
    if x.is_finite() && x >= 0.0 {
        // +0 and -0 both go to the smallest subnormal.
        f64::from_bits(x.abs().to_bits() + 1)
    } else {
        x
    }
}

/// The refusal of a curve whose result overflows in model units (coordinates near the
/// largest double).
pub(super) fn too_large(curve: &BSplineCurve, why: &'static str) -> Error {
    Error::BadParameter {
        name: "points",
        value: curve.points().iter().fold(0.0f64, |m, x| m.max(x.abs())),
        why,
    }
}
