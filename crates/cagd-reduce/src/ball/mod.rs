//! Degree reduction of Wang–Said generalized Ball (WSGB) curves (seed 003, SPEC-reduce §9):
//! the perturbation method (§9.4), the best uniform approximation (§9.5), every Bézier
//! reducer through the exact conversion, and reduction to a tolerance with subdivision.
//!
//! Every reduction ([`reduce_wsgb`]) returns the WSGB(m, L') curve,
//! `L' = min(L, max(floor(m/2) - 1, 0))`, with a certified bound of the Euclidean distance
//! `max_u ||r(u) - q(u)||` (closed forms of SPEC-reduce §9.4 / §9.5 per step, summed over
//! the steps, plus a rounding allowance; the Bézier reducer's bound plus the conversions'
//! rounding) and the measured distance; the seed's per-coordinate figures (bound (11),
//! formula (12), the exact max-abs error) are separate, named fields of [`WsgbStep`].
//!
//! ## Supported range, accuracy and cost
//!
//! Degrees up to 64, every order, any dimension; the perturbation method needs `n >= 2`
//! at every step (target `m >= 1`). The exact routes ([`wsgb_perturbation_step`],
//! [`wsgb_uniform_step_exact`] on `BigRational`) reproduce the spec's `Q_exact`; the `f64`
//! results equal them to a few ulp. Measured by the tests (n <= 30, every L): measured error
//! <= certified bound; the uniform error equals `||lec|| / 2^(2n-1)` within `1e-12` relative
//! (above the floor `8 eps max |p_i|` of the rounded points), the perturbation error its
//! closed form; an elevated curve reduces back exactly. Release build, 3-D, one degree,
//! measurement off (`cargo bench -p cagd-reduce --bench wsgb`): perturbation 0.44 / 0.35 /
//! 0.45 µs per curve at n = 5 / 10 / 20, uniform 0.31 / 0.44 / 0.56 µs; the L2 method
//! through the exact Bézier conversion 0.35 / 0.64 / 6.9 ms (the exact rational conversions
//! dominate).
//!
//! ## The paper's example (SPEC-reduce §9.6)
//!
//! Reproduced exactly (tests `paper_example_*`): the reduced points of the perturbation
//! method for r(u;7,1) and r(u;6,0) (the degree-6 curve needs the erratum `p_0 = (200,130)`,
//! printed (220,130)); the printed perturbation "errors" 17.813 / 34.375 / 20.625, which are
//! the loose bound (11) in the max-abs norm ([`WsgbStep::paper_bound_11`]; the true errors
//! are 2.1199 / 5.7292 / 3.4375, [`WsgbStep::error_inf`]); the uniform errors 0.139 / 0.537 /
//! 0.322 (formula (12), equal to the measured maximum); the relative errors (error / largest
//! coordinate range of the control points, 330 resp. 270); the end points and the middle
//! point of the uniform reductions.
//!
//! NOT reproduced, because the printed values are wrong: the interior points of the
//! uniform reductions of r(u;7,1) and r(u;6,1). Evaluated as WSGB curves they deviate from
//! the original by 0.723 and 17.16 (max-abs norm), not the stated 0.139 and 0.322; the
//! printed degree-7 `Q2`, `Q4` are what one gets with `beta_1` taken as the Wang function
//! `2u(1-u)^3` (not a partition of unity). Ours deviate by exactly 0.139160 and 0.322266.

mod measure;
mod perturbation;
mod reduce;
mod report;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_fuzz;
#[cfg(test)]
mod tests_paper;
mod tolerance;
mod uniform;
mod via_bezier;

pub use measure::wsgb_sampled_error_inf;
pub use perturbation::{
    wsgb_paper_bound_11, wsgb_perturbation_error_factor, wsgb_perturbation_step,
    wsgb_perturbed_points,
};
pub use reduce::{reduce_wsgb, reduce_wsgb_with};
pub use report::{WsgbMethod, WsgbReduction, WsgbReport, WsgbStep};
pub use tolerance::{
    MAX_WSGB_PIECES, WSGB_MEASURED_PIECES, WsgbPiece, WsgbPiecewise, reduce_wsgb_to_tolerance,
};
pub use uniform::{wsgb_chebyshev_coefficients, wsgb_uniform_points, wsgb_uniform_step_exact};
pub use via_bezier::reduce_wsgb_via_bezier;

/// Degree of a flat buffer of `len` values of `dim` coordinates.
fn degree_of(len: usize, dim: usize) -> cagd_core::Result<usize> {
    if dim == 0 {
        return Err(cagd_core::Error::ZeroDimension);
    }
    if len == 0 || len % dim != 0 {
        return Err(cagd_core::Error::LengthMismatch {
            what: "WSGB points (length must be a positive multiple of dim)",
            got: len,
            expected: (len / dim).max(1) * dim,
        });
    }
    Ok(len / dim - 1)
}
