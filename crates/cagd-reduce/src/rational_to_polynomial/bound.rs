//! The certified bound of `max ||C - S||` on one span (curve) or patch (surface), `C = A / W`
//! the rational input and `S` the polynomial result (ours; the brief's plan, no seed
//! formula):
//!
//! `C - S = (A - W S) / W`, and `D = A - W S` is a polynomial of degree `p + m` (per
//! direction) whose Bézier coefficients are exact bilinear forms of those of `A`, `W`, `S`
//! (the Bernstein product, `B^p_i B^m_j = C(p,i) C(m,j) / C(p+m,i+j) B^{p+m}_{i+j}`; the
//! elevation of `A` is its product with the constant 1). `D` is formed centred on the
//! bounding-box centre `c` of the piece's model points ([`cagd_core::kernel::bounding_box_centre`]):
//! `D = (A - c W) - W (S - c)`, the same polynomial, with coefficients of the size of the
//! piece, not of its distance from the origin, so the rounding allowance is unit-consistent.
//!
//! `max ||D / W||` is bounded by joint subdivision of `D` and `W`: on each sub-piece
//! `||D|| / W <= max_k ||D_k|| / min_k W_k` (convex hull; the control weights bound `W`
//! from below), sub-pieces that cannot raise the maximum found at their end points are not
//! split further. For a patch, `D = sum_j B_j(v) D_j(u)` and `W = sum_j B_j(v) W_j(u)`, so
//! `||D|| / W <= max_j ||D_j(u)|| / W_j(u)` (mediant inequality): the largest curve bound
//! over the rows, or over the columns, whichever is smaller.

use cagd_core::kernel::{bounding_box_centre, subdivide};
use cagd_core::{Error, Result, binomial_f64};

/// The bound of an exact conversion (weights all equal, kept at their degree: the same
/// curve or surface), `max(8 terms eps sqrt(dim) max |x|, measured)`: the true error is 0,
/// and what a caller measures is the rounding of evaluating `sum w N P / sum w N` beside
/// `sum N P` (de Boor, a few `terms = p + 2` (curve) or `p + q + 2` (surface) ulps of the
/// largest point; the fuzz harness measured 5.7e-17 beside a reported 0), so the bound
/// covers it and is never below a measurement. Overflow-safe: the largest coordinate
/// times `sqrt(dim)`, the small factor applied first (a point norm overflowed to `+inf` at
/// coordinates of -1.7e308, C ABI fuzz run).
///
/// # Errors
/// [`Error::ConditionNotMet`] when that bound exceeds `tol` (the tolerance is below the
/// rounding level of the curve: the rule of every other input, so that a success always
/// means `bound <= tol`).
pub(crate) fn exact_bound(
    points: &[f64],
    dim: usize,
    terms: usize,
    measured: f64,
    tol: f64,
) -> Result<f64> {
    let amax = points.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let factor = 8.0 * terms as f64 * f64::EPSILON * (dim.max(1) as f64).sqrt();
    let bound = (factor * amax).max(measured);
    if bound <= tol {
        Ok(bound)
    } else {
        Err(Error::ConditionNotMet {
            eq: "tolerance",
            why: "the tolerance is below the rounding level of the curve (weights all equal: the same curve, whose bound is the rounding of evaluating it)",
        })
    }
}

/// Subdivision depth of the ratio bound (at most `2^5` sub-pieces per row).
const DEPTH: usize = 5;

fn norm(p: &[f64]) -> f64 {
    p.iter().map(|v| v * v).sum::<f64>().sqrt()
}

fn max_norm(x: &[f64], dim: usize) -> f64 {
    x.chunks_exact(dim).map(norm).fold(0.0, f64::max)
}

/// `(max_k ||D_k||, min_k W_k)` of one piece.
fn hull(d: &[f64], w: &[f64], dim: usize) -> (f64, f64) {
    (
        max_norm(d, dim),
        w.iter().copied().fold(f64::INFINITY, f64::min),
    )
}

/// An upper bound of `max_{t in [0,1]} ||D(t)|| / W(t)` for Bézier `D` (`dim` coordinates,
/// any degree) and `W` (scalar, positive control values), valid for the given coefficients
/// with the rounding of the subdivisions included (each de Casteljau level is a convex
/// combination: `n eps max ||D_k||` per subdivision). Infinite when a computed lower bound
/// of `W` is not positive.
pub(crate) fn ratio_bound(d: &[f64], w: &[f64], dim: usize) -> f64 {
    let (nd, nw) = (d.len() / dim - 1, w.len() - 1);
    let (dmax, wmin0) = hull(d, w, dim);
    if dmax == 0.0 {
        return 0.0;
    }
    let wmax = w.iter().copied().fold(0.0, f64::max);
    let eps = f64::EPSILON;
    let dslack = ((DEPTH * nd + dim + 4) as f64) * eps * dmax;
    let wslack = ((DEPTH * nw + 4) as f64) * eps * wmax;
    if wmin0 - wslack <= 0.0 {
        return f64::INFINITY;
    }
    let mut lower = (norm(&d[..dim]) / w[0]).max(norm(&d[nd * dim..]) / w[nw]);
    let mut upper: f64 = 0.0;
    // One scratch buffer for the refinement (two children per level, the left one waiting
    // while the right one's subtree is refined), no allocation per piece (issue 18: the
    // span bounds of the NURBS fit spent most of their time allocating pieces).
    let mut scratch = vec![0.0; 2 * DEPTH * (d.len() + w.len())];
    let mut st = RatioState {
        dim,
        slack: (dslack, wslack),
        lower: &mut lower,
        upper: &mut upper,
    };
    ratio_visit((d, w), DEPTH, &mut scratch, &mut st);
    // Every sub-piece, split or not, went into `upper`.
    upper * (1.0 + 4.0 * eps)
}

/// The running state of [`ratio_bound`]'s refinement.
struct RatioState<'a> {
    dim: usize,
    slack: (f64, f64),
    lower: &'a mut f64,
    upper: &'a mut f64,
}

/// Refines the piece `(dp, wp)` depth-first, right child first (see [`ratio_bound`]): a
/// piece whose hull ratio is within the largest ratio seen at a curve point, or at the last
/// level, counts its slackened hull ratio into `upper`; the others are split at the
/// midpoint into the first slots of `scratch`.
fn ratio_visit(
    (dp, wp): (&[f64], &[f64]),
    levels_left: usize,
    scratch: &mut [f64],
    st: &mut RatioState<'_>,
) {
    let dim = st.dim;
    let (h, wl) = hull(dp, wp, dim);
    if h / wl <= *st.lower || levels_left == 0 {
        let (dslack, wslack) = st.slack;
        *st.upper = st.upper.max((h + dslack) / (wl - wslack));
        return;
    }
    let (nd, nw) = (dp.len(), wp.len());
    let (mine, rest) = scratch.split_at_mut(2 * (nd + nw));
    let (dl, mine) = mine.split_at_mut(nd);
    let (dr, mine) = mine.split_at_mut(nd);
    let (wl_, wr) = mine.split_at_mut(nw);
    subdivide(dp, dim, 0.5, dl, dr);
    subdivide(wp, 1, 0.5, wl_, wr);
    *st.lower = st.lower.max(norm(&dr[..dim]) / wr[0]);
    ratio_visit((dr, wr), levels_left - 1, rest, st);
    ratio_visit((dl, wl_), levels_left - 1, rest, st);
}

/// The Bernstein product of a scalar tensor polynomial `f` of degrees `(a, b)` and a
/// vector one `g` of degrees `(c, e)` (`dim` coordinates, i-major), accumulated into `out`
/// (degrees `(a + c, b + e)`) times `sign`.
fn product_into(
    f: &[f64],
    (a, b): (usize, usize),
    g: &[f64],
    (c, e): (usize, usize),
    dim: usize,
    sign: f64,
    out: &mut [f64],
) {
    let cols = b + e + 1;
    // The v factors C(b, j) C(e, l) / C(b + e, j + l), once per call (the same numbers as
    // computed in the loop, so the products are bit for bit those of the definition).
    let cvs: Vec<f64> = (0..=b)
        .flat_map(|j| {
            (0..=e)
                .map(move |l| binomial_f64(b, j) * binomial_f64(e, l) / binomial_f64(b + e, j + l))
        })
        .collect();
    for i in 0..=a {
        for j in 0..=b {
            let fij = f[i * (b + 1) + j] * sign;
            for k in 0..=c {
                let cu = binomial_f64(a, i) * binomial_f64(c, k) / binomial_f64(a + c, i + k);
                for l in 0..=e {
                    let cv = cvs[j * (e + 1) + l];
                    let s = fij * cu * cv;
                    let o = ((i + k) * cols + j + l) * dim;
                    let q = (k * (e + 1) + l) * dim;
                    for x in 0..dim {
                        out[o + x] += s * g[q + x];
                    }
                }
            }
        }
    }
}

/// `(bound, floor)` of `max ||A/W - S||` on one patch: `hom` the input's homogeneous
/// Bézier points there (degrees `(p, q)`, `dim + 1` coordinates, i-major), `s` the result's
/// Bézier points (degrees `(mu, mv)`, `dim` coordinates). A curve is the case `q = mv = 0`.
/// `floor` is the rounding allowance (no fit gets below it).
pub(crate) fn patch_bound(
    hom: &[f64],
    (p, q): (usize, usize),
    s: &[f64],
    (mu, mv): (usize, usize),
    dim: usize,
) -> (f64, f64) {
    let hd = dim + 1;
    let w: Vec<f64> = hom.chunks_exact(hd).map(|h| h[dim]).collect();
    let model: Vec<f64> = hom
        .chunks_exact(hd)
        .flat_map(|h| h[..dim].iter().map(move |x| x / h[dim]))
        .collect();
    let c = bounding_box_centre(&model, dim);
    let cn = norm(&c);
    let ac: Vec<f64> = hom
        .chunks_exact(hd)
        .flat_map(|h| (0..dim).map(move |x| (h[x], h[dim])))
        .zip(c.iter().cycle())
        .map(|((a, wv), cx)| a - cx * wv)
        .collect();
    let sc: Vec<f64> = s
        .chunks_exact(dim)
        .flat_map(|pt| pt.iter().zip(&c).map(|(x, cx)| x - cx))
        .collect();
    let (du, dv) = (p + mu, q + mv);
    let mut d = vec![0.0; (du + 1) * (dv + 1) * dim];
    let ones = vec![1.0; (mu + 1) * (mv + 1)];
    product_into(&ones, (mu, mv), &ac, (p, q), dim, 1.0, &mut d);
    product_into(&w, (p, q), &sc, (mu, mv), dim, -1.0, &mut d);
    // Rounding of the inputs' restriction (subdivision), the translation and the products,
    // relative to the uncentred sizes (generous: a few hundred ulps of the coordinates).
    let eps = f64::EPSILON;
    let wmax = w.iter().copied().fold(0.0, f64::max);
    let wmin = w.iter().copied().fold(f64::INFINITY, f64::min);
    let amax = hom
        .chunks_exact(hd)
        .map(|h| norm(&h[..dim]))
        .fold(0.0, f64::max);
    let smax = max_norm(s, dim);
    let size = amax + cn * wmax + wmax * (smax + cn + 1.0);
    let slack = (4 * (du + dv) + 16 + 2 * dim) as f64 * eps * size;
    // The ratio bound by rows (curves in u at each v index) and by columns.
    let rows = |d: &[f64], w: &[f64], (nu, nv): (usize, usize), by_u: bool| -> f64 {
        let mut worst: f64 = 0.0;
        let (outer, inner) = if by_u { (nv, nu) } else { (nu, nv) };
        for j in 0..=outer {
            let mut dj = Vec::with_capacity((inner + 1) * dim);
            let mut wj = Vec::with_capacity(inner + 1);
            for i in 0..=inner {
                let (iu, iv) = if by_u { (i, j) } else { (j, i) };
                dj.extend_from_slice(
                    &d[(iu * (nv + 1) + iv) * dim..(iu * (nv + 1) + iv + 1) * dim],
                );
                wj.push(w[iu * (nv + 1) + iv]);
            }
            worst = worst.max(ratio_bound(&dj, &wj, dim));
        }
        worst
    };
    // W in the degree of D (product with 1), so that rows share D's basis.
    let mut we = vec![0.0; (du + 1) * (dv + 1)];
    product_into(&ones, (mu, mv), &w, (p, q), 1, 1.0, &mut we);
    let by_u = rows(&d, &we, (du, dv), true);
    let bound = if dv > 0 {
        by_u.min(rows(&d, &we, (du, dv), false))
    } else {
        by_u
    };
    let wlo = wmin - (4 * (p + q) + 8) as f64 * eps * wmax;
    if wlo <= 0.0 || !bound.is_finite() {
        return (f64::INFINITY, f64::INFINITY);
    }
    let floor = slack / wlo;
    ((bound + floor) * (1.0 + 8.0 * eps), floor)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ratio bound is never below the sampled maximum and close to it.
    #[test]
    fn ratio_bound_brackets_the_sampled_maximum() {
        let d = [0.3, -0.2, 1.0, 0.5, -0.7, 0.1, 0.2, 0.4];
        let w = [1.0, 0.3, 2.0];
        let b = ratio_bound(&d, &w, 2);
        let dc = cagd_core::BezierCurve::new(d.to_vec(), 2).unwrap();
        let wc = cagd_core::BezierCurve::new(w.to_vec(), 1).unwrap();
        let mut best: f64 = 0.0;
        for i in 0..=4000 {
            let t = f64::from(i) / 4000.0;
            let (x, y) = (dc.eval(t), wc.eval(t));
            best = best.max(norm(&x) / y[0]);
        }
        assert!(b >= best && b <= 1.1 * best, "{b} vs {best}");
    }

    /// `A - W S` by the product is the pointwise `A(t) - W(t) S(t)`.
    #[test]
    fn product_is_pointwise() {
        let (p, m) = (3, 2);
        let a = [1.0, 2.0, -1.0, 0.5, 3.0, 1.0, 0.0, -2.0];
        let w = [1.0, 0.5, 2.0, 1.5];
        let s = [0.2, 0.1, -0.3, 0.7, 1.1, 0.9];
        let mut d = vec![0.0; (p + m + 1) * 2];
        product_into(&vec![1.0; m + 1], (m, 0), &a, (p, 0), 2, 1.0, &mut d);
        product_into(&w, (p, 0), &s, (m, 0), 2, -1.0, &mut d);
        let (ac, wc, sc, dc) = (
            cagd_core::BezierCurve::new(a.to_vec(), 2).unwrap(),
            cagd_core::BezierCurve::new(w.to_vec(), 1).unwrap(),
            cagd_core::BezierCurve::new(s.to_vec(), 2).unwrap(),
            cagd_core::BezierCurve::new(d, 2).unwrap(),
        );
        for t in [0.0, 0.13, 0.5, 0.77, 1.0] {
            let (x, y, z, e) = (ac.eval(t), wc.eval(t)[0], sc.eval(t), dc.eval(t));
            for k in 0..2 {
                assert!((x[k] - y * z[k] - e[k]).abs() < 1e-14, "{t}");
            }
        }
    }
}
