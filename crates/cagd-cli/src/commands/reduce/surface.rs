//! `cagd reduce` for B-spline / NURBS surfaces: patch-wise with the curve operator in each
//! direction ([`cagd_reduce::reduce_bspline_surface`], no `--tol`), or within a tolerance:
//! by the global fit direction by direction ([`cagd_reduce::reduce_bspline_surface_fit`],
//! `--strategy fit`, the default without `--method`) or patch-wise with uniform knot
//! refinement ([`cagd_reduce::reduce_bspline_surface_to_tolerance`], `--strategy
//! segments`, the default with `--method`).
//!
//! `--to M[,N]` gives the target degrees (`--to M`: `M` in both directions), `--method` is
//! `l2` (the default) or `chebyshev`, `--continuity K` the order kept across knot lines (the
//! library's default without it). The end orders of every patch side come from the knot
//! lines, so `--r` / `--p` do not apply.

use cagd_core::BSplineSurface;
use cagd_reduce::{
    Method, SurfaceFitOptions, SurfaceOptions, reduce_bspline_surface, reduce_bspline_surface_fit,
    reduce_bspline_surface_to_tolerance,
};
use serde_json::{Value, json};

use crate::commands::args::ReduceArgs;
use crate::commands::reduce::{DEFAULT_METHOD, Failure};
use crate::input::shape::Shape;
use crate::input::shape::surface::spans;

/// The options of a surface reduction from the command line, or the usage error.
fn options(args: &ReduceArgs) -> Result<SurfaceOptions, Failure> {
    let usage = |path: &str, message: String| Failure {
        path: path.into(),
        message,
    };
    if args.r.is_some() || args.p.is_some() {
        return Err(usage(
            "--r",
            "--r/--p do not apply to B-spline surfaces: the end orders of each patch come \
             from its knot lines and --continuity"
                .into(),
        ));
    }
    if args.lossy_merge {
        return Err(usage(
            "--merge",
            "lossy merging is for uniform B-spline curves; a surface's patches are merged \
             exactly"
                .into(),
        ));
    }
    let method = match args.method.as_deref().unwrap_or(DEFAULT_METHOD) {
        "l2" => Method::L2 { r: 0, p: 0 },
        "chebyshev" => Method::ConstrainedChebyshev { r: 0, p: 0 },
        other => {
            return Err(usage(
                "--method",
                format!("{other} is not available for B-spline surfaces (l2, chebyshev)"),
            ));
        }
    };
    Ok(SurfaceOptions {
        continuity: args.continuity,
        method,
        measure: true,
        ..SurfaceOptions::new((args.to.0, args.to.1.unwrap_or(args.to.0)))
    })
}

/// Reduces `s` (the object at `path`) as the arguments say; returns the output JSON (the
/// `bspline-surface` shape plus its report) and the result shape.
pub(crate) fn reduce(
    s: &BSplineSurface,
    args: &ReduceArgs,
    path: &str,
) -> Result<(Value, Shape), Failure> {
    let opts = options(args)?;
    if let Some(tol) = args.tol {
        match args.strategy_name() {
            "fit" if args.method.is_some() => {
                return Err(Failure {
                    path: "--method".into(),
                    message: "--method is used by --strategy segments only".into(),
                });
            }
            "fit" => return reduce_fit(s, args, tol, path),
            "segments" => {}
            other => {
                return Err(Failure {
                    path: "--strategy".into(),
                    message: format!("{other:?} is not fit or segments for B-spline surfaces"),
                });
            }
        }
    }
    let red = match args.tol {
        None => reduce_bspline_surface(s, &opts),
        Some(tol) => reduce_bspline_surface_to_tolerance(s, &opts, tol),
    }
    .map_err(|e| Failure {
        path: path.to_string(),
        message: e.to_string(),
    })?;
    let ((p, q), out) = (s.degrees(), &red.surface);
    let (mu, mv) = out.degrees();
    let mut report = json!({
        "strategy": "segments",
        "method": opts.method.name(),
        "degree_from": [p, q],
        "degree_to": [mu, mv],
        "error_bound": red.error_bound,
        "max_error": red.max_error,
        "space": "euclidean",
        "patches": red.patches,
        "spans_in": [spans(s.knots_u(), p), spans(s.knots_v(), q)],
        "spans_out": [spans(out.knots_u(), mu), spans(out.knots_v(), mv)],
    });
    if let Some(tol) = args.tol {
        report["tolerance"] = json!(tol);
    }
    Ok(output(red.surface, report, args))
}

/// The output JSON (the surface's shape plus `report`, with `--continuity` if given) and
/// the result shape.
fn output(surface: BSplineSurface, mut report: Value, args: &ReduceArgs) -> (Value, Shape) {
    if let Some(k) = args.continuity {
        report["continuity"] = json!(k);
    }
    let result = Shape::BSplineSurface(surface);
    let mut v = result.to_json();
    v["report"] = report;
    (v, result)
}

/// `--strategy fit`: the global fit direction by direction.
fn reduce_fit(
    s: &BSplineSurface,
    args: &ReduceArgs,
    tol: f64,
    path: &str,
) -> Result<(Value, Shape), Failure> {
    let target = (args.to.0, args.to.1.unwrap_or(args.to.0));
    let opts = SurfaceFitOptions {
        continuity: args.continuity,
        measure: true,
        ..SurfaceFitOptions::new(target, tol)
    };
    let red = reduce_bspline_surface_fit(s, &opts).map_err(|e| Failure {
        path: path.to_string(),
        message: e.to_string(),
    })?;
    let report = json!({
        "strategy": "fit",
        "degree_from": [s.degrees().0, s.degrees().1],
        "degree_to": [target.0, target.1],
        "error_bound": red.error_bound,
        "direction_bounds": [red.direction_bounds.0, red.direction_bounds.1],
        "max_error": red.max_error,
        "space": "euclidean",
        "tolerance": tol,
        "patches": red.spans_out.0 * red.spans_out.1,
        "spans_in": [red.spans_in.0, red.spans_in.1],
        "spans_out": [red.spans_out.0, red.spans_out.1],
    });
    Ok(output(red.surface, report, args))
}
