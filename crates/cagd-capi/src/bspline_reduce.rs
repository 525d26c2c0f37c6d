//! B-spline / NURBS degree reduction from C: general splines to a tolerance
//! (`cagd_bspline_reduce`) and seed 001's uniform pipeline (`cagd_bspline_reduce_uniform`).

use cagd_core::BSplineCurve;
use cagd_reduce::{
    BSplineOptions, BSplineStrategy, Merge, reduce_bspline, reduce_uniform_bspline,
    spline_max_deviation,
};

use crate::boundary::{CResult, Failure, boundary, handle_ref, into_handle, nonnull, out_ref};
use crate::bspline::{CagdBSpline, spline_failure};
use crate::reduce_options::{CagdReduceOptions, read_options};
use crate::report::{CagdReport, ReportKind, SplineReport};
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

/// Number of non-empty knot spans of the domain of `s`.
fn spans(s: &BSplineCurve) -> usize {
    let (p, n, u) = (s.degree(), s.n_points(), s.knots());
    (p..n).filter(|&i| u[i] < u[i + 1]).count()
}

/// Reduces a B-spline or NURBS curve of degree `p` to degree `opts->target` within
/// `opts->tolerance` (certified, Euclidean, model space): every knot span is extracted as
/// a Bézier piece, reduced by `opts->method` (`CAGD_METHOD_CONSTRAINED_CHEBYSHEV`, seed 000
/// §14.5, or `CAGD_METHOD_L2`; their `r`, `p` are set per end from the continuity to keep)
/// keeping derivatives `0..=min(continuity, p - s_j)` at each knot of multiplicity `s_j`,
/// split at midpoints until each piece meets half the tolerance, merged exactly (seed 001
/// §4.1), then knots are removed while the tracked local bound stays within the tolerance
/// (after Piegl & Tiller 1995). The result is clamped on the input's domain; rational
/// input is reduced in homogeneous coordinates.
///
/// Options used: `method`, `target` (`1 <= target < p`), `tolerance`, `continuity` (at
/// most `floor((target - 1) / 2)`: per-segment Hermite data need `2k + 1 <= target`;
/// default 0), `measure`.
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `opts` (in): the options. Borrowed for the call.
/// - `spline_out` (out): on `CAGD_OK`, the reduced spline of degree `target`, owned by the
///   caller: release with `cagd_bspline_free`.
/// - `report_out` (out): on `CAGD_OK`, the report (`cagd_report_bound`,
///   `cagd_report_max_error`, `cagd_report_spline`), owned by the caller: release with
///   `cagd_report_free`. Neither output is written on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `spline`, `opts`, `spline_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `opts->struct_size` below `sizeof(CagdReduceOptions)`,
///   an invalid method code or a method other than the two above, `tolerance` not finite
///   and `> 0`, the two outputs are the same address, or a pointer is misaligned.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target == 0` or `target >= p`.
/// - `CAGD_ERR_TOO_MANY_CONSTRAINTS`: `continuity > floor((target - 1) / 2)`.
/// - `CAGD_ERR_BAD_KNOTS`: an interior knot of multiplicity `p + 1` (the input may be
///   discontinuous there).
/// - `CAGD_ERR_CONDITION_NOT_MET`: a span cannot meet the tolerance (e.g. a tolerance
///   below the rounding level of the curve).
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
        let bopts = BSplineOptions {
            continuity: Some(o.continuity),
            strategy: BSplineStrategy::Segments(o.method()?),
            measure: o.measure,
            ..BSplineOptions::new(o.target, o.tolerance)
        };
        let red = reduce_bspline(&s.0, &bopts).map_err(spline_failure)?;
        let r = &red.report;
        let report = SplineReport {
            degree_from: r.degree_from,
            degree_to: r.degree_to,
            error_bound: r.error_bound,
            max_error: r.max_error,
            segment_bound: r.segment_bound,
            pieces: r.pieces,
            spans_in: red.spans_in,
            spans_out: red.spans_out,
        };
        *s_out = into_handle(CagdBSpline(red.curve));
        *r_out = into_handle(CagdReport {
            kind: ReportKind::Spline(report),
            method: o.method,
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
/// - `spline` (in): the spline, uniform knots (all gaps equal within `1e-12` relative).
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
///   interpolate the segment ends, the two outputs are the same address, or a pointer is
///   misaligned.
/// - `CAGD_ERR_BAD_KNOTS`: the knots are not uniform.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`, `CAGD_ERR_TOO_MANY_CONSTRAINTS`: as `cagd_curve_reduce`
///   for the pair `(n, target)`.
/// - `CAGD_ERR_CONDITION_NOT_MET`: the exact merge finds joints that do not meet.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a reduced weight of a NURBS is not positive.
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
            Some(spline_max_deviation(&s.0, &red.curve)?)
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
        };
        *s_out = into_handle(CagdBSpline(red.curve));
        *r_out = into_handle(CagdReport {
            kind: ReportKind::Spline(report),
            method: o.method,
        });
        Ok(())
    })
}

/// Reads what a B-spline reduction did: the largest certified bound of a reduced Bézier
/// segment (the reduction step alone, before merging and knot removal), the number of
/// reduced segments, and the non-empty knot spans of the input and of the result.
///
/// Parameters:
/// - `report` (in): the report.
/// - `segment_bound_out` (out): on `CAGD_OK`, the bound of the reduction step.
/// - `pieces_out` (out): on `CAGD_OK`, the number of reduced segments.
/// - `spans_in_out` (out): on `CAGD_OK`, the non-empty spans of the input.
/// - `spans_out_out` (out): on `CAGD_OK`, the non-empty spans of the result.
///
/// Returns:
/// - `CAGD_OK`: all outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: any argument is NULL.
/// - `CAGD_ERR_NOT_AVAILABLE`: the report is not of a B-spline reduction.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `report` must be NULL or a live report handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_spline(
    report: *const CagdReport,
    segment_bound_out: *mut f64,
    pieces_out: *mut usize,
    spans_in_out: *mut usize,
    spans_out_out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let r = unsafe { handle_ref(report, "report") }?;
        // SAFETY: as above.
        let (b, n, si, so) = unsafe {
            (
                out_ref(segment_bound_out, "segment_bound_out")?,
                out_ref(pieces_out, "pieces_out")?,
                out_ref(spans_in_out, "spans_in_out")?,
                out_ref(spans_out_out, "spans_out_out")?,
            )
        };
        let ReportKind::Spline(sr) = &r.kind else {
            return Err(Failure::new(
                CagdStatus::ERR_NOT_AVAILABLE,
                "not the report of a B-spline reduction",
            ));
        };
        (*b, *n, *si, *so) = (sr.segment_bound, sr.pieces, sr.spans_in, sr.spans_out);
        Ok(())
    })
}
