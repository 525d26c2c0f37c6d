//! A certified bound of one rational span's fit error from its *numerator*: the span bound
//! of [`super::rational_span`] for a single NURBS (goes beyond the seed; issue 17, the
//! real-CAD-file row).
//!
//! On a span, the input is `C = A / W` and the fit `S = A' / W'` (homogeneous pieces of
//! degrees `p` and `m`). For any centre `c`, with `A_c = A - c W` and `A'_c = A' - c W'`,
//!
//! ```text
//! C - S = (A W' - A' W) / (W W') = N / (W W'),   N = A_c W' - A'_c W,
//! ```
//!
//! `N` a polynomial of degree `p + m` (the centre cancels exactly; it only keeps the
//! computed values small). So `max ||C - S|| <= max ||N|| / min (W W')`, and `max ||N||` is
//! bounded from `N`'s values at the Chebyshev–Lobatto nodes of degree `p + m` by the
//! Ehlich–Zeller factor, as [`super::node_bound`] does for the polynomial difference (the
//! values from `N`'s Bézier points, `(p + 1)(m + 1)` products per coordinate, then one
//! Bernstein matrix of degree `p + m`); `min (W W')` from below by the smallest Bernstein
//! coefficient of the product `W W'` (degree `p + m`, a convex combination of the products
//! `w_i w'_j`).
//!
//! Why: the earlier bound `(h_A + R h_W) / v` bounds the two homogeneous differences `A_c -
//! A'_c` and `W - W'` separately, but the homogeneous fit's errors nearly cancel in the
//! model (`e_A ≈ C e_W + W (C - S)`), so it was up to 2.2 times the measured error at 1e-3
//! and split spans that met the tolerance. `N` keeps the cancellation: the bound is within
//! the node factor (1.075) and the weights' variation on the span of the true maximum.

use std::cell::RefCell;
use std::rc::Rc;

use super::node_bound::{BLOCK_DIM, LANES, NodeGrid, cached};
use crate::bezier::hull_bound;
use cagd_core::binomial_f64;

/// The Bernstein matrix of degree `p + m` at its nodes, the product's coefficient table
/// and the secant factor.
#[derive(Debug, Clone)]
pub(crate) struct NumeratorNodes {
    p: usize,
    m: usize,
    /// Node count `N + 1`, rounded up to a multiple of [`LANES`] (the extra columns of
    /// `bn` are zero).
    nodes: usize,
    /// `(p + m + 1) x nodes`, row `k` the values `B^(p+m)_k(t_j)`.
    bn: Vec<f64>,
    /// `(p + 1) x (m + 1)`: `C(p, i) C(m, j) / C(p + m, i + j)`, the share of the products
    /// of points `i` and `j` in the product's coefficient `i + j` (each coefficient's
    /// shares sum to one).
    prod: Vec<f64>,
    /// `sec((p + m) (pi / (2N) + margin))`, rounded up.
    sec: f64,
    /// `N` (the nodes `t_j`, `j = 0..=N`).
    big_n: usize,
    /// The columns `j = 0..=N/2` of the symmetric split, rounded up to a multiple of
    /// [`LANES`] (the extra columns of `even` and `odd` are zero).
    half: usize,
    /// `(n/2 + 1) x half` (`n = p + m`): row `k < n - k` the values `B_k(t_j) +
    /// B_(n-k)(t_j)`, and for even `n` row `n / 2` the values `B_(n/2)(t_j)`.
    even: Vec<f64>,
    /// `((n + 1) / 2) x half`: row `k < n - k` the values `B_k(t_j) - B_(n-k)(t_j)`.
    odd: Vec<f64>,
}

thread_local! {
    /// The last nodes built on this thread (a fit asks for the same `(p, m)` every span).
    static LAST: RefCell<Vec<Rc<NumeratorNodes>>> = const { RefCell::new(Vec::new()) };
}

/// The data of one span for [`NumeratorNodes::bound`]: the input's and the fit's Bézier
/// points on the span, centred (`dim` coordinates of `A_c`, then `W`, per point), and the
/// sizes their rounding is measured in.
pub(crate) struct CentredSpan<'a> {
    /// `p + 1` points of `dim + 1` values: the input restricted to the span.
    pub(crate) sub: &'a [f64],
    /// `m + 1` points of `dim + 1` values: the fit's piece on the span.
    pub(crate) tgt: &'a [f64],
    /// `(pa, pw)`: `max ||A_i|| + ||c|| |W_i|` and `max |W_i|` over the input piece `sub`
    /// was restricted from (two de Casteljau cuts, `2 p` convex levels at most).
    pub(crate) piece: (f64, f64),
    /// `(qa, qw)`: the same over the fit's control points `tgt` was extracted from (`m`
    /// levels of de Boor's convex combinations).
    pub(crate) fit: (f64, f64),
    /// The smallest control weight of the fit on the span: `W' >= vmin` exactly.
    pub(crate) vmin: f64,
}

impl NumeratorNodes {
    /// The nodes for `(p, m)`, from this thread's one-entry cache or built.
    pub(crate) fn cached(p: usize, m: usize) -> Rc<Self> {
        cached(&LAST, |nb| nb.p == p && nb.m == m, || Self::new(p, m))
    }

    /// The nodes for the degree-`(p + m)` numerator of a degree-`p` input's span and its
    /// degree-`m` fit, with secant factor at most [`super::node_bound::RATIO`].
    pub(crate) fn new(p: usize, m: usize) -> Self {
        let deg = p + m;
        let grid = NodeGrid::for_degree(deg);
        let mut prod = vec![0.0; (p + 1) * (m + 1)];
        for i in 0..=p {
            for j in 0..=m {
                prod[i * (m + 1) + j] =
                    binomial_f64(p, i) * binomial_f64(m, j) / binomial_f64(deg, i + j);
            }
        }
        let bn = grid.bernstein(deg);
        let big_n = grid.big_n();
        let half = (big_n / 2 + 1).div_ceil(LANES) * LANES;
        let (pairs, rows) = (deg.div_ceil(2), deg / 2 + 1);
        let (mut even, mut odd) = (vec![0.0; rows * half], vec![0.0; pairs * half]);
        for j in 0..=big_n / 2 {
            for k in 0..rows {
                let (x, y) = (bn[k * grid.nodes + j], bn[(deg - k) * grid.nodes + j]);
                if k < deg - k {
                    even[k * half + j] = x + y;
                    odd[k * half + j] = x - y;
                } else {
                    even[k * half + j] = x;
                }
            }
        }
        Self {
            p,
            m,
            nodes: grid.nodes,
            bn,
            prod,
            sec: grid.sec,
            big_n,
            half,
            even,
            odd,
        }
    }

    /// `(a value of ||C - S|| at a node, certified lower bound of W W', certified bound of
    /// max ||C - S||)` on the span (module docs); the node value is the error at the node
    /// where `||N||` is largest (one the error attains, up to rounding). Leaves in `coef`
    /// the numerator's Bézier points (`p + m + 1` points of `dim` coordinates) and then the
    /// product `W W'`'s (`p + m + 1` values), for [`Self::hull`]. The bound is `+inf` where
    /// the weights' lower bound is not positive.
    ///
    /// The numerator's Bézier points come from the product formula, `N_k = sum_(i + j = k)
    /// s_ij (a_i w'_j - a'_j w_i)` with the shares `s_ij` of `prod`, and its node values
    /// from the degree-`(p + m)` Bernstein matrix. Rounding (`eps` = [`f64::EPSILON`],
    /// twice the unit roundoff; sizes `||A_c|| <= pa`, `|W| <= pw`, `||A'_c|| <= qa`,
    /// `|W'| <= qw`, convex combinations of the sized points, and `X = pa qw + qa pw`):
    /// *coefficients*, a sum of at most `m + 1` terms `s (a w' - a' w)` whose shares sum
    /// to one, each share within `3 eps`: within `(m + 8) eps X` per coordinate;
    /// *evaluation*, the Bernstein values of degree `p + m` at the `f64` nodes within
    /// `(3(p + m) + 3) eps` relative and the sum of `p + m + 1` products within `(p + m +
    /// 2) eps` of the coefficients' size: `(4(p + m) + 5) eps X`; by the symmetric split
    /// ([`Self::symmetric_max`], 3-D) `(7(p + m) + 14) eps X`, the larger, is allowed; the
    /// squared norm adds `(dim + 3) eps` relative. So the node values are within `inner =
    /// 2 (7(p + m) + m + 22) (sqrt(dim) + 1) eps X` (a factor 2 for the second-order terms
    /// and the margin).
    /// *Inputs*: `sub` is within `3p eps` of its sizes of the exact restriction, its
    /// centring adds `2 eps pa` (the size includes `||c|| |W|`), the fit's piece is within
    /// `((m + 1)(2m + 1) + 2) eps` of its sizes (`NodeBound::bound`'s extraction allowance,
    /// and the centring); the numerator is bilinear, so its exact value moves by at most
    /// `outer = 2 (3p + (m + 1)(2m + 1) + 4) (sqrt(dim) + 1) eps X`. The weights' product:
    /// each coefficient of the computed `W W'` is a convex combination, within `(p + m +
    /// 4) eps` relative and `(3p + (m + 1)(2m + 1) + 2) eps pw qw` of the exact one's.
    // Not inlined (as `NodeBound::bound`): inlined into the span loop, the node loop
    // compiled to about twice the instructions (callgrind, the `cad_curves` NURBS).
    #[inline(never)]
    pub(crate) fn bound(&self, span: &CentredSpan<'_>, coef: &mut Vec<f64>) -> (f64, f64, f64) {
        let (p, m, nn) = (self.p, self.m, self.nodes);
        let deg = p + m;
        let blk = span.sub.len() / (p + 1);
        let dim = blk - 1;
        debug_assert!(span.sub.len() == (p + 1) * blk && span.tgt.len() == (m + 1) * blk);
        self.coefficients(span, coef);
        let (num, wprod) = coef.split_at((deg + 1) * dim);
        let (best, at) = if dim == 3 {
            self.symmetric_max::<3>(num)
        } else if dim <= BLOCK_DIM {
            self.blocked_max(num, dim)
        } else {
            self.axpy_max(num, dim)
        };
        let lower = best.sqrt();
        let eps = f64::EPSILON;
        let (pf, mf, df) = (p as f64, m as f64, dim as f64);
        let ((pa, pw), (qa, qw)) = (span.piece, span.fit);
        let root = df.sqrt() + 1.0;
        let x = (pa * qw + qa * pw) * (1.0 + 1e-6);
        let inner = 2.0 * (7.0 * (pf + mf) + mf + 22.0) * root * eps * x;
        let outer = 2.0 * (3.0 * pf + (mf + 1.0) * (2.0 * mf + 1.0) + 4.0) * root * eps * x;
        let bn = (self.sec * (lower * (1.0 + (df + 3.0) * eps) + inner) + outer)
            * (1.0 + 4.0 * eps)
            + f64::MIN_POSITIVE;
        let low = self.weight_floor(span, wprod);
        let bound = bn / low * (1.0 + 8.0 * eps);
        let bound = if low > 0.0 && bound >= 0.0 {
            bound
        } else {
            f64::INFINITY
        };
        // The error at the node of the largest `||N||`: `||N|| / (W W')` there.
        let w_at: f64 = wprod
            .iter()
            .enumerate()
            .map(|(k, w)| self.bn[k * nn + at] * w)
            .sum();
        let seen = lower / w_at;
        let seen = if seen.is_finite() && seen >= 0.0 {
            seen.min(bound)
        } else {
            bound
        };
        (seen, low, bound)
    }

    /// The numerator's Bézier points, then the weight product's, into `coef` (see
    /// [`Self::bound`]).
    fn coefficients(&self, span: &CentredSpan<'_>, coef: &mut Vec<f64>) {
        let (p, m) = (self.p, self.m);
        let deg = p + m;
        let blk = span.sub.len() / (p + 1);
        let dim = blk - 1;
        coef.clear();
        coef.resize((deg + 1) * blk, 0.0);
        let (num, wprod) = coef.split_at_mut((deg + 1) * dim);
        if dim == 3 {
            self.products::<3>(span, num, wprod);
            return;
        }
        for (i, q) in span.sub.chunks_exact(blk).enumerate() {
            let row = &self.prod[i * (m + 1)..(i + 1) * (m + 1)];
            for ((j, r), v) in span.tgt.chunks_exact(blk).enumerate().zip(row) {
                let out = &mut num[(i + j) * dim..(i + j + 1) * dim];
                for c in 0..dim {
                    out[c] += v * (q[c] * r[dim] - r[c] * q[dim]);
                }
                wprod[i + j] += v * (q[dim] * r[dim]);
            }
        }
    }

    /// The loop of [`Self::coefficients`] for `D` coordinates known at compile time (the
    /// same operations in the same order, so the same values; the 3-D curves of CAD files
    /// take it).
    fn products<const D: usize>(&self, span: &CentredSpan<'_>, num: &mut [f64], wprod: &mut [f64]) {
        let m1 = self.m + 1;
        let blk = D + 1;
        let num = &mut num[..(self.p + self.m + 1) * D];
        for (i, q) in span.sub.chunks_exact(blk).enumerate() {
            let row = &self.prod[i * m1..(i + 1) * m1];
            let qw = q[D];
            let qa: [f64; D] = q[..D].try_into().expect("D coordinates");
            for ((j, r), v) in span.tgt.chunks_exact(blk).enumerate().zip(row) {
                let rw = r[D];
                let out: &mut [f64; D] = (&mut num[(i + j) * D..(i + j + 1) * D])
                    .try_into()
                    .expect("D coordinates");
                for c in 0..D {
                    out[c] += v * (qa[c] * rw - r[c] * qw);
                }
                wprod[i + j] += v * (qw * rw);
            }
        }
    }

    /// `(max_j ||N(t_j)||^2, its node j)`, [`LANES`] nodes at a time with the accumulators
    /// of every coordinate in registers (`dim <= BLOCK_DIM`).
    #[inline(never)]
    fn blocked_max(&self, num: &[f64], dim: usize) -> (f64, usize) {
        let nn = self.nodes;
        let (mut best, mut at) = (0.0f64, 0);
        for j0 in (0..nn).step_by(LANES) {
            let mut acc = [[0.0f64; LANES]; BLOCK_DIM];
            for (row, x) in self.bn.chunks_exact(nn).zip(num.chunks_exact(dim)) {
                let r: &[f64; LANES] = row[j0..j0 + LANES].try_into().expect("a block");
                for (a, c) in acc.iter_mut().zip(x) {
                    for l in 0..LANES {
                        a[l] += r[l] * c;
                    }
                }
            }
            for l in 0..LANES {
                let sq: f64 = acc[..dim].iter().map(|a| a[l] * a[l]).sum();
                if sq > best || sq.is_nan() {
                    (best, at) = (if sq.is_nan() { f64::INFINITY } else { sq }, j0 + l);
                }
            }
        }
        (best, at)
    }

    /// [`Self::blocked_max`] for `D` coordinates known at compile time by the symmetric
    /// split of the nodes: `t_(N-j) = 1 - t_j` and `B_k(1 - t) = B_(n-k)(t)`, so with `e_k =
    /// c_k + c_(n-k)` and `o_k = c_k - c_(n-k)` (`k < n - k`; `e = 2 c` for the middle
    /// coefficient of an even `n`), `2 N(t_j) = E_j + O_j` and `2 N(t_(N-j)) = E_j - O_j`,
    /// `E_j = sum e_k (B_k + B_(n-k))(t_j)`, `O_j = sum o_k (B_k - B_(n-k))(t_j)`: the two
    /// nodes of a pair for `n + 1` products per coordinate instead of `2 (n + 1)` (the
    /// even/odd split of a reversal-symmetric basis, as the operators' error basis,
    /// `bezier/operator/error_basis.rs`). The mirrored node is `1 - t_j` exactly, within
    /// the grid's angle margin of `t_(N-j)`. Rounding (`C` the largest `|c_k|`): `e_k`
    /// within `eps C`, the table within `(3n + 4) eps` relative, the sums of at most `n/2 +
    /// 1` terms of total weight `<= 1` within `(n/2 + 2) eps` of `2 C`, the last sum `2 eps
    /// C`: `N(t)` within `(7n + 14) eps C` ([`Self::bound`]'s allowance). ADDED (issue 17,
    /// the real-CAD-file row): the node values were a ninth of reducing a NURBS to cubics
    /// within 1e-3. Returns `(max_j ||N(t_j)||^2, its node j)`.
    #[inline(never)]
    fn symmetric_max<const D: usize>(&self, num: &[f64]) -> (f64, usize) {
        let (n, hn, big_n) = (self.p + self.m, self.half, self.big_n);
        let pairs = n.div_ceil(2);
        let rows = n / 2 + 1;
        let mut e = [[0.0f64; D]; 16];
        let mut o = [[0.0f64; D]; 16];
        let (e, o) = if rows <= 16 {
            (&mut e[..rows], &mut o[..pairs])
        } else {
            return self.blocked_max(num, D);
        };
        for k in 0..rows {
            let x: &[f64; D] = num[k * D..(k + 1) * D].try_into().expect("a point");
            if k < n - k {
                let y: &[f64; D] = num[(n - k) * D..(n - k + 1) * D]
                    .try_into()
                    .expect("a point");
                for c in 0..D {
                    e[k][c] = x[c] + y[c];
                    o[k][c] = x[c] - y[c];
                }
            } else {
                for c in 0..D {
                    e[k][c] = 2.0 * x[c];
                }
            }
        }
        let (mut best, mut at) = (0.0f64, 0);
        let mut keep = |sq: f64, j: usize| {
            if sq > best || sq.is_nan() {
                (best, at) = (if sq.is_nan() { f64::INFINITY } else { sq }, j);
            }
        };
        for j0 in (0..hn).step_by(LANES) {
            let mut ae = [[0.0f64; LANES]; D];
            let mut ao = [[0.0f64; LANES]; D];
            for (k, x) in e.iter().enumerate() {
                let r: &[f64; LANES] = self.even[k * hn + j0..k * hn + j0 + LANES]
                    .try_into()
                    .expect("a block");
                for c in 0..D {
                    for l in 0..LANES {
                        ae[c][l] += r[l] * x[c];
                    }
                }
            }
            for (k, x) in o.iter().enumerate() {
                let r: &[f64; LANES] = self.odd[k * hn + j0..k * hn + j0 + LANES]
                    .try_into()
                    .expect("a block");
                for c in 0..D {
                    for l in 0..LANES {
                        ao[c][l] += r[l] * x[c];
                    }
                }
            }
            for l in 0..LANES {
                let j = j0 + l;
                if 2 * j > big_n {
                    break;
                }
                let lo: f64 = (0..D).map(|c| (ae[c][l] + ao[c][l]).powi(2)).sum();
                let hi: f64 = (0..D).map(|c| (ae[c][l] - ao[c][l]).powi(2)).sum();
                keep(0.25 * lo, j);
                keep(0.25 * hi, big_n - j);
            }
        }
        (best, at)
    }

    /// [`Self::blocked_max`] for any `dim`: one axpy over the nodes per coefficient and
    /// coordinate.
    fn axpy_max(&self, num: &[f64], dim: usize) -> (f64, usize) {
        let nn = self.nodes;
        let mut vals = vec![0.0; dim * nn];
        for (row, x) in self.bn.chunks_exact(nn).zip(num.chunks_exact(dim)) {
            for (v, c) in vals.chunks_exact_mut(nn).zip(x) {
                for (a, b) in v.iter_mut().zip(row) {
                    *a += b * c;
                }
            }
        }
        let (mut best, mut at) = (0.0f64, 0);
        for j in 0..nn {
            let sq: f64 = (0..dim).map(|c| vals[c * nn + j] * vals[c * nn + j]).sum();
            if sq > best || sq.is_nan() {
                (best, at) = (if sq.is_nan() { f64::INFINITY } else { sq }, j);
            }
        }
        (best, at)
    }

    /// The refined convex hull ([`crate::bezier::hull_bound`]) of the numerator's Bézier
    /// points `coef` (as [`Self::bound`] left them) over `low` (its lower bound of `W
    /// W'`): the sharper bound of a span above the budget. Rounding: the coefficients are
    /// within `(m + 8) (sqrt(dim) + 1) eps X` of those of the computed pieces' numerator
    /// ([`Self::bound`]), and the inputs add its `outer`.
    pub(crate) fn hull(&self, span: &CentredSpan<'_>, low: f64, coef: &[f64]) -> f64 {
        let (p, m) = (self.p, self.m);
        let blk = span.sub.len() / (p + 1);
        let dim = blk - 1;
        if low <= 0.0 {
            return f64::INFINITY;
        }
        let num = &coef[..(p + m + 1) * dim];
        let eps = f64::EPSILON;
        let (pf, mf, df) = (p as f64, m as f64, dim as f64);
        let ((pa, pw), (qa, qw)) = (span.piece, span.fit);
        let root = df.sqrt() + 1.0;
        let x = (pa * qw + qa * pw) * (1.0 + 1e-6);
        let slack =
            2.0 * ((mf + 8.0) + 3.0 * pf + (mf + 1.0) * (2.0 * mf + 1.0) + 4.0) * root * eps * x;
        let zero = vec![0.0; dim];
        let h = (hull_bound(num, &zero, dim) + slack) * (1.0 + 4.0 * eps);
        let b = h / low * (1.0 + 8.0 * eps);
        if b >= 0.0 { b } else { f64::INFINITY }
    }

    /// A certified lower bound of `W W'` on the span from the product's Bézier points
    /// `wprod` (as computed by [`Self::bound`]): the smallest, less its rounding and the
    /// inputs' (see [`Self::bound`]), and never below `(min w_i - 3p eps pw) vmin`.
    fn weight_floor(&self, span: &CentredSpan<'_>, wprod: &[f64]) -> f64 {
        let (p, m) = (self.p, self.m);
        let blk = span.sub.len() / (p + 1);
        let dim = blk - 1;
        let eps = f64::EPSILON;
        let (pw, qw) = (span.piece.1, span.fit.1);
        let (pf, mf) = (p as f64, m as f64);
        let least = wprod.iter().copied().fold(f64::INFINITY, f64::min);
        let low_prod = least * (1.0 - (pf + mf + 4.0) * eps)
            - (3.0 * pf + (mf + 1.0) * (2.0 * mf + 1.0) + 2.0) * eps * pw * qw * 1.01;
        let wmin = span
            .sub
            .chunks_exact(blk)
            .map(|q| q[dim])
            .fold(f64::INFINITY, f64::min)
            - 3.0 * pf * eps * pw * 1.01;
        let low_sep = if wmin > 0.0 && span.vmin > 0.0 {
            wmin * span.vmin * (1.0 - 2.0 * eps)
        } else {
            0.0
        };
        if low_prod.is_nan() {
            low_sep
        } else {
            low_prod.max(low_sep)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::node_bound::RATIO;
    use super::super::{Source, fit, span_bounds};
    use super::*;
    use cagd_core::BSplineCurve;
    use cagd_testkit::bench::random_input;

    /// The node maximum by the symmetric split is the general loop's (every node by the
    /// full Bernstein matrix) within the split's rounding allowance, `(7n + 14) eps` of the
    /// largest coefficient for the split and `(4n + 5) eps` for the general loop, and its
    /// node holds that value, at degrees 4–15 against 1–5 (odd and even `p + m`),
    /// scales 1e-300 to 1e300, and for a numerator largest at the mirrored half.
    #[test]
    fn the_symmetric_node_loop_is_the_general_one() {
        let mut seed = 500;
        for (p, m) in [(4, 3), (7, 1), (9, 3), (12, 5), (15, 3), (6, 2), (15, 5)] {
            let nodes = NumeratorNodes::new(p, m);
            let n = p + m;
            for scale in [1.0, 1e-300, 1e300, 3e-7] {
                for tilt in [false, true] {
                    seed += 1;
                    let mut num: Vec<f64> = random_input((n + 1) * 3, seed)
                        .iter()
                        .map(|x| scale * x)
                        .collect();
                    if tilt {
                        // Large at the end: the maximum at a node of the mirrored half.
                        for (k, x) in num.iter_mut().enumerate() {
                            *x *= 1.0 + 10.0 * (k / 3) as f64;
                        }
                    }
                    let (a, _) = nodes.blocked_max(&num, 3);
                    let (b, j) = nodes.symmetric_max::<3>(&num);
                    if !a.is_finite() {
                        // The squares overflow at 1e300: both routes say so.
                        assert!(b == f64::INFINITY, "({p}, {m}) scale {scale}: {b}");
                        continue;
                    }
                    let c = num.iter().fold(0.0f64, |s, x| s.max(x.abs()));
                    let tol = (11.0 * n as f64 + 19.0) * f64::EPSILON * c * 3f64.sqrt();
                    assert!(
                        (a.sqrt() - b.sqrt()).abs() <= tol,
                        "({p}, {m}) scale {scale}: {a} {b}"
                    );
                    // The value at node j by the full matrix.
                    let at: f64 = (0..3)
                        .map(|c| {
                            (0..=n)
                                .map(|k| nodes.bn[k * nodes.nodes + j] * num[k * 3 + c])
                                .sum::<f64>()
                                .powi(2)
                        })
                        .sum();
                    assert!((at.sqrt() - b.sqrt()).abs() <= tol, "({p}, {m}) node {j}");
                    if tilt && b > 0.0 {
                        // (At 1e-300 the squares underflow: every node is zero.)
                        assert!(2 * j > nodes.big_n, "({p}, {m}): node {j}");
                    }
                }
            }
        }
    }

    /// `max ||a(t) / w(t) - b(t) / v(t)||` of two homogeneous Bézier pieces on `[0, 1]`
    /// (de Casteljau, independent of the nodes), at 20 000 samples with a golden-section
    /// polish around the best one.
    fn measured_pieces(sub: &[f64], tgt: &[f64], blk: usize) -> f64 {
        let (a, b) = (
            cagd_core::BezierCurve::new(sub.to_vec(), blk).unwrap(),
            cagd_core::BezierCurve::new(tgt.to_vec(), blk).unwrap(),
        );
        let f = |t: f64| {
            let (x, y) = (a.eval(t), b.eval(t));
            (0..blk - 1)
                .map(|c| (x[c] / x[blk - 1] - y[c] / y[blk - 1]).powi(2))
                .sum::<f64>()
                .sqrt()
        };
        let k = 20_000;
        let (mut best, mut at) = (0.0f64, 0.0);
        for i in 0..=k {
            let t = f64::from(i) / f64::from(k);
            let v = f(t);
            if v > best {
                (best, at) = (v, t);
            }
        }
        let (mut lo, mut hi) = (
            (at - 1.0 / f64::from(k)).max(0.0),
            (at + 1.0 / f64::from(k)).min(1.0),
        );
        for _ in 0..60 {
            let (x1, x2) = (lo + 0.382 * (hi - lo), lo + 0.618 * (hi - lo));
            if f(x1) > f(x2) {
                hi = x2;
            } else {
                lo = x1;
            }
        }
        best.max(f(0.5 * (lo + hi)))
    }

    /// Random homogeneous pieces (degrees 4–15 against 1–5, weights with ratios up to
    /// 1e4 inside a piece, near pairs as a fit leaves them, 2-D and 3-D, sizes 1e-3 to
    /// 1e3): the bound is never below the densely measured error, the node value never
    /// above it (it is one), the hull never below it either, and the bound within the node
    /// factor [`super::node_bound::RATIO`] times the weights' variation on the piece (`max w max w' / (min w
    /// min w')`) of the measured error.
    #[test]
    fn the_numerator_bound_covers_the_measured_error() {
        let mut seed = 7;
        let mut worst_near: f64 = 0.0;
        for (p, m) in [(4, 3), (6, 3), (9, 3), (12, 5), (15, 3), (15, 1)] {
            let nodes = NumeratorNodes::new(p, m);
            for dim in [2, 3] {
                let blk = dim + 1;
                for (spread, near, scale) in [
                    (0.3, false, 1.0),
                    (0.3, true, 1.0),
                    (0.3, true, 1e3),
                    (0.3, true, 1e-3),
                    (4.0, true, 1.0),
                    (13.0, false, 1.0),
                ] {
                    seed += 1;
                    let r = random_input((p + 1) * blk + (m + 1) * blk, seed);
                    let weight = |x: f64| 2f64.powf(spread * x);
                    // The fit's piece: a smooth arc with random weights (random points
                    // when not near).
                    let off = (m + 1) * blk;
                    let mut tgt = Vec::new();
                    for j in 0..=m {
                        let w = weight(r[j * blk + dim]);
                        let s = j as f64 / m as f64;
                        for c in 0..dim {
                            let x = if near {
                                scale * ((1.0 + c as f64) * s).sin()
                            } else {
                                scale * r[j * blk + c]
                            };
                            tgt.push(w * x);
                        }
                        tgt.push(w);
                    }
                    // The input: near, the fit's piece elevated to degree `p`, its model
                    // points moved by 1e-4 of the size and its weights by 1e-3; far, a
                    // random arc.
                    let mut sub = vec![0.0; (p + 1) * blk];
                    cagd_core::kernel::elevate(&tgt, blk, p - m, &mut sub);
                    for (i, q) in sub.chunks_exact_mut(blk).enumerate() {
                        let e = &r[off + i * blk..off + (i + 1) * blk];
                        let w = if near {
                            q[dim] * (1.0 + 1e-3 * e[dim])
                        } else {
                            weight(e[dim])
                        };
                        let s = i as f64 / p as f64;
                        for c in 0..dim {
                            let x = if near {
                                q[c] / q[dim] + 1e-4 * scale * e[c]
                            } else {
                                scale * ((1.0 + c as f64) * s).sin() + 0.1 * scale * e[c]
                            };
                            q[c] = w * x;
                        }
                        q[dim] = w;
                    }
                    let sizes = |x: &[f64]| {
                        x.chunks_exact(blk).fold((0.0f64, 0.0f64), |(a, w), q| {
                            let n = q[..dim].iter().map(|v| v * v).sum::<f64>().sqrt();
                            (a.max(n), w.max(q[dim].abs()))
                        })
                    };
                    let vmin = tgt
                        .chunks_exact(blk)
                        .map(|q| q[dim])
                        .fold(f64::INFINITY, f64::min);
                    let span = CentredSpan {
                        sub: &sub,
                        tgt: &tgt,
                        piece: sizes(&sub),
                        fit: sizes(&tgt),
                        vmin,
                    };
                    let mut coef = Vec::new();
                    let (seen, low, bound) = nodes.bound(&span, &mut coef);
                    let hull = nodes.hull(&span, low, &coef);
                    let meas = measured_pieces(&sub, &tgt, blk);
                    let tag =
                        format!("{p}->{m} dim {dim} spread {spread} near {near} scale {scale}");
                    assert!(bound >= meas, "{tag}: bound {bound:e} < measured {meas:e}");
                    assert!(hull >= meas, "{tag}: hull {hull:e} < measured {meas:e}");
                    assert!(
                        seen <= meas * (1.0 + 1e-9),
                        "{tag}: node value {seen:e} > {meas:e}"
                    );
                    // Tightness: the bound is within the node factor times the weights'
                    // variation on the piece (`||N|| = ||C - S|| W W'`).
                    let range = |x: &[f64]| {
                        x.chunks_exact(blk)
                            .fold((f64::INFINITY, 0.0f64), |(lo, hi), q| {
                                (lo.min(q[dim]), hi.max(q[dim]))
                            })
                    };
                    let ((sl, sh), (tl, th)) = (range(&sub), range(&tgt));
                    let spread_w = (sh * th) / (sl * tl);
                    if meas > 1e-9 * scale {
                        let r = bound / meas;
                        assert!(
                            r <= RATIO * spread_w * (1.0 + 1e-6),
                            "{tag}: ratio {r} > {RATIO} x {spread_w}"
                        );
                        if near && spread < 1.0 {
                            worst_near = worst_near.max(r / spread_w);
                        }
                    }
                }
            }
        }
        println!("near pairs: bound / measured / weight spread up to {worst_near}");
    }

    /// `max ||C - S||` on `[a, b]` in model space, sampled at 4 000 parameters: `c` and
    /// `s` homogeneous polynomial splines (last coordinate the weight).
    fn measured(c: &BSplineCurve, s: &BSplineCurve, span: (f64, f64)) -> f64 {
        let model = |h: Vec<f64>| {
            let w = h[h.len() - 1];
            h[..h.len() - 1].iter().map(|x| x / w).collect::<Vec<_>>()
        };
        cagd_testkit::sampled_max_distance(
            |t| model(c.eval(t).unwrap()),
            |t| model(s.eval(t).unwrap()),
            span,
            4000,
        )
    }

    /// Adversarial NURBS fitted by cubics through the fit's own span bounds: weight ratios
    /// up to 4 096 between neighbouring control points, a near-cusp (the control polygon
    /// doubling back), interior knots of multiplicity up to `p - 1`; every span's bound
    /// (node route alone and with the hull) is at least the densely measured error.
    #[test]
    fn adversarial_fits_stay_below_their_span_bounds() {
        for (case, p) in [4usize, 5, 7, 10, 13].into_iter().enumerate() {
            for family in 0..3 {
                let mult = if family == 2 { p - 1 } else { 1 };
                let mut knots = vec![0.0; p + 1];
                knots.extend(std::iter::repeat_n(0.4, mult));
                knots.push(0.7);
                knots.extend(std::iter::repeat_n(1.0, p + 1));
                let n = knots.len() - p - 1;
                let r = random_input(4 * n, 300 + 7 * case as u64 + family as u64);
                let mut hom = Vec::with_capacity(4 * n);
                for i in 0..n {
                    let s = i as f64 / (n - 1) as f64;
                    let w = match family {
                        0 => 2f64.powf(6.0 * r[4 * i + 3]),
                        _ => 2f64.powf(r[4 * i + 3]),
                    };
                    let mut q = [(3.0 * s).sin(), (2.0 * s).cos(), s * s];
                    if family == 1 && i == n / 2 {
                        // The polygon doubles back: a near-cusp.
                        q = [(3.0 * s).sin() - 1.5, (2.0 * s).cos() + 0.8, s * s];
                    }
                    for (k, x) in q.iter().enumerate() {
                        hom.push(w * (x + 0.05 * r[4 * i + k]));
                    }
                    hom.push(w);
                }
                let c = BSplineCurve::new(p, knots.clone(), hom, 4).unwrap();
                let src = Source::new(&c, 4, true).unwrap();
                for extra in [0usize, 7] {
                    let mut inner: Vec<f64> = vec![0.4, 0.7];
                    inner.extend((1..=extra).map(|j| j as f64 / (extra + 1) as f64 + 0.003));
                    inner.sort_by(f64::total_cmp);
                    let mut cubic = vec![0.0; 4];
                    cubic.extend(inner.iter().flat_map(|&t| [t, t]));
                    cubic.extend([1.0; 4]);
                    let pts = fit(&src, 3, &cubic).unwrap();
                    let s = BSplineCurve::new(3, cubic.clone(), pts.clone(), 4).unwrap();
                    for sharpen in [f64::INFINITY, 0.0] {
                        let bounds =
                            span_bounds(&src, 3, (&cubic, &pts), sharpen, &mut Vec::new()).unwrap();
                        for x in &bounds {
                            let meas = measured(&c, &s, (x.a, x.b));
                            assert!(
                                x.bound >= meas,
                                "p={p} family {family} extra {extra}: bound {:e} < measured {meas:e} on [{}, {}]",
                                x.bound,
                                x.a,
                                x.b
                            );
                        }
                    }
                }
            }
        }
    }
}
