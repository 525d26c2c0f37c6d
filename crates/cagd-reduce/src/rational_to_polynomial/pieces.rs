//! The rational input as homogeneous Bézier pieces `(A, W)` (numerator and weight, seed
//! 001's Bézier extraction applied to the homogeneous control points), evaluated in model
//! space `C = A / W` and restricted to sub-intervals for the certified bounds.

use cagd_core::kernel::{bernstein_all, de_casteljau, subdivide};
use cagd_core::{BSplineCurve, Result};

/// A NURBS curve as homogeneous Bézier pieces on increasing breaks.
#[derive(Debug, Clone)]
pub(crate) struct RationalPieces {
    /// The degree `p` of every piece.
    pub(crate) degree: usize,
    /// Model-space dimension `d` (a homogeneous point has `d + 1` coordinates).
    pub(crate) dim: usize,
    /// `pieces + 1` increasing values.
    pub(crate) breaks: Vec<f64>,
    /// `(p + 1) (d + 1)` homogeneous coordinates `(w x, w)` per piece.
    hom: Vec<f64>,
}

impl RationalPieces {
    /// The pieces of `curve` (rational or not: a polynomial curve gets weights 1).
    pub(crate) fn new(curve: &BSplineCurve) -> Result<Self> {
        let (p, dim) = (curve.degree(), curve.dim());
        let hom = match curve.weights() {
            Some(_) => curve.homogeneous_points(),
            None => curve
                .points()
                .chunks_exact(dim)
                .flat_map(|q| q.iter().copied().chain(std::iter::once(1.0)))
                .collect(),
        };
        let work = BSplineCurve::new(p, curve.knots().to_vec(), hom, dim + 1)?;
        let segs = work.to_beziers()?;
        let mut breaks = Vec::with_capacity(segs.len() + 1);
        let mut hom = Vec::with_capacity(segs.len() * (p + 1) * (dim + 1));
        for s in &segs {
            if breaks.is_empty() {
                breaks.push(s.start);
            }
            breaks.push(s.end);
            hom.extend_from_slice(s.curve.points());
        }
        Ok(Self {
            degree: p,
            dim,
            breaks,
            hom,
        })
    }

    /// Number of pieces.
    pub(crate) fn len(&self) -> usize {
        self.breaks.len() - 1
    }

    /// The homogeneous Bézier points of piece `k`.
    pub(crate) fn piece(&self, k: usize) -> &[f64] {
        let len = (self.degree + 1) * (self.dim + 1);
        &self.hom[k * len..(k + 1) * len]
    }

    /// `C(t) = A(t) / W(t)` on piece `k` (`t` global) into `out` (`d` values); `work` holds
    /// `(p + 1) (d + 1)` and `hom` `d + 1` scratch values.
    pub(crate) fn eval(
        &self,
        k: usize,
        t: f64,
        work: &mut [f64],
        hom: &mut [f64],
        out: &mut [f64],
    ) {
        let (a, b) = (self.breaks[k], self.breaks[k + 1]);
        de_casteljau(self.piece(k), self.dim + 1, (t - a) / (b - a), work, hom);
        let w = hom[self.dim];
        for (o, x) in out.iter_mut().zip(hom.iter()) {
            *o = x / w;
        }
    }

    /// [`RationalPieces::eval`] by the Bernstein sum `sum B_i(s) (w_i P_i, w_i)`, `O(p)` per
    /// coordinate where de Casteljau is `O(p^2)` (all `B_i >= 0`, `sum B_i = 1`: the same
    /// few `(p + 2)` ulps of rounding); `bern` holds `p + 1` and `hom` `d + 1` scratch
    /// values. The fit evaluates `p + m + 1` nodes per span: with de Casteljau a degree-60
    /// input cost `O(p^3)` per span (C ABI fuzz run, issue 18).
    pub(crate) fn eval_fast(
        &self,
        k: usize,
        t: f64,
        bern: &mut [f64],
        hom: &mut [f64],
        out: &mut [f64],
    ) {
        let (a, b) = (self.breaks[k], self.breaks[k + 1]);
        bernstein_all(self.degree, (t - a) / (b - a), bern);
        hom.fill(0.0);
        for (bi, q) in bern.iter().zip(self.piece(k).chunks_exact(self.dim + 1)) {
            for (h, c) in hom.iter_mut().zip(q) {
                *h += bi * c;
            }
        }
        let w = hom[self.dim];
        for (o, x) in out.iter_mut().zip(hom.iter()) {
            *o = x / w;
        }
    }

    /// The piece whose interval contains `t` (the last for the domain's end).
    pub(crate) fn piece_at(&self, t: f64) -> usize {
        self.breaks[1..]
            .partition_point(|x| *x <= t)
            .min(self.len() - 1)
    }

    /// The homogeneous Bézier points of the input on `[a, b]` (inside piece `k`).
    pub(crate) fn restrict(&self, k: usize, a: f64, b: f64) -> Vec<f64> {
        let (pa, pb) = (self.breaks[k], self.breaks[k + 1]);
        let (s0, s1) = ((a - pa) / (pb - pa), (b - pa) / (pb - pa));
        restrict_bezier(self.piece(k), self.dim + 1, s0, s1)
    }
}

/// The Bézier points of `points` (`hdim` coordinates each) restricted to `[s0, s1]` of its
/// parameter interval `[0, 1]` (two de Casteljau subdivisions).
pub(crate) fn restrict_bezier(points: &[f64], hdim: usize, s0: f64, s1: f64) -> Vec<f64> {
    let (mut left, mut right) = (vec![0.0; points.len()], vec![0.0; points.len()]);
    let mut cur = points.to_vec();
    if s1 < 1.0 {
        subdivide(&cur, hdim, s1, &mut left, &mut right);
        cur.copy_from_slice(&left);
    }
    if s0 > 0.0 {
        subdivide(&cur, hdim, s0 / s1, &mut left, &mut right);
        cur.copy_from_slice(&right);
    }
    cur
}
