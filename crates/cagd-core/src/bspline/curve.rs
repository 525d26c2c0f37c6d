//! B-spline and NURBS curves of any degree `p` (0..=[`crate::MAX_DEGREE`]) and dimension.
//!
//! `C(t) = sum_i N_{i,p}(t) P_i` (polynomial) or `sum_i N_{i,p}(t) w_i P_i / sum_i
//! N_{i,p}(t) w_i` (NURBS), with the full knot vector `u_0 <= ... <= u_{n+p}` (clamped or
//! unclamped) and the domain `[u_p, u_n]` (see [`crate::check_knots`]). Rational curves are
//! stored as Euclidean points plus weights (DESIGN.md); algorithms work on the homogeneous
//! points `(w_i P_i, w_i)`.

use super::knots::check_knots;
use crate::validate::{check_points, check_weights};
use crate::{Result, kernel};

/// A B-spline (or, with weights, NURBS) curve.
///
/// Invariants (checked by the constructors): `dim >= 1`, `degree <= MAX_DEGREE`,
/// `n_points >= degree + 1`, a valid knot vector of `n_points + degree + 1` knots with a
/// domain of positive length, finite coordinates, finite positive weights.
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineCurve {
    pub(crate) degree: usize,
    pub(crate) dim: usize,
    pub(crate) knots: Vec<f64>,
    pub(crate) points: Vec<f64>,
    pub(crate) weights: Option<Vec<f64>>,
}

impl BSplineCurve {
    /// A polynomial B-spline curve of degree `degree` from its full knot vector and a flat
    /// row-major point buffer.
    ///
    /// # Errors
    /// [`Error::ZeroDimension`](crate::Error::ZeroDimension),
    /// [`Error::NotEnoughPoints`](crate::Error::NotEnoughPoints) (empty buffer or fewer than
    /// `degree + 1` points), [`Error::LengthMismatch`](crate::Error::LengthMismatch),
    /// [`Error::NonFinite`](crate::Error::NonFinite), and the knot errors of
    /// [`check_knots`](crate::check_knots).
    ///
    /// ```
    /// # use cagd_core::BSplineCurve;
    /// // A clamped quadratic with one interior knot.
    /// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0],
    ///                           vec![0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0], 2)?;
    /// assert_eq!(c.n_points(), 4);
    /// assert_eq!(c.domain(), (0.0, 1.0));
    /// assert_eq!(c.eval(1.0)?, vec![4.0, 0.0]);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn new(degree: usize, knots: Vec<f64>, points: Vec<f64>, dim: usize) -> Result<Self> {
        let n_points = check_points(&points, dim)?;
        check_knots(&knots, n_points, degree)?;
        Ok(Self {
            degree,
            dim,
            knots,
            points,
            weights: None,
        })
    }

    /// A NURBS curve from Euclidean points and positive weights.
    ///
    /// # Errors
    /// As [`BSplineCurve::new`], plus [`Error::LengthMismatch`](crate::Error::LengthMismatch)
    /// and [`Error::NonPositiveWeight`](crate::Error::NonPositiveWeight) for the weights.
    pub fn new_rational(
        degree: usize,
        knots: Vec<f64>,
        points: Vec<f64>,
        weights: Vec<f64>,
        dim: usize,
    ) -> Result<Self> {
        let n_points = check_points(&points, dim)?;
        check_weights(&weights, n_points)?;
        check_knots(&knots, n_points, degree)?;
        Ok(Self {
            degree,
            dim,
            knots,
            points,
            weights: Some(weights),
        })
    }

    /// The degree `p`.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The number of coordinates of each point.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The full knot vector (`n_points + degree + 1` knots).
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The control points, row-major (`n_points * dim` doubles, Euclidean).
    pub fn points(&self) -> &[f64] {
        &self.points
    }

    /// The weights of a NURBS curve, `None` for a polynomial one.
    pub fn weights(&self) -> Option<&[f64]> {
        self.weights.as_deref()
    }

    /// Whether the curve carries weights.
    pub fn is_rational(&self) -> bool {
        self.weights.is_some()
    }

    /// The number of control points `n`.
    pub fn n_points(&self) -> usize {
        self.points.len() / self.dim
    }

    /// The parameter domain `[u_p, u_n]`.
    pub fn domain(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.n_points()])
    }

    /// Consumes the curve and returns `(knots, points, weights)`.
    pub fn into_parts(self) -> (Vec<f64>, Vec<f64>, Option<Vec<f64>>) {
        (self.knots, self.points, self.weights)
    }

    /// The homogeneous control points `(w_i P_i, w_i)`, dimension `dim + 1` (weights 1 for a
    /// polynomial curve).
    pub fn homogeneous_points(&self) -> Vec<f64> {
        let n = self.n_points();
        let mut hom = vec![0.0; n * (self.dim + 1)];
        match &self.weights {
            Some(w) => kernel::to_homogeneous(&self.points, w, self.dim, &mut hom),
            None => kernel::to_homogeneous(&self.points, &vec![1.0; n], self.dim, &mut hom),
        }
        hom
    }

    /// The working points of the algorithms: the points themselves (dimension `dim`) for a
    /// polynomial curve, the homogeneous points (dimension `dim + 1`) for a NURBS curve.
    pub(crate) fn work_points(&self) -> (Vec<f64>, usize) {
        match self.weights {
            None => (self.points.clone(), self.dim),
            Some(_) => (self.homogeneous_points(), self.dim + 1),
        }
    }

    /// The working points (as [`Self::work_points`]) of indices `first..first + count` only:
    /// what one span's evaluation needs, without converting or copying the whole net (an
    /// evaluation stays O(p^2), not O(number of points)).
    pub(crate) fn local_work(&self, first: usize, count: usize) -> (Vec<f64>, usize) {
        let d = self.dim;
        let pts = &self.points[first * d..(first + count) * d];
        match &self.weights {
            None => (pts.to_vec(), d),
            Some(w) => {
                let mut out = Vec::with_capacity(count * (d + 1));
                for (p, &wi) in pts.chunks_exact(d).zip(&w[first..first + count]) {
                    out.extend(p.iter().map(|x| x * wi));
                    out.push(wi);
                }
                (out, d + 1)
            }
        }
    }

    /// Rebuilds a curve of the same kind from working points (see `work_points`) and a new
    /// knot vector, re-validating everything (so a numerical accident is an error, never an
    /// invalid object).
    pub(crate) fn rebuild_from_work(&self, knots: Vec<f64>, work: Vec<f64>) -> Result<Self> {
        match self.weights {
            None => Self::new(self.degree, knots, work, self.dim),
            Some(_) => {
                let n = work.len() / (self.dim + 1);
                let mut points = vec![0.0; n * self.dim];
                let mut weights = vec![0.0; n];
                kernel::from_homogeneous(&work, self.dim, &mut points, &mut weights);
                Self::new_rational(self.degree, knots, points, weights, self.dim)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Error;

    fn knots() -> Vec<f64> {
        vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]
    }

    fn pts() -> Vec<f64> {
        vec![0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0]
    }

    #[test]
    fn bad_input_gives_the_matching_variant() {
        let mut nan = pts();
        nan[3] = f64::NAN;
        assert!(matches!(
            BSplineCurve::new(2, knots(), nan, 2),
            Err(Error::NonFinite {
                index: 1,
                coord: 1,
                ..
            })
        ));
        for (w, index) in [([1.0, 0.0, 1.0, 1.0], 1), ([1.0, 1.0, -2.0, 1.0], 2)] {
            assert!(matches!(
                BSplineCurve::new_rational(2, knots(), pts(), w.to_vec(), 2),
                Err(Error::NonPositiveWeight { index: i, .. }) if i == index
            ));
        }
        assert!(matches!(
            BSplineCurve::new_rational(2, knots(), pts(), vec![1.0; 3], 2),
            Err(Error::LengthMismatch { .. })
        ));
        let mut dec = knots();
        dec.swap(3, 4);
        assert_eq!(
            BSplineCurve::new(2, dec, pts(), 2),
            Err(Error::KnotsNotNondecreasing { index: 4 })
        );
        assert!(matches!(
            BSplineCurve::new(2, knots()[1..].to_vec(), pts(), 2),
            Err(Error::KnotCount { .. })
        ));
        let high = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        assert!(matches!(
            BSplineCurve::new(2, high, pts(), 2),
            Err(Error::MultiplicityAboveDegree { .. })
        ));
        let k65: Vec<f64> = (0..132).map(f64::from).collect();
        assert!(matches!(
            BSplineCurve::new(65, k65, vec![0.0; 66], 1),
            Err(Error::DegreeOutOfRange { degree: 65, .. })
        ));
        assert!(matches!(
            BSplineCurve::new(2, knots(), vec![], 2),
            Err(Error::NotEnoughPoints { got: 0, .. })
        ));
        assert_eq!(
            BSplineCurve::new(2, knots(), pts(), 0),
            Err(Error::ZeroDimension)
        );
        assert!(matches!(
            BSplineCurve::new(2, knots(), pts()[..7].to_vec(), 2),
            Err(Error::LengthMismatch { .. })
        ));
        assert!(matches!(
            BSplineCurve::new(4, vec![0.0; 8], vec![0.0; 6], 2),
            Err(Error::NotEnoughPoints { got: 3, need: 5 })
        ));
        let mut inf = knots();
        inf[6] = f64::INFINITY;
        assert!(matches!(
            BSplineCurve::new(2, inf, pts(), 2),
            Err(Error::NonFiniteKnot { index: 6, .. })
        ));
    }

    #[test]
    fn accessors() {
        let c = BSplineCurve::new_rational(2, knots(), pts(), vec![1.0, 2.0, 1.0, 1.0], 2).unwrap();
        assert_eq!(c.degree(), 2);
        assert_eq!(c.dim(), 2);
        assert_eq!(c.n_points(), 4);
        assert_eq!(c.knots(), &knots()[..]);
        assert_eq!(c.points(), &pts()[..]);
        assert_eq!(c.weights(), Some(&[1.0, 2.0, 1.0, 1.0][..]));
        assert!(c.is_rational());
        assert_eq!(c.domain(), (0.0, 1.0));
        assert_eq!(&c.homogeneous_points()[3..6], &[2.0, 4.0, 2.0]);
    }
}
