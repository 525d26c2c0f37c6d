//! The uniform B-spline -> Bézier matrix `S^(n)` of seed 001 (§2.1–2.2, eqs. 2 and 5) and
//! its inverse (§4.2, `S^(-m)`), exact and in `f64`.
//!
//! A degree-`n` uniform (integer knots) B-spline segment with control points
//! `p_s..p_{s+n}` has the Bézier points `b = S^(n) p` (eq. 2:
//! `N_{j-n,n}(u) = sum_i S^(n)_ij B_i^n(u)`, `u in [0, 1]`).
//!
//! `S^(n)` is built by eq. 5 as SPEC-reduce §8 states it:
//! `S^(k+1) = R(E(S^(k) L^(k)))`, `S^(0) = [1]`, where `L^(k)` is `(k+1) x (k+1)` with
//! `L_jj = (j+1)/(k+1)`, `L_{j,j+1} = (k-j)/(k+1)`; `E` appends a zero row and column; `R`
//! sets the last row to the first row shifted right by one place. **Eq. 4 of the seed,
//! `S^(n) = E^n(S^(n-1) L^(n-1)) + E_1(S^(n-1) M^(n-1))`, is wrong as printed**: it adds
//! rows 1..n-1 twice (SPEC-reduce §8 ERRATUM; correct: rows 0..n-1 from `S L`, row n from
//! `S M`); it is not used. Also an erratum: properties (i) and (iii) of the seed refer to
//! the integer matrix `n! S^(n)`; in `S^(n)` itself `S_00 = 1/n!`.
//!
//! Everything is computed in exact rationals (`BigRational`), cached per `n` for the life
//! of the process, and rounded to `f64` once. Checked: the printed `S^(1)..S^(5)` of seed
//! 001 exactly, the vectors `S-matrix-3/4`, and Bézier extraction of the uniform B-spline
//! by blossoming for `n <= 8` (f64, `<= 1e-15`). Degrees `0..=MAX_DEGREE`.

use std::sync::OnceLock;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};

use crate::Result;
use crate::binomial::{MAX_DEGREE, check_degree};

struct Cached {
    exact: Vec<BigRational>,
    float: Vec<f64>,
}

static S: [OnceLock<Cached>; MAX_DEGREE + 1] = [const { OnceLock::new() }; MAX_DEGREE + 1];
static S_INV: [OnceLock<Cached>; MAX_DEGREE + 1] = [const { OnceLock::new() }; MAX_DEGREE + 1];

fn rounded(exact: Vec<BigRational>) -> Cached {
    let float = exact
        .iter()
        .map(|x| x.to_f64().unwrap_or(f64::NAN))
        .collect();
    Cached { exact, float }
}

/// `S^(n)` by eq. 5, cached per `n`: the integer matrices `k! S^(k)` of the recurrence
/// ([`s_integer`]) divided by `n!` once.
fn s_cached(n: usize) -> &'static Cached {
    S[n].get_or_init(|| {
        let fact: BigInt = (1..=n).map(BigInt::from).product();
        rounded(
            s_integer(n)
                .into_iter()
                .map(|x| BigRational::new(x, fact.clone()))
                .collect(),
        )
    })
}

/// `n! S^(n)` (integers, seed 001 property (i)) by eq. 5 scaled by `(k + 1)!` at each step:
/// with `T^(k) = k! S^(k)`, rows `0..=k` of `T^(k+1)` are `T^(k) ((k + 1) L^(k))`, column
/// `c` = `T_ic (c + 1) + T_{i,c-1} (k + 1 - c)` (integer factors), and its last row is its
/// first shifted right by one (`R`). Integer arithmetic without a gcd per operation: the
/// rational recurrence took 1.4 s at `n = 62` (C ABI fuzz, a slow call of
/// `cagd_bspline_reduce_uniform` and `cagd_uniform_bspline_matrix`).
fn s_integer(n: usize) -> Vec<BigInt> {
    let mut t = vec![BigInt::one()];
    for k in 0..n {
        let (m, big) = (k + 1, k + 2);
        let mut out = vec![BigInt::zero(); big * big];
        for i in 0..m {
            for c in 0..m {
                let mut v = &t[i * m + c] * (c + 1);
                if c > 0 {
                    v += &t[i * m + c - 1] * (m - c);
                }
                out[i * big + c] = v;
            }
        }
        for c in 1..big {
            out[(big - 1) * big + c] = out[c - 1].clone();
        }
        t = out;
    }
    t
}

/// `S^(-n)` in closed form by blossoming (Ramshaw; the de Boor–Fix dual functionals): on the
/// segment `[0, 1]` of the knots `-n, ..., n + 1`, B-spline point `p_j` is the blossom of the
/// Bézier curve at the knots `x = j+1-n, ..., j`, and the blossom of `B_i^n` at `x_1..x_n` is
/// the coefficient of `z^i` in `prod_k ((1 - x_k) + x_k z)`. The entries are integers.
fn s_inv_cached(n: usize) -> &'static Cached {
    S_INV[n].get_or_init(|| {
        let d = n + 1;
        let mut out = Vec::with_capacity(d * d);
        for j in 0..d {
            let mut poly = vec![BigInt::zero(); d];
            poly[0] = BigInt::one();
            for k in 0..n {
                // x = j + 1 - n + k, multiply by (1 - x) + x z, from the top down.
                let x = BigInt::from(j + 1 + k) - BigInt::from(n);
                let one_minus = BigInt::one() - &x;
                for i in (0..=k + 1).rev() {
                    let mut v = &poly[i] * &one_minus;
                    if i > 0 {
                        v += &poly[i - 1] * &x;
                    }
                    poly[i] = v;
                }
            }
            out.extend(poly.into_iter().map(BigRational::from_integer));
        }
        rounded(out)
    })
}

/// The exact matrix `S^(n)`, `(n + 1) x (n + 1)` row-major (`S_ij` at `i * (n + 1) + j`;
/// row `i` is Bézier point `i`, column `j` is B-spline point `j`).
///
/// # Errors
/// [`crate::Error::DegreeOutOfRange`] when `n > MAX_DEGREE`.
pub fn s_matrix_exact(n: usize) -> Result<&'static [BigRational]> {
    check_degree(n)?;
    Ok(&s_cached(n).exact)
}

/// `S^(n)` rounded once to `f64` (see [`s_matrix_exact`]).
///
/// # Errors
/// [`crate::Error::DegreeOutOfRange`] when `n > MAX_DEGREE`.
///
/// ```
/// // Cubic: b_0 = (p_0 + 4 p_1 + p_2) / 6 (seed 001, printed S^(3)).
/// let s = cagd_core::s_matrix(3)?;
/// assert_eq!(&s[..4], &[1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0, 0.0]);
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn s_matrix(n: usize) -> Result<&'static [f64]> {
    check_degree(n)?;
    Ok(&s_cached(n).float)
}

/// The exact inverse `S^(-n)` of [`s_matrix_exact`] (seed 001 §4.2, Bézier -> uniform
/// B-spline points of one segment), in closed form by blossoming: row `j` holds the
/// coefficients of `prod_{k=0}^{n-1} ((1 - x_k) + x_k z)`, `x_k = j + 1 - n + k` (integers).
/// Checked: `S^(n) S^(-n) = I` exactly for `n <= 12` (and rows 0, 1, 32 at `n = 64`).
///
/// # Errors
/// [`crate::Error::DegreeOutOfRange`] when `n > MAX_DEGREE`.
pub fn s_matrix_inverse_exact(n: usize) -> Result<&'static [BigRational]> {
    check_degree(n)?;
    Ok(&s_inv_cached(n).exact)
}

/// `S^(-n)` rounded once to `f64` (see [`s_matrix_inverse_exact`]). Its entries grow fast
/// with `n` (`||S^(-3)||_inf = 15`, SPEC-reduce §8; the largest entry of `S^(-64)` is
/// `1.6e106`), so Bézier -> B-spline conversion amplifies noise by that factor: usable in
/// `f64` only for small degrees.
///
/// # Errors
/// As [`s_matrix_inverse_exact`].
pub fn s_matrix_inverse(n: usize) -> Result<&'static [f64]> {
    check_degree(n)?;
    Ok(&s_inv_cached(n).float)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::BSplineCurve;

    fn exact_int(n: usize, rows: &[&[i64]], fact: i64) {
        let s = s_matrix_exact(n).unwrap();
        for (i, row) in rows.iter().enumerate() {
            for (j, &v) in row.iter().enumerate() {
                let e = BigRational::new(BigInt::from(v), BigInt::from(fact));
                assert_eq!(s[i * (n + 1) + j], e, "S^({n})[{i}][{j}]");
            }
        }
    }

    #[test]
    fn printed_matrices_of_seed_001() {
        exact_int(0, &[&[1]], 1);
        exact_int(1, &[&[1, 0], &[0, 1]], 1);
        exact_int(2, &[&[1, 1, 0], &[0, 2, 0], &[0, 1, 1]], 2);
        exact_int(
            3,
            &[&[1, 4, 1, 0], &[0, 4, 2, 0], &[0, 2, 4, 0], &[0, 1, 4, 1]],
            6,
        );
        exact_int(
            4,
            &[
                &[1, 11, 11, 1, 0],
                &[0, 8, 14, 2, 0],
                &[0, 4, 16, 4, 0],
                &[0, 2, 14, 8, 0],
                &[0, 1, 11, 11, 1],
            ],
            24,
        );
        exact_int(
            5,
            &[
                &[1, 26, 66, 26, 1, 0],
                &[0, 16, 66, 36, 2, 0],
                &[0, 8, 60, 48, 4, 0],
                &[0, 4, 48, 60, 8, 0],
                &[0, 2, 36, 66, 16, 0],
                &[0, 1, 26, 66, 26, 1],
            ],
            120,
        );
    }

    /// The recurrence of eq. 5 in rationals, as SPEC-reduce §8 states it (the route the
    /// integer recurrence replaced): `S^(k+1) = R(E(S^(k) L^(k)))`.
    fn s_rational(n: usize) -> Vec<BigRational> {
        let ratio = |a: usize, b: usize| BigRational::new(a.into(), b.into());
        let mut s = vec![BigRational::one()];
        for k in 0..n {
            let (m, big) = (k + 1, k + 2);
            let mut out = vec![BigRational::zero(); big * big];
            for i in 0..m {
                for c in 0..m {
                    let mut v = &s[i * m + c] * ratio(c + 1, m);
                    if c > 0 {
                        v += &s[i * m + c - 1] * ratio(m - c, m);
                    }
                    out[i * big + c] = v;
                }
            }
            for c in 1..big {
                out[(big - 1) * big + c] = out[c - 1].clone();
            }
            s = out;
        }
        s
    }

    #[test]
    fn integer_recurrence_is_the_rational_one() {
        for n in (0..=24).chain([40]) {
            assert_eq!(s_matrix_exact(n).unwrap(), &s_rational(n)[..], "S^({n})");
        }
        // Degree 64: every row sums to one and `n! S` is integral (property (i)).
        let s = s_matrix_exact(64).unwrap();
        let fact: BigInt = (1..=64u32).map(BigInt::from).product();
        for row in s.chunks_exact(65) {
            assert!(row.iter().sum::<BigRational>().is_one());
            assert!(row.iter().all(|x| (x * &fact).is_integer()));
        }
    }

    #[test]
    fn spec_vectors() {
        for (id, n) in [("S-matrix-3", 3usize), ("S-matrix-4", 4)] {
            let v = cagd_testkit::vector("vectors-reduce.json", id);
            let rows = v["expected"]["S_exact"].as_array().unwrap();
            let s = s_matrix_exact(n).unwrap();
            for (i, row) in rows.iter().enumerate() {
                for (j, x) in row.as_array().unwrap().iter().enumerate() {
                    assert_eq!(s[i * (n + 1) + j], cagd_testkit::rational(x), "{id}");
                }
            }
            let expected = cagd_testkit::flat(&v["expected"]["S_exact"]);
            cagd_testkit::assert_close(id, s_matrix(n).unwrap(), &expected, 0.0);
        }
    }

    #[test]
    fn properties_rows_sum_to_one_and_symmetry() {
        for n in 0..=20 {
            let s = s_matrix_exact(n).unwrap();
            let d = n + 1;
            for i in 0..d {
                let sum: BigRational = s[i * d..(i + 1) * d].iter().sum();
                assert!(sum.is_one(), "n={n} row {i}");
                for j in 0..d {
                    assert_eq!(s[i * d + j], s[(n - i) * d + (n - j)]);
                }
            }
        }
        assert!(s_matrix(65).is_err());
        assert!(s_matrix_inverse(65).is_err());
    }

    #[test]
    fn independent_route_by_bezier_extraction() {
        // Uniform B-spline of degree n on knots 0..=2n+1 with points e_0..e_n: its one
        // piece on [n, n+1] has Bézier point i = row i of S^(n).
        for n in 0..=8usize {
            let d = n + 1;
            let mut pts = vec![0.0; d * d];
            (0..d).for_each(|j| pts[j * d + j] = 1.0);
            let knots = (0..=2 * n + 1).map(|x| x as f64).collect();
            let c = BSplineCurve::new(n, knots, pts, d).unwrap();
            let pieces = c.to_beziers().unwrap();
            assert_eq!(pieces.len(), 1);
            cagd_testkit::assert_close(
                "S by extraction",
                pieces[0].curve.points(),
                s_matrix(n).unwrap(),
                1e-15,
            );
        }
    }

    #[test]
    fn inverse_is_exact() {
        for n in (0..=12).chain([64]) {
            let d = n + 1;
            let (s, si) = (
                s_matrix_exact(n).unwrap(),
                s_matrix_inverse_exact(n).unwrap(),
            );
            // All rows up to n = 12; rows 0, 1 and 32 at n = 64 (the full check is slow).
            let rows: Vec<usize> = if n <= 12 {
                (0..d).collect()
            } else {
                vec![0, 1, 32]
            };
            for i in rows {
                for j in 0..d {
                    let v: BigRational = (0..d).map(|k| &s[i * d + k] * &si[k * d + j]).sum();
                    assert_eq!(
                        v,
                        if i == j {
                            BigRational::one()
                        } else {
                            BigRational::zero()
                        }
                    );
                }
            }
        }
        // SPEC-reduce §8: ||S^(-3)||_inf = 15.
        let si = s_matrix_inverse(3).unwrap();
        let norm = (0..4)
            .map(|i| si[i * 4..(i + 1) * 4].iter().map(|x| x.abs()).sum::<f64>())
            .fold(0.0, f64::max);
        assert_eq!(norm, 15.0);
    }
}
