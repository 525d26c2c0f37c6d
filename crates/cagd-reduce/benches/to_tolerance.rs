//! Bézier curves to cubic within a tolerance (issue 17's "a2" row): random 3-D Bézier
//! curves of degree n = 5, 10, 15, 20, 30 (points uniform in `[-1, 1]^3`, as the peers
//! harness draws them) reduced to degree 3 within 1e-4 by each strategy a kernel would use:
//!
//! - `default`: [`reduce_to_tolerance`] with its defaults (L2 with C0 ends, C0 joins);
//! - `c1`: the same with `L2 { r: 1, p: 1 }` and C1 joins (OCCT's `GeomAbs_C1` run);
//! - `fit`: the curve as a one-span clamped B-spline through [`reduce_bspline`]'s default
//!   strategy (global fit, C2 cubic spline).
//!
//! Besides criterion's report, prints per strategy and degree the time per curve (median
//! over 20 curves), its ratio to a plain copy of the same bytes (input points and output
//! knots and points), the mean spans and the worst certified bound. OCCT's times for the
//! same row (`GeomConvert_ApproxCurve`, C1, `MaxSegments = 1000`) come from the peers
//! harness run in `benches/README.md`, not from here.

use cagd_testkit::bench as common;

use std::hint::black_box;

use cagd_core::{BSplineCurve, BezierCurve};
use cagd_reduce::{BSplineOptions, Method, ToleranceOptions, reduce_bspline, reduce_to_tolerance};
use criterion::{Criterion, criterion_group, criterion_main};

const TOL: f64 = 1e-4;
const CURVES: usize = 20;
const DEGREES: [usize; 5] = [5, 10, 15, 20, 30];

fn curves(n: usize) -> Vec<BezierCurve> {
    (0..CURVES)
        .map(|i| {
            let pts = common::random_input(3 * (n + 1), (n * 1000 + i) as u64);
            BezierCurve::new(pts, 3).expect("valid curve")
        })
        .collect()
}

fn as_bspline(c: &BezierCurve) -> BSplineCurve {
    let n = c.degree();
    let mut knots = vec![0.0; n + 1];
    knots.extend(std::iter::repeat_n(1.0, n + 1));
    BSplineCurve::new(n, knots, c.points().to_vec(), 3).expect("valid spline")
}

/// One strategy's result on one curve: the spline and its certified bound.
fn run(strategy: &str, c: &BezierCurve, b: &BSplineCurve) -> (BSplineCurve, f64) {
    match strategy {
        "default" => {
            let r = reduce_to_tolerance(
                c,
                &ToleranceOptions::new(Method::L2 { r: 0, p: 0 }, 3, TOL, 0),
            )
            .expect("reducible");
            let bound = r.report.error_bound;
            (r.spline, bound)
        }
        "c1" => {
            let r = reduce_to_tolerance(
                c,
                &ToleranceOptions::new(Method::L2 { r: 1, p: 1 }, 3, TOL, 1),
            )
            .expect("reducible");
            let bound = r.report.error_bound;
            (r.spline, bound)
        }
        _ => {
            let r = reduce_bspline(b, &BSplineOptions::new(3, TOL)).expect("reducible");
            (r.curve, r.report.error_bound)
        }
    }
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("to_tolerance");
    g.sample_size(10);
    for n in DEGREES {
        let input = curves(n);
        let splines: Vec<BSplineCurve> = input.iter().map(as_bspline).collect();
        for strategy in ["default", "c1", "fit"] {
            let mut spans = 0usize;
            let mut worst: f64 = 0.0;
            let mut flat_in = Vec::new();
            let mut flat_out = Vec::new();
            for (cv, bs) in input.iter().zip(&splines) {
                let (s, bound) = run(strategy, cv, bs);
                assert!(
                    bound <= TOL,
                    "{strategy} n = {n}: bound {bound} above {TOL}"
                );
                spans += s.knots().windows(2).filter(|w| w[1] > w[0]).count();
                worst = worst.max(bound);
                flat_in.extend_from_slice(cv.points());
                flat_out.extend_from_slice(s.knots());
                flat_out.extend_from_slice(s.points());
            }
            let ns = common::median_ns_of(3, || {
                for (cv, bs) in input.iter().zip(&splines) {
                    black_box(run(strategy, black_box(cv), bs));
                }
            }) / CURVES as f64;
            let copy = common::memcpy_ns(&flat_in, &flat_out) / CURVES as f64;
            println!(
                "{n:>2} -> 3 within {TOL:e} {strategy:>8}: {:9.1} us/curve ({:.0}x a copy); \
                 {:.1} spans per curve; worst bound {worst:.3e}",
                ns / 1e3,
                ns / copy,
                spans as f64 / CURVES as f64,
            );
            g.bench_function(format!("{strategy}_{n}_to_3_tol_1e-4"), |b| {
                b.iter(|| run(strategy, black_box(&input[0]), &splines[0]))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
