//! `cagd reduce` on one Bézier curve: a named plan applied (the G1 perturbation one degree
//! per step), and the reports in the JSON form of the command.

use cagd_core::BezierCurve;
use cagd_reduce::{
    Method, PiecewiseReport, ReduceOptions, Reduction, Report, max_deviation, reduce_g1_optimal,
};
use serde_json::{Value, json};

use crate::commands::reduce::methods::Plan;

/// The method's parameters, when it has any: `l1`, `l2` of the G1 perturbation (the optimal
/// ones for `perturbation-g1`), `r`, `p` of the end-constrained methods.
pub(crate) fn method_params(m: &Method) -> Value {
    match *m {
        Method::PerturbG1 { l1, l2 } => json!({"l1": l1, "l2": l2}),
        Method::L2 { r, p } | Method::ConstrainedChebyshev { r, p } => json!({"r": r, "p": p}),
        _ => Value::Null,
    }
}

/// The report in the JSON form of the command (fields only ever added).
pub(crate) fn report_json(r: &Report) -> Value {
    json!({
        "method_params": method_params(&r.method),
        "method": r.method.name(),
        "degree_from": r.degree_from,
        "degree_to": r.degree_to,
        "error_bound": r.error_bound,
        "max_error": r.max_error,
        "space": match r.space {
            cagd_reduce::ErrorSpace::Euclidean => "euclidean",
            cagd_reduce::ErrorSpace::Homogeneous => "homogeneous",
        },
    })
}

/// The report of a reduction to a tolerance in the JSON form of the command: the fields of
/// [`report_json`] plus the tolerance, the continuity and the number of pieces.
pub(crate) fn piecewise_report_json(r: &PiecewiseReport) -> Value {
    json!({
        "method": r.method.name(),
        "degree_from": r.degree_from,
        "degree_to": r.degree_to,
        "error_bound": r.error_bound,
        "max_error": r.max_error,
        "space": "euclidean",
        "tolerance": r.tolerance,
        "continuity": r.continuity,
        "pieces": r.pieces,
    })
}

/// Reduces a Bézier curve to degree `m` by a named plan, measuring the error when
/// `measure` is set.
pub(crate) fn reduce_curve(
    c: &BezierCurve,
    m: usize,
    how: Plan,
    measure: bool,
) -> cagd_reduce::Result<Reduction> {
    match how {
        Plan::Linear(method) => {
            let opts = ReduceOptions {
                measure,
                ..ReduceOptions::new(method, m)
            };
            cagd_reduce::reduce_with(c, &opts)
        }
        Plan::PerturbationG1 => {
            // One degree per step; the bounds add up (triangle inequality).
            if m >= c.degree() {
                // Let the library produce its error for the degree pair.
                return cagd_reduce::reduce(c, m, Method::Perturb);
            }
            let first = reduce_g1_optimal(c, false)?;
            let mut bound = first.report.error_bound.unwrap_or(f64::INFINITY);
            let (mut cur, mut report) = (first.curve, first.report);
            while cur.degree() > m {
                let step = reduce_g1_optimal(&cur, false)?;
                bound += step.report.error_bound.unwrap_or(f64::INFINITY);
                (cur, report) = (step.curve, step.report);
            }
            report.degree_from = c.degree();
            report.error_bound = Some(bound);
            report.max_error = if measure {
                Some(max_deviation(c, &cur)?)
            } else {
                None
            };
            Ok(Reduction { curve: cur, report })
        }
    }
}
