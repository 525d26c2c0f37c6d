//! Runs the `cagd` binary on files and compares its JSON with the spec vectors and with the
//! library; checks the one-line errors and exit codes for bad input.

mod common;

use cagd_testkit::serde_json::{Value, json};
use cagd_testkit::{assert_close, flat, vector};
use common::{cagd, json_out};

fn bezier(points: &Value) -> String {
    json!({"type": "bezier", "points": points}).to_string()
}

#[test]
fn spec_vectors_through_the_command() {
    // (vector id, method, extra args, expected field)
    let cases: &[(&str, &str, &[&str])] = &[
        ("forrest-1", "forrest", &[]),
        ("farin-1", "farin", &[]),
        ("eck-1", "eck", &[]),
        ("piegl-tiller-n8", "piegl", &[]),
        ("perturb-curve-1", "perturbation", &[]),
        ("ginv-n7-m3-free", "pinv", &[]),
        ("ginv-n7-m3-ends", "pinv-ends", &[]),
        (
            "cheb-ends-n15-m10-r1-p1",
            "chebyshev",
            &["--r", "1", "--p", "1"],
        ),
        ("cheb-trunc-n7-m4", "bogacki", &[]),
        ("hermite-n7-m3", "chebyshev", &["--r", "1", "--p", "1"]),
    ];
    for (id, method, extra) in cases {
        let v = vector("vectors-reduce.json", id);
        let p = &v["input"]["P"];
        let n = p.as_array().expect("points").len() - 1;
        let m = v["params"]["m"]
            .as_u64()
            .map_or(n - 1, |m| usize::try_from(m).expect("small"));
        let ms = m.to_string();
        let mut args = vec!["reduce", "--to", ms.as_str(), "--method", method];
        args.extend_from_slice(extra);
        let out = json_out(&cagd(&args, &bezier(p)));
        let tol = v["tol"].as_f64().expect("tol");
        assert_close(id, &flat(&out["points"]), &flat(&v["expected"]["Q"]), tol);
        let report = &out["report"];
        assert_eq!(report["degree_from"], n, "{id}");
        assert_eq!(report["degree_to"], m, "{id}");
        let (bound, measured) = (
            report["error_bound"].as_f64().expect("bound"),
            report["max_error"].as_f64().expect("measured"),
        );
        assert!(
            measured <= bound,
            "{id}: measured {measured} > bound {bound}"
        );
    }
}

#[test]
fn arrays_in_arrays_out_and_files() {
    let dir = std::env::temp_dir().join(format!("cagd-cli-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let input = dir.join("in.json");
    let output = dir.join("out.json");
    let svg = dir.join("out.svg");
    let curves = json!([
        {"type": "bezier", "points": [[0, 0], [1, 3], [3, 4], [5, 1], [6, 5]]},
        {"type": "bezier", "points": [[0, 0, 0], [1, 2, 1], [2, 3, -1], [4, 3, 0]],
         "weights": [1, 2, 2, 1]}
    ]);
    std::fs::write(&input, curves.to_string()).expect("write input");
    let o = cagd(
        &[
            "reduce",
            "--to",
            "2",
            "-i",
            input.to_str().expect("utf8"),
            "-o",
            output.to_str().expect("utf8"),
            "--svg",
            svg.to_str().expect("utf8"),
        ],
        "",
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out: Value =
        serde_json::from_str(&std::fs::read_to_string(&output).expect("output")).expect("JSON");
    let arr = out.as_array().expect("array in, array out");
    assert_eq!(arr.len(), 2);
    assert_eq!(arr[0]["points"].as_array().expect("points").len(), 3);
    assert_eq!(
        arr[1]["weights"]
            .as_array()
            .expect("rational stays rational")
            .len(),
        3
    );
    assert_eq!(arr[1]["report"]["space"], "euclidean");
    let picture = std::fs::read_to_string(&svg).expect("svg written");
    assert!(picture.starts_with("<svg") && picture.contains("<polyline"));
    std::fs::remove_dir_all(&dir).expect("cleanup");
}

#[test]
fn bad_input_gives_one_line_and_exit_code_2() {
    let cases: &[(&[&str], &str, &str)] = &[
        (&["reduce", "--to", "2"], "{", "cagd: input: not valid JSON"),
        (
            &["reduce", "--to", "2"],
            r#"{"type":"bezier"}"#,
            "cagd: input.points: missing field",
        ),
        (
            &["reduce", "--to", "1"],
            r#"[{"type":"bezier","points":[[0,0],[1,1],[2,0]]},{"type":"bezier","points":[[0,0],[1]]}]"#,
            "cagd: input[1].points[1]: has 1 coordinates, the first point has 2",
        ),
        (
            &["reduce", "--to", "3"],
            r#"{"type":"bezier","points":[[0],[1],[2]]}"#,
            "cagd: input: degree pair 2 -> 3",
        ),
        (
            &["reduce", "--to", "2", "--method", "magic"],
            r#"{"type":"bezier","points":[[0],[1],[2],[3]]}"#,
            "cagd: --method: unknown method \"magic\"",
        ),
        (
            &[
                "reduce", "--to", "2", "--method", "l2", "--r", "1", "--p", "1",
            ],
            r#"{"type":"bezier","points":[[0],[1],[2],[3]]}"#,
            "cagd: input: too many end constraints",
        ),
    ];
    for (args, stdin, want) in cases {
        let o = cagd(args, stdin);
        assert_eq!(o.status.code(), Some(2), "{args:?} {stdin}");
        let err = String::from_utf8_lossy(&o.stderr);
        let first = err.lines().next().unwrap_or_default();
        assert!(first.starts_with(want), "{args:?} {stdin}: got {err:?}");
        assert!(!err.contains("panicked"), "{err}");
        assert!(o.stdout.is_empty());
    }
}

#[test]
fn demo_writes_table_and_pictures() {
    let dir = std::env::temp_dir().join(format!("cagd-demo-test-{}", std::process::id()));
    let o = cagd(&["demo", "--out", dir.to_str().expect("utf8")], "");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let table = String::from_utf8_lossy(&o.stdout);
    assert!(table.contains("ex-14.5.1-fifteenth"));
    assert!(table.contains("chebyshev (r,p)=(2,2)"));
    let svgs = std::fs::read_dir(&dir).expect("demo folder").count();
    assert!(svgs >= 5, "{svgs} pictures");
    std::fs::remove_dir_all(&dir).expect("cleanup");
}

#[test]
fn reduction_to_a_tolerance_gives_a_bspline_within_tolerance() {
    let p = json!([
        [0, 0],
        [1, 4],
        [2, 6],
        [4, 7],
        [6, 5],
        [7, 2],
        [9, 1],
        [11, 3],
        [12, 6],
        [14, 7],
        [16, 4]
    ]);
    for (tol, k) in [("1e-2", "0"), ("1e-4", "1"), ("1e-6", "1")] {
        let out = json_out(&cagd(
            &["reduce", "--to", "3", "--tol", tol, "--continuity", k],
            &bezier(&p),
        ));
        assert_eq!(out["type"], "bspline");
        assert_eq!(out["degree"], 3);
        let r = &out["report"];
        let t: f64 = tol.parse().expect("number");
        let (bound, measured) = (
            r["error_bound"].as_f64().expect("bound"),
            r["max_error"].as_f64().expect("measured"),
        );
        assert!(measured <= bound && bound <= t, "{tol}: {measured} {bound}");
        // Interior knots have multiplicity m - k.
        let knots = flat(&out["knots"]);
        let kk: usize = k.parse().expect("k");
        let interior: Vec<f64> = knots
            .iter()
            .copied()
            .filter(|x| *x > 0.0 && *x < 1.0)
            .collect();
        assert_eq!(
            interior.len(),
            (usize::try_from(r["pieces"].as_u64().expect("pieces")).expect("small") - 1) * (3 - kk)
        );
    }
    // Continuity 3 for a cubic is impossible and says so.
    let o = cagd(
        &["reduce", "--to", "3", "--tol", "1e-3", "--continuity", "3"],
        &bezier(&p),
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).starts_with("cagd: input: "));
}

#[test]
fn patches_through_the_command() {
    // tensor-1: 2 x 3 -> 1 x 2 by the perturbation method of §14.3.1.
    let v = vector("vectors-reduce.json", "tensor-1");
    let rows = v["input"]["P"].as_array().expect("rows");
    let pts: Vec<Value> = rows
        .iter()
        .flat_map(|r| r.as_array().expect("row").clone())
        .collect();
    let input = json!({"type": "tensor", "degree": [rows.len() - 1, rows[0].as_array().expect("row").len() - 1], "points": pts});
    let out = json_out(&cagd(
        &["reduce", "--to", "1,2", "--method", "perturbation"],
        &input.to_string(),
    ));
    assert_eq!(out["degree"], json!([1, 2]));
    assert_close(
        "tensor-1",
        &flat(&out["points"]),
        &flat(&v["expected"]["Q"]),
        1e-12,
    );
    let r = &out["report"];
    assert!(r["max_error"].as_f64().expect("m") <= r["error_bound"].as_f64().expect("b"));

    // tri-1: degree 3 -> 2 by §14.3.2.
    let v = vector("vectors-reduce.json", "tri-1");
    let input = json!({"type": "triangle", "degree": 3, "points": v["input"]["T"]});
    let out = json_out(&cagd(
        &["reduce", "--to", "2", "--method", "perturbation"],
        &input.to_string(),
    ));
    assert_close(
        "tri-1",
        &flat(&out["points"]),
        &flat(&v["expected"]["Q"]),
        1e-12,
    );

    // Multi-degree and to a tolerance: every piece within the tolerance.
    let out = json_out(&cagd(
        &["reduce", "--to", "1", "--tol", "0.5"],
        &input.to_string(),
    ));
    assert_eq!(out["type"], "triangle-pieces");
    let pieces = out["pieces"].as_array().expect("pieces");
    assert!(!pieces.is_empty());
    for p in pieces {
        assert!(p["report"]["error_bound"].as_f64().expect("bound") <= 0.5);
        assert_eq!(p["vertices"].as_array().expect("vertices").len(), 3);
    }
    // A triangle has one degree.
    let o = cagd(&["reduce", "--to", "2,1"], &input.to_string());
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).starts_with("cagd: --to: "));
}

#[test]
fn bsplines_through_the_command() {
    // Seed 001's example (vector 001-example): degree 7, 9 points, uniform knots 0..16, C1
    // Hermite segments, lossy merge -> the printed merged points (SPEC-reduce §8).
    let v = vector("vectors-reduce.json", "001-example");
    let input = json!({"type": "bspline", "degree": 7, "knots": v["params"]["knots"], "points": v["input"]["P"]});
    let out = json_out(&cagd(
        &[
            "reduce",
            "--to",
            "3",
            "--method",
            "chebyshev",
            "--r",
            "1",
            "--p",
            "1",
            "--merge",
            "lossy",
        ],
        &input.to_string(),
    ));
    let merged = [
        6.787434, 4.882407, 8.209788, 6.409987, 9.790344, 5.288558, 11.209788, 6.186376, 12.790476,
        6.141931,
    ];
    assert_close(
        "001 merged points (6 decimals)",
        &flat(&out["points"]),
        &merged,
        1e-7,
    );
    let r = &out["report"];
    assert!(r["max_error"].as_f64().expect("m") <= r["error_bound"].as_f64().expect("b"));
    // Any B-spline to a tolerance.
    for tol in ["1e-2", "1e-5"] {
        let out = json_out(&cagd(
            &["reduce", "--to", "3", "--tol", tol],
            &input.to_string(),
        ));
        let r = &out["report"];
        let t: f64 = tol.parse().expect("number");
        let (b, m) = (
            r["error_bound"].as_f64().expect("b"),
            r["max_error"].as_f64().expect("m"),
        );
        assert!(m <= b && b <= t, "{tol}: {m} {b}");
        assert_eq!(out["degree"], 3);
    }
    // Non-uniform knots need a tolerance.
    let nonuniform = json!({"type": "bspline", "degree": 2, "knots": [0, 0, 0, 0.3, 1, 1, 1], "points": [[0, 0], [1, 2], [2, 0], [3, 1]]});
    let o = cagd(&["reduce", "--to", "1"], &nonuniform.to_string());
    assert_eq!(o.status.code(), Some(2));
    // Bad knots name the field.
    let bad =
        json!({"type": "bspline", "degree": 1, "knots": [0, 1, 0.5, 2], "points": [[0], [1]]});
    let o = cagd(&["reduce", "--to", "0", "--tol", "1"], &bad.to_string());
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).starts_with("cagd: input.knots[2]: "));
}
