//! A 256-bit binary floating-point number (beyond the seed): the third base arithmetic of
//! the fast routes, for the constructions whose proven double-word error is above the goal
//! (the stepwise perturbation at degree 40–64, whose running error bound grows by about
//! `2.4` per step; the truncations close to `m = n`). Every operation computes the exact
//! result of its operands in an integer buffer and truncates it once to 256 significant
//! bits (toward zero), so its relative error is below `2^-255`; division truncates twice
//! (the integer quotient, then the normalisation), below `2^-254`. [`Wide::U`] allows
//! `2^-250`.
//!
//! Exact beside `BigRational` and about 20–100 times cheaper: no allocation (a `Copy` value
//! of four limbs), no gcd. Binomials up to `C(130, 65) < 2^128` are exact.

/// `(-1)^neg * m * 2^exp`, `m` little-endian limbs with the top bit of `m[3]` set, or all
/// limbs zero for the value `0`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Wide {
    neg: bool,
    exp: i64,
    m: [u64; 4],
}

/// Bits `[s, s + 256)` of the integer `buf` (little-endian limbs; bits outside are zero).
fn take4(buf: &[u64], s: i64) -> [u64; 4] {
    let get = |q: i64| -> u64 {
        usize::try_from(q)
            .ok()
            .and_then(|q| buf.get(q))
            .copied()
            .unwrap_or(0)
    };
    let mut out = [0u64; 4];
    for (i, o) in out.iter_mut().enumerate() {
        let p = s + 64 * i as i64;
        let (q, off) = (p.div_euclid(64), p.rem_euclid(64));
        *o = if off == 0 {
            get(q)
        } else {
            (get(q) >> off) | (get(q + 1) << (64 - off))
        };
    }
    out
}

/// `2^e` times `x`, without overflow in the intermediate powers.
fn ldexp(mut x: f64, mut e: i64) -> f64 {
    while e > 1000 {
        x *= 2f64.powi(1000);
        e -= 1000;
        if x.is_infinite() {
            return x;
        }
    }
    while e < -1000 {
        x *= 2f64.powi(-1000);
        e += 1000;
        if x == 0.0 {
            return x;
        }
    }
    #[allow(
        clippy::cast_sign_loss,
        reason = "-1000 <= e <= 1000, so e + 1023 is positive"
    )]
    let p = f64::from_bits(((e + 1023) as u64) << 52);
    x * p
}

impl Wide {
    /// A proven bound of the relative error of one operation (see the module docs).
    pub(crate) const U: f64 = 5.527_147_875_260_444e-76; // 2^-250

    /// Zero.
    pub(crate) const ZERO: Self = Self {
        neg: false,
        exp: 0,
        m: [0; 4],
    };

    fn is_zero(&self) -> bool {
        self.m[3] == 0
    }

    /// `(-1)^neg * buf * 2^e`, truncated to 256 significant bits.
    fn normalize(neg: bool, buf: &[u64], e: i64) -> Self {
        let Some(t) = buf.iter().rposition(|&w| w != 0) else {
            return Self::ZERO;
        };
        let bits = 64 * t as i64 + 64 - i64::from(buf[t].leading_zeros());
        let s = bits - 256;
        Self {
            neg,
            exp: e + s,
            m: take4(buf, s),
        }
    }

    /// An `f64`, exactly.
    pub(crate) fn from_f64(x: f64) -> Self {
        if x == 0.0 || !x.is_finite() {
            // Non-finite inputs do not occur (the constructions use finite constants).
            return Self::ZERO;
        }
        let bits = x.to_bits();
        let biased = i64::try_from((bits >> 52) & 0x7ff).unwrap_or(0);
        let frac = bits & ((1u64 << 52) - 1);
        let (mant, e) = if biased == 0 {
            (frac, -1074)
        } else {
            (frac | (1u64 << 52), biased - 1075)
        };
        Self::normalize(x < 0.0, &[mant], e)
    }

    /// A `u128`, exactly.
    #[allow(clippy::cast_possible_truncation, reason = "the two halves of x")]
    pub(crate) fn from_u128(x: u128) -> Self {
        Self::normalize(false, &[x as u64, (x >> 64) as u64], 0)
    }

    /// `-self`.
    pub(crate) fn neg(self) -> Self {
        if self.is_zero() {
            return self;
        }
        Self {
            neg: !self.neg,
            ..self
        }
    }

    /// `|self| >= |y|`.
    fn mag_ge(&self, y: &Self) -> bool {
        if y.is_zero() {
            return true;
        }
        if self.is_zero() {
            return false;
        }
        (self.exp, self.m[3], self.m[2], self.m[1], self.m[0])
            >= (y.exp, y.m[3], y.m[2], y.m[1], y.m[0])
    }

    /// `self + y`, truncated once.
    pub(crate) fn add(self, y: Self) -> Self {
        if y.is_zero() {
            return self;
        }
        if self.is_zero() {
            return y;
        }
        let (big, small) = if self.mag_ge(&y) {
            (self, y)
        } else {
            (y, self)
        };
        let d = big.exp - small.exp;
        if d > 400 {
            // |small| < 2^-399 |big|: below the truncation of the result.
            return big;
        }
        // big.m << d and small.m in a 768-bit buffer, exactly.
        let mut buf = [0u64; 12];
        let (q, off) = (usize::try_from(d / 64).unwrap_or(0), d % 64);
        for (i, &w) in big.m.iter().enumerate() {
            buf[q + i] |= w << off;
            if off != 0 {
                buf[q + i + 1] |= w >> (64 - off);
            }
        }
        if big.neg == small.neg {
            let mut carry = 0u64;
            for (i, b) in buf.iter_mut().enumerate() {
                let w = if i < 4 { small.m[i] } else { 0 };
                let (s1, c1) = b.overflowing_add(w);
                let (s2, c2) = s1.overflowing_add(carry);
                *b = s2;
                carry = u64::from(c1) + u64::from(c2);
            }
        } else {
            let mut borrow = 0u64;
            for (i, b) in buf.iter_mut().enumerate() {
                let w = if i < 4 { small.m[i] } else { 0 };
                let (s1, c1) = b.overflowing_sub(w);
                let (s2, c2) = s1.overflowing_sub(borrow);
                *b = s2;
                borrow = u64::from(c1) + u64::from(c2);
            }
        }
        Self::normalize(big.neg, &buf, small.exp)
    }

    /// `self * y`, truncated once.
    pub(crate) fn mul(self, y: Self) -> Self {
        if self.is_zero() || y.is_zero() {
            return Self::ZERO;
        }
        let mut buf = [0u64; 8];
        for i in 0..4 {
            let mut carry = 0u128;
            for j in 0..4 {
                let t = u128::from(self.m[i]) * u128::from(y.m[j]) + u128::from(buf[i + j]) + carry;
                #[allow(clippy::cast_possible_truncation, reason = "the low limb")]
                {
                    buf[i + j] = t as u64;
                }
                carry = t >> 64;
            }
            #[allow(clippy::cast_possible_truncation, reason = "carry < 2^64")]
            {
                buf[i + 4] = carry as u64;
            }
        }
        Self::normalize(self.neg != y.neg, &buf, self.exp + y.exp)
    }

    /// `self / y`: `floor(m_x 2^256 / m_y)` truncated to 256 bits (zero for `y = 0`, whose
    /// tracked error is infinite).
    pub(crate) fn div(self, y: Self) -> Self {
        if self.is_zero() || y.is_zero() {
            return Self::ZERO;
        }
        let neg = self.neg != y.neg;
        let e = self.exp - y.exp - 256;
        if y.m[0] == 0 && y.m[1] == 0 && y.m[2] == 0 {
            // A divisor of at most 64 significant bits: m_x 2^256 / (d 2^192) = m_x 2^64 / d,
            // by short division.
            let d = u128::from(y.m[3]);
            let num = [0u64, self.m[0], self.m[1], self.m[2], self.m[3]];
            let mut q = [0u64; 5];
            let mut rem = 0u128;
            for i in (0..5).rev() {
                let cur = (rem << 64) | u128::from(num[i]);
                #[allow(clippy::cast_possible_truncation, reason = "cur / d < 2^64")]
                {
                    q[i] = (cur / d) as u64;
                }
                rem = cur % d;
            }
            return Self::normalize(neg, &q, e);
        }
        // Binary long division: the quotient has 256 or 257 bits (m_x, m_y in [2^255, 2^256)).
        let mut r = [self.m[0], self.m[1], self.m[2], self.m[3], 0u64];
        let b = [y.m[0], y.m[1], y.m[2], y.m[3], 0u64];
        let mut q = [0u64; 5];
        let ge = |r: &[u64; 5]| -> bool {
            for i in (0..5).rev() {
                if r[i] != b[i] {
                    return r[i] > b[i];
                }
            }
            true
        };
        let sub = |r: &mut [u64; 5]| {
            let mut borrow = 0u64;
            for i in 0..5 {
                let (s1, c1) = r[i].overflowing_sub(b[i]);
                let (s2, c2) = s1.overflowing_sub(borrow);
                r[i] = s2;
                borrow = u64::from(c1) + u64::from(c2);
            }
        };
        if ge(&r) {
            sub(&mut r);
            q[4] = 1;
        }
        for pos in (0..256).rev() {
            for i in (1..5).rev() {
                r[i] = (r[i] << 1) | (r[i - 1] >> 63);
            }
            r[0] <<= 1;
            if ge(&r) {
                sub(&mut r);
                q[pos / 64] |= 1u64 << (pos % 64);
            }
        }
        Self::normalize(neg, &q, e)
    }

    /// The nearest `f64` of the top 64 bits (up to one more rounding of the value).
    #[allow(
        clippy::cast_precision_loss,
        reason = "rounded; covered by Tracked::err"
    )]
    pub(crate) fn to_f64(self) -> f64 {
        if self.is_zero() {
            return 0.0;
        }
        let v = ldexp(self.m[3] as f64, self.exp + 192);
        if self.neg { -v } else { v }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::{Q, q_to_f64};
    use num_bigint::BigInt;
    use num_traits::{One, Signed, Zero};

    fn exact(x: Wide) -> Q {
        let mut n = BigInt::zero();
        for &w in x.m.iter().rev() {
            n = (n << 64) + BigInt::from(w);
        }
        let p = if x.exp >= 0 {
            Q::from_integer(BigInt::one() << x.exp)
        } else {
            Q::new(BigInt::one(), BigInt::one() << (-x.exp))
        };
        let v = Q::from_integer(n) * p;
        if x.neg { -v } else { v }
    }

    fn rel(got: Wide, want: &Q) -> f64 {
        if want.is_zero() {
            return if got.is_zero() { 0.0 } else { 1.0 };
        }
        q_to_f64(&((exact(got) - want).abs() / want.abs()))
    }

    #[test]
    fn operations_are_within_u_of_the_exact_result() {
        // Operands with full mantissas and very different scales and signs.
        let seeds = [
            1.0 / 3.0,
            -7.0 / 11.0,
            1e-30,
            -2.5e40,
            123_456_789.0,
            1.0,
            -1.0,
            2f64.powi(-60) * 3.0,
            5e-310,
        ];
        let mut xs: Vec<Wide> = seeds.iter().map(|&s| Wide::from_f64(s)).collect();
        // Full-mantissa values: quotients of the seeds and big binomials.
        let third = Wide::from_f64(1.0).div(Wide::from_f64(3.0));
        xs.push(third);
        xs.push(Wide::from_u128(cagd_core::binomial(128, 64)).div(Wide::from_f64(-7.0)));
        xs.push(Wide::from_u128(cagd_core::binomial(130, 41)).div(third));
        for &x in &xs {
            assert!(rel(Wide::from_f64(x.to_f64()), &exact(x)) <= f64::EPSILON);
            for &y in &xs {
                let (ex, ey) = (exact(x), exact(y));
                assert!(rel(x.add(y), &(&ex + &ey)) <= Wide::U, "add");
                assert!(rel(x.add(y.neg()), &(&ex - &ey)) <= Wide::U, "sub");
                assert!(rel(x.mul(y), &(&ex * &ey)) <= Wide::U, "mul");
                assert!(rel(x.div(y), &(&ex / &ey)) <= Wide::U, "div");
            }
        }
        // Exact integers and cancellation.
        let c = cagd_core::binomial(128, 64);
        let w = Wide::from_u128(c);
        assert_eq!(exact(w), Q::from_integer(BigInt::from(c)));
        assert!(w.add(w.neg()).is_zero());
        assert_eq!(Wide::from_f64(1.0).div(Wide::ZERO), Wide::ZERO);
    }
}
