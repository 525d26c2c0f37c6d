//! What the two patch handles (`CagdTensorPatch` in `tensorpatch/`, `CagdTriPatch` in
//! `tripatch/`) share: their reductions (`reduce.rs`: `cagd_tensorpatch_reduce*`,
//! `cagd_tripatch_reduce*`, `cagd_report_patch`) and the piecewise results of the reductions
//! to a tolerance, `CagdTensorPatchList` and `CagdTriPatchList` (`list.rs`; their one-call
//! copies in `list_copy.rs`).

mod list;
mod list_copy;
mod reduce;

pub use list::{
    CagdTensorPatchList, CagdTriPatchList, cagd_tensorpatchlist_count, cagd_tensorpatchlist_free,
    cagd_tensorpatchlist_get, cagd_tripatchlist_count, cagd_tripatchlist_free,
    cagd_tripatchlist_get,
};
pub use list_copy::{CagdPatchListSizes, cagd_tensorpatchlist_copy, cagd_tripatchlist_copy};
pub use reduce::{
    cagd_report_patch, cagd_tensorpatch_reduce, cagd_tensorpatch_reduce_to_tolerance,
    cagd_tripatch_reduce, cagd_tripatch_reduce_to_tolerance,
};
