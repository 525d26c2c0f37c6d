//! Measured errors between WSGB curves, on their exact difference curve.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

use cagd_core::{
    BezierCurve, Error, Result, WsgbCurve, binomial, curve_distance, round_exact_points,
    to_exact_points, wsgb_to_bezier_exact,
};

/// `max_k |x_k|`.
pub(super) fn norm_inf(x: &[f64]) -> f64 {
    x.iter().fold(0.0f64, |a, v| a.max(v.abs()))
}

/// The exact difference `p - q` (q elevated to p's degree) as a Bézier curve, rounded once.
///
/// Both curves are converted exactly to Bézier form and `q` is elevated in one
/// multi-degree step, `b_i = sum_j C(m, j) C(n - m, i - j) / C(n, i) q_j` (the same exact
/// numbers as elevating the WSGB form one degree at a time, at a fraction of the cost:
/// issue 18, a degree-3 piece measured against degree 49 took 0.1 s through 46 WSGB
/// elevations).
pub(crate) fn difference_bezier(p: &WsgbCurve, q: &WsgbCurve) -> Result<BezierCurve> {
    let pb = wsgb_to_bezier_exact(&to_exact_points(p.points()), p.dim(), p.order())?;
    difference_exact(&pb, p.dim(), q)
}

/// The exact difference `p - q` of the exact Bézier points `pb` and the WSGB curve `q`
/// (elevated to their degree), rounded once.
fn difference_exact(pb: &[BigRational], dim: usize, q: &WsgbCurve) -> Result<BezierCurve> {
    let qb = wsgb_to_bezier_exact(&to_exact_points(q.points()), dim, q.order())?;
    let qe = bezier_elevate_to(&qb, dim, pb.len() / dim - 1);
    let diff: Vec<BigRational> = pb.iter().zip(&qe).map(|(a, b)| a - b).collect();
    BezierCurve::new(round_exact_points(&diff), dim)
}

/// Exact Bézier elevation of the points `b` (degree `m`) to degree `n >= m` in one step.
fn bezier_elevate_to(b: &[BigRational], dim: usize, n: usize) -> Vec<BigRational> {
    let m = b.len() / dim - 1;
    if n <= m {
        return b.to_vec();
    }
    let big = |x: u128| BigInt::from(x);
    let mut out = Vec::with_capacity((n + 1) * dim);
    for i in 0..=n {
        let den = big(binomial(n, i));
        let lo = i.saturating_sub(n - m);
        let mut acc = vec![BigRational::zero(); dim];
        for j in lo..=m.min(i) {
            let w = BigRational::new(big(binomial(m, j) * binomial(n - m, i - j)), den.clone());
            for (a, x) in acc.iter_mut().zip(&b[j * dim..(j + 1) * dim]) {
                *a += &w * x;
            }
        }
        out.extend(acc);
    }
    out
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
    distances(&difference_bezier(p, q)?)
}

/// [`measure`] of the WSGB curve `q` against a polynomial Bézier curve `p` of degree at
/// least `q`'s (a subdivided piece of a reduction to a tolerance), exactly as above.
pub(crate) fn measure_bezier(p: &BezierCurve, q: &WsgbCurve) -> Result<(f64, f64)> {
    distances(&difference_exact(&to_exact_points(p.points()), p.dim(), q)?)
}

/// Euclidean and max-abs maxima of the difference curve `diff` (its distance to 0).
fn distances(diff: &BezierCurve) -> Result<(f64, f64)> {
    let dim = diff.dim();
    let zero = BezierCurve::new(vec![0.0; dim], dim)?;
    let e2 = curve_distance(diff, &zero)?;
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
