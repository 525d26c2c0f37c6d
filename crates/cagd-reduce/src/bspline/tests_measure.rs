//! Tests of the measurement with what the caller knows (`measure.rs`,
//! [`spline_max_deviation_known`]): the global fit's report measures with its span bounds
//! as caps and its source's pieces, and must give the measurement without them; caps
//! below the error must be able to change the result (the pruning is real), the cached
//! sample tables must be the fresh ones.

use cagd_core::BSplineCurve;
use cagd_testkit::bench::random_input;

use super::measure::{Known, SpanCaps, max_deviation_passes, spline_max_deviation_known};
use super::test_support::{greville, jittered_knots, sweep_point, sweep_weight};
use super::{BSplineOptions, reduce_bspline, spline_max_deviation};
use crate::SPLINE_MEASURED_PIECES;

/// A degree-`p` spline of `spans` jittered spans on `[t0, t0 + len]` over the smooth 3-D
/// sweep of `test_support` scaled by `size` and moved by `offset` along x, rational
/// (weights `2^sin` in `[0.5, 2]`) when `rational`; the middle interior knot has
/// multiplicity `mult`.
#[allow(clippy::too_many_arguments, reason = "the curve's parameters")]
fn sweep(
    p: usize,
    spans: usize,
    mult: usize,
    (t0, len): (f64, f64),
    (size, offset): (f64, f64),
    rational: bool,
    seed: u64,
) -> BSplineCurve {
    let r = random_input(8, seed);
    let unit = jittered_knots(p, spans, mult, &r);
    let knots: Vec<f64> = unit.iter().map(|t| t0 + len * t).collect();
    let n = knots.len() - p - 1;
    let (mut pts, mut w) = (Vec::with_capacity(3 * n), Vec::with_capacity(n));
    for i in 0..n {
        let g = greville(&unit, p, i);
        let [x, y, z] = sweep_point(g, &r);
        pts.extend([offset + size * x, size * y, size * z]);
        w.push(sweep_weight(g, &r));
    }
    if rational {
        BSplineCurve::new_rational(p, knots, pts, w, 3).unwrap()
    } else {
        BSplineCurve::new(p, knots, pts, 3).unwrap()
    }
}

/// The reports' measured errors (span bounds as caps, the source's pieces for polynomial
/// curves) against the public measurement without either, on 96 reductions of polynomial
/// and rational curves of degree 4–15 with 1–20 spans (some with a double knot, some far
/// from the origin or on a long domain) to cubics within 1e-3 / 1e-5 / 1e-7: never below
/// it (to rounding; for a NURBS, whose report measures with the fit's pieces moved back
/// from its frame, to the rounding level of its coordinates), equal on at least 90 %
/// (bitwise for polynomial curves, to that level for NURBS; the two can differ only where more
/// than `SPLINE_MEASURED_PIECES` pairs reach the maximum: the capped one refines fewer
/// pairs that cannot hold it), never above the certified bound.
#[test]
fn the_capped_measurement_is_the_uncapped_one() {
    let (mut same, mut total) = (0, 0);
    for case in 0..32usize {
        let p = 4 + (case * 5) % 12;
        let spans = 1 + (case * 7) % 20;
        let mult = if case % 3 == 0 && spans >= 3 && p >= 4 {
            2
        } else {
            1
        };
        let domain = if case % 2 == 0 {
            (0.0, 1.0)
        } else {
            (3.0, 250.0)
        };
        let place = if case % 4 == 1 {
            (200.0, 500.0)
        } else {
            (10.0, 0.0)
        };
        let c = sweep(
            p,
            spans,
            mult,
            domain,
            place,
            case % 2 == 1,
            700 + case as u64,
        );
        for tol in [1e-3, 1e-5, 1e-7] {
            let opts = BSplineOptions {
                measure: true,
                ..BSplineOptions::new(3, tol)
            };
            let r = reduce_bspline(&c, &opts).unwrap();
            let capped = r.report.max_error.unwrap();
            let plain = spline_max_deviation(&c, &r.curve).unwrap();
            // A NURBS's report measures with the fit's pieces moved back from its frame:
            // the input up to the rounding of its coordinates.
            let level = if c.is_rational() {
                64.0 * f64::EPSILON * c.points().iter().fold(0.0f64, |m, x| m.max(x.abs()))
            } else {
                0.0
            };
            assert!(
                capped >= plain * (1.0 - 1e-12) - level,
                "case {case} tol {tol}: {capped} < {plain}"
            );
            assert!(capped <= r.report.error_bound, "case {case} tol {tol}");
            same += usize::from((capped - plain).abs() <= level);
            total += 1;
        }
    }
    println!("{same} of {total} equal (bitwise; NURBS to their rounding level)");
    assert!(10 * same >= 9 * total, "{same} of {total} equal");
}

/// Caps decide which pairs are evaluated: with true caps (every span's dense maximum,
/// enlarged by a thousandth) the result is the uncapped one; with the pieces of `a`
/// passed in, too; with the span holding the maximum capped at zero the result is the
/// largest error of the other spans, below the uncapped one (so the first test would see
/// a cap below the error).
#[test]
fn caps_below_the_error_hide_it_and_true_caps_do_not() {
    let c = sweep(9, 6, 1, (0.0, 1.0), (10.0, 0.0), false, 31);
    let r = reduce_bspline(&c, &BSplineOptions::new(3, 1e-4)).unwrap();
    let out = &r.curve;
    let plain = spline_max_deviation(&c, out).unwrap();
    // The output's spans and their dense maxima (4 000 parameters each, model space).
    let (k, m) = (out.knots(), out.degree());
    let mut breaks: Vec<f64> = k[m..k.len() - m].to_vec();
    breaks.dedup();
    let dense: Vec<f64> = breaks
        .windows(2)
        .map(|w| {
            (0..=4000)
                .map(|i| {
                    let t = w[0] + (w[1] - w[0]) * f64::from(i) / 4000.0;
                    let (u, v) = (c.eval(t).unwrap(), out.eval(t).unwrap());
                    (0..3).map(|j| (u[j] - v[j]).powi(2)).sum::<f64>().sqrt()
                })
                .fold(0.0, f64::max)
        })
        .collect();
    let true_caps = SpanCaps {
        breaks: breaks.clone(),
        bounds: dense.iter().map(|x| x * 1.001).collect(),
        pieces: None,
    };
    let known = Known {
        pieces_a: None,
        caps: Some(&true_caps),
    };
    assert_eq!(spline_max_deviation_known(&c, out, known).unwrap(), plain);
    let pieces = c.to_beziers().unwrap();
    let mut pb: Vec<f64> = pieces.iter().map(|x| x.start).collect();
    pb.push(pieces.last().unwrap().end);
    let pts: Vec<f64> = pieces
        .iter()
        .flat_map(|x| x.curve.points().to_vec())
        .collect();
    let with_pieces = Known {
        pieces_a: Some((&pb, &pts)),
        caps: Some(&true_caps),
    };
    assert_eq!(
        spline_max_deviation_known(&c, out, with_pieces).unwrap(),
        plain
    );
    let worst = (0..dense.len())
        .max_by(|&x, &y| dense[x].total_cmp(&dense[y]))
        .unwrap();
    let mut low = true_caps.clone();
    low.bounds[worst] = 0.0;
    let second = dense
        .iter()
        .enumerate()
        .filter(|&(i, _)| i != worst)
        .map(|(_, x)| *x)
        .fold(0.0, f64::max);
    assert!(
        second < dense[worst] * (1.0 - 1e-3),
        "{second} {}",
        dense[worst]
    );
    let hidden = Known {
        pieces_a: None,
        caps: Some(&low),
    };
    let got = spline_max_deviation_known(&c, out, hidden).unwrap();
    assert!(got <= second * 1.001 && got < plain, "{got} vs {plain}");
}

/// The second pass's finer node check ([`max_deviation_passes`] with `finer`) against the
/// second pass without it (the check is taken on polynomial curves only), on reductions of
/// polynomial and rational curves (degree 4–15, 1–20 spans, 1e-3 / 1e-5 / 1e-7): bitwise
/// the same measured maximum wherever neither route reaches the limit of refined pairs,
/// and fewer pairs sampled densely in all (the check prunes).
#[test]
fn the_finer_check_keeps_the_maximum_and_samples_fewer_pairs() {
    let (mut with, mut without, mut compared) = (0, 0, 0);
    for case in 0..32usize {
        let p = 4 + (case * 5) % 12;
        let spans = 1 + (case * 7) % 20;
        let domain = if case % 2 == 0 {
            (0.0, 1.0)
        } else {
            (3.0, 250.0)
        };
        let c = sweep(
            p,
            spans,
            1,
            domain,
            (10.0, 0.0),
            case % 2 == 1,
            900 + case as u64,
        );
        for tol in [1e-3, 1e-5, 1e-7] {
            let r = reduce_bspline(&c, &BSplineOptions::new(3, tol)).unwrap();
            let (fine, n_fine) =
                max_deviation_passes(&c, &r.curve, Known::default(), true).unwrap();
            let (plain, n_plain) =
                max_deviation_passes(&c, &r.curve, Known::default(), false).unwrap();
            with += n_fine;
            without += n_plain;
            if n_fine < SPLINE_MEASURED_PIECES && n_plain < SPLINE_MEASURED_PIECES {
                assert_eq!(fine, plain, "case {case} tol {tol}");
                compared += 1;
            } else {
                assert!(fine >= plain * (1.0 - 1e-12), "case {case} tol {tol}");
            }
        }
    }
    println!(
        "{compared} compared; pairs sampled densely: {with} with the check, {without} without"
    );
    assert!(compared >= 60, "{compared}");
    assert!(with < without, "{with} vs {without}");
}

/// A NURBS's pieces given to the measurement ([`Known::pieces_a`], homogeneous `(w x,
/// w)`) are its pieces: with those of `to_beziers` the result is bitwise the one that
/// extracts them itself; with mismatched sizes they are ignored. And the framed global
/// fit's pieces moved back to the model (what the report measures with) are
/// `to_beziers`'s to the rounding level of the coordinates, far from the origin too.
#[test]
fn rational_pieces_given_are_the_extracted_ones() {
    for (case, place) in [(10.0, 0.0), (200.0, 500.0)].into_iter().enumerate() {
        let c = sweep(7, 5, 2, (3.0, 250.0), place, true, 900 + case as u64);
        let r = reduce_bspline(&c, &BSplineOptions::new(3, 1e-5)).unwrap();
        let plain = spline_max_deviation(&c, &r.curve).unwrap();
        let pieces = c.to_beziers().unwrap();
        let mut breaks: Vec<f64> = pieces.iter().map(|x| x.start).collect();
        breaks.push(pieces.last().unwrap().end);
        let hom: Vec<f64> = pieces
            .iter()
            .flat_map(|x| x.curve.homogeneous_points())
            .collect();
        let given = Known {
            pieces_a: Some((&breaks, &hom)),
            caps: None,
        };
        assert_eq!(
            spline_max_deviation_known(&c, &r.curve, given).unwrap(),
            plain
        );
        let short = Known {
            pieces_a: Some((&breaks, &hom[1..])),
            caps: None,
        };
        assert_eq!(
            spline_max_deviation_known(&c, &r.curve, short).unwrap(),
            plain
        );
        // The framed fit's own pieces, moved back.
        let tol = 1e-5;
        let (frame, moved) = super::framed::frame_curve(&c, tol).unwrap().unwrap();
        let inner = BSplineOptions {
            measure: false,
            ..BSplineOptions::new(3, frame.inner_tol)
        };
        let (_, caps) = super::global::reduce_global(&moved, &inner).unwrap();
        let (fb, fp) = caps.unwrap().pieces.expect("a NURBS hands its pieces on");
        let back = frame.unframe_homogeneous(&fp);
        assert_eq!(fb, breaks);
        assert_eq!(back.len(), hom.len());
        let size = c.points().iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let wmax = c.weights().unwrap().iter().fold(0.0f64, |m, x| m.max(*x));
        for (x, y) in back.iter().zip(&hom) {
            assert!(
                (x - y).abs() <= 64.0 * f64::EPSILON * size * wmax,
                "case {case}: {x} against {y}"
            );
        }
    }
}
