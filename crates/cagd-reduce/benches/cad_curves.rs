//! The proxy of issue 17's real-CAD-file row: B-spline / NURBS curves of degree 4–15 with
//! 1–20 spans (synthetic, `cad_curves/shapes.rs`: polynomial, NURBS with weights in
//! `[0.5, 2]`, exact ellipse arcs elevated to degree 4–8) reduced to degree 3 within 1e-3,
//! 1e-5 and 1e-7 (model units, mm) by exactly what `cagd reduce --to 3 --tol T` runs on a
//! `"bspline"` input: [`reduce_bspline`] with the default strategy (the global fit,
//! continuity `C^2` where the input has it) and `measure: true` (the command reports
//! `max_error`, [`cagd_reduce::spline_max_deviation`]).
//!
//! Besides criterion's report (one iteration reduces every curve of the set), prints per
//! tolerance and kind the mean time per curve, its ratio to a plain copy of the same bytes
//! (input and output knots, points and weights), the mean spans in and out, and the worst
//! ratio of certified bound to measured error; any curve the route fails on is named.
//! OCCT's figures for the row (`GeomConvert_ApproxCurve` C1, in-process: 0.21 / 0.33 /
//! 0.86 ms per curve on the held-back files) are issue 17's, not measured here; the
//! process and JSON costs of the command are measured in `benches/README.md`.

use cagd_testkit::bench as common;

use std::hint::black_box;

use cagd_core::BSplineCurve;
use cagd_reduce::{BSplineOptions, reduce_bspline};
use criterion::{Criterion, criterion_group, criterion_main};

#[path = "cad_curves/shapes.rs"]
mod shapes;

/// Curves in the set (a third of each kind).
const CURVES: usize = 150;
const TOLERANCES: [f64; 3] = [1e-3, 1e-5, 1e-7];
const TARGET: usize = 3;

/// The options the command builds for `reduce --to 3 --tol T` on a B-spline.
fn options(tol: f64) -> BSplineOptions {
    BSplineOptions {
        measure: true,
        ..BSplineOptions::new(TARGET, tol)
    }
}

/// The knots, points and weights of `c` in one buffer (the bytes a reduction reads or
/// writes).
fn flat(c: &BSplineCurve) -> Vec<f64> {
    let mut v = c.knots().to_vec();
    v.extend_from_slice(c.points());
    v.extend_from_slice(c.weights().unwrap_or(&[]));
    v
}

/// Per kind: curves, total ns, total copy ns, spans in, spans out, worst bound / measured.
#[derive(Default, Clone, Copy)]
struct Tally {
    curves: usize,
    ns: f64,
    copy_ns: f64,
    spans_in: usize,
    spans_out: usize,
    worst_ratio: f64,
    worst_bound: f64,
}

fn bench(c: &mut Criterion) {
    let set: Vec<(&str, BSplineCurve)> = (0..CURVES).map(shapes::curve).collect();
    let mut g = c.benchmark_group("cad_curves");
    g.sample_size(10);
    for tol in TOLERANCES {
        let opts = options(tol);
        let mut tally = [Tally::default(); 3];
        let mut failed = Vec::new();
        for (i, (kind, curve)) in set.iter().enumerate() {
            let r = match reduce_bspline(curve, &opts) {
                Ok(r) => r,
                Err(e) => {
                    failed.push(format!("#{i} ({kind}, degree {}): {e}", curve.degree()));
                    continue;
                }
            };
            let ns = common::median_ns_of(5, || {
                black_box(reduce_bspline(black_box(curve), &opts).expect("reducible"));
            });
            let copy = common::memcpy_ns(&flat(curve), &flat(&r.curve));
            let measured = r.report.max_error.unwrap_or(f64::NAN);
            assert!(
                measured <= r.report.error_bound && r.report.error_bound <= tol,
                "curve {i}: bound {:e} measured {measured:e} tolerance {tol:e}",
                r.report.error_bound
            );
            let k = shapes::KINDS.iter().position(|x| x == kind).unwrap_or(0);
            let t = &mut tally[k];
            t.curves += 1;
            t.ns += ns;
            t.copy_ns += copy;
            t.spans_in += r.spans_in;
            t.spans_out += r.spans_out;
            t.worst_ratio = t.worst_ratio.max(r.report.error_bound / measured);
            t.worst_bound = t.worst_bound.max(r.report.error_bound);
        }
        let mut all = Tally::default();
        for (kind, t) in shapes::KINDS.iter().zip(&tally) {
            report(tol, kind, t);
            all.curves += t.curves;
            all.ns += t.ns;
            all.copy_ns += t.copy_ns;
            all.spans_in += t.spans_in;
            all.spans_out += t.spans_out;
            all.worst_ratio = all.worst_ratio.max(t.worst_ratio);
            all.worst_bound = all.worst_bound.max(t.worst_bound);
        }
        report(tol, "all", &all);
        for f in &failed {
            println!("  tol {tol:.0e}: fails on {f}");
        }
        g.bench_function(format!("all_to_3_tol_{tol:.0e}"), |b| {
            b.iter(|| {
                for (_, curve) in &set {
                    let _ = black_box(reduce_bspline(black_box(curve), &opts));
                }
            })
        });
    }
    g.finish();
}

fn report(tol: f64, kind: &str, t: &Tally) {
    let n = t.curves.max(1) as f64;
    println!(
        "tol {tol:.0e} {kind:>8}: {:4} curves {:9.1} us/curve ({:6.0}x a copy); spans in \
         {:5.2} out {:6.2} per curve; bound <= {:.2e}, bound / measured <= {:.3}",
        t.curves,
        t.ns / n / 1e3,
        t.ns / t.copy_ns,
        t.spans_in as f64 / n,
        t.spans_out as f64 / n,
        t.worst_bound,
        t.worst_ratio,
    );
}

criterion_group!(benches, bench);
criterion_main!(benches);
