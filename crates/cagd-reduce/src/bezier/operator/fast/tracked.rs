//! Numbers that carry a rigorous bound of their own error (a running error analysis, beyond
//! the seed): every value `x` of a construction is a computed `v` and an `f64` `e` with
//! `|v - x| <= e`, where `x` is what exact arithmetic would give. Each operation adds its
//! rounding (`U |result|`, `U` the base arithmetic's proven relative error bound) to the
//! propagated errors of its operands. The `e` are themselves computed in `f64`; after at
//! most `10^6` operations their own relative rounding is below `10^-9`, which
//! [`Tracked::err`] covers by doubling.

use super::dd::Dd;
use super::wide::Wide;

/// A base arithmetic: `f64` or double-word, with its proven relative error per operation.
pub(crate) trait Base: Copy + PartialEq + Send + Sync + 'static {
    /// Bound of `|fl(x op y) - x op y| / |x op y|` for `+ - * /`.
    const U: f64;
    /// Bound of `|to_f64(x) - x| / |x|` (`0` for `f64` itself: no final rounding).
    const TO_F64: f64;
    /// Whether a stepwise build in this arithmetic gives up early when its proven error
    /// runs away (the `f64` attempt, which has a next route to fall back to).
    const GIVE_UP_EARLY: bool = false;
    /// An `f64`, exactly.
    fn of(x: f64) -> Self;
    /// A `u128` rounded, with its absolute rounding error bound.
    fn of_u128(x: u128) -> (Self, f64);
    /// `hi + lo` (`hi` the nearest `f64` of an integer, `lo` the rest rounded to `f64`,
    /// see [`binom_parts`]) with its absolute error bound.
    fn of_parts(hi: f64, lo: f64) -> (Self, f64);
    /// The operations.
    fn add(self, y: Self) -> Self;
    /// `self - y`.
    fn sub(self, y: Self) -> Self;
    /// `self * y`.
    fn mul(self, y: Self) -> Self;
    /// `self / y`.
    fn div(self, y: Self) -> Self;
    /// The nearest `f64` (round-to-nearest of the value, up to one more rounding).
    fn to_f64(self) -> f64;
    /// `C(n, k)` (`0 <= k <= n <= MAX_BINOMIAL_N`) with its absolute error bound.
    fn of_binom(n: usize, k: usize) -> (Self, f64) {
        let (hi, lo) = binom_parts(n, k);
        Self::of_parts(hi, lo)
    }
    /// `1 / C(n, k)` (`0 <= k <= n <= MAX_BINOMIAL_N`) with its absolute error bound (the
    /// raw propagated bound of [`Tracked::div`]).
    fn of_recip_binom(n: usize, k: usize) -> (Self, f64) {
        let (b, e) = Self::of_binom(n, k);
        let q = Tracked::<Self>::of(1.0).div(Tracked::from_parts(b, e));
        (q.value(), q.bound())
    }
}

impl Base for f64 {
    const U: f64 = f64::EPSILON / 2.0;
    const TO_F64: f64 = 0.0;
    const GIVE_UP_EARLY: bool = true;
    fn of(x: f64) -> Self {
        x
    }
    #[allow(clippy::cast_precision_loss, reason = "rounded; the error is returned")]
    fn of_u128(x: u128) -> (Self, f64) {
        let v = x as f64;
        let e = if x < (1u128 << 53) { 0.0 } else { v * Self::U };
        (v, e)
    }
    fn of_parts(hi: f64, lo: f64) -> (Self, f64) {
        // The rest `C - hi` is `lo` up to one rounding of it (`u |lo|`, and `2^-100 hi`
        // covers the case of a renormalised pair).
        (
            hi,
            lo.abs() * (1.0 + 2.0 * f64::EPSILON) + hi * 2f64.powi(-100),
        )
    }
    fn add(self, y: Self) -> Self {
        self + y
    }
    fn sub(self, y: Self) -> Self {
        self - y
    }
    fn mul(self, y: Self) -> Self {
        self * y
    }
    fn div(self, y: Self) -> Self {
        self / y
    }
    fn to_f64(self) -> f64 {
        self
    }
}

impl Base for Dd {
    /// `16 u^2`: covers the bounds of all three double-word algorithms (see `dd.rs`).
    const U: f64 = 16.0 * (f64::EPSILON / 2.0) * (f64::EPSILON / 2.0);
    /// `hi + lo` rounded once (`u |x|`), allowed as `eps |x|`.
    const TO_F64: f64 = f64::EPSILON;
    fn of(x: f64) -> Self {
        Dd::from_f64(x)
    }
    #[allow(clippy::cast_precision_loss, reason = "a bound")]
    fn of_u128(x: u128) -> (Self, f64) {
        let e = if x < (1u128 << 106) {
            0.0
        } else {
            (x as f64) * Self::U
        };
        (Dd::from_u128(x), e)
    }
    fn of_parts(hi: f64, lo: f64) -> (Self, f64) {
        // Exact below 2^106 (lo is then the exact rest); above, relative error <= u^2.
        let e = if hi < 2f64.powi(106) {
            0.0
        } else {
            hi * Self::U
        };
        (Dd { hi, lo }, e)
    }
    fn add(self, y: Self) -> Self {
        Dd::add(self, y)
    }
    fn sub(self, y: Self) -> Self {
        Dd::add(self, y.neg())
    }
    fn mul(self, y: Self) -> Self {
        Dd::mul(self, y)
    }
    fn div(self, y: Self) -> Self {
        Dd::div(self, y)
    }
    fn to_f64(self) -> f64 {
        self.hi + self.lo
    }
    /// From a process-wide table, one row per `n` built on first use (the truncations'
    /// coefficient functionals ask for `O(n^2)` of them per build, each a double-word
    /// division).
    fn of_recip_binom(n: usize, k: usize) -> (Self, f64) {
        use std::sync::OnceLock;
        static ROWS: [OnceLock<Vec<(Dd, f64)>>; cagd_core::MAX_BINOMIAL_N + 1] =
            [const { OnceLock::new() }; cagd_core::MAX_BINOMIAL_N + 1];
        let Some(row) = ROWS.get(n) else {
            return (Dd::from_f64(0.0), f64::INFINITY);
        };
        let row = row.get_or_init(|| {
            (0..=n)
                .map(|k| {
                    let (b, e) = Self::of_binom(n, k);
                    let q = Tracked::<Self>::of(1.0).div(Tracked::from_parts(b, e));
                    (q.value(), q.bound())
                })
                .collect()
        });
        row.get(k)
            .copied()
            .unwrap_or((Dd::from_f64(0.0), f64::INFINITY))
    }
}

impl Base for Wide {
    const U: f64 = Wide::U;
    /// One rounding (`u |x|`), allowed as `eps |x|`.
    const TO_F64: f64 = f64::EPSILON;
    fn of(x: f64) -> Self {
        Wide::from_f64(x)
    }
    fn of_u128(x: u128) -> (Self, f64) {
        (Wide::from_u128(x), 0.0)
    }
    fn of_parts(hi: f64, lo: f64) -> (Self, f64) {
        // As for double-word: exact below 2^106, relative error <= u^2 above (unused for
        // binomials, which `of_binom` takes exactly).
        let e = if hi < 2f64.powi(106) {
            0.0
        } else {
            hi * 2f64.powi(-104)
        };
        (Wide::from_f64(hi).add(Wide::from_f64(lo)), e)
    }
    fn of_binom(n: usize, k: usize) -> (Self, f64) {
        // Beyond the exact table (not reached: degrees are validated first) as the other
        // bases do: `0`.
        (
            Wide::from_u128(cagd_core::try_binomial(n, k).unwrap_or(0)),
            0.0,
        )
    }
    fn add(self, y: Self) -> Self {
        Wide::add(self, y)
    }
    fn sub(self, y: Self) -> Self {
        Wide::add(self, y.neg())
    }
    fn mul(self, y: Self) -> Self {
        Wide::mul(self, y)
    }
    fn div(self, y: Self) -> Self {
        Wide::div(self, y)
    }
    fn to_f64(self) -> f64 {
        Wide::to_f64(self)
    }
}

/// `C(n, k)` as `(hi, lo)`: `hi` the nearest `f64`, `lo` the rest `C(n,k) - hi` rounded to
/// `f64` (exact below `2^106`), from a process-wide table (the `u128 -> f64` conversions are
/// libcalls, and the builders ask for thousands of binomials).
pub(crate) fn binom_parts(n: usize, k: usize) -> (f64, f64) {
    use std::sync::OnceLock;
    static TABLE: OnceLock<Vec<Vec<(f64, f64)>>> = OnceLock::new();
    let t = TABLE.get_or_init(|| {
        (0..=cagd_core::MAX_BINOMIAL_N)
            .map(|n| {
                (0..=n)
                    .map(|k| {
                        let d = Dd::from_u128(cagd_core::binomial(n, k));
                        (d.hi, d.lo)
                    })
                    .collect()
            })
            .collect()
    });
    t.get(n)
        .and_then(|r| r.get(k))
        .copied()
        .unwrap_or((0.0, 0.0))
}

/// A computed value and a bound of its distance from the exact value.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Tracked<B> {
    v: B,
    e: f64,
}

impl<B: Base> Tracked<B> {
    /// An exact `f64` constant.
    pub(crate) fn of(x: f64) -> Self {
        Self {
            v: B::of(x),
            e: 0.0,
        }
    }

    /// An exact integer (rounded if needed, the rounding tracked).
    pub(crate) fn int(x: u128) -> Self {
        let (v, e) = B::of_u128(x);
        Self { v, e }
    }

    /// A small signed integer, exactly.
    #[allow(clippy::cast_precision_loss, reason = "|x| <= 2^20 here")]
    pub(crate) fn small(x: i64) -> Self {
        Self::of(x as f64)
    }

    /// `C(n, k)` (`0` outside `0 <= k <= n`).
    pub(crate) fn binom(n: i64, k: i64) -> Self {
        if n < 0 || k < 0 || k > n {
            return Self::of(0.0);
        }
        #[allow(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "0 <= k <= n <= 130"
        )]
        let (v, e) = B::of_binom(n as usize, k as usize);
        Self { v, e }
    }

    /// `1 / C(n, k)` (an infinite error bound outside `0 <= k <= n`).
    pub(crate) fn recip_binom(n: i64, k: i64) -> Self {
        if n < 0 || k < 0 || k > n {
            return Self {
                v: B::of(0.0),
                e: f64::INFINITY,
            };
        }
        #[allow(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "0 <= k <= n <= 130"
        )]
        let (v, e) = B::of_recip_binom(n as usize, k as usize);
        Self { v, e }
    }

    fn mag(self) -> f64 {
        self.v.to_f64().abs()
    }

    /// A computed value `v` and a bound `e` of its distance from the exact value.
    pub(crate) fn from_parts(v: B, e: f64) -> Self {
        Self { v, e }
    }

    /// The computed value in the base arithmetic.
    pub(crate) fn value(self) -> B {
        self.v
    }

    /// The raw propagated error bound (before [`Tracked::err`]'s final allowances).
    pub(crate) fn bound(self) -> f64 {
        self.e
    }

    /// The value rounded to `f64`.
    pub(crate) fn val(self) -> f64 {
        self.v.to_f64()
    }

    /// A rigorous bound of `|val - exact|` (the final rounding to `f64` and the rounding of
    /// the error computation itself included).
    pub(crate) fn err(self) -> f64 {
        2.0 * (self.e + f64::EPSILON * self.mag())
    }

    fn with(v: B, e: f64) -> Self {
        let r = Self { v, e };
        Self {
            v,
            e: e + B::U * r.mag(),
        }
    }

    /// `self + y`.
    pub(crate) fn add(self, y: Self) -> Self {
        Self::with(self.v.add(y.v), self.e + y.e)
    }

    /// `self - y`.
    pub(crate) fn sub(self, y: Self) -> Self {
        Self::with(self.v.sub(y.v), self.e + y.e)
    }

    /// `self * y`.
    pub(crate) fn mul(self, y: Self) -> Self {
        Self::with(
            self.v.mul(y.v),
            self.mag() * y.e + y.mag() * self.e + self.e * y.e,
        )
    }

    /// `self / y` (an infinite error bound if `y` is not bounded away from zero).
    pub(crate) fn div(self, y: Self) -> Self {
        let q = self.v.div(y.v);
        let room = y.mag() - y.e;
        let e = if room > 0.0 {
            (self.e + q.to_f64().abs() * y.e) / room
        } else {
            f64::INFINITY
        };
        Self::with(q, e)
    }

    /// `-self`.
    pub(crate) fn neg(self) -> Self {
        Self::of(0.0).sub(self)
    }

    /// `self + a * b`.
    pub(crate) fn fma(self, a: Self, b: Self) -> Self {
        self.add(a.mul(b))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_cover_the_error() {
        // sum_{i} (-1)^i C(40, i) / C(80, i) in f64 and double-word vs the exact rational.
        use num_rational::BigRational;
        let mut exact = BigRational::from_integer(0.into());
        let mut f = Tracked::<f64>::of(0.0);
        let mut d = Tracked::<Dd>::of(0.0);
        for i in 0..=40i64 {
            let t = crate::exact::binom_q(40, i) / crate::exact::binom_q(80, i);
            let (tf, td) = (
                Tracked::<f64>::binom(40, i).div(Tracked::binom(80, i)),
                Tracked::<Dd>::binom(40, i).div(Tracked::binom(80, i)),
            );
            if i % 2 == 0 {
                exact += t;
                f = f.add(tf);
                d = d.add(td);
            } else {
                exact -= t;
                f = f.sub(tf);
                d = d.sub(td);
            }
        }
        for (v, e) in [(f.val(), f.err()), (d.val(), d.err())] {
            let diff = BigRational::from_float(v).unwrap() - &exact;
            let diff = crate::exact::q_to_f64(&num_traits::Signed::abs(&diff));
            assert!(diff <= e, "{diff:e} > {e:e}");
        }
        // The double-word error is the final rounding to f64 only.
        assert!(d.err() <= 4.0 * f64::EPSILON * d.val().abs() + 1e-28 && d.err() < f.err());
    }
}
