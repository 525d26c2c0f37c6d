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

use num_bigint::BigInt;
use num_traits::Zero;

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
/// parametrization); the implicit polynomial is then `c g^k`. `hom` must be free of base
/// points. The minimum over three rational parameters `s0` is taken (a point with more
/// parameters than the generic count is a singular point, which a fixed small set of
/// parameters avoids for all but contrived curves).
pub(crate) fn parametrization_power(hom: &[[Q; 3]]) -> usize {
    let n = hom.len() - 1;
    let [x, y, w] = power_forms(hom);
    let mut best = n;
    for (a, b) in [(1, 3), (2, 7), (5, 11)] {
        let s0 = Q::new(BigInt::from(a), BigInt::from(b));
        let (xs, ys, ws) = (x.eval(&s0), y.eval(&s0), w.eval(&s0));
        if xs.is_zero() && ys.is_zero() && ws.is_zero() {
            continue;
        }
        // Minors of [X(t) Y(t) W(t); xs ys ws].
        let m1 = x.scale(&ws).sub(&w.scale(&xs));
        let m2 = y.scale(&ws).sub(&w.scale(&ys));
        let m3 = x.scale(&ys).sub(&y.scale(&xs));
        let g = m1.gcd(&m2).gcd(&m3);
        let top = [&m1, &m2, &m3]
            .iter()
            .filter_map(|p| p.degree())
            .max()
            .unwrap_or(0);
        let k = g.degree().unwrap_or(n) + (n - top.min(n));
        best = best.min(k.max(1));
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rational::q;

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
        assert_eq!(parametrization_power(&h), 1);
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
        assert_eq!(parametrization_power(&h), 2);
    }

    #[test]
    fn constant_curve_is_all_base_points() {
        let h = hom(&[(1.0, 1.0), (1.0, 1.0), (1.0, 1.0)], &[1.0, 2.0, 1.0]);
        assert_eq!(base_point_count(&h), 2);
        assert!(divide_out(&h).is_none());
    }
}
