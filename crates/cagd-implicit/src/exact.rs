//! Exact monomial coefficients of `f(x, y) = det F(x, y)` (SPEC-convert §15.8, eqs.
//! 15.8.2–15.8.5).
//!
//! Route: the homogeneous control points are scaled by one common integer `D` (the lcm of
//! their denominators; a power of two for `f64` input), which multiplies `f` by `D^(2n)`.
//! The integer matrix `F(a, b) = a A + b B + C0` is then evaluated on the triangular
//! lattice `a, b >= 0, a + b <= n` and its determinant taken by fraction-free Bareiss
//! elimination; `f` has total degree `n`, so the lattice values determine it through the
//! bivariate Newton forward-difference formula
//! `f(x, y) = sum_{i+j<=n} Δx^i Δy^j f(0,0) C(x,i) C(y,j)`, converted to monomials with the
//! Stirling numbers of the first kind. Everything is exact (`BigInt`); the result is
//! divided by `D^(2n)` once at the end.
//!
//! Cost: `(n+1)(n+2)/2` Bareiss determinants of size `n`, i.e. `O(n^5)` big-integer
//! operations on numbers of a few hundred to a few thousand bits.

use cagd_core::{binomial, tri_count, tri_index};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};

use crate::rational::Q;

/// Exact coefficients of `det F` for homogeneous points `hom` (degree `n = hom.len() - 1 >= 1`),
/// indexed by `tri_index(n, i, j)` for the monomial `x^i y^j`.
pub(crate) fn exact_coefficients(hom: &[[Q; 3]]) -> Vec<Q> {
    let n = hom.len() - 1;
    // Common denominator D and integer homogeneous points.
    let mut d = BigInt::one();
    for p in hom {
        for c in p {
            d = d.lcm(c.denom());
        }
    }
    let ints: Vec<[BigInt; 3]> = hom
        .iter()
        .map(|p| {
            [0, 1, 2].map(|k| {
                let c = &p[k];
                c.numer() * (&d / c.denom())
            })
        })
        .collect();
    let (a, b, c) = integer_bezout(&ints);
    // Values of det F on the lattice.
    let mut values = vec![BigInt::zero(); tri_count(n)];
    let mut m = vec![BigInt::zero(); n * n];
    for ia in 0..=n {
        for ib in 0..=n - ia {
            let (xa, yb) = (BigInt::from(ia), BigInt::from(ib));
            for k in 0..n * n {
                m[k] = &a[k] * &xa + &b[k] * &yb + &c[k];
            }
            values[tri_index(n, ia, ib)] = det_bareiss(&mut m, n);
        }
    }
    let diffs = forward_differences(&values, n);
    let scale = d.pow(u32::try_from(2 * n).unwrap_or(u32::MAX));
    newton_to_monomials(&diffs, n, &scale)
}

/// Integer `A, B, C0` from integer homogeneous points (eqs. 15.8.2–15.8.3).
fn integer_bezout(p: &[[BigInt; 3]]) -> (Vec<BigInt>, Vec<BigInt>, Vec<BigInt>) {
    let n = p.len() - 1;
    let l = |i: usize, j: usize| -> [BigInt; 3] {
        let s = BigInt::from(binomial(n, i)) * BigInt::from(binomial(n, j));
        let (u, v) = (&p[i], &p[j]);
        [
            &s * (&u[1] * &v[2] - &u[2] * &v[1]),
            -&s * (&u[0] * &v[2] - &u[2] * &v[0]),
            &s * (&u[0] * &v[1] - &u[1] * &v[0]),
        ]
    };
    let mut a = vec![BigInt::zero(); n * n];
    let mut b = vec![BigInt::zero(); n * n];
    let mut c = vec![BigInt::zero(); n * n];
    for h in 0..n {
        for k in h..n {
            let mut s = [BigInt::zero(), BigInt::zero(), BigInt::zero()];
            for m in (h + k + 1).saturating_sub(n)..=h.min(k) {
                let t = l(m, h + k + 1 - m);
                for r in 0..3 {
                    s[r] += &t[r];
                }
            }
            let [sa, sb, sc] = s;
            a[h * n + k] = sa.clone();
            a[k * n + h] = sa;
            b[h * n + k] = sb.clone();
            b[k * n + h] = sb;
            c[h * n + k] = sc.clone();
            c[k * n + h] = sc;
        }
    }
    (a, b, c)
}

/// The determinant of an integer matrix (destroyed) by fraction-free Bareiss elimination
/// (every division is exact).
pub(crate) fn det_bareiss(m: &mut [BigInt], n: usize) -> BigInt {
    let mut negate = false;
    let mut prev = BigInt::one();
    for k in 0..n.saturating_sub(1) {
        if m[k * n + k].is_zero() {
            let Some(r) = (k + 1..n).find(|&r| !m[r * n + k].is_zero()) else {
                return BigInt::zero();
            };
            for j in 0..n {
                m.swap(k * n + j, r * n + j);
            }
            negate = !negate;
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let v = &m[i * n + j] * &m[k * n + k] - &m[i * n + k] * &m[k * n + j];
                m[i * n + j] = v / &prev;
            }
        }
        prev = m[k * n + k].clone();
    }
    let d = m[n * n - 1].clone();
    if negate { -d } else { d }
}

/// `Δx^i Δy^j f(0, 0)` for `i + j <= n` from the lattice values `f(a, b)`.
fn forward_differences(values: &[BigInt], n: usize) -> Vec<BigInt> {
    // Along x for each row b: d[i][b] = Δx^i f(0, b), i <= n - b.
    let mut dx = vec![BigInt::zero(); tri_count(n)];
    for b in 0..=n {
        let mut row: Vec<BigInt> = (0..=n - b)
            .map(|a| values[tri_index(n, a, b)].clone())
            .collect();
        for i in 0..=n - b {
            dx[tri_index(n, i, b)] = row[0].clone();
            for a in 0..row.len() - 1 - i {
                row[a] = &row[a + 1] - &row[a];
            }
        }
    }
    // Along y for each i.
    let mut out = vec![BigInt::zero(); tri_count(n)];
    for i in 0..=n {
        let mut col: Vec<BigInt> = (0..=n - i)
            .map(|b| dx[tri_index(n, i, b)].clone())
            .collect();
        for j in 0..=n - i {
            out[tri_index(n, i, j)] = col[0].clone();
            for b in 0..col.len() - 1 - j {
                col[b] = &col[b + 1] - &col[b];
            }
        }
    }
    out
}

/// Signed Stirling numbers of the first kind `s(i, k)`, `i, k <= n`:
/// `x (x-1) ... (x-i+1) = sum_k s(i,k) x^k`.
fn stirling1(n: usize) -> Vec<Vec<BigInt>> {
    let mut s = vec![vec![BigInt::zero(); n + 1]; n + 1];
    s[0][0] = BigInt::one();
    for i in 0..n {
        for k in 0..=i + 1 {
            let mut v = if k > 0 {
                s[i][k - 1].clone()
            } else {
                BigInt::zero()
            };
            if k <= i {
                v -= BigInt::from(i) * &s[i][k];
            }
            s[i + 1][k] = v;
        }
    }
    s
}

/// Monomial coefficients `c_pq = sum_{i>=p, j>=q, i+j<=n} D_ij s(i,p) s(j,q) / (i! j!)`,
/// divided by `scale`.
fn newton_to_monomials(diffs: &[BigInt], n: usize, scale: &BigInt) -> Vec<Q> {
    let s = stirling1(n);
    let mut fact = vec![BigInt::one(); n + 1];
    for i in 1..=n {
        fact[i] = &fact[i - 1] * BigInt::from(i);
    }
    // n!/i! as integers, so that sum * (n!)^2 stays integral.
    let ratio: Vec<BigInt> = (0..=n).map(|i| &fact[n] / &fact[i]).collect();
    let den = &fact[n] * &fact[n] * scale;
    let mut out = vec![Q::zero(); tri_count(n)];
    for p in 0..=n {
        for qd in 0..=n - p {
            let mut acc = BigInt::zero();
            for i in p..=n {
                if s[i][p].is_zero() {
                    continue;
                }
                for j in qd..=n - i {
                    let dij = &diffs[tri_index(n, i, j)];
                    if dij.is_zero() || s[j][qd].is_zero() {
                        continue;
                    }
                    acc += dij * &s[i][p] * &s[j][qd] * &ratio[i] * &ratio[j];
                }
            }
            out[tri_index(n, p, qd)] = Q::new(acc, den.clone());
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rational::q;

    fn hom(points: &[(f64, f64)], w: &[f64]) -> Vec<[Q; 3]> {
        points
            .iter()
            .zip(w)
            .map(|(&(x, y), &w)| [q(w) * q(x), q(w) * q(y), q(w)])
            .collect()
    }

    #[test]
    fn bareiss_matches_cofactor_expansion() {
        let vals = [2, -1, 3, 0, 4, 5, 1, -2, 6];
        let mut m: Vec<BigInt> = vals.iter().map(|&v| BigInt::from(v)).collect();
        // 2(24+10) - (-1)(0-5) + 3(0-4) = 68 - 5 - 12 = 51
        assert_eq!(det_bareiss(&mut m, 3), BigInt::from(51));
        let mut z: Vec<BigInt> = [0, 1, 1, 0].iter().map(|&v| BigInt::from(v)).collect();
        assert_eq!(det_bareiss(&mut z, 2), BigInt::from(-1));
    }

    #[test]
    fn spec_inline_parabola() {
        // f = -16 x^2 + 32 x - 16 y (SPEC-convert §15.8 inline example).
        let c = exact_coefficients(&hom(&[(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)], &[1.0; 3]));
        let n = 2;
        let get = |i, j| c[tri_index(n, i, j)].clone();
        assert_eq!(get(2, 0), q(-16.0));
        assert_eq!(get(1, 0), q(32.0));
        assert_eq!(get(0, 1), q(-16.0));
        for (i, j) in [(0, 0), (1, 1), (0, 2)] {
            assert_eq!(get(i, j), Q::zero());
        }
    }

    #[test]
    fn weights_scale_by_lambda_to_the_2n() {
        // SPEC-convert §15.8: scaling all weights by λ multiplies f by λ^(2n).
        let pts = [(0.0, 0.0), (1.0, 3.0), (3.0, 3.0), (4.0, 0.0)];
        let a = exact_coefficients(&hom(&pts, &[1.0, 2.0, 2.0, 1.0]));
        let b = exact_coefficients(&hom(&pts, &[0.5, 1.0, 1.0, 0.5]));
        let l6 = q(0.5f64.powi(6));
        for (x, y) in a.iter().zip(&b) {
            assert_eq!(&(x * &l6), y);
        }
    }
}
