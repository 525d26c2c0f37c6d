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
    for i in 0..n {
        for j in 0..n - i {
            let o = tri_index(n - 1, i, j) * dim;
            let a = tri_index(n, i + 1, j) * dim;
            let b = tri_index(n, i, j + 1) * dim;
            let c = tri_index(n, i, j) * dim;
            for k in 0..dim {
                out[o + k] = u * net[a + k] + v * net[b + k] + w * net[c + k];
            }
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
/// indexed `[α][β][γ]` (`α + β + γ <= n`), by nested pyramids.
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
                .map(|(beta, net_b)| {
                    let d = n - alpha - beta;
                    tri_pyramid(net_b, d, dim, x[2])
                        .iter()
                        .enumerate()
                        .map(|(gamma, net_c)| tri_value(net_c, d - gamma, dim, x[3]))
                        .collect()
                })
                .collect()
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
