//! [`rational_to_polynomial`]: the curve entry point, its report and the exact case.

use cagd_core::{BSplineCurve, Error, MAX_DEGREE, Result, check_tolerance};

use super::bound::exact_bound;
use super::curve_fit::fit_to_budget;
use super::pieces::RationalPieces;
use crate::{BSplineOptions, LocalBounds, Raw, order_at, reduce_bspline, spline_max_deviation};

/// Share of the tolerance the fit must meet on every span; the rest is for knot removal
/// (as in [`crate::reduce_bspline`]).
const FIT_SHARE: f64 = 0.9;

/// What [`rational_to_polynomial`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct PolynomialReport {
    /// Degree of the input.
    pub degree_from: usize,
    /// Degree of the result (`<= m`).
    pub degree_to: usize,
    /// The tolerance asked for.
    pub tolerance: f64,
    /// `true` when the weights were all equal and the result is the input's own polynomial
    /// spline (no approximation; degree-reduced when `m < p`).
    pub equal_weights: bool,
    /// Certified upper bound of `max_t ||C(t) - S(t)||` (Euclidean, model space, the same
    /// parameter; `<= tolerance`; 0 when the input was polynomial and `m >= p`). It bounds
    /// the geometric (Hausdorff) distance too.
    pub error_bound: f64,
    /// The largest certified bound of a span before knot removal.
    pub segment_bound: f64,
    /// `max_t ||C(t) - S(t)||` measured by dense sampling ([`crate::spline_max_deviation`]).
    pub max_error: f64,
    /// Spans after the adaptive refinement, before knot removal.
    pub pieces: usize,
    /// For every interior break `t` of the input: `(t, k)`, `k = min(p - s, m - 1)` the
    /// continuity the result is guaranteed to have there (the input is `C^(p - s)`, `s`
    /// the multiplicity; knot removal may only raise it).
    pub continuity: Vec<(f64, usize)>,
}

/// The polynomial spline with its report.
#[derive(Debug, Clone, PartialEq)]
pub struct PolynomialReduction {
    /// The polynomial B-spline (no weights) on the input's domain; clamped unless it is the
    /// input itself (equal weights, `m >= p`).
    pub curve: BSplineCurve,
    /// What was done.
    pub report: PolynomialReport,
    /// Non-empty knot spans of the input.
    pub spans_in: usize,
    /// Non-empty knot spans of the result.
    pub spans_out: usize,
}

/// Whether all weights are equal (a common factor cancels in `A / W`), and the polynomial
/// spline of the same control points.
fn polynomial_part(curve: &BSplineCurve) -> Result<Option<BSplineCurve>> {
    let equal = curve.weights().is_none_or(|w| w.iter().all(|x| *x == w[0]));
    if !equal {
        return Ok(None);
    }
    BSplineCurve::new(
        curve.degree(),
        curve.knots().to_vec(),
        curve.points().to_vec(),
        curve.dim(),
    )
    .map(Some)
}

/// Non-empty spans of a knot vector of degree `p` (inside the domain).
pub(crate) fn span_count(knots: &[f64], p: usize) -> usize {
    let n = knots.len() - p - 1;
    (p..n).filter(|&i| knots[i] < knots[i + 1]).count()
}

/// One fit from a start knot vector: the spline after knot removal and its numbers.
struct Attempt {
    curve: BSplineCurve,
    bound: f64,
    segment_bound: f64,
    pieces: usize,
    spans: usize,
    knots_len: usize,
}

/// Fits from the knot vector `start` ([`fit_to_budget`]) and removes knots within `tol`.
fn fit_and_remove(src: &RationalPieces, m: usize, start: Vec<f64>, tol: f64) -> Result<Attempt> {
    let knots_len = start.len();
    let (knots, points, bounds) = fit_to_budget(src, m, start, FIT_SHARE * tol)?;
    let pieces = bounds.len();
    let segment_bound = bounds.iter().map(|x| x.bound).fold(0.0, f64::max);
    let mut breaks: Vec<f64> = bounds.iter().map(|x| x.a).collect();
    breaks.push(bounds[pieces - 1].b);
    let mut local = LocalBounds::new(breaks, bounds.iter().map(|x| x.bound).collect());
    let mut raw = Raw::new(&BSplineCurve::new(m, knots, points, src.dim)?);
    local.remove_greedily(&mut raw, tol)?;
    let curve = raw.into_curve()?;
    let spans = span_count(curve.knots(), m);
    Ok(Attempt {
        curve,
        bound: local.max_bound(),
        segment_bound,
        pieces,
        spans,
        knots_len,
    })
}

/// The continuity report: every interior break of the input with `min(p - s, m - 1)`.
pub(crate) fn continuity_report(
    knots: &[f64],
    p: usize,
    m: usize,
    breaks: &[f64],
) -> Result<Vec<(f64, usize)>> {
    breaks[1..breaks.len() - 1]
        .iter()
        .map(|&t| Ok((t, order_at(knots, p, p, t)?.min(m - 1))))
        .collect()
}

/// The clamped degree-`m` knot vector on `breaks` keeping `C^min(p - s, m - 1)` at each.
///
/// # Errors
/// [`Error::BadParameter`] for an interior knot of multiplicity `p + 1`.
pub(crate) fn start_knots(knots: &[f64], p: usize, m: usize, breaks: &[f64]) -> Result<Vec<f64>> {
    start_knots_from(knots, p, m, breaks, false)
}

/// [`start_knots`]; with `coarse`, the breaks where the result may be `C^(m-1)` (no
/// multiple knot needed) are left out: the refinement places the knots there.
pub(crate) fn start_knots_from(
    knots: &[f64],
    p: usize,
    m: usize,
    breaks: &[f64],
    coarse: bool,
) -> Result<Vec<f64>> {
    let mut out = vec![breaks[0]; m + 1];
    for &t in &breaks[1..breaks.len() - 1] {
        let keep = order_at(knots, p, p, t)?.min(m - 1);
        if !(coarse && keep == m - 1) {
            out.extend(std::iter::repeat_n(t, m - keep));
        }
    }
    out.extend(std::iter::repeat_n(breaks[breaks.len() - 1], m + 1));
    Ok(out)
}

/// Checks the target degree (`1..=MAX_DEGREE`, default `p`).
pub(crate) fn target_degree(p: usize, m: Option<usize>) -> Result<usize> {
    let m = m.unwrap_or(p);
    if m == 0 || m > MAX_DEGREE {
        return Err(Error::BadDegreePair {
            from: p,
            to: m,
            why: "rational to polynomial needs 1 <= m <= 64",
        });
    }
    Ok(m)
}

/// Converts a NURBS curve `C = A / W` of degree `p` to a polynomial B-spline of degree
/// `<= m` (`m` defaults to `p`; any `1 <= m <= 64`, so a conic may become cubic) whose
/// certified distance to `C` is within `tol`, keeping `C^min(p - s, m - 1)` at every input
/// knot of multiplicity `s` (the method: the crate docs, "Rational to polynomial"; ours,
/// on the machinery of [`crate::reduce_bspline`]).
///
/// Weights all equal (or no weights) are recognised exactly: the polynomial spline of the
/// same control points is returned unchanged when `m >= p` (bound at the rounding level of
/// evaluating the rational form, no spans added; [`Error::ConditionNotMet`] when that
/// level is above `tol`, as for any other input) and
/// reduced by [`crate::reduce_bspline`] when `m < p`.
///
/// # Errors
/// [`Error::BadTolerance`]; [`Error::BadDegreePair`] (`m == 0` or `m > 64`);
/// [`Error::BadParameter`] (an interior knot of multiplicity `p + 1`: the input may jump);
/// [`Error::ConditionNotMet`] when the tolerance is below the rounding level of the curve
/// or needs more than 2^20 spans.
///
/// ```
/// use cagd_core::BSplineCurve;
/// use cagd_reduce::rational_to_polynomial;
/// // A quarter circle as a rational quadratic.
/// let h = std::f64::consts::FRAC_1_SQRT_2;
/// let arc = BSplineCurve::new_rational(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
///     vec![1.0, 0.0, 1.0, 1.0, 0.0, 1.0], vec![1.0, h, 1.0], 2)?;
/// let r = rational_to_polynomial(&arc, Some(3), 1e-5)?;
/// assert!(!r.curve.is_rational() && r.curve.degree() == 3);
/// assert!(r.report.max_error <= r.report.error_bound && r.report.error_bound <= 1e-5);
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn rational_to_polynomial(
    curve: &BSplineCurve,
    m: Option<usize>,
    tol: f64,
) -> Result<PolynomialReduction> {
    check_tolerance(tol)?;
    let p = curve.degree();
    let m = target_degree(p, m)?;
    let src = RationalPieces::new(curve)?;
    let spans_in = src.len();
    if let Some(poly) = polynomial_part(curve)? {
        return exact_case(curve, poly, m, tol, &src.breaks, spans_in);
    }
    let full = start_knots_from(curve.knots(), p, m, &src.breaks, false)?;
    let coarse = start_knots_from(curve.knots(), p, m, &src.breaks, true)?;
    let mut best = fit_and_remove(&src, m, full, tol)?;
    if coarse.len() < best.knots_len {
        // A failure of the coarse start (e.g. its refinement runs out of rounds) leaves
        // the full start's result.
        if let Ok(other) = fit_and_remove(&src, m, coarse, tol) {
            if other.spans < best.spans {
                best = other;
            }
        }
    }
    let Attempt {
        curve: out,
        bound,
        segment_bound,
        pieces,
        ..
    } = best;
    let max_error = spline_max_deviation(curve, &out)?;
    let spans_out = span_count(out.knots(), m);
    Ok(PolynomialReduction {
        report: PolynomialReport {
            degree_from: p,
            degree_to: m,
            tolerance: tol,
            equal_weights: false,
            error_bound: bound,
            segment_bound,
            max_error,
            pieces,
            continuity: continuity_report(curve.knots(), p, m, &src.breaks)?,
        },
        curve: out,
        spans_in,
        spans_out,
    })
}

/// Equal weights: the polynomial spline itself, or its reduction to degree `m < p`.
fn exact_case(
    curve: &BSplineCurve,
    poly: BSplineCurve,
    m: usize,
    tol: f64,
    breaks: &[f64],
    spans_in: usize,
) -> Result<PolynomialReduction> {
    let p = curve.degree();
    let continuity = continuity_report(curve.knots(), p, m.min(p), breaks)?;
    if m >= p {
        let max_error = spline_max_deviation(curve, &poly)?;
        let bound = exact_bound(curve.points(), curve.dim(), p + 2, max_error, tol)?;
        return Ok(PolynomialReduction {
            report: PolynomialReport {
                degree_from: p,
                degree_to: p,
                tolerance: tol,
                equal_weights: true,
                error_bound: bound,
                segment_bound: bound,
                max_error,
                pieces: spans_in,
                continuity,
            },
            curve: poly,
            spans_in,
            spans_out: spans_in,
        });
    }
    let opts = BSplineOptions {
        measure: true,
        ..BSplineOptions::new(m, tol)
    };
    let red = reduce_bspline(&poly, &opts)?;
    let max_error = spline_max_deviation(curve, &red.curve)?;
    let spans_out = span_count(red.curve.knots(), m);
    Ok(PolynomialReduction {
        report: PolynomialReport {
            degree_from: p,
            degree_to: m,
            tolerance: tol,
            equal_weights: true,
            error_bound: red.report.error_bound,
            segment_bound: red.report.segment_bound,
            max_error,
            pieces: red.report.pieces,
            continuity,
        },
        curve: red.curve,
        spans_in,
        spans_out,
    })
}
