//! Exact one-degree reduction operators `k -> k-1` (SPEC-reduce §2.1, §2.3, §3, §7):
//! Forrest, Piegl–Tiller, Farin, Eck, perturbation with fixed ends and with G1 ends.
//!
//! Each builder treats the input points as the unit rows `P_i = e_i`, runs the seed's
//! algorithm in exact rationals and returns the rows of the operator, plus the terms
//! `coef * ||g . P||` of the method's own certified error bound.

use num_traits::{One, Zero};

use super::ends::{auxiliary, end_points};
use crate::bezier::method::Method;
use crate::bezier::wn_table::perturbation_error_factor;
use crate::exact::{Q, RatMat, Row, axpy, binom_q, frac, lin2, pow2, q_to_f64, scaled, to_i, unit};

/// One exact step: the `k x (k+1)` operator and its bound terms (on the step's input).
pub(crate) struct Step {
    pub(crate) op: RatMat,
    pub(crate) terms: Vec<(f64, Row)>,
}

/// `2k - 1` as the exponent of Eck's step `k` bound coefficient `2^-(2k-1)`.
pub(crate) fn to_exp(k: usize) -> i64 {
    2 * to_i(k) - 1
}

/// `f64` upper bound of a non-negative exact rational (rounded, then nudged up).
pub(crate) fn up(x: &Q) -> f64 {
    q_to_f64(x) * (1.0 + 4.0 * f64::EPSILON)
}

/// Sign vector `c_i^(k) = (-1)^(k-i) C(k,i)` as exact rationals.
pub(crate) fn signs(k: usize) -> Vec<Q> {
    let ki = to_i(k);
    (0..=ki)
        .map(|i| {
            let c = binom_q(ki, i);
            if (ki - i) % 2 == 0 { c } else { -c }
        })
        .collect()
}

/// The forward and backward inverse-elevation recursions `P^I`, `P^II` of SPEC-reduce §3
/// for input degree `k = n + 1` (output degree `n`).
fn recursions(k: usize) -> (Vec<Row>, Vec<Row>) {
    let n = k - 1;
    let (ni, len) = (to_i(n), k + 1);
    let mut fwd: Vec<Row> = Vec::with_capacity(n + 1);
    for i in 0..=ni {
        let mut v = scaled(&frac(ni + 1, 1), &unit(len, crate::exact::idx(i)));
        if i > 0 {
            axpy(&mut v, &frac(-i, 1), &fwd[crate::exact::idx(i - 1)]);
        }
        fwd.push(scaled(&frac(1, ni + 1 - i), &v));
    }
    let mut bwd: Vec<Row> = vec![Vec::new(); n + 1];
    bwd[n] = unit(len, k);
    for i in (1..=ni).rev() {
        let iu = crate::exact::idx(i);
        let v = lin2(
            &frac(ni + 1, i),
            &unit(len, iu),
            &frac(-(ni + 1 - i), i),
            &bwd[iu],
        );
        bwd[iu - 1] = v;
    }
    (fwd, bwd)
}

/// Inverse elevation of a degenerate polygon `pbar` (degree `k`, exactly of degree `k-1`),
/// eq. 14.2.3; exact, so the forward recursion is as good as the two-sided one.
fn inverse_elevation(pbar: &[Row]) -> Vec<Row> {
    let k = pbar.len() - 1;
    let ki = to_i(k);
    let mut q: Vec<Row> = Vec::with_capacity(k);
    q.push(pbar[0].clone());
    for i in 1..k {
        let ii = to_i(i);
        let v = lin2(&frac(ki, ki - ii), &pbar[i], &frac(-ii, ki - ii), &q[i - 1]);
        q.push(v);
    }
    q
}

/// The exact step `k -> k-1` of a one-degree method.
pub(crate) fn step(method: Method, k: usize) -> Step {
    let len = k + 1;
    match method {
        Method::Forrest => {
            let (fwd, bwd) = recursions(k);
            let n = k - 1;
            let rows = (0..=n)
                .map(|i| {
                    if n % 2 == 0 && i == n / 2 {
                        lin2(&frac(1, 2), &fwd[i], &frac(1, 2), &bwd[i])
                    } else if 2 * i < n {
                        fwd[i].clone()
                    } else {
                        bwd[i].clone()
                    }
                })
                .collect();
            Step {
                op: RatMat::from_rows(rows),
                terms: Vec::new(),
            }
        }
        Method::Farin => {
            let (fwd, bwd) = recursions(k);
            let ni = to_i(k - 1);
            let rows = (0..k)
                .map(|i| {
                    let ii = to_i(i);
                    lin2(&frac(ni - ii, ni), &fwd[i], &frac(ii, ni), &bwd[i])
                })
                .collect();
            Step {
                op: RatMat::from_rows(rows),
                terms: Vec::new(),
            }
        }
        Method::Eck => {
            let (fwd, bwd) = recursions(k);
            let ni = to_i(k - 1);
            let rows = eck_lambdas_exact(k - 1)
                .iter()
                .enumerate()
                .map(|(i, lambda)| lin2(&(Q::one() - lambda), &fwd[i], lambda, &bwd[i]))
                .collect();
            // Error curve 2^(-2n-1) T_{n+1}(2t-1) Delta^{n+1} P_0: max exactly 2^(-2n-1)||F||.
            let terms = vec![(up(&pow2(-2 * ni - 1)), signs(k))];
            Step {
                op: RatMat::from_rows(rows),
                terms,
            }
        }
        Method::Perturb => {
            let c = signs(k);
            let d = binom_q(2 * to_i(k), to_i(k)) - frac(2, 1);
            let pbar: Vec<Row> = (0..=k)
                .map(|i| {
                    let mut v = unit(len, i);
                    if i > 0 && i < k {
                        axpy(&mut v, &(-&c[i] / &d), &c);
                    }
                    v
                })
                .collect();
            let coef = perturbation_error_factor(k) / q_to_f64(&d) * (1.0 + 8.0 * f64::EPSILON);
            Step {
                op: RatMat::from_rows(inverse_elevation(&pbar)),
                terms: vec![(coef, c)],
            }
        }
        Method::PerturbG1 { l1, l2 } => {
            let c = signs(k);
            let ki = to_i(k);
            let s = binom_q(2 * ki, ki) - frac(2 + 2 * ki * ki, 1);
            let l1 = Q::from_float(l1).unwrap_or_else(Q::zero);
            let l2 = Q::from_float(l2).unwrap_or_else(Q::zero);
            let d1 = lin2(&Q::one(), &unit(len, 1), &-Q::one(), &unit(len, 0));
            let d2 = lin2(&Q::one(), &unit(len, k - 1), &-Q::one(), &unit(len, k));
            // F' = F + c_1 l1 d1 + c_{k-1} l2 d2.
            let mut fp = c.clone();
            axpy(&mut fp, &(&c[1] * &l1), &d1);
            axpy(&mut fp, &(&c[k - 1] * &l2), &d2);
            let pbar: Vec<Row> = (0..=k)
                .map(|i| {
                    let mut v = unit(len, i);
                    if i == 1 {
                        axpy(&mut v, &l1, &d1);
                    } else if i == k - 1 {
                        axpy(&mut v, &l2, &d2);
                    } else if i > 1 && i < k - 1 {
                        axpy(&mut v, &(-&c[i] / &s), &fp);
                    }
                    v
                })
                .collect();
            Step {
                op: RatMat::from_rows(inverse_elevation(&pbar)),
                terms: Vec::new(),
            }
        }
        Method::PieglTiller => piegl_tiller(k),
        // Multi-degree methods never come here (checked by the caller).
        _ => Step {
            op: RatMat::zeros(k, len),
            terms: Vec::new(),
        },
    }
}

/// For a step without a bound of its own: if the step reproduces degree-`k-1` curves, its
/// residual `P - E Q` is `r_i Delta^k P_0` row by row, so the exact convex-hull bound of the
/// step is the single term `max_i |r_i| * ||Delta^k P_0||`. `None` when the residual does
/// not have that form (e.g. G1 with non-zero `l`).
pub(crate) fn residual_term(op: &RatMat, k: usize) -> Option<(f64, Row)> {
    let c = signs(k);
    let res = RatMat::identity(k + 1)
        .sub(&crate::exact::elevation(k - 1, k).mul(op).ok()?)
        .ok()?;
    let mut coef = Q::zero();
    for i in 0..=k {
        let ratio = res.at(i, 0) / &c[0];
        if (0..=k).any(|j| *res.at(i, j) != &ratio * &c[j]) {
            return None;
        }
        let a = num_traits::Signed::abs(&ratio);
        if a > coef {
            coef = a;
        }
    }
    Some((up(&coef), c))
}

/// Piegl–Tiller: `m = k-1`, `r = p = floor((m-1)/2)`; Hermite ends by eq. 14.5.10 and, for
/// `m` even, `Q_{m/2} = (QL + QR) / 2` (SPEC-reduce §7). For `m` odd the error is exactly
/// `P^I_{k/2} B^k_{k/2}(t)`, max `||P^I_{k/2}|| C(k,k/2) / 2^k`.
fn piegl_tiller(k: usize) -> Step {
    let m = k - 1;
    let o = (to_i(m) - 1).div_euclid(2);
    #[allow(clippy::cast_possible_truncation, reason = "|o| <= 32")]
    let (r, p) = (o as i32, o as i32);
    let (left, right) = end_points(k, m, r, p);
    let mut rows: Vec<Row> = left.clone();
    let mut terms = Vec::new();
    if m % 2 == 0 {
        let (ki, ri, mi) = (to_i(k), i64::from(r), to_i(m));
        // QL = (k P_{r+1} - (r+1) Q_r) / (k - (r+1)); QR = (k P_{m-p} - (k-m+p) Q_{m-p}) / (m-p).
        let mut ql = scaled(&frac(ki, 1), &unit(k + 1, crate::exact::idx(ri + 1)));
        if let Some(qr) = left.last() {
            axpy(&mut ql, &frac(-(ri + 1), 1), qr);
        }
        let ql = scaled(&frac(1, ki - (ri + 1)), &ql);
        let pi = i64::from(p);
        let mut qr = scaled(&frac(ki, 1), &unit(k + 1, crate::exact::idx(mi - pi)));
        // With p = -1 (m = 0) the coefficient k - m + p is zero and there is no Q_{m-p}.
        if let Some(first) = right.first() {
            axpy(&mut qr, &frac(-(ki - mi + pi), 1), first);
        }
        let qr = scaled(&frac(1, mi - pi), &qr);
        rows.push(lin2(&frac(1, 2), &ql, &frac(1, 2), &qr));
    } else {
        let aux = auxiliary(k, m, r, p, &left, &right);
        let ki = to_i(k);
        let coef = binom_q(ki, ki / 2) * pow2(-ki);
        if let Some(g) = aux.first() {
            terms.push((up(&coef), g.clone()));
        }
    }
    rows.extend(right);
    Step {
        op: RatMat::from_rows(rows),
        terms,
    }
}
/// Eck's weights (seed 000 ch. 14 introduction, SPEC-reduce §3): the degree-`n` reduction
/// of a degree-`n+1` curve is `Q_i = (1 - lambda_i) P^I_i + lambda_i P^II_i` with
/// `lambda_i = 2^(-2n-1) sum_{j=0}^{i} C(2n+2, 2j)`, `i = 0..=n`; exact.
pub(crate) fn eck_lambdas_exact(n: usize) -> Vec<Q> {
    let ni = to_i(n);
    let mut acc = Q::zero();
    (0..=n)
        .map(|i| {
            acc += binom_q(2 * ni + 2, 2 * to_i(i));
            &acc * pow2(-2 * ni - 1)
        })
        .collect()
}

/// Eck's weights `lambda_i`, `i = 0..=n`, of the reduction from degree `n + 1` to `n`
/// (SPEC-reduce §3): `lambda_i = 2^(-2n-1) sum_{j=0}^{i} C(2n+2, 2j)`, exact.
///
/// ```
/// let l = cagd_reduce::eck_lambdas(4)?;
/// assert_eq!(l[1].to_string(), "23/256"); // SPEC-reduce vector eck-lambda
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
///
/// # Errors
/// [`cagd_core::Error::DegreeOutOfRange`] for `n + 1 > MAX_DEGREE`.
pub fn eck_lambdas(n: usize) -> cagd_core::Result<Vec<num_rational::BigRational>> {
    cagd_core::check_degree(n + 1)?;
    Ok(eck_lambdas_exact(n))
}
