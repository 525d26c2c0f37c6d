//! Tests of [`reduce_bspline_piegl_tiller`]: degree-elevated splines reduce back to the
//! original, perturbed ones within a certified bound, generic ones fail, NURBS, bad inputs.

use super::*;
use cagd_core::BezierCurve;
use proptest::prelude::*;

/// Dimension of the test curves.
const DIM: usize = 3;
/// Agreement of a recovered spline with the original, relative to its largest coordinate:
/// elevation, extraction, one-degree reductions and knot removals each cost a few ulp
/// times small factors; 1e-10 leaves ample room and still catches any wrong knot or point.
const REL: f64 = 1e-10;

/// A xorshift generator (deterministic tests without extra dependencies).
pub(in crate::bspline) struct Rng(pub(in crate::bspline) u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in `0..n`.
    pub(in crate::bspline) fn below(&mut self, n: usize) -> usize {
        usize::try_from(self.next() % u64::try_from(n).unwrap()).unwrap()
    }
    fn sym(&mut self) -> f64 {
        2.0 * self.unit() - 1.0
    }
}

/// A clamped degree-`p` spline on `[0, 1]` with `mults.len() + 1` spans of random lengths
/// (ratios up to 1:4), interior multiplicities `mults`, points in `[-1, 1]^3`, weights in
/// `[0.5, 2]` when `rational`.
pub(in crate::bspline) fn random_spline(
    p: usize,
    mults: &[usize],
    rational: bool,
    rng: &mut Rng,
) -> BSplineCurve {
    let lens: Vec<f64> = (0..=mults.len()).map(|_| 1.0 + 3.0 * rng.unit()).collect();
    let total: f64 = lens.iter().sum();
    let mut knots = vec![0.0; p + 1];
    let mut acc = 0.0;
    for (len, &s) in lens.iter().zip(mults) {
        acc += len;
        knots.extend(std::iter::repeat_n(acc / total, s));
    }
    knots.extend(std::iter::repeat_n(1.0, p + 1));
    let n = knots.len() - p - 1;
    let pts: Vec<f64> = (0..n * DIM).map(|_| rng.sym()).collect();
    if rational {
        let w = (0..n).map(|_| 0.5 + 1.5 * rng.unit()).collect();
        BSplineCurve::new_rational(p, knots, pts, w, DIM).unwrap()
    } else {
        BSplineCurve::new(p, knots, pts, DIM).unwrap()
    }
}

/// `c` elevated by `r` exactly: every Bézier piece elevated, merged C0, then each interior
/// knot of multiplicity `s` removed down to `s + r` (the joint keeps its `C^(p-s)`);
/// verified by sampling and by the multiplicities.
pub(in crate::bspline) fn elevate(c: &BSplineCurve, r: usize) -> BSplineCurve {
    let pieces = c.to_beziers().unwrap();
    let mut breaks: Vec<f64> = pieces.iter().map(|x| x.start).collect();
    breaks.push(pieces.last().unwrap().end);
    let segs: Vec<BezierCurve> = pieces.iter().map(|x| x.curve.elevate(r).unwrap()).collect();
    let mut e = BSplineCurve::from_beziers(&segs, &breaks, 0, 1e-12).unwrap();
    for &v in &breaks[1..breaks.len() - 1] {
        let s = knot_multiplicity(c.knots(), v);
        let out = e.remove_knot(v, c.degree() - s, 1e-12).unwrap();
        assert_eq!(out.removed, c.degree() - s);
        e = out.curve;
        assert_eq!(knot_multiplicity(e.knots(), v), s + r);
    }
    assert!(spline_max_deviation(c, &e).unwrap() < 1e-13);
    e
}

/// `c` with every coordinate (and weight) moved by up to `size` (times its own scale).
pub(in crate::bspline) fn perturb(c: &BSplineCurve, size: f64, rng: &mut Rng) -> BSplineCurve {
    let pts = c.points().iter().map(|x| x + size * rng.sym()).collect();
    match c.weights() {
        None => BSplineCurve::new(c.degree(), c.knots().to_vec(), pts, DIM),
        Some(w) => {
            let w = w.iter().map(|x| x * (1.0 + size * rng.sym())).collect();
            BSplineCurve::new_rational(c.degree(), c.knots().to_vec(), pts, w, DIM)
        }
    }
    .unwrap()
}

/// Same knot vector, and points and weights within `REL` of the largest entry.
fn assert_same(got: &BSplineCurve, want: &BSplineCurve) {
    assert_eq!(got.knots(), want.knots());
    let close = |a: &[f64], b: &[f64]| {
        let scale = b.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let dev = a
            .iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
        assert_eq!(a.len(), b.len());
        assert!(dev <= REL * scale, "deviation {dev:e} (scale {scale:e})");
    };
    close(got.points(), want.points());
    assert_eq!(got.is_rational(), want.is_rational());
    if let (Some(a), Some(b)) = (got.weights(), want.weights()) {
        close(a, b);
    }
}

/// The interior knots of `c` with the continuity `p - s` they have.
fn continuity_of(c: &BSplineCurve) -> Vec<(f64, usize)> {
    let (a, b) = c.domain();
    let mut v: Vec<f64> = c
        .knots()
        .iter()
        .copied()
        .filter(|x| *x > a && *x < b)
        .collect();
    v.dedup();
    v.iter()
        .map(|&x| (x, c.degree() - knot_multiplicity(c.knots(), x)))
        .collect()
}

#[test]
fn elevated_cubics_reduce_back() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for rational in [false, true] {
        let c = random_spline(3, &[1, 2, 1, 1, 2, 1], rational, &mut rng);
        for r in [2, 4] {
            let e = elevate(&c, r);
            let red = reduce_bspline_piegl_tiller(&e, 3, 1e-8, true).unwrap();
            assert_same(&red.curve, &c);
            let rep = &red.report;
            let measured = rep.max_error.unwrap();
            assert!(
                measured <= rep.error_bound && rep.error_bound < 1e-12,
                "{rep:?}"
            );
            assert!(rep.segment_bound <= rep.error_bound);
            assert_eq!((red.spans_in, red.spans_out, rep.pieces), (7, 7, 7));
            assert_eq!((rep.degree_from, rep.degree_to), (3 + r, 3));
            assert_eq!(rep.strategy, BSplineStrategy::PieglTiller1995);
            assert_eq!(rep.continuity, continuity_of(&c));
        }
    }
}

#[test]
fn perturbed_elevated_cubics_meet_the_tolerance() {
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    // Weights scaled by 1/20 leave the NURBS unchanged but shrink its homogeneous errors
    // 20-fold: the model-space conversion must then be what keeps bound >= error.
    for (rational, w_scale) in [(false, 1.0), (true, 1.0), (true, 0.05)] {
        let c = random_spline(3, &[2, 1, 1, 2, 1], rational, &mut rng);
        let c = match c.weights() {
            None => c,
            Some(w) => {
                let w = w.iter().map(|x| x * w_scale).collect();
                BSplineCurve::new_rational(3, c.knots().to_vec(), c.points().to_vec(), w, DIM)
                    .unwrap()
            }
        };
        for r in [2, 4] {
            let e = perturb(&elevate(&c, r), 1e-7, &mut rng);
            let red = reduce_bspline_piegl_tiller(&e, 3, 1e-5, true).unwrap();
            let rep = &red.report;
            let measured = rep.max_error.unwrap();
            assert!(measured > 1e-8, "the perturbation is visible: {measured:e}");
            assert!(measured <= rep.error_bound, "{rep:?}");
            assert!(rep.error_bound <= 1e-5, "{rep:?}");
            assert_eq!(red.curve.knots(), c.knots());
        }
    }
}

#[test]
fn generic_splines_fail() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    let c = random_spline(7, &[1; 5], false, &mut rng);
    let r = reduce_bspline_piegl_tiller(&c, 3, 1e-6, false);
    assert!(
        matches!(r, Err(Error::ConditionNotMet { eq: EQ, .. })),
        "{r:?}"
    );
    // Double knots of a generic (rational) quintic: C3 there is not kept by the segments.
    let d = random_spline(5, &[2; 4], true, &mut rng);
    let r = reduce_bspline_piegl_tiller(&d, 3, 1e-6, false);
    assert!(
        matches!(r, Err(Error::ConditionNotMet { eq: EQ, .. })),
        "{r:?}"
    );
}

#[test]
fn one_segment_is_bounded_by_its_reduction() {
    // One Bézier segment: the only error is the one-degree reductions' own bound.
    let mut rng = Rng(0x0dd_ba11);
    let c = random_spline(5, &[], false, &mut rng);
    let big = reduce_bspline_piegl_tiller(&c, 4, 10.0, true).unwrap();
    let rep = &big.report;
    assert!(rep.max_error.unwrap() <= rep.error_bound && rep.error_bound == rep.segment_bound);
    let tight = reduce_bspline_piegl_tiller(&c, 4, 0.5 * rep.error_bound, false);
    assert!(
        matches!(tight, Err(Error::ConditionNotMet { .. })),
        "{tight:?}"
    );
}

#[test]
fn bad_inputs() {
    let mut rng = Rng(7);
    let c = random_spline(4, &[2, 1], false, &mut rng);
    for (m, tol) in [(0, 1e-3), (4, 1e-3), (5, 1e-3)] {
        let r = reduce_bspline_piegl_tiller(&c, m, tol, false);
        assert!(matches!(r, Err(Error::BadDegreePair { .. })), "{m}: {r:?}");
    }
    for tol in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let r = reduce_bspline_piegl_tiller(&c, 3, tol, false);
        assert!(matches!(r, Err(Error::BadTolerance { .. })), "{tol}: {r:?}");
    }
    let jump = random_spline(4, &[1, 5], false, &mut rng);
    let r = reduce_bspline_piegl_tiller(&jump, 3, 1e-3, false);
    assert!(
        matches!(r, Err(Error::BadParameter { name: "knots", .. })),
        "{r:?}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn elevated_random_splines_reduce_back(
        p in 1usize..=4,
        spans in 1usize..=20,
        r in 1usize..=3,
        rational in any::<bool>(),
        seed in 1u64..u64::MAX,
    ) {
        let mut rng = Rng(seed);
        let mults: Vec<usize> = (1..spans)
            .map(|_| 1 + rng.below(p))
            .collect();
        let c = random_spline(p, &mults, rational, &mut rng);
        let red = reduce_bspline_piegl_tiller(&elevate(&c, r), p, 1e-8, false).unwrap();
        assert_same(&red.curve, &c);
        prop_assert!(red.report.error_bound < 1e-11);
        prop_assert_eq!(red.spans_out, spans);
    }
}
