//! The generalized inverse with fixed ends (seed 000 eqs. 14.4.8–14.4.15) as a rank-two
//! correction of the free one (beyond the seed: the seed solves the interior normal
//! equations; the exact route still does, `../least_squares.rs`).
//!
//! With `A` the elevation `m -> n`, `H = A^T A` and `X = H^(-1) A^T` the free generalized
//! inverse (= the L2 reduction, Lutterkort–Peters–Reif, built by the Jacobi truncation),
//! fixing `Q_0 = P_0`, `Q_m = P_n` is the equality-constrained least-squares problem
//! `min ||A Q - P||` s.t. `C Q = D P` (`C` picks `Q_0, Q_m`, `D` picks `P_0, P_n`; the rows
//! `0` and `n` of `A Q - P` then vanish, so this is eq. 14.4.12's interior problem). Its
//! solution is `Q = (X + H^(-1) C^T (C H^(-1) C^T)^(-1) (D - C X)) P`, and since
//! `H^(-1) = X X^T`, everything comes from `X`: with `x_0`, `x_m` the first and last rows of
//! `X`, `y_0 = X x_0`, `y_m = X x_m` and the 2x2 matrix
//! `G = [[y_0[0], y_m[0]], [y_0[m], y_m[m]]]` (`= C X X^T C^T`),
//! row `i` is `X_i + (a_i, b_i) . (e_0 - x_0, e_n - x_m)` with `(a_i, b_i) = (y_0[i], y_m[i]) G^(-1)`.
//! `O(n m)` work on top of `X`, every number tracked.

use super::rows::{Row, Rows, axpy, dot};
use super::tracked::{Base, Tracked};
use super::truncation::{Family, truncated};

/// The rows of the generalized inverse with fixed ends, `n -> m` (no own-bound terms).
/// (`mixed`: as [`truncated`]'s.)
pub(crate) fn ginv_ends<B: Base>(n: usize, m: usize, mixed: bool) -> Rows<B> {
    if m <= 1 {
        let rows = if m == 0 {
            // Not reachable through `Method::check` (two fixed ends need m >= 1); kept total.
            vec![Row::unit(n + 1, 0)]
        } else {
            vec![Row::unit(n + 1, 0), Row::unit(n + 1, n)]
        };
        return (rows, Vec::new());
    }
    let (x, _) = truncated::<B>(Family::Jacobi { a: 0, b: 0 }, n, m, -1, -1, None, mixed);
    let tr = |r: &Row<B>| -> Vec<Tracked<B>> { (0..=n).map(|c| r.at(c)).collect() };
    let x0 = tr(&x[0]);
    // y_0[i] = X_i . x_0; X is centro-symmetric (the free problem is), so y_m[i] = y_0[m-i].
    let y0: Vec<Tracked<B>> = x.iter().map(|row| dot(row, &x0)).collect();
    let ym: Vec<Tracked<B>> = (0..=m).map(|i| y0[m - i]).collect();
    let (g00, g01, g10, g11) = (y0[0], ym[0], y0[m], ym[m]);
    let det = g00.mul(g11).sub(g01.mul(g10));
    // D - C X as two rows.
    let mut r0 = Row::unit(n + 1, 0);
    axpy(&mut r0, Tracked::of(-1.0), &x[0]);
    let mut r1 = Row::unit(n + 1, n);
    axpy(&mut r1, Tracked::of(-1.0), &x[m]);
    let mut rows = Vec::with_capacity(m + 1);
    rows.push(Row::unit(n + 1, 0));
    for i in 1..m {
        let a = y0[i].mul(g11).sub(ym[i].mul(g10)).div(det);
        let b = ym[i].mul(g00).sub(y0[i].mul(g01)).div(det);
        let mut row = x[i].clone();
        axpy(&mut row, a, &r0);
        axpy(&mut row, b, &r1);
        rows.push(row);
    }
    rows.push(Row::unit(n + 1, n));
    (rows, Vec::new())
}
