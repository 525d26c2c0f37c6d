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

/// `a^-1 mod p` for `a != 0 mod p` (Fermat).
pub(crate) fn inv_mod(a: u64, p: u64) -> u64 {
    pow_mod(a, p - 2, p)
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
    pub(crate) fn residue(&self, p: u64) -> u64 {
        let mut r = 0u64;
        for &d in self.digits.iter().rev() {
            r = ((r << 32) | u64::from(d)) % p;
        }
        if self.negative && r != 0 { p - r } else { r }
    }
}

/// The determinant mod `p` of the row-major `n x n` matrix `m` (destroyed), by Gaussian
/// elimination with one modular inverse per pivot.
pub(crate) fn det_mod(m: &mut [u64], n: usize, p: u64) -> u64 {
    let mut det = 1u64;
    for k in 0..n {
        let Some(r) = (k..n).find(|&r| m[r * n + k] != 0) else {
            return 0;
        };
        if r != k {
            for j in k..n {
                m.swap(k * n + j, r * n + j);
            }
            det = (p - det) % p;
        }
        let piv = m[k * n + k];
        det = det * piv % p;
        let inv = inv_mod(piv, p);
        for i in k + 1..n {
            let f = m[i * n + k] * inv % p;
            if f == 0 {
                continue;
            }
            for j in k + 1..n {
                let sub = f * m[k * n + j] % p;
                m[i * n + j] = (m[i * n + j] + p - sub) % p;
            }
        }
    }
    det
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

/// Garner's mixed-radix reconstruction of the integer `x` with `|x| < (prod p) / 2` from its
/// residues.
pub(crate) fn crt(residues: &[u64], primes: &[u64]) -> BigInt {
    let k = residues.len();
    // Mixed-radix digits v_i: x = v_0 + v_1 p_0 + v_2 p_0 p_1 + ...
    let mut v = vec![0u64; k];
    for i in 0..k {
        let p = primes[i];
        let mut t = residues[i] % p;
        // t = (r_i - (v_0 + v_1 p_0 + ... )) / (p_0 ... p_{i-1}) mod p_i
        let mut acc = 0u64;
        let mut prod = 1u64;
        for j in 0..i {
            acc = (acc + v[j] * prod) % p;
            prod = prod * (primes[j] % p) % p;
        }
        t = (t + p - acc) % p;
        v[i] = t * inv_mod(prod, p) % p;
    }
    // Horner from the top digit.
    let mut x = BigInt::zero();
    for i in (0..k).rev() {
        x = x * BigInt::from(primes[i]) + BigInt::from(v[i]);
    }
    // Symmetric range.
    let mut modulus = BigInt::from(1u8);
    for &p in primes.iter().take(k) {
        modulus *= BigInt::from(p);
    }
    if &x + &x > modulus { x - modulus } else { x }
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
            let r: Vec<u64> = ps.iter().map(|&p| d.residue(p)).collect();
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
        assert_eq!(det_mod(&mut m, 3, p), 51);
        // (t - 2)(t + 1) = t^2 - t - 2, (t - 2)(t - 3) = t^2 - 5t + 6
        let a = [p - 2, p - 1, 1];
        let b = [6, p - 5, 1];
        let g = poly_gcd(&a, &b, p);
        assert_eq!(poly_degree(&g), Some(1));
        // g is a multiple of t - 2: g(2) = 0
        assert_eq!((g[0] + 2 * g[1]) % p, 0);
    }
}
