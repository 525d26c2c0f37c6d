//! Subdivision and affine reparametrisation of [`TriPatch`] (seed 000 §14.3.2,
//! Theorem 14.3.1; SPEC-reduce §5).
//!
//! A sub-triangle with vertices `A`, `B`, `C` of the parameter plane is represented by the
//! patch `T'(u', v') = T(C + u' (A - C) + v' (B - C))`: its local `u'`-corner `(1, 0)` is
//! `A`, its `v'`-corner `(0, 1)` is `B`, its origin is `C`. Its control points are the
//! blossom values `T'_ab = b(A^a, B^b, C^(n-a-b))`, computed by nested triangular
//! de Casteljau pyramids (all convex combinations when the triangle lies in the domain).

use super::ops::tri_pyramid;
use crate::validate::check_finite_param;
use crate::{Error, Result, TriPatch, tri_count, tri_index};

/// Barycentric coordinates `(u, v, w)` of a parameter point.
fn bary(p: (f64, f64)) -> (f64, f64, f64) {
    (p.0, p.1, 1.0 - p.0 - p.1)
}

impl TriPatch {
    /// The patch reparametrised on the triangle `(A, B, C)`:
    /// `T'(u', v') = T(C + u' (A - C) + v' (B - C))`, same degree. The triangle may be
    /// degenerate or leave the unit triangle (polynomial extrapolation is exact up to
    /// rounding; outside the domain the combinations are no longer convex).
    ///
    /// Cost `O(n^4 / 12)` point operations (blossoms by two nested pyramids and Bernstein sums).
    ///
    /// # Errors
    /// [`Error::BadParameter`] when a coordinate is not finite.
    ///
    /// ```
    /// # use cagd_core::TriPatch;
    /// let t = TriPatch::new(vec![0.0, 2.0, 1.0], 1, 1)?; // u + 2v
    /// // Triangle A = (1, 0), B = (0, 1), C = (0.5, 0.5): T' = 1.5 - 0.5 u' + 0.5 v'.
    /// let r = t.reparametrize((1.0, 0.0), (0.0, 1.0), (0.5, 0.5))?;
    /// assert_eq!(r.points(), &[1.5, 2.0, 1.0]);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn reparametrize(&self, a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> Result<TriPatch> {
        for (name, x) in [
            ("a.u", a.0),
            ("a.v", a.1),
            ("b.u", b.0),
            ("b.v", b.1),
            ("c.u", c.0),
            ("c.v", c.1),
        ] {
            check_finite_param(name, x)?;
        }
        Ok(self.reparametrize_unchecked(a, b, c))
    }

    /// [`TriPatch::reparametrize`] for finite vertices: `T'_ab = b(A^a, B^b, C^c)` by the
    /// pyramid at `A`, a pyramid at `B` over each of its levels, and the Bernstein sum of
    /// each resulting degree-`c` net at `C` (weights of all degrees tabulated once), so
    /// `O(n^4 / 12)` point operations instead of the `O(n^5 / 120)` of an evaluation by a
    /// pyramid at `C` per point.
    fn reparametrize_unchecked(&self, a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> TriPatch {
        let (n, dim) = (self.degree, self.dim);
        let mut out = vec![0.0; tri_count(n) * dim];
        let weights = bernstein_tables(n, bary(c));
        // Level a of the pyramid at A: b(A^a, corners^(n-a)).
        let at_a = tri_pyramid(&self.points, n, dim, bary(a));
        for (ia, net_a) in at_a.iter().enumerate() {
            // Level b of the pyramid at B on that net: b(A^a, B^b, corners^(n-a-b)).
            let at_b = tri_pyramid(net_a, n - ia, dim, bary(b));
            for (ib, net_ab) in at_b.iter().enumerate() {
                // Its value at C: b(A^a, B^b, C^(n-a-b)).
                let o = tri_index(n, ia, ib) * dim;
                let dst = &mut out[o..o + dim];
                for (w, p) in weights[n - ia - ib].iter().zip(net_ab.chunks_exact(dim)) {
                    for (d, x) in dst.iter_mut().zip(p) {
                        *d += w * x;
                    }
                }
            }
        }
        TriPatch::from_parts(out, n, dim)
    }

    /// The sub-patch on `(A, B, C)` when `A` replaces one corner of the domain, by one pyramid
    /// at `A` (`O(n^3)`): `corner` 0 replaces `V_u` (piece 0 of [`TriPatch::subdivide_at`]),
    /// 1 replaces `V_v` (piece 1), 2 replaces `V_w` (piece 2).
    fn replace_corner(&self, p: (f64, f64), corner: usize) -> TriPatch {
        let (n, dim) = (self.degree, self.dim);
        let pyr = tri_pyramid(&self.points, n, dim, bary(p));
        TriPatch::from_parts(corner_piece(&pyr, n, dim, corner), n, dim)
    }

    /// Splits the patch at the parameter point `p = (u0, v0)` of the closed unit triangle into
    /// three sub-triangles, each replacing one corner of the domain by `p` (one de Casteljau
    /// pyramid at `p`, `O(n^3)`). With `V_u = (1, 0)`, `V_v = (0, 1)`, `V_w = (0, 0)`:
    ///
    /// * piece 0 = triangle `(p, V_v, V_w)`: `(u, v) = (u' u0, u' v0 + v')`,
    ///   `T'_ab = T^a_{0,b}`;
    /// * piece 1 = triangle `(V_u, p, V_w)`: `(u, v) = (u' + v' u0, v' v0)`,
    ///   `T'_ab = T^b_{a,0}`;
    /// * piece 2 = triangle `(V_u, V_v, p)`: `(u, v) = (u' + w' u0, v' + w' v0)`,
    ///   `w' = 1 - u' - v'`, `T'_ab = T^c_{a,b}`, `c = n - a - b`;
    ///
    /// where `T^r_ij` is level `r` of the pyramid and `(u', v')` the piece's own parameters
    /// (the convention of [`TriPatch::reparametrize`]). A point on an edge gives one
    /// degenerate (zero-area) piece.
    ///
    /// # Errors
    /// [`Error::BadParameter`] when `u0` or `v0` is not finite or `p` is outside the
    /// closed unit triangle.
    pub fn subdivide_at(&self, u0: f64, v0: f64) -> Result<[TriPatch; 3]> {
        check_finite_param("u0", u0)?;
        check_finite_param("v0", v0)?;
        if u0 < 0.0 || v0 < 0.0 || u0 + v0 > 1.0 {
            let (name, value) = if u0 < 0.0 { ("u0", u0) } else { ("v0", v0) };
            return Err(Error::BadParameter {
                name,
                value,
                why: "(u0, v0) must lie in the triangle u0, v0 >= 0, u0 + v0 <= 1",
            });
        }
        let (n, dim) = (self.degree, self.dim);
        let pyr = tri_pyramid(&self.points, n, dim, bary((u0, v0)));
        let piece = |corner| TriPatch::from_parts(corner_piece(&pyr, n, dim, corner), n, dim);
        Ok([piece(0), piece(1), piece(2)])
    }

    /// The four midpoint sub-triangles of seed 000 Theorem 14.3.1, parametrised as
    /// SPEC-reduce §5 fixes (local axes parallel to the original ones):
    ///
    /// * `[0]`: corner at `(0, 0)`: `(u, v) = (u'/2, v'/2)`;
    /// * `[1]`: corner at `(1/2, 0)`: `(u, v) = (1/2 + u'/2, v'/2)`;
    /// * `[2]`: corner at `(0, 1/2)`: `(u, v) = (u'/2, 1/2 + v'/2)`;
    /// * `[3]`: middle: `(u, v) = (1/2 - u'/2, 1/2 - v'/2)`.
    ///
    /// Then `F_k(T^(l)) = 2^-n F_k(T)` for the corners and `(-1/2)^n F_k(T)` for the middle
    /// (Theorem 14.3.1 with the spec's erratum; [`TriPatch::degeneracy_invariants`]).
    ///
    /// The corner pieces come from two corner replacements each (pyramids at edge midpoints,
    /// `O(n^3)`, all combinations convex); the middle piece touches all three edges, so no
    /// sequence of convex corner replacements reaches it, and it is the blossom of
    /// [`TriPatch::reparametrize`] (`O(n^4)`).
    pub fn subdivide_midpoint(&self) -> [TriPatch; 4] {
        // (M_uw, V_v, V_w), then V_v -> M_vw (local (0, 1/2)): (M_uw, M_vw, V_w).
        let corner_w = self
            .replace_corner((0.5, 0.0), 0)
            .replace_corner((0.0, 0.5), 1);
        // One pyramid at M_uv gives (M_uv, V_v, V_w) and (V_u, M_uv, V_w).
        let (n, dim) = (self.degree, self.dim);
        let pyr = tri_pyramid(&self.points, n, dim, bary((0.5, 0.5)));
        let half_v = TriPatch::from_parts(corner_piece(&pyr, n, dim, 0), n, dim);
        let half_u = TriPatch::from_parts(corner_piece(&pyr, n, dim, 1), n, dim);
        // (V_u, M_uv, V_w), then V_w -> M_uw (local (1/2, 0)): (V_u, M_uv, M_uw).
        let corner_u = half_u.replace_corner((0.5, 0.0), 2);
        // (M_uv, V_v, V_w), then V_w -> M_vw (local (0, 1/2)): (M_uv, V_v, M_vw).
        let corner_v = half_v.replace_corner((0.0, 0.5), 2);
        let middle = self.reparametrize_unchecked((0.0, 0.5), (0.5, 0.0), (0.5, 0.5));
        [corner_w, corner_u, corner_v, middle]
    }
}

/// The control points of piece `corner` of a split at the apex point of the pyramid `pyr`
/// (see [`TriPatch::subdivide_at`]): `T'_ab = T^a_{0,b}`, `T^b_{a,0}` or `T^c_{a,b}`.
fn corner_piece(pyr: &[Vec<f64>], n: usize, dim: usize, corner: usize) -> Vec<f64> {
    let mut out = vec![0.0; tri_count(n) * dim];
    for a in 0..=n {
        for b in 0..=n - a {
            let c = n - a - b;
            let (level, idx) = match corner {
                0 => (a, tri_index(n - a, 0, b)),
                1 => (b, tri_index(n - b, a, 0)),
                _ => (c, tri_index(n - c, a, b)),
            };
            let o = tri_index(n, a, b) * dim;
            out[o..o + dim].copy_from_slice(&pyr[level][idx * dim..(idx + 1) * dim]);
        }
    }
    out
}

/// The Bernstein polynomials of every degree `d = 0..=n` at barycentric `(u, v, w)`:
/// `[d][tri_index(d, i, j)] = d!/(i! j! k!) u^i v^j w^k`, by the recurrence
/// `B^d_ijk = u B^(d-1)_(i-1)jk + v B^(d-1)_i(j-1)k + w B^(d-1)_ij(k-1)` (convex inside the
/// domain, so as accurate as a de Casteljau evaluation).
fn bernstein_tables(n: usize, (u, v, w): (f64, f64, f64)) -> Vec<Vec<f64>> {
    let mut tables: Vec<Vec<f64>> = Vec::with_capacity(n + 1);
    tables.push(vec![1.0]);
    for d in 1..=n {
        let prev = &tables[d - 1];
        let mut next = vec![0.0; tri_count(d)];
        for i in 0..=d {
            for j in 0..=d - i {
                let k = d - i - j;
                let mut x = 0.0;
                if i > 0 {
                    x += u * prev[tri_index(d - 1, i - 1, j)];
                }
                if j > 0 {
                    x += v * prev[tri_index(d - 1, i, j - 1)];
                }
                if k > 0 {
                    x += w * prev[tri_index(d - 1, i, j)];
                }
                next[tri_index(d, i, j)] = x;
            }
        }
        tables.push(next);
    }
    tables
}
