//! Double-word ("double-double") arithmetic with the algorithms of Joldes, Muller and
//! Popescu, *Tight and rigorous error bounds for basic building blocks of double-word
//! arithmetic*, ACM TOMS 44(2), 2017 (beyond the seed). Every operation here has a proven
//! relative error below `16 u^2` (`u = 2^-53`): `AccurateDWPlusDW` (Alg. 6, `3u^2/(1-4u)`),
//! `DWTimesDW1` (Alg. 10, `7u^2`), `DWDivDW2` (Alg. 17, `15u^2 + 56u^3`). No FMA is needed
//! (Dekker's exact product), so the bounds hold on every target.

/// A double-word number `hi + lo` with `|lo| <= ulp(hi) / 2`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Dd {
    pub(crate) hi: f64,
    pub(crate) lo: f64,
}

/// `s + e = a + b` exactly (Knuth's TwoSum).
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `s + e = a + b` exactly when `|a| >= |b|` (Dekker's Fast2Sum).
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// Veltkamp split of `a` into two halves of 26 bits (no overflow for `|a| < 2^996`).
pub(crate) fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a; // 2^27 + 1
    let hi = c - (c - a);
    (hi, a - hi)
}

/// `p + e = a * b` exactly (Dekker's TwoProduct; no underflow in this crate's ranges).
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

impl Dd {
    /// An `f64`, exactly.
    pub(crate) fn from_f64(x: f64) -> Self {
        Self { hi: x, lo: 0.0 }
    }

    /// A `u128` rounded to double-word (exact below `2^106`, relative error `<= u^2` above).
    #[allow(
        clippy::cast_precision_loss,
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "hi is x rounded; x - hi fits an i128 and is rounded once"
    )]
    pub(crate) fn from_u128(x: u128) -> Self {
        let hi = x as f64;
        // `hi` is an integer below 2^128 (binomials here are below 2^127); the difference
        // is at most half an ulp of `hi` and fits an i128.
        let diff = x.wrapping_sub(hi as u128) as i128;
        let (h, l) = fast_two_sum(hi, diff as f64);
        Self { hi: h, lo: l }
    }

    /// `-self`.
    pub(crate) fn neg(self) -> Self {
        Self {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    /// `AccurateDWPlusDW` (JMP Alg. 6).
    pub(crate) fn add(self, y: Self) -> Self {
        let (sh, sl) = two_sum(self.hi, y.hi);
        let (th, tl) = two_sum(self.lo, y.lo);
        let c = sl + th;
        let (vh, vl) = fast_two_sum(sh, c);
        let w = tl + vl;
        let (hi, lo) = fast_two_sum(vh, w);
        Self { hi, lo }
    }

    /// `DWTimesDW1` (JMP Alg. 10).
    pub(crate) fn mul(self, y: Self) -> Self {
        let (ch, cl1) = two_prod(self.hi, y.hi);
        let tl = self.hi * y.lo;
        let th = self.lo * y.hi;
        let cl2 = tl + th;
        let cl3 = cl1 + cl2;
        let (hi, lo) = fast_two_sum(ch, cl3);
        Self { hi, lo }
    }

    /// `DWTimesFP1` (JMP Alg. 7): `self * y` for an `f64` `y`.
    fn mul_f64(self, y: f64) -> Self {
        let (ch, cl1) = two_prod(self.hi, y);
        let cl2 = self.lo * y;
        let (th, tl1) = fast_two_sum(ch, cl2);
        let tl2 = tl1 + cl1;
        let (hi, lo) = fast_two_sum(th, tl2);
        Self { hi, lo }
    }

    /// `DWDivDW2` (JMP Alg. 17).
    pub(crate) fn div(self, y: Self) -> Self {
        let th = self.hi / y.hi;
        let r = y.mul_f64(th);
        let pih = self.hi - r.hi;
        let dl = self.lo - r.lo;
        let d = pih + dl;
        let tl = d / y.hi;
        let (hi, lo) = fast_two_sum(th, tl);
        Self { hi, lo }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_small_identities() {
        let third = Dd::from_f64(1.0).div(Dd::from_f64(3.0));
        let back = third.mul(Dd::from_f64(3.0));
        assert!((back.hi - 1.0).abs() + back.lo.abs() < 1e-31);
        // 2^100 + 1 is exact in double-word.
        let big = Dd::from_u128((1u128 << 100) + 1);
        assert_eq!(big.hi, 2f64.powi(100));
        assert_eq!(big.lo, 1.0);
        let s = big.add(Dd::from_f64(-(2f64.powi(100))));
        assert_eq!((s.hi, s.lo), (1.0, 0.0));
        // C(128, 64) needs 124 bits: relative error below u^2.
        let c = cagd_core::binomial(128, 64);
        let d = Dd::from_u128(c);
        #[allow(clippy::cast_possible_truncation, reason = "test: exact integers")]
        let back = (d.hi as u128).wrapping_add(d.lo as i128 as u128);
        let err = back.abs_diff(c) as f64 / c as f64;
        assert!(err <= 2f64.powi(-104), "{err:e}");
    }
}
