//! The evaluation difference between an output piece and the input at the mapped points.

use super::{PatchPiece, PatchSurface};

/// Largest coordinate difference `|piece(s, t) - input(X(s, t))|` over a grid of
/// `(g + 1)^2` parameters of the piece's own domain (the unit square, or the triangle
/// `s + t <= 1` for a triangular piece), `X` the piece's declared domain map. Rational
/// patches are compared in Euclidean space. `g >= 1`.
pub fn max_piece_difference(input: &PatchSurface, piece: &PatchPiece, g: usize) -> f64 {
    let g = g.max(1);
    let mut worst: f64 = 0.0;
    for a in 0..=g {
        for b in 0..=g {
            let (s, t) = (a as f64 / g as f64, b as f64 / g as f64);
            if piece.domain.is_triangle() && a + b > g {
                continue;
            }
            let [u, v] = piece.domain.map(s, t);
            let (u, v) = (u.clamp(0.0, 1.0), v.clamp(0.0, 1.0));
            let x = input.eval(u, v);
            let y = piece.surface.eval(s, t);
            for (p, q) in x.iter().zip(&y) {
                worst = worst.max((p - q).abs());
            }
        }
    }
    worst
}
