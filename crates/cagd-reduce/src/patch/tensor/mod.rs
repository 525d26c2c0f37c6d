//! Tensor-product patch reduction `(m, n) -> (m - 1, n - 1)` by control-point perturbation
//! (seed 000 §14.3.1, eqs. 14.3.2-14.3.7, Algorithm 14.3.1; SPEC-reduce §4), unconstrained
//! or with corner / boundary constraints, and the entry point [`reduce_tensor`].

use cagd_core::{
    Error, ExactMatrix, Result, TensorPatch, binomial_f64, sign_binomial_f64, tensor_patch_distance,
};

mod curves;
mod lines;

use crate::patch::exact::{
    Cache, Mat, cached, elevation_exact, inverse_elevate, max_diff, max_norm, norm, pinv_columns,
};
use crate::patch::report::{
    PatchConstraint, PatchOptions, PatchReduction, PatchReport, TensorMethod,
};
use crate::{Method, operator};
use curves::reduce_curves;
use lines::{map_columns, map_rows};

/// Reduces a tensor-product patch of degree `(m, n)` to degree `target = (m', n')`.
///
/// * [`TensorMethod::Perturb`]: seed 000 §14.3.1, one degree in each direction
///   (`target = (m - 1, n - 1)`, `m, n >= 1`). Minimises `sum_ij ||eps_ij||^2` (control
///   points, not the surface error) such that `P + eps` is degenerate (eq. 14.1.2 in both
///   directions), i.e. the orthogonal projection per coordinate
///   `P + eps = (I - c cᵀ/H_m) P (I - d dᵀ/H_n)` (SPEC-reduce §4 closed form: the system
///   14.3.7 is singular), then the inverse elevation, two-sided per column then per row.
///   Certified bound: the smaller of SPEC-reduce §4's
///   `max_j ||F_j||/H_m + max_i ||G_i||/H_n + ||K||/(H_m H_n)` and `max_ij ||eps_ij||`.
///   - [`PatchConstraint::Corners`] (`m, n >= 2`): the same minimum with
///     `eps = 0` at the four corners: a rank-4 correction of the free solution through the
///     Kronecker-structured inverse `(E_uᵀE_u)^-1 ⊗ (E_vᵀE_v)^-1` (exact, cached).
///   - [`PatchConstraint::Boundary`] (`m, n >= 2`): the boundary rows / columns of `Q`
///     are the curve reductions of `P`'s boundary curves; the interior of `Q` minimises
///     `sum ||eps_ij||^2` = `||E_u Q E_vᵀ - P||^2` (separable: exact pseudo-inverses of the
///     interior columns of `E_u`, `E_v`).
///
///   Bound of the constrained variants: `max ||eps_ij||` (convex hull).
/// * [`TensorMethod::Curves`]: any `m' <= m`, `n' <= n` (not both equal), see
///   [`TensorMethod::Curves`]. Bound: the smaller of `max_j bound_u(column j) +
///   max_i bound_v(row i of the intermediate net)` (partition of unity) and the convex-hull
///   bound `max_ij ||P_ij - (E_u Q E_vᵀ)_ij||`.
///
/// All bounds include an allowance for `f64` rounding. Degrees up to 64; the operators are
/// exact rationals rounded once (measured: an exactly elevated `(m, n)` patch comes back to
/// 1e-14 relative, see the tests).
///
/// # Errors
/// [`Error::BadDegreePair`] (a target degree above the source, no reduction at all, or a
/// target other than `(m - 1, n - 1)` for `Perturb`), [`Error::TooManyConstraints`]
/// (corner / boundary constraints with a target degree `0`, a boundary method that does not
/// interpolate the ends), and the curve methods' errors ([`Method::check`]).
///
/// ```
/// use cagd_core::TensorPatch;
/// use cagd_reduce::{Method, PatchConstraint, PatchOptions, TensorMethod, reduce_tensor};
/// // A bilinear patch elevated to (3, 2) comes back from (3, 2) -> (2, 1) -> ... exactly.
/// let p = TensorPatch::new(vec![0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0], 1, 1, 2)?;
/// let e = p.elevate_u(2)?.elevate_v(1)?;
/// let opts = PatchOptions::new(TensorMethod::Curves { u: Method::L2 { r: 0, p: 0 }, v: Method::Eck });
/// let red = reduce_tensor(&e, (1, 1), &opts)?;
/// assert!(cagd_core::tensor_patch_distance(&red.patch, &p)? < 1e-14);
/// let red = reduce_tensor(&e, (2, 1), &PatchOptions::new(TensorMethod::Perturb(PatchConstraint::None)))?;
/// assert!(red.report.error_bound < 1e-13); // rounding allowance only
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn reduce_tensor(
    p: &TensorPatch,
    target: (usize, usize),
    opts: &PatchOptions,
) -> Result<PatchReduction> {
    let (m, n) = p.degrees();
    let (mt, nt) = target;
    for (from, to) in [(m, mt), (n, nt)] {
        if to > from {
            return Err(Error::BadDegreePair {
                from,
                to,
                why: "the target degree must not exceed the source degree",
            });
        }
    }
    if (mt, nt) == (m, n) {
        return Err(Error::BadDegreePair {
            from: m,
            to: mt,
            why: "at least one direction must be reduced",
        });
    }
    let (q, bound) = match opts.method {
        TensorMethod::Curves { u, v } => reduce_curves(p, target, u, v)?,
        TensorMethod::Perturb(constraint) => {
            if m == 0 || n == 0 || (mt, nt) != (m - 1, n - 1) {
                return Err(Error::BadDegreePair {
                    from: m.max(n),
                    to: mt.max(nt),
                    why: "the tensor perturbation reduces (m, n) to (m - 1, n - 1), m, n >= 1",
                });
            }
            match constraint {
                PatchConstraint::None => perturb_free(p)?,
                PatchConstraint::Corners => perturb_corners(p)?,
                PatchConstraint::Boundary(method) => perturb_boundary(p, method)?,
            }
        }
    };
    let max_error = if opts.measure {
        Some(tensor_patch_distance(p, &q)?)
    } else {
        None
    };
    let perturbation = elevated_minus(p, &q)?;
    let bound = bound.min(hull_bound(p, &q, &perturbation));
    Ok(PatchReduction {
        report: PatchReport {
            method: opts.method.name(),
            degrees_from: (m, n),
            degrees_to: q.degrees(),
            error_bound: bound,
            max_error,
        },
        patch: q,
        perturbation,
    })
}

/// `E_u Q E_vᵀ - P` (control points of the difference surface at the degree of `P`).
pub(crate) fn elevated_minus(p: &TensorPatch, q: &TensorPatch) -> Result<Vec<f64>> {
    let ((m, n), (mq, nq)) = (p.degrees(), q.degrees());
    let e = q.elevate_u(m - mq)?.elevate_v(n - nq)?;
    Ok(e.points()
        .iter()
        .zip(p.points())
        .map(|(a, b)| a - b)
        .collect())
}

/// The certified convex-hull bound `max_ij ||P_ij - (E_u Q E_vᵀ)_ij||` of seed 000 §14.4.3
/// on the computed `Q` (`diff` = [`elevated_minus`]), plus an allowance for the rounding of the (convex) elevation and the
/// subtraction.
pub(crate) fn hull_bound(p: &TensorPatch, q: &TensorPatch, diff: &[f64]) -> f64 {
    let dim = p.dim();
    let (m, n) = p.degrees();
    let hull = max_norm(diff, dim);
    let slack = 2.0
        * (m + n + 6) as f64
        * f64::EPSILON
        * (max_norm(p.points(), dim) + max_norm(q.points(), dim));
    hull * (1.0 + 4.0 * f64::EPSILON) + slack
}

/// The free perturbation: projection (SPEC-reduce §4 closed form), two-sided inverse
/// elevation per column then per row; returns `Q` and the certified bound.
fn perturb_free(p: &TensorPatch) -> Result<(TensorPatch, f64)> {
    let ((m, n), dim) = (p.degrees(), p.dim());
    let (f, g) = p.degeneracy_invariants();
    let (hm, hn) = (binomial_f64(2 * m, m), binomial_f64(2 * n, n));
    let mut k = vec![0.0; dim];
    for j in 0..=n {
        let dj = sign_binomial_f64(n, j);
        for c in 0..dim {
            k[c] += dj * f[j * dim + c];
        }
    }
    let mut pbar = p.points().to_vec();
    for i in 0..=m {
        let ci = sign_binomial_f64(m, i);
        for j in 0..=n {
            let dj = sign_binomial_f64(n, j);
            let o = (i * (n + 1) + j) * dim;
            for c in 0..dim {
                pbar[o + c] += -ci * f[j * dim + c] / hm - dj * g[i * dim + c] / hn
                    + ci * dj * k[c] / (hm * hn);
            }
        }
    }
    let q = inverse_elevate_net(&pbar, (m, n), dim);
    let q = TensorPatch::new(q, m - 1, n - 1, dim)?;
    let fmax = max_norm(&f, dim);
    let gmax = max_norm(&g, dim);
    let spec = fmax / hm + gmax / hn + norm(&k) / (hm * hn);
    let eps_max = max_diff(&pbar, p.points(), dim);
    // Rounding of P + eps (see the module tests): the invariants cost (m+1) eps 2^m max|P|
    // per coordinate and |c_i| 2^m / H_m <= 2, so 8 (m + n + 4) eps max||P|| sqrt(dim) covers
    // every term; the inverse elevation's residual is measured.
    let allowance =
        8.0 * (m + n + 4) as f64 * f64::EPSILON * max_norm(p.points(), dim) * (dim as f64).sqrt();
    let e = q.elevate_u(1)?.elevate_v(1)?;
    let residual = max_diff(&pbar, e.points(), dim)
        + 2.0 * (m + n + 6) as f64 * f64::EPSILON * max_norm(q.points(), dim);
    let own = (spec.min(eps_max) + residual + 2.0 * allowance) * (1.0 + 4.0 * f64::EPSILON);
    Ok((q, own))
}

/// Inverse elevation of a degenerate `(m+1) x (n+1)` net: two-sided per column, then per row.
fn inverse_elevate_net(x: &[f64], (m, n): (usize, usize), dim: usize) -> Vec<f64> {
    let cols = map_columns(x, (m + 1, n + 1), dim, m, |a, b| {
        inverse_elevate(a, dim, b);
        Ok(())
    })
    .unwrap_or_default();
    map_rows(&cols, (m, n + 1), dim, n, |a, b| {
        inverse_elevate(a, dim, b);
        Ok(())
    })
    .unwrap_or_default()
}

/// Per degree `k`: columns `0` and `k - 1` of `(E_kᵀ E_k)^-1` (`k x 2`, row-major) and the
/// inverse of their `2 x 2` corner block (`E_k` = elevation `k - 1 -> k`).
#[derive(Debug)]
struct CornerData {
    g: Mat,
    s_inv: Mat,
}

fn corner_data(k: usize) -> Result<std::sync::Arc<CornerData>> {
    static CACHE: Cache<usize, CornerData> = std::sync::OnceLock::new();
    cached(&CACHE, k, || {
        let e = elevation_exact(k);
        let ginv = e.transpose().mul(&e)?.inverse()?;
        let last = k - 1;
        let pick = |i: usize, a: usize| {
            ginv.get(i, if a == 0 { 0 } else { last })
                .cloned()
                .unwrap_or_default()
        };
        let g = ExactMatrix::from_fn(k, 2, pick);
        let s = ExactMatrix::from_fn(2, 2, |a, b| pick(if a == 0 { 0 } else { last }, b));
        Ok(CornerData {
            g: Mat::round(&g),
            s_inv: Mat::round(&s.inverse()?),
        })
    })
}

/// Corner-constrained perturbation: `min sum ||eps||^2` s.t. degenerate and `eps = 0` at
/// the corners. With `M = E_v ⊗ E_u`: `q = q0 - (MᵀM)^-1 Cᵀ S^-1 (C q0 - P_corners)`,
/// `S = C (MᵀM)^-1 Cᵀ = S_v ⊗ S_u`.
fn perturb_corners(p: &TensorPatch) -> Result<(TensorPatch, f64)> {
    let ((m, n), dim) = (p.degrees(), p.dim());
    if m < 2 || n < 2 {
        return Err(Error::TooManyConstraints {
            r: 0,
            p: 0,
            m: m.min(n).saturating_sub(1),
            why: "keeping the four corners needs target degree >= 1 in u and v",
        });
    }
    let (q0, _) = perturb_free(p)?;
    let (cu, cv) = (corner_data(m)?, corner_data(n)?);
    let (mq, nq) = (m - 1, n - 1);
    let mut q = q0.points().to_vec();
    let qidx = |a: usize, b: usize| (a * mq * (nq + 1) + b * nq) * dim;
    let pidx = |a: usize, b: usize| (a * m * (n + 1) + b * n) * dim;
    // r_(a,b) = Q0 - P at the corners; mu = (S_u^-1 ⊗ S_v^-1) r.
    let mut mu = [[0.0; 2]; 2].map(|row| row.map(|_: f64| vec![0.0; dim]));
    for (a, mu_a) in mu.iter_mut().enumerate() {
        for (b, mu_ab) in mu_a.iter_mut().enumerate() {
            for a2 in 0..2 {
                for b2 in 0..2 {
                    let w = cu.s_inv.at(a, a2) * cv.s_inv.at(b, b2);
                    let (qi, pi) = (qidx(a2, b2), pidx(a2, b2));
                    for c in 0..dim {
                        mu_ab[c] += w * (q[qi + c] - p.points()[pi + c]);
                    }
                }
            }
        }
    }
    for i in 0..=mq {
        for j in 0..=nq {
            let o = (i * (nq + 1) + j) * dim;
            for (a, mu_a) in mu.iter().enumerate() {
                for (b, mu_ab) in mu_a.iter().enumerate() {
                    let w = cu.g.at(i, a) * cv.g.at(j, b);
                    for c in 0..dim {
                        q[o + c] -= w * mu_ab[c];
                    }
                }
            }
        }
    }
    // The corners equal P's up to rounding; store them exactly.
    for a in 0..2 {
        for b in 0..2 {
            let (qi, pi) = (qidx(a, b), pidx(a, b));
            q[qi..qi + dim].copy_from_slice(&p.points()[pi..pi + dim]);
        }
    }
    Ok((TensorPatch::new(q, mq, nq, dim)?, f64::INFINITY))
}

/// Exact pseudo-inverse of the interior columns `1..k-2` of `E_k` (elevation `k-1 -> k`),
/// `(k - 2) x (k + 1)`, cached per `k >= 3`.
fn interior_pinv(k: usize) -> Result<std::sync::Arc<Mat>> {
    static CACHE: Cache<usize, Mat> = std::sync::OnceLock::new();
    cached(&CACHE, k, || {
        let cols: Vec<usize> = (1..k - 1).collect();
        Ok(Mat::round(&pinv_columns(&elevation_exact(k), &cols)?))
    })
}

/// Checks that `method` can serve as the boundary reducer `k -> k - 1` with both ends kept.
pub(crate) fn check_boundary_method(method: Method, k: usize, target: usize) -> Result<()> {
    method.check(k, target)?;
    let (r, p) = method.end_orders(target);
    if r < 0 || p < 0 {
        return Err(Error::TooManyConstraints {
            r: i64::from(r),
            p: i64::from(p),
            m: target,
            why: "boundary constraints need a curve method that interpolates both end points",
        });
    }
    Ok(())
}

/// Boundary-constrained perturbation (see [`reduce_tensor`]).
fn perturb_boundary(p: &TensorPatch, method: Method) -> Result<(TensorPatch, f64)> {
    let ((m, n), dim) = (p.degrees(), p.dim());
    if m < 2 || n < 2 {
        return Err(Error::TooManyConstraints {
            r: 0,
            p: 0,
            m: m.min(n).saturating_sub(1),
            why: "boundary constraints need target degree >= 1 in u and v",
        });
    }
    check_boundary_method(method, m, m - 1)?;
    check_boundary_method(method, n, n - 1)?;
    let (mq, nq) = (m - 1, n - 1);
    let (op_u, op_v) = (operator(method, m, mq)?, operator(method, n, nq)?);
    let pts = p.points();
    let mut q = vec![0.0; (mq + 1) * (nq + 1) * dim];
    // Columns 0 and n-1 of Q from P's columns 0 and n.
    for (jp, jq) in [(0, 0), (n, nq)] {
        let col: Vec<f64> = (0..=m)
            .flat_map(|i| p.point(i, jp).iter().copied())
            .collect();
        let red = op_u.apply(&col, dim)?;
        for i in 0..=mq {
            let o = (i * (nq + 1) + jq) * dim;
            q[o..o + dim].copy_from_slice(&red[i * dim..(i + 1) * dim]);
        }
    }
    // Rows 0 and m-1 of Q from P's rows 0 and m (the corners agree: both methods keep ends).
    for (ip, iq) in [(0, 0), (m, mq)] {
        let row = &pts[ip * (n + 1) * dim..(ip + 1) * (n + 1) * dim];
        let o = iq * (nq + 1) * dim;
        op_v.apply_into(row, dim, &mut q[o..o + (nq + 1) * dim])?;
    }
    if mq >= 2 && nq >= 2 {
        // Residual R = P - E_u Q_B E_vᵀ (Q_B: boundary only), then X = Xu R Xvᵀ.
        let qb = TensorPatch::new(q.clone(), mq, nq, dim)?;
        let r: Vec<f64> = elevated_minus(p, &qb)?.iter().map(|x| -x).collect();
        let (xu, xv) = (interior_pinv(m)?, interior_pinv(n)?);
        let t = map_columns(&r, (m + 1, n + 1), dim, mq - 1, |a, b| {
            xu.apply(a, dim, b, false);
            Ok(())
        })?;
        let x = map_rows(&t, (mq - 1, n + 1), dim, nq - 1, |a, b| {
            xv.apply(a, dim, b, false);
            Ok(())
        })?;
        for i in 1..mq {
            for j in 1..nq {
                let o = (i * (nq + 1) + j) * dim;
                let s = ((i - 1) * (nq - 1) + (j - 1)) * dim;
                q[o..o + dim].copy_from_slice(&x[s..s + dim]);
            }
        }
    }
    Ok((TensorPatch::new(q, mq, nq, dim)?, f64::INFINITY))
}
