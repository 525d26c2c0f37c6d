//! A compensated stepwise route for Farin's method and the perturbation method (SPEC-reduce
//! §2.3 and §7; the arithmetic goes beyond the seed): the same steps as `steps.rs`'s split
//! Farin form and symmetric perturbation, each row entry an unevaluated sum `h + l` of two
//! `f64`s, and one error bound *per row* instead of one per entry.
//!
//! **The arithmetic.** Every row operation is `z = a x + b y` (or `y += a x`) with constants
//! `a = a_h + a_l` (`|a_l| <= u |a_h|`, a proven `|a* - a_h - a_l| <= ε_a` of the exact
//! constant `a*`). Per entry, `a_h x_h = p_1 + e_1` and `b_h y_h = p_2 + e_2` are exact
//! (Dekker's product, the constants split once per row), `p_1 + p_2 = r + e_r` exact
//! (Knuth's sum); `z_h = r` and `z_l = fl(e_r + e_1 + e_2 + a_h x_l + a_l x_h + b_h y_l +
//! b_l y_h)` in plain `f64` (straight loops over two arrays, no renormalisation, no per-entry
//! bookkeeping). So `z_h + z_l` misses `(a_h + a_l)(x_h + x_l) + (b_h + b_l)(y_h + y_l)` only
//! by the rounding of the low sum and the dropped `a_l x_l + b_l y_l`.
//!
//! **The bound** (a row's `H >= sum |h|`, `L >= sum |l|`, `E >= sum |h + l - exact|`): with
//! `T = |a_h| H_x + |b_h| H_y` and `S = |a_h| L_x + |b_h| L_y`, the low sum's terms add up
//! to at most `Z = 3 u (1 + u)^2 T + S` over the row (`|e_1| <= u |p_1|`, `|e_r| <= u |r|`,
//! `|a_l x_h| <= u |a_h x_h|`), its rounding is at most `γ_7 Z` (seven terms, four of them
//! products; Higham, *Accuracy and Stability*, §3.1, any summation order), the dropped
//! products at most `u S`, and the inputs' errors propagate as
//! `(|a_h| + |a_l| + ε_a) E_x + ε_a (H_x + L_x)` (and alike for `b`):
//!
//! `E_z <= (|a_h| + |a_l| + ε_a) E_x + ε_a (H_x + L_x) + (|b_h| + |b_l| + ε_b) E_y + ε_b (H_y
//! + L_y) + γ_7 Z + u S`,
//!
//! `H_z <= (1 + u)^2 T`, `L_z <= (1 + γ_7) Z` (or the rows' own sums, rounded up, where they
//! are computed). The bound computations are a few `f64` operations each (relative rounding
//! below `1e-14`), covered by a factor `1 + 1e-9`. The low parts stay about `u` times the
//! high ones times the length of the chain, so `E` is of the order `u^2` times the
//! magnitudes, like the double-word route's running bound, at a fraction of its cost.
//! Dekker's product is exact unless it under- or overflows: every row is checked
//! (`2^-700 <= |h| <= 2^900` or `h = 0`), every constant (`|a_h| >= 2^-200`), else the
//! route gives up (`None`) and the next route is tried.
//!
//! The route is accepted at the rounding level (`build`'s `strict`), so the own bounds are
//! as tight as with the double-word route; where its bound is not (high degrees, where the
//! steps' magnitudes compound), the double-word and 256-bit routes follow.

use super::dd::{Dd, split, two_sum};
use super::rows::{recycle_f64, scratch_f64, to_i};
use super::steps::{perturb_coef, residual_coef_cached, sign_binom};
use super::tracked::Tracked;
use crate::bezier::method::Method;

/// The unit roundoff of `f64`.
const U: f64 = f64::EPSILON / 2.0;

/// The margin for the rounding of the bound computations themselves.
const MARGIN: f64 = 1.0 + 1e-9;

/// `γ_k = k u / (1 - k u)`.
#[allow(clippy::cast_precision_loss, reason = "k <= 8")]
fn gamma(k: usize) -> f64 {
    let ku = k as f64 * U;
    ku / (1.0 - ku)
}

/// The smallest non-zero magnitude of a row's high part (about `2^-697`: with constants of
/// magnitude at least `2^-200`, Dekker's product stays exact).
const TINY: f64 = 1e-210;

/// An absolute allowance per row operation for products of low parts that underflow (each
/// at most `2^-1075`, a few hundred of them per row at most).
const UNDERFLOW: f64 = 1e-300;

/// A row of compensated entries `h[c] + l[c]` (a linear functional of the input points) and
/// bounds of its magnitudes and error (see the module docs).
#[derive(Debug)]
pub(crate) struct CRow {
    h: Vec<f64>,
    l: Vec<f64>,
    /// `>= sum_c |h[c]|`.
    hs: f64,
    /// `>= sum_c |l[c]|`.
    ls: f64,
    /// `>= sum_c |h[c] + l[c] - exact_c|`.
    e: f64,
}

impl Drop for CRow {
    fn drop(&mut self) {
        recycle_f64(std::mem::take(&mut self.h));
        recycle_f64(std::mem::take(&mut self.l));
    }
}

impl CRow {
    /// `len` exact zeros.
    fn zeros(len: usize) -> Self {
        Self {
            h: scratch_f64(len),
            l: scratch_f64(len),
            hs: 0.0,
            ls: 0.0,
            e: 0.0,
        }
    }

    /// A placeholder for a mirrored row (filled in by [`materialize`]).
    fn empty() -> Self {
        Self::zeros(0)
    }

    /// The unit row `e_i`.
    fn unit(len: usize, i: usize) -> Self {
        let mut r = Self::zeros(len);
        r.h[i] = 1.0;
        r.hs = 1.0;
        r
    }

    /// A copy with the entries in reverse order (the same bounds).
    fn reversed(&self) -> Self {
        let mut r = self.copy();
        r.h.reverse();
        r.l.reverse();
        r
    }

    /// A copy (buffers from the pool).
    fn copy(&self) -> Self {
        let mut r = Self::zeros(self.h.len());
        r.h.copy_from_slice(&self.h);
        r.l.copy_from_slice(&self.l);
        (r.hs, r.ls, r.e) = (self.hs, self.ls, self.e);
        r
    }

    /// Replaces `hs` and `ls` by the row's own sums rounded up (`(1 + γ_len)` covers the
    /// rounding of a sum of non-negative terms); `false` if an entry is outside the range
    /// where Dekker's product is exact.
    fn own_sums(&mut self) -> bool {
        let (mut hs, mut ls, mut tiny) = ([0.0f64; 4], [0.0f64; 4], false);
        let mut hc = self.h.chunks_exact(4);
        let mut lc = self.l.chunks_exact(4);
        for (h, l) in (&mut hc).zip(&mut lc) {
            for j in 0..4 {
                let a = h[j].abs();
                hs[j] += a;
                ls[j] += l[j].abs();
                tiny |= a < TINY && a != 0.0;
            }
        }
        for (h, l) in hc.remainder().iter().zip(lc.remainder()) {
            let a = h.abs();
            hs[0] += a;
            ls[0] += l.abs();
            tiny |= a < TINY && a != 0.0;
        }
        let up = 1.0 + gamma(8) * 64.0;
        self.hs = (hs[0] + hs[1] + hs[2] + hs[3]) * up;
        self.ls = (ls[0] + ls[1] + ls[2] + ls[3]) * up;
        !tiny && self.hs < 2f64.powi(900)
    }

    /// The entries rounded to `f64` (`fl(h + l)`, within `u |h + l|`) and the bound of
    /// `sum_c |value_c - exact_c|`.
    pub(crate) fn rounded(&self) -> (Vec<f64>, f64) {
        let v: Vec<f64> = self.h.iter().zip(&self.l).map(|(h, l)| h + l).collect();
        let s: f64 = v.iter().map(|x| x.abs()).sum();
        (v, (self.e + f64::EPSILON * s) * (1.0 + 1e-6))
    }

    /// The number of entries.
    pub(crate) fn len(&self) -> usize {
        self.h.len()
    }
}

/// A constant `h + l` with `|l| <= u |h|` and a bound `e` of its distance from the exact
/// constant.
#[derive(Debug, Clone, Copy)]
struct Coef {
    h: f64,
    l: f64,
    e: f64,
}

impl Coef {
    /// An exact `f64`.
    fn exact(x: f64) -> Self {
        Self {
            h: x,
            l: 0.0,
            e: 0.0,
        }
    }

    /// A tracked double-word constant, renormalised (`h = fl(h + l)`, so `|l| <= u |h|`).
    fn of(t: Tracked<Dd>) -> Self {
        let v = t.value();
        let (h, l) = two_sum(v.hi, v.lo);
        Self {
            h,
            l,
            e: t.bound() * MARGIN,
        }
    }

    /// `true` if Dekker's product with this constant is exact for the rows' entries.
    fn usable(self) -> bool {
        self.e.is_finite() && (self.h == 0.0 || self.h.abs() >= 2f64.powi(-200))
    }
}

/// Dekker's product `p + e = a x` exactly, with `a`'s split `(a1, a2)` given.
#[inline(always)]
fn two_prod(a: f64, a1: f64, a2: f64, x: f64) -> (f64, f64) {
    let p = a * x;
    let (x1, x2) = split(x);
    (p, ((a1 * x1 - p) + a1 * x2 + a2 * x1) + a2 * x2)
}

/// The error bound of `a x + b y` (module docs) and the a-priori `(H, L)` of the result.
fn bound(a: Coef, x: (f64, f64, f64), b: Coef, y: (f64, f64, f64)) -> (f64, f64, f64) {
    let (ah, bh) = (a.h.abs(), b.h.abs());
    let t = ah * x.0 + bh * y.0;
    let s = ah * x.1 + bh * y.1;
    let z = 3.0 * U * (1.0 + U) * (1.0 + U) * t + s;
    let e = (ah + a.l.abs() + a.e) * x.2
        + a.e * (x.0 + x.1)
        + (bh + b.l.abs() + b.e) * y.2
        + b.e * (y.0 + y.1)
        + gamma(7) * z
        + U * s
        + UNDERFLOW;
    (
        e * MARGIN,
        (1.0 + U) * (1.0 + U) * t * MARGIN,
        (1.0 + gamma(7)) * z * MARGIN,
    )
}

/// `a x + b y` (the rows' own sums taken; `None` outside Dekker's range).
fn lin2(a: Coef, x: &CRow, b: Coef, y: &CRow) -> Option<CRow> {
    let len = x.len().min(y.len());
    let mut out = CRow::zeros(len);
    let (a1, a2) = split(a.h);
    let (b1, b2) = split(b.h);
    {
        let (oh, ol) = (&mut out.h[..len], &mut out.l[..len]);
        let (xh, xl, yh, yl) = (&x.h[..len], &x.l[..len], &y.h[..len], &y.l[..len]);
        for c in 0..len {
            let (p1, e1) = two_prod(a.h, a1, a2, xh[c]);
            let (p2, e2) = two_prod(b.h, b1, b2, yh[c]);
            let (r, er) = two_sum(p1, p2);
            oh[c] = r;
            ol[c] = ((er + e1) + e2) + ((a.h * xl[c] + a.l * xh[c]) + (b.h * yl[c] + b.l * yh[c]));
        }
    }
    let (e, _, _) = bound(a, (x.hs, x.ls, x.e), b, (y.hs, y.ls, y.e));
    out.e = e;
    out.own_sums().then_some(out)
}

/// `y += a x` (a-priori sums: the same bound as [`lin2`] with `b = 1`).
fn axpy(y: &mut CRow, a: Coef, x: &CRow) {
    let len = y.len().min(x.len());
    let (a1, a2) = split(a.h);
    {
        let (yh, yl) = (&mut y.h[..len], &mut y.l[..len]);
        let (xh, xl) = (&x.h[..len], &x.l[..len]);
        for c in 0..len {
            let (p1, e1) = two_prod(a.h, a1, a2, xh[c]);
            let (r, er) = two_sum(yh[c], p1);
            yl[c] = ((yl[c] + er) + e1) + (a.h * xl[c] + a.l * xh[c]);
            yh[c] = r;
        }
    }
    let (e, hs, ls) = bound(a, (x.hs, x.ls, x.e), Coef::exact(1.0), (y.hs, y.ls, y.e));
    (y.e, y.hs, y.ls) = (e, hs, ls);
}

/// `Delta^k s` of reversal-symmetric rows (as `steps::delta_k_symmetric`): `h + (-1)^k
/// reversed(h)`, `h = sum_(i < k/2) (-1)^(k-i) C(k,i) s_i` (plus half the middle term for
/// even `k`); the binomials are exact double-words.
fn delta(s: &[CRow]) -> Option<CRow> {
    let k = s.len() - 1;
    let mut h = CRow::zeros(s[0].len());
    for (i, row) in s.iter().enumerate().take(k.div_ceil(2)) {
        axpy(&mut h, Coef::of(sign_binom(k, i)), row);
    }
    if k % 2 == 0 {
        let c = sign_binom(k, k / 2).mul(Tracked::of(0.5));
        axpy(&mut h, Coef::of(c), &s[k / 2]);
    }
    let sign = if k % 2 == 1 { -1.0 } else { 1.0 };
    lin2(Coef::exact(1.0), &h, Coef::exact(sign), &h.reversed())
}

/// The forward recursion `P_i = (k s_i - i P_(i-1)) / (k - i)`, `i = 0..=last`, as
/// `P_i = (k / (k-i)) s_i - (i / (k-i)) P_(i-1)` with double-word constants.
fn forward(s: &[CRow], k: usize, last: usize) -> Option<Vec<CRow>> {
    let mut out: Vec<CRow> = Vec::with_capacity(last + 1);
    out.push(s[0].copy());
    for i in 1..=last {
        let d = Tracked::<Dd>::small(to_i(k - i));
        let a = Coef::of(Tracked::small(to_i(k)).div(d));
        let b = Coef::of(Tracked::small(-to_i(i)).div(d));
        let next = lin2(a, &s[i], b, &out[i - 1])?;
        out.push(next);
    }
    Some(out)
}

/// One step `k -> k-1` on the first half of reversal-symmetric rows: the output's first
/// half and the step's bound term `(coef, Delta^k s)`; `None` outside Dekker's range.
fn step(method: Method, s: &[CRow]) -> Option<(Vec<CRow>, (f64, CRow))> {
    let k = s.len() - 1;
    let n = k - 1;
    let half = n / 2;
    let d = delta(s)?;
    let rows = match method {
        Method::Farin => {
            // `steps::farin`: `Q_i = P^I_i + (i/n) (-1)^(n-i) delta / C(n,i)`.
            let mut rows = forward(s, k, half)?;
            let nn = Tracked::<Dd>::small(to_i(n));
            for (i, row) in rows.iter_mut().enumerate().skip(1) {
                let mut c = Tracked::small(to_i(i)).div(nn.mul(Tracked::binom(to_i(n), to_i(i))));
                if (n - i) % 2 == 1 {
                    c = c.neg();
                }
                let c = Coef::of(c);
                if !c.usable() {
                    return None;
                }
                axpy(row, c, &d);
                if !row.own_sums() {
                    return None;
                }
            }
            rows
        }
        Method::Perturb => {
            // `pbar_i = s_i - (-1)^(k-i) C(k,i) delta / (C(2k,k) - 2)`, `0 < i <= n/2`, then
            // the forward half of the inverse elevation.
            let dd = Tracked::<Dd>::binom(2 * to_i(k), to_i(k)).sub(Tracked::of(2.0));
            let mut pbar: Vec<CRow> = Vec::with_capacity(half + 1);
            pbar.push(s[0].copy());
            for (i, row) in s.iter().enumerate().take(half + 1).skip(1) {
                let c = Coef::of(sign_binom::<Dd>(k, i).div(dd).neg());
                if !c.usable() {
                    return None;
                }
                let mut p = row.copy();
                axpy(&mut p, c, &d);
                if !p.own_sums() {
                    return None;
                }
                pbar.push(p);
            }
            forward(&pbar, k, half)?
        }
        _ => return None,
    };
    let coef = match method {
        Method::Perturb => perturb_coef(k),
        _ => residual_coef_cached(method, k)?,
    };
    Some((rows, (coef, d)))
}

/// The operator `n -> m` of Farin's method or the perturbation method by compensated steps:
/// its rows (`m + 1`) and bound terms, or `None` (another method, outside Dekker's range, or
/// a step's proven error already above [`super::TOLERANCE`] of its rows' magnitudes: the
/// route would be refused, and the next one is tried).
pub(crate) fn stepwise(
    method: Method,
    n: usize,
    m: usize,
) -> Option<(Vec<CRow>, Vec<(f64, CRow)>)> {
    if !matches!(method, Method::Farin | Method::Perturb) || m >= n {
        return None;
    }
    // Only the first half of each step's input is read (`steps::mirror`).
    let mut s: Vec<CRow> = (0..=n)
        .map(|i| {
            if i <= n / 2 {
                CRow::unit(n + 1, i)
            } else {
                CRow::empty()
            }
        })
        .collect();
    let mut terms = Vec::with_capacity(n - m);
    for k in ((m + 1)..=n).rev() {
        let (mut rows, term) = step(method, &s)?;
        let (mut err, mut mag) = (0.0f64, 0.0f64);
        for r in &rows {
            err = err.max(r.e);
            mag = mag.max(r.hs);
        }
        if err.is_nan() || err > super::TOLERANCE * mag {
            return None;
        }
        terms.push(term);
        rows.extend((rows.len()..k).map(|_| CRow::empty()));
        s = rows;
    }
    let last = s.len() - 1;
    for i in 0..=last {
        if s[i].len() == 0 {
            let r = s[last - i].reversed();
            s[i] = r;
        }
    }
    Some((s, terms))
}
