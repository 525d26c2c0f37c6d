//! The control points of the merged spline: point `i` is the blossom
//! `b(u_{i+1}, ..., u_{i+p})` (Ramshaw; seed 001 §4.1) of the Bézier piece on one span of
//! its support, evaluated by de Casteljau with those arguments.
//!
//! The span is the one where the de Casteljau extrapolation is smallest: the amplification
//! of the local arguments `t`, `prod (|1 - t| + |t|)`, written
//! `prod max(1, |2 x - a - b| / (b - a))` (the first such span wins a tie).
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
    // The sum of the ends of each piece's span (`a + b`).
    let mid2: Vec<f64> = span_of.iter().map(|&s| knots[s] + knots[s + 1]).collect();
    let mut amp_buf = vec![0.0; nseg];
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
        let mut end = first_piece;
        while end < nseg && span_of[end] <= i + p {
            end += 1;
        }
        // All candidates at once, argument after argument (the same products as one
        // candidate after the other, in a loop that vectorises).
        let amp = &mut amp_buf[..end - first_piece];
        amp.fill(1.0);
        let (mids, invs) = (&mid2[first_piece..end], &inv_len[first_piece..end]);
        for x in support {
            for (m, (c, inv)) in amp.iter_mut().zip(mids.iter().zip(invs)) {
                let f = (2.0 * x - c).abs() * inv;
                // (max(1, f) as a plain comparison: the knots are finite.)
                *m *= if f > 1.0 { f } else { 1.0 };
            }
        }
        let (mut best, mut best_amp) = (first_piece, f64::INFINITY);
        for (k, &a) in amp.iter().enumerate() {
            if a < best_amp {
                (best, best_amp) = (first_piece + k, a);
            }
        }
        let s = span_of[best];
        let (a, b, inv) = (knots[s], knots[s + 1], inv_len[best]);
        // The arguments are sorted: those below `a`, `a` (t = 0), `b` (t = 1), above `b`
        // (no knot lies inside the span).
        // (Counted, not searched: a few branch-free comparisons beat a binary search's
        // chain of dependent loads.)
        let (mut below, mut at_a, mut at_b) = (0, 0, 0);
        for &x in support {
            below += usize::from(x < a);
            at_a += usize::from(x == a);
            at_b += usize::from(x == b);
        }
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
        for (j, o) in from[..len * d].chunks_exact_mut(d).enumerate() {
            let (x, y) = piece[j * d..(j + 2) * d].split_at(d);
            lerp(w, o, x, y, u, t);
        }
        for &t in rest {
            len -= 1;
            let u = 1.0 - t;
            for (j, o) in to[..len * d].chunks_exact_mut(d).enumerate() {
                let (x, y) = from[j * d..(j + 2) * d].split_at(d);
                lerp(w, o, x, y, u, t);
            }
            std::mem::swap(&mut from, &mut to);
        }
        work.extend_from_slice(&from[..d]);
    }
}
