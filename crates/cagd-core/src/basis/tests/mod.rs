use super::*;
use crate::{BallTerm, MAX_DEGREE, binomial, kernel, wsgb_terms};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

mod rounding;
mod spec;

/// Degrees used by the exact checks (a spread up to MAX_DEGREE, built once each).
const DEGREES: [usize; 16] = [0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 16, 21, 32, 47, 63, 64];

fn named_bases() -> [Basis; 5] {
    [
        Basis::Power,
        Basis::Chebyshev,
        Basis::Legendre,
        Basis::SaidBall,
        Basis::WangBall,
    ]
}

/// WSGB orders to check at degree n: all of them up to n = 16, then the ends, the middle and
/// their neighbours (keeps each test within a few seconds).
pub(super) fn sample_orders(n: usize) -> Vec<usize> {
    let max = wsgb_max_l(n);
    if n <= 16 {
        return (0..=max).collect();
    }
    let mut v = vec![0, 1, max / 2, max - 1, max];
    v.dedup();
    v
}

/// Every named basis of degree n plus the sampled WSGB orders.
fn all_bases(n: usize) -> Vec<Basis> {
    let mut v = named_bases().to_vec();
    v.extend(sample_orders(n).into_iter().map(|l| Basis::Wsgb { l }));
    v
}

fn q(p: i64, d: i64) -> BigRational {
    BigRational::new(p.into(), d.into())
}

/// The k-th basis polynomial of `basis` (degree n) at an exact rational t, computed
/// independently of the matrices: powers, the three-term recurrences, or the §9.1 terms.
fn basis_value_exact(basis: Basis, n: usize, k: usize, t: &BigRational) -> BigRational {
    let x = t * q(2, 1) - q(1, 1);
    match basis {
        Basis::Power => num_traits::pow(t.clone(), k),
        Basis::Chebyshev | Basis::Legendre => {
            let (mut p0, mut p1) = (BigRational::one(), x.clone());
            if k == 0 {
                return p0;
            }
            for j in 1..k {
                let jj = BigRational::from_integer(BigInt::from(j));
                let p2 = if basis == Basis::Chebyshev {
                    q(2, 1) * &x * &p1 - &p0
                } else {
                    // (j+1) P_{j+1} = (2j+1) x P_j - j P_{j-1}
                    ((&jj * q(2, 1) + q(1, 1)) * &x * &p1 - &jj * &p0) / (jj + q(1, 1))
                };
                p0 = std::mem::replace(&mut p1, p2);
            }
            p1
        }
        _ => {
            let Ok(Basis::Wsgb { l }) = basis.canonical(n) else {
                panic!("not a Ball basis");
            };
            let term = wsgb_terms(n, l).unwrap()[k];
            BigRational::from_integer(BigInt::from(term.coef))
                * num_traits::pow(t.clone(), term.a)
                * num_traits::pow(q(1, 1) - t, term.b)
        }
    }
}

#[test]
fn columns_are_the_basis_polynomials_exactly() {
    let ts = [q(0, 1), q(1, 1), q(1, 3), q(2, 7), q(1, 2), q(9, 10)];
    for n in DEGREES {
        for basis in named_bases().into_iter().chain([Basis::Wsgb { l: n / 4 }]) {
            let m = to_bernstein_exact(basis, n).unwrap();
            // All points up to degree 16, two beyond (each costs (n+1)^2 big products).
            let ts = if n <= 16 { &ts[..] } else { &ts[2..4] };
            for t in ts {
                let bern: Vec<BigRational> = (0..=n)
                    .map(|j| {
                        BigRational::from_integer(BigInt::from(binomial(n, j)))
                            * num_traits::pow(t.clone(), j)
                            * num_traits::pow(q(1, 1) - t, n - j)
                    })
                    .collect();
                for k in 0..=n {
                    let via_matrix =
                        (0..=n).fold(BigRational::zero(), |acc, j| acc + &m[(j, k)] * &bern[j]);
                    assert_eq!(
                        via_matrix,
                        basis_value_exact(basis, n, k, t),
                        "{basis:?} n={n} k={k} t={t}"
                    );
                }
            }
        }
    }
}

#[test]
fn exact_round_trips_are_the_identity() {
    for n in DEGREES {
        for basis in all_bases(n) {
            let to = to_bernstein_exact(basis, n).unwrap();
            let from = from_bernstein_exact(basis, n).unwrap();
            assert!(from.mul(&to).unwrap().is_identity(), "{basis:?} n={n}");
            assert!(to.mul(&from).unwrap().is_identity(), "{basis:?} n={n}");
        }
    }
}

/// f64 summation bound: |sum_j m_jk B_j(t) - exact| <= gamma * sum_j |m_jk| B_j(t), plus the
/// error of the direct evaluation (cos/acos: about k^2 ulp near the ends; recurrences: k ulp).
#[test]
fn f64_columns_match_direct_evaluation() {
    let eps = f64::EPSILON;
    let mut bern = vec![0.0; MAX_DEGREE + 1];
    for n in [0usize, 1, 2, 5, 9, 16, 24, 30] {
        for basis in all_bases(n) {
            let m = to_bernstein(basis, n).unwrap();
            let canon = basis.canonical(n).unwrap();
            for s in 0..=200 {
                let t = f64::from(s) / 200.0;
                kernel::bernstein_all(n, t, &mut bern[..=n]);
                for k in 0..=n {
                    let (mut v, mut mag) = (0.0, 0.0);
                    for j in 0..=n {
                        v += m[(j, k)] * bern[j];
                        mag += (m[(j, k)] * bern[j]).abs();
                    }
                    let x = 2.0 * t - 1.0;
                    let direct = match canon {
                        Basis::Power => kernel::powu(t, k),
                        Basis::Chebyshev => (k as f64 * x.acos()).cos(),
                        Basis::Legendre => legendre_f64(k, x),
                        Basis::Wsgb { l } => wsgb_terms(n, l).unwrap()[k].eval(t),
                        _ => unreachable!("canonical"),
                    };
                    let kk = (k * k) as f64;
                    let tol = eps * (4.0 * (n + 2) as f64 * mag + 4.0 * kk + 4.0);
                    assert!(
                        (v - direct).abs() <= tol,
                        "{basis:?} n={n} k={k} t={t}: {v} vs {direct} (tol {tol:e})"
                    );
                }
            }
        }
    }
}

fn legendre_f64(k: usize, x: f64) -> f64 {
    let (mut p0, mut p1) = (1.0, x);
    if k == 0 {
        return 1.0;
    }
    for j in 1..k {
        let jf = j as f64;
        let p2 = ((2.0 * jf + 1.0) * x * p1 - jf * p0) / (jf + 1.0);
        p0 = p1;
        p1 = p2;
    }
    p1
}

#[test]
fn ball_bases_partition_unity_exactly_for_every_degree_and_order() {
    for n in 0..=MAX_DEGREE {
        for l in sample_orders(n) {
            let m = to_bernstein_exact(Basis::Wsgb { l }, n).unwrap();
            for k in 0..=n {
                let row_sum = m.row(k).iter().fold(BigRational::zero(), |a, x| a + x);
                assert!(row_sum.is_one(), "n={n} l={l} row {k}");
            }
        }
    }
}

/// Said–Ball and Wang–Ball by their classical definitions, independent of §9.1.
#[test]
fn said_and_wang_ball_match_their_classical_definitions() {
    for n in 0..=MAX_DEGREE {
        let m = n / 2;
        let said = wsgb_terms(n, 0).unwrap();
        let wang = wsgb_terms(n, wsgb_max_l(n)).unwrap();
        for i in 0..n.div_ceil(2) {
            let s = BallTerm {
                coef: binomial(m + i, i),
                a: i,
                b: m + 1,
            };
            assert_eq!(said[i], s, "Said n={n} i={i}");
            // 2^i u^i (1-u)^(i+2), except 2^m u^m (1-u)^(m+1) just before the middle (n odd).
            let w = BallTerm {
                coef: 1 << i,
                a: i,
                b: (i + 2).min(n - i),
            };
            assert_eq!(wang[i], w, "Wang n={n} i={i}");
        }
        if n % 2 == 0 {
            assert_eq!(
                said[m],
                BallTerm {
                    coef: binomial(n, m),
                    a: m,
                    b: m
                }
            );
            assert_eq!(
                wang[m],
                BallTerm {
                    coef: 1 << m,
                    a: m,
                    b: m
                }
            );
        }
    }
}

/// SPEC-reduce §9.1: beta_i(n, L) = 2u(1-u) beta_{i-1}(n-2, L-1) for L >= 1.
#[test]
fn wsgb_peels_one_layer_per_order() {
    for n in 4..=MAX_DEGREE {
        for l in 1..=wsgb_max_l(n) {
            let big = wsgb_terms(n, l).unwrap();
            let small = wsgb_terms(n - 2, l - 1).unwrap();
            assert_eq!(
                big[0],
                BallTerm {
                    coef: 1,
                    a: 0,
                    b: 2
                }
            );
            assert_eq!(
                big[n],
                BallTerm {
                    coef: 1,
                    a: 2,
                    b: 0
                }
            );
            for i in 1..n {
                let s = small[i - 1];
                assert_eq!(
                    big[i],
                    BallTerm {
                        coef: 2 * s.coef,
                        a: s.a + 1,
                        b: s.b + 1
                    }
                );
            }
        }
    }
}

/// SPEC-reduce §9.2: the u^n coefficient of a WSGB curve.
#[test]
fn wsgb_leading_coefficient_matches_9_2() {
    for n in 1..=MAX_DEGREE {
        let power = from_bernstein_exact(Basis::Power, n).unwrap();
        let m = n / 2;
        for l in sample_orders(n) {
            // Row n of (Bernstein -> power) * (WSGB -> Bernstein).
            let ball = to_bernstein_exact(Basis::Wsgb { l }, n).unwrap();
            let last = ExactMatrix::from_fn(1, n + 1, |_, k| power[(n, k)].clone());
            let lead = last.mul(&ball).unwrap();
            let mut expected = vec![BigInt::zero(); n + 1];
            let sign = |e: usize, v: BigInt| if e % 2 == 0 { v } else { -v };
            if n % 2 == 1 {
                let k = BigInt::from((1u128 << l) * binomial(2 * m - 2 * l, m - l));
                expected[m + 1] = sign(m, k.clone());
                expected[m] = -sign(m, k);
            } else {
                let k = BigInt::from((1u128 << l) * binomial(2 * m - 2 * l - 1, m - l - 1));
                expected[m - 1] = sign(m + 1, k.clone());
                expected[m] = sign(m + 1, k.clone()) * -2;
                expected[m + 1] = sign(m + 1, k);
            }
            for (i, e) in expected.into_iter().enumerate() {
                assert_eq!(
                    lead[(0, i)],
                    BigRational::from_integer(e),
                    "n={n} l={l} i={i}"
                );
            }
        }
    }
}

#[test]
fn out_of_range_inputs_are_errors() {
    for basis in named_bases() {
        assert!(matches!(
            to_bernstein(basis, MAX_DEGREE + 1),
            Err(Error::DegreeOutOfRange {
                degree: 65,
                max: 64
            })
        ));
        assert!(from_bernstein_exact(basis, 1000).is_err());
    }
    assert!(matches!(
        to_bernstein(Basis::Wsgb { l: 3 }, 7),
        Err(Error::ConditionNotMet { .. })
    ));
    assert!(matches!(
        from_bernstein(Basis::Wsgb { l: 1 }, 3),
        Err(Error::ConditionNotMet { .. })
    ));
    assert!(to_bernstein(Basis::Wsgb { l: 2 }, 7).is_ok());
    assert!(to_bernstein(Basis::Wsgb { l: 0 }, 0).is_ok());
    assert!(wsgb_terms(6, 3).is_err());
}

#[test]
fn matrices_are_cached_and_ball_aliases_shared() {
    let a = to_bernstein_exact(Basis::SaidBall, 9).unwrap();
    let b = to_bernstein_exact(Basis::Wsgb { l: 0 }, 9).unwrap();
    assert!(Arc::ptr_eq(&a, &b));
    let c = from_bernstein(Basis::WangBall, 9).unwrap();
    let d = from_bernstein(Basis::Wsgb { l: 3 }, 9).unwrap();
    assert!(Arc::ptr_eq(&c, &d));
    assert!(!Arc::ptr_eq(
        &c,
        &from_bernstein(Basis::SaidBall, 9).unwrap()
    ));
}

#[test]
fn convert_points_checks_its_input() {
    let m = to_bernstein(Basis::Power, 2).unwrap();
    assert!(matches!(
        convert_points(&m, &[1.0; 4], 2),
        Err(Error::LengthMismatch { .. })
    ));
    assert!(matches!(
        convert_points(&m, &[1.0; 6], 0),
        Err(Error::ZeroDimension)
    ));
    assert!(matches!(
        convert_points(&m, &[1.0, f64::NAN, 0.0], 1),
        Err(Error::NonFinite { index: 1, .. })
    ));
    // 2-D: (t, t^2) in the power basis is the parabola with Bézier points (0,0), (1/2,0), (1,1).
    let b = convert_points(&m, &[0.0, 0.0, 1.0, 0.0, 0.0, 1.0], 2).unwrap();
    assert_eq!(b, vec![0.0, 0.0, 0.5, 0.0, 1.0, 1.0]);
}
