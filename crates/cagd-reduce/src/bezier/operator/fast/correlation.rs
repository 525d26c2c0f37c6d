//! The correlation `y_j = sum_l c_l d_(off+j+l)` of the truncations' coefficient functionals
//! (`truncation::functionals`) for double-word rows by compensated `f64` arithmetic (beyond
//! the seed): Ogita–Rump–Oishi's `Dot2` (*Accurate sum and dot product*, SIAM J. Sci.
//! Comput. 26(6), 2005, Alg. 5.3) on the double-word entries `d = y + z` (`y` the high, `z`
//! the low word), with error-free products and sums for the high words and plain `f64` for
//! the rest. It gives the double-word result with an error of the same order as the
//! double-word operations' (below), at about a third of their cost (the high words' Veltkamp
//! splits are computed once per row of `d`, the coefficients' once per `l`, instead of in
//! every product; no per-entry running-error bookkeeping).
//!
//! **Algorithm** (per `j`, `n = L + 1` terms; `c_l` exact `f64`s, `|z| <= u |y|` for a
//! normalised double-word, `u = 2^-53`):
//! `(h_l, r_l) = TwoProduct(c_l, y_l)`, `(π_l, q_l) = TwoSum(π_(l-1), h_l)` (both error-free:
//! `h + r = c y`, `π_l + q_l = π_(l-1) + h_l`), `σ_l = fl(σ_(l-1) + fl(fl(q_l + r_l) + fl(c_l z_l)))`;
//! the result is `TwoSum(π_n, σ_n)` (exact), whose value is `π_n + σ_n`.
//!
//! **Error bound.** The exact correlation is `X = sum c_l y_l + sum c_l z_l = π_n + sum_l
//! (q_l + r_l + c_l z_l)`, so `|π_n + σ_n - X|` is the error of the `f64` recursive sum of
//! the `3n` terms `q_l, r_l, c_l z_l` (the products `c_l z_l` rounded once more), at most
//! `γ_(3n) T` with `T = sum |q_l| + sum |r_l| + sum |c_l z_l|` (Higham, *Accuracy and
//! Stability*, §4.2, `γ_k = k u / (1 - k u)`). With `S = sum_l |c_l y_l|`: `|r_l| <= u |h_l|
//! <= u (1 + u) |c_l y_l|`, `|c_l z_l| <= u |c_l y_l|`, and `|q_l| <= u |π_l|` with
//! `|π_l| <= (1 + γ_n) S` (a recursive sum of the `h`), so `T <= (n + 2) u (1 + γ_n)(1 + u) S`
//! and the rounding error is at most `γ_(3n) (n + 2) u (1 + γ_n)(1 + u) S
//! <= κ_n S`, `κ_n = 3 (n + 1) (n + 3) u^2` (for `n <= 200`, where `3 n u < 1e-13`). The
//! propagated error of the inputs adds `sum_l |c_l| e_(off+j+l)` (`e` the bounds of `d`).
//! So the entry's bound is `sum_l |c_l| (κ_n |y_(off+j+l)| + e_(off+j+l))`, one `f64`
//! correlation of non-negative terms (its own rounding, a relative `(1 + u)^(2n)`, is
//! covered by the `1e-6` margin of [`Row::rounded`]). At `n = 31` (`(30,15)`),
//! `κ_n = 3.2e3 u^2`, beside `16 (2n) u^2 = 1.0e3 u^2` for the running bound of the
//! double-word route: of the same order, far below the rounding to `f64` that follows.

use super::dd::Dd;
use super::rows::{Row, recycle_f64, scratch_f64};

/// `u = 2^-53`.
const U: f64 = f64::EPSILON / 2.0;

/// Veltkamp split of `a` into two halves of 26 bits (as `dd.rs`'s; `|a| < 2^996`).
fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a; // 2^27 + 1
    let hi = c - (c - a);
    (hi, a - hi)
}

/// The per-entry inputs of [`correlate`]: the high words, the low words, the high words'
/// Veltkamp halves and the error weights `κ |y| + e`.
struct Ys<'a> {
    yhi: &'a [f64],
    ylo: &'a [f64],
    yh: &'a [f64],
    yl: &'a [f64],
    w: &'a [f64],
}

/// The loop of [`compensated`] over the coefficients, each one's terms for every `j` side
/// by side (straight loops over arrays, which the compiler vectorises): `π`, `σ` and the
/// error sums updated in place. With `FMA`, `TwoProduct`'s rest is `fma(c, y, -h)` instead
/// of Dekker's (the exact rest of the rounded product either way: the same bits).
#[inline(always)]
fn correlate<const FMA: bool>(
    c: &[f64],
    ys: &Ys<'_>,
    pi: &mut [f64],
    sigma: &mut [f64],
    err: &mut [f64],
) {
    let len = pi.len().min(sigma.len()).min(err.len());
    let (pi, sigma, err) = (&mut pi[..len], &mut sigma[..len], &mut err[..len]);
    for (l, &cl) in c.iter().enumerate() {
        let (ch, cm) = split(cl);
        let ca = cl.abs();
        let (yhi, ylo) = (&ys.yhi[l..l + len], &ys.ylo[l..l + len]);
        let (yh, yl, w) = (&ys.yh[l..l + len], &ys.yl[l..l + len], &ys.w[l..l + len]);
        for j in 0..len {
            let (y, z) = (yhi[j], ylo[j]);
            // TwoProduct (Dekker, the splits precomputed; or by FMA).
            let h = cl * y;
            let r = if FMA {
                cl.mul_add(y, -h)
            } else {
                ((ch * yh[j] - h) + ch * yl[j] + cm * yh[j]) + cm * yl[j]
            };
            // TwoSum (Knuth).
            let p0 = pi[j];
            let p = p0 + h;
            let bb = p - p0;
            let q = (p0 - (p - bb)) + (h - bb);
            pi[j] = p;
            sigma[j] += (q + r) + cl * z;
            err[j] += ca * w[j];
        }
    }
}

/// [`correlate`] compiled with AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn correlate_fused(c: &[f64], ys: &Ys<'_>, pi: &mut [f64], sigma: &mut [f64], err: &mut [f64]) {
    correlate::<true>(c, ys, pi, sigma, err);
}

/// `y_j = sum_l c[l] d[off + j + l]`, `j = 0..len`, as a double-word row (capacity `cap`)
/// with the proven bounds of the module docs. `c` must hold exact `f64` integers of
/// magnitude below `2^996` and `d` normalised double-words (as every `Dd` operation
/// returns); `None` if `d` is too short or a coefficient is not finite.
pub(crate) fn compensated(
    c: &[f64],
    d: &Row<Dd>,
    off: usize,
    len: usize,
    cap: usize,
) -> Option<Row<Dd>> {
    let n = c.len();
    let need = off + len + n.saturating_sub(1);
    if n == 0 || d.v.len() < need || d.e.len() < need || !c.iter().all(|x| x.is_finite()) {
        return None;
    }
    #[allow(clippy::cast_precision_loss, reason = "n <= 200")]
    let kappa = 3.0 * (n as f64 + 1.0) * (n as f64 + 3.0) * U * U;
    let span = &d.v[off..need];
    let m = span.len();
    // Scratch (one pooled buffer): the high words' splits, the low words and the error
    // weights `κ |y| + e`, once per entry of `d` (not per product), then `π` and `σ`.
    let mut scratch = scratch_f64(5 * m + 2 * len);
    let (yh, rest) = scratch.split_at_mut(m);
    let (yl, rest) = rest.split_at_mut(m);
    let (ylo, rest) = rest.split_at_mut(m);
    let (yhi, rest) = rest.split_at_mut(m);
    let (w, rest) = rest.split_at_mut(m);
    let (pi, sigma) = rest.split_at_mut(len);
    for (i, (x, e)) in span.iter().zip(&d.e[off..need]).enumerate() {
        let (h, l) = split(x.hi);
        yh[i] = h;
        yl[i] = l;
        yhi[i] = x.hi;
        ylo[i] = x.lo;
        w[i] = kappa * x.hi.abs() + e;
    }
    let mut out = Row::<Dd>::zeros(cap.max(len));
    let err = &mut out.e[..len];
    let ys = Ys {
        yhi,
        ylo,
        yh,
        yl,
        w,
    };
    if super::compensated::fused() {
        #[cfg(target_arch = "x86_64")]
        #[allow(unsafe_code, reason = "the call of a `target_feature` function")]
        // SAFETY: the CPU has AVX2 and FMA (`fused`), the function's only requirement; the
        // function is itself safe code.
        unsafe {
            correlate_fused(c, &ys, pi, sigma, err);
        }
    } else {
        correlate::<false>(c, &ys, pi, sigma, err);
    }
    for ((o, &p), &s) in out.v.iter_mut().zip(pi.iter()).zip(sigma.iter()) {
        let hi = p + s;
        let bb = hi - p;
        *o = Dd {
            hi,
            lo: (p - (hi - bb)) + (s - bb),
        };
    }
    recycle_f64(scratch);
    out.v.truncate(len);
    out.e.truncate(len);
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::operator::fast::tracked::Tracked;
    use num_rational::BigRational;

    /// Every entry of the compensated correlation of alternating binomials with reciprocal
    /// binomials (the Jacobi functionals' sums, cancellation up to `~4^k`) within its proven
    /// bound of the exact rational value, and the bound within a few `u^2` of the sum of
    /// magnitudes.
    #[test]
    fn compensated_correlation_within_its_proven_bound() {
        for (k, nb) in [(0i64, 10i64), (5, 40), (15, 60), (30, 110)] {
            let d: Vec<Tracked<Dd>> = (0..=nb).map(|s| Tracked::recip_binom(nb, s)).collect();
            let d = Row::from_tracked(&d);
            let c: Vec<f64> = (0..=k)
                .map(|l| {
                    let b = crate::exact::q_to_f64(&crate::exact::binom_q(k + 2, k - l))
                        * crate::exact::q_to_f64(&crate::exact::binom_q(k + 2, l));
                    if (k - l) % 2 == 0 { b } else { -b }
                })
                .filter(|x| x.abs() < 2f64.powi(53))
                .collect();
            if c.len() != usize::try_from(k + 1).unwrap_or(0) {
                continue;
            }
            let len = usize::try_from(nb - k + 1).unwrap_or(0) - 1;
            let row = compensated(&c, &d, 1, len, len).expect("in range");
            for j in 0..len {
                let mut exact = BigRational::from_integer(0.into());
                for (l, cl) in c.iter().enumerate() {
                    let s = i64::try_from(1 + j + l).unwrap_or(0);
                    exact += BigRational::from_float(*cl).expect("finite")
                        / crate::exact::binom_q(nb, s);
                }
                let got = BigRational::from_float(row.v[j].hi).expect("finite")
                    + BigRational::from_float(row.v[j].lo).expect("finite");
                let diff = crate::exact::q_to_f64(&num_traits::Signed::abs(&(got - &exact)));
                assert!(diff <= row.e[j], "k {k} j {j}: {diff:e} > {:e}", row.e[j]);
                let mag: f64 = c
                    .iter()
                    .enumerate()
                    .map(|(l, cl)| cl.abs() * d.v[1 + j + l].hi.abs())
                    .sum();
                assert!(
                    row.e[j] <= 1e-25 * mag + 1e-300,
                    "k {k} j {j}: bound too loose"
                );
            }
        }
    }

    /// The AVX2 + FMA instance of [`correlate`] (where the CPU has it) gives the portable
    /// one's bits: `fma(c, y, -h)` and Dekker's product are the same exact rest.
    #[test]
    fn fused_correlation_is_the_portable_one() {
        if !crate::bezier::operator::fast::compensated::fused() {
            return;
        }
        let nb = 60i64;
        let d: Vec<Tracked<Dd>> = (0..=nb).map(|s| Tracked::recip_binom(nb, s)).collect();
        let (yhi, ylo): (Vec<f64>, Vec<f64>) =
            d.iter().map(|t| (t.value().hi, t.value().lo)).unzip();
        let (yh, yl): (Vec<f64>, Vec<f64>) = yhi.iter().map(|&y| split(y)).unzip();
        let w: Vec<f64> = yhi.iter().map(|y| y.abs() * 1e-30).collect();
        let ys = Ys {
            yhi: &yhi,
            ylo: &ylo,
            yh: &yh,
            yl: &yl,
            w: &w,
        };
        let c: Vec<f64> = (0..=15)
            .map(|l| if l % 2 == 0 { 1.0 } else { -3.0 } * f64::from(l + 1).powi(9))
            .collect();
        let len = 40;
        let run = |fused: bool| {
            let (mut pi, mut sigma, mut err) = (vec![0.0; len], vec![0.0; len], vec![0.0; len]);
            if fused {
                #[cfg(target_arch = "x86_64")]
                #[allow(unsafe_code, reason = "the call of a `target_feature` function")]
                // SAFETY: the CPU has AVX2 and FMA (checked above).
                unsafe {
                    correlate_fused(&c, &ys, &mut pi, &mut sigma, &mut err);
                }
            } else {
                correlate::<false>(&c, &ys, &mut pi, &mut sigma, &mut err);
            }
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
            (bits(&pi), bits(&sigma), bits(&err))
        };
        assert_eq!(run(true), run(false));
    }
}
