//! `cagd reduce --polynomial --tol T [--to M[,N]]`: a NURBS curve or surface to a polynomial
//! B-spline of degree `<= M` within the certified bound `T`
//! ([`cagd_reduce::rational_to_polynomial`], [`cagd_reduce::rational_surface_to_polynomial`]),
//! written without weights, with a report: the certified bound, the sampled error, the
//! spans in and out and the continuity kept at each input knot.

use cagd_reduce::{rational_surface_to_polynomial, rational_to_polynomial};
use serde_json::{Value, json};

use crate::commands::args::ReduceArgs;
use crate::commands::reduce::{Failure, Output};
use crate::input::shape::Shape;

/// `(t, k)` pairs as JSON `[[t, k], ...]`.
fn pairs(list: &[(f64, usize)]) -> Value {
    Value::Array(list.iter().map(|(t, k)| json!([t, k])).collect())
}

/// Runs `reduce --polynomial` on every shape (`args.tol` is set: the parser requires it).
pub(crate) fn run(shapes: &[(String, Shape)], args: &ReduceArgs) -> Result<Vec<Output>, Failure> {
    let tol = args.tol.ok_or_else(|| Failure {
        path: "--tol".into(),
        message: "--polynomial needs --tol T".into(),
    })?;
    // `--to` absent: (0, None) -> the input's degrees.
    let m = (args.to.0 > 0).then_some(args.to.0);
    let mut out = Vec::with_capacity(shapes.len());
    for (path, shape) in shapes {
        let fail = |e: cagd_reduce::Error| Failure {
            path: path.clone(),
            message: e.to_string(),
        };
        match shape {
            Shape::BSpline(c) => {
                if args.to.1.is_some_and(|n| Some(n) != m) {
                    return Err(Failure {
                        path: "--to".into(),
                        message: "a curve has one degree: give --to M".into(),
                    });
                }
                let r = rational_to_polynomial(c, m, tol).map_err(fail)?;
                let result = Shape::BSpline(r.curve);
                let mut v = result.to_json();
                v["report"] = json!({
                    "conversion": "rational-to-polynomial",
                    "degree_from": r.report.degree_from,
                    "degree_to": r.report.degree_to,
                    "equal_weights": r.report.equal_weights,
                    "error_bound": r.report.error_bound,
                    "max_error": r.report.max_error,
                    "space": "euclidean",
                    "tolerance": tol,
                    "spans_in": r.spans_in,
                    "spans_out": r.spans_out,
                    "pieces_before_knot_removal": r.report.pieces,
                    "continuity": pairs(&r.report.continuity),
                });
                out.push(Output {
                    json: v,
                    pair: Some((shape.clone(), result)),
                });
            }
            Shape::BSplineSurface(s) => {
                let target = m.map(|mu| (mu, args.to.1.unwrap_or(mu)));
                let r = rational_surface_to_polynomial(s, target, tol).map_err(fail)?;
                let degree_to = r.surface.degrees();
                let result = Shape::BSplineSurface(r.surface);
                let mut v = result.to_json();
                v["report"] = json!({
                    "conversion": "rational-to-polynomial",
                    "degree_from": s.degrees(),
                    "degree_to": degree_to,
                    "equal_weights": r.equal_weights,
                    "error_bound": r.error_bound,
                    "max_error": r.max_error,
                    "space": "euclidean",
                    "tolerance": tol,
                    "spans_in": r.spans_in,
                    "spans_out": r.spans_out,
                    "pieces_before_knot_removal": r.pieces,
                    "continuity_u": pairs(&r.continuity_u),
                    "continuity_v": pairs(&r.continuity_v),
                });
                out.push(Output {
                    json: v,
                    pair: Some((shape.clone(), result)),
                });
            }
            _ => {
                return Err(Failure {
                    path: path.clone(),
                    message: "--polynomial converts a \"bspline\" (with or without weights) \
                              or a \"bspline-surface\""
                        .into(),
                });
            }
        }
    }
    Ok(out)
}
