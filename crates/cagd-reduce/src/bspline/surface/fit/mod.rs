//! Tensor-product B-spline / NURBS surfaces reduced to a tolerance by the global fit of
//! [`crate::reduce_bspline`], direction by direction.
//!
//! In `u` the surface `S(u, v) = sum_j M_j(v) C_j(u)` is a bundle of curves `C_j` (its
//! columns of control points, homogeneous for NURBS) sharing one knot vector: fitting the
//! bundle at once with one degree-`m_u` knot vector is fitting every `C_j`, and since the
//! `M_j(v)` are a partition of unity, `max ||S - S_u|| <= max_j max ||C_j - C_j'||`, which
//! is the span bound the fit certifies (the largest over the bundle). Then the same in `v`
//! on `S_u`. Knot lines keep `C^min(k, m - 1)` where the input is `C^k` (structurally: the
//! multiplicities), knots are added where a span misses its share of the tolerance, and
//! knot lines are removed within the rest, a removal being charged to the spans it touches
//! with the bound of the whole bundle (for NURBS the bundle's homogeneous change turned
//! into a model-space bound of the surface by
//! [`cagd_core::BSplineCurve::remove_knot_rational_bundle`]).

use cagd_core::{BSplineCurve, BSplineSurface, Error, Result, check_tolerance};

use crate::bspline::fit::Source;
use crate::bspline::global::{fit_to_budget, initial_knots};
use crate::bspline::knots::{LocalBounds, Raw};
use crate::bspline::measure::surface_max_deviation;
use crate::bspline::surface::MAX_SURFACE_PATCHES;

/// Share of a direction's tolerance the fit must meet; the rest is for knot removal.
const FIT_SHARE: f64 = 0.9;

/// Options of [`reduce_bspline_surface_fit`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceFitOptions {
    /// Target degrees `(m_u, m_v)`, `1 <= m_u <= p`, `1 <= m_v <= q`, not both equal to
    /// the source degrees (an unchanged direction is left alone).
    pub target: (usize, usize),
    /// The certified bound of `max ||S - S'||` (Euclidean, model space) must not exceed it.
    pub tolerance: f64,
    /// The continuity `k` to keep across the input's knot lines; `None`: the most a reduced
    /// direction can carry, `m - 1`.
    pub continuity: Option<usize>,
    /// Also measure the error ([`crate::surface_max_deviation`]: sampled and locally
    /// maximised on every cell).
    pub measure: bool,
}

impl SurfaceFitOptions {
    /// Options with the most continuity and no measuring.
    pub fn new(target: (usize, usize), tolerance: f64) -> Self {
        Self {
            target,
            tolerance,
            continuity: None,
            measure: false,
        }
    }
}

/// The result of [`reduce_bspline_surface_fit`].
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceFitReduction {
    /// The reduced surface (clamped on the input's domain, rational if the input is).
    pub surface: BSplineSurface,
    /// Certified bound of `max ||S(u,v) - S'(u,v)||` (Euclidean, model space,
    /// `<= tolerance`): the sum of the two directions' bounds.
    pub error_bound: f64,
    /// The certified bounds of the `u` and the `v` step.
    pub direction_bounds: (f64, f64),
    /// The sampled error (on request).
    pub max_error: Option<f64>,
    /// Non-empty knot spans of the input in `u` and `v`.
    pub spans_in: (usize, usize),
    /// Non-empty knot spans of the result in `u` and `v`.
    pub spans_out: (usize, usize),
}

/// One direction reduced: the new knots, the net (`n * others * block` working
/// coordinates, direction-major) and the certified bound.
struct Step {
    knots: Vec<f64>,
    net: Vec<f64>,
    bound: f64,
}

/// Fits the bundle spline `(p, knots, net)` (points of `others * block` coordinates) by
/// degree `m` within `tol`.
fn reduce_direction(
    (p, knots, net): (usize, &[f64], &[f64]),
    (others, block, rational): (usize, usize, bool),
    m: usize,
    k: usize,
    tol: f64,
) -> Result<Step> {
    let bundle = BSplineCurve::new(p, knots.to_vec(), net.to_vec(), others * block)?;
    let src = Source::new(&bundle, block, rational)?;
    let start = initial_knots(knots, p, &src, m, k)?;
    let (knots, net, bounds) = fit_to_budget(&src, m, start, FIT_SHARE * tol)?;
    let mut breaks: Vec<f64> = bounds.iter().map(|x| x.a).collect();
    breaks.push(bounds[bounds.len() - 1].b);
    let mut local = LocalBounds::new(breaks, bounds.iter().map(|x| x.bound).collect());
    let fitted = BSplineCurve::new(m, knots, net, others * block)?;
    // NURBS: the bundle is homogeneous; its removals are certified in model space.
    let mut raw = if rational {
        Raw::new_rational_bundle(&fitted, block)
    } else {
        Raw::new(&fitted)
    };
    local.remove_greedily(&mut raw, tol)?;
    let curve = raw.into_curve()?;
    let bound = local.max_bound();
    let (knots, net, _) = curve.into_parts();
    Ok(Step { knots, net, bound })
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

/// Refuses a surface of `su x sv` Bézier patches when that is more than
/// [`MAX_SURFACE_PATCHES`] and more than the input's `input` patches (ADDED; bounded work
/// and output, issue 18: a bicubic NURBS to degree (1, 1) within 1e-9 was fitted with
/// 386 140 patches, 4 s and 600 MB in a release build before the measurement and the
/// output).
fn within_patch_cap(su: usize, sv: usize, input: usize) -> Result<()> {
    if su.saturating_mul(sv) > MAX_SURFACE_PATCHES.max(input) {
        return Err(Error::ConditionNotMet {
            eq: "tolerance",
            why: "the refinement needs too much work (a result of more than 2^16 patches)",
        });
    }
    Ok(())
}

/// Non-empty spans of a clamped or unclamped knot vector of degree `p`.
fn spans(knots: &[f64], p: usize) -> usize {
    let n = knots.len() - p - 1;
    (p..n).filter(|&i| knots[i] < knots[i + 1]).count()
}

/// Reduces a B-spline / NURBS surface of degrees `(p, q)` to `(m_u, m_v)` within a
/// tolerance by the global least-squares fit of [`crate::reduce_bspline`] applied in `u`
/// to the bundle of columns and then in `v` to the bundle of rows (see the module docs),
/// with half the tolerance for the `u` step and the rest for the `v` step. The input's knot
/// lines keep `C^min(k, m - 1)` (`C^k` in the input); refinement adds knot lines where
/// needed; knot removal then removes what the tolerance allows (NURBS included: removals
/// are certified in model space over the whole homogeneous bundle).
///
/// # Errors
/// [`Error::BadTolerance`]; [`Error::BadDegreePair`] (a target 0 or above the degree, or
/// both equal to the degrees); [`Error::TooManyConstraints`] (`continuity > m - 1` of a
/// reduced direction); [`Error::BadParameter`] (a knot line of multiplicity `p + 1`);
/// [`Error::ConditionNotMet`] when the tolerance is below the rounding level, or when the
/// result would have more than [`MAX_SURFACE_PATCHES`] Bézier patches (and more than the
/// input).
///
/// ```
/// use cagd_core::BSplineSurface;
/// use cagd_reduce::{SurfaceFitOptions, reduce_bspline_surface_fit};
/// let k = vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0];
/// let pts: Vec<f64> = (0..25)
///     .flat_map(|ij| { let (i, j) = (ij / 5, ij % 5); [i as f64, j as f64, ((i * j) % 3) as f64] })
///     .collect();
/// let s = BSplineSurface::new((3, 3), k.clone(), k, pts, (5, 5), 3)?;
/// let opts = SurfaceFitOptions { measure: true, ..SurfaceFitOptions::new((2, 2), 1e-3) };
/// let r = reduce_bspline_surface_fit(&s, &opts)?;
/// assert_eq!(r.surface.degrees(), (2, 2));
/// assert!(r.max_error.unwrap() <= r.error_bound && r.error_bound <= 1e-3);
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn reduce_bspline_surface_fit(
    s: &BSplineSurface,
    opts: &SurfaceFitOptions,
) -> Result<SurfaceFitReduction> {
    check_tolerance(opts.tolerance)?;
    let ((p, q), (mu, mv)) = (s.degrees(), opts.target);
    if mu == 0 || mv == 0 || mu > p || mv > q || (mu, mv) == (p, q) {
        return Err(Error::BadDegreePair {
            from: p.max(q),
            to: mu.max(mv),
            why: "surface reduction needs 1 <= m_u <= p, 1 <= m_v <= q, not both equal",
        });
    }
    let reduced_min = [(mu, p), (mv, q)]
        .iter()
        .filter(|(m, d)| m < d)
        .map(|(m, _)| m - 1)
        .min()
        .unwrap_or(0);
    if let Some(k) = opts.continuity.filter(|k| *k > reduced_min) {
        let k64 = i64::try_from(k).unwrap_or(i64::MAX);
        return Err(Error::TooManyConstraints {
            r: k64,
            p: k64,
            m: reduced_min + 1,
            why: "a degree-m spline is at most C^(m-1) across a knot line",
        });
    }
    // Each direction keeps what was asked, or (None) the most its own degree carries.
    let keep = |m: usize| opts.continuity.unwrap_or(m - 1);
    let (nu, nv) = s.counts();
    let rational = s.is_rational();
    let dim = s.dim();
    let block = dim + usize::from(rational);
    let hom = homogeneous_net(s);
    let both = mu < p && mv < q;
    let tol = opts.tolerance;
    let input = spans(s.knots_u(), p).saturating_mul(spans(s.knots_v(), q));
    // u: the bundle of columns is the net itself (i-major).
    let (ku, net, bu, n1) = if mu < p {
        let tol_u = if both { 0.5 * tol } else { tol };
        let st = reduce_direction(
            (p, s.knots_u(), &hom),
            (nv, block, rational),
            mu,
            keep(mu),
            tol_u,
        )?;
        within_patch_cap(spans(&st.knots, mu), spans(s.knots_v(), q), input)?;
        let n1 = st.knots.len() - mu - 1;
        (st.knots, st.net, st.bound, n1)
    } else {
        (s.knots_u().to_vec(), hom, 0.0, nu)
    };
    // v: the bundle of rows (the net transposed, j-major).
    let (kv, net, bv, n2) = if mv < q {
        let t = transpose(&net, n1, nv, block);
        let st = reduce_direction(
            (q, s.knots_v(), &t),
            (n1, block, rational),
            mv,
            keep(mv),
            tol - bu,
        )?;
        let n2 = st.knots.len() - mv - 1;
        (st.knots, transpose(&st.net, n2, n1, block), st.bound, n2)
    } else {
        (s.knots_v().to_vec(), net, 0.0, nv)
    };
    let (su, sv) = (spans(&ku, mu), spans(&kv, mv));
    within_patch_cap(su, sv, input)?;
    let surface = if rational {
        let mut pts = Vec::with_capacity(n1 * n2 * dim);
        let mut w = Vec::with_capacity(n1 * n2);
        for h in net.chunks_exact(block) {
            pts.extend(h[..dim].iter().map(|x| x / h[dim]));
            w.push(h[dim]);
        }
        BSplineSurface::new_rational((mu, mv), ku, kv, pts, w, (n1, n2), dim)?
    } else {
        BSplineSurface::new((mu, mv), ku, kv, net, (n1, n2), dim)?
    };
    let max_error = if opts.measure {
        Some(surface_max_deviation(s, &surface)?)
    } else {
        None
    };
    Ok(SurfaceFitReduction {
        surface,
        error_bound: bu + bv,
        direction_bounds: (bu, bv),
        max_error,
        spans_in: (spans(s.knots_u(), p), spans(s.knots_v(), q)),
        spans_out: (su, sv),
    })
}

/// The control net in working coordinates (homogeneous `(w P, w)` for NURBS), i-major.
fn homogeneous_net(s: &BSplineSurface) -> Vec<f64> {
    let dim = s.dim();
    match s.weights() {
        None => s.points().to_vec(),
        Some(w) => s
            .points()
            .chunks_exact(dim)
            .zip(w)
            .flat_map(|(p, &wi)| p.iter().map(move |x| x * wi).chain(std::iter::once(wi)))
            .collect(),
    }
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_fuzz;
