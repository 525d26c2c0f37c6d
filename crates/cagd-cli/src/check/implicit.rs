//! Runners of the implicitization vectors (SPEC-convert §15.8–15.9, `cagd-implicit`).
//!
//! `implicitize_rational_bezier_curve`: every key of `expected` is computed by the library —
//! `monomials` (compared by the runner: scaled by the expected `max |c|`, order-independent,
//! a missing or extra non-zero monomial fails), `matrix_F_at_origin` (the Bézout matrix at
//! (0, 0)), `curve_samples_t_x_y` (the curve evaluated at the vector's `t`s), `degree`. Base points
//! are refused (the exact definition `f = det F` is identically 0).
//! `implicit_subdivision_matrix_A`: `A(α)` of eq. 15.9.6.

use std::collections::BTreeMap;

use cagd_core::BezierCurve;
use cagd_implicit::{BezoutMatrix, implicitize, subdivision_matrix};
use serde_json::{Map, Value};

use super::fields::{matrix_json, numbers, points};
use super::{Outcome, Rule, Runner, Vector, compare};

/// The implicitization family.
pub(crate) const TABLE: &[(&str, Runner)] = &[
    ("implicitize_rational_bezier_curve", run_implicitize),
    ("implicit_subdivision_matrix_A", run_subdivision_matrix),
];

/// The curve of `input.points` / `input.weights` (weights optional), or the library's
/// refusal message.
fn curve(v: &Vector<'_>) -> Result<Result<BezierCurve, String>, String> {
    let (flat, dim) = points(v.input("points")?, "input.points")?;
    let weights = match v.input.get("weights").filter(|w| !w.is_null()) {
        Some(w) => Some(numbers(w, "input.weights")?),
        None => None,
    };
    let built = match weights {
        Some(w) => BezierCurve::new_rational(flat, w, dim),
        None => BezierCurve::new(flat, dim),
    };
    Ok(built.map_err(|e| e.to_string()))
}

/// Monomials `[[i, j, c], ...]` as a map `(i, j) -> c` (duplicates are summed).
fn monomial_map(v: &Value, what: &str) -> Result<BTreeMap<(u64, u64), f64>, String> {
    let list = v.as_array().ok_or_else(|| format!("{what}: not a list"))?;
    let mut out = BTreeMap::new();
    for (k, m) in list.iter().enumerate() {
        let t = m.as_array().filter(|t| t.len() == 3);
        let parsed = t.and_then(|t| Some((t[0].as_u64()?, t[1].as_u64()?, t[2].as_f64()?)));
        let (i, j, c) = parsed.ok_or_else(|| format!("{what}[{k}]: not [i, j, c]"))?;
        *out.entry((i, j)).or_insert(0.0) += c;
    }
    Ok(out)
}

/// Compares monomials by the spec rule for implicit polynomials: `|got - expected|` over
/// `max |expected c|` per monomial; a monomial non-zero in one and absent (zero) in the
/// other fails whatever its size.
fn compare_monomials(
    got: &BTreeMap<(u64, u64), f64>,
    expected: &BTreeMap<(u64, u64), f64>,
    tol: f64,
) -> (f64, Option<String>) {
    let scale = expected.values().fold(0.0_f64, |m, c| m.max(c.abs()));
    let scale = if scale > 0.0 { scale } else { 1.0 };
    let mut max_diff = 0.0_f64;
    let mut failure = None;
    let keys: std::collections::BTreeSet<_> = got.keys().chain(expected.keys()).collect();
    for key in keys {
        let g = got.get(key).copied().unwrap_or(0.0);
        let e = expected.get(key).copied().unwrap_or(0.0);
        let d = (g - e).abs() / scale;
        max_diff = max_diff.max(if d.is_nan() { f64::INFINITY } else { d });
        let structural = (g == 0.0) != (e == 0.0);
        if (structural || d.is_nan() || d > tol) && failure.is_none() {
            failure = Some(format!(
                "monomials: x^{} y^{}: got {g}, expected {e} (scale {scale})",
                key.0, key.1
            ));
        }
    }
    (max_diff, failure)
}

fn run_implicitize(v: &Vector<'_>) -> Result<Outcome, String> {
    let c = match curve(v)? {
        Ok(c) => c,
        Err(e) => return Ok(Outcome::Refused(e)),
    };
    let expected = v.expected.as_object().ok_or("expected: not an object")?;
    // Read the parameters of curve samples before calling the library (malformed = Err).
    let imp = match implicitize(&c) {
        Ok(i) => i,
        Err(e) => return Ok(Outcome::Refused(e.to_string())),
    };
    let bezout = BezoutMatrix::new(&c).map_err(|e| e.to_string())?;
    let mut got = Map::new();
    let mut rest = Map::new();
    let mut max_diff = 0.0_f64;
    let mut failures = Vec::new();
    for (key, ev) in expected {
        match key.as_str() {
            "monomials" => {
                let e = monomial_map(ev, "expected.monomials")?;
                let g: BTreeMap<(u64, u64), f64> = imp
                    .polynomial
                    .monomials()
                    .into_iter()
                    .map(|(i, j, c)| ((i as u64, j as u64), c))
                    .collect();
                let (d, why) = compare_monomials(&g, &e, v.tol);
                max_diff = max_diff.max(d);
                failures.extend(why);
            }
            "degree" => {
                got.insert(key.clone(), serde_json::json!(imp.polynomial.degree()));
                rest.insert(key.clone(), ev.clone());
            }
            "matrix_F_at_origin" => {
                let n = bezout.size();
                got.insert(key.clone(), matrix_json(n, n, &bezout.at(0.0, 0.0)));
                rest.insert(key.clone(), ev.clone());
            }
            "curve_samples_t_x_y" => {
                let rows = ev
                    .as_array()
                    .ok_or("expected.curve_samples_t_x_y: not a list")?;
                let mut out = Vec::with_capacity(rows.len());
                for (k, r) in rows.iter().enumerate() {
                    let r = numbers(r, &format!("expected.curve_samples_t_x_y[{k}]"))?;
                    let t = *r.first().ok_or("curve_samples_t_x_y: empty row")?;
                    let p = c.eval(t);
                    out.push(Value::from(vec![t, p[0], p[1]]));
                }
                got.insert(key.clone(), Value::Array(out));
                rest.insert(key.clone(), ev.clone());
            }
            other => return Err(format!("expected.{other}: unknown key for this algorithm")),
        }
    }
    match compare(
        &Value::Object(got),
        &Value::Object(rest),
        v.tol,
        Rule::Elementwise,
    ) {
        Ok(d) => max_diff = max_diff.max(d),
        Err((d, why)) => {
            max_diff = max_diff.max(d);
            failures.push(why);
        }
    }
    Ok(Outcome::Compared {
        max_diff,
        pass: failures.is_empty(),
        detail: failures.join("; "),
    })
}

fn run_subdivision_matrix(v: &Vector<'_>) -> Result<Outcome, String> {
    let n = v.param_usize("n")?;
    let alpha = v.param_f64("alpha")?;
    Ok(match subdivision_matrix(n, alpha) {
        Ok(a) => Outcome::Values(serde_json::json!({ "A": matrix_json(n, n, &a) })),
        Err(e) => Outcome::Refused(e.to_string()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map(v: &[(u64, u64, f64)]) -> BTreeMap<(u64, u64), f64> {
        v.iter().map(|&(i, j, c)| ((i, j), c)).collect()
    }

    #[test]
    fn monomials_compare_up_to_order_and_scale() {
        let e = map(&[(2, 0, -16.0), (1, 0, 32.0), (0, 1, -16.0)]);
        let g = map(&[(0, 1, -16.0), (2, 0, -16.0), (1, 0, 32.0 + 1e-11)]);
        assert!(compare_monomials(&g, &e, 1e-12).1.is_none());
        let bad = map(&[(0, 1, -16.0), (2, 0, -16.0), (1, 0, 32.0 + 1e-9)]);
        assert!(compare_monomials(&bad, &e, 1e-12).1.is_some());
        let extra = map(&[(0, 1, -16.0), (2, 0, -16.0), (1, 0, 32.0), (0, 0, 1e-30)]);
        assert!(compare_monomials(&extra, &e, 1e-12).1.is_some());
        let missing = map(&[(2, 0, -16.0), (1, 0, 32.0)]);
        assert!(compare_monomials(&missing, &e, 1e-12).1.is_some());
    }
}
