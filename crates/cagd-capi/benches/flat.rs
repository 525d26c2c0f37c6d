//! The handle-free C entry points against the handle API, and the batch calls on 1 and 2
//! threads (issue 17). Besides criterion's report, prints the median (15 runs) per call or
//! per curve and its ratio to a plain copy of the same input and output bytes
//! (measured interleaved with the variants), so that figures compare across machines.
//!
//! Run: `cargo bench -p cagd-capi --bench flat -- --warm-up-time 1 --measurement-time 3`.
//!
//! - single curve, 3-D, L2 with interpolated ends (`cagd_reduce_options_init`'s default),
//!   5 -> 4 and 10 -> 5: the handle call (`cagd_curve_new`, `cagd_curve_reduce`,
//!   `cagd_curve_points`, `cagd_report_bound`, two frees), `cagd_bezier_reduce` with a
//!   report (the same work, certified bound included, no handles), and without one (points
//!   only);
//! - batches of 100 000 random 3-D curves, both layouts, `n_threads` 1 and 2:
//!   `cagd_bezier_reduce_batch` 10 -> 5 and `cagd_bezier_elevate_batch` 5 -> 8.

//!
//! Figures of the last run (the six degree pairs against the GEMM floor and a copy, and
//! the lines above): `crates/cagd-reduce/benches/README.md`, section "The flat C batch".
//! The handle and the flat call with a report cost the same: both are the certified bound
//! (its cost is cagd-reduce's, issue 17's per-curve work). Without a report the flat call
//! is the reduction alone, several times faster than the handle route.

#![allow(unsafe_code, reason = "the benchmark calls the C ABI")]

use std::hint::black_box;
use std::ptr::{null, null_mut};

use cagd_capi::*;
use cagd_testkit::bench::{gemm_floor, interleaved_ns, random_input};
use criterion::{Criterion, criterion_group, criterion_main};

const DIM: usize = 3;
/// Calls per timed run of the single-curve benchmarks (a call is far below the timer's
/// resolution).
const REPS: usize = 2000;
const N_CURVES: usize = 100_000;

fn options(target: usize) -> CagdReduceOptions {
    let mut o = CagdReduceOptions::default();
    // SAFETY: a valid, writable struct.
    assert_eq!(unsafe { cagd_reduce_options_init(&mut o) }, CagdStatus::OK);
    o.target = target;
    o
}

/// The handle route: create, reduce, read back points and bound, free.
fn handle_call(pts: &[f64], o: &CagdReduceOptions, out: &mut [f64]) -> f64 {
    let (mut c, mut q, mut rep) = (null_mut(), null_mut(), null_mut());
    let (mut needed, mut bound) = (0, 0.0);
    // SAFETY: valid pointers of the documented sizes; every handle is freed once.
    unsafe {
        assert_eq!(
            cagd_curve_new(pts.as_ptr(), pts.len() / DIM, DIM, &mut c),
            CagdStatus::OK
        );
        assert_eq!(cagd_curve_reduce(c, o, &mut q, &mut rep), CagdStatus::OK);
        cagd_curve_points(q, out.as_mut_ptr(), out.len(), &mut needed);
        cagd_report_bound(rep, &mut bound);
        cagd_report_free(rep);
        cagd_curve_free(q);
        cagd_curve_free(c);
    }
    bound
}

/// The flat route, with or without the report.
fn flat_call(pts: &[f64], o: &CagdReduceOptions, out: &mut [f64], report: bool) -> f64 {
    let mut r = CagdBezierReport {
        struct_size: size_of::<CagdBezierReport>(),
        method: 0,
        space: 0,
        degree_from: 0,
        degree_to: 0,
        bound: 0.0,
        max_error: 0.0,
        homogeneous_bound: 0.0,
    };
    let rp = if report { &raw mut r } else { null_mut() };
    let mut needed = 0;
    // SAFETY: valid pointers of the documented sizes.
    let s = unsafe {
        cagd_bezier_reduce(
            pts.as_ptr(),
            pts.len() / DIM,
            DIM,
            null(),
            o,
            out.as_mut_ptr(),
            out.len(),
            &mut needed,
            null_mut(),
            0,
            rp,
        )
    };
    assert_eq!(s, CagdStatus::OK);
    r.bound
}

fn single(c: &mut Criterion) {
    for (n, m) in [(5usize, 4usize), (10, 5)] {
        let pts = random_input((n + 1) * DIM, 1);
        let o = options(m);
        let mut out = vec![0.0; (m + 1) * DIM];
        let mut group = c.benchmark_group(format!("single_n{n}_m{m}"));
        group.bench_function("handle", |b| {
            b.iter(|| handle_call(black_box(&pts), &o, &mut out))
        });
        group.bench_function("flat_report", |b| {
            b.iter(|| flat_call(black_box(&pts), &o, &mut out, true))
        });
        group.bench_function("flat_points_only", |b| {
            b.iter(|| flat_call(black_box(&pts), &o, &mut out, false))
        });
        group.finish();
        let (mut o1, mut o2, mut o3) = (out.clone(), out.clone(), out.clone());
        let mut scratch = [0.0; 64];
        let t = interleaved_ns(
            31,
            &mut [
                &mut || {
                    for _ in 0..REPS {
                        black_box(handle_call(black_box(&pts), &o, &mut o1));
                    }
                },
                &mut || {
                    for _ in 0..REPS {
                        black_box(flat_call(black_box(&pts), &o, &mut o2, true));
                    }
                },
                &mut || {
                    for _ in 0..REPS {
                        black_box(flat_call(black_box(&pts), &o, &mut o3, false));
                    }
                },
                &mut || {
                    for _ in 0..REPS {
                        let k = pts.len();
                        scratch[..k].copy_from_slice(black_box(&pts));
                        scratch[k..k + out.len()].copy_from_slice(black_box(&out));
                        black_box(&scratch);
                    }
                },
            ],
        );
        let [t_handle, t_flat, t_points, t_copy] =
            [t[0], t[1], t[2], t[3]].map(|x| x / REPS as f64);
        println!(
            "single ({n:2}, {m:2}): handle {t_handle:8.1} ns/call | flat+report {t_flat:8.1} \
             ns/call ({:.2}x handle) | flat points only {t_points:7.1} ns/call ({:.3}x handle, \
             {:.1}x copy) | copy {t_copy:5.1} ns",
            t_flat / t_handle,
            t_points / t_handle,
            t_points / t_copy
        );
    }
}

/// One batch call (reduce with `opts`, or elevate by `r`).
fn batch_call(
    input: &[f64],
    n: usize,
    layout: CagdBatchLayout,
    what: Result<&CagdReduceOptions, usize>,
    threads: usize,
    out: &mut [f64],
) {
    let mut needed = 0;
    let (p, k, l) = (input.as_ptr(), N_CURVES, layout as i32);
    let (o, cap) = (out.as_mut_ptr(), out.len());
    // SAFETY: valid pointers of the documented sizes.
    let s = unsafe {
        match what {
            Ok(opts) => {
                cagd_bezier_reduce_batch(p, k, n, DIM, l, opts, threads, o, cap, &mut needed)
            }
            Err(r) => cagd_bezier_elevate_batch(p, k, n, DIM, l, r, threads, o, cap, &mut needed),
        }
    };
    assert_eq!(s, CagdStatus::OK);
}

/// `cagd_curve_reduce_batch` (curve-major, the operator cache) on `N_CURVES` curves.
fn curve_batch_call(input: &[f64], n: usize, opts: &CagdReduceOptions, out: &mut [f64]) {
    let mut needed = 0;
    // SAFETY: valid pointers of the documented sizes.
    let s = unsafe {
        cagd_curve_reduce_batch(
            input.as_ptr(),
            N_CURVES,
            n,
            DIM,
            opts,
            out.as_mut_ptr(),
            out.len(),
            &mut needed,
        )
    };
    assert_eq!(s, CagdStatus::OK);
}

fn batches(c: &mut Criterion) {
    let o = options(5);
    let cases: [(&str, usize, usize, Result<&CagdReduceOptions, usize>); 2] = [
        ("reduce_10_5", 10, 6, Ok(&o)),
        ("elevate_5_8", 5, 9, Err(3)),
    ];
    for (name, n, m1, what) in cases {
        let input = random_input(N_CURVES * (n + 1) * DIM, 2);
        let mut out = vec![0.0; N_CURVES * m1 * DIM];
        let mut group = c.benchmark_group(format!("batch_{name}"));
        group.sample_size(10);
        for layout in [
            CagdBatchLayout::LAYOUT_CURVE_MAJOR,
            CagdBatchLayout::LAYOUT_POINT_MAJOR,
        ] {
            for threads in [1usize, 2] {
                let label = format!("{layout:?}_threads{threads}");
                group.bench_function(&label, |b| {
                    b.iter(|| batch_call(black_box(&input), n, layout, what, threads, &mut out))
                });
            }
            // 1 thread, 2 threads and the copy, interleaved.
            let (mut out2, mut copy_in, mut copy_out, zeros) = (
                out.clone(),
                vec![0.0; input.len()],
                vec![0.0; out.len()],
                vec![0.0; out.len()],
            );
            let t = interleaved_ns(
                15,
                &mut [
                    &mut || batch_call(black_box(&input), n, layout, what, 1, &mut out),
                    &mut || batch_call(black_box(&input), n, layout, what, 2, &mut out2),
                    &mut || {
                        copy_in.copy_from_slice(black_box(&input));
                        copy_out.copy_from_slice(black_box(&zeros));
                        black_box((&copy_in, &copy_out));
                    },
                ],
            );
            let [t1, t2, tc] = [t[0], t[1], t[2]].map(|x| x / N_CURVES as f64);
            println!(
                "batch {name} {layout:?}: 1 thread {t1:6.2} ns/curve ({:.2}x copy), 2 threads \
                 {t2:6.2} ns/curve ({:.2}x copy), speed-up {:.2}; copy {tc:.2} ns/curve",
                t1 / tc,
                t2 / tc,
                t1 / t2
            );
        }
        group.finish();
    }
}

/// The six degree pairs of issue 17 and OCCT's times for them are cagd-reduce's; here the
/// batch reductions of `cagd_bezier_reduce_batch` (1 thread) in both layouts against the
/// GEMM floor: the same operator applied to the same curves laid out point-major by one
/// `matrixmultiply::dgemm` call (the kernel both layouts use).
const PAIRS: [(usize, usize); 6] = [(4, 3), (5, 4), (10, 5), (15, 10), (20, 10), (30, 15)];

fn reduce_pairs(c: &mut Criterion) {
    for (n, m) in PAIRS {
        let o = options(m);
        let op = cagd_reduce::operator(cagd_reduce::Method::L2 { r: 0, p: 0 }, n, m).unwrap();
        let (n1, m1) = (n + 1, m + 1);
        let input = random_input(N_CURVES * n1 * DIM, 3);
        let mut pm = vec![0.0; input.len()];
        for cc in 0..N_CURVES {
            for j in 0..n1 {
                for d in 0..DIM {
                    pm[(j * N_CURVES + cc) * DIM + d] = input[(cc * n1 + j) * DIM + d];
                }
            }
        }
        let mut out = vec![0.0; N_CURVES * m1 * DIM];
        let (mut out2, mut out3) = (out.clone(), out.clone());
        let pml = CagdBatchLayout::LAYOUT_POINT_MAJOR;
        let cml = CagdBatchLayout::LAYOUT_CURVE_MAJOR;
        let mut group = c.benchmark_group(format!("reduce_batch_n{n}_m{m}"));
        group.sample_size(10);
        group.bench_function("point_major", |b| {
            b.iter(|| batch_call(black_box(&pm), n, pml, Ok(&o), 1, &mut out))
        });
        group.finish();
        let (mut copy_in, mut copy_out, zeros) = (
            vec![0.0; input.len()],
            vec![0.0; out.len()],
            vec![0.0; out.len()],
        );
        let mut out4 = out.clone();
        let t = interleaved_ns(
            15,
            &mut [
                &mut || batch_call(black_box(&pm), n, pml, Ok(&o), 1, &mut out),
                &mut || batch_call(black_box(&input), n, cml, Ok(&o), 1, &mut out2),
                &mut || curve_batch_call(black_box(&input), n, &o, &mut out4),
                &mut || gemm_floor(op.matrix(), n1, m1, black_box(&pm), &mut out3),
                &mut || {
                    copy_in.copy_from_slice(black_box(&input));
                    copy_out.copy_from_slice(black_box(&zeros));
                    black_box((&copy_in, &copy_out));
                },
            ],
        );
        let [tp, tcm, tcr, tg, tc] = [t[0], t[1], t[2], t[3], t[4]].map(|x| x / N_CURVES as f64);
        println!(
            "reduce_batch ({n:2},{m:2}) 1 thread: cagd_bezier_reduce_batch point-major {tp:6.2} \
             ns/curve ({:.2}x GEMM floor, {:.2}x copy), curve-major {tcm:6.2} ns/curve ({:.2}x \
             floor); cagd_curve_reduce_batch {tcr:6.2} ns/curve ({:.2}x floor, {:.2}x copy); \
             GEMM floor {tg:6.2} ns/curve ({:.2}x copy), copy {tc:.2} ns/curve",
            tp / tg,
            tp / tc,
            tcm / tg,
            tcr / tg,
            tcr / tc,
            tg / tc
        );
    }
}

criterion_group!(benches, single, batches, reduce_pairs);
criterion_main!(benches);
