//! Reading the JSON shape of a tensor-product B-spline / NURBS surface:
//! `{"type":"bspline-surface","degree":[p,q],"knots_u":[...],"knots_v":[...],
//! "points":[[[x,y,...],...],...],"weights":[[...],...]}`.
//!
//! `points[i][j]` is the control point `i` along `u`, `j` along `v` (`n_u` rows of `n_v`
//! points); `weights` is optional and nested like the points. `knots_u` has `n_u + p + 1`
//! knots, `knots_v` has `n_v + q + 1`. Errors name the field: `input.points[2]` (a ragged
//! row), `input.weights[1][3]` (a weight `<= 0`), `input.knots_v` (a knot count).

use serde_json::Value;

use crate::input::fields::check_total;
use crate::input::{InputError, PointList, RawShape, count, field, numbers, point_list};
use crate::limits::MAX_POINTS;

/// The degree pair `[p, q]` at `path`.
fn degree_pair(obj: &Value, path: &str) -> Result<(usize, usize), InputError> {
    let dp = format!("{path}.degree");
    let arr = field(obj, path, "degree")?
        .as_array()
        .filter(|a| a.len() == 2)
        .ok_or_else(|| InputError::new(&dp, "expected [p, q]"))?;
    Ok((
        count(&arr[0], &format!("{dp}[0]"))?,
        count(&arr[1], &format!("{dp}[1]"))?,
    ))
}

/// The control net: rows of points, all rows as long as the first, all points of one
/// dimension. Returns the flat i-major points and `(n_u, n_v)`.
fn grid(v: &Value, path: &str) -> Result<(PointList, (usize, usize)), InputError> {
    let rows = v
        .as_array()
        .ok_or_else(|| InputError::new(path, "expected an array of rows of points"))?;
    if rows.is_empty() {
        return Err(InputError::new(path, "expected at least one row"));
    }
    let mut coords = Vec::new();
    let (mut nv, mut dim) = (0, 0);
    for (i, row) in rows.iter().enumerate() {
        let rp = format!("{path}[{i}]");
        let r = point_list(row, &rp)?;
        if i == 0 {
            (nv, dim) = (r.len(), r.dim);
        } else if r.len() != nv {
            return Err(InputError::new(
                rp,
                format!("has {} points, the first row has {nv}", r.len()),
            ));
        } else if r.dim != dim {
            return Err(InputError::new(
                format!("{rp}[0]"),
                format!("has {} coordinates, the first point has {dim}", r.dim),
            ));
        }
        coords.extend(r.coords);
        check_total(coords.len() / dim, MAX_POINTS, &rp)?;
    }
    Ok((PointList { coords, dim }, (rows.len(), nv)))
}

/// The optional weights, nested like the points, each `> 0`; flat i-major.
fn weights(
    obj: &Value,
    path: &str,
    (nu, nv): (usize, usize),
) -> Result<Option<Vec<f64>>, InputError> {
    let w = match obj.get("weights") {
        None | Some(Value::Null) => return Ok(None),
        Some(w) => w,
    };
    let wp = format!("{path}.weights");
    let rows = w
        .as_array()
        .ok_or_else(|| InputError::new(&wp, "expected an array of rows of numbers"))?;
    if rows.len() != nu {
        return Err(InputError::new(
            wp,
            format!(
                "has {} rows, expected one per row of points ({nu})",
                rows.len()
            ),
        ));
    }
    let mut out = Vec::with_capacity(nu.saturating_mul(nv));
    for (i, row) in rows.iter().enumerate() {
        let rp = format!("{wp}[{i}]");
        let r = numbers(row, &rp)?;
        if r.len() != nv {
            return Err(InputError::new(
                rp,
                format!("has {} entries, expected one per point ({nv})", r.len()),
            ));
        }
        if let Some(j) = r.iter().position(|x| *x <= 0.0) {
            return Err(InputError::new(
                format!("{rp}[{j}]"),
                format!("weight {} must be > 0", r[j]),
            ));
        }
        out.extend(r);
    }
    Ok(Some(out))
}

/// A knot vector of `n + degree + 1` knots at `path.name`; `what` names the count in the
/// message (`n_u + p`).
fn knots(
    obj: &Value,
    path: &str,
    name: &str,
    n: usize,
    degree: usize,
    what: &str,
) -> Result<Vec<f64>, InputError> {
    let kp = format!("{path}.{name}");
    let k = numbers(field(obj, path, name)?, &kp)?;
    let expected = n.saturating_add(degree).saturating_add(1);
    if k.len() != expected {
        return Err(InputError::new(
            kp,
            format!("has {} knots, expected {what} + 1 = {expected}", k.len()),
        ));
    }
    Ok(k)
}

/// Reads a `bspline-surface` object at `path` (the counts and nesting; cagd-core checks the
/// rest when the shape is built).
pub(crate) fn parse(obj: &Value, path: &str) -> Result<RawShape, InputError> {
    let degree = degree_pair(obj, path)?;
    let (points, counts) = grid(field(obj, path, "points")?, &format!("{path}.points"))?;
    let knots_u = knots(obj, path, "knots_u", counts.0, degree.0, "n_u + p")?;
    let knots_v = knots(obj, path, "knots_v", counts.1, degree.1, "n_v + q")?;
    let weights = weights(obj, path, counts)?;
    Ok(RawShape::BSplineSurface {
        degree,
        knots_u,
        knots_v,
        points,
        counts,
        weights,
    })
}

#[cfg(test)]
mod tests {
    use crate::input::{RawShape, parse_input};

    const K: &str = r#""knots_u":[0,0,1,1],"knots_v":[0,0,0,1,1,1]"#;

    #[test]
    fn reads_a_nurbs_surface() {
        let text = format!(
            r#"{{"type":"bspline-surface","degree":[1,2],{K},
               "points":[[[0,0,0],[1,0,1],[2,0,0]],[[0,1,0],[1,1,1],[2,1,0]]],
               "weights":[[1,2,1],[1,0.5,1]]}}"#
        );
        let s = parse_input(&text).unwrap().remove(0);
        let RawShape::BSplineSurface {
            degree,
            points,
            counts,
            weights,
            ..
        } = s
        else {
            panic!("not a surface: {s:?}");
        };
        assert_eq!((degree, counts, points.dim), ((1, 2), (2, 3), 3));
        assert_eq!(&points.coords[9..12], &[0.0, 1.0, 0.0]);
        assert_eq!(weights, Some(vec![1.0, 2.0, 1.0, 1.0, 0.5, 1.0]));
    }

    #[test]
    fn errors_name_the_field() {
        let p2 = r#""points":[[[0],[1],[2]],[[0],[1],[2]]]"#;
        let cases = [
            (
                format!(
                    r#"{{"type":"bspline-surface","degree":[1,2],{K},"points":[[[0],[1],[2]],[[0],[1]]]}}"#
                ),
                "input.points[1]: has 2 points, the first row has 3",
            ),
            (
                format!(
                    r#"{{"type":"bspline-surface","degree":[1,2],{K},"points":[[[0],[1],[2]],[[0,1],[1,1],[2,1]]]}}"#
                ),
                "input.points[1][0]: has 2 coordinates, the first point has 1",
            ),
            (
                format!(
                    r#"{{"type":"bspline-surface","degree":[1,2],"knots_u":[0,1],"knots_v":[0,0,0,1,1,1],{p2}}}"#
                ),
                "input.knots_u: has 2 knots, expected n_u + p + 1 = 4",
            ),
            (
                format!(
                    r#"{{"type":"bspline-surface","degree":[1,2],"knots_u":[0,0,1,1],"knots_v":[0,1],{p2}}}"#
                ),
                "input.knots_v: has 2 knots, expected n_v + q + 1 = 6",
            ),
            (
                format!(
                    r#"{{"type":"bspline-surface","degree":[1,2],{K},{p2},"weights":[[1,1,1],[1,0,1]]}}"#
                ),
                "input.weights[1][1]: weight 0 must be > 0",
            ),
            (
                format!(
                    r#"{{"type":"bspline-surface","degree":[1,2],{K},{p2},"weights":[[1,1,1]]}}"#
                ),
                "input.weights: has 1 rows, expected one per row of points (2)",
            ),
            (
                format!(
                    r#"{{"type":"bspline-surface","degree":[1,2],{K},{p2},"weights":[[1,1,1],[1,1]]}}"#
                ),
                "input.weights[1]: has 2 entries, expected one per point (3)",
            ),
            (
                format!(
                    r#"[{{"type":"bspline-surface","degree":[1,2],{K},"points":[[[0],[1],[2]],[[0],[1e999],[2]]]}}]"#
                ),
                "input[0].points[1][1][0]: not valid JSON: number out of range",
            ),
            (
                format!(r#"{{"type":"bspline-surface","degree":2,{K},{p2}}}"#),
                "input.degree: expected [p, q]",
            ),
            (
                format!(r#"{{"type":"bspline-surface","degree":[1,2],{K},"points":[]}}"#),
                "input.points: expected at least one row",
            ),
        ];
        for (text, want) in cases {
            let got = parse_input(&text).unwrap_err().to_string();
            assert!(got.starts_with(want), "{text}\n got {got}\nwant {want}");
        }
    }
}
