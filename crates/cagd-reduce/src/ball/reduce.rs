//! The WSGB reduction driver: one method repeated from degree `n` to degree `m`, with the
//! certified bound, the measured errors and the seed's figures per step.

use cagd_core::kernel::powu;
use cagd_core::{Error, Result, WsgbCurve, check_degree, wsgb_lec_difference, wsgb_reduced_order};

use super::measure::{measured, norm_inf};
use super::perturbation::{
    wsgb_paper_bound_11, wsgb_perturbation_error_factor, wsgb_perturbation_step,
};
use super::uniform::uniform_step_f64;
use super::via_bezier::reduce_via_bezier;
use super::{WsgbMethod, WsgbReduction, WsgbReport, WsgbStep};

const EPS: f64 = f64::EPSILON;

fn norm2(x: &[f64]) -> f64 {
    x.iter().map(|v| v * v).sum::<f64>().sqrt()
}

/// Checks the target degree `m` of a reduction of a degree-`n` curve.
fn check_target(n: usize, m: usize, method: WsgbMethod) -> Result<()> {
    check_degree(n)?;
    if m >= n {
        return Err(Error::BadDegreePair {
            from: n,
            to: m,
            why: "the target degree must be below the source degree",
        });
    }
    if method == WsgbMethod::Perturbation && m < 1 {
        return Err(Error::BadDegreePair {
            from: n,
            to: m,
            why: "the WSGB perturbation method needs n >= 2 at every step (target m >= 1)",
        });
    }
    Ok(())
}

/// Reduces the WSGB(n, L) curve to degree `m < n` with `method`.
///
/// [`WsgbMethod::Perturbation`] and [`WsgbMethod::Uniform`] are applied one degree at a time
/// (`n -> n-1 -> ... -> m`, the order following `L' = min(L, max(floor(k/2) - 1, 0))` at
/// each degree `k`, SPEC-reduce §9.3); the certified bound is the sum of the steps' bounds.
/// [`WsgbMethod::Bezier`] converts exactly to Bézier form, runs the Bézier reducer
/// (multi-degree methods in one go) and converts back to WSGB(m, L').
///
/// The report's `error_bound` and `max_error` are on the Euclidean distance between the
/// curves; the seed's per-coordinate (max-abs) figures are in [`WsgbReport::steps`] and
/// `max_error_inf`.
///
/// ```
/// use cagd_core::WsgbCurve;
/// use cagd_reduce::{WsgbMethod, reduce_wsgb};
/// let p = vec![220., 110., 160., 220., 180., 340., 260., 400., 355., 425., 470., 320.,
///              490., 200., 420., 100.];
/// let c = WsgbCurve::new(p, 2, 1)?; // seed 003's degree-7 example
/// let r = reduce_wsgb(&c, 6, WsgbMethod::Uniform)?;
/// assert_eq!(r.curve.point(3), &[307.5, 412.5]);
/// // Seed 003 eq. (12): ||lec||_inf / 2^13 = 1140 / 8192 = 0.139...
/// assert_eq!(r.report.steps[0].uniform_error_12, 1140.0 / 8192.0);
/// assert!((r.report.max_error_inf.unwrap() - 1140.0 / 8192.0).abs() < 1e-12);
/// assert!(r.report.max_error.unwrap() <= r.report.error_bound);
/// # Ok::<(), cagd_core::Error>(())
/// ```
///
/// # Errors
/// [`Error::BadDegreePair`] for `m >= n`, or `m < 1` with the perturbation method (it needs
/// `n >= 2` at every step); the Bézier method's own errors ([`crate::Method::check`]).
pub fn reduce_wsgb(curve: &WsgbCurve, m: usize, method: WsgbMethod) -> Result<WsgbReduction> {
    reduce_wsgb_with(curve, m, method, true)
}

/// [`reduce_wsgb`], measuring the error only when `measure` is set (the measurement, on
/// the exact difference curve, costs more than the reduction itself).
///
/// # Errors
/// As [`reduce_wsgb`].
pub fn reduce_wsgb_with(
    curve: &WsgbCurve,
    m: usize,
    method: WsgbMethod,
    measure: bool,
) -> Result<WsgbReduction> {
    let n = curve.degree();
    check_target(n, m, method)?;
    if let WsgbMethod::Bezier(bm) = method {
        return reduce_via_bezier(curve, m, bm, measure);
    }
    let dim = curve.dim();
    let mut pts = curve.points().to_vec();
    let mut l = curve.order();
    let mut steps = Vec::with_capacity(n - m);
    for k in (m + 1..=n).rev() {
        let lec = cagd_core::wsgb_leading_coefficient(&pts, dim, l)?;
        let diff = wsgb_lec_difference(&pts, dim);
        let scale = norm_inf(&pts);
        let (q, exact_err2, err_inf, rounding) = match method {
            WsgbMethod::Perturbation => {
                let phi = wsgb_perturbation_error_factor(k, l);
                let q = wsgb_perturbation_step(&pts, dim, l)?;
                (q, phi * norm2(&diff), phi * norm_inf(&diff), scale)
            }
            _ => {
                let c = powu(2.0, 2 * k - 1);
                let (q, gmax) = uniform_step_f64(&pts, dim, l)?;
                (
                    q,
                    norm2(&lec) / c,
                    norm_inf(&lec) / c,
                    scale + gmax * norm_inf(&lec) / c,
                )
            }
        };
        // Rounding allowance: the f64 points before the inverse elevation differ from the
        // exact degenerate ones by a few ulp of `rounding`; the inverse elevation multiplies
        // that by at most 3 (coefficient sum), the convex hull carries it to the curve.
        let allowance = 64.0 * EPS * (dim as f64).sqrt() * (rounding + norm_inf(&q));
        steps.push(WsgbStep {
            degree_from: k,
            order_from: l,
            error_bound: exact_err2 * (1.0 + 64.0 * EPS) + allowance,
            error_inf: err_inf,
            paper_bound_11: wsgb_paper_bound_11(k, l, norm_inf(&diff)),
            uniform_error_12: norm_inf(&lec) / powu(2.0, 2 * k - 1),
            lec,
        });
        l = wsgb_reduced_order(k, l);
        pts = q;
    }
    let reduced = WsgbCurve::new(pts, dim, l)?;
    let (max_error, max_error_inf) = measured(curve, &reduced, measure)?;
    let error_bound = steps.iter().map(|s| s.error_bound).sum::<f64>() * (1.0 + 8.0 * EPS);
    Ok(WsgbReduction {
        report: WsgbReport {
            method,
            degree_from: n,
            degree_to: m,
            order_from: curve.order(),
            order_to: l,
            error_bound,
            max_error,
            max_error_inf,
            steps,
            bezier: None,
        },
        curve: reduced,
    })
}
