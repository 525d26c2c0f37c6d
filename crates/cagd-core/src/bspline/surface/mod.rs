//! Tensor-product B-spline / NURBS surfaces
//! `S(u, v) = sum_i sum_j N_{i,p}(u) N_{j,q}(v) w_ij P_ij / sum_i sum_j N_{i,p}(u) N_{j,q}(v) w_ij`
//! (weights 1 when polynomial), control net stored i-major (`P_ij` at `i * n_v + j`, `i`
//! along `u`), as [`crate::TensorPatch`] (DESIGN.md).
//!
//! Every algorithm reuses the curve kernels: row `i` of the net is contiguous, so the net is
//! a curve in `u` whose "points" have `n_v * (dim + 1)` coordinates, and each row is a curve
//! in `v`.

use super::eval::{blossom, eval_work};
use super::extract::extract_work;
use super::insert::insert_once;
use super::knots::{check_knots, find_span, knot_multiplicity};
use super::refine::refine_work;
use crate::validate::{check_finite_param, check_points, check_weights};
use crate::{Error, Result, TensorPatch, kernel};

/// A tensor-product B-spline (or, with weights, NURBS) surface.
///
/// Invariants (checked by the constructors): `dim >= 1`, degrees `<= MAX_DEGREE`, valid
/// knot vectors in `u` (`n_u + p + 1` knots) and `v` (`n_v + q + 1`), `n_u * n_v` finite
/// points and, if rational, as many finite positive weights.
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineSurface {
    degrees: (usize, usize),
    counts: (usize, usize),
    dim: usize,
    knots_u: Vec<f64>,
    knots_v: Vec<f64>,
    points: Vec<f64>,
    weights: Option<Vec<f64>>,
}

/// One Bézier patch of a [`BSplineSurface`]: the patch on `[0, 1]^2` that reparametrises the
/// surface on `[u.0, u.1] x [v.0, v.1]`.
///
/// Only polynomial patches exist as [`TensorPatch`]; for a NURBS surface `patch` holds the
/// Euclidean control points and `weights` the patch weights (i-major, like the points), as
/// DESIGN.md stores rational objects.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfacePatchPiece {
    /// The `u` interval of the piece.
    pub u: (f64, f64),
    /// The `v` interval of the piece.
    pub v: (f64, f64),
    /// The Euclidean control points of degree `(p, q)`.
    pub patch: TensorPatch,
    /// The weights of a rational piece (`(p + 1) * (q + 1)`, i-major), `None` if polynomial.
    pub weights: Option<Vec<f64>>,
}

impl BSplineSurface {
    /// A polynomial B-spline surface of degrees `(p, q)` with `counts = (n_u, n_v)` control
    /// points, i-major.
    ///
    /// # Errors
    /// [`Error::ZeroDimension`], [`Error::NotEnoughPoints`], [`Error::NonFinite`],
    /// [`Error::LengthMismatch`] (points not `n_u * n_v`), and the knot errors of
    /// [`crate::check_knots`] for each direction.
    ///
    /// ```
    /// # use cagd_core::BSplineSurface;
    /// // A bilinear patch as a B-spline surface.
    /// let s = BSplineSurface::new((1, 1), vec![0.0, 0.0, 1.0, 1.0], vec![0.0, 0.0, 1.0, 1.0],
    ///                             vec![0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 1.0, 1.0], (2, 2), 2)?;
    /// assert_eq!(s.eval(0.25, 0.5)?, vec![0.25, 0.5]);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn new(
        degrees: (usize, usize),
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        points: Vec<f64>,
        counts: (usize, usize),
        dim: usize,
    ) -> Result<Self> {
        Self::build(degrees, knots_u, knots_v, points, None, counts, dim)
    }

    /// A NURBS surface: as [`BSplineSurface::new`] plus `n_u * n_v` weights (i-major).
    ///
    /// # Errors
    /// As [`BSplineSurface::new`], plus [`Error::LengthMismatch`] and
    /// [`Error::NonPositiveWeight`] for the weights.
    pub fn new_rational(
        degrees: (usize, usize),
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        points: Vec<f64>,
        weights: Vec<f64>,
        counts: (usize, usize),
        dim: usize,
    ) -> Result<Self> {
        Self::build(
            degrees,
            knots_u,
            knots_v,
            points,
            Some(weights),
            counts,
            dim,
        )
    }

    fn build(
        degrees: (usize, usize),
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        points: Vec<f64>,
        weights: Option<Vec<f64>>,
        counts: (usize, usize),
        dim: usize,
    ) -> Result<Self> {
        let n = check_points(&points, dim)?;
        let expected = counts.0.saturating_mul(counts.1);
        if n != expected {
            return Err(Error::LengthMismatch {
                what: "surface points (n_u * n_v)",
                got: n,
                expected,
            });
        }
        if let Some(w) = &weights {
            check_weights(w, n)?;
        }
        check_knots(&knots_u, counts.0, degrees.0)?;
        check_knots(&knots_v, counts.1, degrees.1)?;
        Ok(Self {
            degrees,
            counts,
            dim,
            knots_u,
            knots_v,
            points,
            weights,
        })
    }

    /// Degrees `(p, q)` in `u` and `v`.
    pub fn degrees(&self) -> (usize, usize) {
        self.degrees
    }

    /// Control point counts `(n_u, n_v)`.
    pub fn counts(&self) -> (usize, usize) {
        self.counts
    }

    /// Number of coordinates of each point.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The knot vector in `u`.
    pub fn knots_u(&self) -> &[f64] {
        &self.knots_u
    }

    /// The knot vector in `v`.
    pub fn knots_v(&self) -> &[f64] {
        &self.knots_v
    }

    /// The control points, i-major, Euclidean.
    pub fn points(&self) -> &[f64] {
        &self.points
    }

    /// The weights (i-major) of a NURBS surface, `None` if polynomial.
    pub fn weights(&self) -> Option<&[f64]> {
        self.weights.as_deref()
    }

    /// Whether the surface carries weights.
    pub fn is_rational(&self) -> bool {
        self.weights.is_some()
    }

    /// The domain `([u_p, u_{n_u}], [v_q, v_{n_v}])`.
    pub fn domain(&self) -> ((f64, f64), (f64, f64)) {
        let ((p, q), (nu, nv)) = (self.degrees, self.counts);
        (
            (self.knots_u[p], self.knots_u[nu]),
            (self.knots_v[q], self.knots_v[nv]),
        )
    }

    /// Working points: Euclidean (polynomial) or homogeneous (rational), with their dimension.
    fn work(&self) -> (Vec<f64>, usize) {
        match &self.weights {
            None => (self.points.clone(), self.dim),
            Some(w) => {
                let mut h = vec![0.0; w.len() * (self.dim + 1)];
                kernel::to_homogeneous(&self.points, w, self.dim, &mut h);
                (h, self.dim + 1)
            }
        }
    }

    fn rebuild(
        &self,
        ku: Vec<f64>,
        kv: Vec<f64>,
        work: Vec<f64>,
        counts: (usize, usize),
    ) -> Result<Self> {
        match self.weights {
            None => Self::new(self.degrees, ku, kv, work, counts, self.dim),
            Some(_) => {
                let n = counts.0 * counts.1;
                let (mut p, mut w) = (vec![0.0; n * self.dim], vec![0.0; n]);
                kernel::from_homogeneous(&work, self.dim, &mut p, &mut w);
                Self::new_rational(self.degrees, ku, kv, p, w, counts, self.dim)
            }
        }
    }

    /// Evaluates the surface at `(u, v)`: de Boor in `v` on the `p + 1` rows of the `u` span,
    /// then in `u` (homogeneous for NURBS). Outside the domain the boundary pieces are
    /// extrapolated, as for curves.
    ///
    /// # Errors
    /// [`Error::BadParameter`] when `u` or `v` is not finite.
    pub fn eval(&self, u: f64, v: f64) -> Result<Vec<f64>> {
        check_finite_param("u", u)?;
        check_finite_param("v", v)?;
        let ((p, _), (nu, nv)) = (self.degrees, self.counts);
        let (work, pdim) = self.work();
        let row = nv * pdim;
        let s = find_span(&self.knots_u, p, nu, u);
        let mut local = vec![0.0; (p + 1) * pdim];
        for (l, i) in (s - p..=s).enumerate() {
            let out = &mut local[l * pdim..(l + 1) * pdim];
            eval_work(
                &self.knots_v,
                self.degrees.1,
                &work[i * row..(i + 1) * row],
                pdim,
                v,
                out,
            );
        }
        blossom(&self.knots_u, s, p, &mut local, pdim, &vec![u; p]);
        let mut h = local[p * pdim..].to_vec();
        if self.weights.is_some() {
            let w = h[self.dim];
            h.truncate(self.dim);
            h.iter_mut().for_each(|x| *x /= w);
        }
        Ok(h)
    }

    fn check_insert(
        knots: &[f64],
        degree: usize,
        dom: (f64, f64),
        t: f64,
        times: usize,
    ) -> Result<()> {
        check_finite_param("t", t)?;
        if t < dom.0 || t > dom.1 {
            return Err(Error::BadParameter {
                name: "t",
                value: t,
                why: "an inserted knot must lie in the domain",
            });
        }
        let mult = knot_multiplicity(knots, t) + times;
        if mult > degree + 1 {
            return Err(Error::MultiplicityAboveDegree {
                knot: t,
                mult,
                degree,
            });
        }
        Ok(())
    }

    /// Inserts the knot `t` `times` times in the `u` direction (Boehm on the rows of the
    /// net; the surface is unchanged).
    ///
    /// # Errors
    /// [`Error::BadParameter`] (`t` not finite or outside the `u` domain),
    /// [`Error::MultiplicityAboveDegree`].
    pub fn insert_knot_u(&self, t: f64, times: usize) -> Result<Self> {
        Self::check_insert(&self.knots_u, self.degrees.0, self.domain().0, t, times)?;
        let (mut work, pdim) = self.work();
        let mut knots = self.knots_u.clone();
        for _ in 0..times {
            (knots, work) = insert_once(&knots, self.degrees.0, &work, self.counts.1 * pdim, t);
        }
        let counts = (self.counts.0 + times, self.counts.1);
        self.rebuild(knots, self.knots_v.clone(), work, counts)
    }

    /// Inserts the knot `t` `times` times in the `v` direction (Boehm on every row).
    ///
    /// # Errors
    /// As [`BSplineSurface::insert_knot_u`], for the `v` domain.
    pub fn insert_knot_v(&self, t: f64, times: usize) -> Result<Self> {
        Self::check_insert(&self.knots_v, self.degrees.1, self.domain().1, t, times)?;
        let (work, pdim) = self.work();
        let row = self.counts.1 * pdim;
        let mut out = Vec::with_capacity(self.counts.0 * (row + times * pdim));
        let mut knots = self.knots_v.clone();
        for i in 0..self.counts.0 {
            let (mut k, mut r) = (self.knots_v.clone(), work[i * row..(i + 1) * row].to_vec());
            for _ in 0..times {
                (k, r) = insert_once(&k, self.degrees.1, &r, pdim, t);
            }
            out.extend_from_slice(&r);
            knots = k;
        }
        let counts = (self.counts.0, self.counts.1 + times);
        self.rebuild(self.knots_u.clone(), knots, out, counts)
    }

    /// Inserts every value of `new_knots` (any order; a value listed twice is inserted
    /// twice) in the `u` direction at once (knot refinement, Piegl & Tiller Algorithm
    /// A5.4, on the rows of the net; the surface is unchanged). One pass over the net,
    /// where [`BSplineSurface::insert_knot_u`] per value copies the whole net each time
    /// (quadratic in the number of knots: a surface measured against a reduction with
    /// thousands of spans took many minutes in the C ABI fuzz run).
    ///
    /// # Errors
    /// As [`BSplineSurface::insert_knot_u`], for the first value that cannot be inserted.
    pub fn refine_knots_u(&self, new_knots: &[f64]) -> Result<Self> {
        let x =
            self.checked_refinement(&self.knots_u, self.degrees.0, self.domain().0, new_knots)?;
        let (work, pdim) = self.work();
        let (knots, out) = refine_work(
            &self.knots_u,
            self.degrees.0,
            &work,
            self.counts.1 * pdim,
            &x,
        );
        let counts = (self.counts.0 + x.len(), self.counts.1);
        self.rebuild(knots, self.knots_v.clone(), out, counts)
    }

    /// As [`BSplineSurface::refine_knots_u`], in the `v` direction (every row refined).
    ///
    /// # Errors
    /// As [`BSplineSurface::insert_knot_v`], for the first value that cannot be inserted.
    pub fn refine_knots_v(&self, new_knots: &[f64]) -> Result<Self> {
        let x =
            self.checked_refinement(&self.knots_v, self.degrees.1, self.domain().1, new_knots)?;
        let (work, pdim) = self.work();
        let row = self.counts.1 * pdim;
        let mut out = Vec::with_capacity(self.counts.0 * (row + x.len() * pdim));
        let mut knots = self.knots_v.clone();
        for r in work.chunks_exact(row) {
            let (k, q) = refine_work(&self.knots_v, self.degrees.1, r, pdim, &x);
            out.extend_from_slice(&q);
            knots = k;
        }
        let counts = (self.counts.0, self.counts.1 + x.len());
        self.rebuild(self.knots_u.clone(), knots, out, counts)
    }

    /// `new_knots` sorted, after the checks of one insertion per value (with the copies
    /// of equal values counted together).
    fn checked_refinement(
        &self,
        knots: &[f64],
        degree: usize,
        dom: (f64, f64),
        new_knots: &[f64],
    ) -> Result<Vec<f64>> {
        for &t in new_knots {
            check_finite_param("t", t)?;
        }
        let mut x = new_knots.to_vec();
        x.sort_by(f64::total_cmp);
        for run in x.chunk_by(|a, b| a == b) {
            Self::check_insert(knots, degree, dom, run[0], run.len())?;
        }
        Ok(x)
    }

    /// Every non-empty span rectangle as a Bézier patch, `u` spans outer, `v` spans inner
    /// (blossoming in `u` on the rows of the net, then in `v`; see
    /// [`BSplineCurve::to_beziers`](crate::BSplineCurve::to_beziers)). For a NURBS surface
    /// each piece carries its weights (see [`SurfacePatchPiece`]).
    ///
    /// # Errors
    /// Only when a piece is not representable ([`Error::NonFinite`] after an overflow).
    pub fn to_beziers(&self) -> Result<Vec<SurfacePatchPiece>> {
        let ((p, q), nv) = (self.degrees, self.counts.1);
        let (work, pdim) = self.work();
        let mut out = Vec::new();
        for (ua, ub, rows) in extract_work(&self.knots_u, p, &work, nv * pdim) {
            // For each of the p + 1 rows, its v pieces.
            let per_row: Vec<_> = (0..=p)
                .map(|i| {
                    extract_work(
                        &self.knots_v,
                        q,
                        &rows[i * nv * pdim..(i + 1) * nv * pdim],
                        pdim,
                    )
                })
                .collect();
            for (jv, &(va, vb, _)) in per_row[0].iter().enumerate() {
                let mut net = Vec::with_capacity((p + 1) * (q + 1) * pdim);
                for row in &per_row {
                    net.extend_from_slice(&row[jv].2);
                }
                let (patch, weights) = match self.weights {
                    None => (TensorPatch::new(net, p, q, self.dim)?, None),
                    Some(_) => {
                        let n = (p + 1) * (q + 1);
                        check_points(&net, pdim)?;
                        let (mut pts, mut w) = (vec![0.0; n * self.dim], vec![0.0; n]);
                        kernel::from_homogeneous(&net, self.dim, &mut pts, &mut w);
                        check_weights(&w, n)?;
                        (TensorPatch::new(pts, p, q, self.dim)?, Some(w))
                    }
                };
                out.push(SurfacePatchPiece {
                    u: (ua, ub),
                    v: (va, vb),
                    patch,
                    weights,
                });
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests;
