//! Degree reduction of general B-spline and NURBS curves (non-uniform, clamped or not,
//! rational) to a tolerance: Bézier extraction, per-segment reduction with end constraints
//! that keep the continuity at every knot, adaptive subdivision of segments over
//! their share of the tolerance, exact merge (seed 001 §4.1), then knot removal within the
//! rest of the tolerance, tracked locally per span (the idea of Piegl & Tiller 1995,
//! "Algorithm for degree reduction of B-spline curves").

use cagd_core::{BSplineCurve, BezierCurve, Error, Result, check_tolerance, knot_multiplicity};

use crate::bspline_measure::spline_max_deviation;
use crate::method::Method;
use crate::reduce::{ReduceOptions, reduce_with};

/// Share of the tolerance given to the per-segment reduction; the rest (per span: the
/// tolerance minus that span's reduction bound) is for knot removal. Measured on the
/// benchmark curve (1 000 degree-7 spans -> degree 3, tolerance 1e-6, midpoint splits):
/// 0.5 gave 6 514 output spans, 0.9 gave 4 063, and 4 035 with the proportional split
/// below (pieces that needed splitting rarely merge again; pieces that did not need it
/// keep almost the whole tolerance for knot removal anyway).
const SEGMENT_SHARE: f64 = 0.9;

/// Deepest recursive subdivision of one input span (2^40 pieces would be below rounding).
const MAX_DEPTH: usize = 40;

/// Options of [`reduce_bspline`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BSplineOptions {
    /// The target degree `m` (`1 <= m < p`).
    pub target: usize,
    /// The tolerance: the certified bound of the result, `max_t ||C(t) - C'(t)||`
    /// (Euclidean, model space), must not exceed it.
    pub tolerance: f64,
    /// The continuity `k` to keep at the input's knots (where the input has it); `None`
    /// means the most per-segment end constraints allow, `floor((m - 1) / 2)`.
    pub continuity: Option<usize>,
    /// The segment reducer: [`Method::ConstrainedChebyshev`] (default) or [`Method::L2`];
    /// its `r, p` are ignored and set per segment end from the continuity needed there.
    pub method: Method,
    /// Also measure the error by dense sampling (see [`crate::spline_max_deviation`]).
    pub measure: bool,
}

impl BSplineOptions {
    /// Options for target degree `target` and `tolerance`, constrained Chebyshev segments,
    /// the default continuity, no measuring.
    pub fn new(target: usize, tolerance: f64) -> Self {
        Self {
            target,
            tolerance,
            continuity: None,
            method: Method::ConstrainedChebyshev { r: 0, p: 0 },
            measure: false,
        }
    }
}

/// What [`reduce_bspline`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineReport {
    /// The segment method (its `r, p` as given; they are set per segment end).
    pub method: Method,
    /// Source degree.
    pub degree_from: usize,
    /// Target degree.
    pub degree_to: usize,
    /// The tolerance asked for.
    pub tolerance: f64,
    /// Certified upper bound of `max_t ||C(t) - C'(t)||` (Euclidean, model space,
    /// `<= tolerance`): the maximum over spans of (reduction bound of the piece + merge
    /// allowance + the bounds of every knot removal whose support covers the span).
    pub error_bound: f64,
    /// The largest certified bound of a reduced piece (before knot removal).
    pub segment_bound: f64,
    /// The sampled error (on request).
    pub max_error: Option<f64>,
    /// Number of pieces after the adaptive subdivision (before knot removal).
    pub pieces: usize,
    /// The continuity order guaranteed at each interior knot of the input that is still a
    /// knot of the result: `(knot, k)` with `k = min(continuity, p - s)` (`s` its input
    /// multiplicity). The result's structural continuity there, `m - multiplicity`, is at
    /// least `k` (knot removal may have raised it).
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

/// One reduced piece on `[a, b]` with its certified bound.
struct Piece {
    /// The continuity order kept at the start of the piece.
    order: i32,
    a: f64,
    b: f64,
    curve: BezierCurve,
    bound: f64,
}

/// Reduces `bez` (the input on `[a, b]`) with end orders `(r, p)`, splitting into equal
/// parts while the bound exceeds `budget`; interior joints get order `k`.
#[allow(clippy::too_many_arguments, reason = "recursion state, private helper")]
fn reduce_adaptive(
    bez: &BezierCurve,
    (a, b): (f64, f64),
    (r, p): (i32, i32),
    k: i32,
    opts: &BSplineOptions,
    budget: f64,
    depth: usize,
    out: &mut Vec<Piece>,
) -> Result<()> {
    let method = match opts.method {
        Method::ConstrainedChebyshev { .. } => Method::ConstrainedChebyshev { r, p },
        _ => Method::L2 { r, p },
    };
    let mut parts = 2usize;
    match reduce_with(bez, &ReduceOptions::new(method, opts.target)) {
        Ok(red) => {
            let bound = red.report.error_bound.unwrap_or(f64::INFINITY);
            if bound <= budget {
                out.push(Piece {
                    order: r,
                    a,
                    b,
                    curve: red.curve,
                    bound,
                });
                return Ok(());
            }
            // The error of a smooth piece scales like h^(m+1): split into as many equal
            // parts as that predicts (at least 2, at most 16 per level).
            let ratio = (bound / budget).powf(1.0 / (opts.target as f64 + 1.0));
            parts = (2..16).find(|&j| j as f64 >= ratio).unwrap_or(16);
        }
        Err(Error::NonPositiveWeight { .. }) => {}
        Err(e) => return Err(e),
    }
    let h = (b - a) / parts as f64;
    if depth >= MAX_DEPTH || !(h > 0.0 && a + h < b) {
        return Err(Error::ConditionNotMet {
            eq: "tolerance",
            why: "a span cannot be reduced within the tolerance (below the rounding level?)",
        });
    }
    for i in 0..parts {
        let (s0, s1) = (i as f64 / parts as f64, (i + 1) as f64 / parts as f64);
        let piece = bez.segment(s0, s1)?;
        let ends = (
            if i == 0 { r } else { k },
            if i + 1 == parts { p } else { k },
        );
        let (pa, pb) = (
            a + (b - a) * s0,
            if i + 1 == parts { b } else { a + (b - a) * s1 },
        );
        reduce_adaptive(&piece, (pa, pb), ends, k, opts, budget, depth + 1, out)?;
    }
    Ok(())
}

/// Reduces a B-spline or NURBS curve of degree `p` to degree `m` within a tolerance.
///
/// 1. **Extraction**: every non-empty span becomes a Bézier piece.
/// 2. **Reduction**: each piece is reduced by [`Method::ConstrainedChebyshev`] (seed 000
///    §14.5, Theorem 14.5.2) or [`Method::L2`] with end orders `r, p` equal to the
///    continuity `k_j = min(k, p - s_j)` to keep at the knot there (`s_j` its
///    multiplicity; order 0 at the domain ends). Matching the derivatives `0..=k_j` of the
///    input on both sides of a knot makes the result `C^(k_j)` there. Two-sided Hermite
///    data need `2 k + 1 <= m`, hence `k <= floor((m - 1) / 2)` (the default): for `m = 3`
///    that is C1 even where the input is C2 or smoother. (A global least-squares fit on
///    the degree-`m` spline space with the right multiplicities could keep `C^(m-1)`; it
///    is not implemented. Knot removal, step 5, raises the continuity wherever the
///    tolerance allows.)
/// 3. **Subdivision**: a piece whose certified bound exceeds 0.9 of the tolerance is split
///    into `ceil((bound / budget)^(1/(m+1)))` equal parts (2..=16; the error of a smooth
///    piece scales like `h^(m+1)`), inner joints with order `k`, recursively until every
///    part fits (at most 40 levels).
/// 4. **Merge**: the pieces become one clamped C0 spline (seed 001 §4.1,
///    [`BSplineCurve::from_beziers`]; the joint points agree up to rounding, half the gap
///    is added to the bound), then `k_j` copies of each joint are removed (the joint is
///    `C^(k_j)`, so this costs only rounding, certified) so that later removals nearby
///    cannot spoil it.
/// 5. **Knot removal**: greedy passes (at most 3) remove knot copies while, on every span the removal
///    touches, the accumulated bound (piece bound + bounds of the removals covering it)
///    stays `<= tolerance` — the local error bookkeeping of Piegl & Tiller.
///
/// The result has the input's domain, is clamped there, and never has more spans than the
/// pieces of step 3; with an input that is a degree-elevated degree-`m` spline it recovers
/// the original knots. Rational curves are reduced in homogeneous coordinates; their bounds
/// are converted to model space (see [`crate::reduce_with`]).
///
/// # Errors
/// [`Error::BadDegreePair`] (`m == 0` or `m >= p`); [`Error::BadTolerance`];
/// [`Error::BadParameter`] (a method other than the two above; an interior knot of
/// multiplicity `p + 1`); [`Error::TooManyConstraints`] (`continuity > floor((m-1)/2)`);
/// [`Error::ConditionNotMet`] when a span cannot meet the tolerance (e.g. a tolerance
/// below the rounding level of the curve).
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
    if !matches!(
        opts.method,
        Method::ConstrainedChebyshev { .. } | Method::L2 { .. }
    ) {
        return Err(Error::BadParameter {
            name: "method",
            value: 0.0,
            why: "B-spline reduction needs ConstrainedChebyshev or L2 (end orders set per knot)",
        });
    }
    let kmax = (m - 1) / 2;
    let k = opts.continuity.unwrap_or(kmax);
    if k > kmax {
        return Err(Error::TooManyConstraints {
            r: k as i64,
            p: k as i64,
            m,
            why: "per-segment Hermite constraints keep at most C^floor((m-1)/2)",
        });
    }
    let segs = curve.to_beziers()?;
    let spans_in = segs.len();
    let knots = curve.knots();
    let order_at = |t: f64| -> Result<i32> {
        let s = knot_multiplicity(knots, t);
        if s > p {
            return Err(Error::BadParameter {
                name: "knots",
                value: t,
                why: "interior knot of multiplicity p + 1 (possibly discontinuous)",
            });
        }
        Ok(i32::try_from(k.min(p - s)).unwrap_or(i32::MAX))
    };
    let budget = SEGMENT_SHARE * opts.tolerance;
    let mut pieces = Vec::new();
    let mut guaranteed = Vec::new();
    for (i, seg) in segs.iter().enumerate() {
        let r = if i == 0 { 0 } else { order_at(seg.start)? };
        let q = if i + 1 == segs.len() {
            0
        } else {
            order_at(seg.end)?
        };
        if i > 0 {
            guaranteed.push((seg.start, r as usize));
        }
        let ends = (seg.start, seg.end);
        reduce_adaptive(
            &seg.curve,
            ends,
            (r, q),
            i32::try_from(k).unwrap_or(i32::MAX),
            opts,
            budget,
            0,
            &mut pieces,
        )?;
    }
    let n_pieces = pieces.len();
    let segment_bound = pieces.iter().map(|x| x.bound).fold(0.0, f64::max);
    let (merged, mut local) = crate::bspline_knots::merge_pieces(
        pieces.iter().map(|x| (x.a, x.b, &x.curve, x.bound)),
        curve,
        opts.tolerance,
    )?;
    // Make the continuity of step 2 structural first: a later removal next to a C0-stored
    // joint would otherwise spoil its (only geometric) smoothness.
    let joints: Vec<(f64, usize)> = pieces[1..]
        .iter()
        .map(|x| (x.a, x.order.max(0) as usize))
        .collect();
    let mut raw = crate::bspline_knots::Raw::new(&merged);
    if !local.remove_joint_copies(&mut raw, &joints, opts.tolerance)? {
        return Err(Error::ConditionNotMet {
            eq: "tolerance",
            why: "the C^k joints could not be stored with multiplicity m - k (rounding)",
        });
    }
    local.remove_greedily(&mut raw, opts.tolerance)?;
    let curve_out = raw.into_curve()?;
    let error_bound = local.max_bound();
    let max_error = if opts.measure {
        Some(spline_max_deviation(curve, &curve_out)?)
    } else {
        None
    };
    let out_knots = curve_out.knots().to_vec();
    let continuity = guaranteed
        .into_iter()
        .filter(|(t, _)| knot_multiplicity(&out_knots, *t) > 0)
        .collect();
    let spans_out = curve_out.to_beziers()?.len();
    Ok(BSplineReduction {
        report: BSplineReport {
            method: opts.method,
            degree_from: p,
            degree_to: m,
            tolerance: opts.tolerance,
            error_bound,
            segment_bound,
            max_error,
            pieces: n_pieces,
            continuity,
        },
        curve: curve_out,
        spans_in,
        spans_out,
    })
}

#[cfg(test)]
#[path = "bspline_reduce_tests.rs"]
mod tests;
