//! Interval triangular Bernstein–Bézier patches (seed 004 §1, SPEC-convert I.1).

use cagd_core::{check_points, tri_count};

use super::MAX_INTERVAL_DEGREE;
use super::basis::basis_values;
use super::certify::{Containment, Side, containment_degree_of};
use super::elevation::{IntElevation, check_pair};
use crate::{Error, Result};

/// An interval triangular Bézier patch of degree `n` in any dimension: one control box
/// `[lo, hi]` (per coordinate) for each `i + j + k = n` (SPEC-convert I.1).
///
/// `lo` and `hi` are flat row-major nets in the DESIGN triangle order (i-major: for `i` in
/// `0..=n`, for `j` in `0..=n-i`; box `q` coordinate `c` at `q * dim + c`). The surface at a
/// domain point `P` is the box `[sum B^n(P) lo, sum B^n(P) hi]` (Bernstein functions are
/// non-negative, so interval arithmetic is "lower with lower, upper with upper").
///
/// Invariants (checked by [`IntervalTriPatch::new`]): `dim >= 1`, `n <= MAX_INTERVAL_DEGREE`,
/// every bound finite, `lo <= hi` everywhere.
#[derive(Debug, Clone, PartialEq)]
pub struct IntervalTriPatch {
    degree: usize,
    dim: usize,
    lo: Vec<f64>,
    hi: Vec<f64>,
}

impl IntervalTriPatch {
    /// An interval triangle of degree `degree` from its lower and upper nets
    /// (`tri_count(degree) * dim` doubles each, i-major).
    ///
    /// # Errors
    /// [`Error::DegreeOutOfRange`] (`degree > MAX_INTERVAL_DEGREE`), [`Error::ZeroDimension`],
    /// [`Error::LengthMismatch`], [`Error::NonFinite`] (a NaN or infinite bound, in `lo` or
    /// `hi`), [`Error::EmptyInterval`] (`lo > hi` somewhere).
    pub fn new(lo: Vec<f64>, hi: Vec<f64>, degree: usize, dim: usize) -> Result<Self> {
        if degree > MAX_INTERVAL_DEGREE {
            return Err(Error::DegreeOutOfRange {
                degree,
                max: MAX_INTERVAL_DEGREE,
            });
        }
        for net in [&lo, &hi] {
            let n_points = check_points(net, dim)?;
            if n_points != tri_count(degree) {
                return Err(Error::LengthMismatch {
                    what: "interval triangle boxes ((n + 1)(n + 2) / 2)",
                    got: n_points,
                    expected: tri_count(degree),
                });
            }
        }
        if let Some(p) = (0..lo.len()).find(|&p| lo[p] > hi[p]) {
            return Err(Error::EmptyInterval {
                index: p / dim,
                coord: p % dim,
                lo: lo[p],
                hi: hi[p],
            });
        }
        Ok(Self {
            degree,
            dim,
            lo,
            hi,
        })
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// Number of coordinates of each box.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The lower net, `tri_count(n) * dim` doubles, i-major.
    pub fn lo(&self) -> &[f64] {
        &self.lo
    }

    /// The upper net, `tri_count(n) * dim` doubles, i-major.
    pub fn hi(&self) -> &[f64] {
        &self.hi
    }

    /// Thickness (SPEC-convert I.1, reconstruction of the lost seed 004 §2 definition): the mean
    /// box width over control boxes and coordinates,
    /// `delta = (1 / (dim N_n)) sum_ijk sum_c (hi - lo)`. Unchanged by degree elevation.
    /// When the plain sum overflows (many widths near `f64::MAX`), each width is divided by
    /// the count before summing, so a mean of finite widths stays finite; a width that
    /// itself overflows gives infinity.
    pub fn thickness(&self) -> f64 {
        let count = self.lo.len() as f64;
        let widths = || self.hi.iter().zip(&self.lo).map(|(h, l)| h - l);
        let total: f64 = widths().sum();
        if total.is_finite() {
            total / count
        } else {
            widths().map(|w| w / count).sum()
        }
    }

    /// The box of the surface at the domain point `(u, v)` (`w = 1 - u - v`), evaluated in
    /// `f64` with the Bernstein basis: `(lo, hi)`, `dim` doubles each.
    ///
    /// # Errors
    /// [`Error::BadParameter`] unless `u, v >= 0`, `u + v <= 1` and both are finite.
    pub fn eval(&self, u: f64, v: f64) -> Result<(Vec<f64>, Vec<f64>)> {
        for (name, x) in [("u", u), ("v", v)] {
            if !(x.is_finite() && (0.0..=1.0).contains(&x)) {
                return Err(Error::BadParameter {
                    name,
                    value: x,
                    why: "must be in [0, 1]",
                });
            }
        }
        if u + v > 1.0 {
            return Err(Error::BadParameter {
                name: "u + v",
                value: u + v,
                why: "must be <= 1 (domain triangle)",
            });
        }
        let b = basis_values(self.degree, u, v);
        let d = self.dim;
        let mut lo = vec![0.0; d];
        let mut hi = vec![0.0; d];
        for (q, &bq) in b.iter().enumerate() {
            for c in 0..d {
                lo[c] += bq * self.lo[q * d + c];
                hi[c] += bq * self.hi[q * d + c];
            }
        }
        Ok((lo, hi))
    }

    /// Interval degree elevation to degree `n >= self.degree()` (seed 004 Theorem 1,
    /// SPEC-convert I.1): the lower and upper nets are elevated separately with the
    /// non-negative matrix `E`. Rounded to `f64` (use [`IntervalTriPatch::contains`] for an
    /// exact statement about containment).
    ///
    /// # Errors
    /// [`Error::BadDegreePair`] for `n < degree`, [`Error::DegreeOutOfRange`] above
    /// `MAX_INTERVAL_DEGREE`.
    pub fn elevate(&self, n: usize) -> Result<Self> {
        let e = IntElevation::new(self.degree, n)?;
        let d = self.dim;
        let mut lo = vec![0.0; e.nrows() * d];
        let mut hi = vec![0.0; e.nrows() * d];
        for c in 0..d {
            let col = |net: &[f64]| (0..e.ncols()).map(|q| net[q * d + c]).collect::<Vec<_>>();
            let (l, h) = (e.apply_f64(&col(&self.lo)), e.apply_f64(&col(&self.hi)));
            for q in 0..e.nrows() {
                lo[q * d + c] = l[q];
                hi[q * d + c] = h[q];
            }
        }
        // Rounding of the two nets can cross only where lo == hi exactly; keep boxes proper.
        for p in 0..lo.len() {
            if lo[p] > hi[p] {
                lo[p] = hi[p];
            }
        }
        Self::new(lo, hi, n, d)
    }

    /// Certified containment: whether `self` contains `inner` in the control-box sense at
    /// degree `N = max(n_self, n_inner, containment_degree)`, i.e.
    /// `E_{n_self->N} lo_self <= E_{n_inner->N} lo_inner` and
    /// `E_{n_self->N} hi_self >= E_{n_inner->N} hi_inner`, decided in exact arithmetic on the
    /// stored doubles (SPEC-convert I.2). This implies pointwise containment of the interval
    /// surfaces (Bernstein functions are non-negative and sum to 1).
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] for different dimensions; [`Error::DegreeOutOfRange`] when
    /// `N > MAX_INTERVAL_DEGREE`.
    pub fn contains(&self, inner: &Self, containment_degree: Option<usize>) -> Result<bool> {
        if inner.dim != self.dim {
            return Err(Error::LengthMismatch {
                what: "dimension of the inner interval triangle",
                got: inner.dim,
                expected: self.dim,
            });
        }
        let big = containment_degree_of(self.degree.max(inner.degree), containment_degree)?;
        check_pair(self.degree, big)?;
        contains_exact(self, inner, big)
    }
}

/// Whether `outer` contains `inner` at degree `big` (both nets elevated to `big`), exactly.
fn contains_exact(outer: &IntervalTriPatch, inner: &IntervalTriPatch, big: usize) -> Result<bool> {
    let eo = IntElevation::new(outer.degree(), big)?;
    let ei = IntElevation::new(inner.degree(), big)?;
    let cont = Containment {
        outer: &eo,
        inner: &ei,
    };
    let d = outer.dim();
    for c in 0..d {
        let col = |net: &[f64]| net.iter().skip(c).step_by(d).copied().collect::<Vec<_>>();
        if !cont.holds(&col(outer.lo()), &col(inner.lo()), Side::Lower)
            || !cont.holds(&col(outer.hi()), &col(inner.hi()), Side::Upper)
        {
            return Ok(false);
        }
    }
    Ok(true)
}
