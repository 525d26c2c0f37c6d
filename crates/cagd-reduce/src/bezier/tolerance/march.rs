//! Breakpoints of a reduction to a tolerance placed by marching along the parameter: each
//! piece is made as long as its certified bound allows, its length predicted from the
//! bounds already computed. Goes beyond the seed, whose Algorithm 14.2.1 and eq. 14.2.11
//! split at midpoints only (kept in [`super::reduce_to_tolerance_alg_14_2_1`]); with
//! midpoints a piece is up to half as long as it could be, so a dyadic split needs up to
//! twice the pieces (about 1.4× on average) of the same tolerance.
//!
//! **Prediction.** The bound of a degree-`n` piece of length `h` reduced to degree `m`
//! behaves like `C h^(m+1)` for short pieces (Theorem 14.2.2 for `m = n - 1`: the `n`-th
//! forward difference scales by exactly `h^n`; in general the first neglected term of the
//! piece's expansion). From a bound `e` at length `h` the length that meets the goal `g` is
//! predicted as `h (g / e)^(1/(m+1))`; a piece is accepted only on its own certified
//! bound, the prediction only chooses which lengths are tried.

use cagd_core::{BezierCurve, Error, Result, max_point_norm};

use super::{MAX_PIECES, MAX_TOLERANCE_WORK, ToleranceOptions, rounding_floor};
use crate::bezier::reduce::{ReduceOptions, reduce_with};
use crate::bezier::tolerance::ReducedPiece;

/// Largest number of longer tries after a success, per piece (each at least
/// [`WORTH_LONGER`] times the last success; in practice 0–2 are made). Failures shrink the
/// length by at least a quarter each, down to the shortest allowed piece, so they are
/// bounded by the depth limit.
const MAX_LONGER: usize = 4;

/// The shortest piece is never below this length (about `2^-46`): below it the endpoints
/// of a piece near 1 would not be distinct in `f64`.
const MIN_LENGTH: f64 = 64.0 * f64::EPSILON;

/// Safety factor on a predicted length (a little shorter, so the try usually succeeds).
const SAFETY: f64 = 0.97;

/// A longer try after a success is made only if the prediction gains at least this factor.
const WORTH_LONGER: f64 = 1.2;

/// The part of the curve not yet covered, on `[a, 1]` reparametrised to `[0, 1]`, and a
/// bound on how far the splits that made it moved it from the exact restriction of the
/// original curve (Euclidean, model space).
struct Rest {
    curve: BezierCurve,
    moved: f64,
}

/// One try: the piece on `[a, b]` split off `rest`, its reduction (`None` when the reduced
/// weights of a rational piece are not all positive), its certified bound (`+inf` for
/// `None`; the moves of the splits included) and what is left on `[b, 1]` (`None` when
/// `b = 1`).
struct Try {
    reduced: Option<BezierCurve>,
    bound: f64,
    /// The piece's rounding level ([`rounding_floor`]).
    floor: f64,
    right: Option<Rest>,
}

fn try_piece(
    rest: &Rest,
    ropts: &ReduceOptions,
    (a, b): (f64, f64),
    split_move: f64,
    last_chance: bool,
) -> Result<Try> {
    let (piece, moved, right) = if b == 1.0 {
        (rest.curve.clone(), rest.moved, None)
    } else {
        // The split parameter in the rest's own parameter; the piece is taken to end at
        // `b` (the parameter drift of rounding `s` is in `split_move`).
        let s = (b - a) / (1.0 - a);
        let (l, r) = rest.curve.subdivide(s)?;
        let moved = rest.moved + split_move;
        (l, moved, Some(Rest { curve: r, moved }))
    };
    let floor = rounding_floor(&piece);
    match reduce_with(&piece, ropts) {
        Ok(red) => Ok(Try {
            bound: red.report.error_bound.unwrap_or(f64::INFINITY) + moved,
            reduced: Some(red.curve),
            floor,
            right,
        }),
        Err(err @ Error::NonPositiveWeight { .. }) if last_chance => Err(err),
        Err(Error::NonPositiveWeight { .. }) => Ok(Try {
            reduced: None,
            bound: f64::INFINITY,
            floor,
            right,
        }),
        Err(err) => Err(err),
    }
}

/// Bound on how far one de Casteljau split of a piece of `curve` moves it (as a function
/// of the global parameter) from the exact restriction of `curve`.
///
/// - Rounding of the levels: each is a convex combination, so every computed point is off
///   by at most `gamma_(n+2) max ||P||` per coordinate (`sqrt(dim)` of that in the
///   Euclidean norm); the points of every piece are convex combinations of the original's,
///   so the original's largest norm bounds them all.
/// - Parameter drift: the split parameter `s = (b - a) / (1 - a)` is rounded, so the piece
///   really ends at `b (1 + 3 eps)`; the curve moves by at most `||C'|| 3 eps <= 2 n max ||P||
///   3 eps` under that shift (`||C'|| <= n max ||P_i - P_(i-1)||`).
///
/// For a rational curve the homogeneous points are split, and the model-space move is at
/// most `(||dX|| + ||x|| |dw|) / w` over the smallest weight, which a piece's weights
/// (convex combinations) cannot go below.
fn split_allowance(curve: &BezierCurve) -> f64 {
    let n = curve.degree() as f64;
    let dim = curve.dim();
    let per_point = (4.0 * (n + 2.0) + 6.0 * n + 6.0) * f64::EPSILON;
    let root = (dim as f64 + 1.0).sqrt();
    match curve.weights() {
        None => per_point * root * max_point_norm(curve.points(), dim),
        Some(w) => {
            let hom = curve.homogeneous_points();
            let wmin = w.iter().copied().fold(f64::INFINITY, f64::min);
            let size = max_point_norm(&hom, dim + 1);
            let model = max_point_norm(curve.points(), dim);
            per_point * root * size * (1.0 + model) / wmin
        }
    }
}

/// The length predicted to meet `goal` from a bound `e` at length `h`, by the `h^(m+1)`
/// law, times `SAFETY`, kept within `[h / 16, 4 h]` (and `h / 2` when `e` is not finite).
fn predict(h: f64, e: f64, goal: f64, order: f64) -> f64 {
    if !e.is_finite() || e <= 0.0 {
        return if e <= 0.0 { 4.0 * h } else { 0.5 * h };
    }
    (h * SAFETY * (goal / e).powf(1.0 / order)).clamp(h / 16.0, 4.0 * h)
}

/// The pieces of `curve` on a partition of `[0, 1]` chosen by marching, each with a
/// certified bound `<= goal`, and the depth of the shortest one
/// (`ceil(-log2(length))`, the midpoint level a dyadic split would need for it).
///
/// # Errors
/// [`Error::NoConvergence`] when a piece shorter than `2^-max_depth` still fails or more
/// than [`MAX_PIECES`] pieces would be needed; [`Error::NonPositiveWeight`] when a rational
/// piece of that shortest length still has a non-positive reduced weight; errors of
/// [`reduce_with`].
pub(crate) fn march(
    curve: &BezierCurve,
    opts: &ToleranceOptions,
    goal: f64,
) -> Result<(Vec<ReducedPiece>, usize)> {
    let ropts = ReduceOptions::new(opts.method, opts.target);
    let order = (opts.target + 1) as f64;
    let shortest = (-(opts.max_depth.min(1000) as f64)).exp2().max(MIN_LENGTH);
    let split_move = split_allowance(curve);
    let mut rest = Rest {
        curve: curve.clone(),
        moved: 0.0,
    };
    let mut done: Vec<ReducedPiece> = Vec::new();
    let mut a = 0.0f64;
    let mut h = 1.0f64;
    let mut min_len = 1.0f64;
    let unit = ((curve.degree() + 1).pow(2) + 64) * (curve.dim() + 1);
    let mut work = 0usize;
    while a < 1.0 {
        if done.len() >= MAX_PIECES {
            return Err(Error::NoConvergence {
                tolerance: opts.tolerance,
                achieved: f64::INFINITY,
            });
        }
        // `best`: the longest success so far (end, piece, bound); `fail`: the shortest
        // failing length.
        let mut best: Option<(f64, BezierCurve, f64, Option<Rest>)> = None;
        let mut fail = f64::INFINITY;
        let mut longer_tries = 0;
        let (b, q, e, right) = loop {
            // A piece ending within a tenth of its length of 1 is stretched to 1: the
            // remainder would be a sliver.
            let b = if a + 1.1 * h >= 1.0 { 1.0 } else { a + h };
            let len = b - a;
            let last_chance = len <= shortest;
            work = work.saturating_add(unit);
            if work > MAX_TOLERANCE_WORK {
                return Err(Error::ConditionNotMet {
                    eq: "tolerance",
                    why: "the subdivision needs too much work (more than 2^27 pieces tried \
                          times ((n + 1)^2 + 64) (d + 1))",
                });
            }
            let t = try_piece(&rest, &ropts, (a, b), split_move, last_chance)?;
            let (e, floor, reduced) = (t.bound, t.floor, t.reduced.is_some());
            match t.reduced.filter(|_| e <= goal) {
                Some(q) => {
                    let longer = predict(len, e, goal, order).min(0.5 * (len + fail));
                    if b == 1.0 || longer < WORTH_LONGER * len || longer_tries == MAX_LONGER {
                        break (b, q, e, t.right);
                    }
                    best = Some((b, q, e, t.right));
                    longer_tries += 1;
                    h = longer;
                }
                None => {
                    fail = fail.min(len);
                    if let Some(found) = best.take() {
                        break found;
                    }
                    // No shorter piece gets below the rounding level of the points.
                    if reduced && floor > 0.5 * goal {
                        return Err(Error::ConditionNotMet {
                            eq: "tolerance",
                            why: "the tolerance is below the rounding level of the curve",
                        });
                    }
                    if last_chance {
                        return Err(Error::NoConvergence {
                            tolerance: opts.tolerance,
                            achieved: e,
                        });
                    }
                    h = predict(len, e, goal, order).min(0.75 * len).max(shortest);
                }
            }
        };
        let len = b - a;
        min_len = min_len.min(len);
        done.push(ReducedPiece {
            start: a,
            end: b,
            curve: q,
            error_bound: e,
        });
        // The next piece starts from the length this one reached (or what it predicts).
        h = predict(len, e, goal, order).min(fail).max(len.min(fail));
        a = b;
        if let Some(r) = right {
            rest = r;
            // Splitting the rest again and again adds up moves; once they reach 1/64 of
            // the goal the rest is taken afresh from the original curve (two splits).
            if rest.moved > goal / 64.0 {
                rest = Rest {
                    curve: curve.segment(a, 1.0)?,
                    moved: 2.0 * split_move,
                };
            }
        }
    }
    #[allow(
        clippy::cast_possible_truncation,
        reason = "0 <= depth <= max_depth + 1"
    )]
    let depth = (-min_len.log2()).ceil().max(0.0) as usize;
    Ok((done, depth))
}
