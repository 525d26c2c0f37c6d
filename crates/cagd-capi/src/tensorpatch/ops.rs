//! Operations on `CagdTensorPatch`: evaluation, degree elevation, subdivision in u or v.

use cagd_core::TensorPatch;

use crate::boundary::{
    CResult, Failure, OUT, boundary, handle_ref, into_handle, nonnull, out_ref, slice_out,
};
use crate::status::CagdStatus;
use crate::tensorpatch::CagdTensorPatch;

/// Evaluates a tensor-product patch at `(u, v)` (de Casteljau along v in every row, then
/// along u). `(u, v)` in `[0, 1]^2` is the patch; other finite values extrapolate.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `u` (in): the first parameter (along `i`), finite.
/// - `v` (in): the second parameter (along `j`), finite.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `dim` doubles hold
///   the point. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `dim`.
///
/// Returns:
/// - `CAGD_OK`: the point is in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `patch` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `u` or `v` is NaN or infinite, or a pointer is
///   misaligned.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < dim`; only `*out_needed` is written.
/// - `CAGD_ERR_NON_FINITE`: the point overflows f64 (`(u, v)` far outside the unit
///   square, or coordinates near the limits of f64); nothing is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; `out` NULL or `out_cap` writable doubles;
/// `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_eval(
    patch: *const CagdTensorPatch,
    u: f64,
    v: f64,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let point = p.0.eval(u, v)?;
        dst.copy_from(&point)
    })
}

/// Elevates a tensor-product patch from degree `(deg_u, deg_v)` to
/// `(deg_u + r_u, deg_v + r_v)` (curve elevation of every column, then of every row). The
/// surface is unchanged.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `r_u` (in): degrees to add in u (0 keeps it).
/// - `r_v` (in): degrees to add in v (0 keeps it).
/// - `patch_out` (out): on `CAGD_OK`, the elevated patch
///   (`(deg_u + r_u + 1) * (deg_v + r_v + 1) * dim` doubles, read back with
///   `cagd_tensorpatch_points`), owned by the caller: release with
///   `cagd_tensorpatch_free`. Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*patch_out` holds the elevated patch.
/// - `CAGD_ERR_NULL_POINTER`: `patch` or `patch_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `deg_u + r_u > 64` or `deg_v + r_v > 64`.
/// - `CAGD_ERR_NON_FINITE`: a point of the result rounds past `DBL_MAX` (coordinates near
///   `DBL_MAX`).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; `patch_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_elevate(
    patch: *const CagdTensorPatch,
    r_u: usize,
    r_v: usize,
    patch_out: *mut *mut CagdTensorPatch,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(patch_out, "patch_out") }?;
        let e = p.0.elevate_u(r_u)?.elevate_v(r_v)?;
        *out = into_handle(CagdTensorPatch(e));
        Ok(())
    })
}

/// The direction of a tensor-patch split.
#[derive(Clone, Copy)]
enum Dir {
    U,
    V,
}

/// Splits a patch at `s` in direction `dir` and writes the two handles.
///
/// # Safety
/// As the entry points below.
unsafe fn split(
    patch: *const CagdTensorPatch,
    s: f64,
    dir: Dir,
    first_out: *mut *mut CagdTensorPatch,
    second_out: *mut *mut CagdTensorPatch,
) -> CResult<()> {
    // SAFETY: forwarded contract.
    let p = unsafe { handle_ref(patch, "patch") }?;
    nonnull(first_out, "first_out")?;
    nonnull(second_out, "second_out")?;
    if first_out.addr() == second_out.addr() {
        return Err(Failure::invalid(
            "`first_out` and `second_out` are the same address",
        ));
    }
    // SAFETY: as above; the two outputs do not overlap.
    let (a, b) = unsafe {
        (
            out_ref(first_out, "first_out")?,
            out_ref(second_out, "second_out")?,
        )
    };
    let (l, r): (TensorPatch, TensorPatch) = match dir {
        Dir::U => p.0.subdivide_u(s)?,
        Dir::V => p.0.subdivide_v(s)?,
    };
    (*a, *b) = (
        into_handle(CagdTensorPatch(l)),
        into_handle(CagdTensorPatch(r)),
    );
    Ok(())
}

/// Splits a tensor-product patch at `u = s` into the pieces on `[0, s] x [0, 1]` and
/// `[s, 1] x [0, 1]`, each reparametrised to `[0, 1]^2` (same degrees; de Casteljau on
/// every column).
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `s` (in): the split parameter, finite, in `[0, 1]`.
/// - `first_out` (out): on `CAGD_OK`, the piece on `[0, s]` in u.
/// - `second_out` (out): on `CAGD_OK`, the piece on `[s, 1]` in u. Both are new handles
///   owned by the caller (release each with `cagd_tensorpatch_free`); neither is written
///   on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `patch`, `first_out` or `second_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `s` is NaN, infinite or outside `[0, 1]`, the two
///   outputs are the same address, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_subdivide_u(
    patch: *const CagdTensorPatch,
    s: f64,
    first_out: *mut *mut CagdTensorPatch,
    second_out: *mut *mut CagdTensorPatch,
) -> CagdStatus {
    // SAFETY: the caller's contract (see # Safety).
    boundary(|| unsafe { split(patch, s, Dir::U, first_out, second_out) })
}

/// Splits a tensor-product patch at `v = s` into the pieces on `[0, 1] x [0, s]` and
/// `[0, 1] x [s, 1]`, each reparametrised to `[0, 1]^2` (same degrees; de Casteljau on
/// every row).
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `s` (in): the split parameter, finite, in `[0, 1]`.
/// - `first_out` (out): on `CAGD_OK`, the piece on `[0, s]` in v.
/// - `second_out` (out): on `CAGD_OK`, the piece on `[s, 1]` in v. Both are new handles
///   owned by the caller (release each with `cagd_tensorpatch_free`); neither is written
///   on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `patch`, `first_out` or `second_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `s` is NaN, infinite or outside `[0, 1]`, the two
///   outputs are the same address, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_subdivide_v(
    patch: *const CagdTensorPatch,
    s: f64,
    first_out: *mut *mut CagdTensorPatch,
    second_out: *mut *mut CagdTensorPatch,
) -> CagdStatus {
    // SAFETY: the caller's contract (see # Safety).
    boundary(|| unsafe { split(patch, s, Dir::V, first_out, second_out) })
}
