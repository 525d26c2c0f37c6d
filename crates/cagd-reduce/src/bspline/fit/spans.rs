//! The per-span data the global fit's rows and its span bounds share ([`SpanData`]: one
//! restriction of the source and one Bézier extraction per span, issue 17) and the de
//! Casteljau pass that makes the restrictions ([`casteljau_part`]).

use super::{Source, span_bezier_of};

/// What the fit's rows ([`super::span_rows`]) and the span bounds share per non-empty span
/// `knots[s] < knots[s + 1]` of a degree-`m` knot vector (`s = m..n`, in order): the
/// source's Bézier points on the span ([`Source::restrict_into`], `(p + 1) * pdim` values)
/// and the span's Bézier extraction (`(m + 1) x (m + 1)`, row `l` the Bézier coefficients
/// `l` of the basis functions `s - m ..= s`, by [`span_bezier_of`] on the unit vectors).
///
/// The restrictions are kept only up to [`MAX_STORED_RESTRICTION`] values in all; past it
/// (huge bundles near the work limit) each user restricts the span again, as before the
/// sharing.
#[derive(Debug, Default)]
pub(crate) struct SpanData {
    subs: Vec<f64>,
    pub(super) exts: Vec<f64>,
    pub(super) stored: bool,
}

/// Most values of restrictions [`SpanData`] keeps (`2^22`, 32 MB): below it sharing
/// costs less memory than the source's own pieces times a few.
const MAX_STORED_RESTRICTION: usize = 1 << 22;

impl SpanData {
    /// The data of every non-empty span of `knots` for the source `src`.
    pub(crate) fn fill(&mut self, src: &Source, m: usize, knots: &[f64]) {
        self.fill_keeping(src, m, knots, MAX_STORED_RESTRICTION);
    }

    /// [`Self::fill`], keeping the restrictions when they are at most `cap` values.
    pub(super) fn fill_keeping(&mut self, src: &Source, m: usize, knots: &[f64], cap: usize) {
        let n = knots.len() - m - 1;
        let m1 = m + 1;
        self.subs.clear();
        self.exts.clear();
        let spans = knots[m..=n].windows(2).filter(|w| w[0] < w[1]).count();
        self.stored = spans.saturating_mul((src.degree + 1) * src.pdim) <= cap;
        let mut sub = Vec::with_capacity((src.degree + 1) * src.pdim);
        let mut tmp = [Vec::new(), Vec::new(), Vec::new()];
        let mut unit = vec![0.0; m1 * m1];
        for i in 0..m1 {
            unit[i * m1 + i] = 1.0;
        }
        let (mut ext, mut work) = (vec![0.0; m1 * m1], vec![0.0; m1 * m1]);
        for s in m..n {
            let (a, b) = (knots[s], knots[s + 1]);
            if a < b {
                if self.stored {
                    src.restrict_into(src.piece_of(a, b), (a, b), &mut sub, &mut tmp);
                    self.subs.extend_from_slice(&sub);
                }
                span_bezier_of((knots, m), s, (&unit, m1), &mut ext, &mut work);
                self.exts.extend_from_slice(&ext);
            }
        }
    }

    /// The restriction of the source to the `i`-th non-empty span `[a, b]`: the stored one,
    /// or computed into `buf` (`tmp` scratch).
    pub(super) fn sub<'a>(
        &'a self,
        src: &Source,
        i: usize,
        (a, b): (f64, f64),
        buf: &'a mut Vec<f64>,
        tmp: &mut [Vec<f64>; 3],
    ) -> &'a [f64] {
        if self.stored {
            let len = (src.degree + 1) * src.pdim;
            return &self.subs[i * len..(i + 1) * len];
        }
        src.restrict_into(src.piece_of(a, b), (a, b), buf, tmp);
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
