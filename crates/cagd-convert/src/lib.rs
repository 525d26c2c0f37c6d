//! # cagd-convert
//!
//! Representation conversions of seed 002 (chapter 15.1–15.7) as corrected by
//! SPEC-convert: NURBS spans ↔ rational Bézier segments (closed forms §15.1–15.3 and the
//! general route of any degree), triangular ↔ rectangular patches (§15.4–15.5), and exact
//! subdivision of a patch along a line or a polynomial curve (§15.6–15.7).
//!
//! Every rational formula is applied as a linear map on homogeneous points `(w r, w)`
//! (SPEC-convert §0), divided at the end.
//!
//! NURBS ↔ rational Bézier (SPEC-convert §15.1–15.3):
//! - closed forms: [`quadratic_span_to_bezier`] / [`bezier_to_quadratic_span`] (§15.1),
//!   [`cubic_span_to_bezier`] / [`bezier_to_cubic_span`] (§15.3), the biquadratic patch with
//!   separable weights [`biquadratic_separable_to_bezier`] /
//!   [`bezier_to_biquadratic_separable`] and with any weights [`biquadratic_to_bezier`] /
//!   [`bezier_to_biquadratic`] (§15.2); an inverse whose condition (15.1.8, 15.2.11–12,
//!   15.3.13–16) fails is [`cagd_core::Error::ConversionCondition`] naming the weight;
//! - the general route of any degree: [`to_bezier_pieces`] (curve → [`BezierPieces`], Böhm
//!   insertion in place), [`pieces_to_nurbs`] (pieces → one curve with the continuity the
//!   pieces have), [`span_to_bezier`] (one span), and for surfaces
//!   [`surface_to_bezier_patches`] / [`patches_to_nurbs`];
//! - [`standard_form`]: the Möbius reparametrisation with end weights 1.
#![forbid(unsafe_code)]

mod nurbs;
mod patch;

pub use patch::{
    PatchPiece, PatchSurface, PieceDomain, TensorSurface, TriSplitPoints, TriSurface, TrimChain,
    TrimDirection, TrimKeep, TrimSegment, corner_triangle, curve_split_d5, curve_split_d7,
    degenerate_rect_to_triangle, degenerate_residual, max_piece_difference,
    rect_to_two_triangle_pieces, rect_to_two_triangles, ruled_subpatch, split_along_curve,
    split_along_line, trapezoid, triangle_to_degenerate_rect, triangle_to_quad,
    triangle_to_rect_d1, triangle_to_three_rects, trim_to_patches,
};

pub use nurbs::biquadratic::{
    SeparablePatch, bezier_to_biquadratic, bezier_to_biquadratic_separable,
    biquadratic_separable_to_bezier, biquadratic_to_bezier, separable_factors,
};
pub use nurbs::cubic::{bezier_to_cubic_span, cubic_span_to_bezier};
pub use nurbs::extract::{span_to_bezier, to_bezier_pieces, to_bezier_pieces_into};
pub use nurbs::merge::{DEFAULT_REL_TOL, NurbsFromPieces, pieces_to_nurbs};
pub use nurbs::outer_knots::OuterKnots;
pub use nurbs::pieces::BezierPieces;
pub use nurbs::quadratic::{bezier_to_quadratic_span, quadratic_span_to_bezier};
pub use nurbs::span::NurbsSpan;
pub use nurbs::standard_form::{StandardForm, standard_form};
pub use nurbs::surface::{SurfaceFromPatches, patches_to_nurbs, surface_to_bezier_patches};
