//! Bézier curves of any degree (0..=[`MAX_DEGREE`]) and dimension, polynomial or rational.
//!
//! `P(t) = sum_i B_i^n(t) P_i` (polynomial) or `sum_i B_i^n(t) w_i P_i / sum_i B_i^n(t) w_i`
//! (rational; DESIGN.md: Euclidean points plus a separate weight array).

use crate::binomial::{check_degree, sign_binomial_f64};
use crate::validate::{check_finite_param, check_points, check_weights};
use crate::{Error, MAX_DEGREE, Result, kernel};

/// A Bézier curve: `n + 1` control points of `dim` coordinates (row-major) and, for a
/// rational curve, `n + 1` positive weights.
///
/// Invariants (checked by the constructors): `dim >= 1`, `1 <= n + 1 <= MAX_DEGREE + 1`
/// points, all coordinates finite, all weights finite and `> 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierCurve {
    dim: usize,
    points: Vec<f64>,
    weights: Option<Vec<f64>>,
}

impl BezierCurve {
    /// A polynomial Bézier curve from a flat row-major point buffer.
    ///
    /// # Errors
    /// [`Error::ZeroDimension`], [`Error::NotEnoughPoints`], [`Error::LengthMismatch`],
    /// [`Error::NonFinite`], [`Error::DegreeOutOfRange`] (more than `MAX_DEGREE + 1` points).
    ///
    /// ```
    /// # use cagd_core::BezierCurve;
    /// let c = BezierCurve::new(vec![0.0, 0.0, 1.0, 2.0, 2.0, 0.0], 2)?;
    /// assert_eq!(c.degree(), 2);
    /// assert_eq!(c.eval(0.5), vec![1.0, 1.0]);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn new(points: Vec<f64>, dim: usize) -> Result<Self> {
        let n_points = check_points(&points, dim)?;
        check_degree(n_points - 1)?;
        Ok(Self {
            dim,
            points,
            weights: None,
        })
    }

    /// A rational Bézier curve from Euclidean points and positive weights.
    ///
    /// # Errors
    /// As [`BezierCurve::new`], plus [`Error::LengthMismatch`] and
    /// [`Error::NonPositiveWeight`] for the weights.
    pub fn new_rational(points: Vec<f64>, weights: Vec<f64>, dim: usize) -> Result<Self> {
        let n_points = check_points(&points, dim)?;
        check_degree(n_points - 1)?;
        check_weights(&weights, n_points)?;
        Ok(Self {
            dim,
            points,
            weights: Some(weights),
        })
    }

    /// A curve from homogeneous points `(w_i P_i, w_i)` of dimension `dim + 1`.
    ///
    /// # Errors
    /// As [`BezierCurve::new_rational`]; `hom_dim` must be at least 2.
    pub fn from_homogeneous(hom: &[f64], hom_dim: usize) -> Result<Self> {
        if hom_dim < 2 {
            return Err(Error::ZeroDimension);
        }
        let n_points = check_points(hom, hom_dim)?;
        let dim = hom_dim - 1;
        let mut points = vec![0.0; n_points * dim];
        let mut weights = vec![0.0; n_points];
        for i in 0..n_points {
            weights[i] = hom[i * hom_dim + dim];
        }
        check_weights(&weights, n_points)?;
        kernel::from_homogeneous(hom, dim, &mut points, &mut weights);
        Self::new_rational(points, weights, dim)
    }

    /// The polynomial degree `n` (number of points minus one).
    pub fn degree(&self) -> usize {
        self.points.len() / self.dim - 1
    }

    /// The number of coordinates of each point.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The control points, row-major (`(n + 1) * dim` doubles).
    pub fn points(&self) -> &[f64] {
        &self.points
    }

    /// Control point `i` (`dim` doubles). Panics if `i > n` (an indexing bug of the caller).
    pub fn point(&self, i: usize) -> &[f64] {
        &self.points[i * self.dim..(i + 1) * self.dim]
    }

    /// The weights of a rational curve, `None` for a polynomial one.
    pub fn weights(&self) -> Option<&[f64]> {
        self.weights.as_deref()
    }

    /// Whether the curve carries weights.
    pub fn is_rational(&self) -> bool {
        self.weights.is_some()
    }

    /// Consumes the curve and returns its points and weights.
    pub fn into_parts(self) -> (Vec<f64>, Option<Vec<f64>>) {
        (self.points, self.weights)
    }

    /// Homogeneous control points `(w_i P_i, w_i)`, dimension `dim + 1` (weights 1 for a
    /// polynomial curve).
    pub fn homogeneous_points(&self) -> Vec<f64> {
        let n1 = self.degree() + 1;
        let mut hom = vec![0.0; n1 * (self.dim + 1)];
        match &self.weights {
            Some(w) => kernel::to_homogeneous(&self.points, w, self.dim, &mut hom),
            None => kernel::to_homogeneous(&self.points, &vec![1.0; n1], self.dim, &mut hom),
        }
        hom
    }

    /// The polynomial curve in `dim + 1` dimensions whose points are the homogeneous points.
    pub fn to_homogeneous(&self) -> BezierCurve {
        BezierCurve {
            dim: self.dim + 1,
            points: self.homogeneous_points(),
            weights: None,
        }
    }

    /// Evaluates the curve at `t` into `out` (`dim` doubles), by de Casteljau (in homogeneous
    /// space for a rational curve). `t` outside `[0, 1]` extrapolates.
    pub fn eval_into(&self, t: f64, out: &mut [f64]) {
        match &self.weights {
            None => {
                let mut work = vec![0.0; self.points.len()];
                kernel::de_casteljau(&self.points, self.dim, t, &mut work, out);
            }
            Some(_) => {
                let hom = self.homogeneous_points();
                let mut work = vec![0.0; hom.len()];
                let mut h = vec![0.0; self.dim + 1];
                kernel::de_casteljau(&hom, self.dim + 1, t, &mut work, &mut h);
                for k in 0..self.dim {
                    out[k] = h[k] / h[self.dim];
                }
            }
        }
    }

    /// Evaluates the curve at `t` (see [`BezierCurve::eval_into`]).
    pub fn eval(&self, t: f64) -> Vec<f64> {
        let mut out = vec![0.0; self.dim];
        self.eval_into(t, &mut out);
        out
    }

    /// The forward difference `Delta^n P_0 = sum_i (-1)^(n-i) C(n,i) P_i` (seed 000
    /// eq. 14.1.1): the curve has degree `< n` iff this vector is zero. It is the coefficient
    /// of `t^n` divided by `C(n,n) = 1` in the power form. For a rational curve it is taken
    /// of the homogeneous points (`dim + 1` coordinates).
    pub fn forward_difference(&self) -> Vec<f64> {
        let (pts, d) = match &self.weights {
            None => (self.points.clone(), self.dim),
            Some(_) => (self.homogeneous_points(), self.dim + 1),
        };
        let n = pts.len() / d - 1;
        let mut f = vec![0.0; d];
        for i in 0..=n {
            let c = sign_binomial_f64(n, i);
            for k in 0..d {
                f[k] += c * pts[i * d + k];
            }
        }
        f
    }

    /// Builds a curve of the same kind (rational or not) from new points / weights; used by
    /// operations that keep validity by construction.
    pub(crate) fn with_parts(dim: usize, points: Vec<f64>, weights: Option<Vec<f64>>) -> Self {
        debug_assert!(points.len() % dim == 0 && points.len() / dim <= MAX_DEGREE + 1);
        Self {
            dim,
            points,
            weights,
        }
    }

    /// Checks that `t` is finite (for operations that take a parameter).
    pub(crate) fn check_param(name: &'static str, t: f64) -> Result<()> {
        check_finite_param(name, t)
    }
}
