//! Multi-degree reductions as truncated orthogonal expansions, on tracked rows, by closed
//! forms (no linear system is solved):
//!
//! - Chebyshev (weight `(t(1-t))^(-1/2)`): Watkins–Worsey, Bogacki–Weinstein–Xu and the
//!   constrained Chebyshev reduction of seed 000 §14.5 (Theorem 14.5.2, eqs. 14.5.14–14.5.16);
//! - Jacobi (weight `t^a (1-t)^b`): the L2-optimal reduction with `C^(r,p)` ends (beyond the
//!   seed) and the free generalized inverse (= L2, Lutterkort–Peters–Reif).
//!
//! With the ends `Q_0..Q_r`, `Q_{m-p}..Q_m` fixed by eq. 14.5.10, the residual
//! `P - Q_ends = t^(r+1) (1-t)^(p+1) S(t)` (`S` of degree `N = n - r - p - 2`, Bernstein
//! coefficients `P^II`, eq. 14.5.14) and the free interior is `t^(r+1) (1-t)^(p+1) U(t)`,
//! `U` of degree `M = m - r - p - 2`. Constrained Chebyshev truncates the Chebyshev series of
//! `S`; the constrained L2 problem `min ∫ (P - Q)^2` is `min ∫ t^(2r+2) (1-t)^(2p+2) (S - U)^2`,
//! whose solution truncates the series of `S` in the Jacobi polynomials orthogonal for
//! `t^a (1-t)^b`, `a = 2r+2`, `b = 2p+2`. `U`'s coefficients give the interior points by
//! eq. 14.5.16.
//!
//! Closed forms used (`c_l` the Bernstein coefficients of the basis polynomial `p_k` in
//! degree `k`, times `C(k,l)`):
//! - Chebyshev `T_k(2t-1)`: `c_l = (-1)^(k-l) C(2k,2l)` (SPEC-reduce §3); the coefficient
//!   functional is `(2 - δ_k0)/π ∫ S T_k / sqrt(t(1-t))`, which for `S = B_j^N` is
//!   `(2 - δ_k0) C(N,j) sum_l c_l w_(j+l) w_(K-j-l) / C(K, j+l)`, `K = N + k`,
//!   `w_i = C(2i,i) / 4^i` (from `∫ B_i^K / sqrt(t(1-t)) = π C(2i,i) C(2K-2i,K-i) / 4^K`).
//! - Jacobi `P_k^(b,a)(2t-1)`: `c_l = (-1)^(k-l) C(k+a, k-l) C(k+b, l)`; the functional is
//!   `∫ t^a (1-t)^b S p_k / h_k`, for `S = B_j^N` equal to
//!   `C(N,j) / ((K+a+b+1) h_k) sum_l c_l / C(K+a+b, j+l+a)`, with
//!   `1 / h_k = (2k+a+b+1) C(k+a+b, b) / C(k+b, b)`.
//! - Back to degree `M`: the coefficient of `B_s^M` in `p_k` is
//!   `sum_l c_l C(M-k, s-l) / C(M, s)` (degree elevation).

use super::correlation;
use super::dd::Dd;
use super::quadrature;
use super::rows::{
    Row, Rows, auxiliary, axpy, axpy_range, axpy_window, b, div, dot_window, end_points, idx,
    scale, scale_entry, support, to_i, zero,
};
use super::steps::{inverse_elevation, sign_binom};
use super::tracked::{Base, Tracked};

/// The orthogonal family of a truncation.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Family {
    /// Chebyshev polynomials `T_k(2t-1)`.
    Chebyshev,
    /// Jacobi polynomials orthogonal for `t^a (1-t)^b`.
    Jacobi {
        /// Exponent of `t`.
        a: i64,
        /// Exponent of `1 - t`.
        b: i64,
    },
}

/// Whether the weight is symmetric (`p_k(1-t) = (-1)^k p_k(t)`).
fn symmetric_weight(family: Family) -> bool {
    match family {
        Family::Chebyshev => true,
        Family::Jacobi { a, b } => a == b,
    }
}

/// `c_l`, `l = 0..=k`, of the family's `p_k` (see the module docs).
fn coefficients<B: Base>(family: Family, k: i64) -> Vec<Tracked<B>> {
    (0..=k)
        .map(|l| {
            let c = match family {
                Family::Chebyshev => Tracked::binom(2 * k, 2 * l),
                Family::Jacobi { a, b } => {
                    Tracked::binom(k + a, k - l).mul(Tracked::binom(k + b, l))
                }
            };
            if (k - l) % 2 == 0 { c } else { c.neg() }
        })
        .collect()
}

/// `c_l` as exact integers when they fit an `i128` (`None` otherwise).
fn integer_coefficients(family: Family, k: i64) -> Option<Vec<i128>> {
    let b = |n: i64, k: i64| -> Option<i128> {
        if n < 0 || k < 0 || k > n {
            return Some(0);
        }
        i128::try_from(cagd_core::binomial(idx(n), idx(k))).ok()
    };
    (0..=k)
        .map(|l| {
            let c = match family {
                Family::Chebyshev => b(2 * k, 2 * l)?,
                Family::Jacobi { a, b: bb } => b(k + a, k - l)?.checked_mul(b(k + bb, l)?)?,
            };
            Some(if (k - l) % 2 == 0 { c } else { -c })
        })
        .collect()
}

/// `sum_l c_l C(d, s - l)` exactly in `i128` (then rounded once), `None` on overflow.
fn elevated_exact<B: Base>(c: &[i128], d: i64, s: i64) -> Option<Tracked<B>> {
    let mut acc: i128 = 0;
    for (l, cl) in c.iter().enumerate() {
        let t = s - to_i(l);
        if t < 0 || t > d {
            continue;
        }
        let bin = i128::try_from(cagd_core::binomial(idx(d), idx(t))).ok()?;
        acc = acc.checked_add(cl.checked_mul(bin)?)?;
    }
    let t = Tracked::<B>::int(acc.unsigned_abs());
    Some(if acc < 0 { t.neg() } else { t })
}

/// `(last-first+1) x (N+1)`: row `k - first` is the functional giving the `k`-th expansion
/// coefficient of a degree-`N` polynomial from its Bernstein coefficients, `k = first..=last`: the correlation
/// `sum_l c_l d_(j+l)` as `k + 1` row updates, then the column factors `C(N,j)` and the
/// row's common factor.
fn functionals<B: Base>(family: Family, nn: i64, first: i64, last: i64) -> Vec<Row<B>> {
    let width = idx(nn) + 1;
    let symmetric = match family {
        Family::Chebyshev => true,
        Family::Jacobi { a, b } => a == b,
    };
    (first..=last)
        .map(|k| {
            let kk = nn + k;
            let c = coefficients::<B>(family, k);
            // d_s for s = 0..=K (entries `off..=off + K` of the row `d`) and the row's
            // common factor.
            let (d, off, factor): (std::sync::Arc<Row<B>>, usize, Tracked<B>) = match family {
                Family::Chebyshev => (
                    chebyshev_d::<B>(kk),
                    0,
                    Tracked::of(if k == 0 { 1.0 } else { 2.0 }),
                ),
                Family::Jacobi { a, b } => {
                    let inv_h = Tracked::small(2 * k + a + b + 1)
                        .mul(Tracked::binom(k + a + b, b))
                        .div(Tracked::binom(k + b, b));
                    // d_s = 1 / C(K+a+b, s+a): a window of the reciprocal binomial row.
                    (
                        recip_row::<B>(kk + a + b),
                        idx(a),
                        inv_h.div(Tracked::small(kk + a + b + 1)),
                    )
                }
            };
            // A symmetric weight has `p_k(1-t) = (-1)^k p_k(t)`, so `phi_k(N-j) =
            // (-1)^k phi_k(j)`: only the first half is computed, the rest mirrored (the
            // mirrored error bounds hold for the mirrored exact entries; negation is exact
            // in every base).
            let half = (if symmetric { width / 2 + 1 } else { width }).min(width);
            // The correlation into the first `half` entries of the row (one allocation):
            // compensated for double-word rows with exact `f64` coefficients
            // ([`compensated_dd`]), else one row update per coefficient.
            let mut row = exact_f64(family, k)
                .and_then(|ce| compensated_dd(&ce, &d, off, half, width))
                .unwrap_or_else(|| {
                    let mut acc = Row::zeros(half);
                    for (l, cl) in c.iter().enumerate() {
                        axpy_window(&mut acc, *cl, &d, off + l);
                    }
                    acc
                });
            // The column factors `factor C(N, j)`, in place.
            for j in 0..half {
                scale_entry(&mut row, j, factor.mul(Tracked::binom(nn, to_i(j))));
            }
            row.v.resize(width, B::of(0.0));
            row.e.resize(width, 0.0);
            for j in half..width {
                let (v, e) = (row.v[width - 1 - j], row.e[width - 1 - j]);
                row.v[j] = if k % 2 == 0 { v } else { B::of(0.0).sub(v) };
                row.e[j] = e;
            }
            row
        })
        .collect()
}

/// `c_l` as `f64`s if every one is an integer below `2^53` (so exactly an `f64`), else
/// `None`; remembered per `(family, k)` for the process (a constant, like the binomials).
fn exact_f64(family: Family, k: i64) -> Option<std::sync::Arc<Vec<f64>>> {
    use std::collections::HashMap;
    use std::sync::{Arc, OnceLock, RwLock};
    type Memo = RwLock<HashMap<(i64, i64, i64), Option<Arc<Vec<f64>>>>>;
    static MEMO: OnceLock<Memo> = OnceLock::new();
    let memo = MEMO.get_or_init(|| RwLock::new(HashMap::new()));
    let key = match family {
        Family::Chebyshev => (-1, -1, k),
        Family::Jacobi { a, b } => (a, b, k),
    };
    if let Some(c) = memo.read().ok().and_then(|m| m.get(&key).cloned()) {
        return c;
    }
    #[allow(clippy::cast_precision_loss, reason = "|c| < 2^53: exact")]
    let c: Option<Arc<Vec<f64>>> = integer_coefficients(family, k)
        .and_then(|c| {
            c.into_iter()
                .map(|c| {
                    let c = i64::try_from(c).ok()?;
                    (c.unsigned_abs() < 1u64 << 53).then_some(c as f64)
                })
                .collect::<Option<Vec<f64>>>()
        })
        .map(Arc::new);
    if let Ok(mut m) = memo.write() {
        m.insert(key, c.clone());
    }
    c
}

/// [`correlation::compensated`] when `B` is double-word (`None` otherwise: the caller runs
/// the row updates).
fn compensated_dd<B: Base>(
    c: &[f64],
    d: &Row<B>,
    off: usize,
    len: usize,
    cap: usize,
) -> Option<Row<B>> {
    use std::any::Any;
    let d: &dyn Any = d;
    let row = correlation::compensated(c, d.downcast_ref::<Row<Dd>>()?, off, len, cap)?;
    let boxed: Box<dyn Any> = Box::new(row);
    boxed.downcast::<Row<B>>().ok().map(|b| *b)
}

/// The reciprocal binomials `1 / C(nb, s)`, `s = 0..=nb`, as a row (the Jacobi correlation
/// rows are windows of it), remembered per `(nb, arithmetic)` for the process like
/// [`chebyshev_d`] (it was rebuilt, two allocations and `K` table look-ups, per coefficient
/// functional).
fn recip_row<B: Base>(nb: i64) -> std::sync::Arc<Row<B>> {
    use std::any::{Any, TypeId};
    use std::collections::HashMap;
    use std::sync::{Arc, OnceLock, RwLock};
    type Memo = RwLock<HashMap<(TypeId, i64), Arc<dyn Any + Send + Sync>>>;
    static MEMO: OnceLock<Memo> = OnceLock::new();
    let memo = MEMO.get_or_init(|| RwLock::new(HashMap::new()));
    let key = (TypeId::of::<B>(), nb);
    if let Some(d) = memo
        .read()
        .ok()
        .and_then(|m| m.get(&key).cloned())
        .and_then(|d| d.downcast::<Row<B>>().ok())
    {
        return d;
    }
    let d: Vec<Tracked<B>> = (0..=nb).map(|s| Tracked::recip_binom(nb, s)).collect();
    let d = Arc::new(Row::from_tracked(&d));
    if let Ok(mut m) = memo.write() {
        m.insert(key, Arc::clone(&d) as Arc<dyn Any + Send + Sync>);
    }
    d
}

/// The Chebyshev correlation row `d_s = w_s w_(K-s) / C(K, s)`, `s = 0..=K`, with
/// `w_i = C(2i,i) / 4^i` (see the module docs): a constant of `K` and the arithmetic,
/// remembered for the process like the binomials (its `O(K)` divisions per coefficient
/// functional were a fifth of a Chebyshev build at `(30,15)` in double-word).
fn chebyshev_d<B: Base>(kk: i64) -> std::sync::Arc<Row<B>> {
    use std::any::{Any, TypeId};
    use std::collections::HashMap;
    use std::sync::{Arc, OnceLock, RwLock};
    type Memo = RwLock<HashMap<(TypeId, i64), Arc<dyn Any + Send + Sync>>>;
    static MEMO: OnceLock<Memo> = OnceLock::new();
    let memo = MEMO.get_or_init(|| RwLock::new(HashMap::new()));
    let key = (TypeId::of::<B>(), kk);
    if let Some(d) = memo
        .read()
        .ok()
        .and_then(|m| m.get(&key).cloned())
        .and_then(|d| d.downcast::<Row<B>>().ok())
    {
        return d;
    }
    let mut w: Vec<Tracked<B>> = vec![Tracked::of(1.0)];
    for i in 1..=kk {
        let prev = w[w.len() - 1];
        w.push(
            prev.mul(Tracked::small(2 * i - 1))
                .div(Tracked::small(2 * i)),
        );
    }
    let d: Vec<Tracked<B>> = (0..=kk)
        .map(|s| w[idx(s)].mul(w[idx(kk - s)]).div(Tracked::binom(kk, s)))
        .collect();
    let d = Arc::new(Row::from_tracked(&d));
    if let Ok(mut m) = memo.write() {
        m.insert(key, Arc::clone(&d) as Arc<dyn Any + Send + Sync>);
    }
    d
}

/// The conversion coefficients `[k][s]`: the coefficient of `B_s^M` in `p_k`,
/// `sum_l c_l C(M-k, s-l) / C(M, s)`, for `k = 0..=M`, `s = 0..=last`.
fn conversion<B: Base>(family: Family, mm: i64, last: i64) -> Vec<Vec<Tracked<B>>> {
    (0..=mm)
        .map(|k| {
            let c = coefficients::<B>(family, k);
            let ci = integer_coefficients(family, k);
            (0..=last)
                .map(|s| {
                    let coef = match ci.as_ref().and_then(|ci| elevated_exact(ci, mm - k, s)) {
                        Some(x) => x,
                        None => {
                            let mut coef = zero::<B>();
                            for (l, cl) in c.iter().enumerate() {
                                coef = coef.fma(*cl, Tracked::binom(mm - k, s - to_i(l)));
                            }
                            coef
                        }
                    };
                    coef.div(Tracked::binom(mm, s))
                })
                .collect()
        })
        .collect()
}

/// [`conversion`] in `f64` for every `s`, remembered per `(family, M)` for the process (a
/// table of constants like the binomials': `O(M^2)` numbers, each an `i128` sum, which cost
/// a third of an L2 build at `(30,15)` when recomputed).
fn conversion_f64(family: Family, mm: i64) -> std::sync::Arc<Vec<Vec<Tracked<f64>>>> {
    use std::collections::HashMap;
    use std::sync::{Arc, OnceLock, RwLock};
    type Memo = RwLock<HashMap<(i64, i64, i64), Arc<Vec<Vec<Tracked<f64>>>>>>;
    static MEMO: OnceLock<Memo> = OnceLock::new();
    let memo = MEMO.get_or_init(|| RwLock::new(HashMap::new()));
    let key = match family {
        Family::Chebyshev => (-1, -1, mm),
        Family::Jacobi { a, b } => (a, b, mm),
    };
    if let Some(c) = memo.read().ok().and_then(|m| m.get(&key).cloned()) {
        return c;
    }
    let c = Arc::new(conversion::<f64>(family, mm, mm));
    if let Ok(mut m) = memo.write() {
        m.insert(key, Arc::clone(&c));
    }
    c
}

/// `sum_{k<=M} p_k(coefficients in degree M) f_k`: the rows of `U` (degree `M`) from the
/// kept coefficient functionals `f_0..f_M` and the conversion coefficients `coefs[k][s]`.
/// Only rows `s <= last` are computed (the others are left zero).
fn back_to_bernstein<B: Base>(
    coefs: &[Vec<Tracked<B>>],
    mm: i64,
    last: i64,
    f: &[Row<B>],
) -> Vec<Row<B>> {
    let len = f.first().map_or(0, |r| r.v.len());
    let mut out: Vec<Row<B>> = vec![Row::zeros(len); idx(mm) + 1];
    for (ck, fk) in coefs.iter().zip(f) {
        for (o, c) in out.iter_mut().zip(ck).take(idx(last) + 1) {
            axpy(o, *c, fk);
        }
    }
    out
}

/// The mixed route's back conversion (see [`truncated`]): the rows
/// `scales_s sum_k conv_ks f_k`, `s = 0..scales.len()`, with the coefficient functionals
/// `f_k` rounded to `f64` (`|ĝ - f| <= e_f + eps |ĝ|`, as [`Row::to_f64_row`]) and the sums in
/// `f64`. Each output entry is a recursive sum of `K = M + 1` rounded products
/// `fl(a_ks ĝ_kc)`, `a_ks = conv_ks scales_s` (tracked: value `â`, bound `ε_a`), so its error
/// is at most `γ_K sum_k |â| |ĝ| + sum_k (|â| e_ĝ + ε_a (|ĝ| + e_ĝ))` (Higham, *Accuracy and
/// Stability*, eq. 3.5 for the rounding; `γ_K = K u / (1 - K u) <= K u (1 + 1e-10)` at
/// `K <= 200`), computed as `sum_k |â| (e_ĝ + γ_K |ĝ|) + ε_a (|ĝ| + e_ĝ)`: three `f64`
/// operations per term and no per-entry bookkeeping (the bound's own rounding is covered by
/// the margin of [`Row::rounded`]).
fn back_to_bernstein_f64<B: Base>(
    conv: &[Vec<Tracked<f64>>],
    scales: &[Tracked<f64>],
    f: &[Row<B>],
) -> Vec<Row<B>> {
    let len = f.first().map_or(0, |r| r.v.len());
    #[allow(clippy::cast_precision_loss, reason = "K <= 200")]
    let gamma = f.len() as f64 * (f64::EPSILON / 2.0) * (1.0 + 1e-10);
    // Per functional: the rounded values, `e + γ |ĝ|` and `|ĝ| + e` (one buffer each).
    let mut gv = Vec::with_capacity(f.len() * len);
    let mut h1 = Vec::with_capacity(f.len() * len);
    let mut h2 = Vec::with_capacity(f.len() * len);
    for row in f {
        for (x, e) in row.v.iter().zip(&row.e) {
            let g = x.to_f64();
            let e = e + f64::EPSILON * (1.0 + 1e-9) * g.abs();
            gv.push(g);
            h1.push(e + gamma * g.abs());
            h2.push(g.abs() + e);
        }
    }
    scales
        .iter()
        .enumerate()
        .map(|(s, sc)| {
            let mut v = vec![0.0f64; len];
            let mut e = vec![0.0f64; len];
            for (k, ck) in conv.iter().enumerate().take(f.len()) {
                let Some(c) = ck.get(s) else { continue };
                let a = c.mul(*sc);
                let (av, am, ae) = (a.value(), a.value().abs(), a.bound());
                let span = k * len..(k + 1) * len;
                let (g, x1, x2) = (&gv[span.clone()], &h1[span.clone()], &h2[span]);
                for ((vc, ec), ((gc, x1c), x2c)) in
                    v.iter_mut().zip(e.iter_mut()).zip(g.iter().zip(x1).zip(x2))
                {
                    *vc += av * gc;
                    *ec += am * x1c + ae * x2c;
                }
            }
            Row {
                v: v.into_iter().map(B::of).collect(),
                e,
            }
        })
        .collect()
}

/// The coefficient functionals on `P`, `f_k = sum_i phi_ki P^II_i`, with
/// `P^II_i = C(n, r+1+i) / C(N, i) A_(r+1+i)` and the auxiliary points
/// `A_j = P_j - sum_l b_lj Q_l` over the fixed end points (see `rows::auxiliary`): expanded as
/// `w_k = phi_k C(n, r+1+i) / C(N, i)` on `P_(r+1+i)` minus one scalar `w_k . b_l` per end
/// point, `O(N (r + p + 2))` per functional instead of a dense product. `phi[t]` is the
/// functional of degree `k = first + t` (its parity gives the mirror sign below).
///
/// The scalars run over the band of Lemma 14.5.1 only (`b_lj = 0` unless
/// `l <= j <= l + n - m`). For a symmetric problem (`r = p`, a symmetric weight: `phi_k(N-i) =
/// (-1)^k phi_k(i)` exactly, `C(n, r+1+i) / C(N, i)` symmetric, and `b_(m-l, j) = b_(l, n-j)`)
/// the right end point `m - l`'s scalar is exactly `(-1)^k` times the left end point `l`'s,
/// so the computed left scalar with its proven bound serves for both (the identity holds for
/// the exact values, whatever the rounding of the computed rows).
#[allow(clippy::too_many_arguments, reason = "the truncation's own parameters")]
fn on_points<B: Base>(
    phi: Vec<Row<B>>,
    first: i64,
    n: usize,
    m: usize,
    r: i32,
    p: i32,
    left: &[Row<B>],
    right: &[Row<B>],
    symmetric_weight: bool,
) -> Vec<Row<B>> {
    let (ni, mi, ri, pi) = (to_i(n), to_i(m), i64::from(r), i64::from(p));
    if ri == -1 && pi == -1 {
        return phi;
    }
    let consts = on_points_constants::<B>(n, m, r, p);
    let (sc, bands) = (&consts.0, &consts.1);
    let ends: Vec<(i64, &Row<B>)> = left
        .iter()
        .enumerate()
        .map(|(l, q)| (to_i(l), q))
        .chain(
            right
                .iter()
                .enumerate()
                .map(|(l, q)| (mi - pi + to_i(l), q)),
        )
        .collect();
    // An end point `Q_l` depends on `P_0..=P_l` (left) or `P_(n-p+l)..` (right) only: its
    // row is zero (value and error) outside its support, so the updates run there (the
    // interior entries `r+1..=n-p-1` are disjoint from both ends' supports).
    let supports: Vec<(usize, usize)> = ends.iter().map(|(_, q)| support(q)).collect();
    let mirrored = symmetric_weight && ri == pi;
    let n_left = left.len();
    let (lo_w, hi_w) = (idx(ri + 1), idx(ni - pi - 1));
    phi.iter()
        .zip(first..)
        .map(|(ph, k)| {
            let mut row = Row::zeros(n + 1);
            row.v[lo_w..=hi_w].copy_from_slice(&ph.v);
            row.e[lo_w..=hi_w].copy_from_slice(&ph.e);
            for (i, s) in sc.iter().enumerate() {
                scale_entry(&mut row, lo_w + i, *s);
            }
            let mut scalars: Vec<Tracked<B>> = Vec::with_capacity(ends.len());
            debug_assert_eq!(bands.len(), ends.len());
            for (t, (lo, beta)) in bands.iter().enumerate() {
                let x = if mirrored && t >= n_left {
                    // Right end point `m - p + (t - n_left)` mirrors left `p - (t - n_left)`.
                    let y = scalars[idx(pi) - (t - n_left)];
                    if k % 2 == 0 { y } else { y.neg() }
                } else {
                    dot_window(&row, lo_w + lo, beta)
                };
                scalars.push(x);
            }
            for ((x, (_, q)), &(lo, hi)) in scalars.iter().zip(&ends).zip(&supports) {
                axpy_range(&mut row, x.neg(), q, lo, hi);
            }
            row
        })
        .collect()
}

/// The constants of [`on_points`] for `(n, m, r, p)` in base `B`: the column scalings
/// `C(n, r+1+i) / C(N, i)`, `i = 0..=N`, and per end point (the left ones `l = 0..=r`, then
/// the right ones `l = m-p..=m`) the band `lo..=hi` of `i` where `b_(l, r+1+i) != 0`
/// (Lemma 14.5.1) with those `b`; remembered for the process like the binomials (their
/// tracked binomial products and quotients were 3 % of a constrained Chebyshev build at
/// `(30,15)`).
#[allow(clippy::type_complexity, reason = "a memo of two tables")]
fn on_points_constants<B: Base>(
    n: usize,
    m: usize,
    r: i32,
    p: i32,
) -> std::sync::Arc<(Vec<Tracked<B>>, Vec<(usize, Vec<Tracked<B>>)>)> {
    use std::any::{Any, TypeId};
    use std::collections::HashMap;
    use std::sync::{Arc, OnceLock, RwLock};
    type Memo = RwLock<HashMap<(TypeId, usize, usize, i32, i32), Arc<dyn Any + Send + Sync>>>;
    static MEMO: OnceLock<Memo> = OnceLock::new();
    let memo = MEMO.get_or_init(|| RwLock::new(HashMap::new()));
    let key = (TypeId::of::<B>(), n, m, r, p);
    if let Some(c) = memo
        .read()
        .ok()
        .and_then(|t| t.get(&key).cloned())
        .and_then(|c| {
            c.downcast::<(Vec<Tracked<B>>, Vec<(usize, Vec<Tracked<B>>)>)>()
                .ok()
        })
    {
        return c;
    }
    let (ni, mi, ri, pi) = (to_i(n), to_i(m), i64::from(r), i64::from(p));
    let nn = ni - (ri + pi + 2);
    let sc: Vec<Tracked<B>> = (0..=nn)
        .map(|i| Tracked::binom(ni, ri + 1 + i).div(Tracked::binom(nn, i)))
        .collect();
    let ends = (0..=ri).chain((mi - pi)..=mi);
    let bands: Vec<(usize, Vec<Tracked<B>>)> = ends
        .map(|l| {
            let lo = (l - ri - 1).max(0);
            let hi = (l - ri - 1 + ni - mi).min(nn);
            let beta = (lo..=hi).map(|i| b::<B>(mi, ni, l, ri + 1 + i)).collect();
            (idx(lo.min(nn + 1)), beta)
        })
        .collect();
    let c = Arc::new((sc, bands));
    if let Ok(mut t) = memo.write() {
        t.insert(key, Arc::clone(&c) as Arc<dyn Any + Send + Sync>);
    }
    c
}

/// The bound terms' functionals `f_k`, `k = M+1..=N`, on the points: the Chebyshev
/// coefficients by quadrature ([`quadrature::chebyshev`]), in `f64` (on the double-word
/// route) when the proven errors `coef sum_k ||e_k||_1` stay within 0.9 of what `finish`
/// accepts (`TOLERANCE max(1, coef sum_k ||f_k||_1)`), else in the base arithmetic (whose
/// quadrature error is at its
/// rounding level: the double-word terms no longer lose `4^k` to cancellation); by the
/// correlation of [`functionals`] for a family without a quadrature (none takes terms today).
#[allow(clippy::too_many_arguments, reason = "the truncation's own parameters")]
fn high_terms<B: Base>(
    family: Family,
    n: usize,
    m: usize,
    r: i32,
    p: i32,
    left: &[Row<B>],
    right: &[Row<B>],
    coef: f64,
) -> Vec<Row<B>> {
    let (ni, mi, ri, pi) = (to_i(n), to_i(m), i64::from(r), i64::from(p));
    let (nn, mm) = (ni - (ri + pi + 2), mi - (ri + pi + 2));
    if !matches!(family, Family::Chebyshev) {
        return on_points(
            functionals::<B>(family, nn, mm + 1, nn),
            mm + 1,
            n,
            m,
            r,
            p,
            left,
            right,
            symmetric_weight(family),
        );
    }
    // The double-word route (every pair up to degree 30 that is not `f64`) tries `f64`
    // first; the 256-bit route, a last resort, keeps its terms at its own rounding level.
    if std::any::TypeId::of::<B>() == std::any::TypeId::of::<Dd>() {
        if let Some(phi) = quadrature::chebyshev::<f64>(nn, mm + 1, nn) {
            let l64: Vec<Row<f64>> = left.iter().map(Row::to_f64_row).collect();
            let r64: Vec<Row<f64>> = right.iter().map(Row::to_f64_row).collect();
            let g = on_points(phi, mm + 1, n, m, r, p, &l64, &r64, true);
            let (mut te, mut ts) = (0.0, 0.0);
            for row in &g {
                let (v, e) = row.rounded();
                te += coef * e;
                ts += coef * v.iter().map(|x| x.abs()).sum::<f64>();
            }
            if te <= 0.9 * super::TOLERANCE * f64::max(ts, 1.0) {
                return g.iter().map(Row::from_f64_row).collect();
            }
        }
    }
    let phi = quadrature::chebyshev::<B>(nn, mm + 1, nn)
        .unwrap_or_else(|| functionals::<B>(family, nn, mm + 1, nn));
    on_points(phi, mm + 1, n, m, r, p, left, right, true)
}

/// A truncation by one degree (`N = M + 1`) from the top (beyond the seed): the highest
/// coefficient is the ratio of leading power coefficients, `f_N(S) = Delta^N S / lead(p_N)`
/// with `lead(p_N) = sum_l |c_l|` (`C(2N+a+b, N)` for Jacobi, `2^(2N-1)` for Chebyshev), a
/// single signed binomial per entry; `S - f_N p_N` is then exactly of degree `M`, and its
/// degree-`M` coefficients come from the inverse elevation of `../steps.rs` (Forrest's
/// split). This avoids the alternating sums of the low-order functionals, whose
/// cancellation grows like `4^k` and defeats even double-word at degree 64. Returns the
/// rows of `U` (degree `M`) and `f_N` on the points.
#[allow(clippy::too_many_arguments, reason = "the truncation's own parameters")]
fn top_complement<B: Base>(
    family: Family,
    n: usize,
    m: usize,
    r: i32,
    p: i32,
    left: &[Row<B>],
    right: &[Row<B>],
    input: &[Row<B>],
) -> (Vec<Row<B>>, Row<B>) {
    let (ni, ri, pi) = (to_i(n), i64::from(r), i64::from(p));
    let nn = ni - (ri + pi + 2);
    // S's Bernstein coefficients (degree N) as functionals of P: P^II (eq. 14.5.14).
    let s: Vec<Row<B>> = if ri == -1 && pi == -1 {
        input.to_vec()
    } else {
        auxiliary(n, m, r, p, left, right, input)
            .iter()
            .enumerate()
            .map(|(i, a)| {
                let i = to_i(i);
                scale(a, Tracked::binom(ni, ri + 1 + i).div(Tracked::binom(nn, i)))
            })
            .collect()
    };
    let mut d = Row::zeros(n + 1);
    for (j, row) in s.iter().enumerate() {
        axpy(&mut d, sign_binom(idx(nn), j), row);
    }
    let c = coefficients::<B>(family, nn);
    let lead = match family {
        Family::Chebyshev => Tracked::of(2f64.powi(i32::try_from(2 * nn - 1).unwrap_or(i32::MAX))),
        Family::Jacobi { a, b } => Tracked::binom(2 * nn + a + b, nn),
    };
    let top = div(&d, lead);
    let g: Vec<Row<B>> = s
        .iter()
        .zip(&c)
        .enumerate()
        .map(|(i, (si, ci))| {
            let mut gi = si.clone();
            axpy(&mut gi, ci.div(Tracked::binom(nn, to_i(i))).neg(), &top);
            gi
        })
        .collect();
    (inverse_elevation(&g), top)
}

/// Whether the `f64` route of a truncation is sure to be refused, judged by one row: the
/// proven relative error of the `f64` coefficient functional of degree `k` (the highest the
/// operator needs; bound terms are by quadrature, see [`high_terms`]) on degree-`N`
/// polynomials exceeds `4 tol` (it tracks the
/// operator's own proven error within a factor of about 2 at the pairs of the
/// `operator_build` bench: 7e-10 against 5e-10 at L2-C0 `(30,15)`). Saves the
/// `f64` attempt where cancellation makes it hopeless (a performance choice only: the
/// double-word route is proven on its own).
/// The verdict is remembered per `(family, N, k, tol)` for the process (it is a constant of
/// those, and its one `f64` functional cost 4 % of an L2 build at `(30,15)`).
pub(crate) fn f64_hopeless(family: Family, nn: i64, k: i64, tol: f64) -> bool {
    use std::collections::HashMap;
    use std::sync::{OnceLock, RwLock};
    type Memo = RwLock<HashMap<(i64, i64, i64, i64, u64), bool>>;
    static MEMO: OnceLock<Memo> = OnceLock::new();
    if nn < 0 || k < 0 {
        return false;
    }
    let memo = MEMO.get_or_init(|| RwLock::new(HashMap::new()));
    let (fa, fb) = match family {
        Family::Chebyshev => (-1, -1),
        Family::Jacobi { a, b } => (a, b),
    };
    let key = (fa, fb, nn, k, tol.to_bits());
    if let Some(v) = memo.read().ok().and_then(|m| m.get(&key).copied()) {
        return v;
    }
    let v = f64_hopeless_uncached(family, nn, k, tol);
    if let Ok(mut m) = memo.write() {
        m.insert(key, v);
    }
    v
}

fn f64_hopeless_uncached(family: Family, nn: i64, k: i64, tol: f64) -> bool {
    let row = functionals::<f64>(family, nn, k, k).pop();
    row.is_some_and(|r| {
        let (v, e) = r.rounded();
        let s: f64 = v.iter().map(|x| x.abs()).sum();
        // A NaN or infinite bound counts as hopeless too.
        e.is_nan() || e > 4.0 * tol * s
    })
}

/// The operator `n -> m` with `(r, p)` ends and the interior by truncation in `family`;
/// the bound terms (Chebyshev: `factor * ||f_k . P||`, `k > M`) when `factor` is given.
///
/// With `mixed`, the back conversion of the kept coefficients to Bernstein form
/// ([`back_to_bernstein`]) runs in `f64` on the coefficient functionals rounded to `f64`
/// (their errors carried): the alternating sums that need the base arithmetic are in the
/// functionals, not in the conversion, whose proven error stays at the rounding level
/// (`2e-15` of the inf-norm at the pairs up to degree 64 measured); the caller retries
/// without it if the proven error is above the goal.
pub(crate) fn truncated<B: Base>(
    family: Family,
    n: usize,
    m: usize,
    r: i32,
    p: i32,
    factor: Option<f64>,
    mixed: bool,
) -> Rows<B> {
    let (ni, mi, ri, pi) = (to_i(n), to_i(m), i64::from(r), i64::from(p));
    // The unit rows as the input points; only the end points' (`j <= r`, `j >= n - p`) are
    // read unless the truncation is by one degree (`top_complement` reads them all), so the
    // others stay empty (no allocation).
    let by_one = ri + pi + 1 < mi && ni - mi == 1;
    let input: Vec<Row<B>> = (0..=n)
        .map(|j| {
            let j = to_i(j);
            if by_one || j <= ri || j >= ni - pi {
                Row::unit(n + 1, idx(j))
            } else {
                Row::zeros(0)
            }
        })
        .collect();
    let (left, right) = end_points(n, m, r, p, &input);
    let mut rows = left.clone();
    let mut terms = Vec::new();
    if ri + pi + 1 < mi {
        let (nn, mm) = (ni - (ri + pi + 2), mi - (ri + pi + 2));
        // A symmetric problem (`r = p`, a symmetric weight) has a centro-symmetric operator,
        // `a_(m-i, n-j) = a_ij`: the second half of the interior rows mirrors the first
        // (the mirrored error bounds hold for the mirrored exact entries).
        let symmetric = ri == pi
            && match family {
                Family::Chebyshev => true,
                Family::Jacobi { a, b } => a == b,
            };
        let last_i = if symmetric { mi / 2 } else { mi - pi - 1 };
        let (u, high) = if nn == mm + 1 {
            let (u, top) = top_complement(family, n, m, r, p, &left, &right, &input);
            (u, vec![top])
        } else {
            // The operator needs the kept coefficients (the bound terms the others, by
            // quadrature: `high_terms`).
            let phi = functionals::<B>(family, nn, 0, mm);
            // Coefficient functionals on P: f_k = sum_i phi_ki P^II_i (P^II = P when
            // r = p = -1).
            let f = on_points(phi, 0, n, m, r, p, &left, &right, symmetric_weight(family));
            let u = if mixed {
                let scales: Vec<Tracked<f64>> = ((ri + 1)..=last_i)
                    .map(|i| Tracked::binom(mm, i - ri - 1).div(Tracked::binom(mi, i)))
                    .collect();
                back_to_bernstein_f64(&conversion_f64(family, mm), &scales, &f[..=idx(mm)])
            } else {
                let coefs = conversion::<B>(family, mm, last_i - ri - 1);
                back_to_bernstein(&coefs, mm, last_i - ri - 1, &f[..=idx(mm)])
            };
            let high = match factor {
                Some(coef) => high_terms(family, n, m, r, p, &left, &right, coef),
                None => Vec::new(),
            };
            (u, high)
        };
        // Q_i = U_{i-r-1} C(M, i-r-1) / C(m, i)   (14.5.16; the mixed route's rows come
        // scaled)
        let mut u = u.into_iter();
        for i in (ri + 1)..=(mi - pi - 1) {
            if i > last_i {
                rows.push(rows[idx(mi - i)].reversed());
                continue;
            }
            let s = i - ri - 1;
            let ui = u.next().unwrap_or_else(|| Row::zeros(n + 1));
            rows.push(if mixed && nn != mm + 1 {
                ui
            } else {
                scale(&ui, Tracked::binom(mm, s).div(Tracked::binom(mi, i)))
            });
        }
        if let Some(coef) = factor {
            terms.extend(high.into_iter().map(|g| (coef, g)));
        }
    }
    rows.extend(right);
    (rows, terms)
}
