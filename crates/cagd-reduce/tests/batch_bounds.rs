//! The batch path and its per-curve certified bounds, against independent routes: the
//! reduced points against the per-curve definition, every bound against the error measured
//! by dense sampling plus local maximisation (`max_deviation`) on thousands of random
//! curves per degree pair, with the bound / measured ratios reported.

use cagd_core::BezierCurve;
use cagd_reduce::{
    BoundLevel, Method, ReduceOptions, max_deviation, operator, reduce_batch,
    reduce_batch_with_bounds, reduce_with,
};
use cagd_testkit::bench::random_input;

const PAIRS: [(usize, usize); 6] = [(4, 3), (5, 4), (10, 5), (15, 10), (20, 10), (30, 15)];
const DIM: usize = 3;

/// Ratios bound / measured: (min, mean, max).
fn stats(r: &[f64]) -> (f64, f64, f64) {
    let min = r.iter().copied().fold(f64::INFINITY, f64::min);
    let max = r.iter().copied().fold(0.0, f64::max);
    (min, r.iter().sum::<f64>() / r.len() as f64, max)
}

#[test]
fn batch_bounds_are_true_bounds_on_thousands_of_random_curves() {
    // 1000 curves per pair and method (6000 per method); random coordinates in [-1, 1),
    // one curve in 50 scaled by 1e6 and one by 1e-6 (bounds are relative to the size).
    let curves = 1000;
    for method in [Method::L2 { r: 0, p: 0 }, Method::GeneralizedInverse] {
        for (n, m) in PAIRS {
            let op = operator(method, n, m).unwrap();
            let per_in = (n + 1) * DIM;
            let mut input = random_input(curves * per_in, (n * 100 + m) as u64);
            for (c, curve) in input.chunks_exact_mut(per_in).enumerate() {
                let s = match c % 50 {
                    7 => 1e6,
                    8 => 1e-6,
                    _ => 1.0,
                };
                curve.iter_mut().for_each(|x| *x *= s);
            }
            let mut out = vec![0.0; curves * (m + 1) * DIM];
            let mut fast = vec![0.0; curves];
            let mut tight = vec![0.0; curves];
            reduce_batch_with_bounds(&op, &input, DIM, &mut out, &mut fast, BoundLevel::Fast)
                .unwrap();
            let mut out2 = vec![0.0; out.len()];
            reduce_batch_with_bounds(&op, &input, DIM, &mut out2, &mut tight, BoundLevel::Tight)
                .unwrap();
            assert_eq!(out, out2);
            let (mut rf, mut rt) = (Vec::new(), Vec::new());
            for c in 0..curves {
                let p =
                    BezierCurve::new(input[c * per_in..(c + 1) * per_in].to_vec(), DIM).unwrap();
                let q_pts = out[c * (m + 1) * DIM..(c + 1) * (m + 1) * DIM].to_vec();
                let q = BezierCurve::new(q_pts, DIM).unwrap();
                let measured = max_deviation(&p, &q).unwrap();
                assert!(
                    fast[c] >= measured && tight[c] >= measured,
                    "{method:?} ({n},{m}) curve {c}: fast {} tight {} < measured {measured}",
                    fast[c],
                    tight[c]
                );
                rf.push(fast[c] / measured);
                rt.push(tight[c] / measured);
            }
            let (f, t) = (stats(&rf), stats(&rt));
            println!(
                "{method:?} ({n:2},{m:2}): bound/measured fast min {:.3} mean {:.3} max {:.3}; \
                 tight min {:.4} mean {:.4} max {:.4}",
                f.0, f.1, f.2, t.0, t.1, t.2
            );
            // The levels' promises (secant factors 1.25 and 1.075, plus rounding far below
            // these errors of order 1e-2 relative).
            assert!(
                f.2 <= 1.25 * (1.0 + 1e-9),
                "{method:?} ({n},{m}): fast ratio {}",
                f.2
            );
            assert!(
                t.2 <= 1.075 * (1.0 + 1e-9),
                "{method:?} ({n},{m}): tight ratio {}",
                t.2
            );
        }
    }
}

#[test]
fn batch_equals_the_per_curve_definition_and_the_per_curve_call() {
    for (n, m) in PAIRS {
        for dim in [1, 2, 3, 4, 5] {
            let op = operator(Method::L2 { r: 1, p: 1 }, n, m).unwrap();
            let curves = 257; // several kernel blocks for the small pairs, a ragged end
            let per_in = (n + 1) * dim;
            let input = random_input(curves * per_in, 99);
            let mut out = vec![0.0; curves * (m + 1) * dim];
            reduce_batch(&op, &input, dim, &mut out).unwrap();
            let a = op.matrix();
            let mut bounds = vec![0.0; curves];
            let mut out2 = vec![0.0; out.len()];
            reduce_batch_with_bounds(&op, &input, dim, &mut out2, &mut bounds, BoundLevel::Tight)
                .unwrap();
            assert_eq!(out, out2);
            for c in 0..curves {
                let p = &input[c * per_in..(c + 1) * per_in];
                for i in 0..=m {
                    for k in 0..dim {
                        let want: f64 = (0..=n).map(|j| a[i * (n + 1) + j] * p[j * dim + k]).sum();
                        let got = out[(c * (m + 1) + i) * dim + k];
                        let scale: f64 = (0..=n)
                            .map(|j| (a[i * (n + 1) + j] * p[j * dim + k]).abs())
                            .sum();
                        assert!(
                            (got - want).abs() <= 1e-14 * scale.max(1e-300) * (n as f64 + 1.0),
                            "({n},{m}) dim {dim} curve {c}: {got} vs {want}"
                        );
                    }
                }
            }
            // The per-curve call at the tight level gives a bound of the same quality
            // (its reduced points are the same sums, possibly in another order).
            let curve = BezierCurve::new(input[..per_in].to_vec(), dim).unwrap();
            let opts = ReduceOptions {
                measure: true,
                ..ReduceOptions::new(Method::L2 { r: 1, p: 1 }, m)
            };
            let red = reduce_with(&curve, &opts).unwrap();
            let (b, e) = (
                red.report.error_bound.unwrap(),
                red.report.max_error.unwrap(),
            );
            assert!(e <= b && b <= 1.1 * e, "({n},{m}) dim {dim}: {b} vs {e}");
            assert_eq!(red.report.bound_level, BoundLevel::Tight);
            let none = reduce_with(
                &curve,
                &ReduceOptions {
                    bound: BoundLevel::None,
                    ..opts
                },
            )
            .unwrap();
            assert_eq!(none.report.error_bound, None);
            assert_eq!(none.curve, red.curve);
        }
    }
}

#[test]
fn batch_bound_errors_are_named() {
    let op = operator(Method::L2 { r: 0, p: 0 }, 5, 4).unwrap();
    let input = random_input(2 * 6 * 2, 1);
    let mut out = vec![0.0; 2 * 5 * 2];
    let mut bounds = vec![0.0; 2];
    assert!(matches!(
        reduce_batch_with_bounds(&op, &input, 2, &mut out, &mut bounds[..1], BoundLevel::Fast),
        Err(cagd_core::Error::LengthMismatch { .. })
    ));
    assert!(matches!(
        reduce_batch_with_bounds(&op, &input, 2, &mut out, &mut bounds, BoundLevel::None),
        Err(cagd_core::Error::BadParameter { .. })
    ));
    let mut bad = input.clone();
    bad[13] = f64::NAN;
    assert!(matches!(
        reduce_batch_with_bounds(&op, &bad, 2, &mut out, &mut bounds, BoundLevel::Tight),
        Err(cagd_core::Error::NonFinite {
            index: 6,
            coord: 1,
            ..
        })
    ));
    // Many curves (GEMM route) with one NaN deep inside.
    let op = operator(Method::L2 { r: 0, p: 0 }, 20, 10).unwrap();
    let mut bad = random_input(500 * 21 * 3, 2);
    bad[(321 * 21 + 4) * 3 + 2] = f64::INFINITY;
    let mut out = vec![0.0; 500 * 11 * 3];
    assert!(matches!(
        reduce_batch(&op, &bad, 3, &mut out),
        Err(cagd_core::Error::NonFinite { index, coord: 2, .. }) if index == 321 * 21 + 4
    ));
}

#[test]
fn fused_batch_bounds_hold_on_adversarial_families_and_ragged_ends() {
    // The batch computes the node values and the norms in its lanes kernel (four curves per
    // vector, a partial last group padded with zero curves). Every family here goes through
    // a different branch of the per-curve finish: nearly of degree m (the hull bound from
    // the reduced points), tiny and huge scales (the scaled per-curve route), exact degree
    // m (a zero error curve), plus ragged counts 1..=7. Each bound must be at least the
    // measured error and at most the per-curve node bound (`certified_bound`) up to the
    // rounding of the node values, relative to the largest control point (the batch may be
    // smaller: it also takes the hull bound of the computed reduced points for
    // nearly-degree-m curves).
    for (n, m) in [(5usize, 4usize), (10, 5), (30, 15)] {
        for method in [Method::L2 { r: 0, p: 0 }, Method::GeneralizedInverse] {
            let op = operator(method, n, m).unwrap();
            let per_in = (n + 1) * DIM;
            let low = BezierCurve::new(random_input((m + 1) * DIM, 5), DIM).unwrap();
            let exact = low.elevate(n - m).unwrap().points().to_vec();
            // (name, curve, its scale: a power of two, so that the measurement can run on
            // the exactly unscaled curves, where its squares do not overflow)
            let mut families: Vec<(&str, Vec<f64>, f64)> = Vec::new();
            for (name, eps) in [("exact", 0.0), ("near 1e-9", 1e-9), ("near 1e-14", 1e-14)] {
                let noise = random_input(per_in, 6);
                let curve = exact.iter().zip(&noise).map(|(x, e)| x + eps * e).collect();
                families.push((name, curve, 1.0));
            }
            for (name, s) in [("2^-900", -900), ("2^700", 700), ("2^-500", -500)] {
                let s = 2f64.powi(s);
                let curve = random_input(per_in, 7).iter().map(|x| x * s).collect();
                families.push((name, curve, s));
            }
            for (name, curve, scale) in &families {
                for count in 1..=7 {
                    // The family's curve at every position of a ragged batch of random ones.
                    let mut input = random_input(count * per_in, count as u64);
                    let at = (count - 1) / 2;
                    input[at * per_in..(at + 1) * per_in].copy_from_slice(curve);
                    let mut out = vec![0.0; count * (m + 1) * DIM];
                    for level in [BoundLevel::Fast, BoundLevel::Tight] {
                        let mut bounds = vec![0.0; count];
                        reduce_batch_with_bounds(&op, &input, DIM, &mut out, &mut bounds, level)
                            .unwrap();
                        for c in 0..count {
                            let pts = &input[c * per_in..(c + 1) * per_in];
                            let s = if c == at { *scale } else { 1.0 };
                            let unscaled = |x: &[f64]| x.iter().map(|v| v / s).collect();
                            let p = BezierCurve::new(unscaled(pts), DIM).unwrap();
                            let qp = &out[c * (m + 1) * DIM..(c + 1) * (m + 1) * DIM];
                            let q = BezierCurve::new(unscaled(qp), DIM).unwrap();
                            let measured = max_deviation(&p, &q).unwrap() * s;
                            let what = format!("{method:?} ({n},{m}) {name} {level:?} {c}/{count}");
                            assert!(bounds[c] >= measured, "{what}: {} < {measured}", bounds[c]);
                            let one = op.certified_bound(pts, DIM, level).unwrap().unwrap();
                            let pmax = pts.iter().fold(0.0f64, |a, x| a.max(x.abs()));
                            assert!(
                                bounds[c] <= one * (1.0 + 1e-9) + 1e-12 * pmax + 1e-300,
                                "{what}: batch {} vs per-curve {one}",
                                bounds[c]
                            );
                        }
                    }
                }
            }
        }
    }
}
