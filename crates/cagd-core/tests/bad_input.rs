//! Every kind of bad input named by the foundation issue, through every constructor: the
//! matching error variant, never a panic.

use cagd_core::{BSplineCurve, BSplineSurface, BezierCurve, Error, TensorPatch, TriPatch};

const NAN: f64 = f64::NAN;

#[test]
fn bezier_curves() {
    let ok = vec![0.0, 0.0, 1.0, 1.0, 2.0, 0.0];
    assert!(matches!(
        BezierCurve::new(vec![0.0, 0.0, NAN, 1.0], 2),
        Err(Error::NonFinite {
            index: 1,
            coord: 0,
            ..
        })
    ));
    assert!(matches!(
        BezierCurve::new(vec![0.0, f64::INFINITY], 2),
        Err(Error::NonFinite {
            index: 0,
            coord: 1,
            ..
        })
    ));
    assert_eq!(
        BezierCurve::new(vec![], 2),
        Err(Error::NotEnoughPoints { got: 0, need: 1 })
    );
    assert_eq!(BezierCurve::new(ok.clone(), 0), Err(Error::ZeroDimension));
    assert!(matches!(
        BezierCurve::new(vec![0.0; 5], 2),
        Err(Error::LengthMismatch { .. })
    ));
    assert_eq!(
        BezierCurve::new(vec![0.0; 66], 1),
        Err(Error::DegreeOutOfRange {
            degree: 65,
            max: 64
        })
    );
    assert!(BezierCurve::new(vec![0.0; 65], 1).is_ok());
    for (w, index) in [
        (vec![1.0, 0.0, 1.0], 1),
        (vec![-0.5, 1.0, 1.0], 0),
        (vec![1.0, 1.0, NAN], 2),
    ] {
        assert!(
            matches!(
                BezierCurve::new_rational(ok.clone(), w.clone(), 2),
                Err(Error::NonPositiveWeight { index: i, .. }) if i == index
            ),
            "{w:?}"
        );
    }
    assert!(matches!(
        BezierCurve::new_rational(ok.clone(), vec![1.0, 1.0], 2),
        Err(Error::LengthMismatch {
            what: "weights",
            got: 2,
            expected: 3
        })
    ));
    assert!(matches!(
        BezierCurve::from_homogeneous(&[0.0, 1.0, 1.0, -1.0], 2),
        Err(Error::NonPositiveWeight { index: 1, .. })
    ));
    let c = BezierCurve::new(ok, 2).expect("valid");
    assert!(matches!(c.subdivide(NAN), Err(Error::BadParameter { .. })));
    assert!(matches!(
        c.segment(0.6, 0.4),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(
        c.derivatives(f64::INFINITY, 1),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(
        c.elevate(63),
        Err(Error::DegreeOutOfRange { degree: 65, .. })
    ));
}

#[test]
fn patches() {
    assert!(matches!(
        TensorPatch::new(vec![0.0; 4], 1, 1, 1).map(|p| p.degrees()),
        Ok((1, 1))
    ));
    assert!(matches!(
        TensorPatch::new(vec![0.0; 5], 1, 1, 1),
        Err(Error::LengthMismatch {
            got: 5,
            expected: 4,
            ..
        })
    ));
    assert!(matches!(
        TensorPatch::new(vec![0.0, NAN, 0.0, 0.0], 1, 1, 1),
        Err(Error::NonFinite { index: 1, .. })
    ));
    assert_eq!(
        TensorPatch::new(vec![0.0; 66], 65, 0, 1),
        Err(Error::DegreeOutOfRange {
            degree: 65,
            max: 64
        })
    );
    assert_eq!(
        TensorPatch::new(vec![0.0; 4], 1, 1, 0),
        Err(Error::ZeroDimension)
    );
    assert!(matches!(
        TriPatch::new(vec![0.0; 5], 2, 1),
        Err(Error::LengthMismatch {
            got: 5,
            expected: 6,
            ..
        })
    ));
    assert!(matches!(
        TriPatch::new(vec![0.0; 3], 1, 0),
        Err(Error::ZeroDimension)
    ));
    assert!(matches!(
        TriPatch::new(vec![], 1, 1),
        Err(Error::NotEnoughPoints { .. })
    ));
    assert!(matches!(
        TriPatch::new(vec![0.0; 2211], 65, 1),
        Err(Error::DegreeOutOfRange { degree: 65, .. })
    ));
}

#[test]
fn bspline_curves() {
    let pts = vec![0.0, 0.0, 1.0, 1.0, 2.0, 0.0, 3.0, 1.0];
    let knots = vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
    assert!(BSplineCurve::new(2, knots.clone(), pts.clone(), 2).is_ok());
    assert!(matches!(
        BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.6, 0.5, 1.0, 1.0], pts.clone(), 2),
        Err(Error::KnotsNotNondecreasing { index: 4 })
    ));
    assert!(matches!(
        BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], pts.clone(), 2),
        Err(Error::KnotCount {
            got: 6,
            expected: 7
        })
    ));
    assert!(matches!(
        BSplineCurve::new(1, vec![0.0, 0.5, 0.5, 0.5, 1.0, 1.0], pts.clone(), 2),
        Err(Error::MultiplicityAboveDegree {
            mult: 3,
            degree: 1,
            ..
        })
    ));
    assert!(matches!(
        BSplineCurve::new(2, vec![0.0, 0.0, 0.0, NAN, 1.0, 1.0, 1.0], pts.clone(), 2),
        Err(Error::NonFiniteKnot { index: 3, .. })
    ));
    assert!(matches!(
        BSplineCurve::new(
            2,
            knots.clone(),
            vec![0.0, 0.0, NAN, 1.0, 2.0, 0.0, 3.0, 1.0],
            2
        ),
        Err(Error::NonFinite {
            index: 1,
            coord: 0,
            ..
        })
    ));
    assert!(matches!(
        BSplineCurve::new(65, vec![0.0; 132], vec![0.0; 66], 1),
        Err(Error::DegreeOutOfRange { degree: 65, .. })
    ));
    assert!(matches!(
        BSplineCurve::new(2, knots.clone(), vec![], 2),
        Err(Error::NotEnoughPoints { .. })
    ));
    assert!(matches!(
        BSplineCurve::new(2, knots.clone(), pts.clone(), 0),
        Err(Error::ZeroDimension)
    ));
    assert!(matches!(
        BSplineCurve::new_rational(2, knots.clone(), pts.clone(), vec![1.0, 0.0, 1.0, 1.0], 2),
        Err(Error::NonPositiveWeight { index: 1, .. })
    ));
    assert!(matches!(
        BSplineCurve::new_rational(2, knots, pts, vec![1.0, 1.0], 2),
        Err(Error::LengthMismatch { .. })
    ));
}

#[test]
fn bspline_surfaces() {
    let k = vec![0.0, 0.0, 1.0, 1.0];
    let pts = vec![0.0; 4];
    assert!(BSplineSurface::new((1, 1), k.clone(), k.clone(), pts.clone(), (2, 2), 1).is_ok());
    assert!(matches!(
        BSplineSurface::new(
            (1, 1),
            vec![0.0, 1.0, 0.0, 1.0],
            k.clone(),
            pts.clone(),
            (2, 2),
            1
        ),
        Err(Error::KnotsNotNondecreasing { .. })
    ));
    assert!(matches!(
        BSplineSurface::new((1, 1), k.clone(), k.clone(), vec![0.0; 3], (2, 2), 1),
        Err(Error::LengthMismatch { .. })
    ));
    assert!(matches!(
        BSplineSurface::new_rational(
            (1, 1),
            k.clone(),
            k,
            pts,
            vec![1.0, 1.0, -1.0, 1.0],
            (2, 2),
            1
        ),
        Err(Error::NonPositiveWeight { index: 2, .. })
    ));
}
