//! The per-curve certified bound (`reduce_with`, `Operator::certified_bound`) against the
//! error measured independently (`max_deviation`: dense sampling of the difference curve
//! plus Brent refinement of every local maximum), on thousands of random curves per degree
//! pair and on adversarial families: nearly of the lower degree, huge and tiny
//! coordinates, far from the origin, the error concentrated near an end, a single spike,
//! low and high dimensions. Every bound must be at least the measured error; where the
//! error is far above the rounding allowance, at most the level's secant factor times it.

use cagd_core::BezierCurve;
use cagd_reduce::{BoundLevel, Method, ReduceOptions, max_deviation, operator, reduce_with};
use cagd_testkit::bench::random_input;

const PAIRS: [(usize, usize); 6] = [(4, 3), (5, 4), (10, 5), (15, 10), (20, 10), (30, 15)];
const L2_C0: Method = Method::L2 { r: 0, p: 0 };
/// The levels' secant factors (`bound/mod.rs`) with room for the rounding of the bound's
/// own arithmetic (relative `1e-9` is far above it and far below the 1.1 goal).
const FAST: f64 = 1.25 * (1.0 + 1e-9);
const TIGHT: f64 = 1.075 * (1.0 + 1e-9);

/// Reduces `points` with `method` at both levels and checks the bounds against the
/// measured error; `allowance` is the absolute slack allowed above the ratio (for errors
/// near rounding level). Returns tight / measured.
fn check(method: Method, points: &[f64], dim: usize, m: usize, allowance: f64, what: &str) -> f64 {
    let curve = BezierCurve::new(points.to_vec(), dim).unwrap();
    let opts = ReduceOptions {
        measure: true,
        ..ReduceOptions::new(method, m)
    };
    let red = reduce_with(&curve, &opts).unwrap();
    let (tight, e) = (
        red.report.error_bound.unwrap(),
        red.report.max_error.unwrap(),
    );
    let op = operator(method, curve.degree(), m).unwrap();
    let fast = op
        .certified_bound(points, dim, BoundLevel::Fast)
        .unwrap()
        .unwrap();
    let again = op
        .certified_bound(points, dim, BoundLevel::Tight)
        .unwrap()
        .unwrap();
    // reduce_with may take the smaller hull bound of the formed error curve when the node
    // bound is mostly rounding allowance (nearly degree m); otherwise they are equal.
    assert!(tight <= again, "{what}: reduce_with above certified_bound");
    if tight < again {
        assert!(
            e < 1e-9 * pmax(points, dim),
            "{what}: hull route on a large error"
        );
    }
    // Independent measurement, on the reduced curve as returned.
    assert_eq!(max_deviation(&curve, &red.curve).unwrap(), e);
    assert!(
        tight >= e && fast >= e,
        "{what}: bound below the measured error: tight {tight:e} fast {fast:e} measured {e:e}"
    );
    assert!(
        tight <= TIGHT * e + allowance,
        "{what}: tight {tight:e} vs measured {e:e} (+{allowance:e})"
    );
    assert!(
        fast <= FAST * e + allowance,
        "{what}: fast {fast:e} vs measured {e:e} (+{allowance:e})"
    );
    tight / e
}

#[test]
fn tight_bound_within_1_075_on_thousands_of_random_curves_per_pair() {
    for (n, m) in PAIRS {
        let dim = 3;
        let per = (n + 1) * dim;
        let input = random_input(1500 * per, (7 * n + m) as u64);
        let mut worst: f64 = 0.0;
        for (c, p) in input.chunks_exact(per).enumerate() {
            worst = worst.max(check(L2_C0, p, dim, m, 0.0, &format!("({n},{m}) #{c}")));
        }
        println!("({n:2},{m:2}) L2-C0, 1500 random curves: worst tight/measured {worst:.4}");
    }
}

#[test]
fn other_methods_and_dimensions() {
    for method in [
        Method::GeneralizedInverse,
        Method::L2 { r: 1, p: 1 },
        Method::ConstrainedChebyshev { r: 0, p: 0 },
        Method::Forrest,
        Method::Perturb,
    ] {
        for (n, m) in [(5, 4), (10, 5), (15, 10)] {
            if operator(method, n, m).is_err() {
                continue;
            }
            for dim in [1, 2, 4, 7] {
                let per = (n + 1) * dim;
                let input = random_input(100 * per, (n + 31 * dim) as u64);
                for (c, p) in input.chunks_exact(per).enumerate() {
                    // The method's own bound may be the smaller one and is not bound to the
                    // secant factors: check truth only for those methods.
                    let own = matches!(
                        method,
                        Method::Perturb | Method::ConstrainedChebyshev { .. }
                    );
                    let allowance = if own { f64::INFINITY } else { 0.0 };
                    check(
                        method,
                        p,
                        dim,
                        m,
                        allowance,
                        &format!("{method:?} ({n},{m}) dim {dim} #{c}"),
                    );
                }
            }
        }
    }
}

/// `max_j ||P_j||` of a buffer.
fn pmax(p: &[f64], dim: usize) -> f64 {
    p.chunks_exact(dim)
        .map(|x| x.iter().map(|v| v * v).sum::<f64>().sqrt())
        .fold(0.0, f64::max)
}

#[test]
fn adversarial_curves() {
    let dim = 3;
    for (n, m) in PAIRS {
        let per = (n + 1) * dim;
        let base = random_input(20 * per, 1000 + n as u64);
        for (c, p) in base.chunks_exact(per).enumerate() {
            // Nearly of degree m: an elevated degree-m curve plus a perturbation of relative
            // size 1e-3 .. 1e-14, and exactly elevated (error at rounding level: only
            // truth and the size of the allowance are checked).
            let low = &random_input((m + 1) * dim, c as u64 + 77);
            let mut elevated = vec![0.0; per];
            cagd_core::kernel::elevate(low, dim, n - m, &mut elevated);
            for rel in [1e-3, 1e-8, 1e-14, 0.0] {
                let q: Vec<f64> = elevated.iter().zip(p).map(|(e, x)| e + rel * x).collect();
                // The rounding allowance is a few 1e-11 of max ||P_j|| at these pairs.
                let allowance = 1e-9 * pmax(&q, dim);
                check(
                    L2_C0,
                    &q,
                    dim,
                    m,
                    allowance,
                    &format!("({n},{m}) near degree m, {rel:e} #{c}"),
                );
            }
            // Huge, tiny, and far from the origin (the allowance scales with max ||P_j||).
            for (scale, shift) in [(1e150, 0.0), (1e-150, 0.0), (1.0, 1e3)] {
                let q: Vec<f64> = p.iter().map(|x| x * scale + shift).collect();
                let allowance = 1e-9 * pmax(&q, dim);
                check(
                    L2_C0,
                    &q,
                    dim,
                    m,
                    allowance,
                    &format!("({n},{m}) scale {scale:e} shift {shift} #{c}"),
                );
            }
            // Below the range where squares are normal numbers (the measurement itself
            // underflows there): the bound of the scaled curve against the scaled
            // measurement of the unscaled one (the error is linear in the input; the
            // reduced points' subnormal rounding is ~1e-310, far below 1e-302).
            let unit = reduce_with(
                &BezierCurve::new(p.to_vec(), dim).unwrap(),
                &ReduceOptions {
                    measure: true,
                    ..ReduceOptions::new(L2_C0, m)
                },
            )
            .unwrap();
            let e_unit = unit.report.max_error.unwrap();
            let op = operator(L2_C0, n, m).unwrap();
            for scale in [1e-300, 1e-310, 1e300] {
                let q: Vec<f64> = p.iter().map(|x| x * scale).collect();
                let b = op
                    .certified_bound(&q, dim, BoundLevel::Tight)
                    .unwrap()
                    .unwrap();
                let want = e_unit * scale;
                assert!(
                    b >= want * (1.0 - 1e-9) && b <= TIGHT * want * (1.0 + 1e-6) + 1e-307,
                    "({n},{m}) scale {scale:e} #{c}: {b:e} vs {want:e}"
                );
            }
            // The error concentrated near an end: control points growing like (j/n)^8.
            let q: Vec<f64> = p
                .iter()
                .enumerate()
                .map(|(i, x)| x * ((i / dim) as f64 / n as f64).powi(8))
                .collect();
            check(L2_C0, &q, dim, m, 0.0, &format!("({n},{m}) end-heavy #{c}"));
            // One spike, the rest zero.
            let mut q = vec![0.0; per];
            q[(c % (n + 1)) * dim + c % dim] = 1.0;
            check(L2_C0, &q, dim, m, 0.0, &format!("({n},{m}) spike #{c}"));
        }
        // The zero curve: a zero-size bound, never negative.
        let zero = vec![0.0; per];
        let op = operator(L2_C0, n, m).unwrap();
        let b = op
            .certified_bound(&zero, dim, BoundLevel::Tight)
            .unwrap()
            .unwrap();
        assert!((0.0..1e-300).contains(&b), "({n},{m}) zero curve: {b:e}");
    }
}

#[test]
fn near_overflow_input_gets_a_true_bound_never_nan() {
    let (n, m, dim) = (10, 5, 3);
    let op = operator(L2_C0, n, m).unwrap();
    let unit = random_input((n + 1) * dim, 5);
    let red = reduce_with(
        &BezierCurve::new(unit.clone(), dim).unwrap(),
        &ReduceOptions {
            measure: true,
            ..ReduceOptions::new(L2_C0, m)
        },
    )
    .unwrap();
    let e_unit = red.report.max_error.unwrap();
    for scale in [1e307, f64::MAX / 2.0] {
        let p: Vec<f64> = unit.iter().map(|x| x * scale).collect();
        let b = op
            .certified_bound(&p, dim, BoundLevel::Tight)
            .unwrap()
            .unwrap();
        // Scaled by a power of two before the norms: finite where the error is, +inf
        // where it is not representable; never NaN, never below the error.
        assert!(
            !b.is_nan() && b >= e_unit * scale * (1.0 - 1e-9),
            "{scale:e}: {b:e}"
        );
    }
}

/// A G1 perturbation with `l1 = 1e308` (the C fuzz run, seed 112): its error space came out
/// of rank 0 and the single-curve bound's loop panicked on a zero-length chunk. Now a named
/// error or a result whose bound is not below the measured error (here `+inf` or huge).
#[test]
fn overflowing_operator_gives_no_panic_and_no_false_bound() {
    let c = BezierCurve::new(
        vec![
            0.578_070_148_464_279_8,
            0.038_636_606_968_697_86,
            0.457_350_506_204_539_15,
            0.363_404_193_974_673_8,
            0.882_628_394_694_336_7,
        ],
        1,
    )
    .unwrap();
    for level in [BoundLevel::Fast, BoundLevel::Tight] {
        for (l1, l2) in [(1e308, 0.0), (0.0, 1e308), (1e308, 1e308), (1e300, -0.5)] {
            let opts = ReduceOptions {
                measure: true,
                bound: level,
                ..ReduceOptions::new(Method::PerturbG1 { l1, l2 }, 3)
            };
            if let Ok(r) = reduce_with(&c, &opts) {
                let (b, e) = (r.report.error_bound.unwrap(), r.report.max_error.unwrap());
                assert!(b >= e, "bound {b} below the measured {e} ({l1}, {l2})");
            }
            // The batch route of the same operator: no panic either.
            if let Ok(op) = operator(Method::PerturbG1 { l1, l2 }, 4, 3) {
                let input: Vec<f64> = c.points().repeat(9);
                let (mut out, mut bounds) = (vec![0.0; 4 * 9], vec![0.0; 9]);
                if cagd_reduce::reduce_batch_with_bounds(
                    &op,
                    &input,
                    1,
                    &mut out,
                    &mut bounds,
                    level,
                )
                .is_ok()
                {
                    // (The measurement itself may overflow at this scale.)
                    let q = BezierCurve::new(out[..4].to_vec(), 1).unwrap();
                    if let Ok(e) = max_deviation(&c, &q) {
                        assert!(bounds[0] >= e, "batch bound {} below {e}", bounds[0]);
                    }
                }
            }
        }
    }
}
