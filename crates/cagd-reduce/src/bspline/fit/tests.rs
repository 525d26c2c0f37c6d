//! Tests of the global fit: the residual is orthogonal to the spline space (the defining
//! property of the L2-best fit, checked by an independent quadrature), a spline of the
//! target space is reproduced, span bounds cover sampled errors, unclamped input.

use super::*;
use crate::bspline::test_support::residual_inner_products;

/// A clamped degree-5 planar spline with uneven spans and a double knot.
fn quintic() -> BSplineCurve {
    let knots = vec![
        0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.1, 0.35, 0.35, 0.6, 0.8, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0,
    ];
    let n = knots.len() - 6;
    let pts: Vec<f64> = (0..2 * n)
        .map(|i| ((i * 37 % 11) as f64 - 5.0) / 2.0)
        .collect();
    BSplineCurve::new(5, knots, pts, 2).unwrap()
}

/// Cubic knots: the quintic's breaks (simple) plus an extra knot at 0.2.
fn cubic_knots() -> Vec<f64> {
    vec![
        0.0, 0.0, 0.0, 0.0, 0.1, 0.2, 0.35, 0.6, 0.8, 1.0, 1.0, 1.0, 1.0,
    ]
}

#[test]
fn residual_is_orthogonal_to_the_spline_space() {
    let c = quintic();
    let src = Source::new(&c, 2, false).unwrap();
    let knots = cubic_knots();
    let pts = fit(&src, 3, &knots).unwrap();
    let s = BSplineCurve::new(3, knots.clone(), pts, 2).unwrap();
    let n = knots.len() - 4;
    // Composite Simpson with 4 000 panels per knot span (independent of the Gauss rule;
    // the quintic's breaks are knots of the cubic).
    let inner = residual_inner_products(&c, &s, &knots, 4000);
    // The end points are fixed, so only the interior functions are orthogonal.
    for (j, v) in inner.iter().enumerate().take(n - 1).skip(1) {
        assert!(v[0].abs() < 1e-11 && v[1].abs() < 1e-11, "N_{j}: {v:?}");
    }
    // ... and the fixed ends do carry a residual (the test can tell the difference).
    assert!(inner[0][0].abs() + inner[0][1].abs() > 1e-8);
}

#[test]
fn reproduces_a_spline_of_the_target_space_and_bounds_cover_samples() {
    // A cubic written as a quintic (each piece elevated; merged C0 is enough here).
    let knots = cubic_knots();
    let n = knots.len() - 4;
    let pts: Vec<f64> = (0..2 * n).map(|i| (i as f64 * 0.7).sin()).collect();
    let cubic = BSplineCurve::new(3, knots.clone(), pts.clone(), 2).unwrap();
    let pieces = cubic.to_beziers().unwrap();
    let mut breaks: Vec<f64> = pieces.iter().map(|x| x.start).collect();
    breaks.push(1.0);
    let segs: Vec<_> = pieces.iter().map(|x| x.curve.elevate(2).unwrap()).collect();
    let elevated = BSplineCurve::from_beziers(&segs, &breaks, 0, 1e-12).unwrap();
    let src = Source::new(&elevated, 2, false).unwrap();
    let got = fit(&src, 3, &knots).unwrap();
    for (a, b) in got.iter().zip(&pts) {
        assert!((a - b).abs() < 1e-13, "{a} vs {b}");
    }
    // A genuine fit: every span's certified bound covers the sampled error on the span.
    let c = quintic();
    let src = Source::new(&c, 2, false).unwrap();
    let fitted = fit(&src, 3, &knots).unwrap();
    let s = BSplineCurve::new(3, knots.clone(), fitted.clone(), 2).unwrap();
    for sb in span_bounds(&src, 3, (&knots, &fitted), f64::INFINITY, &mut Vec::new()).unwrap() {
        let mut worst: f64 = 0.0;
        for i in 0..=200 {
            let t = sb.a + (sb.b - sb.a) * f64::from(i) / 200.0;
            let (p, q) = (c.eval(t).unwrap(), s.eval(t).unwrap());
            worst = worst.max(((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt());
        }
        assert!(
            worst <= sb.bound,
            "[{}, {}]: {worst} > {}",
            sb.a,
            sb.b,
            sb.bound
        );
        assert!(
            sb.bound <= 1.5 * worst + 1e-12,
            "loose: {} vs {worst}",
            sb.bound
        );
        assert!(sb.floor < 1e-13);
    }
}

/// Restrictions kept or made again per use (past the memory cap): the same fit and the
/// same bounds, bit for bit.
#[test]
fn restrictions_kept_or_not_give_the_same_fit() {
    let c = quintic();
    let src = Source::new(&c, 2, false).unwrap();
    let knots = cubic_knots();
    let (mut kept, mut made) = (SpanData::default(), SpanData::default());
    kept.fill(&src, 3, &knots);
    made.fill_keeping(&src, 3, &knots, 0);
    assert!(kept.stored && !made.stored);
    let a = fit_restricted(&src, 3, &knots, &kept).unwrap();
    let b = fit_restricted(&src, 3, &knots, &made).unwrap();
    assert_eq!(a, b);
    let ba = span_bounds_restricted(&src, 3, (&knots, &a, &kept), 0.0, &mut Vec::new()).unwrap();
    let bb = span_bounds_restricted(&src, 3, (&knots, &b, &made), 0.0, &mut Vec::new()).unwrap();
    assert_eq!(ba, bb);
    assert_eq!(ba.len(), 6);
}

/// The shared-chain extraction ([`span_bezier_of`]) against one de Boor run per point
/// ([`span_bezier_of_runs`], the route it replaced): bitwise the same points at degrees
/// 1–8 (and the runs themselves above), 1–5 coordinates, simple and multiple knots, whole
/// spans and cells inside them; its end points are the spline's values (`eval`).
#[test]
fn the_shared_chain_extraction_is_the_per_point_runs() {
    use cagd_testkit::bench::random_input;
    let mut seed = 40;
    for m in 1..=10usize {
        for d in 1..=5usize {
            seed += 1;
            let r = random_input(64 + 40 * d, seed);
            // Clamped knots on [0, 1] with a knot of multiplicity m - 1 (at least 1).
            let mut knots = vec![0.0; m + 1];
            let mut t = 0.0;
            for (i, x) in r.iter().take(5).enumerate() {
                t += 0.1 + 0.2 * x.abs();
                let mult = if i == 2 { (m - 1).max(1) } else { 1 };
                knots.extend(std::iter::repeat_n(t, mult));
            }
            let end = t + 0.3;
            knots.extend(std::iter::repeat_n(end, m + 1));
            let n = knots.len() - m - 1;
            let pts: Vec<f64> = r[8..8 + n * d].iter().map(|x| 10.0 * x).collect();
            let c = BSplineCurve::new(m, knots.clone(), pts.clone(), d).unwrap();
            for s in m..n {
                let (ka, kb) = (knots[s], knots[s + 1]);
                if ka >= kb {
                    continue;
                }
                for (a, b) in [(ka, kb), (ka + 0.3 * (kb - ka), ka + 0.8 * (kb - ka))] {
                    let local = &pts[(s - m) * d..(s + 1) * d];
                    let (mut x, mut y) = (vec![0.0; (m + 1) * d], vec![0.0; (m + 1) * d]);
                    let mut work = vec![0.0; 2 * (m + 1) * d];
                    span_bezier_of((&knots, m), s, (a, b), (local, d), &mut x, &mut work);
                    span_bezier_of_runs((&knots, m), s, (a, b), (local, d), &mut y, &mut work);
                    let bits = |v: &[f64]| v.iter().map(|z| z.to_bits()).collect::<Vec<_>>();
                    assert_eq!(bits(&x), bits(&y), "m {m} d {d} span {s} [{a}, {b}]");
                    for (u, at) in [(a, 0), (b, m)] {
                        let v = c.eval(u).unwrap();
                        for (e, z) in v.iter().zip(&x[at * d..(at + 1) * d]) {
                            assert!((e - z).abs() <= 1e-12 * 10.0, "m {m} end {u}: {e} vs {z}");
                        }
                    }
                }
            }
        }
    }
}
