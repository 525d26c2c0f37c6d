//! `CagdCurveList`: a piecewise result — Bézier pieces with their parameter intervals
//! (and, for reductions, their certified error bounds).

use cagd_core::BezierCurve;

use crate::boundary::{
    CResult, Failure, boundary, boundary_void, free_handle, handle_ref, into_handle, out_ref,
};
use crate::curve::CagdCurve;
use crate::status::CagdStatus;

/// One piece of a `CagdCurveList`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Piece {
    /// Start of the piece's parameter interval in the parameter of the whole.
    pub(crate) start: f64,
    /// End of the interval (`> start`).
    pub(crate) end: f64,
    /// The piece, parametrised on `[0, 1]`.
    pub(crate) curve: BezierCurve,
    /// The certified error bound of the piece, for pieces made by a reduction.
    pub(crate) bound: Option<f64>,
}

/// Opaque handle to an ordered list of Bézier curves, each the piece of a whole on a
/// parameter interval `[a_i, b_i]` (`piece_i(s) = whole(a_i + s (b_i - a_i))`,
/// `s` in `[0, 1]`), made by `cagd_bspline_to_beziers` or a piecewise reduction.
/// Immutable; release with `cagd_curvelist_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdCurveList(pub(crate) Vec<Piece>);

/// The piece `i`, or `CAGD_ERR_INVALID_ARGUMENT` when `i >= count`.
fn piece(list: &CagdCurveList, i: usize) -> CResult<&Piece> {
    list.0.get(i).ok_or_else(|| {
        Failure::invalid(format!(
            "index {i} is out of range: the list has {} pieces",
            list.0.len()
        ))
    })
}

/// Releases a curve list (not the curves obtained from it with `cagd_curvelist_get`,
/// which are independent handles). NULL is accepted and ignored; a non-NULL handle must be
/// released exactly once and not used afterwards.
///
/// Parameters:
/// - `list` (in, consumed): a `CagdCurveList **` output of a cagd function, or NULL.
///
/// Does not change `cagd_last_error_message()`.
///
/// # Safety
/// `list` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curvelist_free(list: *mut CagdCurveList) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(list) });
}

/// Reads the number of pieces of a list (`>= 1` for lists made by cagd).
///
/// Parameters:
/// - `list` (in): the list.
/// - `count_out` (out): on `CAGD_OK`, the number of pieces.
///
/// Returns:
/// - `CAGD_OK`: `*count_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `list` or `count_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; `count_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curvelist_count(
    list: *const CagdCurveList,
    count_out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        *unsafe { out_ref(count_out, "count_out") }? = l.0.len();
        Ok(())
    })
}

/// Copies piece `i` of a list into a new curve handle (parametrised on `[0, 1]`;
/// rational when the whole is).
///
/// Parameters:
/// - `list` (in): the list.
/// - `i` (in): the piece index, `0 <= i < count`, in parameter order.
/// - `curve_out` (out): on `CAGD_OK`, a new curve handle owned by the caller, independent
///   of the list: release it with `cagd_curve_free` (before or after the list). Not
///   written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*curve_out` holds the piece.
/// - `CAGD_ERR_NULL_POINTER`: `list` or `curve_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `i >= count`, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; `curve_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curvelist_get(
    list: *const CagdCurveList,
    i: usize,
    curve_out: *mut *mut CagdCurve,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(curve_out, "curve_out") }?;
        *out = into_handle(CagdCurve(piece(l, i)?.curve.clone()));
        Ok(())
    })
}

/// Reads the parameter interval `[a, b]` of piece `i` in the parameter of the whole (the
/// spline's knots for `cagd_bspline_to_beziers`, `[0, 1]` of the source curve for a
/// piecewise reduction).
///
/// Parameters:
/// - `list` (in): the list.
/// - `i` (in): the piece index, `0 <= i < count`.
/// - `a_out` (out): on `CAGD_OK`, the start of the interval.
/// - `b_out` (out): on `CAGD_OK`, the end of the interval (`> a`).
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `list`, `a_out` or `b_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `i >= count`, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curvelist_interval(
    list: *const CagdCurveList,
    i: usize,
    a_out: *mut f64,
    b_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let (a, b) = unsafe { (out_ref(a_out, "a_out")?, out_ref(b_out, "b_out")?) };
        let p = piece(l, i)?;
        (*a, *b) = (p.start, p.end);
        Ok(())
    })
}

/// Reads the certified error bound of piece `i` of a piecewise reduction (Euclidean,
/// model units: the piece is within this distance of the source on its interval).
///
/// Parameters:
/// - `list` (in): the list.
/// - `i` (in): the piece index, `0 <= i < count`.
/// - `bound_out` (out): on `CAGD_OK`, the bound (finite, `>= 0`).
///
/// Returns:
/// - `CAGD_OK`: `*bound_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `list` or `bound_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `i >= count`, or a pointer is misaligned.
/// - `CAGD_ERR_NOT_AVAILABLE`: the list is not the result of a reduction (e.g. from
///   `cagd_bspline_to_beziers`, whose pieces are exact).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; `bound_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curvelist_bound(
    list: *const CagdCurveList,
    i: usize,
    bound_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(bound_out, "bound_out") }?;
        *out = piece(l, i)?.bound.ok_or_else(|| {
            Failure::new(
                CagdStatus::ERR_NOT_AVAILABLE,
                "the pieces of this list are exact (not made by a reduction): no bound",
            )
        })?;
        Ok(())
    })
}
