//! `cagd_bezier_reduce`: one Bézier curve reduced from arrays into caller buffers, with the
//! report in a caller-owned struct or none — `cagd_curve_reduce` without the two handles.

use cagd_core::BezierCurve;
use cagd_reduce::reduce_with;

use super::input::{curve_in, result_weights};
use super::kernel::{apply_one, operator_for};
use super::report::{CagdBezierReport, checked_report};
use crate::boundary::{OUT, boundary, checked_len, disjoint, nonnull, slice_out};
use crate::options::{CagdReduceOptions, read_options};
use crate::status::CagdStatus;

/// Reduces one Bézier curve of degree `n = n_points - 1` to degree `opts->target`, reading
/// the control points from arrays and writing the result to caller buffers: the
/// handle-free form of `cagd_curve_reduce` (same methods, same options, same statuses, and
/// the same points bit for bit), for hot loops where creating and freeing a curve and a
/// report handle would cost as much as the reduction.
///
/// With `report_out` NULL no report is formed: for a polynomial curve only the reduced
/// points are computed (the certified bound, most of the cost of `cagd_curve_reduce`, and
/// the sampling of `opts->measure` are skipped). A rational curve is reduced in
/// homogeneous coordinates as by the handle call, bound included (but not sampled).
///
/// Parameters:
/// - `points` (in): `n_points * dim` doubles, row-major: coordinate k of control point i at
///   `points[i * dim + k]`. Borrowed for the call.
/// - `n_points` (in): number of control points, `1..=65`.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `weights` (in): `n_points` weights, finite and `>= DBL_MIN` (not subnormal), for a rational curve; NULL for a
///   polynomial one. Borrowed for the call.
/// - `opts` (in): the options, as for `cagd_curve_reduce` (start from
///   `cagd_reduce_options_init`). Borrowed for the call.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `(opts->target + 1) * dim` doubles hold the reduced control points, row-major
///   (Euclidean points for a rational curve). May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles (0 asks the size).
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `(opts->target + 1) * dim`.
/// - `weights_out` (out): rational curves only, a buffer of `weights_out_cap` doubles; on
///   `CAGD_OK` its first `opts->target + 1` doubles hold the reduced weights. Ignored (may
///   be NULL) when `weights` is NULL.
/// - `weights_out_cap` (in): capacity of `weights_out` in doubles.
/// - `report_out` (out): NULL (no report), or a caller-owned `CagdBezierReport` whose
///   `struct_size` the caller set to `sizeof(CagdBezierReport)`; on `CAGD_OK` it holds the
///   report. Nothing but `*out_needed` is written on failure.
///
/// Returns:
/// - `CAGD_OK`: the outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `points`, `opts` or `out_needed` is NULL; `out` is NULL with
///   `out_cap > 0`; or `weights_out` is NULL for a rational curve.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, `n_points * dim` or the output size overflows,
///   `opts->struct_size` below `sizeof(CagdReduceOptions)`, an invalid `opts->method` or
///   `opts->space` code, `l1` / `l2` of `CAGD_METHOD_PERTURB_G1` not finite or not `> -1`,
///   `report_out->struct_size` below `sizeof(CagdBezierReport)`, two outputs overlap, or a
///   pointer is misaligned.
/// - `CAGD_ERR_NOT_ENOUGH_POINTS`: `n_points == 0`.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n_points > 65`.
/// - `CAGD_ERR_NON_FINITE`: an input coordinate is NaN or infinite (the message gives the
///   point and coordinate), or a reduced coordinate overflows.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: an input weight is not finite and `>= DBL_MIN`, or a reduced
///   weight of a rational curve is not positive.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target >= n`, or `target` below the method's minimum.
/// - `CAGD_ERR_TOO_MANY_CONSTRAINTS`: `r + p + 1 > target`, or `r` or `p` below -1.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < (target + 1) * dim`, or (rational)
///   `weights_out_cap < target + 1`; only `*out_needed` is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `points` must be NULL or point to `n_points * dim` readable doubles; `weights` NULL or
/// `n_points` readable doubles; `opts` NULL or a readable `CagdReduceOptions` of
/// `opts->struct_size` bytes; `out` NULL or `out_cap` writable doubles; `out_needed` NULL
/// or writable; `weights_out` NULL or `weights_out_cap` writable doubles; `report_out` NULL
/// or `report_out->struct_size` writable bytes. No output may overlap an input.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bezier_reduce(
    points: *const f64,
    n_points: usize,
    dim: usize,
    weights: *const f64,
    opts: *const CagdReduceOptions,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
    weights_out: *mut f64,
    weights_out_cap: usize,
    report_out: *mut CagdBezierReport,
) -> CagdStatus {
    boundary(|| {
        nonnull(points, "points")?;
        // SAFETY: the caller's contract (see # Safety).
        let o = unsafe { read_options(opts) }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        // SAFETY: as above.
        let report = unsafe { checked_report(report_out) }?;
        // SAFETY: as above.
        let curve = unsafe { curve_in(points, n_points, dim, weights) }?;
        let mut rust_opts = o.rust_options()?;
        // Without a report nobody reads a measured error: do not sample.
        rust_opts.measure &= report.is_some();
        // Checks the degree pair (and builds or finds the cached operator) before the size
        // is answered, so that a size query of an impossible reduction fails with its
        // reason.
        let op = operator_for(rust_opts.method, curve.degree(), o.target)?;
        let m1 = o.target + 1;
        let needed = checked_len(m1, dim, "(target + 1) * dim")?;
        let dst = dst.take(needed)?;
        // SAFETY: as above.
        let (w_dst, w_len) =
            unsafe { result_weights(&curve, dst, weights_out, weights_out_cap, m1) }?;
        if let Some(r) = &report {
            let (a, n) = (r.addr(), r.len());
            disjoint(dst.as_ptr(), needed, a, n, "`out` and `report_out`")?;
            disjoint(weights_out, w_len, a, n, "`weights_out` and `report_out`")?;
        }
        match (report, curve.weights) {
            (None, None) => apply_one(&op, curve.points, dim, dst)?,
            (report, w) => {
                let c = match w {
                    None => BezierCurve::new(curve.points.to_vec(), dim)?,
                    Some(w) => BezierCurve::new_rational(curve.points.to_vec(), w.to_vec(), dim)?,
                };
                let red = reduce_with(&c, &rust_opts)?;
                dst.copy_from_slice(red.curve.points());
                if let (Some(wd), Some(wr)) = (w_dst, red.curve.weights()) {
                    wd.copy_from_slice(wr);
                }
                if let Some(r) = report {
                    r.write(&CagdBezierReport::of(&red.report, o.method));
                }
            }
        }
        Ok(())
    })
}
