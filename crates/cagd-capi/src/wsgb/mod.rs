//! `CagdWsgbCurve`: Wang–Said generalized Ball curves WSGB(n, L) of seed 003
//! (SPEC-reduce §9) — creation, read-back, evaluation, exact conversion to and from
//! `CagdCurve` (Bézier), elevation, leading coefficient and degeneracy. The reductions are in
//! `reduce.rs`, the pieces of a reduction to a tolerance in `list.rs`.
//!
//! Design: a separate handle type (not a basis flag on `CagdCurve`), because a WSGB curve
//! carries its order `L` and has its own algorithms (evaluation by peeling, the seed's
//! reductions); the Bézier operations apply through `cagd_wsgb_to_bezier`.

mod list;
mod list_copy;
mod reduce;

pub use list::{
    CagdWsgbCurveList, cagd_wsgb_reduce_to_tolerance, cagd_wsgblist_count, cagd_wsgblist_free,
    cagd_wsgblist_get,
};
pub use list_copy::{CagdWsgbListSizes, cagd_wsgblist_copy};
pub use reduce::{CagdWsgbMethod, CagdWsgbReport, cagd_wsgb_reduce};

use cagd_core::{WsgbCurve, check_finite_param};

use crate::boundary::{
    OUT, boundary, boundary_void, free_handle, handle_ref, into_handle, nonnull, out_ref,
    points_in, slice_out,
};
use crate::curve::CagdCurve;
use crate::status::CagdStatus;

/// Opaque handle to a WSGB(n, L) curve: `n + 1` control points of `dim` coordinates
/// (`0 <= n <= 64`, `dim >= 1`) and the order `0 <= L <= max(floor(n/2) - 1, 0)` (`L = 0`:
/// Said–Ball, `L = floor(n/2) - 1`: Wang–Ball). Polynomial only. Immutable; release with
/// `cagd_wsgb_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdWsgbCurve(pub(crate) WsgbCurve);

impl CagdWsgbCurve {
    /// The curve behind the handle (for Rust callers of this crate).
    pub fn as_wsgb(&self) -> &WsgbCurve {
        &self.0
    }
}

/// Creates a WSGB(n_points - 1, order) curve.
///
/// Parameters:
/// - `points` (in): `n_points * dim` doubles, row-major (`points[i * dim + k]`). Borrowed
///   and copied.
/// - `n_points` (in): number of control points, `1..=65`.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `order` (in): the order `L`, `0 <= L <= max(floor(n/2) - 1, 0)`.
/// - `curve_out` (out): on `CAGD_OK`, a new handle owned by the caller (release with
///   `cagd_wsgb_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*curve_out` holds the new curve.
/// - `CAGD_ERR_NULL_POINTER`: `points` or `curve_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, `order` out of range (the message gives it),
///   `n_points * dim` overflows, or a pointer is misaligned.
/// - `CAGD_ERR_NOT_ENOUGH_POINTS`: `n_points == 0`.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n_points > 65`.
/// - `CAGD_ERR_NON_FINITE`: a coordinate is NaN or infinite.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `points` must be NULL or point to `n_points * dim` readable doubles; `curve_out` NULL
/// or a writable `CagdWsgbCurve *`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_wsgb_new(
    points: *const f64,
    n_points: usize,
    dim: usize,
    order: usize,
    curve_out: *mut *mut CagdWsgbCurve,
) -> CagdStatus {
    boundary(|| {
        nonnull(points, "points")?;
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(curve_out, "curve_out") }?;
        // SAFETY: as above.
        let pts = unsafe { points_in(points, n_points, dim, "points") }?;
        let c = WsgbCurve::new(pts.to_vec(), dim, order)?;
        *out = into_handle(CagdWsgbCurve(c));
        Ok(())
    })
}

/// Releases a WSGB curve. NULL is accepted and ignored; a non-NULL handle must be released
/// exactly once. Does not change `cagd_last_error_message()`.
///
/// # Safety
/// `curve` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_wsgb_free(curve: *mut CagdWsgbCurve) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(curve) });
}

/// Reads the degree `n`, the order `L` and the dimension of a WSGB curve.
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `degree_out`, `order_out`, `dim_out` (out): on `CAGD_OK`, `n`, `L` and `dim`.
///
/// Returns:
/// - `CAGD_OK`: the three outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: an argument is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live WSGB handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_wsgb_shape(
    curve: *const CagdWsgbCurve,
    degree_out: *mut usize,
    order_out: *mut usize,
    dim_out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        nonnull(degree_out, "degree_out")?;
        nonnull(order_out, "order_out")?;
        nonnull(dim_out, "dim_out")?;
        // SAFETY: as above.
        let (d, o, k) = unsafe {
            (
                out_ref(degree_out, "degree_out")?,
                out_ref(order_out, "order_out")?,
                out_ref(dim_out, "dim_out")?,
            )
        };
        *d = c.0.degree();
        *o = c.0.order();
        *k = c.0.dim();
        Ok(())
    })
}

/// Copies the control points of a WSGB curve.
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `(n + 1) * dim`
///   doubles hold the points, row-major. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `(n + 1) * dim`.
///
/// Returns:
/// - `CAGD_OK`: the points are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is too small; only `*out_needed` is written.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live WSGB handle; `out` NULL or `out_cap` writable doubles;
/// `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_wsgb_points(
    curve: *const CagdWsgbCurve,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        dst.copy_from(c.0.points())
    })
}

/// Evaluates a WSGB curve at `u` by the WSGB peeling algorithm (SPEC-reduce §9.1;
/// `O(n dim)`, faster than de Casteljau on the Bézier form). `u` outside `[0, 1]`
/// extrapolates.
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `u` (in): the parameter, finite.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `dim` doubles hold
///   the point. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out`.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `dim`.
///
/// Returns:
/// - `CAGD_OK`: the point is in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `u` is NaN or infinite, or a pointer is misaligned.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < dim`; only `*out_needed` is written.
/// - `CAGD_ERR_NON_FINITE`: the point overflows f64 (`u` far outside `[0, 1]`, or
///   coordinates near the limits of f64); nothing is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live WSGB handle; `out` NULL or `out_cap` writable doubles;
/// `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_wsgb_eval(
    curve: *const CagdWsgbCurve,
    u: f64,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        check_finite_param("u", u)?;
        dst.fill_with(c.0.dim(), |p| c.0.eval_into(u, p))
    })
}

/// The same curve in Bézier form: exact conversion (SPEC-reduce §9.1), each point rounded
/// once.
///
/// Parameters:
/// - `curve` (in): the WSGB curve.
/// - `bezier_out` (out): on `CAGD_OK`, a new `CagdCurve` of the same degree, owned by the
///   caller (release with `cagd_curve_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*bezier_out` holds the curve.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `bezier_out` is NULL.
/// - `CAGD_ERR_NON_FINITE`: a converted coordinate overflows to infinity (inputs near the
///   largest double).
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live WSGB handle; `bezier_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_wsgb_to_bezier(
    curve: *const CagdWsgbCurve,
    bezier_out: *mut *mut CagdCurve,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(bezier_out, "bezier_out") }?;
        let b = c.0.to_bezier()?;
        *out = into_handle(CagdCurve(b));
        Ok(())
    })
}

/// The WSGB(n, `order`) form of a polynomial Bézier curve of degree `n` (exact conversion,
/// rounded once).
///
/// Parameters:
/// - `bezier` (in): a polynomial Bézier curve.
/// - `order` (in): the order `L` of the result, `0 <= L <= max(floor(n/2) - 1, 0)`.
/// - `curve_out` (out): on `CAGD_OK`, a new WSGB handle owned by the caller (release with
///   `cagd_wsgb_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*curve_out` holds the curve.
/// - `CAGD_ERR_NULL_POINTER`: `bezier` or `curve_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `order` out of range, or a pointer is misaligned.
/// - `CAGD_ERR_CONDITION_NOT_MET`: `bezier` is rational (WSGB curves are polynomial).
/// - `CAGD_ERR_NON_FINITE`: a converted coordinate overflows to infinity.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `bezier` must be NULL or a live curve handle; `curve_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_wsgb_from_bezier(
    bezier: *const CagdCurve,
    order: usize,
    curve_out: *mut *mut CagdWsgbCurve,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let b = unsafe { handle_ref(bezier, "bezier") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(curve_out, "curve_out") }?;
        let c = WsgbCurve::from_bezier(&b.0, order)?;
        *out = into_handle(CagdWsgbCurve(c));
        Ok(())
    })
}

/// Degree elevation WSGB(n, L) -> WSGB(n + 1, `order`), exact and rounded once.
///
/// Parameters:
/// - `curve` (in): the curve, degree `n <= 63`.
/// - `order` (in): the order of the result, `0 <= order <= max(floor((n+1)/2) - 1, 0)`.
/// - `curve_out` (out): on `CAGD_OK`, a new WSGB handle owned by the caller.
///
/// Returns:
/// - `CAGD_OK`: `*curve_out` holds the elevated curve.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `curve_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `order` out of range, or a pointer is misaligned.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n + 1 > 64`.
/// - `CAGD_ERR_NON_FINITE`: a coordinate overflows to infinity.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live WSGB handle; `curve_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_wsgb_elevate(
    curve: *const CagdWsgbCurve,
    order: usize,
    curve_out: *mut *mut CagdWsgbCurve,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(curve_out, "curve_out") }?;
        let e = c.0.elevate(order)?;
        *out = into_handle(CagdWsgbCurve(e));
        Ok(())
    })
}

/// The leading coefficient (coefficient of `u^n`, SPEC-reduce §9.2) and whether the curve
/// is exactly degenerate (of degree `< n`; tested in exact arithmetic on the stored
/// doubles; a degree-0 curve is not degenerate).
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `dim` doubles hold
///   the leading coefficient. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out`.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `dim`.
/// - `degenerate_out` (out): on `CAGD_OK`, whether the curve is degenerate.
///
/// Returns:
/// - `CAGD_OK`: the outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `curve`, `out_needed` or `degenerate_out` is NULL, or `out`
///   is NULL with `out_cap > 0`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < dim`; only `*out_needed` is written.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_NON_FINITE`: the coefficient overflows f64 (coordinates near the
///   limits of f64, high degree); nothing is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live WSGB handle; `out` NULL or `out_cap` writable doubles;
/// `out_needed` and `degenerate_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_wsgb_leading_coefficient(
    curve: *const CagdWsgbCurve,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
    degenerate_out: *mut bool,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        nonnull(degenerate_out, "degenerate_out")?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        // SAFETY: as above.
        let deg = unsafe { out_ref(degenerate_out, "degenerate_out") }?;
        dst.copy_from(&c.0.leading_coefficient())?;
        *deg = c.0.is_degenerate();
        Ok(())
    })
}
