//! Degeneracy of a WSGB(n, L) curve: its leading coefficient (SPEC-reduce §9.2, seed 003
//! eq. (4) reconstructed), the exact degeneracy test, and the exact inverse elevation
//! WSGB(n, L) -> WSGB(n-1, L') of a degenerate curve (SPEC-reduce §9.3 with its erratum).

use num_rational::BigRational;
use num_traits::Zero;

use super::scalar::{WsgbScalar, to_exact_points};
use super::{WsgbCurve, check_wsgb_order};
use crate::{Error, Result, binomial, wsgb_max_l};

/// The scalar factor of the leading coefficient (SPEC-reduce §9.2), with `m = floor(n/2)`:
/// `K = 2^L C(2m-2L, m-L)` for odd `n`, `K' = 2^L C(2m-2L-1, m-L-1)` for even `n >= 2`, and
/// its sign `(-1)^m` (odd) / `(-1)^(m+1)` (even). For `n = 0` the curve is the constant
/// `p_0`: factor 1, sign +1.
///
/// Returns `(sign, factor)`. Callers check `n` and `l` first.
pub fn wsgb_lec_factor(n: usize, l: usize) -> (i8, u128) {
    let m = n / 2;
    if n == 0 {
        return (1, 1);
    }
    if n % 2 == 1 {
        let k = (1u128 << l) * binomial(2 * m - 2 * l, m - l);
        (if m % 2 == 0 { 1 } else { -1 }, k)
    } else {
        let k = (1u128 << l) * binomial(2 * m - 2 * l - 1, m - l - 1);
        (if (m + 1) % 2 == 0 { 1 } else { -1 }, k)
    }
}

/// The "difference" `D` whose vanishing is degeneracy (SPEC-reduce §9.2): `Delta p_m =
/// p_{m+1} - p_m` for `n = 2m+1`, `Delta^2 p_{m-1} = p_{m-1} - 2 p_m + p_{m+1}` for
/// `n = 2m >= 2`. `points` is flat with `n + 1` points of `dim` coordinates.
pub fn wsgb_lec_difference<S: WsgbScalar>(points: &[S], dim: usize) -> Vec<S> {
    let n = points.len() / dim - 1;
    let m = n / 2;
    let at = |i: usize, d: usize| points[i * dim + d].clone();
    (0..dim)
        .map(|d| {
            if n == 0 {
                at(0, d)
            } else if n % 2 == 1 {
                at(m + 1, d) - at(m, d)
            } else {
                at(m - 1, d) - S::from_int(2) * at(m, d) + at(m + 1, d)
            }
        })
        .collect()
}

/// The coefficient of `u^n` of the WSGB(n, L) curve with flat points `points`
/// (SPEC-reduce §9.2): `lec = (-1)^m K Delta p_m` (n = 2m+1),
/// `lec = (-1)^(m+1) K' Delta^2 p_{m-1}` (n = 2m). Exact for `BigRational`, a few ulp for
/// `f64`.
///
/// # Errors
/// [`Error::DegreeOutOfRange`], [`Error::BadParameter`] (bad `l`), [`Error::LengthMismatch`]
/// (buffer not `n + 1` points of `dim`).
pub fn wsgb_leading_coefficient<S: WsgbScalar>(
    points: &[S],
    dim: usize,
    l: usize,
) -> Result<Vec<S>> {
    let n = count(points.len(), dim)? - 1;
    check_wsgb_order(n, l)?;
    let (sign, k) = wsgb_lec_factor(n, l);
    let f = S::from_int(i128::from(sign)) * S::from_uint(k);
    Ok(wsgb_lec_difference(points, dim)
        .into_iter()
        .map(|x| f.clone() * x)
        .collect())
}

fn count(len: usize, dim: usize) -> Result<usize> {
    if dim == 0 {
        return Err(Error::ZeroDimension);
    }
    if len == 0 || len % dim != 0 {
        return Err(Error::LengthMismatch {
            what: "WSGB points (length must be a positive multiple of dim)",
            got: len,
            expected: (len / dim).max(1) * dim,
        });
    }
    Ok(len / dim)
}

/// The order `L'` of the degree-`n-1` curve a degree-`n` WSGB(n, L) curve reduces to
/// (SPEC-reduce §9.3): `L' = min(L, max(floor((n-1)/2) - 1, 0))`.
pub fn wsgb_reduced_order(n: usize, l: usize) -> usize {
    l.min(wsgb_max_l(n.saturating_sub(1)))
}

/// The exact inverse elevation of SPEC-reduce §9.3 (seed 003 Lemma 3, with the erratum for
/// `1 <= L <= m - 2`): the WSGB(n-1, L') points `q` of a *degenerate* WSGB(n, L) curve with
/// points `p` (flat, `dim` coordinates), `L' =` [`wsgb_reduced_order`]`(n, L)`:
///
/// * `n = 2m+1`: `q_i = p_i` (i <= m), `q_i = p_{i+1}` (i = m+1..2m);
/// * `n = 2m`: for `i = 0..m-1`, `q_i = p_i` if `i < L`, else
///   `q_i = ((m+i-2L) p_i - (i-L) p_{i-1}) / (m-L)`, and the mirror
///   `q_{2m-1-i} = ((m+i-2L) p_{2m-i} - (i-L) p_{2m-i+1}) / (m-L)`.
///
/// For a non-degenerate `p` this is still a well-defined linear map (the reducers apply it
/// to points that are degenerate in exact arithmetic); [`WsgbCurve::inverse_elevate`]
/// checks degeneracy first. Needs `n >= 1`.
///
/// # Errors
/// [`Error::DegreeOutOfRange`] / [`Error::BadParameter`] / [`Error::LengthMismatch`] as
/// [`wsgb_leading_coefficient`]; [`Error::BadDegreePair`] for `n = 0`.
pub fn wsgb_inverse_elevation<S: WsgbScalar>(points: &[S], dim: usize, l: usize) -> Result<Vec<S>> {
    let n = count(points.len(), dim)? - 1;
    check_wsgb_order(n, l)?;
    if n == 0 {
        return Err(Error::BadDegreePair {
            from: 0,
            to: 0,
            why: "a degree-0 curve has no lower degree",
        });
    }
    let m = n / 2;
    let p = |i: usize, d: usize| points[i * dim + d].clone();
    let mut q: Vec<S> = vec![S::zero(); n * dim];
    if n % 2 == 1 {
        for i in 0..n {
            let src = if i <= m { i } else { i + 1 };
            for d in 0..dim {
                q[i * dim + d] = p(src, d);
            }
        }
        return Ok(q);
    }
    let den = S::from_uint((m - l) as u128);
    for i in 0..m {
        for d in 0..dim {
            let (a, b) = if i < l {
                (p(i, d), p(n - i, d))
            } else {
                let c1 = S::from_uint((m + i - 2 * l) as u128);
                let c2 = S::from_uint((i - l) as u128);
                let a = (c1.clone() * p(i, d)
                    - if i > l {
                        c2.clone() * p(i - 1, d)
                    } else {
                        S::zero()
                    })
                    / den.clone();
                let b = (c1 * p(n - i, d)
                    - if i > l {
                        c2 * p(n - i + 1, d)
                    } else {
                        S::zero()
                    })
                    / den.clone();
                (a, b)
            };
            q[i * dim + d] = a;
            q[(n - 1 - i) * dim + d] = b;
        }
    }
    Ok(q)
}

impl WsgbCurve {
    /// The leading coefficient `lec` (coefficient of `u^n`, SPEC-reduce §9.2), in `f64`.
    pub fn leading_coefficient(&self) -> Vec<f64> {
        wsgb_leading_coefficient(self.points(), self.dim(), self.order()).unwrap_or_default()
    }

    /// Whether the curve is exactly of degree `< n` (SPEC-reduce §9.2): `Delta p_m = 0`
    /// (odd `n`) or `Delta^2 p_{m-1} = 0` (even `n`), tested in exact arithmetic on the
    /// `f64` points. A degree-0 curve is not degenerate.
    pub fn is_degenerate(&self) -> bool {
        if self.degree() == 0 {
            return false;
        }
        let exact = to_exact_points(self.points());
        wsgb_lec_difference::<BigRational>(&exact, self.dim())
            .iter()
            .all(Zero::is_zero)
    }

    /// The exact inverse elevation (SPEC-reduce §9.3) of a degenerate curve: the
    /// WSGB(n-1, L') curve, `L' =` [`wsgb_reduced_order`]`(n, L)`, equal to this one. Computed in
    /// exact arithmetic and rounded once.
    ///
    /// # Errors
    /// [`Error::ConditionNotMet`] if the curve is not degenerate ([`WsgbCurve::is_degenerate`]),
    /// [`Error::BadDegreePair`] for `n = 0`.
    pub fn inverse_elevate(&self) -> Result<WsgbCurve> {
        if self.degree() == 0 {
            return Err(Error::BadDegreePair {
                from: 0,
                to: 0,
                why: "a degree-0 curve has no lower degree",
            });
        }
        if !self.is_degenerate() {
            return Err(Error::ConditionNotMet {
                eq: "SPEC-reduce §9.2 (seed 003 eq. (4))",
                why: "the curve is not degenerate: its leading coefficient is not zero",
            });
        }
        let exact = to_exact_points(self.points());
        let q = wsgb_inverse_elevation(&exact, self.dim(), self.order())?;
        WsgbCurve::new(
            super::scalar::round_exact_points(&q),
            self.dim(),
            wsgb_reduced_order(self.degree(), self.order()),
        )
    }
}
