//! Certified error bounds that cost about one more GEMM (goes beyond the seed; the
//! convex-hull argument is seed 000 §14.4.3): the bound levels ([`BoundLevel`]), the
//! precomputed piecewise error map (`operator/error_map.rs`), the refinement of its pieces into a number
//! (`refine.rs`), and the per-curve entry point [`Operator::certified_bound`].

mod refine;

use cagd_core::Result;

pub(crate) use refine::{Scratch, pieces_bound, split_half};

use super::operator::{BoundMap, Operator, check_len, max_norm};

/// Midpoint-subdivision levels of the error map at [`BoundLevel::Fast`]: `2^2 = 4` pieces.
pub(crate) const FAST_LEVELS: usize = 2;

/// Levels of the error map the tight refinement starts from.
pub(crate) const TIGHT_LEVELS: usize = 2;

/// How much work a certified error bound may take. Every level but
/// [`BoundLevel::None`] gives a true upper bound of `max_t ||P(t) - Q(t)||` (rounding
/// included); they differ in how close it is to the true error.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
#[non_exhaustive]
pub enum BoundLevel {
    /// No bound (the report's `error_bound` is `None`): the reduction alone.
    None,
    /// One more precomputed linear map: the error curve split into 4 pieces, the largest
    /// control-point norm (or the method's own bound, if smaller). Typically 1.2–2.5× the
    /// true error.
    Fast,
    /// As [`BoundLevel::Fast`], then the pieces that may hold the maximum are split
    /// further (best-first branch and bound) until the bound is within 8 % of a curve
    /// value: at most 1.08× the true error (plus the rounding allowance), except when a
    /// piece reaches 16 extra levels or 4096 splits are spent first (then still a true
    /// bound). The default.
    #[default]
    Tight,
}

impl Operator {
    /// The piecewise error map of `level` (`None` for [`BoundLevel::None`]), built on
    /// first use.
    pub(crate) fn bound_map(&self, level: BoundLevel) -> Option<&BoundMap> {
        match level {
            BoundLevel::None => None,
            BoundLevel::Fast => Some(self.error_map(0, FAST_LEVELS)),
            BoundLevel::Tight => Some(self.error_map(1, TIGHT_LEVELS)),
        }
    }

    /// A certified upper bound of `max_t ||P(t) - Q(t)||` (Euclidean, in the space of the
    /// given points) for the input `points` (`n + 1` points of `dim` coordinates) and the
    /// reduced points `Q` that [`Operator::apply`] gives for them (their `f64` rounding
    /// included), at `level`; `None` for [`BoundLevel::None`]. The smaller of the method's
    /// own bound (if it has one) and the piecewise convex-hull bound of the error curve.
    ///
    /// # Errors
    /// [`cagd_core::Error::ZeroDimension`], [`cagd_core::Error::LengthMismatch`].
    pub fn certified_bound(
        &self,
        points: &[f64],
        dim: usize,
        level: BoundLevel,
    ) -> Result<Option<f64>> {
        check_len(points, self.degree_from(), dim, "points")?;
        let Some(bm) = self.bound_map(level) else {
            return Ok(None);
        };
        let mut pieces = vec![0.0; bm.map.rows() * dim];
        bm.map.apply_loop(points, dim, &mut pieces);
        let mut scratch = Scratch::default();
        Ok(Some(self.curve_bound(
            bm,
            points,
            dim,
            &pieces,
            level == BoundLevel::Tight,
            &mut scratch,
        )))
    }

    /// The bound of one curve from its input and its computed reduced points (the route of
    /// the single-curve call, where `reduced` is at hand): the error curve `P - E Q` formed
    /// from the computed `Q` (its rounding included by construction, as in seed 000
    /// §14.4.3's hull bound), split into the same 4 pieces by de Casteljau, then the same
    /// per-piece bounds and refinement as the linear map. Its rounding allowance is that
    /// of the elevation and subtraction (`2 (n + 3) eps (max ||P_j|| + max ||Q_i||)`) and
    /// of the splits (`(n eps)` of the largest difference point per level), smaller than
    /// the map's for operators of large norm. `None` for [`BoundLevel::None`].
    pub(crate) fn direct_bound(
        &self,
        points: &[f64],
        reduced: &[f64],
        dim: usize,
        level: BoundLevel,
    ) -> Option<f64> {
        let tight = match level {
            BoundLevel::None => return None,
            BoundLevel::Fast => false,
            BoundLevel::Tight => true,
        };
        let (n, m) = (self.degree_from(), self.degree_to());
        let len = (n + 1) * dim;
        let pieces_n = 1usize << FAST_LEVELS;
        let mut pieces = vec![0.0; pieces_n * len];
        cagd_core::kernel::elevate(reduced, dim, n - m, &mut pieces[..len]);
        for (d, p) in pieces[..len].iter_mut().zip(points) {
            *d = p - *d;
        }
        let top = max_norm(&pieces[..len], dim);
        let (mut left, mut right) = (vec![0.0; len], vec![0.0; len]);
        for lvl in 0..FAST_LEVELS {
            for piece in (0..1usize << lvl).rev() {
                split_half(
                    &pieces[piece * len..(piece + 1) * len],
                    dim,
                    &mut left,
                    &mut right,
                );
                pieces[2 * piece * len..(2 * piece + 1) * len].copy_from_slice(&left);
                pieces[(2 * piece + 1) * len..(2 * piece + 2) * len].copy_from_slice(&right);
            }
        }
        let eps = f64::EPSILON;
        let mut scratch = Scratch::default();
        let hull = pieces_bound(&pieces, n + 1, dim, tight, &mut scratch)
            + ((FAST_LEVELS * n) as f64) * eps * top;
        let slack = 2.0 * (n as f64 + 3.0) * eps * (max_norm(points, dim) + max_norm(reduced, dim));
        let linear = hull * (1.0 + 4.0 * eps) + slack;
        let bound = match self.own_bound(points, dim) {
            Some(own) => own.min(linear),
            None => linear,
        };
        Some(if bound.is_nan() { f64::INFINITY } else { bound })
    }

    /// The bound of one curve from its computed error pieces (see
    /// [`Operator::certified_bound`]); `+inf` if the numbers overflowed.
    pub(crate) fn curve_bound(
        &self,
        bm: &BoundMap,
        points: &[f64],
        dim: usize,
        pieces: &[f64],
        tight: bool,
        scratch: &mut Scratch,
    ) -> f64 {
        let n1 = self.degree_from() + 1;
        let pmax = max_norm(points, dim);
        let hull = pieces_bound(pieces, n1, dim, tight, scratch);
        let linear = hull + bm.slack * pmax * (1.0 + 4.0 * f64::EPSILON);
        let bound = match self.own_bound(points, dim) {
            Some(own) => own.min(linear),
            None => linear,
        };
        if bound.is_nan() { f64::INFINITY } else { bound }
    }
}
