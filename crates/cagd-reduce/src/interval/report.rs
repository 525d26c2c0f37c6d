//! What an interval reduction reports (SPEC-convert I.2, post-processing (2)).

use super::patch::IntervalTriPatch;

/// Options of [`crate::reduce_interval_triangle`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IntervalOptions {
    /// Target degree `m < n`.
    pub target: usize,
    /// The containment degree `N >= n` of the tighter model (SPEC-convert I.2: require
    /// `E_{m->N} L <= E_{n->N} f_lo` and `E_{m->N} U >= E_{n->N} f_hi`); `None` is `N = n`,
    /// the paper's model.
    pub containment_degree: Option<usize>,
    /// Dense sampling for [`IntervalReport::max_violation`]: the grid `(a/K, b/K)` with this
    /// `K` (`(K + 1)(K + 2) / 2` points; the default 44 gives 1 035). `0` skips sampling.
    pub sample_grid: usize,
}

impl IntervalOptions {
    /// Reduction to `target` with the paper's model (`N = n`) and the default sampling.
    pub fn new(target: usize) -> Self {
        Self {
            target,
            containment_degree: None,
            sample_grid: super::DEFAULT_SAMPLE_GRID,
        }
    }
}

/// The report of an interval reduction.
#[derive(Debug, Clone, PartialEq)]
pub struct IntervalReport {
    /// Thickness of the input (SPEC-convert I.1).
    pub thickness_in: f64,
    /// Thickness of the output.
    pub thickness_out: f64,
    /// `thickness_out / thickness_in`; `None` when the input has thickness 0.
    pub ratio: Option<f64>,
    /// Per coordinate: whether the coupled LP (with `L <= U`) was solved because the
    /// decoupled optimum had an empty interval (SPEC-convert I.2, normative procedure).
    pub coupled: Vec<bool>,
    /// The largest outward shift applied by the containment repair (model units; 0 when
    /// the solver's vertex was already certified).
    pub repair: f64,
    /// The largest pointwise violation of containment found by dense sampling (`<= 0`:
    /// contained at every sample; see [`IntervalOptions::sample_grid`]); `None` when
    /// sampling was skipped.
    pub max_violation: Option<f64>,
    /// Number of domain points sampled.
    pub samples: usize,
    /// The containment degree `N` of the model that was solved and certified.
    pub containment_degree: usize,
    /// Sum over coordinates of the LP optima `sum U - sum L` as solved (before repair).
    pub objective: f64,
    /// Sum over coordinates of the decoupled LP optima (`<= objective`; equal where no
    /// coordinate needed the coupling).
    pub objective_decoupled: f64,
    /// Size of each decoupled LP: `(rows, variables) = (N_N, N_m)`.
    pub lp_size: (usize, usize),
}

/// A certified interval reduction: the wrapping patch and its report.
#[derive(Debug, Clone, PartialEq)]
pub struct IntervalReduction {
    /// The degree-`m` interval triangle; it contains the input (certified).
    pub patch: IntervalTriPatch,
    /// What was done and measured.
    pub report: IntervalReport,
}
