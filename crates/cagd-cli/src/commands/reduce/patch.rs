//! `cagd reduce` for tensor-product and triangular patches (seed 000 §14.3).
//!
//! `--method perturbation` is the seed's one-degree method (14.3.1 / 14.3.2); `l2` (the
//! default) and `chebyshev` reduce several degrees at once: tensor patches direction by
//! direction with the curve operator, triangles by the L2-optimal reduction over the
//! triangle whose boundary curves are the curve method's reductions (so neighbours sharing an
//! edge still share it). `--r -1` asks for no end / boundary constraint.

use cagd_core::{TensorPatch, TriPatch};
use cagd_reduce::{
    Method, PatchConstraint, PatchOptions, PatchReport, TensorMethod, TriMethod, TriOptions,
    reduce_tensor, reduce_tensor_to_tolerance, reduce_triangle, reduce_triangle_to_tolerance,
};
use serde_json::{Value, json};

use crate::commands::reduce::methods::Plan;
use crate::input::shape::Shape;

/// The report of a patch reduction in the JSON form of the command.
pub(crate) fn patch_report_json(r: &PatchReport) -> Value {
    json!({
        "method": r.method,
        "degree_from": [r.degrees_from.0, r.degrees_from.1],
        "degree_to": [r.degrees_to.0, r.degrees_to.1],
        "error_bound": r.error_bound,
        "max_error": r.max_error,
        "space": "euclidean",
    })
}

fn linear(how: Plan, name: &str) -> Result<Method, String> {
    match how {
        Plan::Linear(m) => Ok(m),
        Plan::PerturbationG1 => Err(format!("{name} is not available for patches")),
    }
}

/// The tensor method for a method name: `perturbation` is §14.3.1, every other linear curve
/// method is applied direction by direction.
pub(crate) fn tensor_method(name: &str, how: Plan) -> Result<TensorMethod, String> {
    if name == "perturbation" {
        return Ok(TensorMethod::Perturb(PatchConstraint::None));
    }
    let m = linear(how, name)?;
    Ok(TensorMethod::Curves { u: m, v: m })
}

/// The triangle method for a method name: `perturbation` is §14.3.2; `l2` / `chebyshev`
/// are the L2-optimal reduction over the triangle with the boundary curves reduced by the
/// curve method (`r = -1`: unconstrained).
pub(crate) fn tri_method(name: &str, how: Plan) -> Result<TriMethod, String> {
    match (name, how) {
        ("perturbation", _) => Ok(TriMethod::Perturb),
        (
            "l2" | "chebyshev",
            Plan::Linear(m @ (Method::L2 { r, p } | Method::ConstrainedChebyshev { r, p })),
        ) => {
            if r != p {
                return Err(format!(
                    "a triangle's boundary curves are shared in both directions: --r ({r}) \
                     and --p ({p}) must be equal"
                ));
            }
            if r < 0 {
                Ok(TriMethod::L2(PatchConstraint::None))
            } else {
                Ok(TriMethod::L2(PatchConstraint::Boundary(m)))
            }
        }
        _ => Err(format!(
            "{name} is not available for triangles (perturbation, l2, chebyshev)"
        )),
    }
}

/// Reduces a tensor patch to `target`, or to a tolerance (pieces).
pub(crate) fn tensor(
    p: &TensorPatch,
    target: (usize, usize),
    method: TensorMethod,
    tol: Option<f64>,
) -> cagd_reduce::Result<(Value, Option<Shape>)> {
    let opts = PatchOptions {
        measure: true,
        ..PatchOptions::new(method)
    };
    match tol {
        None => {
            let red = reduce_tensor(p, target, &opts)?;
            let result = Shape::Tensor(red.patch);
            let mut v = result.to_json();
            v["report"] = patch_report_json(&red.report);
            Ok((v, Some(result)))
        }
        Some(tol) => {
            let pieces = reduce_tensor_to_tolerance(p, target, tol, &opts)?;
            let items: Vec<Value> = pieces
                .iter()
                .map(|piece| {
                    let mut v = Shape::Tensor(piece.reduction.patch.clone()).to_json();
                    v["u"] = json!([piece.u.0, piece.u.1]);
                    v["v"] = json!([piece.v.0, piece.v.1]);
                    v["report"] = patch_report_json(&piece.reduction.report);
                    v
                })
                .collect();
            Ok((pieces_json("tensor-pieces", items, tol), None))
        }
    }
}

/// Reduces a triangular patch to degree `m`, or to a tolerance (pieces).
pub(crate) fn triangle(
    t: &TriPatch,
    m: usize,
    method: TriMethod,
    tol: Option<f64>,
) -> cagd_reduce::Result<(Value, Option<Shape>)> {
    let opts = TriOptions {
        measure: true,
        ..TriOptions::new(method)
    };
    match tol {
        None => {
            let red = reduce_triangle(t, m, &opts)?;
            let result = Shape::Triangle(red.patch);
            let mut v = result.to_json();
            v["report"] = patch_report_json(&red.report);
            Ok((v, Some(result)))
        }
        Some(tol) => {
            let pieces = reduce_triangle_to_tolerance(t, m, tol, &opts)?;
            let items: Vec<Value> = pieces
                .iter()
                .map(|piece| {
                    let mut v = Shape::Triangle(piece.reduction.patch.clone()).to_json();
                    v["vertices"] = json!(piece.vertices.map(|(u, v)| [u, v]));
                    v["report"] = patch_report_json(&piece.reduction.report);
                    v
                })
                .collect();
            Ok((pieces_json("triangle-pieces", items, tol), None))
        }
    }
}

fn pieces_json(kind: &str, items: Vec<Value>, tol: f64) -> Value {
    let bound = items
        .iter()
        .filter_map(|v| v["report"]["error_bound"].as_f64())
        .fold(0.0, f64::max);
    let measured = items
        .iter()
        .filter_map(|v| v["report"]["max_error"].as_f64())
        .fold(0.0, f64::max);
    json!({
        "type": kind,
        "report": {"tolerance": tol, "pieces": items.len(), "error_bound": bound, "max_error": measured},
        "pieces": items,
    })
}
