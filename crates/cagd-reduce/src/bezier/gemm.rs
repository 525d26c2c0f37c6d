//! One linear map of control points applied to many curves stored curve-major, through a
//! real GEMM kernel (nalgebra's `gemm`, which hands dynamic products with every side above
//! 5 to the `matrixmultiply` crate, packing and register-blocking included). Goes beyond
//! the seed: this is the data path under [`crate::reduce_batch`] and the batch bounds.
//!
//! The caller's array is viewed, never transposed: coordinate `k` of a block of curves is
//! the `(n+1) x curves` matrix with row stride `dim` and column stride `(n+1) dim` inside
//! the caller's buffer (the point-major view), so `Q_k = A P_k` is one strided GEMM per
//! coordinate and block, written straight into the output. When the map is too small for
//! the kernel in that form (fewer than 6 rows or columns: `(4,3)`, `(5,4)`), the block is
//! instead one GEMM `X K` of the curves-by-`(n+1) dim` matrix `X` (contiguous rows) with the
//! Kronecker expansion `K = (A ⊗ I_dim)^T`; below that (a single small curve, or a map that
//! is small even expanded) a plain unrolled loop is faster than any kernel call.
//!
//! Every output is a dense sum over all inputs with the zeros of the map included (neither
//! route skips zeros), so a NaN or infinity anywhere in a curve reaches its outputs; the
//! callers detect non-finite input from the output alone.

use std::sync::OnceLock;

use nalgebra::{DMatrixView, DMatrixViewMut};

/// Smallest side (rows, columns, curves in a block) for which nalgebra calls its GEMM
/// kernel rather than a column-by-column `gemv` (nalgebra 0.35 `SMALL_DIM` = 5, exclusive).
/// Every `gemm` call below keeps all four sides at or above it, and must: nalgebra 0.35's
/// `gemv` fallback (`axcpy_uninit`) iterates over the *slice* length of a strided vector
/// with the stride applied again, reading and writing out of bounds on views whose row
/// stride is not 1 (it crashed the benchmark's point-major floor for a 4-row operator).
/// If nalgebra is upgraded, re-check its threshold.
const KERNEL_MIN: usize = 6;

/// Target size in bytes of the input of one block of curves: the block's input and output
/// (and the packed panels of the kernel) stay in L2 while the coordinates are swept.
const BLOCK_BYTES: usize = 64 * 1024;

/// Largest `dim` whose Kronecker expansion is cached in the map.
const KRON_DIMS: usize = 4;

/// A row-major `rows x cols` matrix applied to curves of `cols` points, giving curves of
/// `rows` points: `out_i = sum_j a_ij in_j` per coordinate.
#[derive(Debug, Clone)]
pub(crate) struct LinearMap {
    rows: usize,
    cols: usize,
    a: Vec<f64>,
    /// `K = (A ⊗ I_dim)^T`, row-major `(cols dim) x (rows dim)`, built on first use per dim.
    kron: [OnceLock<Vec<f64>>; KRON_DIMS],
}

impl LinearMap {
    /// The map with row-major matrix `a` of `rows x cols`.
    pub(crate) fn new(rows: usize, cols: usize, a: Vec<f64>) -> Self {
        debug_assert_eq!(a.len(), rows * cols);
        Self {
            rows,
            cols,
            a,
            kron: Default::default(),
        }
    }

    /// Number of output points per curve.
    pub(crate) fn rows(&self) -> usize {
        self.rows
    }

    /// Number of input points per curve.
    pub(crate) fn cols(&self) -> usize {
        self.cols
    }

    /// The row-major matrix.
    pub(crate) fn matrix(&self) -> &[f64] {
        &self.a
    }

    /// Curves per block for points of `dim` coordinates (at least one).
    pub(crate) fn block_curves(&self, dim: usize) -> usize {
        (BLOCK_BYTES / (8 * self.cols * dim)).max(KERNEL_MIN)
    }

    /// Applies the map to every curve of `input` (`curves * cols * dim` doubles,
    /// curve-major, row-major inside a curve) writing `curves * rows * dim` doubles to
    /// `output` in the same layout. Lengths are the caller's invariant (checked in debug).
    /// No allocation except the kernel's packing buffers and, once per map and `dim <= 4`,
    /// the Kronecker expansion.
    pub(crate) fn apply(&self, input: &[f64], dim: usize, output: &mut [f64]) {
        let (per_in, per_out) = (self.cols * dim, self.rows * dim);
        debug_assert_eq!(input.len() % per_in, 0);
        let curves = input.len() / per_in;
        debug_assert_eq!(output.len(), curves * per_out);
        let block = self.block_curves(dim);
        for (inp, out) in input
            .chunks(block * per_in)
            .zip(output.chunks_mut(block * per_out))
        {
            self.apply_block(inp, dim, out);
        }
    }

    /// One block (no further splitting): chooses the route described in the module docs.
    fn apply_block(&self, input: &[f64], dim: usize, output: &mut [f64]) {
        let curves = input.len() / (self.cols * dim);
        if curves < KERNEL_MIN {
            return self.apply_loop(input, dim, output);
        }
        if self.rows >= KERNEL_MIN && self.cols >= KERNEL_MIN {
            return self.apply_strided(input, dim, curves, output);
        }
        if dim <= KRON_DIMS && self.rows * dim >= KERNEL_MIN && self.cols * dim >= KERNEL_MIN {
            return self.apply_kron(input, dim, curves, output);
        }
        self.apply_loop(input, dim, output)
    }

    /// One strided GEMM per coordinate over the point-major view of the block.
    fn apply_strided(&self, input: &[f64], dim: usize, curves: usize, output: &mut [f64]) {
        let (r, c) = (self.rows, self.cols);
        let a = DMatrixView::from_slice_with_strides(&self.a, r, c, c, 1);
        for k in 0..dim {
            let p = DMatrixView::from_slice_with_strides(&input[k..], c, curves, dim, c * dim);
            let mut q = DMatrixViewMut::from_slice_with_strides_mut(
                &mut output[k..],
                r,
                curves,
                dim,
                r * dim,
            );
            q.gemm(1.0, &a, &p, 0.0);
        }
    }

    /// One GEMM `X K` with the Kronecker expansion of the map.
    fn apply_kron(&self, input: &[f64], dim: usize, curves: usize, output: &mut [f64]) {
        let (ci, ro) = (self.cols * dim, self.rows * dim);
        let kron = self.kron[dim - 1].get_or_init(|| self.kronecker(dim));
        let k = DMatrixView::from_slice_with_strides(kron, ci, ro, ro, 1);
        let x = DMatrixView::from_slice_with_strides(input, curves, ci, ci, 1);
        let mut y = DMatrixViewMut::from_slice_with_strides_mut(output, curves, ro, ro, 1);
        y.gemm(1.0, &x, &k, 0.0);
    }

    /// `K[(j dim + k), (i dim + k)] = a_ij`, row-major `(cols dim) x (rows dim)`.
    fn kronecker(&self, dim: usize) -> Vec<f64> {
        let ro = self.rows * dim;
        let mut kron = vec![0.0; self.cols * dim * ro];
        for i in 0..self.rows {
            for j in 0..self.cols {
                for k in 0..dim {
                    kron[(j * dim + k) * ro + i * dim + k] = self.a[i * self.cols + j];
                }
            }
        }
        kron
    }

    /// The plain loop (small blocks): unrolled for `dim <= 4`.
    pub(crate) fn apply_loop(&self, input: &[f64], dim: usize, output: &mut [f64]) {
        match dim {
            1 => loop_fixed::<1>(&self.a, self.cols, input, output),
            2 => loop_fixed::<2>(&self.a, self.cols, input, output),
            3 => loop_fixed::<3>(&self.a, self.cols, input, output),
            4 => loop_fixed::<4>(&self.a, self.cols, input, output),
            _ => loop_dyn(&self.a, self.cols, self.rows, dim, input, output),
        }
    }
}

/// Fixed-dimension loop over curves, four rows at a time (independent accumulators, so
/// the multiply-adds of one curve overlap instead of waiting on one another).
fn loop_fixed<const D: usize>(a: &[f64], cols: usize, input: &[f64], output: &mut [f64]) {
    let rows = a.len() / cols;
    for (inp, out) in input
        .chunks_exact(cols * D)
        .zip(output.chunks_exact_mut(rows * D))
    {
        let mut quads = a.chunks_exact(4 * cols);
        let mut outs = out.chunks_exact_mut(4 * D);
        for (rows4, o) in (&mut quads).zip(&mut outs) {
            let (r0, rest) = rows4.split_at(cols);
            let (r1, rest) = rest.split_at(cols);
            let (r2, r3) = rest.split_at(cols);
            let mut acc = [[0.0f64; D]; 4];
            for ((((x, c0), c1), c2), c3) in inp.chunks_exact(D).zip(r0).zip(r1).zip(r2).zip(r3) {
                for k in 0..D {
                    acc[0][k] += c0 * x[k];
                    acc[1][k] += c1 * x[k];
                    acc[2][k] += c2 * x[k];
                    acc[3][k] += c3 * x[k];
                }
            }
            for (o1, a1) in o.chunks_exact_mut(D).zip(&acc) {
                o1.copy_from_slice(a1);
            }
        }
        for (row, o) in quads
            .remainder()
            .chunks_exact(cols)
            .zip(outs.into_remainder().chunks_exact_mut(D))
        {
            let mut acc = [0.0f64; D];
            for (&c, x) in row.iter().zip(inp.chunks_exact(D)) {
                for k in 0..D {
                    acc[k] += c * x[k];
                }
            }
            o.copy_from_slice(&acc);
        }
    }
}

/// Any-dimension loop over curves.
fn loop_dyn(a: &[f64], cols: usize, rows: usize, dim: usize, input: &[f64], output: &mut [f64]) {
    for (inp, out) in input
        .chunks_exact(cols * dim)
        .zip(output.chunks_exact_mut(rows * dim))
    {
        for (row, o) in a.chunks_exact(cols).zip(out.chunks_exact_mut(dim)) {
            o.fill(0.0);
            for (&c, x) in row.iter().zip(inp.chunks_exact(dim)) {
                for (ok, xk) in o.iter_mut().zip(x) {
                    *ok += c * xk;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_core::all_finite;

    /// The reference: the definition, curve by curve, coordinate by coordinate.
    fn reference(a: &[f64], rows: usize, cols: usize, input: &[f64], dim: usize) -> Vec<f64> {
        let curves = input.len() / (cols * dim);
        let mut out = vec![0.0; curves * rows * dim];
        for c in 0..curves {
            for i in 0..rows {
                for k in 0..dim {
                    out[(c * rows + i) * dim + k] = (0..cols)
                        .map(|j| a[i * cols + j] * input[(c * cols + j) * dim + k])
                        .sum();
                }
            }
        }
        out
    }

    #[test]
    fn every_route_equals_the_definition() {
        // Shapes hitting the strided route (rows, cols >= 6), the Kronecker route (small
        // map, dim >= 2), and the loop (dim 1 small map; dim 5; fewer than 6 curves); curve
        // counts that do and do not fill whole blocks.
        for (rows, cols) in [(4, 5), (5, 6), (6, 11), (11, 16), (16, 31), (2, 3)] {
            let a: Vec<f64> = (0..rows * cols)
                .map(|i| ((i * 37 % 23) as f64 - 11.0) / 7.0)
                .collect();
            let map = LinearMap::new(rows, cols, a.clone());
            for dim in 1..=5 {
                for curves in [1, 5, 6, 7, 1000, map.block_curves(dim) * 2 + 3] {
                    let input: Vec<f64> = (0..curves * cols * dim)
                        .map(|i| ((i * 7919 % 1001) as f64 - 500.0) / 97.0)
                        .collect();
                    let mut out = vec![f64::NAN; curves * rows * dim];
                    map.apply(&input, dim, &mut out);
                    let want = reference(&a, rows, cols, &input, dim);
                    for (g, w) in out.iter().zip(&want) {
                        // Same sums in another order: a few ulps of the sum of |terms|.
                        assert!(
                            (g - w).abs() <= 1e-13 * (1.0 + w.abs()) * cols as f64,
                            "{rows}x{cols} dim {dim} curves {curves}: {g} vs {w}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn non_finite_input_reaches_the_output() {
        // A zero column in the map: the NaN must still reach the output (dense sums).
        let (rows, cols) = (6, 8);
        let mut a = vec![1.0; rows * cols];
        for i in 0..rows {
            a[i * cols + 3] = 0.0;
        }
        let map = LinearMap::new(rows, cols, a);
        for dim in [1, 3] {
            let curves = 50;
            let mut input = vec![0.5; curves * cols * dim];
            input[(17 * cols + 3) * dim] = f64::NAN;
            let mut out = vec![0.0; curves * rows * dim];
            map.apply(&input, dim, &mut out);
            assert!(!all_finite(&out), "dim {dim}");
            input[(17 * cols + 3) * dim] = 0.5;
            map.apply(&input, dim, &mut out);
            assert!(all_finite(&out));
        }
    }
}
