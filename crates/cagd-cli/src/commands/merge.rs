//! `cagd merge`: the exact merge of Bézier segments into one B-spline / NURBS curve (seed
//! 001 §4.1, `BSplineCurve::from_beziers`), written in the command's B-spline shape.

use cagd_core::{BSplineCurve, BezierCurve, Error};
use std::process::ExitCode;

use serde_json::{Value, json};

use crate::commands::args::MergeArgs;
use crate::input::InputError;
use crate::input::beziers::{Beziers, parse};
use crate::input::shape::Shape;

/// The relative factor of the default tolerance: `1e-9 * max(1, largest |coordinate|)`.
pub(crate) const DEFAULT_REL_TOL: f64 = 1e-9;

/// The default tolerance of the joint check: [`DEFAULT_REL_TOL`] times the size of the
/// points, `max(1, largest |coordinate|)`, the coordinates of rational segments' homogeneous
/// points `(w x, w)` included (the C0 check compares those).
pub(crate) fn default_tol(segments: &[BezierCurve]) -> f64 {
    let mut size: f64 = 1.0;
    for s in segments {
        for c in s.points() {
            size = size.max(c.abs());
        }
        if s.is_rational() {
            for c in s.homogeneous_points() {
                size = size.max(c.abs());
            }
        }
    }
    // Finite even when a weighted coordinate overflows (the merge then reports that).
    (DEFAULT_REL_TOL * size).min(f64::MAX)
}

/// Reads the input text, merges, and returns the output JSON: the spline in the input
/// shape of `"bspline"` plus a `"report"`. An error names the field (or option) and index.
pub(crate) fn run(text: &str, args: &MergeArgs) -> Result<Value, InputError> {
    let Beziers { segments, breaks } = parse(text)?;
    let m = segments.first().map_or(0, BezierCurve::degree);
    if args.continuity >= m {
        return Err(InputError::new(
            "--continuity",
            format!("{} must be below the segments' degree {m}", args.continuity),
        ));
    }
    let tol = args.tol.unwrap_or_else(|| default_tol(&segments));
    let k = args.continuity;
    let merged = BSplineCurve::from_beziers(&segments, &breaks, k, tol)
        .map_err(|e| locate_joint(&segments, &breaks, k, tol, &e))?;
    let mut v = Shape::BSpline(merged).to_json();
    v["report"] = json!({
        "merge": "exact",
        "segments": segments.len(),
        "continuity": k,
        "tolerance": tol,
    });
    Ok(v)
}

/// The error of a failed merge, naming the segment whose joint fails: for a condition not
/// met, the smallest `n` such that the first `n` segments merge and the first `n + 1` do
/// not (bisection; so `segments[n]` cannot be joined to the merged `segments[..n]`).
fn locate_joint(
    segments: &[BezierCurve],
    breaks: &[f64],
    k: usize,
    tol: f64,
    e: &Error,
) -> InputError {
    if !matches!(e, Error::ConditionNotMet { .. }) || segments.len() < 2 {
        return InputError::new("input", e.to_string());
    }
    let merges =
        |n: usize| BSplineCurve::from_beziers(&segments[..n], &breaks[..=n], k, tol).is_ok();
    // Invariant: the first `lo` segments merge, the first `hi` do not.
    let (mut lo, mut hi) = (1, segments.len());
    if !merges(lo) {
        return InputError::new("input", e.to_string());
    }
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if merges(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let j = hi - 1;
    InputError::new(
        format!("input.segments[{j}]"),
        format!(
            "{e} (at the joint with segments[{}], t = {}; continuity C^{k}, tolerance {tol:e})",
            j - 1,
            breaks[j]
        ),
    )
}

/// `cagd merge`: one object in, one B-spline out.
pub(crate) fn command(args: &MergeArgs) -> ExitCode {
    let result = crate::input::read_input(args.input.as_deref())
        .and_then(|text| run(&text, args).map_err(|e| e.to_string()));
    let json = match result {
        Ok(v) => v,
        Err(e) => {
            eprintln!("cagd: {e}");
            return ExitCode::from(2);
        }
    };
    crate::output::json::write_json(args.output.as_deref(), &json)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-15 * b.abs()
    }

    fn args(continuity: usize, tol: Option<f64>) -> MergeArgs {
        MergeArgs {
            continuity,
            tol,
            input: None,
            output: None,
        }
    }

    #[test]
    fn merges_and_reports() {
        let text = r#"{"type":"beziers","segments":[[[0],[1],[2]],[[2],[4],[5]]]}"#;
        let v = run(text, &args(0, None)).unwrap();
        assert_eq!(v["type"], "bspline");
        assert_eq!(v["degree"], 2);
        assert_eq!(v["knots"], json!([0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0]));
        assert_eq!(v["points"], json!([[0.0], [1.0], [2.0], [4.0], [5.0]]));
        assert!(close(v["report"]["tolerance"].as_f64().unwrap(), 5e-9));
        let e = run(text, &args(1, None)).unwrap_err();
        assert_eq!(e.path, "input.segments[1]");
        assert!(e.message.contains("C^1"), "{}", e.message);
        let e = run(text, &args(2, None)).unwrap_err();
        assert_eq!(
            e.to_string(),
            "--continuity: 2 must be below the segments' degree 2"
        );
    }

    #[test]
    fn the_failing_joint_is_named() {
        for bad in 1..5 {
            let segs: Vec<Value> = (0..5)
                .map(|i| {
                    let start = if i == bad {
                        f64::from(i) + 0.5
                    } else {
                        f64::from(i)
                    };
                    json!([[start], [f64::from(i) + 1.0]])
                })
                .collect();
            let text = json!({"type": "beziers", "segments": segs}).to_string();
            let e = run(&text, &args(0, Some(1e-6))).unwrap_err();
            assert_eq!(e.path, format!("input.segments[{bad}]"));
            assert!(e.message.contains("001 §4.1"), "{}", e.message);
        }
    }

    #[test]
    fn default_tolerance_scales_with_the_points() {
        let a = BezierCurve::new(vec![0.0, -300.0], 1).unwrap();
        assert!(close(default_tol(&[a]), 3e-7));
        let r = BezierCurve::new_rational(vec![0.5, 2.0], vec![4.0, 1.0], 1).unwrap();
        assert!(close(default_tol(&[r]), 4e-9));
        let small = BezierCurve::new(vec![0.0, 0.1], 1).unwrap();
        assert_eq!(default_tol(&[small]), 1e-9);
    }
}
