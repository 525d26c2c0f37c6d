//! The error curve of a linear reduction in a basis of its own size (goes beyond the seed;
//! the error curve is that of seed 000 §14.4.3's hull bound): `D = P - E Q = R P` with
//! `R = I - E A` (`E` = elevation `m -> n`, `A` the `f64` operator). For a method that
//! reproduces degree-`m` curves (`A E = I`) `R` is a projection of rank `n - m` (its range
//! is the kernel of `A`: for L2 with C0 ends, the Jacobi-weighted polynomials of degree
//! `m + 1 ..= n` vanishing at both ends), so `R = U G` with `U` `(n+1) x r` orthonormal
//! and `G = U^T R` `r x (n+1)`, `r = n - m`: the error curve is `D(t) = sum_k c_k phi_k(t)`
//! with the `r` coefficient points `c = G P` and the degree-`n` Bézier curves `phi_k`
//! whose control points are the columns of `U`.
//!
//! The factorisation is computed, not assumed: pivoted modified Gram–Schmidt with
//! reorthogonalisation on the columns of `R`, stopped when every remaining column is at
//! rounding level, and its residual `R - U G` is measured and carried into the bound
//! (`rho`), so a method that is not a projection only loosens the bound.

use nalgebra::DMatrix;

use super::super::gemm::LinearMap;

/// `R = U G` up to the measured residual `rho` (per unit of `max_j ||P_j||`).
#[derive(Debug, Clone)]
pub(crate) struct ErrorBasis {
    /// Source degree `n`.
    pub(crate) n: usize,
    /// `r`, the number of basis curves.
    pub(crate) rank: usize,
    /// `U`, row-major `(n+1) x r`: column `k` holds the control points of `phi_k`.
    pub(crate) u: Vec<f64>,
    /// `G` as a map from the input points to the `r` coefficient points `c = G P`.
    pub(crate) coef: LinearMap,
    /// `g_k = sum_j |G_kj|`: `||c_k|| <= g_k max_j ||P_j||`.
    pub(crate) gsum: Vec<f64>,
    /// A true bound of the row sums of `|R - U G|` for the exact `R = I - E A` (measured,
    /// with the rounding of its measurement and of `R`'s computation; see [`Self::new`]).
    pub(crate) rho: f64,
}

impl ErrorBasis {
    /// The basis for the `f64` operator `a` (`(m+1) x (n+1)`, row-major), whose row sums
    /// of absolute values are at most `op_norm`.
    ///
    /// `rho`: the computed `R^` differs from the exact `I - E A` by at most
    /// `(m + 6) eps (1 + op_norm)` per row sum (coefficients within `3 eps`, at most
    /// `m + 1` terms summed, then one subtraction; the allowance used is the larger
    /// `(3 (n - m) + m + 6) eps (1 + op_norm)`); `fl(U G)` differs from
    /// `U G` by `r eps sum_k |U_ik| g_k`; the measured row sums of `|R^ - fl(U G)|` by
    /// `(n + 3) eps` of themselves. `rho` is twice the sum of the three.
    pub(crate) fn new(a: &[f64], n: usize, m: usize, op_norm: f64) -> Self {
        let n1 = n + 1;
        let r_mat = residual_matrix(a, n, m);
        let (u, rank) = orthonormal_range(&r_mat, n1, n - m);
        // G = U^T R, row-major r x n1.
        // G = U^T R and U G through the GEMM kernel (the rounding bounds below hold for
        // any order of the sums).
        let rm = DMatrix::from_row_slice(n1, n1, &r_mat);
        let um = DMatrix::from_row_slice(n1, rank, &u);
        let gm = um.transpose() * &rm;
        let ugm = &um * &gm;
        let g: Vec<f64> = (0..rank)
            .flat_map(|k| (0..n1).map(move |j| (k, j)))
            .map(|(k, j)| gm[(k, j)])
            .collect();
        let gsum: Vec<f64> = g
            .chunks_exact(n1)
            .map(|row| row.iter().map(|x| x.abs()).sum())
            .collect();
        let (mut measured, mut ug): (f64, f64) = (0.0, 0.0);
        for i in 0..n1 {
            let urow = &u[i * rank..(i + 1) * rank];
            let mut row = 0.0;
            for j in 0..n1 {
                row += (r_mat[i * n1 + j] - ugm[(i, j)]).abs();
            }
            measured = measured.max(row);
            ug = ug.max(urow.iter().zip(&gsum).map(|(x, s)| x.abs() * s).sum());
        }
        let eps = f64::EPSILON;
        let rho = 2.0
            * (measured * (1.0 + (n as f64 + 3.0) * eps)
                + (3.0 * (n - m) as f64 + m as f64 + 6.0) * eps * (1.0 + op_norm)
                + rank as f64 * eps * ug);
        Self {
            n,
            rank,
            u,
            coef: LinearMap::new(rank, n1, g),
            gsum,
            rho,
        }
    }
}

/// `R^ = I - E A` in `f64`, row-major `(n+1) x (n+1)`, with the elevation coefficients
/// `E_il = C(m,l) C(n-m,i-l) / C(n,i)` computed once (each within `3 eps` of itself: the
/// binomials are exact in `u128`, then two roundings and a quotient).
fn residual_matrix(a: &[f64], n: usize, m: usize) -> Vec<f64> {
    let (n1, r) = (n + 1, n - m);
    let mut out = vec![0.0; n1 * n1];
    for i in 0..n1 {
        let band = i.saturating_sub(r)..=i.min(m);
        let coef: Vec<(usize, f64)> = band
            .map(|l| (l, cagd_core::kernel::elevation_coefficient(m, r, i, l)))
            .collect();
        let row = &mut out[i * n1..(i + 1) * n1];
        for (l, e) in &coef {
            for (x, y) in row.iter_mut().zip(&a[l * n1..(l + 1) * n1]) {
                *x += e * y;
            }
        }
        for (j, x) in row.iter_mut().enumerate() {
            *x = f64::from(u8::from(i == j)) - *x;
        }
    }
    out
}

/// An orthonormal basis of the range of the square matrix `r` (`n1 x n1`, row-major) by
/// pivoted modified Gram–Schmidt, each new vector orthogonalised twice: returns `U`
/// row-major `n1 x rank` and `rank`. Columns stop being taken when the largest remaining
/// column norm is below `8 n1 eps` of the largest initial one, or, once `expected`
/// columns are taken (the rank in exact arithmetic), below `1e-11` of it (what is left
/// is rounding of `R` itself and goes into the measured residual).
fn orthonormal_range(r: &[f64], n1: usize, expected: usize) -> (Vec<f64>, usize) {
    // Columns of R as contiguous vectors (the remainders after projection).
    let mut cols: Vec<Vec<f64>> = (0..n1)
        .map(|j| (0..n1).map(|i| r[i * n1 + j]).collect())
        .collect();
    let norm2 = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>();
    let top = cols.iter().map(|c| norm2(c)).fold(0.0, f64::max).sqrt();
    let stop = 8.0 * n1 as f64 * f64::EPSILON * top;
    let mut basis: Vec<Vec<f64>> = Vec::new();
    while basis.len() < n1 {
        let (best, size) = cols
            .iter()
            .enumerate()
            .map(|(j, c)| (j, norm2(c).sqrt()))
            .fold((0, 0.0), |acc, x| if x.1 > acc.1 { x } else { acc });
        if size <= stop || size.is_nan() || (basis.len() >= expected && size <= 1e-11 * top) {
            break;
        }
        let mut q = cols[best].clone();
        // Second orthogonalisation against the basis taken so far.
        for b in &basis {
            let d: f64 = b.iter().zip(&q).map(|(x, y)| x * y).sum();
            q.iter_mut().zip(b).for_each(|(y, x)| *y -= d * x);
        }
        let s = norm2(&q).sqrt();
        q.iter_mut().for_each(|y| *y /= s);
        for c in &mut cols {
            let d: f64 = q.iter().zip(c.iter()).map(|(x, y)| x * y).sum();
            c.iter_mut().zip(&q).for_each(|(y, x)| *y -= d * x);
        }
        basis.push(q);
    }
    let rank = basis.len();
    let mut u = vec![0.0; n1 * rank];
    for (k, b) in basis.iter().enumerate() {
        for (i, x) in b.iter().enumerate() {
            u[i * rank + k] = *x;
        }
    }
    (u, rank)
}

#[cfg(test)]
mod tests {
    use super::super::operator;
    use super::*;
    use crate::Method;

    #[test]
    fn rank_is_n_minus_m_and_the_residual_is_rounding() {
        for method in [
            Method::L2 { r: 0, p: 0 },
            Method::GeneralizedInverse,
            Method::Forrest,
            Method::ConstrainedChebyshev { r: 1, p: 1 },
        ] {
            for (n, m) in [
                (4, 3),
                (5, 4),
                (10, 5),
                (15, 10),
                (20, 10),
                (30, 15),
                (64, 32),
            ] {
                let Ok(op) = operator(method, n, m) else {
                    continue;
                };
                let b = ErrorBasis::new(op.matrix(), n, m, op.norm_inf());
                assert_eq!(b.rank, n - m, "{method:?} ({n},{m})");
                println!(
                    "{method:?} ({n},{m}): rho {:e}, |A| {}",
                    b.rho,
                    op.norm_inf()
                );
                assert!(
                    b.rho <= 1e-12 * (1.0 + op.norm_inf()),
                    "{method:?} ({n},{m}): rho {:e}",
                    b.rho
                );
                // U is orthonormal.
                let r = b.rank;
                for k in 0..r {
                    for l in 0..r {
                        let d: f64 = (0..=n).map(|i| b.u[i * r + k] * b.u[i * r + l]).sum();
                        let want = f64::from(u8::from(k == l));
                        assert!((d - want).abs() < 1e-13, "{method:?} ({n},{m}) {k} {l}");
                    }
                }
            }
        }
    }
}
