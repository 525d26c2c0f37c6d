//! Exact rational matrices, for building conversion and reduction operators without
//! rounding and rounding them to `f64` once (SPEC-reduce §11: "closed forms in exact
//! integer/rational arithmetic where they exist; evaluate in f64 only at the end").

use nalgebra::DMatrix;
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};

use crate::{Error, Result};

mod degeneracy;

pub use degeneracy::{curve_invariant_exact, tensor_invariants_exact, tri_invariants_exact};

/// A dense `rows x cols` matrix of exact rationals ([`BigRational`]), stored row-major.
///
/// Products and the inverse
/// work on integer-scaled rows (one common denominator per row or column), so that the inner
/// loops multiply and add big integers instead of reducing a fraction at every step.
///
/// ```
/// use cagd_core::ExactMatrix;
/// use num_rational::BigRational;
/// let a = ExactMatrix::from_fn(2, 2, |i, j| BigRational::from_integer((1 + i + 2 * j).into()));
/// let inv = a.inverse()?;
/// assert!(a.mul(&inv)?.is_identity());
/// let f = inv.to_f64(); // each entry rounded once
/// assert_eq!(f[(0, 0)], -2.0);
/// # Ok::<(), cagd_core::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct ExactMatrix {
    rows: usize,
    cols: usize,
    data: Vec<BigRational>,
}

impl ExactMatrix {
    /// The `rows x cols` zero matrix.
    pub fn zeros(rows: usize, cols: usize) -> Self {
        Self {
            rows,
            cols,
            data: vec![BigRational::zero(); rows * cols],
        }
    }

    /// The `n x n` identity.
    pub fn identity(n: usize) -> Self {
        Self::from_fn(n, n, |i, j| {
            if i == j {
                BigRational::one()
            } else {
                BigRational::zero()
            }
        })
    }

    /// The matrix with entry `f(i, j)` at row `i`, column `j`.
    pub fn from_fn(
        rows: usize,
        cols: usize,
        mut f: impl FnMut(usize, usize) -> BigRational,
    ) -> Self {
        let mut data = Vec::with_capacity(rows * cols);
        for i in 0..rows {
            for j in 0..cols {
                data.push(f(i, j));
            }
        }
        Self { rows, cols, data }
    }

    /// Number of rows.
    pub fn nrows(&self) -> usize {
        self.rows
    }

    /// Number of columns.
    pub fn ncols(&self) -> usize {
        self.cols
    }

    /// Entry `(i, j)`, or `None` outside the matrix.
    pub fn get(&self, i: usize, j: usize) -> Option<&BigRational> {
        (i < self.rows && j < self.cols).then(|| &self.data[i * self.cols + j])
    }

    /// Sets entry `(i, j)`.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] when `(i, j)` is outside the matrix.
    pub fn set(&mut self, i: usize, j: usize, value: BigRational) -> Result<()> {
        if i >= self.rows {
            return Err(Error::LengthMismatch {
                what: "ExactMatrix::set row index (must be < nrows)",
                got: i,
                expected: self.rows,
            });
        }
        if j >= self.cols {
            return Err(Error::LengthMismatch {
                what: "ExactMatrix::set column index (must be < ncols)",
                got: j,
                expected: self.cols,
            });
        }
        self.data[i * self.cols + j] = value;
        Ok(())
    }

    /// Row `i` as a slice (empty outside the matrix).
    pub fn row(&self, i: usize) -> &[BigRational] {
        if i < self.rows {
            &self.data[i * self.cols..(i + 1) * self.cols]
        } else {
            &[]
        }
    }

    /// The transpose.
    pub fn transpose(&self) -> Self {
        Self::from_fn(self.cols, self.rows, |i, j| {
            self.data[j * self.cols + i].clone()
        })
    }

    /// `true` when the matrix is square and equal to the identity.
    pub fn is_identity(&self) -> bool {
        self.rows == self.cols
            && self.data.iter().enumerate().all(|(idx, x)| {
                if idx / self.cols == idx % self.cols {
                    x.is_one()
                } else {
                    x.is_zero()
                }
            })
    }

    /// Each entry rounded once to the nearest `f64` (num-rational's correctly rounded
    /// conversion).
    pub fn to_f64(&self) -> DMatrix<f64> {
        DMatrix::from_row_iterator(
            self.rows,
            self.cols,
            self.data.iter().map(|x| x.to_f64().unwrap_or(f64::NAN)),
        )
    }

    /// The exact product `self * rhs`.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] when `self.ncols() != rhs.nrows()`.
    pub fn mul(&self, rhs: &ExactMatrix) -> Result<ExactMatrix> {
        if self.cols != rhs.rows {
            return Err(Error::LengthMismatch {
                what: "ExactMatrix::mul (rhs rows must equal lhs columns)",
                got: rhs.rows,
                expected: self.cols,
            });
        }
        // Rows of self and columns of rhs over one common denominator each, so that the
        // inner product is an integer sum.
        let left: Vec<(Vec<BigInt>, BigInt)> = (0..self.rows)
            .map(|i| scale_to_integers(self.row(i).iter()))
            .collect();
        let right: Vec<(Vec<BigInt>, BigInt)> = (0..rhs.cols)
            .map(|j| scale_to_integers((0..rhs.rows).map(|k| &rhs.data[k * rhs.cols + j])))
            .collect();
        Ok(Self::from_fn(self.rows, rhs.cols, |i, j| {
            let (a, da) = &left[i];
            let (b, db) = &right[j];
            let mut sum = BigInt::zero();
            for (x, y) in a.iter().zip(b) {
                if !x.is_zero() && !y.is_zero() {
                    sum += x * y;
                }
            }
            BigRational::new(sum, da * db)
        }))
    }

    /// The exact product `self * v` for a column vector `v`.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] when `v.len() != self.ncols()`.
    pub fn mul_vec(&self, v: &[BigRational]) -> Result<Vec<BigRational>> {
        if v.len() != self.cols {
            return Err(Error::LengthMismatch {
                what: "ExactMatrix::mul_vec (vector length must equal columns)",
                got: v.len(),
                expected: self.cols,
            });
        }
        Ok((0..self.rows)
            .map(|i| {
                self.row(i)
                    .iter()
                    .zip(v)
                    .filter(|(a, b)| !a.is_zero() && !b.is_zero())
                    .fold(BigRational::zero(), |acc, (a, b)| acc + a * b)
            })
            .collect())
    }

    /// The exact difference `self - rhs`.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] when the shapes differ.
    pub fn sub(&self, rhs: &ExactMatrix) -> Result<ExactMatrix> {
        if self.rows != rhs.rows || self.cols != rhs.cols {
            return Err(Error::LengthMismatch {
                what: "ExactMatrix::sub (shapes must be equal; number of entries)",
                got: rhs.data.len(),
                expected: self.data.len(),
            });
        }
        Ok(Self {
            rows: self.rows,
            cols: self.cols,
            data: self
                .data
                .iter()
                .zip(&rhs.data)
                .map(|(a, b)| a - b)
                .collect(),
        })
    }

    /// The exact inverse, by fraction-free Gauss–Jordan elimination ([`ExactMatrix::solve`]
    /// with the identity as right-hand side).
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] for a non-square matrix, [`Error::Singular`] for a singular one.
    pub fn inverse(&self) -> Result<ExactMatrix> {
        self.solve(&Self::identity(self.rows))
    }

    /// The exact solution `X` of `self X = rhs` (any number of right-hand-side columns), by
    /// fraction-free Gauss–Jordan elimination.
    ///
    /// Each row of `[A | B]` is scaled to integers; eliminations are integer row
    /// combinations followed by division by the row's content (gcd of its entries), so the
    /// numbers stay the size of the minors. Zero entries are skipped, which makes banded and
    /// block-triangular matrices (Ball bases) cheap. The pivot of each column is its non-zero
    /// entry with the fewest bits.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] for a non-square `self` or when `rhs.nrows() != self.nrows()`;
    /// [`Error::Singular`] for a singular `self`.
    pub fn solve(&self, rhs: &ExactMatrix) -> Result<ExactMatrix> {
        let n = self.rows;
        if self.cols != n {
            return Err(Error::LengthMismatch {
                what: "ExactMatrix::solve (matrix must be square)",
                got: self.cols,
                expected: n,
            });
        }
        if rhs.rows != n {
            return Err(Error::LengthMismatch {
                what: "ExactMatrix::solve (rhs rows must equal matrix rows)",
                got: rhs.rows,
                expected: n,
            });
        }
        let w = n + rhs.cols;
        // Row r of [S A | S B], S = diag(common denominator of row r of [A | B]):
        // (S A)^-1 (S B) = A^-1 B.
        let mut rows: Vec<Vec<BigInt>> = (0..n)
            .map(|r| {
                let (ints, _) = scale_to_integers(self.row(r).iter().chain(rhs.row(r)));
                debug_assert_eq!(ints.len(), w);
                ints
            })
            .collect();
        for p in 0..n {
            // Pivot: the non-zero entry of column p with the fewest bits, among rows >= p.
            let pivot = (p..n)
                .filter(|&r| !rows[r][p].is_zero())
                .min_by_key(|&r| rows[r][p].bits())
                .ok_or(Error::Singular {
                    what: "ExactMatrix::solve",
                })?;
            rows.swap(p, pivot);
            let (before, rest) = rows.split_at_mut(p);
            let (prow, after) = rest.split_at_mut(1);
            let prow = &prow[0];
            for row in before.iter_mut().chain(after.iter_mut()) {
                if row[p].is_zero() {
                    continue;
                }
                let g = prow[p].gcd(&row[p]);
                let fp = &prow[p] / &g; // multiplies row
                let fr = &row[p] / &g; // multiplies prow
                for (x, y) in row.iter_mut().zip(prow.iter()) {
                    let scaled = if fp.is_one() { x.clone() } else { &*x * &fp };
                    *x = if y.is_zero() {
                        scaled
                    } else {
                        scaled - &fr * y
                    };
                }
                remove_content(row);
            }
        }
        Ok(Self::from_fn(n, rhs.cols, |i, j| {
            BigRational::new(rows[i][n + j].clone(), rows[i][i].clone())
        }))
    }
}

impl core::ops::Index<(usize, usize)> for ExactMatrix {
    type Output = BigRational;

    /// Entry `(i, j)`; panics outside the matrix like any slice index (use [`ExactMatrix::get`]
    /// for a checked access).
    fn index(&self, (i, j): (usize, usize)) -> &BigRational {
        assert!(
            i < self.rows && j < self.cols,
            "ExactMatrix index out of range"
        );
        &self.data[i * self.cols + j]
    }
}

/// Integers `x_k * D` and the least common denominator `D` of a sequence of rationals.
fn scale_to_integers<'a>(
    xs: impl Iterator<Item = &'a BigRational> + Clone,
) -> (Vec<BigInt>, BigInt) {
    let den = xs.clone().fold(BigInt::one(), |acc, x| {
        if x.denom().is_one() {
            acc
        } else {
            acc.lcm(x.denom())
        }
    });
    let ints = xs
        .map(|x| {
            if x.is_zero() {
                BigInt::zero()
            } else if x.denom() == &den {
                x.numer().clone()
            } else {
                x.numer() * (&den / x.denom())
            }
        })
        .collect();
    (ints, den)
}

/// Divides an integer row by the gcd of its entries (its content). Signs are left alone:
/// the final division by the diagonal restores them.
fn remove_content(row: &mut [BigInt]) {
    let mut g = BigInt::zero();
    for x in row.iter().filter(|x| !x.is_zero()) {
        g = g.gcd(x);
        if g.is_one() {
            return;
        }
    }
    if g.is_zero() || g.is_one() {
        return;
    }
    for x in row.iter_mut().filter(|x| !x.is_zero()) {
        *x /= &g;
    }
}

#[cfg(test)]
mod tests;
