//! A certified bound of one span's fit error from its values at Chebyshev–Lobatto nodes
//! (goes beyond the seed; the bound of [`super::span_bounds_restricted`] for polynomial
//! input).
//!
//! On a span, the error `D = C - S` of the fit is a polynomial of degree `p` (the input's
//! piece restricted to the span, `p + 1` Bézier points, minus the fit's degree-`m` piece).
//! Its values at the `N + 1` nodes `t_j = sin^2(j pi / (2N))` of `[0, 1]` are two small
//! matrix products with Bernstein matrices built once per `(p, m)` — no degree
//! elevation, no subdivision. The Ehlich–Zeller inequality (see
//! `bezier/operator/error_map.rs` for the derivation, applied there to the Bézier
//! reducers' error curves) gives `max_t ||D(t)|| <= sec(p pi / (2N)) max_j ||D(t_j)||`, and
//! the node values are themselves curve values, so the bound is within that factor
//! ([`RATIO`]) of the true maximum for every curve.
//!
//! Why not the refined convex hull alone: it subdivides the degree-`p` difference curve up
//! to 15 times per span (`O(p^2)` each) after elevating the fit's piece, and it was half of
//! the C2 fit's instructions (16 M per degree-20 curve, issue 17). This route costs
//! `(N + 1)(p + m + 2)` multiply-adds per coordinate; the refined hull is kept for the few
//! spans whose node bound lands above the budget while their largest node value is below
//! it (`span_bounds`), so no span is split for the factor's sake.

use std::cell::RefCell;
use std::rc::Rc;

use crate::bezier::lobatto_node;
use cagd_core::binomial_f64;

/// The secant factor the nodes are chosen for: `N ≈ 4.2 p`.
pub(crate) const RATIO: f64 = 1.075;

/// Nodes evaluated together (one register block of accumulators per coordinate).
pub(super) const LANES: usize = 4;

/// Most coordinates of the blocked evaluation (more take the axpy route).
pub(super) const BLOCK_DIM: usize = 4;

/// Angle margin added to `pi / (2N)` for the rounding of the `f64` nodes (`|theta^_j -
/// theta_j|` is a few ulps of `theta_j`, far below it).
const NODE_ANGLE_MARGIN: f64 = 1e-9;

/// The Chebyshev–Lobatto nodes `t_j = sin^2(j pi / (2N))`, `j = 0..=N`, of a polynomial of
/// degree `deg`: the fewest (at least `deg + 1`) for which the Ehlich–Zeller factor
/// `sec(deg (pi / (2N) + margin))` is at most [`RATIO`]; shared by this bound and the
/// rational span's numerator bound (`numerator_bound.rs`).
pub(super) struct NodeGrid {
    /// `N`.
    big_n: usize,
    /// `N + 1` rounded up to a multiple of [`LANES`] (the padding columns are zero).
    pub(super) nodes: usize,
    /// `sec(deg (pi / (2N) + margin))`, rounded up.
    pub(super) sec: f64,
}

impl NodeGrid {
    /// The nodes for degree `deg >= 1`.
    pub(super) fn for_degree(deg: usize) -> Self {
        let df = deg as f64;
        let half = (1.0 / RATIO).acos() / df - NODE_ANGLE_MARGIN;
        #[allow(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "deg <= 128 and RATIO = 1.075 give N < 600"
        )]
        let big_n = ((std::f64::consts::FRAC_PI_2 / half).ceil() as usize).max(deg + 1);
        let angle = df * (std::f64::consts::PI / (2.0 * big_n as f64) + NODE_ANGLE_MARGIN);
        let sec = (1.0 / angle.cos()) * (1.0 + 8.0 * f64::EPSILON);
        let nodes = (big_n + 1).div_ceil(LANES) * LANES;
        Self { big_n, nodes, sec }
    }

    /// `N`: the nodes are `t_j`, `j = 0..=N`.
    pub(super) fn big_n(&self) -> usize {
        self.big_n
    }

    /// The Bernstein matrix of degree `n` at the nodes: `(n + 1) x nodes`, row `i` the
    /// values `B^n_i(t_j)` ([`push_bernstein`]), zero in the padding columns.
    pub(super) fn bernstein(&self, n: usize) -> Vec<f64> {
        let mut b = vec![0.0; (n + 1) * self.nodes];
        let mut row = Vec::with_capacity(n + 1);
        for j in 0..=self.big_n {
            row.clear();
            push_bernstein(n, lobatto_node(j, self.big_n), &mut row);
            for (i, v) in row.iter().enumerate() {
                b[i * self.nodes + j] = *v;
            }
        }
        b
    }
}

/// Entries a thread keeps in each cache of [`cached`]: a set of curves of degree 4–15
/// reduced to cubics asks for a dozen `(p, m)` pairs, and with one entry nearly every
/// curve of such a set built its nodes and rows again (ADDED, issue 17's real-CAD-file
/// row: 43 of 50 curves, 3 % of reducing them to cubics within 1e-3).
pub(super) const RECENT: usize = 16;

/// The value in this thread's cache `cell` (the [`RECENT`] most recently used values,
/// oldest first) that `hit` accepts, else `build`'s, which then joins them (a fit asks
/// for the same degrees every span and round, a set of curves for a few pairs).
pub(super) fn cached<T>(
    cell: &'static std::thread::LocalKey<RefCell<Vec<Rc<T>>>>,
    hit: impl Fn(&T) -> bool,
    build: impl FnOnce() -> T,
) -> Rc<T> {
    cell.with(|c| {
        let mut c = c.borrow_mut();
        if let Some(at) = c.iter().position(|v| hit(v)) {
            let v = c.remove(at);
            c.push(Rc::clone(&v));
            return v;
        }
        let v = Rc::new(build());
        if c.len() >= RECENT {
            c.remove(0);
        }
        c.push(Rc::clone(&v));
        v
    })
}

/// The Bernstein matrices of degrees `p` and `m` at the nodes and the bound's constants.
#[derive(Debug, Clone)]
pub(crate) struct NodeBound {
    p: usize,
    m: usize,
    /// Node count `N + 1`, rounded up to a multiple of [`LANES`] (the extra columns of
    /// `bp` and `bm` are zero).
    nodes: usize,
    /// `(p + 1) x (N + 1)`, row `i` the values `B^p_i(t_j)` over the nodes.
    bp: Vec<f64>,
    /// `(m + 1) x (N + 1)`, row `i` the values `B^m_i(t_j)`.
    bm: Vec<f64>,
    /// `sec(p (pi / (2N) + margin))`, rounded up.
    sec: f64,
}

thread_local! {
    /// The last nodes built on this thread (a refinement asks for the same `(p, m)` every
    /// round, and a benchmark for the same pair every curve).
    static LAST: RefCell<Vec<Rc<NodeBound>>> = const { RefCell::new(Vec::new()) };
}

impl NodeBound {
    /// The nodes for `(p, m)`, from this thread's cache ([`cached`]) or built.
    pub(crate) fn cached(p: usize, m: usize) -> Rc<Self> {
        cached(&LAST, |nb| nb.p == p && nb.m == m, || Self::new(p, m))
    }

    /// The nodes for a degree-`p` error curve of a degree-`m` fit (`m < p`), with secant
    /// factor at most [`RATIO`].
    pub(crate) fn new(p: usize, m: usize) -> Self {
        let grid = NodeGrid::for_degree(p);
        Self {
            p,
            m,
            nodes: grid.nodes,
            bp: grid.bernstein(p),
            bm: grid.bernstein(m),
            sec: grid.sec,
        }
    }

    /// `(largest node value, certified bound)` of `max_t ||sub(t) - tgt(t)||` for the
    /// Bézier curves `sub` (degree `p`) and `tgt` (degree `m`) of `dim` coordinates, both
    /// as computed. `pmax` bounds the norms of the points `sub` was restricted from (two
    /// de Casteljau subdivisions, at most `2 p` convex combinations deep), `qmax` those
    /// of the fit's control points `tgt` was extracted from (`m` knot insertions deep);
    /// `vals` is scratch.
    ///
    /// Rounding (`eps` = [`f64::EPSILON`], twice the unit roundoff): the Bernstein values
    /// at the `f64` nodes are within `(3p + 3) eps` relative (binomial, powers, products);
    /// a node value, a sum of `p + m + 2` products, is then within `((3p + 3) + (p + m + 3))
    /// eps` per coordinate of the largest coordinate involved, so within `(4p + 4m + 8)
    /// sqrt(dim) eps (pmax + qmax)` in the Euclidean norm (`inner`, a margin included); the
    /// squared norm adds `(dim + 3) eps` relative. Outside the factor: the restriction is
    /// two de Casteljau runs of convex combinations, each level within `1.5 eps` per
    /// coordinate of the largest input coordinate, so `sub` is within `3p eps pmax` per
    /// coordinate of the exact restriction; `tgt` is the span's extraction matrix `E`
    /// (`m` levels of de Boor's convex combinations on unit vectors: each entry within
    /// `1.5 m eps`; exact rows non-negative, summing to one) times the `m + 1` control
    /// points, so within `(m + 1) 1.5 m eps qmax` for the entries and `(m + 1) eps qmax`
    /// for the sums, i.e. `(m + 1)(2m + 1) eps qmax` per coordinate (it also covers `tgt`
    /// by de Boor's algorithm on the points, `1.5 m eps qmax`). So `outer = (3p + (m +
    /// 1)(2m + 1) + 4) sqrt(dim) eps (pmax + qmax)`.
    // Not inlined: inlined into the span loop its node loop compiled to twice the
    // instructions (callgrind, degree-20 fits).
    #[inline(never)]
    pub(crate) fn bound(
        &self,
        sub: &[f64],
        tgt: &[f64],
        dim: usize,
        (pmax, qmax): (f64, f64),
        vals: &mut Vec<f64>,
    ) -> (f64, f64) {
        let (p, m) = (self.p, self.m);
        debug_assert!(sub.len() == (p + 1) * dim && tgt.len() == (m + 1) * dim);
        let lower = if dim == 3 {
            self.blocked_max_fixed::<3>(sub, tgt)
        } else if dim <= BLOCK_DIM {
            self.blocked_max(sub, tgt, dim)
        } else {
            self.axpy_max(sub, tgt, dim, vals)
        }
        .sqrt();
        let eps = f64::EPSILON;
        let (pf, mf, df) = (p as f64, m as f64, dim as f64);
        let size = (pmax + qmax) * (1.0 + (df + 2.0) * eps);
        let root = df.sqrt() * (1.0 + 2.0 * eps);
        let inner = (4.0 * pf + 4.0 * mf + 8.0) * root * eps * size;
        let outer = (3.0 * pf + (mf + 1.0) * (2.0 * mf + 1.0) + 4.0) * root * eps * size;
        let b = (self.sec * (lower * (1.0 + (df + 3.0) * eps) + inner) + outer) * (1.0 + 4.0 * eps)
            + f64::MIN_POSITIVE;
        (lower, if b.is_nan() { f64::INFINITY } else { b })
    }
}

impl NodeBound {
    /// `max_j ||D(t_j)||^2`, [`LANES`] nodes at a time with the accumulators of every
    /// coordinate in registers (`dim <= BLOCK_DIM`); each node value is the same sum, in
    /// the same order, as in [`Self::axpy_max`].
    fn blocked_max(&self, sub: &[f64], tgt: &[f64], dim: usize) -> f64 {
        let nn = self.nodes;
        let mut best: f64 = 0.0;
        for j0 in (0..nn).step_by(LANES) {
            let mut acc = [[0.0f64; LANES]; BLOCK_DIM];
            for (row, x) in self.bp.chunks_exact(nn).zip(sub.chunks_exact(dim)) {
                let r: &[f64; LANES] = row[j0..j0 + LANES].try_into().expect("a block");
                for (a, c) in acc.iter_mut().zip(x) {
                    for l in 0..LANES {
                        a[l] += r[l] * c;
                    }
                }
            }
            for (row, x) in self.bm.chunks_exact(nn).zip(tgt.chunks_exact(dim)) {
                let r: &[f64; LANES] = row[j0..j0 + LANES].try_into().expect("a block");
                for (a, c) in acc.iter_mut().zip(x) {
                    for l in 0..LANES {
                        a[l] -= r[l] * c;
                    }
                }
            }
            for l in 0..LANES {
                let sq: f64 = acc[..dim].iter().map(|a| a[l] * a[l]).sum();
                best = best.max(sq);
            }
        }
        best
    }

    /// [`Self::blocked_max`] for `D` coordinates known at compile time: the same sums in
    /// the same order, so the same value, with the accumulators a fixed array (ADDED, as
    /// `NumeratorNodes`' fixed loop).
    fn blocked_max_fixed<const D: usize>(&self, sub: &[f64], tgt: &[f64]) -> f64 {
        let nn = self.nodes;
        let mut best: f64 = 0.0;
        for j0 in (0..nn).step_by(LANES) {
            let mut acc = [[0.0f64; LANES]; D];
            for (k, x) in sub.chunks_exact(D).enumerate() {
                let r: &[f64; LANES] = self.bp[k * nn + j0..k * nn + j0 + LANES]
                    .try_into()
                    .expect("a block");
                let x: &[f64; D] = x.try_into().expect("a point");
                for c in 0..D {
                    for l in 0..LANES {
                        acc[c][l] += r[l] * x[c];
                    }
                }
            }
            for (k, x) in tgt.chunks_exact(D).enumerate() {
                let r: &[f64; LANES] = self.bm[k * nn + j0..k * nn + j0 + LANES]
                    .try_into()
                    .expect("a block");
                let x: &[f64; D] = x.try_into().expect("a point");
                for c in 0..D {
                    for l in 0..LANES {
                        acc[c][l] -= r[l] * x[c];
                    }
                }
            }
            for l in 0..LANES {
                let sq: f64 = acc.iter().map(|a| a[l] * a[l]).sum();
                best = best.max(sq);
            }
        }
        best
    }

    /// `max_j ||D(t_j)||^2` by coordinate-major node values in `vals`, one axpy over the
    /// nodes per control point and coordinate (any `dim`).
    fn axpy_max(&self, sub: &[f64], tgt: &[f64], dim: usize, vals: &mut Vec<f64>) -> f64 {
        let nn = self.nodes;
        vals.clear();
        vals.resize(dim * nn, 0.0);
        for (row, x) in self.bp.chunks_exact(nn).zip(sub.chunks_exact(dim)) {
            for (v, c) in vals.chunks_exact_mut(nn).zip(x) {
                for (a, b) in v.iter_mut().zip(row) {
                    *a += b * c;
                }
            }
        }
        for (row, x) in self.bm.chunks_exact(nn).zip(tgt.chunks_exact(dim)) {
            for (v, c) in vals.chunks_exact_mut(nn).zip(x) {
                for (a, b) in v.iter_mut().zip(row) {
                    *a -= b * c;
                }
            }
        }
        let (first, rest) = vals.split_at_mut(nn);
        for a in first.iter_mut() {
            *a *= *a;
        }
        for v in rest.chunks_exact(nn) {
            for (a, b) in first.iter_mut().zip(v) {
                *a += b * b;
            }
        }
        first.iter().copied().fold(0.0, f64::max)
    }
}

/// Appends `B^n_i(t)`, `i = 0..=n`, computed as `C(n, i) t^i (1 - t)^(n - i)`.
pub(super) fn push_bernstein(n: usize, t: f64, out: &mut Vec<f64>) {
    let s = 1.0 - t;
    let start = out.len();
    let mut tp = 1.0;
    for i in 0..=n {
        out.push(binomial_f64(n, i) * tp);
        tp *= t;
    }
    let mut sp = 1.0;
    for i in (0..=n).rev() {
        out[start + i] *= sp;
        sp *= s;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_core::BezierCurve;
    use cagd_testkit::bench::random_input as values;

    /// The thread's cache of nodes keeps the [`RECENT`] pairs asked for last: cycling
    /// through fewer pairs builds each once (the same `Rc` again), more evicts the oldest,
    /// and every value handed out is the fresh one's.
    #[test]
    fn the_cache_keeps_the_recent_pairs() {
        let pairs: Vec<(usize, usize)> = (4..=15).map(|p| (p, 3)).collect();
        assert!(pairs.len() < RECENT);
        let first: Vec<Rc<NodeBound>> = pairs
            .iter()
            .map(|&(p, m)| NodeBound::cached(p, m))
            .collect();
        for (x, &(p, m)) in first.iter().zip(&pairs) {
            let again = NodeBound::cached(p, m);
            assert!(Rc::ptr_eq(x, &again), "({p}, {m}) built again");
            let fresh = NodeBound::new(p, m);
            assert_eq!((again.bp.clone(), again.bm.clone()), (fresh.bp, fresh.bm));
            assert_eq!(again.sec.to_bits(), fresh.sec.to_bits());
        }
        // RECENT more pairs: the first ones are evicted and built anew, equal to fresh.
        for p in 20..20 + RECENT {
            let _ = NodeBound::cached(p, 2);
        }
        let rebuilt = NodeBound::cached(4, 3);
        assert!(!Rc::ptr_eq(&first[0], &rebuilt));
        assert_eq!(rebuilt.bp, NodeBound::new(4, 3).bp);
    }

    /// The node maximum with the coordinates fixed at compile time is the general loop's,
    /// bitwise, at degrees 4–15 against 1–5.
    #[test]
    fn the_fixed_node_loop_is_the_general_one() {
        let mut seed = 900;
        for (p, m) in [(4, 3), (7, 1), (9, 3), (12, 5), (15, 3)] {
            let nb = NodeBound::new(p, m);
            for scale in [1.0, 1e-300, 1e300] {
                seed += 1;
                let sub: Vec<f64> = values((p + 1) * 3, seed)
                    .iter()
                    .map(|x| scale * x)
                    .collect();
                let tgt: Vec<f64> = values((m + 1) * 3, seed + 7)
                    .iter()
                    .map(|x| scale * x)
                    .collect();
                let a = nb.blocked_max(&sub, &tgt, 3);
                let b = nb.blocked_max_fixed::<3>(&sub, &tgt);
                assert_eq!(a.to_bits(), b.to_bits(), "({p}, {m}) scale {scale}");
            }
        }
    }

    /// The densely sampled `max_t ||a(t) - b(t)||` with a golden-section polish around the
    /// best sample (independent of the nodes: de Casteljau evaluation).
    fn measured(a: &BezierCurve, b: &BezierCurve) -> f64 {
        let f = |t: f64| {
            let (x, y) = (a.eval(t), b.eval(t));
            x.iter()
                .zip(&y)
                .map(|(u, v)| (u - v) * (u - v))
                .sum::<f64>()
                .sqrt()
        };
        let k = 1000;
        let (mut best, mut at) = (0.0f64, 0.0);
        for i in 0..=k {
            let t = f64::from(i) / f64::from(k);
            if f(t) > best {
                (best, at) = (f(t), t);
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

    fn check(sub: &[f64], tgt: &[f64], dim: usize) -> (f64, f64, f64) {
        let (a, b) = (
            BezierCurve::new(sub.to_vec(), dim).unwrap(),
            BezierCurve::new(tgt.to_vec(), dim).unwrap(),
        );
        let nb = NodeBound::new(a.degree(), b.degree());
        let norms = |x: &[f64]| {
            x.chunks_exact(dim)
                .map(|q| q.iter().map(|v| v * v).sum::<f64>().sqrt())
                .fold(0.0, f64::max)
        };
        let (lower, upper) = nb.bound(sub, tgt, dim, (norms(sub), norms(tgt)), &mut Vec::new());
        (lower, upper, measured(&a, &b))
    }

    /// Random pairs, near pairs (the fit's situation: a tiny difference of large curves,
    /// `tgt` the degree-`m` truncation-like neighbour of `sub`), spikes, scales 1e-300 ..
    /// 1e300, dimensions 1..=7: the bound is never below the densely measured maximum,
    /// never above [`RATIO`] times it plus rounding, and the node maximum never above it.
    #[test]
    fn never_below_the_measured_error_and_within_the_ratio() {
        let mut worst: f64 = 0.0;
        let mut seed = 0;
        for (p, m) in [
            (4, 3),
            (5, 3),
            (7, 2),
            (10, 3),
            (20, 3),
            (30, 3),
            (40, 8),
            (64, 5),
        ] {
            for dim in [1, 2, 3, 7] {
                for family in 0..4 {
                    for scale in [1.0, 1e-300, 1e150, 1e5] {
                        seed += 1;
                        let mut sub = values((p + 1) * dim, seed);
                        let mut tgt = values((m + 1) * dim, seed + 999);
                        match family {
                            // Near: tgt elevated equals sub up to a small perturbation.
                            1 | 2 => {
                                let mut e = vec![0.0; (p + 1) * dim];
                                cagd_core::kernel::elevate(&tgt, dim, p - m, &mut e);
                                let amp = if family == 1 { 1e-4 } else { 1e-12 };
                                for (s, (x, r)) in sub
                                    .iter_mut()
                                    .zip(e.iter().zip(values((p + 1) * dim, seed + 5)))
                                {
                                    *s = x + amp * r;
                                }
                            }
                            // A single spike in the middle point.
                            3 => {
                                sub.fill(0.0);
                                tgt.fill(0.0);
                                sub[(p / 2) * dim] = 1.0;
                            }
                            _ => {}
                        }
                        for v in sub.iter_mut().chain(tgt.iter_mut()) {
                            *v *= scale;
                        }
                        let (lower, upper, meas) = check(&sub, &tgt, dim);
                        assert!(
                            upper >= meas,
                            "{p}->{m} dim {dim} family {family} scale {scale}: {upper} < {meas}"
                        );
                        // The node maximum is a curve value (up to rounding and the
                        // sampled maximum's own search error).
                        assert!(
                            lower <= meas * (1.0 + 1e-12) + 1e-14 * scale,
                            "{lower} > {meas}"
                        );
                        if meas > 1e-10 * scale {
                            let r = upper / meas;
                            assert!(
                                r <= RATIO + 1e-9,
                                "{p}->{m} dim {dim} family {family}: ratio {r}"
                            );
                            worst = worst.max(r);
                        }
                    }
                }
            }
        }
        println!("worst bound / measured: {worst}");
    }

    #[test]
    fn zero_error_gives_a_rounding_size_bound() {
        let tgt = values(8, 3);
        let mut sub = vec![0.0; 24];
        cagd_core::kernel::elevate(&tgt, 2, 8, &mut sub);
        let (lower, upper, _) = check(&sub, &tgt, 2);
        assert!(
            lower < 1e-14 && upper < 1e-12 && upper > 0.0,
            "{lower} {upper}"
        );
    }
}
