//! `cagd reduce` for B-spline / NURBS curves: seed 001's matrix pipeline for uniform knots
//! (no `--tol`), and reduction of any B-spline within a tolerance (`--tol`).

use cagd_core::BSplineCurve;
use cagd_reduce::{
    BSplineOptions, BSplineStrategy, Merge, Method, reduce_bspline, reduce_uniform_bspline,
};
use serde_json::{Value, json};

use crate::commands::args::ReduceArgs;
use crate::input::shape::Shape;

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
            let opts = BSplineOptions {
                continuity: args.continuity,
                strategy: strategy(args, method)?,
                measure: true,
                ..BSplineOptions::new(m, tol)
            };
            let red = reduce_bspline(c, &opts)?;
            let result = Shape::BSpline(red.curve);
            let mut v = result.to_json();
            v["report"] = json!({
                "strategy": strategy_name(&red.report.strategy),
                "degree_from": red.report.degree_from,
                "degree_to": red.report.degree_to,
                "error_bound": red.report.error_bound,
                "max_error": red.report.max_error,
                "space": "euclidean",
                "tolerance": tol,
                "spans_in": red.spans_in,
                "spans_out": red.spans_out,
                "pieces_before_knot_removal": red.report.pieces,
                "continuity": red.report.continuity.iter().map(|(t, k)| json!([t, k])).collect::<Vec<_>>(),
            });
            Ok((v, result))
        }
    }
}

/// The strategy of `--strategy` (default `fit`, or `segments` when `--method` is given).
fn strategy(args: &ReduceArgs, method: Method) -> Result<BSplineStrategy, SplineError> {
    let name = args.strategy_name();
    match name {
        "fit" | "piegl-tiller-1995" if args.method.is_some() => Err(SplineError::Usage(format!(
            "--method is used by --strategy segments only, not {name}"
        ))),
        "fit" => Ok(BSplineStrategy::GlobalFit),
        "piegl-tiller-1995" => Ok(BSplineStrategy::PieglTiller1995),
        "segments" => match method {
            Method::L2 { .. } | Method::ConstrainedChebyshev { .. } => {
                Ok(BSplineStrategy::Segments(method))
            }
            _ => Err(SplineError::Usage(format!(
                "B-spline segments are reduced to a tolerance with l2 or chebyshev, not {}",
                method.name()
            ))),
        },
        other => Err(SplineError::Usage(format!(
            "--strategy: {other:?} is not fit, segments or piegl-tiller-1995"
        ))),
    }
}

/// The name of a strategy in the report (as `--strategy` spells it).
fn strategy_name(s: &BSplineStrategy) -> String {
    match s {
        BSplineStrategy::GlobalFit => "fit".into(),
        BSplineStrategy::Segments(m) => format!("segments/{}", m.name()),
        BSplineStrategy::PieglTiller1995 => "piegl-tiller-1995".into(),
    }
}
