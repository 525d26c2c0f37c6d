//! Polynomial or rational triangular and tensor-product Bézier patches: a cagd-core net
//! plus optional weights, and the homogeneous form the conversions work on
//! (SPEC-convert §0: a rational formula is a linear map on `q_i = (w_i r_i, w_i)`).

use cagd_core::{Error, Result, TensorPatch, TriPatch, check_weights, kernel};

/// A triangular Bézier patch, polynomial (`weights == None`) or rational.
#[derive(Debug, Clone, PartialEq)]
pub struct TriSurface {
    net: TriPatch,
    weights: Option<Vec<f64>>,
}

/// A tensor-product Bézier patch, polynomial (`weights == None`) or rational.
#[derive(Debug, Clone, PartialEq)]
pub struct TensorSurface {
    net: TensorPatch,
    weights: Option<Vec<f64>>,
}

/// Either kind of patch (an input or an output piece of a conversion).
#[derive(Debug, Clone, PartialEq)]
pub enum PatchSurface {
    /// A tensor-product patch.
    Tensor(TensorSurface),
    /// A triangular patch.
    Tri(TriSurface),
}

/// Homogeneous points `(w r, w)` of a net (dimension `dim + 1`), or the points themselves.
fn homogeneous(points: &[f64], weights: Option<&[f64]>, dim: usize) -> Vec<f64> {
    match weights {
        None => points.to_vec(),
        Some(w) => {
            let mut out = vec![0.0; w.len() * (dim + 1)];
            kernel::to_homogeneous(points, w, dim, &mut out);
            out
        }
    }
}

/// Splits homogeneous points back into Euclidean points and weights.
///
/// # Errors
/// [`Error::NonPositiveWeight`] if a computed weight is not `> 0`, [`Error::NonFinite`] if a
/// division overflows.
fn dehomogenize(hom: Vec<f64>, dim: usize, rational: bool) -> Result<(Vec<f64>, Option<Vec<f64>>)> {
    if !rational {
        return Ok((hom, None));
    }
    let n = hom.len() / (dim + 1);
    let mut points = vec![0.0; n * dim];
    let mut weights = vec![0.0; n];
    for (i, w) in weights.iter_mut().enumerate() {
        *w = hom[i * (dim + 1) + dim];
    }
    check_weights(&weights, n)?;
    kernel::from_homogeneous(&hom, dim, &mut points, &mut weights);
    cagd_core::check_points(&points, dim)?;
    Ok((points, Some(weights)))
}

impl TriSurface {
    /// A patch of degree `degree` from `tri_count(degree) * dim` coordinates (i-major) and,
    /// for a rational patch, `tri_count(degree)` weights in the order of the points.
    ///
    /// # Errors
    /// Those of [`TriPatch::new`], and [`Error::LengthMismatch`] /
    /// [`Error::NonPositiveWeight`] for the weights.
    pub fn new(
        points: Vec<f64>,
        degree: usize,
        dim: usize,
        weights: Option<Vec<f64>>,
    ) -> Result<Self> {
        let net = TriPatch::new(points, degree, dim)?;
        if let Some(w) = &weights {
            check_weights(w, cagd_core::tri_count(degree))?;
        }
        Ok(Self { net, weights })
    }

    /// A polynomial patch.
    pub fn polynomial(net: TriPatch) -> Self {
        Self { net, weights: None }
    }

    /// The Euclidean net.
    pub fn net(&self) -> &TriPatch {
        &self.net
    }

    /// The weights (`None` for a polynomial patch).
    pub fn weights(&self) -> Option<&[f64]> {
        self.weights.as_deref()
    }

    /// Degree `n`.
    pub fn degree(&self) -> usize {
        self.net.degree()
    }

    /// Dimension of the Euclidean points.
    pub fn dim(&self) -> usize {
        self.net.dim()
    }

    /// The homogeneous net `(w r, w)` (dimension `dim + 1`), or the net itself.
    pub fn homogeneous(&self) -> TriPatch {
        match &self.weights {
            None => self.net.clone(),
            Some(w) => {
                let hom = homogeneous(self.net.points(), Some(w), self.dim());
                // Finite products of finite values with positive weights: cannot fail
                // unless they overflow, which `new` would report.
                TriPatch::new(hom, self.degree(), self.dim() + 1)
                    .unwrap_or_else(|_| self.net.clone())
            }
        }
    }

    /// The patch of homogeneous net `hom`, divided when `rational`.
    ///
    /// # Errors
    /// [`Error::NonPositiveWeight`] when a computed weight is not `> 0`.
    pub(crate) fn from_homogeneous(hom: TriPatch, rational: bool) -> Result<Self> {
        let (n, hd) = (hom.degree(), hom.dim());
        let dim = if rational { hd - 1 } else { hd };
        let (points, weights) = dehomogenize(hom.points().to_vec(), dim, rational)?;
        Self::new(points, n, dim, weights)
    }

    /// `T(u, v)` (Euclidean, divided by the weight for a rational patch).
    pub fn eval(&self, u: f64, v: f64) -> Vec<f64> {
        let h = self.homogeneous();
        let mut out = vec![0.0; h.dim()];
        h.eval_into(u, v, &mut out);
        project(out, self.weights.is_some())
    }
}

impl TensorSurface {
    /// A patch of degree `(m, n)` from `(m + 1)(n + 1) * dim` coordinates (i-major) and,
    /// for a rational patch, `(m + 1)(n + 1)` weights in the order of the points.
    ///
    /// # Errors
    /// Those of [`TensorPatch::new`], and [`Error::LengthMismatch`] /
    /// [`Error::NonPositiveWeight`] for the weights.
    pub fn new(
        points: Vec<f64>,
        deg_u: usize,
        deg_v: usize,
        dim: usize,
        weights: Option<Vec<f64>>,
    ) -> Result<Self> {
        let net = TensorPatch::new(points, deg_u, deg_v, dim)?;
        if let Some(w) = &weights {
            check_weights(w, (deg_u + 1) * (deg_v + 1))?;
        }
        Ok(Self { net, weights })
    }

    /// A polynomial patch.
    pub fn polynomial(net: TensorPatch) -> Self {
        Self { net, weights: None }
    }

    /// The Euclidean net.
    pub fn net(&self) -> &TensorPatch {
        &self.net
    }

    /// The weights (`None` for a polynomial patch).
    pub fn weights(&self) -> Option<&[f64]> {
        self.weights.as_deref()
    }

    /// Degrees `(m, n)`.
    pub fn degrees(&self) -> (usize, usize) {
        self.net.degrees()
    }

    /// Dimension of the Euclidean points.
    pub fn dim(&self) -> usize {
        self.net.dim()
    }

    /// The homogeneous net `(w r, w)` (dimension `dim + 1`), or the net itself.
    pub fn homogeneous(&self) -> TensorPatch {
        match &self.weights {
            None => self.net.clone(),
            Some(w) => {
                let (m, n) = self.degrees();
                let hom = homogeneous(self.net.points(), Some(w), self.dim());
                TensorPatch::new(hom, m, n, self.dim() + 1).unwrap_or_else(|_| self.net.clone())
            }
        }
    }

    /// The patch of homogeneous net `hom`, divided when `rational`.
    ///
    /// # Errors
    /// [`Error::NonPositiveWeight`] when a computed weight is not `> 0`.
    pub(crate) fn from_homogeneous(hom: TensorPatch, rational: bool) -> Result<Self> {
        let ((m, n), hd) = (hom.degrees(), hom.dim());
        let dim = if rational { hd - 1 } else { hd };
        let (points, weights) = dehomogenize(hom.points().to_vec(), dim, rational)?;
        Self::new(points, m, n, dim, weights)
    }

    /// `P(u, v)` (Euclidean, divided by the weight for a rational patch).
    pub fn eval(&self, u: f64, v: f64) -> Vec<f64> {
        let h = self.homogeneous();
        let mut out = vec![0.0; h.dim()];
        h.eval_into(u, v, &mut out);
        project(out, self.weights.is_some())
    }
}

impl PatchSurface {
    /// Evaluates the patch at its own parameters `(u, v)` (`(s, t)` of a piece).
    pub fn eval(&self, u: f64, v: f64) -> Vec<f64> {
        match self {
            PatchSurface::Tensor(p) => p.eval(u, v),
            PatchSurface::Tri(t) => t.eval(u, v),
        }
    }

    /// Dimension of the Euclidean points.
    pub fn dim(&self) -> usize {
        match self {
            PatchSurface::Tensor(p) => p.dim(),
            PatchSurface::Tri(t) => t.dim(),
        }
    }

    /// Whether the patch has weights.
    pub fn is_rational(&self) -> bool {
        match self {
            PatchSurface::Tensor(p) => p.weights().is_some(),
            PatchSurface::Tri(t) => t.weights().is_some(),
        }
    }
}

/// Divides a homogeneous point by its last coordinate when `rational`.
fn project(mut h: Vec<f64>, rational: bool) -> Vec<f64> {
    if rational {
        let w = h.pop().unwrap_or(1.0);
        for x in &mut h {
            *x /= w;
        }
    }
    h
}

/// Checks that a split parameter is finite and inside `[lo, hi]`.
///
/// # Errors
/// [`Error::BadParameter`].
pub(crate) fn check_range(
    name: &'static str,
    value: f64,
    lo: f64,
    hi: f64,
    why: &'static str,
) -> Result<()> {
    if value.is_finite() && value >= lo && value <= hi {
        Ok(())
    } else {
        Err(Error::BadParameter { name, value, why })
    }
}
