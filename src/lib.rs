//! # cagd
//!
//! Degree reduction, conversion and implicitization of Bézier, B-spline and NURBS curves
//! and surfaces, under one name (DESIGN.md: the facade package). This crate only
//! re-exports: the shapes, bases and the shared error type of `cagd-core` and every reducer
//! of `cagd-reduce` at the top level (`cagd::BezierCurve`, `cagd::reduce`,
//! `cagd::Method`, `cagd::Error`, …; the slice kernels as [`kernel`]), and the conversions
//! and implicitization crates as the modules [`convert`] and [`implicit`]. Its paths are
//! the stable ones; the member crates' own layout may change.
//!
//! The example of the README:
//!
//! ```rust
//! use cagd::{BezierCurve, Method, reduce};
//!
//! fn main() -> Result<(), cagd::Error> {
//!     let c = BezierCurve::new(vec![0.0, 0.0, 1.0, 3.0, 3.0, 4.0, 5.0, 1.0, 6.0, 5.0], 2)?;
//!     let red = reduce(&c, 3, Method::L2 { r: 1, p: 1 })?; // C1 ends, L2-optimal
//!     println!("{:?} within {}", red.curve.points(), red.report.error_bound.unwrap());
//!     Ok(())
//! }
//! ```
//!
//! ## Supported range and accuracy
//!
//! Those of the member crates, documented on the re-exported items: degrees `0..=64`
//! ([`MAX_DEGREE`]) everywhere, certified error bounds for every reduction (see
//! [`Report::error_bound`]), basis changes and operators exact and rounded once to `f64`.
#![forbid(unsafe_code)]

pub use cagd_core::*;
pub use cagd_reduce::*;

/// Representation conversions (seed 002 ch. 15.1–15.7): the `cagd-convert` crate.
pub use cagd_convert as convert;
/// Implicitization of rational Bézier curves (seed 002 ch. 15.8–15.9): the `cagd-implicit`
/// crate.
pub use cagd_implicit as implicit;
