//! Operations on [`TensorPatch`]: evaluation, partial derivatives, subdivision and degree
//! elevation in each direction, and the degeneracy invariants of seed 000 eq. 14.1.2.
//!
//! Every operation acts on the columns (fixed `j`, a degree-`m` curve in `u`) or the rows
//! (fixed `i`, a degree-`n` curve in `v`) of the net with the curve kernels of
//! [`crate::kernel`], so its accuracy is the curve kernel's: convex combinations (evaluation,
//! subdivision, elevation) with a relative error of a few `m + n` ulp of the net's size.

use crate::binomial::{check_degree, sign_binomial_f64};
use crate::validate::check_finite_param;
use crate::{Error, Result, TensorPatch, kernel};

/// Applies `f(column_in, column_out)` to every column (`m + 1` points along `u`, fixed `j`),
/// producing a net of degree `(new_m, n)`.
fn map_columns(p: &TensorPatch, new_m: usize, mut f: impl FnMut(&[f64], &mut [f64])) -> Vec<f64> {
    let (m, n, dim) = (p.deg_u, p.deg_v, p.dim);
    let mut col = vec![0.0; (m + 1) * dim];
    let mut out_col = vec![0.0; (new_m + 1) * dim];
    let mut out = vec![0.0; (new_m + 1) * (n + 1) * dim];
    for j in 0..=n {
        for i in 0..=m {
            let src = (i * (n + 1) + j) * dim;
            col[i * dim..(i + 1) * dim].copy_from_slice(&p.points[src..src + dim]);
        }
        f(&col, &mut out_col);
        for i in 0..=new_m {
            let dst = (i * (n + 1) + j) * dim;
            out[dst..dst + dim].copy_from_slice(&out_col[i * dim..(i + 1) * dim]);
        }
    }
    out
}

/// Applies `f(row_in, row_out)` to every row (`n + 1` points along `v`, fixed `i`), producing
/// a net of degree `(m, new_n)`.
fn map_rows(p: &TensorPatch, new_n: usize, mut f: impl FnMut(&[f64], &mut [f64])) -> Vec<f64> {
    let (m, n, dim) = (p.deg_u, p.deg_v, p.dim);
    let mut out = vec![0.0; (m + 1) * (new_n + 1) * dim];
    for i in 0..=m {
        let row = &p.points[i * (n + 1) * dim..(i + 1) * (n + 1) * dim];
        f(
            row,
            &mut out[i * (new_n + 1) * dim..(i + 1) * (new_n + 1) * dim],
        );
    }
    out
}

/// `k`-th hodograph of a degree-`deg` polygon: `deg!/(deg-k)! Delta^k P_i`, degree `deg - k`
/// (a single zero point when `k > deg`).
fn hodograph_k(points: &[f64], dim: usize, k: usize, out: &mut [f64]) {
    let deg = points.len() / dim - 1;
    if k > deg {
        out.fill(0.0);
        return;
    }
    let mut cur = points.to_vec();
    for level in 0..k {
        let d = (deg - level) as f64;
        for i in 0..deg - level {
            for c in 0..dim {
                cur[i * dim + c] = d * (cur[(i + 1) * dim + c] - cur[i * dim + c]);
            }
        }
    }
    out.copy_from_slice(&cur[..(deg - k + 1) * dim]);
}

/// Checks a split parameter: finite and in `[0, 1]`.
fn check_split(name: &'static str, s: f64) -> Result<()> {
    check_finite_param(name, s)?;
    if !(0.0..=1.0).contains(&s) {
        return Err(Error::BadParameter {
            name,
            value: s,
            why: "must lie in [0, 1]",
        });
    }
    Ok(())
}

impl TensorPatch {
    pub(crate) fn from_parts(points: Vec<f64>, deg_u: usize, deg_v: usize, dim: usize) -> Self {
        debug_assert_eq!(points.len(), (deg_u + 1) * (deg_v + 1) * dim);
        Self {
            dim,
            deg_u,
            deg_v,
            points,
        }
    }

    /// Evaluates `P(u, v)` into `out` (`dim` doubles) by de Casteljau along `v` in every row,
    /// then along `u`. Parameters outside `[0, 1]^2` extrapolate; non-finite parameters give
    /// non-finite output (use [`TensorPatch::eval`] for checked input).
    pub fn eval_into(&self, u: f64, v: f64, out: &mut [f64]) {
        let (m, n, dim) = (self.deg_u, self.deg_v, self.dim);
        let mut work = vec![0.0; (n + 1) * dim];
        let mut col = vec![0.0; (m + 1) * dim];
        for i in 0..=m {
            let row = &self.points[i * (n + 1) * dim..(i + 1) * (n + 1) * dim];
            kernel::de_casteljau(row, dim, v, &mut work, &mut col[i * dim..(i + 1) * dim]);
        }
        let mut work = vec![0.0; (m + 1) * dim];
        kernel::de_casteljau(&col, dim, u, &mut work, out);
    }

    /// Evaluates `P(u, v)` (see [`TensorPatch::eval_into`]).
    ///
    /// # Errors
    /// [`Error::BadParameter`] when `u` or `v` is not finite.
    ///
    /// ```
    /// # use cagd_core::TensorPatch;
    /// // Bilinear patch with corners 0, 1, 2, 3 (1-D): P(u, v) = 2u + v.
    /// let p = TensorPatch::new(vec![0.0, 1.0, 2.0, 3.0], 1, 1, 1)?;
    /// assert_eq!(p.eval(0.25, 0.5)?, vec![1.0]);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn eval(&self, u: f64, v: f64) -> Result<Vec<f64>> {
        check_finite_param("u", u)?;
        check_finite_param("v", v)?;
        let mut out = vec![0.0; self.dim];
        self.eval_into(u, v, &mut out);
        Ok(out)
    }

    /// The partial derivative `d^(ku+kv) P / du^ku dv^kv` as a patch of degree
    /// `(m - ku, n - kv)`: control points `m!/(m-ku)! n!/(n-kv)! Delta_u^ku Delta_v^kv P_ij`.
    /// An order above the degree in a direction gives degree 0 and zero points there.
    pub fn partial(&self, ku: usize, kv: usize) -> TensorPatch {
        let dim = self.dim;
        let new_m = self.deg_u.saturating_sub(ku);
        let new_n = self.deg_v.saturating_sub(kv);
        let pu = map_columns(self, new_m, |c, o| hodograph_k(c, dim, ku, o));
        let pu = TensorPatch::from_parts(pu, new_m, self.deg_v, dim);
        let puv = map_rows(&pu, new_n, |r, o| hodograph_k(r, dim, kv, o));
        TensorPatch::from_parts(puv, new_m, new_n, dim)
    }

    /// The value of the partial derivative `d^(ku+kv) P / du^ku dv^kv` at `(u, v)`.
    ///
    /// # Errors
    /// [`Error::BadParameter`] when `u` or `v` is not finite.
    pub fn partial_at(&self, u: f64, v: f64, ku: usize, kv: usize) -> Result<Vec<f64>> {
        self.partial(ku, kv).eval(u, v)
    }

    /// Splits the patch at `u = s` into the pieces on `[0, s] x [0, 1]` and `[s, 1] x [0, 1]`,
    /// each reparametrised to `[0, 1]^2` with `u' = u / s` resp. `u' = (u - s) / (1 - s)`
    /// (de Casteljau on every column).
    ///
    /// # Errors
    /// [`Error::BadParameter`] when `s` is not finite or outside `[0, 1]`.
    pub fn subdivide_u(&self, s: f64) -> Result<(TensorPatch, TensorPatch)> {
        check_split("s", s)?;
        let (m, n, dim) = (self.deg_u, self.deg_v, self.dim);
        let mut left = vec![0.0; self.points.len()];
        let mut right = vec![0.0; self.points.len()];
        let mut col = vec![0.0; (m + 1) * dim];
        let mut lc = vec![0.0; (m + 1) * dim];
        let mut rc = vec![0.0; (m + 1) * dim];
        for j in 0..=n {
            for i in 0..=m {
                let at = (i * (n + 1) + j) * dim;
                col[i * dim..(i + 1) * dim].copy_from_slice(&self.points[at..at + dim]);
            }
            kernel::subdivide(&col, dim, s, &mut lc, &mut rc);
            for i in 0..=m {
                let at = (i * (n + 1) + j) * dim;
                left[at..at + dim].copy_from_slice(&lc[i * dim..(i + 1) * dim]);
                right[at..at + dim].copy_from_slice(&rc[i * dim..(i + 1) * dim]);
            }
        }
        Ok((
            TensorPatch::from_parts(left, m, n, dim),
            TensorPatch::from_parts(right, m, n, dim),
        ))
    }

    /// Splits the patch at `v = s` into the pieces on `[0, 1] x [0, s]` and `[0, 1] x [s, 1]`,
    /// each reparametrised to `[0, 1]^2` (de Casteljau on every row).
    ///
    /// # Errors
    /// [`Error::BadParameter`] when `s` is not finite or outside `[0, 1]`.
    pub fn subdivide_v(&self, s: f64) -> Result<(TensorPatch, TensorPatch)> {
        check_split("s", s)?;
        let (m, n, dim) = (self.deg_u, self.deg_v, self.dim);
        let mut right = vec![0.0; self.points.len()];
        let mut i = 0;
        let left = map_rows(self, n, |r, o| {
            let len = r.len();
            kernel::subdivide(r, dim, s, o, &mut right[i * len..(i + 1) * len]);
            i += 1;
        });
        Ok((
            TensorPatch::from_parts(left, m, n, dim),
            TensorPatch::from_parts(right, m, n, dim),
        ))
    }

    /// Elevates the degree in `u` from `m` to `m + r` (curve elevation of every column,
    /// `a_ij = C(m,j) C(r,i-j) / C(m+r,i)`, SPEC-reduce §0). The surface is unchanged.
    ///
    /// # Errors
    /// [`Error::DegreeOutOfRange`] when `m + r > MAX_DEGREE`; [`Error::NonFinite`] when a
    /// point of the result rounds past `f64::MAX`.
    pub fn elevate_u(&self, r: usize) -> Result<TensorPatch> {
        let new_m = self.deg_u.saturating_add(r);
        check_degree(new_m)?;
        let dim = self.dim;
        let pts = map_columns(self, new_m, |c, o| kernel::elevate(c, dim, r, o));
        // Sums of coordinates near f64::MAX can round past it: refused, not handed out.
        crate::validate::check_points(&pts, dim)?;
        Ok(TensorPatch::from_parts(pts, new_m, self.deg_v, dim))
    }

    /// Elevates the degree in `v` from `n` to `n + r` (curve elevation of every row).
    ///
    /// # Errors
    /// [`Error::DegreeOutOfRange`] when `n + r > MAX_DEGREE`; [`Error::NonFinite`] when a
    /// point of the result rounds past `f64::MAX`.
    pub fn elevate_v(&self, r: usize) -> Result<TensorPatch> {
        let new_n = self.deg_v.saturating_add(r);
        check_degree(new_n)?;
        let dim = self.dim;
        let pts = map_rows(self, new_n, |row, o| kernel::elevate(row, dim, r, o));
        // Sums of coordinates near f64::MAX can round past it: refused, not handed out.
        crate::validate::check_points(&pts, dim)?;
        Ok(TensorPatch::from_parts(pts, self.deg_u, new_n, dim))
    }

    /// The degeneracy invariants of seed 000 eq. 14.1.2 (Theorem 14.1.1, SPEC-reduce §1):
    /// `F_j = sum_i (-1)^(m-i) C(m,i) P_ij` (`j = 0..=n`, zero for all `j` iff the patch has
    /// degree `< m` in `u`) and `G_i = sum_j (-1)^(n-j) C(n,j) P_ij` (`i = 0..=m`, zero iff
    /// degree `< n` in `v`). Returned flat: `F` as `(n + 1) * dim` doubles, `G` as
    /// `(m + 1) * dim`. They satisfy `sum_j c_j^(n) F_j = sum_i c_i^(m) G_i`.
    ///
    /// ```
    /// # use cagd_core::TensorPatch;
    /// // P(u, v) = 2u + v has degree (1, 1) but is degenerate in neither direction;
    /// // elevated in u it is degenerate in u: F vanishes.
    /// let p = TensorPatch::new(vec![0.0, 1.0, 2.0, 3.0], 1, 1, 1)?.elevate_u(1)?;
    /// let (f, g) = p.degeneracy_invariants();
    /// assert_eq!(f, vec![0.0, 0.0]);
    /// assert_eq!(g, vec![1.0, 1.0, 1.0]);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn degeneracy_invariants(&self) -> (Vec<f64>, Vec<f64>) {
        let (m, n, dim) = (self.deg_u, self.deg_v, self.dim);
        let mut f = vec![0.0; (n + 1) * dim];
        let mut g = vec![0.0; (m + 1) * dim];
        for i in 0..=m {
            let ci = sign_binomial_f64(m, i);
            for j in 0..=n {
                let dj = sign_binomial_f64(n, j);
                let p = self.point(i, j);
                for k in 0..dim {
                    f[j * dim + k] += ci * p[k];
                    g[i * dim + k] += dj * p[k];
                }
            }
        }
        (f, g)
    }
}
