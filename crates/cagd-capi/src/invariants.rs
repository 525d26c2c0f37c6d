//! Degeneracy invariants (seed 000 §14.1) and parametric distances of curves and patches:
//! `cagd_curve_forward_difference`, `cagd_tensorpatch_degeneracy`,
//! `cagd_tripatch_degeneracy`, `cagd_curve_distance`, `cagd_tensorpatch_distance`,
//! `cagd_tripatch_distance`.

use cagd_core::{curve_distance, tensor_patch_distance, tri_patch_distance};

use crate::boundary::{
    Failure, OUT, OutNames, boundary, check_finite_out, disjoint, handle_ref, out_ref, slice_out,
};
use crate::curve::CagdCurve;
use crate::status::CagdStatus;
use crate::tensorpatch::CagdTensorPatch;
use crate::tripatch::CagdTriPatch;

/// The forward difference `Delta^n P_0 = sum_{i=0..n} (-1)^(n-i) C(n,i) P_i` of a degree-`n`
/// curve (seed 000 eq. 14.1.1): the curve has degree `< n` exactly when it is zero, and it is
/// the vector `F` whose norm enters the perturbation error bound (SPEC-reduce §2.1). For a
/// rational curve it is taken of the homogeneous points `(w_i P_i, w_i)`. Computed in `f64`
/// with the exact binomials; its rounding error is a few `2^n` ulp of the largest point.
///
/// Parameters:
/// - `curve` (in): the curve, degree `n`.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `dim` doubles
///   (polynomial curve) or `dim + 1` doubles (rational curve: the homogeneous coordinates
///   `sum (-1)^(n-i) C(n,i) w_i P_i` followed by `sum (-1)^(n-i) C(n,i) w_i`) hold `F`.
///   May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `dim` (polynomial)
///   or `dim + 1` (rational).
///
/// Returns:
/// - `CAGD_OK`: `F` is in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is below the size; only `*out_needed` is
///   written.
/// - `CAGD_ERR_NON_FINITE`: the difference overflows (coordinates near the largest
///   double); only `*out_needed` is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `out` NULL or `out_cap` writable doubles;
/// `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_forward_difference(
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
        dst.copy_from(&c.0.forward_difference())
    })
}

/// Names of the `F` output of [`cagd_tensorpatch_degeneracy`].
const F_OUT: OutNames = OutNames {
    out: "f_out",
    cap: "f_cap",
    needed: "f_needed",
};

/// Names of the `G` output of [`cagd_tensorpatch_degeneracy`].
const G_OUT: OutNames = OutNames {
    out: "g_out",
    cap: "g_cap",
    needed: "g_needed",
};

/// The degeneracy invariants of a tensor-product patch of degree `(m, n)` (seed 000
/// eq. 14.1.2, Theorem 14.1.1): `F_j = sum_i (-1)^(m-i) C(m,i) P_ij` for `j = 0..=n` (all
/// zero iff the patch has degree `< m` in `u`) and `G_i = sum_j (-1)^(n-j) C(n,j) P_ij` for
/// `i = 0..=m` (all zero iff degree `< n` in `v`). Computed in `f64` with exact binomials.
///
/// Parameters:
/// - `patch` (in): the patch, degrees `(m, n)`, dimension `dim`.
/// - `f_out` (out): buffer of `f_cap` doubles; on `CAGD_OK` its first `(n + 1) * dim`
///   doubles hold `F`, row-major (coordinate k of `F_j` at `f_out[j * dim + k]`). May be
///   NULL only when `f_cap == 0`.
/// - `f_cap` (in): capacity of `f_out` in doubles.
/// - `f_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `(n + 1) * dim`.
/// - `g_out` (out): buffer of `g_cap` doubles; on `CAGD_OK` its first `(m + 1) * dim`
///   doubles hold `G` (coordinate k of `G_i` at `g_out[i * dim + k]`). May be NULL only
///   when `g_cap == 0`. Must not overlap `f_out`.
/// - `g_cap` (in): capacity of `g_out` in doubles.
/// - `g_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `(m + 1) * dim`.
///   Must differ from `f_needed`.
///
/// Returns:
/// - `CAGD_OK`: `F` and `G` are written.
/// - `CAGD_ERR_NULL_POINTER`: `patch`, `f_needed` or `g_needed` is NULL, or `f_out` /
///   `g_out` is NULL with a capacity `> 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `f_needed == g_needed`, the two buffers overlap, or a
///   pointer is misaligned.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `f_cap` or `g_cap` is below its size; both `*f_needed`
///   and `*g_needed` are written, nothing else.
/// - `CAGD_ERR_NON_FINITE`: an invariant overflows (coordinates near the largest double);
///   only `*f_needed` and `*g_needed` are written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; `f_out` NULL or `f_cap` writable doubles;
/// `g_out` NULL or `g_cap` writable doubles; `f_needed`, `g_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_degeneracy(
    patch: *const CagdTensorPatch,
    f_out: *mut f64,
    f_cap: usize,
    f_needed: *mut usize,
    g_out: *mut f64,
    g_cap: usize,
    g_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        if std::ptr::eq(f_needed, g_needed) && !f_needed.is_null() {
            return Err(Failure::invalid(
                "`f_needed` and `g_needed` are the same pointer",
            ));
        }
        // SAFETY: as above.
        let f_dst = unsafe { slice_out(f_out, f_cap, f_needed, &F_OUT) }?;
        // SAFETY: as above.
        let g_dst = unsafe { slice_out(g_out, g_cap, g_needed, &G_OUT) }?;
        let (f, g) = p.0.degeneracy_invariants();
        disjoint(
            f_out,
            f.len().min(f_cap),
            g_out,
            g.len().min(g_cap),
            "`f_out` and `g_out`",
        )?;
        let (f_res, g_res) = (f_dst.take(f.len()), g_dst.take(g.len()));
        let (fs, gs) = (f_res?, g_res?);
        // Alternating sums with binomials up to C(64, 32) overflow for coordinates near
        // the largest double (C ABI fuzz long run: -inf returned with CAGD_OK).
        check_finite_out(&f, "f_out")?;
        check_finite_out(&g, "g_out")?;
        fs.copy_from_slice(&f);
        gs.copy_from_slice(&g);
        Ok(())
    })
}

/// The degeneracy invariants of a degree-`n` triangular patch (seed 000 eq. 14.1.3,
/// SPEC-reduce §1): `F_k = Delta_1^k Delta_2^(n-k) T_00
/// = sum_{i<=k} sum_{j<=n-k} (-1)^(n-i-j) C(k,i) C(n-k,j) T_ij`, `k = 0..=n`. The patch has
/// degree `< n` exactly when all `F_k` vanish. Computed in `f64` with exact binomials.
///
/// Parameters:
/// - `patch` (in): the patch, degree `n`, dimension `dim`.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `(n + 1) * dim`
///   doubles hold `F`, row-major (coordinate d of `F_k` at `out[k * dim + d]`). May be NULL
///   only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `(n + 1) * dim`.
///
/// Returns:
/// - `CAGD_OK`: `F` is in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `patch` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < (n + 1) * dim`; only `*out_needed` is written.
/// - `CAGD_ERR_NON_FINITE`: an invariant overflows (coordinates near the largest double);
///   only `*out_needed` is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; `out` NULL or `out_cap` writable doubles;
/// `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatch_degeneracy(
    patch: *const CagdTriPatch,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        dst.copy_from(&p.0.degeneracy_invariants())
    })
}

/// The parametric distance `max_{t in [0,1]} ||a(t) - b(t)||` (Euclidean norm) between two
/// Bézier curves of any degrees, polynomial or rational (cagd_core::curve_distance: dense
/// sampling of the difference refined by golden-section search; relative accuracy `1e-12`
/// up to degree 10, `2.4e-10` measured at degree 20).
///
/// Parameters:
/// - `a`, `b` (in): the curves, of the same dimension.
/// - `out` (out): on `CAGD_OK`, the distance. Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*out` holds the distance.
/// - `CAGD_ERR_NULL_POINTER`: `a`, `b` or `out` is NULL.
/// - `CAGD_ERR_DIMENSION_MISMATCH`: the dimensions differ.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_NON_FINITE`: the computation overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `a` and `b` must be NULL or live curve handles; `out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_distance(
    a: *const CagdCurve,
    b: *const CagdCurve,
    out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let (ca, cb) = unsafe { (handle_ref(a, "a")?, handle_ref(b, "b")?) };
        // SAFETY: as above.
        let o = unsafe { out_ref(out, "out") }?;
        *o = curve_distance(&ca.0, &cb.0)?;
        Ok(())
    })
}

/// The parametric distance `max_{(u,v) in [0,1]^2} ||a(u,v) - b(u,v)||` (Euclidean norm)
/// between two tensor-product patches of any degrees (cagd_core::tensor_patch_distance:
/// both elevated to the common degree, control points subtracted, grid of
/// `4 (m + n) + 32` intervals per side, `(m, n)` the common degrees, sampled with cached
/// bases; the 8 largest sampled local maxima refined locally: bounded work, about 0.3 s
/// at degrees 64 x 64).
///
/// Parameters:
/// - `a`, `b` (in): the patches, of the same dimension.
/// - `out` (out): on `CAGD_OK`, the distance. Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*out` holds the distance.
/// - `CAGD_ERR_NULL_POINTER`: `a`, `b` or `out` is NULL.
/// - `CAGD_ERR_DIMENSION_MISMATCH`: the dimensions differ.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_NON_FINITE`: the computation overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `a` and `b` must be NULL or live tensor-patch handles; `out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_distance(
    a: *const CagdTensorPatch,
    b: *const CagdTensorPatch,
    out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let (pa, pb) = unsafe { (handle_ref(a, "a")?, handle_ref(b, "b")?) };
        // SAFETY: as above.
        let o = unsafe { out_ref(out, "out") }?;
        *o = tensor_patch_distance(&pa.0, &pb.0)?;
        Ok(())
    })
}

/// The parametric distance `max ||a(u,v) - b(u,v)||` (Euclidean norm) over the unit
/// triangle `u, v >= 0, u + v <= 1` between two triangular patches of any degrees
/// (cagd_core::tri_patch_distance: elevated to the common degree, control points
/// subtracted, grid of `8 n + 32` intervals per side, `n` the common degree, sampled with
/// cached bases; the 8 largest sampled local maxima refined locally: bounded work, about
/// 0.3 s at degree 64).
///
/// Parameters:
/// - `a`, `b` (in): the patches, of the same dimension.
/// - `out` (out): on `CAGD_OK`, the distance. Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*out` holds the distance.
/// - `CAGD_ERR_NULL_POINTER`: `a`, `b` or `out` is NULL.
/// - `CAGD_ERR_DIMENSION_MISMATCH`: the dimensions differ.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_NON_FINITE`: the computation overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `a` and `b` must be NULL or live triangular-patch handles; `out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatch_distance(
    a: *const CagdTriPatch,
    b: *const CagdTriPatch,
    out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let (pa, pb) = unsafe { (handle_ref(a, "a")?, handle_ref(b, "b")?) };
        // SAFETY: as above.
        let o = unsafe { out_ref(out, "out") }?;
        *o = tri_patch_distance(&pa.0, &pb.0)?;
        Ok(())
    })
}
