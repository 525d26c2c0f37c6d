//! Certified error bounds that cost about one more small GEMM (goes beyond the seed; the
//! error curve is that of seed 000 §14.4.3): the bound levels ([`BoundLevel`]), the
//! error curve in a basis of its own size (`operator/error_basis.rs`), its values at
//! Chebyshev–Lobatto nodes with the Ehlich–Zeller factor (`operator/error_map.rs`), the
//! largest node value (`nodes.rs`), and the per-curve entry point
//! [`Operator::certified_bound`].

mod nodes;

use cagd_core::Result;

pub(crate) use nodes::{BY_NODES_MIN, max_pair_norm, max_pair_norm_t, max_value_norm};

use super::operator::{BoundMap, Operator, check_len, hull_bound, max_norm};

/// Largest coordinates outside `[SAFE_LOW, SAFE_HIGH]` are scaled before the norms (see
/// [`Operator::one_bound`]): inside, no square of a value the bound computes overflows,
/// and rounding stays relative (no underflow to subnormals).
const SAFE_LOW: f64 = 3.5e-136; // about 2^-450
const SAFE_HIGH: f64 = 2.9e135; // about 2^450

/// The secant factor of [`BoundLevel::Fast`]: the bound is at most this times the true
/// error (plus the rounding allowance).
pub(crate) const FAST_RATIO: f64 = 1.25;

/// The secant factor of [`BoundLevel::Tight`].
pub(crate) const TIGHT_RATIO: f64 = 1.075;

/// How much work a certified error bound may take. Every level but
/// [`BoundLevel::None`] gives a true upper bound of `max_t ||P(t) - Q(t)||` (rounding
/// included); they differ in how close it is to the true error.
///
/// Both certified levels evaluate the error curve, written in a basis of `n - m` curves,
/// at `N + 1` Chebyshev–Lobatto nodes and multiply the largest value by the Ehlich–Zeller
/// factor `sec(n pi / (2N))` (see `operator/error_map.rs`): the bound is at most that
/// factor times the true error, for every curve. The cost is `(N + 1)(n - m) + (n - m)(n +
/// 1)` multiply-adds per coordinate (the reduction itself: `(m + 1)(n + 1)`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
#[non_exhaustive]
pub enum BoundLevel {
    /// No bound (the report's `error_bound` is `None`): the reduction alone.
    None,
    /// At most 1.25× the true error plus the rounding allowance (`N ≈ 2.4 n` nodes), or
    /// the method's own bound if that is smaller.
    Fast,
    /// At most 1.075× the true error plus the rounding allowance (`N ≈ 4.2 n` nodes), or
    /// the method's own bound if that is smaller. The default.
    #[default]
    Tight,
}

impl Operator {
    /// The node map of `level` (`None` for [`BoundLevel::None`]), built on first use.
    pub(crate) fn bound_map(&self, level: BoundLevel) -> Option<&BoundMap> {
        match level {
            BoundLevel::None => None,
            BoundLevel::Fast => Some(self.error_map(0, FAST_RATIO)),
            BoundLevel::Tight => Some(self.error_map(1, TIGHT_RATIO)),
        }
    }

    /// A certified upper bound of `max_t ||P(t) - Q(t)||` (Euclidean, in the space of the
    /// given points) for the input `points` (`n + 1` points of `dim` coordinates) and the
    /// reduced points `Q` that [`Operator::apply`] gives for them (their `f64` rounding
    /// included, whatever the order of the sums), at `level`; `None` for
    /// [`BoundLevel::None`]. The smaller of the method's own bound (if it has one) and the
    /// node bound of the error curve (see [`BoundLevel`]); `+inf` if the numbers overflow.
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
        Ok(Some(self.one_bound(bm, points, dim)))
    }

    /// The node bound of one curve, through the fused loop; input whose largest coordinate
    /// is outside `[2^-450, 2^450]` is first scaled by a power of two (exact), so that no
    /// square in the norms overflows or underflows, and the bound scaled back.
    pub(crate) fn one_bound(&self, bm: &BoundMap, points: &[f64], dim: usize) -> f64 {
        if safe_range(points) {
            return self.fused_bound(bm, points, dim);
        }
        let amax = points.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        let (s1, s2) = pow2_factors(amax);
        let scaled: Vec<f64> = points.iter().map(|x| x * s1 * s2).collect();
        let b = self.fused_bound(bm, &scaled, dim) / s1 / s2;
        // Subnormal rounding of the reduced points in the caller's scale: far below this.
        b + f64::MIN_POSITIVE
    }

    fn fused_bound(&self, bm: &BoundMap, points: &[f64], dim: usize) -> f64 {
        let basis = self.error_basis();
        let mut stack = [0.0; 96];
        let mut heap;
        let len = basis.rank * dim;
        let coef: &mut [f64] = if len <= stack.len() {
            &mut stack[..len]
        } else {
            heap = vec![0.0; len];
            &mut heap
        };
        basis.coef.apply_loop(points, dim, coef);
        let smax = match &bm.split {
            Some((even, odd)) => {
                let (ce, co) = coef.split_at(even.cols() * dim);
                if even.matrix().len() + odd.matrix().len() >= BY_NODES_MIN {
                    let rows = even.rows();
                    max_pair_norm_t(
                        (even.transposed().0, ce),
                        (odd.transposed().0, co),
                        rows,
                        dim,
                    )
                } else {
                    max_pair_norm((even.matrix(), ce), (odd.matrix(), co), dim)
                }
            }
            // The full map as an even part with an empty odd part: `e +- 0` squares to
            // the bits of `e` squared, so this is `max_value_norm`'s result (tested).
            None if bm.samples.matrix().len() >= BY_NODES_MIN => {
                let rows = bm.samples.rows();
                max_pair_norm_t((bm.samples.transposed().0, coef), (&[], &[]), rows, dim)
            }
            None => max_value_norm(bm.samples.matrix(), basis.rank, coef, dim),
        };
        self.curve_bound(bm, points, dim, smax)
    }

    /// `bound` (a node bound of `points`) or, when it is mostly rounding allowance (a
    /// curve of nearly degree `m`: the operator-sized allowance exceeds a 64th of it), the
    /// smaller of it and the hull bound of the error curve `P - E Q` formed from the
    /// computed reduced points (seed 000 §14.4.3, refined by subdivision; its allowance is
    /// relative to `max ||P_j||` and `max ||Q_i||` only). Both are true bounds.
    pub(crate) fn with_reduced(
        &self,
        bm: &BoundMap,
        points: &[f64],
        reduced: &[f64],
        dim: usize,
        bound: f64,
    ) -> f64 {
        let amax = points.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        self.with_reduced_norms(
            bm,
            (points, reduced),
            dim,
            bound,
            max_norm(points, dim),
            amax,
        )
    }

    /// [`Operator::with_reduced`] with `pmax = max_j ||P_j||` and `amax = max |P_jk|`
    /// already computed (by the batch kernel).
    pub(crate) fn with_reduced_norms(
        &self,
        bm: &BoundMap,
        (points, reduced): (&[f64], &[f64]),
        dim: usize,
        bound: f64,
        pmax: f64,
        amax: f64,
    ) -> f64 {
        let allowance = (bm.sec * bm.inner + bm.outer) * pmax;
        if bound > 64.0 * allowance || !bound.is_finite() || !safe_amax(amax) {
            return bound;
        }
        bound.min(hull_bound(points, reduced, dim))
    }

    /// The bound of one curve from the largest computed node value `smax` of its error
    /// curve (see [`Operator::certified_bound`]).
    pub(crate) fn curve_bound(&self, bm: &BoundMap, points: &[f64], dim: usize, smax: f64) -> f64 {
        self.curve_bound_norms(bm, points, dim, smax, max_norm(points, dim))
    }

    /// [`Operator::curve_bound`] with `pmax = max_j ||P_j||` already computed.
    pub(crate) fn curve_bound_norms(
        &self,
        bm: &BoundMap,
        points: &[f64],
        dim: usize,
        smax: f64,
        pmax: f64,
    ) -> f64 {
        let node = bm.finish(smax, pmax, dim);
        match self.own_bound(points, dim) {
            Some(own) if !own.is_nan() => own.min(node),
            _ => node,
        }
    }
}

/// Whether the largest coordinate of `points` is zero or inside the range where the node
/// bound needs no scaling (see [`Operator::one_bound`]); non-finite input counts as safe
/// (its bound is `+inf`, or the caller reports it).
pub(crate) fn safe_range(points: &[f64]) -> bool {
    safe_amax(points.iter().fold(0.0f64, |a, x| a.max(x.abs())))
}

/// The two factors `(s1, s2)`, each a power of two and a normal number, whose product is
/// `2^-e` with `e` the binary exponent of `amax`: `amax s1 s2` is in `[1, 2)` (for a
/// subnormal `amax`, in `[2^-52, 1)`). Multiplying by them is exact but where a product
/// underflows to a subnormal number; dividing by them undoes it.
pub(crate) fn pow2_factors(amax: f64) -> (f64, f64) {
    let biased = i32::try_from((amax.to_bits() >> 52) & 0x7ff).unwrap_or(1023);
    let e = biased - 1023;
    // In two factors, each a normal number for every exponent (|e| <= 1075).
    (2f64.powi(-e / 2), 2f64.powi(-e + e / 2))
}

/// [`safe_range`] from the largest coordinate magnitude `amax`.
pub(crate) fn safe_amax(amax: f64) -> bool {
    amax == 0.0 || (SAFE_LOW..=SAFE_HIGH).contains(&amax) || !amax.is_finite()
}
