//! Laws of the WSGB reductions (n <= 30, every admissible L): measured error <= certified
//! bound, the uniform error equals ||lec|| / 2^(2n-1), elevated curves reduce back exactly,
//! the uniform step equals Chebyshev economisation of the Bézier form, bad input.

use num_rational::BigRational;
use num_traits::Zero;
use proptest::prelude::*;

use cagd_core::{
    Error, WsgbCurve, to_exact_points, wsgb_elevate_exact, wsgb_leading_coefficient, wsgb_max_l,
    wsgb_reduced_order,
};

use super::*;
use crate::Method;

fn pseudo_points(n: usize, dim: usize, seed: u64) -> Vec<f64> {
    let mut s = seed ^ 0x9E37_79B9_7F4A_7C15;
    (0..(n + 1) * dim)
        .map(|_| {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 11) as f64 / (1u64 << 53) as f64) * 20.0 - 10.0
        })
        .collect()
}

fn norm2(x: &[f64]) -> f64 {
    x.iter().map(|v| v * v).sum::<f64>().sqrt()
}

fn curve(n: usize, l: usize, dim: usize, seed: u64) -> WsgbCurve {
    WsgbCurve::new(pseudo_points(n, dim, seed), dim, l).unwrap()
}

fn degree_and_order(lo: usize) -> impl Strategy<Value = (usize, usize)> {
    (lo..=30usize).prop_flat_map(|n| (Just(n), 0..=wsgb_max_l(n)))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Measured error <= certified bound, for both seed methods, one degree and several.
    #[test]
    fn measured_error_is_below_the_bound(
        (n, l) in degree_and_order(2), dim in 1usize..=3, seed in any::<u64>(), drop in 1usize..=4,
    ) {
        let c = curve(n, l, dim, seed);
        let m = n.saturating_sub(drop).max(1);
        for method in [WsgbMethod::Perturbation, WsgbMethod::Uniform] {
            let r = reduce_wsgb(&c, m, method).unwrap();
            prop_assert_eq!(r.curve.degree(), m);
            prop_assert_eq!(r.curve.order(), l.min(wsgb_max_l(m)));
            prop_assert!(r.report.max_error.unwrap() <= r.report.error_bound,
                "{:?} n {} L {} m {}: {} > {}", method, n, l, m, r.report.max_error.unwrap(), r.report.error_bound);
            prop_assert_eq!(r.report.steps.len(), n - m);
        }
    }

    /// The uniform method's error (measured, Euclidean) equals ||lec|| / 2^(2n-1) within
    /// 1e-12 relative, above the floor `8 eps max |p_i|` set by rounding the reduced points
    /// to f64; the perturbation error equals its closed form likewise.
    #[test]
    fn one_step_errors_equal_the_closed_forms(
        (n, l) in degree_and_order(2), dim in 1usize..=3, seed in any::<u64>(),
    ) {
        let c = curve(n, l, dim, seed);
        let u = reduce_wsgb(&c, n - 1, WsgbMethod::Uniform).unwrap();
        let want = norm2(&c.leading_coefficient()) / cagd_core::kernel::powu(2.0, 2 * n - 1);
        let floor = 8.0 * f64::EPSILON * c.points().iter().fold(0.0f64, |a, v| a.max(v.abs()));
        prop_assert!((u.report.max_error.unwrap() - want).abs() <= 1e-12 * want + floor,
            "n {} L {}: {} vs {}", n, l, u.report.max_error.unwrap(), want);
        let p = reduce_wsgb(&c, n - 1, WsgbMethod::Perturbation).unwrap();
        let s = &p.report.steps[0];
        prop_assert!((p.report.max_error_inf.unwrap() - s.error_inf).abs() <= 1e-12 * s.error_inf + floor,
            "n {} L {}: {} vs {}", n, l, p.report.max_error_inf.unwrap(), s.error_inf);
        // The Euclidean bound is the closed form plus a rounding allowance only.
        prop_assert!(p.report.error_bound <= p.report.max_error.unwrap() * (1.0 + 1e-9) + 1e-11);
    }

    /// An elevated curve reduces back exactly (exact arithmetic), by both methods, and
    /// within rounding in f64.
    #[test]
    fn elevated_curves_reduce_back((n, l) in degree_and_order(2), seed in any::<u64>()) {
        let lp = wsgb_reduced_order(n, l);
        let low = curve(n - 1, lp, 2, seed);
        let exact = to_exact_points(low.points());
        let high = wsgb_elevate_exact(&exact, 2, lp, l).unwrap();
        prop_assert_eq!(wsgb_perturbation_step(&high, 2, l).unwrap(), exact.clone());
        prop_assert_eq!(wsgb_uniform_step_exact(&high, 2, l).unwrap(), exact);
        let e = low.elevate(l).unwrap();
        for method in [WsgbMethod::Perturbation, WsgbMethod::Uniform] {
            let r = reduce_wsgb(&e, n - 1, method).unwrap();
            prop_assert!(r.report.max_error.unwrap() <= 1e-12 * 10.0);
            prop_assert_eq!(r.curve.order(), lp);
        }
    }

    /// The perturbed points are exactly degenerate, only the middle moves, and the reduced
    /// curve elevated back is exactly the perturbed one (exact arithmetic).
    #[test]
    fn perturbation_is_exact((n, l) in degree_and_order(2), seed in any::<u64>()) {
        let p = to_exact_points(&pseudo_points(n, 2, seed));
        let pert = wsgb_perturbed_points(&p, 2).unwrap();
        prop_assert!(wsgb_leading_coefficient(&pert, 2, l).unwrap().iter().all(Zero::is_zero));
        let moved: Vec<usize> = (0..=n).filter(|&i| pert[2 * i] != p[2 * i] || pert[2 * i + 1] != p[2 * i + 1]).collect();
        prop_assert!(moved.iter().all(|&i| i + 1 >= n / 2 && i <= n / 2 + 1));
        let q = wsgb_perturbation_step(&p, 2, l).unwrap();
        let back = wsgb_elevate_exact(&q, 2, wsgb_reduced_order(n, l), l).unwrap();
        prop_assert_eq!(back, pert);
    }

    /// Independent route for the uniform method (SPEC-reduce §9.5): Chebyshev economisation
    /// of the Bézier form (Eck) gives the same curve.
    #[test]
    fn uniform_equals_bezier_economisation((n, l) in degree_and_order(1), seed in any::<u64>()) {
        let c = curve(n, l, 2, seed);
        let u = reduce_wsgb(&c, n - 1, WsgbMethod::Uniform).unwrap();
        let e = reduce_wsgb(&c, n - 1, WsgbMethod::Bezier(Method::Eck)).unwrap();
        let (d, _) = measure::measure(&u.curve, &e.curve).unwrap();
        prop_assert!(d <= 1e-12 * 10.0, "n {} L {}: {}", n, l, d);
        prop_assert!(e.report.max_error.unwrap() <= e.report.error_bound);
    }
}

#[test]
fn every_bezier_method_applies() {
    let c = curve(9, 2, 3, 7);
    let methods = [
        Method::Forrest,
        Method::PieglTiller,
        Method::Farin,
        Method::Perturb,
        Method::PerturbG1 { l1: 0.0, l2: 0.0 },
        Method::Eck,
        Method::WatkinsWorsey,
        Method::BogackiWeinsteinXu,
        Method::GeneralizedInverse,
        Method::GeneralizedInverseEnds,
        Method::ConstrainedChebyshev { r: 1, p: 1 },
        Method::L2 { r: 0, p: 1 },
    ];
    for m in methods {
        let r = reduce_wsgb(&c, 6, WsgbMethod::Bezier(m)).unwrap();
        assert_eq!((r.curve.degree(), r.curve.order()), (6, 2));
        assert!(
            r.report.max_error.unwrap() <= r.report.error_bound,
            "{}",
            m.name()
        );
        assert!(r.report.bezier.is_some());
    }
    // L2 without constraints = the generalized inverse (both the L2-best curve).
    let a = reduce_wsgb(&c, 5, WsgbMethod::Bezier(Method::L2 { r: -1, p: -1 })).unwrap();
    let b = reduce_wsgb(&c, 5, WsgbMethod::Bezier(Method::GeneralizedInverse)).unwrap();
    let (d, _) = measure::measure(&a.curve, &b.curve).unwrap();
    assert!(d < 1e-10, "{d}");
}

#[test]
fn l2_is_the_l2_best_curve() {
    // Independent check: the L2 residual is orthogonal to every degree-m polynomial, i.e.
    // integral (P - Q) B_j^m = 0, by Gauss–Legendre quadrature (exact for these degrees).
    let c = curve(8, 1, 2, 11);
    let m = 4;
    let r = reduce_wsgb(&c, m, WsgbMethod::Bezier(Method::L2 { r: -1, p: -1 })).unwrap();
    let (nodes, weights) = cagd_core::gauss_legendre(16).unwrap();
    for j in 0..=m {
        for d in 0..2 {
            let mut s = 0.0;
            for (x, w) in nodes.iter().zip(&weights) {
                let e = c.eval(*x)[d] - r.curve.eval(*x)[d];
                s += w * e * cagd_core::kernel::bernstein(m, j, *x);
            }
            assert!(s.abs() < 1e-12, "j {j}: {s}");
        }
    }
}

#[test]
fn to_tolerance_subdivides() {
    let c = curve(10, 3, 2, 3);
    for method in [
        WsgbMethod::Perturbation,
        WsgbMethod::Uniform,
        WsgbMethod::Bezier(Method::L2 { r: 1, p: 1 }),
    ] {
        let r = reduce_wsgb_to_tolerance(&c, 4, method, 1e-3).unwrap();
        assert!(r.pieces.len() > 1);
        assert!(r.error_bound <= 1e-3 && r.max_error <= r.error_bound);
        assert_eq!(r.pieces[0].start, 0.0);
        assert_eq!(r.pieces.last().unwrap().end, 1.0);
        for w in r.pieces.windows(2) {
            assert_eq!(w[0].end, w[1].start);
        }
        // Independent: every piece against the original at its own parameters.
        for p in &r.pieces {
            for k in 0..=50 {
                let s = k as f64 / 50.0;
                let (a, b) = (
                    c.eval(p.start + s * (p.end - p.start)),
                    p.reduction.curve.eval(s),
                );
                assert!(norm2(&[a[0] - b[0], a[1] - b[1]]) <= p.error_bound + 1e-12);
            }
        }
    }
    assert!(matches!(
        reduce_wsgb_to_tolerance(&c, 4, WsgbMethod::Uniform, 0.0),
        Err(Error::BadTolerance { .. })
    ));
}

/// Found by the CLI fuzzer (issue 18): a degree-8 WSGB curve to degree 0 within 1e-6 needs
/// about 10^6 pieces; it ran for minutes and is now refused after `MAX_WSGB_PIECES`.
#[test]
fn to_tolerance_refuses_past_the_piece_limit() {
    let c = curve(8, 3, 2, 5);
    let r = reduce_wsgb_to_tolerance(&c, 0, WsgbMethod::Bezier(Method::Eck), 1e-6);
    assert!(matches!(r, Err(Error::NoConvergence { .. })), "{r:?}");
}

#[test]
fn bad_input_is_a_named_error() {
    let c = curve(5, 1, 2, 1);
    assert!(matches!(
        reduce_wsgb(&c, 5, WsgbMethod::Uniform),
        Err(Error::BadDegreePair { from: 5, to: 5, .. })
    ));
    assert!(matches!(
        reduce_wsgb(&c, 9, WsgbMethod::Perturbation),
        Err(Error::BadDegreePair { .. })
    ));
    assert!(matches!(
        reduce_wsgb(&c, 0, WsgbMethod::Perturbation),
        Err(Error::BadDegreePair { to: 0, .. })
    ));
    let line = curve(1, 0, 2, 1);
    assert!(matches!(
        reduce_wsgb(&line, 0, WsgbMethod::Perturbation),
        Err(Error::BadDegreePair { from: 1, .. })
    ));
    let r = reduce_wsgb(&line, 0, WsgbMethod::Uniform).unwrap();
    assert_eq!(r.curve.degree(), 0);
    assert!(r.report.max_error.unwrap() <= r.report.error_bound);
    assert!(matches!(
        wsgb_perturbed_points(&[BigRational::zero(), BigRational::zero()], 1),
        Err(Error::BadDegreePair { .. })
    ));
    assert!(matches!(
        wsgb_chebyshev_coefficients(6, 3),
        Err(Error::BadParameter { name: "L", .. })
    ));
    assert!(matches!(
        reduce_wsgb(
            &c,
            2,
            WsgbMethod::Bezier(Method::PerturbG1 { l1: 0.0, l2: 0.0 })
        ),
        Err(Error::BadDegreePair { .. })
    ));
}
