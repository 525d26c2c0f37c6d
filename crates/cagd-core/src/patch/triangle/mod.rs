//! Triangular Bézier patches of degree `n`:
//! `T(u, v) = sum_{i+j<=n} n!/(i! j! k!) u^i v^j w^k T_ij`, `w = 1 - u - v`, `k = n - i - j`,
//! on the domain `u, v >= 0, u + v <= 1` (seed 002 §15.4, seed 000 §14.1). Stored i-major:
//! for `i` in `0..=n`, for `j` in `0..=n-i` (DESIGN.md).

mod ops;
mod subdivide;

use crate::binomial::check_degree;
use crate::validate::check_points;
use crate::{Error, Result};

/// Number of control points of a triangular patch of degree `n`: `(n + 1)(n + 2) / 2`.
pub fn tri_count(n: usize) -> usize {
    (n + 1) * (n + 2) / 2
}

/// Storage index of `T_ij` (i-major) in a triangular net of degree `n`; requires `i + j <= n`.
pub fn tri_index(n: usize, i: usize, j: usize) -> usize {
    debug_assert!(i + j <= n);
    // Rows 0..i hold (n + 1) + n + ... + (n + 2 - i) points.
    i * (2 * n + 3 - i) / 2 + j
}

/// A triangular Bézier patch of degree `n` with `(n + 1)(n + 2) / 2` control points.
///
/// Invariants (checked by [`TriPatch::new`]): `dim >= 1`, `n <= MAX_DEGREE`, all
/// coordinates finite.
#[derive(Debug, Clone, PartialEq)]
pub struct TriPatch {
    pub(crate) dim: usize,
    pub(crate) degree: usize,
    pub(crate) points: Vec<f64>,
}

impl TriPatch {
    /// A triangular patch of degree `degree` from `tri_count(degree) * dim` coordinates,
    /// i-major.
    ///
    /// # Errors
    /// [`Error::DegreeOutOfRange`], [`Error::ZeroDimension`], [`Error::LengthMismatch`],
    /// [`Error::NonFinite`].
    pub fn new(points: Vec<f64>, degree: usize, dim: usize) -> Result<Self> {
        check_degree(degree)?;
        let n_points = check_points(&points, dim)?;
        if n_points != tri_count(degree) {
            return Err(Error::LengthMismatch {
                what: "triangular patch points ((n + 1)(n + 2) / 2)",
                got: n_points,
                expected: tri_count(degree),
            });
        }
        Ok(Self {
            dim,
            degree,
            points,
        })
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// Number of coordinates of each point.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// All control points, i-major, `tri_count(n) * dim` doubles.
    pub fn points(&self) -> &[f64] {
        &self.points
    }

    /// Control point `T_ij` (`dim` doubles); requires `i + j <= n` (panics otherwise: a
    /// caller bug).
    pub fn point(&self, i: usize, j: usize) -> &[f64] {
        assert!(
            i + j <= self.degree,
            "T_{i}{j} outside a degree-{} net",
            self.degree
        );
        let idx = tri_index(self.degree, i, j);
        &self.points[idx * self.dim..(idx + 1) * self.dim]
    }
}

#[cfg(test)]
mod tests;
