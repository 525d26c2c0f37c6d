//! Tests of the reductions to a tolerance: the spec vectors of Algorithm 14.2.1 and
//! eq. 14.2.11, an accuracy sweep over tolerances, methods and curves, the continuity of
//! the joins, and the error cases.

use cagd_core::{BSplineCurve, BezierCurve, Error};
use cagd_testkit::{assert_close, flat, num, vector, vectors_with_algorithm};

use crate::{
    Method, PiecewiseReduction, ToleranceOptions, reduce_to_tolerance,
    reduce_to_tolerance_alg_14_2_1, subdivision_levels,
};

/// Deterministic pseudo-random coordinates in `[-1, 1]` (64-bit LCG).
fn random_points(n_points: usize, dim: usize, seed: u64) -> Vec<f64> {
    let mut s = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (0..n_points * dim)
        .map(|_| {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        })
        .collect()
}

fn random_curve(n: usize, seed: u64) -> BezierCurve {
    BezierCurve::new(random_points(n + 1, 2, seed), 2).unwrap()
}

/// A degree-7 rational curve in 3D with weights in `[0.5, 2]`.
fn rational_curve() -> BezierCurve {
    let w = vec![1.0, 0.5, 2.0, 1.5, 0.7, 1.2, 2.0, 1.0];
    BezierCurve::new_rational(random_points(8, 3, 7), w, 3).unwrap()
}

#[test]
fn vectors_alg_14_2_1() {
    let vs = vectors_with_algorithm("vectors-reduce.json", "subdiv_reduce_alg_14.2.1");
    assert!(!vs.is_empty());
    for v in vs {
        let id = v["id"].as_str().unwrap();
        let p = flat(&v["input"]["P"]);
        let curve = BezierCurve::new(p, 2).unwrap();
        let d = usize::try_from(v["params"]["d"].as_u64().unwrap()).unwrap();
        let delta = num(&v["params"]["delta"]);
        let opts = ToleranceOptions {
            measure: true,
            ..ToleranceOptions::new(Method::Perturb, d, delta, 0)
        };
        let red = reduce_to_tolerance_alg_14_2_1(&curve, &opts).unwrap();
        let intervals: Vec<f64> = red.pieces.iter().flat_map(|p| [p.start, p.end]).collect();
        assert_eq!(
            intervals,
            flat(&v["expected"]["intervals"]),
            "{id}: intervals"
        );
        let got: Vec<f64> = red
            .pieces
            .iter()
            .flat_map(|p| p.curve.points().to_vec())
            .collect();
        let tol = num(&v["tol"]);
        assert_close(id, &got, &flat(&v["expected"]["Q_pieces"]), tol);
        let total: f64 = red.report.step_bounds.iter().sum();
        let expected = num(&v["expected"]["certified_total"]);
        assert!(
            (total - expected).abs() <= tol,
            "{id}: total {total} vs {expected}"
        );
        let r = &red.report;
        assert!(r.max_error.unwrap() <= r.error_bound && r.error_bound <= total + 1e-15);
        assert!(total < delta);
    }
}

#[test]
fn vector_n_formula() {
    let v = vector("vectors-reduce.json", "N-formula-1");
    let n = usize::try_from(v["params"]["n"].as_u64().unwrap()).unwrap();
    let got = subdivision_levels(n, num(&v["input"]["normF"]), num(&v["params"]["delta"]));
    assert_eq!(
        got.unwrap(),
        usize::try_from(v["expected"]["N"].as_u64().unwrap()).unwrap()
    );
    assert_eq!(subdivision_levels(5, 0.0, 1e-3).unwrap(), 0);
    assert!(subdivision_levels(1, 1.0, 1e-3).is_err());
    assert!(subdivision_levels(5, f64::NAN, 1e-3).is_err());
    assert!(subdivision_levels(5, 1.0, 0.0).is_err());
}

/// The levels of eq. 14.2.11 against the marching placement for one degree: a uniform
/// subdivision into `2^N` pieces meets the tolerance and `2^(N-1)` does not, so the
/// longest piece that meets it is between `2^-N` and `2^-(N-1)` (the bound scales by
/// exactly `h^n`, Theorem 14.2.2); marching finds at most `2^N` and more than `2^(N-1)`
/// pieces, every one but the last at least `0.9 * 2^-N` long.
#[test]
fn n_formula_matches_one_degree_perturbation() {
    let curve = random_curve(6, 3);
    let f = curve.forward_difference();
    let nf = f.iter().map(|x| x * x).sum::<f64>().sqrt();
    for delta in [1e-2, 1e-4, 1e-6] {
        let levels = subdivision_levels(6, nf, delta).unwrap();
        let red = reduce_to_tolerance(
            &curve,
            &ToleranceOptions::new(Method::Perturb, 5, delta / super::piecewise::PIECE_SHARE, 0),
        )
        .unwrap();
        let pieces = red.report.pieces;
        assert!(pieces <= 1 << levels, "delta {delta}: {pieces} pieces");
        assert!(2 * pieces > 1 << levels, "delta {delta}: {pieces} pieces");
        let h = (-(levels as f64)).exp2();
        for p in &red.pieces[..pieces - 1] {
            assert!(p.end - p.start >= 0.9 * h, "delta {delta}: {p:?}");
        }
    }
}

/// Largest jump of derivative `j` (global parameter) at the joints of consecutive
/// segments, relative to the size of that derivative.
fn max_relative_jump(segs: &[(f64, f64, BezierCurve)], j: usize) -> f64 {
    let mut worst = 0.0f64;
    for w in segs.windows(2) {
        let (la, lb) = (w[0].1 - w[0].0, w[1].1 - w[1].0);
        let dl = &w[0].2.derivatives(1.0, j).unwrap()[j];
        let dr = &w[1].2.derivatives(0.0, j).unwrap()[j];
        let (sl, sr) = (la.powf(j as f64), lb.powf(j as f64));
        let jump = dl
            .iter()
            .zip(dr)
            .map(|(a, b)| (a / sl - b / sr).powi(2))
            .sum::<f64>()
            .sqrt();
        let size = dl
            .iter()
            .map(|a| (a / sl).powi(2))
            .sum::<f64>()
            .sqrt()
            .max(1.0);
        worst = worst.max(jump / size);
    }
    worst
}

fn check_result(red: &PiecewiseReduction, what: &str) {
    let r = &red.report;
    let me = r.max_error.unwrap();
    // The measured error is a maximum of evaluated points; allow its own rounding.
    assert!(
        me <= r.error_bound * (1.0 + 1e-9) + 1e-15,
        "{what}: {me} > {}",
        r.error_bound
    );
    assert!(r.error_bound <= r.tolerance, "{what}");
    assert!(r.pieces_bound <= r.error_bound, "{what}");
    let (m, k) = (r.degree_to, r.continuity);
    let s: &BSplineCurve = &red.spline;
    assert_eq!(s.degree(), m);
    // Knots: m+1 at each end, m-k at each interior break.
    assert_eq!(
        s.knots().len(),
        2 * (m + 1) + (m - k) * (r.pieces - 1),
        "{what}"
    );
    for p in &red.pieces[1..] {
        assert_eq!(
            cagd_core::knot_multiplicity(s.knots(), p.start),
            m - k,
            "{what}"
        );
    }
    // Joins: the pieces agree in derivatives 0..=k; the spline's own segments too.
    let pieces: Vec<_> = red
        .pieces
        .iter()
        .map(|p| (p.start, p.end, p.curve.clone()))
        .collect();
    let segs: Vec<_> = s
        .to_beziers()
        .unwrap()
        .into_iter()
        .map(|b| (b.start, b.end, b.curve))
        .collect();
    for j in 0..=k {
        // Relative jump: rounding of the operator and of the subdivision, amplified by
        // 1 / length^j for short pieces; 1e-8 is far above that and far below any real
        // kink (a missing constraint gives O(1) relative jumps).
        let jp = max_relative_jump(&pieces, j);
        assert!(jp < 1e-8, "{what}: pieces jump {jp:e} in derivative {j}");
        let js = max_relative_jump(&segs, j);
        assert!(js < 1e-8, "{what}: spline jump {js:e} in derivative {j}");
    }
}

#[test]
fn accuracy_sweep() {
    let curves = [
        ("random-9", random_curve(9, 1)),
        ("random-12", random_curve(12, 2)),
        ("rational-7", rational_curve()),
    ];
    let methods = [
        (Method::L2 { r: 0, p: 0 }, 0),
        (Method::Perturb, 0),
        (Method::L2 { r: 1, p: 1 }, 1),
        (Method::ConstrainedChebyshev { r: 1, p: 1 }, 1),
        (Method::ConstrainedChebyshev { r: 2, p: 2 }, 2),
        (Method::L2 { r: 2, p: 2 }, 2),
        (Method::Forrest, 2),
    ];
    for (name, curve) in &curves {
        for (method, k) in methods {
            for e in [2, 4, 6, 8, 10] {
                let tol = 10f64.powi(-e);
                let opts = ToleranceOptions {
                    measure: true,
                    ..ToleranceOptions::new(method, 5, tol, k)
                };
                let what = format!("{name} {} k={k} tol={tol:e}", method.name());
                let red =
                    reduce_to_tolerance(curve, &opts).unwrap_or_else(|e| panic!("{what}: {e}"));
                check_result(&red, &what);
            }
        }
    }
}

/// Target degree 3 (Hermite for k = 1): many more pieces, rational C1 merge with ~1000
/// knots at 1e-10.
#[test]
fn accuracy_sweep_cubic() {
    let curves = [
        ("random-12", random_curve(12, 2)),
        ("rational-7", rational_curve()),
    ];
    for (name, curve) in &curves {
        for (method, k) in [(Method::Perturb, 0), (Method::L2 { r: 1, p: 1 }, 1)] {
            for e in [3, 6, 10] {
                let tol = 10f64.powi(-e);
                let opts = ToleranceOptions {
                    measure: true,
                    ..ToleranceOptions::new(method, 3, tol, k)
                };
                let what = format!("{name} {} m=3 k={k} tol={tol:e}", method.name());
                let red =
                    reduce_to_tolerance(curve, &opts).unwrap_or_else(|e| panic!("{what}: {e}"));
                check_result(&red, &what);
                // The check sees real kinks: derivative k + 1 does jump (visibly at a coarse
                // tolerance; the jumps shrink with the tolerance).
                let pieces: Vec<_> = red
                    .pieces
                    .iter()
                    .map(|p| (p.start, p.end, p.curve.clone()))
                    .collect();
                if e == 3 {
                    assert!(max_relative_jump(&pieces, k + 1) > 1e-6, "{what}");
                }
            }
        }
    }
}

#[test]
fn already_low_degree_is_one_piece() {
    let cubic = random_curve(3, 5);
    let curve = cubic.elevate(6).unwrap();
    for (method, k) in [(Method::L2 { r: 1, p: 1 }, 1), (Method::Perturb, 0)] {
        let opts = ToleranceOptions {
            measure: true,
            ..ToleranceOptions::new(method, 3, 1e-9, k)
        };
        let red = reduce_to_tolerance(&curve, &opts).unwrap();
        assert_eq!(red.report.pieces, 1);
        assert_eq!(red.report.depth, 0);
        assert!(red.report.error_bound < 1e-13);
        assert_close(
            "elevated",
            red.pieces[0].curve.points(),
            cubic.points(),
            1e-12,
        );
    }
}

#[test]
fn errors() {
    let curve = random_curve(8, 9);
    let run =
        |method, m, tol, k| reduce_to_tolerance(&curve, &ToleranceOptions::new(method, m, tol, k));
    let l2 = |r| Method::L2 { r, p: r };
    for bad in [0.0, -1e-3, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            run(l2(1), 4, bad, 1),
            Err(Error::BadTolerance { .. })
        ));
    }
    assert!(matches!(
        run(l2(1), 8, 1e-3, 1),
        Err(Error::BadDegreePair { .. })
    ));
    assert!(matches!(
        run(l2(1), 9, 1e-3, 1),
        Err(Error::BadDegreePair { .. })
    ));
    // k >= m.
    assert!(matches!(
        run(l2(0), 2, 1e-3, 2),
        Err(Error::BadParameter {
            name: "continuity",
            ..
        })
    ));
    // The method does not keep order k at the ends.
    assert!(matches!(
        run(Method::Eck, 4, 1e-3, 0),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(
        run(l2(0), 4, 1e-3, 1),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(
        run(Method::Forrest, 4, 1e-3, 2),
        Err(Error::BadParameter { .. })
    ));
    // Too many constraints for the target degree (2k + 1 > m).
    assert!(matches!(
        run(l2(2), 4, 1e-3, 2),
        Err(Error::TooManyConstraints { .. })
    ));
    // Hermite m = 2k + 1 is allowed.
    assert!(run(Method::ConstrainedChebyshev { r: 1, p: 1 }, 3, 1e-3, 1).is_ok());
    // Depth limit: the best achieved bound is reported.
    let opts = ToleranceOptions {
        max_depth: 2,
        ..ToleranceOptions::new(l2(1), 4, 1e-12, 1)
    };
    match reduce_to_tolerance(&curve, &opts) {
        Err(Error::NoConvergence {
            tolerance,
            achieved,
        }) => {
            assert_eq!(tolerance, 1e-12);
            assert!(achieved > 1e-12 && achieved.is_finite());
        }
        other => panic!("expected NoConvergence, got {other:?}"),
    }
    // Algorithm 14.2.1 only for its own setting.
    let alg = |method, k| {
        reduce_to_tolerance_alg_14_2_1(&curve, &ToleranceOptions::new(method, 4, 1e-3, k))
    };
    assert!(matches!(alg(l2(1), 1), Err(Error::ConditionNotMet { .. })));
    assert!(matches!(
        alg(Method::Perturb, 1),
        Err(Error::ConditionNotMet { .. })
    ));
    assert!(alg(Method::Perturb, 0).is_ok());
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

    /// Law: for any curve, method with C^k ends and tolerance, the sampled error of the
    /// spline is below its certified bound, the bound below the tolerance, and the joins
    /// are C^k (coordinates in [-10, 10]; the tolerance is relative to that size).
    #[test]
    fn law_bound_meets_tolerance(
        pts in cagd_testkit::points(9, 2),
        w in cagd_testkit::weights(9),
        rational in proptest::bool::ANY,
        e in 2i32..9,
        case in 0usize..4,
    ) {
        let curve = if rational {
            BezierCurve::new_rational(pts, w, 2).unwrap()
        } else {
            BezierCurve::new(pts, 2).unwrap()
        };
        let (method, m, k) = [
            (Method::Perturb, 4, 0),
            (Method::L2 { r: 1, p: 1 }, 4, 1),
            (Method::ConstrainedChebyshev { r: 1, p: 1 }, 3, 1),
            (Method::ConstrainedChebyshev { r: 2, p: 2 }, 5, 2),
        ][case];
        let tol = 10f64.powi(1 - e);
        let opts = ToleranceOptions { measure: true, ..ToleranceOptions::new(method, m, tol, k) };
        let red = reduce_to_tolerance(&curve, &opts).unwrap();
        check_result(&red, &format!("{} k={k} tol={tol:e}", method.name()));
    }
}
