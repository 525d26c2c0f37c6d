//! `cagd_curvelist_copy`: every array of a `CagdCurveList` (degrees, intervals, points,
//! weights, bounds) copied into caller buffers in one call, with capacity 0 asking the
//! sizes — instead of one `cagd_curvelist_get` handle and three calls per piece.

use crate::boundary::{boundary, handle_ref, out_ref};
use crate::copy_out::{OutArray, copy_all};
use crate::curve::CagdCurveList;
use crate::status::CagdStatus;

/// The sizes of the arrays of a `CagdCurveList`, written by `cagd_curvelist_copy` on
/// `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`. Counts of `size_t` / doubles, never bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CagdCurveListSizes {
    /// Number of pieces (`>= 1` for lists made by cagd): the length of `degrees_out`.
    pub n_pieces: usize,
    /// Coordinates per point, the same for every piece.
    pub dim: usize,
    /// Whether the pieces are rational (then `weights_len > 0`).
    pub rational: bool,
    /// `2 * n_pieces`: the length of `intervals_out`.
    pub intervals_len: usize,
    /// `sum_i (degree_i + 1) * dim`: the length of `points_out`.
    pub points_len: usize,
    /// `sum_i (degree_i + 1)` for rational pieces, 0 for polynomial ones: the length of
    /// `weights_out`.
    pub weights_len: usize,
    /// `n_pieces` when every piece has a certified bound (pieces of a reduction), 0
    /// otherwise (exact pieces, e.g. of `cagd_bspline_to_beziers`): the length of
    /// `bounds_out`.
    pub bounds_len: usize,
}

/// Copies every piece of a curve list into caller buffers in one call. Call it once with
/// every capacity 0 (and the buffers NULL) to learn the sizes, allocate, call again.
///
/// Piece `i` has `degree_i + 1` control points; its points start at
/// `points_out[dim * sum_{k<i} (degree_k + 1)]` (row-major, Euclidean for rational pieces)
/// and its weights at `weights_out[sum_{k<i} (degree_k + 1)]`; its parameter interval
/// `[a_i, b_i]` in the parameter of the whole (as `cagd_curvelist_interval`) is
/// `intervals_out[2 i]`, `intervals_out[2 i + 1]`; its certified bound (as
/// `cagd_curvelist_bound`) is `bounds_out[i]`.
///
/// Parameters:
/// - `list` (in): the list.
/// - `degrees_out` (out): `degrees_out_cap` `size_t`; on `CAGD_OK` the `n_pieces` degrees.
/// - `intervals_out` (out): `intervals_out_cap` doubles; on `CAGD_OK` the `2 * n_pieces`
///   interval ends.
/// - `points_out` (out): `points_out_cap` doubles; on `CAGD_OK` the `points_len` control
///   point coordinates.
/// - `weights_out` (out): `weights_out_cap` doubles; on `CAGD_OK` the `weights_len`
///   weights (none for polynomial pieces).
/// - `bounds_out` (out): `bounds_out_cap` doubles; on `CAGD_OK` the `bounds_len` bounds
///   (none for exact pieces).
/// - each `*_cap` (in): the capacity of its buffer in elements; a buffer may be NULL only
///   when its capacity is 0 (a buffer whose array is empty may always be NULL with 0).
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
pub unsafe extern "C" fn cagd_curvelist_copy(
    list: *const CagdCurveList,
    degrees_out: *mut usize,
    degrees_out_cap: usize,
    intervals_out: *mut f64,
    intervals_out_cap: usize,
    points_out: *mut f64,
    points_out_cap: usize,
    weights_out: *mut f64,
    weights_out_cap: usize,
    bounds_out: *mut f64,
    bounds_out_cap: usize,
    sizes_out: *mut CagdCurveListSizes,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let l = unsafe { handle_ref(list, "list") }?;
        // SAFETY: as above.
        let sizes = unsafe { out_ref(sizes_out, "sizes_out") }?;
        let a = Arrays::of(l);
        let s = a.sizes();
        let arrays = (
            OutArray::new(degrees_out, degrees_out_cap, &a.degrees, "degrees_out"),
            OutArray::new(
                intervals_out,
                intervals_out_cap,
                &a.intervals,
                "intervals_out",
            ),
            OutArray::new(points_out, points_out_cap, &a.points, "points_out"),
            OutArray::new(weights_out, weights_out_cap, &a.weights, "weights_out"),
            OutArray::new(bounds_out, bounds_out_cap, &a.bounds, "bounds_out"),
        );
        // SAFETY: as above.
        unsafe {
            copy_all(
                &[&arrays.0, &arrays.1, &arrays.2, &arrays.3, &arrays.4],
                || *sizes = s,
            )
        }
    })
}

/// The arrays of a list, gathered.
struct Arrays {
    dim: usize,
    rational: bool,
    degrees: Vec<usize>,
    intervals: Vec<f64>,
    points: Vec<f64>,
    weights: Vec<f64>,
    bounds: Vec<f64>,
}

impl Arrays {
    fn of(l: &CagdCurveList) -> Self {
        let pieces = &l.0;
        let dim = pieces.first().map_or(0, |p| p.curve.dim());
        debug_assert!(pieces.iter().all(|p| p.curve.dim() == dim));
        let rational = pieces.iter().any(|p| p.curve.is_rational());
        let mut a = Self {
            dim,
            rational,
            degrees: Vec::with_capacity(pieces.len()),
            intervals: Vec::with_capacity(2 * pieces.len()),
            points: Vec::new(),
            weights: Vec::new(),
            bounds: Vec::with_capacity(pieces.len()),
        };
        for p in pieces {
            a.degrees.push(p.curve.degree());
            a.intervals.extend([p.start, p.end]);
            a.points.extend_from_slice(p.curve.points());
            if rational {
                match p.curve.weights() {
                    Some(w) => a.weights.extend_from_slice(w),
                    None => a
                        .weights
                        .extend(std::iter::repeat_n(1.0, p.curve.degree() + 1)),
                }
            }
        }
        if pieces.iter().all(|p| p.bound.is_some()) {
            a.bounds = pieces.iter().filter_map(|p| p.bound).collect();
        }
        a
    }

    fn sizes(&self) -> CagdCurveListSizes {
        CagdCurveListSizes {
            n_pieces: self.degrees.len(),
            dim: self.dim,
            rational: self.rational,
            intervals_len: self.intervals.len(),
            points_len: self.points.len(),
            weights_len: self.weights.len(),
            bounds_len: self.bounds.len(),
        }
    }
}
