//! The fast routes against the exact oracle (`exact_operator`): entrywise accuracy relative
//! to the inf-norm, soundness of the proven error bounds, and the same bound terms.

use super::*;
use crate::bezier::operator::exact_operator;
use crate::exact::q_to_f64;

/// Every method family with a fast route, with its minimum target degree.
pub(super) fn methods() -> Vec<Method> {
    vec![
        Method::Forrest,
        Method::PieglTiller,
        Method::Farin,
        Method::Perturb,
        Method::PerturbG1 { l1: 0.0, l2: 0.0 },
        Method::PerturbG1 { l1: 0.25, l2: -0.5 },
        Method::Eck,
        Method::WatkinsWorsey,
        Method::BogackiWeinsteinXu,
        Method::GeneralizedInverse,
        Method::ConstrainedChebyshev { r: 0, p: 0 },
        Method::ConstrainedChebyshev { r: 1, p: 2 },
        Method::L2 { r: 0, p: 0 },
        Method::L2 { r: 2, p: 1 },
        Method::L2 { r: -1, p: 1 },
    ]
}

/// Max entrywise `|fast - exact| / ||exact||_inf` over the matrix and the bound functionals,
/// after checking the proven bounds and the term structure. `None` if the pair is invalid
/// for the method or has no fast route.
pub(super) fn compare(method: Method, n: usize, m: usize) -> Option<(f64, OperatorRoute)> {
    method.check(n, m).ok()?;
    let fast = build(method, n, m)?;
    let (exact, terms) = exact_operator(method, n, m).ok()?;
    let ex = exact.to_f64();
    let cols = n + 1;
    let norm = ex
        .chunks_exact(cols)
        .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max);
    let mut worst = 0.0f64;
    for (i, (fr, er)) in fast
        .matrix
        .chunks_exact(cols)
        .zip(ex.chunks_exact(cols))
        .enumerate()
    {
        let diff: f64 = fr.iter().zip(er).map(|(a, b)| (a - b).abs()).sum();
        let rounding: f64 = er.iter().map(|x| x.abs()).sum::<f64>() * f64::EPSILON;
        assert!(
            diff <= fast.error + rounding,
            "{method:?} {n}->{m} row {i}: error {diff:e} above the proven {:e}",
            fast.error
        );
        for (a, b) in fr.iter().zip(er) {
            worst = worst.max((a - b).abs() / norm);
        }
    }
    assert_eq!(fast.terms.len(), terms.len(), "{method:?} {n}->{m} terms");
    for ((fc, fg, fe), (ec, eg)) in fast.terms.iter().zip(&terms) {
        assert!(
            *fc >= *ec * (1.0 - 1e-15) && *fc <= *ec * (1.0 + 1e-12),
            "{method:?} {n}->{m}: coef {fc:e} vs {ec:e}"
        );
        let gn: f64 = eg.iter().map(|x| q_to_f64(x).abs()).sum();
        let diff: f64 = fg
            .iter()
            .zip(eg)
            .map(|(a, b)| (a - q_to_f64(b)).abs())
            .sum();
        assert!(diff <= fe + gn * f64::EPSILON, "{method:?} {n}->{m}: term");
        worst = worst.max(diff / gn.max(f64::MIN_POSITIVE));
    }
    Some((worst, fast.route))
}

#[test]
fn fast_routes_match_the_exact_oracle_up_to_degree_24() {
    let mut report = Vec::new();
    for method in methods() {
        let mut worst = 0.0f64;
        for n in 1..=24 {
            for m in 0..n {
                if let Some((e, _)) = compare(method, n, m) {
                    assert!(e <= 1e-12, "{method:?} {n}->{m}: {e:e}");
                    worst = worst.max(e);
                }
            }
        }
        report.push(format!("{method:?}: {worst:.1e}"));
    }
    println!("{}", report.join("\n"));
}

#[test]
#[ignore = "diagnostic"]
fn routes_diagnostic() {
    for method in methods() {
        let mut line = format!("{method:?}:");
        for (n, m) in [
            (4, 3),
            (5, 4),
            (10, 5),
            (15, 10),
            (20, 10),
            (30, 15),
            (40, 20),
            (64, 32),
            (64, 63),
            (64, 10),
        ] {
            if method.check(n, m).is_err() {
                continue;
            }
            let t = std::time::Instant::now();
            let b = build(method, n, m);
            let us = t.elapsed().as_secs_f64() * 1e6;
            line += &format!(" ({n},{m}) {:?} {us:.0}us;", b.map(|b| b.route));
        }
        println!("{line}");
    }
}
