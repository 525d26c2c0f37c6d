//! The perturbation method of seed 003 §2.1 (SPEC-reduce §9.4): one degree `n -> n-1`.

use cagd_core::kernel::powu;
use cagd_core::{
    Error, Result, WsgbScalar, binomial, check_wsgb_order, wsgb_inverse_elevation,
    wsgb_lec_difference,
};

/// The points `p + eps` of the least perturbation (`min sum ||eps_i||^2`) that makes the
/// WSGB(n, L) curve with flat points `points` degenerate (SPEC-reduce §9.4):
///
/// * `n = 2m+1`: `eps_m = D/2`, `eps_{m+1} = -D/2`, `D = p_{m+1} - p_m` (so both become
///   `(p_m + p_{m+1})/2`);
/// * `n = 2m`: `eps_{m-1} = eps_{m+1} = -F/6`, `eps_m = F/3`, `F = p_{m-1} - 2p_m + p_{m+1}`.
///
/// Only the middle points move. Exact for `BigRational`.
///
/// # Errors
/// [`Error::BadDegreePair`] for `n < 2`; [`Error::LengthMismatch`] /
/// [`Error::ZeroDimension`] for a bad buffer.
pub fn wsgb_perturbed_points<S: WsgbScalar>(points: &[S], dim: usize) -> Result<Vec<S>> {
    let n = super::degree_of(points.len(), dim)?;
    if n < 2 {
        return Err(Error::BadDegreePair {
            from: n,
            to: n.saturating_sub(1),
            why: "the WSGB perturbation method needs n >= 2 (SPEC-reduce §9.4)",
        });
    }
    let m = n / 2;
    let diff = wsgb_lec_difference(points, dim);
    let mut q = points.to_vec();
    for (d, f) in diff.iter().enumerate() {
        if n % 2 == 1 {
            let half = f.clone() / S::from_int(2);
            q[m * dim + d] = q[m * dim + d].clone() + half.clone();
            q[(m + 1) * dim + d] = q[(m + 1) * dim + d].clone() - half;
        } else {
            let sixth = f.clone() / S::from_int(6);
            q[(m - 1) * dim + d] = q[(m - 1) * dim + d].clone() - sixth.clone();
            q[m * dim + d] = q[m * dim + d].clone() + S::from_int(2) * sixth.clone();
            q[(m + 1) * dim + d] = q[(m + 1) * dim + d].clone() - sixth;
        }
    }
    Ok(q)
}

/// One perturbation step WSGB(n, L) -> WSGB(n-1, L'): [`wsgb_perturbed_points`] then the
/// exact inverse elevation ([`cagd_core::wsgb_inverse_elevation`]). Exact for `BigRational`.
/// (SPEC-reduce §9.4, with the §9.3 inverse elevation.)
///
/// # Errors
/// As [`wsgb_perturbed_points`], and [`Error::BadParameter`] for `l` out of range.
pub fn wsgb_perturbation_step<S: WsgbScalar>(points: &[S], dim: usize, l: usize) -> Result<Vec<S>> {
    let n = super::degree_of(points.len(), dim)?;
    check_wsgb_order(n, l)?;
    let pert = wsgb_perturbed_points(points, dim)?;
    wsgb_inverse_elevation(&pert, dim, l)
}

/// `phi` with `max_u ||r(u) - q(u)|| = phi ||D||` for one perturbation step (any norm; the
/// error curve is `D` times a scalar polynomial), SPEC-reduce §9.4:
///
/// * `n = 2m+1`: the error is `(K/2) D (u(1-u))^m (1-2u)`, maximal at `(1-2u)^2 = 1/(2m+1)`:
///   `phi = (K/2) (m/(4m+2))^m / sqrt(2m+1)`;
/// * `n = 2m`: the error is `(K'/6) F w^(m-1) (6w - 1)`, `w = u(1-u) in [0, 1/4]`:
///   `phi = K'/(3 4^m)` (at `u = 1/2`) for `m >= 2`, `phi = K'/6` (at the ends) for `m = 1`.
///
/// `K, K'` as [`cagd_core::wsgb_lec_factor`]. Needs `n >= 2`.
pub fn wsgb_perturbation_error_factor(n: usize, l: usize) -> f64 {
    let (_, k) = cagd_core::wsgb_lec_factor(n, l);
    let k = k as f64;
    let m = n / 2;
    if n % 2 == 1 {
        let mf = m as f64;
        0.5 * k * powu(mf / (4.0 * mf + 2.0), m) / (2.0 * mf + 1.0).sqrt()
    } else if m == 1 {
        k / 6.0
    } else {
        k / (3.0 * powu(4.0, m))
    }
}

/// The paper's bound (11) for one step, `2^L C(2m-2L, m-L) ||D|| / 4^m` with `m =
/// floor(n/2)`, given `||D||` in the norm wanted (seed 003 prints it in the max-abs norm).
pub fn wsgb_paper_bound_11(n: usize, l: usize, d_norm: f64) -> f64 {
    let m = n / 2;
    (1u128 << l) as f64 * binomial(2 * m - 2 * l, m - l) as f64 * d_norm / powu(4.0, m)
}
