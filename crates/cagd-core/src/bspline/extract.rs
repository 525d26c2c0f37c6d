//! Bézier extraction: every non-empty span of a [`BSplineCurve`] as a [`BezierCurve`]
//! (Piegl & Tiller, "The NURBS Book", §5.4; here by blossoming).
//!
//! The Bézier points of the piece on `[a, b] = [u_s, u_{s+1}]` are the blossom values
//! `b_i = P[a^(p-i), b^i]`, `i = 0..=p` (Ramshaw; the same points that inserting every
//! interior knot up to multiplicity `p` produces). They come from two de Boor triangles
//! (ADDED: `O(p^2)` per span; one de Boor triangle per point, `O(p^3)`, was a third of
//! the reduction of degree 4–15 curves in issue 17's real-CAD-file row): the triangle at
//! `a` on the span's `p + 1` points leaves, as the last point of level `r`, `V_(p-r) =
//! P[a^r, u_{s+1}, ..., u_{s+p-r}]` (the points after inserting `a` up to multiplicity
//! `p`); the triangle at `b` on `V` (knots `a^p, u_{s+1}, ..., u_{s+p}`) leaves `b_r` as
//! the first point of level `r`. Both are convex combinations, so the points carry a
//! relative error of a few `p` ulp.
//!
//! The end points are the de Boor values `P[a^p]`, `P[b^p]` themselves and are shared:
//! the last point of a piece is the first point of the next one (the triangle at the next
//! span's start, which is the spline's value there), the last piece's last point a de Boor
//! evaluation at the domain's end. So adjacent pieces meet exactly, as the spline does
//! (a version whose pieces' shared end points differed by rounding failed a `C^0` merge
//! of the pieces within `1e-12` of the size: `bspline_laws`' regression in cagd-reduce).

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
    let mut out: Vec<(f64, f64, Vec<f64>)> = Vec::new();
    let mut tri = vec![0.0; (p + 1) * pdim];
    for s in p..n {
        let (a, b) = (u[s], u[s + 1]);
        if a >= b {
            continue;
        }
        let mut v = vec![0.0; (p + 1) * pdim];
        span_bezier_into(
            u,
            p,
            &work[(s - p) * pdim..(s + 1) * pdim],
            pdim,
            s,
            &mut tri,
            &mut v,
        );
        if let Some((_, _, prev)) = out.last_mut() {
            // The previous piece ends where this one starts: the spline's value there.
            let len = prev.len();
            prev[len - pdim..].copy_from_slice(&v[..pdim]);
        }
        out.push((a, b, v));
    }
    // The last piece's end: the de Boor value at the domain's end on its span.
    if let Some(s) = (p..n).rev().find(|&s| u[s] < u[s + 1]) {
        let mut local = work[(s - p) * pdim..(s + 1) * pdim].to_vec();
        blossom(u, s, p, &mut local, pdim, &vec![u[s + 1]; p]);
        if let Some((_, _, last)) = out.last_mut() {
            let len = last.len();
            last[len - pdim..].copy_from_slice(&local[p * pdim..]);
        }
    }
    out
}

/// The Bézier points of the non-empty span `s` of the degree-`p` spline with knots `u` into
/// `out` (`(p + 1) pdim` values), `local` its points `s - p ..= s`, `tri` scratch of the
/// same length (the two de Boor triangles of the module docs; the last point is the
/// triangle's, which [`extract_work`] replaces by the shared end point).
fn span_bezier_into(
    u: &[f64],
    p: usize,
    local: &[f64],
    pdim: usize,
    s: usize,
    tri: &mut [f64],
    out: &mut [f64],
) {
    let (a, b) = (u[s], u[s + 1]);
    let blend = |x: &mut [f64], j: usize, alpha: f64| {
        let (lo, hi) = x.split_at_mut(j * pdim);
        let prev = &lo[(j - 1) * pdim..];
        for (y, z) in hi[..pdim].iter_mut().zip(prev) {
            *y = (1.0 - alpha) * z + alpha * *y;
        }
    };
    // De Boor at `a`: the last point of level r is V_(p-r) (level p: P[a^p], the same
    // operations as a de Boor evaluation at `a`).
    tri.copy_from_slice(local);
    out[p * pdim..].copy_from_slice(&tri[p * pdim..]);
    for r in 1..=p {
        for j in (r..=p).rev() {
            let lo = u[s + j - p];
            blend(tri, j, (a - lo) / (u[s + 1 + j - r] - lo));
        }
        out[(p - r) * pdim..(p - r + 1) * pdim].copy_from_slice(&tri[p * pdim..]);
    }
    // De Boor at `b` on V (knots a^p, u_{s+1}, ..., u_{s+p}): point r of level r is the
    // Bézier point b_r, which stays in place for the later levels.
    for r in 1..=p {
        for j in (r..=p).rev() {
            blend(out, j, (b - a) / (u[s + j - r + 1] - a));
        }
    }
}

/// The first Bézier point of the non-empty span `s` (the spline's value at `u_s`): the
/// last point of the de Boor triangle at `u_s` on the span's points `local` (scratch
/// `tri`), by the same operations as in [`span_bezier_into`], so bitwise its first point.
fn span_start_into(u: &[f64], p: usize, local: &[f64], pdim: usize, s: usize, tri: &mut [f64]) {
    let a = u[s];
    tri.copy_from_slice(local);
    for r in 1..=p {
        for j in (r..=p).rev() {
            let lo = u[s + j - p];
            let alpha = (a - lo) / (u[s + 1 + j - r] - lo);
            let (lo_part, hi) = tri.split_at_mut(j * pdim);
            let prev = &lo_part[(j - 1) * pdim..];
            for (y, z) in hi[..pdim].iter_mut().zip(prev) {
                *y = (1.0 - alpha) * z + alpha * *y;
            }
        }
    }
}

impl BSplineCurve {
    /// The non-empty knot span `s` (`p <= s < n`, `u_s < u_{s+1}`) as a
    /// [`BezierSegment`]: bitwise the element of [`Self::to_beziers`] on `[u_s, u_{s+1}]`
    /// (Piegl & Tiller §5.4 by blossoming, the module docs: its points `b_i = P[a^(p-i),
    /// b^i]` from the span's two de Boor triangles, its last point the next
    /// non-empty span's first, or the de Boor value at the domain's end), from the
    /// span's own `p + 1` control points and the next span's: `O(p^2)` for one piece,
    /// where [`Self::to_beziers`] extracts every piece. ADDED (issue 17's real-CAD-file
    /// row): a measurement that visits a few pairs of pieces of two splines extracts only
    /// those.
    ///
    /// # Errors
    /// [`crate::Error::BadParameter`] when `s` is not a non-empty span of the domain; as
    /// [`Self::to_beziers`] when the piece is not representable.
    ///
    /// ```
    /// # use cagd_core::BSplineCurve;
    /// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0],
    ///                           vec![0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0], 2)?;
    /// assert_eq!(c.bezier_piece(3)?, c.to_beziers()?[1]);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn bezier_piece(&self, s: usize) -> Result<BezierSegment> {
        let (u, p) = (&self.knots, self.degree);
        let n = self.n_points();
        if s < p || s >= n || u[s] >= u[s + 1] {
            return Err(crate::Error::BadParameter {
                name: "span",
                value: s as f64,
                why: "must be a non-empty knot span of the domain (p <= s < n, u_s < u_(s+1))",
            });
        }
        let (local, pdim) = self.local_work(s - p, p + 1);
        let mut tri = vec![0.0; (p + 1) * pdim];
        let mut bez = vec![0.0; (p + 1) * pdim];
        span_bezier_into(u, p, &local, pdim, s, &mut tri, &mut bez);
        let end = match (s + 1..n).find(|&j| u[j] < u[j + 1]) {
            Some(next) => {
                let (later, _) = self.local_work(next - p, p + 1);
                span_start_into(u, p, &later, pdim, next, &mut tri);
                tri[p * pdim..].to_vec()
            }
            None => {
                let mut last = local;
                blossom(u, s, p, &mut last, pdim, &vec![u[s + 1]; p]);
                last[p * pdim..].to_vec()
            }
        };
        let len = bez.len();
        bez[len - pdim..].copy_from_slice(&end);
        let curve = match self.weights {
            None => BezierCurve::new(bez, self.dim)?,
            Some(_) => {
                let mut pts = vec![0.0; (p + 1) * self.dim];
                let mut w = vec![0.0; p + 1];
                check_points(&bez, pdim)?;
                kernel::from_homogeneous(&bez, self.dim, &mut pts, &mut w);
                BezierCurve::new_rational(pts, w, self.dim)?
            }
        };
        Ok(BezierSegment {
            start: u[s],
            end: u[s + 1],
            curve,
        })
    }

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

    /// A 3-D curve of degree `p` (polynomial or rational) with unclamped ends and interior
    /// knots of multiplicity 1, `p`, 2, 1, `p - 1` (at least 1), its points scaled by
    /// `scale`; and its knot vector.
    fn unclamped_curve(p: usize, rational: bool, scale: f64) -> (Vec<f64>, BSplineCurve) {
        let mut knots: Vec<f64> = (0..p).map(|i| -0.3 * (p - i) as f64).collect();
        for (j, mult) in [1usize, p, 2.min(p), 1, p.saturating_sub(1).max(1)]
            .into_iter()
            .enumerate()
        {
            knots.extend(std::iter::repeat_n(
                1.0 + 0.7 * j as f64 + 0.01 * j as f64 * j as f64,
                mult,
            ));
        }
        knots.extend((0..=p).map(|i| 5.0 + 0.4 * i as f64));
        let n = knots.len() - p - 1;
        let pts: Vec<f64> = (0..3 * n)
            .map(|i| ((i * 37 % 23) as f64 - 11.0) * scale)
            .collect();
        let c = if rational {
            let w: Vec<f64> = (0..n).map(|i| 0.5 + (i * 7 % 5) as f64 * 0.35).collect();
            BSplineCurve::new_rational(p, knots.clone(), pts, w, 3).unwrap()
        } else {
            BSplineCurve::new(p, knots.clone(), pts, 3).unwrap()
        };
        (knots, c)
    }

    /// One piece ([`BSplineCurve::bezier_piece`]) is bitwise the element of
    /// [`BSplineCurve::to_beziers`] on its span, at degrees 1–15, polynomial and rational,
    /// with unclamped ends and knots of multiplicity 1..p (empty spans refused).
    #[test]
    fn one_piece_is_the_extracted_piece() {
        for p in [1usize, 2, 4, 7, 11, 15] {
            for rational in [false, true] {
                let (knots, c) = unclamped_curve(p, rational, 3.7);
                let n = knots.len() - p - 1;
                let all = c.to_beziers().unwrap();
                let mut k = 0;
                for s in 0..knots.len() - 1 {
                    let piece = c.bezier_piece(s);
                    if s < p || s >= n || knots[s] >= knots[s + 1] {
                        assert!(piece.is_err(), "p {p} span {s} accepted");
                        continue;
                    }
                    let piece = piece.unwrap();
                    let bits = |b: &BezierSegment| {
                        let mut v = vec![b.start.to_bits(), b.end.to_bits()];
                        v.extend(b.curve.points().iter().map(|x| x.to_bits()));
                        v.extend(b.curve.weights().unwrap_or(&[]).iter().map(|x| x.to_bits()));
                        v
                    };
                    assert_eq!(
                        bits(&piece),
                        bits(&all[k]),
                        "p {p} rational {rational} span {s}"
                    );
                    k += 1;
                }
                assert_eq!(k, all.len());
            }
        }
    }

    /// The two-triangle extraction against the definition, one blossom `P[a^(p-i), b^i]`
    /// per Bézier point (the route it replaced), at degrees 4–15 with unclamped ends,
    /// knots of multiplicity 1..p and rational points: the same points to a few `p` ulp,
    /// the end points bitwise (so adjacent pieces meet exactly).
    #[test]
    fn pieces_are_the_blossoms_at_high_degree() {
        use crate::bspline::eval::blossom;
        for p in [4usize, 7, 11, 15] {
            let (knots, c) = unclamped_curve(p, true, 3.5);
            let n = knots.len() - p - 1;
            let (work, pdim) = c.work_points();
            let scale = work.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let pieces = extract_work(&knots, p, &work, pdim);
            let mut k = 0;
            for s in p..n {
                let (a, b) = (knots[s], knots[s + 1]);
                if a >= b {
                    continue;
                }
                let (pa, pb, bez) = &pieces[k];
                k += 1;
                assert_eq!((*pa, *pb), (a, b));
                for i in 0..=p {
                    let mut args = vec![a; p - i];
                    args.extend(std::iter::repeat_n(b, i));
                    let mut local = work[(s - p) * pdim..(s + 1) * pdim].to_vec();
                    blossom(&knots, s, p, &mut local, pdim, &args);
                    for (x, y) in bez[i * pdim..(i + 1) * pdim].iter().zip(&local[p * pdim..]) {
                        // The end points are the de Boor values themselves (shared
                        // with the neighbours); the others convex combinations of the
                        // same points: a few p ulp.
                        if i == 0 || i == p {
                            assert_eq!(x.to_bits(), y.to_bits(), "p={p} s={s} i={i}");
                        }
                        assert!(
                            (x - y).abs() <= 8.0 * p as f64 * f64::EPSILON * scale,
                            "p={p} s={s} i={i}: {x} vs {y}"
                        );
                    }
                }
            }
            assert_eq!(k, pieces.len());
        }
    }

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
