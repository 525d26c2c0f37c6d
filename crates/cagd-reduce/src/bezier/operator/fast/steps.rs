//! The one-degree methods (Forrest, Piegl–Tiller, Farin, Eck, perturbation with fixed and
//! with G1 ends; SPEC-reduce §2.1, §2.3, §3, §7) on tracked rows: the twins of
//! `../one_step.rs`. A step `k -> k-1` runs the seed's recursion on the rows of the previous
//! step (functionals of the original points), so composing the steps is `O(n^2 (n - m))`
//! operations, never a dense matrix product.

use super::rows::{
    Row, Rows, auxiliary, div, end_points, identity, idx, lin2, lin2_exact, scale, to_i, zero,
};
use super::tracked::{Base, Tracked};
use crate::bezier::method::Method;

/// One step's output rows and its bound terms `(exact coefficient or None, functional)`.
pub(crate) struct Step<B: 'static> {
    pub(crate) rows: Vec<Row<B>>,
    /// `(coef, g)`: the term `coef ||g . P||` of the step's own bound, `g` a functional of
    /// the original points; `coef` is an `f64` upper bound.
    pub(crate) terms: Vec<(f64, Row<B>)>,
}

/// A small index as an exact `f64`.
#[allow(clippy::cast_precision_loss, reason = "indices <= 130")]
fn f(i: usize) -> f64 {
    i as f64
}

/// `(-1)^(k-i) C(k,i)`.
pub(crate) fn sign_binom<B: Base>(k: usize, i: usize) -> Tracked<B> {
    let c = Tracked::binom(to_i(k), to_i(i));
    if (k - i) % 2 == 0 { c } else { c.neg() }
}

/// `sum_i (-1)^(k-i) C(k,i) s_i` = `Delta^k` of the rows.
fn delta_k<B: Base>(s: &[Row<B>]) -> Row<B> {
    let k = s.len() - 1;
    let mut f = Row::zeros(s[0].v.len());
    for (i, row) in s.iter().enumerate() {
        super::rows::axpy(&mut f, sign_binom(k, i), row);
    }
    f
}

/// `Delta^k` of reversal-symmetric rows (`s_(k-i)` the reversed `s_i`): with
/// `sigma_(k-i) = (-1)^k sigma_i`, it is `h + (-1)^k reversed(h)` for
/// `h = sum_(i < k/2) sigma_i s_i` (plus half the middle term for even `k`, whose row is
/// its own mirror image): half the row updates of [`delta_k`].
fn delta_k_symmetric<B: Base>(s: &[Row<B>]) -> Row<B> {
    let k = s.len() - 1;
    let mut h = Row::zeros(s[0].v.len());
    for (i, row) in s.iter().enumerate().take(k.div_ceil(2)) {
        super::rows::axpy(&mut h, sign_binom(k, i), row);
    }
    if k % 2 == 0 {
        super::rows::axpy(
            &mut h,
            sign_binom(k, k / 2).mul(Tracked::of(0.5)),
            &s[k / 2],
        );
    }
    super::rows::plus_mirror(&h, k % 2 == 1)
}

/// `Delta^k` of a step's input rows, computed on first use and shared by the step and its
/// bound term.
pub(crate) struct Delta<'a, B: 'static> {
    s: &'a [Row<B>],
    symmetric: bool,
    cell: std::cell::OnceCell<Row<B>>,
}

impl<'a, B: Base> Delta<'a, B> {
    /// For the rows `s` (`symmetric`: reversal-symmetric, see [`delta_k_symmetric`]).
    pub(crate) fn new(s: &'a [Row<B>], symmetric: bool) -> Self {
        Self {
            s,
            symmetric,
            cell: std::cell::OnceCell::new(),
        }
    }

    /// The row `Delta^k s`, taken out (no copy when it was computed already).
    pub(crate) fn into_row(self) -> Row<B> {
        self.get();
        self.cell.into_inner().unwrap_or_else(|| Row::zeros(0))
    }

    /// The row `Delta^k s`.
    pub(crate) fn get(&self) -> &Row<B> {
        self.cell.get_or_init(|| {
            if self.symmetric {
                delta_k_symmetric(self.s)
            } else {
                delta_k(self.s)
            }
        })
    }
}

/// Forward recursion `P^I_i = (k s_i - i P^I_{i-1}) / (k - i)`, `i = 0..=last`.
fn forward<B: Base>(s: &[Row<B>], last: usize) -> Vec<Row<B>> {
    let k = s.len() - 1;
    let mut out: Vec<Row<B>> = Vec::with_capacity(last + 1);
    for (i, si) in s.iter().enumerate().take(last + 1) {
        let v = match out.last() {
            None => si.clone(),
            Some(prev) => lin2_exact(f(k), si, -f(i), prev, f(k - i)),
        };
        out.push(v);
    }
    out
}

/// Backward recursion `P^II_{i-1} = (k s_i - (k - i) P^II_i) / i`, `P^II_{k-1} = s_k`, down
/// to index `first`; entry `i - first` holds `P^II_i`.
fn backward<B: Base>(s: &[Row<B>], first: usize) -> Vec<Row<B>> {
    let k = s.len() - 1;
    let mut out: Vec<Row<B>> = vec![s[k].clone()];
    for i in ((first + 1)..k).rev() {
        let next = lin2_exact(f(k), &s[i], -f(k - i), &out[out.len() - 1], f(i));
        out.push(next);
    }
    out.reverse();
    out
}

/// Inverse elevation of a degenerate polygon (eq. 14.2.3): exactly of degree `k-1`, so the
/// forward and the backward recursion give the same points in exact arithmetic; each is
/// used on the half where it does not amplify rounding (Forrest's split).
pub(crate) fn inverse_elevation<B: Base>(pbar: &[Row<B>]) -> Vec<Row<B>> {
    let n = pbar.len() - 2;
    let b0 = n / 2 + 1;
    let mut out = forward(pbar, n / 2);
    if b0 <= n {
        out.extend(backward(pbar, b0));
    }
    out
}

/// Rows `half + 1..=n` left empty (`rows` holds `0..=half`): they are the mirror images of
/// rows `n - i`, which no symmetric step reads (each reads the first half of its input and
/// `Delta^k` by [`delta_k_symmetric`]); [`materialize`] fills them in at the end. The output
/// of a reversal-symmetric step on a reversal-symmetric input (`s_(k-j)` the reversed `s_j`,
/// as the unit rows are) is reversal-symmetric in exact arithmetic, so the mirrored error
/// bounds hold for the mirrored exact rows.
fn mirror<B: Base>(rows: &mut Vec<Row<B>>, n: usize) {
    let half = rows.len() - 1;
    rows.extend((half + 1..=n).map(|_| Row::zeros(0)));
}

/// The rows [`mirror`] left empty, as the mirror images of their partners.
fn materialize<B: Base>(rows: &mut [Row<B>]) {
    let last = rows.len() - 1;
    for i in 0..=last {
        if rows[i].v.is_empty() {
            rows[i] = rows[last - i].reversed();
        }
    }
}

/// The step `k -> k-1` of a one-degree method on the rows `s` (`k + 1` of them).
/// `symmetric`: `s` is reversal-symmetric (`s_(k-j)` the reversed `s_j`: the rows of a
/// stepwise reduction of the unit rows, whose second half [`mirror`] leaves empty), so a
/// reversal-symmetric method (Forrest, Piegl–Tiller, Farin's split form, perturbation)
/// computes the first half of its rows from the first half of `s`. `split`:
/// Farin's step in its split form ([`farin`]) rather than the seed's direct one (the split
/// form is the more accurate in double-word up to degree about 50, the direct one at
/// `(64,10)`; exact arithmetic gives the same).
pub(crate) fn step<B: Base>(
    method: Method,
    s: &[Row<B>],
    delta: &Delta<'_, B>,
    symmetric: bool,
    split: bool,
) -> Step<B> {
    let k = s.len() - 1;
    let n = k - 1;
    match method {
        Method::Forrest if symmetric => {
            // P^II_half is the mirror image of P^I_half.
            let half = n / 2;
            let mut rows = forward(s, half);
            if n % 2 == 0 {
                if let Some(f) = rows.pop() {
                    rows.push(lin2_exact(1.0, &f, 1.0, &f.reversed(), 2.0));
                }
            }
            mirror(&mut rows, n);
            Step {
                rows,
                terms: Vec::new(),
            }
        }
        Method::Forrest => {
            // Forward on the first half, backward on the second (both recursions stop at
            // `n / 2`); the middle point of an even `n` is their average.
            let half = n / 2;
            let mut fwd = forward(s, half);
            let mut bwd = backward(s, half).into_iter();
            let (mid_f, mid_b) = (fwd.pop(), bwd.next());
            let mut rows = fwd;
            if let (Some(f), Some(b)) = (mid_f, mid_b) {
                rows.push(if n % 2 == 0 {
                    lin2_exact(1.0, &f, 1.0, &b, 2.0)
                } else {
                    f
                });
            }
            rows.extend(bwd);
            Step {
                rows,
                terms: Vec::new(),
            }
        }
        Method::Farin if split => Step {
            rows: farin(s, delta.get(), symmetric),
            terms: Vec::new(),
        },
        Method::Farin => {
            let (fwd, bwd) = (forward(s, n), backward(s, 0));
            let rows = (0..=n)
                .map(|i| lin2_exact(f(n - i), &fwd[i], f(i), &bwd[i], f(n)))
                .collect();
            Step {
                rows,
                terms: Vec::new(),
            }
        }
        Method::Eck => {
            let (fwd, bwd) = (forward(s, n), backward(s, 0));
            // lambda_i = S_i / 2^(2n+1), S_i = sum_{j<=i} C(2n+2, 2j) (an exact u128).
            let scale_e = Tracked::of(2f64.powi(-(2 * i32::try_from(n).unwrap_or(0) + 1)));
            let total = 1u128 << (2 * n + 1);
            let mut acc = 0u128;
            let rows = (0..=n)
                .map(|i| {
                    acc += cagd_core::binomial(2 * n + 2, 2 * i);
                    let lambda = Tracked::int(acc).mul(scale_e);
                    let one_minus = Tracked::int(total - acc).mul(scale_e);
                    lin2(one_minus, &fwd[i], lambda, &bwd[i])
                })
                .collect();
            let coef =
                2f64.powi(-(2 * i32::try_from(n).unwrap_or(0) + 1)) * (1.0 + 4.0 * f64::EPSILON);
            Step {
                rows,
                terms: vec![(coef, delta.get().clone())],
            }
        }
        Method::Perturb => {
            let f = delta.get().clone();
            let d = Tracked::binom(2 * to_i(k), to_i(k)).sub(Tracked::of(2.0));
            // Symmetric: only `pbar_0..=pbar_(n/2)` are read (the forward half of the
            // inverse elevation); the rest stay empty.
            let used = if symmetric { n / 2 } else { k };
            let pbar: Vec<Row<B>> = (0..=k)
                .map(|i| {
                    if i > used {
                        Row::zeros(0)
                    } else if i > 0 && i < k {
                        let c = sign_binom::<B>(k, i).div(d).neg();
                        lin2(Tracked::of(1.0), &s[i], c, &f)
                    } else {
                        s[i].clone()
                    }
                })
                .collect();
            let rows = if symmetric {
                let mut rows = forward(&pbar, n / 2);
                mirror(&mut rows, n);
                rows
            } else {
                inverse_elevation(&pbar)
            };
            Step {
                rows,
                terms: vec![(perturb_coef(k), f)],
            }
        }
        Method::PerturbG1 { l1, l2 } => {
            let f = delta.get().clone();
            let ki = to_i(k);
            let sd = Tracked::binom(2 * ki, ki).sub(Tracked::small(2 + 2 * ki * ki));
            let (l1, l2) = (Tracked::of(l1), Tracked::of(l2));
            let one = Tracked::of(1.0);
            let d1 = lin2(one, &s[1], one.neg(), &s[0]);
            let d2 = lin2(one, &s[k - 1], one.neg(), &s[k]);
            let mut fp = f;
            super::rows::axpy(&mut fp, sign_binom::<B>(k, 1).mul(l1), &d1);
            super::rows::axpy(&mut fp, sign_binom::<B>(k, k - 1).mul(l2), &d2);
            let pbar: Vec<Row<B>> = (0..=k)
                .map(|i| {
                    if i == 1 {
                        lin2(one, &s[1], l1, &d1)
                    } else if i == k - 1 {
                        lin2(one, &s[k - 1], l2, &d2)
                    } else if i > 1 && i < k - 1 {
                        lin2(one, &s[i], sign_binom::<B>(k, i).div(sd).neg(), &fp)
                    } else {
                        s[i].clone()
                    }
                })
                .collect();
            Step {
                rows: inverse_elevation(&pbar),
                terms: Vec::new(),
            }
        }
        Method::PieglTiller => piegl_tiller(s, symmetric),
        // Multi-degree methods never come here (checked by the caller).
        _ => Step {
            rows: Vec::new(),
            terms: Vec::new(),
        },
    }
}

/// Farin's step `Q_i = ((n - i) P^I_i + i P^II_i) / n` (SPEC-reduce §2.3) in a stable
/// form (beyond the seed): writing `s = E q + delta e_k` (`delta = Delta^k s`), the forward
/// recursion never reads `s_k`, so `P^I = q`, and the backward one gives
/// `P^II_i = q_i + delta (-1)^(n-i) / C(n,i)` (its run on `e_k`). Hence
/// `Q_i = P^I_i + (i/n) (-1)^(n-i) delta / C(n,i)` for `i <= n/2`, where the forward
/// recursion damps rounding (`i < k - i`), and `Q_i = P^II_i - ((n-i)/n) (-1)^(n-i) delta /
/// C(n,i)` above, where the backward one does: no recursion runs into its amplifying half
/// (the direct form lost 9 digits in `f64` at `(30,15)`).
fn farin<B: Base>(s: &[Row<B>], delta: &Row<B>, symmetric: bool) -> Vec<Row<B>> {
    let k = s.len() - 1;
    let n = k - 1;
    let half = n / 2;
    let mut rows = forward(s, half);
    if half < n && !symmetric {
        rows.extend(backward(s, half + 1));
    }
    let nn = Tracked::<B>::small(to_i(n));
    for (i, row) in rows.iter_mut().enumerate() {
        let w = if i <= half { i } else { n - i };
        if w == 0 {
            continue;
        }
        let mut c = Tracked::small(to_i(w)).div(nn.mul(Tracked::binom(to_i(n), to_i(i))));
        if ((n - i) % 2 == 1) == (i <= half) {
            c = c.neg();
        }
        super::rows::axpy(row, c, delta);
    }
    if symmetric {
        mirror(&mut rows, n);
    }
    rows
}

/// The perturbation bound factor `W_k / (C(2k,k) - 2)` rounded up (as `one_step.rs`),
/// remembered per `k` for the process (a constant of the step, computed with big rationals).
pub(crate) fn perturb_coef(k: usize) -> f64 {
    use std::sync::OnceLock;
    const N: usize = cagd_core::MAX_DEGREE + 2;
    static MEMO: [OnceLock<f64>; N] = [const { OnceLock::new() }; N];
    let exact = || {
        let d = crate::exact::binom_q(2 * to_i(k), to_i(k)) - crate::exact::frac(2, 1);
        crate::bezier::wn_table::perturbation_error_factor(k) / crate::exact::q_to_f64(&d)
            * (1.0 + 8.0 * f64::EPSILON)
    };
    match MEMO.get(k) {
        Some(cell) => *cell.get_or_init(exact),
        None => exact(),
    }
}

/// Piegl–Tiller step (as `one_step::piegl_tiller`).
/// (`symmetric`: the right end points as the mirror images of the left ones, `r = p`.)
fn piegl_tiller<B: Base>(s: &[Row<B>], symmetric: bool) -> Step<B> {
    let k = s.len() - 1;
    let m = k - 1;
    let o = (to_i(m) - 1).div_euclid(2);
    let (r, p) = (i32::try_from(o).unwrap_or(0), i32::try_from(o).unwrap_or(0));
    let (left, right) = if symmetric {
        // By one degree (`n - m = 1`), eq. 14.5.10 is the forward recursion:
        // `b_(j-1,j) = j/k`, `b_(j,j) = (k-j)/k`, so `Q_j = (k s_j - j Q_(j-1)) / (k - j)`.
        let left = if o >= 0 {
            forward(s, idx(o))
        } else {
            Vec::new()
        };
        // The right end points only for the auxiliary point of an odd `m` (the output's
        // second half is left to [`mirror`]).
        let right = if m % 2 == 1 {
            left.iter().rev().map(Row::reversed).collect()
        } else {
            Vec::new()
        };
        (left, right)
    } else {
        end_points(k, m, r, p, s)
    };
    let mut rows = left.clone();
    let mut terms = Vec::new();
    if m % 2 == 0 {
        let (ki, ri, mi, pi) = (to_i(k), i64::from(r), to_i(m), i64::from(p));
        let mut ql = scale(&s[idx(ri + 1)], Tracked::small(ki));
        if let Some(qr) = left.last() {
            super::rows::axpy(&mut ql, Tracked::small(-(ri + 1)), qr);
        }
        let ql = div(&ql, Tracked::small(ki - (ri + 1)));
        // Symmetric: the right one is the mirror image (its input row is not stored).
        let qr = if symmetric {
            ql.reversed()
        } else {
            let mut qr = scale(&s[idx(mi - pi)], Tracked::small(ki));
            if let Some(first) = right.first() {
                super::rows::axpy(&mut qr, Tracked::small(-(ki - mi + pi)), first);
            }
            div(&qr, Tracked::small(mi - pi))
        };
        let h = Tracked::of(0.5);
        rows.push(lin2(h, &ql, h, &qr));
    } else {
        let aux = auxiliary(k, m, r, p, &left, &right, s);
        if let Some(g) = aux.into_iter().next() {
            terms.push((central_binomial_share(k), g));
        }
    }
    if symmetric {
        mirror(&mut rows, m);
    } else {
        rows.extend(right);
    }
    Step { rows, terms }
}

/// `C(k, k/2) / 2^k` rounded up (Piegl–Tiller's bound factor, as `one_step.rs`'s exact
/// `up`, at most one ulp above it): the binomial rounded up to `f64` times an exact power
/// of two.
pub(crate) fn central_binomial_share(k: usize) -> f64 {
    let c = cagd_core::binomial(k, k / 2);
    #[allow(
        clippy::cast_precision_loss,
        reason = "rounded, then corrected upwards"
    )]
    let mut f = c as f64;
    #[allow(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "an integer-valued f64 below 2^128"
    )]
    if (f as u128) < c {
        // One ulp up at least (`f 2^-52 >= ulp(f)`).
        f *= 1.0 + f64::EPSILON;
    }
    f * 2f64.powi(-i32::try_from(k).unwrap_or(i32::MAX))
}

/// For a step without a bound of its own that reproduces degree `k-1` (every one-degree
/// method but G1 with non-zero `l`): the residual `P - E Q` is `r_i Delta^k P_0` row by row
/// (its kernel holds the elevated polygons), so `max_i |r_i|` (from the step applied to `e_0`,
/// rounded up with its tracked error) is the exact convex-hull coefficient of the step
/// (as `one_step::residual_term`). `None` for G1 with non-zero `l`.
pub(crate) fn residual_coef<B: Base>(method: Method, k: usize) -> Option<f64> {
    if let Method::PerturbG1 { l1, l2 } = method {
        if l1 != 0.0 || l2 != 0.0 {
            return None;
        }
    }
    // The step on the single column e_0.
    let e0: Vec<Row<B>> = (0..=k)
        .map(|i| {
            if i == 0 {
                Row::unit(1, 0)
            } else {
                Row::zeros(1)
            }
        })
        .collect();
    let q: Vec<Tracked<B>> = step(method, &e0, &Delta::new(&e0, false), false, true)
        .rows
        .iter()
        .map(|r| r.at(0))
        .collect();
    // Residual column 0: e_0 - E q; r_i = res_i / c_0, c_0 = (-1)^k.
    let kk = Tracked::small(to_i(k));
    let mut coef = 0.0f64;
    for i in 0..=k {
        let mut el = zero::<B>();
        if i > 0 {
            el = el.fma(Tracked::small(to_i(i)).div(kk), q[i - 1]);
        }
        if i < k {
            el = el.fma(Tracked::small(to_i(k - i)).div(kk), q[i]);
        }
        let res = Tracked::of(if i == 0 { 1.0 } else { 0.0 }).sub(el);
        coef = coef.max(res.val().abs() + res.err());
    }
    Some(coef * (1.0 + 4.0 * f64::EPSILON))
}

/// [`residual_coef`] in double-word, remembered per `(method, k)` for the process: a
/// constant of the step (like the `W_n` table of `wn_table.rs`), whose `O(k)` evaluation on
/// one-column rows is allocation-bound (about 40 % of a Forrest build at `(30,15)`). The
/// methods without parameters have a fixed table per `k` (a hashed look-up cost about 700
/// instructions, 7 % of a row-bound Forrest build at `(30,15)`).
pub(crate) fn residual_coef_cached(method: Method, k: usize) -> Option<f64> {
    use std::collections::HashMap;
    use std::sync::{OnceLock, RwLock};
    const N: usize = cagd_core::MAX_DEGREE + 2;
    static PLAIN: [[OnceLock<Option<f64>>; N]; 8] = [const { [const { OnceLock::new() }; N] }; 8];
    if let (key @ 0..=7, 0, 0) = method.key() {
        if let Some(cell) = PLAIN[usize::from(key)].get(k) {
            return *cell.get_or_init(|| residual_coef::<super::dd::Dd>(method, k));
        }
    }
    type Memo = RwLock<HashMap<((u8, u64, u64), usize), Option<f64>>>;
    static MEMO: OnceLock<Memo> = OnceLock::new();
    let memo = MEMO.get_or_init(|| RwLock::new(HashMap::new()));
    let key = (method.key(), k);
    if let Some(c) = memo.read().ok().and_then(|m| m.get(&key).copied()) {
        return c;
    }
    let c = residual_coef::<super::dd::Dd>(method, k);
    if let Ok(mut m) = memo.write() {
        m.insert(key, c);
    }
    c
}

/// The stepwise operator `n -> m`: rows (`m + 1`) and the summed own-bound terms (dropped,
/// like the exact route, if one step has none).
/// (`split`: see [`step`].) `give_up`: `None` once the proven error of a step's rows
/// exceeds this fraction of their inf-norm (the later steps compound it, so the route would
/// be refused anyway: a performance choice for the `f64` attempt only).
pub(crate) fn stepwise<B: Base>(
    method: Method,
    n: usize,
    m: usize,
    split: bool,
    give_up: Option<f64>,
) -> Option<Rows<B>> {
    let mut s = identity::<B>(n + 1);
    // The unit rows are reversal-symmetric, and so is every step's output (see [`mirror`]);
    // G1 and Farin's direct form read every row of their input, and keep them all.
    let symmetric = match method {
        Method::PerturbG1 { .. } => false,
        Method::Farin => split,
        _ => true,
    };
    let mut terms = Vec::new();
    let mut valid = true;
    for k in ((m + 1)..=n).rev() {
        let delta = Delta::new(&s, symmetric);
        let st = step(method, &s, &delta, symmetric, split);
        if valid {
            if st.terms.is_empty() {
                // O(k) work: always in double-word, so the coefficient is tight even when
                // it is tiny beside the step's entries.
                match residual_coef_cached(method, k) {
                    Some(c) => terms.push((c, delta.into_row())),
                    None => valid = false,
                }
            } else {
                terms.extend(st.terms);
            }
        }
        s = st.rows;
        if let Some(limit) = give_up {
            let (mut err, mut norm) = (0.0f64, 0.0f64);
            // The second half mirrors the first (or, for G1, is checked alike).
            for row in s
                .iter()
                .take(if symmetric { s.len() / 2 + 1 } else { s.len() })
            {
                err = err.max(row.e.iter().sum());
                norm = norm.max(row.v.iter().map(|x| x.to_f64().abs()).sum());
            }
            if err.is_nan() || err > limit * norm {
                return None;
            }
        }
    }
    if !valid {
        terms.clear();
    }
    if symmetric {
        materialize(&mut s);
    }
    Some((s, terms))
}
