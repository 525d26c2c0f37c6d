//! From the pieces of the error curve to a number (goes beyond the seed; the convex-hull
//! argument is seed 000 §14.4.3): the largest control-point norm over the pieces, and, for
//! the tight level, branch and bound — a piece whose hull is within `1 + TIGHT_SLACK` of
//! the largest curve value seen so far (piece end points are curve points) is settled,
//! any other is split at its midpoint (de Casteljau) until it is, or until
//! `MAX_REFINE` more levels.

use cagd_core::kernel::subdivide;

/// The tight level stops refining a piece once its hull is within this relative margin of
/// a curve value already seen: the bound is then within `1 + TIGHT_SLACK` of the true
/// maximum (rounding allowance aside).
pub(crate) const TIGHT_SLACK: f64 = 0.04;

/// Most extra midpoint levels the tight level adds to a piece.
pub(crate) const MAX_REFINE: usize = 16;

fn norm(p: &[f64]) -> f64 {
    p.iter().map(|v| v * v).sum::<f64>().sqrt()
}

fn hull(points: &[f64], dim: usize) -> f64 {
    points.chunks_exact(dim).map(norm).fold(0.0, f64::max)
}

/// A bound of `max_t ||D(t)||` over one piece: the smaller of its hull (largest
/// control-point norm) and the chord bound `max(||d_0||, ||d_n||) + max_i ||d_i - c_i||`,
/// `c_i = (1 - i/n) d_0 + (i/n) d_n` the chord written in degree `n` (`D - chord` is the
/// Bézier curve with control points `d_i - c_i`, and the chord's norm is largest at an
/// end). In exact arithmetic; the caller adds the rounding (at most `12 eps` of the
/// largest control-point norm here).
fn piece_value(p: &[f64], dim: usize) -> f64 {
    let len = p.len();
    if len == dim {
        return norm(p);
    }
    let n = (len / dim - 1) as f64;
    let (d0, dn) = (&p[..dim], &p[len - dim..]);
    let mut dev: f64 = 0.0;
    for (i, d) in p.chunks_exact(dim).enumerate() {
        let s = i as f64 / n;
        let e: f64 = (0..dim)
            .map(|k| {
                let v = d[k] - ((1.0 - s) * d0[k] + s * dn[k]);
                v * v
            })
            .sum();
        dev = dev.max(e);
    }
    let chord = norm(d0).max(norm(dn)) + dev.sqrt();
    hull(p, dim).min(chord)
}

/// Reusable buffers of the tight refinement (one per batch, so no allocation per curve).
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    stack: Vec<f64>,
    depth: Vec<usize>,
    piece: Vec<f64>,
}

/// The bound from `pieces` (`count` pieces of `n1` control points of `dim` coordinates,
/// one after the other, as computed): the largest control-point norm, refined by branch
/// and bound when `tight`. Includes the rounding of the norms and of the refinement
/// (`(depth (n1 - 1) + dim + 16) eps` of the largest control-point norm: in every de
/// Casteljau split a computed point moves by at most `(n1 - 1) eps` of it, and the chord
/// bound's arithmetic adds at most `12 eps` of it), not that of computing `pieces` (the
/// caller adds it). For `n1 = 1` (degree 0) the chord bound is skipped.
pub(crate) fn pieces_bound(
    pieces: &[f64],
    n1: usize,
    dim: usize,
    tight: bool,
    scratch: &mut Scratch,
) -> f64 {
    let len = n1 * dim;
    let top = hull(pieces, dim);
    let eps = f64::EPSILON;
    if top == 0.0 {
        return 0.0;
    }
    if !tight {
        let v = pieces
            .chunks_exact(len)
            .map(|p| piece_value(p, dim))
            .fold(0.0, f64::max);
        return v * (1.0 + (dim as f64 + 4.0) * eps) + ((dim + 16) as f64) * eps * top;
    }
    // Largest curve value seen: the end points of the pieces.
    let mut lower: f64 = 0.0;
    for p in pieces.chunks_exact(len) {
        lower = lower.max(norm(&p[..dim])).max(norm(&p[len - dim..]));
    }
    let settle = 1.0 + TIGHT_SLACK;
    let mut upper: f64 = 0.0;
    let mut deepest = 0;
    scratch.stack.clear();
    scratch.depth.clear();
    for p in pieces.chunks_exact(len) {
        let h = piece_value(p, dim);
        if h <= settle * lower {
            upper = upper.max(h);
        } else {
            scratch.stack.extend_from_slice(p);
            scratch.depth.push(0);
        }
    }
    scratch.piece.resize(len, 0.0);
    while let Some(depth) = scratch.depth.pop() {
        let at = scratch.stack.len() - len;
        scratch.piece.copy_from_slice(&scratch.stack[at..]);
        let h = piece_value(&scratch.piece, dim);
        if h <= settle * lower || depth == MAX_REFINE {
            scratch.stack.truncate(at);
            upper = upper.max(h);
            deepest = deepest.max(depth);
            continue;
        }
        // Replace the piece by its two halves on the stack.
        scratch.stack.resize(at + 2 * len, 0.0);
        let (left, right) = scratch.stack[at..].split_at_mut(len);
        subdivide(&scratch.piece, dim, 0.5, left, right);
        lower = lower.max(norm(&right[..dim]));
        scratch.depth.push(depth + 1);
        scratch.depth.push(depth + 1);
    }
    upper * (1.0 + (dim as f64 + 4.0) * eps) + ((deepest * (n1 - 1) + dim + 16) as f64) * eps * top
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_parabola() {
        // D(t) = 2t(1-t): control points 0, 1, 0 (hull 1), true max 1/2.
        let mut s = Scratch::default();
        // Fast: one piece, min(hull 1, chord 0 + 1) = 1.
        let loose = pieces_bound(&[0.0, 1.0, 0.0], 3, 1, false, &mut s);
        assert!((1.0..1.0 + 1e-14).contains(&loose), "{loose}");
        let tight = pieces_bound(&[0.0, 1.0, 0.0], 3, 1, true, &mut s);
        assert!(
            (0.5..0.5 * (1.0 + TIGHT_SLACK) + 1e-14).contains(&tight),
            "{tight}"
        );
    }

    #[test]
    fn tight_is_true_and_within_the_slack_on_wiggly_curves() {
        let mut s = Scratch::default();
        for seed in 0..20usize {
            let n1 = 8 + seed % 13;
            let d: Vec<f64> = (0..2 * n1)
                .map(|i| (((i + 3) * (seed + 7) * 7919 % 211) as f64 - 105.0) / 50.0)
                .collect();
            let c = cagd_core::BezierCurve::new(d.clone(), 2).unwrap();
            let zero = cagd_core::BezierCurve::new(vec![0.0, 0.0], 2).unwrap();
            let measured = cagd_core::curve_distance(&c, &zero).unwrap();
            let b = pieces_bound(&d, n1, 2, true, &mut s);
            assert!(b >= measured, "{seed}: {b} < {measured}");
            assert!(
                b <= (1.0 + TIGHT_SLACK) * measured * (1.0 + 1e-9),
                "{seed}: {b} vs {measured}"
            );
        }
    }
}
