//! Chebyshev coefficient functionals by Chebyshev–Gauss quadrature (beyond the seed): the
//! bound terms of the Chebyshev truncations (`k > M`, see `truncation.rs`) without the
//! alternating sums of the closed-form correlation, whose cancellation grows like `4^k`.
//!
//! With `x = 2t - 1`, `f_k(S) = (2 - δ_k0)/π ∫ S(t) T_k(2t-1) / sqrt(t(1-t)) dt`
//! `= (2 - δ_k0)/π ∫ S((1+x)/2) T_k(x) / sqrt(1-x^2) dx`, and Chebyshev–Gauss quadrature with
//! `Q` nodes `x_q = cos θ_q`, `θ_q = (2q+1)π/(2Q)`, is exact for integrands of degree
//! `<= 2Q - 1`, here `N + k`. So for `S = B_j^N`
//!
//! `f_k(B_j^N) = (c_k / Q) sum_q B_j^N(τ_q) cos(k θ_q)`, `c_k = 2 - δ_k0`,
//! `τ_q = (1 + cos θ_q)/2 = cos^2(θ_q / 2)`, `1 - τ_q = τ_(Q-1-q)`,
//!
//! a sum of `Q` terms bounded by `B_j^N(τ_q)`: no cancellation beyond the functional's own.
//!
//! **Error bound** (per entry, in a base arithmetic with relative error `U` per operation).
//! The Bernstein values at the nodes are a double-word table per `N` ([`bernstein`]),
//! rounded to the base: `B̂_j = B_j (1 + ε)`, `|ε| <= ε_B` (`u` in `f64` plus ~`1e-28`); the
//! cosines `ĉ` are within `β` (one rounding plus ~`1e-30`) of `cos(k θ_q)`, `|c| <= 1`. Each
//! product `B̂_j ĉ` is then within `B_j (ε_B + U + β)` of `B_j c` (up to second order), the
//! pairwise sum of the `Q` products adds `γ_(ceil(log2 Q)) sum |terms|`, and the scaling by
//! `c_k / Q` two roundings, so
//!
//! `|f̂_k(B_j) - f_k(B_j)| <= (c_k / Q) A_j η`, `η = ε_B + U + β + γ_(ceil(log2 Q)) + 2U + U^2`,
//! `A_j = sum_q B_j^N(τ_q)`
//!
//! up to second-order terms below `1e-9 η` (covered by a margin; `γ_n = nU / (1 - nU)`).
//! Since `sum_j A_j = Q`, a row's error is at most `c_k η ≈ 2 * 12 u` in `f64` for `Q <= 65`
//! (`u = 2^-53`), whatever `N` and `k`. The cosines `cos(k θ_q) = cos(π r / (2Q))`,
//! `r = k (2q + 1) mod 4Q`, and the nodes come from one table of `cos(π s / (4Q))`,
//! `s = 0..=2Q`, computed once per `Q` by a Taylor series in double-word on tracked numbers
//! (remainder below `1e-34`).

use super::dd::Dd;
use super::rows::{Row, idx, to_i};
use super::tracked::{Base, Tracked};

/// `π` as a double-word (`hi + lo` within `3e-33` of `π`).
const PI_DD: Dd = Dd {
    hi: std::f64::consts::PI,
    lo: 1.224_646_799_147_353_2e-16,
};

/// The double-word table of `Q` nodes: values with bounds of their absolute errors.
struct Nodes {
    /// `cos(π s / (4Q))`, `s = 0..=2Q`.
    cos: Vec<(Dd, f64)>,
    /// `τ_q = cos^2(π (2q + 1) / (4Q))`, `q = 0..Q`.
    tau: Vec<(Dd, f64)>,
}

/// `cos(π s / d)` for `0 <= s / d <= 1/2` by its Taylor series (17 terms in Horner form on
/// tracked double-words; the alternating remainder is below `(π/2)^36 / 36! < 1e-34`), with
/// a bound of its absolute error (the tracked bound doubled for its own rounding).
fn cos_dd(s: i64, d: i64) -> (Dd, f64) {
    let pi = Tracked::<Dd>::from_parts(PI_DD, 3e-33);
    let x = pi.mul(Tracked::small(s)).div(Tracked::small(d));
    let x2 = x.mul(x);
    let one = Tracked::<Dd>::of(1.0);
    let mut r = one;
    for i in (1..=17i64).rev() {
        r = one.sub(x2.mul(r).div(Tracked::small((2 * i - 1) * (2 * i))));
    }
    (r.value(), 2.0 * (r.bound() + 1e-34))
}

/// The node table of `Q` nodes, built once per `Q` for the process (a table of constants
/// like the binomials'; `O(Q)` double-word series).
fn nodes(q: usize) -> &'static Nodes {
    use std::sync::OnceLock;
    const LEN: usize = cagd_core::MAX_BINOMIAL_N + 2;
    static TABLES: [OnceLock<Nodes>; LEN] = [const { OnceLock::new() }; LEN];
    let build = || {
        let q4 = 4 * to_i(q);
        let cos: Vec<(Dd, f64)> = (0..=2 * to_i(q)).map(|s| cos_dd(s, q4)).collect();
        let tau = (0..q)
            .map(|j| {
                let (c, e) = cos[2 * j + 1];
                let t = Tracked::<Dd>::from_parts(c, e);
                let t2 = t.mul(t);
                (t2.value(), 2.0 * t2.bound())
            })
            .collect();
        Nodes { cos, tau }
    };
    match TABLES.get(q) {
        Some(cell) => cell.get_or_init(build),
        // Not reached (`Q <= N + 1 <= 65`); a leaked table keeps the function total.
        None => Box::leak(Box::new(build())),
    }
}

/// A table double-word in the base arithmetic, with its absolute error bound (the table's
/// plus the conversion's rounding).
fn in_base<B: Base>((d, e): (Dd, f64)) -> (B, f64) {
    let v = B::of(d.hi).add(B::of(d.lo));
    (v, e + B::U * (1.0 + 1e-6) * v.to_f64().abs())
}

/// `γ_n = n U / (1 - n U)`.
#[allow(clippy::cast_precision_loss, reason = "n <= 200")]
fn gamma(n: usize, u: f64) -> f64 {
    let z = n as f64 * u;
    z / (1.0 - z)
}

/// The Bernstein values at the nodes, `B_j^N(τ_q)` for `j <= N/2` (the rest by symmetry),
/// computed in double-word from the node table and remembered per `N` for the process (a
/// table of constants like the binomials'): `vals[j * Q + q]`, with `rel` a bound of their
/// relative errors and `a_up[j]` an upper bound of `A_j = sum_q B_j^N(τ_q)`.
struct Bernstein {
    q: usize,
    vals: Vec<Dd>,
    /// The values rounded to `f64` and transposed, `t64[q * (N/2 + 1) + j]` (the `f64`
    /// route's table: one node's values for every `j` side by side).
    t64: Vec<f64>,
    rel: f64,
    a_up: Vec<f64>,
}

/// [`Bernstein`] for degree `N` with `Q = N + 1` nodes (exact for every `k <= N`); `None` if
/// a precondition of its bound fails (a value near underflow, or a relative error above
/// `1e-20`: neither happens at degree `<= 64`). The values are `C(N,j) τ^j (1-τ)^(N-j)` by
/// repeated products: relative error `z / (1 - z)`, `z = N α + (N + 1) U + β_b` (`α` the
/// nodes' relative error, `N - 2` power roundings and two products, `β_b` the binomials'
/// relative error, zero in double-word at degree `<= 64`). Every value and every partial
/// product is at least `1e-280` (checked), so no double-word part underflows.
fn bernstein(n: usize) -> Option<&'static Bernstein> {
    use std::sync::OnceLock;
    const LEN: usize = cagd_core::MAX_BINOMIAL_N + 2;
    static TABLES: [OnceLock<Option<Bernstein>>; LEN] = [const { OnceLock::new() }; LEN];
    let build = || {
        let q = n + 1;
        let table = nodes(q);
        let alpha = table
            .tau
            .iter()
            .map(|(v, e)| e / v.hi.abs())
            .fold(0.0f64, f64::max)
            * (1.0 + 1e-6);
        let u = <Dd as Base>::U;
        // The binomials' relative error (zero: exact in double-word below 2^106, i.e. for
        // every degree <= 64; kept for the bound's sake).
        let beta_b = (0..=n)
            .map(|j| {
                let (c, e) = <Dd as Base>::of_binom(n, j);
                e / c.hi.abs()
            })
            .fold(0.0f64, f64::max)
            * (1.0 + 1e-6);
        #[allow(clippy::cast_precision_loss, reason = "n <= 130")]
        let z = (n as f64) * alpha + (n as f64 + 1.0) * u + beta_b;
        let rel = z / (1.0 - z) * (1.0 + 1e-6);
        let half = n / 2;
        let mut vals = vec![Dd::from_f64(0.0); (half + 1) * q];
        let (mut tp, mut sp) = (
            vec![Dd::from_f64(1.0); n + 1],
            vec![Dd::from_f64(1.0); n + 1],
        );
        let mut smallest = f64::INFINITY;
        for node in 0..q {
            let (t, s) = (table.tau[node].0, table.tau[q - 1 - node].0);
            for j in 1..=n {
                tp[j] = tp[j - 1].mul(t);
                sp[j] = sp[j - 1].mul(s);
            }
            // The smallest powers (the partial products `C(N,j) τ^j >= τ^j` are larger).
            smallest = smallest.min(tp[n].hi.abs()).min(sp[n].hi.abs());
            for j in 0..=half {
                let b = <Dd as Base>::of_binom(n, j).0.mul(tp[j]).mul(sp[n - j]);
                smallest = smallest.min(b.hi.abs());
                vals[j * q + node] = b;
            }
        }
        if smallest.is_nan() || smallest < 1e-280 || rel.is_nan() || rel > 1e-20 {
            return None;
        }
        // A_j <= sum_q B̂/(1 - rel); the f64 sum of the rounded values within
        // (1 + eps)(1 + (Q - 1) u) of the double-word one.
        #[allow(clippy::cast_precision_loss, reason = "q <= 131")]
        let a_up = (0..=half)
            .map(|j| {
                let s: f64 = vals[j * q..(j + 1) * q].iter().map(|b| b.hi + b.lo).sum();
                s * (1.0 + 2.0 * rel + (q as f64 + 2.0) * f64::EPSILON) * (1.0 + 1e-8)
            })
            .collect();
        let cols = half + 1;
        let mut t64 = vec![0.0f64; q * cols];
        for j in 0..cols {
            for node in 0..q {
                let b = vals[j * q + node];
                t64[node * cols + j] = b.hi + b.lo;
            }
        }
        Some(Bernstein {
            q,
            vals,
            t64,
            rel,
            a_up,
        })
    };
    match TABLES.get(n) {
        Some(cell) => cell.get_or_init(build).as_ref(),
        // Not reached (`N <= 64`); a leaked table keeps the function total.
        None => Box::leak(Box::new(build())).as_ref(),
    }
}

/// (The reference for [`pairwise_columns`]'s order, kept for its test.)
/// `x_0 + ... + x_(len-1)` by pairwise summation (in place): each term passes through at
/// most `ceil(log2 len)` additions, so the error is at most `γ_(ceil(log2 len)) sum |x|`.
#[cfg(test)]
fn pairwise<B: Base>(x: &mut [B]) -> B {
    let mut len = x.len();
    if len == 0 {
        return B::of(0.0);
    }
    while len > 1 {
        let pairs = len / 2;
        for i in 0..pairs {
            let (a, b) = (x[2 * i], x[2 * i + 1]);
            x[i] = a.add(b);
        }
        if len % 2 == 1 {
            x[pairs] = x[len - 1];
        }
        len = len.div_ceil(2);
    }
    x[0]
}

/// `ceil(log2 len)` (`0` for `len <= 1`).
fn depth(len: usize) -> usize {
    let mut d = 0;
    while (1usize << d) < len {
        d += 1;
    }
    d
}

/// `sum_q bt[q][j] c[q]` for every column `j < cols` (`bt` row-major, `Q` rows of `cols`),
/// each by [`pairwise`]'s tree with its first level fused with the products
/// (`b_(2t) c_(2t) + b_(2t+1) c_(2t+1)`, an odd last term alone): the same operations in the
/// same order as one [`pairwise`] sum per column, run on whole rows of `cols` entries (loops
/// the compiler vectorises). `sums` holds at least `ceil(Q/2) cols` entries; the result is
/// its first `cols`.
fn pairwise_columns<'a, B: Base>(sums: &'a mut [B], bt: &[B], c: &[B], cols: usize) -> &'a [B] {
    let q = c.len();
    let pairs = q / 2;
    for t in 0..pairs {
        let (b0, b1) = (
            &bt[2 * t * cols..][..cols],
            &bt[(2 * t + 1) * cols..][..cols],
        );
        let (c0, c1) = (c[2 * t], c[2 * t + 1]);
        for ((o, x), y) in sums[t * cols..][..cols].iter_mut().zip(b0).zip(b1) {
            *o = x.mul(c0).add(y.mul(c1));
        }
    }
    let mut len = pairs;
    if q % 2 == 1 {
        let (b, cl) = (&bt[(q - 1) * cols..][..cols], c[q - 1]);
        for (o, x) in sums[pairs * cols..][..cols].iter_mut().zip(b) {
            *o = x.mul(cl);
        }
        len += 1;
    }
    while len > 1 {
        let pairs = len / 2;
        for i in 0..pairs {
            // Row `i` from rows `2i` and `2i + 1` (`i <= 2i`: row 0 is updated in place).
            let (lo, hi) = sums.split_at_mut((2 * i).max(1) * cols);
            if i == 0 {
                for (o, y) in lo[..cols].iter_mut().zip(&hi[..cols]) {
                    *o = o.add(*y);
                }
            } else {
                let (x, y) = hi[..2 * cols].split_at(cols);
                for ((o, x), y) in lo[i * cols..][..cols].iter_mut().zip(x).zip(y) {
                    *o = x.add(*y);
                }
            }
        }
        if len % 2 == 1 {
            sums.copy_within((len - 1) * cols..len * cols, pairs * cols);
        }
        len = len.div_ceil(2);
    }
    &sums[..cols]
}

/// The Chebyshev coefficient functionals `f_k(B_j^N)`, `k = first..=last` (`last <= N`),
/// `j = 0..=N`, as rows in base `B` with the proven per-entry bounds of the module docs:
/// `(c_k / Q) A_j η`, `η = ε_B + U + β + γ_(ceil(log2 Q)) + 2U + U^2` with the Bernstein
/// values from the double-word table ([`bernstein`], `ε_B` its error plus one rounding)
/// and the sum over the nodes pairwise: `η ≈ 12 u` in `f64` at `Q <= 65`, a row's error
/// `c_k η`. `None` if the table's preconditions fail (never at degree `<= 64`).
pub(crate) fn chebyshev<B: Base>(nn: i64, first: i64, last: i64) -> Option<Vec<Row<B>>> {
    if nn < 0 || first < 0 || last < first {
        return Some(Vec::new());
    }
    if last > nn {
        return None;
    }
    let n = idx(nn);
    let tab = bernstein(n)?;
    let q = tab.q;
    let table = nodes(q);
    let cos: Vec<(B, f64)> = table.cos.iter().map(|c| in_base::<B>(*c)).collect();
    let beta = cos.iter().map(|c| c.1).fold(0.0f64, f64::max);
    let u = B::U;
    let eps_b = (tab.rel + u) * (1.0 + 1e-6);
    if beta.is_nan() || beta > 1e-10 {
        return None;
    }
    let half = n / 2;
    let cols = half + 1;
    // The Bernstein values in the base, transposed (`bt[node * cols + j]`): the `f64` table
    // as it is, another base's converted here.
    let converted: Vec<B>;
    let bt: &[B] = {
        let t64: &dyn std::any::Any = &tab.t64;
        if let Some(t) = t64.downcast_ref::<Vec<B>>() {
            t
        } else {
            converted = (0..q * cols)
                .map(|i| {
                    let d = tab.vals[(i % cols) * q + i / cols];
                    B::of(d.hi).add(B::of(d.lo))
                })
                .collect();
            &converted
        }
    };
    let eta = (eps_b + u + beta + gamma(depth(q), u) + 2.0 * u + u * u) * (1.0 + 1e-8);
    let q4 = 4 * q;
    #[allow(clippy::cast_precision_loss, reason = "q <= 65")]
    let qf = q as f64;
    // The pairwise sums of every `j` side by side: level `t` of the tree in
    // `sums[t * cols..(t + 1) * cols]`.
    let mut sums = vec![B::of(0.0); q.div_ceil(2) * cols];
    let rows = (first..=last)
        .map(|k| {
            let ck = if k == 0 { 1.0 } else { 2.0 };
            let w = B::of(ck).div(B::of(qf));
            let w_up = ck / qf * (1.0 + 4.0 * f64::EPSILON);
            // cos(k θ_q) = cos(π r / (2Q)) = table entry 2r (angles π s / (4Q)).
            let ks = idx(k);
            let cosk: Vec<B> = (0..q)
                .map(|node| {
                    let mut r = (ks * (2 * node + 1)) % q4;
                    if r > 2 * q {
                        r = q4 - r;
                    }
                    if r <= q {
                        cos[2 * r].0
                    } else {
                        B::of(0.0).sub(cos[2 * (2 * q - r)].0)
                    }
                })
                .collect();
            let mut row = Row::zeros(n + 1);
            let v = pairwise_columns(&mut sums, bt, &cosk, cols);
            for (j, (x, a)) in v.iter().zip(&tab.a_up).enumerate().take(half + 1) {
                row.v[j] = x.mul(w);
                // (+ 1e-300: the products `B̂ ĉ` may be subnormal where a cosine is at its
                // rounding level, `|ĉ| ~ 1e-32`; each such product and its double-word parts
                // lose at most `2^-1074` absolutely, far below this allowance.)
                row.e[j] = w_up * a * eta * (1.0 + 1e-8) + 1e-300;
            }
            // f_k(B_(N-j)) = (-1)^k f_k(B_j) (the nodes' symmetry; negation is exact).
            for j in half + 1..=n {
                let v = row.v[n - j];
                row.v[j] = if k % 2 == 0 { v } else { B::of(0.0).sub(v) };
                row.e[j] = row.e[n - j];
            }
            row
        })
        .collect();
    Some(rows)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::q_to_f64;
    use cagd_core::{Basis, from_bernstein_exact};
    use num_traits::Signed;

    /// The quadrature rows against the exact Chebyshev coefficient functionals
    /// (`cagd_core`'s exact basis change), entry by entry within the proven bounds, in
    /// `f64` and in double-word; and the bounds are tight enough to be useful (an `f64`
    /// row's proven error below `2 * 13 u`).
    #[test]
    fn quadrature_functionals_within_their_proven_bounds() {
        for nn in [0usize, 1, 2, 5, 8, 13, 20, 28, 41, 64] {
            let exact = crate::exact::RatMat::from_exact(
                from_bernstein_exact(Basis::Chebyshev, nn).unwrap().as_ref(),
            );
            let n = to_i(nn);
            let f = chebyshev::<f64>(n, 0, n).unwrap();
            let d = chebyshev::<Dd>(n, 0, n).unwrap();
            for k in 0..=nn {
                let row = exact.row(k);
                let mut row_err = 0.0;
                for (j, ex) in row.iter().enumerate() {
                    for (v, e) in [(f[k].v[j], f[k].e[j]), (d[k].v[j].to_f64(), d[k].e[j])] {
                        let diff = q_to_f64(
                            &(num_rational::BigRational::from_float(v).unwrap() - ex).abs(),
                        );
                        // (The double-word value rounded to f64: one more rounding.)
                        let allowed = e + f64::EPSILON * v.abs();
                        assert!(
                            diff <= allowed,
                            "N={nn} k={k} j={j}: {diff:e} > {allowed:e}"
                        );
                    }
                    row_err += f[k].e[j];
                }
                #[allow(clippy::cast_precision_loss, reason = "small")]
                let goal = 2.0 * 13.0 * f64::EPSILON / 2.0;
                assert!(
                    row_err <= goal,
                    "N={nn} k={k}: row bound {row_err:e} > {goal:e}"
                );
                let dd_err: f64 = d[k].e.iter().sum();
                assert!(
                    dd_err <= 1e-20,
                    "N={nn} k={k}: double-word bound {dd_err:e}"
                );
            }
        }
    }

    /// [`pairwise_columns`] gives, bit for bit, one [`pairwise`] sum per column with its
    /// first level fused with the products (the order the module's bound is for), at every
    /// `Q` up to 65 and on values of mixed signs and magnitudes.
    #[test]
    fn pairwise_columns_is_the_pairwise_sum_per_column() {
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            #[allow(clippy::cast_precision_loss, reason = "a test value")]
            let x = (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            x * 10f64.powi(i32::try_from(seed % 7).unwrap_or(0) - 3)
        };
        for q in 1..=65usize {
            let cols = q / 2 + 1;
            let bt: Vec<f64> = (0..q * cols).map(|_| next()).collect();
            let c: Vec<f64> = (0..q).map(|_| next()).collect();
            let mut sums = vec![0.0; q.div_ceil(2) * cols];
            let got = pairwise_columns(&mut sums, &bt, &c, cols).to_vec();
            for (j, g) in got.iter().enumerate() {
                let mut terms: Vec<f64> = (0..q / 2)
                    .map(|t| {
                        bt[2 * t * cols + j] * c[2 * t] + bt[(2 * t + 1) * cols + j] * c[2 * t + 1]
                    })
                    .collect();
                if q % 2 == 1 {
                    terms.push(bt[(q - 1) * cols + j] * c[q - 1]);
                }
                assert_eq!(g.to_bits(), pairwise(&mut terms).to_bits(), "Q={q} j={j}");
            }
        }
    }

    /// The table's cosines against `f64::cos` (a sanity check of the series: the proven
    /// bound is the tracked one).
    #[test]
    fn node_table_cosines() {
        let t = nodes(7);
        for (s, (c, e)) in t.cos.iter().enumerate() {
            #[allow(clippy::cast_precision_loss, reason = "small")]
            let want = (std::f64::consts::PI * s as f64 / 28.0).cos();
            assert!((c.hi + c.lo - want).abs() <= 4.0 * f64::EPSILON && *e < 1e-28);
        }
    }
}
