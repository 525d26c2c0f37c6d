//! `CagdStatus`, the result of every fallible C entry point, and the mapping from the Rust
//! error types to it (STYLE §9.5).
//!
//! Numbers are explicit and stable: argument errors 1–19, input validity 20–39, algorithmic
//! failures 40–59, `CAGD_ERR_PANIC = 99`. A number, once published, is never reused; a
//! retired one stays here as a "reserved" comment. The unit test below pins every value.

use std::ffi::c_char;

use cagd_core::Error;

/// Result code of every fallible `cagd_*` function. `CAGD_OK` (0) is success; every other
/// value is a failure, and `cagd_last_error_message()` then describes it with the
/// offending value. The numbers are stable across releases.
///
/// cbindgen:rename-all=prefix:CAGD_
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(
    non_camel_case_types,
    reason = "C names: the variants become CAGD_OK, CAGD_ERR_*"
)]
pub enum CagdStatus {
    /// Success; every output was written.
    OK = 0,
    /// A pointer argument that must not be NULL was NULL (the message names it).
    ERR_NULL_POINTER = 1,
    /// An output buffer is too small; `*out_needed` holds the number of doubles needed.
    /// Nothing else was written.
    ERR_BUFFER_TOO_SMALL = 2,
    /// A scalar argument is not usable: zero `dim`, a non-finite or out-of-range parameter
    /// or tolerance, a size product that overflows, two outputs aliasing each other.
    ERR_INVALID_ARGUMENT = 3,
    /// Two sizes that must agree do not (e.g. a point count against the degree).
    ERR_DIMENSION_MISMATCH = 4,
    /// A value that was not computed was asked for (e.g. the measured error of a
    /// reduction run without `measure`).
    ERR_NOT_AVAILABLE = 5,
    /// A coordinate or a knot is NaN or infinite.
    ERR_NON_FINITE = 20,
    /// A weight is zero, negative, subnormal (below `DBL_MIN`) or not finite.
    ERR_NON_POSITIVE_WEIGHT = 21,
    /// A knot vector decreases or has the wrong length (`n_points + degree + 1`).
    ERR_BAD_KNOTS = 22,
    /// A knot appears more than `degree + 1` times.
    ERR_MULTIPLICITY = 23,
    /// Too few points (or coefficients) for the object or the algorithm.
    ERR_NOT_ENOUGH_POINTS = 24,
    /// A degree outside the supported range 0..=64.
    ERR_DEGREE_OUT_OF_RANGE = 25,
    /// Too many end constraints for the target degree.
    ERR_TOO_MANY_CONSTRAINTS = 26,
    /// A (source, target) degree pair the operation does not accept, e.g. a reduction
    /// whose target is not below the source degree.
    ERR_BAD_DEGREE_PAIR = 27,
    /// An implicitization / intersection input is not a planar (dim = 2) curve.
    ERR_NOT_PLANAR = 35,
    /// An interval whose lower bound exceeds its upper bound (an empty box side).
    ERR_EMPTY_INTERVAL = 30,
    /// A condition of a seed formula is not met (the message gives the equation number).
    ERR_CONDITION_NOT_MET = 40,
    /// An iterative or adaptive algorithm could not reach the tolerance.
    ERR_NO_CONVERGENCE = 41,
    /// A linear system that must be solved is singular.
    ERR_SINGULAR = 42,
    /// An `n x n` rectangular patch is not a degenerate triangle (SPEC-convert §15.4,
    /// Theorem 15.4.2); the message gives the relative residual.
    ERR_NOT_DEGENERATE = 50,
    /// A split of a patch's parameter domain folds or degenerates (Jacobian <= 0 at a
    /// corner of a sub-domain, SPEC-convert §15.5).
    ERR_DEGENERATE_SPLIT = 51,
    /// A trimming layout the trimmed-patch tiling does not support (SPEC-convert §15.7.3).
    ERR_UNSUPPORTED_TRIM = 52,
    /// A condition of a form conversion is not met (SPEC-convert §15.1.8, §15.3.13–16: an
    /// inverse NURBS weight would be `<= 0`; §15.2: Bézier weights that are not separable
    /// `G_i H_j`). The message names the condition, the failing weight and its value.
    ERR_CONVERSION_CONDITION = 43,
    /// The curve has base points (X, Y, W share a factor; `det F` is identically 0) and
    /// they were not to be divided out, or nothing is left after dividing them out.
    ERR_BASE_POINT = 53,
    /// The point is a singular point (double point, cusp) of the curve: its parameter is
    /// not unique.
    ERR_SINGULAR_POINT = 54,
    /// The point given for inversion is not on the curve.
    ERR_NOT_ON_CURVE = 55,
    /// Two curves overlap along an arc: their intersection is not a finite set.
    ERR_COINCIDENT = 56,
    /// The LP solver answered "infeasible" (cannot happen for the interval reduction LP by
    /// SPEC-convert I.2; reported, never hidden).
    ERR_LP_INFEASIBLE = 60,
    /// The LP solver answered "unbounded" (cannot happen for the interval reduction LP by
    /// SPEC-convert I.2; reported, never hidden).
    ERR_LP_UNBOUNDED = 61,
    /// The LP solver failed (internal error, caught panic, non-finite answer).
    ERR_LP_FAILED = 62,
    /// A containment that must be certified could not be certified after outward repair.
    ERR_NOT_CERTIFIED = 63,
    /// A bug inside cagd was caught at the boundary (a Rust panic); please report it with
    /// the message.
    ERR_PANIC = 99,
}

impl CagdStatus {
    /// The C name of the status as a NUL-terminated static string.
    pub const fn c_name(self) -> &'static std::ffi::CStr {
        match self {
            CagdStatus::OK => c"CAGD_OK",
            CagdStatus::ERR_NULL_POINTER => c"CAGD_ERR_NULL_POINTER",
            CagdStatus::ERR_BUFFER_TOO_SMALL => c"CAGD_ERR_BUFFER_TOO_SMALL",
            CagdStatus::ERR_INVALID_ARGUMENT => c"CAGD_ERR_INVALID_ARGUMENT",
            CagdStatus::ERR_DIMENSION_MISMATCH => c"CAGD_ERR_DIMENSION_MISMATCH",
            CagdStatus::ERR_NOT_AVAILABLE => c"CAGD_ERR_NOT_AVAILABLE",
            CagdStatus::ERR_NON_FINITE => c"CAGD_ERR_NON_FINITE",
            CagdStatus::ERR_NON_POSITIVE_WEIGHT => c"CAGD_ERR_NON_POSITIVE_WEIGHT",
            CagdStatus::ERR_BAD_KNOTS => c"CAGD_ERR_BAD_KNOTS",
            CagdStatus::ERR_MULTIPLICITY => c"CAGD_ERR_MULTIPLICITY",
            CagdStatus::ERR_NOT_ENOUGH_POINTS => c"CAGD_ERR_NOT_ENOUGH_POINTS",
            CagdStatus::ERR_DEGREE_OUT_OF_RANGE => c"CAGD_ERR_DEGREE_OUT_OF_RANGE",
            CagdStatus::ERR_TOO_MANY_CONSTRAINTS => c"CAGD_ERR_TOO_MANY_CONSTRAINTS",
            CagdStatus::ERR_BAD_DEGREE_PAIR => c"CAGD_ERR_BAD_DEGREE_PAIR",
            CagdStatus::ERR_NOT_PLANAR => c"CAGD_ERR_NOT_PLANAR",
            CagdStatus::ERR_CONDITION_NOT_MET => c"CAGD_ERR_CONDITION_NOT_MET",
            CagdStatus::ERR_NO_CONVERGENCE => c"CAGD_ERR_NO_CONVERGENCE",
            CagdStatus::ERR_SINGULAR => c"CAGD_ERR_SINGULAR",
            CagdStatus::ERR_NOT_DEGENERATE => c"CAGD_ERR_NOT_DEGENERATE",
            CagdStatus::ERR_DEGENERATE_SPLIT => c"CAGD_ERR_DEGENERATE_SPLIT",
            CagdStatus::ERR_UNSUPPORTED_TRIM => c"CAGD_ERR_UNSUPPORTED_TRIM",
            CagdStatus::ERR_CONVERSION_CONDITION => c"CAGD_ERR_CONVERSION_CONDITION",
            CagdStatus::ERR_BASE_POINT => c"CAGD_ERR_BASE_POINT",
            CagdStatus::ERR_SINGULAR_POINT => c"CAGD_ERR_SINGULAR_POINT",
            CagdStatus::ERR_NOT_ON_CURVE => c"CAGD_ERR_NOT_ON_CURVE",
            CagdStatus::ERR_COINCIDENT => c"CAGD_ERR_COINCIDENT",
            CagdStatus::ERR_EMPTY_INTERVAL => c"CAGD_ERR_EMPTY_INTERVAL",
            CagdStatus::ERR_LP_INFEASIBLE => c"CAGD_ERR_LP_INFEASIBLE",
            CagdStatus::ERR_LP_UNBOUNDED => c"CAGD_ERR_LP_UNBOUNDED",
            CagdStatus::ERR_LP_FAILED => c"CAGD_ERR_LP_FAILED",
            CagdStatus::ERR_NOT_CERTIFIED => c"CAGD_ERR_NOT_CERTIFIED",
            CagdStatus::ERR_PANIC => c"CAGD_ERR_PANIC",
        }
    }

    /// The status with code `code`, if there is one.
    pub fn from_code(code: i32) -> Option<CagdStatus> {
        ALL_STATUSES.into_iter().find(|s| *s as i32 == code)
    }
}

/// Every status, in numeric order (used by tests and by `cagd_status_name`).
pub(crate) const ALL_STATUSES: [CagdStatus; 32] = [
    CagdStatus::OK,
    CagdStatus::ERR_NULL_POINTER,
    CagdStatus::ERR_BUFFER_TOO_SMALL,
    CagdStatus::ERR_INVALID_ARGUMENT,
    CagdStatus::ERR_DIMENSION_MISMATCH,
    CagdStatus::ERR_NOT_AVAILABLE,
    CagdStatus::ERR_NON_FINITE,
    CagdStatus::ERR_NON_POSITIVE_WEIGHT,
    CagdStatus::ERR_BAD_KNOTS,
    CagdStatus::ERR_MULTIPLICITY,
    CagdStatus::ERR_NOT_ENOUGH_POINTS,
    CagdStatus::ERR_DEGREE_OUT_OF_RANGE,
    CagdStatus::ERR_TOO_MANY_CONSTRAINTS,
    CagdStatus::ERR_BAD_DEGREE_PAIR,
    CagdStatus::ERR_EMPTY_INTERVAL,
    CagdStatus::ERR_NOT_PLANAR,
    CagdStatus::ERR_CONDITION_NOT_MET,
    CagdStatus::ERR_NO_CONVERGENCE,
    CagdStatus::ERR_SINGULAR,
    CagdStatus::ERR_CONVERSION_CONDITION,
    CagdStatus::ERR_NOT_DEGENERATE,
    CagdStatus::ERR_DEGENERATE_SPLIT,
    CagdStatus::ERR_UNSUPPORTED_TRIM,
    CagdStatus::ERR_BASE_POINT,
    CagdStatus::ERR_SINGULAR_POINT,
    CagdStatus::ERR_NOT_ON_CURVE,
    CagdStatus::ERR_COINCIDENT,
    CagdStatus::ERR_LP_INFEASIBLE,
    CagdStatus::ERR_LP_UNBOUNDED,
    CagdStatus::ERR_LP_FAILED,
    CagdStatus::ERR_NOT_CERTIFIED,
    CagdStatus::ERR_PANIC,
];

/// The status of a `cagd_core::Error`: each variant maps to exactly one status.
///
/// `cagd_core::Error` is `#[non_exhaustive]`, so a variant added later falls into the last
/// arm (`CAGD_ERR_INVALID_ARGUMENT`) until it is given its own line here; the test
/// `every_core_error_maps` lists the variants known today.
pub fn status_of_core(e: &Error) -> CagdStatus {
    match e {
        Error::DegreeOutOfRange { .. } => CagdStatus::ERR_DEGREE_OUT_OF_RANGE,
        Error::NotEnoughPoints { .. } => CagdStatus::ERR_NOT_ENOUGH_POINTS,
        Error::ZeroDimension => CagdStatus::ERR_INVALID_ARGUMENT,
        Error::LengthMismatch { .. } => CagdStatus::ERR_DIMENSION_MISMATCH,
        Error::NonFinite { .. } => CagdStatus::ERR_NON_FINITE,
        Error::NonPositiveWeight { .. } => CagdStatus::ERR_NON_POSITIVE_WEIGHT,
        Error::NonFiniteKnot { .. } => CagdStatus::ERR_NON_FINITE,
        Error::KnotsNotNondecreasing { .. } => CagdStatus::ERR_BAD_KNOTS,
        Error::KnotCount { .. } => CagdStatus::ERR_BAD_KNOTS,
        Error::MultiplicityAboveDegree { .. } => CagdStatus::ERR_MULTIPLICITY,
        Error::BadParameter { .. } => CagdStatus::ERR_INVALID_ARGUMENT,
        Error::BadDegreePair { .. } => CagdStatus::ERR_BAD_DEGREE_PAIR,
        Error::TooManyConstraints { .. } => CagdStatus::ERR_TOO_MANY_CONSTRAINTS,
        Error::BadTolerance { .. } => CagdStatus::ERR_INVALID_ARGUMENT,
        Error::ConditionNotMet { .. } => CagdStatus::ERR_CONDITION_NOT_MET,
        Error::NoConvergence { .. } => CagdStatus::ERR_NO_CONVERGENCE,
        Error::Singular { .. } => CagdStatus::ERR_SINGULAR,
        Error::NotDegenerate { .. } => CagdStatus::ERR_NOT_DEGENERATE,
        Error::DegenerateSplit { .. } => CagdStatus::ERR_DEGENERATE_SPLIT,
        Error::UnsupportedTrim { .. } => CagdStatus::ERR_UNSUPPORTED_TRIM,
        Error::ConversionCondition { .. } => CagdStatus::ERR_CONVERSION_CONDITION,
        Error::NotPlanar { .. } => CagdStatus::ERR_NOT_PLANAR,
        Error::BasePoint { .. } => CagdStatus::ERR_BASE_POINT,
        Error::SingularPoint { .. } => CagdStatus::ERR_SINGULAR_POINT,
        Error::NotOnCurve { .. } => CagdStatus::ERR_NOT_ON_CURVE,
        Error::Coincident { .. } => CagdStatus::ERR_COINCIDENT,
        Error::EmptyInterval { .. } => CagdStatus::ERR_EMPTY_INTERVAL,
        Error::LpInfeasible { .. } => CagdStatus::ERR_LP_INFEASIBLE,
        Error::LpUnbounded { .. } => CagdStatus::ERR_LP_UNBOUNDED,
        Error::LpSolverFailed { .. } => CagdStatus::ERR_LP_FAILED,
        Error::NotCertified { .. } => CagdStatus::ERR_NOT_CERTIFIED,
        _ => CagdStatus::ERR_INVALID_ARGUMENT,
    }
}

/// The name of a status code: `"CAGD_OK"`, `"CAGD_ERR_NULL_POINTER"`, ….
///
/// Parameters:
/// - `status` (in): any `int32_t`, normally a `CagdStatus` returned by a `cagd_*` function
///   (the parameter is a plain `int32_t` so that any integer a C program passes is defined
///   behaviour).
///
/// Returns a static, NUL-terminated ASCII string, never NULL; codes that are not a
/// `CagdStatus` give `"CAGD_ERR_UNKNOWN"`. The caller must not free it. Does not change
/// `cagd_last_error_message()`. Thread-safe.
#[unsafe(no_mangle)]
pub extern "C" fn cagd_status_name(status: i32) -> *const c_char {
    match CagdStatus::from_code(status) {
        Some(s) => s.c_name().as_ptr(),
        None => c"CAGD_ERR_UNKNOWN".as_ptr(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::CStr;

    #[test]
    fn discriminants_are_pinned() {
        let expected: [(CagdStatus, i32); 32] = [
            (CagdStatus::OK, 0),
            (CagdStatus::ERR_NULL_POINTER, 1),
            (CagdStatus::ERR_BUFFER_TOO_SMALL, 2),
            (CagdStatus::ERR_INVALID_ARGUMENT, 3),
            (CagdStatus::ERR_DIMENSION_MISMATCH, 4),
            (CagdStatus::ERR_NOT_AVAILABLE, 5),
            (CagdStatus::ERR_NON_FINITE, 20),
            (CagdStatus::ERR_NON_POSITIVE_WEIGHT, 21),
            (CagdStatus::ERR_BAD_KNOTS, 22),
            (CagdStatus::ERR_MULTIPLICITY, 23),
            (CagdStatus::ERR_NOT_ENOUGH_POINTS, 24),
            (CagdStatus::ERR_DEGREE_OUT_OF_RANGE, 25),
            (CagdStatus::ERR_TOO_MANY_CONSTRAINTS, 26),
            (CagdStatus::ERR_BAD_DEGREE_PAIR, 27),
            (CagdStatus::ERR_EMPTY_INTERVAL, 30),
            (CagdStatus::ERR_NOT_PLANAR, 35),
            (CagdStatus::ERR_CONDITION_NOT_MET, 40),
            (CagdStatus::ERR_NO_CONVERGENCE, 41),
            (CagdStatus::ERR_SINGULAR, 42),
            (CagdStatus::ERR_CONVERSION_CONDITION, 43),
            (CagdStatus::ERR_NOT_DEGENERATE, 50),
            (CagdStatus::ERR_DEGENERATE_SPLIT, 51),
            (CagdStatus::ERR_UNSUPPORTED_TRIM, 52),
            (CagdStatus::ERR_BASE_POINT, 53),
            (CagdStatus::ERR_SINGULAR_POINT, 54),
            (CagdStatus::ERR_NOT_ON_CURVE, 55),
            (CagdStatus::ERR_COINCIDENT, 56),
            (CagdStatus::ERR_LP_INFEASIBLE, 60),
            (CagdStatus::ERR_LP_UNBOUNDED, 61),
            (CagdStatus::ERR_LP_FAILED, 62),
            (CagdStatus::ERR_NOT_CERTIFIED, 63),
            (CagdStatus::ERR_PANIC, 99),
        ];
        for (i, (s, code)) in expected.into_iter().enumerate() {
            assert_eq!(s as i32, code, "{s:?}");
            assert_eq!(ALL_STATUSES[i], s, "ALL is in numeric order");
            assert_eq!(CagdStatus::from_code(code), Some(s));
        }
    }

    /// The string `cagd_status_name(code)` points to.
    fn name_of(code: i32) -> String {
        // SAFETY: cagd_status_name returns a static NUL-terminated string, never NULL.
        unsafe { CStr::from_ptr(cagd_status_name(code)) }
            .to_str()
            .unwrap()
            .to_owned()
    }

    #[test]
    fn names_match_the_c_spelling() {
        for s in ALL_STATUSES {
            assert_eq!(name_of(s as i32), format!("CAGD_{s:?}"));
        }
        for code in [-1, 6, 19, 44, 98, 100, i32::MIN, i32::MAX] {
            assert_eq!(name_of(code), "CAGD_ERR_UNKNOWN", "{code}");
        }
    }

    #[test]
    fn every_core_error_maps() {
        use CagdStatus as S;
        let cases: Vec<(Error, CagdStatus)> = vec![
            (
                Error::DegreeOutOfRange {
                    degree: 70,
                    max: 64,
                },
                S::ERR_DEGREE_OUT_OF_RANGE,
            ),
            (
                Error::NotEnoughPoints { got: 0, need: 1 },
                S::ERR_NOT_ENOUGH_POINTS,
            ),
            (Error::ZeroDimension, S::ERR_INVALID_ARGUMENT),
            (
                Error::LengthMismatch {
                    what: "w",
                    got: 1,
                    expected: 2,
                },
                S::ERR_DIMENSION_MISMATCH,
            ),
            (
                Error::NonFinite {
                    index: 0,
                    coord: 0,
                    value: f64::NAN,
                },
                S::ERR_NON_FINITE,
            ),
            (
                Error::NonPositiveWeight {
                    index: 0,
                    weight: -1.0,
                },
                S::ERR_NON_POSITIVE_WEIGHT,
            ),
            (
                Error::NonFiniteKnot {
                    index: 0,
                    value: f64::NAN,
                },
                S::ERR_NON_FINITE,
            ),
            (Error::KnotsNotNondecreasing { index: 1 }, S::ERR_BAD_KNOTS),
            (
                Error::KnotCount {
                    got: 1,
                    expected: 2,
                },
                S::ERR_BAD_KNOTS,
            ),
            (
                Error::MultiplicityAboveDegree {
                    knot: 0.5,
                    mult: 5,
                    degree: 3,
                },
                S::ERR_MULTIPLICITY,
            ),
            (
                Error::BadParameter {
                    name: "t",
                    value: f64::NAN,
                    why: "finite",
                },
                S::ERR_INVALID_ARGUMENT,
            ),
            (
                Error::BadDegreePair {
                    from: 3,
                    to: 5,
                    why: "m < n",
                },
                S::ERR_BAD_DEGREE_PAIR,
            ),
            (
                Error::TooManyConstraints {
                    r: 2,
                    p: 2,
                    m: 3,
                    why: "r + p + 1 < m",
                },
                S::ERR_TOO_MANY_CONSTRAINTS,
            ),
            (Error::BadTolerance { value: 0.0 }, S::ERR_INVALID_ARGUMENT),
            (
                Error::ConditionNotMet {
                    eq: "15.1.8",
                    why: "x",
                },
                S::ERR_CONDITION_NOT_MET,
            ),
            (
                Error::NoConvergence {
                    tolerance: 1e-9,
                    achieved: 1e-3,
                },
                S::ERR_NO_CONVERGENCE,
            ),
            (Error::Singular { what: "Gram" }, S::ERR_SINGULAR),
            (
                Error::NotDegenerate {
                    residual: 0.1,
                    tol: 1e-12,
                },
                S::ERR_NOT_DEGENERATE,
            ),
            (
                Error::DegenerateSplit {
                    what: "jacobian",
                    value: -1.0,
                },
                S::ERR_DEGENERATE_SPLIT,
            ),
            (
                Error::UnsupportedTrim { index: 0, why: "x" },
                S::ERR_UNSUPPORTED_TRIM,
            ),
            (
                Error::ConversionCondition {
                    condition: "15.1.8",
                    what: "inverse weight",
                    index: 0,
                    value: -1.0,
                },
                S::ERR_CONVERSION_CONDITION,
            ),
            (Error::NotPlanar { dim: 3 }, S::ERR_NOT_PLANAR),
            (Error::BasePoint { count: 1 }, S::ERR_BASE_POINT),
            (
                Error::SingularPoint { x: 0.0, y: 0.0 },
                S::ERR_SINGULAR_POINT,
            ),
            (
                Error::NotOnCurve {
                    x: 1.0,
                    y: 2.0,
                    distance: 0.5,
                },
                S::ERR_NOT_ON_CURVE,
            ),
            (Error::Coincident { s0: 0.0, s1: 1.0 }, S::ERR_COINCIDENT),
            (
                Error::EmptyInterval {
                    index: 2,
                    coord: 1,
                    lo: 1.0,
                    hi: 0.0,
                },
                S::ERR_EMPTY_INTERVAL,
            ),
            (Error::LpInfeasible { what: "x" }, S::ERR_LP_INFEASIBLE),
            (Error::LpUnbounded { what: "x" }, S::ERR_LP_UNBOUNDED),
            (
                Error::LpSolverFailed {
                    what: "x",
                    why: "panic".to_string(),
                },
                S::ERR_LP_FAILED,
            ),
            (
                Error::NotCertified {
                    what: "x",
                    residual: 1.0,
                },
                S::ERR_NOT_CERTIFIED,
            ),
        ];
        for (e, s) in cases {
            assert_eq!(status_of_core(&e), s, "{e:?}");
        }
    }
}
