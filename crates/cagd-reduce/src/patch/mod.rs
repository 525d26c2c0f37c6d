//! Degree reduction of Bézier patches (seed 000 §14.3): tensor-product patches (`tensor/`:
//! the perturbation method of §14.3.1 and direction-by-direction curve reduction),
//! triangular patches (`triangle/`: the perturbation method of §14.3.2 and the L2-optimal
//! reduction), reduction to a tolerance by uniform subdivision in bounded work (`tolerance/`), the shared
//! options and reports (`report.rs`) and exact helpers (`exact.rs`).

mod exact;
mod report;
mod tensor;
mod tolerance;
mod triangle;

pub use report::{
    PatchConstraint, PatchOptions, PatchReduction, PatchReport, TensorMethod, TensorPiece,
    TriMethod, TriOptions, TriPiece, TriReduction,
};
pub use tensor::reduce_tensor;
pub use tolerance::{
    MAX_PATCH_TOLERANCE_WORK, MAX_SUBDIVISION_LEVEL, MAX_TOLERANCE_PIECES,
    PIECES_MEASURE_NODE_BUDGET, PIECES_MEASURED_FULLY, reduce_tensor_to_tolerance,
    reduce_triangle_to_tolerance,
};
pub use triangle::{reduce_triangle, tri_perturbation_matrix};
