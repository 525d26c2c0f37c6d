//! The implicit polynomial `f(x, y) = sum_{i+j<=n} c_ij x^i y^j` of total degree `n`
//! (SPEC-convert §15.8, eq. 15.8.5): exact coefficients and the same coefficients rounded
//! once to `f64`, evaluation (Horner), gradient and the absolute-value sum used for scaled
//! residuals.

use cagd_core::{tri_count, tri_index};
use num_traits::{ToPrimitive, Zero};

use crate::rational::Q;

/// An implicit polynomial in the monomial basis, coefficients indexed i-major
/// (`x^i y^j` at `tri_index(n, i, j)`), exact and rounded once to `f64`.
#[derive(Debug, Clone, PartialEq)]
pub struct ImplicitPolynomial {
    degree: usize,
    coefs: Vec<f64>,
    exact: Vec<Q>,
}

/// A rational rounded to the nearest `f64` (big numerators are reduced by `to_f64` of the
/// quotient, which num-rational computes correctly rounded for exact binary fractions and
/// to within an ulp otherwise).
pub(crate) fn round(x: &Q) -> f64 {
    x.to_f64().unwrap_or(f64::NAN)
}

impl ImplicitPolynomial {
    /// From exact coefficients (i-major triangle of total degree `degree`).
    pub(crate) fn from_exact(degree: usize, exact: Vec<Q>) -> Self {
        debug_assert_eq!(exact.len(), tri_count(degree));
        let coefs = exact.iter().map(round).collect();
        ImplicitPolynomial {
            degree,
            coefs,
            exact,
        }
    }

    /// The total degree `n` of the representation (the curve degree).
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The highest total degree with a non-zero coefficient (`None` for the zero polynomial).
    pub fn effective_degree(&self) -> Option<usize> {
        self.monomials_exact().iter().map(|(i, j, _)| i + j).max()
    }

    /// The `f64` coefficient of `x^i y^j` (0 when `i + j > n`).
    pub fn coef(&self, i: usize, j: usize) -> f64 {
        if i + j > self.degree {
            0.0
        } else {
            self.coefs[tri_index(self.degree, i, j)]
        }
    }

    /// The exact coefficient of `x^i y^j` (`None` when `i + j > n`).
    pub fn exact_coef(&self, i: usize, j: usize) -> Option<&Q> {
        (i + j <= self.degree).then(|| &self.exact[tri_index(self.degree, i, j)])
    }

    /// All `f64` coefficients, i-major triangle.
    pub fn coefficients(&self) -> &[f64] {
        &self.coefs
    }

    /// The non-zero monomials `(i, j, c)` meaning `c x^i y^j`, in decreasing total degree,
    /// then decreasing `i` (the order does not matter to the spec's comparison).
    pub fn monomials(&self) -> Vec<(usize, usize, f64)> {
        self.monomials_exact()
            .into_iter()
            .map(|(i, j, c)| (i, j, round(c)))
            .collect()
    }

    /// The non-zero exact monomials `(i, j, c)`, same order as [`Self::monomials`].
    pub fn monomials_exact(&self) -> Vec<(usize, usize, &Q)> {
        let n = self.degree;
        let mut out = Vec::new();
        for total in (0..=n).rev() {
            for i in (0..=total).rev() {
                let c = &self.exact[tri_index(n, i, total - i)];
                if !c.is_zero() {
                    out.push((i, total - i, c));
                }
            }
        }
        out
    }

    /// The exact coefficients as decimal fraction strings `"p/q"` (or `"p"`).
    pub fn exact_strings(&self) -> Vec<(usize, usize, String)> {
        self.monomials_exact()
            .into_iter()
            .map(|(i, j, c)| (i, j, c.to_string()))
            .collect()
    }

    /// `max |c_ij|` of the `f64` coefficients.
    pub fn max_abs_coef(&self) -> f64 {
        self.coefs.iter().fold(0.0, |m, c| m.max(c.abs()))
    }

    /// `f(x, y)` by Horner in `y` then in `x` (`f64` coefficients).
    pub fn eval(&self, x: f64, y: f64) -> f64 {
        self.eval_grad(x, y).0
    }

    /// `sum |c_ij x^i y^j|`: the scale of `f(x, y)` for a relative residual.
    pub fn eval_abs(&self, x: f64, y: f64) -> f64 {
        let n = self.degree;
        let (ax, ay) = (x.abs(), y.abs());
        let mut acc = 0.0;
        for i in (0..=n).rev() {
            let mut p = 0.0;
            for j in (0..=n - i).rev() {
                p = p * ay + self.coefs[tri_index(n, i, j)].abs();
            }
            acc = acc * ax + p;
        }
        acc
    }

    /// `(f, ∂f/∂x, ∂f/∂y)` at `(x, y)` (Horner with derivatives, no allocation).
    pub fn eval_grad(&self, x: f64, y: f64) -> (f64, f64, f64) {
        let n = self.degree;
        let (mut f, mut fx, mut fy) = (0.0, 0.0, 0.0);
        for i in (0..=n).rev() {
            // p_i(y) = sum_j c_ij y^j and its derivative.
            let (mut p, mut dp) = (0.0, 0.0);
            for j in (0..=n - i).rev() {
                dp = dp * y + p;
                p = p * y + self.coefs[tri_index(n, i, j)];
            }
            fx = fx * x + f;
            f = f * x + p;
            fy = fy * x + dp;
        }
        (f, fx, fy)
    }

    /// `f(x, y)` exactly.
    pub fn eval_exact(&self, x: &Q, y: &Q) -> Q {
        let n = self.degree;
        let mut acc = Q::zero();
        for i in (0..=n).rev() {
            let mut p = Q::zero();
            for j in (0..=n - i).rev() {
                p = p * y + &self.exact[tri_index(n, i, j)];
            }
            acc = acc * x + p;
        }
        acc
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rational::q;

    fn circle() -> ImplicitPolynomial {
        // 4 - 4x^2 - 4y^2 (impl-n2-conic-weighted)
        let n = 2;
        let mut e = vec![Q::zero(); tri_count(n)];
        e[tri_index(n, 0, 0)] = q(4.0);
        e[tri_index(n, 2, 0)] = q(-4.0);
        e[tri_index(n, 0, 2)] = q(-4.0);
        ImplicitPolynomial::from_exact(n, e)
    }

    #[test]
    fn evaluation_gradient_and_monomials() {
        let p = circle();
        assert!(p.eval(0.6, 0.8).abs() < 1e-15);
        let (f, fx, fy) = p.eval_grad(0.5, -0.25);
        assert_eq!((f, fx, fy), (4.0 - 1.0 - 0.25, -4.0, 2.0));
        assert_eq!(p.eval_abs(0.5, -0.25), 4.0 + 1.0 + 0.25);
        assert_eq!(p.monomials(), vec![(2, 0, -4.0), (0, 2, -4.0), (0, 0, 4.0)]);
        assert_eq!(p.exact_strings()[0].2, "-4");
        assert_eq!(p.effective_degree(), Some(2));
        assert_eq!(
            p.eval_exact(&q(0.6), &q(0.8)),
            q(4.0) - q(4.0) * q(0.6) * q(0.6) - q(4.0) * q(0.8) * q(0.8)
        );
        assert_eq!(p.coef(3, 0), 0.0);
        assert_eq!(p.max_abs_coef(), 4.0);
    }
}
