//! The error type shared by every cagd crate (DESIGN.md, "Error model").
//!
//! Each variant says what was wrong and with which value, so that a message such as
//! `weights[3] = -0.5 must be finite and > 0, not subnormal` can be shown to a user without extra context.
//! Each variant maps to exactly one C status code in `cagd-capi`.

/// Everything that can go wrong in cagd-core, and the base of the other crates' errors.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A degree outside the supported range `0..=max` (see [`crate::MAX_DEGREE`]).
    #[error("degree {degree} is outside the supported range 0..={max}")]
    DegreeOutOfRange {
        /// The degree that was asked for.
        degree: usize,
        /// The largest supported degree.
        max: usize,
    },
    /// Too few points (or coefficients) for the object or the algorithm.
    #[error("not enough points: got {got}, need at least {need}")]
    NotEnoughPoints {
        /// How many were given.
        got: usize,
        /// How many are needed.
        need: usize,
    },
    /// The spatial dimension is zero.
    #[error("dimension must be at least 1, got 0")]
    ZeroDimension,
    /// Two lengths that must agree do not.
    #[error("length mismatch in {what}: got {got}, expected {expected}")]
    LengthMismatch {
        /// Which array or count.
        what: &'static str,
        /// The length that was given.
        got: usize,
        /// The length that was expected.
        expected: usize,
    },
    /// A coordinate is NaN or infinite.
    #[error("points[{index}][{coord}] = {value} is not finite")]
    NonFinite {
        /// Index of the point.
        index: usize,
        /// Index of the coordinate within the point.
        coord: usize,
        /// The offending value.
        value: f64,
    },
    /// A weight of a rational object is zero, negative, subnormal (below `2^-1022`) or not
    /// finite.
    #[error("weights[{index}] = {weight} must be finite and > 0, not subnormal")]
    NonPositiveWeight {
        /// Index of the weight.
        index: usize,
        /// The offending value.
        weight: f64,
    },
    /// A knot is NaN or infinite.
    #[error("knots[{index}] = {value} is not finite")]
    NonFiniteKnot {
        /// Index of the knot.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// The knot vector decreases at `index` (`knots[index] < knots[index - 1]`).
    #[error("knots[{index}] is smaller than knots[{}]: the knot vector must be non-decreasing", .index - 1)]
    KnotsNotNondecreasing {
        /// First index at which the vector decreases.
        index: usize,
    },
    /// The knot vector has the wrong length (must be `n_points + degree + 1`).
    #[error("knot vector has {got} knots, expected {expected} (n_points + degree + 1)")]
    KnotCount {
        /// Number of knots given.
        got: usize,
        /// Number of knots expected.
        expected: usize,
    },
    /// A knot appears more often than `degree + 1` times.
    #[error("knot {knot} has multiplicity {mult}, above degree + 1 = {}", .degree + 1)]
    MultiplicityAboveDegree {
        /// The knot value.
        knot: f64,
        /// Its multiplicity.
        mult: usize,
        /// The degree of the spline.
        degree: usize,
    },
    /// A parameter (evaluation point, split point, interval end) is not usable.
    #[error("parameter {name} = {value} is not valid: {why}")]
    BadParameter {
        /// Name of the parameter.
        name: &'static str,
        /// The offending value.
        value: f64,
        /// What is required of it.
        why: &'static str,
    },
    /// A pair of degrees that the operation does not accept (e.g. target >= source).
    #[error("degree pair {from} -> {to} is not valid: {why}")]
    BadDegreePair {
        /// Source degree.
        from: usize,
        /// Target degree.
        to: usize,
        /// What is required of the pair.
        why: &'static str,
    },
    /// Too many end constraints for the target degree (needs r + p + 1 < m or similar).
    #[error("too many end constraints: r = {r}, p = {p} for target degree {m} ({why})")]
    TooManyConstraints {
        /// Derivative order kept at t = 0 (-1 for none).
        r: i64,
        /// Derivative order kept at t = 1 (-1 for none).
        p: i64,
        /// Target degree.
        m: usize,
        /// The condition that failed.
        why: &'static str,
    },
    /// A tolerance that is not finite and positive.
    #[error("tolerance {value} must be finite and > 0")]
    BadTolerance {
        /// The offending value.
        value: f64,
    },
    /// A condition of a seed formula is not met (the equation number is given).
    #[error("condition of eq. {eq} is not met: {why}")]
    ConditionNotMet {
        /// Equation number in the seed, e.g. "15.1.8".
        eq: &'static str,
        /// What failed.
        why: &'static str,
    },
    /// A condition of a conversion formula is not met, with the quantity that fails it:
    /// e.g. the inverse of a rational Bézier segment to a NURBS span (SPEC-convert
    /// §15.1.8, §15.3.13–16) needs every inverse weight `> 0`, and §15.2's closed form needs
    /// separable weights.
    #[error("condition {condition} is not met: {what}, index {index}, = {value}")]
    ConversionCondition {
        /// The condition, e.g. "15.1.8" or "15.3.14".
        condition: &'static str,
        /// The quantity that fails it, e.g. "inverse NURBS weight w_{n-2+index} must be > 0".
        what: &'static str,
        /// The index of the failing quantity (local, as `what` says).
        index: usize,
        /// Its value.
        value: f64,
    },
    /// An iterative or adaptive algorithm could not reach the tolerance.
    #[error("no convergence: tolerance {tolerance} asked, {achieved} achieved")]
    NoConvergence {
        /// The tolerance that was asked for.
        tolerance: f64,
        /// The best that was achieved.
        achieved: f64,
    },
    /// A linear system that must be solved is singular.
    #[error("singular system in {what}")]
    Singular {
        /// Which system.
        what: &'static str,
    },
    /// An `n x n` tensor patch is not a degenerate triangle (SPEC-convert §15.4,
    /// Theorem 15.4.2): re-elevating its exactly reduced rows misses it by `residual`
    /// (relative to the largest coordinate), above `tol`.
    #[error(
        "not a degenerate triangular patch: relative residual {residual} above tolerance {tol} (Theorem 15.4.2)"
    )]
    NotDegenerate {
        /// The relative residual measured.
        residual: f64,
        /// The tolerance it was tested against.
        tol: f64,
    },
    /// A split of a parameter domain folds or degenerates (SPEC-convert §15.5: the
    /// Jacobian of a bilinear sub-domain map must be > 0 at its four corners).
    #[error("degenerate or folded split: {what} = {value}")]
    DegenerateSplit {
        /// What degenerates (e.g. "jacobian of D2 at corner X11").
        what: &'static str,
        /// The offending value (a Jacobian, an area).
        value: f64,
    },
    /// A trimming layout the trimmed-patch tiling does not support (SPEC-convert §15.7.3).
    #[error("unsupported trimming layout at segment {index}: {why}")]
    UnsupportedTrim {
        /// Index of the offending trimming segment.
        index: usize,
        /// What is not supported.
        why: &'static str,
    },
    /// An algorithm for planar curves (implicitization, SPEC-convert §15.8) got points of
    /// another dimension.
    #[error("the curve must be planar (dimension 2), got dimension {dim}")]
    NotPlanar {
        /// The dimension that was given.
        dim: usize,
    },
    /// The homogeneous coordinates X(t), Y(t), W(t) of a rational curve share a common factor
    /// of degree `count` (base points, SPEC-convert §15.8 end): `det F` vanishes identically.
    #[error(
        "the curve has {count} base point(s) (a common factor of X, Y, W): det F is identically 0"
    )]
    BasePoint {
        /// The number of base points (degree of the common factor, points at t = ∞ included).
        count: usize,
    },
    /// A point is a singular point (double point, cusp) of the curve, where the parameter
    /// is not unique or not defined by the kernel of the Bézout matrix.
    #[error("({x}, {y}) is a singular point of the curve: its parameter is not unique")]
    SingularPoint {
        /// Abscissa of the point.
        x: f64,
        /// Ordinate of the point.
        y: f64,
    },
    /// A point given for inversion is not on the curve.
    #[error("({x}, {y}) is not on the curve (distance {distance})")]
    NotOnCurve {
        /// Abscissa of the point.
        x: f64,
        /// Ordinate of the point.
        y: f64,
        /// Its distance to the nearest curve point found.
        distance: f64,
    },
    /// Two curves overlap along an arc (they lie on the same algebraic curve): their
    /// intersection is not a finite set of points.
    #[error("the curves overlap along an arc (s in [{s0}, {s1}] on the first curve)")]
    Coincident {
        /// Start of the overlap on the first curve (parameter).
        s0: f64,
        /// End of the overlap on the first curve (parameter).
        s1: f64,
    },
    /// An interval (box side) whose lower bound exceeds its upper bound (seed 004 §1).
    #[error("box {index} coordinate {coord}: lo = {lo} > hi = {hi} (an empty interval)")]
    EmptyInterval {
        /// Index of the control box.
        index: usize,
        /// Index of the coordinate within the box.
        coord: usize,
        /// The lower bound given.
        lo: f64,
        /// The upper bound given.
        hi: f64,
    },
    /// The LP solver answered that a linear program is infeasible.
    #[error("the linear program of {what} is infeasible (solver answer)")]
    LpInfeasible {
        /// Which linear program.
        what: &'static str,
    },
    /// The LP solver answered that a linear program is unbounded.
    #[error("the linear program of {what} is unbounded (solver answer)")]
    LpUnbounded {
        /// Which linear program.
        what: &'static str,
    },
    /// The LP solver failed (an internal error, a panic caught, a non-finite answer).
    #[error("the LP solver failed on {what}: {why}")]
    LpSolverFailed {
        /// Which linear program.
        what: &'static str,
        /// The solver's message.
        why: String,
    },
    /// A containment that must be certified could not be (after outward repair).
    #[error("containment of {what} could not be certified (residual {residual})")]
    NotCertified {
        /// What was to be certified.
        what: &'static str,
        /// The largest residual left (in model units).
        residual: f64,
    },
}

/// `Result` with [`Error`].
pub type Result<T> = core::result::Result<T, Error>;
