//! Tests of the interval reduction: Example 1 of seed 004 exactly (SPEC-convert I.4–I.5),
//! the public spec vectors, the analytic route, the dual LP route, laws and bad input.

use cagd_core::tri_count;
use proptest::prelude::*;

use super::elevation::{IntElevation, tri_indices};
use super::lp::{Lp, Sense, solve_min};
use super::*;
use crate::Error;

/// Example 1 input (SPEC-convert I.4): box `([x, x+2], [y, y+2], [z, z+2])` per `ijk`.
fn example1() -> IntervalTriPatch {
    let table: [((usize, usize, usize), [f64; 3]); 15] = [
        ((4, 0, 0), [55.0, 55.0, 70.0]),
        ((3, 1, 0), [60.0, 50.0, 70.0]),
        ((2, 2, 0), [80.0, 50.0, 70.0]),
        ((1, 3, 0), [100.0, 50.0, 70.0]),
        ((0, 4, 0), [105.0, 55.0, 70.0]),
        ((3, 0, 1), [50.0, 60.0, 70.0]),
        ((2, 1, 1), [70.0, 60.0, 50.0]),
        ((1, 2, 1), [90.0, 60.0, 50.0]),
        ((0, 3, 1), [110.0, 60.0, 70.0]),
        ((2, 0, 2), [60.0, 70.0, 70.0]),
        ((1, 1, 2), [80.0, 70.0, 40.0]),
        ((0, 2, 2), [100.0, 70.0, 70.0]),
        ((1, 0, 3), [70.0, 80.0, 70.0]),
        ((0, 1, 3), [90.0, 80.0, 70.0]),
        ((0, 0, 4), [80.0, 80.0, 70.0]),
    ];
    let mut lo = vec![0.0; 45];
    for ((i, j, _), xyz) in table {
        let q = cagd_core::tri_index(4, i, j);
        lo[3 * q..3 * q + 3].copy_from_slice(&xyz);
    }
    let hi = lo.iter().map(|x| x + 2.0).collect();
    IntervalTriPatch::new(lo, hi, 4, 3).unwrap()
}

/// One box of a result: `(i, j)` and `[lo, hi]` per coordinate.
type ResultBox = ((usize, usize), [[f64; 2]; 3]);

/// Example 1 result (SPEC-convert I.5), `(i, j)` and `[lo, hi]` per coordinate.
fn example1_result() -> Vec<ResultBox> {
    let t = |a: f64, b: f64| [a, b];
    vec![
        ((3, 0), [t(55.0, 57.0), t(55.0, 57.0), t(70.0, 72.0)]),
        (
            (2, 1),
            [
                t(185.0 / 3.0, 191.0 / 3.0),
                t(145.0 / 3.0, 52.0),
                t(70.0, 72.0),
            ],
        ),
        (
            (1, 2),
            [
                t(295.0 / 3.0, 301.0 / 3.0),
                t(145.0 / 3.0, 52.0),
                t(70.0, 72.0),
            ],
        ),
        ((0, 3), [t(105.0, 107.0), t(55.0, 57.0), t(70.0, 72.0)]),
        (
            (2, 0),
            [
                t(145.0 / 3.0, 166.0 / 3.0),
                t(185.0 / 3.0, 191.0 / 3.0),
                t(70.0, 72.0),
            ],
        ),
        (
            (1, 1),
            [
                t(155.0 / 2.0, 169.0 / 2.0),
                t(185.0 / 3.0, 397.0 / 6.0),
                t(10.0, 32.0),
            ],
        ),
        (
            (0, 2),
            [
                t(320.0 / 3.0, 341.0 / 3.0),
                t(185.0 / 3.0, 191.0 / 3.0),
                t(70.0, 72.0),
            ],
        ),
        (
            (1, 0),
            [
                t(200.0 / 3.0, 206.0 / 3.0),
                t(235.0 / 3.0, 82.0),
                t(70.0, 72.0),
            ],
        ),
        (
            (0, 1),
            [
                t(280.0 / 3.0, 286.0 / 3.0),
                t(235.0 / 3.0, 82.0),
                t(70.0, 72.0),
            ],
        ),
        ((0, 0), [t(80.0, 82.0), t(80.0, 82.0), t(70.0, 72.0)]),
    ]
}

#[test]
fn example_1_is_reproduced_exactly() {
    let p = example1();
    assert_eq!(p.thickness(), 2.0);
    let r = reduce_interval_triangle(&p, &IntervalOptions::new(3)).unwrap();
    let rep = &r.report;
    assert!(
        (rep.thickness_out - 125.0 / 36.0).abs() < 1e-12,
        "{}",
        rep.thickness_out
    );
    assert!((rep.ratio.unwrap() - 125.0 / 72.0).abs() < 1e-12);
    assert_eq!(
        rep.coupled,
        vec![false; 3],
        "the optimum is unique and proper"
    );
    // The returned boxes are the exact ones of I.5 up to the rounding of the thirds and
    // the outward repair (a few ulps).
    for ((i, j), boxes) in example1_result() {
        let q = cagd_core::tri_index(3, i, j);
        for (c, [l, h]) in boxes.into_iter().enumerate() {
            let (gl, gh) = (r.patch.lo()[3 * q + c], r.patch.hi()[3 * q + c]);
            assert!(
                (gl - l).abs() < 1e-11 && (gh - h).abs() < 1e-11,
                "{i}{j} c{c}: [{gl}, {gh}] vs [{l}, {h}]"
            );
            assert!(gl <= gh);
        }
    }
    assert!(rep.repair < 1e-11, "repair {}", rep.repair);
    assert!(rep.max_violation.unwrap() <= 0.0);
    assert_eq!(rep.samples, 1035);
    assert!(r.patch.contains(&p, None).unwrap());
    assert_eq!(rep.lp_size, (15, 10));
}

#[test]
fn example_1_by_the_analytic_method() {
    let p = example1();
    let a = reduce_interval_triangle_analytic(&p, 3, None).unwrap();
    assert_eq!(a.bases, 3003);
    assert!(a.proper);
    assert!((a.thickness - 125.0 / 36.0).abs() < 1e-12);
    for ((i, j), boxes) in example1_result() {
        let q = cagd_core::tri_index(3, i, j);
        for (c, [l, h]) in boxes.into_iter().enumerate() {
            assert!((a.lo[3 * q + c] - l).abs() < 1e-10 && (a.hi[3 * q + c] - h).abs() < 1e-10);
        }
    }
}

#[test]
fn example_1_tighter_models() {
    // SPEC-convert I.2: N = 4: 3.472, N = 6: 2.997, N = 10: 2.622, N = 16: 2.491 (printed to
    // 3 decimals, so compared to 5e-4).
    let p = example1();
    let mut last = f64::INFINITY;
    for (big, want) in [(4, 3.472), (6, 2.997), (10, 2.622), (16, 2.491)] {
        let opts = IntervalOptions {
            containment_degree: Some(big),
            ..IntervalOptions::new(3)
        };
        let r = reduce_interval_triangle(&p, &opts).unwrap();
        let t = r.report.thickness_out;
        assert!((t - want).abs() < 5e-4, "N = {big}: {t}");
        assert!(t <= last + 1e-12, "thinner as N grows");
        last = t;
        assert_eq!(r.report.containment_degree, big);
        assert!(r.patch.contains(&p, Some(big)).unwrap());
        assert!(r.report.max_violation.unwrap() <= 0.0);
    }
}

/// The public spec vectors of `interval_triangle_degree_reduction_lp`.
#[test]
fn public_spec_vectors() {
    let vs = cagd_testkit::vectors_with_algorithm("vectors-convert.json", "interval_triangle");
    assert!(vs.len() >= 2);
    for v in vs {
        let boxes = v["input"]["boxes"].as_array().unwrap();
        let n = usize::try_from(v["params"]["n"].as_u64().unwrap()).unwrap();
        let m = usize::try_from(v["params"]["m"].as_u64().unwrap()).unwrap();
        let dim = boxes[0].as_array().unwrap().len();
        let (mut lo, mut hi) = (Vec::new(), Vec::new());
        for b in boxes {
            for side in b.as_array().unwrap() {
                lo.push(side[0].as_f64().unwrap());
                hi.push(side[1].as_f64().unwrap());
            }
        }
        let p = IntervalTriPatch::new(lo, hi, n, dim).unwrap();
        let r = reduce_interval_triangle(&p, &IntervalOptions::new(m)).unwrap();
        let ex = &v["exact"];
        let t_out = cagd_testkit::num(&ex["thickness_out"]);
        assert!(
            (r.report.thickness_out - t_out).abs() < 1e-10 * t_out.max(1.0),
            "{}",
            v["id"]
        );
        for (q, b) in ex["boxes"].as_array().unwrap().iter().enumerate() {
            for (c, side) in b.as_array().unwrap().iter().enumerate() {
                let (l, h) = (cagd_testkit::num(&side[0]), cagd_testkit::num(&side[1]));
                assert!(
                    (r.patch.lo()[q * dim + c] - l).abs() < 1e-10 * l.abs().max(1.0),
                    "{}",
                    v["id"]
                );
                assert!(
                    (r.patch.hi()[q * dim + c] - h).abs() < 1e-10 * h.abs().max(1.0),
                    "{}",
                    v["id"]
                );
            }
        }
    }
}

#[test]
fn elevation_vector_matches_exactly() {
    let v = cagd_testkit::vector("vectors-convert.json", "interval-elevation-2to3");
    let e = triangle_elevation_matrix_exact(2, 3).unwrap();
    for (r, row) in v["exact"]["E"].as_array().unwrap().iter().enumerate() {
        for (c, x) in row.as_array().unwrap().iter().enumerate() {
            assert_eq!(e.get(r, c).unwrap(), &cagd_testkit::rational(x));
        }
    }
}

/// Second LP route: the dual of the coupled LP,
/// `max h'y - l'z s.t. A'y + w = 1, A'z + w = 1, y, z, w >= 0` (and without `w` for the
/// decoupled form), solved by the same crate. Returns the optimum per coordinate summed.
fn dual_objective(p: &IntervalTriPatch, m: usize, big: usize, coupled: bool) -> f64 {
    let (n, d) = (p.degree(), p.dim());
    let eo = IntElevation::new(m, big).unwrap();
    let ei = IntElevation::new(n, big).unwrap();
    let a = eo.to_f64();
    let (rows, nm) = (eo.nrows(), eo.ncols());
    let mut total = 0.0;
    for c in 0..d {
        let col = |net: &[f64]| net.iter().skip(c).step_by(d).copied().collect::<Vec<_>>();
        let h = ei.apply_f64(&col(p.hi()));
        let l = ei.apply_f64(&col(p.lo()));
        let mut lp = Lp::default();
        let y: Vec<usize> = h
            .iter()
            .map(|&hr| lp.var(-hr, (0.0, f64::INFINITY)))
            .collect();
        let z: Vec<usize> = l
            .iter()
            .map(|&lr| lp.var(lr, (0.0, f64::INFINITY)))
            .collect();
        let w: Vec<usize> = if coupled {
            (0..nm).map(|_| lp.var(0.0, (0.0, f64::INFINITY))).collect()
        } else {
            Vec::new()
        };
        for q in 0..nm {
            for vars in [&y, &z] {
                let mut terms: Vec<(usize, f64)> = (0..rows)
                    .filter(|&r| a[r * nm + q] != 0.0)
                    .map(|r| (vars[r], a[r * nm + q]))
                    .collect();
                if coupled {
                    terms.push((w[q], 1.0));
                }
                lp.row(terms, Sense::Eq, 1.0);
            }
        }
        total -= solve_min(&lp, "dual").unwrap().objective;
    }
    total
}

#[test]
fn dual_route_on_example_1() {
    let p = example1();
    let want = 125.0 / 36.0 * 30.0;
    assert!((dual_objective(&p, 3, 4, true) - want).abs() < 1e-9);
    assert!((dual_objective(&p, 3, 4, false) - want).abs() < 1e-9);
}

#[test]
fn bad_input_is_a_named_error() {
    let lo = vec![0.0; 6];
    let mut hi = vec![1.0; 6];
    hi[4] = -1.0;
    assert_eq!(
        IntervalTriPatch::new(lo.clone(), hi, 2, 1),
        Err(Error::EmptyInterval {
            index: 4,
            coord: 0,
            lo: 0.0,
            hi: -1.0
        })
    );
    let mut nan = vec![1.0; 6];
    nan[2] = f64::NAN;
    assert!(matches!(
        IntervalTriPatch::new(lo.clone(), nan, 2, 1),
        Err(Error::NonFinite { index: 2, .. })
    ));
    let mut inf = lo.clone();
    inf[0] = f64::NEG_INFINITY;
    assert!(matches!(
        IntervalTriPatch::new(inf, vec![1.0; 6], 2, 1),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        IntervalTriPatch::new(lo.clone(), vec![1.0; 5], 2, 1),
        Err(Error::LengthMismatch { .. })
    ));
    assert!(matches!(
        IntervalTriPatch::new(lo.clone(), vec![1.0; 6], 2, 0),
        Err(Error::ZeroDimension)
    ));
    let p = IntervalTriPatch::new(lo, vec![1.0; 6], 2, 1).unwrap();
    for m in [2, 3] {
        assert!(matches!(
            reduce_interval_triangle(&p, &IntervalOptions::new(m)),
            Err(Error::BadDegreePair { .. })
        ));
    }
    let low_n = IntervalOptions {
        containment_degree: Some(1),
        ..IntervalOptions::new(1)
    };
    assert!(matches!(
        reduce_interval_triangle(&p, &low_n),
        Err(Error::BadDegreePair { .. })
    ));
    assert!(matches!(p.eval(0.7, 0.7), Err(Error::BadParameter { .. })));
}

#[test]
fn degree_zero_target_and_elevated_input() {
    // An interval triangle that is an exact elevation reduces back to itself (1 ulp repair).
    let lo2 = vec![0.0, 1.0, 3.0, 2.0, -1.0, 0.5];
    let hi2: Vec<f64> = lo2.iter().map(|x| x + 0.25).collect();
    let p2 = IntervalTriPatch::new(lo2.clone(), hi2, 2, 1).unwrap();
    let p5 = p2.elevate(5).unwrap();
    assert!(
        (p5.thickness() - p2.thickness()).abs() < 1e-14,
        "elevation keeps the thickness"
    );
    let r = reduce_interval_triangle(&p5, &IntervalOptions::new(2)).unwrap();
    assert!((r.report.thickness_out - p5.thickness()).abs() < 1e-12);
    for (a, b) in r.patch.lo().iter().zip(&lo2) {
        assert!((a - b).abs() < 1e-12);
    }
    let r0 = reduce_interval_triangle(&p2, &IntervalOptions::new(0)).unwrap();
    assert_eq!(r0.patch.lo(), &[-1.0]);
    assert_eq!(r0.patch.hi(), &[3.25]);
}

/// De Casteljau on one coordinate of a net (independent of the basis evaluation).
fn de_casteljau(net: &[f64], n: usize, dim: usize, c: usize, u: f64, v: f64) -> f64 {
    let w = 1.0 - u - v;
    let mut cur: Vec<f64> = (0..tri_count(n)).map(|q| net[q * dim + c]).collect();
    for k in (1..=n).rev() {
        let idx: Vec<(usize, usize)> = tri_indices(k).collect();
        let at = |i: usize, j: usize| cur[idx.iter().position(|&t| t == (i, j)).unwrap()];
        cur = tri_indices(k - 1)
            .map(|(i, j)| u * at(i + 1, j) + v * at(i, j + 1) + w * at(i, j))
            .collect();
    }
    cur[0]
}

fn interval_patch(max_n: usize) -> impl Strategy<Value = (IntervalTriPatch, usize)> {
    (1..=max_n, 1usize..=3).prop_flat_map(|(n, dim)| {
        let len = tri_count(n) * dim;
        (
            proptest::collection::vec(-10.0f64..10.0, len),
            proptest::collection::vec(0.0f64..3.0, len),
            0..n,
        )
            .prop_map(move |(lo, w, m)| {
                let hi = lo.iter().zip(&w).map(|(l, w)| l + w).collect();
                (IntervalTriPatch::new(lo, hi, n, dim).unwrap(), m)
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    /// Laws: certified containment, pointwise containment at 1 035 domain points by an
    /// independent evaluation, no empty box, the LP optimum equals the dual optimum (second
    /// route), and equals the analytic (vertex enumeration) optimum where that is feasible.
    #[test]
    fn reduction_laws((p, m) in interval_patch(8)) {
        let r = reduce_interval_triangle(&p, &IntervalOptions::new(m)).unwrap();
        let (n, d) = (p.degree(), p.dim());
        prop_assert!(r.patch.contains(&p, None).unwrap());
        prop_assert!(r.patch.lo().iter().zip(r.patch.hi()).all(|(l, h)| l <= h));
        prop_assert!(r.report.max_violation.unwrap() <= 0.0);
        // Pointwise, by de Casteljau; comp = abs, tol = 1e-11 (rounding of two evaluations
        // of values <= 1e2).
        for (a, b) in tri_indices(44) {
            let (u, v) = (a as f64 / 44.0, b as f64 / 44.0);
            for c in 0..d {
                let il = de_casteljau(p.lo(), n, d, c, u, v);
                let ih = de_casteljau(p.hi(), n, d, c, u, v);
                let ol = de_casteljau(r.patch.lo(), m, d, c, u, v);
                let oh = de_casteljau(r.patch.hi(), m, d, c, u, v);
                prop_assert!(ol <= il + 1e-11 && oh >= ih - 1e-11, "({u},{v}) c{c}");
            }
        }
        let nm = tri_count(m) as f64;
        let t_opt = r.report.objective / (d as f64 * nm);
        let rel = |a: f64, b: f64| (a - b).abs() / a.abs().max(b.abs()).max(1.0);
        // The repair only moves by rounding amounts.
        prop_assert!(rel(r.report.thickness_out, t_opt) < 1e-9);
        let any_coupled = r.report.coupled.iter().any(|&c| c);
        let dual = dual_objective(&p, m, n, any_coupled);
        if any_coupled {
            // Each coupled coordinate's optimum; decoupled coordinates equal their decoupled
            // optimum, and the coupled dual of those is the same value.
            prop_assert!(rel(dual, r.report.objective) < 1e-9, "dual {dual} vs {}", r.report.objective);
        } else {
            prop_assert!(rel(dual, r.report.objective) < 1e-9, "dual {dual} vs {}", r.report.objective);
        }
        if let Ok(a) = reduce_interval_triangle_analytic(&p, m, None) {
            prop_assert!(rel(a.objective, r.report.objective_decoupled) < 1e-9);
            if !any_coupled {
                prop_assert!(rel(a.thickness, r.report.thickness_out) < 1e-9);
            } else {
                prop_assert!(r.report.thickness_out >= a.thickness - 1e-9);
            }
        }
    }
}

/// A deterministic pseudo-random interval triangle (xorshift), widths in `[0, 2)`.
fn pseudo_random(n: usize, dim: usize, seed: u64) -> IntervalTriPatch {
    let mut s = seed.max(1);
    let mut next = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let len = tri_count(n) * dim;
    let lo: Vec<f64> = (0..len).map(|_| 20.0 * next() - 10.0).collect();
    let hi = lo.iter().map(|l| l + 2.0 * next()).collect();
    IntervalTriPatch::new(lo, hi, n, dim).unwrap()
}

#[test]
fn degree_20_to_10_in_three_dimensions() {
    // The largest size the issue asks for: LPs of 231 rows x 66 variables (coupled:
    // 528 x 132).
    let p = pseudo_random(20, 3, 7);
    let t0 = std::time::Instant::now();
    let r = reduce_interval_triangle(&p, &IntervalOptions::new(10)).unwrap();
    let dt = t0.elapsed();
    assert_eq!(r.report.lp_size, (231, 66));
    assert!(r.patch.contains(&p, None).unwrap());
    assert!(r.report.max_violation.unwrap() <= 0.0);
    let dual = dual_objective(&p, 10, 20, r.report.coupled.iter().any(|&c| c));
    assert!(
        (dual - r.report.objective).abs() < 1e-8 * dual.abs(),
        "{dual} {}",
        r.report.objective
    );
    eprintln!(
        "20 -> 10, dim 3: {dt:?}, coupled {:?}, repair {:e}",
        r.report.coupled, r.report.repair
    );
}

#[test]
fn adversarial_scales_are_certified() {
    // Far from the origin with tiny widths, zero widths, and a constant coordinate.
    let cases: [(f64, f64); 5] = [
        (1e6, 1e-9),
        (-3e8, 0.0),
        (0.0, 0.0),
        (1e-200, 1e-210),
        (5.0, 1e3),
    ];
    for (offset, width) in cases {
        for (n, m) in [(3, 1), (5, 4), (6, 2)] {
            let base = pseudo_random(n, 2, (n * 31 + m) as u64);
            let lo: Vec<f64> = base
                .lo()
                .iter()
                .map(|x| offset + x * width.max(1e-300))
                .collect();
            let mut hi: Vec<f64> = lo
                .iter()
                .zip(base.hi().iter().zip(base.lo()))
                .map(|(l, (h, b))| l + (h - b) * width)
                .collect();
            for (q, h) in hi.iter_mut().enumerate() {
                if q % 2 == 1 {
                    // A constant second coordinate.
                    *h = offset;
                }
            }
            let lo: Vec<f64> = lo
                .iter()
                .enumerate()
                .map(|(q, &l)| if q % 2 == 1 { offset } else { l })
                .collect();
            let p = IntervalTriPatch::new(lo, hi, n, 2).unwrap();
            let r = reduce_interval_triangle(&p, &IntervalOptions::new(m)).unwrap();
            assert!(
                r.patch.contains(&p, None).unwrap(),
                "{offset} {width} {n}->{m}"
            );
            assert!(r.report.max_violation.unwrap() <= 0.0);
            // The constant coordinate stays (nearly) constant: its thickness is the repair.
            let w1 = (0..tri_count(m))
                .map(|q| r.patch.hi()[2 * q + 1] - r.patch.lo()[2 * q + 1])
                .fold(0.0, f64::max);
            assert!(
                w1 <= 4.0 * r.report.repair + 1e-15 * offset.abs(),
                "{w1} {}",
                r.report.repair
            );
        }
    }
}

#[test]
fn boxes_near_the_largest_double_give_a_finite_report_or_a_named_error() {
    // The C ABI fuzz harness's case: finite boxes near +-1.8e308 made the thickness (a sum
    // of widths) and the LP objective infinite beside an Ok result.
    let n = 2;
    let lo: Vec<f64> = (0..tri_count(n))
        .map(|i| -1.7e308 + i as f64 * 1e300)
        .collect();
    let hi: Vec<f64> = lo.iter().map(|x| x + 1.6e308).collect();
    let p = IntervalTriPatch::new(lo, hi, n, 1).unwrap();
    // Each width is finite and their mean is too (the old sum overflowed).
    assert!(p.thickness().is_finite());
    match reduce_interval_triangle(&p, &IntervalOptions::new(1)) {
        Ok(r) => {
            let rep = &r.report;
            assert!(rep.thickness_out.is_finite() && rep.objective.is_finite());
            assert!(
                r.patch
                    .lo()
                    .iter()
                    .chain(r.patch.hi())
                    .all(|x| x.is_finite())
            );
        }
        Err(e) => assert!(
            matches!(
                e,
                Error::NonFinite { .. } | Error::NotCertified { .. } | Error::LpSolverFailed { .. }
            ),
            "{e}"
        ),
    }
}

/// The C ABI fuzz run's 7.3 s call (seed 107, session 0x7643e3568e5d464a): a 1-D degree-58
/// interval triangle to degree 14 (LPs of 1 770 rows x 120 variables, 2.5e7 units) is refused
/// by the work cap before any LP; the same patch to degree 4 (1 770 x 15, 4.0e5 units) is
/// answered and certified.
#[test]
fn lps_beyond_the_work_cap_are_refused_by_name() {
    let n = 58;
    let lo: Vec<f64> = (0..tri_count(n))
        .map(|i| ((i * 37) % 11) as f64 * 0.1)
        .collect();
    let hi: Vec<f64> = lo.iter().map(|x| x + 0.5).collect();
    let p = IntervalTriPatch::new(lo, hi, n, 1).unwrap();
    match reduce_interval_triangle(&p, &IntervalOptions::new(14)) {
        Err(Error::ConditionNotMet { eq: "I.2", why }) => assert!(why.contains("work cap")),
        other => panic!("expected the work cap, got {:?}", other.map(|r| r.report)),
    }
    assert!(tri_count(n) * tri_count(4).pow(2) <= MAX_INTERVAL_LP_WORK);
    let r = reduce_interval_triangle(&p, &IntervalOptions::new(4)).unwrap();
    assert!(r.patch.contains(&p, None).unwrap());
}
