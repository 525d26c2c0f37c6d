//! The certified bound as a linear map of the input (goes beyond the seed; its convex-hull
//! argument is seed 000 §14.4.3): the error curve `D = P - E Q` (`E` = elevation `m -> n`,
//! `Q = A P` the reduction) is `R P` with `R = I - E A`, and its `2^k` pieces after `k`
//! midpoint subdivisions are `S_k R P`, one precomputed `(2^k (n+1)) x (n+1)` map `T`.
//! Each piece lies in the convex hull of its control points, so the largest control-point
//! norm bounds `max_t ||D(t)||`; it exceeds the true maximum by `O(4^-k)` of `D''`.

use super::super::gemm::LinearMap;

/// The precomputed map `T = S_k (I - E A)` and the rounding allowance of its use.
#[derive(Debug, Clone)]
pub(crate) struct BoundMap {
    /// `T`, rows = piece control points, piece after piece.
    pub(crate) map: LinearMap,
    /// Rounding allowance per unit of `max_j ||P_j||` (see [`BoundMap::new`]).
    pub(crate) slack: f64,
}

impl BoundMap {
    /// `T` for the `f64` operator `a` (`(m+1) x (n+1)`, row-major) with `op_norm =
    /// max_i sum_j |a_ij|`, split into `2^levels` pieces.
    ///
    /// Rounding (`eps` = unit roundoff, `n1 = n + 1`): the reduced points are `fl(A P) =
    /// A P + d1` with `|d1| <= gamma_{n1} |A| |P|`; `T` itself is computed with
    /// `|fl(T) - S_k (I - E A)| <= gamma_{k n + m + 3} (1 + ||A||)` per row sum (elevation and
    /// subtraction, then `k` de Casteljau splits, all convex combinations); and
    /// `fl(T P) = T P + d2` with `|d2| <= gamma_{n1} |T| |P|`. `S_k E` has non-negative rows
    /// summing to 1, so every control point of the true pieces of `P - E fl(A P)` is within
    /// `(n1 (||T|| + ||A||) + (k n + m + 3)(1 + ||A||)) eps (1 + O(eps)) max_j ||P_j||` of
    /// the computed one; `slack` is twice that factor.
    pub(crate) fn new(a: &[f64], n: usize, m: usize, op_norm: f64, levels: usize) -> Self {
        let (n1, m1) = (n + 1, m + 1);
        let pieces = 1usize << levels;
        // R = I - E A, column by column (column j is the error curve of the unit input e_j).
        let mut col = vec![0.0; m1];
        let mut elevated = vec![0.0; n1];
        let mut t = vec![0.0; pieces * n1 * n1];
        let mut work = vec![0.0; pieces * n1];
        let (mut left, mut right) = (vec![0.0; n1], vec![0.0; n1]);
        for j in 0..n1 {
            for (i, c) in col.iter_mut().enumerate() {
                *c = a[i * n1 + j];
            }
            cagd_core::kernel::elevate(&col, 1, n - m, &mut elevated);
            for (i, e) in elevated.iter_mut().enumerate() {
                *e = f64::from(u8::from(i == j)) - *e;
            }
            // Split level by level: `work` holds the current pieces, in parameter order.
            work[..n1].copy_from_slice(&elevated);
            for level in 0..levels {
                let count = 1usize << level;
                for p in (0..count).rev() {
                    cagd_core::kernel::subdivide(
                        &work[p * n1..(p + 1) * n1],
                        1,
                        0.5,
                        &mut left,
                        &mut right,
                    );
                    work[2 * p * n1..(2 * p + 1) * n1].copy_from_slice(&left);
                    work[(2 * p + 1) * n1..(2 * p + 2) * n1].copy_from_slice(&right);
                }
            }
            for (row, v) in work.iter().enumerate() {
                t[row * n1 + j] = *v;
            }
        }
        let t_norm = t
            .chunks_exact(n1)
            .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
            .fold(0.0, f64::max);
        let eps = f64::EPSILON;
        let slack = 2.0
            * eps
            * ((n1 as f64) * (t_norm + op_norm) + ((levels * n + m + 3) as f64) * (1.0 + op_norm));
        Self {
            map: LinearMap::new(pieces * n1, n1, t),
            slack,
        }
    }
}
