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

/// The merged spline in working coordinates.
#[derive(Debug)]
pub(crate) struct Merged {
    /// Full knot vector, clamped at both ends.
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
/// 2. With the knots known, control point `i` is the blossom `b(u_{i+1}, ..., u_{i+p})`
///    (Ramshaw) of the piece on one span of its support: the span whose farthest argument
///    lies the fewest of its own lengths outside it (the de Casteljau extrapolation grows
///    with `prod_k (|1 - t_k| + |t_k|)` over the local arguments, dominated by the
///    extreme ones).
pub(crate) fn merge<L>(breaks: &[f64], p: usize, pdim: usize, tol: f64, mut load: L) -> Merged
where
    L: FnMut(usize, usize, &mut [f64]),
{
    let nseg = breaks.len() - 1;
    let m = (p + 1) * pdim;
    let mut bez = vec![0.0; nseg * m];
    for k in 0..nseg {
        for i in 0..=p {
            let at = k * m + i * pdim;
            load(k, i, &mut bez[at..at + pdim]);
        }
    }
    // 1. Multiplicities, joint by joint.
    let mut mults = Vec::with_capacity(nseg.saturating_sub(1));
    let mut local = Vec::with_capacity((2 * p + 1) * pdim);
    let mut lknots = Vec::with_capacity(2 * p + 1);
    let mut tmp = vec![0.0; (p + 2).max(p + 1) * pdim];
    let mut alpha = vec![0.0; p + 1];
    for j in 1..nseg {
        let left = &bez[(j - 1) * m..j * m];
        let right = &bez[j * m..(j + 1) * m];
        let gap = dist(&left[p * pdim..], &right[..pdim]);
        if p == 0 || !(gap <= tol) {
            mults.push(p + 1);
            continue;
        }
        local.clear();
        local.extend_from_slice(left);
        for (x, y) in local[p * pdim..].iter_mut().zip(&right[..pdim]) {
            *x = 0.5 * (*x + y);
        }
        local.extend_from_slice(&right[pdim..]);
        lknots.clear();
        lknots.extend(std::iter::repeat_n(breaks[j - 1], p + 1));
        lknots.extend(std::iter::repeat_n(breaks[j], p));
        let mut used = 0.5 * gap;
        let mut s = p;
        while s > 1 {
            match remove_last_knot(
                &lknots,
                breaks[j + 1],
                &mut local,
                p,
                pdim,
                s,
                tol - used,
                &mut tmp,
                &mut alpha,
            ) {
                Some(eps) => {
                    used += eps;
                    lknots.pop();
                    s -= 1;
                }
                None => break,
            }
        }
        mults.push(s);
    }
    // 2. Knots, and the knot index of each piece's span.
    let mut knots = Vec::with_capacity((nseg + 1) * (p + 1));
    let mut span_of = Vec::with_capacity(nseg);
    knots.extend(std::iter::repeat_n(breaks[0], p + 1));
    for j in 1..nseg {
        span_of.push(knots.len() - 1);
        knots.extend(std::iter::repeat_n(breaks[j], mults[j - 1]));
    }
    span_of.push(knots.len() - 1);
    knots.extend(std::iter::repeat_n(breaks[nseg], p + 1));
    let n = knots.len() - p - 1;
    // 3. Control points by blossoming.
    let mut work = vec![0.0; n * pdim];
    let mut args = vec![0.0; p];
    let mut first_piece = 0;
    for i in 0..n {
        while span_of[first_piece] < i {
            first_piece += 1;
        }
        // The span of the support whose farthest argument lies the fewest span lengths
        // outside it (the extreme arguments dominate the extrapolation); compared by cross
        // multiplication, no division.
        let (lo_arg, hi_arg) = (knots[i + 1], knots[i + p]);
        let (mut best, mut best_d, mut best_l) = (first_piece, f64::INFINITY, 1.0);
        let mut k = first_piece;
        while k < nseg && span_of[k] <= i + p {
            let s = span_of[k];
            let (a, b) = (knots[s], knots[s + 1]);
            let d = (a - lo_arg).max(hi_arg - b).max(0.0);
            if d * best_l < best_d * (b - a) {
                (best, best_d, best_l) = (k, d, b - a);
            }
            k += 1;
        }
        let k = best;
        let s = span_of[k];
        let (a, b) = (knots[s], knots[s + 1]);
        let inv = 1.0 / (b - a);
        for (t, x) in args.iter_mut().zip(&knots[i + 1..=i + p]) {
            *t = (x - a) * inv;
        }
        let scratch = &mut tmp[..m];
        scratch.copy_from_slice(&bez[k * m..(k + 1) * m]);
        for (lvl, &t) in args.iter().enumerate() {
            let u = 1.0 - t;
            for j in 0..p - lvl {
                let (lo, hi) = scratch.split_at_mut((j + 1) * pdim);
                for (x, y) in lo[j * pdim..].iter_mut().zip(&hi[..pdim]) {
                    *x = u * *x + t * y;
                }
            }
        }
        work[i * pdim..(i + 1) * pdim].copy_from_slice(&scratch[..pdim]);
    }
    // 4. The certificate: extract the merged spline again and compare.
    let mut bound = 0.0f64;
    let mut k = 0;
    super::extract_kernel::extract(
        &knots,
        p,
        n,
        pdim,
        |i, o| o.copy_from_slice(&work[i * pdim..(i + 1) * pdim]),
        |_, _, win| {
            if k < nseg {
                for (x, y) in win
                    .chunks_exact(pdim)
                    .zip(bez[k * m..(k + 1) * m].chunks_exact(pdim))
                {
                    bound = bound.max(dist(x, y));
                }
            }
            k += 1;
        },
    );
    if k != nseg {
        bound = f64::INFINITY;
    }
    Merged {
        knots,
        work,
        mults,
        bound,
    }
}

/// Euclidean distance of two working points.
fn dist(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

/// Removes one copy of the last knot of `knots` (index `r`, multiplicity `s`) if the
/// re-insertion residual is `<= budget`; the knots after `r` (not stored yet) are all
/// `next`. Returns the residual, or `None` (nothing changed). The caller pops the knot.
///
/// Equations (knot insertion of `u` into the new curve `Q`): `P_i = a_i Q_i + (1-a_i) Q_{i-1}`,
/// `a_i = (u - u_i)/(u_{i+p+1} - u_i)`, `i = r-p..=r-s`; `Q_{r-p-1} = P_{r-p-1}`,
/// `Q_{r-s} = P_{r-s+1}`. Equations with `a_i >= 1/2` are solved from the left, the others
/// from the right, and the first with `a_i < 1/2` (or the last) is left over and checked.
#[allow(
    clippy::too_many_arguments,
    reason = "one in-place step over the caller's buffers"
)]
fn remove_last_knot(
    knots: &[f64],
    next: f64,
    work: &mut Vec<f64>,
    p: usize,
    pdim: usize,
    s: usize,
    budget: f64,
    tmp: &mut [f64],
    alpha: &mut [f64],
) -> Option<f64> {
    let r = knots.len() - 1;
    let u = knots[r];
    let kn = |i: usize| if i < knots.len() { knots[i] } else { next };
    let (first, last) = (r - p, r - s);
    for i in first..=last {
        alpha[i - first] = (u - kn(i)) / (kn(i + p + 1) - kn(i));
    }
    let k = (first..=last)
        .find(|&i| alpha[i - first] < 0.5)
        .unwrap_or(last);
    // tmp slot m holds Q_{first - 1 + m}, m = 0..=last - first + 1.
    let m_end = last - first + 1;
    tmp[..pdim].copy_from_slice(&work[(first - 1) * pdim..first * pdim]);
    tmp[m_end * pdim..(m_end + 1) * pdim]
        .copy_from_slice(&work[(last + 1) * pdim..(last + 2) * pdim]);
    for i in first..k {
        let a = alpha[i - first];
        let (inv, b) = (1.0 / a, 1.0 - a);
        let m = i - first + 1;
        for c in 0..pdim {
            tmp[m * pdim + c] = (work[i * pdim + c] - b * tmp[(m - 1) * pdim + c]) * inv;
        }
    }
    for i in (k + 1..=last).rev() {
        let a = alpha[i - first];
        let inv = 1.0 / (1.0 - a);
        let m = i - first;
        for c in 0..pdim {
            tmp[m * pdim + c] = (work[i * pdim + c] - a * tmp[(m + 1) * pdim + c]) * inv;
        }
    }
    let a = alpha[k - first];
    let m = k - first + 1;
    let mut eps2 = 0.0;
    for c in 0..pdim {
        let d = work[k * pdim + c] - a * tmp[m * pdim + c] - (1.0 - a) * tmp[(m - 1) * pdim + c];
        eps2 += d * d;
    }
    let eps = eps2.sqrt();
    if !(eps <= budget) {
        return None;
    }
    for i in first..last {
        let m = i - first + 1;
        work[i * pdim..(i + 1) * pdim].copy_from_slice(&tmp[m * pdim..(m + 1) * pdim]);
    }
    work.drain(last * pdim..(last + 1) * pdim);
    Some(eps)
}
