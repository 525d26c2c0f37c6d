//! NURBS curves and surfaces moved into their [`ModelFrame`] and back: the B-spline
//! strategies that bound a rational change by one homogeneous number (segments,
//! Piegl–Tiller, the uniform pipeline, the patch-wise surface reducer) run on the framed
//! shape, so their bound is the centred, unit-consistent one of [`cagd_core::frame`
//! docs](cagd_core::centred_rational_bound) (ADDED, beyond the seeds).

use cagd_core::{BSplineCurve, BSplineSurface, Error, ModelFrame, Result};

use super::measure::{Known, SpanCaps, spline_max_deviation_known};
use super::options::{BSplineOptions, BSplineReduction};

/// A rational shape's frame and the tolerance to use inside it.
pub(crate) struct Frame {
    /// The frame of the input's control points.
    pub(crate) frame: ModelFrame,
    /// `(tol - allowance) / s`: the tolerance for the framed shape.
    pub(crate) inner_tol: f64,
}

/// Model-space slack reserved for the frame's rounding: the in-map's plus the out-map's
/// of points up to twice the framed input's size (a reduced point further out than that is
/// charged its own rounding by [`Frame::finish`]).
fn reserve(frame: &ModelFrame, framed: &[f64]) -> f64 {
    let doubled: Vec<f64> = framed.iter().map(|x| 2.0 * x.abs() + 1.0).collect();
    frame.rounding(&doubled)
}

impl Frame {
    /// The frame of `points` (`dim` coordinates each) and the inner tolerance for `tol`.
    ///
    /// # Errors
    /// [`Error::ConditionNotMet`] (eq. "tolerance") when `tol` is below twice the rounding
    /// level of the coordinates (a NURBS at `1e8` cannot be reduced to `1e-9`).
    pub(crate) fn new(points: &[f64], dim: usize, tol: f64) -> Result<(Self, Vec<f64>)> {
        let frame = ModelFrame::new(points, dim);
        let framed = frame.to_frame(points);
        let slack = reserve(&frame, &framed);
        let inner = tol - slack;
        if inner.is_nan() || slack >= 0.5 * tol {
            return Err(Error::ConditionNotMet {
                eq: "tolerance",
                why: "the tolerance is below the rounding level of the coordinates",
            });
        }
        let inner_tol = inner / frame.scale();
        Ok((Self { frame, inner_tol }, framed))
    }

    /// An error from inside the frame in model units: [`Error::NoConvergence`] gets the
    /// caller's tolerance `tol` and its achieved bound scaled back; others pass.
    pub(crate) fn model_error(&self, e: Error, tol: f64) -> Error {
        match e {
            Error::NoConvergence { achieved, .. } => Error::NoConvergence {
                tolerance: tol,
                achieved: achieved * self.frame.scale(),
            },
            other => other,
        }
    }

    /// Homogeneous points `(w x, w)` of the frame (`dim + 1` values each) moved back to
    /// the model: `(s (w x) + c w, w)`, the homogeneous form of `s x + c` (exact up to
    /// the rounding of the products and the sum).
    pub(crate) fn unframe_homogeneous(&self, points: &[f64]) -> Vec<f64> {
        let (centre, s) = (self.frame.centre(), self.frame.scale());
        let hdim = centre.len() + 1;
        let mut out = Vec::with_capacity(points.len());
        for q in points.chunks_exact(hdim) {
            let w = q[hdim - 1];
            out.extend(q[..hdim - 1].iter().zip(centre).map(|(x, c)| s * x + c * w));
            out.push(w);
        }
        out
    }

    /// The model-space bound of a bound `b` found in the frame for the framed result
    /// `out` (frame units): `s b` plus the round trip's rounding.
    pub(crate) fn finish(&self, b: f64, out: &[f64]) -> f64 {
        self.finish_rounded(b, self.frame.rounding(out))
    }

    /// [`Frame::finish`] with the out-map's rounding `rounding` of the result computed
    /// once (for many bounds of one result).
    fn finish_rounded(&self, b: f64, rounding: f64) -> f64 {
        b * self.frame.scale() * (1.0 + 2.0 * f64::EPSILON) + rounding
    }
}

/// `curve` (rational) moved into its frame, with the frame; `None` for a polynomial curve
/// (its bounds are already unit-consistent).
///
/// # Errors
/// As [`Frame::new`].
pub(crate) fn frame_curve(curve: &BSplineCurve, tol: f64) -> Result<Option<(Frame, BSplineCurve)>> {
    let Some(w) = curve.weights() else {
        return Ok(None);
    };
    let (f, pts) = Frame::new(curve.points(), curve.dim(), tol)?;
    let framed = BSplineCurve::new_rational(
        curve.degree(),
        curve.knots().to_vec(),
        pts,
        w.to_vec(),
        curve.dim(),
    )?;
    Ok(Some((f, framed)))
}

/// A framed curve moved back to model space (weights and knots unchanged).
///
/// # Errors
/// Those of [`BSplineCurve::new_rational`] (not expected: the input was valid).
pub(crate) fn unframe_curve(frame: &Frame, c: &BSplineCurve) -> Result<BSplineCurve> {
    let pts = frame.frame.from_frame(c.points());
    match c.weights() {
        Some(w) => {
            BSplineCurve::new_rational(c.degree(), c.knots().to_vec(), pts, w.to_vec(), c.dim())
        }
        None => BSplineCurve::new(c.degree(), c.knots().to_vec(), pts, c.dim()),
    }
}

/// `s` (rational) moved into its frame, with the frame; `None` for a polynomial surface.
///
/// # Errors
/// As [`Frame::new`].
pub(crate) fn frame_surface(
    s: &BSplineSurface,
    tol: f64,
) -> Result<Option<(Frame, BSplineSurface)>> {
    let Some(w) = s.weights() else {
        return Ok(None);
    };
    let (f, pts) = Frame::new(s.points(), s.dim(), tol)?;
    let framed = BSplineSurface::new_rational(
        s.degrees(),
        s.knots_u().to_vec(),
        s.knots_v().to_vec(),
        pts,
        w.to_vec(),
        s.counts(),
        s.dim(),
    )?;
    Ok(Some((f, framed)))
}

/// A framed surface moved back to model space.
///
/// # Errors
/// Those of the surface constructors (not expected: the input was valid).
pub(crate) fn unframe_surface(frame: &Frame, s: &BSplineSurface) -> Result<BSplineSurface> {
    let pts = frame.frame.from_frame(s.points());
    let (ku, kv) = (s.knots_u().to_vec(), s.knots_v().to_vec());
    match s.weights() {
        Some(w) => {
            BSplineSurface::new_rational(s.degrees(), ku, kv, pts, w.to_vec(), s.counts(), s.dim())
        }
        None => BSplineSurface::new(s.degrees(), ku, kv, pts, s.counts(), s.dim()),
    }
}

/// Runs the curve reduction `reduce` in the frame of `curve` (the centred, scaled control
/// points of [`frame_curve`], the tolerance shrunk to the frame's inner tolerance, no
/// measurement), moves the result back and finishes its bounds with the round trip's
/// rounding ([`Frame::finish`]); `reduce` on `curve` itself when there is no frame. The
/// tolerance is checked again on the finished bound, and the measured error, if asked, is
/// taken against the input itself.
///
/// # Errors
/// Those of `reduce` (in model units, [`Frame::model_error`]), and
/// [`Error::ConditionNotMet`] when the finished bound exceeds the tolerance.
pub(crate) fn reduce_curve_framed(
    curve: &BSplineCurve,
    opts: &BSplineOptions,
    reduce: impl Fn(&BSplineCurve, &BSplineOptions) -> Result<BSplineReduction>,
) -> Result<BSplineReduction> {
    reduce_curve_framed_capped(curve, opts, |c, o| reduce(c, o).map(|r| (r, None)))
}

/// [`reduce_curve_framed`] for a `reduce` that also returns certified bounds per span
/// ([`SpanCaps`], in the units of its input): moved back with the result (each finished as
/// the error bound is, [`Frame::finish`]), they spare the measurement the pairs of pieces
/// that cannot hold the maximum ([`spline_max_deviation_known`]).
///
/// # Errors
/// As [`reduce_curve_framed`].
pub(crate) fn reduce_curve_framed_capped(
    curve: &BSplineCurve,
    opts: &BSplineOptions,
    reduce: impl Fn(&BSplineCurve, &BSplineOptions) -> Result<(BSplineReduction, Option<SpanCaps>)>,
) -> Result<BSplineReduction> {
    let Some((frame, moved)) = frame_curve(curve, opts.tolerance)? else {
        return reduce(curve, opts).map(|(r, _)| r);
    };
    let inner = BSplineOptions {
        tolerance: frame.inner_tol,
        measure: false,
        ..*opts
    };
    let (mut red, caps) =
        reduce(&moved, &inner).map_err(|e| frame.model_error(e, opts.tolerance))?;
    let out = red.curve.points().to_vec();
    red.curve = unframe_curve(&frame, &red.curve)?;
    red.report.tolerance = opts.tolerance;
    red.report.error_bound = frame.finish(red.report.error_bound, &out);
    red.report.segment_bound = frame.finish(red.report.segment_bound, &out);
    if red.report.error_bound > opts.tolerance {
        return Err(Error::ConditionNotMet {
            eq: "tolerance",
            why: "the bound with the frame's rounding exceeds the tolerance (rounding level)",
        });
    }
    if opts.measure {
        let rounding = frame.frame.rounding(&out);
        let caps = caps.map(|c| SpanCaps {
            bounds: c
                .bounds
                .iter()
                .map(|&b| frame.finish_rounded(b, rounding))
                .collect(),
            breaks: c.breaks,
            pieces: c
                .pieces
                .map(|(breaks, points)| (breaks, frame.unframe_homogeneous(&points))),
        });
        let known = Known {
            pieces_a: caps
                .as_ref()
                .and_then(|c| c.pieces.as_ref())
                .map(|(breaks, points)| (&breaks[..], &points[..])),
            caps: caps.as_ref(),
        };
        red.report.max_error = Some(spline_max_deviation_known(curve, &red.curve, known)?);
    }
    Ok(red)
}
