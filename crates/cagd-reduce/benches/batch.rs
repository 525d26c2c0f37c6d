//! Batch reduction throughput: 100 000 random 3-D curves through [`reduce_batch`] for
//! several `(n, m)`, compared with a `memcpy` of the same input + output bytes.
//!
//! Besides criterion's own report, prints `ns/curve` and the ratio to the copy (median of
//! 15 runs each), so that results are comparable across noisy machines.

use std::hint::black_box;

use cagd_reduce::{Method, operator, reduce_batch};
use criterion::{Criterion, criterion_group, criterion_main};

use cagd_testkit::bench::{median_ns, memcpy_ns, random_input};

const N_CURVES: usize = 100_000;
const DIM: usize = 3;
const PAIRS: [(usize, usize); 5] = [(5, 4), (10, 5), (15, 10), (20, 10), (30, 15)];

fn bench(c: &mut Criterion) {
    for (n, m) in PAIRS {
        let op = operator(Method::GeneralizedInverse, n, m).expect("operator");
        let input = random_input(N_CURVES * (n + 1) * DIM, 0);
        let mut output = vec![0.0; N_CURVES * (m + 1) * DIM];
        let mut copy_in = vec![0.0; input.len()];
        let mut copy_out = vec![0.0; output.len()];
        let mut group = c.benchmark_group(format!("batch_n{n}_m{m}"));
        group.sample_size(10);
        group.bench_function("reduce_batch", |b| {
            b.iter(|| reduce_batch(&op, black_box(&input), DIM, &mut output).expect("batch"))
        });
        group.bench_function("memcpy_in_out", |b| {
            b.iter(|| {
                copy_in.copy_from_slice(black_box(&input));
                copy_out.copy_from_slice(black_box(&output));
            })
        });
        group.finish();
        let t_red = median_ns(|| {
            reduce_batch(&op, black_box(&input), DIM, &mut output).expect("batch");
        });
        let t_cpy = memcpy_ns(&input, &output);
        let per = N_CURVES as f64;
        println!(
            "(n, m) = ({n:2}, {m:2}): reduce_batch {:7.1} ns/curve, memcpy {:6.1} ns/curve, ratio {:5.2}",
            t_red / per,
            t_cpy / per,
            t_red / t_cpy
        );
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
