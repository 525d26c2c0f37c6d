//! Inversion: the parameter `t` of a point on the curve, from the kernel of `F(x, y)`.
//!
//! At a curve point `P(τ)` the Bézout matrix is singular with the kernel vector
//! `v_h = (1-τ)^(n-1-h) τ^h`, `h = 0..n-1` (checked numerically in the tests), so
//! `τ (v_h + v_{h+1}) = v_{h+1}` for every `h`; `τ` is taken as the least-squares solution
//! of these `n - 1` equations and polished by Gauss–Newton on `|P(t) - p|^2`. At a singular
//! point (double point, cusp) the kernel has dimension >= 2: [`Error::SingularPoint`].

use cagd_core::{Error, Result, check_finite_param};

use crate::ImplicitCurve;
use crate::lu::null_vector;

/// Relative size `pivot[n-2] / pivot[0]` under which `F(p)` is taken to have rank `<= n-2`.
const RANK_TOL: f64 = 1e-10;
/// Relative distance (to the coordinate scale) above which a point is not on the curve.
const ON_CURVE_TOL: f64 = 1e-8;

impl ImplicitCurve {
    /// The parameter `t` with `P(t) = (x, y)` (on the whole algebraic curve: `t` may fall
    /// outside `[0, 1]`).
    ///
    /// # Errors
    /// [`Error::BadParameter`] for a non-finite coordinate; [`Error::SingularPoint`] at a
    /// double point or cusp; [`Error::NotOnCurve`] when `(x, y)` is farther than
    /// `1e-8 * max(1, |control points|)` from the curve; [`Error::ConditionNotMet`] for an
    /// improper parametrization (every point has several parameters).
    ///
    /// ```
    /// use cagd_core::BezierCurve;
    /// use cagd_implicit::ImplicitCurve;
    /// let c = BezierCurve::new(vec![0.0, 0.0, 1.0, 3.0, 3.0, 3.0, 4.0, 0.0], 2)?;
    /// let imp = ImplicitCurve::new(&c)?;
    /// let p = c.eval(0.3);
    /// assert!((imp.invert(p[0], p[1])? - 0.3).abs() < 1e-14);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn invert(&self, x: f64, y: f64) -> Result<f64> {
        check_finite_param("x", x)?;
        check_finite_param("y", y)?;
        if self.report.power > 1 {
            return Err(Error::ConditionNotMet {
                eq: "15.8",
                why: "improper parametrization: every curve point has several parameters",
            });
        }
        let t0 = self.kernel_parameter(x, y)?;
        let (t, distance) = self.curve.polish(x, y, t0);
        if distance.is_nan() || distance > ON_CURVE_TOL * self.scale {
            return Err(Error::NotOnCurve { x, y, distance });
        }
        Ok(t)
    }

    /// The parameter estimate from the kernel of `F(x, y)` (degree 1: the linear equation).
    fn kernel_parameter(&self, x: f64, y: f64) -> Result<f64> {
        let n = self.curve.hom.len() - 1;
        if n == 1 {
            // x W(t) - X(t) = 0 (or y), t = e0 / (e0 - e1), the better-conditioned coordinate.
            let e = |k: usize, c: f64| {
                [
                    c * self.curve.hom[0][2] - self.curve.hom[0][k],
                    c * self.curve.hom[1][2] - self.curve.hom[1][k],
                ]
            };
            let (ex, ey) = (e(0, x), e(1, y));
            let (a, b) = if (ex[0] - ex[1]).abs() >= (ey[0] - ey[1]).abs() {
                (ex[0], ex[1])
            } else {
                (ey[0], ey[1])
            };
            return Ok(if a == b { 0.5 } else { a / (a - b) });
        }
        let mut m = self.bezout.at(x, y);
        let k = null_vector(&mut m, n);
        if k.pivots[0] == 0.0 || k.pivots[n - 2] <= RANK_TOL * k.pivots[0] {
            return Err(Error::SingularPoint { x, y });
        }
        let v = &k.v;
        let (mut num, mut den) = (0.0, 0.0);
        for h in 0..n - 1 {
            let s = v[h] + v[h + 1];
            num += v[h + 1] * s;
            den += s * s;
        }
        Ok(if den > 0.0 { num / den } else { 0.5 })
    }
}
