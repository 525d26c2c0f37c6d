//! NURBS → rational Bézier pieces and back: a clamped 1 000-span 3-D NURBS curve of degree
//! 3 and of degree 7 (uniform simple knots, random points of size ~10, weights in
//! [0.5, 2]) through [`to_bezier_pieces_into`] (Böhm insertion in place, buffers reused)
//! and [`pieces_to_nurbs`] (continuity decided at each joint by knot removal, control
//! points by blossoms, certified by re-extraction), with cagd-core's
//! `BSplineCurve::to_beziers` (a blossom per Bézier point) for comparison.
//!
//! Besides criterion's report, prints ns per span and the ratio to a plain copy of the same
//! bytes (the curve's knots, points and weights and the pieces' breaks, points and
//! weights). Anchors measured on this machine (issue 16): OCCT 7.6.3
//! `GeomConvert_BSplineCurveToBezierCurve` 325 / 560 ns per span (degree 3 / 7),
//! `Convert_CompBezierCurvesToBSplineCurve` 330 / 682.
//!
//! The way back, pieces → NURBS, in instructions per span (callgrind on
//! `examples/pieces_to_nurbs_count.rs`, which merges this bench's curve 10 times; stable on
//! a loaded machine): 9180 → 6333 → 4137 at degree 7 and 3369 → 2686 → 1772 at degree 3
//! (the merge kernels per point width; then issue 16's last goal: the joint decision in
//! place, blossoms without the levels of the span's own ends, fixed-width point
//! operations, the tolerance scale without a dependent `max` chain, argument classes
//! counted rather than binary-searched). This bench's median ns per span, the binaries of
//! e919503 and of the change run alternately three times on the loaded 2-core machine
//! (load average 10-13): degree 3 166-170 → 109-113 (38-39x → 26x a copy), degree 7
//! 423-431 → 263-280 (52-55x → 37x a copy), under half of OCCT's 330 / 682. (Criterion's
//! means under that load are 2-3x these medians for both binaries: preemption.)

use cagd_testkit::bench as common;

use std::hint::black_box;

use cagd_convert::{BezierPieces, pieces_to_nurbs, to_bezier_pieces, to_bezier_pieces_into};
use cagd_core::BSplineCurve;
use criterion::{Criterion, criterion_group, criterion_main};

const SPANS: usize = 1000;

fn curve(p: usize) -> BSplineCurve {
    let n = SPANS + p;
    let mut knots = vec![0.0; p + 1];
    knots.extend((1..SPANS).map(|i| i as f64));
    knots.extend(std::iter::repeat_n(SPANS as f64, p + 1));
    let pts: Vec<f64> = common::random_input(3 * n, p as u64)
        .iter()
        .map(|x| 10.0 * x)
        .collect();
    let w: Vec<f64> = common::random_input(n, 100 + p as u64)
        .iter()
        .map(|x| 1.25 + 0.75 * x)
        .collect();
    BSplineCurve::new_rational(p, knots, pts, w, 3).expect("valid curve")
}

fn curve_bytes(c: &BSplineCurve) -> Vec<f64> {
    let mut v = c.knots().to_vec();
    v.extend_from_slice(c.points());
    v.extend_from_slice(c.weights().unwrap_or(&[]));
    v
}

fn pieces_bytes(b: &BezierPieces) -> Vec<f64> {
    let mut v = b.breaks().to_vec();
    v.extend_from_slice(b.points());
    v.extend_from_slice(b.weights().unwrap_or(&[]));
    v
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("nurbs_bezier");
    g.sample_size(20);
    for p in [3, 7] {
        let curve = curve(p);
        let pieces = to_bezier_pieces(&curve).expect("pieces");
        let copy = common::memcpy_ns(&curve_bytes(&curve), &pieces_bytes(&pieces));
        let mut out = BezierPieces::default();
        let fwd = common::median_ns_of(31, || {
            to_bezier_pieces_into(black_box(&curve), &mut out).expect("pieces");
            black_box(&out);
        });
        let back = common::median_ns_of(31, || {
            black_box(pieces_to_nurbs(black_box(&pieces), None).expect("merge"));
        });
        let core = common::median_ns_of(31, || {
            black_box(curve.to_beziers().expect("pieces"));
        });
        let r = pieces_to_nurbs(&pieces, None).expect("merge");
        let same = r.curve.knots() == curve.knots();
        let span = SPANS as f64;
        println!(
            "degree {p}: to pieces {:7.1} ns/span ({:5.1}x a copy), back {:7.1} ns/span \
             ({:5.1}x a copy; same knots: {same}, bound {:.1e}); cagd-core to_beziers {:7.1} \
             ns/span; copy {:5.1} ns/span",
            fwd / span,
            fwd / copy,
            back / span,
            back / copy,
            r.bound,
            core / span,
            copy / span,
        );
        g.bench_function(format!("to_pieces_degree_{p}_1000_spans"), |b| {
            b.iter(|| to_bezier_pieces_into(black_box(&curve), &mut out).expect("pieces"))
        });
        g.bench_function(format!("to_nurbs_degree_{p}_1000_spans"), |b| {
            b.iter(|| pieces_to_nurbs(black_box(&pieces), None).expect("merge"))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
