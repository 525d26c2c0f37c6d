//! Rows (linear functionals of the input control points, each coefficient with a bound of
//! its error) and the end interpolation of seed 000 Theorem 14.5.1 on them: the generic
//! twins of `../ends.rs`.
//!
//! Every builder of this module runs its algorithm on *rows*: a row is the linear functional
//! `sum_j row[j] P_j` of the input points; the input points themselves are the unit rows (or,
//! inside a stepwise reduction, the rows of the previous step's output).

use super::tracked::{Base, Tracked};

/// A linear functional of the input points: its coefficients computed in the base
/// arithmetic and, beside each, a bound of its distance from the exact coefficient (a
/// running error analysis as [`Tracked`]'s, kept as two plain arrays so that the row
/// operations below are straight loops without per-number bookkeeping).
#[derive(Debug)]
pub(crate) struct Row<B: 'static> {
    /// The computed coefficients.
    pub(crate) v: Vec<B>,
    /// `e[c] >= |v[c] - exact_c|` (raw: the final rounding to `f64` and the rounding of
    /// the error computation itself are added by [`Row::rounded`]).
    pub(crate) e: Vec<f64>,
}

/// The rows of an operator and its own-bound terms `(coef, functional)`.
pub(crate) type Rows<B> = (Vec<Row<B>>, Vec<(f64, Row<B>)>);

/// The allowance per rounding relative to the magnitudes involved: `U / (1 - U)` rounded up.
fn ru<B: Base>() -> f64 {
    B::U * (1.0 + 1e-6)
}

/// `|x|` of a base number (as `f64`, within a relative `2^-52`, which the final doubling of
/// [`Row::rounded`] covers).
fn mag<B: Base>(x: B) -> f64 {
    x.to_f64().abs()
}

/// The most buffers [`pool`] keeps per element type (a build at degree 64 holds a few
/// hundred rows at once; beyond this, dropped rows free their buffers as usual).
const POOL_CAP: usize = 256;

thread_local! {
    /// Spare `f64` buffers (error arrays, and values of `f64` rows).
    static POOL_F64: std::cell::RefCell<Vec<Vec<f64>>> = const { std::cell::RefCell::new(Vec::new()) };
    /// Spare double-word buffers (values of double-word rows).
    static POOL_DD: std::cell::RefCell<Vec<Vec<super::dd::Dd>>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// A per-thread pool of row buffers (goes beyond the seed: a performance device only). A
/// stepwise build makes and drops hundreds of short rows (each step's output replaces its
/// input), and `malloc` / `free` were 30–45 % of an `f64` stepwise build; a dropped row's
/// buffers are kept here and [`Row::zeros`] takes them back, cleared and refilled with
/// zeros, so the values are exactly those of a fresh allocation.
mod pool {
    use super::{POOL_CAP, POOL_DD, POOL_F64};
    use std::any::Any;

    /// An empty buffer of capacity `>= len` if the pool has one of `T`'s kind.
    pub(super) fn take<T: 'static>(len: usize) -> Option<Vec<T>> {
        let mut out: Option<Vec<T>> = None;
        {
            let slot: &mut dyn Any = &mut out;
            if let Some(o) = slot.downcast_mut::<Option<Vec<f64>>>() {
                *o = POOL_F64
                    .try_with(|p| p.try_borrow_mut().ok()?.pop())
                    .ok()
                    .flatten();
            } else if let Some(o) = slot.downcast_mut::<Option<Vec<super::super::dd::Dd>>>() {
                *o = POOL_DD
                    .try_with(|p| p.try_borrow_mut().ok()?.pop())
                    .ok()
                    .flatten();
            }
        }
        out.map(|mut v| {
            v.clear();
            v.reserve(len);
            v
        })
    }

    /// Keeps `v`'s buffer for a later [`take`] (if the pool has room and `T` a pool).
    pub(super) fn give<T: 'static>(v: &mut Vec<T>) {
        if v.capacity() == 0 {
            return;
        }
        let slot: &mut dyn Any = v;
        if let Some(v) = slot.downcast_mut::<Vec<f64>>() {
            let _ = POOL_F64.try_with(|p| {
                if let Ok(mut p) = p.try_borrow_mut() {
                    if p.len() < POOL_CAP {
                        p.push(std::mem::take(v));
                    }
                }
            });
        } else if let Some(v) = slot.downcast_mut::<Vec<super::super::dd::Dd>>() {
            let _ = POOL_DD.try_with(|p| {
                if let Ok(mut p) = p.try_borrow_mut() {
                    if p.len() < POOL_CAP {
                        p.push(std::mem::take(v));
                    }
                }
            });
        }
    }
}

/// `len` zeros in a buffer from the per-thread pool (scratch space; give it back with
/// [`recycle_f64`]).
pub(crate) fn scratch_f64(len: usize) -> Vec<f64> {
    let mut v = pool::take::<f64>(len).unwrap_or_default();
    v.resize(len, 0.0);
    v
}

/// Returns a scratch buffer to the per-thread pool.
pub(crate) fn recycle_f64(mut v: Vec<f64>) {
    pool::give(&mut v);
}

impl<B: 'static> Drop for Row<B> {
    fn drop(&mut self) {
        pool::give(&mut self.v);
        pool::give(&mut self.e);
    }
}

impl<B: Base> Clone for Row<B> {
    /// A copy in buffers from the per-thread [`pool`] when it has some.
    fn clone(&self) -> Self {
        let mut v = pool::take::<B>(self.v.len()).unwrap_or_default();
        v.extend_from_slice(&self.v);
        let mut e = pool::take::<f64>(self.e.len()).unwrap_or_default();
        e.extend_from_slice(&self.e);
        Self { v, e }
    }
}

impl<B: Base> Row<B> {
    /// `len` exact zeros (buffers from the per-thread [`pool`] when it has some).
    pub(crate) fn zeros(len: usize) -> Self {
        let mut v = pool::take::<B>(len).unwrap_or_default();
        v.resize(len, B::of(0.0));
        let mut e = pool::take::<f64>(len).unwrap_or_default();
        e.resize(len, 0.0);
        Self { v, e }
    }

    /// The unit row `e_i` of length `len`.
    pub(crate) fn unit(len: usize, i: usize) -> Self {
        let mut r = Self::zeros(len);
        r.v[i] = B::of(1.0);
        r
    }

    /// A row of tracked entries.
    pub(crate) fn from_tracked(x: &[Tracked<B>]) -> Self {
        Self {
            v: x.iter().map(|t| t.value()).collect(),
            e: x.iter().map(|t| t.bound()).collect(),
        }
    }

    /// Entry `c` as a tracked number.
    pub(crate) fn at(&self, c: usize) -> Tracked<B> {
        Tracked::from_parts(self.v[c], self.e[c])
    }

    /// The row with its entries in reverse order.
    pub(crate) fn reversed(&self) -> Self {
        let mut r = self.clone();
        r.v.reverse();
        r.e.reverse();
        r
    }

    /// The row in `f64` arithmetic: each entry rounded (to nearest, up to one more
    /// rounding: at most `2u |v|`, allowed as `eps |v|` with a margin), its error bound carried.
    pub(crate) fn to_f64_row(&self) -> Row<f64> {
        let v: Vec<f64> = self.v.iter().map(|x| x.to_f64()).collect();
        let e = v
            .iter()
            .zip(&self.e)
            .map(|(x, e)| e + f64::EPSILON * (1.0 + 1e-9) * x.abs())
            .collect();
        Row { v, e }
    }

    /// An `f64` row in this arithmetic (exactly), its error bound carried.
    pub(crate) fn from_f64_row(r: &Row<f64>) -> Self {
        Self {
            v: r.v.iter().map(|&x| B::of(x)).collect(),
            e: r.e.clone(),
        }
    }

    /// The entries rounded to `f64` and a rigorous bound of `sum_c |val_c - exact_c|`: the
    /// final rounding (`B::TO_F64 |val|`, with a margin for `|val|` against `|v|`; none in
    /// `f64`) and the rounding of the error computation itself, a relative
    /// `(1 + 2u)^D - 1` after a chain of `D` operations on the (non-negative) error terms,
    /// below `1e-9` for `D <= 10^6` (a build's chains are at most about `10^5` long at
    /// degree 64), allowed as `1e-6`. ([`Tracked::err`] doubles instead, for its scalars.)
    pub(crate) fn rounded(&self) -> (Vec<f64>, f64) {
        let v: Vec<f64> = self.v.iter().map(|x| x.to_f64()).collect();
        let round = B::TO_F64 * (1.0 + 1e-6);
        let err: f64 = v
            .iter()
            .zip(&self.e)
            .map(|(x, e)| e + round * x.abs())
            .sum();
        (v, err * (1.0 + 1e-6))
    }
}

/// `0` as a tracked number.
pub(crate) fn zero<B: Base>() -> Tracked<B> {
    Tracked::of(0.0)
}

/// The `len` unit rows `e_0..e_{len-1}`.
pub(crate) fn identity<B: Base>(len: usize) -> Vec<Row<B>> {
    (0..len).map(|i| Row::unit(len, i)).collect()
}

/// `y[..] += a x[off..off + len(y)]` on raw arrays (see [`axpy`]).
pub(crate) fn axpy_window<B: Base>(y: &mut Row<B>, a: Tracked<B>, x: &Row<B>, off: usize) {
    let (av, ae) = (a.value(), a.bound());
    let am = mag(av);
    if am == 0.0 && ae == 0.0 {
        return;
    }
    let u = ru::<B>();
    let len = y.v.len();
    let (xv, xe) = (&x.v[off..off + len], &x.e[off..off + len]);
    for (((yv, ye), xv), xe) in y.v.iter_mut().zip(y.e.iter_mut()).zip(xv).zip(xe) {
        let t = av.mul(*xv);
        *yv = yv.add(t);
        *ye += am * xe + ae * (mag(*xv) + xe) + u * (mag(t) + mag(*yv));
    }
}

/// `y[lo..=hi] += a x[lo..=hi]` (as [`axpy`]; for an `x` that is zero, value and error,
/// outside `lo..=hi`, where the full update would only add roundings of `y + 0`; nothing
/// for an empty range `lo > hi`).
pub(crate) fn axpy_range<B: Base>(y: &mut Row<B>, a: Tracked<B>, x: &Row<B>, lo: usize, hi: usize) {
    if lo > hi || hi >= y.v.len() || hi >= x.v.len() {
        if lo <= hi {
            axpy(y, a, x);
        }
        return;
    }
    let (av, ae) = (a.value(), a.bound());
    let am = mag(av);
    if am == 0.0 && ae == 0.0 {
        return;
    }
    let u = ru::<B>();
    let ys = y.v[lo..=hi].iter_mut().zip(y.e[lo..=hi].iter_mut());
    for ((yv, ye), (xv, xe)) in ys.zip(x.v[lo..=hi].iter().zip(&x.e[lo..=hi])) {
        let t = av.mul(*xv);
        *yv = yv.add(t);
        *ye += am * xe + ae * (mag(*xv) + xe) + u * (mag(t) + mag(*yv));
    }
}

/// The smallest `lo..=hi` outside which the row is zero, value and error (`(1, 0)`, an empty
/// range, for a zero row).
pub(crate) fn support<B: Base>(x: &Row<B>) -> (usize, usize) {
    // (A value compares equal to the exact zero only if it is zero: an unusual
    // representation of zero would only widen the range.)
    let zero = B::of(0.0);
    let nz = |c: &usize| x.v[*c] != zero || x.e[*c] != 0.0;
    let len = x.v.len();
    match ((0..len).find(nz), (0..len).rev().find(nz)) {
        (Some(lo), Some(hi)) => (lo, hi),
        _ => (1, 0),
    }
}

/// `y += a x`. Per entry: `|a| e_x + e_a (|x| + e_x)` propagated, plus the roundings of the
/// product and the sum (`U (|a x| + |y|)`).
pub(crate) fn axpy<B: Base>(y: &mut Row<B>, a: Tracked<B>, x: &Row<B>) {
    axpy_window(y, a, x, 0);
}

/// `h + reversed(h)` (`minus`: `h - reversed(h)`), entry `c` from `h_c` and `h_(len-1-c)`
/// (their error bounds added, plus the rounding of the sum).
pub(crate) fn plus_mirror<B: Base>(h: &Row<B>, minus: bool) -> Row<B> {
    let len = h.v.len();
    let u = ru::<B>();
    let mut out = Row::zeros(len);
    for c in 0..len {
        let (x, y) = (h.v[c], h.v[len - 1 - c]);
        let z = if minus { x.sub(y) } else { x.add(y) };
        out.v[c] = z;
        out.e[c] = h.e[c] + h.e[len - 1 - c] + u * mag(z);
    }
    out
}

/// `a x + b y`.
pub(crate) fn lin2<B: Base>(a: Tracked<B>, x: &Row<B>, b: Tracked<B>, y: &Row<B>) -> Row<B> {
    let mut out = y.clone();
    let (bv, be) = (b.value(), b.bound());
    let (bm, u) = (mag(bv), ru::<B>());
    for ((ov, oe), yv) in out.v.iter_mut().zip(out.e.iter_mut()).zip(&y.v) {
        let t = bv.mul(*yv);
        *oe = bm * *oe + be * (mag(*yv) + *oe) + u * mag(t);
        *ov = t;
    }
    axpy(&mut out, a, x);
    out
}

/// `(a x + b y) / d` for exact constants `a`, `b` and `d != 0`.
pub(crate) fn lin2_exact<B: Base>(a: f64, x: &Row<B>, b: f64, y: &Row<B>, d: f64) -> Row<B> {
    let (ab, bb, db) = (B::of(a), B::of(b), B::of(d));
    let (aa, ba, di, u) = (a.abs(), b.abs(), 1.0 / d.abs(), ru::<B>());
    // Written into zeroed arrays (no `push`: a straight loop the compiler can vectorise).
    let len = x.v.len().min(y.v.len());
    let mut out = Row::zeros(len);
    let outs = out.v.iter_mut().zip(out.e.iter_mut());
    let ins = x.v.iter().zip(&x.e).zip(y.v.iter().zip(&y.e));
    for ((ov, oe), ((xv, xe), (yv, ye))) in outs.zip(ins) {
        let (s, t) = (ab.mul(*xv), bb.mul(*yv));
        let q = s.add(t);
        let z = q.div(db);
        *ov = z;
        *oe = ((aa * xe + ba * ye + u * (mag(s) + mag(t) + mag(q))) * di + u * mag(z))
            * (1.0 + 1e-12);
    }
    out
}

/// `x / d` (an infinite error bound if `d` is not bounded away from zero).
pub(crate) fn div<B: Base>(x: &Row<B>, d: Tracked<B>) -> Row<B> {
    let (dv, de) = (d.value(), d.bound());
    let room = mag(dv) * (1.0 - 1e-12) - de;
    let u = ru::<B>();
    let mut out = x.clone();
    for (v, e) in out.v.iter_mut().zip(out.e.iter_mut()) {
        let z = v.div(dv);
        let zm = mag(z) * (1.0 + 1e-12);
        *e = if room > 0.0 {
            (*e + zm * de) / room + u * zm
        } else {
            f64::INFINITY
        };
        *v = z;
    }
    out
}

/// `x * a`.
pub(crate) fn scale<B: Base>(x: &Row<B>, a: Tracked<B>) -> Row<B> {
    let (av, ae) = (a.value(), a.bound());
    let (am, u) = (mag(av), ru::<B>());
    let mut out = x.clone();
    for (v, e) in out.v.iter_mut().zip(out.e.iter_mut()) {
        let t = av.mul(*v);
        *e = am * *e + ae * (mag(*v) + *e) + u * mag(t);
        *v = t;
    }
    out
}

/// `x_c *= a` for one entry `c` in place (as [`scale`] entrywise).
pub(crate) fn scale_entry<B: Base>(x: &mut Row<B>, c: usize, a: Tracked<B>) {
    let (av, ae) = (a.value(), a.bound());
    let v = x.v[c];
    let t = av.mul(v);
    x.e[c] = mag(av) * x.e[c] + ae * (mag(v) + x.e[c]) + ru::<B>() * mag(t);
    x.v[c] = t;
}

/// `sum_c x_c a_c` (`a` tracked scalars, one per column) as a tracked number.
pub(crate) fn dot<B: Base>(x: &Row<B>, a: &[Tracked<B>]) -> Tracked<B> {
    let mut s = Tracked::of(0.0);
    for (c, ac) in a.iter().enumerate().take(x.v.len()) {
        s = s.fma(x.at(c), *ac);
    }
    s
}

/// `sum_i x_(off+i) a_i` (`a` tracked scalars) as a tracked number (as [`dot`] on a window
/// of `x`, with an a-priori bound instead of [`Tracked`]'s running one): the value is the
/// recursive sum of the rounded products in the base arithmetic, whose rounding is at most
/// `γ_L(U) sum |x̂ â|` (`L` terms, `γ_L(U) = L U / (1 - L U)`, Higham, *Accuracy and
/// Stability*, eq. 3.5, for any arithmetic with relative error `U` per operation), and the
/// inputs' errors add `sum (|x̂| e_a + e_x (|â| + e_a))`. The magnitudes are taken in `f64`
/// (within a relative `2u` of the base values), allowed for by a factor `1 + 4u`.
pub(crate) fn dot_window<B: Base>(x: &Row<B>, off: usize, a: &[Tracked<B>]) -> Tracked<B> {
    let end = (off + a.len()).min(x.v.len());
    if off >= end {
        return Tracked::of(0.0);
    }
    let (xv, xe) = (&x.v[off..end], &x.e[off..end]);
    let mut s = B::of(0.0);
    let (mut mags, mut prop) = (0.0f64, 0.0f64);
    for ((xv, xe), ac) in xv.iter().zip(xe).zip(a) {
        let (av, ae) = (ac.value(), ac.bound());
        s = s.add(xv.mul(av));
        let (xm, am) = (mag(*xv), mag(av));
        mags += xm * am;
        prop += xm * ae + xe * (am + ae);
    }
    #[allow(clippy::cast_precision_loss, reason = "L <= 200")]
    let l = (end - off) as f64;
    let gamma = l * B::U / (1.0 - l * B::U);
    Tracked::from_parts(
        s,
        (prop + gamma * mags * (1.0 + 4.0 * f64::EPSILON)) * (1.0 + 4.0 * f64::EPSILON),
    )
}

/// `i64` of an index (indices here are at most 130).
#[allow(clippy::cast_possible_wrap, reason = "small indices")]
pub(crate) fn to_i(x: usize) -> i64 {
    x as i64
}

/// `usize` of a non-negative small integer.
#[allow(
    clippy::cast_sign_loss,
    clippy::cast_possible_truncation,
    reason = "0 <= x <= 130"
)]
pub(crate) fn idx(x: i64) -> usize {
    debug_assert!(x >= 0);
    x as usize
}

/// `b_ij = C(m,i) C(n-m,j-i) / C(n,j)` (Lemma 14.5.1; `0` off the band).
pub(crate) fn b<B: Base>(m: i64, n: i64, i: i64, j: i64) -> Tracked<B> {
    Tracked::binom(m, i)
        .mul(Tracked::binom(n - m, j - i))
        .div(Tracked::binom(n, j))
}

/// Eq. 14.5.10 on rows (as `ends::end_points`): `Q_0..Q_r` and `Q_{m-p}..Q_m` as functionals,
/// the input points being the rows `input` (`n + 1` of them).
pub(crate) fn end_points<B: Base>(
    n: usize,
    m: usize,
    r: i32,
    p: i32,
    input: &[Row<B>],
) -> (Vec<Row<B>>, Vec<Row<B>>) {
    let (ni, mi) = (to_i(n), to_i(m));
    let mut left: Vec<Row<B>> = Vec::new();
    for j in 0..=i64::from(r) {
        let mut q = input[idx(j)].clone();
        for i in (j - (ni - mi)).max(0)..j {
            axpy(&mut q, b::<B>(mi, ni, i, j).neg(), &left[idx(i)]);
        }
        left.push(div(&q, b(mi, ni, j, j)));
    }
    let mut right_rev: Vec<Row<B>> = Vec::new();
    for j in 0..=i64::from(p) {
        let mut q = input[idx(ni - j)].clone();
        for i in (j - (ni - mi)).max(0)..j {
            axpy(
                &mut q,
                b::<B>(mi, ni, mi - i, ni - j).neg(),
                &right_rev[idx(i)],
            );
        }
        right_rev.push(div(&q, b(mi, ni, mi - j, ni - j)));
    }
    right_rev.reverse();
    (left, right_rev)
}

/// The auxiliary points `P^I_j`, `j = r+1..=n-p-1` (as `ends::auxiliary`).
pub(crate) fn auxiliary<B: Base>(
    n: usize,
    m: usize,
    r: i32,
    p: i32,
    left: &[Row<B>],
    right: &[Row<B>],
    input: &[Row<B>],
) -> Vec<Row<B>> {
    let (ni, mi) = (to_i(n), to_i(m));
    let (r, p) = (i64::from(r), i64::from(p));
    ((r + 1)..=(ni - p - 1))
        .map(|j| {
            let mut a = input[idx(j)].clone();
            for (i, q) in left.iter().enumerate() {
                axpy(&mut a, b::<B>(mi, ni, to_i(i), j).neg(), q);
            }
            for (k, q) in right.iter().enumerate() {
                axpy(&mut a, b::<B>(mi, ni, mi - p + to_i(k), j).neg(), q);
            }
            a
        })
        .collect()
}
