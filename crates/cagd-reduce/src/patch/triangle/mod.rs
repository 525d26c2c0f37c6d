//! Triangular patch reduction: the entry point [`reduce_triangle`] and the control-point
//! perturbation `n -> n - 1` of seed 000 §14.3.2 (eqs. 14.3.8-14.3.16, Algorithm 14.3.2
//! with the corrections of SPEC-reduce §5).

use cagd_core::{
    Error, ExactMatrix, Result, TriPatch, binomial_f64, tri_count, tri_index, tri_patch_distance,
};

mod l2;

use crate::patch::exact::{Cache, Mat, cached, max_norm, q_binom};
use crate::patch::report::{PatchReport, TriMethod, TriOptions, TriReduction};
use l2::reduce_l2;

/// Reduces a triangular patch of degree `n` to degree `m < n`.
///
/// * [`TriMethod::Perturb`] (`m = n - 1`, `n >= 1`): seed 000 §14.3.2. Minimises
///   `sum ||eps_ij||^2` (control points) subject to `F_k(T + eps) = 0`, `k = 0..=n`
///   (eq. 14.1.3): `B lambda = 2 F` (eq. 14.3.16) with the closed form
///   `B_km = C(k+m, k) C(2n-k-m, n-k)` inverted exactly (cached per `n`),
///   `eps_ij = -1/2 sum_{k=i}^{n-j} (-1)^(n-i-j) C(k,i) C(n-k,j) lambda_k` (eq. 14.3.11),
///   then the inverse of the triangular elevation (Algorithm 14.3.2) computed three-sided:
///   every `Q_ab` from the corner whose barycentric coordinate is largest (the triangular
///   analogue of SPEC-reduce §2.1's two-sided recursion; all recursion factors `<= 1`).
/// * [`TriMethod::L2`]: minimises `∫∫_T ||P - Q||^2 dA` (any `m < n`), optionally with the
///   corners kept or the boundary curves fixed to their curve reductions
///   ([`crate::PatchConstraint`]); exact Gram matrices of triangular Bernstein polynomials
///   (`∫_T B^n_ij B^m_kl dA` by the Dirichlet integral `∫_T u^a v^b w^c = a! b! c! /
///   (a+b+c+2)!`), solved in rationals, rounded once and cached per `(n, m, constraint)`.
///
/// Certified bound: `max_ij ||T_ij - (E Q)_ij||` (convex hull, `E` = elevation `m -> n`;
/// for `Perturb` this is `max ||eps_ij||`, SPEC-reduce §5) plus a rounding allowance.
/// Degrees up to 64 (the bound stays certified at every degree: it is measured on the
/// computed `Q`). Accuracy of `Perturb`, measured as the round trip of an exactly elevated
/// net (coordinates ~1): 8e-16 (n = 6), 2e-14 (10), 2e-13 (14), 4e-12 (20), 1e-8 (30) —
/// the invariants `F_k` are alternating sums with binomial weights, so prefer `L2` above
/// n ~ 20. `L2` builds exact operators of size `tri_count(m)^2` once per `(n, m,
/// constraint)` (16 -> 12: 0.6 s in a debug build), then costs one matrix product.
///
/// # Errors
/// [`Error::BadDegreePair`] (`m >= n`, or `m != n - 1` for `Perturb`),
/// [`Error::TooManyConstraints`] (corner / boundary constraints with `m = 0`, a boundary
/// method that does not keep the end points), the curve methods' errors.
///
/// ```
/// use cagd_core::TriPatch;
/// use cagd_reduce::{Method, PatchConstraint, TriMethod, TriOptions, reduce_triangle};
/// let t = TriPatch::new(vec![0.0, 2.0, 1.0], 1, 1)?.elevate(3)?; // u + 2v at degree 4
/// let opts = TriOptions::new(TriMethod::L2(PatchConstraint::Boundary(Method::L2 { r: 0, p: 0 })));
/// let red = reduce_triangle(&t, 2, &opts)?;
/// assert!(red.report.error_bound < 1e-13);
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn reduce_triangle(t: &TriPatch, m: usize, opts: &TriOptions) -> Result<TriReduction> {
    let n = t.degree();
    if m >= n {
        return Err(Error::BadDegreePair {
            from: n,
            to: m,
            why: "the target degree must be below the source degree",
        });
    }
    let (q, multipliers) = match opts.method {
        TriMethod::Perturb => {
            if m + 1 != n {
                return Err(Error::BadDegreePair {
                    from: n,
                    to: m,
                    why: "the triangular perturbation reduces n to n - 1",
                });
            }
            let (q, lambda) = perturb(t)?;
            (q, Some(lambda))
        }
        TriMethod::L2(c) => (reduce_l2(t, m, c)?, None),
    };
    let (perturbation, bound) = tri_hull(t, &q)?;
    let max_error = if opts.measure {
        Some(tri_patch_distance(t, &q)?)
    } else {
        None
    };
    Ok(TriReduction {
        report: PatchReport {
            method: opts.method.name(),
            degrees_from: (n, n),
            degrees_to: (m, m),
            error_bound: bound,
            max_error,
        },
        patch: q,
        perturbation,
        multipliers,
    })
}

/// `Elevate(Q) - T` and the certified convex-hull bound `max ||.||` + rounding allowance.
pub(crate) fn tri_hull(t: &TriPatch, q: &TriPatch) -> Result<(Vec<f64>, f64)> {
    let dim = t.dim();
    let e = q.elevate(t.degree() - q.degree())?;
    let d: Vec<f64> = e
        .points()
        .iter()
        .zip(t.points())
        .map(|(a, b)| a - b)
        .collect();
    let slack = 2.0
        * (t.degree() + 6) as f64
        * f64::EPSILON
        * (max_norm(t.points(), dim) + max_norm(q.points(), dim));
    let bound = max_norm(&d, dim) * (1.0 + 4.0 * f64::EPSILON) + slack;
    Ok((d, bound))
}

/// The exact `B` of eq. 14.3.16 by the closed form `B_km = C(k+m,k) C(2n-k-m, n-k)`.
fn b_exact(n: usize) -> ExactMatrix {
    ExactMatrix::from_fn(n + 1, n + 1, |k, m| {
        q_binom(k + m, k) * q_binom(2 * n - k - m, n - k)
    })
}

/// The matrix `B` of seed 000 eq. 14.3.16 (SPEC-reduce §5 erratum `B_kn -> B_km`), closed
/// form `B_km = C(k+m, k) C(2n-k-m, n-k)`, `(n+1) x (n+1)` row-major (exact integers as
/// `f64`; exact for `n <= 26`, rounded once beyond).
pub fn tri_perturbation_matrix(n: usize) -> Vec<f64> {
    Mat::round(&b_exact(n)).data
}

/// `B^-1`, exact, rounded once, cached per `n`.
fn b_inverse(n: usize) -> Result<std::sync::Arc<Mat>> {
    static CACHE: Cache<usize, Mat> = std::sync::OnceLock::new();
    cached(&CACHE, n, || Ok(Mat::round(&b_exact(n).inverse()?)))
}

/// The perturbation of §14.3.2: `(Q, lambda)`.
fn perturb(t: &TriPatch) -> Result<(TriPatch, Vec<f64>)> {
    let (n, dim) = (t.degree(), t.dim());
    let f = t.degeneracy_invariants();
    let binv = b_inverse(n)?;
    let mut lambda = vec![0.0; (n + 1) * dim];
    binv.apply(&f, dim, &mut lambda, false);
    lambda.iter_mut().for_each(|x| *x *= 2.0);
    let mut tbar = t.points().to_vec();
    for i in 0..=n {
        for j in 0..=n - i {
            let o = tri_index(n, i, j) * dim;
            let sign = if (n - i - j) % 2 == 0 { -0.5 } else { 0.5 };
            for k in i..=n - j {
                let c = sign * binomial_f64(k, i) * binomial_f64(n - k, j);
                for d in 0..dim {
                    tbar[o + d] += c * lambda[k * dim + d];
                }
            }
        }
    }
    let q = inverse_elevate_tri(&tbar, n, dim);
    Ok((TriPatch::new(q, n - 1, dim)?, lambda))
}

/// Inverse of the triangular elevation `n - 1 -> n` (`Tbar_ij = (i Q_{i-1,j} + j Q_{i,j-1} +
/// k Q_ij) / n`) for a degenerate net `x`, three-sided: with `(a, b, c)` the barycentric
/// indices of `Q_ab` (`c = n - 1 - a - b`), points with `c` largest come from the forward
/// recursion of Algorithm 14.3.2, points with `a` (resp. `b`) largest from the recursion
/// anchored at the `u` (resp. `v`) corner. Each region is closed under its recursion's
/// dependencies, and every factor is `<= 1` in magnitude relative to the pivot.
pub(crate) fn inverse_elevate_tri(x: &[f64], n: usize, dim: usize) -> Vec<f64> {
    let d = n - 1;
    let nf = n as f64;
    let mut q = vec![0.0; tri_count(d) * dim];
    let xi = |a: usize, b: usize| tri_index(n, a, b) * dim;
    let qi = |a: usize, b: usize| tri_index(d, a, b) * dim;
    // w region: c >= a, c >= b; lexicographic.
    for a in 0..=d {
        for b in 0..=d - a {
            let c = d - a - b;
            if c < a || c < b {
                continue;
            }
            for k in 0..dim {
                let mut s = nf * x[xi(a, b) + k];
                if a > 0 {
                    s -= a as f64 * q[qi(a - 1, b) + k];
                }
                if b > 0 {
                    s -= b as f64 * q[qi(a, b - 1) + k];
                }
                q[qi(a, b) + k] = s / (c + 1) as f64;
            }
        }
    }
    // u region: a > c, a >= b; a descending.
    for a in (0..=d).rev() {
        for b in 0..=d - a {
            let c = d - a - b;
            if !(a > c && a >= b) {
                continue;
            }
            for k in 0..dim {
                let mut s = nf * x[xi(a + 1, b) + k];
                if b > 0 {
                    s -= b as f64 * q[qi(a + 1, b - 1) + k];
                }
                if c > 0 {
                    s -= c as f64 * q[qi(a + 1, b) + k];
                }
                q[qi(a, b) + k] = s / (a + 1) as f64;
            }
        }
    }
    // v region: b > c, b > a; b descending.
    for b in (0..=d).rev() {
        for a in 0..=d - b {
            let c = d - a - b;
            if !(b > c && b > a) {
                continue;
            }
            for k in 0..dim {
                let mut s = nf * x[xi(a, b + 1) + k];
                if a > 0 {
                    s -= a as f64 * q[qi(a - 1, b + 1) + k];
                }
                if c > 0 {
                    s -= c as f64 * q[qi(a, b + 1) + k];
                }
                q[qi(a, b) + k] = s / (b + 1) as f64;
            }
        }
    }
    q
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn three_sided_inverse_undoes_elevation() {
        for n in 1..16 {
            let cnt = tri_count(n);
            let pts: Vec<f64> = (0..cnt * 2).map(|i| ((i * 37 % 11) as f64) - 5.0).collect();
            let t = TriPatch::new(pts, n, 2).unwrap();
            let e = t.elevate(1).unwrap();
            let back = inverse_elevate_tri(e.points(), n + 1, 2);
            let err = crate::patch::exact::max_diff(&back, t.points(), 2);
            assert!(err < 1e-13, "n = {n}: {err}");
        }
    }

    #[test]
    fn b_closed_form_matches_the_double_sum() {
        // eq. 14.3.15: B_km = sum_{i<=min(k,m)} sum_{j<=n-max(k,m)} C(k,i)C(m,i)C(n-k,j)C(n-m,j).
        for n in 1..8 {
            let b = tri_perturbation_matrix(n);
            for k in 0..=n {
                for m in 0..=n {
                    let mut s = 0.0;
                    for i in 0..=k.min(m) {
                        for j in 0..=n - k.max(m) {
                            s += binomial_f64(k, i)
                                * binomial_f64(m, i)
                                * binomial_f64(n - k, j)
                                * binomial_f64(n - m, j);
                        }
                    }
                    assert_eq!(b[k * (n + 1) + m], s);
                }
            }
        }
    }
}
