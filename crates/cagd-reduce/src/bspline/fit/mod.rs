//! The global least-squares fit behind [`crate::reduce_bspline`]: the degree-`p` input
//! spline `C` is approximated by the degree-`m` spline `S` on a given knot vector that
//! minimises `int ||C(t) - S(t)||^2 dt` over the domain (parameter L2 norm, seed 000
//! §14.4's criterion applied to the whole spline space instead of one segment), with the
//! end points kept (`S(a) = C(a)`, `S(b) = C(b)`).
//!
//! The domain is cut into *cells*, the spans of `S` cut at the breaks of `C`'s pieces
//! ([`Cells`], `spans.rs`; the spans themselves when every break is a knot of `S`), so on
//! each cell the integrand `||C - S||^2 = ||C||^2 - 2 C.S + ||S||^2` is a polynomial; its
//! part that depends on `S` has degree `p + m` (`m < p`), which the `k`-point
//! Gauss–Legendre rule of each cell, `k = ceil((p + m + 1) / 2)`, integrates exactly (the
//! `||C||^2` part, of degree `2p`, is a constant of the minimisation and need not be). The
//! integral is therefore, up to that constant, the squared norm of the residual of a
//! weighted collocation system with one row per (cell, node) — weight `sqrt(w_q h)` — and
//! the fit
//! is that system's least-squares solution, computed by banded Givens QR
//! ([`banded_lsq`]), each cell's rows first compressed to `m + 1` by an orthogonal
//! transformation fixed per `(p, m)` ([`span_rows`]; the source enters through its
//! restriction to the cell, which the span's bound uses too: a span's bound is the
//! largest of its cells'). No normal equations are
//! formed. (The `(p + 1)`-point rule, exact for
//! the whole integrand, gives the same minimiser with up to twice the rows; it was used
//! until issue 17.)
//!
//! NURBS are fitted in homogeneous coordinates. The points may also be *bundles* of
//! `blocks` curves side by side (the rows of a tensor-product surface, fitted in one
//! direction with one knot vector); the bound of a span is then the largest over the
//! blocks, which bounds the surface by the partition of unity in the other direction.

use cagd_core::{BSplineCurve, Result};

mod banded_lsq;
mod node_bound;
mod numerator_bound;
mod predict;
mod span_rows;
mod spans;

use crate::bezier::{hull_bound, max_norm};
pub(crate) use banded_lsq::BandedLsq;
use node_bound::NodeBound;
pub(crate) use predict::Density;
#[cfg(test)]
pub(crate) use predict::predicted_knots;
use span_rows::SpanRows;
pub(crate) use spans::Cells;
pub(crate) use spans::SpanData;
use spans::{Part, casteljau_part};

/// The spline to approximate, as Bézier pieces in working coordinates.
#[derive(Debug, Clone)]
pub(crate) struct Source {
    pub(crate) degree: usize,
    /// Coordinates of one curve of the bundle (`dim + 1` when rational).
    pub(crate) block: usize,
    /// Coordinates of a point: `blocks * block`.
    pub(crate) pdim: usize,
    pub(crate) rational: bool,
    /// The piece breaks (`pieces + 1` increasing values).
    pub(crate) breaks: Vec<f64>,
    /// `(degree + 1) * pdim` Bézier coordinates per piece.
    points: Vec<f64>,
}

impl Source {
    /// The pieces of the polynomial spline `work` whose points are bundles of curves with
    /// `block` coordinates each (the last one a weight when `rational`).
    pub(crate) fn new(work: &BSplineCurve, block: usize, rational: bool) -> Result<Self> {
        let (p, pdim) = (work.degree(), work.dim());
        let knots = work.knots();
        if knots.len() == 2 * p + 2 && knots[0] == knots[p] && knots[p + 1] == knots[2 * p + 1] {
            // One clamped span (a Bézier curve as a spline): its points are the piece.
            return Ok(Self {
                degree: p,
                block,
                pdim,
                rational,
                breaks: vec![knots[p], knots[p + 1]],
                points: work.points().to_vec(),
            });
        }
        let segs = work.to_beziers()?;
        let mut breaks = Vec::with_capacity(segs.len() + 1);
        let mut points = Vec::with_capacity(segs.len() * (p + 1) * pdim);
        for s in &segs {
            if breaks.is_empty() {
                breaks.push(s.start);
            }
            breaks.push(s.end);
            points.extend_from_slice(s.curve.points());
        }
        Ok(Self {
            degree: p,
            block,
            pdim,
            rational,
            breaks,
            points,
        })
    }

    /// The Bézier points of piece `k`.
    pub(crate) fn piece(&self, k: usize) -> &[f64] {
        let len = (self.degree + 1) * self.pdim;
        &self.points[k * len..(k + 1) * len]
    }

    /// The Bézier points of the source on `[a, b]` (inside piece `k`'s interval) in
    /// `out`: piece `k` cut at `b` (its left part), then at `a` (the right part), each by
    /// de Casteljau's triangle ([`casteljau_part`], `O(p^2)` convex combinations); `tmp`
    /// is scratch.
    fn restrict_into(
        &self,
        k: usize,
        (a, b): (f64, f64),
        out: &mut Vec<f64>,
        tmp: &mut [Vec<f64>; 3],
    ) {
        let (pa, pb) = (self.breaks[k], self.breaks[k + 1]);
        let (s0, s1) = ((a - pa) / (pb - pa), (b - pa) / (pb - pa));
        let d = self.pdim;
        let piece = self.piece(k);
        out.clear();
        out.resize(piece.len(), 0.0);
        let [left, x, y] = tmp;
        left.clear();
        left.extend_from_slice(piece);
        if s1 < 1.0 {
            casteljau_part(piece, d, s1, Part::Left, left, (x, y));
        }
        if s0 > 0.0 {
            casteljau_part(left, d, s0 / s1, Part::Right, out, (x, y));
        } else {
            out.copy_from_slice(left);
        }
    }

    /// The Bézier points of every piece, piece after piece.
    pub(crate) fn all_points(&self) -> &[f64] {
        &self.points
    }

    /// The breaks and the points of every piece ([`Self::all_points`]), moved out.
    pub(crate) fn into_pieces(self) -> (Vec<f64>, Vec<f64>) {
        (self.breaks, self.points)
    }

    fn first_point(&self) -> &[f64] {
        &self.points[..self.pdim]
    }

    fn last_point(&self) -> &[f64] {
        &self.points[self.points.len() - self.pdim..]
    }
}

/// The L2-best degree-`m` spline on the clamped knot vector `knots` (on the domain of
/// `src`; its spans may straddle the breaks of `src`) with the end points of `src`: its control points
/// (`knots.len() - m - 1` points of `src.pdim` coordinates).
///
/// # Errors
/// [`cagd_core::Error::Singular`] if the system is rank-deficient (cannot happen for a
/// valid knot vector: `p + 1 >= m + 1` nodes per span determine the span's polynomial).
#[cfg(test)]
pub(crate) fn fit(src: &Source, m: usize, knots: &[f64]) -> Result<Vec<f64>> {
    let mut data = SpanData::default();
    data.fill(src, m, knots);
    fit_restricted(src, m, knots, &data)
}

/// `fit` with the cells' [`SpanData`] given: per cell, its `m + 1`
/// compressed Gauss rows ([`SpanRows`]: `ceil((p + m + 1) / 2)` nodes, exact for every
/// term that depends on the fit) into the banded QR.
///
/// # Errors
/// [`cagd_core::Error::Singular`] if the system is rank-deficient (cannot happen for a
/// valid knot vector: `p + 1 >= m + 1` nodes per span determine the span's polynomial).
pub(crate) fn fit_restricted(
    src: &Source,
    m: usize,
    knots: &[f64],
    data: &SpanData,
) -> Result<Vec<f64>> {
    let (p, d) = (src.degree, src.pdim);
    let n = knots.len() - m - 1;
    let mut out = vec![0.0; n * d];
    out[..d].copy_from_slice(src.first_point());
    out[(n - 1) * d..].copy_from_slice(src.last_point());
    if n <= 2 {
        return Ok(out);
    }
    let span_rows = SpanRows::cached(p, m)?;
    let m1 = m + 1;
    let mut lsq = BandedLsq::new(n - 2, m1, d);
    let (mut rows, mut rhs) = (vec![0.0; m1 * m1], vec![0.0; m1 * d]);
    let (mut buf, mut tmp) = (Vec::new(), [Vec::new(), Vec::new(), Vec::new()]);
    for (i, (c, ext)) in data
        .cells
        .iter()
        .zip(data.exts.chunks_exact(m1 * m1))
        .enumerate()
    {
        let s = c.s;
        let sub = data.sub(src, i, &mut buf, &mut tmp);
        span_rows.rows(c.b - c.a, ext, sub, d, &mut rows, &mut rhs);
        for (row, value) in rows.chunks_exact_mut(m1).zip(rhs.chunks_exact_mut(d)) {
            // Columns s-m..=s; the first and last control points are fixed.
            let (mut lo, mut hi) = (s - m, m1);
            if lo == 0 {
                for (v, e) in value.iter_mut().zip(src.first_point()) {
                    *v -= row[0] * e;
                }
                lo = 1;
            }
            if s == n - 1 {
                for (v, e) in value.iter_mut().zip(src.last_point()) {
                    *v -= row[m] * e;
                }
                hi = m;
            }
            let first = usize::from(s - m == 0);
            lsq.add_row(lo - 1, &row[first..hi], value);
        }
    }
    let x = lsq.solve()?;
    out[d..(n - 1) * d].copy_from_slice(&x);
    Ok(out)
}

/// The Bernstein values `B^p_i(t) = C(p, i) t^i (1 - t)^(p - i)` into `out` (`p + 1`
/// values), `binom` the binomials `C(p, i)` (as `cagd_core::kernel::bernstein_all`, without
/// looking the binomials up per value).
fn bernstein_with(binom: &[f64], t: f64, out: &mut [f64]) {
    let s = 1.0 - t;
    let mut x = 1.0;
    for (o, c) in out.iter_mut().zip(binom) {
        *o = c * x;
        x *= t;
    }
    let mut y = 1.0;
    for o in out.iter_mut().rev() {
        *o *= y;
        y *= s;
    }
}

/// One span of a fitted spline with its certified bound.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct SpanBound {
    pub(crate) a: f64,
    pub(crate) b: f64,
    /// Certified bound of `max ||C - S||` on `[a, b]` (model space).
    pub(crate) bound: f64,
    /// The part of `bound` that is the rounding allowance: no fit can get below it, so a
    /// span whose tolerance is below it cannot be helped by refinement.
    pub(crate) floor: f64,
}

/// [`span_bounds_restricted`], the [`SpanData`] computed here (the tests' entry).
#[cfg(test)]
pub(crate) fn span_bounds(
    src: &Source,
    m: usize,
    (knots, points): (&[f64], &[f64]),
    sharpen: f64,
    attained: &mut Vec<f64>,
) -> Result<Vec<SpanBound>> {
    let mut data = SpanData::default();
    data.fill(src, m, knots);
    span_bounds_restricted(src, m, (knots, points, &data), sharpen, attained)
}

/// The spans `[a, b]` of the degree-`m` spline `(knots, points)` (working coordinates of
/// `src`) with a certified bound of `max ||C - S||` on each (Euclidean, model space): per
/// cell of the span ([`Cells`]: the span itself, or its parts between the breaks of
/// `src`, the largest of their bounds), the piece of `C` restricted to it minus the piece
/// of `S`, bounded by its values
/// at Chebyshev–Lobatto nodes ([`node_bound`], rounding included, within
/// [`node_bound::RATIO`] of the true maximum) and, where that bound is above `sharpen`
/// while the largest node value is not, also by the refined convex hull of the difference
/// with `S` elevated to degree `p` ([`crate::bezier::hull_bound`]), the smaller of the two;
/// the largest over the blocks. For NURBS by [`rational_bound`] (centred, in model space, node bounds with
/// the hulls above `sharpen`: `rational_span.rs`; a single curve by its numerator,
/// `numerator_bound.rs`).
/// A span on which a control weight of `S` is not positive gets an infinite bound.
/// `attained` receives per span a value the error attains up to rounding (the largest
/// node value; the bound itself where a span has no node bound): no sharper bound of the
/// span can be below it. `data` holds the spans' restrictions and extractions; a
/// polynomial span's piece of `S` is its extraction times its control points.
///
/// # Errors
/// [`cagd_core::Error::LengthMismatch`] when `knots` and `points` do not match.
pub(crate) fn span_bounds_restricted(
    src: &Source,
    m: usize,
    (knots, points, data): (&[f64], &[f64], &SpanData),
    sharpen: f64,
    attained: &mut Vec<f64>,
) -> Result<Vec<SpanBound>> {
    attained.clear();
    let (p, d, blk) = (src.degree, src.pdim, src.block);
    let n = points.len() / d;
    if knots.len() != n + m + 1 {
        return Err(cagd_core::Error::LengthMismatch {
            what: "knots",
            got: knots.len(),
            expected: n + m + 1,
        });
    }
    let mut out: Vec<SpanBound> = Vec::with_capacity(n - m);
    let (mut buf, mut tmp) = (Vec::new(), [Vec::new(), Vec::new(), Vec::new()]);
    let (mut tgt, mut scratch) = (vec![0.0; (m + 1) * d], vec![0.0; 2 * (m + 1) * d]);
    let (mut sb, mut tb) = (vec![0.0; (p + 1) * blk], vec![0.0; (m + 1) * blk]);
    let (mut qb, mut pb) = (vec![0.0; (m + 1) * blk], vec![0.0; (p + 1) * blk]);
    let nodes = NodeBound::cached(p, m);
    let mut vals = Vec::new();
    let mut scratch3 = [Vec::new(), Vec::new(), Vec::new()];
    let mut last = usize::MAX;
    for (i, (c, ext)) in data
        .cells
        .iter()
        .zip(data.exts.chunks_exact((m + 1) * (m + 1)))
        .enumerate()
    {
        let (s, k) = (c.s, c.k);
        let sub = data.sub(src, i, &mut buf, &mut tmp);
        let local = &points[(s - m) * d..(s + 1) * d];
        if src.rational && d != blk {
            span_bezier((knots, points, d, m), s, (c.a, c.b), &mut tgt, &mut scratch);
        } else {
            // E Q: a convex combination per point (the rows of E are non-negative and sum
            // to one); its rounding is in `NodeBound::bound`'s allowance, which the
            // numerator bound of a single NURBS takes over (`numerator_bound.rs`: the fit's
            // piece within `((m + 1)(2m + 1) + 2) eps` of its sizes). A rational bundle
            // keeps de Boor's algorithm on the points (its hull bound has no extraction
            // allowance). ADDED: for a single NURBS this was a second de Boor extraction
            // per cell, 3 % of reducing one to cubics within 1e-3.
            tgt.fill(0.0);
            for (t, e) in tgt.chunks_exact_mut(d).zip(ext.chunks_exact(m + 1)) {
                for (c, q) in e.iter().zip(local.chunks_exact(d)) {
                    for (v, x) in t.iter_mut().zip(q) {
                        *v += c * x;
                    }
                }
            }
        }
        let (bound, floor, lower) = if src.rational {
            let vmin = local
                .chunks_exact(blk)
                .map(|q| q[blk - 1])
                .fold(f64::INFINITY, f64::min);
            let span = RationalSpan {
                sub,
                piece: src.piece(k),
                tgt: &tgt,
                fit: local,
            };
            rational_bound(&span, (d, blk, p), vmin, sharpen, &mut scratch3)
        } else {
            let (mut eps, mut floor, mut seen): (f64, f64, f64) = (0.0, 0.0, 0.0);
            for j in 0..d / blk {
                copy_block(sub, d, j, blk, &mut sb);
                copy_block(&tgt, d, j, blk, &mut tb);
                copy_block(local, d, j, blk, &mut qb);
                let pmax = max_norm(block_of(src.piece(k), d, j, blk, &mut pb), blk);
                let (lower, mut upper) =
                    nodes.bound(&sb, &tb, blk, (pmax, max_norm(&qb, blk)), &mut vals);
                if upper > sharpen {
                    // Over the budget: the refined hull, which the split count of an
                    // offending span follows (its size), and which keeps a span whose
                    // node maximum is within the budget from being split for the factor.
                    upper = upper.min(hull_bound(&sb, &tb, blk));
                }
                eps = eps.max(upper);
                seen = seen.max(lower);
                floor = floor.max(2.0 * (p as f64 + 3.0) * f64::EPSILON * max_norm(&sb, blk));
            }
            (eps, floor, seen.min(eps))
        };
        // A span's bound is the largest of its cells' (one cell per span when every
        // break of the source is a knot).
        if s == last {
            let (x, seen) = (out.last_mut(), attained.last_mut());
            let (x, seen) = x.zip(seen).expect("a span is open");
            x.bound = worse(x.bound, bound);
            x.floor = worse(x.floor, floor);
            *seen = worse(*seen, lower);
        } else {
            last = s;
            let (a, b) = (knots[s], knots[s + 1]);
            out.push(SpanBound { a, b, bound, floor });
            attained.push(lower);
        }
    }
    Ok(out)
}

/// The larger of two bounds, `NaN` if either is (`f64::max` would drop it).
fn worse(x: f64, y: f64) -> f64 {
    if x.is_nan() || y.is_nan() {
        f64::NAN
    } else {
        x.max(y)
    }
}

/// The refined-hull bound ([`crate::bezier::hull_bound`]) of `max ||C - S||` on the span
/// `[a, b]` of the fit `(knots, points)` of degree `m` (`a` a knot; the largest over the
/// blocks): the sharper bound a knot removal asks for where the node bound of
/// [`span_bounds_restricted`] leaves it no room. For a single NURBS the smaller of the
/// numerator's node bound and its refined hull (`rational_span.rs`); `+inf` for a rational
/// bundle (its bound has no node route to sharpen).
pub(crate) fn hull_span_bound(
    src: &Source,
    m: usize,
    (knots, points): (&[f64], &[f64]),
    (a, b): (f64, f64),
) -> f64 {
    let (p, d, blk) = (src.degree, src.pdim, src.block);
    if src.rational && d != blk {
        return f64::INFINITY;
    }
    let s = knots.partition_point(|x| *x <= a) - 1;
    debug_assert!(knots[s] == a && knots[s + 1] == b);
    let (mut tgt, mut work) = (vec![0.0; (m + 1) * d], vec![0.0; 2 * (m + 1) * d]);
    let mut sub = Vec::with_capacity((p + 1) * d);
    let mut tmp = [Vec::new(), Vec::new(), Vec::new()];
    let mut scratch = [Vec::new(), Vec::new(), Vec::new()];
    let (mut sb, mut tb) = (vec![0.0; (p + 1) * blk], vec![0.0; (m + 1) * blk]);
    let fit = &points[(s - m) * d..(s + 1) * d];
    let mut worst: f64 = 0.0;
    // The span's cells (one when every break of the source is a knot), the largest.
    for c in Cells::of_span(knots, s, &src.breaks) {
        span_bezier((knots, points, d, m), s, (c.a, c.b), &mut tgt, &mut work);
        src.restrict_into(c.k, (c.a, c.b), &mut sub, &mut tmp);
        let bound = if src.rational {
            let vmin = fit
                .chunks_exact(blk)
                .map(|q| q[blk - 1])
                .fold(f64::INFINITY, f64::min);
            let span = RationalSpan {
                sub: &sub,
                piece: src.piece(c.k),
                tgt: &tgt,
                fit,
            };
            rational_bound(&span, (d, blk, p), vmin, 0.0, &mut scratch).0
        } else {
            let mut eps: f64 = 0.0;
            for j in 0..d / blk {
                copy_block(&sub, d, j, blk, &mut sb);
                copy_block(&tgt, d, j, blk, &mut tb);
                eps = worse(eps, hull_bound(&sb, &tb, blk));
            }
            eps
        };
        worst = worse(worst, bound);
    }
    worst
}

/// The Bézier points on `[a, b]` (inside span `s`, `knots[s] < knots[s + 1]`) of the
/// degree-`m` spline `(knots, points)` of `d` coordinates in `out`: the blossom values
/// `S(a^(m - k), b^k)`, `k = 0..=m`, each by `m` levels of de Boor's convex combinations
/// of the points `s - m ..= s` (the extraction of [`BSplineCurve::to_beziers`], without
/// its allocations; on the whole span, `a = knots[s]`, `b = knots[s + 1]`).
fn span_bezier(
    (knots, points, d, m): (&[f64], &[f64], usize, usize),
    s: usize,
    (a, b): (f64, f64),
    out: &mut [f64],
    work: &mut [f64],
) {
    span_bezier_of(
        (knots, m),
        s,
        (a, b),
        (&points[(s - m) * d..(s + 1) * d], d),
        out,
        work,
    );
}

/// [`span_bezier`] from the span's own `m + 1` points `local` (those of `s - m ..= s`, `d`
/// coordinates each); with the unit vectors as points, the span's Bézier extraction on
/// `[a, b]`. For `a`, `b` inside the span every de Boor weight is in `[0, 1]`, so the
/// values are convex combinations of `local`, as on the whole span. `work` is scratch of
/// at least `2 (m + 1) d` values.
///
/// Point `k` is the blossom `S(a^(m - k), b^k)`: `m` levels of de Boor's algorithm, the
/// first `m - k` at `a`, the rest at `b`. The levels at `a` are shared: one chain of them
/// (after `r` levels, the start of point `m - r`), and each point continues from it with
/// its levels at `b`, the weights of each level computed once for `a` and once for `b`.
/// Every point is the same sequence of operations as one de Boor run per point
/// ([`span_bezier_of_runs`], the route before; bitwise the same values, tested), with
/// `m + m (m + 1) / 2` levels instead of `m (m + 1)` and a third of the divisions (ADDED,
/// issue 17's real-CAD-file row: the extractions were a tenth of reducing a NURBS to
/// cubics within 1e-3).
fn span_bezier_of(
    (knots, m): (&[f64], usize),
    s: usize,
    (a, b): (f64, f64),
    (local, d): (&[f64], usize),
    out: &mut [f64],
    work: &mut [f64],
) {
    const MAX_M: usize = 8;
    if m > MAX_M || m == 0 {
        span_bezier_of_runs((knots, m), s, (a, b), (local, d), out, work);
        return;
    }
    let len = (m + 1) * d;
    // Level r's weights for point i = s - m + j (j = r..=m), at `a` and at `b`.
    let (mut wa, mut wb) = ([0.0f64; MAX_M * MAX_M], [0.0f64; MAX_M * MAX_M]);
    for r in 1..=m {
        for j in r..=m {
            let i = s - m + j;
            let (lo, hi) = (knots[i], knots[i + m + 1 - r]);
            let at = (r - 1) * MAX_M + (j - 1);
            wa[at] = (a - lo) / (hi - lo);
            wb[at] = (b - lo) / (hi - lo);
        }
    }
    let (chain, cur) = work[..2 * len].split_at_mut(len);
    chain.copy_from_slice(local);
    for k in (0..=m).rev() {
        let ra = m - k;
        if ra > 0 {
            // One more level at `a` on the chain: level `ra`.
            de_boor_level(chain, d, ra, m, &wa[(ra - 1) * MAX_M..ra * MAX_M]);
        }
        cur.copy_from_slice(chain);
        for r in ra + 1..=m {
            de_boor_level(cur, d, r, m, &wb[(r - 1) * MAX_M..r * MAX_M]);
        }
        out[k * d..(k + 1) * d].copy_from_slice(&cur[m * d..(m + 1) * d]);
    }
}

/// One level `r` of de Boor's algorithm on the `m + 1` points `x` (`d` coordinates each):
/// point `j` (descending from `m` to `r`) becomes `(1 - w) x_(j-1) + w x_j` with `w =
/// weights[j - 1]`.
#[inline(always)]
fn de_boor_level(x: &mut [f64], d: usize, r: usize, m: usize, weights: &[f64]) {
    for j in (r..=m).rev() {
        let alpha = weights[j - 1];
        let (lo, hi) = x.split_at_mut(j * d);
        let prev = &lo[(j - 1) * d..];
        for (y, z) in hi[..d].iter_mut().zip(prev) {
            *y = (1.0 - alpha) * z + alpha * *y;
        }
    }
}

/// [`span_bezier_of`] by one de Boor run of `m` levels per point (the route before the
/// shared chain; kept for `m` above its stack tables and as the tests' reference).
fn span_bezier_of_runs(
    (knots, m): (&[f64], usize),
    s: usize,
    (a, b): (f64, f64),
    (local, d): (&[f64], usize),
    out: &mut [f64],
    work: &mut [f64],
) {
    let work = &mut work[..(m + 1) * d];
    for k in 0..=m {
        work.copy_from_slice(local);
        for r in 1..=m {
            let u = if r <= m - k { a } else { b };
            // Point i (of s - m ..= s) at level r, descending so that point i - 1 is
            // still of level r - 1.
            for i in (s - m + r..=s).rev() {
                let (lo, hi) = (knots[i], knots[i + m + 1 - r]);
                let alpha = (u - lo) / (hi - lo);
                let j = (i + m - s) * d;
                for c in 0..d {
                    work[j + c] = (1.0 - alpha) * work[j + c - d] + alpha * work[j + c];
                }
            }
        }
        out[k * d..(k + 1) * d].copy_from_slice(&work[m * d..(m + 1) * d]);
    }
}

/// [`copy_block`] into `to` unless the points are one block: the block's points.
fn block_of<'a>(from: &'a [f64], d: usize, j: usize, blk: usize, to: &'a mut [f64]) -> &'a [f64] {
    if d == blk {
        return from;
    }
    copy_block(from, d, j, blk, to);
    to
}

/// Copies coordinates `j * blk .. (j + 1) * blk` of every point of `from` (points of `d`
/// coordinates) to `to`.
fn copy_block(from: &[f64], d: usize, j: usize, blk: usize, to: &mut [f64]) {
    for (dst, src) in to.chunks_exact_mut(blk).zip(from.chunks_exact(d)) {
        dst.copy_from_slice(&src[j * blk..(j + 1) * blk]);
    }
}

mod rational_span;
use rational_span::{RationalSpan, rational_bound};

#[cfg(test)]
mod tests;
