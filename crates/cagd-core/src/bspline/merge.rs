//! Joining Bézier segments back into one B-spline: the exact merge of seed 001 §4.1.
//!
//! Consecutive degree-`m` segments on the intervals `[b_0, b_1], [b_1, b_2], ...` become one
//! spline with the knots `b_0^(m+1), b_1^m, ..., b_N^(m+1)` (interior multiplicity `m`, C0):
//! the control points are the Bézier points with each shared joint point stored once (seed
//! 001 §4.1, second variant; the vector `001-exact-merge-c0`). When the caller states that
//! the joints are `C^k`, each interior knot is then removed `k` times (multiplicity `m - k`;
//! SPEC-reduce §8 "ADDED"), by [`BSplineCurve::remove_knot`], which certifies the change.

use crate::validate::{check_finite_param, check_tolerance};
use crate::{BSplineCurve, BezierCurve, Error, Result};

impl BSplineCurve {
    /// Merges Bézier segments into one spline (seed 001 §4.1, exact merge).
    ///
    /// `segments[i]` is the piece on `[breaks[i], breaks[i + 1]]` (each curve on `[0, 1]`);
    /// all have the same degree `m >= 1` and dimension; if any is rational, all are merged
    /// in homogeneous space (weights 1 for the polynomial ones) and the result is a NURBS.
    /// `continuity = k` (`0 <= k < m`) states that the joints are `C^k`; it is verified:
    ///
    /// * C0: the end point of each segment must meet the start of the next within `tol`
    ///   (Euclidean distance; for rational segments the distance of the homogeneous points
    ///   `(w P, w)`, so the end weights must agree too); the stored point is their midpoint.
    /// * `C^k`, `k >= 1`: every interior knot is removed `k` times; the accumulated certified
    ///   bound of [`BSplineCurve::remove_knot`] (model units) must stay `<= tol`.
    ///
    /// The parametric continuity is meant with respect to the global parameter, i.e. the
    /// derivatives of the segments are scaled by their interval lengths.
    ///
    /// # Errors
    /// [`Error::NotEnoughPoints`] (no segment); [`Error::LengthMismatch`] (breaks not
    /// `segments + 1`, or differing degrees or dimensions); [`Error::BadParameter`] (a break
    /// not finite or not strictly increasing, degree 0, or `continuity >= m`);
    /// [`Error::BadTolerance`]; [`Error::ConditionNotMet`] (eq. "001 §4.1") when the joints
    /// are not C0 / `C^k` within `tol`.
    ///
    /// ```
    /// # use cagd_core::{BezierCurve, BSplineCurve};
    /// let a = BezierCurve::new(vec![0.0, 1.0, 2.0], 1)?;
    /// let b = BezierCurve::new(vec![2.0, 3.0, 5.0], 1)?;
    /// let s = BSplineCurve::from_beziers(&[a, b], &[0.0, 1.0, 2.0], 0, 1e-12)?;
    /// assert_eq!(s.knots(), &[0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0]);
    /// assert_eq!(s.points(), &[0.0, 1.0, 2.0, 3.0, 5.0]);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn from_beziers(
        segments: &[BezierCurve],
        breaks: &[f64],
        continuity: usize,
        tol: f64,
    ) -> Result<BSplineCurve> {
        check_tolerance(tol)?;
        let first = segments
            .first()
            .ok_or(Error::NotEnoughPoints { got: 0, need: 1 })?;
        let (m, dim) = (first.degree(), first.dim());
        if breaks.len() != segments.len() + 1 {
            return Err(Error::LengthMismatch {
                what: "breaks (segments + 1)",
                got: breaks.len(),
                expected: segments.len() + 1,
            });
        }
        for seg in segments {
            if seg.degree() != m || seg.dim() != dim {
                let (what, got, expected) = if seg.dim() != dim {
                    ("segment dimensions", seg.dim(), dim)
                } else {
                    ("segment degrees", seg.degree(), m)
                };
                return Err(Error::LengthMismatch {
                    what,
                    got,
                    expected,
                });
            }
        }
        for (i, &b) in breaks.iter().enumerate() {
            check_finite_param("breaks", b)?;
            if i > 0 && b <= breaks[i - 1] {
                return Err(Error::BadParameter {
                    name: "breaks",
                    value: b,
                    why: "breaks must be strictly increasing",
                });
            }
        }
        if m == 0 || continuity >= m {
            return Err(Error::BadParameter {
                name: "continuity",
                value: continuity as f64,
                why: "segments need degree m >= 1 and the continuity k must be < m",
            });
        }
        let rational = segments.iter().any(BezierCurve::is_rational);
        let pdim = if rational { dim + 1 } else { dim };
        let work_of = |s: &BezierCurve| {
            if rational {
                s.homogeneous_points()
            } else {
                s.points().to_vec()
            }
        };
        let mut work: Vec<f64> = Vec::with_capacity((segments.len() * m + 1) * pdim);
        let mut knots = vec![breaks[0]; m + 1];
        for (i, seg) in segments.iter().enumerate() {
            let w = work_of(seg);
            if i == 0 {
                work.extend_from_slice(&w);
            } else {
                let joint = work.len() - pdim;
                let dist = (0..pdim)
                    .map(|c| (work[joint + c] - w[c]).powi(2))
                    .sum::<f64>()
                    .sqrt();
                if dist.is_nan() || dist > tol {
                    return Err(Error::ConditionNotMet {
                        eq: "001 §4.1",
                        why: "consecutive segments do not meet (C0) within the tolerance",
                    });
                }
                for c in 0..pdim {
                    work[joint + c] = 0.5 * (work[joint + c] + w[c]);
                }
                work.extend_from_slice(&w[pdim..]);
                knots.extend(std::iter::repeat_n(breaks[i], m));
            }
        }
        knots.extend(std::iter::repeat_n(breaks[segments.len()], m + 1));
        let mut curve = if rational {
            let n = work.len() / pdim;
            let mut points = vec![0.0; n * dim];
            let mut weights = vec![0.0; n];
            crate::kernel::from_homogeneous(&work, dim, &mut points, &mut weights);
            BSplineCurve::new_rational(m, knots, points, weights, dim)?
        } else {
            BSplineCurve::new(m, knots, work, dim)?
        };
        let mut used = 0.0;
        for &b in &breaks[1..segments.len()] {
            if continuity == 0 {
                break;
            }
            let r = curve.remove_knot(b, continuity, (tol - used).max(f64::MIN_POSITIVE))?;
            if r.removed != continuity {
                return Err(Error::ConditionNotMet {
                    eq: "001 §4.1",
                    why: "the joints are not C^k within the tolerance",
                });
            }
            used += r.error_bound;
            curve = r.curve;
        }
        Ok(curve)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bspline::insert::tests::assert_same_curve;

    #[test]
    fn vector_001_exact_merge_c0() {
        let v = cagd_testkit::vector("vectors-reduce.json", "001-exact-merge-c0");
        let segs: Vec<BezierCurve> = v["input"]["segments_exact"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| BezierCurve::new(cagd_testkit::flat(s), 2).unwrap())
            .collect();
        let c = BSplineCurve::from_beziers(&segs, &[0.0, 1.0, 2.0, 3.0], 0, 1e-12).unwrap();
        assert_eq!(c.knots(), &cagd_testkit::flat(&v["expected"]["knots"])[..]);
        let ctrl = cagd_testkit::flat(&v["expected"]["ctrl_exact"]);
        cagd_testkit::assert_close("001-exact-merge-c0", c.points(), &ctrl, 0.0);
        for (s, seg) in c.to_beziers().unwrap().iter().zip(&segs) {
            cagd_testkit::assert_close("round trip", s.curve.points(), seg.points(), 0.0);
        }
    }

    /// Splits a spline into pieces and merges them back with the given continuity.
    fn round_trip(c: &BSplineCurve, k: usize, tol: f64) -> Result<BSplineCurve> {
        let pieces = c.to_beziers()?;
        let mut breaks: Vec<f64> = pieces.iter().map(|p| p.start).collect();
        breaks.push(pieces.last().map_or(0.0, |p| p.end));
        let segs: Vec<BezierCurve> = pieces.into_iter().map(|p| p.curve).collect();
        BSplineCurve::from_beziers(&segs, &breaks, k, tol)
    }

    #[test]
    fn c1_and_c2_joints_give_the_original_spline() {
        // Cubic with simple knots (C2) on uneven intervals; rational and not.
        let knots = vec![0.0, 0.0, 0.0, 0.0, 0.3, 1.0, 1.0, 1.0, 1.0];
        let pts = vec![0.0, 0.0, 1.0, 2.0, 2.0, -1.0, 3.0, 2.0, 4.0, 0.0];
        for w in [None, Some(vec![1.0, 2.0, 0.5, 1.0, 3.0])] {
            let c = match &w {
                None => BSplineCurve::new(3, knots.clone(), pts.clone(), 2),
                Some(w) => BSplineCurve::new_rational(3, knots.clone(), pts.clone(), w.clone(), 2),
            }
            .unwrap();
            let m2 = round_trip(&c, 2, 1e-9).unwrap();
            assert_eq!(m2.knots(), c.knots());
            assert_same_curve(&c, &m2, 200);
            let m1 = round_trip(&c, 1, 1e-9).unwrap();
            assert_eq!(m1.n_points(), 6);
            assert_same_curve(&c, &m1, 200);
        }
        // A C1-only spline (double knot) refuses C2.
        let k1 = vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.3, 1.0, 1.0, 1.0, 1.0];
        let p1 = vec![0.0, 1.0, 5.0, 2.0, 2.0, 7.0];
        let c1 = BSplineCurve::new(3, k1, p1, 1).unwrap();
        assert_same_curve(&c1, &round_trip(&c1, 1, 1e-9).unwrap(), 200);
        assert!(matches!(
            round_trip(&c1, 2, 1e-9),
            Err(Error::ConditionNotMet { .. })
        ));
    }

    #[test]
    fn errors() {
        let a = BezierCurve::new(vec![0.0, 1.0, 2.0], 1).unwrap();
        let b = BezierCurve::new(vec![2.5, 3.0, 5.0], 1).unwrap();
        let c = BezierCurve::new(vec![2.0, 3.0], 1).unwrap();
        let br = [0.0, 1.0, 2.0];
        let merge =
            |s: &[BezierCurve], br: &[f64], k, tol| BSplineCurve::from_beziers(s, br, k, tol);
        assert!(matches!(
            merge(&[a.clone(), b.clone()], &br, 0, 1e-9),
            Err(Error::ConditionNotMet { .. })
        ));
        assert!(merge(&[a.clone(), b.clone()], &br, 0, 0.5).is_ok());
        assert!(matches!(
            merge(&[], &[0.0], 0, 1.0),
            Err(Error::NotEnoughPoints { .. })
        ));
        assert!(matches!(
            merge(&[a.clone(), c], &br, 0, 1.0),
            Err(Error::LengthMismatch { .. })
        ));
        assert!(matches!(
            merge(&[a.clone(), b.clone()], &br[..2], 0, 1.0),
            Err(Error::LengthMismatch { .. })
        ));
        assert!(matches!(
            merge(&[a.clone(), b.clone()], &[0.0, 1.0, 1.0], 0, 1.0),
            Err(Error::BadParameter { .. })
        ));
        assert!(matches!(
            merge(&[a.clone(), b.clone()], &[0.0, f64::NAN, 2.0], 0, 1.0),
            Err(Error::BadParameter { .. })
        ));
        assert!(matches!(
            merge(&[a.clone(), b.clone()], &br, 2, 1.0),
            Err(Error::BadParameter { .. })
        ));
        assert!(matches!(
            merge(&[a, b], &br, 0, 0.0),
            Err(Error::BadTolerance { .. })
        ));
    }
}
