//! Exact reducibility, rational reports and the error cases of the public API.

use cagd_core::BezierCurve;
use cagd_reduce::{
    DEFAULT_REL_TOL, Error, ErrorSpace, Method, ReduceOptions, exact_degree, reduce, reduce_exact,
    reduce_with,
};
use cagd_testkit::points;
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn exact_degree_detects_elevation(k in 0usize..10, extra in 0usize..30, pts in points(10, 3)) {
        let orig = BezierCurve::new(pts[..(k + 1) * 3].to_vec(), 3).unwrap();
        // Random points of degree k have a non-zero top difference (almost surely).
        prop_assume!(orig.forward_difference().iter().any(|x| x.abs() > 1e-3));
        let elev = orig.elevate(extra).unwrap();
        prop_assert_eq!(exact_degree(&elev, DEFAULT_REL_TOL).unwrap(), k);
        let red = reduce_exact(&elev).unwrap();
        prop_assert_eq!(red.curve.degree(), k);
        let s = orig.points().iter().fold(1.0f64, |m, x| m.max(x.abs()));
        for (a, b) in red.curve.points().iter().zip(orig.points()) {
            prop_assert!((a - b).abs() <= 1e-11 * s, "{} vs {}", a, b);
        }
    }
}

#[test]
fn exact_degree_of_a_perturbed_curve_and_bad_tolerances() {
    let c = BezierCurve::new(vec![0.0, 1.0, 3.0, 2.0], 1)
        .unwrap()
        .elevate(3)
        .unwrap();
    assert_eq!(exact_degree(&c, DEFAULT_REL_TOL).unwrap(), 3);
    let mut pts = c.points().to_vec();
    pts[3] += 1e-6;
    let p = BezierCurve::new(pts, 1).unwrap();
    assert_eq!(exact_degree(&p, DEFAULT_REL_TOL).unwrap(), 6);
    assert_eq!(exact_degree(&p, 1e-3).unwrap(), 3);
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            exact_degree(&c, bad),
            Err(Error::BadTolerance { .. })
        ));
    }
    // A curve of genuinely full degree comes back unchanged.
    let full = BezierCurve::new(vec![0.0, 1.0, 0.0, 1.0], 1).unwrap();
    assert_eq!(reduce_exact(&full).unwrap().curve, full);
}

#[test]
fn rational_reports_name_their_space() {
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let arc = BezierCurve::new_rational(vec![1.0, 0.0, 1.0, 1.0, 0.0, 1.0], vec![1.0, h, 1.0], 2)
        .unwrap()
        .elevate(3)
        .unwrap();
    let mut opts = ReduceOptions::new(Method::L2 { r: 1, p: 1 }, 3);
    opts.measure = true;
    let e = reduce_with(&arc, &opts).unwrap();
    assert_eq!(e.report.space, ErrorSpace::Euclidean);
    assert!(e.report.max_error.unwrap() <= e.report.error_bound.unwrap());
    let hb = e.report.homogeneous_bound.unwrap();
    opts.space = ErrorSpace::Homogeneous;
    let h = reduce_with(&arc, &opts).unwrap();
    assert_eq!(h.report.space, ErrorSpace::Homogeneous);
    // Both bound the homogeneous error: the Euclidean reduction's (found in the curve's
    // frame and carried back) and the homogeneous one's own.
    assert!(h.report.max_error.unwrap() <= h.report.error_bound.unwrap());
    assert!(h.report.max_error.unwrap() <= hb);
    // An exact elevation of a rational curve reduces back exactly.
    let back = reduce(&arc, 2, Method::GeneralizedInverse).unwrap();
    assert!(back.report.error_bound.unwrap() < 1e-13);
}

#[test]
fn errors_for_bad_requests() {
    let c = BezierCurve::new((0..12).map(f64::from).collect(), 2).unwrap(); // degree 5
    assert!(matches!(
        reduce(&c, 5, Method::Eck),
        Err(Error::BadDegreePair { .. })
    ));
    assert!(matches!(
        reduce(&c, 7, Method::Eck),
        Err(Error::BadDegreePair { .. })
    ));
    assert!(matches!(
        reduce(&c, 2, Method::ConstrainedChebyshev { r: 1, p: 1 }),
        Err(Error::TooManyConstraints { .. })
    ));
    assert!(matches!(
        reduce(&c, 2, Method::PerturbG1 { l1: 0.0, l2: 0.0 }),
        Err(Error::BadDegreePair { .. })
    ));
    assert!(matches!(
        reduce(&c, 0, Method::Farin),
        Err(Error::BadDegreePair { .. })
    ));
    assert!(matches!(
        reduce(
            &c,
            4,
            Method::PerturbG1 {
                l1: f64::INFINITY,
                l2: 0.0
            }
        ),
        Err(Error::BadParameter { .. })
    ));
    let small = BezierCurve::new(vec![0.0, 1.0, 2.0, 4.0], 1).unwrap();
    assert!(matches!(
        cagd_reduce::reduce_g1_optimal(&small, false),
        Err(Error::BadDegreePair { .. })
    ));
}
