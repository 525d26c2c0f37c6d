//! Theorem 15.9.1 (SPEC-convert §15.9, eq. 15.9.6, with the erratum that the identity
//! carries `α`): if `q*_k = sum_l C(k,l) β^(k-l) α^l q_l` are the homogeneous control points
//! of the piece `[0, α]` (`β = 1 - α`), then `α A(α) F(q) A(α)^T = F(q*)` with the lower
//! triangular `A(α)`, `a_ij = C(n-j, i-j) β^(i-j) α^(j-1)` (1-based), and therefore
//! `det F(q*) = α^(n^2) det F(q)`.

#[cfg(test)]
use cagd_core::binomial;
use cagd_core::{Error, Result, binomial_f64};
#[cfg(test)]
use num_bigint::BigInt;
#[cfg(test)]
use num_traits::{One, Zero};

#[cfg(test)]
use crate::rational::Q;

fn check(n: usize) -> Result<()> {
    if n == 0 || n > crate::MAX_IMPLICIT_DEGREE {
        return Err(Error::DegreeOutOfRange {
            degree: n,
            max: crate::MAX_IMPLICIT_DEGREE,
        });
    }
    Ok(())
}

/// `A(α)` of eq. 15.9.6 for curve degree `n` (an `n x n` row-major lower-triangular
/// matrix; 0-based `a_ij = C(n-1-j, i-j) (1-α)^(i-j) α^j` for `j <= i`).
///
/// # Errors
/// [`Error::DegreeOutOfRange`] for `n = 0` or above [`crate::MAX_IMPLICIT_DEGREE`];
/// [`Error::BadParameter`] for a non-finite `α`.
///
/// ```
/// // impl-15.9.1-A-n3: A(1/3) = [[1,0,0],[4/3,1/3,0],[4/9,2/9,1/9]].
/// let a = cagd_implicit::subdivision_matrix(3, 1.0 / 3.0)?;
/// assert!((a[3] - 4.0 / 3.0).abs() < 1e-15 && (a[8] - 1.0 / 9.0).abs() < 1e-15);
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn subdivision_matrix(n: usize, alpha: f64) -> Result<Vec<f64>> {
    check(n)?;
    cagd_core::check_finite_param("alpha", alpha)?;
    let beta = 1.0 - alpha;
    let mut a = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..=i {
            a[i * n + j] =
                binomial_f64(n - 1 - j, i - j) * beta.powi(pow(i - j)) * alpha.powi(pow(j));
        }
    }
    Ok(a)
}

fn pow(e: usize) -> i32 {
    i32::try_from(e).unwrap_or(i32::MAX)
}

/// `A(α)` in exact arithmetic (see [`subdivision_matrix`]).
#[cfg(test)]
fn subdivision_matrix_exact(n: usize, alpha: &Q) -> Vec<Q> {
    let beta = Q::one() - alpha;
    let mut a = vec![Q::zero(); n * n];
    for i in 0..n {
        for j in 0..=i {
            let mut v = Q::from_integer(BigInt::from(binomial(n - 1 - j, i - j)));
            for _ in 0..i - j {
                v *= &beta;
            }
            for _ in 0..j {
                v *= alpha;
            }
            a[i * n + j] = v;
        }
    }
    a
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rational::q;

    /// Exact F-matrices (A, B, C0) of homogeneous points, eqs. 15.8.2–15.8.3.
    fn exact_f(hom: &[[Q; 3]]) -> [Vec<Q>; 3] {
        let n = hom.len() - 1;
        let mut out = [
            vec![Q::zero(); n * n],
            vec![Q::zero(); n * n],
            vec![Q::zero(); n * n],
        ];
        for h in 0..n {
            for k in 0..n {
                for m in (h + k + 1).saturating_sub(n)..=h.min(k) {
                    let j = h + k + 1 - m;
                    let s = Q::from_integer(BigInt::from(binomial(n, m) * binomial(n, j)));
                    let (u, v) = (&hom[m], &hom[j]);
                    out[0][h * n + k] += &s * (&u[1] * &v[2] - &u[2] * &v[1]);
                    out[1][h * n + k] -= &s * (&u[0] * &v[2] - &u[2] * &v[0]);
                    out[2][h * n + k] += &s * (&u[0] * &v[1] - &u[1] * &v[0]);
                }
            }
        }
        out
    }

    #[test]
    fn theorem_15_9_1_holds_exactly() {
        let raw = [
            (0.0, 0.0, 1.0),
            (1.0, 3.0, 2.0),
            (3.0, 2.5, 0.5),
            (4.0, -1.0, 1.5),
            (6.0, 1.0, 1.0),
        ];
        for n in 2..=4 {
            let hom: Vec<[Q; 3]> = raw[..=n]
                .iter()
                .map(|&(x, y, w)| [q(w * x), q(w * y), q(w)])
                .collect();
            for alpha in [Q::new(BigInt::from(1), BigInt::from(3)), q(0.75)] {
                let beta = Q::one() - &alpha;
                // Left piece by the explicit formula q*_k = sum_l C(k,l) β^(k-l) α^l q_l.
                let star: Vec<[Q; 3]> = (0..=n)
                    .map(|k| {
                        let mut p = [Q::zero(), Q::zero(), Q::zero()];
                        for (l, hl) in hom.iter().enumerate().take(k + 1) {
                            let mut c = Q::from_integer(BigInt::from(binomial(k, l)));
                            for _ in 0..k - l {
                                c *= &beta;
                            }
                            for _ in 0..l {
                                c *= &alpha;
                            }
                            for (pr, hr) in p.iter_mut().zip(hl) {
                                *pr += &c * hr;
                            }
                        }
                        p
                    })
                    .collect();
                let a = subdivision_matrix_exact(n, &alpha);
                let (f, fs) = (exact_f(&hom), exact_f(&star));
                for part in 0..3 {
                    // α A F A^T
                    let mut prod = vec![Q::zero(); n * n];
                    for i in 0..n {
                        for j in 0..n {
                            let mut s = Q::zero();
                            for k in 0..n {
                                for l in 0..n {
                                    s += &a[i * n + k] * &f[part][k * n + l] * &a[j * n + l];
                                }
                            }
                            prod[i * n + j] = &alpha * s;
                        }
                    }
                    assert_eq!(prod, fs[part], "n = {n}, part {part}");
                }
            }
        }
    }

    #[test]
    fn float_matrix_matches_exact_and_rejects_bad_input() {
        let a = subdivision_matrix(4, 0.75).unwrap();
        let e = subdivision_matrix_exact(4, &q(0.75));
        for (x, y) in a.iter().zip(&e) {
            assert_eq!(*x, crate::polynomial::round(y));
        }
        assert!(subdivision_matrix(0, 0.5).is_err());
        assert!(subdivision_matrix(3, f64::NAN).is_err());
    }
}
