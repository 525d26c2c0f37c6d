//! Runners of the reduction algorithms of `vectors-reduce.json` (SPEC-reduce §1–§8: seed 000
//! chapter 14 and seed 001). The generalized Ball vectors (§9) have their own family.
//!
//! Every key of `expected` is computed by the library: the reduced points by the reducers,
//! the perturbations `eps` as `E Q - P` (the elevated reduction minus the input), the printed
//! bounds by their spec formulas from the library's results, exact values by the exact
//! routes (exact degeneracy invariants, exact `S^(n)`, Eck's exact weights).

use cagd_core::{
    BSplineCurve, BezierCurve, TensorPatch, TriPatch, binomial, curve_distance,
    curve_invariant_exact, s_matrix_exact, s_matrix_inverse, tensor_invariants_exact,
    tri_invariants_exact,
};
use cagd_reduce::{
    Merge, Method, PatchConstraint, PatchOptions, TensorMethod, ToleranceOptions, TriMethod,
    TriOptions, constrained_chebyshev_terms, eck_lambdas, perturbation_error_factor, reduce,
    reduce_g1_optimal, reduce_tensor, reduce_to_tolerance_alg_14_2_1, reduce_triangle,
    reduce_uniform_bspline, subdivision_levels, tri_perturbation_matrix,
};
use num_rational::BigRational;
use num_traits::ToPrimitive;
use serde_json::{Map, Value, json};

use super::compare::{Rule, compare, parse_rational, rational_string};
use super::fields::{matrix_json, number, numbers, points, points_json};
use super::{Outcome, Runner, Vector};

/// The reduction algorithms of SPEC-reduce §1–§8.
pub(crate) const TABLE: &[(&str, Runner)] = &[
    ("degeneracy_curve_14.1.1", degeneracy_curve),
    ("degeneracy_tensor_14.1.2", degeneracy_tensor),
    ("degeneracy_tri_14.1.3", degeneracy_tri),
    ("perturb_reduce_14.2", perturb),
    ("perturb_error_factor_W_n", w_n_table),
    ("subdivision_count_14.2.11_corrected", subdivision_count),
    ("subdiv_reduce_alg_14.2.1_corrected", subdiv_reduce),
    ("perturb_reduce_G1_14.2.12", perturb_g1),
    ("forrest_reduce_one_step", forrest),
    ("farin_reduce_one_step", farin),
    ("eck_reduce_one_step", eck),
    ("eck_lambdas", eck_lambda_vector),
    ("tensor_perturb_reduce_14.3.1", tensor_perturb),
    ("tri_perturb_reduce_14.3.2", tri_perturb),
    ("ginv_reduce_14.4", ginv),
    ("reduce_cheb_endpoints_14.5", cheb_endpoints),
    ("reduce_cheb_endpoints_14.5 (r=p=-1)", cheb_endpoints),
    ("hermite_reduce_cor_14.5.2", cheb_endpoints),
    ("piegl_tiller_14.5_special", piegl_tiller),
    ("bspline_to_bezier_S_matrix_001", s_matrix_vector),
    ("uniform_bspline_reduce_001", uniform_bspline),
    ("merge_exact_001_4.1", merge_exact),
];

/// The print precision of the paper's printed numbers (6 decimals in single precision,
/// SPEC-reduce §8: 1.2e-5 on the reduced points, 1.5e-4 on the local points of size ~13),
/// relative to the largest entry of the array as in SPEC-reduce §0.
const PRINT_TOL: f64 = 2e-5;

type Res = Result<Outcome, String>;

/// A library result; its error becomes [`Outcome::Refused`].
fn lib<T>(r: cagd_core::Result<T>) -> Result<Result<T, Outcome>, String> {
    Ok(r.map_err(|e| Outcome::Refused(e.to_string())))
}

macro_rules! try_lib {
    ($e:expr) => {
        match lib($e)? {
            Ok(v) => v,
            Err(o) => return Ok(o),
        }
    };
}

/// `input.P` (or `input.<key>`) as a polynomial Bézier curve.
fn curve(v: &Vector<'_>, key: &str) -> Result<cagd_core::Result<BezierCurve>, String> {
    let (p, dim) = points(v.input(key)?, &format!("input.{key}"))?;
    Ok(BezierCurve::new(p, dim))
}

/// A number or an exact rational string as an exact rational (a double is taken exactly).
fn exact_number(x: &Value, what: &str) -> Result<BigRational, String> {
    match x {
        Value::String(s) => parse_rational(s).ok_or_else(|| format!("{what}: not a rational")),
        _ => BigRational::from_float(number(x, what)?).ok_or_else(|| format!("{what}: not finite")),
    }
}

/// A list of points of numbers or rational strings, exactly, with the dimension.
fn exact_points(v: &Value, what: &str) -> Result<(Vec<BigRational>, usize), String> {
    let a = v
        .as_array()
        .ok_or_else(|| format!("{what}: not a list of points"))?;
    let mut flat = Vec::new();
    let mut dim = 0;
    for (i, p) in a.iter().enumerate() {
        let p = p
            .as_array()
            .ok_or_else(|| format!("{what}[{i}]: not a point"))?;
        if i == 0 {
            dim = p.len();
        } else if p.len() != dim {
            return Err(format!(
                "{what}[{i}]: {} coordinates, expected {dim}",
                p.len()
            ));
        }
        for (k, x) in p.iter().enumerate() {
            flat.push(exact_number(x, &format!("{what}[{i}][{k}]"))?);
        }
    }
    if dim == 0 {
        return Err(format!("{what}: no point"));
    }
    Ok((flat, dim))
}

/// The first of `keys` present in `input`, with its key.
fn input_any<'a>(v: &Vector<'a>, keys: &[&'a str]) -> Result<(&'a str, &'a Value), String> {
    keys.iter()
        .find_map(|k| v.input.get(*k).map(|x| (*k, x)))
        .ok_or_else(|| format!("input: none of {keys:?}"))
}

/// Exact values as rational strings grouped in points of `dim`.
fn exact_points_json(q: &[BigRational], dim: usize) -> Value {
    Value::Array(
        q.chunks(dim.max(1))
            .map(|p| Value::Array(p.iter().map(|x| Value::from(rational_string(x))).collect()))
            .collect(),
    )
}

/// Exact values rounded to doubles, grouped in points of `dim`.
fn rounded_points_json(q: &[BigRational], dim: usize) -> Value {
    let f: Vec<f64> = q.iter().map(|x| x.to_f64().unwrap_or(f64::NAN)).collect();
    points_json(&f, dim)
}

/// A flat grid of `rows` rows of `cols` points as nested JSON `[[pt, ...], ...]`.
fn grid_json(flat: &[f64], rows: usize, cols: usize, dim: usize) -> Value {
    Value::Array(
        (0..rows)
            .map(|i| points_json(&flat[i * cols * dim..(i + 1) * cols * dim], dim))
            .collect(),
    )
}

/// `||x||` of a point.
fn norm(x: &[f64]) -> f64 {
    x.iter().map(|a| a * a).sum::<f64>().sqrt()
}

/// `E Q - P`: the reduction elevated back minus the input, point by point.
fn elevated_difference(p: &BezierCurve, q: &BezierCurve) -> cagd_core::Result<Vec<f64>> {
    let e = q.elevate(p.degree() - q.degree())?;
    Ok(e.points()
        .iter()
        .zip(p.points())
        .map(|(a, b)| a - b)
        .collect())
}

fn object(pairs: Vec<(&str, Value)>) -> Value {
    Value::Object(
        pairs
            .into_iter()
            .map(|(k, v)| (k.to_string(), v))
            .collect::<Map<_, _>>(),
    )
}

// --- §1 degeneracy ----------------------------------------------------------------------

/// Eq. 14.1.1, exactly: `F = Delta^n P_0`.
fn degeneracy_curve(v: &Vector<'_>) -> Res {
    let (key, p) = input_any(v, &["P", "P_exact"])?;
    let (p, dim) = exact_points(p, &format!("input.{key}"))?;
    let f = try_lib!(curve_invariant_exact(&p, dim));
    Ok(Outcome::Values(object(vec![
        ("F", rounded_points_json(&f, dim)[0].clone()),
        ("F_exact", exact_points_json(&f, dim)[0].clone()),
    ])))
}

/// A tensor net `P[i][j]` (nested), exactly, with `(m, n, dim)`.
fn exact_grid(v: &Value, what: &str) -> Result<(Vec<BigRational>, usize, usize, usize), String> {
    let rows = v
        .as_array()
        .ok_or_else(|| format!("{what}: not a list of rows"))?;
    let mut flat = Vec::new();
    let (mut cols, mut dim) = (0, 0);
    for (i, row) in rows.iter().enumerate() {
        let (r, d) = exact_points(row, &format!("{what}[{i}]"))?;
        if i == 0 {
            (cols, dim) = (r.len() / d, d);
        } else if r.len() != cols * dim || d != dim {
            return Err(format!("{what}[{i}]: row shape differs from row 0"));
        }
        flat.extend(r);
    }
    if rows.is_empty() {
        return Err(format!("{what}: no row"));
    }
    Ok((flat, rows.len() - 1, cols - 1, dim))
}

/// Eq. 14.1.2, exactly: `F_j`, `G_i`.
fn degeneracy_tensor(v: &Vector<'_>) -> Res {
    let (key, p) = input_any(v, &["P_ij", "P_ij_exact", "P", "P_exact"])?;
    let (p, m, n, dim) = exact_grid(p, &format!("input.{key}"))?;
    let (f, g) = try_lib!(tensor_invariants_exact(&p, m, n, dim));
    Ok(Outcome::Values(object(vec![
        ("F_j", rounded_points_json(&f, dim)),
        ("G_i", rounded_points_json(&g, dim)),
        ("F_j_exact", exact_points_json(&f, dim)),
        ("G_i_exact", exact_points_json(&g, dim)),
    ])))
}

/// Eq. 14.1.3, exactly: `F_k`.
fn degeneracy_tri(v: &Vector<'_>) -> Res {
    let (key, t) = input_any(v, &["T_exact", "T"])?;
    let (t, dim) = exact_points(t, &format!("input.{key}"))?;
    let n = v.param_usize("n")?;
    let f = try_lib!(tri_invariants_exact(&t, n, dim));
    Ok(Outcome::Values(object(vec![
        ("F_k", rounded_points_json(&f, dim)),
        ("F_k_exact", exact_points_json(&f, dim)),
    ])))
}

// --- §2 perturbation --------------------------------------------------------------------

/// §2.1: one-step perturbation reduction `n -> n-1` with `eps`, the book's bound 14.2.8
/// `||F|| / (C(2n,n) - 2)` (false from n = 6 on, printed for comparison), the measured
/// error and `W_n`.
fn perturb(v: &Vector<'_>) -> Res {
    let c = try_lib!(curve(v, "P")?);
    let n = c.degree();
    if n < 2 {
        return Ok(Outcome::Refused(format!("degree {n} < 2")));
    }
    let red = try_lib!(reduce(&c, n - 1, Method::Perturb));
    let eps = try_lib!(elevated_difference(&c, &red.curve));
    let measured = try_lib!(curve_distance(&c, &red.curve));
    let f = norm(&c.forward_difference());
    let d = (binomial(2 * n, n) - 2) as f64;
    let q = points_json(red.curve.points(), c.dim());
    Ok(Outcome::Values(object(vec![
        ("Q", q.clone()),
        ("Q_exact", q),
        ("eps", points_json(&eps, c.dim())),
        ("bound_book_14.2.8", json!(f / d)),
        ("max_error_exact", json!(measured)),
        ("W_n", json!(perturbation_error_factor(n))),
    ])))
}

/// `W_n` (SPEC-reduce §2.1 table).
fn w_n_table(v: &Vector<'_>) -> Res {
    let ns = numbers(v.input("n")?, "input.n")?;
    let mut w = Vec::with_capacity(ns.len());
    for (i, &n) in ns.iter().enumerate() {
        if !(n >= 2.0 && n.fract() == 0.0 && n <= 64.0) {
            return Ok(Outcome::Refused(format!(
                "input.n[{i}] = {n} is not a degree 2..=64"
            )));
        }
        #[allow(clippy::cast_possible_truncation, reason = "checked integer in 2..=64")]
        w.push(perturbation_error_factor(n as usize));
    }
    Ok(Outcome::Values(json!({ "W_n": w })))
}

/// Eq. 14.2.11 as corrected (SPEC-reduce §2.2).
fn subdivision_count(v: &Vector<'_>) -> Res {
    let n = v.param_usize("n")?;
    let delta = v.param_f64("delta")?;
    let norm_f = number(v.input("normF")?, "input.normF")?;
    let levels = try_lib!(subdivision_levels(n, norm_f, delta));
    Ok(Outcome::Values(json!({ "N": levels })))
}

/// Algorithm 14.2.1 as corrected (SPEC-reduce §2.2).
fn subdiv_reduce(v: &Vector<'_>) -> Res {
    let c = try_lib!(curve(v, "P")?);
    let d = v.param_usize("d")?;
    let delta = v.param_f64("delta")?;
    let opts = ToleranceOptions {
        measure: false,
        ..ToleranceOptions::new(Method::Perturb, d, delta, 0)
    };
    let red = try_lib!(reduce_to_tolerance_alg_14_2_1(&c, &opts));
    let intervals: Vec<Value> = red.pieces.iter().map(|p| json!([p.start, p.end])).collect();
    let pieces: Vec<Value> = red
        .pieces
        .iter()
        .map(|p| points_json(p.curve.points(), c.dim()))
        .collect();
    let total: f64 = red.report.step_bounds.iter().sum();
    Ok(Outcome::Values(json!({
        "intervals": intervals,
        "Q_pieces": pieces,
        "certified_total": total,
    })))
}

/// §2.3: G1 perturbation with given `l1, l2`, or the optimal ones when they are `null`.
fn perturb_g1(v: &Vector<'_>) -> Res {
    let c = try_lib!(curve(v, "P")?);
    let n = c.degree();
    let red = match (v.param("l1"), v.param("l2")) {
        (Some(a), Some(b)) => {
            let (l1, l2) = (number(a, "params.l1")?, number(b, "params.l2")?);
            try_lib!(reduce(
                &c,
                n.saturating_sub(1),
                Method::PerturbG1 { l1, l2 }
            ))
        }
        (None, None) => try_lib!(reduce_g1_optimal(&c, false)),
        _ => return Err("params.l1 / l2: give both or neither".to_string()),
    };
    let Method::PerturbG1 { l1, l2 } = red.report.method else {
        return Err("the G1 reduction reported another method".to_string());
    };
    let q = points_json(red.curve.points(), c.dim());
    Ok(Outcome::Values(json!({ "Q": q, "l1": l1, "l2": l2 })))
}

// --- §3 classical one-step methods ------------------------------------------------------

fn one_step(v: &Vector<'_>, method: Method) -> Res {
    let c = try_lib!(curve(v, "P")?);
    let n = match v.param("n_in") {
        Some(x) => number(x, "params.n_in")?,
        None => c.degree() as f64,
    };
    if n != c.degree() as f64 {
        return Err(format!(
            "params.n_in = {n} but input.P has degree {}",
            c.degree()
        ));
    }
    let red = try_lib!(reduce(&c, c.degree().saturating_sub(1), method));
    let q = points_json(red.curve.points(), c.dim());
    Ok(Outcome::Values(json!({ "Q": q.clone(), "Q_exact": q })))
}

fn forrest(v: &Vector<'_>) -> Res {
    one_step(v, Method::Forrest)
}

fn farin(v: &Vector<'_>) -> Res {
    one_step(v, Method::Farin)
}

fn eck(v: &Vector<'_>) -> Res {
    one_step(v, Method::Eck)
}

/// Eck's weights `lambda_i` for the reduction to degree `n`, exactly.
fn eck_lambda_vector(v: &Vector<'_>) -> Res {
    let n = v.param_usize("n")?;
    let l = try_lib!(eck_lambdas(n));
    let exact: Vec<String> = l.iter().map(rational_string).collect();
    let rounded: Vec<f64> = l.iter().map(|x| x.to_f64().unwrap_or(f64::NAN)).collect();
    Ok(Outcome::Values(
        json!({ "lambda_exact": exact, "lambda": rounded }),
    ))
}

// --- §4, §5 patches ---------------------------------------------------------------------

/// The certified bound of SPEC-reduce §4:
/// `min(max_j ||F_j||/H_m + max_i ||G_i||/H_n + ||K||/(H_m H_n), max_ij ||eps_ij||)` with the
/// invariants `F_j`, `G_i` of eq. 14.1.2, `K = sum_j (-1)^(n-j) C(n,j) F_j`, `H_k = C(2k,k)`.
fn tensor_bound(patch: &TensorPatch, eps: &[f64]) -> f64 {
    let (m, n) = patch.degrees();
    let dim = patch.dim();
    let (f, g) = patch.degeneracy_invariants();
    let (hm, hn) = (binomial(2 * m, m) as f64, binomial(2 * n, n) as f64);
    let mut k = vec![0.0; dim];
    for (j, fj) in f.chunks_exact(dim).enumerate() {
        let dj = cagd_core::sign_binomial_f64(n, j);
        for (a, b) in k.iter_mut().zip(fj) {
            *a += dj * b;
        }
    }
    let max_norm = |x: &[f64]| x.chunks_exact(dim).map(norm).fold(0.0, f64::max);
    let invariant = max_norm(&f) / hm + max_norm(&g) / hn + norm(&k) / (hm * hn);
    invariant.min(max_norm(eps))
}

/// §14.3.1: tensor perturbation `(m, n) -> (m-1, n-1)` with `eps` and the bound.
fn tensor_perturb(v: &Vector<'_>) -> Res {
    let (p, m, n, dim) = exact_grid(v.input("P")?, "input.P")?;
    for (key, want) in [("m", m), ("n", n)] {
        if let Some(x) = v.param(key)
            && x.as_u64() != Some(want as u64)
        {
            return Err(format!("params.{key} = {x} does not match input.P"));
        }
    }
    let p: Vec<f64> = p.iter().map(|x| x.to_f64().unwrap_or(f64::NAN)).collect();
    let patch = try_lib!(TensorPatch::new(p, m, n, dim));
    if m == 0 || n == 0 {
        return Ok(Outcome::Refused(format!(
            "degree ({m}, {n}) cannot be reduced in both directions"
        )));
    }
    let opts = PatchOptions::new(TensorMethod::Perturb(PatchConstraint::None));
    let red = try_lib!(reduce_tensor(&patch, (m - 1, n - 1), &opts));
    let bound = tensor_bound(&patch, &red.perturbation);
    let q = grid_json(red.patch.points(), m, n, dim);
    Ok(Outcome::Values(json!({
        "Q": q.clone(),
        "Q_exact": q,
        "eps": grid_json(&red.perturbation, m + 1, n + 1, dim),
        "bound": bound,
    })))
}

/// §14.3.2: triangular perturbation `n -> n-1` with the multipliers and `B_km`.
fn tri_perturb(v: &Vector<'_>) -> Res {
    let (t, dim) = points(v.input("T")?, "input.T")?;
    let n = v.param_usize("n")?;
    let patch = try_lib!(TriPatch::new(t, n, dim));
    if n == 0 {
        return Ok(Outcome::Refused("degree 0 cannot be reduced".to_string()));
    }
    let red = try_lib!(reduce_triangle(
        &patch,
        n - 1,
        &TriOptions::new(TriMethod::Perturb)
    ));
    let lambda = red.multipliers.as_deref().unwrap_or(&[]);
    let b = tri_perturbation_matrix(n);
    let side = n + 1;
    let q = points_json(red.patch.points(), dim);
    Ok(Outcome::Values(json!({
        "Q": q.clone(),
        "Q_exact": q,
        "lambda": points_json(lambda, dim),
        "B_km": matrix_json(side, side, &b),
    })))
}

// --- §6, §7 multi-degree ----------------------------------------------------------------

/// The convex-hull bound `max_i ||P_i - (E Q)_i||` (eq. 14.4.3).
fn hull_bound(p: &BezierCurve, q: &BezierCurve) -> cagd_core::Result<f64> {
    let d = elevated_difference(p, q)?;
    Ok(d.chunks_exact(p.dim()).map(norm).fold(0.0, f64::max))
}

/// §14.4: generalized inverse, free or with the end points kept.
fn ginv(v: &Vector<'_>) -> Res {
    let c = try_lib!(curve(v, "P")?);
    let m = v.param_usize("m")?;
    let ends = v.param("endpoints").map_or(Ok(false), |x| {
        x.as_bool().ok_or("params.endpoints: not a boolean")
    })?;
    let method = if ends {
        Method::GeneralizedInverseEnds
    } else {
        Method::GeneralizedInverse
    };
    let red = try_lib!(reduce(&c, m, method));
    let bound = try_lib!(hull_bound(&c, &red.curve));
    let q = points_json(red.curve.points(), c.dim());
    Ok(Outcome::Values(
        json!({ "Q": q.clone(), "Q_exact": q, "bound_14.4.3": bound }),
    ))
}

/// `params.<key>` as an end order `>= -1`.
fn end_order(v: &Vector<'_>, key: &str) -> Result<i32, String> {
    let x = v
        .param(key)
        .and_then(Value::as_i64)
        .ok_or_else(|| format!("params.{key}: not an integer"))?;
    i32::try_from(x).map_err(|_| format!("params.{key} = {x} out of range"))
}

/// §14.5: constrained Chebyshev (Theorem 14.5.2; Corollary 14.5.2 when `m = r + p + 1`;
/// truncation when `r = p = -1`), with `P^III` and the theorem's bound.
fn cheb_endpoints(v: &Vector<'_>) -> Res {
    let c = try_lib!(curve(v, "P")?);
    let m = v.param_usize("m")?;
    let (r, p) = (end_order(v, "r")?, end_order(v, "p")?);
    let red = try_lib!(reduce(&c, m, Method::ConstrainedChebyshev { r, p }));
    let dim = c.dim();
    let q = points_json(red.curve.points(), dim);
    let mut out = json!({ "Q": q.clone(), "Q_exact": q });
    if i64::from(r) + i64::from(p) + 1 < i64::try_from(m).unwrap_or(i64::MAX) {
        let terms = try_lib!(constrained_chebyshev_terms(&c, m, r, p));
        out["bound"] = json!(terms.bound);
        out["P_III"] = points_json(&terms.coefficients, dim);
    }
    Ok(Outcome::Values(out))
}

/// §7 Piegl–Tiller special case.
fn piegl_tiller(v: &Vector<'_>) -> Res {
    let c = try_lib!(curve(v, "P")?);
    let m = v.param_usize("m")?;
    let red = try_lib!(reduce(&c, m, Method::PieglTiller));
    let q = points_json(red.curve.points(), c.dim());
    Ok(Outcome::Values(json!({ "Q": q.clone(), "Q_exact": q })))
}

// --- §8 seed 001 ------------------------------------------------------------------------

/// `S^(n)` exactly (seed 001 eq. 5).
fn s_matrix_vector(v: &Vector<'_>) -> Res {
    let n = v.param_usize("n")?;
    let s = try_lib!(s_matrix_exact(n));
    let exact = exact_points_json(s, n + 1);
    let rounded = rounded_points_json(s, n + 1);
    Ok(Outcome::Values(json!({ "S_exact": exact, "S": rounded })))
}

/// The Bézier reduction `T_{n,r}` named by the vector's `bezier_reduction` text (or
/// `method`, `r`, `p` params): constrained Chebyshev §14.5 with `(r, p)` unless the text
/// names L2 / least squares or the generalized inverse.
fn pipeline_method(v: &Vector<'_>) -> Result<Method, String> {
    let text = v
        .param("bezier_reduction")
        .or_else(|| v.param("method"))
        .and_then(Value::as_str)
        .unwrap_or("")
        .to_ascii_lowercase();
    let compact: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    let int_after = |pat: &str| -> Option<i32> {
        let i = compact.find(pat)? + pat.len();
        let digits: String = compact[i..]
            .chars()
            .enumerate()
            .take_while(|(k, ch)| ch.is_ascii_digit() || (*k == 0 && *ch == '-'))
            .map(|(_, ch)| ch)
            .collect();
        digits.parse().ok()
    };
    let pair = || -> Option<(i32, i32)> {
        let i = compact.find("(r,p)=(")? + "(r,p)=(".len();
        let rest = &compact[i..];
        let (a, b) = rest.split_once(',')?;
        let b = b.split(')').next()?;
        Some((a.parse().ok()?, b.parse().ok()?))
    };
    let (r, p) = if v.param("r").is_some() && v.param("p").is_some() {
        (end_order(v, "r")?, end_order(v, "p")?)
    } else if let Some(k) = int_after("r=p=") {
        (k, k)
    } else if let Some(rp) = pair() {
        rp
    } else if let (Some(r), Some(p)) = (int_after("r="), int_after("p=")) {
        (r, p)
    } else if compact.contains("hermite") && compact.contains("c1") {
        (1, 1)
    } else {
        (0, 0)
    };
    Ok(if compact.contains("l2") || compact.contains("least") {
        Method::L2 { r, p }
    } else if compact.contains("14.4") || compact.contains("inverse") {
        if r >= 0 || p >= 0 {
            Method::GeneralizedInverseEnds
        } else {
            Method::GeneralizedInverse
        }
    } else {
        Method::ConstrainedChebyshev { r, p }
    })
}

/// Seed 001's pipeline (SPEC-reduce §8): Bézier points of every segment (`S^(n)`), the
/// reduced segments, their local uniform points `S^(m)^{-1} q`, the merged spline (knots
/// numbered as the paper does, from the input's first knot: the library keeps the input's
/// domain, `(n - m) h` further on). `printed_*` keys hold the paper's printed numbers,
/// compared at their print precision ([`PRINT_TOL`]).
fn uniform_bspline(v: &Vector<'_>) -> Res {
    let n = v.param_usize("degree_in")?;
    let m = v.param_usize("degree_out")?;
    let knots = numbers(
        v.param("knots").ok_or("params.knots: missing")?,
        "params.knots",
    )?;
    let (p, dim) = points(v.input("P")?, "input.P")?;
    let c = try_lib!(BSplineCurve::new(n, knots.clone(), p, dim));
    let method = pipeline_method(v)?;
    let merge_text = v
        .param("merge")
        .and_then(Value::as_str)
        .unwrap_or("lossy")
        .to_ascii_lowercase();
    let merge = if merge_text.contains("exact") {
        Merge::Exact
    } else {
        Merge::Lossy
    };
    let segs = try_lib!(c.to_beziers());
    let red = try_lib!(reduce_uniform_bspline(&c, m, method, merge));
    let s_inv = try_lib!(s_matrix_inverse(m));
    let local: Vec<Value> = red
        .segments
        .iter()
        .map(|s| {
            let q = s.points();
            let mut out = vec![0.0; (m + 1) * dim];
            for i in 0..=m {
                for j in 0..=m {
                    for d in 0..dim {
                        out[i * dim + d] += s_inv[i * (m + 1) + j] * q[j * dim + d];
                    }
                }
            }
            points_json(&out, dim)
        })
        .collect();
    let bez: Vec<Value> = segs
        .iter()
        .map(|s| points_json(s.curve.points(), dim))
        .collect();
    let reduced: Vec<Value> = red
        .segments
        .iter()
        .map(|s| points_json(s.points(), dim))
        .collect();
    let h = knots.get(1).zip(knots.first()).map_or(1.0, |(b, a)| b - a);
    let shift = (n - m) as f64 * h;
    let merged_knots: Vec<f64> = red.curve.knots().iter().map(|k| k - shift).collect();
    let got = json!({
        "bezier_segments": bez,
        "reduced_segments": reduced,
        "local_bspline": local,
        "merged_ctrl": points_json(red.curve.points(), dim),
        "merged_knots": merged_knots,
        "printed_reduced": reduced,
        "printed_local_bspline": local,
    });
    Ok(split_printed(&got, v))
}

/// Compares the computed keys at the vector's tolerance and the `printed_*` keys at
/// [`PRINT_TOL`] (both by SPEC-reduce §0's per-array rule).
fn split_printed(got: &Value, v: &Vector<'_>) -> Outcome {
    let Value::Object(expected) = v.expected else {
        return Outcome::Compared {
            max_diff: f64::NAN,
            pass: false,
            detail: "expected is not an object".to_string(),
        };
    };
    let (printed, computed): (Map<_, _>, Map<_, _>) = expected
        .iter()
        .map(|(k, x)| (k.clone(), x.clone()))
        .partition(|(k, _)| k.starts_with("printed_"));
    let a = compare(got, &Value::Object(computed), v.tol, Rule::PerArray);
    let b = compare(
        got,
        &Value::Object(printed),
        v.tol.max(PRINT_TOL),
        Rule::PerArray,
    );
    match (a, b) {
        (Ok(d), Ok(_)) => Outcome::Compared {
            max_diff: d,
            pass: true,
            detail: String::new(),
        },
        (Err((d, why)), _) => Outcome::Compared {
            max_diff: d,
            pass: false,
            detail: why,
        },
        (Ok(d), Err((_, why))) => Outcome::Compared {
            max_diff: d,
            pass: false,
            detail: format!("printed value beyond the print precision: {why}"),
        },
    }
}

/// Seed 001 §4.1: exact merge of Bézier segments on `0, 1, 2, ...` with interior
/// multiplicity `m - k`.
fn merge_exact(v: &Vector<'_>) -> Res {
    let (key, segs) = input_any(v, &["segments_exact", "segments"])?;
    let list = segs
        .as_array()
        .ok_or_else(|| format!("input.{key}: not a list of segments"))?;
    let mut curves = Vec::with_capacity(list.len());
    let mut exact = Vec::with_capacity(list.len());
    for (i, s) in list.iter().enumerate() {
        let (q, dim) = exact_points(s, &format!("input.{key}[{i}]"))?;
        let f: Vec<f64> = q.iter().map(|x| x.to_f64().unwrap_or(f64::NAN)).collect();
        curves.push(try_lib!(BezierCurve::new(f, dim)));
        exact.push((q, dim));
    }
    let Some(first) = curves.first() else {
        return Ok(Outcome::Refused("no segment".to_string()));
    };
    let degree = first.degree();
    if let Some(d) = v.param("degree")
        && d.as_u64() != Some(degree as u64)
    {
        return Err(format!("params.degree = {d} does not match the segments"));
    }
    let mult = match v.param("interior_multiplicity") {
        Some(_) => v.param_usize("interior_multiplicity")?,
        None => degree,
    };
    if mult == 0 || mult > degree {
        return Ok(Outcome::Refused(format!(
            "interior multiplicity {mult} not in 1..={degree}"
        )));
    }
    let k = degree - mult;
    let breaks: Vec<f64> = (0..=curves.len()).map(|i| i as f64).collect();
    let scale = curves
        .iter()
        .flat_map(|c| c.points().iter())
        .fold(1.0_f64, |a, x| a.max(x.abs()));
    let spline = try_lib!(BSplineCurve::from_beziers(
        &curves,
        &breaks,
        k,
        1e-9 * scale
    ));
    // The exact control points: removing a knot at an exact C^k joint only drops points, so
    // every surviving point is an input point; it is reported exactly where the library's
    // value is that input point rounded (else the library's double, exactly).
    let dim = first.dim();
    let mut ctrl_exact = Vec::new();
    for pt in spline.points().chunks_exact(dim) {
        let found = exact.iter().find_map(|(q, d)| {
            q.chunks_exact(*d).find(|e| {
                e.iter()
                    .zip(pt)
                    .all(|(a, b)| a.to_f64().is_some_and(|x| x == *b))
            })
        });
        match found {
            Some(e) => ctrl_exact.extend(e.iter().cloned()),
            None => ctrl_exact.extend(
                pt.iter()
                    .map(|x| BigRational::from_float(*x).unwrap_or_default()),
            ),
        }
    }
    Ok(Outcome::Values(json!({
        "knots": spline.knots(),
        "ctrl": points_json(spline.points(), dim),
        "ctrl_exact": exact_points_json(&ctrl_exact, dim),
    })))
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn vector(params: Value) -> Value {
        json!({"id": "t", "algorithm": "uniform_bspline_reduce_001", "params": params,
               "input": {}, "expected": {}, "tol": 0})
    }

    #[test]
    fn pipeline_method_reads_the_text() {
        for (text, want) in [
            (
                "C1 Hermite (14.5 cor. 14.5.2, r=p=1)",
                Method::ConstrainedChebyshev { r: 1, p: 1 },
            ),
            (
                "14.5 with (r,p) = (0,0)",
                Method::ConstrainedChebyshev { r: 0, p: 0 },
            ),
            (
                "§7, (r, p) = (0, 2)",
                Method::ConstrainedChebyshev { r: 0, p: 2 },
            ),
            ("L2 r=1, p=0", Method::L2 { r: 1, p: 0 }),
        ] {
            let raw = vector(json!({"bezier_reduction": text}));
            let v = Vector::read(&raw).unwrap();
            assert_eq!(pipeline_method(&v).unwrap(), want, "{text}");
        }
    }
}
