//! `CagdReduceOptions` and the codes of its fields (`CagdReduceMethod`, `CagdErrorSpace`,
//! `CagdPatchMethod`, `CagdPatchConstraint`, `CagdMerge`, `CagdSplineStrategy`): how a
//! reduction is asked for from C, and their translation to `cagd_reduce::ReduceOptions`
//! (here) and to `BSplineOptions` / `SurfaceFitOptions` (`strategy.rs`). No entry point:
//! `cagd_reduce_options_init` is in `reduce/init.rs`.

use cagd_reduce::{BSplineStrategy, BoundLevel, ErrorSpace, Method, ReduceOptions};

use crate::boundary::{CResult, Failure, nonnull};

/// The degree-reduction methods (cagd-reduce `Method`; seed 000 chapter 14 and the
/// classical methods it cites). Stored in `CagdReduceOptions.method` as an `int32_t`.
///
/// cbindgen:rename-all=prefix:CAGD_
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(
    non_camel_case_types,
    reason = "C names: the variants become CAGD_METHOD_*"
)]
pub enum CagdReduceMethod {
    /// Forrest's one-degree reduction, applied stepwise; interpolates derivatives up to
    /// order `floor((m - 1) / 2)` at both ends.
    METHOD_FORREST = 0,
    /// Piegl–Tiller one-degree reduction (equal to Forrest, own formula).
    METHOD_PIEGL_TILLER = 1,
    /// Farin's one-degree reduction; interpolates the end points; needs `m >= 1`.
    METHOD_FARIN = 2,
    /// Control-point perturbation with fixed ends (seed 000 §14.2.1); needs `m >= 1`.
    METHOD_PERTURB = 3,
    /// Perturbation with G1 ends and the given `l1`, `l2` (seed 000 §14.2.3); needs
    /// `m >= 3`, `1 + l1 > 0`, `1 + l2 > 0`.
    METHOD_PERTURB_G1 = 4,
    /// Eck's one-degree reduction (Chebyshev economisation, best uniform for one degree).
    METHOD_ECK = 5,
    /// Watkins–Worsey Chebyshev truncation (multi-degree).
    METHOD_WATKINS_WORSEY = 6,
    /// Bogacki–Weinstein–Xu near-best uniform multi-degree reduction, ends free.
    METHOD_BOGACKI_WEINSTEIN_XU = 7,
    /// Generalized-inverse (L2-best) reduction without end constraints (seed 000 §14.4.1).
    METHOD_GENERALIZED_INVERSE = 8,
    /// Generalized-inverse reduction with interpolated end points (seed 000 §14.4.2);
    /// needs `m >= 1`.
    METHOD_GENERALIZED_INVERSE_ENDS = 9,
    /// Constrained Chebyshev reduction keeping derivatives `0..=r` at t = 0 and `0..=p` at
    /// t = 1 (seed 000 §14.5); needs `r + p + 1 <= m`.
    METHOD_CONSTRAINED_CHEBYSHEV = 10,
    /// L2-optimal reduction with `C^(r,p)` end constraints; needs `r + p + 1 <= m`.
    METHOD_L2 = 11,
}

/// The space in which a reduction report's error numbers are measured (matters for
/// rational curves only). Stored in `CagdReduceOptions.space` as an `int32_t`.
///
/// cbindgen:rename-all=prefix:CAGD_
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(
    non_camel_case_types,
    reason = "C names: the variants become CAGD_SPACE_*"
)]
pub enum CagdErrorSpace {
    /// `max_t |P(t) - Q(t)|` of the Euclidean curves.
    SPACE_EUCLIDEAN = 0,
    /// The same maximum for the homogeneous curves `(wP, w)`, `(vQ, v)`.
    SPACE_HOMOGENEOUS = 1,
}

/// How much work the certified error bound of `cagd_curve_reduce` (and of the optional
/// per-curve bounds of `cagd_curve_reduce_batch_bounded`) may take. Stored in
/// `CagdReduceOptions.bound_level` as an `int32_t`.
///
/// cbindgen:rename-all=prefix:CAGD_
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(
    non_camel_case_types,
    reason = "C names: the variants become CAGD_BOUND_*"
)]
pub enum CagdBoundLevel {
    /// No bound: the reduction alone (`cagd_report_bound` then returns
    /// `CAGD_ERR_NOT_AVAILABLE`).
    BOUND_NONE = 0,
    /// A certified bound within 1.25× of the true error (plus a rounding allowance): the
    /// error curve evaluated at about `2.4 n` Chebyshev–Lobatto nodes (two small
    /// precomputed linear maps), times the Ehlich–Zeller factor.
    BOUND_FAST = 1,
    /// A certified bound within 1.075× of the true error (plus a rounding allowance): as
    /// `CAGD_BOUND_FAST` with about `4.2 n` nodes. The default.
    BOUND_TIGHT = 2,
}

/// How a patch is reduced (`CagdReduceOptions.patch_method`, an `int32_t`).
///
/// cbindgen:rename-all=prefix:CAGD_
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(
    non_camel_case_types,
    reason = "C names: the variants become CAGD_PATCH_*"
)]
pub enum CagdPatchMethod {
    /// Control-point perturbation, one degree in each direction (seed 000 §14.3.1 for
    /// tensor patches, `(m, n) -> (m - 1, n - 1)`, with any `CagdPatchConstraint`;
    /// §14.3.2 for triangles, `n -> n - 1`, constraint `CAGD_CONSTRAINT_NONE` only).
    /// Minimises the sum of squared control-point perturbations.
    PATCH_PERTURB = 0,
    /// Tensor patches only: every column by `method` (`m -> target`), then every row
    /// (`n -> target_v`), with the curve options `method`, `r`, `p`, `l1`, `l2`;
    /// constraint `CAGD_CONSTRAINT_NONE` only. With `CAGD_METHOD_L2` and `r = p = -1` it is
    /// the L2-best reduction over the unit square (the L2 projection is separable).
    PATCH_BY_CURVES = 1,
    /// Triangular patches only: L2-optimal reduction `n -> target` over the triangle,
    /// under the constraint.
    PATCH_L2 = 2,
}

/// Extra conditions on a patch reduction (`CagdReduceOptions.constraint`, an `int32_t`).
///
/// cbindgen:rename-all=prefix:CAGD_
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(
    non_camel_case_types,
    reason = "C names: the variants become CAGD_CONSTRAINT_*"
)]
pub enum CagdPatchConstraint {
    /// No condition.
    CONSTRAINT_NONE = 0,
    /// The corner points are kept (target degrees `>= 1`; tensor `>= 2` for perturbation).
    CONSTRAINT_CORNERS = 1,
    /// The boundary curves of the result are the reductions of the input's boundary curves
    /// by the curve method `method` (with `r`, `p`, `l1`, `l2`), which must interpolate
    /// both end points: patches sharing an edge still share it after reduction (C0).
    CONSTRAINT_BOUNDARY = 2,
}

/// How the reduced segments of a uniform B-spline are joined
/// (`CagdReduceOptions.merge`, an `int32_t`; seed 001 §4).
///
/// cbindgen:rename-all=prefix:CAGD_
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(
    non_camel_case_types,
    reason = "C names: the variants become CAGD_MERGE_*"
)]
pub enum CagdMerge {
    /// §4.1: the reduced segments become one clamped spline with interior knots of
    /// multiplicity `target - k`, `k` the end order the method keeps; exact (the spline is
    /// the reduced segments). Needs a method that interpolates the segment ends.
    MERGE_EXACT = 0,
    /// §4.2: local uniform B-spline points of each segment, overlapping points averaged:
    /// keeps uniform simple knots (`C^(target-1)`) at the price of an extra change, which
    /// the certified bound includes.
    MERGE_LOSSY = 1,
}

/// How `cagd_bspline_reduce` builds the degree-`target` spline from a degree-`p` one
/// (`CagdReduceOptions.spline_strategy`, an `int32_t`; cagd-reduce `BSplineStrategy`).
/// Each keeps, at every interior knot of the input that is still a knot of the result,
/// the continuity `C^min(k, c)`: `c` the input's continuity there (`p - s` for a knot of
/// multiplicity `s`), `k` the `spline_continuity` asked for, at most the strategy's maximum
/// given below (`-1`: that maximum).
///
/// cbindgen:rename-all=prefix:CAGD_
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(
    non_camel_case_types,
    reason = "C names: the variants become CAGD_SPLINE_*"
)]
pub enum CagdSplineStrategy {
    /// One least-squares fit (parameter L2 norm, end points kept) on the whole
    /// degree-`target` spline space whose knots are the input's with the multiplicities
    /// that keep the continuity; spans whose certified bound misses their share of the
    /// tolerance are split and the fit repeated; then knot removal within the rest of the
    /// tolerance. Keeps up to `C^(target - 1)`. The default.
    SPLINE_FIT = 0,
    /// Every Bézier segment reduced on its own by `method` (`CAGD_METHOD_L2` or
    /// `CAGD_METHOD_CONSTRAINED_CHEBYSHEV`) with Hermite data at both ends, split where
    /// needed, merged, then knot removal. Keeps at most
    /// `C^floor((target - 1) / 2)` (two-sided Hermite data need `2k + 1 <= target`).
    SPLINE_SEGMENTS = 1,
    /// The classical algorithm of Piegl & Tiller 1995 (NURBS Book A5.11), as a reference:
    /// one degree at a time, every segment reduced by one degree, merged, and every
    /// interior knot left with one copy fewer per degree. Never subdivides: fails with
    /// `CAGD_ERR_CONDITION_NOT_MET` when the curve is not reducible within the tolerance
    /// that way (it succeeds essentially for degree-elevated splines and those within the
    /// tolerance of one). Keeps the input's `C^c` wherever a knot stays (at most
    /// `C^(target - 1)`).
    SPLINE_PIEGL_TILLER_1995 = 2,
}

impl CagdSplineStrategy {
    /// The C code of a cagd-reduce strategy.
    pub(crate) fn of(strategy: &BSplineStrategy) -> Self {
        match strategy {
            BSplineStrategy::GlobalFit => Self::SPLINE_FIT,
            BSplineStrategy::Segments(_) => Self::SPLINE_SEGMENTS,
            BSplineStrategy::PieglTiller1995 => Self::SPLINE_PIEGL_TILLER_1995,
        }
    }

    /// The `CagdReduceMethod` code `cagd_report_method` gives for a reduction by this
    /// strategy: the method that reduced the pieces (`asked`, the options' `method`, for
    /// segments; `CAGD_METHOD_L2` for the fit, which minimises the L2 norm with the end
    /// points kept; `CAGD_METHOD_PIEGL_TILLER`, the one-degree segment reduction of
    /// Piegl & Tiller 1995).
    pub(crate) fn reported_method(self, asked: i32) -> i32 {
        match self {
            Self::SPLINE_FIT => CagdReduceMethod::METHOD_L2 as i32,
            Self::SPLINE_SEGMENTS => asked,
            Self::SPLINE_PIEGL_TILLER_1995 => CagdReduceMethod::METHOD_PIEGL_TILLER as i32,
        }
    }
}

/// How to reduce: a plain struct the caller owns. Fill it with
/// `cagd_reduce_options_init`, then change the fields you need.
///
/// Versioning rule: the first field, `struct_size`, is set by `cagd_reduce_options_init`
/// to `sizeof(CagdReduceOptions)` of the header the caller was compiled with. Every
/// function taking options reads it first and fails with `CAGD_ERR_INVALID_ARGUMENT` when
/// it is smaller than the size of this first version of the struct (so a struct that was
/// not initialised is most likely caught). Later versions only append fields; a library
/// reads at most the fields it knows, and the fields a smaller (older) struct lacks take
/// their defaults, so a program compiled against an older header keeps working. Never set
/// `struct_size` by hand to anything but `sizeof(CagdReduceOptions)`. No version has been
/// released yet, so every field below (including `spline_strategy` and
/// `spline_continuity`, the last ones added) belongs to the first version and the smallest
/// size accepted is the full size; fields appended after the first release will say in
/// which version they appeared, and the smallest size accepted stays that of the first.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CagdReduceOptions {
    /// `sizeof(CagdReduceOptions)` in bytes, set by `cagd_reduce_options_init` (see the
    /// versioning rule above).
    pub struct_size: usize,
    /// A `CagdReduceMethod` value (an `int32_t`, so that any value a caller stores is
    /// checked rather than undefined). Default `CAGD_METHOD_L2` (with `r = p = 0`: the end
    /// points are interpolated; among the end-interpolating methods it had the smallest
    /// errors in our measurements).
    pub method: i32,
    /// The target degree `m`, below the source degree. Default 3.
    pub target: usize,
    /// Highest derivative order kept at t = 0 for `CAGD_METHOD_CONSTRAINED_CHEBYSHEV` and
    /// `CAGD_METHOD_L2`, `-1` for none. Ignored by the other methods. Default 0 (the end
    /// point is kept, so joints stay connected).
    pub r: i32,
    /// Highest derivative order kept at t = 1, as `r`. Default 0.
    pub p: i32,
    /// Tangent scale at t = 0 for `CAGD_METHOD_PERTURB_G1` (finite, `> -1`). Default 0.
    pub l1: f64,
    /// Tangent scale at t = 1 for `CAGD_METHOD_PERTURB_G1` (finite, `> -1`). Default 0.
    pub l2: f64,
    /// Also measure the error by dense sampling (costs about 8000 evaluations per piece).
    /// Default false.
    pub measure: bool,
    /// A `CagdErrorSpace` value: the space of the report's numbers. Default
    /// `CAGD_SPACE_EUCLIDEAN`.
    pub space: i32,
    /// Reduction to a tolerance only: the tolerance `delta` (model units, Euclidean) the
    /// certified error bound must meet; finite and `> 0`. Default 0, which is rejected
    /// (`CAGD_ERR_INVALID_ARGUMENT`): a tolerance depends on the model's size, so the
    /// caller must choose it.
    pub tolerance: f64,
    /// Reduction to a tolerance only: the order `k` of parametric continuity `C^k` at the
    /// joins of the pieces (interior knots of multiplicity `target - k`); needs
    /// `k < target` and a method that keeps derivatives up to order `k` at both ends
    /// (e.g. `CAGD_METHOD_L2` with `r = p = k`). Default 0 (`C^0`). Not used by
    /// `cagd_bspline_reduce`, which reads `spline_continuity`.
    pub continuity: usize,
    /// Reduction of a curve to a tolerance only: the depth limit, i.e. no piece shorter
    /// than `2^-max_depth` of the parameter range (not below `2^-46`; for
    /// `cagd_curve_reduce_to_tolerance_stepwise` the deepest midpoint-subdivision level,
    /// a total over all steps). Default 30.
    /// (Patches to a tolerance stop at level 8, `4^8` pieces.)
    pub max_depth: usize,
    /// Tensor-product patches only: the target degree in v (`target` is the one in u).
    /// Default 3.
    pub target_v: usize,
    /// Patches only: a `CagdPatchMethod` value. Default `CAGD_PATCH_PERTURB`.
    pub patch_method: i32,
    /// Patches only: a `CagdPatchConstraint` value. Default `CAGD_CONSTRAINT_NONE`.
    pub constraint: i32,
    /// `cagd_bspline_reduce_uniform` only: a `CagdMerge` value. Default
    /// `CAGD_MERGE_EXACT`.
    pub merge: i32,
    /// `cagd_bspline_reduce` only: a `CagdSplineStrategy` value. Default `CAGD_SPLINE_FIT`.
    pub spline_strategy: i32,
    /// `cagd_bspline_reduce` only: the continuity to keep at the input's interior knots.
    /// `-1` (default): all the continuity the input has there, up to the most the strategy
    /// keeps (`C^(target - 1)` for `CAGD_SPLINE_FIT` and `CAGD_SPLINE_PIEGL_TILLER_1995`,
    /// `C^floor((target - 1) / 2)` for `CAGD_SPLINE_SEGMENTS`). `k >= 0`: keep at most
    /// `C^k`, i.e. `C^min(k, c)` where the input is `C^c` (knot removal may leave more; a
    /// `k` above the strategy's maximum is `CAGD_ERR_TOO_MANY_CONSTRAINTS`). Below `-1`:
    /// `CAGD_ERR_INVALID_ARGUMENT`.
    pub spline_continuity: i32,
    /// `cagd_curve_reduce` and `cagd_curve_reduce_batch_bounded` only: a `CagdBoundLevel` value,
    /// how much work the certified bound may take. Default `CAGD_BOUND_TIGHT`.
    pub bound_level: i32,
}

/// The size of the first published version of `CagdReduceOptions` (this one: nothing is
/// released yet, so it is the full size): the smallest `struct_size` accepted.
pub(crate) const OPTIONS_MIN_SIZE: usize = size_of::<CagdReduceOptions>();

impl Default for CagdReduceOptions {
    fn default() -> Self {
        Self {
            struct_size: size_of::<CagdReduceOptions>(),
            method: CagdReduceMethod::METHOD_L2 as i32,
            target: 3,
            r: 0,
            p: 0,
            l1: 0.0,
            l2: 0.0,
            measure: false,
            space: CagdErrorSpace::SPACE_EUCLIDEAN as i32,
            tolerance: 0.0,
            continuity: 0,
            max_depth: 30,
            target_v: 3,
            patch_method: CagdPatchMethod::PATCH_PERTURB as i32,
            constraint: CagdPatchConstraint::CONSTRAINT_NONE as i32,
            merge: CagdMerge::MERGE_EXACT as i32,
            spline_strategy: CagdSplineStrategy::SPLINE_FIT as i32,
            spline_continuity: -1,
            bound_level: CagdBoundLevel::BOUND_TIGHT as i32,
        }
    }
}

/// Reads the caller's options under the versioning rule of `CagdReduceOptions`: NULL →
/// `CAGD_ERR_NULL_POINTER`; `struct_size` below the first version's size →
/// `CAGD_ERR_INVALID_ARGUMENT`; the fields beyond `struct_size` take their defaults.
///
/// # Safety
/// `opts` must be NULL or point to at least `opts->struct_size` readable bytes (at least
/// a `size_t`) laid out as `CagdReduceOptions`.
pub(crate) unsafe fn read_options(opts: *const CagdReduceOptions) -> CResult<CagdReduceOptions> {
    nonnull(opts, "opts")?;
    if !opts.is_aligned() {
        return Err(Failure::invalid("argument `opts` is misaligned"));
    }
    // SAFETY: non-NULL and aligned; the first field is a size_t by the caller's contract.
    let size = unsafe { opts.cast::<usize>().read() };
    if size < OPTIONS_MIN_SIZE {
        return Err(Failure::invalid(format!(
            "opts->struct_size = {size} is below sizeof(CagdReduceOptions) = \
             {OPTIONS_MIN_SIZE}: initialise the options with cagd_reduce_options_init"
        )));
    }
    // Copy the known prefix over the defaults; today the whole struct is known, so this
    // copies all of it. When fields are appended, a smaller (older) struct keeps the
    // defaults of the fields it lacks. The copy goes through raw bytes, and the one field
    // with invalid bit patterns (`bool measure`: a C caller may store any byte there) is
    // normalised before the struct is used, so no invalid `bool` ever exists.
    let mut out = std::mem::MaybeUninit::new(CagdReduceOptions::default());
    let n = size.min(size_of::<CagdReduceOptions>());
    let base = out.as_mut_ptr().cast::<u8>();
    // SAFETY: `n` readable bytes at `opts` by the caller's contract; `out` has at least
    // `n` bytes; the regions do not overlap (`out` is a local).
    unsafe { std::ptr::copy_nonoverlapping(opts.cast::<u8>(), base, n) };
    let at = std::mem::offset_of!(CagdReduceOptions, measure);
    // SAFETY: `at` is inside `out`; the byte is initialised (default, then maybe copied).
    unsafe {
        let b = base.add(at);
        b.write(u8::from(b.read() != 0));
    }
    // SAFETY: every field now holds a valid value: plain numbers (any bit pattern is
    // valid) and a normalised `bool`; padding needs no particular value.
    let mut out = unsafe { out.assume_init() };
    out.struct_size = size;
    Ok(out)
}

impl CagdReduceOptions {
    /// The cagd-reduce method these options name.
    ///
    /// # Errors
    /// `CAGD_ERR_INVALID_ARGUMENT` for a `method` code that is not a `CagdReduceMethod`.
    pub(crate) fn method(&self) -> CResult<Method> {
        let (r, p, l1, l2) = (self.r, self.p, self.l1, self.l2);
        Ok(match self.method {
            0 => Method::Forrest,
            1 => Method::PieglTiller,
            2 => Method::Farin,
            3 => Method::Perturb,
            4 => Method::PerturbG1 { l1, l2 },
            5 => Method::Eck,
            6 => Method::WatkinsWorsey,
            7 => Method::BogackiWeinsteinXu,
            8 => Method::GeneralizedInverse,
            9 => Method::GeneralizedInverseEnds,
            10 => Method::ConstrainedChebyshev { r, p },
            11 => Method::L2 { r, p },
            other => {
                return Err(Failure::invalid(format!(
                    "opts->method = {other} is not a CagdReduceMethod (0..=11)"
                )));
            }
        })
    }

    /// The error space these options name.
    ///
    /// # Errors
    /// `CAGD_ERR_INVALID_ARGUMENT` for a `space` code that is not a `CagdErrorSpace`.
    pub(crate) fn space(&self) -> CResult<ErrorSpace> {
        match self.space {
            0 => Ok(ErrorSpace::Euclidean),
            1 => Ok(ErrorSpace::Homogeneous),
            other => Err(Failure::invalid(format!(
                "opts->space = {other} is not a CagdErrorSpace (0 or 1)"
            ))),
        }
    }

    /// The bound level these options name.
    ///
    /// # Errors
    /// `CAGD_ERR_INVALID_ARGUMENT` for a `bound_level` code that is not a
    /// `CagdBoundLevel`.
    pub(crate) fn bound_level(&self) -> CResult<BoundLevel> {
        match self.bound_level {
            0 => Ok(BoundLevel::None),
            1 => Ok(BoundLevel::Fast),
            2 => Ok(BoundLevel::Tight),
            other => Err(Failure::invalid(format!(
                "opts->bound_level = {other} is not a CagdBoundLevel (0, 1 or 2)"
            ))),
        }
    }

    /// The cagd-reduce options these options describe.
    ///
    /// # Errors
    /// `CAGD_ERR_INVALID_ARGUMENT` for an unknown `method` or `space` code.
    pub(crate) fn rust_options(&self) -> CResult<ReduceOptions> {
        Ok(ReduceOptions {
            measure: self.measure,
            space: self.space()?,
            bound: self.bound_level()?,
            ..ReduceOptions::new(self.method()?, self.target)
        })
    }
}

mod strategy;

pub(crate) use strategy::{spline_options, surface_fit_options};

#[cfg(test)]
mod tests;
