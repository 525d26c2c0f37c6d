//! Triangular ↔ rectangular patches and exact subdivision of a patch along a line or a
//! polynomial curve (seed 002 §15.4–15.7 as corrected by SPEC-convert).
//!
//! Every algorithm is a linear map on control points, so rational patches go through their
//! homogeneous points `(w r, w)` (SPEC-convert §0) and are divided at the end. Every output
//! piece carries the part of the input's `(u, v)` domain it covers ([`PieceDomain`]).

mod blossom;
mod degenerate;
mod domain;
mod measure;
mod quadrilateral;
mod ruled;
mod split_curve;
mod split_line;
mod surface;
mod trim;
mod two_triangles;

#[cfg(test)]
mod tests;

pub use degenerate::{
    degenerate_rect_to_triangle, degenerate_residual, triangle_to_degenerate_rect,
};
pub use domain::{PatchPiece, PieceDomain};
pub use measure::max_piece_difference;
pub use quadrilateral::{
    TriSplitPoints, triangle_to_quad, triangle_to_rect_d1, triangle_to_three_rects,
};
pub use ruled::ruled_subpatch;
pub use split_curve::{curve_split_d5, curve_split_d7, split_along_curve};
pub use split_line::{corner_triangle, split_along_line, trapezoid};
pub use surface::{PatchSurface, TensorSurface, TriSurface};
pub use trim::{TrimChain, TrimDirection, TrimKeep, TrimSegment, trim_to_patches};
pub use two_triangles::{rect_to_two_triangle_pieces, rect_to_two_triangles};
