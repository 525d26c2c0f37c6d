//! Chebyshev-based reductions in exact rationals: Watkins–Worsey truncation and the
//! constrained Chebyshev reduction of seed 000 §14.5 (Theorem 14.5.2 and Corollary 14.5.2
//! with the SPEC-reduce §7 corrections).
//!
//! The Bernstein <-> Chebyshev basis changes are cagd-core's exact cached matrices
//! ([`cagd_core::from_bernstein_exact`] / [`cagd_core::to_bernstein_exact`] with
//! [`Basis::Chebyshev`], polynomials `T_k(2t-1)`): `c = F b` gives the Chebyshev
//! coefficients `c` of Bernstein coefficients `b` (row `k` of `F` is the functional of `c_k`),
//! and `b = A c` goes back (column `k` of `A` holds the Bernstein coefficients of `T_k`, the
//! closed form of Lemma 14.5.3 as corrected in SPEC-reduce §7).

use cagd_core::{Basis, Result, from_bernstein_exact, to_bernstein_exact};
use num_traits::One;

use super::ends::{auxiliary, end_points};
use super::one_step::up;
use crate::exact::{Q, RatMat, Row, binom_q, idx, to_i};

/// `(N+1) x (N+1)` matrix: row `k` gives the Chebyshev coefficient of `T_k(2t-1)` of the
/// degree-`N` Bézier polynomial with the given Bernstein coefficients.
fn bernstein_to_chebyshev(nn: usize) -> Result<RatMat> {
    Ok(RatMat::from_exact(
        from_bernstein_exact(Basis::Chebyshev, nn)?.as_ref(),
    ))
}

/// `(M+1) x (M+1)` matrix mapping Chebyshev coefficients to degree-`M` Bernstein
/// coefficients.
fn chebyshev_to_bernstein(mm: usize) -> Result<RatMat> {
    Ok(RatMat::from_exact(
        to_bernstein_exact(Basis::Chebyshev, mm)?.as_ref(),
    ))
}

/// Watkins–Worsey: Chebyshev coefficients of the degree-`n` input, keep `k = 0..=m`,
/// back to degree-`m` Bernstein. Bound terms `||c_k||`, `k > m` (`|T_k| <= 1`).
///
/// # Errors
/// [`cagd_core::Error::DegreeOutOfRange`] for `n > MAX_DEGREE` (excluded by `Method::check`).
pub(crate) fn truncation(n: usize, m: usize) -> Result<(RatMat, Vec<(f64, Row)>)> {
    let b2c = bernstein_to_chebyshev(n)?;
    let c2b = chebyshev_to_bernstein(m)?;
    let kept = RatMat::from_rows((0..=m).map(|k| b2c.row(k).to_vec()).collect());
    let terms = (m + 1..=n).map(|k| (1.0, b2c.row(k).to_vec())).collect();
    Ok((c2b.mul(&kept)?, terms))
}

/// `x^x` for a small non-negative integer (`0^0 = 1`), exact.
fn self_pow(x: i64) -> Q {
    let mut acc = Q::one();
    for _ in 0..x {
        acc *= Q::from_integer(x.into());
    }
    acc
}

/// Seed 000 §14.5, Theorem 14.5.2 (`r + p + 1 < m`) or Corollary 14.5.2 (`m = r + p + 1`):
/// the exact `(m+1) x (n+1)` operator and its bound terms
/// `(p+1)^(p+1) (r+1)^(r+1) / (p+r+2)^(p+r+2) * ||P^III_k||`, `k = M+1..=N`.
///
/// # Errors
/// As [`truncation`].
pub(crate) fn constrained(n: usize, m: usize, r: i32, p: i32) -> Result<(RatMat, Vec<(f64, Row)>)> {
    let (left, right) = end_points(n, m, r, p);
    let (mi, ri, pi) = (to_i(m), i64::from(r), i64::from(p));
    let mut rows: Vec<Row> = left.clone();
    let mut terms = Vec::new();
    if ri + pi + 1 < mi {
        let (p3, big_m) = chebyshev_rows(n, m, r, p, &left, &right)?;
        let kept = RatMat::from_rows((0..=big_m).map(|k| p3.row(idx(k)).to_vec()).collect());
        let rr = chebyshev_to_bernstein(idx(big_m))?.mul(&kept)?;
        // Q_i = R_{i-r-1} C(M, i-r-1) / C(m, i)   (14.5.16)
        for i in (ri + 1)..=(mi - pi - 1) {
            let f = binom_q(big_m, i - ri - 1) / binom_q(mi, i);
            rows.push(rr.row(idx(i - ri - 1)).iter().map(|x| x * &f).collect());
        }
        let coef = up(&bound_factor(r, p));
        for k in (idx(big_m) + 1)..p3.nrows() {
            terms.push((coef, p3.row(k).to_vec()));
        }
    }
    rows.extend(right);
    Ok((RatMat::from_rows(rows), terms))
}

/// [`bound_factor`] rounded up to `f64` (the fast route's term coefficient), remembered per
/// `(r, p)` for the process (a constant; its big-rational evaluation was 3 % of a
/// constrained Chebyshev build at `(30,15)`).
pub(super) fn bound_factor_up(r: i32, p: i32) -> f64 {
    use std::collections::HashMap;
    use std::sync::{OnceLock, RwLock};
    static MEMO: OnceLock<RwLock<HashMap<(i32, i32), f64>>> = OnceLock::new();
    let memo = MEMO.get_or_init(|| RwLock::new(HashMap::new()));
    if let Some(v) = memo.read().ok().and_then(|m| m.get(&(r, p)).copied()) {
        return v;
    }
    let v = up(&bound_factor(r, p));
    if let Ok(mut m) = memo.write() {
        m.insert((r, p), v);
    }
    v
}

/// The factor `(p+1)^(p+1) (r+1)^(r+1) / (p+r+2)^(p+r+2)` of Theorem 14.5.2's bound
/// (`0^0 = 1`), exact.
fn bound_factor(r: i32, p: i32) -> Q {
    let (ri, pi) = (i64::from(r), i64::from(p));
    self_pow(pi + 1) * self_pow(ri + 1) / self_pow(pi + ri + 2)
}

/// Theorem 14.5.2, eqs. 14.5.14–14.5.15: the exact rows mapping the control points `P` to
/// the Chebyshev coefficients `P^III_k`, `k = 0..=N`, of the deflated inner polynomial
/// (`N = n - (r+p+2)`), and `M = m - (r+p+2)`. Requires `r + p + 1 < m`.
fn chebyshev_rows(
    n: usize,
    m: usize,
    r: i32,
    p: i32,
    left: &[Row],
    right: &[Row],
) -> Result<(RatMat, i64)> {
    let (ni, mi, ri, pi) = (to_i(n), to_i(m), i64::from(r), i64::from(p));
    let aux = auxiliary(n, m, r, p, left, right);
    let big_n = ni - (ri + pi + 2);
    let big_m = mi - (ri + pi + 2);
    // P^II_i = P^I_{r+1+i} C(n, r+1+i) / C(N, i)   (14.5.14)
    let p2 = RatMat::from_rows(
        (0..=big_n)
            .map(|i| {
                let f = binom_q(ni, ri + 1 + i) / binom_q(big_n, i);
                aux[idx(i)].iter().map(|x| x * &f).collect()
            })
            .collect(),
    );
    // P^III = (B->Cheb) P^II   (14.5.15)
    let p3 = bernstein_to_chebyshev(idx(big_n))?.mul(&p2)?;
    Ok((p3, big_m))
}

/// The Chebyshev coefficients of seed 000 Theorem 14.5.2 for one curve (SPEC-reduce §7).
#[derive(Debug, Clone, PartialEq)]
pub struct ChebyshevTerms {
    /// `P^III_k`, `k = 0..=N` (`N = n - (r+p+2)`), flat row-major, `dim` per point
    /// (eq. 14.5.15).
    pub coefficients: Vec<f64>,
    /// How many are kept by the reduction: `M + 1`, `M = m - (r+p+2)`.
    pub kept: usize,
    /// The printed error bound of Theorem 14.5.2 (an upper bound, SPEC-reduce §7 erratum):
    /// `(p+1)^(p+1) (r+1)^(r+1) / (p+r+2)^(p+r+2) * sum_{k=M+1}^{N} ||P^III_k||`, evaluated
    /// in `f64` from the exactly computed coefficients.
    pub bound: f64,
}

/// Seed 000 Theorem 14.5.2 (SPEC-reduce §7): the Chebyshev coefficients `P^III_k` of the
/// deflated inner polynomial of `curve` for the reduction to degree `m` with `(r, p)`-order
/// end interpolation (`r, p >= -1`, `r + p + 1 < m < n`), from the exact operator (each
/// coefficient one exact linear functional of the control points, rounded once), and the
/// theorem's bound. [`crate::Method::ConstrainedChebyshev`] is the reduction itself.
///
/// # Errors
/// [`cagd_core::Error::BadDegreePair`] / [`cagd_core::Error::TooManyConstraints`] unless
/// `r + p + 1 < m < n <= 64` (with `r, p >= -1`); rational curves are refused
/// ([`cagd_core::Error::BadParameter`]).
pub fn constrained_chebyshev_terms(
    curve: &cagd_core::BezierCurve,
    m: usize,
    r: i32,
    p: i32,
) -> Result<ChebyshevTerms> {
    let n = curve.degree();
    crate::Method::ConstrainedChebyshev { r, p }.check(n, m)?;
    if curve.is_rational() {
        return Err(cagd_core::Error::BadParameter {
            name: "curve",
            value: f64::NAN,
            why: "the Chebyshev terms are defined for polynomial curves",
        });
    }
    if i64::from(r) + i64::from(p) + 1 >= to_i(m) {
        return Err(cagd_core::Error::BadDegreePair {
            from: n,
            to: m,
            why: "Theorem 14.5.2 needs r + p + 1 < m (m = r + p + 1 is Hermite interpolation)",
        });
    }
    let (left, right) = end_points(n, m, r, p);
    let (p3, big_m) = chebyshev_rows(n, m, r, p, &left, &right)?;
    let dim = curve.dim();
    let ops = p3.to_f64();
    let cols = n + 1;
    let mut coefficients = vec![0.0; p3.nrows() * dim];
    for k in 0..p3.nrows() {
        for (j, pt) in curve.points().chunks_exact(dim).enumerate() {
            let a = ops[k * cols + j];
            for d in 0..dim {
                coefficients[k * dim + d] += a * pt[d];
            }
        }
    }
    let factor = up(&bound_factor(r, p));
    let tail: f64 = coefficients
        .chunks_exact(dim)
        .skip(idx(big_m) + 1)
        .map(|c| c.iter().map(|x| x * x).sum::<f64>().sqrt())
        .sum();
    Ok(ChebyshevTerms {
        coefficients,
        kept: idx(big_m) + 1,
        bound: factor * tail,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions_are_inverse() {
        for nn in [0, 1, 2, 5, 9] {
            let prod = chebyshev_to_bernstein(nn)
                .unwrap()
                .mul(&bernstein_to_chebyshev(nn).unwrap())
                .unwrap();
            assert_eq!(prod, RatMat::identity(nn + 1), "N = {nn}");
        }
    }

    /// Pins the orientation this module relies on: column `k` of `chebyshev_to_bernstein(K)`
    /// holds the Bernstein coefficients of `T_k(2t-1)`, and `bernstein_to_chebyshev` maps
    /// them to the unit vector `e_k` (row `k` is the functional of `c_k`).
    #[test]
    fn chebyshev_bernstein_coefficients_closed_form() {
        // SPEC-reduce §3: T_k(2t-1) = sum_i (-1)^(k-i) C(2k,2i)/C(k,i) B_i^k(t).
        for k in 0..7usize {
            let a = chebyshev_to_bernstein(k).unwrap();
            let f = bernstein_to_chebyshev(k).unwrap();
            let mut coeffs = Vec::new();
            for i in 0..=k {
                let (ki, ii) = (to_i(k), to_i(i));
                let mut e = binom_q(2 * ki, 2 * ii) / binom_q(ki, ii);
                if (ki - ii) % 2 == 1 {
                    e = -e;
                }
                assert_eq!(*a.at(i, k), e);
                coeffs.push(e);
            }
            for j in 0..=k {
                let c: Q = f.row(j).iter().zip(&coeffs).map(|(x, y)| x * y).sum();
                assert_eq!(
                    c,
                    if j == k {
                        Q::one()
                    } else {
                        num_traits::Zero::zero()
                    }
                );
            }
        }
    }
}
