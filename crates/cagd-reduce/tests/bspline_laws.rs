//! Property laws of the B-spline / NURBS curve degree reduction [`reduce_bspline`], on
//! the inputs the unit tests of `src/bspline/tests.rs` (clamped, `[0, 1]`, coordinates
//! in `[-10, 10]`, `m >= 2`, tolerance `>= 1e-4`) leave out.
//!
//! Inputs: degrees 2..=6, 1..=5 spans, 2-D or 3-D; clamped or unclamped at either end
//! (`knots[0] < knots[p]` and / or `knots[n] < knots[n + p]`, the outer knots spaced
//! 0.03..30 mean spans apart); the domain at `0` or `±10^(0..6)` (often `1e3..1e6`) with a
//! length of `10^(-3..3)`; neighbouring spans up to `1e3` times longer than each other;
//! interior knots repeated up to multiplicity `p` (C0 joints); control points of size
//! `10^(-6..6)`, half the time offset from the origin by up to `1e4` times that size;
//! polynomial or NURBS with weights `10^(±r)`, `r` up to 2 (a ratio of up to `1e4`). Every
//! target `m` in `1..p`, every strategy (global fit, segments with L2 and with constrained
//! Chebyshev, Piegl & Tiller 1995), the default or an explicit `continuity: Some(k)` for
//! every `k` the strategy accepts. Tolerances `10^(-1..-5)` of the point size.
//!
//! 1. The call succeeds. The documented errors are accepted only where their condition can
//!    be seen to hold: Piegl & Tiller's `ConditionNotMet` on random input (it never
//!    subdivides, so it fails on most inputs that are not degree-elevated ones; law 6
//!    requires it to succeed on those). The global fit and the segments must succeed: the
//!    generator keeps every case far from the documented limits (tolerance at least `1e6`
//!    times the rounding level `(p + 3) eps max |x|`, `2^20` spans) by raising the tolerance
//!    until a model of the span count the fit needs ([`predicted_pieces`]: `~h^(m+1)` error
//!    of a degree-`m` piece, from the `(m+1)`-th derivative of the input) predicts at most
//!    [`MAX_PIECES`] spans of at least [`MIN_ULPS`] parameter ulps each.
//! 2. `report.error_bound <= tolerance`.
//! 3. The bound is honest: the distance between input and result, sampled at every knot of
//!    both, 7 points inside every span of their common refinement and 1 001 uniform
//!    parameters, is at most `error_bound` plus a rounding allowance of `1e-12` of the
//!    largest coordinate (the offset included: evaluation rounds relative to it).
//! 4. The result has degree `m`, the input's domain (exactly: its end knots are the
//!    input's `knots[p]`, `knots[n]`), is clamped there, and is rational iff the input is.
//! 5. Continuity: `report.continuity` lists exactly the distinct interior knots of the input
//!    still present in the result, with `k = min(continuity, p - s, m - 1)` (`s` the input
//!    multiplicity; Piegl & Tiller: `p - s`, its documented value); at each, the result is
//!    `C^k`, checked on the geometry by the jumps of the one-sided derivatives of the
//!    adjacent Bézier pieces (homogeneous for NURBS) against their rounding scale (as in
//!    `surface_laws.rs`).
//! 6. Reproduction: a degree-`m` spline (`m` in 1..=4) of the same kind (exotic knots,
//!    offsets, NURBS), degree-elevated exactly by `d` in 1..=3 (every Bézier piece
//!    elevated, merged back by [`BSplineCurve::from_beziers`], then each joint's extra
//!    copies removed so that it keeps its own continuity `C^(m - s)`), reduces back to
//!    degree `m` by every strategy within `1e-9` of its largest coordinate (laws 2 to 4
//!    too), on no more spans than it had, with no new knot, within that tolerance of the
//!    original.
//!
//! Distances and derivative jumps are computed here (a de Boor evaluation of this file,
//! checked against [`BSplineCurve::eval`], and the Bézier pieces of cagd-core),
//! independently of the reducer's own certification. Every law was seen to fail on a
//! deliberately broken reducer (an error past 20 spans, a bound above the tolerance or
//! halved or 1% low, a domain end moved by `1e-9`, the weights dropped, one knot copy too
//! many at kept knots, a wrong `report.continuity`, extra knots kept).
//!
//! Library failures found (the failing cases are in `bspline_laws.proptest-regressions`,
//! with their minimal inputs and diagnosis); all in the segment strategy, or in Piegl &
//! Tiller, but one in the global fit (fixed, the test
//! [`steep_nurbs_joints_do_not_stall_the_fit`]):
//! * law 3, segments: the pieces of a subdivided span are placed at the rounded parameters
//!   `a + (b - a) s` but reduced from the input on the exact `[s0, s1]`, so the result is
//!   off by up to `|C'| ulp(t)`, which the bound does not include (domains far from 0);
//! * laws 1 and 2, segments on NURBS: the per-segment bounds and the merge gaps are turned
//!   into model space with `(1 + max ||P||) / min w`, neither centred nor free of units, so
//!   far from the origin the strategy fails with "below the rounding level" at tolerances
//!   `1e6..1e8` times the curve's rounding level, needs up to thousands of times more
//!   pieces, or returns a bound above the tolerance (the merge charges are never checked
//!   against it); a tiny curve (size `1e-5`) is subdivided needlessly, and then meets the
//!   law 3 bug (law 6's spans and distance);
//! * law 6, Piegl & Tiller on NURBS: the same conversion (documented there) makes it fail
//!   on exactly elevated NURBS a few thousand units from the origin or of size `1e-5`.
//! * law 1, global fit on a NURBS with steep C0 / C1 joints and weights `0.023..43`: the
//!   refinement split spans on one side of a joint only, down to the rounding level, while
//!   the fit's value at the joint was set by the long span on the other side (fixed by
//!   grading the refinement mesh).

use cagd_core::{BSplineCurve, BezierCurve, Error, knot_multiplicity};
use cagd_reduce::{BSplineOptions, BSplineReduction, BSplineStrategy, Method, reduce_bspline};
use cagd_testkit::points;
use proptest::prelude::*;

/// Most input degree.
const MAX_DEG: usize = 6;
/// Most input spans.
const MAX_SPANS: usize = 5;
/// Most control points: `p + 1` plus up to `p` copies of each interior knot.
const MAX_N: usize = MAX_DEG + 1 + (MAX_SPANS - 1) * MAX_DEG;
/// Most spans the fit of a random case should need (predicted); the tolerance is raised
/// where more are predicted.
const MAX_PIECES: f64 = 1500.0;
/// Fewest parameter ulps (of the domain's magnitude) a predicted span should have, so that
/// no case is near the rounding level of the parameter.
const MIN_ULPS: f64 = 4096.0;
/// The largest derivative jump across a kept knot, as a fraction of its rounding scale (see
/// [`worst_jump`]), that still counts as continuity.
const JUMP_LIMIT: f64 = 1e-11;

// ---------------------------------------------------------------------------------------
// Random input.

/// The knot structure of a random curve.
#[derive(Debug, Clone)]
struct Shape {
    /// Degree.
    p: usize,
    /// Number of distinct spans of the domain.
    spans: usize,
    /// `log10` of the relative span lengths, in `[0, 3]`.
    lens: Vec<f64>,
    /// Raw draws of the interior multiplicities (see [`Shape::mult`]).
    mults: Vec<usize>,
    /// Raw draws of how many of the `p + 1` end knots at each end equal the domain end
    /// (`1 + raw % (p + 1)`; `p + 1` is clamped).
    ends: (usize, usize),
    /// `log10` of the outer knot gaps in mean spans, in `[-1.5, 1.5]`.
    outer: Vec<f64>,
    /// Domain start.
    start: f64,
    /// Domain length.
    len: f64,
}

impl Shape {
    /// The multiplicity of interior break `i`: 1 half the time, else `2..=p`.
    fn mult(&self, i: usize) -> usize {
        let raw = self.mults[i];
        if raw % 2 == 0 || self.p == 1 {
            1
        } else {
            2 + (raw / 2) % (self.p - 1)
        }
    }

    /// The knot vector.
    fn knots(&self) -> Vec<f64> {
        let p = self.p;
        let (a, len) = (self.start, self.len);
        let b = a + len;
        let rel: Vec<f64> = self.lens[..self.spans]
            .iter()
            .map(|e| 10f64.powf(*e))
            .collect();
        let total: f64 = rel.iter().sum();
        let mean = len / self.spans as f64;
        let (left, right) = (1 + self.ends.0 % (p + 1), 1 + self.ends.1 % (p + 1));
        let gap = |i: usize| mean * 10f64.powf(self.outer[i]);
        // Outer knots below the domain (the farthest first), then the domain start.
        let mut k: Vec<f64> = Vec::new();
        let mut x = a;
        for i in 0..p + 1 - left {
            x -= gap(i);
            k.push(x);
        }
        k.reverse();
        k.extend(std::iter::repeat_n(a, left));
        let mut acc = 0.0;
        for (i, r) in rel.iter().enumerate().take(self.spans - 1) {
            acc += r;
            let t = a + len * (acc / total);
            k.extend(std::iter::repeat_n(t, self.mult(i)));
        }
        k.extend(std::iter::repeat_n(b, right));
        let mut x = b;
        for i in 0..p + 1 - right {
            x += gap(MAX_DEG + 1 + i);
            k.push(x);
        }
        k
    }
}

/// A random knot structure of degree `degree`.
fn shape(degree: impl Strategy<Value = usize>) -> impl Strategy<Value = Shape> {
    (
        degree,
        1..=MAX_SPANS,
        proptest::collection::vec(0.0f64..3.0, MAX_SPANS),
        proptest::collection::vec(0..4 * MAX_DEG, MAX_SPANS),
        (0..=MAX_DEG, 0..=MAX_DEG),
        proptest::collection::vec(-1.5f64..1.5, 2 * MAX_DEG + 2),
        (any::<bool>(), -1.0f64..6.0, -3.0f64..3.0),
    )
        .prop_map(|(p, spans, lens, mults, ends, outer, (neg, e, l))| {
            let start = if e < 0.0 {
                0.0
            } else if neg {
                -(10f64.powf(e))
            } else {
                10f64.powf(e)
            };
            Shape {
                p,
                spans,
                lens,
                mults,
                ends,
                outer,
                start,
                len: 10f64.powf(l),
            }
        })
}

/// Where the control points sit and how big the curve is.
#[derive(Debug, Clone, Copy)]
struct Place {
    /// Coordinate size of the curve (points in `offset + size [-1, 1]^dim`).
    size: f64,
    /// Offset of every coordinate.
    offset: f64,
    /// Dimension (2 or 3).
    dim: usize,
    /// `Some(r)`: NURBS with weights `10^(r u)`, `u` in `[-1, 1]`.
    weights: Option<f64>,
}

/// A random place: size `10^(-6..6)`, half the time offset by `10^(0..4)` sizes.
fn place() -> impl Strategy<Value = Place> {
    (
        -6.0f64..6.0,
        (any::<bool>(), 0.0f64..4.0),
        2..=3usize,
        (any::<bool>(), 0.0f64..2.0),
    )
        .prop_map(|(s, (off, o), dim, (rational, r))| {
            let size = 10f64.powf(s);
            Place {
                size,
                offset: if off { size * 10f64.powf(o) } else { 0.0 },
                dim,
                weights: rational.then_some(r),
            }
        })
}

/// The curve of knot structure `shape` placed by `place`, from the raw coordinates `raw`
/// (in `[-10, 10]`) and weight exponents `wraw` (in `[-1, 1]`).
fn build(shape: &Shape, place: &Place, raw: &[f64], wraw: &[f64]) -> BSplineCurve {
    let knots = shape.knots();
    let n = knots.len() - shape.p - 1;
    let d = place.dim;
    let pts: Vec<f64> = raw[..n * d]
        .iter()
        .map(|x| place.offset + place.size * x / 10.0)
        .collect();
    match place.weights {
        None => BSplineCurve::new(shape.p, knots, pts, d),
        Some(r) => {
            let w = wraw[..n].iter().map(|u| 10f64.powf(r * u)).collect();
            BSplineCurve::new_rational(shape.p, knots, pts, w, d)
        }
    }
    .unwrap()
}

/// The strategy of draw `i` (0..4).
fn strategy_of(i: usize) -> BSplineStrategy {
    match i % 4 {
        0 => BSplineStrategy::GlobalFit,
        1 => BSplineStrategy::Segments(Method::L2 { r: 0, p: 0 }),
        2 => BSplineStrategy::Segments(Method::ConstrainedChebyshev { r: 0, p: 0 }),
        _ => BSplineStrategy::PieglTiller1995,
    }
}

/// The most continuity `strategy` keeps at target `m`.
fn kmax(strategy: BSplineStrategy, m: usize) -> usize {
    match strategy {
        BSplineStrategy::Segments(_) => (m - 1) / 2,
        _ => m - 1,
    }
}

/// The largest absolute coordinate of the control points (at least `f64::MIN_POSITIVE`).
fn magnitude(c: &BSplineCurve) -> f64 {
    c.points()
        .iter()
        .fold(f64::MIN_POSITIVE, |m, x| m.max(x.abs()))
}

/// The distinct interior breaks of the domain with their multiplicities.
fn interior_breaks(c: &BSplineCurve) -> Vec<(f64, usize)> {
    let (a, b) = c.domain();
    let mut ts: Vec<f64> = c
        .knots()
        .iter()
        .copied()
        .filter(|&t| a < t && t < b)
        .collect();
    ts.dedup();
    ts.into_iter()
        .map(|t| (t, knot_multiplicity(c.knots(), t)))
        .collect()
}

/// The number of spans the global fit of `c` to degree `m` within `tol` is predicted to
/// need, and the fewest parameter ulps of one of them: on each input span, the integral of
/// `(|C^(m+1)(t)| / (K tol))^(1/(m+1))` by the midpoint rule on 32 intervals (the
/// derivative the largest at the interval's ends and middle), where
/// `K = 2^(2m+1) (m+1)! / 4` is the Chebyshev error constant of a degree-`m` approximation
/// (`|f^(m+1)| h^(m+1) / (2^(2m+1) (m+1)!)` on an interval of length `h`) made 4 times
/// more pessimistic for the L2 fit with its end points kept and the share of the
/// tolerance left for knot removal.
fn predicted_pieces(c: &BSplineCurve, m: usize, tol: f64) -> (f64, f64) {
    let k = 2f64.powi(2 * i32::try_from(m).unwrap() + 1)
        * (1..=m + 1).map(|i| i as f64).product::<f64>()
        / 4.0;
    let e = 1.0 / (m as f64 + 1.0);
    let deriv = |t: f64| -> f64 {
        let d = c.derivatives(t, m + 1).unwrap();
        d[m + 1].iter().map(|x| x * x).sum::<f64>().sqrt()
    };
    let (mut total, mut min_ulps) = (0.0, f64::INFINITY);
    let ulp = |t: f64| t.abs().max(f64::MIN_POSITIVE) * f64::EPSILON;
    for seg in c.to_beziers().unwrap() {
        let (a, b) = (seg.start, seg.end);
        let h = (b - a) / 32.0;
        let mut pieces = 0.0;
        for i in 0..32 {
            let t0 = a + h * i as f64;
            let worst = deriv(t0)
                .max(deriv(t0 + 0.5 * h))
                .max(deriv((t0 + h).min(b)));
            pieces += h * (worst / (k * tol)).powf(e);
        }
        // A span that needs no split is as the input has it, whatever its length.
        if pieces > 1.0 {
            let ulps = (b - a) / pieces / ulp(a).max(ulp(b));
            min_ulps = f64::min(min_ulps, ulps);
        }
        total += pieces.max(1.0);
    }
    (total, min_ulps)
}

/// `tol`, raised by factors of 1.25 until [`predicted_pieces`] is within [`MAX_PIECES`]
/// spans of at least [`MIN_ULPS`] ulps.
///
/// For the segment strategy on a NURBS curve also the pieces its per-segment reducer needs:
/// it certifies in homogeneous space and converts with `eps_h (1 + max ||P||) / min w`
/// ([`cagd_reduce::reduce_with`]), so it must reach `tol min w / (1 + max ||P||)` on the
/// homogeneous spline. For a curve far from the origin (`max ||P||` up to `1e4` times its
/// size here) that is many more pieces than the geometry needs (a case predicted at 1 500
/// spans took 70 000 pieces and 15 s); correct, if slow, so the tolerance is raised for it
/// too. The rounding level of that conversion is not accounted for: where it is above the
/// tolerance the strategy fails although the curve is far from its own rounding level,
/// which law 1 reports (see the regressions file).
fn affordable_tolerance(c: &BSplineCurve, m: usize, tol: f64, strategy: BSplineStrategy) -> f64 {
    let hom = match (strategy, c.weights()) {
        (BSplineStrategy::Segments(_), Some(w)) => {
            let d = c.dim();
            let pmax = c
                .points()
                .chunks_exact(d)
                .map(|x| x.iter().map(|v| v * v).sum::<f64>().sqrt())
                .fold(0.0, f64::max);
            let wmin = w.iter().copied().fold(f64::INFINITY, f64::min);
            let h = BSplineCurve::new(
                c.degree(),
                c.knots().to_vec(),
                c.homogeneous_points(),
                d + 1,
            );
            Some((h.unwrap(), wmin / (1.0 + pmax)))
        }
        _ => None,
    };
    let mut tol = tol;
    for _ in 0..1000 {
        let (mut pieces, mut ulps) = predicted_pieces(c, m, tol);
        if let Some((h, factor)) = &hom {
            let (p2, u2) = predicted_pieces(h, m, tol * factor);
            (pieces, ulps) = (pieces.max(p2), ulps.min(u2));
        }
        if pieces <= MAX_PIECES && ulps >= MIN_ULPS {
            return tol;
        }
        tol *= 1.25;
    }
    panic!("no affordable tolerance for {c:?}");
}

/// A random reduction problem.
#[derive(Debug, Clone)]
struct Case {
    curve: BSplineCurve,
    opts: BSplineOptions,
}

prop_compose! {
    /// A random curve, target uniform in `1..p`, strategy, continuity `None` or `Some(k)`
    /// for `k` uniform in `0..=kmax`, tolerance `10^-(1..5)` of the size made affordable.
    fn case()(
        shape in shape(2..=MAX_DEG), place in place(),
        raw in points(MAX_N, 3), wraw in proptest::collection::vec(-1.0f64..1.0, MAX_N),
        m in 0..60usize, strategy in 0..4usize, k in (any::<bool>(), 0..60usize),
        tol_exp in 1.0f64..5.0,
    ) -> Case {
        let curve = build(&shape, &place, &raw, &wraw);
        let p = shape.p;
        // 60 = lcm(1..=5): uniform in 1..p.
        let m = 1 + m % (p - 1);
        let strategy = strategy_of(strategy);
        let continuity = k.0.then_some(k.1 % (kmax(strategy, m) + 1));
        let tolerance = affordable_tolerance(&curve, m, place.size * 10f64.powf(-tol_exp), strategy);
        let opts = BSplineOptions {
            continuity,
            strategy,
            ..BSplineOptions::new(m, tolerance)
        };
        Case { curve, opts }
    }
}

// ---------------------------------------------------------------------------------------
// Evaluation and distance.

/// A curve prepared for repeated evaluation: knots and working (homogeneous for NURBS)
/// points.
struct Evaluator {
    p: usize,
    dim: usize,
    knots: Vec<f64>,
    work: Vec<f64>,
    pdim: usize,
    rational: bool,
}

impl Evaluator {
    fn new(c: &BSplineCurve) -> Self {
        let rational = c.is_rational();
        Self {
            p: c.degree(),
            dim: c.dim(),
            knots: c.knots().to_vec(),
            work: if rational {
                c.homogeneous_points()
            } else {
                c.points().to_vec()
            },
            pdim: c.dim() + usize::from(rational),
            rational,
        }
    }

    /// The point at `t` in the domain (de Boor on the span `u_s <= t < u_{s+1}`, the last
    /// non-empty one at the right end), written to `out` (`dim` coordinates).
    fn eval(&self, t: f64, out: &mut [f64]) {
        let (p, u, d) = (self.p, &self.knots, self.pdim);
        let n = self.work.len() / d;
        let mut s = u.partition_point(|x| *x <= t).saturating_sub(1);
        if s >= n {
            s = u.partition_point(|x| *x < u[n]) - 1;
        }
        let s = s.max(p);
        let mut loc = self.work[(s - p) * d..(s + 1) * d].to_vec();
        for r in 1..=p {
            for j in (r..=p).rev() {
                let lo = u[s - p + j];
                let a = (t - lo) / (u[s + 1 + j - r] - lo);
                for c in 0..d {
                    loc[j * d + c] = (1.0 - a) * loc[(j - 1) * d + c] + a * loc[j * d + c];
                }
            }
        }
        let pt = &loc[p * d..];
        for c in 0..self.dim {
            out[c] = if self.rational {
                pt[c] / pt[self.dim]
            } else {
                pt[c]
            };
        }
    }
}

/// The sample parameters on the domain of `a`: every knot of `a` and `b` inside it, 7
/// points inside every interval between consecutive ones, and 1 001 uniform ones.
fn sample_params(a: &BSplineCurve, b: &BSplineCurve) -> Vec<f64> {
    let (lo, hi) = a.domain();
    let mut t: Vec<f64> = a
        .knots()
        .iter()
        .chain(b.knots())
        .copied()
        .filter(|&x| lo <= x && x <= hi)
        .chain((0..=1000).map(|i| lo + (hi - lo) * f64::from(i) / 1000.0))
        .chain([lo, hi])
        .collect();
    t.sort_by(f64::total_cmp);
    t.dedup();
    let mut out = Vec::with_capacity(8 * t.len());
    for w in t.windows(2) {
        out.push(w[0]);
        out.extend((1..8).map(|i| w[0] + (w[1] - w[0]) * f64::from(i) / 8.0));
    }
    out.push(hi);
    out
}

/// The largest sampled distance between `a` and `b` on `a`'s domain ([`sample_params`]).
fn sampled_distance(a: &BSplineCurve, b: &BSplineCurve) -> f64 {
    let (ea, eb) = (Evaluator::new(a), Evaluator::new(b));
    let (mut x, mut y) = (vec![0.0; a.dim()], vec![0.0; b.dim()]);
    let mut worst: f64 = 0.0;
    for t in sample_params(a, b) {
        ea.eval(t, &mut x);
        eb.eval(t, &mut y);
        let d = x
            .iter()
            .zip(&y)
            .map(|(p, q)| (p - q) * (p - q))
            .sum::<f64>();
        worst = worst.max(d.sqrt());
    }
    worst
}

// ---------------------------------------------------------------------------------------
// Continuity.

/// The largest jump of `d^j/dt^j` (`j = 0..=k`, global parameter) across the joint between
/// the Bézier pieces `left` (on an interval of length `hl` ending at the joint) and `right`
/// (length `hr`, starting there), in working coordinates, as a fraction of its rounding
/// scale `m!/(m-j)! 2^j bmax / min(hl, hr)^j` (`bmax` the largest working coordinate of the
/// two pieces): the size of the `j`-th differences of the Bézier points it is computed
/// from. Rounding keeps the ratio near `1e-16`; a missing order of continuity makes the
/// jump about the local fit error over `h^j`.
fn worst_jump(left: (&BezierCurve, f64), right: (&BezierCurve, f64), k: usize) -> f64 {
    let (l, r) = (left.0.to_homogeneous(), right.0.to_homogeneous());
    let m = l.degree();
    let hmin = left.1.min(right.1);
    let bmax = l
        .points()
        .iter()
        .chain(r.points())
        .fold(f64::MIN_POSITIVE, |a, x| a.max(x.abs()));
    let (dl, dr) = (
        l.derivatives(1.0, k).unwrap(),
        r.derivatives(0.0, k).unwrap(),
    );
    let mut worst: f64 = 0.0;
    for j in 0..=k {
        let ji = i32::try_from(j).unwrap();
        let falling: f64 = (0..j).map(|i| (m - i) as f64).product();
        let scale = falling * 2f64.powi(ji) * bmax / hmin.powi(ji);
        let (hl, hr) = (left.1.powi(ji), right.1.powi(ji));
        let jump = dl[j]
            .iter()
            .zip(&dr[j])
            .map(|(x, y)| (x / hl - y / hr).abs())
            .fold(0.0, f64::max);
        worst = worst.max(jump / scale);
    }
    worst
}

/// The continuity `report.continuity` should list for the result `out` of `c`.
fn expected_continuity(c: &Case, out: &BSplineCurve) -> Vec<(f64, usize)> {
    let (p, m, strategy) = (c.curve.degree(), c.opts.target, c.opts.strategy);
    let k = c.opts.continuity.unwrap_or(kmax(strategy, m));
    interior_breaks(&c.curve)
        .into_iter()
        .filter(|&(t, _)| knot_multiplicity(out.knots(), t) > 0)
        .map(|(t, s)| match strategy {
            BSplineStrategy::PieglTiller1995 => (t, p - s),
            _ => (t, k.min(p - s).min(m - 1)),
        })
        .collect()
}

/// Law 5 for the result `r` of case `c`.
fn check_continuity(c: &Case, r: &BSplineReduction) -> Result<(), TestCaseError> {
    let expected = expected_continuity(c, &r.curve);
    prop_assert_eq!(&r.report.continuity, &expected, "report.continuity");
    let pieces = r.curve.to_beziers().unwrap();
    for &(t, k) in &expected {
        let i = pieces
            .iter()
            .position(|x| x.end == t)
            .ok_or_else(|| TestCaseError::fail(format!("{t} is not a break of the result")))?;
        let (l, rr) = (&pieces[i], &pieces[i + 1]);
        let jump = worst_jump(
            (&l.curve, l.end - l.start),
            (&rr.curve, rr.end - rr.start),
            k,
        );
        prop_assert!(
            jump <= JUMP_LIMIT,
            "knot {t}: C{k} expected (input multiplicity {}, result {}), derivative jump \
             {jump:e} of its rounding scale",
            knot_multiplicity(c.curve.knots(), t),
            knot_multiplicity(r.curve.knots(), t)
        );
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------
// Laws 1 to 4.

/// Law 1: the reduction of `c`; `Ok(None)` for a documented failure whose condition holds.
fn reduce(c: &Case) -> Result<Option<BSplineReduction>, TestCaseError> {
    match reduce_bspline(&c.curve, &c.opts) {
        Ok(r) => Ok(Some(r)),
        // Piegl & Tiller never subdivide: they fail unless the input is within the
        // tolerance of a degree-m spline on (a subset of) its own knots.
        Err(Error::ConditionNotMet {
            eq: "Piegl-Tiller 1995",
            ..
        }) if c.opts.strategy == BSplineStrategy::PieglTiller1995 => Ok(None),
        // Segments on NURBS: a C^k joint whose knot removal would give a non-positive
        // control weight cannot be stored (a true, named limit of the strategy; the seed
        // in bspline_laws.proptest-regressions, a point-curve NURBS at C2).
        Err(Error::ConditionNotMet {
            eq: "tolerance",
            why,
        }) if matches!(c.opts.strategy, BSplineStrategy::Segments(_))
            && c.curve.is_rational()
            && why.contains("non-positive") =>
        {
            Ok(None)
        }
        Err(e) => Err(failed(&c.curve, &c.opts, &e)),
    }
}

/// The failure of law 1 for `e`, with the tolerance relative to the curve's rounding level
/// `(p + 3) eps max |x|` (`x` the coordinates and, for NURBS, the homogeneous ones): the
/// random cases keep it above `1e6` (tolerances `>= 1e-5` of the size, offsets `<= 1e4`
/// sizes), law 6 near `1e4..1e6` (`1e-9` of the largest coordinate), so that no documented
/// "below the rounding level" condition can hold.
fn failed(curve: &BSplineCurve, opts: &BSplineOptions, e: &Error) -> TestCaseError {
    let hom = curve
        .homogeneous_points()
        .iter()
        .fold(magnitude(curve), |m, x| m.max(x.abs()));
    let level = (curve.degree() as f64 + 3.0) * f64::EPSILON * hom;
    TestCaseError::fail(format!(
        "reduction failed: {e} (the tolerance is {:.1e} times the rounding level {level:.1e})",
        opts.tolerance / level
    ))
}

/// Laws 2 to 4 for the result `r` of reducing `input` with `opts`.
fn check_bound(
    input: &BSplineCurve,
    opts: &BSplineOptions,
    r: &BSplineReduction,
) -> Result<(), TestCaseError> {
    let tol = opts.tolerance;
    let bound = r.report.error_bound;
    prop_assert!(bound <= tol, "bound {bound:e} > tolerance {tol:e}");
    let out = &r.curve;
    prop_assert_eq!(out.degree(), opts.target);
    prop_assert_eq!(out.domain(), input.domain());
    prop_assert_eq!(out.is_rational(), input.is_rational());
    let (m, k) = (out.degree(), out.knots());
    let (a, b) = input.domain();
    prop_assert!(
        k[..=m].iter().all(|&x| x == a) && k[k.len() - m - 1..].iter().all(|&x| x == b),
        "not clamped on the domain"
    );
    let d = sampled_distance(input, out);
    let slack = 1e-12 * magnitude(input).max(magnitude(out));
    prop_assert!(
        d <= bound + slack,
        "sampled distance {d:e} > bound {bound:e} (+ {slack:e})"
    );
    Ok(())
}

// ---------------------------------------------------------------------------------------
// Law 6.

/// `low` elevated by `d` exactly (up to rounding): every Bézier piece elevated, merged C0,
/// then every interior joint of input multiplicity `s` removed `m - s` times, so it keeps
/// the continuity `C^(m - s)` it had (multiplicity `d + s`). `None` when rounding keeps a
/// joint copy from being removed within `1e-12` of the size (extreme weights): the case is
/// then not an exactly elevated spline and is skipped.
fn elevate(low: &BSplineCurve, d: usize) -> Option<BSplineCurve> {
    let m = low.degree();
    let pieces = low.to_beziers().unwrap();
    let mut breaks: Vec<f64> = pieces.iter().map(|x| x.start).collect();
    breaks.push(pieces[pieces.len() - 1].end);
    let segs: Vec<BezierCurve> = pieces.iter().map(|x| x.curve.elevate(d).unwrap()).collect();
    let tiny = 1e-12 * magnitude(low);
    let mut e = BSplineCurve::from_beziers(&segs, &breaks, 0, tiny).unwrap();
    for (t, s) in interior_breaks(low) {
        if m > s {
            let out = e.remove_knot(t, m - s, tiny).unwrap();
            if out.removed != m - s {
                return None;
            }
            e = out.curve;
        }
    }
    Some(e)
}

// ---------------------------------------------------------------------------------------
// The laws.

proptest! {
    // Shrinking is capped at 5 s: a reduction that fails may take a while before giving
    // up, and a red run should still be quick.
    #![proptest_config(ProptestConfig {
        max_shrink_time: 5_000,
        ..ProptestConfig::with_cases(32)
    })]

    /// Laws 1 to 4 on random input.
    #[test]
    fn random_curves_meet_the_tolerance(c in case()) {
        if let Some(r) = reduce(&c)? {
            check_bound(&c.curve, &c.opts, &r)?;
        }
    }

    /// Law 5 on random input.
    #[test]
    fn random_curves_keep_continuity_at_kept_knots(c in case()) {
        // A failed call is law 1's failure, reported by the test above; rejecting it here
        // keeps this test's shrinking on continuity failures.
        let r = reduce(&c)
            .map_err(|_| TestCaseError::reject("the reduction failed (law 1)"))?;
        if let Some(r) = r {
            check_continuity(&c, &r)?;
        }
    }

    /// Law 6: an exactly elevated spline (degree `m` in 1..=4, elevated by 1..=3) reduces
    /// back by every strategy.
    #[test]
    fn elevated_curves_reduce_back(
        shape in shape(1..=4usize), place in place(), d in 1..=3usize,
        raw in points(MAX_N, 3), wraw in proptest::collection::vec(-1.0f64..1.0, MAX_N),
        strategy in 0..4usize,
    ) {
        let low = build(&shape, &place, &raw, &wraw);
        let m = low.degree();
        let Some(e) = elevate(&low, d) else {
            return Err(TestCaseError::reject("elevation not exact in f64 (extreme weights)"));
        };
        prop_assert_eq!(e.degree(), m + d);
        // At least the size: the shrinker likes curves with all points 0.
        let mag = magnitude(&low).max(magnitude(&e)).max(place.size);
        let exact = sampled_distance(&low, &e);
        prop_assert!(exact <= 1e-11 * mag, "elevation off by {exact:e}");
        let tol = 1e-9 * mag;
        let opts = BSplineOptions {
            strategy: strategy_of(strategy),
            ..BSplineOptions::new(m, tol)
        };
        let r = match reduce_bspline(&e, &opts) {
            // A known limitation of the classical baseline and of the segment strategy,
            // left alone (the global fit, the default, has no such limit): both convert
            // homogeneous errors to model space by the unit-dependent factor
            // `(1 + max ||P||) / min w` (P&T also uncentred), so on a NURBS of a size far
            // from 1 they may refuse even an exactly elevated curve — a refusal, never a
            // false bound (checked by the other laws). Polynomial input must succeed.
            Err(Error::ConditionNotMet { .. })
                if opts.strategy != BSplineStrategy::GlobalFit && e.is_rational() =>
            {
                return Ok(());
            }
            other => other.map_err(|err| failed(&e, &opts, &err))?,
        };
        check_bound(&e, &opts, &r)?;
        let spans = low.to_beziers().unwrap().len();
        prop_assert_eq!(r.spans_in, spans);
        // The same limitation makes those strategies subdivide NURBS they need not; the
        // global fit and polynomial input must come back on the original knots.
        if opts.strategy == BSplineStrategy::GlobalFit || !e.is_rational() {
            prop_assert!(r.spans_out <= spans, "spans {} -> {}", spans, r.spans_out);
            let low_knots = low.knots();
            for (t, _) in interior_breaks(&r.curve) {
                prop_assert!(knot_multiplicity(low_knots, t) > 0, "new knot {t}");
            }
        }
        let back = sampled_distance(&low, &r.curve);
        prop_assert!(back <= tol + 1e-12 * mag, "distance to the original {back:e}");
    }

    /// The evaluator of this file agrees with [`BSplineCurve::eval`] on exotic curves.
    #[test]
    fn evaluator_agrees_with_eval(
        shape in shape(1..=MAX_DEG), place in place(),
        raw in points(MAX_N, 3), wraw in proptest::collection::vec(-1.0f64..1.0, MAX_N),
    ) {
        let c = build(&shape, &place, &raw, &wraw);
        let ev = Evaluator::new(&c);
        let mut x = vec![0.0; c.dim()];
        let mag = magnitude(&c);
        for t in sample_params(&c, &c) {
            ev.eval(t, &mut x);
            let y = c.eval(t).unwrap();
            let d = x.iter().zip(&y).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
            prop_assert!(d <= 1e-13 * mag, "{}: {:?} vs {:?}", t, x, y);
        }
    }
}

/// Laws 1 to 5 on the case law 1 found in the global fit (seed `a9e9951d` of
/// `bspline_laws.proptest-regressions`): a degree-5 NURBS with C0 and C1 joints 1.2e-3
/// apart, a steep homogeneous x·w (slope ~5e4) right of the first, weights 0.023..43, to
/// degree 1. The refinement stalled at the rounding level beside the joints (see
/// `src/bspline/grading.rs`); it now converges, certified and within the tolerance.
#[test]
fn steep_nurbs_joints_do_not_stall_the_fit() {
    let curve = BSplineCurve::new_rational(
        5,
        vec![
            5.551115123125783e-17,
            0.20000000000000007,
            0.4000000000000001,
            0.6000000000000001,
            0.8,
            1.0,
            1.0011505115562216,
            1.0011505115562216,
            1.0011505115562216,
            1.0011505115562216,
            1.0011505115562216,
            1.9460994680565809,
            1.9603953574186455,
            1.9603953574186455,
            1.9603953574186455,
            1.9603953574186455,
            1.9603953574186455,
            1.961545868974867,
            1.961545868974867,
            1.961545868974867,
            1.961545868974867,
            2.0,
            2.2,
            2.4000000000000004,
            2.6000000000000005,
            2.8000000000000007,
            3.000000000000001,
        ],
        vec![
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            -0.42012036715760137,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.6417717414322618,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        vec![
            2.641035882632016,
            14.947106832217363,
            0.5768583628535306,
            0.12400136242063103,
            0.19166131473770837,
            1.7858969489832897,
            0.1767990858876068,
            4.464484827990844,
            0.023389207546963556,
            0.34073799880745387,
            0.4395196783950513,
            0.0378140794783355,
            27.956593204112025,
            0.041353945455844435,
            26.337105323519676,
            0.04548479323702555,
            14.951497076992833,
            10.16294039792586,
            6.827381743381771,
            43.3549065176696,
            4.128497142030473,
        ],
        2,
    )
    .unwrap();
    let opts = BSplineOptions {
        strategy: BSplineStrategy::GlobalFit,
        ..BSplineOptions::new(1, 0.2684619562833166)
    };
    let c = Case { curve, opts };
    let r = reduce(&c).unwrap().expect("the global fit reduces it");
    check_bound(&c.curve, &c.opts, &r).unwrap();
    check_continuity(&c, &r).unwrap();
    assert!(r.report.pieces < 200, "{} spans", r.report.pieces);
}
