//! Implicitization benchmarks (issue 12): exact implicit coefficients at degree 2, 3, 4, 5,
//! 7, 10 for random curves (full 53-bit mantissas) and for small binary fractions (the `f64` coefficients are the exact ones rounded once, so "f64" here is the
//! whole [`ImplicitCurve`] — exact polynomial, `f64` Bézout matrices and report — and
//! "bezout" the `f64` Bézout matrices alone), classifying one point at degree 5, inverting
//! one point, and intersecting two cubics and two quintics.
//!
//! Anchors (issue 12, same machine): python-flint `fmpq_mpoly.resultant` 0.21 / 0.30 /
//! 0.29 / 0.52 ms at degree 2 / 3 / 4 / 5; libbezier point evaluation 11–18 µs (degree
//! <= 3). Besides criterion's report, prints the median time of each case in µs.

use std::hint::black_box;
use std::time::Instant;

use cagd_core::BezierCurve;
use cagd_implicit::{BezoutMatrix, ImplicitCurve, implicitize, intersect};
use criterion::{Criterion, criterion_group, criterion_main};

/// A deterministic pseudo-random rational curve of degree `n` (coordinates in ±1, weights
/// in 0.5..2, full 53-bit mantissas).
fn curve(n: usize, seed: u64) -> BezierCurve {
    let mut s = seed
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let pts: Vec<f64> = (0..2 * (n + 1)).map(|_| 2.0 * next() - 1.0).collect();
    let w: Vec<f64> = (0..=n).map(|_| 0.5 + 1.5 * next()).collect();
    BezierCurve::new_rational(pts, w, 2).expect("valid curve")
}

/// A curve of degree `n` with small binary-fraction coordinates (multiples of 1/8 in ±2)
/// and weights (multiples of 1/4 in 0.5..2), like the spec vectors.
fn small_curve(n: usize) -> BezierCurve {
    let pts: Vec<f64> = (0..2 * (n + 1))
        .map(|i| ((i * 37 + 11) % 33) as f64 / 8.0 - 2.0)
        .collect();
    let w: Vec<f64> = (0..=n)
        .map(|i| 0.5 + ((i * 5 + 3) % 7) as f64 / 4.0)
        .collect();
    BezierCurve::new_rational(pts, w, 2).expect("valid curve")
}

fn median_us(mut f: impl FnMut()) -> f64 {
    let reps = 31;
    let mut inner = 1usize;
    let t = Instant::now();
    f();
    let once = t.elapsed().as_secs_f64();
    while once * (inner as f64) < 1e-4 {
        inner *= 2;
    }
    let mut times: Vec<f64> = (0..reps)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..inner {
                f();
            }
            t.elapsed().as_secs_f64() * 1e6 / inner as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[reps / 2]
}

fn bench(c: &mut Criterion) {
    let mut summary = Vec::new();
    for n in [2usize, 3, 4, 5, 7, 10] {
        let cv = curve(n, n as u64);
        let mut g = c.benchmark_group(format!("implicitize_n{n}"));
        g.sample_size(20);
        g.bench_function("exact", |b| {
            b.iter(|| implicitize(black_box(&cv)).expect("ok"))
        });
        g.bench_function("f64_implicit_curve", |b| {
            b.iter(|| ImplicitCurve::new(black_box(&cv)).expect("ok"))
        });
        g.bench_function("bezout_f64", |b| {
            b.iter(|| BezoutMatrix::new(black_box(&cv)).expect("ok"))
        });
        g.finish();
        summary.push(format!(
            "implicitize degree {n:>2}: exact {:>9.1} us, ImplicitCurve (exact + f64 matrices) {:>9.1} us, Bezout f64 {:>6.2} us",
            median_us(|| {
                black_box(implicitize(black_box(&cv)).expect("ok"));
            }),
            median_us(|| {
                black_box(ImplicitCurve::new(black_box(&cv)).expect("ok"));
            }),
            median_us(|| {
                black_box(BezoutMatrix::new(black_box(&cv)).expect("ok"));
            }),
        ));
    }
    for n in [2usize, 3, 4, 5, 7, 10] {
        let cv = small_curve(n);
        c.bench_function(&format!("implicitize_small_n{n}"), |b| {
            b.iter(|| implicitize(black_box(&cv)).expect("ok"))
        });
        summary.push(format!(
            "implicitize degree {n:>2}, small binary fractions: exact {:>9.1} us",
            median_us(|| {
                black_box(implicitize(black_box(&cv)).expect("ok"));
            })
        ));
    }
    let c5 = curve(5, 5);
    let imp = ImplicitCurve::new(&c5).expect("ok");
    let p = c5.eval(0.37);
    c.bench_function("classify_n5", |b| {
        b.iter(|| imp.classify(black_box(0.1), black_box(0.2)))
    });
    c.bench_function("invert_n5", |b| {
        b.iter(|| imp.invert(black_box(p[0]), black_box(p[1])))
    });
    summary.push(format!(
        "classify degree 5: {:.3} us; invert degree 5: {:.2} us",
        median_us(|| {
            black_box(imp.classify(black_box(0.1), black_box(0.2)));
        }),
        median_us(|| {
            let _ = black_box(imp.invert(black_box(p[0]), black_box(p[1])));
        })
    ));
    for n in [3usize, 5] {
        let (a, b) = (curve(n, 100 + n as u64), curve(n, 200 + n as u64));
        let hits = intersect(&a, &b).expect("ok").len();
        c.bench_function(&format!("intersect_n{n}"), |bch| {
            bch.iter(|| intersect(black_box(&a), black_box(&b)).expect("ok"))
        });
        summary.push(format!(
            "intersect two degree-{n} curves ({hits} intersections): {:.1} us",
            median_us(|| {
                black_box(intersect(black_box(&a), black_box(&b)).expect("ok"));
            })
        ));
    }
    println!("\n== summary (median)");
    for line in summary {
        println!("{line}");
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
