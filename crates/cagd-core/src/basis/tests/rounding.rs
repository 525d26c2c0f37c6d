//! f64 round trips (measured limits and an a-priori bound) and proptest laws.

use super::super::*;
use crate::{MAX_DEGREE, kernel, wsgb_terms};
use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;

const EPS: f64 = f64::EPSILON;

/// The strict tolerance of the brief.
const ROUND_TRIP_TOL: f64 = 1e-12;

/// Largest degree for which the f64 round trip meets [`ROUND_TRIP_TOL`], per basis and
/// direction: (forward `from * (to * c)`, reverse `to * (from * b)`). Measured with margin
/// (examples/basis_accuracy.rs); beyond, the conditioning of the basis change (not the
/// matrices, which are exact rounded once) takes over and `round_trip_within_condition_bound`
/// is the law.
fn strict_degrees(basis: Basis) -> (usize, usize) {
    match basis {
        Basis::Power => (8, 8),
        Basis::Chebyshev => (14, 64),
        Basis::Legendre => (15, 64),
        Basis::SaidBall => (50, 50),
        Basis::WangBall => (16, 30),
        _ => (0, 0),
    }
}

fn xorshift(state: &mut u64) -> f64 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    (*state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
}

fn inf_norm(m: &DMatrix<f64>) -> f64 {
    m.row_iter()
        .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max)
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// Relative round-trip error `max|second * (first * v) - v| / max|v|`.
fn round_trip(first: &DMatrix<f64>, second: &DMatrix<f64>, v: &[f64]) -> f64 {
    let mid = convert_points(first, v, 1).unwrap();
    let back = convert_points(second, &mid, 1).unwrap();
    let err = v
        .iter()
        .zip(&back)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    err / max_abs(v)
}

#[test]
fn round_trip_within_1e_12_in_the_measured_range() {
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    for basis in [
        Basis::Power,
        Basis::Chebyshev,
        Basis::Legendre,
        Basis::SaidBall,
        Basis::WangBall,
    ] {
        let (fwd, rev) = strict_degrees(basis);
        for n in 0..=fwd.max(rev) {
            let to = to_bernstein(basis, n).unwrap();
            let from = from_bernstein(basis, n).unwrap();
            for _ in 0..8 {
                let v: Vec<f64> = (0..=n).map(|_| xorshift(&mut seed)).collect();
                if n <= fwd {
                    let e = round_trip(&to, &from, &v);
                    assert!(e <= ROUND_TRIP_TOL, "{basis:?} n={n} forward {e:e}");
                }
                if n <= rev {
                    let e = round_trip(&from, &to, &v);
                    assert!(e <= ROUND_TRIP_TOL, "{basis:?} n={n} reverse {e:e}");
                }
            }
        }
    }
}

/// A-priori bound for every degree: with each matrix entry rounded once and each product
/// accumulated in f64, `|c' - c|_inf <= 2 gamma_(n+2) |to|_inf |from|_inf |c|_inf` (1.01
/// slack for gamma vs (n+2) eps and the f64 norms), in both directions.
#[test]
fn round_trip_within_condition_bound() {
    let mut seed = 0x1234_5678_9abc_def1u64;
    for n in [1usize, 4, 9, 16, 25, 33, 40, 48, 57, 64] {
        for basis in all_bases_f64(n) {
            let to = to_bernstein(basis, n).unwrap();
            let from = from_bernstein(basis, n).unwrap();
            let bound = 2.1 * (n + 2) as f64 * EPS * inf_norm(&to) * inf_norm(&from);
            for _ in 0..4 {
                let v: Vec<f64> = (0..=n).map(|_| xorshift(&mut seed)).collect();
                let (f, r) = (round_trip(&to, &from, &v), round_trip(&from, &to, &v));
                assert!(
                    f <= bound && r <= bound,
                    "{basis:?} n={n}: {f:e} {r:e} > {bound:e}"
                );
            }
        }
    }
}

fn all_bases_f64(n: usize) -> Vec<Basis> {
    let mut v = vec![Basis::Power, Basis::Chebyshev, Basis::Legendre];
    v.extend(
        super::sample_orders(n)
            .into_iter()
            .map(|l| Basis::Wsgb { l }),
    );
    v
}

fn basis_of(index: usize, n: usize) -> Basis {
    match index % 4 {
        0 => Basis::Power,
        1 => Basis::Chebyshev,
        2 => Basis::Legendre,
        _ => Basis::Wsgb {
            l: (index / 4) % (wsgb_max_l(n) + 1),
        },
    }
}

/// Direct f64 value of sum_k c_k phi_k(t).
fn direct_value(basis: Basis, n: usize, c: &[f64], t: f64) -> f64 {
    let x = 2.0 * t - 1.0;
    let (mut p0, mut p1) = (1.0, x); // Legendre recurrence state
    let terms = match basis {
        Basis::Wsgb { l } => wsgb_terms(n, l).unwrap(),
        _ => Vec::new(),
    };
    let mut sum = 0.0;
    for (k, ck) in c.iter().enumerate() {
        let phi = match basis {
            Basis::Power => kernel::powu(t, k),
            Basis::Chebyshev => (k as f64 * x.acos()).cos(),
            Basis::Legendre => {
                if k >= 2 {
                    let kf = (k - 1) as f64;
                    let p2 = ((2.0 * kf + 1.0) * x * p1 - kf * p0) / (kf + 1.0);
                    p0 = std::mem::replace(&mut p1, p2);
                }
                if k == 0 { 1.0 } else { p1 }
            }
            _ => terms[k].eval(t),
        };
        sum += ck * phi;
    }
    sum
}

proptest! {
    // Each case at degree 64 costs four exact 65 x 65 matrix-vector products.
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Exact laws for every degree: from * (to * c) == c and to * (from * b) == b.
    #[test]
    fn exact_round_trip_of_integer_vectors(
        n in 0usize..=MAX_DEGREE,
        idx in 0usize..64,
        ints in prop::collection::vec(-1000i64..1000, MAX_DEGREE + 1),
    ) {
        let basis = basis_of(idx, n);
        let v: Vec<BigRational> = ints[..=n].iter().map(|&i| BigRational::from_integer(BigInt::from(i))).collect();
        let to = to_bernstein_exact(basis, n).unwrap();
        let from = from_bernstein_exact(basis, n).unwrap();
        prop_assert_eq!(&from.mul_vec(&to.mul_vec(&v).unwrap()).unwrap(), &v);
        prop_assert_eq!(&to.mul_vec(&from.mul_vec(&v).unwrap()).unwrap(), &v);
    }
}

proptest! {
    /// The Bézier curve of `to * c` has the values of sum_k c_k phi_k(t).
    #[test]
    fn conversion_preserves_values(
        n in 0usize..=20,
        idx in 0usize..64,
        c in prop::collection::vec(-1.0f64..1.0, 21),
        t in 0.0f64..=1.0,
    ) {
        let basis = basis_of(idx, n);
        let c = &c[..=n];
        let m = to_bernstein(basis, n).unwrap();
        let b = convert_points(&m, c, 1).unwrap();
        let mut work = vec![0.0; n + 1];
        let mut out = [0.0];
        kernel::de_casteljau(&b, 1, t, &mut work, &mut out);
        let direct = direct_value(basis, n, c, t);
        let weighted: f64 = c.iter().enumerate().map(|(k, x)| ((k * k) as f64 + 1.0) * x.abs()).sum();
        let tol = EPS * (4.0 * (n + 2) as f64 * inf_norm(&m) * max_abs(c) + 4.0 * weighted);
        prop_assert!((out[0] - direct).abs() <= tol, "{:?} n={} t={}: {} vs {} (tol {:e})", basis, n, t, out[0], direct, tol);
    }

    /// convert_points is linear and works coordinate-wise.
    #[test]
    fn convert_points_is_linear(
        n in 0usize..=MAX_DEGREE,
        idx in 0usize..64,
        x in prop::collection::vec(-1.0f64..1.0, 2 * MAX_DEGREE + 2),
        y in prop::collection::vec(-1.0f64..1.0, 2 * MAX_DEGREE + 2),
    ) {
        let basis = basis_of(idx, n);
        let m = from_bernstein(basis, n).unwrap();
        let (x, y) = (&x[..2 * (n + 1)], &y[..2 * (n + 1)]);
        let sum: Vec<f64> = x.iter().zip(y).map(|(a, b)| a + 2.0 * b).collect();
        let (cx, cy, cs) = (
            convert_points(&m, x, 2).unwrap(),
            convert_points(&m, y, 2).unwrap(),
            convert_points(&m, &sum, 2).unwrap(),
        );
        let tol = 8.0 * (n + 2) as f64 * EPS * inf_norm(&m) * 3.0;
        for i in 0..cs.len() {
            prop_assert!((cs[i] - cx[i] - 2.0 * cy[i]).abs() <= tol);
        }
        // Coordinate 1 alone equals the 1-D conversion of the second coordinates.
        let ys: Vec<f64> = y.iter().skip(1).step_by(2).copied().collect();
        let c1 = convert_points(&m, &ys, 1).unwrap();
        for i in 0..=n {
            prop_assert_eq!(c1[i], cy[2 * i + 1]);
        }
    }
}
