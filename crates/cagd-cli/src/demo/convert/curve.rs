//! The conversion part of `cagd demo`: a non-uniform rational degree-5 curve to its rational
//! Bézier pieces and back (SPEC-convert §15.1–15.3, general route), with the continuity
//! found at each joint and the pictures of both control polygons.

use std::fmt::Write as _;
use std::path::Path;

use cagd_convert::{pieces_to_nurbs, to_bezier_pieces};
use cagd_core::BSplineCurve;

use crate::demo::timing::time_us;
use crate::output::svg::{Panel, project, render};

fn demo_curve() -> Result<BSplineCurve, String> {
    let pts = vec![
        0.0, 0.0, 1.0, 2.5, 2.5, 3.5, 4.5, 3.0, 5.0, 1.0, 6.5, 0.0, 8.0, 1.5, 8.5, 3.5, 10.0, 4.0,
    ];
    let weights = vec![1.0, 0.8, 1.5, 1.0, 0.7, 1.2, 1.0, 0.9, 1.0];
    let knots = vec![
        0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.15, 0.45, 0.45, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0,
    ];
    BSplineCurve::new_rational(5, knots, pts, weights, 2).map_err(|e| e.to_string())
}

/// Appends the conversion rows to `table` and writes `convert.svg` into `out`.
pub(crate) fn run(out: &Path, table: &mut String) -> Result<(), String> {
    let _ = writeln!(
        table,
        "-- NURBS <-> rational Bézier (SPEC-convert §15.1-15.3)"
    );
    let c = demo_curve()?;
    let pieces = to_bezier_pieces(&c).map_err(|e| e.to_string())?;
    let us_fwd = time_us(21, || {
        let _ = to_bezier_pieces(&c);
    });
    let back = pieces_to_nurbs(&pieces, None).map_err(|e| e.to_string())?;
    let us_back = time_us(21, || {
        let _ = pieces_to_nurbs(&pieces, None);
    });
    let same = back.curve.knots() == c.knots();
    let _ = writeln!(
        table,
        "{:<22} {:<24} {:>8} {:>12} {:>12} {:>10.2}",
        "nurbs-5-to-bezier",
        format!("{} rational pieces", pieces.len()),
        "5 -> 5",
        "exact",
        "-",
        us_fwd
    );
    let _ = writeln!(
        table,
        "{:<22} {:<24} {:>8} {:>12.4e} {:>12} {:>10.2}",
        "bezier-to-nurbs-5",
        format!("C^{:?}, same knots: {same}", back.continuity),
        "5 -> 5",
        back.bound,
        "-",
        us_back
    );
    let mut geo = Panel {
        title: "degree-5 NURBS: B-spline polygon (grey), Bézier polygons (red)".into(),
        equal_aspect: true,
        ..Panel::default()
    };
    geo.polygon(c.points().chunks(2).map(project).collect(), "#888888");
    for k in 0..pieces.len() {
        geo.polygon(
            pieces.piece_points(k).chunks(2).map(project).collect(),
            "#e08080",
        );
    }
    let line = (0..=400)
        .filter_map(|i| c.eval(f64::from(i) / 400.0).ok())
        .map(|p| project(&p))
        .collect();
    geo.line(line, "black", 1.4);
    let file = out.join("convert.svg");
    std::fs::write(&file, render(&[vec![geo]])).map_err(|e| format!("{}: {e}", file.display()))?;
    let _ = writeln!(table, "{:<22} pictures: {}", "", file.display());
    Ok(())
}
