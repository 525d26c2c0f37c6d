//! The patch handles of the C ABI: `CagdTensorPatch` (`tensor/`), `CagdTriPatch`
//! (`triangle/`), each with its operations, and the piecewise results of their reductions
//! to a tolerance, `CagdTensorPatchList` and `CagdTriPatchList` (`list.rs`).

mod list;
mod tensor;
mod triangle;

pub use list::{
    CagdTensorPatchList, CagdTriPatchList, cagd_tensorpatchlist_count, cagd_tensorpatchlist_free,
    cagd_tensorpatchlist_get, cagd_tripatchlist_count, cagd_tripatchlist_free,
    cagd_tripatchlist_get,
};
pub use tensor::{
    CagdTensorPatch, cagd_tensorpatch_elevate, cagd_tensorpatch_eval, cagd_tensorpatch_free,
    cagd_tensorpatch_new, cagd_tensorpatch_points, cagd_tensorpatch_shape,
    cagd_tensorpatch_subdivide_u, cagd_tensorpatch_subdivide_v,
};
pub use triangle::{
    CagdTriPatch, cagd_tripatch_elevate, cagd_tripatch_eval, cagd_tripatch_free, cagd_tripatch_new,
    cagd_tripatch_points, cagd_tripatch_shape, cagd_tripatch_subdivide_midpoint,
};
