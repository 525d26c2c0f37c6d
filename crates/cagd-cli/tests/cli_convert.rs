//! `cagd convert --to bezier|nurbs`: random NURBS curves nobody has seen (degree 1–7, up to
//! 20 spans, random knot multiplicities up to p + 1, each end clamped or not — unclamped
//! ends with random outer knots and multiplicities —, rational or not) go to Bézier pieces
//! and back; every segment equals its span (checked by cagd-core's de Boor evaluation) and
//! the round trip gives back the knot vector and the curve; surfaces likewise; bad input
//! is named.

mod common;

use cagd_core::{BSplineCurve, BSplineSurface, BezierCurve};
use cagd_testkit::flat;
use cagd_testkit::serde_json::{Value, json};
use common::{cagd, json_out};

/// A small deterministic generator (xorshift), so that the cases are reproducible.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    /// A number in `0..n` (the last of the `n` equal parts of `[0, 1)` at or below the draw).
    fn below(&mut self, n: usize) -> usize {
        let r = self.next() * n as f64;
        (1..n).take_while(|k| *k as f64 <= r).count()
    }
}

/// `p` knots beyond the end `at` of the domain, going in direction `dir` (-1: the left
/// end, as they come in the knot vector; +1: the right end): `p` copies of `at` (clamped)
/// about a third of the time, else some copies of `at` and then knots of random
/// multiplicity.
fn outer_knots(rng: &mut Rng, p: usize, at: f64, dir: f64) -> Vec<f64> {
    let copies = if rng.next() < 0.3 {
        p
    } else {
        rng.below(p + 1)
    };
    let mut ks = vec![at; copies];
    let mut t = at;
    while ks.len() < p {
        t += dir * (0.1 + rng.next());
        let m = (1 + rng.below(p)).min(p - ks.len());
        ks.extend(std::iter::repeat_n(t, m));
    }
    if dir < 0.0 {
        ks.reverse();
    }
    ks
}

fn random_curve(rng: &mut Rng) -> (Value, BSplineCurve) {
    let p = 1 + rng.below(7);
    let spans = 1 + rng.below(20);
    let dim = 1 + rng.below(3);
    let mut knots = outer_knots(rng, p, 0.0, -1.0);
    knots.push(0.0);
    let mut t = 0.0;
    for _ in 1..spans {
        t += 0.1 + rng.next();
        // Multiplicity 1..=p, sometimes p + 1 (the pieces do not meet).
        let m = 1 + rng.below(p + 1);
        knots.extend(std::iter::repeat_n(t, m));
    }
    t += 0.1 + rng.next();
    knots.push(t);
    knots.extend(outer_knots(rng, p, t, 1.0));
    let n = knots.len() - p - 1;
    let pts: Vec<f64> = (0..n * dim).map(|_| 20.0 * rng.next() - 10.0).collect();
    let rational = rng.next() < 0.5;
    let w: Vec<f64> = (0..n).map(|_| 0.05 + 10.0 * rng.next()).collect();
    let rows: Vec<Value> = pts.chunks(dim).map(|c| json!(c)).collect();
    let mut j = json!({"type": "bspline", "degree": p, "knots": knots, "points": rows});
    let c = if rational {
        j["weights"] = json!(w);
        BSplineCurve::new_rational(p, knots, pts, w, dim).unwrap()
    } else {
        BSplineCurve::new(p, knots, pts, dim).unwrap()
    };
    (j, c)
}

fn scale(c: &BSplineCurve) -> f64 {
    c.points().iter().fold(1.0f64, |m, x| m.max(x.abs()))
}

/// Whether both ends of the knot vector are clamped (`p + 1` copies of the domain ends).
fn knots_clamped(c: &BSplineCurve) -> bool {
    let (p, k) = (c.degree(), c.knots());
    let (lo, hi) = c.domain();
    k[..=p].iter().all(|x| *x == lo) && k[k.len() - p - 1..].iter().all(|x| *x == hi)
}

/// The curve of a `"bspline"` output object.
fn curve_of(v: &Value, dim: usize) -> BSplineCurve {
    let p = usize::try_from(v["degree"].as_u64().unwrap()).unwrap();
    let (knots, pts) = (flat(&v["knots"]), flat(&v["points"]));
    match v.get("weights") {
        Some(w) => BSplineCurve::new_rational(p, knots, pts, flat(w), dim),
        None => BSplineCurve::new(p, knots, pts, dim),
    }
    .unwrap()
}

#[test]
fn random_curves_round_trip() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut unclamped = 0;
    for case in 0..80 {
        let (input, c) = random_curve(&mut rng);
        let bz = json_out(&cagd(&["convert", "--to", "bezier"], &input.to_string()));
        assert_eq!(bz["type"], "beziers");
        assert_eq!(bz["weights"].is_null(), !c.is_rational(), "case {case}");
        let breaks = flat(&bz["breaks"]);
        let segs = bz["segments"].as_array().unwrap();
        assert_eq!(segs.len() + 1, breaks.len());
        let s = scale(&c);
        for (k, seg) in segs.iter().enumerate() {
            let pts = flat(seg);
            let b = if c.is_rational() {
                BezierCurve::new_rational(pts, flat(&bz["weights"][k]), c.dim())
            } else {
                BezierCurve::new(pts, c.dim())
            }
            .unwrap();
            // u = 1 only on the last piece: at a break the spline takes the right piece's
            // value, which differs from the left piece's end where they do not meet.
            let top = if k + 1 == segs.len() { 20 } else { 19 };
            for i in 0..=top {
                let u = f64::from(i) / 20.0;
                let t = breaks[k] + u * (breaks[k + 1] - breaks[k]);
                let (x, y) = (b.eval(u), c.eval(t).unwrap());
                let d = c.derivatives(t, 1).unwrap();
                let speed = d[1].iter().fold(0.0f64, |m, v| m.max(v.abs()));
                for (xi, yi) in x.iter().zip(&y) {
                    assert!(
                        (xi - yi).abs()
                            <= 1e-12 * s + 4.0 * f64::EPSILON * speed * t.abs().max(1.0),
                        "case {case} piece {k} u {u}: {x:?} vs {y:?}"
                    );
                }
            }
        }
        assert!(bz["report"]["max_difference"].as_f64().unwrap() <= 1e-12 * s * 10.0);
        // The outer knots travel with the pieces exactly when the curve is unclamped.
        let clamped = knots_clamped(&c);
        assert_eq!(bz.get("outer_knots").is_none(), clamped, "case {case}");
        // Back: the same knot vector (same values, same multiplicities) and the same curve.
        let back = json_out(&cagd(&["convert", "--to", "nurbs"], &bz.to_string()));
        assert_eq!(back["type"], "bspline");
        assert_eq!(flat(&back["knots"]), c.knots(), "case {case}");
        let curve = curve_of(&back, c.dim());
        for k in 0..segs.len() {
            for i in 0..=40 {
                let t = breaks[k] + f64::from(i) / 40.0 * (breaks[k + 1] - breaks[k]);
                let (x, y) = (curve.eval(t).unwrap(), c.eval(t).unwrap());
                for (xi, yi) in x.iter().zip(&y) {
                    assert!(
                        (xi - yi).abs() <= 1e-12 * s,
                        "case {case} t {t}: {x:?} vs {y:?}"
                    );
                }
            }
        }
        if clamped {
            // Clamped: every point is a well-conditioned blossom, the same points. (An
            // unclamped end's outer points are extrapolated blossoms: their rounding is
            // amplified, the curve does not see it; checked by evaluation above.)
            for (g, w) in flat(&back["points"]).iter().zip(c.points()) {
                assert!((g - w).abs() <= 1e-12 * s, "case {case}: {g} vs {w}");
            }
        }
        match c.weights() {
            Some(w) if clamped => {
                for (g, e) in flat(&back["weights"]).iter().zip(w) {
                    assert!((g - e).abs() <= 1e-12 * e, "case {case}");
                }
            }
            Some(_) => assert!(back["weights"].is_array()),
            None => assert!(back.get("weights").is_none()),
        }
        let cont: Vec<i64> = back["report"]["continuity"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_i64().unwrap())
            .collect();
        assert_eq!(
            cont,
            bz["report"]["continuity"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_i64().unwrap())
                .collect::<Vec<_>>()
        );
        unclamped += usize::from(!clamped);
        // cagd merge reads the same object (when the pieces meet: it checks C0).
        if !cont.contains(&-1) {
            let merged = json_out(&cagd(&["merge"], &bz.to_string()));
            assert_eq!(merged["type"], "bspline");
        }
    }
    // Both kinds were drawn (the generator clamps an end about a third of the time).
    assert!(unclamped >= 20, "{unclamped} unclamped cases of 80");
}

#[test]
fn one_rational_bezier_to_nurbs_and_standard_form() {
    let input = json!({"type": "bezier", "points": [[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
                       "weights": [1.0, std::f64::consts::SQRT_2, 4.0]});
    let out = json_out(&cagd(&["convert", "--to", "nurbs"], &input.to_string()));
    assert_eq!(flat(&out["knots"]), [0.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
    assert_eq!(flat(&out["weights"]), [1.0, std::f64::consts::SQRT_2, 4.0]);
    let sf = json_out(&cagd(
        &["convert", "--to", "bezier", "--standard-form"],
        &input.to_string(),
    ));
    let w = flat(&sf["weights"]);
    assert!(
        (w[0] - 1.0).abs() < 1e-15 && (w[2] - 1.0).abs() < 1e-15,
        "{w:?}"
    );
    // Same shape: a quarter circle stays on the unit circle.
    let b = BezierCurve::new_rational(flat(&sf["points"]), w, 2).unwrap();
    for i in 0..=10 {
        let p = b.eval(f64::from(i) / 10.0);
        assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-15, "{p:?}");
    }
}

#[test]
fn surfaces_round_trip() {
    let ku = vec![0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0];
    let kv = vec![0.0, 0.0, 0.5, 0.5, 2.0, 2.0];
    let (nu, nv) = (4, 4);
    let mut rng = Rng(7);
    let pts: Vec<f64> = (0..nu * nv * 3).map(|_| rng.next() * 4.0).collect();
    let w: Vec<f64> = (0..nu * nv).map(|_| 0.5 + rng.next()).collect();
    let s = BSplineSurface::new_rational(
        (2, 1),
        ku.clone(),
        kv.clone(),
        pts.clone(),
        w.clone(),
        (nu, nv),
        3,
    )
    .unwrap();
    let nest = |f: &[f64], per: usize| -> Value {
        json!(
            (0..nu)
                .map(|i| (0..nv)
                    .map(|j| json!(f[(i * nv + j) * per..(i * nv + j + 1) * per]))
                    .collect::<Vec<_>>())
                .collect::<Vec<_>>()
        )
    };
    let wn: Value = json!(
        (0..nu)
            .map(|i| w[i * nv..(i + 1) * nv].to_vec())
            .collect::<Vec<_>>()
    );
    let input = json!({"type": "bspline-surface", "degree": [2, 1], "knots_u": ku, "knots_v": kv,
                       "points": nest(&pts, 3), "weights": wn});
    let bz = json_out(&cagd(&["convert", "--to", "bezier"], &input.to_string()));
    assert_eq!(bz["type"], "bezier-patches");
    assert_eq!(bz["patches"].as_array().unwrap().len(), 2 * 2);
    let back = json_out(&cagd(&["convert", "--to", "nurbs"], &bz.to_string()));
    assert_eq!(back["type"], "bspline-surface");
    assert_eq!(flat(&back["knots_u"]), ku);
    assert_eq!(flat(&back["knots_v"]), kv);
    for (u, v) in [(0.1, 0.2), (0.5, 1.3), (0.9, 1.9)] {
        let want = s.eval(u, v).unwrap();
        let got = BSplineSurface::new_rational(
            (2, 1),
            flat(&back["knots_u"]),
            flat(&back["knots_v"]),
            flat(&back["points"]),
            flat(&back["weights"]),
            (nu, nv),
            3,
        )
        .unwrap()
        .eval(u, v)
        .unwrap();
        for (a, b) in got.iter().zip(&want) {
            assert!((a - b).abs() < 1e-12);
        }
    }
}

#[test]
fn bad_input_is_named() {
    let cases = [
        (
            vec!["convert"],
            r#"{"type":"bspline","degree":1,"knots":[0,0,1,1],"points":[[0],[1]]}"#,
            "--to",
        ),
        (
            vec!["convert", "--to", "spline"],
            r#"{"type":"bezier","points":[[0],[1]]}"#,
            "--to",
        ),
        (
            vec!["convert", "--to", "bezier"],
            r#"{"type":"bspline","degree":1,"knots":[0,1,0.5,1],"points":[[0],[1]]}"#,
            "input.knots[2]",
        ),
        (
            vec!["convert", "--to", "bezier"],
            r#"{"type":"bspline","degree":1,"knots":[0,0,1,1],"points":[[0],[1]],"weights":[1,0]}"#,
            "input.weights[1]",
        ),
        (
            vec!["convert", "--to", "bezier"],
            r#"{"type":"bspline","degree":1,"knots":[0,0,1],"points":[[0],[1]]}"#,
            "input.knots",
        ),
        (
            vec!["convert", "--to", "nurbs"],
            r#"{"type":"beziers","segments":[[[0],[1]],[[1],[2],[3]]]}"#,
            "input.segments[1]",
        ),
        (
            vec!["convert", "--to", "nurbs"],
            r#"{"type":"beziers","segments":[[[0],[1]],[[1],[2]]],"breaks":[0,1,1]}"#,
            "input.breaks[2]",
        ),
        (
            vec!["convert", "--to", "nurbs"],
            r#"{"type":"beziers","segments":[[[0],[1]],[[1],[2]]],"outer_knots":{"left":[0.5],"right":[3]}}"#,
            "input.outer_knots.left",
        ),
        (
            vec!["convert", "--to", "nurbs"],
            r#"{"type":"beziers","segments":[[[0],[1]],[[1],[2]]],"outer_knots":{"left":[-1]}}"#,
            "input.outer_knots.right",
        ),
        (
            vec!["convert", "--to", "nurbs"],
            r#"{"type":"beziers","segments":[[[0],[1]],[[1],[2]]],"outer_knots":[1]}"#,
            "input.outer_knots",
        ),
        (
            vec!["convert", "--to", "nurbs"],
            r#"{"type":"beziers","segments":[[[0],[1]],[[1],[2]]],"outer_knots":{"left":[-1],"right":[1.5]}}"#,
            "input.outer_knots.right",
        ),
        (
            vec!["convert", "--to", "bezier"],
            r#"{"type":"tensor","degree":[1,1],"points":[[0],[1],[2],[3]]}"#,
            "is not a patch conversion",
        ),
        (
            vec!["convert", "--to", "bezier", "--split-line", "1,0"],
            r#"{"type":"bspline","degree":1,"knots":[0,0,1,1],"points":[[0],[1]]}"#,
            "cagd convert on patches takes a \"triangle\" or a \"tensor\"",
        ),
        (
            vec!["convert", "--to", "bezier"],
            r#"{"type":"bspline","degree":1,"knots":[0,0,1,1],"points":[[0],[1e999]]}"#,
            "input",
        ),
    ];
    for (args, text, want) in cases {
        let out = cagd(&args, text);
        assert_eq!(out.status.code(), Some(2), "{text}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(want), "{text}: {err}");
    }
}
