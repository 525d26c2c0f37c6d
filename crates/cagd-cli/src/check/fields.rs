//! One spec vector and typed access to its fields, with messages that name the field.

use serde_json::Value;

/// One vector of a spec file, its parts borrowed from the parsed JSON.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Vector<'a> {
    /// `params` (an empty object when absent).
    pub(crate) params: &'a Value,
    /// `input` (an empty object when absent).
    pub(crate) input: &'a Value,
    /// `expected`.
    pub(crate) expected: &'a Value,
    /// `tol` of the spec's comparison rule.
    pub(crate) tol: f64,
}

static EMPTY: Value = Value::Null;

impl<'a> Vector<'a> {
    /// Reads the fields every vector has.
    pub(crate) fn read(raw: &'a Value) -> Result<Self, String> {
        let expected = raw.get("expected").ok_or("no \"expected\"")?;
        let tol = raw
            .get("tol")
            .and_then(Value::as_f64)
            .ok_or("no numeric \"tol\"")?;
        if !(tol.is_finite() && tol >= 0.0) {
            return Err(format!("tol {tol} is not finite and >= 0"));
        }
        Ok(Vector {
            params: raw.get("params").unwrap_or(&EMPTY),
            input: raw.get("input").unwrap_or(&EMPTY),
            expected,
            tol,
        })
    }

    /// `params.<key>` (or `None`).
    pub(crate) fn param(&self, key: &str) -> Option<&'a Value> {
        self.params.get(key).filter(|v| !v.is_null())
    }

    /// `params.<key>` as a number.
    pub(crate) fn param_f64(&self, key: &str) -> Result<f64, String> {
        self.param(key)
            .and_then(Value::as_f64)
            .ok_or_else(|| format!("params.{key}: not a number"))
    }

    /// `params.<key>` as a non-negative integer.
    pub(crate) fn param_usize(&self, key: &str) -> Result<usize, String> {
        self.param(key)
            .and_then(Value::as_u64)
            .and_then(|u| usize::try_from(u).ok())
            .ok_or_else(|| format!("params.{key}: not a non-negative integer"))
    }

    /// `input.<key>`.
    pub(crate) fn input(&self, key: &str) -> Result<&'a Value, String> {
        self.input
            .get(key)
            .ok_or_else(|| format!("input.{key}: missing"))
    }
}

/// A number, with the field named in the error.
pub(crate) fn number(v: &Value, what: &str) -> Result<f64, String> {
    v.as_f64().ok_or_else(|| format!("{what}: not a number"))
}

/// A list of numbers.
pub(crate) fn numbers(v: &Value, what: &str) -> Result<Vec<f64>, String> {
    let a = v.as_array().ok_or_else(|| format!("{what}: not a list"))?;
    a.iter()
        .enumerate()
        .map(|(i, x)| number(x, &format!("{what}[{i}]")))
        .collect()
}

/// A list of points `[[x, y, ...], ...]` as a flat row-major buffer and its dimension
/// (every point must have the same, non-zero, dimension; an empty list has dimension 0).
pub(crate) fn points(v: &Value, what: &str) -> Result<(Vec<f64>, usize), String> {
    let a = v
        .as_array()
        .ok_or_else(|| format!("{what}: not a list of points"))?;
    let mut flat = Vec::new();
    let mut dim = 0;
    for (i, p) in a.iter().enumerate() {
        let p = numbers(p, &format!("{what}[{i}]"))?;
        if i == 0 {
            dim = p.len();
            if dim == 0 {
                return Err(format!("{what}[0]: a point needs a coordinate"));
            }
        } else if p.len() != dim {
            return Err(format!(
                "{what}[{i}]: {} coordinates, expected {dim}",
                p.len()
            ));
        }
        flat.extend(p);
    }
    Ok((flat, dim))
}

/// A flat row-major buffer of `dim`-dimensional points as a JSON list of points.
pub(crate) fn points_json(flat: &[f64], dim: usize) -> Value {
    Value::Array(
        flat.chunks(dim.max(1))
            .map(|p| Value::Array(p.iter().map(|&x| Value::from(x)).collect()))
            .collect(),
    )
}

/// A matrix (rows of numbers) as JSON.
pub(crate) fn matrix_json(rows: usize, cols: usize, data: &[f64]) -> Value {
    Value::Array(
        (0..rows)
            .map(|i| {
                Value::Array(
                    data[i * cols..(i + 1) * cols]
                        .iter()
                        .map(|&x| Value::from(x))
                        .collect(),
                )
            })
            .collect(),
    )
}
