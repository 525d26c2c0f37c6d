//! [`ImplicitCurve`]: a planar rational Bézier curve together with its Bézout matrix and
//! implicit polynomial, ready for classification ([`crate::Classification`]), inversion
//! and intersection.

use cagd_core::{BezierCurve, Result};

use crate::implicitize::{BasePointPolicy, ImplicitOptions, ImplicitReport, implicitize_with};
use crate::planar::{HomCurve, coordinate_scale, homogeneous_f64};
use crate::{BezoutMatrix, ImplicitPolynomial};

/// A planar curve with its implicit form: the `f64` Bézout matrices (for `det F` at a point
/// by LU and for inversion), the implicit polynomial (exact and `f64`), and the
/// homogeneous control points (after base points were divided out).
#[derive(Debug, Clone, PartialEq)]
pub struct ImplicitCurve {
    pub(crate) curve: HomCurve,
    pub(crate) bezout: BezoutMatrix,
    pub(crate) polynomial: ImplicitPolynomial,
    pub(crate) report: ImplicitReport,
    pub(crate) scale: f64,
}

impl ImplicitCurve {
    /// Implicitizes `curve`, dividing base points out (they are reported in
    /// [`ImplicitCurve::report`]).
    ///
    /// # Errors
    /// [`cagd_core::Error::NotPlanar`], [`cagd_core::Error::DegreeOutOfRange`],
    /// [`cagd_core::Error::BasePoint`] when the curve is a single point.
    pub fn new(curve: &BezierCurve) -> Result<Self> {
        Self::with_options(
            curve,
            &ImplicitOptions {
                base_points: BasePointPolicy::DivideOut,
            },
        )
    }

    /// Implicitizes `curve` with `options` (see [`crate::implicitize_with`]).
    ///
    /// # Errors
    /// As [`crate::implicitize_with`].
    pub fn with_options(curve: &BezierCurve, options: &ImplicitOptions) -> Result<Self> {
        let imp = implicitize_with(curve, options)?;
        let (hom, bezout) = if imp.report.base_points == 0 {
            (homogeneous_f64(curve), BezoutMatrix::new(curve)?)
        } else {
            let hom = imp.homogeneous_points();
            let b = BezoutMatrix::from_homogeneous(&hom);
            (hom, b)
        };
        let scale = coordinate_scale(&hom);
        Ok(ImplicitCurve {
            curve: HomCurve { hom },
            bezout,
            polynomial: imp.polynomial,
            report: imp.report,
            scale,
        })
    }

    /// The Bézout matrix `F = x A + y B + C0` (of the curve with base points divided out).
    pub fn bezout(&self) -> &BezoutMatrix {
        &self.bezout
    }

    /// The implicit polynomial `f = det F`.
    pub fn polynomial(&self) -> &ImplicitPolynomial {
        &self.polynomial
    }

    /// Degree, base points divided out, properness.
    pub fn report(&self) -> &ImplicitReport {
        &self.report
    }

    /// The curve point at `t` (homogeneous de Casteljau).
    pub fn point(&self, t: f64) -> [f64; 2] {
        self.curve.point(t)
    }
}
