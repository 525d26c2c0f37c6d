//! Rows of tracked numbers (linear functionals of the input control points) and the end
//! interpolation of seed 000 Theorem 14.5.1 on them: the generic twins of `../ends.rs`.
//!
//! Every builder of this module runs its algorithm on *rows*: a row is the linear functional
//! `sum_j row[j] P_j` of the input points; the input points themselves are the unit rows (or,
//! inside a stepwise reduction, the rows of the previous step's output).

use super::tracked::{Base, Tracked};

/// A linear functional of the input points.
pub(crate) type Row<B> = Vec<Tracked<B>>;

/// The rows of an operator and its own-bound terms `(coef, functional)`.
pub(crate) type Rows<B> = (Vec<Row<B>>, Vec<(f64, Row<B>)>);

/// `0` as a tracked number.
pub(crate) fn zero<B: Base>() -> Tracked<B> {
    Tracked::of(0.0)
}

/// The `len` unit rows `e_0..e_{len-1}`.
pub(crate) fn identity<B: Base>(len: usize) -> Vec<Row<B>> {
    (0..len)
        .map(|i| {
            (0..len)
                .map(|j| Tracked::of(if i == j { 1.0 } else { 0.0 }))
                .collect()
        })
        .collect()
}

/// `y += a x` (exact zeros of `x` skipped: they change nothing, error included).
pub(crate) fn axpy<B: Base>(y: &mut [Tracked<B>], a: Tracked<B>, x: &[Tracked<B>]) {
    for (u, v) in y.iter_mut().zip(x) {
        if !v.is_exact_zero() {
            *u = u.fma(a, *v);
        }
    }
}

/// `a x + b y`.
pub(crate) fn lin2<B: Base>(
    a: Tracked<B>,
    x: &[Tracked<B>],
    b: Tracked<B>,
    y: &[Tracked<B>],
) -> Row<B> {
    x.iter().zip(y).map(|(u, v)| a.mul(*u).fma(b, *v)).collect()
}

/// `a x + b y` for exact constants `a`, `b`, divided by the exact constant `d`.
pub(crate) fn lin2_exact<B: Base>(
    a: f64,
    x: &[Tracked<B>],
    b: f64,
    y: &[Tracked<B>],
    d: f64,
) -> Row<B> {
    x.iter()
        .zip(y)
        .map(|(u, v)| {
            if u.is_exact_zero() && v.is_exact_zero() {
                *u
            } else {
                u.scale_by(a).add(v.scale_by(b)).div_by(d)
            }
        })
        .collect()
}

/// `x / d`.
pub(crate) fn div<B: Base>(x: &[Tracked<B>], d: Tracked<B>) -> Row<B> {
    x.iter().map(|u| u.div(d)).collect()
}

/// `x * a`.
pub(crate) fn scale<B: Base>(x: &[Tracked<B>], a: Tracked<B>) -> Row<B> {
    x.iter().map(|u| u.mul(a)).collect()
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
fn b<B: Base>(m: i64, n: i64, i: i64, j: i64) -> Tracked<B> {
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
