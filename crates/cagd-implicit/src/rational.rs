//! Exact rational helpers: `f64` to `BigRational` without rounding, and univariate
//! polynomials over ℚ in the power basis (gcd, exact division, Bernstein ↔ power).
//!
//! Every `f64` is a binary fraction, so [`q`] is exact; the implicitization and base-point
//! routes (SPEC-convert §15.8) run on these exact values.

use cagd_core::binomial;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

/// Exact rational number.
pub(crate) type Q = BigRational;

/// The exact value of a finite `f64` (non-finite values, which validated inputs never
/// hold, give 0).
#[cfg(test)]
pub(crate) fn q(x: f64) -> Q {
    BigRational::from_float(x).unwrap_or_else(Q::zero)
}

/// An exact binomial coefficient as a rational.
pub(crate) fn q_binomial(n: usize, k: usize) -> Q {
    Q::from_integer(BigInt::from(binomial(n, k)))
}

/// A univariate polynomial over ℚ in the power basis: `coef[k]` multiplies `t^k`. Kept
/// trimmed (no trailing zeros), so the zero polynomial is the empty vector.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct UPoly(pub(crate) Vec<Q>);

impl UPoly {
    /// Builds and trims.
    pub(crate) fn new(mut c: Vec<Q>) -> Self {
        while c.last().is_some_and(Zero::is_zero) {
            c.pop();
        }
        UPoly(c)
    }

    /// The degree, `None` for the zero polynomial.
    pub(crate) fn degree(&self) -> Option<usize> {
        self.0.len().checked_sub(1)
    }

    /// Whether this is the zero polynomial.
    pub(crate) fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    /// The power form of `sum_i c_i B^n_i(t)` (n = `c.len() - 1`):
    /// coefficient of `t^k` is `sum_{i<=k} c_i C(n,i) C(n-i,k-i) (-1)^(k-i)`.
    pub(crate) fn from_bernstein(c: &[Q]) -> Self {
        let n = c.len().saturating_sub(1);
        let mut out = vec![Q::zero(); c.len()];
        for (i, ci) in c.iter().enumerate() {
            if ci.is_zero() {
                continue;
            }
            let base = ci * q_binomial(n, i);
            for (k, slot) in out.iter_mut().enumerate().skip(i) {
                let term = &base * q_binomial(n - i, k - i);
                if (k - i) % 2 == 0 {
                    *slot += term;
                } else {
                    *slot -= term;
                }
            }
        }
        UPoly::new(out)
    }

    /// The Bernstein coefficients of degree `m >= degree`: `c_i = sum_{k<=i} a_k C(i,k)/C(m,k)`.
    pub(crate) fn to_bernstein(&self, m: usize) -> Vec<Q> {
        (0..=m)
            .map(|i| {
                let mut s = Q::zero();
                for (k, a) in self.0.iter().enumerate().take(i + 1) {
                    if !a.is_zero() {
                        s += a * q_binomial(i, k) / q_binomial(m, k);
                    }
                }
                s
            })
            .collect()
    }

    /// Value at `t` (Horner).
    #[cfg(test)]
    pub(crate) fn eval(&self, t: &Q) -> Q {
        let mut acc = Q::zero();
        for c in self.0.iter().rev() {
            acc = acc * t + c;
        }
        acc
    }

    /// Quotient and remainder of the division by a non-zero `d`.
    pub(crate) fn div_rem(&self, d: &UPoly) -> (UPoly, UPoly) {
        let Some(dd) = d.degree() else {
            return (UPoly(Vec::new()), self.clone());
        };
        let mut r = self.0.clone();
        if r.len() <= dd {
            return (UPoly(Vec::new()), self.clone());
        }
        let lead = &d.0[dd];
        let mut quot = vec![Q::zero(); r.len() - dd];
        for k in (0..quot.len()).rev() {
            let c = &r[k + dd] / lead;
            if !c.is_zero() {
                for (j, dj) in d.0.iter().enumerate() {
                    r[k + j] -= &c * dj;
                }
            }
            quot[k] = c;
        }
        r.truncate(dd);
        (UPoly::new(quot), UPoly::new(r))
    }

    /// Monic greatest common divisor (zero when both are zero).
    pub(crate) fn gcd(&self, other: &UPoly) -> UPoly {
        let (mut a, mut b) = (self.clone(), other.clone());
        while !b.is_zero() {
            let (_, r) = a.div_rem(&b);
            a = b;
            b = r;
        }
        match a.0.last().cloned() {
            Some(lead) => UPoly(a.0.iter().map(|c| c / &lead).collect()),
            None => a,
        }
    }

    /// The polynomial times a scalar.
    #[cfg(test)]
    pub(crate) fn scale(&self, s: &Q) -> UPoly {
        UPoly::new(self.0.iter().map(|c| c * s).collect())
    }

    /// `self - other`.
    #[cfg(test)]
    pub(crate) fn sub(&self, other: &UPoly) -> UPoly {
        let n = self.0.len().max(other.0.len());
        UPoly::new(
            (0..n)
                .map(|k| {
                    let a = self.0.get(k).cloned().unwrap_or_else(Q::zero);
                    let b = other.0.get(k).cloned().unwrap_or_else(Q::zero);
                    a - b
                })
                .collect(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::One;

    fn qi(n: i64) -> Q {
        Q::from_integer(BigInt::from(n))
    }

    #[test]
    fn exact_conversion_of_binary_fractions() {
        assert_eq!(q(0.75), Q::new(BigInt::from(3), BigInt::from(4)));
        assert_eq!(q(-3.0), qi(-3));
    }

    #[test]
    fn bernstein_power_round_trip() {
        let c = vec![qi(1), qi(-2), qi(5), qi(3)];
        let p = UPoly::from_bernstein(&c);
        assert_eq!(p.to_bernstein(3), c);
        // Value at t = 1/3 by the Bernstein sum.
        let t = Q::new(BigInt::from(1), BigInt::from(3));
        let s = Q::one() - &t;
        let mut v = Q::zero();
        for (i, ci) in c.iter().enumerate() {
            let mut b = q_binomial(3, i) * ci;
            for _ in 0..i {
                b *= &t;
            }
            for _ in i..3 {
                b *= &s;
            }
            v += b;
        }
        assert_eq!(p.eval(&t), v);
        // Elevated Bernstein form evaluates to the same polynomial.
        assert_eq!(UPoly::from_bernstein(&p.to_bernstein(5)), p);
    }

    #[test]
    fn gcd_and_division() {
        // (t - 2)(t + 1) and (t - 2)(t - 3)
        let a = UPoly::new(vec![qi(-2), qi(-1), qi(1)]);
        let b = UPoly::new(vec![qi(6), qi(-5), qi(1)]);
        let g = a.gcd(&b);
        assert_eq!(g, UPoly::new(vec![qi(-2), qi(1)]));
        let (quot, r) = a.div_rem(&g);
        assert!(r.is_zero());
        assert_eq!(quot, UPoly::new(vec![qi(1), qi(1)]));
        assert_eq!(a.sub(&a), UPoly::new(vec![]));
        assert_eq!(a.scale(&qi(2)).0[2], qi(2));
    }
}
