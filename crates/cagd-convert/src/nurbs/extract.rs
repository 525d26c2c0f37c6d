//! The general route, forward (SPEC-convert §15.3 "Recommendation"): a B-spline / NURBS
//! curve of any degree → its (rational) Bézier pieces, by Böhm knot insertion in
//! homogeneous space (the kernel in `extract_kernel`).

use cagd_core::{BSplineCurve, BezierCurve, Result, check_knots};

use super::extract_kernel::extract;
use super::outer_knots::OuterKnots;
use super::pieces::BezierPieces;
use super::span::homogeneous;

/// Every non-empty span of `curve` as a Bézier piece, rational when the curve is (the
/// homogeneous points `(w P, w)` are subdivided, so the piece weights are positive), with
/// the distinct knot values of the domain as breaks. Clamped or unclamped knots, any
/// multiplicity up to `degree + 1`; the knots of an unclamped curve beyond its domain are
/// kept as [`BezierPieces::outer_knots`], so that [`crate::pieces_to_nurbs`] gives back
/// the same knot vector.
/// (SPEC-convert §15.3 recommendation: Bézier point `i` of a span is the blossom
/// `b(t_n^(p-i), t_{n+1}^i)`; the closed forms of §15.1 / §15.3 are its p = 2, 3 cases.)
///
/// Measured: the pieces evaluate to the curve within `1e-13` relative (proptest, degrees
/// 1..=9, up to 100 spans, weights 0.05..20).
///
/// # Errors
/// [`cagd_core::Error::NonFinite`] only when a piece overflows (points near `f64::MAX`).
///
/// ```
/// # use cagd_core::BSplineCurve;
/// # use cagd_convert::to_bezier_pieces;
/// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0],
///                           vec![0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0], 2)?;
/// let pieces = to_bezier_pieces(&c)?;
/// assert_eq!(pieces.breaks(), &[0.0, 0.5, 1.0]);
/// assert_eq!(pieces.piece_points(1), &[2.0, 2.0, 3.0, 2.0, 4.0, 0.0]);
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn to_bezier_pieces(curve: &BSplineCurve) -> Result<BezierPieces> {
    let mut out = BezierPieces::default();
    to_bezier_pieces_into(curve, &mut out)?;
    Ok(out)
}

/// As [`to_bezier_pieces`], writing into `out` and reusing its buffers (no allocation when
/// they are large enough, e.g. in a loop over curves of one size).
///
/// # Errors
/// As [`to_bezier_pieces`].
pub fn to_bezier_pieces_into(curve: &BSplineCurve, out: &mut BezierPieces) -> Result<()> {
    let (p, dim, n) = (curve.degree(), curve.dim(), curve.n_points());
    let u = curve.knots();
    let (lo, hi) = curve.domain();
    let mut spans = 1;
    let mut prev = lo;
    for &k in &u[p + 1..n] {
        if k > prev && k < hi {
            spans += 1;
            prev = k;
        }
    }
    out.degree = p;
    out.dim = dim;
    out.outer = OuterKnots::of_knots(u, p, n);
    out.breaks.clear();
    out.breaks.reserve(spans + 1);
    out.points.clear();
    out.points.reserve(spans * (p + 1) * dim);
    let pts = curve.points();
    match curve.weights() {
        None => {
            out.weights = None;
            extract(
                u,
                p,
                n,
                dim,
                |i, o| o.copy_from_slice(&pts[i * dim..(i + 1) * dim]),
                |a, b, win| {
                    if out.breaks.is_empty() {
                        out.breaks.push(a);
                    }
                    out.breaks.push(b);
                    out.points.extend_from_slice(win);
                },
            );
        }
        Some(w) => {
            let mut ws = out.weights.take().unwrap_or_default();
            ws.clear();
            ws.reserve(spans * (p + 1));
            let pdim = dim + 1;
            extract(
                u,
                p,
                n,
                pdim,
                |i, o| {
                    let wi = w[i];
                    for (x, y) in o[..dim].iter_mut().zip(&pts[i * dim..(i + 1) * dim]) {
                        *x = wi * y;
                    }
                    o[dim] = wi;
                },
                |a, b, win| {
                    if out.breaks.is_empty() {
                        out.breaks.push(a);
                    }
                    out.breaks.push(b);
                    for q in win.chunks_exact(pdim) {
                        let wq = q[dim];
                        let inv = 1.0 / wq;
                        out.points.extend(q[..dim].iter().map(|x| x * inv));
                        ws.push(wq);
                    }
                },
            );
            if let Some(i) = ws
                .iter()
                .position(|x| !(x.is_finite() && *x >= f64::MIN_POSITIVE))
            {
                return Err(cagd_core::Error::NonPositiveWeight {
                    index: i,
                    weight: ws[i],
                });
            }
            out.weights = Some(ws);
        }
    }
    if let Some(pos) = out.points.iter().position(|x| !x.is_finite()) {
        return Err(cagd_core::Error::NonFinite {
            index: pos / dim,
            coord: pos % dim,
            value: out.points[pos],
        });
    }
    Ok(())
}

/// One NURBS span of any degree `p` → its rational Bézier segment, by the general route:
/// `knots` are the `2p` local knots `t_{n-p+1} <= ... <= t_n < t_{n+1} <= ... <= t_{n+p}`,
/// `points` the `p + 1` points `r_{n-p}..r_n` (flat), `weights` their weights. For `p = 2`
/// and `p = 3` this equals the closed forms of SPEC-convert §15.1 and §15.3 (tested).
///
/// # Errors
/// [`cagd_core::Error::KnotCount`] (not `2p` knots), the knot, point and weight errors of
/// [`cagd_core::BSplineCurve::new_rational`], `BadParameter` (`"span"`) for a zero-length
/// span.
pub fn span_to_bezier(
    degree: usize,
    knots: &[f64],
    points: &[f64],
    weights: &[f64],
    dim: usize,
) -> Result<BezierCurve> {
    let p = degree;
    if knots.len() != 2 * p {
        return Err(cagd_core::Error::KnotCount {
            got: knots.len(),
            expected: 2 * p,
        });
    }
    homogeneous(points, weights, dim, p + 1)?;
    if p == 0 {
        return BezierCurve::new_rational(points.to_vec(), weights.to_vec(), dim);
    }
    if let Some(i) = knots.iter().position(|k| !k.is_finite()) {
        return Err(cagd_core::Error::NonFiniteKnot {
            index: i,
            value: knots[i],
        });
    }
    let len = knots[p] - knots[p - 1];
    if len.is_nan() || len <= 0.0 {
        return Err(cagd_core::Error::BadParameter {
            name: "span",
            value: len,
            why: "the knot span [t_n, t_{n+1}] must have positive length",
        });
    }
    let mut full = Vec::with_capacity(2 * p + 2);
    full.push(knots[0]);
    full.extend_from_slice(knots);
    full.push(knots[2 * p - 1]);
    check_knots(&full, p + 1, p)?;
    let c = BSplineCurve::new_rational(p, full, points.to_vec(), weights.to_vec(), dim)?;
    let pieces = to_bezier_pieces(&c)?;
    pieces.piece(0).and_then(|b| {
        let (pts, w) = b.into_parts();
        BezierCurve::new_rational(pts, w.unwrap_or_else(|| vec![1.0; p + 1]), dim)
    })
}
