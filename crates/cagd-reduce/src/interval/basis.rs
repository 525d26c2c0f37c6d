//! Triangular Bernstein values `B^n_ij(u, v) = n!/(i! j! k!) u^i v^j w^k` in the DESIGN
//! storage order (SPEC-convert §0).

use super::elevation::{tri_indices, trinomial};

/// Triangular Bernstein values `B^n_ij(u, v)` (`w = 1 - u - v`) in storage order.
pub(crate) fn basis_values(n: usize, u: f64, v: f64) -> Vec<f64> {
    basis_with(&trinomials(n), n, u, v)
}

/// The trinomials `n! / (i! j! k!)` in storage order, as doubles.
pub(crate) fn trinomials(n: usize) -> Vec<f64> {
    tri_indices(n)
        .map(|(i, j)| trinomial(n, i, j) as f64)
        .collect()
}

/// [`basis_values`] with the trinomials precomputed.
pub(crate) fn basis_with(coefs: &[f64], n: usize, u: f64, v: f64) -> Vec<f64> {
    let w = 1.0 - u - v;
    let powers = |x: f64| {
        let mut p = vec![1.0; n + 1];
        for k in 1..=n {
            p[k] = p[k - 1] * x;
        }
        p
    };
    let (pu, pv, pw) = (powers(u), powers(v), powers(w.max(0.0)));
    tri_indices(n)
        .zip(coefs)
        .map(|((i, j), c)| c * pu[i] * pv[j] * pw[n - i - j])
        .collect()
}
