//! Dense sampling of two interval triangles: the largest pointwise violation of containment
//! (SPEC-convert I.2, post-processing (2)), evaluated in `f64` independently of the
//! certification.

use cagd_core::tri_count;

use super::basis::{basis_with, trinomials};
use super::elevation::tri_indices;
use super::patch::IntervalTriPatch;

/// The grid points `(a/K, b/K)`, `a + b <= K`: `(K + 1)(K + 2) / 2` of them.
pub(crate) fn grid(k: usize) -> impl Iterator<Item = (f64, f64)> {
    let kf = k as f64;
    tri_indices(k).map(move |(a, b)| (a as f64 / kf, b as f64 / kf))
}

/// `sum_q b_q net[q * dim + c]` and `sum_q b_q |net[q * dim + c]|`.
fn dot(b: &[f64], net: &[f64], dim: usize, c: usize) -> (f64, f64) {
    b.iter().enumerate().fold((0.0, 0.0), |(s, m), (q, &bq)| {
        let x = net[q * dim + c];
        (s + bq * x, m + bq * x.abs())
    })
}

/// The largest violation of "`outer` contains `inner`" over the grid of
/// [`grid`]`(k)`: `max(outer_lo(P) - inner_lo(P), inner_hi(P) - outer_hi(P))` over points
/// and coordinates (`<= 0` means contained at every sample).
///
/// Both surfaces are evaluated in `f64` with the Bernstein basis. A difference within the
/// rigorous bound of that evaluation's rounding error,
/// `4 (n + N_n + 8) u (sum B |f| + sum B |g|)` with `u = 2^-53` (a dot product of `N_n`
/// terms whose basis values carry `n + 4` roundings each), cannot be told from touching and
/// is counted as 0; any larger positive difference is reported as it is.
pub(crate) fn max_violation(outer: &IntervalTriPatch, inner: &IntervalTriPatch, k: usize) -> f64 {
    let d = inner.dim();
    let (no, ni) = (outer.degree(), inner.degree());
    let terms = (no.max(ni) + tri_count(no.max(ni)) + 8) as f64;
    let rel = 4.0 * terms * f64::EPSILON / 2.0;
    let mut worst = f64::NEG_INFINITY;
    let (co, ci) = (trinomials(no), trinomials(ni));
    for (u, v) in grid(k.max(1)) {
        let bo = basis_with(&co, no, u, v);
        let bi = basis_with(&ci, ni, u, v);
        for c in 0..d {
            let (ol, olm) = dot(&bo, outer.lo(), d, c);
            let (oh, ohm) = dot(&bo, outer.hi(), d, c);
            let (il, ilm) = dot(&bi, inner.lo(), d, c);
            let (ih, ihm) = dot(&bi, inner.hi(), d, c);
            for (diff, mag) in [(ol - il, olm + ilm), (ih - oh, ihm + ohm)] {
                let counted = if diff > rel * mag {
                    diff
                } else {
                    diff.min(0.0)
                };
                worst = worst.max(counted);
            }
        }
    }
    worst
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interval::basis::basis_values;

    #[test]
    fn basis_is_a_partition_of_unity_with_corners() {
        for n in [0, 1, 3, 7, 20] {
            for (u, v) in grid(9) {
                let s: f64 = basis_values(n, u, v).iter().sum();
                assert!((s - 1.0).abs() < 1e-13, "{n} {u} {v}");
            }
        }
        // At the vertex u = 1 only B_n0 (index tri_index(n, n, 0), the last) is 1.
        let b = basis_values(4, 1.0, 0.0);
        assert_eq!(b[tri_count(4) - 1], 1.0);
        assert_eq!(grid(44).count(), 1035);
    }

    #[test]
    fn sampling_sees_a_real_violation_and_none_for_a_copy() {
        let lo = vec![0.0, 1.0, 0.5, 2.0, 1.0, 0.0];
        let hi: Vec<f64> = lo.iter().map(|x| x + 1.0).collect();
        let p = IntervalTriPatch::new(lo.clone(), hi.clone(), 2, 1).unwrap();
        assert!(max_violation(&p, &p, 20) <= 0.0);
        // Raise the lower net by 0.1: the outer box misses 0.1 everywhere.
        let up: Vec<f64> = lo.iter().map(|x| x + 0.1).collect();
        let q = IntervalTriPatch::new(up, hi, 2, 1).unwrap();
        let v = max_violation(&q, &p, 20);
        assert!((v - 0.1).abs() < 1e-12, "{v}");
    }
}
