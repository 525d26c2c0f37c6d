//! Independent check of the multi-degree reduction with `(r,p)`-order end interpolation,
//! [`Method::ConstrainedChebyshev`] (seed 000 §14.5, Theorem 14.5.2, SPEC-reduce §7).
//!
//! The library's `f64` result is compared with a route computed here in exact rational
//! arithmetic (`BigRational`) that uses none of the library's operators, none of its
//! S / elevation / Chebyshev matrices and none of the spec's formulas (14.5.10)–(14.5.16).
//! Everything is done on polynomials in the power basis of `t`, one coordinate at a time:
//!
//! 1. the degree-`n` Bézier control points (integers / 4) are expanded exactly into power
//!    coefficients (`sum_i P_i C(n,i) t^i (1-t)^(n-i)` multiplied out);
//! 2. `T` = the two-point Hermite interpolant of degree `r+p+1`: `T^(k)(0) = P^(k)(0)`,
//!    `k = 0..=r`, and `T^(k)(1) = P^(k)(1)`, `k = 0..=p`, from the exact linear system on
//!    its power coefficients (`r = -1` / `p = -1`: no condition at that end);
//! 3. `w(t) = t^(r+1) (1-t)^(p+1)` and `D = (P - T) / w` by exact long division (the
//!    remainder is asserted to be zero), of degree `N = n - (r+p+2)`;
//! 4. the Chebyshev series of `D` on `[0,1]`: `D` is rewritten exactly in `x = 2t - 1` and
//!    `c_k T_k(x)` peeled off from the top degree down; `c_0..=c_M` are kept,
//!    `M = m - (r+p+2)`, and the kept part is rewritten in `t`;
//! 5. `Q = T + w trunc(D)`, expanded to degree-`m` Bernstein coefficients exactly
//!    (`t^k = sum_{i>=k} C(i,k)/C(m,k) B_i^m(t)`).
//!
//! Why this is the spec's method: the spec writes `Q = H + w trunc((P - H)/w)` where `H` is
//! the "end part" of `Q` (the Bernstein terms `i <= r` and `i >= m-p` built from (14.5.10)).
//! `H` has the same derivatives as `P` up to order `r` at 0 and `p` at 1, and so does `T`,
//! hence `H - T` vanishes to order `r+1` at 0 and `p+1` at 1 and has degree `<= m`:
//! `H - T = w S` with `deg S <= M`. Then `(P - H)/w = (P - T)/w - S`, and Chebyshev
//! truncation to degree `M` reproduces the degree-`<= M` polynomial `S` exactly, so
//! `H + w trunc((P - H)/w) = H + w trunc((P - T)/w) - w S = T + w trunc((P - T)/w)`.
//!
//! Checked, for `(n,m,r,p)` in a set of symmetric, asymmetric and one-sided orders (and the
//! unconstrained `r = p = -1`), 2-D and 3-D, several pseudo-random curves each:
//!
//! * the library's control points agree with the exact route to `1e-13` relative
//!   (`max|got - want| / max(1, max|want|)`, SPEC-reduce §0);
//! * the error identity `P - Q = w * sum_{k>M} c_k T_k(2t-1)` holds exactly at rational
//!   points (with `P` and `Q` evaluated by exact de Casteljau from the Bernstein
//!   coefficients and the tail by the three-term recurrence, so the conversions of steps
//!   1, 4 and 5 are checked too; the `w` factor is the end interpolation), and to `1e-12`
//!   with the library's `Q`;
//! * the certified bound `report.error_bound` is `>=` the error of the library's `Q`
//!   sampled at 2001 points, and not looser than Theorem 14.5.2's bound
//!   `(r+1)^(r+1) (p+1)^(p+1) / (r+p+2)^(r+p+2) sum_{k>M} ||c_k||` from this route (up to
//!   the rounding allowance).
//!
//! 48 curves; about 1 s in the test profile. Worst relative deviation measured: 2.4e-16.

use cagd_core::BezierCurve;
use cagd_reduce::{Method, reduce};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};

type Q = BigRational;
/// Power coefficients, lowest degree first.
type Poly = Vec<Q>;

/// `(n, m, r, p)`.
const CASES: [(usize, usize, i32, i32); 8] = [
    (15, 9, 0, 3),
    (15, 10, 1, 1),
    (12, 7, 2, 0),
    (9, 5, -1, 1),
    (10, 6, 3, 0),
    (15, 10, 2, 2),
    (8, 3, -1, -1),
    (20, 12, 1, 4),
];
/// Pseudo-random curves per case and dimension.
const CURVES_PER_CASE: usize = 3;
const TOL: f64 = 1e-13;
const SAMPLES: usize = 2001;

fn to_i(x: usize) -> i64 {
    i64::try_from(x).expect("small")
}

fn q(v: i64) -> Q {
    Q::from_integer(BigInt::from(v))
}

fn frac(a: i64, b: i64) -> Q {
    Q::new(BigInt::from(a), BigInt::from(b))
}

fn binom(n: usize, k: usize) -> Q {
    if k > n {
        return Q::zero();
    }
    (0..k).fold(Q::one(), |acc, i| acc * q(to_i(n - i)) / q(to_i(i + 1)))
}

/// `j! / (j-k)!` (0 for `k > j`).
fn falling(j: usize, k: usize) -> Q {
    if k > j {
        return Q::zero();
    }
    (0..k).fold(Q::one(), |acc, i| acc * q(to_i(j - i)))
}

fn coef(a: &[Q], i: usize) -> Q {
    a.get(i).cloned().unwrap_or_else(Q::zero)
}

fn trim(mut a: Poly) -> Poly {
    while a.last().is_some_and(Zero::is_zero) {
        a.pop();
    }
    a
}

fn add(a: &[Q], b: &[Q]) -> Poly {
    trim(
        (0..a.len().max(b.len()))
            .map(|i| coef(a, i) + coef(b, i))
            .collect(),
    )
}

fn sub(a: &[Q], b: &[Q]) -> Poly {
    trim(
        (0..a.len().max(b.len()))
            .map(|i| coef(a, i) - coef(b, i))
            .collect(),
    )
}

fn scale(a: &[Q], s: &Q) -> Poly {
    trim(a.iter().map(|x| x * s).collect())
}

fn mul(a: &[Q], b: &[Q]) -> Poly {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut out = vec![Q::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    trim(out)
}

fn pow(a: &[Q], e: usize) -> Poly {
    (0..e).fold(vec![Q::one()], |acc, _| mul(&acc, a))
}

fn eval(a: &[Q], t: &Q) -> Q {
    a.iter().rev().fold(Q::zero(), |acc, c| acc * t + c)
}

fn deriv(a: &[Q]) -> Poly {
    trim(
        a.iter()
            .enumerate()
            .skip(1)
            .map(|(i, c)| c * q(to_i(i)))
            .collect(),
    )
}

/// `a(alpha s + beta)` as a polynomial in `s` (Horner).
fn compose_linear(a: &[Q], alpha: &Q, beta: &Q) -> Poly {
    let lin = vec![beta.clone(), alpha.clone()];
    a.iter().rev().fold(Vec::new(), |acc, c| {
        add(&mul(&acc, &lin), std::slice::from_ref(c))
    })
}

/// Exact long division `num = quot * den + rem`.
fn divrem(num: &[Q], den: &[Q]) -> (Poly, Poly) {
    let den = trim(den.to_vec());
    let lead = den.last().expect("non-zero divisor").clone();
    let mut rem = trim(num.to_vec());
    if rem.len() < den.len() {
        return (Vec::new(), rem);
    }
    let qlen = rem.len() - den.len() + 1;
    let mut quot = vec![Q::zero(); qlen];
    for k in (0..qlen).rev() {
        let c = &rem[k + den.len() - 1] / &lead;
        for (j, d) in den.iter().enumerate() {
            rem[k + j] -= &c * d;
        }
        quot[k] = c;
    }
    (trim(quot), trim(rem))
}

/// Step 1: Bernstein coefficients of degree `b.len() - 1` to power coefficients in `t`.
fn bernstein_to_power(b: &[Q]) -> Poly {
    let n = b.len() - 1;
    let t = vec![Q::zero(), Q::one()];
    let one_minus_t = vec![Q::one(), -Q::one()];
    b.iter().enumerate().fold(Vec::new(), |acc, (i, bi)| {
        let basis = mul(&pow(&t, i), &pow(&one_minus_t, n - i));
        add(&acc, &scale(&basis, &(bi * binom(n, i))))
    })
}

/// Step 5: power coefficients (degree `<= m`) to degree-`m` Bernstein coefficients.
fn power_to_bernstein(a: &[Q], m: usize) -> Vec<Q> {
    assert!(
        a.len() <= m + 1,
        "degree {} > {m}",
        a.len().saturating_sub(1)
    );
    (0..=m)
        .map(|i| {
            (0..=i.min(a.len().saturating_sub(1)))
                .map(|k| binom(i, k) / binom(m, k) * coef(a, k))
                .sum()
        })
        .collect()
}

/// Exact de Casteljau evaluation of Bernstein coefficients.
fn de_casteljau(b: &[Q], t: &Q) -> Q {
    let mut v = b.to_vec();
    let s = Q::one() - t;
    for len in (1..v.len()).rev() {
        for i in 0..len {
            v[i] = &v[i] * &s + &v[i + 1] * t;
        }
    }
    v.swap_remove(0)
}

fn de_casteljau_f64(b: &[f64], t: f64) -> f64 {
    let mut v = b.to_vec();
    for len in (1..v.len()).rev() {
        for i in 0..len {
            v[i] = v[i] * (1.0 - t) + v[i + 1] * t;
        }
    }
    v[0]
}

/// Solves the square system `a x = rhs` exactly (Gauss–Jordan, any non-zero pivot).
fn solve(mut a: Vec<Vec<Q>>, mut rhs: Vec<Q>) -> Vec<Q> {
    let k = rhs.len();
    for col in 0..k {
        let piv = (col..k)
            .find(|&i| !a[i][col].is_zero())
            .expect("Hermite system is regular");
        a.swap(col, piv);
        rhs.swap(col, piv);
        let d = a[col][col].clone();
        a[col].iter_mut().for_each(|x| *x /= &d);
        rhs[col] /= &d;
        let (prow, prhs) = (a[col].clone(), rhs[col].clone());
        for (i, (row, b)) in a.iter_mut().zip(rhs.iter_mut()).enumerate() {
            if i != col && !row[col].is_zero() {
                let f = row[col].clone();
                for (x, y) in row.iter_mut().zip(&prow) {
                    *x -= &f * y;
                }
                *b -= &f * &prhs;
            }
        }
    }
    rhs
}

/// Step 2: the two-point Hermite interpolant `T` of degree `r+p+1` (power coefficients).
fn hermite(pp: &[Q], r: i32, p: i32) -> Poly {
    let c0 = usize::try_from(r + 1).expect("r >= -1");
    let c1 = usize::try_from(p + 1).expect("p >= -1");
    let kk = c0 + c1;
    let mut rows = Vec::with_capacity(kk);
    let mut rhs = Vec::with_capacity(kk);
    for k in 0..c0 {
        // T^(k)(0) = k! a_k
        rows.push(
            (0..kk)
                .map(|j| if j == k { falling(k, k) } else { Q::zero() })
                .collect(),
        );
        rhs.push(falling(k, k) * coef(pp, k));
    }
    for k in 0..c1 {
        // T^(k)(1) = sum_j j!/(j-k)! a_j
        rows.push((0..kk).map(|j| falling(j, k)).collect());
        rhs.push((0..pp.len()).map(|j| falling(j, k) * &pp[j]).sum());
    }
    let t = if kk == 0 {
        Vec::new()
    } else {
        trim(solve(rows, rhs))
    };
    // The interpolation conditions, checked on the solution.
    let (mut dp, mut dt) = (pp.to_vec(), t.clone());
    for k in 0..c0.max(c1) {
        if k < c0 {
            assert_eq!(eval(&dp, &Q::zero()), eval(&dt, &Q::zero()), "T^({k})(0)");
        }
        if k < c1 {
            assert_eq!(eval(&dp, &Q::one()), eval(&dt, &Q::one()), "T^({k})(1)");
        }
        dp = deriv(&dp);
        dt = deriv(&dt);
    }
    t
}

/// `T_0..=T_k` in the power basis of `x`.
fn chebyshev_polys(k: usize) -> Vec<Poly> {
    let mut ts: Vec<Poly> = vec![vec![Q::one()], vec![Q::zero(), Q::one()]];
    while ts.len() <= k {
        let l = ts.len();
        let next = sub(&mul(&[Q::zero(), q(2)], &ts[l - 1]), &ts[l - 2]);
        ts.push(next);
    }
    ts.truncate(k + 1);
    ts
}

/// `sum_{k >= from} c_k T_k(x)` by the three-term recurrence of the values `T_k(x)`.
fn chebyshev_sum(c: &[Q], from: usize, x: &Q) -> Q {
    let (mut prev, mut cur) = (Q::one(), x.clone()); // T_0, T_1
    let mut acc = Q::zero();
    for (k, ck) in c.iter().enumerate() {
        let tk = if k == 0 { Q::one() } else { cur.clone() };
        if k >= from {
            acc += ck * &tk;
        }
        if k >= 1 {
            let next = q(2) * x * &cur - &prev;
            prev = cur;
            cur = next;
        }
    }
    acc
}

/// The independent route for one coordinate.
struct Route {
    /// Degree-`m` Bernstein coefficients of `Q`.
    q_bernstein: Vec<Q>,
    /// Chebyshev coefficients `c_0..=c_N` of `D = (P - T)/w` in `x = 2t - 1`.
    cheb: Vec<Q>,
    /// `w = t^(r+1) (1-t)^(p+1)`.
    w: Poly,
    /// First dropped Chebyshev degree, `M + 1`.
    first_dropped: usize,
}

fn route(b: &[Q], m: usize, r: i32, p: i32) -> Route {
    let n = b.len() - 1;
    let c0 = usize::try_from(r + 1).expect("r >= -1");
    let c1 = usize::try_from(p + 1).expect("p >= -1");
    let kk = c0 + c1;
    let big_n = n - kk;
    let first_dropped = m + 1 - kk; // M + 1 (M >= -1)
    // 1. power basis
    let pp = bernstein_to_power(b);
    // 2. Hermite interpolant
    let t = hermite(&pp, r, p);
    // 3. deflation
    let w = mul(
        &pow(&[Q::zero(), Q::one()], c0),
        &pow(&[Q::one(), -Q::one()], c1),
    );
    let (d, rem) = divrem(&sub(&pp, &t), &w);
    assert!(
        rem.is_empty(),
        "(P - T) not divisible by w: remainder {rem:?}"
    );
    assert!(d.len() <= big_n + 1, "deg D > N");
    // 4. Chebyshev series of D in x = 2t - 1 (t = (x + 1)/2), peeled from the top
    let mut dx = compose_linear(&d, &frac(1, 2), &frac(1, 2));
    let ts = chebyshev_polys(big_n);
    let mut cheb = vec![Q::zero(); big_n + 1];
    for k in (0..=big_n).rev() {
        let c = coef(&dx, k) / ts[k].last().expect("T_k has degree k");
        dx = sub(&dx, &scale(&ts[k], &c));
        cheb[k] = c;
    }
    assert!(dx.is_empty(), "Chebyshev peeling left {dx:?}");
    let kept_x = (0..first_dropped).fold(Vec::new(), |acc, k| add(&acc, &scale(&ts[k], &cheb[k])));
    let kept_t = compose_linear(&kept_x, &q(2), &-Q::one());
    // 5. Q = T + w trunc(D), to degree-m Bernstein
    let qq = add(&t, &mul(&w, &kept_t));
    Route {
        q_bernstein: power_to_bernstein(&qq, m),
        cheb,
        w,
        first_dropped,
    }
}

/// SplitMix64: a small deterministic generator.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// An integer in `-40..=40` (the coordinate is that over 4, exact in `f64`).
    fn quarter_units(&mut self) -> i64 {
        i64::try_from(self.next() % 81).expect("small") - 40
    }
}

fn column<T: Clone>(pts: &[T], dim: usize, c: usize) -> Vec<T> {
    pts.iter().skip(c).step_by(dim).cloned().collect()
}

/// `(r+1)^(r+1) (p+1)^(p+1) / (r+p+2)^(r+p+2)` = `max_[0,1] w` (`0^0 = 1`).
fn w_max(r: i32, p: i32) -> f64 {
    let sp = |x: i32| f64::from(x).powi(x);
    sp(r + 1) * sp(p + 1) / sp(r + p + 2)
}

#[test]
fn constrained_chebyshev_matches_exact_power_basis_route() {
    let ts_exact = [
        q(0),
        frac(1, 3),
        frac(1, 2),
        frac(5, 7),
        frac(9, 10),
        q(1),
        frac(-1, 2),
        frac(3, 2),
    ];
    let mut rng = SplitMix(0x000C_4EB5);
    let mut worst_rel = 0.0f64;
    let mut checked = 0;
    for &(n, m, r, p) in &CASES {
        let method = Method::ConstrainedChebyshev { r, p };
        for dim in [2usize, 3] {
            for s in 0..CURVES_PER_CASE {
                let what = format!("(n,m,r,p) = ({n},{m},{r},{p}), dim {dim}, curve {s}");
                let ints: Vec<i64> = (0..(n + 1) * dim).map(|_| rng.quarter_units()).collect();
                let pts_q: Vec<Q> = ints.iter().map(|&i| frac(i, 4)).collect();
                let pts_f: Vec<f64> = ints
                    .iter()
                    .map(|&i| i.to_f64().expect("small") / 4.0)
                    .collect();
                let curve = BezierCurve::new(pts_f.clone(), dim).unwrap();
                let red = reduce(&curve, m, method).unwrap();
                let got = red.curve.points();
                assert_eq!(red.curve.degree(), m, "{what}");

                let routes: Vec<Route> = (0..dim)
                    .map(|c| route(&column(&pts_q, dim, c), m, r, p))
                    .collect();

                // Control points: library (f64) vs exact route, SPEC-reduce §0 tolerance rule.
                let want: Vec<f64> = (0..(m + 1) * dim)
                    .map(|k| routes[k % dim].q_bernstein[k / dim].to_f64().unwrap())
                    .collect();
                let scale = want.iter().fold(1.0f64, |a, x| a.max(x.abs()));
                let dev = got
                    .iter()
                    .zip(&want)
                    .map(|(g, w)| (g - w).abs())
                    .fold(0.0f64, f64::max);
                let rel = dev / scale;
                assert!(
                    rel <= TOL,
                    "{what}: relative deviation {rel:e} > {TOL:e}\n got  {got:?}\n want {want:?}"
                );
                worst_rel = worst_rel.max(rel);

                // Error identity P - Q = w * sum_{k>M} c_k T_k(2t-1).
                for (c, rt) in routes.iter().enumerate() {
                    let pc = column(&pts_q, dim, c);
                    let qc_lib = column(got, dim, c);
                    let pc_f = column(&pts_f, dim, c);
                    for t in &ts_exact {
                        let lhs = de_casteljau(&pc, t) - de_casteljau(&rt.q_bernstein, t);
                        let x = q(2) * t - Q::one();
                        let rhs = eval(&rt.w, t) * chebyshev_sum(&rt.cheb, rt.first_dropped, &x);
                        assert_eq!(lhs, rhs, "{what}: error identity, coordinate {c}, t = {t}");
                        // The same with the library's Q, in f64.
                        let tf = t.to_f64().unwrap();
                        let lhs_f = de_casteljau_f64(&pc_f, tf) - de_casteljau_f64(&qc_lib, tf);
                        let rhs_f = rhs.to_f64().unwrap();
                        assert!(
                            (lhs_f - rhs_f).abs() <= 1e-12 * scale,
                            "{what}: library error at t = {t}, coordinate {c}: \
                             {lhs_f:e} vs exact {rhs_f:e}"
                        );
                    }
                }

                // Certified bound >= sampled error of the library's Q; and not looser than
                // Theorem 14.5.2's bound from this route's Chebyshev tail.
                let pcols: Vec<Vec<f64>> = (0..dim).map(|c| column(&pts_f, dim, c)).collect();
                let qcols: Vec<Vec<f64>> = (0..dim).map(|c| column(got, dim, c)).collect();
                let sampled = (0..SAMPLES)
                    .map(|i| {
                        let t = i.to_f64().unwrap() / (SAMPLES - 1).to_f64().unwrap();
                        (0..dim)
                            .map(|c| {
                                let e =
                                    de_casteljau_f64(&pcols[c], t) - de_casteljau_f64(&qcols[c], t);
                                e * e
                            })
                            .sum::<f64>()
                            .sqrt()
                    })
                    .fold(0.0f64, f64::max);
                let bound = red.report.error_bound.expect("certified bound");
                assert!(
                    bound >= sampled,
                    "{what}: certified bound {bound:e} < sampled error {sampled:e}"
                );
                let tail_norms: f64 = (routes[0].first_dropped..routes[0].cheb.len())
                    .map(|k| {
                        routes
                            .iter()
                            .map(|rt| rt.cheb[k].to_f64().unwrap().powi(2))
                            .sum::<f64>()
                            .sqrt()
                    })
                    .sum();
                let theorem = w_max(r, p) * tail_norms;
                assert!(
                    theorem * (1.0 + 1e-12) >= sampled,
                    "{what}: Theorem 14.5.2 bound {theorem:e} < sampled {sampled:e}"
                );
                assert!(
                    bound <= theorem * (1.0 + 1e-9) + 1e-9 * scale,
                    "{what}: certified bound {bound:e} looser than Theorem 14.5.2's {theorem:e}"
                );
                checked += 1;
            }
        }
    }
    assert_eq!(checked, CASES.len() * 2 * CURVES_PER_CASE);
    eprintln!("{checked} curves, worst relative deviation {worst_rel:e}");
}
