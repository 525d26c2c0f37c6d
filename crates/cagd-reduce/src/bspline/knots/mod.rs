//! The merge of reduced pieces and knot removal with local (per span) error bookkeeping,
//! as Piegl & Tiller do it: a knot removal changes the curve only on the support of the
//! basis functions whose points move, so its bound is charged to those spans only, and a
//! removal is accepted when every charged span stays within the tolerance.
//! Also the continuity order a strategy keeps at a knot ([`order_at`]).

use cagd_core::{BSplineCurve, BezierCurve, Error, Result, knot_multiplicity};

use super::measure::euclidean_from_homogeneous;
use crate::bezier::max_norm;

mod floor;

/// Passes of the greedy knot removal (a later pass rarely removes more than a few knots).
const MAX_PASSES: usize = 3;

/// Certified error bounds per span of a fixed partition `breaks` of the domain.
#[derive(Debug, Clone)]
pub(crate) struct LocalBounds {
    breaks: Vec<f64>,
    err: Vec<f64>,
}

impl LocalBounds {
    /// Bounds `err[i]` of the spans `[breaks[i], breaks[i + 1]]` (`breaks` increasing,
    /// one longer than `err`).
    pub(crate) fn new(breaks: Vec<f64>, err: Vec<f64>) -> Self {
        debug_assert_eq!(breaks.len(), err.len() + 1);
        Self { breaks, err }
    }

    /// The partition: `spans().len() + 1` increasing breaks.
    pub(crate) fn breaks(&self) -> &[f64] {
        &self.breaks
    }

    /// The bound of every span.
    pub(crate) fn spans(&self) -> &[f64] {
        &self.err
    }

    /// Adds `amount` to the bound of every span meeting the open interval `(a, b)`.
    pub(crate) fn charge(&mut self, a: f64, b: f64, amount: f64) {
        let r = self.range(a, b);
        for e in &mut self.err[r] {
            *e += amount;
        }
    }

    /// The span range `lo..hi` of the partition meeting the open interval `(a, b)`.
    fn range(&self, a: f64, b: f64) -> std::ops::Range<usize> {
        let n = self.err.len();
        let lo = self.breaks[1..].partition_point(|x| *x <= a).min(n);
        let hi = self.breaks.partition_point(|x| *x < b).min(n).max(lo);
        lo..hi
    }

    /// The largest bound over all spans.
    pub(crate) fn max_bound(&self) -> f64 {
        self.err.iter().copied().fold(0.0, f64::max)
    }

    /// Tries to remove one copy of the interior knot `v` of `c` within `tol` on every span
    /// it touches; on success charges the bound to those spans and updates `c`.
    ///
    /// The removal is done by [`BSplineCurve::remove_knot`] on a local window of `c` (the
    /// points `r-2p-1 .. r-s+p+2` and their knots), which holds every point the removal
    /// and its certificate involve, so each removal costs `O(p^2)` plus a splice instead of
    /// `O(n)` allocations.
    pub(crate) fn try_remove_one(&mut self, c: &mut Raw, v: f64, tol: f64) -> Result<bool> {
        self.try_remove_one_with(c, v, tol, None)
    }

    /// [`Self::try_remove_one`], with the spans' bounds sharpened on demand: when the
    /// removal would fit within the bounds `sharpen` could give at best (its `lower`
    /// values) but not within the current ones, the touched spans get their sharper
    /// bound and the removal is judged again.
    fn try_remove_one_with(
        &mut self,
        c: &mut Raw,
        v: f64,
        tol: f64,
        mut sharpen: Option<&mut Sharpen<'_>>,
    ) -> Result<bool> {
        let (m, n) = (c.degree, c.n_points());
        let s = knot_multiplicity(&c.knots, v);
        let (d0, d1) = (c.knots[m], c.knots[n]);
        if s == 0 || v <= d0 || v >= d1 {
            return Ok(false);
        }
        let r = c.knots.partition_point(|x| *x <= v) - 1;
        // The points r-m..=r-s move; their basis functions live on [u_{r-m}, u_{r-s+m+1}].
        let (a, b) = (
            c.knots[r - m],
            c.knots[(r + m + 1 - s).min(c.knots.len() - 1)],
        );
        let span = self.range(a, b);
        let mut worst = self.err[span.clone()].iter().copied().fold(0.0, f64::max);
        let best = match sharpen.as_deref() {
            Some(sh) => sh.best(&self.err, span.clone()),
            None => worst,
        };
        let avail = tol - best;
        if avail <= 0.0 {
            return Ok(false);
        }
        let (lo, hi) = (r.saturating_sub(2 * m + 1), (r + m + 2 - s).min(n));
        if c.removal_floor(r, s, (lo, hi), avail) > avail {
            // The removal's own bound is at least this (`floor.rs`): it cannot succeed.
            return Ok(false);
        }
        let window = c.window(lo, hi)?;
        let out = match c.bundle {
            None => window.remove_knot(v, 1, avail)?,
            Some(block) => window.remove_knot_rational_bundle(v, 1, avail, block)?,
        };
        if out.removed == 0 {
            return Ok(false);
        }
        if out.error_bound > tol - worst {
            let Some(sh) = sharpen.as_deref_mut() else {
                return Ok(false);
            };
            sh.sharpen(&mut self.err, span.clone());
            worst = self.err[span.clone()].iter().copied().fold(0.0, f64::max);
            if out.error_bound > tol - worst {
                return Ok(false);
            }
        }
        c.splice(lo, hi, &out.curve);
        for e in &mut self.err[span.clone()] {
            *e += out.error_bound;
        }
        if let Some(sh) = sharpen {
            for x in &mut sh.charged[span] {
                *x += out.error_bound;
            }
        }
        Ok(true)
    }

    /// Removes `count` copies of each joint `(v, count)` (joints that are `C^count` by
    /// construction, so this costs rounding only); returns `None` if one cannot be removed
    /// within `tol`.
    pub(crate) fn remove_joint_copies(
        &mut self,
        c: &mut Raw,
        joints: &[(f64, usize)],
        tol: f64,
    ) -> Result<bool> {
        for &(v, count) in joints {
            for _ in 0..count {
                if !self.try_remove_one(c, v, tol)? {
                    return Ok(false);
                }
            }
        }
        Ok(true)
    }

    /// Greedy passes over the distinct interior knots, removing copies while every span a
    /// removal touches keeps its accumulated bound `<= tol`, until a pass removes nothing
    /// (at most [`MAX_PASSES`]; each pass costs `O(knots * points)`).
    pub(crate) fn remove_greedily(&mut self, c: &mut Raw, tol: f64) -> Result<()> {
        self.remove_greedily_with(c, tol, None)
    }

    /// [`Self::remove_greedily`] with the spans' bounds sharpened on demand (see
    /// [`Self::try_remove_one_with`]).
    pub(crate) fn remove_greedily_with(
        &mut self,
        c: &mut Raw,
        tol: f64,
        mut sharpen: Option<&mut Sharpen<'_>>,
    ) -> Result<()> {
        for _ in 0..MAX_PASSES {
            let mut removed_any = false;
            let mut values = c.knots.clone();
            values.dedup();
            for v in values {
                while self.try_remove_one_with(c, v, tol, sharpen.as_deref_mut())? {
                    removed_any = true;
                }
            }
            if !removed_any {
                break;
            }
        }
        Ok(())
    }
}

/// Sharper bounds of the spans of a [`LocalBounds`], computed only where a knot removal
/// needs them (the global fit's spans carry a node bound within 1.075x of their error;
/// the refined hull is tighter and costs several times more).
pub(crate) struct Sharpen<'a> {
    /// Per span: its bound without the removals' charges.
    base: Vec<f64>,
    /// Per span: a value the error attains (no bound can be below it).
    lower: Vec<f64>,
    /// Per span: the removals' charges so far.
    charged: Vec<f64>,
    done: Vec<bool>,
    /// The sharper bound of span `i`.
    bound: &'a mut dyn FnMut(usize) -> f64,
}

impl<'a> Sharpen<'a> {
    /// Spans with bounds `base` (as in the [`LocalBounds`], no charges yet) and attained
    /// values `lower`, sharpened by `bound`.
    pub(crate) fn new(
        base: Vec<f64>,
        lower: Vec<f64>,
        bound: &'a mut dyn FnMut(usize) -> f64,
    ) -> Self {
        let n = base.len();
        Self {
            base,
            lower,
            charged: vec![0.0; n],
            done: vec![false; n],
            bound,
        }
    }

    /// The largest bound over `span` that sharpening could give at best.
    fn best(&self, err: &[f64], span: std::ops::Range<usize>) -> f64 {
        span.map(|i| {
            if self.done[i] {
                err[i]
            } else {
                self.lower[i] + self.charged[i]
            }
        })
        .fold(0.0, f64::max)
    }

    /// Replaces the bound of every span of `span` not sharpened yet by its sharper bound
    /// (when smaller) plus its charges.
    fn sharpen(&mut self, err: &mut [f64], span: std::ops::Range<usize>) {
        for i in span {
            if self.done[i] {
                continue;
            }
            self.done[i] = true;
            let b = (self.bound)(i);
            if b < self.base[i] {
                self.base[i] = b;
                err[i] = (b + self.charged[i]) * (1.0 + 2.0 * f64::EPSILON);
            }
        }
    }
}

/// A spline as plain buffers, edited in place by the knot removal.
#[derive(Debug, Clone)]
pub(crate) struct Raw {
    degree: usize,
    dim: usize,
    knots: Vec<f64>,
    points: Vec<f64>,
    weights: Option<Vec<f64>>,
    /// `Some(block)`: the (polynomial) points are a bundle of NURBS curves of homogeneous
    /// points with `block` coordinates, certified in model space
    /// ([`BSplineCurve::remove_knot_rational_bundle`]).
    bundle: Option<usize>,
}

impl Raw {
    /// The number of knots (with multiplicity).
    pub(crate) fn knot_count(&self) -> usize {
        self.knots.len()
    }

    pub(crate) fn new(c: &BSplineCurve) -> Self {
        Self {
            degree: c.degree(),
            dim: c.dim(),
            knots: c.knots().to_vec(),
            points: c.points().to_vec(),
            weights: c.weights().map(<[f64]>::to_vec),
            bundle: None,
        }
    }

    /// The polynomial spline `c` read as a bundle of NURBS curves whose homogeneous points
    /// have `block` coordinates (the columns of a NURBS surface).
    pub(crate) fn new_rational_bundle(c: &BSplineCurve, block: usize) -> Self {
        Self {
            bundle: Some(block),
            ..Self::new(c)
        }
    }

    fn n_points(&self) -> usize {
        self.points.len() / self.dim
    }

    /// The sub-spline of the points `lo..hi` (with their knots).
    fn window(&self, lo: usize, hi: usize) -> Result<BSplineCurve> {
        let (p, d) = (self.degree, self.dim);
        let knots = self.knots[lo..hi + p + 1].to_vec();
        let pts = self.points[lo * d..hi * d].to_vec();
        match &self.weights {
            None => BSplineCurve::new(p, knots, pts, d),
            Some(w) => BSplineCurve::new_rational(p, knots, pts, w[lo..hi].to_vec(), d),
        }
    }

    /// Replaces the window `lo..hi` by `w` (one point and one knot fewer).
    fn splice(&mut self, lo: usize, hi: usize, w: &BSplineCurve) {
        let (p, d) = (self.degree, self.dim);
        self.knots.splice(lo..hi + p + 1, w.knots().iter().copied());
        self.points
            .splice(lo * d..hi * d, w.points().iter().copied());
        if let (Some(ws), Some(nw)) = (&mut self.weights, w.weights()) {
            ws.splice(lo..hi, nw.iter().copied());
        }
    }

    /// The curve (validated again).
    pub(crate) fn into_curve(self) -> Result<BSplineCurve> {
        match self.weights {
            None => BSplineCurve::new(self.degree, self.knots, self.points, self.dim),
            Some(w) => {
                BSplineCurve::new_rational(self.degree, self.knots, self.points, w, self.dim)
            }
        }
    }
}

/// Merges consecutive reduced pieces `(a, b, curve, bound)` into one clamped C0 spline
/// (seed 001 §4.1) and returns it with the per-span bounds: each piece's bound plus, at
/// each joint, half the gap between the two end points (the merge stores their midpoint),
/// converted to model space for NURBS.
pub(crate) fn merge_pieces<'a>(
    pieces: impl Iterator<Item = (f64, f64, &'a BezierCurve, f64)>,
    input: &BSplineCurve,
) -> Result<(BSplineCurve, LocalBounds)> {
    let mut segs = Vec::new();
    let mut breaks = Vec::new();
    let mut err = Vec::new();
    for (a, b, c, bound) in pieces {
        if breaks.is_empty() {
            breaks.push(a);
        }
        breaks.push(b);
        segs.push(c.clone());
        err.push(bound);
    }
    let rational = input.is_rational();
    let work = |c: &BezierCurve| {
        if rational {
            c.homogeneous_points()
        } else {
            c.points().to_vec()
        }
    };
    let pdim = input.dim() + usize::from(rational);
    let mut gaps = Vec::with_capacity(segs.len());
    for w in segs.windows(2) {
        let (l, r) = (work(&w[0]), work(&w[1]));
        let end = &l[l.len() - pdim..];
        let g = end
            .iter()
            .zip(&r[..pdim])
            .map(|(x, y)| (x - y) * (x - y))
            .sum::<f64>()
            .sqrt();
        gaps.push(g);
    }
    let max_gap = gaps.iter().copied().fold(0.0, f64::max);
    let merged = BSplineCurve::from_beziers(&segs, &breaks, 0, max_gap * 1.5 + f64::MIN_POSITIVE)?;
    // The constants of the model-space conversion, once (per joint they made the merge
    // quadratic in the pieces: a 2^20-piece `segments` result ran for minutes, CLI fuzz).
    let model = input.weights().map(|w| {
        let wmin = w.iter().copied().fold(f64::INFINITY, f64::min);
        let vmin = merged
            .weights()
            .map_or(1.0, |v| v.iter().copied().fold(f64::INFINITY, f64::min));
        // The radius covers the pieces' points too: the changed curve is a piece.
        let pmax = segs
            .iter()
            .map(|c| max_norm(c.points(), c.dim()))
            .fold(max_norm(input.points(), input.dim()), f64::max);
        (pmax, wmin, vmin)
    });
    let to_model = |g: f64| -> f64 {
        match model {
            None => g,
            Some((pmax, wmin, vmin)) => euclidean_from_homogeneous(g, pmax, wmin, vmin),
        }
    };
    for (j, g) in gaps.iter().enumerate() {
        // Joint j is between pieces j and j + 1; its point's basis covers both spans.
        let add = to_model(0.5 * g * (1.0 + 4.0 * f64::EPSILON));
        err[j] += add;
        err[j + 1] += add;
    }
    Ok((merged, LocalBounds { breaks, err }))
}

/// The continuity order to keep at the interior knot `t` of `knots` (degree `p`):
/// `min(k, p - s)`, `s` its multiplicity.
///
/// # Errors
/// [`Error::BadParameter`] for a knot of multiplicity `p + 1` (the input may jump there).
pub(crate) fn order_at(knots: &[f64], p: usize, k: usize, t: f64) -> Result<usize> {
    let s = knot_multiplicity(knots, t);
    if s > p {
        return Err(Error::BadParameter {
            name: "knots",
            value: t,
            why: "interior knot of multiplicity p + 1 (possibly discontinuous)",
        });
    }
    Ok(k.min(p - s))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cubic spline with one interior knot whose removal costs `e > 0`, and bounds of
    /// `0.9 tol` on both spans with `tol = 2 e`: the plain removal refuses (no room), the
    /// sharpened one asks the sharper bound of exactly the touched spans, accepts, and
    /// charges the removal on top of the sharpened bounds.
    #[test]
    fn sharpening_on_demand_allows_a_removal_the_node_bounds_refuse() {
        let knots = vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0];
        let pts = vec![0.0, 0.0, 1.0, 2.0, 2.0, -1.0, 3.0, 1.5, 4.0, 0.0];
        let c = BSplineCurve::new(3, knots, pts, 2).unwrap();
        let e = c.remove_knot(0.5, 1, 1e9).unwrap().error_bound;
        assert!(e > 1e-6, "{e}");
        let tol = 2.0 * e;
        let fresh = || LocalBounds::new(vec![0.0, 0.5, 1.0], vec![0.9 * tol; 2]);

        let (mut plain, mut raw) = (fresh(), Raw::new(&c));
        assert!(!plain.try_remove_one(&mut raw, 0.5, tol).unwrap());

        let mut asked = Vec::new();
        let mut sharper = |i: usize| {
            asked.push(i);
            0.1 * tol
        };
        let mut sh = Sharpen::new(vec![0.9 * tol; 2], vec![0.05 * tol; 2], &mut sharper);
        let (mut local, mut raw) = (fresh(), Raw::new(&c));
        assert!(
            local
                .try_remove_one_with(&mut raw, 0.5, tol, Some(&mut sh))
                .unwrap()
        );
        assert_eq!(raw.into_curve().unwrap().knots().len(), 8);
        for b in local.spans() {
            assert!(*b >= 0.1 * tol + e && *b <= tol, "{b} vs {e} {tol}");
        }
        assert_eq!(asked, vec![0, 1]);

        // A sharper bound that is no sharper: refused, the bounds unchanged.
        let mut same = |_: usize| 0.9 * tol;
        let mut sh = Sharpen::new(vec![0.9 * tol; 2], vec![0.05 * tol; 2], &mut same);
        let (mut local, mut raw) = (fresh(), Raw::new(&c));
        assert!(
            !local
                .try_remove_one_with(&mut raw, 0.5, tol, Some(&mut sh))
                .unwrap()
        );
        assert!(local.spans().iter().all(|b| *b == 0.9 * tol));
    }
}
