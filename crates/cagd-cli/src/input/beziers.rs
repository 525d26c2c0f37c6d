//! Reading the input of `cagd merge`: one object
//! `{"type":"beziers","segments":[[[x,y,...],...],...],"weights":[[...],...],"breaks":[...]}`
//! (weights optional, per segment, `null` for a polynomial segment; breaks optional,
//! default `0, 1, ..., count`). Every error names the JSON path of the offending field
//! (`input.segments[2][1]`).

use cagd_core::BezierCurve;
use serde_json::Value;

use crate::input::fields::check_total;
use crate::input::{InputError, field, numbers, point_list};
use crate::limits::{MAX_OBJECTS, MAX_TOTAL_POINTS};

/// The validated input of a merge: the segments (same degree `>= 1` and dimension) and
/// the strictly increasing breaks, one more than the segments.
#[derive(Debug, Clone)]
pub(crate) struct Beziers {
    pub(crate) segments: Vec<BezierCurve>,
    pub(crate) breaks: Vec<f64>,
}

/// Reads and validates the whole input text.
pub(crate) fn parse(text: &str) -> Result<Beziers, InputError> {
    let obj: Value = serde_json::from_str(text).map_err(|e| {
        let path = crate::input::json_path::path_at(text, e.line(), e.column(), "input");
        InputError::new(path, format!("not valid JSON: {e}"))
    })?;
    if !obj.is_object() {
        return Err(InputError::new(
            "input",
            "expected one object {\"type\":\"beziers\",\"segments\":[...]}",
        ));
    }
    let ty = field(&obj, "input", "type")?;
    if ty.as_str() != Some("beziers") {
        return Err(InputError::new(
            "input.type",
            format!("got {ty}, merge expects \"beziers\""),
        ));
    }
    let segs = field(&obj, "input", "segments")?
        .as_array()
        .ok_or_else(|| InputError::new("input.segments", "expected an array of segments"))?;
    if segs.is_empty() {
        return Err(InputError::new(
            "input.segments",
            "expected at least one segment",
        ));
    }
    let weights = weight_lists(&obj, segs.len())?;
    let mut segments = Vec::with_capacity(segs.len().min(MAX_OBJECTS));
    let mut total = 0usize;
    for (i, s) in segs.iter().enumerate() {
        let path = format!("input.segments[{i}]");
        let pts = point_list(s, &path)?;
        total = total.saturating_add(pts.len());
        check_total(total, MAX_TOTAL_POINTS, &path)?;
        if let Some(first) = segments.first() {
            check_like_first(first, pts.len(), pts.dim, &path)?;
        } else if pts.len() < 2 {
            return Err(InputError::new(
                path,
                "a segment needs at least 2 points (degree >= 1)",
            ));
        }
        let curve = match weights.get(i).and_then(Option::as_ref) {
            None => BezierCurve::new(pts.coords, pts.dim),
            Some(w) => {
                let wp = format!("input.weights[{i}]");
                if w.len() != pts.len() {
                    return Err(InputError::new(
                        wp,
                        format!(
                            "has {} entries, expected one per point of segments[{i}] ({})",
                            w.len(),
                            pts.len()
                        ),
                    ));
                }
                if let Some(j) = w.iter().position(|x| *x <= 0.0) {
                    return Err(InputError::new(
                        format!("{wp}[{j}]"),
                        format!("weight {} must be > 0", w[j]),
                    ));
                }
                BezierCurve::new_rational(pts.coords, w.clone(), pts.dim)
            }
        };
        segments.push(curve.map_err(|e| InputError::new(&path, e.to_string()))?);
    }
    let breaks = breaks(&obj, segments.len())?;
    Ok(Beziers { segments, breaks })
}

/// A segment after the first must have its number of points and dimension.
fn check_like_first(
    first: &BezierCurve,
    n: usize,
    dim: usize,
    path: &str,
) -> Result<(), InputError> {
    if dim != first.dim() {
        return Err(InputError::new(
            format!("{path}[0]"),
            format!(
                "has {dim} coordinates, the points of segments[0] have {}",
                first.dim()
            ),
        ));
    }
    if n != first.degree() + 1 {
        return Err(InputError::new(
            path,
            format!(
                "has {n} points, segments[0] has {} (all segments need the same degree)",
                first.degree() + 1
            ),
        ));
    }
    Ok(())
}

/// The optional `weights`: one list (or `null`) per segment.
fn weight_lists(obj: &Value, count: usize) -> Result<Vec<Option<Vec<f64>>>, InputError> {
    let w = match obj.get("weights") {
        None | Some(Value::Null) => return Ok(Vec::new()),
        Some(w) => w,
    };
    let lists = w
        .as_array()
        .ok_or_else(|| InputError::new("input.weights", "expected an array of weight lists"))?;
    if lists.len() != count {
        return Err(InputError::new(
            "input.weights",
            format!(
                "has {} lists, expected one per segment ({count})",
                lists.len()
            ),
        ));
    }
    lists
        .iter()
        .enumerate()
        .map(|(i, l)| match l {
            Value::Null => Ok(None),
            l => numbers(l, &format!("input.weights[{i}]")).map(Some),
        })
        .collect()
}

/// The optional `breaks` (default `0, 1, ..., count`), strictly increasing.
fn breaks(obj: &Value, count: usize) -> Result<Vec<f64>, InputError> {
    let b = match obj.get("breaks") {
        None | Some(Value::Null) => return Ok((0..=count).map(|i| i as f64).collect()),
        Some(b) => numbers(b, "input.breaks")?,
    };
    if b.len() != count + 1 {
        return Err(InputError::new(
            "input.breaks",
            format!(
                "has {} values, expected one more than the segments ({})",
                b.len(),
                count + 1
            ),
        ));
    }
    if let Some(i) = (1..b.len()).find(|&i| b[i] <= b[i - 1]) {
        return Err(InputError::new(
            format!("input.breaks[{i}]"),
            format!(
                "{} is not above breaks[{}] = {} (breaks must increase strictly)",
                b[i],
                i - 1,
                b[i - 1]
            ),
        ));
    }
    Ok(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_segments_weights_and_breaks() {
        let b = parse(
            r#"{"type":"beziers","segments":[[[0,0],[1,1]],[[1,1],[2,0]]],
                "weights":[null,[1,2]],"breaks":[0,0.5,2]}"#,
        )
        .unwrap();
        assert_eq!(b.segments.len(), 2);
        assert!(!b.segments[0].is_rational() && b.segments[1].is_rational());
        assert_eq!(b.breaks, [0.0, 0.5, 2.0]);
        let b = parse(r#"{"type":"beziers","segments":[[[0],[1]],[[1],[2]],[[2],[3]]]}"#).unwrap();
        assert_eq!(b.breaks, [0.0, 1.0, 2.0, 3.0]);
    }

    #[test]
    fn errors_name_the_field() {
        let cases = [
            ("[]", "input: expected one object"),
            (r#"{"segments":[]}"#, "input.type: missing field"),
            (
                r#"{"type":"bezier","segments":[]}"#,
                "input.type: got \"bezier\", merge expects \"beziers\"",
            ),
            (
                r#"{"type":"beziers","segments":[]}"#,
                "input.segments: expected at least one segment",
            ),
            (
                r#"{"type":"beziers","segments":[[[0]]]}"#,
                "input.segments[0]: a segment needs at least 2 points",
            ),
            (
                r#"{"type":"beziers","segments":[[[0,0],[1,1]],[[1,1],[2,0]],[[2,0],["x",1]]]}"#,
                "input.segments[2][1][0]: expected a number, got \"x\"",
            ),
            (
                r#"{"type":"beziers","segments":[[[0,0],[1,1]],[[1,1],[2]]]}"#,
                "input.segments[1][1]: has 1 coordinates, the first point has 2",
            ),
            (
                r#"{"type":"beziers","segments":[[[0,0],[1,1]],[[1],[2]]]}"#,
                "input.segments[1][0]: has 1 coordinates, the points of segments[0] have 2",
            ),
            (
                r#"{"type":"beziers","segments":[[[0],[1]],[[1],[2],[3]]]}"#,
                "input.segments[1]: has 3 points, segments[0] has 2",
            ),
            (
                r#"{"type":"beziers","segments":[[[0],[1]],[[1],[2]]],"weights":[[1,1]]}"#,
                "input.weights: has 1 lists, expected one per segment (2)",
            ),
            (
                r#"{"type":"beziers","segments":[[[0],[1]],[[1],[2]]],"weights":[null,[1,0]]}"#,
                "input.weights[1][1]: weight 0 must be > 0",
            ),
            (
                r#"{"type":"beziers","segments":[[[0],[1]],[[1],[2]]],"weights":[[1],null]}"#,
                "input.weights[0]: has 1 entries, expected one per point of segments[0] (2)",
            ),
            (
                r#"{"type":"beziers","segments":[[[0],[1]],[[1],[2]]],"breaks":[0,1]}"#,
                "input.breaks: has 2 values, expected one more than the segments (3)",
            ),
            (
                r#"{"type":"beziers","segments":[[[0],[1]],[[1],[2]]],"breaks":[0,2,2]}"#,
                "input.breaks[2]: 2 is not above breaks[1] = 2",
            ),
            (
                r#"{"type":"beziers","segments":[[[0],[1e999]]]}"#,
                "input.segments[0][1][0]: not valid JSON",
            ),
        ];
        for (text, want) in cases {
            let e = parse(text).unwrap_err().to_string();
            assert!(e.starts_with(want), "{text}: got {e:?}, want {want:?}");
        }
    }
}
