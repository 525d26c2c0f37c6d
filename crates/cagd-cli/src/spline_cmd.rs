//! `cagd reduce` for B-spline / NURBS curves: seed 001's matrix pipeline for uniform knots
//! (no `--tol`), and reduction of any B-spline within a tolerance (`--tol`).

use cagd_core::BSplineCurve;
use cagd_reduce::{BSplineOptions, Merge, Method, reduce_bspline, reduce_uniform_bspline};
use serde_json::{Value, json};

use crate::args::ReduceArgs;
use crate::shape::Shape;

/// Why a B-spline reduction failed: a usage problem (method / options) or the library's
/// error.
pub(crate) enum SplineError {
    Usage(String),
    Reduce(cagd_reduce::Error),
}

impl From<cagd_reduce::Error> for SplineError {
    fn from(e: cagd_reduce::Error) -> Self {
        SplineError::Reduce(e)
    }
}

/// Reduces `c` as the arguments say; returns the output JSON and the result shape.
pub(crate) fn reduce(
    c: &BSplineCurve,
    args: &ReduceArgs,
    method: Method,
) -> Result<(Value, Shape), SplineError> {
    let m = args.to.0;
    match args.tol {
        None => {
            let merge = if args.lossy_merge {
                Merge::Lossy
            } else {
                Merge::Exact
            };
            let red = reduce_uniform_bspline(c, m, method, merge)?;
            let measured = cagd_reduce::spline_max_deviation(c, &red.curve)?;
            let result = Shape::BSpline(red.curve);
            let mut v = result.to_json();
            v["report"] = json!({
                "method": method.name(),
                "degree_from": c.degree(),
                "degree_to": m,
                "error_bound": red.error_bound,
                "max_error": measured,
                "space": "euclidean",
                "merge": if args.lossy_merge { "lossy" } else { "exact" },
                "segments": red.segments.len(),
            });
            Ok((v, result))
        }
        Some(tol) => {
            if !matches!(
                method,
                Method::L2 { .. } | Method::ConstrainedChebyshev { .. }
            ) {
                return Err(SplineError::Usage(format!(
                    "B-splines are reduced to a tolerance with l2 or chebyshev segments, not {}",
                    method.name()
                )));
            }
            let opts = BSplineOptions {
                continuity: args.continuity,
                method,
                measure: true,
                ..BSplineOptions::new(m, tol)
            };
            let red = reduce_bspline(c, &opts)?;
            let result = Shape::BSpline(red.curve);
            let mut v = result.to_json();
            v["report"] = json!({
                "method": red.report.method.name(),
                "degree_from": red.report.degree_from,
                "degree_to": red.report.degree_to,
                "error_bound": red.report.error_bound,
                "max_error": red.report.max_error,
                "space": "euclidean",
                "tolerance": tol,
                "spans_in": red.spans_in,
                "spans_out": red.spans_out,
            });
            Ok((v, result))
        }
    }
}
