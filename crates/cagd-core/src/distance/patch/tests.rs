use super::*;
use proptest::prelude::*;

/// `u^2 (1-u) * v (1-v)` (1-D): maximum `4/27 * 1/4 = 1/27` at `(2/3, 1/2)`; `2/3` is not a
/// grid node (grid intervals `4 * 5 + 32 = 52`).
#[test]
fn tensor_maximum_between_nodes() {
    // u^2 (1-u) = B_2^3 / 3, v (1-v) = B_1^2 / 2: only P_21 = 1/6 is non-zero.
    let mut p = vec![0.0; 4 * 3];
    p[2 * 3 + 1] = 1.0 / 6.0;
    let a = TensorPatch::new(p, 3, 2, 1).unwrap();
    let z = TensorPatch::new(vec![0.0], 0, 0, 1).unwrap();
    let d = tensor_patch_distance(&a, &z).unwrap();
    assert!((d - 1.0 / 27.0).abs() <= 1e-13 / 27.0, "{d}");
}

/// `6 c u v w` has maximum `6c/27` at the centroid, not a grid node.
#[test]
fn tri_maximum_at_the_centroid() {
    let mut p = vec![0.0; crate::tri_count(3) * 2];
    let i = crate::tri_index(3, 1, 1);
    p[i * 2] = 0.9; // x: 6 * 0.9 u v w
    p[i * 2 + 1] = 1.2; // y: 6 * 1.2 u v w
    let a = TriPatch::new(p, 3, 2).unwrap();
    let z = TriPatch::new(vec![0.0, 0.0], 0, 2).unwrap();
    let expected = 6.0 * 1.5 / 27.0;
    let d = tri_patch_distance(&a, &z).unwrap();
    assert!((d - expected).abs() <= 1e-13 * expected, "{d}");
    assert!((tri_patch_distance(&z, &a).unwrap() - expected).abs() <= 1e-13 * expected);
}

/// A maximum on the hypotenuse u + v = 1 between nodes: `u^2 v` there is `u^2 (1-u)`,
/// largest `4/27` at `u = 2/3`; inside it is smaller.
#[test]
fn tri_maximum_on_the_hypotenuse() {
    // u^2 v at degree 3: T_21 = 1/3.
    let mut p = vec![0.0; crate::tri_count(3)];
    p[crate::tri_index(3, 2, 1)] = 1.0 / 3.0;
    let a = TriPatch::new(p, 3, 1).unwrap();
    let z = TriPatch::new(vec![0.0], 0, 1).unwrap();
    let d = tri_patch_distance(&a, &z).unwrap();
    assert!((d - 4.0 / 27.0).abs() <= 1e-13, "{d}");
}

#[test]
fn errors() {
    let a = TensorPatch::new(vec![0.0; 4], 1, 1, 1).unwrap();
    let b = TensorPatch::new(vec![0.0; 8], 1, 1, 2).unwrap();
    assert!(matches!(
        tensor_patch_distance(&a, &b),
        Err(Error::LengthMismatch { .. })
    ));
    let s = TriPatch::new(vec![0.0; 3], 1, 1).unwrap();
    let t = TriPatch::new(vec![0.0; 6], 1, 2).unwrap();
    assert!(matches!(
        tri_patch_distance(&s, &t),
        Err(Error::LengthMismatch { .. })
    ));
    let z = |_: f64, _: f64, o: &mut [f64]| o[0] = 0.0;
    let nan = |_: f64, _: f64, o: &mut [f64]| o[0] = f64::NAN;
    assert!(matches!(
        max_distance_2d(z, nan, 1, Domain2::UnitSquare, 8),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        max_distance_2d(z, z, 0, Domain2::UnitSquare, 8),
        Err(Error::ZeroDimension)
    ));
}

fn tensor(m: usize, n: usize) -> impl Strategy<Value = TensorPatch> {
    cagd_testkit::points((m + 1) * (n + 1), 3)
        .prop_map(move |p| TensorPatch::new(p, m, n, 3).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// A shifted copy is at the distance of the shift (rounding floor: a few ulp of 10).
    #[test]
    fn shifted_copies(p in tensor(3, 2), s in cagd_testkit::points(1, 3)) {
        let q: Vec<f64> = p.points().iter().enumerate().map(|(i, x)| x + s[i % 3]).collect();
        let (m, n) = p.degrees();
        let q = TensorPatch::new(q, m, n, 3).unwrap();
        let expected = (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt();
        let d = tensor_patch_distance(&p, &q).unwrap();
        prop_assert!((d - expected).abs() <= 1e-14 * 20.0);
        // And an elevated copy is at distance zero (up to the elevation's rounding).
        let e = p.elevate_u(2).unwrap().elevate_v(1).unwrap();
        prop_assert!(tensor_patch_distance(&p, &e).unwrap() <= 1e-13);
    }

    /// Not below a fine grid, and not above it by more than its O(h^2) miss.
    #[test]
    fn tensor_not_below_a_fine_grid(p in tensor(3, 2), q in tensor(2, 2)) {
        let d = tensor_patch_distance(&p, &q).unwrap();
        let mut grid = 0.0f64;
        for i in 0..=300 {
            for j in 0..=300 {
                let (u, v) = (i as f64 / 300.0, j as f64 / 300.0);
                let (a, b) = (p.eval(u, v).unwrap(), q.eval(u, v).unwrap());
                let s: f64 = a.iter().zip(&b).map(|(x, y)| (x - y) * (x - y)).sum();
                grid = grid.max(s.sqrt());
            }
        }
        prop_assert!(d >= grid * (1.0 - 1e-13));
        prop_assert!(d <= grid * (1.0 + 1e-3) + 1e-13);
    }

    #[test]
    fn tri_not_below_a_fine_grid(
        p in cagd_testkit::points(crate::tri_count(4), 2),
        q in cagd_testkit::points(crate::tri_count(2), 2),
    ) {
        let p = TriPatch::new(p, 4, 2).unwrap();
        let q = TriPatch::new(q, 2, 2).unwrap();
        let d = tri_patch_distance(&p, &q).unwrap();
        let mut grid = 0.0f64;
        for i in 0..=300 {
            for j in 0..=300 - i {
                let (u, v) = (i as f64 / 300.0, j as f64 / 300.0);
                let (a, b) = (p.eval(u, v).unwrap(), q.eval(u, v).unwrap());
                let s: f64 = a.iter().zip(&b).map(|(x, y)| (x - y) * (x - y)).sum();
                grid = grid.max(s.sqrt());
            }
        }
        prop_assert!(d >= grid * (1.0 - 1e-13));
        prop_assert!(d <= grid * (1.0 + 1e-3) + 1e-13);
    }
}

/// A deterministic value in `[-1, 1]` (xorshift).
fn noise(state: &mut u64) -> f64 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    (*state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
}

/// The cached-basis evaluators (`grid`) agree with de Casteljau at grid nodes and at
/// arbitrary points, degrees 0..=64 (an independent route: the pyramid).
#[test]
fn cached_bases_agree_with_de_casteljau() {
    let mut s = 99u64;
    for (m, n) in [(0, 0), (1, 3), (7, 2), (20, 20), (64, 64), (64, 1)] {
        let pts: Vec<f64> = (0..(m + 1) * (n + 1) * 2).map(|_| noise(&mut s)).collect();
        let p = TensorPatch::new(pts, m, n, 2).unwrap();
        let fast = TensorEval::new(&p);
        let samples = 13;
        let g = fast.grid(samples);
        let (mut a, mut b) = ([0.0; 2], [0.0; 2]);
        for i in 0..=samples {
            for j in 0..=samples {
                let (u, v) = (node(i, samples), node(j, samples));
                p.eval_into(u, v, &mut a);
                fast.eval(u, v, &mut b);
                let at = (i * (samples + 1) + j) * 2;
                for k in 0..2 {
                    assert!((a[k] - g[at + k]).abs() <= 1e-13, "tensor grid {m} {n}");
                    assert!((a[k] - b[k]).abs() <= 1e-13, "tensor eval {m} {n}");
                }
            }
        }
        let pts: Vec<f64> = (0..crate::tri_count(m) * 3)
            .map(|_| noise(&mut s))
            .collect();
        let t = TriPatch::new(pts, m, 3).unwrap();
        let fast = TriEval::new(&t);
        let g = fast.grid(samples);
        let (mut a, mut b) = ([0.0; 3], [0.0; 3]);
        for i in 0..=samples {
            for j in 0..=samples - i {
                let u = node(i, samples);
                let v = if i + j == samples {
                    1.0 - u
                } else {
                    node(j, samples)
                };
                t.eval_into(u, v, &mut a);
                fast.eval(u, v, &mut b);
                let at = (i * (samples + 1) + j) * 3;
                for k in 0..3 {
                    assert!((a[k] - g[at + k]).abs() <= 1e-13, "tri grid {m}");
                    assert!((a[k] - b[k]).abs() <= 1e-13, "tri eval {m}");
                }
            }
        }
        // Off the grid, near the corner u = 1.
        for (u, v) in [(0.3, 0.2), (1.0 - 1e-9, 5e-10), (1.0, 0.0), (0.0, 1.0)] {
            t.eval_into(u, v, &mut a);
            fast.eval(u, v, &mut b);
            for k in 0..3 {
                assert!((a[k] - b[k]).abs() <= 1e-12, "tri eval {m} at ({u}, {v})");
            }
        }
    }
}

/// two random degree-24 patches (a distance with hundreds of sampled local maxima, like
/// the fuzz harness's minutes-long degree-64 calls): the bounded refinement still finds
/// the maximum of an independent dense sampling (a 241-node grid per side, de Casteljau)
/// and is not above it by more than the local gain between those nodes.
#[test]
fn degree_24_distances_match_an_independent_dense_sampling() {
    let mut s = 7u64;
    let n = 24;
    let a = TriPatch::new(
        (0..crate::tri_count(n)).map(|_| noise(&mut s)).collect(),
        n,
        1,
    )
    .unwrap();
    let b = TriPatch::new(
        (0..crate::tri_count(n)).map(|_| noise(&mut s)).collect(),
        n,
        1,
    )
    .unwrap();
    let d = tri_patch_distance(&a, &b).unwrap();
    let (mut x, mut y) = ([0.0], [0.0]);
    let k = 241;
    let mut dense = 0.0f64;
    for i in 0..=k {
        for j in 0..=k - i {
            let (u, v) = (i as f64 / k as f64, j as f64 / k as f64);
            a.eval_into(u, v, &mut x);
            b.eval_into(u, v, &mut y);
            dense = dense.max((x[0] - y[0]).abs());
        }
    }
    assert!(
        d >= dense * (1.0 - 1e-12),
        "{d} below the dense sampling {dense}"
    );
    assert!(
        d <= dense * (1.0 + 1e-3),
        "{d} far above the dense sampling {dense}"
    );
}
