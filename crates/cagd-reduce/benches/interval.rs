//! Interval-triangle reduction cost (seed 004's LP, SPEC-convert I.2): 3-D random interval
//! triangles (coordinates in [-10, 10], widths in [0, 2)) reduced 4 -> 3, 6 -> 5, 10 -> 5,
//! 15 -> 10 and 20 -> 10 with certification; dense sampling (1 035 points) off and on.
//!
//! Besides criterion's report, prints the median time per reduction over 8 patches, the LP
//! size and how many coordinates needed the coupled LP.

use std::hint::black_box;
use std::time::Instant;

use cagd_core::tri_count;
use cagd_reduce::{IntervalOptions, IntervalTriPatch, reduce_interval_triangle};
use criterion::{Criterion, criterion_group, criterion_main};

const DIM: usize = 3;
const N_PATCHES: usize = 8;

fn patch(n: usize, seed: u64) -> IntervalTriPatch {
    let mut s = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    let mut next = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let len = tri_count(n) * DIM;
    let lo: Vec<f64> = (0..len).map(|_| 20.0 * next() - 10.0).collect();
    let hi = lo.iter().map(|l| l + 2.0 * next()).collect();
    IntervalTriPatch::new(lo, hi, n, DIM).expect("valid patch")
}

/// Median over 5 runs of the time per reduction of all patches, in microseconds.
fn median_us(patches: &[IntervalTriPatch], opts: &IntervalOptions) -> f64 {
    let mut t: Vec<f64> = (0..5)
        .map(|_| {
            let t0 = Instant::now();
            for p in patches {
                black_box(reduce_interval_triangle(black_box(p), opts).expect("reduce"));
            }
            t0.elapsed().as_secs_f64() * 1e6 / patches.len() as f64
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[2]
}

fn bench(c: &mut Criterion) {
    let mut lines = Vec::new();
    for (n, m) in [(4, 3), (6, 5), (10, 5), (15, 10), (20, 10)] {
        let patches: Vec<IntervalTriPatch> =
            (0..N_PATCHES).map(|k| patch(n, k as u64 + 1)).collect();
        let bare = IntervalOptions {
            sample_grid: 0,
            ..IntervalOptions::new(m)
        };
        let sampled = IntervalOptions::new(m);
        let name = format!("interval {n}->{m} 3-D");
        c.bench_function(&name, |b| {
            b.iter(|| black_box(reduce_interval_triangle(black_box(&patches[0]), &bare)))
        });
        let coupled: usize = patches
            .iter()
            .map(|p| {
                let r = reduce_interval_triangle(p, &bare).expect("reduce");
                r.report.coupled.iter().filter(|&&c| c).count()
            })
            .sum();
        lines.push(format!(
            "{name:22} LP {:3} x {:2}: {:9.0} us/reduction certified, {:9.0} us with sampling; \
             coupled {coupled}/{} coordinates",
            tri_count(n),
            tri_count(m),
            median_us(&patches, &bare),
            median_us(&patches, &sampled),
            N_PATCHES * DIM
        ));
    }
    for l in lines {
        println!("{l}");
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(std::time::Duration::from_secs(2));
    targets = bench
}
criterion_main!(benches);
