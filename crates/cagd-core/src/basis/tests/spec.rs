//! Checks against the spec vectors (vectors-reduce.json).

use super::super::*;
use crate::wsgb_terms;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;

#[test]
fn wsgb_spec_vectors() {
    let vs = cagd_testkit::vectors_with_algorithm("vectors-reduce.json", "wsgb_basis");
    assert!(
        vs.iter().any(|v| v["id"] == "wsgb-basis-7-1"),
        "wsgb-basis-7-1 missing"
    );
    for v in vs {
        let n = usize::try_from(v["params"]["n"].as_u64().unwrap()).unwrap();
        let l = usize::try_from(v["params"]["L"].as_u64().unwrap()).unwrap();
        let terms = wsgb_terms(n, l).unwrap();
        let expected = v["expected"]["terms_K_a_b"].as_array().unwrap();
        assert_eq!(expected.len(), n + 1, "{}", v["id"]);
        for (t, e) in terms.iter().zip(expected) {
            assert_eq!(
                BigRational::from_integer(BigInt::from(t.coef)),
                cagd_testkit::rational(&e[0])
            );
            assert_eq!(
                (t.a as u64, t.b as u64),
                (e[1].as_u64().unwrap(), e[2].as_u64().unwrap())
            );
        }
    }
}

/// [cheb-trunc-n7-m4] (SPEC-reduce §7, Theorem 14.5.2 with r = p = -1): Chebyshev
/// truncation of a degree-7 curve to degree 4 is `to(4) * keep_0..4(from(7) * P)`; the
/// exact result must equal `Q_exact`, and the bound is the sum of the dropped coefficients'
/// Euclidean norms.
#[test]
fn chebyshev_truncation_vector_is_reproduced_exactly() {
    let v = cagd_testkit::vector("vectors-reduce.json", "cheb-trunc-n7-m4");
    let p: Vec<Vec<BigRational>> = v["input"]["P"]
        .as_array()
        .unwrap()
        .iter()
        .map(|pt| {
            pt.as_array()
                .unwrap()
                .iter()
                .map(cagd_testkit::rational)
                .collect()
        })
        .collect();
    let (n, m) = (p.len() - 1, 4);
    let from = from_bernstein_exact(Basis::Chebyshev, n).unwrap();
    let to = to_bernstein_exact(Basis::Chebyshev, m).unwrap();
    // Chebyshev coefficients per coordinate, truncated to k <= m and converted back.
    let cheb: Vec<Vec<BigRational>> = (0..2)
        .map(|d| {
            let coord: Vec<BigRational> = p.iter().map(|pt| pt[d].clone()).collect();
            from.mul_vec(&coord).unwrap()
        })
        .collect();
    let q: Vec<Vec<BigRational>> = cheb.iter().map(|c| to.mul_vec(&c[..=m]).unwrap()).collect();
    let bound: f64 = (m + 1..=n)
        .map(|k| {
            cheb[0][k]
                .to_f64()
                .unwrap()
                .hypot(cheb[1][k].to_f64().unwrap())
        })
        .sum();
    let expected = v["expected"]["Q_exact"].as_array().unwrap();
    for (i, e) in expected.iter().enumerate() {
        for d in 0..2 {
            assert_eq!(q[d][i], cagd_testkit::rational(&e[d]), "Q[{i}][{d}]");
        }
    }
    let want = cagd_testkit::num(&v["expected"]["bound"]);
    assert!(
        (bound - want).abs() <= 1e-14 * want,
        "bound {bound} vs {want}"
    );
}
