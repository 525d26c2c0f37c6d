//! Reduction operators: the `(m+1) x (n+1)` matrix of a linear method in `f64`, with the
//! data for a cheap certified error bound, built once per `(method, n, m)` and cached
//! process-wide. Built by the fast routes of [`fast`] (closed forms and the seed's
//! recursions in `f64` or double-word arithmetic with a proven error of at most `1e-12` of
//! the operator's inf-norm), falling back to the exact rational route ([`exact_operator`],
//! the test oracle, rounded once; Eck falls back to its equal closed form `eck_exact`).

use std::collections::HashMap;
use std::sync::{Arc, OnceLock, RwLock};

use cagd_core::{Error, Result};

mod chebyshev;
mod ends;
mod error_basis;
mod error_map;
mod fast;
mod hull;
mod least_squares;
mod one_step;

use super::gemm::LinearMap;
use super::method::Method;
use crate::exact::{RatMat, Row, Scaled};
use chebyshev::{constrained, truncation};
use least_squares::{ginv_ends, l2};
use one_step::{residual_term, step};

pub use chebyshev::{ChebyshevTerms, constrained_chebyshev_terms};
pub(crate) use error_basis::ErrorBasis;
pub(crate) use error_map::{BoundMap, node as lobatto_node};
pub use fast::OperatorRoute;
pub use one_step::eck_lambdas;

/// One term `coef * ||sum_j g_j P_j||` of a method's own error bound.
#[derive(Debug, Clone)]
struct BoundTerm {
    coef: f64,
    functional: Vec<f64>,
    /// Proven bound of `sum_j |functional_j - exact_j|` (0 on the exact route, where the
    /// rounding is covered by `own_bound`'s allowance).
    error: f64,
}

/// A linear degree-reduction operator from degree `n` to degree `m`: `Q_i = sum_j a_ij P_j`,
/// applied coordinate-wise to points of any dimension (also to homogeneous points).
///
/// Every entry is within `1e-12 * ||A||_inf` of the exact rational value (a proven bound,
/// [`Operator::construction_error`]; on the [`OperatorRoute::Exact`] route each entry is the
/// exact value rounded once).
#[derive(Debug, Clone)]
pub struct Operator {
    method: Method,
    n: usize,
    m: usize,
    /// The matrix and its GEMM data path.
    map: LinearMap,
    terms: Vec<BoundTerm>,
    /// The error curve's basis and the node maps of the fast and the tight bound level,
    /// built on first use.
    error_basis: OnceLock<ErrorBasis>,
    bound_maps: [OnceLock<BoundMap>; 2],
    /// `max_i sum_j |a_ij|` (rounding amplification of the operator).
    op_norm: f64,
    /// `sum_t coef_t sum_j |g_tj|`.
    terms_norm: f64,
    /// Proven bound of `max_i sum_j |a_ij - exact_ij|` beyond rounding once (0 on the exact
    /// route).
    construction_error: f64,
    route: OperatorRoute,
}

type Key = ((u8, u64, u64), usize, usize);

fn cache() -> &'static RwLock<HashMap<Key, Arc<Operator>>> {
    static CACHE: OnceLock<RwLock<HashMap<Key, Arc<Operator>>>> = OnceLock::new();
    CACHE.get_or_init(|| RwLock::new(HashMap::new()))
}

/// The cached operator of `method` reducing degree `n` to degree `m` (built on first use,
/// thread-safe; later calls return the same `Arc`).
///
/// # Errors
/// As [`Method::check`]: [`Error::DegreeOutOfRange`], [`Error::BadDegreePair`],
/// [`Error::TooManyConstraints`], [`Error::BadParameter`].
pub fn operator(method: Method, n: usize, m: usize) -> Result<Arc<Operator>> {
    method.check(n, m)?;
    let key = (method.key(), n, m);
    if let Ok(map) = cache().read() {
        if let Some(op) = map.get(&key) {
            return Ok(Arc::clone(op));
        }
    }
    let op = Arc::new(Operator::build(method, n, m, false)?);
    // A poisoned lock only means another thread panicked while inserting: the map is still
    // a valid cache, so keep using it.
    let mut map = cache()
        .write()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    Ok(Arc::clone(map.entry(key).or_insert(op)))
}

/// Builds the operator of `method` (`n -> m`) afresh, without the cache: by the fast routes
/// (falling back to the exact one) as [`operator`] does, or with `exact` by the exact
/// rational route only. For measuring and testing construction; use [`operator`] otherwise.
/// The methods and their formulas are seed 000 §14.2–14.5 (see [`Method`]); the fast routes
/// go beyond the seed only in how they evaluate them (proven f64 / double-word error).
///
/// # Errors
/// As [`operator`].
pub fn build_operator(method: Method, n: usize, m: usize, exact: bool) -> Result<Operator> {
    Operator::build(method, n, m, exact)
}

/// The exact operator and bound terms of a method (before rounding).
pub(crate) fn exact_operator(
    method: Method,
    n: usize,
    m: usize,
) -> Result<(RatMat, Vec<(f64, Row)>)> {
    method.check(n, m)?;
    if method.is_one_degree() {
        let mut s = Scaled::identity(n + 1);
        // The own bound is the sum of the per-step bounds; a step without one contributes
        // its exact convex-hull term, and if even that has no closed form the own bound is
        // dropped (the convex-hull bound of the composed operator remains).
        let mut terms = Vec::new();
        let mut valid = true;
        for k in ((m + 1)..=n).rev() {
            let st = step(method, k);
            let own = if st.terms.is_empty() {
                residual_term(&st.op, k).map(|t| vec![t])
            } else {
                Some(st.terms)
            };
            match own {
                Some(t) if valid => terms.extend(t.iter().map(|(c, g)| (*c, s.row_times(g)))),
                _ => valid = false,
            }
            s = Scaled::from_rat(&st.op).mul(&s);
        }
        if !valid {
            terms.clear();
        }
        return Ok((s.to_rat(), terms));
    }
    Ok(match method {
        Method::WatkinsWorsey => truncation(n, m)?,
        Method::BogackiWeinsteinXu => constrained(n, m, -1, -1)?,
        Method::ConstrainedChebyshev { r, p } => constrained(n, m, r, p)?,
        // Identical exact operator (Lutterkort–Peters–Reif; unit test
        // `l2_free_equals_generalized_inverse`), and the Gram system is much cheaper in
        // rationals than the normal equations of eq. 14.4.6.
        Method::GeneralizedInverse => (l2(n, m, -1, -1)?, Vec::new()),
        Method::GeneralizedInverseEnds => (ginv_ends(n, m)?, Vec::new()),
        Method::L2 { r, p } => (l2(n, m, r, p)?, Vec::new()),
        // One-degree methods returned above.
        _ => {
            return Err(Error::BadDegreePair {
                from: n,
                to: m,
                why: "unsupported method",
            });
        }
    })
}

/// Eck's exact operator and stepwise terms from the Chebyshev truncation (the fallback of
/// the fast route; beyond the seed): the stepwise Chebyshev economisation composes to the
/// truncated series (Watkins–Worsey's operator, `chebyshev::truncation`), and step `k`'s
/// term `2^-(2k-1) ||Delta^k s||` has `Delta^k s = 2^(2k-1) f_k`, `f_k` the `T_k(2t-1)`
/// coefficient functional. Equal to [`exact_operator`]'s stepwise result (unit test
/// `eck_exact_equals_the_stepwise_route`) at a fraction of its cost (seconds at degree 64).
fn eck_exact(n: usize, m: usize) -> Result<(RatMat, Vec<(f64, Row)>)> {
    Method::Eck.check(n, m)?;
    let (mat, terms) = truncation(n, m)?;
    let mut out: Vec<(f64, Row)> = terms
        .into_iter()
        .zip(m + 1..=n)
        .map(|((_, f), k)| {
            let e = one_step::to_exp(k);
            let scale = crate::exact::pow2(e);
            (
                one_step::up(&crate::exact::pow2(-e)),
                f.iter().map(|x| x * &scale).collect(),
            )
        })
        .collect();
    out.reverse();
    Ok((mat, out))
}

impl Operator {
    fn build(method: Method, n: usize, m: usize, exact_only: bool) -> Result<Self> {
        method.check(n, m)?;
        let fast = if exact_only {
            None
        } else {
            fast::build(method, n, m)
        };
        let (matrix, terms, construction_error, route) = match fast {
            Some(b) => {
                let terms: Vec<BoundTerm> = b
                    .terms
                    .into_iter()
                    .map(|(coef, functional, error)| BoundTerm {
                        coef,
                        functional,
                        error,
                    })
                    .collect();
                (b.matrix, terms, b.error, b.route)
            }
            None => {
                let (exact, terms) = if method == Method::Eck {
                    eck_exact(n, m)?
                } else {
                    exact_operator(method, n, m)?
                };
                let terms = terms
                    .into_iter()
                    .map(|(coef, g)| BoundTerm {
                        coef,
                        functional: g.iter().map(crate::exact::q_to_f64).collect(),
                        error: 0.0,
                    })
                    .collect();
                (exact.to_f64(), terms, 0.0, OperatorRoute::Exact)
            }
        };
        // max_i sum_j |a_ij| of the f64 matrix, rounded up generously.
        let op_norm = matrix
            .chunks_exact(n + 1)
            .map(|row| row.iter().map(|x| x.abs()).sum::<f64>())
            .fold(0.0, f64::max)
            * (1.0 + 1e-12);
        let terms_norm = terms
            .iter()
            .map(|t| t.coef * t.functional.iter().map(|x| x.abs()).sum::<f64>())
            .sum::<f64>()
            * (1.0 + 1e-12);
        Ok(Self {
            method,
            n,
            m,
            map: LinearMap::new(m + 1, n + 1, matrix),
            terms,
            error_basis: OnceLock::new(),
            bound_maps: Default::default(),
            op_norm,
            terms_norm,
            construction_error,
            route,
        })
    }

    /// The method this operator implements.
    pub fn method(&self) -> Method {
        self.method
    }

    /// The source degree `n`.
    pub fn degree_from(&self) -> usize {
        self.n
    }

    /// The target degree `m`.
    pub fn degree_to(&self) -> usize {
        self.m
    }

    /// How the matrix was built.
    pub fn route(&self) -> OperatorRoute {
        self.route
    }

    /// A proven bound of `max_i sum_j |a_ij - exact_ij|` for the fast routes (at most
    /// `1e-12` times [`Operator::norm_inf`]); `0` for the exact route, whose entries are the
    /// exact values rounded once.
    pub fn construction_error(&self) -> f64 {
        self.construction_error
    }

    /// The matrix, row-major, `(m+1) x (n+1)`: `Q_i = sum_j matrix[i * (n+1) + j] P_j`.
    pub fn matrix(&self) -> &[f64] {
        self.map.matrix()
    }

    /// The matrix with its GEMM data path.
    pub(crate) fn map(&self) -> &LinearMap {
        &self.map
    }

    /// The error curve's basis (see `error_basis.rs`), built on first use.
    pub(crate) fn error_basis(&self) -> &ErrorBasis {
        self.error_basis
            .get_or_init(|| ErrorBasis::new(self.matrix(), self.n, self.m, self.op_norm))
    }

    /// The node map in cache slot `slot` (0: the fast level's, 1: the tight level's) with
    /// secant factor at most `ratio`, built on first use (see `bound/mod.rs`, which picks
    /// the slot and ratio).
    pub(crate) fn error_map(&self, slot: usize, ratio: f64) -> &BoundMap {
        self.bound_maps[slot].get_or_init(|| BoundMap::new(self.error_basis(), self.op_norm, ratio))
    }

    /// The method's own bound (e.g. `W_n ||F|| / (C(2n,n) - 2)` for [`Method::Perturb`],
    /// eq. 14.5.2's bound for [`Method::ConstrainedChebyshev`]) for the reduced points
    /// this operator computes from `points`, rounding included; `None` if the method has
    /// none. Lengths are the caller's invariant.
    pub(crate) fn own_bound(&self, points: &[f64], dim: usize) -> Option<f64> {
        if self.terms.is_empty() {
            return None;
        }
        let eps = f64::EPSILON;
        let pmax = max_norm(points, dim);
        let nf = self.n as f64;
        // Method bound on the exact Q, plus the distance of the computed Q from it: the
        // rounding (exact entries rounded once) and the proven construction errors of the
        // matrix and of the functionals (`sum_j |e_j| ||P_j|| <= sum_j |e_j| pmax`).
        let mut construction = self.construction_error;
        let mut own = 0.0;
        let mut v = [0.0; 8];
        let mut heap;
        let v: &mut [f64] = if dim <= v.len() {
            &mut v[..dim]
        } else {
            heap = vec![0.0; dim];
            &mut heap
        };
        for t in &self.terms {
            v.fill(0.0);
            for (g, p) in t.functional.iter().zip(points.chunks_exact(dim)) {
                for (a, b) in v.iter_mut().zip(p) {
                    *a += g * b;
                }
            }
            own += t.coef * v.iter().map(|x| x * x).sum::<f64>().sqrt();
            construction += t.coef * t.error;
        }
        Some(
            own * (1.0 + 4.0 * eps)
                + 2.0 * (nf + 3.0) * eps * (self.op_norm + self.terms_norm + 1.0) * pmax
                + construction * (1.0 + 4.0 * eps) * pmax,
        )
    }

    /// `max_i sum_j |a_ij|`: how much the operator can amplify input noise.
    pub fn norm_inf(&self) -> f64 {
        self.op_norm
    }

    /// A certified upper bound of `max_t ||P(t) - Q(t)||` (Euclidean norm, in the space of
    /// the given points) for input `points` and the reduced points `reduced` this operator
    /// produced from them (`f64` rounding of `reduced` included). Cheap: `O(n^2 dim)`, no
    /// sampling.
    ///
    /// It is the smaller of the method's own bound (e.g. `W_n ||F|| / (C(2n,n) - 2)` for
    /// [`Method::Perturb`], eq. 14.5.2's bound for [`Method::ConstrainedChebyshev`]) and the
    /// universal convex-hull bound `max_i ||P_i - (E Q)_i||` (`E` = elevation `m -> n`,
    /// seed 000 §14.4.3), each plus a rigorous allowance for the `f64` rounding.
    ///
    /// # Errors
    /// [`Error::ZeroDimension`], [`Error::LengthMismatch`].
    pub fn error_bound(&self, points: &[f64], reduced: &[f64], dim: usize) -> Result<f64> {
        check_len(points, self.n, dim, "points")?;
        check_len(reduced, self.m, dim, "reduced")?;
        let hull = hull_bound(points, reduced, dim);
        Ok(match self.own_bound(points, dim) {
            Some(own) => own.min(hull),
            None => hull,
        })
    }
}

/// `max_i ||x_i||` (Euclidean) over the points of a buffer.
pub(crate) fn max_norm(x: &[f64], dim: usize) -> f64 {
    x.chunks_exact(dim)
        .map(|p| p.iter().map(|v| v * v).sum::<f64>().sqrt())
        .fold(0.0, f64::max)
}

/// The convex-hull bound of seed 000 §14.4.3 on *computed* reduced points (their rounding
/// is included by construction), refined by subdivision of the difference curve
/// ([`hull::refined_hull_bound`]): `D = P - E Q`, `E` = elevation `m -> n`, plus an
/// allowance for the rounding of the elevation and the subtraction.
pub(crate) fn hull_bound(points: &[f64], reduced: &[f64], dim: usize) -> f64 {
    let n = points.len() / dim - 1;
    let m = reduced.len() / dim - 1;
    let eps = f64::EPSILON;
    let mut diff = vec![0.0; (n + 1) * dim];
    cagd_core::kernel::elevate(reduced, dim, n - m, &mut diff);
    for (d, p) in diff.iter_mut().zip(points) {
        *d = p - *d;
    }
    let hull = hull::refined_hull_bound(&diff, dim, hull::DEPTH);
    let slack = 2.0 * (n as f64 + 3.0) * eps * (max_norm(points, dim) + max_norm(reduced, dim));
    hull * (1.0 + 4.0 * eps) + slack
}

/// Checks that a buffer holds `degree + 1` points of `dim` coordinates.
pub(crate) fn check_len(x: &[f64], degree: usize, dim: usize, what: &'static str) -> Result<()> {
    if dim == 0 {
        return Err(Error::ZeroDimension);
    }
    let expected = (degree + 1) * dim;
    if x.len() != expected {
        return Err(Error::LengthMismatch {
            what,
            got: x.len(),
            expected,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::{Q, q_to_f64};
    use num_traits::{Signed, Zero};

    #[test]
    fn l2_with_c0_ends_has_the_unit_end_rows_the_batch_kernel_copies() {
        // `padded::Units` on the operators: L2 with C0 ends has them, plain L2 has not.
        use crate::bezier::padded::Units;
        for (n, m) in [(4, 3), (5, 4), (10, 5), (15, 10)] {
            let ends = |r| {
                let op = operator(Method::L2 { r, p: r }, n, m).unwrap();
                Units::of(op.matrix(), m + 1, n + 1).ends()
            };
            assert_eq!(ends(0), Some([0, n]), "({n},{m})");
            assert_eq!(ends(-1), None, "({n},{m})");
        }
    }

    /// Applies the f64 operator to a curve and compares with the exact rational operator
    /// applied exactly: the max deviation relative to the largest exact reduced coordinate.
    fn relative_error(method: Method, n: usize, m: usize) -> f64 {
        let (exact, _) = exact_operator(method, n, m).unwrap();
        let op = operator(method, n, m).unwrap();
        let dim = 2;
        // Deterministic "random" points with few bits, exact in f64.
        let pts: Vec<f64> = (0..(n + 1) * dim)
            .map(|i| (((i * 7919 + 13) % 201) as f64 - 100.0) / 64.0)
            .collect();
        let got = op.apply(&pts, dim).unwrap();
        let (mut worst, mut big) = (0.0f64, 0.0f64);
        for i in 0..=m {
            for k in 0..dim {
                let mut acc = Q::zero();
                for j in 0..=n {
                    acc += exact.at(i, j) * Q::from_float(pts[j * dim + k]).unwrap();
                }
                big = big.max(q_to_f64(&acc.abs()));
                let diff = Q::from_float(got[i * dim + k]).unwrap() - acc;
                worst = worst.max(q_to_f64(&diff.abs()));
            }
        }
        worst / big
    }

    #[test]
    fn high_degree_operators_match_exact_arithmetic() {
        let methods = [
            Method::GeneralizedInverse,
            Method::GeneralizedInverseEnds,
            Method::L2 { r: 2, p: 2 },
            Method::ConstrainedChebyshev { r: 1, p: 1 },
            Method::BogackiWeinsteinXu,
            Method::Forrest,
            Method::Perturb,
        ];
        let mut worst = 0.0f64;
        for method in methods {
            let e = relative_error(method, 40, 20);
            assert!(e <= 1e-10, "{method:?} 40 -> 20: relative error {e:e}");
            worst = worst.max(e);
        }
        // The worst case supported: degree 64 (exact builds of the largest systems take
        // seconds, so a representative subset).
        for (method, m) in [
            (Method::GeneralizedInverse, 32),
            (Method::L2 { r: 2, p: 2 }, 32),
            (Method::ConstrainedChebyshev { r: 1, p: 1 }, 32),
            (Method::Forrest, 32),
            (Method::Perturb, 60),
            (Method::BogackiWeinsteinXu, 60),
        ] {
            let e = relative_error(method, 64, m);
            assert!(e <= 1e-10, "{method:?} 64 -> {m}: relative error {e:e}");
            worst = worst.max(e);
        }
        println!("worst relative error of applying an operator: {worst:e}");
    }

    #[test]
    fn eck_exact_equals_the_stepwise_route() {
        for n in 1..=12 {
            for m in 0..n {
                let (a, ta) = eck_exact(n, m).unwrap();
                let (b, tb) = exact_operator(Method::Eck, n, m).unwrap();
                assert_eq!(a, b, "{n} -> {m}");
                assert_eq!(ta.len(), tb.len());
                for ((ca, ga), (cb, gb)) in ta.iter().zip(&tb) {
                    assert_eq!(ca, cb, "{n} -> {m}");
                    assert_eq!(ga, gb, "{n} -> {m}");
                }
            }
        }
    }

    #[test]
    fn cache_returns_the_same_operator() {
        let a = operator(Method::Eck, 9, 4).unwrap();
        let b = operator(Method::Eck, 9, 4).unwrap();
        assert!(Arc::ptr_eq(&a, &b));
        // Stepwise Eck = Chebyshev truncation (economisation keeps lower coefficients).
        let w = operator(Method::WatkinsWorsey, 9, 4).unwrap();
        for (x, y) in a.matrix().iter().zip(w.matrix()) {
            assert!((x - y).abs() <= 1e-15 * x.abs().max(1.0));
        }
        // Piegl–Tiller = Forrest, stepwise too (exact operators are equal).
        for n in 1..12 {
            for m in 0..n {
                let f = exact_operator(Method::Forrest, n, m).unwrap().0;
                let p = exact_operator(Method::PieglTiller, n, m).unwrap().0;
                assert_eq!(f, p, "{n} -> {m}");
            }
        }
        // BWX = Watkins–Worsey exactly.
        assert_eq!(
            exact_operator(Method::BogackiWeinsteinXu, 11, 5).unwrap().0,
            exact_operator(Method::WatkinsWorsey, 11, 5).unwrap().0
        );
    }

    #[test]
    fn errors_not_panics() {
        assert!(matches!(
            operator(Method::Eck, 65, 3),
            Err(Error::DegreeOutOfRange { .. })
        ));
        assert!(matches!(
            operator(Method::Eck, 5, 5),
            Err(Error::BadDegreePair { .. })
        ));
        assert!(matches!(
            operator(Method::L2 { r: 2, p: 2 }, 9, 4),
            Err(Error::TooManyConstraints { .. })
        ));
        let op = operator(Method::Eck, 3, 2).unwrap();
        assert!(matches!(
            op.apply(&[0.0, 1.0, f64::NAN, 2.0], 1),
            Err(Error::NonFinite { index: 2, .. })
        ));
        assert!(matches!(
            op.apply(&[0.0, 1.0, 2.0], 1),
            Err(Error::LengthMismatch { .. })
        ));
        assert!(matches!(op.apply(&[], 0), Err(Error::ZeroDimension)));
        let mut out = vec![0.0; 5];
        assert!(op.apply_into(&[0.0; 8], 1, &mut out).is_err());
        assert!(op.apply_into(&[0.0; 7], 1, &mut out[..3]).is_err());
    }
}
