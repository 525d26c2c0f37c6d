//! Bézier patches: tensor-product ([`TensorPatch`], `tensor/`) and triangular ([`TriPatch`],
//! `triangle/`, i-major point order), each with its evaluation, elevation and subdivision.

mod tensor;
mod triangle;

pub use tensor::TensorPatch;
pub use triangle::{TriPatch, tri_count, tri_index};
