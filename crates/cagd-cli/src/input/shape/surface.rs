//! B-spline / NURBS surfaces as shapes of the command: validated with cagd-core (errors
//! located at the JSON field, `input.knots_v[3]`, `input.points[1][2][0]`) and written back
//! in the input form (`points[i][j]`, rows along `u`).

use cagd_core::{BSplineSurface, Error, check_knots};
use serde_json::{Value, json};

use crate::input::shape::rows;
use crate::input::{InputError, PointList};

/// Prefixes the field of a knot error of one direction (`knots_u` / `knots_v`).
fn locate_knots(path: &str, name: &str, degree_at: &str, e: &Error) -> InputError {
    let at = match e {
        Error::NonFiniteKnot { index, .. } | Error::KnotsNotNondecreasing { index } => {
            format!("{path}.{name}[{index}]")
        }
        Error::DegreeOutOfRange { .. } => format!("{path}.{degree_at}"),
        Error::NotEnoughPoints { .. } if name == "knots_u" => format!("{path}.points"),
        Error::NotEnoughPoints { .. } => format!("{path}.points[0]"),
        _ => format!("{path}.{name}"),
    };
    InputError::new(at, e.to_string())
}

/// Validates the parts of a `bspline-surface` shape; `path` names it in errors.
pub(crate) fn build(
    degree: (usize, usize),
    (knots_u, knots_v): (Vec<f64>, Vec<f64>),
    points: PointList,
    counts: (usize, usize),
    weights: Option<Vec<f64>>,
    path: &str,
) -> Result<BSplineSurface, InputError> {
    // The knots of each direction first, so that an error names its direction.
    check_knots(&knots_u, counts.0, degree.0)
        .map_err(|e| locate_knots(path, "knots_u", "degree[0]", &e))?;
    check_knots(&knots_v, counts.1, degree.1)
        .map_err(|e| locate_knots(path, "knots_v", "degree[1]", &e))?;
    let PointList { coords, dim } = points;
    let s = match weights {
        None => BSplineSurface::new(degree, knots_u, knots_v, coords, counts, dim),
        Some(w) => BSplineSurface::new_rational(degree, knots_u, knots_v, coords, w, counts, dim),
    };
    let nv = counts.1.max(1);
    s.map_err(|e| {
        let at = match &e {
            Error::NonFinite { index, coord, .. } => {
                format!("{path}.points[{}][{}][{coord}]", index / nv, index % nv)
            }
            Error::NonPositiveWeight { index, .. } => {
                format!("{path}.weights[{}][{}]", index / nv, index % nv)
            }
            _ => path.to_string(),
        };
        InputError::new(at, e.to_string())
    })
}

/// A flat i-major buffer of `n_v` entries per row (`per` numbers each) as rows of rows.
fn nest(flat: &[f64], per: usize, nv: usize) -> Value {
    Value::Array(flat.chunks(per * nv).map(|row| rows(row, per)).collect())
}

/// The surface in the input JSON form.
pub(crate) fn to_json(s: &BSplineSurface) -> Value {
    let ((p, q), (_, nv)) = (s.degrees(), s.counts());
    let mut v = json!({
        "type": "bspline-surface",
        "degree": [p, q],
        "knots_u": s.knots_u(),
        "knots_v": s.knots_v(),
        "points": nest(s.points(), s.dim(), nv),
    });
    if let Some(w) = s.weights() {
        v["weights"] = Value::Array(w.chunks(nv).map(|row| json!(row)).collect());
    }
    v
}

/// The number of non-empty knot spans of a degree-`p` knot vector (on its domain).
pub(crate) fn spans(knots: &[f64], p: usize) -> usize {
    let n = knots.len().saturating_sub(p + 1);
    knots
        .get(p..=n)
        .map_or(0, |d| d.windows(2).filter(|w| w[1] > w[0]).count())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::shape::Shape;
    use crate::input::{RawShape, parse_input};

    fn built(text: &str) -> Result<Shape, InputError> {
        let raw: RawShape = parse_input(text).unwrap().remove(0);
        Shape::build(raw, "input")
    }

    #[test]
    fn round_trip() {
        let text = r#"{"type":"bspline-surface","degree":[1,2],"knots_u":[0.0,0.0,1.0,1.0],
            "knots_v":[0.0,0.0,0.0,0.5,1.0,1.0,1.0],
            "points":[[[0.0,0.0],[1.0,0.0],[2.0,0.5],[3.0,0.0]],[[0.0,1.0],[1.0,1.5],[2.0,1.0],[3.0,1.0]]],
            "weights":[[1.0,2.0,1.0,1.0],[1.0,0.5,1.0,3.0]]}"#;
        let s = built(text).unwrap();
        let Shape::BSplineSurface(ref b) = s else {
            panic!("not a surface");
        };
        assert_eq!((b.counts(), b.dim()), ((2, 4), 2));
        assert_eq!((spans(b.knots_u(), 1), spans(b.knots_v(), 2)), (1, 2));
        assert_eq!(s.to_json(), serde_json::from_str::<Value>(text).unwrap());
    }

    #[test]
    fn core_errors_are_located() {
        let pts = r#""points":[[[0],[1],[2]],[[0],[1],[2]]]"#;
        let cases = [
            (
                format!(
                    r#"{{"type":"bspline-surface","degree":[1,2],"knots_u":[0,0,1,1],"knots_v":[0,0,0,1,0.5,1],{pts}}}"#
                ),
                "input.knots_v[4]",
            ),
            (
                format!(
                    r#"{{"type":"bspline-surface","degree":[1,2],"knots_u":[0,1,0,1],"knots_v":[0,0,0,1,1,1],{pts}}}"#
                ),
                "input.knots_u[2]",
            ),
            (
                format!(
                    r#"{{"type":"bspline-surface","degree":[1,3],"knots_u":[0,0,1,1],"knots_v":[0,0,0,0,1,1,1],{pts}}}"#
                ),
                "input.points[0]",
            ),
            (
                format!(
                    r#"{{"type":"bspline-surface","degree":[1,2],"knots_u":[0,0,0,0],"knots_v":[0,0,0,1,1,1],{pts}}}"#
                ),
                "input.knots_u",
            ),
        ];
        for (text, want) in cases {
            let e = built(&text).unwrap_err();
            assert_eq!(e.path, want, "{text}: {e}");
        }
    }
}
