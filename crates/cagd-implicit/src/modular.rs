//! Word-size modular arithmetic for the exact implicit coefficients: 31-bit primes
//! (products fit in `u64`), residues of big integers, determinants and polynomial gcds
//! mod `p`, and Chinese remaindering (Garner) back to `BigInt`.

use std::sync::OnceLock;

use num_bigint::{BigInt, Sign};
use num_traits::Zero;

/// How many primes are prepared (each `> 2^30`, so up to ~15 000 bits of result).
pub(crate) const PRIME_COUNT: usize = 512;

/// Deterministic Miller–Rabin for `n < 2^32` (bases 2, 7, 61).
fn is_prime(n: u64) -> bool {
    if n < 2 {
        return false;
    }
    for p in [2u64, 3, 5, 7, 11, 13, 61] {
        if n % p == 0 {
            return n == p;
        }
    }
    let (mut d, mut s) = (n - 1, 0);
    while d % 2 == 0 {
        d /= 2;
        s += 1;
    }
    'witness: for a in [2u64, 7, 61] {
        let mut x = pow_mod(a, d, n);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = x * x % n;
            if x == n - 1 {
                continue 'witness;
            }
        }
        return false;
    }
    true
}

/// The primes below `2^31`, largest first.
pub(crate) fn primes() -> &'static [u64] {
    static PRIMES: OnceLock<Vec<u64>> = OnceLock::new();
    PRIMES.get_or_init(|| {
        let mut out = Vec::with_capacity(PRIME_COUNT);
        let mut c = (1u64 << 31) - 1;
        while out.len() < PRIME_COUNT {
            if is_prime(c) {
                out.push(c);
            }
            c -= 2;
        }
        out
    })
}

/// `a^e mod p` (`a, p < 2^32`).
pub(crate) fn pow_mod(mut a: u64, mut e: u64, p: u64) -> u64 {
    let mut r = 1 % p;
    a %= p;
    while e > 0 {
        if e & 1 == 1 {
            r = r * a % p;
        }
        a = a * a % p;
        e >>= 1;
    }
    r
}

/// `a^-1 mod p` for `a != 0 mod p` (extended Euclid).
pub(crate) fn inv_mod(a: u64, p: u64) -> u64 {
    let (mut r0, mut r1) = (p as i64, (a % p) as i64);
    let (mut t0, mut t1) = (0i64, 1i64);
    while r1 != 0 {
        let q = r0 / r1;
        (r0, r1) = (r1, r0 - q * r1);
        (t0, t1) = (t1, t0 - q * t1);
    }
    t0.rem_euclid(p as i64) as u64
}

/// A prime `p < 2^31` with its Barrett constant: `reduce(a)` is `a mod p` for `a < 2^62`
/// (every product of two residues; in fact any `u64`) without a hardware division.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Modulus {
    pub(crate) p: u64,
    m: u64,
}

impl Modulus {
    pub(crate) fn new(p: u64) -> Self {
        Modulus {
            p,
            m: u64::try_from(u128::from(u64::MAX) / u128::from(p)).unwrap_or(u64::MAX),
        }
    }

    /// `a mod p` for any `a` (the quotient estimate is at most one short, since
    /// `m = floor((2^64 - 1) / p)`).
    #[inline]
    pub(crate) fn reduce(self, a: u64) -> u64 {
        let q = ((u128::from(a) * u128::from(self.m)) >> 64) as u64;
        let r = a - q * self.p;
        if r >= self.p { r - self.p } else { r }
    }

    /// `a b mod p` for residues `a, b`.
    #[inline]
    pub(crate) fn mul(self, a: u64, b: u64) -> u64 {
        self.reduce(a * b)
    }
}

/// A big integer prepared for repeated reduction: sign and base-2^32 digits.
#[derive(Debug, Clone)]
pub(crate) struct Digits {
    negative: bool,
    digits: Vec<u32>,
}

impl Digits {
    pub(crate) fn new(x: &BigInt) -> Self {
        let (sign, digits) = x.to_u32_digits();
        Digits {
            negative: sign == Sign::Minus,
            digits,
        }
    }

    /// `x mod p` in `0..p`.
    pub(crate) fn residue(&self, md: Modulus) -> u64 {
        let mut r = 0u64;
        for &d in self.digits.iter().rev() {
            r = md.reduce((r << 32) | u64::from(d));
        }
        if self.negative && r != 0 { md.p - r } else { r }
    }
}

/// The determinant mod `p` of the row-major `n x n` matrix `m` (destroyed) as a fraction
/// `(num, den)`, by division-free elimination: row `i` becomes `piv row_i - m_ik row_k`,
/// which multiplies the determinant by `piv` (collected in `den`); each entry costs two
/// word products and one reduction, and no inverse is taken (see [`batch_divide`]).
pub(crate) fn det_mod_fraction(m: &mut [u64], n: usize, md: Modulus) -> (u64, u64) {
    let p = md.p;
    let (mut num, mut den) = (1u64, 1u64);
    for k in 0..n {
        let Some(r) = (k..n).find(|&r| m[r * n + k] != 0) else {
            return (0, 1);
        };
        if r != k {
            for j in k..n {
                m.swap(k * n + j, r * n + j);
            }
            num = (p - num) % p;
        }
        let piv = m[k * n + k];
        num = md.mul(num, piv);
        let (top, rest) = m.split_at_mut((k + 1) * n);
        let row_k = &top[k * n + k + 1..(k + 1) * n];
        for row_i in rest.chunks_exact_mut(n) {
            let f = row_i[k];
            if f == 0 {
                continue;
            }
            den = md.mul(den, piv);
            let nf = p - f;
            for (x, &y) in row_i[k + 1..].iter_mut().zip(row_k) {
                // piv * x + (p - f) * y < 2^63
                *x = md.reduce(piv * *x + nf * y);
            }
        }
    }
    (num, den)
}

/// The determinant mod `p` of `m` (destroyed).
#[cfg(test)]
pub(crate) fn det_mod(m: &mut [u64], n: usize, md: Modulus) -> u64 {
    let (num, den) = det_mod_fraction(m, n, md);
    md.mul(num, inv_mod(den, md.p))
}

/// `num_i / den_i mod p` for all `i` with one modular inverse (Montgomery's trick); every
/// `den_i` must be non-zero mod `p`.
pub(crate) fn batch_divide(fracs: &[(u64, u64)], md: Modulus) -> Vec<u64> {
    let mut prefix = Vec::with_capacity(fracs.len());
    let mut acc = 1u64;
    for &(_, d) in fracs {
        prefix.push(acc);
        acc = md.mul(acc, d);
    }
    let mut inv = inv_mod(acc, md.p);
    let mut out = vec![0u64; fracs.len()];
    for i in (0..fracs.len()).rev() {
        // inv = (d_0 ... d_i)^-1
        let inv_i = md.mul(inv, prefix[i]);
        out[i] = md.mul(fracs[i].0, inv_i);
        inv = md.mul(inv, fracs[i].1);
    }
    out
}

/// Degree of a polynomial mod `p` (coefficients low to high), `None` for zero.
fn degree(a: &[u64]) -> Option<usize> {
    a.iter().rposition(|&c| c != 0)
}

/// `gcd(a, b)` mod `p` (not normalized), coefficients low to high.
pub(crate) fn poly_gcd(a: &[u64], b: &[u64], p: u64) -> Vec<u64> {
    let (mut a, mut b) = (a.to_vec(), b.to_vec());
    while let Some(db) = degree(&b) {
        // a <- a mod b
        let inv = inv_mod(b[db], p);
        while let Some(da) = degree(&a) {
            if da < db {
                break;
            }
            let f = a[da] * inv % p;
            for j in 0..=db {
                let sub = f * b[j] % p;
                a[da - db + j] = (a[da - db + j] + p - sub) % p;
            }
        }
        std::mem::swap(&mut a, &mut b);
    }
    a.truncate(degree(&a).map_or(0, |d| d + 1));
    a
}

/// The degree of a polynomial mod `p`, `None` for zero (public form of [`degree`]).
pub(crate) fn poly_degree(a: &[u64]) -> Option<usize> {
    degree(a)
}

/// Garner's mixed-radix reconstruction for a fixed list of primes: the constants are
/// computed once and shared by every coefficient.
pub(crate) struct Crt<'a> {
    primes: &'a [u64],
    moduli: Vec<Modulus>,
    /// `(p_0 ... p_{i-1})^-1 mod p_i`.
    inverses: Vec<u64>,
    /// `p_0 ... p_{k-1}`.
    product: BigInt,
}

impl<'a> Crt<'a> {
    pub(crate) fn new(primes: &'a [u64]) -> Self {
        let moduli: Vec<Modulus> = primes.iter().map(|&p| Modulus::new(p)).collect();
        let inverses = (0..primes.len())
            .map(|i| {
                let md = moduli[i];
                let prod = primes[..i]
                    .iter()
                    .fold(1u64, |acc, &q| md.mul(acc, md.reduce(q)));
                inv_mod(prod, md.p)
            })
            .collect();
        let product = primes
            .iter()
            .fold(BigInt::from(1u8), |acc, &p| acc * BigInt::from(p));
        Crt {
            primes,
            moduli,
            inverses,
            product,
        }
    }

    /// The integer `x` with `|x| < (prod p) / 2` and the given residues.
    pub(crate) fn reconstruct(&self, residues: &[u64]) -> BigInt {
        let k = self.primes.len();
        let mut v = vec![0u64; k];
        for i in 0..k {
            let md = self.moduli[i];
            // acc = v_0 + v_1 p_0 + ... + v_{i-1} p_0 ... p_{i-2}  (mod p_i), Horner.
            let mut acc = 0u64;
            for j in (0..i).rev() {
                acc = md.reduce(md.mul(acc, md.reduce(self.primes[j])) + v[j]);
            }
            let r = md.reduce(residues[i]);
            let t = if r >= acc { r - acc } else { r + md.p - acc };
            v[i] = md.mul(t, self.inverses[i]);
        }
        let mut x = BigInt::zero();
        for i in (0..k).rev() {
            x = x * BigInt::from(self.primes[i]) + BigInt::from(v[i]);
        }
        if &x + &x > self.product {
            x - &self.product
        } else {
            x
        }
    }
}

/// Garner's reconstruction of one integer (see [`Crt`]).
#[cfg(test)]
pub(crate) fn crt(residues: &[u64], primes: &[u64]) -> BigInt {
    Crt::new(primes).reconstruct(residues)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn primes_are_prime_and_distinct() {
        let ps = primes();
        assert_eq!(ps.len(), PRIME_COUNT);
        assert_eq!(ps[0], 2_147_483_647);
        assert!(ps.windows(2).all(|w| w[0] > w[1]));
        assert!(ps.iter().all(|&p| p > 1 << 30));
        assert!(!is_prime(2_147_483_647 - 2) || is_prime(2_147_483_645));
        assert!(is_prime(2_147_483_629) && !is_prime(2_147_483_649));
    }

    #[test]
    fn crt_round_trip_of_big_signed_integers() {
        let ps = &primes()[..6];
        for x in [
            BigInt::from(0),
            BigInt::from(-1),
            BigInt::parse_bytes(b"-123456789012345678901234567890123456789", 10).unwrap(),
            BigInt::parse_bytes(b"98765432109876543210987654321", 10).unwrap(),
        ] {
            let d = Digits::new(&x);
            let r: Vec<u64> = ps.iter().map(|&p| d.residue(Modulus::new(p))).collect();
            assert_eq!(crt(&r, ps), x);
        }
    }

    #[test]
    fn determinant_and_gcd_mod_p() {
        let p = primes()[0];
        // [[2,-1,3],[0,4,5],[1,-2,6]] has determinant 51.
        let vals: [i64; 9] = [2, -1, 3, 0, 4, 5, 1, -2, 6];
        let mut m: Vec<u64> = vals
            .iter()
            .map(|&v| v.rem_euclid(p as i64) as u64)
            .collect();
        assert_eq!(det_mod(&mut m, 3, Modulus::new(p)), 51);
        let md = Modulus::new(p);
        let fr = [(6, 3), (p - 10, 5), (7, 7)];
        assert_eq!(batch_divide(&fr, md), vec![2, p - 2, 1]);
        for a in [1u64, 2, 12345, p - 1] {
            assert_eq!(a * inv_mod(a, p) % p, 1);
        }
        let md = Modulus::new(p);
        for a in [0u64, 1, p - 1, p, 2 * p + 5, (1 << 62) - 1] {
            assert_eq!(md.reduce(a), a % p);
        }
        // (t - 2)(t + 1) = t^2 - t - 2, (t - 2)(t - 3) = t^2 - 5t + 6
        let a = [p - 2, p - 1, 1];
        let b = [6, p - 5, 1];
        let g = poly_gcd(&a, &b, p);
        assert_eq!(poly_degree(&g), Some(1));
        // g is a multiple of t - 2: g(2) = 0
        assert_eq!((g[0] + 2 * g[1]) % p, 0);
    }
}
