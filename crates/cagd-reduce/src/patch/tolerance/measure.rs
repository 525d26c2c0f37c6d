//! The measured errors (`max_error`) of the pieces of a patch reduction to a tolerance, in
//! bounded work (ADDED, beyond the seed; the patch analogue of
//! [`crate::surface_max_deviation`]).
//!
//! Pass 1 samples every piece's error surface `E(Q) - P` (its `perturbation`, the
//! difference at the source degree, already computed by the reducer) on a grid by cached
//! Bernstein bases ([`tensor_patch_grid`] / [`tri_patch_grid`]), at the density of
//! [`tensor_patch_distance`] / [`tri_patch_distance`] when all pieces fit in
//! [`PIECES_MEASURE_NODE_BUDGET`] nodes, coarser otherwise (at least 4 intervals per side).
//! Pass 2 maximises the [`PIECES_MEASURED_FULLY`] pieces of largest sampled error in full
//! (those distances: boundary edges by Brent, interior maxima by pattern search). So the
//! largest `max_error` over the pieces is a local maximum like a single patch's; the
//! `max_error` of another piece is the largest sampled value of its error (a lower
//! estimate, never above the true maximum, hence never above the certified bound). Before,
//! every accepted piece was maximised in full: 16 384 pieces took 8 s.

use cagd_core::{
    Result, TensorPatch, TriPatch, tensor_patch_distance, tensor_patch_grid, tri_patch_distance,
    tri_patch_grid,
};

use crate::patch::report::{TensorPiece, TriPiece};

/// Grid nodes sampled over all pieces in pass 1: `2^22`, about a tenth of a second
/// (ADDED, beyond the seeds: bounded measuring of a patch reduction, issue 18).
pub const PIECES_MEASURE_NODE_BUDGET: usize = 1 << 22;

/// Pieces of largest sampled error maximised in full in pass 2 (ADDED, beyond the seeds,
/// as [`PIECES_MEASURE_NODE_BUDGET`]).
pub const PIECES_MEASURED_FULLY: usize = 16;

/// Intervals per side of the pass-1 grid: `full`, or fewer (at least 4) when `pieces` grids
/// of that size would exceed [`PIECES_MEASURE_NODE_BUDGET`].
fn coarse_side(full: usize, pieces: usize) -> usize {
    let per_piece = PIECES_MEASURE_NODE_BUDGET / pieces.max(1);
    full.min(per_piece.isqrt().saturating_sub(1)).max(4)
}

/// The largest Euclidean norm of the `dim`-vectors of `grid` (0 for none).
fn largest(grid: &[f64], dim: usize) -> f64 {
    grid.chunks_exact(dim)
        .map(|x| x.iter().map(|c| c * c).sum::<f64>())
        .fold(0.0f64, f64::max)
        .sqrt()
}

/// Sets `max_error` of the `pieces` (the reductions of the sources, index for index) by the
/// two passes of the module docs: `sampled(piece, side)` is a piece's largest error on a
/// grid of `side` intervals, `full(piece, k)` its full measurement against source `k`.
fn two_passes<P>(
    pieces: &mut [P],
    full_side: usize,
    sampled: impl Fn(&P, usize) -> Result<f64>,
    full: impl Fn(&P, usize) -> Result<f64>,
    max_error: impl Fn(&mut P) -> &mut Option<f64>,
) -> Result<()> {
    let side = coarse_side(full_side, pieces.len());
    let mut ranked = Vec::with_capacity(pieces.len());
    for (k, piece) in pieces.iter_mut().enumerate() {
        let top = sampled(piece, side)?;
        *max_error(piece) = Some(top);
        ranked.push((top, k));
    }
    ranked.sort_by(|x, y| y.0.total_cmp(&x.0));
    for &(top, k) in ranked.iter().take(PIECES_MEASURED_FULLY) {
        let d = full(&pieces[k], k)?;
        *max_error(&mut pieces[k]) = Some(d.max(top));
    }
    Ok(())
}

/// Measures the tensor `pieces`, the reductions of the cells `sources` (same order).
pub(super) fn measure_tensor_pieces(
    sources: &[TensorPatch],
    pieces: &mut [TensorPiece],
) -> Result<()> {
    let Some(first) = sources.first() else {
        return Ok(());
    };
    let ((m, n), dim) = (first.degrees(), first.dim());
    two_passes(
        pieces,
        4 * (m + n) + 32,
        |piece, side| {
            let diff = TensorPatch::new(piece.reduction.perturbation.clone(), m, n, dim)?;
            Ok(largest(&tensor_patch_grid(&diff, side), dim))
        },
        |piece, k| tensor_patch_distance(&sources[k], &piece.reduction.patch),
        |piece| &mut piece.reduction.report.max_error,
    )
}

/// Measures the triangular `pieces`, the reductions of the sub-triangles `sources` (same
/// order).
pub(super) fn measure_tri_pieces(sources: &[TriPatch], pieces: &mut [TriPiece]) -> Result<()> {
    let Some(first) = sources.first() else {
        return Ok(());
    };
    let (n, dim) = (first.degree(), first.dim());
    two_passes(
        pieces,
        8 * n + 32,
        |piece, side| {
            let diff = TriPatch::new(piece.reduction.perturbation.clone(), n, dim)?;
            Ok(largest(&tri_patch_grid(&diff, side), dim))
        },
        |piece, k| tri_patch_distance(&sources[k], &piece.reduction.patch),
        |piece| &mut piece.reduction.report.max_error,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coarse_side_keeps_the_budget() {
        assert_eq!(coarse_side(56, 1), 56);
        assert_eq!(coarse_side(56, 1000), 56);
        // 16 384 pieces: 256 nodes each, a 16 x 16 grid (15 intervals).
        assert_eq!(coarse_side(56, 16_384), 15);
        assert_eq!(coarse_side(56, 1 << 16), 7);
        assert_eq!(coarse_side(56, 1 << 30), 4);
        for pieces in [1, 17, 300, 5000, 65_536] {
            let side = coarse_side(56, pieces);
            assert!(side == 4 || pieces * (side + 1) * (side + 1) <= PIECES_MEASURE_NODE_BUDGET);
        }
    }
}
