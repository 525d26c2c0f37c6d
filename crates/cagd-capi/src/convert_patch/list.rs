//! `CagdPatchPieceList`: the exact pieces of a patch conversion (SPEC-convert §15.4–15.7),
//! each a tensor or triangular patch, polynomial or rational, with the part of the input's
//! `(u, v)` domain it covers.

use cagd_convert::{PatchPiece, PatchSurface, PieceDomain};

use crate::boundary::{
    CResult, Failure, OUT, boundary, boundary_void, free_handle, handle_ref, out_ref, slice_out,
};
use crate::status::CagdStatus;

/// Piece kind: a tensor-product patch of degree `(deg_u, deg_v)`.
pub const CAGD_PIECE_TENSOR: i32 = 1;
/// Piece kind: a triangular patch of degree `deg_u` (`deg_v` is the same number).
pub const CAGD_PIECE_TRIANGLE: i32 = 2;
/// Domain kind: bilinear quadrilateral, 8 doubles `X00, X10, X01, X11` (each `u, v`): the
/// piece's `(s, t)` maps to `(1-s)(1-t) X00 + s(1-t) X10 + (1-s) t X01 + s t X11`.
pub const CAGD_DOMAIN_BILINEAR: i32 = 1;
/// Domain kind: triangle, 6 doubles `A, B, C`: the piece's `(u', v')` maps to
/// `C + u'(A - C) + v'(B - C)`.
pub const CAGD_DOMAIN_TRIANGLE: i32 = 2;
/// Domain kind: ruled region of a curved split, `4 (k + 1)` doubles: the `k + 1` control
/// points `(u, v)` of the side `s = 0`, then those of the side `s = 1`; the piece's
/// `(s, t)` maps to `(1 - s) L(t) + s R(t)` (`L`, `R` Bézier curves of degree `k`).
pub const CAGD_DOMAIN_RULED: i32 = 3;
/// Domain kind: the triangle of a degenerate rectangle (`cagd_tensorpatch_to_triangle`),
/// 0 doubles: the triangle's `(u, v)` is the rectangle's `(s, t) = (u, v / (1 - u))`.
pub const CAGD_DOMAIN_DEGENERATE_RECT: i32 = 4;

/// One piece as the list stores it: the patch, the domain kind and its doubles.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct CPiece {
    pub(crate) surface: PatchSurface,
    pub(crate) domain_kind: i32,
    pub(crate) domain: Vec<f64>,
}

impl CPiece {
    /// A library piece.
    pub(crate) fn from_piece(p: PatchPiece) -> Self {
        let (domain_kind, domain) = match &p.domain {
            PieceDomain::Bilinear(x) => {
                (CAGD_DOMAIN_BILINEAR, x.iter().flatten().copied().collect())
            }
            PieceDomain::Triangle(x) => {
                (CAGD_DOMAIN_TRIANGLE, x.iter().flatten().copied().collect())
            }
            PieceDomain::Ruled { s0, s1 } => (
                CAGD_DOMAIN_RULED,
                s0.iter().chain(s1).flatten().copied().collect(),
            ),
        };
        Self {
            surface: p.surface,
            domain_kind,
            domain,
        }
    }
}

/// Opaque handle to the pieces of a patch conversion, in the order the conversion defines
/// (see each `cagd_tripatch_to_*` / `cagd_tensorpatch_*` function). Immutable; release
/// with `cagd_patchpiecelist_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdPatchPieceList(pub(crate) Vec<CPiece>);

/// Element `i`, or `CAGD_ERR_INVALID_ARGUMENT`.
fn at(l: &CagdPatchPieceList, i: usize) -> CResult<&CPiece> {
    l.0.get(i).ok_or_else(|| {
        Failure::invalid(format!(
            "index {i} is out of range: the list has {} pieces",
            l.0.len()
        ))
    })
}

/// Releases a piece list. NULL is accepted and ignored; a non-NULL handle must be released
/// exactly once and not used afterwards.
///
/// Parameters:
/// - `list` (in, consumed): a `CagdPatchPieceList **` output of a cagd function, or NULL.
///
/// Does not change `cagd_last_error_message()`.
///
/// # Safety
/// `list` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_patchpiecelist_free(list: *mut CagdPatchPieceList) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(list) });
}

/// Reads the number of pieces.
///
/// Parameters:
/// - `list` (in): the list.
/// - `count_out` (out): on `CAGD_OK`, the number of pieces.
///
/// Returns:
/// - `CAGD_OK`: `*count_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: `list` or `count_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; `count_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_patchpiecelist_count(
    list: *const CagdPatchPieceList,
    count_out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        *unsafe { out_ref(count_out, "count_out") }? = l.0.len();
        Ok(())
    })
}

/// Describes piece `i`: its kind, degrees, dimension, whether it has weights, and the kind
/// of its domain.
///
/// Parameters:
/// - `list` (in): the list; `i` (in): the piece index, `0 <= i < count`.
/// - `kind_out` (out): `CAGD_PIECE_TENSOR` or `CAGD_PIECE_TRIANGLE`.
/// - `deg_u_out`, `deg_v_out` (out): the degrees `(m, n)` of a tensor piece; a triangle's
///   degree `n` in both.
/// - `dim_out` (out): coordinates per point.
/// - `rational_out` (out): 1 when the piece has weights, else 0.
/// - `domain_kind_out` (out): `CAGD_DOMAIN_BILINEAR`, `CAGD_DOMAIN_TRIANGLE`,
///   `CAGD_DOMAIN_RULED` or `CAGD_DOMAIN_DEGENERATE_RECT`.
///
/// The piece has `(deg_u + 1)(deg_v + 1)` (tensor, i-major) or `(n + 1)(n + 2) / 2`
/// (triangle, i-major) points. All outputs are written only on `CAGD_OK`.
///
/// Returns:
/// - `CAGD_OK`: every output is written.
/// - `CAGD_ERR_NULL_POINTER`: any pointer argument is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `i >= count`, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; each output NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_patchpiecelist_info(
    list: *const CagdPatchPieceList,
    i: usize,
    kind_out: *mut i32,
    deg_u_out: *mut usize,
    deg_v_out: *mut usize,
    dim_out: *mut usize,
    rational_out: *mut i32,
    domain_kind_out: *mut i32,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let (k, du, dv, d, r, dk) = unsafe {
            (
                out_ref(kind_out, "kind_out")?,
                out_ref(deg_u_out, "deg_u_out")?,
                out_ref(deg_v_out, "deg_v_out")?,
                out_ref(dim_out, "dim_out")?,
                out_ref(rational_out, "rational_out")?,
                out_ref(domain_kind_out, "domain_kind_out")?,
            )
        };
        let p = at(l, i)?;
        let (kind, m, n) = match &p.surface {
            PatchSurface::Tensor(t) => (CAGD_PIECE_TENSOR, t.degrees().0, t.degrees().1),
            PatchSurface::Tri(t) => (CAGD_PIECE_TRIANGLE, t.degree(), t.degree()),
        };
        (*k, *du, *dv, *d) = (kind, m, n, p.surface.dim());
        *r = i32::from(p.surface.is_rational());
        *dk = p.domain_kind;
        Ok(())
    })
}

/// Which array of a piece to copy.
#[derive(Clone, Copy)]
enum Array {
    Points,
    Weights,
    Domain,
}

/// Copies one array of piece `i` into a caller buffer.
///
/// # Safety
/// As the public functions below.
unsafe fn copy_array(
    list: *const CagdPatchPieceList,
    i: usize,
    which: Array,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract.
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let buf = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let p = at(l, i)?;
        let data: &[f64] = match (which, &p.surface) {
            (Array::Points, PatchSurface::Tensor(t)) => t.net().points(),
            (Array::Points, PatchSurface::Tri(t)) => t.net().points(),
            (Array::Weights, PatchSurface::Tensor(t)) => t.weights().unwrap_or_default(),
            (Array::Weights, PatchSurface::Tri(t)) => t.weights().unwrap_or_default(),
            (Array::Domain, _) => &p.domain,
        };
        if matches!(which, Array::Weights) && !p.surface.is_rational() {
            return Err(Failure::new(
                CagdStatus::ERR_NOT_AVAILABLE,
                format!("piece {i} is polynomial: it has no weights"),
            ));
        }
        buf.copy_from(data)
    })
}

/// Copies the control points of piece `i` (Euclidean, i-major, `n_points * dim` doubles).
///
/// Parameters:
/// - `list` (in): the list; `i` (in): the piece index.
/// - `out` (out): `out_cap` doubles; may be NULL when `out_cap == 0` (size query).
/// - `out_needed` (out): the number of doubles needed, also written on
///   `CAGD_ERR_BUFFER_TOO_SMALL`.
///
/// Returns:
/// - `CAGD_OK`: the points are in `out[0 .. *out_needed]`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < *out_needed`; `out` untouched.
/// - `CAGD_ERR_NULL_POINTER`: `list` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `i >= count`, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` NULL or a live list; `out` NULL or `out_cap` writable doubles; `out_needed` NULL
/// or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_patchpiecelist_points(
    list: *const CagdPatchPieceList,
    i: usize,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    // SAFETY: forwarded contract.
    unsafe { copy_array(list, i, Array::Points, out, out_cap, out_needed) }
}

/// Copies the weights of a rational piece `i` (`n_points` doubles, in the order of the
/// points).
///
/// Parameters:
/// - `list` (in): the list; `i` (in): the piece index.
/// - `out` (out): `out_cap` doubles; may be NULL when `out_cap == 0` (size query).
/// - `out_needed` (out): the number of doubles needed, also written on
///   `CAGD_ERR_BUFFER_TOO_SMALL`.
///
/// Returns:
/// - `CAGD_OK`: the weights are in `out[0 .. *out_needed]`.
/// - `CAGD_ERR_NOT_AVAILABLE`: the piece is polynomial (nothing written, not even
///   `*out_needed`).
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < *out_needed`; `out` untouched.
/// - `CAGD_ERR_NULL_POINTER`: `list` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `i >= count`, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// As `cagd_patchpiecelist_points`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_patchpiecelist_weights(
    list: *const CagdPatchPieceList,
    i: usize,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    // SAFETY: forwarded contract.
    unsafe { copy_array(list, i, Array::Weights, out, out_cap, out_needed) }
}

/// Copies the domain of piece `i`: the part of the input's `(u, v)` domain it covers, laid
/// out as its domain kind says (`CAGD_DOMAIN_BILINEAR`: 8 doubles; `CAGD_DOMAIN_TRIANGLE`:
/// 6; `CAGD_DOMAIN_RULED`: `4 (k + 1)`; `CAGD_DOMAIN_DEGENERATE_RECT`: 0).
///
/// Parameters:
/// - `list` (in): the list; `i` (in): the piece index.
/// - `out` (out): `out_cap` doubles; may be NULL when `out_cap == 0` (size query).
/// - `out_needed` (out): the number of doubles needed, also written on
///   `CAGD_ERR_BUFFER_TOO_SMALL`.
///
/// Returns:
/// - `CAGD_OK`: the domain is in `out[0 .. *out_needed]`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < *out_needed`; `out` untouched.
/// - `CAGD_ERR_NULL_POINTER`: `list` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `i >= count`, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// As `cagd_patchpiecelist_points`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_patchpiecelist_domain(
    list: *const CagdPatchPieceList,
    i: usize,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    // SAFETY: forwarded contract.
    unsafe { copy_array(list, i, Array::Domain, out, out_cap, out_needed) }
}
