//! Tests of B-spline / NURBS surfaces: validation, evaluation against curves, insertion and
//! Bézier extraction laws.

use super::*;
use crate::BSplineCurve;
use crate::kernel::bernstein_all;
use proptest::prelude::*;

/// Relative tolerance of the preservation laws (convex-combination algorithms).
const LAW: f64 = 1e-12;

fn surface_strategy() -> impl Strategy<Value = BSplineSurface> {
    (
        1usize..=3,
        1usize..=3,
        0usize..=3,
        0usize..=3,
        1usize..=3,
        any::<bool>(),
    )
        .prop_flat_map(|(p, q, eu, ev, dim, rational)| {
            let (nu, nv) = (p + 1 + eu, q + 1 + ev);
            (
                Just((p, q, nu, nv, dim, rational)),
                cagd_testkit::clamped_knots(nu, p),
                cagd_testkit::clamped_knots(nv, q),
                cagd_testkit::points(nu * nv, dim),
                cagd_testkit::weights(nu * nv),
            )
        })
        .prop_map(|((p, q, nu, nv, dim, rational), ku, kv, pts, w)| {
            if rational {
                BSplineSurface::new_rational((p, q), ku, kv, pts, w, (nu, nv), dim).unwrap()
            } else {
                BSplineSurface::new((p, q), ku, kv, pts, (nu, nv), dim).unwrap()
            }
        })
}

fn scale(s: &BSplineSurface) -> f64 {
    s.points().iter().fold(1.0f64, |m, x| m.max(x.abs()))
}

fn assert_same_surface(a: &BSplineSurface, b: &BSplineSurface) {
    let ((u0, u1), (v0, v1)) = a.domain();
    let s = scale(a);
    for i in 0..=15 {
        for j in 0..=15 {
            let u = u0 + (u1 - u0) * f64::from(i) / 15.0;
            let v = v0 + (v1 - v0) * f64::from(j) / 15.0;
            let (x, y) = (a.eval(u, v).unwrap(), b.eval(u, v).unwrap());
            for (xi, yi) in x.iter().zip(&y) {
                assert!((xi - yi).abs() <= LAW * s, "({u}, {v}): {x:?} vs {y:?}");
            }
        }
    }
}

/// Evaluates a (rational) Bézier piece by its Bernstein sums.
fn eval_piece(piece: &SurfacePatchPiece, s: f64, t: f64) -> Vec<f64> {
    let ((p, q), dim) = (piece.patch.degrees(), piece.patch.dim());
    let (mut bu, mut bv) = (vec![0.0; p + 1], vec![0.0; q + 1]);
    bernstein_all(p, s, &mut bu);
    bernstein_all(q, t, &mut bv);
    let (mut num, mut den) = (vec![0.0; dim], 0.0);
    for i in 0..=p {
        for j in 0..=q {
            let w = piece.weights.as_ref().map_or(1.0, |w| w[i * (q + 1) + j]);
            let b = bu[i] * bv[j] * w;
            den += b;
            for (k, x) in piece.patch.point(i, j).iter().enumerate() {
                num[k] += b * x;
            }
        }
    }
    num.iter().map(|x| x / den).collect()
}

proptest! {
    #[test]
    fn insertion_preserves_the_surface(s in surface_strategy(), t in 0.0f64..=1.0, r in 1usize..=2) {
        let (p, q) = s.degrees();
        prop_assume!(knot_multiplicity(s.knots_u(), t) + r <= p + 1);
        prop_assume!(knot_multiplicity(s.knots_v(), t) + r <= q + 1);
        let su = s.insert_knot_u(t, r).unwrap();
        prop_assert_eq!(su.counts().0, s.counts().0 + r);
        assert_same_surface(&s, &su);
        let sv = s.insert_knot_v(t, r).unwrap();
        prop_assert_eq!(sv.counts().1, s.counts().1 + r);
        assert_same_surface(&s, &sv);
    }

    #[test]
    fn refinement_equals_one_insertion_after_another(
        s in surface_strategy(),
        ts in proptest::collection::vec(0.01f64..0.99, 1..8),
    ) {
        let (p, q) = s.degrees();
        let ((u0, u1), (v0, v1)) = s.domain();
        let xu: Vec<f64> = ts.iter().map(|t| u0 + (u1 - u0) * t).collect();
        let xv: Vec<f64> = ts.iter().map(|t| v0 + (v1 - v0) * t).collect();
        prop_assume!(xu.iter().all(|t| knot_multiplicity(s.knots_u(), *t) == 0) && p >= 1);
        prop_assume!(xv.iter().all(|t| knot_multiplicity(s.knots_v(), *t) == 0) && q >= 1);
        let ru = s.refine_knots_u(&xu).unwrap();
        let rv = s.refine_knots_v(&xv).unwrap();
        let (mut su, mut sv) = (s.clone(), s.clone());
        for (a, b) in xu.iter().zip(&xv) {
            su = su.insert_knot_u(*a, 1).unwrap();
            sv = sv.insert_knot_v(*b, 1).unwrap();
        }
        prop_assert_eq!(ru.knots_u(), su.knots_u());
        prop_assert_eq!(rv.knots_v(), sv.knots_v());
        let sc = scale(&s);
        for (x, y) in [(&ru, &su), (&rv, &sv)] {
            prop_assert_eq!(x.counts(), y.counts());
            for (a, b) in x.points().iter().zip(y.points()) {
                prop_assert!((a - b).abs() <= 1e-12 * sc, "{} vs {}", a, b);
            }
        }
        assert_same_surface(&s, &ru);
        assert_same_surface(&s, &rv);
    }

    #[test]
    fn pieces_evaluate_to_the_surface(s in surface_strategy()) {
        let pieces = s.to_beziers().unwrap();
        let sc = scale(&s);
        for piece in &pieces {
            prop_assert_eq!(piece.weights.is_some(), s.is_rational());
            for (a, b) in [(0.0, 0.0), (0.3, 0.7), (1.0, 0.5), (1.0, 1.0)] {
                let (u, v) = (piece.u.0 + a * (piece.u.1 - piece.u.0), piece.v.0 + b * (piece.v.1 - piece.v.0));
                let x = eval_piece(piece, a, b);
                let y = s.eval(u, v).unwrap();
                // Parameter rounding on short spans: allow a speed term as for curves.
                let du = s.eval(u + 1e-7, v).unwrap();
                let dv = s.eval(u, v + 1e-7).unwrap();
                let speed = x.iter().enumerate().fold(0.0f64, |m, (k, _)| {
                    m.max(((du[k] - y[k]) / 1e-7).abs()).max(((dv[k] - y[k]) / 1e-7).abs())
                });
                for (xi, yi) in x.iter().zip(&y) {
                    prop_assert!((xi - yi).abs() <= 1e-12 * sc + 8.0 * f64::EPSILON * speed,
                        "({}, {}) {:?} {:?}", u, v, x, y);
                }
            }
        }
    }
}

#[test]
fn iso_curves_are_b_spline_curves() {
    // With v fixed at a clamped end, S(u, v0) is the curve of row j = 0 (the first column).
    let ku = vec![0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0];
    let kv = vec![0.0, 0.0, 1.0, 1.0];
    let pts: Vec<f64> = (0..8).map(|i| f64::from(i * i % 7)).collect();
    let w: Vec<f64> = (0..8).map(|i| 1.0 + f64::from(i) / 4.0).collect();
    let s = BSplineSurface::new_rational((2, 1), ku.clone(), kv, pts.clone(), w.clone(), (4, 2), 1)
        .unwrap();
    let col0: Vec<f64> = (0..4).map(|i| pts[2 * i]).collect();
    let w0: Vec<f64> = (0..4).map(|i| w[2 * i]).collect();
    let c = BSplineCurve::new_rational(2, ku, col0, w0, 1).unwrap();
    for i in 0..=10 {
        let u = f64::from(i) / 10.0;
        let (a, b) = (s.eval(u, 0.0).unwrap()[0], c.eval(u).unwrap()[0]);
        assert!((a - b).abs() < 1e-14, "{a} {b}");
    }
    let pieces = s.to_beziers().unwrap();
    assert_eq!(pieces.len(), 2);
    assert_eq!(
        (pieces[0].u, pieces[1].u, pieces[1].v),
        ((0.0, 0.4), (0.4, 1.0), (0.0, 1.0))
    );
}

#[test]
fn bad_input_gives_the_matching_variant() {
    let k = || vec![0.0, 0.0, 1.0, 1.0];
    let pts = || vec![0.0; 8];
    assert!(BSplineSurface::new((1, 1), k(), k(), pts(), (2, 2), 2).is_ok());
    let mut nan = pts();
    nan[5] = f64::NAN;
    assert!(matches!(
        BSplineSurface::new((1, 1), k(), k(), nan, (2, 2), 2),
        Err(Error::NonFinite {
            index: 2,
            coord: 1,
            ..
        })
    ));
    assert!(matches!(
        BSplineSurface::new((1, 1), k(), k(), pts(), (2, 3), 2),
        Err(Error::LengthMismatch { .. })
    ));
    assert!(matches!(
        BSplineSurface::new((1, 1), k(), k(), vec![], (2, 2), 2),
        Err(Error::NotEnoughPoints { .. })
    ));
    assert_eq!(
        BSplineSurface::new((1, 1), k(), k(), pts(), (2, 2), 0),
        Err(Error::ZeroDimension)
    );
    assert!(matches!(
        BSplineSurface::new((1, 1), vec![0.0, 1.0, 0.5, 1.0], k(), pts(), (2, 2), 2),
        Err(Error::KnotsNotNondecreasing { index: 2 })
    ));
    assert!(matches!(
        BSplineSurface::new((1, 1), k(), vec![0.0, 1.0, 1.0], pts(), (2, 2), 2),
        Err(Error::KnotCount { .. })
    ));
    assert!(matches!(
        BSplineSurface::new((65, 1), k(), k(), pts(), (2, 2), 2),
        Err(Error::DegreeOutOfRange { .. })
    ));
    assert!(matches!(
        BSplineSurface::new_rational((1, 1), k(), k(), pts(), vec![1.0, 1.0, 0.0, 1.0], (2, 2), 2),
        Err(Error::NonPositiveWeight { index: 2, .. })
    ));
    assert!(matches!(
        BSplineSurface::new_rational((1, 1), k(), k(), pts(), vec![1.0; 3], (2, 2), 2),
        Err(Error::LengthMismatch { .. })
    ));
    let s = BSplineSurface::new((1, 1), k(), k(), pts(), (2, 2), 2).unwrap();
    assert!(matches!(
        s.eval(f64::NAN, 0.0),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(
        s.insert_knot_u(2.0, 1),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(
        s.insert_knot_v(0.5, 3),
        Err(Error::MultiplicityAboveDegree { .. })
    ));
}
