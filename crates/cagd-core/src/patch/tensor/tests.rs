use super::*;
use crate::binomial::{binomial_f64, sign_binomial_f64};
use cagd_testkit::{assert_close, flat, vector};
use proptest::prelude::*;

fn size(p: &[f64]) -> f64 {
    p.iter().fold(1.0f64, |m, x| m.max(x.abs()))
}

/// Relative tolerance of the laws: evaluation / subdivision / elevation are convex
/// combinations with an error of a few `(m + n)` ulp of the net's size; 1e-12 leaves a
/// margin of ~100 over that for degrees <= 8.
const LAW_TOL: f64 = 1e-12;

/// The patch of `u^a v^b` (1-D) at degree `(m, n)`: coefficients `C(i,a)/C(m,a) C(j,b)/C(n,b)`.
fn monomial(a: usize, b: usize, m: usize, n: usize) -> TensorPatch {
    let mut p = Vec::new();
    for i in 0..=m {
        for j in 0..=n {
            p.push(
                binomial_f64(i, a) / binomial_f64(m, a) * binomial_f64(j, b) / binomial_f64(n, b),
            );
        }
    }
    TensorPatch::new(p, m, n, 1).unwrap()
}

#[test]
fn degeneracy_vector_deg_tensor_1() {
    let v = vector("vectors-reduce.json", "deg-tensor-1");
    let p = TensorPatch::new(flat(&v["input"]["P_ij"]), 2, 2, 3).unwrap();
    let (f, g) = p.degeneracy_invariants();
    assert_close("F_j", &f, &flat(&v["expected"]["F_j"]), 0.0);
    assert_close("G_i", &g, &flat(&v["expected"]["G_i"]), 0.0);
}

#[test]
fn eval_and_partials_of_a_monomial() {
    // f = u^2 v^3 at degree (4, 5).
    let p = monomial(2, 3, 4, 5);
    for (u, v) in [(0.0, 0.0), (0.3, 0.7), (1.0, 0.25), (0.5, 1.0)] {
        let f = p.eval(u, v).unwrap()[0];
        assert!((f - u * u * v * v * v).abs() < 1e-15);
        let fu = p.partial_at(u, v, 1, 0).unwrap()[0];
        assert!((fu - 2.0 * u * v * v * v).abs() < 1e-14);
        let fuv = p.partial_at(u, v, 1, 1).unwrap()[0];
        assert!((fuv - 6.0 * u * v * v).abs() < 1e-13);
        let fvvv = p.partial_at(u, v, 0, 3).unwrap()[0];
        assert!((fvvv - 6.0 * u * u).abs() < 1e-12);
        let fuuvvv = p.partial_at(u, v, 2, 3).unwrap()[0];
        assert!((fuuvvv - 12.0).abs() < 1e-11);
        assert!(p.partial_at(u, v, 3, 0).unwrap()[0].abs() < 1e-12);
    }
    assert_eq!(p.partial(1, 2).degrees(), (3, 3));
    // Order above the degree: degree 0, zero.
    let z = p.partial(5, 0);
    assert_eq!(z.degrees(), (0, 5));
    assert!(z.points().iter().all(|x| *x == 0.0));
}

#[test]
fn bad_input() {
    let p = monomial(1, 1, 2, 2);
    for s in [f64::NAN, -0.1, 1.5, f64::INFINITY] {
        assert!(matches!(p.subdivide_u(s), Err(Error::BadParameter { .. })));
        assert!(matches!(p.subdivide_v(s), Err(Error::BadParameter { .. })));
    }
    assert!(matches!(
        p.eval(f64::NAN, 0.0),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(
        p.elevate_u(63),
        Err(Error::DegreeOutOfRange { .. })
    ));
    assert!(matches!(
        p.elevate_v(usize::MAX),
        Err(Error::DegreeOutOfRange { .. })
    ));
    assert!(p.elevate_v(62).is_ok());
}

fn patch() -> impl Strategy<Value = TensorPatch> {
    (0usize..=5, 0usize..=5, 1usize..=3).prop_flat_map(|(m, n, dim)| {
        cagd_testkit::points((m + 1) * (n + 1), dim)
            .prop_map(move |p| TensorPatch::new(p, m, n, dim).unwrap())
    })
}

/// 210 parameters of the unit square (a 15 x 14 grid with irrational-ish offsets).
fn params() -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for a in 0..15 {
        for b in 0..14 {
            out.push(((a as f64 + 0.137) / 15.0, (b as f64 + 0.291) / 14.0));
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
    fn subdivision_pieces_evaluate_to_the_whole(p in patch(), s in 0.05f64..0.95) {
        let sc = size(p.points());
        let (l, r) = p.subdivide_u(s).unwrap();
        let (b, t) = p.subdivide_v(s).unwrap();
        for (x, y) in params() {
            prop_assert!(close(&l.eval(x, y).unwrap(), &p.eval(s * x, y).unwrap(), sc));
            prop_assert!(close(&r.eval(x, y).unwrap(), &p.eval(s + (1.0 - s) * x, y).unwrap(), sc));
            prop_assert!(close(&b.eval(x, y).unwrap(), &p.eval(x, s * y).unwrap(), sc));
            prop_assert!(close(&t.eval(x, y).unwrap(), &p.eval(x, s + (1.0 - s) * y).unwrap(), sc));
        }
    }

    #[test]
    fn elevation_preserves_the_patch(p in patch(), ru in 0usize..=3, rv in 0usize..=3) {
        let sc = size(p.points());
        let e = p.elevate_u(ru).unwrap().elevate_v(rv).unwrap();
        let (m, n) = p.degrees();
        prop_assert_eq!(e.degrees(), (m + ru, n + rv));
        for (x, y) in params() {
            prop_assert!(close(&e.eval(x, y).unwrap(), &p.eval(x, y).unwrap(), sc));
        }
    }

    /// Elevated nets are degenerate. The invariants sum `2^m` (resp. `2^n`) rounded terms,
    /// so the tolerance is `LAW_TOL * 2^deg * size`.
    #[test]
    fn invariants_vanish_on_elevated_nets(p in patch()) {
        let sc = size(p.points());
        let (f, _) = p.elevate_u(1).unwrap().degeneracy_invariants();
        let (m, n) = p.degrees();
        prop_assert!(f.iter().all(|x| x.abs() <= LAW_TOL * (1u64 << (m + 1)) as f64 * sc));
        let (_, g) = p.elevate_v(1).unwrap().degeneracy_invariants();
        prop_assert!(g.iter().all(|x| x.abs() <= LAW_TOL * (1u64 << (n + 1)) as f64 * sc));
    }

    /// The dependency of SPEC-reduce §1: sum_j c_j^(n) F_j = sum_i c_i^(m) G_i.
    #[test]
    fn invariants_are_dependent(p in patch()) {
        let (m, n) = p.degrees();
        let dim = p.dim();
        let (f, g) = p.degeneracy_invariants();
        let sc = size(p.points()) * (1u64 << (m + n)) as f64;
        for k in 0..dim {
            let a: f64 = (0..=n).map(|j| sign_binomial_f64(n, j) * f[j * dim + k]).sum();
            let b: f64 = (0..=m).map(|i| sign_binomial_f64(m, i) * g[i * dim + k]).sum();
            prop_assert!((a - b).abs() <= LAW_TOL * sc);
        }
    }

    /// Partial derivatives against central differences of the patch.
    #[test]
    fn partials_match_differences(p in patch(), x in 0.1f64..0.9, y in 0.1f64..0.9) {
        let h = 1e-5;
        let sc = size(p.points());
        let (m, n) = p.degrees();
        let fu = p.partial_at(x, y, 1, 0).unwrap();
        let fv = p.partial_at(x, y, 0, 1).unwrap();
        let (a, b) = (p.eval(x + h, y).unwrap(), p.eval(x - h, y).unwrap());
        let (c, d) = (p.eval(x, y + h).unwrap(), p.eval(x, y - h).unwrap());
        // Central difference error ~ h^2 |f'''| / 6 <= h^2 m^3 size; rounding ~ eps size / h.
        let tol_u = 1e-9 * sc * (1 + m * m * m) as f64;
        let tol_v = 1e-9 * sc * (1 + n * n * n) as f64;
        for k in 0..p.dim() {
            prop_assert!((fu[k] - (a[k] - b[k]) / (2.0 * h)).abs() <= tol_u);
            prop_assert!((fv[k] - (c[k] - d[k]) / (2.0 * h)).abs() <= tol_v);
        }
    }
}

/// Elevation sums of coordinates at `f64::MAX` can round past it (the C ABI fuzz run found
/// a `cagd_tensorpatch_reduce` NaN on a patch made by `cagd_tensorpatch_elevate`): the
/// result is finite or refused as non-finite, in both directions.
#[test]
fn elevation_near_f64_max_is_finite_or_refused() {
    let mut refused = 0;
    for m in 1..=8usize {
        for r in 1..=8usize {
            let p = TensorPatch::new(vec![f64::MAX; (m + 1) * 2], m, 1, 1).expect("finite");
            let q = TensorPatch::new(vec![f64::MAX; (m + 1) * 2], 1, m, 1).expect("finite");
            for e in [p.elevate_u(r), q.elevate_v(r)] {
                match e {
                    Ok(e) => assert!(e.points().iter().all(|x| x.is_finite()), "m {m} r {r}"),
                    Err(Error::NonFinite { .. }) => refused += 1,
                    Err(e) => panic!("m {m} r {r}: unexpected {e}"),
                }
            }
        }
    }
    assert!(
        refused > 0,
        "no case rounded past f64::MAX; the test no longer probes it"
    );
}
