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
    Reduction, Report, WsgbMethod, WsgbReduction, WsgbReport, reduce_wsgb,
    reduce_wsgb_to_tolerance, reduce_wsgb_via_bezier,
};
use serde_json::{Value, json};

use crate::commands::args::ReduceArgs;
use crate::commands::reduce::methods::{Plan, plan};
use crate::input::shape::{Shape, rows};

/// `reduce_cmd`'s Bézier reduction by a plan (passed in, so that this module does not
/// import `reduce_cmd`, which calls it).
pub(crate) type ReduceCurve = fn(&BezierCurve, usize, Plan, bool) -> cagd_reduce::Result<Reduction>;

/// `reduce_cmd`'s report JSON of a Bézier reduction (passed in likewise).
pub(crate) type ReportJson = fn(&Report) -> Value;

/// A failure: the argument or JSON path at fault (`None`: the input object) and the message.
pub(crate) type WsgbFailure = (Option<String>, String);

/// The curve in the input JSON form.
fn to_json(c: &WsgbCurve) -> Value {
    json!({"type": "wsgb", "L": c.order(), "points": rows(c.points(), c.dim())})
}

/// The report in the JSON form of the command.
fn wsgb_report_json(r: &WsgbReport, report_json: ReportJson) -> Value {
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
        v["method_params"] = v["bezier_report"]["method_params"].clone();
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
fn reduce_to(
    c: &WsgbCurve,
    m: usize,
    how: &WsgbPlan,
    reduce_curve: ReduceCurve,
) -> cagd_reduce::Result<WsgbReduction> {
    match *how {
        WsgbPlan::Seed(method) => reduce_wsgb(c, m, method),
        WsgbPlan::Bezier(Plan::Linear(method)) => reduce_wsgb(c, m, WsgbMethod::Bezier(method)),
        WsgbPlan::Bezier(p @ Plan::PerturbationG1) => {
            reduce_wsgb_via_bezier(c, |b| reduce_curve(b, m, p, false))
        }
    }
}

/// `cagd reduce` on a WSGB curve: the output JSON and, for pictures, the input and result.
pub(crate) fn reduce(
    c: &WsgbCurve,
    args: &ReduceArgs,
    name: &str,
    reduce_curve: ReduceCurve,
    report_json: ReportJson,
) -> Result<(Value, Option<(Shape, Shape)>), WsgbFailure> {
    let usage = |message: String| (Some("--method".to_string()), message);
    let fail = |e: cagd_reduce::Error| (None, e.to_string());
    if args.to.1.is_some() {
        return Err((
            Some("--to".into()),
            "a WSGB curve has one degree: give --to M".into(),
        ));
    }
    let how = wsgb_plan(name, args).map_err(usage)?;
    let m = args.to.0;
    let input = Shape::Wsgb(c.clone());
    let Some(tol) = args.tol else {
        let red = reduce_to(c, m, &how, reduce_curve).map_err(fail)?;
        let result = Shape::Wsgb(red.curve.clone());
        let mut v = to_json(&red.curve);
        v["report"] = wsgb_report_json(&red.report, report_json);
        return Ok((v, Some((input, result))));
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
    Ok((json, None))
}
