//! Tests of the patch conversions: spec vectors, exactness and tiling laws, independent
//! routes, named errors.

mod errors;
mod laws_rect;
mod laws_tri;
mod trim_tests;
mod vectors;

use proptest::prelude::*;

use super::{PatchPiece, PatchSurface, TensorSurface, TriSurface};

/// 200 parameters of a piece's own domain (a 14 x 14 Halton-like spread plus the four
/// corners), folded into the triangle `s + t <= 1` for triangular pieces.
pub(super) fn sample_params(triangle: bool) -> Vec<(f64, f64)> {
    let mut out = vec![(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)];
    let halton = |mut i: usize, b: usize| {
        let (mut f, mut r) = (1.0, 0.0);
        while i > 0 {
            f /= b as f64;
            r += f * (i % b) as f64;
            i /= b;
        }
        r
    };
    for i in 1..=196 {
        out.push((halton(i, 2), halton(i, 3)));
    }
    if triangle {
        for p in &mut out {
            if p.0 + p.1 > 1.0 {
                *p = (1.0 - p.0, 1.0 - p.1);
            }
        }
    }
    out
}

/// Largest coordinate of a patch's control points (the scale of "relative"), at least 1.
pub(super) fn scale(input: &PatchSurface) -> f64 {
    let pts = match input {
        PatchSurface::Tensor(p) => p.net().points(),
        PatchSurface::Tri(t) => t.net().points(),
    };
    pts.iter().fold(1.0_f64, |a, x| a.max(x.abs()))
}

/// Asserts that every piece equals the input at the mapped points (200 per piece) within
/// `tol` relative to the input's scale.
pub(super) fn assert_exact(input: &PatchSurface, pieces: &[PatchPiece], tol: f64) {
    let sc = scale(input);
    for (k, piece) in pieces.iter().enumerate() {
        for (s, t) in sample_params(piece.domain.is_triangle()) {
            let [u, v] = piece.domain.map(s, t);
            let a = input.eval(u, v);
            let b = piece.surface.eval(s, t);
            for (x, y) in a.iter().zip(&b) {
                assert!(
                    (x - y).abs() <= tol * sc,
                    "piece {k} at (s, t) = ({s}, {t}) -> (u, v) = ({u}, {v}): {x} vs {y}"
                );
            }
        }
    }
}

/// Asserts that the pieces tile the domain (the unit square, or the unit triangle when
/// `triangle`): a point off the pieces' boundaries by more than 1e-7 is in exactly one
/// piece (found by mapping it back).
pub(super) fn assert_tiles(pieces: &[PatchPiece], triangle: bool) {
    for (u, v) in sample_params(triangle) {
        // Pull the sample off the outer boundary.
        let (u, v) = (0.01 + 0.98 * u, 0.01 + 0.98 * v);
        let (u, v) = if triangle {
            (u * 0.98, v * 0.98)
        } else {
            (u, v)
        };
        let loose = pieces
            .iter()
            .filter(|p| p.domain.locate(u, v, 1e-7).is_some())
            .count();
        let strict = pieces
            .iter()
            .filter(|p| p.domain.locate(u, v, -1e-7).is_some())
            .count();
        assert!(loose >= 1, "({u}, {v}) is in no piece");
        assert!(strict <= 1, "({u}, {v}) is inside {strict} pieces");
    }
}

/// A random triangle of degree in `degs`, dimension 1..=4, rational or not.
pub(super) fn any_tri(degs: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = TriSurface> {
    (degs, 1usize..=4, any::<bool>()).prop_flat_map(|(n, dim, rational)| {
        let count = cagd_core::tri_count(n);
        (
            cagd_testkit::points(count, dim),
            cagd_testkit::weights(count),
        )
            .prop_map(move |(p, w)| TriSurface::new(p, n, dim, rational.then_some(w)).unwrap())
    })
}

/// A random `m x n` patch, degrees in the ranges, dimension 1..=4, rational or not.
pub(super) fn any_rect(
    ms: std::ops::RangeInclusive<usize>,
    ns: std::ops::RangeInclusive<usize>,
) -> impl Strategy<Value = TensorSurface> {
    (ms, ns, 1usize..=4, any::<bool>()).prop_flat_map(|(m, n, dim, rational)| {
        let count = (m + 1) * (n + 1);
        (
            cagd_testkit::points(count, dim),
            cagd_testkit::weights(count),
        )
            .prop_map(move |(p, w)| {
                TensorSurface::new(p, m, n, dim, rational.then_some(w)).unwrap()
            })
    })
}
