//! NURBS ↔ rational Bézier (SPEC-convert §15.1–15.3, cagd-convert): the closed forms of
//! degree 2 and 3 for one span both ways, the biquadratic patch both ways, the general
//! route for whole curves (Böhm extraction into a `CagdCurveList`, and the merge of a list
//! back into one spline with the continuity the pieces have), and the standard form.
//!
//! An inverse whose condition fails (15.1.8, 15.2.11–12, 15.3.13–16: an inverse weight
//! `<= 0`; §15.2: Bézier weights that are not separable) returns
//! `CAGD_ERR_CONVERSION_CONDITION`; the message names the condition, the weight and its
//! value.

use cagd_convert::{
    BezierPieces, bezier_to_biquadratic, bezier_to_cubic_span, bezier_to_quadratic_span,
    biquadratic_to_bezier, cubic_span_to_bezier, pieces_to_nurbs, quadratic_span_to_bezier,
    standard_form, to_bezier_pieces,
};
use cagd_core::{BSplineCurve, Error};

use crate::boundary::{
    CResult, Failure, boundary, check_finite_out, disjoint, finite_scalar, handle_ref, into_handle,
    nonnull, out_ref, points_in, slice_in,
};
use crate::bspline::CagdBSpline;
use crate::curve::{CagdCurve, CagdCurveList, Piece};
use crate::status::CagdStatus;

/// The closed forms exist for degree 2 (§15.1) and 3 (§15.3) only.
fn closed_form_degree(degree: usize) -> CResult<()> {
    if degree == 2 || degree == 3 {
        Ok(())
    } else {
        Err(Error::BadDegreePair {
            from: degree,
            to: degree,
            why: "the closed forms of SPEC-convert §15.1 / §15.3 exist for degree 2 and 3",
        }
        .into())
    }
}

/// One quadratic or cubic NURBS span → its rational Bézier segment, by the closed form of
/// SPEC-convert §15.1 (degree 2, eq. 15.1.3–15.1.7) or §15.3 (degree 3, eq. 15.3.3–15.3.10),
/// in homogeneous form (double and triple knots need no special case). The segment is
/// parametrised by `T = (t - t_n) / (t_{n+1} - t_n)`.
///
/// Parameters:
/// - `degree` (in): 2 or 3.
/// - `knots` (in): the `2 * degree` local knots of the span `[t_n, t_{n+1}]`:
///   `t_{n-1}, t_n, t_{n+1}, t_{n+2}` (degree 2) or `t_{n-2} .. t_{n+3}` (degree 3),
///   non-decreasing, `t_n < t_{n+1}`. Borrowed.
/// - `points` (in): the `degree + 1` control points `r_{n-degree} .. r_n`, row-major,
///   `(degree + 1) * dim` doubles. Borrowed.
/// - `weights` (in): their `degree + 1` weights, finite and `>= DBL_MIN` (not subnormal), or NULL for weights 1.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `curve_out` (out): on `CAGD_OK`, a new rational curve handle of degree `degree`, owned
///   by the caller (release with `cagd_curve_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`.
/// - `CAGD_ERR_NULL_POINTER`: `knots`, `points` or `curve_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`; a zero-length span (`t_n == t_{n+1}`); a
///   misaligned pointer.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `degree` is not 2 or 3.
/// - `CAGD_ERR_BAD_KNOTS`: the knots decrease (the message gives the index).
/// - `CAGD_ERR_NON_FINITE`: a coordinate or a knot is NaN or infinite.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a weight is `<= 0` or not finite.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `knots` must be NULL or `2 * degree` readable doubles; `points` NULL or
/// `(degree + 1) * dim`; `weights` NULL or `degree + 1`; `curve_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_nurbs_span_to_bezier(
    degree: usize,
    knots: *const f64,
    points: *const f64,
    weights: *const f64,
    dim: usize,
    curve_out: *mut *mut CagdCurve,
) -> CagdStatus {
    boundary(|| {
        nonnull(knots, "knots")?;
        nonnull(points, "points")?;
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(curve_out, "curve_out") }?;
        closed_form_degree(degree)?;
        // SAFETY: as above.
        let k = unsafe { slice_in(knots, 2 * degree, "knots") }?;
        // SAFETY: as above.
        let p = unsafe { points_in(points, degree + 1, dim, "points") }?;
        let w = if weights.is_null() {
            vec![1.0; degree + 1]
        } else {
            // SAFETY: as above.
            unsafe { slice_in(weights, degree + 1, "weights") }?.to_vec()
        };
        let bez = if degree == 2 {
            quadratic_span_to_bezier(k, p, &w, dim)
        } else {
            cubic_span_to_bezier(k, p, &w, dim)
        }?;
        *out = into_handle(CagdCurve(bez));
        Ok(())
    })
}

/// A rational quadratic or cubic Bézier segment plus the local knots of a span → the NURBS
/// control points and weights of that span (SPEC-convert §15.1 inverse, eq. 15.1.8–15.1.11;
/// §15.3 inverse, eq. 15.3.11–15.3.21, in the division-safe homogeneous form). The
/// conditions 15.1.8 / 15.3.13–16 are checked as "every inverse weight `> 0`" (equivalent
/// for 15.1.8; for the cubic the weight test decides, see the cagd-convert docs).
///
/// The span is returned as a B-spline handle of `degree + 1` points whose knot vector is
/// the local knots with the first and last repeated once more (`2 * degree + 2` knots): its
/// domain is exactly `[t_n, t_{n+1}]` and it evaluates to the segment there.
///
/// Parameters:
/// - `curve` (in): a curve of degree 2 or 3 (a polynomial one is read with weights 1).
/// - `knots` (in): `2 * degree` local knots, as for `cagd_nurbs_span_to_bezier`.
/// - `span_out` (out): on `CAGD_OK`, a new NURBS handle (release with `cagd_bspline_free`).
/// - `extrapolation_out` (out, may be NULL): on `CAGD_OK`, the extrapolation factor: the
///   largest absolute coefficient of the affine maps `r_i = sum_j lambda_ij R_j` (§15.1:
///   `1 + max(k1, k2)`); errors of the Bézier points grow by up to this factor.
///
/// Returns:
/// - `CAGD_OK`.
/// - `CAGD_ERR_NULL_POINTER`: `curve`, `knots` or `span_out` is NULL.
/// - `CAGD_ERR_CONVERSION_CONDITION`: an inverse weight is `<= 0` or subnormal (condition
///   15.1.8 or the case 15.3.13 / 14 / 15 / 16 that applies; the message gives the weight's
///   index `w_{n-degree+index}` and its value).
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: the curve's degree is not 2 or 3.
/// - `CAGD_ERR_BAD_KNOTS`, `CAGD_ERR_NON_FINITE`, `CAGD_ERR_INVALID_ARGUMENT`: as for
///   `cagd_nurbs_span_to_bezier`; `CAGD_ERR_NON_FINITE` also when the extrapolation factor
///   overflows (knot intervals of wildly different lengths).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; `knots` NULL or `2 * degree` readable
/// doubles; `span_out` NULL or writable; `extrapolation_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bezier_to_nurbs_span(
    curve: *const CagdCurve,
    knots: *const f64,
    span_out: *mut *mut CagdBSpline,
    extrapolation_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        nonnull(knots, "knots")?;
        // SAFETY: as above.
        let out = unsafe { out_ref(span_out, "span_out") }?;
        let extra = if extrapolation_out.is_null() {
            None
        } else {
            // SAFETY: as above.
            Some(unsafe { out_ref(extrapolation_out, "extrapolation_out") }?)
        };
        let degree = c.0.degree();
        closed_form_degree(degree)?;
        // SAFETY: as above.
        let k = unsafe { slice_in(knots, 2 * degree, "knots") }?;
        let span = if degree == 2 {
            bezier_to_quadratic_span(&c.0, k)
        } else {
            bezier_to_cubic_span(&c.0, k)
        }?;
        if !span.extrapolation.is_finite() {
            // Knot intervals of wildly different lengths: the inverse maps' coefficients
            // overflow, so nothing can be said about how errors grow.
            return Err(Error::NonFinite {
                index: 0,
                coord: 0,
                value: span.extrapolation,
            }
            .into());
        }
        let mut full = Vec::with_capacity(2 * degree + 2);
        full.push(k[0]);
        full.extend_from_slice(k);
        full.push(k[2 * degree - 1]);
        let spline = BSplineCurve::new_rational(degree, full, span.points, span.weights, span.dim)?;
        *out = into_handle(CagdBSpline(spline));
        if let Some(e) = extra {
            *e = span.extrapolation;
        }
        Ok(())
    })
}

/// A biquadratic NURBS patch → its rational biquadratic Bézier patch (SPEC-convert §15.2):
/// the homogeneous net is mapped with the 15.1 maps along `v` and along `u` (for separable
/// weights `w_ij = g_i h_j` this is the closed form 15.2.3–15.2.10, with Bézier weights
/// `G_i H_j`).
///
/// Parameters:
/// - `u_knots`, `v_knots` (in): the 4 local knots of each direction (`u_{m-1} .. u_{m+2}`,
///   the span is the middle interval, of positive length).
/// - `points` (in): the 3x3 net, i-major (`i` along `u`), `9 * dim` doubles.
/// - `weights` (in): 9 weights (i-major), finite and `> 0`, or NULL for weights 1.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `points_out` (out): `9 * dim` doubles, the Bézier points (i-major).
/// - `weights_out` (out): 9 doubles, the Bézier weights (i-major).
///
/// Returns:
/// - `CAGD_OK`: both outputs are written.
/// - `CAGD_ERR_NULL_POINTER`: a knot, point or output pointer is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, a zero-length span, outputs that overlap, a
///   misaligned pointer.
/// - `CAGD_ERR_BAD_KNOTS`, `CAGD_ERR_NON_FINITE`, `CAGD_ERR_NON_POSITIVE_WEIGHT`.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// Every pointer must be NULL or point to the documented number of doubles (readable for
/// inputs, writable for outputs).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_nurbs22_span_to_bezier(
    u_knots: *const f64,
    v_knots: *const f64,
    points: *const f64,
    weights: *const f64,
    dim: usize,
    points_out: *mut f64,
    weights_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let (uk, vk, p, w) = unsafe { patch_inputs(u_knots, v_knots, points, weights, dim) }?;
        // SAFETY: as above.
        let (po, wo) = unsafe { patch_outputs(points_out, weights_out, dim) }?;
        let (bp, bw) = biquadratic_to_bezier(uk, vk, p, &w, dim)?;
        // Knots far apart in magnitude can overflow the maps (issue 18, fuzz harness):
        // CAGD_ERR_NON_FINITE, nothing written.
        check_finite_out(&bp, "points_out")?;
        check_finite_out(&bw, "weights_out")?;
        po.copy_from_slice(&bp);
        wo.copy_from_slice(&bw);
        Ok(())
    })
}

/// A rational biquadratic Bézier patch → the biquadratic NURBS span (SPEC-convert §15.2
/// inverse, eq. 15.2.11–15.2.17 with the erratum of 15.2.15): the 3x3 Bézier weights must
/// be separable (rank 1, `W_ij = G_i H_j`), then the inverse of 15.1 applies per direction.
///
/// Parameters:
/// - `u_knots`, `v_knots`, `dim` (in): as for `cagd_nurbs22_span_to_bezier`.
/// - `points` (in): the 3x3 Bézier points, i-major, `9 * dim` doubles.
/// - `weights` (in): the 9 Bézier weights (i-major), or NULL for weights 1.
/// - `points_out` (out): `9 * dim` doubles, the NURBS points.
/// - `weights_out` (out): 9 doubles, the NURBS weights `g_i h_j`.
/// - `extrapolation_out` (out, may be NULL): the extrapolation factor.
///
/// Returns:
/// - `CAGD_OK`: the outputs are written.
/// - `CAGD_ERR_CONVERSION_CONDITION`: the weights are not rank 1 (condition "15.2 separable
///   weights"), or an inverse weight is `<= 0` or subnormal (15.2.11 along `u`, 15.2.12
///   along `v`).
/// - `CAGD_ERR_NULL_POINTER`: a knot, point or output pointer is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, a zero-length span, outputs that overlap, a
///   misaligned pointer.
/// - `CAGD_ERR_BAD_KNOTS`, `CAGD_ERR_NON_FINITE`, `CAGD_ERR_NON_POSITIVE_WEIGHT`: as for
///   `cagd_nurbs22_span_to_bezier`.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// As `cagd_nurbs22_span_to_bezier`; `extrapolation_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bezier22_to_nurbs22_span(
    u_knots: *const f64,
    v_knots: *const f64,
    points: *const f64,
    weights: *const f64,
    dim: usize,
    points_out: *mut f64,
    weights_out: *mut f64,
    extrapolation_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let (uk, vk, p, w) = unsafe { patch_inputs(u_knots, v_knots, points, weights, dim) }?;
        // SAFETY: as above.
        let (po, wo) = unsafe { patch_outputs(points_out, weights_out, dim) }?;
        let extra = if extrapolation_out.is_null() {
            None
        } else {
            // SAFETY: as above.
            Some(unsafe { out_ref(extrapolation_out, "extrapolation_out") }?)
        };
        let s = bezier_to_biquadratic(uk, vk, p, &w, dim)?;
        let weights: Vec<f64> = (0..9)
            .map(|k| s.u_weights[k / 3] * s.v_weights[k % 3])
            .collect();
        // As cagd_nurbs22_span_to_bezier: a non-finite result is CAGD_ERR_NON_FINITE.
        check_finite_out(&s.points, "points_out")?;
        check_finite_out(&weights, "weights_out")?;
        let extrapolation = finite_scalar(s.extrapolation, "extrapolation_out")?;
        po.copy_from_slice(&s.points);
        wo.copy_from_slice(&weights);
        if let Some(e) = extra {
            *e = extrapolation;
        }
        Ok(())
    })
}

type PatchIn<'a> = (&'a [f64], &'a [f64], &'a [f64], Vec<f64>);

/// The checked inputs of the patch functions.
///
/// # Safety
/// As the patch functions' inputs.
unsafe fn patch_inputs<'a>(
    u_knots: *const f64,
    v_knots: *const f64,
    points: *const f64,
    weights: *const f64,
    dim: usize,
) -> CResult<PatchIn<'a>> {
    nonnull(u_knots, "u_knots")?;
    nonnull(v_knots, "v_knots")?;
    nonnull(points, "points")?;
    // SAFETY: forwarded contract.
    let uk = unsafe { slice_in(u_knots, 4, "u_knots") }?;
    // SAFETY: forwarded contract.
    let vk = unsafe { slice_in(v_knots, 4, "v_knots") }?;
    // SAFETY: forwarded contract.
    let p = unsafe { points_in(points, 9, dim, "points") }?;
    let w = if weights.is_null() {
        vec![1.0; 9]
    } else {
        // SAFETY: forwarded contract.
        unsafe { slice_in(weights, 9, "weights") }?.to_vec()
    };
    Ok((uk, vk, p, w))
}

/// The checked outputs of the patch functions (`9 * dim` and 9 doubles, disjoint).
///
/// # Safety
/// As the patch functions' outputs.
unsafe fn patch_outputs<'a>(
    points_out: *mut f64,
    weights_out: *mut f64,
    dim: usize,
) -> CResult<(&'a mut [f64], &'a mut [f64])> {
    nonnull(points_out, "points_out")?;
    nonnull(weights_out, "weights_out")?;
    let n = crate::boundary::checked_len(9, dim, "9 * dim")?;
    disjoint(
        points_out,
        n,
        weights_out,
        9,
        "`points_out` and `weights_out`",
    )?;
    if !points_out.is_aligned() || !weights_out.is_aligned() {
        return Err(Failure::invalid(
            "an output pointer is not aligned for double",
        ));
    }
    // SAFETY: non-NULL, aligned, disjoint, sizes by the caller's contract.
    Ok(unsafe {
        (
            std::slice::from_raw_parts_mut(points_out, n),
            std::slice::from_raw_parts_mut(weights_out, 9),
        )
    })
}

/// Every non-empty span of a B-spline / NURBS curve as a (rational) Bézier piece, by the
/// general route of cagd-convert (Böhm knot insertion in homogeneous space, in place; any
/// degree, clamped or unclamped knots). Same pieces as `cagd_bspline_to_beziers` (which
/// blossoms each span), faster.
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `list_out` (out): on `CAGD_OK`, the pieces with their knot intervals (release with
///   `cagd_curvelist_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `list_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a misaligned pointer.
/// - `CAGD_ERR_NON_FINITE`: a piece overflows.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `list_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_to_bezier_pieces(
    spline: *const CagdBSpline,
    list_out: *mut *mut CagdCurveList,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(spline, "spline") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(list_out, "list_out") }?;
        let pieces = to_bezier_pieces(&s.0)?;
        let b = pieces.breaks();
        let list = pieces
            .to_segments()?
            .into_iter()
            .enumerate()
            .map(|(k, curve)| Piece {
                start: b[k],
                end: b[k + 1],
                curve,
                bound: None,
            })
            .collect();
        *out = into_handle(CagdCurveList(list));
        Ok(())
    })
}

/// Merges the pieces of a curve list (consecutive intervals, one degree and dimension)
/// into one B-spline / NURBS curve with the highest continuity the pieces have at each
/// joint (cagd-convert `pieces_to_nurbs`: each joint's knot copies removed while the
/// certified residual stays within `tol`, control points by blossoms, certified by
/// re-extraction). The reverse of `cagd_bspline_to_bezier_pieces`: a clamped spline comes
/// back with its knot vector (an unclamped one comes back clamped, the same curve; give its
/// outer knots to `cagd_curvelist_to_bspline_unclamped` to get its knot vector back).
///
/// Parameters:
/// - `list` (in): the pieces, e.g. from `cagd_bspline_to_bezier_pieces`; piece `i + 1`
///   must start where piece `i` ends.
/// - `tol` (in): the joint tolerance in working coordinates (homogeneous `(w x, w)` for
///   rational pieces), finite and `> 0`, or exactly 0 for the default rounding level
///   (`1e-12` times the largest working coordinate).
/// - `spline_out` (out): on `CAGD_OK`, the spline (release with `cagd_bspline_free`).
///
/// Returns:
/// - `CAGD_OK`.
/// - `CAGD_ERR_NULL_POINTER`: `list` or `spline_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `tol` negative, NaN or infinite; intervals that are not
///   consecutive; a misaligned pointer.
/// - `CAGD_ERR_DIMENSION_MISMATCH`: pieces of differing degree or dimension.
/// - `CAGD_ERR_NON_FINITE`, `CAGD_ERR_NON_POSITIVE_WEIGHT`: the result overflows.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; `spline_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curvelist_to_bspline(
    list: *const CagdCurveList,
    tol: f64,
    spline_out: *mut *mut CagdBSpline,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(spline_out, "spline_out") }?;
        let tol = joint_tolerance(tol)?;
        let pieces = list_pieces(l)?;
        let r = pieces_to_nurbs(&pieces, tol)?;
        *out = into_handle(CagdBSpline(r.curve));
        Ok(())
    })
}

/// The joint tolerance of the merges: 0 for the default (`None`), else finite and `> 0`.
pub(crate) fn joint_tolerance(tol: f64) -> CResult<Option<f64>> {
    if tol == 0.0 {
        Ok(None)
    } else if tol.is_finite() && tol > 0.0 {
        Ok(Some(tol))
    } else {
        Err(Error::BadTolerance { value: tol }.into())
    }
}

/// The pieces of a curve list (consecutive intervals) with their breaks.
pub(crate) fn list_pieces(l: &CagdCurveList) -> CResult<BezierPieces> {
    let mut breaks = Vec::with_capacity(l.0.len() + 1);
    for (i, p) in l.0.iter().enumerate() {
        if i > 0 && p.start != l.0[i - 1].end {
            return Err(Failure::invalid(format!(
                "piece {i} starts at {} but piece {} ends at {}: the intervals must be \
                 consecutive",
                p.start,
                i - 1,
                l.0[i - 1].end
            )));
        }
        breaks.push(p.start);
    }
    breaks.push(l.0.last().map_or(0.0, |p| p.end));
    let segs: Vec<_> = l.0.iter().map(|p| p.curve.clone()).collect();
    Ok(BezierPieces::from_segments(&segs, &breaks)?)
}

/// The standard form of a rational Bézier curve: the Möbius reparametrisation with end
/// weights 1, the same shape (`original(t(s)) = standard(s)`, `t = rho s / ((1 - s) +
/// rho s)`). A polynomial curve is copied (`rho = 1`).
///
/// Parameters:
/// - `curve` (in): the curve (degree `>= 1` when rational).
/// - `curve_out` (out): on `CAGD_OK`, the curve in standard form (release with
///   `cagd_curve_free`).
/// - `rho_out` (out, may be NULL): on `CAGD_OK`, `rho = (w_0 / w_n)^(1/n)`.
///
/// Returns:
/// - `CAGD_OK`.
/// - `CAGD_ERR_NULL_POINTER`: `curve` or `curve_out` is NULL.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: a rational curve of degree 0.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a scaled weight under- or overflows.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a misaligned pointer, or `rho` itself over- or
///   underflows (end weights too far apart, e.g. 1e300 and 1e-300 at degree 1).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `curve` must be NULL or a live curve handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curve_standard_form(
    curve: *const CagdCurve,
    curve_out: *mut *mut CagdCurve,
    rho_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let c = unsafe { handle_ref(curve, "curve") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(curve_out, "curve_out") }?;
        let rho = if rho_out.is_null() {
            None
        } else {
            // SAFETY: as above.
            Some(unsafe { out_ref(rho_out, "rho_out") }?)
        };
        let s = standard_form(&c.0)?;
        *out = into_handle(CagdCurve(s.curve));
        if let Some(r) = rho {
            *r = s.rho;
        }
        Ok(())
    })
}
