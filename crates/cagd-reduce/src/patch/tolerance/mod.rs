//! Patch reduction to a tolerance (seed 000 §14.3, Theorem 14.3.1 for triangles,
//! SPEC-reduce §5): the patch is subdivided until every piece reduces within `δ`
//! (certified), with bounded work.
//!
//! * `tensor.rs`: tensor-product patches on a `2^a x 2^b` grid of equal cells, one
//!   direction split per round, the one whose part of the bound dominates (beyond the
//!   seed: a direction that is not reduced, or whose error is already small, is not split
//!   for nothing);
//! * `triangle.rs`: triangular patches by 4-way midpoint subdivision (Theorem 14.3.1);
//! * `measure.rs`: the measured errors of the accepted pieces within a node budget.
//!
//! Every subdivision is uniform (all cells of one size), so neighbouring pieces share whole
//! edges, never T-junctions; with a boundary-consistent method the reduced pieces meet C⁰.
//!
//! Bounded work (ADDED): at most [`MAX_TOLERANCE_PIECES`] pieces and
//! [`MAX_PATCH_TOLERANCE_WORK`] units of work priced by degree (a round that would pass it
//! is not started); a round stops at its first piece over the tolerance, so the rounds before the accepted one cost at most about
//! as much as the accepted one; the accepted pieces are measured within
//! [`PIECES_MEASURE_NODE_BUDGET`] grid nodes with the [`PIECES_MEASURED_FULLY`] of largest
//! sampled error maximised in full.

mod measure;
mod tensor;
mod triangle;

pub use measure::{PIECES_MEASURE_NODE_BUDGET, PIECES_MEASURED_FULLY};
pub use tensor::reduce_tensor_to_tolerance;
pub use triangle::reduce_triangle_to_tolerance;

/// The deepest level of the triangle subdivision (`4^8 = 65 536` pieces); tensor patches
/// stop at the same number of pieces ([`MAX_TOLERANCE_PIECES`]).
pub const MAX_SUBDIVISION_LEVEL: usize = 8;

/// The most pieces a reduction to a tolerance returns: `4^8 = 65 536` (ADDED; bounded
/// work). A tolerance that needs more is refused with [`cagd_core::Error::NoConvergence`]
/// (the tolerance and the bound reached).
pub const MAX_TOLERANCE_PIECES: usize = 1 << (2 * MAX_SUBDIVISION_LEVEL);

/// Most work of one patch reduction to a tolerance, summed over its rounds (ADDED; bounded
/// work, issue 18): `2^27` units, a tensor cell of degrees `(p, q)` in `d` coordinates
/// counted `d (p + 1)(q + 1)(p + q + 2)`, a degree-`n` triangular piece
/// `d ((n + 1)(n + 2)^2 / 2 + (n + 1)^4 / 12)` (measured 3-11 ns per unit in a release
/// build, so well under a second of a round's reductions and subdivisions). A round that
/// would pass it is not started: the reduction is refused with
/// [`cagd_core::Error::NoConvergence`] and the bound reached. At low degree the piece cap
/// comes first (`65 536` bicubic pieces are `2^24.6` units); a degree-36 triangle in 3-D
/// stops at level 3 instead of subdividing to level 8 for minutes.
pub const MAX_PATCH_TOLERANCE_WORK: usize = 1 << 27;

/// The work units of reducing one `(p, q)` tensor cell in `dim` coordinates and of
/// bisecting it: `dim (p + 1)(q + 1)(p + q + 2)` (its bound subdivides rows and columns).
pub(crate) fn tensor_piece_cost((p, q): (usize, usize), dim: usize) -> usize {
    dim.saturating_mul(p + 1)
        .saturating_mul(q + 1)
        .saturating_mul(p + q + 2)
}

/// The work units of one degree-`n` triangular piece in `dim` coordinates: its reduction
/// and bound, `dim (n + 1)(n + 2)(n + 2) / 2`, and its share of the midpoint split,
/// `dim (n + 1)^4 / 12` (the middle sub-triangle's blossoms).
pub(crate) fn tri_piece_cost(n: usize, dim: usize) -> usize {
    let tri = (n + 1) * (n + 2) / 2;
    let split = (n + 1).pow(4) / 12;
    dim.saturating_mul(tri * (n + 2) + split)
}
