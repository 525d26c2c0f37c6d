//! Operations on `CagdTriPatch`: evaluation, degree elevation, midpoint subdivision.

use crate::boundary::{CResult, Failure, OUT, boundary, handle_ref, into_handle, slice_out};
use crate::status::CagdStatus;
use crate::tripatch::CagdTriPatch;

/// Evaluates a triangular patch at `(u, v)` (triangular de Casteljau at the barycentric
/// point `(u, v, 1 - u - v)`): `T(u, v) = sum_{i+j<=n} n!/(i! j! k!) u^i v^j w^k T_ij`,
/// `w = 1 - u - v`, `k = n - i - j`, so `T(0, 0) = T_00`, `T(1, 0) = T_n0`,
/// `T(0, 1) = T_0n`. `u, v >= 0`, `u + v <= 1` is the patch; other finite values
/// extrapolate.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `u` (in): the first parameter (weight of index `i`), finite.
/// - `v` (in): the second parameter (weight of index `j`), finite.
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
/// - `CAGD_ERR_NON_FINITE`: the point overflows f64 (`(u, v)` far outside the
///   triangle, or coordinates near the limits of f64); nothing is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; `out` NULL or `out_cap` writable doubles;
/// `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatch_eval(
    patch: *const CagdTriPatch,
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

/// Elevates a triangular patch from degree `n` to `n + r`. The surface is unchanged.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `r` (in): degrees to add (0 gives a copy).
/// - `patch_out` (out): on `CAGD_OK`, the elevated patch
///   (`(n + r + 1) * (n + r + 2) / 2 * dim` doubles, read back with
///   `cagd_tripatch_points`), owned by the caller: release with `cagd_tripatch_free`. Not
///   written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*patch_out` holds the elevated patch.
/// - `CAGD_ERR_NULL_POINTER`: `patch` or `patch_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n + r > 64`.
/// - `CAGD_ERR_NON_FINITE`: a point of the result rounds past f64 (coordinates near the
///   limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; `patch_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatch_elevate(
    patch: *const CagdTriPatch,
    r: usize,
    patch_out: *mut *mut CagdTriPatch,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        let out = unsafe { crate::boundary::out_ref(patch_out, "patch_out") }?;
        *out = into_handle(CagdTriPatch(p.0.elevate(r)?));
        Ok(())
    })
}

/// Checks an array of `N` handle outputs: not NULL, aligned.
fn pieces_array<const N: usize>(
    pieces_out: *mut *mut CagdTriPatch,
) -> CResult<*mut [*mut CagdTriPatch; N]> {
    crate::boundary::nonnull(pieces_out, "pieces_out")?;
    if !pieces_out.is_aligned() {
        return Err(Failure::invalid("argument `pieces_out` is misaligned"));
    }
    Ok(pieces_out.cast())
}

/// Splits a triangular patch into the four midpoint sub-triangles (seed 000 Theorem
/// 14.3.1, parametrised as SPEC-reduce §5 fixes, local axes parallel to the original):
/// - `pieces_out[0]`: corner at `(0, 0)`: `(u, v) = (u'/2, v'/2)`;
/// - `pieces_out[1]`: corner at `(1/2, 0)`: `(u, v) = (1/2 + u'/2, v'/2)`;
/// - `pieces_out[2]`: corner at `(0, 1/2)`: `(u, v) = (u'/2, 1/2 + v'/2)`;
/// - `pieces_out[3]`: the middle one: `(u, v) = (1/2 - u'/2, 1/2 - v'/2)`.
///
/// Parameters:
/// - `patch` (in): the patch, degree `n`.
/// - `pieces_out` (out): an array of 4 `CagdTriPatch *`; on `CAGD_OK` each holds a new
///   degree-`n` patch owned by the caller (release each with `cagd_tripatch_free`).
///   Nothing is written on failure.
///
/// Returns:
/// - `CAGD_OK`: the four pieces are written.
/// - `CAGD_ERR_NULL_POINTER`: `patch` or `pieces_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; `pieces_out` NULL or an array of 4
/// writable `CagdTriPatch *`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatch_subdivide_midpoint(
    patch: *const CagdTriPatch,
    pieces_out: *mut *mut CagdTriPatch,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        let arr = pieces_array::<4>(pieces_out)?;
        let handles =
            p.0.subdivide_midpoint()
                .map(|t| into_handle(CagdTriPatch(t)));
        // SAFETY: non-NULL, aligned, 4 writable pointers by the caller's contract.
        unsafe { arr.write(handles) };
        Ok(())
    })
}
