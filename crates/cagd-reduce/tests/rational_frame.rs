//! Unit-consistent rational bounds and bounded work (issue 18).
//!
//! 1. **Frame law.** The same NURBS curve (surface) moved by `t` (`1e-6 ..= 1e8`) or scaled
//!    by `k` (`1e-6 ..= 1e6`) and reduced with the tolerance scaled by `k` gives the same
//!    spans (patches) and the bound `k b` (to `1e-9` relative, plus the rounding level of
//!    the moved coordinates), for the segments strategy (L2 and constrained Chebyshev),
//!    Piegl & Tiller, the global fit, the uniform pipeline (seed 001), the rational Bézier
//!    reducer, and the patch-wise, to-tolerance and global-fit surface reducers. Every
//!    bound is checked against the distance measured independently (dense sampling here,
//!    not the library's maximiser).
//! 2. **Exactly reducible far away.** A degree-elevated NURBS at `1e8` (and one scaled by
//!    `1e6`) reduces back on the input's spans by every strategy.
//! 3. **Bounded work.** Inputs that made the segments strategy / the surface refinement
//!    subdivide without end (weights far from 1 and strongly varying, far from the origin,
//!    tolerances near the rounding level) answer or refuse with a named error, and the work
//!    done is within the documented caps ([`MAX_SEGMENT_REDUCTIONS`],
//!    [`MAX_SURFACE_PATCHES`]) — asserted on the counts, not on timings.

use cagd_core::{BSplineCurve, BSplineSurface, BezierCurve, Error};
use cagd_reduce::{
    BSplineOptions, BSplineStrategy, MAX_SEGMENT_REDUCTIONS, MAX_SURFACE_PATCHES, Merge, Method,
    ReduceOptions, SurfaceFitOptions, SurfaceOptions, reduce_bspline, reduce_bspline_piegl_tiller,
    reduce_bspline_surface, reduce_bspline_surface_fit, reduce_bspline_surface_to_tolerance,
    reduce_uniform_bspline, reduce_with,
};

/// Translations of the law (scale 1) and scales (no translation); and two mixed ones.
const MOVES: [(f64, f64); 13] = [
    (1e-6, 1.0),
    (1e-2, 1.0),
    (1.0, 1.0),
    (1e3, 1.0),
    (1e5, 1.0),
    (1e8, 1.0),
    (0.0, 1e-6),
    (0.0, 1e-3),
    (0.0, 0.37),
    (0.0, 3e3),
    (0.0, 1e6),
    (1e8, 1e3),
    (1e-2, 1e-6),
];

/// The direction translations are applied along (all coordinates move).
const DIR: [f64; 3] = [1.0, -0.7, 0.3];

/// `k x + t DIR` for points of `dim` coordinates.
fn moved(points: &[f64], dim: usize, (t, k): (f64, f64)) -> Vec<f64> {
    points
        .iter()
        .enumerate()
        .map(|(i, x)| k * x + t * DIR[i % dim])
        .collect()
}

/// A degree-5 NURBS (2-D) with 4 spans, an interior double knot and weights 0.4 .. 3.
fn nurbs() -> BSplineCurve {
    let knots = vec![
        0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.2, 0.45, 0.45, 0.7, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0,
    ];
    let n = knots.len() - 6;
    let pts: Vec<f64> = (0..n)
        .flat_map(|i| {
            let a = i as f64 * 0.7;
            [3.0 * a.cos() + 0.2 * a, 2.0 * a.sin() - 0.1 * a * a]
        })
        .collect();
    let w: Vec<f64> = (0..n)
        .map(|i| 1.0 + 0.8 * ((i as f64) * 1.3).sin() + 0.6)
        .collect();
    BSplineCurve::new_rational(5, knots, pts, w, 2).unwrap()
}

/// `c` with its points moved (weights, knots kept).
fn moved_curve(c: &BSplineCurve, mv: (f64, f64)) -> BSplineCurve {
    BSplineCurve::new_rational(
        c.degree(),
        c.knots().to_vec(),
        moved(c.points(), c.dim(), mv),
        c.weights().unwrap().to_vec(),
        c.dim(),
    )
    .unwrap()
}

/// Model-space distance sampled densely: at every knot of both curves and 40 points in
/// every span of their common refinement (independent of the library's maximiser).
fn sampled(a: &BSplineCurve, b: &BSplineCurve) -> f64 {
    let mut ts: Vec<f64> = a.knots().iter().chain(b.knots()).copied().collect();
    let (lo, hi) = a.domain();
    ts.retain(|t| *t >= lo && *t <= hi);
    ts.sort_by(f64::total_cmp);
    ts.dedup();
    let mut best = 0.0f64;
    for w in ts.windows(2) {
        for j in 0..=40 {
            let t = w[0] + (w[1] - w[0]) * f64::from(j) / 40.0;
            let (x, y) = (a.eval(t).unwrap(), b.eval(t).unwrap());
            let d = x
                .iter()
                .zip(&y)
                .map(|(p, q)| (p - q) * (p - q))
                .sum::<f64>();
            best = best.max(d.sqrt());
        }
    }
    best
}

/// The rounding level of coordinates moved by `t` and scaled by `k` (absolute): what a
/// bound may differ by from `k` times the unmoved one.
fn rounding_level((t, k): (f64, f64), size: f64) -> f64 {
    64.0 * f64::EPSILON * (t.abs() + k * size)
}

/// The strategies of the curve law, with the tolerance (unmoved) each is run at.
fn strategies() -> Vec<(&'static str, BSplineStrategy, f64)> {
    vec![
        (
            "segments-l2",
            BSplineStrategy::Segments(Method::L2 { r: 0, p: 0 }),
            1e-3,
        ),
        (
            "segments-cheb",
            BSplineStrategy::Segments(Method::ConstrainedChebyshev { r: 0, p: 0 }),
            1e-3,
        ),
        ("fit", BSplineStrategy::GlobalFit, 1e-3),
    ]
}

#[test]
fn curve_strategies_are_unit_consistent() {
    let c = nurbs();
    let size = 4.0;
    for (name, strategy, tol) in strategies() {
        let run = |mv: (f64, f64)| {
            let opts = BSplineOptions {
                strategy,
                measure: true,
                ..BSplineOptions::new(3, tol * mv.1)
            };
            let input = moved_curve(&c, mv);
            let r = reduce_bspline(&input, &opts).unwrap_or_else(|e| panic!("{name} {mv:?}: {e}"));
            let measured = sampled(&input, &r.curve);
            assert!(
                measured <= r.report.error_bound,
                "{name} {mv:?}: measured {measured} above bound {}",
                r.report.error_bound
            );
            assert!(r.report.max_error.unwrap() <= r.report.error_bound);
            r
        };
        let base = run((0.0, 1.0));
        for mv in MOVES {
            let r = run(mv);
            assert_eq!(r.spans_out, base.spans_out, "{name} {mv:?}: spans");
            let expect = base.report.error_bound * mv.1;
            let slack = 1e-9 * expect + rounding_level(mv, size);
            assert!(
                (r.report.error_bound - expect).abs() <= slack,
                "{name} {mv:?}: bound {} vs {expect}",
                r.report.error_bound
            );
        }
    }
}

/// A cubic NURBS with double interior knots elevated exactly to degree 5 (every piece),
/// so Piegl & Tiller and every strategy reduce it back to degree 3 within rounding.
fn elevated() -> (BSplineCurve, usize) {
    let cubic = BSplineCurve::new_rational(
        3,
        vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.3, 0.6, 1.0, 1.0, 1.0, 1.0],
        vec![
            0.0, 0.0, 1.0, 2.0, 2.5, 2.0, 4.0, -1.0, 5.0, 1.0, 6.0, 0.5, 7.0, 2.0,
        ],
        vec![1.0, 2.0, 0.5, 1.5, 3.0, 1.0, 1.2],
        2,
    )
    .unwrap();
    let segs = cubic.to_beziers().unwrap();
    let pieces: Vec<BezierCurve> = segs.iter().map(|s| s.curve.elevate(2).unwrap()).collect();
    let mut breaks: Vec<f64> = segs.iter().map(|s| s.start).collect();
    breaks.push(1.0);
    let c = BSplineCurve::from_beziers(&pieces, &breaks, 0, 1e-12).unwrap();
    (c, segs.len())
}

#[test]
fn exactly_reducible_nurbs_far_away_or_scaled_reduces_back() {
    let (c, spans) = elevated();
    for mv in [(0.0, 1.0), (1e8, 1.0), (0.0, 1e6), (0.0, 1e-6), (1e5, 1e-2)] {
        let input = moved_curve(&c, mv);
        let tol = 1e-6 * mv.1 + rounding_level(mv, 8.0) * 16.0;
        let pt = reduce_bspline_piegl_tiller(&input, 3, tol, true)
            .unwrap_or_else(|e| panic!("piegl-tiller {mv:?}: {e}"));
        assert!(pt.spans_out <= spans, "piegl-tiller {mv:?}");
        assert!(sampled(&input, &pt.curve) <= pt.report.error_bound);
        for (name, strategy, _) in strategies() {
            let opts = BSplineOptions {
                strategy,
                ..BSplineOptions::new(3, tol)
            };
            let r = reduce_bspline(&input, &opts).unwrap_or_else(|e| panic!("{name} {mv:?}: {e}"));
            assert!(r.spans_out <= spans, "{name} {mv:?}: {} spans", r.spans_out);
            assert!(
                sampled(&input, &r.curve) <= r.report.error_bound,
                "{name} {mv:?}"
            );
        }
    }
}

#[test]
fn piegl_tiller_is_unit_consistent() {
    // A perturbed elevated curve: a real (non-zero) bound that must scale with the curve.
    let (c, _) = elevated();
    let mut pts = c.points().to_vec();
    pts[5] += 1e-5;
    let c = BSplineCurve::new_rational(
        c.degree(),
        c.knots().to_vec(),
        pts,
        c.weights().unwrap().to_vec(),
        2,
    )
    .unwrap();
    let base = reduce_bspline_piegl_tiller(&c, 3, 1e-3, true).unwrap();
    assert!(base.report.error_bound > 1e-7);
    for mv in MOVES {
        let input = moved_curve(&c, mv);
        let r = reduce_bspline_piegl_tiller(&input, 3, 1e-3 * mv.1, true)
            .unwrap_or_else(|e| panic!("{mv:?}: {e}"));
        assert_eq!(r.spans_out, base.spans_out, "{mv:?}");
        let expect = base.report.error_bound * mv.1;
        assert!(
            (r.report.error_bound - expect).abs() <= 1e-9 * expect + rounding_level(mv, 8.0),
            "{mv:?}: {} vs {expect}",
            r.report.error_bound
        );
        assert!(sampled(&input, &r.curve) <= r.report.error_bound, "{mv:?}");
    }
}

#[test]
fn uniform_pipeline_and_bezier_reducer_are_unit_consistent() {
    // Seed 001's uniform knots, a NURBS of degree 6 with 3 segments.
    let knots: Vec<f64> = (0..=15).map(f64::from).collect();
    let n = knots.len() - 7;
    let pts: Vec<f64> = (0..n)
        .flat_map(|i| [i as f64, (i as f64 * 0.9).sin() * 3.0])
        .collect();
    let w: Vec<f64> = (0..n).map(|i| 1.0 + 0.5 * (i % 3) as f64).collect();
    let c = BSplineCurve::new_rational(6, knots, pts, w, 2).unwrap();
    let hermite = Method::ConstrainedChebyshev { r: 1, p: 1 };
    let base = reduce_uniform_bspline(&c, 3, hermite, Merge::Exact).unwrap();
    let bez = c.to_beziers().unwrap()[1].curve.clone();
    let bopts = ReduceOptions::new(Method::L2 { r: 1, p: 1 }, 3);
    let bbase = reduce_with(&bez, &bopts)
        .unwrap()
        .report
        .error_bound
        .unwrap();
    for mv in MOVES {
        let input = moved_curve(&c, mv);
        let r = reduce_uniform_bspline(&input, 3, hermite, Merge::Exact).unwrap();
        let expect = base.error_bound * mv.1;
        let slack = 1e-9 * expect + rounding_level(mv, 16.0);
        assert!((r.error_bound - expect).abs() <= slack, "uniform {mv:?}");
        assert!(sampled(&input, &r.curve) <= r.error_bound, "uniform {mv:?}");
        let b = BezierCurve::new_rational(
            moved(bez.points(), 2, mv),
            bez.weights().unwrap().to_vec(),
            2,
        )
        .unwrap();
        let rb = reduce_with(&b, &bopts).unwrap();
        let got = rb.report.error_bound.unwrap();
        let expect = bbase * mv.1;
        // The bound also holds the rounding of measuring two rational curves at the
        // curve's own coordinates (`2 (2 (n + m) + 8) sqrt(dim) eps max |x|`, ~74 eps |x|
        // here), which grows with the translation by nature: three rounding levels.
        assert!(
            (got - expect).abs() <= 1e-9 * expect + 3.0 * rounding_level(mv, 16.0),
            "bezier {mv:?}: {got} vs {expect}"
        );
        let mut worst = 0.0f64;
        for i in 0..=2000 {
            let t = f64::from(i) / 2000.0;
            let (x, y) = (b.eval(t), rb.curve.eval(t));
            worst = worst.max(((x[0] - y[0]).powi(2) + (x[1] - y[1]).powi(2)).sqrt());
        }
        assert!(worst <= got, "bezier {mv:?}: {worst} above {got}");
    }
}

/// A rational bicubic surface, 3 x 2 spans, weights `wscale * (1 .. 1 + wvar)`.
fn surface(wscale: f64, wvar: f64) -> BSplineSurface {
    let ku = vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.7, 1.0, 1.0, 1.0, 1.0];
    let kv = vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0];
    let (nu, nv) = (6, 5);
    let mut pts = Vec::new();
    let mut w = Vec::new();
    for i in 0..nu {
        for j in 0..nv {
            let (x, y) = (i as f64, j as f64);
            pts.extend([x, y, 0.4 * (x * 0.9).sin() * (y * 0.7).cos() + 0.05 * x * y]);
            w.push(wscale * (1.0 + wvar * 0.5 * (1.0 + ((i * 7 + j * 3) as f64).sin())));
        }
    }
    BSplineSurface::new_rational((3, 3), ku, kv, pts, w, (nu, nv), 3).unwrap()
}

fn moved_surface(s: &BSplineSurface, mv: (f64, f64)) -> BSplineSurface {
    BSplineSurface::new_rational(
        s.degrees(),
        s.knots_u().to_vec(),
        s.knots_v().to_vec(),
        moved(s.points(), 3, mv),
        s.weights().unwrap().to_vec(),
        s.counts(),
        3,
    )
    .unwrap()
}

/// Distance on a `61 x 61` grid per cell of `a` (independent of the library's maximiser).
fn surface_sampled(a: &BSplineSurface, b: &BSplineSurface) -> f64 {
    let distinct = |k: &[f64]| {
        let mut v = k.to_vec();
        v.dedup();
        v
    };
    let (us, vs) = (distinct(a.knots_u()), distinct(a.knots_v()));
    let mut best = 0.0f64;
    for wu in us.windows(2) {
        for wv in vs.windows(2) {
            for i in 0..=60 {
                for j in 0..=60 {
                    let u = wu[0] + (wu[1] - wu[0]) * f64::from(i) / 60.0;
                    let v = wv[0] + (wv[1] - wv[0]) * f64::from(j) / 60.0;
                    let (x, y) = (a.eval(u, v).unwrap(), b.eval(u, v).unwrap());
                    let d = x
                        .iter()
                        .zip(&y)
                        .map(|(p, q)| (p - q) * (p - q))
                        .sum::<f64>();
                    best = best.max(d.sqrt());
                }
            }
        }
    }
    best
}

#[test]
fn surface_reducers_are_unit_consistent() {
    let s = surface(1.0, 2.0);
    let opts = SurfaceOptions::new((2, 2));
    let base = reduce_bspline_surface(&s, &opts).unwrap();
    let tbase = reduce_bspline_surface_to_tolerance(&s, &opts, 1e-2).unwrap();
    let fbase = reduce_bspline_surface_fit(&s, &SurfaceFitOptions::new((2, 2), 1e-2)).unwrap();
    for mv in MOVES {
        let input = moved_surface(&s, mv);
        let r = reduce_bspline_surface(&input, &opts).unwrap();
        let expect = base.error_bound * mv.1;
        let slack = 1e-9 * expect + rounding_level(mv, 8.0);
        assert!(
            (r.error_bound - expect).abs() <= slack,
            "patch-wise {mv:?}: {} vs {expect}",
            r.error_bound
        );
        let t = reduce_bspline_surface_to_tolerance(&input, &opts, 1e-2 * mv.1).unwrap();
        assert_eq!(t.patches, tbase.patches, "to tolerance {mv:?}");
        let expect = tbase.error_bound * mv.1;
        assert!(
            (t.error_bound - expect).abs() <= 1e-9 * expect + rounding_level(mv, 8.0),
            "to tolerance {mv:?}: {} vs {expect}",
            t.error_bound
        );
        let fopts = SurfaceFitOptions::new((2, 2), 1e-2 * mv.1);
        let f = reduce_bspline_surface_fit(&input, &fopts).unwrap();
        assert_eq!(f.spans_out, fbase.spans_out, "fit {mv:?}");
        let expect = fbase.error_bound * mv.1;
        assert!(
            (f.error_bound - expect).abs() <= 1e-9 * expect + rounding_level(mv, 8.0),
            "fit {mv:?}: {} vs {expect}",
            f.error_bound
        );
        if mv.0 <= 1e5 {
            assert!(
                surface_sampled(&input, &f.surface) <= f.error_bound,
                "fit {mv:?}"
            );
            assert!(
                surface_sampled(&input, &r.surface) <= r.error_bound,
                "{mv:?}"
            );
        }
    }
}

#[test]
fn segments_work_is_capped_on_hard_nurbs() {
    // Weights from 1e-3 to 1e3 between neighbours, far from the origin, tolerances down
    // to the rounding level: an answer or a named refusal, within the work cap.
    let knots = vec![
        0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0,
    ];
    let n = knots.len() - 6;
    let pts: Vec<f64> = (0..n)
        .flat_map(|i| [1e6 + (i as f64 * 1.7).sin(), -1e6 + (i as f64).cos()])
        .collect();
    let w: Vec<f64> = (0..n)
        .map(|i| if i % 2 == 0 { 1e-3 } else { 1e3 })
        .collect();
    let c = BSplineCurve::new_rational(5, knots, pts, w, 2).unwrap();
    for tol in [1e-2, 1e-5, 1e-8, 1e-9] {
        for method in [
            Method::L2 { r: 0, p: 0 },
            Method::ConstrainedChebyshev { r: 0, p: 0 },
        ] {
            let opts = BSplineOptions {
                strategy: BSplineStrategy::Segments(method),
                ..BSplineOptions::new(2, tol)
            };
            match reduce_bspline(&c, &opts) {
                Ok(r) => {
                    assert!(r.report.pieces <= MAX_SEGMENT_REDUCTIONS);
                    assert!(r.report.error_bound <= tol);
                    // Evaluation at 1e6 rounds at ~1e-10: allowed on top of the bound.
                    let noise = 64.0 * f64::EPSILON * 2e6;
                    assert!(
                        sampled(&c, &r.curve) <= r.report.error_bound + noise,
                        "{tol}"
                    );
                }
                Err(Error::NoConvergence {
                    tolerance,
                    achieved,
                }) => {
                    assert_eq!(tolerance, tol);
                    assert!(achieved > tolerance * 0.9 || achieved.is_infinite());
                }
                Err(Error::ConditionNotMet { .. }) => {}
                Err(e) => panic!("{tol}: unexpected {e}"),
            }
        }
    }
}

#[test]
fn surface_refinement_work_is_capped() {
    // 10 x 8 spans with weights 1e3 .. 1e5, at 1e6: level 4 has 20 480 patches, level 5
    // would have 81 920 (above the cap). A tolerance no level can meet is refused without
    // going past the cap; a reachable one is met within it.
    let s = moved_surface(&surface(1e3, 1e2), (1e6, 1.0));
    let mut r = s.clone();
    for t in [0.1, 0.2, 0.4, 0.5, 0.6, 0.8, 0.9] {
        r = r.insert_knot_u(t, 1).unwrap();
    }
    for t in [0.1, 0.2, 0.3, 0.4, 0.6, 0.7] {
        r = r.insert_knot_v(t, 1).unwrap();
    }
    let opts = SurfaceOptions::new((2, 2));
    match reduce_bspline_surface_to_tolerance(&r, &opts, 1e-12) {
        Err(Error::NoConvergence {
            tolerance,
            achieved,
        }) => {
            assert_eq!(tolerance, 1e-12);
            assert!(achieved > 1e-12 && achieved.is_finite());
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
    let ok = reduce_bspline_surface_to_tolerance(&r, &opts, 1e-2).unwrap();
    assert!(ok.patches <= MAX_SURFACE_PATCHES && ok.error_bound <= 1e-2);
}

#[test]
fn strongly_varying_weights_refine_instead_of_failing() {
    // Weights 1 .. 1 001 between neighbours, at 1e4: the coarse level's reduced weights go
    // negative (it used to fail there at once); a finer level reduces within the tolerance.
    let s = moved_surface(&surface(1.0, 1e3), (1e4, 1.0));
    let opts = SurfaceOptions {
        measure: true,
        ..SurfaceOptions::new((2, 2))
    };
    assert!(matches!(
        reduce_bspline_surface(&s, &opts),
        Err(Error::NonPositiveWeight { .. })
    ));
    let r = reduce_bspline_surface_to_tolerance(&s, &opts, 1e-3).unwrap();
    assert!(r.error_bound <= 1e-3 && r.patches <= MAX_SURFACE_PATCHES);
    assert!(r.max_error.unwrap() <= r.error_bound);
    assert!(surface_sampled(&s, &r.surface) <= r.error_bound + 1e-9);
}

/// A rational degree-53 curve whose points all coincide (a point, in model space) reduced
/// with the optimal G1 perturbation: the C ABI fuzz harness saw a certified bound of
/// 1.73e-15 beside a measured 1.81e-15 (the measurement's own rounding of two rational
/// evaluations). The bound now includes that rounding, so a report never shows a measured
/// error above its bound.
#[test]
#[allow(
    clippy::excessive_precision,
    reason = "the fuzz harness's %.17g dump, kept verbatim (17 digits round-trip every double)"
)]
fn rational_point_curve_bound_covers_the_measurement() {
    let pts = vec![
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.4595599517703205,
        -0.4595599517703205,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.4595599517703205,
        -0.4595599517703205,
        -0.45955995177032055,
        -0.45955995177032055,
        -0.4595599517703205,
        -0.4595599517703205,
        -0.4595599517703205,
        -0.4595599517703205,
        -0.45955995177032055,
        -0.45955995177032055,
        -0.45955995177032061,
        -0.45955995177032061,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.4595599517703205,
        -0.4595599517703205,
        -0.45955995177032039,
        -0.45955995177032039,
        -0.45955995177032039,
        -0.45955995177032039,
        -0.45955995177032033,
        -0.45955995177032033,
        -0.45955995177032027,
        -0.45955995177032027,
        -0.45955995177032027,
        -0.45955995177032027,
        -0.45955995177032022,
        -0.45955995177032022,
        -0.45955995177032016,
        -0.45955995177032016,
        -0.45955995177032022,
        -0.45955995177032022,
        -0.45955995177032033,
        -0.45955995177032033,
        -0.45955995177032027,
        -0.45955995177032027,
        -0.45955995177032027,
        -0.45955995177032027,
        -0.45955995177032022,
        -0.45955995177032022,
        -0.45955995177032016,
        -0.45955995177032016,
        -0.45955995177032016,
        -0.45955995177032016,
        -0.45955995177032027,
        -0.45955995177032027,
        -0.45955995177032027,
        -0.45955995177032027,
        -0.45955995177032027,
        -0.45955995177032027,
        -0.45955995177032039,
        -0.45955995177032039,
        -0.45955995177032033,
        -0.45955995177032033,
        -0.45955995177032033,
        -0.45955995177032033,
        -0.45955995177032033,
        -0.45955995177032033,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032039,
        -0.45955995177032039,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032039,
        -0.45955995177032039,
        -0.4595599517703205,
        -0.4595599517703205,
        -0.4595599517703205,
        -0.4595599517703205,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032039,
        -0.45955995177032039,
        -0.45955995177032044,
        -0.45955995177032044,
        -0.45955995177032039,
        -0.45955995177032039,
        -0.45955995177032039,
        -0.45955995177032039,
    ];
    let w = vec![
        2.8100124214330418,
        2.8335784645391389,
        2.8587755389375822,
        2.8850030379151477,
        2.9113894422683053,
        2.9368419000509611,
        2.9601174054868844,
        2.9799105288849352,
        2.9949507055344995,
        3.0041007406072788,
        3.0064476767940143,
        3.0013776481825669,
        2.9886277983179661,
        2.9683105838306649,
        2.9409084776064973,
        2.9072398228732936,
        2.8683990335080298,
        2.825676346824423,
        2.7804640456482903,
        2.7341578319282061,
        2.6880642251179188,
        2.6433275190540417,
        2.6008923036911673,
        2.5615182523345021,
        2.5258603855612938,
        2.4946177630888542,
        2.4687349344057141,
        2.4496144379160372,
        2.4392700836134127,
        2.440329215998629,
        2.4557908598332299,
        2.4884793340168629,
        2.5402081482396324,
        2.6107828017614541,
        2.6971001345449066,
        2.7927010567079291,
        2.8881430046691534,
        2.9724236835393096,
        3.0353898146293412,
        3.0706514550321335,
        3.0781187144886881,
        3.0650565941308843,
        3.0446706460906015,
        3.0317624379763335,
        3.035911686116906,
        3.0539203766905207,
        3.0648791302009628,
        3.0328820087308821,
        2.922640131944521,
        2.7280959149648227,
        2.4959738741975275,
        2.2831056488129571,
        1.9269838513610018,
        0.7261160987484232,
    ];
    let c = BezierCurve::new_rational(pts, w, 2).unwrap();
    let r = cagd_reduce::reduce_g1_optimal(&c, true).unwrap();
    let (b, e) = (r.report.error_bound.unwrap(), r.report.max_error.unwrap());
    assert!(e <= b, "measured {e} above the bound {b}");
    // Still a rounding-level bound: the curve is a point.
    assert!(b < 1e-12, "{b}");
    let l2 = reduce_with(
        &c,
        &ReduceOptions {
            measure: true,
            ..ReduceOptions::new(Method::L2 { r: 0, p: 0 }, 40)
        },
    )
    .unwrap();
    let (b, e) = (l2.report.error_bound.unwrap(), l2.report.max_error.unwrap());
    assert!(e <= b && b < 1e-12, "L2: measured {e}, bound {b}");
}
