use super::*;
use cagd_testkit::{flat, num, vector};
use proptest::prelude::*;

fn forward_difference(p: &[f64], dim: usize) -> Vec<f64> {
    BezierCurve::new(p.to_vec(), dim)
        .unwrap()
        .forward_difference()
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// Eck / Chebyshev economisation (SPEC-reduce §3, vector eck-1): the error is exactly
/// `2^(-2n-1) ||Delta^{n+1} P_0||` (n = 4 here).
#[test]
fn eck_vector_error_is_the_closed_form() {
    let v = vector("vectors-reduce.json", "eck-1");
    let p = flat(&v["input"]["P"]);
    let q: Vec<f64> = v["expected"]["Q_exact"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|pt| pt.as_array().unwrap().iter().map(num).collect::<Vec<_>>())
        .collect();
    let a = BezierCurve::new(p.clone(), 2).unwrap();
    let b = BezierCurve::new(q, 2).unwrap();
    let expected = norm(&forward_difference(&p, 2)) / 512.0;
    let d = curve_distance(&a, &b).unwrap();
    assert!(
        (d - expected).abs() <= 1e-14 * expected,
        "{d} vs {expected}"
    );
}

/// Chebyshev economisation built here for several degrees: subtract
/// `2^(-2n-1) T_{n+1}(2t-1) Delta` (Bernstein coefficients of `T_k(2t-1)`:
/// `(-1)^(k-i) C(2k,2i)/C(k,i)`), which lowers the degree and has error
/// `2^(-2n-1) ||Delta||`, attained at n + 2 points.
#[test]
fn chebyshev_economisation_errors() {
    use crate::binomial::binomial_f64;
    for n in [1usize, 3, 6, 10, 20] {
        let k = n + 1;
        let dim = 3;
        let p: Vec<f64> = (0..(k + 1) * dim)
            .map(|i| ((i * 7919) % 23) as f64 / 3.0 - 2.0)
            .collect();
        let delta = forward_difference(&p, dim);
        let s = kernel::powu(0.5, 2 * n + 1);
        let mut q = p.clone();
        let mut err = vec![0.0; p.len()];
        for i in 0..=k {
            let sign = if (k - i) % 2 == 0 { 1.0 } else { -1.0 };
            let c = sign * binomial_f64(2 * k, 2 * i) / binomial_f64(k, i);
            for d in 0..dim {
                err[i * dim + d] = s * c * delta[d];
                q[i * dim + d] -= err[i * dim + d];
            }
        }
        let a = BezierCurve::new(p, dim).unwrap();
        let b = BezierCurve::new(q, dim).unwrap();
        let expected = s * norm(&delta);
        let d = curve_distance(&a, &b).unwrap();
        // Rounding q (|q| <= 6) perturbs the exact value by a few ulp of 6: tolerance
        // 1e-12 relative to the distance plus 1e-15 absolute for that floor.
        assert!(
            (d - expected).abs() <= 1e-12 * expected + 1e-15,
            "n={n}: {d} vs {expected}"
        );
        // The error curve alone (coefficients rounded relative to themselves) against the
        // zero curve of degree 0. De Casteljau is a convex combination, so the evaluation
        // floor is a few k ulp of the largest coefficient (C(2k,2i)/C(k,i) up to 1.5e6
        // times the distance at k = 21): 1e-12 relative plus that floor.
        let big = err.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let e = BezierCurve::new(err, dim).unwrap();
        let zero = BezierCurve::new(vec![0.0; dim], dim).unwrap();
        let d = curve_distance(&e, &zero).unwrap();
        let tol = 1e-12 * expected + 4.0 * k as f64 * f64::EPSILON * big;
        assert!((d - expected).abs() <= tol, "n={n}: {d} vs {expected}");
        if n <= 10 {
            assert!(
                (d - expected).abs() <= 1e-12 * expected,
                "n={n}: {d} vs {expected}"
            );
        }
    }
}

#[test]
fn shifted_copy() {
    let p = vec![0.0, 0.0, 1.0, 3.0, 3.0, 4.0, 5.0, 1.0];
    let q: Vec<f64> = p
        .iter()
        .enumerate()
        .map(|(i, x)| x + if i % 2 == 0 { 0.3 } else { -0.4 })
        .collect();
    let a = BezierCurve::new(p, 2).unwrap();
    let b = BezierCurve::new(q, 2).unwrap();
    let d = curve_distance(&a, &b).unwrap();
    assert!((d - 0.5).abs() < 1e-15, "{d}");
    // Rational curves are evaluated separately: floor a few ulp of the size 5.
    // Rational copies with the same weights: the shift is still exact.
    let w = vec![1.0, 2.0, 0.5, 1.0];
    let ar = BezierCurve::new_rational(a.points().to_vec(), w.clone(), 2).unwrap();
    let br = BezierCurve::new_rational(b.points().to_vec(), w, 2).unwrap();
    let d = curve_distance(&ar, &br).unwrap();
    assert!((d - 0.5).abs() < 8.0 * 5.0 * f64::EPSILON, "{d}");
}

/// `a(t) - b(t) = (9 t^2 (1-t), 0)`: maximum exactly at t = 2/3, which is not a sample
/// (112 and 7 intervals, neither divisible by 3).
#[test]
fn maximum_between_samples() {
    // t^2 (1-t) in Bernstein form of degree 3: coefficients 0, 0, 1/3, 0.
    let a = BezierCurve::new(vec![0.0, 1.0, 0.0, 2.0, 3.0, 3.0, 0.0, 4.0], 2).unwrap();
    let b = BezierCurve::new(vec![0.0, 1.0, 0.0, 2.0, 0.0, 3.0, 0.0, 4.0], 2).unwrap();
    // x-difference = 3 B_2^3(t) = 9 t^2 (1-t): maximum 9 * 4/27 = 4/3.
    let expected = 4.0 / 3.0;
    let d = curve_distance(&a, &b).unwrap();
    assert!(
        (d - expected).abs() <= 1e-14 * expected,
        "{d} vs {expected}"
    );
    // Few samples: still found (refinement inside the bracket).
    let d = max_distance_1d(
        |t, o| a.eval_into(t, o),
        |t, o| b.eval_into(t, o),
        2,
        0.0,
        1.0,
        7,
    )
    .unwrap();
    assert!(
        (d - expected).abs() <= 1e-14 * expected,
        "{d} vs {expected}"
    );
}

#[test]
fn errors() {
    let a = BezierCurve::new(vec![0.0, 1.0], 1).unwrap();
    let b = BezierCurve::new(vec![0.0, 1.0, 2.0, 3.0], 2).unwrap();
    assert!(matches!(
        curve_distance(&a, &b),
        Err(Error::LengthMismatch { .. })
    ));
    let z = |_: f64, o: &mut [f64]| o[0] = 0.0;
    assert!(matches!(
        max_distance_1d(z, z, 1, f64::NAN, 1.0, 10),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(
        max_distance_1d(z, z, 1, 1.0, 0.0, 10),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(
        max_distance_1d(z, z, 0, 0.0, 1.0, 10),
        Err(Error::ZeroDimension)
    ));
    let nan = |_: f64, o: &mut [f64]| o[0] = f64::NAN;
    assert!(matches!(
        max_distance_1d(z, nan, 1, 0.0, 1.0, 10),
        Err(Error::NonFinite { .. })
    ));
    // Degenerate interval: the distance at the single point.
    let d = max_distance_1d(|t, o| o[0] = t, z, 1, 0.5, 0.5, 10).unwrap();
    assert_eq!(d, 0.5);
}

proptest! {
    /// The refined maximum is at least every value on a fine grid, and not more than
    /// rounding above the best of a very fine grid refined around it.
    #[test]
    fn not_below_a_fine_grid(p in cagd_testkit::points(8, 2), q in cagd_testkit::points(5, 2)) {
        let a = BezierCurve::new(p, 2).unwrap();
        let b = BezierCurve::new(q, 2).unwrap();
        let d = curve_distance(&a, &b).unwrap();
        let mut grid: f64 = 0.0;
        for i in 0..=20_000 {
            let t = i as f64 / 20_000.0;
            let (x, y) = (a.eval(t), b.eval(t));
            grid = grid.max(((x[0] - y[0]).powi(2) + (x[1] - y[1]).powi(2)).sqrt());
        }
        // The grid misses the maximum by at most O(h^2) relative: h = 5e-5.
        prop_assert!(d >= grid * (1.0 - 1e-14));
        prop_assert!(d <= grid * (1.0 + 1e-6) + 1e-14);
    }
}

/// The reference of [`refine_sampled_maxima`]'s pruning: every sampled local maximum
/// refined (the function before the pruning).
fn refine_all(
    f: &impl Fn(f64, &mut [f64]),
    g: &impl Fn(f64, &mut [f64]),
    dim: usize,
    d2: &[f64],
) -> f64 {
    let n = d2.len() - 1;
    let t_at = |i: usize| i as f64 / n as f64;
    let (mut a, mut b) = (vec![0.0; dim], vec![0.0; dim]);
    let mut h = |t: f64| sq_dist(f, g, t, &mut a, &mut b);
    let mut best = d2.iter().copied().fold(0.0f64, f64::max);
    for i in 0..=n {
        let left = if i > 0 { d2[i - 1] } else { f64::NEG_INFINITY };
        let right = if i < n { d2[i + 1] } else { f64::NEG_INFINITY };
        if d2[i] >= left && d2[i] >= right && (d2[i] > left || d2[i] > right) {
            let (_, v) = brent_max(
                &mut h,
                t_at(i.saturating_sub(1)),
                t_at((i + 1).min(n)),
                t_at(i),
            );
            best = best.max(v);
        }
    }
    best.sqrt()
}

proptest! {
    /// The pruned refinement finds the maximum that refining every sampled local maximum
    /// finds: on differences with several maxima of similar size (a curve against a
    /// perturbed copy of itself, perturbations from 1 down to the rounding level, where
    /// the sampled distance is noise).
    #[test]
    fn pruning_keeps_the_maximum(p in cagd_testkit::points(12, 3), e in cagd_testkit::points(12, 3), scale in -16i32..=0) {
        let size = 10f64.powi(scale);
        let q: Vec<f64> = p.iter().zip(&e).map(|(x, y)| x + size * y).collect();
        let (a, b) = (BezierCurve::new(p, 3).unwrap(), BezierCurve::new(q, 3).unwrap());
        let f = |t: f64, o: &mut [f64]| a.eval_into(t, o);
        let g = |t: f64, o: &mut [f64]| b.eval_into(t, o);
        let n = 8 * 22 + 64;
        let d2: Vec<f64> = (0..=n)
            .map(|i| {
                let (x, y) = (a.eval(i as f64 / n as f64), b.eval(i as f64 / n as f64));
                x.iter().zip(&y).map(|(u, v)| (u - v) * (u - v)).sum()
            })
            .collect();
        let pruned = refine_sampled_maxima(&f, &g, 3, 0.0, 1.0, &d2);
        let all = refine_all(&f, &g, 3, &d2);
        // Equal, up to the value error of Brent's stopping rule (relative ~eps in the
        // square at a smooth maximum) or a rounding-level spike at the noise floor.
        prop_assert!(pruned <= all);
        prop_assert!(pruned >= all * (1.0 - 1e-12) || all - pruned <= 64.0 * f64::EPSILON, "pruned {pruned:e} all {all:e}");
    }
}

/// A maximum between the last two samples (or the first two), the shape the end rule
/// judges by its parabola: found to rounding, at both ends and at several offsets.
#[test]
fn maximum_inside_an_end_interval_is_refined() {
    let n = 10;
    for (k, offset) in [0.1, 0.3, 0.5, 0.7, 0.9].into_iter().enumerate() {
        for at_start in [false, true] {
            let peak = if at_start {
                offset / n as f64
            } else {
                1.0 - offset / n as f64
            };
            let f = move |t: f64, o: &mut [f64]| o[0] = 2.0 + k as f64 - 1.5 * (t - peak).powi(2);
            let g = |_: f64, o: &mut [f64]| o[0] = 0.0;
            let d2: Vec<f64> = (0..=n)
                .map(|i| {
                    let mut o = [0.0];
                    f(i as f64 / n as f64, &mut o);
                    o[0] * o[0]
                })
                .collect();
            let d = refine_sampled_maxima(&f, &g, 1, 0.0, 1.0, &d2);
            let exact = 2.0 + k as f64;
            assert!(
                (d - exact).abs() <= 1e-12 * exact,
                "peak {peak}: {d} vs {exact}"
            );
        }
    }
}

/// [`refine_sampled_maxima_above`]: with `above` at or below the refined maximum the
/// result is [`refine_sampled_maxima`]'s bitwise; with `above` over it, never below the
/// sampled maximum nor above the refined one, and no evaluation at all when every
/// sampled maximum's reach is below `above` (the pair is left to the caller's maximum).
#[test]
fn refinement_above_a_floor_keeps_the_maxima_that_reach_it() {
    use std::cell::Cell;
    for (k, freq) in [3.0f64, 7.0, 11.0].into_iter().enumerate() {
        let f = move |t: f64, o: &mut [f64]| {
            o[0] = (freq * t).sin() * (1.0 + 0.3 * t) + 0.1 * k as f64;
            o[1] = (0.5 * freq * t).cos();
        };
        let calls = Cell::new(0usize);
        let g = |t: f64, o: &mut [f64]| {
            calls.set(calls.get() + 1);
            o[0] = 0.2 * t;
            o[1] = 0.0;
        };
        let n = 40;
        let d2: Vec<f64> = (0..=n)
            .map(|i| {
                let (mut a, mut b) = ([0.0; 2], [0.0; 2]);
                let t = i as f64 / n as f64;
                f(t, &mut a);
                g(t, &mut b);
                (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)
            })
            .collect();
        let sampled = d2.iter().copied().fold(0.0f64, f64::max).sqrt();
        let full = refine_sampled_maxima(&f, &g, 2, 0.0, 1.0, &d2);
        for above in [0.0, 0.5 * full, full * (1.0 - 1e-9)] {
            let got = refine_sampled_maxima_above(&f, &g, 2, 0.0, 1.0, &d2, above);
            assert_eq!(got.to_bits(), full.to_bits(), "freq {freq} above {above}");
        }
        let got = refine_sampled_maxima_above(&f, &g, 2, 0.0, 1.0, &d2, 1.5 * full);
        assert!(
            got >= sampled && got <= full,
            "freq {freq}: {got} vs {sampled} / {full}"
        );
        calls.set(0);
        let _ = refine_sampled_maxima_above(&f, &g, 2, 0.0, 1.0, &d2, 3.0 * full);
        assert_eq!(calls.get(), 0, "freq {freq}: refined below the floor");
    }
}
