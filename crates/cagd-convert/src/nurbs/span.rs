//! What the closed forms of SPEC-convert §15.1–15.3 share: the NURBS span type, the check
//! of the local knots, and the homogeneous points `q_i = (w_i r_i, w_i)` (§0) they map.

use cagd_core::{BezierCurve, Error, Result, check_points, check_weights};

/// The control data of one NURBS span of degree `p`: `p + 1` Euclidean points (flat,
/// row-major, `dim` coordinates each) and their `p + 1` positive weights, as produced by
/// the inverse closed forms (SPEC-convert §15.1, eq. 15.1.9–15.1.10; §15.3, eq.
/// 15.3.17–15.3.21).
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsSpan {
    /// The points `r_{n-p}, ..., r_n`, flat row-major.
    pub points: Vec<f64>,
    /// The weights `w_{n-p}, ..., w_n`, all `> 0`.
    pub weights: Vec<f64>,
    /// The number of coordinates of each point.
    pub dim: usize,
    /// The extrapolation factor of the inverse: the largest absolute coefficient of the
    /// affine combinations `r_i = sum_j lambda_ij R_j` that give the NURBS points from the
    /// Bézier points (SPEC-convert §15.1: `1 + max(k1, k2)` for the quadratic; `1` means no
    /// extrapolation). An error in the Bézier points grows by up to this factor.
    pub extrapolation: f64,
}

/// Checks local knots (`count` of them, finite, non-decreasing) and returns their gaps
/// `knots[i+1] - knots[i]`; the gap at `span` (the span itself) must be `> 0`.
///
/// # Errors
/// [`Error::KnotCount`], [`Error::NonFiniteKnot`], [`Error::KnotsNotNondecreasing`],
/// [`Error::BadParameter`] (name `"span"`) for a zero-length span.
pub(crate) fn local_gaps(knots: &[f64], count: usize, span: usize) -> Result<Vec<f64>> {
    if knots.len() != count {
        return Err(Error::KnotCount {
            got: knots.len(),
            expected: count,
        });
    }
    if let Some(index) = knots.iter().position(|k| !k.is_finite()) {
        return Err(Error::NonFiniteKnot {
            index,
            value: knots[index],
        });
    }
    if let Some(i) = knots.windows(2).position(|w| w[1] < w[0]) {
        return Err(Error::KnotsNotNondecreasing { index: i + 1 });
    }
    let gaps: Vec<f64> = knots.windows(2).map(|w| w[1] - w[0]).collect();
    if !(gaps[span] > 0.0 && gaps.iter().all(|g| g.is_finite())) {
        return Err(Error::BadParameter {
            name: "span",
            value: gaps[span],
            why: "the knot span [t_n, t_{n+1}] must have finite positive length",
        });
    }
    Ok(gaps)
}

/// The homogeneous points `(w_i r_i, w_i)` of `n` points with weights, checked (finite
/// points, weights finite and `> 0`, lengths).
///
/// # Errors
/// The errors of [`check_points`] and [`check_weights`], and [`Error::LengthMismatch`]
/// when there are not `n` points.
pub(crate) fn homogeneous(
    points: &[f64],
    weights: &[f64],
    dim: usize,
    n: usize,
) -> Result<Vec<f64>> {
    let got = check_points(points, dim)?;
    if got != n {
        return Err(Error::LengthMismatch {
            what: "points of the span (degree + 1)",
            got,
            expected: n,
        });
    }
    check_weights(weights, n)?;
    let mut hom = vec![0.0; n * (dim + 1)];
    cagd_core::kernel::to_homogeneous(points, weights, dim, &mut hom);
    Ok(hom)
}

/// The homogeneous points of a Bézier segment of degree `degree` (weights 1 when it is
/// polynomial).
///
/// # Errors
/// [`Error::BadDegreePair`] when the segment's degree is not `degree`.
pub(crate) fn bezier_homogeneous(bez: &BezierCurve, degree: usize) -> Result<Vec<f64>> {
    if bez.degree() != degree {
        return Err(Error::BadDegreePair {
            from: bez.degree(),
            to: degree,
            why: "the closed form needs a segment of its own degree",
        });
    }
    Ok(bez.homogeneous_points())
}

/// `out = (x a + y b) / z` on homogeneous points of `pdim` coordinates.
pub(crate) fn combine(out: &mut [f64], a: &[f64], x: f64, b: &[f64], y: f64, z: f64) {
    for ((o, p), q) in out.iter_mut().zip(a).zip(b) {
        *o = (x * p + y * q) / z;
    }
}

/// Splits homogeneous points into a [`NurbsSpan`] after checking that every weight is `> 0`
/// (the inverse conditions: SPEC-convert §15.1, eq. 15.1.8, and §15.3, eq. 15.3.13–16, hold
/// exactly when all inverse weights are positive) and not subnormal (below
/// `f64::MIN_POSITIVE`: no curve takes such a weight, so it fails as zero does).
///
/// # Errors
/// [`Error::ConversionCondition`] naming `condition` and the first non-positive weight.
pub(crate) fn span_from_homogeneous(
    hom: &[f64],
    dim: usize,
    condition: &'static str,
    what: &'static str,
    extrapolation: f64,
) -> Result<NurbsSpan> {
    let n = hom.len() / (dim + 1);
    let mut points = vec![0.0; n * dim];
    let mut weights = vec![0.0; n];
    for i in 0..n {
        weights[i] = hom[i * (dim + 1) + dim];
    }
    if let Some(index) = weights
        .iter()
        .position(|w| !(w.is_finite() && *w >= f64::MIN_POSITIVE))
    {
        return Err(Error::ConversionCondition {
            condition,
            what,
            index,
            value: weights[index],
        });
    }
    cagd_core::kernel::from_homogeneous(hom, dim, &mut points, &mut weights);
    check_points(&points, dim)?;
    Ok(NurbsSpan {
        points,
        weights,
        dim,
        extrapolation,
    })
}

/// The extrapolation factor of a homogeneous linear map `q_i = sum_j M_ij Q_j` (given by
/// `apply`, which maps `n` scalars to `n` scalars) from Bézier weights `bw` to NURBS weights
/// `w`: the largest `|M_ij W_j / w_i|`, the coefficient of `R_j` in the Euclidean `r_i`.
pub(crate) fn extrapolation_factor(
    bw: &[f64],
    w: &[f64],
    apply: impl Fn(&[f64], &mut [f64]),
) -> f64 {
    let n = bw.len();
    let mut unit = vec![0.0; n];
    let mut col = vec![0.0; n];
    let mut worst: f64 = 0.0;
    for j in 0..n {
        unit.fill(0.0);
        unit[j] = 1.0;
        apply(&unit, &mut col);
        for i in 0..n {
            worst = worst.max((col[i] * bw[j] / w[i]).abs());
        }
    }
    worst
}

/// The inverse direction shared by §15.1 and §15.3 (and their surfaces' rows): apply the
/// homogeneous inverse map `inverse` (which maps `n` homogeneous points of dimension `pdim`)
/// to the Bézier segment's points, then divide. The condition named in the error is chosen
/// by `condition` from the Bézier weights; `what` describes the failing inverse weight.
pub(crate) fn inverse_span(
    bezier: &BezierCurve,
    degree: usize,
    inverse: impl Fn(&[f64], usize, &mut [f64]),
    condition: impl FnOnce(&[f64]) -> &'static str,
    what: &'static str,
) -> Result<NurbsSpan> {
    let bq = bezier_homogeneous(bezier, degree)?;
    let dim = bezier.dim();
    let n = degree + 1;
    let mut out = vec![0.0; bq.len()];
    inverse(&bq, dim + 1, &mut out);
    let w: Vec<f64> = (0..n).map(|i| out[i * (dim + 1) + dim]).collect();
    let bw: Vec<f64> = (0..n).map(|i| bq[i * (dim + 1) + dim]).collect();
    let extrapolation = if w.iter().all(|x| *x > 0.0) {
        extrapolation_factor(&bw, &w, |u, o| inverse(u, 1, o))
    } else {
        f64::INFINITY
    };
    span_from_homogeneous(&out, dim, condition(&bw), what, extrapolation)
}
