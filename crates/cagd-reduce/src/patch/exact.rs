//! Building blocks of the patch reducers: exact-rational matrices rounded once to `f64`
//! (cached process-wide), a small row-major `f64` matrix, and the stable inverse elevation
//! of curves (two-sided, SPEC-reduce §2.1 ADDED).

use std::collections::HashMap;
use std::hash::Hash;
use std::sync::{Arc, OnceLock, PoisonError, RwLock};

use cagd_core::{ExactMatrix, Result, binomial};
use num_bigint::BigInt;
use num_rational::BigRational;

/// A process-wide cache of built operators.
pub(crate) type Cache<K, V> = OnceLock<RwLock<HashMap<K, Arc<V>>>>;

/// The cached value for `key`, built by `build` on first use (thread-safe).
pub(crate) fn cached<K: Hash + Eq, V>(
    cache: &'static Cache<K, V>,
    key: K,
    build: impl FnOnce() -> Result<V>,
) -> Result<Arc<V>> {
    let map = cache.get_or_init(|| RwLock::new(HashMap::new()));
    if let Ok(m) = map.read() {
        if let Some(v) = m.get(&key) {
            return Ok(Arc::clone(v));
        }
    }
    let v = Arc::new(build()?);
    // A poisoned lock only means another thread panicked while inserting; the map is valid.
    let mut m = map.write().unwrap_or_else(PoisonError::into_inner);
    Ok(Arc::clone(m.entry(key).or_insert(v)))
}

/// An exact integer as a rational.
pub(crate) fn q_int(x: u128) -> BigRational {
    BigRational::from_integer(BigInt::from(x))
}

/// `C(n, k)` as an exact rational.
pub(crate) fn q_binom(n: usize, k: usize) -> BigRational {
    q_int(binomial(n, k))
}

/// A dense row-major `f64` matrix (an exact matrix rounded once).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Mat {
    pub(crate) rows: usize,
    pub(crate) cols: usize,
    pub(crate) data: Vec<f64>,
}

impl Mat {
    /// Every entry of `e` rounded once to the nearest `f64`.
    pub(crate) fn round(e: &ExactMatrix) -> Self {
        let f = e.to_f64();
        let (rows, cols) = (e.nrows(), e.ncols());
        let data = (0..rows)
            .flat_map(|i| (0..cols).map(move |j| (i, j)))
            .map(|(i, j)| f[(i, j)])
            .collect();
        Self { rows, cols, data }
    }

    /// Entry `(i, j)`.
    pub(crate) fn at(&self, i: usize, j: usize) -> f64 {
        self.data[i * self.cols + j]
    }

    /// `out_i = sum_j a_ij x_j` for points of `dim` coordinates (`x`: `cols` points, `out`:
    /// `rows` points), accumulated into `out` when `accumulate`, else overwriting it.
    pub(crate) fn apply(&self, x: &[f64], dim: usize, out: &mut [f64], accumulate: bool) {
        debug_assert_eq!(x.len(), self.cols * dim);
        debug_assert_eq!(out.len(), self.rows * dim);
        if !accumulate {
            out.fill(0.0);
        }
        for (row, o) in self
            .data
            .chunks_exact(self.cols)
            .zip(out.chunks_exact_mut(dim))
        {
            for (a, p) in row.iter().zip(x.chunks_exact(dim)) {
                if *a != 0.0 {
                    for (ok, pk) in o.iter_mut().zip(p) {
                        *ok += a * pk;
                    }
                }
            }
        }
    }
}

/// The exact curve elevation matrix from degree `k - 1` to `k`, `(k + 1) x k`:
/// `a_{i,i} = (k - i) / k`, `a_{i,i-1} = i / k` (seed 000 eq. 14.4.2).
pub(crate) fn elevation_exact(k: usize) -> ExactMatrix {
    let kk = BigInt::from(k);
    ExactMatrix::from_fn(k + 1, k, |i, j| {
        if j == i {
            BigRational::new(BigInt::from(k - i), kk.clone())
        } else if j + 1 == i {
            BigRational::new(BigInt::from(i), kk.clone())
        } else {
            BigRational::from_integer(BigInt::from(0))
        }
    })
}

/// The exact pseudo-inverse `(E_Sᵀ E_S)^-1 E_Sᵀ` of the columns `cols` of a matrix `e` of
/// full column rank (the least-squares solution operator restricted to those unknowns).
///
/// # Errors
/// [`cagd_core::Error::Singular`] when the selected columns are dependent.
pub(crate) fn pinv_columns(e: &ExactMatrix, cols: &[usize]) -> Result<ExactMatrix> {
    let sub = ExactMatrix::from_fn(e.nrows(), cols.len(), |i, j| {
        e.get(i, cols[j]).cloned().unwrap_or_default()
    });
    let st = sub.transpose();
    st.mul(&sub)?.inverse()?.mul(&st)
}

/// Inverse of the curve elevation `k - 1 -> k` for `k + 1` points (`dim` coordinates) that
/// are (numerically) an elevated curve: forward recursion (eq. 14.2.3) for the first half,
/// backward for the second (SPEC-reduce §2.1: rounding error ~1e-16, not `prod i/(k-i)`).
/// Writes `k` points to `out`.
pub(crate) fn inverse_elevate(p: &[f64], dim: usize, out: &mut [f64]) {
    let k = p.len() / dim - 1;
    debug_assert!(k >= 1 && out.len() == k * dim);
    let kf = k as f64;
    let h = (k - 1) / 2;
    out[..dim].copy_from_slice(&p[..dim]);
    for i in 1..=h {
        let (done, rest) = out.split_at_mut(i * dim);
        let prev = &done[(i - 1) * dim..];
        let fi = i as f64;
        for c in 0..dim {
            rest[c] = (kf * p[i * dim + c] - fi * prev[c]) / (kf - fi);
        }
    }
    if k - 1 > h {
        out[(k - 1) * dim..].copy_from_slice(&p[k * dim..]);
        for i in ((h + 2)..k).rev() {
            let (head, tail) = out.split_at_mut(i * dim);
            let next = &tail[..dim];
            let fi = i as f64;
            for c in 0..dim {
                head[(i - 1) * dim + c] = (kf * p[i * dim + c] - (kf - fi) * next[c]) / fi;
            }
        }
    }
}

/// `max_i ||x_i||` (Euclidean) over the points of a buffer.
pub(crate) fn max_norm(x: &[f64], dim: usize) -> f64 {
    x.chunks_exact(dim).map(norm).fold(0.0, f64::max)
}

/// Euclidean norm of one point.
pub(crate) fn norm(p: &[f64]) -> f64 {
    p.iter().map(|v| v * v).sum::<f64>().sqrt()
}

/// `max_i ||a_i - b_i||` over two buffers of the same layout.
pub(crate) fn max_diff(a: &[f64], b: &[f64], dim: usize) -> f64 {
    a.chunks_exact(dim)
        .zip(b.chunks_exact(dim))
        .map(|(x, y)| {
            x.iter()
                .zip(y)
                .map(|(s, t)| (s - t) * (s - t))
                .sum::<f64>()
                .sqrt()
        })
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_elevation_undoes_elevation() {
        for k in 1..12 {
            let q: Vec<f64> = (0..k * 2).map(|i| ((i * 7 % 5) as f64) - 1.5).collect();
            let mut p = vec![0.0; (k + 1) * 2];
            cagd_core::kernel::elevate(&q, 2, 1, &mut p);
            let mut back = vec![0.0; k * 2];
            inverse_elevate(&p, 2, &mut back);
            assert!(max_diff(&q, &back, 2) < 1e-14, "k = {k}");
        }
    }

    #[test]
    fn pinv_of_full_elevation_is_left_inverse() {
        let e = elevation_exact(5);
        let all: Vec<usize> = (0..5).collect();
        assert!(
            pinv_columns(&e, &all)
                .unwrap()
                .mul(&e)
                .unwrap()
                .is_identity()
        );
    }
}
