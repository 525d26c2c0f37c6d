//! WSGB curves (seed 003): evaluation per point by the WSGB peeling algorithm against
//! de Casteljau on the Bézier form of the same curve (n = 5, 10, 20; 3-D; reused work
//! buffer, no allocation on either side), and the reduction time per curve (one degree,
//! perturbation and best uniform, certified bound included, measurement off; and the L2
//! method through the exact conversion).
//!
//! Besides criterion's report, prints `ns/point` and `ns/curve` (median of 15 runs) and,
//! for the reductions, the ratio to a plain copy of the input and output points.

use std::hint::black_box;

use cagd_core::{WsgbCurve, kernel::de_casteljau, wsgb_max_l};
use cagd_reduce::{Method, WsgbMethod, reduce_wsgb_with};
use criterion::{Criterion, criterion_group, criterion_main};

use cagd_testkit::bench::{median_ns, memcpy_ns, random_input};

const DIM: usize = 3;
const POINTS: usize = 1001;

fn bench(c: &mut Criterion) {
    for n in [5usize, 10, 20] {
        let l = wsgb_max_l(n) / 2;
        let curve = WsgbCurve::new(random_input((n + 1) * DIM, n as u64), DIM, l).expect("curve");
        let bez = curve.to_bezier().expect("bezier");
        let params: Vec<f64> = (0..POINTS)
            .map(|k| k as f64 / (POINTS - 1) as f64)
            .collect();
        let mut out = [0.0; DIM];
        let mut work = vec![0.0; bez.points().len()];
        let mut group = c.benchmark_group(format!("wsgb_eval_n{n}"));
        group.sample_size(20);
        group.bench_function("wsgb_peeling", |b| {
            b.iter(|| {
                for &u in &params {
                    curve.eval_into(black_box(u), &mut out);
                }
            })
        });
        group.bench_function("de_casteljau", |b| {
            b.iter(|| {
                for &u in &params {
                    de_casteljau(bez.points(), DIM, black_box(u), &mut work, &mut out);
                }
            })
        });
        group.finish();
        let t_w = median_ns(|| {
            for &u in &params {
                curve.eval_into(black_box(u), &mut out);
            }
        }) / POINTS as f64;
        let t_d = median_ns(|| {
            for &u in &params {
                de_casteljau(bez.points(), DIM, black_box(u), &mut work, &mut out);
            }
        }) / POINTS as f64;
        println!(
            "n = {n:2}, L = {l}: WSGB eval {t_w:6.1} ns/point, de Casteljau {t_d:6.1} ns/point, \
             ratio {:4.2}",
            t_d / t_w
        );
        for (name, method) in [
            ("perturbation", WsgbMethod::Perturbation),
            ("uniform", WsgbMethod::Uniform),
            (
                "l2-via-bezier",
                WsgbMethod::Bezier(Method::L2 { r: 0, p: 0 }),
            ),
        ] {
            let mut g = c.benchmark_group(format!("wsgb_reduce_n{n}"));
            g.sample_size(10);
            g.bench_function(name, |b| {
                b.iter(|| {
                    reduce_wsgb_with(black_box(&curve), n - 1, method, false).expect("reduce")
                })
            });
            g.finish();
            let t = median_ns(|| {
                reduce_wsgb_with(black_box(&curve), n - 1, method, false).expect("reduce");
            });
            let copy = memcpy_ns(curve.points(), &curve.points()[DIM..]);
            println!(
                "n = {n:2} -> {}: {name:<14} {t:9.0} ns/curve (ratio to a copy {:7.1})",
                n - 1,
                t / copy
            );
        }
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
