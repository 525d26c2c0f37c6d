//! Patch reduction cost: a 5 x 5 tensor patch to 3 x 3 (curve operators, and one
//! perturbation step 5 x 5 -> 4 x 4) and a degree-8 triangle to degree 4 (L2, free and
//! boundary-constrained), 3-D, certified bound included, operators cached.
//!
//! Besides criterion's report, prints `ns/patch` (median of 15 runs over 1000 patches) and
//! its ratio to a plain copy of the same input and output points.

use std::hint::black_box;

use cagd_core::{TensorPatch, TriPatch, tri_count};
use cagd_reduce::{
    Method, PatchConstraint, PatchOptions, TensorMethod, TriMethod, TriOptions, reduce_tensor,
    reduce_triangle,
};
use criterion::{Criterion, criterion_group, criterion_main};

use cagd_testkit::bench::{median_ns, memcpy_ns, random_input};

const N_PATCHES: usize = 1000;
const DIM: usize = 3;

fn bench(c: &mut Criterion) {
    let tensors: Vec<TensorPatch> = (0..N_PATCHES)
        .map(|k| TensorPatch::new(random_input(36 * DIM, k as u64), 5, 5, DIM).expect("patch"))
        .collect();
    let tris: Vec<TriPatch> = (0..N_PATCHES)
        .map(|k| TriPatch::new(random_input(tri_count(8) * DIM, k as u64), 8, DIM).expect("tri"))
        .collect();
    let tensor_in: Vec<f64> = tensors.iter().flat_map(|p| p.points().to_vec()).collect();
    let tri_in: Vec<f64> = tris.iter().flat_map(|t| t.points().to_vec()).collect();
    let l2 = Method::L2 { r: 0, p: 0 };
    let tensor_cases = [
        (
            "tensor 5x5->3x3 curves L2(0,0)",
            TensorMethod::Curves { u: l2, v: l2 },
            (3, 3),
        ),
        (
            "tensor 5x5->4x4 perturb",
            TensorMethod::Perturb(PatchConstraint::None),
            (4, 4),
        ),
        (
            "tensor 5x5->4x4 perturb boundary",
            TensorMethod::Perturb(PatchConstraint::Boundary(l2)),
            (4, 4),
        ),
    ];
    let tri_cases = [
        ("tri 8->4 L2", TriMethod::L2(PatchConstraint::None), 4),
        (
            "tri 8->4 L2 boundary",
            TriMethod::L2(PatchConstraint::Boundary(l2)),
            4,
        ),
        ("tri 8->7 perturb", TriMethod::Perturb, 7),
    ];
    let mut lines = Vec::new();
    for (name, method, target) in tensor_cases {
        let opts = PatchOptions::new(method);
        let run = || {
            for p in &tensors {
                black_box(reduce_tensor(black_box(p), target, &opts).expect("reduce"));
            }
        };
        c.bench_function(name, |b| b.iter(run));
        let out_len = N_PATCHES * (target.0 + 1) * (target.1 + 1) * DIM;
        lines.push(report_line(name, median_ns(run), &tensor_in, out_len));
    }
    for (name, method, m) in tri_cases {
        let opts = TriOptions::new(method);
        let run = || {
            for t in &tris {
                black_box(reduce_triangle(black_box(t), m, &opts).expect("reduce"));
            }
        };
        c.bench_function(name, |b| b.iter(run));
        let out_len = N_PATCHES * tri_count(m) * DIM;
        lines.push(report_line(name, median_ns(run), &tri_in, out_len));
    }
    for l in lines {
        println!("{l}");
    }
}

/// `ns/patch` of a run over all patches taking `ns`, and its ratio to copying `input` and
/// `out_len` output doubles.
fn report_line(name: &str, ns: f64, input: &[f64], out_len: usize) -> String {
    let copy = memcpy_ns(input, &vec![0.0; out_len]);
    format!(
        "{name:36} {:9.0} ns/patch ({:.0}x a copy of the points in and out)",
        ns / N_PATCHES as f64,
        ns / copy
    )
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench
}
criterion_main!(benches);
