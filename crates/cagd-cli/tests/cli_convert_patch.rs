//! `cagd convert` on patches and `cagd check` on the vectors of SPEC-convert §15.4–15.7.
//!
//! The pieces are checked here with an evaluator of this file (Bernstein sums, not the
//! library's de Casteljau): every piece composed with its declared domain map equals the
//! input within 1e-12 relative, and the declared domains tile the input domain.

mod common;

use cagd_testkit::serde_json::{self, Value, json};
use common::{cagd, json_out};

const ALGOS: [&str; 9] = [
    "triangle_to_degenerate_rect",
    "degenerate_rect_to_triangle",
    "triangle_to_rect_D1",
    "triangle_to_three_rects",
    "gsub_trapezoid",
    "gsub_corner_triangle",
    "rect_to_two_triangles",
    "gsub_curve",
    "gsub_curve_D7",
];

/// The public vectors of this family.
fn family_vectors() -> Vec<Value> {
    cagd_testkit::load_vectors("vectors-convert.json")
        .into_iter()
        .filter(|v| ALGOS.contains(&v["algorithm"].as_str().unwrap_or("")))
        .collect()
}

/// Writes vectors to a temporary file and runs `cagd check` on it.
fn check(vectors: &[Value], name: &str) -> std::process::Output {
    let path = std::env::temp_dir().join(format!("cagd-conv2-{}-{name}.json", std::process::id()));
    std::fs::write(&path, serde_json::to_string(vectors).unwrap()).unwrap();
    let out = cagd(&["check", path.to_str().unwrap()], "");
    let _ = std::fs::remove_file(&path);
    out
}

#[test]
fn public_vectors_pass_through_check() {
    let vectors = family_vectors();
    let algos: std::collections::BTreeSet<_> = vectors
        .iter()
        .map(|v| v["algorithm"].as_str().unwrap())
        .collect();
    assert_eq!(
        algos.len(),
        ALGOS.len(),
        "every algorithm has a public vector"
    );
    let out = check(&vectors, "pass");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}");
    assert!(
        text.contains(&format!("{} passed, 0 failed", vectors.len())),
        "{text}"
    );
}

#[test]
fn altered_expected_fails_check() {
    for v in family_vectors() {
        let mut bad = v.clone();
        // Nudge the first number of the first list of `expected` by 1e-6 (far above 1e-12).
        let key = ["rect_points", "triangle_points", "rects", "lower_triangle"]
            .into_iter()
            .find(|k| bad["expected"].get(*k).is_some())
            .unwrap();
        let mut x = &mut bad["expected"][key];
        while x.is_array() {
            x = &mut x[0];
        }
        *x = json!(x.as_f64().unwrap() + 1e-6);
        let out = check(&[bad], "fail");
        assert_eq!(
            out.status.code(),
            Some(1),
            "{}: {}",
            v["id"],
            String::from_utf8_lossy(&out.stdout)
        );
    }
    // An expected error that the library does not raise fails too.
    let mut v = family_vectors()
        .into_iter()
        .find(|v| v["algorithm"] == "gsub_trapezoid")
        .unwrap();
    v["expected"] = json!({"error": "should refuse"});
    assert_eq!(check(&[v], "err").status.code(), Some(1));
}

#[test]
fn not_degenerate_is_refused_as_an_error_vector_expects() {
    let mut v = family_vectors()
        .into_iter()
        .find(|v| v["algorithm"] == "degenerate_rect_to_triangle")
        .unwrap();
    v["input"]["rect_points"][7][1] = json!(0.25); // row 2 must be constant: it is not now
    v["expected"] = json!({"error": "NotDegenerate"});
    let out = check(&[v], "notdeg");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
}

/// A tiny deterministic generator (xorshift).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
    fn int(&mut self, n: usize) -> usize {
        self.next();
        usize::try_from(self.0 % (n as u64 + 1)).unwrap_or(0)
    }
}

/// `x^e` by repeated products.
trait Pw {
    fn pw(self, e: usize) -> f64;
}
impl Pw for f64 {
    fn pw(self, e: usize) -> f64 {
        (0..e).fold(1.0, |a, _| a * self)
    }
}

/// A degree field.
fn udeg(v: &Value) -> usize {
    v.as_u64()
        .and_then(|x| usize::try_from(x).ok())
        .expect("a degree")
}

fn binom(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

fn pts(v: &Value) -> Vec<Vec<f64>> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|p| {
            p.as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect()
        })
        .collect()
}

/// Evaluates a `tensor` / `triangle` JSON object at `(u, v)` by explicit Bernstein sums.
fn eval(shape: &Value, u: f64, v: f64) -> Vec<f64> {
    let p = pts(&shape["points"]);
    let w: Vec<f64> = match shape.get("weights") {
        Some(w) => w
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect(),
        None => vec![1.0; p.len()],
    };
    let dim = p[0].len();
    let mut num = vec![0.0; dim];
    let mut den = 0.0;
    let mut add = |b: f64, idx: usize| {
        for k in 0..dim {
            num[k] += b * w[idx] * p[idx][k];
        }
        den += b * w[idx];
    };
    if shape["type"] == "tensor" {
        let (m, n) = (udeg(&shape["degree"][0]), udeg(&shape["degree"][1]));
        for i in 0..=m {
            for j in 0..=n {
                let b = binom(m, i)
                    * u.pw(i)
                    * (1.0 - u).pw(m - i)
                    * binom(n, j)
                    * v.pw(j)
                    * (1.0 - v).pw(n - j);
                add(b, i * (n + 1) + j);
            }
        }
    } else {
        let n = udeg(&shape["degree"]);
        let wv = 1.0 - u - v;
        let mut idx = 0;
        for i in 0..=n {
            for j in 0..=n - i {
                let k = n - i - j;
                let b = binom(n, i) * binom(n - i, j) * u.pw(i) * v.pw(j) * wv.pw(k);
                add(b, idx);
                idx += 1;
            }
        }
    }
    num.iter().map(|x| x / den).collect()
}

/// The declared domain map of a piece.
fn map(domain: &Value, s: f64, t: f64) -> [f64; 2] {
    if let Some(x) = domain.get("bilinear") {
        let x = pts(x);
        let w = [(1.0 - s) * (1.0 - t), s * (1.0 - t), (1.0 - s) * t, s * t];
        let mut out = [0.0; 2];
        for (c, wi) in x.iter().zip(w) {
            out[0] += wi * c[0];
            out[1] += wi * c[1];
        }
        out
    } else {
        let x = pts(&domain["triangle"]);
        let (a, b, c) = (&x[0], &x[1], &x[2]);
        [
            c[0] + s * (a[0] - c[0]) + t * (b[0] - c[0]),
            c[1] + s * (a[1] - c[1]) + t * (b[1] - c[1]),
        ]
    }
}

/// Whether `(u, v)` is inside the piece's domain by margin `slack` (bisection-free: a grid
/// search refined by Newton with a numerical Jacobian).
fn inside(domain: &Value, u: f64, v: f64, slack: f64) -> bool {
    let tri = domain.get("triangle").is_some();
    for start in [(0.5, 0.5), (0.2, 0.2), (0.8, 0.2), (0.2, 0.8), (0.8, 0.8)] {
        let (mut s, mut t) = if tri {
            (start.0 / 2.0, start.1 / 2.0)
        } else {
            start
        };
        for _ in 0..50 {
            let p = map(domain, s, t);
            let h = 1e-7;
            let (ps, pt) = (map(domain, s + h, t), map(domain, s, t + h));
            let j = [
                [(ps[0] - p[0]) / h, (pt[0] - p[0]) / h],
                [(ps[1] - p[1]) / h, (pt[1] - p[1]) / h],
            ];
            let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
            if det.abs() < 1e-300 {
                break;
            }
            let (ru, rv) = (p[0] - u, p[1] - v);
            s -= (ru * j[1][1] - rv * j[0][1]) / det;
            t -= (j[0][0] * rv - j[1][0] * ru) / det;
        }
        let p = map(domain, s, t);
        if (p[0] - u).abs() + (p[1] - v).abs() > 1e-10 {
            continue;
        }
        let ok = if tri {
            s >= slack && t >= slack && s + t <= 1.0 - slack
        } else {
            s >= slack && t >= slack && s <= 1.0 - slack && t <= 1.0 - slack
        };
        if ok {
            return true;
        }
    }
    false
}

/// Checks exactness and tiling of the pieces of `input`.
fn assert_pieces(input: &Value, pieces: &[Value], triangle_domain: bool) {
    let scale = pts(&input["points"])
        .iter()
        .flatten()
        .fold(1.0_f64, |a, x| a.max(x.abs()));
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for (k, piece) in pieces.iter().enumerate() {
        let tri = piece["domain"].get("triangle").is_some();
        for _ in 0..60 {
            let (mut s, mut t) = (rng.next(), rng.next());
            if tri && s + t > 1.0 {
                (s, t) = (1.0 - s, 1.0 - t);
            }
            let [u, v] = map(&piece["domain"], s, t);
            let (a, b) = (eval(input, u, v), eval(piece, s, t));
            for (x, y) in a.iter().zip(&b) {
                assert!(
                    (x - y).abs() <= 1e-12 * scale,
                    "piece {k} at ({s}, {t}): {x} vs {y}"
                );
            }
        }
    }
    for _ in 0..150 {
        let hi = if triangle_domain { 0.97 } else { 0.99 };
        let (mut u, mut v) = (rng.range(0.01, hi), rng.range(0.01, hi));
        if triangle_domain && u + v > 0.98 {
            (u, v) = (0.98 - u, 0.98 - v);
        }
        let loose = pieces
            .iter()
            .filter(|p| inside(&p["domain"], u, v, -1e-7))
            .count();
        let strict = pieces
            .iter()
            .filter(|p| inside(&p["domain"], u, v, 1e-7))
            .count();
        assert!(
            loose >= 1 && strict <= 1,
            "({u}, {v}): in {loose} / {strict} pieces"
        );
    }
}

fn random_points(rng: &mut Rng, count: usize, dim: usize) -> Vec<Vec<f64>> {
    (0..count)
        .map(|_| (0..dim).map(|_| rng.range(-10.0, 10.0)).collect())
        .collect()
}

/// A random shape (rational every other time).
fn random_shape(rng: &mut Rng, triangle: bool, rational: bool) -> Value {
    let dim = 1 + rng.int(3);
    let mut v = if triangle {
        let n = rng.int(10);
        json!({"type": "triangle", "degree": n, "points": random_points(rng, (n + 1) * (n + 2) / 2, dim)})
    } else {
        let (m, n) = (rng.int(6), rng.int(6));
        json!({"type": "tensor", "degree": [m, n], "points": random_points(rng, (m + 1) * (n + 1), dim)})
    };
    if rational {
        let count = v["points"].as_array().unwrap().len();
        v["weights"] = json!((0..count).map(|_| rng.range(0.2, 5.0)).collect::<Vec<_>>());
    }
    v
}

fn as_list(v: Value) -> Vec<Value> {
    match v {
        Value::Array(a) => a,
        one => vec![one],
    }
}

#[test]
fn random_patches_through_convert_are_exact_and_tile() {
    let mut rng = Rng(12345);
    for case in 0..6 {
        let rational = case % 2 == 1;
        let tri = random_shape(&mut rng, true, rational);
        let text = tri.to_string();
        for args in [vec!["--to", "rectangle"], vec!["--to", "rectangles3"]] {
            let out = as_list(json_out(&cagd(&[&["convert"], &args[..]].concat(), &text)));
            assert_pieces(&tri, &out, true);
        }
        // Random split points; a folded draw is refused (DegenerateSplit) and drawn again.
        let mut done = false;
        for _ in 0..50 {
            let p = format!("{},{}", rng.range(0.2, 0.45), rng.range(0.2, 0.45));
            let edges = format!(
                "{},{},{}",
                rng.range(0.3, 0.7),
                rng.range(0.3, 0.7),
                rng.range(0.3, 0.7)
            );
            let o = cagd(
                &[
                    "convert",
                    "--to",
                    "rectangles3",
                    "--inner",
                    &p,
                    "--edges",
                    &edges,
                ],
                &text,
            );
            if !o.status.success() {
                assert!(
                    String::from_utf8_lossy(&o.stderr).contains("folded"),
                    "{}",
                    String::from_utf8_lossy(&o.stderr)
                );
                continue;
            }
            let out = as_list(json_out(&o));
            assert_eq!(out.len(), 3);
            assert_pieces(&tri, &out, true);
            done = true;
            break;
        }
        assert!(done, "no admissible split drawn");

        let rect = random_shape(&mut rng, false, rational);
        let text = rect.to_string();
        let out = as_list(json_out(&cagd(&["convert", "--to", "triangles"], &text)));
        assert_pieces(&rect, &out, false);
        for line in [
            (rng.range(-0.5, 0.5), rng.range(0.2, 0.5)),
            (-1.5, rng.range(0.3, 0.9)),
            (3.0, -1.2),
        ] {
            let arg = format!("{},{}", line.0, line.1);
            let out = as_list(json_out(&cagd(&["convert", "--split-line", &arg], &text)));
            assert!(out.len() >= 2);
            for p in &out {
                assert!(p["report"]["max_difference"].as_f64().unwrap() <= 1e-12 * 10.0);
            }
            assert_pieces(&rect, &out, false);
        }
    }
}

#[test]
fn curve_and_trim_pieces_carry_ruled_domains() {
    let rect = json!({"type": "tensor", "degree": [2, 1], "points": [[0, 0, 0], [0, 1, 0], [1, 0, 1], [1, 1, 2], [2, 0, 2], [2, 1, 4]]});
    let out = as_list(json_out(&cagd(
        &["convert", "--split-curve", "0.5,1,0.25"],
        &rect.to_string(),
    )));
    assert_eq!(out.len(), 2);
    assert_eq!(
        out[0]["domain"]["ruled"]["s1"],
        json!([[0.5, 0.0], [1.0, 0.5], [0.25, 1.0]])
    );
    let trim = std::env::temp_dir().join(format!("cagd-conv2-trim-{}.json", std::process::id()));
    let chain = json!({"direction": "v_of_u", "keep": "below", "segments": [{"interval": [0, 1], "bezier": [0.2, 0.9, 0.4]}]});
    std::fs::write(&trim, chain.to_string()).unwrap();
    let out = as_list(json_out(&cagd(
        &["convert", "--trim", trim.to_str().unwrap()],
        &rect.to_string(),
    )));
    assert_eq!(out.len(), 1);
    assert_eq!(
        out[0]["domain"]["ruled"]["s1"],
        json!([[0.0, 0.2], [0.5, 0.9], [1.0, 0.4]])
    );
    // Evaluate through the ruled map: u = t, v = s g(t).
    let g = |t: f64| 0.2 * (1.0 - t) * (1.0 - t) + 2.0 * 0.9 * t * (1.0 - t) + 0.4 * t * t;
    for (s, t) in [(0.3, 0.6), (1.0, 0.2), (0.5, 0.5)] {
        let (a, b) = (eval(&rect, t, s * g(t)), eval(&out[0], s, t));
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).abs() < 1e-12, "{x} vs {y}");
        }
    }
    std::fs::write(&trim, r#"{"direction":"u_of_v","keep":"below","segments":[{"interval":[0,0.5],"bezier":[0.5,0.5]}]}"#).unwrap();
    let out = cagd(
        &["convert", "--trim", trim.to_str().unwrap()],
        &rect.to_string(),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("unsupported trimming layout"));
    let _ = std::fs::remove_file(&trim);
}

#[test]
fn bad_input_is_a_named_error() {
    let tri = r#"{"type":"triangle","degree":1,"points":[[0,0],[1,0],[0,1]]}"#;
    let rect = r#"{"type":"tensor","degree":[1,1],"points":[[0],[1],[2],[3]]}"#;
    let cases: &[(&[&str], &str, &str)] = &[
        (
            &["convert", "--to", "rectangle"],
            r#"{"type":"triangle","degree":1,"points":[[0,0],[1,0]]}"#,
            "input.points",
        ),
        (
            &["convert", "--to", "triangles"],
            r#"{"type":"tensor","degree":[1,1],"points":[[0],[1],[2],[3]],"weights":[1,1,-1,1]}"#,
            "input.weights[2]",
        ),
        (
            &["convert", "--to", "rectangles3", "--inner", "0.6,0.6"],
            tri,
            "P",
        ),
        (
            &["convert", "--to", "rectangles3", "--inner", "0.1,0.1"],
            tri,
            "folded",
        ),
        (
            &["convert", "--to", "rectangles3", "--edges", "0.5,1.5,0.5"],
            tri,
            "K",
        ),
        (
            &["convert", "--to", "rectangles3", "--edges", "0.5,0.5"],
            tri,
            "--edges",
        ),
        (&["convert", "--split-line", "0,2"], rect, "f0"),
        (&["convert", "--split-curve", "0.5,1.5"], rect, "[0, 1]"),
        (&["convert", "--split-line", "0,nan"], rect, "--split-line"),
        (&["convert", "--to", "triangle"], rect, "not a degenerate"),
        (&["convert", "--to", "triangles"], tri, "tensor"),
        (&["convert", "--to", "pentagon"], tri, "--to"),
        (&["convert"], tri, "give one of"),
    ];
    for (args, input, needle) in cases {
        let out = cagd(args, input);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}
