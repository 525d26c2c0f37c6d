//! `CagdBezierReport`: the report of `cagd_bezier_reduce` as a plain struct the caller owns
//! (the handle-free counterpart of `CagdReport` for one curve), with its versioning rule.

use cagd_reduce::{ErrorSpace, Report};

use crate::boundary::{CResult, Failure};
use crate::options::CagdErrorSpace;

/// What `cagd_bezier_reduce` did: the numbers `cagd_report_method`, `cagd_report_bound`,
/// `cagd_report_max_error` and `cagd_report_space` give for the handle call
/// `cagd_curve_reduce` with the same options, in one caller-owned struct (e.g. on the
/// stack). A value that is not available is NaN (where the handle accessor returns
/// `CAGD_ERR_NOT_AVAILABLE`).
///
/// Versioning rule (as `CagdReduceOptions`): set `struct_size = sizeof(CagdBezierReport)`
/// before the call. cagd writes at most `struct_size` bytes, rejects a size below that of
/// the first version (`CAGD_ERR_INVALID_ARGUMENT`), and only appends fields in later
/// versions. Nothing is released yet, so the first version is this one.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CagdBezierReport {
    /// `sizeof(CagdBezierReport)`, set by the caller before the call (see above).
    pub struct_size: usize,
    /// The `CagdReduceMethod` code that was used (`cagd_report_method`).
    pub method: i32,
    /// The `CagdErrorSpace` code of `bound` and `max_error` (`cagd_report_space`):
    /// `opts->space` for a rational curve, `CAGD_SPACE_EUCLIDEAN` for a polynomial one.
    pub space: i32,
    /// Source degree `n`.
    pub degree_from: usize,
    /// Target degree `m`.
    pub degree_to: usize,
    /// Certified upper bound of `max_t |P(t) - Q(t)|` in model units, in `space`
    /// (`cagd_report_bound`); NaN when no bound was formed or it overflowed f64.
    pub bound: f64,
    /// The error measured by dense sampling with `opts->measure` (`cagd_report_max_error`);
    /// NaN when not measured.
    pub max_error: f64,
    /// The certified bound in homogeneous space for a rational curve, the Euclidean bound
    /// for a polynomial one (`cagd_report_space`); NaN when no bound was formed or it
    /// overflowed f64.
    pub homogeneous_bound: f64,
}

/// The size of the first published version: the smallest `struct_size` accepted.
pub(super) const REPORT_MIN_SIZE: usize = size_of::<CagdBezierReport>();

impl CagdBezierReport {
    /// The struct for a cagd-reduce report of a reduction asked for with the
    /// `CagdReduceMethod` code `method` (`struct_size` is the full size).
    pub(super) fn of(r: &Report, method: i32) -> Self {
        let space = match r.space {
            ErrorSpace::Euclidean => CagdErrorSpace::SPACE_EUCLIDEAN,
            ErrorSpace::Homogeneous => CagdErrorSpace::SPACE_HOMOGENEOUS,
        };
        Self {
            struct_size: size_of::<Self>(),
            method,
            space: space as i32,
            degree_from: r.degree_from,
            degree_to: r.degree_to,
            bound: finite_or_nan(r.error_bound),
            max_error: finite_or_nan(r.max_error),
            homogeneous_bound: finite_or_nan(r.homogeneous_bound.or(r.error_bound)),
        }
    }
}

/// NaN for an absent value and for one that is not finite (a bound that overflowed f64 on
/// coordinates near the f64 limit is no bound, and the handle accessors answer
/// `CAGD_ERR_NOT_AVAILABLE` for it; found by the C ABI fuzz harness, where
/// `cagd_bezier_reduce` wrote `bound = inf` with `CAGD_OK`).
fn finite_or_nan(value: Option<f64>) -> f64 {
    value.filter(|v| v.is_finite()).unwrap_or(f64::NAN)
}

/// A checked caller report struct, not yet written.
pub(super) struct ReportOut {
    ptr: *mut CagdBezierReport,
    size: usize,
}

/// Checks the caller's report pointer: NULL → `None` (no report wanted); misaligned or
/// `struct_size` below the first version's size → `CAGD_ERR_INVALID_ARGUMENT`.
///
/// # Safety
/// `ptr` must be NULL or point to `ptr->struct_size` writable bytes (at least a `size_t`)
/// laid out as `CagdBezierReport`.
pub(super) unsafe fn checked_report(ptr: *mut CagdBezierReport) -> CResult<Option<ReportOut>> {
    if ptr.is_null() {
        return Ok(None);
    }
    if !ptr.is_aligned() {
        return Err(Failure::invalid("argument `report_out` is misaligned"));
    }
    // SAFETY: non-NULL and aligned; the first field is a size_t by the caller's contract.
    let size = unsafe { ptr.cast::<usize>().read() };
    if size < REPORT_MIN_SIZE {
        return Err(Failure::invalid(format!(
            "report_out->struct_size = {size} is below sizeof(CagdBezierReport) = \
             {REPORT_MIN_SIZE}: set it to sizeof(CagdBezierReport) before the call"
        )));
    }
    Ok(Some(ReportOut { ptr, size }))
}

impl ReportOut {
    /// The number of bytes of `*report_out` that will be written.
    pub(super) fn len(&self) -> usize {
        self.size.min(size_of::<CagdBezierReport>())
    }

    /// The address of the caller's struct (for overlap checks).
    pub(super) fn addr(&self) -> *const u8 {
        self.ptr.cast_const().cast()
    }

    /// Writes the report (the first `len()` bytes; `struct_size` keeps the caller's value).
    pub(super) fn write(self, report: &CagdBezierReport) {
        let value = CagdBezierReport {
            struct_size: self.size,
            ..*report
        };
        // SAFETY: `len()` writable bytes at `ptr` by the contract of `report_out`; the
        // source is a local of at least that size; they do not overlap.
        unsafe {
            std::ptr::copy_nonoverlapping(
                (&raw const value).cast::<u8>(),
                self.ptr.cast::<u8>(),
                self.len(),
            );
        }
    }
}
