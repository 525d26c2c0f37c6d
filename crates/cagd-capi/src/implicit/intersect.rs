//! Curve–curve intersection and the theorem 15.9.1 matrix at the C boundary
//! (cagd-implicit).

use crate::CagdCurve;
use crate::boundary::{OUT, boundary, handle_ref, slice_out};
use crate::status::CagdStatus;

/// Doubles per intersection in the output of `cagd_curve_intersect`.
pub const CAGD_INTERSECTION_STRIDE: usize = 5;

/// Intersects two planar Bézier curves (polynomial or rational, degree `1..=16` each;
/// tested to degree 5): every point `A(s) = B(t)` with `s, t` in `[0, 1]`, sorted by `s`,
/// found by implicitizing the lower-degree curve, isolating the roots of the substituted
/// polynomial in the Bernstein basis, inverting, and polishing by Newton.
///
/// Parameters:
/// - `a`, `b` (in): the curves, `dim == 2`.
/// - `out` (out): `CAGD_INTERSECTION_STRIDE` (5) doubles per intersection:
///   `s, t, x, y, tangential` (tangential is 1.0 when the curves are tangent there or the
///   point is singular, else 0.0); `out_cap` doubles; may be NULL when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): `5 * count`, written on `CAGD_OK` and `CAGD_ERR_BUFFER_TOO_SMALL`
///   (a call with `out_cap == 0` asks the size; it runs the whole intersection).
///
/// Returns:
/// - `CAGD_OK`: `out[0 .. *out_needed]` written.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: only `*out_needed` written.
/// - `CAGD_ERR_NULL_POINTER`: `a`, `b` or `out_needed` NULL, or `out` NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a misaligned pointer.
/// - `CAGD_ERR_NOT_PLANAR`, `CAGD_ERR_NOT_ENOUGH_POINTS` (degree 0),
///   `CAGD_ERR_DEGREE_OUT_OF_RANGE` (above 16): bad curves.
/// - `CAGD_ERR_BASE_POINT`: a curve is a single point.
/// - `CAGD_ERR_CONDITION_NOT_MET`: an implicit coefficient is beyond the double range.
/// - `CAGD_ERR_COINCIDENT`: the curves overlap along an arc (the message gives the
///   overlap on `a`).
/// - `CAGD_ERR_NON_FINITE`: an intermediate value overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `a`, `b` NULL or live curves; `out` NULL or `out_cap` writable doubles; `out_needed`
/// NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_intersect(
    a: *const CagdCurve,
    b: *const CagdCurve,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let ca = unsafe { handle_ref(a, "a") }?;
        // SAFETY: as above.
        let cb = unsafe { handle_ref(b, "b") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let hits = cagd_implicit::intersect(&ca.0, &cb.0)?;
        let flat: Vec<f64> = hits
            .iter()
            .flat_map(|h| {
                [
                    h.s,
                    h.t,
                    h.point[0],
                    h.point[1],
                    f64::from(u8::from(h.tangential)),
                ]
            })
            .collect();
        dst.copy_from(&flat)
    })
}

/// The matrix `A(α)` of theorem 15.9.1 (SPEC-convert §15.9, eq. 15.9.6, 0-based
/// `a_ij = C(n-1-j, i-j) (1-α)^(i-j) α^j`, `j <= i`), with `α A F(q) A^T = F(q*)` for the
/// piece `[0, α]`: `n * n` doubles, row-major.
///
/// Parameters:
/// - `n` (in): curve degree, `1..=16`.
/// - `alpha` (in): finite.
/// - `out` (out): `out_cap` doubles; may be NULL when `out_cap == 0` (size query).
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): `n * n`, written on `CAGD_OK` and `CAGD_ERR_BUFFER_TOO_SMALL`.
///
/// Returns:
/// - `CAGD_OK`: `out[0 .. n * n]` written.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: only `*out_needed` written.
/// - `CAGD_ERR_NULL_POINTER`: `out_needed` NULL, or `out` NULL with `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `alpha` not finite, or a misaligned pointer.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n` is 0 or above 16.
/// - `CAGD_ERR_NON_FINITE`: an entry overflows f64 (`|alpha|` large for `n`);
///   nothing is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `out` NULL or `out_cap` writable doubles; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_implicit_subdivision_matrix(
    n: usize,
    alpha: f64,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let a = cagd_implicit::subdivision_matrix(n, alpha)?;
        dst.copy_from(&a)
    })
}
