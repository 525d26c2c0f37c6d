//! Degree reduction of tensor-product B-spline / NURBS surfaces, direction by direction:
//! Bézier extraction, every patch reduced by a curve operator applied to its columns (in
//! `u`) and then to its rows (in `v`) — the tensor multi-degree approach — with end
//! constraints per knot line, and an exact merge back (interior multiplicities = target
//! degree, seed 001 §4.1 per direction).

use cagd_core::{BSplineSurface, Error, Result, knot_multiplicity};

use crate::bezier::max_norm;
use crate::bspline::framed;
use crate::bspline::measure::{euclidean_from_homogeneous, surface_max_deviation};
use crate::{Method, operator};

/// Options of [`reduce_bspline_surface`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceOptions {
    /// Target degrees `(m_u, m_v)`, `1 <= m_u <= p`, `1 <= m_v <= q` (equal: that direction
    /// is left alone).
    pub target: (usize, usize),
    /// Continuity `k` to keep across the knot lines (per direction at most
    /// `floor((m - 1) / 2)`, the default, and the input's `p - s`).
    pub continuity: Option<usize>,
    /// [`Method::ConstrainedChebyshev`] (default) or [`Method::L2`]; `r, p` are set per
    /// patch side.
    pub method: Method,
    /// Also measure the error ([`surface_max_deviation`]: sampled and locally maximised on
    /// every cell of both surfaces' knot lines).
    pub measure: bool,
}

impl SurfaceOptions {
    /// Options for the target degrees with the defaults.
    pub fn new(target: (usize, usize)) -> Self {
        Self {
            target,
            continuity: None,
            method: Method::ConstrainedChebyshev { r: 0, p: 0 },
            measure: false,
        }
    }
}

/// The result of [`reduce_bspline_surface`].
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceReduction {
    /// The reduced surface (clamped, interior knots of multiplicity `m_u` / `m_v`).
    pub surface: BSplineSurface,
    /// Certified bound of `max ||S(u,v) - S'(u,v)||` (Euclidean, model space).
    pub error_bound: f64,
    /// The measured error `max ||S - S'||` (on request; [`surface_max_deviation`]).
    pub max_error: Option<f64>,
    /// Number of Bézier patches.
    pub patches: usize,
}

/// Continuity orders at the distinct break values of one direction.
fn orders(breaks: &[f64], knots: &[f64], p: usize, k: usize) -> Vec<i32> {
    let last = breaks.len() - 1;
    (0..=last)
        .map(|i| {
            if i == 0 || i == last {
                0
            } else {
                i32::try_from(k.min(p.saturating_sub(knot_multiplicity(knots, breaks[i]))))
                    .unwrap_or(i32::MAX)
            }
        })
        .collect()
}

fn with_orders(method: Method, r: i32, p: i32) -> Method {
    match method {
        Method::L2 { .. } => Method::L2 { r, p },
        _ => Method::ConstrainedChebyshev { r, p },
    }
}

/// Reduces `pts` (`count` curves of `deg + 1` points of `pdim` coordinates, point `i` of
/// curve `c` at `(i * stride_i + c * stride_c) * pdim`) to degree `m`; returns the reduced
/// points in the same layout with `m + 1` points and the largest certified curve bound.
fn reduce_curves(
    pts: &[f64],
    (deg, m, pdim): (usize, usize, usize),
    (count, si, sc): (usize, usize, usize),
    (so_i, so_c): (usize, usize),
    method: Method,
    out: &mut [f64],
) -> Result<f64> {
    let op = operator(method, deg, m)?;
    let mut bound = 0.0f64;
    let (mut col, mut red) = (vec![0.0; (deg + 1) * pdim], vec![0.0; (m + 1) * pdim]);
    for c in 0..count {
        for i in 0..=deg {
            let at = (i * si + c * sc) * pdim;
            col[i * pdim..(i + 1) * pdim].copy_from_slice(&pts[at..at + pdim]);
        }
        op.apply_into(&col, pdim, &mut red)?;
        bound = bound.max(op.error_bound(&col, &red, pdim)?);
        for i in 0..=m {
            let at = (i * so_i + c * so_c) * pdim;
            out[at..at + pdim].copy_from_slice(&red[i * pdim..(i + 1) * pdim]);
        }
    }
    Ok(bound)
}

/// Reduces a B-spline / NURBS surface of degrees `(p, q)` to `(m_u, m_v)`.
///
/// Each Bézier patch `P` ((p+1) x (q+1) points, homogeneous for NURBS) is reduced in `u` by
/// the curve operator applied to every column, then in `v` to every row (seed 000 §14.5 /
/// L2 operators with end orders `min(k, p - s)` at each knot line, 0 at the boundary), so
/// patches sharing a knot line keep the same derivatives across it (geometric
/// `C^k`; the merged surface stores interior knots with multiplicity `m_u`, `m_v`, i.e.
/// structurally C0 — surface knot removal is not implemented).
///
/// **Bound.** `S - S' = (S - S_u) + (S_u - S')`; for fixed `v` the first is a convex
/// combination of the column errors, so it is at most the largest certified column bound,
/// likewise the second with the rows. Plus the merge's change of shared boundary points
/// (their average is stored; certified by the convex hull), per patch. A NURBS is reduced
/// in its frame (centred at the origin, scaled to radius 1; moved back after, the rounding added), where the homogeneous bound becomes the
/// centred model-space one ([`cagd_core::centred_rational_bound`]): unit-consistent, so
/// the same surface moved or scaled gets a bound that scales with it.
///
/// `max_error` (on request) is measured by [`surface_max_deviation`]: dense sampling plus
/// local maximisation on every cell, not a bare grid.
///
/// # Errors
/// [`Error::BadDegreePair`] (a target 0 or above the degree, or both equal);
/// [`Error::BadParameter`] (method not `ConstrainedChebyshev` / `L2`);
/// [`Error::TooManyConstraints`] (`continuity` above `floor((m-1)/2)` of a reduced
/// direction); [`Error::NonPositiveWeight`] (a reduced NURBS weight).
///
/// ```
/// use cagd_core::BSplineSurface;
/// use cagd_reduce::{SurfaceOptions, reduce_bspline_surface};
/// // A bicubic surface whose rows are quadratics in disguise reduces to degrees (2, 3).
/// let k = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
/// let pts: Vec<f64> = (0..16).map(|ij| { let (i, j) = (ij / 4, ij % 4); (i * i + j) as f64 }).collect();
/// let s = BSplineSurface::new((3, 3), k.clone(), k, pts, (4, 4), 1)?;
/// let r = reduce_bspline_surface(&s, &SurfaceOptions::new((2, 3)))?;
/// assert_eq!(r.surface.degrees(), (2, 3));
/// assert!(r.error_bound < 0.5);
/// # Ok::<(), cagd_reduce::Error>(())
/// ```
pub fn reduce_bspline_surface(
    s: &BSplineSurface,
    opts: &SurfaceOptions,
) -> Result<SurfaceReduction> {
    let Some((frame, moved)) = framed::frame_surface(s, f64::INFINITY)? else {
        return patchwise_at(s, opts);
    };
    let inner = SurfaceOptions {
        measure: false,
        ..*opts
    };
    let red = patchwise_at(&moved, &inner)?;
    let out = red.surface.points().to_vec();
    let surface = framed::unframe_surface(&frame, &red.surface)?;
    let max_error = if opts.measure {
        Some(surface_max_deviation(s, &surface)?)
    } else {
        None
    };
    Ok(SurfaceReduction {
        surface,
        error_bound: frame.finish(red.error_bound, &out),
        max_error,
        patches: red.patches,
    })
}

/// [`reduce_bspline_surface`] on a polynomial or framed rational surface.
fn patchwise_at(s: &BSplineSurface, opts: &SurfaceOptions) -> Result<SurfaceReduction> {
    let ((p, q), (mu, mv)) = (s.degrees(), opts.target);
    if mu == 0 || mv == 0 || mu > p || mv > q || (mu == p && mv == q) {
        return Err(Error::BadDegreePair {
            from: p.max(q),
            to: mu.max(mv),
            why: "surface targets need 1 <= m_u <= p, 1 <= m_v <= q, one of them below",
        });
    }
    if !matches!(
        opts.method,
        Method::ConstrainedChebyshev { .. } | Method::L2 { .. }
    ) {
        return Err(Error::BadParameter {
            name: "method",
            value: 0.0,
            why: "surface reduction needs ConstrainedChebyshev or L2 (end orders per knot line)",
        });
    }
    let reduced_kmax = |m: usize, deg: usize| if m < deg { (m - 1) / 2 } else { deg };
    let kmax = reduced_kmax(mu, p).min(reduced_kmax(mv, q));
    let k = opts.continuity.unwrap_or(kmax);
    if k > kmax {
        return Err(Error::TooManyConstraints {
            r: k as i64,
            p: k as i64,
            m: mu.min(mv),
            why: "per-patch Hermite constraints keep at most C^floor((m-1)/2)",
        });
    }
    let pieces = s.to_beziers()?;
    let mut ub: Vec<f64> = pieces.iter().map(|x| x.u.0).collect();
    ub.push(pieces.last().map_or(0.0, |x| x.u.1));
    ub.dedup();
    let mut vb: Vec<f64> = pieces.iter().map(|x| x.v.0).collect();
    vb.sort_by(f64::total_cmp);
    vb.dedup();
    vb.push(pieces.last().map_or(0.0, |x| x.v.1));
    let (nu, nv) = (ub.len() - 1, vb.len() - 1);
    let (ou, ov) = (
        orders(&ub, s.knots_u(), p, k),
        orders(&vb, s.knots_v(), q, k),
    );
    let rational = s.is_rational();
    let dim = s.dim();
    let pdim = dim + usize::from(rational);
    let (gu, gv) = (nu * mu + 1, nv * mv + 1);
    let mut acc = vec![0.0; gu * gv * pdim];
    let mut count = vec![0u32; gu * gv];
    let mut nets = Vec::with_capacity(pieces.len());
    for (idx, piece) in pieces.iter().enumerate() {
        let (a, b) = (idx / nv, idx % nv);
        let net: Vec<f64> = match &piece.weights {
            None => piece.patch.points().to_vec(),
            Some(w) => piece
                .patch
                .points()
                .chunks_exact(dim)
                .zip(w)
                .flat_map(|(x, wi)| x.iter().map(move |c| c * wi).chain(std::iter::once(*wi)))
                .collect(),
        };
        // u: columns j (points i * (q+1) + j) -> (mu+1) x (q+1).
        let mut mid = vec![0.0; (mu + 1) * (q + 1) * pdim];
        let bu = if mu < p {
            let mth = with_orders(opts.method, ou[a], ou[a + 1]);
            reduce_curves(
                &net,
                (p, mu, pdim),
                (q + 1, q + 1, 1),
                (q + 1, 1),
                mth,
                &mut mid,
            )?
        } else {
            mid.copy_from_slice(&net);
            0.0
        };
        let mut red = vec![0.0; (mu + 1) * (mv + 1) * pdim];
        let bv = if mv < q {
            let mth = with_orders(opts.method, ov[b], ov[b + 1]);
            reduce_curves(
                &mid,
                (q, mv, pdim),
                (mu + 1, 1, q + 1),
                (1, mv + 1),
                mth,
                &mut red,
            )?
        } else {
            red.copy_from_slice(&mid);
            0.0
        };
        for i in 0..=mu {
            for j in 0..=mv {
                let g = (a * mu + i) * gv + b * mv + j;
                count[g] += 1;
                for c in 0..pdim {
                    acc[g * pdim + c] += red[(i * (mv + 1) + j) * pdim + c];
                }
            }
        }
        nets.push((a, b, red, bu + bv));
    }
    for (g, &c) in count.iter().enumerate() {
        acc[g * pdim..(g + 1) * pdim]
            .iter_mut()
            .for_each(|x| *x /= f64::from(c));
    }
    // Per patch: its own bound plus the largest move of its points by the averaging.
    let mut eps_h = 0.0f64;
    for (a, b, red, bound) in &nets {
        let mut moved = 0.0f64;
        for i in 0..=mu {
            for j in 0..=mv {
                let g = (a * mu + i) * gv + b * mv + j;
                let d = (0..pdim)
                    .map(|c| (acc[g * pdim + c] - red[(i * (mv + 1) + j) * pdim + c]).powi(2))
                    .sum::<f64>()
                    .sqrt();
                moved = moved.max(d);
            }
        }
        eps_h = eps_h.max(bound + moved * (1.0 + 4.0 * f64::EPSILON));
    }
    let knots = |br: &[f64], m: usize| {
        let mut k = vec![br[0]; m + 1];
        for &x in &br[1..br.len() - 1] {
            k.extend(std::iter::repeat_n(x, m));
        }
        k.extend(std::iter::repeat_n(br[br.len() - 1], m + 1));
        k
    };
    let (ku, kv) = (knots(&ub, mu), knots(&vb, mv));
    let (surface, error_bound) = if rational {
        let mut pts = vec![0.0; gu * gv * dim];
        let mut w = vec![0.0; gu * gv];
        cagd_core::kernel::from_homogeneous(&acc, dim, &mut pts, &mut w);
        if let Some(index) = w.iter().position(|x| x.is_nan() || *x <= 0.0) {
            return Err(Error::NonPositiveWeight {
                index,
                weight: w[index],
            });
        }
        let wmin = s
            .weights()
            .map_or(1.0, |w| w.iter().copied().fold(f64::INFINITY, f64::min));
        let vmin = w.iter().copied().fold(f64::INFINITY, f64::min);
        let bound = euclidean_from_homogeneous(eps_h, max_norm(s.points(), dim), wmin, vmin);
        let sf = BSplineSurface::new_rational((mu, mv), ku, kv, pts, w, (gu, gv), dim)?;
        (sf, bound)
    } else {
        (
            BSplineSurface::new((mu, mv), ku, kv, acc, (gu, gv), dim)?,
            eps_h,
        )
    };
    let max_error = if opts.measure {
        Some(surface_max_deviation(s, &surface)?)
    } else {
        None
    };
    Ok(SurfaceReduction {
        surface,
        error_bound,
        max_error,
        patches: pieces.len(),
    })
}

#[cfg(test)]
mod tests;
