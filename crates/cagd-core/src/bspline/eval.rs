//! Evaluation and derivatives of [`BSplineCurve`] by de Boor's algorithm (Piegl & Tiller,
//! "The NURBS Book", §2.5 / §3.3; rational curves in homogeneous space, §4.2).

use super::knots::find_span;
use crate::binomial::{MAX_BINOMIAL_N, binomial_f64};
use crate::validate::check_finite_param;
use crate::{BSplineCurve, Error, Result};

/// The blossom (polar form) of the degree-`q` piece on span `s` of the knot vector `u`,
/// evaluated at `args` (`q` values), written to `local[q]`.
///
/// `local` holds the `q + 1` local control points `d_0..d_q` (dimension `pdim`), which are
/// overwritten; the points belong to the spline whose knots around span `s` are
/// `u[s-q+1..=s+q]` (for a derivative of order `k` of a degree-`p` spline these are the
/// original knots, `q = p - k`). With all arguments equal to `t` this is de Boor's
/// algorithm; with arguments in `[u_s, u_{s+1}]` each step is a convex combination.
/// Requires `u[s] < u[s+1]`, so every denominator is `>= u[s+1] - u[s] > 0`.
pub(crate) fn blossom(u: &[f64], s: usize, q: usize, local: &mut [f64], pdim: usize, args: &[f64]) {
    debug_assert!(local.len() == (q + 1) * pdim && args.len() == q && s >= q);
    for r in 1..=q {
        let t = args[r - 1];
        for j in (r..=q).rev() {
            let lo = u[s + j - q];
            let a = (t - lo) / (u[s + 1 + j - r] - lo);
            let b = 1.0 - a;
            for k in 0..pdim {
                local[j * pdim + k] = b * local[(j - 1) * pdim + k] + a * local[j * pdim + k];
            }
        }
    }
}

/// Evaluates a spline given by working points `work` (dimension `pdim`) at `t` into `out`
/// (`pdim` doubles). `t` must be finite.
pub(crate) fn eval_work(u: &[f64], p: usize, work: &[f64], pdim: usize, t: f64, out: &mut [f64]) {
    let n = work.len() / pdim;
    let s = find_span(u, p, n, t);
    let mut local = work[(s - p) * pdim..(s + 1) * pdim].to_vec();
    blossom(u, s, p, &mut local, pdim, &vec![t; p]);
    out.copy_from_slice(&local[p * pdim..]);
}

impl BSplineCurve {
    /// Evaluates the curve at `t` (de Boor; in homogeneous space for NURBS). `t` outside the
    /// domain extrapolates the first or last non-empty piece; at the right end of the domain
    /// the last piece is used, so `eval(b)` is the end point of a clamped curve.
    ///
    /// Accuracy: de Boor is a sequence of convex combinations inside the domain, relative
    /// error a few `p` ulp of the control-point size.
    ///
    /// # Errors
    /// [`Error::BadParameter`] when `t` is not finite.
    pub fn eval(&self, t: f64) -> Result<Vec<f64>> {
        check_finite_param("t", t)?;
        let (p, u) = (self.degree, &self.knots);
        let s = find_span(u, p, self.n_points(), t);
        let (mut local, pdim) = self.local_work(s - p, p + 1);
        blossom(u, s, p, &mut local, pdim, &vec![t; p]);
        let mut h = local.split_off(p * pdim);
        if self.weights.is_some() {
            let w = h[self.dim];
            h.truncate(self.dim);
            h.iter_mut().for_each(|x| *x /= w);
        }
        Ok(h)
    }

    /// The derivatives of orders `0..=order` at `t`, each `dim` doubles, Euclidean also for
    /// NURBS (quotient rule `C^(k) = (A^(k) - sum_{j=1}^k C(k,j) w^(j) C^(k-j)) / w`, Piegl &
    /// Tiller eq. 4.8, applied to the homogeneous derivatives `A^(k)`, `w^(k)`).
    ///
    /// The homogeneous derivatives come from the local derivative control points
    /// `P^(k)_i = (p-k+1) (P^(k-1)_{i+1} - P^(k-1)_i) / (u_{i+p+1} - u_{i+k})` (Piegl &
    /// Tiller eq. 3.8) evaluated by de Boor on the span of `t`; at an interior knot the
    /// derivative from the right is returned (from the left at the right end). Orders above
    /// the degree are zero for polynomial curves.
    ///
    /// # Errors
    /// [`Error::BadParameter`] when `t` is not finite or `order > 130` (the exact binomial
    /// range of the quotient rule).
    pub fn derivatives(&self, t: f64, order: usize) -> Result<Vec<Vec<f64>>> {
        check_finite_param("t", t)?;
        if order > MAX_BINOMIAL_N {
            return Err(Error::BadParameter {
                name: "order",
                value: order as f64,
                why: "derivative order must be at most 130",
            });
        }
        let (p, u) = (self.degree, &self.knots);
        let s = find_span(u, p, self.n_points(), t);
        let (mut level, pdim) = self.local_work(s - p, p + 1);
        let mut hom = Vec::with_capacity(order + 1);
        for k in 0..=order {
            if k > p {
                hom.push(vec![0.0; pdim]);
                continue;
            }
            if k > 0 {
                // Local points s-p..=s-k of the k-th derivative, from those of order k - 1.
                let next: Vec<f64> = (0..=p - k)
                    .flat_map(|l| {
                        let i = s - p + l;
                        let c = (p - k + 1) as f64 / (u[i + p + 1] - u[i + k]);
                        let lv = &level;
                        (0..pdim).map(move |c2| c * (lv[(l + 1) * pdim + c2] - lv[l * pdim + c2]))
                    })
                    .collect();
                level = next;
            }
            let q = p - k;
            let mut local = level.clone();
            blossom(u, s, q, &mut local, pdim, &vec![t; q]);
            hom.push(local[q * pdim..].to_vec());
        }
        if self.weights.is_none() {
            return Ok(hom);
        }
        let d = self.dim;
        let mut out: Vec<Vec<f64>> = Vec::with_capacity(order + 1);
        for k in 0..=order {
            let mut v = hom[k][..d].to_vec();
            for j in 1..=k {
                let c = binomial_f64(k, j) * hom[j][d];
                for (vi, oi) in v.iter_mut().zip(&out[k - j]) {
                    *vi -= c * oi;
                }
            }
            let w0 = hom[0][d];
            v.iter_mut().for_each(|x| *x /= w0);
            out.push(v);
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::BezierCurve;

    #[test]
    fn bezier_knots_give_the_bezier_curve() {
        let pts = vec![0.0, 0.0, 1.0, 3.0, 3.0, 4.0, 5.0, 1.0];
        let w = vec![1.0, 0.5, 2.0, 1.0];
        let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
        let b = BezierCurve::new_rational(pts.clone(), w.clone(), 2).unwrap();
        let s = BSplineCurve::new_rational(3, knots, pts, w, 2).unwrap();
        for i in 0..=20 {
            let t = f64::from(i) / 20.0;
            let (x, y) = (s.eval(t).unwrap(), b.eval(t));
            assert!((x[0] - y[0]).abs() < 1e-14 && (x[1] - y[1]).abs() < 1e-14);
            let ds = s.derivatives(t, 4).unwrap();
            let db = b.derivatives(t, 4).unwrap();
            for k in 0..=4 {
                for c in 0..2 {
                    let scale = 1.0f64.max(db[k][c].abs());
                    assert!((ds[k][c] - db[k][c]).abs() < 1e-11 * scale, "k={k} t={t}");
                }
            }
        }
        assert!(s.eval(f64::NAN).is_err());
        assert!(s.derivatives(0.5, 131).is_err());
    }

    #[test]
    fn evaluation_reads_only_the_span_and_equals_de_boor_on_the_whole_net() {
        // `eval` converts only the p + 1 local points (it converted the whole net per call,
        // which made measuring an 8192-span NURBS quadratic); the values are those of de
        // Boor on the fully converted net, bit for bit.
        let (p, n, dim) = (3usize, 40usize, 3usize);
        let knots: Vec<f64> = (0..n + p + 1)
            .map(|i| (i.clamp(p, n) as f64 - p as f64).powf(1.3))
            .collect();
        let pts: Vec<f64> = (0..n * dim)
            .map(|i| ((i * 7919) % 101) as f64 - 50.0)
            .collect();
        let w: Vec<f64> = (0..n).map(|i| 0.3 + ((i * 31) % 17) as f64 / 5.0).collect();
        let s = BSplineCurve::new_rational(p, knots, pts, w, dim).unwrap();
        let (work, pdim) = s.work_points();
        let (a, b) = s.domain();
        for i in 0..=400 {
            let t = a + (b - a) * f64::from(i) / 400.0;
            let mut h = vec![0.0; pdim];
            eval_work(&s.knots, p, &work, pdim, t, &mut h);
            let want: Vec<f64> = h[..dim].iter().map(|x| x / h[dim]).collect();
            assert_eq!(s.eval(t).unwrap(), want, "t = {t}");
        }
    }

    #[test]
    fn uniform_quadratic_basis_values() {
        // Uniform quadratic with points e_0, e_1, e_2 on knots 0..5; on [2, 3] the basis
        // functions at t = 2.5 are 1/8, 3/4, 1/8.
        let pts = vec![1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
        let c = BSplineCurve::new(2, (0..6).map(f64::from).collect(), pts, 3).unwrap();
        assert_eq!(c.eval(2.5).unwrap(), vec![0.125, 0.75, 0.125]);
        // Derivative of N_{0,2} on [2, 3] is -(3 - t): -0.5 at 2.5.
        let d = c.derivatives(2.5, 3).unwrap();
        assert_eq!(d[1], vec![-0.5, 0.0, 0.5]);
        assert_eq!(d[2], vec![1.0, -2.0, 1.0]);
        assert_eq!(d[3], vec![0.0, 0.0, 0.0]);
    }
}
