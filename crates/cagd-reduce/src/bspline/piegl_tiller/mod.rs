//! The classical B-spline degree reduction of Piegl & Tiller 1995 ("Algorithm for degree
//! reduction of B-spline curves", Computer-Aided Design 27(2); "The NURBS Book", 2nd ed.,
//! §5.6, algorithm A5.11), written anew from its description as a baseline for
//! [`crate::reduce_bspline`]: one degree at a time, Bézier extraction, one-degree reduction
//! of every segment, merge, and removal of one copy fewer of every knot than the segments
//! leave, with the error tracked per span; it fails instead of subdividing.

use cagd_core::{BSplineCurve, Error, Result, check_tolerance, kernel, knot_multiplicity};

use super::framed;
use super::knots::{LocalBounds, Raw, merge_pieces};
use super::measure::{euclidean_from_homogeneous, spline_max_deviation};
use super::options::{BSplineReduction, BSplineReport, BSplineStrategy};
use crate::bezier::max_norm;
use crate::{Method, ReduceOptions, reduce_with};

/// The `eq` of this algorithm's [`Error::ConditionNotMet`].
const EQ: &str = "Piegl-Tiller 1995";

fn fail(why: &'static str) -> Error {
    Error::ConditionNotMet { eq: EQ, why }
}

/// Reduces a B-spline or NURBS curve of degree `p` to degree `target = m` by the algorithm
/// of Piegl & Tiller 1995 (NURBS Book A5.11), within `tolerance`, or fails.
///
/// The reduction runs `q -> q - 1` for `q = p, p - 1, ..., m + 1`:
/// 1. the current degree-`q` spline is cut into its Bézier segments;
/// 2. every segment is reduced by one degree with [`Method::PieglTiller`] (which keeps the
///    derivatives `0..=floor((q-2)/2)` at both ends), with its certified bound;
/// 3. the segments are merged into one clamped C0 spline of degree `q - 1` (seed 001 §4.1,
///    [`BSplineCurve::from_beziers`]; half the rounding gap at a joint is charged to both
///    neighbouring spans);
/// 4. every interior knot of multiplicity `s` in the degree-`q` spline is removed `q - s`
///    times, leaving multiplicity `s - 1` and so the continuity `C^(q-s)` it had (a simple
///    knot disappears: the spline must be one polynomial across it).
///
/// **What is tracked.** A certified bound per span of the *input's* partition (its distinct
/// knots; spans only merge, the partition never changes): every segment bound is added to
/// the input spans the segment covers, every knot removal's bound
/// ([`BSplineCurve::remove_knot`]) to the spans its moved control points' basis functions
/// touch. By the triangle inequality the sum on a span bounds `max ||C(t) - C'(t)||` there
/// (f64 rounding included by the parts' certificates). A removal is accepted only if every
/// span it touches stays within the tolerance, a segment only if its spans do; otherwise the
/// algorithm stops with [`Error::ConditionNotMet`] — it never subdivides, so the result has
/// at most the input's spans (it succeeds in essence for degree-elevated splines, where every
/// interior knot has multiplicity `>= p - m + 1`, and for those within the tolerance of one).
///
/// Rational curves are reduced in their frame (centred at the origin, scaled to radius 1,
/// the tolerance scaled with it; moved back after, the
/// rounding added; ADDED, beyond Piegl & Tiller) as polynomial splines of their homogeneous
/// points `(w P, w)`; the per-span homogeneous bounds are held below
/// `tol_h = tol w_min / (1 + P_max + tol)` (`w_min`, `P_max <= 1` the smallest input weight
/// and largest framed point norm), which makes the centred model-space bound
/// `eps_h (1 + P_max) / max(v_min, w_min - eps_h)` ([`cagd_core::centred_rational_bound`])
/// `<= tol`. In the frame the bound is unit-consistent: the same curve moved or scaled
/// gives the same result and a bound that scales with it (Piegl & Tiller's
/// `eps (1 + max ||P||) / min w` does not).
///
/// Degrees up to [`cagd_core::MAX_DEGREE`]. Measured (unit tests): a degree-3 spline with
/// double knots elevated to degree 7 comes back with the same knot vector and the points
/// within `1e-10` relative; with a `1e-7` perturbation the bound is `<= 1e-5` and never below
/// the sampled error.
///
/// # Errors
/// [`Error::BadDegreePair`] (`m == 0` or `m >= p`); [`Error::BadTolerance`];
/// [`Error::BadParameter`] (an interior knot of multiplicity `p + 1`);
/// [`Error::ConditionNotMet`] (eq. "Piegl-Tiller 1995") when a segment reduction or a
/// required knot removal does not fit in the tolerance left on its spans, or a reduced
/// weight is not positive; errors of the sampling when `measure` is set.
///
/// ```
/// use cagd_core::BSplineCurve;
/// use cagd_reduce::reduce_bspline_piegl_tiller;
/// // A quadratic with one simple knot at 0.5, elevated to degree 3 (the knot doubles).
/// let quad = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0],
///                              vec![0.0, 0.0, 1.0, 2.0, 3.0, 0.0, 4.0, 1.0], 2)?;
/// let pieces: Vec<_> = quad.to_beziers()?.iter().map(|s| s.curve.elevate(1)).collect::<Result<_, _>>()?;
/// let cubic = BSplineCurve::from_beziers(&pieces, &[0.0, 0.5, 1.0], 1, 1e-12)?;
/// assert_eq!(cubic.knots(), &[0.0, 0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0]);
/// let r = reduce_bspline_piegl_tiller(&cubic, 2, 1e-9, true)?;
/// assert_eq!(r.curve.knots(), quad.knots());
/// assert!(r.report.max_error.unwrap() <= r.report.error_bound && r.report.error_bound < 1e-13);
/// // A genuine cubic with a simple knot cannot keep its C2 joint at degree 2.
/// let c = BSplineCurve::new(3, vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0],
///                           vec![0.0, 0.0, 1.0, 2.0, 2.0, -1.0, 3.0, 2.0, 4.0, 0.0], 2)?;
/// assert!(reduce_bspline_piegl_tiller(&c, 2, 1e-6, false).is_err());
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn reduce_bspline_piegl_tiller(
    curve: &BSplineCurve,
    target: usize,
    tolerance: f64,
    measure: bool,
) -> Result<BSplineReduction> {
    check_tolerance(tolerance)?;
    let Some((frame, moved)) = framed::frame_curve(curve, tolerance)? else {
        return piegl_tiller_at(curve, target, tolerance, measure);
    };
    let mut red = piegl_tiller_at(&moved, target, frame.inner_tol, false)?;
    let out = red.curve.points().to_vec();
    red.curve = framed::unframe_curve(&frame, &red.curve)?;
    red.report.tolerance = tolerance;
    red.report.error_bound = frame.finish(red.report.error_bound, &out);
    red.report.segment_bound = frame.finish(red.report.segment_bound, &out);
    if red.report.error_bound > tolerance {
        return Err(fail("the model-space bound exceeds the tolerance"));
    }
    if measure {
        red.report.max_error = Some(spline_max_deviation(curve, &red.curve)?);
    }
    Ok(red)
}

/// [`reduce_bspline_piegl_tiller`] on a polynomial or framed rational curve.
fn piegl_tiller_at(
    curve: &BSplineCurve,
    target: usize,
    tolerance: f64,
    measure: bool,
) -> Result<BSplineReduction> {
    let (p, m, dim) = (curve.degree(), target, curve.dim());
    if m == 0 || m >= p {
        return Err(Error::BadDegreePair {
            from: p,
            to: m,
            why: "B-spline reduction needs 1 <= m < p",
        });
    }
    let segs = curve.to_beziers()?;
    let spans_in = segs.len();
    let mut breaks: Vec<f64> = segs.iter().map(|s| s.start).collect();
    breaks.extend(segs.last().map(|s| s.end));
    let interior: Vec<(f64, usize)> = breaks[1..breaks.len() - 1]
        .iter()
        .map(|&v| (v, knot_multiplicity(curve.knots(), v)))
        .collect();
    if let Some(&(v, _)) = interior.iter().find(|(_, s)| *s > p) {
        return Err(Error::BadParameter {
            name: "knots",
            value: v,
            why: "interior knot of multiplicity p + 1 (possibly discontinuous)",
        });
    }
    // Work on the homogeneous points as a polynomial spline (the curve itself if polynomial).
    let (mut work, pmax, wmin) = match curve.weights() {
        None => (curve.clone(), 0.0, 1.0),
        Some(w) => (
            BSplineCurve::new(
                p,
                curve.knots().to_vec(),
                curve.homogeneous_points(),
                dim + 1,
            )?,
            max_norm(curve.points(), dim),
            w.iter().copied().fold(f64::INFINITY, f64::min),
        ),
    };
    let tol_h = if curve.is_rational() {
        tolerance * wmin / (1.0 + pmax + tolerance) * (1.0 - 16.0 * f64::EPSILON)
    } else {
        tolerance
    };
    let mut local = LocalBounds::new(breaks, vec![0.0; spans_in]);
    let mut segment_max = 0.0f64;
    for q in (m + 1..=p).rev() {
        work = one_degree(&work, q, &mut local, tol_h, &mut segment_max)?;
    }
    let (curve_out, vmin_out) = match curve.weights() {
        None => (work, None),
        Some(_) => {
            let (knots, hom, _) = work.into_parts();
            let n = hom.len() / (dim + 1);
            let (mut pts, mut w) = (vec![0.0; n * dim], vec![0.0; n]);
            if hom
                .chunks_exact(dim + 1)
                .any(|h| !h[dim].is_finite() || h[dim] <= 0.0)
            {
                return Err(fail("a reduced weight is not positive"));
            }
            kernel::from_homogeneous(&hom, dim, &mut pts, &mut w);
            let vmin = w.iter().copied().fold(f64::INFINITY, f64::min);
            (
                BSplineCurve::new_rational(m, knots, pts, w, dim)?,
                Some(vmin),
            )
        }
    };
    // Model-space bound of a homogeneous one (`vmin`: a lower bound of the output weights).
    let model = |e: f64, vmin: f64| match vmin_out {
        None => e,
        Some(_) => euclidean_from_homogeneous(e, pmax, wmin, vmin),
    };
    let error_bound = model(local.max_bound(), vmin_out.unwrap_or(0.0));
    if error_bound.is_nan() || error_bound > tolerance {
        return Err(fail("the model-space bound exceeds the tolerance"));
    }
    let max_error = if measure {
        Some(spline_max_deviation(curve, &curve_out)?)
    } else {
        None
    };
    let continuity = interior
        .iter()
        .filter(|(v, _)| knot_multiplicity(curve_out.knots(), *v) > 0)
        .map(|&(v, s)| (v, p - s))
        .collect();
    let spans_out = curve_out.to_beziers()?.len();
    Ok(BSplineReduction {
        report: BSplineReport {
            strategy: BSplineStrategy::PieglTiller1995,
            degree_from: p,
            degree_to: m,
            tolerance,
            error_bound,
            segment_bound: model(segment_max, 0.0),
            max_error,
            pieces: spans_out,
            continuity,
        },
        curve: curve_out,
        spans_in,
        spans_out,
    })
}

/// One step `q -> q - 1` of the polynomial spline `c`, charging the bounds to `local` and
/// failing when a span would exceed `tol`; `segment_max` collects the segment bounds.
fn one_degree(
    c: &BSplineCurve,
    q: usize,
    local: &mut LocalBounds,
    tol: f64,
    segment_max: &mut f64,
) -> Result<BSplineCurve> {
    let opts = ReduceOptions::new(Method::PieglTiller, q - 1);
    let segs = c.to_beziers()?;
    let mut reduced = Vec::with_capacity(segs.len());
    for s in &segs {
        let r = reduce_with(&s.curve, &opts)?;
        let bound = r.report.error_bound.unwrap_or(f64::INFINITY);
        *segment_max = segment_max.max(bound);
        reduced.push((s.start, s.end, r.curve, bound));
    }
    let (merged, pieces) = merge_pieces(reduced.iter().map(|(a, b, x, e)| (*a, *b, x, *e)), c)?;
    for ((a, b, _, _), e) in reduced.iter().zip(pieces.spans()) {
        local.charge(*a, *b, *e);
    }
    let worst = local.max_bound();
    if worst.is_nan() || worst > tol {
        return Err(fail(
            "a segment does not reduce by one degree within the tolerance",
        ));
    }
    let mut raw = Raw::new(&merged);
    for w in segs.windows(2) {
        let v = w[0].end;
        let s = knot_multiplicity(c.knots(), v);
        for _ in s..q {
            if !local.try_remove_one(&mut raw, v, tol)? {
                return Err(fail("a knot cannot be removed within the tolerance"));
            }
        }
    }
    raw.into_curve()
}

#[cfg(test)]
pub(super) mod tests;
