//! Runners of the interval-triangle family (SPEC-convert part I, seed 004):
//! `interval_triangle_degree_reduction_lp` and `triangle_elevation_matrix`.
//!
//! Comparison rule of the reduction. A vector whose `params.unique` is `true` is compared
//! value by value (boxes and every other key of `expected`). Any other vector — marked
//! non-unique (`params.unique == false`) or of unknown uniqueness (a non-unique vector may
//! carry no mark other than its id and note) — passes when every non-box key of `expected`
//! matches by the tolerance rule AND either the boxes match within the tolerance, or (the optimum is not
//! unique, so another optimal vertex is as good) the thickness equals the expected
//! thickness within the tolerance, every box is proper (`lo <= hi`) and the result contains
//! the input in exact arithmetic on the returned doubles (at the vector's containment
//! degree). SPEC-convert I.2: "For non-unique cases, tests compare thickness, `L <= U` and
//! containment."

use cagd_core::tri_count;
use cagd_reduce::{
    IntervalOptions, IntervalTriPatch, reduce_interval_triangle, triangle_elevation_matrix,
};
use serde_json::{Map, Value, json};

use super::fields::{matrix_json, points};
use super::{Outcome, Rule, Runner, Vector, compare};

/// The family's dispatch table.
pub(crate) const TABLE: &[(&str, Runner)] = &[
    ("interval_triangle_degree_reduction_lp", run_reduction),
    ("triangle_elevation_matrix", run_elevation),
];

/// A bound: a JSON number, or a string naming a non-finite value (so that a vector can ask
/// for the refusal of NaN / infinite bounds).
fn bound(v: &Value, what: &str) -> Result<f64, String> {
    if let Some(x) = v.as_f64() {
        return Ok(x);
    }
    match v.as_str().map(str::to_ascii_lowercase).as_deref() {
        Some("nan") => Ok(f64::NAN),
        Some("inf" | "+inf" | "infinity" | "+infinity") => Ok(f64::INFINITY),
        Some("-inf" | "-infinity") => Ok(f64::NEG_INFINITY),
        _ => Err(format!("{what}: not a number")),
    }
}

/// `input.boxes` (`[[[lo, hi] per coordinate] per box]`; a bound may be the string "NaN" /
/// "inf" / "-inf") or `input.lo` / `input.hi` (lists of points) as flat nets and the
/// dimension.
fn read_boxes(v: &Vector<'_>) -> Result<(Vec<f64>, Vec<f64>, usize), String> {
    let (mut lo, mut hi) = (Vec::new(), Vec::new());
    let mut dim = 0;
    if let Some(boxes) = v.input.get("boxes") {
        let list = boxes.as_array().ok_or("input.boxes: not a list")?;
        for (q, b) in list.iter().enumerate() {
            let sides = b
                .as_array()
                .ok_or_else(|| format!("input.boxes[{q}]: not a list"))?;
            if q == 0 {
                dim = sides.len();
            } else if sides.len() != dim {
                return Err(format!(
                    "input.boxes[{q}]: {} coordinates, expected {dim}",
                    sides.len()
                ));
            }
            for (c, s) in sides.iter().enumerate() {
                let what = format!("input.boxes[{q}][{c}]");
                let pair = s
                    .as_array()
                    .filter(|p| p.len() == 2)
                    .ok_or_else(|| format!("{what}: not [lo, hi]"))?;
                lo.push(bound(&pair[0], &what)?);
                hi.push(bound(&pair[1], &what)?);
            }
        }
    } else {
        let (l, dl) = points(v.input("lo")?, "input.lo")?;
        let (h, dh) = points(v.input("hi")?, "input.hi")?;
        if dl != dh {
            return Err(format!("input.hi: {dh} coordinates, input.lo has {dl}"));
        }
        (lo, hi, dim) = (l, h, dl);
    }
    Ok((lo, hi, dim))
}

/// The containment degree asked by a vector: `params.containment_degree` or `params.N`, or
/// the number in `params.containment` ("degree-10 control boxes"); `None` is `N = n`.
fn containment_degree(v: &Vector<'_>) -> Result<Option<usize>, String> {
    for key in ["containment_degree", "N"] {
        if v.param(key).is_some() {
            return v.param_usize(key).map(Some);
        }
    }
    let text = v.param("containment").and_then(Value::as_str).unwrap_or("");
    let digits: String = text
        .split(|c: char| !c.is_ascii_digit())
        .find(|s| !s.is_empty())
        .unwrap_or("")
        .to_string();
    Ok(digits.parse().ok())
}

/// Whether the vector says its optimum is unique (`Some(true)`: `params.unique == true`),
/// not unique (`Some(false)`), or nothing.
fn uniqueness(v: &Vector<'_>) -> Option<bool> {
    v.param("unique").and_then(Value::as_bool)
}

fn run_reduction(v: &Vector<'_>) -> Result<Outcome, String> {
    let (lo, hi, dim) = read_boxes(v)?;
    let count = lo.len().checked_div(dim).unwrap_or(0);
    let n = match v.param("n") {
        Some(_) => v.param_usize("n")?,
        None => match (0..=cagd_reduce::MAX_INTERVAL_DEGREE).find(|&n| tri_count(n) == count) {
            Some(n) => n,
            None => {
                return Ok(Outcome::Refused(format!(
                    "{count} boxes is not a triangular count"
                )));
            }
        },
    };
    let m = v.param_usize("m")?;
    let big = containment_degree(v)?;
    let p = match IntervalTriPatch::new(lo, hi, n, dim) {
        Ok(p) => p,
        Err(e) => return Ok(Outcome::Refused(e.to_string())),
    };
    let opts = IntervalOptions {
        containment_degree: big,
        ..IntervalOptions::new(m)
    };
    let r = match reduce_interval_triangle(&p, &opts) {
        Ok(r) => r,
        Err(e) => return Ok(Outcome::Refused(e.to_string())),
    };
    let got = answer(&r, dim);
    if uniqueness(v) == Some(true) {
        return Ok(Outcome::Values(got));
    }
    // Non-unique or unknown: every non-box key by the tolerance rule, the boxes by value or
    // by thickness + proper boxes + exact containment.
    let Value::Object(expected) = v.expected else {
        return Err("expected: not an object".to_string());
    };
    let others: Map<String, Value> = expected
        .iter()
        .filter(|(k, _)| *k != "boxes")
        .map(|(k, x)| (k.clone(), x.clone()))
        .collect();
    let (mut max_diff, mut detail) = (0.0_f64, String::new());
    let mut pass = match compare(&got, &Value::Object(others), v.tol, Rule::Elementwise) {
        Ok(d) => {
            max_diff = d;
            true
        }
        Err((d, why)) => {
            max_diff = max_diff.max(d);
            detail = why;
            false
        }
    };
    if let Some(eb) = expected.get("boxes") {
        match compare(&got["boxes"], eb, v.tol, Rule::Elementwise) {
            Ok(d) => max_diff = max_diff.max(d),
            Err((_, why)) => {
                let t_exp = expected
                    .get("thickness_out")
                    .and_then(Value::as_f64)
                    .ok_or("expected.thickness_out: needed to compare a non-unique optimum")?;
                let t = r.report.thickness_out;
                let dt = (t - t_exp).abs() / t_exp.abs().max(1.0);
                let proper = r.patch.lo().iter().zip(r.patch.hi()).all(|(l, h)| l <= h);
                let contains = r.patch.contains(&p, big).map_err(|e| e.to_string())?;
                // The expected boxes must be another optimal wrap: proper, of the expected
                // thickness, containing the input (within the tolerance: they are rounded).
                let other = expected_is_optimal_wrap(eb, &p, r.patch.degree(), big, t_exp, v.tol)?;
                max_diff = max_diff.max(dt);
                if !(dt <= v.tol && proper && contains && other.is_ok()) {
                    pass = false;
                    detail = format!(
                        "boxes differ ({why}) and thickness {t} vs {t_exp} (diff {dt:.2e}), proper {proper}, \
                         contains {contains}, expected boxes: {}",
                        other
                            .err()
                            .unwrap_or_else(|| "a valid optimal wrap".to_string())
                    );
                }
            }
        }
    }
    Ok(Outcome::Compared {
        max_diff,
        pass,
        detail,
    })
}

/// Whether the expected boxes `eb` are an optimal wrap of `p` at degree `m`: every box
/// proper, their thickness `t_exp` (relative `tol`), and
/// `E_{m->N} lo_exp <= E_{n->N} lo + slack`, `E_{m->N} hi_exp >= E_{n->N} hi - slack` with
/// `slack = tol * max(1, |value|)` (the expected doubles are rounded rationals). `Ok(Err)`
/// says what fails.
fn expected_is_optimal_wrap(
    eb: &Value,
    p: &IntervalTriPatch,
    m: usize,
    big: Option<usize>,
    t_exp: f64,
    tol: f64,
) -> Result<Result<(), String>, String> {
    let dim = p.dim();
    let (mut lo, mut hi) = (Vec::new(), Vec::new());
    for (q, b) in eb
        .as_array()
        .ok_or("expected.boxes: not a list")?
        .iter()
        .enumerate()
    {
        for (c, side) in b
            .as_array()
            .ok_or("expected.boxes: not a list of boxes")?
            .iter()
            .enumerate()
        {
            let pair = side.as_array().filter(|a| a.len() == 2 && c < dim);
            let pair = pair.ok_or_else(|| format!("expected.boxes[{q}][{c}]: not [lo, hi]"))?;
            lo.push(bound(&pair[0], "expected.boxes")?);
            hi.push(bound(&pair[1], "expected.boxes")?);
        }
    }
    if lo.len() != tri_count(m) * dim {
        return Ok(Err(format!(
            "{} bounds, expected {}",
            lo.len(),
            tri_count(m) * dim
        )));
    }
    if let Some(q) = (0..lo.len()).find(|&q| lo[q] > hi[q]) {
        return Ok(Err(format!("box {} is empty", q / dim)));
    }
    let t: f64 = hi.iter().zip(&lo).map(|(h, l)| h - l).sum::<f64>() / lo.len() as f64;
    if (t - t_exp).abs() > tol * t_exp.abs().max(1.0) {
        return Ok(Err(format!("their thickness is {t}, not {t_exp}")));
    }
    let n = p.degree();
    let big = big.unwrap_or(n).max(n);
    let (eo, ei) = match (
        triangle_elevation_matrix(m, big),
        triangle_elevation_matrix(n, big),
    ) {
        (Ok(a), Ok(b)) => (a, b),
        _ => return Ok(Err("degrees out of range".to_string())),
    };
    let (rows, nm, nn) = (tri_count(big), tri_count(m), tri_count(n));
    for c in 0..dim {
        for r in 0..rows {
            let dot = |e: &[f64], cols: usize, net: &[f64]| -> f64 {
                (0..cols).map(|k| e[r * cols + k] * net[k * dim + c]).sum()
            };
            let (ol, oh) = (dot(&eo, nm, &lo), dot(&eo, nm, &hi));
            let (il, ih) = (dot(&ei, nn, p.lo()), dot(&ei, nn, p.hi()));
            if ol > il + tol * il.abs().max(1.0) || oh < ih - tol * ih.abs().max(1.0) {
                return Ok(Err(format!(
                    "they do not contain the input (row {r}, coordinate {c})"
                )));
            }
        }
    }
    Ok(Ok(()))
}

/// Every quantity the library computes, under the names a vector may ask for.
fn answer(r: &cagd_reduce::IntervalReduction, dim: usize) -> Value {
    let boxes: Vec<Value> = r
        .patch
        .lo()
        .chunks(dim)
        .zip(r.patch.hi().chunks(dim))
        .map(|(l, h)| Value::Array(l.iter().zip(h).map(|(a, b)| json!([a, b])).collect()))
        .collect();
    let rep = &r.report;
    let coupled = rep.coupled.iter().any(|&c| c);
    let per_coord = dim as f64 * tri_count(r.patch.degree()) as f64;
    json!({
        "boxes": boxes,
        "lo": super::fields::points_json(r.patch.lo(), dim),
        "hi": super::fields::points_json(r.patch.hi(), dim),
        "thickness_in": rep.thickness_in,
        "thickness_out": rep.thickness_out,
        "thickness": rep.thickness_out,
        "ratio": rep.ratio,
        "coupled": coupled,
        "needs_coupling": coupled,
        "coupled_per_coordinate": rep.coupled,
        "objective": rep.objective,
        "objective_coupled": rep.objective,
        "coupled_objective": rep.objective,
        "objective_decoupled": rep.objective_decoupled,
        "decoupled_objective": rep.objective_decoupled,
        "thickness_coupled": rep.objective / per_coord,
        "thickness_decoupled": rep.objective_decoupled / per_coord,
        "decoupled_thickness": rep.objective_decoupled / per_coord,
        "coupled_thickness": rep.objective / per_coord,
        "objective_value": rep.objective,
        "sum_widths": rep.objective,
        "decoupled_proper": !coupled,
        "decoupled_has_empty_box": coupled,
        "containment_degree": rep.containment_degree,
        "degree": r.patch.degree(),
        "dim": dim,
    })
}

fn run_elevation(v: &Vector<'_>) -> Result<Outcome, String> {
    let m = v.param_usize("m")?;
    let n = v.param_usize("n")?;
    match triangle_elevation_matrix(m, n) {
        Ok(e) => Ok(Outcome::Values(json!({
            "E": matrix_json(tri_count(n), tri_count(m), &e),
            "rows": tri_count(n),
            "cols": tri_count(m),
        }))),
        Err(e) => Ok(Outcome::Refused(e.to_string())),
    }
}
