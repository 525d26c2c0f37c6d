//! Tests of the WSGB curve: evaluation against the basis terms and against de Casteljau on
//! the Bézier form, the leading coefficient against the Bézier forward difference, the
//! inverse elevation against the exact elevation, conversion round trips, bad input.

use num_rational::BigRational;
use num_traits::Zero;
use proptest::prelude::*;

use super::*;
use crate::{BezierCurve, Error, wsgb_max_l, wsgb_terms};

const P7: [f64; 16] = [
    220., 110., 160., 220., 180., 340., 260., 400., 355., 425., 470., 320., 490., 200., 420., 100.,
];

fn terms_eval(c: &WsgbCurve, u: f64) -> Vec<f64> {
    let t = wsgb_terms(c.degree(), c.order()).unwrap();
    let mut out = vec![0.0; c.dim()];
    for (i, b) in t.iter().enumerate() {
        for (o, p) in out.iter_mut().zip(c.point(i)) {
            *o += b.eval(u) * p;
        }
    }
    out
}

fn max_abs(x: &[f64]) -> f64 {
    x.iter().fold(0.0f64, |a, v| a.max(v.abs()))
}

fn pseudo_points(n: usize, dim: usize, seed: u64) -> Vec<f64> {
    let mut s = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (0..(n + 1) * dim)
        .map(|_| {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 11) as f64 / (1u64 << 53) as f64) * 20.0 - 10.0
        })
        .collect()
}

#[test]
fn peeling_evaluation_equals_the_basis_terms_and_de_casteljau() {
    for n in 0..=24 {
        for l in 0..=wsgb_max_l(n) {
            for dim in [1, 3] {
                let c = WsgbCurve::new(pseudo_points(n, dim, (n * 31 + l) as u64), dim, l).unwrap();
                let b = c.to_bezier().unwrap();
                let scale = max_abs(c.points()).max(1.0);
                for k in 0..=20 {
                    let u = k as f64 / 20.0;
                    let (x, y, z) = (c.eval(u), terms_eval(&c, u), b.eval(u));
                    for d in 0..dim {
                        assert!((x[d] - y[d]).abs() <= 1e-13 * scale, "n {n} L {l} u {u}");
                        assert!((x[d] - z[d]).abs() <= 1e-12 * scale, "n {n} L {l} u {u}");
                    }
                }
            }
        }
    }
}

#[test]
fn leading_coefficient_is_the_bezier_forward_difference() {
    for n in 1..=20 {
        for l in 0..=wsgb_max_l(n) {
            let c = WsgbCurve::new(pseudo_points(n, 2, (7 * n + l) as u64), 2, l).unwrap();
            // Exact route: Bézier points exactly, then Delta^n b_0 exactly.
            let b = wsgb_to_bezier_exact(&to_exact_points(c.points()), 2, l).unwrap();
            let ex = wsgb_leading_coefficient(&to_exact_points(c.points()), 2, l).unwrap();
            for d in 0..2 {
                let mut delta = BigRational::zero();
                for i in 0..=n {
                    let s = BigRational::from_integer(crate::binomial(n, i).into());
                    let term = s * &b[i * 2 + d];
                    if (n - i) % 2 == 0 {
                        delta += term;
                    } else {
                        delta -= term;
                    }
                }
                assert_eq!(delta, ex[d], "n {n} L {l}");
            }
        }
    }
}

#[test]
fn paper_example_leading_coefficients() {
    // SPEC-reduce §9.6 vectors wsgb-7-1-*: lec = (-1140, -300).
    let c = WsgbCurve::new(P7.to_vec(), 2, 1).unwrap();
    assert_eq!(c.leading_coefficient(), vec![-1140.0, -300.0]);
    assert!(!c.is_degenerate());
}

#[test]
fn inverse_elevation_undoes_the_exact_elevation() {
    // SPEC-reduce §9.3, checked against the exact elevation for every n <= 14 and L.
    for n in 1..=14 {
        for l in 0..=wsgb_max_l(n) {
            let lp = wsgb_reduced_order(n, l);
            let p = to_exact_points(&pseudo_points(n - 1, 2, (n * 13 + l) as u64));
            let e = wsgb_elevate_exact(&p, 2, lp, l).unwrap();
            let lec = wsgb_leading_coefficient(&e, 2, l).unwrap();
            assert!(
                lec.iter().all(Zero::is_zero),
                "n {n} L {l}: elevated is degenerate"
            );
            let q = wsgb_inverse_elevation(&e, 2, l).unwrap();
            assert_eq!(q, p, "n {n} L {l}");
        }
    }
}

#[test]
fn the_printed_reduced_points_are_wrong_for_middle_orders() {
    // ERRATUM of SPEC-reduce §9.3: for n = 2m, 1 <= L <= m-2 the seed's q_i = p_i (i <= m-2)
    // is false. n = 8 (m = 4), L = 1: the exact inverse differs from p at i = 2.
    let p = to_exact_points(&pseudo_points(7, 1, 5));
    let e = wsgb_elevate_exact(&p, 1, 1, 1).unwrap();
    assert_ne!(e[2], p[2]);
    assert_eq!(wsgb_inverse_elevation(&e, 1, 1).unwrap(), p);
}

#[test]
fn curve_level_degeneracy_and_elevation() {
    // Odd target degree: the elevated middle points are equal exact values, so they stay
    // equal after rounding and the f64 curve is exactly degenerate.
    let c6 = WsgbCurve::new(P7[..14].to_vec(), 2, 1).unwrap();
    for l in 0..=wsgb_max_l(7) {
        let e = c6.elevate(l).unwrap();
        assert!(e.is_degenerate(), "L {l}");
        let back = e.inverse_elevate().unwrap();
        assert_eq!(back.degree(), 6);
        let again = back.with_order(1).unwrap();
        for (x, y) in again.points().iter().zip(c6.points()) {
            assert!((x - y).abs() <= 1e-12 * 500.0, "L {l}");
        }
    }
    // Even target degree: degenerate up to the rounding of the elevated points.
    let c = WsgbCurve::new(P7.to_vec(), 2, 1).unwrap();
    for l in 0..=wsgb_max_l(8) {
        let e = c.elevate(l).unwrap();
        assert!(max_abs(&e.leading_coefficient()) <= 1e-9 * 500.0);
    }
    assert!(matches!(
        c.inverse_elevate(),
        Err(Error::ConditionNotMet { .. })
    ));
}

#[test]
fn named_cases_and_bad_input() {
    let s = WsgbCurve::said_ball(P7.to_vec(), 2).unwrap();
    assert!(s.is_said_ball() && !s.is_wang_ball());
    let w = WsgbCurve::wang_ball(P7.to_vec(), 2).unwrap();
    assert_eq!(w.order(), 2);
    assert!(w.is_wang_ball());
    assert!(matches!(
        WsgbCurve::new(P7.to_vec(), 2, 3),
        Err(Error::BadParameter { name: "L", value, .. }) if value == 3.0
    ));
    let mut bad = P7.to_vec();
    bad[5] = f64::NAN;
    assert!(matches!(
        WsgbCurve::new(bad, 2, 1),
        Err(Error::NonFinite {
            index: 2,
            coord: 1,
            ..
        })
    ));
    assert!(matches!(
        WsgbCurve::new(vec![0.0; 66], 1, 0),
        Err(Error::DegreeOutOfRange { degree: 65, .. })
    ));
    assert!(matches!(
        WsgbCurve::new(vec![], 2, 0),
        Err(Error::NotEnoughPoints { .. })
    ));
    let rational = BezierCurve::new_rational(vec![0.0, 1.0, 2.0], vec![1.0, 2.0, 1.0], 1).unwrap();
    assert!(WsgbCurve::from_bezier(&rational, 0).is_err());
    assert!(matches!(
        WsgbCurve::new(vec![0.0, 1.0], 1, 0)
            .unwrap()
            .inverse_elevate(),
        Err(Error::ConditionNotMet { .. })
    ));
    assert!(
        WsgbCurve::new(vec![1.0], 1, 0)
            .unwrap()
            .inverse_elevate()
            .is_err()
    );
}

fn degree_and_order() -> impl Strategy<Value = (usize, usize)> {
    (1usize..=30).prop_flat_map(|n| (Just(n), 0..=wsgb_max_l(n)))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Bézier -> WSGB -> Bézier within 1e-13 relative (to the larger coordinate of the two
    /// representations) on the points; WSGB -> Bézier -> WSGB within 1e-13 relative as
    /// curves (the WSGB points themselves carry the rounding of the Bézier points times the
    /// conditioning of Bézier -> WSGB, see the docs of `Basis`). n <= 30, every L.
    #[test]
    fn round_trips((n, l) in degree_and_order(), dim in 1usize..=3, seed in any::<u64>()) {
        let pts = pseudo_points(n, dim, seed);
        let b = BezierCurve::new(pts.clone(), dim).unwrap();
        let w = WsgbCurve::from_bezier(&b, l).unwrap();
        let back = w.to_bezier().unwrap();
        let scale = max_abs(&pts).max(max_abs(w.points()));
        for (x, y) in back.points().iter().zip(&pts) {
            prop_assert!((x - y).abs() <= 1e-13 * scale, "n {} L {}: {} vs {}", n, l, x, y);
        }
        let c = WsgbCurve::new(pts.clone(), dim, l).unwrap();
        let bc = c.to_bezier().unwrap();
        let again = WsgbCurve::from_bezier(&bc, l).unwrap();
        let scale = max_abs(&pts).max(max_abs(bc.points()));
        // The difference curve, exactly in Bézier form: its control points bound it.
        let diff: Vec<BigRational> = to_exact_points(again.points())
            .iter()
            .zip(to_exact_points(&pts))
            .map(|(a, b)| a - b)
            .collect();
        let db = round_exact_points(&wsgb_to_bezier_exact(&diff, dim, l).unwrap());
        prop_assert!(max_abs(&db) <= 1e-13 * scale, "n {} L {}: {}", n, l, max_abs(&db));
    }
}
