//! Interval triangles in the `cagd` command (seed 004, SPEC-convert part I): the JSON shape
//! `{"type":"interval-triangle","degree":n,"lo":[[x,y,...],...],"hi":[...]}` (i-major, as
//! for triangles), `cagd reduce --to M [--containment-degree N]`, and its pictures.

use cagd_core::{Error, tri_count};
use cagd_reduce::{IntervalOptions, IntervalReduction, IntervalTriPatch, reduce_interval_triangle};
use serde_json::{Value, json};

use crate::input::{InputError, PointList};
use crate::svg::{Panel, project};

/// A flat row-major buffer as a JSON list of points.
fn rows(flat: &[f64], dim: usize) -> Value {
    Value::Array(flat.chunks(dim).map(|p| json!(p)).collect())
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

/// `cagd reduce` of one interval triangle with `opts`: the output JSON (the shape of
/// degree `m` with its `"report"`) and the result.
pub(crate) fn reduce(
    t: &IntervalTriPatch,
    opts: &IntervalOptions,
) -> cagd_reduce::Result<(Value, IntervalTriPatch)> {
    let red = reduce_interval_triangle(t, opts)?;
    let mut v = to_json(&red.patch);
    v["report"] = report_json(&red, t.degree());
    Ok((v, red.patch))
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
