//! # cagd-implicit
//!
//! Implicitization of rational planar Bézier curves (seed 002 §15.8–15.9 as corrected by
//! SPEC-convert): the Bézout matrix `F = x A + y B + C0`, the implicit polynomial
//! `f(x, y) = det F` (exact and rounded once to `f64`), and what it is used for — point
//! classification, inversion and curve–curve intersection.
