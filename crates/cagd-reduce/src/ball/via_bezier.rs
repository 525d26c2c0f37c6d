//! Every Bézier reducer of cagd-reduce applied to a WSGB curve: exact conversion to Bézier
//! form, the Bézier reduction, exact conversion back to WSGB(m, L').

use cagd_core::{BezierCurve, Error, Result, WsgbCurve, wsgb_max_l};

use super::measure::{measured, norm_inf};
use super::{WsgbMethod, WsgbReduction, WsgbReport};
use crate::{Method, ReduceOptions, Reduction, reduce_with};

/// Reduces through the Bézier form with the Bézier `method` (see [`super::reduce_wsgb`]).
///
/// Bound: the Bézier reducer's certified bound (for the rounded Bézier form) plus the
/// rounding of the two conversions (each point within half an ulp of the exact one, carried
/// to the curve by the convex hull: `eps (max |b| + max |q|) sqrt(dim)`, doubled).
pub(super) fn reduce_via_bezier(
    curve: &WsgbCurve,
    m: usize,
    method: Method,
    measure: bool,
) -> Result<WsgbReduction> {
    let mut red =
        reduce_wsgb_via_bezier(curve, |b| reduce_with(b, &ReduceOptions::new(method, m)))?;
    if !measure {
        red.report.max_error = None;
        red.report.max_error_inf = None;
    }
    Ok(red)
}

/// Reduces a WSGB curve with any Bézier reduction `reduce` (e.g. a non-linear one such as
/// [`crate::reduce_g1_optimal`] repeated): exact conversion to Bézier form, `reduce`, exact
/// conversion of its curve back to WSGB(m, L'), `L' = min(L, max(floor(m/2) - 1, 0))`, `m`
/// the degree it returns. The bound is `reduce`'s certified bound plus the conversions'
/// rounding (see the module docs); the errors are measured on the WSGB curves.
///
/// # Errors
/// `reduce`'s errors; [`cagd_core::Error::ConditionNotMet`] if it returns a rational curve;
/// [`cagd_core::Error::BadDegreePair`] if it does not lower the degree.
pub fn reduce_wsgb_via_bezier(
    curve: &WsgbCurve,
    reduce: impl FnOnce(&BezierCurve) -> Result<Reduction>,
) -> Result<WsgbReduction> {
    via_bezier(curve, reduce, true)
}

/// [`reduce_wsgb_via_bezier`], measuring only when asked.
fn via_bezier(
    curve: &WsgbCurve,
    reduce: impl FnOnce(&BezierCurve) -> Result<Reduction>,
    measure: bool,
) -> Result<WsgbReduction> {
    let bez = curve.to_bezier()?;
    let red = reduce(&bez)?;
    let m = red.curve.degree();
    if m >= curve.degree() {
        return Err(Error::BadDegreePair {
            from: curve.degree(),
            to: m,
            why: "the Bézier reduction did not lower the degree",
        });
    }
    let method = red.report.method;
    let l = curve.order().min(wsgb_max_l(m));
    let reduced = WsgbCurve::from_bezier(&red.curve, l)?;
    let dim = curve.dim() as f64;
    let allowance = 2.0
        * f64::EPSILON
        * dim.sqrt()
        * (norm_inf(bez.points()) + norm_inf(red.curve.points()) + norm_inf(reduced.points()));
    let bound = red.report.error_bound.unwrap_or(f64::INFINITY) + allowance;
    let (max_error, max_error_inf) = measured(curve, &reduced, measure)?;
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
