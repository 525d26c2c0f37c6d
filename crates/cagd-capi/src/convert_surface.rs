//! Tensor B-spline / NURBS surface ↔ rational Bézier patches through the C ABI (the
//! general route of cagd-convert, SPEC-convert §15.2 generalised to any degrees): a surface
//! handle in, a `CagdPatchPieceList` of tensor pieces with rectangular (bilinear) domains
//! out, and back.

use cagd_convert::{PatchSurface, TensorSurface, patches_to_nurbs, surface_to_bezier_patches};
use cagd_core::SurfacePatchPiece;

use crate::boundary::{CResult, Failure, boundary, handle_ref, into_handle, out_ref};
use crate::bspline::CagdBSplineSurface;
use crate::convert_nurbs::joint_tolerance;
use crate::convert_patch::{CAGD_DOMAIN_BILINEAR, CPiece, CagdPatchPieceList};
use crate::status::CagdStatus;

/// Every non-empty span rectangle of a B-spline / NURBS surface as a (rational) tensor
/// Bézier patch of the surface's degrees (Böhm knot insertion in homogeneous space, in `u`
/// on whole rows, then in `v`; clamped or unclamped knots).
///
/// The list holds `n_u * n_v` pieces, `u` spans outer and `v` spans inner (piece
/// `iu * n_v + jv` covers `[u_iu, u_iu+1] x [v_jv, v_jv+1]` of the distinct knot values),
/// each of kind `CAGD_PIECE_TENSOR`, rational iff the surface is, with domain kind
/// `CAGD_DOMAIN_BILINEAR` whose 8 doubles are the rectangle's corners `(u0, v0), (u1, v0),
/// (u0, v1), (u1, v1)`: the piece's `(s, t)` is the surface's
/// `(u0 + s (u1 - u0), v0 + t (v1 - v0))`. Read them with `cagd_patchpiecelist_*`.
///
/// Parameters:
/// - `surface` (in): the surface.
/// - `list_out` (out): on `CAGD_OK`, the pieces (release with `cagd_patchpiecelist_free`).
///   Not written on failure.
///
/// Returns:
/// - `CAGD_OK`.
/// - `CAGD_ERR_NULL_POINTER`: `surface` or `list_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a misaligned pointer.
/// - `CAGD_ERR_NON_FINITE`, `CAGD_ERR_NON_POSITIVE_WEIGHT`: a piece overflows.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `surface` must be NULL or a live surface handle; `list_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bsplinesurface_to_bezier_patches(
    surface: *const CagdBSplineSurface,
    list_out: *mut *mut CagdPatchPieceList,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let s = unsafe { handle_ref(surface, "surface") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(list_out, "list_out") }?;
        let (p, q) = s.0.degrees();
        let dim = s.0.dim();
        let mut list = Vec::new();
        for pc in surface_to_bezier_patches(&s.0)? {
            let (u, v) = (pc.u, pc.v);
            let t = TensorSurface::new(pc.patch.points().to_vec(), p, q, dim, pc.weights)?;
            list.push(CPiece {
                surface: PatchSurface::Tensor(t),
                domain_kind: CAGD_DOMAIN_BILINEAR,
                domain: vec![u.0, v.0, u.1, v.0, u.0, v.1, u.1, v.1],
            });
        }
        *out = into_handle(CagdPatchPieceList(list));
        Ok(())
    })
}

/// Merges tensor Bézier patches on a full rectangular grid into one B-spline / NURBS
/// surface with the highest continuity across each knot line that every row (column) of
/// patches has (cagd-convert `patches_to_nurbs`: the curve merge on bundles of rows, knot
/// copies removed while the certified residual stays within `tol`, control points by
/// blossoms). The reverse of `cagd_bsplinesurface_to_bezier_patches`: a clamped surface
/// comes back with its knot vectors and its net (unclamped knots come back clamped, the
/// same surface).
///
/// Parameters:
/// - `list` (in): tensor pieces of one degree `(p, q)` and dimension, polynomial or
///   rational (if any piece is rational the surface is; a polynomial piece counts with
///   weights 1), in the order and with the domains `cagd_bsplinesurface_to_bezier_patches`
///   gives: `u` outer, `v` inner, each domain `CAGD_DOMAIN_BILINEAR` with the corners of an
///   axis-parallel rectangle `(u0, v0), (u1, v0), (u0, v1), (u1, v1)`, the rectangles
///   tiling a grid.
/// - `tol` (in): the joint tolerance in working coordinates (homogeneous `(w x, w)` when
///   rational), finite and `> 0`, or exactly 0 for the default rounding level (`1e-12`
///   times the largest working coordinate).
/// - `surface_out` (out): on `CAGD_OK`, the surface (release with
///   `cagd_bsplinesurface_free`). Not written on failure.
/// - `bound_out` (out, may be NULL): on `CAGD_OK`, a certified bound of the distance
///   between the surface and the patches, working coordinates.
///
/// Returns:
/// - `CAGD_OK`.
/// - `CAGD_ERR_NULL_POINTER`: `list` or `surface_out` is NULL.
/// - `CAGD_ERR_NOT_ENOUGH_POINTS`: the list is empty.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `tol` negative, NaN or infinite; a triangular piece; a
///   domain that is not an axis-parallel rectangle; rectangles that do not tile a grid in
///   the order above, or non-increasing breaks; a misaligned pointer.
/// - `CAGD_ERR_DIMENSION_MISMATCH`: pieces of differing degrees or dimensions, or a count
///   that is not a full grid.
/// - `CAGD_ERR_NON_FINITE`, `CAGD_ERR_NON_POSITIVE_WEIGHT`: the result or its certified
///   bound overflows.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; `surface_out` NULL or writable; `bound_out`
/// NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_patchpiecelist_to_bsplinesurface(
    list: *const CagdPatchPieceList,
    tol: f64,
    surface_out: *mut *mut CagdBSplineSurface,
    bound_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(surface_out, "surface_out") }?;
        let bound = if bound_out.is_null() {
            None
        } else {
            // SAFETY: as above.
            Some(unsafe { out_ref(bound_out, "bound_out") }?)
        };
        let tol = joint_tolerance(tol)?;
        let pieces =
            l.0.iter()
                .enumerate()
                .map(|(k, pc)| grid_piece(k, pc))
                .collect::<CResult<Vec<_>>>()?;
        let r = patches_to_nurbs(&pieces, tol)?;
        if !r.bound.is_finite() {
            // Working coordinates near the double range: the certified distance overflows
            // (C ABI fuzz run, seed 103), refused rather than handed out with an infinite
            // bound.
            return Err(Failure::new(
                CagdStatus::ERR_NON_FINITE,
                format!("the merge's certified bound = {} is not finite", r.bound),
            ));
        }
        *out = into_handle(CagdBSplineSurface(r.surface));
        if let Some(b) = bound {
            *b = r.bound;
        }
        Ok(())
    })
}

/// Piece `k` of the list as a patch of a grid: a tensor piece on an axis-parallel
/// rectangle.
fn grid_piece(k: usize, pc: &CPiece) -> CResult<SurfacePatchPiece> {
    let PatchSurface::Tensor(t) = &pc.surface else {
        return Err(Failure::invalid(format!(
            "piece {k} is triangular: a surface is merged from tensor pieces only"
        )));
    };
    let d = &pc.domain;
    let rect = pc.domain_kind == CAGD_DOMAIN_BILINEAR
        && d.len() == 8
        && d[0] == d[4]
        && d[2] == d[6]
        && d[1] == d[3]
        && d[5] == d[7]
        && d[0] < d[2]
        && d[1] < d[5];
    if !rect {
        return Err(Failure::invalid(format!(
            "piece {k}: its domain is not an axis-parallel rectangle (CAGD_DOMAIN_BILINEAR \
             with corners (u0, v0), (u1, v0), (u0, v1), (u1, v1), u0 < u1, v0 < v1)"
        )));
    }
    Ok(SurfacePatchPiece {
        u: (d[0], d[2]),
        v: (d[1], d[5]),
        patch: t.net().clone(),
        weights: t.weights().map(<[f64]>::to_vec),
    })
}
