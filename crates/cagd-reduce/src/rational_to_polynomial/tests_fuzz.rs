//! Regression inputs of the C ABI fuzz runs (issue 18) for NURBS to polynomial: each
//! answers within its bound or refuses by name, in bounded work (no timing assertion).

use cagd_core::{BSplineCurve, Error};

use super::*;

/// Knots of the C fuzz run's degree-6 NURBS segment in 3-D (seed 104, session
/// 0x771baad7f9186788, call 144: `cagd_bspline_to_polynomial`, 5.2 s).
const C144_K: [f64; 14] = [
    0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0,
];
/// Its control points.
const C144_P: [f64; 21] = [
    0.48969942743963024,
    -0.4149721997989759,
    -0.5702525885599177,
    -0.7503488811747405,
    -0.9064118393074256,
    0.622214031045238,
    -0.729035677529559,
    0.981091028446081,
    0.7226402999713732,
    0.5613071167835564,
    -0.07696037779189413,
    -0.06922729267321248,
    -0.8043259073146114,
    0.5504701430453589,
    0.14670626738432913,
    0.6486326554973876,
    -0.9225989078990777,
    -0.02384929332728003,
    -0.8623676546746764,
    -0.734390371048365,
    0.876219528475132,
];
/// Its weights.
const C144_W: [f64; 7] = [
    3.1825831172925882,
    2.4486130746076884,
    2.1132582713010013,
    4.834142529648573,
    3.108648063173192,
    1.27167000378322,
    1.2838772939461243,
];

/// 5.2 s in the C fuzz run: to degree 2 within 1e-12.
#[test]
fn call_144_answers_or_refuses() {
    let c = BSplineCurve::new_rational(6, C144_K.to_vec(), C144_P.to_vec(), C144_W.to_vec(), 3)
        .unwrap();
    match rational_to_polynomial(&c, Some(2), 1e-12) {
        Ok(r) => {
            assert!(r.report.error_bound <= 1e-12);
            for k in 0..=400 {
                let u = 2.0 * k as f64 / 400.0;
                let (a, b) = (c.eval(u).unwrap(), r.curve.eval(u).unwrap());
                let d = a
                    .iter()
                    .zip(&b)
                    .map(|(x, y)| (x - y) * (x - y))
                    .sum::<f64>();
                assert!(d.sqrt() <= r.report.error_bound);
            }
        }
        Err(e) => assert!(matches!(e, Error::ConditionNotMet { .. }), "{e:?}"),
    }
}
