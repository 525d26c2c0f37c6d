//! `cagd check` on the NURBS ↔ rational Bézier vectors of SPEC-convert §15.1–15.3: the
//! public vectors pass, the same vectors with an `expected` number altered fail, error
//! vectors pass only when refused, and vectors of other knots (double and triple), weights
//! and dimensions pass against an independent route (cagd-core's blossoming extraction).

#[allow(dead_code, reason = "shared helpers; this file needs only cagd()")]
mod common;

use cagd_core::BSplineCurve;
use cagd_testkit::serde_json::{self, Value, json};
use common::cagd;

const ALGORITHMS: [&str; 6] = [
    "nurbs2_span_to_rational_bezier",
    "rational_bezier2_to_nurbs_span",
    "nurbs3_span_to_rational_bezier",
    "rational_bezier3_to_nurbs_span",
    "nurbs22_span_to_rational_bezier22",
    "rational_bezier22_to_nurbs22_span",
];

fn public_vectors() -> Vec<Value> {
    cagd_testkit::load_vectors("vectors-convert.json")
        .into_iter()
        .filter(|v| ALGORITHMS.contains(&v["algorithm"].as_str().unwrap_or("")))
        .collect()
}

/// Runs `cagd check` on the vectors (written to a temporary file); returns (success, stdout).
fn check(vectors: &[Value], name: &str) -> (bool, String) {
    let path = std::env::temp_dir().join(format!("cagd-check-{}-{name}.json", std::process::id()));
    std::fs::write(&path, serde_json::to_string(vectors).unwrap()).unwrap();
    let out = cagd(&["check", path.to_str().unwrap()], "");
    let _ = std::fs::remove_file(&path);
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
    )
}

#[test]
fn public_vectors_pass() {
    let vectors = public_vectors();
    assert_eq!(vectors.len(), 9);
    let (ok, text) = check(&vectors, "public");
    assert!(ok, "{text}");
    assert!(text.contains("9 passed, 0 failed"), "{text}");
}

/// The first number inside `v` (depth first), mutably.
fn first_number(v: &mut Value) -> Option<&mut Value> {
    match v {
        Value::Number(_) => Some(v),
        Value::Array(a) => a.iter_mut().find_map(first_number),
        Value::Object(o) => o.values_mut().find_map(first_number),
        _ => None,
    }
}

#[test]
fn altered_expected_fails() {
    for v in public_vectors() {
        for key in v["expected"]
            .as_object()
            .unwrap()
            .keys()
            .cloned()
            .collect::<Vec<_>>()
        {
            let mut bad = v.clone();
            let x = first_number(&mut bad["expected"][&key]).unwrap();
            *x = json!(x.as_f64().unwrap() + 1e-6);
            let (ok, text) = check(&[bad], "altered");
            assert!(!ok, "{} {key}: {text}", v["id"]);
            assert!(text.contains("0 passed, 1 failed"), "{text}");
        }
    }
}

#[test]
fn error_vectors_pass_only_when_refused() {
    let vectors = vec![
        // SPEC-convert conv-15.3-inv-condition-fails: the weights would be (-21, 4, -1, 9).
        json!({"id": "c3", "algorithm": "rational_bezier3_to_nurbs_span",
               "params": {"a": 1.0, "b": 1.0, "c": 0.5, "d": 1.0, "e": 1.0},
               "input": {"bezier_weights": [1.0, 2.0, 1.0, 1.0],
                         "bezier_points": [[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]},
               "expected": {"error": "ConditionNotMet(15.3.13-16)"}, "tol": 1e-12}),
        // 15.1.8: b = c = d = 1, W = (1, 3, 1): w_{n-2} = -1.
        json!({"id": "c1", "algorithm": "rational_bezier2_to_nurbs_span",
               "params": {"b": 1.0, "c": 1.0, "d": 1.0},
               "input": {"bezier_weights": [1.0, 3.0, 1.0],
                         "bezier_points": [[0.0], [1.0], [2.0]]},
               "expected": {"error": "ConditionNotMet(15.1.8)"}, "tol": 1e-12}),
        // 15.2: Bézier weights that are not rank 1.
        json!({"id": "c22", "algorithm": "rational_bezier22_to_nurbs22_span",
               "params": {"p": 1.0, "q": 1.0, "r": 1.0, "b": 1.0, "c": 1.0, "d": 1.0},
               "input": {"bezier_weights": [[1.0, 1.0, 1.0], [1.0, 2.0, 1.0], [1.0, 1.0, 1.0]],
                         "bezier_points": (0..9).map(|k| json!([k / 3, k % 3])).collect::<Vec<_>>()},
               "expected": {"error": "not separable"}, "tol": 1e-12}),
        // Bad input: a zero-length span, a non-positive weight.
        json!({"id": "zero-span", "algorithm": "nurbs3_span_to_rational_bezier",
               "input": {"knots_local": [0.0, 1.0, 2.0, 2.0, 3.0, 4.0], "weights": [1.0, 1.0, 1.0, 1.0],
                         "points": [[0.0], [1.0], [2.0], [3.0]]},
               "expected": {"error": "degenerate span"}, "tol": 1e-12}),
        json!({"id": "weight", "algorithm": "nurbs2_span_to_rational_bezier",
               "input": {"knots_local": [0.0, 1.0, 2.0, 3.0], "weights": [1.0, -1.0, 1.0],
                         "points": [[0.0], [1.0], [2.0]]},
               "expected": {"error": "weight"}, "tol": 1e-12}),
    ];
    let (ok, text) = check(&vectors, "errors");
    assert!(ok, "{text}");
    assert!(text.contains("5 passed, 0 failed"), "{text}");
    // The same inputs with a numeric expectation fail.
    let mut wrong = vectors[0].clone();
    wrong["expected"] = json!({"weights": [1.0, 1.0, 1.0, 1.0]});
    let (ok, _) = check(&[wrong], "errors-wrong");
    assert!(!ok);
}

/// Local knots, points and weights of one span of a random-ish spline; the Bézier segment
/// by cagd-core's blossoming extraction (an independent route).
fn core_segment(
    p: usize,
    knots: &[f64],
    pts: &[f64],
    w: &[f64],
    dim: usize,
) -> (Vec<f64>, Vec<f64>) {
    // Full knot vector: repeat the outer local knots once more.
    let mut full = vec![knots[0]];
    full.extend_from_slice(knots);
    full.push(knots[knots.len() - 1]);
    let c = BSplineCurve::new_rational(p, full, pts.to_vec(), w.to_vec(), dim).unwrap();
    let seg = c.to_beziers().unwrap().remove(0).curve;
    (seg.points().to_vec(), seg.weights().unwrap().to_vec())
}

#[test]
fn other_knots_weights_and_dimensions_pass_both_ways() {
    let cases: Vec<(usize, Vec<f64>, usize)> = vec![
        (2, vec![0.0, 0.0, 2.0, 5.0], 2),           // b = 0 (double start)
        (2, vec![0.0, 1.0, 1.5, 1.5], 3),           // d = 0
        (3, vec![1.0, 1.0, 1.0, 2.0, 3.0, 5.0], 2), // a = b = 0 (triple start)
        (3, vec![0.0, 1.0, 2.0, 4.0, 4.0, 4.0], 1), // d = e = 0 (triple end)
        (3, vec![0.0, 0.5, 0.5, 2.0, 2.0, 2.5], 4), // b = d = 0
        (3, vec![-3.0, -1.0, 0.0, 0.25, 7.0, 8.0], 3), // uneven
    ];
    let mut vectors = Vec::new();
    for (case, (p, knots, dim)) in cases.into_iter().enumerate() {
        let n = p + 1;
        let pts: Vec<f64> = (0..n * dim)
            .map(|k| ((k * 7 + case) as f64 * 0.91).sin() * 4.0)
            .collect();
        let w: Vec<f64> = (0..n)
            .map(|k| 0.3 + ((k + case) as f64 * 1.3).cos().abs() * 3.0)
            .collect();
        let (bp, bw) = core_segment(p, &knots, &pts, &w, dim);
        let rows = |f: &[f64]| f.chunks(dim).map(|c| json!(c)).collect::<Vec<_>>();
        let (fwd, inv) = if p == 2 {
            (
                "nurbs2_span_to_rational_bezier",
                "rational_bezier2_to_nurbs_span",
            )
        } else {
            (
                "nurbs3_span_to_rational_bezier",
                "rational_bezier3_to_nurbs_span",
            )
        };
        vectors.push(
            json!({"id": format!("fwd-{case}"), "algorithm": fwd, "params": {},
            "input": {"knots_local": knots, "weights": w, "points": rows(&pts)},
            "expected": {"bezier_weights": bw, "bezier_points": rows(&bp)}, "tol": 1e-12}),
        );
        let names: &[&str] = if p == 2 {
            &["b", "c", "d"]
        } else {
            &["a", "b", "c", "d", "e"]
        };
        let params: serde_json::Map<String, Value> = names
            .iter()
            .enumerate()
            .map(|(i, n)| (n.to_string(), json!(knots[i + 1] - knots[i])))
            .collect();
        vectors.push(
            json!({"id": format!("inv-{case}"), "algorithm": inv, "params": params,
            "input": {"bezier_weights": bw, "bezier_points": rows(&bp)},
            "expected": {"weights": w, "points": rows(&pts)}, "tol": 1e-10}),
        );
    }
    let (ok, text) = check(&vectors, "others");
    assert!(ok, "{text}");
}
