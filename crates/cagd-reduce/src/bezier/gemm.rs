//! One linear map of control points applied to many curves stored curve-major. Goes
//! beyond the seed: this is the data path under [`crate::reduce_batch`] and the batch
//! bounds.
//!
//! Curves of three coordinates (the batch a CAD kernel sends) go through the padded-point
//! kernel of `padded.rs` (AVX2 + FMA: one point per vector, no transpose, the output's
//! finiteness summed in the same pass), all but the last curve and a partial group; those,
//! other dimensions and CPUs without AVX2 go through the curves-in-lanes kernel of
//! `lanes.rs` in blocks of curves (about 64 KiB of input each, so that a block's input and
//! output stay in L2 while the block is checked for non-finite values). Both do exactly
//! the `(m+1)(n+1) dim` multiply-adds of the definition per curve in the same order, so
//! they give the same bits (with AVX-512VL the padded kernel copies a map's unit end rows
//! instead, the same bits for finite inputs: `padded::Units`). They replaced nalgebra's `gemm` (the `matrixmultiply`
//! kernel) over a strided point-major view per coordinate and, for maps with a side below
//! 6, over the Kronecker expansion `(A ⊗ I_dim)^T` (`dim` times the flops); figures in
//! `benches/README.md`.
//!
//! Every summed output of coordinate `k` is a dense sum over all points of its curve with
//! the zeros of the map included, so a NaN or infinity anywhere in a curve reaches its
//! summed outputs (a map has at least one summed row); the callers detect non-finite
//! input from the output alone.

use std::sync::OnceLock;

use cagd_core::all_finite;

use super::{lanes, padded};

/// Curves per block are a multiple of this (the widest group of the lanes kernel: 8 curves
/// with AVX-512, 4 with AVX2), so that only the last block of a batch has curves that do
/// not fill a group (those run the kernel's slower one-curve loop): e.g. (5,4), 455 curves
/// per block of 64 KiB, sent 7 of each 455 through that loop.
const GROUP: usize = 8;

/// Target size in bytes of the input of one block of curves: the block's input and output
/// stay in L2 between the kernel and the finiteness check.
const BLOCK_BYTES: usize = 64 * 1024;

/// A row-major `rows x cols` matrix applied to curves of `cols` points, giving curves of
/// `rows` points: `out_i = sum_j a_ij in_j` per coordinate.
#[derive(Debug, Clone)]
pub(crate) struct LinearMap {
    rows: usize,
    cols: usize,
    a: Vec<f64>,
    /// `A^T`, row-major `cols x rows` (the coefficients of one input point, contiguous).
    at: Vec<f64>,
    /// `A^T` with each coefficient four times, the padded-point kernel's table, and the
    /// map's unit end rows; made on their first use (a batch of 3-D curves).
    splat: OnceLock<(Vec<f64>, padded::Units)>,
}

impl LinearMap {
    /// The map with row-major matrix `a` of `rows x cols`.
    pub(crate) fn new(rows: usize, cols: usize, a: Vec<f64>) -> Self {
        debug_assert_eq!(a.len(), rows * cols);
        let mut at = vec![0.0; rows * cols];
        for (i, row) in a.chunks_exact(cols.max(1)).enumerate() {
            for (j, x) in row.iter().enumerate() {
                at[j * rows + i] = *x;
            }
        }
        Self {
            rows,
            cols,
            a,
            at,
            splat: OnceLock::new(),
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

    /// The transposed matrix (`cols x rows`, row-major) and the number of rows: the form
    /// the lanes kernel takes.
    pub(crate) fn transposed(&self) -> (&[f64], usize) {
        (&self.at, self.rows)
    }

    /// Curves per block for points of `dim` coordinates: a multiple of [`GROUP`], at least
    /// one group.
    pub(crate) fn block_curves(&self, dim: usize) -> usize {
        let fit = BLOCK_BYTES / (8 * self.cols * dim).max(1);
        (fit / GROUP * GROUP).max(GROUP)
    }

    /// Applies the map to every curve of `input` (`curves * cols * dim` doubles,
    /// curve-major, row-major inside a curve) writing `curves * rows * dim` doubles to
    /// `output` in the same layout, checking the output for a non-finite value while it is
    /// in cache (in the padded kernel's pass, or block by block); returns whether every
    /// output is finite (all are written either way). Lengths are the caller's invariant
    /// (checked in debug). One allocation per call (the lanes kernel's scratch of
    /// `(rows + cols) dim` vectors), and the padded kernel's table on the map's first
    /// batch of 3-D curves.
    pub(crate) fn apply_checked(&self, input: &[f64], dim: usize, output: &mut [f64]) -> bool {
        let (per_in, per_out) = (self.cols * dim, self.rows * dim);
        if per_in == 0 || per_out == 0 {
            output.fill(0.0);
            return true;
        }
        debug_assert_eq!(input.len() % per_in, 0);
        let curves = input.len() / per_in;
        debug_assert_eq!(output.len(), curves * per_out);
        let mut scratch = Vec::new();
        if dim == 3 && curves > padded::CURVES && padded::available() {
            let (table, units) = self.splat.get_or_init(|| {
                let units = padded::Units::of(&self.a, self.rows, self.cols);
                (padded::splat(&self.at), units)
            });
            if let Some((done, finite)) = padded::apply3(table, units, self.rows, input, output) {
                let (inp, out) = (&input[done * per_in..], &mut output[done * per_out..]);
                lanes::apply(&self.at, self.rows, dim, inp, out, &mut scratch);
                return (finite && all_finite(out)) || all_finite(output);
            }
        }
        let block = self.block_curves(dim);
        let mut finite = true;
        for (inp, out) in input
            .chunks(block * per_in)
            .zip(output.chunks_mut(block * per_out))
        {
            lanes::apply(&self.at, self.rows, dim, inp, out, &mut scratch);
            if finite {
                finite = all_finite(out);
            }
        }
        finite
    }

    /// The plain loop for one curve (the bound of a single curve): unrolled for `dim <= 4`.
    pub(crate) fn apply_loop(&self, input: &[f64], dim: usize, output: &mut [f64]) {
        if self.rows == 0 || self.cols == 0 || dim == 0 {
            // An empty map (e.g. the error basis of an operator whose residual did not
            // survive rounding: rank 0) writes nothing.
            output.fill(0.0);
            return;
        }
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
    fn apply_and_the_loop_equal_the_definition() {
        // Small and large maps, dimensions 1-5, curve counts that do and do not fill whole
        // groups of four and whole blocks; the one-curve loop on the first curve.
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
                    assert!(map.apply_checked(&input, dim, &mut out));
                    let want = reference(&a, rows, cols, &input, dim);
                    let mut one = vec![f64::NAN; rows * dim];
                    map.apply_loop(&input[..cols * dim], dim, &mut one);
                    for (g, w) in one.iter().zip(&want) {
                        assert!((g - w).abs() <= 1e-13 * (1.0 + w.abs()) * cols as f64);
                    }
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
            // In the first and in a later block (the check stops at neither).
            let curves = map.block_curves(dim) * 3 + 1;
            for bad in [17, curves - 1] {
                let mut input = vec![0.5; curves * cols * dim];
                input[(bad * cols + 3) * dim] = f64::NAN;
                let mut out = vec![0.0; curves * rows * dim];
                assert!(!map.apply_checked(&input, dim, &mut out), "dim {dim}");
                assert!(!all_finite(&out), "dim {dim}");
                input[(bad * cols + 3) * dim] = 0.5;
                assert!(map.apply_checked(&input, dim, &mut out));
                assert!(all_finite(&out));
            }
            // Finite input overflowing to infinity is caught the same way.
            let mut input = vec![f64::MAX; curves * cols * dim];
            input[0] = 0.5;
            let mut out = vec![0.0; curves * rows * dim];
            assert!(!map.apply_checked(&input, dim, &mut out));
        }
    }
}

/// The padded-point kernel (`padded.rs`) through [`LinearMap::apply_checked`].
#[cfg(test)]
mod tests_padded {
    use super::super::padded::{Units, apply3, available, splat};
    use super::*;

    /// The definition with the kernels' operations: `acc = 0`, then `acc = fma(a_ij, x_j,
    /// acc)` for `j` increasing, per curve, point and coordinate.
    fn fused(a: &[f64], rows: usize, cols: usize, input: &[f64]) -> Vec<f64> {
        let curves = input.len() / (cols * 3);
        let mut out = vec![0.0; curves * rows * 3];
        for c in 0..curves {
            for i in 0..rows {
                for k in 0..3 {
                    let mut acc = 0.0f64;
                    for j in 0..cols {
                        acc = a[i * cols + j].mul_add(input[(c * cols + j) * 3 + k], acc);
                    }
                    out[(c * rows + i) * 3 + k] = acc;
                }
            }
        }
        out
    }

    fn map(rows: usize, cols: usize) -> (Vec<f64>, LinearMap) {
        let a: Vec<f64> = (0..rows * cols)
            .map(|i| ((i * 37 % 23) as f64 - 11.0) / 7.3)
            .collect();
        (a.clone(), LinearMap::new(rows, cols, a))
    }

    fn input(curves: usize, cols: usize) -> Vec<f64> {
        (0..curves * cols * 3)
            .map(|i| ((i * 7919 % 1001) as f64 - 500.0) / 97.1)
            .collect()
    }

    #[test]
    fn batch_equals_the_fused_definition_bit_for_bit() {
        // Sized instances (cols <= 11) and the general one; row counts that split into
        // blocks of 4, 3 + 2, and 1; curve counts below, at and above whole groups.
        if !available() {
            return;
        }
        let sizes = [
            (1, 2),
            (2, 3),
            (4, 5),
            (5, 6),
            (6, 11),
            (9, 11),
            (1, 12),
            (5, 12),
            (11, 16),
            (11, 21),
            (13, 20),
            (16, 31),
            (33, 65),
        ];
        for (rows, cols) in sizes {
            let (a, map) = map(rows, cols);
            for curves in [1, 2, 3, 4, 5, 6, 7, 8, 10, 31, 100] {
                let input = input(curves, cols);
                let mut out = vec![f64::NAN; curves * rows * 3];
                assert!(map.apply_checked(&input, 3, &mut out));
                let want = fused(&a, rows, cols, &input);
                for (idx, (g, w)) in out.iter().zip(&want).enumerate() {
                    assert_eq!(
                        g.to_bits(),
                        w.to_bits(),
                        "{rows}x{cols}, {curves} curves, {idx}"
                    );
                }
            }
        }
    }

    /// `map(rows, cols)` with unit end rows: the first row `e_0` (with a `-0`
    /// coefficient), the last `e_(cols-1)`.
    fn with_unit_ends(rows: usize, cols: usize) -> (Vec<f64>, LinearMap) {
        let (mut a, _) = map(rows, cols);
        a[..cols].fill(0.0);
        a[0] = 1.0;
        a[1] = -0.0;
        a[(rows - 1) * cols..].fill(0.0);
        a[rows * cols - 1] = 1.0;
        (a.clone(), LinearMap::new(rows, cols, a))
    }

    #[test]
    fn unit_end_rows_are_found_only_with_a_summed_row_between() {
        let (a, _) = with_unit_ends(5, 6);
        assert_eq!(Units::of(&a, 5, 6).ends(), Some([0, 5]));
        let (a, _) = with_unit_ends(3, 4);
        assert_eq!(Units::of(&a, 3, 4).ends(), Some([0, 3]));
        // Two rows: nothing between them.
        let (a, _) = with_unit_ends(2, 4);
        assert_eq!(Units::of(&a, 2, 4).ends(), None);
        // One end only; a 1 beside a non-zero; a dense map.
        let (mut a, _) = with_unit_ends(5, 6);
        a[29] = 0.5;
        assert_eq!(Units::of(&a, 5, 6).ends(), None);
        let (mut a, _) = with_unit_ends(5, 6);
        a[2] = 1e-300;
        assert_eq!(Units::of(&a, 5, 6).ends(), None);
        let (a, _) = map(5, 6);
        assert_eq!(Units::of(&a, 5, 6).ends(), None);
        // The operators: `operator::tests` (this module may not import `operator`).
    }

    #[test]
    fn unit_end_rows_are_copies_with_the_chains_bits() {
        // The copies give the fused chain's bits for finite inputs, `-0` included (the
        // chain makes it `+0`); on both sides of the wide instance's limit.
        if !available() {
            return;
        }
        for (rows, cols) in [(3, 4), (4, 5), (5, 6), (6, 11), (8, 9), (9, 11), (11, 21)] {
            let (a, map) = with_unit_ends(rows, cols);
            for curves in [4, 5, 7, 31, 100] {
                let mut input = input(curves, cols);
                for c in (0..curves).step_by(3) {
                    input[c * cols * 3] = -0.0;
                    input[((c + 1) * cols - 1) * 3 + 2] = -0.0;
                }
                let mut out = vec![f64::NAN; curves * rows * 3];
                assert!(map.apply_checked(&input, 3, &mut out));
                let want = fused(&a, rows, cols, &input);
                for (idx, (g, w)) in out.iter().zip(&want).enumerate() {
                    assert_eq!(g.to_bits(), w.to_bits(), "{rows}x{cols}, {curves}, {idx}");
                }
            }
        }
    }

    #[test]
    fn a_non_finite_end_point_is_still_seen() {
        // The end rows are copies; the rows between still sum every point, so a NaN or
        // infinity at an end point reaches them and the check.
        let (_, map) = with_unit_ends(5, 6);
        let curves = 10;
        for bad in [f64::NAN, f64::INFINITY] {
            for at in [0, 5] {
                let mut inp = input(curves, 6);
                inp[(4 * 6 + at) * 3 + 1] = bad;
                let mut out = vec![0.0; curves * 5 * 3];
                assert!(!map.apply_checked(&inp, 3, &mut out));
                for i in 1..4 {
                    assert!(!out[(4 * 5 + i) * 3 + 1].is_finite());
                }
            }
        }
    }

    #[test]
    fn the_kernel_does_whole_groups_and_leaves_the_last_curve() {
        if !available() {
            return;
        }
        let (_, map) = map(4, 5);
        let table = splat(map.transposed().0);
        for (curves, done) in [(1, 0), (3, 0), (4, 3), (6, 3), (7, 6), (100, 99)] {
            let input = input(curves, 5);
            let mut out = vec![0.0; curves * 12];
            assert_eq!(
                apply3(&table, &Units::none(), 4, &input, &mut out),
                Some((done, true))
            );
        }
    }

    #[test]
    fn non_finite_values_stay_in_their_curve_and_coordinate() {
        // A zero coefficient column: the NaN or infinity reaches every output of its
        // coordinate in its curve (dense sums), and nothing else.
        if !available() {
            return;
        }
        for (rows, cols) in [(4, 5), (5, 6), (11, 21)] {
            let (mut a, _) = map(rows, cols);
            for i in 0..rows {
                a[i * cols + 1] = 0.0;
            }
            let map = LinearMap::new(rows, cols, a.clone());
            let curves = 10;
            for bad_curve in [0, 4, 8, 9] {
                for k in 0..3 {
                    for bad in [f64::NAN, f64::INFINITY] {
                        let mut inp = input(curves, cols);
                        inp[(bad_curve * cols + 1) * 3 + k] = bad;
                        let mut out = vec![0.0; curves * rows * 3];
                        assert!(!map.apply_checked(&inp, 3, &mut out));
                        let want = fused(&a, rows, cols, &inp);
                        for (idx, (g, w)) in out.iter().zip(&want).enumerate() {
                            let (c, kk) = (idx / (rows * 3), idx % 3);
                            assert_eq!(!g.is_finite(), c == bad_curve && kk == k, "{idx}");
                            assert!(g.to_bits() == w.to_bits() || (g.is_nan() && w.is_nan()));
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn an_overflowing_check_sum_is_not_a_non_finite_output() {
        // Every output near the largest double: their sum overflows, the outputs do not;
        // and an output that overflows is reported.
        if !available() {
            return;
        }
        let (rows, cols) = (4, 5);
        let mut a = vec![0.0; rows * cols];
        for i in 0..rows {
            a[i * cols + i] = 1.0;
        }
        let map = LinearMap::new(rows, cols, a);
        let curves = 50;
        let mut inp = vec![f64::MAX / 2.0; curves * cols * 3];
        let mut out = vec![0.0; curves * rows * 3];
        assert!(map.apply_checked(&inp, 3, &mut out));
        assert!(out.iter().all(|&v| v == f64::MAX / 2.0));
        let mut a2 = vec![0.0; rows * cols];
        a2[0] = 3.0;
        let map2 = LinearMap::new(rows, cols, a2);
        inp[(7 * cols) * 3 + 2] = f64::MAX;
        assert!(!map2.apply_checked(&inp, 3, &mut out));
        assert!(out[7 * rows * 3 + 2].is_infinite());
    }
}
