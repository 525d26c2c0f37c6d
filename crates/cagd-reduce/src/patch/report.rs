//! Options, results and reports of the patch reducers (seed 000 §14.3, SPEC-reduce §4-§5).

use cagd_core::{TensorPatch, TriPatch};

use crate::Method;

/// Extra conditions on a patch reduction, each a constrained version of the same
/// minimisation (what is minimised is the method's own objective; see
/// [`TensorMethod::Perturb`] and [`TriMethod::L2`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum PatchConstraint {
    /// No condition.
    None,
    /// The corner points are kept: `Q` equals `P` at the four (tensor) or three (triangle)
    /// corners. Needs target degree `>= 1` in every direction.
    Corners,
    /// The boundary curves of `Q` are exactly the reductions of `P`'s boundary curves by
    /// this curve method (so two patches sharing an edge still share it after reduction:
    /// C⁰ is kept). The method must interpolate both end points (`end_orders` `>= 0`) so that
    /// the boundary curves meet at the corners, e.g. `Method::L2 { r: 0, p: 0 }`.
    Boundary(Method),
}

/// How a tensor-product patch is reduced by [`crate::reduce_tensor`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum TensorMethod {
    /// Control-point perturbation, seed 000 §14.3.1 (eqs. 14.3.2-14.3.7, Algorithm 14.3.1,
    /// SPEC-reduce §4): degree `(m, n) -> (m - 1, n - 1)` only. Minimises
    /// `sum_ij ||eps_ij||^2` such that `P + eps` is an elevated `(m-1) x (n-1)` patch, under
    /// the given constraint; then `Q` is the inverse elevation of `P + eps`.
    Perturb(PatchConstraint),
    /// Direction by direction with linear curve operators (any `(m, n) -> (m', n')`):
    /// every column (`m + 1` points along `u`) by `u`, then every row of the intermediate net
    /// by `v`; `Q = R_u P R_vᵀ`. When both methods interpolate the end points the boundary
    /// curves of `Q` are exactly the curve reductions of `P`'s boundary curves (C⁰ with
    /// neighbours is kept).
    Curves {
        /// Curve method for the `u` direction (`m -> m'`).
        u: Method,
        /// Curve method for the `v` direction (`n -> n'`).
        v: Method,
    },
}

impl TensorMethod {
    /// A short stable name.
    pub fn name(&self) -> &'static str {
        match self {
            TensorMethod::Perturb(PatchConstraint::None) => "tensor-perturb",
            TensorMethod::Perturb(PatchConstraint::Corners) => "tensor-perturb-corners",
            TensorMethod::Perturb(PatchConstraint::Boundary(_)) => "tensor-perturb-boundary",
            TensorMethod::Curves { .. } => "tensor-curves",
        }
    }
}

/// How a triangular patch is reduced by [`crate::reduce_triangle`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum TriMethod {
    /// Control-point perturbation, seed 000 §14.3.2 (eqs. 14.3.8-14.3.16, Algorithm 14.3.2,
    /// SPEC-reduce §5): degree `n -> n - 1` only, minimises `sum ||eps_ij||^2` such that
    /// `T + eps` is an elevated degree `n - 1` net. Corners are not kept.
    Perturb,
    /// L2-optimal reduction `n -> m` over the triangle (beyond the seed): minimises
    /// `∫∫_T ||P - Q||^2 dA` under the constraint.
    L2(PatchConstraint),
}

impl TriMethod {
    /// A short stable name.
    pub fn name(&self) -> &'static str {
        match self {
            TriMethod::Perturb => "tri-perturb",
            TriMethod::L2(PatchConstraint::None) => "tri-l2",
            TriMethod::L2(PatchConstraint::Corners) => "tri-l2-corners",
            TriMethod::L2(PatchConstraint::Boundary(_)) => "tri-l2-boundary",
        }
    }
}

/// Options of [`crate::reduce_tensor`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchOptions {
    /// The method.
    pub method: TensorMethod,
    /// Also measure the error with [`cagd_core::tensor_patch_distance`] (dense sampling).
    pub measure: bool,
}

impl PatchOptions {
    /// Options for `method`, without measuring.
    pub fn new(method: TensorMethod) -> Self {
        Self {
            method,
            measure: false,
        }
    }
}

/// Options of [`crate::reduce_triangle`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TriOptions {
    /// The method.
    pub method: TriMethod,
    /// Also measure the error with [`cagd_core::tri_patch_distance`] (dense sampling).
    pub measure: bool,
}

impl TriOptions {
    /// Options for `method`, without measuring.
    pub fn new(method: TriMethod) -> Self {
        Self {
            method,
            measure: false,
        }
    }
}

/// What a patch reduction did and how far the result is from the input (Euclidean norm,
/// parametric distance over the domain).
#[derive(Debug, Clone, PartialEq)]
pub struct PatchReport {
    /// The method's name ([`TensorMethod::name`] / [`TriMethod::name`]).
    pub method: &'static str,
    /// Source degrees (`(m, n)`; for triangles `(n, n)`).
    pub degrees_from: (usize, usize),
    /// Target degrees (`(m', n')`; for triangles `(m, m)`).
    pub degrees_to: (usize, usize),
    /// Certified upper bound of `max ||P - Q||` over the domain (`f64` rounding included).
    pub error_bound: f64,
    /// The measured maximum (on request).
    pub max_error: Option<f64>,
}

/// A reduced tensor-product patch and its report.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchReduction {
    /// The reduced patch.
    pub patch: TensorPatch,
    /// What was done, with the certified bound.
    pub report: PatchReport,
    /// `E_u Q E_vᵀ - P` (the control-point perturbation `eps_ij` of §14.3.1 for
    /// [`TensorMethod::Perturb`]), `(m + 1) (n + 1) dim` doubles i-major; its largest norm is
    /// the convex-hull error bound.
    pub perturbation: Vec<f64>,
}

/// A reduced triangular patch and its report.
#[derive(Debug, Clone, PartialEq)]
pub struct TriReduction {
    /// The reduced patch.
    pub patch: TriPatch,
    /// What was done, with the certified bound.
    pub report: PatchReport,
    /// `Elevate(Q) - T` (the perturbation `eps_ij` of §14.3.2 for [`TriMethod::Perturb`]),
    /// i-major, `tri_count(n) dim` doubles.
    pub perturbation: Vec<f64>,
    /// The Lagrange multipliers `lambda_0..lambda_n` of eq. 14.3.16 (`(n + 1) dim` doubles;
    /// [`TriMethod::Perturb`] only).
    pub multipliers: Option<Vec<f64>>,
}

/// One piece of a reduction to a tolerance: the reduced patch on a parameter sub-domain.
#[derive(Debug, Clone, PartialEq)]
pub struct TensorPiece {
    /// The sub-domain `[u0, u1]` of the input patch.
    pub u: (f64, f64),
    /// The sub-domain `[v0, v1]`.
    pub v: (f64, f64),
    /// The piece, reduced, parametrised over `[0, 1]^2` (affinely onto the sub-domain).
    pub reduction: PatchReduction,
}

/// One piece of a triangular reduction to a tolerance.
#[derive(Debug, Clone, PartialEq)]
pub struct TriPiece {
    /// The sub-triangle `(A, B, C)` of the input's parameter domain; the piece is
    /// `T'(u', v') = T(C + u' (A - C) + v' (B - C))` (as [`TriPatch::reparametrize`]).
    pub vertices: [(f64, f64); 3],
    /// The piece, reduced.
    pub reduction: TriReduction,
}
