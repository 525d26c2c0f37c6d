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
//!
//! The symmetric split (goes beyond the seed): for a method symmetric under reversal
//! (`A J_n = J_m A`, `J` the reversal of the points: L2 with equal end orders, the
//! generalized inverse, the Chebyshev family, ...) `R` commutes with `J`, so its range is
//! the sum of its even part (`J u = u`, curves with `phi(1 - t) = phi(t)`) and its odd part
//! (`J u = -u`, `phi(1 - t) = -phi(t)`), of dimensions `ceil((n+1)/2) - ceil((m+1)/2)` and
//! `floor((n+1)/2) - floor((m+1)/2)` (`A` maps the even / odd points onto the even / odd
//! points of degree `m`, as `A E = I`). The basis is then taken part by part (two
//! Gram–Schmidt runs on half-length vectors: a quarter of the work) and its columns made
//! exactly even / odd by mirroring, so that the node maps need only the nodes of
//! `[0, 1/2]` (`error_map.rs`). Nothing else is assumed: `G = U^T R` and the residual `rho`
//! are computed from the actual `R` as before, so a method that is only nearly symmetric
//! only loosens the bound.

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
    /// `Some(r_e)` for the symmetric split: columns `0..r_e` of `U` are exactly even
    /// (`U_(n-i)k = U_ik`), the others exactly odd (`U_(n-i)k = -U_ik`).
    pub(crate) even: Option<usize>,
}

/// Largest reversal asymmetry `max_i sum_j |A_ij - A_(m-i)(n-j)|`, per unit of `1 +
/// ||A||_inf`, for which the symmetric split is taken (operators built to `1e-12`
/// relative; a larger asymmetry would show in `rho`, never break the bound).
const SYMMETRY_TOLERANCE: f64 = 1e-12;

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
        let top = (0..n1)
            .map(|j| (0..n1).map(|i| r_mat[i * n1 + j].powi(2)).sum::<f64>())
            .fold(0.0, f64::max)
            .sqrt();
        let (u, rank, even) = if reversal_asymmetry(a, n, m) <= SYMMETRY_TOLERANCE * (1.0 + op_norm)
        {
            symmetric_range(&r_mat, n, m, top)
        } else {
            let (u, rank) = orthonormal_range(&r_mat, n1, n1, n - m, top);
            (u, rank, None)
        };
        // G = U^T R, row-major r x n1.
        // G = U^T R and U G through the GEMM kernel (the rounding bounds below hold for
        // any order of the sums).
        // Row-major data read as column-major is the transpose: `R^T` and `U^T` need no
        // copy, `G^T = R^T U` is `G` row-major and `G^T U^T` is `U G` row-major.
        let rt = DMatrix::from_column_slice(n1, n1, &r_mat);
        let ut = DMatrix::from_column_slice(rank, n1, &u);
        let gt = rt * ut.transpose();
        let ugm = &gt * &ut;
        let g: Vec<f64> = gt.as_slice().to_vec();
        let ugm = ugm.as_slice();
        let gsum: Vec<f64> = g
            .chunks_exact(n1)
            .map(|row| row.iter().map(|x| x.abs()).sum())
            .collect();
        let (mut measured, mut ug): (f64, f64) = (0.0, 0.0);
        for i in 0..n1 {
            let urow = &u[i * rank..(i + 1) * rank];
            let mut row = 0.0;
            for j in 0..n1 {
                row += (r_mat[i * n1 + j] - ugm[i * n1 + j]).abs();
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
            even,
        }
    }
}

/// `max_i sum_j |A_ij - A_(m-i)(n-j)|` for the row-major `(m+1) x (n+1)` matrix `a`.
fn reversal_asymmetry(a: &[f64], n: usize, m: usize) -> f64 {
    let n1 = n + 1;
    (0..=m)
        .map(|i| {
            (0..n1)
                .map(|j| (a[i * n1 + j] - a[(m - i) * n1 + (n - j)]).abs())
                .sum::<f64>()
        })
        .fold(0.0, f64::max)
}

/// The basis of the range of `r` (`(n+1) x (n+1)`, row-major, commuting with the reversal
/// up to rounding) as `r_e` exactly even columns followed by exactly odd ones: returns `U`
/// (row-major `(n+1) x rank`), `rank` and `Some(r_e)`.
///
/// An even vector `v` is held as its half `w` (`w_i = sqrt 2 v_i` for `i < n - i`, `w_i =
/// v_i` in the middle), an odd one as `w_i = sqrt 2 v_i` (`i < n - i`; its middle is zero),
/// so that `||w|| = ||v||`; the spanning vectors are the halves of the even part of `R
/// (e_j + e_(n-j)) / 2` and of the odd part of `R (e_j - e_(n-j)) / 2` (for `R J = J R`
/// the other columns repeat them up to sign). After the Gram–Schmidt runs each basis vector
/// is unfolded by mirroring its half, so the parity is exact whatever the rounding.
fn symmetric_range(r: &[f64], n: usize, m: usize, top: f64) -> (Vec<f64>, usize, Option<usize>) {
    let n1 = n + 1;
    let (half_e, half_o) = (n / 2 + 1, n1 / 2);
    let (exp_e, exp_o) = (half_e - (m / 2 + 1), half_o - m.div_ceil(2));
    let s2 = std::f64::consts::SQRT_2;
    let at = |i: usize, j: usize| r[i * n1 + j];
    // Column j of the folded matrices, row i of the half (row-major, square).
    let fold = |sign: f64, half: usize| -> Vec<f64> {
        let mut out = vec![0.0; half * half];
        for i in 0..half {
            for j in 0..half {
                let col = |ii: usize| {
                    if j == n - j {
                        at(ii, j)
                    } else {
                        0.5 * (at(ii, j) + sign * at(ii, n - j))
                    }
                };
                out[i * half + j] = if i == n - i {
                    col(i)
                } else {
                    (col(i) + sign * col(n - i)) / s2
                };
            }
        }
        out
    };
    let (ue, re) = orthonormal_range(&fold(1.0, half_e), half_e, half_e, exp_e, top);
    let (uo, ro) = orthonormal_range(&fold(-1.0, half_o), half_o, half_o, exp_o, top);
    let rank = re + ro;
    let mut u = vec![0.0; n1 * rank];
    for i in 0..half_e {
        let mirror = n - i;
        for k in 0..re {
            let w = ue[i * re + k];
            if i == mirror {
                u[i * rank + k] = w;
            } else {
                u[i * rank + k] = w / s2;
                u[mirror * rank + k] = w / s2;
            }
        }
    }
    for i in 0..half_o {
        let mirror = n - i;
        for k in 0..ro {
            let v = uo[i * ro + k] / s2;
            u[i * rank + re + k] = v;
            u[mirror * rank + re + k] = -v;
        }
    }
    (u, rank, Some(re))
}

/// `R^ = I - E A` in `f64`, row-major `(n+1) x (n+1)`, with the elevation coefficients
/// `E_il = C(m,l) C(n-m,i-l) / C(n,i)` computed once (each within `3 eps` of itself: the
/// binomials are exact in `u128`, then two roundings and a quotient). When every
/// `C(n, i)` is below `2^53` (`n <= 55`) the binomials are exact in `f64` as well and the
/// products `C(m,l) C(n-m,i-l) <= C(n,i)` too (Vandermonde), so the coefficient is the
/// same quotient of the same two numbers, from three small tables instead of a `u128`
/// product and two conversions per entry.
fn residual_matrix(a: &[f64], n: usize, m: usize) -> Vec<f64> {
    let (n1, r) = (n + 1, n - m);
    let mut out = vec![0.0; n1 * n1];
    let exact_f64 = cagd_core::binomial(n, n / 2) < 1u128 << 53;
    let table =
        |k: usize| -> Vec<f64> { (0..=k).map(|i| cagd_core::binomial(k, i) as f64).collect() };
    let (bm, br, bn) = if exact_f64 {
        (table(m), table(r), table(n))
    } else {
        (Vec::new(), Vec::new(), Vec::new())
    };
    for i in 0..n1 {
        let band = i.saturating_sub(r)..=i.min(m);
        let coef: Vec<(usize, f64)> = band
            .map(|l| {
                let e = if exact_f64 {
                    bm[l] * br[i - l] / bn[i]
                } else {
                    cagd_core::kernel::elevation_coefficient(m, r, i, l)
                };
                (l, e)
            })
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

/// An orthonormal basis of the range of the matrix `r` (`len x cols`, row-major) by
/// pivoted modified Gram–Schmidt, each new vector orthogonalised twice: returns `U`
/// row-major `len x rank` and `rank`. Columns stop being taken when the largest remaining
/// column norm is below `8 len eps` of `top` (the largest column norm of the whole `R`),
/// or, once `expected` columns are taken (the rank in exact arithmetic), below `1e-11` of
/// it (what is left is rounding of `R` itself and goes into the measured residual).
fn orthonormal_range(
    r: &[f64],
    len: usize,
    cols_n: usize,
    expected: usize,
    top: f64,
) -> (Vec<f64>, usize) {
    let n1 = len;
    // Columns of R as contiguous vectors (the remainders after projection).
    let mut cols: Vec<Vec<f64>> = (0..cols_n)
        .map(|j| (0..n1).map(|i| r[i * cols_n + j]).collect())
        .collect();
    let norm2 = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>();
    let stop = 8.0 * n1 as f64 * f64::EPSILON * top;
    let mut basis: Vec<Vec<f64>> = Vec::new();
    while basis.len() < n1.min(cols_n) {
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
                // Every method here is symmetric under reversal: the split is taken, with
                // the parts' sizes of exact arithmetic and exactly mirrored columns.
                let re = b.even.expect("symmetric split");
                assert_eq!(
                    re,
                    (n + 1).div_ceil(2) - (m + 1).div_ceil(2),
                    "{method:?} ({n},{m})"
                );
                for i in 0..=n {
                    for k in 0..b.rank {
                        let sign = if k < re { 1.0 } else { -1.0 };
                        assert_eq!(b.u[(n - i) * b.rank + k], sign * b.u[i * b.rank + k]);
                    }
                }
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

#[cfg(test)]
mod split_tests {
    use super::super::operator;
    use super::*;
    use crate::Method;

    /// The residual matrix from the `f64` binomial tables equals the one from the `u128`
    /// elevation coefficients bit for bit (the same quotient of the same numbers).
    #[test]
    fn residual_matrix_tables_equal_the_exact_coefficients() {
        for (n, m) in [(4, 3), (10, 5), (30, 15), (55, 20), (56, 30), (64, 32)] {
            let a: Vec<f64> = (0..(m + 1) * (n + 1))
                .map(|i| (i as f64 * 0.37).sin())
                .collect();
            let got = residual_matrix(&a, n, m);
            let (n1, r) = (n + 1, n - m);
            for i in 0..n1 {
                for j in 0..n1 {
                    let mut x = 0.0;
                    for l in i.saturating_sub(r)..=i.min(m) {
                        let e = cagd_core::kernel::elevation_coefficient(m, r, i, l);
                        x += e * a[l * n1 + j];
                    }
                    let want = f64::from(u8::from(i == j)) - x;
                    assert_eq!(
                        got[i * n1 + j].to_bits(),
                        want.to_bits(),
                        "({n},{m}) {i} {j}"
                    );
                }
            }
        }
    }

    /// A method that is not symmetric under reversal (different end orders) takes the
    /// general route, and its residual is as small.
    #[test]
    fn asymmetric_methods_take_the_general_route() {
        for (n, m) in [(10, 5), (15, 10)] {
            let op = operator(Method::L2 { r: 1, p: 0 }, n, m).unwrap();
            let b = ErrorBasis::new(op.matrix(), n, m, op.norm_inf());
            assert!(b.even.is_none());
            assert_eq!(b.rank, n - m);
            assert!(b.rho <= 1e-12 * (1.0 + op.norm_inf()), "rho {:e}", b.rho);
        }
    }

    /// The split and the general route span the same space: the split's `U U^T` projects
    /// the general route's basis onto itself.
    #[test]
    fn split_spans_the_general_range() {
        for (n, m) in [(4, 3), (5, 4), (10, 5), (20, 10), (31, 16)] {
            let op = operator(Method::L2 { r: 0, p: 0 }, n, m).unwrap();
            let n1 = n + 1;
            let r_mat = residual_matrix(op.matrix(), n, m);
            let (ug, rg) = orthonormal_range(&r_mat, n1, n1, n - m, 1.0);
            let b = ErrorBasis::new(op.matrix(), n, m, op.norm_inf());
            assert!(b.even.is_some());
            for k in 0..rg {
                let v: Vec<f64> = (0..n1).map(|i| ug[i * rg + k]).collect();
                let coef: Vec<f64> = (0..b.rank)
                    .map(|l| (0..n1).map(|i| b.u[i * b.rank + l] * v[i]).sum())
                    .collect();
                for (i, vi) in v.iter().enumerate() {
                    let p: f64 = (0..b.rank).map(|l| b.u[i * b.rank + l] * coef[l]).sum();
                    assert!((p - vi).abs() < 1e-13, "({n},{m}) {k} {i}");
                }
            }
        }
    }
}
