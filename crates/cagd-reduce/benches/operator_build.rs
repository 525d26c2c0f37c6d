//! First-call cost of a reduction operator (issue 17): building the `(m+1) x (n+1)` matrix
//! and its bound data for a new `(method, n, m)`, uncached ([`build_operator`]), by the fast
//! routes and (once, for the "before" column) by the exact rational route.
//!
//! Prints, per method and pair `(4,3) (5,4) (10,5) (15,10) (20,10) (30,15)` plus degree 64:
//! µs per construction (median of 9 runs, `cagd_testkit::bench`; one run when the fast routes fall back to the exact one), the route taken, and the
//! exact route's time (one run; skipped at degree 64 unless `CAGD_BENCH_EXACT64=1`, it
//! takes seconds). Criterion's own report covers the L2-C0 pairs, with short times (run
//! with `-- --warm-up-time 1 --measurement-time 3`).

use std::hint::black_box;
use std::time::Instant;

use cagd_reduce::{Method, OperatorRoute, build_operator};
use criterion::{Criterion, criterion_group, criterion_main};

use cagd_testkit::bench::median_ns_of;

const PAIRS: [(usize, usize); 9] = [
    (4, 3),
    (5, 4),
    (10, 5),
    (15, 10),
    (20, 10),
    (30, 15),
    (64, 63),
    (64, 32),
    (64, 10),
];

fn methods() -> Vec<Method> {
    vec![
        Method::L2 { r: 0, p: 0 },
        Method::GeneralizedInverse,
        Method::L2 { r: 1, p: 1 },
        Method::ConstrainedChebyshev { r: 0, p: 0 },
        Method::BogackiWeinsteinXu,
        Method::Forrest,
        Method::PieglTiller,
        Method::Farin,
        Method::Eck,
        Method::Perturb,
        Method::GeneralizedInverseEnds,
    ]
}

fn print_table() {
    let exact64 = std::env::var("CAGD_BENCH_EXACT64").is_ok_and(|v| v == "1");
    println!("first-call construction, µs (fast route [route] / exact route):");
    for method in methods() {
        let mut line = format!("{:<28}", format!("{method:?}"));
        for (n, m) in PAIRS {
            if method.check(n, m).is_err() {
                continue;
            }
            let Ok(op) = build_operator(method, n, m, false) else {
                continue;
            };
            let route = format!("{:?}", op.route());
            let runs = if op.route() == OperatorRoute::Exact {
                1
            } else {
                9
            };
            let fast = median_ns_of(runs, || {
                black_box(build_operator(black_box(method), n, m, false).ok());
            }) / 1e3;
            let exact = if n <= 30 || exact64 {
                let t = Instant::now();
                black_box(build_operator(method, n, m, true).ok());
                format!("{:.0}", t.elapsed().as_secs_f64() * 1e6)
            } else {
                "-".to_string()
            };
            line += &format!(" ({n},{m}) {fast:.1} [{route}] / {exact};");
        }
        println!("{line}");
    }
}

fn bench(c: &mut Criterion) {
    print_table();
    let mut g = c.benchmark_group("operator_build_l2_c0");
    for (n, m) in &PAIRS[..6] {
        g.bench_function(format!("{n}->{m}"), |b| {
            b.iter(|| build_operator(Method::L2 { r: 0, p: 0 }, black_box(*n), *m, false))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
