//! The exact round trip of an unclamped spline through its Bézier pieces (cagd-convert
//! `OuterKnots`): a curve list does not carry the knots beyond the first and last break,
//! so they are copied out of the spline (`cagd_bspline_outer_knots`) and handed to the
//! merge (`cagd_curvelist_to_bspline_unclamped`). Beyond the seed (SPEC-convert §15.3's
//! general route, both ways, for unclamped knot vectors).

use cagd_convert::pieces_to_nurbs;

use crate::boundary::{CResult, Failure, OUT, boundary, handle_ref, out_ref, slice_in, slice_out};
use crate::bspline::CagdBSpline;
use crate::convert_nurbs::{joint_tolerance, list_pieces};
use crate::curve::CagdCurveList;
use crate::status::CagdStatus;

/// `side` of `cagd_bspline_outer_knots`: the knots before the last copy of the first break.
pub const CAGD_SIDE_LEFT: i32 = 0;
/// `side` of `cagd_bspline_outer_knots`: the knots after the first copy of the last break.
pub const CAGD_SIDE_RIGHT: i32 = 1;

/// The outer knots of one side of a valid knot vector of degree `p`.
fn outer_side(knots: &[f64], p: usize, side: i32) -> CResult<&[f64]> {
    let n = knots.len() - p - 1;
    match side {
        CAGD_SIDE_LEFT => {
            let mut s = p;
            while knots[s + 1] <= knots[s] {
                s += 1;
            }
            Ok(&knots[..s])
        }
        CAGD_SIDE_RIGHT => {
            let mut e = n;
            while knots[e - 1] >= knots[e] {
                e -= 1;
            }
            Ok(&knots[e + 1..])
        }
        _ => Err(Failure::invalid(format!(
            "side = {side} is not CAGD_SIDE_LEFT (0) or CAGD_SIDE_RIGHT (1)"
        ))),
    }
}

/// Copies the outer knots of one side of a spline: with `side == CAGD_SIDE_LEFT` the knots
/// before the last copy of the first break (the start of the domain), with
/// `CAGD_SIDE_RIGHT` those after the first copy of the last break. A clamped spline of
/// degree `p` has `p` copies of the break on each side; an unclamped one has its own
/// knots there. These are what `cagd_curvelist_to_bspline_unclamped` needs to rebuild the
/// spline's knot vector from its pieces.
///
/// Parameters:
/// - `spline` (in): the spline.
/// - `side` (in): `CAGD_SIDE_LEFT` or `CAGD_SIDE_RIGHT`.
/// - `out` (out): `out_cap` doubles; may be NULL when `out_cap == 0` (size query).
/// - `out_needed` (out): the number of knots of that side (at least the degree), also
///   written on `CAGD_ERR_BUFFER_TOO_SMALL`.
///
/// Returns:
/// - `CAGD_OK`: the knots are in `out[0 .. *out_needed]`, non-decreasing.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < *out_needed`; `out` untouched.
/// - `CAGD_ERR_NULL_POINTER`: `spline` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `side` is neither constant; a misaligned pointer.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `spline` must be NULL or a live spline handle; `out` NULL or `out_cap` writable
/// doubles; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_outer_knots(
    spline: *const CagdBSpline,
    side: i32,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(spline, "spline") }?;
        // SAFETY: as above.
        let buf = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        buf.copy_from(outer_side(s.0.knots(), s.0.degree(), side)?)
    })
}

/// As `cagd_curvelist_to_bspline`, for the pieces of an unclamped spline: the merged
/// spline's knot vector is `left ++ [first break] ++ (interior knots found) ++ [last break]
/// ++ right`, so that the pieces of a spline, merged with its outer knots from
/// `cagd_bspline_outer_knots`, give back its knot vector and its curve (cagd-convert
/// `BezierPieces::with_outer_knots` then `pieces_to_nurbs`). The points beyond the domain
/// are blossoms of the end pieces.
///
/// Parameters:
/// - `list` (in): the pieces (consecutive intervals, one degree `p` and dimension).
/// - `tol` (in): the joint tolerance, as for `cagd_curvelist_to_bspline` (0: default).
/// - `left`, `n_left` (in): the knots before the last copy of the first break, `n_left >=
///   p`, non-decreasing, `<= ` the first break; those from index `p` on equal the first
///   break, which keeps multiplicity `<= p + 1`. Borrowed.
/// - `right`, `n_right` (in): the knots after the first copy of the last break, mirrored
///   rules. Borrowed.
/// - `spline_out` (out): on `CAGD_OK`, the spline (release with `cagd_bspline_free`).
///
/// Returns:
/// - `CAGD_OK`.
/// - `CAGD_ERR_NULL_POINTER`: `list`, `left`, `right` or `spline_out` is NULL.
/// - `CAGD_ERR_BAD_KNOTS`: the outer knots break a rule above (the message names the side,
///   the knot and the rule).
/// - `CAGD_ERR_INVALID_ARGUMENT`, `CAGD_ERR_DIMENSION_MISMATCH`, `CAGD_ERR_NON_FINITE`,
///   `CAGD_ERR_NON_POSITIVE_WEIGHT`: as for `cagd_curvelist_to_bspline`.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; `left` NULL or `n_left` readable doubles,
/// `right` NULL or `n_right`; `spline_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_curvelist_to_bspline_unclamped(
    list: *const CagdCurveList,
    tol: f64,
    left: *const f64,
    n_left: usize,
    right: *const f64,
    n_right: usize,
    spline_out: *mut *mut CagdBSpline,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let lk = unsafe { slice_in(left, n_left, "left") }?;
        // SAFETY: as above.
        let rk = unsafe { slice_in(right, n_right, "right") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(spline_out, "spline_out") }?;
        let tol = joint_tolerance(tol)?;
        let pieces = list_pieces(l)?
            .with_outer_knots(lk.to_vec(), rk.to_vec())
            .map_err(bad_knots)?;
        let r = pieces_to_nurbs(&pieces, tol)?;
        *out = crate::boundary::into_handle(CagdBSpline(r.curve));
        Ok(())
    })
}

/// An outer-knot rule broken: `CAGD_ERR_BAD_KNOTS` with the library's message.
fn bad_knots(e: cagd_core::Error) -> Failure {
    Failure::new(CagdStatus::ERR_BAD_KNOTS, e.to_string())
}
