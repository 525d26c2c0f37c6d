//! The B-spline part of `cagd demo`: seed 001's worked example (degree 7, 9 control points,
//! uniform knots 0..16, to degree 3 with C1 Hermite segments; exact and lossy merge) and a
//! non-uniform rational (NURBS) degree-5 curve reduced to cubic within tolerances (global
//! fit, and per-segment for comparison).

use std::fmt::Write as _;
use std::path::Path;

use cagd_core::BSplineCurve;
use cagd_reduce::{
    BSplineOptions, BSplineStrategy, Merge, Method, reduce_bspline, reduce_uniform_bspline,
};

use crate::demo::timing::time_us;
use crate::input::shape::Shape;
use crate::output::picture::panels;
use crate::output::svg;

const SEED_001_POINTS: [f64; 18] = [
    3.0, 3.0, 5.0, 9.5, 7.0, 2.0, 8.0, 9.0, 10.0, 3.0, 11.0, 8.0, 13.0, 5.0, 14.0, 6.0, 16.0, 4.0,
];

fn seed_001_curve() -> Result<BSplineCurve, String> {
    let knots: Vec<f64> = (0..=16).map(f64::from).collect();
    BSplineCurve::new(7, knots, SEED_001_POINTS.to_vec(), 2).map_err(|e| e.to_string())
}

fn nurbs_curve() -> Result<BSplineCurve, String> {
    let pts = vec![
        0.0, 0.0, 1.0, 2.5, 2.5, 3.5, 4.5, 3.0, 5.0, 1.0, 6.5, 0.0, 8.0, 1.5, 8.5, 3.5, 10.0, 4.0,
    ];
    let weights = vec![1.0, 0.8, 1.5, 1.0, 0.7, 1.2, 1.0, 0.9, 1.0];
    let knots = vec![
        0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.15, 0.45, 0.6, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0,
    ];
    BSplineCurve::new_rational(5, knots, pts, weights, 2).map_err(|e| e.to_string())
}

fn line(table: &mut String, id: &str, label: &str, nm: &str, bound: f64, measured: f64, us: f64) {
    let _ = writeln!(
        table,
        "{id:<22} {label:<24} {nm:>8} {bound:>12.4e} {measured:>12.4e} {us:>10.2}"
    );
}

/// Appends the B-spline rows to `table` and writes `bsplines.svg` into `out`.
pub(crate) fn run(out: &Path, table: &mut String) -> Result<(), String> {
    let _ = writeln!(table, "-- seed 001, uniform B-spline; a non-uniform NURBS");
    let mut rows = Vec::new();
    let c = seed_001_curve()?;
    let hermite = Method::ConstrainedChebyshev { r: 1, p: 1 };
    for (label, merge) in [
        ("C1 Hermite, exact merge", Merge::Exact),
        ("C1 Hermite, lossy merge", Merge::Lossy),
    ] {
        let red = reduce_uniform_bspline(&c, 3, hermite, merge).map_err(|e| e.to_string())?;
        let us = time_us(11, || {
            let _ = reduce_uniform_bspline(&c, 3, hermite, merge);
        });
        let measured =
            cagd_reduce::spline_max_deviation(&c, &red.curve).map_err(|e| e.to_string())?;
        line(
            table,
            "seed-001-example",
            label,
            "7 -> 3",
            red.error_bound,
            measured,
            us,
        );
        rows.push(panels(
            label,
            &Shape::BSpline(c.clone()),
            &Shape::BSpline(red.curve),
        ));
    }
    let nurbs = nurbs_curve()?;
    let segments = BSplineStrategy::Segments(Method::L2 { r: 0, p: 0 });
    for (tol, strategy, name) in [
        (1e-2, BSplineStrategy::GlobalFit, "fit"),
        (1e-4, BSplineStrategy::GlobalFit, "fit"),
        (1e-4, segments, "segments"),
    ] {
        let opts = BSplineOptions {
            measure: true,
            strategy,
            ..BSplineOptions::new(3, tol)
        };
        let red = reduce_bspline(&nurbs, &opts).map_err(|e| e.to_string())?;
        let unmeasured = BSplineOptions {
            measure: false,
            ..opts
        };
        let us = time_us(5, || {
            let _ = reduce_bspline(&nurbs, &unmeasured);
        });
        let label = format!(
            "{name} {tol:e}, {} -> {} spans",
            red.spans_in, red.spans_out
        );
        line(
            table,
            "nurbs-5-nonuniform",
            &label,
            "5 -> 3",
            red.report.error_bound,
            red.report.max_error.unwrap_or(f64::NAN),
            us,
        );
        rows.push(panels(
            &label,
            &Shape::BSpline(nurbs.clone()),
            &Shape::BSpline(red.curve),
        ));
    }
    let file = out.join("bsplines.svg");
    std::fs::write(&file, svg::render(&rows)).map_err(|e| format!("{}: {e}", file.display()))?;
    let _ = writeln!(table, "{:<22} pictures: {}", "", file.display());
    Ok(())
}
