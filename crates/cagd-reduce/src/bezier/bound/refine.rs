//! From the pieces of the error curve to a number (goes beyond the seed; the convex-hull
//! argument is seed 000 §14.4.3): the largest per-piece bound (hull or chord bound) over
//! the pieces, and, for the tight level, best-first branch and bound — the piece with the
//! largest bound is split at its midpoint (de Casteljau; its end points are curve points
//! and raise the lower bound) until every remaining piece's bound is within
//! `1 + TIGHT_SLACK` of the largest curve value seen, or a piece reaches `MAX_REFINE`
//! more levels.

use std::collections::BinaryHeap;

/// The tight level stops once every piece's bound is within this relative margin of a
/// curve value already seen: the bound is then within `1 + TIGHT_SLACK` of the true
/// maximum (rounding allowance aside).
pub(crate) const TIGHT_SLACK: f64 = 0.08;

/// Most extra midpoint levels the tight level adds to a piece.
pub(crate) const MAX_REFINE: usize = 16;

/// Most midpoint splits the tight level makes for one curve (bounded work and memory:
/// when they are used up, the largest remaining piece bound is the bound).
pub(crate) const MAX_SPLITS: usize = 4096;

fn norm2(p: &[f64]) -> f64 {
    p.iter().map(|v| v * v).sum::<f64>()
}

fn hull2(points: &[f64], dim: usize) -> f64 {
    points.chunks_exact(dim).map(norm2).fold(0.0, f64::max)
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
        return norm2(p).sqrt();
    }
    let n = (len / dim - 1) as f64;
    let (d0, dn) = (&p[..dim], &p[len - dim..]);
    let (mut dev, mut hull): (f64, f64) = (0.0, 0.0);
    for (i, d) in p.chunks_exact(dim).enumerate() {
        let s = i as f64 / n;
        let (mut e, mut h) = (0.0, 0.0);
        for k in 0..dim {
            let v = d[k] - ((1.0 - s) * d0[k] + s * dn[k]);
            e += v * v;
            h += d[k] * d[k];
        }
        dev = dev.max(e);
        hull = hull.max(h);
    }
    let chord = norm2(d0).max(norm2(dn)).sqrt() + dev.sqrt();
    hull.sqrt().min(chord)
}

/// Splits a piece at `t = 1/2` (de Casteljau) into `left` and `right`: the same
/// arithmetic as `cagd_core::kernel::subdivide` at `1/2` (each new point is
/// `0.5 a + 0.5 b`, one rounding), specialised for `dim <= 4`.
pub(crate) fn split_half(p: &[f64], dim: usize, left: &mut [f64], right: &mut [f64]) {
    match dim {
        1 => split_fixed::<1>(p, left, right),
        2 => split_fixed::<2>(p, left, right),
        3 => split_fixed::<3>(p, left, right),
        4 => split_fixed::<4>(p, left, right),
        _ => cagd_core::kernel::subdivide(p, dim, 0.5, left, right),
    }
}

fn split_fixed<const D: usize>(p: &[f64], left: &mut [f64], right: &mut [f64]) {
    let np = p.len() / D;
    right.copy_from_slice(p);
    for level in 0..np {
        left[level * D..(level + 1) * D].copy_from_slice(&right[..D]);
        let live = &mut right[..(np - level) * D];
        for i in 0..np - level - 1 {
            for k in 0..D {
                live[i * D + k] = 0.5 * live[i * D + k] + 0.5 * live[(i + 1) * D + k];
            }
        }
    }
}

/// A piece waiting in the branch and bound: its bound (non-negative, so the bit pattern
/// orders like the value), its place in the arena, its depth.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct Node {
    key: u64,
    at: usize,
    depth: usize,
}

/// Reusable buffers of the tight refinement (one per batch, so no allocation per curve).
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    arena: Vec<f64>,
    heap: BinaryHeap<Node>,
}

/// The bound from `pieces` (`count` pieces of `n1` control points of `dim` coordinates,
/// one after the other, as computed): the largest per-piece bound, refined by best-first
/// branch and bound when `tight`. Includes the rounding of the norms and of the refinement
/// (`(depth (n1 - 1) + dim + 16) eps` of the largest control-point norm: in every de
/// Casteljau split a computed point moves by at most `(n1 - 1) eps` of it, and the chord
/// bound's arithmetic adds at most `12 eps` of it), not that of computing `pieces` (the
/// caller adds it).
pub(crate) fn pieces_bound(
    pieces: &[f64],
    n1: usize,
    dim: usize,
    tight: bool,
    scratch: &mut Scratch,
) -> f64 {
    let len = n1 * dim;
    let eps = f64::EPSILON;
    let top = hull2(pieces, dim).sqrt();
    if top == 0.0 {
        return 0.0;
    }
    let finish = |v: f64, deepest: usize| {
        v * (1.0 + (dim as f64 + 4.0) * eps) + ((deepest * (n1 - 1) + dim + 16) as f64) * eps * top
    };
    if !tight {
        let v = pieces
            .chunks_exact(len)
            .map(|p| piece_value(p, dim))
            .fold(0.0, f64::max);
        return finish(v, 0);
    }
    // Largest curve value seen: the end points of the pieces.
    let mut lower2: f64 = 0.0;
    for p in pieces.chunks_exact(len) {
        lower2 = lower2.max(norm2(&p[..dim])).max(norm2(&p[len - dim..]));
    }
    let mut lower = lower2.sqrt();
    let settle = 1.0 + TIGHT_SLACK;
    let (arena, heap) = (&mut scratch.arena, &mut scratch.heap);
    arena.clear();
    heap.clear();
    arena.extend_from_slice(pieces);
    for (i, p) in pieces.chunks_exact(len).enumerate() {
        let v = piece_value(p, dim);
        heap.push(Node {
            key: v.to_bits(),
            at: i * len,
            depth: 0,
        });
    }
    let (mut upper, mut deepest): (f64, usize) = (0.0, 0);
    let mut splits = 0;
    while let Some(&node) = heap.peek() {
        let v = f64::from_bits(node.key);
        if v.is_nan() {
            return f64::NAN;
        }
        if v <= settle * lower || splits == MAX_SPLITS {
            // Every remaining piece is settled (or the budget is spent): the largest is
            // this one.
            upper = upper.max(v);
            deepest = deepest.max(heap.iter().map(|n| n.depth).max().unwrap_or(0));
            break;
        }
        heap.pop();
        if node.depth == MAX_REFINE {
            upper = upper.max(v);
            deepest = deepest.max(node.depth);
            continue;
        }
        splits += 1;
        let at = arena.len();
        arena.resize(at + 2 * len, 0.0);
        let (old, new) = arena.split_at_mut(at);
        let (left, right) = new.split_at_mut(len);
        split_half(&old[node.at..node.at + len], dim, left, right);
        lower = lower.max(norm2(&right[..dim]).sqrt());
        for (child, off) in [(&*left, at), (&*right, at + len)] {
            heap.push(Node {
                key: piece_value(child, dim).to_bits(),
                at: off,
                depth: node.depth + 1,
            });
        }
    }
    // (A NaN piece value sorts above every number, so it is seen first and returned as NaN,
    // which the caller turns into +inf.)
    finish(upper, deepest)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn split_half_equals_the_core_subdivision() {
        for dim in 1..=5 {
            let p: Vec<f64> = (0..7 * dim)
                .map(|i| ((i * 31 % 17) as f64 - 8.0) / 3.0)
                .collect();
            let (mut l1, mut r1) = (vec![0.0; p.len()], vec![0.0; p.len()]);
            let (mut l2, mut r2) = (vec![0.0; p.len()], vec![0.0; p.len()]);
            split_half(&p, dim, &mut l1, &mut r1);
            cagd_core::kernel::subdivide(&p, dim, 0.5, &mut l2, &mut r2);
            assert_eq!((l1, r1), (l2, r2), "dim {dim}");
        }
    }

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
