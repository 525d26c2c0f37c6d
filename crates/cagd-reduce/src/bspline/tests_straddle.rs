//! Tests of the fit whose spans straddle the input's breaks (`fit/spans.rs`'s cells,
//! `fit/predict.rs`'s `Density::across`, `global.rs`'s `first_knots`): the cells tile
//! every span, the fit is the L2-best one (residual orthogonal to the spline space by an
//! independent quadrature), every span bound covers the densely measured error on random
//! and adversarial curves (weight ratios 4 096, a near-cusp, interior knots of
//! multiplicity `p - 1`, many short input spans), and `reduce_bspline` takes the route
//! where it saves spans, within the tolerance, with the continuity its report states.

use super::fit::{Density, Source, fit, span_bounds};
use super::global::working;
use super::test_support::{
    greville, jittered_knots, residual_inner_products, sweep_point, sweep_weight,
};
use super::*;
use cagd_core::{BSplineCurve, knot_multiplicity};
use cagd_testkit::bench::random_input;
use cagd_testkit::sampled_max_distance;

/// A clamped degree-`p` spline on `[0, 1]` with `spans` jittered spans, the interior knot
/// at index `spans / 2` of multiplicity `mult`, control points on a smooth 3-D sweep
/// (`family` 1: the polygon doubles back at its middle, a near-cusp), weights (when
/// `rational`) `2^(6 r)` for `family` 0 (neighbour ratios up to 4 096) and `2^sin` otherwise.
/// Working (homogeneous) form when rational: blocks of 4.
fn curve(
    p: usize,
    spans: usize,
    mult: usize,
    (family, rational): (usize, bool),
    seed: u64,
) -> BSplineCurve {
    let r = random_input(8, seed);
    let knots = jittered_knots(p, spans, mult, &r);
    let n = knots.len() - p - 1;
    let noise = random_input(4 * n, seed + 1);
    let (mut pts, mut w) = (Vec::with_capacity(3 * n), Vec::with_capacity(n));
    for i in 0..n {
        let g = greville(&knots, p, i);
        let mut q = sweep_point(g, &r);
        if family == 1 && i == n / 2 {
            q = [q[0] - 1.5, q[1] + 0.8, q[2]];
        }
        pts.extend(
            q.iter()
                .enumerate()
                .map(|(k, x)| x + 0.01 * noise[4 * i + k]),
        );
        w.push(if family == 0 {
            2f64.powf(6.0 * noise[4 * i + 3])
        } else {
            sweep_weight(g, &r)
        });
    }
    if rational {
        BSplineCurve::new_rational(p, knots, pts, w, 3).unwrap()
    } else {
        BSplineCurve::new(p, knots, pts, 3).unwrap()
    }
}

/// The source of `c` (homogeneous when rational).
fn source(c: &BSplineCurve) -> Source {
    let r = c.is_rational();
    Source::new(&working(c).unwrap(), c.dim() + usize::from(r), r).unwrap()
}

/// Cubic knots on `[0, 1]`: `inner` uniform simple knots (shifted off any break) plus the
/// input's breaks of multiplicity above one at multiplicity 2 (the `C^1` a cubic keeps
/// there), so most spans straddle breaks.
fn straddling_knots(c: &BSplineCurve, inner: usize) -> Vec<f64> {
    let mut knots = vec![0.0; 4];
    knots.extend((1..=inner).map(|j| (j as f64 + 0.137) / (inner as f64 + 1.0)));
    let ck = c.knots();
    let p = c.degree();
    let mut t = ck[p + 1..ck.len() - p - 1].to_vec();
    t.dedup();
    for b in t {
        if knot_multiplicity(ck, b) > 1 {
            knots.extend([b, b]);
        }
    }
    knots.extend([1.0; 4]);
    knots.sort_by(f64::total_cmp);
    knots
}

/// The cells tile every span: contiguous, each inside its span and inside one piece, one
/// more per break strictly inside a span.
#[test]
fn cells_tile_the_spans_and_the_pieces() {
    let c = curve(7, 13, 1, (2, false), 3);
    let src = source(&c);
    for inner in [0, 4, 9, 30] {
        let knots = straddling_knots(&c, inner);
        let b = &src.breaks;
        let cells: Vec<_> = fit::Cells::new(&knots, 3, b).collect();
        let mut at = 0.0;
        let mut expected = 0;
        for s in 3..knots.len() - 4 {
            let (ka, kb) = (knots[s], knots[s + 1]);
            if ka < kb {
                expected += 1 + b.iter().filter(|x| **x > ka && **x < kb).count();
            }
        }
        assert_eq!(cells.len(), expected, "inner {inner}");
        for x in &cells {
            assert_eq!(x.a, at);
            assert!(x.a < x.b);
            assert!(knots[x.s] <= x.a && x.b <= knots[x.s + 1]);
            assert!(b[x.k] <= x.a && x.b <= b[x.k + 1]);
            at = x.b;
        }
        assert_eq!(at, 1.0);
    }
}

/// The straddling fit is the L2-best cubic with the end points kept: its residual is
/// orthogonal to every interior basis function, by composite Simpson on every cell
/// (knots and breaks merged; independent of the Gauss rows).
#[test]
fn the_straddling_fit_is_orthogonal_to_the_spline_space() {
    let c = curve(6, 9, 1, (2, false), 11);
    let src = source(&c);
    let knots = straddling_knots(&c, 5);
    let pts = fit(&src, 3, &knots).unwrap();
    let s = BSplineCurve::new(3, knots.clone(), pts, 3).unwrap();
    let n = knots.len() - 4;
    let mut cuts: Vec<f64> = knots.iter().chain(&src.breaks).copied().collect();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let inner = residual_inner_products(&c, &s, &cuts, 2000);
    for (j, v) in inner.iter().enumerate().take(n - 1).skip(1) {
        assert!(v.iter().all(|x| x.abs() < 1e-12), "N_{j}: {v:?}");
    }
    assert!(inner[0].iter().map(|x| x.abs()).sum::<f64>() > 1e-9);
}

/// Every span bound of straddling fits (node route alone and with the hulls) is at least
/// the error measured at 4 000 parameters of the span (model space), on polynomial and
/// rational curves of degree 4–13: many short input spans, weight ratios up to 4 096, a
/// near-cusp, an interior knot of multiplicity `p - 1` (kept at multiplicity 2).
#[test]
fn straddling_span_bounds_cover_the_measured_error() {
    for (case, p) in [4usize, 5, 7, 10, 13].into_iter().enumerate() {
        for family in 0..3 {
            for rational in [false, true] {
                let mult = if family == 2 { p - 1 } else { 1 };
                let spans = [24, 7, 15][family];
                let seed = 40 + 3 * case as u64 + family as u64;
                let c = curve(p, spans, mult, (family, rational), seed);
                let src = source(&c);
                let dim = src.pdim;
                for inner in [2usize, 11] {
                    let knots = straddling_knots(&c, inner);
                    let pts = fit(&src, 3, &knots).unwrap();
                    let s = BSplineCurve::new(3, knots.clone(), pts.clone(), dim).unwrap();
                    let model = |h: Vec<f64>| -> Vec<f64> {
                        if rational {
                            h[..3].iter().map(|x| x / h[3]).collect()
                        } else {
                            h
                        }
                    };
                    for sharpen in [f64::INFINITY, 0.0] {
                        let bounds =
                            span_bounds(&src, 3, (&knots, &pts), sharpen, &mut Vec::new()).unwrap();
                        let straddling = bounds
                            .iter()
                            .filter(|x| src.breaks.iter().any(|b| *b > x.a && *b < x.b))
                            .count();
                        assert!(straddling > 0 || inner == 2 && spans < 8);
                        for x in &bounds {
                            let meas = sampled_max_distance(
                                |t| c.eval(t).unwrap(),
                                |t| model(s.eval(t).unwrap()),
                                (x.a, x.b),
                                4000,
                            );
                            assert!(
                                x.bound >= meas,
                                "p={p} family {family} rational {rational} inner {inner}: bound {:e} < measured {meas:e} on [{}, {}]",
                                x.bound,
                                x.a,
                                x.b
                            );
                        }
                    }
                }
            }
        }
    }
}

/// The knots predicted across the pieces: increasing, strictly inside the segments
/// between the kept breaks, as many as the count the model gives (`span_counts`), and
/// fewer spans than the per-piece placement on an input of many short pieces.
#[test]
fn knots_across_the_pieces_follow_the_count() {
    let c = curve(9, 40, 1, (2, true), 7);
    let src = source(&c);
    let density = Density::new(&src, 3, 1e-3).unwrap();
    let (per_piece, across) = density.span_counts(&[]);
    let knots = density.across(&src, &[], usize::MAX).unwrap();
    assert!(across < per_piece, "{across} vs {per_piece}");
    assert!(per_piece >= 40);
    assert_eq!(knots.len() + 1, across);
    assert!(
        knots.windows(2).all(|w| w[0] < w[1]) && knots[0] > 0.0 && knots[knots.len() - 1] < 1.0
    );
    // A kept break splits the segments: no knot on it, the count per segment.
    let kept = [20usize];
    let (_, split) = density.span_counts(&kept);
    let knots = density.across(&src, &kept, usize::MAX).unwrap();
    assert!(knots.iter().all(|t| *t != src.breaks[20]));
    assert_eq!(knots.len() + 2, split);
    assert!(density.across(&src, &[], 3).is_none());
}

/// `reduce_bspline` on inputs of many short spans takes the straddling route (fewer spans
/// out than in), meets the tolerance with measured <= bound (the report's and a dense
/// sampling's), keeps the `C^1` break of multiplicity `p - 1` as a double knot with the
/// order its report states, and is `C^2` at every other knot.
#[test]
fn many_short_spans_reduce_across_their_breaks() {
    for (i, (p, mult, rational, tol)) in [
        (7usize, 1usize, false, 1e-2),
        (9, 1, true, 1e-2),
        (12, 1, true, 3e-3),
        (6, 5, true, 1e-2),
        (5, 4, false, 3e-3),
    ]
    .into_iter()
    .enumerate()
    {
        let c = curve(p, 60, mult, (2, rational), 90 + i as u64);
        let opts = BSplineOptions {
            measure: true,
            ..BSplineOptions::new(3, tol)
        };
        let r = reduce_bspline(&c, &opts).unwrap();
        assert!(
            r.spans_out < r.spans_in,
            "case {i}: {} -> {}",
            r.spans_in,
            r.spans_out
        );
        let bound = r.report.error_bound;
        let measured = r.report.max_error.unwrap();
        assert!(
            measured <= bound && bound <= tol,
            "case {i}: {measured:e} {bound:e}"
        );
        let dense = sampled_max_distance(
            |t| c.eval(t).unwrap(),
            |t| r.curve.eval(t).unwrap(),
            (0.0, 1.0),
            200_000,
        );
        assert!(
            dense <= bound,
            "case {i}: dense {dense:e} > bound {bound:e}"
        );
        let (ok, m) = (r.curve.knots(), 3);
        let mut interior = ok[m + 1..ok.len() - m - 1].to_vec();
        interior.dedup();
        for t in interior {
            let reported = r.report.continuity.iter().find(|x| x.0 == t).map(|x| x.1);
            let order = m - knot_multiplicity(ok, t);
            if knot_multiplicity(c.knots(), t) > 1 {
                assert_eq!(reported, Some(p - mult), "case {i} at {t}");
                assert!(order <= p - mult);
            } else {
                assert_eq!(order, 2, "case {i} at {t}");
                assert!(reported.is_none_or(|x| x == 2));
            }
        }
        if mult > 1 {
            let b = c.knots()[c
                .knots()
                .iter()
                .position(|&x| knot_multiplicity(c.knots(), x) == mult)
                .unwrap()];
            assert!(r.report.continuity.iter().any(|x| x.0 == b));
        }
    }
}
