//! The `cagd_reduce_*` and `cagd_curve_reduce*` entry points: `cagd_reduce_options_init`
//! (`init.rs`; the options themselves are in `options/`) and the reductions of Bézier
//! curves (`curve.rs`: `cagd_curve_reduce`, batch; `extra.rs`: exact degree, G1 optimal,
//! operator; `tolerance.rs`: to a tolerance). The other objects' reductions live with their
//! handles: `bspline/reduce.rs`, `bspline/surface.rs`, `patch/reduce.rs`.

mod curve;
mod extra;
mod init;
mod tolerance;

pub use curve::{cagd_curve_reduce, cagd_curve_reduce_batch, cagd_curve_reduce_batch_bounded};
pub use extra::{
    CAGD_EXACT_DEGREE_REL_TOL, cagd_curve_exact_degree, cagd_curve_reduce_exact,
    cagd_curve_reduce_g1_optimal, cagd_reduce_operator, cagd_report_method_params,
};
pub use init::cagd_reduce_options_init;
pub use tolerance::{cagd_curve_reduce_to_tolerance, cagd_curve_reduce_to_tolerance_stepwise};
