//! Wang–Said generalized Ball (WSGB) curves of seed 003 (SPEC-reduce §9): the curve type,
//! its fast evaluation by peeling, exact conversion to and from Bézier form, degree
//! elevation, the leading coefficient, the exact degeneracy test and the exact inverse
//! elevation. The degree reductions are in `cagd-reduce`.

mod convert;
mod curve;
mod degeneracy;
mod elevate;
mod eval;
mod scalar;
#[cfg(test)]
mod tests;

pub use convert::{bezier_to_wsgb_exact, wsgb_to_bezier_exact};
pub use curve::{WsgbCurve, check_wsgb_order};
pub use degeneracy::{
    wsgb_inverse_elevation, wsgb_leading_coefficient, wsgb_lec_difference, wsgb_lec_factor,
    wsgb_reduced_order,
};
pub use elevate::wsgb_elevate_exact;
pub use scalar::{WsgbScalar, round_exact_points, to_exact_points};
