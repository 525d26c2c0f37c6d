//! Tests of [`reduce_bspline_surface`].

use super::*;
use cagd_core::TensorPatch;

fn clamped(br: &[f64], p: usize) -> Vec<f64> {
    let mut k = vec![br[0]; p + 1];
    k.extend_from_slice(&br[1..br.len() - 1]);
    k.extend(std::iter::repeat_n(br[br.len() - 1], p + 1));
    k
}

#[test]
fn elevated_patch_reduces_back() {
    let pts: Vec<f64> = (0..9 * 2).map(|i| ((i * 5 % 7) as f64) - 3.0).collect();
    let base = TensorPatch::new(pts, 2, 2, 2).unwrap();
    let up = base.elevate_u(2).unwrap().elevate_v(1).unwrap();
    let s = BSplineSurface::new(
        (4, 3),
        clamped(&[0.0, 1.0], 4),
        clamped(&[0.0, 1.0], 3),
        up.points().to_vec(),
        (5, 4),
        2,
    )
    .unwrap();
    let r = reduce_bspline_surface(
        &s,
        &SurfaceOptions {
            measure: true,
            ..SurfaceOptions::new((2, 2))
        },
    )
    .unwrap();
    cagd_testkit::assert_close("surface back", r.surface.points(), base.points(), 1e-12);
    assert!(r.error_bound < 1e-12 && r.max_error.unwrap() <= r.error_bound + 1e-15);
}

#[test]
fn multi_patch_bound_covers_the_error() {
    // Degrees (5, 4), 3 x 2 spans, rational and not -> (3, 2).
    let (p, q) = (5, 4);
    let ku = clamped(&[0.0, 0.3, 0.7, 1.0], p);
    let kv = clamped(&[0.0, 0.4, 1.0], q);
    let (nu, nv) = (ku.len() - p - 1, kv.len() - q - 1);
    let pts: Vec<f64> = (0..nu * nv * 3)
        .map(|i| ((i * 37 % 23) as f64) * 0.1 + (i / 3) as f64 * 0.05)
        .collect();
    let w: Vec<f64> = (0..nu * nv).map(|i| 1.0 + 0.3 * ((i % 4) as f64)).collect();
    for rational in [false, true] {
        let s = if rational {
            BSplineSurface::new_rational(
                (p, q),
                ku.clone(),
                kv.clone(),
                pts.clone(),
                w.clone(),
                (nu, nv),
                3,
            )
        } else {
            BSplineSurface::new((p, q), ku.clone(), kv.clone(), pts.clone(), (nu, nv), 3)
        }
        .unwrap();
        for method in [
            Method::ConstrainedChebyshev { r: 0, p: 0 },
            Method::L2 { r: 0, p: 0 },
        ] {
            let opts = SurfaceOptions {
                measure: true,
                method,
                ..SurfaceOptions::new((3, 2))
            };
            let r = reduce_bspline_surface(&s, &opts).unwrap();
            assert_eq!(r.patches, 6);
            assert_eq!(r.surface.counts(), (3 * 3 + 1, 2 * 2 + 1));
            let e = r.max_error.unwrap();
            assert!(
                e <= r.error_bound,
                "{rational} {method:?}: {e} > {}",
                r.error_bound
            );
            // C0 across the knot lines: the surface is continuous (evaluates the same from
            // the patch pieces on both sides up to rounding).
            let pieces = r.surface.to_beziers().unwrap();
            let left = &pieces[0];
            let right = &pieces[2];
            let (a, b) = (
                left.patch.eval(1.0, 0.5).unwrap(),
                right.patch.eval(0.0, 0.5).unwrap(),
            );
            if !rational {
                cagd_testkit::assert_close("C0 across u = 0.3", &a, &b, 1e-12);
            }
        }
    }
    let s = BSplineSurface::new((p, q), ku, kv, pts, (nu, nv), 3).unwrap();
    for t in [(0, 2), (6, 2), (5, 4)] {
        assert!(matches!(
            reduce_bspline_surface(&s, &SurfaceOptions::new(t)),
            Err(Error::BadDegreePair { .. })
        ));
    }
    assert!(
        reduce_bspline_surface(
            &s,
            &SurfaceOptions {
                method: Method::Eck,
                ..SurfaceOptions::new((3, 2))
            }
        )
        .is_err()
    );
    assert!(
        reduce_bspline_surface(
            &s,
            &SurfaceOptions {
                continuity: Some(1),
                ..SurfaceOptions::new((3, 2))
            }
        )
        .is_err()
    );
}
