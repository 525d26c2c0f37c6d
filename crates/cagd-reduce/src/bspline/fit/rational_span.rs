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
//! That is the bound of a bundle (a surface's rows), with `h_A`, `h_W` refined convex
//! hulls ([`crate::bezier::hull_bound`]). A single curve takes the numerator route
//! instead ([`NumeratorNodes`], `numerator_bound.rs`: `max ||A_c W' - A'_c W|| / min (W
//! W')`, node values of the degree-`p + m` numerator times the Ehlich–Zeller factor,
//! rounding included), which keeps the cancellation of the homogeneous errors that the
//! two separate terms lose (up to 2.2 times the measured error at 1e-3 on the
//! `cad_curves` NURBS), and where that bound is above the budget also the refined hull of
//! the numerator, the smaller of the two — the polynomial spans' rule, so an offending
//! span's split count follows the hull.
//! ADDED (issue 17, real-CAD-file row).

use cagd_core::{ModelFrame, centred_rational_bound};

use super::numerator_bound::{CentredSpan, NumeratorNodes};
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

/// `(bound, floor, attained)` of `max ||C - S||` (model space) on one span of a rational
/// bundle (the module docs): `(d, blk, p)` the point layout and the input degree, `vmin`
/// the smallest control weight of the fit on the span, `sharpen` the value above which the
/// refined hulls are computed as well. The floor is the rounding part no fit can get below;
/// `attained` a value the error attains up to rounding (the bound itself for a bundle).
/// `scratch` is reused between spans.
pub(super) fn rational_bound(
    span: &RationalSpan<'_>,
    (d, blk, p): (usize, usize, usize),
    vmin: f64,
    sharpen: f64,
    scratch: &mut [Vec<f64>; 3],
) -> (f64, f64, f64) {
    let dim = blk - 1;
    if d == blk {
        return single_bound(span, (dim, p), vmin, sharpen, scratch);
    }
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
    let blocks = d / blk;
    let (n_sub, n_tgt) = (span.sub.len() / d, span.tgt.len() / d);
    let (mut sa, mut sw) = (Vec::with_capacity(n_sub * dim), Vec::with_capacity(n_sub));
    let (mut ta, mut tw) = (Vec::with_capacity(n_tgt * dim), Vec::with_capacity(n_tgt));
    // A bundle (the rows of a surface fit, not framed) keeps the refined hulls on the
    // computed points.
    let (mut node_a, mut node_w) = (vec![0.0; blocks], vec![0.0; blocks]);
    let mut size: f64 = 0.0;
    for j in 0..blocks {
        split(span.sub, j, &mut sa, &mut sw);
        split(span.tgt, j, &mut ta, &mut tw);
        node_a[j] = hull_bound(&sa, &ta, dim);
        node_w[j] = hull_bound(&sw, &tw, 1);
        let wmax = sw.iter().chain(&tw).fold(0.0f64, |m, x| m.max(x.abs()));
        let amax = max_norm(&sa, dim).max(max_norm(&ta, dim));
        size = size.max(amax + cnorm * wmax);
    }
    // Each translated coordinate is off by ~2 eps of |x| + |c| w, for both curves.
    let shift = 4.0 * eps * size;
    let floor = 2.0 * (p as f64 + 3.0) * eps * size / wmin;
    if vmin <= 0.0 {
        return (f64::INFINITY, floor, f64::INFINITY);
    }
    let combine = |ha: &[f64], hw: &[f64]| {
        let fold = |x: &[f64]| x.iter().copied().fold(0.0f64, f64::max);
        centred_rational_bound(fold(ha) + shift, fold(hw), radius, wmin, vmin)
    };
    let bound = combine(&node_a, &node_w);
    (bound, floor, bound)
}

/// [`rational_bound`] for a single curve: the numerator route ([`NumeratorNodes`]), and
/// where its bound is above `sharpen` also the refined hull of the numerator, the smaller
/// of the two.
fn single_bound(
    span: &RationalSpan<'_>,
    (dim, p): (usize, usize),
    vmin: f64,
    sharpen: f64,
    [sub, tgt, vals]: &mut [Vec<f64>; 3],
) -> (f64, f64, f64) {
    let blk = dim + 1;
    // Any centre gives the same numerator (module docs of `numerator_bound.rs`); the
    // input's first model point keeps the centred values, and so their rounding, small.
    let first = &span.sub[..blk];
    let (mut small, mut heap) = ([0.0f64; 8], Vec::new());
    let centre: &mut [f64] = if dim <= small.len() {
        &mut small[..dim]
    } else {
        heap.resize(dim, 0.0);
        &mut heap
    };
    for (c, x) in centre.iter_mut().zip(&first[..dim]) {
        *c = x / first[dim];
    }
    let centre: &[f64] = centre;
    let cnorm = centre.iter().map(|x| x * x).sum::<f64>().sqrt();
    let wmin = span
        .sub
        .chunks_exact(blk)
        .map(|q| q[dim])
        .fold(f64::INFINITY, f64::min);
    // Written in place: the same operations as pushing them value by value, 1.3 % less
    // of reducing a NURBS to cubics within 1e-3.
    let centred = |from: &[f64], out: &mut Vec<f64>| {
        out.clear();
        out.resize(from.len(), 0.0);
        for (o, b) in out.chunks_exact_mut(blk).zip(from.chunks_exact(blk)) {
            let w = b[dim];
            for ((y, x), c) in o[..dim].iter_mut().zip(&b[..dim]).zip(centre) {
                *y = x - c * w;
            }
            o[dim] = w;
        }
    };
    // `max ||A_i|| + ||c|| |W_i|` and `max |W_i|`: the sizes the rounding is measured in.
    let sizes = |from: &[f64]| {
        from.chunks_exact(blk).fold((0.0f64, 0.0f64), |(a, w), b| {
            let wa = b[dim].abs();
            let norm = b[..dim].iter().map(|x| x * x).sum::<f64>().sqrt();
            (a.max(norm + cnorm * wa), w.max(wa))
        })
    };
    centred(span.sub, sub);
    centred(span.tgt, tgt);
    let m = span.tgt.len() / blk - 1;
    let nodes = NumeratorNodes::cached(p, m);
    let data = CentredSpan {
        sub,
        tgt,
        piece: sizes(span.piece),
        fit: sizes(span.fit),
        vmin,
    };
    let (seen, low, mut bound) = nodes.bound(&data, vals);
    let floor = 2.0 * (p as f64 + 3.0) * f64::EPSILON * data.piece.0 / wmin;
    if bound > sharpen {
        bound = bound.min(nodes.hull(&data, low, vals));
    }
    (bound, floor, seen.min(bound))
}

#[cfg(test)]
mod tests {
    use super::super::{Source, fit, span_bounds};
    use cagd_core::BSplineCurve;
    use cagd_testkit::bench::random_input;

    /// `max ||C - S||` on `[a, b]` in model space, sampled at 4 000 parameters: `c` and
    /// `s` homogeneous polynomial splines (last coordinate the weight).
    fn measured(c: &BSplineCurve, s: &BSplineCurve, span: (f64, f64)) -> f64 {
        let model = |h: Vec<f64>| {
            let w = h[h.len() - 1];
            h[..h.len() - 1].iter().map(|x| x / w).collect::<Vec<_>>()
        };
        cagd_testkit::sampled_max_distance(
            |t| model(c.eval(t).unwrap()),
            |t| model(s.eval(t).unwrap()),
            span,
            4000,
        )
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
