//! The Wang–Said generalized Ball basis WSGB(n, L) of seed 003, as reconstructed in
//! SPEC-reduce §9.1, and its exact conversion to the Bernstein basis.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

use crate::{Error, ExactMatrix, Result, binomial, check_degree};

/// One WSGB basis function `coef * u^a * (1-u)^b` (seed 003, SPEC-reduce §9.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct BallTerm {
    /// The constant factor `K` (a power of two times a binomial; exact).
    pub coef: u128,
    /// Exponent of `u`.
    pub a: usize,
    /// Exponent of `1 - u`.
    pub b: usize,
}

impl BallTerm {
    /// The value `coef * u^a * (1-u)^b` in `f64`.
    pub fn eval(&self, u: f64) -> f64 {
        self.coef as f64 * crate::kernel::powu(u, self.a) * crate::kernel::powu(1.0 - u, self.b)
    }
}

/// The largest admissible `L` of WSGB(n, L): `max(floor(n/2) - 1, 0)` (the Wang–Ball order).
pub fn wsgb_max_l(n: usize) -> usize {
    (n / 2).saturating_sub(1)
}

/// Checks `n <= MAX_DEGREE` and `0 <= l <= wsgb_max_l(n)`.
pub(crate) fn check_wsgb(n: usize, l: usize) -> Result<()> {
    check_degree(n)?;
    if l > wsgb_max_l(n) {
        return Err(Error::ConditionNotMet {
            eq: "SPEC-reduce §9.1 (WSGB(n, L) basis of seed 003)",
            why: "L must satisfy 0 <= L <= max(floor(n/2) - 1, 0)",
        });
    }
    Ok(())
}

/// The `n + 1` basis functions of WSGB(n, L), `beta_0 .. beta_n`, as exact terms
/// `K u^a (1-u)^b` (seed 003 §2, SPEC-reduce §9.1).
///
/// With `h = floor(n/2)` and `0 <= L <= max(h - 1, 0)`:
///
/// ```text
/// beta_i = 2^i u^i (1-u)^(i+2),                          0 <= i <= L-1          (Wang part)
/// beta_i = 2^L C(h+i-2L, i-L) u^i (1-u)^(h+1),           L <= i <= ceil(n/2)-1  (Said part)
/// beta_{n/2} = 2^L C(n-2L, n/2-L) u^(n/2) (1-u)^(n/2),   n even
/// beta_i(u) = beta_{n-i}(1-u),                           floor(n/2)+1 <= i <= n
/// ```
///
/// `L = 0` is the Said–Ball basis, `L = floor(n/2) - 1` the Wang–Ball basis. Each basis
/// function is one term `K u^a (1-u)^b`, and (SPEC-reduce §9.1)
/// `K u^a (1-u)^b = sum_{k=a}^{n-b} K C(n-a-b, k-a) / C(n, k) B_k^n(u)`.
///
/// ```
/// use cagd_core::{wsgb_terms, BallTerm};
/// let t = wsgb_terms(7, 1)?;
/// assert_eq!(t[2], BallTerm { coef: 6, a: 2, b: 4 });
/// let sum: f64 = t.iter().map(|b| b.eval(0.3)).sum();
/// assert!((sum - 1.0).abs() < 1e-15); // partition of unity
/// # Ok::<(), cagd_core::Error>(())
/// ```
///
/// # Errors
/// [`Error::DegreeOutOfRange`] for `n > MAX_DEGREE`; [`Error::ConditionNotMet`] when
/// `l > max(floor(n/2) - 1, 0)`.
pub fn wsgb_terms(n: usize, l: usize) -> Result<Vec<BallTerm>> {
    check_wsgb(n, l)?;
    let h = n / 2;
    let mut terms: Vec<BallTerm> = Vec::with_capacity(n + 1);
    for i in 0..=n {
        let term = if i < l {
            BallTerm {
                coef: 1u128 << i,
                a: i,
                b: i + 2,
            }
        } else if i < n.div_ceil(2) {
            BallTerm {
                coef: (1u128 << l) * binomial(h + i - 2 * l, i - l),
                a: i,
                b: h + 1,
            }
        } else if n % 2 == 0 && i == h {
            BallTerm {
                coef: (1u128 << l) * binomial(n - 2 * l, h - l),
                a: h,
                b: h,
            }
        } else {
            let m = terms[n - i];
            BallTerm {
                coef: m.coef,
                a: m.b,
                b: m.a,
            }
        };
        terms.push(term);
    }
    Ok(terms)
}

/// The exact WSGB(n, L) -> Bernstein matrix: column `i` holds the degree-n Bernstein
/// coefficients of `beta_i` (`b = M p`).
pub(crate) fn wsgb_to_bernstein(n: usize, l: usize) -> Result<ExactMatrix> {
    let terms = wsgb_terms(n, l)?;
    let mut m = ExactMatrix::zeros(n + 1, n + 1);
    for (i, t) in terms.iter().enumerate() {
        for k in t.a..=n - t.b {
            let num = BigInt::from(t.coef) * BigInt::from(binomial(n - t.a - t.b, k - t.a));
            let v = BigRational::new(num, BigInt::from(binomial(n, k)));
            debug_assert!(!v.is_zero());
            m.set(k, i, v)?;
        }
    }
    Ok(m)
}
