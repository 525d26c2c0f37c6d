//! [`BezierPieces`]: the rational (or polynomial) Bézier pieces of a spline with their
//! breakpoints, in flat arrays (one allocation per array, none per piece).

use cagd_core::{BezierCurve, Error, Result, check_degree, check_points, check_weights};

use super::outer_knots::OuterKnots;

/// Consecutive Bézier pieces of one degree: piece `k` is the segment on `[0, 1]` that
/// reparametrises the spline on `[breaks[k], breaks[k + 1]]`.
///
/// Layout (DESIGN.md): `points` holds `len() * (degree + 1)` Euclidean points of `dim`
/// coordinates, piece-major (piece `k`, point `i`, coordinate `c` at
/// `(k * (degree + 1) + i) * dim + c`); `weights`, when rational, one weight per point in
/// the same order. `breaks` strictly increase, one more than the pieces. `outer`, when
/// set, holds the knots of an unclamped spline beyond its first and last break (see
/// [`OuterKnots`]); without it the pieces stand for a clamped spline.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BezierPieces {
    pub(crate) degree: usize,
    pub(crate) dim: usize,
    pub(crate) breaks: Vec<f64>,
    pub(crate) points: Vec<f64>,
    pub(crate) weights: Option<Vec<f64>>,
    pub(crate) outer: Option<OuterKnots>,
}

impl BezierPieces {
    /// Pieces from their flat arrays, validated.
    ///
    /// # Errors
    /// [`Error::DegreeOutOfRange`], [`Error::ZeroDimension`], [`Error::NotEnoughPoints`]
    /// (no piece), [`Error::LengthMismatch`] (points or weights not
    /// `pieces * (degree + 1)`), [`Error::NonFinite`], [`Error::NonPositiveWeight`],
    /// [`Error::BadParameter`] (`"breaks"` not finite or not strictly increasing).
    pub fn new(
        degree: usize,
        dim: usize,
        breaks: Vec<f64>,
        points: Vec<f64>,
        weights: Option<Vec<f64>>,
    ) -> Result<Self> {
        check_degree(degree)?;
        if breaks.len() < 2 {
            return Err(Error::NotEnoughPoints {
                got: breaks.len(),
                need: 2,
            });
        }
        let count = breaks.len() - 1;
        let n = check_points(&points, dim)?;
        if n != count * (degree + 1) {
            return Err(Error::LengthMismatch {
                what: "points of the pieces (pieces * (degree + 1))",
                got: n,
                expected: count * (degree + 1),
            });
        }
        if let Some(w) = &weights {
            check_weights(w, n)?;
        }
        check_breaks(&breaks)?;
        Ok(Self {
            degree,
            dim,
            breaks,
            points,
            weights,
            outer: None,
        })
    }

    /// The same pieces, standing for the spline whose knot vector has `left` before the
    /// last copy of the first break and `right` after the first copy of the last break (an
    /// unclamped spline; [`crate::pieces_to_nurbs`] then gives back that knot vector).
    ///
    /// # Errors
    /// [`Error::BadParameter`] naming `"outer_knots.left"` / `"outer_knots.right"` (see
    /// [`OuterKnots`] for the rules).
    pub fn with_outer_knots(mut self, left: Vec<f64>, right: Vec<f64>) -> Result<Self> {
        let (a, b) = (self.breaks[0], self.breaks[self.breaks.len() - 1]);
        self.outer = Some(OuterKnots::new(left, right, self.degree, a, b)?);
        Ok(self)
    }

    /// The outer knots of an unclamped spline, `None` for a clamped one.
    pub fn outer_knots(&self) -> Option<&OuterKnots> {
        self.outer.as_ref()
    }

    /// Pieces from Bézier segments and their `segments.len() + 1` breaks. If any segment is
    /// rational all pieces get weights (1 for the polynomial ones).
    ///
    /// # Errors
    /// As [`BezierPieces::new`]; [`Error::LengthMismatch`] for segments of differing degree
    /// or dimension, or a wrong number of breaks.
    pub fn from_segments(segments: &[BezierCurve], breaks: &[f64]) -> Result<Self> {
        let first = segments
            .first()
            .ok_or(Error::NotEnoughPoints { got: 0, need: 1 })?;
        let (p, dim) = (first.degree(), first.dim());
        if breaks.len() != segments.len() + 1 {
            return Err(Error::LengthMismatch {
                what: "breaks (segments + 1)",
                got: breaks.len(),
                expected: segments.len() + 1,
            });
        }
        let rational = segments.iter().any(BezierCurve::is_rational);
        let mut points = Vec::with_capacity(segments.len() * (p + 1) * dim);
        let mut weights = Vec::new();
        for s in segments {
            if s.degree() != p || s.dim() != dim {
                let (what, got, expected) = if s.dim() != dim {
                    ("segment dimensions", s.dim(), dim)
                } else {
                    ("segment degrees", s.degree(), p)
                };
                return Err(Error::LengthMismatch {
                    what,
                    got,
                    expected,
                });
            }
            points.extend_from_slice(s.points());
            if rational {
                match s.weights() {
                    Some(w) => weights.extend_from_slice(w),
                    None => weights.extend(std::iter::repeat_n(1.0, p + 1)),
                }
            }
        }
        Self::new(p, dim, breaks.to_vec(), points, rational.then_some(weights))
    }

    /// The number of pieces.
    pub fn len(&self) -> usize {
        self.breaks.len().saturating_sub(1)
    }

    /// Whether there is no piece (only for a default-constructed value).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The common degree of the pieces.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The number of coordinates of each point.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The breakpoints (`len() + 1`, strictly increasing).
    pub fn breaks(&self) -> &[f64] {
        &self.breaks
    }

    /// Every point of every piece, piece-major, Euclidean.
    pub fn points(&self) -> &[f64] {
        &self.points
    }

    /// Every weight of every piece (same order as the points), `None` when polynomial.
    pub fn weights(&self) -> Option<&[f64]> {
        self.weights.as_deref()
    }

    /// Whether the pieces carry weights.
    pub fn is_rational(&self) -> bool {
        self.weights.is_some()
    }

    /// The points of piece `k` (`(degree + 1) * dim` values). Panics if `k >= len()`.
    pub fn piece_points(&self, k: usize) -> &[f64] {
        let m = (self.degree + 1) * self.dim;
        &self.points[k * m..(k + 1) * m]
    }

    /// The weights of piece `k`, `None` when polynomial. Panics if `k >= len()`.
    pub fn piece_weights(&self, k: usize) -> Option<&[f64]> {
        let m = self.degree + 1;
        self.weights.as_ref().map(|w| &w[k * m..(k + 1) * m])
    }

    /// Piece `k` as a [`BezierCurve`] on `[0, 1]`.
    ///
    /// # Errors
    /// [`Error::BadParameter`] when `k >= len()`.
    pub fn piece(&self, k: usize) -> Result<BezierCurve> {
        if k >= self.len() {
            return Err(Error::BadParameter {
                name: "piece",
                value: k as f64,
                why: "piece index out of range",
            });
        }
        let pts = self.piece_points(k).to_vec();
        match self.piece_weights(k) {
            None => BezierCurve::new(pts, self.dim),
            Some(w) => BezierCurve::new_rational(pts, w.to_vec(), self.dim),
        }
    }

    /// Every piece as a [`BezierCurve`].
    ///
    /// # Errors
    /// None for a valid value (kept for symmetry with [`BezierPieces::piece`]).
    pub fn to_segments(&self) -> Result<Vec<BezierCurve>> {
        (0..self.len()).map(|k| self.piece(k)).collect()
    }

    /// The point at the global parameter `t` (clamped to `[breaks[0], breaks[len]]`),
    /// evaluated on the piece that contains it.
    pub fn eval(&self, t: f64) -> Vec<f64> {
        let n = self.len();
        let k = self.breaks[1..n].partition_point(|b| *b <= t).min(n - 1);
        let (a, b) = (self.breaks[k], self.breaks[k + 1]);
        let s = ((t - a) / (b - a)).clamp(0.0, 1.0);
        let mut out = vec![0.0; self.dim];
        match self.piece(k) {
            Ok(c) => c.eval_into(s, &mut out),
            Err(_) => out.fill(f64::NAN),
        }
        out
    }
}

/// Checks breaks: finite, strictly increasing.
pub(crate) fn check_breaks(breaks: &[f64]) -> Result<()> {
    for (i, &b) in breaks.iter().enumerate() {
        if !b.is_finite() || (i > 0 && b <= breaks[i - 1]) {
            return Err(Error::BadParameter {
                name: "breaks",
                value: b,
                why: "breaks must be finite and strictly increasing",
            });
        }
    }
    Ok(())
}
