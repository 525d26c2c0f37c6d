//! Reduction to a tolerance with `C^k` joins (seed 000 §14.2.2, Algorithm 14.2.1 and
//! eq. 14.2.11, generalised to every linear method; SPEC-reduce §2.2).

mod march;
mod piecewise;
mod stepwise;
#[cfg(test)]
mod tests;

pub use piecewise::{PiecewiseReduction, PiecewiseReport, ReducedPiece};
pub use stepwise::{reduce_to_tolerance_alg_14_2_1, subdivision_levels};

use cagd_core::{BezierCurve, Error, Result, check_tolerance};

use super::method::Method;
use march::march;
use piecewise::{PIECE_SHARE, assemble, measure};

/// Default depth limit: the shortest piece is `2^-30` of the parameter range.
pub const DEFAULT_MAX_DEPTH: usize = 30;

/// The largest number of pieces a reduction to a tolerance may produce (`2^20`).
pub const MAX_PIECES: usize = 1 << 20;

/// Most work of one [`reduce_to_tolerance`]: the pieces tried (accepted or not), each
/// counted `((n + 1)^2 + 64) (d + 1)` for degree `n` in dimension `d`: `2^27`, under a
/// second in a release build (also the limit of [`reduce_to_tolerance_alg_14_2_1`]'s
/// steps, and about that of the measurement of either) (ADDED, bounded work, issue 18: a degree-52 curve ran a
/// million reductions of 27 us each in the C ABI fuzz run; measured, a degree-5 curve in
/// 1D takes 1.2 us per piece).
pub const MAX_TOLERANCE_WORK: usize = 1 << 27;

/// The rounding level of a reduction of `piece`: `2 (n + 3) eps max ||P_i||` (Euclidean
/// points; the allowance of the B-spline fit's spans). No split brings a piece's bound
/// below it: subdividing keeps the points' size, and with it their rounding.
pub(crate) fn rounding_floor(piece: &BezierCurve) -> f64 {
    let n = piece.degree() as f64;
    2.0 * (n + 3.0) * f64::EPSILON * cagd_core::max_point_norm(piece.points(), piece.dim())
}

/// Options of [`reduce_to_tolerance`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToleranceOptions {
    /// The method used on every piece. For `continuity = k` it must interpolate derivatives
    /// up to order `k` at both ends ([`Method::end_orders`]).
    pub method: Method,
    /// The target degree `m < n`.
    pub target: usize,
    /// The tolerance `delta > 0` (Euclidean, model units) the certified bound must meet.
    pub tolerance: f64,
    /// The order `k < m` of the parametric continuity of the joins.
    pub continuity: usize,
    /// Also measure the error of the spline by sampling ([`PiecewiseReport::max_error`]).
    pub measure: bool,
    /// The shortest piece allowed is `2^-max_depth` of the parameter range (not below
    /// `2^-46`; [`DEFAULT_MAX_DEPTH`]). For [`reduce_to_tolerance_alg_14_2_1`]: the
    /// deepest midpoint-subdivision level.
    pub max_depth: usize,
}

impl ToleranceOptions {
    /// Options with the default depth limit, without measuring.
    pub fn new(method: Method, target: usize, tolerance: f64, continuity: usize) -> Self {
        Self {
            method,
            target,
            tolerance,
            continuity,
            measure: false,
            max_depth: DEFAULT_MAX_DEPTH,
        }
    }
}

/// Checks that `method` can produce degree-`m` pieces of a degree-`n` curve that join
/// with `C^k`: as [`Method::check`], `k < m`, and both end orders of the method `>= k`.
pub(crate) fn check_continuity(method: Method, n: usize, m: usize, k: usize) -> Result<()> {
    method.check(n, m)?;
    if k >= m {
        return Err(Error::BadParameter {
            name: "continuity",
            value: k as f64,
            why: "C^k joins of degree-m pieces need k < m (with k >= m the spline would be \
                  one polynomial)",
        });
    }
    let (r, p) = method.end_orders(m);
    if i64::from(r.min(p)) < k as i64 {
        return Err(Error::BadParameter {
            name: "continuity",
            value: k as f64,
            why: "C^k joins need a method that interpolates derivatives up to order k at both \
                  ends of each piece (Method::end_orders), e.g. L2 { r: k, p: k } or \
                  ConstrainedChebyshev { r: k, p: k } with 2k + 1 <= m, Perturb for k = 0, \
                  Forrest for k <= (m - 1) / 2",
        });
    }
    Ok(())
}

/// `log2(ratio) / order` rounded up (`ceil`) or down plus one (`floor + 1`, for a strict
/// `<`), clamped to `0..=64`: the midpoint-subdivision levels after which a bound that
/// scales by `2^-order` per level drops from `ratio * goal` to the goal (eq. 14.2.11).
pub(crate) fn levels_for(ratio: f64, order: usize, strict: bool) -> usize {
    let x = ratio.log2() / order as f64;
    let x = if strict { x.floor() + 1.0 } else { x.ceil() };
    #[allow(clippy::cast_possible_truncation, reason = "clamped to 0..=64 first")]
    let levels = x.clamp(0.0, 64.0) as usize;
    levels
}

/// The pieces of `curve` (on `[a, b]`) after `levels` rounds of midpoint subdivision, in
/// parameter order (`2^levels` pieces, exact dyadic intervals).
pub(crate) fn split_levels(
    curve: BezierCurve,
    a: f64,
    b: f64,
    levels: usize,
) -> Result<Vec<(f64, f64, BezierCurve)>> {
    let mut out = vec![(a, b, curve)];
    for _ in 0..levels {
        let mut next = Vec::with_capacity(2 * out.len());
        for (a, b, c) in out {
            let (l, r) = c.subdivide(0.5)?;
            let mid = 0.5 * (a + b);
            next.push((a, mid, l));
            next.push((mid, b, r));
        }
        out = next;
    }
    Ok(out)
}

/// Reduces `curve` (degree `n`, polynomial or rational) to a degree-`m` B-spline within a
/// certified tolerance, with `C^k` joins (seed 000 §14.2.2 and Algorithm 14.2.1 generalised
/// to any linear method; SPEC-reduce §2.2).
///
/// The breakpoints are placed by marching along the parameter (`march.rs`, beyond the
/// seed): from the end of the last piece, the longest piece whose certified bound
/// ([`crate::Report::error_bound`], Euclidean, also for rational curves, plus the rounding
/// of extracting the piece) is `<= 63/64 delta` is taken, its length predicted from the
/// bounds of the tries already made by the `h^(m+1)` law of short pieces (exact for
/// `m = n - 1`, Theorem 14.2.2: the prediction of eq. 14.2.11 without the restriction to
/// midpoints); a rational piece whose reduced weights are not all positive is shortened
/// too. Against the seed's midpoint subdivision (still in
/// [`reduce_to_tolerance_alg_14_2_1`]) this takes 17–26 % fewer pieces on random curves of
/// degree 5–30 reduced to cubics within 1e-4 (`benches/to_tolerance.rs`).
/// The pieces are merged by [`cagd_core::BSplineCurve::from_beziers`]
/// (C0) and [`cagd_core::BSplineCurve::remove_knot`] (`k` times per interior knot, so the
/// multiplicity is `m - k`); what the merge moved is bounded piece by piece (control-point
/// distance between each piece and the spline's Bézier segment, plus a rounding allowance)
/// and added to the piece's bound; the result must stay `<= delta`.
///
/// **Continuity.** Each piece interpolates the original's derivatives of orders `0..=k`
/// at both of its ends (in its own parameter, i.e. scaled by the interval length), so two
/// neighbours agree in the global parameter up to order `k` whatever their lengths.
///
/// Measured (tests: random degree-9 and degree-12 curves and a rational degree-7 one,
/// `delta` from `1e-2` to `1e-10`, `m = 5` and `3`, `k = 0, 1, 2`): the sampled error is
/// always below the certified bound and the bound below `delta`; the derivative jumps at
/// the knots are below `1e-8` relative (rounding). The sampled error is `0.6..1.0` of the
/// bound for the perturbation and constrained Chebyshev methods (their own bounds are
/// tight) and `0.03..0.8` for the L2 / generalised-inverse methods (convex-hull bound).
///
/// # Errors
/// [`Error::BadTolerance`] (`delta` not finite and `> 0`); as [`Method::check`]
/// ([`Error::BadDegreePair`] for `m >= n`, [`Error::TooManyConstraints`] for `r + p + 1 > m`);
/// [`Error::BadParameter`] (`continuity`) when `k >= m` or the method does not interpolate
/// order `k` at both ends; [`Error::NoConvergence`] (with the bound reached) when a
/// piece of the shortest allowed length (`2^-max_depth`, at least `2^-46`) still fails,
/// when more than [`MAX_PIECES`] pieces would be needed, or when the merged spline's bound
/// exceeds `delta`; [`Error::ConditionNotMet`] if the pieces do not join within
/// `delta / 128` (only when `delta` is near the rounding level; for `k = 1` a join that is
/// off shows in the merged bound instead), when a piece above the goal has a rounding
/// level `2 (n + 3) eps max ||P_i||` above half of it (no shorter piece can help), or when
/// the work exceeds [`MAX_TOLERANCE_WORK`]; [`Error::NonPositiveWeight`] when a reduced
/// weight of a rational piece is still not positive at the shortest allowed length (before
/// that such a piece is shortened).
///
/// ```
/// use cagd_core::BezierCurve;
/// use cagd_reduce::{Method, ToleranceOptions, reduce_to_tolerance};
/// let pts = vec![0.0, 0.0, 1.0, 3.0, 2.0, -1.0, 3.0, 4.0, 4.0, 0.0, 5.0, 2.0, 6.0, 1.0];
/// let curve = BezierCurve::new(pts, 2)?; // degree 6
/// let opts = ToleranceOptions {
///     measure: true,
///     ..ToleranceOptions::new(Method::L2 { r: 1, p: 1 }, 3, 1e-4, 1)
/// };
/// let red = reduce_to_tolerance(&curve, &opts)?;
/// let r = &red.report;
/// assert!(r.max_error.unwrap() <= r.error_bound && r.error_bound <= 1e-4);
/// assert_eq!(red.spline.degree(), 3);
/// // Interior knots have multiplicity m - k = 2.
/// assert_eq!(red.spline.knots().len(), 8 + 2 * (r.pieces - 1));
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn reduce_to_tolerance(
    curve: &BezierCurve,
    opts: &ToleranceOptions,
) -> Result<PiecewiseReduction> {
    check_tolerance(opts.tolerance)?;
    let (n, m, k) = (curve.degree(), opts.target, opts.continuity);
    check_continuity(opts.method, n, m, k)?;
    let goal = opts.tolerance * PIECE_SHARE;
    let (done, depth_used) = march(curve, opts, goal)?;
    finish(curve, opts, done, depth_used, Vec::new())
}

/// Merges the pieces, certifies and (on request) measures the spline, builds the report.
pub(crate) fn finish(
    curve: &BezierCurve,
    opts: &ToleranceOptions,
    pieces: Vec<ReducedPiece>,
    depth: usize,
    step_bounds: Vec<f64>,
) -> Result<PiecewiseReduction> {
    let pieces_bound = pieces.iter().map(|p| p.error_bound).fold(0.0, f64::max);
    let (spline, pieces, error_bound) = assemble(pieces, opts.continuity, opts.tolerance)?;
    if error_bound.is_nan() || error_bound > opts.tolerance {
        return Err(Error::NoConvergence {
            tolerance: opts.tolerance,
            achieved: error_bound,
        });
    }
    let max_error = if opts.measure {
        Some(measure(curve, &spline, &pieces)?)
    } else {
        None
    };
    Ok(PiecewiseReduction {
        report: PiecewiseReport {
            method: opts.method,
            degree_from: curve.degree(),
            degree_to: opts.target,
            continuity: opts.continuity,
            tolerance: opts.tolerance,
            pieces: pieces.len(),
            depth,
            pieces_bound,
            error_bound,
            max_error,
            step_bounds,
        },
        spline,
        pieces,
    })
}
