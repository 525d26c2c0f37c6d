//! Small dense LU factorizations of the `n x n` Bézout matrix at a point
//! (`n <= MAX_IMPLICIT_DEGREE`, row-major, in place): the determinant by partial pivoting
//! (SPEC-convert §15.8, "evaluate f at a point by an LU determinant, which is stable") and a
//! kernel vector by complete pivoting (inversion).

/// The determinant of the row-major `n x n` matrix `m` (destroyed), by Gaussian
/// elimination with partial pivoting.
pub(crate) fn det_in_place(m: &mut [f64], n: usize) -> f64 {
    let mut det = 1.0;
    for k in 0..n {
        let mut p = k;
        let mut best = m[k * n + k].abs();
        for i in k + 1..n {
            let v = m[i * n + k].abs();
            if v > best {
                best = v;
                p = i;
            }
        }
        if best == 0.0 {
            return 0.0;
        }
        if p != k {
            for j in k..n {
                m.swap(k * n + j, p * n + j);
            }
            det = -det;
        }
        let piv = m[k * n + k];
        det *= piv;
        for i in k + 1..n {
            let f = m[i * n + k] / piv;
            if f != 0.0 {
                for j in k + 1..n {
                    m[i * n + j] -= f * m[k * n + j];
                }
            }
        }
    }
    det
}

/// The result of [`null_vector`].
#[derive(Debug, Clone)]
pub(crate) struct Kernel {
    /// A vector `v` with `M v ≈ 0` (the last pivot's column set free), max-norm 1.
    pub(crate) v: Vec<f64>,
    /// `|u_kk|` of the complete-pivoting factorization, non-increasing in exact arithmetic:
    /// the rank is read from the ratios `pivots[k] / pivots[0]`.
    pub(crate) pivots: Vec<f64>,
}

/// Complete-pivoting LU of `m` (destroyed) and the kernel vector that sets the last
/// unknown to 1.
pub(crate) fn null_vector(m: &mut [f64], n: usize) -> Kernel {
    let mut cols: Vec<usize> = (0..n).collect();
    let mut pivots = vec![0.0; n];
    for k in 0..n {
        let (mut pi, mut pj, mut best) = (k, k, -1.0);
        for i in k..n {
            for j in k..n {
                let v = m[i * n + j].abs();
                if v > best {
                    best = v;
                    pi = i;
                    pj = j;
                }
            }
        }
        if pi != k {
            for j in 0..n {
                m.swap(k * n + j, pi * n + j);
            }
        }
        if pj != k {
            for i in 0..n {
                m.swap(i * n + k, i * n + pj);
            }
            cols.swap(k, pj);
        }
        pivots[k] = best;
        let piv = m[k * n + k];
        if piv == 0.0 {
            continue;
        }
        for i in k + 1..n {
            let f = m[i * n + k] / piv;
            m[i * n + k] = 0.0;
            if f != 0.0 {
                for j in k + 1..n {
                    m[i * n + j] -= f * m[k * n + j];
                }
            }
        }
    }
    // Back substitution of U z = 0 with z_{n-1} = 1.
    let mut z = vec![0.0; n];
    if n > 0 {
        z[n - 1] = 1.0;
    }
    for k in (0..n.saturating_sub(1)).rev() {
        let mut s = 0.0;
        for j in k + 1..n {
            s += m[k * n + j] * z[j];
        }
        let piv = m[k * n + k];
        z[k] = if piv == 0.0 { 0.0 } else { -s / piv };
    }
    let mut v = vec![0.0; n];
    for k in 0..n {
        v[cols[k]] = z[k];
    }
    let norm = v.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
    if norm > 0.0 {
        v.iter_mut().for_each(|x| *x /= norm);
    }
    Kernel { v, pivots }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn determinant_with_pivoting() {
        let mut m = vec![0.0, 2.0, 1.0, 3.0, 1.0, 0.0, 1.0, 1.0, 1.0];
        // det = 0*(1-0) - 2*(3-0) + 1*(3-1) = -4
        assert!((det_in_place(&mut m, 3) + 4.0).abs() < 1e-15);
        assert_eq!(det_in_place(&mut [0.0, 0.0, 0.0, 1.0], 2), 0.0);
    }

    #[test]
    fn kernel_of_a_rank_deficient_matrix() {
        // Rows 1 and 3 dependent: kernel spanned by (1, -2, 1) for [[1,2,3],[4,5,6],[7,8,9]].
        let a = vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0];
        let k = null_vector(&mut a.clone(), 3);
        for i in 0..3 {
            let r: f64 = (0..3).map(|j| a[i * 3 + j] * k.v[j]).sum();
            assert!(r.abs() < 1e-13, "{r}");
        }
        assert!(k.pivots[2] < 1e-14 * k.pivots[0]);
        assert!(k.pivots[1] > 0.1);
    }
}
