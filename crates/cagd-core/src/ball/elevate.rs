//! Degree elevation WSGB(n-1, L') -> WSGB(n, L) (seed 003 Lemma 3, reference [9]), exact.

use num_bigint::BigInt;
use num_rational::BigRational;

use super::convert::{bezier_to_wsgb_exact, wsgb_to_bezier_exact};
use super::scalar::{round_exact_points, to_exact_points};
use super::{WsgbCurve, check_wsgb_order};
use crate::Result;

/// Exact Bézier elevation by one degree: `b'_i = (i/(n+1)) b_{i-1} + (1 - i/(n+1)) b_i`.
fn bezier_elevate_exact(b: &[BigRational], dim: usize) -> Vec<BigRational> {
    let n = b.len() / dim - 1;
    let np1 = BigInt::from(n + 1);
    let mut out = Vec::with_capacity((n + 2) * dim);
    for i in 0..=n + 1 {
        let wl = BigRational::new(BigInt::from(i), np1.clone());
        let wr = BigRational::new(BigInt::from(n + 1 - i), np1.clone());
        for d in 0..dim {
            let mut v = BigRational::default();
            if i > 0 {
                v += &wl * &b[(i - 1) * dim + d];
            }
            if i <= n {
                v += &wr * &b[i * dim + d];
            }
            out.push(v);
        }
    }
    out
}

/// The exact WSGB(n+1, `l_to`) points of the WSGB(n, `l_from`) curve with exact points
/// `points`: through the Bézier form (SPEC-reduce §9.1 conversion, Bézier elevation, back).
///
/// # Errors
/// [`crate::Error::BadParameter`] for an order out of range, [`crate::Error::DegreeOutOfRange`]
/// for `n + 1 > MAX_DEGREE`, [`crate::Error::LengthMismatch`] / [`crate::Error::ZeroDimension`]
/// for a bad buffer.
pub fn wsgb_elevate_exact(
    points: &[BigRational],
    dim: usize,
    l_from: usize,
    l_to: usize,
) -> Result<Vec<BigRational>> {
    let b = wsgb_to_bezier_exact(points, dim, l_from)?;
    let n = b.len() / dim - 1;
    check_wsgb_order(n + 1, l_to)?;
    bezier_to_wsgb_exact(&bezier_elevate_exact(&b, dim), dim, l_to)
}

impl WsgbCurve {
    /// The same curve as WSGB(n+1, `l`) (degree elevation, exact and rounded once).
    ///
    /// ```
    /// use cagd_core::WsgbCurve;
    /// let c = WsgbCurve::new(vec![0.0, 1.0, 3.0, 2.0, 5.0], 1, 0)?; // Said–Ball, n = 4
    /// let e = c.elevate(1)?; // WSGB(5, 1)
    /// assert_eq!((e.degree(), e.order()), (5, 1));
    /// assert!(e.is_degenerate());
    /// // Back to degree 4 with L' = min(1, max(floor(4/2) - 1, 0)) = 1, i.e. WSGB(4, 1):
    /// let back = e.inverse_elevate()?;
    /// assert_eq!(back.order(), 1);
    /// assert_eq!(back.with_order(0)?, c);
    /// # Ok::<(), cagd_core::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`crate::Error::DegreeOutOfRange`] for `n + 1 > MAX_DEGREE`,
    /// [`crate::Error::BadParameter`] for `l` out of range for degree `n + 1`.
    pub fn elevate(&self, l: usize) -> Result<WsgbCurve> {
        check_wsgb_order(self.degree() + 1, l)?;
        let e = wsgb_elevate_exact(&to_exact_points(self.points()), self.dim(), self.order(), l)?;
        WsgbCurve::new(round_exact_points(&e), self.dim(), l)
    }
}
