//! # cagd-implicit
//!
//! Implicitization of rational planar Bézier curves (seed 002 §15.8–15.9 as corrected by
//! SPEC-convert): the Bézout matrix `F = x A + y B + C0` ([`BezoutMatrix`]), the implicit
//! polynomial `f(x, y) = det F` exact and rounded once to `f64` ([`implicitize`],
//! [`ImplicitPolynomial`]), base points and improper parametrizations, the subdivision
//! matrix of theorem 15.9.1 ([`subdivision_matrix`]), and what it is used for — point
//! classification, inversion and curve–curve intersection.
//!
//! ```
//! use cagd_core::BezierCurve;
//! // SPEC-convert §15.8 inline example: P = (0,0), (1,2), (2,0) gives f = -16x^2 + 32x - 16y.
//! let c = BezierCurve::new(vec![0.0, 0.0, 1.0, 2.0, 2.0, 0.0], 2)?;
//! let imp = cagd_implicit::implicitize(&c)?;
//! assert_eq!(imp.polynomial.monomials(), vec![(2, 0, -16.0), (1, 0, 32.0), (0, 1, -16.0)]);
//! let p = c.eval(0.3);
//! assert!(imp.polynomial.eval(p[0], p[1]).abs() < 1e-13);
//! # Ok::<(), cagd_core::Error>(())
//! ```
//!
//! ## Supported range and accuracy
//!
//! Curve degree `1..=`[`MAX_IMPLICIT_DEGREE`] (16). The coefficients are exact (`BigInt`
//! fraction-free Bareiss determinants on a lattice plus exact Newton interpolation): the
//! inputs are binary fractions, so nothing is rounded until the single rounding to `f64`.
//! Cost `O(n^5)` big-integer operations: see the benchmark `benches/implicit.rs`.
//! With the rounded coefficients, `|f(p)| / sum |c_ij x^i y^j|` on curve points is at the
//! level of a few ulp times `n` (tested ≤ 1e-12 for degrees 2–10).
#![forbid(unsafe_code)]

mod base_point;
mod bernstein_roots;
mod bezout;
mod classify;
mod compose;
mod exact;
mod implicit_curve;
mod implicitize;
mod intersect;
mod inversion;
mod lu;
mod modular;
mod planar;
mod polynomial;
mod rational;
mod subdivision;

pub use bezout::BezoutMatrix;
pub use classify::Classification;
pub use implicit_curve::ImplicitCurve;
pub use implicitize::{
    BasePointPolicy, ImplicitOptions, ImplicitReport, Implicitization, implicitize,
    implicitize_with,
};
pub use intersect::{Intersection, intersect};
pub use planar::{MAX_IMPLICIT_DEGREE, check_planar};
pub use polynomial::ImplicitPolynomial;
pub use subdivision::subdivision_matrix;
