//! What the B-spline reducers' tests share (`#[cfg(test)]`; sibling test modules do not
//! import each other, `tests/no_import_cycles.rs`): the jittered knot vectors and smooth
//! 3-D sweeps of the random test curves, and the inner products of a fit's residual with
//! the basis functions by an independent quadrature (composite Simpson), the check that a
//! fit is the L2-best one.

use cagd_core::{BSplineCurve, basis_functions, find_span};

/// A clamped degree-`p` knot vector on `[0, 1]` with `spans` jittered spans (interior knot
/// `i` at `(i + 0.3 r[i % 8]) / spans`), the one at index `spans / 2` of multiplicity
/// `mult`; `r` holds eight values in `[-1, 1]`.
pub(crate) fn jittered_knots(p: usize, spans: usize, mult: usize, r: &[f64]) -> Vec<f64> {
    let mut knots = vec![0.0; p + 1];
    for i in 1..spans {
        let t = (i as f64 + 0.3 * r[i % 8]) / spans as f64;
        let times = if i == spans / 2 { mult } else { 1 };
        knots.extend(std::iter::repeat_n(t, times));
    }
    knots.extend(std::iter::repeat_n(1.0, p + 1));
    knots
}

/// The point at `g` (in `[0, 1]`) of the smooth 3-D sweep of size about one that `r` (eight
/// values in `[-1, 1]`) chooses: a sweep of `1.5 (1 + r[0])` radians with a gentle bend
/// and lift (the `cad_curves` bench's kind of face edge).
pub(crate) fn sweep_point(g: f64, r: &[f64]) -> [f64; 3] {
    let a = 1.5 * (1.0 + r[0]) * g + r[1];
    let rad = 1.0 + 0.3 * (3.0 * g).sin() * r[2];
    [rad * a.cos(), rad * a.sin(), 0.4 * r[3] * g]
}

/// The smooth weight at `g` of the sweep `r`: `2^sin(...)`, in `[0.5, 2]`.
pub(crate) fn sweep_weight(g: f64, r: &[f64]) -> f64 {
    2f64.powf(((2.0 + r[4]) * g * std::f64::consts::PI + r[5]).sin())
}

/// The Greville abscissa of control point `i` of a degree-`p` knot vector, relative to
/// its domain: where [`sweep_point`] places the point.
pub(crate) fn greville(knots: &[f64], p: usize, i: usize) -> f64 {
    let (lo, hi) = (knots[p], knots[knots.len() - p - 1]);
    (knots[i + 1..=i + p].iter().sum::<f64>() / p as f64 - lo) / (hi - lo)
}

/// `integral (c - s) N_j dt` for every basis function `N_j` of the polynomial spline `s`
/// (`c` the curve it fits, same dimension and domain), by composite Simpson with
/// `panels` panels on every interval between consecutive `cuts` (increasing; they must
/// include the knots of `s` and the breaks of `c`, so that both are polynomials on each):
/// independent of the fit's Gauss rows. The L2-best fit with its end points kept has every
/// interior value zero up to the quadrature's error.
pub(crate) fn residual_inner_products(
    c: &BSplineCurve,
    s: &BSplineCurve,
    cuts: &[f64],
    panels: u32,
) -> Vec<Vec<f64>> {
    let (knots, m, dim) = (s.knots(), s.degree(), s.dim());
    let n = knots.len() - m - 1;
    let mut inner = vec![vec![0.0f64; dim]; n];
    let (mut basis, mut scratch) = (vec![0.0; m + 1], vec![0.0; 2 * (m + 1)]);
    for w in cuts.windows(2).filter(|w| w[0] < w[1]) {
        let h = (w[1] - w[0]) / f64::from(panels);
        // The span of the interval (its midpoint's: the ends may be knots).
        let span = find_span(knots, m, n, 0.5 * (w[0] + w[1]));
        for i in 0..=2 * panels {
            let t = w[0] + h * f64::from(i) / 2.0;
            let weight = if i == 0 || i == 2 * panels {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            } * h
                / 6.0;
            let (a, b) = (c.eval(t).unwrap(), s.eval(t).unwrap());
            basis_functions(knots, span, m, t, &mut basis, &mut scratch);
            for (k, nk) in basis.iter().enumerate() {
                for d in 0..dim {
                    inner[span - m + k][d] += weight * nk * (a[d] - b[d]);
                }
            }
        }
    }
    inner
}
