//! B-spline / NURBS curves and surfaces: the knot vector rules (`knots.rs`), the basis
//! functions (`basis.rs`), the curve type (`curve.rs`) and de Boor evaluation (`eval.rs`),
//! knot insertion (`insert.rs`) and removal (`removal/`), Bézier extraction (`extract.rs`)
//! and its inverse, the merge of Bézier segments (`merge.rs`), surfaces (`surface/`) and the
//! uniform B-spline <-> Bézier matrices of seed 001 (`uniform.rs`).

mod basis;
mod curve;
mod eval;
mod extract;
mod insert;
mod knots;
mod merge;
mod refine;
mod removal;
mod surface;
mod uniform;

pub use basis::basis_functions;
pub use curve::BSplineCurve;
pub use extract::BezierSegment;
pub use knots::{MAX_KNOT, check_knots, find_span, knot_multiplicity};
pub use removal::KnotRemoval;
pub use surface::{BSplineSurface, SurfacePatchPiece};
pub use uniform::{s_matrix, s_matrix_exact, s_matrix_inverse, s_matrix_inverse_exact};
