//! Validated shapes (cagd-core objects) built from the raw JSON input, and their JSON output.

pub(crate) mod interval;
mod points;
pub(crate) mod surface;

pub(crate) use points::rows;

use cagd_core::{BSplineCurve, BSplineSurface, BezierCurve, Error, TensorPatch, TriPatch};
use cagd_reduce::IntervalTriPatch;
use serde_json::{Value, json};

use crate::input::{InputError, PointList, RawShape};

/// One validated input object.
#[derive(Debug, Clone)]
pub(crate) enum Shape {
    Bezier(BezierCurve),
    BSpline(BSplineCurve),
    Tensor(TensorPatch),
    Triangle(TriPatch),
    BSplineSurface(BSplineSurface),
    IntervalTriangle(IntervalTriPatch),
    Wsgb(cagd_core::WsgbCurve),
}

/// Turns a cagd-core validation error into an input error naming the JSON field.
pub(crate) fn locate(path: &str, e: &Error) -> InputError {
    let at = match e {
        Error::NonFinite { index, coord, .. } => format!("{path}.points[{index}][{coord}]"),
        Error::NonPositiveWeight { index, .. } => format!("{path}.weights[{index}]"),
        Error::NonFiniteKnot { index, .. } | Error::KnotsNotNondecreasing { index } => {
            format!("{path}.knots[{index}]")
        }
        Error::KnotCount { .. } | Error::MultiplicityAboveDegree { .. } => format!("{path}.knots"),
        Error::DegreeOutOfRange { .. } => format!("{path}.degree"),
        Error::LengthMismatch { what, .. } if what.starts_with("weights") => {
            format!("{path}.weights")
        }
        _ => path.to_string(),
    };
    InputError::new(at, e.to_string())
}

impl Shape {
    /// Validates a raw shape with cagd-core; `path` names it in errors.
    pub(crate) fn build(raw: RawShape, path: &str) -> Result<Shape, InputError> {
        let shape = match raw {
            RawShape::Bezier { points, weights } => {
                let PointList { coords, dim } = points;
                let c = match weights {
                    None => BezierCurve::new(coords, dim),
                    Some(w) => BezierCurve::new_rational(coords, w, dim),
                };
                Shape::Bezier(c.map_err(|e| locate(path, &e))?)
            }
            RawShape::Wsgb { l, points } => Shape::Wsgb(
                cagd_core::WsgbCurve::new(points.coords, points.dim, l).map_err(|e| match e {
                    Error::BadParameter { name: "L", .. } => {
                        InputError::new(format!("{path}.L"), e.to_string())
                    }
                    _ => locate(path, &e),
                })?,
            ),
            RawShape::Tensor { degree, points } => Shape::Tensor(
                TensorPatch::new(points.coords, degree.0, degree.1, points.dim)
                    .map_err(|e| locate(path, &e))?,
            ),
            RawShape::Triangle { degree, points } => Shape::Triangle(
                TriPatch::new(points.coords, degree, points.dim).map_err(|e| locate(path, &e))?,
            ),
            RawShape::BSpline {
                degree,
                knots,
                points,
                weights,
            } => {
                let PointList { coords, dim } = points;
                let c = match weights {
                    None => BSplineCurve::new(degree, knots, coords, dim),
                    Some(w) => BSplineCurve::new_rational(degree, knots, coords, w, dim),
                };
                Shape::BSpline(c.map_err(|e| locate(path, &e))?)
            }
            RawShape::IntervalTriangle { degree, lo, hi } => {
                Shape::IntervalTriangle(interval::build(degree, lo, hi, path)?)
            }
            RawShape::BSplineSurface {
                degree,
                knots_u,
                knots_v,
                points,
                counts,
                weights,
            } => Shape::BSplineSurface(surface::build(
                degree,
                (knots_u, knots_v),
                points,
                counts,
                weights,
                path,
            )?),
        };
        Ok(shape)
    }

    /// The shape in the input JSON form.
    pub(crate) fn to_json(&self) -> Value {
        match self {
            Shape::Bezier(c) => {
                let mut v = json!({"type": "bezier", "points": rows(c.points(), c.dim())});
                if let Some(w) = c.weights() {
                    v["weights"] = json!(w);
                }
                v
            }
            Shape::BSpline(c) => {
                let mut v = json!({
                    "type": "bspline",
                    "degree": c.degree(),
                    "knots": c.knots(),
                    "points": rows(c.points(), c.dim()),
                });
                if let Some(w) = c.weights() {
                    v["weights"] = json!(w);
                }
                v
            }
            Shape::Tensor(p) => {
                let (m, n) = p.degrees();
                json!({"type": "tensor", "degree": [m, n], "points": rows(p.points(), p.dim())})
            }
            Shape::Triangle(t) => {
                json!({"type": "triangle", "degree": t.degree(), "points": rows(t.points(), t.dim())})
            }
            Shape::BSplineSurface(s) => surface::to_json(s),
            Shape::IntervalTriangle(t) => interval::to_json(t),
            Shape::Wsgb(c) => {
                json!({"type": "wsgb", "L": c.order(), "points": rows(c.points(), c.dim())})
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::parse_input;

    #[test]
    fn round_trip_and_core_errors_are_located() {
        let text = r#"{"type":"bezier","points":[[0.0,0.5],[1.0,2.0]],"weights":[1.0,2.0]}"#;
        let raw = parse_input(text).unwrap().remove(0);
        let s = Shape::build(raw, "input").unwrap();
        assert_eq!(s.to_json(), serde_json::from_str::<Value>(text).unwrap());
        let long: Vec<Value> = (0..66).map(|i| json!([i])).collect();
        let text = json!({"type": "bezier", "points": long}).to_string();
        let raw = parse_input(&text).unwrap().remove(0);
        let e = Shape::build(raw, "input").unwrap_err();
        assert_eq!(e.path, "input.degree");
        assert!(e.message.contains("0..=64"), "{}", e.message);
    }
}
