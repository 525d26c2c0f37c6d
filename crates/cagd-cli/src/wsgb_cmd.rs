//! WSGB curves in the `cagd` command (seed 003, SPEC-reduce §9).
//!
//! Input `{"type":"wsgb","L":1,"points":[[x,y,...],...]}` (polynomial only: `weights` is an
//! error). `cagd reduce --to m --method perturbation|uniform|<Bézier method>`: the seed's
//! perturbation (§9.4) and best uniform (§9.5) methods, or any Bézier method through the
//! exact conversion (`bezier-perturbation` names the seed-000 Bézier perturbation, since
//! `perturbation` is the seed-003 one for WSGB input). Output
//! `{"type":"wsgb","L":L',"points":[...],"report":{...}}`: `error_bound` (certified) and
//! `max_error` (measured) on the Euclidean distance between the curves; the seed's
//! per-coordinate figures as the extra fields `max_error_inf`, `paper_bound_11`,
//! `uniform_error_12`, `paper_true_error_inf` and per step in `steps`. With `--tol`:
//! `{"type":"wsgb-pieces","pieces":[{"type":"wsgb",...,"start","end","error_bound"}],
//! "report":{...}}`.

use cagd_core::{BezierCurve, WsgbCurve};
use cagd_reduce::{
    WsgbMethod, WsgbReduction, WsgbReport, reduce_wsgb, reduce_wsgb_to_tolerance,
    reduce_wsgb_via_bezier,
};
use serde_json::{Value, json};

use crate::args::ReduceArgs;
use crate::input::{InputError, PointList, RawShape, count, field};
use crate::methods::{Plan, plan};
use crate::reduce_cmd::{Failure, Output, report_json};
use crate::shape::{Shape, locate, rows};

/// Parses the fields of a `wsgb` object after its points.
pub(crate) fn parse(obj: &Value, path: &str, points: PointList) -> Result<RawShape, InputError> {
    if obj.get("weights").is_some() {
        return Err(InputError::new(
            format!("{path}.weights"),
            "rational WSGB curves are not supported (seed 003 has none)",
        ));
    }
    let l = count(field(obj, path, "L")?, &format!("{path}.L"))?;
    Ok(RawShape::Wsgb { l, points })
}

/// Validates a WSGB curve with cagd-core.
pub(crate) fn build(l: usize, points: PointList, path: &str) -> Result<Shape, InputError> {
    WsgbCurve::new(points.coords, points.dim, l)
        .map(Shape::Wsgb)
        .map_err(|e| match e {
            cagd_core::Error::BadParameter { name: "L", .. } => {
                InputError::new(format!("{path}.L"), e.to_string())
            }
            _ => locate(path, &e),
        })
}

/// The curve in the input JSON form.
pub(crate) fn to_json(c: &WsgbCurve) -> Value {
    json!({"type": "wsgb", "L": c.order(), "points": rows(c.points(), c.dim())})
}

/// The Bézier form for pictures (the curve itself if the conversion fails, which it cannot
/// for a valid curve).
pub(crate) fn bezier(c: &WsgbCurve) -> Option<BezierCurve> {
    c.to_bezier().ok()
}

/// The report in the JSON form of the command.
fn wsgb_report_json(r: &WsgbReport) -> Value {
    let steps: Vec<Value> = r
        .steps
        .iter()
        .map(|s| {
            json!({
                "degree_from": s.degree_from,
                "L_from": s.order_from,
                "lec": s.lec,
                "error_bound": s.error_bound,
                "paper_true_error_inf": s.error_inf,
                "paper_bound_11": s.paper_bound_11,
                "uniform_error_12": s.uniform_error_12,
            })
        })
        .collect();
    let sum = |f: fn(&cagd_reduce::WsgbStep) -> f64| r.steps.iter().map(f).sum::<f64>();
    let mut v = json!({
        "method": r.method.name(),
        "degree_from": r.degree_from,
        "degree_to": r.degree_to,
        "L_from": r.order_from,
        "L_to": r.order_to,
        "error_bound": r.error_bound,
        "max_error": r.max_error,
        "space": "euclidean",
        "max_error_inf": r.max_error_inf,
        "steps": steps,
    });
    if !r.steps.is_empty() {
        v["paper_bound_11"] = json!(sum(|s| s.paper_bound_11));
        v["uniform_error_12"] = json!(sum(|s| s.uniform_error_12));
        v["paper_true_error_inf"] = json!(sum(|s| s.error_inf));
    }
    if let Some(b) = &r.bezier {
        v["bezier_report"] = report_json(b);
        v["method_params"] = crate::reduce_cmd::method_params(&b.method);
    }
    v
}

/// Whether `name` is a method only WSGB curves have (`uniform`, `bezier-perturbation`) and
/// every shape is a WSGB curve.
pub(crate) fn applies_to_all(name: &str, shapes: &[(String, Shape)]) -> bool {
    matches!(name, "uniform" | "bezier-perturbation")
        && shapes.iter().all(|(_, s)| matches!(s, Shape::Wsgb(_)))
}

/// How a method name applies to a WSGB curve.
enum WsgbPlan {
    Seed(WsgbMethod),
    Bezier(Plan),
}

fn wsgb_plan(name: &str, args: &ReduceArgs) -> Result<WsgbPlan, String> {
    let seed_only = |m| {
        if args.r.is_some() || args.p.is_some() {
            Err(format!("--r/--p apply to chebyshev and l2, not to {name}"))
        } else {
            Ok(WsgbPlan::Seed(m))
        }
    };
    match name {
        "perturbation" => seed_only(WsgbMethod::Perturbation),
        "uniform" => seed_only(WsgbMethod::Uniform),
        "bezier-perturbation" => Ok(WsgbPlan::Bezier(plan("perturbation", args.r, args.p)?)),
        other => Ok(WsgbPlan::Bezier(plan(other, args.r, args.p)?)),
    }
}

/// One reduction to degree `m`.
fn reduce_to(c: &WsgbCurve, m: usize, how: &WsgbPlan) -> cagd_reduce::Result<WsgbReduction> {
    match *how {
        WsgbPlan::Seed(method) => reduce_wsgb(c, m, method),
        WsgbPlan::Bezier(Plan::Linear(method)) => reduce_wsgb(c, m, WsgbMethod::Bezier(method)),
        WsgbPlan::Bezier(p @ Plan::PerturbationG1) => {
            reduce_wsgb_via_bezier(c, |b| crate::reduce_cmd::reduce_curve(b, m, p, false))
        }
    }
}

/// `cagd reduce` on a WSGB curve (`path` names it in errors).
pub(crate) fn reduce(
    c: &WsgbCurve,
    args: &ReduceArgs,
    name: &str,
    path: &str,
) -> Result<Output, Failure> {
    let usage = |message: String| Failure {
        path: "--method".into(),
        message,
    };
    let fail = |e: cagd_reduce::Error| Failure {
        path: path.to_string(),
        message: e.to_string(),
    };
    if args.to.1.is_some() {
        return Err(Failure {
            path: "--to".into(),
            message: "a WSGB curve has one degree: give --to M".into(),
        });
    }
    let how = wsgb_plan(name, args).map_err(usage)?;
    let m = args.to.0;
    let input = Shape::Wsgb(c.clone());
    let Some(tol) = args.tol else {
        let red = reduce_to(c, m, &how).map_err(fail)?;
        let result = Shape::Wsgb(red.curve.clone());
        let mut v = to_json(&red.curve);
        v["report"] = wsgb_report_json(&red.report);
        return Ok(Output {
            json: v,
            pair: Some((input, result)),
        });
    };
    let method = match how {
        WsgbPlan::Seed(m) => m,
        WsgbPlan::Bezier(Plan::Linear(m)) => WsgbMethod::Bezier(m),
        WsgbPlan::Bezier(Plan::PerturbationG1) => {
            return Err(usage(
                "perturbation-g1 is not linear and cannot reduce to a tolerance".into(),
            ));
        }
    };
    let red = reduce_wsgb_to_tolerance(c, m, method, tol).map_err(fail)?;
    let pieces: Vec<Value> = red
        .pieces
        .iter()
        .map(|p| {
            let mut v = to_json(&p.reduction.curve);
            v["start"] = json!(p.start);
            v["end"] = json!(p.end);
            v["error_bound"] = json!(p.error_bound);
            v["max_error"] = json!(p.reduction.report.max_error);
            v
        })
        .collect();
    let json = json!({
        "type": "wsgb-pieces",
        "pieces": pieces,
        "report": {
            "method": method.name(),
            "degree_from": c.degree(),
            "degree_to": m,
            "tolerance": tol,
            "pieces": red.pieces.len(),
            "depth": red.depth,
            "error_bound": red.error_bound,
            "max_error": red.max_error,
            "space": "euclidean",
        },
    });
    Ok(Output { json, pair: None })
}
