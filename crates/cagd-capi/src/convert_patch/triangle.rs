//! Triangular patch → rectangular patches (SPEC-convert §15.4, §15.5) through the C ABI:
//! a `CagdTriPatch` (plus optional weights) in, a `CagdPatchPieceList` out.

use cagd_convert::{PatchPiece, PatchSurface, TensorSurface, TriSplitPoints, TriSurface};

use super::list::{CAGD_DOMAIN_DEGENERATE_RECT, CPiece, CagdPatchPieceList};
use crate::boundary::{CResult, boundary, handle_ref, into_handle, out_ref, slice_in};
use crate::status::CagdStatus;
use crate::tensorpatch::CagdTensorPatch;
use crate::tripatch::CagdTriPatch;

/// Copies optional weights (`NULL` = polynomial).
///
/// # Safety
/// `weights` NULL or `n` readable doubles.
pub(crate) unsafe fn weights_opt(weights: *const f64, n: usize) -> CResult<Option<Vec<f64>>> {
    if weights.is_null() {
        return Ok(None);
    }
    // SAFETY: forwarded contract.
    Ok(Some(unsafe { slice_in(weights, n, "weights") }?.to_vec()))
}

/// The triangle of a handle plus optional weights.
///
/// # Safety
/// `tri` NULL or a live handle; `weights` NULL or `tri_count(n)` readable doubles.
unsafe fn tri_in(tri: *const CagdTriPatch, weights: *const f64) -> CResult<TriSurface> {
    // SAFETY: forwarded contract.
    let t = unsafe { handle_ref(tri, "patch") }?.as_patch();
    // SAFETY: forwarded contract.
    let w = unsafe { weights_opt(weights, cagd_core::tri_count(t.degree())) }?;
    Ok(TriSurface::new(
        t.points().to_vec(),
        t.degree(),
        t.dim(),
        w,
    )?)
}

/// The tensor patch of a handle plus optional weights.
///
/// # Safety
/// `rect` NULL or a live handle; `weights` NULL or `(m + 1)(n + 1)` readable doubles.
pub(crate) unsafe fn rect_in(
    rect: *const CagdTensorPatch,
    weights: *const f64,
) -> CResult<TensorSurface> {
    // SAFETY: forwarded contract.
    let p = &unsafe { handle_ref(rect, "patch") }?.0;
    let (m, n) = p.degrees();
    // SAFETY: forwarded contract.
    let w = unsafe { weights_opt(weights, (m + 1) * (n + 1)) }?;
    Ok(TensorSurface::new(p.points().to_vec(), m, n, p.dim(), w)?)
}

/// Writes a list of library pieces to `list_out`.
pub(crate) fn put(list_out: &mut *mut CagdPatchPieceList, pieces: Vec<PatchPiece>) {
    *list_out = into_handle(CagdPatchPieceList(
        pieces.into_iter().map(CPiece::from_piece).collect(),
    ));
}

/// The triangle as one degenerate `m x n` rectangle, `m >= n` (SPEC-convert §15.4, eq.
/// 15.4.2; `m = n` for the square one): `P(s, t) = T(s, (1 - s) t)`.
///
/// Parameters:
/// - `patch` (in): the triangle of degree `n`.
/// - `weights` (in): NULL (polynomial) or `(n + 1)(n + 2) / 2` weights `> 0` in the order of
///   the points (a rational patch; the result is rational).
/// - `m` (in): the rectangle's `s`-degree, `n <= m <= 64`.
/// - `list_out` (out): on `CAGD_OK`, one tensor piece with the bilinear domain
///   `[(0,0), (1,0), (0,1), (1,0)]`, owned by the caller (`cagd_patchpiecelist_free`).
///
/// Returns:
/// - `CAGD_OK`: `*list_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `patch` or `list_out` is NULL.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a weight is `<= 0` or not finite.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `m < n`.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `m > 64`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_NON_FINITE`: a control point of a piece overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` NULL or a live handle; `weights` NULL or the documented number of doubles;
/// `list_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatch_to_rect(
    patch: *const CagdTriPatch,
    weights: *const f64,
    m: usize,
    list_out: *mut *mut CagdPatchPieceList,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(list_out, "list_out") }?;
        // SAFETY: as above.
        let t = unsafe { tri_in(patch, weights) }?;
        put(out, vec![cagd_convert::triangle_to_degenerate_rect(&t, m)?]);
        Ok(())
    })
}

/// The triangle over the quadrilateral `X00, X10, X01, X11` of its domain as one
/// non-degenerate `n x n` rectangle, `P(s, t) = T(X(s, t))` with the bilinear `X`
/// (SPEC-convert §15.5, general form; region D1 of eq. 15.5.3 is `[(0,0), (b,0), (0,d),
/// (a,c)]`).
///
/// Parameters:
/// - `patch`, `weights` (in): as `cagd_tripatch_to_rect`.
/// - `corners` (in): 8 doubles `X00.u, X00.v, X10.u, X10.v, X01.u, X01.v, X11.u, X11.v`,
///   each in the closed unit triangle.
/// - `list_out` (out): on `CAGD_OK`, one tensor piece with that bilinear domain.
///
/// Returns:
/// - `CAGD_OK`: `*list_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `patch`, `corners` or `list_out` is NULL.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a weight is `<= 0` or not finite.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a corner is not finite or outside the triangle, or a
///   pointer is misaligned.
/// - `CAGD_ERR_DEGENERATE_SPLIT`: the map folds (Jacobian `<= 0` at a corner).
/// - `CAGD_ERR_NON_FINITE`: a control point of a piece overflows f64 (coordinates near
///   the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// As `cagd_tripatch_to_rect`; `corners` NULL or 8 readable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatch_to_quad(
    patch: *const CagdTriPatch,
    weights: *const f64,
    corners: *const f64,
    list_out: *mut *mut CagdPatchPieceList,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(list_out, "list_out") }?;
        // SAFETY: as above.
        let c = unsafe { slice_in(corners, 8, "corners") }?;
        // SAFETY: as above.
        let t = unsafe { tri_in(patch, weights) }?;
        let x = [[c[0], c[1]], [c[2], c[3]], [c[4], c[5]], [c[6], c[7]]];
        put(out, vec![cagd_convert::triangle_to_quad(&t, x)?]);
        Ok(())
    })
}

/// The triangle as three non-degenerate `n x n` rectangles through the inner point
/// `(inner_u, inner_v)` and the edge points `G = (g, 0)`, `K = (k, 1 - k)`, `H = (0, h)`
/// (SPEC-convert §15.5; the centroid and `g = k = h = 0.5` are the usual choice). Pieces in
/// the order `D1 = (O, G, H, P)`, `D2 = (U, K, G, P)`, `D3 = (V, H, K, P)`, each with its
/// bilinear domain; neighbours share their boundary nets.
///
/// Parameters:
/// - `patch`, `weights` (in): as `cagd_tripatch_to_rect`.
/// - `inner_u`, `inner_v` (in): the inner point, `> 0` with sum `< 1`.
/// - `g`, `k`, `h` (in): the edge points' parameters, each in `(0, 1)`.
/// - `list_out` (out): on `CAGD_OK`, the three pieces.
///
/// Returns:
/// - `CAGD_OK`: `*list_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `patch` or `list_out` is NULL.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a weight is `<= 0` or not finite.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a point outside its range, or a pointer misaligned.
/// - `CAGD_ERR_DEGENERATE_SPLIT`: one of the three quadrilaterals folds.
/// - `CAGD_ERR_NON_FINITE`: a control point of a piece overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// As `cagd_tripatch_to_rect`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatch_to_three_rects(
    patch: *const CagdTriPatch,
    weights: *const f64,
    inner_u: f64,
    inner_v: f64,
    g: f64,
    k: f64,
    h: f64,
    list_out: *mut *mut CagdPatchPieceList,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(list_out, "list_out") }?;
        // SAFETY: as above.
        let t = unsafe { tri_in(patch, weights) }?;
        let split = TriSplitPoints {
            p: [inner_u, inner_v],
            g,
            k,
            h,
        };
        put(
            out,
            cagd_convert::triangle_to_three_rects(&t, split)?.to_vec(),
        );
        Ok(())
    })
}

/// An `n x n` rectangle that is a degenerate triangle (Theorem 15.4.2) back to its triangle
/// of degree `n` (SPEC-convert §15.4, eq. 15.4.4 inverted: row `i` reduced exactly from
/// degree `n` to `n - i`). `T(u, v) = P(u, v / (1 - u))`.
///
/// Parameters:
/// - `patch` (in): the `n x n` tensor patch; `weights` (in): NULL or `(n + 1)^2` weights.
/// - `tol` (in): the largest relative residual accepted (e.g. `1e-12`), finite `> 0`.
/// - `list_out` (out): on `CAGD_OK`, one triangle piece of domain kind
///   `CAGD_DOMAIN_DEGENERATE_RECT`.
///
/// Returns:
/// - `CAGD_OK`: `*list_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `patch` or `list_out` is NULL.
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a weight (given or reduced) is `<= 0`.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: the patch is not square.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `tol` not finite `> 0`, or a pointer misaligned.
/// - `CAGD_ERR_NOT_DEGENERATE`: the relative residual is above `tol` (the message gives it).
/// - `CAGD_ERR_NON_FINITE`: a point of the triangle overflows f64 (a rational patch: its
///   homogeneous point divided by a reduced weight near zero; coordinates near the limits
///   of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` NULL or a live handle; `weights` NULL or `(n + 1)^2` readable doubles;
/// `list_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatch_to_triangle(
    patch: *const CagdTensorPatch,
    weights: *const f64,
    tol: f64,
    list_out: *mut *mut CagdPatchPieceList,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(list_out, "list_out") }?;
        // SAFETY: as above.
        let p = unsafe { rect_in(patch, weights) }?;
        let t = cagd_convert::degenerate_rect_to_triangle(&p, tol)?;
        let piece = CPiece {
            surface: PatchSurface::Tri(t),
            domain_kind: CAGD_DOMAIN_DEGENERATE_RECT,
            domain: Vec::new(),
        };
        *out = into_handle(CagdPatchPieceList(vec![piece]));
        Ok(())
    })
}
