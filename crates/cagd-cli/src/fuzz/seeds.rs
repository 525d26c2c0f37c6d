//! Valid inputs of every shape the command reads, random but well-formed (the fuzzer's
//! starting points before mutation), and the spec-vector files of `cagd check`.

use serde_json::{Value, json};

use super::rng::Rng;

/// The shapes the seeds cover (the `"type"` of the input object; `vectors` is a
/// spec-vector file for `cagd check`).
pub(crate) const SHAPES: &[&str] = &[
    "bezier",
    "bezier-rational",
    "bspline",
    "nurbs",
    "tensor",
    "triangle",
    "bspline-surface",
    "beziers",
    "bezier-patches",
    "wsgb",
    "interval-triangle",
    "trim",
    "vectors",
];

/// A coordinate of size about 5, rounded to 3 decimals or to an integer (the shape's scale
/// is applied by [`make`]).
fn coord(rng: &mut Rng) -> f64 {
    let x = (rng.unit() - 0.5) * 10.0;
    if rng.one_in(10) {
        x.round()
    } else {
        (x * 1000.0).round() / 1000.0
    }
}

/// Multiplies every number under the key `points` (or `lo` / `hi`) of `v` by `scale`.
fn scale_points(v: &mut Value, scale: f64, inside: bool) {
    match v {
        Value::Number(n) if inside => {
            if let Some(x) = n.as_f64() {
                *v = json!(x * scale);
            }
        }
        Value::Array(a) => a.iter_mut().for_each(|x| scale_points(x, scale, inside)),
        Value::Object(o) => o.iter_mut().for_each(|(k, x)| {
            let inner = inside || matches!(k.as_str(), "points" | "segments" | "patches");
            scale_points(x, scale, inner);
        }),
        _ => {}
    }
}

fn point(rng: &mut Rng, dim: usize) -> Value {
    json!((0..dim).map(|_| coord(rng)).collect::<Vec<_>>())
}

fn points(rng: &mut Rng, n: usize, dim: usize) -> Value {
    json!((0..n).map(|_| point(rng, dim)).collect::<Vec<_>>())
}

fn weights(rng: &mut Rng, n: usize) -> Value {
    json!((0..n).map(|_| 0.25 + 2.0 * rng.unit()).collect::<Vec<_>>())
}

/// A clamped knot vector for `n` points of degree `p`: interior knots increasing, some
/// repeated (up to `p`).
fn knots(rng: &mut Rng, n: usize, p: usize) -> Vec<f64> {
    let interior = n - p - 1;
    let mut inner = Vec::with_capacity(interior);
    let mut t = 0.0;
    while inner.len() < interior {
        t += 0.1 + rng.unit();
        let mult = if rng.one_in(4) { 1 + rng.below(p) } else { 1 };
        for _ in 0..mult.min(interior - inner.len()) {
            inner.push(t);
        }
    }
    let end = t + 0.1 + rng.unit();
    let start = if rng.one_in(3) {
        -rng.unit() * 3.0
    } else {
        0.0
    };
    let mut k = vec![start; p + 1];
    k.extend(inner.iter().map(|x| x + start));
    k.extend(std::iter::repeat_n(end + start, p + 1));
    k
}

fn tri_count(n: usize) -> usize {
    (n + 1) * (n + 2) / 2
}

/// One valid input of `shape` (see [`SHAPES`]): at the scale of about 5, or (one in ten)
/// scaled as a whole by 1e-6 or 1e6 (the same tolerances then mean other things).
pub(crate) fn make(rng: &mut Rng, shape: &str) -> Value {
    let mut v = make_unit(rng, shape);
    if rng.one_in(10) {
        let scale = if rng.one_in(2) { 1e-6 } else { 1e6 };
        scale_points(&mut v, scale, false);
    }
    v
}

/// One valid input of `shape` at the scale of about 5.
fn make_unit(rng: &mut Rng, shape: &str) -> Value {
    let dim = 1 + rng.below(3);
    match shape {
        "bezier" | "bezier-rational" => {
            let n = 1 + rng.below(8);
            let dim = if rng.one_in(2) { 2 } else { dim };
            let mut v = json!({"type": "bezier", "points": points(rng, n + 1, dim)});
            if shape == "bezier-rational" {
                v["weights"] = weights(rng, n + 1);
            }
            v
        }
        "bspline" | "nurbs" => {
            let p = 1 + rng.below(4);
            let n = p + 1 + rng.below(6);
            let mut v = json!({"type": "bspline", "degree": p, "knots": knots(rng, n, p),
                               "points": points(rng, n, dim.max(2))});
            if shape == "nurbs" {
                v["weights"] = weights(rng, n);
            }
            v
        }
        "tensor" => {
            let (m, n) = (1 + rng.below(4), 1 + rng.below(4));
            let mut v = json!({"type": "tensor", "degree": [m, n], "points": points(rng, (m + 1) * (n + 1), 3)});
            if rng.one_in(3) {
                v["weights"] = weights(rng, (m + 1) * (n + 1));
            }
            v
        }
        "triangle" => {
            let n = 1 + rng.below(5);
            let mut v =
                json!({"type": "triangle", "degree": n, "points": points(rng, tri_count(n), 3)});
            if rng.one_in(3) {
                v["weights"] = weights(rng, tri_count(n));
            }
            v
        }
        "bspline-surface" => {
            let (p, q) = (1 + rng.below(3), 1 + rng.below(3));
            let (nu, nv) = (p + 1 + rng.below(3), q + 1 + rng.below(3));
            let rows: Vec<Value> = (0..nu).map(|_| points(rng, nv, 3)).collect();
            let mut v = json!({"type": "bspline-surface", "degree": [p, q],
                               "knots_u": knots(rng, nu, p), "knots_v": knots(rng, nv, q),
                               "points": rows});
            if rng.one_in(2) {
                let w: Vec<Value> = (0..nu).map(|_| weights(rng, nv)).collect();
                v["weights"] = json!(w);
            }
            v
        }
        "beziers" => {
            let (m, count) = (1 + rng.below(4), 1 + rng.below(4));
            let dim = dim.max(2);
            // Joined end to start (C0), so that a merge can succeed.
            let mut segs: Vec<Vec<Value>> = Vec::new();
            for i in 0..count {
                let mut seg: Vec<Value> = (0..=m).map(|_| point(rng, dim)).collect();
                if i > 0 {
                    seg[0] = segs[i - 1][m].clone();
                }
                segs.push(seg);
            }
            let mut v = json!({"type": "beziers", "segments": segs});
            if rng.one_in(3) {
                let w: Vec<Value> = (0..count)
                    .map(|_| {
                        if rng.one_in(2) {
                            Value::Null
                        } else {
                            weights(rng, m + 1)
                        }
                    })
                    .collect();
                v["weights"] = json!(w);
            }
            if rng.one_in(2) {
                v["breaks"] = json!((0..=count).map(|i| i as f64 * 0.5).collect::<Vec<_>>());
            }
            v
        }
        "bezier-patches" => {
            let (m, n) = (1 + rng.below(3), 1 + rng.below(3));
            let (cu, cv) = (1 + rng.below(2), 1 + rng.below(2));
            let patches: Vec<Value> = (0..cu * cv)
                .map(|_| points(rng, (m + 1) * (n + 1), 3))
                .collect();
            json!({"type": "bezier-patches", "degree": [m, n],
                   "breaks_u": (0..=cu).map(|i| i as f64).collect::<Vec<_>>(),
                   "breaks_v": (0..=cv).map(|i| i as f64).collect::<Vec<_>>(),
                   "patches": patches})
        }
        "wsgb" => {
            let n = 2 + rng.below(8);
            let l = rng.below(n / 2 + 1);
            json!({"type": "wsgb", "L": l, "points": points(rng, n + 1, dim.max(2))})
        }
        "interval-triangle" => {
            let n = 1 + rng.below(4);
            let lo: Vec<Vec<f64>> = (0..tri_count(n)).map(|_| vec![coord(rng)]).collect();
            let hi: Vec<Vec<f64>> = lo.iter().map(|p| vec![p[0] + rng.unit()]).collect();
            json!({"type": "interval-triangle", "degree": n, "lo": lo, "hi": hi})
        }
        "trim" => {
            let k = 1 + rng.below(3);
            let f: Vec<f64> = (0..=k).map(|_| 0.1 + 0.8 * rng.unit()).collect();
            json!({"direction": if rng.one_in(2) { "u_of_v" } else { "v_of_u" },
                   "keep": if rng.one_in(2) { "below" } else { "above" },
                   "segments": [{"interval": [0, 1], "bezier": f}]})
        }
        _ => vectors(rng),
    }
}

/// A few vectors of `../shared/spec/vectors-*.json` (the spec files are read once).
fn vectors(rng: &mut Rng) -> Value {
    static ALL: std::sync::OnceLock<Vec<Value>> = std::sync::OnceLock::new();
    let all = ALL.get_or_init(|| {
        ["vectors-reduce.json", "vectors-convert.json"]
            .iter()
            .flat_map(|f| cagd_testkit::load_vectors(f))
            .collect()
    });
    let k = 1 + rng.below(3);
    json!((0..k).map(|_| rng.pick(all).clone()).collect::<Vec<_>>())
}
