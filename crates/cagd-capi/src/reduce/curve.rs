//! Degree reduction from C: one curve with a report (`cagd_curve_reduce`), or many curves
//! of one degree through one cached operator (`cagd_curve_reduce_batch`, and
//! `cagd_curve_reduce_batch_bounded` with per-curve certified bounds).

use cagd_core::{Error, all_finite};
use cagd_reduce::{BoundLevel, reduce_batch, reduce_batch_with_bounds, reduce_with};

use crate::boundary::{
    CResult, Failure, OUT, boundary, checked_len, disjoint, handle_ref, into_handle, nonnull,
    out_ref, points_in, slice_out,
};
use crate::curve::CagdCurve;
use crate::flat::operator_for;
use crate::options::{CagdReduceOptions, read_options};
use crate::report::{CagdReport, ReportKind};
use crate::status::CagdStatus;

/// Reduces a curve of degree `n` to degree `opts->target` with `opts->method`, returning
/// the reduced curve and a report with the certified error bound at `opts->bound_level`
/// (default `CAGD_BOUND_TIGHT`: within 1.075× of the true error; `CAGD_BOUND_FAST`:
/// within 1.25×, fewer nodes; `CAGD_BOUND_NONE`: no bound, the cheapest call)
/// and, with `opts->measure`, the measured error. Rational curves are reduced in
/// homogeneous coordinates and stay rational. The operator of each `(method, n, m)` is
/// computed once in exact rational arithmetic and cached process-wide (thread-safe).
///
/// Parameters:
/// - `curve` (in): the curve, degree `n`.
/// - `opts` (in): the options (see `CagdReduceOptions`; start from
///   `cagd_reduce_options_init`). Borrowed for the call.
/// - `curve_out` (out): on `CAGD_OK`, the reduced curve of degree `opts->target`
///   (`(target + 1) * dim` doubles read back with `cagd_curve_points`), owned by the
///   caller: release with `cagd_curve_free`.
/// - `report_out` (out): on `CAGD_OK`, the report, owned by the caller: release with
///   `cagd_report_free`. Neither output is written on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `curve`, `opts`, `curve_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `opts->struct_size` is below
///   `sizeof(CagdReduceOptions)` (options not made by `cagd_reduce_options_init`),
///   `opts->method`, `opts->space` or `opts->bound_level` is not a valid code,
///   `l1` / `l2` of `CAGD_METHOD_PERTURB_G1` are not finite or not `> -1`,
///   `curve_out` and `report_out` are the same address, or a pointer is misaligned.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target >= n`, or `target` below the method's minimum
///   (1 for FARIN, PERTURB, GENERALIZED_INVERSE_ENDS; 3 for PERTURB_G1).
/// - `CAGD_ERR_TOO_MANY_CONSTRAINTS`: `r + p + 1 > target`, or `r` or `p` below -1
///   (CONSTRAINED_CHEBYSHEV, L2).
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a reduced weight of a rational curve is not positive.
/// - `CAGD_ERR_NON_FINITE`: an intermediate or result value overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `opts` NULL or a readable
/// `CagdReduceOptions` of `opts->struct_size` bytes; `curve_out` and `report_out` NULL
/// or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_reduce(
    curve: *const CagdCurve,
    opts: *const CagdReduceOptions,
    curve_out: *mut *mut CagdCurve,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let o = unsafe { read_options(opts) }?;
        nonnull(curve_out, "curve_out")?;
        nonnull(report_out, "report_out")?;
        if curve_out.addr() == report_out.addr() {
            return Err(Failure::invalid(
                "`curve_out` and `report_out` are the same address",
            ));
        }
        // SAFETY: as above; the two outputs do not overlap.
        let (c_out, r_out) = unsafe {
            (
                out_ref(curve_out, "curve_out")?,
                out_ref(report_out, "report_out")?,
            )
        };
        let red = reduce_with(&c.0, &o.rust_options()?)?;
        *c_out = into_handle(CagdCurve(red.curve));
        *r_out = into_handle(CagdReport {
            kind: ReportKind::Single(red.report),
            method: o.method,
        });
        Ok(())
    })
}

/// [`cagd_curve_reduce_batch`] with, optionally, a certified error bound per curve:
/// reduces `n_curves` polynomial curves of one degree `n` to degree `opts->target` with
/// one cached operator through cagd-reduce's batch kernel (several curves per vector),
/// no per-curve allocation. With `bounds_out == NULL` it is exactly
/// `cagd_curve_reduce_batch`; a bound costs two more small matrix products in the same
/// pass (the error curve's coefficients and its values at the bound level's nodes;
/// the error curve is seed 000 §14.4.3's, the node bound goes beyond the seed).
/// Only `opts->method`, `target`, `r`, `p`, `l1`, `l2` and (with `bounds_out`)
/// `bound_level` are used. Rational curves: pass their homogeneous points
/// `(w_i P_i, w_i)` as polynomial curves of dimension `dim + 1` (the bounds are then
/// homogeneous-space bounds).
///
/// Parameters:
/// - `points` (in): `n_curves * (n + 1) * dim` doubles, curve after curve, row-major inside
///   a curve: coordinate k of point j of curve c at `points[(c * (n + 1) + j) * dim + k]`.
///   Borrowed for the call.
/// - `n_curves` (in): number of curves; 0 is allowed (`*out_needed = 0`).
/// - `degree` (in): the common source degree `n`, `0..=64`.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `opts` (in): the options. Borrowed for the call.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `n_curves * (target + 1) * dim` doubles hold the reduced curves in the same layout.
///   May be NULL only when `out_cap == 0`. Not written on failure, but for
///   `CAGD_ERR_NON_FINITE` (contents then unspecified).
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `n_curves * (target + 1) * dim`.
/// - `bounds_out` (out, optional): NULL for no bounds; otherwise a buffer of `n_curves`
///   doubles that on `CAGD_OK` holds, for each curve, a certified upper bound of
///   `max_t |P(t) - Q(t)|` (model units, Euclidean norm of the `dim` coordinates, the
///   rounding of the reduced points included; `+inf` only if the computation overflowed)
///   at `opts->bound_level` (`CAGD_BOUND_FAST` or `CAGD_BOUND_TIGHT`). Not written on
///   failure, but for `CAGD_ERR_NON_FINITE` (contents then unspecified).
///
/// Returns:
/// - `CAGD_OK`: the reduced curves are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `points`, `opts` or `out_needed` is NULL, or `out` is NULL
///   with `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, a size formula overflows,
///   `opts->struct_size` below `sizeof(CagdReduceOptions)`, an invalid `opts->method` code
///   or `l1` / `l2`, `bounds_out` given with an invalid `opts->bound_level` or with
///   `CAGD_BOUND_NONE`, `bounds_out` overlapping `out`, or a pointer is misaligned.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `degree > 64`.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target >= degree` or below the method's minimum.
/// - `CAGD_ERR_TOO_MANY_CONSTRAINTS`: `r + p + 1 > target` or `r`, `p` below -1.
/// - `CAGD_ERR_NON_FINITE`: an input coordinate is NaN or infinite (the message gives
///   the point index counted over the whole batch), or a reduced coordinate overflows to
///   infinity (input near the largest double). On this status the contents of `out` and
///   `bounds_out` are unspecified (the input is not scanned before the kernel writes:
///   non-finite input is found from the output, where it always shows, every reduced
///   coordinate being a sum over all points of its curve with no term skipped);
///   `*out_needed` is written.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is below the formula; only `*out_needed` is
///   written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `points` must be NULL or point to `n_curves * (degree + 1) * dim` readable doubles;
/// `opts` NULL or readable; `out` NULL or `out_cap` writable doubles not overlapping
/// `points`; `out_needed` NULL or writable; `bounds_out` NULL or `n_curves` writable
/// doubles not overlapping `points`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_reduce_batch_bounded(
    points: *const f64,
    n_curves: usize,
    degree: usize,
    dim: usize,
    opts: *const CagdReduceOptions,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
    bounds_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        nonnull(points, "points")?;
        // SAFETY: the caller's contract (see # Safety).
        let o = unsafe { read_options(opts) }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        cagd_core::check_degree(degree)?;
        let n_points = checked_len(n_curves, degree + 1, "n_curves * (degree + 1)")?;
        // SAFETY: as above.
        let input = unsafe { points_in(points, n_points, dim, "points") }?;
        let op = operator_for(o.method()?, degree, o.target)?;
        let per_out = checked_len(o.target + 1, dim, "(target + 1) * dim")?;
        let needed = checked_len(n_curves, per_out, "n_curves * (target + 1) * dim")?;
        let level = if bounds_out.is_null() {
            None
        } else {
            match o.bound_level()? {
                BoundLevel::None => {
                    return Err(Failure::invalid(
                        "`bounds_out` is given but opts->bound_level is CAGD_BOUND_NONE",
                    ));
                }
                level => Some(level),
            }
        };
        let dst = dst.take(needed)?;
        let result = match level {
            None => reduce_batch(&op, input, dim, dst),
            Some(level) => {
                // SAFETY: non-NULL; `n_curves` writable doubles by the caller's contract;
                // checked for alignment and against overlapping `out` by the helper.
                let bounds = unsafe { bounds_slice(bounds_out, n_curves, dst) }?;
                reduce_batch_with_bounds(&op, input, dim, dst, bounds, level)
            }
        };
        result.map_err(|e| match e {
            // Non-finite input is found from the output (no scan before the kernel writes);
            // with finite input, a reduced coordinate overflowed (input near the largest
            // double; found by the C ABI fuzz harness, where this was reported as
            // CAGD_ERR_PANIC).
            Error::NonFinite { .. } if !all_finite(input) => e.into(),
            Error::NonFinite { .. } => Failure::new(
                CagdStatus::ERR_NON_FINITE,
                format!(
                    "a reduced coordinate overflows to infinity (input coordinates near the \
                     largest double): {e}"
                ),
            ),
            // Unreachable after the checks above; reported rather than hidden.
            Error::LengthMismatch { .. } => Failure::new(
                CagdStatus::ERR_PANIC,
                format!("internal error: batch failed after validation: {e}"),
            ),
            other => other.into(),
        })
    })
}

/// Reduces `n_curves` polynomial curves of one degree `n` to degree `opts->target` with
/// one cached operator through cagd-reduce's batch kernel (several curves per vector), no
/// per-curve allocation — the fast path for many curves. The signature of the first C ABI, kept: per-curve certified bounds are
/// [`cagd_curve_reduce_batch_bounded`]'s `bounds_out`. Only `opts->method`, `target`, `r`,
/// `p`, `l1` and `l2` are used. Rational curves: pass their homogeneous points
/// `(w_i P_i, w_i)` as polynomial curves of dimension `dim + 1`.
///
/// Parameters:
/// - `points` (in): `n_curves * (n + 1) * dim` doubles, curve after curve, row-major inside
///   a curve: coordinate k of point j of curve c at `points[(c * (n + 1) + j) * dim + k]`.
///   Borrowed for the call.
/// - `n_curves` (in): number of curves; 0 is allowed (`*out_needed = 0`).
/// - `degree` (in): the common source degree `n`, `0..=64`.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `opts` (in): the options. Borrowed for the call.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `n_curves * (target + 1) * dim` doubles hold the reduced curves in the same layout.
///   May be NULL only when `out_cap == 0`. Not written on failure, but for
///   `CAGD_ERR_NON_FINITE` (contents then unspecified).
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `n_curves * (target + 1) * dim`.
///
/// Returns:
/// - `CAGD_OK`: the reduced curves are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `points`, `opts` or `out_needed` is NULL, or `out` is NULL
///   with `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, a size formula overflows,
///   `opts->struct_size` below `sizeof(CagdReduceOptions)`, an invalid `opts->method` code
///   or `l1` / `l2`, or a pointer is misaligned.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `degree > 64`.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target >= degree` or below the method's minimum.
/// - `CAGD_ERR_TOO_MANY_CONSTRAINTS`: `r + p + 1 > target` or `r`, `p` below -1.
/// - `CAGD_ERR_NON_FINITE`: an input coordinate is NaN or infinite, or a reduced
///   coordinate overflows to infinity (input near the largest double). On this status the
///   contents of `out` are unspecified (non-finite input is found from the output, not by
///   a scan before the kernel writes); `*out_needed` is written.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is below the formula; only `*out_needed` is
///   written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `points` must be NULL or point to `n_curves * (degree + 1) * dim` readable doubles;
/// `opts` NULL or readable; `out` NULL or `out_cap` writable doubles not overlapping
/// `points`; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_reduce_batch(
    points: *const f64,
    n_curves: usize,
    degree: usize,
    dim: usize,
    opts: *const CagdReduceOptions,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    // SAFETY: the same contract, with no bounds buffer.
    unsafe {
        cagd_curve_reduce_batch_bounded(
            points,
            n_curves,
            degree,
            dim,
            opts,
            out,
            out_cap,
            out_needed,
            std::ptr::null_mut(),
        )
    }
}

/// The caller's `bounds_out` as a slice of `n` doubles, after the alignment check and a
/// check that it does not overlap the output slice `out`.
///
/// # Safety
/// `ptr` must be non-NULL and point to `n` writable doubles that no other live reference
/// covers except, possibly, `out` (rejected here).
unsafe fn bounds_slice<'a>(ptr: *mut f64, n: usize, out: &[f64]) -> CResult<&'a mut [f64]> {
    if !ptr.is_aligned() {
        return Err(Failure::invalid("argument `bounds_out` is misaligned"));
    }
    disjoint(ptr, n, out.as_ptr(), out.len(), "`bounds_out` and `out`")?;
    if n == 0 {
        return Ok(&mut []);
    }
    // SAFETY: the caller's contract; non-NULL, aligned, not overlapping `out`.
    Ok(unsafe { std::slice::from_raw_parts_mut(ptr, n) })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn non_finite_input_is_found_from_the_output() {
        // No scan precedes the kernel: NaN / infinity anywhere comes back as
        // CAGD_ERR_NON_FINITE naming the batch point, with and without bounds; finite input
        // near the largest double that overflows is named as an overflow.
        let (k, n, dim) = (700usize, 7usize, 3usize);
        let o = CagdReduceOptions {
            target: 4,
            ..CagdReduceOptions::default()
        };
        let base: Vec<f64> = (0..k * (n + 1) * dim)
            .map(|i| ((i * 7919 % 1001) as f64 - 500.0) / 97.0)
            .collect();
        for (curve, point, coord) in [(0usize, 0usize, 0usize), (333, 5, 2), (k - 1, n, 1)] {
            for bad in [f64::NAN, f64::INFINITY] {
                let mut input = base.clone();
                let idx = curve * (n + 1) + point;
                input[idx * dim + coord] = bad;
                for with_bounds in [false, true] {
                    let mut out = vec![0.0; k * (o.target + 1) * dim];
                    let mut bounds = vec![0.0; k];
                    let mut needed = 0;
                    let bp = if with_bounds {
                        bounds.as_mut_ptr()
                    } else {
                        std::ptr::null_mut()
                    };
                    // SAFETY: buffers of the documented sizes.
                    let s = unsafe {
                        cagd_curve_reduce_batch_bounded(
                            input.as_ptr(),
                            k,
                            n,
                            dim,
                            &o,
                            out.as_mut_ptr(),
                            out.len(),
                            &mut needed,
                            bp,
                        )
                    };
                    assert_eq!(s, CagdStatus::ERR_NON_FINITE);
                    assert_eq!(needed, out.len());
                    let msg = crate::last_error_string();
                    assert!(msg.contains(&format!("[{idx}][{coord}]")), "{msg}");
                }
            }
        }
        let mut input = base;
        for (j, x) in input[(n + 1) * dim..2 * (n + 1) * dim]
            .iter_mut()
            .enumerate()
        {
            *x = if j % 2 == 0 { f64::MAX } else { -f64::MAX };
        }
        let mut out = vec![0.0; k * (o.target + 1) * dim];
        let mut needed = 0;
        // SAFETY: as above.
        let s = unsafe {
            cagd_curve_reduce_batch(
                input.as_ptr(),
                k,
                n,
                dim,
                &o,
                out.as_mut_ptr(),
                out.len(),
                &mut needed,
            )
        };
        assert_eq!(s, CagdStatus::ERR_NON_FINITE);
        assert!(crate::last_error_string().contains("overflows"));
    }
}
