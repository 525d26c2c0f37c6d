//! The exact elevation matrix `E_{m->n}` of triangular Bernstein–Bézier nets
//! (SPEC-convert I.1, seed 004 eq. (2)), as integer rows over a common row denominator.
//!
//! Entry `(alpha, beta)` (rows: degree-`n` multi-indices, columns: degree-`m` ones, both in
//! the DESIGN triangle order) is `C(m; beta) C(n - m; alpha - beta) / C(n; alpha)` with the
//! trinomials `C(n; i, j, k) = n! / (i! j! k!)` (zero unless `beta <= alpha` componentwise).
//! It is the product of the one-step formula of SPEC-convert I.1,
//! `H~_ijk = (i H_{i-1,j,k} + j H_{i,j-1,k} + k H_{i,j,k-1}) / (m + 1)`, for `m -> n`.
//! Every row sums to 1; every column sums to `N_n / N_m` (`N_k = (k+1)(k+2)/2`).

use cagd_core::{ExactMatrix, binomial, tri_count};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;

use super::MAX_INTERVAL_DEGREE;
use crate::{Error, Result};

/// `C(n; i, j, n - i - j) = n! / (i! j! k!)`, exact (fits `u128` for `n <= 64`).
pub(crate) fn trinomial(n: usize, i: usize, j: usize) -> u128 {
    binomial(n, i) * binomial(n - i, j)
}

/// The multi-indices `(i, j)` of a degree-`n` net in storage order.
pub(crate) fn tri_indices(n: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..=n).flat_map(move |i| (0..=n - i).map(move |j| (i, j)))
}

/// `E_{m->n}` as integer numerators (sparse rows) over one denominator per row.
#[derive(Debug, Clone)]
pub(crate) struct IntElevation {
    /// Source degree `m`.
    pub(crate) from: usize,
    /// Target degree `n`.
    pub(crate) to: usize,
    /// For each row (degree-`to` index), the non-zero `(column, numerator)` pairs.
    pub(crate) rows: Vec<Vec<(usize, u128)>>,
    /// For each row `alpha`, its denominator `C(to; alpha)`.
    pub(crate) den: Vec<u128>,
}

impl IntElevation {
    /// `E_{from->to}`; requires `from <= to <= MAX_INTERVAL_DEGREE`.
    pub(crate) fn new(from: usize, to: usize) -> Result<Self> {
        check_pair(from, to)?;
        let d = to - from;
        let mut rows = Vec::with_capacity(tri_count(to));
        let mut den = Vec::with_capacity(tri_count(to));
        for (a1, a2) in tri_indices(to) {
            let a3 = to - a1 - a2;
            let mut row = Vec::new();
            for (col, (b1, b2)) in tri_indices(from).enumerate() {
                let b3 = from - b1 - b2;
                if b1 <= a1 && b2 <= a2 && b3 <= a3 {
                    let num = trinomial(from, b1, b2) * trinomial(d, a1 - b1, a2 - b2);
                    row.push((col, num));
                }
            }
            rows.push(row);
            den.push(trinomial(to, a1, a2));
        }
        Ok(Self {
            from,
            to,
            rows,
            den,
        })
    }

    /// Number of rows `N_to`.
    pub(crate) fn nrows(&self) -> usize {
        self.rows.len()
    }

    /// Number of columns `N_from`.
    pub(crate) fn ncols(&self) -> usize {
        tri_count(self.from)
    }

    /// The entries rounded once to `f64`, dense row-major `N_to x N_from`.
    pub(crate) fn to_f64(&self) -> Vec<f64> {
        let cols = self.ncols();
        let mut out = vec![0.0; self.nrows() * cols];
        for (r, row) in self.rows.iter().enumerate() {
            for &(c, num) in row {
                out[r * cols + c] = ratio_f64(num, self.den[r]);
            }
        }
        out
    }

    /// `E x` in `f64` (the LP's right-hand sides; not used for certification).
    pub(crate) fn apply_f64(&self, x: &[f64]) -> Vec<f64> {
        self.rows
            .iter()
            .zip(&self.den)
            .map(|(row, &den)| row.iter().map(|&(c, num)| ratio_f64(num, den) * x[c]).sum())
            .collect()
    }
}

/// `num / den` correctly rounded to `f64`.
fn ratio_f64(num: u128, den: u128) -> f64 {
    const EXACT: u128 = 1 << 53;
    if num < EXACT && den < EXACT {
        // Both operands are exact doubles, so the quotient is rounded once.
        num as f64 / den as f64
    } else {
        BigRational::new(BigInt::from(num), BigInt::from(den))
            .to_f64()
            .unwrap_or(f64::NAN)
    }
}

/// Checks a degree pair `from <= to <= MAX_INTERVAL_DEGREE`.
pub(crate) fn check_pair(from: usize, to: usize) -> Result<()> {
    if to > MAX_INTERVAL_DEGREE {
        return Err(Error::DegreeOutOfRange {
            degree: to,
            max: MAX_INTERVAL_DEGREE,
        });
    }
    if from > to {
        return Err(Error::BadDegreePair {
            from,
            to,
            why: "elevation needs from <= to",
        });
    }
    Ok(())
}

/// The elevation matrix `E_{m->n}` of triangular nets in exact rationals: rows
/// `tri_count(n)`, columns `tri_count(m)`, both in the DESIGN i-major order
/// (SPEC-convert I.1, seed 004 eq. (2); entry `C(m;beta) C(n-m;alpha-beta) / C(n;alpha)`).
///
/// # Errors
/// [`Error::BadDegreePair`] for `m > n`; [`Error::DegreeOutOfRange`] for
/// `n > MAX_INTERVAL_DEGREE`.
///
/// ```
/// let e = cagd_reduce::triangle_elevation_matrix_exact(2, 3)?;
/// assert_eq!((e.nrows(), e.ncols()), (10, 6));
/// assert_eq!(e.get(5, 1).unwrap().to_string(), "1/3"); // H~_111 = (H_011 + H_101 + H_110) / 3
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn triangle_elevation_matrix_exact(m: usize, n: usize) -> Result<ExactMatrix> {
    let e = IntElevation::new(m, n)?;
    let mut out = ExactMatrix::zeros(e.nrows(), e.ncols());
    for (r, row) in e.rows.iter().enumerate() {
        for &(c, num) in row {
            let v = BigRational::new(BigInt::from(num), BigInt::from(e.den[r]));
            out.set(r, c, v)?;
        }
    }
    Ok(out)
}

/// The elevation matrix `E_{m->n}` rounded once per entry to `f64`, row-major
/// `tri_count(n) x tri_count(m)` (see [`triangle_elevation_matrix_exact`]).
/// (SPEC-convert I.1, seed 004 Theorem 1.)
///
/// # Errors
/// As [`triangle_elevation_matrix_exact`].
pub fn triangle_elevation_matrix(m: usize, n: usize) -> Result<Vec<f64>> {
    Ok(IntElevation::new(m, n)?.to_f64())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Independent route: the product of the one-step formula of SPEC-convert I.1.
    fn stepwise(m: usize, n: usize) -> ExactMatrix {
        let mut acc = ExactMatrix::identity(tri_count(m));
        for k in m..n {
            // One step k -> k + 1: H~_ijk = (i H_{i-1,j,k} + j H_{i,j-1,k} + k H_{i,j,k-1})/(k+1).
            let step = ExactMatrix::from_fn(tri_count(k + 1), tri_count(k), |r, c| {
                let (a1, a2) = tri_indices(k + 1).nth(r).unwrap();
                let a3 = k + 1 - a1 - a2;
                let (b1, b2) = tri_indices(k).nth(c).unwrap();
                let b3 = k - b1 - b2;
                let w = if (a1, a2, a3) == (b1 + 1, b2, b3) {
                    a1
                } else if (a1, a2, a3) == (b1, b2 + 1, b3) {
                    a2
                } else if (a1, a2, a3) == (b1, b2, b3 + 1) {
                    a3
                } else {
                    0
                };
                BigRational::new(BigInt::from(w), BigInt::from(k + 1))
            });
            acc = step.mul(&acc).unwrap();
        }
        acc
    }

    #[test]
    fn closed_form_equals_product_of_steps() {
        for (m, n) in [(0, 3), (1, 4), (2, 3), (3, 4), (2, 6), (4, 7), (5, 5)] {
            assert_eq!(
                triangle_elevation_matrix_exact(m, n).unwrap(),
                stepwise(m, n),
                "{m}->{n}"
            );
        }
    }

    #[test]
    fn rows_sum_to_one_columns_to_count_ratio() {
        let (m, n) = (4, 9);
        let e = triangle_elevation_matrix_exact(m, n).unwrap();
        let one = BigRational::from_integer(1.into());
        for r in 0..e.nrows() {
            let s: BigRational = e.row(r).iter().sum();
            assert_eq!(s, one);
        }
        let t = e.transpose();
        let ratio = BigRational::new(tri_count(n).into(), tri_count(m).into());
        for c in 0..t.nrows() {
            assert_eq!(t.row(c).iter().sum::<BigRational>(), ratio);
        }
    }

    #[test]
    fn degree_64_fits_and_matches_rationals() {
        // The largest coefficients (3^64 range) in u128; spot-check rows against BigRational
        // and that every row sums to its denominator.
        let e = IntElevation::new(30, 64).unwrap();
        for (r, row) in e.rows.iter().enumerate().step_by(97) {
            let s: u128 = row.iter().map(|&(_, x)| x).sum();
            assert_eq!(s, e.den[r]);
        }
        let f = e.to_f64();
        let r = 1000;
        let s: f64 = f[r * e.ncols()..(r + 1) * e.ncols()].iter().sum();
        assert!((s - 1.0).abs() < 1e-13);
    }

    #[test]
    fn bad_pairs_are_named_errors() {
        assert!(matches!(
            triangle_elevation_matrix(3, 2),
            Err(Error::BadDegreePair { .. })
        ));
        assert!(matches!(
            triangle_elevation_matrix(3, MAX_INTERVAL_DEGREE + 1),
            Err(Error::DegreeOutOfRange { .. })
        ));
    }
}
