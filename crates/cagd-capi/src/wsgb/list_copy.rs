//! `cagd_wsgblist_copy`: every piece of a `CagdWsgbCurveList` (degrees, orders, intervals,
//! points, bounds) copied into caller buffers in one call, with capacity 0 asking the
//! sizes — instead of one `cagd_wsgblist_get` handle and its read-back per piece.

use super::CagdWsgbCurveList;
use crate::boundary::{boundary, handle_ref, out_ref};
use crate::copy_out::{OutArray, copy_all};
use crate::status::CagdStatus;

/// The sizes of the arrays of a `CagdWsgbCurveList`, written by `cagd_wsgblist_copy` on
/// `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`. Counts of `size_t` / doubles, never bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CagdWsgbListSizes {
    /// Number of pieces: the length of `degrees_out`, `orders_out` and `bounds_out`.
    pub n_pieces: usize,
    /// Coordinates per point, the same for every piece.
    pub dim: usize,
    /// `2 * n_pieces`: the length of `intervals_out`.
    pub intervals_len: usize,
    /// `sum_i (degree_i + 1) * dim`: the length of `points_out`.
    pub points_len: usize,
}

/// Copies every piece of a WSGB curve list into caller buffers in one call. Call it once
/// with every capacity 0 (and the buffers NULL) to learn the sizes, allocate, call again.
/// Piece `i` is a WSGB curve of degree `degrees_out[i]` and order `orders_out[i]` (as
/// `cagd_wsgb_shape`) with `degree_i + 1` control points following those of the pieces
/// before it in `points_out` (as `cagd_wsgb_points`); it approximates the source on
/// `[intervals_out[2 i], intervals_out[2 i + 1]]` within `bounds_out[i]` (as
/// `cagd_wsgblist_get`).
///
/// Parameters:
/// - `list` (in): the list.
/// - `degrees_out`, `orders_out` (out): `*_cap` `size_t` each; on `CAGD_OK` the `n_pieces`
///   degrees and orders.
/// - `intervals_out` (out): `intervals_out_cap` doubles; on `CAGD_OK` the `2 * n_pieces`
///   interval ends.
/// - `points_out` (out): `points_out_cap` doubles; on `CAGD_OK` the `points_len`
///   coordinates.
/// - `bounds_out` (out): `bounds_out_cap` doubles; on `CAGD_OK` the `n_pieces` certified
///   Euclidean bounds.
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
pub unsafe extern "C" fn cagd_wsgblist_copy(
    list: *const CagdWsgbCurveList,
    degrees_out: *mut usize,
    degrees_out_cap: usize,
    orders_out: *mut usize,
    orders_out_cap: usize,
    intervals_out: *mut f64,
    intervals_out_cap: usize,
    points_out: *mut f64,
    points_out_cap: usize,
    bounds_out: *mut f64,
    bounds_out_cap: usize,
    sizes_out: *mut CagdWsgbListSizes,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let sizes = unsafe { out_ref(sizes_out, "sizes_out") }?;
        let pieces = &l.0;
        let curves = || pieces.iter().map(|p| &p.reduction.curve);
        let degrees: Vec<usize> = curves().map(|c| c.degree()).collect();
        let orders: Vec<usize> = curves().map(|c| c.order()).collect();
        let intervals: Vec<f64> = pieces.iter().flat_map(|p| [p.start, p.end]).collect();
        let points: Vec<f64> = curves().flat_map(|c| c.points().iter().copied()).collect();
        let bounds: Vec<f64> = pieces.iter().map(|p| p.error_bound).collect();
        let s = CagdWsgbListSizes {
            n_pieces: pieces.len(),
            dim: curves().next().map_or(0, |c| c.dim()),
            intervals_len: intervals.len(),
            points_len: points.len(),
        };
        let a = OutArray::new(degrees_out, degrees_out_cap, &degrees, "degrees_out");
        let o = OutArray::new(orders_out, orders_out_cap, &orders, "orders_out");
        let i = OutArray::new(
            intervals_out,
            intervals_out_cap,
            &intervals,
            "intervals_out",
        );
        let p = OutArray::new(points_out, points_out_cap, &points, "points_out");
        let b = OutArray::new(bounds_out, bounds_out_cap, &bounds, "bounds_out");
        // SAFETY: as above.
        unsafe { copy_all(&[&a, &o, &i, &p, &b], || *sizes = s) }
    })
}
