//! `CagdReport`: what a reduction did and how far the result is from the input. The
//! accessors that only piecewise reductions answer are in `piecewise.rs`, those of B-spline
//! reductions in `spline.rs`.

mod piecewise;
mod spline;

pub use piecewise::{cagd_report_pieces, cagd_report_piecewise, cagd_report_step_bounds};
pub use spline::{cagd_report_spline, cagd_report_spline_continuity, cagd_report_spline_strategy};

use cagd_reduce::{BoundLevel, ErrorSpace, PatchReport, PiecewiseReport, ReducedPiece, Report};

use crate::boundary::{
    CResult, Failure, boundary, boundary_void, free_handle, handle_ref, out_ref,
};
use crate::options::{CagdBoundLevel, CagdErrorSpace, CagdSplineStrategy};
use crate::status::CagdStatus;

/// Opaque handle to the report of a reduction: the method, the degrees, the certified
/// error bound, and (on request) the measured error; for a piecewise reduction (to a
/// tolerance) also the pieces. Immutable; release with `cagd_report_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdReport {
    pub(crate) kind: ReportKind,
    /// The `CagdReduceMethod` code `cagd_report_method` gives: the one asked for, except
    /// for `cagd_bspline_reduce` (see `CagdSplineStrategy::reported_method`).
    pub(crate) method: i32,
}

/// The two kinds of reduction reports.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum ReportKind {
    /// One curve reduced to one curve.
    Single(Report),
    /// A curve reduced to a tolerance: pieces merged into a spline.
    Piecewise {
        /// The report of the whole.
        report: PiecewiseReport,
        /// The reduced pieces, in parameter order.
        pieces: Vec<ReducedPiece>,
    },
    /// A B-spline reduced to a B-spline.
    Spline(SplineReport),
    /// A patch reduced (to a patch, or to a tolerance: pieces).
    Patch {
        /// The report (for pieces: the largest bound and measured error of a piece).
        report: PatchReport,
        /// The `CagdPatchMethod` code that was asked for.
        patch_method: i32,
        /// Number of pieces (1 for a single reduction).
        pieces: usize,
    },
}

/// What a B-spline reduction did.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SplineReport {
    /// Source degree.
    pub(crate) degree_from: usize,
    /// Target degree.
    pub(crate) degree_to: usize,
    /// Certified bound of the whole (Euclidean, model space).
    pub(crate) error_bound: f64,
    /// Sampled error, on request.
    pub(crate) max_error: Option<f64>,
    /// Largest certified bound of a reduced Bézier segment (before merging / knot removal).
    pub(crate) segment_bound: f64,
    /// Number of reduced Bézier segments.
    pub(crate) pieces: usize,
    /// Non-empty knot spans of the input.
    pub(crate) spans_in: usize,
    /// Non-empty knot spans of the result.
    pub(crate) spans_out: usize,
    /// The strategy and the kept continuity (`cagd_bspline_reduce` only; `None` for the
    /// uniform pipeline).
    pub(crate) strategy: Option<StrategyReport>,
}

/// What `cagd_bspline_reduce` reports beyond `SplineReport`'s numbers.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct StrategyReport {
    /// The strategy used.
    pub(crate) strategy: CagdSplineStrategy,
    /// `(knot, k)`: the continuity `C^k` guaranteed at each interior knot of the input that
    /// is still a knot of the result, in increasing knot order.
    pub(crate) continuity: Vec<(f64, usize)>,
}

impl CagdReport {
    /// The report of a single reduction (for Rust callers of this crate); `None` for a
    /// piecewise one.
    pub fn as_report(&self) -> Option<&Report> {
        match &self.kind {
            ReportKind::Single(r) => Some(r),
            ReportKind::Piecewise { .. } | ReportKind::Patch { .. } | ReportKind::Spline(_) => None,
        }
    }

    /// The report of a piecewise reduction (for Rust callers of this crate); `None` for a
    /// single one.
    pub fn as_piecewise(&self) -> Option<&PiecewiseReport> {
        match &self.kind {
            ReportKind::Single(_) | ReportKind::Patch { .. } | ReportKind::Spline(_) => None,
            ReportKind::Piecewise { report, .. } => Some(report),
        }
    }

    /// `(degree_from, degree_to, error_bound, max_error)` of any kind (patches: in u).
    fn common(&self) -> (usize, usize, Option<f64>, Option<f64>) {
        match &self.kind {
            ReportKind::Single(r) => (r.degree_from, r.degree_to, r.error_bound, r.max_error),
            ReportKind::Piecewise { report: r, .. } => {
                (r.degree_from, r.degree_to, Some(r.error_bound), r.max_error)
            }
            ReportKind::Patch { report: r, .. } => (
                r.degrees_from.0,
                r.degrees_to.0,
                Some(r.error_bound),
                r.max_error,
            ),
            ReportKind::Spline(r) => (r.degree_from, r.degree_to, Some(r.error_bound), r.max_error),
        }
    }
}

/// `CAGD_ERR_NOT_AVAILABLE` for an absent value, and for one that is not finite (a bound
/// that overflowed f64 on coordinates near the f64 limit is no bound: issue 18, found by
/// the C ABI fuzz harness, where `cagd_report_bound` handed out `inf` with `CAGD_OK`).
fn available(value: Option<f64>, what: &str) -> CResult<f64> {
    match value {
        Some(v) if v.is_finite() => Ok(v),
        Some(v) => Err(Failure::new(
            CagdStatus::ERR_NOT_AVAILABLE,
            format!("{what}: the value overflowed f64 ({v})"),
        )),
        None => Err(Failure::new(CagdStatus::ERR_NOT_AVAILABLE, what.to_owned())),
    }
}

/// Releases a report. NULL is accepted and ignored (freeing NULL twice is fine); a
/// non-NULL handle must be released exactly once and not used afterwards.
///
/// Parameters:
/// - `report` (in, consumed): a `CagdReport **` output of `cagd_curve_reduce` or another
///   reduction, or NULL.
///
/// Does not change `cagd_last_error_message()`.
///
/// # Safety
/// `report` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_free(report: *mut CagdReport) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(report) });
}

/// Reads the method and the degrees of a reduction. For a patch reduction: the curve
/// method option (`opts->method`) and the degrees in u (`cagd_report_patch` gives all).
/// For `cagd_bspline_reduce`: the method that reduced the pieces, which depends on the
/// strategy (`cagd_report_spline_strategy`): `opts->method` for `CAGD_SPLINE_SEGMENTS`,
/// `CAGD_METHOD_L2` for `CAGD_SPLINE_FIT` (its fit minimises the L2 norm with the end
/// points kept; `opts->method` is not used), `CAGD_METHOD_PIEGL_TILLER` for
/// `CAGD_SPLINE_PIEGL_TILLER_1995` (its one-degree segment reduction).
///
/// Parameters:
/// - `report` (in): the report.
/// - `method_out` (out): on `CAGD_OK`, the `CagdReduceMethod` code that was used.
/// - `degree_from_out` (out): on `CAGD_OK`, the source degree `n`.
/// - `degree_to_out` (out): on `CAGD_OK`, the target degree `m`.
///
/// Returns:
/// - `CAGD_OK`: the three outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: any argument is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `report` must be NULL or a live report handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_method(
    report: *const CagdReport,
    method_out: *mut i32,
    degree_from_out: *mut usize,
    degree_to_out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let r = unsafe { handle_ref(report, "report") }?;
        // SAFETY: as above.
        let (m, from, to) = unsafe {
            (
                out_ref(method_out, "method_out")?,
                out_ref(degree_from_out, "degree_from_out")?,
                out_ref(degree_to_out, "degree_to_out")?,
            )
        };
        let (degree_from, degree_to, _, _) = r.common();
        (*m, *from, *to) = (r.method, degree_from, degree_to);
        Ok(())
    })
}

/// Reads the certified upper bound of the reduction error `max_t |P(t) - Q(t)|` (in
/// model units, in the space given by `cagd_report_space`; `f64` rounding included): the
/// true error never exceeds it.
///
/// Parameters:
/// - `report` (in): the report.
/// - `bound_out` (out): on `CAGD_OK`, the bound (`>= 0`; `+inf` only if its computation
///   overflowed).
///
/// Returns:
/// - `CAGD_OK`: `*bound_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `report` or `bound_out` is NULL.
/// - `CAGD_ERR_NOT_AVAILABLE`: no bound was computed for this reduction (it ran with
///   `opts->bound_level = CAGD_BOUND_NONE`).
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `report` must be NULL or a live report handle; `bound_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_bound(
    report: *const CagdReport,
    bound_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let r = unsafe { handle_ref(report, "report") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(bound_out, "bound_out") }?;
        *out = available(r.common().2, "no certified bound for this reduction")?;
        Ok(())
    })
}

/// Reads the bound level a single-curve reduction (`cagd_curve_reduce`) ran with: the
/// `CagdBoundLevel` of its options (`CAGD_BOUND_NONE`: no bound was computed, and
/// `cagd_report_bound` returns `CAGD_ERR_NOT_AVAILABLE`).
///
/// Parameters:
/// - `report` (in): the report.
/// - `level_out` (out): on `CAGD_OK`, the `CagdBoundLevel` code.
///
/// Returns:
/// - `CAGD_OK`: `*level_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `report` or `level_out` is NULL.
/// - `CAGD_ERR_NOT_AVAILABLE`: the report is not that of a single-curve reduction (the
///   other reductions always certify, each in its own way; see their docs).
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `report` must be NULL or a live report handle; `level_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_bound_level(
    report: *const CagdReport,
    level_out: *mut i32,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let r = unsafe { handle_ref(report, "report") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(level_out, "level_out") }?;
        let Some(single) = r.as_report() else {
            return Err(Failure::new(
                CagdStatus::ERR_NOT_AVAILABLE,
                "the bound level is reported by single-curve reductions only".to_owned(),
            ));
        };
        *out = match single.bound_level {
            BoundLevel::None => CagdBoundLevel::BOUND_NONE,
            BoundLevel::Fast => CagdBoundLevel::BOUND_FAST,
            _ => CagdBoundLevel::BOUND_TIGHT,
        } as i32;
        Ok(())
    })
}

/// Reads the error measured by dense sampling (`max_t |P(t) - Q(t)|` over a dense grid
/// plus Brent refinement of every local maximum, in the space given by `cagd_report_space`),
/// available when the
/// reduction ran with `opts->measure = true`. Never above the certified bound.
///
/// Parameters:
/// - `report` (in): the report.
/// - `error_out` (out): on `CAGD_OK`, the measured error (`>= 0`).
///
/// Returns:
/// - `CAGD_OK`: `*error_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `report` or `error_out` is NULL.
/// - `CAGD_ERR_NOT_AVAILABLE`: the reduction ran with `measure = false`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `report` must be NULL or a live report handle; `error_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_max_error(
    report: *const CagdReport,
    error_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let r = unsafe { handle_ref(report, "report") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(error_out, "error_out") }?;
        *out = available(
            r.common().3,
            "the error was not measured: set CagdReduceOptions.measure = true",
        )?;
        Ok(())
    })
}

/// Reads the space of the report's error numbers, and for a rational curve the certified
/// bound in homogeneous space (from which the Euclidean one is derived).
///
/// Parameters:
/// - `report` (in): the report.
/// - `space_out` (out): on `CAGD_OK`, the `CagdErrorSpace` code of `cagd_report_bound`
///   and `cagd_report_max_error`.
/// - `homogeneous_bound_out` (out): on `CAGD_OK`, the homogeneous bound for a rational
///   input, or the Euclidean bound for a polynomial one (the two spaces coincide).
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: any argument is NULL.
/// - `CAGD_ERR_NOT_AVAILABLE`: no bound could be formed for this reduction, or the report
///   is of a reduction to a tolerance, of a B-spline or of a patch (whose numbers are
///   always Euclidean).
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `report` must be NULL or a live report handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_space(
    report: *const CagdReport,
    space_out: *mut i32,
    homogeneous_bound_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let r = unsafe { handle_ref(report, "report") }?;
        // SAFETY: as above.
        let (s, h) = unsafe {
            (
                out_ref(space_out, "space_out")?,
                out_ref(homogeneous_bound_out, "homogeneous_bound_out")?,
            )
        };
        let ReportKind::Single(single) = &r.kind else {
            return Err(Failure::new(
                CagdStatus::ERR_NOT_AVAILABLE,
                "reductions to a tolerance, of splines and of patches report Euclidean numbers \
                 only",
            ));
        };
        let hb = available(
            single.homogeneous_bound.or(single.error_bound),
            "no certified bound for this reduction",
        )?;
        let space = match single.space {
            ErrorSpace::Homogeneous => CagdErrorSpace::SPACE_HOMOGENEOUS,
            ErrorSpace::Euclidean => CagdErrorSpace::SPACE_EUCLIDEAN,
        };
        (*s, *h) = (space as i32, hb);
        Ok(())
    })
}
