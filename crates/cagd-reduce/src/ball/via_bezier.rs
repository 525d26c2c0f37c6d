//! Every Bézier reducer of cagd-reduce applied to a WSGB curve: exact conversion to Bézier
//! form, the Bézier reduction, exact conversion back to WSGB(m, L').

use cagd_core::{Result, WsgbCurve, wsgb_max_l};

use super::reduce::{measure, norm_inf};
use super::{WsgbMethod, WsgbReduction, WsgbReport};
use crate::{Method, ReduceOptions, reduce_with};

/// Reduces through the Bézier form with the Bézier `method` (see [`super::reduce_wsgb`]).
///
/// Bound: the Bézier reducer's certified bound (for the rounded Bézier form) plus the
/// rounding of the two conversions (each point within half an ulp of the exact one, carried
/// to the curve by the convex hull: `eps (max |b| + max |q|) sqrt(dim)`, doubled).
pub(super) fn reduce_via_bezier(
    curve: &WsgbCurve,
    m: usize,
    method: Method,
) -> Result<WsgbReduction> {
    let bez = curve.to_bezier()?;
    let red = reduce_with(&bez, &ReduceOptions::new(method, m))?;
    let l = curve.order().min(wsgb_max_l(m));
    let reduced = WsgbCurve::from_bezier(&red.curve, l)?;
    let dim = curve.dim() as f64;
    let allowance = 2.0
        * f64::EPSILON
        * dim.sqrt()
        * (norm_inf(bez.points()) + norm_inf(red.curve.points()) + norm_inf(reduced.points()));
    let bound = red.report.error_bound.unwrap_or(f64::INFINITY) + allowance;
    let (max_error, max_error_inf) = measure(curve, &reduced)?;
    Ok(WsgbReduction {
        report: WsgbReport {
            method: WsgbMethod::Bezier(method),
            degree_from: curve.degree(),
            degree_to: m,
            order_from: curve.order(),
            order_to: l,
            error_bound: bound * (1.0 + 4.0 * f64::EPSILON),
            max_error,
            max_error_inf,
            steps: Vec::new(),
            bezier: Some(red.report),
        },
        curve: reduced,
    })
}
