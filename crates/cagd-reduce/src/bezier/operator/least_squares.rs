//! Least-squares reductions in exact rationals: the generalized inverse of seed 000 §14.4
//! (discrete least squares on the elevated control points, free or with fixed ends) and the
//! L2-optimal reduction with `C^(r,p)` end constraints (beyond the seed).
//!
//! The normal equations are formed and solved **exactly** (`BigRational`), then rounded
//! once: exact arithmetic has no conditioning problem, so this is as good as Householder QR
//! in exact arithmetic and better than QR in `f64` (SPEC-reduce §6 table: QR reaches 2e-13
//! relative at n = 40, m = 20; the exact operator is correctly rounded).

use cagd_core::Result;

use super::ends::end_points;
use crate::exact::{Q, RatMat, Row, binom_q, elevation, to_i, unit};

/// `min ||A X - P||_2` for the full elevation matrix `A` (degree m -> n), eqs. 14.4.5 /
/// 14.4.6: `X = (A^T A)^{-1} A^T P`, exactly. The library builds the identical operator by
/// the cheaper Gram system of [`l2`]; this literal form is the independent check.
#[cfg(test)]
pub(crate) fn ginv_free(n: usize, m: usize) -> Result<RatMat> {
    let a = elevation(m, n);
    let at = a.transpose();
    at.mul(&a)?.solve(&at, "generalized inverse (14.4.6)")
}

/// Eqs. 14.4.8–14.4.15: `Q_0 = P_0`, `Q_m = P_n`, and the interior minimises
/// `||A^C Q^C - (P^C - A^L P_0 - A^R P_n)||_2` (`A^C = A[1..n-1, 1..m-1]`).
pub(crate) fn ginv_ends(n: usize, m: usize) -> Result<RatMat> {
    let a = elevation(m, n);
    let mut rows: Vec<Row> = vec![unit(n + 1, 0)];
    if m >= 2 {
        // A^C and the right-hand side as functionals of P.
        let ac = RatMat::from_rows(
            (1..n)
                .map(|i| (1..m).map(|j| a.at(i, j).clone()).collect())
                .collect(),
        );
        let rhs = RatMat::from_rows(
            (1..n)
                .map(|i| {
                    let mut r = unit(n + 1, i);
                    r[0] -= a.at(i, 0);
                    r[n] -= a.at(i, m);
                    r
                })
                .collect(),
        );
        let act = ac.transpose();
        let x = act
            .mul(&ac)?
            .solve(&act.mul(&rhs)?, "generalized inverse with ends (14.4.12)")?;
        rows.extend((0..m - 1).map(|i| x.row(i).to_vec()));
    }
    rows.push(unit(n + 1, n));
    Ok(RatMat::from_rows(rows))
}

/// `∫_0^1 B_i^a B_j^b dt = C(a,i) C(b,j) / ((a+b+1) C(a+b, i+j))`.
pub(crate) fn gram(a: usize, b: usize, i: usize, j: usize) -> Q {
    let (a, b, i, j) = (to_i(a), to_i(b), to_i(i), to_i(j));
    binom_q(a, i) * binom_q(b, j) / (binom_q(a + b, i + j) * Q::from_integer((a + b + 1).into()))
}

/// L2-optimal reduction with `C^(r,p)` ends: `Q_0..Q_r`, `Q_{m-p}..Q_m` by eq. 14.5.10 (the
/// only points that satisfy the constraints), the interior `I = r+1..m-p-1` from the exact
/// Gram system `sum_{i in I} G^m_ki Q_i = sum_j G^(m,n)_kj P_j - sum_{i not in I} G^m_ki Q_i`,
/// `k in I`. With `r = p = -1` this equals [`ginv_free`] (Lutterkort–Peters–Reif).
pub(crate) fn l2(n: usize, m: usize, r: i32, p: i32) -> Result<RatMat> {
    let (left, right) = end_points(n, m, r, p);
    let lo = left.len();
    let hi = m + 1 - right.len();
    let mut rows: Vec<Row> = left.clone();
    if lo < hi {
        let interior: Vec<usize> = (lo..hi).collect();
        let g = RatMat::from_rows(
            interior
                .iter()
                .map(|&k| interior.iter().map(|&i| gram(m, m, k, i)).collect())
                .collect(),
        );
        let fixed: Vec<(usize, &Row)> = left
            .iter()
            .enumerate()
            .chain(right.iter().enumerate().map(|(k, q)| (hi + k, q)))
            .collect();
        let rhs = RatMat::from_rows(
            interior
                .iter()
                .map(|&k| {
                    let mut row: Row = (0..=n).map(|j| gram(m, n, k, j)).collect();
                    for (i, q) in &fixed {
                        crate::exact::axpy(&mut row, &-gram(m, m, k, *i), q);
                    }
                    row
                })
                .collect(),
        );
        let x = g.solve(&rhs, "L2 Gram system")?;
        rows.extend((0..interior.len()).map(|i| x.row(i).to_vec()));
    }
    rows.extend(right);
    debug_assert_eq!(rows.len(), m + 1);
    Ok(RatMat::from_rows(rows))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn l2_free_equals_generalized_inverse() {
        // SPEC-reduce §6 (Lutterkort–Peters–Reif): the discrete least squares on the elevated
        // control points equals the continuous L2-best approximation, exactly.
        for (n, m) in [(3, 1), (7, 3), (9, 6), (12, 5)] {
            assert_eq!(
                ginv_free(n, m).unwrap(),
                l2(n, m, -1, -1).unwrap(),
                "{n} -> {m}"
            );
        }
    }

    #[test]
    fn gram_rows_sum_to_the_integral() {
        // sum_j ∫ B_i^m B_j^n = ∫ B_i^m = 1/(m+1).
        for i in 0..=4 {
            let s: Q = (0..=7).map(|j| gram(4, 7, i, j)).sum();
            assert_eq!(s, Q::new(1.into(), 5.into()));
        }
    }
}
