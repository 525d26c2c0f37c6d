//! The Gauss rows of one span of the global fit, compressed to `m + 1` rows (goes beyond
//! the seed; the same least-squares problem as one row per Gauss node, see
//! [`super`]).
//!
//! On a span `[a, b]` (`h = b - a`, local parameter `x`), the fit's `k` weighted rows are
//! `sqrt(h w_q) N_j(a + h x_q)` against `sqrt(h w_q) C(a + h x_q)`. The basis functions
//! alive on the span are degree-`m` polynomials, `N = B^m E` with `E` the span's Bézier
//! extraction (`(m + 1) x (m + 1)`, from the knots), and the source on the span is its
//! restriction `sub` (`p + 1` Bézier points), `C = B^p sub`. With `G = W^(1/2) B^m(x_q)`
//! (`k x (m + 1)`, the same for every span) and its QR factorisation `G = Q R`, the span's
//! part of the objective is
//!
//! `h ||G E y - W^(1/2) B^p(x_q) sub||^2 = h ||R E y - M sub||^2 + (a term without y)`,
//! `M = Q^T W^(1/2) B^p(x_q)`,
//!
//! because `G E y` lies in the range of `Q`. So `m + 1` rows `sqrt(h) R E` against
//! `sqrt(h) M sub` replace the `k = ceil((p + m + 1) / 2)` rows: no normal equations,
//! an orthogonal transformation of the rows, and the source enters through the
//! restriction the span's bound needs anyway (one restriction per span, no evaluation of
//! the source per node).

use std::cell::RefCell;
use std::rc::Rc;

use cagd_core::{Result, gauss_legendre};
use nalgebra::DMatrix;

use super::node_bound::{RECENT, push_bernstein};

/// `R` and `M` of the module docs for one `(p, m)`.
#[derive(Debug)]
pub(crate) struct SpanRows {
    p: usize,
    m: usize,
    /// `(m + 1) x (m + 1)`, row-major, upper triangular.
    r: Vec<f64>,
    /// `(m + 1) x (p + 1)`, row-major.
    mv: Vec<f64>,
}

thread_local! {
    /// The last rows built on this thread (every round and every curve of a batch asks
    /// for the same pair).
    static LAST: RefCell<Vec<Rc<SpanRows>>> = const { RefCell::new(Vec::new()) };
}

impl SpanRows {
    /// The rows for `(p, m)`, from this thread's cache (the [`RECENT`] most recently used
    /// pairs) or built.
    ///
    /// # Errors
    /// Those of [`gauss_legendre`] (the node count is out of its range).
    pub(crate) fn cached(p: usize, m: usize) -> Result<Rc<Self>> {
        LAST.with(|c| {
            let mut c = c.borrow_mut();
            if let Some(at) = c.iter().position(|x| x.p == p && x.m == m) {
                let x = c.remove(at);
                c.push(Rc::clone(&x));
                return Ok(x);
            }
            let x = Rc::new(Self::new(p, m)?);
            if c.len() >= RECENT {
                c.remove(0);
            }
            c.push(Rc::clone(&x));
            Ok(x)
        })
    }

    /// Builds `R` and `M` by a Householder QR of `[G | W^(1/2) B^p(x_q)]` (nalgebra's):
    /// the top `m + 1` rows of `Q^T` times the augmented matrix.
    fn new(p: usize, m: usize) -> Result<Self> {
        let (nodes, weights) = gauss_legendre((p + m + 2) / 2)?;
        let k = nodes.len();
        let mut aug = DMatrix::<f64>::zeros(k, m + 1 + p + 1);
        let (mut bm, mut bp) = (Vec::with_capacity(m + 1), Vec::with_capacity(p + 1));
        for (q, (x, w)) in nodes.iter().zip(&weights).enumerate() {
            let sw = w.sqrt();
            bm.clear();
            bp.clear();
            push_bernstein(m, *x, &mut bm);
            push_bernstein(p, *x, &mut bp);
            for (j, v) in bm.iter().chain(&bp).enumerate() {
                aug[(q, j)] = sw * v;
            }
        }
        let qr = aug.columns(0, m + 1).into_owned().qr();
        let mut rest = aug.columns(m + 1, p + 1).into_owned();
        qr.q_tr_mul(&mut rest);
        let rm = qr.r();
        let mut r = vec![0.0; (m + 1) * (m + 1)];
        let mut mv = vec![0.0; (m + 1) * (p + 1)];
        for i in 0..=m {
            for j in i..=m {
                r[i * (m + 1) + j] = rm[(i, j)];
            }
            for j in 0..=p {
                mv[i * (p + 1) + j] = rest[(i, j)];
            }
        }
        Ok(Self { p, m, r, mv })
    }

    /// The span's `m + 1` rows into `rows` (`(m + 1) x (m + 1)`, row-major: `sqrt(h) R
    /// E`) and right-hand sides into `rhs` (`(m + 1) x d`: `sqrt(h) M sub`), `ext` the
    /// extraction `E` (row `l` the Bézier coefficients `l` of the `m + 1` basis functions),
    /// `sub` the source's `p + 1` points of `d` coordinates on the span.
    pub(crate) fn rows(
        &self,
        h: f64,
        ext: &[f64],
        sub: &[f64],
        d: usize,
        rows: &mut [f64],
        rhs: &mut [f64],
    ) {
        if self.m == 3 && d == 4 {
            self.rows_fixed::<4, 4>(h, ext, sub, rows, rhs);
            return;
        }
        self.rows_general(h, ext, sub, d, rows, rhs);
    }

    /// [`Self::rows`] with `m + 1 = M1` and `d = D` known at compile time (cubic fits of
    /// 3-D NURBS: 4 and 4): the same sums in the same order, so the same values, in fixed
    /// arrays (ADDED, issue 17's real-CAD-file row).
    fn rows_fixed<const M1: usize, const D: usize>(
        &self,
        h: f64,
        ext: &[f64],
        sub: &[f64],
        rows: &mut [f64],
        rhs: &mut [f64],
    ) {
        let p1 = self.p + 1;
        let sh = h.sqrt();
        let ext: &[f64] = &ext[..M1 * M1];
        for i in 0..M1 {
            let mut row = [0.0f64; M1];
            for l in i..M1 {
                let c = sh * self.r[i * M1 + l];
                let e: &[f64; M1] = ext[l * M1..(l + 1) * M1].try_into().expect("a row");
                for j in 0..M1 {
                    row[j] += c * e[j];
                }
            }
            rows[i * M1..(i + 1) * M1].copy_from_slice(&row);
            let mut out = [0.0f64; D];
            for (c, x) in self.mv[i * p1..(i + 1) * p1]
                .iter()
                .zip(sub.chunks_exact(D))
            {
                let x: &[f64; D] = x.try_into().expect("a point");
                for k in 0..D {
                    out[k] += c * x[k];
                }
            }
            for v in &mut out {
                *v *= sh;
            }
            rhs[i * D..(i + 1) * D].copy_from_slice(&out);
        }
    }

    /// [`Self::rows`] for any `m` and `d`.
    fn rows_general(
        &self,
        h: f64,
        ext: &[f64],
        sub: &[f64],
        d: usize,
        rows: &mut [f64],
        rhs: &mut [f64],
    ) {
        let (m1, p1) = (self.m + 1, self.p + 1);
        let sh = h.sqrt();
        rows.fill(0.0);
        rhs.fill(0.0);
        for i in 0..m1 {
            let row = &mut rows[i * m1..(i + 1) * m1];
            for l in i..m1 {
                let c = sh * self.r[i * m1 + l];
                for (v, e) in row.iter_mut().zip(&ext[l * m1..(l + 1) * m1]) {
                    *v += c * e;
                }
            }
            let out = &mut rhs[i * d..(i + 1) * d];
            for (c, x) in self.mv[i * p1..(i + 1) * p1]
                .iter()
                .zip(sub.chunks_exact(d))
            {
                for (v, y) in out.iter_mut().zip(x) {
                    *v += c * y;
                }
            }
            for v in out.iter_mut() {
                *v *= sh;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_testkit::bench::random_input;

    /// The fixed-size rows (cubic, 4 coordinates) are bitwise the general loop's.
    #[test]
    fn the_fixed_rows_are_the_general_ones() {
        for p in [4usize, 9, 15] {
            let rows = SpanRows::new(p, 3).unwrap();
            let ext = random_input(16, 7 + p as u64);
            let sub = random_input((p + 1) * 4, 8 + p as u64);
            let (mut r1, mut b1) = (vec![0.0; 16], vec![0.0; 16]);
            let (mut r2, mut b2) = (vec![0.0; 16], vec![0.0; 16]);
            rows.rows(0.37, &ext, &sub, 4, &mut r1, &mut b1);
            rows.rows_general(0.37, &ext, &sub, 4, &mut r2, &mut b2);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!((bits(&r1), bits(&b1)), (bits(&r2), bits(&b2)), "p {p}");
        }
    }

    /// The compressed rows against the `k` uncompressed Gauss rows of the same span (an
    /// independent route: Bernstein values at the nodes, no QR): the two squared residuals
    /// differ by the same constant for every coefficient vector `y`, so both have the same
    /// minimiser.
    #[test]
    fn compressed_rows_differ_from_the_gauss_rows_by_a_constant() {
        let (p, m, d) = (11, 3, 2);
        let rows = SpanRows::new(p, m).unwrap();
        let h = 0.37;
        let ext = random_input((m + 1) * (m + 1), 5);
        let sub = random_input((p + 1) * d, 6);
        let (mut r, mut rhs) = (vec![0.0; (m + 1) * (m + 1)], vec![0.0; (m + 1) * d]);
        rows.rows(h, &ext, &sub, d, &mut r, &mut rhs);
        let (nodes, weights) = gauss_legendre((p + m + 2) / 2).unwrap();
        let mut diffs = Vec::new();
        for seed in 0..5 {
            let y = random_input((m + 1) * d, 100 + seed);
            let mut full = 0.0;
            for (x, w) in nodes.iter().zip(&weights) {
                let (mut bm, mut bp) = (Vec::new(), Vec::new());
                push_bernstein(m, *x, &mut bm);
                push_bernstein(p, *x, &mut bp);
                for c in 0..d {
                    let mut v = 0.0;
                    for j in 0..=m {
                        let nj: f64 = (0..=m).map(|l| bm[l] * ext[l * (m + 1) + j]).sum();
                        v += nj * y[j * d + c];
                    }
                    let src: f64 = (0..=p).map(|i| bp[i] * sub[i * d + c]).sum();
                    full += h * w * (v - src) * (v - src);
                }
            }
            let mut small = 0.0;
            for i in 0..=m {
                for c in 0..d {
                    let v: f64 = (0..=m).map(|j| r[i * (m + 1) + j] * y[j * d + c]).sum();
                    small += (v - rhs[i * d + c]).powi(2);
                }
            }
            diffs.push(full - small);
        }
        assert!(diffs[0] > 1e-3, "{diffs:?}");
        for x in &diffs {
            assert!((x - diffs[0]).abs() < 1e-12, "{diffs:?}");
        }
    }
}
