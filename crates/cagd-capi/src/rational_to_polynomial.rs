//! Rational → polynomial within a tolerance from C: a NURBS curve or tensor NURBS surface
//! to a polynomial B-spline of degree `<= m` whose certified distance to the input is
//! within the tolerance (cagd-reduce `rational_to_polynomial`,
//! `rational_surface_to_polynomial`; issue 16). The report is the B-spline report of
//! `cagd_bspline_reduce` (curves) or the patch report (surfaces).

use cagd_reduce::{PatchReport, rational_surface_to_polynomial, rational_to_polynomial};

use crate::boundary::{CResult, Failure, boundary, handle_ref, into_handle, nonnull, out_ref};
use crate::bspline::spline_failure;
use crate::report::{ReportKind, SplineReport, StrategyReport};
use crate::status::CagdStatus;
use crate::{CagdBSpline, CagdBSplineSurface, CagdReduceMethod, CagdReport, CagdSplineStrategy};

/// Checks and borrows the two outputs (distinct, non-NULL, aligned).
///
/// # Safety
/// Both pointers NULL or writable.
unsafe fn outputs<'a, T>(
    result_out: *mut *mut T,
    report_out: *mut *mut CagdReport,
    name: &str,
) -> CResult<(&'a mut *mut T, &'a mut *mut CagdReport)> {
    nonnull(result_out, name)?;
    nonnull(report_out, "report_out")?;
    if result_out.addr() == report_out.addr() {
        return Err(Failure::invalid(format!(
            "`{name}` and `report_out` are the same address"
        )));
    }
    // SAFETY: forwarded contract; the two outputs do not overlap.
    unsafe {
        Ok((
            out_ref(result_out, name)?,
            out_ref(report_out, "report_out")?,
        ))
    }
}

/// `0` → `None` (the input's degree), else `Some(m)`.
fn degree_or_input(m: usize) -> Option<usize> {
    (m > 0).then_some(m)
}

/// Converts a NURBS curve `C = A / W` of degree `p` to a polynomial B-spline of degree
/// `<= target` whose certified distance to `C` (`max_t |C(t) - S(t)|`, same parameter,
/// Euclidean, model space, rounding included — so also a bound of the geometric distance)
/// is `<= tolerance`, keeping `C^min(p - s, target - 1)` at every interior knot of the
/// input of multiplicity `s` (the input is `C^(p - s)` there). The method: the degree-
/// `target` spline on the input's breaks, the least-squares fit of `C` at Gauss nodes
/// (joints where the input is only `C^0` interpolated), a certified bound per span of
/// `|A - W S| / W` on Bézier pieces, refinement until every span is within the tolerance,
/// then certified knot removal. Weights all equal (or none) are recognised exactly: the
/// polynomial spline of the same control points is returned (its knots unchanged; its
/// bound the rounding level of evaluating the rational form beside it, `8 (p + 2) eps
/// sqrt(dim) max |x|`, or the measured distance if larger) when `target >= p`, reduced as
/// by `cagd_bspline_reduce` when `target < p`.
///
/// Parameters:
/// - `spline` (in): the curve (rational or not, clamped or not).
/// - `target` (in): the largest degree of the result, `1..=64` (may be above `p`: a conic
///   into cubics), or `0` for the input's degree `p`.
/// - `tolerance` (in): finite, `> 0`.
/// - `spline_out` (out): on `CAGD_OK`, the polynomial spline (no weights) on the input's
///   domain, owned by the caller: release with `cagd_bspline_free`.
/// - `report_out` (out): on `CAGD_OK`, the report, owned by the caller: release with
///   `cagd_report_free`. Neither output is written on failure. Accessors:
///   `cagd_report_bound` (the certified bound, `<= tolerance`), `cagd_report_max_error`
///   (the densely sampled distance, always measured), `cagd_report_spline` (the largest
///   span bound of the fit, its spans before knot removal, spans in and out),
///   `cagd_report_spline_continuity` (every interior break of the input with the order
///   guaranteed there), `cagd_report_spline_strategy` (`CAGD_SPLINE_FIT`),
///   `cagd_report_method` (`CAGD_METHOD_L2`).
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `spline`, `spline_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `tolerance` not finite and `> 0`; the two outputs are
///   the same address; a pointer is misaligned.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target > 64`.
/// - `CAGD_ERR_BAD_KNOTS`: an interior knot of multiplicity `p + 1` (the input may jump
///   there).
/// - `CAGD_ERR_CONDITION_NOT_MET`: the tolerance is below the rounding level of the curve
///   (weights all equal too: the same curve, whose bound is that rounding level, so that
///   `CAGD_OK` always means a bound `<= tolerance`) or needs more than `2^20` spans, or too much work (bounded work: more than `2^19`
///   spans fitted over the refinement rounds, a span counted `(p + target + 1)^2 / 16`
///   times (at least once) and in more than 3D `ceil((dim + 1) / 4)` times;
///   equal weights reduced below `p`: as `cagd_bspline_reduce`'s global fit).
/// - `CAGD_ERR_SINGULAR`: the least-squares system is rank-deficient (not expected).
/// - `CAGD_ERR_NON_FINITE`: the sampled error is not finite.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_to_polynomial(
    spline: *const CagdBSpline,
    target: usize,
    tolerance: f64,
    spline_out: *mut *mut CagdBSpline,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(spline, "spline") }?;
        // SAFETY: as above.
        let (s_out, r_out) = unsafe { outputs(spline_out, report_out, "spline_out") }?;
        let red = rational_to_polynomial(&s.0, degree_or_input(target), tolerance)
            .map_err(spline_failure)?;
        let r = &red.report;
        let report = SplineReport {
            degree_from: r.degree_from,
            degree_to: r.degree_to,
            error_bound: r.error_bound,
            max_error: Some(r.max_error),
            segment_bound: r.segment_bound,
            pieces: r.pieces,
            spans_in: red.spans_in,
            spans_out: red.spans_out,
            strategy: Some(StrategyReport {
                strategy: CagdSplineStrategy::SPLINE_FIT,
                continuity: r.continuity.clone(),
            }),
        };
        *s_out = into_handle(CagdBSpline(red.curve));
        *r_out = into_handle(CagdReport {
            kind: ReportKind::Spline(report),
            method: CagdReduceMethod::METHOD_L2 as i32,
        });
        Ok(())
    })
}

/// Converts a tensor NURBS surface of degrees `(p, q)` to a polynomial B-spline surface of
/// degrees `<= (target_u, target_v)` whose certified distance to the input (same
/// parameters, Euclidean, model space) is `<= tolerance`, keeping `C^min(p - s, m - 1)`
/// across every knot line of multiplicity `s`: the curve method of
/// `cagd_bspline_to_polynomial` on the tensor product (a separable least-squares fit on a
/// grid of Gauss nodes, a certified bound of `|A - W S| / W` per patch, refinement, knot
/// lines removed within the rest). Weights all equal (or none): the polynomial surface of
/// the same control points (bound at rounding level), reduced by the global fit of
/// `cagd_bsplinesurface_reduce_to_tolerance` where a target is below the input's degree.
///
/// Parameters:
/// - `surface` (in): the surface.
/// - `target_u`, `target_v` (in): the largest degrees, `1..=64`, or `0` for the input's.
/// - `tolerance` (in): finite, `> 0`.
/// - `surface_out` (out): on `CAGD_OK`, the polynomial surface (no weights), owned by the
///   caller: release with `cagd_bsplinesurface_free`.
/// - `report_out` (out): on `CAGD_OK`, the report (`cagd_report_bound`: the certified
///   bound; `cagd_report_max_error`: the measured distance (every cell
///   sampled, the 16 of largest sampled distance maximised locally); `cagd_report_patch`: patch method -1 and the patches of the result; `cagd_report_method`:
///   `CAGD_METHOD_L2`), owned by the caller: release with `cagd_report_free`. Neither
///   output is written on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `surface`, `surface_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `tolerance` not finite and `> 0`; the two outputs are
///   the same address; a pointer is misaligned.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: a target above 64.
/// - `CAGD_ERR_BAD_KNOTS`: a knot line of multiplicity `p + 1`.
/// - `CAGD_ERR_CONDITION_NOT_MET`: the tolerance cannot be reached (rounding level, or
///   more than `2^20` patches, or more than `2^17` patches fitted over the refinement
///   rounds: bounded work).
/// - `CAGD_ERR_SINGULAR`: the least-squares system is rank-deficient (not expected).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `surface` must be NULL or a live surface handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bsplinesurface_to_polynomial(
    surface: *const CagdBSplineSurface,
    target_u: usize,
    target_v: usize,
    tolerance: f64,
    surface_out: *mut *mut CagdBSplineSurface,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(surface, "surface") }?;
        // SAFETY: as above.
        let (s_out, r_out) = unsafe { outputs(surface_out, report_out, "surface_out") }?;
        let (p, q) = s.0.degrees();
        let m = (
            degree_or_input(target_u).unwrap_or(p),
            degree_or_input(target_v).unwrap_or(q),
        );
        let red =
            rational_surface_to_polynomial(&s.0, Some(m), tolerance).map_err(spline_failure)?;
        let report = PatchReport {
            method: "rational-to-polynomial",
            degrees_from: s.0.degrees(),
            degrees_to: red.surface.degrees(),
            error_bound: red.error_bound,
            max_error: Some(red.max_error),
        };
        *s_out = into_handle(CagdBSplineSurface(red.surface));
        *r_out = into_handle(CagdReport {
            kind: ReportKind::Patch {
                report,
                patch_method: -1,
                pieces: red.spans_out.0 * red.spans_out.1,
            },
            method: CagdReduceMethod::METHOD_L2 as i32,
        });
        Ok(())
    })
}
