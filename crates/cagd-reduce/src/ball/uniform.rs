//! The best uniform approximation of seed 003 §2.2 (SPEC-reduce §9.5): one degree
//! `n -> n-1`.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use num_bigint::BigInt;
use num_rational::BigRational;

use cagd_core::{
    Basis, Result, WsgbScalar, binomial, check_wsgb_order, from_bernstein_exact,
    round_exact_points, wsgb_inverse_elevation, wsgb_leading_coefficient,
};

/// The WSGB(n, L) coefficients `g` of `T_n(2u-1)` (SPEC-reduce §9.5): `g = D^-1 alpha`, `D`
/// the exact WSGB -> Bernstein matrix (§9.1), `alpha_i = (-1)^(n-i) C(2n, 2i) / C(n, i)` the
/// Bernstein coefficients of `T_n(2u-1)` (seed 003 Lemma 2). Exact.
///
/// # Errors
/// [`cagd_core::Error::DegreeOutOfRange`], [`cagd_core::Error::BadParameter`] (bad `l`).
pub fn wsgb_chebyshev_coefficients(n: usize, l: usize) -> Result<Vec<BigRational>> {
    check_wsgb_order(n, l)?;
    let alpha: Vec<BigRational> = (0..=n)
        .map(|i| {
            let v = BigRational::new(
                BigInt::from(binomial(2 * n, 2 * i)),
                BigInt::from(binomial(n, i)),
            );
            if (n - i) % 2 == 0 { v } else { -v }
        })
        .collect();
    from_bernstein_exact(Basis::Wsgb { l }, n)?.mul_vec(&alpha)
}

/// [`wsgb_chebyshev_coefficients`] rounded once to `f64`, cached per `(n, l)`.
pub(crate) fn chebyshev_coefficients_f64(n: usize, l: usize) -> Result<Arc<Vec<f64>>> {
    type Cache = OnceLock<Mutex<HashMap<(usize, usize), Arc<Vec<f64>>>>>;
    static CACHE: Cache = OnceLock::new();
    let cache = CACHE.get_or_init(Default::default);
    if let Some(v) = cache
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .get(&(n, l))
    {
        return Ok(Arc::clone(v));
    }
    let g = Arc::new(round_exact_points(&wsgb_chebyshev_coefficients(n, l)?));
    cache
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .insert((n, l), Arc::clone(&g));
    Ok(g)
}

/// The points `phat_i = p_i - g_i lec / 2^(2n-1)` (SPEC-reduce §9.5, seed 003 §2.2): the
/// curve minus `lec T_n(2u-1) / 2^(2n-1)`, which is degenerate. `g` from
/// [`wsgb_chebyshev_coefficients`] (in the same scalar type). Exact for `BigRational`.
///
/// # Errors
/// As [`cagd_core::wsgb_leading_coefficient`].
pub fn wsgb_uniform_points<S: WsgbScalar>(
    points: &[S],
    dim: usize,
    l: usize,
    g: &[S],
) -> Result<Vec<S>> {
    let n = super::degree_of(points.len(), dim)?;
    let lec = wsgb_leading_coefficient(points, dim, l)?;
    let scale = S::from_uint(1u128 << (2 * n).saturating_sub(1).min(127));
    let scale = if n == 0 { S::one() } else { scale };
    let c: Vec<S> = lec.into_iter().map(|x| x / scale.clone()).collect();
    let mut q = points.to_vec();
    for (i, gi) in g.iter().enumerate().take(n + 1) {
        for (d, cd) in c.iter().enumerate() {
            q[i * dim + d] = q[i * dim + d].clone() - gi.clone() * cd.clone();
        }
    }
    Ok(q)
}

/// One best-uniform step WSGB(n, L) -> WSGB(n-1, L'), exact for `BigRational`:
/// [`wsgb_uniform_points`] then the exact inverse elevation. Needs `n >= 1`.
/// (SPEC-reduce §9.5, error formula (12).)
///
/// # Errors
/// [`cagd_core::Error::BadDegreePair`] for `n = 0`, [`cagd_core::Error::BadParameter`] for
/// a bad `l`, buffer errors.
pub fn wsgb_uniform_step_exact(
    points: &[BigRational],
    dim: usize,
    l: usize,
) -> Result<Vec<BigRational>> {
    let n = super::degree_of(points.len(), dim)?;
    check_wsgb_order(n, l)?;
    let g = wsgb_chebyshev_coefficients(n, l)?;
    let hat = wsgb_uniform_points(points, dim, l, &g)?;
    wsgb_inverse_elevation(&hat, dim, l)
}

/// The `f64` form of [`wsgb_uniform_step_exact`] (cached `g` rounded once). Returns the
/// reduced points and `max_i |g_i|`.
pub(crate) fn uniform_step_f64(points: &[f64], dim: usize, l: usize) -> Result<(Vec<f64>, f64)> {
    let n = super::degree_of(points.len(), dim)?;
    check_wsgb_order(n, l)?;
    let g = chebyshev_coefficients_f64(n, l)?;
    let hat = wsgb_uniform_points(points, dim, l, &g)?;
    let gmax = g.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    Ok((wsgb_inverse_elevation(&hat, dim, l)?, gmax))
}
