//! `cagd_reduce_options_init`: the entry point that fills a `CagdReduceOptions` with its
//! defaults (the struct and its codes are in `options/`).

use crate::boundary::{boundary, out_ref};
use crate::options::CagdReduceOptions;
use crate::status::CagdStatus;

/// Fills `opts` with the defaults: `struct_size = sizeof(CagdReduceOptions)`,
/// `method = CAGD_METHOD_L2`, `target = 3`, `r = p = 0` (end points interpolated),
/// `l1 = l2 = 0`, `measure = false`, `space = CAGD_SPACE_EUCLIDEAN`, `tolerance = 0`
/// (must be set before a reduction to a tolerance), `continuity = 0`, `max_depth = 30`,
/// `target_v = 3`, `patch_method = CAGD_PATCH_PERTURB`, `constraint = CAGD_CONSTRAINT_NONE`,
/// `merge = CAGD_MERGE_EXACT`, `spline_strategy = CAGD_SPLINE_FIT`, `spline_continuity = -1`
/// (all the continuity the input has, up to the strategy's maximum).
/// Call it before setting fields, so that `struct_size` is right and fields added in later
/// versions get their defaults.
///
/// Parameters:
/// - `opts` (out): the struct to fill (caller-owned, e.g. on the stack).
///
/// Returns:
/// - `CAGD_OK`: `*opts` holds the defaults.
/// - `CAGD_ERR_NULL_POINTER`: `opts` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `opts` is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `opts` must be NULL or point to a writable `CagdReduceOptions`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_reduce_options_init(opts: *mut CagdReduceOptions) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        *unsafe { out_ref(opts, "opts") }? = CagdReduceOptions::default();
        Ok(())
    })
}
