//! Laws of the rectangle conversions (§15.6, §15.7).

use proptest::prelude::*;

use super::{any_rect, assert_exact, assert_tiles};
use crate::patch::{
    PatchSurface, corner_triangle, curve_split_d7, rect_to_two_triangle_pieces, ruled_subpatch,
    split_along_curve, split_along_line, trapezoid,
};

/// Relative tolerance of the exactness laws (issue 11).
const EXACT: f64 = 1e-13;

/// The control points of a tensor piece.
fn net(p: &crate::PatchPiece) -> Vec<f64> {
    match &p.surface {
        PatchSurface::Tensor(r) => r.homogeneous().points().to_vec(),
        PatchSurface::Tri(_) => panic!("tensor expected"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// §15.6: any line that cuts the square gives pieces that are exact and tile it.
    #[test]
    fn line_split_is_exact_and_tiles(p in any_rect(0..=10, 0..=10), f1 in -3.0f64..3.0, f0 in -1.0f64..2.0) {
        let pieces = split_along_line(&p, f1, f0);
        prop_assume!(pieces.is_ok());
        let pieces = pieces.unwrap();
        assert_exact(&PatchSurface::Tensor(p), &pieces, EXACT);
        assert_tiles(&pieces, false);
    }

    /// §15.6.3: two triangles of degree m + n equal the rectangle and tile it.
    #[test]
    fn two_triangles_are_exact(p in any_rect(0..=10, 0..=10)) {
        let pieces = rect_to_two_triangle_pieces(&p).unwrap();
        assert_exact(&PatchSurface::Tensor(p), &pieces, EXACT);
        assert_tiles(&pieces, false);
    }

    /// §15.7: both sides of a random curve (degree <= 4, coefficients in [0, 1]).
    #[test]
    fn curve_split_is_exact_and_tiles(p in any_rect(0..=8, 0..=8), a in proptest::collection::vec(0.0f64..1.0, 1..=5)) {
        let pieces = split_along_curve(&p, &a).unwrap();
        let (m, n) = p.degrees();
        let k = a.len() - 1;
        match &pieces[0].surface {
            PatchSurface::Tensor(r) => prop_assert_eq!(r.degrees(), (m, k * m + n)),
            PatchSurface::Tri(_) => panic!("tensor expected"),
        }
        assert_exact(&PatchSurface::Tensor(p), &pieces, EXACT);
        assert_tiles(&pieces, false);
    }

    /// §15.7 D7: the curved triangle `u = s f(t)`, `v = b t` for random `f` and `b`.
    #[test]
    fn curve_triangle_d7_is_exact(
        p in any_rect(0..=8, 0..=8),
        a in proptest::collection::vec(0.0f64..1.0, 1..=4),
        b in 0.05f64..1.0,
    ) {
        let mut a = a;
        *a.last_mut().unwrap() = 0.0; // the curve meets u = 0 at v = b
        let piece = curve_split_d7(&p, &a, b).unwrap();
        assert_exact(&PatchSurface::Tensor(p), &[piece], EXACT);
    }

    /// Independent routes: the 15.6.3 blossom formula of the trapezoid equals the corner
    /// cutting of §15.7 with k = 1, and the 15.6.2 corner triangle equals D7 with
    /// a = (a, 0).
    #[test]
    fn line_formulas_equal_corner_cutting(p in any_rect(0..=8, 0..=8), a in 0.01f64..1.0, b in 0.01f64..1.0) {
        let x = net(&trapezoid(&p, a, b).unwrap());
        let y = net(&ruled_subpatch(&p, &[0.0], &[a, b], 0.0, 1.0, false).unwrap());
        let sc = super::scale(&PatchSurface::Tensor(p.clone()));
        for (s, t) in x.iter().zip(&y) {
            prop_assert!((s - t).abs() <= EXACT * sc * 10.0);
        }
        let x = net(&corner_triangle(&p, a, b).unwrap());
        let y = net(&curve_split_d7(&p, &[a, 0.0], b).unwrap());
        for (s, t) in x.iter().zip(&y) {
            prop_assert!((s - t).abs() <= EXACT * sc * 10.0);
        }
    }
}

#[test]
fn lines_that_miss_are_refused() {
    let p = crate::TensorSurface::new(vec![0.0, 1.0, 2.0, 3.0], 1, 1, 1, None).unwrap();
    for (f1, f0) in [
        (0.0, 1.5),
        (0.0, 0.0),
        (0.0, 1.0),
        (1.0, -1.0),
        (-1.0, 0.0),
        (f64::NAN, 0.5),
    ] {
        assert!(split_along_line(&p, f1, f0).is_err(), "{f1} {f0}");
    }
}
