//! Implicitization of a planar rational Bézier curve (SPEC-convert §15.8): the exact
//! implicit polynomial `f = det F`, its `f64` rounding, base points and properness.

use cagd_core::{BezierCurve, Error, Result};

use crate::base_point::{base_point_count, divide_out, parametrization_power};
use crate::exact::{IntHom, exact_coefficients};
use crate::planar::check_planar;
use crate::polynomial::ImplicitPolynomial;

/// What to do when `X, Y, W` share a factor (base points, `det F ≡ 0`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum BasePointPolicy {
    /// Return [`Error::BasePoint`] (the exact definition `f = det F` is identically 0).
    #[default]
    Reject,
    /// Divide the common factor out and implicitize the lower-degree curve (reported).
    DivideOut,
}

/// Options of [`implicitize_with`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ImplicitOptions {
    /// Base-point handling (default [`BasePointPolicy::Reject`]).
    pub base_points: BasePointPolicy,
}

/// What the implicitization found out about the curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ImplicitReport {
    /// Degree of the input curve.
    pub input_degree: usize,
    /// Degree `m` of the implicitized curve (`input_degree - base_points`).
    pub degree: usize,
    /// Number of base points divided out (0 unless [`BasePointPolicy::DivideOut`]).
    pub base_points: usize,
    /// How many times the parametrization traces its curve (`1` = proper). With `k > 1` the
    /// polynomial is `c g^k` for the irreducible implicit polynomial `g` of degree `m / k`
    /// (e.g. collinear control points).
    pub power: usize,
}

impl ImplicitReport {
    /// Whether the parametrization is proper (`power == 1`).
    pub fn proper(&self) -> bool {
        self.power == 1
    }
}

/// The result of an implicitization: the polynomial (exact and `f64`), the homogeneous
/// control points it was computed from (after base points were divided out), the report.
#[derive(Debug, Clone, PartialEq)]
pub struct Implicitization {
    /// `f(x, y) = det F(x, y)` of eq. 15.8.5, total degree `report.degree`.
    pub polynomial: ImplicitPolynomial,
    /// What was found (degree, base points, properness).
    pub report: ImplicitReport,
    pub(crate) hom: IntHom,
}

impl Implicitization {
    /// The homogeneous control points `(X_i, Y_i, W_i)` the polynomial belongs to, rounded
    /// to `f64` (the input's `(w x, w y, w)` unless base points were divided out).
    pub fn homogeneous_points(&self) -> Vec<[f64; 3]> {
        self.hom
            .to_rational()
            .iter()
            .map(|p| p.clone().map(|c| crate::polynomial::round(&c)))
            .collect()
    }
}

/// Implicitizes with the default options (base points are an error): `f(x, y) = det F`
/// exactly, `F` the Bézout matrix of eqs. 15.8.2–15.8.4, sign convention
/// `det F = (-1)^(n(n+1)/2) Res_t(W x - X, W y - Y)`.
///
/// Cost: the exact integers carry the binary exponent range of the input (the homogeneous
/// coordinates are scaled by one power of two), so a curve whose coordinates or weights
/// span hundreds of binades (a subnormal beside a value near `1e308`) takes seconds at
/// degree 16 instead of milliseconds (the C ABI fuzz run's slowest: 5.6 s). Bounded by the
/// degree cap and the `f64` exponent range.
///
/// # Errors
/// [`Error::NotPlanar`], [`Error::NotEnoughPoints`] (`n = 0`), [`Error::DegreeOutOfRange`]
/// (`n > MAX_IMPLICIT_DEGREE`),
/// [`Error::BasePoint`], [`Error::ConditionNotMet`] when a coefficient overflows `f64`.
///
/// ```
/// use cagd_core::BezierCurve;
/// // impl-n2-conic-weighted: w = (1, 1, 2) on (1,0), (1,1), (0,1) is the unit circle,
/// // f = 4 - 4x^2 - 4y^2.
/// let c = BezierCurve::new_rational(vec![1.0, 0.0, 1.0, 1.0, 0.0, 1.0], vec![1.0, 1.0, 2.0], 2)?;
/// let imp = cagd_implicit::implicitize(&c)?;
/// assert_eq!(imp.polynomial.monomials(), vec![(2, 0, -4.0), (0, 2, -4.0), (0, 0, 4.0)]);
/// assert!(imp.report.proper());
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn implicitize(curve: &BezierCurve) -> Result<Implicitization> {
    implicitize_with(curve, &ImplicitOptions::default())
}

/// Implicitizes with options (see [`implicitize`]).
///
/// # Errors
/// As [`implicitize`]; with [`BasePointPolicy::DivideOut`], [`Error::BasePoint`] only when
/// nothing is left (the curve is a single point).
pub fn implicitize_with(curve: &BezierCurve, options: &ImplicitOptions) -> Result<Implicitization> {
    check_planar(curve)?;
    let input_degree = curve.degree();
    let mut hom = IntHom::from_curve(curve);
    let mut coefs = exact_coefficients(&hom);
    let mut removed = 0;
    if coefs.iter().all(num_traits::Zero::is_zero) {
        let rational = hom.to_rational();
        let count = base_point_count(&rational);
        let count = if count == 0 { input_degree } else { count };
        match options.base_points {
            BasePointPolicy::Reject => return Err(Error::BasePoint { count }),
            BasePointPolicy::DivideOut => {
                let reduced = divide_out(&rational).ok_or(Error::BasePoint { count })?;
                hom = IntHom::from_rational(&reduced);
                removed = input_degree - hom.degree();
                coefs = exact_coefficients(&hom);
            }
        }
    }
    let degree = hom.degree();
    let polynomial = ImplicitPolynomial::from_exact(degree, coefs);
    if polynomial.coefficients().iter().any(|c| !c.is_finite()) {
        return Err(Error::ConditionNotMet {
            eq: "15.8.5",
            why: "a coefficient of f = det F is beyond the f64 range (coordinates or weights too large)",
        });
    }
    let power = parametrization_power(&hom);
    Ok(Implicitization {
        polynomial,
        report: ImplicitReport {
            input_degree,
            degree,
            base_points: removed,
            power,
        },
        hom,
    })
}
