//! Runs `cagd reduce --polynomial`: NURBS curves and surfaces come back as polynomial
//! B-splines (no weights) within the tolerance, checked by an independent evaluation with
//! cagd-core (the radial error of a circle, the distance at many parameters); `--to` equal
//! to the degree is accepted, lower reduces and drops the weights; bad use gives exit 2.

mod common;

use cagd_testkit::flat;
use cagd_testkit::serde_json::{Value, json};
use common::{cagd, json_out};

const H: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// The unit half circle as a rational quadratic NURBS (two quarter arcs, double knot).
fn half_circle() -> Value {
    json!({
        "type": "bspline", "degree": 2,
        "knots": [0, 0, 0, 0.5, 0.5, 1, 1, 1],
        "points": [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0]],
        "weights": [1, H, 1, H, 1],
    })
}

/// A cagd-core curve from the command's JSON form.
fn curve_of(v: &Value) -> cagd_core::BSplineCurve {
    let p = usize::try_from(v["degree"].as_u64().expect("degree")).expect("small");
    let rows = v["points"].as_array().expect("points");
    let dim = rows[0].as_array().expect("point").len();
    let pts: Vec<f64> = rows.iter().flat_map(flat).collect();
    match v.get("weights") {
        Some(w) => cagd_core::BSplineCurve::new_rational(p, flat(&v["knots"]), pts, flat(w), dim),
        None => cagd_core::BSplineCurve::new(p, flat(&v["knots"]), pts, dim),
    }
    .expect("valid curve")
}

fn run(args: &[&str], input: &Value) -> Value {
    json_out(&cagd(args, &input.to_string()))
}

#[test]
fn half_circle_becomes_cubic_within_the_tolerance() {
    for tol in ["1e-3", "1e-5"] {
        for to in ["2", "3"] {
            let out = run(
                &["reduce", "--polynomial", "--to", to, "--tol", tol],
                &half_circle(),
            );
            assert_eq!(out["type"], "bspline");
            assert!(out.get("weights").is_none(), "weights kept: {out}");
            let s = curve_of(&out);
            assert_eq!(s.degree().to_string(), to);
            let r = &out["report"];
            let (bound, measured) = (
                r["error_bound"].as_f64().unwrap(),
                r["max_error"].as_f64().unwrap(),
            );
            let tol: f64 = tol.parse().unwrap();
            assert!(measured <= bound && bound <= tol, "{r}");
            // Independent: the input evaluated by cagd-core, the radial error and the
            // parametric distance at 2 001 parameters are below the certified bound.
            let c = curve_of(&half_circle());
            for i in 0..=2000 {
                let t = f64::from(i) / 2000.0;
                let (x, y) = (c.eval(t).unwrap(), s.eval(t).unwrap());
                let par = (x[0] - y[0]).hypot(x[1] - y[1]);
                let radial = (y[0].hypot(y[1]) - 1.0).abs();
                assert!(
                    radial <= par + 1e-15 && par <= bound,
                    "t {t}: {radial} {par} {bound}"
                );
            }
            assert_eq!(r["continuity"], json!([[0.5, 0]]));
            assert_eq!(r["spans_in"], 2);
            eprintln!(
                "half circle --to {to} --tol {tol:e}: spans {}",
                r["spans_out"]
            );
        }
    }
}

/// A rational cubic with `--to 3` (refused without `--polynomial`) and with no `--to`;
/// `--to 2` reduces and drops the weights in one pass.
#[test]
fn to_the_same_degree_is_accepted_and_lower_reduces() {
    let cubic = json!({
        "type": "bspline", "degree": 3,
        "knots": [0, 0, 0, 0, 0.4, 1, 1, 1, 1],
        "points": [[0, 0], [1, 2], [2, -1], [3, 2], [4, 0]],
        "weights": [1, 2, 0.5, 3, 1],
    });
    let o = cagd(
        &["reduce", "--to", "3", "--tol", "1e-4"],
        &cubic.to_string(),
    );
    assert_eq!(
        o.status.code(),
        Some(2),
        "plain --to 3 on a cubic is a bad degree pair"
    );
    let c = curve_of(&cubic);
    for args in [vec!["--to", "3"], vec![], vec!["--to", "2"]] {
        let mut all = vec!["reduce", "--polynomial", "--tol", "1e-4"];
        all.extend(&args);
        let out = run(&all, &cubic);
        assert!(out.get("weights").is_none());
        let s = curve_of(&out);
        assert_eq!(s.degree(), if args.contains(&"2") { 2 } else { 3 });
        let bound = out["report"]["error_bound"].as_f64().unwrap();
        assert!(bound <= 1e-4);
        for i in 0..=1000 {
            let t = f64::from(i) / 1000.0;
            let (x, y) = (c.eval(t).unwrap(), s.eval(t).unwrap());
            assert!((x[0] - y[0]).hypot(x[1] - y[1]) <= bound);
        }
    }
}

#[test]
fn equal_weights_come_back_unchanged() {
    let mut v = half_circle();
    v["weights"] = json!([2, 2, 2, 2, 2]);
    let out = run(&["reduce", "--polynomial", "--tol", "1e-6"], &v);
    assert!(out.get("weights").is_none());
    let pts = |x: &Value| -> Vec<f64> {
        x["points"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(flat)
            .collect()
    };
    assert_eq!(pts(&out), pts(&v));
    assert_eq!(flat(&out["knots"]), flat(&v["knots"]));
    assert_eq!(out["report"]["equal_weights"], true);
    // The same curve: the bound is the evaluation rounding only (never below a measurement).
    let bound = out["report"]["error_bound"].as_f64().unwrap();
    assert!((0.0..1e-13).contains(&bound), "{bound}");
    assert_eq!(out["report"]["spans_out"], 2);
}

#[test]
fn surfaces_become_polynomial() {
    // A half cylinder: the half circle in u, linear in v.
    let rows: Vec<Value> = [[1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [-1.0, 1.0], [-1.0, 0.0]]
        .iter()
        .map(|[x, y]| json!([[x, y, 0.0], [x, y, 2.0]]))
        .collect();
    let w: Vec<Value> = [1.0, H, 1.0, H, 1.0]
        .iter()
        .map(|w| json!([w, w]))
        .collect();
    let s = json!({
        "type": "bspline-surface", "degree": [2, 1],
        "knots_u": [0, 0, 0, 0.5, 0.5, 1, 1, 1], "knots_v": [0, 0, 1, 1],
        "points": rows, "weights": w,
    });
    let out = run(
        &["reduce", "--polynomial", "--to", "3,1", "--tol", "1e-4"],
        &s,
    );
    assert_eq!(out["type"], "bspline-surface");
    assert!(out.get("weights").is_none());
    assert_eq!(out["degree"], json!([3, 1]));
    let r = &out["report"];
    assert!(r["max_error"].as_f64().unwrap() <= r["error_bound"].as_f64().unwrap());
    assert!(r["error_bound"].as_f64().unwrap() <= 1e-4);
    assert_eq!(r["continuity_u"], json!([[0.5, 0]]));
    // Independent: every output point on a grid lies within the bound of the cylinder.
    let rows = out["points"].as_array().unwrap();
    let (nu, nv) = (rows.len(), rows[0].as_array().unwrap().len());
    let pts: Vec<f64> = rows.iter().flat_map(flat).collect();
    let surf = cagd_core::BSplineSurface::new(
        (3, 1),
        flat(&out["knots_u"]),
        flat(&out["knots_v"]),
        pts,
        (nu, nv),
        3,
    )
    .unwrap();
    for i in 0..=200 {
        let y = surf.eval(f64::from(i) / 200.0, 0.37).unwrap();
        assert!((y[0].hypot(y[1]) - 1.0).abs() <= r["error_bound"].as_f64().unwrap());
    }
}

#[test]
fn bad_use_gives_exit_code_2() {
    let circle = half_circle().to_string();
    for args in [
        vec!["reduce", "--polynomial"],
        vec!["reduce", "--polynomial", "--tol", "1e-3", "--method", "l2"],
        vec![
            "reduce",
            "--polynomial",
            "--tol",
            "1e-3",
            "--continuity",
            "1",
        ],
        vec!["reduce", "--polynomial", "--tol", "1e-3", "--to", "0"],
        vec!["reduce", "--polynomial", "--tol", "1e-3", "--to", "3,2"],
        vec!["reduce", "--polynomial", "--tol", "1e-300"],
        vec!["reduce", "--polynomial", "--tol", "1e-3", "--to", "65"],
    ] {
        let o = cagd(&args, &circle);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert_eq!(
            String::from_utf8_lossy(&o.stderr)
                .lines()
                .next()
                .map(|l| l.starts_with("cagd: ")),
            Some(true)
        );
    }
    // A Bézier curve is not taken; a non-positive weight is an input error.
    let bez = json!({"type": "bezier", "points": [[0, 0], [1, 1], [2, 0]], "weights": [1, 2, 1]});
    let o = cagd(
        &["reduce", "--polynomial", "--tol", "1e-3"],
        &bez.to_string(),
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("bspline"));
    let mut bad = half_circle();
    bad["weights"] = json!([1, 0, 1, H, 1]);
    let o = cagd(
        &["reduce", "--polynomial", "--tol", "1e-3"],
        &bad.to_string(),
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("weights[1]"));
}
