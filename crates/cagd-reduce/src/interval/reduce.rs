//! Degree reduction of interval triangles by linear programming (seed 004 §2, eqs. (4)–(6)
//! as reconstructed in SPEC-convert I.2): decoupled first, coupled where needed, then
//! certified.

use cagd_core::tri_count;

use super::MAX_INTERVAL_LP_WORK;
use super::certify::{Containment, Side, containment_degree_of};
use super::elevation::IntElevation;
use super::lp::{Lp, Sense, solve_min};
use super::patch::IntervalTriPatch;
use super::report::{IntervalOptions, IntervalReduction, IntervalReport};
use super::sample::{grid, max_violation};
use crate::{Error, Result};

const FREE: (f64, f64) = (f64::NEG_INFINITY, f64::INFINITY);

/// Round-off allowed between `L_q` and `U_q` of a decoupled answer on unit-size data before
/// the box counts as empty (SPEC-convert I.2: "if any `L > U`").
const CROSSING_TOL: f64 = 1e-11;

/// Reduces an interval triangle of degree `n` to the tightest degree-`m` interval triangle
/// that contains it in the control-box sense (SPEC-convert I.2, seed 004 §2).
///
/// Per coordinate, with `A = E_{m->N}`, `g_lo = E_{n->N} f_lo`, `g_hi = E_{n->N} f_hi`
/// (`N = n` unless [`IntervalOptions::containment_degree`] asks more):
/// `minimise sum U - sum L  s.t.  A L <= g_lo,  A U >= g_hi` (objective (4), constraints
/// (5)), first decoupled (two LPs `min 1'x s.t. A x >= g`), and, for a coordinate whose
/// decoupled optimum has some `L_q > U_q` (an empty interval), again with the coupling
/// `L <= U`. The LPs are solved by `microlp` (simplex: a vertex, like the paper's
/// enumeration) on data moved to the coordinate's centre and scaled to unit size.
///
/// Certification: the control points under the failing rows are moved outward until
/// `E_{m->N} L <= E_{n->N} f_lo` and `E_{m->N} U >= E_{n->N} f_hi` hold in **exact
/// arithmetic on the returned doubles** (see [`IntervalTriPatch::contains`]), and `L <= U`
/// holds; a result that is not certified is never returned. Containment of the control boxes
/// implies pointwise containment of the surfaces (Bernstein functions are non-negative and
/// sum to 1); the report adds the largest violation found by dense sampling.
///
/// Supported: `0 <= m < n <= MAX_INTERVAL_DEGREE` (64), `n <= N <= 64`, any dimension.
///
/// Time per reduction of a random 3-D interval triangle (release, the project's 2-core
/// machine shared with other builds, so the two runs below differ by up to 2x;
/// `cargo bench -p cagd-reduce --bench interval`; certified, without / with the 1 035-point
/// sampling; the coupled LP was needed for 10 / 20 / 24 / 24 / 24 of 24 coordinates):
/// 4 -> 3 (LP 15 x 10) 0.9–1.6 / 2.7–3.6 ms, 6 -> 5 (28 x 21) 3.5–4.7 / 5.3–9.6 ms,
/// 10 -> 5 (66 x 21) 15–22 / 15–31 ms, 15 -> 10 (136 x 66) 75–150 / 100–170 ms,
/// 20 -> 10 (231 x 66) 0.19–0.39 / 0.29–0.40 s. Nearly all of it is the simplex solver
/// (`microlp` is a sparse solver and `E` is dense); the exact certification is a few
/// percent.
///
/// # Errors
/// [`Error::BadDegreePair`] unless `m < n`, or when `N < n`; [`Error::DegreeOutOfRange`]
/// for `N > 64`; [`Error::LpInfeasible`] / [`Error::LpUnbounded`] if the solver says so
/// (impossible by SPEC-convert I.2: the LP is feasible and bounded),
/// [`Error::LpSolverFailed`] (solver failure or caught panic), [`Error::NotCertified`];
/// [`Error::NonFinite`] when the LP objective overflows or a reduced box is wider than
/// `f64` can represent (the value is the objective or the width).
/// [`Error::ConditionNotMet`] when the LPs would pass [`super::MAX_INTERVAL_LP_WORK`]
/// (`tri_count(N) tri_count(m)^2 dim > 2^23`).
///
/// ```
/// use cagd_reduce::{IntervalOptions, IntervalTriPatch, reduce_interval_triangle};
/// // A degree-2 interval triangle in 1-D reduced to degree 1.
/// let lo = vec![0.0, 1.0, 0.0, 2.0, 1.0, 0.0];
/// let hi: Vec<f64> = lo.iter().map(|x| x + 1.0).collect();
/// let p = IntervalTriPatch::new(lo, hi, 2, 1)?;
/// let r = reduce_interval_triangle(&p, &IntervalOptions::new(1))?;
/// assert!(r.patch.contains(&p, None)?);
/// assert!(r.report.thickness_out >= r.report.thickness_in);
/// assert!(r.report.max_violation.unwrap() <= 0.0);
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn reduce_interval_triangle(
    p: &IntervalTriPatch,
    opts: &IntervalOptions,
) -> Result<IntervalReduction> {
    let (n, m, d) = (p.degree(), opts.target, p.dim());
    if m >= n {
        return Err(Error::BadDegreePair {
            from: n,
            to: m,
            why: "interval reduction needs a target m < n",
        });
    }
    let big = containment_degree_of(n, opts.containment_degree)?;
    let work = tri_count(big)
        .saturating_mul(tri_count(m).pow(2))
        .saturating_mul(d);
    if work > MAX_INTERVAL_LP_WORK {
        return Err(Error::ConditionNotMet {
            eq: "I.2",
            why: "the LPs are beyond the work cap (MAX_INTERVAL_LP_WORK: tri_count(N) \
                  tri_count(m)^2 dim <= 2^23, about a second of simplex): use a lower \
                  target degree or fewer coordinates per call",
        });
    }
    let eo = IntElevation::new(m, big)?;
    let ei = IntElevation::new(n, big)?;
    let a = eo.to_f64();
    let cont = Containment {
        outer: &eo,
        inner: &ei,
    };
    let nm = tri_count(m);
    let mut lo = vec![0.0; nm * d];
    let mut hi = vec![0.0; nm * d];
    let mut coupled = vec![false; d];
    let (mut objective, mut objective_decoupled, mut repair) = (0.0, 0.0, 0.0_f64);
    for c in 0..d {
        let f_lo: Vec<f64> = p.lo().iter().skip(c).step_by(d).copied().collect();
        let f_hi: Vec<f64> = p.hi().iter().skip(c).step_by(d).copied().collect();
        let sol = solve_coordinate(&a, nm, &ei, &f_lo, &f_hi)?;
        coupled[c] = sol.coupled;
        objective += sol.objective;
        objective_decoupled += sol.objective_decoupled;
        let (mut l, mut u) = (sol.lo, sol.hi);
        // A coupled vertex may cross by rounding: lowering L keeps E L <= g_lo (E >= 0).
        for q in 0..nm {
            l[q] = l[q].min(u[q]);
        }
        repair = repair.max(cont.repair(&mut l, &f_lo, Side::Lower)?);
        repair = repair.max(cont.repair(&mut u, &f_hi, Side::Upper)?);
        if let Some(q) = (0..nm).find(|&q| l[q] > u[q]) {
            return Err(Error::NotCertified {
                what: "interval reduction (L <= U)",
                residual: l[q] - u[q],
            });
        }
        for q in 0..nm {
            lo[q * d + c] = l[q];
            hi[q * d + c] = u[q];
        }
    }
    // Finite bounds whose difference overflows (boxes wider than f64 can say, from inputs
    // near +-1.8e308) would certify nothing: a named error, not an infinite thickness.
    if !(objective.is_finite() && objective_decoupled.is_finite()) {
        // The LP's objective (a sum of widths) overflowed: its vertex cannot be trusted to
        // be optimal, and a report with an infinite objective would be garbage.
        return Err(Error::NonFinite {
            index: 0,
            coord: 0,
            value: objective + objective_decoupled,
        });
    }
    if let Some(k) = lo.iter().zip(&hi).position(|(a, b)| !(b - a).is_finite()) {
        return Err(Error::NonFinite {
            index: k / d,
            coord: k % d,
            value: hi[k] - lo[k],
        });
    }
    let patch = IntervalTriPatch::new(lo, hi, m, d)?;
    let (max_viol, samples) = if opts.sample_grid == 0 {
        (None, 0)
    } else {
        (
            Some(max_violation(&patch, p, opts.sample_grid)),
            grid(opts.sample_grid).count(),
        )
    };
    let (tin, tout) = (p.thickness(), patch.thickness());
    Ok(IntervalReduction {
        report: IntervalReport {
            thickness_in: tin,
            thickness_out: tout,
            ratio: (tin > 0.0).then(|| tout / tin),
            coupled,
            repair,
            max_violation: max_viol,
            samples,
            containment_degree: big,
            objective,
            objective_decoupled,
            lp_size: (eo.nrows(), nm),
        },
        patch,
    })
}

/// One coordinate's LP answer (before certification).
struct CoordinateSolution {
    lo: Vec<f64>,
    hi: Vec<f64>,
    coupled: bool,
    objective: f64,
    objective_decoupled: f64,
}

/// The decoupled LPs, and the coupled one if the decoupled answer has an empty interval.
/// Solved on `(g - t) / s` (centre `t`, size `s`) and mapped back: rows of `E` sum to 1, so
/// the map commutes with the LP (the rounding of the map is undone by the repair).
fn solve_coordinate(
    a: &[f64],
    nm: usize,
    ei: &IntElevation,
    f_lo: &[f64],
    f_hi: &[f64],
) -> Result<CoordinateSolution> {
    let (min, max) = f_lo
        .iter()
        .chain(f_hi)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let t = 0.5 * min + 0.5 * max;
    let s = if max - min > 0.0 && (max - min).is_finite() {
        0.5 * (max - min)
    } else {
        1.0
    };
    let norm = |f: &[f64]| f.iter().map(|x| (x - t) / s).collect::<Vec<_>>();
    let g_lo = ei.apply_f64(&norm(f_lo));
    let g_hi = ei.apply_f64(&norm(f_hi));
    let neg_lo: Vec<f64> = g_lo.iter().map(|x| -x).collect();
    let u = bound_lp(a, nm, &g_hi)?;
    let x = bound_lp(a, nm, &neg_lo)?;
    let l: Vec<f64> = x.iter().map(|v| -v).collect();
    let objective_decoupled = (u.iter().sum::<f64>() - l.iter().sum::<f64>()) * s;
    let back = |v: &[f64]| v.iter().map(|x| t + s * x).collect::<Vec<_>>();
    // An empty interval is `L_q > U_q` beyond the solver's round-off (the data are of unit
    // size here); a crossing within it is a touching box (`L_q = U_q` at the exact
    // optimum), closed by lowering `L_q`, which keeps `A L <= g_lo` (`A >= 0`).
    if l.iter().zip(&u).all(|(a, b)| a <= &(b + CROSSING_TOL)) {
        let l: Vec<f64> = l.iter().zip(&u).map(|(a, b)| a.min(*b)).collect();
        return Ok(CoordinateSolution {
            lo: back(&l),
            hi: back(&u),
            coupled: false,
            objective: objective_decoupled,
            objective_decoupled,
        });
    }
    let (l, u, obj) = coupled_lp(a, nm, &g_lo, &g_hi)?;
    Ok(CoordinateSolution {
        lo: back(&l),
        hi: back(&u),
        coupled: true,
        objective: obj * s,
        objective_decoupled,
    })
}

/// `min 1'x s.t. A x >= g` (x free): the one routine of the decoupled form.
fn bound_lp(a: &[f64], nm: usize, g: &[f64]) -> Result<Vec<f64>> {
    let mut lp = Lp::default();
    for _ in 0..nm {
        lp.var(1.0, FREE);
    }
    for (r, &gr) in g.iter().enumerate() {
        lp.row(row_terms(&a[r * nm..(r + 1) * nm], 0), Sense::Ge, gr);
    }
    Ok(solve_min(&lp, "interval reduction (decoupled bound)")?.x)
}

/// `min 1'U - 1'L s.t. A L <= g_lo, A U >= g_hi, L <= U`, solved as
/// `min 1'W s.t. A L <= g_lo, A L + A W >= g_hi, W >= 0` with `U = L + W` (the coupling
/// becomes variable bounds, so the LP has `2 N_N` rows instead of `2 N_N + N_m`).
fn coupled_lp(
    a: &[f64],
    nm: usize,
    g_lo: &[f64],
    g_hi: &[f64],
) -> Result<(Vec<f64>, Vec<f64>, f64)> {
    let mut lp = Lp::default();
    for _ in 0..nm {
        lp.var(0.0, FREE); // L
    }
    for _ in 0..nm {
        lp.var(1.0, (0.0, f64::INFINITY)); // W = U - L
    }
    for r in 0..g_lo.len() {
        let row = &a[r * nm..(r + 1) * nm];
        lp.row(row_terms(row, 0), Sense::Le, g_lo[r]);
        let mut both = row_terms(row, 0);
        both.extend(row_terms(row, nm));
        lp.row(both, Sense::Ge, g_hi[r]);
    }
    let sol = solve_min(&lp, "interval reduction (coupled)")?;
    let (l, w) = sol.x.split_at(nm);
    let u = l.iter().zip(w).map(|(l, w)| l + w).collect();
    Ok((l.to_vec(), u, sol.objective))
}

/// The non-zero entries of a dense row, as `(offset + column, value)`.
fn row_terms(row: &[f64], offset: usize) -> Vec<(usize, f64)> {
    row.iter()
        .enumerate()
        .filter(|(_, v)| **v != 0.0)
        .map(|(c, &v)| (offset + c, v))
        .collect()
}
