//! The control points of the merged spline: point `i` is the blossom
//! `b(u_{i+1}, ..., u_{i+p})` (Ramshaw; seed 001 §4.1) of the Bézier piece on one span of
//! its support, evaluated by de Casteljau with those arguments.
//!
//! The span is the one where the de Casteljau extrapolation is smallest: the amplification
//! of the local arguments `t`, `prod (|1 - t| + |t|)`, written
//! `prod max(1, |2 x - a - b| / (b - a))` (the first such span wins a tie). Every factor is
//! at least 1, so a candidate is dropped as soon as its partial product can no longer win.
//!
//! Arguments equal to the span's ends cost nothing: `t = 0` keeps the points `0..len-1`
//! and `t = 1` the points `1..len` (exactly; a selection commutes with the other levels),
//! so only the arguments outside the span are de Casteljau levels. On simple knots that
//! saves the two levels of the span's own ends (degree 7: 15 combinations instead of 28;
//! degree 3: 1 instead of 6).

use super::width::{Width, lerp};

/// Appends the `knots.len() - p - 1` control points (`pdim` working coordinates each) to
/// `work`. `bez`: the pieces' working points, piece-major; `span_of[k]`: the knot index
/// `s` of piece `k`'s span `[u_s, u_{s+1}]`.
pub(crate) fn control_points<W: Width>(
    bez: &[f64],
    knots: &[f64],
    span_of: &[usize],
    p: usize,
    w: W,
    work: &mut Vec<f64>,
) {
    let d = w.get();
    let m = (p + 1) * d;
    let nseg = span_of.len();
    let n = knots.len() - p - 1;
    let inv_len: Vec<f64> = span_of
        .iter()
        .map(|&s| 1.0 / (knots[s + 1] - knots[s]))
        .collect();
    work.reserve(n * d);

    let (mut from, mut to) = (vec![0.0; m], vec![0.0; m]);
    let mut ts = Vec::with_capacity(p);
    let mut first_piece = 0;
    for i in 0..n {
        // (Past the last span, an unclamped end's last points: blossoms of the last piece.)
        while first_piece + 1 < nseg && span_of[first_piece] < i {
            first_piece += 1;
        }
        let support = &knots[i + 1..=i + p];
        let (mut best, mut best_amp) = (first_piece, f64::INFINITY);
        let mut k = first_piece;
        while k < nseg && span_of[k] <= i + p {
            let s = span_of[k];
            let (c, inv) = (knots[s] + knots[s + 1], inv_len[k]);
            let amp = support
                .iter()
                .fold(1.0f64, |m, x| m * ((2.0 * x - c).abs() * inv).max(1.0));
            if amp < best_amp {
                (best, best_amp) = (k, amp);
            }
            k += 1;
        }
        let s = span_of[best];
        let (a, b, inv) = (knots[s], knots[s + 1], inv_len[best]);
        // The arguments are sorted: those below `a`, `a` (t = 0), `b` (t = 1), above `b`
        // (no knot lies inside the span).
        let below = support.partition_point(|x| *x < a);
        let at_a = support[below..].partition_point(|x| *x <= a);
        let at_b = support[below + at_a..].partition_point(|x| *x <= b);
        let (lo, hi) = (at_b, p - at_a);
        let piece = &bez[best * m + lo * d..best * m + (hi + 1) * d];
        // The local arguments outside the span, in order.
        ts.clear();
        for x in support[..below]
            .iter()
            .chain(&support[below + at_a + at_b..])
        {
            ts.push((x - a) * inv);
        }
        let Some((&t, rest)) = ts.split_first() else {
            work.extend_from_slice(&piece[..d]);
            continue;
        };
        // The first level reads the piece, the others go back and forth between two
        // scratch buffers (out of place, so that each level vectorises).
        let mut len = hi - lo; // points - 1
        let u = 1.0 - t;
        for j in 0..len {
            lerp(
                w,
                &mut from[j * d..],
                &piece[j * d..],
                &piece[(j + 1) * d..],
                u,
                t,
            );
        }
        for &t in rest {
            len -= 1;
            let u = 1.0 - t;
            for j in 0..len {
                lerp(
                    w,
                    &mut to[j * d..],
                    &from[j * d..],
                    &from[(j + 1) * d..],
                    u,
                    t,
                );
            }
            std::mem::swap(&mut from, &mut to);
        }
        work.extend_from_slice(&from[..d]);
    }
}
