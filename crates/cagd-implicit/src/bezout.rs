//! The Bézout matrix `F = x A + y B + C0` of a planar rational Bézier curve
//! (SPEC-convert §15.8, eqs. 15.8.2–15.8.5, with the errata: `l_ij` carries
//! `C(n,i) C(n,j)`, and the upper limit of 15.8.3 is `min(h, k)`).
//!
//! `l_ij(x, y) = C(n,i) C(n,j) det[[x, y, 1], [X_i, Y_i, W_i], [X_j, Y_j, W_j]]` is linear in
//! `(x, y)`; `L_hk = sum_{l = max(0, h+k+1-n)}^{min(h,k)} l_{l, h+k+1-l}` for
//! `h, k = 0..n-1`; `f(x, y) = det F = (-1)^(n(n+1)/2) Res_t(W x - X, W y - Y)`.

use cagd_core::{BezierCurve, Result, binomial_f64};

use crate::lu::det_in_place;
use crate::planar::{check_planar, weight};

/// The three constant symmetric `n x n` matrices of `F(x, y) = x A + y B + C0`
/// (eq. 15.8.4), row-major.
#[derive(Debug, Clone, PartialEq)]
pub struct BezoutMatrix {
    n: usize,
    a: Vec<f64>,
    b: Vec<f64>,
    c: Vec<f64>,
}

impl BezoutMatrix {
    /// The Bézout matrix of a planar curve of degree `n >= 1` (rational or polynomial).
    /// Each `l_ij` is formed as `C(n,i) C(n,j) w_i w_j det[[x,y,1],[x_i,y_i,1],[x_j,y_j,1]]`
    /// (eq. 15.8.2, Euclidean form, no cancellation between weights).
    ///
    /// # Errors
    /// [`cagd_core::Error::NotPlanar`], [`cagd_core::Error::DegreeOutOfRange`].
    ///
    /// ```
    /// use cagd_core::BezierCurve;
    /// use cagd_implicit::BezoutMatrix;
    /// // SPEC-convert §15.8 inline example: f = -16 x^2 + 32 x - 16 y.
    /// let c = BezierCurve::new(vec![0.0, 0.0, 1.0, 2.0, 2.0, 0.0], 2)?;
    /// let f = BezoutMatrix::new(&c)?;
    /// assert_eq!(f.at(0.0, 0.0), vec![0.0, 0.0, 0.0, -8.0]);
    /// assert_eq!(f.det_at(1.0, 1.0), -16.0 + 32.0 - 16.0);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn new(curve: &BezierCurve) -> Result<Self> {
        check_planar(curve)?;
        let n = curve.degree();
        Ok(Self::assemble(n, |i, j| {
            let (pi, pj) = (curve.point(i), curve.point(j));
            let s = binomial_f64(n, i) * binomial_f64(n, j) * weight(curve, i) * weight(curve, j);
            [
                s * (pi[1] - pj[1]),
                -s * (pi[0] - pj[0]),
                s * (pi[0] * pj[1] - pi[1] * pj[0]),
            ]
        }))
    }

    /// The Bézout matrix of homogeneous control points `(X_i, Y_i, W_i)` (any signs; used
    /// after base points are divided out).
    pub(crate) fn from_homogeneous(hom: &[[f64; 3]]) -> Self {
        let n = hom.len() - 1;
        Self::assemble(n, |i, j| {
            let (p, r) = (hom[i], hom[j]);
            let s = binomial_f64(n, i) * binomial_f64(n, j);
            [
                s * (p[1] * r[2] - p[2] * r[1]),
                -s * (p[0] * r[2] - p[2] * r[0]),
                s * (p[0] * r[1] - p[1] * r[0]),
            ]
        })
    }

    /// Assembles `L_hk` (eq. 15.8.3 with the upper limit `min(h, k)`) from `l(i, j)`,
    /// `i < j`, the coefficients of `x`, `y`, 1.
    fn assemble(n: usize, l: impl Fn(usize, usize) -> [f64; 3]) -> Self {
        let mut a = vec![0.0; n * n];
        let mut b = vec![0.0; n * n];
        let mut c = vec![0.0; n * n];
        for h in 0..n {
            for k in h..n {
                let (mut sa, mut sb, mut sc) = (0.0, 0.0, 0.0);
                for m in (h + k + 1).saturating_sub(n)..=h.min(k) {
                    let j = h + k + 1 - m;
                    // m < j always (m <= min(h,k) < h + k + 1 - m).
                    let t = l(m, j);
                    sa += t[0];
                    sb += t[1];
                    sc += t[2];
                }
                for (mat, v) in [(&mut a, sa), (&mut b, sb), (&mut c, sc)] {
                    mat[h * n + k] = v;
                    mat[k * n + h] = v;
                }
            }
        }
        BezoutMatrix { n, a, b, c }
    }

    /// The size `n` of the matrices (the curve degree).
    pub fn size(&self) -> usize {
        self.n
    }

    /// `A`, the coefficient of `x` (row-major `n x n`).
    pub fn a(&self) -> &[f64] {
        &self.a
    }

    /// `B`, the coefficient of `y` (row-major `n x n`).
    pub fn b(&self) -> &[f64] {
        &self.b
    }

    /// `C0`, the constant term (row-major `n x n`).
    pub fn c0(&self) -> &[f64] {
        &self.c
    }

    /// `F(x, y)` into `out` (`n * n` doubles, row-major).
    pub fn at_into(&self, x: f64, y: f64, out: &mut [f64]) {
        for (k, o) in out.iter_mut().enumerate().take(self.n * self.n) {
            *o = x * self.a[k] + y * self.b[k] + self.c[k];
        }
    }

    /// `F(x, y)` (row-major `n x n`).
    pub fn at(&self, x: f64, y: f64) -> Vec<f64> {
        let mut out = vec![0.0; self.n * self.n];
        self.at_into(x, y, &mut out);
        out
    }

    /// `f(x, y) = det F(x, y)` by an LU factorization with partial pivoting (backward
    /// stable; no allocation up to `MAX_IMPLICIT_DEGREE`).
    pub fn det_at(&self, x: f64, y: f64) -> f64 {
        const CAP: usize = crate::MAX_IMPLICIT_DEGREE * crate::MAX_IMPLICIT_DEGREE;
        let nn = self.n * self.n;
        let mut buf = [0.0; CAP];
        let m = &mut buf[..nn];
        self.at_into(x, y, m);
        det_in_place(m, self.n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spec_matrix_at_origin() {
        // impl-n2-conic-weighted: F(0,0) = [[2,2],[2,4]].
        let c =
            BezierCurve::new_rational(vec![1.0, 0.0, 1.0, 1.0, 0.0, 1.0], vec![1.0, 1.0, 2.0], 2)
                .unwrap();
        let f = BezoutMatrix::new(&c).unwrap();
        assert_eq!(f.at(0.0, 0.0), vec![2.0, 2.0, 2.0, 4.0]);
        // f = 4 - 4x^2 - 4y^2 vanishes on the unit circle.
        assert!(f.det_at(0.6, 0.8).abs() < 1e-14);
        assert_eq!(f.det_at(0.0, 0.0), 4.0);
        // The homogeneous route gives the same matrices.
        let g = BezoutMatrix::from_homogeneous(&crate::planar::homogeneous_f64(&c));
        assert_eq!(f, g);
    }

    #[test]
    fn matrices_are_symmetric_and_vanish_at_the_end_points() {
        let c =
            BezierCurve::new(vec![0.0, 0.0, 1.0, 3.0, 3.0, 3.0, 4.0, 0.0, 5.0, 2.0], 2).unwrap();
        let f = BezoutMatrix::new(&c).unwrap();
        let n = f.size();
        for h in 0..n {
            for k in 0..n {
                assert_eq!(f.a()[h * n + k], f.a()[k * n + h]);
                assert_eq!(f.c0()[h * n + k], f.c0()[k * n + h]);
            }
        }
        // First row of F(P_0) vanishes (seed §15.8 proof): det is exactly 0.
        assert_eq!(f.det_at(0.0, 0.0), 0.0);
        assert!(f.det_at(5.0, 2.0).abs() < 1e-9);
    }
}
