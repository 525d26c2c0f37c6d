//! End control points that interpolate derivatives of orders `0..=r` at `t = 0` and
//! `0..=p` at `t = 1` (seed 000 Theorem 14.5.1, eq. 14.5.10), and the auxiliary points
//! `P^I` of the unified form (SPEC-reduce §7), as exact linear functionals of the input.

use crate::exact::{Q, Row, axpy, binom_q, idx, to_i, unit};

/// `b_ij = C(m,i) C(n-m,j-i) / C(n,j)`: the coefficient of `B_j^n` in `B_i^m` (Lemma 14.5.1),
/// `0` outside the band `0 <= j - i <= n - m`.
pub(crate) fn b(m: i64, n: i64, i: i64, j: i64) -> Q {
    binom_q(m, i) * binom_q(n - m, j - i) / binom_q(n, j)
}

/// The end points of a degree-`m` reduction of a degree-`n` curve (eq. 14.5.10):
/// `Q_0..Q_r` (left, in order) and `Q_{m-p}..Q_m` (right, in order), each a row of length
/// `n + 1`. Requires `r + p + 1 <= m < n` (checked by the caller).
pub(crate) fn end_points(n: usize, m: usize, r: i32, p: i32) -> (Vec<Row>, Vec<Row>) {
    let (ni, mi) = (to_i(n), to_i(m));
    let len = n + 1;
    let mut left: Vec<Row> = Vec::new();
    for j in 0..=i64::from(r) {
        let mut q = unit(len, idx(j));
        for i in (j - (ni - mi)).max(0)..j {
            axpy(&mut q, &-b(mi, ni, i, j), &left[idx(i)]);
        }
        let d = b(mi, ni, j, j).recip();
        left.push(q.iter().map(|x| x * &d).collect());
    }
    // right[j] holds Q_{m-j}.
    let mut right_rev: Vec<Row> = Vec::new();
    for j in 0..=i64::from(p) {
        let mut q = unit(len, idx(ni - j));
        for i in (j - (ni - mi)).max(0)..j {
            axpy(&mut q, &-b(mi, ni, mi - i, ni - j), &right_rev[idx(i)]);
        }
        let d = b(mi, ni, mi - j, ni - j).recip();
        right_rev.push(q.iter().map(|x| x * &d).collect());
    }
    right_rev.reverse();
    (left, right_rev)
}

/// The auxiliary points `P^I_j = P_j - sum_{i<=r} b_ij Q_i - sum_{i<=p} b_{m-i,j} Q_{m-i}`,
/// `j = r+1..=n-p-1` (SPEC-reduce §7, unified form of eqs. 14.5.11 / 14.5.12): the control
/// points of the residual `P - Q_ends` in degree `n`.
pub(crate) fn auxiliary(
    n: usize,
    m: usize,
    r: i32,
    p: i32,
    left: &[Row],
    right: &[Row],
) -> Vec<Row> {
    let (ni, mi) = (to_i(n), to_i(m));
    let (r, p) = (i64::from(r), i64::from(p));
    ((r + 1)..=(ni - p - 1))
        .map(|j| {
            let mut a = unit(n + 1, idx(j));
            for (i, q) in left.iter().enumerate() {
                axpy(&mut a, &-b(mi, ni, to_i(i), j), q);
            }
            // right[k] is Q_{m-p+k}.
            for (k, q) in right.iter().enumerate() {
                axpy(&mut a, &-b(mi, ni, mi - p + to_i(k), j), q);
            }
            a
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::{RatMat, elevation};

    #[test]
    fn ends_reproduce_an_elevated_curve() {
        // Elevate a generic degree-4 curve (unit rows) to 7; the end formulas must give the
        // original points back for any r, p with r + p + 1 <= 4.
        let e = elevation(4, 7);
        for (r, p) in [(0, 0), (1, 2), (2, 1), (-1, 3), (3, 0)] {
            let (left, right) = end_points(7, 4, r, p);
            if left.is_empty() {
                continue;
            }
            let el = RatMat::from_rows(left.clone());
            let got = el.mul(&e).unwrap();
            for (i, row) in (0..left.len()).map(|i| (i, got.row(i))) {
                assert_eq!(row.to_vec(), unit(5, i), "left {i} for r={r}");
            }
            if right.is_empty() {
                continue;
            }
            let er = RatMat::from_rows(right.clone());
            let got = er.mul(&e).unwrap();
            for k in 0..right.len() {
                let idx_q = 4 - right.len() + 1 + k;
                assert_eq!(got.row(k).to_vec(), unit(5, idx_q), "right {k} for p={p}");
            }
        }
    }
}
