//! The pruned measurement of `spline_max_deviation` (a Chebyshev–Lobatto node pass bounds
//! each pair of pieces, only the pairs that can hold the maximum are sampled densely and
//! refined) against a dense sample of the distance.

use cagd_core::BSplineCurve;
use cagd_reduce::{BSplineOptions, reduce_bspline, spline_max_deviation};

use cagd_testkit::bench::random_input;

/// The largest distance at `count + 1` equidistant parameters (model space).
fn dense(a: &BSplineCurve, b: &BSplineCurve, count: u32) -> f64 {
    let (ea, eb) = (|t| a.eval(t).unwrap(), |t| b.eval(t).unwrap());
    cagd_testkit::sampled_max_distance(ea, eb, a.domain(), count)
}

/// The pruned measurement (node values, Ehlich–Zeller bounds, at most 16 pairs refined)
/// against 200 000 equidistant samples, on degree 6–13 splines and NURBS (weights in
/// `[0.5, 2]`) and their cubic fits at 1e-3 / 1e-5 (tens of pairs of pieces with
/// errors of like size, where the pruning decides): never below the dense maximum
/// (up to the evaluations' rounding), and within the dense sampling's own shortfall
/// of it (a dense sample misses a quadratic maximum by `~(pi / samples per pair)^2`).
#[test]
fn the_pruned_measurement_is_the_dense_maximum() {
    for case in 0..8usize {
        let p = 6 + case;
        let spans = 3 + case % 4;
        let mut knots = vec![0.0; p + 1];
        knots.extend((1..spans).map(|i| (i as f64 + 0.2) / spans as f64));
        knots.extend(std::iter::repeat_n(1.0, p + 1));
        let n = knots.len() - p - 1;
        let seed = 900 + case as u64;
        let pts = random_input(3 * n, seed);
        let c = if case % 2 == 0 {
            BSplineCurve::new(p, knots, pts, 3).unwrap()
        } else {
            let w: Vec<f64> = random_input(n, seed + 50)
                .iter()
                .map(|x| 2f64.powf(*x))
                .collect();
            BSplineCurve::new_rational(p, knots, pts, w, 3).unwrap()
        };
        for tol in [1e-3, 1e-5] {
            let r = reduce_bspline(&c, &BSplineOptions::new(3, tol)).unwrap();
            let measured = spline_max_deviation(&c, &r.curve).unwrap();
            let sampled = dense(&c, &r.curve, 200_000);
            assert!(
                measured >= sampled * (1.0 - 1e-9),
                "case {case} tol {tol}: {measured} < {sampled}"
            );
            assert!(
                measured <= sampled * (1.0 + 1e-4),
                "case {case} tol {tol}: {measured} far above {sampled}"
            );
            assert!(measured <= r.report.error_bound);
        }
    }
}
