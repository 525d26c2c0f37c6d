//! SPEC-convert §15.1: one quadratic NURBS span ↔ one rational quadratic Bézier segment,
//! in closed form, both ways, as linear maps on homogeneous points (§0; no 0/0 cases).

use cagd_core::{BezierCurve, Result};

use super::span::{NurbsSpan, combine, homogeneous, inverse_span, local_gaps};

/// The forward map of SPEC-convert §15.1 (eq. 15.1.4–15.1.5 in homogeneous form, = Böhm
/// insertion): `Q0 = (c q0 + b q1)/(b+c)`, `Q1 = q1`, `Q2 = (d q1 + c q2)/(c+d)` with the
/// gaps (15.1.6) `b, c, d`; `q` and `out` hold 3 points of `pdim` coordinates.
pub(crate) fn forward_map(gaps: [f64; 3], q: &[f64], pdim: usize, out: &mut [f64]) {
    let [b, c, d] = gaps;
    let (q0, rest) = q.split_at(pdim);
    let (q1, q2) = rest.split_at(pdim);
    let (o0, rest) = out.split_at_mut(pdim);
    let (o1, o2) = rest.split_at_mut(pdim);
    combine(o0, q0, c, q1, b, b + c);
    o1.copy_from_slice(q1);
    combine(o2, q1, d, q2, c, c + d);
}

/// The inverse map of SPEC-convert §15.1 (eq. 15.1.9–15.1.10 in the division-safe form):
/// `q0 = ((b+c) Q0 - b Q1)/c`, `q1 = Q1`, `q2 = ((c+d) Q2 - d Q1)/c`.
pub(crate) fn inverse_map(gaps: [f64; 3], bq: &[f64], pdim: usize, out: &mut [f64]) {
    let [b, c, d] = gaps;
    let (p0, rest) = bq.split_at(pdim);
    let (p1, p2) = rest.split_at(pdim);
    let (o0, rest) = out.split_at_mut(pdim);
    let (o1, o2) = rest.split_at_mut(pdim);
    combine(o0, p0, b + c, p1, -b, c);
    o1.copy_from_slice(p1);
    combine(o2, p2, c + d, p1, -d, c);
}

/// A quadratic NURBS span → its rational Bézier segment (SPEC-convert §15.1, eq.
/// 15.1.3–15.1.7). `knots` are the four local knots `t_{n-1} <= t_n < t_{n+1} <= t_{n+2}`
/// of the span `[t_n, t_{n+1}]`, `points` the three points `r_{n-2}, r_{n-1}, r_n` (flat,
/// `dim` coordinates each), `weights` their weights. The segment is parametrised by
/// `T = (t - t_n)/c` (15.1.3) and is always returned rational.
///
/// # Errors
/// [`cagd_core::Error::KnotCount`] (not 4 knots), `NonFiniteKnot`, `KnotsNotNondecreasing`,
/// `BadParameter` (a zero-length span), `NonFinite`, `NonPositiveWeight`, `LengthMismatch`.
///
/// ```
/// # use cagd_convert::quadratic_span_to_bezier;
/// // SPEC-convert conv-15.1-a: W = (4/3, 2, 4/3), R = ((1/2,1), (1,2), (2,1)).
/// let b = quadratic_span_to_bezier(&[0.0, 1.0, 3.0, 4.0], &[0.0, 0.0, 1.0, 2.0, 3.0, 0.0],
///                                  &[1.0, 2.0, 1.0], 2)?;
/// assert_eq!(b.weights().unwrap(), &[4.0 / 3.0, 2.0, 4.0 / 3.0]);
/// assert_eq!(b.points(), &[0.5, 1.0, 1.0, 2.0, 2.0, 1.0]);
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn quadratic_span_to_bezier(
    knots: &[f64],
    points: &[f64],
    weights: &[f64],
    dim: usize,
) -> Result<BezierCurve> {
    let g = local_gaps(knots, 4, 1)?;
    let q = homogeneous(points, weights, dim, 3)?;
    let mut out = vec![0.0; q.len()];
    forward_map([g[0], g[1], g[2]], &q, dim + 1, &mut out);
    BezierCurve::from_homogeneous(&out, dim + 1)
}

/// A rational quadratic Bézier segment plus the local knots of a span → the NURBS points
/// and weights of that span (SPEC-convert §15.1, inverse, eq. 15.1.8–15.1.11 in the
/// division-safe homogeneous form). A polynomial segment is read with weights 1.
///
/// The condition 15.1.8, `c > max(b (W1-W0)/W0, d (W1-W2)/W2)`, holds exactly when all
/// three inverse weights are positive, which is what is checked. The extrapolation factor
/// `1 + max(k1, k2)` is reported in [`NurbsSpan::extrapolation`].
///
/// # Errors
/// [`cagd_core::Error::ConversionCondition`] (condition "15.1.8", the index `0..=2` of the
/// weight `w_{n-2+index}` that is not `> 0`, and its value); the knot errors of
/// [`quadratic_span_to_bezier`]; `BadDegreePair` for a segment that is not quadratic.
///
/// ```
/// # use cagd_convert::{bezier_to_quadratic_span, quadratic_span_to_bezier};
/// let knots = [0.0, 1.0, 3.0, 4.0];
/// let b = quadratic_span_to_bezier(&knots, &[0.0, 0.0, 1.0, 2.0, 3.0, 0.0], &[1.0, 2.0, 1.0], 2)?;
/// let s = bezier_to_quadratic_span(&b, &knots)?;
/// assert!((s.weights[0] - 1.0).abs() < 1e-15 && (s.points[4] - 3.0).abs() < 1e-15);
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn bezier_to_quadratic_span(bezier: &BezierCurve, knots: &[f64]) -> Result<NurbsSpan> {
    let g = local_gaps(knots, 4, 1)?;
    let gaps = [g[0], g[1], g[2]];
    inverse_span(
        bezier,
        2,
        |bq, pdim, out| inverse_map(gaps, bq, pdim, out),
        |_| "15.1.8",
        "inverse NURBS weight w_{n-2+index} must be > 0",
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_core::Error;

    #[test]
    fn double_knot_start_needs_no_special_case() {
        // conv-15.1-inv-b-double-knot-start: b = 0, c = 2, d = 3.
        let bez =
            BezierCurve::new_rational(vec![-1.0, 0.0, 0.0, 4.0, 2.5, 2.5], vec![0.5, 2.0, 2.4], 2)
                .unwrap();
        let s = bezier_to_quadratic_span(&bez, &[0.0, 0.0, 2.0, 5.0]).unwrap();
        let want_w = [0.5, 2.0, 3.0];
        let want_p = [-1.0, 0.0, 0.0, 4.0, 5.0, 1.0];
        for (g, w) in s.weights.iter().zip(want_w) {
            assert!((g - w).abs() < 1e-14);
        }
        for (g, w) in s.points.iter().zip(want_p) {
            assert!((g - w).abs() < 1e-14);
        }
        // k1 = 0, k2 = d W1 / (c w_n) = 3*2/(2*3) = 1.
        assert!((s.extrapolation - 2.0).abs() < 1e-14, "{}", s.extrapolation);
        let back =
            quadratic_span_to_bezier(&[0.0, 0.0, 2.0, 5.0], &s.points, &s.weights, 2).unwrap();
        for (g, w) in back.points().iter().zip(bez.points()) {
            assert!((g - w).abs() < 1e-14);
        }
    }

    #[test]
    fn condition_15_1_8_names_the_weight() {
        // b = c = d = 1, W = (1, 3, 1): w_{n-2} = 2*1 - 3 = -1.
        let bez = BezierCurve::new_rational(vec![0.0, 1.0, 2.0], vec![1.0, 3.0, 1.0], 1).unwrap();
        let e = bezier_to_quadratic_span(&bez, &[0.0, 1.0, 2.0, 3.0]).unwrap_err();
        assert_eq!(
            e,
            Error::ConversionCondition {
                condition: "15.1.8",
                what: "inverse NURBS weight w_{n-2+index} must be > 0",
                index: 0,
                value: -1.0
            }
        );
        // 15.1.8 as printed: c > max(b (W1-W0)/W0, d (W1-W2)/W2) = 2 fails for c = 1.
        assert!(e.to_string().contains("15.1.8"), "{e}");
    }

    #[test]
    fn a_subnormal_inverse_weight_fails_the_condition() {
        // w_{n-2} = 2 W0 - W1 = 2^-1060, positive but subnormal: no curve takes that weight,
        // so the condition fails (the C fuzz run found it reported as a bad input weight).
        let (w0, w1) = (2f64.powi(-1020), 2f64.powi(-1019) - 2f64.powi(-1060));
        assert!(2.0 * w0 - w1 > 0.0 && 2.0 * w0 - w1 < f64::MIN_POSITIVE);
        let bez = BezierCurve::new_rational(vec![0.0, 1.0, 2.0], vec![w0, w1, w0], 1).unwrap();
        let e = bezier_to_quadratic_span(&bez, &[0.0, 1.0, 2.0, 3.0]).unwrap_err();
        assert!(
            matches!(
                e,
                Error::ConversionCondition {
                    condition: "15.1.8",
                    ..
                }
            ),
            "{e}"
        );
    }

    #[test]
    fn condition_matches_15_1_8_as_printed() {
        // 15.1.8 is necessary and sufficient (SPEC-convert §15.1): compare on a grid.
        for &(b, c, d) in &[(1.0, 0.5, 2.0), (0.0, 1.0, 1.0), (2.0, 3.0, 0.0)] {
            for w1 in [0.2, 0.9, 1.5, 2.5, 4.0] {
                let (w0, w2) = (0.7, 1.3);
                let bez =
                    BezierCurve::new_rational(vec![0.0, 1.0, 3.0], vec![w0, w1, w2], 1).unwrap();
                let cond: f64 = f64::max(b * (w1 - w0) / w0, d * (w1 - w2) / w2);
                let ok = bezier_to_quadratic_span(&bez, &[0.0, b, b + c, b + c + d]).is_ok();
                assert_eq!(ok, c > cond, "b={b} c={c} d={d} W1={w1}");
            }
        }
    }

    #[test]
    fn bad_input_is_named() {
        let p = [0.0, 1.0, 2.0];
        let w = [1.0, 1.0, 1.0];
        assert!(matches!(
            quadratic_span_to_bezier(&[0.0, 1.0, 1.0, 2.0], &p, &w, 1),
            Err(Error::BadParameter { name: "span", .. })
        ));
        assert!(matches!(
            quadratic_span_to_bezier(&[0.0, 2.0, 1.0, 3.0], &p, &w, 1),
            Err(Error::KnotsNotNondecreasing { index: 2 })
        ));
        assert!(matches!(
            quadratic_span_to_bezier(&[0.0, 1.0, 2.0], &p, &w, 1),
            Err(Error::KnotCount {
                got: 3,
                expected: 4
            })
        ));
        assert!(matches!(
            quadratic_span_to_bezier(&[0.0, 1.0, 2.0, 3.0], &p, &[1.0, 0.0, 1.0], 1),
            Err(Error::NonPositiveWeight { index: 1, .. })
        ));
        assert!(matches!(
            quadratic_span_to_bezier(&[0.0, 1.0, 2.0, 3.0], &[0.0, f64::NAN, 1.0], &w, 1),
            Err(Error::NonFinite { index: 1, .. })
        ));
        assert!(matches!(
            quadratic_span_to_bezier(&[0.0, 1.0, 2.0, f64::INFINITY], &p, &w, 1),
            Err(Error::NonFiniteKnot { index: 3, .. })
        ));
        assert!(matches!(
            quadratic_span_to_bezier(&[0.0, 1.0, 2.0, 3.0], &p[..2], &w, 1),
            Err(Error::LengthMismatch { .. })
        ));
        let cubic = BezierCurve::new(vec![0.0, 1.0, 2.0, 3.0], 1).unwrap();
        assert!(matches!(
            bezier_to_quadratic_span(&cubic, &[0.0, 1.0, 2.0, 3.0]),
            Err(Error::BadDegreePair { from: 3, to: 2, .. })
        ));
    }
}
