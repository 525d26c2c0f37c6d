//! `CagdImplicit`: the implicit form of a planar rational Bézier curve (SPEC-convert §15.8,
//! cagd-implicit) — creation from a `CagdCurve`, read-back of the polynomial and the Bézout
//! matrices, point classification and inversion. Intersection and the theorem 15.9.1 matrix
//! are in `intersect.rs`.

mod intersect;

pub use intersect::{
    CAGD_INTERSECTION_STRIDE, cagd_curve_intersect, cagd_implicit_subdivision_matrix,
};

use cagd_implicit::{BasePointPolicy, ImplicitCurve, ImplicitOptions};

use crate::CagdCurve;
use crate::boundary::{
    OUT, boundary, boundary_void, free_handle, handle_ref, into_handle, out_ref, slice_out,
};
use crate::status::CagdStatus;

/// Opaque handle to the implicit form of a planar curve of degree `n` (after base points
/// were divided out, if asked): the Bézout matrix `F = x A + y B + C0` (`n x n`) and the
/// polynomial `f(x, y) = det F = sum_{i+j<=n} c_ij x^i y^j` with exact coefficients rounded
/// once to double. Immutable; release with `cagd_implicit_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdImplicit(pub(crate) ImplicitCurve);

/// Implicitizes a planar Bézier curve (polynomial or rational, degree `1..=16`):
/// `f(x, y) = det F(x, y)` of SPEC-convert eqs. 15.8.2–15.8.5, sign convention
/// `det F = (-1)^(n(n+1)/2) Res_t(W x - X, W y - Y)`. Cost: about 0.1 ms at degree 5,
/// 10 ms at degree 10 (exact big-integer arithmetic); up to seconds at degree 16 when the
/// coordinates and weights span hundreds of binades (a subnormal beside a value near
/// `1e308`: the exact integers carry the whole exponent range).
///
/// Parameters:
/// - `curve` (in): a curve with `dim == 2`.
/// - `divide_base_points` (in): non-zero to divide a common factor of X, Y, W (base points,
///   e.g. a degree-elevated curve) out and implicitize the lower-degree curve; 0 to refuse
///   such a curve with `CAGD_ERR_BASE_POINT`.
/// - `implicit_out` (out): on `CAGD_OK`, a new handle owned by the caller, released with
///   `cagd_implicit_free` exactly once. Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*implicit_out` holds the implicit form.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `implicit_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_NOT_PLANAR`: `dim != 2`.
/// - `CAGD_ERR_NOT_ENOUGH_POINTS`: degree 0.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: degree above 16.
/// - `CAGD_ERR_BASE_POINT`: the curve has base points and `divide_base_points == 0`, or it
///   is a single point.
/// - `CAGD_ERR_CONDITION_NOT_MET`: a coefficient of `f` is beyond the double range
///   (coordinates or weights too large).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live `CagdCurve`; `implicit_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_implicitize(
    curve: *const CagdCurve,
    divide_base_points: i32,
    implicit_out: *mut *mut CagdImplicit,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(implicit_out, "implicit_out") }?;
        let options = ImplicitOptions {
            base_points: if divide_base_points != 0 {
                BasePointPolicy::DivideOut
            } else {
                BasePointPolicy::Reject
            },
        };
        let imp = ImplicitCurve::with_options(&c.0, &options)?;
        *out = into_handle(CagdImplicit(imp));
        Ok(())
    })
}

/// Releases an implicit form. NULL is accepted and ignored; a non-NULL handle must be
/// released exactly once and not used afterwards. Does not change
/// `cagd_last_error_message()`.
///
/// # Safety
/// `implicit` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_implicit_free(implicit: *mut CagdImplicit) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(implicit) });
}

/// Reads what the implicitization found.
///
/// Parameters:
/// - `implicit` (in): the implicit form.
/// - `degree_out` (out): the degree `n` of the implicit polynomial (the input degree minus
///   the base points divided out).
/// - `base_points_out` (out): the number of base points divided out (0 normally).
/// - `power_out` (out): how many times the parametrization traces its curve (1 = proper;
///   `k > 1` means `f = c g^k`, e.g. 2 for a quadratic with collinear control points).
///
/// Returns:
/// - `CAGD_OK`: all three written.
/// - `CAGD_ERR_NULL_POINTER`: a pointer is NULL (nothing written).
/// - `CAGD_ERR_INVALID_ARGUMENT`: a misaligned pointer.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `implicit` must be NULL or a live handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_implicit_report(
    implicit: *const CagdImplicit,
    degree_out: *mut usize,
    base_points_out: *mut usize,
    power_out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let imp = unsafe { handle_ref(implicit, "implicit") }?;
        // SAFETY: as above.
        let d = unsafe { out_ref(degree_out, "degree_out") }?;
        // SAFETY: as above.
        let b = unsafe { out_ref(base_points_out, "base_points_out") }?;
        // SAFETY: as above.
        let p = unsafe { out_ref(power_out, "power_out") }?;
        let r = imp.0.report();
        *d = r.degree;
        *b = r.base_points;
        *p = r.power;
        Ok(())
    })
}

/// Copies the monomial coefficients of `f(x, y) = sum c_ij x^i y^j` (exact values rounded
/// once to double) into `out`, i-major: for i in 0..=n, for j in 0..=n-i, `c_ij` — i.e.
/// `c_ij` at index `i (2n + 3 - i) / 2 + j`; `(n + 1)(n + 2) / 2` doubles.
///
/// Parameters:
/// - `implicit` (in): the implicit form.
/// - `out` (out): `out_cap` doubles; may be NULL when `out_cap == 0` (size query).
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): `(n + 1)(n + 2) / 2`, written on `CAGD_OK` and on
///   `CAGD_ERR_BUFFER_TOO_SMALL`.
///
/// Returns:
/// - `CAGD_OK`: `out[0 .. *out_needed]` written.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` too small; only `*out_needed` written.
/// - `CAGD_ERR_NULL_POINTER`: `implicit` or `out_needed` NULL, or `out` NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a misaligned pointer.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `implicit` NULL or live; `out` NULL or `out_cap` writable doubles; `out_needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_implicit_coefficients(
    implicit: *const CagdImplicit,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let imp = unsafe { handle_ref(implicit, "implicit") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        dst.copy_from(imp.0.polynomial().coefficients())
    })
}

/// Copies the Bézout matrices `A`, `B`, `C0` of `F(x, y) = x A + y B + C0` (eq. 15.8.4,
/// symmetric `n x n`, row-major) one after the other into `out`: `3 n^2` doubles.
///
/// Parameters:
/// - `implicit` (in): the implicit form.
/// - `out` (out): `out_cap` doubles: `A`, then `B`, then `C0`; may be NULL when
///   `out_cap == 0` (size query).
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): `3 n^2`, written on `CAGD_OK` and `CAGD_ERR_BUFFER_TOO_SMALL`.
///
/// Returns:
/// - `CAGD_OK`: `out[0 .. 3 n^2]` written.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: only `*out_needed` written.
/// - `CAGD_ERR_NULL_POINTER`: `implicit` or `out_needed` NULL, or `out` NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a misaligned pointer.
/// - `CAGD_ERR_NON_FINITE`: a matrix entry overflows f64 (coordinates near the limits
///   of f64); nothing is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// As `cagd_implicit_coefficients`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_implicit_bezout(
    implicit: *const CagdImplicit,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let imp = unsafe { handle_ref(implicit, "implicit") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let f = imp.0.bezout();
        let mut all = Vec::with_capacity(3 * f.a().len());
        all.extend_from_slice(f.a());
        all.extend_from_slice(f.b());
        all.extend_from_slice(f.c0());
        dst.copy_from(&all)
    })
}

/// Classifies a point against the implicit curve: `f(x, y) = det F(x, y)` by LU with
/// partial pivoting, its sign, and the algebraic distance `f / |∇f|` (signed, model units
/// to first order; ±infinity where the gradient vanishes and f ≠ 0). About 0.1 µs at
/// degree 5; no allocation.
///
/// Parameters:
/// - `implicit` (in): the implicit form.
/// - `x`, `y` (in): the point, finite.
/// - `value_out` (out): `f(x, y)`.
/// - `sign_out` (out): -1, 0 or 1 (0 only for an exact zero).
/// - `distance_out` (out): `f / |∇f|`.
///
/// Returns:
/// - `CAGD_OK`: the three outputs written (they are written only on `CAGD_OK`).
/// - `CAGD_ERR_NULL_POINTER`: a pointer is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `x` or `y` not finite, or a misaligned pointer.
/// - `CAGD_ERR_NON_FINITE`: `f(x, y)` overflows f64 (a point far from the curve).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `implicit` NULL or live; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_implicit_classify(
    implicit: *const CagdImplicit,
    x: f64,
    y: f64,
    value_out: *mut f64,
    sign_out: *mut i32,
    distance_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let imp = unsafe { handle_ref(implicit, "implicit") }?;
        // SAFETY: as above.
        let v = unsafe { out_ref(value_out, "value_out") }?;
        // SAFETY: as above.
        let s = unsafe { out_ref(sign_out, "sign_out") }?;
        // SAFETY: as above.
        let d = unsafe { out_ref(distance_out, "distance_out") }?;
        cagd_core::check_finite_param("x", x)?;
        cagd_core::check_finite_param("y", y)?;
        let c = imp.0.classify(x, y);
        // Far from the curve f(x, y) overflows (issue 18, fuzz harness): refused, not inf.
        let value = crate::boundary::finite_scalar(c.value, "value_out")?;
        if c.distance.is_nan() {
            return Err(crate::boundary::Failure::new(
                CagdStatus::ERR_NON_FINITE,
                "`distance_out` is NaN (f and its gradient overflowed f64)",
            ));
        }
        *v = value;
        *s = i32::from(c.sign);
        *d = c.distance;
        Ok(())
    })
}

/// Inverts a point on the curve: the parameter `t` with `C(t) = (x, y)`, from the kernel
/// of `F(x, y)` (polished by Gauss–Newton); `t` may lie outside `[0, 1]` for a point of
/// the algebraic curve beyond the segment.
///
/// Parameters:
/// - `implicit` (in): the implicit form.
/// - `x`, `y` (in): the point, finite.
/// - `t_out` (out): on `CAGD_OK`, the parameter.
///
/// Returns:
/// - `CAGD_OK`: `*t_out` written.
/// - `CAGD_ERR_NULL_POINTER`: `implicit` or `t_out` NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `x` or `y` not finite, or a misaligned pointer.
/// - `CAGD_ERR_SINGULAR_POINT`: the point is a double point or cusp of the curve.
/// - `CAGD_ERR_NOT_ON_CURVE`: the point is farther than `1e-8 * max(1, |control points|)`
///   from the curve.
/// - `CAGD_ERR_CONDITION_NOT_MET`: improper parametrization (every point has several
///   parameters; see `cagd_implicit_report`'s power).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `implicit` NULL or live; `t_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_implicit_invert(
    implicit: *const CagdImplicit,
    x: f64,
    y: f64,
    t_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let imp = unsafe { handle_ref(implicit, "implicit") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(t_out, "t_out") }?;
        *out = imp.0.invert(x, y)?;
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{cagd_curve_free, cagd_curve_new_rational};

    #[test]
    fn conic_round_trip() {
        let pts = [1.0, 0.0, 1.0, 1.0, 0.0, 1.0];
        let w = [1.0, 1.0, 2.0];
        let mut c = std::ptr::null_mut();
        let mut imp = std::ptr::null_mut();
        let mut coefs = [0.0; 6];
        let mut needed = 0;
        let (mut v, mut s, mut d, mut t) = (0.0, 0, 0.0, 0.0);
        // SAFETY: valid pointers of the documented sizes; handles freed once.
        unsafe {
            assert_eq!(
                cagd_curve_new_rational(pts.as_ptr(), w.as_ptr(), 3, 2, &mut c),
                CagdStatus::OK
            );
            assert_eq!(cagd_curve_implicitize(c, 0, &mut imp), CagdStatus::OK);
            assert_eq!(
                cagd_implicit_coefficients(imp, std::ptr::null_mut(), 0, &mut needed),
                CagdStatus::ERR_BUFFER_TOO_SMALL
            );
            assert_eq!(needed, 6);
            assert_eq!(
                cagd_implicit_coefficients(imp, coefs.as_mut_ptr(), 6, &mut needed),
                CagdStatus::OK
            );
            assert_eq!(
                cagd_implicit_classify(imp, 0.0, 0.0, &mut v, &mut s, &mut d),
                CagdStatus::OK
            );
            assert_eq!(cagd_implicit_invert(imp, 0.6, 0.8, &mut t), CagdStatus::OK);
            assert_eq!(
                cagd_implicit_invert(imp, 2.0, 0.8, &mut t),
                CagdStatus::ERR_NOT_ON_CURVE
            );
            cagd_implicit_free(imp);
            cagd_curve_free(c);
        }
        // i-major: c00, c01, c02, c10, c11, c20 = 4, 0, -4, 0, 0, -4
        assert_eq!(coefs, [4.0, 0.0, -4.0, 0.0, 0.0, -4.0]);
        assert_eq!((v, s, d), (4.0, 1, f64::INFINITY));
        assert!(t > 0.0 && t < 1.0);
    }
}
