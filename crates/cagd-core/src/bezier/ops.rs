//! Operations on [`BezierCurve`]: subdivision, sub-interval extraction, degree elevation,
//! hodographs and derivatives.

use crate::binomial::check_degree;
use crate::{BezierCurve, Error, Result, kernel};

impl BezierCurve {
    /// Splits the curve at `t` into the pieces on `[0, t]` and `[t, 1]`, each reparametrised
    /// to `[0, 1]` (de Casteljau; homogeneous for rational curves, so weights split too).
    ///
    /// # Errors
    /// [`Error::BadParameter`] when `t` is not finite; [`Error::NonFinite`] when a piece's
    /// point overflows and [`Error::NonPositiveWeight`] when a piece's weight is not finite
    /// and `> 0` (both only when `t` extrapolates far outside `[0, 1]`; the C ABI fuzz
    /// harness found pieces with infinite coordinates and weights returned as `Ok`).
    pub fn subdivide(&self, t: f64) -> Result<(BezierCurve, BezierCurve)> {
        Self::check_param("t", t)?;
        let (l, r) = self.subdivide_unchecked(t);
        Ok((l.checked_piece()?, r.checked_piece()?))
    }

    /// The piece itself when its points are finite and its weights finite and `> 0`
    /// (pieces made by extrapolation can overflow). Goes beyond the seeds (validation).
    fn checked_piece(self) -> Result<BezierCurve> {
        if let Some(w) = self.weights() {
            crate::validate::check_weights(w, w.len())?;
        }
        crate::validate::check_points(self.points(), self.dim())?;
        Ok(self)
    }

    fn subdivide_unchecked(&self, t: f64) -> (BezierCurve, BezierCurve) {
        match self.weights() {
            None => {
                let mut l = vec![0.0; self.points().len()];
                let mut r = vec![0.0; self.points().len()];
                kernel::subdivide(self.points(), self.dim(), t, &mut l, &mut r);
                (
                    Self::with_parts(self.dim(), l, None),
                    Self::with_parts(self.dim(), r, None),
                )
            }
            Some(_) => {
                let hom = self.homogeneous_points();
                let d = self.dim() + 1;
                let mut l = vec![0.0; hom.len()];
                let mut r = vec![0.0; hom.len()];
                kernel::subdivide(&hom, d, t, &mut l, &mut r);
                (self.rational_from_hom(&l), self.rational_from_hom(&r))
            }
        }
    }

    fn rational_from_hom(&self, hom: &[f64]) -> BezierCurve {
        let n1 = hom.len() / (self.dim() + 1);
        let mut p = vec![0.0; n1 * self.dim()];
        let mut w = vec![0.0; n1];
        kernel::from_homogeneous(hom, self.dim(), &mut p, &mut w);
        Self::with_parts(self.dim(), p, Some(w))
    }

    /// The piece of the curve on `[a, b]`, reparametrised to `[0, 1]`. `a < b` need not lie
    /// in `[0, 1]` (extrapolation is exact for polynomials).
    ///
    /// For a rational curve with `[a, b]` outside `[0, 1]` the weights of the piece may
    /// become non-positive; that is reported as [`Error::NonPositiveWeight`].
    ///
    /// # Errors
    /// [`Error::BadParameter`] when `a` or `b` is not finite or `a >= b`;
    /// [`Error::NonPositiveWeight`] as above (also for a weight that overflows);
    /// [`Error::NonFinite`] when a point of the piece overflows.
    pub fn segment(&self, a: f64, b: f64) -> Result<BezierCurve> {
        Self::check_param("a", a)?;
        Self::check_param("b", b)?;
        if a >= b {
            return Err(Error::BadParameter {
                name: "a",
                value: a,
                why: "the interval [a, b] must have a < b",
            });
        }
        // Split at b, then the left piece (on [0, b]) at a / b; or, when b is 0, go through
        // the right piece of a split at a.
        let piece = if b != 0.0 {
            let (left, _) = self.subdivide_unchecked(b);
            left.subdivide_unchecked(a / b).1
        } else {
            let (_, right) = self.subdivide_unchecked(a);
            right.subdivide_unchecked((b - a) / (1.0 - a)).0
        };
        piece.checked_piece()
    }

    /// Elevates the degree by `r` at once: `Q_i = sum_j C(n,j) C(r,i-j) / C(n+r,i) P_j`
    /// (seed 001 §3.2; the elevation matrix of seed 000 eq. 14.4.4 in closed form). Rational
    /// curves are elevated in homogeneous space. The curve is unchanged as a point set and
    /// parametrisation.
    ///
    /// # Errors
    /// [`Error::DegreeOutOfRange`] when `n + r > MAX_DEGREE`; [`Error::NonFinite`] when a
    /// point overflows (a rational curve's homogeneous points `w_i P_i` beyond f64, or a
    /// rounding of coordinates at `f64::MAX`), never an `Ok` curve with infinite points
    /// (the C ABI fuzz harness found one).
    pub fn elevate(&self, r: usize) -> Result<BezierCurve> {
        let n = self.degree();
        check_degree(n.saturating_add(r))?;
        match self.weights() {
            None => {
                let mut out = vec![0.0; (n + r + 1) * self.dim()];
                kernel::elevate(self.points(), self.dim(), r, &mut out);
                Self::with_parts(self.dim(), out, None).checked_piece()
            }
            Some(_) => {
                let hom = self.homogeneous_points();
                let mut out = vec![0.0; (n + r + 1) * (self.dim() + 1)];
                kernel::elevate(&hom, self.dim() + 1, r, &mut out);
                self.rational_from_hom(&out).checked_piece()
            }
        }
    }

    /// The hodograph `P'(t) = sum_i n (P_{i+1} - P_i) B_i^{n-1}(t)` of a polynomial curve,
    /// a polynomial curve of degree `n - 1` (degree 0 with a zero point when `n = 0`). For a
    /// rational curve the hodograph of the homogeneous curve (`dim + 1` coordinates).
    pub fn hodograph(&self) -> BezierCurve {
        let (pts, d) = match self.weights() {
            None => (self.points().to_vec(), self.dim()),
            Some(_) => (self.homogeneous_points(), self.dim() + 1),
        };
        let n = pts.len() / d - 1;
        if n == 0 {
            return Self::with_parts(d, vec![0.0; d], None);
        }
        let nf = n as f64;
        let out: Vec<f64> = (0..n)
            .flat_map(|i| (0..d).map(move |k| (i, k)))
            .map(|(i, k)| nf * (pts[(i + 1) * d + k] - pts[i * d + k]))
            .collect();
        Self::with_parts(d, out, None)
    }

    /// The derivatives of orders `0..=order` at `t`, each `dim` doubles (Euclidean, also for
    /// rational curves: the quotient rule `C^(k) = (A^(k) - sum_{j=1}^k C(k,j) w^(j)
    /// C^(k-j)) / w`, Piegl & Tiller eq. 4.8). Orders above the degree are zero for
    /// polynomial curves.
    ///
    /// # Errors
    /// [`Error::BadParameter`] when `t` is not finite.
    pub fn derivatives(&self, t: f64, order: usize) -> Result<Vec<Vec<f64>>> {
        Self::check_param("t", t)?;
        let d = self.dim();
        // Derivatives of the (homogeneous) polynomial curve.
        let mut hod = match self.weights() {
            None => Self::with_parts(d, self.points().to_vec(), None),
            Some(_) => self.to_homogeneous(),
        };
        let mut poly = Vec::with_capacity(order + 1);
        for _ in 0..=order {
            poly.push(hod.eval(t));
            hod = hod.hodograph();
        }
        if self.weights().is_none() {
            return Ok(poly);
        }
        let mut out: Vec<Vec<f64>> = Vec::with_capacity(order + 1);
        for k in 0..=order {
            let w0 = poly[0][d];
            let mut v: Vec<f64> = poly[k][..d].to_vec();
            for j in 1..=k {
                let c = crate::binomial::binomial_f64(k, j) * poly[j][d];
                for (vi, oi) in v.iter_mut().zip(&out[k - j]) {
                    *vi -= c * oi;
                }
            }
            v.iter_mut().for_each(|x| *x /= w0);
            out.push(v);
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quarter_circle() -> BezierCurve {
        let h = std::f64::consts::FRAC_1_SQRT_2;
        BezierCurve::new_rational(vec![1.0, 0.0, 1.0, 1.0, 0.0, 1.0], vec![1.0, h, 1.0], 2).unwrap()
    }

    #[test]
    fn rational_quarter_circle_is_on_the_circle() {
        let c = quarter_circle();
        for i in 0..=100 {
            let p = c.eval(i as f64 / 100.0);
            assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-15);
        }
        let (l, r) = c.subdivide(0.3).unwrap();
        for i in 0..=20 {
            let s = i as f64 / 20.0;
            let pl = l.eval(s);
            let pr = r.eval(s);
            let ql = c.eval(0.3 * s);
            let qr = c.eval(0.3 + 0.7 * s);
            assert!((pl[0] - ql[0]).abs() < 1e-15 && (pl[1] - ql[1]).abs() < 1e-15);
            assert!((pr[0] - qr[0]).abs() < 1e-15 && (pr[1] - qr[1]).abs() < 1e-15);
        }
    }

    #[test]
    fn rational_derivative_is_tangent_to_circle() {
        let c = quarter_circle();
        for t in [0.0, 0.25, 0.6, 1.0] {
            let d = c.derivatives(t, 2).unwrap();
            let dot = d[0][0] * d[1][0] + d[0][1] * d[1][1];
            assert!(dot.abs() < 1e-14, "t={t}");
        }
        // Finite-difference check of the first derivative.
        let h = 1e-6;
        let (a, b) = (c.eval(0.4 - h), c.eval(0.4 + h));
        let d = c.derivatives(0.4, 1).unwrap();
        for k in 0..2 {
            assert!(((b[k] - a[k]) / (2.0 * h) - d[1][k]).abs() < 1e-8);
        }
    }

    #[test]
    fn segment_and_elevation() {
        let c =
            BezierCurve::new(vec![0.0, 0.0, 1.0, 3.0, 3.0, 4.0, 5.0, 1.0, 6.0, 5.0], 2).unwrap();
        let s = c.segment(0.2, 0.7).unwrap();
        let e = c.elevate(3).unwrap();
        assert_eq!(e.degree(), 7);
        for i in 0..=50 {
            let t = i as f64 / 50.0;
            let (p, q) = (s.eval(t), c.eval(0.2 + 0.5 * t));
            let (a, b) = (e.eval(t), c.eval(t));
            for k in 0..2 {
                assert!((p[k] - q[k]).abs() < 1e-13);
                assert!((a[k] - b[k]).abs() < 1e-13);
            }
        }
        assert!(c.segment(0.5, 0.5).is_err());
        assert!(c.segment(f64::NAN, 0.5).is_err());
        assert!(matches!(
            c.elevate(61),
            Err(Error::DegreeOutOfRange {
                degree: 65,
                max: 64
            })
        ));
    }

    /// Extrapolating pieces that overflow are refused, not returned with infinite points or
    /// weights (issue 18: found by the C ABI fuzz harness, a curve of
    /// `cagd_curve_subdivide` whose `cagd_curve_weights` then failed).
    #[test]
    fn overflowing_pieces_are_refused() {
        let cubic =
            BezierCurve::new(vec![0.0, 0.0, 1.0, 3.0, 3.0, 4.0, 5.0, 1.0], 2).expect("valid");
        // t^3 * 5 overflows near t = 1e103; the right piece then runs from C(t) to C(1).
        assert!(matches!(
            cubic.subdivide(1e120),
            Err(Error::NonFinite { .. })
        ));
        assert!(matches!(
            cubic.segment(-1e120, 0.5),
            Err(Error::NonFinite { .. })
        ));
        // Far but representable: still fine, and exact at the ends.
        let (l, _) = cubic.subdivide(1e50).expect("finite pieces");
        assert_eq!(l.eval(0.0), cubic.eval(0.0));
        // A rational curve whose homogeneous points w_i P_i overflow cannot be elevated.
        let big = BezierCurve::new_rational(vec![1e308, -1e308], vec![4.0, 1.0], 1).expect("ok");
        assert!(matches!(big.elevate(1), Err(Error::NonFinite { .. })));
        let c = quarter_circle();
        // The homogeneous weights of the pieces change sign beyond the pole of w(t).
        assert!(matches!(
            c.subdivide(-1e200),
            Err(Error::NonPositiveWeight { .. } | Error::NonFinite { .. })
        ));
        assert!(matches!(
            c.segment(1e160, 1e200),
            Err(Error::NonPositiveWeight { .. } | Error::NonFinite { .. })
        ));
        let (l, r) = c.subdivide(0.5).expect("inside");
        assert!(l.weights().is_some_and(|w| w.iter().all(|w| *w > 0.0)));
        assert!(r.weights().is_some_and(|w| w.iter().all(|w| *w > 0.0)));
    }

    #[test]
    fn polynomial_derivatives() {
        // P(t) = (t^2) as a quadratic with points 0, 0, 1.
        let c = BezierCurve::new(vec![0.0, 0.0, 1.0], 1).unwrap();
        let d = c.derivatives(0.5, 3).unwrap();
        assert_eq!(d, vec![vec![0.25], vec![1.0], vec![2.0], vec![0.0]]);
    }
}
