//! Point classification against the implicit curve: the sign of `f(x, y) = det F(x, y)`
//! (LU determinant of the Bézout matrix, SPEC-convert §15.8 implementation notes) and the
//! algebraic distance `f / |∇f|` (first-order distance to the zero set).

use crate::ImplicitCurve;

/// Where a point lies relative to the implicit curve `f = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Classification {
    /// `f(x, y) = det F(x, y)` by LU with partial pivoting.
    pub value: f64,
    /// `-1`, `0` or `1`: the sign of `value` (0 only for an exact zero). Which side is
    /// positive follows from the sign convention `det F = (-1)^(n(n+1)/2) Res_t`.
    pub sign: i8,
    /// The algebraic distance `f / |∇f|` (signed, in model units to first order);
    /// `±∞` where the gradient vanishes and `f ≠ 0`, 0 where both vanish.
    pub distance: f64,
}

impl ImplicitCurve {
    /// Classifies the point `(x, y)`: about 100 ns at degree 5 (no allocation).
    ///
    /// ```
    /// use cagd_core::BezierCurve;
    /// use cagd_implicit::ImplicitCurve;
    /// // The unit circle quarter of impl-n2-conic-weighted, f = 4 - 4x^2 - 4y^2.
    /// let c = BezierCurve::new_rational(vec![1.0, 0.0, 1.0, 1.0, 0.0, 1.0], vec![1.0, 1.0, 2.0], 2)?;
    /// let imp = ImplicitCurve::new(&c)?;
    /// assert_eq!(imp.classify(0.0, 0.0).sign, 1);
    /// assert_eq!(imp.classify(2.0, 0.0).sign, -1);
    /// assert!((imp.classify(0.0, 0.5).distance - 0.75).abs() < 1e-15); // (4 - 1) / |(0, -4)|
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn classify(&self, x: f64, y: f64) -> Classification {
        let value = self.bezout.det_at(x, y);
        let (_, fx, fy) = self.polynomial.eval_grad(x, y);
        let g = fx.hypot(fy);
        let sign = if value > 0.0 {
            1
        } else if value < 0.0 {
            -1
        } else {
            0
        };
        let distance = if g > 0.0 {
            value / g
        } else if value == 0.0 {
            0.0
        } else {
            value.signum() * f64::INFINITY
        };
        Classification {
            value,
            sign,
            distance,
        }
    }
}
