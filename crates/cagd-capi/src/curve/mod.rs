//! `CagdCurve`: Bézier curves (polynomial or rational) — creation, read-back, release.
//! The operations (evaluation, elevation, subdivision) are in `ops.rs`, the piecewise result
//! `CagdCurveList` in `list.rs` (its one-call copy in `list_copy.rs`); the reductions are in
//! `reduce/`.

mod list;
mod list_copy;
mod ops;

pub use list::{
    CagdCurveList, cagd_curvelist_bound, cagd_curvelist_count, cagd_curvelist_free,
    cagd_curvelist_get, cagd_curvelist_interval,
};
pub use list_copy::{CagdCurveListSizes, cagd_curvelist_copy};
pub use ops::{
    cagd_curve_elevate, cagd_curve_eval, cagd_curve_eval_many, cagd_curve_segment,
    cagd_curve_subdivide,
};

pub(crate) use list::Piece;

use cagd_core::BezierCurve;

use crate::boundary::{
    OUT, boundary, boundary_void, free_handle, handle_ref, into_handle, nonnull, out_ref,
    points_in, slice_in, slice_out,
};
use crate::status::CagdStatus;

/// Opaque handle to a Bézier curve of degree `n` (`n + 1` control points of `dim`
/// coordinates, `0 <= n <= 64`, `dim >= 1`), polynomial or rational (Euclidean points plus
/// positive weights). Immutable once created; release with `cagd_curve_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdCurve(pub(crate) BezierCurve);

impl CagdCurve {
    /// The curve behind the handle (for Rust callers of this crate).
    pub fn as_bezier(&self) -> &BezierCurve {
        &self.0
    }
}

/// Creates a polynomial Bézier curve of degree `n_points - 1`.
///
/// Parameters:
/// - `points` (in): `n_points * dim` doubles, row-major: coordinate k of control point i
///   at `points[i * dim + k]`. Borrowed for the call and copied.
/// - `n_points` (in): number of control points, `1..=65` (degree `0..=64`).
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `curve_out` (out): on `CAGD_OK`, a new handle owned by the caller, to be released
///   with `cagd_curve_free` exactly once. Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*curve_out` holds the new curve.
/// - `CAGD_ERR_NULL_POINTER`: `points` or `curve_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, `n_points * dim` overflows, or a pointer is
///   misaligned.
/// - `CAGD_ERR_NOT_ENOUGH_POINTS`: `n_points == 0`.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n_points > 65`.
/// - `CAGD_ERR_NON_FINITE`: a coordinate is NaN or infinite (the message gives i, k).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `points` must be NULL or point to `n_points * dim` readable doubles; `curve_out` must be
/// NULL or point to a writable `CagdCurve *`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_new(
    points: *const f64,
    n_points: usize,
    dim: usize,
    curve_out: *mut *mut CagdCurve,
) -> CagdStatus {
    boundary(|| {
        nonnull(points, "points")?;
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(curve_out, "curve_out") }?;
        // SAFETY: as above.
        let pts = unsafe { points_in(points, n_points, dim, "points") }?;
        let curve = BezierCurve::new(pts.to_vec(), dim)?;
        *out = into_handle(CagdCurve(curve));
        Ok(())
    })
}

/// Creates a rational Bézier curve of degree `n_points - 1` from Euclidean control points
/// and weights: `C(t) = sum_i B_i(t) w_i P_i / sum_i B_i(t) w_i`.
///
/// Parameters:
/// - `points` (in): `n_points * dim` doubles, row-major (`points[i * dim + k]`), Euclidean
///   (not multiplied by the weights). Borrowed and copied.
/// - `weights` (in): `n_points` doubles, each finite and `>= DBL_MIN` (positive, not subnormal). Borrowed and copied.
/// - `n_points` (in): number of control points, `1..=65`.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `curve_out` (out): on `CAGD_OK`, a new handle owned by the caller (release with
///   `cagd_curve_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*curve_out` holds the new curve.
/// - `CAGD_ERR_NULL_POINTER`: `points`, `weights` or `curve_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, `n_points * dim` overflows, or a pointer is
///   misaligned.
/// - `CAGD_ERR_NOT_ENOUGH_POINTS`: `n_points == 0`.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n_points > 65`.
/// - `CAGD_ERR_NON_FINITE`: a coordinate is NaN or infinite.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a weight is `<= 0`, subnormal, NaN or infinite (the message gives
///   its index and value).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `points` must be NULL or point to `n_points * dim` readable doubles, `weights` NULL or
/// `n_points` readable doubles; `curve_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_new_rational(
    points: *const f64,
    weights: *const f64,
    n_points: usize,
    dim: usize,
    curve_out: *mut *mut CagdCurve,
) -> CagdStatus {
    boundary(|| {
        nonnull(points, "points")?;
        nonnull(weights, "weights")?;
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(curve_out, "curve_out") }?;
        // SAFETY: as above.
        let pts = unsafe { points_in(points, n_points, dim, "points") }?;
        // SAFETY: as above.
        let w = unsafe { slice_in(weights, n_points, "weights") }?;
        let curve = BezierCurve::new_rational(pts.to_vec(), w.to_vec(), dim)?;
        *out = into_handle(CagdCurve(curve));
        Ok(())
    })
}

/// Releases a curve. NULL is accepted and ignored, so freeing NULL twice is fine; a
/// non-NULL handle must be released exactly once and not used afterwards.
///
/// Parameters:
/// - `curve` (in, consumed): a handle from `cagd_curve_new*` or a `CagdCurve **` output of
///   another function, or NULL.
///
/// Does not change `cagd_last_error_message()`.
///
/// # Safety
/// `curve` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_free(curve: *mut CagdCurve) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(curve) });
}

/// Reads the degree `n` of a curve (its number of control points minus one, `0..=64`).
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `degree_out` (out): on `CAGD_OK`, the degree.
///
/// Returns:
/// - `CAGD_OK`: `*degree_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `degree_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `degree_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_degree(
    curve: *const CagdCurve,
    degree_out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        *unsafe { out_ref(degree_out, "degree_out") }? = c.0.degree();
        Ok(())
    })
}

/// Reads the number of coordinates per point of a curve (`>= 1`).
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `dim_out` (out): on `CAGD_OK`, the dimension.
///
/// Returns:
/// - `CAGD_OK`: `*dim_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `dim_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `dim_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_dim(
    curve: *const CagdCurve,
    dim_out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        *unsafe { out_ref(dim_out, "dim_out") }? = c.0.dim();
        Ok(())
    })
}

/// Tells whether a curve is rational (was created with weights).
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `rational_out` (out): on `CAGD_OK`, `true` for a rational curve.
///
/// Returns:
/// - `CAGD_OK`: `*rational_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `rational_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `rational_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_is_rational(
    curve: *const CagdCurve,
    rational_out: *mut bool,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        *unsafe { out_ref(rational_out, "rational_out") }? = c.0.is_rational();
        Ok(())
    })
}

/// Copies the control points of a curve, row-major, Euclidean (for a rational curve, not
/// multiplied by the weights). Call with `out_cap = 0` (and `out` NULL) to ask the size.
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `(degree + 1) * dim` doubles hold the points (`out[i * dim + k]`), the rest is
///   untouched. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `(degree + 1) * dim`.
///
/// Returns:
/// - `CAGD_OK`: the points are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < (degree + 1) * dim`; only `*out_needed` is
///   written.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `out` NULL or `out_cap` writable doubles;
/// `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_points(
    curve: *const CagdCurve,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        unsafe { slice_out(out, out_cap, out_needed, &OUT) }?.copy_from(c.0.points())
    })
}

/// Copies the weights of a curve; a polynomial curve reports `degree + 1` weights equal to
/// 1.0 (the same curve as a rational one), so callers that treat every curve as rational
/// need no special case. Call with `out_cap = 0` (and `out` NULL) to ask the size.
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `degree + 1`
///   doubles hold `w_0 .. w_n`. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `degree + 1`.
///
/// Returns:
/// - `CAGD_OK`: the weights are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < degree + 1`; only `*out_needed` is written.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `out` NULL or `out_cap` writable doubles;
/// `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_weights(
    curve: *const CagdCurve,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        match c.0.weights() {
            Some(w) => dst.copy_from(w),
            None => {
                dst.take(c.0.degree() + 1)?.fill(1.0);
                Ok(())
            }
        }
    })
}
