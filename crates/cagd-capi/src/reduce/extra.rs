//! The remaining curve reductions from C: the true degree of a curve and its exact
//! reduction (`cagd_curve_exact_degree`, `cagd_curve_reduce_exact`), the G1 perturbation
//! with optimal tangent scales (`cagd_curve_reduce_g1_optimal`), the reduction matrix
//! itself (`cagd_reduce_operator`), and the parameters a report's method used
//! (`cagd_report_method_params`).

use cagd_reduce::{Method, Reduction, exact_degree, operator, reduce_exact, reduce_g1_optimal};

use crate::boundary::{
    CResult, Failure, OUT, boundary, handle_ref, into_handle, nonnull, out_ref, slice_out,
};
use crate::curve::CagdCurve;
use crate::options::{CagdReduceMethod, CagdReduceOptions, read_options};
use crate::report::{CagdReport, ReportKind};
use crate::status::CagdStatus;

/// The default relative tolerance of `cagd_curve_exact_degree`: a difference
/// `Delta^j P_0` counts as zero when `||Delta^j P_0||_inf <= tol * 2^j * max ||P_i||_inf`
/// (an `f64`-elevated curve stays below `(n + 4) eps <= 1.6e-14`; 1e-12 leaves a margin
/// of 60). Becomes `#define CAGD_EXACT_DEGREE_REL_TOL`.
pub const CAGD_EXACT_DEGREE_REL_TOL: f64 = 1e-12;

/// The C code and parameters `(code, r, p, l1, l2)` of a method (`r = p = -1` and
/// `l1 = l2 = 0` where the method has none; code -1 for a method without a C code yet).
pub(crate) fn method_params(m: &Method) -> (i32, i32, i32, f64, f64) {
    use CagdReduceMethod as C;
    let code = |c: C| c as i32;
    match *m {
        Method::Forrest => (code(C::METHOD_FORREST), -1, -1, 0.0, 0.0),
        Method::PieglTiller => (code(C::METHOD_PIEGL_TILLER), -1, -1, 0.0, 0.0),
        Method::Farin => (code(C::METHOD_FARIN), -1, -1, 0.0, 0.0),
        Method::Perturb => (code(C::METHOD_PERTURB), -1, -1, 0.0, 0.0),
        Method::PerturbG1 { l1, l2 } => (code(C::METHOD_PERTURB_G1), -1, -1, l1, l2),
        Method::Eck => (code(C::METHOD_ECK), -1, -1, 0.0, 0.0),
        Method::WatkinsWorsey => (code(C::METHOD_WATKINS_WORSEY), -1, -1, 0.0, 0.0),
        Method::BogackiWeinsteinXu => (code(C::METHOD_BOGACKI_WEINSTEIN_XU), -1, -1, 0.0, 0.0),
        Method::GeneralizedInverse => (code(C::METHOD_GENERALIZED_INVERSE), -1, -1, 0.0, 0.0),
        Method::GeneralizedInverseEnds => {
            (code(C::METHOD_GENERALIZED_INVERSE_ENDS), -1, -1, 0.0, 0.0)
        }
        Method::ConstrainedChebyshev { r, p } => {
            (code(C::METHOD_CONSTRAINED_CHEBYSHEV), r, p, 0.0, 0.0)
        }
        Method::L2 { r, p } => (code(C::METHOD_L2), r, p, 0.0, 0.0),
        // `Method` is non-exhaustive: a method added to cagd-reduce before it has a C code
        // reports -1 (the test below pins that every current method has its code).
        _ => (-1, -1, -1, 0.0, 0.0),
    }
}

/// Writes a single reduction's outputs.
fn write_reduction(red: Reduction, c_out: &mut *mut CagdCurve, r_out: &mut *mut CagdReport) {
    let code = method_params(&red.report.method).0;
    *c_out = into_handle(CagdCurve(red.curve));
    *r_out = into_handle(CagdReport {
        kind: ReportKind::Single(red.report),
        method: code,
    });
}

/// Checks and borrows the two outputs of a curve reduction.
///
/// # Safety
/// Both pointers NULL or writable.
unsafe fn outputs<'a>(
    curve_out: *mut *mut CagdCurve,
    report_out: *mut *mut CagdReport,
) -> CResult<(&'a mut *mut CagdCurve, &'a mut *mut CagdReport)> {
    nonnull(curve_out, "curve_out")?;
    nonnull(report_out, "report_out")?;
    if curve_out.addr() == report_out.addr() {
        return Err(Failure::invalid(
            "`curve_out` and `report_out` are the same address",
        ));
    }
    // SAFETY: forwarded contract; the two outputs do not overlap.
    unsafe {
        Ok((
            out_ref(curve_out, "curve_out")?,
            out_ref(report_out, "report_out")?,
        ))
    }
}

/// Finds the true degree of a curve: the smallest `k` such that the curve is, up to
/// `rel_tol`, a degree-`k` curve elevated to its degree `n` (every `Delta^j P_0`, `j > k`,
/// has `||Delta^j P_0||_inf <= rel_tol * 2^j * max_i ||P_i||_inf`; rational curves are
/// tested in homogeneous coordinates).
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `rel_tol` (in): the relative tolerance, finite and `> 0`; `CAGD_EXACT_DEGREE_REL_TOL`
///   (1e-12) is right for curves elevated in `double`.
/// - `degree_out` (out): on `CAGD_OK`, the true degree `k <= n`.
///
/// Returns:
/// - `CAGD_OK`: `*degree_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `degree_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `rel_tol` is not finite and `> 0`, or a pointer is
///   misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `degree_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_exact_degree(
    curve: *const CagdCurve,
    rel_tol: f64,
    degree_out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(degree_out, "degree_out") }?;
        *out = exact_degree(&c.0, rel_tol)?;
        Ok(())
    })
}

/// Reduces a curve that is (up to `CAGD_EXACT_DEGREE_REL_TOL`) an elevated lower-degree
/// curve to that lower degree; any other curve is copied unchanged (bound 0). The reducing
/// operator is whichever reproducing one amplifies rounding least (generalized inverse or
/// stepwise Forrest, both exact on elevated curves); `cagd_report_method` tells which.
///
/// Parameters:
/// - `curve` (in): the curve, degree `n`.
/// - `curve_out` (out): on `CAGD_OK`, the curve at its true degree, owned by the caller:
///   release with `cagd_curve_free`.
/// - `report_out` (out): on `CAGD_OK`, the report with the certified bound, owned by the
///   caller: release with `cagd_report_free`. Neither output is written on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `curve`, `curve_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: the two outputs are the same address, or a pointer is
///   misaligned.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a reduced weight of a rational curve is not positive.
/// - `CAGD_ERR_NON_FINITE`: an intermediate or result value overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_reduce_exact(
    curve: *const CagdCurve,
    curve_out: *mut *mut CagdCurve,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let (c_out, r_out) = unsafe { outputs(curve_out, report_out) }?;
        write_reduction(reduce_exact(&c.0)?, c_out, r_out);
        Ok(())
    })
}

/// Reduces a curve of degree `n >= 4` to degree `n - 1` by control-point perturbation
/// keeping both end points and end tangent directions (G1), with the tangent scales
/// `l1, l2` chosen to minimise the perturbation's own objective `sum ||eps_i||^2`
/// (seed 000 §14.2.3, SPEC-reduce §2.3). The scales found are read with
/// `cagd_report_method_params`.
///
/// Parameters:
/// - `curve` (in): the curve, degree `n >= 4`.
/// - `measure` (in): also measure the error by dense sampling.
/// - `curve_out` (out): on `CAGD_OK`, the reduced curve (degree `n - 1`), owned by the
///   caller: release with `cagd_curve_free`.
/// - `report_out` (out): on `CAGD_OK`, the report (method `CAGD_METHOD_PERTURB_G1`),
///   owned by the caller: release with `cagd_report_free`. Neither output is written on
///   failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `curve`, `curve_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: the two outputs are the same address, or a pointer is
///   misaligned.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `n < 4`.
/// - `CAGD_ERR_CONDITION_NOT_MET`: an optimal scale gives `1 + l <= 0` (the tangent would
///   flip; eq. 14.2.12).
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a reduced weight of a rational curve is not positive.
/// - `CAGD_ERR_NON_FINITE`: an intermediate or result value overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_reduce_g1_optimal(
    curve: *const CagdCurve,
    measure: bool,
    curve_out: *mut *mut CagdCurve,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let (c_out, r_out) = unsafe { outputs(curve_out, report_out) }?;
        write_reduction(reduce_g1_optimal(&c.0, measure)?, c_out, r_out);
        Ok(())
    })
}

/// Copies the reduction matrix of `opts->method` (with `r`, `p`, `l1`, `l2`) from degree
/// `degree` to `opts->target`, built on first use and cached process-wide. Route: closed
/// forms and the seed's recursions in double, double-word or 256-bit floating-point
/// arithmetic, each number carrying a rigorous error bound, accepted only when the proven
/// error of every row is at most `1e-12` times the matrix's inf-norm `max_i sum_j |a_ij|`;
/// otherwise exact rational arithmetic rounded once (no pair up to degree 64 needs it any
/// more; the slowest build is about 0.2 s, the G1 perturbation near degree 64). So every
/// entry is within `1e-12 * max_i sum_j |a_ij|` of the exact value (measured against the
/// exact route up to degree 64: at most `1.1e-14` relative to the inf-norm). Row-major
/// `(target + 1) x (degree + 1)`: the reduced points are
/// `Q_i = sum_j out[i * (degree + 1) + j] P_j`, per coordinate (homogeneous coordinates for
/// a rational curve). For applying it yourself, e.g. on a GPU.
///
/// Parameters:
/// - `opts` (in): the options (`method`, `r`, `p`, `l1`, `l2`, `target`). Borrowed.
/// - `degree` (in): the source degree `n`, `0..=64`.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `(target + 1) * (degree + 1)` doubles hold the matrix. May be NULL only when
///   `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `(target + 1) * (degree + 1)`.
///
/// Returns:
/// - `CAGD_OK`: the matrix is in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `opts` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `opts->struct_size` below `sizeof(CagdReduceOptions)`,
///   an invalid method code or `l1` / `l2`, or a pointer is misaligned.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `degree > 64`.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target >= degree` or below the method's minimum.
/// - `CAGD_ERR_TOO_MANY_CONSTRAINTS`: `r + p + 1 > target`, or `r`, `p` below -1.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is below the size; only `*out_needed` is
///   written.
/// - `CAGD_ERR_NON_FINITE`: an entry of the matrix overflows f64 (`CAGD_METHOD_PERTURB_G1`
///   with `l1` or `l2` near the limits of f64); `out` is not written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `opts` must be NULL or a readable `CagdReduceOptions` of `opts->struct_size` bytes;
/// `out` NULL or `out_cap` writable doubles; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_reduce_operator(
    opts: *const CagdReduceOptions,
    degree: usize,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let o = unsafe { read_options(opts) }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let op = operator(o.method()?, degree, o.target)?;
        dst.copy_from(op.matrix())
    })
}

/// Reads the parameters of the method a curve reduction used: for
/// `cagd_curve_reduce_g1_optimal` the optimal tangent scales found, for
/// `cagd_curve_reduce_exact` the operator chosen, otherwise the method asked for.
///
/// Parameters:
/// - `report` (in): the report.
/// - `method_out` (out): on `CAGD_OK`, the `CagdReduceMethod` code.
/// - `r_out` (out): on `CAGD_OK`, the derivative order kept at t = 0 (`-1` for methods
///   without `r`).
/// - `p_out` (out): on `CAGD_OK`, the order kept at t = 1 (`-1` likewise).
/// - `l1_out` (out): on `CAGD_OK`, the tangent scale at t = 0 of `CAGD_METHOD_PERTURB_G1`
///   (0 for other methods).
/// - `l2_out` (out): on `CAGD_OK`, the scale at t = 1 (0 for other methods).
///
/// Returns:
/// - `CAGD_OK`: all outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: any argument is NULL.
/// - `CAGD_ERR_NOT_AVAILABLE`: the report is not of a curve reduction (one curve or to a
///   tolerance).
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `report` must be NULL or a live report handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_method_params(
    report: *const CagdReport,
    method_out: *mut i32,
    r_out: *mut i32,
    p_out: *mut i32,
    l1_out: *mut f64,
    l2_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let rep = unsafe { handle_ref(report, "report") }?;
        // SAFETY: as above.
        let (m, r, p, l1, l2) = unsafe {
            (
                out_ref(method_out, "method_out")?,
                out_ref(r_out, "r_out")?,
                out_ref(p_out, "p_out")?,
                out_ref(l1_out, "l1_out")?,
                out_ref(l2_out, "l2_out")?,
            )
        };
        let method = match &rep.kind {
            ReportKind::Single(s) => s.method,
            ReportKind::Piecewise { report, .. } => report.method,
            ReportKind::Patch { .. } | ReportKind::Spline(_) => {
                return Err(Failure::new(
                    CagdStatus::ERR_NOT_AVAILABLE,
                    "not the report of a curve reduction",
                ));
            }
        };
        (*m, *r, *p, *l1, *l2) = method_params(&method);
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_reduce::DEFAULT_REL_TOL;

    #[test]
    fn default_rel_tol_matches_cagd_reduce() {
        assert_eq!(CAGD_EXACT_DEGREE_REL_TOL, DEFAULT_REL_TOL);
    }

    #[test]
    fn method_params_round_trip_through_options() {
        for code in 0..=11 {
            let o = CagdReduceOptions {
                method: code,
                r: 1,
                p: 0,
                l1: 0.25,
                l2: -0.5,
                ..CagdReduceOptions::default()
            };
            let m = o.method().unwrap();
            assert_eq!(method_params(&m).0, code, "{m:?}");
        }
    }
}
