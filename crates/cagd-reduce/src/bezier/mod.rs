//! Degree reduction of one Bézier curve (seed 000 ch. 14): the methods ([`Method`],
//! `method.rs`), their exact operators cached per degree pair (`operator/`: one-step,
//! Chebyshev, least-squares and end-constraint constructions), [`reduce`] / [`reduce_with`]
//! with certified bounds (`reduce.rs`), many curves through one operator (`batch.rs`), the
//! G1 perturbation with optimal parameters (`g1.rs`), exact-degree detection
//! (`exact_degree.rs`), the `W_n` table (`wn_table.rs`), the sampled error (`measure.rs`)
//! and reduction to a tolerance by subdivision into a B-spline (`tolerance/`).

mod batch;
mod bound;
mod exact_degree;
mod g1;
pub(crate) mod gemm;
mod lanes;
mod measure;
mod method;
mod operator;
mod padded;
mod reduce;
mod tolerance;
mod wn_table;

pub use batch::{reduce_batch, reduce_batch_with_bounds};
pub use bound::BoundLevel;
pub use exact_degree::{DEFAULT_REL_TOL, exact_degree, reduce_exact};
pub use g1::reduce_g1_optimal;
pub use measure::max_deviation;
pub use method::Method;
pub use operator::{
    ChebyshevTerms, Operator, OperatorRoute, build_operator, constrained_chebyshev_terms,
    eck_lambdas, operator,
};
pub use reduce::{ErrorSpace, ReduceOptions, Reduction, Report, reduce, reduce_with};
pub use tolerance::{
    DEFAULT_MAX_DEPTH, MAX_PIECES, MAX_TOLERANCE_WORK, PiecewiseReduction, PiecewiseReport,
    ReducedPiece, ToleranceOptions, reduce_to_tolerance, reduce_to_tolerance_alg_14_2_1,
    subdivision_levels,
};
pub use wn_table::perturbation_error_factor;

pub(crate) use bound::{pow2_factors, safe_amax};
pub(crate) use operator::{exact_operator, hull_bound, lobatto_node, max_norm};
