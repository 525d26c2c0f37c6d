//! B-spline degree reduction to a tolerance: a 1 000-span degree-7 curve to degree 3 at
//! tolerance 1e-6 by [`reduce_bspline`], every strategy, on two inputs:
//!
//! - `spiral`: clamped, uniform knots on `[0, 1000]`, control points on a slowly turning
//!   planar spiral with a small wiggle (size ~100): every span smooth but genuinely of
//!   degree 7 (Piegl & Tiller 1995 cannot reduce it without subdividing and fails).
//! - `near-cubic`: a random C2 cubic spline with 1 000 spans, elevated to degree 7 and
//!   perturbed by 1e-8 relative: the case the classical algorithm is made for.
//!
//! Besides criterion's report, prints per strategy the time per input span, its ratio to a
//! plain copy of the same bytes (the input's and the result's knots, points and weights),
//! the spans in and out, the spans before knot removal, the certified bound and the
//! measured error.

use cagd_testkit::bench as common;

use std::hint::black_box;

use cagd_core::{BSplineCurve, BezierCurve};
use cagd_reduce::{BSplineOptions, BSplineStrategy, Method, reduce_bspline};
use criterion::{Criterion, criterion_group, criterion_main};

const SPANS: usize = 1000;
const P: usize = 7;
const TOL: f64 = 1e-6;

fn spiral() -> BSplineCurve {
    let n = SPANS + P;
    let mut knots = vec![0.0; P + 1];
    knots.extend((1..SPANS).map(|i| i as f64));
    knots.extend(std::iter::repeat_n(SPANS as f64, P + 1));
    let points: Vec<f64> = (0..n)
        .flat_map(|i| {
            let t = i as f64 * 0.01;
            let r = 50.0 + 20.0 * t + 0.3 * (i as f64 * 0.7).sin();
            [r * t.cos(), r * t.sin()]
        })
        .collect();
    BSplineCurve::new(P, knots, points, 2).expect("valid curve")
}

/// A C2 cubic with `SPANS` uniform spans (random points of size ~10), every piece elevated
/// to degree 7 and merged back `C^2` (multiplicity 5), then every point moved by ~1e-7.
fn near_cubic() -> BSplineCurve {
    let mut knots = vec![0.0; 4];
    knots.extend((1..SPANS).map(|i| i as f64));
    knots.extend(std::iter::repeat_n(SPANS as f64, 4));
    let pts: Vec<f64> = common::random_input(2 * (SPANS + 3), 7)
        .iter()
        .map(|x| 10.0 * x)
        .collect();
    let cubic = BSplineCurve::new(3, knots, pts, 2).expect("valid cubic");
    let pieces = cubic.to_beziers().expect("pieces");
    let mut breaks: Vec<f64> = pieces.iter().map(|x| x.start).collect();
    breaks.push(SPANS as f64);
    let segs: Vec<BezierCurve> = pieces
        .iter()
        .map(|x| x.curve.elevate(P - 3).expect("elevate"))
        .collect();
    let e = BSplineCurve::from_beziers(&segs, &breaks, 2, 1e-9).expect("merge");
    let noise = common::random_input(e.points().len(), 11);
    let pts: Vec<f64> = e
        .points()
        .iter()
        .zip(&noise)
        .map(|(p, n)| p + noise_size() * n)
        .collect();
    BSplineCurve::new(P, e.knots().to_vec(), pts, 2).expect("valid")
}

fn strategies() -> [(&'static str, BSplineStrategy); 3] {
    [
        ("fit", BSplineStrategy::GlobalFit),
        (
            "segments",
            BSplineStrategy::Segments(Method::ConstrainedChebyshev { r: 0, p: 0 }),
        ),
        ("piegl-tiller-1995", BSplineStrategy::PieglTiller1995),
    ]
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("bspline");
    g.sample_size(10);
    for (input_name, input) in [("spiral", spiral()), ("near-cubic", near_cubic())] {
        for (name, strategy) in strategies() {
            let opts = BSplineOptions {
                strategy,
                ..BSplineOptions::new(3, TOL)
            };
            let measured = BSplineOptions {
                measure: true,
                ..opts
            };
            match reduce_bspline(&input, &measured) {
                Ok(r) => {
                    let ns = common::median_ns(|| {
                        black_box(reduce_bspline(&input, &opts).expect("reducible"));
                    });
                    let copy = common::memcpy_ns(&flat(&input), &flat(&r.curve));
                    println!(
                        "{input_name:>10} {name:>17}: {:8.1} us/span ({:.0}x a copy); spans in {} \
                         out {} (before knot removal {}); bound {:.3e}, measured {:.3e}",
                        ns / 1e3 / SPANS as f64,
                        ns / copy,
                        r.spans_in,
                        r.spans_out,
                        r.report.pieces,
                        r.report.error_bound,
                        r.report.max_error.unwrap_or(f64::NAN)
                    );
                    g.bench_function(format!("{input_name}_{name}_7_to_3_tol_1e-6"), |b| {
                        b.iter(|| reduce_bspline(black_box(&input), &opts).expect("reducible"))
                    });
                }
                Err(e) => println!("{input_name:>10} {name:>17}: fails: {e}"),
            }
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);

/// The knots, points and weights of `c` in one buffer (the bytes a reduction reads or
/// writes).
fn flat(c: &BSplineCurve) -> Vec<f64> {
    let mut v = c.knots().to_vec();
    v.extend_from_slice(c.points());
    v.extend_from_slice(c.weights().unwrap_or(&[]));
    v
}

fn noise_size() -> f64 {
    std::env::var("NOISE")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1e-7)
}
