//! Tests of triangular patches: indexing, operations (ops.rs) and subdivision (subdivide.rs).

use crate::binomial::binomial_f64;
use crate::{Error, TriPatch, tri_count, tri_index};
use cagd_testkit::{assert_close, num, vector};
use proptest::prelude::*;

/// Relative tolerance of the laws: convex-combination algorithms with an error of a few `n`
/// ulp of the net's size (`n <= 7` here); 1e-12 leaves a margin of ~100.
const LAW_TOL: f64 = 1e-12;

fn size(p: &[f64]) -> f64 {
    p.iter().fold(1.0f64, |m, x| m.max(x.abs()))
}

/// The 1-D patch of `u^a v^b` at degree `n`: `T_ij = C(i,a) C(j,b) / (C(n,a) C(n-a,b))`.
fn monomial(a: usize, b: usize, n: usize) -> TriPatch {
    let mut p = Vec::new();
    for i in 0..=n {
        for j in 0..=n - i {
            p.push(
                binomial_f64(i, a) * binomial_f64(j, b)
                    / (binomial_f64(n, a) * binomial_f64(n - a, b)),
            );
        }
    }
    TriPatch::new(p, n, 1).unwrap()
}

#[test]
fn degeneracy_vector_deg_tri_2() {
    let v = vector("vectors-reduce.json", "deg-tri-2");
    let t: Vec<f64> = v["input"]["T_exact"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|p| p.as_array().unwrap().iter().map(num).collect::<Vec<_>>())
        .collect();
    let t = TriPatch::new(t, 3, 2).unwrap();
    let f = t.degeneracy_invariants();
    assert_close("F_k", &f, &cagd_testkit::flat(&v["expected"]["F_k"]), 1e-15);
}

#[test]
fn invariants_are_the_top_power_coefficients() {
    // u^k v^(n-k) has F_k = 1 / C(n, k) and the other F zero; a lower-degree monomial has
    // all F zero.
    let n = 5;
    for k in 0..=n {
        let f = monomial(k, n - k, n).degeneracy_invariants();
        for (l, x) in f.iter().enumerate() {
            let e = if l == k {
                1.0 / binomial_f64(n, k)
            } else {
                0.0
            };
            assert!((x - e).abs() < 1e-14, "k={k} l={l}: {x}");
        }
    }
    assert!(
        monomial(2, 1, n)
            .degeneracy_invariants()
            .iter()
            .all(|x| x.abs() < 1e-14)
    );
}

#[test]
fn eval_and_derivatives_of_a_monomial() {
    // u^2 v at degree 4.
    let t = monomial(2, 1, 4);
    for (u, v) in [(0.0, 0.0), (0.2, 0.3), (1.0, 0.0), (0.0, 1.0), (0.5, 0.25)] {
        assert!((t.eval(u, v).unwrap()[0] - u * u * v).abs() < 1e-15);
        let du = t.directional_derivative_at(u, v, 1.0, 0.0, 1).unwrap()[0];
        assert!((du - 2.0 * u * v).abs() < 1e-14);
        let dv = t.directional_derivative_at(u, v, 0.0, 1.0, 1).unwrap()[0];
        assert!((dv - u * u).abs() < 1e-14);
        // Along (1, -1): d/ds (u+s)^2 (v-s) = 2u v - u^2; second order 2v - 4u; third -6.
        let d1 = t.directional_derivative_at(u, v, 1.0, -1.0, 1).unwrap()[0];
        assert!((d1 - (2.0 * u * v - u * u)).abs() < 1e-14);
        let d2 = t.directional_derivative_at(u, v, 1.0, -1.0, 2).unwrap()[0];
        assert!((d2 - (2.0 * v - 4.0 * u)).abs() < 1e-13);
        let d3 = t.directional_derivative_at(u, v, 1.0, -1.0, 3).unwrap()[0];
        assert!((d3 + 6.0).abs() < 1e-12);
    }
    let z = t.directional_derivative(1.0, 0.0, 5).unwrap();
    assert_eq!((z.degree(), z.points()), (0, &[0.0][..]));
    assert_eq!(t.directional_derivative(0.3, 0.1, 2).unwrap().degree(), 2);
}

#[test]
fn bad_input() {
    let t = monomial(1, 1, 3);
    for (u, v) in [
        (f64::NAN, 0.1),
        (0.1, f64::INFINITY),
        (-0.1, 0.2),
        (0.6, 0.6),
        (0.2, -1e-3),
    ] {
        assert!(
            matches!(t.subdivide_at(u, v), Err(Error::BadParameter { .. })),
            "{u} {v}"
        );
    }
    assert!(matches!(
        t.eval(0.1, f64::NAN),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(
        t.directional_derivative(f64::NAN, 0.0, 1),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(t.elevate(62), Err(Error::DegreeOutOfRange { .. })));
    assert!(matches!(
        t.reparametrize((0.0, f64::NAN), (0.0, 1.0), (0.0, 0.0)),
        Err(Error::BadParameter { .. })
    ));
    assert_eq!(t.elevate(61).unwrap().degree(), 64);
}

fn tri() -> impl Strategy<Value = TriPatch> {
    (0usize..=7, 1usize..=3).prop_flat_map(|(n, dim)| {
        cagd_testkit::points(tri_count(n), dim).prop_map(move |p| TriPatch::new(p, n, dim).unwrap())
    })
}

/// 210 points of the unit triangle (a 20-row grid, shifted off the edges).
fn params() -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for a in 0..20 {
        for b in 0..20 - a {
            out.push(((a as f64 + 0.3) / 21.0, (b as f64 + 0.4) / 21.0));
        }
    }
    out
}

fn close(a: &[f64], b: &[f64], scale: f64) -> bool {
    a.iter()
        .zip(b)
        .all(|(x, y)| (x - y).abs() <= LAW_TOL * scale)
}

proptest! {
    #[test]
    fn elevation_preserves_the_patch(t in tri(), r in 0usize..=4) {
        let e = t.elevate(r).unwrap();
        prop_assert_eq!(e.degree(), t.degree() + r);
        let sc = size(t.points());
        let pts = params();
        prop_assert!(pts.len() >= 200);
        for (u, v) in pts {
            prop_assert!(close(&e.eval(u, v).unwrap(), &t.eval(u, v).unwrap(), sc));
        }
        // Elevation by r equals r elevations by 1.
        let mut s = t.clone();
        for _ in 0..r {
            s = s.elevate(1).unwrap();
        }
        prop_assert!(close(s.points(), e.points(), sc));
    }

    /// Invariants of an elevated net vanish; they sum up to `2^n` rounded terms, so the
    /// tolerance is `LAW_TOL * 2^(n+1) * size`.
    #[test]
    fn invariants_vanish_on_elevated_nets(t in tri()) {
        let f = t.elevate(1).unwrap().degeneracy_invariants();
        let tol = LAW_TOL * (1u64 << (t.degree() + 1)) as f64 * size(t.points());
        prop_assert!(f.iter().all(|x| x.abs() <= tol));
    }

    #[test]
    fn three_pieces_evaluate_to_the_whole(t in tri(), a in 0.05f64..0.9, b in 0.05f64..0.9) {
        prop_assume!(a + b < 0.95);
        let [p0, p1, p2] = t.subdivide_at(a, b).unwrap();
        let sc = size(t.points());
        for (x, y) in params() {
            let w = 1.0 - x - y;
            prop_assert!(close(&p0.eval(x, y).unwrap(), &t.eval(x * a, x * b + y).unwrap(), sc));
            prop_assert!(close(&p1.eval(x, y).unwrap(), &t.eval(x + y * a, y * b).unwrap(), sc));
            prop_assert!(close(&p2.eval(x, y).unwrap(), &t.eval(x + w * a, y + w * b).unwrap(), sc));
        }
    }

    #[test]
    fn midpoint_pieces_evaluate_to_the_whole(t in tri()) {
        let pieces = t.subdivide_midpoint();
        let sc = size(t.points());
        type Map = fn(f64, f64) -> (f64, f64);
        let maps: [Map; 4] = [
            |x, y| (x / 2.0, y / 2.0),
            |x, y| (0.5 + x / 2.0, y / 2.0),
            |x, y| (x / 2.0, 0.5 + y / 2.0),
            |x, y| (0.5 - x / 2.0, 0.5 - y / 2.0),
        ];
        for (p, map) in pieces.iter().zip(maps) {
            for (x, y) in params() {
                let (u, v) = map(x, y);
                prop_assert!(close(&p.eval(x, y).unwrap(), &t.eval(u, v).unwrap(), sc));
            }
        }
    }

    /// Theorem 14.3.1 (SPEC-reduce §5 erratum): F_k(T^(l)) = 2^-n F_k(T) for the corner
    /// pieces and (-1/2)^n F_k(T) for the middle one, hence ||F_k(T^(l))|| = 2^-n ||F_k(T)||.
    /// Tolerance: F sums 2^n terms of size `size`.
    #[test]
    fn theorem_14_3_1_scaling(t in tri()) {
        let n = t.degree();
        let f = t.degeneracy_invariants();
        let half_n = 0.5f64.powi(i32::from(u8::try_from(n).unwrap_or(0)));
        let tol = LAW_TOL * (1u64 << n) as f64 * size(t.points());
        let pieces = t.subdivide_midpoint();
        for (l, p) in pieces.iter().enumerate() {
            let sign = if l == 3 && n % 2 == 1 { -1.0 } else { 1.0 };
            let fl = p.degeneracy_invariants();
            for (x, y) in fl.iter().zip(&f) {
                prop_assert!((x - sign * half_n * y).abs() <= tol, "piece {l}: {x} vs {}", sign * half_n * y);
            }
        }
    }

    /// An arbitrary triangle: the reparametrised patch is T composed with the affine map.
    #[test]
    fn reparametrize_is_composition(
        t in tri(),
        q in proptest::collection::vec(-0.5f64..1.5, 6),
    ) {
        let (a, b, c) = ((q[0], q[1]), (q[2], q[3]), (q[4], q[5]));
        let r = t.reparametrize(a, b, c).unwrap();
        // Outside the domain the combinations are not convex: allow growth 3^n.
        let sc = size(t.points()) * 3f64.powi(i32::from(u8::try_from(t.degree()).unwrap_or(0)));
        for (x, y) in params().into_iter().step_by(7) {
            let u = c.0 + x * (a.0 - c.0) + y * (b.0 - c.0);
            let v = c.1 + x * (a.1 - c.1) + y * (b.1 - c.1);
            prop_assert!(close(&r.eval(x, y).unwrap(), &t.eval(u, v).unwrap(), sc));
        }
    }

    /// Directional derivative against a central difference.
    #[test]
    fn derivative_matches_difference(t in tri(), du in -1.0f64..1.0, dv in -1.0f64..1.0) {
        let (u, v, h) = (0.3, 0.25, 1e-5);
        let d = t.directional_derivative_at(u, v, du, dv, 1).unwrap();
        let a = t.eval(u + h * du, v + h * dv).unwrap();
        let b = t.eval(u - h * du, v - h * dv).unwrap();
        let n = t.degree();
        let tol = 1e-9 * size(t.points()) * (1 + n * n * n) as f64;
        for k in 0..t.dim() {
            prop_assert!((d[k] - (a[k] - b[k]) / (2.0 * h)).abs() <= tol);
        }
    }
}

#[test]
fn layout_helpers_agree() {
    // The pieces of subdivide_at share the point p: T'_{n,0} of piece 0, T'_{0,n} of piece 1,
    // T'_{0,0} of piece 2 all equal T(p).
    let t = monomial(1, 2, 4);
    let [p0, p1, p2] = t.subdivide_at(0.2, 0.3).unwrap();
    let tp = t.eval(0.2, 0.3).unwrap()[0];
    assert!((p0.point(4, 0)[0] - tp).abs() < 1e-16);
    assert!((p1.point(0, 4)[0] - tp).abs() < 1e-16);
    assert!((p2.point(0, 0)[0] - tp).abs() < 1e-16);
    assert_eq!(tri_index(4, 4, 0), tri_count(4) - 1);
}

#[test]
fn index_is_i_major() {
    for n in 0..8 {
        let mut k = 0;
        for i in 0..=n {
            for j in 0..=n - i {
                assert_eq!(tri_index(n, i, j), k);
                k += 1;
            }
        }
        assert_eq!(k, tri_count(n));
    }
}

/// Elevation never hands out an infinite point: coordinates at `f64::MAX` whose convex
/// combinations round past it are refused with `NonFinite` (issue 18: the C ABI fuzz
/// harness found a `cagd_tripatch_elevate` handle whose `cagd_tripatch_points` failed).
#[test]
fn elevation_near_f64_max_is_finite_or_refused() {
    let mut refused = 0;
    for n in 1..=12usize {
        for r in 1..=12usize {
            let pts = vec![f64::MAX; (n + 1) * (n + 2) / 2];
            let t = TriPatch::new(pts, n, 1).expect("finite points");
            match t.elevate(r) {
                Ok(e) => assert!(e.points().iter().all(|x| x.is_finite()), "n {n} r {r}"),
                Err(Error::NonFinite { .. }) => refused += 1,
                Err(e) => panic!("n {n} r {r}: unexpected {e}"),
            }
        }
    }
    assert!(
        refused > 0,
        "no case rounded past f64::MAX; the test no longer probes it"
    );
}

/// High degree (the proptest laws stop at 7): the midpoint pieces of a degree-40 net (its
/// corners from corner replacements, its middle from blossoms with Bernstein sums) are the
/// patch on their sub-triangles to a few hundred ulp of the net's size, as a de Casteljau
/// evaluation is.
#[test]
fn midpoint_pieces_at_degree_40() {
    let n = 40;
    let mut s = 99u64;
    let pts: Vec<f64> = (0..tri_count(n) * 3)
        .map(|_| {
            s = s
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        })
        .collect();
    let t = TriPatch::new(pts, n, 3).unwrap();
    let sc = size(t.points());
    // Each piece's (u, v) = origin + sign (x, y) / 2.
    let maps = [
        (0.0, 0.0, 0.5),
        (0.5, 0.0, 0.5),
        (0.0, 0.5, 0.5),
        (0.5, 0.5, -0.5),
    ];
    for (p, (u0, v0, h)) in t.subdivide_midpoint().iter().zip(maps) {
        for (x, y) in params().into_iter().step_by(3) {
            let (u, v) = (u0 + h * x, v0 + h * y);
            let (a, b) = (p.eval(x, y).unwrap(), t.eval(u, v).unwrap());
            for (a, b) in a.iter().zip(&b) {
                assert!((a - b).abs() <= 1e-13 * sc, "{a} vs {b}");
            }
        }
    }
}
