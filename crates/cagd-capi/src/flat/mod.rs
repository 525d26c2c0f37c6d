//! Handle-free entry points for the hot paths (DESIGN.md, "C ABI conventions": arrays in,
//! arrays out, no handle). Creating and freeing a `CagdCurve` and a `CagdReport` costs
//! about as much as a small reduction, so a C caller that has its control points in an
//! array and wants them back in an array calls these instead:
//!
//! - `cagd_bezier_reduce` (`reduce.rs`): one Bézier curve, every method of
//!   `cagd_curve_reduce`, the same options, the report in a caller-owned
//!   `CagdBezierReport` struct (`report.rs`) or none at all;
//! - `cagd_bezier_elevate` (`elevate.rs`): one curve, degree `n -> n + r`;
//! - `cagd_bezier_elevate_batch` and `cagd_bezier_reduce_batch` (`batch.rs`): many curves of
//!   one degree in a point-major or curve-major array (`CagdBatchLayout`, `layout.rs`), on
//!   an optional number of threads (`threads.rs`).
//!
//! No algorithm lives here: single curves go through the same cagd-core / cagd-reduce
//! functions as the handle API (so the results are equal bit for bit, which the tests
//! check), and the batches go through `kernel.rs`, the one place that knows the batch
//! internals of cagd-reduce (batch reductions sum in the GEMM kernel's order, so they equal
//! the single-curve route up to rounding).

mod batch;
mod elevate;
mod input;
mod kernel;
mod layout;
mod reduce;
mod report;
#[cfg(test)]
mod tests;
mod threads;

pub use batch::{cagd_bezier_elevate_batch, cagd_bezier_reduce_batch};
pub use elevate::cagd_bezier_elevate;
pub(crate) use kernel::operator_for;
pub use layout::CagdBatchLayout;
pub use reduce::cagd_bezier_reduce;
pub use report::CagdBezierReport;
