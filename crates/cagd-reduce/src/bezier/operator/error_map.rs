//! The certified bound as two small linear maps of the input (goes beyond the seed; the
//! error curve is that of seed 000 §14.4.3): the error curve's coefficient points
//! `c = G P` ([`ErrorBasis`], `r = n - m` of them) and its values `D(t_j) = V c` at the
//! `N + 1` Chebyshev–Lobatto nodes `t_j = sin^2(j pi / (2N))` of `[0, 1]`.
//!
//! The Ehlich–Zeller inequality: a real polynomial `p` of degree `n < N` satisfies
//! `max_[0,1] |p| <= sec(n pi / (2N)) max_j |p(t_j)|`. (With `t = sin^2(theta/2)`,
//! `q(theta) = p(t)` is a cosine polynomial of degree `n`; where `|q|` is largest, at
//! `theta*`, the Szegő inequality `q'^2 + n^2 q^2 <= n^2 ||q||^2` gives
//! `|q(theta)| >= ||q|| cos(n |theta - theta*|)` for `n |theta - theta*| <= pi`, and a node
//! `j pi / N` lies within `pi / (2N)` of `theta*`.) For a curve, apply it to
//! `p = u . D` with `u` the unit vector along `D` at its largest norm: `max_t ||D(t)|| <=
//! sec(n pi / (2N)) max_j ||D(t_j)||`. The node values are themselves curve values, so the
//! bound is within `sec(n pi / (2N))` of the true maximum, whatever the curve: `N` is
//! chosen from the ratio a level asks (1.25 fast, 1.075 tight).
//!
//! With the basis' symmetric split (`error_basis.rs`: `phi_k(1 - t) = +-phi_k(t)` exactly)
//! `N` is odd and only the nodes `t_j`, `j = 0 ..= (N - 1) / 2`, of `[0, 1/2)` are
//! evaluated: `D(t_j) = e_j + o_j` and `D(1 - t_j) = e_j - o_j` with `e = V_e c_e`, `o =
//! V_o c_o` (the even and the odd columns), so `V`'s work halves. The mirrored points `1 -
//! t^_j` (exact reals, never rounded) are within the same angle of the ideal nodes `t_(N -
//! j)` as `t^_j` of `t_j`, so the Ehlich–Zeller argument holds on the union as it is.

use nalgebra::DMatrix;

use super::super::gemm::LinearMap;
use super::error_basis::ErrorBasis;

/// Angle margin added to `pi / (2N)` for the rounding of the nodes (`|theta^_j - theta_j|`
/// is a few ulps of `theta_j`, far below this).
const NODE_ANGLE_MARGIN: f64 = 1e-9;

/// The node values map of one level and the constants of its bound.
#[derive(Debug, Clone)]
pub(crate) struct BoundMap {
    /// `V`, `(N+1) x r`: `V_jk = phi_k(t_j)`; with the symmetric split only the rows
    /// `j <= (N - 1) / 2`.
    pub(crate) samples: LinearMap,
    /// With the symmetric split: `V_e` (the even columns of `samples`) and `V_o` (the odd
    /// ones) as maps of their own.
    pub(crate) split: Option<(LinearMap, LinearMap)>,
    /// `sec(n (pi / (2N) + margin))`, rounded up.
    pub(crate) sec: f64,
    /// Rounding allowance inside the secant factor, per unit of `max_j ||P_j||`.
    pub(crate) inner: f64,
    /// Allowance outside it (the basis residual and the rounding of the reduced points),
    /// per unit of `max_j ||P_j||`.
    pub(crate) outer: f64,
}

impl BoundMap {
    /// The map for `basis` whose secant factor is at most `ratio` (`> 1`), for an operator
    /// whose row sums of absolute values are at most `op_norm`.
    ///
    /// Rounding (`eps` unit roundoff; `g_k`, `u_k = max_i |U_ik|` from the basis): the
    /// Bernstein values at the `f64` nodes are within `(3n + 3) eps` of themselves
    /// (binomial, powers, products), so `V^` is within `(4n + 5) eps u_k` of the exact
    /// `phi_k(t^_j)`; `c^ = fl(G P)` within `(n + 1) eps g_k pmax` of `c`; `fl(V^ c^)` within
    /// `r eps sum_k |V^_jk| ||c^_k||` (with the split: `fl(V_e c_e) +- fl(V_o c_o)`, the
    /// two sums within `r eps sum_k |V^_jk| ||c^_k||` together, the `+-` one more rounding
    /// of the value, counted in the relative factor). So `||D~(t^_j)|| <= ||s^_j|| (1 +
    /// (dim + 4) eps) + inner pmax` (the norm's `dim` roundings, its square root, the `+-`,
    /// and a margin) with `inner = 2 eps ((r + n + 1) vg + (4n + 5) ug)`, `vg = max_j sum_k
    /// |V^_jk| g_k`, `ug = sum_k u_k g_k` (2: margin for second-order terms). The true
    /// error curve `P - E fl(A P)` differs from `D~ = U G P` by the basis residual
    /// (`rho pmax`) and `E (fl(A P) - A P)` (`(n + 1) eps op_norm pmax`, `E` convex):
    /// `outer = rho + 2 (n + 1) eps op_norm`.
    pub(crate) fn new(basis: &ErrorBasis, op_norm: f64, ratio: f64) -> Self {
        let (n, r) = (basis.n, basis.rank);
        let nf = n as f64;
        // Smallest N with sec(n (pi/(2N) + margin)) <= ratio.
        let half = (1.0 / ratio).acos() / nf - NODE_ANGLE_MARGIN;
        #[allow(
            clippy::cast_possible_truncation,
            reason = "n <= 64 and ratio >= 1.075 give N < 300"
        )]
        let mut big_n = ((std::f64::consts::FRAC_PI_2 / half).ceil() as usize).max(n + 1);
        // The split evaluates (N + 1) / 2 nodes for N odd, N / 2 + 1 for N even: an odd N
        // is the better bound for the same work.
        let rows = match basis.even {
            Some(_) => {
                big_n |= 1;
                big_n.div_ceil(2)
            }
            None => big_n + 1,
        };
        let angle = nf * (std::f64::consts::PI / (2.0 * big_n as f64) + NODE_ANGLE_MARGIN);
        let sec = (1.0 / angle.cos()) * (1.0 + 8.0 * f64::EPSILON);
        let binom: Vec<f64> = (0..=n).map(|i| cagd_core::binomial_f64(n, i)).collect();
        let (mut tp, mut sp) = (vec![1.0; n + 1], vec![1.0; n + 1]);
        // The Bernstein values at the nodes (`B^T`, column `j` for node `j`), then `V^T =
        // U^T B^T` through the GEMM kernel: column-major, so `V` row-major.
        let mut bern_t = vec![0.0; rows * (n + 1)];
        for (j, col) in bern_t.chunks_exact_mut(n + 1).enumerate() {
            let t = node(j, big_n);
            let s = 1.0 - t;
            let (mut pt, mut ps) = (1.0, 1.0);
            for (x, y) in tp.iter_mut().zip(sp.iter_mut()) {
                (*x, *y) = (pt, ps);
                pt *= t;
                ps *= s;
            }
            // b_i = C(n,i) t^i s^(n-i), the same products in the same order as before.
            for ((b, c), (x, y)) in col
                .iter_mut()
                .zip(&binom)
                .zip(tp.iter().zip(sp.iter().rev()))
            {
                *b = c * x * y;
            }
        }
        let vt = DMatrix::from_column_slice(r, n + 1, &basis.u)
            * DMatrix::from_column_slice(n + 1, rows, &bern_t);
        let v: Vec<f64> = vt.as_slice().to_vec();
        let umax: Vec<f64> = (0..r)
            .map(|k| {
                (0..=n)
                    .map(|i| basis.u[i * r + k].abs())
                    .fold(0.0, f64::max)
            })
            .collect();
        let ug: f64 = umax.iter().zip(&basis.gsum).map(|(u, g)| u * g).sum();
        let vg = v
            .chunks_exact(r.max(1))
            .map(|row| row.iter().zip(&basis.gsum).map(|(x, g)| x.abs() * g).sum())
            .fold(0.0, f64::max);
        let eps = f64::EPSILON;
        let inner = 2.0 * eps * ((r as f64 + nf + 1.0) * vg + (4.0 * nf + 5.0) * ug);
        let outer = basis.rho + 2.0 * (nf + 1.0) * eps * op_norm;
        let split = basis.even.map(|re| {
            let part = |cols: std::ops::Range<usize>| {
                let w = cols.len();
                let a = v
                    .chunks_exact(r.max(1))
                    .flat_map(|row| row[cols.clone()].iter().copied())
                    .collect();
                LinearMap::new(rows, w, a)
            };
            (part(0..re), part(re..r))
        });
        Self {
            samples: LinearMap::new(rows, r, v),
            split,
            sec,
            inner,
            outer,
        }
    }

    /// The bound from the largest node value `smax = max_j ||s^_j||` and `pmax = max_j
    /// ||P_j||` (both as computed); `+inf` if they overflowed.
    pub(crate) fn finish(&self, smax: f64, pmax: f64, dim: usize) -> f64 {
        let eps = f64::EPSILON;
        let pmax = pmax * (1.0 + (dim as f64 + 2.0) * eps);
        let b = (self.sec * (smax * (1.0 + (dim as f64 + 4.0) * eps) + self.inner * pmax)
            + self.outer * pmax)
            * (1.0 + 4.0 * eps)
            + f64::MIN_POSITIVE;
        if b.is_nan() { f64::INFINITY } else { b }
    }
}

/// The node `t_j = sin^2(j pi / (2N))` (`t_0 = 0`, `t_N = 1` exactly); shared with the
/// B-spline fit's span bounds (`bspline/fit/node_bound.rs`).
pub(crate) fn node(j: usize, big_n: usize) -> f64 {
    if j == big_n {
        return 1.0;
    }
    let s = (j as f64 * std::f64::consts::PI / (2.0 * big_n as f64)).sin();
    s * s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The inequality itself on the worst polynomials we know: Chebyshev polynomials
    /// shifted so their extrema fall between nodes, measured on a fine grid.
    #[test]
    fn secant_factor_bounds_shifted_chebyshev_polynomials() {
        for n in [1usize, 2, 5, 10, 30] {
            for ratio in [1.25, 1.075] {
                let angle_half = (1.0_f64 / ratio).acos() / n as f64;
                #[allow(clippy::cast_possible_truncation, reason = "N < 300")]
                let big_n = ((std::f64::consts::FRAC_PI_2 / angle_half).ceil() as usize).max(n + 1);
                let sec = 1.0 / (n as f64 * std::f64::consts::PI / (2.0 * big_n as f64)).cos();
                assert!(sec <= ratio * (1.0 + 1e-9));
                // p(x) = T_n(a x + b) squeezed so that it has its extrema at shifted places.
                for shift in 0..20 {
                    let a = 1.0 - 0.01 * shift as f64;
                    let b = 1.0 - a;
                    let p = |t: f64| {
                        let x = a * (1.0 - 2.0 * t) + b * (shift % 2) as f64;
                        (n as f64 * x.clamp(-1.0, 1.0).acos()).cos()
                    };
                    let at_nodes = (0..=big_n)
                        .map(|j| p(node(j, big_n)).abs())
                        .fold(0.0, f64::max);
                    let true_max = (0..=20000)
                        .map(|i| p(i as f64 / 20000.0).abs())
                        .fold(0.0, f64::max);
                    assert!(
                        true_max <= sec * at_nodes * (1.0 + 1e-12),
                        "n {n} ratio {ratio} shift {shift}: {true_max} > {sec} * {at_nodes}"
                    );
                }
            }
        }
    }
}
