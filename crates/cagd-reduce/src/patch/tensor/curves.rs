//! Multi-degree tensor-product reduction direction by direction with the cached linear
//! curve operators ([`crate::TensorMethod::Curves`]).

use cagd_core::{Result, TensorPatch};

use super::lines::{map_columns, map_rows};
use crate::{Method, operator};

/// `Q = R_u P R_vᵀ` (columns first, then rows of the intermediate net) and its certified
/// bound `max_j b_u(col j) + max_i b_v(row i)` (the caller takes the minimum with the
/// convex-hull bound).
///
/// Why the sum bound holds: for fixed `v`, `P(u,v) - P1(u,v) = sum_j B_j^n(v) (col_j(u) -
/// R_u col_j(u))`, a convex combination of the column errors; likewise `P1 - Q` is a convex
/// combination (in `u`) of the row errors of the intermediate net `P1`.
pub(crate) fn reduce_curves(
    p: &TensorPatch,
    (mt, nt): (usize, usize),
    u: Method,
    v: Method,
) -> Result<(TensorPatch, f64)> {
    let ((m, n), dim) = (p.degrees(), p.dim());
    let mut bound = 0.0f64;
    let mut net = p.points().to_vec();
    if mt < m {
        let op = operator(u, m, mt)?;
        let mut worst = 0.0f64;
        net = map_columns(&net, (m + 1, n + 1), dim, mt + 1, |a, b| {
            op.apply_into(a, dim, b)?;
            worst = worst.max(op.error_bound(a, b, dim)?);
            Ok(())
        })?;
        bound += worst;
    }
    if nt < n {
        let op = operator(v, n, nt)?;
        let mut worst = 0.0f64;
        net = map_rows(&net, (mt + 1, n + 1), dim, nt + 1, |a, b| {
            op.apply_into(a, dim, b)?;
            worst = worst.max(op.error_bound(a, b, dim)?);
            Ok(())
        })?;
        bound += worst;
    }
    let q = TensorPatch::new(net, mt, nt, dim)?;
    Ok((q, bound * (1.0 + 4.0 * f64::EPSILON)))
}
