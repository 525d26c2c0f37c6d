//! Measured (sampled) error between two B-spline / NURBS curves on a common parameter, and
//! the small helpers the B-spline reducers share.

use cagd_core::{BSplineCurve, BezierSegment, Error, Result, max_distance_1d};

/// `max_t ||a(t) - b(t)||` (Euclidean; rational curves compared in model space) over the
/// common domain, measured per polynomial piece: the domain is cut at the union of both
/// curves' knots and [`max_distance_1d`] samples every piece densely (`8 (p_a + p_b) + 64`
/// intervals) and refines the sampled maxima by Brent's method (SPEC-reduce §0 "sampled").
///
/// # Errors
/// [`Error::LengthMismatch`] (different dimensions), [`Error::BadParameter`] (domains
/// differ by more than `1e-12` relative), [`Error::NonFinite`] from the sampling.
///
/// ```
/// use cagd_core::BSplineCurve;
/// let a = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], vec![0.0, 1.0], 1)?;
/// let b = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], vec![0.0, 1.5], 1)?;
/// assert!((cagd_reduce::spline_max_deviation(&a, &b)? - 0.5).abs() < 1e-15);
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn spline_max_deviation(a: &BSplineCurve, b: &BSplineCurve) -> Result<f64> {
    if a.dim() != b.dim() {
        return Err(Error::LengthMismatch {
            what: "curve dimensions",
            got: b.dim(),
            expected: a.dim(),
        });
    }
    let ((a0, a1), (b0, b1)) = (a.domain(), b.domain());
    let scale = 1e-12 * (a1 - a0).max(a0.abs()).max(a1.abs());
    if (a0 - b0).abs() > scale || (a1 - b1).abs() > scale {
        return Err(Error::BadParameter {
            name: "domain",
            value: b0,
            why: "the two curves must have the same parameter domain",
        });
    }
    let (sa, sb) = (a.to_beziers()?, b.to_beziers()?);
    let samples = 8 * (a.degree() + b.degree()) + 64;
    let (mut i, mut j, mut best) = (0, 0, 0.0f64);
    while i < sa.len() && j < sb.len() {
        let lo = sa[i].start.max(sb[j].start);
        let hi = sa[i].end.min(sb[j].end);
        if hi > lo {
            let (pa, pb) = (&sa[i], &sb[j]);
            let d = max_distance_1d(
                |t, o| eval_piece(pa, t, o),
                |t, o| eval_piece(pb, t, o),
                a.dim(),
                lo,
                hi,
                samples,
            )?;
            best = best.max(d);
        }
        if sa[i].end <= sb[j].end {
            i += 1;
        } else {
            j += 1;
        }
    }
    Ok(best)
}

/// Evaluates a piece at the global parameter `t` (clamped to its interval).
fn eval_piece(piece: &BezierSegment, t: f64, out: &mut [f64]) {
    let s = ((t - piece.start) / (piece.end - piece.start)).clamp(0.0, 1.0);
    piece.curve.eval_into(s, out);
}

/// The Euclidean bound of a rational result from a homogeneous one (the argument of
/// [`crate::reduce_with`]): `eps_h (1 + max_i ||P_i||) / v_min`, `v_min = max(min v,
/// min w - eps_h)`, with a few ulp of slack. Returns infinity when `v_min <= 0`.
pub(crate) fn euclidean_from_homogeneous(eps_h: f64, pmax: f64, wmin: f64, vmin: f64) -> f64 {
    let v = vmin.max(wmin - eps_h);
    if v <= 0.0 {
        return f64::INFINITY;
    }
    eps_h * (1.0 + pmax) / v * (1.0 + 8.0 * f64::EPSILON)
}
