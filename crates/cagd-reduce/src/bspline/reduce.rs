//! Degree reduction of general B-spline and NURBS curves (non-uniform, clamped or not,
//! rational) to a tolerance, keeping the continuity the input has at its knots: the entry
//! point [`reduce_bspline`], which dispatches to the strategies (`global.rs`, default;
//! `segments.rs`; `piegl_tiller/`); the options and reports are in `options.rs`.

use cagd_core::{BSplineCurve, Error, Result, check_tolerance};

use super::framed::reduce_curve_framed_capped;
use super::options::{BSplineOptions, BSplineReduction, BSplineStrategy};
use crate::Method;

/// Reduces a B-spline or NURBS curve of degree `p` to degree `m` within a tolerance,
/// keeping continuity `C^min(k, m - 1)` at every knot where the input is `C^k`, with as
/// few knots as the tolerance allows (the job of Piegl & Tiller 1995, "Algorithm for degree
/// reduction of B-spline curves", done by a global fit).
///
/// [`BSplineStrategy::GlobalFit`] (default):
/// 1. **Knots**: the input's breaks with multiplicity `m - min(k, p - s, m - 1)`, so the
///    degree-`m` space has exactly the continuity to keep, plus knots predicted by an
///    error model (`fit/predict.rs`) inside the pieces; or, where the model predicts
///    fewer spans that way, only the breaks of multiplicity above one (the input less
///    smooth than `C^(m-1)`) plus knots predicted across the pieces, so that spans
///    straddle the other breaks (the fit is `C^(m-1)` there, which is all the input's
///    continuity a degree-`m` spline can keep).
/// 2. **Fit**: the spline of that space nearest to the input in the parameter L2 norm with
///    the end points kept (exact Gauss–Legendre quadrature per span and input piece,
///    banded Givens QR; NURBS in homogeneous coordinates).
/// 3. **Certify and refine**: every span gets a certified bound (input piece minus fit, its
///    values at Chebyshev–Lobatto nodes times the Ehlich–Zeller factor, at most 1.075× the
///    error; the refined convex hull where that is above the share, and for NURBS); spans
///    above their share of the tolerance are split
///    (`ceil((bound / budget)^(1/(m+1)))` parts, simple knots) and the fit is repeated.
/// 4. **Knot removal** (Tiller's certified removal, Piegl & Tiller's local bookkeeping):
///    greedy passes remove knot copies while every span a removal touches keeps its
///    accumulated bound within the tolerance.
///
/// [`BSplineStrategy::Segments`]: per-segment Hermite reductions, merge, knot removal
/// — continuity at most `C^floor((m-1)/2)`.
///
/// The result has the input's domain, is clamped there and rational if the input is. With
/// an input that is a degree-elevated degree-`m` spline it recovers the original knots.
///
/// Supported range: input degrees up to [`cagd_core::MAX_DEGREE`] (64; tested at 40 -> 8
/// and 64 -> 20), any target `1..p`, up to 2^20 spans after refinement. The fit is a
/// backward-stable QR solve of a B-spline collocation system (condition number bounded
/// in terms of `m` and the span-length ratio, not squared); its accuracy does not enter
/// the certified bound, which is computed on the fitted points as they are (rounding of
/// the bound's own arithmetic included).
///
/// # Errors
/// [`Error::BadDegreePair`] (`m == 0` or `m >= p`); [`Error::BadTolerance`];
/// [`Error::BadParameter`] (a segment method other than the two above; an interior knot
/// of multiplicity `p + 1`); [`Error::TooManyConstraints`] (`continuity` above the
/// strategy's maximum); [`Error::ConditionNotMet`] when a span cannot meet the tolerance
/// (e.g. a tolerance below the rounding level of the curve).
///
/// ```
/// use cagd_core::BSplineCurve;
/// use cagd_reduce::{BSplineOptions, reduce_bspline};
/// let knots = vec![0.0, 0.0, 0.0, 0.0, 0.0, 0.3, 0.6, 1.0, 1.0, 1.0, 1.0, 1.0];
/// let pts = vec![0.0, 0.0, 1.0, 2.0, 2.0, -1.0, 3.0, 2.0, 4.0, 0.0, 5.0, 1.0, 6.0, 0.0];
/// let c = BSplineCurve::new(4, knots, pts, 2)?;
/// let opts = BSplineOptions { measure: true, ..BSplineOptions::new(3, 1e-3) };
/// let r = reduce_bspline(&c, &opts)?;
/// assert_eq!(r.curve.degree(), 3);
/// let measured = r.report.max_error.unwrap();
/// assert!(measured <= r.report.error_bound && r.report.error_bound <= 1e-3);
/// // The input is C^3 at its knots: the cubic keeps C^2 wherever a knot is left.
/// assert!(r.report.continuity.iter().all(|&(_, k)| k == 2));
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn reduce_bspline(curve: &BSplineCurve, opts: &BSplineOptions) -> Result<BSplineReduction> {
    let (p, m) = (curve.degree(), opts.target);
    check_tolerance(opts.tolerance)?;
    if m == 0 || m >= p {
        return Err(Error::BadDegreePair {
            from: p,
            to: m,
            why: "B-spline reduction needs 1 <= m < p",
        });
    }
    let (kmax, why) = match opts.strategy {
        BSplineStrategy::GlobalFit | BSplineStrategy::PieglTiller1995 => {
            (m - 1, "a degree-m spline is at most C^(m-1)")
        }
        BSplineStrategy::Segments(_) => (
            (m - 1) / 2,
            "per-segment Hermite constraints keep at most C^floor((m-1)/2)",
        ),
    };
    let k = opts.continuity.unwrap_or(kmax);
    if k > kmax {
        return Err(Error::TooManyConstraints {
            r: i64::try_from(k).unwrap_or(i64::MAX),
            p: i64::try_from(k).unwrap_or(i64::MAX),
            m,
            why,
        });
    }
    let opts = BSplineOptions {
        continuity: Some(k),
        ..*opts
    };
    match opts.strategy {
        BSplineStrategy::GlobalFit => reduce_global_framed(curve, &opts),
        BSplineStrategy::PieglTiller1995 => {
            crate::reduce_bspline_piegl_tiller(curve, m, opts.tolerance, opts.measure)
        }
        BSplineStrategy::Segments(method) => {
            if !matches!(
                method,
                Method::ConstrainedChebyshev { .. } | Method::L2 { .. }
            ) {
                return Err(Error::BadParameter {
                    name: "method",
                    value: 0.0,
                    why: "segment reduction needs ConstrainedChebyshev or L2 (end orders set per knot)",
                });
            }
            super::segments::reduce_segments(curve, &opts, method)
        }
    }
}

/// The global fit ([`super::global::reduce_global`]) of a NURBS curve in its frame
/// (`super::framed`: control points centred on their bounding box and scaled by its radius,
/// weights unchanged), moved back; a polynomial curve as it is (its fit commutes with
/// translation and scaling).
///
/// Why (ADDED, issue 17's real-CAD-file row): the span bound of a NURBS fit
/// (`fit/rational_span.rs`) charges the rounding of restricting and extracting the
/// homogeneous points, which is relative to their size: far from the origin (CAD parts
/// placed in an assembly) that allowance grows with the distance, so the same shape moved
/// would get a different bound. In the frame the points are of size one and the bound is
/// the framed one times `s` plus the round trip's rounding
/// ([`super::framed::Frame::finish`]), as for the other strategies; the measured error is
/// taken against the input itself. (Spans: the same as unframed on the `cad_curves`
/// bench.)
fn reduce_global_framed(curve: &BSplineCurve, opts: &BSplineOptions) -> Result<BSplineReduction> {
    reduce_curve_framed_capped(curve, opts, super::global::reduce_global)
}
