//! Rational → polynomial within a tolerance: a NURBS curve or tensor NURBS surface becomes
//! a polynomial B-spline of degree `<= m` (`m` the input degree by default, lower to reduce
//! the degree and drop the weights in one pass, higher to take a conic into cubics) whose
//! certified distance to the input is within the tolerance, keeping the continuity the
//! input has at each knot (issue 16; SPEC-convert §15 converts exactly, this approximates).
//!
//! The method is ours, built on [`crate::reduce_bspline`]'s global fit (no seed formula):
//! 1. **Exact case**: weights all equal (any common factor) make `C = A / W` the
//!    polynomial spline of the same control points — returned as it is, no spans added
//!    (degree-reduced by [`crate::reduce_bspline`] when `m < p`).
//! 2. **Space**: degree `m` on the input's breaks, each with multiplicity
//!    `m - min(p - s, m - 1)` (`s` its input multiplicity), so the result is
//!    `C^min(p - s, m - 1)` there as the input is `C^(p - s)`.
//! 3. **Fit** ([`curve_fit`]): the discrete parameter-L2 fit of `C = A / W` at
//!    Gauss–Legendre nodes per span, end points kept, banded Givens QR.
//! 4. **Certify** ([`bound`]): per span, `max ||A/W - S|| <= max ||A - W S|| / W` on Bézier
//!    pieces (the polynomial `A - W S` of degree `p + m` by the Bernstein product, centred
//!    on the piece's bounding-box centre, joint subdivision with `W`, rounding included).
//! 5. **Refine** where spans are above 0.9 of the tolerance ([`refine`]: knots placed by
//!    error equidistribution, later rounds split the offending spans) and fit again; then
//!    **remove knots** (Tiller's certified removal, charged per span) within the rest.
//! 6. Steps 2–5 run twice for curves: from every input break, and from only the breaks
//!    that need a multiple knot (`C^(m-1)` cannot be kept there); the result with fewer
//!    spans is returned. Measured on a 1 000-span rational cubic spiral: to cubics within
//!    1e-3 the coarse start gives 350 spans (every break: 455), within 1e-5 every break
//!    gives 1 738 (coarse: 2 148 — the input's third derivative jumps at its knots, which
//!    a cubic follows best with a knot there).
//!
//! Surfaces ([`rational_surface_to_polynomial`]): the same per direction — the fit is the
//! tensor product of the two curve fits on a grid of Gauss nodes (a separable least-squares
//! problem: one banded QR in `u` with every `v` node as a right-hand side, then one in `v`),
//! certified per patch by the tensor form of the same bound, refined by splitting the
//! offending patches' knot intervals, knot lines then removed within the rest.

mod bound;
mod curve;
mod curve_fit;
mod pieces;
mod refine;
mod surface;
mod surface_fit;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_fuzz;
#[cfg(test)]
mod tests_surface;

pub use curve::{PolynomialReduction, PolynomialReport, rational_to_polynomial};
pub use surface::{PolynomialSurfaceReduction, rational_surface_to_polynomial};
