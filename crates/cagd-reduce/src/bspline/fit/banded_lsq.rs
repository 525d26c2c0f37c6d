//! Banded linear least squares by Givens rotations, one observation row at a time
//! (sequential QR as in Lawson & Hanson, "Solving Least Squares Problems", ch. 27, and
//! Dierckx's spline fitting; written anew). No normal equations are formed: the triangular
//! factor `R` of the (weighted) observation matrix is updated row by row, so the condition
//! number that matters is that of the observation matrix, not its square.
//!
//! Every row has its non-zeros in `width` consecutive columns, and rows arrive with
//! non-decreasing first columns (true for B-spline collocation rows ordered by parameter).
//! `R` then has bandwidth `width`, and adding a row costs `O(width (width + rhs))`.

use cagd_core::{Error, Result};

/// The running QR factorisation of a banded least-squares problem `min ||A x - B||_F`
/// with several right-hand sides (`B` has `rhs` columns).
#[derive(Debug, Clone)]
pub(crate) struct BandedLsq {
    n: usize,
    width: usize,
    rhs: usize,
    /// Row `j` of `R`: the entries of columns `j..j + width`.
    r: Vec<f64>,
    /// Row `j` of `Q^T B`.
    z: Vec<f64>,
    /// Whether row `j` of `R` has been set.
    filled: Vec<bool>,
    row: Vec<f64>,
    b: Vec<f64>,
}

impl BandedLsq {
    /// An empty problem with `n` unknowns, bandwidth `width` and `rhs` right-hand sides.
    pub(crate) fn new(n: usize, width: usize, rhs: usize) -> Self {
        Self {
            n,
            width,
            rhs,
            r: vec![0.0; n * width],
            z: vec![0.0; n * rhs],
            filled: vec![false; n],
            row: vec![0.0; width],
            b: vec![0.0; rhs],
        }
    }

    /// Adds the observation `sum_k vals[k] x[start + k] = b` (`vals.len() <= width`,
    /// `start + vals.len() <= n`, `b.len() == rhs`).
    pub(crate) fn add_row(&mut self, start: usize, vals: &[f64], b: &[f64]) {
        debug_assert!(vals.len() <= self.width && start + vals.len() <= self.n);
        if self.width == 4 && self.rhs == 4 {
            self.add_row_fixed::<4, 4>(start, vals, b);
            return;
        }
        let w = self.width;
        self.row.fill(0.0);
        self.row[..vals.len()].copy_from_slice(vals);
        self.b.copy_from_slice(b);
        // `row[k]` is the coefficient of column `col + k`.
        for col in start..self.n {
            let x = self.row[0];
            if x != 0.0 {
                let rj = &mut self.r[col * w..(col + 1) * w];
                let zj = &mut self.z[col * self.rhs..(col + 1) * self.rhs];
                if !self.filled[col] {
                    rj.copy_from_slice(&self.row);
                    zj.copy_from_slice(&self.b);
                    self.filled[col] = true;
                    return;
                }
                let h = norm2(rj[0], x);
                let (c, s) = (rj[0] / h, x / h);
                rj[0] = h;
                for (a, e) in rj[1..].iter_mut().zip(self.row[1..].iter_mut()) {
                    let (ra, re) = (*a, *e);
                    *a = c * ra + s * re;
                    *e = c * re - s * ra;
                }
                for (a, e) in zj.iter_mut().zip(self.b.iter_mut()) {
                    let (za, ze) = (*a, *e);
                    *a = c * za + s * ze;
                    *e = c * ze - s * za;
                }
            }
            self.row.copy_within(1.., 0);
            self.row[w - 1] = 0.0;
            if self.row.iter().all(|v| *v == 0.0) {
                return;
            }
        }
    }

    /// [`Self::add_row`] for a width `W` and `R` right-hand sides known at compile time
    /// (cubic fits of 3-D NURBS: 4 and 4): the same rotations in the same order, so the
    /// same factor, with the row and its right-hand sides in fixed arrays instead of
    /// library copies and fills of four values per column (ADDED, issue 17's
    /// real-CAD-file row: the rows were 7 % of reducing a NURBS to cubics within 1e-3).
    fn add_row_fixed<const W: usize, const R: usize>(
        &mut self,
        start: usize,
        vals: &[f64],
        b: &[f64],
    ) {
        let mut row = [0.0f64; W];
        row[..vals.len()].copy_from_slice(vals);
        let mut rb: [f64; R] = b.try_into().expect("R right-hand sides");
        for col in start..self.n {
            let x = row[0];
            if x != 0.0 {
                let rj: &mut [f64; W] = (&mut self.r[col * W..(col + 1) * W])
                    .try_into()
                    .expect("a row of R");
                let zj: &mut [f64; R] = (&mut self.z[col * R..(col + 1) * R])
                    .try_into()
                    .expect("a row of Q^T B");
                if !self.filled[col] {
                    *rj = row;
                    *zj = rb;
                    self.filled[col] = true;
                    return;
                }
                let h = norm2(rj[0], x);
                let (c, s) = (rj[0] / h, x / h);
                rj[0] = h;
                for k in 1..W {
                    let (ra, re) = (rj[k], row[k]);
                    rj[k] = c * ra + s * re;
                    row[k] = c * re - s * ra;
                }
                for k in 0..R {
                    let (za, ze) = (zj[k], rb[k]);
                    zj[k] = c * za + s * ze;
                    rb[k] = c * ze - s * za;
                }
            }
            row.copy_within(1.., 0);
            row[W - 1] = 0.0;
            if row.iter().all(|v| *v == 0.0) {
                return;
            }
        }
    }

    /// Solves `R x = Q^T B` by back substitution: `n * rhs` values, row-major (`x[j * rhs
    /// + k]`).
    ///
    /// # Errors
    /// [`Error::Singular`] when a diagonal entry of `R` is zero or below `1e-13` of the
    /// largest (the observations do not determine the unknowns).
    pub(crate) fn solve(&self) -> Result<Vec<f64>> {
        let (w, nr) = (self.width, self.rhs);
        let scale = self.r.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let mut x = vec![0.0; self.n * nr];
        for j in (0..self.n).rev() {
            let d = self.r[j * w];
            if !self.filled[j] || d.abs() <= 1e-13 * scale || !d.is_finite() {
                return Err(Error::Singular {
                    what: "banded least-squares system (the fit is not determined)",
                });
            }
            for k in 0..nr {
                let mut acc = self.z[j * nr + k];
                for i in 1..w.min(self.n - j) {
                    acc -= self.r[j * w + i] * x[(j + i) * nr + k];
                }
                x[j * nr + k] = acc / d;
            }
        }
        Ok(x)
    }
}

/// `sqrt(a^2 + b^2)` without overflow or harmful underflow, to a few ulps: the Givens
/// rotation needs no more, and libm's `hypot` (correctly rounded to < 1 ulp) cost a tenth
/// of the whole B-spline fit (profiled on the 1 000-span benchmark).
fn norm2(a: f64, b: f64) -> f64 {
    let (a, b) = (a.abs(), b.abs());
    let (big, small) = if a >= b { (a, b) } else { (b, a) };
    if big == 0.0 {
        return 0.0;
    }
    let r = small / big;
    big * r.mul_add(r, 1.0).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Straight-line fit `y = a + b t` to four points (bandwidth 2 after a change of
    /// basis is not needed: the full 2-column problem is banded with width 2).
    #[test]
    fn matches_a_closed_form_line_fit() {
        let data = [(0.0, 1.0), (1.0, 2.9), (2.0, 5.1), (3.0, 7.0)];
        let mut lsq = BandedLsq::new(2, 2, 1);
        for (t, y) in data {
            lsq.add_row(0, &[1.0, t], &[y]);
        }
        let x = lsq.solve().unwrap();
        // Closed form: b = cov(t, y) / var(t), a = mean(y) - b mean(t).
        let (mt, my) = (1.5, (1.0 + 2.9 + 5.1 + 7.0) / 4.0);
        let b = data.iter().map(|(t, y)| (t - mt) * (y - my)).sum::<f64>()
            / data.iter().map(|(t, _)| (t - mt) * (t - mt)).sum::<f64>();
        assert!(
            (x[1] - b).abs() < 1e-14 && (x[0] - (my - b * mt)).abs() < 1e-14,
            "{x:?}"
        );
    }

    /// A banded problem with an exact solution is solved to rounding, with two right-hand
    /// sides, rows whose fill-in runs past their own band.
    #[test]
    fn recovers_an_exact_banded_solution() {
        let (n, w) = (9usize, 3usize);
        let truth: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin() + 2.0).collect();
        let mut lsq = BandedLsq::new(n, w, 2);
        for start in 0..=n - w {
            for k in 0..3 {
                let vals: Vec<f64> = (0..w).map(|i| 1.0 + ((start + i + k) % 4) as f64).collect();
                let y: f64 = vals.iter().zip(&truth[start..]).map(|(a, b)| a * b).sum();
                lsq.add_row(start, &vals, &[y, -2.0 * y]);
            }
        }
        let x = lsq.solve().unwrap();
        for j in 0..n {
            assert!((x[2 * j] - truth[j]).abs() < 1e-13, "{j}");
            assert!((x[2 * j + 1] + 2.0 * truth[j]).abs() < 1e-13, "{j}");
        }
    }

    /// The fixed-size rows (width 4, four right-hand sides) give bitwise the factor and
    /// solution of the general loop: the same problem through a width-4 / 5-rhs
    /// instance whose fifth right-hand side is zero runs the general loop.
    #[test]
    fn the_fixed_rows_are_the_general_ones() {
        let (n, w) = (12usize, 4usize);
        let vals = cagd_testkit::bench::random_input(400, 3);
        let (mut fixed, mut general) = (BandedLsq::new(n, w, 4), BandedLsq::new(n, w, 5));
        let mut at = 0;
        for start in 0..=n - w {
            for k in 0..5 {
                let len = if k == 4 { 2 } else { w };
                let row = &vals[at..at + len];
                let b = &vals[at + len..at + len + 4];
                at += len + 4;
                fixed.add_row(start, row, b);
                let mut b5 = b.to_vec();
                b5.push(0.0);
                general.add_row(start, row, &b5);
            }
        }
        let (x, y) = (fixed.solve().unwrap(), general.solve().unwrap());
        for j in 0..n {
            for k in 0..4 {
                assert_eq!(x[j * 4 + k].to_bits(), y[j * 5 + k].to_bits(), "{j} {k}");
            }
            assert_eq!(
                fixed.r[j * w..(j + 1) * w],
                general.r[j * w..(j + 1) * w],
                "row {j} of R"
            );
        }
    }

    #[test]
    fn undetermined_is_singular() {
        let mut lsq = BandedLsq::new(3, 2, 1);
        lsq.add_row(0, &[1.0, 1.0], &[1.0]);
        lsq.add_row(0, &[2.0, 2.0], &[2.0]);
        assert!(matches!(lsq.solve(), Err(Error::Singular { .. })));
    }

    #[test]
    fn norm2_is_hypot_to_a_few_ulps_without_overflow() {
        for (a, b) in [
            (3.0, 4.0),
            (-1e300, 1e300),
            (1e-300, -3e-310),
            (0.0, -2.5),
            (7.0, 0.0),
        ] {
            let (got, want) = (norm2(a, b), f64::hypot(a, b));
            assert!(
                (got - want).abs() <= 4.0 * f64::EPSILON * want,
                "{a} {b}: {got} vs {want}"
            );
        }
        assert_eq!(norm2(0.0, 0.0), 0.0);
        assert!(norm2(f64::NAN, 1.0).is_nan());
    }
}
