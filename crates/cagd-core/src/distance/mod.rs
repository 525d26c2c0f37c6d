//! Parametric distances `max ||a - b||` between two shapes of one kind: curves over `[0, 1]`
//! (`curve/`, with the 1-D maximiser the others build on) and patches over the unit square or
//! triangle (`patch/`).

mod curve;
mod patch;

pub use curve::{
    curve_distance, max_distance_1d, refine_sampled_maxima, refine_sampled_maxima_above,
};
pub use patch::{
    Domain2, MAX_REFINED_MAXIMA, max_distance_2d, max_distance_2d_with_grid, tensor_patch_distance,
    tensor_patch_grid, tri_patch_distance, tri_patch_grid,
};
