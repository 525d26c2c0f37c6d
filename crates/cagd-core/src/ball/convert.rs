//! Exact conversion between WSGB(n, L) and Bézier control points (SPEC-reduce §9.1:
//! `K u^a (1-u)^b = sum_{k=a}^{n-b} K C(n-a-b, k-a) / C(n, k) B_k^n`), on exact rationals
//! and, for `f64` points, exactly with one rounding at the end.

use num_rational::BigRational;
use num_traits::Zero;

use super::scalar::{round_exact_points, to_exact_points};
use super::{WsgbCurve, check_wsgb_order};
use crate::{
    Basis, BezierCurve, Error, ExactMatrix, Result, check_points, from_bernstein_exact,
    to_bernstein_exact,
};

/// `out_i = sum_j m_ij p_j` for every coordinate, exactly.
fn apply(m: &ExactMatrix, pts: &[BigRational], dim: usize) -> Vec<BigRational> {
    let mut out = vec![BigRational::zero(); m.nrows() * dim];
    for i in 0..m.nrows() {
        for (j, a) in m.row(i).iter().enumerate() {
            if a.is_zero() {
                continue;
            }
            for d in 0..dim {
                let p = &pts[j * dim + d];
                if !p.is_zero() {
                    out[i * dim + d] += a * p;
                }
            }
        }
    }
    out
}

/// Number of points of an exact buffer, checked against `dim` and the order `l`.
fn exact_count(points: &[BigRational], dim: usize, l: usize) -> Result<usize> {
    if dim == 0 {
        return Err(Error::ZeroDimension);
    }
    if points.is_empty() || points.len() % dim != 0 {
        return Err(Error::LengthMismatch {
            what: "exact WSGB points (length must be a positive multiple of dim)",
            got: points.len(),
            expected: (points.len() / dim).max(1) * dim,
        });
    }
    let np = points.len() / dim;
    check_wsgb_order(np - 1, l)?;
    Ok(np)
}

/// The Bézier points of the WSGB(n, L) curve with exact points `points` (flat, `dim`
/// coordinates each): `b = D p`, `D` the exact WSGB -> Bernstein matrix of SPEC-reduce §9.1.
///
/// # Errors
/// [`Error::ZeroDimension`], [`Error::LengthMismatch`], [`Error::DegreeOutOfRange`],
/// [`Error::BadParameter`] (bad `l`).
pub fn wsgb_to_bezier_exact(
    points: &[BigRational],
    dim: usize,
    l: usize,
) -> Result<Vec<BigRational>> {
    let np = exact_count(points, dim, l)?;
    let m = to_bernstein_exact(Basis::Wsgb { l }, np - 1)?;
    Ok(apply(&m, points, dim))
}

/// The WSGB(n, L) points of the Bézier curve with exact points `points`: `p = D^-1 b`
/// (the exact inverse of the §9.1 matrix).
///
/// # Errors
/// As [`wsgb_to_bezier_exact`].
pub fn bezier_to_wsgb_exact(
    points: &[BigRational],
    dim: usize,
    l: usize,
) -> Result<Vec<BigRational>> {
    let np = exact_count(points, dim, l)?;
    let m = from_bernstein_exact(Basis::Wsgb { l }, np - 1)?;
    Ok(apply(&m, points, dim))
}

impl WsgbCurve {
    /// The same polynomial curve in Bézier form, computed exactly from the `f64` points and
    /// rounded once (each Bézier point is within half an ulp of the exact one).
    ///
    /// # Errors
    /// None for a valid curve (the `Result` carries the basis cache's errors).
    pub fn to_bezier(&self) -> Result<BezierCurve> {
        let exact =
            wsgb_to_bezier_exact(&to_exact_points(self.points()), self.dim(), self.order())?;
        BezierCurve::new(round_exact_points(&exact), self.dim())
    }

    /// The WSGB(n, `l`) form of a polynomial Bézier curve, computed exactly and rounded once.
    /// Every admissible `l` represents every polynomial of degree `<= n`.
    ///
    /// # Errors
    /// [`Error::BadParameter`] for `l` out of range; [`Error::ConditionNotMet`] for a
    /// rational curve (cagd has no rational WSGB curves).
    pub fn from_bezier(curve: &BezierCurve, l: usize) -> Result<WsgbCurve> {
        if curve.is_rational() {
            return Err(Error::ConditionNotMet {
                eq: "SPEC-reduce §9.1 (WSGB curves are polynomial)",
                why: "a rational Bézier curve has no WSGB form",
            });
        }
        check_points(curve.points(), curve.dim())?;
        let exact = bezier_to_wsgb_exact(&to_exact_points(curve.points()), curve.dim(), l)?;
        WsgbCurve::new(round_exact_points(&exact), curve.dim(), l)
    }

    /// The same curve in WSGB(n, `l`) form for another order `l` (exact, rounded once).
    ///
    /// # Errors
    /// [`Error::BadParameter`] for `l` out of range.
    pub fn with_order(&self, l: usize) -> Result<WsgbCurve> {
        check_wsgb_order(self.degree(), l)?;
        if l == self.order() {
            return Ok(self.clone());
        }
        let b = wsgb_to_bezier_exact(&to_exact_points(self.points()), self.dim(), self.order())?;
        let p = bezier_to_wsgb_exact(&b, self.dim(), l)?;
        WsgbCurve::new(round_exact_points(&p), self.dim(), l)
    }
}
