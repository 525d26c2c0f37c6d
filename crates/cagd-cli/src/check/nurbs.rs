//! Runners of SPEC-convert §15.1–15.3 (NURBS span ↔ rational Bézier, closed forms).
//!
//! Inputs are read as the spec's vectors write them and in the equivalent forms a vector
//! of the same algorithm may use: local knots (`input.knots_local`, `u_knots_local`,
//! `v_knots_local`, or in `params`) or the knot gaps in `params` (`b, c, d`; `a..e`;
//! `p, q, r` and `b, c, d` for the patch); weights as separate lists (`weights`, `g`, `h`,
//! `G`, `H`) or, for the patch, one 3x3 (or flat 9) matrix. Missing weights are 1. Every
//! output is computed by the library; a refusal of the library is `Refused`.

use cagd_core::{BezierCurve, Error};
use serde_json::{Value, json};

use super::fields::{numbers, points, points_json};
use super::{Outcome, Runner, Vector};

/// The runners of this family.
pub(crate) const TABLE: &[(&str, Runner)] = &[
    ("nurbs2_span_to_rational_bezier", run_nurbs2),
    ("rational_bezier2_to_nurbs_span", run_bezier2),
    ("nurbs3_span_to_rational_bezier", run_nurbs3),
    ("rational_bezier3_to_nurbs_span", run_bezier3),
    ("nurbs22_span_to_rational_bezier22", run_nurbs22),
    ("rational_bezier22_to_nurbs22_span", run_bezier22),
];

/// `input.<key>` or `params.<key>`, if present and not null.
fn field<'a>(v: &Vector<'a>, key: &str) -> Option<&'a Value> {
    v.input
        .get(key)
        .filter(|x| !x.is_null())
        .or_else(|| v.param(key))
}

/// Local knots: the first of `keys` present, else the prefix sums of the gaps `gaps`
/// (starting at 0).
fn local_knots(v: &Vector<'_>, keys: &[&str], gaps: &[&str]) -> Result<Vec<f64>, String> {
    for k in keys {
        if let Some(x) = field(v, k) {
            return numbers(x, k);
        }
    }
    let mut knots = vec![0.0];
    for g in gaps {
        let x = field(v, g)
            .and_then(Value::as_f64)
            .ok_or_else(|| format!("no local knots ({}) and no gap {g:?}", keys.join(", ")))?;
        knots.push(knots[knots.len() - 1] + x);
    }
    Ok(knots)
}

/// Weights under the first present key, else `n` ones.
fn weights_or_ones(v: &Vector<'_>, keys: &[&str], n: usize) -> Result<Vec<f64>, String> {
    for k in keys {
        if let Some(x) = field(v, k) {
            return flat_numbers(x, k);
        }
    }
    Ok(vec![1.0; n])
}

/// A list of numbers, or a list of lists of numbers flattened (a matrix).
fn flat_numbers(x: &Value, what: &str) -> Result<Vec<f64>, String> {
    match x.as_array() {
        Some(a) if a.iter().all(Value::is_array) => Ok(points(x, what)?.0),
        _ => numbers(x, what),
    }
}

fn refused(e: &Error) -> Outcome {
    Outcome::Refused(e.to_string())
}

/// Forward 15.1 / 15.3.
fn run_forward(v: &Vector<'_>, degree: usize) -> Result<Outcome, String> {
    let gaps: &[&str] = if degree == 2 {
        &["b", "c", "d"]
    } else {
        &["a", "b", "c", "d", "e"]
    };
    let knots = local_knots(v, &["knots_local", "knots"], gaps)?;
    let (pts, dim) = points(field(v, "points").ok_or("input.points: missing")?, "points")?;
    let n = pts.len() / dim.max(1);
    let w = weights_or_ones(v, &["weights"], n)?;
    let r = if degree == 2 {
        cagd_convert::quadratic_span_to_bezier(&knots, &pts, &w, dim)
    } else {
        cagd_convert::cubic_span_to_bezier(&knots, &pts, &w, dim)
    };
    Ok(match r {
        Ok(b) => Outcome::Values(json!({
            "bezier_weights": b.weights().unwrap_or(&[]),
            "bezier_points": points_json(b.points(), dim),
        })),
        Err(e) => refused(&e),
    })
}

/// Inverse 15.1 / 15.3.
fn run_inverse(v: &Vector<'_>, degree: usize) -> Result<Outcome, String> {
    let gaps: &[&str] = if degree == 2 {
        &["b", "c", "d"]
    } else {
        &["a", "b", "c", "d", "e"]
    };
    let knots = local_knots(v, &["knots_local", "knots"], gaps)?;
    let (pts, dim) = points(
        field(v, "bezier_points").ok_or("input.bezier_points: missing")?,
        "bezier_points",
    )?;
    let n = pts.len() / dim.max(1);
    let w = weights_or_ones(v, &["bezier_weights"], n)?;
    let bez = match BezierCurve::new_rational(pts, w, dim) {
        Ok(b) => b,
        Err(e) => return Ok(refused(&e)),
    };
    let r = if degree == 2 {
        cagd_convert::bezier_to_quadratic_span(&bez, &knots)
    } else {
        cagd_convert::bezier_to_cubic_span(&bez, &knots)
    };
    Ok(match r {
        Ok(s) => Outcome::Values(json!({
            "weights": s.weights,
            "points": points_json(&s.points, dim),
            "extrapolation": s.extrapolation,
        })),
        Err(e) => refused(&e),
    })
}

fn run_nurbs2(v: &Vector<'_>) -> Result<Outcome, String> {
    run_forward(v, 2)
}

fn run_bezier2(v: &Vector<'_>) -> Result<Outcome, String> {
    run_inverse(v, 2)
}

fn run_nurbs3(v: &Vector<'_>) -> Result<Outcome, String> {
    run_forward(v, 3)
}

fn run_bezier3(v: &Vector<'_>) -> Result<Outcome, String> {
    run_inverse(v, 3)
}

/// A 3x3 weight matrix as JSON in the shape `like` has (nested rows, or flat).
fn matrix_like(w: &[f64], like: Option<&Value>) -> Value {
    let nested = like
        .and_then(Value::as_array)
        .is_some_and(|a| a.iter().any(Value::is_array));
    if nested {
        json!([&w[0..3], &w[3..6], &w[6..9]])
    } else {
        json!(w)
    }
}

/// Forward 15.2: separable `g`, `h` (closed form) or a 3x3 weight matrix (rank 1: closed
/// form on its factors; otherwise the general homogeneous route).
fn run_nurbs22(v: &Vector<'_>) -> Result<Outcome, String> {
    let uk = local_knots(v, &["u_knots_local", "knots_u"], &["p", "q", "r"])?;
    let vk = local_knots(v, &["v_knots_local", "knots_v"], &["b", "c", "d"])?;
    let (pts, dim) = points(field(v, "points").ok_or("input.points: missing")?, "points")?;
    let matrix = match field(v, "weights") {
        Some(w) => Some(flat_numbers(w, "weights")?),
        None => None,
    };
    let want_matrix = v.expected.get("bezier_weights");
    let result = match matrix {
        None => {
            let g = weights_or_ones(v, &["g"], 3)?;
            let h = weights_or_ones(v, &["h"], 3)?;
            cagd_convert::biquadratic_separable_to_bezier(&uk, &vk, &g, &h, &pts, dim).map(|s| {
                let w: Vec<f64> = (0..9)
                    .map(|k| s.u_weights[k / 3] * s.v_weights[k % 3])
                    .collect();
                json!({
                    "G": s.u_weights,
                    "H": s.v_weights,
                    "bezier_points": points_json(&s.points, dim),
                    "bezier_weights": matrix_like(&w, want_matrix),
                })
            })
        }
        Some(w) => cagd_convert::biquadratic_to_bezier(&uk, &vk, &pts, &w, dim).map(|(bp, bw)| {
            let mut out = json!({
                "bezier_points": points_json(&bp, dim),
                "bezier_weights": matrix_like(&bw, want_matrix.or(field(v, "weights"))),
            });
            if let Ok((g, h)) = cagd_convert::separable_factors(&bw) {
                // G and H of a separable result, normalised as the forward map of the
                // factors of the input gives them.
                if let Ok((ig, ih)) = cagd_convert::separable_factors(&w)
                    && let Ok(s) =
                        cagd_convert::biquadratic_separable_to_bezier(&uk, &vk, &ig, &ih, &pts, dim)
                {
                    out["G"] = json!(s.u_weights);
                    out["H"] = json!(s.v_weights);
                } else {
                    out["G"] = json!(g);
                    out["H"] = json!(h);
                }
            }
            out
        }),
    };
    Ok(match result {
        Ok(j) => Outcome::Values(j),
        Err(e) => refused(&e),
    })
}

/// Inverse 15.2: `G`, `H`, or a 3x3 Bézier weight matrix that must be rank 1.
fn run_bezier22(v: &Vector<'_>) -> Result<Outcome, String> {
    let uk = local_knots(v, &["u_knots_local", "knots_u"], &["p", "q", "r"])?;
    let vk = local_knots(v, &["v_knots_local", "knots_v"], &["b", "c", "d"])?;
    let (pts, dim) = points(
        field(v, "bezier_points").ok_or("input.bezier_points: missing")?,
        "bezier_points",
    )?;
    let result = match field(v, "bezier_weights") {
        Some(w) => {
            let w = flat_numbers(w, "bezier_weights")?;
            cagd_convert::bezier_to_biquadratic(&uk, &vk, &pts, &w, dim)
        }
        None => {
            let g = weights_or_ones(v, &["G"], 3)?;
            let h = weights_or_ones(v, &["H"], 3)?;
            cagd_convert::bezier_to_biquadratic_separable(&uk, &vk, &g, &h, &pts, dim)
        }
    };
    Ok(match result {
        Ok(s) => {
            let w: Vec<f64> = (0..9)
                .map(|k| s.u_weights[k / 3] * s.v_weights[k % 3])
                .collect();
            Outcome::Values(json!({
                "g": s.u_weights,
                "h": s.v_weights,
                "points": points_json(&s.points, dim),
                "weights": matrix_like(&w, v.expected.get("weights")),
                "extrapolation": s.extrapolation,
            }))
        }
        Err(e) => refused(&e),
    })
}
