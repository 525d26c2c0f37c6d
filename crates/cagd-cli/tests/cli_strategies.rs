//! `cagd reduce --tol` on B-spline curves with each `--strategy`: the global fit keeps
//! `C^(m-1)` (report and an independent evaluation), the per-segment strategy `C^1` for
//! cubics, the classical Piegl–Tiller 1995 algorithm fails where it cannot reduce without
//! subdividing; bad strategy arguments exit 2 with one line.

mod common;

use cagd_core::BSplineCurve;
use cagd_testkit::serde_json::{Value, json};
use cagd_testkit::{flat, vector};
use common::{cagd, json_out};

/// The seed 001 example curve: degree 7, 9 points, uniform knots 0..16 (C6 everywhere).
fn seed_curve() -> (Value, BSplineCurve) {
    let v = vector("vectors-reduce.json", "001-example");
    let knots = flat(&v["params"]["knots"]);
    let points = flat(&v["input"]["P"]);
    let curve = BSplineCurve::new(7, knots.clone(), points.clone(), 2).expect("valid");
    let shape = json!({"type": "bspline", "degree": 7, "knots": v["params"]["knots"], "points": v["input"]["P"]});
    (shape, curve)
}

/// The output shape as a curve.
fn curve_of(out: &Value) -> BSplineCurve {
    let degree = usize::try_from(out["degree"].as_u64().expect("degree")).expect("small");
    BSplineCurve::new(degree, flat(&out["knots"]), flat(&out["points"]), 2).expect("valid output")
}

#[test]
fn each_strategy_keeps_what_it_promises() {
    let (shape, input) = seed_curve();
    for (args, strategy, order) in [
        (vec![], "fit", 2),
        (vec!["--strategy", "fit"], "fit", 2),
        (vec!["--strategy", "segments"], "segments/l2", 1),
        (
            vec!["--method", "chebyshev"],
            "segments/constrained-chebyshev",
            1,
        ),
    ] {
        let mut all = vec!["reduce", "--to", "3", "--tol", "1e-3"];
        all.extend(args.iter().copied());
        let out = json_out(&cagd(&all, &shape.to_string()));
        let r = &out["report"];
        assert_eq!(r["strategy"], strategy, "{args:?}");
        let bound = r["error_bound"].as_f64().expect("bound");
        assert!(bound <= 1e-3, "{args:?}: {bound}");
        for kv in r["continuity"].as_array().expect("continuity list") {
            assert_eq!(kv[1], order, "{args:?}");
        }
        // Independent check: evaluate both curves at 2 001 parameters.
        let red = curve_of(&out);
        let (a, b) = input.domain();
        for i in 0..=2000 {
            let t = a + (b - a) * f64::from(i) / 2000.0;
            let (p, q) = (input.eval(t).expect("eval"), red.eval(t).expect("eval"));
            let d = ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt();
            assert!(d <= bound, "{args:?}: {d} > {bound} at {t}");
        }
    }
}

#[test]
fn piegl_tiller_and_bad_strategy_arguments() {
    let (shape, _) = seed_curve();
    // A genuine degree-7 curve is not reducible to a cubic within 1e-6 without
    // subdividing: the classical algorithm reports it (exit code of a failed reduction).
    let o = cagd(
        &[
            "reduce",
            "--to",
            "3",
            "--tol",
            "1e-6",
            "--strategy",
            "piegl-tiller-1995",
        ],
        &shape.to_string(),
    );
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("Piegl-Tiller"), "{err}");
    // The global fit does it.
    let out = json_out(&cagd(
        &["reduce", "--to", "3", "--tol", "1e-6"],
        &shape.to_string(),
    ));
    assert!(out["report"]["error_bound"].as_f64().expect("bound") <= 1e-6);
    for bad in [
        vec!["--strategy", "best"],
        vec!["--strategy", "fit", "--method", "l2"],
        vec!["--strategy", "segments", "--method", "eck"],
    ] {
        let mut all = vec!["reduce", "--to", "3", "--tol", "1e-3"];
        all.extend(bad.iter().copied());
        let o = cagd(&all, &shape.to_string());
        assert_eq!(o.status.code(), Some(2), "{bad:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.lines().count(), 1, "{bad:?}: {err}");
    }
}
