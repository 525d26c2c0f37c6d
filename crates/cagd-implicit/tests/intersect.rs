//! Curve–curve intersection against an independent subdivision intersector written here
//! (control-polygon boxes, de Casteljau splitting, chord intersection, Newton polish):
//! every intersection of one is found by the other within 1e-10 in both parameters.

use cagd_core::BezierCurve;
use cagd_implicit::intersect;
use proptest::prelude::*;

fn curve(lo: usize, hi: usize) -> impl Strategy<Value = BezierCurve> {
    (lo..=hi).prop_flat_map(|n| {
        (
            proptest::collection::vec(-1.0f64..1.0, 2 * (n + 1)),
            proptest::collection::vec(0.5f64..2.0, n + 1),
        )
            .prop_map(|(p, w)| BezierCurve::new_rational(p, w, 2).unwrap())
    })
}

fn bbox(c: &BezierCurve) -> [f64; 4] {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for i in 0..=c.degree() {
        let p = c.point(i);
        b[0] = b[0].min(p[0]);
        b[1] = b[1].min(p[1]);
        b[2] = b[2].max(p[0]);
        b[3] = b[3].max(p[1]);
    }
    b
}

fn tangent(c: &BezierCurve, t: f64) -> [f64; 2] {
    let h = 1e-7;
    let (a, b) = (c.eval((t - h).max(0.0)), c.eval((t + h).min(1.0)));
    let dt = (t + h).min(1.0) - (t - h).max(0.0);
    [(b[0] - a[0]) / dt, (b[1] - a[1]) / dt]
}

struct Reference<'a> {
    a: &'a BezierCurve,
    b: &'a BezierCurve,
    hits: Vec<(f64, f64)>,
}

impl Reference<'_> {
    fn run(
        &mut self,
        pa: &BezierCurve,
        s: (f64, f64),
        pb: &BezierCurve,
        t: (f64, f64),
        depth: u32,
    ) {
        let (ba, bb) = (bbox(pa), bbox(pb));
        let m = 1e-12;
        if ba[0] > bb[2] + m || bb[0] > ba[2] + m || ba[1] > bb[3] + m || bb[1] > ba[3] + m {
            return;
        }
        let small = |b: [f64; 4]| (b[2] - b[0]).max(b[3] - b[1]) < 1e-7;
        if (small(ba) && small(bb)) || depth > 60 {
            // Chord intersection.
            let (a0, a1) = (pa.eval(0.0), pa.eval(1.0));
            let (b0, b1) = (pb.eval(0.0), pb.eval(1.0));
            let da = [a1[0] - a0[0], a1[1] - a0[1]];
            let db = [b1[0] - b0[0], b1[1] - b0[1]];
            let det = -da[0] * db[1] + db[0] * da[1];
            let r = [b0[0] - a0[0], b0[1] - a0[1]];
            let (u, v) = if det.abs() > 0.0 {
                (
                    (-r[0] * db[1] + db[0] * r[1]) / det,
                    (da[0] * r[1] - da[1] * r[0]) / det,
                )
            } else {
                (0.5, 0.5)
            };
            if (-0.5..=1.5).contains(&u) && (-0.5..=1.5).contains(&v) {
                let ss = s.0 + u.clamp(0.0, 1.0) * (s.1 - s.0);
                let tt = t.0 + v.clamp(0.0, 1.0) * (t.1 - t.0);
                self.hits.push(self.newton(ss, tt));
            }
            return;
        }
        let wa = (ba[2] - ba[0]).max(ba[3] - ba[1]);
        let wb = (bb[2] - bb[0]).max(bb[3] - bb[1]);
        if wa >= wb {
            let (l, r) = pa.subdivide(0.5).unwrap();
            let mid = 0.5 * (s.0 + s.1);
            self.run(&l, (s.0, mid), pb, t, depth + 1);
            self.run(&r, (mid, s.1), pb, t, depth + 1);
        } else {
            let (l, r) = pb.subdivide(0.5).unwrap();
            let mid = 0.5 * (t.0 + t.1);
            self.run(pa, s, &l, (t.0, mid), depth + 1);
            self.run(pa, s, &r, (mid, t.1), depth + 1);
        }
    }

    fn newton(&self, mut s: f64, mut t: f64) -> (f64, f64) {
        for _ in 0..20 {
            let (p, q) = (self.a.eval(s), self.b.eval(t));
            let (dp, dq) = (tangent(self.a, s), tangent(self.b, t));
            let r = [p[0] - q[0], p[1] - q[1]];
            let det = -dp[0] * dq[1] + dq[0] * dp[1];
            if det.abs() < 1e-14 {
                break;
            }
            let ds = (r[0] * dq[1] - dq[0] * r[1]) / det;
            let dt = (dp[0] * -r[1] + dp[1] * r[0]) / det;
            s = (s + ds).clamp(0.0, 1.0);
            t = (t + dt).clamp(0.0, 1.0);
            if ds.abs().max(dt.abs()) < 1e-15 {
                break;
            }
        }
        (s, t)
    }
}

fn reference(a: &BezierCurve, b: &BezierCurve) -> Vec<(f64, f64)> {
    let mut r = Reference {
        a,
        b,
        hits: Vec::new(),
    };
    r.run(a, (0.0, 1.0), b, (0.0, 1.0), 0);
    let mut out: Vec<(f64, f64)> = Vec::new();
    for (s, t) in r.hits {
        let (p, q) = (a.eval(s), b.eval(t));
        if (p[0] - q[0]).hypot(p[1] - q[1]) > 1e-11 {
            continue;
        }
        if !out
            .iter()
            .any(|o| (o.0 - s).abs() < 1e-8 && (o.1 - t).abs() < 1e-8)
        {
            out.push((s, t));
        }
    }
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn intersections_match_a_subdivision_intersector(a in curve(1, 5), b in curve(1, 5)) {
        let got = intersect(&a, &b).unwrap();
        let want = reference(&a, &b);
        for h in &got {
            let (p, q) = (a.eval(h.s), b.eval(h.t));
            prop_assert!((p[0] - q[0]).hypot(p[1] - q[1]) < 1e-10, "{h:?} is not an intersection");
            prop_assert!((0.0..=1.0).contains(&h.s) && (0.0..=1.0).contains(&h.t));
        }
        for w in &want {
            prop_assert!(
                got.iter().any(|h| (h.s - w.0).abs() <= 1e-10 && (h.t - w.1).abs() <= 1e-10),
                "missed {w:?}; got {got:?}"
            );
        }
        prop_assert_eq!(got.len(), want.len(), "got {:?}, reference {:?}", got, want);
        prop_assert!(got.windows(2).all(|w| w[0].s <= w[1].s));
    }
}

#[test]
fn tangential_intersection_is_flagged() {
    // The unit-circle quarter and the line x = 1 touch at (1, 0)... use y = 1 - x^2 style:
    // parabola y = 2x(1 - x)·2 ... simpler: the parabola (0,0),(1,2),(2,0) has its apex at
    // (1, 1); the line y = 1 touches it there.
    let a = BezierCurve::new(vec![0.0, 0.0, 1.0, 2.0, 2.0, 0.0], 2).unwrap();
    let b = BezierCurve::new(vec![-1.0, 1.0, 3.0, 1.0], 2).unwrap();
    let hits = intersect(&a, &b).unwrap();
    assert_eq!(hits.len(), 1, "{hits:?}");
    assert!(hits[0].tangential);
    assert!((hits[0].s - 0.5).abs() < 1e-7 && (hits[0].t - 0.5).abs() < 1e-7);
}

#[test]
fn overlapping_curves_are_coincident() {
    let a = BezierCurve::new(vec![0.0, 0.0, 1.0, 2.0, 2.0, 0.0], 2).unwrap();
    let (l, _) = a.subdivide(0.6).unwrap();
    let (_, r) = a.subdivide(0.3).unwrap();
    assert!(matches!(
        intersect(&l, &r),
        Err(cagd_core::Error::Coincident { .. })
    ));
    assert!(matches!(
        intersect(&a, &a),
        Err(cagd_core::Error::Coincident { .. })
    ));
    // Same algebraic curve, disjoint arcs that share an end point: one intersection.
    let (l, r) = a.subdivide(0.5).unwrap();
    let hits = intersect(&l, &r).unwrap();
    assert_eq!(hits.len(), 1, "{hits:?}");
    assert!((hits[0].s - 1.0).abs() < 1e-12 && hits[0].t.abs() < 1e-12);
}

#[test]
fn bad_input_is_a_named_error() {
    let a = BezierCurve::new(vec![0.0, 0.0, 1.0, 2.0, 2.0, 0.0], 2).unwrap();
    let c3 = BezierCurve::new(vec![0.0; 6], 3).unwrap();
    assert!(matches!(
        intersect(&a, &c3),
        Err(cagd_core::Error::NotPlanar { dim: 3 })
    ));
    let p = BezierCurve::new(vec![1.0, 1.0], 2).unwrap();
    assert!(matches!(
        intersect(&p, &a),
        Err(cagd_core::Error::NotEnoughPoints { .. })
    ));
}

#[test]
fn improper_and_degree_elevated_curves_intersect() {
    // A collinear quadratic (traced twice by its implicit polynomial (x - y)^2) against the
    // line x + y = 1: one transversal intersection at (1/2, 1/2).
    let a = BezierCurve::new(vec![0.0, 0.0, 2.0, 2.0, 1.0, 1.0], 2).unwrap();
    let b = BezierCurve::new(vec![0.0, 1.0, 1.0, 0.0], 2).unwrap();
    let hits = intersect(&a, &b).unwrap();
    assert_eq!(hits.len(), 1, "{hits:?}");
    let s = (4.0 - 10f64.sqrt()) / 6.0; // 4s - 3s^2 = 1/2
    assert!(
        (hits[0].s - s).abs() < 1e-12 && (hits[0].t - 0.5).abs() < 1e-12,
        "{hits:?}"
    );
    assert!(!hits[0].tangential);
    // The same with the line given degree-elevated (a base point at t = ∞) on either side.
    let b3 = b.elevate(2).unwrap();
    for (x, y, swap) in [(&a, &b3, false), (&b3, &a, true)] {
        let hits = intersect(x, y).unwrap();
        assert_eq!(hits.len(), 1, "{hits:?}");
        let (hs, ht) = if swap {
            (hits[0].t, hits[0].s)
        } else {
            (hits[0].s, hits[0].t)
        };
        assert!(
            (hs - s).abs() < 1e-12 && (ht - 0.5).abs() < 1e-12,
            "{hits:?}"
        );
    }
}
