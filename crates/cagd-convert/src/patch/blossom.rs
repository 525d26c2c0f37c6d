//! Blossoms of Bézier curves and triangular nets: de Casteljau with a different parameter
//! at each level (SPEC-convert §0, "operator ↔ blossom rule"). cagd-core keeps its own
//! pyramids private, so the few lines needed are here.

use cagd_core::{tri_count, tri_index};

/// Blossom of the degree-`n` curve `points` (`(n + 1) * dim`) at `args` (`n` values):
/// level `r` of de Casteljau uses `args[r]`. Returns `dim` doubles.
pub(crate) fn curve_blossom(points: &[f64], dim: usize, args: &[f64]) -> Vec<f64> {
    let n = points.len() / dim - 1;
    debug_assert_eq!(args.len(), n);
    let mut cur = points.to_vec();
    for (r, &t) in args.iter().enumerate() {
        let s = 1.0 - t;
        for i in 0..n - r {
            for k in 0..dim {
                cur[i * dim + k] = s * cur[i * dim + k] + t * cur[(i + 1) * dim + k];
            }
        }
    }
    cur.truncate(dim);
    cur
}

/// The degree-`n` curve restricted to `[t0, t1]` and reparametrised on `[0, 1]`: point `j`
/// is the blossom at `(t0^(n - j), t1^j)`.
pub(crate) fn curve_restrict(points: &[f64], dim: usize, t0: f64, t1: f64) -> Vec<f64> {
    let n = points.len() / dim - 1;
    let mut out = Vec::with_capacity(points.len());
    let mut args = vec![t0; n];
    for j in 0..=n {
        if j > 0 {
            args[n - j] = t1;
        }
        out.extend(curve_blossom(points, dim, &args));
    }
    out
}

/// One triangular de Casteljau level: the degree-`n` net to degree `n - 1` at barycentric
/// `(u, v, w)`: `N'_ij = u N_{i+1,j} + v N_{i,j+1} + w N_ij`.
fn tri_step(net: &[f64], n: usize, dim: usize, p: [f64; 2]) -> Vec<f64> {
    let (u, v) = (p[0], p[1]);
    let w = 1.0 - u - v;
    let mut out = vec![0.0; tri_count(n - 1) * dim];
    // Row by row (rows are contiguous): row i of the output from rows i and i + 1.
    for i in 0..n {
        let len = (n - i) * dim;
        let (here, next) = (tri_index(n, i, 0) * dim, tri_index(n, i + 1, 0) * dim);
        let o = tri_index(n - 1, i, 0) * dim;
        let row = &net[here..here + len + dim];
        let up = &net[next..next + len];
        for (((x, a), b), c) in out[o..o + len]
            .iter_mut()
            .zip(up)
            .zip(&row[dim..])
            .zip(&row[..len])
        {
            *x = u * a + v * b + w * c;
        }
    }
    out
}

/// The de Casteljau pyramid of a degree-`n` net at the domain point `p`: level `r` is the
/// degree-`(n - r)` net `b(p^r, ·)`.
pub(crate) fn tri_pyramid(net: &[f64], n: usize, dim: usize, p: [f64; 2]) -> Vec<Vec<f64>> {
    let mut levels = Vec::with_capacity(n + 1);
    levels.push(net.to_vec());
    for r in 1..=n {
        let next = tri_step(&levels[r - 1], n - r + 1, dim, p);
        levels.push(next);
    }
    levels
}

/// Value of a degree-`n` net at the domain point `p` (the blossom `b(p^n)`), by de
/// Casteljau in place: level `d - 1` entry `(i, j)` is written at its own index, which is
/// never above the indices of the three level-`d` entries a later `(i, j)` still reads.
pub(crate) fn tri_value(net: &[f64], n: usize, dim: usize, p: [f64; 2]) -> Vec<f64> {
    let (u, v) = (p[0], p[1]);
    let w = 1.0 - u - v;
    let mut cur = net.to_vec();
    for d in (1..=n).rev() {
        for i in 0..d {
            for j in 0..d - i {
                let o = tri_index(d - 1, i, j) * dim;
                let a = tri_index(d, i + 1, j) * dim;
                let b = tri_index(d, i, j + 1) * dim;
                let c = tri_index(d, i, j) * dim;
                for k in 0..dim {
                    cur[o + k] = u * cur[a + k] + v * cur[b + k] + w * cur[c + k];
                }
            }
        }
    }
    cur.truncate(dim);
    cur
}

/// All blossom values `b(x[0]^α, x[1]^β, x[2]^γ, x[3]^(n-α-β-γ))` of a degree-`n` net,
/// indexed `[α][β][γ]` (`α + β + γ <= n`): nested pyramids at `x[0]` and `x[1]`, then for
/// each `(α, β)` the line restriction [`line_blossoms`] on `x[3] x[2]` in `O(d^3)` — the
/// whole table in `O(n^5)` (a pyramid and a full evaluation per `γ`, `O(n^6)`, took seconds
/// at degree 64 in the fuzz run).
pub(crate) fn tri_blossom_table(
    net: &[f64],
    n: usize,
    dim: usize,
    x: [[f64; 2]; 4],
) -> Vec<Vec<Vec<Vec<f64>>>> {
    let at_a = tri_pyramid(net, n, dim, x[0]);
    at_a.iter()
        .enumerate()
        .map(|(alpha, net_a)| {
            let at_b = tri_pyramid(net_a, n - alpha, dim, x[1]);
            at_b.iter()
                .enumerate()
                .map(|(beta, net_b)| line_blossoms(net_b, n - alpha - beta, dim, x[3], x[2]))
                .collect()
        })
        .collect()
}

/// `b(q^γ, p^(d-γ))`, `γ = 0..=d`, of a degree-`d` net (the Bézier points of the net along
/// the segment `p q`), in `O(d^3)`: the pyramid at `p` gives the net of the sub-triangle
/// `(p, V_b, V_c)` (one of the three triangles `p` cuts the domain into, the one that
/// contains `q`, so that `q`'s barycentric coordinates in it are `>= 0` and the second
/// pyramid is convex), then the pyramid at `q` on that net, whose level `γ` has
/// `b(q^γ, p^(d-γ))` at its corner `p`.
pub(crate) fn line_blossoms(
    net: &[f64],
    d: usize,
    dim: usize,
    p: [f64; 2],
    q: [f64; 2],
) -> Vec<Vec<f64>> {
    if d == 0 {
        return vec![net[..dim].to_vec()];
    }
    // Domain vertices U = (1, 0) (index i), V = (0, 1) (index j), O = (0, 0) (rest).
    const VERTS: [[f64; 2]; 3] = [[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]];
    let area = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    };
    // Drop vertex `drop`: the sub-triangle (p, V_b, V_c) in the vertex order U, V, O.
    let mut best: Option<(f64, f64, usize, [f64; 3])> = None;
    for drop in 0..3 {
        let (b, c) = match drop {
            0 => (1, 2),
            1 => (0, 2),
            _ => (0, 1),
        };
        let whole = area(p, VERTS[b], VERTS[c]);
        if whole.abs() <= f64::MIN_POSITIVE {
            continue;
        }
        let l0 = area(q, VERTS[b], VERTS[c]) / whole;
        let lb = area(p, q, VERTS[c]) / whole;
        let lc = 1.0 - l0 - lb;
        let inside = l0.min(lb).min(lc);
        let better = match best {
            None => true,
            Some((bi, ba, _, _)) => inside > bi || (inside == bi && whole.abs() > ba),
        };
        if better {
            best = Some((inside, whole.abs(), drop, [l0, lb, lc]));
        }
    }
    let Some((_, _, drop, lam)) = best else {
        // p is no point of a proper triangle (not expected for finite corners): fall back
        // to evaluation level by level.
        return tri_pyramid(net, d, dim, p)
            .iter()
            .enumerate()
            .rev()
            .map(|(r, level)| tri_value(level, d - r, dim, q))
            .collect();
    };
    let levels = tri_pyramid(net, d, dim, p);
    // Sub-net over (p, V_b, V_c): entry (r, s) = b(p^r, V_b^s, V_c^(d-r-s)), stored with
    // index i = r (p), j = s (V_b).
    let mut sub = vec![0.0; tri_count(d) * dim];
    for (r, level) in levels.iter().enumerate() {
        let e = d - r;
        for s in 0..=e {
            let t = e - s;
            let (i, j) = match drop {
                0 => (0, s), // V_b = V, V_c = O
                1 => (s, 0), // V_b = U, V_c = O
                _ => (s, t), // V_b = U, V_c = V
            };
            let from = tri_index(e, i, j) * dim;
            let to = tri_index(d, r, s) * dim;
            sub[to..to + dim].copy_from_slice(&level[from..from + dim]);
        }
    }
    let lam = [lam[0].max(0.0), lam[1].max(0.0)];
    tri_pyramid(&sub, d, dim, lam)
        .iter()
        .enumerate()
        .map(|(gamma, level)| {
            let at = tri_index(d - gamma, d - gamma, 0) * dim;
            level[at..at + dim].to_vec()
        })
        .collect()
}

/// Binomial coefficients `C(n, k)` for `n <= nmax` as `f64` (from cagd-core's exact table),
/// row `n` holding `k = 0..=n`: looked up in the inner loops instead of converting `u128`.
pub(crate) fn pascal(nmax: usize) -> Vec<Vec<f64>> {
    (0..=nmax)
        .map(|n| (0..=n).map(|k| cagd_core::binomial_f64(n, k)).collect())
        .collect()
}

/// The left part of the degree-`n` curve subdivided at `t`: point `j` is the blossom
/// `b(0^(n - j), t^j)`.
pub(crate) fn left_part(points: &[f64], dim: usize, t: f64) -> Vec<f64> {
    let (mut left, mut right) = (vec![0.0; points.len()], vec![0.0; points.len()]);
    cagd_core::kernel::subdivide(points, dim, t, &mut left, &mut right);
    left
}

/// Multiplies the degree-`d` Bernstein rows of `z` by the degree-`k` Bernstein
/// function `c` in the corner-cutting step of SPEC-convert §15.7 ("recommended
/// algorithm"): row `p` becomes `sum_l B^k_l(t) ((1 - c_l) z_p + c_l z_{p+1})`, degree
/// `d + k`; one row fewer. Coefficients `C(k,l) C(d,r) / C(k+d,l+r) >= 0`, read from
/// `binom` (a [`pascal`] table up to `d + k` at least).
pub(crate) fn corner_cut(
    z: &[Vec<f64>],
    d: usize,
    dim: usize,
    c: &[f64],
    binom: &[Vec<f64>],
) -> Vec<Vec<f64>> {
    let k = c.len() - 1;
    let e = d + k;
    let mut out = Vec::with_capacity(z.len().saturating_sub(1));
    for p in 0..z.len().saturating_sub(1) {
        let mut row = vec![0.0; (e + 1) * dim];
        for q in 0..=e {
            let lo = q.saturating_sub(d);
            for (l, &cl) in c.iter().enumerate().take(q.min(k) + 1).skip(lo) {
                let r = q - l;
                let coef = binom[k][l] * binom[d][r] / binom[e][q];
                let (a, b) = ((1.0 - cl) * coef, cl * coef);
                for x in 0..dim {
                    row[q * dim + x] += a * z[p][r * dim + x] + b * z[p + 1][r * dim + x];
                }
            }
        }
        out.push(row);
    }
    out
}

/// Elevates a degree-`d` polygon to degree `to >= d`.
pub(crate) fn elevate_to(points: &[f64], dim: usize, to: usize) -> Vec<f64> {
    let d = points.len() / dim - 1;
    let mut out = vec![0.0; (to + 1) * dim];
    cagd_core::kernel::elevate(points, dim, to - d, &mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The line restriction equals the direct route (pyramid at `q`, then each level
    /// evaluated at `p`), on segments from corners, edges and the inside of the domain.
    #[test]
    fn line_blossoms_match_pyramid_then_value() {
        let mut s = 5u64;
        let mut r = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let pts: [[f64; 2]; 8] = [
            [0.0, 0.0],
            [1.0, 0.0],
            [0.0, 1.0],
            [0.5, 0.0],
            [0.0, 0.3],
            [0.4, 0.6],
            [1.0 / 3.0, 1.0 / 3.0],
            [0.2, 0.1],
        ];
        for d in [0usize, 1, 2, 5, 12, 24] {
            let dim = 3;
            let net: Vec<f64> = (0..tri_count(d) * dim).map(|_| r()).collect();
            for p in pts {
                for q in pts {
                    let fast = line_blossoms(&net, d, dim, p, q);
                    let direct: Vec<Vec<f64>> = tri_pyramid(&net, d, dim, q)
                        .iter()
                        .enumerate()
                        .map(|(g, level)| tri_value(level, d - g, dim, p))
                        .collect();
                    assert_eq!(fast.len(), d + 1);
                    for (a, b) in fast.iter().zip(&direct) {
                        for (x, y) in a.iter().zip(b) {
                            assert!((x - y).abs() <= 1e-12, "d {d} p {p:?} q {q:?}: {x} vs {y}");
                        }
                    }
                }
            }
        }
    }
}
