//! B-spline degree reduction to a tolerance: a 1 000-span degree-7 curve to degree 3 at
//! tolerance 1e-6 by [`reduce_bspline`].
//!
//! The curve: clamped, uniform knots on `[0, 1000]`, control points on a slowly turning
//! planar spiral with a small wiggle (size ~100), so each span is smooth but genuinely of
//! degree 7. Besides criterion's report, prints the time per input span, the spans in and
//! out, the pieces after subdivision, the certified bound and the measured error.

use std::hint::black_box;
use std::time::Instant;

use cagd_core::BSplineCurve;
use cagd_reduce::{BSplineOptions, reduce_bspline};
use criterion::{Criterion, criterion_group, criterion_main};

const SPANS: usize = 1000;
const P: usize = 7;

fn curve() -> BSplineCurve {
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

fn bench(c: &mut Criterion) {
    let input = curve();
    let opts = BSplineOptions::new(3, 1e-6);
    let measured = BSplineOptions {
        measure: true,
        ..opts
    };
    let r = reduce_bspline(&input, &measured).expect("reducible");
    let start = Instant::now();
    let runs = 3;
    for _ in 0..runs {
        black_box(reduce_bspline(&input, &opts).expect("reducible"));
    }
    let per_span = start.elapsed().as_secs_f64() / runs as f64 / SPANS as f64;
    println!(
        "bspline 1000 spans deg 7 -> 3, tol 1e-6: {:.1} us/span; spans in {} out {} \
         (pieces after subdivision {}); bound {:.3e}, measured {:.3e}",
        per_span * 1e6,
        r.spans_in,
        r.spans_out,
        r.report.pieces,
        r.report.error_bound,
        r.report.max_error.unwrap_or(f64::NAN)
    );
    let mut g = c.benchmark_group("bspline");
    g.sample_size(10);
    g.bench_function("reduce_1000_spans_7_to_3_tol_1e-6", |b| {
        b.iter(|| reduce_bspline(black_box(&input), &opts).expect("reducible"))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
