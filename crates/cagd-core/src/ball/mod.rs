//! Wang–Said generalized Ball (WSGB) curves of seed 003 (SPEC-reduce §9): the curve type,
//! its fast evaluation by peeling, exact conversion to and from Bézier form, degree
//! elevation, the leading coefficient, the exact degeneracy test and the exact inverse
//! elevation. The degree reductions are in `cagd-reduce`.
//!
//! ## Supported range and accuracy
//!
//! Degrees `0..=64`, every order `0 <= L <= max(floor(n/2) - 1, 0)`, any dimension;
//! polynomial curves only (seed 003 has no rational ones). Conversions, elevation, the
//! leading coefficient and the inverse elevation are exact (rationals, the `f64` input
//! taken exactly), rounded once at the end. Measured by the tests (n <= 30, every L):
//! Bézier -> WSGB -> Bézier within `1e-13` of the larger coordinate of the two forms;
//! WSGB -> Bézier -> WSGB the same curve within `1e-13` relative (the WSGB points
//! themselves move by the rounding of the Bézier points times the conditioning of
//! Bézier -> WSGB, tabulated in the docs of [`crate::Basis`]). Evaluation by peeling
//! ([`WsgbCurve::eval_into`]) agrees with de Casteljau on the exact Bézier form within
//! `1e-12` relative (n <= 24) and is faster: 3.2x at n = 5, 5.9x at n = 10, 12.7x at
//! n = 20 (3-D, 25 / 38 / 68 ns per point, release build, `cargo bench -p cagd-reduce
//! --bench wsgb`).

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
