//! The continuity decision and the certificate of `pieces_to_nurbs` at the edge of the
//! tolerance: a joint perturbed just above / just below `tol` changes / keeps the
//! multiplicity, and an altered piece either lowers the continuity or shows in a bound that
//! still holds (measured by evaluating both shapes, an independent route).

use cagd_core::BSplineCurve;

use crate::{BezierPieces, pieces_to_nurbs, to_bezier_pieces};

/// A clamped polynomial 2-D spline of degree `p` with `spans` uniform simple spans and
/// points of size ~1 (deterministic).
fn spline(p: usize, spans: usize) -> BSplineCurve {
    let n = spans + p;
    let mut knots = vec![0.0; p + 1];
    knots.extend((1..spans).map(|i| i as f64));
    knots.extend(std::iter::repeat_n(spans as f64, p + 1));
    let pts: Vec<f64> = (0..2 * n)
        .map(|i| ((i * 7919 % 113) as f64 / 113.0) - 0.5)
        .collect();
    BSplineCurve::new(p, knots, pts, 2).unwrap()
}

/// Pieces with point `i` of piece `k` moved by `(dx, dy)`.
fn moved(pieces: &BezierPieces, k: usize, i: usize, dx: f64, dy: f64) -> BezierPieces {
    let mut pts = pieces.points().to_vec();
    let at = (k * (pieces.degree() + 1) + i) * 2;
    pts[at] += dx;
    pts[at + 1] += dy;
    BezierPieces::new(pieces.degree(), 2, pieces.breaks().to_vec(), pts, None).unwrap()
}

/// The largest distance between the merged curve and the pieces at 50 parameters per
/// piece (Euclidean; the pieces are polynomial, so working = Euclidean coordinates).
fn measured_distance(curve: &BSplineCurve, pieces: &BezierPieces) -> f64 {
    let b = pieces.breaks();
    let mut worst = 0.0f64;
    for k in 0..pieces.len() {
        let piece = pieces.piece(k).unwrap();
        for j in 0..=50 {
            let s = f64::from(j) / 50.0;
            // Inside the span (a joint belongs to both pieces, which may differ there).
            let s = s.clamp(1e-9, 1.0 - 1e-9);
            let t = b[k] + s * (b[k + 1] - b[k]);
            let x = curve.eval(t).unwrap();
            let y = piece.eval(s);
            worst = worst.max(
                x.iter()
                    .zip(&y)
                    .map(|(u, v)| (u - v).powi(2))
                    .sum::<f64>()
                    .sqrt(),
            );
        }
    }
    worst
}

#[test]
fn a_joint_moved_just_above_or_below_tol_changes_or_keeps_the_multiplicity() {
    // Moving the joint point of both pieces by d (no gap) leaves every knot-removal
    // equation but the first (C^1) one exact, whose residual becomes |d|: the joint is
    // C^(p-1) for tol >= |d| (plus rounding) and C^0 for tol < |d|.
    for p in [2, 3, 5, 7] {
        let pieces = to_bezier_pieces(&spline(p, 4)).unwrap();
        let d = 1e-6;
        let (dx, dy) = (0.6 * d, 0.8 * d);
        let bumped = moved(&moved(&pieces, 1, p, dx, dy), 2, 0, dx, dy);
        let above = pieces_to_nurbs(&bumped, Some(d * (1.0 + 1e-6))).unwrap();
        assert_eq!(above.continuity, vec![p as i64 - 1; 3], "p={p}: kept");
        let below = pieces_to_nurbs(&bumped, Some(d * (1.0 - 1e-6))).unwrap();
        assert_eq!(
            below.continuity,
            vec![p as i64 - 1, 0, p as i64 - 1],
            "p={p}: lowered"
        );
        // Either way the bound holds, and is at least the distance measured.
        for r in [&above, &below] {
            let seen = measured_distance(&r.curve, &bumped);
            assert!(
                seen <= r.bound * (1.0 + 1e-9) + 1e-15,
                "p={p}: {seen} > {}",
                r.bound
            );
        }
        // Kept continuity moves the curve: the bound sees it (it cannot be ~0).
        assert!(above.bound > 0.1 * d, "p={p}: bound {}", above.bound);
        // Kept C^0 reproduces the pieces at rounding level.
        assert!(below.bound < 1e-13, "p={p}: bound {}", below.bound);
    }
}

#[test]
fn an_altered_piece_lowers_the_continuity_or_shows_in_the_bound() {
    for p in [3, 7] {
        let curve = spline(p, 6);
        let pieces = to_bezier_pieces(&curve).unwrap();
        let tol = 1e-8;
        let exact = pieces_to_nurbs(&pieces, Some(tol)).unwrap();
        assert_eq!(exact.continuity, vec![p as i64 - 1; 5]);
        assert!(exact.bound < 1e-13);
        // An interior point of piece 2 moved far beyond tol: the joints on both sides
        // lose continuity, and the result still reproduces every piece.
        let far = moved(&pieces, 2, 1, 1e-4, -2e-4);
        let r = pieces_to_nurbs(&far, Some(tol)).unwrap();
        assert!(
            r.continuity[1] < p as i64 - 1 && r.continuity[2] < p as i64 - 1,
            "{r:?}"
        );
        assert_eq!(r.continuity[0], p as i64 - 1);
        assert!(r.bound <= 2.0 * tol, "p={p}: bound {}", r.bound);
        assert!(measured_distance(&r.curve, &far) <= r.bound * (1.0 + 1e-9) + 1e-15);
        // Moved within tol: continuity may stay, but then the bound reports the change,
        // never less than the distance measured.
        let near = moved(&pieces, 2, 1, 0.2 * tol, 0.1 * tol);
        let r = pieces_to_nurbs(&near, Some(tol)).unwrap();
        let seen = measured_distance(&r.curve, &near);
        assert!(
            seen <= r.bound * (1.0 + 1e-9) + 1e-15,
            "p={p}: {seen} > {}",
            r.bound
        );
        if r.continuity == exact.continuity {
            assert!(
                r.bound > 0.01 * tol,
                "p={p}: bound {} misses the change",
                r.bound
            );
        }
    }
}
