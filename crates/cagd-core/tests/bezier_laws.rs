//! Property laws of Bézier curves (polynomial and rational): subdivision halves evaluate to
//! the whole, elevation and sub-interval extraction preserve the curve, derivatives agree
//! with the hodograph and with finite differences.
//!
//! Tolerance: `1e-12` relative to the curve's size (the largest control-point coordinate),
//! for de Casteljau-type algorithms whose rounding is a few `n` ulp of that size.

use cagd_core::BezierCurve;
use cagd_testkit::{points, weights};
use proptest::prelude::*;

const REL: f64 = 1e-12;
const PARAMS: usize = 200;

fn size(c: &BezierCurve) -> f64 {
    c.points().iter().fold(1.0f64, |m, x| m.max(x.abs()))
}

fn curve() -> impl Strategy<Value = BezierCurve> {
    (0usize..=12, 1usize..=4, any::<bool>()).prop_flat_map(|(n, dim, rational)| {
        (points(n + 1, dim), weights(n + 1)).prop_map(move |(p, w)| {
            if rational {
                BezierCurve::new_rational(p, w, dim).expect("valid by construction")
            } else {
                BezierCurve::new(p, dim).expect("valid by construction")
            }
        })
    })
}

fn assert_same(a: &[f64], b: &[f64], tol: f64, what: &str) -> Result<(), TestCaseError> {
    for (x, y) in a.iter().zip(b) {
        prop_assert!((x - y).abs() <= tol, "{what}: {x} vs {y} (tol {tol:e})");
    }
    Ok(())
}

proptest! {
    #[test]
    fn subdivision_halves_are_the_whole(c in curve(), t in 0.05f64..0.95) {
        let (l, r) = c.subdivide(t).expect("finite t");
        let tol = REL * size(&c);
        for i in 0..=PARAMS {
            let s = i as f64 / PARAMS as f64;
            assert_same(&l.eval(s), &c.eval(t * s), tol, "left")?;
            assert_same(&r.eval(s), &c.eval(t + (1.0 - t) * s), tol, "right")?;
        }
    }

    #[test]
    fn elevation_preserves_the_curve(c in curve(), r in 1usize..=6) {
        let e = c.elevate(r).expect("within range");
        prop_assert_eq!(e.degree(), c.degree() + r);
        let tol = REL * size(&c);
        for i in 0..=PARAMS {
            let s = i as f64 / PARAMS as f64;
            assert_same(&e.eval(s), &c.eval(s), tol, "elevated")?;
        }
        // The invariant 14.1.1 of an elevated polynomial curve vanishes (exactly up to
        // rounding of the alternating sum, whose terms are up to C(n, n/2) times the size).
        if !c.is_rational() {
            let n = e.degree();
            let scale = cagd_core::binomial_f64(n, n / 2) * size(&e) * 1e-13;
            for f in e.forward_difference() {
                prop_assert!(f.abs() <= scale, "Delta^n = {f}");
            }
        }
    }

    #[test]
    fn segment_is_the_restriction(c in curve(), a in 0.0f64..0.5, len in 0.1f64..0.5) {
        let b = a + len;
        let s = c.segment(a, b).expect("a < b");
        let tol = 10.0 * REL * size(&c);
        for i in 0..=PARAMS {
            let u = i as f64 / PARAMS as f64;
            assert_same(&s.eval(u), &c.eval(a + (b - a) * u), tol, "segment")?;
        }
    }

    #[test]
    fn derivatives_match_finite_differences(c in curve(), t in 0.1f64..0.9) {
        let d = c.derivatives(t, 2).expect("finite t");
        let h = 1e-5;
        let (a, b) = (c.eval(t - h), c.eval(t + h));
        let scale = d[1].iter().fold(size(&c), |m, x| m.max(x.abs()));
        for k in 0..c.dim() {
            let fd = (b[k] - a[k]) / (2.0 * h);
            // Central difference error O(h^2 |P'''|) plus rounding O(eps |P| / h).
            prop_assert!((fd - d[1][k]).abs() <= 1e-4 * scale, "{fd} vs {}", d[1][k]);
        }
        if !c.is_rational() {
            let hod = c.hodograph();
            assert_same(&hod.eval(t), &d[1], REL * scale * c.degree().max(1) as f64, "hodograph")?;
        }
    }
}
