//! `cagd reduce` and `cagd check` on interval triangles (seed 004, SPEC-convert part I):
//! the public vectors pass and altered ones fail, the printed result contains the input in
//! exact rational arithmetic on the printed doubles, bad input is refused with a named field.

mod common;

use cagd_testkit::serde_json::{self, Value, json};
use common::{cagd, json_out};
use num_bigint::BigInt;
use num_rational::BigRational;

/// The public vectors of this family, written to a temporary file (with `edit` applied).
fn vector_file(name: &str, edit: impl Fn(&mut Vec<Value>)) -> std::path::PathBuf {
    let mut vs: Vec<Value> = cagd_testkit::load_vectors("vectors-convert.json")
        .into_iter()
        .filter(|v| {
            let a = v["algorithm"].as_str().unwrap_or("");
            a == "interval_triangle_degree_reduction_lp" || a == "triangle_elevation_matrix"
        })
        .collect();
    edit(&mut vs);
    let path =
        std::env::temp_dir().join(format!("cagd-interval-{}-{name}.json", std::process::id()));
    std::fs::write(&path, serde_json::to_string(&vs).unwrap()).unwrap();
    path
}

fn check(path: &std::path::Path) -> (bool, String) {
    let o = cagd(&["check", path.to_str().unwrap()], "");
    (
        o.status.success(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
    )
}

#[test]
fn public_vectors_pass_through_check() {
    let path = vector_file("public", |_| {});
    let (ok, out) = check(&path);
    assert!(ok, "{out}");
    assert!(out.contains("3 passed, 0 failed"), "{out}");
}

#[test]
fn altered_vectors_fail() {
    // A wrong thickness fails (whatever the uniqueness rule).
    let path = vector_file("thickness", |vs| {
        vs[0]["expected"]["thickness_out"] = json!(3.5);
    });
    let (ok, out) = check(&path);
    assert!(!ok && out.contains("FAIL interval-ex1-4to3"), "{out}");
    // A wrong box of a vector marked unique fails.
    let path = vector_file("unique-box", |vs| {
        vs[1]["expected"]["boxes"][1][0][1] = json!(11.6);
    });
    let (ok, out) = check(&path);
    assert!(!ok && out.contains("FAIL interval-3to2-2d-unique"), "{out}");
    // A wrong elevation entry fails.
    let path = vector_file("elevation", |vs| {
        vs[2]["expected"]["E"][1][0] = json!(0.34);
    });
    let (ok, out) = check(&path);
    assert!(!ok && out.contains("FAIL interval-elevation-2to3"), "{out}");
}

/// A vector (SPEC-convert §0 form) for `p` reduced to `m` with the given expected boxes.
fn reduction_vector(
    p: &cagd_reduce::IntervalTriPatch,
    m: usize,
    lo: &[f64],
    hi: &[f64],
    t: f64,
) -> Value {
    let d = p.dim();
    let boxes = |l: &[f64], h: &[f64]| -> Vec<Value> {
        l.chunks(d)
            .zip(h.chunks(d))
            .map(|(a, b)| Value::Array(a.iter().zip(b).map(|(x, y)| json!([x, y])).collect()))
            .collect()
    };
    json!({
        "id": "nonunique-synthetic",
        "algorithm": "interval_triangle_degree_reduction_lp",
        "params": {"n": p.degree(), "m": m, "unique": false},
        "input": {"boxes": boxes(p.lo(), p.hi())},
        "expected": {"boxes": boxes(lo, hi), "thickness_out": t},
        "tol": 1e-9
    })
}

#[test]
fn non_unique_rule_accepts_another_optimal_vertex_only() {
    // Find a random 1-D 3 -> 2 case whose optimum is not unique: the vertex enumeration
    // (seed 004 §3) and the simplex return different optimal vertices, both proper.
    use cagd_reduce::{IntervalOptions, IntervalTriPatch, reduce_interval_triangle};
    let mut rng = Rng(0xabcd_ef01);
    let mut found = None;
    for _ in 0..400 {
        let lo: Vec<f64> = (0..10).map(|_| (rng.next() * 8.0).round()).collect();
        let hi: Vec<f64> = lo.iter().map(|l| l + (rng.next() * 3.0).round()).collect();
        let p = IntervalTriPatch::new(lo, hi, 3, 1).unwrap();
        let r = reduce_interval_triangle(&p, &IntervalOptions::new(2)).unwrap();
        let a = cagd_reduce::reduce_interval_triangle_analytic(&p, 2, None).unwrap();
        let differs =
            a.lo.iter()
                .chain(&a.hi)
                .zip(r.patch.lo().iter().chain(r.patch.hi()))
                .any(|(x, y)| (x - y).abs() > 1e-6);
        if a.proper && !r.report.coupled[0] && differs {
            found = Some((p, a));
            break;
        }
    }
    let (p, a) = found.expect("a non-unique 3 -> 2 case among 400 random ones");
    let path = vector_file("nonunique", |vs| {
        *vs = vec![reduction_vector(&p, 2, &a.lo, &a.hi, a.thickness)]
    });
    let (ok, out) = check(&path);
    assert!(ok, "another optimal vertex is accepted:\n{out}");
    // The same vector with one expected bound moved (thickness no longer matches) fails.
    let mut lo = a.lo.clone();
    lo[3] -= 0.5;
    let path = vector_file("nonunique-moved", |vs| {
        *vs = vec![reduction_vector(&p, 2, &lo, &a.hi, a.thickness)]
    });
    let (ok, out) = check(&path);
    assert!(!ok, "{out}");
    // Moved so that the thickness still matches but the input is no longer contained.
    let mut hi = a.hi.clone();
    let q = (0..hi.len()).find(|&q| lo[q] + 0.5 <= hi[q]).unwrap_or(0);
    lo[3] += 0.5;
    lo[q] += 0.25;
    hi[q] -= 0.0;
    let t = (hi.iter().sum::<f64>() - lo.iter().sum::<f64>()) / 6.0;
    let path = vector_file("nonunique-raised", |vs| {
        *vs = vec![reduction_vector(&p, 2, &lo, &hi, t)]
    });
    let (ok, out) = check(&path);
    assert!(!ok, "{out}");
}

#[test]
fn error_vectors_pass_only_when_refused() {
    let path = vector_file("errors", |vs| {
        let mut empty = vs[1].clone();
        empty["id"] = json!("empty-box");
        empty["input"]["boxes"][3][0] = json!([2.0, 1.0]);
        empty["expected"] = json!({"error": "lo > hi"});
        let mut up = vs[1].clone();
        up["id"] = json!("m-not-below-n");
        up["params"]["m"] = json!(3);
        up["expected"] = json!({"error": "m >= n"});
        let mut elev = vs[2].clone();
        elev["id"] = json!("elevation-down");
        elev["params"] = json!({"m": 3, "n": 2});
        elev["expected"] = json!({"error": "m > n"});
        *vs = vec![empty, up, elev];
    });
    let (ok, out) = check(&path);
    assert!(ok && out.contains("3 passed, 0 failed"), "{out}");
}

/// A small deterministic pseudo-random generator (xorshift), values in [0, 1).
struct Rng(u64);
impl Rng {
    fn bits(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn next(&mut self) -> f64 {
        (self.bits() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in `0..k`.
    fn below(&mut self, k: usize) -> usize {
        usize::try_from(self.bits() % k as u64).unwrap()
    }
}

fn exact(x: f64) -> BigRational {
    BigRational::from_float(x).unwrap()
}

/// Exact rational `E_{m->n}` entry `C(m;b) C(n-m;a-b) / C(n;a)` (independent of the library).
fn elevation_entry(m: usize, n: usize, a: (usize, usize), b: (usize, usize)) -> BigRational {
    let fact = |k: usize| (1..=k).fold(BigInt::from(1), |acc, i| acc * i);
    let tri = |n: usize, i: usize, j: usize| fact(n) / (fact(i) * fact(j) * fact(n - i - j));
    let (ak, bk) = (n - a.0 - a.1, m - b.0 - b.1);
    if b.0 > a.0 || b.1 > a.1 || bk > ak {
        return BigRational::from_integer(0.into());
    }
    BigRational::new(
        tri(m, b.0, b.1) * tri(n - m, a.0 - b.0, a.1 - b.1),
        tri(n, a.0, a.1),
    )
}

fn indices(n: usize) -> Vec<(usize, usize)> {
    (0..=n)
        .flat_map(|i| (0..=n - i).map(move |j| (i, j)))
        .collect()
}

#[test]
fn random_reductions_contain_their_input_exactly_on_the_printed_doubles() {
    let mut rng = Rng(0x5eed_1234);
    for case in 0..40 {
        let n = 1 + rng.below(7); // 1..=7
        let dim = 1 + rng.below(3); // 1..=3
        let m = rng.below(n); // 0..n
        let count = (n + 1) * (n + 2) / 2;
        let mut lo = Vec::new();
        let mut hi = Vec::new();
        for _ in 0..count {
            let (mut l, mut h) = (Vec::new(), Vec::new());
            for _ in 0..dim {
                let x = 200.0 * rng.next() - 100.0;
                l.push(x);
                h.push(x + 3.0 * rng.next());
            }
            lo.push(l);
            hi.push(h);
        }
        let input = json!({"type": "interval-triangle", "degree": n, "lo": lo, "hi": hi});
        let out = json_out(&cagd(
            &["reduce", "--to", &m.to_string()],
            &input.to_string(),
        ));
        assert_eq!(out["type"], "interval-triangle");
        assert_eq!(out["degree"], m);
        let rep = &out["report"];
        assert!(rep["max_violation"].as_f64().unwrap() <= 0.0, "case {case}");
        let get = |v: &Value, q: usize, c: usize| v[q][c].as_f64().unwrap();
        // Exact containment: E L <= f_lo and E U >= f_hi, in rationals, on the printed
        // doubles; no empty box.
        let (ai, bi) = (indices(n), indices(m));
        for c in 0..dim {
            for q in 0..bi.len() {
                assert!(
                    get(&out["lo"], q, c) <= get(&out["hi"], q, c),
                    "case {case}: empty box {q}"
                );
            }
            for (r, &a) in ai.iter().enumerate() {
                let mut el = BigRational::from_integer(0.into());
                let mut eu = el.clone();
                for (q, &b) in bi.iter().enumerate() {
                    let e = elevation_entry(m, n, a, b);
                    el += &e * exact(get(&out["lo"], q, c));
                    eu += &e * exact(get(&out["hi"], q, c));
                }
                assert!(
                    el <= exact(lo[r][c]),
                    "case {case} (n {n}, m {m}, dim {dim}): lower row {r} coordinate {c}: {el} vs {}\n{input}\n{out}",
                    lo[r][c]
                );
                assert!(
                    eu >= exact(hi[r][c]),
                    "case {case}: upper row {r} coordinate {c}"
                );
            }
        }
        let t_in = rep["thickness_in"].as_f64().unwrap();
        let t_out = rep["thickness_out"].as_f64().unwrap();
        assert!(
            t_out >= t_in * (1.0 - 1e-12),
            "a wrap is never thinner than its content"
        );
        let objective = rep["objective"].as_f64().unwrap();
        let t_opt = objective / (dim * (m + 1) * (m + 2) / 2) as f64;
        assert!(
            (t_out - t_opt).abs() <= 1e-9 * t_opt.max(1.0),
            "case {case}: repair moved the optimum"
        );
    }
}

#[test]
fn containment_degree_and_svg() {
    let svg = std::env::temp_dir().join(format!("cagd-interval-{}.svg", std::process::id()));
    let input = json!({"type": "interval-triangle", "degree": 3,
        "lo": [[0.0], [1.0], [0.5], [2.0], [1.0], [0.0], [3.0], [1.5], [0.5], [1.0]],
        "hi": [[1.0], [1.5], [1.5], [2.5], [1.2], [1.0], [3.5], [2.0], [1.0], [2.0]]});
    let base = json_out(&cagd(&["reduce", "--to", "2"], &input.to_string()));
    let o = cagd(
        &[
            "reduce",
            "--to",
            "2",
            "--containment-degree",
            "8",
            "--svg",
            svg.to_str().unwrap(),
        ],
        &input.to_string(),
    );
    let tight = json_out(&o);
    assert_eq!(tight["report"]["containment_degree"], 8);
    let (a, b) = (
        base["report"]["thickness_out"].as_f64().unwrap(),
        tight["report"]["thickness_out"].as_f64().unwrap(),
    );
    assert!(
        b <= a + 1e-12,
        "the tighter model is not thicker: {b} vs {a}"
    );
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg") && text.contains("thickness") && text.contains("polyline"));
}

#[test]
fn bad_input_names_the_field() {
    let cases = [
        (
            json!({"type": "interval-triangle", "degree": 1, "lo": [[0.0], [1.0], [2.0]], "hi": [[1.0], [0.5], [3.0]]}),
            vec!["--to", "0"],
            "input.lo[1][0]",
        ),
        (
            json!({"type": "interval-triangle", "degree": 2, "lo": [[0.0], [1.0], [2.0]], "hi": [[1.0], [1.5], [3.0]]}),
            vec!["--to", "1"],
            "input.lo: has 3 points, expected (n + 1)(n + 2) / 2 = 6",
        ),
        (
            json!({"type": "interval-triangle", "degree": 1, "lo": [[0.0], [1.0], [2.0]], "hi": [[1.0], [1.5], [3.0]]}),
            vec!["--to", "1"],
            "degree pair 1 -> 1",
        ),
        (
            json!({"type": "interval-triangle", "degree": 1, "lo": [[0.0], [1.0], [2.0]], "hi": [[1.0], [1.5], [3.0]]}),
            vec!["--to", "0", "--containment-degree", "0"],
            "containment degree",
        ),
        (
            json!({"type": "interval-triangle", "degree": 1, "lo": [[0.0], [1.0], [2.0]], "hi": [[1.0], [1.5], [3.0]]}),
            vec!["--to", "0", "--method", "l2"],
            "--method",
        ),
    ];
    for (input, args, want) in cases {
        let mut full = vec!["reduce"];
        full.extend(args);
        let o = cagd(&full, &input.to_string());
        assert_eq!(o.status.code(), Some(2), "{input}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(want), "{err} lacks {want}");
    }
    // Non-finite numbers cannot be written in JSON; a string where a bound belongs is refused.
    let o = cagd(
        &["reduce", "--to", "0"],
        r#"{"type":"interval-triangle","degree":1,"lo":[[0],[1],["NaN"]],"hi":[[1],[2],[3]]}"#,
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("input.lo[2][0]"));
}
