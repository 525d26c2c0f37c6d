//! Operations on `CagdCurve`: evaluation, degree elevation, subdivision, sub-interval.

use cagd_core::check_finite_param;

use crate::boundary::{
    CResult, Failure, OUT, boundary, checked_len, handle_ref, into_handle, nonnull, out_ref,
    slice_in, slice_out,
};
use crate::curve::CagdCurve;
use crate::status::CagdStatus;

/// Evaluates a curve at one parameter `t` (de Casteljau; in homogeneous coordinates for a
/// rational curve). `t` in `[0, 1]` is the curve; other finite `t` extrapolate.
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `t` (in): the parameter, finite.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `dim` doubles hold
///   the point. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `dim`.
///
/// Returns:
/// - `CAGD_OK`: the point is in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `t` is NaN or infinite, or a pointer is misaligned.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < dim`; only `*out_needed` is written.
/// - `CAGD_ERR_NON_FINITE`: the point overflows f64 (`t` far outside `[0, 1]`, or
///   coordinates near the limits of f64); nothing is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `out` NULL or `out_cap` writable doubles;
/// `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_eval(
    curve: *const CagdCurve,
    t: f64,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        check_finite_param("t", t)?;
        dst.fill_with(c.0.dim(), |p| c.0.eval_into(t, p))
    })
}

/// Evaluates a curve at `n_params` parameters at once.
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `params` (in): `n_params` finite doubles (any order; outside `[0, 1]` extrapolates).
///   Borrowed for the call.
/// - `n_params` (in): number of parameters; 0 is allowed (nothing is written but
///   `*out_needed = 0`).
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `n_params * dim`
///   doubles hold the points, row-major: coordinate k of the point at `params[j]` is
///   `out[j * dim + k]`. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `n_params * dim`.
///
/// Returns:
/// - `CAGD_OK`: the points are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `curve`, `params` or `out_needed` is NULL, or `out` is NULL
///   with `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a parameter is NaN or infinite (the message gives its
///   index), `n_params * dim` overflows, or a pointer is misaligned.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < n_params * dim`; only `*out_needed` is written.
/// - `CAGD_ERR_NON_FINITE`: a point overflows f64 (a parameter far outside `[0, 1]`,
///   or coordinates near the limits of f64); nothing is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `params` NULL or `n_params` readable
/// doubles; `out` NULL or `out_cap` writable doubles; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_eval_many(
    curve: *const CagdCurve,
    params: *const f64,
    n_params: usize,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        nonnull(params, "params")?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        // SAFETY: as above.
        let ts = unsafe { slice_in(params, n_params, "params") }?;
        if let Some(j) = ts.iter().position(|t| !t.is_finite()) {
            return Err(Failure::invalid(format!(
                "params[{j}] = {} is not finite",
                ts[j]
            )));
        }
        let dim = c.0.dim();
        let needed = checked_len(n_params, dim, "n_params * dim")?;
        dst.fill_with(needed, |out| {
            for (t, p) in ts.iter().zip(out.chunks_exact_mut(dim)) {
                c.0.eval_into(*t, p);
            }
        })
    })
}

/// Elevates the degree of a curve by `r` (the same curve, `n + r + 1` control points;
/// rational curves are elevated in homogeneous coordinates). `r = 0` gives a copy.
///
/// Parameters:
/// - `curve` (in): the curve, degree `n`.
/// - `r` (in): how many degrees to add; `n + r <= 64`.
/// - `curve_out` (out): on `CAGD_OK`, a new curve of degree `n + r` owned by the caller
///   (release with `cagd_curve_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*curve_out` holds the elevated curve.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `curve_out` is NULL.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n + r > 64`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_NON_FINITE`: a point of the result overflows f64 (a rational curve's
///   homogeneous points `w_i P_i` beyond f64).
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: an elevated weight rounds above the largest double
///   (weights within a rounding of `DBL_MAX`).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `curve_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_elevate(
    curve: *const CagdCurve,
    r: usize,
    curve_out: *mut *mut CagdCurve,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(curve_out, "curve_out") }?;
        *out = into_handle(CagdCurve(c.0.elevate(r)?));
        Ok(())
    })
}

/// Splits a curve at `t` into the pieces on `[0, t]` and `[t, 1]`, each reparametrised to
/// `[0, 1]` and of the same degree (de Casteljau; weights split too for a rational curve).
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `t` (in): the split parameter, finite (usually in `(0, 1)`; other values extrapolate).
/// - `left_out` (out): on `CAGD_OK`, the piece on `[0, t]`, owned by the caller.
/// - `right_out` (out): on `CAGD_OK`, the piece on `[t, 1]`, owned by the caller. Must
///   differ from `left_out`. Release both with `cagd_curve_free`; neither is written on
///   failure.
///
/// Returns:
/// - `CAGD_OK`: both pieces are written.
/// - `CAGD_ERR_NULL_POINTER`: `curve`, `left_out` or `right_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `t` is NaN or infinite, `left_out == right_out`, or a
///   pointer is misaligned.
/// - `CAGD_ERR_NON_FINITE`: a piece's point overflows f64 (`t` far outside `[0, 1]`).
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a rational piece's weight is not finite and `> 0`
///   (`t` outside `[0, 1]`, beyond a pole of the curve's weight function).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `left_out` and `right_out` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_subdivide(
    curve: *const CagdCurve,
    t: f64,
    left_out: *mut *mut CagdCurve,
    right_out: *mut *mut CagdCurve,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        nonnull(left_out, "left_out")?;
        nonnull(right_out, "right_out")?;
        distinct_outputs(left_out, right_out)?;
        // SAFETY: as above; the two pointers differ.
        let (l_out, r_out) = unsafe {
            (
                out_ref(left_out, "left_out")?,
                out_ref(right_out, "right_out")?,
            )
        };
        let (l, r) = c.0.subdivide(t)?;
        *l_out = into_handle(CagdCurve(l));
        *r_out = into_handle(CagdCurve(r));
        Ok(())
    })
}

/// Rejects two handle outputs that alias (the first handle would leak).
fn distinct_outputs(a: *mut *mut CagdCurve, b: *mut *mut CagdCurve) -> CResult<()> {
    if std::ptr::eq(a, b) {
        Err(Failure::invalid(
            "`left_out` and `right_out` are the same pointer; the first curve would leak",
        ))
    } else {
        Ok(())
    }
}

/// The piece of a curve on `[a, b]`, reparametrised to `[0, 1]`, same degree. `[a, b]` may
/// leave `[0, 1]` (exact extrapolation for polynomial curves; for a rational curve the
/// piece's weights may then become non-positive, which is reported).
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `a`, `b` (in): finite interval ends with `a < b`.
/// - `curve_out` (out): on `CAGD_OK`, the new curve owned by the caller (release with
///   `cagd_curve_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*curve_out` holds the piece.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `curve_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `a` or `b` is NaN or infinite, `a >= b`, or a pointer is
///   misaligned.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: rational curve whose piece outside `[0, 1]` has a
///   weight `<= 0`.
/// - `CAGD_ERR_NON_FINITE`: a point of the piece overflows f64 (`[a, b]` far outside
///   `[0, 1]`).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `curve_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_segment(
    curve: *const CagdCurve,
    a: f64,
    b: f64,
    curve_out: *mut *mut CagdCurve,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(curve_out, "curve_out") }?;
        *out = into_handle(CagdCurve(c.0.segment(a, b)?));
        Ok(())
    })
}
