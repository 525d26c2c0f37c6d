//! Degree reduction of B-spline / NURBS surfaces: patch by patch (`patchwise/`), patch-wise
//! with uniform knot refinement to a tolerance (`tolerance.rs`), and the global fit of the
//! curves applied direction by direction (`fit/`).

mod fit;
mod patchwise;
mod tolerance;

pub use fit::{SurfaceFitOptions, SurfaceFitReduction, reduce_bspline_surface_fit};
pub use patchwise::{SurfaceOptions, SurfaceReduction, reduce_bspline_surface};
pub use tolerance::{MAX_SURFACE_LEVEL, MAX_SURFACE_PATCHES, reduce_bspline_surface_to_tolerance};
