//! The per-cell data the global fit's rows and its span bounds share ([`SpanData`]: one
//! restriction of the source and one Bézier extraction per cell, issue 17), the cells
//! themselves ([`Cells`]: the fit's spans cut at the source's breaks) and the de
//! Casteljau pass that makes the restrictions ([`casteljau_part`]).

use super::{Source, span_bezier_of};

/// A cell of a fit over a source: the part `[a, b]` of the fit's non-empty span `s`
/// (`knots[s] < knots[s + 1]`) inside the source's piece `k`. On a cell both the source
/// and the fit are polynomials, so the fit's Gauss rows are exact per cell and a span's
/// bound is the largest of its cells'. When every break of the source is a knot of the
/// fit (the fit on the input's breaks), the cells are the spans; a fit whose spans
/// straddle the source's breaks (ADDED, issue 17's real-CAD-file row: fewer spans on
/// inputs of many short pieces) has more cells than spans.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Cell {
    /// The fit's span: knots `s` and `s + 1`, basis functions `s - m ..= s`.
    pub(crate) s: usize,
    /// The source's piece.
    pub(crate) k: usize,
    pub(crate) a: f64,
    pub(crate) b: f64,
}

/// The cells ([`Cell`]) of the non-empty spans `s` in `first..last` of a degree-`m` knot
/// vector over the source's `breaks`, in order (increasing `a`).
#[derive(Debug, Clone)]
pub(crate) struct Cells<'a> {
    knots: &'a [f64],
    breaks: &'a [f64],
    s: usize,
    last: usize,
    k: usize,
    /// Where the next cell of span `s` starts (`NaN`: at the span's start).
    at: f64,
}

impl<'a> Cells<'a> {
    /// Every cell of the degree-`m` knot vector `knots` (spans `m..n`, clamped on the
    /// domain of `breaks`).
    pub(crate) fn new(knots: &'a [f64], m: usize, breaks: &'a [f64]) -> Self {
        Self {
            knots,
            breaks,
            s: m,
            last: knots.len() - m - 1,
            k: 0,
            at: f64::NAN,
        }
    }

    /// The cells of the one span `s` (`knots[s] < knots[s + 1]`).
    pub(crate) fn of_span(knots: &'a [f64], s: usize, breaks: &'a [f64]) -> Self {
        let a = knots[s];
        let k = breaks[1..]
            .partition_point(|x| *x <= a)
            .min(breaks.len() - 2);
        Self {
            knots,
            breaks,
            s,
            last: s + 1,
            k,
            at: f64::NAN,
        }
    }
}

impl Iterator for Cells<'_> {
    type Item = Cell;

    fn next(&mut self) -> Option<Cell> {
        while self.s < self.last {
            let (ka, kb) = (self.knots[self.s], self.knots[self.s + 1]);
            if ka < kb {
                let a = if self.at.is_nan() { ka } else { self.at };
                // The piece containing `a` (the last piece ends at the domain's end).
                while self.k + 2 < self.breaks.len() && self.breaks[self.k + 1] <= a {
                    self.k += 1;
                }
                let (s, k, end) = (self.s, self.k, self.breaks[self.k + 1]);
                if end < kb && k + 2 < self.breaks.len() {
                    self.at = end;
                    return Some(Cell { s, k, a, b: end });
                }
                self.at = f64::NAN;
                self.s += 1;
                return Some(Cell { s, k, a, b: kb });
            }
            self.s += 1;
        }
        None
    }
}

/// What the fit's rows ([`super::span_rows`]) and the span bounds share per cell
/// ([`Cells`], in order): the cell itself, the source's Bézier points on the cell
/// ([`Source::restrict_into`], `(p + 1) * pdim` values) and the fit span's Bézier
/// extraction on the cell (`(m + 1) x (m + 1)`, row `l` the Bézier coefficients `l` of
/// the basis functions `s - m ..= s` on `[a, b]`, by [`span_bezier_of`] on the unit
/// vectors).
///
/// The restrictions are kept only up to [`MAX_STORED_RESTRICTION`] values in all; past it
/// (huge bundles near the work limit) each user restricts the span again, as before the
/// sharing.
#[derive(Debug, Default)]
pub(crate) struct SpanData {
    pub(crate) cells: Vec<Cell>,
    subs: Vec<f64>,
    pub(super) exts: Vec<f64>,
    pub(super) stored: bool,
}

/// Most values of restrictions [`SpanData`] keeps (`2^22`, 32 MB): below it sharing
/// costs less memory than the source's own pieces times a few.
const MAX_STORED_RESTRICTION: usize = 1 << 22;

impl SpanData {
    /// The data of every cell of `knots` for the source `src`.
    pub(crate) fn fill(&mut self, src: &Source, m: usize, knots: &[f64]) {
        self.fill_keeping(src, m, knots, MAX_STORED_RESTRICTION);
    }

    /// [`Self::fill`], keeping the restrictions when they are at most `cap` values.
    pub(super) fn fill_keeping(&mut self, src: &Source, m: usize, knots: &[f64], cap: usize) {
        let n = knots.len() - m - 1;
        let m1 = m + 1;
        self.subs.clear();
        self.exts.clear();
        self.cells.clear();
        self.cells.extend(Cells::new(knots, m, &src.breaks));
        self.stored = self.cells.len().saturating_mul((src.degree + 1) * src.pdim) <= cap;
        let mut sub = Vec::with_capacity((src.degree + 1) * src.pdim);
        let mut tmp = [Vec::new(), Vec::new(), Vec::new()];
        let mut unit = vec![0.0; m1 * m1];
        for i in 0..m1 {
            unit[i * m1 + i] = 1.0;
        }
        let (mut ext, mut work) = (vec![0.0; m1 * m1], vec![0.0; 2 * m1 * m1]);
        debug_assert!(self.cells.last().is_none_or(|c| c.s < n));
        for c in &self.cells {
            if self.stored {
                src.restrict_into(c.k, (c.a, c.b), &mut sub, &mut tmp);
                self.subs.extend_from_slice(&sub);
            }
            span_bezier_of(
                (knots, m),
                c.s,
                (c.a, c.b),
                (&unit, m1),
                &mut ext,
                &mut work,
            );
            self.exts.extend_from_slice(&ext);
        }
    }

    /// The restriction of the source to the `i`-th cell: the stored one, or computed into
    /// `buf` (`tmp` scratch).
    pub(super) fn sub<'a>(
        &'a self,
        src: &Source,
        i: usize,
        buf: &'a mut Vec<f64>,
        tmp: &mut [Vec<f64>; 3],
    ) -> &'a [f64] {
        if self.stored {
            let len = (src.degree + 1) * src.pdim;
            return &self.subs[i * len..(i + 1) * len];
        }
        let c = self.cells[i];
        src.restrict_into(c.k, (c.a, c.b), buf, tmp);
        buf
    }
}

/// Which part of a Bézier curve [`casteljau_part`] computes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Part {
    /// On `[0, t]`: point `i` is `b_0^i`, the first point of level `i`.
    Left,
    /// On `[t, 1]`: point `i` is `b_i^(n - i)`, the last point of level `n - i`.
    Right,
}

/// The Bézier points of the part `which` of the curve `from` (`dim` coordinates per
/// point) split at `t` in `out` (as long as `from`), by de Casteljau's triangle: level `r`
/// point `i` is `(1 - t) b_i^(r-1) + t b_(i+1)^(r-1)`, each level one pass over the whole
/// level from one buffer of `bufs` into the other (no overlapping reads and writes, so the
/// pass vectorises), the part's point of each level copied out as it is made.
pub(super) fn casteljau_part(
    from: &[f64],
    dim: usize,
    t: f64,
    which: Part,
    out: &mut [f64],
    (a, b): (&mut Vec<f64>, &mut Vec<f64>),
) {
    let u = 1.0 - t;
    let len = from.len();
    a.clear();
    a.extend_from_slice(from);
    b.clear();
    b.resize(len, 0.0);
    match which {
        Part::Left => out[..dim].copy_from_slice(&from[..dim]),
        Part::Right => out[len - dim..].copy_from_slice(&from[len - dim..]),
    }
    let (mut old, mut new) = (a, b);
    for r in (dim..len).step_by(dim) {
        let n = len - r;
        for ((o, x), y) in new[..n].iter_mut().zip(&old[..n]).zip(&old[dim..n + dim]) {
            *o = u * x + t * y;
        }
        match which {
            Part::Left => out[r..r + dim].copy_from_slice(&new[..dim]),
            Part::Right => out[n - dim..n].copy_from_slice(&new[n - dim..n]),
        }
        std::mem::swap(&mut old, &mut new);
    }
}
