//! The `CagdReport` accessors that only reports of piecewise reductions (to a tolerance)
//! answer: the piece count and depth, the pieces, the per-step bounds.

use crate::boundary::{
    CResult, Failure, OUT, boundary, handle_ref, into_handle, out_ref, slice_out,
};
use crate::curve::{CagdCurveList, Piece};
use crate::report::{CagdReport, ReportKind};
use crate::status::CagdStatus;

/// The piecewise parts of a report, or `CAGD_ERR_NOT_AVAILABLE`.
fn piecewise(
    r: &CagdReport,
) -> CResult<(&cagd_reduce::PiecewiseReport, &[cagd_reduce::ReducedPiece])> {
    match &r.kind {
        ReportKind::Piecewise { report, pieces } => Ok((report, pieces)),
        ReportKind::Single(_) | ReportKind::Patch { .. } | ReportKind::Spline(_) => {
            Err(Failure::new(
                CagdStatus::ERR_NOT_AVAILABLE,
                "not the report of a curve reduction to a tolerance",
            ))
        }
    }
}

/// Reads the shape of a piecewise reduction (to a tolerance): the number of pieces, the
/// depth of the shortest piece (`ceil(-log2(length))`, the midpoint-subdivision level a
/// dyadic split would need for it; 0: the curve was not split), the continuity
/// order `k` of the joins, and the largest certified bound of a single piece (the bound
/// of the whole, `cagd_report_bound`, adds what merging into the spline moved).
///
/// Parameters:
/// - `report` (in): the report.
/// - `n_pieces_out` (out): on `CAGD_OK`, the number of pieces (`>= 1`).
/// - `depth_out` (out): on `CAGD_OK`, the deepest subdivision level.
/// - `continuity_out` (out): on `CAGD_OK`, the order `k` of the `C^k` joins.
/// - `pieces_bound_out` (out): on `CAGD_OK`, the largest bound of a piece.
///
/// Returns:
/// - `CAGD_OK`: all outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: any argument is NULL.
/// - `CAGD_ERR_NOT_AVAILABLE`: the report is not of a curve reduction to a tolerance.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `report` must be NULL or a live report handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_piecewise(
    report: *const CagdReport,
    n_pieces_out: *mut usize,
    depth_out: *mut usize,
    continuity_out: *mut usize,
    pieces_bound_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let r = unsafe { handle_ref(report, "report") }?;
        // SAFETY: as above.
        let (n, d, k, b) = unsafe {
            (
                out_ref(n_pieces_out, "n_pieces_out")?,
                out_ref(depth_out, "depth_out")?,
                out_ref(continuity_out, "continuity_out")?,
                out_ref(pieces_bound_out, "pieces_bound_out")?,
            )
        };
        let (pr, _) = piecewise(r)?;
        (*n, *d, *k, *b) = (pr.pieces, pr.depth, pr.continuity, pr.pieces_bound);
        Ok(())
    })
}

/// Copies the reduced pieces of a piecewise reduction, before they were merged into the
/// spline: piece `i` approximates the source curve on its interval
/// (`cagd_curvelist_interval`, in `[0, 1]`) within its certified bound
/// (`cagd_curvelist_bound`).
///
/// Parameters:
/// - `report` (in): the report.
/// - `list_out` (out): on `CAGD_OK`, a new list owned by the caller: release with
///   `cagd_curvelist_free`. Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*list_out` holds the pieces.
/// - `CAGD_ERR_NULL_POINTER`: `report` or `list_out` is NULL.
/// - `CAGD_ERR_NOT_AVAILABLE`: the report is not of a curve reduction to a tolerance.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `report` must be NULL or a live report handle; `list_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_pieces(
    report: *const CagdReport,
    list_out: *mut *mut CagdCurveList,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let r = unsafe { handle_ref(report, "report") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(list_out, "list_out") }?;
        let (_, pieces) = piecewise(r)?;
        let list = pieces
            .iter()
            .map(|p| Piece {
                start: p.start,
                end: p.end,
                curve: p.curve.clone(),
                bound: Some(p.error_bound),
            })
            .collect();
        *out = into_handle(CagdCurveList(list));
        Ok(())
    })
}

/// Copies the per-step bounds of `cagd_curve_reduce_to_tolerance_stepwise`: the largest
/// bound of each one-degree step, `n -> n-1` first (`n - target` doubles; their sum is the
/// seed's certified total). Empty (`*out_needed = 0`) for
/// `cagd_curve_reduce_to_tolerance`. Call with `out_cap = 0` (and `out` NULL) to ask the
/// size.
///
/// Parameters:
/// - `report` (in): the report.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `*out_needed`
///   doubles hold the bounds. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, the count.
///
/// Returns:
/// - `CAGD_OK`: the bounds are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `report` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is below the count; only `*out_needed` is
///   written.
/// - `CAGD_ERR_NOT_AVAILABLE`: the report is not of a curve reduction to a tolerance.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `report` must be NULL or a live report handle; `out` NULL or `out_cap` writable
/// doubles; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_step_bounds(
    report: *const CagdReport,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let r = unsafe { handle_ref(report, "report") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let (pr, _) = piecewise(r)?;
        dst.copy_from(&pr.step_bounds)
    })
}
