//! Base points and improper parametrizations (SPEC-convert §15.8 end; seed 002 §15.8 last
//! paragraph).
//!
//! A base point is a parameter `τ` (real outside `[0, 1]`, complex, or `∞`) with
//! `X(τ) = Y(τ) = W(τ) = 0`; then `det F ≡ 0`. As binary forms of degree `n`, X, Y, W share
//! the factor `g(t) = gcd(X, Y, W)` and, when all three have degree `< n` (a curve given
//! in a degree-elevated form), powers of the factor at `t = ∞`. Dividing out both lowers
//! the degree to `m = n - deg g - e` and leaves the same point set.
//!
//! A parametrization that traces its curve `k > 1` times (e.g. collinear control points)
//! gives `f = c g^k` with `g` the irreducible implicit polynomial of degree `n / k`
//! (`f = -(x - y)^2` for a collinear quadratic). `k` is the number of parameters of a
//! generic curve point: the degree of `gcd_t` of the 2 x 2 minors of `[P(t); P(s0)]`.

use cagd_core::binomial;

use crate::exact::IntHom;
use crate::modular::{Digits, Modulus, poly_degree, poly_gcd, primes};
use crate::rational::{Q, UPoly};

/// The power-basis polynomials X(t), Y(t), W(t) of homogeneous Bernstein points.
fn power_forms(hom: &[[Q; 3]]) -> [UPoly; 3] {
    [0, 1, 2].map(|k| {
        let c: Vec<Q> = hom.iter().map(|p| p[k].clone()).collect();
        UPoly::from_bernstein(&c)
    })
}

/// The common factor of X, Y, W: `(g, e)` with `g = gcd(X, Y, W)` (monic) and `e` base
/// points at `t = ∞`. The number of base points is `deg g + e`.
fn common_factor(hom: &[[Q; 3]]) -> (UPoly, usize) {
    let n = hom.len() - 1;
    let forms = power_forms(hom);
    let g = forms[0].gcd(&forms[1]).gcd(&forms[2]);
    let top = forms.iter().filter_map(UPoly::degree).max();
    let e = top.map_or(n, |d| n - d);
    (g, e)
}

/// The number of base points (0 for a curve whose `det F` is not identically 0).
pub(crate) fn base_point_count(hom: &[[Q; 3]]) -> usize {
    let (g, e) = common_factor(hom);
    // A zero gcd means X = Y = W = 0: every parameter is a base point.
    g.degree().unwrap_or(hom.len() - 1) + e
}

/// The homogeneous Bernstein points of degree `m = n - base_point_count` of the curve with
/// its base points divided out (`X/g, Y/g, W/g`, elevated by nothing, reduced by `e`).
/// `None` when nothing is left (`m = 0`: the curve is a single point).
pub(crate) fn divide_out(hom: &[[Q; 3]]) -> Option<Vec<[Q; 3]>> {
    let n = hom.len() - 1;
    let (g, e) = common_factor(hom);
    let dg = g.degree()?;
    let m = n.checked_sub(dg + e).filter(|&m| m > 0)?;
    let forms = power_forms(hom);
    let reduced: Vec<Vec<Q>> = forms
        .iter()
        .map(|f| f.div_rem(&g).0.to_bernstein(m))
        .collect();
    Some(
        (0..=m)
            .map(|i| {
                [
                    reduced[0][i].clone(),
                    reduced[1][i].clone(),
                    reduced[2][i].clone(),
                ]
            })
            .collect(),
    )
}

/// The number `k` of parameters of a generic curve point (1 for a proper
/// parametrization); the implicit polynomial is then `c g^k`. `h` must be free of base
/// points. `k` is the degree of `gcd_t` of the 2 x 2 minors of `[P(t); P(s0)]` (plus the
/// roots at `t = ∞`), computed modulo two 31-bit primes for `s0 = 2, 5, 11`; the minimum is
/// taken (a special `s0` — a singular point — or an unlucky prime can only raise it).
pub(crate) fn parametrization_power(h: &IntHom) -> usize {
    let n = h.degree();
    let mut best = n;
    for &p in &primes()[..2] {
        let forms: Vec<Vec<u64>> = (0..3)
            .map(|k| {
                let c: Vec<u64> = h
                    .pts
                    .iter()
                    .map(|pt| Digits::new(&pt[k]).residue(Modulus::new(p)))
                    .collect();
                bernstein_to_power_mod(&c, p)
            })
            .collect();
        let eval = |f: &[u64], s: u64| f.iter().rev().fold(0u64, |acc, &c| (acc * s + c) % p);
        for s0 in [2u64, 5, 11] {
            let (xs, ys, ws) = (
                eval(&forms[0], s0),
                eval(&forms[1], s0),
                eval(&forms[2], s0),
            );
            if xs == 0 && ys == 0 && ws == 0 {
                continue;
            }
            let minor = |f: &[u64], fa: u64, g: &[u64], ga: u64| -> Vec<u64> {
                f.iter()
                    .zip(g)
                    .map(|(&a, &b)| (a * fa % p + p - b * ga % p) % p)
                    .collect()
            };
            let m1 = minor(&forms[0], ws, &forms[2], xs);
            let m2 = minor(&forms[1], ws, &forms[2], ys);
            let m3 = minor(&forms[0], ys, &forms[1], xs);
            let Some(top) = [&m1, &m2, &m3].iter().filter_map(|m| poly_degree(m)).max() else {
                continue;
            };
            let g = poly_gcd(&poly_gcd(&m1, &m2, p), &m3, p);
            let k = poly_degree(&g).unwrap_or(0) + (n - top);
            best = best.min(k.max(1));
        }
    }
    best
}

/// Power-basis coefficients mod `p` of the Bernstein polynomial with coefficients `c`.
fn bernstein_to_power_mod(c: &[u64], p: u64) -> Vec<u64> {
    let n = c.len() - 1;
    let b = |n: usize, k: usize| u64::try_from(binomial(n, k) % u128::from(p)).unwrap_or(0);
    let mut out = vec![0u64; n + 1];
    for (i, &ci) in c.iter().enumerate() {
        let base = ci * b(n, i) % p;
        for (k, slot) in out.iter_mut().enumerate().skip(i) {
            let t = base * b(n - i, k - i) % p;
            *slot = if (k - i) % 2 == 0 {
                (*slot + t) % p
            } else {
                (*slot + p - t) % p
            };
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rational::q;
    use num_bigint::BigInt;

    fn hom(points: &[(f64, f64)], w: &[f64]) -> Vec<[Q; 3]> {
        points
            .iter()
            .zip(w)
            .map(|(&(x, y), &w)| [q(w) * q(x), q(w) * q(y), q(w)])
            .collect()
    }

    #[test]
    fn proper_curves_have_no_base_points() {
        let h = hom(&[(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)], &[1.0; 3]);
        assert_eq!(base_point_count(&h), 0);
        assert_eq!(parametrization_power(&IntHom::from_rational(&h)), 1);
    }

    #[test]
    fn degree_elevated_curve_has_a_base_point_at_infinity() {
        // The parabola above elevated to degree 3.
        let h = hom(
            &[
                (0.0, 0.0),
                (2.0 / 3.0, 4.0 / 3.0),
                (4.0 / 3.0, 4.0 / 3.0),
                (2.0, 0.0),
            ],
            &[1.0; 4],
        );
        // 2/3 and 4/3 are not binary fractions; use exact values instead.
        let third = |a: i64| Q::new(BigInt::from(a), BigInt::from(3));
        let mut h = h;
        h[1] = [third(2), third(4), q(1.0)];
        h[2] = [third(4), third(4), q(1.0)];
        assert_eq!(base_point_count(&h), 1);
        let r = divide_out(&h).unwrap();
        assert_eq!(r, hom(&[(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)], &[1.0; 3]));
    }

    #[test]
    fn collinear_quadratic_is_traced_twice() {
        let h = hom(&[(0.0, 0.0), (2.0, 2.0), (1.0, 1.0)], &[1.0; 3]);
        assert_eq!(base_point_count(&h), 0);
        assert_eq!(parametrization_power(&IntHom::from_rational(&h)), 2);
    }

    #[test]
    fn constant_curve_is_all_base_points() {
        let h = hom(&[(1.0, 1.0), (1.0, 1.0), (1.0, 1.0)], &[1.0, 2.0, 1.0]);
        assert_eq!(base_point_count(&h), 2);
        assert!(divide_out(&h).is_none());
    }
}
