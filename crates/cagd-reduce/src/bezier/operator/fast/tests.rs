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
        Method::GeneralizedInverseEnds,
        Method::ConstrainedChebyshev { r: 0, p: 0 },
        Method::ConstrainedChebyshev { r: 1, p: 2 },
        Method::L2 { r: 0, p: 0 },
        Method::L2 { r: 2, p: 1 },
        Method::L2 { r: -1, p: 1 },
    ]
}

/// Max entrywise `|fast - exact| / ||exact||_inf` of the matrix and the functionals' error
/// `sum_t coef_t ||g_fast - g_exact||_1` as a fraction of what `finish` accepts, after
/// checking the proven bounds and the term structure. `None` if the pair is invalid
/// for the method or has no fast route.
pub(super) fn compare(method: Method, n: usize, m: usize) -> Option<(f64, f64, OperatorRoute)> {
    method.check(n, m).ok()?;
    compare_built(method, n, m, &build(method, n, m)?)
}

/// [`compare`] for a given fast-built operator.
fn compare_built(
    method: Method,
    n: usize,
    m: usize,
    fast: &Built,
) -> Option<(f64, f64, OperatorRoute)> {
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
    let (mut term_abs, mut ts) = (0.0f64, 0.0f64);
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
        term_abs += ec * diff;
        ts += ec * gn;
    }
    // The functionals' errors are added to the own bound: what `finish` accepts is
    // `1e-12 max(1, sum_t coef_t ||g_t||_1)` or half the own bound's rounding allowance
    // `(n+3) eps (||A|| + sum_t coef_t ||g_t||_1 + 1)`; the ratio of the actual error to that.
    #[allow(clippy::cast_precision_loss, reason = "n <= 64")]
    let accepted =
        (TOLERANCE * ts.max(1.0)).max((n as f64 + 3.0) * f64::EPSILON * (norm + ts + 1.0));
    Some((worst, term_abs / accepted, fast.route))
}

/// Compares every method at the pairs of `pairs`, asserting the 1e-12 goal; returns one
/// report line per method (worst relative error, routes taken).
fn sweep(pairs: &[(usize, usize)]) -> Vec<String> {
    let mut report = Vec::new();
    for method in methods() {
        let (mut worst, mut tworst, mut routes, mut exact) = (0.0f64, 0.0f64, Vec::new(), 0);
        for &(n, m) in pairs {
            if method.check(n, m).is_err() {
                continue;
            }
            match compare(method, n, m) {
                Some((e, te, route)) => {
                    assert!(e <= 1e-12, "{method:?} {n}->{m}: {e:e}");
                    assert!(
                        te <= 1.0,
                        "{method:?} {n}->{m}: terms {te:e} of the accepted"
                    );
                    worst = worst.max(e);
                    tworst = tworst.max(te);
                    if !routes.contains(&route) {
                        routes.push(route);
                    }
                }
                None => exact += 1,
            }
        }
        report.push(format!(
            "{method:?}: matrix {worst:.1e}, terms {tworst:.1e} of the accepted error, routes {routes:?}, {exact} of the pairs left to the exact route"
        ));
    }
    report
}

#[test]
fn fast_routes_match_the_exact_oracle_up_to_degree_16() {
    let mut pairs: Vec<(usize, usize)> =
        (1..=16).flat_map(|n| (0..n).map(move |m| (n, m))).collect();
    pairs.extend([(20, 10), (24, 12), (24, 23)]);
    println!("{}", sweep(&pairs).join("\n"));
}

/// Degrees up to 64 (the supported maximum): minutes of exact arithmetic, so ignored in the
/// debug suite; run with `cargo test --release -p cagd-reduce --lib oracle_to_degree_64 --
/// --ignored --nocapture`.
#[test]
#[ignore = "exact oracle at degree 64 takes minutes"]
fn fast_routes_match_the_exact_oracle_to_degree_64() {
    let mut pairs = Vec::new();
    for n in [20, 30, 40, 50, 64] {
        for m in [0, 1, 3, n / 4, n / 2, 3 * n / 4, n - 2, n - 1] {
            if !pairs.contains(&(n, m)) {
                pairs.push((n, m));
            }
        }
    }
    println!("{}", sweep(&pairs).join("\n"));
}

/// The 256-bit route of every method against the oracle at every pair up to degree 12
/// (forced: at these degrees `build` takes `f64` or double-word), and at pairs of degree 40
/// where `build` takes it (the stepwise perturbation, truncations close to `m = n`): within
/// its proven error, and that error far below the goal.
#[test]
fn multi_word_route_matches_the_exact_oracle() {
    for method in methods() {
        for n in 1..=12 {
            for m in 0..n {
                if method.check(n, m).is_err() {
                    continue;
                }
                let (rows, terms) = rows_of::<wide::Wide>(method, n, m, false).unwrap();
                let b = finish(&rows, &terms, OperatorRoute::MultiWord, 1e-15)
                    .unwrap_or_else(|| panic!("{method:?} {n}->{m}: not proven to 1e-15"));
                let (e, te, _) = compare_built(method, n, m, &b).unwrap();
                assert!(e <= 1e-15 && te <= 1.0, "{method:?} {n}->{m}: {e:e} {te:e}");
            }
        }
    }
    for (method, n, m) in [
        (Method::Perturb, 40, 10),
        // (40,10) takes double-word since the final bound is no longer doubled.
        (Method::PerturbG1 { l1: 0.25, l2: -0.5 }, 44, 10),
        (Method::GeneralizedInverse, 40, 37),
        (Method::Eck, 40, 37),
    ] {
        let (e, te, route) = compare(method, n, m).unwrap();
        assert_eq!(route, OperatorRoute::MultiWord, "{method:?} {n}->{m}");
        assert!(e <= 1e-15 && te <= 1.0, "{method:?} {n}->{m}: {e:e} {te:e}");
    }
}

/// The pairs that fell back to the exact rationals at degree 64 (seconds each: the C fuzz
/// run's slow calls) now take the 256-bit route within the goal (the route's accuracy
/// against the oracle: `multi_word_route_matches_the_exact_oracle` and the ignored sweep
/// to degree 64), and Eck's and the Chebyshev truncations' `(64,10)` the double-word one
/// (their bound terms by quadrature, no longer by alternating sums).
#[test]
fn no_exact_fallback_at_degree_64() {
    for (method, n, m, route) in [
        (Method::Perturb, 64, 32, OperatorRoute::MultiWord),
        (Method::GeneralizedInverse, 64, 60, OperatorRoute::MultiWord),
        (Method::Eck, 64, 10, OperatorRoute::DoubleWord),
        (
            Method::BogackiWeinsteinXu,
            64,
            10,
            OperatorRoute::DoubleWord,
        ),
        (
            Method::ConstrainedChebyshev { r: 0, p: 0 },
            64,
            10,
            OperatorRoute::DoubleWord,
        ),
    ] {
        let op = crate::build_operator(method, n, m, false).unwrap();
        assert_eq!(op.route(), route, "{method:?} {n}->{m}");
        assert!(op.construction_error() <= TOLERANCE * op.norm_inf());
    }
}

/// The pairs of the two stepwise routes' oracle tests: every pair `n <= 16` and `(20,10)`,
/// `(24,12)`, `(30,15)`.
fn stepwise_oracle_pairs() -> Vec<(usize, usize)> {
    let mut pairs: Vec<(usize, usize)> =
        (1..=16).flat_map(|n| (0..n).map(move |m| (n, m))).collect();
    pairs.extend([(20, 10), (24, 12), (30, 15)]);
    pairs
}

/// For every method of `methods` at every pair of [`stepwise_oracle_pairs`] it accepts:
/// the rows and terms `stepwise` gives, rounded by `finish` as `route`, are proven at the
/// rounding level (`build`'s `strict`), every row of the matrix and every bound term is
/// within its proven error of the exact oracle, and `build` takes that matrix; `more` then
/// checks the finished operator and `build`'s further.
fn stepwise_route_matches_the_exact_oracle<R: Rounded>(
    methods: [Method; 2],
    route: OperatorRoute,
    stepwise: impl Fn(Method, usize, usize) -> Option<(Vec<R>, Vec<(f64, R)>)>,
    more: impl Fn(Method, usize, usize, &Built, &Built),
) {
    for method in methods {
        for (n, m) in stepwise_oracle_pairs() {
            if method.check(n, m).is_err() {
                continue;
            }
            #[allow(clippy::cast_precision_loss, reason = "n <= 30")]
            let strict = 2.0 * (n as f64 + 3.0) * f64::EPSILON;
            let (rows, terms) =
                stepwise(method, n, m).unwrap_or_else(|| panic!("{method:?} {n}->{m}: given up"));
            let b = finish(&rows, &terms, route, strict)
                .unwrap_or_else(|| panic!("{method:?} {n}->{m}: not proven at {strict:e}"));
            let (e, te, _) = compare_built(method, n, m, &b).unwrap();
            assert!(
                e <= strict && te <= 1.0,
                "{method:?} {n}->{m}: {e:e} {te:e}"
            );
            let built = build(method, n, m).unwrap();
            assert_eq!(built.matrix, b.matrix, "{method:?} {n}->{m}: build's route");
            more(method, n, m, &b, &built);
        }
    }
}

/// The compensated route of Farin's and the perturbation method (`compensated.rs`) at every
/// pair `n <= 16` and at `(20,10)`, `(24,12)`, `(30,15)`: proven at the rounding level
/// (`build`'s `strict`), every row of the matrix and every bound term within its proven
/// error of the exact oracle, and `build` takes it there.
#[test]
fn compensated_route_matches_the_exact_oracle() {
    stepwise_route_matches_the_exact_oracle(
        [Method::Farin, Method::Perturb],
        OperatorRoute::DoubleWord,
        compensated::stepwise,
        |_, _, _, _, _| {},
    );
}

/// The row-bound route of Forrest and Piegl–Tiller (`row_bound.rs`) at every pair `n <= 16`
/// and at `(20,10)`, `(24,12)`, `(30,15)`: proven at the rounding level (`build`'s
/// `strict`), every row of the matrix and every bound term within its proven error of the
/// exact oracle, `build` takes it; and against the independent tracked `f64` route (one
/// error per entry): the same matrix bit for bit, its proven error at most `1 + 1e-5` times
/// that route's (the per-row bound is the sum of the per-entry ones, plus the underflow
/// allowances; Piegl–Tiller's middle point is bounded as Forrest's, a little tighter).
#[test]
fn row_bound_route_matches_the_exact_oracle() {
    stepwise_route_matches_the_exact_oracle(
        [Method::Forrest, Method::PieglTiller],
        OperatorRoute::F64,
        row_bound::stepwise,
        |method, n, m, b, built| {
            assert_eq!(built.route, OperatorRoute::F64, "{method:?} {n}->{m}");
            let (rows, terms) = rows_of::<f64>(method, n, m, false).unwrap();
            let tracked = finish(&rows, &terms, OperatorRoute::F64, 1e300).unwrap();
            assert_eq!(tracked.matrix, b.matrix, "{method:?} {n}->{m}: tracked");
            assert!(
                b.error <= tracked.error * (1.0 + 1e-5) + 1e-290,
                "{method:?} {n}->{m}: proven {:e} against the tracked {:e}",
                b.error,
                tracked.error
            );
        },
    );
    // Degree 64 (the oracle there is the ignored sweep's): accepted, the tracked route's
    // matrix.
    for method in [Method::Forrest, Method::PieglTiller] {
        for (n, m) in [(64, 63), (64, 32), (64, 10)] {
            let strict = 2.0 * (64.0 + 3.0) * f64::EPSILON;
            let (rows, terms) = row_bound::stepwise(method, n, m).unwrap();
            let b = finish(&rows, &terms, OperatorRoute::F64, strict)
                .unwrap_or_else(|| panic!("{method:?} {n}->{m}: not proven at {strict:e}"));
            let (rows, terms) = rows_of::<f64>(method, n, m, false).unwrap();
            let tracked = finish(&rows, &terms, OperatorRoute::F64, 1e300).unwrap();
            assert_eq!(tracked.matrix, b.matrix, "{method:?} {n}->{m}: tracked");
            assert!(b.error <= tracked.error * (1.0 + 1e-5));
        }
    }
}

/// Farin at `(64,10)`: its split form gives up in double-word, the direct form is proven
/// (a regression: the give-up once ended the fast routes, and the exact route took 3 s).
#[test]
fn farin_falls_back_to_the_direct_form_not_the_exact_route() {
    let b = build(Method::Farin, 64, 10).expect("a fast route");
    assert_eq!(b.route, OperatorRoute::DoubleWord);
    let norm = b
        .matrix
        .chunks_exact(65)
        .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max);
    assert!(b.error <= TOLERANCE * norm);
}

#[test]
fn every_method_has_a_fast_route_and_the_exact_one_on_request() {
    for method in methods() {
        let op = crate::build_operator(method, 9, 4, false).unwrap();
        assert_ne!(op.route(), OperatorRoute::Exact, "{method:?}");
        assert!(op.construction_error() <= TOLERANCE * op.norm_inf());
    }
    let op = crate::build_operator(Method::GeneralizedInverseEnds, 9, 4, true).unwrap();
    assert_eq!(op.route(), OperatorRoute::Exact);
    assert_eq!(op.construction_error(), 0.0);
}

/// The source degrees of the survey: `CAGD_SURVEY_ALL=1` every `n` from 17 to 64, else
/// 40, 48, 56, 64.
fn survey_degrees() -> Vec<usize> {
    if std::env::var("CAGD_SURVEY_ALL").is_ok_and(|v| v == "1") {
        (17..=64).collect()
    } else {
        vec![40, 48, 56, 64]
    }
}

/// Survey (not a check): at degree >= 40 (or 17..=64, see [`survey_degrees`]), the pairs left to the exact route and the
/// slowest build per method (`cargo test --release -p cagd-reduce --lib survey -- --ignored
/// --nocapture`).
#[test]
#[ignore = "survey"]
fn survey_high_degree_routes() {
    for method in methods() {
        let (mut exact, mut slowest, mut wide) = (Vec::new(), (0.0f64, 0, 0), 0);
        for n in survey_degrees() {
            for m in 1..n {
                if method.check(n, m).is_err() {
                    continue;
                }
                let t = std::time::Instant::now();
                let b = build(method, n, m);
                let dt = t.elapsed().as_secs_f64();
                if dt > slowest.0 {
                    slowest = (dt, n, m);
                }
                match b {
                    None => exact.push((n, m)),
                    Some(b) if b.route == OperatorRoute::MultiWord => wide += 1,
                    Some(_) => {}
                }
            }
        }
        println!(
            "{method:?}: {wide} multi-word, slowest {:.1} ms at {:?}, exact: {exact:?}",
            slowest.0 * 1e3,
            (slowest.1, slowest.2)
        );
    }
}

/// Profiling aid (not a check): 200 builds of L2-C0 `(30,15)`.
#[test]
#[ignore = "profiling aid"]
fn profile_l2_c0_30_15() {
    for _ in 0..200 {
        std::hint::black_box(build(Method::L2 { r: 0, p: 0 }, 30, 15));
    }
}

/// Diagnostic (not a check): the proven error of the `f64` and the double-word route of a
/// few methods, relative to the inf-norm, and their bound terms' proven errors against the
/// terms' size (`cargo test --release -p cagd-reduce --lib diag_route_errors -- --ignored
/// --nocapture`).
#[test]
#[ignore = "diagnostic"]
fn diag_route_errors() {
    fn summary<R: Rounded>(rows: &[R], terms: &[(f64, R)], n: usize) -> Option<String> {
        let b = finish(rows, terms, OperatorRoute::F64, 1e300)?;
        let norm = b
            .matrix
            .chunks_exact(n + 1)
            .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
            .fold(0.0, f64::max);
        let te: f64 = b.terms.iter().map(|t| t.0 * t.2).sum();
        let ts: f64 = b
            .terms
            .iter()
            .map(|t| t.0 * t.1.iter().map(|x| x.abs()).sum::<f64>())
            .sum();
        Some(format!(
            "norm {norm:.2e} err {:.2e} terms {te:.2e} of {ts:.2e}",
            b.error / norm
        ))
    }
    for method in [
        Method::Forrest,
        Method::PieglTiller,
        Method::Farin,
        Method::Perturb,
        Method::Eck,
        Method::BogackiWeinsteinXu,
        Method::L2 { r: 1, p: 1 },
    ] {
        for (n, m) in [(10, 5), (15, 10), (20, 10), (30, 15), (64, 32)] {
            let f = rows_of::<f64>(method, n, m, false)
                .and_then(|(rows, terms)| summary(&rows, &terms, n))
                .unwrap_or_else(|| "given up".to_string());
            let d = rows_of::<dd::Dd>(method, n, m, false)
                .and_then(|(rows, terms)| summary(&rows, &terms, n))
                .unwrap_or_else(|| "given up".to_string());
            let c = compensated::stepwise(method, n, m)
                .and_then(|(rows, terms)| summary(&rows, &terms, n))
                .unwrap_or_else(|| "given up / none".to_string());
            println!("{method:?} ({n},{m}) f64: {f}; double-word: {d}; compensated: {c}");
        }
    }
}

/// Profiling aid (not a check): 200 builds of the method `CAGD_PROFILE_METHOD` (an index
/// into the bench's list: 0 L2 C0, 3 constrained Chebyshev, 5 Forrest, 6 Piegl–Tiller,
/// 7 Farin, 9 perturbation) at `(30,15)`.
#[test]
#[ignore = "profiling aid"]
fn profile_method_30_15() {
    let list = [
        Method::L2 { r: 0, p: 0 },
        Method::GeneralizedInverse,
        Method::L2 { r: 1, p: 1 },
        Method::ConstrainedChebyshev { r: 0, p: 0 },
        Method::BogackiWeinsteinXu,
        Method::Forrest,
        Method::PieglTiller,
        Method::Farin,
        Method::Eck,
        Method::Perturb,
        Method::GeneralizedInverseEnds,
    ];
    let i: usize = std::env::var("CAGD_PROFILE_METHOD")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0);
    for _ in 0..200 {
        std::hint::black_box(build(list[i], 30, 15));
    }
}
