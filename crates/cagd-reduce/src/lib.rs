//! # cagd-reduce
//!
//! Degree reduction of Bézier curves (polynomial or rational, any dimension): every method
//! of seed 000 (chapter 14) and the classical ones it cites, with the errata of
//! SPEC-reduce, as cached linear operators with certified error bounds.
//!
//! ```
//! use cagd_core::BezierCurve;
//! use cagd_reduce::{Method, operator, reduce, reduce_batch};
//!
//! // A cubic elevated to degree 5 reduces back to the cubic (up to rounding).
//! let cubic = BezierCurve::new(vec![0.0, 0.0, 1.0, 3.0, 3.0, 4.0, 5.0, 1.0], 2)?;
//! let quintic = cubic.elevate(2)?;
//! let red = reduce(&quintic, 3, Method::L2 { r: 1, p: 1 })?;
//! for (a, b) in red.curve.points().iter().zip(cubic.points()) {
//!     assert!((a - b).abs() < 1e-13);
//! }
//! assert!(red.report.error_bound.unwrap() < 1e-12);
//!
//! // A genuine reduction: the certified bound is never below the measured error.
//! let p = BezierCurve::new(vec![0.0, 0.0, 1.0, 3.0, 3.0, 4.0, 5.0, 1.0, 6.0, 5.0, 8.0, 2.0], 2)?;
//! let opts = cagd_reduce::ReduceOptions { measure: true, ..cagd_reduce::ReduceOptions::new(Method::Eck, 4) };
//! let red = cagd_reduce::reduce_with(&p, &opts)?;
//! let (bound, measured) = (red.report.error_bound.unwrap(), red.report.max_error.unwrap());
//! assert!(measured <= bound && bound < 1.0001 * measured); // Eck's bound is exact
//!
//! // Batch: one cached operator, many curves, no per-curve allocation.
//! let op = operator(Method::ConstrainedChebyshev { r: 1, p: 1 }, 5, 4)?;
//! let input = [p.points(), p.points()].concat();
//! let mut output = vec![0.0; 2 * 5 * 2];
//! reduce_batch(&op, &input, 2, &mut output)?;
//! assert_eq!(output[..10], output[10..]);
//! # Ok::<(), cagd_reduce::Error>(())
//! ```
//!
//! ## Methods
//!
//! See [`Method`]. One-degree methods (Forrest, Piegl–Tiller, Farin, Eck, perturbation,
//! G1 perturbation) are applied stepwise for `m < n - 1`; the operator is the exact product
//! of the steps and the bound the sum of the per-step bounds carried through the product
//! (or the convex-hull bound of the composed operator, whichever is smaller). The G1
//! perturbation with optimal `l1, l2` is not linear: [`reduce_g1_optimal`].
//!
//! ## Reduction to a tolerance
//!
//! [`reduce_to_tolerance`] splits the curve adaptively and reduces every piece with any
//! method until each certified bound meets the tolerance, and returns a degree-`m` B-spline
//! with `C^k` joins (interior knot multiplicity `m - k`); [`reduce_to_tolerance_alg_14_2_1`]
//! is seed 000's stepwise perturbation algorithm as corrected in SPEC-reduce §2.2.
//!
//! ## How the operators are computed
//!
//! Every operator is computed in exact rational arithmetic (`BigRational`) from the seed's
//! formulas — closed forms, the exact Gram / normal systems of the least-squares methods,
//! exact Bernstein <-> Chebyshev conversions — and rounded to `f64` once, then cached per
//! `(method, n, m, r, p)`. No normal equations are formed in floating point.
//!
//! ## Certified bounds
//!
//! [`Report::error_bound`] is the smaller of the method's own bound (SPEC-reduce §2.1
//! `W_n ||F|| / (C(2n,n) - 2)` with the rounded-up table [`perturbation_error_factor`];
//! Eck's exact `2^(-2n-1) ||Delta^(n+1) P_0||`; eq. 14.5.2's bound; Piegl–Tiller's exact
//! error for odd `m`) and the universal convex-hull bound `max_i ||P_i - (E Q)_i||`, plus a
//! rigorous allowance for `f64` rounding. Rational curves: see [`reduce_with`].
//!
//! ## Supported range and accuracy
//!
//! Degrees `0..=64` ([`cagd_core::MAX_DEGREE`]). Because each operator entry is the exact
//! value rounded once, the operator itself is accurate to 1 ulp per entry for every
//! supported `(n, m)`; applying it to a curve costs a relative error of about
//! `(n + 1) eps * ||A||_inf` of the control-point size (see [`Operator::norm_inf`]; the
//! amplification is intrinsic to the problem, SPEC-reduce §6).
#![forbid(unsafe_code)]

mod alg_14_2_1;
mod batch;
mod chebyshev;
mod ends;
mod exact;
mod exact_degree;
mod g1;
mod least_squares;
mod measure;
mod method;
mod one_step;
mod operator;
mod piecewise;
mod reduce;
mod tolerance;
#[cfg(test)]
mod tolerance_tests;
mod wn_table;

pub use alg_14_2_1::{reduce_to_tolerance_alg_14_2_1, subdivision_levels};
pub use batch::reduce_batch;
pub use cagd_core::{Error, Result};
pub use exact_degree::{DEFAULT_REL_TOL, exact_degree, reduce_exact};
pub use g1::reduce_g1_optimal;
pub use measure::{SAMPLES, max_deviation};
pub use method::Method;
pub use operator::{Operator, operator};
pub use piecewise::{PiecewiseReduction, PiecewiseReport, ReducedPiece};
pub use reduce::{ErrorSpace, ReduceOptions, Reduction, Report, reduce, reduce_with};
pub use tolerance::{DEFAULT_MAX_DEPTH, MAX_PIECES, ToleranceOptions, reduce_to_tolerance};
pub use wn_table::perturbation_error_factor;
