//! `CagdBSpline`: B-spline and NURBS curves — creation, scalar read-back, release. The
//! arrays are read back in `arrays.rs`; the operations (evaluation, derivatives, knot
//! insertion, Bézier extraction) are in `ops.rs`, the merge of Bézier segments in `merge.rs`,
//! the reductions in `reduce.rs`, and the surface handle `CagdBSplineSurface` in
//! `surface.rs`.

mod arrays;
mod copy;
mod merge;
mod ops;
mod reduce;
mod surface;

pub use arrays::{cagd_bspline_knots, cagd_bspline_points, cagd_bspline_weights};
pub use copy::{CagdBSplineSizes, cagd_bspline_copy};
pub use merge::cagd_bspline_from_beziers;
pub use ops::{
    cagd_bspline_derivatives, cagd_bspline_eval, cagd_bspline_insert_knot, cagd_bspline_to_beziers,
};
pub use reduce::{cagd_bspline_reduce, cagd_bspline_reduce_uniform};
pub use surface::{
    CagdBSplineSurface, cagd_bsplinesurface_array, cagd_bsplinesurface_eval,
    cagd_bsplinesurface_free, cagd_bsplinesurface_new, cagd_bsplinesurface_reduce,
    cagd_bsplinesurface_reduce_to_tolerance, cagd_bsplinesurface_shape,
};

use cagd_core::{BSplineCurve, Error};

use crate::boundary::{
    CResult, Failure, boundary, boundary_void, free_handle, handle_ref, into_handle, nonnull,
    out_ref, points_in, slice_in,
};
use crate::status::CagdStatus;

/// Opaque handle to a B-spline curve of degree `p` (`0..=64`) with `n_points >= p + 1`
/// control points of `dim >= 1` coordinates and a full knot vector of
/// `n_points + p + 1` non-decreasing knots (clamped or not; the domain is
/// `[knots[p], knots[n_points]]`), polynomial or NURBS (Euclidean points plus positive
/// weights). Immutable once created; release with `cagd_bspline_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdBSpline(pub(crate) BSplineCurve);

impl CagdBSpline {
    /// The spline behind the handle (for Rust callers of this crate).
    pub fn as_bspline(&self) -> &BSplineCurve {
        &self.0
    }
}

/// The failure of a spline constructor: an empty domain (`knots[p] == knots[n_points]`)
/// is a knot-vector error in C (`CAGD_ERR_BAD_KNOTS`), not a generic bad parameter.
pub(crate) fn spline_failure(e: Error) -> Failure {
    match e {
        Error::BadParameter { name: "knots", .. } => {
            Failure::new(CagdStatus::ERR_BAD_KNOTS, e.to_string())
        }
        other => other.into(),
    }
}

/// Creates a polynomial B-spline curve
/// `C(t) = sum_i N_{i,degree}(t) P_i`, `t` in `[knots[degree], knots[n_points]]`.
///
/// Parameters:
/// - `degree` (in): the degree `p`, `0..=64`.
/// - `knots` (in): `n_knots` doubles, non-decreasing, finite, each value at most
///   `degree + 1` times, with `knots[degree] < knots[n_points]`. Borrowed and copied.
/// - `n_knots` (in): must equal `n_points + degree + 1` (checked, not assumed).
/// - `points` (in): `n_points * dim` doubles, row-major: coordinate k of control point i
///   at `points[i * dim + k]`. Borrowed and copied.
/// - `n_points` (in): number of control points, `>= degree + 1`.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `spline_out` (out): on `CAGD_OK`, a new handle owned by the caller, to be released
///   with `cagd_bspline_free` exactly once. Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*spline_out` holds the new spline.
/// - `CAGD_ERR_NULL_POINTER`: `knots`, `points` or `spline_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, `n_points * dim` overflows, or a pointer is
///   misaligned.
/// - `CAGD_ERR_NOT_ENOUGH_POINTS`: `n_points == 0` or `n_points < degree + 1`.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `degree > 64`.
/// - `CAGD_ERR_NON_FINITE`: a coordinate or a knot is NaN or infinite.
/// - `CAGD_ERR_BAD_KNOTS`: `n_knots != n_points + degree + 1`, the knots decrease
///   somewhere (the message gives the index), or the domain is empty.
/// - `CAGD_ERR_MULTIPLICITY`: a knot value appears more than `degree + 1` times.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `knots` must be NULL or point to `n_knots` readable doubles, `points` NULL or
/// `n_points * dim` readable doubles; `spline_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_new(
    degree: usize,
    knots: *const f64,
    n_knots: usize,
    points: *const f64,
    n_points: usize,
    dim: usize,
    spline_out: *mut *mut CagdBSpline,
) -> CagdStatus {
    boundary(|| {
        nonnull(knots, "knots")?;
        nonnull(points, "points")?;
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(spline_out, "spline_out") }?;
        // SAFETY: as above.
        let pts = unsafe { points_in(points, n_points, dim, "points") }?;
        // SAFETY: as above.
        let u = unsafe { slice_in(knots, n_knots, "knots") }?;
        let s = BSplineCurve::new(degree, u.to_vec(), pts.to_vec(), dim).map_err(spline_failure)?;
        *out = into_handle(CagdBSpline(s));
        Ok(())
    })
}

/// Creates a NURBS curve from Euclidean control points and weights:
/// `C(t) = sum_i N_{i,p}(t) w_i P_i / sum_i N_{i,p}(t) w_i`.
///
/// Parameters:
/// - `degree` (in): the degree `p`, `0..=64`.
/// - `knots` (in): `n_knots` doubles, as in `cagd_bspline_new`. Borrowed and copied.
/// - `n_knots` (in): must equal `n_points + degree + 1`.
/// - `points` (in): `n_points * dim` doubles, row-major, Euclidean (not multiplied by the
///   weights). Borrowed and copied.
/// - `weights` (in): `n_points` doubles, each finite and `>= DBL_MIN` (positive, not subnormal). Borrowed and copied.
/// - `n_points` (in): number of control points, `>= degree + 1`.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `spline_out` (out): on `CAGD_OK`, a new handle owned by the caller (release with
///   `cagd_bspline_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*spline_out` holds the new spline.
/// - `CAGD_ERR_NULL_POINTER`: `knots`, `points`, `weights` or `spline_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, `n_points * dim` overflows, or a pointer is
///   misaligned.
/// - `CAGD_ERR_NOT_ENOUGH_POINTS`: `n_points == 0` or `n_points < degree + 1`.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `degree > 64`.
/// - `CAGD_ERR_NON_FINITE`: a coordinate or a knot is NaN or infinite.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a weight is `<= 0`, subnormal, NaN or infinite (the message
///   gives its index and value).
/// - `CAGD_ERR_BAD_KNOTS`: wrong `n_knots`, decreasing knots, or an empty domain.
/// - `CAGD_ERR_MULTIPLICITY`: a knot value appears more than `degree + 1` times.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `knots` must be NULL or point to `n_knots` readable doubles, `points` NULL or
/// `n_points * dim` readable doubles, `weights` NULL or `n_points` readable doubles;
/// `spline_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_new_rational(
    degree: usize,
    knots: *const f64,
    n_knots: usize,
    points: *const f64,
    weights: *const f64,
    n_points: usize,
    dim: usize,
    spline_out: *mut *mut CagdBSpline,
) -> CagdStatus {
    boundary(|| {
        nonnull(knots, "knots")?;
        nonnull(points, "points")?;
        nonnull(weights, "weights")?;
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(spline_out, "spline_out") }?;
        // SAFETY: as above.
        let pts = unsafe { points_in(points, n_points, dim, "points") }?;
        // SAFETY: as above.
        let u = unsafe { slice_in(knots, n_knots, "knots") }?;
        // SAFETY: as above.
        let w = unsafe { slice_in(weights, n_points, "weights") }?;
        let s = BSplineCurve::new_rational(degree, u.to_vec(), pts.to_vec(), w.to_vec(), dim)
            .map_err(spline_failure)?;
        *out = into_handle(CagdBSpline(s));
        Ok(())
    })
}

/// Releases a spline. NULL is accepted and ignored, so freeing NULL twice is fine; a
/// non-NULL handle must be released exactly once and not used afterwards.
///
/// Parameters:
/// - `spline` (in, consumed): a handle from `cagd_bspline_new*` or a `CagdBSpline **`
///   output of another function, or NULL.
///
/// Does not change `cagd_last_error_message()`.
///
/// # Safety
/// `spline` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_free(spline: *mut CagdBSpline) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(spline) });
}

/// Reads one scalar of a spline into an out-pointer.
///
/// # Safety
/// As the entry points below.
unsafe fn read_scalar<T>(
    spline: *const CagdBSpline,
    out: *mut T,
    name: &str,
    f: impl FnOnce(&BSplineCurve) -> T,
) -> CResult<()> {
    // SAFETY: forwarded contract.
    let s = unsafe { handle_ref(spline, "spline") }?;
    // SAFETY: as above.
    *unsafe { out_ref(out, name) }? = f(&s.0);
    Ok(())
}

/// Reads the degree `p` of a spline (`0..=64`).
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `degree_out` (out): on `CAGD_OK`, the degree.
///
/// Returns:
/// - `CAGD_OK`: `*degree_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `degree_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `degree_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_degree(
    spline: *const CagdBSpline,
    degree_out: *mut usize,
) -> CagdStatus {
    // SAFETY: the caller's contract (see # Safety).
    boundary(|| unsafe { read_scalar(spline, degree_out, "degree_out", BSplineCurve::degree) })
}

/// Reads the number of coordinates per point of a spline (`>= 1`).
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `dim_out` (out): on `CAGD_OK`, the dimension.
///
/// Returns:
/// - `CAGD_OK`: `*dim_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `dim_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `dim_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_dim(
    spline: *const CagdBSpline,
    dim_out: *mut usize,
) -> CagdStatus {
    // SAFETY: the caller's contract (see # Safety).
    boundary(|| unsafe { read_scalar(spline, dim_out, "dim_out", BSplineCurve::dim) })
}

/// Reads the number of control points of a spline (`>= degree + 1`); the knot count is
/// `n_points + degree + 1`.
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `n_points_out` (out): on `CAGD_OK`, the number of control points.
///
/// Returns:
/// - `CAGD_OK`: `*n_points_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `n_points_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `n_points_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_n_points(
    spline: *const CagdBSpline,
    n_points_out: *mut usize,
) -> CagdStatus {
    // SAFETY: the caller's contract (see # Safety).
    boundary(|| unsafe {
        read_scalar(spline, n_points_out, "n_points_out", BSplineCurve::n_points)
    })
}

/// Tells whether a spline is rational (NURBS, created with weights).
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `rational_out` (out): on `CAGD_OK`, `true` for a NURBS curve.
///
/// Returns:
/// - `CAGD_OK`: `*rational_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `rational_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `rational_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_is_rational(
    spline: *const CagdBSpline,
    rational_out: *mut bool,
) -> CagdStatus {
    // SAFETY: the caller's contract (see # Safety).
    boundary(|| unsafe {
        read_scalar(
            spline,
            rational_out,
            "rational_out",
            BSplineCurve::is_rational,
        )
    })
}

/// Reads the parameter domain `[a, b] = [knots[degree], knots[n_points]]` of a spline
/// (`a < b`).
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `a_out` (out): on `CAGD_OK`, the start of the domain.
/// - `b_out` (out): on `CAGD_OK`, the end of the domain.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: any argument is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_domain(
    spline: *const CagdBSpline,
    a_out: *mut f64,
    b_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(spline, "spline") }?;
        // SAFETY: as above.
        let (a, b) = unsafe { (out_ref(a_out, "a_out")?, out_ref(b_out, "b_out")?) };
        (*a, *b) = s.0.domain();
        Ok(())
    })
}
