//! Tests of the reductions to a tolerance: the spec vectors of Algorithm 14.2.1 and
//! eq. 14.2.11, an accuracy sweep over tolerances, methods and curves, the continuity of
//! the joins, and the error cases.

use cagd_core::{BSplineCurve, BezierCurve, Error};
use cagd_testkit::{assert_close, flat, num, vector, vectors_with_algorithm};

use crate::{
    Method, PiecewiseReduction, ToleranceOptions, reduce_to_tolerance,
    reduce_to_tolerance_alg_14_2_1, subdivision_levels,
};

/// Deterministic pseudo-random coordinates in `[-1, 1]` (64-bit LCG).
fn random_points(n_points: usize, dim: usize, seed: u64) -> Vec<f64> {
    let mut s = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (0..n_points * dim)
        .map(|_| {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        })
        .collect()
}

fn random_curve(n: usize, seed: u64) -> BezierCurve {
    BezierCurve::new(random_points(n + 1, 2, seed), 2).unwrap()
}

/// A degree-7 rational curve in 3D with weights in `[0.5, 2]`.
fn rational_curve() -> BezierCurve {
    let w = vec![1.0, 0.5, 2.0, 1.5, 0.7, 1.2, 2.0, 1.0];
    BezierCurve::new_rational(random_points(8, 3, 7), w, 3).unwrap()
}

#[test]
fn vectors_alg_14_2_1() {
    let vs = vectors_with_algorithm("vectors-reduce.json", "subdiv_reduce_alg_14.2.1");
    assert!(!vs.is_empty());
    for v in vs {
        let id = v["id"].as_str().unwrap();
        let p = flat(&v["input"]["P"]);
        let curve = BezierCurve::new(p, 2).unwrap();
        let d = usize::try_from(v["params"]["d"].as_u64().unwrap()).unwrap();
        let delta = num(&v["params"]["delta"]);
        let opts = ToleranceOptions {
            measure: true,
            ..ToleranceOptions::new(Method::Perturb, d, delta, 0)
        };
        let red = reduce_to_tolerance_alg_14_2_1(&curve, &opts).unwrap();
        let intervals: Vec<f64> = red.pieces.iter().flat_map(|p| [p.start, p.end]).collect();
        assert_eq!(
            intervals,
            flat(&v["expected"]["intervals"]),
            "{id}: intervals"
        );
        let got: Vec<f64> = red
            .pieces
            .iter()
            .flat_map(|p| p.curve.points().to_vec())
            .collect();
        let tol = num(&v["tol"]);
        assert_close(id, &got, &flat(&v["expected"]["Q_pieces"]), tol);
        let total: f64 = red.report.step_bounds.iter().sum();
        let expected = num(&v["expected"]["certified_total"]);
        assert!(
            (total - expected).abs() <= tol,
            "{id}: total {total} vs {expected}"
        );
        let r = &red.report;
        assert!(r.max_error.unwrap() <= r.error_bound && r.error_bound <= total + 1e-15);
        assert!(total < delta);
    }
}

#[test]
fn vector_n_formula() {
    let v = vector("vectors-reduce.json", "N-formula-1");
    let n = usize::try_from(v["params"]["n"].as_u64().unwrap()).unwrap();
    let got = subdivision_levels(n, num(&v["input"]["normF"]), num(&v["params"]["delta"]));
    assert_eq!(
        got.unwrap(),
        usize::try_from(v["expected"]["N"].as_u64().unwrap()).unwrap()
    );
    assert_eq!(subdivision_levels(5, 0.0, 1e-3).unwrap(), 0);
    assert!(subdivision_levels(1, 1.0, 1e-3).is_err());
    assert!(subdivision_levels(5, f64::NAN, 1e-3).is_err());
    assert!(subdivision_levels(5, 1.0, 0.0).is_err());
}

/// The levels of eq. 14.2.11 against the marching placement for one degree: a uniform
/// subdivision into `2^N` pieces meets the tolerance and `2^(N-1)` does not, so the
/// longest piece that meets it is between `2^-N` and `2^-(N-1)` (the bound scales by
/// exactly `h^n`, Theorem 14.2.2); marching finds at most `2^N` and more than `2^(N-1)`
/// pieces, every one but the last at least `0.9 * 2^-N` long.
#[test]
fn n_formula_matches_one_degree_perturbation() {
    let curve = random_curve(6, 3);
    let f = curve.forward_difference();
    let nf = f.iter().map(|x| x * x).sum::<f64>().sqrt();
    for delta in [1e-2, 1e-4, 1e-6] {
        let levels = subdivision_levels(6, nf, delta).unwrap();
        let red = reduce_to_tolerance(
            &curve,
            &ToleranceOptions::new(Method::Perturb, 5, delta / super::piecewise::PIECE_SHARE, 0),
        )
        .unwrap();
        let pieces = red.report.pieces;
        assert!(pieces <= 1 << levels, "delta {delta}: {pieces} pieces");
        assert!(2 * pieces > 1 << levels, "delta {delta}: {pieces} pieces");
        let h = (-(levels as f64)).exp2();
        for p in &red.pieces[..pieces - 1] {
            assert!(p.end - p.start >= 0.9 * h, "delta {delta}: {p:?}");
        }
    }
}

/// Largest jump of derivative `j` (global parameter) at the joints of consecutive
/// segments, relative to the size of that derivative.
fn max_relative_jump(segs: &[(f64, f64, BezierCurve)], j: usize) -> f64 {
    let mut worst = 0.0f64;
    for w in segs.windows(2) {
        let (la, lb) = (w[0].1 - w[0].0, w[1].1 - w[1].0);
        let dl = &w[0].2.derivatives(1.0, j).unwrap()[j];
        let dr = &w[1].2.derivatives(0.0, j).unwrap()[j];
        let (sl, sr) = (la.powf(j as f64), lb.powf(j as f64));
        let jump = dl
            .iter()
            .zip(dr)
            .map(|(a, b)| (a / sl - b / sr).powi(2))
            .sum::<f64>()
            .sqrt();
        let size = dl
            .iter()
            .map(|a| (a / sl).powi(2))
            .sum::<f64>()
            .sqrt()
            .max(1.0);
        worst = worst.max(jump / size);
    }
    worst
}

fn check_result(red: &PiecewiseReduction, what: &str) {
    let r = &red.report;
    let me = r.max_error.unwrap();
    // The measured error is a maximum of evaluated points; allow its own rounding.
    assert!(
        me <= r.error_bound * (1.0 + 1e-9) + 1e-15,
        "{what}: {me} > {}",
        r.error_bound
    );
    assert!(r.error_bound <= r.tolerance, "{what}");
    assert!(r.pieces_bound <= r.error_bound, "{what}");
    let (m, k) = (r.degree_to, r.continuity);
    let s: &BSplineCurve = &red.spline;
    assert_eq!(s.degree(), m);
    // Knots: m+1 at each end, m-k at each interior break.
    assert_eq!(
        s.knots().len(),
        2 * (m + 1) + (m - k) * (r.pieces - 1),
        "{what}"
    );
    for p in &red.pieces[1..] {
        assert_eq!(
            cagd_core::knot_multiplicity(s.knots(), p.start),
            m - k,
            "{what}"
        );
    }
    // Joins: the pieces agree in derivatives 0..=k; the spline's own segments too.
    let pieces: Vec<_> = red
        .pieces
        .iter()
        .map(|p| (p.start, p.end, p.curve.clone()))
        .collect();
    let segs: Vec<_> = s
        .to_beziers()
        .unwrap()
        .into_iter()
        .map(|b| (b.start, b.end, b.curve))
        .collect();
    for j in 0..=k {
        // Relative jump: rounding of the operator and of the subdivision, amplified by
        // 1 / length^j for short pieces; 1e-8 is far above that and far below any real
        // kink (a missing constraint gives O(1) relative jumps).
        let jp = max_relative_jump(&pieces, j);
        assert!(jp < 1e-8, "{what}: pieces jump {jp:e} in derivative {j}");
        let js = max_relative_jump(&segs, j);
        assert!(js < 1e-8, "{what}: spline jump {js:e} in derivative {j}");
    }
}

#[test]
fn accuracy_sweep() {
    let curves = [
        ("random-9", random_curve(9, 1)),
        ("random-12", random_curve(12, 2)),
        ("rational-7", rational_curve()),
    ];
    let methods = [
        (Method::L2 { r: 0, p: 0 }, 0),
        (Method::Perturb, 0),
        (Method::L2 { r: 1, p: 1 }, 1),
        (Method::ConstrainedChebyshev { r: 1, p: 1 }, 1),
        (Method::ConstrainedChebyshev { r: 2, p: 2 }, 2),
        (Method::L2 { r: 2, p: 2 }, 2),
        (Method::Forrest, 2),
    ];
    for (name, curve) in &curves {
        for (method, k) in methods {
            for e in [2, 4, 6, 8, 10] {
                let tol = 10f64.powi(-e);
                let opts = ToleranceOptions {
                    measure: true,
                    ..ToleranceOptions::new(method, 5, tol, k)
                };
                let what = format!("{name} {} k={k} tol={tol:e}", method.name());
                let red =
                    reduce_to_tolerance(curve, &opts).unwrap_or_else(|e| panic!("{what}: {e}"));
                check_result(&red, &what);
            }
        }
    }
}

/// Target degree 3 (Hermite for k = 1): many more pieces, rational C1 merge with ~1000
/// knots at 1e-10.
#[test]
fn accuracy_sweep_cubic() {
    let curves = [
        ("random-12", random_curve(12, 2)),
        ("rational-7", rational_curve()),
    ];
    for (name, curve) in &curves {
        for (method, k) in [(Method::Perturb, 0), (Method::L2 { r: 1, p: 1 }, 1)] {
            for e in [3, 6, 10] {
                let tol = 10f64.powi(-e);
                let opts = ToleranceOptions {
                    measure: true,
                    ..ToleranceOptions::new(method, 3, tol, k)
                };
                let what = format!("{name} {} m=3 k={k} tol={tol:e}", method.name());
                let red =
                    reduce_to_tolerance(curve, &opts).unwrap_or_else(|e| panic!("{what}: {e}"));
                check_result(&red, &what);
                // The check sees real kinks: derivative k + 1 does jump (visibly at a coarse
                // tolerance; the jumps shrink with the tolerance).
                let pieces: Vec<_> = red
                    .pieces
                    .iter()
                    .map(|p| (p.start, p.end, p.curve.clone()))
                    .collect();
                if e == 3 {
                    assert!(max_relative_jump(&pieces, k + 1) > 1e-6, "{what}");
                }
            }
        }
    }
}

#[test]
fn already_low_degree_is_one_piece() {
    let cubic = random_curve(3, 5);
    let curve = cubic.elevate(6).unwrap();
    for (method, k) in [(Method::L2 { r: 1, p: 1 }, 1), (Method::Perturb, 0)] {
        let opts = ToleranceOptions {
            measure: true,
            ..ToleranceOptions::new(method, 3, 1e-9, k)
        };
        let red = reduce_to_tolerance(&curve, &opts).unwrap();
        assert_eq!(red.report.pieces, 1);
        assert_eq!(red.report.depth, 0);
        assert!(red.report.error_bound < 1e-13);
        assert_close(
            "elevated",
            red.pieces[0].curve.points(),
            cubic.points(),
            1e-12,
        );
    }
}

#[test]
fn errors() {
    let curve = random_curve(8, 9);
    let run =
        |method, m, tol, k| reduce_to_tolerance(&curve, &ToleranceOptions::new(method, m, tol, k));
    let l2 = |r| Method::L2 { r, p: r };
    for bad in [0.0, -1e-3, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            run(l2(1), 4, bad, 1),
            Err(Error::BadTolerance { .. })
        ));
    }
    assert!(matches!(
        run(l2(1), 8, 1e-3, 1),
        Err(Error::BadDegreePair { .. })
    ));
    assert!(matches!(
        run(l2(1), 9, 1e-3, 1),
        Err(Error::BadDegreePair { .. })
    ));
    // k >= m.
    assert!(matches!(
        run(l2(0), 2, 1e-3, 2),
        Err(Error::BadParameter {
            name: "continuity",
            ..
        })
    ));
    // The method does not keep order k at the ends.
    assert!(matches!(
        run(Method::Eck, 4, 1e-3, 0),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(
        run(l2(0), 4, 1e-3, 1),
        Err(Error::BadParameter { .. })
    ));
    assert!(matches!(
        run(Method::Forrest, 4, 1e-3, 2),
        Err(Error::BadParameter { .. })
    ));
    // Too many constraints for the target degree (2k + 1 > m).
    assert!(matches!(
        run(l2(2), 4, 1e-3, 2),
        Err(Error::TooManyConstraints { .. })
    ));
    // Hermite m = 2k + 1 is allowed.
    assert!(run(Method::ConstrainedChebyshev { r: 1, p: 1 }, 3, 1e-3, 1).is_ok());
    // Depth limit: the best achieved bound is reported.
    let opts = ToleranceOptions {
        max_depth: 2,
        ..ToleranceOptions::new(l2(1), 4, 1e-12, 1)
    };
    match reduce_to_tolerance(&curve, &opts) {
        Err(Error::NoConvergence {
            tolerance,
            achieved,
        }) => {
            assert_eq!(tolerance, 1e-12);
            assert!(achieved > 1e-12 && achieved.is_finite());
        }
        other => panic!("expected NoConvergence, got {other:?}"),
    }
    // Algorithm 14.2.1 only for its own setting.
    let alg = |method, k| {
        reduce_to_tolerance_alg_14_2_1(&curve, &ToleranceOptions::new(method, 4, 1e-3, k))
    };
    assert!(matches!(alg(l2(1), 1), Err(Error::ConditionNotMet { .. })));
    assert!(matches!(
        alg(Method::Perturb, 1),
        Err(Error::ConditionNotMet { .. })
    ));
    assert!(alg(Method::Perturb, 0).is_ok());
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

    /// Law: for any curve, method with C^k ends and tolerance, the sampled error of the
    /// spline is below its certified bound, the bound below the tolerance, and the joins
    /// are C^k (coordinates in [-10, 10]; the tolerance is relative to that size).
    #[test]
    fn law_bound_meets_tolerance(
        pts in cagd_testkit::points(9, 2),
        w in cagd_testkit::weights(9),
        rational in proptest::bool::ANY,
        e in 2i32..9,
        case in 0usize..4,
    ) {
        let curve = if rational {
            BezierCurve::new_rational(pts, w, 2).unwrap()
        } else {
            BezierCurve::new(pts, 2).unwrap()
        };
        let (method, m, k) = [
            (Method::Perturb, 4, 0),
            (Method::L2 { r: 1, p: 1 }, 4, 1),
            (Method::ConstrainedChebyshev { r: 1, p: 1 }, 3, 1),
            (Method::ConstrainedChebyshev { r: 2, p: 2 }, 5, 2),
        ][case];
        let tol = 10f64.powi(1 - e);
        let opts = ToleranceOptions { measure: true, ..ToleranceOptions::new(method, m, tol, k) };
        let red = reduce_to_tolerance(&curve, &opts).unwrap();
        check_result(&red, &format!("{} k={k} tol={tol:e}", method.name()));
    }
}

/// The C ABI fuzz input (session 0x544177ccc84a9a70, call 148) that ran 13.3 s: a smooth
/// degree-63 curve in 2-D reduced stepwise to degree 1 within `1.06e-6` (every piece of
/// every step reduced again, 62 steps).
#[allow(
    clippy::excessive_precision,
    reason = "17 significant digits as gdb printed the fuzz input: kept as read"
)]
const FUZZ_DEGREE_63: [f64; 128] = [
    -0.1597580533548093,
    0.97922550091989802,
    -0.18013734513965174,
    0.94112352953192702,
    -0.19768186791253181,
    0.90497835088803147,
    -0.21520004867254369,
    0.86923898719719828,
    -0.23161111614507987,
    0.83760446744150918,
    -0.24602063945424696,
    0.80689333127777108,
    -0.25635276022022779,
    0.77843154406719606,
    -0.2641593796507356,
    0.75150269025632876,
    -0.27239322597657672,
    0.72471253343701481,
    -0.28183535693847872,
    0.69852913554238361,
    -0.28996293134369283,
    0.67447730943276085,
    -0.29451227850424727,
    0.654404159596505,
    -0.29550528823688571,
    0.63805028634571714,
    -0.29440225116910651,
    0.62285342970419755,
    -0.29287468230302183,
    0.60635325674701424,
    -0.29177713389106658,
    0.5877901873083955,
    -0.29130162952318445,
    0.5677830362458941,
    -0.29249178773020357,
    0.54787257830683589,
    -0.29717575513511119,
    0.52819439162946302,
    -0.30393786275157858,
    0.50877018228738613,
    -0.31156012020543306,
    0.4900627615542742,
    -0.31730295119898416,
    0.48277706340196264,
    -0.32513386519542792,
    0.48110034378783562,
    -0.31955672108440669,
    0.50630587092864454,
    -0.33254707435658676,
    0.50432285876236249,
    -0.33813414562677263,
    0.52664072104798554,
    -0.40057490069161,
    0.44400264680235751,
    -0.34599606321928428,
    0.54358106016326635,
    -0.41913977095890664,
    0.4624027158628235,
    -0.32244341698467804,
    0.61384251125586153,
    -0.37821205286922477,
    0.3131121625136043,
    -0.4411732770633911,
    0.74756365169738215,
    -0.42266171907348138,
    0.62640091576522106,
    -0.40887132656171482,
    0.52373806608983786,
    -0.3048272702345507,
    0.6791507646436663,
    -0.48014748173874011,
    0.43408653121499818,
    -0.41563699128751119,
    0.59770514673726793,
    -0.43579191354060359,
    0.53261445757195935,
    -0.38754924884991671,
    0.61681669736243183,
    -0.4217091620303795,
    0.61703195090229035,
    -0.43478209999950312,
    0.64880992416084204,
    -0.45644936246486489,
    0.62569644988411299,
    -0.4625271222729348,
    0.60650998206801576,
    -0.4653711480432054,
    0.59078453515149032,
    -0.46112142512646465,
    0.59614605268270882,
    -0.45849136826341236,
    0.61113294835878851,
    -0.46248031311203935,
    0.62916950051074394,
    -0.47670674216809189,
    0.64541979063911292,
    -0.49988175458514328,
    0.65914871551783949,
    -0.52831466917099767,
    0.66879244912093516,
    -0.55795765010585863,
    0.67483596260831402,
    -0.58560320933000409,
    0.68128280520672013,
    -0.61003108311065413,
    0.69093408777837728,
    -0.6326673139392901,
    0.70213847790068795,
    -0.65572978152368377,
    0.7122346177493587,
    -0.67926091645456299,
    0.72074437600585572,
    -0.70102016462479944,
    0.72799994325622808,
    -0.71923523638394327,
    0.73309476656208183,
    -0.73507774521586011,
    0.73532117555322007,
    -0.75205241953658364,
    0.7362082123662631,
    -0.77258640944225487,
    0.7367792472015593,
    -0.79741848731532872,
    0.73238939599574859,
    -0.82189520767217106,
    0.72732402010436303,
    -0.84467925869390226,
    0.71990033697794575,
];

#[test]
fn stepwise_fuzz_degree_63_is_measured_within_bounded_work() {
    // 9 232 pieces: the reduction is light, its measurement (576 samples of the degree-63
    // curve per piece) took 13 s; now fewer samples per piece, and the measured error still
    // close below the certified bound.
    let curve = BezierCurve::new(FUZZ_DEGREE_63.to_vec(), 2).unwrap();
    let opts = ToleranceOptions {
        measure: true,
        ..ToleranceOptions::new(Method::Perturb, 1, 1.06048e-06, 0)
    };
    let red = reduce_to_tolerance_alg_14_2_1(&curve, &opts).unwrap();
    let r = &red.report;
    let e = r.max_error.unwrap();
    assert!(r.pieces > 9000 && e <= r.error_bound, "{e:e}");
    // Against an independent dense sampling (2^16 parameters): the measurement finds at
    // least what it finds.
    let dense = (0..=1u32 << 16)
        .map(|i| {
            let t = f64::from(i) / f64::from(1u32 << 16);
            let (a, b) = (curve.eval(t), red.spline.eval(t).unwrap());
            a.iter()
                .zip(&b)
                .map(|(x, y)| (x - y) * (x - y))
                .sum::<f64>()
                .sqrt()
        })
        .fold(0.0f64, f64::max);
    assert!(e >= dense * (1.0 - 1e-6), "{e:e} below the dense {dense:e}");
    let samples = super::piecewise::samples_per_piece(63, 1, r.pieces);
    assert!((super::piecewise::MIN_SAMPLES..8 * 64 + 64).contains(&samples));
    assert!(
        samples == super::piecewise::MIN_SAMPLES
            || samples * r.pieces * (64 * 64 + 4 + 64) <= crate::MAX_TOLERANCE_WORK
    );
    // Few pieces: the full count.
    assert_eq!(super::piecewise::samples_per_piece(63, 1, 10), 8 * 64 + 64);
}

#[test]
fn stepwise_work_is_bounded() {
    // Pieces split at a high degree are reduced again at every later step: a random
    // degree-24 curve in 8-D to degree 1 within 1e-9 would reduce millions of pieces.
    let curve = BezierCurve::new(random_points(25, 8, 5), 8).unwrap();
    let opts = ToleranceOptions::new(Method::Perturb, 1, 1e-9, 0);
    match reduce_to_tolerance_alg_14_2_1(&curve, &opts) {
        Err(Error::ConditionNotMet {
            eq: "tolerance",
            why,
        }) => {
            assert!(why.contains("too much work"), "{why}");
        }
        other => panic!(
            "{:?}",
            other.map(|r| (r.report.pieces, r.report.error_bound))
        ),
    }
}
