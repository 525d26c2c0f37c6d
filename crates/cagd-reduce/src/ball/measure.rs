//! Measured errors between WSGB curves, on their exact difference curve.

use num_rational::BigRational;

use cagd_core::{
    BezierCurve, Error, Result, WsgbCurve, curve_distance, round_exact_points, to_exact_points,
    wsgb_elevate_exact, wsgb_to_bezier_exact,
};

/// `max_k |x_k|`.
pub(super) fn norm_inf(x: &[f64]) -> f64 {
    x.iter().fold(0.0f64, |a, v| a.max(v.abs()))
}

/// The exact difference `p - q` (q elevated to p's degree and order) as a Bézier curve,
/// rounded once.
pub(crate) fn difference_bezier(p: &WsgbCurve, q: &WsgbCurve) -> Result<BezierCurve> {
    let dim = p.dim();
    let mut qe = to_exact_points(q.points());
    let mut lq = q.order();
    for k in q.degree() + 1..=p.degree() {
        let lk = if k == p.degree() {
            p.order()
        } else {
            lq.min(cagd_core::wsgb_max_l(k))
        };
        qe = wsgb_elevate_exact(&qe, dim, lq, lk)?;
        lq = lk;
    }
    let diff: Vec<BigRational> = to_exact_points(p.points())
        .iter()
        .zip(&qe)
        .map(|(a, b)| a - b)
        .collect();
    let b = wsgb_to_bezier_exact(&diff, dim, p.order())?;
    BezierCurve::new(round_exact_points(&b), dim)
}

/// [`measure`] as options, when asked for.
pub(crate) fn measured(
    p: &WsgbCurve,
    q: &WsgbCurve,
    wanted: bool,
) -> Result<(Option<f64>, Option<f64>)> {
    if !wanted {
        return Ok((None, None));
    }
    let (a, b) = measure(p, q)?;
    Ok((Some(a), Some(b)))
}

/// Measured `max_u ||p(u) - q(u)||` (Euclidean) and `max_u max_k |p_k(u) - q_k(u)|`, on the
/// exact difference curve (so accurate relative to the error itself).
pub(crate) fn measure(p: &WsgbCurve, q: &WsgbCurve) -> Result<(f64, f64)> {
    let diff = difference_bezier(p, q)?;
    let dim = diff.dim();
    let zero = BezierCurve::new(vec![0.0; dim], dim)?;
    let e2 = curve_distance(&diff, &zero)?;
    let zero1 = BezierCurve::new(vec![0.0], 1)?;
    let mut einf = 0.0f64;
    for d in 0..dim {
        let coord: Vec<f64> = diff.points().iter().skip(d).step_by(dim).copied().collect();
        einf = einf.max(curve_distance(&BezierCurve::new(coord, 1)?, &zero1)?);
    }
    Ok((e2, einf))
}

/// `max_k max_{j} |p_k(u_j) - q_k(u_j)|` over the grid `u_j = j/(samples-1)` (max-abs
/// coordinate norm, no refinement): the "sampled" error of SPEC-reduce §0 (4001 points), as
/// used by the spec vectors' `true_max_error_inf`. Evaluated on the exact difference curve.
///
/// # Errors
/// [`Error::LengthMismatch`] for different dimensions; [`Error::BadParameter`] for
/// `samples < 2`.
pub fn wsgb_sampled_error_inf(p: &WsgbCurve, q: &WsgbCurve, samples: usize) -> Result<f64> {
    if p.dim() != q.dim() {
        return Err(Error::LengthMismatch {
            what: "WSGB curve dimensions",
            got: q.dim(),
            expected: p.dim(),
        });
    }
    if samples < 2 {
        return Err(Error::BadParameter {
            name: "samples",
            value: samples as f64,
            why: "a grid needs at least 2 samples",
        });
    }
    let (p, q) = if p.degree() >= q.degree() {
        (p, q)
    } else {
        (q, p)
    };
    let diff = difference_bezier(p, q)?;
    let mut out = vec![0.0; diff.dim()];
    let mut work = vec![0.0; diff.points().len()];
    let mut worst = 0.0f64;
    for j in 0..samples {
        let u = j as f64 / (samples - 1) as f64;
        cagd_core::kernel::de_casteljau(diff.points(), diff.dim(), u, &mut work, &mut out);
        worst = worst.max(norm_inf(&out));
    }
    Ok(worst)
}
