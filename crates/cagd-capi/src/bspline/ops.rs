//! Operations on `CagdBSpline`: evaluation, derivatives, knot insertion, Bézier
//! extraction.

use crate::boundary::{
    Failure, OUT, boundary, checked_len, handle_ref, into_handle, out_ref, slice_out,
};
use crate::bspline::CagdBSpline;
use crate::curve::{CagdCurveList, Piece};
use crate::status::CagdStatus;

/// Evaluates a spline at one parameter `t` (de Boor; in homogeneous coordinates for a
/// NURBS curve). `t` in the domain `[a, b]` (`cagd_bspline_domain`) is the curve; at `b`
/// the last piece is used (so a clamped spline gives its last control point); other finite
/// `t` extrapolate the first or last piece.
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `t` (in): the parameter, finite.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `dim` doubles hold
///   the point. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `dim`.
///
/// Returns:
/// - `CAGD_OK`: the point is in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `t` is NaN or infinite, or a pointer is misaligned.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < dim`; only `*out_needed` is written.
/// - `CAGD_ERR_NON_FINITE`: the point overflows f64 (`t` far outside the domain, or
///   coordinates near the limits of f64); nothing is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `out` NULL or `out_cap` writable
/// doubles; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_eval(
    spline: *const CagdBSpline,
    t: f64,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(spline, "spline") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let p = s.0.eval(t)?;
        dst.copy_from(&p)
    })
}

/// Evaluates the derivatives of orders `0..=order` of a spline at `t` (Euclidean also for
/// NURBS, by the quotient rule). At an interior knot the derivative from the right is
/// returned (from the left at the end of the domain); orders above the degree of a
/// polynomial spline are zero.
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `t` (in): the parameter, finite.
/// - `order` (in): the highest derivative order, `0..=130`.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `(order + 1) * dim` doubles hold the derivatives: coordinate k of the derivative of
///   order j at `out[j * dim + k]` (order 0 is the point). May be NULL only when
///   `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `(order + 1) * dim`.
///
/// Returns:
/// - `CAGD_OK`: the derivatives are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `t` is NaN or infinite, `order > 130`, or a pointer is
///   misaligned.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < (order + 1) * dim`; only `*out_needed` is
///   written.
/// - `CAGD_ERR_NON_FINITE`: a derivative overflows f64 (`t` far outside the domain,
///   close knots, or coordinates near the limits of f64); nothing is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `out` NULL or `out_cap` writable
/// doubles; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_derivatives(
    spline: *const CagdBSpline,
    t: f64,
    order: usize,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(spline, "spline") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let ders = s.0.derivatives(t, order)?;
        let needed = checked_len(ders.len(), s.0.dim(), "(order + 1) * dim")?;
        dst.fill_with(needed, |buf| {
            for (chunk, d) in buf.chunks_exact_mut(s.0.dim()).zip(&ders) {
                chunk.copy_from_slice(d);
            }
        })
    })
}

/// Inserts the knot `t` `times` times (Boehm's algorithm): the same curve on a finer knot
/// vector, with `times` more control points and knots.
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `t` (in): the knot, finite, in the domain `[a, b]`.
/// - `times` (in): how many times to insert it; the multiplicity of `t` afterwards must be
///   at most `degree + 1`. 0 gives a copy.
/// - `spline_out` (out): on `CAGD_OK`, the refined spline (`n_points + times` control
///   points, `n_points + degree + 1 + times` knots), owned by the caller: release with
///   `cagd_bspline_free`. Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*spline_out` holds the refined spline.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `spline_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `t` is NaN, infinite or outside the domain, or a pointer
///   is misaligned.
/// - `CAGD_ERR_MULTIPLICITY`: the multiplicity of `t` would exceed `degree + 1`.
/// - `CAGD_ERR_NON_FINITE`: a new control point overflows f64 (coordinates near the limits of f64, or their
///   products with the weights).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `spline_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_insert_knot(
    spline: *const CagdBSpline,
    t: f64,
    times: usize,
    spline_out: *mut *mut CagdBSpline,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(spline, "spline") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(spline_out, "spline_out") }?;
        cagd_core::check_finite_param("t", t)?;
        if times > s.0.degree() + 1 {
            // Rejected before any work: the multiplicity would exceed degree + 1 anyway.
            return Err(cagd_core::Error::MultiplicityAboveDegree {
                knot: t,
                mult: times,
                degree: s.0.degree(),
            }
            .into());
        }
        *out = into_handle(CagdBSpline(s.0.insert_knot(t, times)?));
        Ok(())
    })
}

/// Splits a spline into its Bézier pieces, one per non-empty knot span of the domain, in
/// order (rational pieces for a NURBS curve). Piece `i` on `[a_i, b_i]` is the Bézier
/// curve of degree `degree` with `piece_i(s) = spline(a_i + s (b_i - a_i))`.
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `list_out` (out): on `CAGD_OK`, the pieces (read with `cagd_curvelist_count`,
///   `cagd_curvelist_get`, `cagd_curvelist_interval`), owned by the caller: release with
///   `cagd_curvelist_free`. Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*list_out` holds the pieces.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `list_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_NON_FINITE`: a piece overflows (control points near the `double` range).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `list_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_to_beziers(
    spline: *const CagdBSpline,
    list_out: *mut *mut CagdCurveList,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(spline, "spline") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(list_out, "list_out") }?;
        let pieces: Vec<Piece> =
            s.0.to_beziers()?
                .into_iter()
                .map(|seg| Piece {
                    start: seg.start,
                    end: seg.end,
                    curve: seg.curve,
                    bound: None,
                })
                .collect();
        if pieces.is_empty() {
            // A valid spline has a domain of positive length, so at least one span.
            return Err(Failure::new(
                CagdStatus::ERR_PANIC,
                "internal error: a spline with an empty domain",
            ));
        }
        *out = into_handle(CagdCurveList(pieces));
        Ok(())
    })
}
