//! Seed 000 Algorithm 14.2.1 as corrected in SPEC-reduce §2.2: stepwise perturbation
//! reduction `n -> n-1 -> ... -> d` with a-priori midpoint subdivision, and the
//! subdivision count of eq. 14.2.11 (corrected).

use cagd_core::{BezierCurve, Error, Result, binomial, check_degree, check_tolerance};

use super::piecewise::{PiecewiseReduction, ReducedPiece};
use super::{MAX_PIECES, MAX_TOLERANCE_WORK, ToleranceOptions, finish, levels_for, split_levels};
use crate::bezier::method::Method;
use crate::bezier::operator::operator;
use crate::bezier::wn_table::perturbation_error_factor;

/// The smallest number `N` of midpoint-subdivision levels after which every piece of a
/// degree-`n` curve with `||Delta^n P_0|| = norm_f` reduces one degree by the perturbation
/// method ([`Method::Perturb`]) within `delta` (seed 000 eq. 14.2.11, corrected in
/// SPEC-reduce §2.2: `delta` and `W_n` were missing):
/// `N = max(0, ceil((1/n) log2(W_n ||F|| / ((C(2n,n) - 2) delta))))`, because subdividing
/// at `1/2` scales `F` by `2^-n` (Theorem 14.2.2). `W_n` is
/// [`crate::perturbation_error_factor`] (rounded up).
///
/// # Errors
/// [`Error::DegreeOutOfRange`] (`n > 64`), [`Error::BadDegreePair`] (`n < 2`),
/// [`Error::BadTolerance`] (`delta`), [`Error::BadParameter`] (`norm_f` negative or not
/// finite).
///
/// ```
/// // SPEC-reduce vector N-formula-1: n = 5, ||F|| = 100, delta = 1e-3.
/// assert_eq!(cagd_reduce::subdivision_levels(5, 100.0, 1e-3)?, 2);
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn subdivision_levels(n: usize, norm_f: f64, delta: f64) -> Result<usize> {
    check_degree(n)?;
    if n < 2 {
        return Err(Error::BadDegreePair {
            from: n,
            to: n.saturating_sub(1),
            why: "the perturbation reduction needs a source degree >= 2",
        });
    }
    check_tolerance(delta)?;
    if !norm_f.is_finite() || norm_f < 0.0 {
        return Err(Error::BadParameter {
            name: "norm_f",
            value: norm_f,
            why: "must be finite and >= 0",
        });
    }
    let e = perturbation_error(n, norm_f);
    Ok(if e <= delta {
        0
    } else {
        levels_for(e / delta, n, false)
    })
}

/// `W_k ||F|| / (C(2k,k) - 2)`: the perturbation error of one step of a degree-`k` curve.
fn perturbation_error(k: usize, norm_f: f64) -> f64 {
    let d = (binomial(2 * k, k) - 2) as f64;
    perturbation_error_factor(k) * norm_f / d
}

/// Seed 000 Algorithm 14.2.1, corrected (SPEC-reduce §2.2): reduce a polynomial Bézier
/// curve of degree `n` to degree `d = opts.target` one degree at a time by control-point
/// perturbation ([`Method::Perturb`], eq. 14.2.5), subdividing before each step so that
/// every step's error stays below `tol = delta / (n - d)`:
///
/// ```text
/// for k = n, n-1, ..., d+1, for each piece S (degree k):
///     e = W_k ||Delta^k S_0|| / (C(2k,k) - 2)
///     if e >= tol: split S at midpoints K = floor(log2(e/tol)/k) + 1 times
///     replace every resulting piece by its one-step perturbation reduction
/// ```
///
/// The error of the steps adds (triangle inequality): the seed's certified total is the
/// sum of the per-step maxima ([`crate::PiecewiseReport::step_bounds`]); each piece also
/// carries the sum of the bounds along its own history
/// ([`ReducedPiece::error_bound`], `<=` the total), from which
/// [`crate::PiecewiseReport::error_bound`] is formed. The joins are C0 (exactly: the
/// perturbation keeps the end points). Reproduces the vector `subdiv-reduce-9to4-0.01`
/// (intervals exactly, points and certified total within the vector's `1e-9`).
///
/// `opts.method` must be [`Method::Perturb`] and `opts.continuity` must be `0`;
/// `opts.measure` and `opts.max_depth` (total depth over all steps) apply.
///
/// # Errors
/// [`Error::ConditionNotMet`] (eq. "Algorithm 14.2.1") for another method, `continuity > 0`
/// or a rational curve (use [`crate::reduce_to_tolerance`]); [`Error::BadTolerance`]; as
/// [`Method::check`] (`d >= n`, `d = 0`); [`Error::NoConvergence`] when a piece would need
/// more than `max_depth` levels or the pieces would exceed [`MAX_PIECES`] (with the
/// largest step error reached); [`Error::ConditionNotMet`] (eq. "tolerance") when the
/// steps would reduce more than [`MAX_TOLERANCE_WORK`] pieces, each counted `((k + 1)^2 +
/// 64) (dim + 1)` at degree `k` (ADDED, bounded work: a degree-64 curve reduced to degree
/// 1 reduces every piece 63 times, and the C ABI fuzz saw such a call run 13 s);
/// [`Error::NonFinite`] when a reduced point overflows (coordinates near the limits of
/// `f64`).
pub fn reduce_to_tolerance_alg_14_2_1(
    curve: &BezierCurve,
    opts: &ToleranceOptions,
) -> Result<PiecewiseReduction> {
    if opts.method != Method::Perturb || opts.continuity != 0 || curve.is_rational() {
        return Err(Error::ConditionNotMet {
            eq: "Algorithm 14.2.1",
            why: "the algorithm is defined for Method::Perturb, continuity 0 and polynomial \
                  curves (use reduce_to_tolerance otherwise)",
        });
    }
    check_tolerance(opts.tolerance)?;
    let (n, d, dim) = (curve.degree(), opts.target, curve.dim());
    Method::Perturb.check(n, d)?;
    let tol = opts.tolerance / (n - d) as f64;
    // (start, end, depth, piece, bound accumulated along the piece's history)
    let mut pieces = vec![(0.0, 1.0, 0usize, curve.clone(), 0.0f64)];
    let mut step_bounds = Vec::with_capacity(n - d);
    let mut work = 0usize;
    for k in ((d + 1)..=n).rev() {
        let op = operator(Method::Perturb, k, k - 1)?;
        let unit = ((k + 1) * (k + 1) + 64) * (dim + 1);
        let mut next = Vec::with_capacity(pieces.len());
        let mut step_max = 0.0f64;
        for (a, b, depth, s, acc) in pieces {
            let f = s.forward_difference();
            let e = perturbation_error(k, f.iter().map(|x| x * x).sum::<f64>().sqrt());
            let levels = if e >= tol {
                levels_for(e / tol, k, true)
            } else {
                0
            };
            if depth + levels > opts.max_depth
                || next.len() + (1usize << levels.min(40)) > MAX_PIECES
            {
                return Err(Error::NoConvergence {
                    tolerance: opts.tolerance,
                    achieved: e,
                });
            }
            work = work.saturating_add((1usize << levels.min(40)).saturating_mul(unit));
            if work > MAX_TOLERANCE_WORK {
                return Err(Error::ConditionNotMet {
                    eq: "tolerance",
                    why: "the steps need too much work (more than 2^27 pieces reduced times \
                          ((k + 1)^2 + 64) (d + 1))",
                });
            }
            for (a2, b2, sub) in split_levels(s, a, b, levels)? {
                let q = op.apply(sub.points(), dim)?;
                let bound = op.error_bound(sub.points(), &q, dim)?;
                step_max = step_max.max(bound);
                next.push((
                    a2,
                    b2,
                    depth + levels,
                    BezierCurve::new(q, dim)?,
                    acc + bound,
                ));
            }
        }
        step_bounds.push(step_max);
        pieces = next;
    }
    let depth = pieces.iter().map(|p| p.2).max().unwrap_or(0);
    let done = pieces
        .into_iter()
        .map(|(start, end, _, curve, error_bound)| ReducedPiece {
            start,
            end,
            curve,
            error_bound,
        })
        .collect();
    finish(curve, opts, done, depth, step_bounds)
}
