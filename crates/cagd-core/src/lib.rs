//! # cagd-core
//!
//! Numbers and shapes for computer-aided geometric design: exact binomials, Bernstein and
//! related bases, Bézier curves (polynomial and rational, any dimension), tensor-product and
//! triangular Bézier patches, B-spline / NURBS curves and surfaces, and the error type
//! shared by every cagd crate. The reducers, converters and implicitizers of the other
//! crates stand on it.
//!
//! Features:
//! - exact binomials ([`binomial`]) and exact rational matrices ([`ExactMatrix`]: product,
//!   Gauss–Jordan inverse, rounding once to `f64`) for building operators without rounding;
//! - basis changes between Bernstein and the power, shifted Chebyshev, shifted Legendre,
//!   Said–Ball, Wang–Ball and Wang–Said generalized Ball bases ([`Basis`],
//!   [`to_bernstein`], [`from_bernstein`], their `_exact` forms, [`convert_points`]), exact
//!   and cached per degree;
//! - Bézier curves ([`BezierCurve`]), tensor-product and triangular patches
//!   ([`TensorPatch`], [`TriPatch`]) and the slice kernels under them ([`kernel`]).
//!
//! Data layout (DESIGN.md): scalars are `f64`; point sets are flat row-major buffers (point
//! `i`, coordinate `k` at `i * dim + k`); rational objects carry Euclidean points plus a
//! separate weight array.
//!
//! ```
//! use cagd_core::BezierCurve;
//! let c = BezierCurve::new(vec![0.0, 0.0, 1.0, 3.0, 3.0, 4.0, 5.0, 1.0], 2)?;
//! let e = c.elevate(2)?; // degree 5, same curve
//! let (left, right) = c.subdivide(0.5)?;
//! assert_eq!(left.eval(1.0), right.eval(0.0));
//! assert!((e.eval(0.3)[1] - c.eval(0.3)[1]).abs() < 1e-14);
//! # Ok::<(), cagd_core::Error>(())
//! ```
//!
//! ## Supported range and accuracy
//!
//! Degrees `0..=64` ([`MAX_DEGREE`]) in every direction; a larger degree is
//! [`Error::DegreeOutOfRange`]. Binomial coefficients are exact (`u128`) up to `C(130, k)`.
//! Evaluation, subdivision and elevation are convex-combination algorithms with a relative
//! error of a few `n` ulp of the control-point size. Basis-change matrices are exact, rounded
//! once to `f64`; their `f64` round-trip accuracy per basis and degree is tabulated in
//! the docs of [`Basis`] (limited by the conditioning of the basis, e.g. 1e-15 for
//! Bernstein -> Chebyshev -> Bernstein at every degree, but ~1e-12 for the power basis
//! already at degree 10).
//!
//! Parametric distances ([`curve_distance`], [`tensor_patch_distance`], [`tri_patch_distance`]) are maxima found by
//! dense sampling plus local refinement, relative accuracy `1e-12` above a floor of a few
//! ulp of the difference's control points (measured on closed-form cases).
//!
//! B-spline / NURBS evaluation (de Boor), knot insertion and Bézier extraction are
//! convex-combination algorithms too (measured: curves and surfaces preserved to `1e-12`
//! relative); knot removal returns a certified error bound.
#![forbid(unsafe_code)]

mod ball;
mod basis;
mod bezier;
mod binomial;
mod bspline;
mod distance;
mod error;
mod exact;
mod frame;
pub mod kernel;
mod norm;
mod patch;
mod quadrature;
mod validate;

pub use ball::{
    WsgbCurve, WsgbScalar, bezier_to_wsgb_exact, check_wsgb_order, round_exact_points,
    to_exact_points, wsgb_elevate_exact, wsgb_inverse_elevation, wsgb_leading_coefficient,
    wsgb_lec_difference, wsgb_lec_factor, wsgb_reduced_order, wsgb_to_bezier_exact,
};
pub use basis::{
    BallTerm, Basis, convert_points, from_bernstein, from_bernstein_exact, to_bernstein,
    to_bernstein_exact, wsgb_max_l, wsgb_terms,
};
pub use bezier::BezierCurve;
pub use binomial::{
    MAX_BINOMIAL_N, MAX_DEGREE, binomial, binomial_f64, check_degree, sign_binomial_f64,
    try_binomial,
};
pub use bspline::{
    BSplineCurve, BSplineSurface, BezierSegment, KnotRemoval, MAX_KNOT, SurfacePatchPiece,
    basis_functions, check_knots, find_span, knot_multiplicity, s_matrix, s_matrix_exact,
    s_matrix_inverse, s_matrix_inverse_exact,
};
pub use distance::{
    Domain2, MAX_REFINED_MAXIMA, curve_distance, max_distance_1d, max_distance_2d,
    max_distance_2d_with_grid, refine_sampled_maxima, refine_sampled_maxima_above,
    tensor_patch_distance, tensor_patch_grid, tri_patch_distance, tri_patch_grid,
};
pub use error::{Error, Result};
pub use exact::{
    ExactMatrix, curve_invariant_exact, tensor_invariants_exact, tri_invariants_exact,
};
pub use frame::{ModelFrame, centred_rational_bound};
pub use norm::{max_point_norm, point_norm};
pub use patch::{TensorPatch, TriPatch, tri_count, tri_index};
pub use quadrature::{MAX_GAUSS_NODES, gauss_legendre};
pub use validate::{all_finite, check_finite_param, check_points, check_tolerance, check_weights};
