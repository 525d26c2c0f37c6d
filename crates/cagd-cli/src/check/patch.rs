//! `cagd check` runners for SPEC-convert §15.4–15.7 (triangular ↔ rectangular patches,
//! generalized subdivision along a line or a curve).
//!
//! Inputs: `input.triangle_points` (i-major, degree from the count; `params.n` when given
//! must agree) or `input.rect_points` (degrees `params.m`, `params.n`; a square net when
//! they are absent), optional weights in `input.weights` (or `triangle_weights` /
//! `rect_weights`) in the order of the points. Every output key is computed by the library;
//! rational results also carry `<key>_weights`.

use cagd_convert::{
    PatchPiece, PatchSurface, PieceDomain, TensorSurface, TriSplitPoints, TriSurface,
};
use cagd_core::tri_count;
use serde_json::{Map, Value, json};

use super::fields::{number, numbers, points, points_json};
use super::{Outcome, Runner, Vector};

/// The runners of this family.
pub(crate) const TABLE: &[(&str, Runner)] = &[
    ("triangle_to_degenerate_rect", run_tri_to_rect),
    ("degenerate_rect_to_triangle", run_rect_to_tri),
    ("triangle_to_rect_D1", run_rect_d1),
    ("triangle_to_three_rects", run_three_rects),
    ("gsub_trapezoid", run_trapezoid),
    ("gsub_corner_triangle", run_corner),
    ("rect_to_two_triangles", run_two_triangles),
    ("gsub_curve", run_curve),
    ("gsub_curve_D7", run_curve_d7),
];

/// Optional weights of the input.
fn weights(v: &Vector<'_>, key: &str) -> Result<Option<Vec<f64>>, String> {
    for k in [format!("{key}_weights"), "weights".to_string()] {
        if let Some(w) = v.input.get(&k).filter(|w| !w.is_null()) {
            return numbers(w, &format!("input.{k}")).map(Some);
        }
    }
    Ok(None)
}

/// The input triangle (the library's refusal becomes `Err(Outcome)`).
fn triangle(v: &Vector<'_>) -> Result<Result<TriSurface, String>, String> {
    let (pts, dim) = points(v.input("triangle_points")?, "input.triangle_points")?;
    let count = pts.len().checked_div(dim).unwrap_or(0);
    let n = (0..=64).find(|&n| tri_count(n) == count);
    let n = match (n, v.param("n")) {
        (Some(n), None) => n,
        (Some(n), Some(_)) if v.param_usize("n")? == n => n,
        (found, _) => {
            let n = v.param_usize("n").ok().or(found).unwrap_or(0);
            // Let the library name the mismatch.
            return Ok(TriSurface::new(pts, n, dim.max(1), weights(v, "triangle")?)
                .map_err(|e| e.to_string()));
        }
    };
    Ok(TriSurface::new(pts, n, dim, weights(v, "triangle")?).map_err(|e| e.to_string()))
}

/// The input rectangle.
fn rect(v: &Vector<'_>) -> Result<Result<TensorSurface, String>, String> {
    let (pts, dim) = points(v.input("rect_points")?, "input.rect_points")?;
    let count = pts.len().checked_div(dim).unwrap_or(0);
    let (m, n) = match (v.param("m"), v.param("n")) {
        (Some(_), Some(_)) => (v.param_usize("m")?, v.param_usize("n")?),
        (None, Some(_)) => {
            let n = v.param_usize("n")?;
            (n, n)
        }
        _ => {
            let side = (0..=64).find(|s| (s + 1) * (s + 1) == count).unwrap_or(0);
            (side, side)
        }
    };
    Ok(TensorSurface::new(pts, m, n, dim.max(1), weights(v, "rect")?).map_err(|e| e.to_string()))
}

/// Weights of a rational result under the names a vector may use for them:
/// `<key>_weights`, `<key without _points>_weights` and, for a single output, `weights`.
fn put_weights(out: &mut Map<String, Value>, key: &str, w: Option<&[f64]>, single: bool) {
    if let Some(w) = w {
        out.insert(format!("{key}_weights"), json!(w));
        if let Some(stem) = key.strip_suffix("_points") {
            out.insert(format!("{stem}_weights"), json!(w));
        }
        if single {
            out.insert("weights".into(), json!(w));
        }
    }
}

/// Points (and weights) of a tensor patch as JSON under `key`.
fn put_tensor(out: &mut Map<String, Value>, key: &str, p: &TensorSurface) {
    out.insert(key.into(), points_json(p.net().points(), p.dim()));
    put_weights(out, key, p.weights(), true);
}

/// Points (and weights) of a triangular patch as JSON under `key`.
fn put_tri(out: &mut Map<String, Value>, key: &str, t: &TriSurface, single: bool) {
    out.insert(key.into(), points_json(t.net().points(), t.dim()));
    put_weights(out, key, t.weights(), single);
}

/// The tensor patch of a piece.
fn tensor_of(piece: &PatchPiece) -> Result<&TensorSurface, String> {
    match &piece.surface {
        PatchSurface::Tensor(p) => Ok(p),
        PatchSurface::Tri(_) => Err("internal: expected a tensor piece".into()),
    }
}

/// A tensor-piece result under `rect_points` with `degree: [m, n]` (an extra key is
/// harmless: only the keys of `expected` are compared).
fn tensor_outcome(r: cagd_core::Result<PatchPiece>) -> Result<Outcome, String> {
    let piece = match r {
        Ok(p) => p,
        Err(e) => return Ok(Outcome::Refused(e.to_string())),
    };
    let p = tensor_of(&piece)?;
    let mut out = Map::new();
    put_tensor(&mut out, "rect_points", p);
    let (m, n) = p.degrees();
    out.insert("degree".into(), json!([m, n]));
    Ok(Outcome::Values(Value::Object(out)))
}

macro_rules! input_or_refuse {
    ($e:expr) => {
        match $e? {
            Ok(x) => x,
            Err(msg) => return Ok(Outcome::Refused(msg)),
        }
    };
}

/// §15.4 forward (eq. 15.4.2); `params.m >= n` elevates further in `s`.
fn run_tri_to_rect(v: &Vector<'_>) -> Result<Outcome, String> {
    let t = input_or_refuse!(triangle(v));
    let m = match v.param("m") {
        Some(_) => v.param_usize("m")?,
        None => t.degree(),
    };
    tensor_outcome(cagd_convert::triangle_to_degenerate_rect(&t, m))
}

/// §15.4 inverse (Theorem 15.4.2); an error vector passes on `NotDegenerate`.
fn run_rect_to_tri(v: &Vector<'_>) -> Result<Outcome, String> {
    let p = input_or_refuse!(rect(v));
    let tol = match v.param("tol") {
        Some(_) => v.param_f64("tol")?,
        None if v.tol > 0.0 => v.tol,
        None => 1e-12,
    };
    match cagd_convert::degenerate_rect_to_triangle(&p, tol) {
        Ok(t) => {
            let mut out = Map::new();
            put_tri(&mut out, "triangle_points", &t, true);
            Ok(Outcome::Values(Value::Object(out)))
        }
        Err(e) => Ok(Outcome::Refused(e.to_string())),
    }
}

/// §15.5 one rectangle over D1.
fn run_rect_d1(v: &Vector<'_>) -> Result<Outcome, String> {
    let t = input_or_refuse!(triangle(v));
    let (a, b, c, d) = (
        v.param_f64("a")?,
        v.param_f64("b")?,
        v.param_f64("c")?,
        v.param_f64("d")?,
    );
    tensor_outcome(cagd_convert::triangle_to_rect_d1(&t, a, b, c, d))
}

/// A parameter-plane point `[u, v]`.
fn plane_point(v: &Vector<'_>, key: &str) -> Result<[f64; 2], String> {
    let p = numbers(
        v.param(key).ok_or(format!("params.{key}: missing"))?,
        &format!("params.{key}"),
    )?;
    match p[..] {
        [a, b] => Ok([a, b]),
        _ => Err(format!("params.{key}: expected [u, v]")),
    }
}

/// §15.5 three rectangles through `P` and `G`, `K`, `H` (points of the parameter plane;
/// `G` on `v = 0`, `K` on `u + v = 1`, `H` on `u = 0`).
fn run_three_rects(v: &Vector<'_>) -> Result<Outcome, String> {
    let t = input_or_refuse!(triangle(v));
    let p = plane_point(v, "P")?;
    let (g, k, h) = (
        plane_point(v, "G")?,
        plane_point(v, "K")?,
        plane_point(v, "H")?,
    );
    let off = |what: &str, x: f64| format!("{what} = {x} is not on its edge");
    if g[1] != 0.0 {
        return Ok(Outcome::Refused(off("G.v", g[1])));
    }
    if (k[0] + k[1] - 1.0).abs() > 1e-12 {
        return Ok(Outcome::Refused(off("K.u + K.v", k[0] + k[1])));
    }
    if h[0] != 0.0 {
        return Ok(Outcome::Refused(off("H.u", h[0])));
    }
    let split = TriSplitPoints {
        p,
        g: g[0],
        k: k[0],
        h: h[1],
    };
    let pieces = match cagd_convert::triangle_to_three_rects(&t, split) {
        Ok(p) => p,
        Err(e) => return Ok(Outcome::Refused(e.to_string())),
    };
    let mut rects = Vec::new();
    let mut corners = Vec::new();
    let mut weights = Vec::new();
    for piece in &pieces {
        let r = tensor_of(piece)?;
        rects.push(points_json(r.net().points(), r.dim()));
        if let Some(w) = r.weights() {
            weights.push(json!(w));
        }
        if let PieceDomain::Bilinear(x) = &piece.domain {
            corners.push(json!(x));
        }
    }
    let mut out = Map::new();
    out.insert("rects".into(), Value::Array(rects));
    out.insert("corners".into(), Value::Array(corners));
    if !weights.is_empty() {
        out.insert("rects_weights".into(), Value::Array(weights));
    }
    Ok(Outcome::Values(Value::Object(out)))
}

/// §15.6.1 left trapezoid.
fn run_trapezoid(v: &Vector<'_>) -> Result<Outcome, String> {
    let p = input_or_refuse!(rect(v));
    tensor_outcome(cagd_convert::trapezoid(
        &p,
        v.param_f64("a")?,
        v.param_f64("b")?,
    ))
}

/// §15.6.2 corner triangle.
fn run_corner(v: &Vector<'_>) -> Result<Outcome, String> {
    let p = input_or_refuse!(rect(v));
    tensor_outcome(cagd_convert::corner_triangle(
        &p,
        v.param_f64("a")?,
        v.param_f64("b")?,
    ))
}

/// §15.6.3 rectangle → two triangles.
fn run_two_triangles(v: &Vector<'_>) -> Result<Outcome, String> {
    let p = input_or_refuse!(rect(v));
    let [lower, upper] = match cagd_convert::rect_to_two_triangles(&p) {
        Ok(t) => t,
        Err(e) => return Ok(Outcome::Refused(e.to_string())),
    };
    let mut out = Map::new();
    out.insert("degree".into(), json!(lower.degree()));
    put_tri(&mut out, "lower_triangle", &lower, false);
    put_tri(&mut out, "upper_triangle", &upper, false);
    Ok(Outcome::Values(Value::Object(out)))
}

/// The Bernstein coefficients `params.a` of the splitting curve; `params.k` must agree.
fn curve_coeffs(v: &Vector<'_>) -> Result<Vec<f64>, String> {
    let a = numbers(v.param("a").ok_or("params.a: missing")?, "params.a")?;
    if v.param("k").is_some() && v.param_usize("k")? + 1 != a.len() {
        return Err(format!(
            "params.k = {} does not match {} coefficients",
            v.param_usize("k")?,
            a.len()
        ));
    }
    Ok(a)
}

/// §15.7 region D5.
fn run_curve(v: &Vector<'_>) -> Result<Outcome, String> {
    let p = input_or_refuse!(rect(v));
    let a = curve_coeffs(v)?;
    match v.param("b") {
        Some(b) => {
            let b = number(b, "params.b")?;
            tensor_outcome(cagd_convert::curve_split_d7(&p, &a, b))
        }
        None => tensor_outcome(cagd_convert::curve_split_d5(&p, &a)),
    }
}

/// §15.7 region D7.
fn run_curve_d7(v: &Vector<'_>) -> Result<Outcome, String> {
    let p = input_or_refuse!(rect(v));
    let a = curve_coeffs(v)?;
    tensor_outcome(cagd_convert::curve_split_d7(&p, &a, v.param_f64("b")?))
}
