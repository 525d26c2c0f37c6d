//! The scalar types the exact WSGB formulas run on: `f64` for the library's results and
//! [`BigRational`] for exact checks (SPEC-reduce §11: closed forms in exact arithmetic where
//! they exist).

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Num;

/// A field the WSGB formulas of SPEC-reduce §9.2–§9.5 are written over: `f64` (rounded) or
/// [`BigRational`] (exact). The formulas only add, subtract, multiply and divide by exact
/// integers, so one generic implementation serves both.
pub trait WsgbScalar: Clone + Num {
    /// The integer `k` in this field (exact for `BigRational`, rounded once for `f64`).
    fn from_int(k: i128) -> Self;
    /// The unsigned integer `k` (`u128` binomials and powers of two of §9.1).
    fn from_uint(k: u128) -> Self;
}

impl WsgbScalar for f64 {
    fn from_int(k: i128) -> Self {
        k as f64
    }
    fn from_uint(k: u128) -> Self {
        k as f64
    }
}

impl WsgbScalar for BigRational {
    fn from_int(k: i128) -> Self {
        BigRational::from_integer(BigInt::from(k))
    }
    fn from_uint(k: u128) -> Self {
        BigRational::from_integer(BigInt::from(k))
    }
}

/// The exact value of every `f64` of `x` (finite inputs; a non-finite one maps to 0, callers
/// validate first).
pub fn to_exact_points(x: &[f64]) -> Vec<BigRational> {
    x.iter()
        .map(|v| BigRational::from_float(*v).unwrap_or_default())
        .collect()
}

/// Every exact value rounded once to the nearest `f64`.
pub fn round_exact_points(x: &[BigRational]) -> Vec<f64> {
    use num_traits::ToPrimitive;
    x.iter().map(|v| v.to_f64().unwrap_or(f64::NAN)).collect()
}
