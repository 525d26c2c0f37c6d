//! `CagdTriPatch`: triangular Bézier patches — creation, read-back, release.

mod ops;

pub use ops::{cagd_tripatch_elevate, cagd_tripatch_eval, cagd_tripatch_subdivide_midpoint};

use cagd_core::{TriPatch, tri_count};

use crate::boundary::{
    OUT, boundary, boundary_void, free_handle, handle_ref, into_handle, nonnull, out_ref,
    points_in, slice_out,
};
use crate::status::CagdStatus;

/// Opaque handle to a triangular Bézier patch of degree `n` (`0..=64`) with
/// `(n + 1)(n + 2) / 2` control points `T_ij` (`i + j <= n`) of `dim` coordinates, stored
/// i-major: for i in 0..=n, for j in 0..=n-i. Domain `u, v >= 0, u + v <= 1`,
/// `T(u, v) = sum n!/(i! j! k!) u^i v^j (1 - u - v)^k T_ij`, `k = n - i - j`. Immutable;
/// release with `cagd_tripatch_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdTriPatch(pub(crate) TriPatch);

impl CagdTriPatch {
    /// The patch behind the handle (for Rust callers of this crate).
    pub fn as_patch(&self) -> &TriPatch {
        &self.0
    }
}

/// Creates a triangular Bézier patch of degree `degree`.
///
/// Parameters:
/// - `points` (in): `(degree + 1) * (degree + 2) / 2 * dim` doubles, i-major: the points
///   `T_i0, T_i1, .., T_i(n-i)` for i = 0, 1, .., n in turn, each `dim` coordinates (`T_ij`
///   starts at double `(i * (2n + 3 - i) / 2 + j) * dim`). Borrowed and copied.
/// - `degree` (in): the degree `n`, `0..=64`.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `patch_out` (out): on `CAGD_OK`, a new handle owned by the caller (release with
///   `cagd_tripatch_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*patch_out` holds the new patch.
/// - `CAGD_ERR_NULL_POINTER`: `points` or `patch_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, the length formula overflows, or a pointer
///   is misaligned.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `degree > 64`.
/// - `CAGD_ERR_NON_FINITE`: a coordinate is NaN or infinite.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `points` must be NULL or point to `(degree + 1) * (degree + 2) / 2 * dim` readable
/// doubles; `patch_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatch_new(
    points: *const f64,
    degree: usize,
    dim: usize,
    patch_out: *mut *mut CagdTriPatch,
) -> CagdStatus {
    boundary(|| {
        nonnull(points, "points")?;
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(patch_out, "patch_out") }?;
        cagd_core::check_degree(degree)?;
        // SAFETY: as above; degree <= 64 so tri_count cannot overflow.
        let pts = unsafe { points_in(points, tri_count(degree), dim, "points") }?;
        let patch = TriPatch::new(pts.to_vec(), degree, dim)?;
        *out = into_handle(CagdTriPatch(patch));
        Ok(())
    })
}

/// Releases a triangular patch. NULL is accepted and ignored (freeing NULL twice is fine);
/// a non-NULL handle must be released exactly once and not used afterwards.
///
/// Parameters:
/// - `patch` (in, consumed): a handle from `cagd_tripatch_new` or another function's
///   `CagdTriPatch **` output, or NULL.
///
/// Does not change `cagd_last_error_message()`.
///
/// # Safety
/// `patch` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatch_free(patch: *mut CagdTriPatch) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(patch) });
}

/// Reads the degree and the dimension of a triangular patch.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `degree_out` (out): on `CAGD_OK`, the degree `n`.
/// - `dim_out` (out): on `CAGD_OK`, the coordinates per point.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: any argument is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatch_shape(
    patch: *const CagdTriPatch,
    degree_out: *mut usize,
    dim_out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        let (n, d) = unsafe {
            (
                out_ref(degree_out, "degree_out")?,
                out_ref(dim_out, "dim_out")?,
            )
        };
        (*n, *d) = (p.0.degree(), p.0.dim());
        Ok(())
    })
}

/// Copies the control points of a triangular patch, i-major as in `cagd_tripatch_new`.
/// Call with `out_cap = 0` (and `out` NULL) to ask the size.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `(n + 1) * (n + 2) / 2 * dim` doubles hold the points. May be NULL only when
///   `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `(n + 1) * (n + 2) / 2 * dim`.
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
pub unsafe extern "C" fn cagd_tripatch_points(
    patch: *const CagdTriPatch,
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
