//! The merge kernel of the general route, reverse: consecutive Bézier pieces (working
//! points) → one spline whose knots have the lowest multiplicity the pieces allow.
//!
//! The pieces are appended one by one with knot multiplicity `p` at each joint (seed 001
//! §4.1's exact merge; the shared joint point is the average of the two end points, which
//! must agree within the tolerance, else the joint keeps both and multiplicity `p + 1`).
//! Then copies of the joint's knot are removed while each removal is exact within the
//! tolerance: Tiller's knot removal (Piegl & Tiller A5.8, as in cagd-core's
//! `BSplineCurve::remove_knot`, with its choice of the leftover equation where
//! `a_i` crosses 1/2 so that no sweep divides by less than 1/2), done in place on the tail
//! of the growing arrays. A removal at joint `j` only needs the knots up to the next joint,
//! whose copies are all `breaks[j + 1]` at that time, so each joint costs `O(p^2)` and the
//! whole merge `O(pieces * p^2)` with no allocation per piece.
//!
//! The certificate of a removal is the re-insertion residual: the new points reproduce
//! every old point exactly except at the leftover equation, whose residual `eps` (Euclidean,
//! working coordinates) bounds the change of the curve (partition of unity).

use super::outer_knots::OuterKnots;
use super::width::{Width, with_width};

/// The merged spline in working coordinates.
#[derive(Debug)]
pub(crate) struct Merged {
    /// Full knot vector (clamped at both ends unless outer knots were given).
    pub(crate) knots: Vec<f64>,
    /// Working points, `pdim` coordinates each.
    pub(crate) work: Vec<f64>,
    /// The multiplicity kept at each joint (`p + 1`: the pieces do not meet).
    pub(crate) mults: Vec<usize>,
    /// Certified bound of the change: the largest distance between a Bézier point of the
    /// pieces and the same point re-extracted from the merged spline (working units; by
    /// the convex hull property it bounds the distance of the curves).
    pub(crate) bound: f64,
}

/// Merges `breaks.len() - 1` pieces of degree `p` whose point `i` of piece `k` (`pdim`
/// working coordinates) `load(k, i, out)` writes; `tol` is the budget of each joint.
///
/// 1. Each joint is decided on its own, from the two original pieces only (a two-piece
///    spline with the joint's knot of multiplicity `p`, copies removed while the summed
///    residual stays `<= tol`). Removing copies joint after joint on one growing spline
///    would feed each joint's rounding into the next joint's extrapolation, and the
///    residuals grow geometrically with the number of joints at high degree (measured:
///    x50 per joint at degree 9).
/// 2. With the knots known (`outer`: the knots beyond the end breaks of an unclamped
///    spline; `None` clamps both ends), control point `i` is the blossom `b(u_{i+1}, ..., u_{i+p})`
///    (Ramshaw) of the piece on one span of its support: the span where the de Casteljau
///    extrapolation, `prod_k (|1 - t_k| + |t_k|)` over the local arguments, is smallest.
pub(crate) fn merge<L>(
    breaks: &[f64],
    p: usize,
    pdim: usize,
    tol: f64,
    outer: Option<&OuterKnots>,
    load: L,
) -> Merged
where
    L: Fn(usize, usize, &mut [f64]),
{
    with_width!(pdim, merge_w(breaks, p, tol, outer, load))
}

/// [`merge`] for the point width `w`.
fn merge_w<L, W: Width>(
    breaks: &[f64],
    p: usize,
    tol: f64,
    outer: Option<&OuterKnots>,
    load: L,
    w: W,
) -> Merged
where
    L: Fn(usize, usize, &mut [f64]),
{
    let pdim = w.get();
    let nseg = breaks.len() - 1;
    let m = (p + 1) * pdim;
    // The working points of every piece, once (cheaper than loading a piece for each of
    // the phases below, which read each piece about p + 3 times).
    let mut bez = vec![0.0; nseg * m];
    for (k, piece) in bez.chunks_exact_mut(m).enumerate() {
        for (i, o) in piece.chunks_exact_mut(pdim).enumerate() {
            load(k, i, o);
        }
    }
    let piece = |k: usize| &bez[k * m..(k + 1) * m];
    let load_piece = |k: usize, out: &mut [f64]| out.copy_from_slice(piece(k));
    // 1. Multiplicities, joint by joint, on a two-piece spline of the original pieces.
    let mut mults = Vec::with_capacity(nseg.saturating_sub(1));
    let mut local = vec![0.0; (2 * p + 2) * pdim];
    let mut tmp = vec![0.0; (p + 2) * pdim];
    let mut right = vec![0.0; m];
    for j in 1..nseg {
        load_piece(j - 1, &mut local[..m]);
        load_piece(j, &mut right);
        let gap = dist2(&local[p * pdim..m], &right[..pdim]).sqrt();
        if p == 0 || gap.is_nan() || gap > tol {
            mults.push(p + 1);
            continue;
        }
        for (x, y) in local[p * pdim..m].iter_mut().zip(&right[..pdim]) {
            *x = 0.5 * (*x + y);
        }
        local[m..m + p * pdim].copy_from_slice(&right[pdim..]);
        let (hl, hr) = (breaks[j] - breaks[j - 1], breaks[j + 1] - breaks[j]);
        let s = decide_joint(&mut local, p, w, hl / (hl + hr), tol - 0.5 * gap, &mut tmp);
        mults.push(s);
    }
    // 2. Knots, and the knot index of each piece's span.
    let mut knots = Vec::with_capacity((nseg + 1) * (p + 1));
    let mut span_of = Vec::with_capacity(nseg);
    match outer {
        Some(o) => knots.extend_from_slice(&o.left),
        None => knots.extend(std::iter::repeat_n(breaks[0], p)),
    }
    knots.push(breaks[0]);
    for j in 1..nseg {
        span_of.push(knots.len() - 1);
        knots.extend(std::iter::repeat_n(breaks[j], mults[j - 1]));
    }
    span_of.push(knots.len() - 1);
    knots.push(breaks[nseg]);
    match outer {
        Some(o) => knots.extend_from_slice(&o.right),
        None => knots.extend(std::iter::repeat_n(breaks[nseg], p)),
    }
    let n = knots.len() - p - 1;
    // 3. Control points by blossoming.
    let inv_len: Vec<f64> = span_of
        .iter()
        .map(|&s| 1.0 / (knots[s + 1] - knots[s]))
        .collect();
    let mut work = vec![0.0; n * pdim];
    let mut args = vec![0.0; p];
    let scratch = &mut right;
    let mut other = vec![0.0; m];
    let mut first_piece = 0;
    for i in 0..n {
        // (Past the last span, an unclamped end's last points: blossoms of the last piece.)
        while first_piece + 1 < nseg && span_of[first_piece] < i {
            first_piece += 1;
        }
        // The span of the support where the de Casteljau extrapolation is smallest: the
        // amplification of the local arguments t, prod (|1 - t| + |t|), written
        // prod max(1, |2 x - a - b| / (b - a)) (the first such span wins a tie).
        let (mut best, mut best_amp) = (first_piece, f64::INFINITY);
        let mut k = first_piece;
        let support = &knots[i + 1..=i + p];
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
        let k = best;
        let (a, inv) = (knots[span_of[k]], inv_len[k]);
        for (t, x) in args.iter_mut().zip(&knots[i + 1..=i + p]) {
            *t = (x - a) * inv;
        }
        // de Casteljau with the arguments, level after level, between two buffers (the
        // first level reads the piece itself): out of place, so that each level
        // vectorises.
        let (mut from, mut to): (&mut [f64], &mut [f64]) = (scratch, &mut other);
        let mut src: &[f64] = piece(k);
        for (lvl, &t) in args.iter().enumerate() {
            let u = 1.0 - t;
            let len = (p - lvl) * pdim;
            for (o, (x, y)) in to[..len]
                .iter_mut()
                .zip(src[..len].iter().zip(&src[pdim..len + pdim]))
            {
                *o = u * x + t * y;
            }
            std::mem::swap(&mut from, &mut to);
            src = from;
        }
        work[i * pdim..(i + 1) * pdim].copy_from_slice(&src[..pdim]);
    }
    // 4. The certificate: extract the merged spline again and compare.
    let mut worst2 = 0.0f64;
    let mut k = 0;
    super::extract_kernel::extract(
        &knots,
        p,
        n,
        pdim,
        |i, o| o.copy_from_slice(&work[i * pdim..(i + 1) * pdim]),
        |_, _, win| {
            if k < nseg {
                for (x, y) in win.chunks_exact(pdim).zip(piece(k).chunks_exact(pdim)) {
                    worst2 = worst2.max(dist2(x, y));
                }
            }
            k += 1;
        },
    );
    let bound = if k == nseg {
        worst2.sqrt()
    } else {
        f64::INFINITY
    };
    Merged {
        knots,
        work,
        mults,
        bound,
    }
}

/// Squared Euclidean distance of two working points.
fn dist2(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum::<f64>()
}

/// Removes copies of the joint knot of a local two-piece spline (points `0..=2p` of
/// `pdim` coordinates: the left piece, the averaged joint, the right piece; knots
/// `b0^(p+1), b1^p, b2^(p+1)`) while the summed residual stays `<= budget`; returns the
/// multiplicity kept (`>= 1`).
///
/// Removal of one copy (multiplicity `s`, last index `r = p + s`): the knot-insertion
/// equations `P_i = a Q_i + (1-a) Q_{i-1}`, `i = r-p..=r-s = s..=p`, with
/// `a_i = (u - u_i)/(u_{i+p+1} - u_i)`, which on this knot vector is the same for every
/// equation, `a = (b1 - b0)/(b2 - b0)`; `Q_{s-1} = P_{s-1}`, `Q_p = P_{p+1}`. With
/// `a >= 1/2` the equations are solved from the left (dividing by `a`) and the last one is
/// left over, else from the right (dividing by `1 - a`) and the first is left over, as
/// Tiller's removal does where `a_i` crosses 1/2; the residual of the leftover equation
/// certifies the removal. The points are not shifted: point `j >= p` (the index `r - s` is
/// `p` for every copy) is stored at `j + (p - s)`.
fn decide_joint<W: Width>(
    local: &mut [f64],
    p: usize,
    w: W,
    a: f64,
    mut budget: f64,
    tmp: &mut [f64],
) -> usize {
    let pdim = w.get();
    let b = 1.0 - a;
    let from_left = a >= 0.5;
    let inv = if from_left { 1.0 / a } else { 1.0 / b };
    let mut s = p;
    while s > 1 {
        let shift = p - s;
        let (first, last) = (s, p);
        let pt = |j: usize| {
            let at = if j >= last { j + shift } else { j } * pdim;
            at..at + pdim
        };
        // tmp slot m holds Q_{first - 1 + m}, m = 0..=last - first + 1.
        let end = last - first + 1;
        tmp[..pdim].copy_from_slice(&local[pt(first - 1)]);
        tmp[end * pdim..(end + 1) * pdim].copy_from_slice(&local[pt(last + 1)]);
        let (k, qk, qk1) = if from_left {
            for i in first..last {
                let m = i - first + 1;
                let (lo, hi) = tmp.split_at_mut(m * pdim);
                let prev = &lo[(m - 1) * pdim..];
                for ((q, x), y) in hi[..pdim].iter_mut().zip(&local[pt(i)]).zip(prev) {
                    *q = (x - b * y) * inv;
                }
            }
            (last, end, end - 1)
        } else {
            for i in (first + 1..=last).rev() {
                let m = i - first;
                let (lo, hi) = tmp.split_at_mut((m + 1) * pdim);
                for ((q, x), y) in lo[m * pdim..]
                    .iter_mut()
                    .zip(&local[pt(i)])
                    .zip(&hi[..pdim])
                {
                    *q = (x - a * y) * inv;
                }
            }
            (first, 1, 0)
        };
        let mut eps2 = 0.0;
        for ((x, q), q1) in local[pt(k)]
            .iter()
            .zip(&tmp[qk * pdim..(qk + 1) * pdim])
            .zip(&tmp[qk1 * pdim..(qk1 + 1) * pdim])
        {
            let d = x - a * q - b * q1;
            eps2 += d * d;
        }
        let eps = eps2.sqrt();
        if eps.is_nan() || eps > budget {
            break;
        }
        budget -= eps;
        local[first * pdim..last * pdim].copy_from_slice(&tmp[pdim..end * pdim]);
        s -= 1;
    }
    s
}
