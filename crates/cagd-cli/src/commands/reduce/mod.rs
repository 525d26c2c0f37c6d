//! `cagd reduce`: read shapes, reduce each, write the results with their reports.

mod curve;
pub(crate) mod interval;
pub(crate) mod methods;
mod outcome;
pub(crate) mod patch;
mod polynomial;
mod spline;
mod surface;
mod threads;
pub(crate) mod wsgb;

pub(crate) use curve::{piecewise_report_json, reduce_curve, report_json};
pub(crate) use outcome::{DEFAULT_METHOD, Failure, Output};

use cagd_reduce::{Method, ToleranceOptions, reduce_to_tolerance};
use std::process::ExitCode;

use serde_json::Value;

use crate::commands::args::ReduceArgs;
use crate::commands::reduce::methods::{Plan, plan};
use crate::commands::reduce::patch::{tensor_method, tri_method};
use crate::input::shape::Shape;

/// Runs `cagd reduce` on validated shapes; returns one output per input object.
pub(crate) fn run(shapes: &[(String, Shape)], args: &ReduceArgs) -> Result<Vec<Output>, Failure> {
    let name = args.method.as_deref().unwrap_or(DEFAULT_METHOD);
    let how = match plan(name, args.r, args.p) {
        Ok(how) => how,
        // Names only WSGB curves know (seed 003): fine when every input is one.
        Err(_) if wsgb::applies_to_all(name, shapes) => Plan::Linear(Method::Eck),
        Err(message) => {
            return Err(Failure {
                path: "--method".into(),
                message,
            });
        }
    };
    // With a tolerance the pieces must join with C^k: the end orders of chebyshev / l2
    // default to the continuity K instead of 0.
    let k = args
        .continuity
        .map(|k| i64::try_from(k).unwrap_or(i64::MAX));
    let how_tol = if args.tol.is_some() && matches!(name, "chebyshev" | "l2") {
        plan(name, args.r.or(k), args.p.or(k)).map_err(|message| Failure {
            path: "--method".into(),
            message,
        })?
    } else {
        how
    };
    let mut out = Vec::with_capacity(shapes.len());
    for (path, shape) in shapes {
        let fail = |e: cagd_reduce::Error| Failure {
            path: path.clone(),
            message: e.to_string(),
        };
        match shape {
            Shape::Bezier(c) => {
                if let Some(tol) = args.tol {
                    let Plan::Linear(method) = how_tol else {
                        return Err(Failure {
                            path: "--method".into(),
                            message: "perturbation-g1 is not linear and cannot reduce to a \
                                      tolerance; use l2 or chebyshev with --r/--p"
                                .into(),
                        });
                    };
                    let k = args.continuity.unwrap_or(0);
                    let opts = ToleranceOptions {
                        measure: true,
                        // The command's bound on the work (crate::limits).
                        max_depth: crate::limits::MAX_TOLERANCE_DEPTH,
                        ..ToleranceOptions::new(method, args.to.0, tol, k)
                    };
                    let red = reduce_to_tolerance(c, &opts).map_err(fail)?;
                    let result = Shape::BSpline(red.spline);
                    let mut v = result.to_json();
                    v["report"] = piecewise_report_json(&red.report);
                    out.push(Output {
                        json: v,
                        pair: Some((shape.clone(), result)),
                    });
                    continue;
                }
                let red = reduce_curve(c, args.to.0, how, true).map_err(fail)?;
                let result = Shape::Bezier(red.curve.clone());
                let mut v = result.to_json();
                v["report"] = report_json(&red.report);
                out.push(Output {
                    json: v,
                    pair: Some((shape.clone(), result)),
                });
            }
            Shape::BSpline(c) => {
                let method = match how_tol {
                    Plan::Linear(m) => m,
                    Plan::PerturbationG1 => {
                        return Err(Failure {
                            path: "--method".into(),
                            message: "perturbation-g1 is not available for B-splines".into(),
                        });
                    }
                };
                let (json, result) = spline::reduce(c, args, method).map_err(|e| match e {
                    spline::SplineError::Usage(message) => Failure {
                        path: "--method".into(),
                        message,
                    },
                    spline::SplineError::Reduce(e) => fail(e),
                })?;
                out.push(Output {
                    json,
                    pair: Some((shape.clone(), result)),
                });
            }
            Shape::Tensor(p) => {
                let target = (args.to.0, args.to.1.unwrap_or(args.to.0));
                let method = tensor_method(name, how).map_err(|message| Failure {
                    path: "--method".into(),
                    message,
                })?;
                let (json, result) = patch::tensor(p, target, method, args.tol).map_err(fail)?;
                out.push(Output {
                    json,
                    pair: result.map(|r| (shape.clone(), r)),
                });
            }
            Shape::IntervalTriangle(t) => {
                if args.to.1.is_some_and(|n| n != args.to.0) {
                    return Err(Failure {
                        path: "--to".into(),
                        message: "an interval triangle has one degree: give --to M".into(),
                    });
                }
                if args.method.is_some() || args.tol.is_some() {
                    return Err(Failure {
                        path: "--method".into(),
                        message: "an interval triangle is reduced by the LP of seed 004 only \
                                  (no --method / --tol)"
                            .into(),
                    });
                }
                let opts = cagd_reduce::IntervalOptions {
                    containment_degree: args.containment_degree,
                    ..cagd_reduce::IntervalOptions::new(args.to.0)
                };
                let (json, result) = interval::reduce(t, &opts).map_err(fail)?;
                out.push(Output {
                    json,
                    pair: Some((shape.clone(), Shape::IntervalTriangle(result))),
                });
            }
            Shape::Wsgb(c) => {
                let (json, pair) = wsgb::reduce(c, args, name, reduce_curve, report_json).map_err(
                    |(at, message)| Failure {
                        path: at.unwrap_or_else(|| path.clone()),
                        message,
                    },
                )?;
                out.push(Output { json, pair });
            }
            Shape::BSplineSurface(s) => {
                let (json, result) = surface::reduce(s, args, path)?;
                out.push(Output {
                    json,
                    pair: Some((shape.clone(), result)),
                });
            }
            Shape::Triangle(t) => {
                if args.to.1.is_some_and(|n| n != args.to.0) {
                    return Err(Failure {
                        path: "--to".into(),
                        message: "a triangular patch has one degree: give --to M".into(),
                    });
                }
                let method = tri_method(name, how).map_err(|message| Failure {
                    path: "--method".into(),
                    message,
                })?;
                let (json, result) =
                    patch::triangle(t, args.to.0, method, args.tol).map_err(fail)?;
                out.push(Output {
                    json,
                    pair: result.map(|r| (shape.clone(), r)),
                });
            }
        }
    }
    Ok(out)
}

/// `cagd reduce`: shapes in (one object or an array), each reduced, results out (and a
/// picture with `--svg`).
pub(crate) fn command(args: &ReduceArgs) -> ExitCode {
    let text = match crate::input::read_input(args.input.as_deref()) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("cagd: {e}");
            return ExitCode::from(2);
        }
    };
    let single = text.trim_start().starts_with('{');
    let raws = match crate::input::parse_input(&text) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("cagd: {e}");
            return ExitCode::from(2);
        }
    };
    let mut shapes = Vec::with_capacity(raws.len());
    for (i, raw) in raws.into_iter().enumerate() {
        let path = if single {
            "input".to_string()
        } else {
            format!("input[{i}]")
        };
        match Shape::build(raw, &path) {
            Ok(s) => shapes.push((path, s)),
            Err(e) => {
                eprintln!("cagd: {e}");
                return ExitCode::from(2);
            }
        }
    }
    let run: threads::Run = if args.polynomial {
        polynomial::run
    } else {
        run
    };
    let results = match threads::run_on_threads(run, &shapes, args) {
        Ok(r) => r,
        Err(f) => {
            eprintln!("cagd: {}: {}", f.path, f.message);
            return ExitCode::from(2);
        }
    };
    if let Some(svg_path) = &args.svg {
        let rows: Vec<_> = results
            .iter()
            .zip(&shapes)
            .filter_map(|(o, (path, _))| {
                o.pair
                    .as_ref()
                    .map(|(a, b)| crate::output::picture::panels(path, a, b))
            })
            .filter(|row| !row.is_empty())
            .collect();
        if let Err(e) =
            crate::output::json::write_output(Some(svg_path), &crate::output::svg::render(&rows))
        {
            eprintln!("cagd: {e}");
            return ExitCode::from(1);
        }
    }
    let values: Vec<Value> = results.into_iter().map(|o| o.json).collect();
    let json = if single && values.len() == 1 {
        values.into_iter().next().unwrap_or(Value::Null)
    } else {
        Value::Array(values)
    };
    crate::output::json::write_json(args.output.as_deref(), &json)
}
