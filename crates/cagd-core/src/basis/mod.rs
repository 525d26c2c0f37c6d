//! Basis-change matrices between the degree-n Bernstein basis and other polynomial bases on
//! `[0, 1]`, exact (rationals) and rounded once to `f64`, cached per `(basis, n)`.
//! Everything is documented on [`Basis`].

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use nalgebra::DMatrix;

mod ball;
mod closed;

pub use ball::{BallTerm, wsgb_max_l, wsgb_terms};

use crate::{Error, ExactMatrix, Result, check_degree, check_points};
use ball::{check_wsgb, wsgb_to_bernstein};
use closed::{
    chebyshev_from_bernstein, chebyshev_to_bernstein, legendre_from_bernstein,
    legendre_to_bernstein, power_from_bernstein, power_to_bernstein,
};

/// A polynomial basis of degree `n` on `[0, 1]` other than Bernstein, for the basis-change
/// matrices [`to_bernstein`], [`from_bernstein`] and their `_exact` forms.
///
/// Convention: if `c` holds the coefficients of a polynomial in `basis` and `b` its Bernstein
/// coefficients, then `b = to_bernstein(basis, n) * c` and `c = from_bernstein(basis, n) * b`.
/// Column `k` of `to_bernstein` is the Bernstein coefficient vector of the k-th basis
/// polynomial. Points of any dimension are converted coordinate-wise by [`convert_points`].
///
/// | basis | polynomials | to Bernstein | from Bernstein |
/// |---|---|---|---|
/// | [`Basis::Power`] | `t^k` | closed form | closed form |
/// | [`Basis::Chebyshev`] | `T_k(2t-1)` (seed 000 Lemma 14.5.3) | closed form (SPEC-reduce §7) | closed form by orthogonality |
/// | [`Basis::Legendre`] | `P_k(2t-1)` | closed form | closed form by orthogonality |
/// | [`Basis::SaidBall`], [`Basis::WangBall`], [`Basis::Wsgb`] | seed 003, SPEC-reduce §9.1 | closed form | exact inverse |
///
/// ```
/// use cagd_core::{Basis, convert_points, to_bernstein, from_bernstein};
/// // 1 - 2t + 3t^2 in the power basis, as a 1-D "curve".
/// let to = to_bernstein(Basis::Power, 2)?; // Arc<DMatrix<f64>>, cached
/// let b = convert_points(&to, &[1.0, -2.0, 3.0], 1)?;
/// assert_eq!(b, vec![1.0, 0.0, 2.0]);
/// let from = from_bernstein(Basis::Chebyshev, 2)?;
/// let c = convert_points(&from, &b, 1)?;
/// // 1 - 2t + 3t^2 = 9/8 T_0 + 1/2 T_1 + 3/8 T_2 with T_k = T_k(2t - 1).
/// assert_eq!(c, vec![9.0 / 8.0, 0.5, 3.0 / 8.0]);
/// # Ok::<(), cagd_core::Error>(())
/// ```
///
/// ## Supported range and accuracy
///
/// Degrees `0..=64` ([`crate::MAX_DEGREE`]); `Wsgb { l }` needs
/// `l <= max(floor(n/2) - 1, 0)`. The `_exact` matrices are exact, and
/// `from_bernstein_exact * to_bernstein_exact = I` exactly. Every `f64` entry is the exact entry
/// rounded once (relative error <= 2^-53), so applying a matrix costs at most
/// `(n+2) eps |M|_inf |c|_inf`; a round trip through another basis is then limited only by
/// the conditioning `|to|_inf |from|_inf` of the basis change, which no `f64` matrix can beat.
/// Measured (examples/basis_accuracy.rs; max abs error / max abs input, worst of 20 random
/// vectors in `[-1, 1]`):
///
/// Basis -> Bernstein -> basis, `from * (to * c)`:
///
/// | n | Power | Chebyshev | Legendre | Said–Ball | Wang–Ball |
/// |---|---|---|---|---|---|
/// | 5 | 7.1e-15 | 8.8e-16 | 4.9e-16 | 3.0e-16 | 3.3e-16 |
/// | 10 | 1.2e-12 | 2.4e-14 | 8.9e-15 | 3.7e-16 | 3.3e-15 |
/// | 20 | 5.5e-8 | 8.5e-12 | 3.7e-12 | 1.2e-15 | 9.9e-13 |
/// | 30 | 1.5e-3 | 1.1e-8 | 6.0e-9 | 5.4e-15 | 1.8e-10 |
/// | 40 | 1.4e2 | 1.3e-5 | 3.5e-6 | 4.2e-14 | 2.5e-8 |
/// | 50 | 1.6e7 | 9.0e-3 | 3.6e-3 | 2.1e-13 | 6.9e-6 |
/// | 64 | 2.7e13 | 1.1e2 | 4.2e1 | 1.3e-12 | 9.5e-3 |
///
/// Bernstein -> basis -> Bernstein, `to * (from * b)` (the direction of Chebyshev
/// economisation and of degree reduction):
///
/// | n | Power | Chebyshev | Legendre | Said–Ball | Wang–Ball |
/// |---|---|---|---|---|---|
/// | 5 | 7.7e-15 | 3.0e-16 | 3.0e-16 | 1.7e-16 | 4.6e-16 |
/// | 10 | 2.7e-12 | 4.6e-16 | 3.6e-16 | 3.5e-16 | 5.9e-16 |
/// | 20 | 8.8e-8 | 4.8e-16 | 5.8e-16 | 1.9e-15 | 2.2e-14 |
/// | 30 | 5.8e-3 | 6.0e-16 | 5.7e-16 | 5.2e-15 | 8.2e-13 |
/// | 40 | 4.8e2 | 7.0e-16 | 6.9e-16 | 2.2e-14 | 1.6e-11 |
/// | 50 | 1.5e7 | 7.8e-16 | 7.8e-16 | 1.3e-13 | 3.8e-10 |
/// | 64 | 8.0e13 | 1.1e-15 | 7.9e-16 | 1.4e-12 | 7.4e-8 |
///
/// Condition numbers `|to|_inf |from|_inf` at n = 20 / 40 / 64: Power 1.3e10 / 6.6e19 /
/// 2.4e31, Chebyshev 9.5e5 / 9.9e11 / 1.7e19, Legendre 3.2e5 / 2.8e11 / 4.2e18, Said–Ball 22 /
/// 610 / 3.3e4, Wang–Ball 8.7e3 / 3.8e8 / 1.6e14. So: the power basis is usable in `f64` up to
/// degree ~10; Chebyshev and Legendre coefficients of a Bézier curve are accurate at every
/// degree, but going from given Chebyshev/Legendre coefficients to Bézier points loses
/// accuracy beyond degree ~15. Use the `_exact` matrices when exact input is at hand.
///
/// Build cost: Power, Chebyshev and Legendre use closed forms in both directions
/// (Bernstein -> Chebyshev and -> Legendre by exact orthogonality integrals); the Ball bases
/// use the closed form to Bernstein and an exact fraction-free inverse back. First call for
/// `to` + `from` at n = 64 (test profile): Power 2 ms, Chebyshev 80 ms, Legendre 65 ms,
/// Said–Ball 20 ms, Wang–Ball 55 ms, WSGB(64, 16) 60 ms; later calls are a hash-map lookup.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Basis {
    /// Monomials `t^k`, `k = 0..=n`.
    Power,
    /// Shifted Chebyshev polynomials `T_k(2t - 1)`, `T_k(x) = cos(k arccos x)`
    /// (seed 000 Lemma 14.5.3).
    Chebyshev,
    /// Shifted Legendre polynomials `P_k(2t - 1)` (`P_k(1) = 1`).
    Legendre,
    /// The Said–Ball basis, `Wsgb { l: 0 }`.
    SaidBall,
    /// The Wang–Ball basis, `Wsgb { l: max(floor(n/2) - 1, 0) }`.
    WangBall,
    /// The Wang–Said generalized Ball basis WSGB(n, L) of seed 003 (SPEC-reduce §9.1),
    /// `0 <= l <= max(floor(n/2) - 1, 0)`.
    Wsgb {
        /// The order `L` of the generalized Ball basis.
        l: usize,
    },
}

impl Basis {
    /// The basis with `SaidBall` / `WangBall` written as `Wsgb { l }` for degree `n`, after
    /// checking `n` and `l`.
    ///
    /// # Errors
    /// [`Error::DegreeOutOfRange`] for `n > MAX_DEGREE`; [`Error::ConditionNotMet`] for an
    /// `l` outside `0..=max(floor(n/2) - 1, 0)`.
    pub fn canonical(self, n: usize) -> Result<Basis> {
        check_degree(n)?;
        let b = match self {
            Basis::SaidBall => Basis::Wsgb { l: 0 },
            Basis::WangBall => Basis::Wsgb { l: wsgb_max_l(n) },
            other => other,
        };
        if let Basis::Wsgb { l } = b {
            check_wsgb(n, l)?;
        }
        Ok(b)
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum Dir {
    To,
    From,
}

type Key = (Basis, usize, Dir);
type Cell<T> = Arc<OnceLock<Result<Arc<T>>>>;
type Cache<T> = OnceLock<Mutex<HashMap<Key, Cell<T>>>>;

/// Looks up (or builds once, outside the map's lock) the value for `key`.
fn cached<T>(
    cache: &'static Cache<T>,
    key: Key,
    build: impl FnOnce() -> Result<T>,
) -> Result<Arc<T>> {
    let cell = {
        let mut map = cache
            .get_or_init(Default::default)
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        Arc::clone(map.entry(key).or_default())
    };
    cell.get_or_init(|| build().map(Arc::new)).clone()
}

fn build_exact(basis: Basis, n: usize, dir: Dir) -> Result<ExactMatrix> {
    Ok(match (basis, dir) {
        (Basis::Power, Dir::To) => power_to_bernstein(n),
        (Basis::Power, Dir::From) => power_from_bernstein(n),
        (Basis::Chebyshev, Dir::To) => chebyshev_to_bernstein(n),
        (Basis::Chebyshev, Dir::From) => chebyshev_from_bernstein(n),
        (Basis::Legendre, Dir::To) => legendre_to_bernstein(n),
        (Basis::Legendre, Dir::From) => legendre_from_bernstein(n),
        (Basis::Wsgb { l }, Dir::To) => wsgb_to_bernstein(n, l)?,
        (Basis::Wsgb { .. }, Dir::From) => exact(basis, n, Dir::To)?.inverse()?,
        (Basis::SaidBall | Basis::WangBall, _) => {
            return Err(Error::ConditionNotMet {
                eq: "internal: Basis::canonical",
                why: "Ball bases are built as Wsgb { l }",
            });
        }
    })
}

fn exact(basis: Basis, n: usize, dir: Dir) -> Result<Arc<ExactMatrix>> {
    static CACHE: Cache<ExactMatrix> = OnceLock::new();
    let basis = basis.canonical(n)?;
    cached(&CACHE, (basis, n, dir), || build_exact(basis, n, dir))
}

fn rounded(basis: Basis, n: usize, dir: Dir) -> Result<Arc<DMatrix<f64>>> {
    static CACHE: Cache<DMatrix<f64>> = OnceLock::new();
    let basis = basis.canonical(n)?;
    cached(&CACHE, (basis, n, dir), || {
        Ok(exact(basis, n, dir)?.to_f64())
    })
}

/// The exact `(n+1) x (n+1)` matrix `M` with `b = M c`: coefficients `c` in `basis` to
/// Bernstein coefficients `b` of degree `n`. Built once per `(basis, n)` and cached.
///
/// # Errors
/// [`Error::DegreeOutOfRange`] for `n > MAX_DEGREE`; [`Error::ConditionNotMet`] for a bad
/// WSGB order `l`.
pub fn to_bernstein_exact(basis: Basis, n: usize) -> Result<Arc<ExactMatrix>> {
    exact(basis, n, Dir::To)
}

/// The exact inverse of [`to_bernstein_exact`]: Bernstein coefficients to coefficients in
/// `basis`. Built once per `(basis, n)` and cached.
///
/// # Errors
/// As [`to_bernstein_exact`].
pub fn from_bernstein_exact(basis: Basis, n: usize) -> Result<Arc<ExactMatrix>> {
    exact(basis, n, Dir::From)
}

/// [`to_bernstein_exact`] with each entry rounded once to `f64`; cached.
///
/// # Errors
/// As [`to_bernstein_exact`].
pub fn to_bernstein(basis: Basis, n: usize) -> Result<Arc<DMatrix<f64>>> {
    rounded(basis, n, Dir::To)
}

/// [`from_bernstein_exact`] with each entry rounded once to `f64`; cached.
///
/// # Errors
/// As [`to_bernstein_exact`].
pub fn from_bernstein(basis: Basis, n: usize) -> Result<Arc<DMatrix<f64>>> {
    rounded(basis, n, Dir::From)
}

/// Applies a coefficient matrix to a flat row-major point buffer (`points[j*dim + d]`):
/// output point `i` is `sum_j m[(i, j)] * point_j`, coordinate by coordinate.
///
/// # Errors
/// [`Error::ZeroDimension`], [`Error::NotEnoughPoints`], [`Error::LengthMismatch`] (buffer
/// not a multiple of `dim`, or not `m.ncols()` points), [`Error::NonFinite`].
pub fn convert_points(m: &DMatrix<f64>, points: &[f64], dim: usize) -> Result<Vec<f64>> {
    let n_points = check_points(points, dim)?;
    if n_points != m.ncols() {
        return Err(Error::LengthMismatch {
            what: "convert_points (number of points must equal matrix columns)",
            got: n_points,
            expected: m.ncols(),
        });
    }
    let mut out = vec![0.0; m.nrows() * dim];
    for i in 0..m.nrows() {
        let o = &mut out[i * dim..(i + 1) * dim];
        for j in 0..n_points {
            let w = m[(i, j)];
            if w != 0.0 {
                for (x, p) in o.iter_mut().zip(&points[j * dim..(j + 1) * dim]) {
                    *x += w * p;
                }
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests;
