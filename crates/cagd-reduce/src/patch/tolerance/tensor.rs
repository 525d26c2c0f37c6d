//! Tensor-product patches reduced to a tolerance on a grid of `2^a x 2^b` equal cells
//! (seed 000 §14.3.1 per cell; the grid and its growth go beyond the seed).
//!
//! Each round reduces the cells in `u`-major order and stops at the first certified bound
//! over the tolerance; then one direction is bisected in every cell. A direction whose
//! degree is kept is never bisected (its error is zero: bisecting it gains nothing).
//! When both are reduced, the first cell over the tolerance is tried both ways: its two
//! halves in `u` and its two halves in `v` are reduced, and the direction whose worse half
//! has the smaller certified bound is bisected everywhere (ties: the less bisected
//! direction). A patch reduced in one direction only, or whose error lies mostly in one
//! direction, is so cut into strips instead of `4^L` squares (a `(1, 3) -> (1, 1)` patch
//! to `1e3` at coordinates `5e6` took `65 536` square pieces and 7 s; now `128` strips),
//! and the piece count grows by 2, not 4, per round.

use cagd_core::{Error, Result, TensorPatch, check_tolerance};

use super::measure::measure_tensor_pieces;
use super::{MAX_PATCH_TOLERANCE_WORK, MAX_TOLERANCE_PIECES, tensor_piece_cost};
use crate::patch::report::{PatchOptions, TensorPiece};
use crate::reduce_tensor;

/// The cells of one round: `2^a x 2^b` sub-patches, `u`-major (cell `(i, j)` at
/// `i 2^b + j`).
struct Grid {
    cells: Vec<TensorPatch>,
    /// `a`, `b`: bisections in `u`, `v`.
    splits: [u32; 2],
}

impl Grid {
    fn pieces_after_split(&self) -> usize {
        self.cells.len().saturating_mul(2)
    }

    /// The parameter interval of cell `k` in `u` and in `v` (exact dyadic values).
    fn domain(&self, k: usize) -> ((f64, f64), (f64, f64)) {
        let [a, b] = self.splits;
        let (i, j) = (k >> b, k & ((1usize << b) - 1));
        let span = |idx: usize, s: u32| {
            let h = 1.0 / (1u64 << s) as f64;
            (idx as f64 * h, (idx + 1) as f64 * h)
        };
        (span(i, a), span(j, b))
    }

    /// Every cell bisected in `u` (`dir = 0`) or `v` (`dir = 1`) by de Casteljau at `1/2`
    /// (shared edges stay bitwise equal).
    fn split(self, dir: usize) -> Result<Grid> {
        let [a, b] = self.splits;
        let cols = 1usize << b;
        let mut cells = Vec::with_capacity(self.cells.len() * 2);
        if dir == 0 {
            for row in self.cells.chunks(cols) {
                let halves = row
                    .iter()
                    .map(|c| c.subdivide_u(0.5))
                    .collect::<Result<Vec<_>>>()?;
                let (lo, hi): (Vec<_>, Vec<_>) = halves.into_iter().unzip();
                cells.extend(lo);
                cells.extend(hi);
            }
            Ok(Grid {
                cells,
                splits: [a + 1, b],
            })
        } else {
            for c in &self.cells {
                let (lo, hi) = c.subdivide_v(0.5)?;
                cells.push(lo);
                cells.push(hi);
            }
            Ok(Grid {
                cells,
                splits: [a, b + 1],
            })
        }
    }
}

/// Reduces `p` to degree `target` within `tol` (certified, Euclidean): rounds of a grid of
/// `2^a x 2^b` equal sub-patches (module docs), each cell reduced by [`crate::reduce_tensor`]
/// with `opts`; the first grid on which every certified bound is `<= tol` is returned,
/// pieces in `u`-major order with their sub-domains. At most [`MAX_TOLERANCE_PIECES`]
/// pieces. With `opts.measure` the pieces' `max_error` is measured within a node budget
/// (see [`super::PIECES_MEASURE_NODE_BUDGET`]).
///
/// C⁰: neighbouring sub-patches share bitwise-identical boundary rows (de Casteljau copies
/// them), and the boundary curves of a reduced piece depend only on the corresponding
/// boundary curve of the piece for [`crate::TensorMethod::Curves`] with end-interpolating
/// methods and for [`crate::TensorMethod::Perturb`] with
/// [`crate::PatchConstraint::Boundary`]: for these the reduced pieces coincide along
/// shared edges (bitwise). The other variants give pieces that are each within `tol` but
/// may show gaps up to `2 tol`.
///
/// # Errors
/// [`Error::BadTolerance`] (`tol` not finite and `> 0`), the errors of
/// [`crate::reduce_tensor`], [`Error::NoConvergence`] (with the bound reached) when
/// [`MAX_TOLERANCE_PIECES`] pieces are not enough or the next round would pass
/// [`super::MAX_PATCH_TOLERANCE_WORK`].
pub fn reduce_tensor_to_tolerance(
    p: &TensorPatch,
    target: (usize, usize),
    tol: f64,
    opts: &PatchOptions,
) -> Result<Vec<TensorPiece>> {
    check_tolerance(tol)?;
    let (m, n) = p.degrees();
    // A direction that keeps its degree has no error to shrink.
    let reduced = [target.0 < m, target.1 < n];
    // The rounds are searched without measuring; only the accepted pieces are measured.
    let search = PatchOptions {
        measure: false,
        ..*opts
    };
    let mut grid = Grid {
        cells: vec![p.clone()],
        splits: [0, 0],
    };
    let unit = tensor_piece_cost(p.degrees(), p.dim());
    let mut work = unit;
    loop {
        let mut pieces = Vec::with_capacity(grid.cells.len());
        let (mut worst, mut failed) = (0.0f64, None);
        for (k, cell) in grid.cells.iter().enumerate() {
            let reduction = reduce_tensor(cell, target, &search)?;
            worst = worst.max(reduction.report.error_bound);
            if worst > tol {
                failed = Some(cell);
                break;
            }
            let (u, v) = grid.domain(k);
            pieces.push(TensorPiece { u, v, reduction });
        }
        let Some(failed) = failed else {
            if opts.measure {
                measure_tensor_pieces(&grid.cells, &mut pieces)?;
            }
            return Ok(pieces);
        };
        // The next round: its cells, and the four halves of a direction trial.
        work = work.saturating_add((grid.pieces_after_split() + 4).saturating_mul(unit));
        if grid.pieces_after_split() > MAX_TOLERANCE_PIECES || work > MAX_PATCH_TOLERANCE_WORK {
            return Err(Error::NoConvergence {
                tolerance: tol,
                achieved: worst,
            });
        }
        let dir = match reduced {
            [true, false] => 0,
            [false, true] => 1,
            _ => {
                let [bu, bv] = [0, 1].map(|d| trial(failed, d, target, &search));
                match (bu?, bv?) {
                    (x, y) if x < y => 0,
                    (x, y) if y < x => 1,
                    _ => usize::from(grid.splits[1] < grid.splits[0]),
                }
            }
        };
        grid = grid.split(dir)?;
    }
}

/// The larger certified bound of the two halves of `cell` bisected in `u` (`dir = 0`) or
/// `v` (`dir = 1`).
fn trial(
    cell: &TensorPatch,
    dir: usize,
    target: (usize, usize),
    search: &PatchOptions,
) -> Result<f64> {
    let (a, b) = if dir == 0 {
        cell.subdivide_u(0.5)?
    } else {
        cell.subdivide_v(0.5)?
    };
    let bound = |h: &TensorPatch| reduce_tensor(h, target, search).map(|r| r.report.error_bound);
    Ok(bound(&a)?.max(bound(&b)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_domains_and_splits_are_u_major() {
        let p = TensorPatch::new((0..12).map(f64::from).collect(), 1, 1, 3).unwrap();
        let g = Grid {
            cells: vec![p.clone()],
            splits: [0, 0],
        };
        let g = g.split(1).unwrap().split(0).unwrap().split(1).unwrap();
        assert_eq!(g.splits, [1, 2]);
        assert_eq!(g.cells.len(), 8);
        for k in 0..8 {
            let ((u0, u1), (v0, v1)) = g.domain(k);
            assert_eq!(u1 - u0, 0.5);
            assert_eq!(v1 - v0, 0.25);
            // The cell is the patch on its sub-domain: compare the corner points.
            for (s, t) in [(0.0, 0.0), (1.0, 1.0), (0.5, 0.25)] {
                let a = g.cells[k].eval(s, t).unwrap();
                let b = p.eval(u0 + s * (u1 - u0), v0 + t * (v1 - v0)).unwrap();
                let d = a
                    .iter()
                    .zip(&b)
                    .map(|(x, y)| (x - y).abs())
                    .fold(0.0, f64::max);
                assert!(d < 1e-13, "cell {k}: {d}");
            }
        }
    }
}
