//! Degree reduction of general B-spline and NURBS curves (non-uniform, clamped or not,
//! rational) to a tolerance, keeping the continuity the input has at its knots: options,
//! report and the entry point [`reduce_bspline`]; the strategies live in
//! [`crate::bspline_global`] (default) and [`crate::bspline_segments`].

use cagd_core::{BSplineCurve, Error, Result, check_tolerance, knot_multiplicity};

use crate::Method;

/// How [`reduce_bspline`] builds the degree-`m` spline before knot removal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BSplineStrategy {
    /// One least-squares fit on the whole degree-`m` spline space whose knots are the
    /// input's (multiplicity `m - min(k, m - 1)` where the input is `C^k`) plus the knots
    /// the adaptive refinement adds, with the end points kept; keeps up to `C^(m-1)`. The
    /// default.
    GlobalFit,
    /// Every Bézier segment reduced on its own by the given method
    /// ([`Method::ConstrainedChebyshev`] or [`Method::L2`]; their `r, p` are set per end)
    /// with Hermite end data; keeps up to `C^floor((m-1)/2)` (two-sided Hermite data need
    /// `2k + 1 <= m`).
    Segments(Method),
    /// The classical algorithm of Piegl & Tiller 1995 ([`crate::reduce_bspline_piegl_tiller`]):
    /// one degree at a time, every knot keeps its multiplicity minus one per degree, never
    /// subdivides, fails when that is not within the tolerance. Kept as the reference to
    /// compare with; `continuity` is ignored (the input's is kept where a knot stays).
    PieglTiller1995,
}

/// Options of [`reduce_bspline`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BSplineOptions {
    /// The target degree `m` (`1 <= m < p`).
    pub target: usize,
    /// The tolerance: the certified bound of the result, `max_t ||C(t) - C'(t)||`
    /// (Euclidean, model space), must not exceed it.
    pub tolerance: f64,
    /// The continuity `k` to keep at the input's knots (where the input has it); `None`
    /// means the most the strategy can keep: `m - 1` for [`BSplineStrategy::GlobalFit`],
    /// `floor((m - 1) / 2)` for [`BSplineStrategy::Segments`].
    pub continuity: Option<usize>,
    /// The strategy.
    pub strategy: BSplineStrategy,
    /// Also measure the error by dense sampling (see [`crate::spline_max_deviation`]).
    pub measure: bool,
}

impl BSplineOptions {
    /// Options for target degree `target` and `tolerance`: global fit, the most continuity,
    /// no measuring.
    pub fn new(target: usize, tolerance: f64) -> Self {
        Self {
            target,
            tolerance,
            continuity: None,
            strategy: BSplineStrategy::GlobalFit,
            measure: false,
        }
    }
}

/// What [`reduce_bspline`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineReport {
    /// The strategy used.
    pub strategy: BSplineStrategy,
    /// Source degree.
    pub degree_from: usize,
    /// Target degree.
    pub degree_to: usize,
    /// The tolerance asked for.
    pub tolerance: f64,
    /// Certified upper bound of `max_t ||C(t) - C'(t)||` (Euclidean, model space,
    /// `<= tolerance`): the maximum over spans of (the bound of the fitted or reduced piece
    /// + the bounds of every knot removal whose support covers the span).
    pub error_bound: f64,
    /// The largest certified bound of a span before knot removal.
    pub segment_bound: f64,
    /// The sampled error (on request).
    pub max_error: Option<f64>,
    /// Number of spans before knot removal (after the adaptive refinement).
    pub pieces: usize,
    /// The continuity order guaranteed at each interior knot of the input that is still a
    /// knot of the result: `(knot, k)` with `k = min(continuity, p - s, m - 1)` (`s` its
    /// input multiplicity). The result's structural continuity there, `m - multiplicity`,
    /// is at least `k` (knot removal may have raised it).
    pub continuity: Vec<(f64, usize)>,
}

/// The reduced spline with its report and span counts.
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineReduction {
    /// The degree-`m` spline (clamped on the input's domain; rational if the input is).
    pub curve: BSplineCurve,
    /// What was done.
    pub report: BSplineReport,
    /// Non-empty knot spans of the input.
    pub spans_in: usize,
    /// Non-empty knot spans of the result.
    pub spans_out: usize,
}

/// The continuity order to keep at the interior knot `t` of `knots` (degree `p`):
/// `min(k, p - s)`, `s` its multiplicity.
///
/// # Errors
/// [`Error::BadParameter`] for a knot of multiplicity `p + 1` (the input may jump there).
pub(crate) fn order_at(knots: &[f64], p: usize, k: usize, t: f64) -> Result<usize> {
    let s = knot_multiplicity(knots, t);
    if s > p {
        return Err(Error::BadParameter {
            name: "knots",
            value: t,
            why: "interior knot of multiplicity p + 1 (possibly discontinuous)",
        });
    }
    Ok(k.min(p - s))
}

/// Reduces a B-spline or NURBS curve of degree `p` to degree `m` within a tolerance,
/// keeping continuity `C^min(k, m - 1)` at every knot where the input is `C^k`, with as
/// few knots as the tolerance allows (the job of Piegl & Tiller 1995, "Algorithm for degree
/// reduction of B-spline curves", done by a global fit).
///
/// [`BSplineStrategy::GlobalFit`] (default):
/// 1. **Knots**: the input's breaks with multiplicity `m - min(k, p - s, m - 1)`, so the
///    degree-`m` space has exactly the continuity to keep.
/// 2. **Fit**: the spline of that space nearest to the input in the parameter L2 norm with
///    the end points kept (exact Gauss–Legendre quadrature, banded Givens QR; NURBS in
///    homogeneous coordinates).
/// 3. **Certify and refine**: every span gets a certified bound (input piece minus fit,
///    refined convex hull); spans above their share of the tolerance are split
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
        BSplineStrategy::GlobalFit => super::global::reduce_global(curve, &opts),
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
