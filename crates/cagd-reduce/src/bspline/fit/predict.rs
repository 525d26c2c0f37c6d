//! A predicted first knot vector for the global fit (goes beyond the seed): simple knots
//! inside the source's pieces that equidistribute the local error a degree-`m` spline
//! would make, so that the first fit lands near its final spans and the refinement of
//! [`crate::bspline`]'s global strategy has little left to do.
//!
//! The model: where the source's derivative `C^(m+1)` is nearly constant over a mesh of
//! spacing `h`, the L2-best degree-`m` spline with `C^(m-1)` joins leaves the error
//! `h^(m+1) C^(m+1) B~_(m+1)(t / h) / (m+1)!`, `B~` the periodic Bernoulli function: it
//! differs from `t^(m+1)` by a spline of that space, and `m` integrations by parts show it
//! orthogonal to every such spline (the last one meets a piecewise constant `s^(m)`
//! against the zero-mean `B~_(2m+1)`). Its largest value is `K_m h^(m+1) ||C^(m+1)||` with
//! `K_m = max |B_(m+1)| / (m+1)! <= 2 zeta(m+1) / (2 pi)^(m+1)` (equal for odd `m`:
//! `1/12` for lines, `1/720` for cubics). A span of length `h` then meets the budget
//! `e` when `h <= (e / (K_m ||C^(m+1)||))^(1/(m+1))`, so the number of spans a piece needs
//! is the integral of the density `g = (K_m ||C^(m+1)|| / e)^(1/(m+1))`, and the knots
//! that equidistribute `g` make every span's predicted error alike.
//!
//! The prediction only places knots: every span of the fit is still certified a
//! posteriori and refined where its bound is above the budget.

use std::cell::RefCell;
use std::rc::Rc;

use cagd_core::binomial_f64;

use super::{Source, bernstein_with};
use crate::bezier::gemm::LinearMap;

/// Share of the budget the predicted spans aim at: the prediction's error is the model's
/// largest value, which a span whose derivative varies exceeds somewhat; aiming a little
/// lower saves the second round on most spans.
pub(crate) const PREDICT_TARGET: f64 = 0.4;

/// Spans the placement across the pieces ([`Density::across`]) makes per span the model
/// asks for. Rounding up per piece ([`Density::per_piece`]) leaves the model some slack
/// that one rounding per segment does not: without a margin half of the `cad_curves`
/// B-splines at 1e-3 needed a second round (a refit and rebound of every span); measured
/// there (50 B-splines / 50 NURBS at 1e-3, spans out and cells fitted over all rounds):
/// 1.0: 15.34 / 24.62 spans, 1 899 / 2 544 cells; 1.07: 15.30 / 24.80, 1 689 / 2 249;
/// 1.1: 15.00 / 24.98, 1 357 / 2 205 (OCCT: 17.18 / 24.88 spans); the per-piece route:
/// 17.18 / 27.70 spans, 1 132 / 2 096 cells.
const ACROSS_MARGIN: f64 = 1.07;

/// Samples of the density per degree of the derivative (plus a few), per piece.
const SAMPLES_PER_DEGREE: usize = 3;

/// `K_m = 2 zeta(m + 1) / (2 pi)^(m + 1)`: the error constant of the model (see the module
/// docs), an upper bound of `max |B_(m+1)| / (m+1)!` on `[0, 1]`, equal for odd `m`.
pub(crate) fn error_constant(m: usize) -> f64 {
    let s = m as f64 + 1.0;
    // zeta(s), s >= 2: 64 terms and the integral tail from 64.5 (error below 1e-5).
    let zeta: f64 =
        (1..=64).map(|k| (k as f64).powf(-s)).sum::<f64>() + 64.5f64.powf(1.0 - s) / (s - 1.0);
    2.0 * zeta / (2.0 * std::f64::consts::PI).powf(s)
}

/// The knots to add strictly inside the pieces of the polynomial source `src` so that a
/// degree-`m` fit on them has, by the model of the module docs, every span's error near
/// [`PREDICT_TARGET`] `* budget`: per piece, `J = ceil(integral of g)` spans (none added
/// when `J = 1`) equidistributing the density `g`, sampled at the midpoints of
/// `3 (p - m) + 8` equal parts of the piece. For a rational source (a NURBS in
/// homogeneous coordinates `(A, W)`, blocks of `dim + 1`) the density is that of the
/// model-space error: the homogeneous fit's error is the model's in every coordinate,
/// `e_A = K h^(m+1) A^(m+1) B~`, `e_W = K h^(m+1) W^(m+1) B~` (one Bernoulli factor), and
/// `C - S = (e_A - C e_W) / W` to first order, so `||C^(m+1)||` is replaced by
/// `||A^(m+1) - C W^(m+1)|| / W` (ADDED, issue 17's real-CAD-file row: the NURBS fit
/// started from the input's knots and took several rounds and more spans than OCCT).
/// Empty when the model cannot be evaluated (non-finite values, a weight that is not
/// positive), or when more than `limit` knots would be added (the refinement then starts
/// from the input's knots, as without a prediction).
#[cfg(test)]
pub(crate) fn predicted_knots(src: &Source, m: usize, budget: f64, limit: usize) -> Vec<f64> {
    Density::new(src, m, budget).map_or_else(Vec::new, |x| x.per_piece(src, limit))
}

/// Tables [`midpoint_table`] keeps per thread, `(degree, samples)` and the map.
type MidpointTables = Vec<(usize, usize, Rc<LinearMap>)>;

/// Most tables [`midpoint_table`] keeps (one per derivative degree, and per source degree
/// for NURBS: a few dozen for degrees up to 64).
const CACHED_MIDPOINT_TABLES: usize = 64;

thread_local! {
    static MIDPOINT_TABLES: RefCell<MidpointTables> = const { RefCell::new(Vec::new()) };
}

/// The Bernstein values of degree `q` at the midpoints `(i + 1/2) / samples` of `samples`
/// equal parts of `[0, 1]` (row `i`, `q + 1` values, as [`bernstein_with`] forms them) as a
/// map from Bézier points to their values there, kept per thread (ADDED, issue 17's
/// real-CAD-file row: forming the values per sample and piece was most of
/// [`Density::new`], 10 % of reducing a degree 4–15 B-spline to cubics within 1e-3).
fn midpoint_table(q: usize, samples: usize) -> Rc<LinearMap> {
    MIDPOINT_TABLES.with(|c| {
        let mut c = c.borrow_mut();
        if let Some(e) = c.iter().find(|e| e.0 == q && e.1 == samples) {
            return Rc::clone(&e.2);
        }
        let binom: Vec<f64> = (0..=q).map(|i| binomial_f64(q, i)).collect();
        let mut values = vec![0.0; samples * (q + 1)];
        for (i, row) in values.chunks_exact_mut(q + 1).enumerate() {
            bernstein_with(&binom, (i as f64 + 0.5) / samples as f64, row);
        }
        let map = Rc::new(LinearMap::new(samples, q + 1, values));
        if c.len() == CACHED_MIDPOINT_TABLES {
            c.remove(0);
        }
        c.push((q, samples, Rc::clone(&map)));
        map
    })
}

/// The model's density `g` of [`predicted_knots`], sampled per piece of a source: what
/// both knot placements ([`Density::per_piece`], [`Density::across`]) start from.
#[derive(Debug, Clone)]
pub(crate) struct Density {
    /// Samples per piece.
    samples: usize,
    /// `samples` values of `g` per piece (without the common factor `scale`).
    values: Vec<f64>,
    /// Per piece, the spans the model asks for (`scale` times the mean of its values).
    spans: Vec<f64>,
    /// `PREDICT_TARGET^(1 / (m + 1))`: a piece or segment of at most `1 / this` spans is
    /// within the whole budget by the model.
    within: f64,
}

impl Density {
    /// The density of `src` for a degree-`m` fit within `budget` (the module docs and
    /// [`predicted_knots`]); `None` when the model cannot be evaluated (non-finite values,
    /// a weight that is not positive, `m >= p`, a budget that is not positive).
    pub(crate) fn new(src: &Source, m: usize, budget: f64) -> Option<Self> {
        let (p, d, blk) = (src.degree, src.pdim, src.block);
        if m >= p || budget.is_nan() || budget <= 0.0 {
            return None;
        }
        // The derivative's Bézier points are `fac / h^(m+1)` times the (m+1)-th differences
        // of the piece's points; with `t = pa + h u`, `integral of g dt` over the piece is
        // `scale * integral_0^1 ||Delta(u)||^(1/(m+1)) du`: `h` cancels.
        let order = m + 1;
        let q = p - order;
        let fac: f64 = (0..order).map(|i| (p - i) as f64).product();
        let inv = 1.0 / order as f64;
        let scale = (error_constant(m) * fac / (PREDICT_TARGET * budget)).powf(inv);
        let diff: Vec<f64> = (0..=order)
            .map(|j| {
                let sign = if (order - j) % 2 == 0 { 1.0 } else { -1.0 };
                sign * binomial_f64(order, j)
            })
            .collect();
        let samples = SAMPLES_PER_DEGREE * (q + 1) + 5;
        let mut delta = vec![0.0; (q + 1) * d];
        // The derivative's values at the samples, and for a rational source the piece's
        // own (`C = A / W` at the sample, degree `p`), each by one table of Bernstein
        // values applied as a small matrix product.
        let rational = src.rational;
        let table_q = midpoint_table(q, samples);
        let table_p = rational.then(|| midpoint_table(p, samples));
        let (mut dvals, mut pvals) = (vec![0.0; samples * d], vec![0.0; samples * d]);
        let pieces = src.breaks.len() - 1;
        let mut values = vec![0.0; samples * pieces];
        let mut spans_of = Vec::with_capacity(pieces);
        for (k, density) in values.chunks_exact_mut(samples).enumerate() {
            let piece = src.piece(k);
            // The (m+1)-th differences and their rounding level (coefficients of absolute
            // sum 2^(m+1) over points of size `size`; the sum below is convex).
            let size = piece.iter().fold(0.0f64, |a, x| a.max(x.abs()));
            let noise = 2f64.powf(order as f64)
                * (p as f64 + 4.0)
                * f64::EPSILON
                * size
                * (blk as f64).sqrt();
            for (i, di) in delta.chunks_exact_mut(d).enumerate() {
                di.fill(0.0);
                for (j, c) in diff.iter().enumerate() {
                    for (v, x) in di.iter_mut().zip(&piece[(i + j) * d..(i + j + 1) * d]) {
                        *v += c * x;
                    }
                }
            }
            table_q.apply_loop(&delta, d, &mut dvals);
            if let Some(t) = &table_p {
                t.apply_loop(piece, d, &mut pvals);
            }
            let mut total = 0.0;
            let values = dvals.chunks_exact(d).zip(pvals.chunks_exact(d));
            for (g, (value, point)) in density.iter_mut().zip(values) {
                let x = if rational {
                    let mut worst: f64 = 0.0;
                    for (dv, pv) in value.chunks_exact(blk).zip(point.chunks_exact(blk)) {
                        let (w, dw) = (pv[blk - 1], dv[blk - 1]);
                        if w.is_nan() || w <= 0.0 {
                            return None;
                        }
                        let (mut sq, mut cx) = (0.0, 0.0);
                        for (da, a) in dv[..blk - 1].iter().zip(&pv[..blk - 1]) {
                            let c = a / w;
                            let e = da - c * dw;
                            sq += e * e;
                            cx += c * c;
                        }
                        // The rounding of `A^(m+1) - C W^(m+1)`: that of each part.
                        worst = worst.max((sq.sqrt() - noise * (1.0 + cx.sqrt())).max(0.0) / w);
                    }
                    worst
                } else {
                    let norm = value
                        .chunks_exact(blk)
                        .map(|c| c.iter().map(|x| x * x).sum::<f64>().sqrt())
                        .fold(0.0, f64::max);
                    (norm - noise).max(0.0)
                };
                // The root by square roots where it is one (lines, cubics): `powf` is a
                // `libm` call several times their cost.
                *g = match order {
                    2 => x.sqrt(),
                    4 => x.sqrt().sqrt(),
                    _ => x.powf(inv),
                };
                total += *g;
            }
            let spans = scale * total / samples as f64;
            if !spans.is_finite() {
                return None;
            }
            spans_of.push(spans);
        }
        Some(Self {
            samples,
            values,
            spans: spans_of,
            within: PREDICT_TARGET.powf(inv),
        })
    }

    /// The spans the model asks for in all.
    pub(crate) fn total(&self) -> f64 {
        self.spans.iter().sum()
    }

    /// The knots of [`predicted_knots`]: per piece, `ceil` of its spans equidistributing
    /// the density (none in a piece the model has within the budget); empty when more than
    /// `limit` knots would be added.
    pub(crate) fn per_piece(&self, src: &Source, limit: usize) -> Vec<f64> {
        let samples = self.samples;
        let mut out = Vec::new();
        for (k, density) in self.values.chunks_exact(samples).enumerate() {
            let spans = self.spans[k];
            if spans > limit as f64 {
                return Vec::new();
            }
            if spans * self.within <= 1.0 {
                // The model has the piece within the whole budget as it is: leave it to the
                // refinement (input that is nearly of degree m needs no new knots, and one
                // added here might not be removed again).
                continue;
            }
            #[allow(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "0 <= spans <= limit"
            )]
            let parts = (spans.ceil() as usize).max(1);
            if out.len() + parts - 1 > limit {
                return Vec::new();
            }
            let total: f64 = density.iter().sum();
            let (pa, pb) = (src.breaks[k], src.breaks[k + 1]);
            // Knot j where the running integral (piecewise linear between the sample
            // intervals' ends) reaches j / parts of the total.
            let (mut acc, mut i) = (0.0, 0);
            for j in 1..parts {
                let goal = total * j as f64 / parts as f64;
                while i < samples && acc + density[i] < goal {
                    acc += density[i];
                    i += 1;
                }
                let frac = if i < samples && density[i] > 0.0 {
                    ((goal - acc) / density[i]).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let u = (i as f64 + frac) / samples as f64;
                let t = pa + (pb - pa) * u;
                if t > pa && t < pb && out.last().is_none_or(|x| *x < t) {
                    out.push(t);
                }
            }
        }
        out
    }

    /// The knots of a fit whose spans may straddle the source's breaks (ADDED, issue
    /// 17's real-CAD-file row): the domain cut at the breaks `kept` (indices into
    /// `src.breaks`, increasing, interior: the breaks that stay knots) into segments, and
    /// per segment `ceil` of the spans the model asks for over the whole segment (one span,
    /// no knot, where the model has it within the budget), equidistributing the density
    /// across the pieces — where [`Self::per_piece`] rounds up per piece and keeps every
    /// break. `None` when more than `limit` knots would be added.
    pub(crate) fn across(&self, src: &Source, kept: &[usize], limit: usize) -> Option<Vec<f64>> {
        let (samples, pieces) = (self.samples, self.spans.len());
        if self.total() > limit as f64 {
            return None;
        }
        let mut out = Vec::new();
        let mut first = 0;
        for last in kept.iter().copied().chain([pieces]) {
            // Pieces `first..last`.
            let total: f64 = ACROSS_MARGIN * self.spans[first..last].iter().sum::<f64>();
            if total * self.within > 1.0 {
                #[allow(
                    clippy::cast_possible_truncation,
                    clippy::cast_sign_loss,
                    reason = "0 <= total <= limit"
                )]
                let parts = (total.ceil() as usize).max(1);
                if out.len() + parts - 1 > limit {
                    return None;
                }
                let (lo, hi) = (src.breaks[first], src.breaks[last]);
                // The running integral in spans: sample `i` of piece `k` holds
                // `spans[k] * values[i] / sum(values of k)`.
                let (mut acc, mut j) = (0.0, 1);
                'pieces: for k in first..last {
                    let density = &self.values[k * samples..(k + 1) * samples];
                    let sum: f64 = density.iter().sum();
                    if sum.is_nan() || sum <= 0.0 {
                        continue;
                    }
                    let unit = ACROSS_MARGIN * self.spans[k] / sum;
                    let (pa, pb) = (src.breaks[k], src.breaks[k + 1]);
                    for (i, g) in density.iter().enumerate() {
                        let c = g * unit;
                        while j < parts {
                            let goal = total * j as f64 / parts as f64;
                            if acc + c < goal {
                                break;
                            }
                            let frac = if c > 0.0 {
                                ((goal - acc) / c).clamp(0.0, 1.0)
                            } else {
                                0.0
                            };
                            let t = pa + (pb - pa) * ((i as f64 + frac) / samples as f64);
                            if t > lo && t < hi && out.last().is_none_or(|x| *x < t) {
                                out.push(t);
                            }
                            j += 1;
                        }
                        if j >= parts {
                            break 'pieces;
                        }
                        acc += c;
                    }
                }
            }
            first = last;
        }
        Some(out)
    }

    /// The spans of the knot placements: `(per_piece, across)`, as the model rounds them
    /// (a piece or segment within the budget counts one).
    pub(crate) fn span_counts(&self, kept: &[usize]) -> (usize, usize) {
        let parts = |x: f64| -> usize {
            if x * self.within <= 1.0 {
                1
            } else {
                #[allow(
                    clippy::cast_possible_truncation,
                    clippy::cast_sign_loss,
                    reason = "a finite, positive count (saturating)"
                )]
                let n = x.ceil() as usize;
                n.max(1)
            }
        };
        let per_piece = self
            .spans
            .iter()
            .fold(0usize, |n, x| n.saturating_add(parts(*x)));
        let (mut across, mut first) = (0usize, 0);
        for last in kept.iter().copied().chain([self.spans.len()]) {
            let segment = ACROSS_MARGIN * self.spans[first..last].iter().sum::<f64>();
            across = across.saturating_add(parts(segment));
            first = last;
        }
        (per_piece, across)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bspline::fit::fit;
    use cagd_core::BSplineCurve;
    use cagd_testkit::bench::random_input;

    /// The constant against the Bernoulli polynomials' maxima on `[0, 1]`, sampled:
    /// `B_2 = x^2 - x + 1/6` (largest `1/6` at the ends), `B_4 = x^4 - 2x^3 + x^2 - 1/30`
    /// (`1/30`), and for even `m` an upper bound (`B_3 = x^3 - 3x^2/2 + x/2`).
    #[test]
    fn error_constant_is_the_bernoulli_maximum() {
        let sampled = |f: &dyn Fn(f64) -> f64| {
            (0..=10_000)
                .map(|i| f(f64::from(i) / 1e4).abs())
                .fold(0.0, f64::max)
        };
        let b2 = sampled(&|x| x * x - x + 1.0 / 6.0) / 2.0;
        let b4 = sampled(&|x| x.powi(4) - 2.0 * x.powi(3) + x * x - 1.0 / 30.0) / 24.0;
        let b3 = sampled(&|x| x.powi(3) - 1.5 * x * x + 0.5 * x) / 6.0;
        assert!(
            (error_constant(1) - b2).abs() < 1e-6 * b2,
            "{}",
            error_constant(1)
        );
        assert!(
            (error_constant(3) - b4).abs() < 1e-6 * b4,
            "{}",
            error_constant(3)
        );
        assert!(error_constant(2) >= b3 && error_constant(2) < 1.25 * b3);
    }

    /// `t^4` (a 1-D quartic Bézier curve: points `0, 0, 0, 0, 1`) fitted by cubics on 24
    /// uniform spans: away from the ends (where the fixed end points disturb it) the
    /// largest sampled error is the model's `K_3 h^4 24` (the fourth derivative is 24),
    /// checking the model by the fit itself.
    #[test]
    fn the_model_is_the_fits_error_on_a_uniform_mesh() {
        let c = BSplineCurve::new(
            4,
            vec![0.0; 5].into_iter().chain([1.0; 5]).collect(),
            vec![0.0, 0.0, 0.0, 0.0, 1.0],
            1,
        )
        .unwrap();
        let src = Source::new(&c, 1, false).unwrap();
        let spans = 24;
        let mut knots = vec![0.0; 4];
        knots.extend((1..spans).map(|i| f64::from(i) / f64::from(spans)));
        knots.extend([1.0; 4]);
        let s = BSplineCurve::new(3, knots.clone(), fit(&src, 3, &knots).unwrap(), 1).unwrap();
        let mut worst: f64 = 0.0;
        for i in 0..=4000 {
            let t = 0.375 + 0.25 * f64::from(i) / 4000.0;
            worst = worst.max((t.powi(4) - s.eval(t).unwrap()[0]).abs());
        }
        let h = 1.0 / f64::from(spans);
        let model = error_constant(3) * h.powi(4) * 24.0;
        assert!((worst / model - 1.0).abs() < 1e-3, "{worst} vs {model}");
    }

    /// A random degree-`n` Bézier curve in 3-D as a one-span spline (the a2 row's input).
    fn bezier(n: usize, seed: u64) -> BSplineCurve {
        let mut knots = vec![0.0; n + 1];
        knots.extend(std::iter::repeat_n(1.0, n + 1));
        BSplineCurve::new(n, knots, random_input(3 * (n + 1), seed), 3).unwrap()
    }

    /// The knots are strictly inside the pieces and increasing, equidistribute the
    /// density (the sampled integral between neighbours is alike), and a tighter budget
    /// asks for `(ratio)^(1/(m+1))` times as many spans.
    #[test]
    fn knots_equidistribute_the_density() {
        let c = bezier(12, 7);
        let src = Source::new(&c, 3, false).unwrap();
        let k1 = predicted_knots(&src, 3, 1e-4, usize::MAX);
        let k2 = predicted_knots(&src, 3, 1e-4 / 16.0, usize::MAX);
        assert!(k1.len() >= 8, "{}", k1.len());
        assert!(k1.windows(2).all(|w| w[0] < w[1]) && k1[0] > 0.0 && k1[k1.len() - 1] < 1.0);
        let ratio = (k2.len() + 1) as f64 / (k1.len() + 1) as f64;
        assert!((ratio - 2.0).abs() < 0.15, "{ratio}");
        // The density by direct evaluation of the fourth derivative (finite differences of
        // the curve, an independent route), integrated between the knots.
        let g = |t: f64| {
            let h = 1e-3;
            let v: Vec<Vec<f64>> = (-2..=2)
                .map(|i| c.eval(t + f64::from(i) * h).unwrap())
                .collect();
            let d4: f64 = (0..3)
                .map(|k| {
                    (v[0][k] - 4.0 * v[1][k] + 6.0 * v[2][k] - 4.0 * v[3][k] + v[4][k]) / h.powi(4)
                })
                .map(|x| x * x)
                .sum::<f64>()
                .sqrt();
            d4.powf(0.25)
        };
        let mut breaks = vec![0.0];
        breaks.extend(&k1);
        breaks.push(1.0);
        let parts: Vec<f64> = breaks
            .windows(2)
            .map(|w| {
                let (a, b) = (w[0].max(0.003), w[1].min(0.997));
                (0..200)
                    .map(|i| g(a + (b - a) * (f64::from(i) + 0.5) / 200.0))
                    .sum::<f64>()
                    * (b - a)
                    / 200.0
            })
            .collect();
        let mean = parts[1..parts.len() - 1].iter().sum::<f64>() / (parts.len() - 2) as f64;
        for x in &parts[1..parts.len() - 1] {
            assert!((x / mean - 1.0).abs() < 0.1, "{parts:?}");
        }
    }

    /// No knots for input of degree `m` written in a higher degree (its `m+1`-th
    /// differences are rounding), for rational input, for a piece the model has within
    /// the budget, and past the limit.
    #[test]
    fn no_knots_where_none_are_wanted() {
        let cubic = BSplineCurve::new(
            3,
            vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
            random_input(12, 3),
            3,
        )
        .unwrap();
        let pieces = cubic.to_beziers().unwrap();
        let e = pieces[0].curve.elevate(9).unwrap();
        let mut knots = vec![0.0; 13];
        knots.extend([1.0; 13]);
        let elevated = BSplineCurve::new(12, knots, e.points().to_vec(), 3).unwrap();
        let src = Source::new(&elevated, 3, false).unwrap();
        assert!(predicted_knots(&src, 3, 1e-14, usize::MAX).is_empty());
        let c = bezier(12, 7);
        let src = Source::new(&c, 3, false).unwrap();
        assert!(predicted_knots(&src, 3, 1e3, usize::MAX).is_empty());
        assert!(predicted_knots(&src, 3, 1e-4, 3).is_empty());
        let rational = Source {
            rational: true,
            ..src
        };
        assert!(predicted_knots(&rational, 3, 1e-4, usize::MAX).is_empty());
    }
}
