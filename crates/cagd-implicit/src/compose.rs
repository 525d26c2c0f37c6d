//! Substitution of a parametric curve into an implicit polynomial, in the Bernstein basis:
//! `g(t) = W(t)^n f(X(t)/W(t), Y(t)/W(t)) = sum_{i+j<=n} c_ij X^i Y^j W^(n-i-j)`, a
//! polynomial of degree `n m` in `t`, with a coefficient-wise bound of its rounding error.
//! Products are convolutions of scaled Bernstein coefficients `a_k C(m, k)`.

use cagd_core::{binomial_f64, tri_index};

use crate::ImplicitPolynomial;

fn conv(a: &[f64], b: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        if *x == 0.0 {
            continue;
        }
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

/// Powers `0..=n` of a scaled Bernstein polynomial.
fn powers(base: &[f64], n: usize) -> Vec<Vec<f64>> {
    let mut out = vec![vec![1.0]];
    for i in 1..=n {
        let next = conv(&out[i - 1], base);
        out.push(next);
    }
    out
}

/// Bernstein coefficients of `g` (degree `n m`) and a bound of their absolute rounding
/// errors, for the implicit polynomial `f` (degree `n`) and homogeneous points `hom`
/// (degree `m`).
pub(crate) fn compose(f: &ImplicitPolynomial, hom: &[[f64; 3]]) -> (Vec<f64>, Vec<f64>) {
    let n = f.degree();
    let m = hom.len() - 1;
    let scaled =
        |k: usize| -> Vec<f64> { (0..=m).map(|i| hom[i][k] * binomial_f64(m, i)).collect() };
    let (xs, ys, ws) = (scaled(0), scaled(1), scaled(2));
    let abs = |v: &[f64]| -> Vec<f64> { v.iter().map(|x| x.abs()).collect() };
    let (xp, yp, wp) = (powers(&xs, n), powers(&ys, n), powers(&ws, n));
    let (xa, ya, wa) = (
        powers(&abs(&xs), n),
        powers(&abs(&ys), n),
        powers(&abs(&ws), n),
    );
    let total = n * m;
    let mut g = vec![0.0; total + 1];
    let mut bound = vec![0.0; total + 1];
    let coefs = f.coefficients();
    for i in 0..=n {
        for j in 0..=n - i {
            let c = coefs[tri_index(n, i, j)];
            if c == 0.0 {
                continue;
            }
            let term = conv(&conv(&xp[i], &yp[j]), &wp[n - i - j]);
            let tabs = conv(&conv(&xa[i], &ya[j]), &wa[n - i - j]);
            for k in 0..=total {
                g[k] += c * term[k];
                bound[k] += c.abs() * tabs[k];
            }
        }
    }
    // Each coefficient is a sum of products of about 2n + 3 rounded factors (the implicit
    // coefficient rounded once, the homogeneous points rounded once, the convolutions):
    // a relative error of (4 (n + 2) m + 16) ulp of the absolute sum is a safe bound.
    let gamma = (4.0 * (n as f64 + 2.0) * m as f64 + 16.0) * f64::EPSILON;
    for k in 0..=total {
        let b = binomial_f64(total, k);
        g[k] /= b;
        bound[k] = gamma * bound[k] / b;
    }
    (g, bound)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bernstein_roots::de_casteljau;
    use cagd_core::BezierCurve;

    #[test]
    fn composition_evaluates_f_on_the_curve() {
        let a =
            BezierCurve::new_rational(vec![1.0, 0.0, 1.0, 1.0, 0.0, 1.0], vec![1.0, 1.0, 2.0], 2)
                .unwrap();
        let f = crate::implicitize(&a).unwrap().polynomial;
        let b = BezierCurve::new_rational(
            vec![-1.0, 0.5, 0.0, 2.0, 1.5, 0.2, 2.0, -1.0],
            vec![1.0, 0.7, 1.3, 1.0],
            2,
        )
        .unwrap();
        let hom = crate::planar::homogeneous_f64(&b);
        let (g, e) = compose(&f, &hom);
        assert_eq!(g.len(), 7);
        for &t in &[0.0, 0.2, 0.5, 0.9, 1.0] {
            let (h, _) = crate::planar::hom_eval(&hom, t);
            let want = f.eval(h[0] / h[2], h[1] / h[2]) * h[2] * h[2];
            assert!((de_casteljau(&g, t) - want).abs() < 1e-13 * want.abs().max(1.0));
        }
        assert!(e.iter().all(|x| *x > 0.0 && *x < 1e-12));
    }
}
