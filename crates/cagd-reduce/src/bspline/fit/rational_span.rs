//! The certified bound of one span of a NURBS fit (a rational bundle; [`super::span_bounds`]).
//!
//! With a centre `c` (of the input's model-space points on the span) and `R = max ||P_i -
//! c||`, `C - S = ((C - c)(W' - W) + (A_c - A'_c)) / W'` where `A_c = A - c W`: the input
//! curve lies in the hull of its points, so `||C - c|| <= R`, and with `h_A >= max_t
//! ||A_c(t) - A'_c(t)||` and `h_W >= max_t |W(t) - W'(t)|` (the largest over the blocks:
//! the bundle combines them convexly), `||C - S|| <= (h_A + R h_W) / v`, `v = max(vmin,
//! min w - h_W)` ([`cagd_core::centred_rational_bound`]). Centring makes the bound
//! independent of where the model sits.
//!
//! For a single curve, `h_A` and `h_W` are node bounds ([`NodeBound`]: the polynomial
//! differences at Chebyshev–Lobatto nodes times the Ehlich–Zeller factor, at most 1.075
//! times their maxima, rounding included), and where the resulting bound is above the
//! budget also refined convex hulls ([`crate::bezier::hull_bound`]), the smaller of the
//! two — the polynomial spans' rule, so an offending span's split count still follows the
//! hull. A bundle (a surface's rows) takes the refined hulls alone, as before.
//! ADDED (issue 17, real-CAD-file row): the hull alone, an elevation and several
//! subdivisions per span, was 35 % of the reduction of degree 4–15 NURBS to cubics.

use cagd_core::{ModelFrame, centred_rational_bound};

use super::node_bound::NodeBound;
use crate::bezier::{hull_bound, max_norm};

/// The data of one span: `sub` the input's Bézier points on the span (`p + 1` points of
/// `d` homogeneous coordinates, blocks of `blk`), `piece` the input piece `sub` was
/// restricted from, `tgt` the fit's Bézier points on the span (`m + 1` points), `fit` the
/// fit's control points `tgt` was extracted from.
pub(super) struct RationalSpan<'a> {
    pub(super) sub: &'a [f64],
    pub(super) piece: &'a [f64],
    pub(super) tgt: &'a [f64],
    pub(super) fit: &'a [f64],
}

/// `(bound, floor)` of `max ||C - S||` (model space) on one span of a rational bundle (the
/// module docs): `(d, blk, p)` the point layout and the input degree, `vmin` the smallest
/// control weight of the fit on the span, `sharpen` the value above which the refined hulls
/// are computed as well. The floor is the rounding part no fit can get below.
pub(super) fn rational_bound(
    span: &RationalSpan<'_>,
    nodes: &NodeBound,
    (d, blk, p): (usize, usize, usize),
    vmin: f64,
    sharpen: f64,
) -> (f64, f64) {
    let dim = blk - 1;
    let eps = f64::EPSILON;
    let mut model = Vec::with_capacity(span.sub.len() / blk * dim);
    let mut wmin = f64::INFINITY;
    for q in span.sub.chunks_exact(blk) {
        wmin = wmin.min(q[dim]);
        model.extend(q[..dim].iter().map(|x| x / q[dim]));
    }
    let frame = ModelFrame::new(&model, dim);
    let centre = frame.centre();
    let cnorm = centre.iter().map(|x| x * x).sum::<f64>().sqrt();
    let radius = frame.radius() * (1.0 + 4.0 * eps);
    let split = |from: &[f64], j: usize, a: &mut Vec<f64>, w: &mut Vec<f64>| {
        a.clear();
        w.clear();
        for q in from.chunks_exact(d) {
            let b = &q[j * blk..(j + 1) * blk];
            a.extend((0..dim).map(|c| b[c] - centre[c] * b[dim]));
            w.push(b[dim]);
        }
    };
    // The sizes of the node bound's rounding model: the points the centred values come
    // from, `||A_i|| + ||c|| |W_i|` (the restriction's and the extraction's rounding of
    // `A` and `W` reach `A_c` through `c W`), and the weights.
    let sizes = |from: &[f64], j: usize| {
        from.chunks_exact(d).fold((0.0f64, 0.0f64), |(a, w), q| {
            let b = &q[j * blk..(j + 1) * blk];
            let wa = b[dim].abs();
            let norm = b[..dim].iter().map(|x| x * x).sum::<f64>().sqrt();
            (a.max(norm + cnorm * wa), w.max(wa))
        })
    };
    let (n_sub, n_tgt) = (span.sub.len() / d, span.tgt.len() / d);
    let (mut sa, mut sw) = (Vec::with_capacity(n_sub * dim), Vec::with_capacity(n_sub));
    let (mut ta, mut tw) = (Vec::with_capacity(n_tgt * dim), Vec::with_capacity(n_tgt));
    let mut vals = Vec::new();
    let blocks = d / blk;
    // Node bounds for a single curve only: their rounding model charges the restriction of
    // the uncentred homogeneous points, which grows with the distance from the origin, so
    // the curve fit runs in its frame (`crate::bspline::reduce`); a bundle (the rows of a
    // surface fit, not framed) keeps the refined hulls on the computed points.
    let single = blocks == 1;
    let (mut node_a, mut node_w) = (vec![0.0; blocks], vec![0.0; blocks]);
    let mut size: f64 = 0.0;
    for j in 0..blocks {
        split(span.sub, j, &mut sa, &mut sw);
        split(span.tgt, j, &mut ta, &mut tw);
        let ((pa, pw), (qa, qw)) = (sizes(span.piece, j), sizes(span.fit, j));
        if single {
            node_a[j] = nodes.bound(&sa, &ta, dim, (pa, qa), &mut vals).1;
            node_w[j] = nodes.bound(&sw, &tw, 1, (pw, qw), &mut vals).1;
        } else {
            node_a[j] = hull_bound(&sa, &ta, dim);
            node_w[j] = hull_bound(&sw, &tw, 1);
        }
        let wmax = sw.iter().chain(&tw).fold(0.0f64, |m, x| m.max(x.abs()));
        let amax = max_norm(&sa, dim).max(max_norm(&ta, dim));
        size = size.max(amax + cnorm * wmax);
    }
    // Each translated coordinate is off by ~2 eps of |x| + |c| w, for both curves.
    let shift = 4.0 * eps * size;
    let floor = 2.0 * (p as f64 + 3.0) * eps * size / wmin;
    if vmin <= 0.0 {
        return (f64::INFINITY, floor);
    }
    let combine = |ha: &[f64], hw: &[f64]| {
        let fold = |x: &[f64]| x.iter().copied().fold(0.0f64, f64::max);
        centred_rational_bound(fold(ha) + shift, fold(hw), radius, wmin, vmin)
    };
    let bound = combine(&node_a, &node_w);
    if bound <= sharpen || !single {
        return (bound, floor);
    }
    // Over the budget: per block the smaller of the node bound and the refined hull.
    for j in 0..blocks {
        split(span.sub, j, &mut sa, &mut sw);
        split(span.tgt, j, &mut ta, &mut tw);
        node_a[j] = node_a[j].min(hull_bound(&sa, &ta, dim));
        node_w[j] = node_w[j].min(hull_bound(&sw, &tw, 1));
    }
    (bound.min(combine(&node_a, &node_w)), floor)
}

#[cfg(test)]
mod tests {
    use super::super::{Source, fit, span_bounds};
    use cagd_core::BSplineCurve;
    use cagd_testkit::bench::random_input;

    /// `max ||C - S||` on `[a, b]` in model space, sampled at 4 000 parameters: `c` and
    /// `s` homogeneous polynomial splines (last coordinate the weight).
    fn measured(c: &BSplineCurve, s: &BSplineCurve, (a, b): (f64, f64)) -> f64 {
        let model = |h: Vec<f64>| {
            let w = h[h.len() - 1];
            h[..h.len() - 1].iter().map(|x| x / w).collect::<Vec<_>>()
        };
        (0..=4000)
            .map(|i| {
                let t = a + (b - a) * f64::from(i) / 4000.0;
                let (x, y) = (model(c.eval(t).unwrap()), model(s.eval(t).unwrap()));
                x.iter()
                    .zip(&y)
                    .map(|(u, v)| (u - v) * (u - v))
                    .sum::<f64>()
                    .sqrt()
            })
            .fold(0.0, f64::max)
    }

    /// NURBS of degree 4–14 (weights in [0.5, 2], 3-D, far from the origin, sizes 1e-2 to
    /// 1e3) fitted by cubics on their breaks and on refined knots: every span's bound, by
    /// the node route alone (`sharpen` infinite) and with the hulls (`sharpen` 0), is at
    /// least the densely measured error, and the node route is within a factor of the
    /// hull route's.
    #[test]
    fn bounds_cover_the_measured_error() {
        for (case, p) in [4usize, 6, 9, 11, 14].into_iter().enumerate() {
            for (scale, shift) in [(1e-2, 0.0), (1.0, 50.0), (1e3, 4e3)] {
                let spans = 3;
                let mut knots = vec![0.0; p + 1];
                knots.extend([0.3, 0.55]);
                knots.extend(std::iter::repeat_n(1.0, p + 1));
                let n = knots.len() - p - 1;
                let r = random_input(4 * n, 100 + case as u64);
                let mut hom = Vec::with_capacity(4 * n);
                for i in 0..n {
                    let w = 2f64.powf(r[4 * i + 3]);
                    let smooth = |k: usize| {
                        let s = i as f64 / (n - 1) as f64;
                        shift + scale * ((2.0 + k as f64) * s).sin() + 0.05 * scale * r[4 * i + k]
                    };
                    hom.extend((0..3).map(|k| w * smooth(k)));
                    hom.push(w);
                }
                let c = BSplineCurve::new(p, knots, hom, 4).unwrap();
                let src = Source::new(&c, 4, true).unwrap();
                for extra in [0usize, 5] {
                    let mut cubic = vec![0.0; 4];
                    let mut inner: Vec<f64> = vec![0.3, 0.55];
                    inner.extend((1..=extra).map(|j| j as f64 / (extra + 1) as f64 * 0.98 + 0.001));
                    inner.sort_by(f64::total_cmp);
                    cubic.extend(inner.iter().flat_map(|&t| [t, t]));
                    cubic.extend([1.0; 4]);
                    let pts = fit(&src, 3, &cubic).unwrap();
                    let s = BSplineCurve::new(3, cubic.clone(), pts.clone(), 4).unwrap();
                    let nodes_only =
                        span_bounds(&src, 3, (&cubic, &pts), f64::INFINITY, &mut Vec::new())
                            .unwrap();
                    let sharpened =
                        span_bounds(&src, 3, (&cubic, &pts), 0.0, &mut Vec::new()).unwrap();
                    assert!(nodes_only.len() >= spans);
                    for (x, y) in nodes_only.iter().zip(&sharpened) {
                        let m = measured(&c, &s, (x.a, x.b));
                        assert!(
                            x.bound >= m && y.bound >= m,
                            "p={p} scale={scale}: bounds {:e} / {:e} below measured {m:e}",
                            x.bound,
                            y.bound
                        );
                        assert!(y.bound <= x.bound);
                    }
                }
            }
        }
    }
}
