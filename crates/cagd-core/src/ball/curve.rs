//! The WSGB(n, L) curve type of seed 003 (SPEC-reduce §9.1): `n + 1` control points of any
//! dimension in a flat row-major buffer, and the order `L`.

use crate::{Error, MAX_DEGREE, Result, check_points, wsgb_max_l};

/// A polynomial Wang–Said generalized Ball curve `r(u; n, L) = sum_i beta_i(u; n, L) p_i`,
/// `u in [0, 1]` (seed 003 eq. (1), basis as reconstructed in SPEC-reduce §9.1;
/// [`crate::wsgb_terms`] lists the basis functions).
///
/// `0 <= L <= max(floor(n/2) - 1, 0)`: `L = 0` is the Said–Ball curve
/// ([`WsgbCurve::said_ball`]), `L = floor(n/2) - 1` the Wang–Ball curve
/// ([`WsgbCurve::wang_ball`]). Points are stored flat and row-major (point `i`,
/// coordinate `k` at `i * dim + k`), as every curve of cagd. Rational WSGB curves are not
/// supported (seed 003 has none).
///
/// ```
/// use cagd_core::WsgbCurve;
/// // The degree-7 curve of seed 003's example, L = 1.
/// let p = vec![220., 110., 160., 220., 180., 340., 260., 400., 355., 425., 470., 320.,
///              490., 200., 420., 100.];
/// let c = WsgbCurve::new(p, 2, 1)?;
/// assert_eq!((c.degree(), c.order(), c.dim()), (7, 1, 2));
/// assert_eq!(c.eval(0.0), vec![220.0, 110.0]); // end-point interpolation
/// let b = c.to_bezier()?; // exact conversion, rounded once
/// let (x, y) = (c.eval(0.3), b.eval(0.3));
/// assert!((x[0] - y[0]).abs() < 1e-12 && (x[1] - y[1]).abs() < 1e-12);
/// # Ok::<(), cagd_core::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct WsgbCurve {
    points: Vec<f64>,
    dim: usize,
    l: usize,
}

/// Checks `0 <= l <= max(floor(n/2) - 1, 0)` (SPEC-reduce §9.1).
///
/// # Errors
/// [`Error::DegreeOutOfRange`] for `n > MAX_DEGREE`; [`Error::BadParameter`] (name `"L"`,
/// the offending value) for `l` out of range.
pub fn check_wsgb_order(n: usize, l: usize) -> Result<()> {
    crate::check_degree(n)?;
    if l > wsgb_max_l(n) {
        return Err(Error::BadParameter {
            name: "L",
            value: l as f64,
            why: "the WSGB(n, L) order must satisfy 0 <= L <= max(floor(n/2) - 1, 0) \
                  (SPEC-reduce §9.1)",
        });
    }
    Ok(())
}

impl WsgbCurve {
    /// A WSGB(n, L) curve from `n + 1` points of dimension `dim` and the order `l`.
    ///
    /// # Errors
    /// [`Error::ZeroDimension`], [`Error::NotEnoughPoints`], [`Error::LengthMismatch`],
    /// [`Error::NonFinite`] (as [`crate::check_points`]); [`Error::DegreeOutOfRange`] for
    /// more than `MAX_DEGREE + 1` points; [`Error::BadParameter`] for `l` out of range.
    pub fn new(points: Vec<f64>, dim: usize, l: usize) -> Result<Self> {
        let np = check_points(&points, dim)?;
        if np > MAX_DEGREE + 1 {
            return Err(Error::DegreeOutOfRange {
                degree: np - 1,
                max: MAX_DEGREE,
            });
        }
        check_wsgb_order(np - 1, l)?;
        Ok(Self { points, dim, l })
    }

    /// The Said–Ball curve (`L = 0`).
    ///
    /// # Errors
    /// As [`WsgbCurve::new`].
    pub fn said_ball(points: Vec<f64>, dim: usize) -> Result<Self> {
        Self::new(points, dim, 0)
    }

    /// The Wang–Ball curve (`L = max(floor(n/2) - 1, 0)`).
    ///
    /// # Errors
    /// As [`WsgbCurve::new`].
    pub fn wang_ball(points: Vec<f64>, dim: usize) -> Result<Self> {
        let np = check_points(&points, dim)?;
        Self::new(points, dim, wsgb_max_l(np - 1))
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.points.len() / self.dim - 1
    }

    /// The order `L`.
    pub fn order(&self) -> usize {
        self.l
    }

    /// The dimension of the points.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The flat row-major control points.
    pub fn points(&self) -> &[f64] {
        &self.points
    }

    /// Control point `i` (`dim` coordinates). Panics if `i > n`.
    pub fn point(&self, i: usize) -> &[f64] {
        &self.points[i * self.dim..(i + 1) * self.dim]
    }

    /// Whether this is a Said–Ball curve (`L = 0`).
    pub fn is_said_ball(&self) -> bool {
        self.l == 0
    }

    /// Whether this is a Wang–Ball curve (`L = max(floor(n/2) - 1, 0)`).
    pub fn is_wang_ball(&self) -> bool {
        self.l == wsgb_max_l(self.degree())
    }

    /// The points and the order, consuming the curve.
    pub fn into_parts(self) -> (Vec<f64>, usize) {
        (self.points, self.l)
    }
}
