//! Exact conversion between WSGB(n, L) and Bézier control points (SPEC-reduce §9.1:
//! `K u^a (1-u)^b = sum_{k=a}^{n-b} K C(n-a-b, k-a) / C(n, k) B_k^n`), on exact rationals
//! and, for `f64` points, exactly with one rounding at the end.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};

use super::scalar::{round_exact_points, to_exact_points};
use super::{WsgbCurve, check_wsgb_order};
use crate::{
    Basis, BezierCurve, Error, ExactMatrix, Result, check_points, from_bernstein_exact,
    to_bernstein_exact,
};

/// A basis-change matrix with each row over one common denominator: row `i` is
/// `num[i][j] / den[i]`, integers, so that a product with integer vectors needs no fraction
/// arithmetic until the end.
struct IntRows {
    num: Vec<Vec<BigInt>>,
    den: Vec<BigInt>,
}

fn int_rows(m: &ExactMatrix) -> IntRows {
    let mut num = Vec::with_capacity(m.nrows());
    let mut den = Vec::with_capacity(m.nrows());
    for i in 0..m.nrows() {
        let row = m.row(i);
        let l = row.iter().fold(BigInt::one(), |acc, x| acc.lcm(x.denom()));
        num.push(row.iter().map(|x| x.numer() * (&l / x.denom())).collect());
        den.push(l);
    }
    IntRows { num, den }
}

/// The integer-row form of the WSGB(n, l) <-> Bernstein matrices, cached per
/// `(n, l, to_bezier)`.
fn cached_rows(n: usize, l: usize, to_bezier: bool) -> Result<Arc<IntRows>> {
    type Cache = OnceLock<Mutex<HashMap<(usize, usize, bool), Arc<IntRows>>>>;
    static CACHE: Cache = OnceLock::new();
    let cache = CACHE.get_or_init(Default::default);
    let key = (n, l, to_bezier);
    if let Some(r) = cache
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .get(&key)
    {
        return Ok(Arc::clone(r));
    }
    let m = if to_bezier {
        to_bernstein_exact(Basis::Wsgb { l }, n)?
    } else {
        from_bernstein_exact(Basis::Wsgb { l }, n)?
    };
    let rows = Arc::new(int_rows(&m));
    cache
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .insert(key, Arc::clone(&rows));
    Ok(rows)
}

/// `out_i = sum_j m_ij p_j` for every coordinate, exactly: per coordinate the points over
/// one common denominator, integer dot products, one fraction per output.
fn apply(m: &IntRows, pts: &[BigRational], dim: usize) -> Vec<BigRational> {
    let np = pts.len() / dim;
    let mut out = vec![BigRational::zero(); m.num.len() * dim];
    for d in 0..dim {
        let col: Vec<&BigRational> = (0..np).map(|j| &pts[j * dim + d]).collect();
        let cden = col.iter().fold(BigInt::one(), |acc, x| acc.lcm(x.denom()));
        let ints: Vec<BigInt> = col
            .iter()
            .map(|x| x.numer() * (&cden / x.denom()))
            .collect();
        for (i, (row, rden)) in m.num.iter().zip(&m.den).enumerate() {
            let mut s = BigInt::zero();
            for (a, p) in row.iter().zip(&ints) {
                if !a.is_zero() && !p.is_zero() {
                    s += a * p;
                }
            }
            out[i * dim + d] = BigRational::new(s, rden * &cden);
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
    let rows = cached_rows(np - 1, l, true)?;
    Ok(apply(&rows, points, dim))
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
    let rows = cached_rows(np - 1, l, false)?;
    Ok(apply(&rows, points, dim))
}

impl WsgbCurve {
    /// The same polynomial curve in Bézier form, computed exactly from the `f64` points and
    /// rounded once (each Bézier point is within half an ulp of the exact one).
    /// (SPEC-reduce §9.1 basis.)
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
    /// (SPEC-reduce §9.1 basis, inverted exactly.)
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
