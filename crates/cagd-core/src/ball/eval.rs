//! Evaluation of a WSGB(n, L) curve by peeling (SPEC-reduce §9.1): `L` Wang layers, then a
//! Said–Ball core evaluated by two Horner sums. `O(n dim)` operations against the
//! `O(n^2 dim)` of de Casteljau on the same curve in Bézier form (the reason the basis
//! exists, seed 003 introduction).

use super::WsgbCurve;
use crate::{MAX_DEGREE, binomial_f64};

/// Number of Horner coefficients of the largest Said–Ball core, `ceil(MAX_DEGREE / 2)`.
const MAX_CORE: usize = MAX_DEGREE.div_ceil(2) + 1;

impl WsgbCurve {
    /// Evaluates the curve at `u` into `out` (`dim` doubles, overwritten); `u` outside
    /// `[0, 1]` extrapolates.
    ///
    /// Algorithm (SPEC-reduce §9.1, the peeling `beta_i(u; n, L) = 2u(1-u)
    /// beta_{i-1}(u; n-2, L-1)`), with `v = 1 - u`, `w = 2uv`:
    ///
    /// ```text
    /// r(u) = sum_{k<L} w^k (v^2 p_k + u^2 p_{n-k})  +  w^L S(u),
    /// S(u) = v^(h+1) sum_{j<c} C(h+j, j) u^j p_{L+j} + u^(h+1) sum_{j<c} C(h+j, j) v^j p_{n-L-j}
    ///        [+ C(n', h) (uv)^h p_{L+h} if n' is even]
    /// ```
    ///
    /// where `S` is the Said–Ball core of degree `n' = n - 2L`, `h = floor(n'/2)`,
    /// `c = ceil(n'/2)`, each sum by Horner. Cost about `3 (n + 1) dim` multiplications, no
    /// allocation. Accuracy: every term is a non-negative basis value times a point, so the
    /// relative error is a few `n` ulp of `max |p_i|` for `u` in `[0, 1]` (measured against
    /// de Casteljau on the exact Bézier form in the tests).
    ///
    /// # Panics
    /// If `out.len() != dim`.
    pub fn eval_into(&self, u: f64, out: &mut [f64]) {
        let (n, l, dim) = (self.degree(), self.order(), self.dim());
        assert_eq!(
            out.len(),
            dim,
            "WsgbCurve::eval_into: out must hold dim values"
        );
        let p = self.points();
        let v = 1.0 - u;
        let (uu, vv, w) = (u * u, v * v, 2.0 * u * v);
        let core = n - 2 * l;
        let h = core / 2;
        let c = core.div_ceil(2);
        let vh = crate::kernel::powu(v, h + 1);
        let uh = crate::kernel::powu(u, h + 1);
        let mid = if core % 2 == 0 {
            binomial_f64(core, h) * crate::kernel::powu(u * v, h)
        } else {
            0.0
        };
        // C(h + j, j), j < c <= 33, by the exact-integer recurrence (exact below 2^53).
        let mut coef = [0.0f64; MAX_CORE];
        let mut cj = 1.0;
        for (j, slot) in coef.iter_mut().enumerate().take(c) {
            if j > 0 {
                cj = cj * (h + j) as f64 / j as f64;
            }
            *slot = cj;
        }
        for (d, o) in out.iter_mut().enumerate() {
            // Wang layers.
            let mut f = 1.0;
            let mut acc = 0.0;
            for k in 0..l {
                acc += f * (vv * p[k * dim + d] + uu * p[(n - k) * dim + d]);
                f *= w;
            }
            // Said–Ball core on p_L .. p_{n-L}, Horner in u (left) and v (right).
            let (mut left, mut right) = (0.0, 0.0);
            for j in (0..c).rev() {
                let cj = coef[j];
                left = left * u + cj * p[(l + j) * dim + d];
                right = right * v + cj * p[(n - l - j) * dim + d];
            }
            let mut s = vh * left + uh * right;
            if core % 2 == 0 {
                s += mid * p[(l + h) * dim + d];
            }
            *o = acc + f * s;
        }
    }

    /// Evaluates the curve at `u` (see [`WsgbCurve::eval_into`]).
    pub fn eval(&self, u: f64) -> Vec<f64> {
        let mut out = vec![0.0; self.dim()];
        self.eval_into(u, &mut out);
        out
    }
}
