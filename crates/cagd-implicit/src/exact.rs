//! Exact monomial coefficients of `f(x, y) = det F(x, y)` (SPEC-convert §15.8, eqs.
//! 15.8.2–15.8.5).
//!
//! Route: the homogeneous control points are scaled by one common integer `D` (a power of
//! two for `f64` input, the lcm of the denominators otherwise), which multiplies `f` by
//! `D^(2n)` and makes `A, B, C0` integer matrices. `det(x A + y B + C0)` has total degree
//! `n`, so its values on the triangular lattice `a, b >= 0, a + b <= n` determine it through
//! the bivariate Newton forward-difference formula
//! `f(x, y) = sum_{i+j<=n} Δx^i Δy^j f(0,0) C(x,i) C(y,j)`, converted to monomials with the
//! Stirling numbers of the first kind. All of this is done modulo enough 31-bit primes to
//! exceed twice the bound `prod_i (sum_j (|A_ij| + |B_ij| + |C0_ij|)^2)^(1/2)` on every
//! coefficient (a coefficient is a Fourier coefficient of `det F` on the torus
//! `|x| = |y| = 1`, where Hadamard's inequality bounds `|det F|`), and the integer coefficients are
//! recovered by Chinese remaindering: exact, with machine-word arithmetic inside.
//! Beyond [`PRIME_COUNT`] primes (numbers of more than ~15 000 bits) the same lattice
//! determinants are taken by fraction-free Bareiss elimination on `BigInt`s instead.
//!
//! Cost: `(n+1)(n+2)/2` determinants of size `n` per prime, `O(n^5 k)` word operations for
//! `k ≈ (bits of the bound) / 30` primes.

use cagd_core::{BezierCurve, binomial, tri_count, tri_index};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

use crate::modular::{
    Crt, Digits, Modulus, PRIME_COUNT, batch_divide, det_mod_fraction, inv_mod, primes,
};
use crate::planar::weight;
use crate::rational::Q;

/// Integer homogeneous points `pts` with `(X_i, Y_i, W_i) = pts_i / den`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct IntHom {
    pub(crate) pts: Vec<[BigInt; 3]>,
    /// The common denominator `D`.
    den: BigInt,
    /// `Some(k)` when `den = 2^k` (exact reduction by shifting).
    den_log2: Option<u64>,
}

/// Mantissa and exponent of a finite `f64`: `x = m * 2^e`.
fn decode(x: f64) -> (i64, i32) {
    if x == 0.0 {
        return (0, 0);
    }
    let bits = x.to_bits();
    let sign = if bits >> 63 == 0 { 1i64 } else { -1 };
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let frac = bits & 0x000f_ffff_ffff_ffff;
    let (m, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | 0x0010_0000_0000_0000, exp - 1075)
    };
    let tz = m.trailing_zeros();
    (sign * (m >> tz) as i64, e + tz as i32)
}

impl IntHom {
    /// From a planar curve: `(w x, w y, w)` exactly, scaled by the power of two that makes
    /// every value an integer.
    pub(crate) fn from_curve(curve: &BezierCurve) -> Self {
        let vals: Vec<[(BigInt, i32); 3]> = (0..=curve.degree())
            .map(|i| {
                let p = curve.point(i);
                let (mw, ew) = decode(weight(curve, i));
                let (mx, ex) = decode(p[0]);
                let (my, ey) = decode(p[1]);
                let bw = BigInt::from(mw);
                [
                    (&bw * BigInt::from(mx), ew + ex),
                    (&bw * BigInt::from(my), ew + ey),
                    (bw, ew),
                ]
            })
            .collect();
        let e_min = vals
            .iter()
            .flatten()
            .filter(|(m, _)| !m.is_zero())
            .map(|(_, e)| *e)
            .min()
            .unwrap_or(0)
            .min(0);
        let pts = vals
            .into_iter()
            .map(|p| p.map(|(m, e)| m << ((e - e_min) as u64)))
            .collect();
        let k = u64::from(e_min.unsigned_abs());
        IntHom {
            pts,
            den: BigInt::one() << k,
            den_log2: Some(k),
        }
    }

    /// From exact rational homogeneous points (common denominator = lcm).
    pub(crate) fn from_rational(hom: &[[Q; 3]]) -> Self {
        let mut d = BigInt::one();
        for p in hom {
            for c in p {
                d = d.lcm(c.denom());
            }
        }
        let pts = hom
            .iter()
            .map(|p| [0, 1, 2].map(|k| p[k].numer() * (&d / p[k].denom())))
            .collect();
        IntHom {
            pts,
            den: d,
            den_log2: None,
        }
    }

    /// The exact rational homogeneous points.
    pub(crate) fn to_rational(&self) -> Vec<[Q; 3]> {
        self.pts
            .iter()
            .map(|p| p.clone().map(|c| Q::new(c, self.den.clone())))
            .collect()
    }

    /// The degree `n`.
    pub(crate) fn degree(&self) -> usize {
        self.pts.len() - 1
    }
}

/// Exact coefficients of `det F`, indexed by `tri_index(n, i, j)` for `x^i y^j`.
pub(crate) fn exact_coefficients(h: &IntHom) -> Vec<Q> {
    let n = h.degree();
    let (a, b, c) = integer_bezout(&h.pts);
    // |c_pq| <= max over |x| = |y| = 1 of |det F| <= prod_i ||row_i||_2 (Hadamard), with
    // |a x + b y + c| <= |a| + |b| + |c| on the torus.
    let bits: u64 = (0..n)
        .map(|i| {
            let mut s = BigInt::zero();
            for j in 0..n {
                let k = i * n + j;
                let e = a[k].abs() + b[k].abs() + c[k].abs();
                s += &e * &e;
            }
            s.bits().div_ceil(2)
        })
        .sum();
    let k = usize::try_from(bits / 30 + 2).unwrap_or(usize::MAX);
    let ints = if k <= PRIME_COUNT {
        modular_coefficients(&a, &b, &c, n, &primes()[..k])
    } else {
        bareiss_coefficients(&a, &b, &c, n)
    };
    // Divide by D^(2n).
    let two_n = 2 * n as u64;
    ints.into_iter()
        .map(|v| match h.den_log2 {
            Some(k) => {
                let total = k * two_n;
                let tz = if v.is_zero() {
                    total
                } else {
                    v.trailing_zeros().unwrap_or(0).min(total)
                };
                Q::new_raw(v >> tz, BigInt::one() << (total - tz))
            }
            None => Q::new(v, h.den.pow(u32::try_from(two_n).unwrap_or(u32::MAX))),
        })
        .collect()
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

/// The integer coefficients by lattice determinants, Newton and Stirling, all mod each
/// prime, then Chinese remaindering.
fn modular_coefficients(
    a: &[BigInt],
    b: &[BigInt],
    c: &[BigInt],
    n: usize,
    ps: &[u64],
) -> Vec<BigInt> {
    let da: Vec<Digits> = a.iter().map(Digits::new).collect();
    let db: Vec<Digits> = b.iter().map(Digits::new).collect();
    let dc: Vec<Digits> = c.iter().map(Digits::new).collect();
    let stir = stirling1(n);
    let stir_d: Vec<Vec<Digits>> = stir
        .iter()
        .map(|r| r.iter().map(Digits::new).collect())
        .collect();
    let count = tri_count(n);
    let mut residues = vec![vec![0u64; ps.len()]; count];
    let mut m = vec![0u64; n * n];
    let mut fracs = vec![(0u64, 1u64); count];
    for (pi, &p) in ps.iter().enumerate() {
        let md = Modulus::new(p);
        let (ra, rb, rc): (Vec<u64>, Vec<u64>, Vec<u64>) = (
            da.iter().map(|d| d.residue(md)).collect(),
            db.iter().map(|d| d.residue(md)).collect(),
            dc.iter().map(|d| d.residue(md)).collect(),
        );
        for ia in 0..=n {
            for ib in 0..=n - ia {
                let (xa, yb) = (ia as u64, ib as u64);
                for k in 0..n * n {
                    m[k] = md.reduce(xa * ra[k] + yb * rb[k] + rc[k]);
                }
                fracs[tri_index(n, ia, ib)] = det_mod_fraction(&mut m, n, md);
            }
        }
        let vals = batch_divide(&fracs, md);
        let diffs = forward_differences_mod(&vals, n, p);
        // 1 / i! mod p
        let mut inv_fact = vec![1u64; n + 1];
        let mut f = 1u64;
        for (i, slot) in inv_fact.iter_mut().enumerate().skip(1) {
            f = f * i as u64 % p;
            *slot = inv_mod(f, p);
        }
        let s: Vec<Vec<u64>> = stir_d
            .iter()
            .map(|r| r.iter().map(|d| d.residue(md)).collect())
            .collect();
        for pp in 0..=n {
            for qq in 0..=n - pp {
                let mut acc = 0u64;
                for i in pp..=n {
                    let si = md.mul(s[i][pp], inv_fact[i]);
                    if si == 0 {
                        continue;
                    }
                    for j in qq..=n - i {
                        let t = md.mul(diffs[tri_index(n, i, j)], md.mul(s[j][qq], inv_fact[j]));
                        acc = md.reduce(acc + md.mul(si, t));
                    }
                }
                residues[tri_index(n, pp, qq)][pi] = acc;
            }
        }
    }
    let crt = Crt::new(ps);
    residues.iter().map(|r| crt.reconstruct(r)).collect()
}

/// `a - b mod p` for residues.
fn sub_mod(a: u64, b: u64, p: u64) -> u64 {
    if a >= b { a - b } else { a + p - b }
}

/// `Δx^i Δy^j f(0, 0)` mod `p` for `i + j <= n` from the lattice values.
fn forward_differences_mod(values: &[u64], n: usize, p: u64) -> Vec<u64> {
    let mut dx = vec![0u64; tri_count(n)];
    for b in 0..=n {
        let mut row: Vec<u64> = (0..=n - b).map(|a| values[tri_index(n, a, b)]).collect();
        for i in 0..=n - b {
            dx[tri_index(n, i, b)] = row[0];
            for a in 0..row.len() - 1 - i {
                row[a] = sub_mod(row[a + 1], row[a], p);
            }
        }
    }
    let mut out = vec![0u64; tri_count(n)];
    for i in 0..=n {
        let mut col: Vec<u64> = (0..=n - i).map(|b| dx[tri_index(n, i, b)]).collect();
        for j in 0..=n - i {
            out[tri_index(n, i, j)] = col[0];
            for b in 0..col.len() - 1 - j {
                col[b] = sub_mod(col[b + 1], col[b], p);
            }
        }
    }
    out
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

/// The integer coefficients by `BigInt` Bareiss determinants on the lattice and exact
/// Newton interpolation (the route for numbers beyond the prepared primes; also the test
/// oracle of the modular route).
fn bareiss_coefficients(a: &[BigInt], b: &[BigInt], c: &[BigInt], n: usize) -> Vec<BigInt> {
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
    // Forward differences.
    let mut dx = vec![BigInt::zero(); tri_count(n)];
    for bb in 0..=n {
        let mut row: Vec<BigInt> = (0..=n - bb)
            .map(|x| values[tri_index(n, x, bb)].clone())
            .collect();
        for i in 0..=n - bb {
            dx[tri_index(n, i, bb)] = row[0].clone();
            for x in 0..row.len() - 1 - i {
                row[x] = &row[x + 1] - &row[x];
            }
        }
    }
    let mut diffs = vec![BigInt::zero(); tri_count(n)];
    for i in 0..=n {
        let mut col: Vec<BigInt> = (0..=n - i)
            .map(|y| dx[tri_index(n, i, y)].clone())
            .collect();
        for j in 0..=n - i {
            diffs[tri_index(n, i, j)] = col[0].clone();
            for y in 0..col.len() - 1 - j {
                col[y] = &col[y + 1] - &col[y];
            }
        }
    }
    let s = stirling1(n);
    let mut fact = vec![BigInt::one(); n + 1];
    for i in 1..=n {
        fact[i] = &fact[i - 1] * BigInt::from(i);
    }
    let ratio: Vec<BigInt> = (0..=n).map(|i| &fact[n] / &fact[i]).collect();
    let den = &fact[n] * &fact[n];
    let mut out = vec![BigInt::zero(); tri_count(n)];
    for p in 0..=n {
        for q in 0..=n - p {
            let mut acc = BigInt::zero();
            for i in p..=n {
                for j in q..=n - i {
                    let dij = &diffs[tri_index(n, i, j)];
                    if !dij.is_zero() {
                        acc += dij * &s[i][p] * &s[j][q] * &ratio[i] * &ratio[j];
                    }
                }
            }
            debug_assert!((&acc % &den).is_zero());
            out[tri_index(n, p, q)] = acc / &den;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rational::q;

    fn hom(points: &[(f64, f64)], w: &[f64]) -> IntHom {
        let h: Vec<[Q; 3]> = points
            .iter()
            .zip(w)
            .map(|(&(x, y), &w)| [q(w) * q(x), q(w) * q(y), q(w)])
            .collect();
        IntHom::from_rational(&h)
    }

    #[test]
    fn bareiss_matches_cofactor_expansion() {
        let vals = [2, -1, 3, 0, 4, 5, 1, -2, 6];
        let mut m: Vec<BigInt> = vals.iter().map(|&v| BigInt::from(v)).collect();
        assert_eq!(det_bareiss(&mut m, 3), BigInt::from(51));
        let mut z: Vec<BigInt> = [0, 1, 1, 0].iter().map(|&v| BigInt::from(v)).collect();
        assert_eq!(det_bareiss(&mut z, 2), BigInt::from(-1));
    }

    #[test]
    fn spec_inline_parabola() {
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
        let pts = [(0.0, 0.0), (1.0, 3.0), (3.0, 3.0), (4.0, 0.0)];
        let a = exact_coefficients(&hom(&pts, &[1.0, 2.0, 2.0, 1.0]));
        let b = exact_coefficients(&hom(&pts, &[0.5, 1.0, 1.0, 0.5]));
        let l6 = q(0.5f64.powi(6));
        for (x, y) in a.iter().zip(&b) {
            assert_eq!(&(x * &l6), y);
        }
    }

    #[test]
    fn modular_route_equals_bareiss_and_f64_scaling_equals_rational() {
        let raw = [
            (0.1, -0.7, 1.3),
            (0.33, 0.25, 0.6),
            (-0.9, 0.01, 1.9),
            (0.5, 0.5, 0.7),
            (1e-5, -3.0, 1.0),
            (0.2, 0.8, 1.1),
        ];
        for n in 1..=5 {
            let pts: Vec<f64> = raw[..=n].iter().flat_map(|r| [r.0, r.1]).collect();
            let w: Vec<f64> = raw[..=n].iter().map(|r| r.2).collect();
            let curve = BezierCurve::new_rational(pts, w, 2).unwrap();
            let ih = IntHom::from_curve(&curve);
            let (a, b, c) = integer_bezout(&ih.pts);
            let k = 200;
            assert_eq!(
                modular_coefficients(&a, &b, &c, n, &primes()[..k]),
                bareiss_coefficients(&a, &b, &c, n)
            );
            let rational = IntHom::from_rational(&crate::planar::exact_homogeneous(&curve));
            assert_eq!(exact_coefficients(&ih), exact_coefficients(&rational));
            assert_eq!(ih.to_rational(), crate::planar::exact_homogeneous(&curve));
        }
    }

    #[test]
    fn decode_is_exact() {
        for x in [1.0, -0.75, 3.0e-310, 1.5e300, 0.1, -7.0] {
            let (m, e) = decode(x);
            let pow = if e >= 0 {
                Q::from_integer(BigInt::one() << e.unsigned_abs())
            } else {
                Q::new(BigInt::one(), BigInt::one() << e.unsigned_abs())
            };
            assert_eq!(q(x), Q::from_integer(BigInt::from(m)) * pow, "{x}");
        }
    }
}
