//! Measured (sampled) error between two B-spline / NURBS curves on a common parameter, and
//! the small helpers the B-spline reducers share.

use std::cell::RefCell;
use std::rc::Rc;

use cagd_core::kernel::{bernstein_all, subdivide};

use crate::bezier::gemm::LinearMap;

use cagd_core::{
    BSplineCurve, BSplineSurface, BezierSegment, Domain2, Error, Result, SurfacePatchPiece,
    TensorPatch, max_distance_2d_with_grid, refine_sampled_maxima_above, tensor_patch_grid,
};

/// `max_t ||a(t) - b(t)||` (Euclidean; rational curves compared in model space) over the
/// common domain, measured per polynomial piece: the domain is cut at the union of both
/// curves' knots, and on every pair of pieces the distance is taken at the `N + 1`
/// Chebyshev–Lobatto nodes of its interval (`N = 3 n`, `n` the degree of the difference's
/// polynomial form: `max(p_a, p_b)`, or `p_a + p_b` for the numerator `A W_b - B W_a` of
/// rational pieces; fewer when the pairs together would exceed
/// [`SPLINE_MEASURE_NODE_BUDGET`] points, a budget divided by `(p_a + p_b + 2) / 16` above
/// degrees 7 + 7: a point costs `O(p_a + p_b)`). By Ehlich and Zeller the largest node
/// value times `sec(n pi / (2 N)) = 1.155` (over the smallest restricted weights for
/// rational pieces) bounds the pair's distance, so in order of their largest node value
/// the pairs that can still hold the maximum — at most [`SPLINE_MEASURED_PIECES`] of them
/// — are sampled at
/// `8 (p_a + p_b) + 64` equidistant parameters and their sampled maxima refined by Brent's
/// method (those of their sampled local maxima that may exceed the largest distance
/// found, [`cagd_core::refine_sampled_maxima_above`]); the pairs whose bound is below the
/// largest distance found are not needed (SPEC-reduce §0 "sampled"; the bounded passes
/// are ADDED). For polynomial curves, after the first refined pair a candidate is first
/// taken at the other half of the Lobatto nodes of `2 N` intervals (factor `sec(n pi / (4
/// N)) = 1.035`) and sampled densely only if that sharper bound still reaches the largest
/// distance found. Never below the sampled maximum, and where no more than
/// [`SPLINE_MEASURED_PIECES`] pairs reach it, the maximum over every pair to Brent's
/// accuracy. ADDED (issue 17, real-CAD-file row): the first pass sampled every pair at the
/// full equidistant density (and refined the 16 of largest sample), the largest part of
/// reducing degree 4–15 curves to cubics with the measurement on; the node values cost
/// about a quarter of that and prune most pairs. Each pair's two pieces are restricted to
/// its interval (de Casteljau) and evaluated with one table of Bernstein values per degree
/// and parameter set applied as a small matrix product (`O(p)` per point, no powers or
/// binomials; de Casteljau per point, `O(p^2)`, made a degree-60 spline of 12 000 pieces
/// take half a minute, C ABI fuzz run, issue 18); Brent refines the maxima on the pieces
/// themselves.
///
/// # Errors
/// [`Error::LengthMismatch`] (different dimensions), [`Error::BadParameter`] (domains
/// differ by more than `1e-12` relative), [`Error::NonFinite`] from the sampling.
///
/// ```
/// use cagd_core::BSplineCurve;
/// let a = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], vec![0.0, 1.0], 1)?;
/// let b = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], vec![0.0, 1.5], 1)?;
/// assert!((cagd_reduce::spline_max_deviation(&a, &b)? - 0.5).abs() < 1e-15);
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn spline_max_deviation(a: &BSplineCurve, b: &BSplineCurve) -> Result<f64> {
    spline_max_deviation_known(a, b, Known::default())
}

/// What a caller of [`spline_max_deviation_known`] knows already about the two curves.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct Known<'a> {
    /// The Bézier pieces of `a`: `pieces + 1` increasing breaks and `(p + 1) h` points per
    /// piece (`h = dim`, or for a NURBS `dim + 1` homogeneous `(w x, w)`), those of
    /// `a.to_beziers()` up to rounding (the global fit's source holds them), so that they
    /// are not extracted again. Ignored unless the sizes match.
    pub(crate) pieces_a: Option<(&'a [f64], &'a [f64])>,
    /// Certified bounds of the distance per interval.
    pub(crate) caps: Option<&'a SpanCaps>,
}

/// Certified bounds of the distance between two curves per interval: `bounds[i] >= max
/// ||a(t) - b(t)||` on `[breaks[i], breaks[i + 1]]` (model units; `breaks` increasing over
/// the domain, one longer than `bounds`), e.g. those a reduction keeps per span.
#[derive(Debug, Clone, Default)]
pub(crate) struct SpanCaps {
    pub(crate) breaks: Vec<f64>,
    pub(crate) bounds: Vec<f64>,
    /// The reduction's input as Bézier pieces, as its reducer extracted them (breaks and
    /// points, [`Known::pieces_a`]'s layout), when it hands them on: a NURBS reduced in
    /// its frame, whose pieces the framed caller moves back to the model
    /// (`framed::Frame::unframe_homogeneous`) for the measurement.
    pub(crate) pieces: Option<(Vec<f64>, Vec<f64>)>,
}

impl Known<'_> {
    /// The largest of the certified bounds ([`Known::caps`]) of the intervals that meet the
    /// open interval `(lo, hi)`: a bound of the distance on it; infinite without caps or
    /// when a cap is not a number.
    fn cap(&self, lo: f64, hi: f64) -> f64 {
        let Some(SpanCaps { breaks, bounds, .. }) = self.caps else {
            return f64::INFINITY;
        };
        let n = bounds.len();
        if n == 0 || breaks.len() != n + 1 || lo < breaks[0] || hi > breaks[n] {
            return f64::INFINITY;
        }
        let first = breaks[1..].partition_point(|x| *x <= lo).min(n);
        let last = breaks.partition_point(|x| *x < hi).min(n).max(first + 1);
        let mut cap = 0.0f64;
        for &x in &bounds[first..last] {
            if x.is_nan() {
                return f64::INFINITY;
            }
            cap = cap.max(x);
        }
        cap
    }
}

/// Relative margin by which a pair's certified cap must fall below the largest distance
/// found for [`spline_max_deviation_known`] to skip it: the sampled distances carry the
/// rounding of their evaluation, which the caps (bounds of the exact distance) do not.
const CAP_MARGIN: f64 = 1e-6;

/// [`spline_max_deviation`] with what the caller knows ([`Known`]): `a`'s pieces as they
/// are, and certified bounds of the distance per interval. With the bounds, the pairs of
/// pieces are visited in decreasing order of their bound (the largest bound over the
/// intervals a pair meets) and a pair whose bound is below the largest distance found so
/// far is not evaluated at all (it cannot hold the maximum, as a pair pruned by its
/// Ehlich–Zeller bound in the second pass); the bound also caps the pair's Ehlich–Zeller
/// bound there. The result is the same maximum — the largest distance found over the pairs
/// that can hold it, each maximised by Brent where it may exceed the rest — with fewer
/// pairs evaluated (ADDED, issue 17's real-CAD-file row: the reductions' span bounds are
/// within about twice the error, so most pairs fall below the largest distance). It is a
/// measurement, not a bound: the caps only decide which pairs need no evaluation, and a
/// wrong cap would hide a larger distance, so the tests compare it with the measurement
/// without caps and with dense sampling.
///
/// # Errors
/// As [`spline_max_deviation`].
pub(crate) fn spline_max_deviation_known(
    a: &BSplineCurve,
    b: &BSplineCurve,
    known: Known<'_>,
) -> Result<f64> {
    max_deviation_passes(a, b, known, true).map(|(d, _)| d)
}

/// [`spline_max_deviation_known`], with the second pass's finer node check on or off
/// (`finer`), and the number of pairs sampled densely (the tests compare the two).
///
/// The finer check (ADDED, issue 17's real-CAD-file row), for polynomial curves: after the
/// first pair's Brent refinement, a pair that its first-pass bound leaves as a candidate
/// is evaluated at the other half of the Chebyshev–Lobatto nodes of twice as many
/// intervals ([`SampleTable::lobatto_odd`]); with the first pass's nodes that is the
/// Lobatto set of `2 N` intervals, whose Ehlich–Zeller factor is `sec(n pi / (4 N)) =
/// 1.035` instead of 1.155, and the pair is sampled densely only where that bound still
/// reaches the largest distance found. A global fit's spans have errors of alike size,
/// and the half set costs a quarter of the dense samples: 2 % fewer instructions on the
/// `cad_curves` B-splines at 1e-3. Not for rational pairs: their bound divides by the
/// smallest restricted control weights, whose slack (the weights vary by ~10 % over a
/// pair there) hides the sharper factor — on the NURBS at 1e-3 it spared 46 of 331 dense
/// pairs for 284 half sets, 3 % more instructions. The result is the same: a pair skipped
/// cannot hold a distance above the largest found.
pub(crate) fn max_deviation_passes(
    a: &BSplineCurve,
    b: &BSplineCurve,
    known: Known<'_>,
    finer: bool,
) -> Result<(f64, usize)> {
    if a.dim() != b.dim() {
        return Err(Error::LengthMismatch {
            what: "curve dimensions",
            got: b.dim(),
            expected: a.dim(),
        });
    }
    let ((a0, a1), (b0, b1)) = (a.domain(), b.domain());
    let scale = 1e-12 * (a1 - a0).max(a0.abs()).max(a1.abs());
    if (a0 - b0).abs() > scale || (a1 - b1).abs() > scale {
        return Err(Error::BadParameter {
            name: "domain",
            value: b0,
            why: "the two curves must have the same parameter domain",
        });
    }
    let hdim = a.dim() + usize::from(a.is_rational());
    let len = (a.degree() + 1) * hdim;
    let mut sa = match known.pieces_a {
        Some((breaks, points)) if breaks.len() >= 2 && points.len() == (breaks.len() - 1) * len => {
            LazyPieces::given(breaks, points, hdim, a.is_rational())
        }
        _ => LazyPieces::of(a),
    };
    let mut sb = LazyPieces::of(b);
    let samples = 8 * (a.degree() + b.degree()) + 64;
    let per_point = (a.degree() + b.degree() + 2).max(16) / 16;
    let (mut i, mut j) = (0, 0);
    let mut pairs = Vec::new();
    while i < sa.spans.len() && j < sb.spans.len() {
        let ((a0, a1), (b0, b1)) = (sa.spans[i].1, sb.spans[j].1);
        let lo = a0.max(b0);
        let hi = a1.min(b1);
        if hi > lo {
            pairs.push((lo, hi, i, j));
        }
        if a1 <= b1 {
            i += 1;
        } else {
            j += 1;
        }
    }
    let dim = a.dim();
    let rational = a.is_rational() || b.is_rational();
    // Pass 1: every pair's distance at the Chebyshev–Lobatto nodes of its interval, and
    // from them an upper bound of the pair's distance (Ehlich–Zeller), at most
    // SPLINE_MEASURE_NODE_BUDGET points in all.
    let degree = if rational {
        a.degree() + b.degree()
    } else {
        a.degree().max(b.degree())
    };
    let nodes = (NODES_PER_DEGREE * degree)
        .min(SPLINE_MEASURE_NODE_BUDGET / per_point / pairs.len().max(1))
        .max(4);
    let factor = ehlich_zeller(degree, nodes);
    let (na, nb) = (
        SampleTable::cached(a.degree(), nodes, Grid::Lobatto),
        SampleTable::cached(b.degree(), nodes, Grid::Lobatto),
    );
    // Distances in units of a power of two `unit` at least the curves' size (exact, so the
    // same maxima as in model units; the squares of a curve at 1e300 do not overflow).
    let unit = measure_unit(a, b);
    let mut scratch = PairScratch {
        inv: 1.0 / unit,
        ..PairScratch::default()
    };
    let mut d2 = Vec::with_capacity(samples + 1);
    let mut best = 0.0f64;
    let mut ranked = Vec::with_capacity(pairs.len());
    // The visited pairs' pieces restricted to their intervals (`a`'s, then `b`'s), for the
    // second pass.
    let mut restricted = Vec::new();
    // The pairs' certified caps, squared in units of `unit` (infinite without caps), and
    // the order of the visit: decreasing caps (the pairs' own order without caps).
    let caps: Vec<f64> = pairs
        .iter()
        .map(|&(lo, hi, _, _)| {
            let c = known.cap(lo, hi) * scratch.inv;
            c * c * (1.0 + CAP_MARGIN)
        })
        .collect();
    let mut order: Vec<usize> = (0..pairs.len()).collect();
    if known.caps.is_some() {
        order.sort_by(|&x, &y| caps[y].total_cmp(&caps[x]));
    }
    for idx in order {
        if caps[idx] < best {
            // Sorted: no later pair can reach the largest distance found either.
            break;
        }
        let (lo, hi, i, j) = pairs[idx];
        let (pa, pb) = (sa.get(i)?, sb.get(j)?);
        scratch.restrict(pa, pb, (lo, hi));
        let reach = scratch.at_nodes(pa, &na, pb, &nb, dim, &mut d2)?;
        let top = d2.iter().copied().fold(0.0f64, f64::max);
        best = best.max(top);
        let from = restricted.len();
        restricted.extend_from_slice(&scratch.a);
        let mid = restricted.len();
        restricted.extend_from_slice(&scratch.b);
        let kept = (from, mid, restricted.len());
        ranked.push((
            top,
            (factor * factor * reach).min(caps[idx]),
            idx,
            reach,
            kept,
        ));
    }
    // Pass 2: in order of their largest node value, the pairs whose bound reaches the
    // largest distance found so far (at most SPLINE_MEASURED_PIECES of them) sampled at
    // `samples + 1` equidistant parameters and their sampled local maxima refined by Brent
    // (`max_distance_1d` with the samples of the tables); a pair whose bound is below it
    // cannot hold the maximum.
    ranked.sort_by(|p, q| q.0.total_cmp(&p.0));
    let fine = ehlich_zeller(degree, 2 * nodes);
    let fine = fine * fine;
    let mut odd: Option<(Rc<SampleTable>, Rc<SampleTable>)> = None;
    let (ta, tb) = (
        SampleTable::cached(a.degree(), samples, Grid::Equidistant),
        SampleTable::cached(b.degree(), samples, Grid::Equidistant),
    );
    let inv = scratch.inv;
    let eval_piece = |piece: &PieceEval, t: f64, out: &mut [f64]| {
        piece.eval(t, out);
        for x in out.iter_mut() {
            *x *= inv;
        }
    };
    let mut refined = 0;
    for &(_, reach, idx, coarse, (from, mid, to)) in &ranked {
        if refined == SPLINE_MEASURED_PIECES {
            break;
        }
        if reach < best {
            continue;
        }
        let (lo, hi, i, j) = pairs[idx];
        let (pa, pb) = (sa.get(i)?, sb.get(j)?);
        scratch.load(&restricted[from..mid], &restricted[mid..to]);
        if finer && !rational && refined > 0 {
            // The other half of the Lobatto nodes of `2 N` intervals: with the first
            // pass's, the pair's bound by the factor of `2 N`.
            let (oa, ob) = odd.get_or_insert_with(|| {
                (
                    SampleTable::cached(a.degree(), nodes, Grid::LobattoOdd),
                    SampleTable::cached(b.degree(), nodes, Grid::LobattoOdd),
                )
            });
            let half = scratch.at_nodes(pa, oa, pb, ob, dim, &mut d2)?;
            if (fine * coarse.max(half)).min(caps[idx]) < best {
                continue;
            }
        }
        refined += 1;
        scratch.sampled(pa, &ta, pb, &tb, dim, &mut d2)?;
        // Only the local maxima that may exceed the largest distance found (a hair below
        // it, so that no maximum the full refinement would raise it with is skipped).
        let d = refine_sampled_maxima_above(
            &|t, o| eval_piece(pa, t, o),
            &|t, o| eval_piece(pb, t, o),
            dim,
            lo,
            hi,
            &d2,
            best.sqrt() * (1.0 - 1e-12),
        );
        best = best.max(d * d);
    }
    Ok((best.sqrt() * unit, refined))
}

/// The smallest power of two at least the largest absolute control point coordinate of
/// `a` and `b` (model space; both curves lie in their control points' hulls; within
/// `2^-1000 ..= 2^1000`), or one when that is zero or not finite: [`spline_max_deviation`]'s
/// unit.
fn measure_unit(a: &BSplineCurve, b: &BSplineCurve) -> f64 {
    let size = a
        .points()
        .iter()
        .chain(b.points())
        .fold(0.0f64, |m, x| m.max(x.abs()));
    if size > 0.0 && size.is_finite() {
        // 2^-1000 ..= 2^1000: the unit and its inverse are normal numbers.
        return size.log2().ceil().clamp(-1000.0, 1000.0).exp2();
    }
    1.0
}

/// Chebyshev–Lobatto nodes per degree of the difference in [`spline_max_deviation`]'s
/// first pass: the Ehlich–Zeller factor is then `sec(pi / 6) = 1.155`.
const NODES_PER_DEGREE: usize = 3;

/// The Ehlich–Zeller factor `sec(n pi / (2 N))` by which the largest absolute value of a
/// degree-`n` polynomial on an interval exceeds its largest value at the `N + 1`
/// Chebyshev–Lobatto nodes (Ehlich & Zeller 1964; for a vector polynomial per direction,
/// so for its Euclidean norm), with a relative allowance of `1e-9` for the rounding of the
/// node values; infinite when `N <= n`.
fn ehlich_zeller(n: usize, nodes: usize) -> f64 {
    if nodes <= n {
        return f64::INFINITY;
    }
    let x = n as f64 * std::f64::consts::PI / (2.0 * nodes as f64);
    (1.0 + 1e-9) / x.cos()
}

/// Pieces maximised in full by [`spline_max_deviation`] (the others are sampled): bounded
/// work on splines of many pieces (ADDED).
pub const SPLINE_MEASURED_PIECES: usize = 16;

/// Points [`spline_max_deviation`] samples over all pieces in its first pass: `2^21`
/// (ADDED; a result of a million pieces took 10+ s to measure at the full density with a
/// Brent refinement on every piece).
pub const SPLINE_MEASURE_NODE_BUDGET: usize = 1 << 21;

/// The Bernstein values of degree `p` at the `coarse + 1` fractions `k / coarse` (row `k`,
/// `p + 1` values) as a map from a piece's points to its samples, shared by every pair of
/// pieces of a measurement.
struct SampleTable(LinearMap);

/// The parameters of a [`SampleTable`]'s rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Grid {
    /// `count + 1` equidistant fractions `k / count` ([`SampleTable::new`]).
    Equidistant,
    /// The `count + 1` Chebyshev–Lobatto nodes ([`SampleTable::lobatto`]).
    Lobatto,
    /// The `count` nodes of the Chebyshev–Lobatto set of `2 count` intervals that the set
    /// of `count` intervals lacks ([`SampleTable::lobatto_odd`]).
    LobattoOdd,
}

/// Sample tables kept per thread for [`SampleTable::cached`]: `(grid, p, count)` and the
/// table, most recent last.
type TableCache = Vec<(Grid, usize, usize, Rc<SampleTable>)>;

/// Most tables [`SampleTable::cached`] keeps: a measurement asks for up to six, which
/// depend on both degrees, so a set of curves of degree 4–15 reduced to cubics, polynomial
/// and rational, cycles through about 130 (at most 2 MB: a degree-15 dense table of 209
/// rows is 27 KB, most are far smaller). Fewer, and the least recently used one is evicted
/// on every call of such a cycle.
const CACHED_TABLES: usize = 144;

thread_local! {
    static TABLES: RefCell<TableCache> = const { RefCell::new(Vec::new()) };
}

impl SampleTable {
    /// The table of degree `p` on the grid `grid` of `count` intervals, kept per thread
    /// for the next measurement (ADDED, issue 17's real-CAD-file row: building the four
    /// tables of a measurement was 6 % of reducing a degree 4–15 B-spline to cubics within
    /// 1e-3 with the measurement on). The values are those of a fresh table.
    fn cached(p: usize, count: usize, grid: Grid) -> Rc<Self> {
        TABLES.with(|c| {
            let mut c = c.borrow_mut();
            if let Some(at) = c
                .iter()
                .position(|e| e.0 == grid && e.1 == p && e.2 == count)
            {
                let hit = c.remove(at);
                let table = Rc::clone(&hit.3);
                c.push(hit);
                return table;
            }
            let table = Rc::new(Self::fresh(p, count, grid));
            if c.len() == CACHED_TABLES {
                c.remove(0);
            }
            c.push((grid, p, count, Rc::clone(&table)));
            table
        })
    }

    /// The table of degree `p` on the grid `grid` of `count` intervals, built.
    fn fresh(p: usize, count: usize, grid: Grid) -> Self {
        match grid {
            Grid::Equidistant => Self::new(p, count),
            Grid::Lobatto => Self::lobatto(p, count),
            Grid::LobattoOdd => Self::lobatto_odd(p, count),
        }
    }

    fn new(p: usize, coarse: usize) -> Self {
        let width = p + 1;
        let mut values = vec![0.0; (coarse + 1) * width];
        for (k, row) in values.chunks_exact_mut(width).enumerate() {
            bernstein_all(p, k as f64 / coarse as f64, row);
        }
        Self(LinearMap::new(coarse + 1, width, values))
    }

    /// The Bernstein values of degree `p` at the `nodes + 1` Chebyshev–Lobatto nodes
    /// `(1 - cos(k pi / nodes)) / 2` of `[0, 1]`.
    fn lobatto(p: usize, nodes: usize) -> Self {
        let width = p + 1;
        let mut values = vec![0.0; (nodes + 1) * width];
        for (k, row) in values.chunks_exact_mut(width).enumerate() {
            let x = if k == nodes {
                1.0
            } else {
                0.5 * (1.0 - (k as f64 * std::f64::consts::PI / nodes as f64).cos())
            };
            bernstein_all(p, x, row);
        }
        Self(LinearMap::new(nodes + 1, width, values))
    }

    /// The Bernstein values of degree `p` at the `nodes` Chebyshev–Lobatto nodes of `2
    /// nodes` intervals with odd index, `(1 - cos((2k + 1) pi / (2 nodes))) / 2`: with
    /// [`SampleTable::lobatto`]`(p, nodes)`, the Lobatto set of `2 nodes` intervals.
    fn lobatto_odd(p: usize, nodes: usize) -> Self {
        let width = p + 1;
        let mut values = vec![0.0; nodes * width];
        for (k, row) in values.chunks_exact_mut(width).enumerate() {
            let angle = (2 * k + 1) as f64 * std::f64::consts::PI / (2 * nodes) as f64;
            bernstein_all(p, 0.5 * (1.0 - angle.cos()), row);
        }
        Self(LinearMap::new(nodes, width, values))
    }
}

/// Buffers of [`PairScratch::sampled`], reused over the pairs, and the measurement's unit.
#[derive(Default)]
struct PairScratch {
    /// `1 / S`, `S` the power of two of [`measure_unit`]: distances are taken in units of
    /// `S` (exactly: a power of two), so that their squares do not overflow.
    inv: f64,
    a: Vec<f64>,
    b: Vec<f64>,
    left: Vec<f64>,
    right: Vec<f64>,
    va: Vec<f64>,
    vb: Vec<f64>,
}

impl PairScratch {
    /// `d2[k] = ||a(x_k) - b(x_k)||^2` at the parameters of the tables' rows (both tables
    /// at the same fractions `x_k` of the pair's interval), as [`Self::sampled`]; returns
    /// the largest squared norm of the difference's polynomial form at those parameters:
    /// `d2` itself for polynomial pieces, and for rational ones `||A W_b - B W_a||^2 / (w_a w_b)^2` with
    /// `w_a`, `w_b` the smallest restricted control weights (lower bounds of `W_a`, `W_b` on
    /// the interval; infinite unless both are positive), so that the Ehlich–Zeller factor
    /// of the numerator's degree `p_a + p_b` bounds the pair's squared distance by it.
    ///
    /// # Errors
    /// [`Error::NonFinite`] at the first value that is not finite.
    fn at_nodes(
        &mut self,
        pa: &PieceEval,
        ta: &SampleTable,
        pb: &PieceEval,
        tb: &SampleTable,
        dim: usize,
        d2: &mut Vec<f64>,
    ) -> Result<f64> {
        self.sampled(pa, ta, pb, tb, dim, d2)?;
        if !pa.rational && !pb.rational {
            return Ok(d2.iter().copied().fold(0.0f64, f64::max));
        }
        let min_weight = |p: &PieceEval, pts: &[f64]| {
            if p.rational {
                pts.chunks_exact(p.hdim)
                    .map(|q| q[p.hdim - 1])
                    .fold(f64::INFINITY, f64::min)
            } else {
                1.0
            }
        };
        let (wa, wb) = (min_weight(pa, &self.a), min_weight(pb, &self.b));
        if !(wa > 0.0 && wb > 0.0) {
            return Ok(f64::INFINITY);
        }
        let weight = |p: &PieceEval, h: &[f64]| if p.rational { h[p.hdim - 1] } else { 1.0 };
        let rows = self
            .va
            .chunks_exact(pa.hdim)
            .zip(self.vb.chunks_exact(pb.hdim));
        let mut top = 0.0f64;
        for (ha, hb) in rows {
            let (xa, xb) = (weight(pa, ha), weight(pb, hb));
            let v: f64 = (0..dim)
                .map(|c| {
                    let d = (ha[c] * xb - hb[c] * xa) * self.inv;
                    d * d
                })
                .sum();
            top = top.max(v);
        }
        Ok(top / (wa * wb * wa * wb))
    }

    /// The pieces `pa` and `pb` restricted to the pair's interval `[lo, hi]` (inside both
    /// pieces' own) into `self.a`, `self.b`: each by two de Casteljau splits, or copied when
    /// it is the whole piece (exact up to rounding).
    fn restrict(&mut self, pa: &PieceEval, pb: &PieceEval, (lo, hi): (f64, f64)) {
        pa.restrict(lo, hi, &mut self.a, &mut self.left, &mut self.right);
        pb.restrict(lo, hi, &mut self.b, &mut self.left, &mut self.right);
    }

    /// A pair's restricted pieces kept from [`Self::restrict`] into `self.a`, `self.b`
    /// (ADDED, issue 17's real-CAD-file row: the second pass restricted every pair it
    /// visited again, 2 % of reducing a NURBS to cubics within 1e-3).
    fn load(&mut self, a: &[f64], b: &[f64]) {
        self.a.clear();
        self.a.extend_from_slice(a);
        self.b.clear();
        self.b.extend_from_slice(b);
    }

    /// `d2[k] = ||a(t_k) - b(t_k)||^2` (in units of `1 / self.inv`) at the parameters
    /// `t_k` of the tables' rows (fractions of the pair's interval; `n + 1` rows), from the
    /// pieces restricted to the interval in `self.a`, `self.b` ([`Self::restrict`] or
    /// [`Self::load`]), all samples of a piece by its table's map.
    ///
    /// # Errors
    /// [`Error::NonFinite`] at the first sample whose distance is not finite.
    fn sampled(
        &mut self,
        pa: &PieceEval,
        ta: &SampleTable,
        pb: &PieceEval,
        tb: &SampleTable,
        dim: usize,
        d2: &mut Vec<f64>,
    ) -> Result<()> {
        let Self {
            inv, a, b, va, vb, ..
        } = self;
        let inv = *inv;
        let samples = ta.0.rows();
        va.resize(samples * pa.hdim, 0.0);
        vb.resize(samples * pb.hdim, 0.0);
        ta.0.apply_loop(a, pa.hdim, va);
        tb.0.apply_loop(b, pb.hdim, vb);
        let rows = va.chunks_exact(pa.hdim).zip(vb.chunks_exact(pb.hdim));
        d2.clear();
        for (k, (ha, hb)) in rows.enumerate() {
            let v: f64 = (0..dim)
                .map(|c| {
                    let d = (pa.coordinate(ha, c) - pb.coordinate(hb, c)) * inv;
                    d * d
                })
                .sum();
            if !v.is_finite() {
                return Err(Error::NonFinite {
                    index: k,
                    coord: 0,
                    value: v,
                });
            }
            d2.push(v);
        }
        Ok(())
    }
}

/// The Bézier pieces of a spline for a measurement, each made ready for evaluation
/// ([`PieceEval`]) when first asked for: a measurement with caps visits a few of its
/// pairs, and extracting every piece of both curves was a tenth of reducing a NURBS to
/// cubics within 1e-3 (issue 17's real-CAD-file row). The pieces are
/// [`BSplineCurve::bezier_piece`]'s, bitwise those of [`BSplineCurve::to_beziers`], or
/// those given ([`Known::pieces_a`]).
struct LazyPieces<'c> {
    source: PieceSource<'c>,
    /// Per piece: its knot span (of an extracted curve) and interval.
    spans: Vec<(usize, (f64, f64))>,
    pieces: Vec<Option<PieceEval>>,
}

/// Where [`LazyPieces`] takes a piece from.
enum PieceSource<'c> {
    /// Extracted from the spline.
    Curve(&'c BSplineCurve),
    /// Given: the pieces' points (`len` values each, `hdim` per point, homogeneous when
    /// `rational`).
    Given {
        points: &'c [f64],
        len: usize,
        hdim: usize,
        rational: bool,
    },
}

impl<'c> LazyPieces<'c> {
    /// The non-empty knot spans of the domain of `curve`, nothing extracted yet.
    fn of(curve: &'c BSplineCurve) -> Self {
        let (u, p) = (curve.knots(), curve.degree());
        let spans: Vec<(usize, (f64, f64))> = (p..u.len() - p - 1)
            .filter(|&s| u[s] < u[s + 1])
            .map(|s| (s, (u[s], u[s + 1])))
            .collect();
        let pieces = spans.iter().map(|_| None).collect();
        Self {
            source: PieceSource::Curve(curve),
            spans,
            pieces,
        }
    }

    /// Pieces given: `breaks` (one more than the pieces) and their points (`(p + 1) hdim`
    /// values each, homogeneous when `rational`), made ready when first asked for.
    fn given(breaks: &[f64], points: &'c [f64], hdim: usize, rational: bool) -> Self {
        let spans: Vec<(usize, (f64, f64))> =
            breaks.windows(2).map(|t| (0, (t[0], t[1]))).collect();
        Self {
            source: PieceSource::Given {
                points,
                len: points.len() / spans.len().max(1),
                hdim,
                rational,
            },
            pieces: spans.iter().map(|_| None).collect(),
            spans,
        }
    }

    /// Piece `i`, extracted now if it was not.
    ///
    /// # Errors
    /// Those of [`BSplineCurve::bezier_piece`].
    fn get(&mut self, i: usize) -> Result<&PieceEval> {
        if self.pieces[i].is_none() {
            let piece = match self.source {
                PieceSource::Curve(curve) => PieceEval::new(&curve.bezier_piece(self.spans[i].0)?),
                PieceSource::Given {
                    points,
                    len,
                    hdim,
                    rational,
                } => {
                    let (start, end) = self.spans[i].1;
                    let q = points[i * len..(i + 1) * len].to_vec();
                    PieceEval::ready(start, end, q, hdim, rational)
                }
            };
            self.pieces[i] = Some(piece);
        }
        Ok(self.pieces[i].as_ref().expect("extracted"))
    }
}

/// A Bézier piece of a spline ready for many evaluations: its (homogeneous, for NURBS)
/// points and scratch for the Bernstein values.
struct PieceEval {
    start: f64,
    end: f64,
    /// Coordinates per point of `points` (`dim + 1` when rational).
    hdim: usize,
    rational: bool,
    points: Vec<f64>,
    /// `C(p, i)`, `i = 0..=p` (computed once, not per point).
    binom: Vec<f64>,
    scratch: RefCell<(Vec<f64>, Vec<f64>)>,
}

impl PieceEval {
    /// The piece on `[start, end]` with Bézier points `points` (`hdim` each: homogeneous
    /// `(w x, w)` when `rational`).
    fn ready(start: f64, end: f64, points: Vec<f64>, hdim: usize, rational: bool) -> Self {
        let n = points.len() / hdim;
        Self {
            start,
            end,
            hdim,
            rational,
            points,
            binom: (0..n).map(|i| cagd_core::binomial_f64(n - 1, i)).collect(),
            scratch: RefCell::new((vec![0.0; n], vec![0.0; hdim])),
        }
    }

    /// The piece `piece` (homogeneous points for a rational one).
    fn new(piece: &BezierSegment) -> Self {
        let c = &piece.curve;
        let rational = c.is_rational();
        let (hdim, points) = if rational {
            (c.dim() + 1, c.homogeneous_points())
        } else {
            (c.dim(), c.points().to_vec())
        };
        Self::ready(piece.start, piece.end, points, hdim, rational)
    }

    /// The piece's (homogeneous) points restricted to the global interval `[lo, hi]` (inside
    /// its own) into `out`: two de Casteljau splits, or a copy when it is the whole piece.
    fn restrict(
        &self,
        lo: f64,
        hi: f64,
        out: &mut Vec<f64>,
        left: &mut Vec<f64>,
        right: &mut Vec<f64>,
    ) {
        let len = self.end - self.start;
        let (a, b) = (
            ((lo - self.start) / len).clamp(0.0, 1.0),
            ((hi - self.start) / len).clamp(0.0, 1.0),
        );
        out.clear();
        out.extend_from_slice(&self.points);
        let n = self.points.len();
        left.resize(n, 0.0);
        right.resize(n, 0.0);
        if b < 1.0 {
            subdivide(out, self.hdim, b, left, right);
            out.copy_from_slice(left);
        }
        if a > 0.0 && b > 0.0 {
            subdivide(out, self.hdim, a / b, left, right);
            out.copy_from_slice(right);
        }
    }

    /// Model-space coordinate `c` of the (homogeneous) sum `h`.
    fn coordinate(&self, h: &[f64], c: usize) -> f64 {
        if self.rational {
            h[c] / h[self.hdim - 1]
        } else {
            h[c]
        }
    }

    /// The piece at the global parameter `t` (clamped to its interval) into `out`, by the
    /// Bernstein sum `sum B_i(s) P_i` (all `B_i >= 0`, `sum B_i = 1`: the rounding is a few
    /// `(p + 2)` ulps of the largest point, as de Casteljau's).
    fn eval(&self, t: f64, out: &mut [f64]) {
        let s = ((t - self.start) / (self.end - self.start)).clamp(0.0, 1.0);
        let mut guard = self.scratch.borrow_mut();
        let (bern, h) = &mut *guard;
        // The Bernstein values as `kernel::bernstein_all` forms them (t^i, then the
        // (1-t)^(n-i) C(n, i) factors from the right), with the binomials of the piece.
        let r = 1.0 - s;
        let mut p = 1.0;
        for b in bern.iter_mut() {
            *b = p;
            p *= s;
        }
        let mut q = 1.0;
        for (b, c) in bern.iter_mut().zip(&self.binom).rev() {
            *b *= q * c;
            q *= r;
        }
        h.fill(0.0);
        for (b, q) in bern.iter().zip(self.points.chunks_exact(self.hdim)) {
            for (v, c) in h.iter_mut().zip(q) {
                *v += b * c;
            }
        }
        if self.rational {
            let w = h[self.hdim - 1];
            for (o, x) in out.iter_mut().zip(h.iter()) {
                *o = x / w;
            }
        } else {
            out.copy_from_slice(h);
        }
    }
}

/// `max_{(u,v)} ||a(u,v) - b(u,v)||` (Euclidean; NURBS compared in model space) over the
/// common domain of two B-spline / NURBS surfaces, measured per cell: both surfaces get
/// the other's missing knot values (knot insertion, exact up to rounding), their Bézier
/// patches are paired cell by cell and sampled on grids by cached Bernstein bases; the
/// [`SURFACE_MEASURED_CELLS`] cells of largest sampled distance are then maximised by
/// [`max_distance_2d_with_grid`] on a grid of `2 (p_a + q_a + p_b + q_b) + 16` intervals
/// per side (boundary edges as curves by Brent, the largest interior sampled local maxima
/// refined by pattern search down to a step of `1e-10` of the cell). ADDED; the surface
/// analogue of [`spline_max_deviation`]. Bounded work: the first pass samples at most
/// [`SURFACE_MEASURE_NODE_BUDGET`] nodes over all cells (the full density when it fits, coarser on
/// surfaces of many thousands of patches). The result is never below the sampled maximum;
/// on a cell whose error has a narrow peak between grid nodes it is the peak to `~1e-12`
/// relative (tests: against a `400 x 400` grid plus refinement).
///
/// # Errors
/// [`Error::LengthMismatch`] (different dimensions, or the cells do not pair up),
/// [`Error::BadParameter`] (domains differ by more than `1e-12` relative),
/// [`Error::NonFinite`] from the sampling.
///
/// ```
/// use cagd_core::BSplineSurface;
/// let k = vec![0.0, 0.0, 1.0, 1.0];
/// let a = BSplineSurface::new((1, 1), k.clone(), k.clone(), vec![0.0, 0.0, 0.0, 0.0], (2, 2), 1)?;
/// let b = BSplineSurface::new((1, 1), k.clone(), k, vec![0.0, 0.0, 0.0, 2.0], (2, 2), 1)?;
/// assert!((cagd_reduce::surface_max_deviation(&a, &b)? - 2.0).abs() < 1e-15);
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn surface_max_deviation(a: &BSplineSurface, b: &BSplineSurface) -> Result<f64> {
    if a.dim() != b.dim() {
        return Err(Error::LengthMismatch {
            what: "surface dimensions",
            got: b.dim(),
            expected: a.dim(),
        });
    }
    let (da, db) = (a.domain(), b.domain());
    for ((a0, a1), (b0, b1)) in [(da.0, db.0), (da.1, db.1)] {
        let scale = 1e-12 * (a1 - a0).max(a0.abs()).max(a1.abs());
        if (a0 - b0).abs() > scale || (a1 - b1).abs() > scale {
            return Err(Error::BadParameter {
                name: "domain",
                value: b0,
                why: "the two surfaces must have the same parameter domain",
            });
        }
    }
    let (ra, rb) = (with_knots_of(a, b)?, with_knots_of(b, a)?);
    let (pa, pb) = (ra.to_beziers()?, rb.to_beziers()?);
    let cells_differ = |x: &SurfacePatchPiece, y: &SurfacePatchPiece| {
        let close = |p: (f64, f64), q: (f64, f64)| {
            let s = 1e-12 * (p.1 - p.0).abs().max(p.0.abs()).max(p.1.abs());
            (p.0 - q.0).abs() <= s && (p.1 - q.1).abs() <= s
        };
        !(close(x.u, y.u) && close(x.v, y.v))
    };
    if pa.len() != pb.len() || pa.iter().zip(&pb).any(|(x, y)| cells_differ(x, y)) {
        return Err(Error::LengthMismatch {
            what: "Bézier cells of the two surfaces",
            got: pb.len(),
            expected: pa.len(),
        });
    }
    let ((p, q), (r, t)) = (a.degrees(), b.degrees());
    let samples = 2 * (p + q + r + t) + 16;
    let cells: Vec<(CellEval, CellEval)> = pa
        .iter()
        .zip(&pb)
        .map(|(x, y)| Ok((CellEval::new(x)?, CellEval::new(y)?)))
        .collect::<Result<_>>()?;
    // Pass 1: every cell sampled on a grid of cached bases, its density shrunk so that all
    // cells together stay within the node budget.
    let coarse = coarse_samples(samples, cells.len());
    let mut best = 0.0f64;
    let mut ranked = Vec::with_capacity(cells.len());
    for (idx, (fx, fy)) in cells.iter().enumerate() {
        let grid = fx.grid_distances(fy, coarse)?;
        let top = grid.iter().copied().fold(0.0f64, f64::max);
        best = best.max(top);
        ranked.push((top, idx));
    }
    // Pass 2: the cells of largest sampled distance maximised in full.
    ranked.sort_by(|x, y| y.0.total_cmp(&x.0));
    for &(_, idx) in ranked.iter().take(SURFACE_MEASURED_CELLS) {
        let (fx, fy) = &cells[idx];
        let grid = fx.grid_distances(fy, samples)?;
        let d = max_distance_2d_with_grid(
            |u, v, o| fx.eval(u, v, o),
            |u, v, o| fy.eval(u, v, o),
            a.dim(),
            Domain2::UnitSquare,
            samples,
            &grid,
        )?;
        best = best.max(d * d);
    }
    Ok(best.sqrt())
}

/// Cells maximised in full by [`surface_max_deviation`] (the others are sampled): bounded
/// work on surfaces of many patches (ADDED).
pub const SURFACE_MEASURED_CELLS: usize = 16;

/// Grid nodes [`surface_max_deviation`] samples over all cells in its first pass: `2^22`,
/// a few tenths of a second (ADDED; a 65 536-patch surface took minutes at the full
/// density on every cell).
pub const SURFACE_MEASURE_NODE_BUDGET: usize = 1 << 22;

/// The per-side sample count of the first pass: `samples`, or fewer (at least 4) when
/// `cells` grids of that size would exceed [`SURFACE_MEASURE_NODE_BUDGET`].
fn coarse_samples(samples: usize, cells: usize) -> usize {
    let per_cell = SURFACE_MEASURE_NODE_BUDGET / cells.max(1);
    let side = per_cell.isqrt();
    samples.min(side.saturating_sub(1)).max(4)
}

/// `s` with every distinct interior knot value of `other` that `s` lacks inserted once.
fn with_knots_of(s: &BSplineSurface, other: &BSplineSurface) -> Result<BSplineSurface> {
    let missing = |mine: &[f64], theirs: &[f64], deg: usize| -> Vec<f64> {
        let (lo, hi) = (theirs[deg], theirs[theirs.len() - deg - 1]);
        let mut out: Vec<f64> = theirs
            .iter()
            .copied()
            .filter(|t| {
                // `mine` is sorted: a binary search (a linear `contains` per knot was
                // quadratic too).
                let i = mine.partition_point(|v| v < t);
                *t > lo && *t < hi && mine.get(i) != Some(t)
            })
            .collect();
        out.dedup();
        out
    };
    let ((_, _), (p, q)) = (s.degrees(), other.degrees());
    // All at once (knot refinement): one insertion after another copied the whole net per
    // knot, quadratic in the spans of `other` (minutes in the C ABI fuzz long run).
    s.refine_knots_u(&missing(s.knots_u(), other.knots_u(), p))?
        .refine_knots_v(&missing(s.knots_v(), other.knots_v(), q))
}

/// One Bézier cell evaluated on the unit square (homogeneous and projected for NURBS).
struct CellEval {
    patch: TensorPatch,
    rational: bool,
    work: RefCell<Vec<f64>>,
}

impl CellEval {
    fn new(piece: &SurfacePatchPiece) -> Result<Self> {
        let (m, n) = piece.patch.degrees();
        let dim = piece.patch.dim();
        let (patch, rational) = match &piece.weights {
            None => (piece.patch.clone(), false),
            Some(w) => {
                let hom: Vec<f64> = piece
                    .patch
                    .points()
                    .chunks_exact(dim)
                    .zip(w)
                    .flat_map(|(x, wi)| x.iter().map(move |c| c * wi).chain([*wi]))
                    .collect();
                (TensorPatch::new(hom, m, n, dim + 1)?, true)
            }
        };
        let work = RefCell::new(vec![0.0; patch.dim()]);
        Ok(Self {
            patch,
            rational,
            work,
        })
    }

    /// The squared distances to `other` on the grid of `samples` intervals per side
    /// ([`max_distance_2d_with_grid`]'s layout), both evaluated by cached bases
    /// ([`tensor_patch_grid`]).
    fn grid_distances(&self, other: &CellEval, samples: usize) -> Result<Vec<f64>> {
        let (ga, gb) = (self.model_grid(samples), other.model_grid(samples));
        let dim = self.patch.dim() - usize::from(self.rational);
        let out: Vec<f64> = ga
            .chunks_exact(dim)
            .zip(gb.chunks_exact(dim))
            .map(|(x, y)| x.iter().zip(y).map(|(a, b)| (a - b) * (a - b)).sum())
            .collect();
        if let Some(index) = out.iter().position(|x: &f64| !x.is_finite()) {
            return Err(Error::NonFinite {
                index,
                coord: 0,
                value: out[index],
            });
        }
        Ok(out)
    }

    /// The cell at every grid node, in model space (projected for NURBS).
    fn model_grid(&self, samples: usize) -> Vec<f64> {
        let g = tensor_patch_grid(&self.patch, samples);
        if !self.rational {
            return g;
        }
        let hd = self.patch.dim();
        g.chunks_exact(hd)
            .flat_map(|h| {
                let w = h[hd - 1];
                h[..hd - 1].iter().map(move |x| x / w)
            })
            .collect()
    }

    fn eval(&self, u: f64, v: f64, out: &mut [f64]) {
        if !self.rational {
            self.patch.eval_into(u, v, out);
            return;
        }
        let mut h = self.work.borrow_mut();
        self.patch.eval_into(u, v, &mut h);
        let w = h[out.len()];
        for (o, x) in out.iter_mut().zip(h.iter()) {
            *o = x / w;
        }
    }
}

/// The model-space bound of a homogeneous bound `eps_h` of a NURBS change *in its frame*
/// (`crate::bspline::framed`: control points centred at the origin, radius `pmax <= 1`):
/// [`cagd_core::centred_rational_bound`] with `h_A = h_W = eps_h`, radius `pmax`, i.e.
/// `eps_h (1 + pmax) / max(vmin, wmin - eps_h)`, infinity when that divisor is not
/// positive. Outside a frame this form mixes units (it grows with the distance from the
/// origin): every caller works on a framed shape.
pub(crate) fn euclidean_from_homogeneous(eps_h: f64, pmax: f64, wmin: f64, vmin: f64) -> f64 {
    cagd_core::centred_rational_bound(eps_h, eps_h, pmax, wmin, vmin)
}

#[cfg(test)]
mod tests {
    use super::{Grid, SampleTable};

    /// The cached tables are the fresh ones, for both kinds, again after more tables than
    /// the cache keeps were asked for (evictions), and a hit is the same table.
    #[test]
    fn cached_tables_are_the_fresh_ones() {
        for round in 0..2 {
            for p in 1..=60 {
                for (count, grid) in [
                    (3 * p + 1, Grid::Lobatto),
                    (3 * p + 1, Grid::LobattoOdd),
                    (8 * p + 64, Grid::Equidistant),
                ] {
                    let fresh = SampleTable::fresh(p, count, grid);
                    let cached = SampleTable::cached(p, count, grid);
                    assert_eq!(cached.0.matrix(), fresh.0.matrix(), "round {round} p {p}");
                    let again = SampleTable::cached(p, count, grid);
                    assert!(std::rc::Rc::ptr_eq(&cached, &again));
                }
            }
        }
    }
}
