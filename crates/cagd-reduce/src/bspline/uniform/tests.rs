//! Tests of the seed 001 uniform B-spline reduction against the spec vector and closed forms.

use super::*;
use cagd_testkit::{assert_close, flat, vector};

use crate::spline_max_deviation;

fn example() -> (cagd_testkit::serde_json::Value, BSplineCurve) {
    let v = vector("vectors-reduce.json", "001-example");
    let knots = flat(&v["params"]["knots"]);
    let c = BSplineCurve::new(7, knots, flat(&v["input"]["P"]), 2).unwrap();
    (v, c)
}

const HERMITE: Method = Method::ConstrainedChebyshev { r: 1, p: 1 };

/// Seed 001's worked example (SPEC-reduce §8): what is reproduced and to what accuracy.
#[test]
fn vector_001_example() {
    let (v, c) = example();
    let e = &v["expected"];
    let tol = v["tol"].as_f64().unwrap();
    // Bézier points of both segments (S^(7) by eq. 5).
    let segs = c.to_beziers().unwrap();
    let bez: Vec<f64> = segs
        .iter()
        .flat_map(|s| s.curve.points().to_vec())
        .collect();
    assert_close("001 bezier", &bez, &flat(&e["bezier_segments"]), 1e-13);
    let s7 = s_matrix(7).unwrap();
    let mut via_s = Vec::new();
    apply(s7, 8, &c.points()[..16], 2, &mut via_s);
    assert_close(
        "001 bezier by S^(7)",
        &via_s,
        &flat(&e["bezier_segments"][0]),
        tol,
    );

    let lossy = reduce_uniform_bspline(&c, 3, HERMITE, Merge::Lossy).unwrap();
    let red: Vec<f64> = lossy
        .segments
        .iter()
        .flat_map(|s| s.points().to_vec())
        .collect();
    assert_close("001 reduced", &red, &flat(&e["reduced_segments"]), tol);
    assert_close(
        "001 merged",
        lossy.curve.points(),
        &flat(&e["merged_ctrl"]),
        tol,
    );
    // Knots: the paper's 0..8 shifted by n - m = 4 (same domain as the input).
    let shifted: Vec<f64> = flat(&e["merged_knots"]).iter().map(|k| k + 4.0).collect();
    assert_eq!(lossy.curve.knots(), &shifted[..]);
    assert_eq!(lossy.curve.domain(), c.domain());
    // Local cubic points S^(3)^{-1} q per segment.
    let mats = matrices(HERMITE, 7, 3).unwrap();
    for s in 0..2 {
        let mut loc = Vec::new();
        apply(
            &mats.to_local,
            8,
            &c.points()[2 * s..2 * (s + 8)],
            2,
            &mut loc,
        );
        assert_close("001 local", &loc, &flat(&e["local_bspline"][s]), tol);
        // The paper's printed local points: only to its print noise (SPEC §8: 1.5e-4).
        let printed = flat(&e["printed_local_bspline"][s]);
        let d = loc
            .iter()
            .zip(&printed)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(d < 1.6e-4, "printed local points differ by {d}");
    }
    // The paper's printed reduced points: to 1.2e-5 (10.736496, 11.236519 are print noise).
    let printed = flat(&e["printed_reduced"]);
    let d = red
        .iter()
        .zip(&printed)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(
        d < 1.2e-5 && d > 1e-5,
        "printed reduced points differ by {d}"
    );

    // Measured errors (SPEC §8): reduction step max 1.30e-2, after the lossy merge 5.4e-2.
    let exact = reduce_uniform_bspline(&c, 3, HERMITE, Merge::Exact).unwrap();
    let step = spline_max_deviation(&c, &exact.curve).unwrap();
    assert!((step - 1.30e-2).abs() < 5e-4, "reduction step error {step}");
    assert!(step <= exact.error_bound && exact.segment_bound <= exact.error_bound);
    let merged = spline_max_deviation(&c, &lossy.curve).unwrap();
    assert!((merged - 5.4e-2).abs() < 5e-4, "lossy merge error {merged}");
    assert!(merged <= lossy.error_bound);
}

#[test]
fn exact_merge_is_c1_and_equals_the_segments() {
    let (_, c) = example();
    let r = reduce_uniform_bspline(&c, 3, HERMITE, Merge::Exact).unwrap();
    // C1 Hermite: multiplicity m - 1 = 2 at the interior knot.
    assert_eq!(
        r.curve.knots(),
        &[7.0, 7.0, 7.0, 7.0, 8.0, 8.0, 9.0, 9.0, 9.0, 9.0]
    );
    for (piece, seg) in r.curve.to_beziers().unwrap().iter().zip(&r.segments) {
        assert_close("exact merge", piece.curve.points(), seg.points(), 1e-12);
    }
}

#[test]
fn elevated_uniform_spline_reduces_back() {
    // A cubic polynomial written as a uniform degree-5 spline reduces to the same cubic.
    let cubic = |t: f64| [t * t * t - 2.0 * t, 0.5 * t * t + 1.0];
    // Its uniform degree-5 points: S^(5)^{-1} times its Bézier points on [5, 6].
    let b3: Vec<f64> = {
        // Bézier points of the cubic on [5, 6] = blossom values (t^3 - 2t, t^2/2 + 1).
        let bl = |a: f64, b: f64, c: f64| {
            [
                a * b * c - 2.0 * (a + b + c) / 3.0,
                0.5 * (a * b + b * c + a * c) / 3.0 + 1.0,
            ]
        };
        [
            bl(5.0, 5.0, 5.0),
            bl(5.0, 5.0, 6.0),
            bl(5.0, 6.0, 6.0),
            bl(6.0, 6.0, 6.0),
        ]
        .concat()
    };
    let b5 = BezierCurve::new(b3.clone(), 2).unwrap().elevate(2).unwrap();
    let sinv = cagd_core::s_matrix_inverse(5).unwrap();
    let mut p = Vec::new();
    apply(sinv, 6, b5.points(), 2, &mut p);
    let knots: Vec<f64> = (0..=11).map(f64::from).collect();
    let c = BSplineCurve::new(5, knots, p, 2).unwrap();
    assert!((c.eval(5.5).unwrap()[0] - cubic(5.5)[0]).abs() < 1e-12);
    for merge in [Merge::Exact, Merge::Lossy] {
        let r = reduce_uniform_bspline(&c, 3, Method::L2 { r: 1, p: 1 }, merge).unwrap();
        assert_close("reduce back", r.segments[0].points(), &b3, 1e-11);
        // Rounding only (the points are of size ~250).
        assert!(r.error_bound < 1e-9 * 250.0, "{merge:?}: {}", r.error_bound);
    }
}

#[test]
fn rational_and_errors() {
    let (_, c) = example();
    let w = vec![1.0, 2.0, 1.0, 0.5, 1.0, 1.5, 1.0, 1.0, 2.0];
    let knots: Vec<f64> = (0..=16).map(f64::from).collect();
    let r = BSplineCurve::new_rational(7, knots, c.points().to_vec(), w, 2).unwrap();
    for merge in [Merge::Exact, Merge::Lossy] {
        let red = reduce_uniform_bspline(&r, 4, Method::L2 { r: 1, p: 1 }, merge).unwrap();
        let d = spline_max_deviation(&r, &red.curve).unwrap();
        assert!(d <= red.error_bound, "{merge:?}: {d} > {}", red.error_bound);
    }
    assert!(matches!(
        reduce_uniform_bspline(&c, 3, Method::Eck, Merge::Exact),
        Err(Error::BadParameter { .. })
    ));
    assert!(reduce_uniform_bspline(&c, 3, Method::Eck, Merge::Lossy).is_ok());
    assert!(matches!(
        reduce_uniform_bspline(&c, 7, HERMITE, Merge::Lossy),
        Err(Error::BadDegreePair { .. })
    ));
    let clamped = BSplineCurve::new(
        3,
        vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
        vec![0.0, 1.0, 2.0, 3.0],
        1,
    )
    .unwrap();
    assert!(matches!(
        reduce_uniform_bspline(&clamped, 2, Method::Eck, Merge::Lossy),
        Err(Error::BadParameter { .. })
    ));
}

/// A one-span degree-4 plane curve on the knots `lo + i h` (computed in `f64`), with the
/// points of the C fuzz case that found a bound below the measured error.
fn one_span(lo: f64, h: f64) -> Result<BSplineCurve> {
    let knots: Vec<f64> = (0..10).map(|i| lo + f64::from(i) * h).collect();
    let pts = vec![0.3, -0.7, 0.9, 0.2, -0.4, 0.8, 0.1, -0.9, -0.6, 0.5];
    BSplineCurve::new(4, knots, pts, 2)
}

#[test]
fn a_spacing_of_a_few_ulps_is_not_uniform() {
    // The fuzz case (seed 112): a domain ~8 ulps wide at 0.19; its knots, rounded, have
    // gaps of 7 to 9 ulps, which the old check (1e-12 of the knots' size) called uniform,
    // and the reduction to a line reported a bound 7x below the measured error.
    let c = one_span(0.193_378_843_759_196, 2.2e-16).unwrap();
    for merge in [Merge::Exact, Merge::Lossy] {
        let r = reduce_uniform_bspline(&c, 1, Method::L2 { r: 0, p: 0 }, merge);
        assert!(
            matches!(r, Err(Error::BadParameter { name: "knots", .. })),
            "{merge:?}: {r:?}"
        );
    }
    // Gaps 1e-9 apart at knots of size 1000 (spacing 1e-6): not uniform either (the old
    // check accepted 1e-3 of the spacing there).
    let mut knots: Vec<f64> = (0..10).map(|i| 1000.0 + f64::from(i) * 1e-6).collect();
    knots[5] += 5e-10;
    let c = BSplineCurve::new(4, knots, one_span(0.0, 1.0).unwrap().points().to_vec(), 2).unwrap();
    assert!(matches!(
        reduce_uniform_bspline(&c, 2, Method::Eck, Merge::Lossy),
        Err(Error::BadParameter { name: "knots", .. })
    ));
}

#[test]
fn rounded_uniform_knots_far_from_zero_keep_true_bounds() {
    // Uniform knots rounded to f64 (gaps equal only within a few ulps of 1000) are
    // accepted; the output has the input's own knots, and every bound holds against the
    // actual (slightly non-uniform) input.
    for (lo, h) in [(1000.0, 0.1), (1000.0, 1e-3), (-37.25, 0.01), (0.0, 1.0)] {
        let c = one_span(lo, h).unwrap();
        for (m, method) in [
            (1, Method::L2 { r: 0, p: 0 }),
            (2, Method::Eck),
            (3, Method::L2 { r: 1, p: 1 }),
        ] {
            for merge in [Merge::Exact, Merge::Lossy] {
                let Ok(r) = reduce_uniform_bspline(&c, m, method, merge) else {
                    assert_eq!(merge, Merge::Exact, "{lo} {h} {method:?}");
                    continue;
                };
                assert_eq!(
                    r.curve.domain(),
                    c.domain(),
                    "{lo} {h} {method:?} {merge:?}"
                );
                let d = spline_max_deviation(&c, &r.curve).unwrap();
                assert!(
                    d <= r.error_bound,
                    "{lo} {h} {method:?} {merge:?}: {d} > {}",
                    r.error_bound
                );
                assert!(
                    r.error_bound <= 1.5 * d + 1e-9,
                    "{lo} {h} {method:?} {merge:?}: {d} vs {}",
                    r.error_bound
                );
            }
        }
    }
}

/// The C ABI fuzz input of seed 121: a 2-D uniform quartic spline (12 knots at spacing 0.5)
/// with one coordinate `big`, the others `sin(0.37 i)`.
fn fuzz_121(big: f64, weights: Option<Vec<f64>>) -> BSplineCurve {
    let knots: Vec<f64> = (0..13).map(|i| 17.0 + 0.5 * f64::from(i)).collect();
    let mut pts: Vec<f64> = (0..16).map(|i| (f64::from(i) * 0.37).sin()).collect();
    pts[7] = big;
    match weights {
        Some(w) => BSplineCurve::new_rational(4, knots, pts, w, 2).expect("curve"),
        None => BSplineCurve::new(4, knots, pts, 2).expect("curve"),
    }
}

/// `c` with its control points multiplied by `s` (a power of two: exact here).
fn times(c: &BSplineCurve, s: f64) -> BSplineCurve {
    let pts: Vec<f64> = c.points().iter().map(|x| x * s).collect();
    match c.weights() {
        Some(w) => {
            BSplineCurve::new_rational(c.degree(), c.knots().to_vec(), pts, w.to_vec(), c.dim())
        }
        None => BSplineCurve::new(c.degree(), c.knots().to_vec(), pts, c.dim()),
    }
    .expect("scaled curve")
}

#[test]
fn coordinates_near_1e300_are_reduced_in_a_scaled_frame() {
    // The fuzz input of seed 121 (coordinate 1e300) used to be refused by both merges (its
    // certified bound overflowed). Now reduced, with finite bounds that hold: against a
    // dense measurement in model units and in a frame scaled by 2^-900 (exact), and the
    // result is the reduction of the curve scaled by 2^-900 (where no square overflows, the
    // unscaled route) scaled back, bit for bit.
    let k = 2f64.powi(-900);
    let weights = vec![1.0, 0.5, 2.0, 1.5, 1.0, 0.75, 1.25, 1.0];
    for rational in [false, true] {
        let c = fuzz_121(1e300, rational.then(|| weights.clone()));
        let small = times(&c, k);
        for merge in [Merge::Lossy, Merge::Exact] {
            let what = format!("rational {rational} {merge:?}");
            let r = reduce_uniform_bspline(&c, 3, Method::L2 { r: 0, p: 0 }, merge)
                .unwrap_or_else(|e| panic!("{what}: {e}"));
            assert!(
                r.segment_bound.is_finite() && r.error_bound.is_finite(),
                "{what}"
            );
            assert!(r.segment_bound <= r.error_bound, "{what}");
            let d = spline_max_deviation(&c, &r.curve).unwrap();
            assert!(
                d > 1e280 && d <= r.error_bound,
                "{what}: {d:e} {:e}",
                r.error_bound
            );
            let d_small = spline_max_deviation(&small, &times(&r.curve, k)).unwrap();
            assert!(d_small <= r.error_bound * k, "{what}: {d_small:e}");
            let direct = reduce_uniform_bspline(&small, 3, Method::L2 { r: 0, p: 0 }, merge)
                .unwrap_or_else(|e| panic!("{what}: scaled input {e}"));
            assert_eq!(times(&direct.curve, 1.0 / k), r.curve, "{what}: curve");
            for (a, b) in direct.segments.iter().zip(&r.segments) {
                let back: Vec<f64> = a.points().iter().map(|x| x / k).collect();
                assert_eq!(back, b.points(), "{what}: segment");
            }
            // The bounds are those of the scaled frame up to its rounding allowances (a
            // few ulps of the result's size).
            let rel = (r.error_bound / (direct.error_bound / k) - 1.0).abs();
            assert!(
                rel < 1e-6,
                "{what}: {:e} vs {:e}",
                r.error_bound,
                direct.error_bound / k
            );
        }
    }
}

#[test]
fn coordinates_near_1e_minus_300_are_reduced_in_a_scaled_frame() {
    // Tiny coordinates (their bounds' squares would underflow): reduced in the frame scaled
    // by a power of two; the bound holds against a measurement in a frame scaled by 2^900
    // (exact), where the rounding of the result's subnormal coordinates is small.
    let k = 2f64.powi(900);
    let c = times(&fuzz_121(0.5, None), 2f64.powi(-990));
    for merge in [Merge::Lossy, Merge::Exact] {
        let r = reduce_uniform_bspline(&c, 3, Method::L2 { r: 0, p: 0 }, merge)
            .unwrap_or_else(|e| panic!("{merge:?}: {e}"));
        assert!(
            r.error_bound > 0.0 && r.error_bound.is_finite(),
            "{merge:?}"
        );
        let d = spline_max_deviation(&times(&c, k), &times(&r.curve, k)).unwrap();
        assert!(
            d <= r.error_bound * k,
            "{merge:?}: {d:e} {:e}",
            r.error_bound * k
        );
        assert!(
            d > 0.25 * r.error_bound * k,
            "{merge:?}: a bound {:e} far above {d:e}",
            r.error_bound * k
        );
    }
}

#[test]
fn only_a_bound_or_result_that_overflows_in_model_units_is_refused() {
    // Control points alternating in pairs at +-DBL_MAX: in 2-D the reduction's error is
    // about 0.3 DBL_MAX, so the curve is reduced, with a finite bound that holds.
    let pattern = |dim: usize| -> BSplineCurve {
        let knots: Vec<f64> = (0..13).map(f64::from).collect();
        let pts: Vec<f64> = (0..8 * dim)
            .map(|i| {
                if (i / dim) % 4 < 2 {
                    f64::MAX
                } else {
                    -f64::MAX
                }
            })
            .collect();
        BSplineCurve::new(4, knots, pts, dim).expect("curve")
    };
    let c = pattern(2);
    for merge in [Merge::Lossy, Merge::Exact] {
        let r = reduce_uniform_bspline(&c, 1, Method::L2 { r: 0, p: 0 }, merge)
            .unwrap_or_else(|e| panic!("{merge:?}: {e}"));
        let d = spline_max_deviation(&c, &r.curve).unwrap();
        assert!(
            r.error_bound.is_finite() && d <= r.error_bound,
            "{merge:?}: {d:e}"
        );
    }
    // In 32 dimensions the same error has a Euclidean norm beyond DBL_MAX: no finite
    // certified bound exists in model units, and the curve is refused.
    let c = pattern(32);
    for merge in [Merge::Lossy, Merge::Exact] {
        let r = reduce_uniform_bspline(&c, 1, Method::L2 { r: 0, p: 0 }, merge);
        assert!(
            matches!(r, Err(Error::BadParameter { name: "points", .. })),
            "{merge:?}: {r:?}"
        );
    }
}
