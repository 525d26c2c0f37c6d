//! `CagdTensorPatchList` and `CagdTriPatchList`: the pieces of a patch reduction to a
//! tolerance, each with its parameter sub-domain and certified bound.

use cagd_reduce::{TensorPiece, TriPiece};

use crate::boundary::{
    CResult, Failure, OUT, boundary, boundary_void, free_handle, handle_ref, into_handle, out_ref,
    slice_out,
};
use crate::status::CagdStatus;
use crate::tensorpatch::CagdTensorPatch;
use crate::tripatch::CagdTriPatch;

/// Opaque handle to the reduced pieces of a tensor-product patch, in u-major order: piece
/// `i` is the reduction of the input on the sub-domain `[u0, u1] x [v0, v1]`, parametrised
/// over `[0, 1]^2`. Immutable; release with `cagd_tensorpatchlist_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdTensorPatchList(pub(crate) Vec<TensorPiece>);

/// Opaque handle to the reduced pieces of a triangular patch: piece `i` is the reduction
/// of the input on the sub-triangle `(A, B, C)` of its parameter domain,
/// `T_i(u', v') ~ T(C + u' (A - C) + v' (B - C))`. Immutable; release with
/// `cagd_tripatchlist_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdTriPatchList(pub(crate) Vec<TriPiece>);

/// Element `i` of a list, or `CAGD_ERR_INVALID_ARGUMENT`.
fn at<T>(items: &[T], i: usize) -> CResult<&T> {
    items.get(i).ok_or_else(|| {
        Failure::invalid(format!(
            "index {i} is out of range: the list has {} pieces",
            items.len()
        ))
    })
}

/// Releases a tensor patch list (not the patches obtained from it). NULL is accepted and
/// ignored; a non-NULL handle must be released exactly once and not used afterwards.
///
/// Parameters:
/// - `list` (in, consumed): a `CagdTensorPatchList **` output of a cagd function, or NULL.
///
/// Does not change `cagd_last_error_message()`.
///
/// # Safety
/// `list` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatchlist_free(list: *mut CagdTensorPatchList) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(list) });
}

/// Reads the number of pieces of a tensor patch list (`4^L` for subdivision level `L`).
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
pub unsafe extern "C" fn cagd_tensorpatchlist_count(
    list: *const CagdTensorPatchList,
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

/// Reads piece `i` of a tensor patch list: a new patch handle, its sub-domain and its
/// certified error bound (Euclidean, model units).
///
/// Parameters:
/// - `list` (in): the list.
/// - `i` (in): the piece index, `0 <= i < count`.
/// - `patch_out` (out): on `CAGD_OK`, the reduced piece, a new handle owned by the caller,
///   independent of the list: release it with `cagd_tensorpatch_free`.
/// - `domain_out` (out): on `CAGD_OK`, 4 doubles `u0, u1, v0, v1`: the sub-domain.
/// - `bound_out` (out): on `CAGD_OK`, the certified bound of the piece. Nothing is written
///   on failure.
///
/// Returns:
/// - `CAGD_OK`: all outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: any pointer argument is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `i >= count`, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; `patch_out`, `bound_out` NULL or writable;
/// `domain_out` NULL or 4 writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatchlist_get(
    list: *const CagdTensorPatchList,
    i: usize,
    patch_out: *mut *mut CagdTensorPatch,
    domain_out: *mut f64,
    bound_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let (p, b) = unsafe {
            (
                out_ref(patch_out, "patch_out")?,
                out_ref(bound_out, "bound_out")?,
            )
        };
        crate::boundary::nonnull(domain_out, "domain_out")?;
        let mut needed = 0;
        // SAFETY: as above: 4 writable doubles.
        let d = unsafe { slice_out(domain_out, 4, &mut needed, &OUT) }?;
        let piece = at(&l.0, i)?;
        d.copy_from(&[piece.u.0, piece.u.1, piece.v.0, piece.v.1])?;
        *b = piece.reduction.report.error_bound;
        *p = into_handle(CagdTensorPatch(piece.reduction.patch.clone()));
        Ok(())
    })
}

/// Releases a triangular patch list (not the patches obtained from it). NULL is accepted
/// and ignored; a non-NULL handle must be released exactly once and not used afterwards.
///
/// Parameters:
/// - `list` (in, consumed): a `CagdTriPatchList **` output of a cagd function, or NULL.
///
/// Does not change `cagd_last_error_message()`.
///
/// # Safety
/// `list` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatchlist_free(list: *mut CagdTriPatchList) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(list) });
}

/// Reads the number of pieces of a triangular patch list (`4^L` for subdivision level
/// `L`).
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
pub unsafe extern "C" fn cagd_tripatchlist_count(
    list: *const CagdTriPatchList,
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

/// Reads piece `i` of a triangular patch list: a new patch handle, its sub-triangle and
/// its certified error bound (Euclidean, model units).
///
/// Parameters:
/// - `list` (in): the list.
/// - `i` (in): the piece index, `0 <= i < count`.
/// - `patch_out` (out): on `CAGD_OK`, the reduced piece, a new handle owned by the caller,
///   independent of the list: release it with `cagd_tripatch_free`.
/// - `vertices_out` (out): on `CAGD_OK`, 6 doubles `A.u, A.v, B.u, B.v, C.u, C.v`: the
///   sub-triangle in the input's parameters (the piece's `(1, 0)`, `(0, 1)` and `(0, 0)`
///   corners).
/// - `bound_out` (out): on `CAGD_OK`, the certified bound of the piece. Nothing is written
///   on failure.
///
/// Returns:
/// - `CAGD_OK`: all outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: any pointer argument is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `i >= count`, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; `patch_out`, `bound_out` NULL or writable;
/// `vertices_out` NULL or 6 writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatchlist_get(
    list: *const CagdTriPatchList,
    i: usize,
    patch_out: *mut *mut CagdTriPatch,
    vertices_out: *mut f64,
    bound_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let (p, b) = unsafe {
            (
                out_ref(patch_out, "patch_out")?,
                out_ref(bound_out, "bound_out")?,
            )
        };
        crate::boundary::nonnull(vertices_out, "vertices_out")?;
        let mut needed = 0;
        // SAFETY: as above: 6 writable doubles.
        let v = unsafe { slice_out(vertices_out, 6, &mut needed, &OUT) }?;
        let piece = at(&l.0, i)?;
        let [a, bb, c] = piece.vertices;
        v.copy_from(&[a.0, a.1, bb.0, bb.1, c.0, c.1])?;
        *b = piece.reduction.report.error_bound;
        *p = into_handle(CagdTriPatch(piece.reduction.patch.clone()));
        Ok(())
    })
}
