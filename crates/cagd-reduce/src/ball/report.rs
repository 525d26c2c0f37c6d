//! The result of a WSGB degree reduction: the reduced curve, the certified bound and the
//! measured error (Euclidean), and the paper's per-coordinate figures (seed 003), named as
//! such.

use cagd_core::WsgbCurve;

use crate::{Method, Report};

/// A degree-reduction method for WSGB curves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum WsgbMethod {
    /// The perturbation method of seed 003 §2.1 (SPEC-reduce §9.4): the least change
    /// `sum ||eps_i||^2` of the middle control points that makes the curve degenerate, then
    /// the exact inverse elevation (§9.3). One degree per step; ends interpolated for
    /// `n >= 3`. Needs `n >= 2`.
    Perturbation,
    /// The best uniform approximation of seed 003 §2.2 (SPEC-reduce §9.5): subtract
    /// `lec T_n(2u-1) / 2^(2n-1)` in WSGB form, then the exact inverse elevation. One degree
    /// per step; optimal per step in every coordinate and in the Euclidean norm.
    Uniform,
    /// Any Bézier reducer of cagd-reduce, through the exact conversion to Bézier form and
    /// back to WSGB(m, L').
    Bezier(Method),
}

impl WsgbMethod {
    /// A short stable name: `"perturbation"`, `"uniform"`, or the Bézier method's name.
    pub fn name(&self) -> &'static str {
        match self {
            WsgbMethod::Perturbation => "perturbation",
            WsgbMethod::Uniform => "uniform",
            WsgbMethod::Bezier(m) => m.name(),
        }
    }
}

/// One degree step `n -> n-1` of [`WsgbMethod::Perturbation`] or [`WsgbMethod::Uniform`],
/// with the seed's figures for that step.
#[derive(Debug, Clone, PartialEq)]
pub struct WsgbStep {
    /// Degree before the step.
    pub degree_from: usize,
    /// Order `L` before the step.
    pub order_from: usize,
    /// The leading coefficient of the curve before the step (SPEC-reduce §9.2).
    pub lec: Vec<f64>,
    /// Certified bound of the step's error `max_u ||r(u) - q(u)||` (Euclidean), `f64`
    /// rounding included.
    pub error_bound: f64,
    /// The step's exact maximum error in the max-abs coordinate norm, the norm of seed 003
    /// (SPEC-reduce §9.4 / §9.5 closed forms).
    pub error_inf: f64,
    /// The paper's loose bound (11), `2^L C(2m-2L, m-L) ||D||_inf / 4^m`: what seed 003
    /// prints as the perturbation "error" (6-8x the true error).
    pub paper_bound_11: f64,
    /// The paper's formula (12), `||lec||_inf / 2^(2n-1)`: the uniform method's exact error.
    pub uniform_error_12: f64,
}

/// What a WSGB reduction did.
#[derive(Debug, Clone, PartialEq)]
pub struct WsgbReport {
    /// The method.
    pub method: WsgbMethod,
    /// Source degree `n`.
    pub degree_from: usize,
    /// Target degree `m`.
    pub degree_to: usize,
    /// Source order `L`.
    pub order_from: usize,
    /// Order `L'` of the result (`min(L, max(floor(m/2) - 1, 0))`).
    pub order_to: usize,
    /// Certified upper bound of `max_u ||r(u) - q(u)||` (Euclidean), never below the true
    /// error, `f64` rounding included.
    pub error_bound: f64,
    /// The measured `max_u ||r(u) - q(u)||` (Euclidean): dense sampling plus local
    /// refinement of the exact difference curve ([`cagd_core::curve_distance`]). `None`
    /// when not asked for ([`crate::reduce_wsgb_with`]).
    pub max_error: Option<f64>,
    /// The measured maximum of `max_k |r_k(u) - q_k(u)|` (max-abs coordinate norm, the norm
    /// of seed 003's printed errors); `None` when not measured.
    pub max_error_inf: Option<f64>,
    /// The degree steps (perturbation and uniform methods; empty for Bézier methods).
    pub steps: Vec<WsgbStep>,
    /// The Bézier reducer's own report (Bézier methods only).
    pub bezier: Option<Report>,
}

/// The reduced WSGB curve and its report.
#[derive(Debug, Clone, PartialEq)]
pub struct WsgbReduction {
    /// The reduced curve, WSGB(m, L').
    pub curve: WsgbCurve,
    /// What was done.
    pub report: WsgbReport,
}
