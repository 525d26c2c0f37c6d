//! WSGB curves (seed 003) through the command: `cagd check` on the public `wsgb_*` vectors
//! (and a tampered copy that must fail), `cagd reduce` on random curves against independent
//! routes (the spec's one-step formulas written out here, Chebyshev economisation of the
//! Bézier form, sampling of both curves), bad input.

mod common;

use cagd_core::{BezierCurve, WsgbCurve, wsgb_max_l};
use cagd_reduce::{Method, reduce as reduce_bezier};
use cagd_testkit::serde_json::{self, Value, json};
use cagd_testkit::{flat, load_vectors};
use common::{cagd, json_out};

fn write_vectors(name: &str, vs: &[Value]) -> String {
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::write(&path, serde_json::to_string(vs).unwrap()).unwrap();
    path.to_string_lossy().into_owned()
}

fn public_wsgb() -> Vec<Value> {
    load_vectors("vectors-reduce.json")
        .into_iter()
        .filter(|v| {
            v["algorithm"]
                .as_str()
                .is_some_and(|a| a.starts_with("wsgb"))
        })
        .collect()
}

#[test]
fn check_passes_the_public_wsgb_vectors() {
    let vs = public_wsgb();
    assert!(vs.len() >= 5);
    let file = write_vectors("wsgb_public.json", &vs);
    let out = cagd(&["check", &file], "");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}");
    assert!(
        text.contains(&format!("{} passed, 0 failed", vs.len())),
        "{text}"
    );
}

#[test]
fn check_passes_independent_vectors_of_unseen_forms() {
    // Other n, L, dimensions (n = 2..12, 1-D to 3-D, L up to the Wang–Ball order), made by
    // tests/data/wsgb_reference.py from the spec's formulas in Python fractions (its own
    // basis, matrix solve, inverse elevation and 4001-point grid).
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/wsgb_independent.json"
    );
    let out = cagd(&["check", file], "");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}");
    assert!(text.contains("17 passed, 0 failed"), "{text}");
}

#[test]
fn check_fails_altered_vectors() {
    let base = public_wsgb();
    let mut cases: Vec<Value> = Vec::new();
    let reduce = base.iter().find(|v| v["id"] == "wsgb-7-1-perturb").unwrap();
    let mut a = reduce.clone();
    a["expected"]["Q_exact"][3][0] = json!("614/2");
    cases.push(a);
    let mut b = reduce.clone();
    b["expected"]["true_max_error_inf"] = json!(2.1198517418565643 * (1.0 + 1e-9));
    cases.push(b);
    let mut c = reduce.clone();
    c["expected"]["lec"][0] = json!(-1141.0);
    cases.push(c);
    let mut d = base
        .iter()
        .find(|v| v["algorithm"] == "wsgb_basis")
        .unwrap()
        .clone();
    d["expected"]["terms_K_a_b"][2][0] = json!("7");
    cases.push(d);
    for (i, v) in cases.iter().enumerate() {
        let file = write_vectors(&format!("wsgb_altered_{i}.json"), std::slice::from_ref(v));
        let out = cagd(&["check", &file], "");
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(!out.status.success(), "case {i} passed: {text}");
        assert!(text.contains("0 passed, 1 failed"), "case {i}: {text}");
    }
}

#[test]
fn check_refuses_bad_wsgb_input() {
    // Unseen forms: L out of range and n < 2 for the perturbation method must be refused;
    // a 3-D WSGB(9, 3) basis must be produced.
    let vs = vec![
        json!({"id": "bad-L", "algorithm": "wsgb_reduce_003",
               "params": {"n": 6, "L": 3, "method": "uniform"},
               "input": {"P": [[0,0],[1,1],[2,0],[3,1],[4,0],[5,1],[6,0]]},
               "expected": {"error": "L out of range"}, "tol": 0}),
        json!({"id": "short", "algorithm": "wsgb_reduce_003",
               "params": {"n": 1, "L": 0, "method": "perturb"},
               "input": {"P": [[0,0,1],[1,1,2]]},
               "expected": {"error": "n < 2"}, "tol": 0}),
        json!({"id": "basis-bad", "algorithm": "wsgb_basis", "params": {"n": 4, "L": 2},
               "input": {}, "expected": {"error": "L"}, "tol": 0}),
        // Said–Ball degree 3: (1-u)^2, 2u(1-u)^2, 2u^2(1-u), u^2 (hand-expanded).
        json!({"id": "basis-3-0", "algorithm": "wsgb_basis", "params": {"n": 3, "L": 0},
               "input": {}, "expected": {"terms_K_a_b": [["1",0,2],["2",1,2],["2",2,1],["1",2,0]]},
               "tol": 0}),
    ];
    let file = write_vectors("wsgb_errors.json", &vs);
    let out = cagd(&["check", &file], "");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}");
}

fn pseudo(n: usize, dim: usize, seed: u64) -> Vec<f64> {
    let mut s = seed.wrapping_add(0x2545_F491_4F6C_DD1D);
    (0..(n + 1) * dim)
        .map(|_| {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 11) as f64 / (1u64 << 53) as f64) * 200.0 - 100.0
        })
        .collect()
}

/// SPEC-reduce §9.4 + §9.3 written out independently of the library (f64).
fn spec_perturbation(p: &[f64], dim: usize, l: usize) -> Vec<f64> {
    let n = p.len() / dim - 1;
    let m = n / 2;
    let at = |i: usize, d: usize| p[i * dim + d];
    let mut pb = p.to_vec();
    for d in 0..dim {
        if n % 2 == 1 {
            let mid = 0.5 * (at(m, d) + at(m + 1, d));
            pb[m * dim + d] = mid;
            pb[(m + 1) * dim + d] = mid;
        } else {
            let f = at(m - 1, d) - 2.0 * at(m, d) + at(m + 1, d);
            pb[(m - 1) * dim + d] -= f / 6.0;
            pb[m * dim + d] += f / 3.0;
            pb[(m + 1) * dim + d] -= f / 6.0;
        }
    }
    let b = |i: usize, d: usize| pb[i * dim + d];
    let mut q = vec![0.0; n * dim];
    for d in 0..dim {
        if n % 2 == 1 {
            for i in 0..n {
                q[i * dim + d] = b(if i <= m { i } else { i + 1 }, d);
            }
        } else {
            for i in 0..m {
                let (lo, hi) = if i < l {
                    (b(i, d), b(n - i, d))
                } else {
                    let (c1, c2, den) = ((m + i - 2 * l) as f64, (i - l) as f64, (m - l) as f64);
                    let prev = |j: usize| if i > l { b(j, d) } else { 0.0 };
                    (
                        (c1 * b(i, d) - c2 * prev(i.saturating_sub(1))) / den,
                        (c1 * b(n - i, d) - c2 * prev(n - i + 1)) / den,
                    )
                };
                q[i * dim + d] = lo;
                q[(n - 1 - i) * dim + d] = hi;
            }
        }
    }
    q
}

fn sampled(a: &dyn Fn(f64) -> Vec<f64>, b: &dyn Fn(f64) -> Vec<f64>) -> f64 {
    (0..=2000)
        .map(|k| {
            let u = k as f64 / 2000.0;
            let (x, y) = (a(u), b(u));
            x.iter()
                .zip(&y)
                .map(|(s, t)| (s - t) * (s - t))
                .sum::<f64>()
                .sqrt()
        })
        .fold(0.0, f64::max)
}

#[test]
fn reduce_random_curves_by_both_methods() {
    let mut seed = 1;
    for n in 2..=14 {
        for l in 0..=wsgb_max_l(n) {
            for dim in [2, 3] {
                seed += 1;
                let p = pseudo(n, dim, seed);
                let orig = WsgbCurve::new(p.clone(), dim, l).unwrap();
                let rows: Vec<Value> = p.chunks(dim).map(|c| json!(c)).collect();
                let input = json!({"type": "wsgb", "L": l, "points": rows}).to_string();
                let scale = p.iter().fold(1.0f64, |a, v| a.max(v.abs()));
                let lp = l.min(wsgb_max_l(n - 1));
                // Perturbation: equal to the spec's formulas.
                let out = json_out(&cagd(
                    &[
                        "reduce",
                        "--to",
                        &(n - 1).to_string(),
                        "--method",
                        "perturbation",
                    ],
                    &input,
                ));
                assert_eq!(out["type"], "wsgb");
                assert_eq!(out["L"], lp);
                let q = flat(&out["points"]);
                for (g, w) in q.iter().zip(spec_perturbation(&p, dim, l)) {
                    assert!((g - w).abs() <= 1e-9 * scale, "n {n} L {l}: {g} vs {w}");
                }
                // Uniform: the same polynomial as Chebyshev economisation of the Bézier form.
                let out_u = json_out(&cagd(
                    &[
                        "reduce",
                        "--to",
                        &(n - 1).to_string(),
                        "--method",
                        "uniform",
                    ],
                    &input,
                ));
                let qu = WsgbCurve::new(flat(&out_u["points"]), dim, lp).unwrap();
                let eck = reduce_bezier(&orig.to_bezier().unwrap(), n - 1, Method::Eck).unwrap();
                let d = sampled(&|u| qu.eval(u), &|u| eck.curve.eval(u));
                assert!(d <= 1e-9 * scale, "n {n} L {l}: uniform vs Eck {d}");
                for out in [&out, &out_u] {
                    let qc = WsgbCurve::new(flat(&out["points"]), dim, lp).unwrap();
                    let s = sampled(&|u| orig.eval(u), &|u| qc.eval(u));
                    let r = &out["report"];
                    let (bound, measured) = (
                        r["error_bound"].as_f64().unwrap(),
                        r["max_error"].as_f64().unwrap(),
                    );
                    assert!(s <= bound, "n {n} L {l}: sampled {s} > bound {bound}");
                    assert!(
                        measured >= s * (1.0 - 1e-9) && measured <= s * 1.01 + 1e-12,
                        "n {n} L {l}: measured {measured}, sampled {s}"
                    );
                    assert_eq!(r["space"], "euclidean");
                }
            }
        }
    }
}

#[test]
fn l2_on_a_wsgb_curve_is_the_l2_best_curve() {
    let p = pseudo(9, 2, 99);
    let orig = WsgbCurve::new(p.clone(), 2, 2).unwrap();
    let rows: Vec<Value> = p.chunks(2).map(|c| json!(c)).collect();
    let input = json!({"type": "wsgb", "L": 2, "points": rows}).to_string();
    let out = json_out(&cagd(
        &[
            "reduce", "--to", "5", "--method", "l2", "--r", "-1", "--p", "-1",
        ],
        &input,
    ));
    assert_eq!(out["L"], 1);
    let q = WsgbCurve::new(flat(&out["points"]), 2, 1).unwrap();
    // Residual orthogonal to every degree-5 polynomial (Gauss–Legendre, exact here).
    let (x, w) = cagd_core::gauss_legendre(20).unwrap();
    for j in 0..=5 {
        for d in 0..2 {
            let s: f64 = x
                .iter()
                .zip(&w)
                .map(|(u, wt)| {
                    wt * (orig.eval(*u)[d] - q.eval(*u)[d]) * cagd_core::kernel::bernstein(5, j, *u)
                })
                .sum();
            assert!(s.abs() < 1e-10, "j {j}: {s}");
        }
    }
    // And the same curve as the Bézier generalized inverse.
    let pinv = reduce_bezier(&orig.to_bezier().unwrap(), 5, Method::GeneralizedInverse).unwrap();
    let b: BezierCurve = pinv.curve;
    assert!(sampled(&|u| q.eval(u), &|u| b.eval(u)) < 1e-9);
}

#[test]
fn to_tolerance_gives_pieces() {
    let p = pseudo(10, 2, 5);
    let rows: Vec<Value> = p.chunks(2).map(|c| json!(c)).collect();
    let input = json!({"type": "wsgb", "L": 2, "points": rows}).to_string();
    let out = json_out(&cagd(
        &[
            "reduce",
            "--to",
            "4",
            "--method",
            "perturbation",
            "--tol",
            "0.01",
        ],
        &input,
    ));
    assert_eq!(out["type"], "wsgb-pieces");
    let r = &out["report"];
    assert!(r["error_bound"].as_f64().unwrap() <= 0.01);
    assert!(r["max_error"].as_f64().unwrap() <= r["error_bound"].as_f64().unwrap());
    assert_eq!(r["pieces"], out["pieces"].as_array().unwrap().len());
}

#[test]
fn bad_wsgb_input_is_one_line_errors() {
    let cases: &[(&str, &[&str], &str)] = &[
        (
            r#"{"type":"wsgb","L":3,"points":[[0],[1],[2],[3],[4],[5],[6]]}"#,
            &["--to", "5"],
            "input.L",
        ),
        (
            r#"{"type":"wsgb","points":[[0],[1],[2]]}"#,
            &["--to", "1"],
            "input.L",
        ),
        (
            r#"{"type":"wsgb","L":0,"points":[[0],[1]]}"#,
            &["--to", "0", "--method", "perturbation"],
            "degree pair",
        ),
        (
            r#"{"type":"wsgb","L":0,"points":[[0],[1],[2]]}"#,
            &["--to", "2", "--method", "uniform"],
            "degree pair",
        ),
        (
            r#"{"type":"wsgb","L":0,"points":[[0],[1],[2]],"weights":[1,1,1]}"#,
            &["--to", "1"],
            "input.weights",
        ),
        (
            r#"{"type":"wsgb","L":0,"points":[[0],[1],[2]]}"#,
            &["--to", "1", "--method", "nope"],
            "--method",
        ),
        (
            r#"{"type":"wsgb","L":0,"points":[[0],[1],[2]]}"#,
            &["--to", "1", "--method", "uniform", "--r", "1"],
            "--method",
        ),
    ];
    for (input, extra, needle) in cases {
        let mut args = vec!["reduce"];
        args.extend_from_slice(extra);
        let out = cagd(&args, input);
        assert_eq!(out.status.code(), Some(2), "{input}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(needle), "{input}: {err}");
    }
    // "uniform" is a WSGB method only.
    let out = cagd(
        &["reduce", "--to", "1", "--method", "uniform"],
        r#"{"type":"bezier","points":[[0],[1],[0]]}"#,
    );
    assert_eq!(out.status.code(), Some(2));
}
