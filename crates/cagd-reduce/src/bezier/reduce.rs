//! The curve-level entry points: [`reduce`], [`reduce_with`], and the [`Report`].

use cagd_core::{BezierCurve, Error, ModelFrame, Result};

use super::bound::BoundLevel;
use super::measure::{max_deviation, rational_eval_rounding};
use super::method::Method;
use super::operator::operator;

/// The space an error number refers to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ErrorSpace {
    /// `max_t ||P(t) - Q(t)||` of the Euclidean curves (for rational curves: of the
    /// projected curves `P/w`, `Q/v`).
    #[default]
    Euclidean,
    /// The same maximum for the homogeneous polynomial curves `(wP, w)`, `(vQ, v)` in
    /// `dim + 1` coordinates (rational curves only; equal to Euclidean for polynomial ones).
    Homogeneous,
}

/// What a reduction did and how far the result is from the input.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// The method used (for [`crate::reduce_g1_optimal`]: `PerturbG1` with the optimal
    /// `l1, l2` found).
    pub method: Method,
    /// Source degree `n`.
    pub degree_from: usize,
    /// Target degree `m`.
    pub degree_to: usize,
    /// Certified upper bound of the error in [`Report::space`] (never below the true
    /// error, `f64` rounding included). `None` when [`Report::bound_level`] is
    /// [`BoundLevel::None`] (no bound asked for).
    pub error_bound: Option<f64>,
    /// The bound level `error_bound` was computed at ([`ReduceOptions::bound`]; the
    /// functions that always certify, such as [`crate::reduce_g1_optimal`], report
    /// [`BoundLevel::Tight`]).
    pub bound_level: BoundLevel,
    /// The sampled error in [`Report::space`] (on request, see [`crate::max_deviation`]).
    pub max_error: Option<f64>,
    /// Which space `error_bound` and `max_error` refer to.
    pub space: ErrorSpace,
    /// For rational curves: a certified bound of the homogeneous curves `(wP, w)`,
    /// `(vQ, v)` in the input's coordinates (`None` for polynomial curves). In
    /// [`ErrorSpace::Euclidean`] the reduction runs in the curve's frame (see
    /// [`crate::reduce_with`]) and this is that frame's bound carried back,
    /// `eps_h (s + ||c|| + 1)` plus rounding.
    pub homogeneous_bound: Option<f64>,
}

/// The reduced curve and its report.
#[derive(Debug, Clone, PartialEq)]
pub struct Reduction {
    /// The reduced curve (rational if the input was).
    pub curve: BezierCurve,
    /// What was done, with the certified bound.
    pub report: Report,
}

/// Options of [`reduce_with`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReduceOptions {
    /// The method.
    pub method: Method,
    /// The target degree `m < n`.
    pub target: usize,
    /// Also measure the error ([`crate::max_deviation`]: dense sampling plus local
    /// maximisation).
    pub measure: bool,
    /// The space the reported numbers refer to (matters for rational curves only).
    pub space: ErrorSpace,
    /// How much work the certified bound may take (default [`BoundLevel::Tight`];
    /// [`BoundLevel::None`]: no bound, the report's `error_bound` is `None`). Used by
    /// [`reduce_with`]; the other reducers always certify.
    pub bound: BoundLevel,
}

impl ReduceOptions {
    /// Options for `method` and `target`, without measuring, in Euclidean space.
    pub fn new(method: Method, target: usize) -> Self {
        Self {
            method,
            target,
            measure: false,
            space: ErrorSpace::Euclidean,
            bound: BoundLevel::Tight,
        }
    }
}

/// Reduces `curve` to degree `m` with `method` and a certified error bound (no sampling).
///
/// Rational curves are reduced in homogeneous coordinates (`dim + 1`) and the bound is
/// converted to Euclidean space (see [`reduce_with`]).
///
/// # Errors
/// As [`Method::check`] (e.g. [`Error::BadDegreePair`] for `m >= n`,
/// [`Error::TooManyConstraints`]), and [`Error::NonPositiveWeight`] when a reduced weight
/// of a rational curve is not positive.
pub fn reduce(curve: &BezierCurve, m: usize, method: Method) -> Result<Reduction> {
    reduce_with(curve, &ReduceOptions::new(method, m))
}

/// Reduces `curve` as `opts` says.
///
/// Rational curves ([`ErrorSpace::Euclidean`]): the curve is moved into its frame
/// ([`cagd_core::ModelFrame`]: `P' = (P - c) / s`, `c` the centre of the points' bounding
/// box, `s = R` their radius about it), its homogeneous points
/// `(w_i P'_i, w_i)` are reduced with the certified homogeneous bound `eps_h`, and the
/// result is moved back. The Euclidean error is at most
/// `s eps_h (1 + R / s) / v_min` with `v_min = max(min_i v_i, min_i w_i - eps_h)` (`v` the
/// reduced weights), plus the round trip's rounding: the centred form
/// `(h_A + R h_W) / v_min` of [`cagd_core::centred_rational_bound`] (from
/// `P/w - Q/v = ((P - c)(v - w) + (A_c - A'_c)) / v`, the convex-hull properties
/// `||P(t)/w(t) - c|| <= R`, `v(t) >= min v_i`, `v(t) >= w(t) - eps_h`). It does not
/// depend on where the curve sits and scales with it (the uncentred
/// `eps_h (1 + max ||P_i||) / v_min` grows with the distance from the origin and mixes a
/// length with a pure number). [`ErrorSpace::Homogeneous`]: the points `(w_i P_i, w_i)`
/// are reduced as they are.
///
/// # Errors
/// As [`reduce`].
pub fn reduce_with(curve: &BezierCurve, opts: &ReduceOptions) -> Result<Reduction> {
    let op = operator(opts.method, curve.degree(), opts.target)?;
    finish(curve, opts, |pts, dim| {
        let q = op.apply(pts, dim)?;
        let bound =
            op.certified_bound(pts, dim, opts.bound)?
                .map(|b| match op.bound_map(opts.bound) {
                    Some(bm) => op.with_reduced(bm, pts, &q, dim, b),
                    None => b,
                });
        Ok((q, bound, opts.method))
    })
}

/// Runs a reduction `f(points, dim) -> (reduced points, certified bound or None, method
/// used)` on the curve's (homogeneous, if rational) points and assembles the [`Reduction`]
/// (with `opts.bound` as the reported bound level).
pub(crate) fn finish<F>(curve: &BezierCurve, opts: &ReduceOptions, f: F) -> Result<Reduction>
where
    F: FnOnce(&[f64], usize) -> Result<(Vec<f64>, Option<f64>, Method)>,
{
    let dim = curve.dim();
    let Some(w) = curve.weights() else {
        let (q, bound, method) = f(curve.points(), dim)?;
        let reduced = BezierCurve::new(q, dim)?;
        let max_error = if opts.measure {
            Some(max_deviation(curve, &reduced)?)
        } else {
            None
        };
        return Ok(Reduction {
            report: Report {
                method,
                degree_from: curve.degree(),
                degree_to: reduced.degree(),
                error_bound: bound,
                bound_level: opts.bound,
                max_error,
                space: ErrorSpace::Euclidean,
                homogeneous_bound: None,
            },
            curve: reduced,
        });
    };
    let hd = dim + 1;
    if opts.space == ErrorSpace::Homogeneous {
        return finish_homogeneous(curve, opts, f);
    }
    // Euclidean: reduce the curve in its frame (centred, scaled to radius 1), where
    // `eps_h (1 + R / s) / v` is the centred, unit-consistent bound; then move back.
    let frame = ModelFrame::new(curve.points(), dim);
    let framed = BezierCurve::new_rational(frame.to_frame(curve.points()), w.to_vec(), dim)?;
    let (qh, eps_h, method) = f(&framed.homogeneous_points(), hd)?;
    let v = reduced_weights(&qh, hd)?;
    let inner = BezierCurve::from_homogeneous(&qh, hd)?;
    let wmin = w.iter().copied().fold(f64::INFINITY, f64::min);
    let vmin = v.iter().copied().fold(f64::INFINITY, f64::min);
    let bound = eps_h.map(|e| frame.model_bound(e, wmin, vmin) + frame.rounding(inner.points()));
    let reduced = BezierCurve::new_rational(frame.from_frame(inner.points()), v, dim)?;
    // Never below what a measurement of the two rational curves can show.
    let bound = bound.map(|b| b + rational_eval_rounding(curve, &reduced));
    // In the input's own homogeneous coordinates `dA = s dA' + c dW`, `dW = dW'`; plus the
    // out-map's rounding times the largest reduced weight.
    let cnorm = frame.centre().iter().map(|x| x * x).sum::<f64>().sqrt();
    let vmax = reduced
        .weights()
        .map_or(1.0, |x| x.iter().copied().fold(0.0, f64::max));
    let homogeneous = eps_h.map(|e| {
        e * (frame.scale() + cnorm + 1.0) * (1.0 + 4.0 * f64::EPSILON)
            + vmax * frame.rounding(inner.points())
    });
    let max_error = if opts.measure {
        Some(max_deviation(curve, &reduced)?)
    } else {
        None
    };
    Ok(Reduction {
        report: Report {
            method,
            degree_from: curve.degree(),
            degree_to: reduced.degree(),
            error_bound: bound,
            bound_level: opts.bound,
            max_error,
            space: opts.space,
            homogeneous_bound: homogeneous,
        },
        curve: reduced,
    })
}

/// The reduced weights of homogeneous points `qh` (`hd` coordinates each).
///
/// # Errors
/// [`Error::NonPositiveWeight`] for a weight that is not positive and finite.
fn reduced_weights(qh: &[f64], hd: usize) -> Result<Vec<f64>> {
    let v: Vec<f64> = qh.chunks_exact(hd).map(|p| p[hd - 1]).collect();
    if let Some(index) = v.iter().position(|x| !x.is_finite() || *x <= 0.0) {
        return Err(Error::NonPositiveWeight {
            index,
            weight: v[index],
        });
    }
    Ok(v)
}

/// [`finish`] for a rational curve in [`ErrorSpace::Homogeneous`]: the homogeneous points
/// `(w P, w)` reduced as they are, the bound and measure of the homogeneous curves.
fn finish_homogeneous<F>(curve: &BezierCurve, opts: &ReduceOptions, f: F) -> Result<Reduction>
where
    F: FnOnce(&[f64], usize) -> Result<(Vec<f64>, Option<f64>, Method)>,
{
    let hd = curve.dim() + 1;
    let hom = curve.homogeneous_points();
    let (qh, eps_h, method) = f(&hom, hd)?;
    reduced_weights(&qh, hd)?;
    let reduced = BezierCurve::from_homogeneous(&qh, hd)?;
    let max_error = if opts.measure {
        Some(max_deviation(
            &curve.to_homogeneous(),
            &BezierCurve::new(qh, hd)?,
        )?)
    } else {
        None
    };
    let bound = eps_h;
    Ok(Reduction {
        report: Report {
            method,
            degree_from: curve.degree(),
            degree_to: reduced.degree(),
            error_bound: bound,
            bound_level: opts.bound,
            max_error,
            space: opts.space,
            homogeneous_bound: eps_h,
        },
        curve: reduced,
    })
}
