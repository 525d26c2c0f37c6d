//! Test helpers shared by the cagd crates (dev-only, not published):
//! loading the spec vectors of `../shared/spec`, exact fractions, the vector tolerance rule,
//! and proptest strategies for curves and knot vectors.
//!
//! The shared folder is found at `$CAGD_SHARED` or, by default, `<workspace>/../shared`.

use std::path::PathBuf;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;
use proptest::prelude::*;
use serde_json::Value;

pub use serde_json;

pub mod bench;

/// Path of a file in `shared/spec`.
pub fn spec_path(name: &str) -> PathBuf {
    let shared = std::env::var_os("CAGD_SHARED")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared"));
    shared.join("spec").join(name)
}

/// All vectors of a spec JSON file (`vectors-reduce.json`, `vectors-convert.json`).
pub fn load_vectors(file: &str) -> Vec<Value> {
    let path = spec_path(file);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("cannot read spec vectors {}: {e}", path.display()));
    let v: Value = serde_json::from_str(&text).expect("spec vectors are JSON");
    v.as_array().expect("spec vector file is an array").clone()
}

/// The vector with the given id; panics (a test failure) if it is missing.
pub fn vector(file: &str, id: &str) -> Value {
    load_vectors(file)
        .into_iter()
        .find(|v| v["id"] == id)
        .unwrap_or_else(|| panic!("vector {id} not in {file}"))
}

/// All vectors of a file whose `algorithm` starts with `prefix`.
pub fn vectors_with_algorithm(file: &str, prefix: &str) -> Vec<Value> {
    load_vectors(file)
        .into_iter()
        .filter(|v| {
            v["algorithm"]
                .as_str()
                .is_some_and(|a| a.starts_with(prefix))
        })
        .collect()
}

/// An exact fraction `"p/q"` or integer `"p"` (string or JSON number) as a rational.
pub fn rational(v: &Value) -> BigRational {
    match v {
        Value::String(s) => {
            let (p, q) = s.split_once('/').unwrap_or((s.as_str(), "1"));
            BigRational::new(
                p.trim().parse::<BigInt>().expect("numerator"),
                q.trim().parse::<BigInt>().expect("denominator"),
            )
        }
        Value::Number(n) => {
            if let Some(i) = n.as_i64() {
                BigRational::from_integer(i.into())
            } else {
                BigRational::from_float(n.as_f64().expect("number")).expect("finite")
            }
        }
        other => panic!("not a number: {other}"),
    }
}

/// A number or exact fraction as `f64` (fractions rounded once).
pub fn num(v: &Value) -> f64 {
    match v {
        Value::Number(n) => n.as_f64().expect("number"),
        Value::String(_) => rational(v).to_f64().expect("fraction fits f64"),
        other => panic!("not a number: {other}"),
    }
}

/// Flattens nested JSON arrays of numbers / fractions (any depth) into a row-major `Vec`.
pub fn flat(v: &Value) -> Vec<f64> {
    let mut out = Vec::new();
    fn go(v: &Value, out: &mut Vec<f64>) {
        match v {
            Value::Array(a) => a.iter().for_each(|x| go(x, out)),
            other => out.push(num(other)),
        }
    }
    go(v, &mut out);
    out
}

/// Length of the innermost arrays of a nested JSON array (the point dimension).
pub fn inner_dim(v: &Value) -> usize {
    let mut cur = v;
    loop {
        match cur {
            Value::Array(a) if a.first().is_some_and(Value::is_array) => cur = &a[0],
            Value::Array(a) => return a.len(),
            _ => return 1,
        }
    }
}

/// The spec's tolerance rule: `max|g - e| <= tol * max(1, max|e|)` (`tol = 0` means
/// exact up to the rounding of the exact value to f64, checked here as `<= 4 ulp` of the
/// scale). Panics with the worst index on failure.
pub fn assert_close(what: &str, got: &[f64], expected: &[f64], tol: f64) {
    assert_eq!(got.len(), expected.len(), "{what}: length");
    let scale = expected.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    let allowed = if tol == 0.0 {
        4.0 * f64::EPSILON * scale
    } else {
        tol * scale
    };
    let (mut worst, mut at) = (0.0f64, 0);
    for (i, (g, e)) in got.iter().zip(expected).enumerate() {
        let d = (g - e).abs();
        // NaN counts as the worst deviation.
        if d.is_nan() || d > worst {
            worst = d;
            at = i;
        }
    }
    assert!(
        worst.is_finite() && worst <= allowed,
        "{what}: max deviation {worst:e} at index {at} (got {}, expected {}) exceeds {allowed:e}",
        got[at],
        expected[at]
    );
}

/// Coordinates in `[-10, 10]`.
pub fn coord() -> impl Strategy<Value = f64> {
    -10.0f64..10.0
}

/// `n_points * dim` coordinates in `[-10, 10]`.
pub fn points(n_points: usize, dim: usize) -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(coord(), n_points * dim)
}

/// `n_points * dim` small integer coordinates in `-5..=5` (exact in every basis).
pub fn int_points(n_points: usize, dim: usize) -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec((-5i32..=5).prop_map(f64::from), n_points * dim)
}

/// `n` weights in `[0.2, 5]`, positive by construction.
pub fn weights(n: usize) -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(0.2f64..5.0, n)
}

/// A clamped, non-decreasing knot vector for `n_points` control points of degree `p`
/// (`n_points >= p + 1`), on `[0, 1]`, with interior knots of multiplicity `<= p`.
pub fn clamped_knots(n_points: usize, p: usize) -> impl Strategy<Value = Vec<f64>> {
    let n_interior = n_points - p - 1;
    proptest::collection::vec(0.05f64..0.95, n_interior).prop_map(move |mut inner| {
        inner.sort_by(f64::total_cmp);
        // Cap multiplicity at p by nudging repeated values apart when p would be exceeded.
        let mut knots = vec![0.0; p + 1];
        for (i, k) in inner.iter().enumerate() {
            let run = inner[..i].iter().rev().take_while(|x| *x == k).count();
            knots.push(if run + 1 > p {
                k + 1e-3 * (run as f64)
            } else {
                *k
            });
        }
        knots.sort_by(f64::total_cmp);
        knots.extend(std::iter::repeat_n(1.0, p + 1));
        knots
    })
}

/// The largest Euclidean distance between `a(t)` and `b(t)` at `count + 1` equidistant
/// parameters of `[lo, hi]`: the dense reference the tests hold measured errors and
/// certified bounds against (`a` and `b` return the points, e.g. a curve's `eval`).
pub fn sampled_max_distance(
    a: impl Fn(f64) -> Vec<f64>,
    b: impl Fn(f64) -> Vec<f64>,
    (lo, hi): (f64, f64),
    count: u32,
) -> f64 {
    (0..=count)
        .map(|i| {
            let t = lo + (hi - lo) * f64::from(i) / f64::from(count);
            let (x, y) = (a(t), b(t));
            x.iter()
                .zip(&y)
                .map(|(u, v)| (u - v) * (u - v))
                .sum::<f64>()
                .sqrt()
        })
        .fold(0.0, f64::max)
}
