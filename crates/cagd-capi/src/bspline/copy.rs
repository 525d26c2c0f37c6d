//! `cagd_bspline_copy`: the knots, control points and weights of a `CagdBSpline` copied
//! into caller buffers in one call (capacity 0 asks the sizes), with its shape — instead
//! of `cagd_bspline_degree`, `_dim`, `_n_points`, `_is_rational`, `_knots`, `_points` and
//! `_weights`.

use crate::boundary::{boundary, handle_ref, out_ref};
use crate::bspline::CagdBSpline;
use crate::copy_out::{OutArray, copy_all};
use crate::status::CagdStatus;

/// The shape of a `CagdBSpline` and the sizes of its arrays, written by
/// `cagd_bspline_copy` on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`. Counts of doubles,
/// never bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CagdBSplineSizes {
    /// The degree `p`.
    pub degree: usize,
    /// Coordinates per point.
    pub dim: usize,
    /// Number of control points.
    pub n_points: usize,
    /// Whether the spline is rational (NURBS).
    pub rational: bool,
    /// `n_points + degree + 1`: the length of `knots_out`.
    pub knots_len: usize,
    /// `n_points * dim`: the length of `points_out`.
    pub points_len: usize,
    /// `n_points` for a NURBS, 0 for a polynomial spline: the length of `weights_out`.
    pub weights_len: usize,
}

/// Copies the knots, control points and weights of a spline into caller buffers in one
/// call. Call it once with every capacity 0 (and the buffers NULL) to learn the sizes,
/// allocate, call again.
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `knots_out` (out): `knots_out_cap` doubles; on `CAGD_OK` the `knots_len` knots
///   (non-decreasing).
/// - `points_out` (out): `points_out_cap` doubles; on `CAGD_OK` the `points_len` control
///   point coordinates, row-major (Euclidean for a NURBS).
/// - `weights_out` (out): `weights_out_cap` doubles; on `CAGD_OK` the `weights_len`
///   weights (none for a polynomial spline; `cagd_bspline_weights` gives ones there).
/// - each `*_cap` (in): the capacity of its buffer in doubles; a buffer may be NULL only
///   when its capacity is 0.
/// - `sizes_out` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, the shape and
///   sizes.
///
/// Returns:
/// - `CAGD_OK`: every array is copied.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `sizes_out` is NULL, or a buffer is NULL with a
///   capacity above 0.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: a capacity is below its size (the message names every
///   short buffer); only `*sizes_out` is written.
/// - `CAGD_ERR_INVALID_ARGUMENT`: two buffers overlap, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; each buffer NULL or its capacity of
/// writable doubles; `sizes_out` NULL or writable and not overlapping a buffer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_copy(
    spline: *const CagdBSpline,
    knots_out: *mut f64,
    knots_out_cap: usize,
    points_out: *mut f64,
    points_out_cap: usize,
    weights_out: *mut f64,
    weights_out_cap: usize,
    sizes_out: *mut CagdBSplineSizes,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = &unsafe { handle_ref(spline, "spline") }?.0;
        // SAFETY: as above.
        let sizes = unsafe { out_ref(sizes_out, "sizes_out") }?;
        let weights = s.weights().unwrap_or_default();
        let shape = CagdBSplineSizes {
            degree: s.degree(),
            dim: s.dim(),
            n_points: s.n_points(),
            rational: s.is_rational(),
            knots_len: s.knots().len(),
            points_len: s.points().len(),
            weights_len: weights.len(),
        };
        let k = OutArray::new(knots_out, knots_out_cap, s.knots(), "knots_out");
        let p = OutArray::new(points_out, points_out_cap, s.points(), "points_out");
        let w = OutArray::new(weights_out, weights_out_cap, weights, "weights_out");
        // SAFETY: as above.
        unsafe { copy_all(&[&k, &p, &w], || *sizes = shape) }
    })
}
