//! `cagd_bezier_elevate`: one Bézier curve elevated from arrays into caller buffers —
//! `cagd_curve_elevate` without the handles.

use cagd_core::{BezierCurve, check_degree};

use super::input::{curve_in, result_weights};
use super::kernel::{Overflow, elevate_one};
use crate::boundary::{OUT, boundary, checked_len, nonnull, slice_out};
use crate::status::CagdStatus;

/// Elevates one Bézier curve of degree `n = n_points - 1` by `r` degrees
/// (`Q_i = sum_j C(n,j) C(r,i-j) / C(n+r,i) P_j`, seed 001 §3.2; rational curves in
/// homogeneous coordinates), reading the control points from arrays and writing the result
/// to caller buffers: the handle-free form of `cagd_curve_elevate`, with the same points
/// and weights bit for bit.
///
/// Parameters:
/// - `points` (in): `n_points * dim` doubles, row-major: coordinate k of control point i at
///   `points[i * dim + k]`. Borrowed for the call.
/// - `n_points` (in): number of control points, `1..=65`.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `weights` (in): `n_points` weights, finite and `>= DBL_MIN` (not subnormal), for a rational curve; NULL for a
///   polynomial one. Borrowed for the call.
/// - `r` (in): how many degrees to add; `n + r <= 64`; 0 copies.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `(n_points + r) * dim` doubles hold the elevated control points, row-major (Euclidean
///   for a rational curve). May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles (0 asks the size).
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `(n_points + r) * dim`.
/// - `weights_out` (out): rational curves only, a buffer of `weights_out_cap` doubles; on
///   `CAGD_OK` its first `n_points + r` doubles hold the elevated weights. Ignored (may be
///   NULL) when `weights` is NULL.
/// - `weights_out_cap` (in): capacity of `weights_out` in doubles.
///
/// Returns:
/// - `CAGD_OK`: the outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `points` or `out_needed` is NULL; `out` is NULL with
///   `out_cap > 0`; or `weights_out` is NULL for a rational curve.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, a size overflows, `out` and `weights_out`
///   overlap, or a pointer is misaligned.
/// - `CAGD_ERR_NOT_ENOUGH_POINTS`: `n_points == 0`.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n_points > 65` or `n_points - 1 + r > 64`.
/// - `CAGD_ERR_NON_FINITE`: an input coordinate is NaN or infinite (the message gives the
///   point and coordinate), or an elevated coordinate overflows (input near the largest
///   double; `out` may then be partly written).
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a weight is not finite and `>= DBL_MIN`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < (n_points + r) * dim`, or (rational)
///   `weights_out_cap < n_points + r`; only `*out_needed` is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `points` must be NULL or point to `n_points * dim` readable doubles; `weights` NULL or
/// `n_points` readable doubles; `out` NULL or `out_cap` writable doubles; `out_needed` NULL
/// or writable; `weights_out` NULL or `weights_out_cap` writable doubles. No output may
/// overlap an input.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bezier_elevate(
    points: *const f64,
    n_points: usize,
    dim: usize,
    weights: *const f64,
    r: usize,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
    weights_out: *mut f64,
    weights_out_cap: usize,
) -> CagdStatus {
    boundary(|| {
        nonnull(points, "points")?;
        // SAFETY: the caller's contract (see # Safety).
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        // SAFETY: as above.
        let curve = unsafe { curve_in(points, n_points, dim, weights) }?;
        let n = curve.degree();
        check_degree(n.saturating_add(r))?;
        let m1 = n + r + 1;
        let needed = checked_len(m1, dim, "(n_points + r) * dim")?;
        let dst = dst.take(needed)?;
        // SAFETY: as above.
        let (w_dst, _) = unsafe { result_weights(&curve, dst, weights_out, weights_out_cap, m1) }?;
        match (curve.weights, w_dst) {
            (Some(w), Some(wd)) => {
                let c = BezierCurve::new_rational(curve.points.to_vec(), w.to_vec(), dim)?;
                let e = c.elevate(r)?;
                let we = e.weights().unwrap_or_default();
                // The Euclidean points of the elevated curve (homogeneous points over the
                // elevated weights) may overflow where the homogeneous ones do not: no
                // result then (found by the C ABI fuzz harness: `-inf` with `CAGD_OK`).
                if !e.points().iter().chain(we).all(|x| x.is_finite()) {
                    return Err(Overflow::failure(0));
                }
                dst.copy_from_slice(e.points());
                wd.copy_from_slice(we);
            }
            _ => {
                // The kernel `BezierCurve::elevate` uses for a polynomial curve, straight
                // into the caller's buffer (the input is finite, so only an overflow can
                // fail, and then `dst` holds no result: the status says so).
                elevate_one(curve.points, dim, r, dst).map_err(|_| Overflow::failure(0))?;
            }
        }
        Ok(())
    })
}
