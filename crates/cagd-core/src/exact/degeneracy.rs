//! The degeneracy invariants of seed 000 §14.1 (Theorem 14.1.1, eqs. 14.1.1–14.1.3,
//! SPEC-reduce §1) in exact rational arithmetic, for control points given exactly (the
//! spec vectors' `*_exact` inputs): an elevated curve or patch then gives invariants that
//! are exactly zero, which `f64` arithmetic on rounded inputs cannot show.
//!
//! The `f64` versions are [`crate::BezierCurve::forward_difference`],
//! [`crate::TensorPatch::degeneracy_invariants`] and
//! [`crate::TriPatch::degeneracy_invariants`]; these compute the same sums exactly.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

use crate::{Error, Result, check_degree, tri_count, tri_index, try_binomial};

/// `(-1)^(n-i) C(n, i)` exactly.
fn sign_binomial(n: usize, i: usize) -> Result<BigRational> {
    let b = BigRational::from_integer(BigInt::from(try_binomial(n, i)?));
    Ok(if (n - i) % 2 == 0 { b } else { -b })
}

/// Checks that `points` holds `count` points of dimension `dim >= 1`.
fn check_count(points: &[BigRational], count: usize, dim: usize) -> Result<()> {
    if dim == 0 || points.len() != count * dim {
        return Err(Error::LengthMismatch {
            what: "exact control points",
            got: points.len(),
            expected: count * dim.max(1),
        });
    }
    Ok(())
}

/// Eq. 14.1.1: `F = Delta^n P_0 = sum_i (-1)^(n-i) C(n,i) P_i` of a degree-`n` Bézier curve
/// (`n + 1` points of dimension `dim`, flat row-major); zero iff the degree is `< n`.
///
/// # Errors
/// [`Error::LengthMismatch`] (the point count is not a multiple of `dim`, or no point);
/// [`Error::DegreeOutOfRange`].
pub fn curve_invariant_exact(points: &[BigRational], dim: usize) -> Result<Vec<BigRational>> {
    if dim == 0 || points.is_empty() || points.len() % dim != 0 {
        return Err(Error::LengthMismatch {
            what: "exact control points",
            got: points.len(),
            expected: dim.max(1),
        });
    }
    let n = points.len() / dim - 1;
    check_degree(n)?;
    let mut f = vec![BigRational::zero(); dim];
    for (i, p) in points.chunks_exact(dim).enumerate() {
        let c = sign_binomial(n, i)?;
        for (fk, x) in f.iter_mut().zip(p) {
            *fk += &c * x;
        }
    }
    Ok(f)
}

/// Eq. 14.1.2: `F_j = sum_i (-1)^(m-i) C(m,i) P_ij` (`j = 0..=n`) and
/// `G_i = sum_j (-1)^(n-j) C(n,j) P_ij` (`i = 0..=m`) of a degree-`(m, n)` tensor patch
/// (i-major points), returned flat.
///
/// # Errors
/// [`Error::LengthMismatch`]; [`Error::DegreeOutOfRange`].
pub fn tensor_invariants_exact(
    points: &[BigRational],
    m: usize,
    n: usize,
    dim: usize,
) -> Result<(Vec<BigRational>, Vec<BigRational>)> {
    check_degree(m)?;
    check_degree(n)?;
    check_count(points, (m + 1) * (n + 1), dim)?;
    let mut f = vec![BigRational::zero(); (n + 1) * dim];
    let mut g = vec![BigRational::zero(); (m + 1) * dim];
    for i in 0..=m {
        let ci = sign_binomial(m, i)?;
        for j in 0..=n {
            let dj = sign_binomial(n, j)?;
            let p = &points[(i * (n + 1) + j) * dim..][..dim];
            for (k, x) in p.iter().enumerate() {
                f[j * dim + k] += &ci * x;
                g[i * dim + k] += &dj * x;
            }
        }
    }
    Ok((f, g))
}

/// Eq. 14.1.3: `F_k = sum_{i<=k} sum_{j<=n-k} (-1)^(n-i-j) C(k,i) C(n-k,j) T_ij`
/// (`k = 0..=n`) of a degree-`n` triangular patch (i-major points), returned flat.
///
/// # Errors
/// [`Error::LengthMismatch`]; [`Error::DegreeOutOfRange`].
pub fn tri_invariants_exact(
    points: &[BigRational],
    n: usize,
    dim: usize,
) -> Result<Vec<BigRational>> {
    check_degree(n)?;
    check_count(points, tri_count(n), dim)?;
    let mut f = vec![BigRational::zero(); (n + 1) * dim];
    for k in 0..=n {
        for i in 0..=k {
            for j in 0..=n - k {
                let mut c = BigRational::from_integer(BigInt::from(
                    try_binomial(k, i)? * try_binomial(n - k, j)?,
                ));
                if (n - i - j) % 2 == 1 {
                    c = -c;
                }
                let p = &points[tri_index(n, i, j) * dim..][..dim];
                for (d, x) in p.iter().enumerate() {
                    f[k * dim + d] += &c * x;
                }
            }
        }
    }
    Ok(f)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BezierCurve, TensorPatch, TriPatch};
    use num_traits::ToPrimitive;

    fn q(x: f64) -> BigRational {
        BigRational::from_float(x).unwrap()
    }

    fn to_f64(v: &[BigRational]) -> Vec<f64> {
        v.iter().map(|x| x.to_f64().unwrap()).collect()
    }

    #[test]
    fn agree_with_the_f64_invariants_on_integer_data() {
        let pts = [0.0, 0.0, 1.0, 3.0, 3.0, 4.0, 5.0, 1.0, 6.0, 5.0];
        let c = BezierCurve::new(pts.to_vec(), 2).unwrap();
        let e: Vec<_> = pts.iter().map(|&x| q(x)).collect();
        assert_eq!(
            to_f64(&curve_invariant_exact(&e, 2).unwrap()),
            c.forward_difference()
        );

        let tp: Vec<f64> = (0..18).map(|i| f64::from((i * 7 + 3) % 11)).collect();
        let t = TensorPatch::new(tp.clone(), 2, 2, 2).unwrap();
        let (f, g) =
            tensor_invariants_exact(&tp.iter().map(|&x| q(x)).collect::<Vec<_>>(), 2, 2, 2)
                .unwrap();
        assert_eq!((to_f64(&f), to_f64(&g)), t.degeneracy_invariants());

        let rp: Vec<f64> = (0..10).map(|i| f64::from((i * 5 + 1) % 7)).collect();
        let r = TriPatch::new(rp.clone(), 3, 1).unwrap();
        let f = tri_invariants_exact(&rp.iter().map(|&x| q(x)).collect::<Vec<_>>(), 3, 1).unwrap();
        assert_eq!(to_f64(&f), r.degeneracy_invariants());
    }

    #[test]
    fn elevated_triangle_with_thirds_is_exactly_degenerate() {
        // A degree-1 triangle elevated to 2 exactly: T_ij = (i a + j b + k c)/2 with
        // coordinates that are not binary fractions after elevation (thirds at degree 3).
        let third = |a: i64| BigRational::new(a.into(), 3.into());
        // Degree 2 -> 3 of the linear function 1 + u: T_ij = 1 + i/3.
        let pts: Vec<BigRational> = (0..=3usize)
            .flat_map(|i| (0..=3 - i).map(move |_| i))
            .map(|i| third(3 + i64::try_from(i).unwrap()))
            .collect();
        let f = tri_invariants_exact(&pts, 3, 1).unwrap();
        assert!(f.iter().all(Zero::is_zero));
        assert!(tri_invariants_exact(&pts[1..], 3, 1).is_err());
        assert!(curve_invariant_exact(&[], 2).is_err());
    }
}
