//! Forrest's and Piegl–Tiller's stepwise reduction (SPEC-reduce §3; seed 000 chapter
//! introduction and eq. 14.5.10) on plain `f64` rows with one error bound *per row* (the
//! arithmetic goes beyond the seed): the same operations, in the same order, as the `f64`
//! instance of `steps.rs`'s symmetric steps, so the same matrix bit for bit, without the
//! per-entry error array of [`super::rows::Row`].
//!
//! **The bound.** Every bound of the tracked route is a sum of non-negative terms linear in
//! the entries' magnitudes and errors, so its sum over a row is the same expression in the
//! row sums `H >= sum_c |v_c|` (computed, rounded up) and `E >= sum_c |v_c - exact_c|`
//! (Higham, *Accuracy and Stability*, §3.1: `fl(x op y) = (x op y)(1 + δ) = (x op y) / (1 +
//! δ')`, `|δ|, |δ'| <= u`). For `z = (a x + b y) / d` (exact small integers `a, b, d`):
//! `sum_c |ẑ_c - z_c| <= (|a| E_x + |b| E_y + u (|a| H_x + |b| H_y + sum |q̂|)) / |d| + u
//! sum |ẑ|`, and `sum |q̂| <= |d| sum |ẑ| / (1 - u)`, so
//!
//! `E_z <= (|a| E_x + |b| E_y + u (|a| H_x + |b| H_y)) / |d| + 2 u (1 + 2u) H_z`.
//!
//! For `y += a x` (a tracked constant `a`, `|â - a| <= ε_a`): `E_y' <= E_y + |â| E_x + ε_a
//! (H_x + E_x) + u ((1 + u) |â| H_x + H_y')`; for `z_c = h_c ± h_(len-1-c)`: `E_z <= 2 E_h +
//! u H_z`. The sums `H` are recomputed from each new row (four lanes; their rounding,
//! at most `γ_130 < 1.5e-14` relative, is covered by `1 + 1e-13`), so cancellation keeps
//! the bounds as tight as the per-entry ones; every bound computation is a few `f64`
//! operations on non-negative numbers, covered by a factor `1 + 1e-9`, and `1e-300` per
//! operation covers products and quotients that underflow.
//!
//! **The supports.** A symmetric step reads only the first half of its input
//! (`steps::mirror`), and the forward recursion's row `i` reads input rows `0..=i`: from
//! the unit rows, row `i` of every step is zero beyond column `i` (the middle row of an even
//! step, `(f + reversed(f)) / 2`, is full, and only `Delta^k` reads it), so the row
//! operations run over each row's support only.

use super::Rounded;
use super::rows::{recycle_f64, scratch_f64, to_i};
use super::steps::{central_binomial_share, residual_coef_cached};
use super::tracked::Tracked;
use crate::bezier::method::Method;

/// The unit roundoff of `f64`.
const U: f64 = f64::EPSILON / 2.0;

/// The margin for the rounding of the bound computations themselves.
const MARGIN: f64 = 1.0 + 1e-9;

/// Covers the rounding of a sum of at most 130 non-negative terms (`γ_130 < 1.5e-14`).
const SUM_UP: f64 = 1.0 + 1e-13;

/// An absolute allowance per row operation for products and quotients that underflow (each
/// at most `2^-1075`, at most 65 per row).
const UNDERFLOW: f64 = 1e-300;

/// A small index as an exact `f64`.
#[allow(clippy::cast_precision_loss, reason = "indices <= 130")]
fn f(i: usize) -> f64 {
    i as f64
}

/// `sum_c |x_c|` rounded up (four lanes, which the compiler vectorises).
fn abs_sum(x: &[f64]) -> f64 {
    let mut acc = [0.0f64; 4];
    let mut chunks = x.chunks_exact(4);
    for c in &mut chunks {
        for j in 0..4 {
            acc[j] += c[j].abs();
        }
    }
    for (j, v) in chunks.remainder().iter().enumerate() {
        acc[j] += v.abs();
    }
    ((acc[0] + acc[1]) + (acc[2] + acc[3])) * SUM_UP
}

/// `(-1)^(k-i) C(k,i)` rounded to `f64` (the value of `steps::sign_binom`, from the table of
/// the exact binomials rounded once), with a bound of its rounding: none below `2^53`, else
/// the tracked one.
fn sign_binom(k: usize, i: usize) -> Tracked<f64> {
    let v = cagd_core::binomial_f64(k, i);
    let e = if v < 2f64.powi(53) {
        0.0
    } else {
        Tracked::<f64>::binom(to_i(k), to_i(i)).bound()
    };
    Tracked::from_parts(if (k - i) % 2 == 0 { v } else { -v }, e)
}

/// A row of the result: its `f64` entries and the bound of `sum_c |v_c - exact_c|`.
#[derive(Debug)]
pub(crate) struct SRow {
    v: Vec<f64>,
    e: f64,
}

impl Drop for SRow {
    fn drop(&mut self) {
        recycle_f64(std::mem::take(&mut self.v));
    }
}

impl Rounded for SRow {
    fn rounded(&self) -> (Vec<f64>, f64) {
        (self.v.clone(), self.e)
    }
    fn len(&self) -> usize {
        self.v.len()
    }
}

/// A row's bounds `(H, E)`: `H >= sum |v|`, `E >= sum |v - exact|`.
type St = (f64, f64);

/// The first half of a step's rows: rows of `len` entries in one flat array (two blocks per
/// build, used in turn), with their bounds and supports (entries from `sup[i]` on are exact
/// zeros).
struct Block {
    v: Vec<f64>,
    len: usize,
    st: Vec<St>,
    sup: Vec<usize>,
}

impl Drop for Block {
    fn drop(&mut self) {
        recycle_f64(std::mem::take(&mut self.v));
    }
}

impl Block {
    /// Room for `rows` zero rows of `len` entries.
    fn new(rows: usize, len: usize) -> Self {
        Self {
            v: scratch_f64(rows * len),
            len,
            st: vec![(0.0, 0.0); rows],
            sup: vec![0; rows],
        }
    }

    /// Row `i` over its support, with its bounds.
    fn row(&self, i: usize) -> (&[f64], St) {
        let start = i * self.len;
        (&self.v[start..start + self.sup[i]], self.st[i])
    }

    /// The first `w` entries of row `i` (`w <= len`; zeros beyond its support).
    fn head(&self, i: usize, w: usize) -> &[f64] {
        &self.v[i * self.len..i * self.len + w]
    }

    /// Makes row `i`'s support `w` (zeroing what lay beyond it) and returns the first `w`
    /// entries of row `i - 1` (none for `i = 0`) and of row `i`, mutable.
    fn prepare(&mut self, i: usize, w: usize) -> (&[f64], &mut [f64]) {
        let start = i * self.len;
        if self.sup[i] > w {
            self.v[start + w..start + self.sup[i]].fill(0.0);
        }
        self.sup[i] = w;
        let (before, from) = self.v.split_at_mut(start);
        let prev = if i > 0 {
            &before[start - self.len..start - self.len + w]
        } else {
            &before[..0]
        };
        (prev, &mut from[..w])
    }
}

/// The forward recursion `P_i = (k s_i - i P_(i-1)) / (k - i)`, `i = 0..=last` (as
/// `steps::forward` in `f64`: products, sum and quotient rounded in that order).
fn forward(s: &Block, k: usize, last: usize, out: &mut Block) {
    {
        let (x, st) = s.row(0);
        let (_, o) = out.prepare(0, x.len());
        o.copy_from_slice(x);
        out.st[0] = st;
    }
    for i in 1..=last {
        let (xs, ys) = (s.st[i], out.st[i - 1]);
        let w = s.sup[i].max(out.sup[i - 1]);
        let x = s.head(i, w);
        let (a, b, d) = (f(k), -f(i), f(k - i));
        let (y, o) = out.prepare(i, w);
        for ((o, x), y) in o.iter_mut().zip(x).zip(y) {
            *o = (a * x + b * y) / d;
        }
        let hz = abs_sum(o);
        let e = (a * xs.1 + f(i) * ys.1 + U * (a * xs.0 + f(i) * ys.0)) / d
            + 2.0 * U * (1.0 + 2.0 * U) * hz
            + UNDERFLOW;
        out.st[i] = (hz, e * MARGIN);
    }
}

/// Row `i` replaced by `(f + reversed(f)) / 2` (`f` the row over the full length; the
/// result is its own mirror image), as `steps`'s `lin2_exact(1, f, 1, reversed(f), 2)`
/// (the same values; the bound without roundings of the exact products by 1 and halving).
fn middle(out: &mut Block, i: usize) {
    let len = out.len;
    let (_, fs) = out.row(i);
    let (_, o) = out.prepare(i, len);
    for c in 0..len / 2 {
        let z = (o[c] + o[len - 1 - c]) / 2.0;
        o[c] = z;
        o[len - 1 - c] = z;
    }
    if len % 2 == 1 {
        let c = len / 2;
        o[c] = (o[c] + o[c]) / 2.0;
    }
    let hz = abs_sum(o);
    // The sums' roundings `u |f_c + f_(len-1-c)| = 2u |z_c|` halved (the halving is exact
    // but for underflow), the errors `(e_c + e_(len-1-c)) / 2` summed: `E_f + u H_z`.
    let e = fs.1 + U * hz + UNDERFLOW;
    out.st[i] = (hz, e * MARGIN);
}

/// `y += a x` (`x` no longer than `y`, the rest of `y` unchanged); returns the new bounds
/// of `y`.
fn axpy(y: &mut [f64], ys: St, a: Tracked<f64>, x: (&[f64], St)) -> St {
    let (av, ae) = (a.value(), a.bound());
    let (xv, xs) = x;
    for (yc, xc) in y.iter_mut().zip(xv) {
        *yc += av * xc;
    }
    let hy = abs_sum(y);
    let am = av.abs();
    let e = ys.1 + am * xs.1 + ae * (xs.0 + xs.1) + U * ((1.0 + U) * am * xs.0 + hy) + UNDERFLOW;
    (hy, e * MARGIN)
}

/// `Delta^k s` of reversal-symmetric rows (as `steps::delta_k_symmetric` in `f64`; `s`
/// holds rows `0..=k/2`): `h + (-1)^k reversed(h)`, `h = sum_(i < k/2) (-1)^(k-i) C(k,i)
/// s_i` (plus half the middle term for even `k`).
fn delta(s: &Block, k: usize) -> SRow {
    let len = s.len;
    let mut h = scratch_f64(len);
    let (mut hst, mut w) = ((0.0, 0.0), 0usize);
    let mut add = |h: &mut [f64], c: Tracked<f64>, i: usize| {
        let x = s.row(i);
        w = w.max(x.0.len());
        hst = axpy(&mut h[..w], hst, c, x);
    };
    for i in 0..k.div_ceil(2) {
        add(&mut h, sign_binom(k, i), i);
    }
    if k % 2 == 0 {
        let c = sign_binom(k, k / 2);
        // (Halving is exact.)
        let half = Tracked::from_parts(0.5 * c.value(), 0.5 * c.bound());
        add(&mut h, half, k / 2);
    }
    let mut v = scratch_f64(len);
    if k % 2 == 1 {
        for c in 0..len {
            v[c] = h[c] - h[len - 1 - c];
        }
    } else {
        for c in 0..len {
            v[c] = h[c] + h[len - 1 - c];
        }
    }
    recycle_f64(h);
    let hz = abs_sum(&v);
    let e = (2.0 * hst.1 + U * hz + UNDERFLOW) * MARGIN;
    SRow { v, e }
}

/// Piegl–Tiller's auxiliary point of an odd `m = k - 1` on symmetric rows (as
/// `rows::auxiliary` with `r = p = o = (m - 1) / 2`): by one degree only two of eq.
/// 14.5.10's `b_ij` are non-zero, `b_(o, o+1) = C(m, o) / C(k, o+1) = 1/2` and
/// `b_(o+1, o+1)` = the same, on the left end point `Q_o` and on the right one, its mirror
/// image; so `g = s_(o+1) - (Q_o + reversed(Q_o)) / 2`.
fn auxiliary(s: &Block, out: &Block, o: usize) -> SRow {
    let len = s.len;
    let (x, xs) = (s.head(o + 1, len), s.st[o + 1]);
    let (q, qs) = (out.head(o, len), out.st[o]);
    let mut v = scratch_f64(len);
    for c in 0..len {
        v[c] = x[c] - 0.5 * (q[c] + q[len - 1 - c]);
    }
    let hz = abs_sum(&v);
    // `t`: its rounding `u |t|` (summed: `u (1 + u) 2 H_q`), halved exactly; the
    // difference's rounding `u H_g`.
    let e = xs.1 + qs.1 + U * (1.0 + U) * qs.0 + U * hz + UNDERFLOW;
    SRow { v, e: e * MARGIN }
}

/// The rows (`m + 1`) and bound terms `(coef, functional)` of a row-bound build.
pub(crate) type Built = (Vec<SRow>, Vec<(f64, SRow)>);

/// The operator `n -> m` of Forrest's or Piegl–Tiller's method on `f64` rows with per-row
/// bounds: its rows and bound terms, or `None` (another method, or a step's proven error
/// above `8 (n+3) eps` of its rows' magnitudes, four times what `build` accepts: the route
/// would be refused, and the next one is tried).
pub(crate) fn stepwise(method: Method, n: usize, m: usize) -> Option<Built> {
    if !matches!(method, Method::Forrest | Method::PieglTiller) || m >= n {
        return None;
    }
    let len = n + 1;
    let mut s = Block::new(n / 2 + 1, len);
    for i in 0..=n / 2 {
        s.v[i * len + i] = 1.0;
        s.sup[i] = i + 1;
        s.st[i] = (1.0, 0.0);
    }
    let mut rows = Block::new(n / 2 + 1, len);
    let limit = 8.0 * (f(n) + 3.0) * f64::EPSILON;
    let mut terms = Vec::with_capacity(n - m);
    for k in ((m + 1)..=n).rev() {
        let nk = k - 1;
        forward(&s, k, nk / 2, &mut rows);
        if nk % 2 == 0 {
            middle(&mut rows, nk / 2);
        }
        let term = if method == Method::PieglTiller && nk % 2 == 1 {
            (central_binomial_share(k), auxiliary(&s, &rows, nk / 2))
        } else {
            (residual_coef_cached(method, k)?, delta(&s, k))
        };
        terms.push(term);
        let mag = rows.st[..=nk / 2].iter().fold(0.0f64, |a, st| a.max(st.0));
        let within = |e: f64| e.partial_cmp(&(limit * mag)).is_some_and(|o| o.is_le());
        if !rows.st[..=nk / 2].iter().all(|st| within(st.1)) {
            return None;
        }
        std::mem::swap(&mut s, &mut rows);
    }
    // Rows `m/2 + 1..=m` are the mirror images of rows `m - i`.
    let out = (0..=m)
        .map(|i| {
            let j = if i <= m / 2 { i } else { m - i };
            let (x, st) = s.row(j);
            let mut v = scratch_f64(len);
            v[..x.len()].copy_from_slice(x);
            if j != i {
                v.reverse();
            }
            SRow { v, e: st.1 }
        })
        .collect();
    Some((out, terms))
}
