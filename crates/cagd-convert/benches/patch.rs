//! Cost of the patch conversions of SPEC-convert §15.4–15.7 at degrees 3, 6 and 10 (3-D,
//! polynomial): triangle → degenerate rectangle, triangle → three rectangles, rectangle →
//! two triangles, split along a line (trapezoids; corner cut), split along a quadratic curve.
//!
//! Besides criterion's report, prints `ns/conversion` (median of 15 runs over a batch) and
//! its ratio to a plain copy of the output points (the bytes the conversion writes).

use std::hint::black_box;

use cagd_testkit::bench::{median_ns, random_input};

use cagd_convert::{
    PatchPiece, PatchSurface, TensorSurface, TriSplitPoints, TriSurface,
    rect_to_two_triangle_pieces, split_along_curve, split_along_line, triangle_to_degenerate_rect,
    triangle_to_three_rects,
};
use cagd_core::tri_count;
use criterion::{Criterion, criterion_group, criterion_main};

const DIM: usize = 3;

/// Median time of copying `len` doubles into a fresh buffer.
fn copy_ns(len: usize) -> f64 {
    let src = vec![1.0; len];
    let mut dst = vec![0.0; len];
    median_ns(|| {
        dst.copy_from_slice(black_box(&src));
        black_box(&dst);
    })
}

/// Number of output doubles (points and weights) of a list of pieces.
fn out_len(pieces: &[PatchPiece]) -> usize {
    pieces
        .iter()
        .map(|p| match &p.surface {
            PatchSurface::Tensor(t) => t.net().points().len() + t.weights().map_or(0, <[f64]>::len),
            PatchSurface::Tri(t) => t.net().points().len() + t.weights().map_or(0, <[f64]>::len),
        })
        .sum()
}

type Op = fn(&TriSurface, &TensorSurface) -> Vec<PatchPiece>;

fn bench(c: &mut Criterion) {
    let ops: [(&str, Op); 6] = [
        ("tri->degenerate rect", |t, _| {
            vec![triangle_to_degenerate_rect(t, t.degree()).expect("15.4")]
        }),
        ("tri->3 rects", |t, _| {
            triangle_to_three_rects(t, TriSplitPoints::default())
                .expect("15.5")
                .to_vec()
        }),
        ("rect->2 tris", |_, p| {
            rect_to_two_triangle_pieces(p).expect("15.6.3")
        }),
        ("rect split line", |_, p| {
            split_along_line(p, 0.3, 0.3).expect("15.6.1")
        }),
        ("rect split corner", |_, p| {
            split_along_line(p, -1.5, 0.6).expect("15.6.2")
        }),
        ("rect split quad curve", |_, p| {
            split_along_curve(p, &[0.3, 0.9, 0.5]).expect("15.7")
        }),
    ];
    let mut lines = Vec::new();
    for n in [3usize, 6, 10] {
        let batch = if n == 10 { 20 } else { 200 };
        let tris: Vec<TriSurface> = (0..batch)
            .map(|k| {
                TriSurface::new(random_input(tri_count(n) * DIM, k as u64), n, DIM, None)
                    .expect("tri")
            })
            .collect();
        let rects: Vec<TensorSurface> = (0..batch)
            .map(|k| {
                TensorSurface::new(
                    random_input((n + 1) * (n + 1) * DIM, k as u64),
                    n,
                    n,
                    DIM,
                    None,
                )
                .expect("rect")
            })
            .collect();
        for (name, op) in ops {
            let run = || {
                for (t, p) in tris.iter().zip(&rects) {
                    black_box(op(black_box(t), black_box(p)));
                }
            };
            let label = format!("{name} n={n}");
            c.bench_function(&label, |b| b.iter(run));
            let ns = median_ns(run) / batch as f64;
            let len = out_len(&op(&tris[0], &rects[0]));
            lines.push(format!(
                "{label:32} {ns:12.0} ns/conversion ({:.0}x a copy of the {len} output doubles)",
                ns / copy_ns(len)
            ));
        }
    }
    for l in lines {
        println!("{l}");
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench
}
criterion_main!(benches);
