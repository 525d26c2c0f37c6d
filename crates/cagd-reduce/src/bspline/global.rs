//! The global-fit strategy of [`crate::reduce_bspline`] ([`BSplineStrategy::GlobalFit`]):
//! the degree-`m` spline space with the input's knots at the multiplicities that keep its
//! continuity, the L2-best fit in it ([`super::fit`]), adaptive refinement of the
//! spans whose certified bound exceeds their share of the tolerance (on a graded mesh,
//! [`super::grading`]), then knot removal
//! within the rest, tracked per span ([`super::knots`]).
//!
//! Why a global fit: reducing segment by segment can only join segments with Hermite data
//! matched on both sides, which needs `2k + 1 <= m` (C1 at best for cubics), while the
//! spline space itself carries `C^(m-1)` joins; and a fit over the whole space spreads the
//! error instead of pinning each joint to the input, so fewer spans are needed.

use cagd_core::{BSplineCurve, Error, Result, knot_multiplicity};

use super::fit::{
    Density, Source, SpanBound, SpanData, fit_restricted, hull_span_bound, span_bounds_restricted,
};
use super::grading::{GRADE, grading_breaks};
use super::knots::order_at;
use super::knots::{LocalBounds, Raw, Sharpen};
use super::measure::{Known, SpanCaps, spline_max_deviation_known};
use super::options::{BSplineOptions, BSplineReduction, BSplineReport, BSplineStrategy};

/// Share of the tolerance the fit must meet on every span; the rest is for knot removal.
/// The share matters only for spans near the budget (refined ones); measured on the
/// benchmark spiral (1 000 degree-7 spans -> cubic at 1e-6): 0.75 gives 3 946 spans,
/// 0.9 gives 3 815, 0.97 gives 3 761 but 1.3x the time. Input with more knots than it needs
/// fits far below the budget, so knot removal keeps most of the tolerance there anyway.
const FIT_SHARE: f64 = 0.9;

/// Most refine-and-refit rounds (each at least halves the offending spans).
const MAX_ROUNDS: usize = 60;

/// From the second split on, the split count aims each new span at this share of the
/// budget, not at the budget itself. The fit is global: refining a span moves the fit on
/// its neighbours, and a span that lands right at the budget (the `h^(m+1)` prediction is
/// sharp for smooth input, so most do) is pushed over by a refined neighbour, whose
/// refinement then pushes the next one — a creep of a few spans per round that once
/// exhausted [`MAX_ROUNDS`] (a parabola to degree 1 at 6.3e-6: ~5% over, 4 spans further
/// each round). Measured: the pushes were at most 6%. Not for the first split: aiming it
/// lower costs spans everywhere (the spiral benchmark: 3 896 instead of 3 815).
const SPLIT_TARGET: f64 = 0.9;

/// From this round on, spans above [`SPLIT_TARGET`] of the budget are split too, so a creep
/// the margin did not prevent ends within a round or two (every span near the budget is
/// refined at once) instead of running out of rounds.
const CREEP_ROUNDS: usize = 6;

/// Most spans the refinement may create (a safety net; a span whose tolerance is below its
/// rounding floor stops the refinement at once).
pub(crate) const MAX_FIT_SPANS: usize = 1 << 20;

/// Most knots the prediction may add ([`predicted_knots`]; also at most half of
/// [`MAX_FIT_WORK`] in its first round); more means the tolerance is far below what the
/// input's pieces carry, and the refinement starts from the input's knots (and its work
/// limits answer).
const MAX_PREDICTED_KNOTS: usize = 1 << 16;

/// Most work of one refinement, counted per span as its point coordinates plus
/// [`SPAN_OVERHEAD`], times [`degree_cost`], summed over its rounds (each round fits and
/// bounds every span): `2^23`, about a second in a release build. A bundle (the rows of a
/// surface fitted together) has many coordinates per point, so a surface that would need
/// `2^20` spans in one direction is refused by this cap, not by [`MAX_FIT_SPANS`] after
/// minutes (ADDED; bounded work, issue 18).
pub(crate) const MAX_FIT_WORK: usize = 1 << 23;

/// The cost of a span beside its coordinates (basis, bound, bookkeeping), in coordinates:
/// measured, a degree-5 curve in 3D took 1.1 us per span coordinate (3.7 s for 61 rounds
/// near 19 000 spans, C ABI fuzz run, issue 18), about 25 times a bundle's per coordinate.
const SPAN_OVERHEAD: usize = 24;

/// The cost of one span coordinate of a source of degree `p` in units of [`MAX_FIT_WORK`]:
/// `max(1, (p + 1)^2 / 64)`. Fitting a span evaluates the source at `p + 1` Gauss nodes
/// (`O(p)` each) and bounding it restricts a piece by two de Casteljau subdivisions
/// (`O(p^2)`), so a span costs `O(p^2)` per coordinate; the unit is a degree-7 span. Without
/// the factor a degree-60 spline to lines within `4e-7` fitted 12 000 spans per round for
/// a minute (C ABI fuzz run, issue 18).
pub(crate) fn degree_cost(p: usize) -> usize {
    ((p + 1) * (p + 1) / 64).max(1)
}

/// The work of one span of `src` in units of [`MAX_FIT_WORK`]: its coordinates plus
/// [`SPAN_OVERHEAD`] per curve of the bundle, times [`degree_cost`]. A bundle's span bound
/// is a refined hull bound per curve (two, centred, for a rational curve): measured, a
/// NURBS surface's bundle of 1 807 rational columns took 13 s for 1 071 spans and a
/// polynomial bundle of 4 columns 5.5 s for 47 rounds of 6 400 spans when a span counted
/// its coordinates plus 24 (C ABI fuzz run seed 104, issue 18). A single curve counts as
/// before.
pub(crate) fn span_unit(src: &Source) -> usize {
    let curves = src.pdim / src.block.max(1);
    src.pdim
        .saturating_add(SPAN_OVERHEAD.saturating_mul(curves.max(1)))
        .saturating_mul(degree_cost(src.degree))
}

/// The error for a tolerance the refinement cannot reach.
fn unreachable(why: &'static str) -> Error {
    Error::ConditionNotMet {
        eq: "tolerance",
        why,
    }
}

/// The working (homogeneous, for NURBS) polynomial spline of `curve`.
pub(crate) fn working(curve: &BSplineCurve) -> Result<BSplineCurve> {
    if curve.is_rational() {
        BSplineCurve::new(
            curve.degree(),
            curve.knots().to_vec(),
            curve.homogeneous_points(),
            curve.dim() + 1,
        )
    } else {
        Ok(curve.clone())
    }
}

/// The clamped degree-`m` knot vector on the breaks of `src`: the domain ends `m + 1` times,
/// each interior break `t` with multiplicity `m - min(k, p - s_t, m - 1)`.
pub(crate) fn initial_knots(
    input_knots: &[f64],
    p: usize,
    src: &Source,
    m: usize,
    k: usize,
) -> Result<Vec<f64>> {
    let b = &src.breaks;
    let mut knots = vec![b[0]; m + 1];
    for &t in &b[1..b.len() - 1] {
        let keep = order_at(input_knots, p, k, t)?.min(m - 1);
        knots.extend(std::iter::repeat_n(t, m - keep));
    }
    knots.extend(std::iter::repeat_n(b[b.len() - 1], m + 1));
    Ok(knots)
}

/// The first knot vector of the global fit of `src` (the working form of a degree-`p`
/// input with knots `input_knots`) to degree `m` with continuity `k` within `budget`:
/// knots placed where the error model wants them ([`Density`], `fit/predict.rs`: one round
/// instead of four on the a2 row's curves, issue 17), in one of two ways:
/// - on the input's breaks ([`initial_knots`]) plus, per piece, the predicted knots
///   inside it ([`Density::per_piece`]);
/// - or only the breaks where the fit must be less smooth than `C^(m-1)` (multiplicity
///   above one) plus knots predicted across the pieces between them
///   ([`Density::across`]): the fit's spans then straddle the other breaks (its rows and
///   bounds are per cell, `fit/spans.rs`), and where the input has many short pieces it
///   needs fewer spans than one knot per break and a rounding up per piece (ADDED, issue
///   17's real-CAD-file row: NURBS at 1e-3 had 11 % more spans than OCCT, whose knots
///   ignore the input's).
///
/// The second when the model predicts fewer spans for it. Without a model (see
/// [`Density::new`]) or past the prediction's limit, the input's breaks alone.
fn first_knots(
    input_knots: &[f64],
    src: &Source,
    m: usize,
    k: usize,
    budget: f64,
) -> Result<Vec<f64>> {
    let p = src.degree;
    let limit = MAX_PREDICTED_KNOTS.min(MAX_FIT_WORK / 2 / span_unit(src).max(1));
    let mut knots = initial_knots(input_knots, p, src, m, k)?;
    let Some(density) = Density::new(src, m, budget) else {
        return Ok(knots);
    };
    let b = &src.breaks;
    // The interior breaks that stay knots: multiple knots of the fit (continuity below
    // C^(m-1)), and breaks where the input is less than C^m: there its m-th derivative
    // jumps, an error source the model's density (of the (m+1)-th) does not see (a
    // degree-elevated degree-m spline has no density at all, and its breaks are its knots).
    let mut kept = Vec::new();
    for (i, &t) in b.iter().enumerate().take(b.len() - 1).skip(1) {
        let smooth = p.saturating_sub(knot_multiplicity(input_knots, t));
        if order_at(input_knots, p, k, t)?.min(m - 1) < m - 1 || smooth < m {
            kept.push(i);
        }
    }
    let (per_piece, across) = density.span_counts(&kept);
    if across < per_piece {
        if let Some(inner) = density.across(src, &kept, limit) {
            // The domain's ends and the kept breaks, at their multiplicities.
            let stay: Vec<f64> = kept.iter().map(|&i| b[i]).collect();
            let (lo, hi) = (b[0], b[b.len() - 1]);
            knots.retain(|t| {
                *t == lo || *t == hi || stay.binary_search_by(|x| x.total_cmp(t)).is_ok()
            });
            knots.extend(inner);
            knots.sort_by(f64::total_cmp);
            return Ok(knots);
        }
    }
    knots.extend(density.per_piece(src, limit));
    knots.sort_by(f64::total_cmp);
    Ok(knots)
}

/// The simple knots that split every span whose bound is above `threshold` into
/// `ceil((bound / target)^(1/(m+1)))` equal parts (2..=16; the error of a smooth piece
/// scales like `h^(m+1)`).
///
/// # Errors
/// [`Error::ConditionNotMet`] when a span's rounding floor is above half the budget or the
/// span is too short to split.
fn splits(
    bounds: &[SpanBound],
    budget: f64,
    (threshold, target): (f64, f64),
    m: usize,
) -> Result<Vec<f64>> {
    let mut out = Vec::new();
    for x in bounds.iter().filter(|x| x.bound > threshold) {
        if x.floor > 0.5 * budget {
            return Err(unreachable(
                "the tolerance is below the rounding level of the curve",
            ));
        }
        let ratio = (x.bound / target).powf(1.0 / (m as f64 + 1.0));
        let parts = (2..16).find(|&j| j as f64 >= ratio).unwrap_or(16);
        let h = (x.b - x.a) / parts as f64;
        if !(x.a + h > x.a && x.a + h < x.b) {
            return Err(unreachable(
                "a span cannot be split further (rounding level)",
            ));
        }
        out.extend((1..parts).map(|j| x.a + h * j as f64));
    }
    Ok(out)
}

/// Fits `src` on the degree-`m` knot vector `knots`, refining it (simple knots inside the
/// offending spans, [`splits`], then inside their much longer neighbours,
/// [`grading_breaks`]) and fitting again until every span's certified bound is within
/// `budget`. Returns the final knots, working points and span bounds.
///
/// # Errors
/// [`Error::ConditionNotMet`] when the budget is below the rounding level or needs more
/// than [`MAX_FIT_SPANS`] spans or [`MAX_FIT_WORK`]; the errors of [`fit_restricted`].
pub(crate) fn fit_to_budget(
    src: &Source,
    m: usize,
    knots: Vec<f64>,
    budget: f64,
) -> Result<(Vec<f64>, Vec<f64>, Vec<SpanBound>)> {
    fit_to_budget_attained(src, m, knots, budget, &mut Vec::new())
}

/// [`fit_to_budget`], with per span of the result a value the error attains in `attained`
/// (see [`span_bounds_restricted`]).
fn fit_to_budget_attained(
    src: &Source,
    m: usize,
    mut knots: Vec<f64>,
    budget: f64,
    attained: &mut Vec<f64>,
) -> Result<(Vec<f64>, Vec<f64>, Vec<SpanBound>)> {
    let mut rounds = 0;
    let mut work = 0usize;
    let mut data = SpanData::default();
    loop {
        // One restriction of the source and one extraction per span, for the fit's rows
        // and the bounds.
        data.fill(src, m, &knots);
        let points = fit_restricted(src, m, &knots, &data)?;
        let bounds = span_bounds_restricted(src, m, (&knots, &points, &data), budget, attained)?;
        if bounds.iter().all(|x| x.bound <= budget) {
            return Ok((knots, points, bounds));
        }
        rounds += 1;
        let unit = span_unit(src);
        work = work.saturating_add(bounds.len().saturating_mul(unit));
        // The first split aims at the budget (the input's spans are far from it, so the
        // prediction has slack); later ones, which refine spans already near it, aim lower.
        let target = if rounds >= 2 {
            SPLIT_TARGET * budget
        } else {
            budget
        };
        let threshold = if rounds >= CREEP_ROUNDS {
            target
        } else {
            budget
        };
        let new = splits(&bounds, budget, (threshold, target), m)?;
        let too_many = || unreachable("the refinement needs too many spans");
        let spans = bounds.len() + new.len();
        if rounds > MAX_ROUNDS || spans > MAX_FIT_SPANS {
            return Err(too_many());
        }
        let next = (bounds.len() + new.len()).saturating_mul(unit);
        if work.saturating_add(next) > MAX_FIT_WORK {
            return Err(unreachable(
                "the refinement needs too much work (more than 2^23 span coordinates over its rounds, each span counted with 24 more per curve of the bundle, times (p + 1)^2 / 64 above degree 7)",
            ));
        }
        knots.extend(new);
        knots.sort_by(f64::total_cmp);
        let mut breaks = knots[m..knots.len() - m].to_vec();
        breaks.dedup();
        let graded = grading_breaks(&breaks, GRADE, MAX_FIT_SPANS - spans).ok_or_else(too_many)?;
        knots.extend(graded);
        knots.sort_by(f64::total_cmp);
    }
}

/// The spline of working points `work` as a model-space curve (NURBS when `rational`).
fn model_curve(
    m: usize,
    knots: Vec<f64>,
    work: &[f64],
    dim: usize,
    rational: bool,
) -> Result<BSplineCurve> {
    if !rational {
        return BSplineCurve::new(m, knots, work.to_vec(), dim);
    }
    let mut pts = Vec::with_capacity(work.len() / (dim + 1) * dim);
    let mut w = Vec::with_capacity(work.len() / (dim + 1));
    for q in work.chunks_exact(dim + 1) {
        pts.extend(q[..dim].iter().map(|x| x / q[dim]));
        w.push(q[dim]);
    }
    BSplineCurve::new_rational(m, knots, pts, w, dim)
}

/// [`BSplineStrategy::GlobalFit`] (see [`crate::reduce_bspline`]; `opts` validated there,
/// `opts.continuity` set), with the certified bound of every span of the fit after knot
/// removal ([`SpanCaps`], in the units of `curve`): the measurement, here or of the framed
/// caller, visits only the pairs of pieces whose bound can reach the largest distance
/// ([`spline_max_deviation_known`]; for a polynomial curve also with the source's pieces,
/// which are `curve`'s).
pub(crate) fn reduce_global(
    curve: &BSplineCurve,
    opts: &BSplineOptions,
) -> Result<(BSplineReduction, Option<SpanCaps>)> {
    let (p, m, tol) = (curve.degree(), opts.target, opts.tolerance);
    let k = opts.continuity.unwrap_or(m - 1);
    let rational = curve.is_rational();
    let src = Source::new(
        &working(curve)?,
        curve.dim() + usize::from(rational),
        rational,
    )?;
    let knots = first_knots(curve.knots(), &src, m, k, FIT_SHARE * tol)?;
    let mut attained = Vec::new();
    let (knots, points, bounds) =
        fit_to_budget_attained(&src, m, knots, FIT_SHARE * tol, &mut attained)?;
    let fitted = model_curve(m, knots.clone(), &points, curve.dim(), rational)?;
    let pieces = bounds.len();
    let segment_bound = bounds.iter().map(|x| x.bound).fold(0.0, f64::max);
    let mut breaks: Vec<f64> = bounds.iter().map(|x| x.a).collect();
    breaks.push(bounds[pieces - 1].b);
    let mut local = LocalBounds::new(breaks, bounds.iter().map(|x| x.bound).collect());
    let mut raw = Raw::new(&fitted);
    // Knot removal with the spans' bounds sharpened by the refined hull where the node
    // bound alone would refuse a removal the sharper bound might allow.
    let mut hull =
        |i: usize| hull_span_bound(&src, m, (&knots, &points), (bounds[i].a, bounds[i].b));
    let mut sharpen = Sharpen::new(
        bounds.iter().map(|x| x.bound).collect(),
        attained,
        &mut hull,
    );
    local.remove_greedily_with(&mut raw, tol, Some(&mut sharpen))?;
    let curve_out = raw.into_curve()?;
    let mut caps = SpanCaps {
        breaks: local.breaks().to_vec(),
        bounds: local.spans().to_vec(),
        pieces: None,
    };
    let max_error = if opts.measure {
        let known = Known {
            pieces_a: (!rational).then_some((&src.breaks[..], src.all_points())),
            caps: Some(&caps),
        };
        Some(spline_max_deviation_known(curve, &curve_out, known)?)
    } else {
        None
    };
    let out_knots = curve_out.knots();
    let mut continuity = Vec::new();
    for &t in &src.breaks[1..src.breaks.len() - 1] {
        if knot_multiplicity(out_knots, t) > 0 {
            continuity.push((t, order_at(curve.knots(), p, k, t)?.min(m - 1)));
        }
    }
    // The non-empty knot spans of the (clamped) domain: the Bézier pieces.
    let (ko, mo) = (curve_out.knots(), curve_out.degree());
    let spans_out = ko[mo..ko.len() - mo]
        .windows(2)
        .filter(|w| w[0] < w[1])
        .count();
    let spans_in = src.breaks.len() - 1;
    // A NURBS is reduced in its frame: the caller measures in the model, with the source's
    // pieces moved back (a polynomial input's are passed above).
    if rational {
        caps.pieces = Some(src.into_pieces());
    }
    let red = BSplineReduction {
        report: BSplineReport {
            strategy: BSplineStrategy::GlobalFit,
            degree_from: p,
            degree_to: m,
            tolerance: tol,
            error_bound: local.max_bound(),
            segment_bound,
            max_error,
            pieces,
            continuity,
        },
        curve: curve_out,
        spans_in,
        spans_out,
    };
    Ok((red, Some(caps)))
}
