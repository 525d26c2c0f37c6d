//! Tests of knot removal: exact recovery of inserted knots and bounds checked by sampling.

use super::*;
use crate::bspline::insert::tests::curve_strategy;
use proptest::prelude::*;

/// Sampled `max_t ||a(t) - b(t)||_2` on 2001 parameters of the domain.
fn sampled_distance(a: &BSplineCurve, b: &BSplineCurve) -> f64 {
    let (lo, hi) = a.domain();
    (0..=2000)
        .map(|i| {
            let t = lo + (hi - lo) * f64::from(i) / 2000.0;
            let (x, y) = (a.eval(t).unwrap(), b.eval(t).unwrap());
            x.iter()
                .zip(&y)
                .map(|(p, q)| (p - q) * (p - q))
                .sum::<f64>()
                .sqrt()
        })
        .fold(0.0, f64::max)
}

fn scale(c: &BSplineCurve) -> f64 {
    c.points().iter().fold(1.0f64, |m, x| m.max(x.abs()))
}

proptest! {
    #[test]
    fn inserted_knot_is_removed_exactly(c in curve_strategy(), t in 0.02f64..0.98) {
        let finer = c.insert_knot(t, 1).unwrap();
        let back = finer.remove_knot(t, 1, 1e-9 * scale(&c)).unwrap();
        prop_assert_eq!(back.removed, 1);
        prop_assert_eq!(back.curve.knots(), c.knots());
        let s = scale(&c);
        for (x, y) in back.curve.points().iter().zip(c.points()) {
            prop_assert!((x - y).abs() <= 1e-12 * s, "{} vs {}", x, y);
        }
        if let (Some(w1), Some(w0)) = (back.curve.weights(), c.weights()) {
            for (x, y) in w1.iter().zip(w0) {
                prop_assert!((x - y).abs() <= 1e-12 * y.abs().max(1.0));
            }
        }
        // The sweeps do not amplify rounding; for NURBS the bound carries the factor
        // (1 + max|P|) / w_min <= 55 and the homogeneous scale (w <= 5).
        let allowed = if c.is_rational() { 1e-11 * s } else { 1e-13 * s };
        prop_assert!(back.error_bound <= allowed, "bound {} > {}", back.error_bound, allowed);
    }

    #[test]
    fn removal_respects_the_bound(c in curve_strategy(), tol in 0.01f64..5.0) {
        let r = c.remove_knots(tol).unwrap();
        prop_assert!(r.error_bound <= tol);
        prop_assert_eq!(r.curve.n_points() + r.removed, c.n_points());
        let d = sampled_distance(&c, &r.curve);
        prop_assert!(d <= r.error_bound + 1e-12 * scale(&c), "sampled {} > bound {}", d, r.error_bound);
    }
}

#[test]
fn genuine_knot_bound_is_respected_and_tight_enough() {
    // A cubic with a genuine interior knot at 0.5 (not C3 there).
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0];
    let pts = vec![0.0, 0.0, 1.0, 2.0, 2.0, -1.0, 3.0, 2.0, 4.0, 0.0];
    for rational in [false, true] {
        let c = if rational {
            BSplineCurve::new_rational(
                3,
                knots.clone(),
                pts.clone(),
                vec![1.0, 2.0, 0.5, 1.0, 1.0],
                2,
            )
        } else {
            BSplineCurve::new(3, knots.clone(), pts.clone(), 2)
        }
        .unwrap();
        // Too small a tolerance: nothing removed, curve unchanged.
        let none = c.remove_knot(0.5, 1, 1e-3).unwrap();
        assert_eq!(none.removed, 0);
        assert_eq!(none.curve, c);
        let r = c.remove_knot(0.5, 1, 100.0).unwrap();
        assert_eq!(r.removed, 1);
        let d = sampled_distance(&c, &r.curve);
        assert!(
            d > 0.01 && d <= r.error_bound,
            "rational={rational} d={d} bound={}",
            r.error_bound
        );
    }
}

#[test]
fn double_knot_of_a_c0_quadratic() {
    // Quadratic with knot 0.5 of multiplicity 2 (= p) whose middle polygon is straight
    // through the joint with matching speed: the curve is C1 there, so one copy goes.
    let knots = vec![0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0];
    let pts = vec![0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 0.0];
    let c = BSplineCurve::new(2, knots, pts, 2).unwrap();
    let r = c.remove_knot(0.5, 2, 1e-12).unwrap();
    assert_eq!(r.removed, 1);
    assert_eq!(r.curve.knots(), &[0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]);
    assert!(sampled_distance(&c, &r.curve) < 1e-14);
    // Multiplicity p + 1 with coinciding points: removable exactly.
    let k3 = vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0];
    let pts3 = vec![0.0, 1.0, 2.0, 2.0, 3.0, 0.0];
    let c3 = BSplineCurve::new(2, k3, pts3, 1).unwrap();
    let r3 = c3.remove_knot(0.5, 1, 1e-12).unwrap();
    assert_eq!((r3.removed, r3.error_bound), (1, 0.0));
    assert_eq!(r3.curve.points(), &[0.0, 1.0, 2.0, 3.0, 0.0]);
}

#[test]
fn errors() {
    let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], vec![0.0; 4], 1).unwrap();
    for tol in [0.0, -1.0, f64::NAN] {
        assert!(matches!(
            c.remove_knot(0.5, 1, tol),
            Err(Error::BadTolerance { .. })
        ));
        assert!(matches!(
            c.remove_knots(tol),
            Err(Error::BadTolerance { .. })
        ));
    }
    for v in [0.0, 1.0, 0.25, f64::NAN] {
        assert!(matches!(
            c.remove_knot(v, 1, 1.0),
            Err(Error::BadParameter { .. })
        ));
    }
    assert!(matches!(
        c.remove_knot_at(7, 1, 1.0),
        Err(Error::BadParameter { .. })
    ));
    assert_eq!(c.remove_knot_at(3, 1, 1.0).unwrap().removed, 1);
}

/// The NURBS bound is taken about the centre of the control points, so it does not grow
/// when the curve is moved away from the origin (Piegl & Tiller's `eps (1 + max ||P||) /
/// min w` would grow ~1e4 times here), and it stays above the sampled distance.
#[test]
fn rational_bound_is_translation_invariant() {
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0, 1.0];
    let pts = [0.0, 0.0, 1.0, 2.0, 2.5, -1.0, 4.0, 1.5, 5.0, 0.0];
    let w = vec![1.0, 0.7, 1.6, 0.9, 1.0];
    let mut bounds = Vec::new();
    for offset in [0.0, 1e4] {
        let moved: Vec<f64> = pts.iter().map(|x| x + offset).collect();
        let c = BSplineCurve::new_rational(3, knots.clone(), moved, w.clone(), 2).unwrap();
        let out = c.remove_knot(0.4, 1, 100.0).unwrap();
        assert_eq!(out.removed, 1);
        let d = sampled_distance(&c, &out.curve);
        assert!(
            d <= out.error_bound,
            "offset {offset}: {d} > {}",
            out.error_bound
        );
        bounds.push(out.error_bound);
    }
    assert!(bounds[1] < 1.01 * bounds[0], "{bounds:?}");
}

/// Two NURBS curves with different weights on one knot vector, stored side by side as
/// one polynomial curve of homogeneous points (a NURBS surface's columns).
fn rational_bundle(offset: f64) -> BSplineCurve {
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.4, 0.7, 1.0, 1.0, 1.0, 1.0];
    let a = [
        (0.0, 0.0, 1.0),
        (1.0, 2.0, 0.7),
        (2.5, -1.0, 1.6),
        (4.0, 1.5, 0.9),
        (4.5, 0.5, 1.2),
        (5.0, 0.0, 1.0),
    ];
    let b = [
        (0.0, 1.0, 1.0),
        (1.2, 2.5, 1.3),
        (2.0, 0.0, 0.6),
        (3.5, 2.5, 1.1),
        (4.8, 1.0, 0.8),
        (5.5, 1.0, 1.0),
    ];
    let mut pts = Vec::new();
    for (p, q) in a.iter().zip(&b) {
        for (x, y, w) in [p, q] {
            pts.extend([(x + offset) * w, (y + offset) * w, *w]);
        }
    }
    BSplineCurve::new(3, knots, pts, 6).unwrap()
}

/// `max_t ||S(t) - S'(t)||` of the rational combination `sum_j l_j A_j / sum_j l_j W_j` of
/// two homogeneous bundles (blocks of 3), sampled.
fn combination_distance(a: &BSplineCurve, b: &BSplineCurve, l: [f64; 2]) -> f64 {
    let model = |c: &BSplineCurve, t: f64| {
        let h = c.eval(t).unwrap();
        let w = l[0] * h[2] + l[1] * h[5];
        [
            (l[0] * h[0] + l[1] * h[3]) / w,
            (l[0] * h[1] + l[1] * h[4]) / w,
        ]
    };
    (0..=2000)
        .map(|i| {
            let t = f64::from(i) / 2000.0;
            let (x, y) = (model(a, t), model(b, t));
            ((x[0] - y[0]).powi(2) + (x[1] - y[1]).powi(2)).sqrt()
        })
        .fold(0.0, f64::max)
}

#[test]
fn rational_bundle_bound_covers_every_combination() {
    let mut bounds = Vec::new();
    for offset in [0.0, 1e4] {
        let c = rational_bundle(offset);
        // An inserted knot comes out again at rounding cost.
        let finer = c.insert_knot(0.55, 1).unwrap();
        let back = finer.remove_knot_rational_bundle(0.55, 1, 1e-6, 3).unwrap();
        assert_eq!(back.removed, 1);
        assert!(
            back.error_bound < 1e-9 * (1.0 + offset),
            "{}",
            back.error_bound
        );
        // A genuine knot: the bound covers every non-negative combination of the bundle.
        let out = c.remove_knot_rational_bundle(0.4, 1, 100.0, 3).unwrap();
        assert_eq!(out.removed, 1);
        for l in [[1.0, 0.0], [0.0, 1.0], [0.5, 0.5], [0.9, 0.1], [0.2, 3.0]] {
            let d = combination_distance(&c, &out.curve, l);
            assert!(
                d > 0.0 && d <= out.error_bound,
                "{l:?} offset {offset}: {d} > {}",
                out.error_bound
            );
        }
        // A tolerance below the change removes nothing.
        let none = c
            .remove_knot_rational_bundle(0.4, 1, 0.5 * out.error_bound, 3)
            .unwrap();
        assert_eq!((none.removed, &none.curve), (0, &c));
        bounds.push(out.error_bound);
    }
    // Centred: moving the bundle far from the origin does not inflate the bound.
    assert!(bounds[1] < 1.01 * bounds[0], "{bounds:?}");
}

#[test]
fn rational_bundle_errors() {
    let c = rational_bundle(0.0);
    for block in [0, 1, 4] {
        assert!(matches!(
            c.remove_knot_rational_bundle(0.4, 1, 1.0, block),
            Err(Error::BadParameter { name: "block", .. })
        ));
    }
    let mut pts = c.points().to_vec();
    pts[5] = -1.0;
    let bad = BSplineCurve::new(3, c.knots().to_vec(), pts, 6).unwrap();
    assert!(matches!(
        bad.remove_knot_rational_bundle(0.4, 1, 1.0, 3),
        Err(Error::BadParameter {
            name: "weights",
            ..
        })
    ));
    let nurbs = BSplineCurve::new_rational(
        1,
        vec![0.0, 0.0, 0.5, 1.0, 1.0],
        vec![0.0, 1.0, 2.0],
        vec![1.0; 3],
        1,
    )
    .unwrap();
    assert!(nurbs.remove_knot_rational_bundle(0.5, 1, 1.0, 1).is_err());
}
