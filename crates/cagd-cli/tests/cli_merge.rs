//! `cagd merge` (seed 001 §4.1, exact merge): the spec vector 001-exact-merge-c0, a C1
//! spline split into its Bézier pieces and merged back, files, and bad input.

mod common;

use cagd_core::BSplineCurve;
use cagd_testkit::serde_json::{self, Value, json};
use cagd_testkit::{assert_close, flat, num, vector};
use common::{cagd, json_out};

/// The same nesting with every exact fraction `"p/q"` as a JSON number (rounded once).
fn numeric(v: &Value) -> Value {
    match v {
        Value::Array(a) => Value::Array(a.iter().map(numeric).collect()),
        other => json!(num(other)),
    }
}

/// The segments of vector 001-exact-merge-c0 as the input of `cagd merge`.
fn vector_input() -> (Value, Value) {
    let v = vector("vectors-reduce.json", "001-exact-merge-c0");
    let input = json!({"type": "beziers", "segments": numeric(&v["input"]["segments_exact"])});
    (input, v)
}

#[test]
fn vector_001_exact_merge_c0() {
    let (input, v) = vector_input();
    let out = json_out(&cagd(&["merge"], &input.to_string()));
    assert_eq!(out["type"], "bspline");
    assert_eq!(out["degree"], v["params"]["degree"]);
    assert_eq!(flat(&out["knots"]), flat(&v["expected"]["knots"]));
    let ctrl = flat(&v["expected"]["ctrl_exact"]);
    assert_close("001-exact-merge-c0", &flat(&out["points"]), &ctrl, 1e-15);
    assert!(out.get("weights").is_none());
    assert_eq!(out["report"]["segments"], 3);
    assert_eq!(out["report"]["continuity"], 0);

    // The segments are C1 too (not C2): with --continuity 1 the joint points go and the
    // interior knots have multiplicity 2.
    let out = json_out(&cagd(&["merge", "--continuity", "1"], &input.to_string()));
    assert_eq!(
        flat(&out["knots"]),
        [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 3.0, 3.0]
    );
    let without_joints: Vec<f64> = ctrl
        .chunks(2)
        .enumerate()
        .filter(|(i, _)| *i != 3 && *i != 6)
        .flat_map(|(_, p)| p.to_vec())
        .collect();
    assert_close("C1 merge", &flat(&out["points"]), &without_joints, 1e-14);
    let o = cagd(&["merge", "--continuity", "2"], &input.to_string());
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.starts_with("cagd: input.segments[1]: "), "{err}");
}

/// Splits `c` into its Bézier pieces and writes them as the input of `cagd merge`.
fn pieces_input(c: &BSplineCurve) -> Value {
    let pieces = c.to_beziers().expect("pieces");
    let rows =
        |flat: &[f64], dim: usize| -> Vec<Value> { flat.chunks(dim).map(|p| json!(p)).collect() };
    let segments: Vec<Value> = pieces
        .iter()
        .map(|p| json!(rows(p.curve.points(), p.curve.dim())))
        .collect();
    let mut breaks: Vec<f64> = pieces.iter().map(|p| p.start).collect();
    breaks.extend(pieces.last().map(|p| p.end));
    let mut input = json!({"type": "beziers", "segments": segments, "breaks": breaks});
    if c.is_rational() {
        let w: Vec<Value> = pieces.iter().map(|p| json!(p.curve.weights())).collect();
        input["weights"] = json!(w);
    }
    input
}

#[test]
fn c1_spline_split_and_merged_back() {
    // Cubic, double knots at 0.4 and 0.7 (C1 there), uneven spans; polynomial and NURBS.
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.4, 0.4, 0.7, 0.7, 1.0, 1.0, 1.0, 1.0];
    let pts = vec![
        0.0, 0.0, 1.0, 3.0, 2.0, 4.0, 4.0, 1.0, 5.0, -1.0, 7.0, 2.0, 8.0, 5.0, 9.0, 0.0,
    ];
    let w = vec![1.0, 2.0, 0.5, 1.0, 3.0, 1.0, 0.7, 1.0];
    let polynomial = BSplineCurve::new(3, knots.clone(), pts.clone(), 2).expect("spline");
    let nurbs = BSplineCurve::new_rational(3, knots.clone(), pts.clone(), w, 2).expect("nurbs");
    for c in [polynomial, nurbs] {
        let input = pieces_input(&c);
        let out = json_out(&cagd(&["merge", "--continuity", "1"], &input.to_string()));
        assert_eq!(out["degree"], 3);
        assert_eq!(flat(&out["knots"]), knots);
        assert_close("C1 round trip", &flat(&out["points"]), &pts, 1e-12);
        match c.weights() {
            Some(w) => assert_close("weights", &flat(&out["weights"]), w, 1e-12),
            None => assert!(out.get("weights").is_none()),
        }
        // The same pieces merged C0: every joint knot three times, the same curve.
        let out = json_out(&cagd(&["merge"], &input.to_string()));
        assert_eq!(flat(&out["knots"]).len(), 14);
    }
}

#[test]
fn files_in_and_out() {
    let dir = std::env::temp_dir().join(format!("cagd-merge-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let (input, v) = vector_input();
    let (inp, outp) = (dir.join("in.json"), dir.join("out.json"));
    std::fs::write(&inp, input.to_string()).expect("write input");
    let o = cagd(
        &[
            "merge",
            "-i",
            inp.to_str().expect("utf8"),
            "-o",
            outp.to_str().expect("utf8"),
            "--tol",
            "1e-12",
        ],
        "",
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(o.stdout.is_empty());
    let text = std::fs::read_to_string(&outp).expect("output");
    let out: Value = serde_json::from_str(&text).expect("JSON");
    assert_eq!(flat(&out["knots"]), flat(&v["expected"]["knots"]));
    assert_eq!(out["report"]["tolerance"], 1e-12);
    std::fs::remove_dir_all(&dir).expect("cleanup");
}

#[test]
fn bad_input_gives_one_line_and_exit_code_2() {
    let (input, _) = vector_input();
    let mut apart = input.clone();
    apart["segments"][2][0][1] = json!(0.75); // segment 2 starts 0.05 away from segment 1
    let mut short_point = input.clone();
    short_point["segments"][2][1] = json!([1.0]);
    let mut decreasing = input.clone();
    decreasing["breaks"] = json!([0, 2, 1, 3]);
    let mut bad_weight = input.clone();
    bad_weight["weights"] = json!([null, [1, 1, -1, 1], null]);
    let (apart, short_point, decreasing, bad_weight, input) = (
        apart.to_string(),
        short_point.to_string(),
        decreasing.to_string(),
        bad_weight.to_string(),
        input.to_string(),
    );
    let cases: &[(&[&str], &str, &str)] = &[
        (
            &["merge"],
            &apart,
            "cagd: input.segments[2]: condition of eq. 001 §4.1",
        ),
        (
            &["merge", "--tol", "0.1"],
            &apart,
            "", // within a tolerance of 0.1 the gap of 0.05 is accepted
        ),
        (
            &["merge"],
            &short_point,
            "cagd: input.segments[2][1]: has 1 coordinates, the first point has 2",
        ),
        (
            &["merge"],
            &decreasing,
            "cagd: input.breaks[2]: 1 is not above breaks[1] = 2",
        ),
        (
            &["merge"],
            &bad_weight,
            "cagd: input.weights[1][2]: weight -1 must be > 0",
        ),
        (
            &["merge", "--continuity", "3"],
            &input,
            "cagd: --continuity: 3 must be below the segments' degree 3",
        ),
        (
            &["merge"],
            "{\"type\":\"beziers\"}",
            "cagd: input.segments: missing field",
        ),
        (&["merge"], "[1,", "cagd: input[1]: not valid JSON"),
        (
            &["merge", "--tol", "-1"],
            &input,
            "cagd: --tol: -1 must be finite and > 0",
        ),
        (
            &["merge", "--svg", "x.svg"],
            &input,
            "cagd: merge: unknown argument \"--svg\"",
        ),
    ];
    for (args, stdin, want) in cases {
        let o = cagd(args, stdin);
        let err = String::from_utf8_lossy(&o.stderr);
        if want.is_empty() {
            assert!(o.status.success(), "{args:?}: {err}");
            continue;
        }
        assert_eq!(o.status.code(), Some(2), "{args:?} {stdin}");
        let first = err.lines().next().unwrap_or_default();
        assert!(
            first.starts_with(want),
            "{args:?}: got {err:?}, want {want:?}"
        );
        assert!(!err.contains("panicked"), "{err}");
        assert!(o.stdout.is_empty());
        // Only a usage error (an unknown or bad option) adds the usage text.
        if want.starts_with("cagd: input") || want.starts_with("cagd: --continuity") {
            assert_eq!(err.lines().count(), 1, "one line: {err:?}");
        }
    }
}
