//! Runs the `cagd` binary on B-spline / NURBS surfaces (`bspline-surface`): the results are
//! checked against an independent evaluation with cagd-core; bad surfaces give one line
//! naming the field and exit code 2.

mod common;

use cagd_testkit::flat;
use cagd_testkit::serde_json::{Value, json};
use common::{cagd, json_out};

/// A `bspline-surface` JSON object: a bicubic height field over `[0, 1]^2` with `6 x 5`
/// control points and one interior knot per direction (weights when `rational`).
fn bicubic_surface(rational: bool) -> Value {
    let (nu, nv) = (6, 5);
    let points: Vec<Value> = (0..nu)
        .map(|i| {
            let row: Vec<Value> = (0..nv)
                .map(|j| {
                    let (x, y) = (f64::from(i) / 5.0, f64::from(j) / 4.0);
                    json!([x, y, (3.0 * x).sin() * (2.0 * y).cos() + x * y * y])
                })
                .collect();
            Value::Array(row)
        })
        .collect();
    let mut v = json!({
        "type": "bspline-surface",
        "degree": [3, 3],
        "knots_u": [0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1],
        "knots_v": [0, 0, 0, 0, 0.45, 1, 1, 1, 1],
        "points": points,
    });
    if rational {
        let w: Vec<Value> = (0..nu)
            .map(|i| {
                json!(
                    (0..nv)
                        .map(|j| 1.0 + 0.15 * f64::from((i + 2 * j) % 4))
                        .collect::<Vec<_>>()
                )
            })
            .collect();
        v["weights"] = Value::Array(w);
    }
    v
}

/// A cagd-core surface from the command's JSON form (the test's own reading of it).
fn surface_of(v: &Value) -> cagd_core::BSplineSurface {
    let deg = |k: usize| usize::try_from(v["degree"][k].as_u64().expect("degree")).expect("small");
    let rows = v["points"].as_array().expect("rows");
    let (nu, nv) = (rows.len(), rows[0].as_array().expect("row").len());
    let dim = rows[0][0].as_array().expect("point").len();
    let pts: Vec<f64> = rows.iter().flat_map(flat).collect();
    let (ku, kv) = (flat(&v["knots_u"]), flat(&v["knots_v"]));
    match v.get("weights") {
        Some(w) => {
            let w: Vec<f64> = w.as_array().expect("rows").iter().flat_map(flat).collect();
            cagd_core::BSplineSurface::new_rational((deg(0), deg(1)), ku, kv, pts, w, (nu, nv), dim)
        }
        None => cagd_core::BSplineSurface::new((deg(0), deg(1)), ku, kv, pts, (nu, nv), dim),
    }
    .expect("valid surface")
}

/// The largest distance between two surfaces on a `30 x 30` grid of the first's domain.
fn grid_distance(a: &cagd_core::BSplineSurface, b: &cagd_core::BSplineSurface) -> f64 {
    let ((u0, u1), (v0, v1)) = a.domain();
    let mut worst = 0.0f64;
    for i in 0..30 {
        for j in 0..30 {
            let u = u0 + (u1 - u0) * f64::from(i) / 29.0;
            let v = v0 + (v1 - v0) * f64::from(j) / 29.0;
            let (x, y) = (a.eval(u, v).expect("eval"), b.eval(u, v).expect("eval"));
            let d: f64 = x.iter().zip(&y).map(|(p, q)| (p - q) * (p - q)).sum();
            worst = worst.max(d.sqrt());
        }
    }
    worst
}

#[test]
fn bspline_surfaces_to_a_tolerance_and_patchwise() {
    let tol = 1e-3;
    for rational in [false, true] {
        let input = bicubic_surface(rational);
        let out = json_out(&cagd(
            &["reduce", "--to", "2,2", "--tol", "1e-3"],
            &input.to_string(),
        ));
        assert_eq!(out["type"], "bspline-surface");
        assert_eq!(out["degree"], json!([2, 2]));
        assert_eq!(out.get("weights").is_some(), rational);
        let r = &out["report"];
        let (bound, measured) = (
            r["error_bound"].as_f64().expect("bound"),
            r["max_error"].as_f64().expect("measured"),
        );
        let (a, b) = (surface_of(&input), surface_of(&out));
        assert_eq!(b.degrees(), (2, 2));
        let d = grid_distance(&a, &b);
        assert!(
            d <= bound && measured <= bound && bound <= tol,
            "rational {rational}: grid {d}, measured {measured}, bound {bound}"
        );
        assert_eq!(r["degree_from"], json!([3, 3]));
        assert_eq!(r["spans_in"], json!([3, 2]));
        assert_eq!(r["tolerance"], tol);
        let (su, sv) = (
            r["spans_out"][0].as_u64().expect("u"),
            r["spans_out"][1].as_u64().expect("v"),
        );
        assert_eq!(r["patches"], su * sv);
        assert!(su >= 3 && sv >= 2);

        // Without --tol: patch-wise on the input's own knot spans, `--to 2` in both.
        let out = json_out(&cagd(&["reduce", "--to", "2"], &input.to_string()));
        let r = &out["report"];
        assert_eq!(r["spans_out"], json!([3, 2]));
        assert_eq!(r["patches"], 6);
        let bound = r["error_bound"].as_f64().expect("bound");
        let d = grid_distance(&surface_of(&input), &surface_of(&out));
        assert!(d <= bound, "rational {rational}: grid {d} > bound {bound}");
    }
    // One direction only, chebyshev.
    let out = json_out(&cagd(
        &["reduce", "--to", "3,2", "--method", "chebyshev"],
        &bicubic_surface(false).to_string(),
    ));
    assert_eq!(out["degree"], json!([3, 2]));
    assert_eq!(out["report"]["method"], "constrained-chebyshev");
}

#[test]
fn bad_surfaces_give_one_line_naming_the_field() {
    let good = bicubic_surface(true);
    let with = |f: &dyn Fn(&mut Value)| {
        let mut v = good.clone();
        f(&mut v);
        v.to_string()
    };
    let cases: Vec<(Vec<&str>, String, &str)> = vec![
        (
            vec![],
            with(&|v| {
                v["points"][4].as_array_mut().expect("row").pop();
            }),
            "cagd: input.points[4]: has 4 points, the first row has 5",
        ),
        (
            vec![],
            with(&|v| {
                v["knots_v"].as_array_mut().expect("knots").pop();
            }),
            "cagd: input.knots_v: has 8 knots, expected n_v + q + 1 = 9",
        ),
        (
            vec![],
            with(&|v| v["weights"][2][3] = json!(0)),
            "cagd: input.weights[2][3]: weight 0 must be > 0",
        ),
        (
            vec![],
            with(&|v| v["knots_u"][5] = json!(0.1)),
            "cagd: input.knots_u[5]: ",
        ),
        (
            vec![],
            with(&|v| v["points"][1][2][2] = json!(7.5)).replace("7.5", "1e999"),
            "cagd: input.points[1][2][2]: not valid JSON: number out of range",
        ),
        (
            vec!["--method", "forrest"],
            good.to_string(),
            "cagd: --method: forrest is not available for B-spline surfaces",
        ),
        (
            vec!["--r", "1"],
            good.to_string(),
            "cagd: --r: --r/--p do not apply to B-spline surfaces",
        ),
        (vec!["--to", "4,2"], good.to_string(), "cagd: input: "),
    ];
    for (extra, stdin, want) in &cases {
        let mut args = vec!["reduce"];
        if !extra.contains(&"--to") {
            args.extend(["--to", "2"]);
        }
        args.extend(extra);
        let o = cagd(&args, stdin);
        assert_eq!(o.status.code(), Some(2), "{args:?} {stdin}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(
            err.starts_with(want),
            "{args:?}: got {err:?}, want {want:?}"
        );
        assert!(o.stdout.is_empty());
    }
}
