//! Laws of the patch reducers: exact elevations come back, measured error <= certified
//! bound, constraints hold, pieces of reductions to a tolerance meet C⁰, errors not panics.

use cagd_core::{TensorPatch, TriPatch, tri_count};
use cagd_reduce::{
    Error, Method, PatchConstraint, PatchOptions, TensorMethod, TriMethod, TriOptions, operator,
    reduce_tensor, reduce_tensor_to_tolerance, reduce_triangle, reduce_triangle_to_tolerance,
};
use cagd_testkit::points;
use proptest::prelude::*;

const L2_00: Method = Method::L2 { r: 0, p: 0 };

/// Round-trip tolerance relative to the net size: inverse elevations and rounded operators
/// cost a few hundred ulp at these degrees (<= 6).
const ROUND_TRIP: f64 = 1e-12;

fn tensor_methods() -> Vec<TensorMethod> {
    vec![
        TensorMethod::Perturb(PatchConstraint::None),
        TensorMethod::Perturb(PatchConstraint::Corners),
        TensorMethod::Perturb(PatchConstraint::Boundary(L2_00)),
        TensorMethod::Perturb(PatchConstraint::Boundary(Method::Perturb)),
        TensorMethod::Curves {
            u: L2_00,
            v: Method::ConstrainedChebyshev { r: 0, p: 0 },
        },
        TensorMethod::Curves {
            u: Method::Eck,
            v: Method::GeneralizedInverse,
        },
    ]
}

fn tri_methods() -> Vec<TriMethod> {
    vec![
        TriMethod::Perturb,
        TriMethod::L2(PatchConstraint::None),
        TriMethod::L2(PatchConstraint::Corners),
        TriMethod::L2(PatchConstraint::Boundary(L2_00)),
    ]
}

fn size(x: &[f64]) -> f64 {
    x.iter().fold(1.0f64, |a, b| a.max(b.abs()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn tensor_exact_elevation_reduces_back(
        (m, n) in (2usize..5, 2usize..5),
        pts in points(25, 3),
    ) {
        let q = TensorPatch::new(pts[..m * n * 3].to_vec(), m - 1, n - 1, 3).unwrap();
        let p = q.elevate_u(1).unwrap().elevate_v(1).unwrap();
        for method in tensor_methods() {
            let red = reduce_tensor(&p, (m - 1, n - 1), &PatchOptions::new(method)).unwrap();
            let err = red.patch.points().iter().zip(q.points()).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
            prop_assert!(err <= ROUND_TRIP * size(q.points()), "{method:?}: {err}");
            prop_assert!(red.report.error_bound <= ROUND_TRIP * size(q.points()));
        }
    }

    #[test]
    fn tensor_multi_degree_elevation_reduces_back(pts in points(9, 2)) {
        let q = TensorPatch::new(pts, 2, 2, 2).unwrap();
        let p = q.elevate_u(3).unwrap().elevate_v(2).unwrap();
        let opts = PatchOptions::new(TensorMethod::Curves { u: Method::L2 { r: 1, p: 0 }, v: L2_00 });
        let red = reduce_tensor(&p, (2, 2), &opts).unwrap();
        let err = red.patch.points().iter().zip(q.points()).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        prop_assert!(err <= ROUND_TRIP * size(q.points()));
    }

    #[test]
    fn tri_exact_elevation_reduces_back(n in 2usize..7, pts in points(28, 2)) {
        let q = TriPatch::new(pts[..tri_count(n - 1) * 2].to_vec(), n - 1, 2).unwrap();
        let p = q.elevate(1).unwrap();
        for method in tri_methods() {
            let red = reduce_triangle(&p, n - 1, &TriOptions::new(method)).unwrap();
            let err = red.patch.points().iter().zip(q.points()).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
            prop_assert!(err <= ROUND_TRIP * size(q.points()), "{method:?} n={n}: {err}");
        }
        // Multi-degree L2: degree n - 1 elevated by 3 comes back.
        let p3 = q.elevate(3).unwrap();
        let red = reduce_triangle(&p3, n - 1, &TriOptions::new(TriMethod::L2(PatchConstraint::Boundary(L2_00)))).unwrap();
        let err = red.patch.points().iter().zip(q.points()).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        prop_assert!(err <= ROUND_TRIP * size(q.points()));
    }

    #[test]
    fn tensor_measured_error_within_bound((m, n) in (2usize..6, 2usize..6), pts in points(36, 3)) {
        let p = TensorPatch::new(pts[..(m + 1) * (n + 1) * 3].to_vec(), m, n, 3).unwrap();
        for method in tensor_methods() {
            let opts = PatchOptions { method, measure: true };
            let red = reduce_tensor(&p, (m - 1, n - 1), &opts).unwrap();
            let measured = red.report.max_error.unwrap();
            prop_assert!(measured <= red.report.error_bound * (1.0 + 1e-12), "{method:?}: {measured} > {}", red.report.error_bound);
        }
        if m >= 4 && n >= 3 {
            let opts = PatchOptions { method: TensorMethod::Curves { u: Method::L2 { r: 1, p: 0 }, v: Method::Eck }, measure: true };
            let red = reduce_tensor(&p, (m - 2, n - 1), &opts).unwrap();
            prop_assert!(red.report.max_error.unwrap() <= red.report.error_bound * (1.0 + 1e-12));
        }
    }

    #[test]
    fn tri_measured_error_within_bound(n in 2usize..7, pts in points(28, 3)) {
        let p = TriPatch::new(pts[..tri_count(n) * 3].to_vec(), n, 3).unwrap();
        for method in tri_methods() {
            let m = if method == TriMethod::Perturb { n - 1 } else { n / 2 + 1 }.min(n - 1);
            let red = reduce_triangle(&p, m, &TriOptions { method, measure: true }).unwrap();
            let measured = red.report.max_error.unwrap();
            prop_assert!(measured <= red.report.error_bound * (1.0 + 1e-12), "{method:?}: {measured} > {}", red.report.error_bound);
        }
    }

    #[test]
    fn constraints_hold((m, n) in (3usize..6, 3usize..6), pts in points(36, 2)) {
        let p = TensorPatch::new(pts[..(m + 1) * (n + 1) * 2].to_vec(), m, n, 2).unwrap();
        let red = reduce_tensor(&p, (m - 1, n - 1), &PatchOptions::new(TensorMethod::Perturb(PatchConstraint::Corners))).unwrap();
        for (i, j, iq, jq) in [(0, 0, 0, 0), (m, 0, m - 1, 0), (0, n, 0, n - 1), (m, n, m - 1, n - 1)] {
            prop_assert_eq!(p.point(i, j), red.patch.point(iq, jq));
        }
        // Boundary: Q's boundary rows are the curve reductions of P's (both variants).
        let op = operator(L2_00, n, n - 1).unwrap();
        for method in [TensorMethod::Perturb(PatchConstraint::Boundary(L2_00)), TensorMethod::Curves { u: L2_00, v: L2_00 }] {
            let (mt, nt) = (m - 1, n - 1);
            let red = reduce_tensor(&p, (mt, nt), &PatchOptions::new(method)).unwrap();
            let row0 = op.apply(&p.points()[..(n + 1) * 2], 2).unwrap();
            prop_assert_eq!(&red.patch.points()[..(nt + 1) * 2], &row0[..]);
        }
    }
}

/// Tensor pieces: neighbours share their edge rows / columns.
fn check_tensor_c0(pieces: &[cagd_reduce::TensorPiece], tol: f64) {
    for a in pieces {
        for b in pieces {
            let (pa, pb) = (&a.reduction.patch, &b.reduction.patch);
            let (m, n) = pa.degrees();
            if a.u.1 == b.u.0 && a.v == b.v {
                for j in 0..=n {
                    let d = pa
                        .point(m, j)
                        .iter()
                        .zip(pb.point(0, j))
                        .map(|(x, y)| (x - y).abs())
                        .fold(0.0, f64::max);
                    assert!(d <= tol, "u-edge gap {d}");
                }
            }
            if a.v.1 == b.v.0 && a.u == b.u {
                for i in 0..=m {
                    let d = pa
                        .point(i, n)
                        .iter()
                        .zip(pb.point(i, 0))
                        .map(|(x, y)| (x - y).abs())
                        .fold(0.0, f64::max);
                    assert!(d <= tol, "v-edge gap {d}");
                }
            }
        }
    }
}

/// The patch restricted to `[u0, u1] x [v0, v1]`, reparametrised to the unit square.
fn sub_patch(p: &TensorPatch, (u0, u1): (f64, f64), (v0, v1): (f64, f64)) -> TensorPatch {
    let a = p.subdivide_u(u1).unwrap().0;
    let a = a.subdivide_u(u0 / u1).unwrap().1;
    let b = a.subdivide_v(v1).unwrap().0;
    b.subdivide_v(v0 / v1).unwrap().1
}

#[test]
fn tensor_tolerance_pieces_meet_c0() {
    let pts: Vec<f64> = (0..36 * 3)
        .map(|i| ((i * 7919 % 97) as f64) / 10.0 - 4.0)
        .collect();
    let p = TensorPatch::new(pts, 5, 5, 3).unwrap();
    for method in [
        TensorMethod::Curves { u: L2_00, v: L2_00 },
        TensorMethod::Perturb(PatchConstraint::Boundary(L2_00)),
    ] {
        let target = if matches!(method, TensorMethod::Curves { .. }) {
            (3, 3)
        } else {
            (4, 4)
        };
        let pieces =
            reduce_tensor_to_tolerance(&p, target, 1e-3, &PatchOptions::new(method)).unwrap();
        assert!(pieces.len() > 1);
        assert!(
            pieces
                .iter()
                .all(|x| x.reduction.report.error_bound <= 1e-3)
        );
        check_tensor_c0(&pieces, 1e-12 * size(p.points()));
        // Each piece is within the tolerance of the patch on its sub-domain (measured).
        for piece in pieces.iter().step_by(5) {
            let sub = sub_patch(&p, piece.u, piece.v);
            let d = cagd_core::tensor_patch_distance(&sub, &piece.reduction.patch).unwrap();
            assert!(d <= 1e-3, "{d}");
        }
    }
}

/// Triangle pieces: points on every piece's edges evaluate equally in every piece holding them.
#[test]
fn tri_tolerance_pieces_meet_c0() {
    let pts: Vec<f64> = (0..tri_count(6) * 3)
        .map(|i| ((i * 7919 % 89) as f64) / 10.0 - 4.0)
        .collect();
    let t = TriPatch::new(pts, 6, 3).unwrap();
    let opts = TriOptions::new(TriMethod::L2(PatchConstraint::Boundary(L2_00)));
    let pieces = reduce_triangle_to_tolerance(&t, 4, 1e-2, &opts).unwrap();
    assert!(pieces.len() >= 4);
    let local = |v: &[(f64, f64); 3], x: (f64, f64)| {
        let [a, b, c] = *v;
        let (e1, e2, r) = (
            (a.0 - c.0, a.1 - c.1),
            (b.0 - c.0, b.1 - c.1),
            (x.0 - c.0, x.1 - c.1),
        );
        let det = e1.0 * e2.1 - e1.1 * e2.0;
        (
            (r.0 * e2.1 - r.1 * e2.0) / det,
            (e1.0 * r.1 - e1.1 * r.0) / det,
        )
    };
    let mut checked = 0;
    for a in &pieces {
        let [va, vb, vc] = a.vertices;
        for (s, e) in [(va, vb), (vb, vc), (vc, va)] {
            for k in 1..6 {
                let f = f64::from(k) / 6.0;
                let x = (s.0 + f * (e.0 - s.0), s.1 + f * (e.1 - s.1));
                let (u, v) = local(&a.vertices, x);
                let ya = a.reduction.patch.eval(u, v).unwrap();
                for b in &pieces {
                    let (ub, vb2) = local(&b.vertices, x);
                    if ub < -1e-12 || vb2 < -1e-12 || ub + vb2 > 1.0 + 1e-12 || std::ptr::eq(a, b) {
                        continue;
                    }
                    let yb = b.reduction.patch.eval(ub, vb2).unwrap();
                    let d = ya
                        .iter()
                        .zip(&yb)
                        .map(|(p, q)| (p - q).abs())
                        .fold(0.0, f64::max);
                    assert!(d <= 1e-12 * size(t.points()), "gap {d}");
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 0);
    // Each piece is within the tolerance of the original on its sub-triangle (measured).
    for piece in pieces.iter().take(5) {
        let [a, b, c] = piece.vertices;
        let sub = t.reparametrize(a, b, c).unwrap();
        let d = cagd_core::tri_patch_distance(&sub, &piece.reduction.patch).unwrap();
        assert!(d <= 1e-2);
    }
}

#[test]
fn errors_not_panics() {
    let p = TensorPatch::new(vec![0.0; 16], 3, 3, 1).unwrap();
    let free = PatchOptions::new(TensorMethod::Perturb(PatchConstraint::None));
    let curves = PatchOptions::new(TensorMethod::Curves { u: L2_00, v: L2_00 });
    assert!(matches!(
        reduce_tensor(&p, (4, 2), &curves),
        Err(Error::BadDegreePair { .. })
    ));
    assert!(matches!(
        reduce_tensor(&p, (3, 3), &curves),
        Err(Error::BadDegreePair { .. })
    ));
    assert!(matches!(
        reduce_tensor(&p, (1, 1), &free),
        Err(Error::BadDegreePair { .. })
    ));
    let lin = TensorPatch::new(vec![0.0; 6], 1, 2, 1).unwrap();
    let corners = PatchOptions::new(TensorMethod::Perturb(PatchConstraint::Corners));
    assert!(matches!(
        reduce_tensor(&lin, (0, 1), &corners),
        Err(Error::TooManyConstraints { .. })
    ));
    let eck = PatchOptions::new(TensorMethod::Perturb(PatchConstraint::Boundary(
        Method::Eck,
    )));
    assert!(matches!(
        reduce_tensor(&p, (2, 2), &eck),
        Err(Error::TooManyConstraints { .. })
    ));
    let hermite = PatchOptions::new(TensorMethod::Perturb(PatchConstraint::Boundary(
        Method::L2 { r: 1, p: 1 },
    )));
    assert!(matches!(
        reduce_tensor(&p, (2, 2), &hermite),
        Err(Error::TooManyConstraints { .. })
    ));
    for tol in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            reduce_tensor_to_tolerance(&p, (2, 2), tol, &curves),
            Err(Error::BadTolerance { .. })
        ));
    }
    let t = TriPatch::new(vec![0.0; 10], 3, 1).unwrap();
    let l2 = TriOptions::new(TriMethod::L2(PatchConstraint::None));
    assert!(matches!(
        reduce_triangle(&t, 3, &l2),
        Err(Error::BadDegreePair { .. })
    ));
    assert!(matches!(
        reduce_triangle(&t, 1, &TriOptions::new(TriMethod::Perturb)),
        Err(Error::BadDegreePair { .. })
    ));
    let corner0 = TriOptions::new(TriMethod::L2(PatchConstraint::Corners));
    assert!(matches!(
        reduce_triangle(&t, 0, &corner0),
        Err(Error::TooManyConstraints { .. })
    ));
    let asym = TriOptions::new(TriMethod::L2(PatchConstraint::Boundary(Method::L2 {
        r: 1,
        p: 0,
    })));
    assert!(matches!(
        reduce_triangle_to_tolerance(&t, 2, 0.1, &asym),
        Err(Error::ConditionNotMet { .. })
    ));
    assert!(matches!(
        reduce_triangle_to_tolerance(&t, 2, f64::NAN, &l2),
        Err(Error::BadTolerance { .. })
    ));
    // A tolerance below the rounding floor cannot be reached: an error, not a hang.
    let big: Vec<f64> = (0..10).map(|i| f64::from(i * i % 7)).collect();
    let t = TriPatch::new(big, 3, 1).unwrap();
    assert!(matches!(
        reduce_triangle_to_tolerance(&t, 1, 1e-300, &l2),
        Err(Error::NoConvergence { .. })
    ));
}
