//! Batch and per-curve reduction speed for the six degree pairs of issue 17, on random 3-D
//! curves, with the floors this crate can measure itself:
//!
//! - `copy`: a `memcpy` of the same input + output bytes;
//! - `GEMM floor`: one `matrixmultiply::dgemm` (the kernel crate under nalgebra's `gemm`)
//!   applying the same operator to the same curves laid out point-major (`(n+1) x (curves
//!   dim)`, contiguous rows), the layout an external BLAS floor uses.
//!
//! Prints, per pair: `reduce_batch` ns/curve and its ratios; `reduce_batch_with_bounds`
//! at the fast and tight levels; and one curve through `reduce_with` with no bound, the
//! fast and the tight bound (ns per call, the curve cycling through 1000 inputs). The batch
//! variants, the copy and the floor are timed in 15 interleaved rounds (medians), so that
//! the load of a shared machine moves them alike; criterion's own report covers
//! `reduce_batch` only, with short times (run with `-- --warm-up-time 1
//! --measurement-time 3`).

use std::hint::black_box;
use std::time::Duration;

use cagd_core::BezierCurve;
use cagd_reduce::{
    BoundLevel, Method, ReduceOptions, operator, reduce_batch, reduce_batch_with_bounds,
    reduce_with,
};
use criterion::{Criterion, criterion_group, criterion_main};

use cagd_testkit::bench::{gemm_floor, interleaved_ns, median_ns, random_input};

const N_CURVES: usize = 100_000;
const DIM: usize = 3;
const PAIRS: [(usize, usize); 6] = [(4, 3), (5, 4), (10, 5), (15, 10), (20, 10), (30, 15)];
/// OCCT `GeomConvert_ApproxCurve` per curve (µs), issue 17's measurement, same pairs.
const OCCT_US: [f64; 6] = [5.8, 6.6, 7.0, 10.4, 10.5, 29.2];
const METHOD: Method = Method::L2 { r: 0, p: 0 };

fn bench(c: &mut Criterion) {
    println!(
        "reduce_batch, {N_CURVES} random 3-D curves, {METHOD:?}; ratios to a copy of the same \
         bytes and to the point-major GEMM floor (matrixmultiply::dgemm), 15 interleaved rounds"
    );
    for (idx, (n, m)) in PAIRS.into_iter().enumerate() {
        let (n1, m1) = (n + 1, m + 1);
        let op = operator(METHOD, n, m).expect("operator");
        let input = random_input(N_CURVES * n1 * DIM, 0);
        let mut output = vec![0.0; N_CURVES * m1 * DIM];
        let mut bounds = vec![0.0; N_CURVES];
        let mut group = c.benchmark_group(format!("batch_n{n}_m{m}"));
        group.sample_size(10);
        group.warm_up_time(Duration::from_millis(500));
        group.measurement_time(Duration::from_secs(1));
        group.bench_function("reduce_batch", |b| {
            b.iter(|| reduce_batch(&op, black_box(&input), DIM, &mut output).expect("batch"))
        });
        group.finish();

        // The point-major copy of the input for the floor is made once, outside the timing.
        let mut pm = vec![0.0; input.len()];
        for cc in 0..N_CURVES {
            for j in 0..n1 {
                for d in 0..DIM {
                    pm[j * N_CURVES * DIM + cc * DIM + d] = input[(cc * n1 + j) * DIM + d];
                }
            }
        }
        let (mut out_f, mut out_t, mut qpm) = (output.clone(), output.clone(), output.clone());
        let (mut bounds_t, mut copy_in, mut copy_out) = (
            bounds.clone(),
            vec![0.0; input.len()],
            vec![0.0; output.len()],
        );
        let zeros = vec![0.0; output.len()];
        let t = interleaved_ns(
            15,
            &mut [
                &mut || reduce_batch(&op, black_box(&input), DIM, &mut output).expect("batch"),
                &mut || {
                    reduce_batch_with_bounds(
                        &op,
                        black_box(&input),
                        DIM,
                        &mut out_f,
                        &mut bounds,
                        BoundLevel::Fast,
                    )
                    .expect("batch")
                },
                &mut || {
                    reduce_batch_with_bounds(
                        &op,
                        black_box(&input),
                        DIM,
                        &mut out_t,
                        &mut bounds_t,
                        BoundLevel::Tight,
                    )
                    .expect("batch")
                },
                &mut || gemm_floor(op.matrix(), n1, m1, black_box(&pm), &mut qpm),
                &mut || {
                    copy_in.copy_from_slice(black_box(&input));
                    copy_out.copy_from_slice(black_box(&zeros));
                    black_box((&copy_in, &copy_out));
                },
            ],
        );
        let [t_red, t_fast, t_tight, floor, t_cpy] =
            [t[0], t[1], t[2], t[3], t[4]].map(|x| x / N_CURVES as f64);
        println!(
            "({n:2},{m:2}) batch {t_red:6.1} ns/curve = {:4.2}x copy ({t_cpy:5.1} ns), {:4.2}x \
             GEMM floor ({floor:6.1} ns, {:4.2}x copy); with fast bounds {t_fast:6.1} ns \
             ({:4.2}x floor), tight bounds {t_tight:7.1} ns ({:4.2}x floor)",
            t_red / t_cpy,
            t_red / floor,
            floor / t_cpy,
            t_fast / floor,
            t_tight / floor,
        );

        // One curve per call, cycling through 1000 different curves.
        let curves: Vec<BezierCurve> = input
            .chunks_exact(n1 * DIM)
            .take(1000)
            .map(|p| BezierCurve::new(p.to_vec(), DIM).expect("curve"))
            .collect();
        let mut line = format!("({n:2},{m:2}) one curve (reduce_with):");
        for (name, level) in [
            ("no bound", BoundLevel::None),
            ("fast", BoundLevel::Fast),
            ("tight", BoundLevel::Tight),
        ] {
            let opts = ReduceOptions {
                bound: level,
                ..ReduceOptions::new(METHOD, m)
            };
            let t = median_ns(|| {
                for cv in &curves {
                    black_box(reduce_with(black_box(cv), &opts).expect("reduce"));
                }
            }) / curves.len() as f64;
            line += &format!(
                " {name} {:6.3} µs ({:4.2}x OCCT)",
                t / 1e3,
                t / 1e3 / OCCT_US[idx]
            );
        }
        println!("{line}");
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
