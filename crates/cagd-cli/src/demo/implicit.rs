//! The implicitization part of `cagd demo` (SPEC-convert §15.8–15.9): the weighted conic of
//! `impl-n2-conic-weighted` (the unit circle) and a rational cubic implicitized exactly, a
//! point classified, and two cubics intersected; pictures of the sign of `f` and the zero set.

use std::fmt::Write as _;
use std::path::Path;

use crate::demo::timing::time_us;
use cagd_core::BezierCurve;
use cagd_implicit::{ImplicitCurve, implicitize, intersect};

fn curve(points: &[f64], weights: &[f64]) -> Result<BezierCurve, String> {
    BezierCurve::new_rational(points.to_vec(), weights.to_vec(), 2).map_err(|e| e.to_string())
}

/// Appends the implicitization rows to `table` and writes the pictures into `out`.
pub(crate) fn run(out: &Path, table: &mut String) -> Result<(), String> {
    let _ = writeln!(
        table,
        "-- implicitization (SPEC-convert 15.8): f = det F, exact"
    );
    let circle = curve(&[1.0, 0.0, 1.0, 1.0, 0.0, 1.0], &[1.0, 1.0, 2.0])?;
    let cubic = curve(
        &[0.0, 0.0, 1.0, 3.0, 3.0, 3.0, 4.0, 0.0],
        &[1.0, 2.0, 2.0, 1.0],
    )?;
    for (id, c) in [("impl-conic", &circle), ("impl-cubic", &cubic)] {
        let imp = implicitize(c).map_err(|e| e.to_string())?;
        let us = time_us(21, || {
            let _ = implicitize(c);
        });
        let terms: Vec<String> = imp
            .polynomial
            .exact_strings()
            .iter()
            .map(|(i, j, s)| format!("({s}) x^{i} y^{j}"))
            .collect();
        let _ = writeln!(table, "{id:<22} f = {}  [{us:.1} us]", terms.join(" + "));
        let ic = ImplicitCurve::new(c).map_err(|e| e.to_string())?;
        let cl = ic.classify(0.5, 0.5);
        let _ = writeln!(
            table,
            "{:<22} f(0.5, 0.5) = {:.6}, sign {}, algebraic distance {:.6}",
            "", cl.value, cl.sign, cl.distance
        );
        let file = out.join(format!("{id}.svg"));
        std::fs::write(&file, crate::output::implicit::render(c, &ic, &[], &[]))
            .map_err(|e| format!("{}: {e}", file.display()))?;
        let _ = writeln!(table, "{:<22} pictures: {}", "", file.display());
    }
    let other = curve(
        &[-0.5, 1.5, 1.5, -1.0, 3.0, 4.0, 4.5, 1.0],
        &[1.0, 0.5, 1.5, 1.0],
    )?;
    let hits = intersect(&cubic, &other).map_err(|e| e.to_string())?;
    let us = time_us(11, || {
        let _ = intersect(&cubic, &other);
    });
    let _ = writeln!(
        table,
        "{:<22} {} intersections of two rational cubics [{us:.1} us]",
        "impl-intersect",
        hits.len()
    );
    for h in &hits {
        let _ = writeln!(
            table,
            "{:<22} s = {:.12}, t = {:.12}, point ({:.9}, {:.9}){}",
            "",
            h.s,
            h.t,
            h.point[0],
            h.point[1],
            if h.tangential { ", tangential" } else { "" }
        );
    }
    let ic = ImplicitCurve::new(&cubic).map_err(|e| e.to_string())?;
    let pts: Vec<[f64; 2]> = hits.iter().map(|h| h.point).collect();
    let file = out.join("impl-intersect.svg");
    std::fs::write(
        &file,
        crate::output::implicit::render(&cubic, &ic, &[&other], &pts),
    )
    .map_err(|e| format!("{}: {e}", file.display()))?;
    let _ = writeln!(table, "{:<22} pictures: {}", "", file.display());
    Ok(())
}
