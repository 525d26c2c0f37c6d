//! Degree reduction of WSGB curves from C: `cagd_wsgb_reduce` with the seed-003 methods
//! (perturbation, best uniform) or any Bézier method of `CagdReduceOptions`, and the
//! report struct `CagdWsgbReport`.

use cagd_reduce::{WsgbMethod, reduce_wsgb_with};

use super::CagdWsgbCurve;
use crate::boundary::{Failure, boundary, handle_ref, into_handle, nonnull, out_ref};
use crate::options::{CagdReduceOptions, read_options};
use crate::status::CagdStatus;

/// The WSGB reduction method of `cagd_wsgb_reduce`.
///
/// cbindgen:rename-all=prefix:CAGD_
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[allow(
    non_camel_case_types,
    reason = "C names: the variants become CAGD_WSGB_*"
)]
pub enum CagdWsgbMethod {
    /// Seed 003 §2.1, SPEC-reduce §9.4: least perturbation of the middle points, then the
    /// exact inverse elevation. One degree per step; needs `n >= 2` at every step.
    WSGB_PERTURBATION = 0,
    /// Seed 003 §2.2, SPEC-reduce §9.5: best uniform approximation, one degree per step.
    WSGB_UNIFORM = 1,
    /// The Bézier method of `opts->method` (with `r`, `p`, `l1`, `l2`) through the exact
    /// conversion to Bézier form and back.
    WSGB_BEZIER = 2,
}

/// What `cagd_wsgb_reduce` did. The caller sets `struct_size = sizeof(CagdWsgbReport)`;
/// the library writes the fields that fit in `struct_size` bytes (later versions only
/// append fields). Numbers that were not computed are NaN, as documented per field.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CagdWsgbReport {
    /// `sizeof(CagdWsgbReport)`, set by the caller (at least the size of this version).
    pub struct_size: usize,
    /// Source degree `n`.
    pub degree_from: usize,
    /// Target degree `m`.
    pub degree_to: usize,
    /// Source order `L`.
    pub order_from: usize,
    /// Order `L'` of the result.
    pub order_to: usize,
    /// Certified upper bound of `max_u ||r(u) - q(u)||` (Euclidean), rounding included.
    pub error_bound: f64,
    /// Measured `max_u ||r(u) - q(u)||` (Euclidean); NaN when `opts->measure` is false.
    pub max_error: f64,
    /// Measured `max_u max_k |r_k(u) - q_k(u)|` (the max-abs norm of seed 003); NaN when
    /// `opts->measure` is false.
    pub max_error_inf: f64,
    /// Seed 003's bound (11) summed over the steps (max-abs norm; what the seed prints as
    /// the perturbation "error"); NaN for `CAGD_WSGB_BEZIER`.
    pub paper_bound_11: f64,
    /// Seed 003's formula (12), `||lec||_inf / 2^(2n-1)`, summed over the steps; NaN for
    /// `CAGD_WSGB_BEZIER`.
    pub uniform_error_12: f64,
    /// The exact max-abs error of each step by its closed form (SPEC-reduce §9.4/§9.5),
    /// summed over the steps; NaN for `CAGD_WSGB_BEZIER`.
    pub paper_true_error_inf: f64,
}

impl CagdWsgbReport {
    /// A report with `struct_size` set and every number NaN.
    pub fn new() -> Self {
        Self {
            struct_size: size_of::<Self>(),
            degree_from: 0,
            degree_to: 0,
            order_from: 0,
            order_to: 0,
            error_bound: f64::NAN,
            max_error: f64::NAN,
            max_error_inf: f64::NAN,
            paper_bound_11: f64::NAN,
            uniform_error_12: f64::NAN,
            paper_true_error_inf: f64::NAN,
        }
    }
}

impl Default for CagdWsgbReport {
    fn default() -> Self {
        Self::new()
    }
}

/// Reduces a WSGB(n, L) curve to degree `opts->target` (order `L' = min(L, max(floor(m/2)
/// - 1, 0))`) with a certified Euclidean error bound.
///
/// Parameters:
/// - `curve` (in): the curve.
/// - `method` (in): a `CagdWsgbMethod` value.
/// - `opts` (in): the options (start from `cagd_reduce_options_init`): `target` and
///   `measure` always; `method`, `r`, `p`, `l1`, `l2` for `CAGD_WSGB_BEZIER`. Borrowed.
/// - `curve_out` (out): on `CAGD_OK`, the reduced curve, owned by the caller (release with
///   `cagd_wsgb_free`). Not written on failure.
/// - `report_out` (out, may be NULL): on `CAGD_OK`, filled with the report up to its
///   `struct_size` (which the caller sets to `sizeof(CagdWsgbReport)`).
///
/// Returns:
/// - `CAGD_OK`: the outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `curve`, `opts` or `curve_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `method` is not a `CagdWsgbMethod`, `opts->struct_size`
///   is below `sizeof(CagdReduceOptions)`, an invalid Bézier method code or `l1`/`l2`,
///   `report_out->struct_size` below `sizeof(size_t)`, or a pointer is misaligned.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target >= n`; the perturbation method with `target < 1`
///   (it needs `n >= 2` at every step); a target below the Bézier method's minimum.
/// - `CAGD_ERR_TOO_MANY_CONSTRAINTS`: `r + p + 1 > target` (Bézier methods with ends).
/// - `CAGD_ERR_NON_FINITE`: a reduced coordinate, the certified bound or the measured
///   error overflows to infinity.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live WSGB handle; `opts` NULL or a readable
/// `CagdReduceOptions` of `opts->struct_size` bytes; `curve_out` NULL or writable;
/// `report_out` NULL or `report_out->struct_size` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_wsgb_reduce(
    curve: *const CagdWsgbCurve,
    method: i32,
    opts: *const CagdReduceOptions,
    curve_out: *mut *mut CagdWsgbCurve,
    report_out: *mut CagdWsgbReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let o = unsafe { read_options(opts) }?;
        nonnull(curve_out, "curve_out")?;
        let method = match method {
            0 => WsgbMethod::Perturbation,
            1 => WsgbMethod::Uniform,
            2 => WsgbMethod::Bezier(o.method()?),
            other => {
                return Err(Failure::invalid(format!(
                    "method = {other} is not a CagdWsgbMethod (0, 1 or 2)"
                )));
            }
        };
        let report_size = if report_out.is_null() {
            0
        } else {
            if !report_out.is_aligned() {
                return Err(Failure::invalid("argument `report_out` is misaligned"));
            }
            // SAFETY: non-NULL and aligned; the first field is a size_t by the contract.
            let size = unsafe { report_out.cast::<usize>().read() };
            if size < size_of::<usize>() {
                return Err(Failure::invalid(format!(
                    "report_out->struct_size = {size}: set it to sizeof(CagdWsgbReport)"
                )));
            }
            size
        };
        // SAFETY: as above.
        let out = unsafe { out_ref(curve_out, "curve_out") }?;
        let red = reduce_wsgb_with(&c.0, o.target, method, o.measure)?;
        let r = &red.report;
        // Coordinates near the f64 limit overflow the bound (issue 18, found by the C ABI
        // fuzz harness: error_bound = inf with CAGD_OK): a bound that is no bound is refused.
        crate::boundary::finite_scalar(r.error_bound, "report error_bound")?;
        if let Some(e) = r.max_error {
            crate::boundary::finite_scalar(e, "report max_error")?;
        }
        let seed = |f: fn(&cagd_reduce::WsgbStep) -> f64| {
            if r.steps.is_empty() {
                f64::NAN
            } else {
                r.steps.iter().map(f).sum()
            }
        };
        let rep = CagdWsgbReport {
            struct_size: report_size,
            degree_from: r.degree_from,
            degree_to: r.degree_to,
            order_from: r.order_from,
            order_to: r.order_to,
            error_bound: r.error_bound,
            max_error: r.max_error.unwrap_or(f64::NAN),
            max_error_inf: r.max_error_inf.unwrap_or(f64::NAN),
            paper_bound_11: seed(|s| s.paper_bound_11),
            uniform_error_12: seed(|s| s.uniform_error_12),
            paper_true_error_inf: seed(|s| s.error_inf),
        };
        if report_size > 0 {
            let n = report_size.min(size_of::<CagdWsgbReport>());
            // SAFETY: `report_size` writable bytes at `report_out` by the contract; `n` is
            // at most that and at most the size of `rep`; the regions do not overlap.
            unsafe {
                std::ptr::copy_nonoverlapping(
                    (&raw const rep).cast::<u8>(),
                    report_out.cast::<u8>(),
                    n,
                );
            }
        }
        *out = into_handle(CagdWsgbCurve(red.curve));
        Ok(())
    })
}
