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

/// `γ_7 = 7 u / (1 - 7 u)`.
const GAMMA7: f64 = 7.0 * U / (1.0 - 7.0 * U);

/// `1 + 64 γ_8`: covers the rounding of a sum of at most 130 non-negative terms in four
/// lanes (`γ_(n+3)` for `n` terms).
const SUM_UP: f64 = 1.0 + 64.0 * (8.0 * U / (1.0 - 8.0 * U));

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

    /// The row `(h, l)` with its bounds `(H, L, E)`.
    fn from_parts(h: &[f64], l: &[f64], st: St) -> Self {
        let mut r = Self::zeros(h.len());
        r.h.copy_from_slice(h);
        r.l.copy_from_slice(l);
        (r.hs, r.ls, r.e) = st;
        r
    }

    /// The bounds `(H, L, E)`.
    fn st(&self) -> St {
        (self.hs, self.ls, self.e)
    }

    /// Replaces `H` and `L` by the row's own sums ([`sums`]); `false` outside Dekker's
    /// range.
    fn own_sums(&mut self) -> bool {
        match sums(&self.h, &self.l) {
            Some((hs, ls)) => {
                (self.hs, self.ls) = (hs, ls);
                true
            }
            None => false,
        }
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

/// `p + e = a x` exactly: `e = fma(a, x, -p)` (`FMA`), else Dekker's product with `a`'s
/// split `(a1, a2)` given. Both give the same `e` (the exact rest of the rounded product),
/// so the two instances of the kernels give the same bits.
#[inline(always)]
fn two_prod<const FMA: bool>(a: f64, a1: f64, a2: f64, x: f64) -> (f64, f64) {
    let p = a * x;
    if FMA {
        (p, a.mul_add(x, -p))
    } else {
        let (x1, x2) = split(x);
        (p, ((a1 * x1 - p) + a1 * x2 + a2 * x1) + a2 * x2)
    }
}

/// Whether the AVX2 + FMA instances of the kernels run on this CPU.
pub(super) fn fused() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        crate::bezier::lanes::isa() != crate::bezier::lanes::Isa::Portable
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// The loop of [`lin2_into`]: `o = a x + b y` entrywise (arrays of one length).
#[inline(always)]
fn lin2_body<const FMA: bool>(
    o: (&mut [f64], &mut [f64]),
    a: Coef,
    x: (&[f64], &[f64]),
    b: Coef,
    y: (&[f64], &[f64]),
) {
    let len = o.0.len().min(x.0.len()).min(y.0.len());
    let (oh, ol) = (&mut o.0[..len], &mut o.1[..len]);
    let (xh, xl, yh, yl) = (&x.0[..len], &x.1[..len], &y.0[..len], &y.1[..len]);
    let (a1, a2) = split(a.h);
    let (b1, b2) = split(b.h);
    for c in 0..len {
        let (p1, e1) = two_prod::<FMA>(a.h, a1, a2, xh[c]);
        let (p2, e2) = two_prod::<FMA>(b.h, b1, b2, yh[c]);
        let (r, er) = two_sum(p1, p2);
        oh[c] = r;
        ol[c] = ((er + e1) + e2) + ((a.h * xl[c] + a.l * xh[c]) + (b.h * yl[c] + b.l * yh[c]));
    }
}

/// [`lin2_body`] compiled with AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn lin2_fused(
    o: (&mut [f64], &mut [f64]),
    a: Coef,
    x: (&[f64], &[f64]),
    b: Coef,
    y: (&[f64], &[f64]),
) {
    lin2_body::<true>(o, a, x, b, y);
}

/// The loop of [`axpy_into`]: `y += a x` entrywise.
#[inline(always)]
fn axpy_body<const FMA: bool>(y: (&mut [f64], &mut [f64]), a: Coef, x: (&[f64], &[f64])) {
    let len = y.0.len().min(x.0.len());
    let (yh, yl) = (&mut y.0[..len], &mut y.1[..len]);
    let (xh, xl) = (&x.0[..len], &x.1[..len]);
    let (a1, a2) = split(a.h);
    for c in 0..len {
        let (p1, e1) = two_prod::<FMA>(a.h, a1, a2, xh[c]);
        let (r, er) = two_sum(yh[c], p1);
        yl[c] = ((yl[c] + er) + e1) + (a.h * xl[c] + a.l * xh[c]);
        yh[c] = r;
    }
}

/// [`axpy_body`] compiled with AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn axpy_fused(y: (&mut [f64], &mut [f64]), a: Coef, x: (&[f64], &[f64])) {
    axpy_body::<true>(y, a, x);
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
        + GAMMA7 * z
        + U * s
        + UNDERFLOW;
    (
        e * MARGIN,
        (1.0 + U) * (1.0 + U) * t * MARGIN,
        (1.0 + GAMMA7) * z * MARGIN,
    )
}

/// The rows (`m + 1`) and bound terms `(coef, functional)` of a compensated build.
pub(crate) type Built = (Vec<CRow>, Vec<(f64, CRow)>);

/// The constants of one kind of row operation of a step.
#[derive(Debug, Clone, Copy)]
enum Kind {
    /// `Delta^k`'s `(-1)^(k-i) C(k,i)`, `i < k/2`, and half the middle one (`i = k/2`, even
    /// `k`).
    Delta,
    /// The forward recursion's `(k / (k-i), -i / (k-i))`, `1 <= i < k`.
    Forward,
    /// Farin's `(-1)^(n-i) i / (n C(n,i))`, `n = k - 1`, `1 <= i < k`.
    Farin,
    /// The perturbation's `-(-1)^(k-i) C(k,i) / (C(2k,k) - 2)`.
    Perturb,
}

/// The constants of `kind` for step `k` (`k <= 64`), by index `i`, computed once per process
/// in tracked double-word (a few operations on exact integers each); one not
/// [`Coef::usable`] gets a NaN error bound, which makes the route give up.
fn table(kind: Kind, k: usize) -> &'static [(Coef, Coef)] {
    use std::sync::OnceLock;
    const N: usize = cagd_core::MAX_DEGREE + 2;
    type Table = OnceLock<Vec<(Coef, Coef)>>;
    static TABLES: [[Table; N]; 4] = [const { [const { OnceLock::new() }; N] }; 4];
    let Some(cell) = TABLES[kind as usize].get(k) else {
        return &[];
    };
    cell.get_or_init(|| {
        let ki = to_i(k);
        let one = Coef::exact(1.0);
        let checked = |c: Coef| {
            if c.usable() {
                c
            } else {
                Coef { e: f64::NAN, ..c }
            }
        };
        (0..=k)
            .map(|i| {
                let ii = to_i(i);
                let c = match kind {
                    Kind::Delta if 2 * i == k => sign_binom::<Dd>(k, i).mul(Tracked::of(0.5)),
                    Kind::Delta => sign_binom::<Dd>(k, i),
                    Kind::Forward | Kind::Farin if i == 0 || i == k => return (one, one),
                    Kind::Forward => {
                        let d = Tracked::<Dd>::small(ki - ii);
                        let a = Coef::of(Tracked::small(ki).div(d));
                        let b = Coef::of(Tracked::small(-ii).div(d));
                        return (checked(a), checked(b));
                    }
                    Kind::Farin => {
                        let n = ki - 1;
                        let c =
                            Tracked::small(ii).div(Tracked::small(n).mul(Tracked::binom(n, ii)));
                        if (n - ii) % 2 == 1 { c.neg() } else { c }
                    }
                    Kind::Perturb => {
                        let d = Tracked::<Dd>::binom(2 * ki, ki).sub(Tracked::of(2.0));
                        sign_binom::<Dd>(k, i).div(d).neg()
                    }
                };
                (checked(Coef::of(c)), one)
            })
            .collect()
    })
}

/// A row's bounds `(H, L, E)`: `H >= sum |h|`, `L >= sum |l|`, `E >= sum |h + l - exact|`.
type St = (f64, f64, f64);

/// The sums `sum |h|` and `sum |l|` rounded up (`1 + 64 γ_8` covers the rounding of a sum of
/// at most 130 non-negative terms in four lanes), or `None` if an `h` is outside the range
/// where Dekker's product is exact (`0 < |h| < TINY`, or `sum |h| >= 2^900`).
#[inline(always)]
fn sums_body(h: &[f64], l: &[f64]) -> Option<(f64, f64)> {
    // `low[j]`: the least non-zero `|h|` of lane `j` (infinity if none).
    let (mut hs, mut ls, mut low) = ([0.0f64; 4], [0.0f64; 4], [f64::INFINITY; 4]);
    let mut hc = h.chunks_exact(4);
    let mut lc = l.chunks_exact(4);
    for (h, l) in (&mut hc).zip(&mut lc) {
        for j in 0..4 {
            let a = h[j].abs();
            hs[j] += a;
            ls[j] += l[j].abs();
            let t = if a > 0.0 { a } else { f64::INFINITY };
            low[j] = if t < low[j] { t } else { low[j] };
        }
    }
    for (h, l) in hc.remainder().iter().zip(lc.remainder()) {
        let a = h.abs();
        hs[0] += a;
        ls[0] += l.abs();
        let t = if a > 0.0 { a } else { f64::INFINITY };
        low[0] = if t < low[0] { t } else { low[0] };
    }
    let hs = ((hs[0] + hs[1]) + (hs[2] + hs[3])) * SUM_UP;
    let ls = ((ls[0] + ls[1]) + (ls[2] + ls[3])) * SUM_UP;
    // (A NaN entry makes `hs` NaN, refused by the comparison.)
    let ok = low.iter().all(|&x| x >= TINY) && hs < 2f64.powi(900);
    ok.then_some((hs, ls))
}

/// [`sums_body`] compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn sums_fused(h: &[f64], l: &[f64]) -> Option<(f64, f64)> {
    sums_body(h, l)
}

/// [`sums_body`] (the AVX2 instance where the CPU has it: the same sums).
fn sums(h: &[f64], l: &[f64]) -> Option<(f64, f64)> {
    if fused() {
        #[cfg(target_arch = "x86_64")]
        #[allow(unsafe_code, reason = "the call of a `target_feature` function")]
        // SAFETY: the CPU has AVX2 and FMA (`fused`), the function's only requirement; the
        // function is itself safe code.
        return unsafe { sums_fused(h, l) };
    }
    sums_body(h, l)
}

/// `o = a x + b y` entrywise; returns `E` of the result ([`bound`]).
fn lin2_into(
    o: (&mut [f64], &mut [f64]),
    a: Coef,
    x: ((&[f64], &[f64]), St),
    b: Coef,
    y: ((&[f64], &[f64]), St),
) -> f64 {
    if fused() {
        #[cfg(target_arch = "x86_64")]
        #[allow(unsafe_code, reason = "the call of a `target_feature` function")]
        // SAFETY: as in [`sums`].
        unsafe {
            lin2_fused(o, a, x.0, b, y.0);
        }
    } else {
        lin2_body::<false>(o, a, x.0, b, y.0);
    }
    bound(a, x.1, b, y.1).0
}

/// `y += a x` entrywise; returns the bounds of the result ([`bound`] with `b = 1`, a-priori
/// `H` and `L`).
fn axpy_into(y: (&mut [f64], &mut [f64]), ys: St, a: Coef, x: ((&[f64], &[f64]), St)) -> St {
    if fused() {
        #[cfg(target_arch = "x86_64")]
        #[allow(unsafe_code, reason = "the call of a `target_feature` function")]
        // SAFETY: as in [`sums`].
        unsafe {
            axpy_fused(y, a, x.0);
        }
    } else {
        axpy_body::<false>(y, a, x.0);
    }
    let (e, hs, ls) = bound(a, x.1, Coef::exact(1.0), ys);
    (hs, ls, e)
}

/// The first half of a step's rows: up to `rows` rows of `len` entries in two flat arrays
/// (two blocks per build, used in turn), with their bounds (one per row in use).
struct Block {
    h: Vec<f64>,
    l: Vec<f64>,
    len: usize,
    st: Vec<St>,
}

impl Drop for Block {
    fn drop(&mut self) {
        recycle_f64(std::mem::take(&mut self.h));
        recycle_f64(std::mem::take(&mut self.l));
    }
}

impl Block {
    /// Room for `rows` rows of `len` entries (zeros), `rows` in use.
    fn new(rows: usize, len: usize) -> Self {
        Self {
            h: scratch_f64(rows * len),
            l: scratch_f64(rows * len),
            len,
            st: vec![(0.0, 0.0, 0.0); rows],
        }
    }

    /// `rows` rows in use (their entries are written before they are read).
    fn reuse(&mut self, rows: usize) {
        self.st.clear();
        self.st.resize(rows, (0.0, 0.0, 0.0));
    }

    /// Row `i` with its bounds.
    fn row(&self, i: usize) -> ((&[f64], &[f64]), St) {
        let r = i * self.len..(i + 1) * self.len;
        ((&self.h[r.clone()], &self.l[r]), self.st[i])
    }

    /// Row `i`, mutable.
    fn row_mut(&mut self, i: usize) -> (&mut [f64], &mut [f64]) {
        let r = i * self.len..(i + 1) * self.len;
        (&mut self.h[r.clone()], &mut self.l[r])
    }

    /// Row `i - 1` and row `i` (mutable), `i >= 1`.
    #[allow(clippy::type_complexity, reason = "two rows of two arrays")]
    fn pair_mut(&mut self, i: usize) -> ((&[f64], &[f64]), (&mut [f64], &mut [f64])) {
        let len = self.len;
        let (h0, h1) = self.h.split_at_mut(i * len);
        let (l0, l1) = self.l.split_at_mut(i * len);
        (
            (&h0[(i - 1) * len..], &l0[(i - 1) * len..]),
            (&mut h1[..len], &mut l1[..len]),
        )
    }

    /// Replaces row `i`'s `H` and `L` by its own sums; `false` outside Dekker's range.
    fn own_sums(&mut self, i: usize) -> bool {
        let ((h, l), _) = self.row(i);
        match sums(h, l) {
            Some((hs, ls)) => {
                (self.st[i].0, self.st[i].1) = (hs, ls);
                true
            }
            None => false,
        }
    }
}

/// `Delta^k s` of reversal-symmetric rows (as `steps::delta_k_symmetric`; `s` holds rows
/// `0..=k/2`): `h + (-1)^k reversed(h)`, `h = sum_(i < k/2) (-1)^(k-i) C(k,i) s_i` (plus half
/// the middle term for even `k`); the binomials are exact double-words.
fn delta(s: &Block, k: usize) -> Option<CRow> {
    let len = s.len;
    let mut h = CRow::zeros(len);
    let add = |h: &mut CRow, c: Coef, i: usize| {
        let st = h.st();
        (h.hs, h.ls, h.e) = axpy_into((&mut h.h, &mut h.l), st, c, s.row(i));
    };
    // `(-1)^(k-i) C(k,i)`, `i < k/2`, then half the middle one for even `k`.
    let coefs = table(Kind::Delta, k);
    for (i, c) in coefs.iter().enumerate().take(k.div_ceil(2)) {
        add(&mut h, c.0, i);
    }
    if k % 2 == 0 {
        add(&mut h, coefs[k / 2].0, k / 2);
    }
    // The mirror image of `h`, then `h ± reversed(h)`.
    let mut rev = CRow::from_parts(&h.h, &h.l, h.st());
    rev.h.reverse();
    rev.l.reverse();
    let sign = if k % 2 == 1 { -1.0 } else { 1.0 };
    let mut out = CRow::zeros(len);
    out.e = lin2_into(
        (&mut out.h, &mut out.l),
        Coef::exact(1.0),
        ((&h.h, &h.l), h.st()),
        Coef::exact(sign),
        ((&rev.h, &rev.l), rev.st()),
    );
    out.own_sums().then_some(out)
}

/// The forward recursion `P_i = (k s_i - i P_(i-1)) / (k - i)`, `i = 0..=last`, as
/// `P_i = (k / (k-i)) s_i - (i / (k-i)) P_(i-1)` with double-word constants.
fn forward(s: &Block, k: usize, last: usize, out: &mut Block) -> Option<()> {
    out.reuse(last + 1);
    let ((h0, l0), st0) = s.row(0);
    out.row_mut(0).0.copy_from_slice(h0);
    out.row_mut(0).1.copy_from_slice(l0);
    out.st[0] = st0;
    let coefs = table(Kind::Forward, k);
    for (i, &(a, b)) in coefs.iter().enumerate().take(last + 1).skip(1) {
        let ys = out.st[i - 1];
        let (prev, o) = out.pair_mut(i);
        let e = lin2_into(o, a, s.row(i), b, (prev, ys));
        out.st[i].2 = e;
        if !out.own_sums(i) {
            return None;
        }
    }
    Some(())
}

/// One step `k -> k-1` on the first half of reversal-symmetric rows (`s`: rows
/// `0..=k/2`): the output's first half and the step's bound term `(coef, Delta^k s)`;
/// `None` outside Dekker's range.
fn step(method: Method, s: &mut Block, rows: &mut Block, k: usize) -> Option<(f64, CRow)> {
    let n = k - 1;
    let half = n / 2;
    let d = delta(s, k)?;
    let dv = ((&d.h[..], &d.l[..]), d.st());
    match method {
        Method::Farin => {
            // `steps::farin`: `Q_i = P^I_i + (i/n) (-1)^(n-i) delta / C(n,i)`.
            forward(s, k, half, rows)?;
            let coefs = table(Kind::Farin, k);
            for (i, c) in coefs.iter().enumerate().take(half + 1).skip(1) {
                let st = rows.st[i];
                rows.st[i] = axpy_into(rows.row_mut(i), st, c.0, dv);
                if !rows.own_sums(i) {
                    return None;
                }
            }
        }
        Method::Perturb => {
            // `pbar_i = s_i - (-1)^(k-i) C(k,i) delta / (C(2k,k) - 2)`, `0 < i <= n/2` (in
            // place: `s` is not read again), then the forward half of the inverse elevation.
            let coefs = table(Kind::Perturb, k);
            for (i, c) in coefs.iter().enumerate().take(half + 1).skip(1) {
                let st = s.st[i];
                s.st[i] = axpy_into(s.row_mut(i), st, c.0, dv);
                if !s.own_sums(i) {
                    return None;
                }
            }
            forward(s, k, half, rows)?;
        }
        _ => return None,
    }
    let coef = match method {
        Method::Perturb => perturb_coef(k),
        _ => residual_coef_cached(method, k)?,
    };
    Some((coef, d))
}

/// The operator `n -> m` of Farin's method or the perturbation method by compensated steps:
/// its rows (`m + 1`) and bound terms, or `None` (another method, outside Dekker's range, or
/// a step's proven error already above [`super::TOLERANCE`] of its rows' magnitudes: the
/// route would be refused, and the next one is tried).
pub(crate) fn stepwise(method: Method, n: usize, m: usize) -> Option<Built> {
    if !matches!(method, Method::Farin | Method::Perturb) || m >= n {
        return None;
    }
    // Only the first half of each step's input is read (`steps::mirror`): rows `0..=k/2`.
    let len = n + 1;
    let mut s = Block::new(n / 2 + 1, len);
    for i in 0..=n / 2 {
        s.row_mut(i).0[i] = 1.0;
        s.st[i] = (1.0, 0.0, 0.0);
    }
    let mut rows = Block::new(n / 2 + 1, len);
    let mut terms = Vec::with_capacity(n - m);
    for k in ((m + 1)..=n).rev() {
        let term = step(method, &mut s, &mut rows, k)?;
        // (A NaN bound, from a constant not usable, fails the comparison.)
        let mag = rows.st.iter().fold(0.0f64, |a, st| a.max(st.0));
        let within = |e: f64| {
            e.partial_cmp(&(super::TOLERANCE * mag))
                .is_some_and(|o| o.is_le())
        };
        if !rows.st.iter().all(|st| within(st.2)) {
            return None;
        }
        terms.push(term);
        std::mem::swap(&mut s, &mut rows);
    }
    // Rows `m/2 + 1..=m` are the mirror images of rows `m - i`.
    let out = (0..=m)
        .map(|i| {
            let j = if i <= m / 2 { i } else { m - i };
            let ((h, l), st) = s.row(j);
            let mut r = CRow::from_parts(h, l, st);
            if j != i {
                r.h.reverse();
                r.l.reverse();
            }
            r
        })
        .collect();
    Some((out, terms))
}
