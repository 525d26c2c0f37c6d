//! # cagd-convert
//!
//! Representation conversions of seed 002 (chapter 15.1–15.7) as corrected by
//! SPEC-convert: NURBS spans ↔ rational Bézier segments (closed forms §15.1–15.3 and the
//! general route of any degree), triangular ↔ rectangular patches (§15.4–15.5), and exact
//! subdivision of a patch along a line or a polynomial curve (§15.6–15.7).
//!
//! Every rational formula is applied as a linear map on homogeneous points `(w r, w)`
//! (SPEC-convert §0), divided at the end.
#![forbid(unsafe_code)]

mod patch;

pub use patch::{
    PatchPiece, PatchSurface, PieceDomain, TensorSurface, TriSplitPoints, TriSurface, TrimChain,
    TrimDirection, TrimKeep, TrimSegment, corner_triangle, curve_split_d5, curve_split_d7,
    degenerate_rect_to_triangle, degenerate_residual, max_piece_difference,
    rect_to_two_triangle_pieces, rect_to_two_triangles, ruled_subpatch, split_along_curve,
    split_along_line, trapezoid, triangle_to_degenerate_rect, triangle_to_quad,
    triangle_to_rect_d1, triangle_to_three_rects, trim_to_patches,
};
