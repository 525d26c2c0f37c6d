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
//! Bounded work (ADDED): at most [`MAX_TOLERANCE_PIECES`] pieces; a round stops at its
//! first piece over the tolerance, so the rounds before the accepted one cost at most about
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
