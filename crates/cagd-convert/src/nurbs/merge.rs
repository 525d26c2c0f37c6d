//! The general route, reverse: rational (or polynomial) Bézier pieces with their
//! breakpoints → one B-spline / NURBS curve with the highest continuity the pieces actually
//! have at each joint (seed 001 §4.1's exact merge, then knot removal at rounding level;
//! the kernel is `merge_kernel`).

use cagd_core::{BSplineCurve, Result, check_tolerance, kernel};

use super::merge_kernel::merge;
use super::pieces::BezierPieces;

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

/// The largest absolute working coordinate of the pieces (`max(|w x|, w)` when rational).
pub(crate) fn working_scale(points: &[f64], weights: Option<&[f64]>, dim: usize) -> f64 {
    // `if a > m` rather than `f64::max`: the values are finite (validated), and the plain
    // comparison vectorises.
    let bigger = |m: f64, a: f64| if a > m { a } else { m };
    match weights {
        None => points.iter().fold(0.0f64, |m, x| bigger(m, x.abs())),
        Some(w) => points.chunks_exact(dim).zip(w).fold(0.0f64, |m, (p, wi)| {
            p.iter()
                .fold(bigger(m, *wi), |m, x| bigger(m, (x * wi).abs()))
        }),
    }
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
    let tol = match tol {
        Some(t) => {
            check_tolerance(t)?;
            t
        }
        None => (DEFAULT_REL_TOL * working_scale(pieces.points(), pieces.weights(), dim))
            .max(f64::MIN_POSITIVE),
    };
    let pts = pieces.points();
    let outer = pieces.outer_knots();
    let m = p + 1;
    let merged = match pieces.weights() {
        None => merge(pieces.breaks(), p, dim, tol, outer, |k, i, o| {
            let at = (k * m + i) * dim;
            o.copy_from_slice(&pts[at..at + dim]);
        }),
        Some(w) => merge(pieces.breaks(), p, dim + 1, tol, outer, |k, i, o| {
            let at = k * m + i;
            let wi = w[at];
            for (x, y) in o[..dim].iter_mut().zip(&pts[at * dim..(at + 1) * dim]) {
                *x = wi * y;
            }
            o[dim] = wi;
        }),
    };
    let continuity = merged
        .mults
        .iter()
        .map(|&s| i64::try_from(p).unwrap_or(i64::MAX) - i64::try_from(s).unwrap_or(0))
        .collect();
    let curve = if pieces.is_rational() {
        let n = merged.work.len() / (dim + 1);
        let mut points = vec![0.0; n * dim];
        let mut weights = vec![0.0; n];
        kernel::from_homogeneous(&merged.work, dim, &mut points, &mut weights);
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
