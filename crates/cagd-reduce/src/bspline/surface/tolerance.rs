//! B-spline / NURBS surfaces reduced to a tolerance: uniform knot refinement around the
//! patch-wise reduction of [`crate::reduce_bspline_surface`].
//!
//! At level `L` every non-empty knot span of both directions is split into `2^L` equal
//! spans (knot insertion, exact), so the refined surface has one tensor-product structure
//! (no T-junctions); its Bézier patches are reduced and merged back. The first level whose
//! certified bound meets the tolerance is returned. The bound of a patch shrinks like
//! `2^-(m+1)` per level for a smooth surface, so few levels are needed.

use cagd_core::{BSplineSurface, Error, Result, check_tolerance};

use super::patchwise::{SurfaceOptions, SurfaceReduction, reduce_bspline_surface};
use crate::bspline::measure::surface_max_deviation;

/// Deepest uniform refinement tried by [`reduce_bspline_surface_to_tolerance`]: `2^6 = 64`
/// spans per input span and direction.
pub const MAX_SURFACE_LEVEL: usize = 6;

/// The work cap of [`reduce_bspline_surface_to_tolerance`]: a refinement level whose
/// surface would have more Bézier patches than this (and more than the input has) is not
/// tried; the reduction fails with [`Error::NoConvergence`] (the tolerance and the best
/// bound reached) instead. Level `L` has `4^L` patches per input patch, so a 16 x 16-span
/// surface stops at level 4 (`2^16 = 65 536` patches, about a second to reduce in a release
/// build) rather than growing to `1 048 576` patches at level 6.
pub const MAX_SURFACE_PATCHES: usize = 1 << 16;

/// The distinct interior values to insert so that every non-empty span of `knots` (on the
/// domain `[knots[p], knots[len - p - 1]]`) is split into `parts` equal spans.
fn midpoints(knots: &[f64], p: usize, parts: usize) -> Vec<f64> {
    let (lo, hi) = (knots[p], knots[knots.len() - p - 1]);
    let mut breaks: Vec<f64> = knots
        .iter()
        .copied()
        .filter(|k| *k >= lo && *k <= hi)
        .collect();
    breaks.dedup();
    let mut out = Vec::new();
    for w in breaks.windows(2) {
        for j in 1..parts {
            out.push(w[0] + (w[1] - w[0]) * j as f64 / parts as f64);
        }
    }
    out
}

/// The number of non-empty spans of `knots` (degree `p`) on its domain.
fn spans(knots: &[f64], p: usize) -> usize {
    let (lo, hi) = (knots[p], knots[knots.len() - p - 1]);
    let mut inner: Vec<f64> = knots
        .iter()
        .copied()
        .filter(|k| *k >= lo && *k <= hi)
        .collect();
    inner.dedup();
    inner.len().saturating_sub(1).max(1)
}

/// `s` with every non-empty span split into `2^level` equal spans in both directions, all
/// knots of a direction inserted in one pass (knot refinement: one insertion after another
/// copied the whole net per knot, quadratic in the spans of the level).
fn refine(s: &BSplineSurface, level: usize) -> Result<BSplineSurface> {
    let parts = 1usize << level;
    let (p, q) = s.degrees();
    s.refine_knots_u(&midpoints(s.knots_u(), p, parts))?
        .refine_knots_v(&midpoints(s.knots_v(), q, parts))
}

/// Reduces a B-spline / NURBS surface to degrees `opts.target` with a certified error
/// bound `<= tolerance` (Euclidean, model space): the smallest uniform refinement level
/// `L <= MAX_SURFACE_LEVEL` at which [`reduce_bspline_surface`] meets the tolerance (see
/// the module docs). Continuity across knot lines is as [`reduce_bspline_surface`] keeps it.
///
/// # Errors
/// [`Error::BadTolerance`]; the errors of [`reduce_bspline_surface`];
/// [`Error::NoConvergence`] when level [`MAX_SURFACE_LEVEL`], or the deepest level within
/// [`MAX_SURFACE_PATCHES`], is not enough (with the best bound reached): bounded work;
/// [`Error::NonPositiveWeight`] only when a reduced weight is negative at every level
/// tried (a coarse level's negative weight moves on to the next level).
pub fn reduce_bspline_surface_to_tolerance(
    s: &BSplineSurface,
    opts: &SurfaceOptions,
    tolerance: f64,
) -> Result<SurfaceReduction> {
    check_tolerance(tolerance)?;
    reduce_to_tolerance_capped(s, opts, tolerance, MAX_SURFACE_PATCHES)
}

/// [`reduce_bspline_surface_to_tolerance`] with at most `cap` patches per level (beyond the
/// input's own).
fn reduce_to_tolerance_capped(
    s: &BSplineSurface,
    opts: &SurfaceOptions,
    tolerance: f64,
    cap: usize,
) -> Result<SurfaceReduction> {
    let (p, q) = s.degrees();
    let patches = spans(s.knots_u(), p).saturating_mul(spans(s.knots_v(), q));
    let inner = SurfaceOptions {
        measure: false,
        ..*opts
    };
    let mut best = f64::INFINITY;
    let mut weight_error = None;
    for level in 0..=MAX_SURFACE_LEVEL {
        if level > 0 && patches.saturating_mul(1 << (2 * level)) > cap {
            break;
        }
        let refined = refine(s, level)?;
        let mut red = match reduce_bspline_surface(&refined, &inner) {
            Ok(red) => red,
            // A reduced weight of a coarse patch may be negative where the finer patches'
            // are not (their weights vary less): try the next level.
            Err(e @ Error::NonPositiveWeight { .. }) => {
                weight_error = Some(e);
                continue;
            }
            Err(e) => return Err(e),
        };
        if red.error_bound <= tolerance {
            if opts.measure {
                red.max_error = Some(surface_max_deviation(&refined, &red.surface)?);
            }
            return Ok(red);
        }
        best = best.min(red.error_bound);
    }
    match weight_error {
        Some(e) if best.is_infinite() => Err(e),
        _ => Err(Error::NoConvergence {
            tolerance,
            achieved: best,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A bicubic height field with a real cubic term in both directions.
    fn surface() -> BSplineSurface {
        let k = vec![0.0, 0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0, 1.0];
        let mut pts = Vec::new();
        for i in 0..5 {
            for j in 0..5 {
                let (x, y) = (f64::from(i) / 4.0, f64::from(j) / 4.0);
                pts.extend([x, y, (3.0 * x).sin() * (2.0 * y).cos() + x * y * y]);
            }
        }
        BSplineSurface::new((3, 3), k.clone(), k, pts, (5, 5), 3).unwrap()
    }

    #[test]
    fn meets_tolerances_with_sampled_check() {
        let s = surface();
        for tol in [1e-2, 1e-3, 1e-4] {
            let opts = SurfaceOptions {
                measure: true,
                ..SurfaceOptions::new((2, 2))
            };
            let red = reduce_bspline_surface_to_tolerance(&s, &opts, tol).unwrap();
            assert_eq!(red.surface.degrees(), (2, 2));
            assert!(red.error_bound <= tol, "{tol}: bound {}", red.error_bound);
            // Independent check on a grid that is not the one the reducer samples.
            let mut worst: f64 = 0.0;
            for i in 0..=37 {
                for j in 0..=37 {
                    let (u, v) = (f64::from(i) / 37.0, f64::from(j) / 37.0);
                    let (a, b) = (s.eval(u, v).unwrap(), red.surface.eval(u, v).unwrap());
                    let d = a
                        .iter()
                        .zip(&b)
                        .map(|(x, y)| (x - y) * (x - y))
                        .sum::<f64>();
                    worst = worst.max(d.sqrt());
                }
            }
            assert!(worst <= red.error_bound, "{tol}: sampled {worst} > bound");
        }
    }

    #[test]
    fn bad_tolerance_and_unreachable() {
        let s = surface();
        let opts = SurfaceOptions::new((2, 2));
        for bad in [0.0, -1.0, f64::NAN] {
            assert!(matches!(
                reduce_bspline_surface_to_tolerance(&s, &opts, bad),
                Err(Error::BadTolerance { .. })
            ));
        }
        assert!(matches!(
            reduce_bspline_surface_to_tolerance(&s, &opts, 1e-300),
            Err(Error::NoConvergence { .. })
        ));
    }

    #[test]
    fn the_patch_cap_bounds_the_levels_tried() {
        // 2 x 2 spans: levels 0, 1, 2 have 4, 16, 64 patches.
        let s = surface();
        let opts = SurfaceOptions::new((2, 2));
        let full = reduce_bspline_surface_to_tolerance(&s, &opts, 1e-5).unwrap();
        assert!(full.patches > 64, "{} patches", full.patches);
        // Under a cap of 64 patches level 3 is not tried: refused with the best bound.
        match reduce_to_tolerance_capped(&s, &opts, 1e-5, 64) {
            Err(Error::NoConvergence {
                tolerance,
                achieved,
            }) => {
                assert_eq!(tolerance, 1e-5);
                assert!(achieved > 1e-5 && achieved.is_finite());
            }
            other => panic!("expected NoConvergence, got {other:?}"),
        }
        let again = reduce_to_tolerance_capped(&s, &opts, 1e-5, full.patches).unwrap();
        assert_eq!(again.surface, full.surface);
    }

    #[test]
    fn refine_inserts_what_one_at_a_time_would() {
        let s = surface();
        for level in 0..4 {
            let fast = refine(&s, level).unwrap();
            let mut slow = s.clone();
            for t in midpoints(s.knots_u(), 3, 1 << level) {
                slow = slow.insert_knot_u(t, 1).unwrap();
            }
            for t in midpoints(s.knots_v(), 3, 1 << level) {
                slow = slow.insert_knot_v(t, 1).unwrap();
            }
            assert_eq!(fast.knots_u(), slow.knots_u());
            assert_eq!(fast.knots_v(), slow.knots_v());
            let d = fast
                .points()
                .iter()
                .zip(slow.points())
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            assert!(d < 1e-13, "level {level}: {d}");
        }
    }

    #[test]
    fn midpoints_split_every_span() {
        let k = [0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0];
        assert_eq!(midpoints(&k, 2, 2), vec![0.25, 0.75]);
        assert_eq!(midpoints(&k, 2, 1), Vec::<f64>::new());
    }
}
