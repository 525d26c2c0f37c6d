//! Closed-form exact conversion matrices between the degree-n Bernstein basis and the power,
//! shifted Chebyshev and shifted Legendre bases on `[0, 1]`, both directions.
//!
//! Convention: `to_*` matrices map coefficients in the basis to Bernstein coefficients
//! (`b = M c`, column k = Bernstein coefficients of the k-th basis polynomial); `from_*`
//! matrices map Bernstein coefficients to basis coefficients. Every entry is an integer sum
//! over one common denominator, turned into a rational once.

use std::sync::OnceLock;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::{ExactMatrix, MAX_DEGREE, binomial};

/// `C(n, k)` as a big integer (exact; `n <= MAX_BINOMIAL_N`).
fn c(n: usize, k: usize) -> BigInt {
    BigInt::from(binomial(n, k))
}

/// `k!` for `k <= 4 * MAX_DEGREE`, exact.
fn factorial(k: usize) -> &'static BigInt {
    static TABLE: OnceLock<Vec<BigInt>> = OnceLock::new();
    let t = TABLE.get_or_init(|| {
        let mut v = vec![BigInt::one()];
        for i in 1..=4 * MAX_DEGREE + 2 {
            let next = &v[i - 1] * BigInt::from(i);
            v.push(next);
        }
        v
    });
    &t[k]
}

/// `(-1)^e` applied to `x`.
fn signed(x: BigInt, e: usize) -> BigInt {
    if e % 2 == 0 { x } else { -x }
}

/// Power -> Bernstein: `t^k = sum_{j >= k} C(j,k)/C(n,k) B_j^n(t)`.
pub(crate) fn power_to_bernstein(n: usize) -> ExactMatrix {
    ExactMatrix::from_fn(n + 1, n + 1, |j, k| {
        if j < k {
            BigRational::zero()
        } else {
            BigRational::new(c(j, k), c(n, k))
        }
    })
}

/// Bernstein -> power: `B_i^n(t) = sum_{k >= i} (-1)^(k-i) C(n,k) C(k,i) t^k`.
pub(crate) fn power_from_bernstein(n: usize) -> ExactMatrix {
    ExactMatrix::from_fn(n + 1, n + 1, |k, i| {
        if k < i {
            BigRational::zero()
        } else {
            BigRational::from_integer(signed(c(n, k) * c(k, i), k - i))
        }
    })
}

/// Chebyshev -> Bernstein (seed 000 Lemma 14.5.3, SPEC-reduce §7 erratum form):
/// `T_k(2t-1) = sum_j A_kj B_j^n(t)`,
/// `A_kj = sum_i (-1)^(k+i) C(2k,2i) C(n-k,j-i) / C(n,j)`; the matrix returned is `A^T`.
pub(crate) fn chebyshev_to_bernstein(n: usize) -> ExactMatrix {
    ExactMatrix::from_fn(n + 1, n + 1, |j, k| {
        let lo = (j + k).saturating_sub(n);
        let sum = (lo..=j.min(k)).fold(BigInt::zero(), |acc, i| {
            acc + signed(c(2 * k, 2 * i) * c(n - k, j - i), k + i)
        });
        BigRational::new(sum, c(n, j))
    })
}

/// Bernstein -> Chebyshev by orthogonality (ADDED): with `w = 1/sqrt(t(1-t))`,
/// `c_k = (eps_k / pi) int_0^1 f(t) T_k(2t-1) w dt` (`eps_0 = 1`, `eps_k = 2`),
/// `T_k(2t-1) = sum_j (-1)^(k+j) C(2k,2j) t^j (1-t)^(k-j)` and
/// `int_0^1 t^(a-1/2) (1-t)^(b-1/2) dt = pi (2a)! (2b)! / (4^N a! b! N!)`, `N = a + b`:
/// `M_ki = eps_k C(n,i) / (4^N N!) sum_j (-1)^(k+j) C(2k,2j) (2a)!/a! (2b)!/b!`,
/// `a = i + j`, `N = n + k`. The `pi` cancels, so the entries are rational.
pub(crate) fn chebyshev_from_bernstein(n: usize) -> ExactMatrix {
    let half_fact = |a: usize| factorial(2 * a) / factorial(a); // (2a)!/a!, exact
    let hf: Vec<BigInt> = (0..=2 * n).map(half_fact).collect();
    ExactMatrix::from_fn(n + 1, n + 1, |k, i| {
        let big_n = n + k;
        let sum = (0..=k).fold(BigInt::zero(), |acc, j| {
            let a = i + j;
            acc + signed(c(2 * k, 2 * j) * &hf[a] * &hf[big_n - a], k + j)
        });
        let eps = if k == 0 { 1u32 } else { 2 };
        let den = (BigInt::one() << (2 * big_n)) * factorial(big_n);
        BigRational::new(sum * c(n, i) * eps, den)
    })
}

/// Legendre -> Bernstein: `P_k(2t-1) = sum_i (-1)^(k-i) C(k,i) B_i^k(t)`, elevated to degree
/// n (SPEC-reduce §0 elevation matrix):
/// `M_jk = sum_i (-1)^(k-i) C(k,i)^2 C(n-k,j-i) / C(n,j)`.
pub(crate) fn legendre_to_bernstein(n: usize) -> ExactMatrix {
    ExactMatrix::from_fn(n + 1, n + 1, |j, k| {
        let lo = (j + k).saturating_sub(n);
        let sum = (lo..=j.min(k)).fold(BigInt::zero(), |acc, i| {
            let cki = c(k, i);
            acc + signed(&cki * &cki * c(n - k, j - i), k - i)
        });
        BigRational::new(sum, c(n, j))
    })
}

/// Bernstein -> Legendre by orthogonality (ADDED): `c_k = (2k+1) int_0^1 f P_k(2t-1) dt`,
/// `int_0^1 t^a (1-t)^b dt = a! b! / (a+b+1)!`:
/// `M_ki = (2k+1) C(n,i) / (n+k+1)! sum_l (-1)^(k-l) C(k,l)^2 (i+l)! (n+k-i-l)!`.
pub(crate) fn legendre_from_bernstein(n: usize) -> ExactMatrix {
    ExactMatrix::from_fn(n + 1, n + 1, |k, i| {
        let big_n = n + k;
        let sum = (0..=k).fold(BigInt::zero(), |acc, l| {
            let ckl = c(k, l);
            let a = i + l;
            acc + signed(&ckl * &ckl * factorial(a) * factorial(big_n - a), k - l)
        });
        BigRational::new(
            sum * c(n, i) * BigInt::from(2 * k + 1),
            factorial(big_n + 1).clone(),
        )
    })
}
