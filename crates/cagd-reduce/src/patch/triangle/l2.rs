//! L2-optimal multi-degree reduction of triangular patches (beyond seed 000 §14.3.2):
//! minimise `∫∫_T ||P - Q||^2 dA` over degree-`m` patches `Q`, optionally with the corners
//! or the boundary curves fixed ([`PatchConstraint`]).
//!
//! Gram matrices (ADDED): with `M(n; i, j) = n! / (i! j! (n-i-j)!)` and the Dirichlet
//! integral `∫_T u^a v^b w^c dA = a! b! c! / (a+b+c+2)!`,
//! `∫_T B^a_ij B^b_kl dA = M(a;i,j) M(b;k,l) (i+k)! (j+l)! (a-i-j+b-k-l)! / (a+b+2)!`.
//! With free unknowns `F` and fixed ones `C`: `G_FF q_F = G_Fn p - G_FC q_C`; the operators
//! `G_FF^-1 G_Fn` and `G_FF^-1 G_FC` are exact rationals rounded once, cached per
//! `(n, m, constraint kind)`.

use cagd_core::{Error, ExactMatrix, Result, TriPatch, tri_count, tri_index};
use num_bigint::BigInt;
use num_rational::BigRational;

use crate::operator;
use crate::patch::exact::{Cache, Mat, cached, q_binom};
use crate::patch::report::PatchConstraint;
use crate::patch::tensor::check_boundary_method;

/// The rounded operators of one `(n, m, kind)`.
#[derive(Debug)]
struct L2Op {
    free: Vec<usize>,
    fixed: Vec<usize>,
    lp: Mat,
    lc: Mat,
}

/// `(i, j)` of every storage index of a degree-`d` net.
fn indices(d: usize) -> Vec<(usize, usize)> {
    (0..=d)
        .flat_map(|i| (0..=d - i).map(move |j| (i, j)))
        .collect()
}

fn factorial(k: usize) -> BigInt {
    (1..=k).fold(BigInt::from(1), |acc, x| acc * BigInt::from(x))
}

/// `∫_T B^a_ij B^b_kl dA`, exact.
fn gram_entry(a: usize, (i, j): (usize, usize), b: usize, (k, l): (usize, usize)) -> BigRational {
    let num = factorial(i + k) * factorial(j + l) * factorial(a - i - j + b - k - l);
    q_binom(a, i)
        * q_binom(a - i, j)
        * q_binom(b, k)
        * q_binom(b - k, l)
        * BigRational::new(num, factorial(a + b + 2))
}

/// Storage indices of `Q` (degree `m`) fixed by the constraint kind (0 none, 1 corners,
/// 2 boundary).
fn fixed_set(m: usize, kind: u8) -> Vec<usize> {
    indices(m)
        .into_iter()
        .enumerate()
        .filter(|&(_, (a, b))| match kind {
            1 => (a == 0 && b == 0) || a == m || b == m,
            2 => a == 0 || b == 0 || a + b == m,
            _ => false,
        })
        .map(|(s, _)| s)
        .collect()
}

fn l2_operator(n: usize, m: usize, kind: u8) -> Result<std::sync::Arc<L2Op>> {
    static CACHE: Cache<(usize, usize, u8), L2Op> = std::sync::OnceLock::new();
    cached(&CACHE, (n, m, kind), || {
        let (iq, ip) = (indices(m), indices(n));
        let fixed = fixed_set(m, kind);
        let free: Vec<usize> = (0..iq.len()).filter(|s| !fixed.contains(s)).collect();
        if free.is_empty() {
            let empty = Mat::round(&ExactMatrix::zeros(0, 0));
            return Ok(L2Op {
                free,
                fixed,
                lp: empty.clone(),
                lc: empty,
            });
        }
        let gff = ExactMatrix::from_fn(free.len(), free.len(), |r, c| {
            gram_entry(m, iq[free[r]], m, iq[free[c]])
        });
        let gfn = ExactMatrix::from_fn(free.len(), ip.len(), |r, c| {
            gram_entry(m, iq[free[r]], n, ip[c])
        });
        let gfc = ExactMatrix::from_fn(free.len(), fixed.len(), |r, c| {
            gram_entry(m, iq[free[r]], m, iq[fixed[c]])
        });
        let inv = gff.inverse()?;
        Ok(L2Op {
            lp: Mat::round(&inv.mul(&gfn)?),
            lc: Mat::round(&inv.mul(&gfc)?),
            free,
            fixed,
        })
    })
}

/// The three boundary curves of a degree-`d` net as storage-index lists: `v = 0`
/// (`w`-corner to `u`-corner), `u = 0` (`w` to `v`), `w = 0` (`v` to `u`).
pub(crate) fn edge_indices(d: usize) -> [Vec<usize>; 3] {
    [
        (0..=d).map(|i| tri_index(d, i, 0)).collect(),
        (0..=d).map(|j| tri_index(d, 0, j)).collect(),
        (0..=d).map(|i| tri_index(d, i, d - i)).collect(),
    ]
}

/// The L2 reduction of `t` to degree `m` under `constraint`.
pub(crate) fn reduce_l2(t: &TriPatch, m: usize, constraint: PatchConstraint) -> Result<TriPatch> {
    let (n, dim) = (t.degree(), t.dim());
    let kind = match constraint {
        PatchConstraint::None => 0,
        PatchConstraint::Corners => 1,
        PatchConstraint::Boundary(_) => 2,
    };
    if kind > 0 && m == 0 {
        return Err(Error::TooManyConstraints {
            r: 0,
            p: 0,
            m,
            why: "corner or boundary constraints on a triangle need target degree >= 1",
        });
    }
    let mut q = vec![0.0; tri_count(m) * dim];
    let tp = t.points();
    let copy = |q: &mut [f64], dst: usize, src: &[f64]| {
        q[dst * dim..(dst + 1) * dim].copy_from_slice(src);
    };
    match constraint {
        PatchConstraint::None => {}
        PatchConstraint::Corners => {
            copy(&mut q, tri_index(m, 0, 0), t.point(0, 0));
            copy(&mut q, tri_index(m, m, 0), t.point(n, 0));
            copy(&mut q, tri_index(m, 0, m), t.point(0, n));
        }
        PatchConstraint::Boundary(method) => {
            check_boundary_method(method, n, m)?;
            let op = operator(method, n, m)?;
            for (ep, eq) in edge_indices(n).iter().zip(edge_indices(m).iter()) {
                let curve: Vec<f64> = ep
                    .iter()
                    .flat_map(|&s| tp[s * dim..(s + 1) * dim].iter().copied())
                    .collect();
                let red = op.apply(&curve, dim)?;
                for (k, &s) in eq.iter().enumerate() {
                    copy(&mut q, s, &red[k * dim..(k + 1) * dim]);
                }
            }
        }
    }
    let op = l2_operator(n, m, kind)?;
    if !op.free.is_empty() {
        let qc: Vec<f64> = op
            .fixed
            .iter()
            .flat_map(|&s| q[s * dim..(s + 1) * dim].iter().copied())
            .collect();
        let mut qf = vec![0.0; op.free.len() * dim];
        op.lp.apply(tp, dim, &mut qf, false);
        if !op.fixed.is_empty() {
            let mut corr = vec![0.0; op.free.len() * dim];
            op.lc.apply(&qc, dim, &mut corr, false);
            qf.iter_mut().zip(&corr).for_each(|(a, b)| *a -= b);
        }
        for (k, &s) in op.free.iter().enumerate() {
            copy(&mut q, s, &qf[k * dim..(k + 1) * dim]);
        }
    }
    TriPatch::new(q, m, dim)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gram_rows_sum_to_the_basis_integral() {
        // sum_kl B^b_kl = 1, so a Gram row sums to ∫_T B^a_ij dA = 1 / ((a + 1)(a + 2)).
        for (a, b) in [(3, 2), (4, 4), (5, 1)] {
            for ij in indices(a) {
                let s: BigRational = indices(b)
                    .into_iter()
                    .map(|kl| gram_entry(a, ij, b, kl))
                    .sum();
                assert_eq!(
                    s,
                    BigRational::new(1.into(), BigInt::from((a + 1) * (a + 2)))
                );
            }
        }
    }
}

#[cfg(test)]
mod optimality {
    use super::*;
    use num_traits::ToPrimitive;

    /// The L2 residual `P - Q` is orthogonal to every free basis function of degree `m`:
    /// `sum_ij ∫ B^n_ij B^m_kl (P - E Q)_ij = 0` (the normal equations), per coordinate.
    #[test]
    fn residual_is_orthogonal_to_the_free_basis() {
        let (n, m) = (6, 3);
        let pts: Vec<f64> = (0..tri_count(n))
            .map(|i| ((i * 31 % 13) as f64) - 6.0)
            .collect();
        let t = TriPatch::new(pts, n, 1).unwrap();
        for (kind, c) in [
            (0u8, PatchConstraint::None),
            (1, PatchConstraint::Corners),
            (
                2,
                PatchConstraint::Boundary(crate::Method::L2 { r: 0, p: 0 }),
            ),
        ] {
            let q = reduce_l2(&t, m, c).unwrap();
            let e = q.elevate(n - m).unwrap();
            let fixed = fixed_set(m, kind);
            for (s, kl) in indices(m).into_iter().enumerate() {
                if fixed.contains(&s) {
                    continue;
                }
                let dot: f64 = indices(n)
                    .into_iter()
                    .enumerate()
                    .map(|(r, ij)| {
                        gram_entry(n, ij, m, kl).to_f64().unwrap() * (t.points()[r] - e.points()[r])
                    })
                    .sum();
                assert!(dot.abs() < 1e-14, "kind {kind}, {kl:?}: {dot}");
            }
        }
    }
}
