//! The shared readers of the JSON input: named errors at a JSON path, numbers, counts and
//! point lists.

use std::fmt;

use serde_json::Value;

use crate::limits::{MAX_DEGREE, MAX_DIM, MAX_POINTS};

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

/// A finite number; `path` names it (formatted only on failure: `cagd reduce` reads every
/// coordinate of its input through here, and formatting `points[i][k]` for each was a
/// tenth of a small command's work, issue 17's real-CAD-file row).
fn number_at(v: &Value, path: &dyn Fn() -> String) -> Result<f64, InputError> {
    let Some(x) = v.as_f64() else {
        return Err(InputError::new(
            path(),
            format!("expected a number, got {v}"),
        ));
    };
    if x.is_finite() {
        Ok(x)
    } else {
        Err(InputError::new(path(), "number is not finite"))
    }
}

/// A degree (or WSGB `L`): a non-negative integer `<=` [`MAX_DEGREE`] (the reader's limit,
/// so that the counts derived from it cannot overflow).
pub(crate) fn count(v: &Value, path: &str) -> Result<usize, InputError> {
    let n = v
        .as_u64()
        .and_then(|x| usize::try_from(x).ok())
        .ok_or_else(|| {
            InputError::new(path, format!("expected a non-negative integer, got {v}"))
        })?;
    if n > MAX_DEGREE {
        return Err(InputError::new(
            path,
            format!("{n} is above the limit of {MAX_DEGREE}"),
        ));
    }
    Ok(n)
}

/// Refuses `total` control points above `limit` ([`MAX_POINTS`] for one object,
/// [`crate::limits::MAX_TOTAL_POINTS`] for a whole input); `path` names where the count was
/// passed.
pub(crate) fn check_total(total: usize, limit: usize, path: &str) -> Result<(), InputError> {
    if total > limit {
        return Err(InputError::new(
            path,
            format!("{total} control points in all, above the limit of {limit}"),
        ));
    }
    Ok(())
}

/// Refuses an array of more than [`MAX_POINTS`] entries.
fn check_len(arr: &[Value], path: &dyn Fn() -> String) -> Result<(), InputError> {
    if arr.len() > MAX_POINTS {
        return Err(InputError::new(
            path(),
            format!("has {} entries, above the limit of {MAX_POINTS}", arr.len()),
        ));
    }
    Ok(())
}

pub(crate) fn numbers(v: &Value, path: &str) -> Result<Vec<f64>, InputError> {
    numbers_at(v, &|| path.to_string())
}

/// [`numbers`] with the path formatted only on failure.
fn numbers_at(v: &Value, path: &dyn Fn() -> String) -> Result<Vec<f64>, InputError> {
    let arr = v
        .as_array()
        .ok_or_else(|| InputError::new(path(), "expected an array of numbers"))?;
    check_len(arr, path)?;
    arr.iter()
        .enumerate()
        .map(|(i, x)| number_at(x, &|| format!("{}[{i}]", path())))
        .collect()
}

pub(crate) fn point_list(v: &Value, path: &str) -> Result<PointList, InputError> {
    let arr = v
        .as_array()
        .ok_or_else(|| InputError::new(path, "expected an array of points"))?;
    check_len(arr, &|| path.to_string())?;
    if arr.is_empty() {
        return Err(InputError::new(path, "expected at least one point"));
    }
    let mut coords = Vec::with_capacity(arr.len() * 3);
    let mut dim = 0;
    for (i, p) in arr.iter().enumerate() {
        let pp = || format!("{path}[{i}]");
        let c = numbers_at(p, &pp)?;
        if i == 0 {
            if c.is_empty() {
                return Err(InputError::new(
                    pp(),
                    "a point needs at least one coordinate",
                ));
            }
            if c.len() > MAX_DIM {
                return Err(InputError::new(
                    pp(),
                    format!("has {} coordinates, above the limit of {MAX_DIM}", c.len()),
                ));
            }
            dim = c.len();
        } else if c.len() != dim {
            return Err(InputError::new(
                pp(),
                format!("has {} coordinates, the first point has {dim}", c.len()),
            ));
        }
        coords.extend(c);
    }
    Ok(PointList { coords, dim })
}
