//! WSGB reduction to a tolerance from C: `cagd_wsgb_reduce_to_tolerance` and the list of
//! reduced pieces `CagdWsgbCurveList`.

use cagd_reduce::{WsgbMethod, WsgbPiece, reduce_wsgb_to_tolerance};

use super::CagdWsgbCurve;
use crate::boundary::{
    Failure, boundary, boundary_void, free_handle, handle_ref, into_handle, nonnull, out_ref,
};
use crate::options::{CagdReduceOptions, read_options};
use crate::status::CagdStatus;

/// Opaque handle to the pieces of a WSGB reduction to a tolerance: piece `i` is a
/// WSGB(m, L') curve on `[0, 1]` approximating the original on `[a_i, b_i]`
/// (`piece_i(s) ~ whole(a_i + s (b_i - a_i))`) within its certified bound. Immutable;
/// release with `cagd_wsgblist_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdWsgbCurveList(pub(crate) Vec<WsgbPiece>);

/// Reduces a WSGB curve to degree `opts->target` so that every piece's certified
/// Euclidean error is at most `opts->tolerance`, splitting at parameter midpoints (at most 30
/// levels; `opts->max_depth` is not used). The pieces join continuously only when the method
/// interpolates the end points (perturbation for target `>= 2`, Bézier methods with ends);
/// the uniform method does not.
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `method` (in): a `CagdWsgbMethod` value.
/// - `opts` (in): `target`, `tolerance` and, for `CAGD_WSGB_BEZIER`, `method`, `r`, `p`,
///   `l1`, `l2`. Borrowed.
/// - `list_out` (out): on `CAGD_OK`, the pieces, owned by the caller (release with
///   `cagd_wsgblist_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*list_out` holds the pieces.
/// - `CAGD_ERR_NULL_POINTER`: `curve`, `opts` or `list_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `method` not a `CagdWsgbMethod`, `opts->tolerance` not
///   finite and `> 0`, `opts->struct_size` too small, an invalid Bézier method code, or a
///   pointer is misaligned.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`, `CAGD_ERR_TOO_MANY_CONSTRAINTS`: as `cagd_wsgb_reduce`.
/// - `CAGD_ERR_NO_CONVERGENCE`: the depth limit was reached before the tolerance.
/// - `CAGD_ERR_NON_FINITE`: a coordinate overflows to infinity.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live WSGB handle; `opts` NULL or a readable
/// `CagdReduceOptions` of `opts->struct_size` bytes; `list_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_wsgb_reduce_to_tolerance(
    curve: *const CagdWsgbCurve,
    method: i32,
    opts: *const CagdReduceOptions,
    list_out: *mut *mut CagdWsgbCurveList,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let o = unsafe { read_options(opts) }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(list_out, "list_out") }?;
        let method = match method {
            0 => WsgbMethod::Perturbation,
            1 => WsgbMethod::Uniform,
            2 => WsgbMethod::Bezier(o.method()?),
            other => {
                return Err(Failure::invalid(format!(
                    "method = {other} is not a CagdWsgbMethod (0, 1 or 2)"
                )));
            }
        };
        let red = reduce_wsgb_to_tolerance(&c.0, o.target, method, o.tolerance)?;
        *out = into_handle(CagdWsgbCurveList(red.pieces));
        Ok(())
    })
}

/// Releases a WSGB piece list (not the curves obtained from it). NULL is accepted and
/// ignored; a non-NULL handle must be released exactly once. Does not change
/// `cagd_last_error_message()`.
///
/// # Safety
/// `list` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_wsgblist_free(list: *mut CagdWsgbCurveList) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(list) });
}

/// Reads the number of pieces (`>= 1`).
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
pub unsafe extern "C" fn cagd_wsgblist_count(
    list: *const CagdWsgbCurveList,
    count_out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(count_out, "count_out") }?;
        *out = l.0.len();
        Ok(())
    })
}

/// Reads piece `index`: a new handle to its curve, its interval `[start, end]` and its
/// certified Euclidean error bound.
///
/// Parameters:
/// - `list` (in): the list.
/// - `index` (in): `0 <= index < count`.
/// - `curve_out` (out): on `CAGD_OK`, a new WSGB handle owned by the caller (release with
///   `cagd_wsgb_free`).
/// - `start_out`, `end_out`, `bound_out` (out): on `CAGD_OK`, the interval and the bound.
///
/// Returns:
/// - `CAGD_OK`: the outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: an argument is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `index >= count`, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_wsgblist_get(
    list: *const CagdWsgbCurveList,
    index: usize,
    curve_out: *mut *mut CagdWsgbCurve,
    start_out: *mut f64,
    end_out: *mut f64,
    bound_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        nonnull(curve_out, "curve_out")?;
        nonnull(start_out, "start_out")?;
        nonnull(end_out, "end_out")?;
        nonnull(bound_out, "bound_out")?;
        let p = l.0.get(index).ok_or_else(|| {
            Failure::invalid(format!(
                "index {index} is out of range: the list has {} pieces",
                l.0.len()
            ))
        })?;
        // SAFETY: as above; distinct output types, so no aliasing between them matters.
        let (c, s, e, b) = unsafe {
            (
                out_ref(curve_out, "curve_out")?,
                out_ref(start_out, "start_out")?,
                out_ref(end_out, "end_out")?,
                out_ref(bound_out, "bound_out")?,
            )
        };
        *s = p.start;
        *e = p.end;
        *b = p.error_bound;
        *c = into_handle(CagdWsgbCurve(p.reduction.curve.clone()));
        Ok(())
    })
}
