//! `CagdBSplineSurface`: tensor-product B-spline / NURBS surfaces — creation, read-back,
//! evaluation, release, and their degree reduction (`cagd_bsplinesurface_reduce`).

use cagd_core::BSplineSurface;
use cagd_reduce::{
    PatchReport, SurfaceOptions, reduce_bspline_surface, reduce_bspline_surface_fit,
    reduce_bspline_surface_to_tolerance,
};

use crate::boundary::{
    CResult, Failure, OUT, boundary, boundary_void, checked_len, free_handle, handle_ref,
    into_handle, nonnull, out_ref, points_in, slice_in, slice_out,
};
use crate::bspline::spline_failure;
use crate::options::{CagdReduceMethod, CagdReduceOptions, read_options};
use crate::report::{CagdReport, ReportKind};
use crate::status::CagdStatus;

/// Opaque handle to a tensor-product B-spline surface of degrees `(p, q)` (each `0..=64`)
/// with `n_u * n_v` control points stored i-major (`P_ij` is point `i * n_v + j`, `i` along
/// u), knot vectors of `n_u + p + 1` and `n_v + q + 1` knots, polynomial or NURBS.
/// Immutable; release with `cagd_bsplinesurface_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdBSplineSurface(pub(crate) BSplineSurface);

/// Creates a B-spline or NURBS surface (`weights` NULL for a polynomial one)
/// `S(u, v) = sum_ij N_i,p(u) N_j,q(v) w_ij P_ij / sum_ij N_i,p(u) N_j,q(v) w_ij`.
///
/// Parameters:
/// - `deg_u` (in), `deg_v` (in): the degrees `p`, `q`, each `0..=64`.
/// - `knots_u` (in): `n_knots_u` doubles, non-decreasing, finite, multiplicities at most
///   `p + 1`; `n_knots_u` must equal `n_u + p + 1`. Borrowed and copied.
/// - `n_knots_u` (in): the length of `knots_u`.
/// - `knots_v` (in): `n_knots_v = n_v + q + 1` doubles, likewise. Borrowed and copied.
/// - `n_knots_v` (in): the length of `knots_v`.
/// - `points` (in): `n_u * n_v * dim` doubles, i-major: coordinate k of `P_ij` at
///   `points[(i * n_v + j) * dim + k]`, Euclidean. Borrowed and copied.
/// - `weights` (in): NULL (polynomial) or `n_u * n_v` doubles, i-major, each finite and
///   `> 0`. Borrowed and copied.
/// - `n_u` (in), `n_v` (in): control points in u and v, `>= p + 1`, `>= q + 1`.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `surface_out` (out): on `CAGD_OK`, a new handle owned by the caller (release with
///   `cagd_bsplinesurface_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*surface_out` holds the new surface.
/// - `CAGD_ERR_NULL_POINTER`: `knots_u`, `knots_v`, `points` or `surface_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, a length formula overflows, or a pointer is
///   misaligned.
/// - `CAGD_ERR_NOT_ENOUGH_POINTS`: `n_u < p + 1` or `n_v < q + 1` (or zero).
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `p > 64` or `q > 64`.
/// - `CAGD_ERR_NON_FINITE`: a coordinate or a knot is NaN or infinite.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a weight is `<= 0`, subnormal, NaN or infinite.
/// - `CAGD_ERR_BAD_KNOTS`: a knot count is wrong, knots decrease, or a domain is empty.
/// - `CAGD_ERR_MULTIPLICITY`: a knot value appears more than degree + 1 times.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// Each array pointer must be NULL or point to the documented number of readable doubles;
/// `surface_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bsplinesurface_new(
    deg_u: usize,
    deg_v: usize,
    knots_u: *const f64,
    n_knots_u: usize,
    knots_v: *const f64,
    n_knots_v: usize,
    points: *const f64,
    weights: *const f64,
    n_u: usize,
    n_v: usize,
    dim: usize,
    surface_out: *mut *mut CagdBSplineSurface,
) -> CagdStatus {
    boundary(|| {
        nonnull(knots_u, "knots_u")?;
        nonnull(knots_v, "knots_v")?;
        nonnull(points, "points")?;
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(surface_out, "surface_out") }?;
        let n = checked_len(n_u, n_v, "n_u * n_v")?;
        // SAFETY: as above.
        let pts = unsafe { points_in(points, n, dim, "points") }?;
        // SAFETY: as above.
        let ku = unsafe { slice_in(knots_u, n_knots_u, "knots_u") }?;
        // SAFETY: as above.
        let kv = unsafe { slice_in(knots_v, n_knots_v, "knots_v") }?;
        let (d, c) = ((deg_u, deg_v), (n_u, n_v));
        let s = if weights.is_null() {
            BSplineSurface::new(d, ku.to_vec(), kv.to_vec(), pts.to_vec(), c, dim)
        } else {
            // SAFETY: as above.
            let w = unsafe { slice_in(weights, n, "weights") }?;
            BSplineSurface::new_rational(
                d,
                ku.to_vec(),
                kv.to_vec(),
                pts.to_vec(),
                w.to_vec(),
                c,
                dim,
            )
        }
        .map_err(spline_failure)?;
        *out = into_handle(CagdBSplineSurface(s));
        Ok(())
    })
}

/// Releases a surface. NULL is accepted and ignored; a non-NULL handle must be released
/// exactly once and not used afterwards.
///
/// Parameters:
/// - `surface` (in, consumed): a handle made by cagd, or NULL.
///
/// Does not change `cagd_last_error_message()`.
///
/// # Safety
/// `surface` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bsplinesurface_free(surface: *mut CagdBSplineSurface) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(surface) });
}

/// Reads the shape of a surface: degrees, control-point counts, dimension, rationality.
/// The knot counts are `n_u + deg_u + 1` and `n_v + deg_v + 1`.
///
/// Parameters:
/// - `surface` (in): the surface.
/// - `shape_out` (out): on `CAGD_OK`, 5 `size_t`: `deg_u, deg_v, n_u, n_v, dim`.
/// - `rational_out` (out): on `CAGD_OK`, `true` for a NURBS surface.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: any argument is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `surface` must be NULL or a live surface handle; `shape_out` NULL or 5 writable
/// `size_t`; `rational_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bsplinesurface_shape(
    surface: *const CagdBSplineSurface,
    shape_out: *mut usize,
    rational_out: *mut bool,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(surface, "surface") }?;
        // SAFETY: as above: 5 writable size_t.
        let (sh, r) = unsafe {
            (
                out_ref(shape_out.cast::<[usize; 5]>(), "shape_out")?,
                out_ref(rational_out, "rational_out")?,
            )
        };
        let ((p, q), (nu, nv)) = (s.0.degrees(), s.0.counts());
        (*sh, *r) = ([p, q, nu, nv, s.0.dim()], s.0.is_rational());
        Ok(())
    })
}

/// Which array of a surface to copy.
#[derive(Clone, Copy)]
#[repr(i32)]
enum Part {
    KnotsU,
    KnotsV,
    Points,
    Weights,
}

/// Copies one array of a surface (`part`: 0 knots in u, 1 knots in v, 2 points, 3 weights).
///
/// Parameters:
/// - `surface` (in): the surface.
/// - `part` (in): which array: 0 = knots in u (`n_u + deg_u + 1` doubles), 1 = knots in v
///   (`n_v + deg_v + 1`), 2 = control points (`n_u * n_v * dim`, i-major, Euclidean), 3 =
///   weights (`n_u * n_v`, i-major; all 1.0 for a polynomial surface).
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `*out_needed`
///   doubles hold the array. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, the length.
///
/// Returns:
/// - `CAGD_OK`: the array is in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `surface` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `part` is not 0..=3, or a pointer is misaligned.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is below the length; only `*out_needed` is
///   written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `surface` must be NULL or a live surface handle; `out` NULL or `out_cap` writable
/// doubles; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bsplinesurface_array(
    surface: *const CagdBSplineSurface,
    part: i32,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(surface, "surface") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let part = match part {
            0 => Part::KnotsU,
            1 => Part::KnotsV,
            2 => Part::Points,
            3 => Part::Weights,
            other => return Err(Failure::invalid(format!("part = {other} is not 0..=3"))),
        };
        match (part, s.0.weights()) {
            (Part::KnotsU, _) => dst.copy_from(s.0.knots_u()),
            (Part::KnotsV, _) => dst.copy_from(s.0.knots_v()),
            (Part::Points, _) => dst.copy_from(s.0.points()),
            (Part::Weights, Some(w)) => dst.copy_from(w),
            (Part::Weights, None) => {
                let (nu, nv) = s.0.counts();
                dst.take(nu * nv)?.fill(1.0);
                Ok(())
            }
        }
    })
}

/// Evaluates a surface at `(u, v)` (de Boor in each direction; homogeneous for NURBS).
/// Inside the domain `[knots_u[p], knots_u[n_u]] x [knots_v[q], knots_v[n_v]]` it is the
/// surface; other finite values extrapolate.
///
/// Parameters:
/// - `surface` (in): the surface.
/// - `u` (in), `v` (in): the parameters, finite.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `dim` doubles hold
///   the point. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `dim`.
///
/// Returns:
/// - `CAGD_OK`: the point is in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `surface` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `u` or `v` is NaN or infinite, or a pointer is
///   misaligned.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < dim`; only `*out_needed` is written.
/// - `CAGD_ERR_NON_FINITE`: the point overflows f64 (`(u, v)` far outside the
///   domain, or coordinates near the limits of f64); nothing is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `surface` must be NULL or a live surface handle; `out` NULL or `out_cap` writable
/// doubles; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bsplinesurface_eval(
    surface: *const CagdBSplineSurface,
    u: f64,
    v: f64,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(surface, "surface") }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let p = s.0.eval(u, v)?;
        dst.copy_from(&p)
    })
}

/// Checks and borrows the two outputs of the surface reduction.
///
/// # Safety
/// Both pointers NULL or writable.
unsafe fn outputs<'a>(
    surface_out: *mut *mut CagdBSplineSurface,
    report_out: *mut *mut CagdReport,
) -> CResult<(&'a mut *mut CagdBSplineSurface, &'a mut *mut CagdReport)> {
    nonnull(surface_out, "surface_out")?;
    nonnull(report_out, "report_out")?;
    if surface_out.addr() == report_out.addr() {
        return Err(Failure::invalid(
            "`surface_out` and `report_out` are the same address",
        ));
    }
    // SAFETY: forwarded contract; the two outputs do not overlap.
    unsafe {
        Ok((
            out_ref(surface_out, "surface_out")?,
            out_ref(report_out, "report_out")?,
        ))
    }
}

/// Reduces a B-spline / NURBS surface of degrees `(p, q)` to
/// `(opts->target, opts->target_v)` patch by patch: each Bézier patch is reduced in u by
/// the curve operator of `opts->method` (`CAGD_METHOD_CONSTRAINED_CHEBYSHEV`, seed 000
/// §14.5, or `CAGD_METHOD_L2`) on every column, then in v on every row, with end orders
/// `min(continuity, p - s)` at each knot line (0 at the boundary), so patches sharing a
/// knot line keep the same derivatives across it; the merged surface stores interior knots
/// of multiplicity `target` / `target_v` (structurally C0; surface knot removal is not
/// implemented). Certified bound of `max ||S - S'||` (Euclidean, model space).
///
/// Options used: `method`, `target`, `target_v` (`1 <= target <= p`,
/// `1 <= target_v <= q`, not both equal: an equal one leaves that direction alone),
/// `continuity` (at most `floor((m - 1) / 2)` for a reduced direction; default 0),
/// `measure` (17 x 17 samples per input patch).
///
/// Parameters:
/// - `surface` (in): the surface.
/// - `opts` (in): the options. Borrowed for the call.
/// - `surface_out` (out): on `CAGD_OK`, the reduced surface, owned by the caller: release
///   with `cagd_bsplinesurface_free`.
/// - `report_out` (out): on `CAGD_OK`, the report (`cagd_report_bound`,
///   `cagd_report_max_error`, `cagd_report_patch` with patch method -1 and the number of
///   Bézier patches), owned by the caller: release with `cagd_report_free`. Neither output
///   is written on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `surface`, `opts`, `surface_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `opts->struct_size` below `sizeof(CagdReduceOptions)`,
///   an invalid method code or a method other than the two above, the two outputs are the
///   same address, or a pointer is misaligned.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: a target 0 or above its degree, or both equal.
/// - `CAGD_ERR_TOO_MANY_CONSTRAINTS`: `continuity` too large for a reduced direction.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a reduced NURBS weight is not positive.
/// - `CAGD_ERR_CONDITION_NOT_MET`: coordinates near the limits of f64, whose rounding
///   level in the centred model frame overflows.
/// - `CAGD_ERR_NON_FINITE`: a reduced control point overflows (coordinates near the limits
///   of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `surface` must be NULL or a live surface handle; `opts` NULL or a readable
/// `CagdReduceOptions` of `opts->struct_size` bytes; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bsplinesurface_reduce(
    surface: *const CagdBSplineSurface,
    opts: *const CagdReduceOptions,
    surface_out: *mut *mut CagdBSplineSurface,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(surface, "surface") }?;
        // SAFETY: as above.
        let o = unsafe { read_options(opts) }?;
        // SAFETY: as above.
        let (s_out, r_out) = unsafe { outputs(surface_out, report_out) }?;
        surface_reduce(&s.0, &o, None, s_out, r_out)
    })
}

/// Reduces a B-spline / NURBS surface to `(opts->target, opts->target_v)` with a certified
/// bound `<= opts->tolerance` (Euclidean, model space), by `opts->spline_strategy`:
/// - `CAGD_SPLINE_FIT` (default): the global least-squares fit of `cagd_bspline_reduce`
///   in u on the bundle of control-point columns, then in v on the rows (half the
///   tolerance for u, the rest for v); knot lines keep `C^min(k, m - 1)` where the input is
///   `C^k` (`k` capped by `spline_continuity`, `-1` = no cap), knots are added where a span
///   misses its share and removed where the tolerance allows (NURBS too). The
///   report's method is `CAGD_METHOD_L2`, its pieces the patches of the result.
/// - `CAGD_SPLINE_SEGMENTS`: the surface is refined uniformly (every knot span split into
///   `2^L` equal spans by exact knot insertion, `L = 0..=6`) and reduced as by
///   `cagd_bsplinesurface_reduce` (`method`, `continuity`); the first level whose bound
///   meets the tolerance is returned.
///
/// Options used: `spline_strategy`, `target`, `target_v`, `tolerance` (finite, `> 0`),
/// `measure`; `spline_continuity` (fit) or `method`, `continuity` (segments).
///
/// Parameters:
/// - `surface` (in): the surface.
/// - `opts` (in): the options. Borrowed for the call.
/// - `surface_out` (out): on `CAGD_OK`, the reduced surface, owned by the caller: release
///   with `cagd_bsplinesurface_free`.
/// - `report_out` (out): on `CAGD_OK`, the report, as for `cagd_bsplinesurface_reduce`
///   (its number of pieces is the number of Bézier patches of the refined surface), owned
///   by the caller: release with `cagd_report_free`. Neither output is written on failure.
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: `surface`, `opts`, `surface_out` or `report_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `tolerance` not finite and `> 0`; an unknown
///   `spline_strategy` or `CAGD_SPLINE_PIEGL_TILLER_1995` (curves only); `spline_continuity`
///   below `-1`; and as `cagd_bsplinesurface_reduce`.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`, `CAGD_ERR_TOO_MANY_CONSTRAINTS` (fit: `spline_continuity`
///   above `m - 1` of a reduced direction), `CAGD_ERR_NON_POSITIVE_WEIGHT`: as
///   `cagd_bsplinesurface_reduce`.
/// - `CAGD_ERR_BAD_KNOTS` (fit): a knot line of multiplicity `p + 1`.
/// - `CAGD_ERR_CONDITION_NOT_MET` (fit): the tolerance is below the rounding level, or
///   the refinement of a direction needs more than `2^23` span coordinates fitted over
///   its rounds, each span counted with 24 more per curve of the bundle and, above degree 7, `(p + 1)^2 / 64`
///   times (bounded work: about a second).
/// - `CAGD_ERR_NO_CONVERGENCE` (segments): level 6 is not enough.
/// - `CAGD_ERR_SINGULAR`: a least-squares system of the fit is singular (degenerate
///   knots or data).
/// - `CAGD_ERR_NON_FINITE`: a computed point overflows f64 (knot insertion or the
///   reduction of coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `surface` must be NULL or a live surface handle; `opts` NULL or a readable
/// `CagdReduceOptions` of `opts->struct_size` bytes; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bsplinesurface_reduce_to_tolerance(
    surface: *const CagdBSplineSurface,
    opts: *const CagdReduceOptions,
    surface_out: *mut *mut CagdBSplineSurface,
    report_out: *mut *mut CagdReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(surface, "surface") }?;
        // SAFETY: as above.
        let o = unsafe { read_options(opts) }?;
        // SAFETY: as above.
        let (s_out, r_out) = unsafe { outputs(surface_out, report_out) }?;
        surface_reduce(&s.0, &o, Some(o.tolerance), s_out, r_out)
    })
}

/// The body shared by [`cagd_bsplinesurface_reduce`] and
/// [`cagd_bsplinesurface_reduce_to_tolerance`]: reduce (within `tolerance` when given) and
/// write both outputs.
fn surface_reduce(
    s: &BSplineSurface,
    o: &CagdReduceOptions,
    tolerance: Option<f64>,
    s_out: &mut *mut CagdBSplineSurface,
    r_out: &mut *mut CagdReport,
) -> CResult<()> {
    if let Some(tol) = tolerance {
        let fit = crate::options::surface_fit_options(o, tol)?;
        if let Some(fopts) = fit {
            let red = reduce_bspline_surface_fit(s, &fopts).map_err(spline_failure)?;
            let out = SurfaceOut {
                pieces: red.spans_out.0 * red.spans_out.1,
                method: CagdReduceMethod::METHOD_L2 as i32,
                name: "bspline-surface-fit",
                bounds: (red.error_bound, red.max_error),
            };
            write_outputs(s, red.surface, out, s_out, r_out);
            return Ok(());
        }
    }
    let sopts = SurfaceOptions {
        continuity: Some(o.continuity),
        method: o.method()?,
        measure: o.measure,
        ..SurfaceOptions::new((o.target, o.target_v))
    };
    let red = match tolerance {
        None => reduce_bspline_surface(s, &sopts),
        Some(tol) => reduce_bspline_surface_to_tolerance(s, &sopts, tol),
    }
    .map_err(spline_failure)?;
    let out = SurfaceOut {
        pieces: red.patches,
        method: o.method,
        name: "bspline-surface",
        bounds: (red.error_bound, red.max_error),
    };
    write_outputs(s, red.surface, out, s_out, r_out);
    Ok(())
}

/// What the report of a surface reduction holds besides the degrees.
struct SurfaceOut {
    pieces: usize,
    method: i32,
    name: &'static str,
    /// Certified bound and (on request) the measured error.
    bounds: (f64, Option<f64>),
}

/// Writes the reduced surface and its report to the outputs.
fn write_outputs(
    input: &BSplineSurface,
    surface: BSplineSurface,
    out: SurfaceOut,
    s_out: &mut *mut CagdBSplineSurface,
    r_out: &mut *mut CagdReport,
) {
    let report = PatchReport {
        method: out.name,
        degrees_from: input.degrees(),
        degrees_to: surface.degrees(),
        error_bound: out.bounds.0,
        max_error: out.bounds.1,
    };
    *s_out = into_handle(CagdBSplineSurface(surface));
    *r_out = into_handle(CagdReport {
        kind: ReportKind::Patch {
            report,
            patch_method: -1,
            pieces: out.pieces,
        },
        method: out.method,
    });
}
