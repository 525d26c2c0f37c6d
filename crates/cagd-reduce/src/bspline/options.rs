//! The options and the result of [`reduce_bspline`](crate::reduce_bspline): the strategy,
//! the options, the report and the reduction. Shared by the entry point (`reduce.rs`) and
//! the strategies, which it dispatches to, so that neither imports the other back.

use cagd_core::BSplineCurve;

use crate::Method;

/// How [`reduce_bspline`](crate::reduce_bspline) builds the degree-`m` spline before knot
/// removal.
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

/// Options of [`reduce_bspline`](crate::reduce_bspline).
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

/// What [`reduce_bspline`](crate::reduce_bspline) did.
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
