//! The result of a reduction to a tolerance: reduced Bézier pieces on sub-intervals of
//! `[0, 1]`, merged into one degree-`m` B-spline whose interior knots have multiplicity
//! `m - k` (the `C^k` joins are explicit), with a certified bound of the whole.

use cagd_core::{BSplineCurve, BezierCurve, Error, Result, max_distance_1d};

use super::MAX_TOLERANCE_WORK;
use crate::bezier::method::Method;
use crate::bezier::operator::max_norm;

/// One reduced piece: `curve(s)` approximates the original on `[start, end]`,
/// `s = (t - start) / (end - start)`.
#[derive(Debug, Clone, PartialEq)]
pub struct ReducedPiece {
    /// Start of the parameter interval (in the original curve's parameter).
    pub start: f64,
    /// End of the parameter interval (`> start`).
    pub end: f64,
    /// The reduced piece, degree `m`, on `[0, 1]` (rational if the original is).
    pub curve: BezierCurve,
    /// Certified bound of `max_s ||original(start + s (end - start)) - curve(s)||`
    /// (Euclidean), as [`crate::Report::error_bound`] of the piece's reduction.
    pub error_bound: f64,
}

/// What a reduction to a tolerance did.
#[derive(Debug, Clone, PartialEq)]
pub struct PiecewiseReport {
    /// The method used on every piece.
    pub method: Method,
    /// Degree `n` of the original curve.
    pub degree_from: usize,
    /// Degree `m` of the pieces and of the spline.
    pub degree_to: usize,
    /// Continuity order `k` of the joins (interior knot multiplicity `m - k`).
    pub continuity: usize,
    /// The tolerance `delta` that was asked for.
    pub tolerance: f64,
    /// Number of pieces.
    pub pieces: usize,
    /// The depth of the shortest piece: `ceil(-log2(length))`, the midpoint-subdivision
    /// level a dyadic split would need for it (`0`: the curve was not split; for
    /// [`crate::reduce_to_tolerance_alg_14_2_1`] the deepest level used).
    pub depth: usize,
    /// Largest certified bound of the pieces ([`ReducedPiece::error_bound`]).
    pub pieces_bound: f64,
    /// Certified bound of `max_t ||original(t) - spline(t)||` (Euclidean): `pieces_bound`
    /// plus what merging the pieces into the spline moved (`<= tolerance`).
    pub error_bound: f64,
    /// The measured `max_t ||original(t) - spline(t)||` (on request): [`max_distance_1d`]
    /// on every piece's interval (fewer samples per piece when the pieces are many).
    pub max_error: Option<f64>,
    /// For the stepwise [`crate::reduce_to_tolerance_alg_14_2_1`]: the largest bound of
    /// each one-degree step, `n -> n-1` first (their sum is the seed's certified total).
    /// Empty for [`crate::reduce_to_tolerance`].
    pub step_bounds: Vec<f64>,
}

/// The pieces, the spline made of them and the report.
#[derive(Debug, Clone, PartialEq)]
pub struct PiecewiseReduction {
    /// The reduced curve as one degree-`m` B-spline (NURBS if the original is rational)
    /// on `[0, 1]`, interior knots at the piece breaks with multiplicity `m - k`.
    pub spline: BSplineCurve,
    /// The reduced pieces, in parameter order, before merging.
    pub pieces: Vec<ReducedPiece>,
    /// What was done.
    pub report: PiecewiseReport,
}

/// Share of the tolerance given to the pieces; the rest (at least `1/64`) absorbs the
/// merge.
pub(crate) const PIECE_SHARE: f64 = 63.0 / 64.0;

/// Merges `pieces` into a `C^k` spline and certifies it: the returned bound is
/// `max_i (bound_i + mu_i)`, `mu_i` the distance between piece `i` and the spline's Bézier
/// segment on its interval (control-point distance, a convex-hull bound, plus an allowance
/// for the rounding of the extraction).
pub(crate) fn assemble(
    pieces: Vec<ReducedPiece>,
    k: usize,
    tolerance: f64,
) -> Result<(BSplineCurve, Vec<ReducedPiece>, f64)> {
    let curves: Vec<BezierCurve> = pieces.iter().map(|p| p.curve.clone()).collect();
    let mut breaks: Vec<f64> = pieces.iter().map(|p| p.start).collect();
    breaks.push(pieces.last().map_or(1.0, |p| p.end));
    // What the merge may move: the slack left by the pieces (at least delta / 64). Each
    // interior knot is removed `k` times with that budget (a C^k check, not a sum over the
    // knots as in `from_beziers`): what the merge really moved is measured below, piece by
    // piece, and added to the piece's bound.
    let pieces_bound = pieces.iter().map(|p| p.error_bound).fold(0.0, f64::max);
    let slack = (tolerance - pieces_bound).max((1.0 - PIECE_SHARE) * tolerance);
    let mut spline = if k == 1 && curves.len() > 1 {
        c1_spline(&curves, &breaks)?
    } else {
        BSplineCurve::from_beziers(&curves, &breaks, 0, slack)?
    };
    if k > 1 {
        for &b in &breaks[1..breaks.len() - 1] {
            let r = spline.remove_knot(b, k, slack)?;
            if r.removed != k {
                return Err(Error::ConditionNotMet {
                    eq: "001 §4.1",
                    why: "the reduced pieces do not join C^k within the tolerance (rounding \
                          of the joins above the tolerance)",
                });
            }
            spline = r.curve;
        }
    }
    let segments = spline.to_beziers()?;
    if segments.len() != pieces.len() {
        return Err(Error::LengthMismatch {
            what: "spline segments (one per piece)",
            got: segments.len(),
            expected: pieces.len(),
        });
    }
    let mut bound = 0.0f64;
    for (seg, piece) in segments.iter().zip(&pieces) {
        bound = bound.max(piece.error_bound + hull_distance(&piece.curve, &seg.curve));
    }
    Ok((spline, pieces, bound))
}

/// The degree-`m` spline with interior knots of multiplicity `m - 1` (C1) made of pieces
/// that join C1 (up to rounding), without knot removal. Each de Boor point is the blossom
/// of the spline at its `m` knots; with multiplicity `m - 1` those knots take at most two
/// distinct values `t_i, t_(i+1)`, so the de Boor point is a Bézier point of the piece on
/// `[t_i, t_(i+1)]`: piece `i` gives its points `1..=m-1` (the first piece also its point
/// `0`, the last also its point `m`), and the shared joint points, implied by C1, are
/// dropped. Rational pieces are taken in homogeneous space (point and weight together).
/// Goes beyond the seed (the same spline as the C0 merge of seed 001 §4.1 followed by one
/// knot removal per joint, when the joints are exactly C1); the caller certifies the result
/// against the pieces.
fn c1_spline(curves: &[BezierCurve], breaks: &[f64]) -> Result<BSplineCurve> {
    let (m, dim) = (curves[0].degree(), curves[0].dim());
    let last = curves.len() - 1;
    let rational = curves.iter().any(BezierCurve::is_rational);
    let count = (m + 1) + last * (m - 1);
    let mut points = Vec::with_capacity(count * dim);
    let mut weights = Vec::with_capacity(if rational { count } else { 0 });
    let mut knots = Vec::with_capacity(count + m + 1);
    knots.extend(std::iter::repeat_n(breaks[0], m + 1));
    for (i, c) in curves.iter().enumerate() {
        let lo = usize::from(i > 0);
        let hi = if i == last { m } else { m - 1 };
        points.extend_from_slice(&c.points()[lo * dim..(hi + 1) * dim]);
        if rational {
            match c.weights() {
                Some(w) => weights.extend_from_slice(&w[lo..=hi]),
                None => weights.extend(std::iter::repeat_n(1.0, hi + 1 - lo)),
            }
        }
        if i > 0 {
            knots.extend(std::iter::repeat_n(breaks[i], m - 1));
        }
    }
    knots.extend(std::iter::repeat_n(breaks[last + 1], m + 1));
    if rational {
        BSplineCurve::new_rational(m, knots, points, weights, dim)
    } else {
        BSplineCurve::new(m, knots, points, dim)
    }
}

/// A certified bound of `max_s ||a(s) - b(s)||` for two curves of the same degree and kind:
/// the largest control-point distance plus a rounding allowance; for rational curves the
/// centred form of [`cagd_core::centred_rational_bound`] about the centre `c` of `b`'s
/// points (`a - b = ((A_c - B_c) + (b - c)(W_b - W_a)) / W_a`, so the bound is
/// `(max ||dA_i - c dW_i|| + R max |dW_i|) / min w_a`, `R` the radius of `b`'s points
/// about `c`), which does not grow with the distance from the origin.
fn hull_distance(a: &BezierCurve, b: &BezierCurve) -> f64 {
    let m = a.points().len() / a.dim().max(1);
    let slack = |x: f64| 4.0 * (m as f64 + 2.0) * f64::EPSILON * x;
    let dist = |pa: &[f64], pb: &[f64], d: usize| {
        pa.chunks_exact(d)
            .zip(pb.chunks_exact(d))
            .map(|(x, y)| {
                x.iter()
                    .zip(y)
                    .map(|(u, v)| (u - v) * (u - v))
                    .sum::<f64>()
                    .sqrt()
            })
            .fold(0.0, f64::max)
            * (1.0 + 4.0 * f64::EPSILON)
    };
    let (Some(wa), Some(wb)) = (a.weights(), b.weights()) else {
        let (pa, pb, d) = (a.points(), b.points(), a.dim());
        return dist(pa, pb, d) + slack(max_norm(pa, d) + max_norm(pb, d));
    };
    let dim = a.dim();
    let frame = cagd_core::ModelFrame::new(b.points(), dim);
    let centred = |pts: &[f64], w: &[f64]| -> (Vec<f64>, Vec<f64>) {
        let mut ac = Vec::with_capacity(pts.len());
        for (p, wi) in pts.chunks_exact(dim).zip(w) {
            ac.extend(p.iter().zip(frame.centre()).map(|(x, c)| wi * (x - c)));
        }
        (ac, w.to_vec())
    };
    let ((aa, aw), (ba, bw)) = (centred(a.points(), wa), centred(b.points(), wb));
    let h_a = dist(&aa, &ba, dim) + slack(max_norm(&aa, dim) + max_norm(&ba, dim));
    let h_w = dist(&aw, &bw, 1) + slack(max_norm(&aw, 1) + max_norm(&bw, 1));
    let wmin = wa.iter().copied().fold(f64::INFINITY, f64::min);
    // The centring rounds each model point by ~2 ulp of |x| + |c|: a hull move of `a`, `b`.
    let size = a
        .points()
        .iter()
        .chain(b.points())
        .chain(frame.centre())
        .fold(0.0f64, |s, x| s.max(x.abs()));
    cagd_core::centred_rational_bound(h_a, h_w, frame.radius(), wmin, wmin)
        + 8.0 * (dim as f64).sqrt() * f64::EPSILON * size
}

/// Sample intervals per piece of [`measure`]: `8 (n + m) + 64`, fewer when the pieces are
/// many, so that all of them together hold at most about [`MAX_TOLERANCE_WORK`] units of
/// `(n + 1)^2 + (m + 1)^2 + 64` (an evaluation of both curves), but never below
/// [`MIN_SAMPLES`] (ADDED, bounded work: the C ABI fuzz measured 9 232 pieces of a
/// degree-63 curve at 576 samples each for 13 s).
pub(crate) fn samples_per_piece(n: usize, m: usize, pieces: usize) -> usize {
    let full = 8 * (n + m) + 64;
    let unit = (n + 1) * (n + 1) + (m + 1) * (m + 1) + 64;
    (MAX_TOLERANCE_WORK / unit / pieces.max(1)).clamp(MIN_SAMPLES, full)
}

/// The fewest sample intervals of a piece in [`measure`] (the pieces are then short: their
/// error curves are nearly of the reduced degree, and Brent refines the sampled maxima).
pub(crate) const MIN_SAMPLES: usize = 8;

/// `max_t ||original(t) - spline(t)||` measured by [`max_distance_1d`] on every piece's
/// interval ([`samples_per_piece`] sample intervals each, Brent refinement of local
/// maxima).
///
/// # Errors
/// [`Error::NonFinite`] if an evaluation fails (not expected for valid inputs).
pub(crate) fn measure(
    original: &BezierCurve,
    spline: &BSplineCurve,
    pieces: &[ReducedPiece],
) -> Result<f64> {
    let samples = samples_per_piece(original.degree(), spline.degree(), pieces.len());
    let mut worst = 0.0f64;
    for p in pieces {
        let d = max_distance_1d(
            |t, o| match spline.eval(t) {
                Ok(v) => o.copy_from_slice(&v),
                Err(_) => o.fill(f64::NAN),
            },
            |t, o| original.eval_into(t, o),
            original.dim(),
            p.start,
            p.end,
            samples,
        )?;
        worst = worst.max(d);
    }
    Ok(worst)
}
