//! Perturbation reduction with G1 end constraints and *optimal* `l1, l2` (seed 000 §14.2.3,
//! eq. 14.2.12; SPEC-reduce §2.3). Not linear in the control points, hence a plain function.

use cagd_core::{BezierCurve, Error, Result, binomial, sign_binomial_f64};

use super::method::Method;
use super::operator::hull_bound;
use super::reduce::{ReduceOptions, Reduction, finish};

/// Reduces `curve` (degree `n >= 4`) to degree `n - 1` keeping both end points and the end
/// tangent directions (G1), with `l1, l2` chosen to minimise the same objective as the
/// perturbation itself, `sum_{i=1}^{n-1} ||eps_i||^2` (SPEC-reduce §2.3):
/// `M = S I + n^2 (d1 d1^T / ||d1||^2 + d2 d2^T / ||d2||^2)`, `lambda = 2 M^{-1} F`,
/// `eps_i = -c_i lambda / 2` (`i = 2..n-2`), `l1 = -c_1 (d1 . lambda) / (2 ||d1||^2)`,
/// `l2 = -c_{n-1} (d2 . lambda) / (2 ||d2||^2)`, then the two-sided inverse elevation.
/// A zero end tangent (`d = 0`) leaves that `l` at `0`.
///
/// The report's `method` is [`Method::PerturbG1`] with the optimal `l1, l2`; the bound is the
/// convex-hull bound (in exact arithmetic `max_i ||eps_i||`). Rational curves are reduced in
/// homogeneous space as in [`crate::reduce_with`]. If the optimal `l` violates `1 + l > 0`
/// the tangent direction flips; this is reported as [`Error::ConditionNotMet`].
///
/// # Errors
/// [`Error::BadDegreePair`] for `n < 4`; [`Error::ConditionNotMet`] (eq. "14.2.12") when an
/// optimal `l` gives `1 + l <= 0`; [`Error::NonPositiveWeight`] for rational curves whose
/// reduced weights are not positive.
pub fn reduce_g1_optimal(curve: &BezierCurve, measure: bool) -> Result<Reduction> {
    let n = curve.degree();
    if n < 4 {
        return Err(Error::BadDegreePair {
            from: n,
            to: n.saturating_sub(1),
            why: "the G1 perturbation needs a source degree >= 4",
        });
    }
    let opts = ReduceOptions {
        measure,
        ..ReduceOptions::new(Method::PerturbG1 { l1: 0.0, l2: 0.0 }, n - 1)
    };
    finish(curve, &opts, |pts, dim| {
        let (q, l1, l2) = g1_optimal_points(pts, dim);
        for l in [l1, l2] {
            if l.is_nan() || 1.0 + l <= 0.0 {
                return Err(Error::ConditionNotMet {
                    eq: "14.2.12",
                    why: "the optimal l gives 1 + l <= 0 (tangent direction would flip)",
                });
            }
        }
        let bound = hull_bound(pts, &q, dim);
        Ok((q, Some(bound), Method::PerturbG1 { l1, l2 }))
    })
}

/// The optimal G1 perturbation in `f64`; returns `(Q, l1, l2)`.
pub(crate) fn g1_optimal_points(p: &[f64], d: usize) -> (Vec<f64>, f64, f64) {
    let n = p.len() / d - 1;
    let nf = n as f64;
    let pt = |i: usize| &p[i * d..(i + 1) * d];
    let mut f = vec![0.0; d];
    for i in 0..=n {
        let c = sign_binomial_f64(n, i);
        for (fk, x) in f.iter_mut().zip(pt(i)) {
            *fk += c * x;
        }
    }
    let d1: Vec<f64> = pt(1).iter().zip(pt(0)).map(|(a, b)| a - b).collect();
    let d2: Vec<f64> = pt(n - 1).iter().zip(pt(n)).map(|(a, b)| a - b).collect();
    let s = (binomial(2 * n, n) - 2 - 2 * (n as u128) * (n as u128)) as f64;
    // M = S I + n^2 (u1 u1^T + u2 u2^T), u = d / ||d||.
    let mut mat = vec![0.0; d * d];
    for i in 0..d {
        mat[i * d + i] = s;
    }
    for dv in [&d1, &d2] {
        let nn: f64 = dv.iter().map(|x| x * x).sum();
        if nn > 0.0 {
            for i in 0..d {
                for j in 0..d {
                    mat[i * d + j] += nf * nf * dv[i] * dv[j] / nn;
                }
            }
        }
    }
    let rhs: Vec<f64> = f.iter().map(|x| 2.0 * x).collect();
    let lambda = solve_spd(&mut mat, rhs, d);
    let l_of = |dv: &[f64], c: f64| {
        let nn: f64 = dv.iter().map(|x| x * x).sum();
        if nn > 0.0 {
            -c * dv.iter().zip(&lambda).map(|(a, b)| a * b).sum::<f64>() / (2.0 * nn)
        } else {
            0.0
        }
    };
    let l1 = l_of(&d1, sign_binomial_f64(n, 1));
    let l2 = l_of(&d2, sign_binomial_f64(n, n - 1));
    let mut pbar = p.to_vec();
    for k in 0..d {
        pbar[d + k] += l1 * d1[k];
        pbar[(n - 1) * d + k] += l2 * d2[k];
    }
    for i in 2..n - 1 {
        let c = sign_binomial_f64(n, i);
        for k in 0..d {
            pbar[i * d + k] -= c * lambda[k] / 2.0;
        }
    }
    (two_sided_inverse(&pbar, d), l1, l2)
}

/// Inverse elevation of a (nearly) degenerate degree-`n` polygon, two-sided (SPEC-reduce
/// §2.1 numerics): forward recursion of eq. 14.2.3 for `i <= floor((n-1)/2)`, backward for
/// the rest.
pub(crate) fn two_sided_inverse(pbar: &[f64], d: usize) -> Vec<f64> {
    let n = pbar.len() / d - 1;
    let nf = n as f64;
    let mut q = vec![0.0; n * d];
    let h = (n - 1) / 2;
    q[..d].copy_from_slice(&pbar[..d]);
    for i in 1..=h {
        for k in 0..d {
            q[i * d + k] = (nf * pbar[i * d + k] - i as f64 * q[(i - 1) * d + k]) / (nf - i as f64);
        }
    }
    if h + 1 < n {
        q[(n - 1) * d..].copy_from_slice(&pbar[n * d..]);
        for i in (h + 2..n).rev() {
            for k in 0..d {
                q[(i - 1) * d + k] =
                    (nf * pbar[i * d + k] - (nf - i as f64) * q[i * d + k]) / i as f64;
            }
        }
    }
    q
}

/// Solves the small SPD system `mat x = rhs` (Cholesky-free Gaussian elimination; the matrix
/// is `S I + ...` with `S > 0` dominant, so no pivoting is needed).
fn solve_spd(mat: &mut [f64], mut rhs: Vec<f64>, d: usize) -> Vec<f64> {
    for c in 0..d {
        let piv = mat[c * d + c];
        for r in c + 1..d {
            let f = mat[r * d + c] / piv;
            for j in c..d {
                mat[r * d + j] -= f * mat[c * d + j];
            }
            rhs[r] -= f * rhs[c];
        }
    }
    let mut x = vec![0.0; d];
    for c in (0..d).rev() {
        let s: f64 = (c + 1..d).map(|j| mat[c * d + j] * x[j]).sum();
        x[c] = (rhs[c] - s) / mat[c * d + c];
    }
    x
}
