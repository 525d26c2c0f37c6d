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
    // Measured only when asked: the measurement (exact difference curve) costs more than
    // the reduction; a reduction to a tolerance measures only the pieces it keeps.
    via_bezier(
        curve,
        |b| reduce_with(b, &ReduceOptions::new(method, m)),
        measure,
    )
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
    let mut red = from_bezier_form(&bez, curve.order(), reduce)?;
    let (max_error, max_error_inf) = measured(curve, &red.curve, measure)?;
    red.report.max_error = max_error;
    red.report.max_error_inf = max_error_inf;
    Ok(red)
}

/// The Bézier `method` applied to `bez`, the Bézier form of a WSGB(n, `l`) curve, the
/// result converted exactly to WSGB(m, L') (not measured). Used by the reduction to a
/// tolerance on its subdivided pieces, which it keeps in Bézier form (no exact conversion
/// of the source per piece tried).
///
/// # Errors
/// As [`reduce_via_bezier`].
pub(super) fn reduce_bezier_form(
    bez: &BezierCurve,
    l: usize,
    m: usize,
    method: Method,
) -> Result<WsgbReduction> {
    from_bezier_form(bez, l, |b| reduce_with(b, &ReduceOptions::new(method, m)))
}

/// `reduce` on the Bézier form `bez` of a WSGB(n, `l`) curve, its result converted back to
/// WSGB(m, L'), with the bound (see the module docs); the measured errors are left `None`.
fn from_bezier_form(
    bez: &BezierCurve,
    l_from: usize,
    reduce: impl FnOnce(&BezierCurve) -> Result<Reduction>,
) -> Result<WsgbReduction> {
    let red = reduce(bez)?;
    let m = red.curve.degree();
    if m >= bez.degree() {
        return Err(Error::BadDegreePair {
            from: bez.degree(),
            to: m,
            why: "the Bézier reduction did not lower the degree",
        });
    }
    let method = red.report.method;
    let l = l_from.min(wsgb_max_l(m));
    let reduced = WsgbCurve::from_bezier(&red.curve, l)?;
    let dim = bez.dim() as f64;
    let allowance = 2.0
        * f64::EPSILON
        * dim.sqrt()
        * (norm_inf(bez.points()) + norm_inf(red.curve.points()) + norm_inf(reduced.points()));
    let bound = red.report.error_bound.unwrap_or(f64::INFINITY) + allowance;
    Ok(WsgbReduction {
        report: WsgbReport {
            method: WsgbMethod::Bezier(method),
            degree_from: bez.degree(),
            degree_to: m,
            order_from: l_from,
            order_to: l,
            error_bound: bound * (1.0 + 4.0 * f64::EPSILON),
            max_error: None,
            max_error_inf: None,
            steps: Vec::new(),
            bezier: Some(red.report),
        },
        curve: reduced,
    })
}
