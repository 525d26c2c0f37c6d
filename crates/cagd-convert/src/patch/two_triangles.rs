//! Rectangle → two triangles of degree `m + n` (SPEC-convert §15.6.3).

use cagd_core::{Result, TensorPatch, TriPatch, tri_count, tri_index};

use super::blossom::pascal;

use super::{PatchPiece, PatchSurface, PieceDomain, TensorSurface, TriSurface};

/// The lower triangle `T(u, v) = P(u, v)` on `u + v <= 1` of the homogeneous net `h`,
/// degree `N = m + n`, in closed form:
/// `T_ij = sum_{α+β+γ=m} C(i,α) C(j,β) C(k,γ) / C(N,m) * P_{α, j-β}`, `k = N - i - j`.
///
/// Derivation (independent of the spec's route, which elevates / exactly reduces the
/// columns of the §15.6.1 patch with `a = 1, b = 0`): the total-degree-`N` blossom of a
/// bidegree-`(m, n)` polynomial is the mean, over the `C(N, m)` ways to send `m` of its `N`
/// arguments to the `u`-slots and the rest to the `v`-slots, of the tensor blossom. At the
/// arguments `(e1^i, e2^j, e0^k)` (`e1 = (1,0)`, `e2 = (0,1)`, `e0 = (0,0)`) a choice sending
/// `α` of the `e1`, `β` of the `e2` and `γ` of the `e0` to `u` has `u`-arguments
/// `(1^α, 0^(m-α))` and `v`-arguments `(1^(j-β), 0^(n-j+β))`: the control point
/// `P_{α, j-β}`. All weights are positive and sum to 1 (Vandermonde), so the result is a
/// convex combination — no exact reduction, no rounding amplification.
fn lower_net(h: &TensorPatch) -> Vec<f64> {
    let ((m, n), dim) = (h.degrees(), h.dim());
    let big_n = m + n;
    let binom = pascal(big_n);
    let denom = binom[big_n][m];
    let mut out = vec![0.0; tri_count(big_n) * dim];
    for i in 0..=big_n {
        for j in 0..=big_n - i {
            let k = big_n - i - j;
            let o = tri_index(big_n, i, j) * dim;
            for alpha in 0..=i.min(m) {
                for beta in 0..=j.min(m - alpha) {
                    let gamma = m - alpha - beta;
                    if gamma > k || j - beta > n {
                        continue;
                    }
                    let c = binom[i][alpha] * binom[j][beta] * binom[k][gamma] / denom;
                    let src = h.point(alpha, j - beta);
                    for x in 0..dim {
                        out[o + x] += c * src[x];
                    }
                }
            }
        }
    }
    out
}

/// The `u`- and `v`-reversed net `P'_ij = P_{m-i, n-j}`.
fn reversed(h: &TensorPatch) -> TensorPatch {
    let ((m, n), dim) = (h.degrees(), h.dim());
    let mut pts = Vec::with_capacity(h.points().len());
    for i in 0..=m {
        for j in 0..=n {
            pts.extend_from_slice(h.point(m - i, n - j));
        }
    }
    TensorPatch::new(pts, m, n, dim).unwrap_or_else(|_| h.clone())
}

/// An `m x n` patch as two triangles of degree `m + n` (SPEC-convert §15.6.3): the lower
/// `T(u, v) = P(u, v)` on `u + v <= 1` and the upper `T'(u', v') = P(1 - u', 1 - v')`
/// (the same construction on `P'_ij = P_{m-i, n-j}`). Rational patches through homogeneous
/// points.
///
/// # Errors
/// [`cagd_core::Error::DegreeOutOfRange`] when `m + n > 64`.
pub fn rect_to_two_triangles(p: &TensorSurface) -> Result<[TriSurface; 2]> {
    let h = p.homogeneous();
    let ((m, n), dim) = (h.degrees(), h.dim());
    let rational = p.weights().is_some();
    let lower = TriPatch::new(lower_net(&h), m + n, dim)?;
    let upper = TriPatch::new(lower_net(&reversed(&h)), m + n, dim)?;
    Ok([
        TriSurface::from_homogeneous(lower, rational)?,
        TriSurface::from_homogeneous(upper, rational)?,
    ])
}

/// [`rect_to_two_triangles`] as pieces with their domains: the lower triangle
/// `[A, B, C] = [(1,0), (0,1), (0,0)]`, the upper `[(0,1), (1,0), (1,1)]`.
/// (SPEC-convert §15.6.3.)
///
/// # Errors
/// As [`rect_to_two_triangles`].
pub fn rect_to_two_triangle_pieces(p: &TensorSurface) -> Result<Vec<PatchPiece>> {
    let [lower, upper] = rect_to_two_triangles(p)?;
    Ok(vec![
        PatchPiece {
            surface: PatchSurface::Tri(lower),
            domain: PieceDomain::Triangle([[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]),
        },
        PatchPiece {
            surface: PatchSurface::Tri(upper),
            domain: PieceDomain::Triangle([[0.0, 1.0], [1.0, 0.0], [1.0, 1.0]]),
        },
    ])
}
