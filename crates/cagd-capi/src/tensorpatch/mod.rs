//! `CagdTensorPatch`: tensor-product Bézier patches — creation, read-back, release.

mod ops;

pub use ops::{
    cagd_tensorpatch_elevate, cagd_tensorpatch_eval, cagd_tensorpatch_subdivide_u,
    cagd_tensorpatch_subdivide_v,
};

use cagd_core::TensorPatch;

use crate::boundary::{
    CResult, Failure, OUT, boundary, boundary_void, free_handle, handle_ref, into_handle, nonnull,
    out_ref, points_in, slice_out,
};
use crate::status::CagdStatus;

/// Opaque handle to a tensor-product Bézier patch of degree `(deg_u, deg_v)`, each in
/// `0..=64`, with `(deg_u + 1) * (deg_v + 1)` control points of `dim` coordinates stored
/// i-major (`P_ij` is point `i * (deg_v + 1) + j`, `i` along u). Immutable; release with
/// `cagd_tensorpatch_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdTensorPatch(pub(crate) TensorPatch);

impl CagdTensorPatch {
    /// The patch behind the handle (for Rust callers of this crate).
    pub fn as_patch(&self) -> &TensorPatch {
        &self.0
    }
}

/// `(m + 1) * (n + 1)` without overflow.
fn grid_count(deg_u: usize, deg_v: usize) -> CResult<usize> {
    deg_u
        .checked_add(1)
        .zip(deg_v.checked_add(1))
        .and_then(|(a, b)| a.checked_mul(b))
        .ok_or_else(|| {
            Failure::invalid(format!(
                "(deg_u + 1) * (deg_v + 1) overflows for ({deg_u}, {deg_v})"
            ))
        })
}

/// Creates a tensor-product Bézier patch
/// `P(u, v) = sum_i sum_j B_i^deg_u(u) B_j^deg_v(v) P_ij`.
///
/// Parameters:
/// - `points` (in): `(deg_u + 1) * (deg_v + 1) * dim` doubles, i-major: coordinate k of
///   `P_ij` at `points[(i * (deg_v + 1) + j) * dim + k]`. Borrowed and copied.
/// - `deg_u` (in): degree in u, `0..=64`.
/// - `deg_v` (in): degree in v, `0..=64`.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `patch_out` (out): on `CAGD_OK`, a new handle owned by the caller (release with
///   `cagd_tensorpatch_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*patch_out` holds the new patch.
/// - `CAGD_ERR_NULL_POINTER`: `points` or `patch_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, the length formula overflows, or a pointer
///   is misaligned.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `deg_u > 64` or `deg_v > 64`.
/// - `CAGD_ERR_NON_FINITE`: a coordinate is NaN or infinite.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `points` must be NULL or point to `(deg_u + 1) * (deg_v + 1) * dim` readable doubles;
/// `patch_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_new(
    points: *const f64,
    deg_u: usize,
    deg_v: usize,
    dim: usize,
    patch_out: *mut *mut CagdTensorPatch,
) -> CagdStatus {
    boundary(|| {
        nonnull(points, "points")?;
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(patch_out, "patch_out") }?;
        cagd_core::check_degree(deg_u)?;
        cagd_core::check_degree(deg_v)?;
        let n_points = grid_count(deg_u, deg_v)?;
        // SAFETY: as above.
        let pts = unsafe { points_in(points, n_points, dim, "points") }?;
        let patch = TensorPatch::new(pts.to_vec(), deg_u, deg_v, dim)?;
        *out = into_handle(CagdTensorPatch(patch));
        Ok(())
    })
}

/// Releases a tensor-product patch. NULL is accepted and ignored (freeing NULL twice is
/// fine); a non-NULL handle must be released exactly once and not used afterwards.
///
/// Parameters:
/// - `patch` (in, consumed): a handle from `cagd_tensorpatch_new` or another function's
///   `CagdTensorPatch **` output, or NULL.
///
/// Does not change `cagd_last_error_message()`.
///
/// # Safety
/// `patch` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_free(patch: *mut CagdTensorPatch) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(patch) });
}

/// Reads the degrees `(deg_u, deg_v)` and the dimension of a tensor-product patch.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `deg_u_out` (out): on `CAGD_OK`, the degree in u.
/// - `deg_v_out` (out): on `CAGD_OK`, the degree in v.
/// - `dim_out` (out): on `CAGD_OK`, the coordinates per point.
///
/// Returns:
/// - `CAGD_OK`: the three outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: any argument is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_shape(
    patch: *const CagdTensorPatch,
    deg_u_out: *mut usize,
    deg_v_out: *mut usize,
    dim_out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        let (u, v, d) = unsafe {
            (
                out_ref(deg_u_out, "deg_u_out")?,
                out_ref(deg_v_out, "deg_v_out")?,
                out_ref(dim_out, "dim_out")?,
            )
        };
        let (m, n) = p.0.degrees();
        (*u, *v, *d) = (m, n, p.0.dim());
        Ok(())
    })
}

/// Copies the control points of a tensor-product patch, i-major as in
/// `cagd_tensorpatch_new`. Call with `out_cap = 0` (and `out` NULL) to ask the size.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `(deg_u + 1) * (deg_v + 1) * dim` doubles hold the points. May be NULL only when
///   `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `(deg_u + 1) * (deg_v + 1) * dim`.
///
/// Returns:
/// - `CAGD_OK`: the points are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `patch` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is below the formula; only `*out_needed` is
///   written.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; `out` NULL or `out_cap` writable doubles;
/// `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_points(
    patch: *const CagdTensorPatch,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        unsafe { slice_out(out, out_cap, out_needed, &OUT) }?.copy_from(p.0.points())
    })
}
