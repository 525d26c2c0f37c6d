//! Fast construction of the reduction operators (goes beyond the seed): the same algorithms
//! as the exact route (`super::exact_operator`, kept as the oracle) and closed forms for the
//! multi-degree methods ([`truncation`]), run in `f64` and, where that is not accurate
//! enough, in double-word arithmetic, and where even that is not, in 256-bit floating point
//! ([`wide`]), every number carrying a rigorous bound of its error ([`tracked`]).
//!
//! A route is accepted only if its *proven* error is at most [`TOLERANCE`] relative to the
//! operator's inf-norm (entrywise and per row sum) and to each bound functional's 1-norm;
//! otherwise the next route is tried, and the exact route (`BigRational`) is the last resort.
//! The proven errors travel with the operator (`Operator::own_bound` adds them), so a
//! method's own bound stays a true bound for the matrix actually used.

mod compensated;
mod correlation;
mod dd;
mod ginv_ends;
mod quadrature;
mod row_bound;
mod rows;
mod steps;
mod tracked;
mod truncation;
mod wide;

use rows::{Row, Rows, to_i};
use tracked::Base;
use truncation::{Family, truncated};

use crate::bezier::method::Method;

/// The largest accepted proven error, relative to the operator's inf-norm (issue 17's
/// accuracy goal); for the bound functionals, relative to `max(1, sum_t coef_t ||g_t||_1)`
/// (their proven errors are added to the own bound, so they only cost tightness).
pub(crate) const TOLERANCE: f64 = 1e-12;

/// How an operator was built.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum OperatorRoute {
    /// `f64` arithmetic with a proven error bound.
    F64,
    /// Double-word (about 106-bit) arithmetic with a proven error bound.
    DoubleWord,
    /// 256-bit binary floating point with a proven error bound (where the double-word
    /// route's proven error is above the goal: the stepwise perturbation at high degree,
    /// truncations close to `m = n`).
    MultiWord,
    /// Exact rational arithmetic, rounded once.
    Exact,
}

/// A fast-built operator: the `f64` matrix, the proven bound of `max_i sum_j |a_ij - exact|`,
/// and the bound terms `(coef, functional, proven sum_j |g_j - exact|)`.
#[derive(Debug, Clone)]
pub(crate) struct Built {
    pub(crate) matrix: Vec<f64>,
    pub(crate) error: f64,
    pub(crate) terms: Vec<(f64, Vec<f64>, f64)>,
    pub(crate) route: OperatorRoute,
}

/// The rows and terms of `method` in base arithmetic `B` (`None` for a method without a
/// fast route: none today, kept for methods added later; or for an `f64` stepwise attempt
/// given up early, see `steps::stepwise`); `mixed`: the truncations' back
/// conversion in `f64` (see [`truncated`]), and Farin's steps in their split form (see
/// `steps::step`).
fn rows_of<B: Base>(method: Method, n: usize, m: usize, mixed: bool) -> Option<Rows<B>> {
    if method == Method::Eck {
        return Some(eck(n, m, mixed));
    }
    if method.is_one_degree() {
        // The `f64` attempt gives up once a step's proven error is 4 times the strictest
        // goal (`build`'s `strict`), relative to that step's rows; Farin's split form in
        // double-word at 4 times the goal (its direct form is tried next).
        #[allow(clippy::cast_precision_loss, reason = "n <= 64")]
        let give_up = if B::GIVE_UP_EARLY {
            Some(8.0 * (n as f64 + 3.0) * f64::EPSILON)
        } else if mixed {
            Some(4.0 * TOLERANCE)
        } else {
            None
        };
        return steps::stepwise(method, n, m, mixed, give_up);
    }
    let cheb = |r: i32, p: i32| {
        let factor = super::chebyshev::bound_factor_up(r, p);
        truncated(Family::Chebyshev, n, m, r, p, Some(factor), mixed)
    };
    Some(match method {
        Method::WatkinsWorsey | Method::BogackiWeinsteinXu => cheb(-1, -1),
        Method::ConstrainedChebyshev { r, p } => cheb(r, p),
        Method::GeneralizedInverse => {
            truncated(Family::Jacobi { a: 0, b: 0 }, n, m, -1, -1, None, mixed)
        }
        Method::GeneralizedInverseEnds => ginv_ends::ginv_ends(n, m, mixed),
        Method::L2 { r, p } => {
            let family = Family::Jacobi {
                a: 2 * i64::from(r) + 2,
                b: 2 * i64::from(p) + 2,
            };
            truncated(family, n, m, r, p, None, mixed)
        }
        _ => return None,
    })
}

/// The truncation behind a multi-degree method (and Eck's): family, end orders, and whether
/// it carries bound terms (the coefficient functionals above `M`, by quadrature).
fn truncation_of(method: Method) -> Option<(Family, i32, i32, bool)> {
    Some(match method {
        Method::Eck | Method::WatkinsWorsey | Method::BogackiWeinsteinXu => {
            (Family::Chebyshev, -1, -1, true)
        }
        Method::ConstrainedChebyshev { r, p } => (Family::Chebyshev, r, p, true),
        Method::GeneralizedInverse | Method::GeneralizedInverseEnds => {
            (Family::Jacobi { a: 0, b: 0 }, -1, -1, false)
        }
        Method::L2 { r, p } => (
            Family::Jacobi {
                a: 2 * i64::from(r) + 2,
                b: 2 * i64::from(p) + 2,
            },
            r,
            p,
            false,
        ),
        _ => return None,
    })
}

/// Eck's stepwise reduction (SPEC-reduce §3) by its closed form (beyond the seed): each
/// step is the Chebyshev economisation of its polygon (it removes the `T_k` term and keeps
/// the lower Chebyshev coefficients), so `n -> m` is the truncated Chebyshev series, the
/// operator of Watkins–Worsey. Step `k`'s own bound term is `2^-(2k-1) ||Delta^k s||` on
/// the degree-`k` stage `s` (the truncation to degree `k`), whose leading power coefficient
/// `Delta^k s` is `2^(2k-1)` times the `T_k(2t-1)` coefficient functional `f_k` of `P`; the
/// terms are listed from `k = n` down, as the stepwise exact route lists them.
fn eck<B: Base>(n: usize, m: usize, mixed: bool) -> Rows<B> {
    let (rows, terms) = truncated::<B>(Family::Chebyshev, n, m, -1, -1, Some(1.0), mixed);
    let mut terms: Vec<(f64, Row<B>)> = terms
        .into_iter()
        .zip(m + 1..=n)
        .map(|((_, f), k)| {
            let e = i32::try_from(2 * k - 1).unwrap_or(i32::MAX);
            let coef = 2f64.powi(-e) * (1.0 + 4.0 * f64::EPSILON);
            (coef, rows::scale(&f, tracked::Tracked::of(2f64.powi(e))))
        })
        .collect();
    terms.reverse();
    (rows, terms)
}

/// A row of a builder's result: its entries rounded to `f64` and a bound of the sum of
/// their errors.
trait Rounded {
    /// `(values, bound of sum_c |value_c - exact_c|)`.
    fn rounded(&self) -> (Vec<f64>, f64);
    /// The number of entries.
    fn len(&self) -> usize;
}

impl<B: Base> Rounded for Row<B> {
    fn rounded(&self) -> (Vec<f64>, f64) {
        Row::rounded(self)
    }
    fn len(&self) -> usize {
        self.v.len()
    }
}

impl Rounded for compensated::CRow {
    fn rounded(&self) -> (Vec<f64>, f64) {
        compensated::CRow::rounded(self)
    }
    fn len(&self) -> usize {
        compensated::CRow::len(self)
    }
}

/// Rounds the rows and checks the proven errors against `tol` (relative).
fn finish<R: Rounded>(
    rows: &[R],
    terms: &[(f64, R)],
    route: OperatorRoute,
    tol: f64,
) -> Option<Built> {
    let mut matrix = Vec::with_capacity(rows.len() * rows.first().map_or(0, Rounded::len));
    let (mut error, mut norm) = (0.0f64, 0.0f64);
    for row in rows {
        let (v, e) = row.rounded();
        norm = norm.max(v.iter().map(|x| x.abs()).sum());
        error = error.max(e);
        matrix.extend(v);
    }
    let ok = |e: f64, s: f64| e.is_finite() && e <= tol * s;
    if !ok(error, norm) || !matrix.iter().all(|x| x.is_finite()) {
        return None;
    }
    let mut out = Vec::with_capacity(terms.len());
    let (mut te, mut ts) = (0.0, 0.0);
    for (coef, g) in terms {
        let (v, e) = g.rounded();
        let s: f64 = v.iter().map(|x| x.abs()).sum();
        te += coef * e;
        ts += coef * s;
        out.push((*coef, v, e * (1.0 + 1e-9)));
    }
    // The functionals' proven errors are added to the own bound (`Operator::own_bound`),
    // which already allows `2 (n+3) eps (||A|| + sum_t coef_t ||g_t|| + 1) max ||P_j||` for
    // the rounding of the exact route: half of that much more (beside the relative goal)
    // leaves the reported bound within that allowance's scale. At degree 64 the highest
    // Chebyshev coefficient functionals (Eck's step terms) lose more than `1e-12` to
    // cancellation even in double-word; their matrix is still within [`TOLERANCE`].
    #[allow(clippy::cast_precision_loss, reason = "n <= 64")]
    let allowance =
        (rows.first().map_or(0, Rounded::len) as f64 + 2.0) * f64::EPSILON * (norm + ts + 1.0);
    if !(ok(te, ts.max(1.0)) || (te.is_finite() && te <= allowance)) {
        return None;
    }
    Some(Built {
        matrix,
        error: error * (1.0 + 1e-9),
        terms: out,
        route,
    })
}

/// The operator of `method` (`n -> m`, preconditions checked by the caller) by the first
/// route whose proven error is within [`TOLERANCE`]: `f64`, then double-word, then 256-bit
/// ([`wide`]); `None` if none is (or the method has no fast route), and the caller uses the
/// exact route.
///
/// A method with its own bound terms takes the `f64` route only if its proven error is
/// within `2 (n+3) eps` of the inf-norm, the rounding allowance `Operator::own_bound` already
/// makes, so that adding the construction error leaves the reported bounds as tight as the
/// exact route's; otherwise the double-word route, whose errors are at the rounding level.
pub(crate) fn build(method: Method, n: usize, m: usize) -> Option<Built> {
    #[allow(clippy::cast_precision_loss, reason = "n <= 64")]
    let strict = 2.0 * (n as f64 + 3.0) * f64::EPSILON;
    let skip_f64 = truncation_of(method).is_some_and(|(family, r, p, terms)| {
        let (r, p) = (i64::from(r), i64::from(p));
        let (nn, mm) = (to_i(n) - (r + p + 2), to_i(m) - (r + p + 2));
        let tol = if terms { strict } else { TOLERANCE };
        // A one-degree truncation goes from the top (no alternating sums): always try f64.
        mm >= 0 && n - m > 1 && truncation::f64_hopeless(family, nn, mm, tol)
    });
    // Forrest and Piegl–Tiller: `f64` rows with one bound per row first (`row_bound.rs`:
    // the tracked `f64` route's matrix and bound, without its per-entry error arrays).
    if let Some((rows, terms)) = row_bound::stepwise(method, n, m) {
        if let Some(b) = finish(&rows, &terms, OperatorRoute::F64, strict) {
            return Some(b);
        }
    }
    // Farin and the perturbation: compensated steps first (`compensated.rs`), accepted at
    // the rounding level.
    if let Some((rows, terms)) = compensated::stepwise(method, n, m) {
        if let Some(b) = finish(&rows, &terms, OperatorRoute::DoubleWord, strict) {
            return Some(b);
        }
    }
    if !skip_f64 {
        if let Some((rows, terms)) = rows_of::<f64>(method, n, m, false) {
            let tol = if terms.is_empty() { TOLERANCE } else { strict };
            if let Some(b) = finish(&rows, &terms, OperatorRoute::F64, tol) {
                return Some(b);
            }
        }
    }
    // Double-word with the back conversion in `f64` first (for a truncation), then all in
    // double-word.
    let tries: &[bool] = if truncation_of(method).is_some() || method == Method::Farin {
        &[true, false]
    } else {
        &[false]
    };
    for &mixed in tries {
        // (`None`: Farin's split form given up early; the direct form is next.)
        let Some((rows, terms)) = rows_of::<dd::Dd>(method, n, m, mixed) else {
            continue;
        };
        // The mixed route only at the rounding level (`strict`): the error-curve basis of
        // the bounds (`error_basis.rs`) finds its rank at that level, and a less accurate
        // operator would only loosen the bounds.
        let tol = if mixed && truncation_of(method).is_some() {
            strict
        } else {
            TOLERANCE
        };
        if let Some(b) = finish(&rows, &terms, OperatorRoute::DoubleWord, tol) {
            return Some(b);
        }
    }
    let (rows, terms) = rows_of::<wide::Wide>(method, n, m, false)?;
    finish(&rows, &terms, OperatorRoute::MultiWord, TOLERANCE)
}

#[cfg(test)]
mod tests;
