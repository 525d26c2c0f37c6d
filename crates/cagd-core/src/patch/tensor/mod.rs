//! Tensor-product Bézier patches of degree `(m, n)`:
//! `P(u, v) = sum_i sum_j B_i^m(u) B_j^n(v) P_ij`, stored i-major (`P_ij` at `i * (n + 1) + j`,
//! `i` along `u`), DESIGN.md.

mod ops;
#[cfg(test)]
mod tests;

use crate::binomial::check_degree;
use crate::validate::check_points;
use crate::{Error, Result};

/// A tensor-product Bézier patch: `(m + 1) * (n + 1)` control points of `dim` coordinates.
///
/// Invariants (checked by [`TensorPatch::new`]): `dim >= 1`, `m, n <= MAX_DEGREE`, all
/// coordinates finite.
#[derive(Debug, Clone, PartialEq)]
pub struct TensorPatch {
    pub(crate) dim: usize,
    pub(crate) deg_u: usize,
    pub(crate) deg_v: usize,
    pub(crate) points: Vec<f64>,
}

impl TensorPatch {
    /// A patch of degree `(deg_u, deg_v)` from `(deg_u + 1) * (deg_v + 1) * dim` coordinates,
    /// i-major.
    ///
    /// # Errors
    /// [`Error::DegreeOutOfRange`], [`Error::ZeroDimension`], [`Error::LengthMismatch`],
    /// [`Error::NonFinite`].
    pub fn new(points: Vec<f64>, deg_u: usize, deg_v: usize, dim: usize) -> Result<Self> {
        check_degree(deg_u)?;
        check_degree(deg_v)?;
        let n_points = check_points(&points, dim)?;
        let expected = (deg_u + 1) * (deg_v + 1);
        if n_points != expected {
            return Err(Error::LengthMismatch {
                what: "tensor patch points ((m + 1) * (n + 1))",
                got: n_points,
                expected,
            });
        }
        Ok(Self {
            dim,
            deg_u,
            deg_v,
            points,
        })
    }

    /// Degrees `(m, n)` in `u` and `v`.
    pub fn degrees(&self) -> (usize, usize) {
        (self.deg_u, self.deg_v)
    }

    /// Number of coordinates of each point.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// All control points, i-major, `(m + 1) * (n + 1) * dim` doubles.
    pub fn points(&self) -> &[f64] {
        &self.points
    }

    /// Control point `P_ij` (`dim` doubles). Panics when out of range (a caller bug).
    pub fn point(&self, i: usize, j: usize) -> &[f64] {
        let idx = i * (self.deg_v + 1) + j;
        &self.points[idx * self.dim..(idx + 1) * self.dim]
    }
}
