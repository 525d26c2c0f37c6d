//! The standard form of a rational Bézier curve: the Möbius reparametrisation that makes
//! both end weights 1, the same shape (SPEC-convert §15 conventions; Farin's
//! `w_i -> w_i rho^i` rule).
//!
//! Replacing the weights `w_i` by `w_i rho^i` (`rho > 0`) gives the same curve under
//! `t = rho s / ((1 - s) + rho s)`: `sum B_i(s) w_i rho^i P_i` is `(1 - s)^n sum C(n,i)
//! (rho s / (1 - s))^i w_i P_i`. `rho = (w_0 / w_n)^(1/n)` makes the end weights equal,
//! and dividing every weight by `w_0` makes them 1.

use cagd_core::{BezierCurve, Error, Result};

/// A rational Bézier curve in standard form and the reparametrisation that maps it to the
/// original: `original(t(s)) = standard(s)` with `t(s) = rho s / ((1 - s) + rho s)`.
#[derive(Debug, Clone, PartialEq)]
pub struct StandardForm {
    /// The curve with end weights 1 (same points).
    pub curve: BezierCurve,
    /// The Möbius factor `rho = (w_0 / w_n)^(1/n)`.
    pub rho: f64,
}

impl StandardForm {
    /// The parameter `t` of the original curve at the parameter `s` of the standard one.
    pub fn original_parameter(&self, s: f64) -> f64 {
        self.rho * s / ((1.0 - s) + self.rho * s)
    }
}

/// The standard form of a rational Bézier curve (end weights 1, same shape); a polynomial
/// curve is returned unchanged (`rho = 1`).
/// (Farin's `w_i -> w_i rho^i` with `t = rho s / ((1 - s) + rho s)`, see the module docs;
/// used with SPEC-convert §15.1–15.3.)
///
/// # Errors
/// [`Error::DegreeOutOfRange`] is impossible for a valid curve; [`Error::BadDegreePair`]
/// for degree 0 (no reparametrisation can change a single weight);
/// [`Error::NonPositiveWeight`] when a scaled weight under- or overflows;
/// [`Error::BadParameter`] (`rho`) when `rho` itself does.
///
/// ```
/// # use cagd_core::BezierCurve;
/// # use cagd_convert::standard_form;
/// let c = BezierCurve::new_rational(vec![1.0, 0.0, 1.0, 1.0, 0.0, 1.0], vec![2.0, 1.0, 0.5], 2)?;
/// let s = standard_form(&c)?;
/// let w = s.curve.weights().unwrap();
/// assert!((w[0] - 1.0).abs() < 1e-15 && (w[2] - 1.0).abs() < 1e-15);
/// let (a, b) = (s.curve.eval(0.3), c.eval(s.original_parameter(0.3)));
/// assert!((a[0] - b[0]).abs() < 1e-15 && (a[1] - b[1]).abs() < 1e-15);
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn standard_form(curve: &BezierCurve) -> Result<StandardForm> {
    let Some(w) = curve.weights() else {
        return Ok(StandardForm {
            curve: curve.clone(),
            rho: 1.0,
        });
    };
    let n = curve.degree();
    if n == 0 {
        return Err(Error::BadDegreePair {
            from: 0,
            to: 0,
            why: "the standard form needs degree >= 1",
        });
    }
    let exponent = 1.0 / n as f64;
    let rho = (w[0] / w[n]).powf(exponent);
    // Degree 1 with end weights 1e300 and 1e-300 gave rho = inf with Ok (C ABI fuzz long
    // run): the reparametrisation is not representable then.
    if !(rho.is_finite() && rho > 0.0) {
        return Err(Error::BadParameter {
            name: "rho",
            value: rho,
            why: "the Möbius factor (w_0 / w_n)^(1/n) over- or underflows f64 (end weights too \
                  far apart)",
        });
    }
    // w_i rho^i / w_0 = (w_i / w_0) (w_0/w_n)^(i/n): computed as a power of the ratio.
    let ratio = w[0] / w[n];
    let new: Vec<f64> = w
        .iter()
        .enumerate()
        .map(|(i, wi)| {
            if i == 0 || i == n {
                1.0
            } else {
                wi / w[0] * ratio.powf(i as f64 * exponent)
            }
        })
        .collect();
    let curve = BezierCurve::new_rational(curve.points().to_vec(), new, curve.dim())?;
    Ok(StandardForm { curve, rho })
}
