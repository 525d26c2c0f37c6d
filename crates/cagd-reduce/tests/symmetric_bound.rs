//! The certified bound's symmetric split (methods symmetric under reversal evaluate the
//! error curve's even and odd parts at the nodes of `[0, 1/2)` only and take `e +- o`;
//! `src/bezier/operator/error_map.rs`) on families built to stress it: error curves purely
//! even, purely odd, one part dominating the other by up to 1e12, the error's peak at
//! `t = 1/2`, at one end or at a node and not at its mirror; methods and degree pairs with
//! every parity of `n` and `m`; dimensions 1–5. Each bound, through the batch and through
//! the per-curve call, must be at least the error measured by dense sampling plus local
//! maximisation (`max_deviation`), at most the level's factor times it plus a rounding
//! allowance, and the two calls must agree up to the order of their sums.

use cagd_core::BezierCurve;
use cagd_reduce::{
    BoundLevel, Method, ReduceOptions, max_deviation, operator, reduce_batch_with_bounds,
    reduce_with,
};
use cagd_testkit::bench::random_input;

/// The families for degree `n` in `dim` coordinates: (name, control points).
fn families(n: usize, dim: usize, seed: u64) -> Vec<(String, Vec<f64>)> {
    let n1 = n + 1;
    let base = random_input(n1 * dim, seed);
    let mirror = |sign: f64| -> Vec<f64> {
        let mut p = base.clone();
        for j in 0..n1 {
            for k in 0..dim {
                p[j * dim + k] = 0.5 * (base[j * dim + k] + sign * base[(n - j) * dim + k]);
            }
        }
        p
    };
    let (even, odd) = (mirror(1.0), mirror(-1.0));
    let mut out = vec![
        ("random".to_string(), base.clone()),
        ("even".to_string(), even.clone()),
        ("odd".to_string(), odd.clone()),
    ];
    for ratio in [1e-3, 1e-8, 1e-12] {
        let mix = |a: &[f64], b: &[f64]| -> Vec<f64> {
            a.iter().zip(b).map(|(x, y)| x + ratio * y).collect()
        };
        out.push((format!("even + {ratio:e} odd"), mix(&even, &odd)));
        out.push((format!("odd + {ratio:e} even"), mix(&odd, &even)));
    }
    // Single spikes: the error's peak in the middle, at one end, near one node only.
    for j in [0, n / 2, n.div_ceil(2), 1, n - 1] {
        let mut p = vec![0.0; n1 * dim];
        p[j * dim + dim - 1] = 1.0;
        out.push((format!("spike {j}"), p));
    }
    // Two spikes at mirrored places with unequal weights (even and odd parts alike in size).
    for (j, w) in [(1, -0.9), (n / 3, 0.5), (0, -1.0)] {
        let mut p = vec![0.0; n1 * dim];
        p[j * dim] = 1.0;
        p[(n - j) * dim] = w;
        out.push((format!("pair {j} {w}"), p));
    }
    out
}

#[test]
fn split_bounds_hold_on_families_built_against_it() {
    let methods = [
        Method::L2 { r: 0, p: 0 },
        Method::L2 { r: 1, p: 1 },
        Method::L2 { r: 2, p: 2 },
        Method::GeneralizedInverse,
        Method::ConstrainedChebyshev { r: 1, p: 1 },
    ];
    let pairs = [(4, 3), (5, 4), (6, 3), (7, 2), (9, 6), (12, 7), (31, 16)];
    let mut worst = [0.0f64; 2];
    let mut checked = 0;
    for method in methods {
        for (n, m) in pairs {
            let Ok(op) = operator(method, n, m) else {
                continue;
            };
            for dim in [1, 2, 3, 5] {
                let fams = families(n, dim, (n * 31 + m * 7 + dim) as u64);
                let input: Vec<f64> = fams.iter().flat_map(|(_, p)| p.clone()).collect();
                let curves = fams.len();
                let mut out = vec![0.0; curves * (m + 1) * dim];
                for (li, (level, ratio)) in [(BoundLevel::Fast, 1.25), (BoundLevel::Tight, 1.075)]
                    .into_iter()
                    .enumerate()
                {
                    let mut bounds = vec![0.0; curves];
                    reduce_batch_with_bounds(&op, &input, dim, &mut out, &mut bounds, level)
                        .unwrap();
                    for (c, (name, pts)) in fams.iter().enumerate() {
                        let what = format!("{method:?} ({n},{m}) dim {dim} {level:?} {name}");
                        let p = BezierCurve::new(pts.clone(), dim).unwrap();
                        let qp = out[c * (m + 1) * dim..(c + 1) * (m + 1) * dim].to_vec();
                        let q = BezierCurve::new(qp, dim).unwrap();
                        let measured = max_deviation(&p, &q).unwrap();
                        let pmax = pts.iter().fold(0.0f64, |a, x| a.max(x.abs()));
                        let b = bounds[c];
                        assert!(b >= measured, "{what}: bound {b} < measured {measured}");
                        assert!(
                            b <= ratio * measured * (1.0 + 1e-9) + 1e-11 * pmax,
                            "{what}: bound {b} vs measured {measured}"
                        );
                        if measured > 1e-9 * pmax {
                            worst[li] = worst[li].max(b / measured);
                        }
                        // The per-curve call: the same bound up to the order of the sums.
                        let opts = ReduceOptions {
                            bound: level,
                            ..ReduceOptions::new(method, m)
                        };
                        let red = reduce_with(&p, &opts).unwrap();
                        assert_eq!(red.curve.points(), q.points(), "{what}");
                        let one = red.report.error_bound.unwrap();
                        assert!(
                            (one - b).abs() <= 1e-10 * b + 1e-13 * pmax,
                            "{what}: per-curve {one} vs batch {b}"
                        );
                        checked += 1;
                    }
                }
            }
        }
    }
    println!(
        "{checked} bounds; worst bound/measured fast {:.4}, tight {:.4}",
        worst[0], worst[1]
    );
    assert!(checked > 1000);
}
