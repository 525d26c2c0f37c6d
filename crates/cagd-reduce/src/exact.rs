//! Exact rational matrices: every reduction operator of this crate is computed here in
//! `BigRational` arithmetic and rounded to `f64` once (SPEC-reduce §11: "closed forms in
//! exact integer/rational arithmetic; evaluate in f64 only at the end"). Exact arithmetic has
//! no conditioning problem, so no normal equations are ever formed in floating point.

use cagd_core::{Error, ExactMatrix, Result, binomial};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};

/// Exact rational number.
pub(crate) type Q = BigRational;

/// `C(n, k)` as an exact rational (`0` when `k > n` or `k < 0`).
pub(crate) fn binom_q(n: i64, k: i64) -> Q {
    if n < 0 || k < 0 || k > n {
        return Q::zero();
    }
    // n <= 2 * MAX_DEGREE + 2 everywhere in this crate: binomial() is exact.
    #[allow(clippy::cast_possible_truncation, reason = "0 <= k <= n <= 130")]
    let b = binomial(n as usize, k as usize);
    Q::from_integer(BigInt::from(b))
}

/// `a / b` for small integers.
pub(crate) fn frac(a: i64, b: i64) -> Q {
    Q::new(BigInt::from(a), BigInt::from(b))
}

/// `2^e` for `e` of any sign.
pub(crate) fn pow2(e: i64) -> Q {
    let p = BigInt::one() << e.unsigned_abs();
    if e >= 0 {
        Q::from_integer(p)
    } else {
        Q::new(BigInt::one(), p)
    }
}

/// A dense matrix of exact rationals: a thin layer over [`cagd_core::ExactMatrix`] (which
/// does the arithmetic: integer-scaled products, fraction-free solves) adding the
/// row-building and rounding helpers the operator code of this crate uses.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct RatMat(ExactMatrix);

impl RatMat {
    /// The zero matrix.
    pub(crate) fn zeros(rows: usize, cols: usize) -> Self {
        Self(ExactMatrix::zeros(rows, cols))
    }

    /// The identity.
    pub(crate) fn identity(n: usize) -> Self {
        Self(ExactMatrix::identity(n))
    }

    /// A copy of a cagd-core exact matrix.
    pub(crate) fn from_exact(m: &ExactMatrix) -> Self {
        Self(m.clone())
    }

    /// Number of rows.
    pub(crate) fn nrows(&self) -> usize {
        self.0.nrows()
    }

    /// Number of columns.
    pub(crate) fn ncols(&self) -> usize {
        self.0.ncols()
    }

    /// Entry `(i, j)` (indices are internal and in range).
    pub(crate) fn at(&self, i: usize, j: usize) -> &Q {
        &self.0[(i, j)]
    }

    /// Row `i` as a slice.
    pub(crate) fn row(&self, i: usize) -> &[Q] {
        self.0.row(i)
    }

    /// Builds a matrix from rows of equal length.
    pub(crate) fn from_rows(rows: Vec<Vec<Q>>) -> Self {
        let r = rows.len();
        let c = rows.first().map_or(0, Vec::len);
        debug_assert!(rows.iter().all(|x| x.len() == c));
        let mut it = rows.into_iter().flatten();
        Self(ExactMatrix::from_fn(r, c, |_, _| {
            it.next().unwrap_or_else(Q::zero)
        }))
    }

    /// `self * other`, exact.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] on mismatched shapes (an internal error).
    pub(crate) fn mul(&self, other: &RatMat) -> Result<RatMat> {
        self.0.mul(&other.0).map(Self)
    }

    /// `self - other`.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] on mismatched shapes (an internal error).
    pub(crate) fn sub(&self, other: &RatMat) -> Result<RatMat> {
        self.0.sub(&other.0).map(Self)
    }

    /// The transpose.
    pub(crate) fn transpose(&self) -> RatMat {
        Self(self.0.transpose())
    }

    /// Solves `self X = rhs` exactly (fraction-free Gauss–Jordan, [`ExactMatrix::solve`]).
    ///
    /// # Errors
    /// [`Error::Singular`] naming `what` when `self` is singular (never for the SPD systems
    /// of this crate); [`Error::LengthMismatch`] on mismatched shapes.
    pub(crate) fn solve(&self, rhs: &RatMat, what: &'static str) -> Result<RatMat> {
        match self.0.solve(&rhs.0) {
            Ok(x) => Ok(Self(x)),
            Err(Error::Singular { .. }) => Err(Error::Singular { what }),
            Err(e) => Err(e),
        }
    }

    /// Every entry rounded once to the nearest `f64`, row-major.
    pub(crate) fn to_f64(&self) -> Vec<f64> {
        (0..self.nrows())
            .flat_map(|i| self.row(i).iter().map(q_to_f64))
            .collect()
    }
}

/// A row vector of exact rationals: a linear functional of the input control points.
pub(crate) type Row = Vec<Q>;

/// The unit row `e_i` of length `len`.
pub(crate) fn unit(len: usize, i: usize) -> Row {
    let mut r = vec![Q::zero(); len];
    r[i] = Q::one();
    r
}

/// `a x + b y`.
pub(crate) fn lin2(a: &Q, x: &[Q], b: &Q, y: &[Q]) -> Row {
    x.iter().zip(y).map(|(u, v)| a * u + b * v).collect()
}

/// `y += a x`.
pub(crate) fn axpy(y: &mut [Q], a: &Q, x: &[Q]) {
    if a.is_zero() {
        return;
    }
    for (u, v) in y.iter_mut().zip(x) {
        if !v.is_zero() {
            *u += a * v;
        }
    }
}

/// `a x`.
pub(crate) fn scaled(a: &Q, x: &[Q]) -> Row {
    x.iter().map(|u| a * u).collect()
}

/// A rational matrix stored as an integer matrix over one common denominator.
///
/// Why it exists next to [`ExactMatrix`]: the stepwise one-degree methods compose `n - m`
/// step operators. [`ExactMatrix::mul`] rescales every row and column to integers and
/// normalises every entry (a gcd each) after each product; here the whole matrix keeps one
/// denominator, a product multiplies the two denominators, and entries are normalised once
/// at the end ([`Scaled::to_rat`]). The step operators have small denominators, so the
/// un-normalised products stay small and the composition is a pure big-integer loop.
pub(crate) struct Scaled {
    rows: usize,
    cols: usize,
    num: Vec<BigInt>,
    den: BigInt,
}

impl Scaled {
    /// The identity.
    pub(crate) fn identity(n: usize) -> Self {
        let mut num = vec![BigInt::zero(); n * n];
        for i in 0..n {
            num[i * n + i] = BigInt::one();
        }
        Self {
            rows: n,
            cols: n,
            num,
            den: BigInt::one(),
        }
    }

    /// A rational matrix over the lcm of its denominators.
    pub(crate) fn from_rat(m: &RatMat) -> Self {
        use num_integer::Integer;
        let entries = || (0..m.nrows()).flat_map(|i| m.row(i));
        let den = entries().fold(BigInt::one(), |l, x| l.lcm(x.denom()));
        let num = entries().map(|x| x.numer() * (&den / x.denom())).collect();
        Self {
            rows: m.nrows(),
            cols: m.ncols(),
            num,
            den,
        }
    }

    /// `self * other`.
    pub(crate) fn mul(&self, other: &Scaled) -> Scaled {
        let mut num = vec![BigInt::zero(); self.rows * other.cols];
        for i in 0..self.rows {
            for k in 0..self.cols {
                let a = &self.num[i * self.cols + k];
                if a.is_zero() {
                    continue;
                }
                for j in 0..other.cols {
                    let b = &other.num[k * other.cols + j];
                    if !b.is_zero() {
                        num[i * other.cols + j] += a * b;
                    }
                }
            }
        }
        Scaled {
            rows: self.rows,
            cols: other.cols,
            num,
            den: &self.den * &other.den,
        }
    }

    /// `sum_j g_j S_j`: the functional `g` of intermediate points expressed in the inputs.
    pub(crate) fn row_times(&self, g: &[Q]) -> Row {
        let gs = Scaled::from_rat(&RatMat::from_rows(vec![g.to_vec()]));
        gs.mul(self).to_rat().row(0).to_vec()
    }

    /// Back to normalised rationals.
    pub(crate) fn to_rat(&self) -> RatMat {
        RatMat(ExactMatrix::from_fn(self.rows, self.cols, |i, j| {
            Q::new(self.num[i * self.cols + j].clone(), self.den.clone())
        }))
    }
}

/// An exact rational rounded to `f64` (to nearest, up to the library's conversion).
pub(crate) fn q_to_f64(x: &Q) -> f64 {
    x.to_f64().unwrap_or(f64::NAN)
}

/// The elevation matrix from degree `m` to degree `n >= m`, `(n+1) x (m+1)`,
/// `a_ij = C(m,j) C(n-m,i-j) / C(n,i)` (SPEC-reduce §0; seed 000 eq. 14.4.4 in closed form).
pub(crate) fn elevation(m: usize, n: usize) -> RatMat {
    let (mi, ni) = (to_i(m), to_i(n));
    RatMat(ExactMatrix::from_fn(n + 1, m + 1, |i, j| {
        let (i, j) = (to_i(i), to_i(j));
        if i >= j && i - j <= ni - mi {
            binom_q(mi, j) * binom_q(ni - mi, i - j) / binom_q(ni, i)
        } else {
            Q::zero()
        }
    }))
}

/// `usize -> i64` for degrees (all <= 130).
pub(crate) fn to_i(x: usize) -> i64 {
    i64::try_from(x).unwrap_or(i64::MAX)
}

/// `i64 -> usize` for indices known to be non-negative.
pub(crate) fn idx(x: i64) -> usize {
    debug_assert!(x >= 0);
    usize::try_from(x).unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solve_and_elevation() {
        let e = elevation(1, 3);
        // Rows of the elevation matrix sum to one.
        for i in 0..4 {
            let s: Q = e.row(i).iter().sum();
            assert_eq!(s, Q::one());
        }
        let a = RatMat::from_rows(vec![
            vec![frac(2, 1), frac(1, 1)],
            vec![frac(1, 1), frac(3, 1)],
        ]);
        let x = a.solve(&RatMat::identity(2), "test").unwrap();
        assert_eq!(a.mul(&x).unwrap(), RatMat::identity(2));
        let s = RatMat::from_rows(vec![
            vec![frac(1, 1), frac(2, 1)],
            vec![frac(2, 1), frac(4, 1)],
        ]);
        assert!(s.solve(&RatMat::identity(2), "test").is_err());
        assert_eq!(pow2(-3), frac(1, 8));
        assert_eq!(binom_q(5, 7), Q::zero());
    }
}
