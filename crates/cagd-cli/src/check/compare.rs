//! The spec files' comparison rules.
//!
//! * SPEC-convert §0 ([`Rule::Elementwise`]): a number passes when
//!   `|got - expected| <= tol * max(1, |expected|)`.
//! * SPEC-reduce §0 ([`Rule::PerArray`]): an expected array `e` (the value of one key of
//!   `expected`) passes against the computed `g` when `max|g - e| <= tol * max(1, max|e|)`.
//!
//! Exact values are rational strings (`"p/q"`, `"-3"`). Two strings are compared by value
//! (exactly when `tol = 0`); a string against a computed double by the number rule, and with
//! `tol = 0` the double must be the correctly rounded value of the rational (the best an
//! `f64` result can be: "exact up to the final rounding").

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use serde_json::Value;

/// Which spec's tolerance rule applies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Rule {
    /// SPEC-convert §0: every number relative to `max(1, |expected|)`.
    Elementwise,
    /// SPEC-reduce §0: every top-level array relative to `max(1, max|expected|)`.
    PerArray,
}

/// Parses an exact rational string `"p/q"` or `"p"` (integers of any size).
pub(crate) fn parse_rational(s: &str) -> Option<BigRational> {
    let s = s.trim();
    let (p, q) = match s.split_once('/') {
        Some((p, q)) => (
            p.trim().parse::<BigInt>().ok()?,
            q.trim().parse::<BigInt>().ok()?,
        ),
        None => (s.parse::<BigInt>().ok()?, BigInt::from(1)),
    };
    if q.is_zero() {
        return None;
    }
    Some(BigRational::new(p, q))
}

/// A rational as the spec files write it (`"615/2"`, `"220"`, `"-3/4"`).
pub(crate) fn rational_string(q: &BigRational) -> String {
    if q.denom() == &BigInt::from(1) {
        q.numer().to_string()
    } else {
        format!("{}/{}", q.numer(), q.denom())
    }
}

/// Compares `got` with `expected`: every key of an `expected` object must be in `got`;
/// arrays must have equal lengths; numbers (and rational strings) follow `rule`; other
/// strings, booleans and `null` must be equal. Returns the largest relative difference, or
/// that difference and the first mismatch.
pub(crate) fn compare(
    got: &Value,
    expected: &Value,
    tol: f64,
    rule: Rule,
) -> Result<f64, (f64, String)> {
    let mut state = State {
        tol,
        max_diff: 0.0,
        first_failure: None,
    };
    match (rule, got, expected) {
        (Rule::PerArray, Value::Object(g), Value::Object(e)) => {
            for (k, ev) in e {
                let path = format!("expected.{k}");
                match g.get(k) {
                    Some(gv) => {
                        let scale = max_abs(ev).max(1.0);
                        state.walk(gv, ev, &path, Some(scale));
                    }
                    None => state.fail(format!("{path}: not produced")),
                }
            }
        }
        _ => state.walk(got, expected, "expected", None),
    }
    match state.first_failure {
        None => Ok(state.max_diff),
        Some(why) => Err((state.max_diff, why)),
    }
}

/// The largest `|x|` of the numbers (and rational strings) in `v`.
fn max_abs(v: &Value) -> f64 {
    match v {
        Value::Number(n) => n.as_f64().map_or(0.0, f64::abs),
        Value::String(s) => parse_rational(s)
            .and_then(|q| q.to_f64())
            .map_or(0.0, f64::abs),
        Value::Array(a) => a.iter().map(max_abs).fold(0.0, f64::max),
        Value::Object(o) => o.values().map(max_abs).fold(0.0, f64::max),
        _ => 0.0,
    }
}

/// A JSON value as a number: a double, or a rational string.
enum Num {
    Float(f64),
    Exact(BigRational),
}

fn as_num(v: &Value) -> Option<Num> {
    match v {
        Value::Number(n) => n.as_f64().map(Num::Float),
        Value::String(s) => parse_rational(s).map(Num::Exact),
        _ => None,
    }
}

struct State {
    tol: f64,
    max_diff: f64,
    first_failure: Option<String>,
}

impl State {
    fn fail(&mut self, why: String) {
        if self.first_failure.is_none() {
            self.first_failure = Some(why);
        }
    }

    fn walk(&mut self, got: &Value, expected: &Value, path: &str, scale: Option<f64>) {
        if let (Some(g), Some(e)) = (as_num(got), as_num(expected)) {
            return self.number(&g, &e, path, scale);
        }
        match (got, expected) {
            (_, Value::Object(e)) => {
                let Value::Object(g) = got else {
                    return self.fail(format!("{path}: expected an object"));
                };
                for (k, ev) in e {
                    match g.get(k) {
                        Some(gv) => self.walk(gv, ev, &format!("{path}.{k}"), scale),
                        None => self.fail(format!("{path}.{k}: not produced")),
                    }
                }
            }
            (Value::Array(g), Value::Array(e)) => {
                if g.len() != e.len() {
                    return self.fail(format!("{path}: {} entries, expected {}", g.len(), e.len()));
                }
                for (i, (gv, ev)) in g.iter().zip(e).enumerate() {
                    self.walk(gv, ev, &format!("{path}[{i}]"), scale);
                }
            }
            (g, e) if g == e => {}
            (g, e) => self.fail(format!("{path}: got {g}, expected {e}")),
        }
    }

    fn number(&mut self, got: &Num, expected: &Num, path: &str, scale: Option<f64>) {
        let (ok, d, shown) = match (got, expected) {
            (Num::Exact(g), Num::Exact(e)) => {
                let diff = (g - e).abs().to_f64().unwrap_or(f64::INFINITY);
                let s = scale.unwrap_or_else(|| e.abs().to_f64().unwrap_or(f64::INFINITY).max(1.0));
                let d = diff / s;
                let ok = if self.tol == 0.0 {
                    g == e
                } else {
                    d <= self.tol
                };
                (
                    ok,
                    d,
                    format!(
                        "got {}, expected {}",
                        rational_string(g),
                        rational_string(e)
                    ),
                )
            }
            _ => {
                let g = num_f64(got);
                let e = num_f64(expected);
                let s = scale.unwrap_or_else(|| e.abs().max(1.0));
                let d = (g - e).abs() / s;
                let ok = if self.tol == 0.0 {
                    // Exact: equal values, or the correctly rounded double of an exact
                    // expected rational.
                    match expected {
                        Num::Exact(q) => q.to_f64() == Some(g) && g.is_finite(),
                        Num::Float(_) => g == e,
                    }
                } else {
                    d <= self.tol
                };
                (ok, d, format!("got {g}, expected {e}"))
            }
        };
        let d = if d.is_nan() { f64::INFINITY } else { d };
        self.max_diff = self.max_diff.max(d);
        if !ok {
            self.fail(format!("{path}: {shown}"));
        }
    }
}

fn num_f64(n: &Num) -> f64 {
    match n {
        Num::Float(x) => *x,
        Num::Exact(q) => q.to_f64().unwrap_or(f64::NAN),
    }
}

#[cfg(test)]
mod tests {
    use super::{Rule, compare};
    use serde_json::json;

    #[test]
    fn elementwise_rule_is_relative_above_one() {
        let e = json!({"x": [1000.0, 0.5]});
        let r = Rule::Elementwise;
        assert!(compare(&json!({"x": [1000.0 + 9e-10, 0.5]}), &e, 1e-12, r).is_ok());
        assert!(compare(&json!({"x": [1000.0 + 2e-9, 0.5]}), &e, 1e-12, r).is_err());
        assert!(compare(&json!({"x": [1000.0, 0.5 + 2e-12]}), &e, 1e-12, r).is_err());
    }

    #[test]
    fn per_array_rule_scales_by_the_largest_entry() {
        let e = json!({"x": [1000.0, 0.5]});
        let r = Rule::PerArray;
        // 0.5 + 5e-10 is within 1e-12 * 1000 of 0.5 under the per-array rule only.
        assert!(compare(&json!({"x": [1000.0, 0.5 + 5e-10]}), &e, 1e-12, r).is_ok());
        assert!(
            compare(
                &json!({"x": [1000.0, 0.5 + 5e-10]}),
                &e,
                1e-12,
                Rule::Elementwise
            )
            .is_err()
        );
        assert!(compare(&json!({"x": [1000.0, 0.5 + 2e-9]}), &e, 1e-12, r).is_err());
    }

    #[test]
    fn exact_strings_compare_by_value() {
        let e = json!({"q": ["615/2", "-3/4", "7"]});
        let r = Rule::PerArray;
        assert!(compare(&json!({"q": ["1230/4", "-6/8", "7/1"]}), &e, 0.0, r).is_ok());
        assert!(compare(&json!({"q": ["615/2", "-3/4", "8"]}), &e, 0.0, r).is_err());
        // A double passes an exact rational at tol 0 only when correctly rounded.
        assert!(compare(&json!({"q": [307.5, -0.75, 7.0]}), &e, 0.0, r).is_ok());
        let third = json!({"q": ["1/3"]});
        assert!(compare(&json!({"q": [1.0 / 3.0]}), &third, 0.0, r).is_ok());
        assert!(compare(&json!({"q": [1.0 / 3.0 + 1e-16]}), &third, 0.0, r).is_err());
        assert!(compare(&json!({"q": [0.3333333333333]}), &third, 1e-12, r).is_ok());
    }

    #[test]
    fn missing_keys_lengths_and_types_fail() {
        let e = json!({"a": [1.0, 2.0], "b": 3.0});
        for r in [Rule::Elementwise, Rule::PerArray] {
            assert!(compare(&json!({"a": [1.0, 2.0]}), &e, 1e-9, r).is_err());
            assert!(compare(&json!({"a": [1.0], "b": 3.0}), &e, 1e-9, r).is_err());
            assert!(compare(&json!({"a": [1.0, 2.0], "b": "x"}), &e, 1e-9, r).is_err());
            assert!(compare(&json!({"a": [1.0, 2.0], "b": 3.0, "c": 0}), &e, 1e-9, r).is_ok());
            assert!(compare(&json!({"a": [1.0, f64::NAN], "b": 3.0}), &e, 1e-9, r).is_err());
        }
    }
}
