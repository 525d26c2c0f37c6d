//! Refinement by error equidistribution (ours, after the classical de Boor-style
//! equidistribution of `h^(m+1)` error models): inside every input span that has a fitted
//! span above the budget, the simple knots are placed anew so that each new span gets an
//! equal share of `int c(t)^(1/(m+1)) dt`, `c = bound / h^(m+1)` the error density the
//! current spans measured, and their number is what brings the predicted bound to the
//! target (at least one more than before). Spans of the other input spans keep their knots.
//!
//! Compared with splitting each offending span into equal parts (the global B-spline fit's
//! rule), redistributing over the whole input span reaches counts that are not products of
//! small integers (a quarter circle within 1e-3 by cubics: 3 spans, where repeated
//! splitting gives 1 -> 2 -> 4).

use cagd_core::{Error, Result};

use crate::SpanBound;

/// Most spans one input span may get in one round, as a multiple of what it had.
const MAX_GROWTH: usize = 16;

/// The new simple knots (sorted) for the fitted spans `bounds` (covering the domain, in
/// order) on the input breaks `breaks`, refining every input span holding a span above
/// `budget` so that its spans are predicted at `target`.
///
/// # Errors
/// [`Error::ConditionNotMet`] when an offending span's rounding floor is above half the
/// budget, or a span is too short to split.
pub(crate) fn refine(
    bounds: &[SpanBound],
    breaks: &[f64],
    budget: f64,
    target: f64,
    m: usize,
) -> Result<Vec<f64>> {
    refine_with(bounds, breaks, (budget, target), m, false)
}

/// [`refine`], or with `local` the offending spans alone split (each into
/// `ceil((bound / target)^(1/(m+1)))` equal parts, at least 2), the other knots kept: the
/// later rounds, where re-placing every knot of a long group would move spans that were
/// already within the budget back above it.
///
/// # Errors
/// As [`refine`].
pub(crate) fn refine_with(
    bounds: &[SpanBound],
    breaks: &[f64],
    (budget, target): (f64, f64),
    m: usize,
    local: bool,
) -> Result<Vec<f64>> {
    let e = 1.0 / (m as f64 + 1.0);
    let mut out = Vec::new();
    let mut i = 0;
    for w in breaks.windows(2) {
        let (lo, hi) = (w[0], w[1]);
        let start = i;
        while i < bounds.len() && bounds[i].b <= hi {
            i += 1;
        }
        let group = &bounds[start..i];
        if group.iter().all(|x| x.bound <= budget) {
            out.extend(group[1..].iter().map(|x| x.a));
            continue;
        }
        if group
            .iter()
            .any(|x| x.bound > budget && x.floor > 0.5 * budget)
        {
            return Err(Error::ConditionNotMet {
                eq: "tolerance",
                why: "the tolerance is below the rounding level of the curve",
            });
        }
        if local {
            for (j, x) in group.iter().enumerate() {
                if j > 0 {
                    out.push(x.a);
                }
                if x.bound > budget {
                    let ratio = (x.bound / target).powf(e);
                    let parts = (2..MAX_GROWTH)
                        .find(|&j| j as f64 >= ratio)
                        .unwrap_or(MAX_GROWTH);
                    let h = (x.b - x.a) / parts as f64;
                    for k in 1..parts {
                        let t = x.a + h * k as f64;
                        if !(t > x.a && t < x.b) {
                            return Err(Error::ConditionNotMet {
                                eq: "tolerance",
                                why: "a span cannot be split further (rounding level)",
                            });
                        }
                        out.push(t);
                    }
                }
            }
            continue;
        }
        // Cumulative int c^(1/(m+1)) dt over the group (piecewise constant density).
        let mass: Vec<f64> = group
            .iter()
            .map(|x| {
                (x.bound.max(f64::MIN_POSITIVE) / (x.b - x.a).powf(1.0 / e)).powf(e) * (x.b - x.a)
            })
            .collect();
        let total: f64 = mass.iter().sum();
        let want = total / target.powf(e);
        let cap = group.len() * MAX_GROWTH;
        let n = (group.len() + 1..=cap)
            .find(|&j| j as f64 >= want)
            .unwrap_or(cap);
        let mut k = 0;
        let mut acc = 0.0;
        for j in 1..n {
            let goal = total * j as f64 / n as f64;
            while k + 1 < group.len() && acc + mass[k] < goal {
                acc += mass[k];
                k += 1;
            }
            let x = &group[k];
            let frac = if mass[k] > 0.0 {
                ((goal - acc) / mass[k]).clamp(0.0, 1.0)
            } else {
                0.5
            };
            let t = x.a + (x.b - x.a) * frac;
            if !(t > lo && t < hi) {
                return Err(Error::ConditionNotMet {
                    eq: "tolerance",
                    why: "a span cannot be split further (rounding level)",
                });
            }
            out.push(t);
        }
    }
    out.sort_by(f64::total_cmp);
    out.dedup();
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sb(a: f64, b: f64, bound: f64) -> SpanBound {
        SpanBound {
            a,
            b,
            bound,
            floor: 0.0,
        }
    }

    /// A uniform error density: equal spans, as many as `h^(m+1)` predicts.
    #[test]
    fn uniform_density_gives_equal_spans() {
        // One span [0, 1] at bound 8e-3, m = 3, target 1e-3: (8)^(1/4) = 1.68 -> 2 spans.
        let k = refine(&[sb(0.0, 1.0, 8e-3)], &[0.0, 1.0], 1e-3, 1e-3, 3).unwrap();
        assert_eq!(k, vec![0.5]);
        // Two spans at 1.7e-3 each: density 1.7e-3 / 0.5^4 -> total (0.0272)^(1/4) = 0.406,
        // over 1e-3^(1/4) = 0.178: 2.29 -> 3 spans.
        let k = refine(
            &[sb(0.0, 0.5, 1.7e-3), sb(0.5, 1.0, 1.7e-3)],
            &[0.0, 1.0],
            1e-3,
            1e-3,
            3,
        )
        .unwrap();
        assert_eq!(k.len(), 2);
        assert!(
            (k[0] - 1.0 / 3.0).abs() < 1e-12 && (k[1] - 2.0 / 3.0).abs() < 1e-12,
            "{k:?}"
        );
    }

    /// Input spans within the budget keep their knots; the others are refined.
    #[test]
    fn only_offending_input_spans_move() {
        let b = [
            sb(0.0, 0.5, 1e-4),
            sb(0.5, 0.7, 1e-4),
            sb(0.7, 1.0, 1e-4),
            sb(1.0, 2.0, 5e-3),
        ];
        let k = refine(&b, &[0.0, 1.0, 2.0], 1e-3, 1e-3, 2).unwrap();
        assert_eq!(k[..2], [0.5, 0.7]);
        assert!(k[2..].iter().all(|t| *t > 1.0 && *t < 2.0) && k.len() >= 3);
        // Local: the offending span alone is split, the others keep their knots.
        let b = [sb(0.0, 0.5, 1e-4), sb(0.5, 0.7, 5e-3), sb(0.7, 1.0, 1e-4)];
        let k = refine_with(&b, &[0.0, 1.0], (1e-3, 1e-3), 3, true).unwrap();
        assert_eq!(k, vec![0.5, 0.6, 0.7]);
    }
}
