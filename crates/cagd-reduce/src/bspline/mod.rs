//! Degree reduction of B-spline / NURBS curves and surfaces (seed 001 and Piegl & Tiller).
//!
//! Curves to a tolerance, [`reduce_bspline`] (`reduce.rs`, its options and report in
//! `options.rs`), by one of three strategies: the global least-squares fit on the input's
//! knots (`global.rs` over `fit/`, default), per-segment Hermite reductions (`segments.rs`),
//! or Piegl & Tiller 1995 (`piegl_tiller/`); the knot bookkeeping they share (`knots.rs`:
//! certified per-span bounds, knot removal, merge, continuity orders) and the sampled error
//! (`measure.rs`). Uniform B-splines by seed 001's matrix product (`uniform/`). Surfaces
//! (`surface/`): patch-wise, to a tolerance, and by the global fit.

mod fit;
mod framed;
mod global;
mod grading;
mod knots;
mod measure;
mod options;
mod piegl_tiller;
mod reduce;
mod segments;
mod surface;
#[cfg(test)]
mod test_support;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_measure;
#[cfg(test)]
mod tests_straddle;
mod uniform;

pub use measure::{
    SPLINE_MEASURE_NODE_BUDGET, SPLINE_MEASURED_PIECES, SURFACE_MEASURE_NODE_BUDGET,
    SURFACE_MEASURED_CELLS, spline_max_deviation, surface_max_deviation,
};
pub use options::{BSplineOptions, BSplineReduction, BSplineReport, BSplineStrategy};
pub use piegl_tiller::reduce_bspline_piegl_tiller;
pub use reduce::reduce_bspline;
pub use segments::{MAX_GREEDY_REMOVAL_KNOTS, MAX_SEGMENT_REDUCTIONS};
pub use surface::{
    MAX_SURFACE_LEVEL, MAX_SURFACE_PATCHES, SurfaceFitOptions, SurfaceFitReduction, SurfaceOptions,
    SurfaceReduction, reduce_bspline_surface, reduce_bspline_surface_fit,
    reduce_bspline_surface_to_tolerance,
};
pub use uniform::{Merge, UniformReduction, reduce_uniform_bspline};

// For the rational -> polynomial conversion (`crate::rational_to_polynomial`).
pub(crate) use fit::{BandedLsq, SpanBound};
pub(crate) use knots::{LocalBounds, Raw, order_at};
