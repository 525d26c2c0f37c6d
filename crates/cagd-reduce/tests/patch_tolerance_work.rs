//! Bounded work of the patch reductions to a tolerance (issue 18; the CLI fuzzer's inputs
//! `crates/cagd-cli/tests/data/fuzz/tensor-*.json`): a direction that keeps its degree is
//! not subdivided, the grid grows one direction at a time, and the accepted pieces are
//! measured within a node budget with the largest errors maximised in full.

use cagd_core::{TensorPatch, tensor_patch_distance};
use cagd_reduce::{
    MAX_TOLERANCE_PIECES, Method, PatchOptions, TensorMethod, TensorPiece,
    reduce_tensor_to_tolerance,
};
use cagd_testkit::bench::random_input;

fn opts(m: Method) -> PatchOptions {
    PatchOptions {
        measure: true,
        ..PatchOptions::new(TensorMethod::Curves { u: m, v: m })
    }
}

/// The sub-patch of `p` on a piece's domain (independent of the reducer's bisections).
fn sub_patch(p: &TensorPatch, piece: &TensorPiece) -> TensorPatch {
    let ((u0, u1), (v0, v1)) = (piece.u, piece.v);
    let a = p.subdivide_u(u1).unwrap().0;
    let a = a.subdivide_u(u0 / u1).unwrap().1;
    let b = a.subdivide_v(v1).unwrap().0;
    b.subdivide_v(v0 / v1).unwrap().1
}

/// Every piece: bound within the tolerance and not below its measured error; the pieces
/// tile the unit square; a sample of pieces measured again against the input.
fn check(p: &TensorPatch, pieces: &[TensorPiece], tol: f64) {
    let mut area = 0.0;
    for piece in pieces {
        let r = &piece.reduction.report;
        let measured = r.max_error.unwrap();
        assert!(r.error_bound <= tol, "{} > {tol}", r.error_bound);
        assert!(measured <= r.error_bound, "{measured} > {}", r.error_bound);
        area += (piece.u.1 - piece.u.0) * (piece.v.1 - piece.v.0);
    }
    assert!((area - 1.0).abs() < 1e-12, "area {area}");
    let step = (pieces.len() / 7).max(1);
    for piece in pieces.iter().step_by(step) {
        let d = tensor_patch_distance(&sub_patch(p, piece), &piece.reduction.patch).unwrap();
        assert!(d <= piece.reduction.report.error_bound, "{d}");
    }
}

/// `tests/data/fuzz/tensor-1e6-scale-pinv-ends-tol-1e3.json`: degree (1, 3) to (1, 1)
/// within 1e3 at coordinates ~5e6. Only `v` is reduced: the pieces are strips over the
/// whole `u` range (it was cut into 65 536 squares, 7 s in a release build).
#[test]
fn a_direction_that_keeps_its_degree_is_not_split() {
    let pts = [
        [-1797000.0, 3828000.0, 1040999.9999999999],
        [4757000.0, -3752000.0, 3414000.0],
        [2635000.0, 4104000.0, 3333000.0],
        [3646000.0, 975000.0, -3352000.0],
        [-1000000.0, -4666000.0, 4481000.0],
        [4998000.0, 4018000.0, 1593000.0],
        [-1230000.0, -2299000.0, 2905000.0],
        [1992000.0, 3688000.0, 4712000.0],
    ];
    let p = TensorPatch::new(pts.concat(), 1, 3, 3).unwrap();
    let pieces =
        reduce_tensor_to_tolerance(&p, (1, 1), 1e3, &opts(Method::GeneralizedInverseEnds)).unwrap();
    assert!(pieces.len() > 1 && pieces.len() <= 256, "{}", pieces.len());
    assert!(pieces.iter().all(|x| x.u == (0.0, 1.0)));
    check(&p, &pieces, 1e3);
}

fn bicubic() -> TensorPatch {
    // `tests/data/fuzz/tensor-pinv-16384-pieces.json`: one control point far out.
    let pts = [
        [-0.286, 0.047, 4.501],
        [-2.601, 2.868, 2.43],
        [-2.703, 0.259, 2.852],
        [4.092, 3.381, 2.484],
        [4.191, 0.844, 2.829],
        [-1.361, -3.736, 3.937],
        [-2.742, 3.755, -3.36],
        [1.494, -4.274, 1.454],
        [-1.755, -1.512, -1.44],
        [0.399, -1.0, 1.74],
        [3.857, -0.808, 3.052],
        [2.882, 4.35, -4.0],
        [-1.0, 4.236, -4.535],
        [-4.984, 0.0, -0.018],
        [0.519, 2.0, -1.0],
        [161.0, -3.166, 3.679],
    ];
    TensorPatch::new(pts.concat(), 3, 3, 3).unwrap()
}

/// `tests/data/fuzz/tensor-pinv-16384-pieces.json` to (1, 1) by `pinv` (within 1e-2: 16 384
/// square pieces measured in full took 8-18 s; here 4e-2 to keep the debug test short):
/// the answer is certified, the largest
/// measured error is maximised in full (it matches the tight bound), and no piece claims
/// more than its bound.
#[test]
fn many_pieces_are_measured_within_the_budget() {
    let p = bicubic();
    let tol = 4e-2;
    let pieces =
        reduce_tensor_to_tolerance(&p, (1, 1), tol, &opts(Method::GeneralizedInverse)).unwrap();
    assert!(pieces.len() >= 512 && pieces.len() <= MAX_TOLERANCE_PIECES);
    check(&p, &pieces, tol);
    // The piece of largest bound, measured again in full: the reported maximum over all
    // pieces is at least that (pass 2 maximises the largest sampled errors in full).
    let worst = pieces
        .iter()
        .max_by(|a, b| {
            let e = |x: &TensorPiece| x.reduction.report.error_bound;
            e(a).total_cmp(&e(b))
        })
        .unwrap();
    let full = tensor_patch_distance(&sub_patch(&p, worst), &worst.reduction.patch).unwrap();
    let reported = pieces
        .iter()
        .filter_map(|x| x.reduction.report.max_error)
        .fold(0.0, f64::max);
    assert!(reported >= full * (1.0 - 1e-9), "{reported} < {full}");
}

/// A tolerance out of reach within the piece cap is refused with the bound reached, not
/// answered after minutes.
#[test]
fn out_of_reach_is_refused() {
    match reduce_tensor_to_tolerance(&bicubic(), (1, 1), 1e-6, &opts(Method::GeneralizedInverse)) {
        Err(cagd_core::Error::NoConvergence {
            tolerance,
            achieved,
        }) => {
            assert_eq!(tolerance, 1e-6);
            assert!(achieved > 1e-6 && achieved.is_finite());
        }
        other => panic!("expected NoConvergence, got {:?}", other.map(|p| p.len())),
    }
}

/// The C ABI fuzz run's 199 s call (session 0xff98dcc0cc1a0e5a): a random degree-36
/// triangle to degree 3 within 8.7e-4 by L2. Its bound falls like `2^-4L`, so it would need
/// level 8 (87 381 reductions and 21 845 blossom splits at degree 36); the work cap priced by
/// degree stops it after a few levels with the bound reached.
#[test]
fn a_high_degree_triangle_is_refused_by_the_work_cap() {
    use cagd_core::TriPatch;
    use cagd_reduce::{PatchConstraint, TriMethod, TriOptions, reduce_triangle_to_tolerance};
    let t = TriPatch::new(random_input(703 * 3, 7), 36, 3).unwrap();
    let opts = TriOptions::new(TriMethod::L2(PatchConstraint::None));
    match reduce_triangle_to_tolerance(&t, 3, 8.7e-4, &opts) {
        Err(cagd_core::Error::NoConvergence {
            tolerance,
            achieved,
        }) => {
            assert_eq!(tolerance, 8.7e-4);
            assert!(achieved > tolerance && achieved.is_finite(), "{achieved}");
        }
        other => panic!("expected NoConvergence, got {other:?}"),
    }
}

/// The same at a reachable tolerance still answers, certified, at a level within the cap.
#[test]
fn a_high_degree_triangle_within_reach_answers() {
    use cagd_core::{TriPatch, tri_patch_distance};
    use cagd_reduce::{PatchConstraint, TriMethod, TriOptions, reduce_triangle_to_tolerance};
    let t = TriPatch::new(random_input(703 * 3, 7), 36, 3).unwrap();
    let opts = TriOptions::new(TriMethod::L2(PatchConstraint::None));
    let whole = cagd_reduce::reduce_triangle(&t, 3, &opts)
        .unwrap()
        .report
        .error_bound;
    let tol = whole * 0.5;
    let pieces = reduce_triangle_to_tolerance(&t, 3, tol, &opts).unwrap();
    assert!(pieces.len() >= 4);
    for p in pieces.iter().step_by(5) {
        assert!(p.reduction.report.error_bound <= tol);
        let [a, b, c] = p.vertices;
        let src = t.reparametrize(a, b, c).unwrap();
        let d = tri_patch_distance(&src, &p.reduction.patch).unwrap();
        assert!(d <= p.reduction.report.error_bound, "{d}");
    }
}

/// A degree-(40, 40) tensor patch to (3, 3) within a tolerance out of reach: the work cap
/// (each cell's reduction subdivides rows and columns for its bound) refuses it by name
/// instead of reducing up to 65 536 cells of 1 681 points.
#[test]
fn a_high_degree_tensor_patch_is_refused_by_the_work_cap() {
    let p = TensorPatch::new(random_input(41 * 41 * 3, 11), 40, 40, 3).unwrap();
    match reduce_tensor_to_tolerance(&p, (3, 3), 1e-9, &opts(Method::L2 { r: 0, p: 0 })) {
        Err(cagd_core::Error::NoConvergence { achieved, .. }) => {
            assert!(achieved > 1e-9 && achieved.is_finite(), "{achieved}");
        }
        other => panic!("expected NoConvergence, got {:?}", other.map(|v| v.len())),
    }
}
