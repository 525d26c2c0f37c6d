//! Operations on [`TriPatch`]: evaluation by the triangular de Casteljau algorithm,
//! directional derivatives, degree elevation and the degeneracy invariants of seed 000
//! eq. 14.1.3.
//!
//! Convention (SPEC-reduce §1): `T(u, v) = sum_{i+j<=n} n!/(i! j! k!) u^i v^j w^k T_ij`,
//! `w = 1 - u - v`, `k = n - i - j`; the corner `(u, v) = (0, 0)` is `T_00`, `(1, 0)` is
//! `T_n0`, `(0, 1)` is `T_0n`.

use crate::binomial::{binomial_f64, check_degree};
use crate::validate::check_finite_param;
use crate::{Result, TriPatch, tri_count, tri_index};

/// One triangular de Casteljau step at barycentric `(u, v, w)`: the degree-`n` net `src`
/// becomes the degree-`n - 1` net `dst`, `dst_ij = u src_{i+1,j} + v src_{i,j+1} + w src_ij`.
pub(crate) fn tri_step(src: &[f64], n: usize, dim: usize, bary: (f64, f64, f64), dst: &mut [f64]) {
    let (u, v, w) = bary;
    // Row i of a net (fixed i, j = 0..) is contiguous (i-major storage), so each output row
    // is one flat loop over (j, coordinate): dst_i = u src_(i+1) + v src_i[+1] + w src_i.
    for i in 0..n {
        let len = (n - i) * dim;
        let d0 = tri_index(n - 1, i, 0) * dim;
        let s0 = tri_index(n, i, 0) * dim;
        let s1 = tri_index(n, i + 1, 0) * dim;
        let out = &mut dst[d0..d0 + len];
        let here = &src[s0..s0 + len];
        let next_j = &src[s0 + dim..s0 + dim + len];
        let next_i = &src[s1..s1 + len];
        for (((o, a), b), c) in out.iter_mut().zip(next_i).zip(next_j).zip(here) {
            *o = u * a + v * b + w * c;
        }
    }
}

/// All levels of the de Casteljau pyramid at `bary`: level `r` is the degree-`n - r` net
/// `T^r_ij` (level 0 the input).
pub(crate) fn tri_pyramid(
    net: &[f64],
    n: usize,
    dim: usize,
    bary: (f64, f64, f64),
) -> Vec<Vec<f64>> {
    let mut levels = Vec::with_capacity(n + 1);
    levels.push(net.to_vec());
    for r in 1..=n {
        let mut next = vec![0.0; tri_count(n - r) * dim];
        tri_step(&levels[r - 1], n - r + 1, dim, bary, &mut next);
        levels.push(next);
    }
    levels
}

/// Evaluates the degree-`n` net at barycentric `bary` into `out`.
pub(crate) fn tri_eval(net: &[f64], n: usize, dim: usize, bary: (f64, f64, f64), out: &mut [f64]) {
    let mut cur = net.to_vec();
    let mut next = vec![0.0; cur.len()];
    for d in (1..=n).rev() {
        tri_step(&cur, d, dim, bary, &mut next);
        std::mem::swap(&mut cur, &mut next);
    }
    out.copy_from_slice(&cur[..dim]);
}

impl TriPatch {
    pub(crate) fn from_parts(points: Vec<f64>, degree: usize, dim: usize) -> Self {
        debug_assert_eq!(points.len(), tri_count(degree) * dim);
        Self {
            dim,
            degree,
            points,
        }
    }

    /// Evaluates `T(u, v)` into `out` (`dim` doubles) by the triangular de Casteljau
    /// algorithm with barycentric coordinates `(u, v, 1 - u - v)` (convex combinations inside
    /// the domain: relative error of a few `n` ulp of the net's size). Points outside the
    /// triangle extrapolate; non-finite input gives non-finite output (use
    /// [`TriPatch::eval`] for checked input).
    pub fn eval_into(&self, u: f64, v: f64, out: &mut [f64]) {
        tri_eval(
            &self.points,
            self.degree,
            self.dim,
            (u, v, 1.0 - u - v),
            out,
        );
    }

    /// Evaluates `T(u, v)` (see [`TriPatch::eval_into`]).
    ///
    /// # Errors
    /// [`crate::Error::BadParameter`] when `u` or `v` is not finite.
    ///
    /// ```
    /// # use cagd_core::TriPatch;
    /// // Linear patch with T_00 = 0, T_01 = 2, T_10 = 1 (1-D): T(u, v) = u + 2v.
    /// let t = TriPatch::new(vec![0.0, 2.0, 1.0], 1, 1)?;
    /// assert_eq!(t.eval(0.25, 0.5)?, vec![1.25]);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn eval(&self, u: f64, v: f64) -> Result<Vec<f64>> {
        check_finite_param("u", u)?;
        check_finite_param("v", v)?;
        let mut out = vec![0.0; self.dim];
        self.eval_into(u, v, &mut out);
        Ok(out)
    }

    /// The `order`-th directional derivative `D_d^order T` along `d = (du, dv)` in the
    /// parameter plane (so `w` changes by `-du - dv`), as a patch of degree `n - order`:
    /// `D_d T = n sum_{i+j<=n-1} B_ij^{n-1} (du (T_{i+1,j} - T_ij) + dv (T_{i,j+1} - T_ij))`,
    /// applied `order` times (ADDED: the standard blossom form). An order above `n` gives degree 0
    /// and a zero point. `(du, dv) = (1, 0)` is `d/du`, `(0, 1)` is `d/dv`.
    ///
    /// # Errors
    /// [`crate::Error::BadParameter`] when `du` or `dv` is not finite.
    pub fn directional_derivative(&self, du: f64, dv: f64, order: usize) -> Result<TriPatch> {
        check_finite_param("du", du)?;
        check_finite_param("dv", dv)?;
        let dim = self.dim;
        if order > self.degree {
            return Ok(TriPatch::from_parts(vec![0.0; dim], 0, dim));
        }
        let mut cur = self.points.clone();
        for level in 0..order {
            let n = self.degree - level;
            let mut next = vec![0.0; tri_count(n - 1) * dim];
            // Differences: a de Casteljau step with the "barycentric" (du, dv, -du - dv),
            // times n.
            tri_step(&cur, n, dim, (du, dv, -du - dv), &mut next);
            let nf = n as f64;
            next.iter_mut().for_each(|x| *x *= nf);
            cur = next;
        }
        Ok(TriPatch::from_parts(cur, self.degree - order, dim))
    }

    /// The value of the `order`-th directional derivative along `(du, dv)` at `(u, v)`.
    ///
    /// # Errors
    /// [`crate::Error::BadParameter`] when a parameter is not finite.
    pub fn directional_derivative_at(
        &self,
        u: f64,
        v: f64,
        du: f64,
        dv: f64,
        order: usize,
    ) -> Result<Vec<f64>> {
        self.directional_derivative(du, dv, order)?.eval(u, v)
    }

    /// Elevates the degree from `n` to `n + r`, unchanged surface. Closed form (product of the
    /// patch with `(u + v + w)^r`):
    /// `Tbar_ab = sum_{i<=a, j<=b, i+j>=a+b-r} M(n; i,j) M(r; a-i, b-j) / M(n+r; a,b) T_ij`,
    /// `M(n; i, j) = n! / (i! j! (n-i-j)!)` evaluated as products of exact binomials; for
    /// `r = 1` it is `Tbar_ab = (a T_{a-1,b} + b T_{a,b-1} + (n+1-a-b) T_ab) / (n + 1)`
    /// (SPEC-reduce §5, the triangular elevation of Algorithm 14.3.2). All weights are
    /// non-negative and sum to one: relative error a few ulp of the net's size.
    ///
    /// # Errors
    /// [`crate::Error::DegreeOutOfRange`] when `n + r > MAX_DEGREE`;
    /// [`crate::Error::NonFinite`] when a point of the result rounds past `f64::MAX`.
    ///
    /// ```
    /// # use cagd_core::TriPatch;
    /// let t = TriPatch::new(vec![0.0, 2.0, 1.0], 1, 1)?; // u + 2v
    /// let e = t.elevate(1)?;
    /// assert_eq!(e.points(), &[0.0, 1.0, 2.0, 0.5, 1.5, 1.0]);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn elevate(&self, r: usize) -> Result<TriPatch> {
        let (n, dim) = (self.degree, self.dim);
        let nr = n.saturating_add(r);
        check_degree(nr)?;
        let trinom = |n: usize, i: usize, j: usize| binomial_f64(n, i) * binomial_f64(n - i, j);
        let mut out = vec![0.0; tri_count(nr) * dim];
        for a in 0..=nr {
            for b in 0..=nr - a {
                let o = tri_index(nr, a, b) * dim;
                let denom = trinom(nr, a, b);
                for i in a.saturating_sub(r)..=a.min(n) {
                    for j in 0..=b.min(n - i) {
                        // (a - i) + (b - j) <= r, i.e. the k-index difference is >= 0.
                        if (a - i) + (b - j) > r {
                            continue;
                        }
                        let c = trinom(n, i, j) * trinom(r, a - i, b - j) / denom;
                        let s = tri_index(n, i, j) * dim;
                        for k in 0..dim {
                            out[o + k] += c * self.points[s + k];
                        }
                    }
                }
            }
        }
        // Sums of coordinates near f64::MAX can round past it (the C ABI fuzz harness
        // found an Ok patch with infinite points): refused, not handed out.
        crate::validate::check_points(&out, dim)?;
        Ok(TriPatch::from_parts(out, nr, dim))
    }

    /// The degeneracy invariants of seed 000 eq. 14.1.3 (SPEC-reduce §1):
    /// `F_k = Delta_1^k Delta_2^(n-k) T_00
    ///      = sum_{i<=k} sum_{j<=n-k} (-1)^(n-i-j) C(k,i) C(n-k,j) T_ij`, `k = 0..=n`,
    /// returned flat (`(n + 1) * dim` doubles). `C(n,k) F_k` is the coefficient of
    /// `u^k v^(n-k)` in the power form; the patch has degree `< n` iff all `F_k` vanish.
    pub fn degeneracy_invariants(&self) -> Vec<f64> {
        let (n, dim) = (self.degree, self.dim);
        let mut f = vec![0.0; (n + 1) * dim];
        for k in 0..=n {
            for i in 0..=k {
                for j in 0..=n - k {
                    let sign = if (n - i - j) % 2 == 0 { 1.0 } else { -1.0 };
                    let c = sign * binomial_f64(k, i) * binomial_f64(n - k, j);
                    let s = tri_index(n, i, j) * dim;
                    for d in 0..dim {
                        f[k * dim + d] += c * self.points[s + d];
                    }
                }
            }
        }
        f
    }
}
