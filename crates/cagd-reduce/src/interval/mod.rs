//! Interval triangular Bernstein–Bézier patches and their degree reduction by linear
//! programming (seed 004, reconstructed in SPEC-convert part I).
//!
//! - [`IntervalTriPatch`]: control boxes `[lo, hi]` per coordinate, thickness, the interval
//!   surface at a point, interval elevation, certified containment.
//! - [`triangle_elevation_matrix`] / [`triangle_elevation_matrix_exact`]: `E_{m->n}`.
//! - [`reduce_interval_triangle`]: the LP of SPEC-convert I.2 (decoupled, coupled where
//!   needed), certified by exact arithmetic.
//! - [`reduce_interval_triangle_analytic`]: seed 004 §3's vertex enumeration (test oracle).

mod analytic;
mod basis;
mod certify;
mod elevation;
mod lp;
mod patch;
mod reduce;
mod report;
mod sample;
#[cfg(test)]
mod tests;

pub use analytic::{AnalyticOptimum, MAX_ANALYTIC_BASES, reduce_interval_triangle_analytic};
pub use elevation::{triangle_elevation_matrix, triangle_elevation_matrix_exact};
pub use patch::IntervalTriPatch;
pub use reduce::reduce_interval_triangle;
pub use report::{IntervalOptions, IntervalReduction, IntervalReport};

/// The largest degree (input, target or containment degree) of the interval routines:
/// cagd-core's [`cagd_core::MAX_DEGREE`] (the exact elevation coefficients are trinomials
/// `<= 3^64`, which fit `u128`). Above degree ~20 the LPs are slow (see
/// [`reduce_interval_triangle`]).
pub const MAX_INTERVAL_DEGREE: usize = cagd_core::MAX_DEGREE;

/// Most work of one [`reduce_interval_triangle`], in units of `rows x variables^2` of its
/// LPs summed over the coordinates: `tri_count(N) tri_count(m)^2 d` at most `2^23` (ADDED;
/// bounded work, issue 18). Measured 50-300 ns per unit with `microlp` (the dense
/// elevation rows make its sparse factorisations slow), so a second or two at the cap:
/// a 3-D 20 -> 10 (3.0e6 units, 0.2-0.4 s) is answered, a 1-D 58 -> 14 (2.5e7 units,
/// 7.3 s in the C ABI fuzz run) is refused with [`cagd_core::Error::ConditionNotMet`].
pub const MAX_INTERVAL_LP_WORK: usize = 1 << 23;

/// The default sampling grid `K` of [`IntervalOptions::sample_grid`] (1 035 points).
pub const DEFAULT_SAMPLE_GRID: usize = 44;
