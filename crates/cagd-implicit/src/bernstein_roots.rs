//! Robust root isolation of a polynomial in Bernstein form on `[0, 1]` by recursive
//! subdivision (de Casteljau at `1/2`), with a coefficient-wise error bound:
//!
//! - a piece whose coefficients all exceed their error bound with one sign has no root
//!   (convex hull property);
//! - a piece whose coefficients all have a certain sign with exactly one sign variation
//!   has exactly one root (Descartes' rule of signs for the Bernstein basis), refined by
//!   bisection on the de Casteljau value;
//! - anything else is split, down to width `2^-MAX_DEPTH`; the undecided leaves that touch
//!   are merged into one cluster (a multiple or numerically multiple root, e.g. a tangency),
//!   reported at its centre.
//!
//! The power basis is never used. Cost: `O(d^2)` per piece, a handful of pieces per root.

use cagd_core::Error;

/// Depth limit of the subdivision (leaf width `2^-32 ≈ 2.3e-10`).
const MAX_DEPTH: u32 = 32;
/// Undecided leaves allowed before the polynomial is declared zero within rounding on a
/// stretch (its roots are not a finite set at this precision).
const LEAF_BUDGET: usize = 20_000;

/// A root found on `[0, 1]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct BernsteinRoot {
    /// The root (for a cluster, the centre of the cluster).
    pub(crate) t: f64,
    /// Whether it was found as a cluster of undecided leaves (multiple root, or a simple
    /// root on a subdivision point) rather than isolated as a simple root.
    pub(crate) cluster: bool,
}

struct Solver {
    roots: Vec<BernsteinRoot>,
    leaves: Vec<(f64, f64)>,
    overflow: bool,
}

/// The value of the Bernstein polynomial `c` at `u` (de Casteljau).
pub(crate) fn de_casteljau(c: &[f64], u: f64) -> f64 {
    let mut b = c.to_vec();
    let n = b.len();
    for level in 1..n {
        for i in 0..n - level {
            b[i] = (1.0 - u) * b[i] + u * b[i + 1];
        }
    }
    b.first().copied().unwrap_or(0.0)
}

/// Splits `c` at `1/2` into its two halves.
fn split(c: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let n = c.len();
    let mut work = c.to_vec();
    let mut left = vec![0.0; n];
    let mut right = vec![0.0; n];
    left[0] = work[0];
    right[n - 1] = work[n - 1];
    for level in 1..n {
        for i in 0..n - level {
            work[i] = 0.5 * (work[i] + work[i + 1]);
        }
        left[level] = work[0];
        right[n - 1 - level] = work[n - 1 - level];
    }
    (left, right)
}

impl Solver {
    fn run(&mut self, c: &[f64], e: &[f64], lo: f64, hi: f64, depth: u32) {
        if self.overflow {
            return;
        }
        let certain = c.iter().zip(e).all(|(c, e)| c.abs() > *e);
        if certain {
            let variations = c
                .windows(2)
                .filter(|w| (w[0] > 0.0) != (w[1] > 0.0))
                .count();
            if variations == 0 {
                return;
            }
            if variations == 1 {
                let u = bisect(c);
                self.roots.push(BernsteinRoot {
                    t: lo + u * (hi - lo),
                    cluster: false,
                });
                return;
            }
        } else if c.iter().zip(e).all(|(c, e)| *c > *e) || c.iter().zip(e).all(|(c, e)| *c < -*e) {
            return;
        }
        if depth >= MAX_DEPTH {
            self.leaves.push((lo, hi));
            if self.leaves.len() > LEAF_BUDGET {
                self.overflow = true;
            }
            return;
        }
        let (cl, cr) = split(c);
        let (el, er) = split(e);
        // Rounding of the split itself: a few ulp of the coefficients' size per level.
        let d = c.len() as f64;
        let widen = |e: Vec<f64>, c: &[f64]| -> Vec<f64> {
            e.iter()
                .zip(c)
                .map(|(e, c)| e + 2.0 * d * f64::EPSILON * c.abs())
                .collect()
        };
        let (el, er) = (widen(el, &cl), widen(er, &cr));
        let mid = 0.5 * (lo + hi);
        self.run(&cl, &el, lo, mid, depth + 1);
        self.run(&cr, &er, mid, hi, depth + 1);
    }
}

/// The root in `[0, 1]` of `c` whose end coefficients have opposite signs, by bisection on
/// the de Casteljau value (to the last bit).
fn bisect(c: &[f64]) -> f64 {
    let (mut a, mut b) = (0.0_f64, 1.0_f64);
    let fa_pos = c[0] > 0.0;
    for _ in 0..64 {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        let fm = de_casteljau(c, m);
        if fm == 0.0 {
            return m;
        }
        if (fm > 0.0) == fa_pos {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// Roots on `[0, 1]` of the Bernstein polynomial with coefficients `c` whose absolute
/// errors are bounded by `err` (same length, non-negative), in increasing order.
///
/// # Errors
/// [`Error::Coincident`] with the stretch `[s0, s1]` when the polynomial is zero within its
/// error bound on too long a stretch (more than 20 000 undecided leaves) or everywhere.
pub(crate) fn bernstein_roots(c: &[f64], err: &[f64]) -> Result<Vec<BernsteinRoot>, Error> {
    if c.iter().zip(err).all(|(c, e)| c.abs() <= *e) {
        return Err(Error::Coincident { s0: 0.0, s1: 1.0 });
    }
    let mut s = Solver {
        roots: Vec::new(),
        leaves: Vec::new(),
        overflow: false,
    };
    s.run(c, err, 0.0, 1.0, 0);
    if s.overflow {
        let lo = s.leaves.first().map_or(0.0, |l| l.0);
        let hi = s.leaves.last().map_or(1.0, |l| l.1);
        return Err(Error::Coincident { s0: lo, s1: hi });
    }
    // Merge touching leaves into clusters.
    let mut clusters: Vec<(f64, f64)> = Vec::new();
    for (lo, hi) in s.leaves {
        match clusters.last_mut() {
            Some(last) if lo <= last.1 => last.1 = hi,
            _ => clusters.push((lo, hi)),
        }
    }
    s.roots
        .extend(clusters.into_iter().map(|(lo, hi)| BernsteinRoot {
            t: 0.5 * (lo + hi),
            cluster: true,
        }));
    s.roots.sort_by(|a, b| a.t.total_cmp(&b.t));
    Ok(s.roots)
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_core::binomial_f64;

    /// Bernstein coefficients of prod (t - r_k) (degree = roots.len() + extra, times a
    /// positive factor (1 + t^2) per extra).
    fn from_roots(roots: &[f64]) -> Vec<f64> {
        // Start with the constant 1 and multiply by (t - r) = -r (1-t) + (1 - r) t.
        let mut c = vec![1.0];
        for &r in roots {
            let d = c.len(); // current degree + 1
            let mut out = vec![0.0; d + 1];
            // scaled Bernstein convolution
            let n = d - 1;
            for (i, ci) in c.iter().enumerate() {
                let s = ci * binomial_f64(n, i);
                out[i] += s * -r;
                out[i + 1] += s * (1.0 - r);
            }
            for (k, o) in out.iter_mut().enumerate() {
                *o /= binomial_f64(n + 1, k);
            }
            c = out;
        }
        c
    }

    fn bound(c: &[f64]) -> Vec<f64> {
        let m = c.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
        vec![64.0 * f64::EPSILON * m; c.len()]
    }

    #[test]
    fn simple_roots_are_isolated_and_refined() {
        let roots = [0.1, 0.25, 0.7, 0.9999, 1.5, -0.2];
        let c = from_roots(&roots);
        let got = bernstein_roots(&c, &bound(&c)).unwrap();
        let want = [0.1, 0.25, 0.7, 0.9999];
        assert_eq!(got.len(), want.len(), "{got:?}");
        for (g, w) in got.iter().zip(want) {
            assert!((g.t - w).abs() < 1e-13, "{g:?} vs {w}");
        }
    }

    #[test]
    fn double_root_is_one_cluster_and_end_roots_are_found() {
        let c = from_roots(&[0.3, 0.3, 0.0, 1.0]);
        let got = bernstein_roots(&c, &bound(&c)).unwrap();
        let ts: Vec<f64> = got.iter().map(|r| r.t).collect();
        assert_eq!(ts.len(), 3, "{got:?}");
        assert!(ts[0].abs() < 1e-9 && (ts[1] - 0.3).abs() < 1e-7 && (ts[2] - 1.0).abs() < 1e-9);
        assert!(got[1].cluster);
    }

    #[test]
    fn zero_polynomial_is_coincident() {
        let c = vec![0.0; 5];
        assert!(matches!(
            bernstein_roots(&c, &[1e-16; 5]),
            Err(Error::Coincident { .. })
        ));
        let none = vec![1.0, -0.1, 2.0];
        assert!(bernstein_roots(&none, &bound(&none)).unwrap().is_empty());
    }
}
