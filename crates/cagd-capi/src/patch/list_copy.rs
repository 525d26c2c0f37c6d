//! `cagd_tensorpatchlist_copy` and `cagd_tripatchlist_copy`: every piece of a patch
//! reduction to a tolerance (degrees, sub-domains, control points, bounds) copied into
//! caller buffers in one call, with capacity 0 asking the sizes — instead of one
//! `cagd_*patchlist_get` handle and its read-back per piece.

use crate::boundary::{CResult, boundary, handle_ref, out_ref};
use crate::copy_out::{OutArray, copy_all};
use crate::patch::{CagdTensorPatchList, CagdTriPatchList};
use crate::status::CagdStatus;

/// The sizes of the arrays of a `CagdTensorPatchList` or `CagdTriPatchList`, written by
/// `cagd_tensorpatchlist_copy` / `cagd_tripatchlist_copy` on `CAGD_OK` and on
/// `CAGD_ERR_BUFFER_TOO_SMALL`. Counts of `size_t` / doubles, never bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CagdPatchListSizes {
    /// Number of pieces.
    pub n_pieces: usize,
    /// Coordinates per point, the same for every piece.
    pub dim: usize,
    /// The length of `degrees_out`: `2 * n_pieces` (tensor: `deg_u, deg_v` per piece) or
    /// `n_pieces` (triangles).
    pub degrees_len: usize,
    /// The length of `domains_out`: `4 * n_pieces` (tensor: `u0, u1, v0, v1` per piece, as
    /// `cagd_tensorpatchlist_get`) or `6 * n_pieces` (triangles: `A.u, A.v, B.u, B.v, C.u,
    /// C.v`, as `cagd_tripatchlist_get`).
    pub domains_len: usize,
    /// The length of `points_out`: `sum_i (deg_u_i + 1) (deg_v_i + 1) dim` (tensor) or
    /// `sum_i (n_i + 1) (n_i + 2) / 2 * dim` (triangles).
    pub points_len: usize,
    /// `n_pieces`: the length of `bounds_out`.
    pub bounds_len: usize,
}

/// The gathered arrays of a patch list.
struct Arrays {
    dim: usize,
    degrees: Vec<usize>,
    domains: Vec<f64>,
    points: Vec<f64>,
    bounds: Vec<f64>,
}

impl Arrays {
    fn sizes(&self) -> CagdPatchListSizes {
        CagdPatchListSizes {
            n_pieces: self.bounds.len(),
            dim: self.dim,
            degrees_len: self.degrees.len(),
            domains_len: self.domains.len(),
            points_len: self.points.len(),
            bounds_len: self.bounds.len(),
        }
    }

    /// Copies the arrays into the caller's buffers.
    ///
    /// # Safety
    /// As the entry points.
    #[allow(
        clippy::too_many_arguments,
        reason = "one buffer and capacity per array"
    )]
    unsafe fn copy(
        &self,
        degrees_out: *mut usize,
        degrees_out_cap: usize,
        domains_out: *mut f64,
        domains_out_cap: usize,
        points_out: *mut f64,
        points_out_cap: usize,
        bounds_out: *mut f64,
        bounds_out_cap: usize,
        sizes: &mut CagdPatchListSizes,
    ) -> CResult<()> {
        let s = self.sizes();
        let d = OutArray::new(degrees_out, degrees_out_cap, &self.degrees, "degrees_out");
        let o = OutArray::new(domains_out, domains_out_cap, &self.domains, "domains_out");
        let p = OutArray::new(points_out, points_out_cap, &self.points, "points_out");
        let b = OutArray::new(bounds_out, bounds_out_cap, &self.bounds, "bounds_out");
        // SAFETY: forwarded contract.
        unsafe { copy_all(&[&d, &o, &p, &b], || *sizes = s) }
    }
}

/// Copies every piece of a tensor patch list into caller buffers in one call. Call it
/// once with every capacity 0 (and the buffers NULL) to learn the sizes, allocate, call
/// again. Piece `i` has degrees `degrees_out[2 i]`, `degrees_out[2 i + 1]` and
/// `(deg_u + 1) (deg_v + 1)` control points (i-major, as `cagd_tensorpatch_points`),
/// following those of the pieces before it in `points_out`.
///
/// Parameters:
/// - `list` (in): the list.
/// - `degrees_out` (out): `degrees_out_cap` `size_t`; on `CAGD_OK` `deg_u, deg_v` of each
///   piece.
/// - `domains_out` (out): `domains_out_cap` doubles; on `CAGD_OK` `u0, u1, v0, v1` of each
///   piece.
/// - `points_out` (out): `points_out_cap` doubles; on `CAGD_OK` the control points of every
///   piece.
/// - `bounds_out` (out): `bounds_out_cap` doubles; on `CAGD_OK` the certified bound of
///   each piece (Euclidean, model units).
/// - each `*_cap` (in): the capacity of its buffer in elements; a buffer may be NULL only
///   when its capacity is 0.
/// - `sizes_out` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, the sizes.
///
/// Returns:
/// - `CAGD_OK`: every array is copied.
/// - `CAGD_ERR_NULL_POINTER`: `list` or `sizes_out` is NULL, or a buffer is NULL with a
///   capacity above 0.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: a capacity is below its size (the message names every
///   short buffer); only `*sizes_out` is written.
/// - `CAGD_ERR_INVALID_ARGUMENT`: two buffers overlap, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; each buffer NULL or its capacity of writable
/// elements; `sizes_out` NULL or writable and not overlapping a buffer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tensorpatchlist_copy(
    list: *const CagdTensorPatchList,
    degrees_out: *mut usize,
    degrees_out_cap: usize,
    domains_out: *mut f64,
    domains_out_cap: usize,
    points_out: *mut f64,
    points_out_cap: usize,
    bounds_out: *mut f64,
    bounds_out_cap: usize,
    sizes_out: *mut CagdPatchListSizes,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let sizes = unsafe { out_ref(sizes_out, "sizes_out") }?;
        let mut a = Arrays {
            dim: l.0.first().map_or(0, |p| p.reduction.patch.dim()),
            degrees: Vec::new(),
            domains: Vec::new(),
            points: Vec::new(),
            bounds: Vec::new(),
        };
        for p in &l.0 {
            let (du, dv) = p.reduction.patch.degrees();
            a.degrees.extend([du, dv]);
            a.domains.extend([p.u.0, p.u.1, p.v.0, p.v.1]);
            a.points.extend_from_slice(p.reduction.patch.points());
            a.bounds.push(p.reduction.report.error_bound);
        }
        // SAFETY: as above.
        unsafe {
            a.copy(
                degrees_out,
                degrees_out_cap,
                domains_out,
                domains_out_cap,
                points_out,
                points_out_cap,
                bounds_out,
                bounds_out_cap,
                sizes,
            )
        }
    })
}

/// Copies every piece of a triangular patch list into caller buffers in one call. Call it
/// once with every capacity 0 (and the buffers NULL) to learn the sizes, allocate, call
/// again. Piece `i` has degree `degrees_out[i]` and `(n_i + 1) (n_i + 2) / 2` control
/// points (i-major, as `cagd_tripatch_points`), following those of the pieces before it
/// in `points_out`.
///
/// Parameters:
/// - `list` (in): the list.
/// - `degrees_out` (out): `degrees_out_cap` `size_t`; on `CAGD_OK` the degree of each
///   piece.
/// - `domains_out` (out): `domains_out_cap` doubles; on `CAGD_OK` the sub-triangle
///   `A.u, A.v, B.u, B.v, C.u, C.v` of each piece.
/// - `points_out` (out): `points_out_cap` doubles; on `CAGD_OK` the control points of every
///   piece.
/// - `bounds_out` (out): `bounds_out_cap` doubles; on `CAGD_OK` the certified bound of
///   each piece (Euclidean, model units).
/// - each `*_cap` (in): the capacity of its buffer in elements; a buffer may be NULL only
///   when its capacity is 0.
/// - `sizes_out` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, the sizes.
///
/// Returns:
/// - `CAGD_OK`: every array is copied.
/// - `CAGD_ERR_NULL_POINTER`: `list` or `sizes_out` is NULL, or a buffer is NULL with a
///   capacity above 0.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: a capacity is below its size (the message names every
///   short buffer); only `*sizes_out` is written.
/// - `CAGD_ERR_INVALID_ARGUMENT`: two buffers overlap, or a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `list` must be NULL or a live list handle; each buffer NULL or its capacity of writable
/// elements; `sizes_out` NULL or writable and not overlapping a buffer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_tripatchlist_copy(
    list: *const CagdTriPatchList,
    degrees_out: *mut usize,
    degrees_out_cap: usize,
    domains_out: *mut f64,
    domains_out_cap: usize,
    points_out: *mut f64,
    points_out_cap: usize,
    bounds_out: *mut f64,
    bounds_out_cap: usize,
    sizes_out: *mut CagdPatchListSizes,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let sizes = unsafe { out_ref(sizes_out, "sizes_out") }?;
        let mut a = Arrays {
            dim: l.0.first().map_or(0, |p| p.reduction.patch.dim()),
            degrees: Vec::new(),
            domains: Vec::new(),
            points: Vec::new(),
            bounds: Vec::new(),
        };
        for p in &l.0 {
            a.degrees.push(p.reduction.patch.degree());
            a.domains
                .extend(p.vertices.iter().flat_map(|&(u, v)| [u, v]));
            a.points.extend_from_slice(p.reduction.patch.points());
            a.bounds.push(p.reduction.report.error_bound);
        }
        // SAFETY: as above.
        unsafe {
            a.copy(
                degrees_out,
                degrees_out_cap,
                domains_out,
                domains_out_cap,
                points_out,
                points_out_cap,
                bounds_out,
                bounds_out_cap,
                sizes,
            )
        }
    })
}
