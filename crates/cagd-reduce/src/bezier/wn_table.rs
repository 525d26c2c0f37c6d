//! The error factor `W_n = max_{t in [0,1]} |sum_{i=1}^{n-1} (-1)^(n-i) C(n,i) B_i^n(t)|` of
//! the perturbation reduction (SPEC-reduce §2.1, the erratum of seed 000 eqs. 14.2.7 /
//! 14.2.8: `W_n > 1` for `n >= 6`, so the printed bound `||F|| / (C(2n,n) - 2)` is false).
//!
//! The table was computed with 50-digit arithmetic (mpmath: `w_n(t) = P_n(2t-1) -
//! (-1)^n (1-t)^n - t^n`, a 6001-point grid on `[0, 1/2]` — `|w_n|` is symmetric — and a
//! golden-section refinement of every local maximum to 1e-40) and **rounded up** to 17
//! significant digits. The unit test `table_is_certified` re-derives every entry
//! independently in `f64` (Legendre three-term recurrence, a finer grid, golden-section
//! refinement), evaluates `|w_n|` at the maximiser found **exactly** in rationals and checks
//! `table >= |w_n(t*)|` (rigorous) and `|table - W_n(f64)| <= 1e-13` (tightness).

/// `W_n` rounded up, `n = 0..=64` (`0` for `n < 2`, where the method does not apply).
#[allow(
    clippy::excessive_precision,
    reason = "17 significant digits, rounded up from 50-digit values: kept as computed"
)]
const W_TABLE: [f64; 65] = [
    0.0,                 // n = 0
    0.0,                 // n = 1
    1.0000000000000000,  // n = 2
    0.86602540378443865, // n = 3
    0.94117647058823530, // n = 4
    0.99265915099320451, // n = 5
    1.0342851717767610,  // n = 6
    1.0682853104423882,  // n = 7
    1.0965398054975035,  // n = 8
    1.1203781466094809,  // n = 9
    1.1407569470805544,  // n = 10
    1.1583778957808978,  // n = 11
    1.1737659204780264,  // n = 12
    1.1873210023813309,  // n = 13
    1.1993530488651661,  // n = 14
    1.2101058126417084,  // n = 15
    1.2197736181393852,  // n = 16
    1.2285132763210991,  // n = 17
    1.2364527195542929,  // n = 18
    1.2436973596220785,  // n = 19
    1.2503348379805781,  // n = 20
    1.2564386225731706,  // n = 21
    1.2620707648921358,  // n = 22
    1.2672840373143281,  // n = 23
    1.2721236073168128,  // n = 24
    1.2766283615660919,  // n = 25
    1.2808319624458626,  // n = 26
    1.2847636980681891,  // n = 27
    1.2884491713993823,  // n = 28
    1.2919108629606019,  // n = 29
    1.2951685933764700,  // n = 30
    1.2982399059829624,  // n = 31
    1.3011403851732476,  // n = 32
    1.3038839227400408,  // n = 33
    1.3064829418701362,  // n = 34
    1.3089485864497308,  // n = 35
    1.3112908817952143,  // n = 36
    1.3135188717218398,  // n = 37
    1.3156407359200869,  // n = 38
    1.3176638908657245,  // n = 39
    1.3195950768990438,  // n = 40
    1.3214404336371382,  // n = 41
    1.3232055655044235,  // n = 42
    1.3248955988608953,  // n = 43
    1.3265152319596184,  // n = 44
    1.3280687787627632,  // n = 45
    1.3295602074799398,  // n = 46
    1.3309931745563981,  // n = 47
    1.3323710547261805,  // n = 48
    1.3336969676520321,  // n = 49
    1.3349738015962220,  // n = 50
    1.3362042345015435,  // n = 51
    1.3373907528073563,  // n = 52
    1.3385356682797531,  // n = 53
    1.3396411330962962,  // n = 54
    1.3407091533930420,  // n = 55
    1.3417416014537808,  // n = 56
    1.3427402266977390,  // n = 57
    1.3437066656017683,  // n = 58
    1.3446424506757133,  // n = 59
    1.3455490185947740,  // n = 60
    1.3464277175798596,  // n = 61
    1.3472798141058740,  // n = 62
    1.3481064990082987,  // n = 63
    1.3489088930501423,  // n = 64
];

/// `W_n` for `2 <= n <= 64`, rounded up (an upper bound of the true maximum; `0.0` outside
/// the range). The certified error of the perturbation reduction is
/// `W_n ||F|| / (C(2n,n) - 2)` (SPEC-reduce §2.1). The returned value already includes the
/// rounding of the decimal table entry to `f64` (one extra ulp upwards).
pub fn perturbation_error_factor(n: usize) -> f64 {
    W_TABLE
        .get(n)
        .map_or(0.0, |w| w * (1.0 + 2.0 * f64::EPSILON))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `w_n(t)` by the Legendre recurrence (`|P_k| <= 1` on `[-1,1]`: stable).
    fn w(n: usize, t: f64) -> f64 {
        let x = 2.0 * t - 1.0;
        let (mut p0, mut p1) = (1.0, x);
        for k in 1..n {
            let kf = k as f64;
            let p2 = ((2.0 * kf + 1.0) * x * p1 - kf * p0) / (kf + 1.0);
            p0 = p1;
            p1 = p2;
        }
        let sign = if n % 2 == 0 { 1.0 } else { -1.0 };
        p1 - sign * cagd_core::kernel::powu(1.0 - t, n) - cagd_core::kernel::powu(t, n)
    }

    /// The largest `|w_n|` found in `f64` and the parameter where it is attained.
    fn max_abs_w(n: usize) -> (f64, f64) {
        let k = 20_000usize;
        let h = 0.5 / k as f64;
        // The grid runs one step past 1/2 so that a maximum at the symmetry point is found.
        let vals: Vec<f64> = (0..=k + 1).map(|i| w(n, i as f64 * h).abs()).collect();
        let (mut best, mut arg) = (0.0, 0.0);
        for i in 1..=k {
            if vals[i] >= vals[i - 1] && vals[i] >= vals[i + 1] {
                let (mut a, mut b) = ((i - 1) as f64 * h, (i + 1) as f64 * h);
                let g = (5f64.sqrt() - 1.0) / 2.0;
                for _ in 0..80 {
                    let c = b - g * (b - a);
                    let d = a + g * (b - a);
                    if w(n, c).abs() > w(n, d).abs() {
                        b = d;
                    } else {
                        a = c;
                    }
                }
                let t = 0.5 * (a + b);
                if w(n, t).abs() > best {
                    (best, arg) = (w(n, t).abs(), t);
                }
            }
        }
        (best, arg)
    }

    /// `|w_n(t)|` exactly (Bernstein form in rationals) for a dyadic `t`.
    fn exact_abs_w(n: usize, t: f64) -> num_rational::BigRational {
        use crate::exact::{Q, binom_q, to_i};
        use num_traits::{One, Signed, Zero};
        let t = Q::from_float(t).expect("finite");
        let s = Q::one() - &t;
        let ni = to_i(n);
        let mut acc = Q::zero();
        for i in 1..ni {
            let mut term = binom_q(ni, i) * binom_q(ni, i);
            for _ in 0..i {
                term *= &t;
            }
            for _ in 0..(ni - i) {
                term *= &s;
            }
            if (ni - i) % 2 == 1 {
                term = -term;
            }
            acc += term;
        }
        acc.abs()
    }

    #[test]
    fn table_is_certified() {
        for n in 2..=64 {
            let t = perturbation_error_factor(n);
            let (m, arg) = max_abs_w(n);
            // Rigorous: the table is above an exactly evaluated attained value ...
            let exact = exact_abs_w(n, arg);
            let table = crate::exact::Q::from_float(t).expect("finite");
            assert!(table >= exact, "n = {n}: table {t} below |w({arg})|");
            // ... and agrees with the independent f64 search to f64 evaluation accuracy,
            // and is tight.
            assert!(
                t >= m - 1e-14,
                "n = {n}: table {t} below the recomputed {m}"
            );
            assert!(t - m <= 1e-13, "n = {n}: table {t} not tight ({m})");
        }
        assert_eq!(
            perturbation_error_factor(2),
            1.0 * (1.0 + 2.0 * f64::EPSILON)
        );
        assert_eq!(perturbation_error_factor(65), 0.0);
    }

    #[test]
    fn closed_forms() {
        // SPEC-reduce §2.1: W_3 = sqrt(3)/2, W_4 = 16/17.
        assert!((perturbation_error_factor(3) - 3f64.sqrt() / 2.0).abs() < 1e-15);
        assert!((perturbation_error_factor(4) - 16.0 / 17.0).abs() < 1e-15);
    }
}
