//! The one place that applies reduction and elevation operators to arrays of curves: the
//! single-curve apply of `cagd_bezier_reduce`, and the blocks of the batch calls in both
//! layouts. Everything the batch internals of cagd-reduce offer is used here and nowhere
//! else in the C layer (`reduce_batch` for curve-major reduction, `Operator::matrix` for
//! point-major, through the `matrixmultiply` GEMM kernel; cagd-core's `kernel::elevate` and `elevation_coefficient` for elevation),
//! so that a faster cagd-reduce kernel is adopted by changing this file only.
//!
//! No kernel here computes anything the library does not: the point-major elevation loops
//! form the same sums, term by term in the same order, as the curve-major library kernel,
//! so the two layouts give equal bits (tested); the point-major reduction is one GEMM of
//! the same operator, equal to the curve-major result up to the order of the sums.

use std::cell::RefCell;
use std::marker::PhantomData;
use std::ops::Range;
use std::sync::Arc;

use cagd_core::all_finite;
use cagd_core::kernel::{elevate, elevation_coefficient};
use cagd_reduce::{Method, Operator, operator, reduce_batch};

use crate::boundary::{CResult, Failure};
use crate::status::CagdStatus;

/// Columns (doubles of one point-major row) processed together, so that the tile of the
/// output row stays in L1 while every input row is added to it (4 KiB).
const TILE: usize = 512;

/// Bytes of output per column tile of the point-major GEMM (checked while in cache).
const GEMM_TILE_BYTES: usize = 64 * 1024;

/// A reduced or elevated coordinate that overflowed to infinity (finite input of
/// magnitude near `f64::MAX`): the first curve of the block where it happened.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Overflow {
    /// Index of a curve of the block (relative to the block).
    pub(super) curve: usize,
}

impl Overflow {
    /// The status for an overflow in curve `curve` of the whole batch.
    pub(super) fn failure(curve: usize) -> Failure {
        Failure::new(
            CagdStatus::ERR_NON_FINITE,
            format!(
                "curve {curve}: a result coordinate overflows to infinity (input coordinates \
                 near the largest double)"
            ),
        )
    }
}

/// The key and the operator of the last successful lookup of [`operator_for`].
type LastOperator = Option<(Method, usize, usize, Arc<Operator>)>;

/// The operator of `(method, n, m)`: cagd-reduce's process-wide cache ([`operator`]),
/// behind a one-entry cache per thread, so that a loop of single-curve calls with one
/// `(method, n, m)` — the usual hot loop — skips the shared cache's lock and hash. A hit
/// needs the same method (parameters compared with `==`, so a NaN parameter never hits
/// and reaches cagd-reduce's check) and degrees as the previous, successful lookup.
///
/// # Errors
/// As [`operator`].
pub(crate) fn operator_for(method: Method, n: usize, m: usize) -> cagd_core::Result<Arc<Operator>> {
    thread_local! {
        static LAST: RefCell<LastOperator> = const { RefCell::new(None) };
    }
    LAST.with_borrow_mut(|last| {
        if let Some((lm, ln, lmm, op)) = last.as_ref() {
            if *lm == method && *ln == n && *lmm == m {
                return Ok(Arc::clone(op));
            }
        }
        let op = operator(method, n, m)?;
        *last = Some((method, n, m, Arc::clone(&op)));
        Ok(op)
    })
}

/// Applies `op` to one curve (`n + 1` points of `dim` doubles) and writes the `m + 1`
/// reduced points to `dst`, through a per-thread scratch buffer, so that `dst` is written
/// only on success. The input must be finite (checked by the caller).
///
/// # Errors
/// `CAGD_ERR_NON_FINITE` when a reduced coordinate overflows.
pub(super) fn apply_one(op: &Operator, points: &[f64], dim: usize, dst: &mut [f64]) -> CResult<()> {
    thread_local! {
        static SCRATCH: RefCell<Vec<f64>> = const { RefCell::new(Vec::new()) };
    }
    SCRATCH.with_borrow_mut(|scratch| {
        scratch.clear();
        scratch.resize(dst.len(), 0.0);
        op.apply_into(points, dim, scratch)
            .map_err(|_| Overflow::failure(0))?;
        dst.copy_from_slice(scratch);
        Ok(())
    })
}

/// Reduces the curve-major block `input` (whole curves) into `output` with `op`.
///
/// # Errors
/// [`Overflow`] naming the first curve (relative to the block) with a non-finite output.
pub(super) fn reduce_curve_major(
    op: &Operator,
    input: &[f64],
    dim: usize,
    output: &mut [f64],
) -> Result<(), Overflow> {
    reduce_batch(op, input, dim, output)
        .map_err(|_| first_bad_curve(output, (op.degree_to() + 1) * dim))
}

/// Elevates one curve (`n + 1` points of `dim` doubles) by `r` into `output` with
/// cagd-core's `kernel::elevate`, the kernel `BezierCurve::elevate` uses.
///
/// # Errors
/// [`Overflow`] when an elevated coordinate is not finite (input near `f64::MAX`).
pub(super) fn elevate_one(
    input: &[f64],
    dim: usize,
    r: usize,
    output: &mut [f64],
) -> Result<(), Overflow> {
    elevate(input, dim, r, output);
    if all_finite(output) {
        Ok(())
    } else {
        Err(Overflow { curve: 0 })
    }
}

/// The band of the elevation matrix from degree `n` by `r`: for output point `i`, the
/// pairs `(j, Q(i, j))`, `i - r <= j <= min(i, n)` in increasing `j` — the terms and the
/// order of cagd-core's `kernel::elevate`, computed once per batch instead of once per
/// curve (each coefficient costs three binomials).
pub(super) fn elevation_terms(n: usize, r: usize) -> Vec<Vec<(usize, f64)>> {
    (0..=n + r)
        .map(|i| {
            (i.saturating_sub(r)..=i.min(n))
                .map(|j| (j, elevation_coefficient(n, r, i, j)))
                .collect()
        })
        .collect()
}

/// Elevates the curve-major block `input` (curves of `n + 1` points) into `output` with
/// the band `terms` of [`elevation_terms`]: every output coordinate is `0` plus the terms
/// in order, as `kernel::elevate` sums them, so the bits are the same.
///
/// # Errors
/// [`Overflow`] naming the first curve (relative to the block) with a non-finite output.
pub(super) fn elevate_curve_major(
    input: &[f64],
    terms: &[Vec<(usize, f64)>],
    dim: usize,
    output: &mut [f64],
) -> Result<(), Overflow> {
    let n1 = terms.iter().flatten().map(|t| t.0 + 1).max().unwrap_or(1);
    match dim {
        1 => elevate_fixed::<1>(input, terms, n1, output),
        2 => elevate_fixed::<2>(input, terms, n1, output),
        3 => elevate_fixed::<3>(input, terms, n1, output),
        4 => elevate_fixed::<4>(input, terms, n1, output),
        _ => {
            for (p, q) in input
                .chunks_exact(n1 * dim)
                .zip(output.chunks_exact_mut(terms.len() * dim))
            {
                for (row, o) in terms.iter().zip(q.chunks_exact_mut(dim)) {
                    o.fill(0.0);
                    for &(j, c) in row {
                        for (ok, xk) in o.iter_mut().zip(&p[j * dim..(j + 1) * dim]) {
                            *ok += c * xk;
                        }
                    }
                }
            }
        }
    }
    if all_finite(output) {
        Ok(())
    } else {
        Err(first_bad_curve(output, terms.len() * dim))
    }
}

/// [`elevate_curve_major`] for a fixed dimension (the same sums in the same order, with
/// the point held in registers).
fn elevate_fixed<const D: usize>(
    input: &[f64],
    terms: &[Vec<(usize, f64)>],
    n1: usize,
    output: &mut [f64],
) {
    for (p, q) in input
        .chunks_exact(n1 * D)
        .zip(output.chunks_exact_mut(terms.len() * D))
    {
        for (row, o) in terms.iter().zip(q.chunks_exact_mut(D)) {
            let mut acc = [0.0f64; D];
            for &(j, c) in row {
                let x = &p[j * D..(j + 1) * D];
                for k in 0..D {
                    acc[k] += c * x[k];
                }
            }
            o.copy_from_slice(&acc);
        }
    }
}

/// The first curve of `output` (curves of `per` doubles) with a non-finite coordinate.
fn first_bad_curve(output: &[f64], per: usize) -> Overflow {
    let pos = output.iter().position(|x| !x.is_finite()).unwrap_or(0);
    Overflow {
        curve: pos / per.max(1),
    }
}

/// One column block of a point-major batch's output: the columns `cols` (doubles of a
/// row, a whole number of curves) of every output row. Blocks made by
/// [`PointMajorBlock::split`] of one output have disjoint columns, so they may be written
/// on different threads; the output stays exclusively borrowed for `'a`.
pub(super) struct PointMajorBlock<'a> {
    /// The columns of the block, in doubles of a row.
    cols: Range<usize>,
    /// Start of the whole output (row 0, column 0).
    base: *mut f64,
    /// Doubles per output row.
    row_len: usize,
    /// Number of output rows.
    n_rows: usize,
    _out: PhantomData<&'a mut [f64]>,
}

// SAFETY: a block reads and writes only its own columns of the output rows (disjoint from
// every other block of the same `split`), through a pointer derived from the exclusive
// borrow of the whole output, which outlives it (`'a`).
unsafe impl Send for PointMajorBlock<'_> {}

impl<'a> PointMajorBlock<'a> {
    /// The blocks of `out` (rows of `row_len` doubles) for the column ranges `ranges`,
    /// which must be in increasing order, disjoint and within a row (checked: a panic, a
    /// bug of the caller, not undefined behaviour).
    pub(super) fn split(
        out: &'a mut [f64],
        row_len: usize,
        ranges: Vec<Range<usize>>,
    ) -> Vec<Self> {
        let n_rows = out.len().checked_div(row_len).unwrap_or(0);
        assert_eq!(n_rows * row_len, out.len(), "whole rows");
        let mut end = 0;
        for r in &ranges {
            assert!(
                r.start >= end && r.start <= r.end && r.end <= row_len,
                "disjoint columns"
            );
            end = r.end;
        }
        let base = out.as_mut_ptr();
        ranges
            .into_iter()
            .map(|cols| Self {
                cols,
                base,
                row_len,
                n_rows,
                _out: PhantomData,
            })
            .collect()
    }

    /// The block's part of each output row, row 0 first.
    fn rows(&mut self) -> Vec<&mut [f64]> {
        (0..self.n_rows)
            .map(|i| {
                // SAFETY: row i's columns `cols` are inside `out` (checked in `split`),
                // belong to this block only, and `&mut self` keeps the slices unique.
                unsafe {
                    std::slice::from_raw_parts_mut(
                        self.base.add(i * self.row_len + self.cols.start),
                        self.cols.len(),
                    )
                }
            })
            .collect()
    }

    /// The first curve (relative to the block) with a non-finite output coordinate.
    fn check(&mut self, dim: usize) -> Result<(), Overflow> {
        for row in self.rows() {
            if all_finite(row) {
                continue;
            }
            if let Some(pos) = row.iter().position(|x| !x.is_finite()) {
                return Err(Overflow { curve: pos / dim });
            }
        }
        Ok(())
    }
}

/// A slice length (or a stride within one) as the kernel's `isize`: a slice never spans
/// more than `isize::MAX` bytes, so this cannot fail.
fn stride(x: usize) -> isize {
    isize::try_from(x).unwrap_or(isize::MAX)
}

/// Reduces one point-major block with `op`: output row `i` is `sum_j a_ij * row_j`, one
/// GEMM `Q = A P` of the `(m + 1) x (n + 1)` operator and the block's `(n + 1) x width`
/// columns of the caller's rows (row stride `row_len`, no copy), written straight into
/// the caller's output rows, through the `matrixmultiply` kernel (the one under
/// nalgebra's `gemm`; called directly because nalgebra has no kernel route
/// for a side below 6). Sums in the kernel's order: equal to the curve-major result up to
/// rounding. The kernel multiplies every entry (no zero skipping), so an overflow shows in
/// the output.
///
/// # Errors
/// [`Overflow`] with the first curve (relative to the block) of a non-finite output.
pub(super) fn reduce_point_major(
    op: &Operator,
    input: &[f64],
    row_len: usize,
    dim: usize,
    block: PointMajorBlock<'_>,
) -> Result<(), Overflow> {
    let a = op.matrix();
    let (n1, m1) = (op.degree_from() + 1, op.degree_to() + 1);
    let width = block.cols.len();
    if width == 0 {
        // No curves in the block (an empty batch has no rows at all).
        return Ok(());
    }
    assert!(
        input.len() == n1 * row_len && block.n_rows == m1 && block.row_len == row_len,
        "point-major sizes"
    );
    // Column tiles whose output (m1 rows) stays in L1/L2 while it is checked for an
    // overflow right after the kernel wrote it (a separate pass over the whole output
    // would cost as much memory traffic as writing it).
    let tile = (GEMM_TILE_BYTES / (8 * m1)).max(dim) / dim * dim;
    let mut t0 = 0;
    while t0 < width {
        let t1 = (t0 + tile).min(width);
        let c0 = block.cols.start + t0;
        // SAFETY: `a` holds m1 x n1 doubles (row stride n1); the input tile is rows 0..n1
        // of `input` at columns c0..c0 + (t1 - t0), inside the block's columns (checked
        // above and in `split`); the output tile is the same columns of rows 0..m1 of the
        // output, which only this block writes.
        unsafe {
            matrixmultiply::dgemm(
                m1,
                n1,
                t1 - t0,
                1.0,
                a.as_ptr(),
                stride(n1),
                1,
                input.as_ptr().add(c0),
                stride(row_len),
                1,
                0.0,
                block.base.add(c0),
                stride(row_len),
                1,
            );
        }
        for i in 0..m1 {
            // SAFETY: as above; no other reference to these doubles exists meanwhile.
            let row =
                unsafe { std::slice::from_raw_parts(block.base.add(i * row_len + c0), t1 - t0) };
            if !all_finite(row) {
                let pos = row.iter().position(|x| !x.is_finite()).unwrap_or(0);
                return Err(Overflow {
                    curve: (t0 + pos) / dim,
                });
            }
        }
        t0 = t1;
    }
    Ok(())
}

/// Elevates one point-major block with the band `terms` of [`elevation_terms`]: output
/// row `i` is `sum_j Q(i, j) * row_j` over the band, as cagd-core's `kernel::elevate` sums
/// a curve.
///
/// # Errors
/// [`Overflow`] as [`reduce_point_major`].
pub(super) fn elevate_point_major(
    input: &[f64],
    row_len: usize,
    dim: usize,
    terms: &[Vec<(usize, f64)>],
    block: PointMajorBlock<'_>,
) -> Result<(), Overflow> {
    point_major(input, row_len, dim, block, |i| terms[i].iter().copied())
}

/// The point-major loop: for every tile of the block's columns, every output row `i` is
/// zeroed, then `c * row_j` is added for each `(j, c)` of `terms(i)` in order.
fn point_major<T, I>(
    input: &[f64],
    row_len: usize,
    dim: usize,
    mut block: PointMajorBlock<'_>,
    terms: T,
) -> Result<(), Overflow>
where
    T: Fn(usize) -> I,
    I: Iterator<Item = (usize, f64)>,
{
    let cols = block.cols.clone();
    let width = cols.len();
    let mut rows = block.rows();
    let mut t0 = 0;
    while t0 < width {
        let t1 = (t0 + TILE).min(width);
        for (i, row) in rows.iter_mut().enumerate() {
            let o = &mut row[t0..t1];
            o.fill(0.0);
            for (j, c) in terms(i) {
                let start = j * row_len + cols.start;
                let x = &input[start + t0..start + t1];
                for (ov, xv) in o.iter_mut().zip(x) {
                    *ov += c * xv;
                }
            }
        }
        t0 = t1;
    }
    drop(rows);
    // Every output is a finite sum of finite terms unless it overflowed.
    block.check(dim)
}
