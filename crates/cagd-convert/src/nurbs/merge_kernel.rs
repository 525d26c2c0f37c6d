//! The merge kernel of the general route, reverse: consecutive Bézier pieces (working
//! points) → one spline whose knots have the lowest multiplicity the pieces allow (seed
//! 001 §4.1's merge, then knot removal at rounding level).
//!
//! Three passes over the pieces, each `O(p^2)` per piece with no allocation per piece:
//! the continuity decision at each joint (`merge_joint`: Tiller's knot removal on the
//! two-piece spline, certified by its residuals), the control points of the spline with
//! those knots (`merge_blossom`: blossoms of the pieces), and the certificate of the
//! result (the spline extracted again by Böhm insertion, `extract_kernel`, and compared
//! with the pieces point by point: by the convex hull property the largest distance bounds
//! the distance of the curves).

use super::merge_blossom::control_points;
use super::merge_joint::{JointScratch, joint_multiplicity};
use super::outer_knots::OuterKnots;
use super::width::{Width, dist2, with_width};

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
/// working coordinates) `load(k, i, out)` writes; see [`merge_work`].
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
    let nseg = breaks.len() - 1;
    let mut bez = vec![0.0; nseg * (p + 1) * pdim];
    for (idx, o) in bez.chunks_exact_mut(pdim).enumerate() {
        load(idx / (p + 1), idx % (p + 1), o);
    }
    merge_work(&bez, breaks, p, pdim, tol, outer)
}

/// Merges `breaks.len() - 1` pieces of degree `p` given by their working points `bez`
/// (`pdim` coordinates each, piece-major: point `i` of piece `k` at
/// `(k * (p + 1) + i) * pdim`); `tol` is the budget of each joint.
///
/// 1. Each joint is decided on its own, from the two original pieces only
///    (`merge_joint`: a two-piece spline with the joint's knot of multiplicity `p`, copies
///    removed while the summed residual stays `<= tol`). Removing copies joint after joint
///    on one growing spline would feed each joint's rounding into the next joint's
///    extrapolation, and the residuals grow geometrically with the number of joints at
///    high degree (measured: x50 per joint at degree 9).
/// 2. With the knots known (`outer`: the knots beyond the end breaks of an unclamped
///    spline; `None` clamps both ends), control point `i` is the blossom
///    `b(u_{i+1}, ..., u_{i+p})` (Ramshaw) of the piece on one span of its support
///    (`merge_blossom`).
/// 3. The certificate: the merged spline is extracted again (Böhm insertion,
///    `extract_kernel`) and every Bézier point is compared with the piece's.
pub(crate) fn merge_work(
    bez: &[f64],
    breaks: &[f64],
    p: usize,
    pdim: usize,
    tol: f64,
    outer: Option<&OuterKnots>,
) -> Merged {
    with_width!(pdim, merge_w(bez, breaks, p, tol, outer))
}

/// [`merge_work`] for the point width `w`.
fn merge_w<W: Width>(
    bez: &[f64],
    breaks: &[f64],
    p: usize,
    tol: f64,
    outer: Option<&OuterKnots>,
    w: W,
) -> Merged {
    let pdim = w.get();
    let nseg = breaks.len() - 1;
    let m = (p + 1) * pdim;
    let piece = |k: usize| &bez[k * m..(k + 1) * m];
    // 1. Multiplicities, joint by joint, on a two-piece spline of the original pieces.
    let mut mults = Vec::with_capacity(nseg.saturating_sub(1));
    let mut scratch = JointScratch::new(p, pdim);
    for j in 1..nseg {
        let (hl, hr) = (breaks[j] - breaks[j - 1], breaks[j + 1] - breaks[j]);
        let a = hl / (hl + hr);
        mults.push(joint_multiplicity(
            piece(j - 1),
            piece(j),
            p,
            a,
            tol,
            w,
            &mut scratch,
        ));
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
    let mut work = Vec::new();
    control_points(bez, &knots, &span_of, p, w, &mut work);
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
                    let e2 = dist2(w, x, y);
                    // (A plain comparison: f64::max costs more and likewise skips a NaN,
                    // which the validation of the result reports.)
                    if e2 > worst2 {
                        worst2 = e2;
                    }
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
