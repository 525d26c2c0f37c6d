//! Reduction of a Bézier curve to a tolerance from C: adaptive subdivision, every piece
//! reduced, the pieces merged into a `C^k` B-spline (`cagd_curve_reduce_to_tolerance`), or
//! seed 000's stepwise Algorithm 14.2.1 (`cagd_curve_reduce_to_tolerance_stepwise`).

use cagd_reduce::{
    PiecewiseReduction, ToleranceOptions, reduce_to_tolerance, reduce_to_tolerance_alg_14_2_1,
};

use crate::boundary::{CResult, Failure, boundary, handle_ref, into_handle, nonnull, out_ref};
use crate::bspline::CagdBSpline;
use crate::curve::CagdCurve;
use crate::options::{CagdReduceOptions, read_options};
use crate::report::{CagdReport, ReportKind};
use crate::status::CagdStatus;

/// Which reduction to a tolerance.
#[derive(Clone, Copy)]
enum Algorithm {
    Adaptive,
    Stepwise,
}

/// The common body of the two entry points.
///
/// # Safety
/// As the entry points.
unsafe fn run(
    algorithm: Algorithm,
    curve: *const CagdCurve,
    opts: *const CagdReduceOptions,
    spline_out: *mut *mut CagdBSpline,
    report_out: *mut *mut CagdReport,
) -> CResult<()> {
    // SAFETY: forwarded contract.
    let c = unsafe { handle_ref(curve, "curve") }?;
    // SAFETY: as above.
    let o = unsafe { read_options(opts) }?;
    nonnull(spline_out, "spline_out")?;
    nonnull(report_out, "report_out")?;
    if spline_out.addr() == report_out.addr() {
        return Err(Failure::invalid(
            "`spline_out` and `report_out` are the same address",
        ));
    }
    // SAFETY: as above; the two outputs do not overlap.
    let (s_out, r_out) = unsafe {
        (
            out_ref(spline_out, "spline_out")?,
            out_ref(report_out, "report_out")?,
        )
    };
    let topts = ToleranceOptions {
        measure: o.measure,
        max_depth: o.max_depth,
        ..ToleranceOptions::new(o.method()?, o.target, o.tolerance, o.continuity)
    };
    let PiecewiseReduction {
        spline,
        pieces,
        report,
    } = match algorithm {
        Algorithm::Adaptive => reduce_to_tolerance(&c.0, &topts)?,
        Algorithm::Stepwise => reduce_to_tolerance_alg_14_2_1(&c.0, &topts)?,
    };
    *s_out = into_handle(CagdBSpline(spline));
    *r_out = into_handle(CagdReport {
        kind: ReportKind::Piecewise { report, pieces },
        method: o.method,
    });
    Ok(())
}

/// Reduces a Bézier curve of degree `n` (polynomial or rational) to a B-spline of degree
/// `opts->target` whose certified distance to the curve is at most `opts->tolerance`, with
/// `C^k` joins, `k = opts->continuity` (seed 000 §14.2.2 and Algorithm 14.2.1 generalised
/// to every linear method; SPEC-reduce §2.2). The breakpoints are placed by marching
/// along the parameter, each piece as long as its certified bound (of `opts->method`, the
/// rounding of extracting the piece included) allows within the tolerance (fewer pieces
/// than the seed's midpoint subdivision, which `cagd_curve_reduce_to_tolerance_stepwise`
/// keeps); the reduced pieces are
/// merged into one spline on `[0, 1]` whose interior knots have multiplicity
/// `target - k`; what the merge moved is added to the bound.
///
/// Options used: `method` (with `r`, `p`, `l1`, `l2`), `target`, `tolerance`,
/// `continuity`, `measure`, `max_depth`; `space` is ignored (the numbers are Euclidean).
///
/// Parameters:
/// - `curve` (in): the curve, degree `n > target`.
/// - `opts` (in): the options (start from `cagd_reduce_options_init`, then set at least
///   `tolerance`). Borrowed for the call.
/// - `spline_out` (out): on `CAGD_OK`, the reduced spline of degree `target` on `[0, 1]`
///   (NURBS when the curve is rational), owned by the caller: release with
///   `cagd_bspline_free`. Its size is known only afterwards (`cagd_bspline_n_points`).
/// - `report_out` (out): on `CAGD_OK`, the report, owned by the caller: release with
///   `cagd_report_free`. `cagd_report_bound` gives the certified bound of the whole
///   (`<= tolerance`); `cagd_report_piecewise` the piece count and depth;
///   `cagd_report_pieces` the reduced pieces with their intervals and bounds. Neither
///   output is written on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `curve`, `opts`, `spline_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `opts->struct_size` is below
///   `sizeof(CagdReduceOptions)`, `opts->method` is not a valid code, `tolerance` is not
///   finite and `> 0` (the default 0 must be changed), `continuity >= target`, the method
///   does not keep derivatives up to order `continuity` at both ends (use
///   `CAGD_METHOD_L2` or `CAGD_METHOD_CONSTRAINED_CHEBYSHEV` with `r = p = continuity`),
///   `l1` / `l2` invalid, the two outputs are the same address, or a pointer is
///   misaligned.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target >= n` or below the method's minimum.
/// - `CAGD_ERR_TOO_MANY_CONSTRAINTS`: `r + p + 1 > target`, or `r`, `p` below -1.
/// - `CAGD_ERR_NO_CONVERGENCE`: the tolerance was not reached within `max_depth`
///   subdivision levels (at most 52 are used) or 2^20 pieces (the message gives the bound
///   reached).
/// - `CAGD_ERR_CONDITION_NOT_MET`: the pieces do not join within `tolerance / 128` (only
///   for a tolerance near the rounding level); a piece above the tolerance has a rounding
///   level `2 (n + 3) eps max |P_i|` above half of it (no subdivision can help: e.g. a
///   curve far from the origin); or the subdivision needs too much work (more than `2^27`
///   pieces reduced times `((n + 1)^2 + 64) (dim + 1)`, bounded work).
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a reduced weight of a rational piece is not positive.
/// - `CAGD_ERR_NON_FINITE`: an intermediate or result value overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `opts` NULL or a readable
/// `CagdReduceOptions` of `opts->struct_size` bytes; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_reduce_to_tolerance(
    curve: *const CagdCurve,
    opts: *const CagdReduceOptions,
    spline_out: *mut *mut CagdBSpline,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    // SAFETY: the caller's contract (see # Safety).
    boundary(|| unsafe { run(Algorithm::Adaptive, curve, opts, spline_out, report_out) })
}

/// Reduces a polynomial Bézier curve of degree `n` to a `C^0` B-spline of degree
/// `opts->target` within `opts->tolerance` by seed 000's Algorithm 14.2.1 as corrected in
/// SPEC-reduce §2.2: one degree at a time by control-point perturbation (eq. 14.2.5),
/// subdividing before each step so that every step's error, as eq. 14.2.11 predicts it,
/// stays below `tolerance / (n - target)`. The per-step maxima of the certified bounds are
/// read with `cagd_report_step_bounds` (their sum is the seed's certified total; one may
/// exceed the prediction by the certified bound's margin); `cagd_report_bound`, the largest
/// sum along a piece's steps, is `<= tolerance`.
///
/// Options used: `method` (must be `CAGD_METHOD_PERTURB`), `target`, `tolerance`,
/// `continuity` (must be 0), `measure`, `max_depth` (total over all steps).
///
/// Parameters:
/// - `curve` (in): the curve, polynomial, degree `n > target`.
/// - `opts` (in): the options. Borrowed for the call.
/// - `spline_out` (out): on `CAGD_OK`, the reduced spline of degree `target` on `[0, 1]`,
///   owned by the caller: release with `cagd_bspline_free`.
/// - `report_out` (out): on `CAGD_OK`, the report, owned by the caller: release with
///   `cagd_report_free`. Neither output is written on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `curve`, `opts`, `spline_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `opts->struct_size` is below
///   `sizeof(CagdReduceOptions)`, an invalid `opts->method` code, `tolerance` not finite
///   and `> 0`, the two outputs are the same address, or a pointer is misaligned.
/// - `CAGD_ERR_CONDITION_NOT_MET`: `method` is not `CAGD_METHOD_PERTURB`,
///   `continuity > 0`, or the curve is rational (the algorithm's preconditions; use
///   `cagd_curve_reduce_to_tolerance`); or the steps need too much work (more than `2^27`
///   pieces reduced times `((k + 1)^2 + 64) (dim + 1)` at degree `k`, bounded work).
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target >= n` or `target == 0`.
/// - `CAGD_ERR_NO_CONVERGENCE`: more than `max_depth` levels or 2^20 pieces would be
///   needed.
/// - `CAGD_ERR_NON_FINITE`: a reduced point overflows f64 (coordinates near the limits of
///   f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `opts` NULL or a readable
/// `CagdReduceOptions` of `opts->struct_size` bytes; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_reduce_to_tolerance_stepwise(
    curve: *const CagdCurve,
    opts: *const CagdReduceOptions,
    spline_out: *mut *mut CagdBSpline,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    // SAFETY: the caller's contract (see # Safety).
    boundary(|| unsafe { run(Algorithm::Stepwise, curve, opts, spline_out, report_out) })
}
