//! Patch conversions of SPEC-convert §15.4–15.7 through the C ABI: triangular ↔
//! rectangular patches, exact subdivision along a line, a polynomial curve or a trimming
//! chain. Handles (plus optional weights) in, a `CagdPatchPieceList` out.

mod list;
mod rectangle;
mod triangle;

pub(crate) use list::CPiece;
pub use list::{
    CAGD_DOMAIN_BILINEAR, CAGD_DOMAIN_DEGENERATE_RECT, CAGD_DOMAIN_RULED, CAGD_DOMAIN_TRIANGLE,
    CAGD_PIECE_TENSOR, CAGD_PIECE_TRIANGLE, CagdPatchPieceList, cagd_patchpiecelist_count,
    cagd_patchpiecelist_domain, cagd_patchpiecelist_free, cagd_patchpiecelist_info,
    cagd_patchpiecelist_points, cagd_patchpiecelist_weights,
};
pub use rectangle::{
    CAGD_TRIM_KEEP_ABOVE, CAGD_TRIM_KEEP_BELOW, CAGD_TRIM_U_OF_V, CAGD_TRIM_V_OF_U,
    cagd_tensorpatch_split_curve, cagd_tensorpatch_split_line, cagd_tensorpatch_to_triangles,
    cagd_tensorpatch_trim,
};
pub use triangle::{
    cagd_tensorpatch_to_triangle, cagd_tripatch_to_quad, cagd_tripatch_to_rect,
    cagd_tripatch_to_three_rects,
};
