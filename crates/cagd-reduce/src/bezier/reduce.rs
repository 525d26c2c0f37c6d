//! The curve-level entry points: [`reduce`], [`reduce_with`], and the [`Report`].

use cagd_core::{BezierCurve, Error, Result};

use super::bound::BoundLevel;
use super::measure::max_deviation;
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
    /// For rational curves: the certified bound in homogeneous space, from which the
    /// Euclidean one is derived (`None` for polynomial curves).
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
/// Rational curves: the homogeneous points `(w_i P_i, w_i)` are reduced; with `eps_h` the
/// certified homogeneous bound, the Euclidean error is at most
/// `eps_h (1 + max_i ||P_i||) / v_min` with `v_min = max(min_i v_i, min_i w_i - eps_h)`
/// (`v` the reduced weights): from `P/w - Q/v = ((P - Q) - (P/w)(w - v)) / v`, Cauchy–Schwarz,
/// and the convex-hull properties `||P(t)/w(t)|| <= max ||P_i||`, `v(t) >= min v_i`,
/// `v(t) >= w(t) - eps_h`.
///
/// # Errors
/// As [`reduce`].
pub fn reduce_with(curve: &BezierCurve, opts: &ReduceOptions) -> Result<Reduction> {
    let op = operator(opts.method, curve.degree(), opts.target)?;
    finish(curve, opts, |pts, dim| {
        let q = op.apply(pts, dim)?;
        let bound = op.direct_bound(pts, &q, dim, opts.bound);
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
    let hom = curve.homogeneous_points();
    let (qh, eps_h, method) = f(&hom, hd)?;
    let v: Vec<f64> = qh.chunks_exact(hd).map(|p| p[dim]).collect();
    if let Some(index) = v.iter().position(|x| !x.is_finite() || *x <= 0.0) {
        return Err(Error::NonPositiveWeight {
            index,
            weight: v[index],
        });
    }
    let reduced = BezierCurve::from_homogeneous(&qh, hd)?;
    let pmax = curve
        .points()
        .chunks_exact(dim)
        .map(|p| p.iter().map(|x| x * x).sum::<f64>().sqrt())
        .fold(0.0, f64::max);
    let wmin = w.iter().copied().fold(f64::INFINITY, f64::min);
    let vmin_q = v.iter().copied().fold(f64::INFINITY, f64::min);
    let eucl = eps_h.map(|e| {
        let vmin = vmin_q.max(wmin - e);
        e * (1.0 + pmax) / vmin * (1.0 + 8.0 * f64::EPSILON)
    });
    let (bound, max_error) = match opts.space {
        ErrorSpace::Euclidean => {
            let me = if opts.measure {
                Some(max_deviation(curve, &reduced)?)
            } else {
                None
            };
            (eucl, me)
        }
        ErrorSpace::Homogeneous => {
            let me = if opts.measure {
                Some(max_deviation(
                    &curve.to_homogeneous(),
                    &BezierCurve::new(qh, hd)?,
                )?)
            } else {
                None
            };
            (eps_h, me)
        }
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
            homogeneous_bound: eps_h,
        },
        curve: reduced,
    })
}
