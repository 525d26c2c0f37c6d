//! The `CagdReport` accessors that only reports of B-spline reductions answer: the segment
//! bound and span counts (`cagd_bspline_reduce`, `cagd_bspline_reduce_uniform`), the
//! strategy and the continuity kept at the knots (`cagd_bspline_reduce`).

use crate::boundary::{
    CResult, Failure, OutNames, boundary, disjoint, handle_ref, out_ref, slice_out,
};
use crate::report::{CagdReport, ReportKind, SplineReport, StrategyReport};
use crate::status::CagdStatus;

/// The B-spline part of a report, or `CAGD_ERR_NOT_AVAILABLE`.
fn spline(r: &CagdReport) -> CResult<&SplineReport> {
    match &r.kind {
        ReportKind::Spline(sr) => Ok(sr),
        ReportKind::Single(_) | ReportKind::Piecewise { .. } | ReportKind::Patch { .. } => {
            Err(Failure::new(
                CagdStatus::ERR_NOT_AVAILABLE,
                "not the report of a B-spline reduction",
            ))
        }
    }
}

/// The `cagd_bspline_reduce` part of a report, or `CAGD_ERR_NOT_AVAILABLE`.
fn strategy(r: &CagdReport) -> CResult<&StrategyReport> {
    spline(r)?.strategy.as_ref().ok_or_else(|| {
        Failure::new(
            CagdStatus::ERR_NOT_AVAILABLE,
            "not the report of cagd_bspline_reduce (the uniform pipeline has no strategy)",
        )
    })
}

/// Reads what a B-spline reduction did: the largest certified bound of a piece of the
/// reduction step alone, before merging and knot removal (a reduced Bézier segment; for
/// `CAGD_SPLINE_FIT` a span of the fitted spline), the number of those pieces (after any
/// subdivision; for `CAGD_SPLINE_PIEGL_TILLER_1995` the result's spans), and the non-empty
/// knot spans of the input and of the result.
///
/// Parameters:
/// - `report` (in): the report.
/// - `segment_bound_out` (out): on `CAGD_OK`, the bound of the reduction step.
/// - `pieces_out` (out): on `CAGD_OK`, the number of pieces of the reduction step.
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
        let sr = spline(r)?;
        (*b, *n, *si, *so) = (sr.segment_bound, sr.pieces, sr.spans_in, sr.spans_out);
        Ok(())
    })
}

/// Reads the strategy of a `cagd_bspline_reduce` reduction.
///
/// Parameters:
/// - `report` (in): the report.
/// - `strategy_out` (out): on `CAGD_OK`, the `CagdSplineStrategy` code that was used.
///
/// Returns:
/// - `CAGD_OK`: `*strategy_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `report` or `strategy_out` is NULL.
/// - `CAGD_ERR_NOT_AVAILABLE`: the report is not of `cagd_bspline_reduce` (e.g. of
///   `cagd_bspline_reduce_uniform` or of a curve reduction).
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `report` must be NULL or a live report handle; `strategy_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_spline_strategy(
    report: *const CagdReport,
    strategy_out: *mut i32,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let r = unsafe { handle_ref(report, "report") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(strategy_out, "strategy_out") }?;
        *out = strategy(r)?.strategy as i32;
        Ok(())
    })
}

/// Names of the knot buffer of `cagd_report_spline_continuity`.
const KNOTS_OUT: OutNames = OutNames {
    out: "knots_out",
    cap: "out_cap",
    needed: "out_needed",
};

/// Names of the order buffer of `cagd_report_spline_continuity`.
const ORDERS_OUT: OutNames = OutNames {
    out: "orders_out",
    cap: "out_cap",
    needed: "out_needed",
};

/// Copies the continuity a `cagd_bspline_reduce` reduction guarantees: for each interior
/// knot of the input that is still a knot of the result, in increasing order, the knot
/// and the order `k` of the continuity `C^k` there (`min(spline_continuity, c)` where the
/// input is `C^c`, at most the strategy's maximum; the result's own continuity there,
/// `target - multiplicity`, is at least `k`: knot removal may have raised it). Input
/// knots the reduction removed are not listed (the result is a polynomial across them).
/// Call with `out_cap = 0` (and both buffers NULL) to ask the count.
///
/// Parameters:
/// - `report` (in): the report.
/// - `knots_out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `*out_needed` doubles hold the knots. May be NULL only when `out_cap == 0`.
/// - `orders_out` (out): buffer of `out_cap` `int32_t`; on `CAGD_OK` its first
///   `*out_needed` entries hold the orders (`orders_out[i]` belongs to `knots_out[i]`).
///   May be NULL only when `out_cap == 0`. Must not overlap `knots_out`.
/// - `out_cap` (in): capacity of each buffer, in entries (doubles for `knots_out`,
///   `int32_t` for `orders_out`).
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, the count.
///
/// Returns:
/// - `CAGD_OK`: the knots and orders are in the buffers (nothing when the count is 0).
/// - `CAGD_ERR_NULL_POINTER`: `report` or `out_needed` is NULL, or `knots_out` or
///   `orders_out` is NULL with `out_cap > 0`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is below the count; only `*out_needed` is
///   written.
/// - `CAGD_ERR_NOT_AVAILABLE`: the report is not of `cagd_bspline_reduce`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: the two buffers overlap, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `report` must be NULL or a live report handle; `knots_out` NULL or `out_cap` writable
/// doubles; `orders_out` NULL or `out_cap` writable `int32_t`; `out_needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_spline_continuity(
    report: *const CagdReport,
    knots_out: *mut f64,
    orders_out: *mut i32,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let r = unsafe { handle_ref(report, "report") }?;
        // SAFETY: as above.
        let knots = unsafe { slice_out(knots_out, out_cap, out_needed, &KNOTS_OUT) }?;
        // The count goes to `*out_needed` through `knots`; the same capacity gives the
        // same answer here.
        let mut count = 0usize;
        // SAFETY: as above; `count` is a local.
        let orders = unsafe { slice_out(orders_out, out_cap, &mut count, &ORDERS_OUT) }?;
        let list = &strategy(r)?.continuity;
        let ks = list
            .iter()
            .map(|&(_, k)| i32::try_from(k))
            .collect::<Result<Vec<i32>, _>>()
            .map_err(|_| Failure::invalid("a continuity order does not fit in int32_t"))?;
        let n = list.len().min(out_cap);
        disjoint(knots_out, n, orders_out, n, "`knots_out` and `orders_out`")?;
        let (kn, or) = (knots.take(list.len())?, orders.take(list.len())?);
        for (t, &(knot, _)) in kn.iter_mut().zip(list) {
            *t = knot;
        }
        or.copy_from_slice(&ks);
        Ok(())
    })
}
