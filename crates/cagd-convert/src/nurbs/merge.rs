//! The general route, reverse: rational (or polynomial) Bézier pieces with their
//! breakpoints → one B-spline / NURBS curve with the highest continuity the pieces actually
//! have at each joint (seed 001 §4.1's exact merge, then knot removal at rounding level;
//! the kernel is `merge_kernel`).

use cagd_core::{BSplineCurve, Result, check_tolerance};

use super::merge_kernel::merge_work;
use super::pieces::BezierPieces;
use super::width::{Width, with_width};

/// The relative tolerance of the default joint check: the pieces are taken to agree when
/// they agree within `DEFAULT_REL_TOL` times the largest working coordinate (the
/// homogeneous `(w x, w)` for rational pieces) — rounding level for pieces that come from
/// one spline, far below any intended break.
pub const DEFAULT_REL_TOL: f64 = 1e-12;

/// One spline made from Bézier pieces, with what was found at the joints.
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsFromPieces {
    /// The spline: degree of the pieces, knots clamped at `breaks[0]` and `breaks[len]`
    /// (or, when the pieces carry [`crate::OuterKnots`], those outer knots), each interior
    /// break with multiplicity `degree - continuity[j]`; rational iff the pieces are.
    pub curve: BSplineCurve,
    /// The parametric continuity found at each interior joint `breaks[j + 1]`: `k` for
    /// `C^k` (`0..degree`), `-1` when the pieces do not meet.
    pub continuity: Vec<i64>,
    /// A certified bound of the distance between the curve and the pieces, in working
    /// coordinates (homogeneous `(w x, w)` when rational): the largest distance between a
    /// Bézier point of the pieces and the same point extracted again from `curve` (convex
    /// hull property).
    pub bound: f64,
    /// The tolerance of each joint that was used (working coordinates).
    pub tolerance: f64,
}

/// `out` = the homogeneous points `(w x, w)` of `points` (`w.get()` coordinates each) and
/// `weights`.
fn homogeneous_into<W: Width>(points: &[f64], weights: &[f64], out: &mut [f64], w: W) {
    let d = w.get();
    for ((o, x), wi) in out
        .chunks_exact_mut(d + 1)
        .zip(points.chunks_exact(d))
        .zip(weights)
    {
        let (o, x) = (&mut o[..d + 1], &x[..d]);
        for c in 0..d {
            o[c] = wi * x[c];
        }
        o[d] = *wi;
    }
}

/// Appends the Euclidean points `h / w` (`w.get()` coordinates each) and the weights `w`
/// of the homogeneous points `hom` (`(h, w)`) to `points` and `weights` (as
/// `cagd_core::kernel::from_homogeneous`, without zeroing the outputs first).
fn euclidean_into<W: Width>(hom: &[f64], points: &mut Vec<f64>, weights: &mut Vec<f64>, w: W) {
    let d = w.get();
    for q in hom.chunks_exact(d + 1) {
        let wq = q[d];
        points.extend(q[..d].iter().map(|x| x / wq));
        weights.push(wq);
    }
}

/// The largest absolute value of `v` (finite values; 0 for none). Eight running maxima:
/// one chain of `max` waits on the previous at every value, eight vectorise (the maximum
/// does not depend on the order).
pub(crate) fn max_abs(v: &[f64]) -> f64 {
    let mut acc = [0.0f64; 8];
    let mut chunks = v.chunks_exact(8);
    for c in &mut chunks {
        for (m, x) in acc.iter_mut().zip(c) {
            *m = bigger(*m, x.abs());
        }
    }
    let rest = chunks
        .remainder()
        .iter()
        .fold(0.0f64, |m, x| bigger(m, x.abs()));
    acc.iter().fold(rest, |m, &a| bigger(m, a))
}

/// `max(m, a)` as a plain comparison rather than `f64::max`: the values are finite
/// (validated), and the plain comparison vectorises.
fn bigger(m: f64, a: f64) -> f64 {
    if a > m { a } else { m }
}

/// Merges Bézier pieces into one spline (the reverse of [`crate::to_bezier_pieces`]).
/// (Seed 001 §4.1's exact merge — pieces joined at knots of multiplicity p — then Tiller's
/// knot-removal conditions per joint at rounding level; the inverse of SPEC-convert
/// §15.1–15.3's extraction.)
///
/// At each joint the end point of one piece and the start of the next must agree within
/// `tol` (Euclidean distance of the working points; else the joint keeps multiplicity
/// `degree + 1`, continuity `-1`); copies of the joint's knot are then removed while the
/// certified residual of the removals at that joint stays within `tol` (the knot keeps at
/// least multiplicity 1, so every break stays a knot). `tol = None` uses
/// [`DEFAULT_REL_TOL`] times the largest working coordinate.
///
/// Measured: a curve split by [`crate::to_bezier_pieces`] comes back with its knot vector
/// (an unclamped one too: the pieces carry its outer knots) and its curve within `1e-12`
/// relative (proptest, degrees 1..=9, up to 100 spans,
/// weights 0.05..20).
///
/// # Errors
/// [`cagd_core::Error::BadTolerance`]; the validation errors of the result (a numerical
/// accident, e.g. an overflow, is an error, never an invalid curve).
///
/// ```
/// # use cagd_core::BSplineCurve;
/// # use cagd_convert::{pieces_to_nurbs, to_bezier_pieces};
/// let c = BSplineCurve::new_rational(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0],
///     vec![0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0], vec![1.0, 2.0, 0.5, 1.0], 2)?;
/// let back = pieces_to_nurbs(&to_bezier_pieces(&c)?, None)?;
/// assert_eq!(back.curve.knots(), c.knots());
/// assert_eq!(back.continuity, vec![1]);
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn pieces_to_nurbs(pieces: &BezierPieces, tol: Option<f64>) -> Result<NurbsFromPieces> {
    let (p, dim) = (pieces.degree(), pieces.dim());
    if let Some(t) = tol {
        check_tolerance(t)?;
    }
    // The working points of every piece, piece-major: (w x, w) when rational.
    let pts = pieces.points();
    let bez = match pieces.weights() {
        None => std::borrow::Cow::Borrowed(pts),
        Some(w) => {
            let mut bez = vec![0.0; w.len() * (dim + 1)];
            with_width!(dim, homogeneous_into(pts, w, &mut bez));
            std::borrow::Cow::Owned(bez)
        }
    };
    // The working scale of the default tolerance: max(|w x|, w) = the largest working
    // coordinate (weights are positive).
    let tol = tol.unwrap_or_else(|| (DEFAULT_REL_TOL * max_abs(&bez)).max(f64::MIN_POSITIVE));
    let pdim = if pieces.is_rational() { dim + 1 } else { dim };
    let merged = merge_work(&bez, pieces.breaks(), p, pdim, tol, pieces.outer_knots());
    let continuity = merged
        .mults
        .iter()
        .map(|&s| i64::try_from(p).unwrap_or(i64::MAX) - i64::try_from(s).unwrap_or(0))
        .collect();
    let curve = if pieces.is_rational() {
        let n = merged.work.len() / (dim + 1);
        let (mut points, mut weights) = (Vec::with_capacity(n * dim), Vec::with_capacity(n));
        with_width!(dim, euclidean_into(&merged.work, &mut points, &mut weights));
        BSplineCurve::new_rational(p, merged.knots, points, weights, dim)?
    } else {
        BSplineCurve::new(p, merged.knots, merged.work, dim)?
    };
    Ok(NurbsFromPieces {
        curve,
        continuity,
        bound: merged.bound,
        tolerance: tol,
    })
}
