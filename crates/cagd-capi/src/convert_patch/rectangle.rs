//! Rectangular patch → triangles, and exact subdivision along a line, a polynomial curve or
//! a trimming chain (SPEC-convert §15.6, §15.7) through the C ABI: a `CagdTensorPatch`
//! (plus optional weights) in, a `CagdPatchPieceList` out.

use cagd_convert::{TrimChain, TrimDirection, TrimKeep, TrimSegment};

use super::list::CagdPatchPieceList;
use super::triangle::{put, rect_in};
use crate::boundary::{Failure, boundary, nonnull, out_ref, slice_in};
use crate::status::CagdStatus;
use crate::tensorpatch::CagdTensorPatch;

/// Trimming curves `u = f(v)` (intervals in `v`).
pub const CAGD_TRIM_U_OF_V: i32 = 0;
/// Trimming curves `v = g(u)` (intervals in `u`).
pub const CAGD_TRIM_V_OF_U: i32 = 1;
/// Keep `u <= f(v)` (resp. `v <= g(u)`).
pub const CAGD_TRIM_KEEP_BELOW: i32 = 0;
/// Keep `u >= f(v)` (resp. `v >= g(u)`).
pub const CAGD_TRIM_KEEP_ABOVE: i32 = 1;

/// An `m x n` rectangle as two triangles of degree `m + n` (SPEC-convert §15.6.3): piece 0
/// `T(u, v) = P(u, v)` on `u + v <= 1` (triangle domain `[(1,0), (0,1), (0,0)]`), piece 1
/// `T'(u', v') = P(1 - u', 1 - v')` (domain `[(0,1), (1,0), (1,1)]`).
///
/// Parameters:
/// - `patch` (in): the tensor patch of degree `(m, n)`, `m + n <= 64`.
/// - `weights` (in): NULL (polynomial) or `(m + 1)(n + 1)` weights `> 0` in the order of the
///   points (the result is rational).
/// - `list_out` (out): on `CAGD_OK`, the two pieces, owned by the caller
///   (`cagd_patchpiecelist_free`).
///
/// Returns:
/// - `CAGD_OK`: `*list_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `patch` or `list_out` is NULL.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a weight is `<= 0` or not finite.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `m + n > 64`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_NON_FINITE`: a control point of a piece overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` NULL or a live handle; `weights` NULL or the documented number of doubles;
/// `list_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_to_triangles(
    patch: *const CagdTensorPatch,
    weights: *const f64,
    list_out: *mut *mut CagdPatchPieceList,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(list_out, "list_out") }?;
        // SAFETY: as above.
        let p = unsafe { rect_in(patch, weights) }?;
        put(out, cagd_convert::rect_to_two_triangle_pieces(&p)?);
        Ok(())
    })
}

/// Splits an `m x n` patch along the line `u = f1 v + f0` into exact pieces that tile the
/// unit square (SPEC-convert §15.6): two trapezoids `m x (m + n)` when the line meets
/// `v = 0` and `v = 1` inside `[0, 1]` (left first); a corner triangle and the pentagon as
/// the spec decomposes it (a trapezoid and, unless the cut reaches the opposite corner, a
/// strip) when it cuts a corner off; two trapezoids of the transposed patch when it meets
/// `u = 0` and `u = 1`. Every piece has a bilinear domain.
///
/// Parameters:
/// - `patch`, `weights` (in): as `cagd_tensorpatch_to_triangles`.
/// - `f1`, `f0` (in): the line.
/// - `list_out` (out): on `CAGD_OK`, the pieces (2 or 3).
///
/// Returns:
/// - `CAGD_OK`: `*list_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `patch` or `list_out` is NULL.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a weight is `<= 0` or not finite.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `f1` or `f0` not finite, the line does not cut the open
///   square in two, or a pointer is misaligned.
/// - `CAGD_ERR_NON_FINITE`: a control point of a piece overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// As `cagd_tensorpatch_to_triangles`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_split_line(
    patch: *const CagdTensorPatch,
    weights: *const f64,
    f1: f64,
    f0: f64,
    list_out: *mut *mut CagdPatchPieceList,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(list_out, "list_out") }?;
        // SAFETY: as above.
        let p = unsafe { rect_in(patch, weights) }?;
        put(out, cagd_convert::split_along_line(&p, f1, f0)?);
        Ok(())
    })
}

/// Splits an `m x n` patch along the curve `u = f(v) = sum_l B^k_l(v) a_l` (SPEC-convert
/// §15.7, corner cutting): piece 0 is `{u <= f(v)}` (D5, `u = s f(t)`, `v = t`), piece 1
/// `{u >= f(v)}` (`u = f(t) + s (1 - f(t))`), each `m x (k m + n)` with a ruled domain.
///
/// Parameters:
/// - `patch`, `weights` (in): as `cagd_tensorpatch_to_triangles`.
/// - `coeffs` (in): the `k + 1` Bernstein coefficients `a_0 .. a_k` of `f`; `f` must stay
///   in `[0, 1]`.
/// - `n_coeffs` (in): `k + 1 >= 1`.
/// - `list_out` (out): on `CAGD_OK`, the two pieces.
///
/// Returns:
/// - `CAGD_OK`: `*list_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `patch`, `coeffs` or `list_out` is NULL.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a weight is `<= 0` or not finite.
/// - `CAGD_ERR_NOT_ENOUGH_POINTS`: `n_coeffs == 0`.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `k > 64`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `f` leaves `[0, 1]` or a coefficient is not finite, or a
///   pointer is misaligned.
/// - `CAGD_ERR_NON_FINITE`: a control point of a piece overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// As `cagd_tensorpatch_to_triangles`; `coeffs` NULL or `n_coeffs` readable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_split_curve(
    patch: *const CagdTensorPatch,
    weights: *const f64,
    coeffs: *const f64,
    n_coeffs: usize,
    list_out: *mut *mut CagdPatchPieceList,
) -> CagdStatus {
    boundary(|| {
        nonnull(coeffs, "coeffs")?;
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(list_out, "list_out") }?;
        // SAFETY: as above.
        let p = unsafe { rect_in(patch, weights) }?;
        if n_coeffs == 0 {
            return Err(cagd_core::Error::NotEnoughPoints { got: 0, need: 1 }.into());
        }
        // SAFETY: as above.
        let a = unsafe { slice_in(coeffs, n_coeffs, "coeffs") }?;
        put(out, cagd_convert::split_along_curve(&p, a)?);
        Ok(())
    })
}

/// The untrimmed patches covering exactly the kept region of a patch trimmed by one chain
/// of polynomial curves (SPEC-convert §15.7.3; supported layout: the chain is the graph of
/// a piecewise polynomial over one parameter, segments of degree `<= 3` on consecutive
/// intervals, continuous, running from edge to edge of the square — across `[0, 1]` or
/// starting / ending where the curve meets a side edge). Ruled pieces along the curves,
/// bilinear strips beyond the chain's ends.
///
/// Parameters:
/// - `patch`, `weights` (in): as `cagd_tensorpatch_to_triangles`.
/// - `direction` (in): `CAGD_TRIM_U_OF_V` or `CAGD_TRIM_V_OF_U`.
/// - `keep` (in): `CAGD_TRIM_KEEP_BELOW` or `CAGD_TRIM_KEEP_ABOVE`.
/// - `intervals` (in): `2 * n_segments` doubles, `start, end` of each segment's interval.
/// - `n_coeffs` (in): `n_segments` counts, segment `s` has `n_coeffs[s]` (1..=4) Bernstein
///   coefficients over its local `t in [0, 1]`.
/// - `coeffs` (in): the coefficients of all segments, one after the other
///   (`sum n_coeffs` doubles).
/// - `n_segments` (in): `>= 1`.
/// - `list_out` (out): on `CAGD_OK`, the pieces.
///
/// Returns:
/// - `CAGD_OK`: `*list_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: a pointer argument is NULL.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a weight is `<= 0` or not finite.
/// - `CAGD_ERR_INVALID_ARGUMENT`: unknown `direction` / `keep`, a curve leaving `[0, 1]`, an
///   interval outside `[0, 1]`, a sum of counts that overflows, or a misaligned pointer.
/// - `CAGD_ERR_UNSUPPORTED_TRIM`: a layout outside the supported one (gap, jump, end inside
///   the square, degree > 3, no segment).
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: a piece's degree would exceed 64 (the patch's
///   degree composed with a trimming curve's).
/// - `CAGD_ERR_NON_FINITE`: a point of a trimmed piece overflows (coordinates near the
///   double range).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// As `cagd_tensorpatch_to_triangles`; `intervals` NULL or `2 * n_segments` readable
/// doubles; `n_coeffs` NULL or `n_segments` readable `size_t`; `coeffs` NULL or
/// `sum n_coeffs` readable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_trim(
    patch: *const CagdTensorPatch,
    weights: *const f64,
    direction: i32,
    keep: i32,
    intervals: *const f64,
    n_coeffs: *const usize,
    coeffs: *const f64,
    n_segments: usize,
    list_out: *mut *mut CagdPatchPieceList,
) -> CagdStatus {
    boundary(|| {
        nonnull(intervals, "intervals")?;
        nonnull(n_coeffs, "n_coeffs")?;
        nonnull(coeffs, "coeffs")?;
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(list_out, "list_out") }?;
        // SAFETY: as above.
        let p = unsafe { rect_in(patch, weights) }?;
        let direction = match direction {
            CAGD_TRIM_U_OF_V => TrimDirection::UOfV,
            CAGD_TRIM_V_OF_U => TrimDirection::VOfU,
            d => {
                return Err(Failure::invalid(format!(
                    "direction = {d}: expected CAGD_TRIM_U_OF_V or CAGD_TRIM_V_OF_U"
                )));
            }
        };
        let keep = match keep {
            CAGD_TRIM_KEEP_BELOW => TrimKeep::Below,
            CAGD_TRIM_KEEP_ABOVE => TrimKeep::Above,
            k => {
                return Err(Failure::invalid(format!(
                    "keep = {k}: expected CAGD_TRIM_KEEP_BELOW or CAGD_TRIM_KEEP_ABOVE"
                )));
            }
        };
        let two_n = crate::boundary::checked_len(n_segments, 2, "2 * n_segments")?;
        // SAFETY: as above (n_segments == 0 gives an empty chain, refused below).
        let iv = if n_segments == 0 {
            &[][..]
        } else {
            unsafe { slice_in(intervals, two_n, "intervals") }?
        };
        if !n_coeffs.is_aligned() {
            return Err(Failure::invalid(
                "argument `n_coeffs` is not aligned for size_t",
            ));
        }
        crate::boundary::checked_len(n_segments, 1, "n_segments")?;
        // SAFETY: non-NULL and aligned checked; n_segments readable size_t by the contract.
        let counts = if n_segments == 0 {
            &[][..]
        } else {
            unsafe { std::slice::from_raw_parts(n_coeffs, n_segments) }
        };
        let total = counts
            .iter()
            .try_fold(0usize, |a, &c| a.checked_add(c))
            .ok_or_else(|| Failure::invalid("the sum of n_coeffs overflows"))?;
        // SAFETY: as above.
        let all = if total == 0 {
            &[][..]
        } else {
            unsafe { slice_in(coeffs, total, "coeffs") }?
        };
        let mut segments = Vec::with_capacity(n_segments);
        let mut at = 0;
        for (s, &c) in counts.iter().enumerate() {
            segments.push(TrimSegment {
                start: iv[2 * s],
                end: iv[2 * s + 1],
                bezier: all[at..at + c].to_vec(),
            });
            at += c;
        }
        let chain = TrimChain {
            direction,
            keep,
            segments,
        };
        put(out, cagd_convert::trim_to_patches(&p, &chain)?);
        Ok(())
    })
}
