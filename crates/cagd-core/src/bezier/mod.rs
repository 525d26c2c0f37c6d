//! Bézier curves: the type [`BezierCurve`] (`curve.rs`: construction, evaluation, de
//! Casteljau subdivision, elevation) and its further operations (`ops.rs`: derivatives,
//! forward differences, hodographs and the like).

mod curve;
mod ops;

pub use curve::BezierCurve;
