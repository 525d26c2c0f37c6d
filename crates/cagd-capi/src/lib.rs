//! # cagd-capi
//!
//! The C ABI of cagd (DESIGN.md, "C ABI conventions"; STYLE §9.4–9.10). The header
//! `include/cagd.h` is generated from this crate by cbindgen, committed, and checked fresh by
//! the test `header_is_fresh` (`CAGD_BLESS=1 cargo test -p cagd-capi --test header`
//! rewrites it).
//!
//! Conventions, in short:
//! - functions are `cagd_<noun>_<verb>`, return a `CagdStatus` (`CAGD_OK = 0`) and write
//!   results through out-pointers, which are written only on `CAGD_OK` (except
//!   `*out_needed`, also written on `CAGD_ERR_BUFFER_TOO_SMALL`);
//! - objects are opaque, immutable handles made by `cagd_<noun>_new*` or by an algorithm,
//!   released by the NULL-safe `cagd_<noun>_free`;
//! - arrays are flat row-major doubles (`points[i * dim + k]`); inputs are borrowed and
//!   copied; outputs go to caller buffers with a capacity, and capacity 0 asks the size;
//! - a NULL pointer gives `CAGD_ERR_NULL_POINTER`, a panic `CAGD_ERR_PANIC`, never a crash;
//!   `cagd_last_error_message()` tells what was wrong, with the value.
//!
//! ```
//! # #![allow(unsafe_code, reason = "the example calls the C ABI")]
//! use cagd_capi::*;
//! let pts = [0.0, 0.0, 1.0, 2.0, 2.0, 0.0];
//! let mut curve = std::ptr::null_mut();
//! let (mut p, mut needed) = ([0.0; 2], 0);
//! // SAFETY: valid pointers of the documented sizes; the handle is freed once.
//! unsafe {
//!     assert_eq!(cagd_curve_new(pts.as_ptr(), 3, 2, &mut curve), CagdStatus::OK);
//!     assert_eq!(cagd_curve_eval(curve, 0.5, p.as_mut_ptr(), 2, &mut needed), CagdStatus::OK);
//!     cagd_curve_free(curve);
//! }
//! assert_eq!((p, needed), ([1.0, 1.0], 2));
//! ```
//!
//! ## What is exposed
//!
//! - Handles: `CagdCurve` (Bézier, polynomial or rational), `CagdBSpline` (B-spline /
//!   NURBS curve), `CagdBSplineSurface`, `CagdTensorPatch`, `CagdTriPatch`, `CagdReport`,
//!   and the piecewise results `CagdCurveList`, `CagdTensorPatchList`, `CagdTriPatchList`.
//! - Operations: evaluation, derivatives, elevation, subdivision, knot insertion, Bézier
//!   extraction, and its inverse, the exact merge of Bézier segments into one spline
//!   (`cagd_bspline_from_beziers`, seed 001 §4.1).
//! - Form conversions (SPEC-convert §15.1–15.3): one NURBS span ↔ one rational Bézier
//!   segment in closed form (`cagd_nurbs_span_to_bezier`, `cagd_bezier_to_nurbs_span`,
//!   degree 2 and 3), the biquadratic patch (`cagd_nurbs22_span_to_bezier`,
//!   `cagd_bezier22_to_nurbs22_span`), whole curves by the general route
//!   (`cagd_bspline_to_bezier_pieces`, `cagd_curvelist_to_bspline`) and the standard form
//!   (`cagd_curve_standard_form`); a failed inverse condition is
//!   `CAGD_ERR_CONVERSION_CONDITION`.
//! - WSGB curves of seed 003 (`CagdWsgbCurve`, a handle of its own): creation,
//!   evaluation by peeling, exact conversion to and from `CagdCurve`, elevation, leading
//!   coefficient and degeneracy, and `cagd_wsgb_reduce` (perturbation, best uniform, or any
//!   Bézier method) with the `CagdWsgbReport` struct, `cagd_wsgb_reduce_to_tolerance`
//!   (pieces in a `CagdWsgbCurveList`).
//! - Every reduction of cagd-reduce: `cagd_curve_reduce` (twelve methods, with report),
//!   `cagd_curve_reduce_batch` (`_bounded`: with per-curve bounds),
//!   `cagd_curve_reduce_to_tolerance` (C^k B-spline) and `_stepwise` (seed 000 Algorithm
//!   14.2.1), `cagd_curve_reduce_exact` /
//!   `cagd_curve_exact_degree`, `cagd_curve_reduce_g1_optimal`, `cagd_reduce_operator`,
//!   `cagd_bspline_reduce` (to a tolerance) and `cagd_bspline_reduce_uniform` (seed 001),
//!   `cagd_bsplinesurface_reduce`, `cagd_tensorpatch_reduce` / `cagd_tripatch_reduce` and
//!   their `_to_tolerance` forms; `cagd_intervaltri_reduce` (interval triangles, seed 004:
//!   LP reduction certified to contain its input; handle `CagdIntervalTriPatch`);
//!   `cagd_bspline_to_polynomial` / `cagd_bsplinesurface_to_polynomial` (NURBS to polynomial
//!   within a tolerance). The reductions take one `CagdReduceOptions` (versioned by its
//!   leading `struct_size`, filled by `cagd_reduce_options_init`).
//!
//! - Handle-free hot paths (`flat/`): `cagd_bezier_reduce` (one curve from arrays into
//!   caller buffers, report in a `CagdBezierReport` struct or none), `cagd_bezier_elevate`,
//!   and the batches `cagd_bezier_reduce_batch` / `cagd_bezier_elevate_batch` (point-major
//!   or curve-major `CagdBatchLayout`, an optional thread count). Results of unknown size
//!   in one call per result (`copy_out.rs`): `cagd_curvelist_copy`, `cagd_bspline_copy`,
//!   `cagd_tensorpatchlist_copy`, `cagd_tripatchlist_copy`, `cagd_wsgblist_copy` (every
//!   capacity 0 asks the sizes). README.md says which entry point to use when.
//! - Patch conversions (SPEC-convert §15.4–15.7), handles in and a `CagdPatchPieceList`
//!   out (each piece a tensor or triangular patch, polynomial or rational, with the part of
//!   the input's domain it covers): `cagd_tripatch_to_rect`, `_to_quad`, `_to_three_rects`,
//!   `cagd_tensorpatch_to_triangle`, `_to_triangles`, `_split_line`, `_split_curve`, `_trim`.
//! - Implicitization (cagd-implicit, SPEC-convert §15.8–15.9): `CagdImplicit` from
//!   `cagd_curve_implicitize` (coefficients, Bézout matrices, classification, inversion),
//!   `cagd_curve_intersect`, `cagd_implicit_subdivision_matrix`.
//!
//! ## Supported range and accuracy
//!
//! That of cagd-core (degrees `0..=64`, any `dim >= 1`); the C layer adds no numerics, it
//! only copies. Every entry point runs inside a panic boundary; the release profile keeps
//! `panic = "unwind"` so that the boundary works.

#[allow(unsafe_code, reason = "raw-pointer helpers of the C boundary")]
mod boundary;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod bspline;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod convert_nurbs;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod convert_patch;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod convert_surface;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod convert_unclamped;
#[allow(unsafe_code, reason = "writes caller buffers through raw pointers")]
mod copy_out;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod curve;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod flat;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod implicit;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod interval;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod invariants;
#[allow(
    unsafe_code,
    reason = "C entry points (no_mangle) returning static strings"
)]
mod last_error;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod matrices;
#[allow(
    unsafe_code,
    reason = "reads the caller's options through a raw pointer"
)]
mod options;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod patch;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod rational_to_polynomial;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod reduce;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod report;
#[allow(
    unsafe_code,
    reason = "C entry points (no_mangle) returning static strings"
)]
mod status;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod tensorpatch;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod tripatch;
mod version;
#[allow(unsafe_code, reason = "C entry points taking raw pointers")]
mod wsgb;

pub use bspline::{
    CagdBSpline, CagdBSplineSizes, CagdBSplineSurface, cagd_bspline_copy, cagd_bspline_degree,
    cagd_bspline_derivatives, cagd_bspline_dim, cagd_bspline_domain, cagd_bspline_eval,
    cagd_bspline_free, cagd_bspline_from_beziers, cagd_bspline_insert_knot,
    cagd_bspline_is_rational, cagd_bspline_knots, cagd_bspline_n_points, cagd_bspline_new,
    cagd_bspline_new_rational, cagd_bspline_points, cagd_bspline_reduce,
    cagd_bspline_reduce_uniform, cagd_bspline_to_beziers, cagd_bspline_weights,
    cagd_bsplinesurface_array, cagd_bsplinesurface_eval, cagd_bsplinesurface_free,
    cagd_bsplinesurface_new, cagd_bsplinesurface_reduce, cagd_bsplinesurface_reduce_to_tolerance,
    cagd_bsplinesurface_shape,
};
pub use convert_nurbs::{
    cagd_bezier_to_nurbs_span, cagd_bezier22_to_nurbs22_span, cagd_bspline_to_bezier_pieces,
    cagd_curve_standard_form, cagd_curvelist_to_bspline, cagd_nurbs_span_to_bezier,
    cagd_nurbs22_span_to_bezier,
};
pub use convert_patch::{
    CAGD_DOMAIN_BILINEAR, CAGD_DOMAIN_DEGENERATE_RECT, CAGD_DOMAIN_RULED, CAGD_DOMAIN_TRIANGLE,
    CAGD_PIECE_TENSOR, CAGD_PIECE_TRIANGLE, CAGD_TRIM_KEEP_ABOVE, CAGD_TRIM_KEEP_BELOW,
    CAGD_TRIM_U_OF_V, CAGD_TRIM_V_OF_U, CagdPatchPieceList, cagd_patchpiecelist_count,
    cagd_patchpiecelist_domain, cagd_patchpiecelist_free, cagd_patchpiecelist_info,
    cagd_patchpiecelist_points, cagd_patchpiecelist_weights, cagd_tensorpatch_split_curve,
    cagd_tensorpatch_split_line, cagd_tensorpatch_to_triangle, cagd_tensorpatch_to_triangles,
    cagd_tensorpatch_trim, cagd_tripatch_to_quad, cagd_tripatch_to_rect,
    cagd_tripatch_to_three_rects,
};
pub use convert_surface::{
    cagd_bsplinesurface_to_bezier_patches, cagd_patchpiecelist_to_bsplinesurface,
};
pub use convert_unclamped::{
    CAGD_SIDE_LEFT, CAGD_SIDE_RIGHT, cagd_bspline_outer_knots, cagd_curvelist_to_bspline_unclamped,
};
pub use curve::{
    CagdCurve, CagdCurveList, CagdCurveListSizes, cagd_curve_degree, cagd_curve_dim,
    cagd_curve_elevate, cagd_curve_eval, cagd_curve_eval_many, cagd_curve_free,
    cagd_curve_is_rational, cagd_curve_new, cagd_curve_new_rational, cagd_curve_points,
    cagd_curve_segment, cagd_curve_subdivide, cagd_curve_weights, cagd_curvelist_bound,
    cagd_curvelist_copy, cagd_curvelist_count, cagd_curvelist_free, cagd_curvelist_get,
    cagd_curvelist_interval,
};
pub use flat::{
    CagdBatchLayout, CagdBezierReport, cagd_bezier_elevate, cagd_bezier_elevate_batch,
    cagd_bezier_reduce, cagd_bezier_reduce_batch,
};
pub use implicit::{
    CAGD_INTERSECTION_STRIDE, CagdImplicit, cagd_curve_implicitize, cagd_curve_intersect,
    cagd_implicit_bezout, cagd_implicit_classify, cagd_implicit_coefficients, cagd_implicit_free,
    cagd_implicit_invert, cagd_implicit_report, cagd_implicit_subdivision_matrix,
};
pub use interval::{
    CagdIntervalReport, CagdIntervalTriPatch, cagd_intervaltri_contains, cagd_intervaltri_free,
    cagd_intervaltri_net, cagd_intervaltri_new, cagd_intervaltri_reduce, cagd_intervaltri_shape,
    cagd_triangle_elevation_matrix,
};
pub use invariants::{
    cagd_curve_distance, cagd_curve_forward_difference, cagd_tensorpatch_degeneracy,
    cagd_tensorpatch_distance, cagd_tripatch_degeneracy, cagd_tripatch_distance,
};
pub use last_error::{cagd_last_error_message, last_error_string};
pub use matrices::{
    CagdBasis, cagd_basis_matrix, cagd_perturbation_error_factor, cagd_subdivision_levels,
    cagd_uniform_bspline_matrix,
};
pub use options::{
    CagdBoundLevel, CagdErrorSpace, CagdMerge, CagdPatchConstraint, CagdPatchMethod,
    CagdReduceMethod, CagdReduceOptions, CagdSplineStrategy,
};
pub use patch::{
    CagdPatchListSizes, CagdTensorPatchList, CagdTriPatchList, cagd_report_patch,
    cagd_tensorpatch_reduce, cagd_tensorpatch_reduce_to_tolerance, cagd_tensorpatchlist_copy,
    cagd_tensorpatchlist_count, cagd_tensorpatchlist_free, cagd_tensorpatchlist_get,
    cagd_tripatch_reduce, cagd_tripatch_reduce_to_tolerance, cagd_tripatchlist_copy,
    cagd_tripatchlist_count, cagd_tripatchlist_free, cagd_tripatchlist_get,
};
pub use rational_to_polynomial::{cagd_bspline_to_polynomial, cagd_bsplinesurface_to_polynomial};
pub use reduce::{
    CAGD_EXACT_DEGREE_REL_TOL, cagd_curve_exact_degree, cagd_curve_reduce, cagd_curve_reduce_batch,
    cagd_curve_reduce_batch_bounded, cagd_curve_reduce_exact, cagd_curve_reduce_g1_optimal,
    cagd_curve_reduce_to_tolerance, cagd_curve_reduce_to_tolerance_stepwise, cagd_reduce_operator,
    cagd_reduce_options_init, cagd_report_method_params,
};
pub use report::{
    CagdReport, cagd_report_bound, cagd_report_bound_level, cagd_report_free,
    cagd_report_max_error, cagd_report_method, cagd_report_pieces, cagd_report_piecewise,
    cagd_report_space, cagd_report_spline, cagd_report_spline_continuity,
    cagd_report_spline_strategy, cagd_report_step_bounds,
};
pub use status::{CagdStatus, cagd_status_name, status_of_core};
pub use tensorpatch::{
    CagdTensorPatch, cagd_tensorpatch_elevate, cagd_tensorpatch_eval, cagd_tensorpatch_free,
    cagd_tensorpatch_new, cagd_tensorpatch_points, cagd_tensorpatch_shape,
    cagd_tensorpatch_subdivide_u, cagd_tensorpatch_subdivide_v,
};
pub use tripatch::{
    CagdTriPatch, cagd_tripatch_elevate, cagd_tripatch_eval, cagd_tripatch_free, cagd_tripatch_new,
    cagd_tripatch_points, cagd_tripatch_shape, cagd_tripatch_subdivide_midpoint,
};
pub use version::{CAGD_VERSION_MAJOR, CAGD_VERSION_MINOR, CAGD_VERSION_PATCH};
pub use wsgb::{
    CagdWsgbCurve, CagdWsgbCurveList, CagdWsgbListSizes, CagdWsgbMethod, CagdWsgbReport,
    cagd_wsgb_elevate, cagd_wsgb_eval, cagd_wsgb_free, cagd_wsgb_from_bezier,
    cagd_wsgb_leading_coefficient, cagd_wsgb_new, cagd_wsgb_points, cagd_wsgb_reduce,
    cagd_wsgb_reduce_to_tolerance, cagd_wsgb_shape, cagd_wsgb_to_bezier, cagd_wsgblist_copy,
    cagd_wsgblist_count, cagd_wsgblist_free, cagd_wsgblist_get,
};
