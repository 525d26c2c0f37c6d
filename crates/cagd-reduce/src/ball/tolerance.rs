//! Reduction of a WSGB curve to a tolerance with midpoint subdivision (seed 003 §3: "if the
//! perturbation method does not reach the required error, subdivide the curve and reduce
//! piece by piece"; the same scheme as [`crate::reduce_to_tolerance`] for Bézier curves).

use cagd_core::{BezierCurve, Error, Result, WsgbCurve, check_tolerance};

use super::measure::{measure_bezier, measured, norm_inf};
use super::via_bezier::reduce_bezier_form;
use super::{WsgbMethod, WsgbReduction, reduce_wsgb_with};
use crate::DEFAULT_MAX_DEPTH;

/// The most pieces [`reduce_wsgb_to_tolerance`] measures (those of largest bound first):
/// a measurement elevates the reduced piece back to degree `n` in exact arithmetic, 75 ms
/// at degree 64 (ADDED; bounded work, issue 18: measuring every piece tried made a
/// degree-64 curve take 7.8 s in the C ABI fuzz run).
pub const WSGB_MEASURED_PIECES: usize = 16;

/// Work budget of the measurements of [`reduce_wsgb_to_tolerance`], counted `(n + 1)^3`
/// per piece: `2^20` (three pieces at degree 64, 16 up to degree 39; the piece of largest
/// bound is always measured).
const WSGB_MEASURE_WORK: usize = 1 << 20;

/// The most pieces [`reduce_wsgb_to_tolerance`] makes before it refuses (2^10; beyond the
/// seed: a bound on its work, issue 18 — the fuzzer's WSGB curve of degree 8 reduced to
/// degree 0 within 1e-6 ran for minutes under the former limit of 2^20).
pub const MAX_WSGB_PIECES: usize = 1 << 10;

/// One reduced piece of a WSGB curve.
#[derive(Debug, Clone, PartialEq)]
pub struct WsgbPiece {
    /// Start of the parameter interval of the original curve.
    pub start: f64,
    /// End of the parameter interval (`> start`).
    pub end: f64,
    /// The reduced piece, WSGB(m, L') on `[0, 1]`: it approximates the original at
    /// `start + s (end - start)`.
    pub reduction: WsgbReduction,
    /// Certified bound of `max_s ||original(start + s (end - start)) - piece(s)||`
    /// (Euclidean): the piece's reduction bound plus the subdivision rounding.
    pub error_bound: f64,
}

/// The pieces of a reduction to a tolerance.
#[derive(Debug, Clone, PartialEq)]
pub struct WsgbPiecewise {
    /// The pieces in parameter order.
    pub pieces: Vec<WsgbPiece>,
    /// Largest certified bound of the pieces (`<= tolerance`).
    pub error_bound: f64,
    /// Largest measured error of the measured pieces (against the subdivided original
    /// pieces): the [`WSGB_MEASURED_PIECES`] of largest bound, fewer at high degree (a
    /// piece's report has `max_error: None` when it was not measured).
    pub max_error: f64,
    /// Deepest midpoint-subdivision level used.
    pub depth: usize,
}

/// Reduces `curve` to degree `m` with `method` so that the certified Euclidean error of
/// every piece is at most `tolerance`, splitting at parameter midpoints (through the exact
/// Bézier form: de Casteljau subdivision, exact conversion back) as often as needed, at most
/// [`DEFAULT_MAX_DEPTH`] levels and [`MAX_WSGB_PIECES`] pieces.
///
/// The pieces join continuously (`C^0`) only when the method interpolates the end points
/// (perturbation for `m >= 2`, Bézier methods with `end_orders >= 0`); the uniform method
/// does not.
///
/// # Errors
/// [`Error::BadTolerance`]; the errors of [`reduce_wsgb`](super::reduce_wsgb); [`Error::NoConvergence`] when
/// the depth or piece limit is reached.
pub fn reduce_wsgb_to_tolerance(
    curve: &WsgbCurve,
    m: usize,
    method: WsgbMethod,
    tolerance: f64,
) -> Result<WsgbPiecewise> {
    check_tolerance(tolerance)?;
    let n = curve.degree();
    let l = curve.order();
    let whole_size = norm_inf(curve.points());
    // The whole curve is reduced in its WSGB form (the errors of `reduce_wsgb`); the pieces
    // of a subdivision are kept in Bézier form (de Casteljau in f64, no exact conversion of
    // the source per piece tried) and converted exactly to WSGB(n, L) only for the WSGB
    // methods (issue 18: a degree-49 curve in 141 pieces took 21.7 s through two exact
    // conversions and a measurement per piece tried).
    let whole = reduce_wsgb_with(curve, m, method, false)?;
    if whole.report.error_bound <= tolerance {
        let (e2, einf) = measured(curve, &whole.curve, true)?;
        let mut reduction = whole;
        reduction.report.max_error = e2;
        reduction.report.max_error_inf = einf;
        let error_bound = reduction.report.error_bound;
        return Ok(WsgbPiecewise {
            max_error: e2.unwrap_or(0.0),
            pieces: vec![WsgbPiece {
                start: 0.0,
                end: 1.0,
                reduction,
                error_bound,
            }],
            error_bound,
            depth: 0,
        });
    }
    let (left, right) = curve.to_bezier()?.subdivide(0.5)?;
    let mut stack = vec![(0.5f64, 1.0f64, 1usize, right), (0.0, 0.5, 1, left)];
    let mut done: Vec<WsgbPiece> = Vec::new();
    let mut sources: Vec<BezierCurve> = Vec::new();
    let mut depth_used = 0;
    while let Some((a, b, depth, piece)) = stack.pop() {
        let red = match method {
            WsgbMethod::Bezier(bm) => reduce_bezier_form(&piece, l, m, bm)?,
            _ => reduce_wsgb_with(&WsgbCurve::from_bezier(&piece, l)?, m, method, false)?,
        };
        // Rounding of the subdivision (de Casteljau, a few n ulp per level) and of the exact
        // conversions, relative to the points' size, carried by the convex hull.
        let size = norm_inf(piece.points()).max(whole_size);
        let sub = (depth as f64 + 1.0)
            * 4.0
            * (n as f64 + 2.0)
            * f64::EPSILON
            * (curve.dim() as f64).sqrt()
            * size;
        let e = red.report.error_bound + sub;
        if e <= tolerance {
            depth_used = depth_used.max(depth);
            done.push(WsgbPiece {
                start: a,
                end: b,
                reduction: red,
                error_bound: e,
            });
            sources.push(piece);
            continue;
        }
        if depth >= DEFAULT_MAX_DEPTH || done.len() + stack.len() + 2 > MAX_WSGB_PIECES {
            return Err(Error::NoConvergence {
                tolerance,
                achieved: e,
            });
        }
        let (left, right) = piece.subdivide(0.5)?;
        let mid = 0.5 * (a + b);
        stack.push((mid, b, depth + 1, right));
        stack.push((a, mid, depth + 1, left));
    }
    let error_bound = done.iter().map(|p| p.error_bound).fold(0.0, f64::max);
    // Measure the pieces of largest bound, within the budget.
    let mut order: Vec<usize> = (0..done.len()).collect();
    order.sort_by(|&i, &j| done[j].error_bound.total_cmp(&done[i].error_bound));
    let cost = (n + 1).saturating_pow(3);
    let mut spent = 0usize;
    for &i in order.iter().take(WSGB_MEASURED_PIECES) {
        if spent > 0 && spent.saturating_add(cost) > WSGB_MEASURE_WORK {
            break;
        }
        spent = spent.saturating_add(cost);
        let (e2, einf) = measure_bezier(&sources[i], &done[i].reduction.curve)?;
        let report = &mut done[i].reduction.report;
        report.max_error = Some(e2);
        report.max_error_inf = Some(einf);
    }
    let max_error = done
        .iter()
        .filter_map(|p| p.reduction.report.max_error)
        .fold(0.0, f64::max);
    Ok(WsgbPiecewise {
        pieces: done,
        error_bound,
        max_error,
        depth: depth_used,
    })
}
