//! Interval triangles in the `cagd` command (seed 004, SPEC-convert part I): the JSON shape
//! `{"type":"interval-triangle","degree":n,"lo":[[x,y,...],...],"hi":[...]}` (i-major, as
//! for triangles), `cagd reduce --to M [--containment-degree N]` (the shape is read in
//! [`crate::input::shape`], drawn in [`crate::output::interval`]).

use cagd_reduce::{IntervalOptions, IntervalReduction, IntervalTriPatch, reduce_interval_triangle};
use serde_json::{Value, json};

use crate::input::shape::interval::to_json;

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
