//! Seed 001 (Xu et al. 2012, "Matrix representation of multi-degree elevation/reduction of
//! uniform B-splines"): degree reduction of a uniform B-spline segment by segment,
//! `P' = T_{z-b}^m T_{n,m} T_{b-z}^n P` (model (1)), with `T_{b-z}^n = S^(n)` (eq. 5; the
//! printed eq. 4 is wrong, SPEC-reduce §8), any Bézier reducer of this crate as `T_{n,m}`
//! and one of the two merges of §4.
//!
//! The per-segment matrices `T S^(n)` (exact merge) and `S^(m)^{-1} T S^(n)` (lossy merge)
//! are built once per `(method, n, m)` in exact rational arithmetic, rounded once to `f64`
//! and cached process-wide, as the paper intends (one matrix product per segment).
//! Coordinates outside `[2^-450, 2^450]` are reduced in a frame scaled by a power of two
//! (`scaled.rs`).

mod scaled;

use std::collections::HashMap;
use std::sync::{Arc, OnceLock, RwLock};

use cagd_core::{
    BSplineCurve, BezierCurve, Error, Result, s_matrix, s_matrix_exact, s_matrix_inverse_exact,
};

use super::framed;
use super::measure::euclidean_from_homogeneous;
use crate::bezier::{hull_bound, max_norm, safe_amax};
use crate::exact::{Q, RatMat};
use crate::{Method, operator};

/// How the reduced segments are joined (seed 001 §4).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Merge {
    /// §4.1: the reduced Bézier segments become one clamped spline with interior knots of
    /// multiplicity `m - k`, where `k = min(r, p)` are the end orders the method keeps
    /// ([`Method::end_orders`]), verified by [`BSplineCurve::from_beziers`]. Exact: the
    /// spline is the reduced segments. Needs a method that interpolates the ends (`k >= 0`).
    Exact,
    /// §4.2: each reduced segment is turned into local uniform B-spline points
    /// `S^(m)^{-1} q` (segment `s` gives global points `s..=s+m`) and overlapping points are
    /// averaged. Keeps uniform simple knots (C^(m-1)) at the price of an uncontrolled
    /// change (the certified bound below measures it afterwards).
    Lossy,
}

/// The result of [`reduce_uniform_bspline`].
#[derive(Debug, Clone, PartialEq)]
pub struct UniformReduction {
    /// The merged degree-`m` spline, on the input's parameter domain. [`Merge::Exact`]:
    /// clamped knots with interior multiplicity `m - k`. [`Merge::Lossy`]: the uniform knots
    /// of the input's spacing `h`, shifted by `(n - m) h` (the paper numbers them from 0;
    /// e.g. its example prints 0..8, here 4..12, the domain [7, 9] of the input).
    pub curve: BSplineCurve,
    /// The reduced Bézier segments (on `[0, 1]` each), before the merge.
    pub segments: Vec<BezierCurve>,
    /// Certified bound of `max_t ||C(t) - Q_s(t)||` over the reduced segments (the
    /// reduction step alone; Euclidean, model space).
    pub segment_bound: f64,
    /// Certified bound of `max_t ||C(t) - C'(t)||` for the returned spline (Euclidean):
    /// equal to `segment_bound` plus the merge's joint allowance for [`Merge::Exact`], the
    /// convex-hull bound of every span of the merged spline against the input's Bézier
    /// span for [`Merge::Lossy`].
    pub error_bound: f64,
}

/// The cached per-segment matrices of one `(method, n, m)`.
#[derive(Debug)]
struct SegmentMatrices {
    /// `T S^(n)`, `(m+1) x (n+1)`: uniform B-spline points -> reduced Bézier points.
    to_bezier: Vec<f64>,
    /// `S^(m)^{-1} T S^(n)`, `(m+1) x (n+1)`: -> local uniform degree-`m` points.
    to_local: Vec<f64>,
}

type Key = ((u8, u64, u64), usize, usize);

fn cache() -> &'static RwLock<HashMap<Key, Arc<SegmentMatrices>>> {
    static CACHE: OnceLock<RwLock<HashMap<Key, Arc<SegmentMatrices>>>> = OnceLock::new();
    CACHE.get_or_init(|| RwLock::new(HashMap::new()))
}

fn rat(flat: &[Q], n: usize) -> RatMat {
    RatMat::from_rows(flat.chunks_exact(n).map(<[Q]>::to_vec).collect())
}

fn matrices(method: Method, n: usize, m: usize) -> Result<Arc<SegmentMatrices>> {
    let key = (method.key(), n, m);
    if let Ok(map) = cache().read() {
        if let Some(x) = map.get(&key) {
            return Ok(Arc::clone(x));
        }
    }
    let (t, _) = crate::bezier::exact_operator(method, n, m)?;
    let ts = t.mul(&rat(s_matrix_exact(n)?, n + 1))?;
    let local = rat(s_matrix_inverse_exact(m)?, m + 1).mul(&ts)?;
    let built = Arc::new(SegmentMatrices {
        to_bezier: ts.to_f64(),
        to_local: local.to_f64(),
    });
    let mut map = cache()
        .write()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    Ok(Arc::clone(map.entry(key).or_insert(built)))
}

/// `out = A x` for a row-major `rows x cols` matrix and `cols` points of `pdim` coordinates.
fn apply(a: &[f64], cols: usize, x: &[f64], pdim: usize, out: &mut Vec<f64>) {
    out.clear();
    for row in a.chunks_exact(cols) {
        for c in 0..pdim {
            out.push(
                row.iter()
                    .enumerate()
                    .map(|(j, v)| v * x[j * pdim + c])
                    .sum(),
            );
        }
    }
}

/// Largest gap deviation accepted as uniform, relative to the spacing `h`: enough for
/// uniform knots rounded to `f64` up to `|knot| / h` of about `2e6`, and small enough that
/// the seed's uniform model and the actual spline differ only by rounding (the difference
/// is bounded and added anyway, see [`uniform_at`]).
const UNIFORM_GAP_TOL: f64 = 1e-9;

/// The uniform knot spacing of `knots`, or an error if they are not uniform: every gap
/// within `1e-9 h` of `h`, relative to the spacing itself (a tolerance relative to the
/// knots' magnitude would call a spacing of a few ulps uniform).
fn uniform_spacing(knots: &[f64]) -> Result<f64> {
    let h = (knots[knots.len() - 1] - knots[0]) / (knots.len() - 1) as f64;
    let tol = UNIFORM_GAP_TOL * h;
    if h <= 0.0 || knots.windows(2).any(|w| ((w[1] - w[0]) - h).abs() > tol) {
        return Err(Error::BadParameter {
            name: "knots",
            value: h,
            why: "seed 001 needs uniform (equally spaced, simple) knots: every gap within \
                  1e-9 of the spacing (a spacing of a few ulps of the knots is not uniform)",
        });
    }
    Ok(h)
}

/// The Bézier pieces of every span of the spline `(degree, knots, work)` in working
/// coordinates (`pdim`, homogeneous for a NURBS), as flat point lists.
fn pieces(degree: usize, knots: &[f64], work: &[f64], pdim: usize) -> Result<Vec<Vec<f64>>> {
    Ok(
        BSplineCurve::new(degree, knots.to_vec(), work.to_vec(), pdim)?
            .to_beziers()?
            .into_iter()
            .map(|s| s.curve.points().to_vec())
            .collect(),
    )
}

/// Reduces a uniform B-spline (or NURBS: the homogeneous points are reduced) of degree `n`
/// to degree `m` segment by segment (seed 001, model (1)): the B-spline points of each
/// segment go to its Bézier points by `S^(n)` (eq. 5), `method` reduces them
/// (`T_{n,m}`; "any published method", §3.3), and `merge` joins the results (§4).
///
/// A NURBS is reduced in its frame (centred at the origin, scaled to radius 1; moved
/// back after, the rounding added to the bounds; ADDED, beyond
/// the seed), so its model-space bounds are the centred, unit-consistent ones
/// ([`cagd_core::centred_rational_bound`]): the same curve moved or scaled gives the same
/// result, and bounds that scale with it.
///
/// The seed's worked example (SPEC-reduce §8, vector `001-example`: degree 7, 9 points,
/// knots 0..16 -> degree 3 by the C1 Hermite reduction `ConstrainedChebyshev { r: 1, p: 1 }`,
/// lossy merge) is reproduced: Bézier points of both segments, reduced Bézier points, local
/// cubic points and merged points to `1e-12` of the spec's exact values; the paper's own
/// printed numbers only to their print accuracy (reduced points `1.2e-5`, local points
/// `1.6e-4`, both within the single-precision noise SPEC-reduce §8 documents). The
/// measured errors match the spec (reduction step `1.30e-2`, after the lossy merge
/// `5.4e-2`; the paper's "average error 5e-3" is the mean of the reduction step).
///
/// Coordinates outside `[2^-450, 2^450]` (e.g. near `1e300`, where the squares in the
/// bounds overflow), or a curve whose bounds overflow in its own units, are reduced in a
/// frame scaled by a power of two (exact; the result and its bounds moved back, the
/// rounding of subnormal coordinates added; ADDED, beyond the seed): only a bound or a
/// point that overflows in model units is refused.
///
/// # Errors
/// [`Error::BadParameter`] (knots not uniform, [`Merge::Exact`] with a method that does
/// not interpolate the segment ends, or coordinates so near the largest double that the
/// certified bound or the reduced points overflow in model units); the errors of
/// [`Method::check`] for `(n, m)`;
/// [`Error::ConditionNotMet`] if the exact merge finds joints that do not meet;
/// [`Error::NonPositiveWeight`] when a reduced weight of a NURBS is not positive.
///
/// ```
/// use cagd_core::BSplineCurve;
/// use cagd_reduce::{Merge, Method, reduce_uniform_bspline};
/// let pts = vec![3.0, 3.0, 5.0, 9.5, 7.0, 2.0, 8.0, 9.0, 10.0, 3.0, 11.0, 8.0, 13.0, 5.0,
///                14.0, 6.0, 16.0, 4.0];
/// let knots: Vec<f64> = (0..=16).map(f64::from).collect();
/// let c = BSplineCurve::new(7, knots, pts, 2)?;
/// let hermite = Method::ConstrainedChebyshev { r: 1, p: 1 };
/// let lossy = reduce_uniform_bspline(&c, 3, hermite, Merge::Lossy)?;
/// assert_eq!(lossy.curve.n_points(), 5);
/// assert!((lossy.curve.points()[2] - 8.209788359788).abs() < 1e-11); // paper: 8.209788
/// let exact = reduce_uniform_bspline(&c, 3, hermite, Merge::Exact)?;
/// assert_eq!(exact.curve.knots(), &[7.0, 7.0, 7.0, 7.0, 8.0, 8.0, 9.0, 9.0, 9.0, 9.0]);
/// let d = cagd_reduce::spline_max_deviation(&c, &exact.curve)?;
/// assert!((d - 0.0130).abs() < 1e-4 && d <= exact.error_bound); // SPEC-reduce §8: 1.30e-2
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn reduce_uniform_bspline(
    curve: &BSplineCurve,
    m: usize,
    method: Method,
    merge: Merge,
) -> Result<UniformReduction> {
    let amax = curve.points().iter().fold(0.0f64, |a, x| a.max(x.abs()));
    if safe_amax(amax) {
        match uniform_model(curve, m, method, merge) {
            // Bounds that overflow in the curve's own units: again in the scaled frame.
            Err(Error::BadParameter { name: "points", .. }) => {}
            r => return r,
        }
    }
    scaled::reduce_scaled(curve, amax, |c| uniform_model(c, m, method, merge))
}

/// [`reduce_uniform_bspline`] in model units: a NURBS in its frame, a polynomial curve as
/// it is.
fn uniform_model(
    curve: &BSplineCurve,
    m: usize,
    method: Method,
    merge: Merge,
) -> Result<UniformReduction> {
    let Some((frame, moved)) = framed::frame_curve(curve, f64::INFINITY)? else {
        return uniform_at(curve, m, method, merge);
    };
    let red = uniform_at(&moved, m, method, merge)?;
    let out = red.curve.points().to_vec();
    let seg_out: Vec<f64> = red
        .segments
        .iter()
        .flat_map(|s| s.points().iter().copied())
        .collect();
    let segments = red
        .segments
        .iter()
        .map(|s| match s.weights() {
            Some(w) => {
                BezierCurve::new_rational(frame.frame.from_frame(s.points()), w.to_vec(), s.dim())
            }
            None => BezierCurve::new(frame.frame.from_frame(s.points()), s.dim()),
        })
        .collect::<Result<_>>()?;
    Ok(UniformReduction {
        curve: framed::unframe_curve(&frame, &red.curve)?,
        segments,
        segment_bound: frame.finish(red.segment_bound, &seg_out),
        error_bound: frame.finish(red.error_bound, &out),
    })
}

/// [`reduce_uniform_bspline`] on a polynomial or framed rational curve.
fn uniform_at(
    curve: &BSplineCurve,
    m: usize,
    method: Method,
    merge: Merge,
) -> Result<UniformReduction> {
    let (n, dim, knots) = (curve.degree(), curve.dim(), curve.knots());
    method.check(n, m)?;
    uniform_spacing(knots)?;
    let k = method.end_orders(m).0.min(method.end_orders(m).1);
    if merge == Merge::Exact && k < 0 {
        return Err(Error::BadParameter {
            name: "merge",
            value: f64::from(k),
            why: "the exact merge needs a method that interpolates the segment ends",
        });
    }
    let mats = matrices(method, n, m)?;
    let weights = curve.weights();
    let pdim = if weights.is_some() { dim + 1 } else { dim };
    let work = match weights {
        Some(_) => curve.homogeneous_points(),
        None => curve.points().to_vec(),
    };
    let nseg = curve.n_points() - n;
    let s_n = s_matrix(n)?;
    let (mut bez_in, mut bez_out) = (Vec::new(), Vec::new());
    let mut segments = Vec::with_capacity(nseg);
    let mut reduced_work = Vec::with_capacity(nseg);
    let mut seg_bound_h = 0.0f64;
    let mut input_bez = Vec::with_capacity(nseg);
    for s in 0..nseg {
        let local = &work[s * pdim..(s + n + 1) * pdim];
        apply(s_n, n + 1, local, pdim, &mut bez_in);
        apply(&mats.to_bezier, n + 1, local, pdim, &mut bez_out);
        let op = operator(method, n, m)?;
        seg_bound_h = seg_bound_h.max(op.error_bound(&bez_in, &bez_out, pdim)?);
        segments.push(to_curve(&bez_out, pdim, weights.is_some())?);
        reduced_work.push(bez_out.clone());
        input_bez.push(bez_in.clone());
    }
    // Model-space conversion of a homogeneous bound (identity for polynomial curves).
    let to_model = |eps_h: f64, out_pts: &[f64]| -> f64 {
        match weights {
            None => eps_h,
            Some(w) => {
                let wmin = w.iter().copied().fold(f64::INFINITY, f64::min);
                let vmin = out_pts
                    .chunks_exact(pdim)
                    .map(|p| p[dim])
                    .fold(f64::INFINITY, f64::min);
                euclidean_from_homogeneous(eps_h, max_norm(curve.points(), dim), wmin, vmin)
            }
        }
    };
    // The seed's model takes the knots as exactly uniform; the actual spans of the input
    // (its knots uniform within `UNIFORM_GAP_TOL`, rounded) may differ from the model's
    // `S^(n)` pieces: that difference, bounded by the convex hull, is part of every bound.
    let actual_in = pieces(n, knots, &work, pdim)?;
    let model_gap_h = actual_in
        .iter()
        .zip(&input_bez)
        .map(|(a, b)| hull_bound(a, b, pdim))
        .fold(0.0f64, f64::max);
    let all_reduced: Vec<f64> = reduced_work.concat();
    let segment_bound = to_model(seg_bound_h + model_gap_h, &all_reduced);
    if !segment_bound.is_finite() {
        return Err(overflow(curve));
    }
    let (merged, error_bound) = match merge {
        Merge::Exact => {
            // The input's own span ends: the output has the input's parameterization.
            let breaks = knots[n..=n + nseg].to_vec();
            let scale = max_norm(&work, pdim) + 1.0;
            // The joints agree up to the rounding of the reduced points; the merge moves a
            // joint point by at most tol / 2 and the knot removals by at most tol in total.
            // Rounding of the reduced points: (n + 1) ulp per entry of `T S^(n)`, with a
            // generous factor 256.
            let norm = mats
                .to_bezier
                .chunks_exact(n + 1)
                .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
                .fold(0.0, f64::max);
            let tol = 256.0 * (n + 1) as f64 * f64::EPSILON * scale * norm;
            let c = BSplineCurve::from_beziers(&segments, &breaks, k as usize, tol)?;
            (c, segment_bound + to_model(0.5 * tol, &all_reduced) + tol)
        }
        Merge::Lossy => {
            let npts = nseg + m;
            let mut acc = vec![0.0; npts * pdim];
            let mut count = vec![0usize; npts];
            let mut loc = Vec::new();
            for s in 0..nseg {
                apply(
                    &mats.to_local,
                    n + 1,
                    &work[s * pdim..(s + n + 1) * pdim],
                    pdim,
                    &mut loc,
                );
                for (i, p) in loc.chunks_exact(pdim).enumerate() {
                    count[s + i] += 1;
                    for c in 0..pdim {
                        acc[(s + i) * pdim + c] += p[c];
                    }
                }
            }
            for (p, c) in acc.chunks_exact_mut(pdim).zip(&count) {
                p.iter_mut().for_each(|x| *x /= *c as f64);
            }
            // The input's knots shifted by `n - m` (uniform spacing `h`, the input's
            // domain), taken from the input rather than recomputed so that no rounding of
            // `knot + i h` moves them.
            let new_knots = knots[n - m..n - m + npts + m + 1].to_vec();
            // Every span of the merged spline against the input's span, both extracted
            // from the actual knots.
            let bound_h = actual_in
                .iter()
                .zip(pieces(m, &new_knots, &acc, pdim)?)
                .map(|(bin, span)| hull_bound(bin, &span, pdim))
                .fold(0.0f64, f64::max);
            let c = match weights {
                None => BSplineCurve::new(m, new_knots, acc.clone(), dim)?,
                Some(_) => {
                    let mut pts = vec![0.0; npts * dim];
                    let mut w = vec![0.0; npts];
                    cagd_core::kernel::from_homogeneous(&acc, dim, &mut pts, &mut w);
                    BSplineCurve::new_rational(m, new_knots, pts, w, dim)?
                }
            };
            (c, to_model(bound_h, &acc))
        }
    };
    if !error_bound.is_finite() {
        return Err(overflow(curve));
    }
    Ok(UniformReduction {
        curve: merged,
        segments,
        segment_bound,
        error_bound,
    })
}

/// The error for coordinates whose certified bound overflows (e.g. near 1e300): a report
/// without a finite bound would be garbage; [`reduce_uniform_bspline`] tries such a curve
/// again in a scaled frame.
fn overflow(curve: &BSplineCurve) -> Error {
    scaled::too_large(
        curve,
        "coordinates too large: the certified error bound overflows",
    )
}

/// A Bézier curve from working points (homogeneous when `rational`).
pub(crate) fn to_curve(work: &[f64], pdim: usize, rational: bool) -> Result<BezierCurve> {
    if rational {
        if let Some((index, p)) = work
            .chunks_exact(pdim)
            .enumerate()
            .find(|(_, p)| p[pdim - 1].is_nan() || p[pdim - 1] <= 0.0)
        {
            return Err(Error::NonPositiveWeight {
                index,
                weight: p[pdim - 1],
            });
        }
        BezierCurve::from_homogeneous(work, pdim)
    } else {
        BezierCurve::new(work.to_vec(), pdim)
    }
}

#[cfg(test)]
mod tests;
