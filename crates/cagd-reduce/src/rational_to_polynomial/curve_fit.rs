//! The polynomial fit of a rational curve (ours, on the machinery of
//! [`crate::reduce_bspline`]'s global fit): the degree-`m` spline on a given clamped knot
//! vector nearest to `C = A / W` in the discrete parameter-L2 norm of `g` Gauss–Legendre
//! nodes per span (`g = p + m + 1`; `C` is not a polynomial, so the rule is not exact, but
//! it is a weighted collocation fit with more nodes than local unknowns), with the end
//! points kept, solved by banded Givens QR (no normal equations); then the certified
//! per-span bounds of [`super::bound::patch_bound`] and the adaptive refinement.

use cagd_core::{BSplineCurve, Error, Result, basis_functions, gauss_legendre};

use super::bound::patch_bound;
use super::pieces::{RationalPieces, restrict_bezier};
use super::refine::refine_with;
use crate::{BandedLsq, SpanBound};

/// Most refine-and-refit rounds.
const MAX_ROUNDS: usize = 60;
/// New spans aim at this share of the budget (the `h^(m+1)` prediction is not exact, and
/// the fit is global: refining one span moves its neighbours' error a little).
const SPLIT_TARGET: f64 = 0.95;
/// Rounds that re-place the knots by equidistribution before local splitting takes over.
const GLOBAL_ROUNDS: usize = 3;
/// Most spans the refinement may create.
const MAX_SPANS: usize = 1 << 20;
/// Most spans fitted and bounded over all rounds of one refinement, each counted
/// [`span_cost`] times: `2^19` units, about a second in a release build (ADDED; bounded
/// work, issue 18: the fuzz harness found curves whose refinement ran for 60 rounds near
/// `2^20` spans, and degree-60 curves whose spans cost 50 times a cubic's).
const MAX_SPAN_WORK: usize = 1 << 19;

/// The cost of one fitted and bounded span of a degree-`p` input of dimension `d` fitted
/// by degree `m`: `max(1, (p + m + 1)^2 / 16)` (the product `A - W S` has degree `p + m`,
/// and its ratio bound refines a full tree of de Casteljau subdivisions when the error is
/// near the rounding level: measured 10 us per span at degrees 6 -> 2 in 3D, C ABI fuzz run
/// seed 104, issue 18, where a span counted once let a refinement creep for 5.2 s) times
/// `ceil((d + 1) / 4)`.
fn span_cost(p: usize, m: usize, d: usize) -> usize {
    ((p + m + 1) * (p + m + 1) / 16)
        .max(1)
        .saturating_mul((d + 1).div_ceil(4))
}

/// Gauss nodes per span for degrees `p -> m`.
pub(crate) fn nodes_per_span(p: usize, m: usize) -> usize {
    (p + m + 1).clamp(2, cagd_core::MAX_GAUSS_NODES)
}

/// The control points the fit keeps fixed: `(index, value)` for the first and last point
/// and, at every interior knot of multiplicity `m` (a `C^0` joint, where the input is only
/// `C^0`), the point through which the spline passes there, set to `C(t)`. Joints are
/// interpolated: the pieces between them are fitted independently of each other (a
/// corner stays exact, and one piece's error does not leak into its neighbour).
fn fixed_points(src: &RationalPieces, m: usize, knots: &[f64]) -> Vec<(usize, Vec<f64>)> {
    let (p, d) = (src.degree, src.dim);
    let n = knots.len() - m - 1;
    let (mut work, mut hom, mut value) =
        (vec![0.0; (p + 1) * (d + 1)], vec![0.0; d + 1], vec![0.0; d]);
    let mut at = |k: usize, t: f64| {
        src.eval(k, t, &mut work, &mut hom, &mut value);
        value.clone()
    };
    let mut out = vec![(0, at(0, src.breaks[0]))];
    let mut r = m + 1;
    while r < n {
        let t = knots[r];
        let s = knots[r..].iter().take_while(|x| **x == t).count();
        if s >= m {
            let k = src.breaks[1..]
                .partition_point(|x| *x < t)
                .min(src.len() - 1);
            out.push((r - 1, at(k, t)));
        }
        r += s;
    }
    out.push((n - 1, at(src.len() - 1, src.breaks[src.len()])));
    out
}

/// The fitted control points (`knots.len() - m - 1` points of `src.dim` coordinates), the
/// points of [`fixed_points`] kept.
///
/// # Errors
/// [`Error::Singular`] if the system is not determined (cannot happen on a valid knot
/// vector: `g >= m + 1` nodes per span).
pub(crate) fn fit(src: &RationalPieces, m: usize, knots: &[f64]) -> Result<Vec<f64>> {
    let (p, d) = (src.degree, src.dim);
    let n = knots.len() - m - 1;
    let mut out = vec![0.0; n * d];
    let fixed = fixed_points(src, m, knots);
    let mut is_fixed = vec![false; n];
    for (i, v) in &fixed {
        out[i * d..(i + 1) * d].copy_from_slice(v);
        is_fixed[*i] = true;
    }
    // The unknowns: the free points, numbered in order.
    let mut index = vec![usize::MAX; n];
    let mut free = 0;
    for i in 0..n {
        if !is_fixed[i] {
            index[i] = free;
            free += 1;
        }
    }
    if free == 0 {
        return Ok(out);
    }
    let (nodes, weights) = gauss_legendre(nodes_per_span(p, m))?;
    let mut lsq = BandedLsq::new(free, m + 1, d);
    let (mut basis, mut scratch) = (vec![0.0; m + 1], vec![0.0; 2 * m + 2]);
    let (mut bern, mut hom) = (vec![0.0; p + 1], vec![0.0; d + 1]);
    let mut value = vec![0.0; d];
    let mut row = Vec::with_capacity(m + 1);
    let mut rhs = vec![0.0; d];
    for s in m..n {
        let (a, b) = (knots[s], knots[s + 1]);
        if a >= b {
            continue;
        }
        for (x, w) in nodes.iter().zip(&weights) {
            let t = a + (b - a) * x;
            let sw = (w * (b - a)).sqrt();
            basis_functions(knots, s, m, t, &mut basis, &mut scratch);
            src.eval_fast(src.piece_at(t), t, &mut bern, &mut hom, &mut value);
            row.clear();
            let mut first = None;
            for (j, bj) in basis.iter().enumerate() {
                let col = s - m + j;
                if is_fixed[col] {
                    for (v, e) in value.iter_mut().zip(&out[col * d..(col + 1) * d]) {
                        *v -= bj * e;
                    }
                } else {
                    first.get_or_insert(index[col]);
                    row.push(sw * bj);
                }
            }
            let Some(first) = first else { continue };
            for (r, v) in rhs.iter_mut().zip(&value) {
                *r = sw * v;
            }
            lsq.add_row(first, &row, &rhs);
        }
    }
    let x = lsq.solve()?;
    for i in 0..n {
        if !is_fixed[i] {
            out[i * d..(i + 1) * d].copy_from_slice(&x[index[i] * d..(index[i] + 1) * d]);
        }
    }
    Ok(out)
}

/// The certified bound of `max ||C - S||` on every span of the degree-`m` spline
/// `(knots, points)`: the largest over the input pieces the span meets, each bounded on
/// the overlap (both Bézier forms restricted to it).
pub(crate) fn span_bounds(
    src: &RationalPieces,
    m: usize,
    knots: &[f64],
    points: &[f64],
) -> Result<Vec<SpanBound>> {
    let fitted = BSplineCurve::new(m, knots.to_vec(), points.to_vec(), src.dim)?;
    let mut out = Vec::new();
    for piece in fitted.to_beziers()? {
        let (a, b) = (piece.start, piece.end);
        let (mut bound, mut floor): (f64, f64) = (0.0, 0.0);
        let mut k = src.piece_at(a);
        loop {
            let (lo, hi) = (a.max(src.breaks[k]), b.min(src.breaks[k + 1]));
            if hi > lo {
                let hom = src.restrict(k, lo, hi);
                let sub = if (lo, hi) == (a, b) {
                    piece.curve.points().to_vec()
                } else {
                    restrict_bezier(
                        piece.curve.points(),
                        src.dim,
                        (lo - a) / (b - a),
                        (hi - a) / (b - a),
                    )
                };
                let (x, f) = patch_bound(&hom, (src.degree, 0), &sub, (m, 0), src.dim);
                bound = bound.max(x);
                floor = floor.max(f);
            }
            if src.breaks[k + 1] >= b || k + 1 >= src.len() {
                break;
            }
            k += 1;
        }
        out.push(SpanBound { a, b, bound, floor });
    }
    Ok(out)
}

/// Fits and refines until every span's bound is within `budget`: the final knots, points
/// and span bounds (the loop of [`crate::reduce_bspline`]'s global fit, with the
/// equidistributing refinement of [`refine_with`]). `start` is the knot vector on the input's
/// breaks; the simple knots the refinement adds are kept apart and merged in.
///
/// # Errors
/// [`Error::ConditionNotMet`] when the budget is below the rounding level or needs too
/// many spans.
pub(crate) fn fit_to_budget(
    src: &RationalPieces,
    m: usize,
    start: Vec<f64>,
    budget: f64,
) -> Result<(Vec<f64>, Vec<f64>, Vec<SpanBound>)> {
    let mut rounds = 0;
    let mut work = 0usize;
    let mut knots = start.clone();
    // The refinement places knots anew between the distinct knots of `start`.
    let mut groups = start.clone();
    groups.dedup();
    loop {
        let points = fit(src, m, &knots)?;
        let bounds = span_bounds(src, m, &knots, &points)?;
        if bounds.iter().all(|x| x.bound <= budget) {
            return Ok((knots, points, bounds));
        }
        rounds += 1;
        let unit = span_cost(src.degree, m, src.dim);
        work = work.saturating_add(bounds.len().saturating_mul(unit));
        // Equidistribution in the first rounds, local splits after (see `refine_with`).
        let added = refine_with(
            &bounds,
            &groups,
            (budget, SPLIT_TARGET * budget),
            m,
            rounds > GLOBAL_ROUNDS,
        )?;
        if rounds > MAX_ROUNDS || src.len() + added.len() > MAX_SPANS {
            return Err(Error::ConditionNotMet {
                eq: "tolerance",
                why: "the refinement needs too many spans",
            });
        }
        if work.saturating_add((src.len() + added.len()).saturating_mul(unit)) > MAX_SPAN_WORK {
            return Err(Error::ConditionNotMet {
                eq: "tolerance",
                why: "the refinement needs too much work (more than 2^19 spans fitted over its rounds, a span counted (p + m + 1)^2 / 16 times, more in more than 3D)",
            });
        }
        knots.clone_from(&start);
        knots.extend(added);
        knots.sort_by(f64::total_cmp);
    }
}
