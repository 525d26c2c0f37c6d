//! The options every reduction of the C ABI takes: `CagdReduceOptions` and the codes of its
//! fields (`options/`), their translation to the B-spline options (`strategy.rs`), and the
//! reductions of Bézier curves (`curve.rs`: `cagd_curve_reduce`, batch; `extra.rs`: exact
//! degree, G1 optimal, operator; `tolerance.rs`: to a tolerance). The other objects' reductions
//! live with their handles: `bspline/reduce.rs`, `bspline/surface.rs`, `patch/reduce.rs`.

mod curve;
mod extra;
mod options;
mod strategy;
mod tolerance;

pub use curve::{cagd_curve_reduce, cagd_curve_reduce_batch};
pub use extra::{
    CAGD_EXACT_DEGREE_REL_TOL, cagd_curve_exact_degree, cagd_curve_reduce_exact,
    cagd_curve_reduce_g1_optimal, cagd_reduce_operator, cagd_report_method_params,
};
pub use options::{
    CagdErrorSpace, CagdMerge, CagdPatchConstraint, CagdPatchMethod, CagdReduceMethod,
    CagdReduceOptions, CagdSplineStrategy, cagd_reduce_options_init,
};
pub use tolerance::{cagd_curve_reduce_to_tolerance, cagd_curve_reduce_to_tolerance_stepwise};

pub(crate) use options::read_options;
pub(crate) use strategy::{spline_options, surface_fit_options};
