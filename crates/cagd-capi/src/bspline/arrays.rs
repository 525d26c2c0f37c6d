//! Read-back of the arrays of a `CagdBSpline`: knots, control points, weights.

use crate::boundary::{CResult, OUT, boundary, handle_ref, slice_out};
use crate::bspline::CagdBSpline;
use crate::status::CagdStatus;

/// Which array of a spline to copy.
#[derive(Clone, Copy)]
enum Part {
    Knots,
    Points,
    Weights,
}

/// Copies one array of a spline into a caller buffer (size query with capacity 0).
///
/// # Safety
/// As the entry points below.
unsafe fn copy_part(
    spline: *const CagdBSpline,
    part: Part,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CResult<()> {
    // SAFETY: forwarded contract.
    let s = unsafe { handle_ref(spline, "spline") }?;
    // SAFETY: as above.
    let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
    match (part, s.0.weights()) {
        (Part::Knots, _) => dst.copy_from(s.0.knots()),
        (Part::Points, _) => dst.copy_from(s.0.points()),
        (Part::Weights, Some(w)) => dst.copy_from(w),
        (Part::Weights, None) => {
            dst.take(s.0.n_points())?.fill(1.0);
            Ok(())
        }
    }
}

/// Copies the knot vector of a spline (`n_points + degree + 1` doubles, non-decreasing).
/// Call with `out_cap = 0` (and `out` NULL) to ask the size.
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `n_points + degree + 1` doubles hold the knots. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `n_points + degree + 1`.
///
/// Returns:
/// - `CAGD_OK`: the knots are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is below the count; only `*out_needed` is
///   written.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `out` NULL or `out_cap` writable
/// doubles; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_knots(
    spline: *const CagdBSpline,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    // SAFETY: the caller's contract (see # Safety).
    boundary(|| unsafe { copy_part(spline, Part::Knots, out, out_cap, out_needed) })
}

/// Copies the control points of a spline, row-major, Euclidean (for a NURBS curve, not
/// multiplied by the weights). Call with `out_cap = 0` (and `out` NULL) to ask the size.
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `n_points * dim`
///   doubles hold the points (`out[i * dim + k]`). May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `n_points * dim`.
///
/// Returns:
/// - `CAGD_OK`: the points are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < n_points * dim`; only `*out_needed` is
///   written.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `out` NULL or `out_cap` writable
/// doubles; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_points(
    spline: *const CagdBSpline,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    // SAFETY: the caller's contract (see # Safety).
    boundary(|| unsafe { copy_part(spline, Part::Points, out, out_cap, out_needed) })
}

/// Copies the weights of a spline; a polynomial spline reports `n_points` weights equal
/// to 1.0 (the same curve as a NURBS one). Call with `out_cap = 0` (and `out` NULL) to
/// ask the size.
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `n_points` doubles
///   hold the weights. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `n_points`.
///
/// Returns:
/// - `CAGD_OK`: the weights are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < n_points`; only `*out_needed` is written.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `out` NULL or `out_cap` writable
/// doubles; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_weights(
    spline: *const CagdBSpline,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    // SAFETY: the caller's contract (see # Safety).
    boundary(|| unsafe { copy_part(spline, Part::Weights, out, out_cap, out_needed) })
}
