//! The one place that applies reduction and elevation operators to arrays of curves: the
//! single-curve apply of `cagd_bezier_reduce`, and the blocks of the batch calls in both
//! layouts. Everything the batch internals of cagd-reduce offer is used here and nowhere
//! else in the C layer (`reduce_batch` for curve-major reduction, `Operator::matrix` for
//! point-major; cagd-core's `kernel::elevate` and `elevation_coefficient` for elevation),
//! so that a faster cagd-reduce kernel is adopted by changing this file only.
//!
//! No kernel here computes anything the library does not: the point-major loops form
//! the same sums, term by term in the same order, as the curve-major library kernels, so
//! the two layouts give equal bits (tested).

use std::cell::RefCell;
use std::ops::Range;
use std::sync::Arc;

use cagd_core::kernel::{elevate, elevation_coefficient};
use cagd_reduce::{Method, Operator, operator, reduce_batch};

use crate::boundary::{CResult, Failure};
use crate::status::CagdStatus;

/// Columns (doubles of one point-major row) processed together, so that the tile of the
/// output row stays in L1 while every input row is added to it (4 KiB).
const TILE: usize = 512;

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
pub(super) fn operator_for(method: Method, n: usize, m: usize) -> cagd_core::Result<Arc<Operator>> {
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
    if output.iter().all(|x| x.is_finite()) {
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
    if output.iter().all(|x| x.is_finite()) {
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

/// One column block of a point-major batch: the columns `cols` (doubles of a row, a whole
/// number of curves) of every output row.
pub(super) struct PointMajorBlock<'a> {
    /// The columns of the block, in doubles of a row.
    pub(super) cols: Range<usize>,
    /// The block's part of each output row, row 0 first.
    pub(super) rows: Vec<&'a mut [f64]>,
}

/// Reduces one point-major block with `op`: output row `i` is `sum_j a_ij * row_j`, every
/// `j` in order, as cagd-reduce's `reduce_batch` sums a curve-major curve.
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
    let n1 = op.degree_from() + 1;
    point_major(input, row_len, dim, block, |i| {
        (0..n1).map(move |j| (j, a[i * n1 + j]))
    })
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
    block: PointMajorBlock<'_>,
    terms: T,
) -> Result<(), Overflow>
where
    T: Fn(usize) -> I,
    I: Iterator<Item = (usize, f64)>,
{
    let PointMajorBlock { cols, mut rows } = block;
    let width = cols.len();
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
    // Every output is a finite sum of finite terms unless it overflowed.
    for row in &rows {
        if let Some(pos) = row.iter().position(|x| !x.is_finite()) {
            return Err(Overflow { curve: pos / dim });
        }
    }
    Ok(())
}
