//! Batch and per-curve reduction speed for the six degree pairs of issue 17, on random 3-D
//! curves, with the floors this crate can measure itself:
//!
//! - `copy`: a `memcpy` of the same input + output bytes;
//! - `gemm floor`: the same kernel crate (nalgebra's `gemm`, i.e. `matrixmultiply` for
//!   sides above 5) applying the same operator to the same bytes laid out point-major
//!   (`(n+1) x (curves dim)`, one GEMM), the layout an external BLAS floor uses; for
//!   `(4,3)` / `(5,4)` nalgebra has no kernel route for a 4- or 5-row operator, so the floor
//!   there is also given as the Kronecker-expanded single GEMM (`kron floor`, `dim` times
//!   the flops, contiguous rows), and the ratio is taken to the faster of the two.
//!
//! Prints, per pair: `reduce_batch` ns/curve and its ratios; `reduce_batch_with_bounds`
//! at the fast and tight levels; and one curve through `reduce_with` with no bound, the
//! fast and the tight bound (ns per call, the curve cycling through 1000 inputs). Medians
//! of 15 runs (`cagd_testkit::bench`); criterion's own report covers `reduce_batch` only,
//! with short times (run with `-- --warm-up-time 1 --measurement-time 3`).

use std::hint::black_box;
use std::time::Duration;

use cagd_core::BezierCurve;
use cagd_reduce::{
    BoundLevel, Method, ReduceOptions, operator, reduce_batch, reduce_batch_with_bounds,
    reduce_with,
};
use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::{DMatrixView, DMatrixViewMut};

use cagd_testkit::bench::{median_ns, memcpy_ns, random_input};

const N_CURVES: usize = 100_000;
const DIM: usize = 3;
const PAIRS: [(usize, usize); 6] = [(4, 3), (5, 4), (10, 5), (15, 10), (20, 10), (30, 15)];
/// OCCT `GeomConvert_ApproxCurve` per curve (µs), issue 17's measurement, same pairs.
const OCCT_US: [f64; 6] = [5.8, 6.6, 7.0, 10.4, 10.5, 29.2];
const METHOD: Method = Method::L2 { r: 0, p: 0 };

/// The point-major floor: `Q = A P` with `P` `(n+1) x (curves dim)` contiguous.
fn gemm_floor(a: &[f64], n1: usize, m1: usize, p: &[f64], q: &mut [f64]) {
    let cols = p.len() / n1;
    let a = DMatrixView::from_slice_with_strides(a, m1, n1, n1, 1);
    let p = DMatrixView::from_slice_with_strides(p, n1, cols, cols, 1);
    let mut q = DMatrixViewMut::from_slice_with_strides_mut(q, m1, cols, cols, 1);
    q.gemm(1.0, &a, &p, 0.0);
}

/// The Kronecker floor: `Y = X K` with `X` curves x `(n+1) dim`, `K = (A ⊗ I)^T`.
fn kron_floor(k: &[f64], ci: usize, ro: usize, x: &[f64], y: &mut [f64]) {
    let curves = x.len() / ci;
    let k = DMatrixView::from_slice_with_strides(k, ci, ro, ro, 1);
    let x = DMatrixView::from_slice_with_strides(x, curves, ci, ci, 1);
    let mut y = DMatrixViewMut::from_slice_with_strides_mut(y, curves, ro, ro, 1);
    y.gemm(1.0, &x, &k, 0.0);
}

fn kronecker(a: &[f64], n1: usize, m1: usize) -> Vec<f64> {
    let ro = m1 * DIM;
    let mut k = vec![0.0; n1 * DIM * ro];
    for i in 0..m1 {
        for j in 0..n1 {
            for d in 0..DIM {
                k[(j * DIM + d) * ro + i * DIM + d] = a[i * n1 + j];
            }
        }
    }
    k
}

fn bench(c: &mut Criterion) {
    println!(
        "reduce_batch, {N_CURVES} random 3-D curves, {METHOD:?}; ratios to a copy of the same bytes and to the GEMM floor"
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

        let per = N_CURVES as f64;
        let t_red = median_ns(|| {
            reduce_batch(&op, black_box(&input), DIM, &mut output).expect("batch");
        }) / per;
        let t_fast = median_ns(|| {
            reduce_batch_with_bounds(
                &op,
                black_box(&input),
                DIM,
                &mut output,
                &mut bounds,
                BoundLevel::Fast,
            )
            .expect("batch");
        }) / per;
        let t_tight = median_ns(|| {
            reduce_batch_with_bounds(
                &op,
                black_box(&input),
                DIM,
                &mut output,
                &mut bounds,
                BoundLevel::Tight,
            )
            .expect("batch");
        }) / per;
        let t_cpy = memcpy_ns(&input, &output) / per;
        // Floors on the same bytes (the point-major copy of the input is made once, outside
        // the timing).
        let mut pm = vec![0.0; input.len()];
        for cc in 0..N_CURVES {
            for j in 0..n1 {
                for d in 0..DIM {
                    pm[j * N_CURVES * DIM + cc * DIM + d] = input[(cc * n1 + j) * DIM + d];
                }
            }
        }
        let mut qpm = vec![0.0; output.len()];
        let t_gemm = if m1 >= 6 {
            median_ns(|| gemm_floor(op.matrix(), n1, m1, black_box(&pm), &mut qpm)) / per
        } else {
            f64::INFINITY
        };
        let kron = kronecker(op.matrix(), n1, m1);
        let t_kron =
            median_ns(|| kron_floor(&kron, n1 * DIM, m1 * DIM, black_box(&input), &mut output))
                / per;
        let floor = t_gemm.min(t_kron);
        println!(
            "({n:2},{m:2}) batch {t_red:6.1} ns/curve = {:4.2}x copy ({t_cpy:5.1} ns), {:4.2}x GEMM floor \
             (point-major {t_gemm:6.1} ns, kron {t_kron:6.1} ns); with fast bounds {t_fast:6.1} ns \
             ({:4.2}x floor), tight bounds {t_tight:7.1} ns ({:4.2}x floor)",
            t_red / t_cpy,
            t_red / floor,
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
