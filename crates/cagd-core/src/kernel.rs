//! Low-level slice kernels on flat row-major point buffers (`point i, coordinate k at
//! i * dim + k`). The friendly types ([`crate::BezierCurve`], patches, splines) are built on
//! these, and `cagd-capi` / the batch reducers call them directly to avoid allocation.
//!
//! The kernels assume valid input (checked by the callers); they never allocate unless the
//! name says so.

use crate::binomial::{binomial, binomial_f64};

/// All Bernstein basis values `B_i^n(t) = C(n,i) t^i (1-t)^(n-i)`, `i = 0..=n`, into `out`
/// (length `n + 1`).
///
/// Computed as products of non-negative factors (`t^i` and `(1-t)^(n-i)` by repeated
/// multiplication) for `t` in `[0, 1]`, so every value has a relative error of a few
/// `n` ulp; outside `[0, 1]` the same formula is used (extrapolation).
pub fn bernstein_all(n: usize, t: f64, out: &mut [f64]) {
    debug_assert_eq!(out.len(), n + 1);
    let s = 1.0 - t;
    // out[i] = t^i first, then multiply by (1-t)^(n-i) from the right.
    let mut p = 1.0;
    for o in out.iter_mut() {
        *o = p;
        p *= t;
    }
    let mut q = 1.0;
    for i in (0..=n).rev() {
        out[i] *= q * binomial_f64(n, i);
        q *= s;
    }
}

/// One Bernstein basis value `B_i^n(t)`; `0` when `i > n`.
pub fn bernstein(n: usize, i: usize, t: f64) -> f64 {
    if i > n {
        return 0.0;
    }
    binomial_f64(n, i) * powu(t, i) * powu(1.0 - t, n - i)
}

/// `x^e` for a non-negative integer exponent, by binary powering (exact for `e <= 1`, a few
/// ulp otherwise; `0^0 = 1`).
pub fn powu(x: f64, e: usize) -> f64 {
    let (mut base, mut e, mut acc) = (x, e, 1.0);
    while e > 0 {
        if e & 1 == 1 {
            acc *= base;
        }
        base *= base;
        e >>= 1;
    }
    acc
}

/// De Casteljau evaluation of a polynomial Bézier curve given by `points` (`n + 1` points of
/// `dim` coordinates) at `t`, written to `out` (length `dim`). `work` must hold
/// `points.len()` doubles and is overwritten.
pub fn de_casteljau(points: &[f64], dim: usize, t: f64, work: &mut [f64], out: &mut [f64]) {
    let np = points.len() / dim;
    debug_assert!(np >= 1 && work.len() >= points.len() && out.len() == dim);
    work[..points.len()].copy_from_slice(points);
    let s = 1.0 - t;
    for level in 1..np {
        // Coordinate j of point i is element i * dim + j: one flat pass per level, in the
        // same order and with the same operations as a loop over points and coordinates.
        lerp_level(&mut work[..(np - level + 1) * dim], dim, s, t);
    }
    out.copy_from_slice(&work[..dim]);
}

/// One de Casteljau level in place: `x[j] = s x[j] + t x[j + dim]` for every `j` but the
/// last point's (`x` holds whole points of `dim` coordinates). Each new value reads only
/// old values, so the flat loop is the point-and-coordinate loop in the same order (bit for
/// bit the same results), without the inner loop over `dim` that kept it from being
/// unrolled and vectorised.
#[inline]
fn lerp_level(x: &mut [f64], dim: usize, s: f64, t: f64) {
    let len = x.len() - dim;
    for j in 0..len {
        x[j] = s * x[j] + t * x[j + dim];
    }
}

/// Splits the Bézier control polygon `points` at `t` into `left` and `right` (each the same
/// length as `points`), by the de Casteljau triangle: `left` holds the first column, `right`
/// the diagonal. The two pieces reparametrise `[0, t]` and `[t, 1]` to `[0, 1]`.
pub fn subdivide(points: &[f64], dim: usize, t: f64, left: &mut [f64], right: &mut [f64]) {
    let np = points.len() / dim;
    debug_assert!(left.len() == points.len() && right.len() == points.len());
    right.copy_from_slice(points);
    let s = 1.0 - t;
    for level in 0..np {
        // right[0] is now point `level` of the left piece.
        left[level * dim..(level + 1) * dim].copy_from_slice(&right[..dim]);
        lerp_level(&mut right[..(np - level) * dim], dim, s, t);
    }
    // Each level leaves its last point in place, so right[i] = b_i^(n-i): point i of the
    // right piece.
}

/// Coefficient `Q(i, j) = C(n, j) C(r, i - j) / C(n + r, i)` of degree elevation from `n` to
/// `n + r` (seed 001 §3.2; seed 000 eq. 14.4.4 in closed form). `0` outside the band
/// `0 <= i - j <= r`.
pub fn elevation_coefficient(n: usize, r: usize, i: usize, j: usize) -> f64 {
    if j > n || i < j || i - j > r {
        return 0.0;
    }
    // By Vandermonde, C(n,j) C(r,i-j) <= C(n+r,i) <= C(128,64) < 2^127: exact in u128.
    (binomial(n, j) * binomial(r, i - j)) as f64 / binomial(n + r, i) as f64
}

/// Elevates the degree-`n` polygon `points` by `r` into `out` (`(n + r + 1) * dim` doubles).
pub fn elevate(points: &[f64], dim: usize, r: usize, out: &mut [f64]) {
    let n = points.len() / dim - 1;
    debug_assert_eq!(out.len(), (n + r + 1) * dim);
    out.fill(0.0);
    for i in 0..=n + r {
        let lo = i.saturating_sub(r);
        for j in lo..=i.min(n) {
            let c = elevation_coefficient(n, r, i, j);
            for k in 0..dim {
                out[i * dim + k] += c * points[j * dim + k];
            }
        }
    }
}

/// Writes the homogeneous points `(w_i P_i, w_i)` (dimension `dim + 1`) into `out`.
pub fn to_homogeneous(points: &[f64], weights: &[f64], dim: usize, out: &mut [f64]) {
    for (i, &w) in weights.iter().enumerate() {
        for k in 0..dim {
            out[i * (dim + 1) + k] = w * points[i * dim + k];
        }
        out[i * (dim + 1) + dim] = w;
    }
}

/// Splits homogeneous points (dimension `dim + 1`, last coordinate the weight) into
/// Euclidean `points` (dimension `dim`) and `weights`.
pub fn from_homogeneous(hom: &[f64], dim: usize, points: &mut [f64], weights: &mut [f64]) {
    for (i, w) in weights.iter_mut().enumerate() {
        *w = hom[i * (dim + 1) + dim];
        for k in 0..dim {
            points[i * dim + k] = hom[i * (dim + 1) + k] / *w;
        }
    }
}

/// The centre of the axis-aligned bounding box of `points` (`dim` coordinates each): the
/// centre `c` of the translation-invariant rational bounds (`(h_A + R h_W) / v` with
/// `R = max ||P_i - c||`, see `BSplineCurve::remove_knot`). Zeros for no points.
pub fn bounding_box_centre(points: &[f64], dim: usize) -> Vec<f64> {
    let mut lo = vec![f64::INFINITY; dim];
    let mut hi = vec![f64::NEG_INFINITY; dim];
    for q in points.chunks_exact(dim) {
        for c in 0..dim {
            lo[c] = lo[c].min(q[c]);
            hi[c] = hi[c].max(q[c]);
        }
    }
    lo.iter()
        .zip(&hi)
        .map(|(a, b)| if a <= b { 0.5 * (a + b) } else { 0.0 })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bernstein_partition_of_unity() {
        for n in [0usize, 1, 5, 30, 64] {
            let mut b = vec![0.0; n + 1];
            for t in [0.0, 0.1, 0.5, 0.77, 1.0] {
                bernstein_all(n, t, &mut b);
                let s: f64 = b.iter().sum();
                assert!((s - 1.0).abs() < 1e-13, "n={n} t={t} sum={s}");
                for (i, bi) in b.iter().enumerate() {
                    let direct = bernstein(n, i, t);
                    assert!((bi - direct).abs() <= 1e-14 * direct.abs().max(1e-300) + 1e-300);
                }
            }
        }
    }

    #[test]
    fn de_casteljau_matches_bernstein_sum() {
        let p = [0.0, 0.0, 1.0, 3.0, 3.0, 4.0, 5.0, 1.0, 6.0, 5.0];
        let mut work = [0.0; 10];
        let mut out = [0.0; 2];
        let mut b = [0.0; 5];
        for t in [0.0, 0.3, 0.5, 1.0] {
            de_casteljau(&p, 2, t, &mut work, &mut out);
            bernstein_all(4, t, &mut b);
            for k in 0..2 {
                let s: f64 = (0..5).map(|i| b[i] * p[i * 2 + k]).sum();
                assert!((s - out[k]).abs() < 1e-13);
            }
        }
    }

    #[test]
    fn subdivide_halves() {
        // Cubic 1-D with points 0,1,2,3 is the line 3t: halves are 0..1.5 and 1.5..3.
        let p = [0.0, 1.0, 2.0, 3.0];
        let (mut l, mut r) = ([0.0; 4], [0.0; 4]);
        subdivide(&p, 1, 0.5, &mut l, &mut r);
        assert_eq!(l, [0.0, 0.5, 1.0, 1.5]);
        assert_eq!(r, [1.5, 2.0, 2.5, 3.0]);
    }

    #[test]
    fn elevation_of_a_line() {
        let p = [0.0, 3.0];
        let mut out = [0.0; 4];
        elevate(&p, 1, 2, &mut out);
        assert_eq!(out, [0.0, 1.0, 2.0, 3.0]);
    }
}
