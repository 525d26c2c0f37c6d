//! Runners of the WSGB family (seed 003, SPEC-reduce §9): `wsgb_reduce_003` (perturbation
//! and best uniform reduction) and `wsgb_basis` (the basis functions as exact terms).

use serde_json::{Value, json};

use cagd_core::{WsgbCurve, to_exact_points, wsgb_lec_difference, wsgb_reduced_order, wsgb_terms};
use cagd_reduce::{
    WsgbMethod, reduce_wsgb, wsgb_paper_bound_11, wsgb_perturbation_step, wsgb_sampled_error_inf,
    wsgb_uniform_step_exact,
};

use super::fields::{points, points_json};
use super::{Outcome, Runner, Vector};

/// The WSGB runners.
pub(crate) const TABLE: &[(&str, Runner)] =
    &[("wsgb_reduce_003", run_reduce), ("wsgb_basis", run_basis)];

/// Grid of the spec's "sampled" maxima (SPEC-reduce §0).
const GRID: usize = 4001;

fn norm_inf(x: &[f64]) -> f64 {
    x.iter().fold(0.0f64, |a, v| a.max(v.abs()))
}

/// `wsgb_reduce_003`: params `n`, `L`, `method` (`perturb` | `uniform`), optional target
/// `m` (default `n - 1`), `norm` (the max-abs norm of seed 003); input `P`. Produces the
/// reduced points `Q` (library, f64), `Q_exact` (the same steps in exact arithmetic, as
/// fractions), `lec` of the input, the paper's bound (11) and formula (12) of the first step
/// (summed over the steps for several), `true_max_error_inf` (the 4001-point grid maximum
/// of the max-abs difference between the curves), and the certified Euclidean
/// `error_bound` / measured `max_error`.
fn run_reduce(v: &Vector<'_>) -> Result<Outcome, String> {
    let (p, dim) = points(v.input("P")?, "input.P")?;
    if dim == 0 {
        return Ok(Outcome::Refused("input.P has no points".into()));
    }
    let count = p.len() / dim;
    let n = match v.param("n") {
        Some(_) => v.param_usize("n")?,
        None => count - 1,
    };
    if n + 1 != count {
        return Err(format!("params.n = {n} but input.P has {count} points"));
    }
    let l = v.param_usize("L")?;
    let method = match v.param("method").and_then(Value::as_str) {
        Some("perturb" | "perturbation") => WsgbMethod::Perturbation,
        Some("uniform") => WsgbMethod::Uniform,
        other => return Err(format!("params.method: unknown {other:?}")),
    };
    if let Some(norm) = v.param("norm").and_then(Value::as_str)
        && !norm.starts_with("inf")
    {
        return Err(format!(
            "params.norm: only the max-abs norm is supported, got {norm:?}"
        ));
    }
    let m = match v.param("m") {
        Some(_) => v.param_usize("m")?,
        None => n.saturating_sub(1),
    };
    let curve = match WsgbCurve::new(p, dim, l) {
        Ok(c) => c,
        Err(e) => return Ok(Outcome::Refused(e.to_string())),
    };
    let red = match reduce_wsgb(&curve, m, method) {
        Ok(r) => r,
        Err(e) => return Ok(Outcome::Refused(e.to_string())),
    };
    // The exact route: the same steps on exact rationals.
    let mut exact = to_exact_points(curve.points());
    let mut lk = l;
    for k in (m + 1..=n).rev() {
        let step = match method {
            WsgbMethod::Perturbation => wsgb_perturbation_step(&exact, dim, lk),
            _ => wsgb_uniform_step_exact(&exact, dim, lk),
        };
        exact = step.map_err(|e| format!("exact route refused what f64 accepted: {e}"))?;
        lk = wsgb_reduced_order(k, lk);
    }
    let q_exact: Vec<Value> = exact
        .chunks(dim)
        .map(|pt| Value::Array(pt.iter().map(|x| Value::from(x.to_string())).collect()))
        .collect();
    let steps = &red.report.steps;
    let sum = |f: fn(&cagd_reduce::WsgbStep) -> f64| steps.iter().map(f).sum::<f64>();
    // Independent of the report: bound (11) from the input's difference D directly.
    let d = wsgb_lec_difference(curve.points(), dim);
    let first_bound_11 = wsgb_paper_bound_11(n, l, norm_inf(&d));
    let paper_bound_11 = if steps.len() == 1 {
        first_bound_11
    } else {
        sum(|s| s.paper_bound_11)
    };
    let sampled = wsgb_sampled_error_inf(&curve, &red.curve, GRID).map_err(|e| e.to_string())?;
    Ok(Outcome::Values(json!({
        "Q": points_json(red.curve.points(), dim),
        "Q_exact": q_exact,
        "L_reduced": red.curve.order(),
        "lec": curve.leading_coefficient(),
        "paper_bound_11": paper_bound_11,
        "uniform_error_12": sum(|s| s.uniform_error_12),
        "true_max_error_inf": sampled,
        "max_error_inf": red.report.max_error_inf,
        "error_bound": red.report.error_bound,
        "max_error": red.report.max_error,
    })))
}

/// `wsgb_basis`: params `n`, `L`; `terms_K_a_b` lists `beta_i = K u^a (1-u)^b` as
/// `[K as an exact integer string, a, b]`.
fn run_basis(v: &Vector<'_>) -> Result<Outcome, String> {
    let n = v.param_usize("n")?;
    let l = v.param_usize("L")?;
    if let Err(e) = cagd_core::check_wsgb_order(n, l) {
        return Ok(Outcome::Refused(e.to_string()));
    }
    match wsgb_terms(n, l) {
        Ok(t) => Ok(Outcome::Values(json!({
            "terms_K_a_b": t
                .iter()
                .map(|b| json!([b.coef.to_string(), b.a, b.b]))
                .collect::<Vec<_>>(),
        }))),
        Err(e) => Ok(Outcome::Refused(e.to_string())),
    }
}
