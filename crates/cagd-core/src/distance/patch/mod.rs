//! Parametric distance between two surfaces on a common parameter domain:
//! `max_{(u,v) in D} ||P(u,v) - Q(u,v)||` (Euclidean norm), `D` the unit square (tensor
//! patches) or the unit triangle `u, v >= 0, u + v <= 1` (triangular patches). This is the
//! error of a surface reduction (seed 000 §14.3, SPEC-reduce §4-§5).
//!
//! Method (ADDED): the squared distance is sampled on a dense grid; the boundary edges are
//! maximised as curves by [`max_distance_1d`]; every interior grid node that is a local
//! maximum among its 8 neighbours (and not flat to `1e-13` relative) is refined by a pattern
//! search (steps along `±u`, `±v`, `±(u - v)`, `±(u + v)`, halved when no step improves,
//! points outside the domain rejected) down to a step of `1e-10` — the [`MAX_REFINED_MAXIMA`] largest
//! of them, so the work is bounded. The result is never below the sampled maximum.
//!
//! The patch distances sample their grid with cached Bernstein bases (`grid`, ADDED):
//! `O(N^2 n)` for an `N x N` grid of a degree-`n` difference instead of `O(N^2 n^3)`.

use super::curve::max_distance_1d;
use crate::{Error, Result, TensorPatch, TriPatch};
use grid::{TensorEval, TriEval, node};

/// Smallest step of the pattern search: the value error at a smooth maximum is quadratic in
/// the position error, so `1e-10` is far below the `1e-12` relative target.
const MIN_STEP: f64 = 1e-10;

/// A parameter point `(u, v)`.
type Param = (f64, f64);

/// A 3 x 3 grid neighbourhood whose values differ by less than this (relative) is flat: its
/// centre is not refined (the possible gain is below the `1e-12` target).
const FLAT: f64 = 1e-13;

/// At most this many sampled interior local maxima are refined by the pattern search (the
/// largest ones): a noisy distance (rounding noise of two nearly equal patches) has
/// thousands of strict grid maxima, and refining all of them made one distance of two
/// degree-64 triangles take minutes (ADDED; bounded work).
pub const MAX_REFINED_MAXIMA: usize = 8;

/// The parameter domain of [`max_distance_2d`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Domain2 {
    /// `[0, 1] x [0, 1]` (tensor-product patches).
    UnitSquare,
    /// `u >= 0, v >= 0, u + v <= 1` (triangular patches).
    UnitTriangle,
}

impl Domain2 {
    fn contains(self, u: f64, v: f64) -> bool {
        match self {
            Domain2::UnitSquare => (0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v),
            Domain2::UnitTriangle => u >= 0.0 && v >= 0.0 && u + v <= 1.0,
        }
    }

    /// The boundary edges as `(start, end)` parameter pairs.
    fn edges(self) -> &'static [(Param, Param)] {
        match self {
            Domain2::UnitSquare => &[
                ((0.0, 0.0), (1.0, 0.0)),
                ((1.0, 0.0), (1.0, 1.0)),
                ((0.0, 1.0), (1.0, 1.0)),
                ((0.0, 0.0), (0.0, 1.0)),
            ],
            Domain2::UnitTriangle => &[
                ((0.0, 0.0), (1.0, 0.0)),
                ((0.0, 0.0), (0.0, 1.0)),
                ((1.0, 0.0), (0.0, 1.0)),
            ],
        }
    }
}

/// `max_{(u,v) in domain} ||f(u,v) - g(u,v)||` (Euclidean norm) for two maps into `R^dim`,
/// given as closures writing `dim` coordinates.
///
/// `samples` grid intervals per side (at least 2); boundary edges by [`max_distance_1d`] with
/// the same count, interior local maxima of the grid refined by pattern search (module
/// docs). Accuracy: relative `1e-12` (above the rounding floor of `f` and `g`) when every
/// local maximum is separated from the others by a grid cell; measured `<= 1e-13` on the
/// tests (maxima between grid nodes, shifted copies, elevated nets).
///
/// # Errors
/// [`Error::ZeroDimension`] when `dim == 0`; [`Error::NonFinite`] when a closure returns a
/// non-finite coordinate on the grid.
///
/// ```
/// use cagd_core::{Domain2, max_distance_2d};
/// // u v (1 - u - v) is largest, 1/27, at the centroid (1/3, 1/3): not a grid node.
/// let d = max_distance_2d(
///     |u, v, o| o[0] = u * v * (1.0 - u - v),
///     |_, _, o| o[0] = 0.0,
///     1,
///     Domain2::UnitTriangle,
///     32,
/// )?;
/// assert!((d - 1.0 / 27.0).abs() < 1e-15);
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn max_distance_2d(
    f: impl Fn(f64, f64, &mut [f64]),
    g: impl Fn(f64, f64, &mut [f64]),
    dim: usize,
    domain: Domain2,
    samples: usize,
) -> Result<f64> {
    if dim == 0 {
        return Err(Error::ZeroDimension);
    }
    let n = samples.max(2);
    let (mut a, mut b) = (vec![0.0; dim], vec![0.0; dim]);
    // Grid values, NaN outside the triangle.
    let mut grid = vec![f64::NAN; (n + 1) * (n + 1)];
    for i in 0..=n {
        let jmax = match domain {
            Domain2::UnitSquare => n,
            Domain2::UnitTriangle => n - i,
        };
        for j in 0..=jmax {
            let (u, v) = (
                node(i, n),
                if i + j == n && domain == Domain2::UnitTriangle {
                    1.0 - node(i, n)
                } else {
                    node(j, n)
                },
            );
            f(u, v, &mut a);
            g(u, v, &mut b);
            grid[i * (n + 1) + j] = squared_distance(&a, &b);
        }
    }
    max_distance_2d_with_grid(f, g, dim, domain, n, &grid)
}

/// `||a - b||^2`.
fn squared_distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b.iter())
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
}

/// [`max_distance_2d`] with the grid already sampled: `grid[i (samples + 1) + j]` is
/// `||f - g||^2` at the node `(i / samples, j / samples)` (on the triangle's hypotenuse
/// `i + j = samples` at `(i / samples, 1 - i / samples)`; entries outside the triangle are
/// ignored). For callers that evaluate a whole grid faster than point by point (cached
/// bases, ADDED); `f` and `g` are used on the boundary edges and for the refinement.
///
/// Refinement (bounded work, ADDED): the interior sampled local maxima are refined in
/// decreasing order of their sampled value, at most [`MAX_REFINED_MAXIMA`] of them; the others
/// count with their sampled values. The result is never below the sampled maximum.
///
/// # Errors
/// [`Error::ZeroDimension`] when `dim == 0`; [`Error::LengthMismatch`] when the grid does
/// not have `(samples + 1)^2` entries; [`Error::NonFinite`] when a grid value in the domain
/// is not finite.
pub fn max_distance_2d_with_grid(
    f: impl Fn(f64, f64, &mut [f64]),
    g: impl Fn(f64, f64, &mut [f64]),
    dim: usize,
    domain: Domain2,
    samples: usize,
    grid: &[f64],
) -> Result<f64> {
    if dim == 0 {
        return Err(Error::ZeroDimension);
    }
    let n = samples.max(2);
    if grid.len() != (n + 1) * (n + 1) {
        return Err(Error::LengthMismatch {
            what: "sampled grid of max_distance_2d_with_grid",
            got: grid.len(),
            expected: (n + 1) * (n + 1),
        });
    }
    let inside = |i: usize, j: usize| domain == Domain2::UnitSquare || i + j <= n;
    let mut best = 0.0f64;
    for i in 0..=n {
        for j in 0..=n {
            if !inside(i, j) {
                continue;
            }
            let val = grid[i * (n + 1) + j];
            if !val.is_finite() {
                return Err(Error::NonFinite {
                    index: i * (n + 1) + j,
                    coord: 0,
                    value: val,
                });
            }
            best = best.max(val);
        }
    }
    let (mut a, mut b) = (vec![0.0; dim], vec![0.0; dim]);
    let mut d2 = |u: f64, v: f64| {
        f(u, v, &mut a);
        g(u, v, &mut b);
        squared_distance(&a, &b)
    };
    // Boundary edges as curves.
    for &((u0, v0), (u1, v1)) in domain.edges() {
        let e = max_distance_1d(
            |t, o| f(u0 + t * (u1 - u0), v0 + t * (v1 - v0), o),
            |t, o| g(u0 + t * (u1 - u0), v0 + t * (v1 - v0), o),
            dim,
            0.0,
            1.0,
            n,
        )?;
        best = best.max(e * e);
    }
    // Interior local maxima of the grid, largest first.
    let mut candidates = Vec::new();
    for i in 1..n {
        for j in 1..n {
            if !inside(i, j) {
                continue;
            }
            let c = grid[i * (n + 1) + j];
            let (mut ge, mut gt, mut lowest) = (true, false, c);
            for ni in i - 1..=i + 1 {
                for nj in j - 1..=j + 1 {
                    if (ni == i && nj == j) || !inside(ni, nj) {
                        continue;
                    }
                    let w = grid[ni * (n + 1) + nj];
                    ge &= c >= w;
                    gt |= c > w;
                    lowest = lowest.min(w);
                }
            }
            // Refine strict local maxima only; a neighbourhood flat to 1e-13 relative (e.g.
            // rounding noise on a constant distance) cannot hide a larger value within it.
            if ge && gt && c - lowest > FLAT * c {
                candidates.push((c, i, j));
            }
        }
    }
    candidates.sort_by(|x, y| y.0.total_cmp(&x.0));
    const DIRS: [(f64, f64); 8] = [
        (1.0, 0.0),
        (-1.0, 0.0),
        (0.0, 1.0),
        (0.0, -1.0),
        (1.0, -1.0),
        (-1.0, 1.0),
        (1.0, 1.0),
        (-1.0, -1.0),
    ];
    for &(c, i, j) in candidates.iter().take(MAX_REFINED_MAXIMA) {
        let (mut u, mut v, mut val) = (node(i, n), node(j, n), c);
        let mut step = 1.0 / n as f64;
        while step >= MIN_STEP {
            let mut moved = false;
            for (du, dv) in DIRS {
                let (nu, nv) = (u + step * du, v + step * dv);
                if !domain.contains(nu, nv) {
                    continue;
                }
                let nval = d2(nu, nv);
                if nval > val {
                    (u, v, val) = (nu, nv, nval);
                    moved = true;
                    break;
                }
            }
            if !moved {
                step *= 0.5;
            }
        }
        if val.is_finite() {
            best = best.max(val);
        }
    }
    Ok(best.sqrt())
}

/// The tensor patch `p` at every node `(i / samples, j / samples)`, `i, j` in
/// `0..=samples`: node `(i, j)` at `(i (samples + 1) + j) dim` — the grid of
/// [`max_distance_2d_with_grid`], by cached Bernstein bases (`O(N m n + N^2 n)` for `N`
/// samples, ADDED).
pub fn tensor_patch_grid(p: &TensorPatch, samples: usize) -> Vec<f64> {
    TensorEval::new(p).grid(samples.max(2))
}

/// The triangular patch `t` at the nodes of [`max_distance_2d_with_grid`]'s triangle grid
/// of `samples` intervals per side: node `(i, j)`, `i + j <= samples`, at
/// `(i (samples + 1) + j) dim` (on the hypotenuse `i + j = samples` the point
/// `(i / samples, 1 - i / samples)`; entries outside the triangle are 0), by its rows
/// elevated once and cached bases (`O(N^2 n)` for `N` samples, ADDED).
pub fn tri_patch_grid(t: &TriPatch, samples: usize) -> Vec<f64> {
    TriEval::new(t).grid(samples.max(2))
}

/// Grid size for two patches of the given total degrees.
fn grid_for(total_degree: usize) -> usize {
    4 * total_degree + 32
}

/// The parametric distance `max_{(u,v) in [0,1]^2} ||a(u,v) - b(u,v)||` (Euclidean norm)
/// between two tensor-product patches (any degrees). Both are elevated to the common degree
/// and the control points subtracted, so rounding is relative to the difference; then
/// [`max_distance_2d`] with `4 (m + n) + 32` grid intervals per side, `(m, n)` the common
/// degrees (the degrees of the difference; sampled with cached bases, `grid`).
///
/// # Errors
/// [`Error::LengthMismatch`] when the dimensions differ.
pub fn tensor_patch_distance(a: &TensorPatch, b: &TensorPatch) -> Result<f64> {
    if a.dim() != b.dim() {
        return Err(Error::LengthMismatch {
            what: "patch dimensions",
            got: b.dim(),
            expected: a.dim(),
        });
    }
    let (ma, na) = a.degrees();
    let (mb, nb) = b.degrees();
    let (m, n) = (ma.max(mb), na.max(nb));
    let ea = a.elevate_u(m - ma)?.elevate_v(n - na)?;
    let eb = b.elevate_u(m - mb)?.elevate_v(n - nb)?;
    let diff: Vec<f64> = ea
        .points()
        .iter()
        .zip(eb.points())
        .map(|(x, y)| x - y)
        .collect();
    let d = TensorPatch::from_parts(diff, m, n, a.dim());
    let fast = TensorEval::new(&d);
    let samples = grid_for(m + n);
    let values = fast.grid(samples);
    let grid: Vec<f64> = values
        .chunks_exact(a.dim())
        .map(|x| x.iter().map(|c| c * c).sum())
        .collect();
    max_distance_2d_with_grid(
        |u, v, o| fast.eval(u, v, o),
        |_, _, o| o.fill(0.0),
        a.dim(),
        Domain2::UnitSquare,
        samples,
        &grid,
    )
}

/// The parametric distance `max ||a(u,v) - b(u,v)||` (Euclidean norm) over the unit
/// triangle between two triangular patches (any degrees): elevated to the common degree,
/// control points subtracted, then [`max_distance_2d`] with `8 n + 32` grid intervals per
/// side, `n` the common degree (the degree of the difference; sampled with cached bases,
/// `grid`).
///
/// # Errors
/// [`Error::LengthMismatch`] when the dimensions differ.
pub fn tri_patch_distance(a: &TriPatch, b: &TriPatch) -> Result<f64> {
    if a.dim() != b.dim() {
        return Err(Error::LengthMismatch {
            what: "patch dimensions",
            got: b.dim(),
            expected: a.dim(),
        });
    }
    let n = a.degree().max(b.degree());
    let ea = a.elevate(n - a.degree())?;
    let eb = b.elevate(n - b.degree())?;
    let diff: Vec<f64> = ea
        .points()
        .iter()
        .zip(eb.points())
        .map(|(x, y)| x - y)
        .collect();
    let d = TriPatch::from_parts(diff, n, a.dim());
    let fast = TriEval::new(&d);
    let samples = grid_for(2 * n);
    let values = fast.grid(samples);
    let grid: Vec<f64> = values
        .chunks_exact(a.dim())
        .map(|x| x.iter().map(|c| c * c).sum())
        .collect();
    max_distance_2d_with_grid(
        |u, v, o| fast.eval(u, v, o),
        |_, _, o| o.fill(0.0),
        a.dim(),
        Domain2::UnitTriangle,
        samples,
        &grid,
    )
}

mod grid;
#[cfg(test)]
mod tests;
