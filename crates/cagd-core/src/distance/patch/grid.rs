//! Fast evaluators for the patch distances (ADDED, beyond the seed): Bernstein bases
//! cached per grid line instead of a de Casteljau pyramid per point.
//!
//! A tensor patch of degrees `(m, n)` is `sum_i sum_j B^m_i(u) B^n_j(v) P_ij`; on the
//! sampling grid the `u` basis of a row and the `v` basis of a column are computed once, so
//! a grid of `(N + 1)^2` nodes costs `O(N m n + N^2 n)` instead of `O(N^2 m n^2)`.
//!
//! A triangular patch of degree `n` is `sum_i B^n_i(u) C_i(t)`, `t = v / (1 - u)`, where
//! `C_i` is the Bézier curve of degree `n - i` through row `i` of the net (the
//! multinomial `n! / (i! j! k!) u^i v^j w^k = B^n_i(u) B^(n-i)_j(t)` with `w = 1 - u - v`).
//! Elevated once to degree `n`, the rows give a point in `O(n^2)` (one combination of the
//! elevated rows, one curve in `t`) instead of the `O(n^3)` triangular de Casteljau.
//!
//! Both are sums of non-negative basis values times control points, so their rounding is
//! of the same order as de Casteljau's (a few `n` ulp of the largest control point).

use crate::kernel::elevate;
use crate::{TensorPatch, TriPatch, binomial_f64, tri_index};

/// The Bernstein basis of one degree with its binomials converted once (the `u128` table
/// conversion of [`crate::kernel::bernstein_all`] dominated the grid otherwise).
struct Basis {
    binom: Vec<f64>,
}

impl Basis {
    fn new(n: usize) -> Self {
        Self {
            binom: (0..=n).map(|k| binomial_f64(n, k)).collect(),
        }
    }

    /// `B^n_i(t)`, `i = 0..=n`, into `out` (the products of
    /// [`crate::kernel::bernstein_all`]).
    fn fill(&self, t: f64, out: &mut [f64]) {
        let s = 1.0 - t;
        let mut p = 1.0;
        for o in out.iter_mut() {
            *o = p;
            p *= t;
        }
        let mut q = 1.0;
        for (o, c) in out.iter_mut().zip(&self.binom).rev() {
            *o *= q * c;
            q *= s;
        }
    }
}

/// Parameter of grid node `i` of `n` intervals: `i / n`, exactly 1 at `i = n` (the nodes
/// [`super::max_distance_2d`] samples).
pub(super) fn node(i: usize, n: usize) -> f64 {
    if i == n {
        1.0
    } else {
        i as f64 * (1.0 / n as f64)
    }
}

/// A tensor patch with point evaluation by its two Bernstein bases.
pub(super) struct TensorEval<'a> {
    patch: &'a TensorPatch,
    basis: (Basis, Basis),
}

impl<'a> TensorEval<'a> {
    pub(super) fn new(patch: &'a TensorPatch) -> Self {
        let (m, n) = patch.degrees();
        Self {
            patch,
            basis: (Basis::new(m), Basis::new(n)),
        }
    }

    /// `P(u, v)` into `out` (`dim` values).
    pub(super) fn eval(&self, u: f64, v: f64, out: &mut [f64]) {
        let (m, n) = self.patch.degrees();
        let dim = self.patch.dim();
        let (mut bu, mut bv) = (vec![0.0; m + 1], vec![0.0; n + 1]);
        self.basis.0.fill(u, &mut bu);
        self.basis.1.fill(v, &mut bv);
        out.fill(0.0);
        let pts = self.patch.points();
        for (i, &a) in bu.iter().enumerate() {
            for (j, &b) in bv.iter().enumerate() {
                let w = a * b;
                let at = (i * (n + 1) + j) * dim;
                for (o, p) in out.iter_mut().zip(&pts[at..at + dim]) {
                    *o += w * p;
                }
            }
        }
    }

    /// The patch at every grid node `(node(a, n_grid), node(b, n_grid))`, `a, b` in
    /// `0..=n_grid`: node `(a, b)` at `(a (n_grid + 1) + b) dim`.
    pub(super) fn grid(&self, n_grid: usize) -> Vec<f64> {
        let (m, n) = self.patch.degrees();
        let dim = self.patch.dim();
        let pts = self.patch.points();
        let bv: Vec<Vec<f64>> = (0..=n_grid)
            .map(|b| {
                let mut row = vec![0.0; n + 1];
                self.basis.1.fill(node(b, n_grid), &mut row);
                row
            })
            .collect();
        let mut out = vec![0.0; (n_grid + 1) * (n_grid + 1) * dim];
        let (mut bu, mut q) = (vec![0.0; m + 1], vec![0.0; (n + 1) * dim]);
        for a in 0..=n_grid {
            self.basis.0.fill(node(a, n_grid), &mut bu);
            q.fill(0.0);
            for (i, &w) in bu.iter().enumerate() {
                let row = &pts[i * (n + 1) * dim..(i + 1) * (n + 1) * dim];
                for (x, p) in q.iter_mut().zip(row) {
                    *x += w * p;
                }
            }
            for (b, basis) in bv.iter().enumerate() {
                let o = &mut out[(a * (n_grid + 1) + b) * dim..][..dim];
                for (j, &w) in basis.iter().enumerate() {
                    for (x, p) in o.iter_mut().zip(&q[j * dim..(j + 1) * dim]) {
                        *x += w * p;
                    }
                }
            }
        }
        out
    }
}

/// A triangular patch with its rows elevated to the full degree (module docs).
pub(super) struct TriEval {
    n: usize,
    dim: usize,
    /// Row `i` elevated to degree `n`: `(n + 1) * (n + 1) * dim` values, row-major.
    rows: Vec<f64>,
    basis: Basis,
}

impl TriEval {
    pub(super) fn new(patch: &TriPatch) -> Self {
        let (n, dim) = (patch.degree(), patch.dim());
        let pts = patch.points();
        let mut rows = vec![0.0; (n + 1) * (n + 1) * dim];
        for i in 0..=n {
            let start = tri_index(n, i, 0) * dim;
            let row = &pts[start..start + (n - i + 1) * dim];
            elevate(
                row,
                dim,
                i,
                &mut rows[i * (n + 1) * dim..(i + 1) * (n + 1) * dim],
            );
        }
        Self {
            n,
            dim,
            rows,
            basis: Basis::new(n),
        }
    }

    /// The curve `T(u, (1 - u) t)`, `t` in `[0, 1]`, of degree `n` into `curve`.
    fn row_curve(&self, u: f64, bu: &mut [f64], curve: &mut [f64]) {
        let (n, dim) = (self.n, self.dim);
        self.basis.fill(u, bu);
        curve.fill(0.0);
        for (i, &w) in bu.iter().enumerate() {
            let row = &self.rows[i * (n + 1) * dim..(i + 1) * (n + 1) * dim];
            for (x, p) in curve.iter_mut().zip(row) {
                *x += w * p;
            }
        }
    }

    /// `sum_j B^n_j(t) curve_j` into `out`.
    fn on_curve(&self, curve: &[f64], t: f64, bt: &mut [f64], out: &mut [f64]) {
        let dim = self.dim;
        self.basis.fill(t, bt);
        out.fill(0.0);
        for (j, &w) in bt.iter().enumerate() {
            for (o, p) in out.iter_mut().zip(&curve[j * dim..(j + 1) * dim]) {
                *o += w * p;
            }
        }
    }

    /// `t = v / (1 - u)` clamped to `[0, 1]` (0 at the corner `u = 1`).
    fn along(u: f64, v: f64) -> f64 {
        let r = 1.0 - u;
        if r > 0.0 {
            (v / r).clamp(0.0, 1.0)
        } else {
            0.0
        }
    }

    /// `T(u, v)` into `out` (`dim` values), `(u, v)` in the unit triangle.
    pub(super) fn eval(&self, u: f64, v: f64, out: &mut [f64]) {
        let n = self.n;
        let (mut b, mut curve) = (vec![0.0; n + 1], vec![0.0; (n + 1) * self.dim]);
        self.row_curve(u, &mut b, &mut curve);
        self.on_curve(&curve, Self::along(u, v), &mut b, out);
    }

    /// The patch at the triangle's grid nodes `(node(a), node(b))`, `a + b < n_grid`, and
    /// `(node(a), 1 - node(a))` for `a + b = n_grid` (the nodes of
    /// [`super::max_distance_2d`]): node `(a, b)` at `(a (n_grid + 1) + b) dim`; entries
    /// outside the triangle are left 0.
    pub(super) fn grid(&self, n_grid: usize) -> Vec<f64> {
        let (n, dim) = (self.n, self.dim);
        let mut out = vec![0.0; (n_grid + 1) * (n_grid + 1) * dim];
        let (mut b, mut curve) = (vec![0.0; n + 1], vec![0.0; (n + 1) * dim]);
        for a in 0..=n_grid {
            let u = node(a, n_grid);
            self.row_curve(u, &mut b, &mut curve);
            for j in 0..=n_grid - a {
                let v = if a + j == n_grid {
                    1.0 - u
                } else {
                    node(j, n_grid)
                };
                let t = if a + j == n_grid && a < n_grid {
                    1.0
                } else {
                    Self::along(u, v)
                };
                let o = &mut out[(a * (n_grid + 1) + j) * dim..][..dim];
                self.on_curve(&curve, t, &mut b, o);
            }
        }
        out
    }
}
