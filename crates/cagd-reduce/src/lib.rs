//! # cagd-reduce
//!
//! Degree reduction of Bézier curves (polynomial or rational, any dimension): every method
//! of seed 000 (chapter 14) and the classical ones it cites, with the errata of
//! SPEC-reduce, as cached linear operators with certified error bounds.
//!
//! ```
//! use cagd_core::BezierCurve;
//! use cagd_reduce::{Method, operator, reduce, reduce_batch};
//!
//! // A cubic elevated to degree 5 reduces back to the cubic (up to rounding).
//! let cubic = BezierCurve::new(vec![0.0, 0.0, 1.0, 3.0, 3.0, 4.0, 5.0, 1.0], 2)?;
//! let quintic = cubic.elevate(2)?;
//! let red = reduce(&quintic, 3, Method::L2 { r: 1, p: 1 })?;
//! for (a, b) in red.curve.points().iter().zip(cubic.points()) {
//!     assert!((a - b).abs() < 1e-13);
//! }
//! assert!(red.report.error_bound.unwrap() < 1e-12);
//!
//! // A genuine reduction: the certified bound is never below the measured error.
//! let p = BezierCurve::new(vec![0.0, 0.0, 1.0, 3.0, 3.0, 4.0, 5.0, 1.0, 6.0, 5.0, 8.0, 2.0], 2)?;
//! let opts = cagd_reduce::ReduceOptions { measure: true, ..cagd_reduce::ReduceOptions::new(Method::Eck, 4) };
//! let red = cagd_reduce::reduce_with(&p, &opts)?;
//! let (bound, measured) = (red.report.error_bound.unwrap(), red.report.max_error.unwrap());
//! assert!(measured <= bound && bound < 1.0001 * measured); // Eck's bound is exact
//!
//! // Batch: one cached operator, many curves, no per-curve allocation.
//! let op = operator(Method::ConstrainedChebyshev { r: 1, p: 1 }, 5, 4)?;
//! let input = [p.points(), p.points()].concat();
//! let mut output = vec![0.0; 2 * 5 * 2];
//! reduce_batch(&op, &input, 2, &mut output)?;
//! assert_eq!(output[..10], output[10..]);
//! # Ok::<(), cagd_reduce::Error>(())
//! ```
//!
//! ## Methods
//!
//! See [`Method`]. One-degree methods (Forrest, Piegl–Tiller, Farin, Eck, perturbation,
//! G1 perturbation) are applied stepwise for `m < n - 1`; the operator is the exact product
//! of the steps and the bound the sum of the per-step bounds carried through the product
//! (or the convex-hull bound of the composed operator, whichever is smaller). The G1
//! perturbation with optimal `l1, l2` is not linear: [`reduce_g1_optimal`].
//!
//! ## Reduction to a tolerance
//!
//! [`reduce_to_tolerance`] splits the curve adaptively and reduces every piece with any
//! method until each certified bound meets the tolerance, and returns a degree-`m` B-spline
//! with `C^k` joins (interior knot multiplicity `m - k`); [`reduce_to_tolerance_alg_14_2_1`]
//! is seed 000's stepwise perturbation algorithm as corrected in SPEC-reduce §2.2.
//!
//! ## How the operators are computed
//!
//! Each operator is built once per `(method, n, m, r, p)` and cached ([`operator`]). The
//! fast routes (beyond the seed) run the seed's one-degree recursions step by step on rows of
//! functionals (never dense matrix products) and, for the multi-degree methods, closed
//! forms: Watkins–Worsey, Bogacki–Weinstein–Xu and the constrained Chebyshev reduction
//! truncate the Chebyshev series of the deflated residual (seed 000 eqs. 14.5.14–14.5.16);
//! the L2 operators (free = generalized inverse, and with `C^(r,p)` ends) truncate its
//! series in the Jacobi polynomials orthogonal for `t^(2r+2) (1-t)^(2p+2)` — closed-form
//! Bernstein coefficients and moments, no Gram or normal system. They run in `f64`, or in
//! double-word arithmetic where `f64` is not accurate enough, every number carrying a
//! rigorous running error bound; a route is taken only if its proven error is at most
//! `1e-12 ||A||_inf` per row (for methods with their own bound terms, `f64` only at the
//! rounding level `2 (n+3) eps`). Otherwise — and always for the generalized inverse with
//! fixed ends — the exact rational route (`BigRational`: the seed's formulas, exact Gram
//! and normal systems, exact Bernstein <-> Chebyshev conversions) rounded once, which is
//! also the test oracle. [`Operator::route`] says which route built an operator and
//! [`Operator::construction_error`] gives its proven error, which the method's own bound
//! includes. No normal equations are formed in floating point.
//!
//! ## Certified bounds
//!
//! [`Report::error_bound`] is the smaller of the method's own bound (SPEC-reduce §2.1
//! `W_n ||F|| / (C(2n,n) - 2)` with the rounded-up table [`perturbation_error_factor`];
//! Eck's exact `2^(-2n-1) ||Delta^(n+1) P_0||`; eq. 14.5.2's bound; Piegl–Tiller's exact
//! error for odd `m`) and the universal convex-hull bound of the error curve `P - E Q` split
//! into pieces (seed 000 §14.4.3 on each piece; [`BoundLevel`] says how far it is
//! refined), plus a rigorous allowance for `f64` rounding. Rational curves: see
//! [`reduce_with`].
//!
//! ## Supported range and accuracy
//!
//! Degrees `0..=64` ([`cagd_core::MAX_DEGREE`]) for every method and every `m < n`
//! (larger degrees are [`Error::DegreeOutOfRange`]). Each operator entry is within
//! `1e-12 ||A||_inf` of the exact rational value (proven on the fast routes, 1 ulp on the
//! exact route; measured against the exact route, see below); applying it costs about `(n + 1) eps ||A||_inf` relative to the
//! control-point size ([`Operator::norm_inf`]; the amplification is intrinsic to the
//! problem for `m ~ n/2`, SPEC-reduce §6).
//!
//! Measured (unit test `high_degree_operators_match_exact_arithmetic`): applying the `f64`
//! operators to a curve agrees with exact rational arithmetic to **2.0e-15 relative** (max
//! deviation / max reduced coordinate) for seven methods at `n = 40 -> m = 20`, and for the
//! worst case supported, `n = 64` (`m = 32` for the generalized inverse, L2 with
//! `(r,p) = (2,2)`, constrained Chebyshev `(1,1)`, Forrest; `m = 60` for perturbation and
//! BWX). The required 1e-10 is met with five orders of magnitude to spare.
//!
//! Fast routes against the exact oracle (unit tests in `bezier/operator/fast/tests.rs`:
//! every pair `n <= 16` in the debug suite; the ignored sweep over `n` in 20, 30, 40, 50, 64
//! with eight `m` each, run in release): the largest entrywise error relative to
//! `||A||_inf` is 1.1e-14 (L2 with ends, `f64` route at `n <= 16`), 4.9e-15 (generalized
//! inverse, with and without ends) and below 2e-16 for every other method, and every proven
//! bound held. Where no fast route proves 1e-12 the exact route is used: in the sweep, 0 to
//! 12 of its 38 pairs per method, all at `n >= 40` with `m` near `n` (Chebyshev and L2
//! families) or far below it (one-degree steps).
//!
//! Building an operator is a one-time cost per `(method, n, m)` (then cached). Bench
//! `operator_build` (release, 2-core machine shared with other jobs, medians of 9; see
//! `benches/README.md` for every method): L2 with C0 ends 4.7 / 4.7 / 10 / 38 / 41 / 91 µs
//! at `(4,3) (5,4) (10,5) (15,10) (20,10) (30,15)` (exact route 0.1 / 0.1 / 0.2 / 1.3 / 2.0 /
//! 22 ms), 0.6 ms at `64 -> 32`; Forrest 1.3–113 µs; the generalized inverse with fixed
//! ends (a rank-two correction of the free one) 3.7–95 µs; Eck (its closed form, the
//! truncated Chebyshev series) and the Chebyshev family 7–330 µs; the stepwise double-word
//! methods (Piegl–Tiller, Farin, perturbation) up to 0.5–1.2 ms at `(30,15)`; every method
//! 46–100 µs at `64 -> 63` (a one-degree truncation goes from the top). Pairs left to the
//! exact route cost up to seconds at degree 64 (perturbation `64 -> 32` 5–9 s, the
//! Chebyshev family at `64 -> 10` 20–40 ms).
//!
//! Certified bounds: `measured <= bound` is a property test for every method (and for
//! rational curves in Euclidean space). Eck's and the perturbation bounds are the exact
//! maximum errors up to a relative rounding allowance of ~1e-11. The Chebyshev truncation
//! (BWX / Watkins–Worsey) was within a factor 4.6 of the lower bound
//! `(pi/4) ||c_{m+1}||` of the best uniform error (random curves, `n <= 12`, `n - m <= 3`),
//! and equal to Eck's best uniform approximation for one degree.
//!
//! ## Batch reduction and bounds that cost two small matrix products
//!
//! [`reduce_batch`] applies one operator to many curves of the caller's curve-major array
//! through a kernel of this crate with the curves in the lanes of the vectors (8 per
//! vector with AVX-512F, 4 with AVX2, both with FMA and detected at run time, or portable):
//! exactly the multiply-adds of the definition, in blocks of about 64 KiB of input, no
//! allocation per curve, and the same bits for a curve wherever it sits in the batch.
//! [`reduce_batch_with_bounds`] adds a certified bound per curve: the error curve
//! `P - E Q = (I - E A) P` lies in an `(n - m)`-dimensional space, so it is `n - m`
//! coefficient points `c = G P` (one small product) in a precomputed orthonormal basis; its
//! values at `N + 1` Chebyshev–Lobatto nodes are one more small product `V c` (both in the
//! same pass of the kernel as the reduction), and the
//! largest value times the Ehlich–Zeller factor `sec(n pi / (2N))` bounds the error over
//! the whole curve (rounding included). The factor is the bound's promise: at most 1.25×
//! the true error at [`BoundLevel::Fast`] (`N ≈ 2.4 n`), 1.075× at [`BoundLevel::Tight`]
//! (`N ≈ 4.2 n`), for every curve.
//! [`ReduceOptions::bound`] picks the level of a single reduction ([`BoundLevel::None`]
//! skips the bound). Figures: `benches/README.md`.
//!
//! ## Patches (seed 000 §14.3)
//!
//! [`reduce_tensor`]: the perturbation method of §14.3.1 (SPEC-reduce §4 closed form of the
//! singular system 14.3.7), optionally keeping the corners or the boundary curves as the
//! curve reducer reduces them, and multi-degree reduction direction by direction with any
//! linear curve method. [`reduce_triangle`]: the perturbation method of §14.3.2 (closed-form
//! `B_km`, exact) and the L2-optimal reduction over the triangle with corner or boundary
//! constraints. [`reduce_tensor_to_tolerance`] / [`reduce_triangle_to_tolerance`] subdivide
//! uniformly (2-way per direction, 4-way midpoint for triangles per Theorem 14.3.1) until
//! every piece is within the tolerance; with the boundary-consistent methods neighbouring
//! pieces share their edges. The triangular perturbation loses accuracy above degree ~20
//! (4e-12 relative at 20, 1e-8 at 30; the bound stays valid): use L2 there.
//!
//! ## B-splines and NURBS (seed 001)
//!
//! [`reduce_uniform_bspline`]: seed 001's `P' = T_zb^m T_{n,r} T_bz^n P` with any [`Method`]
//! as `T_{n,r}`, per-segment matrices cached, exact (§4.1) or lossy (§4.2) merge; the paper's
//! example is reproduced (see the function's docs for which printed numbers are and are
//! not).
//!
//! [`reduce_bspline`]: any B-spline / NURBS (non-uniform, clamped or not, rational) to a
//! tolerance, keeping `C^min(k, m-1)` wherever the input is `C^k`. Default strategy
//! ([`BSplineStrategy::GlobalFit`]): the degree-`m` spline space on the input's knots (with
//! the multiplicities that carry that continuity), the parameter-L2-best fit in it with the
//! end points kept (exact Gauss–Legendre quadrature per span, banded Givens QR — no normal
//! equations), certified per-span bounds (refined convex hull of input minus fit), simple
//! knots added where a span misses 0.9 of the tolerance and the fit repeated, then Tiller's
//! certified knot removal within the rest, charged per span (Piegl & Tiller's
//! bookkeeping). [`BSplineStrategy::Segments`]: per-segment Hermite reductions, at most
//! `C^floor((m-1)/2)`. [`reduce_bspline_piegl_tiller`] ([`BSplineStrategy::PieglTiller1995`]):
//! the classical algorithm of Piegl & Tiller 1995 (NURBS Book A5.11) as the reference — one
//! degree at a time, every knot's multiplicity lowered by one, per-span certified bounds, no
//! subdivision (it fails where the input is not close to a degree-elevated spline).
//!
//! Measured (`cargo bench -p cagd-reduce --bench bspline`, 1 000-span degree-7 curves to
//! degree 3 at 1e-6, release, 2-core machine shared with builds, so +-30%; the ratio is to a
//! `memcpy` of the input and output knots and points): a genuine degree-7 spiral — global
//! fit 3 815 spans out (29.3 µs per input span, 3.3e4x the copy; bound 9.88e-7, measured
//! 8.99e-7), segments 3 971 spans (23.7 µs), Piegl–Tiller fails; a C2 cubic elevated to
//! degree 7 and perturbed by 1e-7 — global fit 1 000 spans (4.4 µs/span, bound 8.0e-8),
//! segments 1 000 (4.3 µs/span, bound 7.1e-7), Piegl–Tiller fails; perturbed by 1e-8 —
//! fit 1 000 spans (bound 8.0e-9), segments 1 000 (7.1e-8), Piegl–Tiller 1 000 (14.5
//! µs/span, bound 1.0e-7). A test (300 random near-reducible curves) checks
//! that the fit never keeps more spans than Piegl–Tiller wherever that succeeds.
//!
//! Surfaces: [`reduce_bspline_surface_fit`] (the global fit direction by direction, the
//! other direction's control points as a bundle; knot lines keep `C^min(k, m-1)`);
//! [`reduce_bspline_surface`]: patch-wise; [`reduce_bspline_surface_to_tolerance`]: patch-wise
//! with uniform knot refinement until the certified bound meets a tolerance.
//!
//! ## Rational to polynomial
//!
//! [`rational_to_polynomial`] / [`rational_surface_to_polynomial`]: a NURBS curve or tensor
//! surface to a polynomial B-spline of degree `<= m` (the input's by default; lower drops
//! the weights and reduces in one pass) within a certified tolerance, keeping
//! `C^min(p - s, m - 1)` at each knot. Ours, on the global fit's machinery: the degree-`m`
//! space on the input's breaks, the least-squares fit of `C = A / W` at Gauss nodes (banded
//! Givens QR; joints where the input is only `C^0` interpolated), per span the certified
//! bound `max |A - W S| / W` (the degree-`p + m` polynomial `A - W S` by the Bernstein
//! product, centred on the piece's bounding-box centre, joint subdivision with `W`), knots
//! placed by error equidistribution until every span is within the tolerance, then
//! certified knot removal. Weights all equal are recognised exactly (same control points,
//! no spans added). Measured (unit tests, parametric distance `max_t |C(t) - S(t)|`, which
//! bounds the geometric one): a quarter / half / full unit circle to cubics within 1e-3
//! takes 3 / 6 / 12 spans, within 1e-5 8 / 16 / 32 (a `C^1` cubic Hermite fit needs
//! 3 / 6 / 12 and 9 / 18 / 36); to quadratics 5 / 10 / 20 and 19 / 38 / 76.
// Unsafe code is denied (workspace lint) with one exception: the calls of the AVX2 + FMA
// and AVX-512 instances of the batch kernel after run-time detection (`bezier/lanes.rs`).
#![deny(unsafe_code)]

mod ball;
mod bezier;
mod bspline;
mod exact;
mod interval;
mod patch;
mod rational_to_polynomial;

pub use ball::{
    MAX_WSGB_PIECES, WSGB_MEASURED_PIECES, WsgbMethod, WsgbPiece, WsgbPiecewise, WsgbReduction,
    WsgbReport, WsgbStep, reduce_wsgb, reduce_wsgb_to_tolerance, reduce_wsgb_via_bezier,
    reduce_wsgb_with, wsgb_chebyshev_coefficients, wsgb_paper_bound_11,
    wsgb_perturbation_error_factor, wsgb_perturbation_step, wsgb_perturbed_points,
    wsgb_sampled_error_inf, wsgb_uniform_points, wsgb_uniform_step_exact,
};
pub use bezier::{
    BoundLevel, ChebyshevTerms, DEFAULT_MAX_DEPTH, DEFAULT_REL_TOL, ErrorSpace, MAX_PIECES,
    MAX_TOLERANCE_WORK, Method, Operator, OperatorRoute, PiecewiseReduction, PiecewiseReport,
    ReduceOptions, ReducedPiece, Reduction, Report, ToleranceOptions, build_operator,
    constrained_chebyshev_terms, eck_lambdas, exact_degree, max_deviation, operator,
    perturbation_error_factor, reduce, reduce_batch, reduce_batch_with_bounds, reduce_exact,
    reduce_g1_optimal, reduce_to_tolerance, reduce_to_tolerance_alg_14_2_1, reduce_with,
    subdivision_levels,
};
pub use bspline::{
    BSplineOptions, BSplineReduction, BSplineReport, BSplineStrategy, MAX_GREEDY_REMOVAL_KNOTS,
    MAX_SEGMENT_REDUCTIONS, MAX_SURFACE_LEVEL, MAX_SURFACE_PATCHES, Merge,
    SPLINE_MEASURE_NODE_BUDGET, SPLINE_MEASURED_PIECES, SURFACE_MEASURE_NODE_BUDGET,
    SURFACE_MEASURED_CELLS, SurfaceFitOptions, SurfaceFitReduction, SurfaceOptions,
    SurfaceReduction, UniformReduction, reduce_bspline, reduce_bspline_piegl_tiller,
    reduce_bspline_surface, reduce_bspline_surface_fit, reduce_bspline_surface_to_tolerance,
    reduce_uniform_bspline, spline_max_deviation, surface_max_deviation,
};
pub use cagd_core::{Error, Result};
pub use interval::{
    AnalyticOptimum, DEFAULT_SAMPLE_GRID, IntervalOptions, IntervalReduction, IntervalReport,
    IntervalTriPatch, MAX_ANALYTIC_BASES, MAX_INTERVAL_DEGREE, MAX_INTERVAL_LP_WORK,
    reduce_interval_triangle, reduce_interval_triangle_analytic, triangle_elevation_matrix,
    triangle_elevation_matrix_exact,
};
pub use patch::{
    MAX_PATCH_TOLERANCE_WORK, MAX_SUBDIVISION_LEVEL, MAX_TOLERANCE_PIECES,
    PIECES_MEASURE_NODE_BUDGET, PIECES_MEASURED_FULLY, PatchConstraint, PatchOptions,
    PatchReduction, PatchReport, TensorMethod, TensorPiece, TriMethod, TriOptions, TriPiece,
    TriReduction, reduce_tensor, reduce_tensor_to_tolerance, reduce_triangle,
    reduce_triangle_to_tolerance, tri_perturbation_matrix,
};
pub use rational_to_polynomial::{
    PolynomialReduction, PolynomialReport, PolynomialSurfaceReduction,
    rational_surface_to_polynomial, rational_to_polynomial,
};

// Crate-internal items `rational_to_polynomial` builds on (imported through the root).
use bspline::{BandedLsq, LocalBounds, Raw, SpanBound, order_at};
