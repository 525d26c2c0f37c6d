//! [`rational_surface_to_polynomial`]: the surface entry point, its result and the exact
//! case.

use cagd_core::{BSplineCurve, BSplineSurface, Result, check_tolerance};

use super::bound::exact_bound;
use super::curve::{continuity_report, span_count, start_knots, target_degree};
use super::surface_fit::{RationalPatches, fit_to_budget};
use crate::{
    LocalBounds, Raw, SurfaceFitOptions, reduce_bspline_surface_fit, surface_max_deviation,
};

/// Share of the tolerance the fit must meet on every patch; the rest is for knot removal.
const FIT_SHARE: f64 = 0.9;

/// The result of [`rational_surface_to_polynomial`].
#[derive(Debug, Clone, PartialEq)]
pub struct PolynomialSurfaceReduction {
    /// The polynomial B-spline surface (no weights) on the input's domain.
    pub surface: BSplineSurface,
    /// `true` when the weights were all equal (no approximation in the rational step).
    pub equal_weights: bool,
    /// The tolerance asked for.
    pub tolerance: f64,
    /// Certified bound of `max ||S(u,v) - S'(u,v)||` (Euclidean, model space,
    /// `<= tolerance`): the largest over the patches of the fitted patch's bound plus the
    /// bounds of the knot-line removals whose support covers it.
    pub error_bound: f64,
    /// The measured distance ([`crate::surface_max_deviation`]: sampled and locally
    /// maximised on every cell).
    pub max_error: f64,
    /// Patches of the fit before knot removal `(u, v)` spans.
    pub pieces: (usize, usize),
    /// Non-empty knot spans of the input in `u` and `v`.
    pub spans_in: (usize, usize),
    /// Non-empty knot spans of the result in `u` and `v`.
    pub spans_out: (usize, usize),
    /// For every interior knot line `u = t` of the input, `(t, k)`: the continuity
    /// guaranteed across it, `k = min(p - s, m_u - 1)` (as for curves).
    pub continuity_u: Vec<(f64, usize)>,
    /// The same for the knot lines `v = t` (`k = min(q - s, m_v - 1)`).
    pub continuity_v: Vec<(f64, usize)>,
}

/// `net` (`rows x cols` points of `block` coordinates, row-major) transposed.
fn transpose(net: &[f64], rows: usize, cols: usize, block: usize) -> Vec<f64> {
    let mut out = vec![0.0; net.len()];
    for i in 0..rows {
        for j in 0..cols {
            let (from, to) = ((i * cols + j) * block, (j * rows + i) * block);
            out[to..to + block].copy_from_slice(&net[from..from + block]);
        }
    }
    out
}

/// Converts a tensor NURBS surface of degrees `(p, q)` to a polynomial B-spline surface of
/// degrees `<= (m_u, m_v)` (default `(p, q)`; each `1..=64`) within `tol`, certified,
/// keeping `C^min(p - s, m - 1)` across every knot line of multiplicity `s` (the crate docs,
/// "Rational to polynomial"; ours). Weights all equal are recognised exactly: the surface of
/// the same control points (reduced by [`crate::reduce_bspline_surface_fit`] where a
/// target degree is below the input's).
///
/// # Errors
/// [`crate::Error::BadTolerance`]; [`crate::Error::BadDegreePair`] (a target 0 or above 64);
/// [`crate::Error::BadParameter`] (a knot line of multiplicity `p + 1`);
/// [`crate::Error::ConditionNotMet`] when the tolerance cannot be reached.
///
/// ```
/// use cagd_core::BSplineSurface;
/// use cagd_reduce::rational_surface_to_polynomial;
/// // A quarter of a cylinder: a rational quadratic in u, linear in v.
/// let h = std::f64::consts::FRAC_1_SQRT_2;
/// let k2 = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
/// let k1 = vec![0.0, 0.0, 1.0, 1.0];
/// let pts = vec![1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0, 1.0,
///                0.0, 1.0, 0.0, 0.0, 1.0, 1.0];
/// let w = vec![1.0, 1.0, h, h, 1.0, 1.0];
/// let s = BSplineSurface::new_rational((2, 1), k2, k1, pts, w, (3, 2), 3)?;
/// let r = rational_surface_to_polynomial(&s, Some((3, 1)), 1e-4)?;
/// assert!(!r.surface.is_rational() && r.error_bound <= 1e-4 && r.max_error <= r.error_bound);
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn rational_surface_to_polynomial(
    s: &BSplineSurface,
    m: Option<(usize, usize)>,
    tol: f64,
) -> Result<PolynomialSurfaceReduction> {
    check_tolerance(tol)?;
    let (p, q) = s.degrees();
    let (mu, mv) = (
        target_degree(p, m.map(|x| x.0))?,
        target_degree(q, m.map(|x| x.1))?,
    );
    let src = RationalPatches::new(s)?;
    let spans_in = (src.breaks_u.len() - 1, src.breaks_v.len() - 1);
    let continuity = (
        continuity_report(s.knots_u(), p, mu, &src.breaks_u)?,
        continuity_report(s.knots_v(), q, mv, &src.breaks_v)?,
    );
    let equal = s.weights().is_none_or(|w| w.iter().all(|x| *x == w[0]));
    if equal {
        return exact_case(s, (mu, mv), tol, spans_in, continuity);
    }
    let ku = start_knots(s.knots_u(), p, mu, &src.breaks_u)?;
    let kv = start_knots(s.knots_v(), q, mv, &src.breaks_v)?;
    let fit = fit_to_budget(&src, (mu, mv), (ku, kv), FIT_SHARE * tol)?;
    let (ku, kv, net, bounds) = (fit.knots_u, fit.knots_v, fit.net, fit.bounds);
    let dim = s.dim();
    let (nu, nv) = (ku.len() - mu - 1, kv.len() - mv - 1);
    // Per-patch bounds on the fit's grid.
    let mut bu: Vec<f64> = bounds.iter().map(|x| x.u.0).collect();
    bu.push(ku[nu]);
    bu.sort_by(f64::total_cmp);
    bu.dedup();
    let mut bv: Vec<f64> = bounds.iter().map(|x| x.v.0).collect();
    bv.push(kv[nv]);
    bv.sort_by(f64::total_cmp);
    bv.dedup();
    let (pu, pv) = (bu.len() - 1, bv.len() - 1);
    let mut grid = vec![0.0; pu * pv];
    for x in &bounds {
        let i = bu.partition_point(|t| *t < x.u.0);
        let j = bv.partition_point(|t| *t < x.v.0);
        grid[i * pv + j] = x.bound;
    }
    // u: the net (i-major) is a bundle curve of n_v * dim coordinates.
    let row_max: Vec<f64> = (0..pu)
        .map(|i| {
            grid[i * pv..(i + 1) * pv]
                .iter()
                .copied()
                .fold(0.0, f64::max)
        })
        .collect();
    let mut local_u = LocalBounds::new(bu.clone(), row_max.clone());
    let mut raw = Raw::new(&BSplineCurve::new(mu, ku, net, nv * dim)?);
    local_u.remove_greedily(&mut raw, tol)?;
    let (ku, net, _) = raw.into_curve()?.into_parts();
    let nu = ku.len() - mu - 1;
    let charge: Vec<f64> = local_u
        .spans()
        .iter()
        .zip(&row_max)
        .map(|(a, b)| a - b)
        .collect();
    // v: rows of the net (transposed, j-major), bounds per v span with the u charges.
    let col_max: Vec<f64> = (0..pv)
        .map(|j| {
            (0..pu)
                .map(|i| grid[i * pv + j] + charge[i])
                .fold(0.0, f64::max)
        })
        .collect();
    let mut local_v = LocalBounds::new(bv, col_max);
    let t = transpose(&net, nu, nv, dim);
    let mut raw = Raw::new(&BSplineCurve::new(mv, kv, t, nu * dim)?);
    local_v.remove_greedily(&mut raw, tol)?;
    let (kv, t, _) = raw.into_curve()?.into_parts();
    let nv = kv.len() - mv - 1;
    let net = transpose(&t, nv, nu, dim);
    let spans_out = (span_count(&ku, mu), span_count(&kv, mv));
    let surface = BSplineSurface::new((mu, mv), ku, kv, net, (nu, nv), dim)?;
    let max_error = surface_max_deviation(s, &surface)?;
    Ok(PolynomialSurfaceReduction {
        surface,
        equal_weights: false,
        tolerance: tol,
        error_bound: local_v.max_bound(),
        max_error,
        pieces: (pu, pv),
        spans_in,
        spans_out,
        continuity_u: continuity.0,
        continuity_v: continuity.1,
    })
}

/// The continuity reports in `u` and `v`.
type Continuity = (Vec<(f64, usize)>, Vec<(f64, usize)>);

/// Equal weights: the polynomial surface of the same points, reduced where a target
/// degree is below the input's.
fn exact_case(
    s: &BSplineSurface,
    (mu, mv): (usize, usize),
    tol: f64,
    spans_in: (usize, usize),
    continuity: Continuity,
) -> Result<PolynomialSurfaceReduction> {
    let (p, q) = s.degrees();
    let poly = BSplineSurface::new(
        (p, q),
        s.knots_u().to_vec(),
        s.knots_v().to_vec(),
        s.points().to_vec(),
        s.counts(),
        s.dim(),
    )?;
    let target = (mu.min(p), mv.min(q));
    let (surface, bound) = if target == (p, q) {
        (poly, 0.0)
    } else {
        let r = reduce_bspline_surface_fit(&poly, &SurfaceFitOptions::new(target, tol))?;
        (r.surface, r.error_bound)
    };
    let max_error = surface_max_deviation(s, &surface)?;
    let bound = if target == (p, q) {
        exact_bound(s.points(), s.dim(), p + q + 2, max_error, tol)?
    } else {
        bound
    };
    let (a, b) = surface.degrees();
    let spans_out = (
        span_count(surface.knots_u(), a),
        span_count(surface.knots_v(), b),
    );
    Ok(PolynomialSurfaceReduction {
        surface,
        equal_weights: true,
        tolerance: tol,
        error_bound: bound,
        max_error,
        pieces: spans_out,
        spans_in,
        spans_out,
        continuity_u: continuity.0,
        continuity_v: continuity.1,
    })
}
