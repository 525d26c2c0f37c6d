//! Interval triangles in the `cagd` command (seed 004, SPEC-convert part I): the JSON shape
//! `{"type":"interval-triangle","degree":n,"lo":[[x,y,...],...],"hi":[...]}` (i-major, as
//! for triangles), `cagd reduce --to M [--containment-degree N]`, and its pictures.

use cagd_core::{Error, tri_count};
use cagd_reduce::{IntervalOptions, IntervalReduction, IntervalTriPatch, reduce_interval_triangle};
use serde_json::{Value, json};

use crate::args::ReduceArgs;
use crate::input::{InputError, PointList, RawShape, count, field, point_list};
use crate::reduce_cmd::{Failure, Output};
use crate::shape::{Shape, rows};
use crate::svg::{Panel, project};

/// Reads an `interval-triangle` object (the counts are checked here, the values by
/// [`build`]).
pub(crate) fn parse(obj: &Value, path: &str) -> Result<RawShape, InputError> {
    let degree = count(field(obj, path, "degree")?, &format!("{path}.degree"))?;
    let lo = point_list(field(obj, path, "lo")?, &format!("{path}.lo"))?;
    let hi = point_list(field(obj, path, "hi")?, &format!("{path}.hi"))?;
    let expected = (degree + 1).saturating_mul(degree + 2) / 2;
    for (name, net) in [("lo", &lo), ("hi", &hi)] {
        if net.len() != expected {
            return Err(InputError::new(
                format!("{path}.{name}"),
                format!(
                    "has {} points, expected (n + 1)(n + 2) / 2 = {expected}",
                    net.len()
                ),
            ));
        }
    }
    if hi.dim != lo.dim {
        return Err(InputError::new(
            format!("{path}.hi"),
            format!("points have {} coordinates, lo has {}", hi.dim, lo.dim),
        ));
    }
    Ok(RawShape::IntervalTriangle { degree, lo, hi })
}

/// Validates the nets with cagd-reduce; errors name the offending field.
pub(crate) fn build(
    degree: usize,
    lo: PointList,
    hi: PointList,
    path: &str,
) -> Result<IntervalTriPatch, InputError> {
    IntervalTriPatch::new(lo.coords, hi.coords, degree, lo.dim).map_err(|e| {
        let at = match &e {
            Error::EmptyInterval { index, coord, .. } => format!("{path}.lo[{index}][{coord}]"),
            Error::DegreeOutOfRange { .. } => format!("{path}.degree"),
            _ => path.to_string(),
        };
        InputError::new(at, e.to_string())
    })
}

/// The shape in the input JSON form.
pub(crate) fn to_json(t: &IntervalTriPatch) -> Value {
    json!({
        "type": "interval-triangle",
        "degree": t.degree(),
        "lo": rows(t.lo(), t.dim()),
        "hi": rows(t.hi(), t.dim()),
    })
}

/// The report in the JSON form of the command.
pub(crate) fn report_json(r: &IntervalReduction, degree_from: usize) -> Value {
    let rep = &r.report;
    json!({
        "method": "interval-lp",
        "solver": "microlp (simplex), certified by exact arithmetic",
        "degree_from": degree_from,
        "degree_to": r.patch.degree(),
        "model": format!("degree-{} control boxes", rep.containment_degree),
        "containment_degree": rep.containment_degree,
        "thickness_in": rep.thickness_in,
        "thickness_out": rep.thickness_out,
        "ratio": rep.ratio,
        "coupled": rep.coupled.iter().any(|&c| c),
        "coupled_per_coordinate": rep.coupled,
        "repair": rep.repair,
        "max_violation": rep.max_violation,
        "samples": rep.samples,
        "objective": rep.objective,
        "objective_decoupled": rep.objective_decoupled,
        "lp_rows": rep.lp_size.0,
        "lp_cols": rep.lp_size.1,
        "certified": true,
    })
}

/// `cagd reduce` of one interval triangle.
pub(crate) fn reduce(
    t: &IntervalTriPatch,
    args: &ReduceArgs,
    path: &str,
) -> Result<Output, Failure> {
    let usage = |flag: &str, message: &str| Failure {
        path: flag.into(),
        message: message.into(),
    };
    if args.to.1.is_some_and(|n| n != args.to.0) {
        return Err(usage(
            "--to",
            "an interval triangle has one degree: give --to M",
        ));
    }
    if args.method.is_some() || args.tol.is_some() {
        return Err(usage(
            "--method",
            "an interval triangle is reduced by the LP of seed 004 only (no --method / --tol)",
        ));
    }
    let opts = IntervalOptions {
        containment_degree: args.containment_degree,
        ..IntervalOptions::new(args.to.0)
    };
    let red = reduce_interval_triangle(t, &opts).map_err(|e| Failure {
        path: path.to_string(),
        message: e.to_string(),
    })?;
    let mut v = to_json(&red.patch);
    v["report"] = report_json(&red, t.degree());
    Ok(Output {
        json: v,
        pair: Some((
            Shape::IntervalTriangle(t.clone()),
            Shape::IntervalTriangle(red.patch),
        )),
    })
}

/// The control-net lines of a triangular net (rows along i, j and k), projected.
fn net_lines(net: &[f64], n: usize, dim: usize) -> Vec<Vec<(f64, f64)>> {
    let at = |i: usize, j: usize| project(&net[cagd_core::tri_index(n, i, j) * dim..][..dim]);
    let mut lines = Vec::new();
    for a in 0..n {
        lines.push((0..=n - a).map(|j| at(a, j)).collect()); // i = a
        lines.push((0..=n - a).map(|i| at(i, a)).collect()); // j = a
        lines.push((0..=n - a).map(|i| at(i, n - a - i)).collect()); // k = a
    }
    lines
}

/// The mean box width (over coordinates) of the surface at `(u, v)`.
fn width_at(t: &IntervalTriPatch, u: f64, v: f64) -> f64 {
    t.eval(u, v)
        .map(|(l, h)| h.iter().zip(&l).map(|(a, b)| a - b).sum::<f64>() / t.dim() as f64)
        .unwrap_or(0.0)
}

/// Two panels: the lower and upper control nets of input (grey / black) and result (light /
/// dark red); the mean box width of both surfaces along the median from the vertex `w = 1`
/// to the midpoint of the opposite edge, with the thicknesses in the title.
pub(crate) fn panels(title: &str, a: &IntervalTriPatch, b: &IntervalTriPatch) -> Vec<Panel> {
    let mut nets = Panel {
        title: format!(
            "{title}: {} (black) -> {} (red), lower nets dashed",
            a.degree(),
            b.degree()
        ),
        equal_aspect: true,
        ..Panel::default()
    };
    for (t, lo_color, hi_color) in [(a, "#888888", "black"), (b, "#e08080", "#d01010")] {
        for l in net_lines(t.lo(), t.degree(), t.dim()) {
            nets.polygon(l, lo_color);
        }
        for l in net_lines(t.hi(), t.degree(), t.dim()) {
            nets.line(l, hi_color, 0.9);
        }
    }
    let mut width = Panel {
        title: format!(
            "box width on the median u = v; thickness {:.4} -> {:.4}",
            a.thickness(),
            b.thickness()
        ),
        equal_aspect: false,
        ..Panel::default()
    };
    const STEPS: usize = 200;
    // The axis w = 0, so that the widths are seen against zero.
    width.line(vec![(0.0, 0.0), (1.0, 0.0)], "#bbbbbb", 0.6);
    for (t, color) in [(a, "black"), (b, "#d01010")] {
        let pts = (0..=STEPS)
            .map(|s| {
                let x = s as f64 / STEPS as f64;
                (x, width_at(t, x / 2.0, x / 2.0))
            })
            .collect();
        width.line(pts, color, 1.2);
    }
    debug_assert_eq!(a.lo().len(), tri_count(a.degree()) * a.dim());
    vec![nets, width]
}
