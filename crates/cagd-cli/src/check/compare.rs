//! The spec's comparison rule (SPEC-convert §0): a number passes when
//! `|got - expected| <= tol * max(1, |expected|)`.

use serde_json::Value;

/// Compares `got` with `expected` recursively: every key of an `expected` object must be in
/// `got`; arrays must have equal lengths; numbers follow the tolerance rule; strings, booleans
/// and `null` must be equal. Returns the largest relative difference
/// `|got - expected| / max(1, |expected|)`, or that difference and the first mismatch.
pub(crate) fn compare(got: &Value, expected: &Value, tol: f64) -> Result<f64, (f64, String)> {
    let mut state = State {
        tol,
        max_diff: 0.0,
        first_failure: None,
    };
    state.walk(got, expected, "expected");
    match state.first_failure {
        None => Ok(state.max_diff),
        Some(why) => Err((state.max_diff, why)),
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

    fn walk(&mut self, got: &Value, expected: &Value, path: &str) {
        match (got, expected) {
            (_, Value::Object(e)) => {
                let Value::Object(g) = got else {
                    return self.fail(format!("{path}: expected an object"));
                };
                for (k, ev) in e {
                    match g.get(k) {
                        Some(gv) => self.walk(gv, ev, &format!("{path}.{k}")),
                        None => self.fail(format!("{path}.{k}: not produced")),
                    }
                }
            }
            (Value::Array(g), Value::Array(e)) => {
                if g.len() != e.len() {
                    return self.fail(format!("{path}: {} entries, expected {}", g.len(), e.len()));
                }
                for (i, (gv, ev)) in g.iter().zip(e).enumerate() {
                    self.walk(gv, ev, &format!("{path}[{i}]"));
                }
            }
            (Value::Number(g), Value::Number(e)) => {
                let (g, e) = (
                    g.as_f64().unwrap_or(f64::NAN),
                    e.as_f64().unwrap_or(f64::NAN),
                );
                let d = (g - e).abs() / e.abs().max(1.0);
                if d.is_nan() || d > self.tol {
                    self.max_diff = if d.is_nan() {
                        f64::INFINITY
                    } else {
                        self.max_diff.max(d)
                    };
                    self.fail(format!("{path}: got {g}, expected {e}"));
                } else {
                    self.max_diff = self.max_diff.max(d);
                }
            }
            (g, e) if g == e => {}
            (g, e) => self.fail(format!("{path}: got {g}, expected {e}")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::compare;
    use serde_json::json;

    #[test]
    fn tolerance_rule_is_relative_above_one() {
        let e = json!({"x": [1000.0, 0.5]});
        assert!(compare(&json!({"x": [1000.0 + 9e-10, 0.5]}), &e, 1e-12).is_ok());
        assert!(compare(&json!({"x": [1000.0 + 2e-9, 0.5]}), &e, 1e-12).is_err());
        assert!(compare(&json!({"x": [1000.0, 0.5 + 2e-12]}), &e, 1e-12).is_err());
    }

    #[test]
    fn missing_keys_lengths_and_types_fail() {
        let e = json!({"a": [1.0, 2.0], "b": 3.0});
        assert!(compare(&json!({"a": [1.0, 2.0]}), &e, 1e-9).is_err());
        assert!(compare(&json!({"a": [1.0], "b": 3.0}), &e, 1e-9).is_err());
        assert!(compare(&json!({"a": [1.0, 2.0], "b": "3"}), &e, 1e-9).is_err());
        assert!(compare(&json!({"a": [1.0, 2.0], "b": 3.0, "c": 0}), &e, 1e-9).is_ok());
    }
}
