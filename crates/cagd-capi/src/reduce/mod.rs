//! Every reduction of the C ABI and its options: `CagdReduceOptions` and the codes of its
//! fields (`options/`), their translation to the B-spline options (`strategy.rs`), and the entry
//! points by object: Bézier curves (`curve.rs`: `cagd_curve_reduce`, batch; `extra.rs`:
//! exact degree, G1 optimal, operator; `tolerance.rs`: to a tolerance), B-splines
//! (`bspline.rs`) and patches (`patch.rs`). `cagd_bsplinesurface_reduce*` live with their
//! handle in `bspline/surface.rs`.

mod bspline;
mod curve;
mod extra;
mod options;
mod patch;
mod strategy;
mod tolerance;

pub use bspline::{cagd_bspline_reduce, cagd_bspline_reduce_uniform};
pub use curve::{cagd_curve_reduce, cagd_curve_reduce_batch};
pub use extra::{
    CAGD_EXACT_DEGREE_REL_TOL, cagd_curve_exact_degree, cagd_curve_reduce_exact,
    cagd_curve_reduce_g1_optimal, cagd_reduce_operator, cagd_report_method_params,
};
pub use options::{
    CagdErrorSpace, CagdMerge, CagdPatchConstraint, CagdPatchMethod, CagdReduceMethod,
    CagdReduceOptions, CagdSplineStrategy, cagd_reduce_options_init,
};
pub use patch::{
    cagd_report_patch, cagd_tensorpatch_reduce, cagd_tensorpatch_reduce_to_tolerance,
    cagd_tripatch_reduce, cagd_tripatch_reduce_to_tolerance,
};
pub use tolerance::{cagd_curve_reduce_to_tolerance, cagd_curve_reduce_to_tolerance_stepwise};

pub(crate) use options::read_options;
pub(crate) use strategy::{spline_options, surface_fit_options};
