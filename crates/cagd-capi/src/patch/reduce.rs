//! Patch reduction from C: tensor-product and triangular patches, to given degrees
//! (`cagd_tensorpatch_reduce`, `cagd_tripatch_reduce`) or to a tolerance by uniform
//! subdivision (`cagd_tensorpatch_reduce_to_tolerance`, `cagd_tripatch_reduce_to_tolerance`).

use cagd_reduce::{
    PatchConstraint, PatchOptions, PatchReport, TensorMethod, TriMethod, TriOptions, reduce_tensor,
    reduce_tensor_to_tolerance, reduce_triangle, reduce_triangle_to_tolerance,
};

use crate::boundary::{CResult, Failure, boundary, handle_ref, into_handle, nonnull, out_ref};
use crate::options::{CagdReduceOptions, read_options};
use crate::patch::{CagdTensorPatchList, CagdTriPatchList};
use crate::report::{CagdReport, ReportKind};
use crate::status::CagdStatus;
use crate::tensorpatch::CagdTensorPatch;
use crate::tripatch::CagdTriPatch;

/// The constraint the options name.
fn constraint(o: &CagdReduceOptions) -> CResult<PatchConstraint> {
    Ok(match o.constraint {
        0 => PatchConstraint::None,
        1 => PatchConstraint::Corners,
        2 => PatchConstraint::Boundary(o.method()?),
        other => {
            return Err(Failure::invalid(format!(
                "opts->constraint = {other} is not a CagdPatchConstraint (0..=2)"
            )));
        }
    })
}

/// Fails unless the constraint is `CAGD_CONSTRAINT_NONE`.
fn no_constraint(o: &CagdReduceOptions, what: &str) -> CResult<()> {
    if o.constraint == 0 {
        Ok(())
    } else {
        Err(Failure::invalid(format!(
            "{what} takes no constraint (opts->constraint = {}, need CAGD_CONSTRAINT_NONE)",
            o.constraint
        )))
    }
}

/// The tensor options the C options name.
fn tensor_options(o: &CagdReduceOptions) -> CResult<PatchOptions> {
    let method = match o.patch_method {
        0 => TensorMethod::Perturb(constraint(o)?),
        1 => {
            no_constraint(o, "CAGD_PATCH_BY_CURVES")?;
            let m = o.method()?;
            TensorMethod::Curves { u: m, v: m }
        }
        2 => {
            return Err(Failure::invalid(
                "CAGD_PATCH_L2 is for triangular patches; for tensor patches use \
                 CAGD_PATCH_BY_CURVES with CAGD_METHOD_L2 (r = p = -1: the L2-best reduction)",
            ));
        }
        other => {
            return Err(Failure::invalid(format!(
                "opts->patch_method = {other} is not a CagdPatchMethod (0..=2)"
            )));
        }
    };
    Ok(PatchOptions {
        measure: o.measure,
        ..PatchOptions::new(method)
    })
}

/// The triangle options the C options name.
fn tri_options(o: &CagdReduceOptions) -> CResult<TriOptions> {
    let method = match o.patch_method {
        0 => {
            no_constraint(o, "CAGD_PATCH_PERTURB of a triangular patch")?;
            TriMethod::Perturb
        }
        1 => {
            return Err(Failure::invalid(
                "CAGD_PATCH_BY_CURVES is for tensor-product patches; for triangles use \
                 CAGD_PATCH_L2 or CAGD_PATCH_PERTURB",
            ));
        }
        2 => TriMethod::L2(constraint(o)?),
        other => {
            return Err(Failure::invalid(format!(
                "opts->patch_method = {other} is not a CagdPatchMethod (0..=2)"
            )));
        }
    };
    Ok(TriOptions {
        measure: o.measure,
        ..TriOptions::new(method)
    })
}

/// Checks and borrows the two outputs of a reduction (distinct, non-NULL, aligned).
///
/// # Safety
/// Both pointers NULL or writable.
unsafe fn outputs<'a, T>(
    first: *mut *mut T,
    first_name: &str,
    report_out: *mut *mut CagdReport,
) -> CResult<(&'a mut *mut T, &'a mut *mut CagdReport)> {
    nonnull(first, first_name)?;
    nonnull(report_out, "report_out")?;
    if first.addr() == report_out.addr() {
        return Err(Failure::invalid(format!(
            "`{first_name}` and `report_out` are the same address"
        )));
    }
    // SAFETY: forwarded contract; the two outputs do not overlap.
    unsafe {
        Ok((
            out_ref(first, first_name)?,
            out_ref(report_out, "report_out")?,
        ))
    }
}

/// The handle of a patch report.
fn patch_report(report: PatchReport, o: &CagdReduceOptions, pieces: usize) -> *mut CagdReport {
    into_handle(CagdReport {
        kind: ReportKind::Patch {
            report,
            patch_method: o.patch_method,
            pieces,
        },
        method: o.method,
    })
}

/// The report of the whole of a reduction to a tolerance: the largest bound and measured
/// error of the pieces.
fn worst<'a>(reports: impl Iterator<Item = &'a PatchReport>) -> Option<PatchReport> {
    reports.fold(None, |acc: Option<PatchReport>, r| {
        Some(match acc {
            None => r.clone(),
            Some(a) => PatchReport {
                error_bound: a.error_bound.max(r.error_bound),
                max_error: a.max_error.zip(r.max_error).map(|(x, y)| x.max(y)),
                ..a
            },
        })
    })
}

/// Reduces a tensor-product patch of degree `(m, n)` to degree
/// `(opts->target, opts->target_v)` with `opts->patch_method` (seed 000 §14.3.1 for
/// `CAGD_PATCH_PERTURB`; direction by direction with the curve method for
/// `CAGD_PATCH_BY_CURVES`), with a certified bound of `max ||P(u,v) - Q(u,v)||` over the
/// unit square (Euclidean).
///
/// Options used: `patch_method`, `constraint`, `target`, `target_v`, `measure`, and
/// `method`, `r`, `p`, `l1`, `l2` for `CAGD_PATCH_BY_CURVES` and
/// `CAGD_CONSTRAINT_BOUNDARY`.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `opts` (in): the options. Borrowed for the call.
/// - `patch_out` (out): on `CAGD_OK`, the reduced patch
///   (`(target + 1) * (target_v + 1) * dim` doubles, read back with
///   `cagd_tensorpatch_points`), owned by the caller: release with
///   `cagd_tensorpatch_free`.
/// - `report_out` (out): on `CAGD_OK`, the report (`cagd_report_bound`,
///   `cagd_report_max_error`, `cagd_report_patch`), owned by the caller: release with
///   `cagd_report_free`. Neither output is written on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `patch`, `opts`, `patch_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `opts->struct_size` is below
///   `sizeof(CagdReduceOptions)`; an invalid `patch_method`, `constraint` or `method`
///   code; `CAGD_PATCH_L2` (triangles only); `CAGD_PATCH_BY_CURVES` with a constraint;
///   the two outputs are the same address; or a pointer is misaligned.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: a target degree above the source, no reduction at all, a
///   target other than `(m - 1, n - 1)` for `CAGD_PATCH_PERTURB`, or a pair the curve
///   method does not accept.
/// - `CAGD_ERR_TOO_MANY_CONSTRAINTS`: corner / boundary constraints with a target degree
///   too small, a boundary method that does not interpolate the end points, or `r + p + 1`
///   above a target degree.
/// - `CAGD_ERR_NON_FINITE`: an intermediate or result value overflows f64 (coordinates
///   near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; `opts` NULL or a readable
/// `CagdReduceOptions` of `opts->struct_size` bytes; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_reduce(
    patch: *const CagdTensorPatch,
    opts: *const CagdReduceOptions,
    patch_out: *mut *mut CagdTensorPatch,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        let o = unsafe { read_options(opts) }?;
        // SAFETY: as above.
        let (q_out, r_out) = unsafe { outputs(patch_out, "patch_out", report_out) }?;
        let red = reduce_tensor(&p.0, (o.target, o.target_v), &tensor_options(&o)?)?;
        *q_out = into_handle(CagdTensorPatch(red.patch));
        *r_out = patch_report(red.report, &o, 1);
        Ok(())
    })
}

/// Reduces a triangular patch of degree `n` to degree `opts->target` with
/// `opts->patch_method` (`CAGD_PATCH_PERTURB`: seed 000 §14.3.2, `n -> n - 1`, no
/// constraint; `CAGD_PATCH_L2`: L2-optimal over the triangle, any constraint), with a
/// certified bound of `max ||T(u,v) - Q(u,v)||` over the triangle (Euclidean).
///
/// Options used: `patch_method`, `constraint`, `target`, `measure`, and `method`, `r`, `p`,
/// `l1`, `l2` for `CAGD_CONSTRAINT_BOUNDARY`.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `opts` (in): the options. Borrowed for the call.
/// - `patch_out` (out): on `CAGD_OK`, the reduced patch
///   (`(target + 1) * (target + 2) / 2 * dim` doubles), owned by the caller: release with
///   `cagd_tripatch_free`.
/// - `report_out` (out): on `CAGD_OK`, the report, owned by the caller: release with
///   `cagd_report_free`. Neither output is written on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `patch`, `opts`, `patch_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `opts->struct_size` is below
///   `sizeof(CagdReduceOptions)`; an invalid `patch_method`, `constraint` or `method`
///   code; `CAGD_PATCH_BY_CURVES` (tensor patches only); `CAGD_PATCH_PERTURB` with a
///   constraint; the two outputs are the same address; or a pointer is misaligned.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target >= n`, or `target != n - 1` for
///   `CAGD_PATCH_PERTURB`.
/// - `CAGD_ERR_TOO_MANY_CONSTRAINTS`: corner / boundary constraints with `target = 0`, or
///   a boundary method that does not interpolate the end points.
/// - `CAGD_ERR_NON_FINITE`: an intermediate or result value overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; `opts` NULL or a readable
/// `CagdReduceOptions` of `opts->struct_size` bytes; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatch_reduce(
    patch: *const CagdTriPatch,
    opts: *const CagdReduceOptions,
    patch_out: *mut *mut CagdTriPatch,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        let o = unsafe { read_options(opts) }?;
        // SAFETY: as above.
        let (q_out, r_out) = unsafe { outputs(patch_out, "patch_out", report_out) }?;
        let red = reduce_triangle(&p.0, o.target, &tri_options(&o)?)?;
        *q_out = into_handle(CagdTriPatch(red.patch));
        *r_out = patch_report(red.report, &o, 1);
        Ok(())
    })
}

/// Reduces a tensor-product patch to degree `(opts->target, opts->target_v)` within
/// `opts->tolerance` (certified, Euclidean): at levels `L = 0, 1, ..., 8` the patch is
/// split into `2^L x 2^L` sub-patches by midpoint bisection and each is reduced as by
/// `cagd_tensorpatch_reduce`; the first level at which every bound meets the tolerance is
/// returned. Neighbouring pieces coincide along shared edges for `CAGD_PATCH_BY_CURVES`
/// with an end-interpolating method and for `CAGD_CONSTRAINT_BOUNDARY`; otherwise each
/// piece is within the tolerance but gaps up to twice the tolerance may appear.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `opts` (in): the options (as `cagd_tensorpatch_reduce`, plus `tolerance`). Borrowed.
/// - `pieces_out` (out): on `CAGD_OK`, the pieces in u-major order, owned by the caller:
///   release with `cagd_tensorpatchlist_free`.
/// - `report_out` (out): on `CAGD_OK`, the report (`cagd_report_bound`: the largest bound
///   of a piece, `<= tolerance`; `cagd_report_patch`: the piece count), owned by the
///   caller: release with `cagd_report_free`. Neither output is written on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `patch`, `opts`, `pieces_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `tolerance` not finite and `> 0`, and as
///   `cagd_tensorpatch_reduce`.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`, `CAGD_ERR_TOO_MANY_CONSTRAINTS`: as
///   `cagd_tensorpatch_reduce`.
/// - `CAGD_ERR_NO_CONVERGENCE`: more than 65 536 pieces (`MAX_TOLERANCE_PIECES`, a
///   `2^a x 2^b` grid) would be needed, or the next round would pass the work cap
///   (`MAX_PATCH_TOLERANCE_WORK`: 2^27 units, a cell of degrees `(p, q)` in `d`
///   coordinates counted `d (p + 1)(q + 1)(p + q + 2)`).
/// - `CAGD_ERR_NON_FINITE`: a reduced piece or its bound overflows (coordinates near the
///   double range).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; `opts` NULL or a readable
/// `CagdReduceOptions` of `opts->struct_size` bytes; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_reduce_to_tolerance(
    patch: *const CagdTensorPatch,
    opts: *const CagdReduceOptions,
    pieces_out: *mut *mut CagdTensorPatchList,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        let o = unsafe { read_options(opts) }?;
        // SAFETY: as above.
        let (l_out, r_out) = unsafe { outputs(pieces_out, "pieces_out", report_out) }?;
        let target = (o.target, o.target_v);
        let pieces = reduce_tensor_to_tolerance(&p.0, target, o.tolerance, &tensor_options(&o)?)?;
        let report = worst(pieces.iter().map(|x| &x.reduction.report))
            .ok_or_else(|| Failure::new(CagdStatus::ERR_PANIC, "internal error: no pieces"))?;
        *r_out = patch_report(report, &o, pieces.len());
        *l_out = into_handle(CagdTensorPatchList(pieces));
        Ok(())
    })
}

/// Reduces a triangular patch to degree `opts->target` within `opts->tolerance`
/// (certified, Euclidean): at levels `L = 0, 1, ..., 8` the patch is split by the 4-way
/// midpoint subdivision of seed 000 Theorem 14.3.1 into `4^L` pieces, each reduced as by
/// `cagd_tripatch_reduce`; the first level at which every bound meets the tolerance is
/// returned. With `CAGD_PATCH_L2` and `CAGD_CONSTRAINT_BOUNDARY` (and a boundary method
/// with `r == p`) neighbouring pieces coincide along shared edges.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `opts` (in): the options (as `cagd_tripatch_reduce`, plus `tolerance`). Borrowed.
/// - `pieces_out` (out): on `CAGD_OK`, the pieces, owned by the caller: release with
///   `cagd_tripatchlist_free`.
/// - `report_out` (out): on `CAGD_OK`, the report, owned by the caller: release with
///   `cagd_report_free`. Neither output is written on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `patch`, `opts`, `pieces_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `tolerance` not finite and `> 0`, and as
///   `cagd_tripatch_reduce`.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`, `CAGD_ERR_TOO_MANY_CONSTRAINTS`: as
///   `cagd_tripatch_reduce`.
/// - `CAGD_ERR_CONDITION_NOT_MET`: a boundary method with `r != p` (the middle
///   sub-triangle traverses shared edges backwards).
/// - `CAGD_ERR_NO_CONVERGENCE`: level 8 (65536 pieces) is not enough, or the next level
///   would pass the work cap (`MAX_PATCH_TOLERANCE_WORK`: 2^27 units, a degree-`n` piece
///   in `d` coordinates counted `d ((n + 1)(n + 2)^2 / 2 + (n + 1)^4 / 12)`: a degree-36 3-D
///   patch stops at level 3).
/// - `CAGD_ERR_NON_FINITE`: a reduced piece or its bound overflows (coordinates near the
///   double range).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live patch handle; `opts` NULL or a readable
/// `CagdReduceOptions` of `opts->struct_size` bytes; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatch_reduce_to_tolerance(
    patch: *const CagdTriPatch,
    opts: *const CagdReduceOptions,
    pieces_out: *mut *mut CagdTriPatchList,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        let o = unsafe { read_options(opts) }?;
        // SAFETY: as above.
        let (l_out, r_out) = unsafe { outputs(pieces_out, "pieces_out", report_out) }?;
        let pieces = reduce_triangle_to_tolerance(&p.0, o.target, o.tolerance, &tri_options(&o)?)?;
        let report = worst(pieces.iter().map(|x| &x.reduction.report))
            .ok_or_else(|| Failure::new(CagdStatus::ERR_PANIC, "internal error: no pieces"))?;
        *r_out = patch_report(report, &o, pieces.len());
        *l_out = into_handle(CagdTriPatchList(pieces));
        Ok(())
    })
}

/// Reads what a patch reduction did: the `CagdPatchMethod` code (-1 for
/// `cagd_bsplinesurface_reduce`), the source and target degrees in u and v (for a triangle
/// both are its degree), and the number of pieces (1 for `cagd_tensorpatch_reduce` /
/// `cagd_tripatch_reduce`; the Bézier patches for `cagd_bsplinesurface_reduce`).
///
/// Parameters:
/// - `report` (in): the report.
/// - `patch_method_out` (out): on `CAGD_OK`, the `CagdPatchMethod` code, or -1.
/// - `degrees_out` (out): on `CAGD_OK`, 4 `size_t`: `from_u, from_v, to_u, to_v`.
/// - `n_pieces_out` (out): on `CAGD_OK`, the number of pieces.
///
/// Returns:
/// - `CAGD_OK`: all outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: any argument is NULL.
/// - `CAGD_ERR_NOT_AVAILABLE`: the report is of a curve reduction.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `report` must be NULL or a live report handle; `patch_method_out`, `n_pieces_out` NULL
/// or writable; `degrees_out` NULL or 4 writable `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_report_patch(
    report: *const CagdReport,
    patch_method_out: *mut i32,
    degrees_out: *mut usize,
    n_pieces_out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let r = unsafe { handle_ref(report, "report") }?;
        // SAFETY: as above.
        let (m, n) = unsafe {
            (
                out_ref(patch_method_out, "patch_method_out")?,
                out_ref(n_pieces_out, "n_pieces_out")?,
            )
        };
        // SAFETY: as above: 4 writable size_t (checked non-NULL and aligned here).
        let d = unsafe { out_ref(degrees_out.cast::<[usize; 4]>(), "degrees_out") }?;
        let ReportKind::Patch {
            report: pr,
            patch_method,
            pieces,
        } = &r.kind
        else {
            return Err(Failure::new(
                CagdStatus::ERR_NOT_AVAILABLE,
                "not the report of a patch reduction",
            ));
        };
        let ((fu, fv), (tu, tv)) = (pr.degrees_from, pr.degrees_to);
        (*m, *d, *n) = (*patch_method, [fu, fv, tu, tv], *pieces);
        Ok(())
    })
}
