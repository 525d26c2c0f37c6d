//! Certified containment (SPEC-convert I.2, post-processing): exact comparisons of
//! `E_{m->N} x` with `E_{n->N} f` on the stored doubles, and the outward repair.
//!
//! Method (documented choice: exact arithmetic, not directed rounding). Row `alpha` of both
//! `E_{m->N}` and `E_{n->N}` has the denominator `C(N; alpha)`, so
//! `(E_{m->N} x)_alpha <= (E_{n->N} f)_alpha` is the comparison of two sums of
//! *integer x double* products. A fast filter evaluates the difference in `f64` with the
//! rigorous dot-product bound `gamma_k sum |a_i x_i|` (Higham, Accuracy and Stability, §3.1)
//! plus an underflow allowance; a row that the filter cannot decide is decided exactly by
//! writing every double as `mantissa * 2^exponent` and summing in `BigInt`. Nothing here
//! trusts a rounded value.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_traits::{Signed, Zero};

use super::MAX_INTERVAL_DEGREE;
use super::elevation::IntElevation;
use crate::{Error, Result};

/// Which bound a column is: the lower net must stay below, the upper net above.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Side {
    /// `E_out x <= E_in f`.
    Lower,
    /// `E_out x >= E_in f`.
    Upper,
}

/// The containment degree `N` for an input of degree `n` (`None` = `n`).
pub(crate) fn containment_degree_of(n: usize, asked: Option<usize>) -> Result<usize> {
    let big = asked.unwrap_or(n);
    if big < n {
        return Err(Error::BadDegreePair {
            from: n,
            to: big,
            why: "the containment degree N must be >= the input degree n",
        });
    }
    if big > MAX_INTERVAL_DEGREE {
        return Err(Error::DegreeOutOfRange {
            degree: big,
            max: MAX_INTERVAL_DEGREE,
        });
    }
    Ok(big)
}

/// The pair of elevations `E_{m->N}` (outer net) and `E_{n->N}` (inner net) with rows of a
/// common denominator.
#[derive(Debug)]
pub(crate) struct Containment<'a> {
    pub(crate) outer: &'a IntElevation,
    pub(crate) inner: &'a IntElevation,
}

impl Containment<'_> {
    /// Whether `E_out x <= E_in f` (`Lower`) or `>=` (`Upper`) holds in every row, exactly.
    pub(crate) fn holds(&self, x: &[f64], f: &[f64], side: Side) -> bool {
        debug_assert_eq!(self.outer.to, self.inner.to);
        (0..self.outer.nrows()).all(|r| {
            let ord = row_cmp(&self.outer.rows[r], x, &self.inner.rows[r], f);
            match side {
                Side::Lower => ord != Ordering::Greater,
                Side::Upper => ord != Ordering::Less,
            }
        })
    }

    /// An `f64` estimate of the largest violation in model units:
    /// `max_alpha (E_out x - E_in f)_alpha` (`Lower`) or `(E_in f - E_out x)` (`Upper`).
    pub(crate) fn violation_f64(&self, x: &[f64], f: &[f64], side: Side) -> f64 {
        let ex = self.outer.apply_f64(x);
        let ef = self.inner.apply_f64(f);
        ex.iter()
            .zip(&ef)
            .map(|(a, b)| match side {
                Side::Lower => a - b,
                Side::Upper => b - a,
            })
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// The rows that fail, decided exactly.
    fn failing_rows(&self, x: &[f64], f: &[f64], side: Side) -> Vec<usize> {
        (0..self.outer.nrows())
            .filter(|&r| {
                let ord = row_cmp(&self.outer.rows[r], x, &self.inner.rows[r], f);
                match side {
                    Side::Lower => ord == Ordering::Greater,
                    Side::Upper => ord == Ordering::Less,
                }
            })
            .collect()
    }

    /// Moves `x` outward until [`Containment::holds`]; returns the largest shift applied (0
    /// when it already held). SPEC-convert I.2 post-processing (1): rows of `E` sum to 1 and
    /// `E >= 0`, so shifting every column in the support of a failing row by `delta` moves
    /// that row by exactly `delta` and every other row only in the safe direction. Only those
    /// columns move (the spec's uniform shift restricted to where it is needed), by the
    /// estimated violation plus one rounding unit, doubled until the failing rows hold.
    ///
    /// # Errors
    /// [`Error::NotCertified`] if 200 doublings do not certify (cannot happen for finite
    /// data; reported, never hidden).
    pub(crate) fn repair(&self, x: &mut Vec<f64>, f: &[f64], side: Side) -> Result<f64> {
        let scale = x.iter().chain(f).fold(0.0_f64, |m, v| m.max(v.abs()));
        let ulp = (scale * f64::EPSILON).max(f64::MIN_POSITIVE);
        let mut shift = 0.0_f64;
        for _ in 0..64 {
            let failing = self.failing_rows(x, f, side);
            if failing.is_empty() {
                return Ok(shift);
            }
            let mut cols = vec![false; x.len()];
            for &r in &failing {
                for &(c, _) in &self.outer.rows[r] {
                    cols[c] = true;
                }
            }
            let estimate = self.violation_f64(x, f, side).max(0.0);
            let mut delta = estimate + ulp;
            let mut moved = false;
            for _ in 0..200 {
                let cand: Vec<f64> = x
                    .iter()
                    .zip(&cols)
                    .map(|(&v, &m)| match (m, side) {
                        (false, _) => v,
                        (true, Side::Lower) => v - delta,
                        (true, Side::Upper) => v + delta,
                    })
                    .collect();
                let fixed = failing.iter().all(|&r| {
                    let ord = row_cmp(&self.outer.rows[r], &cand, &self.inner.rows[r], f);
                    match side {
                        Side::Lower => ord != Ordering::Greater,
                        Side::Upper => ord != Ordering::Less,
                    }
                });
                if cand.iter().all(|v| v.is_finite()) && fixed {
                    *x = cand;
                    shift = shift.max(delta);
                    moved = true;
                    break;
                }
                delta *= 2.0;
            }
            if !moved {
                break;
            }
        }
        Err(Error::NotCertified {
            what: "interval reduction (outward repair)",
            residual: self.violation_f64(x, f, side),
        })
    }
}

/// Exact comparison of `sum a_i x_i` with `sum b_j f_j` (integer `a`, `b`; finite doubles).
fn row_cmp(a: &[(usize, u128)], x: &[f64], b: &[(usize, u128)], f: &[f64]) -> Ordering {
    if let Some(ord) = row_cmp_filter(a, x, b, f) {
        return ord;
    }
    row_cmp_exact(a, x, b, f)
}

/// The `f64` filter: `Some(ordering)` when the rounded difference is farther from 0 than
/// its rigorous error bound, `None` otherwise.
fn row_cmp_filter(
    a: &[(usize, u128)],
    x: &[f64],
    b: &[(usize, u128)],
    f: &[f64],
) -> Option<Ordering> {
    const EXACT: u128 = 1 << 53;
    let k = a.len() + b.len();
    let mut s = 0.0;
    let mut mag = 0.0;
    for (coefs, vals, sign) in [(a, x, 1.0), (b, f, -1.0)] {
        for &(i, c) in coefs {
            if c >= EXACT {
                return None; // the coefficient itself would be rounded
            }
            let p = c as f64 * vals[i];
            s += sign * p;
            mag += p.abs();
        }
    }
    // |fl(sum) - sum| <= gamma_k * sum |a_i x_i| with gamma_k = k u / (1 - k u), u = 2^-53
    // (products included); doubled to cover the rounding of `mag` itself, plus k subnormal
    // steps for underflowing products.
    let u = f64::EPSILON / 2.0;
    let ku = (k as f64 + 2.0) * u;
    let bound = 2.0 * ku / (1.0 - ku) * mag + (k as f64 + 2.0) * f64::from_bits(1);
    if !(s.is_finite() && bound.is_finite()) {
        return None;
    }
    if s > bound {
        Some(Ordering::Greater)
    } else if s < -bound {
        Some(Ordering::Less)
    } else {
        None
    }
}

/// `x = m * 2^e` exactly (`m` signed, `|m| < 2^54`).
fn decode(x: f64) -> (i64, i32) {
    let bits = x.to_bits();
    let sign = if bits >> 63 == 0 { 1 } else { -1 };
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let frac = bits & 0x000f_ffff_ffff_ffff;
    let m = if exp == 0 {
        frac << 1
    } else {
        frac | 0x0010_0000_0000_0000
    };
    (sign * m as i64, exp - 1075)
}

/// Exact comparison in `BigInt` (every double as `m * 2^e`, shifted to the smallest `e`).
fn row_cmp_exact(a: &[(usize, u128)], x: &[f64], b: &[(usize, u128)], f: &[f64]) -> Ordering {
    let mut terms: Vec<(BigInt, i32)> = Vec::with_capacity(a.len() + b.len());
    for (coefs, vals, neg) in [(a, x, false), (b, f, true)] {
        for &(i, c) in coefs {
            let (m, e) = decode(vals[i]);
            if m == 0 || c == 0 {
                continue;
            }
            let t = BigInt::from(c) * BigInt::from(m);
            terms.push((if neg { -t } else { t }, e));
        }
    }
    let Some(e_min) = terms.iter().map(|t| t.1).min() else {
        return Ordering::Equal;
    };
    let mut acc = BigInt::zero();
    for (t, e) in terms {
        // e - e_min <= 2098 (the double exponent range), so the shift is bounded.
        acc += t << usize::try_from(e - e_min).unwrap_or(0);
    }
    if acc.is_zero() {
        Ordering::Equal
    } else if acc.is_positive() {
        Ordering::Greater
    } else {
        Ordering::Less
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exact(a: &[(usize, u128)], x: &[f64], b: &[(usize, u128)], f: &[f64]) -> Ordering {
        row_cmp_exact(a, x, b, f)
    }

    #[test]
    fn decode_is_exact() {
        for x in [
            1.0,
            -0.1,
            3.5e-310,
            -1e300,
            f64::MIN_POSITIVE,
            0.0,
            123456.789,
        ] {
            let (m, e) = decode(x);
            let two = num_rational::BigRational::from_integer(2.into());
            let scale = if e >= 0 {
                two.pow(e)
            } else {
                two.pow(-e).recip()
            };
            let got = num_rational::BigRational::from_integer(m.into()) * scale;
            assert_eq!(Some(got), num_rational::BigRational::from_float(x), "{x}");
        }
    }

    #[test]
    fn exact_comparison_sees_one_ulp() {
        // 3 * 0.1 (the double) vs 0.30000000000000004 and vs 0.3: decided exactly.
        let a = [(0, 3u128)];
        let tenth = [0.1];
        // 3 * fl(0.1) = 0.3000000000000000166..., fl(0.3) = 0.299999999999999988...
        assert_eq!(exact(&a, &tenth, &[(0, 1)], &[0.3]), Ordering::Greater);
        assert_eq!(
            exact(&a, &tenth, &[(0, 1)], &[0.30000000000000004]),
            Ordering::Less
        );
        assert_eq!(exact(&[(0, 2)], &[0.5], &[(0, 1)], &[1.0]), Ordering::Equal);
        // The filter never contradicts the exact answer.
        for (x, y) in [
            (0.1, 0.3),
            (0.1, 0.30000000000000004),
            (1e-300, 3e-300),
            (5.0, 15.0),
        ] {
            let e = exact(&a, &[x], &[(0, 1)], &[y]);
            if let Some(o) = row_cmp_filter(&a, &[x], &[(0, 1)], &[y]) {
                assert_eq!(o, e, "{x} {y}");
            }
        }
    }

    #[test]
    fn containment_degree_rules() {
        assert_eq!(containment_degree_of(4, None), Ok(4));
        assert_eq!(containment_degree_of(4, Some(9)), Ok(9));
        assert!(matches!(
            containment_degree_of(4, Some(3)),
            Err(Error::BadDegreePair { .. })
        ));
        assert!(matches!(
            containment_degree_of(4, Some(MAX_INTERVAL_DEGREE + 1)),
            Err(Error::DegreeOutOfRange { .. })
        ));
    }
}
