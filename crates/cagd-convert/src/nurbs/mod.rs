//! NURBS ↔ rational Bézier (SPEC-convert §15.1–15.3): the closed forms of degree 2 and 3,
//! the separable biquadratic patch, and the general route of any degree for curves and
//! tensor surfaces, both ways; the standard form of a rational Bézier.

pub(crate) mod biquadratic;
pub(crate) mod cubic;
pub(crate) mod extract;
mod extract_kernel;
pub(crate) mod merge;
mod merge_blossom;
mod merge_joint;
mod merge_kernel;
pub(crate) mod outer_knots;
pub(crate) mod pieces;
pub(crate) mod quadratic;
pub(crate) mod span;
pub(crate) mod standard_form;
pub(crate) mod surface;
mod width;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_merge;
#[cfg(test)]
mod tests_outer_knots;
