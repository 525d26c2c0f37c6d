//! The "analytic method" of seed 004 §3 (SPEC-convert I.3): the decoupled LP solved by
//! enumerating its vertices. A second, independent route used as a test oracle; feasible
//! only for small cases (the count of bases is `C(N_N, N_m)`: 3003 for 4 -> 3, 1.2e6 for
//! 6 -> 5).

use cagd_core::tri_count;

use super::certify::containment_degree_of;
use super::elevation::IntElevation;
use super::patch::IntervalTriPatch;
use crate::{Error, Result};

/// The largest number of bases [`reduce_interval_triangle_analytic`] enumerates.
pub const MAX_ANALYTIC_BASES: usize = 250_000;

/// The decoupled optimum found by vertex enumeration.
#[derive(Debug, Clone, PartialEq)]
pub struct AnalyticOptimum {
    /// Lower net of degree `m` (i-major, `tri_count(m) * dim`).
    pub lo: Vec<f64>,
    /// Upper net of degree `m`.
    pub hi: Vec<f64>,
    /// `sum over coordinates of (sum U - sum L)`, the decoupled optimum.
    pub objective: f64,
    /// `objective / (dim N_m)`: the thickness of the decoupled optimum.
    pub thickness: f64,
    /// Whether every box is proper (`lo <= hi`); when not, the coupled LP's optimum is
    /// larger than `objective`.
    pub proper: bool,
    /// Bases enumerated per bound.
    pub bases: usize,
}

/// Seed 004 §3's one-degree analytic method (any `m < n` while the count of bases is at
/// most [`MAX_ANALYTIC_BASES`]): for each coordinate and bound, every choice of `N_m` rows of
/// `A = E_{m->N}` made tight ("set these eps to 0", the slack form of SPEC-convert I.2)
/// gives a candidate vertex `A_S x = g_S`; the feasible one (`A x >= g`) of least `1'x` is
/// the optimum. The seed calls it Lagrange multipliers; it is vertex enumeration
/// (SPEC-convert I.3). `f64` elimination with partial pivoting per basis.
///
/// # Errors
/// [`Error::BadDegreePair`] unless `m < n`, or when the count of bases exceeds
/// [`MAX_ANALYTIC_BASES`]; containment-degree errors as in
/// [`crate::reduce_interval_triangle`]; [`Error::LpInfeasible`] if no basis is feasible
/// (impossible).
pub fn reduce_interval_triangle_analytic(
    p: &IntervalTriPatch,
    m: usize,
    containment_degree: Option<usize>,
) -> Result<AnalyticOptimum> {
    let (n, d) = (p.degree(), p.dim());
    if m >= n {
        return Err(Error::BadDegreePair {
            from: n,
            to: m,
            why: "interval reduction needs a target m < n",
        });
    }
    let big = containment_degree_of(n, containment_degree)?;
    let (nm, rows) = (tri_count(m), tri_count(big));
    let bases = choose(rows, nm);
    if bases > MAX_ANALYTIC_BASES as f64 {
        return Err(Error::BadDegreePair {
            from: n,
            to: m,
            why: "vertex enumeration is limited to 250 000 bases (use the LP)",
        });
    }
    let eo = IntElevation::new(m, big)?;
    let ei = IntElevation::new(n, big)?;
    let a = eo.to_f64();
    let mut lo = vec![0.0; nm * d];
    let mut hi = vec![0.0; nm * d];
    let mut objective = 0.0;
    for c in 0..d {
        let f_lo: Vec<f64> = p.lo().iter().skip(c).step_by(d).copied().collect();
        let f_hi: Vec<f64> = p.hi().iter().skip(c).step_by(d).copied().collect();
        let g_hi = ei.apply_f64(&f_hi);
        let neg_lo: Vec<f64> = ei.apply_f64(&f_lo).iter().map(|x| -x).collect();
        let u = enumerate(&a, rows, nm, &g_hi)?;
        let l: Vec<f64> = enumerate(&a, rows, nm, &neg_lo)?
            .iter()
            .map(|x| -x)
            .collect();
        objective += u.iter().sum::<f64>() - l.iter().sum::<f64>();
        for q in 0..nm {
            lo[q * d + c] = l[q];
            hi[q * d + c] = u[q];
        }
    }
    let proper = lo.iter().zip(&hi).all(|(l, h)| l <= h);
    Ok(AnalyticOptimum {
        lo,
        hi,
        objective,
        thickness: objective / (d * nm) as f64,
        proper,
        // bases <= MAX_ANALYTIC_BASES (checked above), an exact integer in f64.
        bases: (0..=MAX_ANALYTIC_BASES)
            .find(|&b| b as f64 >= bases)
            .unwrap_or(MAX_ANALYTIC_BASES),
    })
}

/// `C(n, k)` as a float (only to bound the work).
fn choose(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

/// `argmin 1'x s.t. A x >= g` over all bases (sets of `cols` tight rows).
fn enumerate(a: &[f64], rows: usize, cols: usize, g: &[f64]) -> Result<Vec<f64>> {
    let scale = g.iter().fold(1.0_f64, |s, x| s.max(x.abs()));
    let tol = 1e-9 * scale;
    let mut best: Option<(f64, Vec<f64>)> = None;
    let mut subset: Vec<usize> = (0..cols).collect();
    loop {
        if let Some(x) = solve_square(a, cols, &subset, g) {
            let feasible = (0..rows).all(|r| {
                let ax: f64 = (0..cols).map(|c| a[r * cols + c] * x[c]).sum();
                ax >= g[r] - tol
            });
            let value: f64 = x.iter().sum();
            if feasible && best.as_ref().is_none_or(|(b, _)| value < *b) {
                best = Some((value, x));
            }
        }
        if !next_subset(&mut subset, rows) {
            break;
        }
    }
    best.map(|(_, x)| x).ok_or(Error::LpInfeasible {
        what: "interval reduction (vertex enumeration)",
    })
}

/// The next `k`-subset of `0..n` in lexicographic order; `false` after the last.
fn next_subset(s: &mut [usize], n: usize) -> bool {
    let k = s.len();
    let mut i = k;
    while i > 0 {
        i -= 1;
        if s[i] < n - k + i {
            s[i] += 1;
            for j in i + 1..k {
                s[j] = s[j - 1] + 1;
            }
            return true;
        }
    }
    false
}

/// Solves `A_S x = g_S` by Gaussian elimination with partial pivoting; `None` if singular.
fn solve_square(a: &[f64], cols: usize, subset: &[usize], g: &[f64]) -> Option<Vec<f64>> {
    let k = subset.len();
    let mut m: Vec<f64> = Vec::with_capacity(k * (k + 1));
    for &r in subset {
        m.extend_from_slice(&a[r * cols..(r + 1) * cols]);
        m.push(g[r]);
    }
    let w = k + 1;
    for col in 0..k {
        let piv =
            (col..k).max_by(|&i, &j| m[i * w + col].abs().total_cmp(&m[j * w + col].abs()))?;
        if m[piv * w + col].abs() < 1e-10 {
            return None;
        }
        if piv != col {
            for c in 0..w {
                m.swap(piv * w + c, col * w + c);
            }
        }
        for r in col + 1..k {
            let f = m[r * w + col] / m[col * w + col];
            if f != 0.0 {
                for c in col..w {
                    m[r * w + c] -= f * m[col * w + c];
                }
            }
        }
    }
    let mut x = vec![0.0; k];
    for r in (0..k).rev() {
        let s: f64 = (r + 1..k).map(|c| m[r * w + c] * x[c]).sum();
        x[r] = (m[r * w + k] - s) / m[r * w + r];
    }
    Some(x)
}
