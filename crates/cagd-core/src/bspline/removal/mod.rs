//! Knot removal within a tolerance (Tiller 1992; the idea of Piegl & Tiller, "The NURBS
//! Book", §5.4, algorithm A5.8, written anew here).
//!
//! Removing one copy of an interior knot `u` (last index `r`, multiplicity `s`) keeps the
//! points `Q_i = P_i` for `i < r - p` and `Q_i = P_{i+1}` for `i >= r - s`, and solves the
//! `p - s` unknown points from the `p - s + 1` knot-insertion equations
//! `P_i = a_i Q_i + (1 - a_i) Q_{i-1}`, `a_i = (u - u_i) / (u_{i+p+1} - u_i)`,
//! `i = r-p..=r-s`, from both ends. One equation `k` is left over and only its point moves.
//! A5.8 meets in the middle (and averages in the odd case); here `k` is where `a_i`
//! (non-increasing in `i`) crosses `1/2`, so the left sweep divides by `a_i >= 1/2` and the
//! right one by `1 - a_i > 1/2` and rounding is never amplified — the middle choice loses
//! a factor `~(1/a)^(p/2)` for a knot near a neighbour. For `s = p + 1` (no equations) the
//! two end points of the pieces are averaged.
//!
//! **Certified bound.** Re-inserting `u` into the new curve gives points `P'_i` on the old
//! knot vector, and `C(t) - C'(t) = sum_i N_i(t) (P_i - P'_i)`, so by the partition of unity
//! `max_t ||C - C'||_2 <= eps = max_i ||P_i - P'_i||_2` (Euclidean norm; this is the quantity
//! A5.8 compares with its tolerance). For NURBS the removal is done on the homogeneous
//! points `(w P, w)` as in Piegl & Tiller, and `eps` is measured in homogeneous space
//! (`dim + 1` coordinates); it is turned into a bound in model space from
//! `C - C' = ((A - A') + C (W' - W)) / W'` (the form of Piegl & Tiller eq. 5.30) taken
//! about the centre `c` of the control points' bounding box: with `A_c = A - c W` and
//! `R = max_i ||P_i - c||`, `max_t ||C - C'||_2 <= (max_i ||dA_i - c dW_i|| + R max_i |dW_i|)
//! / min_i w'_i`, which is the bound reported. (Piegl & Tiller's `eps (1 + max ||P||) /
//! min w'` grows with the distance of the curve from the origin; the centred form does
//! not.) Removals accumulate: the reported bound is the sum of the bounds of
//! the single removals (triangle inequality) and never exceeds the caller's tolerance.
//!

use super::insert::insert_once;
use super::knots::knot_multiplicity;
use crate::validate::{check_finite_param, check_tolerance};
use crate::{BSplineCurve, Error, Result};

/// The result of a knot removal.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotRemoval {
    /// The curve with the knots removed.
    pub curve: BSplineCurve,
    /// How many knots were removed (may be `0`).
    pub removed: usize,
    /// A certified upper bound of `max_t ||C(t) - C'(t)||_2` over the domain, in model
    /// units (Euclidean norm), `<= tol`.
    pub error_bound: f64,
}

/// Removes one copy of the knot with last index `r` from the spline `(u, work)` of degree
/// `p` (points of dimension `pdim`); returns the new knots and points, and the new points
/// re-inserted on the old knots (to compare with `work`).
fn remove_once(
    u: &[f64],
    p: usize,
    work: &[f64],
    pdim: usize,
    r: usize,
) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let n = work.len() / pdim;
    let t = u[r];
    let s = u[..=r].iter().rev().take_while(|x| **x == t).count();
    let mut q = vec![0.0; (n - 1) * pdim];
    let alpha = |i: usize| (t - u[i]) / (u[i + p + 1] - u[i]);
    if s == p + 1 {
        // The curve may jump at u: average the two end points of the pieces.
        let f = r - p - 1;
        q[..f * pdim].copy_from_slice(&work[..f * pdim]);
        q[f * pdim..].copy_from_slice(&work[(f + 1) * pdim..]);
        for c in 0..pdim {
            q[f * pdim + c] = 0.5 * (work[f * pdim + c] + work[(f + 1) * pdim + c]);
        }
    } else {
        let (first, last) = (r - p, r - s);
        q[..first * pdim].copy_from_slice(&work[..first * pdim]);
        q[last * pdim..].copy_from_slice(&work[(last + 1) * pdim..]);
        // Drop equation k where a_i (non-increasing in i) crosses 1/2: the left sweep then
        // divides by a_i >= 1/2 and the right sweep by 1 - a_i > 1/2, so neither amplifies.
        // Ties (a_i = 1/2, growth factor 1 either way) are split evenly, so a symmetric
        // configuration drops the middle equation as A5.8 does.
        let above = (first..=last).filter(|&i| alpha(i) > 0.5).count();
        let half = (first..=last).filter(|&i| alpha(i) == 0.5).count();
        let k = (first + above + half / 2).min(last);
        for i in first..k {
            let ai = alpha(i);
            for c in 0..pdim {
                q[i * pdim + c] = (work[i * pdim + c] - (1.0 - ai) * q[(i - 1) * pdim + c]) / ai;
            }
        }
        for i in (k + 1..=last).rev() {
            let ai = alpha(i);
            for c in 0..pdim {
                q[(i - 1) * pdim + c] = (work[i * pdim + c] - ai * q[i * pdim + c]) / (1.0 - ai);
            }
        }
    }
    let mut knots = u.to_vec();
    knots.remove(r);
    let (_, back) = insert_once(&knots, p, &q, pdim, t);
    (knots, q, back)
}

/// `max_i ||a_i - b_i||` over points of `pdim` coordinates (`inf` if a difference is NaN).
fn max_distance(a: &[f64], b: &[f64], pdim: usize) -> f64 {
    a.chunks_exact(pdim)
        .zip(b.chunks_exact(pdim))
        .map(|(x, y)| {
            x.iter()
                .zip(y)
                .map(|(p, q)| (p - q) * (p - q))
                .sum::<f64>()
                .sqrt()
        })
        .fold(
            0.0f64,
            |m, e| if e.is_nan() { f64::INFINITY } else { m.max(e) },
        )
}

/// The model-space bound of a NURBS change from homogeneous points `old` to `new` (both
/// `dim + 1` coordinates, on the same knots; `old` the curve's, whose model points are
/// `points`), whose weights are at least `wmin` after the change. With a centre `c` (the
/// middle of the bounding box of `points`) and `R = max ||P_i - c||`:
/// `C - C' = ((C - c)(W' - W) + (A_c - A'_c)) / W'` with `A_c = A - c W`, so
/// `max ||C - C'|| <= (max_i ||dA_i - c dW_i|| + R max_i |dW_i|) / wmin` — independent of
/// where the curve sits, unlike `eps (1 + max ||P||) / wmin`.
fn centred_change_bound(old: &[f64], new: &[f64], points: &[f64], dim: usize, wmin: f64) -> f64 {
    let frame = crate::ModelFrame::new(points, dim);
    let (centre, radius) = (frame.centre(), frame.radius());
    let (mut ea, mut ew) = (0.0f64, 0.0f64);
    for (a, b) in old.chunks_exact(dim + 1).zip(new.chunks_exact(dim + 1)) {
        let dw = a[dim] - b[dim];
        let da = (0..dim)
            .map(|c| {
                let d = (a[c] - b[c]) - centre[c] * dw;
                d * d
            })
            .sum::<f64>()
            .sqrt();
        if da.is_nan() || dw.is_nan() {
            return f64::INFINITY;
        }
        ea = ea.max(da);
        ew = ew.max(dw.abs());
    }
    crate::centred_rational_bound(ea, ew, radius, wmin, wmin)
}

/// The weight coordinates (every `block`-th, the last of each block) of a bundle's points.
fn block_weights(points: &[f64], block: usize) -> impl Iterator<Item = f64> + '_ {
    points.chunks_exact(block).map(move |q| q[block - 1])
}

/// The model points `x / w` of every homogeneous point of `block` coordinates in `work`.
fn model_points(work: &[f64], block: usize) -> Vec<f64> {
    let dim = block - 1;
    let mut out = Vec::with_capacity(work.len() / block * dim);
    for q in work.chunks_exact(block) {
        out.extend(q[..dim].iter().map(|x| x / q[dim]));
    }
    out
}

impl BSplineCurve {
    /// Removes one copy of the interior knot with last index `r`, if the result is a valid
    /// curve; returns it with the certified model-space bound of the change. With
    /// `bundle = Some(block)` the (polynomial) curve is read as a bundle of NURBS curves of
    /// homogeneous points with `block` coordinates (see
    /// [`BSplineCurve::remove_knot_rational_bundle`]).
    fn remove_one(&self, r: usize, bundle: Option<usize>) -> Option<(BSplineCurve, f64)> {
        let (work, pdim) = self.work_points();
        let (knots, q, back) = remove_once(&self.knots, self.degree, &work, pdim, r);
        let eps = max_distance(&work, &back, pdim);
        if !eps.is_finite() {
            return None;
        }
        let curve = self.rebuild_from_work(knots, q).ok()?;
        let bound = match (bundle, curve.weights()) {
            (Some(block), _) => {
                let wmin = block_weights(curve.points(), block).fold(f64::INFINITY, f64::min);
                if wmin.is_nan() || wmin <= 0.0 {
                    return None;
                }
                let model = model_points(&work, block);
                centred_change_bound(&work, &back, &model, block - 1, wmin)
            }
            (None, None) => eps,
            (None, Some(w)) => {
                let wmin = w.iter().fold(f64::INFINITY, |m, x| m.min(*x));
                centred_change_bound(&work, &back, &self.points, self.dim, wmin)
            }
        };
        bound.is_finite().then_some((curve, bound))
    }

    /// Last index of the interior knot `value`, or `None`.
    fn interior_last_index(&self, value: f64) -> Option<usize> {
        let (a, b) = self.domain();
        if !(value > a && value < b) || knot_multiplicity(&self.knots, value) == 0 {
            return None;
        }
        Some(self.knots.partition_point(|x| *x <= value) - 1)
    }

    /// Removes up to `times` copies of the interior knot `value` while the accumulated
    /// certified bound stays `<= tol` (see the module docs for the bound; Euclidean norm,
    /// model units; for NURBS converted from homogeneous space). Stops at the first copy
    /// that cannot be removed; `removed` says how many were.
    ///
    /// Measured: a knot inserted into a curve is removed again with the original points
    /// recovered to `1e-12` relative; for a genuine knot, the distance measured by dense
    /// sampling is below the reported bound (tests and proptest, degrees 1..=6).
    ///
    /// # Errors
    /// [`Error::BadTolerance`]; [`Error::BadParameter`] when `value` is not finite or not
    /// an interior knot (`u_p < value < u_n`).
    ///
    /// ```
    /// # use cagd_core::BSplineCurve;
    /// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
    ///                           vec![0.0, 0.0, 1.0, 2.0, 2.0, 0.0], 2)?;
    /// let finer = c.insert_knot(0.3, 1)?;
    /// let back = finer.remove_knot(0.3, 1, 1e-9)?;
    /// assert_eq!(back.removed, 1);
    /// assert!(back.error_bound < 1e-14);
    /// assert_eq!(back.curve.n_points(), 3);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    pub fn remove_knot(&self, value: f64, times: usize, tol: f64) -> Result<KnotRemoval> {
        self.remove_copies(value, times, tol, None)
    }

    /// As [`BSplineCurve::remove_knot`] for a *bundle of NURBS curves* stored as one
    /// polynomial curve: each control point is `dim / block` homogeneous points
    /// `(w P, w)` of `block` coordinates side by side (the columns of a NURBS surface's
    /// net, which share the `u` knots). The bound is the model-space bound of every
    /// rational combination of the bundle with non-negative coefficients — in particular of
    /// the surface `S(u, v) = sum_j M_j(v) A_j(u) / sum_j M_j(v) W_j(u)`: with a centre `c`
    /// of all the bundle's model points and `R` their largest distance from it,
    /// `||S - S'|| <= (max ||dA - c dW|| + R max |dW|) / min w'` over every homogeneous
    /// point of the bundle (the module docs' centred form; `S` lies in the hull of the
    /// model points, `W' >= min w'` by the partition of unity). A removal that would make a
    /// weight non-positive is not done.
    ///
    /// # Errors
    /// As [`BSplineCurve::remove_knot`]; [`Error::BadParameter`] when the curve is rational,
    /// `block < 2`, `dim` is not a multiple of `block`, or a weight coordinate is not
    /// positive.
    pub fn remove_knot_rational_bundle(
        &self,
        value: f64,
        times: usize,
        tol: f64,
        block: usize,
    ) -> Result<KnotRemoval> {
        let bad = |why: &'static str| Error::BadParameter {
            name: "block",
            value: block as f64,
            why,
        };
        if self.weights.is_some() {
            return Err(bad(
                "a bundle is stored as a polynomial curve of homogeneous points",
            ));
        }
        if block < 2 || self.dim % block != 0 {
            return Err(bad("must be at least 2 and divide the dimension"));
        }
        if let Some(w) = block_weights(&self.points, block).find(|w| w.is_nan() || *w <= 0.0) {
            return Err(Error::BadParameter {
                name: "weights",
                value: w,
                why: "every weight coordinate of the bundle must be positive",
            });
        }
        self.remove_copies(value, times, tol, Some(block))
    }

    /// The body of [`BSplineCurve::remove_knot`] and
    /// [`BSplineCurve::remove_knot_rational_bundle`].
    fn remove_copies(
        &self,
        value: f64,
        times: usize,
        tol: f64,
        bundle: Option<usize>,
    ) -> Result<KnotRemoval> {
        check_tolerance(tol)?;
        check_finite_param("value", value)?;
        if self.interior_last_index(value).is_none() {
            return Err(Error::BadParameter {
                name: "value",
                value,
                why: "must be an interior knot (u_p < value < u_n)",
            });
        }
        let mut out = KnotRemoval {
            curve: self.clone(),
            removed: 0,
            error_bound: 0.0,
        };
        while out.removed < times {
            let Some(r) = out.curve.interior_last_index(value) else {
                break;
            };
            match out.curve.remove_one(r, bundle) {
                Some((c, b)) if out.error_bound + b <= tol => {
                    out.curve = c;
                    out.removed += 1;
                    out.error_bound += b;
                }
                _ => break,
            }
        }
        Ok(out)
    }

    /// As [`BSplineCurve::remove_knot`], with the knot given by its index in
    /// [`BSplineCurve::knots`].
    ///
    /// # Errors
    /// As [`BSplineCurve::remove_knot`]; [`Error::BadParameter`] for an index out of range.
    pub fn remove_knot_at(&self, index: usize, times: usize, tol: f64) -> Result<KnotRemoval> {
        match self.knots.get(index) {
            Some(&v) => self.remove_knot(v, times, tol),
            None => Err(Error::BadParameter {
                name: "index",
                value: index as f64,
                why: "knot index out of range",
            }),
        }
    }

    /// Removes as many interior knots as possible with the accumulated certified bound
    /// `<= tol`: greedy passes over the distinct interior knots, each removing copies while
    /// the budget allows, until a pass removes nothing.
    ///
    /// # Errors
    /// [`Error::BadTolerance`].
    pub fn remove_knots(&self, tol: f64) -> Result<KnotRemoval> {
        check_tolerance(tol)?;
        let mut out = KnotRemoval {
            curve: self.clone(),
            removed: 0,
            error_bound: 0.0,
        };
        loop {
            let before = out.removed;
            let mut values: Vec<f64> = out.curve.knots.clone();
            values.dedup();
            for v in values {
                while let Some(r) = out.curve.interior_last_index(v) {
                    match out.curve.remove_one(r, None) {
                        Some((c, b)) if out.error_bound + b <= tol => {
                            out.curve = c;
                            out.removed += 1;
                            out.error_bound += b;
                        }
                        _ => break,
                    }
                }
            }
            if out.removed == before {
                return Ok(out);
            }
        }
    }
}

#[cfg(test)]
mod tests;
