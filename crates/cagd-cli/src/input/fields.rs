//! The shared readers of the JSON input: named errors at a JSON path, numbers, counts and
//! point lists.

use std::fmt;

use serde_json::Value;

/// A bad input: the JSON path of the field and what is wrong with it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct InputError {
    pub(crate) path: String,
    pub(crate) message: String,
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path, self.message)
    }
}

impl InputError {
    pub(crate) fn new(path: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            path: path.into(),
            message: message.into(),
        }
    }
}

/// A point list read from JSON: flat row-major coordinates and the dimension.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PointList {
    pub(crate) coords: Vec<f64>,
    pub(crate) dim: usize,
}

impl PointList {
    pub(crate) fn len(&self) -> usize {
        self.coords.len() / self.dim
    }
}

pub(crate) fn field<'a>(obj: &'a Value, path: &str, name: &str) -> Result<&'a Value, InputError> {
    obj.get(name)
        .ok_or_else(|| InputError::new(format!("{path}.{name}"), "missing field"))
}

pub(crate) fn number(v: &Value, path: &str) -> Result<f64, InputError> {
    let x = v
        .as_f64()
        .ok_or_else(|| InputError::new(path, format!("expected a number, got {v}")))?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(InputError::new(path, "number is not finite"))
    }
}

pub(crate) fn count(v: &Value, path: &str) -> Result<usize, InputError> {
    v.as_u64()
        .and_then(|x| usize::try_from(x).ok())
        .ok_or_else(|| InputError::new(path, format!("expected a non-negative integer, got {v}")))
}

pub(crate) fn numbers(v: &Value, path: &str) -> Result<Vec<f64>, InputError> {
    let arr = v
        .as_array()
        .ok_or_else(|| InputError::new(path, "expected an array of numbers"))?;
    arr.iter()
        .enumerate()
        .map(|(i, x)| number(x, &format!("{path}[{i}]")))
        .collect()
}

pub(crate) fn point_list(v: &Value, path: &str) -> Result<PointList, InputError> {
    let arr = v
        .as_array()
        .ok_or_else(|| InputError::new(path, "expected an array of points"))?;
    if arr.is_empty() {
        return Err(InputError::new(path, "expected at least one point"));
    }
    let mut coords = Vec::new();
    let mut dim = 0;
    for (i, p) in arr.iter().enumerate() {
        let pp = format!("{path}[{i}]");
        let c = numbers(p, &pp)?;
        if i == 0 {
            if c.is_empty() {
                return Err(InputError::new(pp, "a point needs at least one coordinate"));
            }
            dim = c.len();
        } else if c.len() != dim {
            return Err(InputError::new(
                pp,
                format!("has {} coordinates, the first point has {dim}", c.len()),
            ));
        }
        coords.extend(c);
    }
    Ok(PointList { coords, dim })
}
