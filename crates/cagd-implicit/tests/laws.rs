//! Laws of the implicitization (issue 12): the implicit polynomial vanishes on the curve
//! (scaled residual), has total degree n and is not small off the curve; the exact
//! coefficients vanish exactly at rational parameters and equal an independent exact
//! Sylvester resultant; inversion recovers the parameter.

use cagd_core::BezierCurve;
use cagd_implicit::{ImplicitCurve, implicitize};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use proptest::prelude::*;

type Q = BigRational;

fn q(x: f64) -> Q {
    BigRational::from_float(x).unwrap()
}

/// A random planar rational curve of degree `lo..=hi`: coordinates in ±1, weights 0.5..2.
fn curve(lo: usize, hi: usize) -> impl Strategy<Value = BezierCurve> {
    (lo..=hi).prop_flat_map(|n| {
        (
            proptest::collection::vec(-1.0f64..1.0, 2 * (n + 1)),
            proptest::collection::vec(0.5f64..2.0, n + 1),
        )
            .prop_map(|(p, w)| BezierCurve::new_rational(p, w, 2).unwrap())
    })
}

/// Exact homogeneous point of the curve at rational `t` (Bernstein sum).
fn exact_point(c: &BezierCurve, t: &Q) -> (Q, Q) {
    let n = c.degree();
    let s = Q::one() - t;
    let (mut x, mut y, mut w) = (Q::zero(), Q::zero(), Q::zero());
    for i in 0..=n {
        let mut b = Q::from_integer(BigInt::from(cagd_core::binomial(n, i)));
        for _ in 0..i {
            b *= t;
        }
        for _ in i..n {
            b *= &s;
        }
        let wi = q(c.weights().unwrap()[i]);
        let p = c.point(i);
        x += &b * &wi * q(p[0]);
        y += &b * &wi * q(p[1]);
        w += &b * &wi;
    }
    (x / &w, y / w)
}

/// Power-basis coefficients (t^0..t^n) of the Bernstein polynomial with exact coefficients.
fn power(c: &[Q]) -> Vec<Q> {
    let n = c.len() - 1;
    let mut out = vec![Q::zero(); n + 1];
    for (i, ci) in c.iter().enumerate() {
        for (k, slot) in out.iter_mut().enumerate().skip(i) {
            let m = BigInt::from(cagd_core::binomial(n, i) * cagd_core::binomial(n - i, k - i));
            let term = ci * Q::from_integer(m);
            if (k - i) % 2 == 0 {
                *slot += term;
            } else {
                *slot -= term;
            }
        }
    }
    out
}

/// Determinant of a rational matrix by Gaussian elimination in ℚ.
fn det_q(mut m: Vec<Q>, n: usize) -> Q {
    let mut det = Q::one();
    for k in 0..n {
        let Some(p) = (k..n).find(|&r| !m[r * n + k].is_zero()) else {
            return Q::zero();
        };
        if p != k {
            for j in 0..n {
                m.swap(k * n + j, p * n + j);
            }
            det = -det;
        }
        let piv = m[k * n + k].clone();
        det *= &piv;
        for i in k + 1..n {
            let f = &m[i * n + k] / &piv;
            for j in k..n {
                let v = &f * &m[k * n + j];
                m[i * n + j] -= v;
            }
        }
    }
    det
}

/// Sylvester resultant `Res_t(W x - X, W y - Y)` at a rational point, formal degree n both
/// (rows of the first polynomial, then of the second, coefficients from t^n down).
fn sylvester_at(c: &BezierCurve, x: &Q, y: &Q) -> Q {
    let n = c.degree();
    let w: Vec<Q> = c.weights().unwrap().iter().map(|&w| q(w)).collect();
    let bx: Vec<Q> = (0..=n).map(|i| &w[i] * q(c.point(i)[0])).collect();
    let by: Vec<Q> = (0..=n).map(|i| &w[i] * q(c.point(i)[1])).collect();
    let (pw, px, py) = (power(&w), power(&bx), power(&by));
    let f: Vec<Q> = (0..=n).map(|k| &pw[k] * x - &px[k]).collect();
    let g: Vec<Q> = (0..=n).map(|k| &pw[k] * y - &py[k]).collect();
    let size = 2 * n;
    let mut m = vec![Q::zero(); size * size];
    for r in 0..n {
        for k in 0..=n {
            m[r * size + r + k] = f[n - k].clone();
            m[(r + n) * size + r + k] = g[n - k].clone();
        }
    }
    det_q(m, size)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Scaled residual on 2000 curve points <= 1e-12 with the f64 coefficients, total
    /// degree n, and not small off the curve.
    #[test]
    fn polynomial_vanishes_on_the_curve(c in curve(2, 10), shift in 0.05f64..0.5) {
        let imp = implicitize(&c).unwrap();
        let p = &imp.polynomial;
        prop_assert_eq!(p.effective_degree(), Some(c.degree()));
        let mut worst = 0.0_f64;
        for k in 0..2000 {
            let t = k as f64 / 1999.0;
            let e = c.eval(t);
            worst = worst.max(p.eval(e[0], e[1]).abs() / p.eval_abs(e[0], e[1]));
        }
        prop_assert!(worst <= 1e-12, "scaled residual {worst:e}");
        // Off the curve (a shifted copy of the curve points): the polynomial is not small
        // everywhere there, relative to the same scale.
        let mut best = 0.0_f64;
        for k in 0..50 {
            let e = c.eval(k as f64 / 49.0);
            let (x, y) = (e[0] + shift, e[1] - 0.5 * shift);
            best = best.max(p.eval(x, y).abs() / p.eval_abs(x, y));
        }
        prop_assert!(best > 1e-6, "polynomial small off the curve: {best:e}");
    }

    /// The exact coefficients vanish exactly at rational parameters t = k/7.
    #[test]
    fn exact_coefficients_vanish_at_rational_parameters(c in curve(1, 6)) {
        let imp = implicitize(&c).unwrap();
        for k in 0..=7 {
            let t = Q::new(BigInt::from(k), BigInt::from(7));
            let (x, y) = exact_point(&c, &t);
            prop_assert!(imp.polynomial.eval_exact(&x, &y).is_zero());
        }
    }

    /// det F = (-1)^(n(n+1)/2) Res_t(W x - X, W y - Y) (SPEC-convert §15.8): compared on the
    /// principal lattice of a skewed triangle (unisolvent for total degree n, so the two
    /// polynomials are equal) plus one extra point.
    #[test]
    fn exact_coefficients_equal_the_sylvester_resultant(c in curve(1, 5)) {
        let n = c.degree();
        let imp = implicitize(&c).unwrap();
        let sign = if (n * (n + 1) / 2) % 2 == 0 { Q::one() } else { -Q::one() };
        let third = Q::new(BigInt::from(1), BigInt::from(3));
        let seventh = Q::new(BigInt::from(-2), BigInt::from(7));
        let mut pts: Vec<(Q, Q)> = Vec::new();
        for a in 0..=n {
            for b in 0..=n - a {
                let (fa, fb) = (Q::from_integer(BigInt::from(a)), Q::from_integer(BigInt::from(b)));
                pts.push((&fa * &third + &fb * &seventh, &fb * &third - &fa * &seventh + &seventh));
            }
        }
        pts.push((Q::new(BigInt::from(5), BigInt::from(11)), Q::new(BigInt::from(-3), BigInt::from(13))));
        for (x, y) in pts {
            let res = sylvester_at(&c, &x, &y);
            prop_assert_eq!(imp.polynomial.eval_exact(&x, &y), &sign * res);
        }
    }

    /// Inversion recovers t within 1e-12 (or, at a double point of the curve, another
    /// parameter of the same point).
    #[test]
    fn inversion_recovers_the_parameter(c in curve(1, 8), t in 0.0f64..1.0) {
        let imp = ImplicitCurve::new(&c).unwrap();
        let p = c.eval(t);
        match imp.invert(p[0], p[1]) {
            Ok(s) => {
                let q = c.eval(s);
                prop_assert!(
                    (s - t).abs() <= 1e-12 || (q[0] - p[0]).hypot(q[1] - p[1]) <= 1e-10,
                    "t = {t}, got {s}"
                );
            }
            Err(cagd_core::Error::SingularPoint { .. }) => {
                // Only acceptable at (or extremely near) a double point: another parameter
                // reaches the same point.
                let near = (0..=4000).any(|k| {
                    let s = k as f64 / 4000.0;
                    let q = c.eval(s);
                    (s - t).abs() > 1e-3 && (q[0] - p[0]).hypot(q[1] - p[1]) < 1e-3
                });
                prop_assert!(near, "SingularPoint away from a double point at t = {t}");
            }
            Err(e) => prop_assert!(false, "t = {t}: {e}"),
        }
    }
}

#[test]
fn collinear_quadratic_is_improper_with_power_two() {
    // SPEC-convert §15.8: a collinear quadratic gives f = -(x - y)^2.
    let c = BezierCurve::new(vec![0.0, 0.0, 2.0, 2.0, 1.0, 1.0], 2).unwrap();
    let imp = implicitize(&c).unwrap();
    assert_eq!(imp.report.power, 2);
    assert!(!imp.report.proper());
    let m = imp.polynomial.monomials();
    let s = -m.iter().find(|(i, j, _)| (*i, *j) == (2, 0)).unwrap().2;
    // f = -s (x - y)^2 = -s x^2 + 2 s x y - s y^2
    assert_eq!(m, vec![(2, 0, -s), (1, 1, 2.0 * s), (0, 2, -s)]);
}

#[test]
fn base_point_is_refused_or_divided_out() {
    // (2 - t) * ((1-t) q0 + t q1) with q0 = (0, 2, 2), q1 = (1, 0, 1): the Bernstein form of
    // degree 2 is (0,4,4), (1,1,2), (1,0,1), i.e. points (0,1), (1/2,1/2), (1,0) with weights
    // 4, 2, 1 (all binary fractions, so the common factor is exact). The curve is the
    // segment of x + y = 1.
    let c = BezierCurve::new_rational(vec![0.0, 1.0, 0.5, 0.5, 1.0, 0.0], vec![4.0, 2.0, 1.0], 2)
        .unwrap();
    assert_eq!(
        implicitize(&c).unwrap_err(),
        cagd_core::Error::BasePoint { count: 1 }
    );
    let imp = ImplicitCurve::new(&c).unwrap();
    assert_eq!(imp.report().degree, 1);
    assert_eq!(imp.report().base_points, 1);
    assert!(imp.classify(0.3, 0.7).value.abs() < 1e-15);
    assert!(imp.classify(0.3, 0.4).value.abs() > 1e-3);
    let p = c.eval(0.4);
    let s = imp.invert(p[0], p[1]).unwrap();
    let r = imp.point(s);
    assert!((r[0] - p[0]).abs() < 1e-14 && (r[1] - p[1]).abs() < 1e-14);
}

#[test]
fn degree_elevated_curve_implicitizes_at_its_true_degree() {
    // Elevating a cubic once divides by 4: exact in binary, one base point at t = ∞.
    let c = BezierCurve::new(vec![0.0, 0.0, 1.0, 3.0, 3.0, 3.0, 4.0, -1.0], 2).unwrap();
    let e = c.elevate(1).unwrap();
    assert!(matches!(
        implicitize(&e),
        Err(cagd_core::Error::BasePoint { count: 1 })
    ));
    let imp = ImplicitCurve::new(&e).unwrap();
    assert_eq!(imp.report().degree, 3);
    let direct = implicitize(&c).unwrap();
    // Same polynomial up to a constant factor.
    let (a, b) = (imp.polynomial().monomials(), direct.polynomial.monomials());
    assert_eq!(a.len(), b.len());
    let k = a[0].2 / b[0].2;
    for (x, y) in a.iter().zip(&b) {
        assert_eq!((x.0, x.1), (y.0, y.1));
        assert!((x.2 - k * y.2).abs() <= 1e-12 * x.2.abs().max(1.0));
    }
}

#[test]
fn bad_input_is_a_named_error() {
    let c3 = BezierCurve::new(vec![0.0; 9], 3).unwrap();
    assert_eq!(
        implicitize(&c3).unwrap_err(),
        cagd_core::Error::NotPlanar { dim: 3 }
    );
    let c0 = BezierCurve::new(vec![1.0, 1.0], 2).unwrap();
    assert!(matches!(
        implicitize(&c0),
        Err(cagd_core::Error::NotEnoughPoints { .. })
    ));
    let point = BezierCurve::new(vec![1.0, 1.0, 1.0, 1.0, 1.0, 1.0], 2).unwrap();
    assert!(matches!(
        implicitize(&point),
        Err(cagd_core::Error::BasePoint { count: 2 })
    ));
    assert!(matches!(
        ImplicitCurve::new(&point),
        Err(cagd_core::Error::BasePoint { .. })
    ));
    let huge = BezierCurve::new_rational(
        vec![1e-300, 1e300, 1.0, 2.0, 3.0, -1e-200],
        vec![1e-10, 1.0, 3e10],
        2,
    )
    .unwrap();
    assert!(matches!(
        implicitize(&huge),
        Err(cagd_core::Error::ConditionNotMet { eq: "15.8.5", .. })
    ));
    let big = BezierCurve::new(vec![0.5; 2 * 18], 2).unwrap();
    assert!(matches!(
        implicitize(&big),
        Err(cagd_core::Error::DegreeOutOfRange { degree: 17, .. })
    ));
    let c = BezierCurve::new(vec![0.0, 0.0, 1.0, 2.0, 2.0, 0.0], 2).unwrap();
    let imp = ImplicitCurve::new(&c).unwrap();
    assert!(matches!(
        imp.invert(f64::NAN, 0.0),
        Err(cagd_core::Error::BadParameter { .. })
    ));
    assert!(matches!(
        imp.invert(5.0, 5.0),
        Err(cagd_core::Error::NotOnCurve { .. })
    ));
}
