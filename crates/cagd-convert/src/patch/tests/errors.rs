//! Bad input gives a named error, never a panic.

use cagd_core::Error;

use crate::patch::{
    TensorSurface, TriSurface, curve_split_d5, curve_split_d7, degenerate_rect_to_triangle,
    trapezoid, triangle_to_degenerate_rect,
};

#[test]
fn bad_nets_are_named() {
    assert!(matches!(
        TriSurface::new(vec![0.0, f64::NAN, 1.0], 1, 1, None),
        Err(Error::NonFinite { index: 1, .. })
    ));
    assert!(matches!(
        TriSurface::new(vec![0.0, 1.0], 1, 1, None),
        Err(Error::LengthMismatch { .. })
    ));
    assert!(matches!(
        TriSurface::new(vec![0.0, 1.0, 2.0], 1, 1, Some(vec![1.0, -0.5, 1.0])),
        Err(Error::NonPositiveWeight { index: 1, .. })
    ));
    assert!(matches!(
        TensorSurface::new(vec![0.0; 4], 1, 1, 1, Some(vec![1.0, 1.0, 0.0, 1.0])),
        Err(Error::NonPositiveWeight { index: 2, .. })
    ));
    assert!(matches!(
        TensorSurface::new(vec![0.0; 5], 1, 1, 1, None),
        Err(Error::LengthMismatch { .. })
    ));
}

#[test]
fn bad_parameters_are_named() {
    let p = TensorSurface::new(vec![0.0, 1.0, 2.0, 3.0], 1, 1, 1, None).unwrap();
    for (a, b) in [
        (-0.1, 0.5),
        (0.5, 1.1),
        (f64::NAN, 0.5),
        (0.5, f64::INFINITY),
    ] {
        assert!(
            matches!(trapezoid(&p, a, b), Err(Error::BadParameter { .. })),
            "{a} {b}"
        );
    }
    assert!(matches!(
        curve_split_d5(&p, &[0.5, 1.5, 0.5, 1.2]),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(
        curve_split_d5(&p, &[]),
        Err(Error::NotEnoughPoints { .. })
    ));
    assert!(matches!(
        curve_split_d7(&p, &[0.5, 0.0], 0.0),
        Err(Error::BadParameter { .. })
    ));
    let t = TriSurface::new(vec![0.0, 1.0, 2.0], 1, 1, None).unwrap();
    assert!(matches!(
        triangle_to_degenerate_rect(&t, 0),
        Err(Error::BadDegreePair { .. })
    ));
}

#[test]
fn not_degenerate_reports_the_residual() {
    // Row 1 of a 1 x 1 net must be constant (degree 0); here it is not.
    let p = TensorSurface::new(vec![0.0, 1.0, 2.0, 3.0], 1, 1, 1, None).unwrap();
    match degenerate_rect_to_triangle(&p, 1e-12) {
        Err(Error::NotDegenerate { residual, tol }) => {
            assert!(residual > 0.1, "{residual}");
            assert_eq!(tol, 1e-12);
        }
        other => panic!("{other:?}"),
    }
    let p = TensorSurface::new(vec![0.0, 1.0, 2.0, 3.0], 1, 2, 1, None).unwrap_err();
    let _ = p;
    let rect = TensorSurface::new(vec![0.0; 6], 1, 2, 1, None).unwrap();
    assert!(matches!(
        degenerate_rect_to_triangle(&rect, 1e-12),
        Err(Error::BadDegreePair { .. })
    ));
    assert!(matches!(
        degenerate_rect_to_triangle(&rect, -1.0),
        Err(Error::BadTolerance { .. })
    ));
}
