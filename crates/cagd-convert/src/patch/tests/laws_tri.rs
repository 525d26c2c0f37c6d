//! Laws of the triangle conversions (§15.4, §15.5).

use proptest::prelude::*;

use super::{any_tri, assert_exact, assert_tiles};
use crate::patch::{
    PatchSurface, PieceDomain, TriSplitPoints, degenerate_rect_to_triangle,
    triangle_to_degenerate_rect, triangle_to_rect_d1, triangle_to_three_rects,
};
use cagd_core::Error;

/// Relative tolerance of the exactness laws (issue 11).
const EXACT: f64 = 1e-13;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// §15.4: the degenerate rectangle equals the triangle at mapped points, and the inverse
    /// (Theorem 15.4.2) gives the triangle back.
    #[test]
    fn degenerate_rect_round_trip(t in any_tri(0..=12), extra in 0usize..=2) {
        let n = t.degree();
        let piece = triangle_to_degenerate_rect(&t, n + extra).unwrap();
        let input = PatchSurface::Tri(t.clone());
        assert_exact(&input, std::slice::from_ref(&piece), EXACT);
        prop_assert_eq!(&piece.domain, &PieceDomain::Bilinear([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 0.0]]));
        if extra == 0 {
            let PatchSurface::Tensor(r) = &piece.surface else { panic!("tensor expected") };
            let back = degenerate_rect_to_triangle(r, 1e-12).unwrap();
            let sc = super::scale(&input);
            for (a, b) in back.net().points().iter().zip(t.net().points()) {
                prop_assert!((a - b).abs() <= EXACT * sc, "{} vs {}", a, b);
            }
            for (a, b) in back.weights().unwrap_or(&[]).iter().zip(t.weights().unwrap_or(&[])) {
                prop_assert!((a - b).abs() <= EXACT * b.abs().max(1.0));
            }
        }
    }

    /// §15.5: one rectangle over a random admissible D1.
    #[test]
    fn rect_d1_is_exact(t in any_tri(0..=12), a in 0.02f64..0.9, c in 0.02f64..0.9, b in 0.05f64..0.95, d in 0.05f64..0.95) {
        prop_assume!(a + c < 0.98 && a * d + b * c > b * d * 1.01);
        let piece = triangle_to_rect_d1(&t, a, b, c, d).unwrap();
        assert_exact(&PatchSurface::Tri(t), &[piece], EXACT);
    }

    /// §15.5: three rectangles through random P, G, K, H: exact, tiling the triangle, and
    /// neighbours sharing their boundary nets.
    #[test]
    fn three_rects_tile_and_share_edges(
        t in any_tri(0..=12),
        p in (0.05f64..0.9, 0.05f64..0.9),
        g in 0.05f64..0.95, k in 0.05f64..0.95, h in 0.05f64..0.95,
    ) {
        prop_assume!(p.0 + p.1 < 0.95);
        let split = TriSplitPoints { p: [p.0, p.1], g, k, h };
        let pieces = match triangle_to_three_rects(&t, split) {
            Ok(x) => x,
            Err(Error::DegenerateSplit { .. }) => { prop_assume!(false); unreachable!() }
            Err(e) => panic!("{e}"),
        };
        let input = PatchSurface::Tri(t.clone());
        assert_exact(&input, &pieces, EXACT);
        assert_tiles(&pieces, true);
        let n = t.degree();
        let sc = super::scale(&input);
        let nets: Vec<_> = pieces.iter().map(|q| match &q.surface {
            PatchSurface::Tensor(r) => r.homogeneous(),
            PatchSurface::Tri(_) => panic!("tensor expected"),
        }).collect();
        for a in 0..3 {
            let b = (a + 1) % 3;
            for j in 0..=n {
                let (x, y) = (nets[a].point(n, j), nets[b].point(j, n));
                for (p, q) in x.iter().zip(y) {
                    prop_assert!((p - q).abs() <= EXACT * sc * 10.0, "edge {a}/{b}: {p} vs {q}");
                }
            }
        }
    }
}

#[test]
fn default_split_is_centroid_and_midpoints() {
    let s = TriSplitPoints::default();
    assert_eq!((s.g, s.k, s.h), (0.5, 0.5, 0.5));
    assert!((s.p[0] - 1.0 / 3.0).abs() < 1e-16 && (s.p[1] - 1.0 / 3.0).abs() < 1e-16);
}

#[test]
fn folded_quadrilateral_is_degenerate_split() {
    let t = crate::TriSurface::new(vec![0.0, 1.0, 2.0], 1, 1, None).unwrap();
    // P = (0.1, 0.1) with G = (0.5, 0), H = (0, 0.5): a/b + c/d = 0.4 < 1, D1 folds.
    let e = triangle_to_rect_d1(&t, 0.1, 0.5, 0.1, 0.5).unwrap_err();
    assert!(matches!(e, Error::DegenerateSplit { .. }), "{e}");
    let split = TriSplitPoints {
        p: [0.1, 0.1],
        ..Default::default()
    };
    assert!(matches!(
        triangle_to_three_rects(&t, split),
        Err(Error::DegenerateSplit { .. })
    ));
    // P outside the triangle.
    let split = TriSplitPoints {
        p: [0.6, 0.6],
        ..Default::default()
    };
    assert!(matches!(
        triangle_to_three_rects(&t, split),
        Err(Error::BadParameter { .. })
    ));
}
