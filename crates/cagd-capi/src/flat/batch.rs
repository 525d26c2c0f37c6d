//! The batch calls: `cagd_bezier_reduce_batch` and `cagd_bezier_elevate_batch`, many
//! curves of one degree in one array (either `CagdBatchLayout`), on an optional number of
//! threads. The arithmetic is in `kernel.rs`, the threads in `threads.rs`; this file
//! checks the arguments and cuts the batch into blocks.

use cagd_core::check_degree;
use cagd_reduce::Operator;

use super::kernel::{
    Overflow, PointMajorBlock, elevate_curve_major, elevate_point_major, elevation_terms,
    operator_for, reduce_curve_major, reduce_point_major,
};
use super::layout::CagdBatchLayout;
use super::threads::{block_count, block_range, run_blocks};
use crate::boundary::{
    CResult, Failure, OUT, boundary, checked_len, nonnull, points_in, slice_out,
};
use crate::options::{CagdReduceOptions, read_options};
use crate::status::CagdStatus;

/// The fewest curves worth a block of their own on another thread (below that, the cost of
/// handing the block over is a sizeable part of the work).
const MIN_CURVES_PER_BLOCK: usize = 512;

/// What a batch does to every curve.
#[derive(Clone, Copy)]
enum BatchOp<'a> {
    /// Apply a reduction operator.
    Reduce(&'a Operator),
    /// Elevate with the band of [`elevation_terms`].
    Elevate(&'a [Vec<(usize, f64)>]),
}

/// A validated batch: input, sizes, layout, threads.
struct Batch<'a> {
    input: &'a [f64],
    n_curves: usize,
    n1: usize,
    m1: usize,
    dim: usize,
    layout: CagdBatchLayout,
    n_threads: usize,
}

/// The failure for a non-finite input coordinate (naming curve, point and coordinate), if
/// the input has one. Called only after a kernel found a non-finite output: every output
/// of coordinate `k` of a curve is a sum over all its points with no term skipped (the
/// reduction is dense; elevation sums each point into at least its own index), so a NaN
/// or infinity in the input always shows in the output, and the input needs no scan of
/// its own on the way to success.
fn non_finite_input(b: &Batch<'_>) -> Option<Failure> {
    let pos = b.input.iter().position(|x| !x.is_finite())?;
    let (curve, point) = b.layout.curve_and_point(pos / b.dim, b.n_curves, b.n1);
    Some(Failure::new(
        CagdStatus::ERR_NON_FINITE,
        format!(
            "points: curve {curve}, point {point}, coordinate {} = {} is not finite",
            pos % b.dim,
            b.input[pos]
        ),
    ))
}

/// Runs the batch into `out` (`n_curves * m1 * dim` doubles, the input's layout).
fn run(b: &Batch<'_>, op: BatchOp<'_>, out: &mut [f64]) -> CResult<()> {
    let blocks = block_count(b.n_threads, b.n_curves, MIN_CURVES_PER_BLOCK);
    let first = |k: usize| block_range(k, blocks, b.n_curves).0;
    let results = match b.layout {
        CagdBatchLayout::LAYOUT_CURVE_MAJOR => {
            let (per_in, per_out) = (b.n1 * b.dim, b.m1 * b.dim);
            let mut parts = Vec::with_capacity(blocks);
            let mut rest = out;
            for k in 0..blocks {
                let (s, e) = block_range(k, blocks, b.n_curves);
                let (head, tail) = std::mem::take(&mut rest).split_at_mut((e - s) * per_out);
                parts.push((&b.input[s * per_in..e * per_in], head));
                rest = tail;
            }
            run_blocks(b.n_threads, parts, |(inp, o)| match op {
                BatchOp::Reduce(a) => reduce_curve_major(a, inp, b.dim, o),
                BatchOp::Elevate(terms) => elevate_curve_major(inp, terms, b.dim, o),
            })
        }
        CagdBatchLayout::LAYOUT_POINT_MAJOR => {
            let row_len = b.n_curves * b.dim;
            let ranges = (0..blocks)
                .map(|k| {
                    let (s, e) = block_range(k, blocks, b.n_curves);
                    s * b.dim..e * b.dim
                })
                .collect();
            let parts = PointMajorBlock::split(out, row_len, ranges);
            run_blocks(b.n_threads, parts, |part| match op {
                BatchOp::Reduce(a) => reduce_point_major(a, b.input, row_len, b.dim, part),
                BatchOp::Elevate(terms) => {
                    elevate_point_major(b.input, row_len, b.dim, terms, part)
                }
            })
        }
    };
    for (k, res) in results.into_iter().enumerate() {
        if let Err(Overflow { curve }) = res {
            return Err(non_finite_input(b).unwrap_or_else(|| Overflow::failure(first(k) + curve)));
        }
    }
    Ok(())
}

/// Checks the common arguments of the batch calls and borrows the input.
///
/// # Safety
/// `points` NULL or `n_curves * (degree + 1) * dim` readable doubles valid for `'a`.
unsafe fn batch_in<'a>(
    points: *const f64,
    n_curves: usize,
    degree: usize,
    dim: usize,
    layout: i32,
    n_threads: usize,
) -> CResult<Batch<'a>> {
    let layout = CagdBatchLayout::of(layout)?;
    check_degree(degree)?;
    let n_points = checked_len(n_curves, degree + 1, "n_curves * (degree + 1)")?;
    // SAFETY: forwarded contract.
    let input = unsafe { points_in(points, n_points, dim, "points") }?;
    Ok(Batch {
        input,
        n_curves,
        n1: degree + 1,
        m1: 0,
        dim,
        layout,
        n_threads,
    })
}

/// Reduces `n_curves` polynomial Bézier curves of one degree `n` to degree `opts->target`
/// with one cached operator, on `n_threads` threads: `cagd_curve_reduce_batch` with a
/// choice of layout and threads. Curve-major input gives `cagd_curve_reduce_batch`'s points
/// bit for bit, whatever the thread count; point-major input gives the same points up to
/// rounding (its sums run in another order than the GEMM kernel's: a few ulps of
/// `sum_j |a_ij| |P_j|`).
/// Only `opts->method`, `target`, `r`, `p`, `l1`, `l2` are used; no report (call
/// `cagd_bezier_reduce` for a certified bound per curve). Rational curves: pass their
/// homogeneous points `(w_i P_i, w_i)` as polynomial curves of dimension `dim + 1`.
///
/// Parameters:
/// - `points` (in): `n_curves * (n + 1) * dim` doubles in `layout` (see
///   `CagdBatchLayout`). Borrowed for the call.
/// - `n_curves` (in): number of curves; 0 is allowed (`*out_needed = 0`).
/// - `degree` (in): the common source degree `n`, `0..=64`.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `layout` (in): a `CagdBatchLayout` code, for the input and the output alike.
/// - `opts` (in): the options. Borrowed for the call.
/// - `n_threads` (in): 0 or 1: the calling thread only; `k > 1`: a pool of `k` worker
///   threads (at most 256), started on the first call with that count and kept for the
///   process (the calling thread waits). Small batches (under 1024 curves) run on the
///   calling thread whatever the count. The result does not depend on it.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `n_curves * (target + 1) * dim` doubles hold the reduced curves in `layout`. May be
///   NULL only when `out_cap == 0`. Not written on failure, but for `CAGD_ERR_NON_FINITE`
///   (contents then unspecified).
/// - `out_cap` (in): capacity of `out` in doubles (0 asks the size).
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `n_curves * (target + 1) * dim`.
///
/// Returns:
/// - `CAGD_OK`: the reduced curves are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `points`, `opts` or `out_needed` is NULL, or `out` is NULL
///   with `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, a size formula overflows, `layout` is not a
///   `CagdBatchLayout`, `opts->struct_size` below `sizeof(CagdReduceOptions)`, an invalid
///   `opts->method` code or `l1` / `l2`, or a pointer is misaligned.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `degree > 64`.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target >= degree` or below the method's minimum.
/// - `CAGD_ERR_TOO_MANY_CONSTRAINTS`: `r + p + 1 > target` or `r`, `p` below -1.
/// - `CAGD_ERR_NON_FINITE`: an input coordinate is NaN or infinite (the message names the
///   curve, point and coordinate), or a reduced coordinate overflows to infinity (input
///   near the largest double). On this status the contents of `out` are unspecified (the
///   input is not scanned before the kernel writes: non-finite input is found from the
///   output); `*out_needed` is written.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is below the formula; only `*out_needed` is
///   written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `points` must be NULL or point to `n_curves * (degree + 1) * dim` readable doubles;
/// `opts` NULL or readable; `out` NULL or `out_cap` writable doubles not overlapping
/// `points`; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bezier_reduce_batch(
    points: *const f64,
    n_curves: usize,
    degree: usize,
    dim: usize,
    layout: i32,
    opts: *const CagdReduceOptions,
    n_threads: usize,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        nonnull(points, "points")?;
        // SAFETY: the caller's contract (see # Safety).
        let o = unsafe { read_options(opts) }?;
        // SAFETY: as above.
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        // SAFETY: as above.
        let mut b = unsafe { batch_in(points, n_curves, degree, dim, layout, n_threads) }?;
        let op = operator_for(o.method()?, degree, o.target)?;
        b.m1 = o.target + 1;
        let per_out = checked_len(b.m1, dim, "(target + 1) * dim")?;
        let needed = checked_len(n_curves, per_out, "n_curves * (target + 1) * dim")?;
        run(&b, BatchOp::Reduce(&op), dst.take(needed)?)
    })
}

/// Elevates `n_curves` polynomial Bézier curves of one degree `n` to degree `n + r`
/// (`Q_i = sum_j C(n,j) C(r,i-j) / C(n+r,i) P_j`, seed 001 §3.2), on `n_threads` threads:
/// the batch form of `cagd_curve_elevate` / `cagd_bezier_elevate`, with the same points bit
/// for bit. Rational curves: pass their homogeneous points `(w_i P_i, w_i)` as polynomial
/// curves of dimension `dim + 1` (elevation is linear in them).
///
/// Parameters:
/// - `points` (in): `n_curves * (n + 1) * dim` doubles in `layout` (see
///   `CagdBatchLayout`). Borrowed for the call.
/// - `n_curves` (in): number of curves; 0 is allowed (`*out_needed = 0`).
/// - `degree` (in): the common source degree `n`, `0..=64`.
/// - `dim` (in): coordinates per point, `>= 1`.
/// - `layout` (in): a `CagdBatchLayout` code, for the input and the output alike.
/// - `r` (in): how many degrees to add; `n + r <= 64`; 0 copies.
/// - `n_threads` (in): as for `cagd_bezier_reduce_batch` (0 or 1: the calling thread).
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `n_curves * (n + r + 1) * dim` doubles hold the elevated curves in `layout`. May be
///   NULL only when `out_cap == 0`. Not written on failure, but for `CAGD_ERR_NON_FINITE`
///   (contents then unspecified).
/// - `out_cap` (in): capacity of `out` in doubles (0 asks the size).
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `n_curves * (n + r + 1) * dim`.
///
/// Returns:
/// - `CAGD_OK`: the elevated curves are in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `points` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, a size formula overflows, `layout` is not a
///   `CagdBatchLayout`, or a pointer is misaligned.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `degree > 64` or `degree + r > 64`.
/// - `CAGD_ERR_NON_FINITE`: an input coordinate is NaN or infinite (the message names the
///   curve, point and coordinate), or an elevated coordinate overflows to infinity (input
///   near the largest double). On this status the contents of `out` are unspecified (the
///   input is not scanned before the kernel writes: non-finite input is found from the
///   output); `*out_needed` is written.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is below the formula; only `*out_needed` is
///   written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `points` must be NULL or point to `n_curves * (degree + 1) * dim` readable doubles;
/// `out` NULL or `out_cap` writable doubles not overlapping `points`; `out_needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bezier_elevate_batch(
    points: *const f64,
    n_curves: usize,
    degree: usize,
    dim: usize,
    layout: i32,
    r: usize,
    n_threads: usize,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        nonnull(points, "points")?;
        // SAFETY: the caller's contract (see # Safety).
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        // SAFETY: as above.
        let mut b = unsafe { batch_in(points, n_curves, degree, dim, layout, n_threads) }?;
        check_degree(degree.saturating_add(r))?;
        b.m1 = degree + r + 1;
        let per_out = checked_len(b.m1, dim, "(degree + r + 1) * dim")?;
        let needed = checked_len(n_curves, per_out, "n_curves * (degree + r + 1) * dim")?;
        let dst = dst.take(needed)?;
        run(&b, BatchOp::Elevate(&elevation_terms(degree, r)), dst)
    })
}
