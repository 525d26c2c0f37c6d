//! B-spline / NURBS degree reduction from C: general splines to a tolerance
//! (`cagd_bspline_reduce`, strategies translated in `reduce/strategy.rs`) and seed 001's uniform
//! pipeline (`cagd_bspline_reduce_uniform`); the report accessors are in
//! `report/spline.rs`.

use cagd_core::BSplineCurve;
use cagd_reduce::{Merge, reduce_bspline, reduce_uniform_bspline, spline_max_deviation};

use crate::boundary::{CResult, Failure, boundary, handle_ref, into_handle, nonnull, out_ref};
use crate::bspline::{CagdBSpline, spline_failure};
use crate::options::{CagdReduceOptions, read_options};
use crate::options::{CagdSplineStrategy, spline_options};
use crate::report::{CagdReport, ReportKind, SplineReport, StrategyReport};
use crate::status::CagdStatus;

/// Checks and borrows the two outputs (distinct, non-NULL, aligned).
///
/// # Safety
/// Both pointers NULL or writable.
unsafe fn outputs<'a>(
    spline_out: *mut *mut CagdBSpline,
    report_out: *mut *mut CagdReport,
) -> CResult<(&'a mut *mut CagdBSpline, &'a mut *mut CagdReport)> {
    nonnull(spline_out, "spline_out")?;
    nonnull(report_out, "report_out")?;
    if spline_out.addr() == report_out.addr() {
        return Err(Failure::invalid(
            "`spline_out` and `report_out` are the same address",
        ));
    }
    // SAFETY: forwarded contract; the two outputs do not overlap.
    unsafe {
        Ok((
            out_ref(spline_out, "spline_out")?,
            out_ref(report_out, "report_out")?,
        ))
    }
}

/// [`spline_max_deviation`] of `a` and `b`, or, when that overflows (a NURBS near the
/// largest double: its homogeneous points `w x` overflow), the same measured on both curves
/// scaled by one power of two (exact but for subnormal coordinates, far below the bound)
/// and scaled back: the curves `cagd_bspline_reduce_uniform` reduces in a scaled frame.
fn measured(a: &BSplineCurve, b: &BSplineCurve) -> cagd_core::Result<f64> {
    let amax = a
        .points()
        .iter()
        .chain(b.points())
        .fold(0.0f64, |m, x| m.max(x.abs()));
    match spline_max_deviation(a, b) {
        Err(cagd_core::Error::NonFinite { .. }) if amax > 1.0 && amax.is_finite() => {}
        other => return other,
    }
    // 2^-k in two normal factors, k = the binary exponent of amax (|k| <= 1024).
    #[allow(clippy::cast_possible_truncation, reason = "|log2| <= 1075")]
    let k = amax.log2().floor() as i32;
    let (s1, s2) = (2f64.powi(-k / 2), 2f64.powi(-k + k / 2));
    let scale = |c: &BSplineCurve| -> cagd_core::Result<BSplineCurve> {
        let pts: Vec<f64> = c.points().iter().map(|x| x * s1 * s2).collect();
        let knots = c.knots().to_vec();
        match c.weights() {
            Some(w) => BSplineCurve::new_rational(c.degree(), knots, pts, w.to_vec(), c.dim()),
            None => BSplineCurve::new(c.degree(), knots, pts, c.dim()),
        }
    };
    Ok(spline_max_deviation(&scale(a)?, &scale(b)?)? / s1 / s2)
}

/// Number of non-empty knot spans of the domain of `s`.
fn spans(s: &BSplineCurve) -> usize {
    let (p, n, u) = (s.degree(), s.n_points(), s.knots());
    (p..n).filter(|&i| u[i] < u[i + 1]).count()
}

/// Reduces a B-spline or NURBS curve of degree `p` to degree `opts->target` within
/// `opts->tolerance`, keeping the continuity the input has at its knots (cagd-reduce
/// `reduce_bspline`; the task of Piegl & Tiller 1995, "Algorithm for degree reduction of
/// B-spline curves"). The bound is certified: `cagd_report_bound` gives an upper bound of
/// `max_t |C(t) - C'(t)|` (Euclidean, model space, `f64` rounding included) that is
/// `<= tolerance` and never below the true error. The result is clamped on the input's
/// domain and rational if the input is (NURBS are reduced in homogeneous coordinates).
///
/// Continuity: at every interior knot of the input that is still a knot of the result,
/// the result is `C^min(k, c)`, `c` the input's continuity there (`p - s` for a knot of
/// multiplicity `s`) and `k = opts->spline_continuity`, or the strategy's maximum `K` when
/// it is `-1` (`cagd_report_spline_continuity` lists the knots and orders). The strategy
/// (`opts->spline_strategy`, a `CagdSplineStrategy`) decides how:
/// - `CAGD_SPLINE_FIT` (default), `K = target - 1`: one least-squares fit (parameter L2
///   norm, end points kept) on the degree-`target` spline space with the input's knots at
///   multiplicity `target - min(k, c, target - 1)`; spans whose certified bound misses
///   their share of the tolerance are split and the fit repeated; then knots are removed
///   while every span's tracked bound stays within the tolerance.
/// - `CAGD_SPLINE_SEGMENTS`, `K = floor((target - 1) / 2)` (two-sided Hermite data need
///   `2k + 1 <= target`): every knot span is extracted as a Bézier piece and reduced by
///   `opts->method` (`CAGD_METHOD_L2`, or `CAGD_METHOD_CONSTRAINED_CHEBYSHEV`, seed 000
///   §14.5; their end orders are set per knot from the continuity to keep, `opts->r` and
///   `opts->p` are not used), split where needed until each piece meets its share of
///   the tolerance, merged exactly (seed 001 §4.1), then knots are removed as above.
/// - `CAGD_SPLINE_PIEGL_TILLER_1995`, `K = target - 1`: the classical algorithm (NURBS
///   Book A5.11), kept as a reference: one degree at a time, every segment reduced by one
///   degree (Piegl–Tiller's formula), merged, and every interior knot left with one copy
///   fewer per degree (so `C^c` is kept where a knot stays; `spline_continuity` is checked
///   against `K` but changes nothing). It never subdivides: the result has at most the
///   input's spans, and when the curve is not reducible within the tolerance that way it
///   fails with `CAGD_ERR_CONDITION_NOT_MET` (it succeeds essentially for degree-elevated
///   splines, every interior knot of multiplicity `>= p - target + 1`, and those within
///   the tolerance of one).
///
/// Options used: `spline_strategy`, `target` (`1 <= target < p`), `tolerance`,
/// `spline_continuity`, `method` (`CAGD_SPLINE_SEGMENTS` only; ignored otherwise),
/// `measure`. Not used: `continuity`, `r`, `p`, `max_depth` and the rest.
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `opts` (in): the options. Borrowed for the call.
/// - `spline_out` (out): on `CAGD_OK`, the reduced spline of degree `target`, owned by the
///   caller: release with `cagd_bspline_free`.
/// - `report_out` (out): on `CAGD_OK`, the report, owned by the caller: release with
///   `cagd_report_free`. Neither output is written on failure. Its accessors:
///   `cagd_report_bound`, `cagd_report_max_error` (with `measure`), `cagd_report_method`
///   (the method that reduced the pieces: `opts->method` for segments, `CAGD_METHOD_L2`
///   for the fit, `CAGD_METHOD_PIEGL_TILLER` for Piegl–Tiller 1995),
///   `cagd_report_spline` (segment bound, spans), `cagd_report_spline_strategy`,
///   `cagd_report_spline_continuity`.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `spline`, `opts`, `spline_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `opts->struct_size` below `sizeof(CagdReduceOptions)`,
///   a `spline_strategy` code that is not a `CagdSplineStrategy`, `spline_continuity`
///   below `-1`, with `CAGD_SPLINE_SEGMENTS` an invalid method code or a method other than
///   the two above, `tolerance` not finite and `> 0`, the two outputs are the same address,
///   or a pointer is misaligned.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target == 0` or `target >= p`.
/// - `CAGD_ERR_TOO_MANY_CONSTRAINTS`: `spline_continuity > K` (the strategy's maximum
///   above).
/// - `CAGD_ERR_BAD_KNOTS`: an interior knot of multiplicity `p + 1` (the input may be
///   discontinuous there).
/// - `CAGD_ERR_CONDITION_NOT_MET`: `CAGD_SPLINE_FIT`, `CAGD_SPLINE_SEGMENTS`: the
///   tolerance cannot be met (below the rounding level of the curve, or more than `2^20`
///   spans, or for the fit more than `2^23` span coordinates fitted over the refinement
///   rounds, each span counted with 24 more per curve of the bundle and, above degree 7, `(p + 1)^2 / 64` times,
///   needed; for the segments more than `2^20` segment reductions, or a `C^k` joint of two
///   reduced NURBS pieces whose knot removal would make a control weight non-positive);
///   `CAGD_SPLINE_PIEGL_TILLER_1995`: the curve is not reducible within the
///   tolerance without subdivision (a segment reduction or a required knot removal does
///   not fit in the tolerance left on its spans), or a reduced NURBS weight is not
///   positive.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: `CAGD_SPLINE_FIT`: a weight of the fitted NURBS is
///   not positive.
/// - `CAGD_ERR_SINGULAR`: `CAGD_SPLINE_FIT`: the least-squares system is rank-deficient
///   (not expected for a valid spline).
/// - `CAGD_ERR_NON_FINITE`: with `measure`, the sampled error is not finite.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `opts` NULL or a readable
/// `CagdReduceOptions` of `opts->struct_size` bytes; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_reduce(
    spline: *const CagdBSpline,
    opts: *const CagdReduceOptions,
    spline_out: *mut *mut CagdBSpline,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(spline, "spline") }?;
        // SAFETY: as above.
        let o = unsafe { read_options(opts) }?;
        // SAFETY: as above.
        let (s_out, r_out) = unsafe { outputs(spline_out, report_out) }?;
        let red = reduce_bspline(&s.0, &spline_options(&o)?).map_err(spline_failure)?;
        let r = &red.report;
        let strategy = CagdSplineStrategy::of(&r.strategy);
        let report = SplineReport {
            degree_from: r.degree_from,
            degree_to: r.degree_to,
            error_bound: r.error_bound,
            max_error: r.max_error,
            segment_bound: r.segment_bound,
            pieces: r.pieces,
            spans_in: red.spans_in,
            spans_out: red.spans_out,
            strategy: Some(StrategyReport {
                strategy,
                continuity: r.continuity.clone(),
            }),
        };
        *s_out = into_handle(CagdBSpline(red.curve));
        *r_out = into_handle(CagdReport {
            kind: ReportKind::Spline(report),
            method: strategy.reported_method(o.method),
        });
        Ok(())
    })
}

/// Reduces a uniform B-spline or NURBS curve (equally spaced knots) of degree `n` to
/// degree `opts->target` segment by segment, seed 001's pipeline (model (1)): the B-spline
/// points of each segment go to its Bézier points by `S^(n)` (eq. 5), `opts->method`
/// reduces them, and `opts->merge` joins the results (§4). Not driven by a tolerance: the
/// report gives the certified bound of what was done.
///
/// Options used: `method` (with `r`, `p`, `l1`, `l2`), `target`, `merge`, `measure`.
///
/// Parameters:
/// - `spline` (in): the spline, uniform knots (every gap within `1e-9` of the spacing; the
///   output keeps the input's own knots, and the bounds include the rounding of their gaps).
/// - `opts` (in): the options. Borrowed for the call.
/// - `spline_out` (out): on `CAGD_OK`, the merged spline of degree `target` on the
///   input's domain (`CAGD_MERGE_EXACT`: clamped, interior knots of multiplicity
///   `target - k`; `CAGD_MERGE_LOSSY`: uniform knots of the input's spacing), owned by the
///   caller: release with `cagd_bspline_free`.
/// - `report_out` (out): on `CAGD_OK`, the report (`cagd_report_bound`: the certified
///   bound of the merged spline; `cagd_report_spline`: the bound of the reduction step
///   alone), owned by the caller: release with `cagd_report_free`. Neither output is
///   written on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `spline`, `opts`, `spline_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `opts->struct_size` below `sizeof(CagdReduceOptions)`,
///   an invalid `method` or `merge` code, `CAGD_MERGE_EXACT` with a method that does not
///   interpolate the segment ends, the two outputs are the same address, a pointer is
///   misaligned, or coordinates so near the largest double that the certified bound or
///   the reduced points overflow (coordinates outside `[2^-450, 2^450]`, e.g. near
///   `1e300`, are reduced in a frame scaled by a power of two: only what overflows in
///   model units is refused).
/// - `CAGD_ERR_BAD_KNOTS`: the knots are not uniform (a spacing of a few ulps of the knots
///   is not: its gaps differ by whole ulps).
/// - `CAGD_ERR_BAD_DEGREE_PAIR`, `CAGD_ERR_TOO_MANY_CONSTRAINTS`: as `cagd_curve_reduce`
///   for the pair `(n, target)`.
/// - `CAGD_ERR_CONDITION_NOT_MET`: the exact merge finds joints that do not meet.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a reduced weight of a NURBS is not positive.
/// - `CAGD_ERR_MULTIPLICITY`: the reduced knot vector would carry a knot of multiplicity
///   above `target + 1` (an input with a knot of multiplicity above `target + 1`, e.g.
///   merged Bézier pieces, whose multiplicities the uniform route keeps).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `opts` NULL or a readable
/// `CagdReduceOptions` of `opts->struct_size` bytes; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_reduce_uniform(
    spline: *const CagdBSpline,
    opts: *const CagdReduceOptions,
    spline_out: *mut *mut CagdBSpline,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(spline, "spline") }?;
        // SAFETY: as above.
        let o = unsafe { read_options(opts) }?;
        // SAFETY: as above.
        let (s_out, r_out) = unsafe { outputs(spline_out, report_out) }?;
        let merge = match o.merge {
            0 => Merge::Exact,
            1 => Merge::Lossy,
            other => {
                return Err(Failure::invalid(format!(
                    "opts->merge = {other} is not a CagdMerge (0 or 1)"
                )));
            }
        };
        let red =
            reduce_uniform_bspline(&s.0, o.target, o.method()?, merge).map_err(spline_failure)?;
        let max_error = if o.measure {
            Some(measured(&s.0, &red.curve)?)
        } else {
            None
        };
        let report = SplineReport {
            degree_from: s.0.degree(),
            degree_to: red.curve.degree(),
            error_bound: red.error_bound,
            max_error,
            segment_bound: red.segment_bound,
            pieces: red.segments.len(),
            spans_in: spans(&s.0),
            spans_out: spans(&red.curve),
            strategy: None,
        };
        *s_out = into_handle(CagdBSpline(red.curve));
        *r_out = into_handle(CagdReport {
            kind: ReportKind::Spline(report),
            method: o.method,
        });
        Ok(())
    })
}
