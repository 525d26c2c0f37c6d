//! Tests of the rational to polynomial curve conversion: circles (exact radial error and
//! parametric distance sampled independently by de Boor), a cubic-fit baseline for the span
//! counts, the exact case, continuity, random NURBS, bad input.

use cagd_core::{BSplineCurve, BezierCurve, Error, knot_multiplicity};
use proptest::prelude::*;

use super::*;

const H: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// A unit circle arc of `quarters` quarter arcs (rational quadratic, double knots), centred
/// at `(cx, cy)`.
fn circle(quarters: usize, (cx, cy): (f64, f64)) -> BSplineCurve {
    let corners = [
        (1.0, 0.0),
        (1.0, 1.0),
        (0.0, 1.0),
        (-1.0, 1.0),
        (-1.0, 0.0),
        (-1.0, -1.0),
        (0.0, -1.0),
        (1.0, -1.0),
        (1.0, 0.0),
    ];
    let n = 2 * quarters + 1;
    let pts: Vec<f64> = corners[..n]
        .iter()
        .flat_map(|&(x, y)| [x + cx, y + cy])
        .collect();
    let w: Vec<f64> = (0..n).map(|i| if i % 2 == 1 { H } else { 1.0 }).collect();
    let mut knots = vec![0.0; 3];
    for k in 1..quarters {
        let t = k as f64 / quarters as f64;
        knots.extend([t, t]);
    }
    knots.extend([1.0; 3]);
    BSplineCurve::new_rational(2, knots, pts, w, 2).unwrap()
}

/// The same arc on a sub-domain with an unclamped knot vector: knot `a` and `b` inserted
/// once, then the first and last point and knot dropped (the basis functions left keep
/// their knots, so the curve on `[a, b]` is unchanged; the end knots are not repeated).
fn unclamped(c: &BSplineCurve, a: f64, b: f64) -> BSplineCurve {
    let r = c.insert_knot(a, 1).unwrap().insert_knot(b, 1).unwrap();
    let (d, n) = (r.dim(), r.n_points());
    let k = r.knots()[1..r.knots().len() - 1].to_vec();
    let pts = r.points()[d..(n - 1) * d].to_vec();
    let w = r.weights().unwrap()[1..n - 1].to_vec();
    let out = BSplineCurve::new_rational(2, k, pts, w, d).unwrap();
    assert_eq!(out.domain(), (a, b));
    assert!(out.knots()[0] < out.knots()[2], "not unclamped");
    for i in 0..=20 {
        let t = a + (b - a) * f64::from(i) / 20.0;
        let (x, y) = (out.eval(t).unwrap(), c.eval(t).unwrap());
        assert!((x[0] - y[0]).abs() + (x[1] - y[1]).abs() < 1e-14);
    }
    out
}

/// `(parametric, radial)`: `max ||C(t) - S(t)||` and, for a circle of centre `centre` and
/// radius 1, `max | ||S(t) - centre|| - 1 |`, sampled at 400 parameters per span of the
/// union of both knot vectors, both curves evaluated by de Boor (not by the Bézier route
/// of the bound).
fn sampled(c: &BSplineCurve, s: &BSplineCurve, centre: Option<(f64, f64)>) -> (f64, f64) {
    let mut cuts: Vec<f64> = c.knots().iter().chain(s.knots()).copied().collect();
    let (a, b) = c.domain();
    cuts.retain(|t| *t >= a && *t <= b);
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let (mut par, mut rad): (f64, f64) = (0.0, 0.0);
    for w in cuts.windows(2) {
        for i in 0..=400 {
            let t = w[0] + (w[1] - w[0]) * f64::from(i) / 400.0;
            let (x, y) = (c.eval(t).unwrap(), s.eval(t).unwrap());
            let d: f64 = x.iter().zip(&y).map(|(p, q)| (p - q) * (p - q)).sum();
            par = par.max(d.sqrt());
            if let Some((cx, cy)) = centre {
                rad = rad.max(((y[0] - cx).hypot(y[1] - cy) - 1.0).abs());
            }
        }
    }
    (par, rad)
}

/// Position and derivative of a rational Bézier piece on `[a, b]` at local `s`.
fn pos_der(seg: &BezierCurve, (a, b): (f64, f64), s: f64) -> (Vec<f64>, Vec<f64>) {
    let (d, n) = (seg.dim(), seg.degree());
    let hom = seg.homogeneous_points();
    let hod: Vec<f64> = (0..n)
        .flat_map(|i| (0..=d).map(move |k| (i, k)))
        .map(|(i, k)| n as f64 * (hom[(i + 1) * (d + 1) + k] - hom[i * (d + 1) + k]) / (b - a))
        .collect();
    let h = BezierCurve::new(hom, d + 1).unwrap().eval(s);
    let dh = BezierCurve::new(hod, d + 1).unwrap().eval(s);
    let c: Vec<f64> = h[..d].iter().map(|x| x / h[d]).collect();
    let dc = (0..d).map(|k| (dh[k] - dh[d] * c[k]) / h[d]).collect();
    (c, dc)
}

/// The plain cubic approach the spans are compared with: every rational piece split into
/// `k` equal parts, each replaced by the cubic Hermite interpolant of `C` (position and
/// first derivative at both ends, `C^1`), `k` the smallest with a *sampled* error within
/// `tol` (sampling underestimates the error: the comparison favours the baseline).
fn hermite_cubic_spans(c: &BSplineCurve, tol: f64) -> usize {
    let mut total = 0;
    for seg in c.to_beziers().unwrap() {
        let (a, b) = (seg.start, seg.end);
        let k = (1..=4096)
            .find(|&k| {
                (0..k).all(|j| {
                    let (s0, s1) = (j as f64 / k as f64, (j + 1) as f64 / k as f64);
                    let h = (b - a) * (s1 - s0);
                    let (p0, d0) = pos_der(&seg.curve, (a, b), s0);
                    let (p1, d1) = pos_der(&seg.curve, (a, b), s1);
                    let ctrl: Vec<f64> = (0..c.dim())
                        .flat_map(|x| {
                            [
                                p0[x],
                                p0[x] + h / 3.0 * d0[x],
                                p1[x] - h / 3.0 * d1[x],
                                p1[x],
                            ]
                        })
                        .collect();
                    // ctrl is coordinate-major; reorder to point-major.
                    let pts: Vec<f64> = (0..4)
                        .flat_map(|i| (0..c.dim()).map(move |x| (i, x)))
                        .map(|(i, x)| ctrl[x * 4 + i])
                        .collect();
                    let cub = BezierCurve::new(pts, c.dim()).unwrap();
                    (0..=100).all(|i| {
                        let u = f64::from(i) / 100.0;
                        let (x, _) = pos_der(&seg.curve, (a, b), s0 + (s1 - s0) * u);
                        let y = cub.eval(u);
                        x.iter()
                            .zip(&y)
                            .map(|(p, q)| (p - q) * (p - q))
                            .sum::<f64>()
                            .sqrt()
                            <= tol
                    })
                })
            })
            .unwrap();
        total += k;
    }
    total
}

/// Checks the laws of one conversion and returns it: bound within the tolerance, never
/// below the sampled parametric distance (nor the radial error for a circle), the report's
/// measured error below the bound, no weights, the domain kept, and the continuity at
/// every interior break of the input (structural: multiplicity `<= m - k` in the result).
fn check(
    c: &BSplineCurve,
    m: Option<usize>,
    tol: f64,
    centre: Option<(f64, f64)>,
) -> PolynomialReduction {
    let r = rational_to_polynomial(c, m, tol).unwrap();
    let s = &r.curve;
    assert!(!s.is_rational());
    assert!(s.degree() <= m.unwrap_or(c.degree()));
    assert_eq!(s.domain(), c.domain());
    let (par, rad) = sampled(c, s, centre);
    let b = r.report.error_bound;
    assert!(b <= tol, "bound {b} above {tol}");
    assert!(par <= b, "sampled {par} above the bound {b}");
    assert!(
        rad <= par * (1.0 + 1e-9) + 1e-15,
        "radial {rad} above parametric {par}"
    );
    assert!(r.report.max_error <= b, "{} > {b}", r.report.max_error);
    for &(t, k) in &r.report.continuity {
        let mult = knot_multiplicity(s.knots(), t);
        assert!(
            mult + k <= s.degree(),
            "at {t}: multiplicity {mult}, C^{k} promised"
        );
        let s_in = knot_multiplicity(c.knots(), t);
        assert_eq!(k, (c.degree() - s_in).min(s.degree() - 1));
    }
    r
}

/// Circles at 1e-3 and 1e-5, m = 2 and 3: the laws, and for cubics no more spans than the
/// Hermite baseline. The counts are printed (`--nocapture`) for the report.
#[test]
fn circles_within_tolerance_and_no_more_spans_than_a_cubic_fit() {
    let arcs = [
        ("quarter", circle(1, (0.0, 0.0)), (0.0, 0.0)),
        ("half", circle(2, (3.0, -2.0)), (3.0, -2.0)),
        ("full", circle(4, (100.0, 50.0)), (100.0, 50.0)),
        (
            "unclamped-arc",
            unclamped(&circle(4, (0.0, 0.0)), 0.1, 0.8),
            (0.0, 0.0),
        ),
        (
            "unclamped-quarter",
            unclamped(&circle(1, (0.0, 0.0)), 0.2, 0.7),
            (0.0, 0.0),
        ),
    ];
    for (name, c, centre) in &arcs {
        for tol in [1e-3, 1e-5] {
            let base = hermite_cubic_spans(c, tol);
            for m in [2, 3] {
                let r = check(c, Some(m), tol, Some(*centre));
                eprintln!(
                    "{name} tol {tol:e} m {m}: spans {} -> {} (fit {}), bound {:.3e}, measured {:.3e}; hermite cubic {base}",
                    r.spans_in,
                    r.spans_out,
                    r.report.pieces,
                    r.report.error_bound,
                    r.report.max_error
                );
                if m == 3 {
                    assert!(
                        r.spans_out <= base,
                        "{name} {tol}: {} > {base}",
                        r.spans_out
                    );
                }
            }
        }
    }
}

/// A cubic rational (a quarter circle elevated, plus a genuinely cubic rational curve) to
/// degree 3 (`--to 3` on a cubic) and to degree 2 (reduction and weights dropped at once).
#[test]
fn cubic_rational_to_cubic_and_to_quadratic() {
    let q = BezierCurve::new_rational(vec![1.0, 0.0, 1.0, 1.0, 0.0, 1.0], vec![1.0, H, 1.0], 2)
        .unwrap();
    let e = q.elevate(1).unwrap();
    let c = BSplineCurve::new_rational(
        3,
        vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
        e.points().to_vec(),
        e.weights().unwrap().to_vec(),
        2,
    )
    .unwrap();
    for tol in [1e-3, 1e-5] {
        check(&c, None, tol, Some((0.0, 0.0)));
        check(&c, Some(2), tol, Some((0.0, 0.0)));
    }
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0];
    let pts = vec![
        0.0, 0.0, 0.0, 1.0, 2.0, 0.5, 2.0, 3.0, -1.0, 3.5, 1.0, 2.0, 4.0, 0.0, 1.0, 5.0, 2.0, 0.0,
        6.0, 1.0, 1.0,
    ];
    let c = BSplineCurve::new_rational(3, knots, pts, vec![1.0, 3.0, 0.5, 2.0, 1.0, 4.0, 1.0], 3)
        .unwrap();
    for tol in [1e-3, 1e-5] {
        let r = check(&c, None, tol, None);
        // The knot 0.5 (double, C^1) is kept with C^1, 0.3 with C^2.
        assert_eq!(r.report.continuity, vec![(0.3, 2), (0.5, 1)]);
        check(&c, Some(2), tol, None);
    }
}

/// Equal weights (any common factor): exactly the polynomial spline, same knots, no spans
/// added, bound at rounding level; also with no weights, and unclamped. `m < p` reduces it.
#[test]
fn equal_weights_are_exact() {
    let knots = vec![-1.0, -0.5, 0.0, 0.2, 0.7, 1.0, 1.5, 2.0];
    let pts = vec![0.0, 0.0, 1.0, 2.0, 2.0, -1.0, 3.0, 2.0, 4.0, 0.0];
    let c = BSplineCurve::new_rational(2, knots.clone(), pts.clone(), vec![2.5; 5], 2).unwrap();
    for m in [None, Some(2), Some(5)] {
        let r = rational_to_polynomial(&c, m, 1e-9).unwrap();
        assert!(r.report.equal_weights);
        assert_eq!(
            r.curve,
            BSplineCurve::new(2, knots.clone(), pts.clone(), 2).unwrap()
        );
        assert_eq!((r.spans_in, r.spans_out), (3, 3));
        // The bound is the evaluation rounding only, and never below a measurement (it was
        // 0 beside a measured 5.7e-17 in the C ABI fuzz run).
        assert!(r.report.error_bound < 1e-13 && r.report.max_error <= r.report.error_bound);
        assert!(r.report.max_error < 1e-14);
    }
    let poly = BSplineCurve::new(2, knots.clone(), pts.clone(), 2).unwrap();
    assert_eq!(
        rational_to_polynomial(&poly, None, 1e-3).unwrap().curve,
        poly
    );
    let r = rational_to_polynomial(&c, Some(1), 1e-2).unwrap();
    assert!(r.report.equal_weights && r.curve.degree() == 1 && !r.curve.is_rational());
    assert!(r.report.max_error <= r.report.error_bound && r.report.error_bound <= 1e-2);
}

/// The bound does not depend on where the model sits (centred) beyond the rounding
/// allowance, which grows with the coordinates' size (`~ 100 eps |x|` here).
#[test]
fn bound_is_translation_consistent() {
    let a = rational_to_polynomial(&circle(2, (0.0, 0.0)), Some(3), 1e-4).unwrap();
    let b = rational_to_polynomial(&circle(2, (1e4, -3e4)), Some(3), 1e-4).unwrap();
    assert_eq!(a.spans_out, b.spans_out);
    let diff = (a.report.error_bound - b.report.error_bound).abs();
    assert!(
        diff < 200.0 * f64::EPSILON * 3e4 * 4.0,
        "{} vs {}",
        a.report.error_bound,
        b.report.error_bound
    );
}

#[test]
fn bad_input_is_a_named_error() {
    let c = circle(2, (0.0, 0.0));
    for tol in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            rational_to_polynomial(&c, None, tol),
            Err(Error::BadTolerance { .. })
        ));
    }
    for m in [0, 65] {
        assert!(matches!(
            rational_to_polynomial(&c, Some(m), 1e-3),
            Err(Error::BadDegreePair { .. })
        ));
    }
    // An interior knot of multiplicity p + 1 (the curve may jump there).
    let k = vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0];
    let pts = vec![0.0, 0.0, 1.0, 1.0, 2.0, 0.0, 3.0, 1.0, 4.0, 0.0, 5.0, 1.0];
    let j = BSplineCurve::new_rational(2, k, pts, vec![1.0, 2.0, 1.0, 1.0, 3.0, 1.0], 2).unwrap();
    assert!(matches!(
        rational_to_polynomial(&j, None, 1e-3),
        Err(Error::BadParameter { .. })
    ));
    // A tolerance below the rounding level.
    assert!(matches!(
        rational_to_polynomial(&c, None, 1e-300),
        Err(Error::ConditionNotMet { .. })
    ));
}

fn random_nurbs() -> impl Strategy<Value = (BSplineCurve, usize, f64)> {
    (
        1usize..=5,
        0usize..=4,
        1usize..=3,
        1usize..=5,
        prop_oneof![Just(1e-3), Just(1e-5)],
    )
        .prop_flat_map(|(p, extra, dim, m, tol)| {
            let n = p + 1 + extra;
            (
                cagd_testkit::clamped_knots(n, p),
                cagd_testkit::points(n, dim),
                cagd_testkit::weights(n),
                Just((p, dim, m, tol)),
            )
        })
        .prop_map(|(k, pts, w, (p, dim, m, tol))| {
            (
                BSplineCurve::new_rational(p, k, pts, w, dim).unwrap(),
                m,
                tol,
            )
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Random NURBS (degree 1–5, weights 0.2..5) to random degrees 1–5 at 1e-3 / 1e-5:
    /// the laws of `check` (bound within the tolerance, never below the sampled distance,
    /// continuity kept).
    #[test]
    fn random_nurbs_laws((c, m, tol) in random_nurbs()) {
        check(&c, Some(m), tol, None);
    }
}

/// A smooth rational cubic with many more spans than the tolerance needs (a spiral, 60
/// simple knots, smoothly varying weights): fewer spans out than in, the laws of `check`
/// (the spans of the coarse start cross input knots, so their bounds are the largest over
/// the input pieces they meet).
#[test]
fn many_span_spiral_gets_fewer_spans() {
    let n = 63;
    let mut knots = vec![0.0; 4];
    knots.extend((1..60).map(|i| f64::from(i) / 60.0));
    knots.extend([1.0; 4]);
    let pts: Vec<f64> = (0..n)
        .flat_map(|i| {
            let (a, r) = (f64::from(i) * 0.1, 1.0 + 0.01 * f64::from(i));
            [r * a.cos(), r * a.sin(), 0.05 * f64::from(i)]
        })
        .collect();
    let w: Vec<f64> = (0..n)
        .map(|i| 1.0 + 0.5 * (0.37 * f64::from(i)).sin())
        .collect();
    let c = BSplineCurve::new_rational(3, knots, pts, w, 3).unwrap();
    for tol in [1e-3, 1e-5] {
        for m in [2, 3] {
            let r = check(&c, Some(m), tol, None);
            eprintln!("spiral tol {tol:e} m {m}: spans 60 -> {}", r.spans_out);
            if tol == 1e-3 {
                assert!(r.spans_out < 60, "{}", r.spans_out);
            }
        }
    }
}

/// Equal weights and a coordinate of 1e300 (C ABI fuzz run): the rounding bound was
/// `8 (p + 2) eps sqrt(sum x^2)` with an overflowing square, so `+inf` with `Ok`. It is
/// finite now and still at least the measurement; a tolerance below it (the rounding level
/// of the curve) is refused, as for any other input, so a success means `bound <= tol`.
#[test]
fn equal_weights_with_huge_coordinates_give_a_finite_bound() {
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.0, 1.5, 3.0, 3.0, 3.0, 3.0, 3.0];
    let pts = vec![-0.372, -0.0826, 0.1236, 1e300, -0.346, 0.00883];
    let c = BSplineCurve::new_rational(4, knots, pts, vec![1.0; 6], 1).unwrap();
    assert!(matches!(
        rational_to_polynomial(&c, None, 5.1e-7),
        Err(Error::ConditionNotMet { .. })
    ));
    // Above the rounding level of the largest point: the same curve.
    let tol = 1e-12 * 1e300;
    let r = rational_to_polynomial(&c, None, tol).unwrap();
    assert!(r.report.equal_weights);
    for b in [r.report.error_bound, r.report.segment_bound] {
        assert!(
            b.is_finite() && b >= r.report.max_error && b <= tol,
            "{b:e} vs {:e}",
            r.report.max_error
        );
    }
    assert_eq!(r.curve.points(), c.points());
}

#[test]
fn equal_weights_with_a_point_norm_above_the_largest_double_give_a_finite_bound() {
    // C ABI fuzz (seed 115): a point at (-1.7e308, -1.7e308), whose norm overflows; the
    // bound was `+inf` with success.
    let knots = vec![
        0.0,
        0.0,
        0.375_567_289_332_096_7,
        0.892_253_525_870_262_7,
        1.275,
        1.275,
    ];
    let pts = vec![
        -1.726_876_898_925_010_6e308,
        -1.726_876_898_925_010_6e308,
        100.0,
        1e-8,
        -72.36,
        -1.741e16,
    ];
    let c = BSplineCurve::new_rational(2, knots, pts, vec![1.0; 3], 2).unwrap();
    // Below the rounding level of those points: refused (was success with `+inf`).
    assert!(matches!(
        rational_to_polynomial(&c, None, 1.3e-6),
        Err(Error::ConditionNotMet { .. })
    ));
    let r = rational_to_polynomial(&c, None, 1e296).unwrap();
    for b in [r.report.error_bound, r.report.segment_bound] {
        assert!(
            b.is_finite() && b >= r.report.max_error && b <= 1e296,
            "{b:e} vs {:e}",
            r.report.max_error
        );
    }
}
