//! Reading the JSON shapes of the `cagd` command.
//!
//! Shapes (kept stable; later versions only add fields):
//! `{"type":"bezier","points":[[x,y,...],...],"weights":[...]}` (weights optional),
//! `{"type":"bspline","degree":p,"knots":[...],"points":[...],"weights":[...]}`,
//! `{"type":"tensor","degree":[m,n],"points":[...]}` (i-major),
//! `{"type":"triangle","degree":n,"points":[...]}` (i-major),
//! `{"type":"wsgb","L":l,"points":[...]}` (seed 003; see [`crate::commands::reduce::wsgb`]),
//! `{"type":"bspline-surface","degree":[p,q],"knots_u":[...],"knots_v":[...],
//! "points":[[[x,y,...],...],...],"weights":[[...],...]}` (`points[i][j]`: `i` along `u`;
//! weights optional, nested like the points; see [`crate::input::surface`]),
//! `{"type":"interval-triangle","degree":n,"lo":[...],"hi":[...]}` (i-major lower and upper
//! nets; see [`crate::commands::reduce::interval`]).
//!
//! Every error names the JSON path of the offending field (`input[2].points[3][1]`).

pub(crate) mod beziers;
pub(crate) mod fields;
mod file;
pub(crate) mod json_path;
mod raw;
pub(crate) mod shape;
mod surface;

pub(crate) use fields::{InputError, PointList, count, field, numbers, point_list};

use crate::input::fields::check_total;
use crate::limits::{MAX_OBJECTS, MAX_TOTAL_POINTS};
pub(crate) use file::{read_file, read_input};
pub(crate) use raw::RawShape;

use serde_json::Value;

/// Reads the whole input: one object, or an array of objects. Paths start with `input`
/// (one object) or `input[i]`.
pub(crate) fn parse_input(text: &str) -> Result<Vec<RawShape>, InputError> {
    let value: Value = serde_json::from_str(text).map_err(|e| {
        let path = json_path::path_at(text, e.line(), e.column(), "input");
        InputError::new(path, format!("not valid JSON: {e}"))
    })?;
    match &value {
        Value::Array(items) => {
            if items.len() > MAX_OBJECTS {
                return Err(InputError::new(
                    "input",
                    format!(
                        "has {} objects, above the limit of {MAX_OBJECTS}",
                        items.len()
                    ),
                ));
            }
            let mut total = 0usize;
            items
                .iter()
                .enumerate()
                .map(|(i, v)| {
                    let path = format!("input[{i}]");
                    let shape = parse_shape(v, &path)?;
                    total = total.saturating_add(shape.point_count());
                    check_total(total, MAX_TOTAL_POINTS, &path)?;
                    Ok(shape)
                })
                .collect()
        }
        Value::Object(_) => Ok(vec![parse_shape(&value, "input")?]),
        _ => Err(InputError::new(
            "input",
            "expected an object or an array of objects",
        )),
    }
}

fn optional_weights(obj: &Value, path: &str, n: usize) -> Result<Option<Vec<f64>>, InputError> {
    match obj.get("weights") {
        None | Some(Value::Null) => Ok(None),
        Some(w) => {
            let wp = format!("{path}.weights");
            let w = numbers(w, &wp)?;
            if w.len() != n {
                return Err(InputError::new(
                    wp,
                    format!("has {} entries, expected one per point ({n})", w.len()),
                ));
            }
            if let Some(i) = w.iter().position(|x| *x <= 0.0) {
                return Err(InputError::new(
                    format!("{wp}[{i}]"),
                    format!("weight {} must be > 0", w[i]),
                ));
            }
            Ok(Some(w))
        }
    }
}

/// Reads an `interval-triangle` object (seed 004; the counts are checked here, the values
/// by `crate::input::shape::interval::build`).
fn parse_interval(obj: &Value, path: &str) -> Result<RawShape, InputError> {
    let degree = count(field(obj, path, "degree")?, &format!("{path}.degree"))?;
    let lo = point_list(field(obj, path, "lo")?, &format!("{path}.lo"))?;
    let hi = point_list(field(obj, path, "hi")?, &format!("{path}.hi"))?;
    let expected = (degree + 1).saturating_mul(degree + 2) / 2;
    for (name, net) in [("lo", &lo), ("hi", &hi)] {
        if net.len() != expected {
            return Err(InputError::new(
                format!("{path}.{name}"),
                format!(
                    "has {} points, expected (n + 1)(n + 2) / 2 = {expected}",
                    net.len()
                ),
            ));
        }
    }
    if hi.dim != lo.dim {
        return Err(InputError::new(
            format!("{path}.hi"),
            format!("points have {} coordinates, lo has {}", hi.dim, lo.dim),
        ));
    }
    Ok(RawShape::IntervalTriangle { degree, lo, hi })
}

fn parse_shape(obj: &Value, path: &str) -> Result<RawShape, InputError> {
    if !obj.is_object() {
        return Err(InputError::new(path, "expected an object"));
    }
    let ty = field(obj, path, "type")?;
    let ty = ty
        .as_str()
        .ok_or_else(|| InputError::new(format!("{path}.type"), "expected a string"))?;
    if ty == "bspline-surface" {
        return surface::parse(obj, path);
    }
    if ty == "interval-triangle" {
        return parse_interval(obj, path);
    }
    let points = point_list(field(obj, path, "points")?, &format!("{path}.points"))?;
    match ty {
        "wsgb" => {
            // Seed 003's curves are polynomial (see crate::commands::reduce::wsgb).
            if obj.get("weights").is_some() {
                return Err(InputError::new(
                    format!("{path}.weights"),
                    "rational WSGB curves are not supported (seed 003 has none)",
                ));
            }
            let l = count(field(obj, path, "L")?, &format!("{path}.L"))?;
            Ok(RawShape::Wsgb { l, points })
        }
        "bezier" => {
            let weights = optional_weights(obj, path, points.len())?;
            Ok(RawShape::Bezier { points, weights })
        }
        "bspline" => {
            let degree = count(field(obj, path, "degree")?, &format!("{path}.degree"))?;
            let knots = numbers(field(obj, path, "knots")?, &format!("{path}.knots"))?;
            let expected = points.len() + degree + 1;
            if knots.len() != expected {
                return Err(InputError::new(
                    format!("{path}.knots"),
                    format!(
                        "has {} knots, expected n_points + degree + 1 = {expected}",
                        knots.len()
                    ),
                ));
            }
            let weights = optional_weights(obj, path, points.len())?;
            Ok(RawShape::BSpline {
                degree,
                knots,
                points,
                weights,
            })
        }
        "tensor" => {
            let dp = format!("{path}.degree");
            let d = field(obj, path, "degree")?;
            let arr = d
                .as_array()
                .filter(|a| a.len() == 2)
                .ok_or_else(|| InputError::new(&dp, "expected [m, n]"))?;
            let m = count(&arr[0], &format!("{dp}[0]"))?;
            let n = count(&arr[1], &format!("{dp}[1]"))?;
            let expected = (m + 1).saturating_mul(n + 1);
            if points.len() != expected {
                return Err(InputError::new(
                    format!("{path}.points"),
                    format!(
                        "has {} points, expected (m + 1)(n + 1) = {expected}",
                        points.len()
                    ),
                ));
            }
            Ok(RawShape::Tensor {
                degree: (m, n),
                points,
            })
        }
        "triangle" => {
            let n = count(field(obj, path, "degree")?, &format!("{path}.degree"))?;
            let expected = (n + 1).saturating_mul(n + 2) / 2;
            if points.len() != expected {
                return Err(InputError::new(
                    format!("{path}.points"),
                    format!(
                        "has {} points, expected (n + 1)(n + 2) / 2 = {expected}",
                        points.len()
                    ),
                ));
            }
            Ok(RawShape::Triangle { degree: n, points })
        }
        other => Err(InputError::new(
            format!("{path}.type"),
            format!(
                "unknown type {other:?} (expected bezier, bspline, tensor, triangle or bspline-surface)"
            ),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_one_bezier() {
        let s = parse_input(r#"{"type":"bezier","points":[[0,0],[1,2],[3,1]]}"#).unwrap();
        assert_eq!(
            s,
            vec![RawShape::Bezier {
                points: PointList {
                    coords: vec![0.0, 0.0, 1.0, 2.0, 3.0, 1.0],
                    dim: 2
                },
                weights: None
            }]
        );
    }

    #[test]
    fn errors_name_the_field() {
        let cases = [
            (r#"{"type":"bezier"}"#, "input.points: missing field"),
            (
                r#"[{"type":"bezier","points":[[0,0],[1]]}]"#,
                "input[0].points[1]: has 1 coordinates, the first point has 2",
            ),
            (
                r#"{"type":"bezier","points":[[0,"a"]]}"#,
                "input.points[0][1]: expected a number, got \"a\"",
            ),
            (
                r#"{"type":"bezier","points":[[0],[1]],"weights":[1,-2]}"#,
                "input.weights[1]: weight -2 must be > 0",
            ),
            (
                r#"{"type":"bspline","degree":1,"knots":[0,1],"points":[[0],[1]]}"#,
                "input.knots: has 2 knots, expected n_points + degree + 1 = 4",
            ),
            (
                r#"{"type":"tensor","degree":[1,1],"points":[[0],[1]]}"#,
                "input.points: has 2 points, expected (m + 1)(n + 1) = 4",
            ),
            (
                r#"{"type":"circle","points":[[0]]}"#,
                "input.type: unknown type \"circle\" (expected bezier, bspline, tensor, triangle or \
                 bspline-surface)",
            ),
            (
                r#"{"type":"bezier","points":[]}"#,
                "input.points: expected at least one point",
            ),
            (
                "[1,",
                "input[1]: not valid JSON: EOF while parsing a value at line 1 column 3",
            ),
        ];
        for (text, want) in cases {
            assert_eq!(parse_input(text).unwrap_err().to_string(), want, "{text}");
        }
    }
}
