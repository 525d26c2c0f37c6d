//! Bézier extraction: every non-empty span of a [`BSplineCurve`] as a [`BezierCurve`]
//! (Piegl & Tiller, "The NURBS Book", §5.4; here by blossoming).
//!
//! The Bézier points of the piece on `[a, b] = [u_s, u_{s+1}]` are the blossom values
//! `b_i = P[a^(p-i), b^i]`, `i = 0..=p` (Ramshaw; the same points that inserting every
//! interior knot up to multiplicity `p` produces). Each is a de Boor triangle of convex
//! combinations, so the points carry a relative error of a few `p` ulp.

use super::eval::blossom;
use crate::validate::check_points;
use crate::{BSplineCurve, BezierCurve, Result, kernel};

/// One polynomial piece of a spline: the Bézier curve on `[0, 1]` that reparametrises the
/// spline on `[start, end]` (`curve(s) = spline(start + s (end - start))`).
#[derive(Debug, Clone, PartialEq)]
pub struct BezierSegment {
    /// The start of the parameter interval of the piece.
    pub start: f64,
    /// The end of the parameter interval of the piece (`> start`).
    pub end: f64,
    /// The piece as a Bézier curve on `[0, 1]` (rational when the spline is).
    pub curve: BezierCurve,
}

/// The Bézier points (dimension `pdim`) of every non-empty span of the spline `(u, work)`
/// of degree `p`, with the span intervals.
pub(crate) fn extract_work(
    u: &[f64],
    p: usize,
    work: &[f64],
    pdim: usize,
) -> Vec<(f64, f64, Vec<f64>)> {
    let n = work.len() / pdim;
    let mut out = Vec::new();
    for s in p..n {
        let (a, b) = (u[s], u[s + 1]);
        if a >= b {
            continue;
        }
        let mut bez = Vec::with_capacity((p + 1) * pdim);
        let mut args = vec![a; p];
        for i in 0..=p {
            let mut local = work[(s - p) * pdim..(s + 1) * pdim].to_vec();
            blossom(u, s, p, &mut local, pdim, &args);
            bez.extend_from_slice(&local[p * pdim..]);
            if i < p {
                args[i] = b;
            }
        }
        out.push((a, b, bez));
    }
    out
}

impl BSplineCurve {
    /// Every non-empty span `[u_s, u_{s+1}]` of the domain as a [`BezierSegment`], in
    /// order; rational pieces for a NURBS curve (the blossom is taken of the homogeneous
    /// points, so the piece weights are positive).
    ///
    /// Measured: the pieces evaluate to the spline within `1e-12` relative (proptest,
    /// degrees 1..=6, 200+ parameters).
    ///
    /// # Errors
    /// Only when a piece is not representable ([`crate::Error::NonFinite`] after an
    /// overflow for control points near `f64::MAX`).
    ///
    /// ```
    /// # use cagd_core::BSplineCurve;
    /// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0],
    ///                           vec![0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0], 2)?;
    /// let pieces = c.to_beziers()?;
    /// assert_eq!(pieces.len(), 2);
    /// assert_eq!((pieces[1].start, pieces[1].end), (0.5, 1.0));
    /// assert_eq!(pieces[0].curve.eval(1.0), pieces[1].curve.eval(0.0));
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn to_beziers(&self) -> Result<Vec<BezierSegment>> {
        let (work, pdim) = self.work_points();
        extract_work(&self.knots, self.degree, &work, pdim)
            .into_iter()
            .map(|(start, end, bez)| {
                let curve = match self.weights {
                    None => BezierCurve::new(bez, self.dim)?,
                    Some(_) => {
                        let n1 = self.degree + 1;
                        let mut pts = vec![0.0; n1 * self.dim];
                        let mut w = vec![0.0; n1];
                        check_points(&bez, pdim)?;
                        kernel::from_homogeneous(&bez, self.dim, &mut pts, &mut w);
                        BezierCurve::new_rational(pts, w, self.dim)?
                    }
                };
                Ok(BezierSegment { start, end, curve })
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bspline::insert::tests::curve_strategy;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn pieces_evaluate_to_the_spline(c in curve_strategy()) {
            let pieces = c.to_beziers().unwrap();
            let distinct_interior = {
                let mut k: Vec<f64> = c.knots()[c.degree() + 1..c.n_points()].to_vec();
                k.dedup();
                k.len()
            };
            prop_assert_eq!(pieces.len(), distinct_interior + 1);
            let scale = c.points().iter().fold(1.0f64, |m, x| m.max(x.abs()));
            for (i, seg) in pieces.iter().enumerate() {
                if i > 0 {
                    prop_assert_eq!(seg.start, pieces[i - 1].end);
                }
                prop_assert_eq!(seg.curve.is_rational(), c.is_rational());
                for j in 0..=40 {
                    let s = f64::from(j) / 40.0;
                    let t = seg.start + s * (seg.end - seg.start);
                    let (x, y) = (seg.curve.eval(s), c.eval(t).unwrap());
                    // t = start + s (end - start) is rounded: allow |C'(t)| * 4 ulp(1) on
                    // top (a short span makes the curve fast).
                    let d = c.derivatives(t, 1).unwrap();
                    let speed = d[1].iter().fold(0.0f64, |m, v| m.max(v.abs()));
                    let allowed = 1e-12 * scale + 4.0 * f64::EPSILON * speed;
                    for (xi, yi) in x.iter().zip(&y) {
                        prop_assert!((xi - yi).abs() <= allowed, "t={} {:?} {:?}", t, x, y);
                    }
                }
            }
        }
    }

    #[test]
    fn bezier_knot_vector_is_one_piece() {
        let pts = vec![0.0, 1.0, 5.0, 2.0];
        let c = BSplineCurve::new(
            3,
            vec![2.0, 2.0, 2.0, 2.0, 4.0, 4.0, 4.0, 4.0],
            pts.clone(),
            1,
        )
        .unwrap();
        let pieces = c.to_beziers().unwrap();
        assert_eq!(pieces.len(), 1);
        assert_eq!(pieces[0].curve.points(), &pts[..]);
        assert_eq!((pieces[0].start, pieces[0].end), (2.0, 4.0));
    }
}
