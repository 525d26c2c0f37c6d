//! `cagd reduce`: read shapes, reduce each, write the results with their reports.

use cagd_core::BezierCurve;
use cagd_reduce::{Method, ReduceOptions, Reduction, Report, max_deviation, reduce_g1_optimal};
use serde_json::{Value, json};

use crate::args::ReduceArgs;
use crate::methods::{Plan, plan};
use crate::shape::Shape;

/// The default method when `--method` is not given: the L2-optimal reduction with the end
/// points interpolated, the choice that keeps neighbouring curves connected.
pub(crate) const DEFAULT_METHOD: &str = "l2";

/// A failure of one object: its JSON path and the message.
#[derive(Debug)]
pub(crate) struct Failure {
    pub(crate) path: String,
    pub(crate) message: String,
}

/// The report in the JSON form of the command (fields only ever added).
pub(crate) fn report_json(r: &Report) -> Value {
    json!({
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

/// Reduces a Bézier curve to degree `m` by a named plan, measuring the error.
pub(crate) fn reduce_curve(c: &BezierCurve, m: usize, how: Plan) -> cagd_reduce::Result<Reduction> {
    match how {
        Plan::Linear(method) => {
            let opts = ReduceOptions {
                measure: true,
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
            report.max_error = Some(max_deviation(c, &cur)?);
            Ok(Reduction { curve: cur, report })
        }
    }
}

/// The result of one input object: its output JSON and, for pictures, the input and result.
pub(crate) struct Output {
    pub(crate) json: Value,
    pub(crate) pair: Option<(Shape, Shape)>,
}

/// Runs `cagd reduce` on validated shapes; returns one output per input object.
pub(crate) fn run(shapes: &[(String, Shape)], args: &ReduceArgs) -> Result<Vec<Output>, Failure> {
    let name = args.method.as_deref().unwrap_or(DEFAULT_METHOD);
    let how = plan(name, args.r, args.p).map_err(|message| Failure {
        path: "--method".into(),
        message,
    })?;
    let mut out = Vec::with_capacity(shapes.len());
    for (path, shape) in shapes {
        let fail = |e: cagd_reduce::Error| Failure {
            path: path.clone(),
            message: e.to_string(),
        };
        match shape {
            Shape::Bezier(c) => {
                if args.tol.is_some() {
                    return Err(Failure {
                        path: "--tol".into(),
                        message: "reduction to a tolerance is not available in this build".into(),
                    });
                }
                let red = reduce_curve(c, args.to.0, how).map_err(fail)?;
                let result = Shape::Bezier(red.curve.clone());
                let mut v = result.to_json();
                v["report"] = report_json(&red.report);
                out.push(Output {
                    json: v,
                    pair: Some((shape.clone(), result)),
                });
            }
            Shape::Tensor(_) | Shape::Triangle(_) => {
                return Err(Failure {
                    path: path.clone(),
                    message: "patch reduction is not available in this build".into(),
                });
            }
        }
    }
    Ok(out)
}
