//! Exact binomial coefficients.
//!
//! All formulas of the seeds use `C(n, k)` for `n` up to `2 * MAX_DEGREE + 2`
//! (e.g. `C(2n, n)` in seed 000 eq. 14.2.6 and the Vandermonde forms of §14.3.2). They are
//! kept exactly in a `u128` Pascal triangle (built at compile time): the largest,
//! `C(130, 65) ≈ 9.5e37`, is below `2^128 ≈ 3.4e38`.

use crate::{Error, Result};

/// The largest polynomial degree cagd supports, in every direction of every object.
pub const MAX_DEGREE: usize = 64;

/// The largest `n` for which [`binomial`] is exact: `2 * MAX_DEGREE + 2`.
pub const MAX_BINOMIAL_N: usize = 2 * MAX_DEGREE + 2;

/// Entries of the triangle `C(n, k)`, `0 <= k <= n <= MAX_BINOMIAL_N`, row after row.
const ENTRIES: usize = (MAX_BINOMIAL_N + 1) * (MAX_BINOMIAL_N + 2) / 2;

/// The index of `C(n, 0)` in the row-after-row triangle.
const fn row_start(n: usize) -> usize {
    n * (n + 1) / 2
}

/// The Pascal triangle in `u128`, built at compile time (ADDED: it was built on first use,
/// with the rounded copy of [`binomial_f64`] 0.6 M instructions — a tenth of a small
/// `cagd reduce` process, issue 17's real-CAD-file row).
static EXACT: [u128; ENTRIES] = pascal();

/// [`EXACT`] with every value rounded once to the nearest `f64`.
static ROUNDED: [f64; ENTRIES] = rounded();

const fn pascal() -> [u128; ENTRIES] {
    let mut t = [0u128; ENTRIES];
    let mut n = 0;
    while n <= MAX_BINOMIAL_N {
        let s = row_start(n);
        t[s] = 1;
        t[s + n] = 1;
        let mut k = 1;
        while k < n {
            t[s + k] = t[row_start(n - 1) + k - 1] + t[row_start(n - 1) + k];
            k += 1;
        }
        n += 1;
    }
    t
}

const fn rounded() -> [f64; ENTRIES] {
    let exact = pascal();
    let mut t = [0.0f64; ENTRIES];
    let mut i = 0;
    while i < ENTRIES {
        t[i] = exact[i] as f64;
        i += 1;
    }
    t
}

/// `C(n, k)` exactly; `0` when `k > n`.
///
/// Callers pass `n <= MAX_BINOMIAL_N` (every degree is validated against [`MAX_DEGREE`]
/// first); a larger `n` is an internal error, checked in debug builds, and yields `0`.
/// Use [`try_binomial`] for unchecked input.
pub fn binomial(n: usize, k: usize) -> u128 {
    debug_assert!(
        n <= MAX_BINOMIAL_N,
        "binomial({n}, {k}) beyond the exact table"
    );
    if k > n || n > MAX_BINOMIAL_N {
        return 0;
    }
    EXACT[row_start(n) + k]
}

/// `C(n, k)` exactly, or [`Error::DegreeOutOfRange`] when `n > MAX_BINOMIAL_N`.
pub fn try_binomial(n: usize, k: usize) -> Result<u128> {
    if n > MAX_BINOMIAL_N {
        return Err(Error::DegreeOutOfRange {
            degree: n,
            max: MAX_BINOMIAL_N,
        });
    }
    Ok(binomial(n, k))
}

/// `C(n, k)` rounded to the nearest `f64` (exact below `2^53`), from a table of the exact
/// values each rounded once at compile time (a `u128 -> f64` conversion is a libcall, and
/// Bernstein evaluation in the fit and the bounds asks for these in inner loops); `0` when
/// `k > n` or `n` is beyond the exact table, as [`binomial`].
pub fn binomial_f64(n: usize, k: usize) -> f64 {
    if k > n || n > MAX_BINOMIAL_N {
        return 0.0;
    }
    ROUNDED[row_start(n) + k]
}

/// `(-1)^(n-i) C(n, i)`, the sign vector `c_i^(n)` of seed 000 eq. 14.1.1 / 14.2.5.
pub fn sign_binomial_f64(n: usize, i: usize) -> f64 {
    let b = binomial_f64(n, i);
    if (n - i) % 2 == 0 { b } else { -b }
}

/// Checks that `degree <= MAX_DEGREE`.
///
/// # Errors
/// [`Error::DegreeOutOfRange`] naming the supported range.
pub fn check_degree(degree: usize) -> Result<()> {
    if degree > MAX_DEGREE {
        Err(Error::DegreeOutOfRange {
            degree,
            max: MAX_DEGREE,
        })
    } else {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_values() {
        assert_eq!(binomial(0, 0), 1);
        assert_eq!(binomial(5, 2), 10);
        assert_eq!(binomial(5, 6), 0);
        assert_eq!(binomial(10, 5), 252);
    }

    #[test]
    fn central_coefficient_at_the_top_of_the_table() {
        // C(130, 65) = 95067625827960698145584333020095113100 (exact, from the product formula).
        assert_eq!(
            binomial(130, 65),
            95_067_625_827_960_698_145_584_333_020_095_113_100
        );
        // Multiplicative check of a whole row: C(n,k+1) = C(n,k) (n-k)/(k+1).
        for k in 0..120usize {
            assert_eq!(
                binomial(120, k + 1) * (k as u128 + 1),
                binomial(120, k) * (120 - k as u128)
            );
        }
    }

    /// The compile-time rounding is the run-time one: every entry of the `f64` table is
    /// its exact value converted here, and the exact table satisfies Pascal's rule.
    #[test]
    fn rounded_table_is_the_exact_one_rounded() {
        for n in 0..=MAX_BINOMIAL_N {
            for k in 0..=n {
                let exact = binomial(n, k);
                assert_eq!(
                    binomial_f64(n, k),
                    std::hint::black_box(exact) as f64,
                    "C({n}, {k})"
                );
                if n > 0 && k > 0 && k < n {
                    assert_eq!(exact, binomial(n - 1, k - 1) + binomial(n - 1, k));
                }
            }
            assert_eq!((binomial(n, 0), binomial(n, n)), (1, 1));
        }
        assert_eq!(binomial_f64(5, 6), 0.0);
        assert_eq!(binomial_f64(MAX_BINOMIAL_N + 1, 0), 0.0);
    }

    #[test]
    fn sum_of_squares_is_central() {
        // seed 000 eq. 14.2.6: sum_i (c_i^(n))^2 = C(2n, n).
        for n in 0..=MAX_DEGREE {
            let s: u128 = (0..=n).map(|i| binomial(n, i) * binomial(n, i)).sum();
            assert_eq!(s, binomial(2 * n, n));
        }
    }

    #[test]
    fn out_of_range() {
        assert_eq!(
            try_binomial(131, 3),
            Err(Error::DegreeOutOfRange {
                degree: 131,
                max: 130
            })
        );
        assert!(check_degree(64).is_ok());
        assert_eq!(
            check_degree(65),
            Err(Error::DegreeOutOfRange {
                degree: 65,
                max: 64
            })
        );
    }
}
