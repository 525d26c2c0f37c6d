//! `cagd check` on the implicitization vectors (public file and our sympy-generated
//! `data/implicit_extra.json`), altered vectors that must fail, and the `implicitize` /
//! `intersect` commands with their bad input.

mod common;

use std::path::PathBuf;

use cagd_testkit::load_vectors;
use cagd_testkit::serde_json::{self, Value, json};
use common::{cagd, json_out};

const ALGOS: [&str; 2] = [
    "implicitize_rational_bezier_curve",
    "implicit_subdivision_matrix_A",
];

fn temp(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cagd-cli-implicit-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let p = dir.join(name);
    std::fs::write(&p, text).expect("write temp file");
    p
}

fn public_implicit_vectors() -> Vec<Value> {
    load_vectors("vectors-convert.json")
        .into_iter()
        .filter(|v| ALGOS.contains(&v["algorithm"].as_str().unwrap_or("")))
        .collect()
}

fn extra_vectors() -> Vec<Value> {
    let text = include_str!("data/implicit_extra.json");
    serde_json::from_str(text).expect("extra vectors")
}

fn check(name: &str, vectors: &[Value]) -> (bool, String) {
    let p = temp(name, &Value::Array(vectors.to_vec()).to_string());
    let o = cagd(&["check", p.to_str().expect("utf-8 path")], "");
    (
        o.status.success(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
    )
}

#[test]
fn public_and_extra_vectors_pass() {
    let public = public_implicit_vectors();
    assert!(
        public.len() >= 4,
        "public implicit vectors: {}",
        public.len()
    );
    let (ok, out) = check("public.json", &public);
    assert!(ok, "{out}");
    assert!(
        out.contains(&format!("{} passed, 0 failed", public.len())),
        "{out}"
    );
    let extra = extra_vectors();
    let (ok, out) = check("extra.json", &extra);
    assert!(ok, "{out}");
}

#[test]
fn altered_expectations_fail() {
    let base = public_implicit_vectors()
        .into_iter()
        .find(|v| v["id"] == "impl-n3-cubic")
        .expect("impl-n3-cubic");
    let mut alterations: Vec<Value> = Vec::new();
    // A coefficient off by 1e-9 relative to max |c|.
    let mut v = base.clone();
    let c = v["expected"]["monomials"][0][2].as_f64().unwrap();
    v["expected"]["monomials"][0][2] = json!(c + 1e-9 * 186_624.0);
    alterations.push(v);
    // A monomial missing.
    let mut v = base.clone();
    v["expected"]["monomials"].as_array_mut().unwrap().pop();
    alterations.push(v);
    // An extra monomial.
    let mut v = base.clone();
    v["expected"]["monomials"]
        .as_array_mut()
        .unwrap()
        .push(json!([3, 0, 1.0]));
    alterations.push(v);
    // The matrix at the origin and a curve sample.
    let mut v = base.clone();
    v["expected"]["matrix_F_at_origin"][1][1] = json!(-216.001);
    alterations.push(v);
    let mut v = base.clone();
    v["expected"]["curve_samples_t_x_y"][1][2] = json!(2.5714);
    alterations.push(v);
    // An error expected from a curve without base points.
    let mut v = base.clone();
    v["expected"] = json!({"error": "base point"});
    alterations.push(v);
    // A(alpha) altered.
    let mut a = public_implicit_vectors()
        .into_iter()
        .find(|v| v["algorithm"] == "implicit_subdivision_matrix_A")
        .expect("A vector");
    a["expected"]["A"][2][1] = json!(0.2223);
    alterations.push(a);
    for (k, v) in alterations.iter().enumerate() {
        let (ok, out) = check(&format!("altered{k}.json"), std::slice::from_ref(v));
        assert!(!ok, "alteration {k} passed: {out}");
        assert!(out.contains("0 passed, 1 failed"), "{out}");
    }
}

#[test]
fn implicitize_command_prints_the_polynomial() {
    let input = json!({"type": "bezier", "points": [[1, 0], [1, 1], [0, 1]], "weights": [1, 1, 2]});
    let out = json_out(&cagd(&["implicitize"], &input.to_string()));
    assert_eq!(out["degree"], 2);
    assert_eq!(
        out["monomials"],
        json!([[2, 0, -4.0], [0, 2, -4.0], [0, 0, 4.0]])
    );
    assert_eq!(
        out["monomials_exact"],
        json!([[2, 0, "-4"], [0, 2, "-4"], [0, 0, "4"]])
    );
    assert_eq!(out["report"]["proper"], true);
    // Base points: refused, or divided out on request.
    let bp =
        json!({"type": "bezier", "points": [[0, 1], [0.5, 0.5], [1, 0]], "weights": [4, 2, 1]});
    let o = cagd(&["implicitize"], &bp.to_string());
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("base point"));
    let out = json_out(&cagd(
        &["implicitize", "--divide-base-points"],
        &bp.to_string(),
    ));
    assert_eq!(out["degree"], 1);
    assert_eq!(out["report"]["base_points"], 1);
    // SVG.
    let svg = std::env::temp_dir().join(format!("cagd-impl-{}.svg", std::process::id()));
    let svg_s = svg.to_str().unwrap();
    json_out(&cagd(&["implicitize", "--svg", svg_s], &input.to_string()));
    let text = std::fs::read_to_string(&svg).expect("svg written");
    assert!(text.starts_with("<svg") && text.contains("<polyline"));
}

#[test]
fn implicitize_bad_input_is_one_line_with_exit_2() {
    let cases = [
        (
            json!({"type": "bezier", "points": [[0, 0, 0], [1, 1, 1]]}),
            "planar",
        ),
        (
            json!({"type": "bezier", "points": [[0, 0], [1, 1]], "weights": [1, 0]}),
            "weights[1]",
        ),
        (
            json!({"type": "bezier", "points": [[0, 0], [1, 1]], "weights": [1, -1]}),
            "weights[1]",
        ),
        (
            json!({"type": "bezier", "points": [[0, 0]]}),
            "not enough points",
        ),
        (
            json!({"type": "bezier", "points": [[0, 0], [1, "x"]]}),
            "points[1][1]",
        ),
        (
            json!({"type": "tensor", "degree": [1, 1], "points": [[0, 0], [1, 0], [0, 1], [1, 1]]}),
            "bezier",
        ),
    ];
    for (input, needle) in cases {
        let o = cagd(&["implicitize"], &input.to_string());
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{input}: {err}");
        assert!(err.contains(needle), "{input}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    }
    let big: Vec<Value> = (0..18).map(|i| json!([i, i * i % 7])).collect();
    let o = cagd(
        &["implicitize"],
        &json!({"type": "bezier", "points": big}).to_string(),
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("0..=16"));
}

#[test]
fn intersect_command() {
    let a = temp(
        "a.json",
        &json!({"type": "bezier", "points": [[0, 0], [1, 2], [2, 0]]}).to_string(),
    );
    let b = temp(
        "b.json",
        &json!({"type": "bezier", "points": [[-1, 0.5], [3, 0.5]], "weights": [1, 2]}).to_string(),
    );
    let out = json_out(&cagd(
        &["intersect", a.to_str().unwrap(), b.to_str().unwrap()],
        "",
    ));
    let hits = out["intersections"].as_array().expect("list");
    assert_eq!(hits.len(), 2);
    let s: Vec<f64> = hits.iter().map(|h| h["s"].as_f64().unwrap()).collect();
    assert!(s[0] < s[1]);
    // y(s) = 4 s (1 - s) = 0.5
    let root = (1.0 - 0.5f64.sqrt()) / 2.0;
    assert!((s[0] - root).abs() < 1e-14 && (s[1] - (1.0 - root)).abs() < 1e-14);
    for h in hits {
        assert_eq!(h["tangential"], false);
        assert!((h["point"][1].as_f64().unwrap() - 0.5).abs() < 1e-14);
    }
    // Overlapping arcs: a "coincident" report, no flood of points.
    let out = json_out(&cagd(
        &["intersect", a.to_str().unwrap(), a.to_str().unwrap()],
        "",
    ));
    assert_eq!(out["report"]["coincident"], true);
    assert_eq!(out["intersections"], json!([]));
    // Bad input names the file.
    let bad = temp(
        "bad.json",
        &json!({"type": "bezier", "points": [[0, 0, 1], [1, 1, 1]]}).to_string(),
    );
    let o = cagd(
        &["intersect", a.to_str().unwrap(), bad.to_str().unwrap()],
        "",
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("bad.json"));
}
